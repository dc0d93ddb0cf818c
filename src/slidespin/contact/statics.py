"""Static friction under a load: whether a loaded body at rest stays at rest, and how it
starts (MODEL §11).

Static friction can supply exactly the convex set C of wrenches (Fx, Fy, M about G) of
:mod:`slidespin.contact.static_set`, with support function h(d) = max_{W ∈ C} d·W for a
wrench direction d = (d_F, d_M); C is symmetric, C = −C. A body at rest under an applied
wrench W_a stays at rest iff −W_a ∈ C, that is iff the **load factor**

    λ*(W_a) = min_{d·W_a > 0} h(d)/(d·W_a)            (the gauge of C at W_a, inverted)

is at least 1: λ* is the factor by which the load can be scaled before the body slips. The
minimising d is the outward normal of C where the ray through W_a leaves it.

**Onset** (MODEL §11). If −W_a ∉ C the body starts moving in the direction u of the scaled
twist (vx, vy, k ω)/s (k = √(I/m), s² = vx² + vy² + k² ω²) for which

    A_a + A(u) = λ u,   λ > 0,

with A(u) = (Fx, Fy, M/k)/m the friction accelerations of the sliding law and
A_a = (Qx, Qy, T/k)/m the applied ones: M⁻¹(W_a + W(u)) is a positive multiple of the twist
(M = diag(m, m, I)). λ = ds/dt is the initial rate at which s grows. For isotropic friction
u = (A_a − P_C(A_a))/|A_a − P_C(A_a)| (the proximal point of the support function in the mass
metric: the solution exists and is unique exactly when −W_a ∉ C). For any tensor a solution
exists when −W_a ∉ C: u ↦ A_a + A(u) then never vanishes (W(u) ∈ C) and is homotopic,
through t A_a + A(u), t ≥ 1, to a constant, so the map to its direction has degree 0 and
Lefschetz number 1, hence a fixed point. It is not the direction of the load in general: a
force plus a torque start a mixed motion. At the threshold (−W_a on ∂C) λ = 0 and u is the
twist whose friction wrench is −W_a (for isotropic friction the outward normal of C at W_a).

Units: wrenches in N, N, N m; directions d = (d_Fx, d_Fy, d_M) pair with wrenches as
d·W = d_Fx Fx + d_Fy Fy + d_M M, so d_M is in 1/m. Internally natural units (a = m = g = 1,
a the body's length unit :attr:`slidespin.Body.length_unit`: the semi-axis of an ellipse, the
extent of a footprint).
"""

from __future__ import annotations

import inspect
import math
from dataclasses import dataclass

import numpy as np

from slidespin import _validate as v
from slidespin.contact._engine import TwistWrench
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.static_set import (
    _TOL,
    StaticSupport,
    _check,
    _normal,
    _wrench3,
    static_support,
)
from slidespin.contact.tall import TallTwist, tall_factors

__all__ = [
    "Onset",
    "OnsetNotFound",
    "can_stick",
    "critical_tilt",
    "load_factor",
    "onset",
]

#: bound on |W_a| in units of (m g, m g, m g a): beyond it the optimiser's numbers overflow
WRENCH_MAX = 1e6
#: a load below this (same units) is negligible: held, load factor inf, no onset (its load
#: factor would exceed 1e300 × the smallest coefficient, far beyond any meaning)
WRENCH_NEGLIGIBLE = 1e-300


def _norm(b):
    """|b| without overflow or underflow of the squares."""
    big = float(np.max(np.abs(b)))
    return big * float(np.linalg.norm(b / big)) if 0.0 < big < math.inf else big


def _check_load(name, b, incline=None):
    """Range of a natural-unit wrench b (per unit normal load); False if it is negligible
    (held exactly). On an incline the normal load is m g cos α: a steep slope, not the
    applied wrench, is then what makes b large, and the message says so."""
    nb = _norm(b)
    if not nb <= WRENCH_MAX:
        if incline is not None and incline.normal_factor < 1.0:
            alpha = incline.angle
            raise ValueError(
                f"incline angle = {alpha!r} rad is invalid for static friction: it leaves a "
                f"normal load of m g cos(angle) = {incline.normal_factor:.3g} m g, and the "
                "load to hold there (the applied wrench plus the slope's pull m g sin(angle) "
                f"= {incline.downhill_factor:.3g} m g) is {nb:.3g} times it, far beyond "
                "what friction can give (at most the friction coefficient, <= 5, times it); "
                f"valid range: loads up to {WRENCH_MAX:g} times the normal load, i.e. on the "
                f"slope alone angle <= atan({WRENCH_MAX:g}) = {math.atan(WRENCH_MAX):.9g} rad"
            )
        raise ValueError(
            f"{name} = ({', '.join(f'{x:.6g}' for x in b)}) in units of (m g, m g, m g a) is "
            f"invalid; valid range: magnitude <= {WRENCH_MAX:g} m g (the load must be finite "
            "relative to the weight)"
        )
    return nb >= WRENCH_NEGLIGIBLE


def _applied(body, applied_wrench, phi, t):
    """W_a = (Qx, Qy, M about G) [N, N, N m] in the fixed frame from a triple, or from a load
    object: anything with a method ``wrench(t, phi, mass_centre)`` returning that triple
    (:class:`slidespin.Load`; ``contact`` cannot import it, so it is recognised by this
    method), evaluated at time ``t`` and body angle ``phi``."""
    method = getattr(applied_wrench, "wrench", None)
    if callable(method) and not isinstance(applied_wrench, (str, bytes)):
        t = v.finite("t", t)
        try:
            inspect.signature(method).bind(t, phi, body.mass_centre)
        except (TypeError, ValueError):
            raise ValueError(
                f"applied_wrench = {v._short(applied_wrench)} is invalid: its wrench method "
                "does not take (t, phi, mass_centre); valid values: (Fx, Fy, M), or a load "
                "such as slidespin.Load with wrench(t, phi, mass_centre) -> (Qx, Qy, M)"
            ) from None
        w = method(t, phi, body.mass_centre)
        return _wrench3(f"applied_wrench.wrench({t!r}, {phi!r}, mass_centre)", w)
    return _wrench3("applied_wrench", applied_wrench)


def _with_pull(body, w, incline, g):
    """W_a plus gravity's downhill pull m g sin α d at G on an incline (MODEL §11)."""
    if incline is None:
        return w
    gx, gy = incline.gravity_force(body.mass, g)
    return np.array([w[0] + gx, w[1] + gy, w[2]])


def _load_factor_nat(sup: StaticSupport, b: np.ndarray, d0=None):
    """(λ*, d*) for a wrench b ≠ 0 in natural units: min over d·b > 0 of h(d)/(d·b)."""
    nb = _norm(b)
    bh = b / nb
    # orthonormal frame (bh, e1, e2); d = bh + p e1 + q e2 covers the open half space d·b > 0
    e1 = np.cross(bh, [1.0, 0.0, 0.0] if abs(bh[0]) < 0.9 else [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(bh, e1)

    def fun(pq):
        # h(d)/(d·bh), d·bh = 1: the ratio for the unit load bh (λ* = this / |b|, divided
        # at the end so that neither a tiny nor a huge |b| reaches the optimiser)
        d = bh + pq[0] * e1 + pq[1] * e2
        h, grad = sup(d)
        gd = grad - h * bh  # gradient of h/(d·bh) with respect to d
        return h, np.array([gd @ e1, gd @ e2])

    starts = [np.zeros(2)]
    if d0 is not None and float(np.dot(d0, bh)) > 1e-3:
        d0 = np.asarray(d0, float) / float(np.dot(d0, bh))
        starts.insert(0, np.array([d0 @ e1, d0 @ e2]))  # warm start first
    # the ratio is quasi-convex in d (its sublevel sets are convex cones), so any local
    # minimum is global; a second start only guards against a failed line search
    best = None
    for p0 in starts:
        # lazy: scipy.optimize costs ~0.8 s to import, needed only when a load is tested
        from scipy.optimize import minimize

        r = minimize(fun, p0, jac=True, method="BFGS", options={"gtol": 1e-13, "maxiter": 400})
        if best is None or r.fun < best.fun:
            best = r
        if r.success or np.linalg.norm(r.jac) < 1e-10:
            break
    assert best is not None  # at least one start ran
    pq = best.x
    d = bh + pq[0] * e1 + pq[1] * e2
    return float(best.fun) / nb, d / np.linalg.norm(d)


def load_factor(
    body: Body,
    friction: FrictionTensor,
    applied_wrench,
    phi: float = 0.0,
    g: float = 9.81,
    *,
    incline: Incline | None = None,
    t: float = 0.0,
) -> float:
    """Load factor λ*: the applied wrench can be multiplied by λ* before the body slips.

    λ* = min over wrench directions d with d·W_a > 0 of h(d)/(d·W_a) (the inverse of the
    gauge of C at W_a; MODEL §11). The body at rest stays at rest iff λ* ≥ 1.

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body and its friction tensor.
    applied_wrench : (float, float, float) or a load
        W_a = (Qx [N], Qy [N], moment about G [N m]) in the fixed frame: the loads other
        than gravity (``(0, 0, 0)`` asks whether the body holds on the slope alone). Or a
        load object, such as :class:`slidespin.Load`: anything with a method
        ``wrench(t, phi, mass_centre)`` returning that triple (a force given in the body
        frame or acting away from G is turned and carried to G by it), evaluated at time
        ``t``, body angle ``phi`` and the body's mass centre.
    phi : float
        Body angle [rad].
    g : float
        Gravitational acceleration [m/s²].
    incline : Incline or None
        A plane of fixed tilt α (MODEL §11): the normal load, hence C, scales by cos α, and
        gravity's downhill pull m g sin α d at G is added to ``applied_wrench``, as
        :func:`slidespin.simulate` does. λ* then multiplies the total W_a + m g sin α d.
        A tilt varying in time is refused (give the plane at one time).
    t : float, default 0
        Time [s] at which a load object that varies in time is evaluated (unused for a
        triple).

    Returns
    -------
    float
        λ* (``inf`` for a zero load).

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> disk = Body(Circle(0.1), UniformPressure(), mass=1.0)
    >>> round(load_factor(disk, FrictionTensor(0.3, 0.3), (1.5, 0.0, 0.0), g=10.0), 12)
    2.0

    Any footprint (MODEL §10): a 5 kg box pushed by 10 N holds up to μ m g = 17.5 N.

    >>> from slidespin.contact.shapes import Rectangle
    >>> box = Body(Rectangle(0.4, 0.3), UniformPressure(), mass=5.0)
    >>> round(load_factor(box, FrictionTensor(0.35, 0.35), (10.0, 0.0, 0.0), g=10.0), 12)
    1.75

    On a slope gravity's pull is included: a block holds iff tan α ≤ μ, λ* = μ / tan α.

    >>> from slidespin.motion.loads import Incline
    >>> round(load_factor(box, FrictionTensor(0.35, 0.35), (0.0, 0.0, 0.0),
    ...                   incline=Incline(math.atan(0.25))), 12)
    1.4
    """
    phi, w, nf, g, b = _inputs(body, friction, applied_wrench, phi, g, incline, t)
    if not _check_load("applied_wrench", b, incline):
        return math.inf
    if body.height > 0.0:
        return _tall(body, friction, applied_wrench, b, phi, t, body.mass * g * nf)[0]
    sup = static_support(TwistWrench(body, friction.kinetic), friction, phi)
    return _load_factor_nat(sup, b)[0]


def _raised(body, applied_wrench, phi, t):
    """Σ (h − h_Q) Q [N m] (fixed frame) of a load object with heights, else (0, 0): a
    triple acts at G's height (MODEL §14)."""
    method = getattr(applied_wrench, "raised_force", None)
    if not callable(method):
        return (0.0, 0.0)
    return method(t, phi, body.height)


def _tall(body, friction, applied_wrench, b, phi, t, normal_load):
    """:func:`slidespin.contact.tall.tall_factors` of the load ``applied_wrench`` (natural
    wrench ``b``, normal load P [N]) on a tall body at rest at angle φ, time t."""
    raised = _raised(body, applied_wrench, phi, t)
    return tall_factors(body, friction, b, phi, raised, normal_load, _load_factor_nat)


def _inputs(body, friction, applied_wrench, phi, g, incline, t):
    """The checked inputs of :func:`load_factor`, :func:`onset` and
    :func:`slidespin.breakaway`: (φ, W_a with gravity's pull [N, N, N m], cos α, g, W_a per
    unit normal load in natural units)."""
    _check(body, friction)
    phi = v.finite("phi", phi)
    w = _applied(body, applied_wrench, phi, t)
    nf = _normal(incline, 1.0)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    w = _with_pull(body, w, incline, g)
    return phi, w, nf, g, _natural_wrench(body, w, nf, g)


def _natural_wrench(body, w, nf, g):
    """W_a per unit normal load, moment per unit a: the wrench :func:`load_factor` and
    :func:`onset` both judge (one formula, so their verdicts agree to the last bit)."""
    load = body.mass * g * nf
    return np.array([w[0] / load, w[1] / load, w[2] / (load * body.length_unit)])


def can_stick(
    body: Body,
    friction: FrictionTensor,
    applied_wrench,
    phi: float = 0.0,
    g: float = 9.81,
    *,
    incline: Incline | None = None,
    t: float = 0.0,
) -> bool:
    """Whether static friction can hold the body at rest under ``applied_wrench``.

    True iff −W_a ∈ C (MODEL §11), i.e. :func:`load_factor` ≥ 1: a load exactly at the
    threshold is held. Arguments as in :func:`load_factor`: ``applied_wrench`` is a triple
    (Qx, Qy, M about G) or a load such as ``slidespin.Load(force=(2.0, 0.0))`` (at time
    ``t``); with ``incline`` gravity's downhill pull is included, so
    ``can_stick(body, friction, (0, 0, 0), incline=...)`` answers "does it hold on this
    slope?" (for isotropic friction: iff tan α ≤ μ).

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> disk = Body(Circle(0.1), UniformPressure(), mass=1.0)
    >>> fr = FrictionTensor(0.3, 0.3)
    >>> can_stick(disk, fr, (0.0, 0.0, 0.199), g=10.0), can_stick(disk, fr, (0.0, 0.0, 0.201), g=10.0)
    (True, False)
    """
    return load_factor(body, friction, applied_wrench, phi, g, incline=incline, t=t) >= 1.0


def critical_tilt(
    body: Body, friction: FrictionTensor, downhill: float = 0.0, phi: float = 0.0
) -> float:
    """Tilt α_c [rad] above which the body at rest slides down a plane (MODEL §11).

    On a plane tilted by α the applied wrench is m g sin α (d, 0) and C scales by cos α, so
    the body holds iff tan α ≤ λ*(m g d) on the level plane: α_c = atan λ*(m g (cos δ, sin δ), 0).
    For isotropic friction α_c = atan μ whatever the patch and pressure law. A tall body
    (``Body(..., height=h)``, MODEL §14) tips first where its pressure centroid, moved
    downhill by h tan α, reaches the footprint's hull: α_c is then the smaller of the two
    (a box of base width w: atan((w/2)/h)).

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body and its friction tensor.
    downhill : float
        Direction δ of steepest descent in the plane frame [rad].
    phi : float
        Body angle [rad].

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> disk = Body(Circle(0.1), UniformPressure(), mass=1.0)
    >>> round(critical_tilt(disk, FrictionTensor(0.3, 0.5), downhill=math.pi / 2), 12)
    0.463647609001
    """
    _check(body, friction)
    d = v.finite("downhill", downhill)
    mg = body.mass * 9.81
    return math.atan(
        load_factor(body, friction, (mg * math.cos(d), mg * math.sin(d), 0.0), phi, 9.81)
    )


# ------------------------------------------------------------------------------------------
# onset of slip
# ------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class Onset:
    """How a body at rest starts to slip under a load it cannot resist (MODEL §11).

    Attributes
    ----------
    direction : ndarray, shape (3,)
        Unit scaled twist u = (vx, vy, k ω)/s (dimensionless; k = √(I/m)).
    twist : ndarray, shape (3,)
        The same direction as (vx [m/s], vy [m/s], ω [rad/s]) per unit s [m/s].
    acceleration : float
        λ = ds/dt at the start [m/s²] (> 0; 0 for a load at the threshold within
        round-off, where the rate of the start vanishes).
    residual : float
        |A_a + A(u) − λ u| in units of g, the accuracy of the solve.
    mode : str
        ``"slide"``; ``"tip"`` for a tall body that tips before it slides (MODEL §14): it
        does not slide, and ``direction``, ``twist``, ``acceleration`` and ``residual`` are
        zero (:func:`slidespin.breakaway` gives the factors).
    """

    direction: np.ndarray
    twist: np.ndarray
    acceleration: float
    residual: float
    mode: str = "slide"


#: residual |A_a + A(u) − λ u| (units of g) below which an onset direction is accepted: the
#: kernel evaluates A to ~1e-13, so a converged root sits well below it
_ONSET_RES_TOL = 1e-10
#: an onset rate λ ≥ −_ONSET_LAM_TOL (1 + |A_a|) counts as λ = 0⁺ (units of g): at the threshold
#: (γ = 1 within round-off) λ vanishes and its computed sign is decided by round-off
_ONSET_LAM_TOL = 1e-12
#: cap on the explicit sphere-flow steps of one start (each a kernel call from Python)
_FLOW_STEPS = 4000


class OnsetNotFound(RuntimeError):
    """The load exceeds static friction, but the onset solve found no slip direction.

    A slip direction always exists when −W_a ∉ C (MODEL §11; a degree argument: the map
    u ↦ A_a + A(u) never vanishes and is homotopic to a constant), so this is a failure of
    the numerical solve, not a property of the input. :func:`slidespin.motion.loaded.simulate_loaded`
    ends the run with ``status = "no_onset"`` and the message instead of raising.
    """


def _onset_nat(acc_fun, b, u0, quick=False, allow_negative=False, lam_tol=0.0):
    """Solve b + A(u) = λ u, λ > −``lam_tol``, for u on the unit sphere (natural units).

    ``acc_fun(u)`` returns the friction accelerations A(u) (scaled coordinates).
    Returns (u, λ, residual) or None. ``quick``: Newton from u0 only (u0 already close);
    ``allow_negative``: accept any λ (a fixed point the body does not leave from rest).
    Otherwise Newton (``hybr``) is started from u0, from the direction of b, and from
    where a short run of the sphere flow from each of them ends; the first root with a
    residual below _ONSET_RES_TOL and an admissible λ is returned (the best one if several
    starts are tried).
    """

    def residual_at(u):
        x = b + acc_fun(u)
        return x - (u @ x) * u, float(u @ x)

    def polish(u_start):
        e1 = np.cross(u_start, [1.0, 0.0, 0.0] if abs(u_start[0]) < 0.9 else [0.0, 1.0, 0.0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(u_start, e1)

        def eqs(pq):
            u = u_start + pq[0] * e1 + pq[1] * e2
            u = u / np.linalg.norm(u)
            t, _ = residual_at(u)
            return [t @ e1, t @ e2]

        from scipy.optimize import root  # lazy: see load_factor

        sol = root(eqs, np.zeros(2), method="hybr", options={"xtol": 1e-14})
        u = u_start + sol.x[0] * e1 + sol.x[1] * e2
        u /= np.linalg.norm(u)
        t, lam = residual_at(u)
        return u, lam, float(np.linalg.norm(t))

    def flow(u, tau):
        # explicit sphere-flow steps du/dτ = X − (u·X)u towards a sink, then re-normalise
        # (at most _FLOW_STEPS steps: a start, not a solve; a stiff b shortens the run)
        h = 0.05 / (float(np.linalg.norm(b)) + 1.0)
        for _ in range(min(int(tau / h), _FLOW_STEPS)):
            t, _ = residual_at(u)
            u = u + h * t
            u /= np.linalg.norm(u)
        return u

    def admissible(lam):
        return allow_negative or lam > -lam_tol

    if quick:
        u, lam, res = polish(u0)
        return (u, lam, res) if admissible(lam) and res < 1e-11 else None
    nb = float(np.linalg.norm(b))
    starts = [lambda: u0, lambda: flow(u0, 20.0)]
    if nb > 0.0:
        starts += [lambda: b / nb, lambda: flow(b / nb, 20.0)]
    best = None
    for start in starts:
        u_start = start()
        if not np.all(np.isfinite(u_start)):  # pragma: no cover - guard
            continue
        u, lam, res = polish(u_start)
        if admissible(lam) and res < _ONSET_RES_TOL and (best is None or res < best[2]):
            best = (u, lam, res)
        if best is not None and best[2] < 1e-12:
            break
    return best


def _scaled_b(body, wrench, load_nf, g):
    """Applied accelerations in scaled natural coordinates (Qx, Qy, T/k)/(m g)."""
    k = body.radius_of_gyration / body.length_unit
    mg = body.mass * g
    return np.array([wrench[0] / mg, wrench[1] / mg, wrench[2] / (mg * body.length_unit * k)])


def onset(
    body: Body,
    friction: FrictionTensor,
    applied_wrench,
    phi: float = 0.0,
    g: float = 9.81,
    *,
    incline: Incline | None = None,
    t: float = 0.0,
) -> Onset | None:
    """Direction and initial rate in which a body at rest starts to slip (MODEL §11).

    Parameters
    ----------
    body, friction, applied_wrench, phi, g, incline, t
        As in :func:`load_factor` (``applied_wrench`` a triple or a load such as
        :class:`slidespin.Load`, at time ``t``); with ``incline`` gravity's downhill pull
        m g sin α d is added to ``applied_wrench`` (the loads other than gravity).

    Returns
    -------
    Onset or None
        ``None`` when static friction holds the body (:func:`can_stick` is true).

    Raises
    ------
    OnsetNotFound
        The load is beyond static friction but the solve found no direction (a numerical
        failure: a direction always exists, MODEL §11).

    Notes
    -----
    Solves A_a + A(u) = λ u with λ > 0 on the unit sphere of scaled twists, starting from
    the outward normal of C found by :func:`load_factor` (exact for isotropic friction at
    the threshold) and, if that fails, from the direction of A_a and from short runs of
    the sphere flow du/dτ = A_a + A − ((A_a + A)·u) u, of which the onset direction is an
    attracting fixed point for isotropic friction (the tangent eigenvalues are −λ − the
    curvatures of h). At the threshold λ → 0⁺: a root whose λ is negative only by
    round-off (≥ −1e-12 (1 + |A_a|) g) is that limit, reported with λ = 0.

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> disk = Body(Circle(0.1), UniformPressure(), mass=1.0)
    >>> o = onset(disk, FrictionTensor(0.3, 0.3), (5.0, 0.0, 0.0), g=10.0)
    >>> [round(float(x), 9) for x in o.direction], round(o.acceleration, 9)  # (5 − 3) N / 1 kg
    ([1.0, 0.0, 0.0], 2.0)
    """
    phi, w, nf, g, wn = _inputs(body, friction, applied_wrench, phi, g, incline, t)
    tw: TwistWrench | TallTwist
    if not _check_load("applied_wrench", wn, incline):
        return None
    if body.height > 0.0:
        # a tall body (MODEL §14): it tips, or it slides with the pressure it has moved
        lam, mode, _slide, _tip, tall, s_vec, sig = _tall(
            body, friction, applied_wrench, wn, phi, t, body.mass * g * nf
        )
        if lam >= 1.0:
            return None
        if mode == "tip":
            zero = np.zeros(3)
            return Onset(zero, zero.copy(), 0.0, 0.0, mode="tip")
        tw = TallTwist(tall, sig)
        rp = (tall.rg[0] + s_vec[0], tall.rg[1] + s_vec[1])
        sup = tall.at(rp).support(friction, phi)
    else:
        tw = TwistWrench(body, friction, _TOL)
        sup = static_support(tw, friction, phi)
    lam_star, d = _load_factor_nat(sup, wn)
    if lam_star >= 1.0:  # the verdict of load_factor and can_stick, bit for bit
        return None
    u, lam, resid = _onset_from_par(
        tw, friction, phi, _scaled_b(body, w, nf, g), nf, sup, slipping=True, d0=d
    )
    k = body.radius_of_gyration
    return Onset(u, np.array([u[0], u[1], u[2] / k]), lam * g, resid)


def _friction_acc(tw: TwistWrench, phi, nf):
    """u ↦ A(u) = cos α · (Fx, Fy, M/k) in scaled natural coordinates."""
    k = tw.k

    def acc(u):
        fx, fy, m = tw(phi, u[0], u[1], u[2] / k)
        return np.array([fx * nf, fy * nf, m * nf / k])

    return acc


def _onset_from_par(tw, friction, phi, b, nf, sup=None, *, slipping=False, d0=None):
    """(u, λ, residual) of the onset for scaled applied accelerations b, or None if stuck.

    ``b`` is in scaled natural coordinates (Qx, Qy, T/k)/(m g); ``nf`` = cos α.
    ``slipping``: the caller has already found the gauge γ > 1 (the load is beyond C), so
    the load factor is computed here only for the starting direction (its outward normal
    of C) and a second, round-off-level verdict at the threshold cannot contradict the
    first; ``d0`` warm-starts that computation.

    At the threshold (γ = 1 within round-off) the onset rate λ vanishes and its computed
    value may be a round-off negative: a root with λ ≥ −_ONSET_LAM_TOL (1 + |b|) is the
    onset with λ = 0⁺ (the body starts from rest with zero initial rate; the slow start
    then follows λ(t) as the load grows), and λ is reported as max(λ, 0).

    Raises
    ------
    OnsetNotFound
        The load is beyond C but no root was found (a solver failure; never for a load
        that static friction holds).
    """
    if not b.any():
        return None
    k = tw.k
    if sup is None:
        sup = static_support(tw, friction, phi)
    # wrench per unit normal load, natural units: (Qx, Qy, T)/(m g cos α)
    bw = np.array([b[0], b[1], b[2] * k]) / nf
    lam_star, d = _load_factor_nat(sup, bw, d0)
    if lam_star >= 1.0 and not slipping:
        return None
    u0 = np.array([d[0], d[1], k * d[2]])
    u0 /= np.linalg.norm(u0)
    lam_tol = _ONSET_LAM_TOL * (1.0 + float(np.linalg.norm(b)))
    got = _onset_nat(_friction_acc(tw, phi, nf), b, u0, lam_tol=lam_tol)
    if got is None:
        raise OnsetNotFound(
            f"no slip direction found for the applied wrench (load factor {lam_star:.12g} "
            f"< 1, body angle {phi:.6g} rad): the onset solve A_a + A(u) = λ u, λ > 0, did "
            "not converge from any of its starts"
        )
    u, lam, res = got
    return u, max(lam, 0.0), res
