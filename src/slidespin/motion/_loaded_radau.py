"""Compiled implicit integration of a stiff loaded slip (MODEL §11): Radau IIA of order 5.

A slip that starts from rest near the threshold is stiff: the direction u relaxes in a τ of
order 1 while the motion evolves over 1/|u·X|, which is large while the load is barely
beyond the static-friction set (:mod:`slidespin.motion._stick_slip`). The Python path
integrates it with ``scipy.integrate.Radau`` in τ; this is the same method (the collocation,
its simplified Newton iteration, the error estimate and the step-size control of scipy's
``Radau``, after Hairer & Wanner, *Solving ODEs II*, §IV.8), compiled, on the right-hand
sides of :mod:`slidespin.motion._loaded_flow`:

* ``MODE_T``: in the time t itself, with s in place of ln s. A start from rest grows like a
  polynomial in t (s ∝ (t − t₀)² under a ramp), which a collocation method follows in a few
  steps, while in τ that growth has a pole (t − t₀ ∝ 1/(τ∞ − τ)) that costs a step count
  proportional to its logarithm (measured on the pushed box: 35 steps in t where τ takes
  375). The knots of the load and ``t_end`` cut the steps exactly. The form is singular at
  s = 0, so a speed that falls below half its peak ends this mode (``R_DECAY``: the
  regularised time takes over);
* ``MODE_TAU``: in τ, for a stiff approach to rest (a load that stalls near the threshold);
  ``t_end`` and the knots are located as by :mod:`slidespin.motion._loaded_dop853` (the
  collocation polynomial's guess, one step again, an Euler step for the last difference),
  and ln s below ``ln_stop`` is the stop (closed-form tail).

Either mode ends with ``R_SWITCH`` once the problem is no longer stiff (the ratio of
:func:`~slidespin.motion._loaded_flow.stiffness` at most ``stiff_min``, looked at each time
ln s has moved by 1): the explicit DOP853 then continues. The Jacobian is a forward
difference in the six entries that feed back (u, s or ln s, t, φ). A singular iteration
matrix or non-finite stages count as a failed Newton iteration (the step is halved).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._engine import P_K, kernel_constants
from slidespin.contact._kernel_ellipse import WORKSPACE_SHAPE
from slidespin.motion._loaded_dop853 import (
    NROW,
    R_DECAY,
    R_FAILED,
    R_MAX_STEPS,
    R_STOP,
    R_SWITCH,
    R_T_END,
    closed_tail,
    initial_step,
    initial_trial,
    push_row,
    speed_of,
)
from slidespin.motion._loaded_flow import MODE_T, NOUT, NY, rhs, stiffness

_S6 = 6.0**0.5
_RC = np.array([(4.0 - _S6) / 10.0, (4.0 + _S6) / 10.0, 1.0])
_RE = np.array([-13.0 - 7.0 * _S6, -13.0 + 7.0 * _S6, -1.0]) / 3.0
_MU_REAL = 3.0 + 3.0 ** (2.0 / 3.0) - 3.0 ** (1.0 / 3.0)
_MU_CRE = 3.0 + 0.5 * (3.0 ** (1.0 / 3.0) - 3.0 ** (2.0 / 3.0))
_MU_CIM = -0.5 * (3.0 ** (5.0 / 6.0) + 3.0 ** (7.0 / 6.0))
_T = np.array(
    [
        [0.09443876248897524, -0.14125529502095421, 0.03002919410514742],
        [0.25021312296533332, 0.20412935229379994, -0.38294211275726192],
        [1.0, 1.0, 0.0],
    ]
)
_TI = np.array(
    [
        [4.17871859155190428, 0.32768282076106237, 0.52337644549944951],
        [-4.17871859155190428, -0.32768282076106237, 0.47662355450055044],
        [0.50287263494578682, -2.57192694985560522, 0.59603920482822492],
    ]
)
_P = np.array(
    [
        [13.0 / 3.0 + 7.0 * _S6 / 3.0, -23.0 / 3.0 - 22.0 * _S6 / 3.0, 10.0 / 3.0 + 5.0 * _S6],
        [13.0 / 3.0 - 7.0 * _S6 / 3.0, -23.0 / 3.0 + 22.0 * _S6 / 3.0, 10.0 / 3.0 - 5.0 * _S6],
        [1.0 / 3.0, -8.0 / 3.0, 10.0 / 3.0],
    ]
)
_NEWTON_MAXITER = 6
_EPS = float(np.finfo(float).eps)
#: the state entries that feed back into the right-hand side (u, s or ln s, t, φ): the
#: columns of the difference Jacobian (the others are zero)
_COLS = np.array([0, 1, 2, 3, 4, 7], dtype=np.int64)


@jit(error_model="numpy")
def _lu(a, piv):
    """LU factorisation with partial pivoting, in place (real or complex); False if
    singular."""
    n = a.shape[0]
    for k in range(n):
        p = k
        big = abs(a[k, k])
        for i in range(k + 1, n):
            if abs(a[i, k]) > big:
                big = abs(a[i, k])
                p = i
        piv[k] = p
        if big == 0.0 or not math.isfinite(big):
            return False
        if p != k:
            for j in range(n):
                tmp = a[k, j]
                a[k, j] = a[p, j]
                a[p, j] = tmp
        for i in range(k + 1, n):
            a[i, k] /= a[k, k]
            m = a[i, k]
            for j in range(k + 1, n):
                a[i, j] -= m * a[k, j]
    return True


@jit(error_model="numpy")
def _lu_solve(a, piv, b):
    """Solve with the factors of :func:`_lu`, b overwritten by the solution."""
    n = a.shape[0]
    for k in range(n):
        p = piv[k]
        if p != k:
            tmp = b[k]
            b[k] = b[p]
            b[p] = tmp
    for i in range(1, n):
        acc = b[i]
        for j in range(i):
            acc -= a[i, j] * b[j]
        b[i] = acc
    for i in range(n - 1, -1, -1):
        acc = b[i]
        for j in range(i + 1, n):
            acc -= a[i, j] * b[j]
        b[i] = acc / a[i, i]


@jit(error_model="numpy")
def _rms(v, scale):
    acc = 0.0
    for i in range(v.size):
        acc += (v[i] / scale[i]) ** 2
    return math.sqrt(acc / v.size)


@jit(error_model="numpy")
def _jacobian(par, kc, W, fp, tab, mode, y, f, J):
    """Forward-difference Jacobian in the columns _COLS; returns kernel calls."""
    yh = y.copy()
    fh = np.empty(NOUT)
    calls = 0
    for i in range(NY):
        for j in range(NY):
            J[i, j] = 0.0
    for c in range(_COLS.size):
        j = _COLS[c]
        h = 1e-7 * max(1.0, abs(y[j]))
        if mode == MODE_T and j == 3:
            h = 1e-7 * abs(y[3])  # s: a relative difference (s may be tiny)
        yh[j] = y[j] + h
        _, n = rhs(par, kc, W, fp, tab, mode, yh, fh)
        calls += n
        yh[j] = y[j]
        for i in range(NY):
            J[i, j] = (fh[i] - f[i]) / h
    return calls


@jit(error_model="numpy")
def _factor(J, h, LUr, pivr, LUc, pivc):
    """The iteration matrices MU_REAL/h − J and MU_COMPLEX/h − J, factorised."""
    mr = _MU_REAL / h
    mc = complex(_MU_CRE, _MU_CIM) / h
    for i in range(NY):
        for j in range(NY):
            LUr[i, j] = -J[i, j]
            LUc[i, j] = -J[i, j]
        LUr[i, i] += mr
        LUc[i, i] += mc
    return _lu(LUr, pivr) and _lu(LUc, pivc)


@jit(error_model="numpy")
def _collocation(par, kc, W, fp, tab, mode, y, h, Z0, scale, tol, LUr, pivr, LUc, pivc, Z, F):
    """scipy's ``solve_collocation_system``: returns (converged, iterations, rate, calls,
    status); Z holds the stage increments."""
    mr = _MU_REAL / h
    mc = complex(_MU_CRE, _MU_CIM) / h
    Wm = np.zeros((3, NY))
    for i in range(3):
        for j in range(NY):
            acc = 0.0
            for m in range(3):
                acc += _TI[i, m] * Z0[m, j]
            Wm[i, j] = acc
            Z[i, j] = Z0[i, j]
    yt = np.empty(NY)
    fr = np.empty(NY)
    fc = np.empty(NY, dtype=np.complex128)
    dW = np.empty((3, NY))
    dw_old = -1.0
    rate = -1.0
    converged = False
    calls = 0
    status = 0
    k = 0
    for k in range(_NEWTON_MAXITER):
        finite = True
        for i in range(3):
            for j in range(NY):
                yt[j] = y[j] + Z[i, j]
            st, c = rhs(par, kc, W, fp, tab, mode, yt, F[i])
            calls += c
            status += st
            for j in range(NY):
                if not math.isfinite(F[i, j]):
                    finite = False
        if not finite:
            break
        for j in range(NY):
            fr[j] = _TI[0, 0] * F[0, j] + _TI[0, 1] * F[1, j] + _TI[0, 2] * F[2, j] - mr * Wm[0, j]
            cre = _TI[1, 0] * F[0, j] + _TI[1, 1] * F[1, j] + _TI[1, 2] * F[2, j]
            cim = _TI[2, 0] * F[0, j] + _TI[2, 1] * F[1, j] + _TI[2, 2] * F[2, j]
            fc[j] = complex(cre, cim) - mc * complex(Wm[1, j], Wm[2, j])
        _lu_solve(LUr, pivr, fr)
        _lu_solve(LUc, pivc, fc)
        acc = 0.0
        for j in range(NY):
            dW[0, j] = fr[j]
            dW[1, j] = fc[j].real
            dW[2, j] = fc[j].imag
            for i in range(3):
                acc += (dW[i, j] / scale[j]) ** 2
        dw = math.sqrt(acc / (3 * NY))
        if not math.isfinite(dw):
            break
        if dw_old >= 0.0:
            rate = dw / dw_old
        if rate >= 0.0 and (rate >= 1.0 or rate ** (_NEWTON_MAXITER - k) / (1.0 - rate) * dw > tol):
            break
        for i in range(3):
            for j in range(NY):
                Wm[i, j] += dW[i, j]
        for i in range(3):
            for j in range(NY):
                Z[i, j] = _T[i, 0] * Wm[0, j] + _T[i, 1] * Wm[1, j] + _T[i, 2] * Wm[2, j]
        if dw == 0.0 or (rate >= 0.0 and rate / (1.0 - rate) * dw < tol):
            converged = True
            break
        dw_old = dw
    return converged, k + 1, rate, calls, status


@jit(error_model="numpy")
def _predict(h_abs, h_old, err, err_old):
    if err_old < 0.0 or h_old < 0.0 or err == 0.0:
        mult = 1.0
    else:
        mult = h_abs / h_old * (err_old / err) ** 0.25
    if err == 0.0:
        return math.inf
    return min(1.0, mult) * err**-0.25


@jit(error_model="numpy")
def _dense(Q, y_old, theta, out):
    """The collocation polynomial of the last step at fraction θ of it."""
    for j in range(NY):
        out[j] = y_old[j] + Q[j, 0] * theta + Q[j, 1] * theta**2 + Q[j, 2] * theta**3


@jit(error_model="numpy")
def run_radau(
    par, fp, tab, mode, y0, rtol, atol, h_max, t_end, breaks, ln_stop, stiff_min, steps, record
):
    """Integrate a stiff slip in ``mode`` (``MODE_T`` or ``MODE_TAU``) from y0 (module
    docstring).

    Returns (y, reason, n_steps, n_calls, n_fail, rec): the state at the end, ``R_SWITCH``,
    ``R_DECAY``, ``R_T_END``, ``R_STOP`` (τ only; tail added), ``R_MAX_STEPS`` or
    ``R_FAILED``, accepted steps, kernel calls, wrench evaluations above their target, and
    the rows of the accepted steps (empty unless ``record``).
    """
    k = par[P_K]
    kc = kernel_constants(par)
    W = np.empty(WORKSPACE_SHAPE)
    in_t = mode == MODE_T
    y = y0.copy()
    f = np.empty(NOUT)
    fnew = np.empty(NOUT)
    st, calls = rhs(par, kc, W, fp, tab, mode, y, f)
    nfail = 1 if st != 0 else 0
    rec = np.empty((64 if record else 0, NROW))
    nrec = 0
    J = np.zeros((NY, NY))
    calls += _jacobian(par, kc, W, fp, tab, mode, y, f, J)
    current_jac = True
    LUr = np.empty((NY, NY))
    LUc = np.empty((NY, NY), dtype=np.complex128)
    pivr = np.empty(NY, dtype=np.int64)
    pivc = np.empty(NY, dtype=np.int64)
    lu_ok = False
    Z = np.empty((3, NY))
    Z0 = np.empty((3, NY))
    F = np.empty((3, NOUT))
    Q = np.empty((NY, 3))
    y_old = np.empty(NY)
    y_new = np.empty(NY)
    ye = np.empty(NY)
    scale = np.empty(NY)
    err_v = np.empty(NY)
    have_dense = False
    h_dense = 1.0
    nb = breaks.size
    ib = 0
    while ib < nb and breaks[ib] <= y[4]:
        ib += 1
    target = min(t_end, breaks[ib] if ib < nb else math.inf)
    newton_tol = max(10.0 * _EPS / rtol, min(0.03, rtol**0.5))
    s_now = speed_of(y, mode)
    h_cap = h_max * s_now if in_t else h_max
    span = (target - y[4]) if in_t else 1e4
    span = max(span, 1e-300)
    h0, d1 = initial_trial(y, f, span, rtol, atol, ye, False)
    _, c = rhs(par, kc, W, fp, tab, mode, ye, fnew)
    calls += c
    h_abs = initial_step(y, f, fnew, h0, d1, span, h_cap, 3.0, rtol, atol, False)
    h_old = -1.0
    err_old = -1.0
    ln_check = math.log(s_now) if in_t else y[3]
    ln_peak = ln_check
    nsteps = 0
    reason = R_MAX_STEPS
    x_prev = 0.0  # the independent variable: t, or τ from the start
    x = y[4] if in_t else 0.0
    while nsteps < steps:
        if in_t and target - y[4] <= 4e-16 * max(1.0, abs(target)):
            y[4] = target
            if target >= t_end:
                reason = R_T_END
                break
            ib += 1
            target = min(t_end, breaks[ib] if ib < nb else math.inf)
            continue
        s_now = speed_of(y, mode)
        h_cap = h_max * s_now if in_t else h_max
        if h_abs > h_cap:
            h_abs = h_cap
            h_old = -1.0
            err_old = -1.0
        rejected = False
        accepted = False
        n_iter = 0
        rate = -1.0
        err = 0.0
        while not accepted:
            if in_t and h_abs >= 0.99 * (target - y[4]):
                h_abs = target - y[4]  # onto the knot or t_end (never a sliver short of it)
            if not h_abs >= 1e-12 * max(1.0, abs(x)):
                reason = R_FAILED
                break
            h = h_abs
            if have_dense:
                for i in range(3):
                    theta = (x + h * _RC[i] - x_prev) / h_dense
                    _dense(Q, y_old, theta, ye)
                    for j in range(NY):
                        Z0[i, j] = ye[j] - y[j]
            else:
                for i in range(3):
                    for j in range(NY):
                        Z0[i, j] = 0.0
            for j in range(NY):
                scale[j] = atol[j] + abs(y[j]) * rtol
            converged = False
            while not converged:
                if not lu_ok:
                    lu_ok = _factor(J, h, LUr, pivr, LUc, pivc)
                    if not lu_ok:
                        break
                converged, n_iter, rate, c, st = _collocation(
                    par,
                    kc,
                    W,
                    fp,
                    tab,
                    mode,
                    y,
                    h,
                    Z0,
                    scale,
                    newton_tol,
                    LUr,
                    pivr,
                    LUc,
                    pivc,
                    Z,
                    F,
                )
                calls += c
                if not converged:
                    if current_jac:
                        break
                    calls += _jacobian(par, kc, W, fp, tab, mode, y, f, J)
                    current_jac = True
                    lu_ok = False
            if not converged:
                h_abs *= 0.5
                lu_ok = False
                continue
            for j in range(NY):
                y_new[j] = y[j] + Z[2, j]
            if in_t:  # dt/dt = 1: the time exactly (a knot or t_end exactly)
                y_new[4] = target if h == target - y[4] else y[4] + h
            for j in range(NY):
                err_v[j] = f[j] + (Z[0, j] * _RE[0] + Z[1, j] * _RE[1] + Z[2, j] * _RE[2]) / h
            _lu_solve(LUr, pivr, err_v)
            for j in range(NY):
                scale[j] = atol[j] + max(abs(y[j]), abs(y_new[j])) * rtol
            err = _rms(err_v, scale)
            safety = 0.9 * (2 * _NEWTON_MAXITER + 1) / (2 * _NEWTON_MAXITER + n_iter)
            if rejected and err > 1.0:
                for j in range(NY):
                    ye[j] = y[j] + err_v[j]
                _, c = rhs(par, kc, W, fp, tab, mode, ye, fnew)
                calls += c
                for j in range(NY):
                    err_v[j] = (
                        fnew[j] + (Z[0, j] * _RE[0] + Z[1, j] * _RE[1] + Z[2, j] * _RE[2]) / h
                    )
                _lu_solve(LUr, pivr, err_v)
                err = _rms(err_v, scale)
            if in_t and not y_new[3] > 0.5 * y[3]:
                err = math.inf  # s may at most halve in a step of the t-form (singular at 0)
            if not math.isfinite(err) or err > 1.0:
                fac = _predict(h_abs, h_old, err, err_old) if math.isfinite(err) else 0.0
                h_abs *= max(0.2, safety * fac)
                lu_ok = False
                rejected = True
            else:
                accepted = True
        if reason == R_FAILED:
            break
        nsteps += 1
        recompute = n_iter > 2 and rate > 1e-3
        fac = min(10.0, safety * _predict(h_abs, h_old, err, err_old))
        if not recompute and fac < 1.2:
            fac = 1.0
        else:
            lu_ok = False
        nu = math.sqrt(y_new[0] ** 2 + y_new[1] ** 2 + y_new[2] ** 2)
        for j in range(3):
            y_new[j] /= nu
        st, c = rhs(par, kc, W, fp, tab, mode, y_new, fnew)
        calls += c
        nfail += 1 if st != 0 else 0
        # the collocation polynomial of this step (the next step's predictor)
        for j in range(NY):
            for m in range(3):
                Q[j, m] = Z[0, j] * _P[0, m] + Z[1, j] * _P[1, m] + Z[2, j] * _P[2, m]
            y_old[j] = y[j]
        have_dense = True
        x_prev = x
        h_dense = h_abs
        x = x + h_abs if not in_t else y_new[4]
        if not in_t and y_new[4] >= target:
            # t_end or a knot inside the step (τ): the collocation polynomial's guess, one
            # step to it again, then an Euler step for the last difference
            lo = 0.0
            hi = 1.0
            for _ in range(60):
                th = 0.5 * (lo + hi)
                _dense(Q, y_old, th, ye)
                if ye[4] < target:
                    lo = th
                else:
                    hi = th
            h2 = 0.5 * (lo + hi) * h_abs
            ok = h2 > 0.0 and _factor(J, h2, LUr, pivr, LUc, pivc)
            lu_ok = False
            conv = False
            if ok:
                for i in range(3):
                    _dense(Q, y_old, _RC[i] * h2 / h_abs, ye)
                    for j in range(NY):
                        Z0[i, j] = ye[j] - y_old[j]
                for j in range(NY):
                    scale[j] = atol[j] + abs(y_old[j]) * rtol
                conv, _n, _r, c, st = _collocation(
                    par,
                    kc,
                    W,
                    fp,
                    tab,
                    mode,
                    y_old,
                    h2,
                    Z0,
                    scale,
                    newton_tol,
                    LUr,
                    pivr,
                    LUc,
                    pivc,
                    Z,
                    F,
                )
                calls += c
            if conv:
                for j in range(NY):
                    y_new[j] = y_old[j] + Z[2, j]
            else:
                _dense(Q, y_old, h2 / h_abs, y_new)
            st, c = rhs(par, kc, W, fp, tab, mode, y_new, fnew)
            calls += c
            if fnew[4] > 0.0:
                dtau = (target - y_new[4]) / fnew[4]
                for j in range(NY):
                    y_new[j] += dtau * fnew[j]
            y_new[4] = target
            st, c = rhs(par, kc, W, fp, tab, mode, y_new, fnew)
            calls += c
            have_dense = False
        for j in range(NY):
            y[j] = y_new[j]
        for j in range(NOUT):
            f[j] = fnew[j]
        if record:
            rec, nrec = push_row(rec, nrec, y, mode)
        if recompute:
            calls += _jacobian(par, kc, W, fp, tab, mode, y, f, J)
            current_jac = True
        else:
            current_jac = False
        h_old = h_dense
        err_old = err
        h_abs = h_abs * fac
        if y[4] >= target:
            if target >= t_end:
                reason = R_T_END
                break
            ib += 1
            target = min(t_end, breaks[ib] if ib < nb else math.inf)
            if not in_t:
                h_old = -1.0
                err_old = -1.0
        if not in_t and y[3] < ln_stop:
            closed_tail(y, f, k)
            if record:
                rec[nrec - 1, 0] = y[4]
                rec[nrec - 1, 1] = y[5]
                rec[nrec - 1, 2] = y[6]
                rec[nrec - 1, 3] = y[7]
            reason = R_STOP
            break
        ln_s = math.log(y[3]) if in_t else y[3]
        if not math.isfinite(ln_s):
            reason = R_FAILED
            break
        ln_peak = max(ln_peak, ln_s)
        if in_t and ln_s < ln_peak - math.log(2.0) and f[3] < 0.0:
            reason = R_DECAY
            break
        if abs(ln_s - ln_check) >= 1.0:
            ln_check = ln_s
            ratio, c = stiffness(par, kc, W, fp, tab, y[0], y[1], y[2], y[4], y[7])
            calls += c
            if ratio <= stiff_min:
                reason = R_SWITCH
                break
    return y, reason, nsteps, calls, nfail, rec[:nrec].copy()
