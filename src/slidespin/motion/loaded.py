"""Motion of a loaded body: applied forces and torques, slopes, stick and slip (MODEL §11).

During slip the Newton–Euler equations are m dv/dt = F + Q, I dω/dt = M + T + r_Q × Q
(:mod:`slidespin.motion.loads`). They are integrated in the regularised time of MODEL §5: with
s = √(vx² + vy² + k² ω²), k = √(I/m), u = (vx, vy, k ω)/s, the friction accelerations
A(u) = cos α (Fx, Fy, M/k)/(m g) (degree 0 in the speed) and the applied ones
B(t, φ) = (Qx, Qy, T_G/k)/(m g), Newton–Euler read dv/dt = A + B, so s ds/dt = s u·(A + B) and

    ds/dt = u·X,    du/dt = (X − (u·X) u)/s,     X = A + B,

and with dt = s dτ:

    du/dτ = X − (u·X) u,   d ln s/dτ = u·X,   dt/dτ = s,
    dx/dτ = s² u₁,  dy/dτ = s² u₂,  dφ/dτ = s² u₃/k,

plus the friction and load work, dW_f/dτ = s² u·A and dW_Q/dτ = s² u·B. This is MODEL §5's
system with X in place of A; B does not scale with s, so u·X may be positive (the body
speeds up). The stop (s → 0 with u·X < 0) is an exponential approach in τ as before.

Stick and slip, exactly (no regularised friction):

* at rest, the body stays while −W_a(t) lies in the static-friction set C
  (:mod:`slidespin.contact.statics`), to within GAUGE_TOL = 1e-12 (relative) of its boundary; for
  a time-varying load the moment W_a leaves C is the root of γ(t) − 1 − GAUGE_TOL, γ the
  gauge of C at W_a(t) (the inverse load factor), located by Brent's method to
  ``time_tol`` after a scan: at every knot of a piecewise-linear load or tilt (exact: γ is
  convex between knots, so no excursion is missed) and, for callables, on a grid of step
  ``scan_step`` (default at most SCAN_STEP_MAX = 1 ms; an excursion beyond C longer than
  the step is always found, a shorter one may be missed);
* a tilt may vary in time (``Incline(callable)``, :meth:`Incline.piecewise_linear`): the
  factor cos α(t) of the friction accelerations and of C and the pull sin α(t) d follow it;
* it starts in the onset direction u (A_a + A(u) = λ u, λ > 0; :func:`slidespin.contact.statics.onset`);
  s grows linearly, s ≈ λ (t − t₀), so the slip starts analytically at a small s. A ramped
  load starts the body at the threshold, where λ = 0⁺ (computed as round-off of either
  sign); s then grows like (t − t₀)² as λ(t) grows. Should the onset solve fail (a direction
  always exists beyond C, so only numerically), the run ends there, at rest, with status
  ``no_onset`` and a message, never an exception;
* it stops when s falls to a tiny fraction of its scale (the rest of the approach is added
  in closed form, t += s/|u·X|), and then sticks if −W_a ∈ C there, or starts again at once
  in the new onset direction (a body thrown up a slope steeper than the friction angle
  stops and slides back down).

The slip equations become stiff where s is small while the load changes slowly (the
direction u relaxes in O(1) τ while the motion evolves over O(1/λ) τ), so the default
integrator is ``Radau`` (implicit, order 5) of :func:`scipy.integrate.solve_ivp`, which
calls the compiled wrench kernel once per right-hand side.

Every patch: the ellipses and circles of the paper and the footprints of MODEL §10 (a
``Blade``, a line contact, included); the
friction wrench comes from :class:`slidespin.contact._engine.TwistWrench` (the elliptic or the
exact footprint kernel) and the static-friction set C from
``slidespin.contact.statics.static_support``. Natural units use the body's length unit
(:attr:`slidespin.Body.length_unit`).

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
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from slidespin import _validate as v
from slidespin._validate import _short
from slidespin.contact._engine import TwistWrench
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.statics import (
    WRENCH_MAX,
    OnsetNotFound,
    _load_factor_nat,
    _onset_from_par,
    _onset_nat,
    check_anisotropy,
    static_support,
)
from slidespin.motion.loads import Load
from slidespin.motion.outcomes import (
    LOADED_ENDINGS as LOADED_ENDINGS,  # re-exported (older imports)
)
from slidespin.motion.outcomes import status_message
from slidespin.motion.state import State

__all__ = [
    "GAUGE_TOL",
    "SCAN_POINTS_MAX",
    "SCAN_STEP_MAX",
    "LoadedTrajectory",
    "default_scan_step",
    "simulate_loaded",
]

_TOL = 1e-13
_STOP_DROP = 1e-13  # the stop is declared when s has fallen below this fraction of its scale
STEADY_TOL = 1e-6  # relative change of the speed that would take the elapsed time: steady
_STIFF = 100.0  # relaxation-to-growth ratio above which a slip phase is integrated by Radau
#: a body at rest is held while the gauge γ = 1/λ* ≤ 1 + GAUGE_TOL. Within 1e-12 of the
#: threshold the onset rate λ (∝ γ − 1) is below the round-off of the friction kernel, its
#: sign is noise, and the motion such a load could produce is nil; the margin keeps the
#: decision to slip and the onset it leads to consistent (a load held exactly at the
#: threshold would otherwise start, stall and start again at the same instant)
GAUGE_TOL = 1e-12
#: cap [s] on the default step of the scan for a time-varying load leaving C (a callable
#: load whose excursion beyond C lasts longer than the step is always found)
SCAN_STEP_MAX = 1e-3
#: the default scan takes at most this many points per stick phase (so for stick phases
#: longer than SCAN_STEP_MAX × SCAN_POINTS_MAX = 200 s the default step is duration/2e5)
SCAN_POINTS_MAX = 200_000


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
        ``step_too_small`` when the integrator gave up (values as reached).
    message : str
        Why the run ended early (empty for ``ok``).
    energy_error : float
        |ΔKE − W_f − W_Q| [J] over the run (integration accuracy).
    gravity_work : float
        m g sin α d·(r_end − r_0) [J] from the displacement alone (0 on a level plane). For
        a tilt varying in time the work of gravity depends on the path: it is then the
        integrated load work when gravity is the only applied load, NaN otherwise.
    n_rhs : int
        Right-hand-side evaluations.
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
    load: Load | None = field(default=None, repr=False)
    incline: Incline | None = field(default=None, repr=False)
    g: float = 9.81
    message: str = ""

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
        from slidespin.motion.simulate import _html_table

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


class _Problem:
    """Everything in natural units (a = m = g = 1, time √(a/g)) for one loaded run."""

    def __init__(self, body, friction, load, incline, g):
        self.body, self.friction, self.load, self.incline, self.g = body, friction, load, incline, g
        self.a = body.length_unit
        self.t_unit = math.sqrt(self.a / g)
        self.v_unit = math.sqrt(self.a * g)
        self.tw = TwistWrench(body, friction, _TOL)  # the wrench of any patch
        self.k = self.tw.k
        # a constant tilt keeps its factors as numbers (bit for bit the fixed-plane run)
        self.fixed_tilt = incline is None or incline.is_constant
        self.nf = 1.0 if incline is None or not self.fixed_tilt else incline.normal_factor
        if incline is None or not self.fixed_tilt:
            self.grav = (0.0, 0.0)
        else:
            dx, dy = incline.direction
            self.grav = (incline.downhill_factor * dx, incline.downhill_factor * dy)
        self.constant = (load is None or load.is_constant) and self.fixed_tilt
        self.n_rhs = 0
        self.failure = ""
        self._support = {}
        self._d_last = None

    def nf_at(self, t):
        """cos α at the natural time t (the constant cos α for a fixed tilt)."""
        if self.fixed_tilt:
            return self.nf
        return self.incline.normal_factor_at(t * self.t_unit)

    def b(self, t, phi):
        """Applied accelerations (Qx, Qy, T_G/k)/(m g), scaled natural coordinates."""
        if self.fixed_tilt:
            bx, by = self.grav
        else:
            sa = self.incline.downhill_factor_at(t * self.t_unit)
            dx, dy = self.incline.direction
            bx, by = sa * dx, sa * dy
        bm = 0.0
        if self.load is not None:
            qx, qy, mz = self.load.wrench(t * self.t_unit, phi, self.body.mass_centre)
            mg = self.body.mass * self.g
            bx += qx / mg
            by += qy / mg
            bm = mz / (mg * self.a * self.k)
            big = max(abs(qx), abs(qy), abs(mz) / self.a) / mg
            if not big <= WRENCH_MAX:
                raise ValueError(
                    f"load = {_short(self.load)} gives (Qx, Qy, T) = ({qx:.6g} N, {qy:.6g} N, "
                    f"{mz:.6g} N m) at t = {t * self.t_unit:.6g} s, {big:.3g} in units of "
                    f"(m g, m g, m g a); valid range: force and torque up to {WRENCH_MAX:g} "
                    "m g (m g a)"
                )
        return bx, by, bm

    def friction_acc(self, u1, u2, u3, phi, t=0.0):
        fx, fy, m = self.tw(phi, u1, u2, u3 / self.k)
        nf = self.nf if self.fixed_tilt else self.nf_at(t)
        return fx * nf, fy * nf, m * nf / self.k

    def rhs(self, tau, y):
        self.n_rhs += 1
        u1, u2, u3 = y[0], y[1], y[2]
        inv = 1.0 / math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
        u1 *= inv
        u2 *= inv
        u3 *= inv
        ax, ay, am = self.friction_acc(u1, u2, u3, y[7], y[4])
        bx, by, bm = self.b(y[4], y[7])
        xx, xy, xm = ax + bx, ay + by, am + bm
        ux = u1 * xx + u2 * xy + u3 * xm
        s = math.exp(y[3])
        s2 = s * s
        return np.array(
            [
                xx - ux * u1,
                xy - ux * u2,
                xm - ux * u3,
                ux,
                s,
                s2 * u1,
                s2 * u2,
                s2 * u3 / self.k,
                s2 * (u1 * ax + u2 * ay + u3 * am),
                s2 * (u1 * bx + u2 * by + u3 * bm),
            ]
        )

    def jac(self, tau, y):
        """Forward-difference Jacobian of :meth:`rhs` (the columns of x, y, W vanish)."""
        f0 = self.rhs(tau, y)
        jm = np.zeros((10, 10))
        for j in (0, 1, 2, 3, 4, 7):
            h = 1e-7 * max(1.0, abs(y[j]))
            yh = y.copy()
            yh[j] += h
            jm[:, j] = (self.rhs(tau, yh) - f0) / h
        return jm

    def stiffness(self, y):
        """Ratio of the fastest relaxation rate of u to the growth rate |u·X| (in τ)."""
        jm = self.jac(0.0, y)[:3, :3]
        u = y[:3] / np.linalg.norm(y[:3])
        proj = np.eye(3) - np.outer(u, u)
        kappa = float(np.max(np.abs(np.linalg.eigvals(proj @ jm @ proj))))
        rate = abs(float(self.rhs(0.0, y)[3]))
        return kappa / max(rate, 1e-300)

    def support(self, phi):
        key = float(phi)
        if key not in self._support:
            if len(self._support) > 8:
                self._support.clear()
            self._support[key] = static_support(self.tw, self.friction, key)
        return self._support[key]

    def w_nat(self, t, phi):
        """The applied wrench per unit normal load, in the coordinates of C (natural)."""
        bx, by, bm = self.b(t, phi)
        return np.array([bx, by, bm * self.k]) / self.nf_at(t)

    def gauge(self, t, phi, w=None):
        """γ = 1/λ*: the body at rest holds iff γ ≤ 1."""
        if w is None:
            w = self.w_nat(t, phi)
        if not w.any():
            return 0.0
        lam, self._d_last = _load_factor_nat(self.support(phi), w, self._d_last)
        return 1.0 / lam

    def onset(self, t, phi):
        """Onset (u, λ, residual) at a time where :meth:`gauge` has found γ > 1.

        Raises :class:`~slidespin.contact.statics.OnsetNotFound` if the solve fails.
        """
        b = np.array(self.b(t, phi))
        return _onset_from_par(
            self.tw,
            self.friction,
            phi,
            b,
            self.nf_at(t),
            self.support(phi),
            slipping=True,
            d0=self._d_last,
        )


def simulate_loaded(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    load: Load | None = None,
    incline: Incline | None = None,
    t_end: float | None = None,
    g: float = 9.81,
    rtol: float = 1e-10,
    *,
    method: str = "auto",
    max_step: float | None = None,
    max_steps: int = 200_000,
    max_phases: int = 1000,
    scan_step: float | None = None,
    time_tol: float = 1e-12,
    slow_speed: float = 1e-6,
) -> LoadedTrajectory:
    """Integrate a loaded body through its stick and slip phases (MODEL §11).

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body and its friction tensor.
    initial_state : State
        Initial position, angle and velocities (SI).
    load : Load or None
        Applied force and torque, constant or functions of time.
    incline : Incline or None
        Tilted plane: normal load m g cos α, downhill pull m g sin α. The tilt may vary in
        time (``Incline(angle=callable)`` or :meth:`Incline.piecewise_linear`): then both
        vary, static friction holds while the wrench is in C scaled by cos α(t), and the
        slip starts when the load leaves it (for a block with isotropic friction, when
        tan α(t) passes μ).
    t_end : float or None
        End of the run [s]. ``None`` is allowed for a constant load that static friction
        can hold at the initial angle: the run then ends when the body sticks (or after
        ``max_steps``).
    g : float, default 9.81
        Gravitational acceleration [m/s²].
    rtol : float, default 1e-10
        Relative tolerance of the slip integration (absolute tolerance rtol·1e-2 in natural
        units).
    method : str, default "auto"
        :func:`scipy.integrate.solve_ivp` method for slip phases. ``"auto"``: ``Radau``
        (implicit, with a difference Jacobian) for a slip that starts from rest, where the
        equations are stiff near a threshold, and ``DOP853`` for a body already moving.
    max_step : float or None
        Largest step in the regularised time τ (more recorded points for plots).
    max_steps : int
        Budget of integrator steps over the whole run.
    max_phases : int
        Budget of stick and slip phases.
    scan_step : float or None
        Step [s] of the scan for the moment a time-varying load overcomes static friction
        (the gauge of C at the load exceeds 1; Brent's method then locates the moment to
        ``time_tol``). Default :func:`default_scan_step`: (t_end − t)/400, but at most
        SCAN_STEP_MAX = 1 ms (for a stick phase longer than 200 s, at most 2e5 points:
        (t_end − t)/2e5). What is guaranteed:

        * a load built by :meth:`Load.piecewise_linear` (every ``[load]`` profile of a case
          file) on a plane of fixed tilt, or a tilt built by
          :meth:`Incline.piecewise_linear` alone: the test looks at every sample time and,
          the gauge being convex (resp. monotone) in between, never misses the load
          leaving C, however briefly (the grid is then not used unless ``scan_step`` is
          given);
        * any other load varying in time (a callable): every excursion beyond C that
          lasts longer than the scan step is found; a shorter one may be missed. Give a
          smaller ``scan_step`` for short pulses, or tabulate the load.

        Between grid points at which the load stays far inside C the gauge is bounded
        (triangle inequality of the gauge of C) instead of computed, so a fine grid
        costs little more than evaluating the load.
    time_tol : float
        Accuracy [s] of the located stick-to-slip times.
    slow_speed : float
        s [m/s] below which a slip starting from rest is integrated with the direction of
        motion slaved to the onset direction (the equations are stiff there; the error is
        O(s/κ) in the direction, a few 1e-12 of the motion at the default).

    Returns
    -------
    LoadedTrajectory

    Examples
    --------
    >>> import math
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor, State
    >>> from slidespin.motion.loads import Incline
    >>> disk = Body(Circle(0.05), UniformPressure(), mass=1.0)
    >>> tr = simulate_loaded(disk, FrictionTensor(0.3, 0.3), State(), incline=Incline(0.4),
    ...                      t_end=1.0, g=10.0)
    >>> a = 10.0 * (math.sin(0.4) - 0.3 * math.cos(0.4))
    >>> tr.ending, bool(abs(tr.x[-1] - a / 2) < 1e-9)
    ('moving_at_t_end', True)
    """
    check_body_friction(body, friction)
    if load is not None or incline is not None:  # the static-friction set C will be needed
        check_anisotropy(body, friction, "static friction under a load or on an incline")
    if not isinstance(initial_state, State):
        raise ValueError(
            f"initial_state = {initial_state!r} is invalid; valid values: a slidespin.State"
        )
    if load is not None and not isinstance(load, Load):
        raise ValueError(
            f"load = {load!r} is invalid; valid values: a slidespin.motion.loads.Load or None"
        )
    if incline is not None and not isinstance(incline, Incline):
        raise ValueError(
            f"incline = {incline!r} is invalid; valid values: a slidespin.contact.incline.Incline or None"
        )
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    rtol = v.in_range("rtol", rtol, 0.0, 1e-3, lo_open=True)
    method = v.choice("method", method, ("auto", "radau", "dop853", "lsoda", "bdf", "rk45"))
    method = {
        "radau": "Radau",
        "dop853": "DOP853",
        "lsoda": "LSODA",
        "bdf": "BDF",
        "rk45": "RK45",
        "auto": "auto",
    }[method]
    prob = _Problem(body, friction, load, incline, g)
    prob.b(0.0, initial_state.phi)  # the load's range, before any work
    if t_end is None:
        if not prob.constant:
            raise ValueError(
                "t_end = None is invalid for a load or a tilt varying in time; give t_end [s]"
            )
        t_end_n = math.inf
    else:
        t_end_n = v.positive("t_end", t_end, "s") / prob.t_unit
    slow_speed = v.positive("slow_speed", slow_speed, "m/s")
    h_max = math.inf if max_step is None else v.positive("max_step", max_step)
    scan = None if scan_step is None else v.positive("scan_step", scan_step, "s") / prob.t_unit
    t_tol = v.positive("time_tol", time_tol, "s") / prob.t_unit
    for name, val in (("max_steps", max_steps), ("max_phases", max_phases)):
        if isinstance(val, bool) or not isinstance(val, (int, np.integer)) or val < 1:
            raise ValueError(f"{name} = {val!r} is invalid; valid range: integer >= 1")

    if math.isinf(t_end_n) and prob.gauge(0.0, initial_state.phi) > 1.0 + GAUGE_TOL:
        raise ValueError(
            "t_end = None is invalid here: the load exceeds what static friction can hold "
            f"(load factor {1.0 / prob.gauge(0.0, initial_state.phi):.6g} < 1), so the body "
            "need never stop; give t_end [s]"
        )
    a, k = prob.a, prob.k
    s0 = initial_state
    # recorded rows: t, x, y, phi, vx, vy, kω (natural), W_f, W_Q
    rows: list[np.ndarray] = []
    phases: list[list] = []
    t = 0.0
    pos = np.array([s0.x / a, s0.y / a, s0.phi])
    vel = np.array([s0.vx / prob.v_unit, s0.vy / prob.v_unit, k * s0.omega * prob.t_unit])
    work = np.zeros(2)
    status = "ok"
    message = ""
    moved = False
    steps_left = int(max_steps)

    def record(tt, p, vv, w):
        rows.append(np.array([tt, p[0], p[1], p[2], vv[0], vv[1], vv[2], w[0], w[1]]))

    record(t, pos, vel, work)
    n_phase = 0
    while True:
        n_phase += 1
        if n_phase > max_phases:
            status = "max_phases"
            message = f"more than max_phases = {max_phases} stick and slip phases"
            break
        speed = float(np.linalg.norm(vel))
        phase_method = "DOP853" if method == "auto" else method
        if speed == 0.0:
            # ---- at rest: does static friction hold? ----
            if prob.gauge(t, pos[2]) <= 1.0 + GAUGE_TOL:
                t_exit = _stick_exit(prob, t, pos[2], t_end_n, scan, t_tol)
                t_stop_stick = t_end_n if t_exit is None else t_exit
                if math.isinf(t_stop_stick):  # no t_end: the run ends when the body sticks
                    break
                phases.append(["stick", t, t_stop_stick])
                t = t_stop_stick
                record(t, pos, vel, work)
                if t_exit is None:
                    break
            # ---- onset: the slow start, with u slaved to the onset direction ----
            t_phase0 = t
            try:
                qs = _quasi_static(prob, t, pos, work, t_end_n, rtol, slow_speed / prob.v_unit)
            except OnsetNotFound as exc:
                # a slip direction exists whenever γ > 1 (MODEL §11), so this is a solver
                # failure: end the run honestly, at rest where the onset was sought
                status = "no_onset"
                message = (
                    f"at t = {t * prob.t_unit:.12g} s the load left the static-friction "
                    f"set C but the body could not be started: {exc}; the run ends "
                    "there with the body at rest"
                )
                break
            if qs[5] == "stall" and qs[3] <= 0.0 and qs[0] <= t:
                # the start stalled at once: λ ≤ 0 beyond C, not a Coulomb onset (never seen
                # for isotropic friction, where λ ∝ γ − 1 > 0); end rather than loop here
                status = "no_onset"
                message = (
                    f"at t = {t * prob.t_unit:.12g} s the load left the static-friction "
                    "set C but the onset rate was not positive, so the body did not "
                    "start; the run ends there with the body at rest"
                )
                break
            moved = True
            t, pos, work, s_now, u, reason, rec = qs
            for r in rec:
                record(r[0], r[2:5], r[1] * r[5:8], r[8:10])
            if reason == "failed":
                vel = s_now * u
                phases.append(["slip", t_phase0, t])
                status = "step_too_small"
                message = (
                    f"the integrator of the slow start gave up at t = "
                    f"{t * prob.t_unit:.12g} s: {prob.failure}; values as reached"
                )
                break
            if reason == "t_end" or s_now <= 0.0:
                vel = s_now * u
                phases.append(["slip", t_phase0, t])
                if s_now <= 0.0 and reason != "t_end":
                    vel = np.zeros(3)
                    continue
                break
            y0 = np.concatenate([u, [math.log(s_now), t, pos[0], pos[1], pos[2]], work])
            ln_stop = math.log(max(s_now, slow_speed / prob.v_unit) * _STOP_DROP)
            if method == "auto" and prob.stiffness(y0) > _STIFF:
                phase_method = "Radau"
        else:
            moved = True
            t_phase0 = t
            u = vel / speed
            y0 = np.concatenate([u, [math.log(speed), t, pos[0], pos[1], pos[2]], work])
            ln_stop = math.log(speed * _STOP_DROP)
        while True:
            # Radau while stiff; every time s has grown e^5-fold, look again
            ln_switch = y0[3] + 5.0 if phase_method == "Radau" and method == "auto" else None
            y_end, rec, nst, reason = _slip(
                prob, y0, ln_stop, t_end_n, rtol, phase_method, h_max, steps_left, ln_switch
            )
            steps_left -= nst
            for r in rec:
                s = math.exp(r[3])
                record(r[4], r[5:8], s * r[0:3], r[8:10])
            if reason != "switch":
                break
            y0 = y_end
            if prob.stiffness(y0) <= _STIFF:
                phase_method = "DOP853"
        t = float(y_end[4])
        pos = y_end[5:8].copy()
        work = y_end[8:10].copy()
        if reason == "stop":
            vel = np.zeros(3)
            rows[-1][4:7] = 0.0
            phases.append(["slip", t_phase0, t])
            if t >= t_end_n:
                break
            continue
        s = math.exp(y_end[3])
        vel = s * y_end[0:3]
        phases.append(["slip", t_phase0, t])
        if reason == "max_steps":
            status = "max_steps"
            message = f"the budget of max_steps = {max_steps} integrator steps ran out"
        elif reason == "failed":
            status = "step_too_small"
            message = (
                f"the slip integrator gave up at t = {t * prob.t_unit:.12g} s: "
                f"{prob.failure}; values as reached"
            )
        break

    arr = np.array(rows)
    tu, vu = prob.t_unit, prob.v_unit
    load_scale = body.mass * g * a
    ke = 0.5 * (arr[:, 4] ** 2 + arr[:, 5] ** 2 + arr[:, 6] ** 2) * load_scale
    wf = arr[:, 7] * load_scale
    wq = arr[:, 8] * load_scale
    speed_end = float(np.linalg.norm(arr[-1, 4:7]))
    if speed_end == 0.0:
        ending = "stopped_stuck" if moved else "at_rest_throughout"
    else:
        ending = "moving_at_t_end"
        if prob.constant and status == "ok":
            u = arr[-1, 4:7] / speed_end
            ax, ay, am = prob.friction_acc(u[0], u[1], u[2], arr[-1, 3], arr[-1, 0])
            bx, by, bm = prob.b(arr[-1, 0], arr[-1, 3])
            acc = math.sqrt((ax + bx) ** 2 + (ay + by) ** 2 + (am + bm) ** 2)
            if acc * arr[-1, 0] < STEADY_TOL * speed_end:
                ending = "steady_sliding"
    dx = (arr[-1, 1] - arr[0, 1]) * a
    dy = (arr[-1, 2] - arr[0, 2]) * a
    grav = 0.0
    if incline is not None and incline.is_constant:
        gx, gy = incline.gravity_force(body.mass, g)
        grav = gx * dx + gy * dy
    elif incline is not None:
        # a tilt varying in time: the work of gravity depends on the path; it is the load
        # work when gravity is the only applied load, and not separated otherwise
        grav = float(wq[-1] - wq[0]) if load is None else math.nan
    energy_error = abs((ke[-1] - ke[0]) - (wf[-1] - wf[0]) - (wq[-1] - wq[0]))
    t_si = arr[:, 0] * tu
    phases_si = [(kind, float(t0 * tu), float(t1 * tu)) for kind, t0, t1 in phases]
    if t_end is not None and abs(arr[-1, 0] - t_end_n) <= 1e-9 * t_end_n:
        # the run reached t_end: report it exactly (t_end / t_unit × t_unit rounds)
        t_si[-1] = float(t_end)
        if phases_si and abs(phases_si[-1][2] / tu - t_end_n) <= 1e-9 * t_end_n:
            phases_si[-1] = (phases_si[-1][0], phases_si[-1][1], float(t_end))
    return LoadedTrajectory(
        t=t_si,
        x=arr[:, 1] * a,
        y=arr[:, 2] * a,
        phi=arr[:, 3].copy(),
        vx=arr[:, 4] * vu,
        vy=arr[:, 5] * vu,
        omega=arr[:, 6] / k / tu,
        kinetic_energy=ke,
        friction_work=wf,
        load_work=wq,
        phases=tuple(phases_si),
        ending=ending,
        status=status,
        energy_error=float(energy_error),
        gravity_work=float(grav),
        n_rhs=prob.n_rhs,
        body=body,
        friction=friction,
        initial_state=initial_state,
        load=load,
        incline=incline,
        g=g,
        message=message,
    )


def _quasi_static(prob, t0, pos, work, t_end, rtol, s_slow):
    """Slow start from rest at t0 with u slaved to the onset direction u*(t, φ).

    While s is tiny the direction relaxes to u* in a time ~ s/κ, far faster than the load
    or the angle change, so u = u*(t, φ) + O(s): integrate, in t, ds/dt = λ = u*·X,
    dr/dt = s u*, and the work, until s reaches ``s_slow`` (then the full equations take
    over), λ falls to 0 (the load has re-entered C), s falls back to 0 (a load that only
    grazed the boundary of C), or t_end. At the threshold λ(t0) = 0 (within round-off) and
    grows as the load does. Returns (t, pos, work, s, u, reason, rows) with rows
    (t, s, x, y, φ, u, W_f, W_Q).

    Raises :class:`~slidespin.contact.statics.OnsetNotFound` when no slip direction is found.
    """
    res = prob.onset(t0, pos[2])
    cache = {"u": res[0]}
    k = prob.k

    def slaved(t, phi):
        b = np.array(prob.b(t, phi))
        acc = _friction_fun(prob, phi, t)
        got = _onset_nat(acc, b, cache["u"], quick=True)
        if got is None:
            got = _onset_nat(acc, b, cache["u"], allow_negative=True)
        if got is None:
            raise OnsetNotFound(
                f"the slow start lost its slip direction at t = {t * prob.t_unit:.12g} s"
            )
        u, lam, _ = got
        cache["u"] = u
        a = np.array(acc(u))
        return u, lam, a, b

    def rhs(t, z):
        prob.n_rhs += 1
        u, lam, a, b = slaved(t, z[3])
        s = z[0]
        return np.array([lam, s * u[0], s * u[1], s * u[2] / k, s * (u @ a), s * (u @ b)])

    def ev_fast(t, z):
        return z[0] - s_slow

    ev_fast.terminal = True
    ev_fast.direction = 1.0

    def ev_stall(t, z):
        return slaved(t, z[3])[1]

    ev_stall.terminal = True
    ev_stall.direction = -1.0

    def ev_back(t, z):  # s back through 0: the load only grazed C, the body stays
        return z[0]

    ev_back.terminal = True
    ev_back.direction = -1.0

    def ev_end(t, z):
        return t - t_end

    ev_end.terminal = True
    ev_end.direction = 1.0
    events = [ev_fast, ev_stall, ev_back] + ([] if math.isinf(t_end) else [ev_end])
    z0 = np.array([0.0, pos[0], pos[1], pos[2], work[0], work[1]])
    t_hi = t0 + 1e6 if math.isinf(t_end) else t_end + 1.0
    sol = solve_ivp(rhs, (t0, t_hi), z0, method="DOP853", rtol=rtol, atol=1e-18, events=events)
    z = sol.y[:, -1]
    te = sol.t[-1]
    reason = "t_end"
    if sol.status == -1:  # the integrator gave up: the values as reached, and why
        reason = "failed"
        prob.failure = str(sol.message)
    if sol.status == 1:
        for i, name in enumerate(("fast", "stall", "stall", "t_end")):
            if i < len(sol.t_events) and sol.t_events[i].size:
                reason = name
                te = sol.t_events[i][0]
                z = sol.y_events[i][0]
                break
    u = slaved(te, z[3])[0]
    rows = []
    for tt, zz in zip(sol.t[1:], sol.y[:, 1:].T):
        uu = slaved(tt, zz[3])[0]
        rows.append(np.concatenate([[tt, zz[0]], zz[1:4], uu, zz[4:6]]))
    rows[-1] = np.concatenate([[te, z[0]], z[1:4], u, z[4:6]])
    return te, z[1:4].copy(), z[4:6].copy(), max(float(z[0]), 0.0), u, reason, rows


def _friction_fun(prob, phi, t):
    return lambda u: np.array(prob.friction_acc(u[0], u[1], u[2], phi, t))


def _knots_nat(prob, t0, t_end):
    """Sample times of piecewise-linear loads and tilts in (t0, t_end], natural units."""
    times = set()
    for obj in (prob.load, prob.incline):
        if obj is not None:
            times.update(tk / prob.t_unit for tk in obj.knots)
    return sorted(tk for tk in times if t0 < tk < t_end)


def _exact_at_knots(prob):
    """True when looking at the knots alone cannot miss the load leaving C.

    A piecewise-linear load on a fixed plane is affine in t between knots (the body is at
    rest, φ fixed), so the gauge γ of the convex set C at it is convex there and exceeds 1
    somewhere in a segment only if it does at an end. A piecewise-linear tilt with no
    other load gives γ = tan α(t) γ(d), monotone between knots.
    """
    load, inc = prob.load, prob.incline
    if inc is None or inc.is_constant:
        return load is not None and load.is_piecewise_linear
    return load is None and inc.knots != ()


def default_scan_step(duration: float) -> float:
    """Default ``scan_step`` [s] of :func:`simulate_loaded` for a stick phase that may last
    ``duration`` [s]: min(duration/400, max(SCAN_STEP_MAX, duration/SCAN_POINTS_MAX))."""
    return min(duration / 400.0, max(SCAN_STEP_MAX, duration / SCAN_POINTS_MAX))


def _stick_exit(prob, t0, phi, t_end, scan, t_tol):
    """First time after t0 at which the gauge γ(t) exceeds 1 + GAUGE_TOL, or None (stays
    stuck).

    γ is evaluated at every knot of a piecewise-linear load or tilt and (unless that is
    exact, :func:`_exact_at_knots`) on a grid of step ``scan`` (natural units; default
    :func:`default_scan_step`). Where the load has moved little from the last point at which
    γ was computed, γ is bounded instead of computed: γ is a gauge of the symmetric convex
    set C, so γ(w) ≤ γ(w₀) + Σᵢ |wᵢ − w₀ᵢ| γ(eᵢ) (the triangle inequality), and a point
    with that bound below 1 is inside C without the minimisation.
    """
    if prob.constant or math.isinf(t_end):
        return None
    exact = _exact_at_knots(prob)
    points = _knots_nat(prob, t0, t_end)
    if scan is not None or not exact:
        h = (
            scan
            if scan is not None
            else (default_scan_step((t_end - t0) * prob.t_unit) / prob.t_unit)
        )
        n = int(math.ceil((t_end - t0) / h))
        grid = t0 + h * np.arange(1, n + 1)
        points = np.union1d(grid[grid < t_end], np.asarray(points, dtype=float)).tolist()
    points.append(t_end)
    memo = {}

    def f(tt):
        # γ carries round-off that depends on the minimiser's warm start; a load held at the
        # threshold would then change sign between the scan and Brent's own evaluation of
        # the same end point ("f(a) and f(b) must have different signs"): one value per time
        if tt not in memo:
            memo[tt] = prob.gauge(tt, phi) - (1.0 + GAUGE_TOL)
        return memo[tt]

    fa = f(t0)
    if fa > 0.0:  # pragma: no cover - γ > 1 at the scan start: slip at once
        return t0
    # the gauge of the unit wrenches, for the bound (C is symmetric: γ(−e) = γ(e))
    sup = prob.support(phi)
    ge = np.array([1.0 / _load_factor_nat(sup, e)[0] for e in np.eye(3)])
    w_anchor, g_anchor = prob.w_nat(t0, phi), fa + 1.0 + GAUGE_TOL
    ta = t0
    for tb in points:
        w = prob.w_nat(tb, phi)
        bound = g_anchor + float(np.abs(w - w_anchor) @ ge)
        if bound * (1.0 + 1e-8) < 1.0:  # certainly inside C
            ta = tb
            continue
        fb = f(tb)
        if fb > 0.0:
            f(ta)  # the bracket's left end (inside C, perhaps only bounded so far)
            r = brentq(f, ta, tb, xtol=t_tol, rtol=1e-15, maxiter=200)
            # return a time at which the load is already beyond C (slip starts there)
            for _ in range(60):
                if r >= tb or f(r) > 0.0:
                    return min(r, tb)
                r += t_tol
            return tb
        ta, w_anchor, g_anchor = tb, w, fb + 1.0 + GAUGE_TOL
    return None


class _StepBudget(Exception):
    """Raised from inside solve_ivp when a slip phase has used its budget of steps."""


def _slip(prob, y0, ln_stop, t_end, rtol, method, h_max, steps_left, ln_switch=None):
    """Integrate one slip phase in τ; returns (y_end, recorded rows, steps, reason).

    ``reason``: ``stop``, ``t_end``, ``max_steps``, ``switch`` (ln s reached ``ln_switch``)
    or ``failed`` (the integrator gave up; its message in ``prob.failure``).
    """

    def ev_stop(tau, y):
        return y[3] - ln_stop

    ev_stop.terminal = True
    ev_stop.direction = -1.0

    def ev_end(tau, y):
        return y[4] - t_end

    ev_end.terminal = True
    ev_end.direction = 1.0

    def ev_switch(tau, y):
        return y[3] - ln_switch

    ev_switch.terminal = True
    ev_switch.direction = 1.0
    events = [ev_stop, ev_end]
    if ln_switch is not None:
        events.append(ev_switch)
    # solve_ivp evaluates every event once per accepted step (and once at the start); this
    # one never changes sign and only counts the steps, so that max_steps bounds the work
    # inside one call too (a chunk alone may take unboundedly many steps)
    taken = []

    def ev_watch(tau, y):
        taken.append(y.copy())
        if steps + len(taken) - 1 > steps_left:
            raise _StepBudget
        return 1.0

    events.append(ev_watch)
    atol = np.full(10, rtol * 1e-2)
    implicit = method in ("Radau", "BDF", "LSODA")
    if implicit:
        # the kernel's quadrature noise (~1e-13) times the long τ-steps an implicit method
        # takes near a threshold would defeat a tighter bound on u
        atol[:3] = max(atol[0], 1e-10)
    tau0 = 0.0
    chunk = 1e4
    rec = []
    steps = 0
    y = y0
    while True:
        extra = {"jac": prob.jac} if implicit else {}
        taken.clear()
        try:
            sol = solve_ivp(
                prob.rhs,
                (tau0, tau0 + chunk),
                y,
                method=method,
                rtol=rtol,
                atol=atol,
                events=events,
                max_step=h_max,
                **extra,
            )
        except _StepBudget:  # the accepted steps so far, the last one as reached
            rec.extend(taken[1:])
            steps += len(taken) - 1
            return (taken[-1] if taken else y), rec, steps, "max_steps"
        steps += sol.t.size - 1
        y = sol.y[:, -1].copy()
        if sol.status == -1:  # the integrator gave up: the values as reached, and why
            rec.extend(sol.y[:, 1:].T)
            prob.failure = str(sol.message)
            return y, rec, steps, "failed"
        if sol.status == 1:
            rec.extend(sol.y[:, 1:-1].T)
            if sol.t_events[0].size:
                ye = sol.y_events[0][0].copy()
                # closed-form tail of the approach to rest: t += s/|u·X|
                u = ye[0:3] / np.linalg.norm(ye[0:3])
                ax, ay, am = prob.friction_acc(u[0], u[1], u[2], ye[7], ye[4])
                bx, by, bm = prob.b(ye[4], ye[7])
                rate = -(u[0] * (ax + bx) + u[1] * (ay + by) + u[2] * (am + bm))
                s = math.exp(ye[3])
                if rate > 0.0:
                    ye[4] += s / rate
                    ye[5:8] += 0.5 * s * s / rate * np.array([u[0], u[1], u[2] / prob.k])
                rec.append(ye)
                return ye, rec, steps, "stop"
            if sol.t_events[1].size:
                ye = sol.y_events[1][0].copy()
                rec.append(ye)
                return ye, rec, steps, "t_end"
            ye = sol.y_events[2][0].copy()
            rec.append(ye)
            return ye, rec, steps, "switch"
        rec.extend(sol.y[:, 1:].T)
        if steps >= steps_left:
            return y, rec, steps, "max_steps"
        tau0 = sol.t[-1]
