"""Compiled forward-mode sensitivities of the regularised motion (MODEL §5, §15).

The state y of :mod:`slidespin.motion._flow` (u, ln s, t, x, y, φ, ℓ) and, for each
parameter θ_k, its sensitivity S_k = ∂y/∂θ_k at fixed regularised time τ, integrated together:

    dy/dτ = G(y; θ),     dS_k/dτ = (∂G/∂y) S_k + ∂G/∂θ_k       (MODEL §15, in τ).

With the wrench's exact derivatives (:func:`slidespin.contact._engine.accelerations_jacobian`:
analytic on an ellipse, :mod:`slidespin.contact._kernel_ellipse_jac`; differenced in the ICR
on a footprint, :mod:`slidespin.contact._kernel_footprint_jac`) ∂G/∂y is assembled once per
evaluation (:func:`rhs_jacobian`) and serves every parameter; ∂G/∂θ_k is exact for the
parameters that move only the tensor's entries, the radius of gyration, an ellipse's
pressure centre, or the start (:func:`direct_parameters`, :func:`parameter_rhs`). For the
others (a footprint's pressure centre), and at a state where the kernel has no derivative
(the elliptic quadrature's adaptive fallback, a blade, a footprint's translation), the
right-hand side is the directional derivative of the flow along (S_k, e_k) in the joint
(state, parameter) space, a central difference of :func:`slidespin.motion._flow._rhs` with
the step h_k of parameter k,

    (G(y + h_k S_k; θ + h_k e_k) − G(y − h_k S_k; θ − h_k e_k)) / (2 h_k),

the perturbed parameters θ ± h_k e_k reaching the kernels as whole parameter vectors
(``pars``, rows 1 + 2k and 2 + 2k) and, for a footprint, kernel geometries (``geos``); its
error is O(h_k²), about 1e-10 of the derivative, and it costs two wrench evaluations per
parameter and stage (the exact path: one evaluation with derivatives, about three wrenches'
worth, for all parameters).

The integrator is the DOP853 pair of :mod:`slidespin.motion._integrator` (the same
coefficients and error norm) on the joint vector (y, S), the sensitivities of the exact
parameters weighted by ``DIRECT_WEIGHT`` in the error norm and each S_k's components scaled
with a floor at ``SCALE_FLOOR`` of its largest, its steps cut to land on the plain
run's recorded times (or, with ``replay``, those steps themselves without an error test:
an internal differentiation of the integrator in the sense of Bock, cheaper but not accurate
enough at the plain run's tolerance), until s has dropped by ``ln_drop`` and the stop's
sensitivities of t, x, y, φ have converged; no projection and no tail (s is below 1e-13 s₀
there, and the tail is O(s)).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _aot
from slidespin._jit import is_none_type, jit, overload
from slidespin.contact._engine import (
    P_BODY,
    P_K,
    P_LAW,
    P_SHAPE,
    P_T00,
    P_T01,
    P_T10,
    P_T11,
    P_XG,
    P_YG,
    SHAPE_FOOTPRINT,
    accelerations_jacobian,
    footprint_argument,
    kernel_constants,
)
from slidespin.contact._jacobian import JAC_SIZE
from slidespin.contact._kernel_ellipse import tensor_in_body
from slidespin.contact._kernel_ellipse_jac import JAC_WORKSPACE_SHAPE
from slidespin.motion import _dop853 as _dop
from slidespin.motion._flow import NY, _rhs, flow, unit_direction
from slidespin.motion._integrator import _E3, _E5

_NS = _dop.N_STAGES
_A = np.ascontiguousarray(_dop.A)
_B = np.ascontiguousarray(_dop.B)

# status codes of :func:`integrate_sensitivities`
SS_CONVERGED, SS_MAX_STEPS, SS_STEP_TOO_SMALL, SS_NON_FINITE = range(4)
#: weight in the step control of the sensitivities of parameters with exact derivatives
#: (those of central differences weigh 1, the state 1). Measured (tests/analysis/
#: test_sensitivities.py's cases against Richardson differences of whole runs): left out
#: (0) the state's steps leave S under-resolved where the ICR crosses the rim (the wrench
#: is only C¹ there) and ∂t_stop/∂ηc was 1.3e-6 off; 0.2: 1.2e-6; 0.3: within the 1e-6
#: of the tests with a margin of 3 (the worst case left is a differenced parameter's).
#: Steps for 6 parameters of an ellipse: 49 (0), 69 (0.3), 80 (1)
DIRECT_WEIGHT = 0.3
#: a sensitivity's component is controlled relative to the larger of itself and this
#: fraction of its parameter's largest component (the state's scale atol + rtol |y| alone
#: held components that vanish by a symmetry, or start at 0, to atol in the sensitivity's
#: units: measured, the curling stone's 6 parameters took 133 steps, 83 with it; the
#: accuracy of the tests' cases unchanged)
SCALE_FLOOR = 0.1
#: a step up to this factor short of the next output time (a record of the plain run) is
#: stretched to land on it, instead of a step and a sliver (measured, 6 parameters: ellipse
#: 65 -> 51 steps, box 81 -> 68, curling stone 83 -> 69; the tests' accuracy unchanged)
LAND_STRETCH = 1.5
#: rejections of one step after which the run ends with ``SS_STEP_TOO_SMALL`` (each cuts the
#: step by at least 10 %, so a step that converges needs far fewer)
MAX_REJECTIONS = 200


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
    for i in range(NY):
        for j in range(NY):
            Jy[i, j] = 0.0
    # rows ∂G_i/∂u before the normalisation's projection P = (I − uuᵀ)/|z|, kept in the
    # columns 4–6 of Jy (zero in ∂G/∂y) until projected into columns 0–2
    Jy[0, 4], Jy[0, 5], Jy[0, 6] = d00 - u1 * c0 - ua, d01 - u1 * c1, d02 - u1 * c2
    Jy[1, 4], Jy[1, 5], Jy[1, 6] = d10 - u2 * c0, d11 - u2 * c1 - ua, d12 - u2 * c2
    Jy[2, 4], Jy[2, 5], Jy[2, 6] = d20 - u3 * c0, d21 - u3 * c1, d22 - u3 * c2 - ua
    Jy[3, 4], Jy[3, 5], Jy[3, 6] = c0, c1, c2
    Jy[5, 4] = s2
    Jy[6, 5] = s2
    Jy[7, 6] = s2 * ik
    if r > 0.0:
        Jy[8, 4] = s2 * u1 / r
        Jy[8, 5] = s2 * u2 / r
    for i in range(NY):
        g0, g1, g2 = Jy[i, 4], Jy[i, 5], Jy[i, 6]
        gu = g0 * u1 + g1 * u2 + g2 * u3
        Jy[i, 0] = (g0 - gu * u1) * inz
        Jy[i, 1] = (g1 - gu * u2) * inz
        Jy[i, 2] = (g2 - gu * u3) * inz
        Jy[i, 4] = 0.0
        Jy[i, 5] = 0.0
        Jy[i, 6] = 0.0
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


@jit(error_model="numpy", inline="always")
def parameter_rhs(par, jo, y, d, c, sn, out):
    """∂G/∂θ (added to ``out``) for a parameter that moves only the tensor's entries (by
    d𝔽 = (d[0], d[1]; d[2], d[3]) per unit θ, in the tensor's own frame), the radius of
    gyration (by d[4]) and an ellipse's pressure centre G (by (d[5], d[6]) in the body frame):
    exact, from the wrench's isotropic parts and its derivatives in ``jo``
    (:func:`rhs_jacobian` at ``y``; c, sn the cosine and sine of its angle φ); the wrench is
    linear in 𝔽 (MODEL §10)."""
    d00, d01, d10, d11, dk, dxg, dyg = d[0], d[1], d[2], d[3], d[4], d[5], d[6]
    u1, u2, u3, _ = unit_direction(y)
    k = par[P_K]
    e00, e01, e10, e11 = tensor_in_body(d00, d01, d10, d11, par[P_BODY] != 0.0, c, sn)
    fbx = -(e00 * jo[3] + e01 * jo[4])  # F = −𝔽Q, M = −Σ 𝔽_ij N_ij (body frame)
    fby = -(e10 * jo[3] + e11 * jo[4])
    mm = -(e00 * jo[5] + e01 * jo[6] + e10 * jo[7] + e11 * jo[8])
    b1 = c * fbx - sn * fby
    b2 = sn * fbx + c * fby
    if dxg != 0.0 or dyg != 0.0:  # (NaN where the kernel has no ∂W/∂G: never direct there)
        b1 += dxg * jo[21] + dyg * jo[24]
        b2 += dxg * jo[22] + dyg * jo[25]
        mm += dxg * jo[23] + dyg * jo[26]
    b3 = mm / k
    if dk != 0.0:
        dt = -u3 / (k * k) * dk  # the twist's ω = u3/k moves
        b1 += jo[11] * dt
        b2 += jo[14] * dt
        b3 += jo[17] * dt / k - jo[2] / (k * k) * dk
    ub = u1 * b1 + u2 * b2 + u3 * b3
    out[0] += b1 - ub * u1
    out[1] += b2 - ub * u2
    out[2] += b3 - ub * u3
    out[3] += ub
    if dk != 0.0:
        s = math.exp(y[3])
        out[7] -= s * s * u3 / (k * k) * dk


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
    for k in range(npar):
        off = NY * (k + 1)
        if ok and direct[k]:
            # ∂G/∂y has its non-zero columns at u (0–2), ln s (3) and φ (7) only
            s0, s1, s2, s3, s7 = Y[off], Y[off + 1], Y[off + 2], Y[off + 3], Y[off + 7]
            for i in range(NY):
                out[off + i] = (
                    Jy[i, 0] * s0 + Jy[i, 1] * s1 + Jy[i, 2] * s2 + Jy[i, 3] * s3 + Jy[i, 7] * s7
                )
            d = dts[k]
            moved = False
            for i in range(d.size):
                moved = moved or d[i] != 0.0
            if moved:
                parameter_rhs(pars[0], jo, Y[:NY], d, cph, sph, out[off : off + NY])
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
    """Which parameters move only the tensor's entries, k and an ellipse's pressure centre
    (``direct``: their ∂G/∂θ is :func:`parameter_rhs`'s), and their rates (d𝔽, dk, dξ_G,
    dη_G) per unit θ: central differences of the rows (linear in θ for the tensor and G)."""
    npar = hs.size
    direct = np.zeros(npar, dtype=np.bool_)
    dts = np.zeros((npar, 7))
    moved = (P_T00, P_T01, P_T10, P_T11, P_K, P_XG, P_YG)
    ellipse = pars[0, P_SHAPE] != SHAPE_FOOTPRINT
    for k in range(npar):
        p = pars[1 + 2 * k]
        m = pars[2 + 2 * k]
        same = True
        for i in range(pars.shape[1]):
            free = i == P_T00 or i == P_T01 or i == P_T10 or i == P_T11 or i == P_K
            # G moves with the law uniform ↔ linear (the kernel's formulas are the same)
            free = free or (ellipse and (i == P_XG or i == P_YG or i == P_LAW))
            if not free and (p[i] != pars[0, i] or m[i] != pars[0, i]):
                same = False
        for i in range(geos.shape[1]):
            if geos[1 + 2 * k, i] != geos[0, i] or geos[2 + 2 * k, i] != geos[0, i]:
                same = False
        direct[k] = same
        for i in range(7):
            dts[k, i] = (p[moved[i]] - m[moved[i]]) / (2.0 * hs[k])
    return direct, dts


@jit(error_model="numpy", inline="always")
def _combine(Y, K, coef, m, h, out):
    """out = Y + h Σ_{j<m} coef[j] K[j] (a stage's argument, or the new state), the sum
    formed before it is added to Y (added term by term, Y's rounding would enter m times:
    measured 20x larger errors in the early, small sensitivities). The sum runs over the
    stages in the outer loop, the components contiguous inside (it vectorises), in ``out``;
    each component's terms in the same order as one component at a time, zero coefficients
    skipped (they add +0)."""
    n = Y.size
    for i in range(n):
        out[i] = 0.0
    for j in range(m):
        c = coef[j]
        if c != 0.0:
            row = K[j]
            for i in range(n):
                out[i] += c * row[i]
    for i in range(n):
        out[i] = Y[i] + h * out[i]


@jit(error_model="numpy")
def _joint_err_norm(K, h, scale, weight, a5, a3):
    """The integrator's DOP853 error norm (:func:`slidespin.motion._integrator._err_norm`)
    with a weight per component (0: left out); ``a5``, ``a3`` are work arrays."""
    n = scale.size
    for i in range(n):
        a5[i] = 0.0
        a3[i] = 0.0
    for j in range(_NS + 1):
        c5 = _E5[j]
        c3 = _E3[j]
        row = K[j]
        for i in range(n):
            a5[i] += c5 * row[i]
            a3[i] += c3 * row[i]
    e5 = 0.0
    e3 = 0.0
    m = 0
    for i in range(n):
        if weight[i] != 0.0:
            m += 1
            w = weight[i] / scale[i]
            e5 += (a5[i] * w) ** 2
            e3 += (a3[i] * w) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * m)


@jit(error_model="numpy")
def _converged_measure(Y, F, npar, rate):
    """How far the stop's sensitivities still move: the largest |dS/dτ| / rate over the
    components t, x, y, φ, relative to 1 + |S| (they converge with s, at the rate of ln s)."""
    worst = 0.0
    for k in range(npar):
        off = NY * (k + 1)
        for i in range(4, 8):
            d = abs(F[off + i]) / rate / (1.0 + abs(Y[off + i]))
            if d > worst:
                worst = d
    return worst


@jit(error_model="numpy")
def integrate_sensitivities(
    pars, fp, geos, hs, Y0, rtol, atol, ln_drop, conv_tol, replay, max_steps, taus, yterm
):
    """Integrate the joint system from ``Y0`` until the stop's sensitivities converge.

    Parameters
    ----------
    pars : ndarray (1 + 2p, NPAR)
        The parameter vector, then for each parameter k the vectors at θ ± h_k e_k.
    fp : None or tuple
        ``None`` for an ellipse; else the footprint's (edges, circles, geo) (the geo unused:
        row j of ``geos`` is used with row j of ``pars``).
    geos : ndarray (1 + 2p, NGEO)
        Footprint kernel geometries per row (ignored for an ellipse).
    hs : ndarray (p,)
        The parameters' steps h_k (in the parameters' own units).
    Y0 : ndarray (NY (1 + p),)
        Initial state and sensitivities.
    rtol, atol : float
        Step-size control on the joint vector.
    ln_drop : float
        Integration goes on at least until ln s < ln s₀ − ``ln_drop``.
    conv_tol : float
        Then until :func:`_converged_measure` is below it.
    replay : bool
        Take the steps ``taus`` themselves (the accepted steps of the plain run, whose error
        control chose them for the motion) without an error test, then go on with error
        control to convergence; else cut the error-controlled steps to land on ``taus``.
    max_steps : int
        Step budget.
    taus : ndarray (n,)
        Increasing regularised times at which to record (Y, dY/dτ); steps are cut to land on
        them exactly.
    yterm : ndarray (NY,)
        A state (the plain run's stop) at which to return the terms of
        :func:`stop_terms`.

    Returns
    -------
    Y : ndarray
        The joint state at the end.
    F : ndarray
        Its rate dY/dτ there.
    status : int
        ``SS_CONVERGED``, ``SS_MAX_STEPS``, ``SS_STEP_TOO_SMALL`` or ``SS_NON_FINITE``.
    n_steps, fails : int
        Accepted steps; wrench evaluations above their error target.
    rec : ndarray (n, len(Y))
        Y at the times ``taus`` that were reached (rows beyond remain NaN).
    term : ndarray (NY + p, NY)
        :func:`stop_terms` at ``yterm``.
    """
    n = Y0.size
    npar = hs.size
    kcs = [kernel_constants(pars[j]) for j in range(pars.shape[0])]
    W = np.empty(JAC_WORKSPACE_SHAPE)  # the wrench's rows and the derivatives'
    jo = np.empty(JAC_SIZE)
    Jy = np.empty((NY, NY))
    direct, dts = direct_parameters(pars, geos, hs)
    weight = np.ones(n)
    for k in range(npar):
        if direct[k]:
            weight[NY * (k + 1) : NY * (k + 2)] = DIRECT_WEIGHT
    yp = np.empty(NY)
    ym = np.empty(NY)
    gp = np.empty(NY)
    gm = np.empty(NY)
    Y = Y0.copy()
    K = np.empty((_NS + 1, n))
    Yt = np.empty(n)
    Ynew = np.empty(n)
    scale = np.empty(n)
    a5 = np.empty(n)
    a3 = np.empty(n)
    F = np.empty(n)
    rec = np.full((taus.size, n), np.nan)
    fails = joint_rhs(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, Y, F, yp, ym, gp, gm)
    ln_s0 = Y[3]
    tau = 0.0
    nxt = 0
    while nxt < taus.size and taus[nxt] <= 0.0:
        for i in range(n):
            rec[nxt, i] = Y[i]
        nxt += 1
    fm = math.sqrt(F[0] ** 2 + F[1] ** 2 + F[2] ** 2 + F[3] ** 2)
    h = 0.01 / max(fm, 1e-3)
    exponent = -1.0 / 8.0
    status = SS_MAX_STEPS
    nsteps = 0
    while nsteps < max_steps:
        rejected = False
        rejections = 0
        landed = False
        while True:
            hh = h
            landed = False
            # a step a little short of an output time is stretched to land on it (not after
            # a rejection: the retry would land on it again)
            stretch = 1.0 if rejected else LAND_STRETCH
            if nxt < taus.size and (replay or tau + stretch * hh >= taus[nxt]):
                hh = taus[nxt] - tau
                landed = True
            if not hh >= 1e-12 * (1.0 + tau):
                if landed and hh >= 0.0:  # on an output time already: record it and go on
                    for i in range(n):
                        rec[nxt, i] = Y[i]
                    nxt += 1
                    continue
                status = SS_STEP_TOO_SMALL if hh == hh else SS_NON_FINITE
                break
            for i in range(n):
                K[0, i] = F[i]
            for st in range(1, _NS):
                _combine(Y, K, _A[st], st, hh, Yt)
                fails += joint_rhs(
                    pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, Yt, K[st], yp, ym, gp, gm
                )
            _combine(Y, K, _B, _NS, hh, Ynew)
            fails += joint_rhs(
                pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, Ynew, K[_NS], yp, ym, gp, gm
            )
            for i in range(n):
                scale[i] = atol + max(abs(Y[i]), abs(Ynew[i])) * rtol
            scale[7] = atol  # the body angle to an absolute tolerance, as the integrator
            for k in range(npar):
                off = NY * (k + 1)
                big = 0.0
                for i in range(off, off + NY):
                    big = max(big, abs(Y[i]))
                for i in range(off, off + NY):
                    scale[i] = max(scale[i], SCALE_FLOOR * rtol * big)
            en = _joint_err_norm(K, hh, scale, weight, a5, a3)
            if not math.isfinite(en):
                status = SS_NON_FINITE
                break
            if replay and landed:  # the plain run's own step: accepted as it was there
                tau = taus[nxt]
                h = hh
                break
            if en < 1.0:
                factor = 10.0 if en == 0.0 else min(10.0, 0.9 * en**exponent)
                if rejected:
                    factor = min(1.0, factor)
                tau += hh
                if not landed or hh >= h:
                    h = hh * factor
                break
            h = hh * max(0.2, 0.9 * en**exponent)
            rejected = True
            rejections += 1
            if rejections > MAX_REJECTIONS:  # (a guard: no step may hang the run)
                status = SS_STEP_TOO_SMALL
                break
        if status == SS_STEP_TOO_SMALL or status == SS_NON_FINITE:
            break
        for i in range(n):
            Y[i] = Ynew[i]
            F[i] = K[_NS, i]
        nsteps += 1
        if landed:
            for i in range(n):
                rec[nxt, i] = Y[i]
            nxt += 1
        if Y[3] < ln_s0 - ln_drop and nxt >= taus.size:
            rate = max(abs(F[3]), 1e-300)
            if _converged_measure(Y, F, npar, rate) < conv_tol:
                status = SS_CONVERGED
                break
    term = stop_terms(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, yterm)
    return Y, F, status, nsteps, fails, rec, term


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


def run(pars, fe, fc, geos, hs, Y0, rtol, atol, ln_drop, conv_tol, replay, max_steps, taus, yterm):
    """:func:`integrate_sensitivities` for the rows ``pars`` (and ``geos``) and the footprint
    arrays ``fe``, ``fc`` (empty for an ellipse): run by the ahead-of-time compiled core when
    the install built one from these sources (:mod:`slidespin._aot`), else by the JIT."""
    pars = np.ascontiguousarray(pars, dtype=np.float64)
    geos = np.ascontiguousarray(geos, dtype=np.float64)
    tail = (
        np.ascontiguousarray(hs, dtype=np.float64),
        np.ascontiguousarray(Y0, dtype=np.float64),
        float(rtol), float(atol), float(ln_drop), float(conv_tol), bool(replay),
        int(max_steps), np.ascontiguousarray(taus, dtype=np.float64),
        np.ascontiguousarray(yterm, dtype=np.float64),
    )  # fmt: skip
    footprint = pars[0, P_SHAPE] == SHAPE_FOOTPRINT
    aot = _aot.core()
    if aot is not None:
        if footprint:
            return aot.sensitivities_footprint(pars, fe, fc, geos, *tail)
        return aot.sensitivities_ellipse(pars, geos, *tail)
    fp = footprint_argument(pars[0], fe, fc, geos[0])
    return integrate_sensitivities(pars, fp, geos, *tail)
