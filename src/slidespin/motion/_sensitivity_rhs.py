"""The right-hand side of the variational equations of the regularised motion (MODEL §5, §15).

For parameters θ_k the sensitivity S_k = ∂y/∂θ_k of the state y of
:mod:`slidespin.motion._flow` follows dS_k/dτ = (∂G/∂y) S_k + ∂G/∂θ_k. Here: G with ∂G/∂y
(:func:`rhs_jacobian`), the exact ∂G/∂θ_k (:func:`parameter_rhs`, for the parameters
:func:`direct_parameters` marks), the joint right-hand side (:func:`joint_rhs`) and the terms
at the stop (:func:`stop_terms`); the collocation (:mod:`slidespin.motion._sensitivity_colloc`)
and the joint integration (:mod:`slidespin.motion._sensitivity_core`) use them.

With the wrench's exact derivatives (:func:`slidespin.contact._engine.accelerations_jacobian`:
analytic on an ellipse, :mod:`slidespin.contact._kernel_ellipse_jac`; on a footprint,
:mod:`slidespin.contact._kernel_footprint_jac`) ∂G/∂y is assembled once per
evaluation (:func:`rhs_jacobian`) and serves every parameter; ∂G/∂θ_k is exact for the
parameters that move only the tensor's entries, the radius of gyration, the pressure
centre (an ellipse's, with its law; a footprint's, with its pressure coefficients), or the
start (:func:`direct_parameters`, :func:`parameter_rhs`). For any other parameter, and at a
state where the kernel has no derivative (the elliptic quadrature's adaptive fallback when
even its tightest rule misses, a blade, a footprint's translation), the
right-hand side is the directional derivative of the flow along (S_k, e_k) in the joint
(state, parameter) space, a central difference of :func:`slidespin.motion._flow._rhs` with
the step h_k of parameter k,

    (G(y + h_k S_k; θ + h_k e_k) − G(y − h_k S_k; θ − h_k e_k)) / (2 h_k),

the perturbed parameters θ ± h_k e_k reaching the kernels as whole parameter vectors
(``pars``, rows 1 + 2k and 2 + 2k) and, for a footprint, kernel geometries (``geos``); its
error is O(h_k²), about 1e-10 of the derivative, and it costs two wrench evaluations per
parameter and stage (the exact path: one evaluation with derivatives, about three wrenches'
worth, for all parameters).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import is_none_type, jit, overload
from slidespin.contact._engine import (
    P_BODY,
    P_CSYM,
    P_K,
    P_LAW,
    P_RSYM,
    P_SHAPE,
    P_T00,
    P_T01,
    P_T10,
    P_T11,
    P_XG,
    P_YG,
    SHAPE_FOOTPRINT,
    accelerations_jacobian,
)
from slidespin.contact._kernel_ellipse import tensor_in_body
from slidespin.contact._kernel_footprint import (
    GEO_P0,
    GEO_P1,
    GEO_P2,
    GEO_XG,
    GEO_XP,
    GEO_YG,
    GEO_YP,
)
from slidespin.motion._flow import NY, _rhs, flow, unit_direction


def row_patch(fp, geos, j):
    """The patch argument for row ``j`` of the perturbed parameters: ``None`` for an ellipse,
    else the footprint's edges and circles with row ``j`` of ``geos``."""
    if fp is None:
        return None
    return (fp[0], fp[1], geos[j])


@overload(row_patch, jit_options={"error_model": "numpy"})
def _row_patch_of_type(fp, geos, j):
    if is_none_type(fp):
        return lambda fp, geos, j: None
    return lambda fp, geos, j: (fp[0], fp[1], geos[j])


@jit(error_model="numpy", inline="always")
def _projected_row(Jy, i, g0, g1, g2, u1, u2, u3, inz):
    """Row ``i`` of ∂G/∂y: its ∂G_i/∂u (g0, g1, g2) through the normalisation's projection
    P = (I − uuᵀ)/|z| into columns 0–2, the other columns zeroed (3 and 7 set after)."""
    gu = g0 * u1 + g1 * u2 + g2 * u3
    Jy[i, 0] = (g0 - gu * u1) * inz
    Jy[i, 1] = (g1 - gu * u2) * inz
    Jy[i, 2] = (g2 - gu * u3) * inz
    for j in range(3, NY):
        Jy[i, j] = 0.0


@jit(error_model="numpy", inline="always")
def rhs_jacobian(par, kc, W, jo, fp, y, out, Jy):
    """The right-hand side G(y) of :func:`slidespin.motion._flow._rhs` into ``out`` and, when
    the kernel has the wrench's exact derivatives, ∂G/∂y into ``Jy`` (NY × NY); returns
    (wrench status, available). ``jo`` keeps the kernel's derivative vector for
    :func:`parameter_rhs`."""
    u1, u2, u3, inz = unit_direction(y)
    k = par[P_K]
    a1, a2, a3, st, ok = accelerations_jacobian(par, kc, W, fp, u1, u2, u3, y[7], jo)
    ua, s, s2, r = flow(a1, a2, a3, u1, u2, u3, y[3], k, out)
    if not ok:
        return st, ok
    # dA/du: the twist is (u1, u2, u3/k) and A₃ = M/k
    ik = 1.0 / k
    d00, d01, d02 = jo[9], jo[10], jo[11] * ik
    d10, d11, d12 = jo[12], jo[13], jo[14] * ik
    d20, d21, d22 = jo[15] * ik, jo[16] * ik, jo[17] * ik * ik
    p0, p1, p2 = jo[18], jo[19], jo[20] * ik
    udphi = u1 * p0 + u2 * p1 + u3 * p2
    # ∂(u·A)/∂u_j
    c0 = a1 + u1 * d00 + u2 * d10 + u3 * d20
    c1 = a2 + u1 * d01 + u2 * d11 + u3 * d21
    c2 = a3 + u1 * d02 + u2 * d12 + u3 * d22
    # rows ∂G_i/∂u before the normalisation's projection P = (I − uuᵀ)/|z| (rows 4–8: t, x,
    # y, φ, ℓ); columns 4–6 and 8 of ∂G/∂y are zero
    sr = s2 / r if r > 0.0 else 0.0
    _projected_row(Jy, 0, d00 - u1 * c0 - ua, d01 - u1 * c1, d02 - u1 * c2, u1, u2, u3, inz)
    _projected_row(Jy, 1, d10 - u2 * c0, d11 - u2 * c1 - ua, d12 - u2 * c2, u1, u2, u3, inz)
    _projected_row(Jy, 2, d20 - u3 * c0, d21 - u3 * c1, d22 - u3 * c2 - ua, u1, u2, u3, inz)
    _projected_row(Jy, 3, c0, c1, c2, u1, u2, u3, inz)
    _projected_row(Jy, 4, 0.0, 0.0, 0.0, u1, u2, u3, inz)
    _projected_row(Jy, 5, s2, 0.0, 0.0, u1, u2, u3, inz)
    _projected_row(Jy, 6, 0.0, s2, 0.0, u1, u2, u3, inz)
    _projected_row(Jy, 7, 0.0, 0.0, s2 * ik, u1, u2, u3, inz)
    _projected_row(Jy, 8, sr * u1, sr * u2, 0.0, u1, u2, u3, inz)
    Jy[0, 7] = p0 - udphi * u1
    Jy[1, 7] = p1 - udphi * u2
    Jy[2, 7] = p2 - udphi * u3
    Jy[3, 7] = udphi
    Jy[4, 3] = s
    Jy[5, 3] = 2.0 * s2 * u1
    Jy[6, 3] = 2.0 * s2 * u2
    Jy[7, 3] = 2.0 * s2 * u3 * ik
    Jy[8, 3] = 2.0 * s2 * r
    return st, ok


@jit(error_model="numpy")
def parameter_rhs(pars, jo, u1, u2, u3, ln_s, dts, q, c, sn):
    """∂G/∂θ for a parameter that moves only the tensor's entries (by d𝔽 = (d[0], d[1];
    d[2], d[3]) per unit θ, in the tensor's own frame), the radius of gyration (by d[4]), the
    pressure centre G (by (d[5], d[6]) in the body frame) and a footprint's pressure
    coefficients (by (d[7], d[8], d[9])), d = ``dts[q]``: exact, from the wrench's isotropic
    parts and its derivatives in ``jo`` (:func:`rhs_jacobian` at the state of unit direction
    (u1, u2, u3), ln s = ``ln_s`` and angle φ, c, sn its cosine and sine; the layout of
    :mod:`slidespin.contact._jacobian`); the wrench is linear in 𝔽 (MODEL §10). Returns its
    non-zero components (0, 1, 2, 3, 7); the row is read in place (a view of it would cost a
    reference count per parameter and node)."""
    d00, d01, d10, d11, dk = dts[q, 0], dts[q, 1], dts[q, 2], dts[q, 3], dts[q, 4]
    dxg, dyg, dp0, dp1, dp2 = dts[q, 5], dts[q, 6], dts[q, 7], dts[q, 8], dts[q, 9]
    k = pars[0, P_K]
    e00, e01, e10, e11 = tensor_in_body(d00, d01, d10, d11, pars[0, P_BODY] != 0.0, c, sn)
    fbx = -(e00 * jo[3] + e01 * jo[4])  # F = −𝔽Q, M = −Σ 𝔽_ij N_ij (body frame)
    fby = -(e10 * jo[3] + e11 * jo[4])
    mm = -(e00 * jo[5] + e01 * jo[6] + e10 * jo[7] + e11 * jo[8])
    b1 = c * fbx - sn * fby
    b2 = sn * fbx + c * fby
    if dxg != 0.0 or dyg != 0.0:
        b1 += dxg * jo[21] + dyg * jo[24]
        b2 += dxg * jo[22] + dyg * jo[25]
        mm += dxg * jo[23] + dyg * jo[26]
    if dp0 != 0.0 or dp1 != 0.0 or dp2 != 0.0:  # (zero for an ellipse: G carries its law)
        b1 += dp0 * jo[27] + dp1 * jo[30] + dp2 * jo[33]
        b2 += dp0 * jo[28] + dp1 * jo[31] + dp2 * jo[34]
        mm += dp0 * jo[29] + dp1 * jo[32] + dp2 * jo[35]
    b3 = mm / k
    if dk != 0.0:
        dt = -u3 / (k * k) * dk  # the twist's ω = u3/k moves
        b1 += jo[11] * dt
        b2 += jo[14] * dt
        b3 += jo[17] * dt / k - jo[2] / (k * k) * dk
    ub = u1 * b1 + u2 * b2 + u3 * b3
    g7 = 0.0
    if dk != 0.0:
        s = math.exp(ln_s)
        g7 = -s * s * u3 / (k * k) * dk
    return b1 - ub * u1, b2 - ub * u2, b3 - ub * u3, ub, g7


@jit(error_model="numpy", inline="always")
def moved_row(dts, q):
    """Whether parameter ``q`` moves anything :func:`parameter_rhs` reads (row ``q`` of
    ``dts`` not all zero)."""
    for i in range(dts.shape[1]):
        if dts[q, i] != 0.0:
            return True
    return False


@jit(error_model="numpy", inline="always")
def joint_rhs(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, Y, out, yp, ym, gp, gm):
    """Right-hand side of the joint system (y, S₁, …, S_p) (MODEL §15); returns the number
    of wrench evaluations above their error target.

    With the wrench's exact derivatives (:func:`rhs_jacobian`), S_k' = (∂G/∂y) S_k + ∂G/∂θ_k,
    ∂G/∂θ_k exact (:func:`parameter_rhs`) for the parameters marked ``direct`` (tensor
    entries, inertia, start; ``dts[k]`` = (d𝔽, dk)); the others (the pressure centre) and
    every parameter at a state without them, by the central difference of the module notes.
    """
    npar = hs.size
    st, ok = rhs_jacobian(pars[0], kcs[0], W, jo, row_patch(fp, geos, 0), Y[:NY], out[:NY], Jy)
    fails = st
    cph = math.cos(Y[7])  # for parameter_rhs, once for all parameters
    sph = math.sin(Y[7])
    u1, u2, u3, _ = unit_direction(Y[:NY])
    for k in range(npar):
        off = NY * (k + 1)
        if ok and direct[k]:
            # ∂G/∂y has its non-zero columns at u (0–2), ln s (3) and φ (7) only
            s0, s1, s2, s3, s7 = Y[off], Y[off + 1], Y[off + 2], Y[off + 3], Y[off + 7]
            for i in range(NY):
                out[off + i] = (
                    Jy[i, 0] * s0 + Jy[i, 1] * s1 + Jy[i, 2] * s2 + Jy[i, 3] * s3 + Jy[i, 7] * s7
                )
            if moved_row(dts, k):
                g0, g1, g2, g3, g7 = parameter_rhs(pars, jo, u1, u2, u3, Y[3], dts, k, cph, sph)
                out[off] += g0
                out[off + 1] += g1
                out[off + 2] += g2
                out[off + 3] += g3
                out[off + 7] += g7
            continue
        h = hs[k]
        for i in range(NY):
            yp[i] = Y[i] + h * Y[off + i]
            ym[i] = Y[i] - h * Y[off + i]
        j = 1 + 2 * k
        fails += _rhs(pars[j], kcs[j], W, row_patch(fp, geos, j), yp, gp)
        fails += _rhs(pars[j + 1], kcs[j + 1], W, row_patch(fp, geos, j + 1), ym, gm)
        for i in range(NY):
            out[off + i] = (gp[i] - gm[i]) / (2.0 * h)
    return fails


@jit(error_model="numpy")
def direct_parameters(pars, geos, hs):
    """Which parameters move only the tensor's entries, k and the pressure centre
    (``direct``: their ∂G/∂θ is :func:`parameter_rhs`'s), and their rates per unit θ
    (d𝔽, dk, dξ_G, dη_G, and a footprint's dp₀, dp₁, dp₂): central differences of the rows,
    linear in θ for the tensor, G and p. An ellipse's G moves its law too (uniform ↔ linear:
    the kernel's formulas are the same); a footprint's moves its pressure coefficients (and
    its symmetry flags, which only the stop's classification reads)."""
    npar = hs.size
    direct = np.zeros(npar, dtype=np.bool_)
    dts = np.zeros((npar, 10))
    moved = (P_T00, P_T01, P_T10, P_T11, P_K)
    ellipse = pars[0, P_SHAPE] != SHAPE_FOOTPRINT
    for k in range(npar):
        p = pars[1 + 2 * k]
        m = pars[2 + 2 * k]
        same = True
        for i in range(pars.shape[1]):
            free = i == P_T00 or i == P_T01 or i == P_T10 or i == P_T11 or i == P_K
            if ellipse:
                free = free or i == P_XG or i == P_YG or i == P_LAW
            else:
                free = free or i == P_CSYM or i == P_RSYM
            if not free and (p[i] != pars[0, i] or m[i] != pars[0, i]):
                same = False
        gp = geos[1 + 2 * k]
        gm = geos[2 + 2 * k]
        for i in range(geos.shape[1]):
            free = not ellipse and (
                i == GEO_P0 or i == GEO_P1 or i == GEO_P2 or i == GEO_XG or i == GEO_YG
                or i == GEO_XP or i == GEO_YP
            )  # fmt: skip
            if not free and (gp[i] != geos[0, i] or gm[i] != geos[0, i]):
                same = False
        direct[k] = same
        h2 = 2.0 * hs[k]
        for i in range(5):
            dts[k, i] = (p[moved[i]] - m[moved[i]]) / h2
        if ellipse:
            dts[k, 5] = (p[P_XG] - m[P_XG]) / h2
            dts[k, 6] = (p[P_YG] - m[P_YG]) / h2
        else:
            dts[k, 5] = (gp[GEO_XG] - gm[GEO_XG]) / h2
            dts[k, 6] = (gp[GEO_YG] - gm[GEO_YG]) / h2
            dts[k, 7] = (gp[GEO_P0] - gm[GEO_P0]) / h2
            dts[k, 8] = (gp[GEO_P1] - gm[GEO_P1]) / h2
            dts[k, 9] = (gp[GEO_P2] - gm[GEO_P2]) / h2
    return direct, dts


@jit(error_model="numpy")
def stop_terms(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, y):
    """∂G/∂y (rows 0..NY−1, NaN where the kernel has no exact derivatives) and ∂G/∂θ_k (row
    NY + k) at the state ``y``: for the implicit-function theorem at the terminal direction
    (:func:`slidespin.motion.sensitivity._terminal_sensitivity`)."""
    npar = hs.size
    n = NY * (1 + npar)
    term = np.full((NY + npar, NY), np.nan)
    Y = np.zeros(n)
    Y[:NY] = y
    out = np.empty(n)
    joint_rhs(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, Y, out,
              np.empty(NY), np.empty(NY), np.empty(NY), np.empty(NY))  # fmt: skip
    if math.isfinite(jo[9]):  # the kernel's derivatives were there: Jy is ∂G/∂y at y
        term[:NY] = Jy
    for k in range(npar):
        term[NY + k] = out[NY * (k + 1) : NY * (k + 2)]
    return term
