"""Compiled integration to the stop in the regularised time of MODEL §5.

The system (the state y = (u, ln s, t, x, y, φ, ℓ) and its right-hand side) is that of
:mod:`slidespin.motion._flow`: smooth through the stop, where s decays exponentially in τ while
u converges to a fixed point u* of the sphere flow and t, x, y, φ converge to their stop
values. The integrator is the Dormand–Prince 8(5,3) pair (DOP853, Hairer–Nørsett–Wanner)
with the coefficients (:mod:`slidespin.motion._dop853`) and error norm of
``scipy.integrate.DOP853``, run entirely in compiled
code; u is projected back onto the unit sphere after each step. Once s has dropped by
``s_drop`` and u is near a fixed point (|du/dτ| < ``POLISH_START``), the fixed point u* is
found by Newton's method at the frozen final φ (φ moves by O(s²) from there on) and accepted
if it is stable (both tangent eigenvalues negative) and within ``POLISH_MAX_MOVE`` of u;
otherwise integration goes on (a new attempt each time |du/dτ| has halved) until
|du/dτ| < ``utol``. The stop is then classified from that fixed point and its eigenvalues
(MODEL §9; :mod:`slidespin.motion._stops`). The remaining tail is added in closed form
(t += s/|u·A|, x += s² u₁/(2|u·A|), ...); its error is O(s·|u − u*|/|u·A|), below 1e-12 s₀
in t since s < 1e-8 s₀ and |u − u*| ≲ 1e-4/|λ|.

Footprints (MODEL §10): one integrator source serves every patch. Every compiled function
here takes the patch as the argument ``fp``: ``None`` for an ellipse (the kernel of
:mod:`slidespin.contact._kernel_ellipse`), or the tuple (edges, circles, geo) of the exact
footprint kernel (:func:`slidespin.contact._kernel_footprint.wrench_world`;
:func:`footprint_argument`). numba compiles one specialisation per argument type, on first
use, and caches each on disk; the kernel is chosen when numba types the call of
:func:`~slidespin.contact._engine.accelerations` (an ``overload`` on the type of ``fp``), so
the ellipse specialisation holds no footprint code and the footprint one none of the ellipse
kernel but its constants (:func:`kernel_constants`, small): an ellipse-only user compiles
only the ellipse, a footprint compiles on its first use. (Two other routes were tried and
rejected: a jitted wrench function passed as an argument, or a factory closing over it,
specialise as well but miss numba's disk cache in every new process, numba 0.68: the
dispatcher's type carries a per-process identity.) For a footprint the length unit a is its
extent.

Speed: the wrench kernel's per-body constants and its workspace are set up once per
trajectory (:func:`slidespin.contact._kernel_ellipse.wrench_constants`,
:func:`~slidespin.contact._kernel_ellipse.workspace`), so a right-hand side costs one call of
the kernel's inner function; the batch
(:func:`slidespin.motion._parallel.integrate_many`) runs :func:`integrate_fp` itself, without
records, under ``prange``.
Compile time: each function is compiled once per kind of patch. Nothing large is inlined by
numba (an inlined function is typed and lowered again at every call site; LLVM still inlines
where it pays), and no call passes an integer literal (numba would compile the callee once
per value: ``np.int64(40)``, not ``40``).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _aot
from slidespin._jit import jit
from slidespin.contact._engine import (
    P_BODY,
    P_CSYM,
    P_K,
    P_SHAPE,
    P_T00,
    P_T01,
    P_T10,
    P_T11,
    P_XG,
    P_YG,
    SHAPE_FOOTPRINT,
    elliptic_args,
    footprint_argument,
    kernel_constants,
)
from slidespin.contact._kernel_ellipse import WORKSPACE_SHAPE
from slidespin.contact._kernel_ellipse import wrench_array as ellipse_wrench_array
from slidespin.contact._kernel_footprint import wrench_array as footprint_wrench_array
from slidespin.motion import _dop853 as _dop
from slidespin.motion._flow import NY, _rhs
from slidespin.motion._stops import (
    ENDING_TOL,
    MARGIN,
    _pure_spin_direction,
    _rel_lam,
    polish_fixed_point,
    terminal_point,
)

_NS = _dop.N_STAGES  # 12
_A = np.ascontiguousarray(_dop.A)
_B = np.ascontiguousarray(_dop.B)
_C = np.ascontiguousarray(_dop.C)
_E3 = np.ascontiguousarray(_dop.E3)
_E5 = np.ascontiguousarray(_dop.E5)

#: |du/dτ| below which the terminal direction is polished by Newton (once s has dropped by
#: ``s_drop``), and the farthest the polished direction may lie from the integrated one
POLISH_START = 1e-4
POLISH_MAX_MOVE = 1e-2

# integration status codes (indices into slidespin.motion.outcomes.STATUSES; ST_SPIRAL is reported
# as "stopped" with the ending "spiral")
(
    ST_STOPPED,
    ST_MAX_STEPS,
    ST_STEP_TOO_SMALL,
    ST_AT_REST,
    ST_MARGINAL,
    ST_SADDLE,
    ST_NON_FINITE,
    ST_SPIRAL,
) = range(8)
#: |u₃| (|u₁₂|) below which the sign of the spin (the direction of the velocity) is at the
#: level of the round-off of the friction moment (force) and no longer set by the physics
EPS_INVARIANT = 1e-9
# once s < s_drop s₀: every further drop of s by e^LN_S_WINDOW, a search for an attracting
# fixed point near the current direction; if none has been seen while the direction swept an
# arc of SPIRAL_ARC [rad] (one and a half turns of a great circle), it turns for ever: the
# ω-limit set of the flow on the sphere is a closed orbit (Poincaré–Bendixson), a spiral stop
LN_S_WINDOW = 30.0
#: a direction that moved less than this over a whole window has converged even where no
#: smooth fixed point is found (a kernel not differentiable there: a blade with the ICR on it)
WIN_STILL = 1e-8
SPIRAL_ARC = 3.0 * math.pi
#: windows in which the direction stays near an attracting fixed point without halving its
#: distance to it: over STALL_WINDOWS · LN_S_WINDOW in ln s the distance falls by less than
#: a half, so the approach's rate is below ln 2 / 720 < MARGIN relative to the decay of ln s:
#: marginal by definition (e.g. a slow focus under a strongly skew tensor); reported as such
#: at the fixed point rather than run to the step budget
STALL_WINDOWS = 24


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
def integrate(par, y0, rtol, atol, utol, s_drop, max_steps, h_max, record, stages):
    """:func:`integrate_fp` for an elliptic patch (``fp`` = None)."""
    return integrate_fp(par, None, y0, rtol, atol, utol, s_drop, max_steps, h_max, record, stages)


def integrate_on(
    par, fe, fc, geo, y0, rtol, atol, utol, s_drop, max_steps, h_max, record, stages=False
):
    """:func:`integrate_fp` for the parameter vector ``par`` and the footprint arrays ``fe``,
    ``fc``, ``geo`` of :meth:`slidespin.Body.engine_params` (edges (n, 4), circles (m, 4)
    and kernel constants (``NGEO``,) in natural units; ignored for an ellipse).

    The ahead-of-time compiled core runs it when the install built one from these sources
    (:mod:`slidespin._aot`; the same code, the same numbers); otherwise the JIT
    specialisation of the patch's kind, compiled on its first use.
    """
    fp = footprint_argument(par, fe, fc, geo)
    par = np.ascontiguousarray(par, dtype=np.float64)
    y0 = np.ascontiguousarray(y0, dtype=np.float64)
    tail = (float(rtol), float(atol), float(utol), float(s_drop), int(max_steps), float(h_max))
    aot = _aot.core()
    if aot is not None:
        if fp is None:
            return aot.integrate_ellipse(par, y0, *tail, bool(record), bool(stages))
        return aot.integrate_footprint(par, *fp, y0, *tail, bool(record), bool(stages))
    return integrate_fp(par, fp, y0, *tail, bool(record), bool(stages))


def wrench_rows(par, fe, fc, geo, phi, u1, u2, w):
    """The friction wrench (Fx, Fy, M) in natural units along recorded rows: body angle
    ``phi``, velocity ``(u1, u2)`` and spin ``w`` (1-D arrays of equal length), for the patch
    of ``par`` (the ellipse kernel to 1e-12, or the footprint's exact kernel). Run by the
    ahead-of-time compiled core when there is one, like :func:`integrate_on`."""
    phi, u1, u2, w = (np.ascontiguousarray(x, dtype=np.float64) for x in (phi, u1, u2, w))
    fp = footprint_argument(par, fe, fc, geo)
    if fp is None:
        fx, fy, mm, _ = ellipse_wrench_array(*elliptic_args(par), phi, u1, u2, w, 1e-12)
        return fx, fy, mm
    t = (float(par[P_T00]), float(par[P_T01]), float(par[P_T10]), float(par[P_T11]))
    body = bool(par[P_BODY] != 0.0)
    aot = _aot.core()
    run = footprint_wrench_array if aot is None else aot.wrench_array_footprint
    return run(*fp, *t, body, phi, u1, u2, w)


@jit(error_model="numpy")
def integrate_fp(par, fp, y0, rtol, atol, utol, s_drop, max_steps, h_max, record, stages):
    """Integrate the regularised system from ``y0`` to the stop and classify the stop.

    Parameters
    ----------
    par : ndarray (NPAR,)
        Body, law and tensor parameters (natural units).
    fp : None or tuple of ndarray
        The patch: ``None`` for an ellipse (the kernel of
        :mod:`slidespin.contact._kernel_ellipse`), else the footprint's edges (n, 4), circles (m, 4) and kernel constants (``NGEO``,) in natural
        units (lengths in the extent, unit load; :func:`footprint_argument`). numba compiles
        one specialisation per kind, on first use.
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
    stages : bool
        With ``record``, keep also each accepted step's 13 stage derivatives (the last at
        its end), for its dense output (:mod:`slidespin.motion._sensitivity_colloc`).

    Returns
    -------
    y_stop : ndarray (9,)
        State at the stop (tail added; s = 0 there, stored as ln s = −inf); its u is the
        reported terminal direction (the analytic fixed point for ``ST_MARGINAL``, the saddle
        for ``ST_SADDLE``).
    status : int
        ``ST_STOPPED``, ``ST_SPIRAL`` (stopped, but the direction of motion keeps turning: no
        terminal direction exists), ``ST_MARGINAL``, ``ST_SADDLE``, ``ST_MAX_STEPS``,
        ``ST_STEP_TOO_SMALL`` or ``ST_NON_FINITE``.
    n_steps, n_rhs, n_wrench_failed : int
        Accepted steps, right-hand-side calls, wrench evaluations above their error target.
    rate : float
        |u·A| at the stop (the final decay rate of ln s).
    rec : ndarray (n, 10) or (n, 10 + 13 · 9)
        Records (τ, y) of accepted steps, including the start (empty unless ``record``);
        with ``stages``, then the stages of the step that ended there (K₀ … K₁₂, 0 at the
        start).
    term : ndarray (4,)
        ϑ* (NaN where no limiting direction exists; the direction reached if not converged),
        ln(s/s₀) down to which a ``saddle`` ending was observed (NaN otherwise), the largest
        real part of the eigenvalues of the sphere flow at the reported fixed point relative to
        the decay rate (λ/|u·A|), and β*/a = k u₁₂/u₃ of the reported direction (inf for
        u₃ = 0).

    Notes
    -----
    The stop is classified from the analysis of the fixed point u* (MODEL §9), not from the
    last step: u* is polished by Newton's method at the frozen final φ and the eigenvalues of
    the flow there decide between an exponential approach (``ST_STOPPED``), a marginal one
    (|λ| < ``MARGIN`` |u·A|: an algebraic approach at a Table 2 boundary, reported at its
    analytic limit) and a saddle. The spin can never change sign in exact arithmetic (pure
    translation is an invariant set: the moment about G vanishes there), nor can the velocity
    of G vanish exactly under a centrally symmetric pressure (pure spin is invariant); a
    trajectory that comes within ``EPS_INVARIANT`` of either set and then leaves it has been
    steered out by round-off, and is reported as a ``saddle`` passage at the energy where it
    came that close.
    """
    y = y0.copy()
    nrm = math.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2])
    y[0] /= nrm
    y[1] /= nrm
    y[2] /= nrm
    ln_s0 = y[3]
    ln_s_target = ln_s0 + math.log(s_drop)
    spin0 = y[2] != 0.0
    slide0 = y[0] != 0.0 or y[1] != 0.0
    sign3 = 1.0 if y[2] > 0.0 else -1.0
    eps_inv = max(EPS_INVARIANT, 10.0 * atol)
    # the last direction whose velocity part is still well above round-off and the
    # integrator's absolute tolerance: where a pure-spinning ending's ϑ* is read
    thr12 = ENDING_TOL
    u_dir = y[:3].copy()
    phi_dir = y[7]
    u_sad12 = y[:3].copy()
    phi_sad12 = y[7]
    if par[P_SHAPE] == SHAPE_FOOTPRINT:
        symmetric = par[P_CSYM] != 0.0
    else:
        symmetric = par[P_XG] == 0.0 and par[P_YG] == 0.0
    K = np.empty((_NS + 1, NY))
    f = np.empty(NY)
    yt = np.empty(NY)
    ynew = np.empty(NY)
    scale = np.empty(NY)
    kc = kernel_constants(par)
    W = np.empty(WORKSPACE_SHAPE)
    fails = 0
    fails += _rhs(par, kc, W, fp, y, f)
    nrhs = 1
    cap = 256 if record else 1
    width = NY + 1 + (_NS + 1) * NY if record and stages else NY + 1
    rec = np.empty((cap, width))
    nrec = 0
    tau = 0.0
    term = np.empty(4)
    term[0] = math.nan
    term[1] = math.nan
    term[2] = math.nan
    if record:
        rec[0, 0] = tau
        for i in range(NY):
            rec[0, 1 + i] = y[i]
        for i in range(NY + 1, width):
            rec[0, i] = 0.0
        nrec = 1
    status = ST_MAX_STEPS
    finite = True
    for i in range(NY):
        if not math.isfinite(f[i]) or not (math.isfinite(y[i]) or i == 3):
            finite = False
    if not finite or not math.isfinite(ln_s0):
        status = ST_NON_FINITE
        max_steps = 0
    # initial step: resolve the sphere flow (rates are O(friction coefficient))
    fm = math.sqrt(f[0] ** 2 + f[1] ** 2 + f[2] ** 2 + f[3] ** 2)
    h = min(h_max, 0.01 / max(fm, 1e-3)) if finite else 0.0
    nsteps = 0
    exponent = -1.0 / 8.0
    du_polish = math.inf  # |du/dτ| at the last polishing attempt
    # near-invariant sets (MODEL §9): ln s when |u₃| (|u₁₂|) first fell below EPS_INVARIANT,
    # and the direction where the flow was slowest while still close to the set
    ln_inv3 = math.nan
    ln_inv12 = math.nan
    du_inv3 = math.inf
    du_inv12 = math.inf
    u_inv3 = np.zeros(3)
    u_inv12 = np.zeros(3)
    # windows of LN_S_WINDOW in ln s once s < s_drop s₀: fixed-point search and spiral test
    ln_s_win = math.inf
    u_win = np.zeros(3)  # the direction at the start of the current window
    arc = 0.0  # arc swept by u since the tail began or an attracting point was last seen
    u3_max = 0.0  # largest |u₃| over that arc, and over the arc before
    u3_max_prev = math.inf
    extra_arcs = 0
    spiral_slides = False
    tau_arc = 0.0
    us_prev = np.zeros(3)  # the attracting fixed point found at the last window
    d_ref = math.inf  # distance from it when first found
    stalled = 0  # windows spent near an attracting point without converging to it
    while nsteps < max_steps:
        rejected = False
        while True:
            if not h >= 1e-12 * (1.0 + tau):  # (also catches a NaN step)
                status = ST_STEP_TOO_SMALL if h == h else ST_NON_FINITE
                break
            for i in range(NY):
                K[0, i] = f[i]
            for st in range(1, _NS):
                for i in range(NY):
                    acc = 0.0
                    for j in range(st):
                        acc += _A[st, j] * K[j, i]
                    yt[i] = y[i] + h * acc
                fails += _rhs(par, kc, W, fp, yt, K[st])
                nrhs += 1
            for i in range(NY):
                acc = 0.0
                for j in range(_NS):
                    acc += _B[j] * K[j, i]
                ynew[i] = y[i] + h * acc
            fails += _rhs(par, kc, W, fp, ynew, K[_NS])
            nrhs += 1
            for i in range(NY):
                scale[i] = atol + max(abs(y[i]), abs(ynew[i])) * rtol
            # the body angle to an absolute tolerance: relative to |φ| it would loosen with
            # every turn, and β*, ϑ* at the frozen final φ inherit its error
            scale[7] = atol
            en = _err_norm(K, h, scale)
            if not math.isfinite(en):
                status = ST_NON_FINITE
                break
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
        if status == ST_STEP_TOO_SMALL or status == ST_NON_FINITE:
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
                big = np.empty((2 * cap, width))
                for i in range(cap):  # (loops: slice assignment is slow to compile)
                    for c in range(width):
                        big[i, c] = rec[i, c]
                rec = big
                cap *= 2
            rec[nrec, 0] = tau
            for i in range(NY):
                rec[nrec, 1 + i] = y[i]
            if width > NY + 1:
                for j in range(_NS + 1):
                    for i in range(NY):
                        rec[nrec, 1 + NY + j * NY + i] = K[j, i]
            nrec += 1
        du = math.sqrt(f[0] ** 2 + f[1] ** 2 + f[2] ** 2)
        u12 = math.sqrt(y[0] * y[0] + y[1] * y[1])
        if u12 > thr12:
            u_dir[0] = y[0]
            u_dir[1] = y[1]
            u_dir[2] = y[2]
            phi_dir = y[7]
        if spin0 and (abs(y[2]) < eps_inv or y[2] * sign3 < 0.0) and ln_inv3 != ln_inv3:
            ln_inv3 = y[3]
        if ln_inv3 == ln_inv3 and abs(y[2]) < 1e-3 and du < du_inv3:
            du_inv3 = du
            for i in range(3):
                u_inv3[i] = y[i]
        if symmetric and slide0 and u12 < eps_inv and ln_inv12 != ln_inv12:
            ln_inv12 = y[3]
            for i in range(3):  # the last direction well above round-off, for ϑ*
                u_sad12[i] = u_dir[i]
            phi_sad12 = phi_dir
        if ln_inv12 == ln_inv12 and u12 < 1e-3 and du < du_inv12:
            du_inv12 = du
            for i in range(3):
                u_inv12[i] = y[i]
        if y[3] < ln_s_target:
            if du < utol:
                status = ST_STOPPED
                break
            if du < POLISH_START and du < 0.5 * du_polish:
                # near a hyperbolic fixed point: Newton gives u* to ~1e-13 at once, where the
                # explicit integrator would take many more steps to converge
                du_polish = du
                us, ok, lam, nit = polish_fixed_point(
                    par, kc, W, fp, y[:3], y[7], np.int64(12), POLISH_MAX_MOVE
                )
                nrhs += 5 * nit
                if ok and lam < 0.0:
                    status = ST_STOPPED
                    break
            arc += du * (tau - tau_arc)
            tau_arc = tau
            u3_max = max(u3_max, abs(y[2]))
            if ln_s_win == math.inf:
                ln_s_win = y[3] - LN_S_WINDOW
                for i in range(3):
                    u_win[i] = y[i]
                arc = 0.0
                u3_max = abs(y[2])
            elif y[3] < ln_s_win:
                # s fell by another e^LN_S_WINDOW: t, x, y, φ have converged far below
                # rounding and only the direction's limit is open. A fixed point that attracts
                # (exponentially, or algebraically at a boundary) and that the direction has
                # come to half its distance from (or within 1e-3) is the limit; a direction
                # that sweeps SPIRAL_ARC with no attracting point near turns for ever
                us, ok, rel, calls = terminal_point(
                    par, kc, W, fp, y[:3], y[7], symmetric, np.int64(40), 0.5
                )
                nrhs += calls
                attracting = ok and rel <= MARGIN
                if attracting:
                    d = math.sqrt((y[0] - us[0]) ** 2 + (y[1] - us[1]) ** 2 + (y[2] - us[2]) ** 2)
                    same = (
                        math.sqrt(
                            (us[0] - us_prev[0]) ** 2
                            + (us[1] - us_prev[1]) ** 2
                            + (us[2] - us_prev[2]) ** 2
                        )
                        < 1e-8
                    )
                    if not same:
                        d_ref = d
                        for i in range(3):
                            us_prev[i] = us[i]
                    if d < max(1e-3, 100.0 * atol) or d < 0.5 * d_ref:
                        status = ST_STOPPED
                        break
                    stalled += 1
                    if stalled >= STALL_WINDOWS:
                        status = ST_MARGINAL
                        break
                    arc = 0.0
                    u3_max = abs(y[2])
                    u3_max_prev = math.inf
                elif arc > SPIRAL_ARC:
                    # no attracting point, and the direction keeps turning. Over those turns
                    # the spin stayed below ENDING_TOL: it dies out on the orbit (β* = ∞);
                    # it is still shrinking: watch more turns (at most 20 more arcs); else
                    # the orbit is off the equator and keeps it (β* NaN)
                    if u3_max <= ENDING_TOL:
                        spiral_slides = True
                        status = ST_SPIRAL
                        break
                    if extra_arcs < 20 and (u3_max < 0.7 * u3_max_prev or abs(y[2]) < 0.5 * u3_max):
                        extra_arcs += 1
                        u3_max_prev = u3_max
                        arc = 0.0
                        u3_max = abs(y[2])
                    else:
                        status = ST_SPIRAL
                        break
                elif (
                    not ok
                    and math.sqrt(
                        (y[0] - u_win[0]) ** 2 + (y[1] - u_win[1]) ** 2 + (y[2] - u_win[2]) ** 2
                    )
                    < WIN_STILL
                ):
                    # no smooth fixed point (a kernel that is not differentiable there, e.g.
                    # the v ln|v| force of a blade with the ICR on it), but the direction has
                    # not moved over a whole window: it has converged
                    status = ST_STOPPED
                    break
                ln_s_win = y[3] - LN_S_WINDOW
                for i in range(3):
                    u_win[i] = y[i]
    stall = status == ST_MARGINAL  # the slow approach above: classified as a stop, marginal
    if stall:
        status = ST_STOPPED
    if status == ST_STOPPED:
        # classify the stop from the fixed point and its eigenvalues (MODEL §9)
        u_pre = u_dir
        us, ok, rel, calls = terminal_point(
            par, kc, W, fp, y[:3], y[7], symmetric, np.int64(60), 0.5
        )
        nrhs += calls
        if ok:
            y[0] = us[0]
            y[1] = us[1]
            y[2] = us[2]
        else:
            rel = _rel_lam(par, kc, W, fp, y[:3], y[7])
        term[2] = rel
        u12 = math.sqrt(y[0] * y[0] + y[1] * y[1])
        if ln_inv3 == ln_inv3 and abs(y[2]) > ENDING_TOL:
            # the spin came back from round-off: what the motion does down to that energy is
            # to approach pure sliding (the invariant set ω = 0)
            us, ok, lam, nit = polish_fixed_point(par, kc, W, fp, u_inv3, y[7], np.int64(40), 0.05)
            src = us if ok else u_inv3
            n12 = math.sqrt(src[0] ** 2 + src[1] ** 2)
            y[0] = src[0] / n12
            y[1] = src[1] / n12
            y[2] = 0.0
            status = ST_SADDLE
            term[1] = ln_inv3 - ln_s0
        elif ln_inv12 == ln_inv12 and u12 > ENDING_TOL:
            y[0] = 0.0
            y[1] = 0.0
            y[2] = 1.0 if u_inv12[2] >= 0.0 else -1.0
            u_pre = u_sad12
            phi_dir = phi_sad12
            status = ST_SADDLE
            term[1] = ln_inv12 - ln_s0
        elif stall:
            status = ST_MARGINAL
        elif rel > -MARGIN:
            if rel < MARGIN:
                status = ST_MARGINAL
            elif not (
                (not spin0 and abs(y[2]) <= ENDING_TOL)
                or (not slide0 and symmetric and u12 <= ENDING_TOL)
            ):
                # held on an unstable fixed point (other than by an exact invariance)
                status = ST_SADDLE
                term[1] = y[3] - ln_s0
        u12 = math.sqrt(y[0] * y[0] + y[1] * y[1])
        if u12 <= ENDING_TOL:
            y[0] = 0.0
            y[1] = 0.0
            y[2] = 1.0 if y[2] >= 0.0 else -1.0
            term[0] = _pure_spin_direction(par, kc, W, fp, u_pre, phi_dir, y[7])
            nrhs += 5
        else:
            if abs(y[2]) <= ENDING_TOL:
                y[0] /= u12
                y[1] /= u12
                y[2] = 0.0
            term[0] = math.atan2(y[1], y[0])
        fails += _rhs(par, kc, W, fp, y, f)
    # β*/a = k u₁₂/u₃ of the reported direction (computed here, so that simulate() and the
    # batch agree to the last bit)
    u12 = math.hypot(y[0], y[1])
    term[3] = math.inf if y[2] == 0.0 else par[P_K] * u12 / y[2]
    if status == ST_SPIRAL:
        term[3] = math.inf if spiral_slides else math.nan
    if status != ST_STOPPED and status != ST_MARGINAL and status != ST_SADDLE:
        term[0] = math.atan2(y[1], y[0])  # not converged: the direction as reached
    # closed-form tail: ln s decays at the rate |u·A| once u has converged
    rate = -f[3]
    yend = y.copy()
    if rate > 0.0 and math.isfinite(rate):
        s = math.exp(y[3])
        yend[4] += s / rate
        q = s * s / (2.0 * rate)
        yend[5] += q * y[0]
        yend[6] += q * y[1]
        yend[7] += q * y[2] / par[P_K]
        yend[8] += q * math.sqrt(y[0] ** 2 + y[1] ** 2)
    yend[3] = -np.inf
    return yend, status, nsteps, nrhs, fails, rate, rec[:nrec].copy(), term
