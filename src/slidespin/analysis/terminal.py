"""Terminal motion: how the body stops (paper eq. 14–16; MODEL §5–6).

Near the stop the wrench depends only on the direction of motion, so the direction

    u = (vx, vy, k ω)/s,     s = √(vx² + vy² + k² ω²),     k = √(I/m),

obeys an autonomous flow on the unit sphere, du/dτ = A(u, φ) − (u·A) u (MODEL §5, dt = s dτ),
and converges to one of its fixed points u*, where A(u*) is antiparallel to u*. A fixed point is
a *terminal motion*: v and ω vanish together with the fixed ratio β* = v/ω and the fixed
direction ϑ* of the velocity of G. In the paper's variables (eq. 4) a fixed point is

    F_n = 0     and     β = I* F_τ / M_Cζ     (units of a; eq. 14–16, I* = I/(m a²)).

Paper symbols and code names: β → ``beta`` [m] (``beta_ratio`` = β/a), ϑ → ``theta`` [rad],
φ → ``phi`` [rad], I* → ``inertia_ratio``, F_τ, F_n, M_Cζ → ``tangential``, ``normal``,
``moment_paper`` of :func:`slidespin.friction_wrench`.

What is here
------------
:func:`terminal_ratio`
    The paper's Table 1 quantity: the root β of eq. 16 with ϑ imposed (0 by default) and F_n
    ignored. It is a true terminal state only where F_n vanishes there too.
:func:`terminal_states`
    The true terminal motions at a frozen orientation φ: every fixed point of the sphere flow,
    its kind (``mixed``, ``pure_sliding``, ``pure_spinning``) and whether it attracts.

Table 2 (circular patch, orthotropic friction) is in :mod:`slidespin.analysis.intervals`;
trajectories in the (a ω, v) plane in :mod:`slidespin.analysis.phase_portrait`.

Departures from the paper: the paper solves eq. 16 with ϑ* = 0 imposed ("zero for orthotropic
friction") and reports that root as the terminal ratio. For an ellipse turned by φ ≠ 0, π/2
from the friction axes F_n ≠ 0 there, so the body does not stop that way: the true terminal
motion has ϑ* ≠ 0 and a different β* (MODEL §6, erratum 11). :func:`terminal_ratio` reproduces
the paper's method; :func:`terminal_states` gives the true answer.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import brentq, root

from slidespin import _validate as v
from slidespin.analysis._natural import _WRENCH_TOL, _fp_world, _missed, _params, _wrench_nat
from slidespin.contact import _engine
from slidespin.contact._kernel_ellipse import STATUS_OK, wrench_array
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure_map import symmetry

__all__ = ["terminal_ratio", "terminal_states", "TerminalState"]

_FP_TOL = 1e-9  # |du/dτ| below which a refined point is accepted as a fixed point


# ------------------------------------------------------------------------------------------
# input checks and the sphere flow in natural units (a = m = g = 1)
# ------------------------------------------------------------------------------------------
def _check_bracket(bracket, a: float) -> tuple[float, float]:
    """(lo, hi) of a β bracket [m], each in [1e-9 a, 1e9 a], lo < hi."""
    lo_r, hi_r = v.RATIO
    if not isinstance(bracket, (tuple, list, np.ndarray)) or len(bracket) != 2:
        raise ValueError(
            f"bracket = {v._short(bracket)} is invalid; valid values: a pair (lo, hi) of "
            f"terminal ratios beta [m] with {lo_r:g} a <= lo < hi <= {hi_r:g} a (a = {a!r} m)"
        )
    lo = v.bounded("bracket[0]", bracket[0], lo_r * a, hi_r * a, "m")
    hi = v.bounded("bracket[1]", bracket[1], lo_r * a, hi_r * a, "m")
    if not lo < hi:
        raise ValueError(f"bracket = ({lo!r}, {hi!r}) m is invalid; valid values: lo < hi")
    return lo, hi


def _acc(par, phi, u):
    """A(u, φ) = (Fx, Fy, M/k) in natural units for a direction u on the unit sphere."""
    k = par[_engine.P_K]
    fx, fy, m = _wrench_nat(par, phi, u[0], u[1], u[2] / k)
    return np.array([fx, fy, m / k])


def _acc_array(par, phi, u1, u2, u3):
    """A for arrays of directions (same shape), vectorised through the compiled kernel."""
    k = par[_engine.P_K]
    shape = np.shape(u1)
    u1, u2, u3 = (np.ascontiguousarray(np.ravel(x), dtype=float) for x in (u1, u2, u3))
    ph = np.full(u1.size, float(phi))
    if getattr(par, "fp", None) is not None:
        fx, fy, m = _fp_world(par, ph, u1, u2, u3 / k)
        return fx.reshape(shape), fy.reshape(shape), (m / k).reshape(shape)
    fx, fy, m, st = wrench_array(
        *_engine.elliptic_args(par),
        ph,
        u1,
        u2,
        u3 / k,
        _WRENCH_TOL,
    )
    if (st != STATUS_OK).any() or not np.all(np.isfinite(fx + fy + m)):
        raise RuntimeError(_missed(par))  # pragma: no cover - guard
    return fx.reshape(shape), fy.reshape(shape), (m / k).reshape(shape)


def _flow(par, phi, u):
    """Tangential field G(u) = A − (u·A) u of the sphere flow (MODEL §5)."""
    a = _acc(par, phi, u)
    return a - (u @ a) * u


# ------------------------------------------------------------------------------------------
# eq. 16: the paper's terminal ratio with ϑ imposed
# ------------------------------------------------------------------------------------------
def _eq16_residual(par, inertia_ratio, phi, theta):
    """h(β) = β M_Cζ − I* F_τ at ω = 1 (natural units); its sign is that of dβ/dt."""
    c, s = math.cos(theta), math.sin(theta)

    def h(beta):
        fx, fy, m = _wrench_nat(par, phi, beta * c, beta * s, 1.0)
        f_tau = -(fx * c + fy * s)
        return beta * (-m) - inertia_ratio * f_tau

    return h


def terminal_ratio(
    body: Body,
    friction: FrictionTensor,
    phi: float,
    theta: float = 0.0,
    *,
    bracket: tuple[float, float] | None = None,
) -> float:
    """Root β of the paper's eq. 16, β = I* F_τ/M_Cζ, with the direction ϑ imposed [m].

    This is how the paper computed its Table 1: the velocity of G is held in the direction
    ``theta`` (ϑ* = 0 in the paper) at the body angle ``phi``, the force across the velocity
    F_n is ignored, and β = v/ω > 0 is the root of β M_Cζ(β) − I* F_τ(β) = 0.

    Parameters
    ----------
    body : Body
        Patch (an ellipse or any footprint), pressure law and inertia (I* = I/(m a²) enters
        eq. 16; for a footprint a is its extent, :attr:`slidespin.Body.length_unit`).
    friction : FrictionTensor
        Friction tensor.
    phi : float
        Body angle φ [rad] between OX and the body axis ξ.
    theta : float, default 0
        Imposed direction ϑ of the velocity of G [rad].
    bracket : (float, float), optional
        Interval (lo, hi) of β [m], 1e-9 a ≤ lo < hi ≤ 1e9 a, known to contain exactly one
        root; skips the
        scan of β over 1e-5 a … 1e5 a (for repeated solves, e.g. fitting fx to Table 1).

    Returns
    -------
    float
        β [m] (same length unit as the patch; divide by ``body.length_unit`` for the
        paper's units). ``inf`` if eq. 16 has no root because β grows without bound (the spin dies
        first: β M_Cζ > I* F_τ for every β), ``0.0`` if it shrinks to zero (the sliding
        dies first). If there are several roots, the smallest one that attracts the motion
        along the imposed direction (dβ/dt, which has the sign of β M_Cζ − I* F_τ, changes
        from + to −); NaN if every root repels.

    Notes
    -----
    Paper eq. 14–16 and §3.1; MODEL §6. The root is a true terminal motion only where F_n
    also vanishes (for the paper's Table 1: φ = π/2, not φ = π/4 or π/3); use
    :func:`terminal_states` for the true terminal motion. Spin ω > 0 is assumed, as in the
    paper's coefficients (6).

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> disk = Body.from_inertia_ratio(Circle(1.0), UniformPressure(), 1.0, 0.5)
    >>> round(terminal_ratio(disk, FrictionTensor(0.3, 0.3), phi=0.0), 3)  # published 0.653
    0.653
    """
    check_body_friction(body, friction)
    phi = v.finite("phi", phi)
    theta = v.finite("theta", theta)
    par = _params(body, friction)
    h = _eq16_residual(par, body.inertia_ratio, phi, theta)
    a = body.length_unit
    if bracket is not None:
        lo, hi = (x / a for x in _check_bracket(bracket, a))
        if h(lo) * h(hi) > 0.0:
            raise ValueError(
                f"bracket = {tuple(bracket)!r} m is invalid; valid values: lo < hi with one "
                "root of eq. 16 between them"
            )
        return float(brentq(h, lo, hi, xtol=1e-15, rtol=1e-15, maxiter=200) * a)
    grid = np.logspace(-5.0, 5.0, 201)
    vals = np.array([h(b) for b in grid])
    roots = []
    for i in range(grid.size - 1):
        if vals[i] == 0.0:
            roots.append((grid[i], vals[i - 1] > 0.0 if i else True))
        elif vals[i] * vals[i + 1] < 0.0:
            r = brentq(h, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15, maxiter=200)
            roots.append((r, vals[i] > 0.0))
    attracting = [r for r, falling in roots if falling]
    if attracting:
        return float(attracting[0] * a)
    if roots:  # only repelling roots: no terminal ratio along this direction
        return math.nan
    return math.inf if vals[-1] > 0.0 else 0.0


# ------------------------------------------------------------------------------------------
# fixed points of the sphere flow
# ------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class TerminalState:
    """One terminal motion: a fixed point u* of the sphere flow at a frozen body angle.

    Attributes
    ----------
    beta : float
        β* = v/ω [m], signed like ω; ``inf`` for a pure-sliding ending (ω/v → 0) and 0 for a
        pure-spinning one (v/ω → 0).
    beta_ratio : float
        β*/a, the paper's units.
    theta : float
        Direction ϑ* of the velocity of G [rad] in (−π, π]. For a pure-spinning ending, the
        direction of the vanishing velocity as u approaches the pole (the slow
        eigendirection, defined modulo π and given in (−π/2, π/2]). NaN when it is undetermined: a circle of
        fixed points (isotropic friction with a rotationally symmetric body) or a pure spin
        approached along every direction alike.
    ending : str
        ``mixed``, ``pure_sliding`` or ``pure_spinning``.
    stable : bool
        Whether the motion converges to it from nearby directions (both eigenvalues of the
        linearised sphere flow have negative real parts; for a circle of fixed points, the
        eigenvalue across the circle).
    eigenvalues : tuple of complex
        Eigenvalues of the sphere flow linearised at u*, per unit regularised time τ
        (dt = s dτ, natural units a = m = g = 1).
    u : tuple of float
        The fixed point (vx, vy, k ω)/s, k = √(I/m).
    phi : float
        Body angle φ [rad] at which it was computed.
    continuum : bool
        True when u* lies on a circle of fixed points (then ``theta`` is NaN).
    """

    beta: float
    beta_ratio: float
    theta: float
    ending: str
    stable: bool
    eigenvalues: tuple[complex, ...]
    u: tuple[float, ...]
    phi: float
    continuum: bool = False

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dict (``inf``/``nan`` written as strings)."""

        def num(x):
            x = float(x)
            if math.isnan(x):
                return "nan"
            return x if math.isfinite(x) else ("inf" if x > 0 else "-inf")

        return {
            "beta": num(self.beta),
            "beta_ratio": num(self.beta_ratio),
            "theta": num(self.theta),
            "ending": self.ending,
            "stable": bool(self.stable),
            "eigenvalues": [[num(z.real), num(z.imag)] for z in self.eigenvalues],
            "u": [num(x) for x in self.u],
            "phi": num(self.phi),
            "continuum": self.continuum,
        }


def _tangent_basis(u):
    """Two orthonormal vectors spanning the tangent plane of the sphere at u."""
    ref = np.array([0.0, 0.0, 1.0]) if abs(u[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    e1 = np.cross(ref, u)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(u, e1)
    return e1, e2


def _jacobian(par, phi, u, e1, e2, h=1e-5):
    """2×2 Jacobian of the sphere flow at u in the tangent basis (e1, e2) (central differences)."""
    jac = np.empty((2, 2))
    for j, e in enumerate((e1, e2)):
        up = u + h * e
        um = u - h * e
        gp = _flow(par, phi, up / np.linalg.norm(up))
        gm = _flow(par, phi, um / np.linalg.norm(um))
        d = (gp - gm) / (2.0 * h)
        jac[0, j] = e1 @ d
        jac[1, j] = e2 @ d
    return jac


def _wrap(angle):
    """Angle in (−π, π]."""
    a = math.remainder(angle, 2.0 * math.pi)
    return math.pi if a == -math.pi else a


def _make_state(par, phi, u, a_len, *, continuum=False, jac=None, e1=None, e2=None):
    u = np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    k = par[_engine.P_K]
    u12 = math.hypot(u[0], u[1])
    if e1 is None:
        e1, e2 = _tangent_basis(u)
    if jac is None:
        jac = _jacobian(par, phi, u, e1, e2)
    lam, vec = np.linalg.eig(jac)
    order = np.argsort(-lam.real)  # slowest (largest real part) first
    lam = lam[order]
    vec = vec[:, order]
    if continuum:
        # one eigenvalue is the neutral direction along the circle: judge by the other one
        across = lam[np.argmax(np.abs(lam))]
        stable = bool(across.real < 0.0)
    else:
        stable = bool(np.all(lam.real < 0.0))
    if abs(u[2]) <= 1e-12:
        ending, beta = "pure_sliding", math.inf
        theta = math.atan2(u[1], u[0])
    elif u12 <= 1e-12:
        ending, beta = "pure_spinning", 0.0
        theta = math.nan
        if not continuum and np.all(np.abs(lam.imag) < 1e-9) and abs(lam[0] - lam[1]) > 1e-7:
            d = vec[0, 0].real * e1 + vec[1, 0].real * e2  # slow eigendirection
            theta = math.atan2(d[1], d[0])
            if theta <= -math.pi / 2:
                theta += math.pi
            elif theta > math.pi / 2:
                theta -= math.pi
    else:
        ending = "mixed"
        beta = k * u12 / u[2]
        theta = math.atan2(u[1], u[0])
    if continuum:
        theta = math.nan
    if math.isfinite(beta):
        beta_m = beta * a_len
    else:
        beta_m = beta
    return TerminalState(
        beta=float(beta_m),
        beta_ratio=float(beta),
        theta=float(theta if math.isnan(theta) else _wrap(theta)),
        ending=ending,
        stable=stable,
        eigenvalues=tuple(complex(z) for z in lam),
        u=tuple(float(x) for x in u),
        phi=float(phi),
        continuum=continuum,
    )


def _rotationally_symmetric(body, friction) -> bool:
    """Circle, centred pressure and an isotropic symmetric part: the flow commutes with
    rotations about the spin axis, so fixed points off the poles come in circles. For a
    footprint: a centred disk or ring under uniform pressure
    (:func:`slidespin.contact.pressure_map.symmetry`)."""
    if body.is_footprint:
        return bool(symmetry(body.patch, body.pressure)[1] and friction.fx == friction.fy)
    patch = body.patch
    centred = body.mass_centre == (0.0, 0.0)
    return bool(patch.a == patch.b and centred and friction.fx == friction.fy)


def _equator_points(par, body, friction, phi, a_len):
    """Pure-sliding fixed points: u = (v̂, 0) with 𝔽_world v̂ ∥ v̂ (M = 0 in pure translation)."""
    t = friction.world_matrix(phi)
    out = []
    if np.allclose(t, t[0, 0] * np.eye(2), rtol=0.0, atol=1e-15 * abs(t[0, 0])):
        # isotropic: every direction is a fixed point; judge the circle by its worst point
        worst = None
        for th in np.linspace(0.0, math.pi, 13)[:-1] + 0.0123:
            u = np.array([math.cos(th), math.sin(th), 0.0])
            e1 = np.array([-math.sin(th), math.cos(th), 0.0])
            e2 = np.array([0.0, 0.0, 1.0])
            st = _make_state(par, phi, u, a_len, continuum=True, e1=e1, e2=e2)
            across = max(st.eigenvalues, key=abs).real  # the other one is ≈ 0 (neutral)
            if worst is None or across > worst[0]:
                worst = (across, st)
        return [worst[1]]
    lam, vec = np.linalg.eig(t)
    if np.any(np.abs(lam.imag) > 0.0):
        return out  # skew part dominates: the sliding direction keeps turning
    for j in range(2):
        d = vec[:, j].real
        d = d / np.linalg.norm(d)
        for sgn in (1.0, -1.0):
            th = math.atan2(sgn * d[1], sgn * d[0])
            u = np.array([math.cos(th), math.sin(th), 0.0])
            e1 = np.array([-math.sin(th), math.cos(th), 0.0])
            e2 = np.array([0.0, 0.0, 1.0])
            out.append(_make_state(par, phi, u, a_len, e1=e1, e2=e2))
    return out


def _pole_points(par, body, friction, phi, a_len, symmetric):
    """Pure-spinning fixed points u = (0, 0, ±1), present when the force in pure spin is 0."""
    out = []
    for sgn in (1.0, -1.0):
        u = np.array([0.0, 0.0, sgn])
        a = _acc(par, phi, u)
        if math.hypot(a[0], a[1]) <= _FP_TOL * max(1.0, np.abs(a).max()):
            e1 = np.array([1.0, 0.0, 0.0])
            e2 = np.array([0.0, sgn, 0.0])
            st = _make_state(par, phi, u, a_len, e1=e1, e2=e2)
            if symmetric:
                st = TerminalState(**{**_as_kwargs(st), "theta": math.nan})
            out.append(st)
    return out


def _as_kwargs(st):
    return {name: getattr(st, name) for name in TerminalState.__dataclass_fields__}


def _chart(theta, chi):
    """u(ϑ, χ) = (cos χ cos ϑ, cos χ sin ϑ, sin χ) and its unit tangent vectors."""
    ct, st = math.cos(theta), math.sin(theta)
    cc, sc = math.cos(chi), math.sin(chi)
    u = np.array([cc * ct, cc * st, sc])
    e_th = np.array([-st, ct, 0.0])
    e_chi = np.array([-sc * ct, -sc * st, cc])
    return u, e_th, e_chi


def _mixed_points(par, phi, a_len, symmetric, n_theta=72, n_chi=28):
    """Fixed points off the equator and the poles, in the upper hemisphere (ω > 0)."""
    j = np.arange(1, n_chi + 1)
    chi = 0.25 * math.pi * (1.0 - np.cos(math.pi * j / (n_chi + 1)))  # dense near both ends
    found = []

    def residual(x):
        u, e_th, e_chi = _chart(x[0], x[1])
        a = _acc(par, phi, u)
        return np.array([e_th @ a, e_chi @ a])

    def accept(x):
        th, ch = float(x[0]), float(x[1])
        if not (1e-7 < ch < 0.5 * math.pi - 1e-7):
            return
        u, _, _ = _chart(th, ch)
        if np.linalg.norm(_flow(par, phi, u)) > _FP_TOL:
            return
        for w in found:
            if np.linalg.norm(w - u) < 1e-7:
                return
        found.append(u)

    if symmetric:
        # rotation invariance: solve on the meridian ϑ = 0 only
        c, s = np.cos(chi), np.sin(chi)
        ax, ay, am = _acc_array(par, phi, c, 0.0 * c, s)
        g_th = ay
        g_chi = -s * ax + c * am
        for i in range(chi.size - 1):
            if g_chi[i] * g_chi[i + 1] <= 0.0 and max(abs(g_th[i]), abs(g_th[i + 1])) < 1e-6:
                f = lambda x: residual((0.0, x))[1]  # noqa: E731
                try:
                    r = brentq(f, chi[i], chi[i + 1], xtol=1e-15)
                except ValueError:
                    continue
                accept((0.0, r))
        return found

    th = -math.pi + 2.0 * math.pi * (np.arange(n_theta + 1) + 0.3719) / n_theta
    tt, cc = np.meshgrid(th, chi, indexing="ij")
    u1 = np.cos(cc) * np.cos(tt)
    u2 = np.cos(cc) * np.sin(tt)
    u3 = np.sin(cc)
    ax, ay, am = _acc_array(par, phi, u1, u2, u3)
    g_th = -np.sin(tt) * ax + np.cos(tt) * ay
    g_chi = -np.sin(cc) * (np.cos(tt) * ax + np.sin(tt) * ay) + np.cos(cc) * am

    def straddles(g):
        corners = np.stack([g[:-1, :-1], g[1:, :-1], g[:-1, 1:], g[1:, 1:]])
        return (corners.min(axis=0) <= 0.0) & (corners.max(axis=0) >= 0.0)

    cand = np.argwhere(straddles(g_th) & straddles(g_chi))
    for i, jj in cand:
        x0 = (0.5 * (th[i] + th[i + 1]), 0.5 * (chi[jj] + chi[jj + 1]))
        sol = root(residual, x0, method="hybr", options={"xtol": 1e-14})
        accept(sol.x)
    return found


def terminal_states(body: Body, friction: FrictionTensor, phi: float) -> tuple[TerminalState, ...]:
    """All terminal motions of ``body`` at the body angle ``phi`` (MODEL §5–6).

    The terminal motions are the fixed points of the flow of the direction of motion on the
    unit sphere, du/dτ = A(u, φ) − (u·A) u, with the body angle frozen at φ (the body turns
    by a vanishing angle once u is close to a fixed point). Each fixed point satisfies the
    paper's terminal conditions F_n = 0 and β = I* F_τ/M_Cζ (eq. 14–16) *without* imposing ϑ.

    Parameters
    ----------
    body : Body
        Patch (an ellipse or any footprint; β*/a is then in units of its extent), pressure
        law, mass and inertia.
    friction : FrictionTensor
        Friction tensor (plane- or body-fixed).
    phi : float
        Body angle φ [rad].

    Returns
    -------
    tuple of TerminalState
        Every fixed point found, attracting ones first, then spin ω ≥ 0 before ω < 0, then by
        |ϑ*|. Fixed points come in antipodal pairs (u*, −u*: the same motion with velocity
        and spin reversed); for a centrally symmetric body under a plane-fixed tensor also
        (ϑ*, ϑ* + π).

    Notes
    -----
    Method: pure-sliding fixed points (u₃ = 0) are the real eigenvectors of the world-frame
    tensor (the moment vanishes in pure translation because G lies over the pressure
    centroid); pure-spinning ones (u₁₂ = 0) exist where the force vanishes in a pure spin
    about G; the others are found on a 72 × 28 grid of the hemisphere ω > 0 by sign changes
    of the two tangential components of du/dτ, refined by Powell's hybrid method to
    |du/dτ| < 1e-9, and mirrored to ω < 0. Stability: eigenvalues of the 2 × 2 Jacobian of
    the flow in the tangent plane, by central differences. Fixed points closer than about
    1e-3 rad to the equator or the poles (an inertia ratio very close to a Table 2 boundary)
    can be missed by the grid.

    Examples
    --------
    >>> import math
    >>> from slidespin import Body, Ellipse, UniformPressure, FrictionTensor
    >>> body = Body(Ellipse.from_eccentricity(1.0, 0.866), UniformPressure(), mass=1.0)
    >>> best = terminal_states(body, FrictionTensor(0.42, 0.54), math.pi / 2)[0]
    >>> best.ending, round(best.beta_ratio, 3), round(best.theta, 6) + 0.0
    ('mixed', 0.637, 0.0)
    """
    check_body_friction(body, friction)
    phi = v.finite("phi", phi)
    par = _params(body, friction)
    a_len = body.length_unit
    symmetric = _rotationally_symmetric(body, friction)
    states = []
    states += _equator_points(par, body, friction, phi, a_len)
    states += _pole_points(par, body, friction, phi, a_len, symmetric)
    for u in _mixed_points(par, phi, a_len, symmetric):
        st = _make_state(par, phi, u, a_len, continuum=symmetric)
        states.append(st)
        anti = TerminalState(
            **{
                **_as_kwargs(st),
                "beta": -st.beta,
                "beta_ratio": -st.beta_ratio,
                "theta": st.theta if math.isnan(st.theta) else _wrap(st.theta + math.pi),
                "u": tuple(-x for x in st.u),
            }
        )
        states.append(anti)

    def key(s):
        spin_first = 0 if s.u[2] >= 0.0 else 1
        th = 0.0 if math.isnan(s.theta) else abs(s.theta)
        return (0 if s.stable else 1, spin_first, th)

    return tuple(sorted(states, key=key))
