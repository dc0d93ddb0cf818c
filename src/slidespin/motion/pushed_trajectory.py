"""The result of a pushed run (MODEL §13): :class:`PushedTrajectory`, the motion of a body pushed
by a finger or a line pusher, with the pusher's force, the contact point and mode over time, the
switches between modes, the plastic impacts and the energy balance (computed by
:func:`slidespin.motion.pushed.simulate_pushed`, a line pusher's by
:mod:`slidespin.motion.pushed_line`; ``_assemble`` turns either engine's rows into it).

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
from slidespin.motion.outcomes import PUSH_MODES
from slidespin.motion.state import State

__all__ = ["PushedTrajectory"]


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
        The finger p(t) [m], plane frame (a line pusher's centre).
    pusher_force : ndarray, shape (n, 2)
        The force λ the finger applies to the body [N], plane frame (0 while separated;
        impulses are in ``impacts``).
    contact_point : ndarray, shape (n, 2)
        The contact point c [m], plane frame (the finger's position; for a line pusher in
        face contact, the point of the line load's resultant); NaN while separated.
    mode : tuple of str
        Contact mode per row: ``separated``, ``sticking``, ``sliding_left`` (the finger slides
        towards +t = ẑ × n relative to the body, n the inward normal: to its left looking
        into the body) or ``sliding_right``. A line pusher's
        (:mod:`slidespin.motion.pushed_line`): ``face_sticking``, ``face_sliding_left``,
        ``face_sliding_right`` (a body edge flush with the pusher's face, a line load whose
        resultant lies on the shared segment), ``vertex_sticking``, ``vertex_sliding_left``,
        ``vertex_sliding_right`` (a body vertex on the face, n the face's normal),
        ``end_sticking``, ``end_sliding_left``, ``end_sliding_right`` (the pusher's end on a
        body edge, n the edge's normal); left and right in the same sense.
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


_MESSAGES = {
    "max_steps": "the budget of max_steps = {max_steps} integrator steps ran out",
    "max_phases": "more than max_phases = {max_phases} phases",
    "step_too_small": "the integrator could not meet its tolerance",
    "no_onset": "a separated body at rest under a load beyond static friction (its slow "
    "start is not integrated by the pushing engine)",
    "indeterminate": "no contact mode is consistent here (a Painleve-type paradox)",
}


def _assemble(
    eng, status, t_stop, t_end, max_steps, max_phases, prob, body, friction, state, pusher, g
) -> PushedTrajectory:
    """The :class:`PushedTrajectory` of a pushing engine's rows (natural units → SI).

    Each row of ``eng.rows`` is (t, x, y, φ, vx, vy, ω, λx, λy, cx, cy, mode, pusher work,
    friction work, slip work, load work, impact loss, px, py); ``eng.switches`` holds
    (t, from, to) and ``eng.impacts`` (t, Λx, Λy, loss), all in natural units."""
    a, tu, vu = prob.a, prob.t_unit, prob.v_unit
    if status == "ok":
        message = ""
    else:
        what = _MESSAGES[status].format(max_steps=max_steps, max_phases=max_phases)
        message = f"{what} at t = {t_stop * tu:.12g} s"
    arr = np.array(eng.rows, dtype=float)
    scale = body.mass * g * a
    k = prob.k
    ke = 0.5 * (arr[:, 4] ** 2 + arr[:, 5] ** 2 + (k * arr[:, 6]) ** 2) * scale
    wp, wf, ws, wl, loss = (arr[:, j] * scale for j in (12, 13, 14, 15, 16))
    err = abs((ke[-1] - ke[0]) - wf[-1] + ws[-1] + loss[-1] - wp[-1] - wl[-1])
    codes = arr[:, 11].astype(int)
    cpt = arr[:, 9:11] * a
    cpt[codes == 0] = math.nan  # separated
    t_si = arr[:, 0] * tu
    if status == "ok":
        t_si[-1] = t_end
    return PushedTrajectory(
        t=t_si,
        x=arr[:, 1] * a,
        y=arr[:, 2] * a,
        phi=arr[:, 3] + getattr(eng, "turns", 0.0),
        vx=arr[:, 4] * vu,
        vy=arr[:, 5] * vu,
        omega=arr[:, 6] / tu,
        pusher_position=arr[:, 17:19] * a,
        pusher_force=arr[:, 7:9] * body.mass * g,
        contact_point=cpt,
        mode=tuple(PUSH_MODES[c] for c in codes),
        mode_code=codes,
        switches=tuple((float(t * tu), m0, m1) for t, m0, m1 in eng.switches),
        impacts=tuple(
            (float(t * tu), lx * body.mass * vu, ly * body.mass * vu, e * scale)
            for t, lx, ly, e in eng.impacts
        ),
        kinetic_energy=ke,
        pusher_work=wp,
        friction_work=-wf,
        contact_slip_work=ws,
        load_work=wl,
        impact_loss=loss,
        energy_error=float(err),
        status=status,
        message=message,
        n_rhs=prob.n_rhs,
        body=body,
        friction=friction,
        initial_state=state,
        pusher=pusher,
        g=g,
    )
