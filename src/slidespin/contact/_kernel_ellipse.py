"""Compiled friction wrench on an elliptic patch (plain floats in, plain floats out).

Method (MODEL §2–3; the paper's route, eq. 8–9 and 12–13, is not used here): for ω ≠ 0 the
force and the moment about G are one angular integral, over a half turn, of the chord moments
of the lines through the instantaneous centre of rotation (ICR). The integrand, its
singularities, the tabulated rules (trapezoid, plain or √κ-mapped; sine-trapezoid;
Clenshaw–Curtis) and the node rule are in :mod:`slidespin.contact._kernel_ellipse_rules` (its
notes give the derivation and the calibration). Here, per state (:func:`wrench_fast`): a pure
translation (ω = 0, or the ICR beyond ``FAR_ICR``) in closed form; otherwise the rule whose
predicted cost is least, its error estimated from the nested rules and checked against
``tol``. If the check fails, N is doubled; beyond ``MAX_NODES`` nodes (ICR within ~1e-4 a of
the rim with uniform or linear pressure, or b/a below ~5e-3) globally adaptive Gauss–Kronrod
7/15 takes over, split at ψ₁ (:mod:`slidespin.contact._kernel_ellipse_adaptive`).

Speed: per-body constants (:func:`wrench_constants`) and the workspace (:func:`workspace`) can
be set up once and reused (:func:`wrench_fast`).

Units: lengths in units of the semi-axis a (a = 1), load P = 1. The caller rescales.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _aot
from slidespin._jit import jit
from slidespin.contact._kernel_ellipse_adaptive import (
    STATUS_OK,
    _adaptive,
    adaptive_derivative_sums,
)
from slidespin.contact._kernel_ellipse_lines import LAW_LINEAR, LAW_UNIFORM
from slidespin.contact._kernel_ellipse_rules import (
    _CC_SIZES,
    _NODE_SIZES,
    C_CC,
    C_SINE,
    C_TRAPEZOID,
    COST_MAPPED,
    COST_ROTATED,
    ENTIRE_HEIGHT_CC,
    ENTIRE_HEIGHT_SINE,
    GAMMA_CC,
    GAMMA_TRAPEZOID,
    MAP_MIN_HALF_WIDTH,
    MAX_NODES,
    METHOD_ADAPTIVE_INSIDE,
    METHOD_ADAPTIVE_OUTSIDE,
    METHOD_CLENSHAW_CURTIS,
    METHOD_CLENSHAW_CURTIS_INSIDE,
    METHOD_CLENSHAW_CURTIS_MAPPED,
    METHOD_SINE,
    METHOD_SINE_MAPPED,
    METHOD_TRANSLATION,
    METHOD_TRAPEZOID,
    METHOD_TRAPEZOID_MAPPED,
    MIN_NODES,
    MIN_NODES_CC,
    _atanh_sym,
    _count,
    _estimate,
    _log_rho,
    _mapped_strip,
    _out_distance,
    _q_form,
    _run_rule,
)

FAR_ICR = 1e15  # beyond this distance (in units of a) the ICR is at infinity: pure translation


# ---------------------------------------------------------------------------------------------
# the wrench

#: rows and columns of the workspace the rules need
WORKSPACE_SHAPE = (8, MAX_NODES + 1)


def workspace():
    """A workspace for :func:`wrench_fast` (reuse it across calls; one per thread)."""
    return np.empty(WORKSPACE_SHAPE)


@jit(error_model="numpy")
def wrench_constants(bn, law, xg, yg, tnorm, tol):
    """Per-body constants of the kernel: (κ, 1/κ², 1/κ, ξ_G, η_G, lx, ly, √κ, re0, d_A,
    d_A(√κ map), ln(‖𝔽‖/tol), tanh d_A, expm1(4 d_A(√κ map))) with ‖𝔽‖ the Frobenius norm,
    which does not change when the tensor is turned between frames."""
    s22 = 1.0 / (bn * bn)
    lx = 4.0 * xg if law == LAW_LINEAR else 0.0
    ly = 4.0 * yg * s22 if law == LAW_LINEAR else 0.0
    ksq = math.sqrt(bn)
    re0 = 0.0 if bn < 1.0 else 0.5 * math.pi  # A-points: tan ψ = ±iκ
    # the line integrands carry a factor 1/κ (and the moment arm κ for κ > 1)
    logterm = max(math.log(tnorm / tol * max(bn, 1.0 / bn)), 0.0) if tnorm > 0.0 else 0.0
    d_a = _atanh_sym(bn)
    d_am = _atanh_sym(ksq)
    return (
        bn,
        s22,
        1.0 / bn,
        xg,
        yg,
        lx,
        ly,
        ksq,
        re0,
        d_a,
        d_am,
        logterm,
        min(bn, 1.0 / bn),
        math.expm1(4.0 * d_am) if d_am < 100.0 else math.inf,
    )


@jit(error_model="numpy")
def wrench_rule(law, K, t00, t01, t10, t11, vx, vy, omega, tol, W, D):
    """:func:`wrench_fast` and the last tabulated rule it ran: (fx, fy, m, status, method,
    nodes, n, half, rule, derr), ``rule`` that rule's method code, ``n`` its node count (0
    if none ran, a translation, or after the adaptive fallback) and ``half`` its half-width
    (Clenshaw–Curtis); its directions and weights are left in rows 0–4 of ``W``. Unless ``D`` is ``None`` (a flag), ``W`` is a
    derivative workspace and each rule also fills its lower rows with the integrands of the
    wrench's twist derivatives on its nodes (:mod:`slidespin.contact._kernel_ellipse_jac`
    sums the accepted rule's); after the adaptive fallback the derivatives' integrals on its
    final partition are in the last column of those rows already
    (:func:`slidespin.contact._kernel_ellipse_adaptive.adaptive_derivative_sums`) and
    ``derr`` is their relative error estimate (−1 otherwise: nothing summed)."""
    bn, s22, ib, xg, yg, lx, ly, ksq, re0, d_a, d_am, logterm, r_a, x_am = K
    if omega == 0.0 or not (abs(vx) + abs(vy)) / abs(omega) < FAR_ICR:
        speed = math.sqrt(vx * vx + vy * vy)
        if speed == 0.0:
            return 0.0, 0.0, 0.0, STATUS_OK, METHOD_TRANSLATION, 0, 0, 0.0, METHOD_TRANSLATION, -1.0
        ux = vx / speed
        uy = vy / speed
        # pure translation: F = −𝔽 v̂, M = 0 since G lies over the pressure centroid
        return (
            -(t00 * ux + t01 * uy),
            -(t10 * ux + t11 * uy),
            0.0,
            STATUS_OK,
            METHOD_TRANSLATION,
            0,
            0,
            0.0,
            METHOD_TRANSLATION,
            -1.0,
        )
    if t00 == 0.0 and t01 == 0.0 and t10 == 0.0 and t11 == 0.0:
        return 0.0, 0.0, 0.0, STATUS_OK, METHOD_TRANSLATION, 0, 0, 0.0, METHOD_TRANSLATION, -1.0
    cx = xg - vy / omega
    cy = yg + vx / omega
    sgn = -1.0 if omega > 0.0 else 1.0  # the overall factor −sign(ω)
    branch = law == LAW_UNIFORM or law == LAW_LINEAR  # √D is a branch point
    q = cx * cx + cy * cy * s22
    used = 0
    if q <= 1.0:
        # ---- ICR inside (or on the rim): trapezoid, plain or mapped; CC near the rim
        d = d_a
        d_m = d_am if bn != 1.0 else 0.0
        r = 0.0
        c2 = 1.0
        s2 = 0.0
        if branch:
            # D's zeros at ψ₁ ± i atanh r; the logarithms only when they are the nearest
            lam1, lam2, c2, s2 = _q_form(s22, cx, cy)
            r = math.sqrt(lam1 / lam2) if lam1 > 0.0 else 0.0
            if r < r_a:  # atanh r < d_A
                d = _atanh_sym(r) if r > 0.0 else 0.0
            if bn != 1.0:
                xm = _mapped_strip(c2, s2, r, ksq) if r > 0.0 else 0.0
                if xm < x_am:
                    d_m = 0.25 * math.log1p(xm)
        method = METHOD_TRAPEZOID
        n = _count(logterm, C_TRAPEZOID, GAMMA_TRAPEZOID, d, _NODE_SIZES, MIN_NODES)
        k = 1.0
        if bn != 1.0:
            n2 = _count(logterm, C_TRAPEZOID, GAMMA_TRAPEZOID, d_m, _NODE_SIZES, MIN_NODES)
            if n2 > 0 and (n < 0 or COST_MAPPED * n2 < n):
                method = METHOD_TRAPEZOID_MAPPED
                n = n2
                k = ksq
        half = 0.5 * math.pi
        psi1 = 0.5 * math.atan2(s2, c2) if branch else 0.0
        mid = psi1 + half
        if branch and (n < 0 or n > 64):
            # near the rim: Clenshaw–Curtis over [ψ₁, ψ₁ + π], D's zeros at its ends
            cost = COST_MAPPED * n if k != 1.0 else 1.0 * n
            enough = (logterm + C_CC) / (GAMMA_CC * MIN_NODES_CC)
            d, _ = _out_distance(
                psi1, psi1 + math.pi, d_a, re0, math.pi, q > 1.0, enough, ENTIRE_HEIGHT_CC
            )  # (q > 1 is False here, as a variable)
            d = min(d, _log_rho(psi1, _atanh_sym(r) if r > 0.0 else 0.0, mid, half))
            n3 = _count(logterm, C_CC, GAMMA_CC, d, _CC_SIZES, MIN_NODES_CC)
            if n3 > 0 and (n < 0 or COST_ROTATED * (n3 + 1) < cost):
                method = METHOD_CLENSHAW_CURTIS_INSIDE
                n = n3
                k = 1.0
        while 0 < n <= MAX_NODES:
            fx, fy, mm, e1, e2 = _run_rule(
                W,
                D,
                method,
                n,
                law,
                s22,
                ib,
                lx,
                ly,
                xg,
                yg,
                t00,
                t01,
                t10,
                t11,
                cx,
                cy,
                k,
                mid,
                half,
                0.0,
                0.0,
                0.0,
            )
            used += n + 1 if method == METHOD_CLENSHAW_CURTIS_INSIDE else n
            if _estimate(e1, e2) <= tol:
                return sgn * fx, sgn * fy, sgn * mm, STATUS_OK, method, used, n, half, method, -1.0
            n *= 2
        # fallback, split where D is smallest (the near-tangent line through a near-rim ICR)
        if not branch:
            lam1, lam2, c2, s2 = _q_form(s22, cx, cy)
            psi1 = 0.5 * math.atan2(s2, c2)
        inside = q <= 1.0  # (a variable: a literal True would compile a second version)
        fx, fy, mm, nev, status, tab, n_int = _adaptive(
            inside,
            psi1,
            psi1 + math.pi,
            tol,
            law,
            s22,
            ib,
            lx,
            ly,
            xg,
            yg,
            t00,
            t01,
            t10,
            t11,
            cx,
            cy,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        )
        derr = -1.0
        if D is not None:
            derr = adaptive_derivative_sums(
                tab, n_int, inside, law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, cx, cy,
                0.0, 0.0, 0.0, 0.0, 0.0, W,
            )  # fmt: skip
        return (
            sgn * fx,
            sgn * fy,
            sgn * mm,
            status,
            METHOD_ADAPTIVE_INSIDE,
            used + nev,
            0,
            0.0,
            method,
            derr,
        )
    # ---- ICR outside: the sector α₋ ≤ α ≤ α₊ of lines that meet the patch (α from ê_c)
    dist = math.sqrt(cx * cx + cy * cy)
    ecx = -cx / dist
    ecy = -cy / dist
    nx = -ecy
    ny = ecx
    suu = ecx * ecx + ecy * ecy * s22
    suv = ecx * nx + ecy * ny * s22
    rr = math.sqrt(s22 * (q - 1.0))
    a_plus = math.atan2(suu, rr - suv)
    a_minus = math.atan2(-suu, suv + rr)
    mid = 0.5 * (a_plus + a_minus)
    half = 0.5 * (a_plus - a_minus)
    if branch:
        c_rule, gamma, sizes, least, entire = (
            C_SINE,
            GAMMA_TRAPEZOID,
            _NODE_SIZES,
            MIN_NODES,
            ENTIRE_HEIGHT_SINE,
        )
        method = METHOD_SINE
    else:
        c_rule, gamma, sizes, least, entire = (
            C_CC,
            GAMMA_CC,
            _CC_SIZES,
            MIN_NODES_CC,
            ENTIRE_HEIGHT_CC,
        )
        method = METHOD_CLENSHAW_CURTIS
    enough = (logterm + c_rule) / (gamma * least)
    psic = math.atan2(ecy, ecx)
    d, a_nearest = _out_distance(
        a_minus + psic, a_plus + psic, d_a, re0, math.pi, branch, enough, entire
    )
    n = _count(logterm, c_rule, gamma, d, sizes, least)
    k = 1.0
    # the map can only help when the A-points limit the rule
    if a_nearest and half > MAP_MIN_HALF_WIDTH and bn != 1.0:
        p_lo = psic + a_minus
        p_hi = psic + a_plus
        lo2 = math.atan2(math.sin(p_lo) / ksq, math.cos(p_lo))
        hi2 = math.atan2(math.sin(p_hi) / ksq, math.cos(p_hi))
        while hi2 < lo2:
            hi2 += 2.0 * math.pi
        while hi2 > lo2 + 2.0 * math.pi:
            hi2 -= 2.0 * math.pi
        # A-type points and the map's own, one at Re ψ' = 0, the other at π/2 (mod π)
        d, _ = _out_distance(lo2, hi2, d_am, 0.0, 0.5 * math.pi, branch, enough, entire)
        n2 = _count(logterm, c_rule, gamma, d, sizes, least)
        if n2 > 0 and (n < 0 or COST_MAPPED * n2 < n):
            n = n2
            k = ksq
            mid = 0.5 * (lo2 + hi2)
            half = 0.5 * (hi2 - lo2)
            method = METHOD_SINE_MAPPED if branch else METHOD_CLENSHAW_CURTIS_MAPPED
    while 0 < n <= MAX_NODES:
        fx, fy, mm, e1, e2 = _run_rule(
            W,
            D,
            method,
            n,
            law,
            s22,
            ib,
            lx,
            ly,
            xg,
            yg,
            t00,
            t01,
            t10,
            t11,
            cx,
            cy,
            k,
            mid,
            half,
            ecx,
            ecy,
            dist,
        )
        used += n - 1 if branch else n + 1
        if _estimate(e1, e2) <= tol:
            return sgn * fx, sgn * fy, sgn * mm, STATUS_OK, method, used, n, half, method, -1.0
        n *= 2
    mid = 0.5 * (a_plus + a_minus)
    half = 0.5 * (a_plus - a_minus)
    inside = q <= 1.0
    fx, fy, mm, nev, status, tab, n_int = _adaptive(
        inside,
        -0.5 * math.pi,
        0.5 * math.pi,
        tol,
        law,
        s22,
        ib,
        lx,
        ly,
        xg,
        yg,
        t00,
        t01,
        t10,
        t11,
        cx,
        cy,
        ecx,
        ecy,
        dist,
        mid,
        half,
    )
    derr = -1.0
    if D is not None:
        derr = adaptive_derivative_sums(
            tab, n_int, inside, law, s22, ib, lx, ly, xg, yg, t00, t01, t10, t11, cx, cy, ecx,
            ecy, dist, mid, half, W,
        )  # fmt: skip
    return (
        sgn * fx,
        sgn * fy,
        sgn * mm,
        status,
        METHOD_ADAPTIVE_OUTSIDE,
        used + nev,
        0,
        0.0,
        method,
        derr,
    )


@jit(error_model="numpy")
def wrench_fast(law, K, t00, t01, t10, t11, vx, vy, omega, tol, W):
    """:func:`wrench_body_info` with precomputed constants ``K`` (:func:`wrench_constants`)
    and a reusable workspace ``W`` (:func:`workspace`); the engine's inner call."""
    fx, fy, m, status, method, used, _, _, _, _ = wrench_rule(
        law, K, t00, t01, t10, t11, vx, vy, omega, tol, W, None
    )
    return fx, fy, m, status, method, used


@jit(error_model="numpy", inline="always")
def _tensor_norm(t00, t01, t10, t11):
    return math.sqrt(t00 * t00 + t01 * t01 + t10 * t10 + t11 * t11)


@jit(error_model="numpy")
def wrench_body_info(bn, law, xg, yg, t00, t01, t10, t11, vx, vy, omega, tol):
    """:func:`wrench_body` plus the quadrature used: (fx, fy, m, status, method, nodes).

    ``method`` is one of the ``METHOD_*`` codes (names in ``METHOD_NAMES``, both in
    :mod:`slidespin.contact._kernel_ellipse_rules`) and ``nodes`` the number of integrand
    evaluations (all attempts included).
    """
    K = wrench_constants(bn, law, xg, yg, _tensor_norm(t00, t01, t10, t11), tol)
    return wrench_fast(law, K, t00, t01, t10, t11, vx, vy, omega, tol, np.empty(WORKSPACE_SHAPE))


@jit(error_model="numpy")
def wrench_body(bn, law, xg, yg, t00, t01, t10, t11, vx, vy, omega, tol):
    """Friction wrench in the body frame, for unit load P = 1 and semi-axis a = 1.

    Parameters
    ----------
    bn : float
        b/a.
    law : int
        0 uniform, 1 linear, 2 Boussinesq, 3 Hertz.
    xg, yg : float
        Mass centre G in the body frame, units of a (the linear law's pressure centroid).
    t00, t01, t10, t11 : float
        Friction tensor in the body frame.
    vx, vy : float
        Velocity of G in the body frame (any scale: only the direction of (v/a, ω) matters).
    omega : float
        Spin rate.
    tol : float
        Absolute error target for the force (units of P) and moment (units of P a).

    Returns
    -------
    fx, fy, m : float
        Force (body frame) and moment about G, counter-clockwise positive.
    status : int
        0 converged, 1 error target not reached.
    """
    fx, fy, m, status, _, _ = wrench_body_info(
        bn, law, xg, yg, t00, t01, t10, t11, vx, vy, omega, tol
    )
    return fx, fy, m, status


@jit(error_model="numpy", inline="always")
def tensor_in_body(t00, t01, t10, t11, body_frame, c, s):
    """The friction tensor in the body frame, 𝔽_body = Rᵀ 𝔽 R with R = R(φ), c = cos φ,
    s = sin φ (unchanged if it is fixed to the body); shared by both compiled kernels."""
    if body_frame:
        return t00, t01, t10, t11
    a00 = c * t00 + s * t10
    a01 = c * t01 + s * t11
    a10 = -s * t00 + c * t10
    a11 = -s * t01 + c * t11
    return a00 * c + a01 * s, -a00 * s + a01 * c, a10 * c + a11 * s, -a10 * s + a11 * c


@jit(error_model="numpy", inline="always")
def wrench_world_fast(law, K, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol, W):
    """:func:`wrench_world` with precomputed constants and a workspace (see
    :func:`wrench_fast`)."""
    c = math.cos(phi)
    s = math.sin(phi)
    vbx = c * vx + s * vy
    vby = -s * vx + c * vy
    b00, b01, b10, b11 = tensor_in_body(t00, t01, t10, t11, body_frame, c, s)
    fbx, fby, m, status, _, _ = wrench_fast(law, K, b00, b01, b10, b11, vbx, vby, omega, tol, W)
    return c * fbx - s * fby, s * fbx + c * fby, m, status


@jit(error_model="numpy")
def wrench_world(bn, law, xg, yg, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol):
    """Friction wrench in the fixed frame (unit load, a = 1).

    The tensor (t00..t11) is given in its own frame: the plane's (``body_frame`` false,
    the paper's choice) or the body's. Velocities are those of G in the fixed frame.
    Returns (Fx, Fy, M, status) with M about G, counter-clockwise positive.
    """
    K = wrench_constants(bn, law, xg, yg, _tensor_norm(t00, t01, t10, t11), tol)
    return wrench_world_fast(
        law, K, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol, np.empty(WORKSPACE_SHAPE)
    )


def wrench_array(bn, law, xg, yg, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol):
    """:func:`wrench_world` over 1-D arrays ``phi, vx, vy, omega`` of equal length (called
    from Python): :func:`wrench_loop`, on the ahead-of-time compiled core when there is one
    (:mod:`slidespin._aot`; the same code, the same numbers).

    Returns (Fx, Fy, M, status) arrays.
    """
    c = np.ascontiguousarray
    args = (float(bn), int(law), float(xg), float(yg), float(t00), float(t01), float(t10))
    args += (float(t11), bool(body_frame))
    arrays = (c(phi, np.float64), c(vx, np.float64), c(vy, np.float64), c(omega, np.float64))
    aot = _aot.core()
    run = wrench_loop if aot is None else aot.wrench_array_ellipse
    return run(*args, *arrays, float(tol))


@jit(error_model="numpy")
def wrench_loop(bn, law, xg, yg, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol):
    """:func:`wrench_world` over 1-D arrays ``phi, vx, vy, omega`` of equal length, compiled
    (the loop of :func:`wrench_array`). Returns (Fx, Fy, M, status) arrays."""
    n = vx.size
    fx = np.empty(n)
    fy = np.empty(n)
    mm = np.empty(n)
    st = np.empty(n, dtype=np.int64)
    K = wrench_constants(bn, law, xg, yg, _tensor_norm(t00, t01, t10, t11), tol)
    W = np.empty(WORKSPACE_SHAPE)
    for i in range(n):
        fx[i], fy[i], mm[i], st[i] = wrench_world_fast(
            law, K, t00, t01, t10, t11, body_frame, phi[i], vx[i], vy[i], omega[i], tol, W
        )
    return fx, fy, mm, st
