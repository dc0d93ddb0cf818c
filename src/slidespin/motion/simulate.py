"""Integration of the motion to its stop (paper eq. 4, 8, 11; MODEL §4–5).

``simulate`` integrates the Newton–Euler equations of the body in the regularised time of
MODEL §5, in which the stop is reached smoothly instead of being approached by ever smaller
steps; it returns a :class:`Trajectory` with the paper's quantities: the speed v, the
direction ϑ of the velocity of G, β = v/ω (the distance from G to the instantaneous centre of
rotation), the friction components F_τ, F_n, M over time, the stop time, and the terminal
ratio β* with its direction ϑ* at the stop.

Any patch runs here: the paper's ellipses, and every footprint of MODEL §10 (polygons,
rectangles, disks, rings, pads, and a ``Blade``, a line contact). With an applied load, a
slope or a time bound, :func:`simulate` hands over to the stick–slip engine
(:func:`slidespin.motion.loaded.simulate_loaded`, MODEL §11), which takes the same patches.

Departures from the paper: the paper integrates in t with unstated tolerances and reads β at
the end; slidespin integrates in τ (dt = s dτ), so t_stop is the limit t(τ → ∞) and β*, ϑ*
are the converged terminal direction, not a value read at a cut-off speed; the last row of a
:class:`Trajectory` (the stop, where the velocity is zero and its direction is no longer
given by the state) holds these limits. Results are in SI units; the paper's eq. 7 scaling
has t = t₁√(aπ/g) (MODEL §7, erratum 2).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from slidespin import _validate as v
from slidespin.contact import _engine
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.speed_laws import law_is_constant
from slidespin.motion import _integrator
from slidespin.motion._law_motion import simulate_law
from slidespin.motion._stops import ENDING_TOL
from slidespin.motion.loads import Load
from slidespin.motion.outcomes import ENDINGS, STATUSES
from slidespin.motion.sensitivity import COLLOCATE_RTOL, check_parameters, check_setup
from slidespin.motion.sensitivity import compute as compute_sensitivities
from slidespin.motion.springs import Spring
from slidespin.motion.state import State
from slidespin.motion.trajectory import Trajectory

if TYPE_CHECKING:
    from slidespin.motion.loaded_trajectory import LoadedTrajectory
    from slidespin.motion.pushed_trajectory import PushedTrajectory
    from slidespin.motion.pushers import LinePusher, PointPusher

__all__ = ["simulate", "Trajectory", "ENDINGS", "STATUSES", "classify_ending", "status_name"]


#: largest step budget (the integrator counts steps in 64-bit integers; 1e9 steps of a few
#: microseconds each is already an hour)
MAX_STEPS_LIMIT = v.MAX_STEPS


def check_solver_options(rtol: float, max_steps: int) -> tuple[float, int]:
    """Validate ``rtol`` in (0, 1e-3] and ``max_steps`` an integer in [1, 1e9]."""
    rtol = v.in_range("rtol", rtol, 0.0, 1e-3, lo_open=True)
    if (
        isinstance(max_steps, bool)
        or not isinstance(max_steps, (int, np.integer))
        or not 1 <= max_steps <= MAX_STEPS_LIMIT
    ):
        raise ValueError(
            f"max_steps = {max_steps!r} is invalid; valid range: integer in [1, {MAX_STEPS_LIMIT}]"
        )
    return rtol, int(max_steps)


def status_name(code: int) -> str:
    """Status name (:data:`slidespin.motion.outcomes.STATUSES`) of an integrator status code; a
    spiral stop is ``stopped`` (its ending says ``spiral``)."""
    code = int(code)
    return "stopped" if code == _integrator.ST_SPIRAL else STATUSES[code]


def classify_ending(u_plane: float, u_spin: float, tol: float = ENDING_TOL) -> str:
    """Kind of terminal motion from the converged direction u* = (u₁₂, u₃) (MODEL §5).

    ``pure_sliding`` when u₃* = 0 (ω/v → 0), ``pure_spinning`` when u₁₂* = 0 (v/ω → 0),
    ``mixed`` otherwise (v = β ω with finite β ≠ 0).
    """
    if abs(u_spin) <= tol:
        return "pure_sliding"
    if abs(u_plane) <= tol:
        return "pure_spinning"
    return "mixed"


def _beta(u_plane: ArrayLike, u_spin: ArrayLike, k: float) -> NDArray[np.float64]:
    """β = v/ω = k u₁₂/u₃ (±inf for ω = 0, and where it overflows: a spin below 1e-308 of
    the speed)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        b = k * np.asarray(u_plane) / np.asarray(u_spin)
    return np.where(np.asarray(u_spin) == 0.0, np.inf, b)


@overload
def simulate(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    g: float = ...,
    rtol: float = ...,
    *,
    max_steps: int = ...,
    max_step: float | None = ...,
    load: None = ...,
    incline: None = ...,
    t_end: None = ...,
    scan_step: float | None = ...,
    pusher: None = ...,
    outline: None = ...,
    sensitivities: Sequence[str] | None = ...,
) -> Trajectory: ...


@overload
def simulate(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    g: float = ...,
    rtol: float = ...,
    *,
    max_steps: int = ...,
    max_step: float | None = ...,
    load: Load | Spring | list | tuple,
    incline: Incline | None = ...,
    t_end: float | None = ...,
    scan_step: float | None = ...,
    pusher: None = ...,
    outline: None = ...,
) -> LoadedTrajectory: ...


@overload
def simulate(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    g: float = ...,
    rtol: float = ...,
    *,
    max_steps: int = ...,
    max_step: float | None = ...,
    load: Load | Spring | list | tuple | None = ...,
    incline: Incline,
    t_end: float | None = ...,
    scan_step: float | None = ...,
    pusher: None = ...,
    outline: None = ...,
) -> LoadedTrajectory: ...


@overload
def simulate(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    g: float = ...,
    rtol: float = ...,
    *,
    max_steps: int = ...,
    max_step: float | None = ...,
    load: Load | Spring | list | tuple | None = ...,
    incline: Incline | None = ...,
    t_end: float,
    scan_step: float | None = ...,
    pusher: None = ...,
    outline: None = ...,
) -> LoadedTrajectory: ...


@overload
def simulate(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    g: float = ...,
    rtol: float = ...,
    *,
    max_steps: int = ...,
    max_step: float | None = ...,
    load: Load | Spring | list | tuple | None = ...,
    incline: Incline | None = ...,
    t_end: float | None = ...,
    scan_step: float | None = ...,
    pusher: PointPusher | LinePusher,
    outline: Any = ...,
    sensitivities: None = ...,
) -> PushedTrajectory: ...


@overload
def simulate(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    g: float = ...,
    rtol: float = ...,
    *,
    max_steps: int = ...,
    max_step: float | None = ...,
    load: Load | Spring | list | tuple | None = ...,
    incline: Incline | None = ...,
    t_end: float | None = ...,
    scan_step: float | None = ...,
    pusher: PointPusher | LinePusher | None = ...,
    outline: Any = ...,
    sensitivities: Sequence[str] | None = ...,
) -> Trajectory | LoadedTrajectory | PushedTrajectory: ...


def simulate(
    body: Body,
    friction: FrictionTensor,
    initial_state: State,
    g: float = 9.81,
    rtol: float = 1e-10,
    *,
    max_steps: int = 200_000,
    max_step: float | None = None,
    load: Load | Spring | list | tuple | None = None,
    incline: Incline | None = None,
    t_end: float | None = None,
    scan_step: float | None = None,
    pusher: PointPusher | LinePusher | None = None,
    outline: Any = None,
    sensitivities: Sequence[str] | None = None,
) -> Trajectory | LoadedTrajectory | PushedTrajectory:
    """Integrate the motion of ``body`` from ``initial_state`` until it stops.

    Parameters
    ----------
    body : Body
        Patch, pressure law, mass and moment of inertia. Any patch: an ellipse (the paper's),
        or any footprint of :mod:`slidespin.contact.shapes` (``Polygon``, ``Rectangle``,
        ``Disk``, ``Annulus``, ``Pads``, and ``Blade``, a line contact under a uniform line
        load), with or without a load. A ``PressureMap`` is refused with a ``ValueError``
        (it works with :func:`slidespin.friction_wrench` only).
    friction : FrictionTensor
        Friction tensor (plane- or body-fixed).
    initial_state : State
        Initial position, angle and velocities (SI).
    g : float, default 9.81
        Gravitational acceleration [m/s²], in [1e-6, 1e6].
    rtol : float, default 1e-10
        Relative (and, in natural units, absolute) tolerance of the integrator, in (0, 1e-3].
        The stop values carry the integration's global error: measured over random cases,
        t_stop, β* and ϑ* change by less than 1e-6 (relative, resp. rad) between rtol 1e-10
        and 1e-12, and by up to ~1e3·rtol at looser tolerances; the ending does not change.
    max_steps : int, default 200000
        Step budget, at most 1e9; if exhausted, ``status`` is ``"max_steps"`` and the stop
        values are those reached.
    max_step : float or None
        Largest step in the regularised time τ (dimensionless); smaller values give more
        points along the trajectory (for plotting and CSV export; ``slidespin demo`` uses
        0.05, about 1000 points), not more accuracy. By default only the integrator's own
        steps are recorded (about 40 for the demo), which is enough for the stop values.

    load : Load, Spring or a list of them, optional
        Applied force and torque (constant, tabulated, or functions of time:
        :mod:`slidespin.motion.loads`; a Python function is about 70 times slower than the same
        load tabulated with :meth:`~slidespin.motion.loads.Load.piecewise_linear`, see
        :class:`~slidespin.motion.loads.Load`); a :class:`~slidespin.Spring` to an anchor on a
        prescribed path (:mod:`slidespin.motion.springs`), alone or in a list with loads.
    incline : Incline, optional
        A tilted plane: normal load m g cos α, downhill pull m g sin α.
    t_end : float, optional
        Time bound [s]; a loaded body need not stop.
    scan_step : float, optional
        Step [s] of the scan for the moment a load varying in time (a callable) overcomes
        static friction; see :func:`slidespin.motion.loaded.simulate_loaded`. By default at most
        :data:`slidespin.motion.loaded.SCAN_STEP_MAX` = 1 ms (for runs up to 200 s); an excursion
        of a callable load beyond static friction lasting longer than the step is always
        found. Piecewise-linear loads are also checked at every sample time.
    pusher : PointPusher or LinePusher, optional
        A pusher with a prescribed motion (MODEL §13): the contact decides the force. Needs
        ``t_end``; runs :func:`slidespin.motion.pushed.simulate_pushed` (with ``load`` and
        ``incline`` if given; ``max_step`` and ``scan_step`` do not apply and are refused).
    outline : array_like (n, 2), Ellipse or None, optional
        With a pusher: the outline the pusher touches, in the body frame [m] (a polygon's
        vertices, or an ellipse), when the body is wider than its contact patch; default the
        footprint's convex hull (:func:`slidespin.contact.outline.body_outline`). Refused
        without a pusher.
    sensitivities : sequence of str, optional
        Parameters to differentiate the motion with respect to (MODEL §15): any of ``fx``,
        ``fy``, ``f``, ``xi_c``, ``eta_c``, ``moment_of_inertia``, ``vx``, ``vy``,
        ``omega`` (the last three of the start), also ``angle`` (the tensor's) and ``phi0``
        (the start's body angle). The variational equations are solved along the motion, by
        collocation on the plain run's own steps (:mod:`slidespin.motion.sensitivity`), and the trajectory's ``sensitivities`` holds
        ∂q(t)/∂θ along it and the stop's derivatives (t_stop, the stop pose, β*). Free
        motion under a constant law only (refused with a load, a slope, ``t_end``, a pusher,
        a speed law or a tall body), for a motion that stops (status ``stopped``; a
        spiral's β* has no derivative: NaN).

    Returns
    -------
    Trajectory, LoadedTrajectory or PushedTrajectory
        A :class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory` (with stick and slip
        phases and the energy balance) when ``load``, ``incline`` or ``t_end`` is given, and
        for a tall body (``Body(..., height=h)`` under a constant law, MODEL §14: its status
        is ``ok`` or ``tipping``, its ending ``stopped_stuck`` where a thin body's run says
        ``stopped``): see :func:`slidespin.motion.loaded.simulate_loaded` (every patch that
        runs without a load, the ``Blade`` included). Otherwise a :class:`Trajectory`, whose last row is
        the stop and holds the terminal values (ϑ*, β*) as limits along the motion. A
        :class:`~slidespin.motion.pushed_trajectory.PushedTrajectory` (the pusher's force,
        the contact point and mode over time, the energy balance) when ``pusher`` is given.

    Notes
    -----
    Integrates paper eq. 4 (eq. 8 and 11 are its semi-analytic forms for the uniform and
    linear laws) in the regularised time of MODEL §5 with a compiled DOP853 integrator.

    Examples
    --------
    >>> from slidespin import Body, Ellipse, UniformPressure, FrictionTensor, State
    >>> body = Body(Ellipse.from_eccentricity(0.1, 0.866), UniformPressure(), mass=1.0)
    >>> tr = simulate(body, FrictionTensor(0.42, 0.54), State.from_speed(1.0, 5.0, 0.785))
    >>> tr.status, tr.ending
    ('stopped', 'mixed')
    """
    if not isinstance(body, Body):
        raise ValueError(f"body = {body!r} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    if not isinstance(initial_state, State):
        raise ValueError(
            f"initial_state = {initial_state!r} is invalid; valid values: a slidespin.State"
        )
    for name, val in (("g", g), ("rtol", rtol)):
        if isinstance(val, (Load, Incline)):  # simulate(body, friction, state, load)
            raise ValueError(
                f"{name} = {v._short(val)} is invalid: the 4th and 5th positional arguments "
                "are g and rtol (valid values: g in [1e-06, 1e+06] m/s^2, rtol in (0, "
                "0.001]); pass load=, incline=, t_end= by keyword, e.g. "
                "simulate(body, friction, state, load=load, t_end=2.0)"
            )
    if sensitivities is not None:
        sensitivities = check_parameters(sensitivities)
        _check_differentiable(body, friction, load, incline, t_end, pusher)
        check_setup(body, sensitivities)
    if pusher is not None:
        return _pushed(body, friction, initial_state, g, rtol, max_steps, max_step, load,
                       incline, t_end, scan_step, pusher, outline)  # fmt: skip
    if outline is not None:
        raise ValueError(
            f"outline = {v._short(outline)} is invalid without a pusher (it is the outline a "
            "pusher touches); valid values: None"
        )
    if load is not None or incline is not None or t_end is not None or _tall(body, friction):
        # applied loads, a tilted plane, a time bound or a tall body (its pressure moves
        # with the friction force, MODEL §14): the stick-slip engine (MODEL §11),
        # imported when first needed (a free run's first demo need not load it: ~0.1 s)
        from slidespin.motion.loaded import simulate_loaded

        return simulate_loaded(
            body,
            friction,
            initial_state,
            load=load,
            incline=incline,
            t_end=t_end,
            g=g,
            rtol=rtol,
            max_steps=max_steps,
            max_step=max_step,
            scan_step=scan_step,
        )
    if scan_step is not None:
        raise ValueError(
            f"scan_step = {v._short(scan_step)} is invalid without load, incline or t_end "
            "(it only applies to the stick-slip engine); valid values: None"
        )
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    rtol, max_steps = check_solver_options(rtol, max_steps)
    h_max = math.inf if max_step is None else v.positive("max_step", max_step)

    a = body.length_unit  # the semi-axis, or a footprint's extent
    t_unit = math.sqrt(a / g)
    v_unit = math.sqrt(a * g)
    s0 = initial_state
    if not law_is_constant(friction.speed_law) and (s0.vx, s0.vy, s0.omega) != (0.0, 0.0, 0.0):
        return simulate_law(body, friction, s0, g, rtol, max_steps, h_max, classify_ending)
    par, fe, fc, geo = body.engine_params(friction.kinetic)
    k = par[_engine.P_K]
    vxn, vyn, wn = s0.vx / v_unit, s0.vy / v_unit, s0.omega * t_unit
    speed0 = math.sqrt(vxn * vxn + vyn * vyn + (k * wn) ** 2)
    if speed0 == 0.0 and sensitivities is not None:
        raise ValueError(
            f"initial_state = {initial_state!r} is at rest: there is no motion to "
            "differentiate (sensitivities); valid values: a state that moves"
        )
    if speed0 == 0.0:
        one = lambda x: np.array([float(x)])  # noqa: E731
        return Trajectory(
            t=one(0.0),
            x=one(s0.x),
            y=one(s0.y),
            phi=one(s0.phi),
            vx=one(0.0),
            vy=one(0.0),
            omega=one(0.0),
            speed=one(0.0),
            theta=one(math.nan),  # no motion, no direction: ϑ* is NaN
            beta=one(math.nan),
            tangential=one(0.0),
            normal=one(0.0),
            moment_paper=one(0.0),
            path_length=one(0.0),
            t_stop=0.0,
            stop_state=State(s0.x, s0.y, s0.phi),
            beta_stop=math.nan,
            theta_stop=math.nan,
            ending="at_rest",
            status="at_rest",
            n_steps=0,
            n_rhs=0,
            body=body,
            friction=friction,
            initial_state=initial_state,
            g=g,
        )
    y0 = np.array(
        [
            vxn / speed0,
            vyn / speed0,
            k * wn / speed0,
            math.log(speed0),
            0.0,
            s0.x / a,
            s0.y / a,
            s0.phi,
            0.0,
        ]
    )
    # the sensitivities' collocation needs the steps' stages (their dense output)
    stages = sensitivities is not None and rtol <= COLLOCATE_RTOL
    yend, status, nsteps, nrhs, fails, rate, rec, term = _integrator.integrate_on(
        par, fe, fc, geo, y0, rtol, rtol, rtol, min(rtol, 1e-8), int(max_steps), h_max, True,
        stages,
    )  # fmt: skip
    if fails:  # pragma: no cover - guard, not reached in tests
        raise RuntimeError(
            f"simulate: {fails} wrench evaluations missed their error target; please report"
        )
    rows = np.vstack([rec[:, 1 : 1 + yend.size], yend[None, :]])
    u1, u2, u3 = rows[:, 0], rows[:, 1], rows[:, 2]
    s = np.exp(rows[:, 3])  # 0 at the stop
    fx, fy, mm = _integrator.wrench_rows(par, fe, fc, geo, rows[:, 7], u1, u2, u3 / k)
    weight = body.mass * g  # the normal load m g [N]
    u12 = np.hypot(u1, u2)
    theta = np.arctan2(u2, u1)
    beta = _beta(u12, u3, k) * a
    ending, beta_stop, theta_stop = _terminal_values(
        status, math.hypot(yend[0], yend[1]), yend[2], term[0], term[3]
    )
    beta_stop *= a
    # the stop row (v = 0, where atan2(0, 0) = 0 is no direction) holds the limits along the
    # motion (MODEL §5, §9): ϑ* (NaN where there is none) and β*
    reached = theta[-1]
    theta[-1] = theta_stop
    beta[-1] = beta_stop
    # the wrench's components along the direction of motion: at the stop along ϑ* where it
    # exists, else along the last direction reached (a spiral's)
    c, sn = np.cos(theta), np.sin(theta)
    if not math.isfinite(theta_stop):
        c[-1], sn[-1] = np.cos(reached), np.sin(reached)
    tangential = -(fx * c + fy * sn) * weight
    normal = -(-fx * sn + fy * c) * weight
    if ending == "pure_spinning" and not math.isfinite(theta_stop):
        # the net force vanishes at a pure-spinning fixed point (A(u*) ∥ u* = (0, 0, ±1)):
        # F_τ and F_n tend to 0 whatever the vanishing velocity's direction does
        tangential[-1] = normal[-1] = 0.0
    stop = State(yend[5] * a, yend[6] * a, yend[7])
    sens = None
    if sensitivities is not None:
        if status_name(status) != "stopped":
            raise ValueError(
                f"sensitivities = {sensitivities!r} cannot be computed for this motion: it "
                f"ends with status {status_name(status)!r}, ending {ending!r}; valid: a "
                "motion that stops (status 'stopped')"
            )
        accel = np.column_stack([fx, fy, mm / k])
        sens = compute_sensitivities(
            body, friction, initial_state, sensitivities, g, rtol, ending, float(term[2]),
            rec[:, 0], rows, accel, rec if stages else None, (par, fe, fc, geo),
        )  # fmt: skip
    return Trajectory(
        t=rows[:, 4] * t_unit,
        x=rows[:, 5] * a,
        y=rows[:, 6] * a,
        phi=rows[:, 7].copy(),
        vx=s * u1 * v_unit,
        vy=s * u2 * v_unit,
        omega=s * u3 / k / t_unit,
        speed=s * u12 * v_unit,
        theta=theta,
        beta=beta,
        tangential=tangential,
        normal=normal,
        moment_paper=-mm * weight * a,
        path_length=rows[:, 8] * a,
        t_stop=float(yend[4] * t_unit),
        stop_state=stop,
        beta_stop=beta_stop,
        theta_stop=theta_stop,
        ending=ending,
        status=status_name(status),
        n_steps=int(nsteps),
        n_rhs=int(nrhs),
        saddle_energy=math.exp(2.0 * term[1]) if math.isfinite(term[1]) else math.nan,
        eigenvalue_ratio=float(term[2]),
        body=body,
        friction=friction,
        initial_state=initial_state,
        g=g,
        sensitivities=sens,
    )


def _check_differentiable(body, friction, load, incline, t_end, pusher) -> None:
    """Refuse ``sensitivities=`` where they are not built: loaded, inclined, bounded or
    pushed runs, speed laws and tall bodies (MODEL §15 covers free motion here)."""
    for name, val in (("load", load), ("incline", incline), ("t_end", t_end),
                      ("pusher", pusher)):  # fmt: skip
        if val is not None:
            raise ValueError(
                f"{name} = {v._short(val)} is invalid with sensitivities (they are computed "
                "for free motion under a constant friction law only); valid values: None"
            )
    if not law_is_constant(friction.speed_law) or _tall(body, friction):
        raise ValueError(
            "sensitivities are computed for a thin body under a constant friction law only; "
            f"friction.speed_law = {friction.speed_law!r}, body.height = {body.height!r} m "
            "(valid: speed_law None, height 0)"
        )


def _terminal_values(
    status: int, u12: float, u3: float, theta_star: float, beta_nat: float
) -> tuple[str, float, float]:
    """(ending, β*/a, ϑ*) of a stop from its reported direction (|u₁₂|, u₃) and the
    integrator's ϑ* and k u₁₂/u₃ (MODEL §5, §9)."""
    status = int(status)
    if status == _integrator.ST_SPIRAL:
        # the direction of motion turns for ever while the body stops: no terminal direction
        return "spiral", float(beta_nat), math.nan  # inf if the spin dies out, else NaN
    ending = classify_ending(u12, u3)
    if status in (_integrator.ST_STOPPED, _integrator.ST_MARGINAL, _integrator.ST_SADDLE):
        if ending == "pure_sliding":
            return ending, math.inf, float(theta_star)  # the sign of a vanishing ω is noise
        if ending == "pure_spinning":
            return ending, 0.0, float(theta_star)
    # mixed, or not converged: the direction as reached
    return ending, float(beta_nat), float(theta_star)


def _pushed(body, friction, state, g, rtol, max_steps, max_step, load, incline, t_end, scan_step,
            pusher, outline):  # fmt: skip
    """``simulate(..., pusher=...)``: the pushed dynamics (MODEL §13), after the checks that
    belong to ``simulate``'s own options."""
    # imported when first needed, like the loaded engine
    from slidespin.motion.pushed import simulate_pushed

    if t_end is None:
        raise ValueError(
            "t_end = None is invalid with a pusher (a pushed body need not stop); valid "
            f"values: a time bound in (0, {v.T_END:g}] s, e.g. the end of the pusher's path"
        )
    for name, val in (("max_step", max_step), ("scan_step", scan_step)):
        if val is not None:
            raise ValueError(
                f"{name} = {v._short(val)} is invalid with a pusher (it applies to free and "
                "loaded runs only); valid values: None"
            )
    return simulate_pushed(
        body, friction, state, pusher, t_end, g=g, rtol=rtol, max_steps=max_steps, load=load,
        incline=incline, outline=outline,
    )  # fmt: skip


def _tall(body, friction) -> bool:
    """A tall body (MODEL §14) under a constant law: it runs on the stick-slip engine's
    Python path (under a speed law, free motion runs on the law's integrator)."""
    law = getattr(friction, "speed_law", None)
    return isinstance(body, Body) and body.height > 0.0 and law_is_constant(law)
