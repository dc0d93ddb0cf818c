"""Compiled explicit integration of a loaded slip (MODEL §11): DOP853 in τ to the stop, and
the slow start from rest with the direction slaved to the onset direction.

The step is the Dormand–Prince 8(5,3) pair with the coefficients and error norm of the
unloaded integrator (:mod:`slidespin.motion._integrator`, those of ``scipy.integrate.DOP853``),
on the right-hand sides of :mod:`slidespin.motion._loaded_flow`:

* ``MODE_TAU`` (τ independent): integrates until ln s falls below ``ln_stop`` (the rest of the
  approach to rest is added in closed form, t += s/|u·X|, x += s² u₁/(2|u·X|), ..., as the
  Python path does), until t reaches ``t_end``, or until the step budget is spent. The knots
  of the load and tilt (``breaks``) and ``t_end`` are located exactly: the step that crosses
  one is taken again with the step h* for which t = T, found by Newton's method on the step
  (dt/dτ = s; the first guess from the cubic Hermite interpolant of t(τ)), and the last
  difference, below 1e-13 of T, is closed by one Euler step, so t = T exactly. A knot is
  where the load's slope jumps: the integration restarts there.
* ``MODE_T`` (t independent): while the body speeds up or holds its speed, where the motion
  is polynomial-like in t but has a pole in τ; the steps are cut at the knots and at
  ``t_end`` (landing on them exactly); a speed below half its peak and falling ends it
  (``R_DECAY``: τ then takes over), and a step may at most halve s. A step in which the
  speed has an extremum records it too (located like ``stall``): the steps are long here
  (the motion is polynomial-like), and a plot drawn through the points reaches the peak;
* ``MODE_SLAVED`` (t independent): the slow start of :func:`~slidespin.motion._stick_slip._quasi_static`
  in compiled form; steps are cut at the knots and at ``t_end``; the events ``fast``
  (s reaches ``s_fast``), ``back`` (s back through 0) and ``stall`` (λ = ds/dt through 0
  downwards) are located by a bracketed Newton / regula-falsi iteration on the step, to
  ``t_tol`` for ``back`` and ``stall``. A failed Newton solve of the slaved direction ends
  the integration with ``R_SLAVE`` (the Python path continues from there).

A trial step whose stages are not finite (a wild trial of ln s beyond e^709 with a loose
``rtol``) is rejected and shortened, never propagated; only a step below 1e-12 of the
independent variable ends the run (``R_FAILED``).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._engine import P_K, kernel_constants
from slidespin.contact._kernel_ellipse import WORKSPACE_SHAPE
from slidespin.motion._integrator import _A, _B, _NS, _err_norm
from slidespin.motion._loaded_flow import MODE_SLAVED, MODE_T, NOUT, NY, rhs

# reasons an integration ended (shared with the Radau stepper)
R_STOP, R_T_END, R_MAX_STEPS, R_FAILED, R_FAST, R_STALL, R_BACK, R_SLAVE, R_SWITCH, R_DECAY = range(
    10
)
#: columns of a recorded row: t, x, y, φ, vx, vy, k ω, W_f, W_Q (natural units)
NROW = 9


@jit(error_model="numpy")
def speed_of(y, mode):
    """s of the state y in ``mode`` (ln s in τ, s itself otherwise)."""
    if mode == MODE_SLAVED or mode == MODE_T:
        return y[3]
    return math.exp(y[3])


@jit(error_model="numpy")
def push_row(rec, n, y, mode):
    """Append the row of y to rec (grown by doubling); returns (rec, n + 1)."""
    if n == rec.shape[0]:
        big = np.empty((2 * rec.shape[0] + 1, NROW))
        for i in range(n):  # (loops: slice assignment is slow to compile)
            for c in range(NROW):
                big[i, c] = rec[i, c]
        rec = big
    s = speed_of(y, mode)
    nu = math.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2])
    g = s / nu if nu > 0.0 else 0.0
    rec[n, 0] = y[4]
    rec[n, 1] = y[5]
    rec[n, 2] = y[6]
    rec[n, 3] = y[7]
    rec[n, 4] = g * y[0]
    rec[n, 5] = g * y[1]
    rec[n, 6] = g * y[2]
    rec[n, 7] = y[8]
    rec[n, 8] = y[9]
    return rec, n + 1


@jit(error_model="numpy")
def _stages(par, kc, W, fp, tab, mode, y, h, K, yt, ynew):
    """One DOP853 step of size h from y with K[0] = f(y): fills K[1:], ynew and
    K[_NS] = f(ynew); returns (status, kernel calls)."""
    st = 0
    calls = 0
    for s in range(1, _NS):
        for i in range(NY):
            acc = 0.0
            for j in range(s):
                acc += _A[s, j] * K[j, i]
            yt[i] = y[i] + h * acc
        a, c = rhs(par, kc, W, fp, tab, mode, yt, K[s])
        st += a
        calls += c
    for i in range(NY):
        acc = 0.0
        for j in range(_NS):
            acc += _B[j] * K[j, i]
        ynew[i] = y[i] + h * acc
    a, c = rhs(par, kc, W, fp, tab, mode, ynew, K[_NS])
    return st + a, calls + c


@jit(error_model="numpy")
def _finite(v, n):
    for i in range(n):
        if not math.isfinite(v[i]):
            return False
    return True


@jit(error_model="numpy")
def _error(y, ynew, K, h, rtol, atol, scale, mode):
    for i in range(NY):
        scale[i] = atol[i] + max(abs(y[i]), abs(ynew[i])) * rtol
    if not (_finite(ynew, NY) and _finite(K[_NS], NY)):
        return math.inf
    for r in range(_NS + 1):
        if not _finite(K[r], NY):
            return math.inf
    return _err_norm(K, h, scale)


@jit(error_model="numpy")
def _counts(i, slaved):
    """Whether entry i of the state enters the first-step norms (the slow start: not the
    slaved direction u, nor t, which its Python form does not integrate)."""
    return not (slaved and (i < 3 or i == 4))


@jit(error_model="numpy")
def initial_trial(y, f, span, rtol, atol, y1, slaved):
    """First half of scipy's ``select_initial_step`` (Hairer, Nørsett & Wanner, §II.4) for
    the state y with derivative f over an interval of length ``span``: the trial step h0,
    with y1 = y + h0 f to evaluate; returns (h0, d1). (The right-hand side at y1 is the
    caller's: see :func:`initial_step`.)"""
    d0 = 0.0
    d1 = 0.0
    n = 0
    for i in range(NY):
        if _counts(i, slaved):
            sc = atol[i] + abs(y[i]) * rtol
            d0 += (y[i] / sc) ** 2
            d1 += (f[i] / sc) ** 2
            n += 1
    d0 = math.sqrt(d0 / n)
    d1 = math.sqrt(d1 / n)
    h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    h0 = min(h0, span)
    for i in range(NY):
        y1[i] = y[i] + h0 * f[i]
    return h0, d1


@jit(error_model="numpy")
def initial_step(y, f, f1, h0, d1, span, h_max, order, rtol, atol, slaved):
    """Second half of ``select_initial_step``: the first step from f1 = f(y + h0 f)."""
    d2 = 0.0
    n = 0
    for i in range(NY):
        if _counts(i, slaved):
            sc = atol[i] + abs(y[i]) * rtol
            d2 += ((f1[i] - f[i]) / sc) ** 2
            n += 1
    d2 = math.sqrt(d2 / n) / h0
    if not math.isfinite(d2):
        d2 = 1e300
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / (order + 1.0))
    return min(100.0 * h0, h1, span, h_max)


@jit(error_model="numpy")
def closed_tail(y, f, k):
    """The closed-form rest of an approach to rest from y (ln s in y[3]) with f = f(y) in τ:
    t += s/r, x += ½ s² u₁/r, y += ½ s² u₂/r, φ += ½ s² u₃/(k r), r = −u·X (if r > 0)."""
    rate = -f[3]
    if rate > 0.0 and math.isfinite(rate):
        s = math.exp(y[3])
        nu = math.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2])
        y[4] += s / rate
        q = 0.5 * s * s / rate / nu
        y[5] += q * y[0]
        y[6] += q * y[1]
        y[7] += q * y[2] / k


@jit(error_model="numpy")
def _hermite_fraction(t0, t1, d0, d1, h, target):
    """θ ∈ [0, 1] where the cubic Hermite interpolant of t (values t0, t1, slopes d0, d1 per
    unit of the step h) reaches ``target`` (bisection: the interpolant is increasing)."""
    lo = 0.0
    hi = 1.0
    for _ in range(60):
        th = 0.5 * (lo + hi)
        h00 = (1.0 + 2.0 * th) * (1.0 - th) ** 2
        h10 = th * (1.0 - th) ** 2
        h01 = th * th * (3.0 - 2.0 * th)
        h11 = th * th * (th - 1.0)
        v = h00 * t0 + h10 * h * d0 + h01 * t1 + h11 * h * d1
        if v < target:
            lo = th
        else:
            hi = th
    return 0.5 * (lo + hi)


@jit(error_model="numpy")
def _event_value(kind, y, f, s_fast):
    """g of an event at a state: kind 0 fast (s − s_fast), 1 back (s), 2 stall (λ)."""
    if kind == 0.0:
        return y[3] - s_fast
    if kind == 1.0:
        return y[3]
    return f[3]


@jit(error_model="numpy")
def _event(
    par, kc, W, fp, tab, mode, y, f0, ynew, fnew, K, yt, h, kind, target, s_fast, t_tol, yout, fout
):
    """Where an event happens in the accepted step from y (f0 = f(y)) to ynew (fnew =
    f(ynew)) of size h, found by taking the step again with other sizes; fills yout, fout
    there and returns (h*, status, kernel calls).

    * ``kind`` −1, τ: t = ``target``. Newton's method on the step size (dt/dτ = s) from the
      cubic Hermite interpolant's guess, then one Euler step for the last difference, so
      that t = target exactly.
    * ``kind`` 0, 1, 2, t independent: ``fast`` (s = s_fast), ``back`` (s = 0), ``stall``
      (λ = 0): Newton where g' is known (s: g' = λ), regula falsi (Illinois) otherwise,
      inside the bracket, to ``t_tol`` in t (``fast``: to 1e-3 of s_fast).
    """
    st = 0
    calls = 0
    for i in range(NOUT):
        K[0, i] = f0[i]
    if kind < 0.0:
        th = _hermite_fraction(y[4], ynew[4], f0[4], fnew[4], h, target)
        hs = max(th * h, 1e-300)
        scale_t = max(1.0, abs(target))
        for _ in range(4):
            a, c = _stages(par, kc, W, fp, tab, mode, y, hs, K, yt, yout)
            st += a
            calls += c
            dt = target - yout[4]
            slope = K[_NS, 4]
            if abs(dt) <= 1e-13 * scale_t or not slope > 0.0:
                break
            hs = min(max(hs + dt / slope, 0.0), h)
        for i in range(NOUT):
            fout[i] = K[_NS, i]
        if fout[4] > 0.0:
            dtau = (target - yout[4]) / fout[4]
            for i in range(NY):
                yout[i] += dtau * fout[i]
        yout[4] = target
        a, c = rhs(par, kc, W, fp, tab, mode, yout, fout)
        return hs, st + a, calls + c
    a = 0.0
    ga = _event_value(kind, y, f0, s_fast)
    b = h
    gb = _event_value(kind, ynew, fnew, s_fast)
    if ga == 0.0:
        for i in range(NY):
            yout[i] = y[i]
        for i in range(NOUT):
            fout[i] = f0[i]
        return 0.0, st, calls
    hs = b
    gs = gb
    ds = fnew[3]
    side = 0
    for i in range(NY):
        yout[i] = ynew[i]
    for i in range(NOUT):
        fout[i] = fnew[i]
    for _ in range(60):
        if b - a <= t_tol or (kind == 0.0 and abs(gs) <= 1e-3 * s_fast):
            break
        cand = -1.0
        if kind != 2.0 and ds != 0.0:
            cand = hs - gs / ds  # Newton on g = s − target, g' = λ
        if not (a < cand < b):
            cand = (a * gb - b * ga) / (gb - ga)  # regula falsi
            if not (a < cand < b):
                cand = 0.5 * (a + b)
        hs = cand
        a_, c_ = _stages(par, kc, W, fp, tab, mode, y, hs, K, yt, yout)
        st += a_
        calls += c_
        for i in range(NOUT):
            fout[i] = K[_NS, i]
        gs = _event_value(kind, yout, fout, s_fast)
        ds = fout[3]
        if gs == 0.0:
            break
        if (gs > 0.0) == (ga > 0.0):
            a = hs
            ga = gs
            if side == -1:
                gb *= 0.5  # Illinois
            side = -1
        else:
            b = hs
            gb = gs
            if side == 1:
                ga *= 0.5
            side = 1
    return hs, st, calls


@jit(error_model="numpy")
def run_dop853(
    par, fp, tab, mode, y0, rtol, atol, h_max, t_end, breaks, ln_stop, s_fast, t_tol, steps, record
):
    """Integrate a slip in ``mode`` (``MODE_TAU``, ``MODE_T`` or ``MODE_SLAVED``) from y0
    (module docstring).

    Returns
    -------
    y : ndarray (NY,)
        The state at the end (in τ with the closed-form tail added after ``R_STOP``).
    reason : int
        ``R_STOP`` (τ), ``R_T_END``, ``R_MAX_STEPS``, ``R_FAILED``; ``R_DECAY`` (t);
        ``R_FAST``, ``R_BACK``, ``R_STALL``, ``R_SLAVE`` (slaved).
    n_steps, n_calls, n_fail : int
        Accepted steps, kernel calls, wrench evaluations that missed their target.
    rec : ndarray (n, NROW)
        Rows of the accepted steps and the end (empty unless ``record``).
    """
    k = par[P_K]
    kc = kernel_constants(par)
    W = np.empty(WORKSPACE_SHAPE)
    K = np.empty((_NS + 1, NOUT))
    yt = np.empty(NY)
    ynew = np.empty(NY)
    ye = np.empty(NY)
    fe = np.empty(NOUT)
    yb = np.empty(NY)
    fb = np.empty(NOUT)
    f0 = np.empty(NOUT)
    fnew = np.empty(NOUT)
    scale = np.empty(NY)
    rec = np.empty((64 if record else 0, NROW))
    nrec = 0
    y = y0.copy()
    slaved = mode == MODE_SLAVED
    in_t = mode == MODE_T
    indep_t = slaved or in_t  # t independent: steps cut at the knots and t_end
    s_peak = y[3]
    nb = breaks.size
    ib = 0
    while ib < nb and breaks[ib] <= y[4]:
        ib += 1
    nfail = 0
    a, calls = rhs(par, kc, W, fp, tab, mode, y, K[0])
    nfail += 1 if a != 0 else 0
    if slaved:
        if a == 2:
            return y, R_SLAVE, 0, calls, rec[:0].copy(), nfail
        for i in range(3):
            y[i] = K[0, NY + i]
    if not _finite(K[0], NY):
        return y, R_FAILED, 0, calls, rec[:0].copy(), nfail
    target = min(t_end, breaks[ib] if ib < nb else math.inf)
    span = (target - y[4]) if indep_t else 1e4
    span = max(span, 1e-300)
    h0, d1 = initial_trial(y, K[0], span, rtol, atol, yt, slaved)
    _, c = rhs(par, kc, W, fp, tab, mode, yt, fe)
    calls += c
    h = initial_step(
        y, K[0], fe, h0, d1, span, h_max * y[3] if in_t else h_max, 7.0, rtol, atol, slaved
    )
    exponent = -1.0 / 8.0
    nsteps = 0
    reason = R_MAX_STEPS
    while nsteps < steps:
        rejected = False
        if indep_t and target - y[4] <= 4e-16 * max(1.0, abs(target)):
            y[4] = target  # at a knot or t_end (a located event may stop a hair short)
            if target >= t_end:
                reason = R_T_END
                break
            ib += 1
            target = min(t_end, breaks[ib] if ib < nb else math.inf)
            continue
        if in_t:
            h = min(h, h_max * y[3])  # at most h_max in τ: dt = s dτ
        while True:
            if indep_t and h >= 0.99 * (target - y[4]):
                h = target - y[4]  # onto the knot or t_end (never a sliver short of it)
            if not h >= 1e-12 * (1.0 + abs(y[4] if indep_t else 1.0)) or not h > 0.0:
                reason = R_FAILED
                break
            st, c = _stages(par, kc, W, fp, tab, mode, y, h, K, yt, ynew)
            calls += c
            if st >= 2 and slaved:
                reason = R_SLAVE
                break
            en = _error(y, ynew, K, h, rtol, atol, scale, mode)
            if in_t and not ynew[3] > 0.5 * y[3]:
                en = math.inf  # s may at most halve in a step of the t-form (singular at 0)
            if not math.isfinite(en):
                h *= 0.2
                rejected = True
                continue
            if en < 1.0:
                factor = 10.0 if en == 0.0 else min(10.0, 0.9 * en**exponent)
                if rejected:
                    factor = min(1.0, factor)
                h_next = h * factor if in_t else min(h * factor, h_max)
                nfail += 1 if st != 0 else 0
                break
            h *= max(0.2, 0.9 * en**exponent)
            rejected = True
        if reason == R_FAILED or reason == R_SLAVE:
            break
        nsteps += 1
        if in_t:
            if h == target - y[4]:
                ynew[4] = target  # dt/dt = 1: on the knot or t_end exactly
            nu = math.sqrt(ynew[0] ** 2 + ynew[1] ** 2 + ynew[2] ** 2)
            for i in range(3):
                ynew[i] /= nu
        elif not slaved:
            if ynew[4] >= target:
                stop_first = False
                if ynew[3] < ln_stop:
                    fs = (y[3] - ln_stop) / (y[3] - ynew[3])
                    ft = (target - y[4]) / (ynew[4] - y[4])
                    stop_first = fs < ft
                if not stop_first:
                    for i in range(NOUT):
                        f0[i] = K[0, i]
                        fnew[i] = K[_NS, i]
                    _, a, c = _event(
                        par,
                        kc,
                        W,
                        fp,
                        tab,
                        mode,
                        y,
                        f0,
                        ynew,
                        fnew,
                        K,
                        yt,
                        h,
                        -1.0,
                        target,
                        s_fast,
                        t_tol,
                        ye,
                        fe,
                    )
                    calls += c
                    nfail += 1 if a != 0 else 0
                    for i in range(NY):
                        y[i] = ye[i]
                    for i in range(NOUT):
                        K[0, i] = fe[i]
                    if record:
                        rec, nrec = push_row(rec, nrec, y, mode)
                    if target >= t_end:
                        reason = R_T_END
                        break
                    ib += 1
                    target = min(t_end, breaks[ib] if ib < nb else math.inf)
                    h = h_next
                    continue
            if ynew[3] < ln_stop:
                for i in range(NY):
                    y[i] = ynew[i]
                closed_tail(y, K[_NS], k)
                if record:
                    rec, nrec = push_row(rec, nrec, y, mode)
                reason = R_STOP
                break
            nu = math.sqrt(ynew[0] ** 2 + ynew[1] ** 2 + ynew[2] ** 2)
            for i in range(3):
                ynew[i] /= nu
        else:
            # the events whose sign changed in this step; the earliest is located
            act0 = y[3] < s_fast <= ynew[3]
            act1 = ynew[3] <= 0.0 and (y[3] > 0.0 or ynew[3] < 0.0)
            act2 = K[0, 3] >= 0.0 and K[_NS, 3] <= 0.0 and (K[0, 3] > 0.0 or K[_NS, 3] < 0.0)
            if act0 or act1 or act2:
                for i in range(NOUT):
                    f0[i] = K[0, i]
                    fnew[i] = K[_NS, i]
                best = math.inf
                kbest = -1.0
                for kk in range(3):
                    if not ((kk == 0 and act0) or (kk == 1 and act1) or (kk == 2 and act2)):
                        continue
                    kind = float(kk)
                    hk, a, c = _event(
                        par,
                        kc,
                        W,
                        fp,
                        tab,
                        mode,
                        y,
                        f0,
                        ynew,
                        fnew,
                        K,
                        yt,
                        h,
                        kind,
                        target,
                        s_fast,
                        t_tol,
                        ye,
                        fe,
                    )
                    calls += c
                    if hk < best:
                        best = hk
                        kbest = kind
                        for i in range(NY):
                            yb[i] = ye[i]
                        for i in range(NOUT):
                            fb[i] = fe[i]
                for i in range(NY):
                    y[i] = yb[i]
                for i in range(3):
                    y[i] = fb[NY + i]
                if kbest == 1.0:
                    y[3] = max(y[3], 0.0)
                if record:
                    rec, nrec = push_row(rec, nrec, y, mode)
                reason = R_FAST if kbest == 0.0 else (R_BACK if kbest == 1.0 else R_STALL)
                break
            for i in range(3):
                ynew[i] = K[_NS, NY + i]
        if record and not slaved and K[0, 3] * K[_NS, 3] < 0.0:
            # the speed has an extremum inside the step (ds/dt through 0): it is recorded
            # too, so that the points drawn reach the true peak (the step is kept)
            for i in range(NOUT):
                f0[i] = K[0, i]
                fnew[i] = K[_NS, i]
            hk, a, c = _event(
                par, kc, W, fp, tab, mode, y, f0, ynew, fnew, K, yt, h, 2.0, target, s_fast,
                t_tol, ye, fe,
            )  # fmt: skip
            calls += c
            if 0.0 < hk < h:
                rec, nrec = push_row(rec, nrec, ye, mode)
            for i in range(NOUT):
                K[_NS, i] = fnew[i]
        for i in range(NY):
            y[i] = ynew[i]
        for i in range(NOUT):
            K[0, i] = K[_NS, i]
        if record:
            rec, nrec = push_row(rec, nrec, y, mode)
        if indep_t and y[4] >= target:
            if target >= t_end:
                reason = R_T_END
                break
            ib += 1
            target = min(t_end, breaks[ib] if ib < nb else math.inf)
        h = h_next
        if in_t:
            s_peak = max(s_peak, y[3])
            if y[3] < 0.5 * s_peak and K[0, 3] < 0.0:
                reason = R_DECAY  # on in τ, which is smooth through the stop
                break
    if reason == R_MAX_STEPS and record and (nrec == 0 or rec[nrec - 1, 0] != y[4]):
        rec, nrec = push_row(rec, nrec, y, mode)
    return y, reason, nsteps, calls, rec[:nrec].copy(), nfail
