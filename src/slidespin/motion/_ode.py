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

Footprints (MODEL §10): one integrator source serves every patch. Every compiled function
here takes the patch as the argument ``fp``: ``None`` for an ellipse (the kernel of
:mod:`slidespin.contact._kernel_ellipse`), or the tuple (edges, circles, geo) of the exact footprint kernel
(:func:`slidespin.contact._kernel_footprint.wrench_world`; :func:`footprint_argument`). numba compiles
one specialisation per argument type, on first use, and caches each on disk; the kernel is
chosen when numba types the call of :func:`accelerations` (an ``overload`` on the type of
``fp``), so the ellipse specialisation holds no footprint code and the footprint one none of
the ellipse kernel but its constants (:func:`kernel_constants`, small): an ellipse-only user
compiles only the ellipse, a footprint compiles on its first use. (Two other routes were tried and rejected: a jitted wrench function passed as an
argument, or a factory closing over it, specialise as well but miss numba's disk cache in
every new process, numba 0.68: the dispatcher's type carries a per-process identity.) For a
footprint the length unit a is its extent, and the classification of MODEL §9 uses the flags
``P_CSYM`` (pure spin about G is invariant: a centrally symmetric pressure) and ``P_RSYM``
(axisymmetric: a centred disk or ring under uniform pressure) in place of the ellipse's tests
on b/a and G.

Speed: the wrench kernel's per-body constants and its workspace are set up once per
trajectory (:func:`slidespin.contact._kernel_ellipse.wrench_constants`, :func:`~slidespin.contact._kernel_ellipse.workspace`),
so a right-hand side costs one call of the kernel's inner function; the batch
(:func:`integrate_many`) runs :func:`integrate_fp` itself, without records, under ``prange``.
Compile time: each function is compiled once per kind of patch. Nothing large is inlined by
numba (an inlined function is typed and lowered again at every call site; LLVM still inlines
where it pays), and no call passes an integer literal (numba would compile the callee once
per value: ``np.int64(40)``, not ``40``).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as _dop

from slidespin._jit import jit, prange
from slidespin.contact._engine import (
    P_BN,
    P_CSYM,
    P_K,
    P_RSYM,
    P_SHAPE,
    P_T00,
    P_T01,
    P_T10,
    P_T11,
    P_XG,
    P_YG,
    SHAPE_FOOTPRINT,
    accelerations,
    footprint_argument,
    kernel_constants,
)
from slidespin.contact._kernel_ellipse import WORKSPACE_SHAPE

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
#: |u₃| or |u₁₂| at or below which a terminal direction is pure sliding or pure spinning
ENDING_TOL = 1e-6
#: |λ|/|u·A| below which a fixed point is marginal: the direction approaches it like
#: s^(|λ|/|u·A|), algebraically in the limit (a Table 2 boundary and its analogues)
MARGIN = 1e-3
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
#: [rad] a pure-spinning ending's ϑ* needs the body to have turned less than this after the
#: vanishing velocity fell below 1e-6 of s (see :func:`_pure_spin_direction`)
PHI_RESOLVED = 0.05
SPIRAL_ARC = 3.0 * math.pi


@jit(error_model="numpy")
def _rhs(par, kc, W, fp, y, out):
    """Right-hand side of the regularised system; returns the wrench status."""
    u1 = y[0]
    u2 = y[1]
    u3 = y[2]
    inv = 1.0 / math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
    u1 *= inv
    u2 *= inv
    u3 *= inv
    ax, ay, am, st = accelerations(par, kc, W, fp, u1, u2, u3, y[7])
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
def _rhs_once(par, fp, y, out):
    return _rhs(par, kernel_constants(par), np.empty(WORKSPACE_SHAPE), fp, y, out)


def rhs(par, fe, fc, geo, y, out):
    """Right-hand side of the regularised system (one call; the integrator keeps its
    constants and workspace); returns the wrench status. ``fe``, ``fc``, ``geo``: the
    footprint arrays (:func:`no_footprint` for an ellipse; ignored unless ``par[P_SHAPE]`` is
    ``SHAPE_FOOTPRINT``)."""
    return _rhs_once(par, footprint_argument(par, fe, fc, geo), y, out)


@jit(error_model="numpy")
def tangent_jacobian(par, kc, W, fp, uu, phi, t1, t2, jac, g):
    """Jacobian of the sphere flow G(u) = A − (u·A)u in the tangent plane at the unit vector
    ``uu`` (frozen φ), by central differences; fills the tangent basis ``t1``, ``t2``, the 2×2
    ``jac`` (in that basis) and G(uu) in ``g``.

    The basis: t1 from the axis least aligned with uu, t2 = uu × t1 (at the pole u = (0, 0, 1)
    this is t1 = e_x, t2 = e_y). G is the first three components of :func:`_rhs` at ln s = 0;
    one call site keeps the compiled code small (scalar loops: array expressions compile
    slowly).
    """
    ax = (
        0
        if abs(uu[0]) <= abs(uu[1]) and abs(uu[0]) <= abs(uu[2])
        else (1 if abs(uu[1]) <= abs(uu[2]) else 2)
    )
    d = uu[ax]
    for i in range(3):
        t1[i] = (1.0 if i == ax else 0.0) - d * uu[i]
    n1 = math.sqrt(t1[0] ** 2 + t1[1] ** 2 + t1[2] ** 2)
    for i in range(3):
        t1[i] /= n1
    t2[0] = uu[1] * t1[2] - uu[2] * t1[1]
    t2[1] = uu[2] * t1[0] - uu[0] * t1[2]
    t2[2] = uu[0] * t1[1] - uu[1] * t1[0]
    yp = np.zeros(NY)
    yp[7] = phi
    out = np.empty(NY)
    hd = 1e-6
    # G at uu (m = 0) and at uu ± hd t_j (m = 1..4), central differences along t_j
    for m in range(5):
        j = (m - 1) // 2
        sg = 0.0 if m == 0 else (1.0 if m % 2 == 1 else -1.0)
        for i in range(3):
            yp[i] = uu[i] + sg * hd * (t1[i] if j == 0 else t2[i])
        _rhs(par, kc, W, fp, yp, out)
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


@jit(error_model="numpy", inline="always")
def _lam_max(jac):
    """Largest real part of the eigenvalues of a 2×2 matrix."""
    tr = jac[0, 0] + jac[1, 1]
    disc = 0.25 * tr * tr - (jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0])
    return 0.5 * tr + (math.sqrt(disc) if disc > 0.0 else 0.0)


@jit(error_model="numpy")
def polish_fixed_point(par, kc, W, fp, u, phi, max_iter, max_dist):
    """Newton iteration for the fixed point u* of the sphere flow at frozen φ (MODEL §5–6).

    Starts from ``u`` (close to u*); works in the tangent plane of the sphere with the
    central-difference Jacobian of :func:`tangent_jacobian`. Returns (u*, converged, largest
    real part of the two tangent eigenvalues, number of iterations). ``converged`` is false if
    the iteration moves more than ``max_dist`` away from ``u`` or does not settle below 1e-13
    within ``max_iter`` iterations. ``kc``, ``W``: kernel constants and workspace.
    """
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
    converged = False
    lam = 0.0
    it = 0
    # footprints: a residual at the round-off of the wrench is a fixed point already; a Newton
    # step from there is noise over the Jacobian, arbitrary along a neutral direction (e.g.
    # the circle of pure-sliding fixed points of an isotropic tensor)
    fp_floor = -1.0
    if par[P_SHAPE] == SHAPE_FOOTPRINT:
        fp_floor = 1e-15 * math.sqrt(
            par[P_T00] ** 2 + par[P_T01] ** 2 + par[P_T10] ** 2 + par[P_T11] ** 2
        )
    for it in range(max_iter):
        tangent_jacobian(par, kc, W, fp, uu, phi, t1, t2, jac, g)
        r0 = g[0] * t1[0] + g[1] * t1[1] + g[2] * t1[2]
        r1 = g[0] * t2[0] + g[1] * t2[1] + g[2] * t2[2]
        det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
        lam = _lam_max(jac)
        if math.sqrt(r0 * r0 + r1 * r1) <= fp_floor:
            converged = True
            break
        if det == 0.0 or not math.isfinite(det):
            break
        d0 = (-r0 * jac[1, 1] + r1 * jac[0, 1]) / det
        d1 = (-r1 * jac[0, 0] + r0 * jac[1, 0]) / det
        for i in range(3):
            uu[i] += d0 * t1[i] + d1 * t2[i]
        nu = math.sqrt(uu[0] ** 2 + uu[1] ** 2 + uu[2] ** 2)
        for i in range(3):
            uu[i] /= nu
        dist = math.sqrt((uu[0] - u0[0]) ** 2 + (uu[1] - u0[1]) ** 2 + (uu[2] - u0[2]) ** 2)
        if not dist <= max_dist:
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
def _equator_point(par, kc, W, fp, u, phi):
    """The pure-sliding fixed point (u₃ = 0) nearest the direction ``u``: Newton's method on
    the tangential component of the flow along the invariant circle u₃ = 0 (pure translation:
    the moment about G vanishes there). Returns (u*, converged)."""
    th = math.atan2(u[1], u[0])
    yp = np.zeros(NY)
    yp[7] = phi
    out = np.empty(NY)
    hd = 1e-7
    ok = False
    for _ in range(40):
        gv = np.empty(3)
        for m in range(3):
            t = th + (m - 1) * hd
            yp[0] = math.cos(t)
            yp[1] = math.sin(t)
            yp[2] = 0.0
            _rhs(par, kc, W, fp, yp, out)
            gv[m] = -math.sin(t) * out[0] + math.cos(t) * out[1]
        der = (gv[2] - gv[0]) / (2.0 * hd)
        if der == 0.0 or not math.isfinite(der):
            break
        step = gv[1] / der
        th -= step
        if abs(step) < 1e-14:
            ok = True
            break
    us = np.zeros(3)
    us[0] = math.cos(th)
    us[1] = math.sin(th)
    return us, ok


@jit(error_model="numpy")
def _meridian_point(par, kc, W, fp, u, phi, max_dist):
    """Under rotational symmetry, the fixed point on the meridian through ``u`` (the great
    circle through the pole and u): Newton's method on the flow's component along the
    meridian, at the fixed azimuth of u. Every rotation of a fixed point about the vertical is
    one too, so the azimuth (the direction of the velocity) is kept exactly instead of being
    left to an iteration whose Jacobian is singular along it. Returns (u*, converged)."""
    th = math.atan2(u[1], u[0])
    ct = math.cos(th)
    sn = math.sin(th)
    al0 = math.atan2(u[2], math.hypot(u[0], u[1]))
    al = al0
    yp = np.zeros(NY)
    yp[7] = phi
    out = np.empty(NY)
    hd = 1e-7
    ok = False
    gv = np.empty(3)
    for _ in range(40):
        for m in range(3):
            a = al + (m - 1) * hd
            ca = math.cos(a)
            sa = math.sin(a)
            yp[0] = ca * ct
            yp[1] = ca * sn
            yp[2] = sa
            _rhs(par, kc, W, fp, yp, out)
            gv[m] = -sa * ct * out[0] - sa * sn * out[1] + ca * out[2]
        der = (gv[2] - gv[0]) / (2.0 * hd)
        if der == 0.0 or not math.isfinite(der):
            break
        step = gv[1] / der
        al -= step
        if not abs(al - al0) <= max_dist:
            break
        if abs(step) < 1e-14:
            ok = True
            break
    us = np.zeros(3)
    us[0] = math.cos(al) * ct
    us[1] = math.cos(al) * sn
    us[2] = math.sin(al)
    return us, ok


@jit(error_model="numpy", inline="always")
def rotationally_symmetric(par):
    """True for a circular patch with a centred, axisymmetric pressure under a tensor that
    commutes with rotations (fx = fy): every rotation of a fixed point about the vertical is a
    fixed point too, so one tangent eigenvalue vanishes identically (a neutral direction along
    that circle of fixed points, not a marginal one)."""
    if par[P_SHAPE] == SHAPE_FOOTPRINT:
        axis = par[P_RSYM] != 0.0
    else:
        axis = par[P_BN] == 1.0 and par[P_XG] == 0.0 and par[P_YG] == 0.0
    return axis and par[P_T00] == par[P_T11] and par[P_T01] == -par[P_T10]


@jit(error_model="numpy")
def _rel_lam(par, kc, W, fp, us, phi):
    """λ/|u·A| at the unit vector ``us``: the largest real part of the eigenvalues of the
    sphere flow's tangent Jacobian over the decay rate of ln s (MODEL §9). Under rotational
    symmetry (:func:`rotationally_symmetric`) the neutral eigenvalue along the circle of fixed
    points is left out (away from the pole): λ is then the other one, the trace."""
    t1 = np.empty(3)
    t2 = np.empty(3)
    jac = np.empty((2, 2))
    g = np.empty(3)
    tangent_jacobian(par, kc, W, fp, us, phi, t1, t2, jac, g)
    if rotationally_symmetric(par) and us[0] ** 2 + us[1] ** 2 > ENDING_TOL**2:
        lam = jac[0, 0] + jac[1, 1]
    else:
        lam = _lam_max(jac)
    yp = np.zeros(NY)
    yp[0] = us[0]
    yp[1] = us[1]
    yp[2] = us[2]
    yp[7] = phi
    out = np.empty(NY)
    _rhs(par, kc, W, fp, yp, out)
    return lam / max(abs(out[3]), 1e-300)


@jit(error_model="numpy")
def terminal_point(par, kc, W, fp, u, phi, symmetric, max_iter, max_dist):
    """The fixed point of the sphere flow that the direction ``u`` approaches, at frozen φ.

    Newton's method first (:func:`polish_fixed_point`, or :func:`_meridian_point` under
    rotational symmetry); where it fails because the Jacobian is singular (a marginal fixed
    point), the invariant sets on which Table 2's boundaries
    lie: the pole (pure spin about G, a fixed point for a centrally symmetric pressure) and
    the equator (pure sliding), accepted only if marginal there. Returns (u*, found, λ/|u·A|,
    right-hand-side calls).
    """
    u12 = math.sqrt(u[0] ** 2 + u[1] ** 2)
    if rotationally_symmetric(par) and u12 > 1e-3:
        us, ok = _meridian_point(par, kc, W, fp, u, phi, max_dist)
        calls = 120 + 6
    else:
        us, ok, lam, nit = polish_fixed_point(par, kc, W, fp, u, phi, max_iter, max_dist)
        calls = 5 * nit + 6
    if ok:
        return us, True, _rel_lam(par, kc, W, fp, us, phi), calls
    cand = np.zeros(3)
    found = False
    if symmetric and u12 < 0.1:
        cand[2] = 1.0 if u[2] >= 0.0 else -1.0
        found = True
    elif abs(u[2]) < 0.1:
        cand, found = _equator_point(par, kc, W, fp, u, phi)
        calls += 120
    if found:
        rel = _rel_lam(par, kc, W, fp, cand, phi)
        if abs(rel) < MARGIN:
            return cand, True, rel, calls
    return us, False, math.nan, calls


@jit(error_model="numpy")
def _pole_eigen(par, kc, W, fp, sign, phi, out_v):
    """The linearised flow of the velocity direction (u₁, u₂) at the pole u = (0, 0, sign),
    frozen at φ: returns 0 where its Jacobian J is a multiple of the identity (the direction is
    frozen), 1 where the eigenvalues are complex (it keeps turning), 2 where they are real and
    distinct, with the eigenvector of the slower (larger) one in ``out_v[0:2]`` and the left
    eigenvector in ``out_v[2:4]``."""
    pole = np.zeros(3)
    pole[2] = sign
    t1 = np.empty(3)
    t2 = np.empty(3)
    jac = np.empty((2, 2))
    g = np.empty(3)
    tangent_jacobian(par, kc, W, fp, pole, phi, t1, t2, jac, g)
    # J in the (u₁, u₂) coordinates: t1 = e_x, t2 = ±e_y
    sy = t2[1]
    a = jac[0, 0]
    b = jac[0, 1] * sy
    c = jac[1, 0] * sy
    d = jac[1, 1]
    half = 0.5 * (a + d)
    # traceless part [[p, b], [c, -p]]: its size decides whether the direction moves at all
    p = 0.5 * (a - d)
    size = math.sqrt(p * p + b * b + c * c)
    yp = np.zeros(NY)
    yp[2] = sign
    yp[7] = phi
    out = np.empty(NY)
    _rhs(par, kc, W, fp, yp, out)
    rate = abs(out[3])  # the decay rate of ln s: the scale of every eigenvalue here
    if not math.isfinite(size) or size <= 1e-6 * rate:
        return 0
    disc = p * p + b * c
    if disc < -1e-12 * rate * rate:
        return 1
    lam = half + math.sqrt(max(disc, 0.0))
    if abs(b) + abs(lam - a) >= abs(c) + abs(lam - d):
        out_v[0], out_v[1] = b, lam - a
    else:
        out_v[0], out_v[1] = lam - d, c
    if abs(c) + abs(lam - a) >= abs(b) + abs(lam - d):  # wᵀ(J − λ) = 0
        out_v[2], out_v[3] = c, lam - a
    else:
        out_v[2], out_v[3] = lam - d, b
    return 2


@jit(error_model="numpy")
def _pure_spin_direction(par, kc, W, fp, u_pre, phi_pre, phi):
    """ϑ* of a pure-spinning ending (MODEL §9), or NaN where the velocity has no limiting
    direction.

    Near the pole u* = (0, 0, ±1) the vanishing velocity direction (u₁, u₂) obeys the linear
    flow of the 2×2 tangent Jacobian J (:func:`_pole_eigen`). Complex eigenvalues: it keeps
    turning (NaN). J ∝ the identity: it is frozen. Real distinct eigenvalues: it tends to the
    eigenvector of the slower one, on the side of the component along it of the direction
    ``u_pre`` that the integration reached at the body angle ``phi_pre`` (read while |u₁₂| was
    still far above round-off). If the body turned by more than ``PHI_RESOLVED`` after that,
    the side is not resolved (NaN); below, the eigenvector is followed continuously from
    ``phi_pre`` to the final angle ``phi`` (steps of 0.02 rad).
    """
    if not abs(phi - phi_pre) <= PHI_RESOLVED:
        # the spin was still turning the body (and with it the field that steers the
        # vanishing velocity) when |u₁₂| fell below what the integration resolves: which side
        # of the eigenvector the velocity ends on is not determined
        return math.nan
    sign = 1.0 if u_pre[2] >= 0.0 else -1.0
    ev = np.empty(4)
    vx = u_pre[0]
    vy = u_pre[1]
    kind = _pole_eigen(par, kc, W, fp, sign, phi_pre, ev)
    if kind == 1:
        return math.nan  # complex eigenvalues: the direction keeps turning
    if kind == 2:
        comp = (ev[2] * u_pre[0] + ev[3] * u_pre[1]) / (ev[2] * ev[0] + ev[3] * ev[1])
        vx, vy = ev[0], ev[1]
        if comp < 0.0:
            vx, vy = -vx, -vy
    n = int(abs(phi - phi_pre) / 0.02) + 1 if phi != phi_pre else 0
    for i in range(1, n + 1):
        kind = _pole_eigen(par, kc, W, fp, sign, phi_pre + (phi - phi_pre) * i / n, ev)
        if kind == 1:
            return math.nan
        if kind == 2:
            if ev[0] * vx + ev[1] * vy < 0.0:
                vx, vy = -ev[0], -ev[1]
            else:
                vx, vy = ev[0], ev[1]
    return math.atan2(vy, vx)


@jit(error_model="numpy")
def integrate(par, y0, rtol, atol, utol, s_drop, max_steps, h_max, record):
    """:func:`integrate_fp` for an elliptic patch (``fp`` = None)."""
    return integrate_fp(par, None, y0, rtol, atol, utol, s_drop, max_steps, h_max, record)


def integrate_on(par, fe, fc, geo, y0, rtol, atol, utol, s_drop, max_steps, h_max, record):
    """:func:`integrate_fp` for the parameter vector ``par`` and the footprint arrays ``fe``,
    ``fc``, ``geo`` of :meth:`slidespin.Body.kernel_params` (edges (n, 4), circles (m, 4)
    and kernel constants (``NGEO``,) in natural units; ignored for an ellipse): the compiled
    specialisation of the patch's kind runs, compiled on its first use."""
    return integrate_fp(
        par,
        footprint_argument(par, fe, fc, geo),
        y0,
        rtol,
        atol,
        utol,
        s_drop,
        max_steps,
        h_max,
        record,
    )


@jit(error_model="numpy")
def integrate_fp(par, fp, y0, rtol, atol, utol, s_drop, max_steps, h_max, record):
    """Integrate the regularised system from ``y0`` to the stop and classify the stop.

    Parameters
    ----------
    par : ndarray (NPAR,)
        Body, law and tensor parameters (natural units).
    fp : None or tuple of ndarray
        The patch: ``None`` for an ellipse (the kernel of :mod:`slidespin.contact._kernel_ellipse`), else the
        footprint's edges (n, 4), circles (m, 4) and kernel constants (``NGEO``,) in natural
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
    rec : ndarray (n, 10)
        Records (τ, y) of accepted steps, including the start (empty unless ``record``).
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
    rec = np.empty((cap, NY + 1))
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


@jit(error_model="numpy")
def initial_state(par, vx, vy, wn, x, y, phi):
    """Regularised initial state (MODEL §5) from the velocity (vx, vy) of G, the spin ω (as
    ``wn``) and the position (x, y, φ), all in natural units; a body at rest gets
    ln s = −inf. The same arithmetic as :func:`slidespin.motion.simulate`, so that batch and single
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
    functions as :func:`slidespin.motion.simulate` (math.hypot, math.atan2), bit for bit."""
    n = yend.shape[0]
    u12 = np.empty(n)
    theta = np.empty(n)
    for i in range(n):
        u12[i] = math.hypot(yend[i, 0], yend[i, 1])
        theta[i] = math.atan2(yend[i, 1], yend[i, 0])
    return u12, theta


def integrate_many(pars, *args):
    """:func:`integrate_fp` for many independent cases in parallel (no per-step records).

    Called as ``integrate_many(pars, edges, circles, eidx, cidx, geos, init, rtol, atol, utol,
    s_drop, max_steps)``: variadic after ``pars`` so that callers may splat the footprint
    arrays (``*fps``) as they did into the compiled function this wrapper replaced (mypy maps
    a splatted tuple of unknown length onto every remaining named parameter).

    Parameters
    ----------
    pars : ndarray (N, NPAR)
        One parameter vector per case.
    edges, circles : ndarray (·, 4)
        The footprints' edges and circles of all cases, stacked (natural units of each case):
        case i's are rows ``eidx[i, 0]:eidx[i, 1]`` and ``cidx[i, 0]:cidx[i, 1]`` (cases may
        share rows).
    eidx, cidx : ndarray (N, 2) of int64
        Row ranges into ``edges`` and ``circles`` (all zero for ellipses).
    geos : ndarray (N, NGEO)
        The footprints' kernel constants (unused for ellipses).
    init : ndarray (N, 6)
        Initial (vx, vy, ω, x, y, φ) per case in natural units (:func:`initial_state`).

    Returns
    -------
    y_stop : ndarray (N, NY)
        Stop states (a body at rest keeps its initial state, with ln s = −inf).
    status, n_steps, n_rhs, n_wrench_failed : ndarray (N,) of int64
    term : ndarray (N, 4)
        ϑ*, the saddle's ln(s/s₀), λ/|u·A| and β*/a per case (see :func:`integrate_fp`).

    Notes
    -----
    The elliptic and the footprint cases run through the specialisation of their kind
    (:func:`_integrate_many` with ``fps`` None or the footprint arrays), each compiled on its
    first use; a batch that mixes both runs twice, on each kind's rows (the cases are
    independent: the same results as one run).
    """
    edges, circles, eidx, cidx, geos, init, rtol, atol, utol, s_drop, max_steps = args
    c = np.ascontiguousarray
    pars = c(pars, dtype=np.float64)
    init = c(init, dtype=np.float64)
    foot = pars[:, P_SHAPE] == SHAPE_FOOTPRINT
    args = (rtol, atol, utol, s_drop, max_steps)
    fps = (
        c(edges, dtype=np.float64),
        c(circles, dtype=np.float64),
        c(eidx, dtype=np.int64),
        c(cidx, dtype=np.int64),
        c(geos, dtype=np.float64),
    )
    if not foot.any():
        return _integrate_many(pars, None, init, *args)
    if foot.all():
        return _integrate_many(pars, fps, init, *args)
    n = pars.shape[0]
    out = (
        np.empty((n, NY)),
        np.empty(n, dtype=np.int64),
        np.empty(n, dtype=np.int64),
        np.empty(n, dtype=np.int64),
        np.empty(n, dtype=np.int64),
        np.empty((n, 4)),
    )
    ell = np.flatnonzero(~foot)
    res = _integrate_many(c(pars[ell]), None, c(init[ell]), *args)
    for whole, part in zip(out, res):
        whole[ell] = part
    fpi = np.flatnonzero(foot)
    res = _integrate_many(
        c(pars[fpi]),
        fps[:2] + (c(fps[2][fpi]), c(fps[3][fpi]), c(fps[4][fpi])),
        c(init[fpi]),
        *args,
    )
    for whole, part in zip(out, res):
        whole[fpi] = part
    return out


@jit(parallel=True, error_model="numpy")
def _integrate_many(pars, fps, init, rtol, atol, utol, s_drop, max_steps):
    """:func:`integrate_many` for cases of one kind: ``fps`` is None (ellipses) or the tuple
    (edges, circles, eidx, cidx, geos) of its arguments."""
    n = init.shape[0]
    out = np.empty((n, NY))
    status = np.empty(n, dtype=np.int64)
    steps = np.empty(n, dtype=np.int64)
    rhss = np.empty(n, dtype=np.int64)
    fails = np.empty(n, dtype=np.int64)
    terms = np.empty((n, 4))
    no_record = max_steps < 0
    for i in prange(n):
        y0 = initial_state(
            pars[i], init[i, 0], init[i, 1], init[i, 2], init[i, 3], init[i, 4], init[i, 5]
        )
        if y0[3] == -np.inf:
            for c in range(NY):
                out[i, c] = y0[c]
            status[i] = ST_AT_REST
            steps[i] = 0
            rhss[i] = 0
            fails[i] = 0
            for c in range(4):
                terms[i, c] = math.nan
            continue
        # ``no_record`` is False as a variable: a literal False would compile integrate_fp() a
        # second time, specialised, instead of reusing the version simulate() compiled
        if fps is None:
            yend, st, ns, nr, nf, rate, rec, term = integrate_fp(
                pars[i], None, y0, rtol, atol, utol, s_drop, max_steps, np.inf, no_record
            )
        else:
            edges, circles, eidx, cidx, geos = fps
            # contiguous copies: the same array types as simulate() passes (one compilation)
            fp = (
                np.ascontiguousarray(edges[eidx[i, 0] : eidx[i, 1]]),
                np.ascontiguousarray(circles[cidx[i, 0] : cidx[i, 1]]),
                np.ascontiguousarray(geos[i]),
            )
            yend, st, ns, nr, nf, rate, rec, term = integrate_fp(
                pars[i], fp, y0, rtol, atol, utol, s_drop, max_steps, np.inf, no_record
            )
        for c in range(NY):
            out[i, c] = yend[c]
        for c in range(4):
            terms[i, c] = term[c]
        status[i] = st
        steps[i] = ns
        rhss[i] = nr
        fails[i] = nf
    return out, status, steps, rhss, fails, terms
