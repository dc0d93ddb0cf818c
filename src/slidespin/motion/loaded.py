"""Motion of a loaded body: applied forces and torques, slopes, stick and slip (MODEL §11).

:func:`simulate_loaded` runs a body through its stick and slip phases, exactly (no
regularised friction): the slip equations of MODEL §5 with the applied accelerations added
(:mod:`slidespin.motion._loaded_problem`); the stick, held while the applied wrench lies in
the static-friction set C, its end, the slow start in the onset direction and the slip to
the next stop (:mod:`slidespin.motion._stick_slip`, which defines GAUGE_TOL, SCAN_STEP_MAX,
SCAN_POINTS_MAX and :func:`default_scan_step`; this module is their public home). The result
is a :class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory`.

Every patch: the ellipses and circles of the paper and the footprints of MODEL §10 (a
``Blade``, a line contact, included); the friction wrench comes from
:class:`slidespin.contact._engine.TwistWrench` (the elliptic or the exact footprint kernel)
and the static-friction set C from ``slidespin.contact.static_set.static_support``. Natural
units use the body's length unit (:attr:`slidespin.Body.length_unit`).

Energy: ΔKE = W_f + W_Q, reported as ``energy_error`` (an integration-accuracy check); on a
slope the gravity work m g sin α d·Δr is also computed from the displacement alone.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.static_set import check_anisotropy
from slidespin.contact.statics import OnsetNotFound
from slidespin.motion._loaded_problem import _Problem
from slidespin.motion._stick_slip import (
    GAUGE_TOL,
    SCAN_POINTS_MAX,
    SCAN_STEP_MAX,
    _quasi_static,
    _slip,
    _stick_exit,
    default_scan_step,
)
from slidespin.motion.loaded_trajectory import LoadedTrajectory
from slidespin.motion.loads import Load
from slidespin.motion.outcomes import (
    LOADED_ENDINGS as LOADED_ENDINGS,  # re-exported (older imports)
)
from slidespin.motion.state import State

__all__ = [
    "GAUGE_TOL",
    "SCAN_POINTS_MAX",
    "SCAN_STEP_MAX",
    "default_scan_step",
    "simulate_loaded",
]

_STOP_DROP = 1e-13  # the stop is declared when s has fallen below this fraction of its scale
STEADY_TOL = 1e-6  # relative change of the speed that would take the elapsed time: steady
_STIFF = 100.0  # relaxation-to-growth ratio above which a slip phase is integrated by Radau


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
        raise ValueError(f"load = {load!r} is invalid; valid values: a slidespin.Load or None")
    if incline is not None and not isinstance(incline, Incline):
        raise ValueError(
            f"incline = {incline!r} is invalid; valid values: a slidespin.Incline or None"
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
