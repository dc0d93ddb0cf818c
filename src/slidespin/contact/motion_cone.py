"""Motion cones of a sticking point push, on the exact limit surface (MODEL §13).

A finger touching the body's outline at c with inward unit normal n and Coulomb coefficient
μp can push with any force in the cone spanned by f± = n ± μp t (t = ẑ × n). Quasi-statically
(inertia neglected, MODEL §13) the body moves with the unit twist û whose plane friction
wrench balances the pusher's: W(û) = −s w, s > 0. The **motion cone** (Mason 1986; Lynch &
Mason 1996) is the set of twists reachable with a sticking contact; its two edges are the
images û± of the friction cone's edges, with pusher wrenches (about the mass centre G)

    w± = (f±, (c − r_G) × f±).

:func:`motion_cone` solves W(û±) = −s± w± for the exact wrench of
:func:`slidespin.friction_wrench` (closed forms for footprints, the paper's quadrature for
ellipses), any footprint, pressure law and friction tensor, and
:meth:`MotionCone.compare_fits` reports how far the ellipsoid and quartic fits of
:func:`slidespin.limit_surface` put the same edges: the number the field lacks.

Symbols and code names: c → ``contact`` (body frame C ξ η, like footprint vertices), n →
``normal``, μp → ``mu``, û± → ``MotionCone.edges`` as unit (vx, vy, ω ℓ) with ℓ =
:attr:`slidespin.Body.length_unit`, w± → ``MotionCone.wrenches``.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from slidespin import _validate as v
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.wrench import friction_wrench

__all__ = [
    "FitComparison",
    "MotionCone",
    "StablePushing",
    "edge_twist",
    "motion_cone",
    "stable_pushing",
]

#: |Ŵ(û) + ŵ| at which an edge twist is accepted (the exact wrench's round-off is ~1e-15)
RESIDUAL_TOL = 1e-11


def _pair(name: str, value: object) -> NDArray[np.float64]:
    bad = f"{name} = {v._short(value)} is invalid; valid values: a pair of finite numbers"
    if isinstance(value, (str, bytes, bytearray)) or value is None:
        raise ValueError(bad)
    try:
        items = list(value)  # type: ignore[call-overload]
    except TypeError:
        raise ValueError(bad) from None
    if len(items) != 2:
        raise ValueError(bad)
    out = []
    for i, x in enumerate(items):
        if isinstance(x, np.generic):
            x = x.item()
        if isinstance(x, bool) or not isinstance(x, numbers.Real):
            raise ValueError(
                f"{name}[{i}] = {v._short(x)} is invalid; valid values: a finite real number"
            )
        out.append(v.finite(f"{name}[{i}]", x))
    return np.array(out)


#: the largest pusher–body coefficient μp accepted (beyond it the cone's edge directions lose
#: every digit: 1 + μp² overflows near 1e154)
MU_MAX = 1e9


def pusher_mu(value: object) -> float:
    """A pusher's Coulomb coefficient μp at the pusher–body contact, checked: a real number in
    [0, ``MU_MAX``], not a bool (one-line ``ValueError`` naming ``mu``). Shared with the pushers
    of :mod:`slidespin.motion.pushers`."""
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(
            f"mu = {v._short(value)} ({type(value).__name__}) is invalid; valid range: a "
            "number in [0, 1e+09] (the pusher-body Coulomb coefficient)"
        )
    x = v._as_float("mu", value)
    if not (math.isfinite(x) and 0.0 <= x <= MU_MAX):
        raise ValueError(
            f"mu = {x!r} is invalid; valid range: [0, {MU_MAX:g}] (the pusher-body Coulomb "
            "coefficient; 1e9 is a cone within 1e-9 rad of a half plane: no slip)"
        )
    return x


class _Wrench:
    """W(û) in natural units: (Fx/P, Fy/P, M/(P ℓ)) for the unit twist û = (vx, vy, ω ℓ),
    body at φ = 0, P = m g (g = 1)."""

    def __init__(self, body: Body, friction: FrictionTensor) -> None:
        self.body, self.friction = body, friction
        self.ell = body.length_unit
        self.calls = 0

    def __call__(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        self.calls += 1
        m, ell = self.body.mass, self.ell
        w = friction_wrench(self.body, self.friction, u[0], u[1], u[2] / ell, 0.0, 1.0)
        return np.array([w.force_x / m, w.force_y / m, w.moment / (m * ell)])

    def many(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        m, ell = self.body.mass, self.ell
        w = friction_wrench(self.body, self.friction, u[:, 0], u[:, 1], u[:, 2] / ell, 0.0, 1.0)
        return np.column_stack((w.force_x / m, w.force_y / m, w.moment / (m * ell)))


def _basis(d: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Two unit vectors completing the unit vector d to an orthonormal basis."""
    k = int(np.argmin(np.abs(d)))
    e = np.zeros(3)
    e[k] = 1.0
    e1 = e - (e @ d) * d
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(d, e1)


def _solve(wrench: _Wrench, target: NDArray[np.float64], guess: NDArray[np.float64]):
    """The unit twist û near ``guess`` with Ŵ(û) = ``target`` (a unit wrench): Newton's
    method on the two angles of û about the current iterate, with a finite-difference
    Jacobian and a backtracking line search on |Ŵ − target|. Returns (û, residual)."""
    f1, f2 = _basis(target)

    def resid(u):
        w = wrench(u)
        nw = np.linalg.norm(w)
        wh = w / nw
        # the components across the target, and a penalty for the opposite direction
        r = np.array([wh @ f1, wh @ f2])
        return r, float(np.linalg.norm(wh - target)), wh

    u = guess / np.linalg.norm(guess)
    r, err, _ = resid(u)
    for _ in range(60):
        if err <= 1e-15:
            break
        e1, e2 = _basis(u)
        h = 1e-7
        jac = np.empty((2, 2))
        for j, e in enumerate((e1, e2)):
            up = u + h * e
            um = u - h * e
            jac[:, j] = (resid(up / np.linalg.norm(up))[0] - resid(um / np.linalg.norm(um))[0]) / (
                2 * h
            )
        try:
            step = -np.linalg.solve(jac, r)
        except np.linalg.LinAlgError:
            step = -np.linalg.lstsq(jac, r, rcond=None)[0]
        lam = 1.0
        norm = float(np.linalg.norm(step))
        if norm > 0.5:  # at most ~0.5 rad per step
            lam = 0.5 / norm
        improved = False
        for _ in range(40):
            trial = u + lam * (step[0] * e1 + step[1] * e2)
            trial /= np.linalg.norm(trial)
            rt, et, _ = resid(trial)
            if et < err:
                u, r, err = trial, rt, et
                improved = True
                break
            lam *= 0.5
        if not improved:
            break
    return u, err


def edge_twist(
    body: Body,
    friction: FrictionTensor,
    wrench: NDArray[np.float64],
    *,
    _w: _Wrench | None = None,
) -> tuple[NDArray[np.float64], float]:
    """The quasi-static unit twist û = (vx, vy, ω ℓ)/|·| under a pusher wrench (MODEL §13).

    Solves W(û) = −s w, s > 0, for the exact friction wrench W of the body at φ = 0.

    Parameters
    ----------
    body, friction : Body, FrictionTensor
    wrench : array_like (3,)
        The pusher's wrench (Fx, Fy, M/ℓ) in natural units (any scale; M about G, ℓ =
        ``body.length_unit``).

    Returns
    -------
    (ndarray (3,), float)
        û and the residual |Ŵ(û) + ŵ| (hats: unit vectors).

    Notes
    -----
    The search starts from the twist the limit surface's ellipsoid of the body's own
    force and spin wrenches would give, then Newton's method on the sphere of twists. For
    isotropic friction the twist is the normal of the convex limit surface (maximum
    dissipation) and unique. For an anisotropic tensor W(û) is not of maximum dissipation
    and the equation may have several solutions; the one reached from that start is
    returned and, if it fails, starts spread over the sphere are tried and the solution
    nearest the ellipsoid's start is kept.
    """
    w = np.asarray(wrench, dtype=float)
    target = -w / np.linalg.norm(w)
    wr = _w if _w is not None else _Wrench(body, friction)
    # start: an ellipsoid with the body's pure-translation force and pure-spin moment
    fmax = float(np.linalg.norm(wr(np.array([1.0, 0.0, 0.0]))[:2]))
    mmax = abs(float(wr(np.array([0.0, 0.0, 1.0]))[2]))
    guess = np.array([w[0] / fmax**2, w[1] / fmax**2, w[2] / mmax**2])
    u, err = _solve(wr, target, guess)
    if err <= RESIDUAL_TOL:
        return u, err
    # multi-start over the sphere (the Fibonacci lattice), best candidates first
    i = np.arange(200) + 0.5
    z = 1.0 - 2.0 * i / 200
    rr = np.sqrt(np.maximum(0.0, 1.0 - z * z))
    t = math.pi * (3.0 - math.sqrt(5.0)) * i
    starts = np.column_stack((rr * np.cos(t), rr * np.sin(t), z))
    ws = wr.many(starts)
    ws /= np.linalg.norm(ws, axis=1)[:, None]
    order = np.argsort(np.linalg.norm(ws - target, axis=1))
    best = (u, err)
    gh = guess / np.linalg.norm(guess)
    found = []
    for k in order[:12]:
        uk, ek = _solve(wr, target, starts[k])
        if ek <= RESIDUAL_TOL:
            found.append(uk)
        elif ek < best[1]:
            best = (uk, ek)
    if found:
        uk = max(found, key=lambda x: float(x @ gh))
        return uk, float(np.linalg.norm(wr(uk) / np.linalg.norm(wr(uk)) - target))
    return best


@dataclass(frozen=True)
class FitComparison:
    """What the fitted limit surfaces predict for the motion cone's edges.

    Attributes
    ----------
    ellipsoid_edges, quartic_edges : ndarray (2, 3)
        The twists normal to the fitted ellipsoid and quartic at the directions of the two
        pusher wrenches, unit (vx, vy, ω ℓ) with ℓ = ``body.length_unit``.
    ellipsoid_angle, quartic_angle : ndarray (2,)
        Angle [rad] between each predicted edge and the exact one.
    """

    ellipsoid_edges: NDArray[np.float64]
    quartic_edges: NDArray[np.float64]
    ellipsoid_angle: NDArray[np.float64]
    quartic_angle: NDArray[np.float64]


def _angle(a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    """Angles between the rows of a and b, accurate also for tiny angles (atan2 of the
    cross and dot products)."""
    cr = np.linalg.norm(np.cross(a, b), axis=-1)
    return np.arctan2(cr, np.sum(a * b, axis=-1))


@dataclass(frozen=True)
class MotionCone:
    """The motion cone of a sticking point push (MODEL §13).

    Attributes
    ----------
    edges : ndarray (2, 3)
        The edge twists û± at G as unit rows (vx, vy, ω ℓ), ℓ = ``length``, in the order
        (n + μ t edge, n − μ t edge).
    wrenches : ndarray (2, 3)
        The pusher wrenches w± = (fx, fy, M) [1, 1, m] of the unit-normal-load forces
        f± = n ± μ t, moments about G (counter-clockwise).
    contact, normal : ndarray (2,)
        c in the body frame C ξ η [m], and the inward unit normal n.
    mu : float
        μp.
    length : float
        ℓ [m] of the twists' ω ℓ.
    residuals : ndarray (2,)
        |Ŵ(û) + ŵ| per edge (unit vectors): how exactly the friction wrench of each edge
        twist opposes its pusher wrench.

    The cone also reads as its two edge rows: ``np.asarray(cone)`` is ``edges``,
    ``cone[0]`` and ``cone[1]`` the edges, and ``upper, lower = cone`` unpacks them.
    """

    edges: NDArray[np.float64]
    wrenches: NDArray[np.float64]
    contact: NDArray[np.float64]
    normal: NDArray[np.float64]
    mu: float
    length: float
    residuals: NDArray[np.float64]
    body: Body
    friction: FrictionTensor

    # the cone reads as its two edge rows: np.asarray(cone) is ``edges`` (2, 3), cone[0] and
    # cone[1] are the edges, and ``upper, lower = cone`` unpacks them
    def __array__(self, dtype=None, copy=None) -> NDArray[np.float64]:
        return np.array(self.edges, dtype=dtype)

    def __len__(self) -> int:
        return 2

    def __getitem__(self, index):
        return self.edges[index]

    def __iter__(self):
        return iter(self.edges)

    @property
    def rotation_centres(self) -> NDArray[np.float64]:
        """The instantaneous centres of rotation of the two edge twists, relative to G in the
        body frame's orientation [m] (rows of inf for a pure translation)."""
        out = np.full((2, 2), np.inf)
        for k, (vx, vy, wl) in enumerate(self.edges):
            if wl != 0.0:
                om = wl / self.length
                out[k] = (-vy / om, vx / om)
        return out

    @property
    def half_angle(self) -> float:
        """Half the angle between the two edges [rad] (0 for μp = 0)."""
        return float(0.5 * _angle(self.edges[0], self.edges[1]))

    def contains(self, twist) -> bool:
        """True if the twist (vx, vy, ω ℓ) lies in the cone spanned by the two edges, i.e. is
        a non-negative combination of them (a sticking push produces it)."""
        t = _pair3("twist", twist)
        a, b = self.edges
        m = np.column_stack((a, b))
        coef, *_ = np.linalg.lstsq(m, t, rcond=None)
        off = np.linalg.norm(m @ coef - t)
        return bool(np.all(coef >= -1e-12 * np.linalg.norm(t)) and off <= 1e-9 * np.linalg.norm(t))

    def compare_fits(self, surface=None, n: int = 400) -> FitComparison:
        """The edges the ellipsoid and quartic fits of :func:`slidespin.limit_surface` predict,
        and their angles [rad] from the exact edges.

        Parameters
        ----------
        surface : LimitSurface or None
            A limit surface of this body and friction (at φ = 0); default
            ``limit_surface(body, friction, n=n)``.
        n : int, default 400
            Samples of the default surface.

        Notes
        -----
        A fitted surface F(w) = 1 (w normalised by P and the surface's own length ℓ_s)
        predicts, for a pusher wrench w, the twist normal to it where the ray of w meets it:
        ∇F(w) ∝ (A w) for the ellipsoid, the quartic's gradient for the quartic (the limit
        surface is symmetric, W(−û) = −W(û), so the normal at w is the twist whose friction
        wrench is along −w). Its ω ℓ_s is turned into ω ℓ before comparing.
        """
        ell, quart = _fit_twists(self.wrenches, self.body, self.friction, surface, n, self.length)
        return FitComparison(ell, quart, _angle(ell, self.edges), _angle(quart, self.edges))


def motion_cone(
    body: Body, friction: FrictionTensor, contact, normal, mu: float = 0.0
) -> MotionCone:
    """The motion cone of a sticking point push on the exact limit surface (MODEL §13).

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body (at φ = 0: the cone is expressed in the body frame's orientation) and the
        plane friction tensor, any footprint, pressure law and tensor.
    contact : (float, float)
        The contact point c [m] in the body frame C ξ η (measured from the patch centre C,
        like footprint vertices and ``Load.at``; for uniform pressure on a centred symmetric
        patch C = G). It should lie on the body's outline
        (:func:`slidespin.contact.outline.body_outline`); it is not checked against it.
    normal : (float, float)
        The inward normal n at c (into the body), body frame; normalised here. It must point
        to the side of G: n·(r_G − c) > 0.
    mu : float, default 0
        μp, the pusher-body Coulomb coefficient, finite and ≥ 0.

    Returns
    -------
    MotionCone
        ``edges`` (2, 3): the unit twists (vx, vy, ω ℓ) at G, ℓ = ``body.length_unit``,
        for the forces n + μ t and n − μ t (t = ẑ × n), in this order.

    Notes
    -----
    Each edge twist solves W(û) = −s w, s > 0, with W the exact friction wrench
    (:func:`edge_twist`), to a residual |Ŵ(û) + ŵ| ≲ 1e-13; the twist then carries an error
    of about the residual times the limit surface's curvature ratio. For isotropic friction
    the solution is unique (maximum dissipation, convex limit surface); for an anisotropic
    tensor see :func:`edge_twist`.

    Examples
    --------
    >>> import slidespin as ss
    >>> disk = ss.Body(ss.Circle(0.1), ss.UniformPressure(), 1.0)
    >>> cone = motion_cone(disk, ss.FrictionTensor(0.3, 0.3), (-0.1, 0.0), (1.0, 0.0), 0.0)
    >>> (cone.edges.round(12) + 0.0).tolist()  # a push through G translates the disk
    [[1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    """
    check_body_friction(body, friction)
    c = _pair("contact", contact)
    n = _pair("normal", normal)
    mu = pusher_mu(mu)
    size = math.hypot(*n)
    if not size > 0.0:
        raise ValueError(
            f"normal = {tuple(n.tolist())} is invalid; valid values: a non-zero (unit) vector"
        )
    n = n / size
    g = np.array(body.mass_centre, dtype=float)
    r = c - g
    ell = body.length_unit
    far = math.hypot(*r)
    if not far <= 1e6 * ell:
        raise ValueError(
            f"contact = {tuple(c.tolist())} m is invalid: {far:.6g} m from G; valid range: "
            f"within 1e6 length units ({1e6 * ell:g} m) of G"
        )
    if not float(n @ (-r)) > 0.0:
        raise ValueError(
            f"normal = {tuple(n.tolist())} is invalid at contact = {tuple(c.tolist())}: it "
            f"does not point into the body (towards G = {tuple(g.tolist())}); valid values: "
            "the inward normal, n . (G - c) > 0"
        )
    t = np.array([-n[1], n[0]])
    forces = np.array([n + mu * t, n - mu * t])
    moments = r[0] * forces[:, 1] - r[1] * forces[:, 0]
    wrenches = np.column_stack((forces, moments))
    wr = _Wrench(body, friction)
    edges, res = np.empty((2, 3)), np.empty(2)
    for k in range(2):
        nat = wrenches[k].copy()
        nat[2] /= ell
        if k == 1 and mu == 0.0:
            edges[1], res[1] = edges[0], res[0]
            break
        edges[k], res[k] = edge_twist(body, friction, nat, _w=wr)
    if not np.all(res <= RESIDUAL_TOL):
        raise RuntimeError(
            f"motion_cone: no twist balances the pusher wrench to {RESIDUAL_TOL:g} "
            f"(residuals {res.tolist()}); please report this body and friction"
        )
    return MotionCone(edges, wrenches, c, n, mu, ell, res, body, friction)


# ------------------------------------------------------------------------------------------
# stable pushing with a line pusher (Lynch & Mason 1996)


def _fit_twists(wrenches, body, friction, surface, n, length) -> tuple:
    """Twists normal to the ellipsoid and quartic fits at the directions of ``wrenches``
    (rows (fx, fy, M) in N-free units, M in m), as unit (vx, vy, ω ℓ)."""
    from slidespin.contact.limit_surface import (  # lazy: scipy.optimize (nnls) is slow to import
        LimitSurface,
        _quartic_value_grad,
        limit_surface,
    )

    if surface is None:
        surface = limit_surface(body, friction, n=n)
    if not isinstance(surface, LimitSurface):
        raise ValueError(
            f"surface = {v._short(surface)} is invalid; valid values: a LimitSurface or None"
        )
    ls = surface.length
    w = np.array(wrenches, dtype=float)
    w[:, 2] /= ls
    _, quart = _quartic_value_grad(surface.quartic, w)
    out = []
    for pred in (w @ surface.ellipsoid, quart):
        tw = pred.copy()
        tw[:, 2] *= length / ls
        tw /= np.linalg.norm(tw, axis=1)[:, None]
        out.append(tw)
    return out[0], out[1]


@dataclass(frozen=True)
class StablePushing:
    """The pusher motions for which a body in face contact stays stuck to a line pusher.

    With the pusher's face against a flat edge of the body over the segment [a, b] (body
    frame), inward normal n, the contact can transmit any wrench in the cone spanned by the
    four wrenches of the friction-cone edges n ± μ t at a and at b (a line contact's normal
    load may sit anywhere on the segment; MODEL §13). Quasi-statically the body moves with
    the pusher (the same twist at G) iff the friction wrench of that twist is balanced by the
    contact: −W(û) ∈ cone{g₁..g₄} (Lynch & Mason 1996, "Stable pushing", here with the exact
    limit surface rather than an ellipsoid).

    Attributes
    ----------
    face : ndarray (2, 2)
        The shared segment's ends a, b in the body frame [m].
    normal : ndarray (2,)
        Inward unit normal n.
    mu : float
        μp.
    generators : ndarray (4, 3)
        The wrenches (fx, fy, M) [1, 1, m] of n + μt at a, n − μt at a, n + μt at b,
        n − μt at b (unit normal load, M about G).
    corners : ndarray (4, 3)
        The unit twists (vx, vy, ω ℓ) whose friction wrench opposes each generator: the
        corners of the stable set (:func:`edge_twist`).
    length : float
        ℓ [m].
    """

    face: NDArray[np.float64]
    normal: NDArray[np.float64]
    mu: float
    generators: NDArray[np.float64]
    corners: NDArray[np.float64]
    length: float
    body: Body
    friction: FrictionTensor

    def margin(self, twist) -> float:
        """Where the contact wrench the twist needs lies relative to the contact's wrench cone:
        > 0 outside (the distance of the unit wrench −Ŵ(û) from the cone: the body would slide
        or turn on the face), ≤ 0 inside (minus the smallest generator's share of the
        non-negative weights; 0 on the boundary)."""
        u = _pair3("twist", twist)
        wr = _Wrench(self.body, self.friction)
        target = -wr(u)
        target /= np.linalg.norm(target)
        g = self.generators.copy()
        g[:, 2] /= self.length
        from scipy.optimize import nnls  # lazy: scipy.optimize is slow to import

        lam, dist = nnls(g.T, target)
        if dist > 1e-12:
            return float(dist)
        return -float(np.min(lam) / max(np.sum(lam), 1e-300)) if np.all(lam > 0) else 0.0

    def contains(self, twist) -> bool:
        """True if the pusher moving with the unit twist (vx, vy, ω ℓ) (at G, body frame)
        keeps the body stuck to its face (the exact Lynch–Mason condition)."""
        return self.margin(twist) <= 1e-12

    def compare_fits(self, surface=None, n: int = 400) -> FitComparison:
        """The corners the ellipsoid and quartic fits of :func:`slidespin.limit_surface`
        predict (as :meth:`MotionCone.compare_fits`), rows in the order of
        ``generators``, with their angles [rad] from the exact corners."""
        ell, quart = _fit_twists(self.generators, self.body, self.friction, surface, n, self.length)
        return FitComparison(ell, quart, _angle(ell, self.corners), _angle(quart, self.corners))


def _pair3(name: str, value: object) -> NDArray[np.float64]:
    if isinstance(value, (str, bytes)) or value is None:
        raise ValueError(f"{name} = {v._short(value)} is invalid; valid values: (vx, vy, omega*l)")
    arr = v.real_array(name, value)
    if arr.shape != (3,) or not np.any(arr != 0.0):
        raise ValueError(
            f"{name} = {v._short(value)} is invalid; valid values: a non-zero (vx, vy, omega*l)"
        )
    return arr / np.linalg.norm(arr)


def stable_pushing(body: Body, friction: FrictionTensor, face, mu: float = 0.0) -> StablePushing:
    """The exact stable-pushing set of a line pusher in face contact (Lynch & Mason 1996).

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        As in :func:`motion_cone`.
    face : ((float, float), (float, float))
        The two ends a ≠ b [m] (body frame C ξ η) of the segment the pusher's face shares
        with a flat edge of the body's outline. The inward normal is the unit normal of the
        segment on the side of G (G must not lie on the segment's line).
    mu : float, default 0
        μp, finite and ≥ 0.

    Returns
    -------
    StablePushing
        Its :meth:`~StablePushing.contains` tests a pusher twist; its ``corners`` are the four
        twists where the stable set's boundary turns.
    """
    check_body_friction(body, friction)
    if isinstance(face, (str, bytes)) or face is None:
        raise ValueError(f"face = {v._short(face)} is invalid; valid values: two points (a, b) [m]")
    try:
        ends = list(face)  # type: ignore[call-overload]
    except TypeError:
        raise ValueError(
            f"face = {v._short(face)} is invalid; valid values: two points (a, b) [m]"
        ) from None
    if len(ends) != 2:
        raise ValueError(f"face = {v._short(face)} is invalid; valid values: two points (a, b) [m]")
    a, b = _pair("face[0]", ends[0]), _pair("face[1]", ends[1])
    mu = pusher_mu(mu)
    d = b - a
    if not math.hypot(*d) > 0.0:
        raise ValueError(
            f"face = {v._short(face)} is invalid: its ends coincide; valid values: a != b"
        )
    g = np.array(body.mass_centre, dtype=float)
    n = np.array([-d[1], d[0]]) / math.hypot(*d)
    side = float(n @ (g - a))
    if side == 0.0:
        raise ValueError(
            f"face = {v._short(face)} is invalid: the mass centre G = {tuple(g.tolist())} lies on "
            "its line; valid values: a face of the outline, G to one side"
        )
    if side < 0.0:
        n = -n
    t = np.array([-n[1], n[0]])
    gens = []
    for p in (a, b):
        r = p - g
        for f in (n + mu * t, n - mu * t):
            gens.append((f[0], f[1], r[0] * f[1] - r[1] * f[0]))
    gen = np.array(gens)
    ell = body.length_unit
    wr = _Wrench(body, friction)
    corners = np.empty((4, 3))
    for k in range(4):
        nat = gen[k].copy()
        nat[2] /= ell
        corners[k], res = edge_twist(body, friction, nat, _w=wr)
        if res > RESIDUAL_TOL:
            raise RuntimeError(
                f"stable_pushing: no twist balances generator {k} to {RESIDUAL_TOL:g} "
                f"(residual {res:g}); please report this body and friction"
            )
    return StablePushing(np.array([a, b]), n, mu, gen, corners, ell, body, friction)
