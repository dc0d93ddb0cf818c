"""Static friction: when a loaded body at rest stays at rest, and how it starts (MODEL §11).

At rest, a contact point with pressure p can supply any traction in p·E, E = {𝔽 s : |s| ≤ 1}
(the image of the unit disk under the friction tensor), so static friction can supply exactly
the convex set of wrenches (Fx, Fy, M about G)

    C = ∫ p E dS,       support function  h(d) = max_{W ∈ C} d·W = ∫ p |𝔽ᵀ (d_F + d_M r′⊥)| dS,

for a wrench direction d = (d_F, d_M), with r′ = R(φ)(r − r_G) and r′⊥ = (−y′, x′). (The
maximising traction at each point is p 𝔽 ẑ, ẑ = 𝔽ᵀc/|𝔽ᵀc|, c = d_F + d_M r′⊥.) C is symmetric,
C = −C. A body at rest under an applied wrench W_a stays at rest iff −W_a ∈ C, that is iff the
**load factor**

    λ*(W_a) = min_{d·W_a > 0} h(d)/(d·W_a)            (the gauge of C at W_a, inverted)

is at least 1: λ* is the factor by which the load can be scaled before the body slips. The
minimising d is the outward normal of C where the ray through W_a leaves it.

How h is computed (exactly, with the compiled kernel). With S = 𝔽ᵀ and L = J⁻¹ S J
(J the quarter turn), S J r′ = J L r′, so 𝔽ᵀc = S d_F + d_M J (L r′): the field 𝔽ᵀc is the
velocity field of the rigid twist (S d_F, d_M) of the *image* patch L·Ω, which is again an
ellipse carrying the same pressure law (uniform, Boussinesq and Hertz depend on the patch's
own quadratic form; the linear law stays linear with its centroid at the image of G). Hence
h(d) = −W_iso·(S d_F, d_M), the dissipation of that twist under *isotropic unit* friction on
the image patch, and the support point is ∇h(d) = (−𝔽 F_iso, −M_iso). One kernel call, 1e-12.

On a footprint (MODEL §10; ``FootprintSupport``) the same change of variables holds,
y = L r′ with the pressure p/det L: a polygon's image is a polygon (the exact footprint
kernel), a disk's or a ring hole's is an ellipse (the elliptic kernel, one call per disk,
with its own load and pressure centroid), and a linear pressure stays linear. For isotropic
friction no map is needed: h(d) = −W(d)·d and ∇h(d) = −W(d), one call of the footprint
kernel. The sliding wrench W(u) of every feature below comes from one dispatch on the shape,
:class:`slidespin.contact._engine.TwistWrench` (elliptic or footprint kernel).

For isotropic friction (𝔽 = μ 1) the support point in direction d is −W(d), minus the friction
wrench of the twist d: C is bounded by the limit surface, and the twist is normal to it
(maximum dissipation; Goyal, Ruina & Papadopoulos 1991). For an anisotropic tensor the law
τ = −p 𝔽 ŵ is not of maximum dissipation and the limit surface may lie inside C.

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

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize, root

from slidespin import _validate as v
from slidespin.contact import _engine
from slidespin.contact._engine import TwistWrench
from slidespin.contact._kernel_ellipse import STATUS_OK, wrench_world
from slidespin.contact._kernel_footprint import NGEO
from slidespin.contact._kernel_footprint import wrench_world as fp_wrench_world
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.pressure import LAW_LINEAR, LAW_UNIFORM

__all__ = [
    "Onset",
    "OnsetNotFound",
    "StaticSupport",
    "can_stick",
    "critical_tilt",
    "load_factor",
    "onset",
    "support_function",
]

_TOL = 1e-13  # kernel error target (units of the load and load × a)
_J = np.array([[0.0, -1.0], [1.0, 0.0]])


# ------------------------------------------------------------------------------------------
# the support function through the image patch (natural units: a = 1, P = 1)
# ------------------------------------------------------------------------------------------
class StaticSupport:
    """Support function h and support point ∇h of C at one body angle (natural units).

    Built once per (body, friction, φ); evaluations cost one kernel call each. Wrench
    directions d = (d_Fx, d_Fy, d_M) with d_M per unit a; h per unit normal load.
    """

    __slots__ = ("S", "bn", "fw", "law", "psi", "s1", "xg", "yg")

    def __init__(self, par: np.ndarray, friction: FrictionTensor, phi: float) -> None:
        fw = friction.world_matrix(phi)
        self.fw = fw
        self.S = fw.T.copy()
        lmap = np.linalg.solve(_J, self.S @ _J)  # L = J⁻¹ S J
        c, s = math.cos(phi), math.sin(phi)
        rot = np.array([[c, -s], [s, c]])
        bn = par[_engine.P_BN]
        rg = np.array([par[_engine.P_XG], par[_engine.P_YG]])
        centre = lmap @ (rot @ (-rg))  # image of the patch centre (G is at the origin)
        u_, sig, _ = np.linalg.svd(lmap @ rot @ np.diag([1.0, bn]))
        if np.linalg.det(u_) < 0.0:
            u_[:, 1] *= -1.0
        self.s1 = float(sig[0])
        self.bn = float(sig[1] / sig[0])
        self.psi = math.atan2(u_[1, 0], u_[0, 0])
        g_img = -(u_.T @ centre) / sig[0]  # G in the image patch's own frame, units of s1
        self.xg, self.yg = float(g_img[0]), float(g_img[1])
        self.law = int(par[_engine.P_LAW])

    def __call__(self, d):
        """(h(d), ∇h(d)) for a direction d = (d_Fx, d_Fy, d_M) (natural units)."""
        vx, vy = self.S @ np.asarray(d[:2], dtype=float)
        om = float(d[2])
        f1, f2, m, st = wrench_world(
            self.bn,
            self.law,
            self.xg,
            self.yg,
            1.0,
            0.0,
            0.0,
            1.0,
            False,
            self.psi,
            vx / self.s1,
            vy / self.s1,
            om,
            _TOL,
        )
        if st != STATUS_OK:  # pragma: no cover - guard
            raise RuntimeError("statics: the wrench quadrature missed its error target")
        mom = m * self.s1
        h = -(f1 * vx + f2 * vy + mom * om)
        grad = np.array(
            [
                -(self.fw[0, 0] * f1 + self.fw[0, 1] * f2),
                -(self.fw[1, 0] * f1 + self.fw[1, 1] * f2),
                -mom,
            ]
        )
        return h, grad


class FootprintSupport:
    """Support function h and support point ∇h of C for a footprint at one body angle.

    Natural units as :class:`StaticSupport` (lengths in ℓ = the footprint's extent, unit
    load). From the definition (MODEL §11), with r′ = R(φ)(r − r_G), S = 𝔽ᵀ (world frame)
    and c(r) = d_F + d_M J r′ the velocity field of the rigid twist d:

        h(d) = ∫ p |S c| dS,      ∇h(d) = (𝔽 ∫ p ẑ dS,  ∫ p (J r′)·𝔽ẑ dS),  ẑ = Sc/|Sc|.

    *Isotropic* 𝔽 = μ·1: ẑ = ĉ, so h(d) = −W(d)·d and ∇h(d) = −W(d) with W the sliding
    wrench of the twist d (one call of the exact footprint kernel).

    *Any tensor*: S J = J L with L = J⁻¹ S J, so S c = S d_F + d_M J (L r′) is the rigid
    velocity field of the twist (S d_F, d_M) on the image y = L r′ of the footprint, and
    h(d) = ∫_{LΩ} p̂ |S d_F + d_M J y| dy with p̂(y) = p(r)/det L (det L = det 𝔽 > 0): the
    dissipation of that twist under *isotropic unit* friction on the image footprint, which
    is again a footprint the exact kernels take: a linear map sends each polygon to a
    polygon (its edges mapped, orientation kept since det L > 0), each disk or hole of
    radius R to an ellipse with semi-axes R σ₁, R σ₂ (σ the singular values of L), and a
    linear pressure to a linear pressure. The polygons are integrated by the footprint
    kernel (exact), each disk (σ = ±1) by the elliptic kernel with its own load
    ∫_disk p = π R² p(o) and pressure centroid o + (R²/4) ∇p/p(o) (uniform or linear law,
    1e-13), moments carried to G. The support point is (−𝔽 F_iso, −M_iso), F_iso and M_iso
    the image twist's isotropic wrench.
    """

    __slots__ = ("S", "circ", "edge_geo", "edges", "fw", "iso", "phi", "tw")

    def __init__(self, tw: TwistWrench, friction: FrictionTensor, phi: float) -> None:
        self.tw = tw
        self.phi = phi
        fw = friction.world_matrix(phi)
        self.fw = fw
        self.S = fw.T.copy()
        self.iso = friction.fx == friction.fy and friction.f == 0.0
        self.edges = np.empty((0, 4))
        self.edge_geo = np.zeros(NGEO)
        self.circ: list[tuple] = []
        if self.iso:
            return
        geo = tw.geo
        p0, p1, p2 = geo[3], geo[4], geo[5]
        gx, gy = geo[6], geo[7]
        lmap = np.linalg.solve(_J, self.S @ _J)  # L = J⁻¹ S J
        c, s = math.cos(phi), math.sin(phi)
        mmap = lmap @ np.array([[c, -s], [s, c]])  # body offsets from G → image
        det = float(np.linalg.det(lmap))
        pg = p0 + p1 * gx + p2 * gy  # p at G
        grad = np.linalg.solve(mmap.T, np.array([p1, p2]))  # ∇ of p(y) in the image
        q0, q1, q2 = pg / det, grad[0] / det, grad[1] / det  # p̂ = p/det L
        e = tw.edges
        if e.shape[0]:
            a0 = (e[:, 0:2] - (gx, gy)) @ mmap.T
            a1 = (e[:, 2:4] - (gx, gy)) @ mmap.T
            self.edges = np.ascontiguousarray(np.hstack((a0, a1)))
            o = mmap @ (geo[0:2] - (gx, gy))
            ext = float(np.max(np.hypot(a0[:, 0] - o[0], a0[:, 1] - o[1])))
            # load and first moments of the polygons' part (the kernel's pure-translation
            # branch needs them): signed fan from o, exact rules for linear and quadratic
            ar = 0.5 * (
                (a0[:, 0] - o[0]) * (a1[:, 1] - o[1]) - (a0[:, 1] - o[1]) * (a1[:, 0] - o[0])
            )
            mids = (0.5 * (a0 + a1), 0.5 * (a0 + o), 0.5 * (a1 + o))
            load = 0.0
            mx = my = 0.0
            for mid in mids:
                pv = q0 + q1 * mid[:, 0] + q2 * mid[:, 1]
                load += float(np.sum(ar * pv)) / 3.0
                mx += float(np.sum(ar * pv * mid[:, 0])) / 3.0
                my += float(np.sum(ar * pv * mid[:, 1])) / 3.0
            self.edge_geo = np.array(
                [o[0], o[1], ext, q0, q1, q2, 0.0, 0.0, mx / load, my / load, load]
            )
        if tw.circles.shape[0]:
            u_, sig, _ = np.linalg.svd(lmap)
            if np.linalg.det(u_) < 0.0:
                u_[:, 1] *= -1.0
            psi = math.atan2(u_[1, 0], u_[0, 0])
            bn = float(sig[1] / sig[0])
            for ox, oy, rad, sgn in tw.circles:
                po = p0 + p1 * ox + p2 * oy  # p at the disk's centre (its mean)
                cen = np.array([ox, oy]) + (0.25 * rad * rad / po) * np.array([p1, p2])
                gimg = mmap @ (cen - (gx, gy))  # the disk's pressure centroid, image
                eimg = mmap @ (np.array([ox, oy]) - (gx, gy))  # its centre, image
                semi = float(rad * sig[0])
                gl = u_.T @ (gimg - eimg) / semi  # centroid in the ellipse's frame, per a
                law = LAW_UNIFORM if p1 == 0.0 and p2 == 0.0 else LAW_LINEAR
                self.circ.append(
                    (
                        bn,
                        law,
                        float(gl[0]),
                        float(gl[1]),
                        psi,
                        semi,
                        float(gimg[0]),
                        float(gimg[1]),
                        float(sgn * math.pi * rad * rad * po),
                    )
                )

    def _image_wrench(self, vx, vy, om):
        """Isotropic unit-friction wrench (F, M about G) of the image twist (vx, vy, ω)."""
        fx = fy = mm = 0.0
        if self.edges.shape[0]:
            fx, fy, mm = fp_wrench_world(
                self.edges, _NO_CIRCLES, self.edge_geo, 1.0, 0.0, 0.0, 1.0, False, 0.0, vx, vy, om
            )
        for bn, law, xg, yg, psi, semi, gx, gy, load in self.circ:
            # velocity of the twist at the disk's pressure centroid, lengths per semi-axis
            wx, wy = vx - om * gy, vy + om * gx
            f1, f2, m, st = wrench_world(
                bn, law, xg, yg, 1.0, 0.0, 0.0, 1.0, False, psi, wx / semi, wy / semi, om, _TOL
            )
            if st != STATUS_OK:  # pragma: no cover - guard
                raise RuntimeError("statics: the wrench quadrature missed its error target")
            f1 *= load
            f2 *= load
            fx += f1
            fy += f2
            mm += m * load * semi + gx * f2 - gy * f1
        return fx, fy, mm

    def __call__(self, d):
        """(h(d), ∇h(d)) for a direction d = (d_Fx, d_Fy, d_M) (natural units)."""
        if self.iso:
            fx, fy, m = self.tw(self.phi, float(d[0]), float(d[1]), float(d[2]))
            return -(fx * d[0] + fy * d[1] + m * d[2]), np.array([-fx, -fy, -m])
        vx, vy = self.S @ np.asarray(d[:2], dtype=float)
        om = float(d[2])
        f1, f2, mom = self._image_wrench(float(vx), float(vy), om)
        h = -(f1 * vx + f2 * vy + mom * om)
        grad = np.array(
            [
                -(self.fw[0, 0] * f1 + self.fw[0, 1] * f2),
                -(self.fw[1, 0] * f1 + self.fw[1, 1] * f2),
                -mom,
            ]
        )
        return h, grad


_NO_CIRCLES = np.empty((0, 4))


def static_support(tw: TwistWrench, friction: FrictionTensor, phi: float):
    """The support function of C at angle ``phi``: :class:`StaticSupport` for an ellipse,
    :class:`FootprintSupport` for a footprint (natural units of ``tw``)."""
    if tw.footprint:
        return FootprintSupport(tw, friction, phi)
    return StaticSupport(tw.par, friction, phi)


#: bound on (friction anisotropy) × (patch elongation): the static features map the patch to
#: its image under the tensor, an ellipse elongated by at most their product; the wrench
#: quadrature meets its target for every product ≤ 1e4 measured (aspects 1e-3..30, both
#: frames, skewed tensors) and misses it from ~1e5 on
ANISOTROPY_ELONGATION = 1e4
#: bound on |W_a| in units of (m g, m g, m g a): beyond it the optimiser's numbers overflow
WRENCH_MAX = 1e6
#: a load below this (same units) is negligible: held, load factor inf, no onset (its load
#: factor would exceed 1e300 × the smallest coefficient, far beyond any meaning)
WRENCH_NEGLIGIBLE = 1e-300


def anisotropy_elongation(body, friction) -> float:
    """cond(𝔽) × max(b/a, a/b): the worst elongation of the image patch the statics see
    (cond(𝔽) for a footprint: the image of a disk)."""
    sv = np.linalg.svd(friction.matrix, compute_uv=False)
    ratio = math.inf if sv[1] <= 0.0 else float(sv[0] / sv[1])
    if body.is_footprint:
        # a footprint's polygons map to polygons (the exact kernel); its disks to ellipses
        # of elongation cond(𝔽) (elongation 1 here)
        return ratio
    bn = body.patch.b / body.patch.a
    return ratio * max(bn, 1.0 / bn)


def check_anisotropy(body, friction, feature="static friction") -> None:
    """Raise ValueError naming ``friction`` unless cond(𝔽) × elongation ≤ 1e4."""
    prod = anisotropy_elongation(body, friction)
    if not prod <= ANISOTROPY_ELONGATION:
        raise ValueError(
            f"friction = {friction!r} is invalid for {feature} on this patch: anisotropy "
            f"(ratio of the tensor's singular values) x patch elongation max(b/a, a/b) = "
            f"{prod:.3g}; valid range: [1, {ANISOTROPY_ELONGATION:g}]"
        )


def _check(body, friction):
    check_body_friction(body, friction)
    check_anisotropy(body, friction)


def _norm(b):
    """|b| without overflow or underflow of the squares."""
    big = float(np.max(np.abs(b)))
    return big * float(np.linalg.norm(b / big)) if 0.0 < big < math.inf else big


def _check_load(name, b):
    """Range of a natural-unit wrench b; False if it is negligible (held exactly)."""
    nb = _norm(b)
    if not nb <= WRENCH_MAX:
        raise ValueError(
            f"{name} = ({', '.join(f'{x:.6g}' for x in b)}) in units of (m g, m g, m g a) is "
            f"invalid; valid range: magnitude <= {WRENCH_MAX:g} m g (the load must be finite "
            "relative to the weight)"
        )
    return nb >= WRENCH_NEGLIGIBLE


def _wrench3(name, w):
    try:
        items = [float(x) for x in w]
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {w!r} is invalid; valid values: (Fx, Fy, M)") from None
    if len(items) != 3 or not all(math.isfinite(x) for x in items):
        raise ValueError(
            f"{name} = {w!r} is invalid; valid values: three finite numbers (Fx, Fy, M)"
        )
    return np.array(items)


def _normal(incline, normal_factor):
    if incline is not None:
        if not isinstance(incline, Incline):
            raise ValueError(f"incline = {incline!r} is invalid; valid values: an Incline or None")
        if not incline.is_constant:
            raise ValueError(
                f"incline = {v._short(incline, 80)} has a tilt that varies in time; valid "
                "here: a fixed tilt (static friction is judged on one plane; give "
                "Incline(incline.angle_at(t)) for the plane at time t)"
            )
        return incline.normal_factor
    return v.positive("normal_factor", normal_factor)


def _with_pull(body, w, incline, g):
    """W_a plus gravity's downhill pull m g sin α d at G on an incline (MODEL §11)."""
    if incline is None:
        return w
    gx, gy = incline.gravity_force(body.mass, g)
    return np.array([w[0] + gx, w[1] + gy, w[2]])


def support_function(
    body: Body,
    friction: FrictionTensor,
    direction,
    phi: float = 0.0,
    g: float = 9.81,
    *,
    incline: Incline | None = None,
):
    """Support function h(d) of the static-friction set C and its support point (MODEL §11).

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body and its friction tensor.
    direction : (float, float, float)
        Wrench direction d = (d_Fx, d_Fy, d_M) [1, 1, 1/m]; need not be a unit vector.
    phi : float
        Body angle [rad].
    g : float
        Gravitational acceleration [m/s²].
    incline : Incline or None
        A tilted plane scales the normal load, hence C, by cos α.

    Returns
    -------
    h : float
        max over C of d·W [N] (for d_F dimensionless).
    point : ndarray, shape (3,)
        The wrench of C where d is an outward normal: (Fx [N], Fy [N], M [N m]).

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> disk = Body(Circle(0.1), UniformPressure(), mass=1.0)
    >>> h, _ = support_function(disk, FrictionTensor(0.3, 0.3), (0.0, 0.0, 1.0), g=10.0)
    >>> round(h, 12)  # (2/3) μ m g R, the torque a uniform disk resists
    0.2
    """
    _check(body, friction)
    d = _wrench3("direction", direction)
    nf = _normal(incline, 1.0)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    a = body.length_unit
    sup = static_support(TwistWrench(body, friction), friction, v.finite("phi", phi))
    h, grad = sup(np.array([d[0], d[1], d[2] * a]))
    load = body.mass * g * nf
    return float(h * load), np.array([grad[0] * load, grad[1] * load, grad[2] * load * a])


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
) -> float:
    """Load factor λ*: the applied wrench can be multiplied by λ* before the body slips.

    λ* = min over wrench directions d with d·W_a > 0 of h(d)/(d·W_a) (the inverse of the
    gauge of C at W_a; MODEL §11). The body at rest stays at rest iff λ* ≥ 1.

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body and its friction tensor.
    applied_wrench : (float, float, float)
        W_a = (Qx [N], Qy [N], moment about G [N m]) in the fixed frame: the loads other
        than gravity (``(0, 0, 0)`` asks whether the body holds on the slope alone).
    phi : float
        Body angle [rad].
    g : float
        Gravitational acceleration [m/s²].
    incline : Incline or None
        A plane of fixed tilt α (MODEL §11): the normal load, hence C, scales by cos α, and
        gravity's downhill pull m g sin α d at G is added to ``applied_wrench``, as
        :func:`slidespin.motion.simulate` does. λ* then multiplies the total W_a + m g sin α d.
        A tilt varying in time is refused (give the plane at one time).

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
    _check(body, friction)
    w = _wrench3("applied_wrench", applied_wrench)
    nf = _normal(incline, 1.0)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    w = _with_pull(body, w, incline, g)
    b = _natural_wrench(body, w, nf, g)
    if not _check_load("applied_wrench", b):
        return math.inf
    sup = static_support(TwistWrench(body, friction), friction, v.finite("phi", phi))
    return _load_factor_nat(sup, b)[0]


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
) -> bool:
    """Whether static friction can hold the body at rest under ``applied_wrench``.

    True iff −W_a ∈ C (MODEL §11), i.e. :func:`load_factor` ≥ 1: a load exactly at the
    threshold is held. Arguments as in :func:`load_factor`: with ``incline`` gravity's
    downhill pull is included, so ``can_stick(body, friction, (0, 0, 0), incline=...)``
    answers "does it hold on this slope?" (for isotropic friction: iff tan α ≤ μ).

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> disk = Body(Circle(0.1), UniformPressure(), mass=1.0)
    >>> fr = FrictionTensor(0.3, 0.3)
    >>> can_stick(disk, fr, (0.0, 0.0, 0.199), g=10.0), can_stick(disk, fr, (0.0, 0.0, 0.201), g=10.0)
    (True, False)
    """
    return load_factor(body, friction, applied_wrench, phi, g, incline=incline) >= 1.0


def critical_tilt(
    body: Body, friction: FrictionTensor, downhill: float = 0.0, phi: float = 0.0
) -> float:
    """Tilt α_c [rad] above which the body at rest slides down a plane (MODEL §11).

    On a plane tilted by α the applied wrench is m g sin α (d, 0) and C scales by cos α, so
    the body holds iff tan α ≤ λ*(m g d) on the level plane: α_c = atan λ*(m g (cos δ, sin δ), 0).
    For isotropic friction α_c = atan μ whatever the patch and pressure law.

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
    """

    direction: np.ndarray
    twist: np.ndarray
    acceleration: float
    residual: float


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
) -> Onset | None:
    """Direction and initial rate in which a body at rest starts to slip (MODEL §11).

    Parameters
    ----------
    body, friction, applied_wrench, phi, g, incline
        As in :func:`load_factor`; with ``incline`` gravity's downhill pull m g sin α d is
        added to ``applied_wrench`` (the loads other than gravity).

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
    _check(body, friction)
    w = _wrench3("applied_wrench", applied_wrench)
    nf = _normal(incline, 1.0)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    phi = v.finite("phi", phi)
    w = _with_pull(body, w, incline, g)
    tw = TwistWrench(body, friction, _TOL)
    wn = _natural_wrench(body, w, nf, g)
    if not _check_load("applied_wrench", wn):
        return None
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
