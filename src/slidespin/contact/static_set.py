"""The static-friction set C: the wrenches friction can supply to a body at rest (MODEL §11).

At rest, a contact point with pressure p can supply any traction in p·E, E = {𝔽 s : |s| ≤ 1}
(the image of the unit disk under the friction tensor), so static friction can supply exactly
the convex set of wrenches (Fx, Fy, M about G)

    C = ∫ p E dS,       support function  h(d) = max_{W ∈ C} d·W = ∫ p |𝔽ᵀ (d_F + d_M r′⊥)| dS,

for a wrench direction d = (d_F, d_M), with r′ = R(φ)(r − r_G) and r′⊥ = (−y′, x′). (The
maximising traction at each point is p 𝔽 ẑ, ẑ = 𝔽ᵀc/|𝔽ᵀc|, c = d_F + d_M r′⊥.) C is symmetric,
C = −C. A body at rest under an applied wrench W_a stays at rest iff −W_a ∈ C: the
load-facing questions (does a loaded body hold, by what load factor, how does it start) are
in :mod:`slidespin.contact.statics`.

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
with its own load and pressure centroid), a blade's (a line contact) is a segment carrying
the same load uniformly (the blade's closed forms), and a linear pressure stays linear. For isotropic
friction no map is needed: h(d) = −W(d)·d and ∇h(d) = −W(d), one call of the footprint
kernel. The sliding wrench W(u) of every feature below comes from one dispatch on the shape,
:class:`slidespin.contact._engine.TwistWrench` (elliptic or footprint kernel).

For isotropic friction (𝔽 = μ 1) the support point in direction d is −W(d), minus the friction
wrench of the twist d: C is bounded by the limit surface, and the twist is normal to it
(maximum dissipation; Goyal, Ruina & Papadopoulos 1991). For an anisotropic tensor the law
τ = −p 𝔽 ŵ is not of maximum dissipation and the limit surface may lie inside C.

The tensor's anisotropy times the patch's elongation is bounded (``check_anisotropy``,
ANISOTROPY_ELONGATION = 1e4): the image patch is that much more elongated.

Units: wrenches in N, N, N m; directions d = (d_Fx, d_Fy, d_M) pair with wrenches as
d·W = d_Fx Fx + d_Fy Fy + d_M M, so d_M is in 1/m. Internally natural units (a = m = g = 1,
a the body's length unit :attr:`slidespin.Body.length_unit`: the semi-axis of an ellipse, the
extent of a footprint).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.contact import _engine
from slidespin.contact._engine import TwistWrench, world_kernels
from slidespin.contact._kernel_ellipse import STATUS_OK
from slidespin.contact._kernel_footprint import GEO_LOAD, NGEO
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.pressure import LAW_LINEAR, LAW_UNIFORM
from slidespin.contact.shapes import Annulus, Blade, as_patches

__all__ = ["StaticSupport", "support_function"]

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
        f1, f2, m, st = world_kernels()[0](
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
    linear pressure to a linear pressure; a blade (one edge, a line load q over its length
    L) to the segment L·(blade) carrying the same load P with density q/|L ê| (ê its
    direction), exact by the blade's closed forms. The polygons are integrated by the footprint
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
        if e.shape[0] == 1:
            # a blade (one edge, MODEL §10): its image is a segment carrying the same load
            # P uniformly (the line density q/|L ê| on a segment |L ê| times as long), G at
            # the origin; the footprint kernel hands it to the blade's closed forms
            a0 = (e[:, 0:2] - (gx, gy)) @ mmap.T
            a1 = (e[:, 2:4] - (gx, gy)) @ mmap.T
            self.edges = np.ascontiguousarray(np.hstack((a0, a1)))
            mid = 0.5 * (a0[0] + a1[0])
            half = 0.5 * float(np.hypot(*(a1[0] - a0[0])))
            self.edge_geo = np.array(
                [mid[0], mid[1], half, 0.0, 0.0, 0.0, 0.0, 0.0, mid[0], mid[1], geo[GEO_LOAD]]
            )
        elif e.shape[0]:
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
        ellipse_world, footprint_world = world_kernels()
        if self.edges.shape[0]:
            fx, fy, mm = footprint_world(
                self.edges, _NO_CIRCLES, self.edge_geo, 1.0, 0.0, 0.0, 1.0, False, 0.0, vx, vy, om
            )
        for bn, law, xg, yg, psi, semi, gx, gy, load in self.circ:
            # velocity of the twist at the disk's pressure centroid, lengths per semi-axis
            wx, wy = vx - om * gy, vy + om * gx
            f1, f2, m, st = ellipse_world(
                float(bn), int(law), float(xg), float(yg), 1.0, 0.0, 0.0, 1.0, False,
                float(psi), wx / semi, wy / semi, om, _TOL,
            )  # fmt: skip
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


class ScaledSupport:
    """The support function of ``ratio`` × C: the static set of a tensor whose static
    coefficients are ``ratio`` (= μs/μk ≥ 1) times its kinetic ones (MODEL §14: C scales with
    the tensor, h and its support point by ``ratio``)."""

    __slots__ = ("base", "ratio")

    def __init__(self, base, ratio: float) -> None:
        self.base = base
        self.ratio = ratio

    def __call__(self, d):
        h, grad = self.base(d)
        return h * self.ratio, grad * self.ratio


def static_support(tw: TwistWrench, friction: FrictionTensor, phi: float):
    """The support function of the static set at angle ``phi``: :class:`StaticSupport` for
    an ellipse, :class:`FootprintSupport` for a footprint (natural units of ``tw``), scaled
    by the tensor's ``static`` ratio μs/μk when it exceeds 1 (:class:`ScaledSupport`)."""
    if tw.footprint:
        base: FootprintSupport | StaticSupport = FootprintSupport(tw, friction, phi)
    else:
        base = StaticSupport(tw.par, friction, phi)
    if friction.static != 1.0:
        return ScaledSupport(base, friction.static)
    return base


#: bound on (friction anisotropy) × (patch elongation): the static features map the patch to
#: its image under the tensor, an ellipse elongated by at most their product; the wrench
#: quadrature meets its target for every product ≤ 1e4 measured (aspects 1e-3..30, both
#: frames, skewed tensors) and misses it from ~1e5 on
ANISOTROPY_ELONGATION = 1e4


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


#: thinnest ring ((R − r)/R) whose static set an anisotropic tensor may ask for: the image of
#: a ring is an elliptic ring, the outer ellipse's integral minus the hole's (the elliptic
#: quadrature, to 1e-13 of each), which keeps ~1e-13 R/(R − r) (measured: load factors within
#: 7e-14 at 1e-3, 7e-11 at 1e-6, 1e-4 at 1e-12); isotropic friction needs no image (exact)
THIN_RING_STATICS = 1e-3


def check_anisotropy(body, friction, feature="static friction") -> None:
    """Raise ValueError naming ``friction`` unless cond(𝔽) × elongation ≤ 1e4, and, for an
    anisotropic tensor, unless every ring of the footprint is at least THIN_RING_STATICS
    wide (relative to its radius)."""
    prod = anisotropy_elongation(body, friction)
    if not prod <= ANISOTROPY_ELONGATION:
        raise ValueError(
            f"friction = {friction!r} is invalid for {feature} on this patch: anisotropy "
            f"(ratio of the tensor's singular values) x patch elongation max(b/a, a/b) = "
            f"{prod:.3g}; valid range: [1, {ANISOTROPY_ELONGATION:g}]"
        )
    iso = friction.fx == friction.fy and friction.f == 0.0
    if iso or not body.is_footprint or isinstance(body.patch, Blade):
        return
    for p in as_patches(body.patch):
        if isinstance(p, Annulus) and p.inner_radius > 0.0:
            width = (p.outer_radius - p.inner_radius) / p.outer_radius
            if not width >= THIN_RING_STATICS * (1.0 - 1e-9):  # (R - r)/R rounds
                raise ValueError(
                    f"patch = {v._short(p, 100)} is invalid for {feature} under the "
                    f"anisotropic friction = {friction!r}: its relative width (R - r)/R = "
                    f"{width:.3g} is below what the static set of its image (an elliptic "
                    f"ring) keeps digits for; valid range: (R - r)/R >= {THIN_RING_STATICS:g} "
                    "(or isotropic friction, which takes any ring)"
                )


def _check(body, friction):
    check_body_friction(body, friction)
    check_anisotropy(body, friction)


def _wrench3(name, w):
    """Three finite real numbers (Fx, Fy, M) as an array; a string, bytes or bools refused."""
    bad = (
        f"{name} = {v._short(w)} is invalid; valid values: three finite real numbers (Fx, Fy, "
        "M) [N, N, N m]"
    )
    if isinstance(w, (str, bytes, bytearray)):
        raise ValueError(bad)
    try:
        items = list(w)
    except TypeError:
        raise ValueError(bad) from None
    if len(items) != 3:
        raise ValueError(bad)
    try:
        return np.array([v.finite(f"{name}[{i}]", x) for i, x in enumerate(items)])
    except ValueError:
        raise ValueError(bad) from None


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
    sup = static_support(TwistWrench(body, friction.kinetic), friction, v.finite("phi", phi))
    h, grad = sup(np.array([d[0], d[1], d[2] * a]))
    load = body.mass * g * nf
    return float(h * load), np.array([grad[0] * load, grad[1] * load, grad[2] * load * a])
