"""Compiled exact friction wrench on any footprint given as plain arrays (MODEL §2, §10).

One kernel for every shape: the footprint is *data*, the arrays of
:meth:`slidespin.contact.shapes.Polygon.to_arrays` and friends:

* ``edges`` (n, 4): oriented straight edges (ξ₀, η₀, ξ₁, η₁), counter-clockwise around each
  polygon, so that the signed fan of triangles (c, P₀, P₁) over all edges, from any apex c,
  covers the polygons once;
* ``circles`` (m, 4): (ξ_o, η_o, R, σ), a disk added (σ = +1) or removed (σ = −1, the hole
  of a ring);
* ``geo`` (``NGEO``,): per-body constants, see :data:`GEO_FIELDS` (built by
  :func:`slidespin.contact.pressure_map.kernel_geometry`).

Pressure is linear, p = p₀ + p₁ξ + p₂η (uniform: p₁ = p₂ = 0), ≥ 0 on the footprint.

Method
------
For ω ≠ 0 every point moves about the instantaneous centre of rotation (ICR) c,
ŵ = sign(ω) ẑ×ê with ê = (r − c)/|r − c|, and τ = −p 𝔽ŵ. Because 𝔽 is constant,

    F = −sign(ω) 𝔽 ẑ×V,            V = ∫ p ê dS,
    M = −sign(ω) (−𝔽₁₀N_xy + 𝔽₁₁N_xx + 𝔽₀₀N_yy − 𝔽₀₁N_yx),   N_ab = ∫ p (r − r_G)_a ê_b dS,

and with x = r − c, p = α + β·x (α = p(c), β = (p₁, p₂)) both reduce to three purely
geometric tensors about the ICR,

    G_k = ∫_Ω x^{⊗k}/|x| dS,   k = 1, 2, 3:
    V = α G₁ + G₂β,   S = α G₂ + G₃β,   N = S + (c − r_G) ⊗ V.

*Polygons* (exact, closed form). Fan the footprint into signed triangles (c, P, Q), one per
edge. On an edge, x = d n̂ + s t̂ (t̂ along the edge, n̂ its outward normal, d the signed
distance of the edge's line from c, s from s_P to s_Q), dψ = d ds/|x|², and the radial
integral is elementary:

    ∫_triangle x^{⊗k}/|x| dS = d/(k+1) ∫ (d n̂ + s t̂)^{⊗k} / √(d² + s²) ds,

which needs J_b = ∫ s^b/√(d² + s²) ds, b = 0..3: asinh, √, and their combinations (written
without cancellation for a short edge seen from afar). An edge whose line passes through c
(d = 0) contributes nothing: the ICR on an edge or at a vertex needs no special case.

*Disks* (exact, complete elliptic integrals). On the line through c in direction ψ (measured
from the direction u of o − c, D = |o − c|) the disk cuts the chord m ± h, m = D cos ψ,
h = √(R² − D² sin²ψ), and the line form of the kernel for the ellipse (:mod:`._kernel`),
∫_Ω x^{⊗k}/|x| dS = ∫_{half turn} ê^{⊗k} ∫_chord ρ^k dρ dψ, leaves

    I_n = ∫ sin^{2n}ψ h dψ,  n = 0..3,

over the half turn (ICR inside, ε = D/R ≤ 1: I_n = 2R U_n(ε²), U_n(m) = ∫₀^{π/2} s^{2n}√(1 − m s²))
or over the lines that meet the disk (ICR outside, k = R/D: I_n = 2R k^{2n+1} V_n(k²),
V_n(m) = ∫₀^{π/2} s^{2n} c²/√(1 − m s²)). Both are a·K(m) + b·E(m) by the recurrence
(2n+1) m T_{n+1} = 2n(1+m) T_n − (2n−1) T_{n−1} for T_n = ∫ s^{2n}/√(1 − m s²), with K, E by
the arithmetic-geometric mean; the coefficient of K vanishes like 1 − m, so the ICR on the
rim (m = 1, I_n = 2R/(2n+1)) is exact too. Below m = 0.45 the binomial series of the
integrand (48 terms) is used instead (the recurrence divides by m). A ring adds the hole with
σ = −1 (the disk and ring terms: :mod:`slidespin.contact._kernel_disk`).

*Thin rings.* Disk and hole are O(R^k) each, the ring O((R − r) R^(k−1)): subtracted in
floats the ring keeps only ~1e-16 R/(R − r) of its digits (4e-8 at r/R = 1 − 1e-9, none at
1 − 1e-16). A ring thinner than ``THIN_RING`` (its hole the next row: same centre, σ = −1)
forms both circles' I_n in double-double arithmetic (a float pair hi + lo, ~32 digits, from
Dekker's exact sums and products), subtracts them there, and assembles its tensors from
those differences and R² − r² = (R − r)(R + r): exact to ~1e-16 at any width (tested against
the closed forms and the loaded-circle limit), at ~10 times the cost (~4 µs). The far rules
integrate a ring over r ≤ ρ ≤ R directly.

*Far ICR.* The fan's terms grow like |c|^k and cancel; beyond |c − o| > ``FAR_RATIO`` ×
extent the integrand is analytic over the footprint and V, N are integrated directly by
Gauss rules: n² points per signed triangle (o, P, Q), n × ``FAR_ANGULAR`` per disk, n = 4
beyond 24 extents and n = 3 beyond 300. Measured against the reference on either side of
the switches: the fan ≲ 9e-13 at 24 extents, the rules ≲ 1e-13 at 24 (n = 4) and ≲ 3e-13 at
300 (n = 3), in units of P and P·extent; the fan's error grows like (|c|/extent)², the rules'
falls with |c|. Beyond ``FAR_ICR`` × extent, or ω = 0, the motion is a translation:
F = −P_tot 𝔽v̂, M = (r_P − r_G) × F (r_P the pressure centroid).

Accuracy: against the independent reference (``tests/references/footprint_reference.py``) and the
ellipse kernel on a disk, ≲ 3e-12 P and P·extent for every motion state tested (ICR inside,
on an edge, at a (reflex) vertex, in a ring's hole, on and near a rim, far, ω = 0).

Speed (``time_wrenches``, a compiled loop over 1e5 states, best of 5; a 2-core machine
shared with other jobs, load ≈ 5, on which the ellipse kernel of :mod:`._kernel` took
0.39–0.46 µs per wrench in the same run), ICR uniform within 1 / 5 / 100 extents of G:
octagon 0.71 / 0.63 / 0.92 µs, non-convex hexagon 0.49 / 0.48 / 0.69 µs, rectangle 0.35 /
0.35 / 0.48 µs, ring 0.46 / 0.38 / 0.51 µs, disk 0.26 / 0.19 / 0.27 µs. The cost is one
logarithm and two square roots per edge, one AGM (or a 48-term series) per circle, and
16 (9) points per edge or 40 (30) per circle for a far ICR.

Units: any consistent length unit; the pressure coefficients set the load (P_tot = ∫p dS).
Forces come out in units of the load, moments in load × length.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._kernel_blade import blade_wrench_body
from slidespin.contact._kernel_disk import ring_terms, round_terms, thin_hole
from slidespin.contact._kernel_ellipse import tensor_in_body

#: fields of the ``geo`` vector
GEO_FIELDS = ("ox", "oy", "extent", "p0", "p1", "p2", "xg", "yg", "xp", "yp", "load")
(GEO_OX, GEO_OY, GEO_EXT, GEO_P0, GEO_P1, GEO_P2, GEO_XG, GEO_YG, GEO_XP, GEO_YP, GEO_LOAD) = range(
    11
)
NGEO = 11

#: ICR distance (in extents, from the reference point o) beyond which V, N are integrated
#: directly (the exact fan's cancellation grows like (|c|/extent)²)
FAR_RATIO = 24.0
#: the far rules use FAR_NODES Gauss points per direction up to FAR_RATIO_3 extents, then 3
#: (exact for the Taylor terms of the integrand up to (extent/|c|)²; the rest ≲ 3e-13 there)
FAR_RATIO_3 = 300.0
#: ICR distance (in extents) beyond which the motion is a translation
FAR_ICR = 1e15
FAR_NODES = 4
FAR_ANGULAR = 10


def _gauss_tables():
    """Gauss–Legendre nodes and weights on [0, 1] for n = 1..FAR_NODES: row n − 1, first n."""
    x = np.zeros((FAR_NODES, FAR_NODES))
    w = np.zeros((FAR_NODES, FAR_NODES))
    for n in range(1, FAR_NODES + 1):
        gx, gw = np.polynomial.legendre.leggauss(n)
        x[n - 1, :n] = 0.5 * (gx + 1.0)
        w[n - 1, :n] = 0.5 * gw
    return x, w


_GL_X, _GL_W = _gauss_tables()
_TH_C = np.cos(2.0 * np.pi * np.arange(FAR_ANGULAR) / FAR_ANGULAR)
_TH_S = np.sin(2.0 * np.pi * np.arange(FAR_ANGULAR) / FAR_ANGULAR)


# ---------------------------------------------------------------------------------------------
# the geometric tensors G₁, G₂, G₃ about the ICR


@jit(error_model="numpy", inline="always")
def sym3(nx, ny, tx, ty, l0, l1, l2, l3):
    """Components (xxx, xxy, xyy, yyy) of the symmetric tensor with components l0 (nnn),
    l1 (nnt), l2 (ntt), l3 (ttt) in the orthonormal frame (n, t)."""
    xxx = l0 * nx * nx * nx + 3.0 * l1 * nx * nx * tx + 3.0 * l2 * nx * tx * tx + l3 * tx * tx * tx
    xxy = (
        l0 * nx * nx * ny
        + l1 * (nx * nx * ty + 2.0 * nx * tx * ny)
        + l2 * (2.0 * nx * tx * ty + tx * tx * ny)
        + l3 * tx * tx * ty
    )
    xyy = (
        l0 * nx * ny * ny
        + l1 * (2.0 * nx * ny * ty + tx * ny * ny)
        + l2 * (nx * ty * ty + 2.0 * tx * ny * ty)
        + l3 * tx * ty * ty
    )
    yyy = l0 * ny * ny * ny + 3.0 * l1 * ny * ny * ty + 3.0 * l2 * ny * ty * ty + l3 * ty * ty * ty
    return xxx, xxy, xyy, yyy


@jit(error_model="numpy", inline="always")
def edge_lines(edges, i, cx, cy, rq):
    """The line integrals of edge ``i`` (P → Q) seen from c = (cx, cy): (ℓ, t̂x, t̂y, d, J₀,
    J₁, J₂, J₃, |Q − c|), J_b = ∫ s^b/√(d² + s²) ds (module notes); ``rq`` is the previous
    edge's |Q − c| (its P's distance when the edges are chained, as a polygon's), or −1.

    ℓ = 0 for a point. On a line through c (d² = 0) d is 0 and J₀ (divergent there, it only
    comes multiplied by d) is returned as 0: J₁, J₂, J₃ are the limits ∫ s^b/|s| ds.
    """
    px = edges[i, 0] - cx
    py = edges[i, 1] - cy
    qx = edges[i, 2] - cx
    qy = edges[i, 3] - cy
    if rq >= 0.0 and edges[i, 0] == edges[i - 1, 2] and edges[i, 1] == edges[i - 1, 3]:
        rp = rq
    else:
        rp = math.sqrt(px * px + py * py)
    rq = math.sqrt(qx * qx + qy * qy)
    ex = qx - px
    ey = qy - py
    ln = math.sqrt(ex * ex + ey * ey)
    if ln == 0.0:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, rq
    tx = ex / ln
    ty = ey / ln
    d = (px * qy - py * qx) / ln  # signed distance of the edge's line from c
    sp = tx * px + ty * py
    sq = tx * qx + ty * qy
    if d * d == 0.0:
        j2 = 0.5 * (sq * rq - sp * rp)
        return ln, tx, ty, 0.0, 0.0, rq - rp, j2, (sq * sq * rq - sp * sp * rp) / 3.0, rq
    ssum = sp + sq
    j1 = ln * ssum / (rp + rq)  # r_Q − r_P
    # J₀ = asinh(s_Q/|d|) − asinh(s_P/|d|) as one logarithm, without cancellation
    if sp >= 0.0:
        j0 = math.log1p((ln + j1) / (sp + rp))
        j2a = ln * ssum * (sq * sq + sp * sp + d * d) / (sq * rq + sp * rp)
    elif sq <= 0.0:
        j0 = math.log1p((ln - j1) / (rq - sq))
        j2a = ln * ssum * (sq * sq + sp * sp + d * d) / (sq * rq + sp * rp)
    else:
        j0 = math.log((sq + rq) * (rp - sp) / (d * d))
        j2a = sq * rq - sp * rp
    j2 = 0.5 * (j2a - d * d * j0)
    j3 = (
        j1
        * (
            sq * sq
            + sp * sp
            + (sq * sq * sp * sp + d * d * (sq * sq + sp * sp)) / (rq * rp + d * d)
        )
        / 3.0
    )
    return ln, tx, ty, d, j0, j1, j2, j3, rq


@jit(error_model="numpy", inline="always")
def circle_frame(circles, i, cx, cy):
    """(D, uₓ, u_y): the distance D of circle ``i``'s centre o from c and the unit vector u
    from c towards it (u = (1, 0) at D = 0; v = ẑ×u completes the frame)."""
    ux = circles[i, 0] - cx
    uy = circles[i, 1] - cy
    dd = math.sqrt(ux * ux + uy * uy)
    if dd > 0.0:
        return dd, ux / dd, uy / dd
    return dd, 1.0, 0.0


@jit(error_model="numpy", inline="always")
def round_tensors(sgn, ux, uy, g1, g2u, g2v, g3u, g3v):
    """A circle's G₁, G₂, G₃ (the 9 components of :func:`fan_tensors`) times its sign
    ``sgn`` from its scalars (G₁ᵤ, G₂ᵤᵤ, G₂ᵥᵥ, G₃ᵤᵤᵤ, G₃ᵤᵥᵥ) in the frame (u, v = ẑ×u)."""
    vx = -uy
    vy = ux
    a, b, c, e = sym3(ux, uy, vx, vy, g3u, 0.0, g3v, 0.0)
    return (
        sgn * g1 * ux,
        sgn * g1 * uy,
        sgn * (g2u * ux * ux + g2v * vx * vx),
        sgn * (g2u * ux * uy + g2v * vx * vy),
        sgn * (g2u * uy * uy + g2v * vy * vy),
        sgn * a,
        sgn * b,
        sgn * c,
        sgn * e,
    )


@jit(error_model="numpy")
def fan_tensors(edges, circles, cx, cy):
    """G₁ (x, y), G₂ (xx, xy, yy), G₃ (xxx, xxy, xyy, yyy) of the footprint about the point
    c = (cx, cy): G_k = ∫ x^{⊗k}/|x| dS, x = r − c (module notes), as a tuple of 9 floats."""
    g1x = 0.0
    g1y = 0.0
    g2xx = 0.0
    g2xy = 0.0
    g2yy = 0.0
    g3a = 0.0
    g3b = 0.0
    g3c = 0.0
    g3d = 0.0
    rq = -1.0
    for i in range(edges.shape[0]):
        ln, tx, ty, d, j0, j1, j2, j3, rq = edge_lines(edges, i, cx, cy, rq)
        if ln == 0.0 or d == 0.0:  # a point, or a line through c: no area (the ICR on an edge)
            continue
        nx = ty
        ny = -tx
        w1 = 0.5 * d
        g1x += w1 * (d * j0 * nx + j1 * tx)
        g1y += w1 * (d * j0 * ny + j1 * ty)
        w2 = d / 3.0
        l0 = d * d * j0
        l1 = d * j1
        g2xx += w2 * (l0 * nx * nx + 2.0 * l1 * nx * tx + j2 * tx * tx)
        g2xy += w2 * (l0 * nx * ny + l1 * (nx * ty + tx * ny) + j2 * tx * ty)
        g2yy += w2 * (l0 * ny * ny + 2.0 * l1 * ny * ty + j2 * ty * ty)
        w3 = 0.25 * d
        a, b, c, e = sym3(nx, ny, tx, ty, d * l0, d * l1, d * j2, j3)
        g3a += w3 * a
        g3b += w3 * b
        g3c += w3 * c
        g3d += w3 * e
    nc = circles.shape[0]
    skip = False
    for i in range(nc):
        if skip:  # the hole of a thin ring, taken with its disk
            skip = False
            continue
        dd, ux, uy = circle_frame(circles, i, cx, cy)
        rr = circles[i, 2]
        if thin_hole(circles, i):
            g1u, g2uu, g2vv, g3uuu, g3uvv = ring_terms(dd, rr, circles[i + 1, 2])
            skip = True
        else:
            g1u, g2uu, g2vv, g3uuu, g3uvv = round_terms(dd, rr)
        t = round_tensors(circles[i, 3], ux, uy, g1u, g2uu, g2vv, g3uuu, g3uvv)
        g1x += t[0]
        g1y += t[1]
        g2xx += t[2]
        g2xy += t[3]
        g2yy += t[4]
        g3a += t[5]
        g3b += t[6]
        g3c += t[7]
        g3d += t[8]
    return g1x, g1y, g2xx, g2xy, g2yy, g3a, g3b, g3c, g3d


@jit(error_model="numpy", inline="always")
def _far_point(x, y, w, cx, cy, p0, p1, p2):
    """p ê w at the point (x, y): its (x, y) components."""
    ex = x - cx
    ey = y - cy
    pw = w * (p0 + p1 * x + p2 * y) / math.sqrt(ex * ex + ey * ey)
    return ex * pw, ey * pw


@jit(error_model="numpy")
def far_sums(edges, circles, ox, oy, cx, cy, xg, yg, p0, p1, p2, nodes):
    """V (x, y) and N (xx, xy, yx, yy) by Gauss rules (``nodes`` points per direction) over
    signed triangles (o, P, Q) and disks, for an ICR c far from the footprint (module notes)."""
    vx = 0.0
    vy = 0.0
    nxx = 0.0
    nxy = 0.0
    nyx = 0.0
    nyy = 0.0
    row = nodes - 1
    for i in range(edges.shape[0]):
        ax = edges[i, 0] - ox
        ay = edges[i, 1] - oy
        bx = edges[i, 2] - edges[i, 0]
        by = edges[i, 3] - edges[i, 1]
        jac = ax * by - ay * bx
        if jac == 0.0:
            continue
        for a in range(nodes):
            u = _GL_X[row, a]
            wu = _GL_W[row, a] * u * jac
            for b in range(nodes):
                v = _GL_X[row, b]
                x = ox + u * (ax + v * bx)
                y = oy + u * (ay + v * by)
                qx, qy = _far_point(x, y, wu * _GL_W[row, b], cx, cy, p0, p1, p2)
                vx += qx
                vy += qy
                nxx += (x - xg) * qx
                nxy += (x - xg) * qy
                nyx += (y - yg) * qx
                nyy += (y - yg) * qy
    skip = False
    for i in range(circles.shape[0]):
        if skip:  # a ring's hole, integrated with its disk
            skip = False
            continue
        ccx = circles[i, 0]
        ccy = circles[i, 1]
        rr = circles[i, 2]
        inner = 0.0  # a ring (a disk and its hole in the next row): r ≤ ρ ≤ R directly
        if (
            circles[i, 3] > 0.0
            and i + 1 < circles.shape[0]
            and circles[i + 1, 3] < 0.0
            and circles[i + 1, 0] == ccx
            and circles[i + 1, 1] == ccy
        ):
            inner = circles[i + 1, 2]
            skip = True
        wc = circles[i, 3] * (rr - inner) * 2.0 * math.pi / FAR_ANGULAR
        for a in range(nodes):
            rho = inner + (rr - inner) * _GL_X[row, a]
            wr = wc * _GL_W[row, a] * rho
            for b in range(FAR_ANGULAR):
                x = ccx + rho * _TH_C[b]
                y = ccy + rho * _TH_S[b]
                qx, qy = _far_point(x, y, wr, cx, cy, p0, p1, p2)
                vx += qx
                vy += qy
                nxx += (x - xg) * qx
                nxy += (x - xg) * qy
                nyx += (y - yg) * qx
                nyy += (y - yg) * qy
    return vx, vy, nxx, nxy, nyx, nyy


# ---------------------------------------------------------------------------------------------
# the wrench


@jit(error_model="numpy")
def iso_parts(edges, circles, geo, cx, cy):
    """V = ∫ p ê dS (x, y) and N_ab = ∫ p (r − r_G)_a ê_b dS (xx, xy, yx, yy) about the ICR
    c = (cx, cy) (module notes): the exact fan, or the Gauss rules for a far ICR."""
    ext = geo[GEO_EXT]
    xg = geo[GEO_XG]
    yg = geo[GEO_YG]
    p0 = geo[GEO_P0]
    p1 = geo[GEO_P1]
    p2 = geo[GEO_P2]
    ox = geo[GEO_OX]
    oy = geo[GEO_OY]
    dist = math.sqrt((cx - ox) ** 2 + (cy - oy) ** 2)
    if dist > FAR_RATIO * ext:
        nodes = FAR_NODES if dist <= FAR_RATIO_3 * ext else 3
        vx_, vy_, nxx, nxy, nyx, nyy = far_sums(
            edges, circles, ox, oy, cx, cy, xg, yg, p0, p1, p2, nodes
        )
    else:
        g1x, g1y, g2xx, g2xy, g2yy, g3a, g3b, g3c, g3d = fan_tensors(edges, circles, cx, cy)
        al = p0 + p1 * cx + p2 * cy
        vx_ = al * g1x + g2xx * p1 + g2xy * p2
        vy_ = al * g1y + g2xy * p1 + g2yy * p2
        sxx = al * g2xx + g3a * p1 + g3b * p2
        sxy = al * g2xy + g3b * p1 + g3c * p2
        syy = al * g2yy + g3c * p1 + g3d * p2
        ax = cx - xg
        ay = cy - yg
        nxx = sxx + ax * vx_
        nxy = sxy + ax * vy_
        nyx = sxy + ay * vx_
        nyy = syy + ay * vy_
    return vx_, vy_, nxx, nxy, nyx, nyy


@jit(error_model="numpy")
def wrench_body(edges, circles, geo, t00, t01, t10, t11, vx, vy, omega):
    """Friction force (body frame) and moment about G for the footprint in array form.

    Parameters
    ----------
    edges, circles : ndarray
        The footprint (module notes; :meth:`slidespin.contact.shapes.Polygon.to_arrays`).
    geo : ndarray
        Per-body constants, layout :data:`GEO_FIELDS` (reference point, extent, pressure
        coefficients p₀, p₁, p₂, mass centre G, pressure centroid, load ∫p dS).
    t00, t01, t10, t11 : float
        Friction tensor 𝔽 in the body frame.
    vx, vy, omega : float
        Velocity of G in the body frame and spin rate (any scale: only the direction of the
        motion matters).

    Returns
    -------
    fx, fy, m : float
        Force in the body frame (units of the load) and moment about G (load × length),
        counter-clockwise positive. Zero at rest.
    """
    if edges.shape[0] == 1:  # a blade (slidespin.contact.shapes.Blade): the line-contact kernel
        return blade_wrench_body(
            edges[0, 0],
            edges[0, 1],
            edges[0, 2],
            edges[0, 3],
            geo[GEO_XG],
            geo[GEO_YG],
            geo[GEO_LOAD],
            t00,
            t01,
            t10,
            t11,
            vx,
            vy,
            omega,
        )
    ext = geo[GEO_EXT]
    xg = geo[GEO_XG]
    yg = geo[GEO_YG]
    speed = math.sqrt(vx * vx + vy * vy)
    if omega == 0.0 or speed > FAR_ICR * ext * abs(omega):
        if speed == 0.0:
            return 0.0, 0.0, 0.0
        ux = vx / speed
        uy = vy / speed
        load = geo[GEO_LOAD]
        fx = -(t00 * ux + t01 * uy) * load
        fy = -(t10 * ux + t11 * uy) * load
        return fx, fy, (geo[GEO_XP] - xg) * fy - (geo[GEO_YP] - yg) * fx
    cx = xg - vy / omega
    cy = yg + vx / omega
    vx_, vy_, nxx, nxy, nyx, nyy = iso_parts(edges, circles, geo, cx, cy)
    sg = -1.0 if omega > 0.0 else 1.0  # the factor −sign(ω)
    fx = sg * (-t00 * vy_ + t01 * vx_)
    fy = sg * (-t10 * vy_ + t11 * vx_)
    m = sg * (-t10 * nxy + t11 * nxx + t00 * nyy - t01 * nyx)
    return fx, fy, m


@jit(error_model="numpy")
def wrench_world(edges, circles, geo, t00, t01, t10, t11, body_frame, phi, vx, vy, omega):
    """Friction wrench in the fixed frame: (Fx, Fy, M about G).

    The tensor (t00..t11) is given in its own frame: the plane's (``body_frame`` false) or the
    body's; (vx, vy) is the velocity of G in the fixed frame, ``phi`` the body angle.
    """
    c = math.cos(phi)
    s = math.sin(phi)
    vbx = c * vx + s * vy
    vby = -s * vx + c * vy
    b00, b01, b10, b11 = tensor_in_body(t00, t01, t10, t11, body_frame, c, s)
    fbx, fby, m = wrench_body(edges, circles, geo, b00, b01, b10, b11, vbx, vby, omega)
    return c * fbx - s * fby, s * fbx + c * fby, m


@jit(error_model="numpy")
def wrench_array(edges, circles, geo, t00, t01, t10, t11, body_frame, phi, vx, vy, omega):
    """:func:`wrench_world` over 1-D arrays ``phi, vx, vy, omega`` of equal length."""
    n = vx.size
    fx = np.empty(n)
    fy = np.empty(n)
    mm = np.empty(n)
    for i in range(n):
        fx[i], fy[i], mm[i] = wrench_world(
            edges, circles, geo, t00, t01, t10, t11, body_frame, phi[i], vx[i], vy[i], omega[i]
        )
    return fx, fy, mm


@jit(error_model="numpy")
def time_wrenches(edges, circles, geo, t00, t01, t10, t11, vx, vy, omega):
    """Sum of :func:`wrench_body` over the states (a compiled loop for timing the kernel)."""
    s = 0.0
    for i in range(vx.size):
        fx, fy, m = wrench_body(edges, circles, geo, t00, t01, t10, t11, vx[i], vy[i], omega[i])
        s += fx + fy + m
    return s
