"""Globally adaptive Gauss–Kronrod 7/15 for the elliptic wrench, and for its derivatives on
the same partition (compiled; MODEL §2, §15).

The fallback of :mod:`slidespin.contact._kernel_ellipse` where no tabulated rule reaches the
wrench's target (the ICR within ~1e-4 a of the rim with uniform or linear pressure, or b/a
below ~5e-3): :func:`_adaptive` bisects the interval with the largest error until the sum of
the estimates meets ``tol``. :func:`adaptive_derivative_sums` then sums the integrands of
the wrench's twist derivatives (:func:`slidespin.contact._kernel_ellipse_lines.lines_and_derivatives`)
with the same Gauss–Kronrod nodes on the final partition, which is refined where the
integrand's branch points are, and estimates their error from the Gauss–Kronrod differences,
as the wrench's.

Units: lengths in units of the semi-axis a (a = 1), load P = 1.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._kernel_ellipse_lines import DROW, NROWS, _line_terms, lines_and_derivatives

__all__ = [
    "GK_INITIAL_CAPACITY",
    "GK_MAX_INTERVALS",
    "STATUS_NOT_CONVERGED",
    "STATUS_OK",
    "adaptive_derivative_sums",
]

STATUS_OK, STATUS_NOT_CONVERGED = 0, 1
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


# adaptive fallback


@jit(error_model="numpy", inline="always")
def _node_line(t, inside, cx, cy, ecx, ecy, dist, mid, half):
    """The line of the Gauss–Kronrod node ``t``: (ê_x, ê_y, c·ê, ê×c, the Jacobian of the
    variable), the variable ψ (``inside``) or s with α = mid + half sin s from ê_c."""
    if inside:
        ex = math.cos(t)
        ey = math.sin(t)
        return ex, ey, cx * ex + cy * ey, ex * cy - ey * cx, 1.0
    alpha = mid + half * math.sin(t)
    ca = math.cos(alpha)
    sa = math.sin(alpha)
    return ca * ecx - sa * ecy, ca * ecy + sa * ecx, -dist * ca, dist * sa, half * math.cos(t)


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
    evaluations, status, the interval table, its number of rows). The interval table starts small and grows on demand (the fallback
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
                ex, ey, cde, exc, jac = _node_line(
                    c + r * _GK_X[q], inside, cx, cy, ecx, ecy, dist, mid, half
                )
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
    return sx, sy, sm, 15 * (2 * n - 2), status, tab, n


@jit(error_model="numpy")
def adaptive_derivative_sums(
    tab,
    n,
    inside,
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
    W,
):
    """The integrals of the derivative rows (:data:`slidespin.contact._kernel_ellipse_lines.NROWS`)
    over the final partition ``tab[:n]`` of :func:`_adaptive` (same variable and arguments),
    by its Gauss–Kronrod 15 nodes, into the last column of ``W`` (a derivative workspace,
    rows ``DROW`` on; rows 0–4 and 5–7 are used as scratch). Returns the largest
    Gauss–Kronrod difference of the derivative rows proper (6 on), summed over the
    intervals, relative to their largest integral, as
    :func:`slidespin.contact._kernel_ellipse_jac._rule_sums` does."""
    last = W.shape[1] - 1
    for r in range(NROWS):
        W[DROW + r, last] = 0.0
    err = np.zeros(NROWS)
    for i in range(n):
        c = 0.5 * (tab[i, 0] + tab[i, 1])
        r_ = 0.5 * (tab[i, 1] - tab[i, 0])
        for q in range(15):
            ex, ey, cde, exc, jac = _node_line(
                c + r_ * _GK_X[q], inside, cx, cy, ecx, ecy, dist, mid, half
            )
            if ex * ex + ey * ey * s22 - s22 * exc * exc <= 0.0 or jac <= 0.0:
                jac = 0.0  # the line misses the patch: every row is 0
            W[0, q] = ex
            W[1, q] = ey
            W[2, q] = cde
            W[3, q] = exc
            W[4, q] = jac
        lines_and_derivatives(law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, W, 15)
        for row in range(NROWS):
            k = 0.0
            g = 0.0
            for q in range(15):
                v = W[DROW + row, q]
                k += _GK_WK[q] * v
                g += _GK_WG[q] * v
            W[DROW + row, last] += k * r_
            err[row] += abs(k - g) * abs(r_)
    big = 0.0
    worst = 0.0
    for row in range(6, NROWS):
        big = max(big, abs(W[DROW + row, last]))
        worst = max(worst, err[row])
    return worst / big if big > 0.0 else 0.0
