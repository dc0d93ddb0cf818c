"""The stop classification of MODEL §9: the fixed point of the sphere flow that the direction
of motion approaches, and what its eigenvalues say about the ending.

Near the stop s decays exponentially in the regularised time τ while the direction u
converges to a fixed point u* of the sphere flow G(u) = A − (u·A)u
(:mod:`slidespin.motion._flow`). Once s has dropped by ``s_drop`` and u is near a fixed
point, the integrator (:mod:`slidespin.motion._integrator`) finds u* by Newton's method at the
frozen final φ (:func:`polish_fixed_point`; φ moves by O(s²) from there on) and accepts it if
it is stable (both tangent eigenvalues negative) and near u. The eigenvalues of the flow at
u* decide between an exponential approach, a marginal one (|λ| < ``MARGIN`` |u·A|: an
algebraic approach at a Table 2 boundary) and a saddle (:func:`terminal_point`,
:func:`_rel_lam`). Where Newton's method fails, the invariant sets on which Table 2's
boundaries lie are searched: the pole (pure spin about G) and the equator (pure sliding,
:func:`_equator_point`); under rotational symmetry the fixed point is sought on the meridian
of u (:func:`_meridian_point`). A pure-spinning ending's ϑ* is read from the linearised flow
of the vanishing velocity at the pole (:func:`_pure_spin_direction`).

Footprints (MODEL §10): the classification uses the flags ``P_CSYM`` (pure spin about G is
invariant: a centrally symmetric pressure) and ``P_RSYM`` (axisymmetric: a centred disk or
ring under uniform pressure) in place of the ellipse's tests on b/a and G.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._engine import (
    P_BN,
    P_RSYM,
    P_SHAPE,
    P_T00,
    P_T01,
    P_T10,
    P_T11,
    P_XG,
    P_YG,
    SHAPE_FOOTPRINT,
)
from slidespin.motion._flow import NY, _rhs

#: |u₃| or |u₁₂| at or below which a terminal direction is pure sliding or pure spinning
ENDING_TOL = 1e-6
#: |λ|/|u·A| below which a fixed point is marginal: the direction approaches it like
#: s^(|λ|/|u·A|), algebraically in the limit (a Table 2 boundary and its analogues)
MARGIN = 1e-3
#: [rad] a pure-spinning ending's ϑ* needs the body to have turned less than this after the
#: vanishing velocity fell below 1e-6 of s (see :func:`_pure_spin_direction`)
PHI_RESOLVED = 0.05


@jit(error_model="numpy")
def tangent_jacobian(par, kc, W, fp, uu, phi, t1, t2, jac, g):
    """Jacobian of the sphere flow G(u) = A − (u·A)u in the tangent plane at the unit vector
    ``uu`` (frozen φ), by central differences; fills the tangent basis ``t1``, ``t2``, the 2×2
    ``jac`` (in that basis) and G(uu) in ``g``.

    The basis: t1 from the axis least aligned with uu, t2 = uu × t1 (at the pole u = (0, 0, 1)
    this is t1 = e_x, t2 = e_y). G is the first three components of
    :func:`~slidespin.motion._flow._rhs` at ln s = 0; one call site keeps the compiled code
    small (scalar loops: array expressions compile slowly).
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
def _turn_invariant(par):
    """True if the flow does not depend on the body angle φ: an axisymmetric pressure about
    G (a centred circle under a radial law, or a footprint flagged ``P_RSYM``) and a tensor
    [[fx, f], [−f, fy]] with fx = fy (it commutes with rotations, in either frame)."""
    if par[P_SHAPE] == SHAPE_FOOTPRINT:
        axial = par[P_RSYM] != 0.0
    else:
        axial = par[P_BN] == 1.0 and par[P_XG] == 0.0 and par[P_YG] == 0.0
    return axial and par[P_T00] == par[P_T11] and par[P_T01] == -par[P_T10]


@jit(error_model="numpy")
def _pure_spin_direction(par, kc, W, fp, u_pre, phi_pre, phi):
    """ϑ* of a pure-spinning ending (MODEL §9), or NaN where the velocity has no limiting
    direction.

    Near the pole u* = (0, 0, ±1) the vanishing velocity direction (u₁, u₂) obeys the linear
    flow of the 2×2 tangent Jacobian J (:func:`_pole_eigen`). Complex eigenvalues: it keeps
    turning (NaN). J ∝ the identity: it is frozen. Real distinct eigenvalues: it tends to the
    eigenvector of the slower one, on the side of the component along it of the direction
    ``u_pre`` that the integration reached at the body angle ``phi_pre`` (read while |u₁₂| was
    still far above round-off). Where the flow does not depend on φ (:func:`_turn_invariant`)
    J ∝ 1 freezes the direction at ``u_pre`` however far the body turns on. Otherwise, if the
    body turned by more than ``PHI_RESOLVED`` after ``phi_pre``, the side is not resolved (NaN); below, the eigenvector is followed continuously from
    ``phi_pre`` to the final angle ``phi`` (steps of 0.02 rad).
    """
    sign = 1.0 if u_pre[2] >= 0.0 else -1.0
    ev = np.empty(4)
    if _turn_invariant(par):
        # an axisymmetric patch under a tensor that commutes with rotations: the flow does
        # not depend on φ, J is fixed, and the direction is frozen (J ∝ 1) or turns for ever
        if _pole_eigen(par, kc, W, fp, sign, phi_pre, ev) == 0:
            return math.atan2(u_pre[1], u_pre[0])
        return math.nan
    if not abs(phi - phi_pre) <= PHI_RESOLVED:
        # the spin was still turning the body (and with it the field that steers the
        # vanishing velocity) when |u₁₂| fell below what the integration resolves: which side
        # of the eigenvector the velocity ends on is not determined
        return math.nan
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
