"""The layout of the wrench kernels' derivative vector and its turn into the fixed frame
(MODEL §2, §15), shared by :mod:`slidespin.contact._kernel_ellipse_jac` and
:mod:`slidespin.contact._kernel_footprint_jac`.

A kernel's body-frame derivative fills ``out[:18]`` of a vector of :data:`JAC_SIZE`:
(Fx, Fy, M); the isotropic parts Q (2) and N (4) with F = −𝔽Q and M = −Σ 𝔽_ij N_ij (the
wrench is linear in the tensor, MODEL §10); ∂(Fx, Fy, M)/∂(vx, vy, ω) row-major; and in
``out[21:27]`` ∂(Fx, Fy, M)/∂ξ_G, ∂/∂η_G, the derivatives with respect to the pressure centre
G in the body frame at a fixed twist of G (NaN where the kernel has none): for an ellipse
the whole change (the linear law follows G), for a footprint at fixed pressure coefficients
(the ICR moves with G, and the moment's arm), whose own derivatives ∂(Fx, Fy, M)/∂p₀, ∂/∂p₁,
∂/∂p₂ (p = p₀ + p₁ξ + p₂η in the kernel's units) follow in ``out[27:36]`` (zero for an
ellipse). :func:`world_from_body` turns it into the fixed frame and adds ∂(Fx, Fy, M)/∂φ
(``out[18:21]``).
"""

from __future__ import annotations

import math

from slidespin._jit import jit

__all__ = ["JAC_SIZE", "unavailable", "world_from_body"]

#: length of the derivative vector: W (3), Q (2), N (4), ∂W/∂(vx, vy, ω) (9), ∂W/∂φ (3),
#: ∂W/∂(ξ_G, η_G) (6), ∂W/∂(p₀, p₁, p₂) (9)
JAC_SIZE = 36


@jit(error_model="numpy", inline="always")
def unavailable(out, start):
    """Mark the derivative entries from ``start`` on as unavailable (NaN)."""
    for i in range(start, JAC_SIZE):
        out[i] = math.nan


@jit(error_model="numpy")
def world_from_body(out, c, s, vbx, vby, b00, b01, b10, b11, body_frame, available):
    """Turn a body-frame derivative vector (twist (vbx, vby, ω) in the body frame, tensor
    ``b`` in the body frame, the body at angle φ with c = cos φ, s = sin φ) into the fixed
    frame: the force and, if ``available``, the twist derivatives and ∂W/∂φ at a fixed world
    twist and tensor (the tensor's own frame: the plane's unless ``body_frame``); else they
    are marked unavailable."""
    fbx, fby = out[0], out[1]
    out[0] = c * fbx - s * fby
    out[1] = s * fbx + c * fby
    if not available:
        unavailable(out, 9)
        return
    j00, j01, j02 = out[9], out[10], out[11]
    j10, j11, j12 = out[12], out[13], out[14]
    m0, m1, m2 = out[15], out[16], out[17]
    # ∂/∂φ: v_b turns by −φ (δv_b = −ẑ×v_b δφ), F_w = R F_b, and a plane-frame tensor turns
    # in the body frame (δ𝔽_b = (𝔽_b J − J 𝔽_b) δφ, J = [[0, −1], [1, 0]])
    dvx = vby
    dvy = -vbx
    dfx = j00 * dvx + j01 * dvy - fby  # + J F_b
    dfy = j10 * dvx + j11 * dvy + fbx
    dm = m0 * dvx + m1 * dvy
    if not body_frame:
        d00 = b01 + b10
        d01 = -b00 + b11
        d10 = b11 - b00
        d11 = -b10 - b01
        qx, qy = out[3], out[4]
        dfx -= d00 * qx + d01 * qy
        dfy -= d10 * qx + d11 * qy
        dm -= d00 * out[5] + d01 * out[6] + d10 * out[7] + d11 * out[8]
    out[18] = c * dfx - s * dfy
    out[19] = s * dfx + c * dfy
    out[20] = dm
    # ∂F_w/∂v_w = R (∂F_b/∂v_b) Rᵀ, ∂F_w/∂ω = R ∂F_b/∂ω, ∂M/∂v_w = (∂M/∂v_b) Rᵀ
    a00 = j00 * c - j01 * s
    a01 = j00 * s + j01 * c
    a10 = j10 * c - j11 * s
    a11 = j10 * s + j11 * c
    out[9] = c * a00 - s * a10
    out[10] = c * a01 - s * a11
    out[12] = s * a00 + c * a10
    out[13] = s * a01 + c * a11
    out[11] = c * j02 - s * j12
    out[14] = s * j02 + c * j12
    out[15] = m0 * c - m1 * s
    out[16] = m0 * s + m1 * c
    out[17] = m2
    for i in (21, 24, 27, 30, 33):  # ∂F/∂G, ∂F/∂p: turned like F
        gx, gy = out[i], out[i + 1]
        out[i] = c * gx - s * gy
        out[i + 1] = s * gx + c * gy
