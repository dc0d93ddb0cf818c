"""The engine-independent core of a coupling: the planar friction wrench of one body for one
engine step, with stick–slip by a discrete projection (MODEL §16).

An engine integrates the body in 3-D and resolves the normal contact; :class:`SteppedFriction`
turns the body's planar twist ν = (vx, vy, ω) relative to its support (in the support's plane
frame: two axes in the plane, ω about the normal), its angle φ in that plane and the engine's
normal force N into the wrench (Fx, Fy, M about the normal through G) that the engine applies
for the step:

* **stick or stop**: the wrench that brings the planar twist to zero at the end of the step,
  w_req = −M ν/h − f, if it lies in the static set C (N × the set of
  :mod:`slidespin.contact.static_set`, times μs/μk): a projection onto C, not a smoothed law,
  so a body at rest under a load inside C does not creep, and a slip that would stop within
  the step stops (the stop time interpolated within it, :attr:`SteppedFriction.stop_time`);
* **slip**: the exact wrench of the patch, N w(z) (the compiled kernel of
  :class:`slidespin.contact._engine.TwistWrench`, per unit load), at the twist z of the
  positions' time. An engine's semi-implicit (kick-drift) Euler holds its velocities half a
  step after its positions, so z is the implicit midpoint z = ν + (h/2) M⁻¹(f + W(z)): second
  order, and stable where the twist nears zero (an explicit W(ν) there flips the spin's sign
  from step to step). It is solved by fixed-point iteration (a contraction while
  |h M⁻¹ W| ≪ |ν|), else as the onset problem b + A(u) = λu of MODEL §11; if no z exists
  (the twist would stop by the midpoint and cannot stick at the end) the implicit Euler step
  of length h; at rest, breaking away, the onset direction;
* **a launch** (the twist set by hand at the start of a contact, or a kick: the load estimate
  jumps by more than JUMP × the friction's capacity): half the step's impulse of every load,
  the leapfrog start, so that positions stay second order.

Here M = diag(m, m, I) and f is the planar wrench of everything else on the body (gravity on a
slope, springs, a finger, actuators). The part of it the adapter knows before the engine's
solve (``known``: gravity, a push it reads) is exact; the rest, which the engine resolves in
the same step, is estimated from the previous step, M (ν_k − ν_{k−1})/h − W_{k−1} − known_{k−1}
(exact for loads constant over a step), or given whole by the adapter (``load``: the first
step of a contact). A twist below 1e-9 of one step's change by friction is rest (engines
leave ~1e-19 m/s).

Whether w_req ∈ C is decided from bounds first: the gauge γ of C is at least (d·w)/h(d) for the
last outward normal d, and at most γ_ref + |w − w_ref|/r_in from the last exact evaluation
(γ is subadditive; r_in, the radius of a ball inside C, is σ_min(𝔽) × the static ratio × the
inradius of the isotropic unit set, found once; a plane-frame tensor's C turns with the body,
which :func:`slidespin.engines._stepcore.gauge_upper` bounds too). Only in between is the
exact load factor of :mod:`slidespin.contact.statics` computed (a few milliseconds).

The state lives in one float array ``s`` (layout in :mod:`slidespin.engines._stepcore`),
shared with the MuJoCo coupling's compiled steady step, which does most steps of a coupled
body from the same state with the same arithmetic; this class does the others.

May import: :mod:`slidespin.contact` (and below), :mod:`slidespin.engines._stepcore`. Works
on plain floats; the engines' adapters (:mod:`slidespin.engines.mujoco`,
:mod:`slidespin.engines.drake`) own the frames.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.contact._engine import TwistWrench
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.outline import body_outline
from slidespin.contact.static_set import check_anisotropy, static_support
from slidespin.contact.statics import _load_factor_nat, _onset_nat
from slidespin.engines import _stepcore as sc

__all__ = ["Held", "SteppedFriction", "check_coupled"]

#: a load jumping by this many times the friction's capacity within a step is an impulse
JUMP = sc.JUMP
#: a twist below this fraction of one step's change by friction is rest
_REST = sc.REST
#: fixed-point iterations of the implicit step before the onset solver takes over
_FIXED_POINT_ITERATIONS = sc.FIXED_POINT_ITERATIONS
#: … to this change of the twist's direction (the engine's own errors are far larger)
_FIXED_POINT_TOL = sc.FIXED_POINT_TOL
_STATES = {sc.FREE: "free", sc.SLIP: "slip", sc.STICK: "stick"}
_CODES = {name: code for code, name in _STATES.items()}
#: safety factor on the inner ball of C (the bound only decides when to compute exactly)
_INNER_MARGIN = 0.98


def _dist(a, b, ell: float) -> float:
    """|a − b| for wrenches (F, F, M), the moment per ℓ."""
    return math.sqrt((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 + ((a[2] - b[2]) / ell) ** 2)


def check_coupled(body: Body, friction: FrictionTensor) -> None:
    """Raise ValueError naming the parameter unless the body and friction can be coupled:
    a thin body (``height`` 0: the engine resolves the tilt itself) and a constant law
    (``static`` ≥ 1 allowed; a speed law is refused)."""
    if not isinstance(body, Body):
        raise TypeError(f"body = {body!r} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise TypeError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    if body.height != 0.0:
        raise ValueError(
            f"body.height = {body.height!r} is invalid for an engine coupling; valid values: 0 "
            "(the engine integrates the body in 3-D and shifts its own normal load: give the "
            "thin body, whose pressure law slidespin integrates, with height=0)"
        )
    if friction.speed_law is not None and not friction.speed_law.is_constant:
        raise ValueError(
            f"friction.speed_law = {friction.speed_law!r} is invalid for an engine coupling; "
            "valid values: None (the constant law, with static >= 1); speed laws run in "
            "slidespin.simulate"
        )
    if friction.static != 1.0:
        check_anisotropy(body, friction)


def _unit_inradius(tw: TwistWrench) -> float:
    """min over unit d of the isotropic unit support function h(d) = −W(d)·d (natural units):
    the radius of the largest ball about 0 inside the isotropic unit static set."""

    def h(x):
        d = np.array(
            [math.cos(x[0]) * math.cos(x[1]), math.sin(x[0]) * math.cos(x[1]), math.sin(x[1])]
        )
        fx, fy, m = tw(0.0, *d)
        return -(fx * d[0] + fy * d[1] + m * d[2])

    # a grid over the sphere, then a local refinement from its best points
    best = []
    for lat in np.linspace(-1.5, 1.5, 13):
        for lon in np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False):
            best.append((h((lon, lat)), lon, lat))
    for pole in (-math.pi / 2, math.pi / 2):
        best.append((h((0.0, pole)), 0.0, pole))
    best.sort()
    from scipy.optimize import minimize  # lazy: scipy.optimize costs ~0.8 s to import

    value = best[0][0]
    for _, lon, lat in best[:4]:
        r = minimize(h, np.array([lon, lat]), method="Nelder-Mead", options={"xatol": 1e-8})
        value = min(value, float(r.fun))
    return value


class Held:
    """An attribute of :class:`SteppedFriction` held in its state array ``s`` (the layout of
    :mod:`slidespin.engines._stepcore`, which the compiled steady step reads and writes): a
    float (``n`` 1), or a tuple of ``n`` floats that is None while ``s[flag]`` is 0."""

    def __init__(self, i: int, n: int = 1, flag: int | None = None, kind=float) -> None:
        self.i, self.n, self.flag, self.kind = i, n, flag, kind

    def __get__(self, obj, cls=None):
        if obj is None:
            return self
        s = obj.s
        if self.flag is not None and s[self.flag] == 0.0:
            return None
        if self.n == 1:
            return self.kind(s[self.i])
        return tuple(s[self.i : self.i + self.n].tolist())

    def __set__(self, obj, value) -> None:
        s = obj.s
        if value is None:
            s[self.flag] = 0.0
            return
        if self.n == 1:
            s[self.i] = value
        else:
            s[self.i : self.i + self.n] = value
        if self.flag is not None:
            s[self.flag] = 1.0


class SteppedFriction:
    """The friction of one body for an engine, step by step (MODEL §16).

    Parameters
    ----------
    body : Body
        The thin body (footprint or ellipse and pressure law; ``height`` 0).
    friction : FrictionTensor
        Its tensor (constant law; ``static`` ≥ 1 allowed). A plane-frame tensor's axes are
        the support frame's axes.
    mass, inertia : float
        The mass [kg] and the moment of inertia about the normal through G [kg m²] that the
        engine integrates with (M = diag(m, m, I) of the discrete projection).
    dt : float
        The engine's time step h [s].

    Attributes
    ----------
    state : str
        ``"slip"``, ``"stick"`` or ``"free"`` (no contact) after the last step.
    stop_time : float
        The time [s] at which the last slip stopped, interpolated within its step (the
        twist, half a step after the positions in a kick-drift engine, followed under the
        step's acceleration); NaN before any stop.
    exact_checks : int
        How many exact static-set tests the bounds could not spare (a counter).
    evaluations : int
        How many times the patch's kinetic wrench was evaluated (a counter).
    steps, compiled_steps : int
        How many steps were taken, and how many of them by the compiled steady step
        (:mod:`slidespin.engines._stepcore`; counters).
    s : ndarray
        The state, shared with the compiled steady step (layout in
        :mod:`slidespin.engines._stepcore`).
    """

    dt = Held(sc.S_DT)
    stop_time = Held(sc.S_STOP)
    exact_checks = Held(sc.S_EXACT, kind=int)
    evaluations = Held(sc.S_EVALS, kind=int)
    steps = Held(sc.S_STEPS, kind=int)
    compiled_steps = Held(sc.S_FAST, kind=int)
    _slipping = Held(sc.S_SLIPPING, kind=bool)
    _nu = Held(sc.S_NU, 3, sc.S_NU_OK)
    _w = Held(sc.S_W, 3)
    _key = Held(sc.S_KEY, 6, sc.S_KEY_OK)
    _u = Held(sc.S_U, 3, sc.S_U_OK)
    _u_raw = Held(sc.S_URAW, 3)
    _known = Held(sc.S_KNOWN, 3, sc.S_KNOWN_OK)

    @property
    def state(self) -> str:
        """``"slip"``, ``"stick"`` or ``"free"`` after the last step."""
        return _STATES[float(self.s[sc.S_STATE])]

    @state.setter
    def state(self, value: str) -> None:
        self.s[sc.S_STATE] = _CODES[value]

    @property
    def _t(self) -> float | None:
        t = float(self.s[sc.S_T])
        return None if math.isnan(t) else t

    @_t.setter
    def _t(self, value: float | None) -> None:
        self.s[sc.S_T] = math.nan if value is None else value

    @property
    def _ref(self) -> tuple | None:
        """(φ, body-frame wrench, γ) of the last exact gauge, or None."""
        s = self.s
        if s[sc.S_REF_OK] == 0.0:
            return None
        return float(s[sc.S_REF_PHI]), s[sc.S_REF_B : sc.S_REF_B + 3].copy(), float(s[sc.S_REF_G])

    @_ref.setter
    def _ref(self, value: tuple | None) -> None:
        s = self.s
        if value is None:
            s[sc.S_REF_OK] = 0.0
            return
        s[sc.S_REF_PHI], s[sc.S_REF_B : sc.S_REF_B + 3], s[sc.S_REF_G] = value
        s[sc.S_REF_OK] = 1.0

    def __init__(
        self, body: Body, friction: FrictionTensor, mass: float, inertia: float, dt: float
    ) -> None:
        check_coupled(body, friction)
        self.s = np.zeros(sc.NSTATE)
        self.body = body
        self.friction = friction
        self.ell = float(body.length_unit)
        self.tw = TwistWrench(body, friction.kinetic)
        self.m = float(mass)
        self.inertia = float(inertia)
        if not (self.m > 0.0 and self.inertia > 0.0 and math.isfinite(self.m * self.inertia)):
            raise ValueError(
                f"mass = {mass!r}, inertia = {inertia!r} are invalid; valid range: > 0 "
                "(the engine's mass and moment of inertia about the normal)"
            )
        self.k = math.sqrt(self.inertia / self.m)
        self.dt = float(dt)
        if not (self.dt > 0.0 and math.isfinite(self.dt)):
            raise ValueError(f"dt = {dt!r} is invalid; valid range: > 0 s (the engine's step)")
        iso = TwistWrench(body, FrictionTensor(1.0, 1.0))
        smin = float(np.linalg.svd(friction.matrix, compute_uv=False)[-1])
        # the force friction can hold per unit normal load: a load that jumps by JUMP times
        # more within one step is an impulse
        self.capacity = friction.static * friction.norm
        self.r_in = _INNER_MARGIN * smin * friction.static * _unit_inradius(iso)
        # C lies in the ball |W| ≤ μs σ_max √(1 + ρ²) per unit load (|F| ≤ σ_max P and
        # |M| ≤ σ_max P ρ ℓ, ρ ℓ the farthest point of the footprint from G)
        outline = body_outline(body)
        rho = max(
            float(np.hypot(*outline.support((math.cos(a), math.sin(a)))))
            for a in np.linspace(0.0, 2.0 * math.pi, 720, endpoint=False)
        )
        rho = 1.001 * rho / self.ell
        smax = float(np.linalg.svd(friction.matrix, compute_uv=False)[0])
        self.r_out = friction.static * smax * math.sqrt(1.0 + rho * rho)
        self.state = "free"
        self._slipping = False
        self.stop_time = math.nan
        self.exact_checks = 0
        self._w_last: tuple | None = None
        st = self.s
        st[sc.S_M], st[sc.S_I], st[sc.S_ELL], st[sc.S_K] = self.m, self.inertia, self.ell, self.k
        st[sc.S_CAP], st[sc.S_RIN], st[sc.S_ROUT] = self.capacity, self.r_in, self.r_out
        st[sc.S_BODYFRAME] = float(
            friction.frame == "body" or (friction.fx == friction.fy and friction.f == 0.0)
        )
        self.reset()

    def reset(self) -> None:
        """Forget the previous step (a new contact, a reset engine): the next step's load is
        then the one given to :meth:`step`, or 0."""
        self._t = None
        self._nu = (0.0, 0.0, 0.0)
        self._w = (0.0, 0.0, 0.0)
        self._key = None
        self._ref = None  # (phi, b natural, gamma) of the last exact test
        self._d: np.ndarray | None = None  # the last outward normal of C
        self._u = None  # the last accepted unknown part of the load
        self._u_raw = (0.0, 0.0, 0.0)  # … and the last estimate of it
        self._known = None  # the part of the load the adapter knew
        self.s[sc.S_NH] = 0.0  # no slip steps to predict from

    def airborne(self, t: float) -> None:
        """Record a step at time ``t`` [s] without load on the support (no contact, or a
        contact without normal force): no friction; the next step with load is not a launch
        (its twist is the engine's, half a step after its positions)."""
        self.state = "free"
        self._slipping = False
        self._t, self._nu, self._w, self._key = t, None, (0.0, 0.0, 0.0), None
        self._known = None
        self.s[sc.S_NH] = 0.0

    # -- the wrench of the patch --------------------------------------------------------
    def _gauge(self, b: np.ndarray, phi: float) -> float:
        """γ(b) for a wrench b in natural units (per unit load, M per ℓ): b ∈ C iff γ ≤ 1."""
        c, s = math.cos(phi), math.sin(phi)
        bb = np.array([c * b[0] + s * b[1], -s * b[0] + c * b[1], b[2]])  # body frame
        upper = sc.gauge_upper.py_func(self.s, float(b[0]), float(b[1]), float(b[2]), phi)
        if upper <= 1.0:
            return upper
        sup = static_support(self.tw, self.friction, phi)
        if self._d is not None:
            h, _ = sup(self._d)
            lower = float(np.dot(self._d, b)) / h
            if lower > 1.0:
                return lower
        self.exact_checks += 1
        lam, d = _load_factor_nat(sup, b, self._d)
        gamma = 1.0 / lam if lam > 0.0 else math.inf
        self._ref = (phi, bb, gamma)
        self._d = d
        return gamma

    # -- one step -----------------------------------------------------------------------
    def step(
        self, t: float, nu, phi: float, normal: float, load=None, known=None
    ) -> tuple[float, float, float]:
        """The wrench (Fx, Fy, M about the normal through G) [N, N, N m] to apply over the
        step starting at time ``t`` [s], as a tuple of floats.

        Parameters
        ----------
        t : float
            The engine's time at the start of the step [s]; a second call at the same time
            and twist returns the same wrench (engines evaluate their inputs more than once).
        nu : (3,) array_like
            Planar twist relative to the support (vx, vy [m/s] in the support frame, ω
            [rad/s] about its normal).
        phi : float
            Body angle in the support frame [rad].
        normal : float
            The normal force N [N] (≤ 0: no contact, no friction).
        load : (3,) array_like or None
            The planar wrench of everything else on the body over this step, when the
            adapter knows it; None: estimated from the previous step if it was the step
            just before (t − h), else 0.
        known : (3,) array_like or None
            The part of that load the adapter knows for this step (a push it reads, gravity):
            the estimate from the previous step then lags only in the rest (a contact, an
            actuator), so that a push applied suddenly is held from its first step.
        """
        n0, n1, n2 = float(nu[0]), float(nu[1]), float(nu[2])
        key = (t, n0, n1, n2, phi, normal)
        if key == self._key:
            return self._w
        if not normal > 0.0:  # touching without load (or lifting off): no friction
            self.airborne(t)
            self._nu, self._key = (n0, n1, n2), key
            return self._w
        h = self.dt
        m, inertia, ell = self.m, self.inertia, self.ell
        consecutive = self._t is not None and abs(t - self._t - h) <= min(
            1e-9 * max(h, abs(t)), 0.5 * h
        )
        # a twist below round-off of one step's change is rest (engines leave ~1e-19 m/s)
        tol = _REST * h * normal * self.capacity / m
        moving = n0 * n0 + n1 * n1 + (ell * n2) ** 2 > tol * tol
        if not moving:
            n0 = n1 = n2 = 0.0
        kn = None if known is None else (float(known[0]), float(known[1]), float(known[2]))
        launch = False
        if load is not None:
            f0, f1, f2 = (float(c) for c in load)
            launch = moving and not consecutive
            # the unknown part of this load, for the next step's estimate and impulse test
            u = (f0, f1, f2) if kn is None else (f0 - kn[0], f1 - kn[1], f2 - kn[2])
            self._u = self._u_raw = u
        elif consecutive and self._nu is not None:
            # the load of the step before, from the change of the twist; its unknown part
            # (less what the adapter knew then) carries over to this step
            p0, p1, p2 = self._nu
            w0, w1, w2 = self._w
            u0 = m * (n0 - p0) / h - w0
            u1 = m * (n1 - p1) / h - w1
            u2 = inertia * (n2 - p2) / h - w2
            if self._known is not None:
                k0, k1, k2 = self._known
                u0, u1, u2 = u0 - k0, u1 - k1, u2 - k2
            raw = (u0, u1, u2)
            if self._u is not None:
                # an impulse (a launch, a kick): the load jumps by far more than friction can
                # hold, from the last accepted one and from the last estimate; the step then
                # keeps the last accepted load (a lasting change is accepted a step later)
                thr = JUMP * normal * self.capacity
                if _dist(raw, self._u, ell) > thr and _dist(raw, self._u_raw, ell) > thr:
                    u0, u1, u2 = self._u
                    launch = moving
            self._u_raw = raw
            self._u = (u0, u1, u2)
            f0, f1, f2 = u0, u1, u2
            if kn is not None:
                f0, f1, f2 = f0 + kn[0], f1 + kn[1], f2 + kn[2]
        else:  # a first step, or the first after a step in the air: the known loads
            f0, f1, f2 = kn if kn is not None else (0.0, 0.0, 0.0)
            launch = moving and not consecutive
            self._u = self._u_raw = (0.0, 0.0, 0.0)
        self._slipping = self.state == "slip" and consecutive
        self._t_now = t
        self._midpoint = False
        w = self._decide(n0, n1, n2, phi, normal, f0, f1, f2, h, launch)
        # the friction of a slip at its implicit midpoint starts the next step's iteration
        sc.push_history.py_func(self.s, w[0], w[1], w[2], normal, self.ell, self._midpoint)
        self._t, self._nu, self._w, self._key = t, (n0, n1, n2), w, key
        self._known = kn
        self.s[sc.S_STEPS] += 1.0
        return w

    def _stop_time(self, n0, n1, n2, f0, f1, f2, h) -> float:
        """The time at which the slip stops within the step at ``self._t`` + h: the twist,
        which a kick-drift engine holds half a step after its positions, continues under the
        last step's acceleration to its smallest kinetic energy."""
        m, inertia = self.m, self.inertia
        w0, w1, w2 = self._w
        a0, a1, a2 = (f0 + w0) / m, (f1 + w1) / m, (f2 + w2) / inertia
        aa = m * (a0 * a0 + a1 * a1) + inertia * a2 * a2
        if not aa > 0.0:
            return self._t_now
        tau = -(m * (n0 * a0 + n1 * a1) + inertia * n2 * a2) / aa
        return self._t_now - 0.5 * h + min(max(tau, 0.0), h)

    def _acc(self, phi, normal):
        """u ↦ A(u): the friction accelerations (Fx/m, Fy/m, M/(m k)) [m/s²] of a twist in
        the scaled coordinates (vx, vy, k ω) (k = √(I/m), kinetic energy ½ m |x|²)."""
        ell, k = self.ell, self.k
        tw, c = self.tw, normal / self.m

        def acc(u):
            self.s[sc.S_EVALS] += 1.0
            fx, fy, mo = tw(phi, u[0] / ell, u[1] / ell, u[2] / k)
            return np.array([c * fx, c * fy, c * mo * ell / k])

        return acc

    def _implicit(self, x, a, tau, phi, normal):
        """The twist z ≠ 0 (scaled) with z = x + τ (a + A(z/|z|)) (an implicit step of
        length τ from x under the loads a and friction), or None if friction holds the step
        (no such z: the twist would stop within it). ``self._w_last`` is then W(z), or None
        when the onset solver found z."""
        self._w_last = None
        ell, k, tw, c = self.ell, self.k, self.tw, normal / self.m
        x0, x1, x2 = x
        a0, a1, a2 = a
        g0, g1, g2 = x0, x1, x2
        if self._slipping and self.s[sc.S_NH] > 0.0:
            # start from the friction of the last slip steps, extrapolated (one evaluation
            # then usually meets the tolerance; the compiled steady step does the same)
            pf = sc.predicted_friction.py_func
            g0 += tau * (a0 + c * pf(self.s, 0))
            g1 += tau * (a1 + c * pf(self.s, 1))
            g2 += tau * (a2 + c * pf(self.s, 2) * ell / k)
        elif self._slipping:  # start from the friction of the step before
            w0, w1, w2 = self._w
            g0 += tau * (a0 + w0 / self.m)
            g1 += tau * (a1 + w1 / self.m)
            g2 += tau * (a2 + w2 / (self.m * k))
        ng = math.sqrt(g0 * g0 + g1 * g1 + g2 * g2)
        if not ng > 0.0:
            g0, g1, g2 = x0, x1, x2
            ng = math.sqrt(g0 * g0 + g1 * g1 + g2 * g2)
        u0, u1, u2 = g0 / ng, g1 / ng, g2 / ng
        for _ in range(_FIXED_POINT_ITERATIONS):  # a contraction while |τ A| ≪ |x|
            self.s[sc.S_EVALS] += 1.0
            fx, fy, mo = tw(phi, u0 / ell, u1 / ell, u2 / k)
            z0 = x0 + tau * (a0 + c * fx)
            z1 = x1 + tau * (a1 + c * fy)
            z2 = x2 + tau * (a2 + c * mo * ell / k)
            nz = math.sqrt(z0 * z0 + z1 * z1 + z2 * z2)
            if nz == 0.0:
                break
            v0, v1, v2 = z0 / nz, z1 / nz, z2 / nz
            moved = abs(v0 - u0) + abs(v1 - u1) + abs(v2 - u2)
            u0, u1, u2 = v0, v1, v2
            if moved <= _FIXED_POINT_TOL:
                # W of the direction before the last update: within the tolerance of z's
                self._w_last = (normal * fx, normal * fy, normal * mo * ell)
                return (z0, z1, z2)
        acc = self._acc(phi, normal)
        u = np.array([u0, u1, u2])
        # near a stop: b + A(u) = λ u with b = x/τ + a, λ = |z|/τ > 0 (the onset problem of
        # MODEL §11; natural units: accelerations per N/m)
        gn = normal / self.m
        b = (np.array(x) / tau + np.array(a)) / gn
        got = _onset_nat(lambda v: acc(v) / gn, b, u)
        if got is None or not got[1] > 0.0:
            return None
        return tuple((got[0] * got[1] * gn * tau).tolist())

    def _decide(self, n0, n1, n2, phi, normal, f0, f1, f2, h, launch) -> tuple:
        m, inertia, ell, k = self.m, self.inertia, self.ell, self.k
        moving = n0 != 0.0 or n1 != 0.0 or n2 != 0.0
        # the wrench that brings the twist to zero at the end of the step: if friction can
        # hold it (it lies in C), the slip stops within the step, or the body stays at rest
        r0 = -m * n0 / h - f0
        r1 = -m * n1 / h - f1
        r2 = -inertia * n2 / h - f2
        b0, b1, b2 = r0 / normal, r1 / normal, r2 / (ell * normal)
        if b0 * b0 + b1 * b1 + b2 * b2 <= self.r_out**2:  # else outside C for sure
            if self._gauge(np.array([b0, b1, b2]), phi) <= 1.0:
                if self._slipping:  # a stop within this step: when, by the step's trend
                    self.stop_time = self._stop_time(n0, n1, n2, f0, f1, f2, h)
                self.state = "stick"
                return (r0, r1, r2)
        self.state = "slip"
        x = (n0, n1, k * n2)  # scaled twist and loads
        a = (f0 / m, f1 / m, f2 / (m * k))
        if launch:
            # the leapfrog start: the twist is the launch's, at the positions' time; half
            # the step's impulse of every load
            self.s[sc.S_EVALS] += 1.0
            fx, fy, mo = self.tw(float(phi), n0 / ell, n1 / ell, n2)
            c = 0.5 * normal
            return (c * fx - 0.5 * f0, c * fy - 0.5 * f1, c * mo * ell - 0.5 * f2)
        # kick-drift: the engine's twist lies half a step before the positions' time, and
        # the friction is that of the twist z at that time, z = x + (h/2)(a + A(z)) (the
        # implicit midpoint: second order, and stable where the twist nears zero); if the
        # twist would stop by then and cannot stick at the end, the implicit Euler step
        z = self._implicit(x, a, 0.5 * h, phi, normal) if moving else None
        self._midpoint = z is not None
        if z is None:
            z = self._implicit(x, a, h, phi, normal) if moving else None
        if z is None:  # at rest, breaking away: the onset direction (MODEL §11)
            self._w_last = None
            gn = normal / m
            av = np.array(a)
            acc = self._acc(phi, normal)
            got = _onset_nat(lambda v: acc(v) / gn, av / gn, av / np.linalg.norm(av))
            if got is None:  # pragma: no cover - the load lies beyond C (tested above)
                raise RuntimeError("the coupling found no slip direction from rest")
            z = got[0]
        if self._w_last is not None:
            return self._w_last
        self.s[sc.S_EVALS] += 1.0
        fx, fy, mo = self.tw(float(phi), z[0] / ell, z[1] / ell, z[2] / k)
        return (normal * fx, normal * fy, normal * mo * ell)
