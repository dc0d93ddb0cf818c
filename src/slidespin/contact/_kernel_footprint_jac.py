"""Compiled twist derivatives of the footprint wrench (MODEL §10, §15).

The footprint kernel (:mod:`slidespin.contact._kernel_footprint`) writes the wrench through
two isotropic integrals about the ICR c: V = ∫ p ê dS and N_ab = ∫ p (r − r_G)_a ê_b dS,

    F = −sign(ω) 𝔽 ẑ×V,     M = −sign(ω) (−𝔽₁₀N_xy + 𝔽₁₁N_xx + 𝔽₀₀N_yy − 𝔽₀₁N_yx),

so the wrench depends on the twist (v, ω) only through c = r_G + ẑ×v/ω (and the sign of ω):

    ∂W/∂(vx, vy, ω) = ∂W/∂c · ∂c/∂(vx, vy, ω),   ∂c/∂v = ẑ×/ω,   ∂c/∂ω = −(c − r_G)/ω.

∂V/∂c and ∂N/∂c are central differences of the exact V and N (the closed-form fan, or the
Gauss rules of a far ICR) at the step h = ``REL_STEP`` (extent + |c − o|): V and N are
smooth in c away from the footprint's rim (O(h²) = 1e-10 relative, round-off 1e-16/h), and
C¹ across it (their second derivative has a logarithmic singularity there: within ~h of a
rim the difference is good to O(h log h)). This departs from the elliptic kernel's
analytic derivative (:mod:`slidespin.contact._kernel_ellipse_jac`): the fan's lower-order
tensors ∫ x^{⊗k}/|x|³ dS are not written yet. It costs five evaluations of V and N (one
wrench's worth each) for every parameter at once, instead of two wrench evaluations per
parameter. The isotropic parts Q = sign(ω) ẑ×V and N' (M = −Σ 𝔽_ij N'_ij) come exact.
Not available (the caller differences the whole right-hand side): a blade (one edge) and
a translation (ω = 0 or the ICR beyond ``FAR_ICR`` extents).
"""

from __future__ import annotations

import math

from slidespin._jit import jit
from slidespin.contact._jacobian import JAC_SIZE, unavailable, world_from_body
from slidespin.contact._kernel_ellipse import tensor_in_body
from slidespin.contact._kernel_footprint import (
    FAR_ICR,
    GEO_EXT,
    GEO_OX,
    GEO_OY,
    GEO_XG,
    GEO_YG,
    iso_parts,
    wrench_body,
)

__all__ = ["REL_STEP", "jacobian_world"]

#: relative step of the differences in c (of the extent plus the ICR's distance)
REL_STEP = 1e-5


@jit(error_model="numpy")
def _primed(edges, circles, geo, cx, cy, sg):
    """(Q, N') with F = −𝔽Q, M = −Σ 𝔽_ij N'_ij from V, N about c and sign(ω)."""
    v0, v1, nxx, nxy, nyx, nyy = iso_parts(edges, circles, geo, cx, cy)
    return -sg * v1, sg * v0, sg * nyy, -sg * nyx, -sg * nxy, sg * nxx


@jit(error_model="numpy")
def _dw_dc(edges, circles, geo, cx, cy, hx, hy, sg, b00, b01, b10, b11):
    """∂(Fx, Fy, M)/∂c along (hx, hy)/h (one of them zero) by the central difference of Q, N'."""
    a0, a1, a2, a3, a4, a5 = _primed(edges, circles, geo, cx + hx, cy + hy, sg)
    c0, c1, c2, c3, c4, c5 = _primed(edges, circles, geo, cx - hx, cy - hy, sg)
    i2h = 0.5 / (hx + hy)
    dq0 = (a0 - c0) * i2h
    dq1 = (a1 - c1) * i2h
    dfx = -(b00 * dq0 + b01 * dq1)
    dfy = -(b10 * dq0 + b11 * dq1)
    dm = -(b00 * (a2 - c2) + b01 * (a3 - c3) + b10 * (a4 - c4) + b11 * (a5 - c5)) * i2h
    return dfx, dfy, dm


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
    q0, q1, n00, n01, n10, n11 = _primed(edges, circles, geo, cx, cy, sg)
    out[0] = -(b00 * q0 + b01 * q1)  # F = −𝔽Q, M = −Σ 𝔽_ij N'_ij (wrench_body's sums)
    out[1] = -(b10 * q0 + b11 * q1)
    out[2] = -(b00 * n00 + b01 * n01 + b10 * n10 + b11 * n11)
    out[3] = q0
    out[4] = q1
    out[5] = n00
    out[6] = n01
    out[7] = n10
    out[8] = n11
    h = REL_STEP * (ext + math.hypot(cx - geo[GEO_OX], cy - geo[GEO_OY]))
    # ∂W/∂c_d (d = x, y) from the differences of Q and N'
    x0, x1, x2 = _dw_dc(edges, circles, geo, cx, cy, h, 0.0, sg, b00, b01, b10, b11)
    y0, y1, y2 = _dw_dc(edges, circles, geo, cx, cy, 0.0, h, sg, b00, b01, b10, b11)
    # ∂c/∂(vx, vy, ω): columns (0, 1/ω), (−1/ω, 0), −(c − r_G)/ω
    iw = 1.0 / omega
    gx = -(cx - xg) * iw
    gy = -(cy - yg) * iw
    out[9], out[10], out[11] = y0 * iw, -x0 * iw, x0 * gx + y0 * gy
    out[12], out[13], out[14] = y1 * iw, -x1 * iw, x1 * gx + y1 * gy
    out[15], out[16], out[17] = y2 * iw, -x2 * iw, x2 * gx + y2 * gy
    unavailable(out, 21)  # ∂W/∂G: the pressure centre moves the footprint's law (differenced)
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
