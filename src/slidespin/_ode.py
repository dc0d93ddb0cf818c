"""Compiled integration to the stop in the regularised time of MODEL §5.

State (natural units: lengths in a, time in √(a/g), mass m, so forces are in m g):

    y = (u₁, u₂, u₃, ln s, t, x, y, φ, ℓ),   s = √(vx² + vy² + k² ω²),  u = (vx, vy, k ω)/s,

with k = √(I/m) the radius of gyration. With dt = s dτ and A(u, φ) = (Fx, Fy, M/k)/(m g):

    du/dτ = A − (u·A) u,   d ln s/dτ = u·A < 0,   dt/dτ = s,
    dx/dτ = s² u₁,  dy/dτ = s² u₂,  dφ/dτ = s² u₃ / k,  dℓ/dτ = s² √(u₁² + u₂²),

ℓ being the length of the path of G.

This system is smooth through the stop: s decays exponentially in τ while u converges to a
fixed point u* of the sphere flow; t, x, y, φ converge to their stop values. The integrator
is the Dormand–Prince 8(5,3) pair (DOP853, Hairer–Nørsett–Wanner) with the coefficients and
error norm of ``scipy.integrate.DOP853``, run entirely in compiled code; u is projected back
onto the unit sphere after each step. Integration ends when u has converged (|du/dτ| below
``utol``) and s has dropped by ``s_drop``; the remaining tail is added in closed form
(t += s/|u·A|, x += s² u₁/(2|u·A|), ...), which is exact to first order in the already
negligible remainder.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as _dop

from ._jit import jit
from ._kernel import wrench_world

_NS = _dop.N_STAGES  # 12
_A = np.ascontiguousarray(_dop.A[:_NS, :_NS])
_B = np.ascontiguousarray(_dop.B)
_C = np.ascontiguousarray(_dop.C[:_NS])
_E3 = np.ascontiguousarray(_dop.E3)
_E5 = np.ascontiguousarray(_dop.E5)

NY = 9
# parameter vector layout
P_BN, P_LAW, P_XG, P_YG, P_T00, P_T01, P_T10, P_T11, P_BODY, P_K, P_WTOL = range(11)
NPAR = 11

# integration status codes
ST_STOPPED, ST_MAX_STEPS, ST_STEP_TOO_SMALL, ST_AT_REST = 0, 1, 2, 3


@jit
def accelerations(par, u1, u2, u3, phi):
    """A(u, φ) = (Fx, Fy, M/k)/(m g) in natural units, and the wrench status."""
    k = par[P_K]
    fx, fy, m, st = wrench_world(
        par[P_BN], int(par[P_LAW]), par[P_XG], par[P_YG],
        par[P_T00], par[P_T01], par[P_T10], par[P_T11],
        par[P_BODY] != 0.0, phi, u1, u2, u3 / k, par[P_WTOL],
    )
    return fx, fy, m / k, st


@jit
def rhs(par, y, out):
    """Right-hand side of the regularised system; returns the wrench status."""
    u1 = y[0]
    u2 = y[1]
    u3 = y[2]
    nrm = math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
    u1 /= nrm
    u2 /= nrm
    u3 /= nrm
    ax, ay, am, st = accelerations(par, u1, u2, u3, y[7])
    ua = u1 * ax + u2 * ay + u3 * am
    out[0] = ax - ua * u1
    out[1] = ay - ua * u2
    out[2] = am - ua * u3
    out[3] = ua
    s = math.exp(y[3])
    s2 = s * s
    out[4] = s
    out[5] = s2 * u1
    out[6] = s2 * u2
    out[7] = s2 * u3 / par[P_K]
    out[8] = s2 * math.sqrt(u1 * u1 + u2 * u2)
    return st


@jit
def _err_norm(K, h, scale):
    n = scale.size
    e5 = 0.0
    e3 = 0.0
    for i in range(n):
        a5 = 0.0
        a3 = 0.0
        for j in range(_NS + 1):
            a5 += K[j, i] * _E5[j]
            a3 += K[j, i] * _E3[j]
        a5 /= scale[i]
        a3 /= scale[i]
        e5 += a5 * a5
        e3 += a3 * a3
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * n)


@jit
def integrate(par, y0, rtol, atol, utol, s_drop, max_steps, h_max, record):
    """Integrate the regularised system from ``y0`` to the stop.

    Parameters
    ----------
    par : ndarray (NPAR,)
        Body, law and tensor parameters (natural units).
    y0 : ndarray (9,)
        Initial (u, ln s, t, x, y, φ, ℓ); u need not be normalised.
    rtol, atol : float
        Step-size control tolerances (natural units).
    utol : float
        Convergence target for |du/dτ| at the stop.
    s_drop : float
        Integration continues at least until s < s_drop · s₀.
    max_steps : int
        Step budget.
    h_max : float
        Largest step in τ (use ``inf`` for none; smaller values give denser records).
    record : bool
        Keep every accepted step.

    Returns
    -------
    y_stop : ndarray (9,)
        State at the stop (tail added; s = 0 there, stored as ln s = −inf).
    status : int
        ``ST_STOPPED``, ``ST_MAX_STEPS`` or ``ST_STEP_TOO_SMALL``.
    n_steps, n_rhs, n_wrench_failed : int
        Accepted steps, right-hand-side calls, wrench evaluations above their error target.
    rate : float
        |u·A| at the stop (the final decay rate of ln s).
    rec : ndarray (n, 10)
        Records (τ, y) of accepted steps, including the start (empty unless ``record``).
    """
    y = y0.copy()
    nrm = math.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2])
    y[0] /= nrm
    y[1] /= nrm
    y[2] /= nrm
    ln_s_target = y0[3] + math.log(s_drop)
    K = np.empty((_NS + 1, NY))
    f = np.empty(NY)
    yt = np.empty(NY)
    ynew = np.empty(NY)
    scale = np.empty(NY)
    fails = 0
    fails += rhs(par, y, f)
    nrhs = 1
    cap = 256 if record else 1
    rec = np.empty((cap, NY + 1))
    nrec = 0
    tau = 0.0
    if record:
        rec[0, 0] = tau
        rec[0, 1:] = y
        nrec = 1
    # initial step: resolve the sphere flow (rates are O(friction coefficient))
    fm = math.sqrt(f[0] ** 2 + f[1] ** 2 + f[2] ** 2 + f[3] ** 2)
    h = min(h_max, 0.01 / max(fm, 1e-3))
    status = ST_MAX_STEPS
    nsteps = 0
    exponent = -1.0 / 8.0
    while nsteps < max_steps:
        rejected = False
        while True:
            if h < 1e-12 * (1.0 + tau):
                status = ST_STEP_TOO_SMALL
                break
            K[0, :] = f
            for st in range(1, _NS):
                for i in range(NY):
                    acc = 0.0
                    for j in range(st):
                        acc += _A[st, j] * K[j, i]
                    yt[i] = y[i] + h * acc
                fails += rhs(par, yt, K[st])
                nrhs += 1
            for i in range(NY):
                acc = 0.0
                for j in range(_NS):
                    acc += _B[j] * K[j, i]
                ynew[i] = y[i] + h * acc
            fails += rhs(par, ynew, K[_NS])
            nrhs += 1
            for i in range(NY):
                scale[i] = atol + max(abs(y[i]), abs(ynew[i])) * rtol
            en = _err_norm(K, h, scale)
            if en < 1.0:
                if en == 0.0:
                    factor = 10.0
                else:
                    factor = min(10.0, 0.9 * en**exponent)
                if rejected:
                    factor = min(1.0, factor)
                tau += h
                h = min(h * factor, h_max)
                break
            h *= max(0.2, 0.9 * en**exponent)
            rejected = True
        if status == ST_STEP_TOO_SMALL:
            break
        nrm = math.sqrt(ynew[0] ** 2 + ynew[1] ** 2 + ynew[2] ** 2)
        for i in range(NY):
            y[i] = ynew[i]
        y[0] /= nrm
        y[1] /= nrm
        y[2] /= nrm
        for i in range(NY):
            f[i] = K[_NS, i]
        nsteps += 1
        if record:
            if nrec == cap:
                big = np.empty((2 * cap, NY + 1))
                big[:cap, :] = rec
                rec = big
                cap *= 2
            rec[nrec, 0] = tau
            rec[nrec, 1:] = y
            nrec += 1
        du = math.sqrt(f[0] ** 2 + f[1] ** 2 + f[2] ** 2)
        if y[3] < ln_s_target and du < utol:
            status = ST_STOPPED
            break
    # closed-form tail: ln s decays at the rate |u·A| once u has converged
    rate = -f[3]
    yend = y.copy()
    if rate > 0.0:
        s = math.exp(y[3])
        yend[4] += s / rate
        q = s * s / (2.0 * rate)
        yend[5] += q * y[0]
        yend[6] += q * y[1]
        yend[7] += q * y[2] / par[P_K]
        yend[8] += q * math.sqrt(y[0] ** 2 + y[1] ** 2)
    yend[3] = -np.inf
    return yend, status, nsteps, nrhs, fails, rate, rec[:nrec].copy()
