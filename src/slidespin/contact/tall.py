"""Tall bodies (MODEL §14): the pressure moved by the friction force and by loads applied
above or below G, lift-off, and tipping.

A body whose mass centre G is at height h above the plane, decelerated by the friction force
F and pushed by loads Q at heights h_Q, presses on its footprint with a pressure whose
centroid is (the moment balance about G's horizontal axes, in the body's accelerating
frame; body-frame vectors, P the normal load)

    r_p = r_G − [h F + Σ (h − h_Q) Q] / P.                                       (MODEL §14)

Gravity's pull along a slope acts at G (h_Q = h) and shifts nothing; a load given without a
height acts at G's height. The pressure is the linear law of MODEL §10 with its centroid at
r_p; where it would turn negative that part of the footprint lifts off: p = max(0, p₀ + p₁ξ +
p₂η) with the three coefficients solved so that ∫p dS = P and ∫p r dS = P r_p (on a footprint
of polygons: the polygons are clipped by the line p = 0, and on the part left the linear law
is fitted again: Newton's method on the convex function ½ ∫max(0, p)² − c·(P, P r_p), whose
Hessian is the moment matrix of the part in contact, so that each step fits the linear law on
the part in contact of the last). The body **tips** when r_p reaches the
boundary of the footprint's convex hull: :meth:`TallContact.tip_gauge` is the gauge of the
hull about G at r_p (1 on the boundary).

In motion F depends on the pressure and the pressure on F: :meth:`TallContact.solve` finds
r_p and the wrench together (Broyden's method on the 2×2 equation above; for the linear law
without lift-off the wrench is affine in r_p and the iteration ends in a few steps). At rest,
static friction balances the applied force (F = −ΣQ, gravity's pull included), so r_p is
known directly: r_p = r_G + [Σ h_Q Q + h Q_gravity]/P.

Everything is in natural units, as :class:`slidespin.contact._engine.TwistWrench`: lengths in
ℓ = :attr:`slidespin.Body.length_unit`, unit normal load, body-frame vectors.

Where we depart from MODEL §14: once a disk or a ring lifts off, each circle is clipped as a
regular polygon of ``CIRCLE_SIDES`` sides and the same area (the wrench then to about
1e-7; the hull, hence the tipping, stays exact). On an :class:`~slidespin.Ellipse` patch (the
elliptic kernel) and under a speed law the pressure may shift up to where its linear law
reaches zero (a quarter of the semi-axes on an ellipse), and a shift beyond raises
:class:`LiftOffUnsupported`.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq
from scipy.spatial import ConvexHull

from slidespin.contact._engine import P_BN, P_LAW, P_XG, P_YG, TwistWrench
from slidespin.contact.footprint_arrays import FootprintArrays, _moments, linear_load
from slidespin.contact.pressure import LAW_LINEAR
from slidespin.contact.static_set import static_support

__all__ = ["LiftOffUnsupported", "TallContact", "TallTwist", "tall_factors"]

#: a pressure minimum above −LIFT_TOL × the mean pressure counts as ≥ 0 (no lift-off)
LIFT_TOL = 1e-12
#: a centroid closer to the hull than this gauge (or beyond it, where no pressure exists) is
#: taken at this gauge on its ray from G, so that the equations stay continuous through the
#: tipping event: the part in contact is then a sliver ~3e-6 of the footprint wide, which the
#: footprint kernel integrates to ~2e-11 of the load (measured on a box; at 1 − 1e-9 the
#: sliver's round-off reaches 4e-8 and worse near the ICR)
_GAUGE_CAP = 1.0 - 1e-6
_NEWTON_TOL = 1e-15
#: points of the scan for the first slide root in :func:`tall_factors`
_SCAN = 8
#: sides of the regular polygon of the same area that stands for a circle once a disk or a
#: ring lifts off: its area and second moments are the circle's to O((2π/n)⁴) (1e-15 here);
#: the wrench, whose integrand is not a polynomial, to O((2π/n)²) ≈ 1.5e-7 at most
CIRCLE_SIDES = 16384
_NO_CIRCLES = np.zeros((0, 4))


class LiftOffUnsupported(ValueError):
    """The pressure would lift off part of an Ellipse patch, or of a footprint under a speed
    law, which slidespin does not integrate yet (give a circle as a ``Disk``, which lifts
    off; MODEL §14)."""


class _Pressed:
    """The wrench about G of one pressure (centroid r_p), and its static-friction set."""

    __slots__ = ("d", "ellipse", "rp", "tw")

    def __init__(self, tw: TwistWrench, rp, d, ellipse: bool) -> None:
        self.tw, self.rp, self.d, self.ellipse = tw, rp, d, ellipse

    def __call__(self, phi, vx, vy, omega):
        if not self.ellipse:
            return self.tw(phi, vx, vy, omega)
        # the elliptic kernel's G is the law's centroid r_p: its velocity there, its moment
        # carried back to G
        c, s = math.cos(phi), math.sin(phi)
        dx = c * self.d[0] - s * self.d[1]
        dy = s * self.d[0] + c * self.d[1]
        fx, fy, m = self.tw(phi, vx - omega * dy, vy + omega * dx, omega)
        return fx, fy, m + dx * fy - dy * fx

    def support(self, friction, phi):
        """The support function of C about G for this pressure (natural units)."""
        sup = static_support(self.tw, friction, phi)
        if not self.ellipse:
            return sup
        c, s = math.cos(phi), math.sin(phi)
        dx = c * self.d[0] - s * self.d[1]
        dy = s * self.d[0] + c * self.d[1]
        return _Sheared(sup, dx, dy)


class _Sheared:
    """C about G from C about r_p: W_G = A W_p, M_G = M_p + d × F (d = r_p − r_G, world)."""

    __slots__ = ("dx", "dy", "sup")

    def __init__(self, sup, dx, dy) -> None:
        self.sup, self.dx, self.dy = sup, dx, dy

    def __call__(self, d):
        d = np.asarray(d, dtype=float)
        dp = np.array([d[0] - self.dy * d[2], d[1] + self.dx * d[2], d[2]])
        h, grad = self.sup(dp)
        g = np.array([grad[0], grad[1], grad[2] - self.dy * grad[0] + self.dx * grad[1]])
        return h, g


class TallContact:
    """The pressure of a tall body at any centroid r_p, its wrench about G, and the hull.

    Parameters
    ----------
    body : Body
        A body with ``height`` ≥ 0 under the uniform or linear law.
    friction : FrictionTensor
        Its (constant) friction tensor.
    tol : float
        The elliptic kernel's error target (the footprint kernel is exact).
    """

    def __init__(self, body, friction, tol: float = 1e-13) -> None:
        base = TwistWrench(body, friction, tol)
        self.base = base
        ell = body.length_unit
        self.ell = ell
        self.h = body.height / ell
        self.k = base.k
        self.ellipse = not base.footprint
        self._cache: dict = {}
        self._warm: tuple | None = None  # the last lift-off's coefficients (p₀, p₁, p₂)
        self._probes: tuple | None = None  # the centroids of :meth:`_affine`'s differences
        self._delta = 0.0
        self._probe_cache: dict = {}
        if self.ellipse:
            bn = float(base.par[P_BN])
            xg, yg = body.pressure.centroid
            self.rg = (xg / ell, yg / ell)
            self.area = math.pi * bn
            self.rc = (0.0, 0.0)
            self.jm = np.diag([self.area / 4.0, self.area * bn * bn / 4.0])
            self._ell: tuple | None = (1.0, bn, 0.0, 0.0)  # semi-axes, centre of the hull
            self._facets = None
            self._loops = None
            return
        gx, gy = body.mass_centre
        self.rg = (gx / ell, gy / ell)
        e, c = base.edges, base.circles
        ox, oy = float(base.geo[0]), float(base.geo[1])
        a, mx, my, sxx, sxy, syy = _moments(
            e - np.array([ox, oy, ox, oy]), c - np.array([ox, oy, 0.0, 0.0])
        )
        cx, cy = mx / a, my / a
        self.area = a
        self.rc = (ox + cx, oy + cy)
        self.jm = np.array(
            [[sxx - a * cx * cx, sxy - a * cx * cy], [sxy - a * cx * cy, syy - a * cy * cy]]
        )
        # the loops lift-off clips: the polygons, and each circle as a polygon of CIRCLE_SIDES
        # sides and the same area (MODEL §14: a lifted disk or ring, module notes)
        self._loops = _loops(e) + _circle_loops(c)
        self._ell = None
        self._facets = None
        if not len(c):
            pts = e[:, 0:2]
            hull = ConvexHull(pts)
            self._facets = hull.equations  # n·x + off ≤ 0 inside
        else:
            disks = [(float(x), float(y), float(r)) for x, y, r, sg in c if sg > 0.0]
            same = all(d[:2] == disks[0][:2] for d in disks)
            if not len(e) and same:
                r = max(d[2] for d in disks)
                self._ell = (r, r, disks[0][0], disks[0][1])
            else:
                self._mixed = (e[:, 0:2].copy(), np.array(disks))

    # ---- the hull ------------------------------------------------------------------------
    def tip_gauge(self, rp) -> float:
        """Gauge of the footprint's convex hull about G at ``rp``: < 1 inside, 1 on the
        boundary (the body tips), > 1 beyond."""
        dx, dy = rp[0] - self.rg[0], rp[1] - self.rg[1]
        if dx == 0.0 and dy == 0.0:
            return 0.0
        if self._facets is not None:
            n = self._facets
            gxr, gyr = self.rg
            den = -(n[:, 2] + n[:, 0] * gxr + n[:, 1] * gyr)
            return float(np.max((n[:, 0] * dx + n[:, 1] * dy) / den))
        if self._ell is not None:
            sa, sb, ex, ey = self._ell
            qx, qy = self.rg[0] - ex, self.rg[1] - ey
            aa = (dx / sa) ** 2 + (dy / sb) ** 2
            bb = qx * dx / sa**2 + qy * dy / sb**2
            cc = (qx / sa) ** 2 + (qy / sb) ** 2 - 1.0  # < 0: G inside
            s = (-bb + math.sqrt(bb * bb - aa * cc)) / aa  # the positive root of aa s² + 2bb s + cc
            return float(1.0 / s)
        return float(self._mixed_gauge(dx, dy))

    def _mixed_gauge(self, dx, dy):
        pts, disks = self._mixed
        gxr, gyr = self.rg

        def ratio(th):
            nx, ny = math.cos(th), math.sin(th)
            hk = -math.inf
            if len(pts):
                hk = float(np.max(pts[:, 0] * nx + pts[:, 1] * ny))
            hk = max(hk, float(np.max(disks[:, 0] * nx + disks[:, 1] * ny + disks[:, 2])))
            return (nx * dx + ny * dy) / (hk - nx * gxr - ny * gyr)

        th = np.linspace(-math.pi, math.pi, 2049)
        vals = [ratio(t) for t in th]
        i = int(np.argmax(vals))
        lo, hi = th[max(i - 1, 0)], th[min(i + 1, len(th) - 1)]
        # golden section on the bracket around the best sample
        gr = (math.sqrt(5.0) - 1.0) / 2.0
        a, b = lo, hi
        for _ in range(80):
            c1, c2 = b - gr * (b - a), a + gr * (b - a)
            if ratio(c1) > ratio(c2):
                b = c2
            else:
                a = c1
        return max(float(vals[i]), ratio(0.5 * (a + b)))

    # ---- the pressure at a centroid ------------------------------------------------------
    def at(self, rp) -> _Pressed:
        """The pressure with centroid ``rp`` (natural units, body frame), lifted off where
        the linear law turns negative; beyond the hull, the pressure at gauge 1 − 1e-9 on
        the ray from G (no pressure exists there: the body tips)."""
        key = (float(rp[0]), float(rp[1]))
        got = self._cache.get(key)
        if got is not None:
            return got
        gam = self.tip_gauge(key)
        r = key
        if gam > _GAUGE_CAP:
            f = _GAUGE_CAP / gam
            r = (self.rg[0] + f * (key[0] - self.rg[0]), self.rg[1] + f * (key[1] - self.rg[1]))
        got = self._make(r)
        if len(self._cache) > 64:
            self._cache.clear()
        self._cache[key] = got
        return got

    def _linear(self, r):
        """(p₀, p₁, p₂) of the linear law of MODEL §10 with centroid r, unit load."""
        a = self.area
        g = a * np.linalg.solve(self.jm, np.array([r[0] - self.rc[0], r[1] - self.rc[1]]))
        p1, p2 = g[0] / a, g[1] / a
        return (1.0 - p1 * self.rc[0] * a - p2 * self.rc[1] * a) / a, p1, p2

    def _make(self, r) -> _Pressed:
        d = (r[0] - self.rg[0], r[1] - self.rg[1])
        p0, p1, p2 = self._linear(r)
        mean = 1.0 / self.area
        if self.ellipse:
            assert self._ell is not None
            sa, sb = self._ell[0], self._ell[1]
            low = p0 - math.hypot(p1 * sa, p2 * sb)
            if low < -LIFT_TOL * mean:
                raise LiftOffUnsupported(
                    _lift_message((r[0] * self.ell, r[1] * self.ell), "this ellipse")
                )
            return _Pressed(_with_pressure(self.base, centroid=r), r, d, True)
        base = self.base
        e, c = base.edges, base.circles
        low = math.inf
        if len(e):
            low = float(np.min(p0 + p1 * e[:, 0] + p2 * e[:, 1]))
        for ox, oy, rad, sg in c:
            if sg > 0.0:
                low = min(low, p0 + p1 * ox + p2 * oy - math.hypot(p1, p2) * rad)
        edges = e
        if low < -LIFT_TOL * mean:
            c = _NO_CIRCLES  # (the circles are among the loops, as polygons)
            # warm start: the last lift-off's law (the integrator asks for nearby centroids)
            start = self._warm if self._warm is not None else (p0, p1, p2)
            edges, (p0, p1, p2) = _lift_off(self._loops, r, start)
            self._warm = (p0, p1, p2)
        geo = base.geo.copy()
        arrays = FootprintArrays(edges, c, geo[0:3])
        if edges is not e:
            geo[0:3] = _frame(edges)
            arrays = FootprintArrays(edges, c, geo[0:3])
        geo[3:6] = (p0, p1, p2)
        geo[3:6] /= linear_load(arrays, *geo[3:6])
        geo[8], geo[9] = r
        geo[10] = 1.0
        return _Pressed(_with_pressure(base, edges, geo, circles=c), r, d, False)

    # ---- the pressure in motion ----------------------------------------------------------
    def solve(self, phi, vx, vy, omega, sigma):
        """(Fx, Fy, M about G, r_p) with r_p = r_G − σ − h F_body(r_p) (MODEL §14).

        ``sigma`` = Σ (h − h_Q) Q / P in the body frame (natural units); (vx, vy, ω) the
        twist of G at angle φ (world frame), as :class:`~slidespin.contact._engine.TwistWrench`.
        """
        c, s = math.cos(phi), math.sin(phi)
        h = self.h
        x = np.array([self.rg[0] - sigma[0], self.rg[1] - sigma[1]])
        jinv = np.eye(2)  # Broyden's method from the fixed-point iteration (J ≈ 1) ...
        if h > 0.0:
            got, jac = self._affine(phi, vx, vy, omega, sigma, c, s)
            if got is not None:
                return got
            if jac is not None:  # ... or from the Jacobian without lift-off
                jinv = np.linalg.inv(jac)

        def resid(r):
            fx, fy, m = self.at(r)(phi, vx, vy, omega)
            fb = (c * fx + s * fy, -s * fx + c * fy)
            res = np.array(
                [r[0] - self.rg[0] + sigma[0] + h * fb[0], r[1] - self.rg[1] + sigma[1] + h * fb[1]]
            )
            return res, (fx, fy, m)

        if h == 0.0:
            w = resid(x)[1]
            return (*w, (float(x[0]), float(x[1])))
        return _broyden(
            resid, x, jinv, lambda xv: _NEWTON_TOL * max(1.0, float(np.max(np.abs(xv))))
        )

    def _lifts(self, r) -> bool:
        """True if the linear law with centroid r turns negative on the patch."""
        p0, p1, p2 = self._linear(r)
        tol = -LIFT_TOL / self.area
        if self.ellipse:
            assert self._ell is not None
            return p0 - math.hypot(p1 * self._ell[0], p2 * self._ell[1]) < tol
        e, c = self.base.edges, self.base.circles
        if len(e) and float(np.min(p0 + p1 * e[:, 0] + p2 * e[:, 1])) < tol:
            return True
        return any(
            sg > 0.0 and p0 + p1 * ox + p2 * oy - math.hypot(p1, p2) * rad < tol
            for ox, oy, rad, sg in c
        )

    def _affine(self, phi, vx, vy, omega, sigma, c, s):
        """:meth:`solve` without lift-off, in one step: the wrench is affine in r_p (the
        linear law's coefficients are), W(r) = W(r_G) + D (r − r_G) with D from the pressures
        centred at r_G + δ e_x, r_G + δ e_y (kept: their kernels are built once), so
        (1 + h D_F) (r − r_G) = −σ − h F(r_G) is solved exactly. Returns (the wrench and r_p,
        the Jacobian 1 + h D_F); the wrench is None where the solution would lift off (then
        :meth:`solve` iterates, from that Jacobian), and both where a probe would."""
        probes = self._probes
        if probes is None:
            gx, gy = self.rg
            delta = 0.01
            while delta > 1e-6 and (self._lifts((gx + delta, gy)) or self._lifts((gx, gy + delta))):
                delta *= 0.1
            probes = () if delta <= 1e-6 else ((gx, gy), (gx + delta, gy), (gx, gy + delta))
            self._probes = probes
            self._delta = delta
        if not probes:
            return None, None
        w0, wx, wy = (np.array(self._at_probe(k)(phi, vx, vy, omega)) for k in range(3))
        dx, dy = (wx - w0) / self._delta, (wy - w0) / self._delta

        def body(f):
            return np.array([c * f[0] + s * f[1], -s * f[0] + c * f[1]])

        fb0, dbx, dby = body(w0), body(dx), body(dy)
        h = self.h
        mat = np.array([[1.0 + h * dbx[0], h * dby[0]], [h * dbx[1], 1.0 + h * dby[1]]])
        rhs = np.array([-sigma[0] - h * fb0[0], -sigma[1] - h * fb0[1]])
        d = np.linalg.solve(mat, rhs)
        r = (self.rg[0] + float(d[0]), self.rg[1] + float(d[1]))
        if self._lifts(r):
            return None, mat
        w = w0 + dx * d[0] + dy * d[1]
        return (float(w[0]), float(w[1]), float(w[2]), r), mat

    def _at_probe(self, k) -> _Pressed:
        """The pressure at the k-th probe of :meth:`_affine`, built once."""
        got = self._probe_cache.get(k)
        if got is None:
            assert self._probes is not None
            got = self._make(self._probes[k])
            self._probe_cache[k] = got
        return got


def tall_factors(body, friction, b, phi, raised, normal_load, load_factor_nat):
    """(λ*, mode, λ_slide, λ_tip, tall, s, σ) of a tall body at rest (MODEL §14).

    Static friction balances the applied force, so under λ W_a the pressure centroid is
    r_p(λ) = r_G + λ s, s = [h F_a − Σ (h − h_Q) Q]/P (body frame, natural units): the body
    tips at λ_tip = 1/γ(r_G + s), γ the gauge of the footprint's hull about G, and slides at
    the λ where λ W_a leaves C of the pressure at r_p(λ) (Brent's method on λ*(λ) − λ; beyond
    λ_tip with the pressure held at the hull's edge). σ = the raised forces' part of s.

    ``b``: the applied wrench per unit normal load (natural units, fixed frame, gravity's
    pull included); ``raised`` = Σ (h − h_Q) Q [N m] (fixed frame); ``normal_load`` = P
    [N]; ``load_factor_nat(sup, b)`` the load factor of :mod:`slidespin.contact.statics`.
    """
    tall = TallContact(body, friction.kinetic)
    c, sn = math.cos(phi), math.sin(phi)
    rx, ry = raised
    scale = body.length_unit * normal_load
    sig = ((c * rx + sn * ry) / scale, (-sn * rx + c * ry) / scale)
    fxb, fyb = c * b[0] + sn * b[1], -sn * b[0] + c * b[1]
    s_vec = (tall.h * fxb - sig[0], tall.h * fyb - sig[1])
    rg = tall.rg
    gam = tall.tip_gauge((rg[0] + s_vec[0], rg[1] + s_vec[1]))
    lam_tip = math.inf if gam == 0.0 else 1.0 / gam

    def lam_star(lam):
        sup = tall.at((rg[0] + lam * s_vec[0], rg[1] + lam * s_vec[1])).support(friction, phi)
        return load_factor_nat(sup, b)[0]

    def f(lam):
        return lam_star(lam) - lam

    if math.isinf(lam_tip):
        lam_slide = lam_star(0.0)
    else:
        # f need not be monotone (C moves with the pressure): the first sign change on a
        # scan of [0, hi], then Brent's method in it; beyond the hull (the pressure held at
        # its edge) by doubling
        f_lo = lam_star(0.0)
        hi = min(lam_tip * _GAUGE_CAP, f_lo)
        grid = np.linspace(0.0, hi, _SCAN + 1)[1:]
        lo, f_hi = 0.0, f_lo
        for lam in grid:
            f_hi = f(lam)
            if f_hi <= 0.0:
                hi = lam
                break
            lo = lam
        while f_hi > 0.0 and hi < 1e12 * max(lam_tip, f_lo):
            lo, hi = hi, 2.0 * hi
            f_hi = f(hi)
        lam_slide = brentq(f, lo, hi, xtol=1e-15 * hi, rtol=1e-15) if f_hi <= 0.0 else math.inf
    mode = "tip" if lam_tip <= lam_slide else "slide"
    return min(lam_slide, lam_tip), mode, lam_slide, lam_tip, tall, s_vec, sig


class TallTwist:
    """A tall body's wrench under a fixed load tilt σ, called as a ``TwistWrench``
    (``k``; ``(phi, vx, vy, omega) -> (Fx, Fy, M about G)``)."""

    __slots__ = ("k", "sigma", "tall")

    def __init__(self, tall: TallContact, sigma) -> None:
        self.tall, self.sigma, self.k = tall, sigma, tall.k

    def __call__(self, phi, vx, vy, omega):
        fx, fy, m, _ = self.tall.solve(phi, vx, vy, omega, self.sigma)
        return fx, fy, m


def _with_pressure(
    tw: TwistWrench, edges=None, geo=None, centroid=None, circles=None
) -> TwistWrench:
    """A copy of ``tw`` with another pressure on the same body.

    For a footprint: the arrays ``edges`` (the part in contact) and ``geo`` (pressure
    coefficients, centroid, load), G kept where ``geo`` puts it: the copy's wrench is about
    G, for G's velocity. For an ellipse: the linear law with its centroid at ``centroid``
    (units of a); the elliptic kernel takes that centroid as its G, so the copy's wrench is
    about the pressure centroid, for its velocity (:class:`_Pressed` carries it to G).
    """
    new = object.__new__(TwistWrench)
    for name in TwistWrench.__slots__:
        if hasattr(tw, name):
            object.__setattr__(new, name, getattr(tw, name))
    if tw.footprint:
        new.edges = np.ascontiguousarray(edges, dtype=np.float64)
        new.geo = np.ascontiguousarray(geo, dtype=np.float64)
        if circles is not None:
            new.circles = np.ascontiguousarray(circles, dtype=np.float64)
        new._args = (new.edges, new.circles, new.geo, *tw._args[3:])
    else:
        par = tw.par.copy()
        par[P_LAW] = LAW_LINEAR
        par[P_XG], par[P_YG] = float(centroid[0]), float(centroid[1])
        new.par = par
        bn, _law, _xg, _yg, *rest = tw._args
        new._args = (bn, LAW_LINEAR, float(par[P_XG]), float(par[P_YG]), *rest)
    return new


def _broyden(resid, x, jinv, step_tol):
    """Broyden's ("good") method on the 2×2 equation ``resid(x)[0] = 0`` from x with the
    inverse Jacobian ``jinv``, until a step is below ``step_tol(x)``; returns (*w, x) with
    w = ``resid(x)[1]`` (the wrench) at the last x."""
    fr, w = resid(x)
    for _ in range(60):
        step = -jinv @ fr
        x = x + step
        f_new, w = resid(x)
        if float(np.max(np.abs(step))) <= step_tol(x):
            break
        df = f_new - fr
        jdf = jinv @ df
        den = float(step @ jdf)
        if den != 0.0:
            jinv = jinv + np.outer(step - jdf, step @ jinv) / den
        fr = f_new
    return (*w, (float(x[0]), float(x[1])))


def _lift_message(r, what):
    """The message of :class:`LiftOffUnsupported` for a centroid ``r`` [m, body frame]."""
    return (
        f"the pressure centroid of the tall body would move to (ξ, η) = ({r[0]:.6g}, "
        f"{r[1]:.6g}) m, beyond where the linear pressure stays >= 0 on {what}: the patch "
        "would lift off there, which slidespin does not integrate on an Ellipse patch or "
        "under a speed law yet (MODEL §14); valid here: a smaller height or load height, "
        "or the patch as a Disk or a Polygon footprint with a constant law"
    )


def _loops(edges: np.ndarray) -> list[np.ndarray]:
    """The closed loops (vertex arrays) of a list of chained counter-clockwise edges."""
    loops, cur = [], []
    start = None
    for x0, y0, x1, y1 in edges:
        if start is None:
            start = (x0, y0)
            cur = [(x0, y0)]
        cur.append((x1, y1))
        if (x1, y1) == start:
            loops.append(np.array(cur[:-1]))
            start = None
    if start is not None:  # pragma: no cover - the shapes' edges always close
        loops.append(np.array(cur))
    return loops


def _clip(loops, c0, c1, c2) -> np.ndarray:
    """Edges of the loops clipped to c₀ + c₁ξ + c₂η ≥ 0 (Sutherland–Hodgman per loop, on
    arrays: each vertex inside is kept, and each edge that crosses the line adds its
    crossing point after it)."""
    out = []
    for pts in loops:
        if len(pts) <= 32:  # a few vertices: the plain loop is faster than the arrays
            e = _clip_small(pts, c0, c1, c2)
            if e is not None:
                out.append(e)
            continue
        vals = c0 + c1 * pts[:, 0] + c2 * pts[:, 1]
        nxt = np.roll(pts, -1, axis=0)
        vn = np.roll(vals, -1)
        inside = vals >= 0.0
        cross = inside != (vn >= 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            frac = np.where(cross, vals / (vals - vn), 0.0)
        xpt = pts + frac[:, None] * (nxt - pts)
        both = np.stack((pts, xpt), axis=1).reshape(-1, 2)
        keep = np.stack((inside, cross), axis=1).reshape(-1)
        k = both[keep]
        if len(k) >= 3:
            e = np.hstack((k, np.roll(k, -1, axis=0)))
            e = e[(e[:, 0] != e[:, 2]) | (e[:, 1] != e[:, 3])]
            out.append(e)
    return np.ascontiguousarray(np.vstack(out)) if out else np.zeros((0, 4))


def _clip_small(pts, c0, c1, c2):
    """:func:`_clip` of one loop of a few vertices, vertex by vertex (None if nothing is
    left)."""
    kept = []
    n = len(pts)
    vals = [c0 + c1 * x + c2 * y for x, y in pts.tolist()]
    pl = pts.tolist()
    for i in range(n):
        j = (i + 1) % n
        (px, py), (qx, qy) = pl[i], pl[j]
        vp, vq = vals[i], vals[j]
        if vp >= 0.0:
            kept.append((px, py))
        if (vp >= 0.0) != (vq >= 0.0):
            f = vp / (vp - vq)
            kept.append((px + f * (qx - px), py + f * (qy - py)))
    if len(kept) < 3:
        return None
    e = [(*kept[i], *kept[(i + 1) % len(kept)]) for i in range(len(kept))]
    e = [row for row in e if row[0] != row[2] or row[1] != row[3]]
    return np.array(e)


def _moment_matrix(edges, o):
    """∫ (1, ξ', η')ᵀ (1, ξ', η') dS over the polygons of ``edges``, ξ' = ξ − o."""
    a, sx, sy, sxx, sxy, syy = _moments(
        edges - np.array([o[0], o[1], o[0], o[1]]), np.zeros((0, 4))
    )
    return np.array([[a, sx, sy], [sx, sxx, sxy], [sy, sxy, syy]])


def _lift_off(loops, r, coef):
    """(edges, (p₀, p₁, p₂)): the part of the footprint in contact and the linear law on it,
    p = max(0, p₀ + p₁ξ + p₂η), with unit load and centroid ``r`` (module notes)."""
    o = r  # the moments about the centroid: well conditioned
    p0, p1, p2 = coef
    c = np.array([p0 + p1 * o[0] + p2 * o[1], p1, p2])  # coefficients in ξ' = ξ − o
    b = np.array([1.0, 0.0, 0.0])

    def state(cv):
        e = _clip_shifted(loops, cv, o)
        mm = _moment_matrix(e, (0.0, 0.0)) if len(e) else np.zeros((3, 3))
        return e, mm

    e, mm = state(c)
    for _ in range(60):
        if float(np.max(np.abs(mm @ c - b))) <= 4e-15:
            break
        # Newton's step c − M⁻¹(M c − b) = M⁻¹ b: the linear law fitted on the part in
        # contact; halved towards c while the new part is empty or degenerate
        c_new = np.linalg.solve(mm, b)
        for _k in range(60):
            e_new, mm_new = state(c_new)
            if len(e_new) and mm_new[0, 0] > 0.0 and np.linalg.det(mm_new) > 0.0:
                break
            c_new = 0.5 * (c + c_new)
        c, e, mm = c_new, e_new, mm_new
    edges = e + np.array([o[0], o[1], o[0], o[1]])
    q0 = c[0] - c[1] * o[0] - c[2] * o[1]
    return np.ascontiguousarray(edges), (q0, c[1], c[2])


def _circle_loops(circles) -> list[np.ndarray]:
    """Each circle row (ξ_o, η_o, R, sign) as a regular polygon of :data:`CIRCLE_SIDES`
    sides with the circle's area, counter-clockwise for a disk, clockwise for a hole."""
    n = CIRCLE_SIDES
    th = 2.0 * np.pi * np.arange(n) / n
    grow = math.sqrt(2.0 * math.pi / (n * math.sin(2.0 * math.pi / n)))  # same area
    loops = []
    for ox, oy, rad, sg in circles:
        t = th if sg > 0.0 else th[::-1]
        loops.append(np.column_stack((ox + rad * grow * np.cos(t), oy + rad * grow * np.sin(t))))
    return loops


def _clip_shifted(loops, cv, o):
    """:func:`_clip` of the loops shifted by −o (coefficients in the shifted coordinates)."""
    shifted = [pts - np.asarray(o) for pts in loops]
    return _clip(shifted, cv[0], cv[1], cv[2])


def _frame(edges):
    """(ξ_o, η_o, extent) of a footprint of polygons: its area centroid and the largest
    distance from it to a vertex."""
    o = edges[:, 0:2].mean(axis=0)
    a, sx, sy, *_ = _moments(edges - np.array([o[0], o[1], o[0], o[1]]), np.zeros((0, 4)))
    cx, cy = o[0] + sx / a, o[1] + sy / a
    ext = float(np.max(np.hypot(edges[:, 0] - cx, edges[:, 1] - cy)))
    return np.array([cx, cy, ext])
