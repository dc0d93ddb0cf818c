"""Motion of a loaded body: applied forces and torques, slopes, stick and slip (MODEL §11).

:func:`simulate_loaded` runs a body through its stick and slip phases, exactly (no
regularised friction): the slip equations of MODEL §5 with the applied accelerations added
(:mod:`slidespin.motion._loaded_problem`); the stick, held while the applied wrench lies in
the static-friction set C, its end, the slow start in the onset direction and the slip to
the next stop (:mod:`slidespin.motion._stick_slip`, which defines GAUGE_TOL, SCAN_STEP_MAX,
SCAN_POINTS_MAX, SCAN_SAMPLES_MAX and :func:`default_scan_step`; this module is their public
home). The result is a :class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory`.

Two engines integrate the slip phases, the same equations to the same tolerances:

* the compiled engine (:mod:`slidespin.motion._loaded_engine`), for every load and tilt
  given as a table (constant, :meth:`Load.piecewise_linear`, a case file's ``[load]``
  profile, :meth:`Incline.piecewise_linear`): Dormand–Prince 8(5,3) and Radau IIA in
  compiled code, the load evaluated from its knots, the knots and ``t_end`` landed on
  exactly; a pushed box (stick, slip, stick) takes about 2 ms (it took 0.3 to 0.8 s);
* the Python path (:class:`slidespin.motion._stick_slip.PythonSlip`), for a load or tilt
  given as a Python function, which compiled code cannot call: ``scipy.integrate.solve_ivp``
  with Python right-hand sides, correct but about a hundred times slower (``method="scipy"``
  asks for it for any load).

Either way the statics (does the body hold, when does the load leave C, in which direction
does it start) are those of :mod:`slidespin.contact.statics`, called a handful of times per
phase.

Every patch: the ellipses and circles of the paper and the footprints of MODEL §10 (a
``Blade``, a line contact, included); the friction wrench comes from the elliptic or the
exact footprint kernel (:func:`slidespin.contact._engine.accelerations` in compiled code,
:class:`slidespin.contact._engine.TwistWrench` in Python) and the static-friction set C from
``slidespin.contact.static_set.static_support``. Natural units use the body's length unit
(:attr:`slidespin.Body.length_unit`).

Bounded work: ``max_steps`` counts the steps of every integration of the run (the slow
starts included) and ``max_phases`` its stick and slip phases; either ends the run with its
status and the values reached. A scan of the stick phases finer than SCAN_SAMPLES_MAX
samples per run (t_end / scan_step) is refused before any work (``simulate`` passes
``scan_step`` here unchecked).

Energy: ΔKE = W_f + W_Q, reported as ``energy_error`` (an integration-accuracy check); on a
slope the gravity work m g sin α d·Δr is also computed from the displacement alone.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin._validate import _short
from slidespin.contact._profile import Profile
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.static_set import check_anisotropy
from slidespin.contact.statics import OnsetNotFound
from slidespin.motion._loaded_engine import CompiledSlip
from slidespin.motion._loaded_flow import load_table
from slidespin.motion._loaded_problem import _Problem
from slidespin.motion._stick_slip import (
    GAUGE_TOL,
    SCAN_POINTS_MAX,
    SCAN_SAMPLES_MAX,
    SCAN_STEP_MAX,
    PythonSlip,
    _stick_exit,
    default_scan_step,
)
from slidespin.motion.loaded_trajectory import LoadedTrajectory
from slidespin.motion.loads import Load
from slidespin.motion.outcomes import (
    LOADED_ENDINGS as LOADED_ENDINGS,  # re-exported (older imports)
)
from slidespin.motion.springs import Spring, split_loads
from slidespin.motion.state import State

__all__ = [
    "GAUGE_TOL",
    "METHODS",
    "NeverStops",
    "SCAN_POINTS_MAX",
    "SCAN_SAMPLES_MAX",
    "SCAN_STEP_MAX",
    "default_scan_step",
    "simulate_loaded",
]


class NeverStops(ValueError):
    """A run without ``t_end`` under a load (or a slope) that static friction cannot hold:
    the body need never stop.

    Attributes
    ----------
    load_factor : float
        λ* < 1 at the start: the applied wrench would have to shrink by this factor to be
        held (:func:`slidespin.load_factor`).
    """

    def __init__(self, message: str, load_factor: float) -> None:
        super().__init__(message)
        self.load_factor = load_factor


_STOP_DROP = 1e-13  # the stop is declared when s has fallen below this fraction of its scale
STEADY_TOL = 1e-6  # relative change of the speed that would take the elapsed time: steady
#: values of ``method``: the compiled engine (``auto`` where the load is a table), the Python
#: path with solve_ivp (``scipy``: Radau while stiff, DOP853 otherwise; or one named method)
METHODS = ("auto", "compiled", "scipy", "radau", "dop853", "lsoda", "bdf", "rk45")
_SCIPY = {
    "auto": "auto",
    "compiled": "auto",
    "scipy": "auto",
    "radau": "Radau",
    "dop853": "DOP853",
    "lsoda": "LSODA",
    "bdf": "BDF",
    "rk45": "RK45",
}


def simulate_loaded(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    load: Load | Spring | list | tuple | None = None,
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
    load : Load, Spring, a list of them, or None
        Applied force and torque, constant or functions of time; a
        :class:`~slidespin.Spring` to an anchor on a prescribed path (a force that depends on
        the body's position and velocity, MODEL §14), alone or in a list with other loads
        and springs (their wrenches add; springs run on the Python path).
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
        units), in (0, 1e-3].
    method : str, default "auto"
        The engine of the slip phases. ``"auto"``: the compiled engine for a load and a tilt
        given as tables (constant or piecewise linear), the Python path otherwise (a
        function of time). ``"compiled"``: the compiled engine (a ``ValueError`` for a
        function of time). ``"scipy"``: the Python path, :func:`scipy.integrate.solve_ivp`
        with ``Radau`` (implicit, difference Jacobian) for a slip from rest while it is
        stiff and ``DOP853`` otherwise; ``"radau"``, ``"dop853"``, ``"lsoda"``, ``"bdf"``,
        ``"rk45"``: the Python path with that solve_ivp method throughout. Both engines
        integrate the same equations to ``rtol`` and locate the same events; the compiled
        one is about a hundred times faster (the Python path: about 20 µs per right-hand
        side, 85 % of it Python).
    max_step : float or None
        Largest step in the regularised time τ (more recorded points for plots); in the
        time t, the compiled engine's steps are at most ``max_step`` times the speed s
        (natural units), the same bound.
    max_steps : int
        Budget of integrator steps over the whole run (the slow starts of the compiled
        engine included): when it runs out the run ends with status ``max_steps`` and the
        values reached (a box spun up for ever by a constant torque, say).
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
        costs little more than evaluating the load. A ``scan_step`` that asks for more
        than SCAN_SAMPLES_MAX = 10⁶ samples over the run (t_end / scan_step) is refused
        with a ``ValueError`` before any work.
    time_tol : float
        Accuracy [s] of the located stick-to-slip times (and of the events of the slow
        start); the stops are found by the integration itself, to its accuracy.
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
    time_load, springs = (None, ()) if load is None else split_loads(load)
    if incline is not None and not isinstance(incline, Incline):
        raise ValueError(
            f"incline = {incline!r} is invalid; valid values: a slidespin.Incline or None"
        )
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    rtol = v.in_range("rtol", rtol, 0.0, 1e-3, lo_open=True)
    method = v.choice("method", method, METHODS)
    prob = _Problem(body, friction, time_load, incline, g, springs)
    prob.hold_at((initial_state.x / prob.a, initial_state.y / prob.a))
    prob.b(0.0, initial_state.phi)  # the load's range, before any work
    tab = None if prob.python_only else load_table(prob)
    if method == "compiled" and prob.tall is not None:
        raise ValueError(
            f"method = 'compiled' is invalid for a tall body (height = {body.height!r} m): "
            "its pressure moves with the friction force (MODEL §14), which the Python path "
            "integrates; valid values here: 'auto', 'scipy', 'radau', 'dop853', 'lsoda', "
            "'bdf', 'rk45'"
        )
    if method == "compiled" and tab is None:
        raise ValueError(
            f"method = 'compiled' is invalid for load = {_short(load)} and incline = "
            f"{_short(incline)}: a load or tilt given as a Python function has no table; "
            "valid values here: 'auto', 'scipy', 'radau', 'dop853', 'lsoda', 'bdf', 'rk45'"
        )
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
    if scan is not None and not prob.constant and t_end is not None:
        samples = t_end_n / scan
        if not samples <= SCAN_SAMPLES_MAX:
            raise ValueError(
                f"scan_step = {scan_step!r} s with t_end = {t_end!r} s asks for a scan of "
                f"{samples:.3g} samples; valid: at most SCAN_SAMPLES_MAX = "
                f"{SCAN_SAMPLES_MAX:,} samples per run, i.e. scan_step >= t_end / "
                f"{SCAN_SAMPLES_MAX:g} = {t_end / SCAN_SAMPLES_MAX:.3g} s (or tabulate the "
                "load with Load.piecewise_linear: its knots are checked exactly)"
            )
    t_tol = v.positive("time_tol", time_tol, "s") / prob.t_unit
    for name, val in (("max_steps", max_steps), ("max_phases", max_phases)):
        if isinstance(val, bool) or not isinstance(val, (int, np.integer)) or val < 1:
            raise ValueError(f"{name} = {val!r} is invalid; valid range: integer >= 1")
    if tab is not None and t_end is not None:
        _check_knots(prob, t_end_n, initial_state.phi)

    if math.isinf(t_end_n) and prob.gauge(0.0, initial_state.phi) > 1.0 + GAUGE_TOL:
        factor = 1.0 / prob.gauge(0.0, initial_state.phi)
        raise NeverStops(
            "t_end = None is invalid here: the load exceeds what static friction can hold "
            f"(load factor {factor:.6g} < 1), so the body need never stop; give t_end [s]",
            factor,
        )
    slow_n = slow_speed / prob.v_unit
    engine: CompiledSlip | PythonSlip
    if tab is not None and method in ("auto", "compiled"):
        engine = CompiledSlip(prob, tab, rtol, h_max, slow_n, t_tol)
        w_many = engine.w_many
    else:
        engine = PythonSlip(prob, _SCIPY[method], rtol, h_max, slow_n)
        w_many = None
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
    tip_time = None
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
        from_rest = speed == 0.0
        if from_rest:
            prob.hold_at(pos)
            # ---- at rest: does static friction hold? ----
            g_here = prob.gauge(t, pos[2])
            if g_here <= 1.0 + GAUGE_TOL:
                t_exit = _stick_exit(prob, t, pos[2], t_end_n, scan, t_tol, w_many, g_here)
                t_stop_stick = t_end_n if t_exit is None else t_exit
                if math.isinf(t_stop_stick):  # no t_end: the run ends when the body sticks
                    break
                phases.append(["stick", t, t_stop_stick])
                t = t_stop_stick
                record(t, pos, vel, work)
                if t_exit is None:
                    break
                prob.gauge(t, pos[2])  # which way it leaves: slides, or tips
            if prob.tipped:  # a tall body at rest tips before it slides (MODEL §14)
                status, tip_time = "tipping", t
                message = _tip_message(t * prob.t_unit, "at rest")
                break
            # ---- onset: the slow start, with u slaved to the onset direction ----
            t_phase0 = t
            try:
                u_onset = engine.onset(t, pos[2])
                qs = engine.slow_start(t, pos, work, u_onset, t_end_n, steps_left)
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
            t, pos, work, s_now, u, reason, rec, nst = qs
            steps_left -= nst
            rows.extend(rec)
            if reason in ("failed", "max_steps"):
                vel = s_now * u
                phases.append(["slip", t_phase0, t])
                if reason == "failed":
                    status = "step_too_small"
                    message = (
                        f"the integrator of the slow start gave up at t = "
                        f"{t * prob.t_unit:.12g} s: {engine.failure}; values as reached"
                    )
                else:
                    status = "max_steps"
                    message = f"the budget of max_steps = {max_steps} integrator steps ran out"
                break
            if reason == "t_end" or s_now <= 0.0:
                vel = s_now * u
                phases.append(["slip", t_phase0, t])
                if s_now <= 0.0 and reason != "t_end":
                    vel = np.zeros(3)
                    continue
                break
            ln_stop = math.log(max(s_now, slow_n) * _STOP_DROP)
        else:
            moved = True
            t_phase0 = t
            u = vel / speed
            s_now = speed
            ln_stop = math.log(speed * _STOP_DROP)
        t, pos, work, vel, reason, rec, nst = engine.slip(
            u, s_now, t, pos, work, ln_stop, t_end_n, steps_left, from_rest
        )
        steps_left -= nst
        rows.extend(rec)
        phases.append(["slip", t_phase0, t])
        if reason == "tip":
            status, tip_time = "tipping", t
            message = _tip_message(t * prob.t_unit, "sliding")
            break
        if reason == "stop":
            vel = np.zeros(3)
            rows[-1][4:7] = 0.0
            if t >= t_end_n:
                break
            continue
        if reason == "max_steps":
            status = "max_steps"
            message = f"the budget of max_steps = {max_steps} integrator steps ran out"
        elif reason == "failed":
            status = "step_too_small"
            message = (
                f"the slip integrator gave up at t = {t * prob.t_unit:.12g} s: "
                f"{engine.failure}; values as reached"
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
            ax, ay, am = prob.friction_acc(u[0], u[1], u[2], arr[-1, 3], arr[-1, 0], speed_end)
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
        n_rhs=prob.n_rhs + engine.calls,
        body=body,
        friction=friction,
        initial_state=initial_state,
        load=load,
        incline=incline,
        g=g,
        message=message,
        tip_time=None if tip_time is None else float(tip_time * tu),
    )


def _tip_message(t, how):
    return (
        f"the tall body tips at t = {t:.12g} s ({how}): its pressure centroid reached the "
        "convex hull of the footprint (MODEL §14); the run ends there"
    )


def _check_knots(prob, t_end, phi):
    """The range of a tabulated load over the run, before any work: at the knot up to t_end
    where each profile is largest (the extremes of a piecewise-linear load), the load is
    checked as every evaluation checks it (:meth:`_Problem.b`, which raises a ValueError)."""
    load = prob.load
    if load is None or load.is_constant or not isinstance(load, Load):
        return  # (several loads, or springs, are checked as they are evaluated)
    mg = prob.body.mass * prob.g
    for col, scale in ((load.force, mg), (load.torque, mg * prob.a)):
        if not isinstance(col, Profile):
            continue
        times = np.asarray(col.times, dtype=float)
        n = int(np.searchsorted(times, t_end * prob.t_unit, side="right")) + 1
        size = np.sum(np.abs(np.asarray(col.columns, dtype=float)[:, :n]), axis=0) / scale
        prob.b(float(times[int(np.argmax(size))]) / prob.t_unit, phi)
