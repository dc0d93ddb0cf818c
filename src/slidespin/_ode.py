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
onto the unit sphere after each step. Once s has dropped by ``s_drop`` and u is near a fixed
point (|du/dτ| < ``POLISH_START``), the fixed point u* is found by Newton's method at the
frozen final φ (φ moves by O(s²) from there on) and accepted if it is stable (both tangent
eigenvalues negative) and within ``POLISH_MAX_MOVE`` of u; otherwise integration goes on (a
new attempt each time |du/dτ| has halved) until |du/dτ| < ``utol``. The remaining tail is
added in closed form (t += s/|u·A|, x += s² u₁/(2|u·A|), ...); its error is
O(s·|u − u*|/|u·A|), below 1e-12 s₀ in t since s < 1e-8 s₀ and |u − u*| ≲ 1e-4/|λ|.

Speed: the wrench kernel's per-body constants and its workspace are set up once per
trajectory (:func:`slidespin._kernel.wrench_constants`, :func:`~slidespin._kernel.workspace`),
so a right-hand side costs one call of the kernel's inner function; the batch
(:func:`integrate_many`) runs :func:`integrate` itself, without records, under ``prange``.
Compile time: the Newton polish is inlined and every call site passes non-literal arguments,
so the first call compiles each function once.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as _dop

from ._jit import jit, prange
from ._kernel import WORKSPACE_SHAPE, wrench_constants, wrench_world_fast

_NS = _dop.N_STAGES  # 12
_A = np.ascontiguousarray(_dop.A[:_NS, :_NS])
_B = np.ascontiguousarray(_dop.B)
_C = np.ascontiguousarray(_dop.C[:_NS])
_E3 = np.ascontiguousarray(_dop.E3)
_E5 = np.ascontiguousarray(_dop.E5)

NY = 9
#: |du/dτ| below which the terminal direction is polished by Newton (once s has dropped by
#: ``s_drop``), and the farthest the polished direction may lie from the integrated one
POLISH_START = 1e-4
POLISH_MAX_MOVE = 1e-2
# parameter vector layout
P_BN, P_LAW, P_XG, P_YG, P_T00, P_T01, P_T10, P_T11, P_BODY, P_K, P_WTOL = range(11)
NPAR = 11

# integration status codes
ST_STOPPED, ST_MAX_STEPS, ST_STEP_TOO_SMALL, ST_AT_REST, ST_SPIRAL = 0, 1, 2, 3, 4
# each time s drops by a further e^-60 beyond ``s_drop`` while u has not converged: if |du/dτ|
# has not halved and u has swept more than SPIRAL_ARC since the last check, in SPIRAL_WINDOWS
# windows in a row, the body has stopped (to far below rounding) while its direction of
# motion keeps turning: a spiral stop with no terminal direction
LN_S_SPIRAL = -60.0
SPIRAL_ARC = 1.0  # [rad] u must also have swept this arc between two checks
SPIRAL_WINDOWS = 2  # ... in this many consecutive windows


@jit(error_model="numpy")
def kernel_constants(par):
    """The wrench kernel's per-body constants for the parameter vector ``par``."""
    t00, t01, t10, t11 = par[P_T00], par[P_T01], par[P_T10], par[P_T11]
    return wrench_constants(par[P_BN], int(par[P_LAW]), par[P_XG], par[P_YG],
                            math.sqrt(t00 * t00 + t01 * t01 + t10 * t10 + t11 * t11),
                            par[P_WTOL])


@jit(error_model="numpy", inline="always")
def accelerations(par, kc, W, u1, u2, u3, phi):
    """A(u, φ) = (Fx, Fy, M/k)/(m g) in natural units, and the wrench status.

    ``kc`` are the kernel constants (:func:`kernel_constants`), ``W`` a kernel workspace.
    """
    k = par[P_K]
    fx, fy, m, st = wrench_world_fast(
        int(par[P_LAW]), kc, par[P_T00], par[P_T01], par[P_T10], par[P_T11],
        par[P_BODY] != 0.0, phi, u1, u2, u3 / k, par[P_WTOL], W,
    )
    return fx, fy, m / k, st


@jit(error_model="numpy")
def _rhs(par, kc, W, y, out):
    """Right-hand side of the regularised system; returns the wrench status."""
    u1 = y[0]
    u2 = y[1]
    u3 = y[2]
    inv = 1.0 / math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
    u1 *= inv
    u2 *= inv
    u3 *= inv
    ax, ay, am, st = accelerations(par, kc, W, u1, u2, u3, y[7])
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


@jit(error_model="numpy")
def rhs(par, y, out):
    """Right-hand side of the regularised system (one call; the integrator keeps its
    constants and workspace); returns the wrench status."""
    return _rhs(par, kernel_constants(par), np.empty(WORKSPACE_SHAPE), y, out)


@jit(error_model="numpy", inline="always")
def polish_fixed_point(par, kc, W, u, phi, max_iter, max_dist):
    """Newton iteration for the fixed point u* of the sphere flow at frozen φ (MODEL §5–6).

    Starts from ``u`` (close to u*); works in the tangent plane of the sphere with a
    central-difference Jacobian. Returns (u*, converged, largest real part of the two
    tangent eigenvalues, number of iterations). ``converged`` is false if the iteration
    moves more than ``max_dist`` away from ``u`` or does not settle below 1e-13 within
    ``max_iter`` iterations. ``kc``, ``W``: kernel constants and workspace.

    The sphere flow G(u) = A − (u·A)u is the first three components of the right-hand side
    (:func:`_rhs` at ln s = 0); one call site for it keeps the compiled code small.
    """
    # (scalar loops throughout: array expressions are slow to compile)
    nu = math.sqrt(u[0] ** 2 + u[1] ** 2 + u[2] ** 2)
    uu = np.empty(3)
    u0 = np.empty(3)
    for i in range(3):
        uu[i] = u[i] / nu
        u0[i] = uu[i]
    g = np.empty(3)
    t1 = np.empty(3)
    t2 = np.empty(3)
    jac = np.empty((2, 2))
    yp = np.zeros(NY)
    yp[7] = phi
    out = np.empty(NY)
    hd = 1e-6
    converged = False
    lam = 0.0
    it = 0
    for it in range(max_iter):
        # orthonormal tangent basis (t1, t2) at uu, from the axis least aligned with uu
        ax = 0 if abs(uu[0]) <= abs(uu[1]) and abs(uu[0]) <= abs(uu[2]) else (
            1 if abs(uu[1]) <= abs(uu[2]) else 2)
        d = uu[ax]
        for i in range(3):
            t1[i] = (1.0 if i == ax else 0.0) - d * uu[i]
        n1 = math.sqrt(t1[0] ** 2 + t1[1] ** 2 + t1[2] ** 2)
        for i in range(3):
            t1[i] /= n1
        t2[0] = uu[1] * t1[2] - uu[2] * t1[1]
        t2[1] = uu[2] * t1[0] - uu[0] * t1[2]
        t2[2] = uu[0] * t1[1] - uu[1] * t1[0]
        # G at uu (m = 0) and at uu ± hd t_j (m = 1..4), central differences along t_j
        for m in range(5):
            j = (m - 1) // 2
            sg = 0.0 if m == 0 else (1.0 if m % 2 == 1 else -1.0)
            for i in range(3):
                yp[i] = uu[i] + sg * hd * (t1[i] if j == 0 else t2[i])
            _rhs(par, kc, W, yp, out)
            if m == 0:
                for i in range(3):
                    g[i] = out[i]
                continue
            a0 = out[0] * t1[0] + out[1] * t1[1] + out[2] * t1[2]
            a1 = out[0] * t2[0] + out[1] * t2[1] + out[2] * t2[2]
            if m % 2 == 1:
                jac[0, j] = a0
                jac[1, j] = a1
            else:
                jac[0, j] = (jac[0, j] - a0) / (2.0 * hd)
                jac[1, j] = (jac[1, j] - a1) / (2.0 * hd)
        r0 = g[0] * t1[0] + g[1] * t1[1] + g[2] * t1[2]
        r1 = g[0] * t2[0] + g[1] * t2[1] + g[2] * t2[2]
        det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
        tr = jac[0, 0] + jac[1, 1]
        disc = 0.25 * tr * tr - det
        lam = 0.5 * tr + (math.sqrt(disc) if disc > 0.0 else 0.0)
        if det == 0.0:
            break
        d0 = (-r0 * jac[1, 1] + r1 * jac[0, 1]) / det
        d1 = (-r1 * jac[0, 0] + r0 * jac[1, 0]) / det
        for i in range(3):
            uu[i] += d0 * t1[i] + d1 * t2[i]
        nu = math.sqrt(uu[0] ** 2 + uu[1] ** 2 + uu[2] ** 2)
        for i in range(3):
            uu[i] /= nu
        dist = math.sqrt((uu[0] - u0[0]) ** 2 + (uu[1] - u0[1]) ** 2 + (uu[2] - u0[2]) ** 2)
        if dist > max_dist:
            break
        if math.sqrt(d0 * d0 + d1 * d1) < 1e-13:
            converged = True
            break
    return uu, converged, lam, it + 1


@jit(error_model="numpy")
def _err_norm(K, h, scale):
    """scipy's DOP853 error norm."""
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


@jit(error_model="numpy")
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
        ``ST_STOPPED``, ``ST_SPIRAL`` (stopped, but the direction of motion keeps turning:
        no terminal direction exists), ``ST_MAX_STEPS`` or ``ST_STEP_TOO_SMALL``.
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
    kc = kernel_constants(par)
    W = np.empty(WORKSPACE_SHAPE)
    fails = 0
    fails += _rhs(par, kc, W, y, f)
    nrhs = 1
    cap = 256 if record else 1
    rec = np.empty((cap, NY + 1))
    nrec = 0
    tau = 0.0
    if record:
        rec[0, 0] = tau
        for i in range(NY):
            rec[0, 1 + i] = y[i]
        nrec = 1
    # initial step: resolve the sphere flow (rates are O(friction coefficient))
    fm = math.sqrt(f[0] ** 2 + f[1] ** 2 + f[2] ** 2 + f[3] ** 2)
    h = min(h_max, 0.01 / max(fm, 1e-3))
    status = ST_MAX_STEPS
    nsteps = 0
    exponent = -1.0 / 8.0
    du_polish = math.inf  # |du/dτ| at the last polishing attempt
    du_check = -1.0  # |du/dτ| when s first fell below target, then at each spiral check
    ln_s_check = 0.0
    arc = 0.0  # arc swept by u since the last spiral check [rad]
    spiral_windows = 0  # consecutive checks that looked like a spiral
    tau_arc = 0.0
    while nsteps < max_steps:
        rejected = False
        while True:
            if h < 1e-12 * (1.0 + tau):
                status = ST_STEP_TOO_SMALL
                break
            for i in range(NY):
                K[0, i] = f[i]
            for st in range(1, _NS):
                for i in range(NY):
                    acc = 0.0
                    for j in range(st):
                        acc += _A[st, j] * K[j, i]
                    yt[i] = y[i] + h * acc
                fails += _rhs(par, kc, W, yt, K[st])
                nrhs += 1
            for i in range(NY):
                acc = 0.0
                for j in range(_NS):
                    acc += _B[j] * K[j, i]
                ynew[i] = y[i] + h * acc
            fails += _rhs(par, kc, W, ynew, K[_NS])
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
                for i in range(cap):  # (loops: slice assignment is slow to compile)
                    for c in range(NY + 1):
                        big[i, c] = rec[i, c]
                rec = big
                cap *= 2
            rec[nrec, 0] = tau
            for i in range(NY):
                rec[nrec, 1 + i] = y[i]
            nrec += 1
        du = math.sqrt(f[0] ** 2 + f[1] ** 2 + f[2] ** 2)
        if y[3] < ln_s_target:
            if du < utol:
                status = ST_STOPPED
                break
            if du < POLISH_START and du < 0.5 * du_polish:
                # near a hyperbolic fixed point: Newton gives u* to ~1e-13 at once, where the
                # explicit integrator would take many more steps to converge
                du_polish = du
                us, ok, lam, nit = polish_fixed_point(par, kc, W, y[:3], y[7], 12,
                                                      POLISH_MAX_MOVE)
                nrhs += 5 * nit
                if ok and lam < 0.0:
                    y[0] = us[0]
                    y[1] = us[1]
                    y[2] = us[2]
                    fails += _rhs(par, kc, W, y, f)
                    nrhs += 1
                    status = ST_STOPPED
                    break
            arc += du * (tau - tau_arc)
            tau_arc = tau
            if du_check < 0.0:
                du_check = du
                ln_s_check = y[3] + LN_S_SPIRAL
                arc = 0.0
            elif y[3] < ln_s_check:
                # s fell by another e^60 (t, x, y, φ are converged far below rounding). A
                # direction turning for ever has kept its rate of change and swept a large
                # arc since the last check; one approaching a fixed point, however slowly
                # (near a Table 2 boundary the approach is algebraic), moves less and less
                if du > 0.5 * du_check and arc > SPIRAL_ARC:
                    spiral_windows += 1
                    if spiral_windows >= SPIRAL_WINDOWS:  # not a transient near a saddle
                        status = ST_SPIRAL
                        break
                else:
                    spiral_windows = 0
                du_check = du
                ln_s_check = y[3] + LN_S_SPIRAL
                arc = 0.0
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


@jit(error_model="numpy")
def initial_state(par, vx, vy, wn, x, y, phi):
    """Regularised initial state (MODEL §5) from the velocity (vx, vy) of G, the spin ω (as
    ``wn``) and the position (x, y, φ), all in natural units; a body at rest gets
    ln s = −inf. The same arithmetic as :func:`slidespin.simulate`, so that batch and single
    runs agree to the last bit."""
    k = par[P_K]
    y0 = np.zeros(NY)
    s0 = math.sqrt(vx * vx + vy * vy + (k * wn) ** 2)
    y0[5] = x
    y0[6] = y
    y0[7] = phi
    if s0 == 0.0:
        y0[3] = -np.inf
        return y0
    y0[0] = vx / s0
    y0[1] = vy / s0
    y0[2] = k * wn / s0
    y0[3] = math.log(s0)
    return y0


@jit(error_model="numpy")
def stop_direction(yend):
    """|u₁₂| and the direction ϑ = atan2(u₂, u₁) of each stop state, with the same libm
    functions as :func:`slidespin.simulate` (math.hypot, math.atan2), bit for bit."""
    n = yend.shape[0]
    u12 = np.empty(n)
    theta = np.empty(n)
    for i in range(n):
        u12[i] = math.hypot(yend[i, 0], yend[i, 1])
        theta[i] = math.atan2(yend[i, 1], yend[i, 0])
    return u12, theta


@jit(parallel=True, error_model="numpy")
def integrate_many(pars, init, rtol, atol, utol, s_drop, max_steps):
    """:func:`integrate` for many independent cases in parallel (no per-step records).

    Parameters
    ----------
    pars : ndarray (N, NPAR)
        One parameter vector per case.
    init : ndarray (N, 6)
        Initial (vx, vy, ω, x, y, φ) per case in natural units (:func:`initial_state`).

    Returns
    -------
    y_stop : ndarray (N, NY)
        Stop states (a body at rest keeps its initial state, with ln s = −inf).
    status, n_steps, n_rhs, n_wrench_failed : ndarray (N,) of int64
    """
    n = init.shape[0]
    out = np.empty((n, NY))
    status = np.empty(n, dtype=np.int64)
    steps = np.empty(n, dtype=np.int64)
    rhss = np.empty(n, dtype=np.int64)
    fails = np.empty(n, dtype=np.int64)
    no_record = max_steps < 0
    for i in prange(n):
        y0 = initial_state(pars[i], init[i, 0], init[i, 1], init[i, 2], init[i, 3],
                           init[i, 4], init[i, 5])
        if y0[3] == -np.inf:
            for c in range(NY):
                out[i, c] = y0[c]
            status[i] = ST_AT_REST
            steps[i] = 0
            rhss[i] = 0
            fails[i] = 0
            continue
        # ``no_record`` is False as a variable: a literal False would compile integrate() a
        # second time, specialised, instead of reusing the version simulate() compiled
        yend, st, ns, nr, nf, rate, rec = integrate(
            pars[i], y0, rtol, atol, utol, s_drop, max_steps, np.inf, no_record
        )
        for c in range(NY):
            out[i, c] = yend[c]
        status[i] = st
        steps[i] = ns
        rhss[i] = nr
        fails[i] = nf
    return out, status, steps, rhss, fails
