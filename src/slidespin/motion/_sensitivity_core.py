"""Compiled forward-mode sensitivities of the regularised motion (MODEL §5, §15).

The state y of :mod:`slidespin.motion._flow` (u, ln s, t, x, y, φ, ℓ) and, for each
parameter θ_k, its sensitivity S_k = ∂y/∂θ_k at fixed regularised time τ, integrated together:

    dy/dτ = G(y; θ),     dS_k/dτ = (∂G/∂y) S_k + ∂G/∂θ_k       (MODEL §15, in τ).

The right-hand side and its derivatives are those of
:mod:`slidespin.motion._sensitivity_rhs`.

Two routes (:func:`integrate_sensitivities`):

- **Collocation on the plain run's steps** (``collocate``;
  :mod:`slidespin.motion._sensitivity_colloc`): S is linear and the motion is known, so S is
  solved step by step of the plain run by Lobatto IIIA collocation (order 8, four
  evaluations of G, ∂G/∂y and ∂G/∂θ per step), the state inside a step being the plain
  step's DOP853 dense output (its stages are in the plain run's records; three plain
  right-hand sides more per step); a step across which the ICR crosses the patch's rim
  (where the wrench is only C¹) is split there and graded; once s < 1e-8 s₀ and the stop's
  sensitivities have converged the later records keep them, and the tail the plain run adds
  in closed form is differentiated. About 2x a plain run's work for 6
  parameters, as accurate as the joint route (measured against the Richardson references of
  tests/analysis/test_sensitivities.py: worst 3e-7, a differenced parameter; typically
  1e-8 to 1e-10).
- **The joint integration** (the other route: a tolerance looser than the plain run's
  default, or no ∂G/∂y somewhere): the DOP853 pair of :mod:`slidespin.motion._integrator`
  (the same coefficients and error norm) on the joint vector (y, S), the sensitivities of
  the exact parameters weighted by ``DIRECT_WEIGHT`` in the error norm and each S_k's
  components scaled with a floor at ``SCALE_FLOOR`` of its largest, its steps cut to land on
  the plain run's recorded times, until s has dropped by ``ln_drop`` and the stop's
  sensitivities of t, x, y, φ have converged; no projection and no tail (s is below 1e-13 s₀
  there, and the tail is O(s)). (Taking the plain run's steps without an error test, an
  internal differentiation in the sense of Bock, was measured 1e-6 to 1e-5 off where the ICR
  crosses a rim: not done.)
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _aot
from slidespin._jit import jit
from slidespin.contact._engine import P_SHAPE, SHAPE_FOOTPRINT, footprint_argument, kernel_constants
from slidespin.contact._jacobian import JAC_SIZE
from slidespin.contact._kernel_ellipse_jac import JAC_WORKSPACE_SHAPE
from slidespin.motion import _dop853 as _dop
from slidespin.motion._flow import NY
from slidespin.motion._integrator import _E3, _E5
from slidespin.motion._sensitivity_colloc import solve_on_records
from slidespin.motion._sensitivity_rhs import direct_parameters, joint_rhs, stop_terms

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
    pars, fp, geos, hs, Y0, rtol, atol, ln_drop, conv_tol, collocate, max_steps, taus, rows,
    stages, yterm,
):  # fmt: skip
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
    collocate : bool
        Solve for S along the plain run's records (``taus``, ``rows``) by collocation
        (:func:`slidespin.motion._sensitivity_colloc.collocate`), then go on with the joint integration from the last record
        only if the stop's sensitivities have not converged there; else (or where the
        collocation cannot be done) integrate the joint system from ``Y0``, its steps cut
        to land on ``taus``.
    max_steps : int
        Step budget.
    taus : ndarray (n,)
        Increasing regularised times at which to record (Y, dY/dτ); steps are cut to land on
        them exactly.
    rows : ndarray (n, NY)
        The plain run's states at ``taus`` (used with ``collocate``).
    stages : ndarray (n, 1 + NY + 13 NY)
        The plain run's records with its steps' stages (used with ``collocate``: the
        records of :func:`slidespin.motion._integrator.integrate_fp` with ``stages``).
    yterm : ndarray (NY,)
        A state (the plain run's stop) at which to return the terms of
        :func:`stop_terms`.

    Returns
    -------
    Y : ndarray
        The joint state at the end.
    F : ndarray
        Its rate dY/dτ there (zeros after a collocation: not formed).
    status : int
        ``SS_CONVERGED``, ``SS_MAX_STEPS``, ``SS_STEP_TOO_SMALL`` or ``SS_NON_FINITE``.
    n_steps, fails : int
        Accepted steps (the plain run's records collocated count as steps); wrench
        evaluations above their error target.
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
    ln_s0 = Y[3]
    tau = 0.0
    nxt = 0
    nsteps = 0
    status = SS_MAX_STEPS
    fails = 0
    done = False
    if collocate and taus.size > 1 and taus[0] == 0.0:
        f, done = solve_on_records(
            pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, taus, rows, stages, Y, rec, conv_tol
        )
        fails += f
        if done:
            tau = taus[-1]
            nxt = taus.size
            nsteps = taus.size - 1
        else:  # (no derivative somewhere: the joint integration from the start)
            for i in range(n):
                Y[i] = Y0[i]
                for j in range(taus.size):
                    rec[j, i] = math.nan
    if done:  # (to the stop: the tail in closed form; F is not needed)
        status = SS_CONVERGED
        max_steps = 0
        for i in range(n):
            F[i] = 0.0
    else:
        fails += joint_rhs(pars, kcs, W, jo, Jy, fp, geos, hs, direct, dts, Y, F, yp, ym, gp, gm)
    while nxt < taus.size and taus[nxt] <= 0.0:
        for i in range(n):
            rec[nxt, i] = Y[i]
        nxt += 1
    fm = math.sqrt(F[0] ** 2 + F[1] ** 2 + F[2] ** 2 + F[3] ** 2)
    h = 0.01 / max(fm, 1e-3)
    if done:  # going on from the last record: the plain run's last step
        h = taus[-1] - taus[-2]
    exponent = -1.0 / 8.0
    max_steps += nsteps
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
            if nxt < taus.size and tau + stretch * hh >= taus[nxt]:
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
def fixed_time(rows, accel, rec, Y, k, dk, a, t_unit, v_unit):
    """The path's derivatives at fixed t from those at fixed τ (:func:`integrate_sensitivities`'
    ``rec`` at the records, then ``Y`` at the stop): ∂q/∂θ|t = ∂q/∂θ|τ − q̇ ∂t/∂θ|τ for
    q = x, y, φ, vx, vy, ω (SI), with v = s u, so ∂v/∂θ|τ = s (u S_ln s + S_u) (S_u's radial
    part is round-off); ``rows`` (n, NY) the plain run's states (the stop's last),
    ``accel`` (n, 3) its natural accelerations (Fx, Fy, M/k), ``k`` the natural radius of
    gyration and ``dk`` (p,) its ∂k/∂θ. Returns (6, n, p); the stop's velocities and their
    derivatives are 0."""
    n = rows.shape[0]
    npar = dk.size
    out = np.empty((6, n, npar))
    for j in range(n):
        u1, u2, u3 = rows[j, 0], rows[j, 1], rows[j, 2]
        inv = 1.0 / math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
        u1, u2, u3 = u1 * inv, u2 * inv, u3 * inv
        s = math.exp(rows[j, 3])
        ax, ay, am = accel[j, 0], accel[j, 1], accel[j, 2]
        for q in range(npar):
            off = NY * (q + 1)
            S = Y[off:] if j == n - 1 else rec[j, off:]
            st = S[4]
            out[0, j, q] = (S[5] - s * u1 * st) * a
            out[1, j, q] = (S[6] - s * u2 * st) * a
            out[2, j, q] = S[7] - s * u3 / k * st
            if j == n - 1:
                out[3, j, q] = out[4, j, q] = out[5, j, q] = 0.0
                continue
            out[3, j, q] = (s * (u1 * S[3] + S[0]) - ax * st) * v_unit
            out[4, j, q] = (s * (u2 * S[3] + S[1]) - ay * st) * v_unit
            out[5, j, q] = ((s * (u3 * S[3] + S[2]) - am * st) / k
                            - s * u3 * dk[q] / (k * k)) / t_unit  # fmt: skip
    return out


@jit(error_model="numpy")
def terminal_direction(u, term, s_phi):
    """∂u*/∂θ (p, 3) of a mixed ending's terminal direction u* by the implicit function
    theorem on T(u*, φ*; θ) = 0 in the tangent plane at u*:
    J_T ∂u* = −(∂T/∂φ ∂φ*/∂θ + ∂T/∂θ), from the exact terms ``term`` of :func:`stop_terms`
    and ∂φ*/∂θ = ``s_phi``; and whether it could (the terms finite, J_T well conditioned:
    its |λ| ratio above 1e-7; else the caller's general route,
    :func:`slidespin.motion.sensitivity._terminal_sensitivity`)."""
    npar = s_phi.size
    su = np.full((npar, 3), np.nan)
    for i in range(NY):
        for j in range(NY):
            if not math.isfinite(term[i, j]):
                return su, False
    nrm = math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])
    u0, u1, u2 = u[0] / nrm, u[1] / nrm, u[2] / nrm
    # an orthonormal basis (b, c) of the tangent plane: b from the axis u is least along
    ax = 0
    if abs(u1) < abs(u0):
        ax = 1
    if abs(u2) < min(abs(u0), abs(u1)):
        ax = 2
    e = np.zeros(3)
    e[ax] = 1.0
    uu = (u0, u1, u2)
    eu = uu[ax]
    b0, b1, b2 = e[0] - eu * u0, e[1] - eu * u1, e[2] - eu * u2
    bn = math.sqrt(b0 * b0 + b1 * b1 + b2 * b2)
    b0, b1, b2 = b0 / bn, b1 / bn, b2 / bn
    c0, c1, c2 = u1 * b2 - u2 * b1, u2 * b0 - u0 * b2, u0 * b1 - u1 * b0
    B = np.array([[b0, c0], [b1, c1], [b2, c2]])
    jt = np.zeros((2, 2))
    for r in range(2):
        for q in range(2):
            acc = 0.0
            for i in range(3):
                for j in range(3):
                    acc += B[i, r] * term[i, j] * B[j, q]
            jt[r, q] = acc
    tr = jt[0, 0] + jt[1, 1]
    det = jt[0, 0] * jt[1, 1] - jt[0, 1] * jt[1, 0]
    disc = 0.25 * tr * tr - det
    if disc < 0.0:
        small = big = math.sqrt(det)
    else:
        root = math.sqrt(disc)
        small = min(abs(0.5 * tr - root), abs(0.5 * tr + root))
        big = max(abs(0.5 * tr - root), abs(0.5 * tr + root))
    if not (small > 1e-7 * big and det != 0.0):
        return su, False
    for k in range(npar):
        r0 = 0.0
        r1 = 0.0
        for i in range(3):
            rhs = term[i, 7] * s_phi[k] + term[NY + k, i]
            r0 -= B[i, 0] * rhs
            r1 -= B[i, 1] * rhs
        x0 = (jt[1, 1] * r0 - jt[0, 1] * r1) / det
        x1 = (-jt[1, 0] * r0 + jt[0, 0] * r1) / det
        for i in range(3):
            su[k, i] = B[i, 0] * x0 + B[i, 1] * x1
    return su, True


def path_at_fixed_time(rows, accel, rec, Y, k, dk, a, t_unit, v_unit):
    """:func:`fixed_time`, run by the ahead-of-time compiled core when there is one."""
    args = (
        np.ascontiguousarray(rows, dtype=np.float64),
        np.ascontiguousarray(accel, dtype=np.float64),
        np.ascontiguousarray(rec, dtype=np.float64),
        np.ascontiguousarray(Y, dtype=np.float64),
        float(k),
        np.ascontiguousarray(dk, dtype=np.float64),
        float(a), float(t_unit), float(v_unit),
    )  # fmt: skip
    aot = _aot.core()
    return (aot.fixed_time if aot is not None else fixed_time)(*args)


def terminal_direction_sensitivity(u, term, s_phi):
    """:func:`terminal_direction`, run by the ahead-of-time compiled core when there is one."""
    args = (
        np.ascontiguousarray(u, dtype=np.float64),
        np.ascontiguousarray(term, dtype=np.float64),
        np.ascontiguousarray(s_phi, dtype=np.float64),
    )
    aot = _aot.core()
    return (aot.terminal_direction if aot is not None else terminal_direction)(*args)


def run(
    pars, fe, fc, geos, hs, Y0, rtol, atol, ln_drop, conv_tol, collocate, max_steps, taus, rows,
    stages, yterm,
):  # fmt: skip
    """:func:`integrate_sensitivities` for the rows ``pars`` (and ``geos``) and the footprint
    arrays ``fe``, ``fc`` (empty for an ellipse): run by the ahead-of-time compiled core when
    the install built one from these sources (:mod:`slidespin._aot`), else by the JIT."""
    pars = np.ascontiguousarray(pars, dtype=np.float64)
    geos = np.ascontiguousarray(geos, dtype=np.float64)
    tail = (
        np.ascontiguousarray(hs, dtype=np.float64),
        np.ascontiguousarray(Y0, dtype=np.float64),
        float(rtol), float(atol), float(ln_drop), float(conv_tol), bool(collocate),
        int(max_steps), np.ascontiguousarray(taus, dtype=np.float64),
        np.ascontiguousarray(rows, dtype=np.float64),
        np.ascontiguousarray(stages, dtype=np.float64),
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
