"""Aiming: the launch whose motion stops at a target pose (MODEL §15).

:func:`aim` finds the start velocities (any of vx, vy, ω, the others fixed) whose motion
stops with G at the target (x, y) and, if given, the body at the target angle φ, by a
Levenberg–Marquardt iteration. The miss is measured with :func:`slidespin.simulate` itself,
at the same tolerance, so the launch returned stops where ``simulate`` says it does. Its
Jacobian: for free motion of a thin body under a constant law, the stop's exact
sensitivities (:func:`slidespin.stop_sensitivities`: one sensitivity run per iteration);
under loads, springs or on a slope (MODEL §11), and for tall bodies and speed laws, whose
sensitivities are not built, central differences of whole simulations (two runs per free
component and iteration; the Jacobian only steers the iteration, the miss is exact). With a
load the stop is where the body first sticks (the run ``simulate`` makes without ``t_end``).
When no launch reaches the target, :class:`UnreachableTarget` says so, with the nearest stop
pose found.

The target angle is the body's total angle at the stop, as :func:`slidespin.simulate`
reports it (not reduced modulo 2π: a stone that turns one and a quarter times stops at
φ₀ + 5π/2). The angle's miss is weighted by the body's length unit ℓ, so that a miss of
1e-9 rad counts as 1e-9 ℓ in the least-squares miss (the nearest pose of an unreachable
target); a target is hit when x and y are within ``tol`` metres and φ within ``tol`` radians.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.speed_laws import law_is_constant
from slidespin.motion.loaded import NeverStops
from slidespin.motion.loaded_trajectory import LoadedTrajectory
from slidespin.motion.loads import Load
from slidespin.motion.simulate import simulate
from slidespin.motion.state import State

__all__ = ["aim", "UnreachableTarget", "AIM_FREE"]

#: the start's components :func:`aim` may solve for: the velocity of G as (vx, vy) or as
#: its ``speed`` [m/s] and ``direction`` [rad from OX] (not mixed), and the spin
AIM_FREE = ("vx", "vy", "omega", "speed", "direction")
_POLAR = ("speed", "direction")
#: default miss tolerance [m] (the angle's in units of ℓ)
TOL = 1e-10
MAX_ITER = 60
#: damping increases per Levenberg–Marquardt iteration before it gives up (λ × 4 each)
MAX_TRIES = 12
#: the smallest miss asked for, relative to the distances involved (round-off of the
#: positions and the integration's own error set a floor far from the origin)
REL_FLOOR = 1e-12
#: relative step of the central differences that give the Jacobian where the sensitivities
#: are not built (of the free component, or of its typical size): the simulations' own error
#: (rtol) over the step stays far below the Jacobian accuracy the iteration needs
DIFF_STEP = 1e-5
#: a miss below NOISE · rtol · distance is as near as the simulated stop is resolved (its
#: error grows with the distance slid): accepted, with a warning, when no closer one is found
NOISE = 10.0


class UnreachableTarget(ValueError):
    """No launch with the given free components stops at the target.

    Attributes
    ----------
    target : tuple of float
        The target (x, y[, φ]).
    nearest : State
        The nearest stop pose found (its velocities are zero).
    start : State
        The launch that stops there.
    miss : float
        The least-squares miss √(Δx² + Δy² + (ℓ Δφ)²) [m] (the angle's miss weighted by the
        body's length unit ℓ).
    position_miss, angle_miss : float
        The nearest stop's distance from the target's (x, y) [m] and its angle's miss [rad].
    """

    def __init__(self, message: str, target, nearest: State, start: State, miss: float):
        super().__init__(message)
        self.target = target
        self.nearest = nearest
        self.start = start
        self.miss = miss
        #: the distance of the nearest stop's G from the target (x, y) [m] (inf when no
        #: launch could be simulated: ``nearest`` is then the start)
        self.position_miss = math.hypot(nearest.x - target[0], nearest.y - target[1])
        #: its angle's miss [rad] (0 for a target without an angle)
        self.angle_miss = abs(nearest.phi - target[2]) if len(target) == 3 else 0.0
        if not math.isfinite(miss):
            self.position_miss = self.angle_miss = math.inf


def check_target(target) -> tuple[float, ...]:
    """Validate a target: (x, y) or (x, y, phi), finite numbers (not booleans)."""
    try:
        t = tuple(float(x) for x in target if not isinstance(x, (bool, np.bool_)))
        if len(t) != len(target):
            t = ()
    except (TypeError, ValueError):
        t = ()
    if len(t) not in (2, 3) or not all(math.isfinite(x) for x in t):
        raise ValueError(
            f"target = {v._short(target)} is invalid; valid values: (x, y) or (x, y, phi), "
            "finite, in m and rad"
        )
    return t


def _check_free(free) -> tuple[str, ...]:
    names = (free,) if isinstance(free, str) else tuple(free) if free is not None else ()
    if not names or len(set(names)) != len(names) or not all(n in AIM_FREE for n in names):
        raise ValueError(
            f"free = {v._short(free)} is invalid; valid values: a non-empty set of distinct "
            f"names among {', '.join(AIM_FREE)}"
        )
    if any(n in _POLAR for n in names) and any(n in ("vx", "vy") for n in names):
        raise ValueError(
            f"free = {v._short(free)} is invalid: it mixes vx, vy with speed, direction; "
            "valid values: the velocity as vx, vy or as speed, direction (with or without "
            "omega)"
        )
    return names


def _launch(start: State, names, q) -> State:
    """``start`` with the free components ``names`` set to ``q`` (speed and direction set
    the velocity of G in polar form, the other of the two kept from ``start``)."""
    vals = dict(zip(names, (float(x) for x in q)))
    if not any(n in _POLAR for n in names):
        return replace(start, **vals)
    speed = vals.get("speed", math.hypot(start.vx, start.vy))
    direction = vals.get("direction", math.atan2(start.vy, start.vx))
    omega = vals.get("omega", start.omega)
    return replace(start, vx=speed * math.cos(direction), vy=speed * math.sin(direction),
                   omega=omega)  # fmt: skip


def _components(state: State, names) -> np.ndarray:
    """The free components ``names`` of a state (polar ones from its velocity)."""
    polar = {"speed": math.hypot(state.vx, state.vy), "direction": math.atan2(state.vy, state.vx)}
    return np.array([polar[n] if n in _POLAR else getattr(state, n) for n in names])


def aim(
    body: Body,
    friction: FrictionTensor,
    target: Sequence[float],
    start: State | None = None,
    free: Sequence[str] = ("vx", "vy", "omega"),
    g: float = 9.81,
    rtol: float = 1e-10,
    tol: float = TOL,
    max_iter: int = MAX_ITER,
    *,
    load=None,
    incline: Incline | None = None,
    t_end: float | None = None,
) -> State:
    """The start whose motion stops at ``target`` (MODEL §15).

    Parameters
    ----------
    body : Body
        Any body :func:`slidespin.simulate` runs to a stop.
    friction : FrictionTensor
        Its friction (any law ``simulate`` runs).
    target : (x, y) or (x, y, phi)
        Where G must stop [m] and, if given, the body's total angle there [rad] (as
        ``simulate`` reports it: not reduced modulo 2π).
    start : State, optional
        The launch position and angle, and the velocities that are not ``free``; its free
        velocities, if not all zero, are the first guess. Default: at the origin, at rest.
    free : sequence of str, default ("vx", "vy", "omega")
        The start's components to solve for: any of ``vx``, ``vy``, ``omega``, or the
        velocity of G in polar form, ``speed`` [m/s] and ``direction`` [rad from OX] (with
        or without ``omega``; the other polar component kept from ``start``): e.g.
        ``free=("speed",)`` for how hard to throw along a given line (a negative speed
        found is a launch backwards along it).
    g : float, default 9.81
        Gravitational acceleration [m/s²].
    rtol : float, default 1e-10
        Tolerance of the simulations (use the same to check the result with ``simulate``).
    tol : float, default 1e-10
        Largest accepted miss in x and y [m] and in φ [rad], in [1e-14, 1]; at least 1e-12
        of the distances involved (the target's and the start's distance from the origin,
        the length unit), below which round-off of the positions sets the floor.
    max_iter : int, default 60
        Iterations per first guess.
    load : Load, Spring, list of them, or None
        Applied loads during the motion (as in :func:`slidespin.simulate`); the stop is where
        the body first sticks. Loads static friction cannot hold (the body need never stop)
        are refused.
    incline : Incline or None
        The plane's tilt (as in :func:`slidespin.simulate`), one static friction can hold.
    t_end : float or None
        With a load or tilt varying in time (which ``simulate`` runs to a given end): the
        time [s] at which the body must be at rest at the target; None: where it first
        sticks.

    Returns
    -------
    State
        The start: ``start`` with its free velocities solved for.

    Raises
    ------
    UnreachableTarget
        (a ``ValueError``) When no launch with these free components stops within ``tol``
        of the target; it holds the nearest stop pose found (``nearest``), its launch
        (``start``) and the miss.
    ValueError
        For invalid input.

    Notes
    -----
    Where several launches stop at the target (a spin of either sign, when only ω is free),
    the one found is the one reached from the first guess: give the free components a
    nonzero value in ``start`` to choose. A target (x, y) without an angle, with the velocity
    and the spin all free, has a launch for every spin: the one with the start's own spin is
    tried first (the spin free only if it cannot reach the target). A target hit means |Δx| ≤ ``tol``, |Δy| ≤ ``tol``
    and |Δφ| ≤ ``tol`` (so the straight-line miss is at most √2 ``tol``).

    Levenberg–Marquardt on the miss r(q) = (x_stop − x, y_stop − y, ℓ(φ_stop − φ)) over the
    free velocities q, with r from :func:`slidespin.simulate` and its Jacobian from the
    stop's sensitivities (:mod:`slidespin.motion.sensitivity`) or, where those are not built
    (loads, slopes, tall bodies, speed laws), central differences of whole simulations.
    First guesses: the free velocities of ``start`` if not all zero, then launches along the
    line to the target at the speed that stops there in pure translation (v² = 2 a d, with
    a = μ g cos α less the slope's and a constant load's pull along the line, when that is
    positive), with the spin that turns the body by Δφ over the same time (ω = Δφ v/d),
    scaled by 1, 0.7 and 1.4 (and, under a load or on a slope, by −1 and −0.5: a launch
    against the push).

    Examples
    --------
    >>> import slidespin as ss
    >>> body = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0)
    >>> s = ss.aim(body, ss.FrictionTensor(0.3, 0.3), target=(1.0, 0.5, 2.0))
    >>> tr = ss.simulate(body, ss.FrictionTensor(0.3, 0.3), s)
    >>> bool(abs(tr.stop_state.x - 1.0) < 1e-9 and abs(tr.stop_state.phi - 2.0) < 1e-9)
    True
    """
    if not isinstance(body, Body):
        raise ValueError(f"body = {body!r} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    tgt = check_target(target)
    names = _check_free(free)
    if start is None:
        start = State()
    if not isinstance(start, State):
        raise ValueError(f"start = {start!r} is invalid; valid values: a slidespin.State")
    tol = v.in_range("tol", tol, 1e-14, 1.0)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    rtol = v.in_range("rtol", rtol, 0.0, 1e-3, lo_open=True)
    if incline is not None and not isinstance(incline, Incline):
        raise ValueError(
            f"incline = {incline!r} is invalid; valid values: a slidespin.Incline or None"
        )
    # the stop's exact sensitivities where they are built; else central differences
    exact = (
        load is None and incline is None and body.height == 0.0
        and law_is_constant(friction.speed_law)
    )  # fmt: skip
    if t_end is not None and load is None and incline is None:
        raise ValueError(
            f"t_end = {t_end!r} is invalid without a load or an incline; valid: None (free "
            "motion runs to its stop)"
        )
    run = _Runs(body, friction, g, rtol, load, incline, t_end, exact)
    if isinstance(max_iter, bool) or not isinstance(max_iter, int) or not 1 <= max_iter <= 1000:
        raise ValueError(f"max_iter = {max_iter!r} is invalid; valid range: integer in [1, 1000]")
    if "direction" in names and "speed" not in names and start.vx == start.vy == 0.0:
        raise ValueError(
            f"free = {names!r} with start = {start!r}: the direction of a launch at zero speed "
            "moves nothing; valid: a start with a speed (vx, vy not both 0), or 'speed' free too"
        )
    ell = body.length_unit
    far = max(ell, abs(tgt[0]), abs(tgt[1]), abs(start.x), abs(start.y))
    turn = max(1.0, abs(start.phi), abs(tgt[2]) if len(tgt) == 3 else 0.0)
    tol = max(tol, REL_FLOOR * far, REL_FLOOR * turn * ell)
    zero = np.array([0.0 if n != "direction" else _components(start, names)[i]
                     for i, n in enumerate(names)])  # fmt: skip
    try:  # bad input (a load, a slope, a t_end) is refused here, before any aiming
        r, _, _ = _miss(run, tgt, start, names, zero, False)
    except _NoStop:  # the free components at zero do not end at rest: aim on
        r = np.full(len(tgt), np.inf)
    except NeverStops as exc:
        parts = [f"{k} = {x!r}" for k, x in (("load", load), ("incline", incline))
                 if x is not None]  # fmt: skip
        raise ValueError(
            f"{', '.join(parts)} {'is' if len(parts) == 1 else 'are'} invalid for aim: static "
            f"friction cannot hold the body against it (load factor {exc.load_factor:.6g} < 1), "
            "so the body need never stop; valid: loads and slopes that static friction can "
            "hold (load factor >= 1)"
        ) from None
    if _hit(r, ell, tol):  # the target is where the free components at zero stop
        return _launch(start, names, zero)
    best: tuple[float, State, State] | None = None
    # a target without an angle and a free spin: first the launch with the start's own spin
    # (any spin would do; this one adds none), then the spin free too
    attempts = [names]
    if len(tgt) == 2 and "omega" in names and len(names) == 3:
        attempts.insert(0, tuple(n for n in names if n != "omega"))
    for sub in attempts:
        for guess in _guesses(run, tgt, start, sub):
            q, miss, hit, pose = _solve(run, tgt, start, sub, guess, tol, max_iter)
            launch = _launch(start, sub, q)
            if hit:
                return launch
            if sub == names and miss <= NOISE * rtol * far:  # as near as simulate resolves
                warnings.warn(
                    f"target = {tgt!r} reached to {miss:.3g} m, not to tol = {tol:.3g} m: that "
                    f"is the resolution of the simulated stop this far out ({NOISE:g} rtol x "
                    f"{far:.3g} m; a smaller rtol resolves it better)",
                    RuntimeWarning,
                    stacklevel=2,
                )
                return launch
            if best is None or miss < best[0]:
                best = (miss, pose, launch)
    if best is None or best[1] is None:
        why = f" (the runs end otherwise: {run.no_stop})" if run.no_stop else ""
        raise UnreachableTarget(
            f"target = {tgt!r}: no launch from the first guesses could be simulated to a stop "
            f"while varying {', '.join(names)}{why}; valid: a target some launch reaches",
            tgt, start, start, math.inf,
        )  # fmt: skip
    miss, pose, launch = best
    wanted = f"({', '.join(f'{x:.10g}' for x in tgt)})"
    got = f"({pose.x:.10g}, {pose.y:.10g}" + (f", {pose.phi:.10g})" if len(tgt) == 3 else ")")
    raise UnreachableTarget(
        f"target = {wanted} cannot be reached by varying {', '.join(names)} (the other start "
        f"components fixed): the nearest stop found is {got}, {miss:.3g} m away"
        + (f" (the angle's miss weighted by the length unit {ell:.6g} m)" if len(tgt) == 3 else "")
        + f", from the launch {launch!r}; valid: "
        "a target within tol = {:.3g} m of a reachable stop, or more free components".format(tol),
        tgt,
        pose,
        launch,
        miss,
    )


class _NoStop(ValueError):
    """A launch whose run does not end at rest (it tips, or runs out of steps or phases)."""


class _Runs:
    """The simulations aim makes: the problem's fixed data, and how the Jacobian is had."""

    def __init__(self, body, friction, g, rtol, load, incline, t_end, exact) -> None:
        self.body, self.friction, self.g, self.rtol = body, friction, g, rtol
        self.load, self.incline, self.t_end, self.exact = load, incline, t_end, exact
        self.no_stop = ""  # how the last run that did not end at rest ended

    def stop(self, launch: State, sensitivities=None):
        """(stop pose, sensitivities or None) of ``launch``; ValueError if it does not stop."""
        if self.load is None and self.incline is None:
            tr = simulate(self.body, self.friction, launch, self.g, self.rtol,
                          sensitivities=sensitivities)  # fmt: skip
        else:
            tr = simulate(self.body, self.friction, launch, self.g, self.rtol, load=self.load,
                          incline=self.incline, t_end=self.t_end)  # fmt: skip
        if isinstance(tr, LoadedTrajectory):  # loads, slopes, a tall body
            if tr.status != "ok" or tr.ending not in ("stopped_stuck", "at_rest_throughout"):
                self.no_stop = f"ending {tr.ending!r}, status {tr.status!r}" + (
                    f" at t_end = {self.t_end!r} s" if self.t_end is not None else ""
                )
                raise _NoStop(f"the launch {launch!r} does not stop: {self.no_stop}")
            return State(x=float(tr.x[-1]), y=float(tr.y[-1]), phi=float(tr.phi[-1])), None
        if tr.status not in ("stopped", "at_rest"):
            self.no_stop = f"status {tr.status!r}"
            raise _NoStop(f"the launch {launch!r} does not stop: {tr.status}")
        return tr.stop_state, tr.sensitivities

    def pull(self, start: State) -> tuple[float, float, float]:
        """(a_x, a_y, cos α): the acceleration [m/s²] of the slope's and a constant load's
        pull at the start, and the normal load's factor (for the first guesses)."""
        ax = ay = 0.0
        cos_a = 1.0
        if self.incline is not None and self.incline.is_constant:
            gx, gy = self.incline.gravity_force(1.0, self.g)
            ax, ay, cos_a = gx, gy, self.incline.normal_factor
        if isinstance(self.load, Load) and self.load.is_constant:
            fx, fy, _ = self.load.wrench(0.0, phi=start.phi, mass_centre=(start.x, start.y))
            ax, ay = ax + fx / self.body.mass, ay + fy / self.body.mass
        return ax, ay, cos_a


def _guesses(run, tgt, start, names):
    """First guesses of the free velocities (module docstring)."""
    body, friction, g = run.body, run.friction, run.g
    own = _components(start, names)
    if np.any([x != 0.0 for x, n in zip(own, names) if n != "direction"]):
        yield own
    dx, dy = tgt[0] - start.x, tgt[1] - start.y
    d = math.hypot(dx, dy)
    dphi = tgt[2] - start.phi if len(tgt) == 3 else 0.0
    kin = friction.kinetic
    if d > 0.0:
        ex, ey = dx / d, dy / d
        mu = kin.fx * ex * ex + kin.fy * ey * ey
        ax, ay, cos_a = run.pull(start)
        decel = mu * g * cos_a - (ax * ex + ay * ey)
        speed = math.sqrt(2.0 * (decel if decel > 0.0 else mu * g) * d)
        omega = dphi * speed / d
        vel = {"vx": speed * ex, "vy": speed * ey, "omega": omega}
    else:  # a turn on the spot: a spinning disk of radius ℓ, M = (2/3) μ m g ℓ
        mu = 0.5 * (kin.fx + kin.fy)
        alpha = (2.0 / 3.0) * mu * body.mass * g * body.length_unit / body.moment_of_inertia
        vel = {"vx": 0.0, "vy": 0.0, "omega": math.copysign(math.sqrt(2 * alpha * abs(dphi)), dphi)}
    guess = State(vx=vel["vx"], vy=vel["vy"], omega=vel["omega"])
    mine = _components(guess, names)
    fixed = _components(start, names)
    base = np.where((mine != 0.0) | (fixed == 0.0), mine, fixed)
    # under a load or on a slope the launch may have to go against it: also backwards
    loaded = run.load is not None or run.incline is not None
    for f in (1.0, 0.7, 1.4) + ((-1.0, -0.5) if loaded else ()):
        yield np.array([x if n == "direction" else x * f for x, n in zip(base, names)])


def _miss(run, tgt, start, names, q, jac, typ=None):
    """(miss vector, its Jacobian or None, stop pose) of the launch with free velocities q
    (the Jacobian by central differences of steps DIFF_STEP × ``typ`` where the
    sensitivities are not built)."""
    launch = _launch(start, names, q)
    polar = any(n in _POLAR for n in names)
    wanted = tuple(n for n in names if n not in _POLAR) + (("vx", "vy") if polar else ())
    with warnings.catch_warnings():  # about β*'s derivatives, which aiming does not use
        warnings.simplefilter("ignore", RuntimeWarning)
        s, sens = run.stop(launch, wanted if jac and run.exact else None)
    ell = run.body.length_unit
    r = [s.x - tgt[0], s.y - tgt[1]] + ([(s.phi - tgt[2]) * ell] if len(tgt) == 3 else [])
    J = None
    if jac and not run.exact:
        typ = np.ones(len(names)) if typ is None else typ
        cols = []
        for i in range(len(names)):
            h = DIFF_STEP * max(abs(float(q[i])), float(typ[i]))
            qp, qm = np.array(q, dtype=float), np.array(q, dtype=float)
            qp[i] += h
            qm[i] -= h
            rp, _, _ = _miss(run, tgt, start, names, qp, False)
            rm, _, _ = _miss(run, tgt, start, names, qm, False)
            cols.append((rp - rm) / (2.0 * h))
        J = np.array(cols).T
    elif jac:
        d = sens.stop  # type: ignore[union-attr]
        # the polar values _launch used (a negative speed is a launch the other way)
        vals = dict(zip(names, (float(x) for x in q)))
        speed = vals.get("speed", math.hypot(start.vx, start.vy))
        angle = vals.get("direction", math.atan2(start.vy, start.vx))
        c, sn = math.cos(angle), math.sin(angle)

        def column(n, q):  # ∂q_stop/∂n, polar components by the chain rule
            if n == "speed":
                return c * d["vx"][q] + sn * d["vy"][q]
            if n == "direction":
                return speed * (-sn * d["vx"][q] + c * d["vy"][q])
            return d[n][q]

        rows = [[column(n, "x") for n in names], [column(n, "y") for n in names]]
        if len(tgt) == 3:
            rows.append([column(n, "phi") * ell for n in names])
        J = np.array(rows)
    return np.array(r), J, s


def _hit(r, ell: float, tol: float) -> bool:
    """Whether the miss vector ``r`` is within ``tol`` in x and y [m] and in φ [rad]."""
    return max(abs(r[0]), abs(r[1]), abs(r[2]) / ell if r.size == 3 else 0.0) <= tol


def _solve(run, tgt, start, names, q0, tol, max_iter):
    """Levenberg–Marquardt from ``q0``; returns (q, miss, hit, stop pose) of the best
    point (``hit``: within ``tol`` in x and y [m] and φ [rad])."""
    body = run.body
    k = body.radius_of_gyration
    q = np.asarray(q0, dtype=float)
    scale = max(float(np.max(np.abs([x * (k if n == "omega" else 1.0)
                                     for x, n in zip(q, names) if n != "direction"] or [0.0]))),
                1e-3)  # fmt: skip
    typ = np.array([scale / k if n == "omega" else 1.0 if n == "direction" else scale
                    for n in names])  # fmt: skip
    ell = body.length_unit
    try:
        r, J, pose = _miss(run, tgt, start, names, q, True, typ)
    except (ValueError, RuntimeError):
        return q, math.inf, False, None
    lam = 1e-3

    def hit(r):
        return _hit(r, ell, tol)

    for _ in range(max_iter):
        miss = float(np.linalg.norm(r))
        if hit(r):
            break
        Js = J * typ  # scaled unknowns
        A = Js.T @ Js
        gvec = Js.T @ r
        improved = False
        for _ in range(MAX_TRIES):
            step = -np.linalg.solve(A + lam * np.diag(np.maximum(np.diag(A), 1e-12)), gvec)
            n_step = float(np.linalg.norm(step))
            if n_step > 0.5 * (1.0 + float(np.linalg.norm(q / typ))):
                step *= 0.5 * (1.0 + float(np.linalg.norm(q / typ))) / n_step
            q_new = q + step * typ
            if np.all(np.abs(step * typ) <= 1e-15 * (np.abs(q) + typ)):
                break  # no step left that changes the launch: as near as it gets
            try:  # a trial is judged by a plain run; the Jacobian only where it is taken
                r_new, _, pose_new = _miss(run, tgt, start, names, q_new, False)
                accepted = np.linalg.norm(r_new) < miss or (hit(r_new) and not hit(r))
                if accepted and not hit(r_new):
                    r_new, J, pose_new = _miss(run, tgt, start, names, q_new, True, typ)
            except (ValueError, RuntimeError):
                lam *= 4.0
                continue
            if accepted:
                q, r, pose = q_new, r_new, pose_new
                lam = max(lam / 5.0, 1e-12)
                improved = True
                break
            lam *= 4.0
        if not improved:
            break
    return q, float(np.linalg.norm(r)), hit(r), pose
