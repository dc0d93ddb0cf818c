"""The integrand and the tabulated quadrature rules of the elliptic wrench (compiled).

The kernel proper (:mod:`slidespin.contact._kernel_ellipse`) chooses a rule and its node count
per state, runs it (:func:`_run_rule`, here), checks its error and falls back to adaptive
Gauss–Kronrod; what it runs lives here: the line integrand, the node and weight tables, the
vectorised passes over the nodes, the nested sums and their error estimate, and where the
integrand's singularities lie (the distances that fix the node count).

Method (MODEL §2–3; the paper's route, eq. 8–9 and 12–13, is not used here)
--------------------------------------------------------------------------
For ω ≠ 0 every patch point r moves with w = ω ẑ×(r − c) about the instantaneous centre of
rotation (ICR) c. On the straight line through c in direction ê(ψ), r = c + ρ ê with ρ signed,
the slip direction is sign(ωρ) t̂(ψ), t̂ = ẑ×ê, and the area element is |ρ| dρ dψ for ψ over a
half turn. The sign of ρ cancels against |ρ|, so with whole lines instead of rays

    F = −sign(ω) ∫ 𝔽 t̂ K₁(ψ) dψ,
    M = −sign(ω) ∫ [ (m_r − r_G) × 𝔽t̂ · K₁ + ê × 𝔽t̂ · K₂ ] dψ,       ψ over a half turn,

where m_r is the midpoint of the chord that the line cuts from the ellipse, x the position on
the chord measured from m_r, m = (m_r − c)·ê, h the half chord, and

    K₁ = ∫ p (m + x) dx,      K₂ = ∫ p (m + x) x dx        over the whole chord −h ≤ x ≤ h.

Along the chord 1 − q = A (h² − x²) with A = ê·S·ê, S = diag(1, a²/b²), so the chord moments
are elementary for all four laws, with no case split at the ICR (κ = b/a):

    uniform      K₁ = 2hm/(πκ),               K₂ = 2h³/(3πκ)
    linear       the same with the weight l₀ + l₁x of the pressure along the chord
    Boussinesq   K₁ = m/(2κ√A),               K₂ = h²/(4κ√A)
    Hertz        K₁ = 3√A m h²/(4κ),          K₂ = 3√A h⁴/(16κ)

Writing the moment about the chord midpoint keeps every term O(patch size), so nothing
cancels when the ICR is far. One angular quadrature is left. Its integrand is analytic, and
where its complex singularities lie is known in closed form:

* h² = D/A² with D(ψ) = ê·Q·ê (``_q_form``) vanishes on lines tangent to the ellipse.
  Boussinesq and Hertz depend on h² only, so D = 0 is no singularity for them; uniform and
  linear carry h = √D/A, a square-root branch point. With the ICR inside, Q is positive
  definite and D's complex zeros lie at ψ₁ ± i atanh(√(λ₁/λ₂)) (λ₁ ≤ λ₂ its eigenvalues, ψ₁
  the direction of λ₁): close to the real axis when the ICR is near the rim.
* A(ψ) = 0 at tan ψ = ±iκ, a branch point for every law, at distance atanh(κ) (atanh(1/κ)
  for κ > 1) from the real axis.

Quadrature rules, chosen per state by the cost the rules below predict:

* ICR inside (q(c) ≤ 1): the integrand is π-periodic and analytic in a strip |Im ψ| < d, so
  the trapezoid rule converges geometrically (Trefethen & Weideman, SIAM Rev. 56 (2014) 385,
  Thm 3.2: error ≤ 4πM/(e^{2dN} − 1) for N nodes over the period π). The map
  tan ψ = √κ tan ψ' moves the A-points (and its own singularities) to atanh(√κ), which pays
  for thin ellipses; D's zeros are mapped exactly (``_mapped_strip``). For uniform and linear
  pressure near the rim D's zeros approach the real axis at ψ₁: Clenshaw–Curtis over
  [ψ₁, ψ₁ + π] puts them at the ends of the interval, where its nodes cluster.
* ICR outside: the lines that meet the patch fill the sector between the two tangents.
  Boussinesq and Hertz are analytic on it and across its ends: Clenshaw–Curtis in the angle.
  Uniform and linear vanish like √ at both ends: with α = ᾱ + Δ sin s the integrand is a
  smooth 2π-periodic function of s, and the trapezoid rule in s (Gauss–Chebyshev of the
  second kind in α) converges geometrically. A wide sector is also tried in the mapped angle.
  For a rule on an interval the rate is log ρ = |Im acos(w)| for the singularity w (scaled to
  [−1, 1]) nearest to it (Bernstein ellipse; Trefethen, ATAP ch. 19), and a
  pseudo-singularity at a fixed height stands for the growth of the trigonometric factors.

Node rule: N = ⌈(ln(‖𝔽‖ max(κ, 1/κ)/tol) + C)/(γ d)⌉ rounded up to a tabulated size, with
d the distance above, ‖𝔽‖ the Frobenius norm of the tensor, γ = 2 for the trapezoid rules and
1.5 for Clenshaw–Curtis, and C = 8 calibrated on ~5 600 random states (aspect ratios
0.05-3, ICR anywhere, all laws and tensors) against an independent adaptive quadrature:
above the 99th percentile of the constant each state needs for 1e-12, so that the rule
under-counts in under 1 % of the states (docs/benchmarks.md). All rules are
nested, so T_N, T_{N/2} and T_{N/4} come from the same nodes; the error of T_N is estimated
as e₂³/e₁² (e₂ = |T_N − T_{N/2}|, e₁ = |T_{N/2} − T_{N/4}|, exact for geometric convergence)
and checked against ``tol``. If the check fails, N is doubled; beyond ``MAX_NODES`` nodes
(ICR within ~1e-4 a of the rim with uniform or linear pressure, or b/a below ~5e-3) globally
adaptive Gauss–Kronrod 7/15 takes over, split at ψ₁ (in the kernel,
:mod:`slidespin.contact._kernel_ellipse`).

Speed: nodes come from tables, and each rule runs as three loops over its nodes (directions,
line integrands, weighted sums), the first two free of calls and data-dependent branches so
that the compiler vectorises them; trigonometric functions of non-tabulated angles are
evaluated by a polynomial on [−π/2, π/2].

Units: lengths in units of the semi-axis a (a = 1), load P = 1.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._kernel_ellipse_lines import (
    _lines,
    lines_and_derivatives,
)

# quadrature used (returned by ``wrench_body_info``)
METHOD_TRANSLATION = 0
METHOD_TRAPEZOID = 1  # ICR inside, trapezoid over a half turn (plain angle)
METHOD_TRAPEZOID_MAPPED = 2  # ICR inside, trapezoid in the √κ-mapped angle
METHOD_SINE = 3  # ICR outside, uniform/linear: trapezoid in s, α = ᾱ + Δ sin s
METHOD_SINE_MAPPED = 4
METHOD_CLENSHAW_CURTIS = 5  # ICR outside, Boussinesq/Hertz: Clenshaw–Curtis in α
METHOD_CLENSHAW_CURTIS_MAPPED = 6
METHOD_CLENSHAW_CURTIS_INSIDE = 7  # ICR inside near the rim, uniform/linear
METHOD_ADAPTIVE_INSIDE = 8  # fallback: adaptive Gauss–Kronrod
METHOD_ADAPTIVE_OUTSIDE = 9
METHOD_NAMES = (
    "translation",
    "trapezoid",
    "trapezoid-mapped",
    "sine-trapezoid",
    "sine-trapezoid-mapped",
    "clenshaw-curtis",
    "clenshaw-curtis-mapped",
    "clenshaw-curtis-inside",
    "adaptive-inside",
    "adaptive-outside",
)

#: node counts of the tabulated rules (each doubling stays in the table up to MAX_NODES)
NODE_SIZES = (8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256)
CC_SIZES = (8, 16, 24, 32, 48, 64, 96, 128, 192, 256)  # N/4 must be even
MAX_NODES = 256
#: constants of the node rule N = ⌈(ln(‖𝔽‖/tol) + C)/(γ d)⌉ (see the module notes)
C_TRAPEZOID = 8.0
C_SINE = 8.0
C_CC = 8.0
GAMMA_TRAPEZOID = 2.0
GAMMA_CC = 1.5
#: height of the pseudo-singularity that stands for the growth of the trigonometric factors
#: of the integrand off the real axis (rad), for the sine-trapezoid and Clenshaw–Curtis rules
#: (Boussinesq and Hertz carry powers h², h⁴ of the chord, hence the lower height)
ENTIRE_HEIGHT_SINE = 1.0
ENTIRE_HEIGHT_CC = 0.5
MIN_NODES = 8.0
MIN_NODES_CC = 16.0
#: relative cost per node of the rules (table directions = 1), for choosing among them
COST_MAPPED = 1.2
COST_ROTATED = 1.5
#: the √κ map is tried for a sector wider than this half-width (rad); narrow sectors (far
#: ICR) stay in the angle measured from the direction to the centre, which keeps full
#: relative precision of the sector width
MAP_MIN_HALF_WIDTH = 0.2


def _node_tables():
    """cos(jπ/N), sin(jπ/N), j = 0..N, for N in NODE_SIZES, concatenated; index by N."""
    index = -np.ones(MAX_NODES + 1, dtype=np.int64)
    offsets = []
    cs, sn = [], []
    o = 0
    for n in NODE_SIZES:
        t = np.arange(n + 1) * np.pi / n
        c = np.cos(t)
        s = np.sin(t)
        c[n] = -1.0
        s[n] = 0.0
        if n % 2 == 0:
            c[n // 2] = 0.0
            s[n // 2] = 1.0
        index[n] = len(offsets)
        offsets.append(o)
        cs.append(c)
        sn.append(s)
        o += n + 1
    return index, np.array(offsets, dtype=np.int64), np.concatenate(cs), np.concatenate(sn)


def _cc_weights(n):
    """Clenshaw–Curtis weights on [−1, 1] for the nodes cos(jπ/n), j = 0..n (n even)."""
    j = np.arange(n + 1)
    theta = j * np.pi / n
    k = np.arange(1, n // 2 + 1)
    b = np.where(2 * k == n, 1.0, 2.0)
    w = 1.0 - (b / (4.0 * k * k - 1.0) * np.cos(2.0 * np.outer(theta, k))).sum(axis=1)
    return w * np.where((j == 0) | (j == n), 1.0, 2.0) / n


def _cc_tables():
    """For each N in CC_SIZES, the weights of the rules with N, N/2 and N/4 intervals on the
    nodes of the N rule (zero where a coarser rule has no node), concatenated (N + 1 each)."""
    w1, w2, w4 = [], [], []
    index = -np.ones(MAX_NODES + 1, dtype=np.int64)
    offsets = []
    o = 0
    for n in CC_SIZES:
        a = _cc_weights(n)
        b = np.zeros(n + 1)
        b[::2] = _cc_weights(n // 2)
        c = np.zeros(n + 1)
        c[::4] = _cc_weights(n // 4)
        w1.append(a)
        w2.append(b)
        w4.append(c)
        index[n] = len(offsets)
        offsets.append(o)
        o += n + 1
    return (
        index,
        np.array(offsets, dtype=np.int64),
        np.concatenate(w1),
        np.concatenate(w2),
        np.concatenate(w4),
    )


_NODE_INDEX, _NODE_OFFSETS, _COS, _SIN = _node_tables()
_CC_INDEX, _CC_OFFSETS, _CC_W1, _CC_W2, _CC_W4 = _cc_tables()
_NODE_SIZES = np.array(NODE_SIZES, dtype=np.int64)
_CC_SIZES = np.array(CC_SIZES, dtype=np.int64)


# ---------------------------------------------------------------------------------------------
# vectorised passes over the nodes of a rule; the work array W has rows
# 0 ex, 1 ey, 2 c·ê, 3 ê×c, 4 dψ/dθ (times any weight function), 5 Fx, 6 Fy, 7 M


@jit(error_model="numpy", inline="always")
def _dirs_table(W, o, n, k, cx, cy):
    """Directions of the tabulated angles jπ/n (j < n): ψ itself (k = 1) or the √κ-mapped
    angle ψ' with tan ψ = k tan ψ'."""
    if k == 1.0:
        for j in range(n):
            ex = _COS[o + j]
            ey = _SIN[o + j]
            W[0, j] = ex
            W[1, j] = ey
            W[2, j] = cx * ex + cy * ey
            W[3, j] = ex * cy - ey * cx
            W[4, j] = 1.0
    else:
        for j in range(n):
            c = _COS[o + j]
            s = k * _SIN[o + j]
            ir = 1.0 / math.sqrt(c * c + s * s)
            ex = c * ir
            ey = s * ir
            W[0, j] = ex
            W[1, j] = ey
            W[2, j] = cx * ex + cy * ey
            W[3, j] = ex * cy - ey * cx
            W[4, j] = k * ir * ir


@jit(error_model="numpy", inline="always")
def _sincos(t):
    """(cos t, sin t) by Taylor polynomials for |t| ≤ π/2 (truncation < 1e-18; vectorisable,
    unlike the library functions)."""
    t2 = t * t
    s = 1.0 + t2 * (
        -0.16666666666666666
        + t2
        * (
            0.008333333333333333
            + t2
            * (
                -0.0001984126984126984
                + t2
                * (
                    2.7557319223985893e-06
                    + t2
                    * (
                        -2.505210838544172e-08
                        + t2
                        * (
                            1.6059043836821613e-10
                            + t2
                            * (
                                -7.647163731819816e-13
                                + t2
                                * (
                                    2.8114572543455206e-15
                                    + t2 * (-8.22063524662433e-18 + t2 * (1.9572941063391263e-20))
                                )
                            )
                        )
                    )
                )
            )
        )
    )
    c = 1.0 + t2 * (
        -0.5
        + t2
        * (
            0.041666666666666664
            + t2
            * (
                -0.001388888888888889
                + t2
                * (
                    2.48015873015873e-05
                    + t2
                    * (
                        -2.755731922398589e-07
                        + t2
                        * (
                            2.08767569878681e-09
                            + t2
                            * (
                                -1.1470745597729725e-11
                                + t2
                                * (
                                    4.779477332387385e-14
                                    + t2
                                    * (
                                        -1.5619206968586225e-16
                                        + t2
                                        * (4.110317623312165e-19 + t2 * (-8.896791392450574e-22))
                                    )
                                )
                            )
                        )
                    )
                )
            )
        )
    )
    return c, s * t


@jit(error_model="numpy", inline="always")
def _dirs_rotated(W, o, n, sine, mode, mid, half, k, cx, cy, ecx, ecy, dist):
    """Directions of the angles θ_j = mid + half·cos(jπ/n), j = 0..n (Clenshaw–Curtis nodes;
    with ``sine`` the weight half·sin(jπ/n) of the sine substitution goes into row 4).

    ``mode`` 0: θ = α measured from ê_c, the direction from the ICR to the patch centre; as
    c = −d ê_c, c·ê = −d cos α and ê×c = d sin α keep full relative precision for a far ICR.
    ``mode`` 1: θ is the √κ-mapped angle ψ'. ``mode`` 2: θ = ψ.
    """
    cm = math.cos(mid)
    sm = math.sin(mid)
    ws = half if sine else 0.0
    w0 = 0.0 if sine else 1.0
    for j in range(n + 1):
        ct, st = _sincos(half * _COS[o + j])
        W[0, j] = cm * ct - sm * st  # cos θ, sin θ
        W[1, j] = sm * ct + cm * st
        W[4, j] = ws * _SIN[o + j] + w0
    if mode == 0:
        for j in range(n + 1):
            ca = W[0, j]
            sa = W[1, j]
            W[0, j] = ca * ecx - sa * ecy
            W[1, j] = ca * ecy + sa * ecx
            W[2, j] = -dist * ca
            W[3, j] = dist * sa
    else:
        if mode == 1:
            for j in range(n + 1):
                c = W[0, j]
                s = k * W[1, j]
                ir = 1.0 / math.sqrt(c * c + s * s)
                W[0, j] = c * ir
                W[1, j] = s * ir
                W[4, j] *= k * ir * ir
        for j in range(n + 1):
            ex = W[0, j]
            ey = W[1, j]
            W[2, j] = cx * ex + cy * ey
            W[3, j] = ex * cy - ey * cx


@jit(error_model="numpy", inline="always")
def _sums_trapezoid(W, n, h):
    """Trapezoid sums h Σ over nodes 0..n−1 and the nested differences (e₁, e₂)."""
    x1 = y1 = m1 = x2 = y2 = m2 = x4 = y4 = m4 = 0.0
    for j in range(n):
        if j % 2 == 1:
            x1 += W[5, j]
            y1 += W[6, j]
            m1 += W[7, j]
        elif j % 4 == 2:
            x2 += W[5, j]
            y2 += W[6, j]
            m2 += W[7, j]
        else:
            x4 += W[5, j]
            y4 += W[6, j]
            m4 += W[7, j]
    # T_N = h(S4 + S2 + S1), T_{N/2} = 2h(S4 + S2), T_{N/4} = 4h S4
    e2 = h * max(abs(x1 - x2 - x4), abs(y1 - y2 - y4), abs(m1 - m2 - m4))
    e1 = 2.0 * h * max(abs(x2 - x4), abs(y2 - y4), abs(m2 - m4))
    return h * (x1 + x2 + x4), h * (y1 + y2 + y4), h * (m1 + m2 + m4), e1, e2


@jit(error_model="numpy", inline="always")
def _sums_cc(W, n, half):
    """Clenshaw–Curtis sums over nodes 0..n with the N, N/2 and N/4 weights; (e₁, e₂)."""
    o = _CC_OFFSETS[_CC_INDEX[n]]
    c1 = _CC_W1[o : o + n + 1]  # (sliced: an index known to be non-negative)
    c2 = _CC_W2[o : o + n + 1]
    c4 = _CC_W4[o : o + n + 1]
    x1 = y1 = m1 = x2 = y2 = m2 = x4 = y4 = m4 = 0.0
    for j in range(n + 1):
        w1 = c1[j]
        w2 = c2[j]
        w4 = c4[j]
        x1 += w1 * W[5, j]
        y1 += w1 * W[6, j]
        m1 += w1 * W[7, j]
        x2 += w2 * W[5, j]
        y2 += w2 * W[6, j]
        m2 += w2 * W[7, j]
        x4 += w4 * W[5, j]
        y4 += w4 * W[6, j]
        m4 += w4 * W[7, j]
    e2 = half * max(abs(x1 - x2), abs(y1 - y2), abs(m1 - m2))
    e1 = half * max(abs(x2 - x4), abs(y2 - y4), abs(m2 - m4))
    return half * x1, half * y1, half * m1, e1, e2


@jit(error_model="numpy", inline="always")
def _estimate(e1, e2):
    """Error of T_N from e₂ = |T_N − T_{N/2}| and e₁ = |T_{N/2} − T_{N/4}|: e₂³/e₁², exact for
    geometric convergence; e₂ itself when the rules do not converge."""
    if e2 == 0.0:
        return 0.0
    if e1 <= e2:
        return e2
    q = e2 / e1
    return e2 * q * q


# singularity distances and node rules


@jit(error_model="numpy", inline="always")
def _atanh_sym(x):
    """atanh(min(x, 1/x)) for x > 0: |Im| of the roots of tan z = ±i x (inf for x = 1)."""
    if x > 1.0:
        x = 1.0 / x
    if x >= 1.0:
        return math.inf
    return math.atanh(x)


@jit(error_model="numpy", inline="always")
def _log_rho(zr, zi, mid, half):
    """log ρ of the Bernstein ellipse of [mid − half, mid + half] through z = zr + i zi."""
    wr = (zr - mid) / half
    wi = zi / half
    s = 0.5 * (math.sqrt((wr - 1.0) ** 2 + wi * wi) + math.sqrt((wr + 1.0) ** 2 + wi * wi))
    if s <= 1.0:
        return 0.0
    return math.log(s + math.sqrt((s - 1.0) * (s + 1.0)))  # acosh s


@jit(error_model="numpy", inline="always")
def _mapped_strip(c2, s2, r, k):
    """x with |Im ψ'| = ¼ log1p(x) for tan ψ' = tan(ψ₁ + i atanh r)/k: the image under the √κ
    map of D's complex zeros (c2, s2 = cos 2ψ₁, sin 2ψ₁). Returning x lets the caller skip
    the logarithm when the point is farther than the A-points anyway."""
    cc = 0.5 * (1.0 + c2)  # cos²ψ₁, sin²ψ₁, sin ψ₁ cos ψ₁
    ss = 0.5 * (1.0 - c2)
    den = k * (cc + ss * r * r)
    x = 0.5 * s2 * (1.0 - r * r) / den
    y = r / den
    q = x * x + (1.0 - y) * (1.0 - y)
    if q == 0.0:
        return math.inf
    return 4.0 * y / q


@jit(error_model="numpy")
def _count(logterm, c, gamma, d, sizes, least):
    """Smallest size in ``sizes`` ≥ max(⌈(logterm + c)/(γ d)⌉, least); −1 if none."""
    if not d > 0.0:
        return -1
    x = (logterm + c) / (gamma * d)
    if x > MAX_NODES:
        return -1
    n = max(x, least)
    for i in range(sizes.size):
        if sizes[i] >= n:
            return sizes[i]
    return -1


@jit(error_model="numpy", inline="always")
def _q_form(s22, cx, cy):
    """D(ψ) = ê·Q·ê: eigenvalues λ₁ ≤ λ₂ of Q (λ₁ = det/λ₂, stable near the rim) and cos 2ψ₁,
    sin 2ψ₁ of the eigendirection ψ₁ of λ₁."""
    q11 = 1.0 - s22 * cy * cy
    q22 = s22 * (1.0 - cx * cx)
    q12 = s22 * cx * cy
    mean = 0.5 * (q11 + q22)
    hd = 0.5 * (q11 - q22)
    rad = math.sqrt(hd * hd + q12 * q12)
    det = s22 * (1.0 - cx * cx - s22 * cy * cy)
    lam2 = mean + rad
    lam1 = det / lam2 if lam2 != 0.0 else mean - rad
    if rad == 0.0:
        return lam1, lam2, 1.0, 0.0
    return lam1, lam2, -hd / rad, -q12 / rad


@jit(error_model="numpy")
def _out_distance(lo, hi, y, re0, step, branch, enough, entire):
    """Smallest log ρ, for the interval [lo, hi], over the A-type singularities
    re0 + j·step ± i y, the pseudo-singularity mid ± i·``entire`` and, if ``branch``, the
    other tangent lines lo + π and hi − π, and whether the A-type points are the nearest.
    Stops early once the distance is known to exceed ``enough`` (then the fewest nodes do)."""
    mid = 0.5 * (lo + hi)
    half = 0.5 * (hi - lo)
    # the integrand is not a low-degree polynomial even without singularities (its
    # trigonometric factors grow like e^{k|Im θ|}): a pseudo-singularity at height ``entire``
    d = math.asinh(entire / half)
    if branch:
        d = min(d, math.acosh(max((math.pi - half) / half, 1.0)))  # lo + π, hi − π
    # log ρ ≥ asinh(y/Δ) for any point at height y; of the points at one height the one
    # nearest to the middle of the interval lies on the smallest Bernstein ellipse
    if y < math.inf and math.asinh(y / half) < min(d, enough):
        j = math.floor((mid - re0) / step + 0.5)
        da = _log_rho(re0 + step * j, y, mid, half)
        if da < d:
            return da, True
    return d, False


# ---------------------------------------------------------------------------------------------
# one tabulated rule


@jit(error_model="numpy")
def _run_rule(
    W,
    D,
    method,
    n,
    law,
    s22,
    ib,
    lx,
    ly,
    xg,
    yg,
    t00,
    t01,
    t10,
    t11,
    cx,
    cy,
    k,
    mid,
    half,
    ecx,
    ecy,
    dist,
):
    """One tabulated rule with n nodes in the workspace W: (Fx, Fy, M, e₁, e₂) before the
    factor −sign ω. Unless ``D`` is ``None`` (a flag: any array), the integrands of the
    twist derivatives on the same nodes go into the rows below (a workspace of
    :data:`slidespin.contact._kernel_ellipse_jac.JAC_WORKSPACE_SHAPE`)
    (:func:`slidespin.contact._kernel_ellipse_lines.lines_and_derivatives`)."""
    o = _NODE_OFFSETS[_NODE_INDEX[n]]
    cc = (
        method == METHOD_CLENSHAW_CURTIS
        or method == METHOD_CLENSHAW_CURTIS_MAPPED
        or method == METHOD_CLENSHAW_CURTIS_INSIDE
    )
    if method == METHOD_TRAPEZOID or method == METHOD_TRAPEZOID_MAPPED:
        _dirs_table(W, o, n, k, cx, cy)
    else:
        if method == METHOD_SINE_MAPPED or method == METHOD_CLENSHAW_CURTIS_MAPPED:
            mode = 1
        elif method == METHOD_CLENSHAW_CURTIS_INSIDE:
            mode = 2
        else:
            mode = 0
        _dirs_rotated(W, o, n, not cc, mode, mid, half, k, cx, cy, ecx, ecy, dist)
    # the sine rule's node n and the trapezoid's (= node 0) are not used
    m = n + 1 if cc else n
    if D is None:
        _lines(law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, W, m)
    else:
        lines_and_derivatives(law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, W, m)
    if cc:
        return _sums_cc(W, n, half)
    return _sums_trapezoid(W, n, math.pi / n)
