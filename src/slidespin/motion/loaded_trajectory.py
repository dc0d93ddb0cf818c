"""The result of a loaded run (MODEL §11): :class:`LoadedTrajectory`, the motion of a body
under applied forces and torques or on a slope, with its stick and slip phases and the energy
balance (computed by :func:`slidespin.motion.loaded.simulate_loaded`).

Energy: ΔKE = W_f + W_Q, reported as ``energy_error`` (an integration-accuracy check); on a
slope the gravity work m g sin α d·Δr is also computed from the displacement alone.
"""

from __future__ import annotations

import csv
import io
import json
import math
from dataclasses import dataclass, field

import numpy as np

from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.motion._report import _html_table
from slidespin.motion.loads import Load
from slidespin.motion.outcomes import status_message
from slidespin.motion.springs import Spring
from slidespin.motion.state import State

__all__ = ["LoadedTrajectory"]


@dataclass(frozen=True)
class LoadedTrajectory:
    """Motion of a loaded body over [0, t_end] with its stick and slip phases (SI units).

    Attributes
    ----------
    t, x, y, phi, vx, vy, omega : ndarray
        Time [s], position of G [m], body angle [rad], velocity of G [m/s] and spin
        [rad/s] at the integrator's steps, and at the start and end of each stick phase.
    kinetic_energy, friction_work, load_work : ndarray
        ½ m v² + ½ I ω² [J] and the cumulative work of friction and of the applied loads
        (gravity along a slope included) [J] at the same instants.
    phases : tuple of (str, float, float)
        ``("stick", t0, t1)`` and ``("slip", t0, t1)`` intervals in order, covering
        [0, t_final]. Without ``t_end`` the run ends when the body sticks (no final stick
        interval).
    ending : str
        ``at_rest_throughout`` (never moved), ``stopped_stuck`` (moved, and is stuck at
        the end), ``moving_at_t_end``, or ``steady_sliding`` (moving at t_end under a
        constant load with an acceleration that would change the speed s by less than
        STEADY_TOL = 1e-6 of itself over the whole elapsed time).
    status : str
        ``ok``; ``max_steps`` when the step budget ran out (values as reached);
        ``max_phases`` when more than ``max_phases`` stick–slip phases occurred;
        ``no_onset`` when the load left the static-friction set C but the onset solve
        found no slip direction (a solver failure: one always exists, MODEL §11); the run
        then ends at that time with the body at rest, and ``ending`` describes that state;
        ``step_too_small`` when the integrator gave up (values as reached); ``tipping``
        when a tall body tips (its pressure centroid reached the footprint's hull, MODEL
        §14): the run ends at ``tip_time``.
    message : str
        Why the run ended early (empty for ``ok``).
    tip_time : float or None
        The time [s] at which a tall body tips (status ``tipping``), located to
        ``time_tol``; ``None`` otherwise.
    energy_error : float
        |ΔKE − W_f − W_Q| [J] over the run (integration accuracy).
    gravity_work : float
        m g sin α d·(r_end − r_0) [J] from the displacement alone (0 on a level plane). For
        a tilt varying in time the work of gravity depends on the path: it is then the
        integrated load work when gravity is the only applied load, NaN otherwise.
    n_rhs : int
        Work done: right-hand-side evaluations of the Python path plus the wrench-kernel
        calls of the compiled engine (one per right-hand side, a few for a slaved one).
    """

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    phi: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray
    kinetic_energy: np.ndarray
    friction_work: np.ndarray
    load_work: np.ndarray
    phases: tuple
    ending: str
    status: str
    energy_error: float
    gravity_work: float
    n_rhs: int
    body: Body = field(repr=False)
    friction: FrictionTensor = field(repr=False)
    initial_state: State = field(repr=False)
    load: Load | Spring | list | tuple | None = field(default=None, repr=False)
    incline: Incline | None = field(default=None, repr=False)
    g: float = 9.81
    message: str = ""
    tip_time: float | None = None

    def __repr__(self) -> str:
        f = self.final_state
        t_stop = self.t_stop
        return (
            f"LoadedTrajectory(status={self.status!r}, ending={self.ending!r}, "
            f"t_final={float(self.t[-1]):.6g} s, t_stop={t_stop:.6g} s, "
            f"phases={len(self.phases)}, final_position=({f.x:.6g} m, {f.y:.6g} m, "
            f"{f.phi:.6g} rad), n_points={self.t.size})"
        )

    def _repr_html_(self) -> str:
        """A short summary table for notebooks (no arrays)."""
        items = self.summary()
        items["phases"] = len(self.phases)
        return _html_table("LoadedTrajectory", items)

    @property
    def stick_intervals(self) -> list[tuple[float, float]]:
        """(t0, t1) of every stick phase [s]."""
        return [(a, b) for kind, a, b in self.phases if kind == "stick"]

    @property
    def slip_intervals(self) -> list[tuple[float, float]]:
        """(t0, t1) of every slip phase [s]."""
        return [(a, b) for kind, a, b in self.phases if kind == "slip"]

    @property
    def t_stop(self) -> float:
        """Time [s] of the last stop: the end of the last slip when the run ends stuck
        (``stopped_stuck``), 0 for ``at_rest_throughout``, NaN while moving."""
        if self.ending == "at_rest_throughout":
            return 0.0
        if self.ending != "stopped_stuck":
            return math.nan
        return self.slip_intervals[-1][1]

    @property
    def final_state(self) -> State:
        """State at the last recorded time."""
        return State(self.x[-1], self.y[-1], self.phi[-1], self.vx[-1], self.vy[-1], self.omega[-1])

    @property
    def speed(self) -> np.ndarray:
        """|v_G| [m/s]."""
        return np.hypot(self.vx, self.vy)

    @property
    def status_message(self) -> str:
        """One line saying what ``status`` means (:mod:`slidespin.motion.outcomes`)."""
        return status_message(self.status, loaded=True)

    def summary(self) -> dict:
        """Results as a JSON-ready dict (SI units)."""
        f = self.final_state
        return {
            "t_final": float(self.t[-1]),
            "t_stop": None if math.isnan(self.t_stop) else self.t_stop,
            "x_final": f.x,
            "y_final": f.y,
            "phi_final": f.phi,
            "vx_final": f.vx,
            "vy_final": f.vy,
            "omega_final": f.omega,
            "ending": self.ending,
            "status": self.status,
            "status_message": self.status_message,
            "message": self.message,
            "tip_time": self.tip_time,
            "phases": [[k, a, b] for k, a, b in self.phases],
            "energy_error": self.energy_error,
            "gravity_work": self.gravity_work,
        }

    def to_json(self, path=None) -> str:
        """Write (or return) :meth:`summary` as JSON."""
        text = json.dumps(self.summary(), indent=2)
        if path is not None:
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text + "\n")
        return text

    COLUMNS = (
        "t",
        "x",
        "y",
        "phi",
        "vx",
        "vy",
        "omega",
        "kinetic_energy",
        "friction_work",
        "load_work",
    )

    def to_csv(self, path=None) -> str:
        """Write (or return) the recorded instants as CSV (SI units)."""
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(self.COLUMNS)
        for row in zip(*(getattr(self, c) for c in self.COLUMNS)):
            w.writerow([repr(float(x)) for x in row])
        if path is not None:
            with open(path, "w", encoding="utf-8", newline="") as fh:
                fh.write(buf.getvalue())
        return buf.getvalue()
