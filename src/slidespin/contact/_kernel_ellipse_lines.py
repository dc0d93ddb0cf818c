"""The line integrand of the elliptic wrench and of its twist derivatives (compiled).

On the line through the ICR in direction ê the ellipse cuts a chord; its pressure moments
(:func:`chord_moments`) give the wrench's integrand (:func:`_line_terms`, the notes of
:mod:`slidespin.contact._kernel_ellipse_rules`) and, one order lower, the integrands of the
wrench's twist derivatives (the notes of :mod:`slidespin.contact._kernel_ellipse_jac`).
:func:`_lines` fills the wrench's rows of a rule's workspace, :func:`lines_and_derivatives`
the same rows and the derivatives' in one pass over the nodes.

Units: lengths in units of the semi-axis a (a = 1), load P = 1.
"""

from __future__ import annotations

import math

from slidespin._jit import jit

LAW_UNIFORM, LAW_LINEAR, LAW_BOUSSINESQ, LAW_HERTZ = 0, 1, 2, 3

#: rows of the derivative workspace: Q (2), N (4), the symmetric êêᵀK₀ (3), êσK₀ (2), the
#: moment's (3), the wrench of the linear law's gradient (lx: 3, ly: 3); see
#: :mod:`slidespin.contact._kernel_ellipse_jac`
NROWS = 20
#: the first of them in the workspace (rows 0–7 are the wrench's rule, see
#: :mod:`slidespin.contact._kernel_ellipse_rules`)
DROW = 8


@jit(error_model="numpy", inline="always")
def chord_moments(law, s22, ib, lx, ly, ex, ey, cde, exc, A, disc, jac):
    """The chord through the ICR in direction ê and its pressure moments, times ``jac``:
    (m_r, m, K₀, K₁, K₂, J₁) with m_r = (mx, my) the chord's midpoint, m = (m_r − c)·ê, x the
    position on the chord from m_r and

        K₀ = ∫ p dx,   K₁ = ∫ p (m + x) dx,   K₂ = ∫ p (m + x) x dx,   J₁ = ∫ p x dx

    over the chord (the module notes; K₀ and J₁ are the twist derivatives' moments, see
    :mod:`slidespin.contact._kernel_ellipse_jac`). Arguments as :func:`_line_terms`.
    """
    ia = 1.0 / A
    h2 = disc * ia * ia
    f = exc * (ex * ey * (s22 - 1.0)) * ia  # (ê×c) (ê·S·ê⊥)/A, ê⊥ = ẑ×ê
    mx = -exc * ey - ex * f  # chord midpoint m_r
    my = exc * ex - ey * f
    m = -cde - f  # (m_r − c)·ê
    j1 = 0.0
    if law == LAW_BOUSSINESQ:
        k0 = 0.5 * ib * math.sqrt(ia) * jac
        k1 = k0 * m
        k2 = 0.5 * k0 * h2
    elif law == LAW_HERTZ:
        k0 = 0.75 * ib * math.sqrt(A) * h2 * jac
        k1 = k0 * m
        k2 = 0.25 * k0 * h2
    else:
        k0 = (2.0 / math.pi) * ib * math.sqrt(h2) * jac
        k1 = k0 * m
        k2 = (1.0 / 3.0) * k0 * h2
        if law == LAW_LINEAR:
            l0 = 1.0 + lx * mx + ly * my  # p/p₀ at the midpoint, and its slope along ê
            l1 = lx * ex + ly * ey
            j1 = l1 * k2
            k0 = l0 * k0
            k1 = l0 * k1 + j1
            k2 = (l0 + l1 * m) * k2
    return mx, my, m, k0, k1, k2, j1


@jit(error_model="numpy", inline="always")
def _line_terms(law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, ex, ey, cde, exc, A, disc, jac):
    """(F_x, F_y, M) integrand, times ``jac``, of the line through the ICR in direction ê
    (before the factor −sign ω), from the chord moments K₁, K₂ of the module notes.

    ``cde`` = c·ê and ``exc`` = ê×c (the caller computes them without cancellation),
    ``A`` = ê·S·ê, ``disc`` = D ≥ 0, ``ib`` = 1/κ, (lx, ly) the gradient of the linear law's
    p/p₀.
    """
    mx, my, _, _, k1, k2, _ = chord_moments(law, s22, ib, lx, ly, ex, ey, cde, exc, A, disc, jac)
    gx = -t00 * ey + t01 * ex  # 𝔽 t̂, t̂ = (−ey, ex)
    gy = -t10 * ey + t11 * ex
    mom = k1 * ((mx - xg) * gy - (my - yg) * gx) + k2 * (ex * gy - ey * gx)
    return k1 * gx, k1 * gy, mom


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
def lines_and_derivatives(law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, W, n):
    """:func:`_lines` and the integrands of the wrench's isotropic parts and twist
    derivatives into the rows ``DROW`` on of the same workspace (layout :data:`NROWS`; the
    formulas in :mod:`slidespin.contact._kernel_ellipse_jac`).

    The chord moments are those of :func:`chord_moments`, written without a branch on the
    law inside the loops: K₀ = jac (cu √h² + cb /√A + ch √A h²)/κ with one of the three
    coefficients non-zero, K₂ = r K₀ h² before the linear law's weight l₀ + l₁x (l₀ = 1,
    l₁ = 0 for the other laws, whose (lx, ly) are zero). Five passes over the nodes, each
    reading and writing a few rows: a loop over twenty rows of one array is not vectorised
    by the compiler (measured: 7x slower in one pass), the rows of a pass are kept in rows
    the later passes overwrite."""
    cu = 2.0 / math.pi if law == LAW_UNIFORM or law == LAW_LINEAR else 0.0
    cb = 0.5 if law == LAW_BOUSSINESQ else 0.0
    ch = 0.75 if law == LAW_HERTZ else 0.0
    r = 0.5 if law == LAW_BOUSSINESQ else (0.25 if law == LAW_HERTZ else 1.0 / 3.0)
    # 1: the chord's midpoint (mx, my), m, and the unweighted moments kb (K₀), k2b (K₂)
    for j in range(n):
        ex = W[0, j]
        ey = W[1, j]
        exc = W[3, j]
        A = ex * ex + ey * ey * s22
        disc = max(A - s22 * exc * exc, 0.0)
        ia = 1.0 / A
        h2 = disc * ia * ia
        f = exc * (ex * ey * (s22 - 1.0)) * ia
        sa = math.sqrt(A)
        kb = ib * W[4, j] * (cu * math.sqrt(h2) + cb / sa + ch * sa * h2)
        W[DROW + 2, j] = -exc * ey - ex * f
        W[DROW + 3, j] = exc * ex - ey * f
        W[DROW + 6, j] = -W[2, j] - f
        W[DROW + 7, j] = kb
        W[DROW + 8, j] = r * kb * h2
    # 2: the linear law's weight; the wrench's rows, K₀, J₁, K₁, K₂
    for j in range(n):
        ex = W[0, j]
        ey = W[1, j]
        mx = W[DROW + 2, j]
        my = W[DROW + 3, j]
        m = W[DROW + 6, j]
        kb = W[DROW + 7, j]
        k2b = W[DROW + 8, j]
        l0 = 1.0 + lx * mx + ly * my
        l1 = lx * ex + ly * ey
        j1 = l1 * k2b
        k1 = l0 * (kb * m) + j1
        k2 = (l0 + l1 * m) * k2b
        gx = -t00 * ey + t01 * ex  # 𝔽 t̂, t̂ = (−ey, ex)
        gy = -t10 * ey + t11 * ex
        W[5, j] = k1 * gx
        W[6, j] = k1 * gy
        W[7, j] = k1 * ((mx - xg) * gy - (my - yg) * gx) + k2 * (ex * gy - ey * gx)
        W[DROW, j] = l0 * kb
        W[DROW + 1, j] = j1
        W[DROW + 4, j] = k1
        W[DROW + 5, j] = k2
    # 3: the wrench of the linear law's gradient: the weight l₀ + l₁x is linear in (lx, ly),
    # ∂/∂lx of K₁, K₂ is (mx K₁⁰ + ex K₂⁰, (mx + ex m) K₂⁰) with K₁⁰ = kb m, K₂⁰ = k2b
    for j in range(n):
        ex = W[0, j]
        ey = W[1, j]
        mx = W[DROW + 2, j]
        my = W[DROW + 3, j]
        m = W[DROW + 6, j]
        k1b = W[DROW + 7, j] * m
        k2b = W[DROW + 8, j]
        gx = -t00 * ey + t01 * ex
        gy = -t10 * ey + t11 * ex
        dk1x = mx * k1b + ex * k2b
        dk2x = (mx + ex * m) * k2b
        dk1y = my * k1b + ey * k2b
        dk2y = (my + ey * m) * k2b
        arm = (mx - xg) * gy - (my - yg) * gx
        tor = ex * gy - ey * gx
        W[DROW + 14, j] = dk1x * gx
        W[DROW + 15, j] = dk1x * gy
        W[DROW + 16, j] = dk1x * arm + dk2x * tor
        W[DROW + 17, j] = dk1y * gx
        W[DROW + 18, j] = dk1y * gy
        W[DROW + 19, j] = dk1y * arm + dk2y * tor
    # 4: the twist derivatives' rows, from K₀ and J₁
    for j in range(n):
        ex = W[0, j]
        ey = W[1, j]
        k0 = W[DROW, j]
        j1 = W[DROW + 1, j]
        px = W[DROW + 2, j] - xg
        py = W[DROW + 3, j] - yg
        sig = -W[3, j] + ex * yg - ey * xg  # ê·ẑ×(c − r_G) = −ê×(c − r_G)
        bx = px * k0 + ex * j1
        by = py * k0 + ey * j1
        mu = bx * (t10 * ex + t11 * ey) - by * (t00 * ex + t01 * ey)
        W[DROW + 6, j] = ex * ex * k0
        W[DROW + 7, j] = ex * ey * k0
        W[DROW + 8, j] = ey * ey * k0
        W[DROW + 9, j] = ex * sig * k0
        W[DROW + 10, j] = ey * sig * k0
        W[DROW + 11, j] = ex * mu
        W[DROW + 12, j] = ey * mu
        W[DROW + 13, j] = sig * mu
    # 5: the isotropic parts Q = t̂ K₁ and N_ij: a × 𝔽t̂ = Σ 𝔽_ij t̂_j (δ_i1 a_x − δ_i0 a_y)
    for j in range(n):
        ex = W[0, j]
        ey = W[1, j]
        k1 = W[DROW + 4, j]
        k2 = W[DROW + 5, j]
        ax = (W[DROW + 2, j] - xg) * k1 + ex * k2
        ay = (W[DROW + 3, j] - yg) * k1 + ey * k2
        W[DROW, j] = -ey * k1
        W[DROW + 1, j] = ex * k1
        W[DROW + 2, j] = ay * ey
        W[DROW + 3, j] = -ay * ex
        W[DROW + 4, j] = -ax * ey
        W[DROW + 5, j] = ax * ex
