"""The result of a pushed run (MODEL §13): :class:`PushedTrajectory`, the motion of a body pushed
by a finger, with the pusher's force, the contact point and mode over time, the switches between
modes, the plastic impacts and the energy balance (computed by
:func:`slidespin.motion.pushed.simulate_pushed`).

Energy: pusher work + load work = ΔKE + plane friction dissipation + contact slip dissipation
+ impact losses; ``energy_error`` is the residual (an integration-accuracy check).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.motion._report import _html_table
from slidespin.motion.state import State

__all__ = ["PushedTrajectory"]

#: the contact modes, indexed by the codes of :attr:`PushedTrajectory.mode_code`


@dataclass(frozen=True)
class PushedTrajectory:
    """Motion of a body pushed by a finger over [0, t_end] (SI units, MODEL §13).

    Rows are the integrator's steps, with two rows at each switch, knot and impact (before
    and after, at the same time).

    Attributes
    ----------
    t, x, y, phi, vx, vy, omega : ndarray
        Time [s], position of G [m], body angle [rad], velocity of G [m/s], spin [rad/s].
    pusher_position : ndarray, shape (n, 2)
        The finger p(t) [m], plane frame.
    pusher_force : ndarray, shape (n, 2)
        The force λ the finger applies to the body [N], plane frame (0 while separated;
        impulses are in ``impacts``).
    contact_point : ndarray, shape (n, 2)
        The contact point c [m], plane frame (the finger's position); NaN while separated.
    mode : tuple of str
        Contact mode per row: ``separated``, ``sticking``, ``sliding_left`` (the finger slides
        towards +t = ẑ × n relative to the body, n the inward normal: to its left looking
        into the body) or ``sliding_right``.
    mode_code : ndarray of int
        The same as indices into :data:`slidespin.motion.outcomes.PUSH_MODES`.
    switches : tuple of (float, str, str)
        (time [s], from mode, to mode) of every change of mode, in order.
    impacts : tuple of (float, float, float, float)
        (time [s], impulse Λx, Λy [N s], energy lost [J]) of every plastic impact.
    kinetic_energy : ndarray
        ½ m v² + ½ I ω² [J].
    pusher_work, friction_work, contact_slip_work, load_work : ndarray
        Cumulative work of the finger on the body (impulses included) [J]; energy dissipated
        by the plane's friction (≥ 0) [J]; energy dissipated by slip at the finger contact,
        ∫ μp λn |u·t| dt (≥ 0) [J]; work of the applied loads and the slope [J].
    impact_loss : ndarray
        Cumulative energy lost in plastic impacts [J].
    energy_error : float
        |ΔKE + friction + slip + impact losses − pusher work − load work| at the end [J].
    status : str
        ``ok``, or why the run ended early (:data:`slidespin.motion.outcomes.PUSHED_STATUSES`).
    message : str
        Why the run ended early (empty for ``ok``).
    n_rhs : int
        Right-hand-side evaluations of the separated phases (a measure of work).
    """

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    phi: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray
    pusher_position: np.ndarray
    pusher_force: np.ndarray
    contact_point: np.ndarray
    mode: tuple
    mode_code: np.ndarray
    switches: tuple
    impacts: tuple
    kinetic_energy: np.ndarray
    pusher_work: np.ndarray
    friction_work: np.ndarray
    contact_slip_work: np.ndarray
    load_work: np.ndarray
    impact_loss: np.ndarray
    energy_error: float
    status: str
    body: Body = field(repr=False)
    friction: FrictionTensor = field(repr=False)
    initial_state: State = field(repr=False)
    pusher: Any = field(repr=False)
    g: float = 9.81
    message: str = ""
    n_rhs: int = 0

    def __repr__(self) -> str:
        f = self.final_state
        return (
            f"PushedTrajectory(status={self.status!r}, t_final={float(self.t[-1]):.6g} s, "
            f"final_position=({f.x:.6g} m, {f.y:.6g} m, {f.phi:.6g} rad), "
            f"switches={len(self.switches)}, impacts={len(self.impacts)}, "
            f"n_points={self.t.size})"
        )

    @property
    def final_state(self) -> State:
        """The state at the last row."""
        return State(
            float(self.x[-1]),
            float(self.y[-1]),
            float(self.phi[-1]),
            float(self.vx[-1]),
            float(self.vy[-1]),
            float(self.omega[-1]),
        )

    @property
    def relative_energy_error(self) -> float:
        """``energy_error`` over the largest term of the balance (0 if all vanish)."""
        terms = (
            abs(float(self.pusher_work[-1])),
            abs(float(self.load_work[-1])),
            abs(float(self.friction_work[-1])),
            abs(float(self.kinetic_energy[-1] - self.kinetic_energy[0])),
        )
        scale = max(terms)
        return self.energy_error / scale if scale > 0.0 else 0.0

    def phases(self) -> list[tuple[str, float, float]]:
        """(mode, t0, t1) intervals in order, covering the run."""
        out: list[tuple[str, float, float]] = []
        start, mode = float(self.t[0]), self.mode[0]
        for t, _, new in self.switches:
            if t > start or out or new != mode:
                out.append((mode, start, float(t)))
            start, mode = float(t), new
        out.append((mode, start, float(self.t[-1])))
        return [p for p in out if p[2] > p[1] or len(out) == 1]

    def summary(self) -> dict[str, Any]:
        """The run's outcome as a JSON-ready dict (SI units)."""

        def num(x):
            x = float(x)
            return x if math.isfinite(x) else None

        f = self.final_state
        return {
            "t_final": num(self.t[-1]),
            "x_final": num(f.x),
            "y_final": num(f.y),
            "phi_final": num(f.phi),
            "switches": len(self.switches),
            "impacts": len(self.impacts),
            "pusher_work": num(self.pusher_work[-1]),
            "friction_work": num(self.friction_work[-1]),
            "contact_slip_work": num(self.contact_slip_work[-1]),
            "impact_loss": num(self.impact_loss[-1]),
            "energy_error": num(self.energy_error),
            "status": self.status,
            "message": self.message,
        }

    def _repr_html_(self) -> str:
        """A short summary table for notebooks (no arrays)."""
        return _html_table("PushedTrajectory", self.summary())
