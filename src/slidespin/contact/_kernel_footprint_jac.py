"""Compiled twist derivatives of the footprint wrench (MODEL §10, §15).

The footprint kernel (:mod:`slidespin.contact._kernel_footprint`) writes the wrench through
two isotropic integrals about the ICR c: V = ∫ p ê dS and N_ab = ∫ p (r − r_G)_a ê_b dS,

    F = −sign(ω) 𝔽 ẑ×V,     M = −sign(ω) (−𝔽₁₀N_xy + 𝔽₁₁N_xx + 𝔽₀₀N_yy − 𝔽₀₁N_yx),

so the wrench depends on the twist (v, ω) only through c = r_G + ẑ×v/ω (and the sign of ω):

    ∂W/∂(vx, vy, ω) = ∂W/∂c · ∂c/∂(vx, vy, ω),   ∂c/∂v = ẑ×/ω,   ∂c/∂ω = −(c − r_G)/ω.

∂V/∂c and ∂N/∂c are exact (:func:`fan_tensors_jac`). With x = r − c and the divergence
theorem (the integrand's gradient ~ |x|^(k−2) is integrable for k ≥ 1),

    ∂G_k/∂c_j = −∫_Ω ∂_j (x^{⊗k}/|x|) dS = −∮ x^{⊗k}/|x| n̂_j dl,

so an edge adds −n̂_j L_k, L_k = ∫ (d n̂ + s t̂)^{⊗k}/√(d² + s²) ds, the line integrals the fan
already forms (its triangle is d/(k+1) L_k; an edge through c, d = 0, has no area but still
its L_k). A disk's tensors are scalars of its distance D = |o − c| in the frame (u, v) of
u = (o − c)/D (:func:`slidespin.contact._kernel_disk.round_terms`); moving c by
a u + b v moves D by −a and turns the frame by −b/D, and the scalars' D-derivatives follow
from dI_n/dD = −∫ D sin^{2n+2}ψ/h dψ: inside, −(2D/R) T_{n+1}(m); outside,
−2 k^{2n+2} T_{n+1}(m) (T_n of the notes of :mod:`slidespin.contact._kernel_footprint`).
T_{n+1} diverges at the rim (m → 1), but the tensors need only the differences
T_{n+1} − T_{n+2} = V_{n+1} (inside) and T_{n+1} − m T_{n+2} = U_{n+1} (outside), finite
there (:func:`slidespin.contact._kernel_disk.round_terms_jac`); the frame's turn (÷ D) is
written with D factored out, G₂'s through (2U₁ − U₀)/m by its own series, so that c at the
centre needs no special case. The V and N of a far ICR (Gauss rules) and a thin ring
(double-double arithmetic) are differenced in c instead (:func:`_iso_parts_differenced`):
central differences of the exact V and N at the step h = ``REL_STEP`` (extent + |c − o|),
O(h²) = 1e-10 relative, five evaluations of V and N. The isotropic parts Q = sign(ω) ẑ×V and N'
(M = −Σ 𝔽_ij N'_ij) come exact.

The pressure centre (MODEL §15) moves G and the pressure coefficients p = (p₀, p₁, p₂) (the
linear law through it). At a fixed twist of G the ICR moves with G (∂W/∂c again) and the
moment changes its arm (∂M/∂ξ_G = −F_y, ∂M/∂η_G = F_x); V and N are linear in p,
∂V/∂p_i = φ_i(c) G₁ + G₂∇φ_i and ∂S/∂p_i = φ_i(c) G₂ + G₃∇φ_i with φ = (1, ξ, η), from the
same tensors (for a far ICR or a thin ring: V and N of the three unit pressures). Both go to
the derivative vector (``out[21:36]``, :mod:`slidespin.contact._jacobian`); the caller
combines them with dp/dθ and dG/dθ.
Not available (the caller differences the whole right-hand side): a blade (one edge) and
a translation (ω = 0 or the ICR beyond ``FAR_ICR`` extents).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._jacobian import JAC_SIZE, unavailable, world_from_body
from slidespin.contact._kernel_disk import round_terms_jac, thin_hole
from slidespin.contact._kernel_ellipse import tensor_in_body
from slidespin.contact._kernel_footprint import (
    FAR_ICR,
    FAR_RATIO,
    GEO_EXT,
    GEO_OX,
    GEO_OY,
    GEO_P0,
    GEO_P1,
    GEO_P2,
    GEO_XG,
    GEO_YG,
    circle_frame,
    edge_lines,
    iso_parts,
    round_tensors,
    sym3,
    wrench_body,
)

__all__ = ["REL_STEP", "jacobian_world"]

#: relative step of the differences in c (of the extent plus the ICR's distance)
REL_STEP = 1e-5


@jit(error_model="numpy")
def fan_tensors_jac(edges, circles, cx, cy, dg):
    """:func:`slidespin.contact._kernel_footprint.fan_tensors` (returned) and its derivatives
    ∂G/∂cx, ∂G/∂cy in the same order into ``dg[0:9]``, ``dg[9:18]``, G itself into
    ``dg[18:27]`` (the view returned; module notes; not for a
    thin ring: :func:`slidespin.contact._kernel_disk.thin_hole`)."""
    for i in range(27):
        dg[i] = 0.0
    g = dg[18:27]
    rq = -1.0
    for i in range(edges.shape[0]):
        ln, tx, ty, d, j0, j1, j2, j3, rq = edge_lines(edges, i, cx, cy, rq)
        if ln == 0.0:
            continue
        nx = ty
        ny = -tx
        # L_k = ∫ x^{⊗k}/|x| dl along the edge: the triangle's G_k is d/(k+1) L_k
        l0 = d * d * j0
        l1 = d * j1
        a1x = d * j0 * nx + j1 * tx
        a1y = d * j0 * ny + j1 * ty
        a2xx = l0 * nx * nx + 2.0 * l1 * nx * tx + j2 * tx * tx
        a2xy = l0 * nx * ny + l1 * (nx * ty + tx * ny) + j2 * tx * ty
        a2yy = l0 * ny * ny + 2.0 * l1 * ny * ty + j2 * ty * ty
        a, b, c, e = sym3(nx, ny, tx, ty, d * l0, d * l1, d * j2, j3)
        lk = (a1x, a1y, a2xx, a2xy, a2yy, a, b, c, e)
        for q in range(9):
            w = d / (2.0 if q < 2 else 3.0 if q < 5 else 4.0)
            g[q] += w * lk[q]
            dg[q] -= nx * lk[q]
            dg[9 + q] -= ny * lk[q]
    for i in range(circles.shape[0]):
        dd, ux, uy = circle_frame(circles, i, cx, cy)
        vx = -uy
        vy = ux
        sgn = circles[i, 3]
        (g1, g2u, g2v, g3u, g3v, d1, d2u, d2v, d3u, d3v, t1, t2, t3a, t3b) = round_terms_jac(
            dd, circles[i, 2]
        )
        t = round_tensors(sgn, ux, uy, g1, g2u, g2v, g3u, g3v)
        for q in range(9):
            g[q] += t[q]
        # along e_j = a u + b v: D moves by −a, the frame (u, v) turns by −b/D
        for j in range(2):
            al = -sgn * (ux if j == 0 else uy)
            be = sgn * (vx if j == 0 else vy)
            o = 9 * j
            dg[o] += al * d1 * ux - be * t1 * vx
            dg[o + 1] += al * d1 * uy - be * t1 * vy
            dg[o + 2] += al * (d2u * ux * ux + d2v * vx * vx) + 2.0 * be * t2 * ux * vx
            dg[o + 3] += al * (d2u * ux * uy + d2v * vx * vy) + be * t2 * (ux * vy + vx * uy)
            dg[o + 4] += al * (d2u * uy * uy + d2v * vy * vy) + 2.0 * be * t2 * uy * vy
            a, b, c, e = sym3(ux, uy, vx, vy, al * d3u, be * t3a, al * d3v, be * t3b)
            dg[o + 5] += a
            dg[o + 6] += b
            dg[o + 7] += c
            dg[o + 8] += e
    return g


@jit(error_model="numpy")
def iso_parts_jac(edges, circles, geo, cx, cy, dv, work):
    """:func:`slidespin.contact._kernel_footprint.iso_parts` (V, N; returned) about an ICR c
    near the footprint (the exact fan) and their derivatives into ``dv``: ∂(V, N)/∂cx at
    ``dv[0:6]``, ∂/∂cy at ``dv[6:12]``, ∂/∂p₀, ∂/∂p₁, ∂/∂p₂ at ``dv[12:18]``, ``dv[18:24]``,
    ``dv[24:30]`` (the order of V, N; V and N are linear in p: ∂V/∂p_i = φ_i(c) G₁ + G₂∇φ_i,
    ∂S/∂p_i = φ_i(c) G₂ + G₃∇φ_i with φ = (1, ξ, η)); ``work`` (27) for the tensors."""
    dg = work
    g = fan_tensors_jac(edges, circles, cx, cy, dg)
    p0, p1, p2 = geo[GEO_P0], geo[GEO_P1], geo[GEO_P2]
    al = p0 + p1 * cx + p2 * cy
    vx_ = al * g[0] + g[2] * p1 + g[3] * p2
    vy_ = al * g[1] + g[3] * p1 + g[4] * p2
    sxx = al * g[2] + g[5] * p1 + g[6] * p2
    sxy = al * g[3] + g[6] * p1 + g[7] * p2
    syy = al * g[4] + g[7] * p1 + g[8] * p2
    ax = cx - geo[GEO_XG]
    ay = cy - geo[GEO_YG]
    for j in range(2):
        o = 9 * j
        pj = p1 if j == 0 else p2
        dvx = pj * g[0] + al * dg[o] + dg[o + 2] * p1 + dg[o + 3] * p2
        dvy = pj * g[1] + al * dg[o + 1] + dg[o + 3] * p1 + dg[o + 4] * p2
        dsxx = pj * g[2] + al * dg[o + 2] + dg[o + 5] * p1 + dg[o + 6] * p2
        dsxy = pj * g[3] + al * dg[o + 3] + dg[o + 6] * p1 + dg[o + 7] * p2
        dsyy = pj * g[4] + al * dg[o + 4] + dg[o + 7] * p1 + dg[o + 8] * p2
        q = 6 * j
        dv[q] = dvx
        dv[q + 1] = dvy
        dv[q + 2] = dsxx + (vx_ if j == 0 else 0.0) + ax * dvx
        dv[q + 3] = dsxy + (vy_ if j == 0 else 0.0) + ax * dvy
        dv[q + 4] = dsxy + (vx_ if j == 1 else 0.0) + ay * dvx
        dv[q + 5] = dsyy + (vy_ if j == 1 else 0.0) + ay * dvy
    for i in range(3):
        f, e1, e2 = (1.0, 0.0, 0.0) if i == 0 else ((cx, 1.0, 0.0) if i == 1 else (cy, 0.0, 1.0))
        pvx = f * g[0] + g[2] * e1 + g[3] * e2
        pvy = f * g[1] + g[3] * e1 + g[4] * e2
        psxx = f * g[2] + g[5] * e1 + g[6] * e2
        psxy = f * g[3] + g[6] * e1 + g[7] * e2
        psyy = f * g[4] + g[7] * e1 + g[8] * e2
        q = 12 + 6 * i
        dv[q] = pvx
        dv[q + 1] = pvy
        dv[q + 2] = psxx + ax * pvx
        dv[q + 3] = psxy + ax * pvy
        dv[q + 4] = psxy + ay * pvx
        dv[q + 5] = psyy + ay * pvy
    return vx_, vy_, sxx + ax * vx_, sxy + ax * vy_, sxy + ay * vx_, syy + ay * vy_


@jit(error_model="numpy")
def _iso_parts_differenced(edges, circles, geo, cx, cy, h, dv):
    """:func:`iso_parts_jac` where the fan is not used (a far ICR: Gauss rules; a thin ring:
    double-double): V, N returned, their derivatives in c by central differences at the step
    ``h``, in p by V and N of the unit pressures (V, N are linear in p)."""
    v = iso_parts(edges, circles, geo, cx, cy)
    for j in range(2):
        hx = h if j == 0 else 0.0
        hy = h - hx
        a = iso_parts(edges, circles, geo, cx + hx, cy + hy)
        c = iso_parts(edges, circles, geo, cx - hx, cy - hy)
        for q in range(6):
            dv[6 * j + q] = (a[q] - c[q]) / (2.0 * h)
    basis = geo.copy()
    for i in range(3):
        basis[GEO_P0] = 1.0 if i == 0 else 0.0
        basis[GEO_P1] = 1.0 if i == 1 else 0.0
        basis[GEO_P2] = 1.0 if i == 2 else 0.0
        u = iso_parts(edges, circles, basis, cx, cy)
        for q in range(6):
            dv[12 + 6 * i + q] = u[q]
    return v


@jit(error_model="numpy", inline="always")
def _wrench_of(dv, o, sg, b00, b01, b10, b11):
    """The change of (Fx, Fy, M) (body frame) for the change of (V, N) at ``dv[o:o + 6]``:
    F = −𝔽Q, Q = sign(ω) ẑ×V, M = −sign(ω) (𝔽₀₀N_yy − 𝔽₀₁N_yx − 𝔽₁₀N_xy + 𝔽₁₁N_xx)."""
    vx, vy, nxx, nxy, nyx, nyy = dv[o], dv[o + 1], dv[o + 2], dv[o + 3], dv[o + 4], dv[o + 5]
    return (
        -sg * (-b00 * vy + b01 * vx),
        -sg * (-b10 * vy + b11 * vx),
        -sg * (b00 * nyy - b01 * nyx - b10 * nxy + b11 * nxx),
    )


@jit(error_model="numpy")
def jacobian_body(edges, circles, geo, b00, b01, b10, b11, vx, vy, omega, out):
    """The wrench, its isotropic parts and its twist derivatives in the body frame (the
    layout of :mod:`slidespin.contact._jacobian`); returns whether they are available."""
    ext = geo[GEO_EXT]
    speed = math.sqrt(vx * vx + vy * vy)
    if edges.shape[0] == 1 or omega == 0.0 or speed > FAR_ICR * ext * abs(omega):
        fx, fy, m = wrench_body(edges, circles, geo, b00, b01, b10, b11, vx, vy, omega)
        out[0] = fx
        out[1] = fy
        out[2] = m
        unavailable(out, 3)
        return False
    xg = geo[GEO_XG]
    yg = geo[GEO_YG]
    cx = xg - vy / omega
    cy = yg + vx / omega
    sg = 1.0 if omega > 0.0 else -1.0
    dist = math.hypot(cx - geo[GEO_OX], cy - geo[GEO_OY])
    thin = False
    for i in range(circles.shape[0]):
        thin = thin or thin_hole(circles, i)
    work = np.empty(63)  # (one allocation per call)
    dv = work[:36]  # ∂(V, N)/∂(cx, cy, p₀, p₁, p₂) (6 each); (V, N) itself at dv[30:36]
    if dist > FAR_RATIO * ext or thin:
        v = _iso_parts_differenced(edges, circles, geo, cx, cy, REL_STEP * (ext + dist), dv)
    else:
        v = iso_parts_jac(edges, circles, geo, cx, cy, dv, work[36:])
    for q in range(6):
        dv[30 + q] = v[q]
    fx, fy, m = _wrench_of(dv, 30, sg, b00, b01, b10, b11)
    out[0] = fx
    out[1] = fy
    out[2] = m
    out[3], out[4] = -sg * v[1], sg * v[0]  # Q, N' (F = −𝔽Q, M = −Σ 𝔽_ij N'_ij)
    out[5], out[6], out[7], out[8] = sg * v[5], -sg * v[4], -sg * v[3], sg * v[2]
    x0, x1, x2 = _wrench_of(dv, 0, sg, b00, b01, b10, b11)  # ∂W/∂cx
    y0, y1, y2 = _wrench_of(dv, 6, sg, b00, b01, b10, b11)  # ∂W/∂cy
    # ∂c/∂(vx, vy, ω): columns (0, 1/ω), (−1/ω, 0), −(c − r_G)/ω
    iw = 1.0 / omega
    gx = -(cx - xg) * iw
    gy = -(cy - yg) * iw
    out[9], out[10], out[11] = y0 * iw, -x0 * iw, x0 * gx + y0 * gy
    out[12], out[13], out[14] = y1 * iw, -x1 * iw, x1 * gx + y1 * gy
    out[15], out[16], out[17] = y2 * iw, -x2 * iw, x2 * gx + y2 * gy
    # G at a fixed twist of G and fixed p: the ICR moves with G, and the moment's arm
    # (N = S + (c − r_G) ⊗ V: ∂M/∂ξ_G = −Fy, ∂M/∂η_G = Fx)
    out[21], out[22], out[23] = x0, x1, x2 - fy
    out[24], out[25], out[26] = y0, y1, y2 + fx
    for i in range(3):
        out[27 + 3 * i], out[28 + 3 * i], out[29 + 3 * i] = _wrench_of(
            dv, 12 + 6 * i, sg, b00, b01, b10, b11
        )
    return True


@jit(error_model="numpy", inline="always")
def jacobian_world(edges, circles, geo, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, out):
    """:func:`jacobian_body` in the fixed frame (arguments as
    :func:`slidespin.contact._kernel_footprint.wrench_world`); returns whether the
    derivatives are available."""
    if out.size < JAC_SIZE:  # (compiled code does not check its writes)
        raise ValueError("out: the derivative vector needs JAC_SIZE entries")
    c = math.cos(phi)
    s = math.sin(phi)
    vbx = c * vx + s * vy
    vby = -s * vx + c * vy
    b00, b01, b10, b11 = tensor_in_body(t00, t01, t10, t11, body_frame, c, s)
    ok = jacobian_body(edges, circles, geo, b00, b01, b10, b11, vbx, vby, omega, out)
    world_from_body(out, c, s, vbx, vby, b00, b01, b10, b11, body_frame, ok)
    return ok
