"""Compiled forward-mode sensitivities of the regularised motion (MODEL §5, §15).

The state y of :mod:`slidespin.motion._flow` (u, ln s, t, x, y, φ, ℓ) and, for each
parameter θ_k, its sensitivity S_k = ∂y/∂θ_k at fixed regularised time τ, integrated together:

    dy/dτ = G(y; θ),     dS_k/dτ = (∂G/∂y) S_k + ∂G/∂θ_k       (MODEL §15, in τ).

The right-hand side of the variational equation is the directional derivative of the flow
along (S_k, e_k) in the joint (state, parameter) space, taken by a central difference of the
exact right-hand side :func:`slidespin.motion._flow._rhs` (the wrench kernels of MODEL §2 and
§10) with the step h_k of parameter k:

    (G(y + h_k S_k; θ + h_k e_k) − G(y − h_k S_k; θ − h_k e_k)) / (2 h_k),

where the perturbed parameters θ ± h_k e_k reach the kernels as whole parameter vectors
(``pars``, rows 1 + 2k and 2 + 2k) and, for a footprint, kernel geometries (``geos``):
every parameter of a body, a tensor or a start is then one case of the same code. The error
of that difference is O(h_k²) (the kernels are smooth in the twist's direction, the body
angle and the parameters; the friction entries enter linearly), about 1e-10 of the
derivative at the relative steps :mod:`slidespin.motion.sensitivity` uses. This departs from
the issue's wish for analytic derivatives of the chord integrals: they are not written yet,
and each parameter costs two wrench evaluations per stage instead of a fraction of one.

The integrator is the DOP853 pair of :mod:`slidespin.motion._integrator` (the same
coefficients and error norm) on the joint vector (y, S), its steps cut to land on the plain
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
    P_SHAPE,
    SHAPE_FOOTPRINT,
    footprint_argument,
    kernel_constants,
)
from slidespin.contact._kernel_ellipse import WORKSPACE_SHAPE
from slidespin.motion import _dop853 as _dop
from slidespin.motion._flow import NY, _rhs
from slidespin.motion._integrator import _err_norm

_NS = _dop.N_STAGES
_A = np.ascontiguousarray(_dop.A)
_B = np.ascontiguousarray(_dop.B)

# status codes of :func:`integrate_sensitivities`
SS_CONVERGED, SS_MAX_STEPS, SS_STEP_TOO_SMALL, SS_NON_FINITE = range(4)


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


@jit(error_model="numpy")
def joint_rhs(pars, kcs, W, fp, geos, hs, Y, out, yp, ym, gp, gm):
    """Right-hand side of the joint system (y, S₁, …, S_p) (MODEL §15); returns the number
    of wrench evaluations above their error target."""
    npar = hs.size
    fails = _rhs(pars[0], kcs[0], W, row_patch(fp, geos, 0), Y[:NY], out[:NY])
    for k in range(npar):
        h = hs[k]
        off = NY * (k + 1)
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
    pars, fp, geos, hs, Y0, rtol, atol, ln_drop, conv_tol, replay, max_steps, taus
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
    """
    n = Y0.size
    npar = hs.size
    kcs = [kernel_constants(pars[j]) for j in range(pars.shape[0])]
    W = np.empty(WORKSPACE_SHAPE)
    yp = np.empty(NY)
    ym = np.empty(NY)
    gp = np.empty(NY)
    gm = np.empty(NY)
    Y = Y0.copy()
    K = np.empty((_NS + 1, n))
    Yt = np.empty(n)
    Ynew = np.empty(n)
    scale = np.empty(n)
    F = np.empty(n)
    rec = np.full((taus.size, n), np.nan)
    fails = joint_rhs(pars, kcs, W, fp, geos, hs, Y, F, yp, ym, gp, gm)
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
        landed = False
        while True:
            hh = h
            landed = False
            if nxt < taus.size and (replay or tau + hh >= taus[nxt]):
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
                for i in range(n):
                    acc = 0.0
                    for j in range(st):
                        acc += _A[st, j] * K[j, i]
                    Yt[i] = Y[i] + hh * acc
                fails += joint_rhs(pars, kcs, W, fp, geos, hs, Yt, K[st], yp, ym, gp, gm)
            for i in range(n):
                acc = 0.0
                for j in range(_NS):
                    acc += _B[j] * K[j, i]
                Ynew[i] = Y[i] + hh * acc
            fails += joint_rhs(pars, kcs, W, fp, geos, hs, Ynew, K[_NS], yp, ym, gp, gm)
            for i in range(n):
                scale[i] = atol + max(abs(Y[i]), abs(Ynew[i])) * rtol
            scale[7] = atol  # the body angle to an absolute tolerance, as the integrator
            en = _err_norm(K, hh, scale)
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
    return Y, F, status, nsteps, fails, rec


def run(pars, fe, fc, geos, hs, Y0, rtol, atol, ln_drop, conv_tol, replay, max_steps, taus):
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
    )  # fmt: skip
    footprint = pars[0, P_SHAPE] == SHAPE_FOOTPRINT
    aot = _aot.core()
    if aot is not None:
        if footprint:
            return aot.sensitivities_footprint(pars, fe, fc, geos, *tail)
        return aot.sensitivities_ellipse(pars, geos, *tail)
    fp = footprint_argument(pars[0], fe, fc, geos[0])
    return integrate_sensitivities(pars, fp, geos, *tail)
