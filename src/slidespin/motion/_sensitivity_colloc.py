"""Compiled sensitivities by collocation along the plain run (MODEL §15).

The variational equation dS/dτ = J(τ) S + B(τ) (J = ∂G/∂y, B = ∂G/∂θ along the motion,
:mod:`slidespin.motion._sensitivity_rhs`) is linear in S, and the motion itself is known:
the plain run (:mod:`slidespin.motion._integrator`, with ``stages``) recorded the state at
every accepted step and the step's DOP853 stages. So S need not be integrated *with* the
motion (twelve stages per step, each with J, under a joint error control that takes more
steps than the motion's). :func:`solve_on_records` solves it on the plain run's own steps by
collocation at the five Lobatto points (Lobatto IIIA, order 8, its first stage explicit:
four evaluations of G, J and B per step, the last shared with the next step), the state at
the inner points from the step's dense output (scipy's DOP853 interpolant, order 7: three
plain right-hand sides more per step). Once s < 1e-8 s₀ and the stop's sensitivities have
converged the later records keep them, and the tail the plain run adds in closed form after
its last record (t += s/|u·A|) is differentiated (:func:`_tail`). Where the kernel has no J
it gives up and the caller integrates the joint system
(:func:`slidespin.motion._sensitivity_core.integrate_sensitivities`).

Where the motion's instantaneous centre of rotation (ICR) crosses the patch's rim the
wrench is only C¹ (J has a cusp), so a step across it is split there and once more a
quarter of the way on either side (``GRADE``; :func:`step_pieces`). Measured on an ellipse
under the linear law: a step across the rim left S 2.5e-6 off (relative), split 9e-8,
graded 5e-9. The state from a quintic Hermite interpolant of y, y' and y'' = J y' at the
step's ends (no stages needed) left S 1e-8 to 1e-5 off (the interpolant's error through
∂J/∂y; a derivative that is small by cancellation lost most): the dense output is used.
Against the Richardson references of tests/analysis/test_sensitivities.py the collocated
derivatives agree like the joint run's (worst 3e-7, a differenced parameter; typically 1e-8
to 1e-10). Tried and left: collocating two steps at once, or Lobatto's four points (order
6): 1e-6 to 1e-5 off.

The core (5 components) is (u₁, u₂, u₃, ln s, φ): the rows and columns where J couples; t,
x, y, ℓ are quadratures of it (their columns of J vanish), summed after the solve.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import is_none_type, jit, overload
from slidespin.contact._engine import P_BN, P_K, P_XG, P_YG
from slidespin.contact._kernel_footprint import GEO_XG, GEO_YG
from slidespin.motion import _dop853 as _dop
from slidespin.motion._flow import NY, _rhs, unit_direction
from slidespin.motion._sensitivity_rhs import moved_row, parameter_rhs, rhs_jacobian, row_patch


def _lobatto_points(n: int) -> np.ndarray:
    """The ``n`` Lobatto points on [0, 1]: the ends and the roots of P'_{n−1}(2t − 1)."""
    inner = np.sort(np.polynomial.legendre.Legendre.basis(n - 1).deriv().roots().real)
    return np.concatenate([[0.0], (inner + 1.0) / 2.0, [1.0]])


#: Lobatto points per collocation interval
N_LOBATTO = 5
#: the Lobatto points on [0, 1]
LOBATTO_C = _lobatto_points(N_LOBATTO)


def _lobatto_a(c: np.ndarray) -> np.ndarray:
    """Lobatto IIIA: a_ij = ∫₀^{c_i} ℓ_j, ℓ_j the Lagrange basis on the points ``c``."""
    n = c.size
    coef = np.linalg.inv(np.vander(c, n, increasing=True))  # ℓ_j(t) = Σ_k coef[k, j] tᵏ
    powers = np.arange(1, n + 1)
    return np.array([[np.sum(coef[:, j] * c[i] ** powers / powers) for j in range(n)]
                     for i in range(n)])  # fmt: skip


#: the Lobatto IIIA tableau (its last row are the weights)
LOBATTO_A = _lobatto_a(LOBATTO_C)
#: rows of the DOP853 dense output's coefficients (scipy's INTERPOLATOR_POWER)
N_DENSE = 7
#: the core components (module notes) and their count
CORE = np.array([0, 1, 2, 3, 7], dtype=np.int64)
NCORE = 5
#: the quadrature components (their columns of J vanish)
QUAD = np.array([4, 5, 6, 8], dtype=np.int64)
#: the Lobatto points per step, and the size of the stage system (its implicit stages' core)
NL = LOBATTO_C.size
NI = NCORE * (NL - 1)
#: a crossing splits its step there and at this fraction of the way to either end
GRADE = 0.25
#: samples of the crossing functions per step (a sign change between two is a crossing)
CROSS_SAMPLES = 4
#: most sub-intervals of one step
MAX_PIECES = 64
#: the stage solve searches a column for its pivot only where the diagonal entry is below
#: this (I − h a ⊗ J is near I: |h a J| ≲ 0.5 on the run's steps, so no growth without it)
PIVOT_SEARCH = 0.5
#: the collocation stops once s has dropped by e^this (1e-8) and the stop's sensitivities
#: have converged (the later records keep them)
CONVERGED_DROP = 18.4
_NS = _dop.N_STAGES
_B = np.ascontiguousarray(_dop.B)
_AX = np.ascontiguousarray(_dop.A_EXTRA)
_D = np.ascontiguousarray(_dop.D)


@jit(error_model="numpy", inline="always")
def dense_at(x, y0, F, out):
    """The state at the fraction ``x`` of a DOP853 step from ``y0``, from its dense output's
    coefficients ``F`` (:data:`N_DENSE`, NY) (scipy's ``Dop853DenseOutput``, the same
    nesting), into ``out``."""
    for i in range(NY):
        out[i] = 0.0
    for j in range(N_DENSE):
        f = F[N_DENSE - 1 - j]
        w = x if j % 2 == 0 else 1.0 - x
        for i in range(NY):
            out[i] = (out[i] + f[i]) * w
    for i in range(NY):
        out[i] += y0[i]


@jit(error_model="numpy", inline="always")
def _icr_scaled(xg, yg, k, y):
    """(ω cx, ω cy, ω) of the ICR c = G + ẑ×v_b/ω in the body frame (natural units; finite
    for a translation, ω = 0) at the state ``y``."""
    u1, u2, u3 = y[0], y[1], y[2]
    inv = 1.0 / math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
    c = math.cos(y[7])
    s = math.sin(y[7])
    vbx = (c * u1 + s * u2) * inv
    vby = (-s * u1 + c * u2) * inv
    w = u3 * inv / k
    return xg * w - vby, yg * w + vbx, w


def icr_scaled(par, fp, y):
    """:func:`_icr_scaled` with the patch's G: the ellipse's (``fp`` None) or the
    footprint's."""
    if fp is None:
        return _icr_scaled(par[P_XG], par[P_YG], par[P_K], y)
    return _icr_scaled(fp[2][GEO_XG], fp[2][GEO_YG], par[P_K], y)


@overload(icr_scaled, jit_options={"error_model": "numpy"})
def _icr_scaled_of_type(par, fp, y):
    if is_none_type(fp):
        return lambda par, fp, y: _icr_scaled(par[P_XG], par[P_YG], par[P_K], y)
    return lambda par, fp, y: _icr_scaled(fp[2][GEO_XG], fp[2][GEO_YG], par[P_K], y)


def n_rims(fp):
    """How many crossing functions the patch has: the ellipse's rim (``fp`` None), else one
    per edge and circle of the footprint."""
    return 1 if fp is None else fp[0].shape[0] + fp[1].shape[0]


@overload(n_rims, jit_options={"error_model": "numpy"})
def _n_rims_of_type(fp):
    if is_none_type(fp):
        return lambda fp: 1
    return lambda fp: fp[0].shape[0] + fp[1].shape[0]


def rim_value(par, fp, j, cx, cy, w):
    """Crossing function ``j`` at the scaled ICR (cx, cy, w) (:func:`icr_scaled`): its sign
    tells the side of the rim; and (second value) for an edge where along it the ICR's
    projection falls (0..1 within the segment; 0.5 for a closed curve)."""
    return _rim_ellipse(par, cx, cy, w) if fp is None else _rim_footprint(fp, j, cx, cy, w)


@overload(rim_value, jit_options={"error_model": "numpy"})
def _rim_value_of_type(par, fp, j, cx, cy, w):
    if is_none_type(fp):
        return lambda par, fp, j, cx, cy, w: _rim_ellipse(par, cx, cy, w)
    return lambda par, fp, j, cx, cy, w: _rim_footprint(fp, j, cx, cy, w)


@jit(error_model="numpy", inline="always")
def _rim_ellipse(par, cx, cy, w):
    """ω² (cx² + (cy/b)² − 1) for the ellipse of semi-axes 1, b (natural units)."""
    return cx * cx + (cy / par[P_BN]) ** 2 - w * w, 0.5


@jit(error_model="numpy", inline="always")
def _rim_footprint(fp, j, cx, cy, w):
    """An edge's ω |PQ| × the ICR's signed distance from its line PQ, or a circle's
    ω² (|c − o|² − R²)."""
    edges = fp[0]
    ne = edges.shape[0]
    if j < ne:
        x0, y0 = edges[j, 0] * w, edges[j, 1] * w
        dx, dy = (edges[j, 2] - edges[j, 0]) * w, (edges[j, 3] - edges[j, 1]) * w
        ln2 = dx * dx + dy * dy
        along = ((cx - x0) * dx + (cy - y0) * dy) / ln2 if ln2 > 0.0 else -1.0
        return dx * (cy - y0) - dy * (cx - x0), along
    o = fp[1][j - ne]
    return (cx - o[0] * w) ** 2 + (cy - o[1] * w) ** 2 - (o[2] * w) ** 2, 0.5


@jit(error_model="numpy")
def _bisect_rim(par, fp, j, lo, hi, glo, y0, F, yi):
    """The fraction where crossing function ``j`` changes sign in (lo, hi) (bisection on the
    interpolated state), or −1 if the ICR passes there outside the edge's segment."""
    a, b, ga = lo, hi, glo
    for _ in range(60):
        mid = 0.5 * (a + b)
        if not (a < mid < b):
            break
        dense_at(mid, y0, F, yi)
        cx, cy, w = icr_scaled(par, fp, yi)
        gm, _ = rim_value(par, fp, j, cx, cy, w)
        if (gm < 0.0) == (ga < 0.0):
            a, ga = mid, gm
        else:
            b = mid
    r = 0.5 * (a + b)
    dense_at(r, y0, F, yi)
    cx, cy, w = icr_scaled(par, fp, yi)
    _, along = rim_value(par, fp, j, cx, cy, w)
    return r if 0.0 <= along <= 1.0 else -1.0


@jit(error_model="numpy")
def step_pieces(par, fp, y0, F, yi, gprev, pieces):
    """The sub-interval boundaries (fractions 0 = p₀ < … < p_n = 1 of the step, into
    ``pieces``; returns n) of a step of the motion: split where the ICR crosses the rim
    (located by bisection on the dense output ``F`` from ``y0``) and graded towards it
    (module notes).
    ``yi`` (NY) and ``gprev`` (:func:`n_rims`) are work arrays."""
    nr = n_rims(fp)
    pts = pieces  # (the crossings gathered in place, sorted at the end)
    pts[0] = 0.0
    pts[1] = 1.0
    n = 2
    dense_at(0.0, y0, F, yi)
    cx, cy, w = icr_scaled(par, fp, yi)
    for j in range(nr):
        gprev[j], _ = rim_value(par, fp, j, cx, cy, w)
    for q in range(1, CROSS_SAMPLES + 1):
        hi = q / CROSS_SAMPLES
        dense_at(hi, y0, F, yi)
        cx, cy, w = icr_scaled(par, fp, yi)
        for j in range(nr):
            g, _ = rim_value(par, fp, j, cx, cy, w)
            if (g < 0.0) != (gprev[j] < 0.0) and n + 3 <= MAX_PIECES + 1:
                lo = (q - 1) / CROSS_SAMPLES
                r = _bisect_rim(par, fp, j, lo, hi, gprev[j], y0, F, yi)
                if 0.0 < r < 1.0:
                    pts[n] = r
                    pts[n + 1] = r - GRADE * r
                    pts[n + 2] = r + GRADE * (1.0 - r)
                    n += 3
            gprev[j] = g
    if n == 2:
        return 1
    srt = np.sort(pts[:n])
    m = 1
    pieces[0] = 0.0
    for i in range(1, n):
        if srt[i] - pieces[m - 1] > 1e-9:
            pieces[m] = srt[i]
            m += 1
    pieces[m - 1] = 1.0
    return m - 1


@jit(error_model="numpy")
def _lu_solve(M, R, p):
    """Solve M X = R in place (X into R; M overwritten) by Gaussian elimination with partial
    pivoting, M of size :data:`NI` (a constant: numba unrolls for it), R with ``p`` columns;
    False if M is singular."""
    n = NI
    for c in range(n):
        piv = c
        big = abs(M[c, c])
        if big < PIVOT_SEARCH:  # (M is near I on the run's steps: the search is rarely run)
            for r in range(c + 1, n):
                if abs(M[r, c]) > big:
                    big = abs(M[r, c])
                    piv = r
        if big == 0.0:
            return False
        if piv != c:
            for j in range(n):
                M[c, j], M[piv, j] = M[piv, j], M[c, j]
            for j in range(p):
                R[c, j], R[piv, j] = R[piv, j], R[c, j]
        inv = 1.0 / M[c, c]
        for r in range(c + 1, n):
            f = M[r, c] * inv
            if f != 0.0:
                for j in range(c + 1, n):
                    M[r, j] -= f * M[c, j]
                for j in range(p):
                    R[r, j] -= f * R[c, j]
    for c in range(n - 1, -1, -1):
        inv = 1.0 / M[c, c]
        for j in range(p):
            acc = R[c, j]
            for i in range(c + 1, n):
                acc -= M[c, i] * R[i, j]
            R[c, j] = acc * inv
    return True


@jit(error_model="numpy")
def collocation_step(S, K, Z, Jc, Bs, h, M, R):
    """Advance S (NY × p) over a step of length ``h`` by Lobatto IIIA collocation, with the
    core columns of J (:data:`CORE`) and B at the Lobatto points in ``Jc`` (NL, NY, NCORE)
    and ``Bs`` (NL, p, NY); ``K``, ``Z`` (NL, NY, p), ``M`` (NI, NI), ``R`` (NI, p)
    (NI = NCORE (NL − 1)) are work arrays. False if the stage system is singular (not met:
    I − h a ⊗ J is near I on the run's steps)."""
    p = S.shape[1]
    A = LOBATTO_A
    # Z₁ = S on the core; the first stage is explicit: K₁ = J₁ S + B₁
    for q in range(NCORE):
        for k in range(p):
            Z[0, q, k] = S[CORE[q], k]
    for i in range(NY):
        for k in range(p):
            acc = Bs[0, k, i]
            for q in range(NCORE):
                acc += Jc[0, i, q] * Z[0, q, k]
            K[0, i, k] = acc
    # the core of the implicit stages: (I − h a_mj J_m) K_j = J_m (S + h a_m1 K₁) + B_m
    for a in range(NL - 1):
        m = a + 1
        ham = h * A[m, 0]
        for q in range(NCORE):
            for k in range(p):
                Z[m, q, k] = Z[0, q, k] + ham * K[0, CORE[q], k]
        for r in range(NCORE):
            ri = CORE[r]
            row = a * NCORE + r
            for b in range(NL - 1):
                amb = h * A[m, b + 1]
                for q in range(NCORE):
                    M[row, b * NCORE + q] = -amb * Jc[m, ri, q]
            M[row, row] += 1.0
            for k in range(p):
                acc = Bs[m, k, ri]
                for q in range(NCORE):
                    acc += Jc[m, ri, q] * Z[m, q, k]
                R[row, k] = acc
    if not _lu_solve(M, R, p):
        return False
    for a in range(NL - 1):
        for r in range(NCORE):
            for k in range(p):
                K[a + 1, CORE[r], k] = R[a * NCORE + r, k]
    # the stage values Z_m = S + h Σ_j a_mj K_j of the core, then the quadrature rows (t, x,
    # y, ℓ) of the implicit stages: K_m = J_m Z_m + B_m
    for m in range(1, NL):
        for q in range(NCORE):
            qi = CORE[q]
            for k in range(p):
                acc = 0.0
                for j in range(NL):
                    acc += A[m, j] * K[j, qi, k]
                Z[m, q, k] = S[qi, k] + h * acc
        for i in QUAD:
            for k in range(p):
                acc = Bs[m, k, i]
                for q in range(NCORE):
                    acc += Jc[m, i, q] * Z[m, q, k]
                K[m, i, k] = acc
    for i in range(NY):
        for k in range(p):
            acc = 0.0
            for j in range(NL):
                acc += A[NL - 1, j] * K[j, i, k]
            S[i, k] += h * acc
    return True


@jit(error_model="numpy")
def _node(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, y, gp, gm, G, Js, Bs, m):
    """G, the core columns of J = ∂G/∂y (into ``Js[m]``, NY × NCORE) and B_k = ∂G/∂θ_k
    (into ``Bs[m]``) at the state ``y`` (as :func:`joint_rhs` forms them), G into ``G``;
    returns (wrench evaluations off target, J available). ``gp``, ``gm`` (NY) are work
    arrays. (The slots by index and the rates ``dts`` read in place: an array view costs two
    atomic reference counts, and per parameter and node they added up to a few per cent.)"""
    npar = hs.size
    fails, ok = rhs_jacobian(pars[0], kcs[0], W, jo, row_patch(fp, geos, 0), y, G, Jy)
    if ok:
        for i in range(NY):
            for q in range(NCORE):
                Js[m, i, q] = Jy[i, CORE[q]]
        cph = math.cos(y[7])
        sph = math.sin(y[7])
        u1, u2, u3, _ = unit_direction(y)
        for k in range(npar):
            for i in range(NY):
                Bs[m, k, i] = 0.0
            if not direct[k]:
                fails += _differenced(pars, kcs, W, fp, geos, hs, y, gp, gm, Bs, m, k)
            elif moved_row(dts, k):
                g0, g1, g2, g3, g7 = parameter_rhs(pars, jo, u1, u2, u3, y[3], dts, k, cph, sph)
                Bs[m, k, 0] = g0
                Bs[m, k, 1] = g1
                Bs[m, k, 2] = g2
                Bs[m, k, 3] = g3
                Bs[m, k, 7] = g7
    return fails, ok


@jit(error_model="numpy")
def _differenced(pars, kcs, W, fp, geos, hs, y, gp, gm, Bs, m, k):
    """B_k at ``y`` into ``Bs[m, k]`` by the central difference of the right-hand sides of
    the rows 1 + 2k, 2 + 2k (a parameter without an exact ∂G/∂θ); returns the wrench
    evaluations off target."""
    j = 1 + 2 * k
    fails = _rhs(pars[j], kcs[j], W, row_patch(fp, geos, j), y, gp)
    fails += _rhs(pars[j + 1], kcs[j + 1], W, row_patch(fp, geos, j + 1), y, gm)
    for i in range(NY):
        Bs[m, k, i] = (gp[i] - gm[i]) / (2.0 * hs[k])
    return fails


@jit(error_model="numpy")
def _dense(par, kc, W, fp, y0, h, stg, Kx, F, yt):
    """The dense output's coefficients ``F`` (N_DENSE, NY) of the plain run's step of length
    ``h`` from ``y0`` whose 13 stages are ``stg`` (13 NY): its three extra stages (plain
    right-hand sides) into ``Kx`` (16, NY), then scipy's DOP853 interpolant (7th order);
    returns the wrench evaluations off target."""
    fails = 0
    for j in range(_NS + 1):
        for i in range(NY):
            Kx[j, i] = stg[j * NY + i]
    for e in range(3):  # (the zero columns 1–4 of A_EXTRA, B and D skipped)
        s = _NS + 1 + e
        for i in range(NY):
            yt[i] = 0.0
        for j in range(s):
            c = _AX[e, j]
            if c != 0.0:
                for i in range(NY):
                    yt[i] += c * Kx[j, i]
        for i in range(NY):
            yt[i] = y0[i] + h * yt[i]
        fails += _rhs(par, kc, W, fp, yt, Kx[s])
    for r in range(N_DENSE):
        for i in range(NY):
            F[r, i] = 0.0
    for j in range(16):
        if j < _NS and _B[j] != 0.0:
            for i in range(NY):
                F[0, i] += _B[j] * Kx[j, i]
        for r in range(4):
            c = _D[r, j]
            if c != 0.0:
                for i in range(NY):
                    F[3 + r, i] += c * Kx[j, i]
    for i in range(NY):
        dy = h * F[0, i]
        F[0, i] = dy
        F[1, i] = h * Kx[0, i] - dy
        F[2, i] = 2.0 * dy - h * (Kx[_NS, i] + Kx[0, i])
        for r in range(4):
            F[3 + r, i] *= h
    return fails


@jit(error_model="numpy")
def _tail(S, G, Jc, B, ln_s, Y):
    """Add to the stop's ∂t/∂θ in ``Y`` the derivative of the tail the plain run adds in
    closed form after its last record (:mod:`slidespin.motion._integrator`): t += s/r with
    r = −u·A = −G₃, so ∂t += s S_ln s / r + s ∂(u·A)/∂θ / r², ∂(u·A)/∂θ = J₃ S + B₃ (``G``,
    ``Jc``, ``B`` at the last record). (The tails of x, y, φ are O(s²): below 1e-16 there.)"""
    r = -G[3]
    if not r > 0.0:
        return
    s = math.exp(ln_s)
    for k in range(S.shape[1]):
        dua = B[k, 3]
        for q in range(NCORE):
            dua += Jc[3, q] * S[CORE[q], k]
        Y[NY * (k + 1) + 4] += s * S[3, k] / r + s * dua / (r * r)


@jit(error_model="numpy")
def solve_on_records(
    pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, taus, rows, stages, Y, rec, conv_tol
):
    """S along the plain run's records by Lobatto IIIA collocation
    (:mod:`slidespin.motion._sensitivity_colloc`): ``rows`` (n, NY) are the plain run's states
    at the regularised times ``taus`` (n), ``stages`` its steps' stages, ``Y`` the joint
    start (at ``taus[0]``), on exit the joint state at the last record; rows of ``rec``
    (n, len(Y)) filled. The state inside a step is the step's dense output (from the stages in
    the plain run's records ``stages``). Returns (wrench
    evaluations off target, done): not done where the kernel has no J (a blade, a
    footprint's translation, an ellipse's derivative off its target) or a stage system is
    singular; the caller then integrates the joint system instead."""
    n = taus.size
    npar = hs.size
    nr = Y.size
    gp = np.empty(NY)
    gm = np.empty(NY)
    G = np.empty(NY)  # (G at a point: the collocation needs only J and B)
    Js = np.zeros((NL + 1, NY, NCORE))  # the Lobatto points' J, B; the record's in slot NL
    Bs = np.empty((NL + 1, npar, NY))
    Gr = np.empty(NY)
    yi = np.empty(NY)
    Kx = np.empty((16, NY))
    F = np.empty((N_DENSE, NY))
    K = np.empty((NL, NY, npar))
    Z = np.empty((NL, NY, npar))
    M = np.empty((NCORE * (NL - 1), NCORE * (NL - 1)))
    R = np.empty((NCORE * (NL - 1), npar))
    S = np.empty((NY, npar))
    pieces = np.empty(MAX_PIECES + 1)
    gprev = np.empty(n_rims(fp))
    for k in range(npar):
        for i in range(NY):
            S[i, k] = Y[NY * (k + 1) + i]
    for i in range(nr):
        rec[0, i] = Y[i]
    fails, ok = _node(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, rows[0], gp, gm,
                      G, Js, Bs, 0)  # fmt: skip
    if not ok:
        return fails, False
    last = NL - 1
    for st in range(n - 1):
        y0 = rows[st]
        H = taus[st + 1] - taus[st]
        fails += _dense(pars[0], kcs[0], W, fp, y0, H, stages[st + 1, NY + 1 :], Kx, F, yi)
        npc = step_pieces(pars[0], fp, y0, F, yi, gprev, pieces)
        f, ok = _node(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, rows[st + 1], gp, gm,
                      Gr, Js, Bs, NL)  # fmt: skip
        fails += f
        if not ok:
            return fails, False
        for pc in range(npc):
            f0 = pieces[pc]
            f1 = pieces[pc + 1]
            for m in range(1, NL):
                if m == last and pc == npc - 1:  # the step's end: the record
                    for i in range(NY):
                        for q in range(NCORE):
                            Js[last, i, q] = Js[NL, i, q]
                        for k in range(npar):
                            Bs[last, k, i] = Bs[NL, k, i]
                    continue
                dense_at(f0 + (f1 - f0) * LOBATTO_C[m], y0, F, yi)
                f, ok = _node(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, yi, gp, gm,
                              G, Js, Bs, m)  # fmt: skip
                fails += f
                if not ok:
                    return fails, False
            if not collocation_step(S, K, Z, Js, Bs, H * (f1 - f0), M, R):
                return fails, False
            for i in range(NY):  # the piece's end is the next piece's start
                for q in range(NCORE):
                    Js[0, i, q] = Js[last, i, q]
                for k in range(npar):
                    Bs[0, k, i] = Bs[last, k, i]
        for i in range(NY):
            Y[i] = rows[st + 1, i]
        for k in range(npar):
            for i in range(NY):
                Y[NY * (k + 1) + i] = S[i, k]
        for i in range(nr):
            rec[st + 1, i] = Y[i]
        end = st + 1
        if end == n - 1:
            _tail(S, Gr, Js[NL], Bs[NL], rows[end, 3], Y)
            return fails, True
        if rows[end, 3] < rows[0, 3] - CONVERGED_DROP:
            # the stop's sensitivities converged (|dS/dτ|/rate below conv_tol, as the joint
            # run's test): the rest of the records keep them (their velocities' terms are
            # O(s) there)
            rate = max(abs(Gr[3]), 1e-300)
            worst = 0.0
            for k in range(npar):
                for i in range(4, 8):
                    dS = Bs[NL, k, i]
                    for q in range(NCORE):
                        dS += Js[NL, i, q] * S[CORE[q], k]
                    worst = max(worst, abs(dS) / rate / (1.0 + abs(S[i, k])))
            if worst < conv_tol:
                for i in range(NY):
                    Y[i] = rows[n - 1, i]
                _tail(S, Gr, Js[NL], Bs[NL], rows[end, 3], Y)
                for j in range(end + 1, n):
                    for i in range(nr):
                        rec[j, i] = Y[i] if i >= NY else rows[j, i]
                return fails, True
    return fails, True
