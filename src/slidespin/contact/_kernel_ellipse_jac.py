"""Compiled twist derivatives of the elliptic wrench, on the nodes of its own rule (MODEL §2, §15).

With w = ω ẑ×(r − c) about the ICR c, ŵ = w/|w| and a change δ(v, ω) of the twist (body
frame, v the velocity of G), the slip velocity changes by δw = δv + δω ẑ×(r − r_G) and

    δŵ = (I − ŵŵᵀ) δw / |w|.

On the line through c in direction ê (r = c + ρê, ρ signed, dS = |ρ| dρ dψ over a half turn)
ŵ = ±ẑ×ê, so I − ŵŵᵀ = êêᵀ, |w| = |ω||ρ|, and ê·δw = ê·δw_c does not depend on ρ
(ê·(ẑ×ê) = 0), δw_c = δv + δω ẑ×(c − r_G) being the change of velocity at the ICR. The
factor |ρ| cancels, and with the isotropic integrals Q = ∫ p ŵ dS and the tensor 𝔽 (F = −𝔽Q):

    δF = −(1/|ω|) 𝔽 ∫ ê (ê·δw_c) K₀ dψ,
    δM = −(1/|ω|) ∫ (ê·δw_c) [((m_r − r_G) K₀ + ê J₁) × 𝔽ê] dψ,

K₀ = ∫ p dx and J₁ = ∫ p x dx the chord moments one order below the wrench's K₁, K₂
(:func:`slidespin.contact._kernel_ellipse_lines.chord_moments`; J₁ = 0 but for the linear
law). ê·δw_c = a·δ(vx, vy, ω) with a = (ê_x, ê_y, −ê×(c − r_G)), all O(1) on the lines that
meet the patch however far the ICR is. The integrands have the branch points of the wrench's
own (K₀ ∝ h like K₁ ∝ hm), so the derivative is summed with the wrench's accepted rule, on its
nodes, and its error estimated from the same nested sums (:func:`jacobian_body`); after the
adaptive fallback, with the Gauss–Kronrod nodes of its final partition. The 1/|ρ|
singularity of δŵ at the ICR is integrable and has cancelled analytically: nothing is
differenced. Checks: the Jacobian annihilates the twist itself (the wrench is homogeneous of
degree 0; a·(v, ω) = 0 node by node) and, for an isotropic 𝔽, ∂F/∂v is symmetric.

A pure translation (ω = 0, or the ICR beyond ``FAR_ICR``) is closed form: δF = −𝔽 P⊥ δv/|v|
with P⊥ = I − v̂v̂ᵀ, and δM = −(δω/|v|) Σ_ab Σ_ab e_a × 𝔽P⊥ẑ×e_b with Σ = ∫ p (r − r_G)(r −
r_G)ᵀ dS, the pressure's second moment about G. After the adaptive Gauss–Kronrod fallback
(the ICR within ~1e-4 a of the rim) the derivative is summed on its final partition
(:mod:`slidespin.contact._kernel_ellipse_adaptive`). Where an estimate misses
``DERIVATIVE_TOL`` (the derivative needs far less than the wrench's 1e-14, but its integrands
converge more slowly: with the ICR a few per cent inside the rim of an elongated ellipse, the
rule accepted for the wrench at 1e-12 can leave the derivative at 1e-8; the rule is therefore
chosen for a target ``JACOBIAN_TOL_FACTOR`` times the wrench's, which one size up avoids most
misses) the rule runs again at targets 100 times tighter each (``RETRY_FACTOR``), down to
1e-16; if it still misses, the derivative
is reported unavailable (the caller differences).

Also returned, the wrench's isotropic parts Q and N (M = −Σ 𝔽_ij N_ij), which make its
derivatives with respect to the tensor entries and the body angle exact (𝔽 enters linearly).
Units: a = 1, P = 1, as the kernel.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._jacobian import JAC_SIZE, unavailable, world_from_body
from slidespin.contact._kernel_ellipse import (
    FAR_ICR,
    STATUS_OK,
    WORKSPACE_SHAPE,
    tensor_in_body,
    wrench_rule,
)
from slidespin.contact._kernel_ellipse_lines import DROW, LAW_BOUSSINESQ, LAW_HERTZ, NROWS
from slidespin.contact._kernel_ellipse_rules import (
    _CC_INDEX,
    _CC_OFFSETS,
    _CC_W1,
    _CC_W2,
    _CC_W4,
    METHOD_CLENSHAW_CURTIS,
    METHOD_CLENSHAW_CURTIS_INSIDE,
    METHOD_CLENSHAW_CURTIS_MAPPED,
    _estimate,
)

__all__ = [
    "JAC_WORKSPACE_SHAPE",
    "NROWS",
    "jacobian_body",
    "jacobian_world",
    "jac_workspace",
]

#: relative error target of the derivative's sums (of their largest entry); above it the
#: derivative is reported unavailable
DERIVATIVE_TOL = 1e-9
#: the rule is chosen for the wrench's target × JACOBIAN_TOL_FACTOR: the derivative's
#: integrands converge at the wrench's rate with a larger constant, and a rule one size up
#: avoids most re-runs (below) with the ICR near the rim (measured on the paper's ellipse
#: under the linear law: 1.74 -> 1.20 us per Jacobian; elsewhere within 3 %)
JACOBIAN_TOL_FACTOR = 0.3
#: where the accepted rule's derivative misses DERIVATIVE_TOL, the rule runs again at its
#: target × RETRY_FACTOR, down to RETRY_TOL_MIN, at most RETRY_MAX times
RETRY_FACTOR = 1e-2
RETRY_TOL_MIN = 1e-16
RETRY_MAX = 3


#: shape of the derivative workspace: the wrench's rows, a row per derivative integrand over
#: the rule's nodes, and a last column for the sums
JAC_WORKSPACE_SHAPE = (DROW + NROWS, WORKSPACE_SHAPE[1] + 1)


def jac_workspace():
    """A workspace for :func:`jacobian_body` (one per thread, reused; it serves the plain
    wrench too)."""
    return np.empty(JAC_WORKSPACE_SHAPE)


@jit(error_model="numpy", inline="always")
def _second_moment(law, s22, xg, yg):
    """Σ = ∫ p (r − r_G)(r − r_G)ᵀ dS for P = 1, a = 1 (the linear law's odd part adds
    nothing to ∫ p r rᵀ): (Σxx, Σxy, Σyy)."""
    c = 0.25
    if law == LAW_BOUSSINESQ:
        c = 1.0 / 3.0
    elif law == LAW_HERTZ:
        c = 0.2
    return c - xg * xg, -xg * yg, c / s22 - yg * yg


@jit(error_model="numpy")
def _rule_sums(W, n, cc, half):
    """The rows' sums with the rule's weights (trapezoid over a period π, or Clenshaw–Curtis
    on ``half``) into the last column of ``W``; returns the largest nested error estimate of
    the derivative rows (6 on) relative to their largest sum (rows 0–5 are the wrench's own
    integrands, whose error the kernel has checked). One pass over each row (the trapezoid's
    nested rules are its nodes 0 mod 2 and 0 mod 4, n a multiple of 4)."""
    last = W.shape[1] - 1
    worst = 0.0
    big = 0.0
    if cc:
        # the weights sliced once (an index known to be non-negative: no wrap-around test
        # per node) and two rows at a time (six independent sums: the loop is bound by the
        # additions' latency otherwise); each row's sum in node order, as before
        o = _CC_OFFSETS[_CC_INDEX[n]]
        w1 = _CC_W1[o : o + n + 1]
        w2 = _CC_W2[o : o + n + 1]
        w4 = _CC_W4[o : o + n + 1]
        for r in range(0, 6, 2):
            a1 = b1 = 0.0
            for j in range(n + 1):
                a1 += w1[j] * W[DROW + r, j]
                b1 += w1[j] * W[DROW + r + 1, j]
            W[DROW + r, last] = half * a1
            W[DROW + r + 1, last] = half * b1
        for r in range(6, NROWS, 2):
            a1 = a2 = a4 = b1 = b2 = b4 = 0.0
            for j in range(n + 1):
                va = W[DROW + r, j]
                vb = W[DROW + r + 1, j]
                a1 += w1[j] * va
                a2 += w2[j] * va
                a4 += w4[j] * va
                b1 += w1[j] * vb
                b2 += w2[j] * vb
                b4 += w4[j] * vb
            for rr, s1, s2, s4 in ((r, a1, a2, a4), (r + 1, b1, b2, b4)):
                W[DROW + rr, last] = half * s1
                big = max(big, abs(half * s1))
                worst = max(worst, _estimate(half * abs(s2 - s4), half * abs(s1 - s2)))
    else:
        h = math.pi / n
        for r in range(0, NROWS, 2):  # two rows at a time: six independent sums
            a1 = a2 = a4 = b1 = b2 = b4 = 0.0
            for j in range(0, n, 4):
                a4 += W[DROW + r, j]
                a1 += W[DROW + r, j + 1]
                a2 += W[DROW + r, j + 2]
                a1 += W[DROW + r, j + 3]
                b4 += W[DROW + r + 1, j]
                b1 += W[DROW + r + 1, j + 1]
                b2 += W[DROW + r + 1, j + 2]
                b1 += W[DROW + r + 1, j + 3]
            for rr, s1, s2, s4 in ((r, a1, a2, a4), (r + 1, b1, b2, b4)):
                t1 = h * (s1 + s2 + s4)
                W[DROW + rr, last] = t1
                if rr >= 6:
                    t2, t4 = 2.0 * h * (s2 + s4), 4.0 * h * s4
                    big = max(big, abs(t1))
                    worst = max(worst, _estimate(abs(t2 - t4), abs(t1 - t2)))
    return worst / big if big > 0.0 else 0.0


@jit(error_model="numpy")
def _derivative_error(W, n, half, method, derr):
    """The derivative's sums (in ``W``'s last column) and their relative error estimate
    after :func:`slidespin.contact._kernel_ellipse.wrench_rule`: the adaptive fallback's
    ``derr``, or the accepted rule's (:func:`_rule_sums`); NaN if no rule ran."""
    if derr >= 0.0:  # the adaptive fallback's partition has summed them
        return derr
    if n == 0:
        return math.nan
    cc = (
        method == METHOD_CLENSHAW_CURTIS
        or method == METHOD_CLENSHAW_CURTIS_MAPPED
        or method == METHOD_CLENSHAW_CURTIS_INSIDE
    )
    return _rule_sums(W, n, cc, half)


@jit(error_model="numpy")
def jacobian_body(law, K, b00, b01, b10, b11, vx, vy, omega, tol, W, out):
    """The wrench, its isotropic parts and its twist derivatives in the body frame.

    Arguments as :func:`slidespin.contact._kernel_ellipse.wrench_fast` (body-frame tensor
    ``b``; ``W`` a :func:`jac_workspace`). Writes ``out[:18]``: (Fx, Fy, M), Q (2), N (4)
    with F = −𝔽Q and M = −Σ 𝔽_ij N_ij, and ∂(Fx, Fy, M)/∂(vx, vy, ω) row-major. Returns
    (status, available): the wrench's status and whether the derivative is there (False if
    no rule ran or its own error estimate misses ``DERIVATIVE_TOL``, at ``tol`` ×
    ``JACOBIAN_TOL_FACTOR`` and at the tighter targets of the module notes; ``out[9:]`` is
    then NaN; the wrench is that of the rule the derivative was summed on, so within
    ``tol`` or better).
    """
    s22, xg, yg = K[1], K[3], K[4]
    t = tol * JACOBIAN_TOL_FACTOR
    fx, fy, m, status, _, _, n, half, method, derr = wrench_rule(
        law, K, b00, b01, b10, b11, vx, vy, omega, t, W, W
    )
    err = _derivative_error(W, n, half, method, derr)
    for _ in range(RETRY_MAX):
        if not (err > DERIVATIVE_TOL and t > RETRY_TOL_MIN and status == STATUS_OK):
            break
        # the derivative's integrands converge more slowly than the wrench's (an ICR near
        # the rim): the rule again at a tighter target, its wrench kept for consistency
        t = max(t * RETRY_FACTOR, RETRY_TOL_MIN)
        fx, fy, m, status, _, _, n, half, method, derr = wrench_rule(
            law, K, b00, b01, b10, b11, vx, vy, omega, t, W, W
        )
        err = _derivative_error(W, n, half, method, derr)
    out[0] = fx
    out[1] = fy
    out[2] = m
    for i in range(3, JAC_SIZE):
        out[i] = 0.0  # (a translation: ∂W/∂G = 0, G stays the pressure centroid)
    if omega == 0.0 or not (abs(vx) + abs(vy)) / abs(omega) < FAR_ICR:
        speed = math.sqrt(vx * vx + vy * vy)
        if speed == 0.0:
            unavailable(out, 9)
            return status, False
        ux = vx / speed
        uy = vy / speed
        out[3] = ux
        out[4] = uy
        # P⊥ = I − v̂v̂ᵀ over |v|; δF = −𝔽 P⊥ δv / |v|
        p00 = (1.0 - ux * ux) / speed
        p01 = -ux * uy / speed
        p11 = (1.0 - uy * uy) / speed
        out[9] = -(b00 * p00 + b01 * p01)
        out[10] = -(b00 * p01 + b01 * p11)
        out[12] = -(b10 * p00 + b11 * p01)
        out[13] = -(b10 * p01 + b11 * p11)
        # δM = −(δω/|v|) Σ_ab Σ_ab e_a × 𝔽 P⊥ ẑ×e_b  (P⊥ ẑ×e_b: columns of P⊥ J)
        sxx, sxy, syy = _second_moment(law, s22, xg, yg)
        acc = 0.0
        for a_ in range(2):
            for b_ in range(2):
                sab = sxx if a_ + b_ == 0 else (syy if a_ + b_ == 2 else sxy)
                # ẑ×e_b = (−δ_b1, δ_b0)
                jx = -1.0 if b_ == 1 else 0.0
                jy = 1.0 if b_ == 0 else 0.0
                px = p00 * jx + p01 * jy
                py = p01 * jx + p11 * jy
                gx = b00 * px + b01 * py
                gy = b10 * px + b11 * py
                acc += sab * (gy if a_ == 0 else -gx)  # e_a × g
        out[17] = -acc  # (P⊥ carries the 1/|v|)
        return status, True
    if derr < 0.0 and n == 0:
        unavailable(out, 9)
        return status, False
    sums = W[DROW:, W.shape[1] - 1]
    sg = 1.0 if omega > 0.0 else -1.0  # Q = sign(ω) ∫ t̂ K₁, N likewise
    for i in range(6):
        out[3 + i] = sg * sums[i]
    if not err <= DERIVATIVE_TOL:
        unavailable(out, 9)
        return status, False
    iw = 1.0 / abs(omega)
    g00, g01, g11, g02, g12 = sums[6], sums[7], sums[8], sums[9], sums[10]
    # ∂F/∂(vx, vy, ω) = −(1/|ω|) 𝔽 G, G = [[g00, g01, g02], [g01, g11, g12]]
    out[9] = -iw * (b00 * g00 + b01 * g01)
    out[10] = -iw * (b00 * g01 + b01 * g11)
    out[11] = -iw * (b00 * g02 + b01 * g12)
    out[12] = -iw * (b10 * g00 + b11 * g01)
    out[13] = -iw * (b10 * g01 + b11 * g11)
    out[14] = -iw * (b10 * g02 + b11 * g12)
    out[15] = -iw * sums[11]
    out[16] = -iw * sums[12]
    out[17] = -iw * sums[13]
    # the pressure centre G = (ξ_G, η_G) at a fixed twist of G: the ICR moves with G
    # (∂W/∂c_x = −ω ∂W/∂vy, ∂W/∂c_y = ω ∂W/∂vx), the moment's arm (∂M/∂ξ_G = −F_y,
    # ∂M/∂η_G = F_x) and the linear law's gradient (lx = 4 ξ_G, ly = 4 η_G a²/b²)
    sw = -sg  # the wrench's factor −sign(ω)
    for r in range(3):
        out[21 + r] = -omega * out[10 + 3 * r] + 4.0 * sw * sums[14 + r]
        out[24 + r] = omega * out[9 + 3 * r] + 4.0 * s22 * sw * sums[17 + r]
    out[23] -= fy
    out[26] += fx
    return status, True


@jit(error_model="numpy", inline="always")
def jacobian_world(law, K, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol, W, out):
    """:func:`jacobian_body` in the fixed frame: the tensor (t00..t11) in its own frame (the
    plane's, or the body's with ``body_frame``), the twist of G in the fixed frame. Writes
    ``out`` (:data:`slidespin.contact._jacobian.JAC_SIZE`; the layout there): the fixed-frame
    wrench and derivatives. Returns (status, available)."""
    if out.size < JAC_SIZE or W.shape[0] < DROW + NROWS or W.shape[1] < WORKSPACE_SHAPE[1] + 1:
        # (compiled code does not check its writes)
        raise ValueError("out, W: the vector needs JAC_SIZE entries, W jac_workspace()'s shape")
    c = math.cos(phi)
    s = math.sin(phi)
    vbx = c * vx + s * vy
    vby = -s * vx + c * vy
    b00, b01, b10, b11 = tensor_in_body(t00, t01, t10, t11, body_frame, c, s)
    status, ok = jacobian_body(law, K, b00, b01, b10, b11, vbx, vby, omega, tol, W, out)
    world_from_body(out, c, s, vbx, vby, b00, b01, b10, b11, body_frame, ok)
    return status, ok
