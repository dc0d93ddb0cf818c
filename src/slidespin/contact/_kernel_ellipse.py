"""Compiled friction wrench on an elliptic patch (plain floats in, plain floats out).

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
adaptive Gauss–Kronrod 7/15 takes over, split at ψ₁.

Speed: nodes come from tables, and each rule runs as three loops over its nodes (directions,
line integrands, weighted sums), the first two free of calls and data-dependent branches so
that the compiler vectorises them; trigonometric functions of non-tabulated angles are
evaluated by a polynomial on [−π/2, π/2]. Per-body constants (:func:`wrench_constants`) and
the workspace (:func:`workspace`) can be set up once and reused (:func:`wrench_fast`).

Units: lengths in units of the semi-axis a (a = 1), load P = 1. The caller rescales.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit

LAW_UNIFORM, LAW_LINEAR, LAW_BOUSSINESQ, LAW_HERTZ = 0, 1, 2, 3
FAR_ICR = 1e15  # beyond this distance (in units of a) the ICR is at infinity: pure translation
STATUS_OK, STATUS_NOT_CONVERGED = 0, 1

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
GK_INITIAL_CAPACITY = 64
GK_MAX_INTERVALS = 4000


def _gk15_tables():
    """Gauss–Kronrod 7/15 (QUADPACK qk15) as 15 nodes with their Kronrod and Gauss weights
    (the Gauss weight is 0 at the 8 Kronrod-only nodes)."""
    xgk = [
        0.991455371120812639206854697526329,
        0.949107912342758524526189684047851,
        0.864864423359769072789712788640926,
        0.741531185599394439863864773280788,
        0.586087235467691130294144845693013,
        0.405845151377397166906606412076961,
        0.207784955007898467600689403773245,
        0.0,
    ]
    wgk = [
        0.022935322010529224963732008058970,
        0.063092092629978553290700663189204,
        0.104790010322250183839876322541518,
        0.140653259715525918745189590510238,
        0.169004726639267902826583426598550,
        0.190350578064785409913256402421014,
        0.204432940075298892414161999234649,
        0.209482141084727828012999174891714,
    ]
    wg = [
        0.129484966168869693270611432679082,
        0.279705391489276667901467771423780,
        0.381830050505118944950369775488975,
        0.417959183673469387755102040816327,
    ]
    x, wk, wgs = [0.0], [wgk[7]], [wg[3]]
    for j in range(7):
        g = wg[j // 2] if j % 2 == 1 else 0.0
        x += [-xgk[j], xgk[j]]
        wk += [wgk[j], wgk[j]]
        wgs += [g, g]
    return np.array(x), np.array(wk), np.array(wgs)


_GK_X, _GK_WK, _GK_WG = _gk15_tables()


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
# the line integrand


@jit(error_model="numpy", inline="always")
def _line_terms(law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, ex, ey, cde, exc, A, disc, jac):
    """(F_x, F_y, M) integrand, times ``jac``, of the line through the ICR in direction ê
    (before the factor −sign ω), from the chord moments K₁, K₂ of the module notes.

    ``cde`` = c·ê and ``exc`` = ê×c (the caller computes them without cancellation),
    ``A`` = ê·S·ê, ``disc`` = D ≥ 0, ``ib`` = 1/κ, (lx, ly) the gradient of the linear law's
    p/p₀.
    """
    ia = 1.0 / A
    h2 = disc * ia * ia
    f = exc * (ex * ey * (s22 - 1.0)) * ia  # (ê×c) (ê·S·ê⊥)/A, ê⊥ = ẑ×ê
    mx = -exc * ey - ex * f  # chord midpoint m_r
    my = exc * ex - ey * f
    m = -cde - f  # (m_r − c)·ê
    if law == LAW_BOUSSINESQ:
        w = 0.5 * ib * math.sqrt(ia) * jac
        k1 = w * m
        k2 = 0.5 * w * h2
    elif law == LAW_HERTZ:
        w = 0.75 * ib * math.sqrt(A) * h2 * jac
        k1 = w * m
        k2 = 0.25 * w * h2
    else:
        h = math.sqrt(h2)
        c = (2.0 / math.pi) * ib * h * jac
        k1 = c * m
        k2 = (1.0 / 3.0) * c * h2
        if law == LAW_LINEAR:
            l0 = 1.0 + lx * mx + ly * my  # p/p₀ at the midpoint, and its slope along ê
            l1 = lx * ex + ly * ey
            k1 = l0 * k1 + l1 * k2
            k2 = (l0 + l1 * m) * k2
    gx = -t00 * ey + t01 * ex  # 𝔽 t̂, t̂ = (−ey, ex)
    gy = -t10 * ey + t11 * ex
    mom = k1 * ((mx - xg) * gy - (my - yg) * gx) + k2 * (ex * gy - ey * gx)
    return k1 * gx, k1 * gy, mom


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
def _lines(law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, W, n):
    """Line integrands (rows 5–7) for the directions in rows 0–4, nodes 0..n−1.

    D is clamped at 0: only tangent lines (end nodes, up to rounding) can have D ≤ 0, and
    their limit is what the clamp gives (zero, except K₁ = m/(2κ√A) for Boussinesq).
    """
    for j in range(n):
        ex = W[0, j]
        ey = W[1, j]
        A = ex * ex + ey * ey * s22
        disc = max(A - s22 * W[3, j] * W[3, j], 0.0)
        fx, fy, mm = _line_terms(
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
            ex,
            ey,
            W[2, j],
            W[3, j],
            A,
            disc,
            W[4, j],
        )
        W[5, j] = fx
        W[6, j] = fy
        W[7, j] = mm


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
    x1 = y1 = m1 = x2 = y2 = m2 = x4 = y4 = m4 = 0.0
    for j in range(n + 1):
        w1 = _CC_W1[o + j]
        w2 = _CC_W2[o + j]
        w4 = _CC_W4[o + j]
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


# ---------------------------------------------------------------------------------------------
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
# adaptive fallback


@jit(error_model="numpy")
def _adaptive(
    inside,
    lo,
    hi,
    tol,
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
    ecx,
    ecy,
    dist,
    mid,
    half,
):
    """Globally adaptive Gauss–Kronrod 7/15 on [lo, hi], first split at the midpoint.

    The integration variable is ψ (``inside``) or s with α = mid + half sin s (outside, α
    from ê_c as in :func:`_dirs_rotated`). Returns (Fx, Fy, M, number of integrand
    evaluations, status). The interval table starts small and grows on demand (the fallback
    is rare; no large per-call allocation). One loop evaluates every node, which keeps the
    compiled code small.
    """
    cap = GK_INITIAL_CAPACITY
    tab = np.empty((cap, 6))  # lo, hi, fx, fy, m, err
    tab[0, 0] = lo
    tab[0, 1] = 0.5 * (lo + hi)
    tab[1, 0] = 0.5 * (lo + hi)
    tab[1, 1] = hi
    n = 2
    todo0 = 0  # rows to (re)compute: todo0 and todo1
    todo1 = 1
    status = STATUS_OK
    while True:
        for rr in range(2):
            row = todo0 if rr == 0 else todo1
            c = 0.5 * (tab[row, 0] + tab[row, 1])
            r = 0.5 * (tab[row, 1] - tab[row, 0])
            kx = ky = km = gx = gy = gm = 0.0
            for q in range(15):
                t = c + r * _GK_X[q]
                if inside:
                    ex = math.cos(t)
                    ey = math.sin(t)
                    cde = cx * ex + cy * ey
                    exc = ex * cy - ey * cx
                    jac = 1.0
                else:
                    jac = half * math.cos(t)
                    alpha = mid + half * math.sin(t)
                    ca = math.cos(alpha)
                    sa = math.sin(alpha)
                    ex = ca * ecx - sa * ecy
                    ey = ca * ecy + sa * ecx
                    cde = -dist * ca
                    exc = dist * sa
                A = ex * ex + ey * ey * s22
                disc = A - s22 * exc * exc
                if disc <= 0.0 or jac <= 0.0:
                    continue  # the line misses the patch
                fx, fy, mm = _line_terms(
                    law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, ex, ey, cde, exc, A, disc, jac
                )
                kx += _GK_WK[q] * fx
                ky += _GK_WK[q] * fy
                km += _GK_WK[q] * mm
                gx += _GK_WG[q] * fx
                gy += _GK_WG[q] * fy
                gm += _GK_WG[q] * mm
            tab[row, 2] = kx * r
            tab[row, 3] = ky * r
            tab[row, 4] = km * r
            tab[row, 5] = max(abs(kx - gx), abs(ky - gy), abs(km - gm)) * abs(r)
        total = 0.0
        worst = 0
        for i in range(n):
            total += tab[i, 5]
            if tab[i, 5] > tab[worst, 5]:
                worst = i
        if total <= tol:
            break
        a = tab[worst, 0]
        b = tab[worst, 1]
        if n + 1 >= GK_MAX_INTERVALS or b - a < 1e-14 * (1.0 + abs(a)):
            status = STATUS_NOT_CONVERGED
            break
        if n == cap:
            big = np.empty((2 * cap, 6))
            for i in range(cap):  # (explicit loops: slice assignment drags in slow-to-compile
                for j in range(6):  # error formatting)
                    big[i, j] = tab[i, j]
            tab = big
            cap *= 2
        tab[worst, 1] = 0.5 * (a + b)
        tab[n, 0] = 0.5 * (a + b)
        tab[n, 1] = b
        todo0 = worst
        todo1 = n
        n += 1
    sx = 0.0
    sy = 0.0
    sm = 0.0
    for i in range(n):
        sx += tab[i, 2]
        sy += tab[i, 3]
        sm += tab[i, 4]
    return sx, sy, sm, 15 * (2 * n - 2), status


# ---------------------------------------------------------------------------------------------
# the wrench


@jit(error_model="numpy")
def _run_rule(
    W,
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
    factor −sign ω."""
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
    _lines(law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, W, n + 1 if cc else n)
    if cc:
        return _sums_cc(W, n, half)
    return _sums_trapezoid(W, n, math.pi / n)


#: rows and columns of the workspace the rules need
WORKSPACE_SHAPE = (8, MAX_NODES + 1)


def workspace():
    """A workspace for :func:`wrench_fast` (reuse it across calls; one per thread)."""
    return np.empty(WORKSPACE_SHAPE)


@jit(error_model="numpy")
def wrench_constants(bn, law, xg, yg, tnorm, tol):
    """Per-body constants of the kernel: (κ, 1/κ², 1/κ, ξ_G, η_G, lx, ly, √κ, re0, d_A,
    d_A(√κ map), ln(‖𝔽‖/tol), tanh d_A, expm1(4 d_A(√κ map))) with ‖𝔽‖ the Frobenius norm,
    which does not change when the tensor is turned between frames."""
    s22 = 1.0 / (bn * bn)
    lx = 4.0 * xg if law == LAW_LINEAR else 0.0
    ly = 4.0 * yg * s22 if law == LAW_LINEAR else 0.0
    ksq = math.sqrt(bn)
    re0 = 0.0 if bn < 1.0 else 0.5 * math.pi  # A-points: tan ψ = ±iκ
    # the line integrands carry a factor 1/κ (and the moment arm κ for κ > 1)
    logterm = max(math.log(tnorm / tol * max(bn, 1.0 / bn)), 0.0) if tnorm > 0.0 else 0.0
    d_a = _atanh_sym(bn)
    d_am = _atanh_sym(ksq)
    return (
        bn,
        s22,
        1.0 / bn,
        xg,
        yg,
        lx,
        ly,
        ksq,
        re0,
        d_a,
        d_am,
        logterm,
        min(bn, 1.0 / bn),
        math.expm1(4.0 * d_am) if d_am < 100.0 else math.inf,
    )


@jit(error_model="numpy")
def wrench_fast(law, K, t00, t01, t10, t11, vx, vy, omega, tol, W):
    """:func:`wrench_body_info` with precomputed constants ``K`` (:func:`wrench_constants`)
    and a reusable workspace ``W`` (:func:`workspace`); the engine's inner call."""
    bn, s22, ib, xg, yg, lx, ly, ksq, re0, d_a, d_am, logterm, r_a, x_am = K
    if omega == 0.0 or not (abs(vx) + abs(vy)) / abs(omega) < FAR_ICR:
        speed = math.sqrt(vx * vx + vy * vy)
        if speed == 0.0:
            return 0.0, 0.0, 0.0, STATUS_OK, METHOD_TRANSLATION, 0
        ux = vx / speed
        uy = vy / speed
        # pure translation: F = −𝔽 v̂, M = 0 since G lies over the pressure centroid
        return (
            -(t00 * ux + t01 * uy),
            -(t10 * ux + t11 * uy),
            0.0,
            STATUS_OK,
            METHOD_TRANSLATION,
            0,
        )
    if t00 == 0.0 and t01 == 0.0 and t10 == 0.0 and t11 == 0.0:
        return 0.0, 0.0, 0.0, STATUS_OK, METHOD_TRANSLATION, 0
    cx = xg - vy / omega
    cy = yg + vx / omega
    sgn = -1.0 if omega > 0.0 else 1.0  # the overall factor −sign(ω)
    branch = law == LAW_UNIFORM or law == LAW_LINEAR  # √D is a branch point
    q = cx * cx + cy * cy * s22
    used = 0
    if q <= 1.0:
        # ---- ICR inside (or on the rim): trapezoid, plain or mapped; CC near the rim
        d = d_a
        d_m = d_am if bn != 1.0 else 0.0
        r = 0.0
        c2 = 1.0
        s2 = 0.0
        if branch:
            # D's zeros at ψ₁ ± i atanh r; the logarithms only when they are the nearest
            lam1, lam2, c2, s2 = _q_form(s22, cx, cy)
            r = math.sqrt(lam1 / lam2) if lam1 > 0.0 else 0.0
            if r < r_a:  # atanh r < d_A
                d = _atanh_sym(r) if r > 0.0 else 0.0
            if bn != 1.0:
                xm = _mapped_strip(c2, s2, r, ksq) if r > 0.0 else 0.0
                if xm < x_am:
                    d_m = 0.25 * math.log1p(xm)
        method = METHOD_TRAPEZOID
        n = _count(logterm, C_TRAPEZOID, GAMMA_TRAPEZOID, d, _NODE_SIZES, MIN_NODES)
        k = 1.0
        if bn != 1.0:
            n2 = _count(logterm, C_TRAPEZOID, GAMMA_TRAPEZOID, d_m, _NODE_SIZES, MIN_NODES)
            if n2 > 0 and (n < 0 or COST_MAPPED * n2 < n):
                method = METHOD_TRAPEZOID_MAPPED
                n = n2
                k = ksq
        half = 0.5 * math.pi
        psi1 = 0.5 * math.atan2(s2, c2) if branch else 0.0
        mid = psi1 + half
        if branch and (n < 0 or n > 64):
            # near the rim: Clenshaw–Curtis over [ψ₁, ψ₁ + π], D's zeros at its ends
            cost = COST_MAPPED * n if k != 1.0 else 1.0 * n
            enough = (logterm + C_CC) / (GAMMA_CC * MIN_NODES_CC)
            d, _ = _out_distance(
                psi1, psi1 + math.pi, d_a, re0, math.pi, q > 1.0, enough, ENTIRE_HEIGHT_CC
            )  # (q > 1 is False here, as a variable)
            d = min(d, _log_rho(psi1, _atanh_sym(r) if r > 0.0 else 0.0, mid, half))
            n3 = _count(logterm, C_CC, GAMMA_CC, d, _CC_SIZES, MIN_NODES_CC)
            if n3 > 0 and (n < 0 or COST_ROTATED * (n3 + 1) < cost):
                method = METHOD_CLENSHAW_CURTIS_INSIDE
                n = n3
                k = 1.0
        while 0 < n <= MAX_NODES:
            fx, fy, mm, e1, e2 = _run_rule(
                W,
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
                0.0,
                0.0,
                0.0,
            )
            used += n + 1 if method == METHOD_CLENSHAW_CURTIS_INSIDE else n
            if _estimate(e1, e2) <= tol:
                return sgn * fx, sgn * fy, sgn * mm, STATUS_OK, method, used
            n *= 2
        # fallback, split where D is smallest (the near-tangent line through a near-rim ICR)
        if not branch:
            lam1, lam2, c2, s2 = _q_form(s22, cx, cy)
            psi1 = 0.5 * math.atan2(s2, c2)
        inside = q <= 1.0  # (a variable: a literal True would compile a second version)
        fx, fy, mm, nev, status = _adaptive(
            inside,
            psi1,
            psi1 + math.pi,
            tol,
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
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        )
        return sgn * fx, sgn * fy, sgn * mm, status, METHOD_ADAPTIVE_INSIDE, used + nev
    # ---- ICR outside: the sector α₋ ≤ α ≤ α₊ of lines that meet the patch (α from ê_c)
    dist = math.sqrt(cx * cx + cy * cy)
    ecx = -cx / dist
    ecy = -cy / dist
    nx = -ecy
    ny = ecx
    suu = ecx * ecx + ecy * ecy * s22
    suv = ecx * nx + ecy * ny * s22
    rr = math.sqrt(s22 * (q - 1.0))
    a_plus = math.atan2(suu, rr - suv)
    a_minus = math.atan2(-suu, suv + rr)
    mid = 0.5 * (a_plus + a_minus)
    half = 0.5 * (a_plus - a_minus)
    if branch:
        c_rule, gamma, sizes, least, entire = (
            C_SINE,
            GAMMA_TRAPEZOID,
            _NODE_SIZES,
            MIN_NODES,
            ENTIRE_HEIGHT_SINE,
        )
        method = METHOD_SINE
    else:
        c_rule, gamma, sizes, least, entire = (
            C_CC,
            GAMMA_CC,
            _CC_SIZES,
            MIN_NODES_CC,
            ENTIRE_HEIGHT_CC,
        )
        method = METHOD_CLENSHAW_CURTIS
    enough = (logterm + c_rule) / (gamma * least)
    psic = math.atan2(ecy, ecx)
    d, a_nearest = _out_distance(
        a_minus + psic, a_plus + psic, d_a, re0, math.pi, branch, enough, entire
    )
    n = _count(logterm, c_rule, gamma, d, sizes, least)
    k = 1.0
    # the map can only help when the A-points limit the rule
    if a_nearest and half > MAP_MIN_HALF_WIDTH and bn != 1.0:
        p_lo = psic + a_minus
        p_hi = psic + a_plus
        lo2 = math.atan2(math.sin(p_lo) / ksq, math.cos(p_lo))
        hi2 = math.atan2(math.sin(p_hi) / ksq, math.cos(p_hi))
        while hi2 < lo2:
            hi2 += 2.0 * math.pi
        while hi2 > lo2 + 2.0 * math.pi:
            hi2 -= 2.0 * math.pi
        # A-type points and the map's own, one at Re ψ' = 0, the other at π/2 (mod π)
        d, _ = _out_distance(lo2, hi2, d_am, 0.0, 0.5 * math.pi, branch, enough, entire)
        n2 = _count(logterm, c_rule, gamma, d, sizes, least)
        if n2 > 0 and (n < 0 or COST_MAPPED * n2 < n):
            n = n2
            k = ksq
            mid = 0.5 * (lo2 + hi2)
            half = 0.5 * (hi2 - lo2)
            method = METHOD_SINE_MAPPED if branch else METHOD_CLENSHAW_CURTIS_MAPPED
    while 0 < n <= MAX_NODES:
        fx, fy, mm, e1, e2 = _run_rule(
            W,
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
        )
        used += n - 1 if branch else n + 1
        if _estimate(e1, e2) <= tol:
            return sgn * fx, sgn * fy, sgn * mm, STATUS_OK, method, used
        n *= 2
    mid = 0.5 * (a_plus + a_minus)
    half = 0.5 * (a_plus - a_minus)
    inside = q <= 1.0
    fx, fy, mm, nev, status = _adaptive(
        inside,
        -0.5 * math.pi,
        0.5 * math.pi,
        tol,
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
        ecx,
        ecy,
        dist,
        mid,
        half,
    )
    return sgn * fx, sgn * fy, sgn * mm, status, METHOD_ADAPTIVE_OUTSIDE, used + nev


@jit(error_model="numpy", inline="always")
def _tensor_norm(t00, t01, t10, t11):
    return math.sqrt(t00 * t00 + t01 * t01 + t10 * t10 + t11 * t11)


@jit(error_model="numpy")
def wrench_body_info(bn, law, xg, yg, t00, t01, t10, t11, vx, vy, omega, tol):
    """:func:`wrench_body` plus the quadrature used: (fx, fy, m, status, method, nodes).

    ``method`` is one of the ``METHOD_*`` codes (names in ``METHOD_NAMES``) and ``nodes`` the
    number of integrand evaluations (all attempts included).
    """
    K = wrench_constants(bn, law, xg, yg, _tensor_norm(t00, t01, t10, t11), tol)
    return wrench_fast(law, K, t00, t01, t10, t11, vx, vy, omega, tol, np.empty(WORKSPACE_SHAPE))


@jit(error_model="numpy")
def wrench_body(bn, law, xg, yg, t00, t01, t10, t11, vx, vy, omega, tol):
    """Friction wrench in the body frame, for unit load P = 1 and semi-axis a = 1.

    Parameters
    ----------
    bn : float
        b/a.
    law : int
        0 uniform, 1 linear, 2 Boussinesq, 3 Hertz.
    xg, yg : float
        Mass centre G in the body frame, units of a (the linear law's pressure centroid).
    t00, t01, t10, t11 : float
        Friction tensor in the body frame.
    vx, vy : float
        Velocity of G in the body frame (any scale: only the direction of (v/a, ω) matters).
    omega : float
        Spin rate.
    tol : float
        Absolute error target for the force (units of P) and moment (units of P a).

    Returns
    -------
    fx, fy, m : float
        Force (body frame) and moment about G, counter-clockwise positive.
    status : int
        0 converged, 1 error target not reached.
    """
    fx, fy, m, status, _, _ = wrench_body_info(
        bn, law, xg, yg, t00, t01, t10, t11, vx, vy, omega, tol
    )
    return fx, fy, m, status


@jit(error_model="numpy", inline="always")
def tensor_in_body(t00, t01, t10, t11, body_frame, c, s):
    """The friction tensor in the body frame, 𝔽_body = Rᵀ 𝔽 R with R = R(φ), c = cos φ,
    s = sin φ (unchanged if it is fixed to the body); shared by both compiled kernels."""
    if body_frame:
        return t00, t01, t10, t11
    a00 = c * t00 + s * t10
    a01 = c * t01 + s * t11
    a10 = -s * t00 + c * t10
    a11 = -s * t01 + c * t11
    return a00 * c + a01 * s, -a00 * s + a01 * c, a10 * c + a11 * s, -a10 * s + a11 * c


@jit(error_model="numpy", inline="always")
def wrench_world_fast(law, K, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol, W):
    """:func:`wrench_world` with precomputed constants and a workspace (see
    :func:`wrench_fast`)."""
    c = math.cos(phi)
    s = math.sin(phi)
    vbx = c * vx + s * vy
    vby = -s * vx + c * vy
    b00, b01, b10, b11 = tensor_in_body(t00, t01, t10, t11, body_frame, c, s)
    fbx, fby, m, status, _, _ = wrench_fast(law, K, b00, b01, b10, b11, vbx, vby, omega, tol, W)
    return c * fbx - s * fby, s * fbx + c * fby, m, status


@jit(error_model="numpy")
def wrench_world(bn, law, xg, yg, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol):
    """Friction wrench in the fixed frame (unit load, a = 1).

    The tensor (t00..t11) is given in its own frame: the plane's (``body_frame`` false,
    the paper's choice) or the body's. Velocities are those of G in the fixed frame.
    Returns (Fx, Fy, M, status) with M about G, counter-clockwise positive.
    """
    K = wrench_constants(bn, law, xg, yg, _tensor_norm(t00, t01, t10, t11), tol)
    return wrench_world_fast(
        law, K, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol, np.empty(WORKSPACE_SHAPE)
    )


@jit(error_model="numpy")
def wrench_array(bn, law, xg, yg, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol):
    """:func:`wrench_world` over 1-D arrays ``phi, vx, vy, omega`` of equal length.

    Returns (Fx, Fy, M, status) arrays.
    """
    n = vx.size
    fx = np.empty(n)
    fy = np.empty(n)
    mm = np.empty(n)
    st = np.empty(n, dtype=np.int64)
    K = wrench_constants(bn, law, xg, yg, _tensor_norm(t00, t01, t10, t11), tol)
    W = np.empty(WORKSPACE_SHAPE)
    for i in range(n):
        fx[i], fy[i], mm[i], st[i] = wrench_world_fast(
            law, K, t00, t01, t10, t11, body_frame, phi[i], vx[i], vy[i], omega[i], tol, W
        )
    return fx, fy, mm, st
