"""Compiled friction wrench on an elliptic patch (plain floats in, plain floats out).

Method (MODEL §2–3; the paper's route, eq. 8–9 and 12–13, is not used here)
--------------------------------------------------------------------------
For ω ≠ 0 every patch point r moves with w = ω ẑ×(r − c) about the instantaneous centre of
rotation (ICR) c, so the slip direction ŵ = sign(ω) ẑ×ê(ψ) depends only on the polar angle ψ
of r − c = ρ ê(ψ). In polar coordinates centred at c (dS = ρ dρ dψ) the friction force and
the moment about G are

    F = −sign(ω) ∫ 𝔽 t̂(ψ) K₁(ψ) dψ,
    M = −sign(ω) ∫ [ (m_r − r_G) × 𝔽t̂ · K₁ + ê × 𝔽t̂ · K₂ ] dψ,        t̂ = ẑ×ê,

where m_r is the midpoint of the chord that the ray cuts from the ellipse, x the position on
the chord measured from m_r, m the distance from c to m_r, and

    K₁ = ∫ p (m + x) dx,      K₂ = ∫ p (m + x) x dx

over the part of the chord with ρ = m + x ≥ 0. Along the chord 1 − q = A (h² − x²), so the
radial integrals are closed-form for all four laws: polynomials (uniform, linear) and, with
x = h sin θ, elementary trigonometric moments (Boussinesq, Hertz). Writing the moment about
the chord midpoint keeps every term O(patch size), so nothing cancels when the ICR is far.

The remaining ψ-integral is smooth. With the ICR inside (or on) the rim it runs over the full
circle, split at the two directions where the ray is tangent to the level set of q through
c (there the chord length changes fastest when c is near the rim). With the ICR outside it
runs over the sector α₋ < α < α₊ of rays that hit the patch, measured from the direction to
the centre, with the substitution α = ᾱ + Δ sin s that removes the square-root ends. Both are
integrated by adaptive Gauss–Kronrod (7/15) with a global absolute error target, so the
node count adapts to the state (ICR near the rim needs more) instead of being fixed.

Units: lengths in units of the semi-axis a (a = 1), load P = 1. The caller rescales.
"""

from __future__ import annotations

import math

import numpy as np

from ._jit import jit

# Gauss–Kronrod 7/15 (QUADPACK qk15): Kronrod abscissae (descending), weights, Gauss weights.
_XGK = np.array(
    [
        0.991455371120812639206854697526329,
        0.949107912342758524526189684047851,
        0.864864423359769072789712788640926,
        0.741531185599394439863864773280788,
        0.586087235467691130294144845693013,
        0.405845151377397166906606412076961,
        0.207784955007898467600689403773245,
        0.0,
    ]
)
_WGK = np.array(
    [
        0.022935322010529224963732008058970,
        0.063092092629978553290700663189204,
        0.104790010322250183839876322541518,
        0.140653259715525918745189590510238,
        0.169004726639267902826583426598550,
        0.190350578064785409913256402421014,
        0.204432940075298892414161999234649,
        0.209482141084727828012999174891714,
    ]
)
_WG = np.array(
    [
        0.129484966168869693270611432679082,
        0.279705391489276667901467771423780,
        0.381830050505118944950369775488975,
        0.417959183673469387755102040816327,
    ]
)

LAW_UNIFORM, LAW_LINEAR, LAW_BOUSSINESQ, LAW_HERTZ = 0, 1, 2, 3
MAX_INTERVALS = 2000
FAR_ICR = 1e15  # beyond this distance (in units of a) the ICR is at infinity: pure translation
STATUS_OK, STATUS_NOT_CONVERGED = 0, 1

# parameter vector layout of the angular integrand
_P_BN, _P_LAW, _P_XG, _P_YG = 0, 1, 2, 3
_P_T00, _P_T01, _P_T10, _P_T11 = 4, 5, 6, 7
_P_CX, _P_CY, _P_OMC0, _P_D = 8, 9, 10, 11
_P_ECX, _P_ECY, _P_AMID, _P_AHALF = 12, 13, 14, 15
_NPAR = 16


@jit
def _ray(p, ex, ey, cde, exc, inside):
    """Contribution (force x, force y, moment) of the ray from the ICR in direction ê.

    ``cde`` = c·ê and ``exc`` = ê×c are passed in, computed without cancellation by the caller.
    Returns ``(F_x, F_y, M)`` integrands before the factor −sign(ω).
    """
    bn = p[_P_BN]
    s22 = 1.0 / (bn * bn)
    A = ex * ex + ey * ey * s22
    sep = ex * ey * (s22 - 1.0)  # ê·S·ê⊥ with ê⊥ = ẑ×ê = (−ey, ex)
    disc = A - s22 * exc * exc  # = (c·Sê)² − A (cSc − 1), cancellation-free form
    if disc <= 0.0:
        return 0.0, 0.0, 0.0
    h = math.sqrt(disc) / A
    if h == 0.0:
        return 0.0, 0.0, 0.0
    # chord midpoint m_r = (ê×c) (ê⊥ − ê sep/A) and its distance m from the ICR along ê
    f = exc * sep / A
    mx = -exc * ey - ex * f
    my = exc * ex - ey * f
    m = -cde - f
    if inside:
        x0 = -m
        c0 = math.sqrt(max(p[_P_OMC0], 0.0) / A) / h  # cos θ₀ = √(h² − m²)/h
        s0 = min(1.0, max(-1.0, -m / h))  # sin θ₀
        if c0 > 1.0:
            c0 = 1.0
    else:
        x0 = -h
        c0 = 0.0
        s0 = -1.0
    law = int(p[_P_LAW])
    inv_area = 1.0 / (math.pi * bn)
    if law == LAW_UNIFORM or law == LAW_LINEAR:
        u0 = h - x0
        u1 = 0.5 * (h * h - x0 * x0)
        u2 = (h * h * h - x0 * x0 * x0) / 3.0
        k1 = m * u0 + u1
        k2 = m * u1 + u2
        if law == LAW_LINEAR:
            lx = 4.0 * p[_P_XG]
            ly = 4.0 * p[_P_YG] * s22
            l0 = 1.0 + lx * mx + ly * my
            l1 = lx * ex + ly * ey
            u3 = 0.25 * (h * h * h * h - x0 * x0 * x0 * x0)
            k1 = l0 * k1 + l1 * (m * u1 + u2)
            k2 = l0 * k2 + l1 * (m * u2 + u3)
        k1 *= inv_area
        k2 *= inv_area
    else:
        theta = math.atan2(c0, s0)  # Θ = π/2 − θ₀ ∈ [0, π]
        sc = s0 * c0
        if law == LAW_BOUSSINESQ:
            w0 = theta
            w1 = h * c0
            w2 = h * h * 0.5 * (theta + sc)
            scale = 0.5 * inv_area / math.sqrt(A)
        else:  # Hertz
            h2 = h * h
            w0 = h2 * 0.5 * (theta - sc)
            w1 = h2 * h * c0 * c0 * c0 / 3.0
            w2 = h2 * h2 * 0.125 * (theta + sc * (c0 * c0 - s0 * s0))
            scale = 1.5 * inv_area * math.sqrt(A)
        k1 = scale * (m * w0 + w1)
        k2 = scale * (m * w1 + w2)
    # g = 𝔽 t̂ with t̂ = ẑ×ê = (−ey, ex)
    gx = -p[_P_T00] * ey + p[_P_T01] * ex
    gy = -p[_P_T10] * ey + p[_P_T11] * ex
    mom = k1 * ((mx - p[_P_XG]) * gy - (my - p[_P_YG]) * gx) + k2 * (ex * gy - ey * gx)
    return k1 * gx, k1 * gy, mom


@jit
def _integrand(p, t, inside):
    """Angular integrand: ψ for an ICR inside, s (α = ᾱ + Δ sin s) for an ICR outside."""
    if inside:
        ex = math.cos(t)
        ey = math.sin(t)
        cx = p[_P_CX]
        cy = p[_P_CY]
        return _ray(p, ex, ey, cx * ex + cy * ey, ex * cy - ey * cx, True)
    half = p[_P_AHALF]
    jac = half * math.cos(t)
    if jac <= 0.0:
        return 0.0, 0.0, 0.0
    alpha = p[_P_AMID] + half * math.sin(t)
    ca = math.cos(alpha)
    sa = math.sin(alpha)
    ecx = p[_P_ECX]
    ecy = p[_P_ECY]
    ex = ca * ecx - sa * ecy  # ê = cos α ê_c + sin α n̂, n̂ = ẑ×ê_c
    ey = ca * ecy + sa * ecx
    d = p[_P_D]
    fx, fy, mm = _ray(p, ex, ey, -d * ca, d * sa, False)
    return fx * jac, fy * jac, mm * jac


@jit
def _gk15(p, lo, hi, inside):
    """Gauss–Kronrod 7/15 on [lo, hi] for the 3-vector integrand; returns (result, error)."""
    c = 0.5 * (lo + hi)
    r = 0.5 * (hi - lo)
    fx, fy, fm = _integrand(p, c, inside)
    kx = _WGK[7] * fx
    ky = _WGK[7] * fy
    km = _WGK[7] * fm
    gx = _WG[3] * fx
    gy = _WG[3] * fy
    gm = _WG[3] * fm
    for j in range(7):
        dx = r * _XGK[j]
        ax, ay, am = _integrand(p, c - dx, inside)
        bx, by, bm = _integrand(p, c + dx, inside)
        w = _WGK[j]
        kx += w * (ax + bx)
        ky += w * (ay + by)
        km += w * (am + bm)
        if j % 2 == 1:
            wg = _WG[j // 2]
            gx += wg * (ax + bx)
            gy += wg * (ay + by)
            gm += wg * (am + bm)
    res = np.empty(3)
    res[0] = kx * r
    res[1] = ky * r
    res[2] = km * r
    err = max(abs(kx - gx), abs(ky - gy), abs(km - gm)) * abs(r)
    return res, err


@jit
def _adaptive(p, edges, inside, tol):
    """Globally adaptive Gauss–Kronrod over consecutive intervals ``edges``.

    Returns (integral[3], estimated error, number of intervals, status).
    """
    lo = np.empty(MAX_INTERVALS)
    hi = np.empty(MAX_INTERVALS)
    val = np.empty((MAX_INTERVALS, 3))
    err = np.empty(MAX_INTERVALS)
    n = 0
    for i in range(edges.size - 1):
        lo[n] = edges[i]
        hi[n] = edges[i + 1]
        r, e = _gk15(p, lo[n], hi[n], inside)
        val[n, :] = r
        err[n] = e
        n += 1
    status = STATUS_OK
    while True:
        total = 0.0
        worst = 0
        for i in range(n):
            total += err[i]
            if err[i] > err[worst]:
                worst = i
        if total <= tol:
            break
        if n + 1 >= MAX_INTERVALS or hi[worst] - lo[worst] < 1e-14 * (1.0 + abs(lo[worst])):
            status = STATUS_NOT_CONVERGED
            break
        a0 = lo[worst]
        b0 = hi[worst]
        mid = 0.5 * (a0 + b0)
        r1, e1 = _gk15(p, a0, mid, inside)
        r2, e2 = _gk15(p, mid, b0, inside)
        hi[worst] = mid
        val[worst, :] = r1
        err[worst] = e1
        lo[n] = mid
        hi[n] = b0
        val[n, :] = r2
        err[n] = e2
        n += 1
    out = np.zeros(3)
    total = 0.0
    for i in range(n):
        out += val[i, :]
        total += err[i]
    return out, total, n, status


@jit
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
    if omega == 0.0 or not (abs(vx) + abs(vy)) / abs(omega) < FAR_ICR:
        speed = math.hypot(vx, vy)
        if speed == 0.0:
            return 0.0, 0.0, 0.0, STATUS_OK
        ux = vx / speed
        uy = vy / speed
        # pure translation: F = −𝔽 v̂, M = 0 since G lies over the pressure centroid
        return -(t00 * ux + t01 * uy), -(t10 * ux + t11 * uy), 0.0, STATUS_OK
    cx = xg - vy / omega
    cy = yg + vx / omega
    sgn = 1.0 if omega > 0.0 else -1.0
    s22 = 1.0 / (bn * bn)
    c0 = cx * cx + cy * cy * s22
    p = np.empty(_NPAR)
    p[_P_BN] = bn
    p[_P_LAW] = law
    p[_P_XG] = xg
    p[_P_YG] = yg
    p[_P_T00] = t00
    p[_P_T01] = t01
    p[_P_T10] = t10
    p[_P_T11] = t11
    p[_P_CX] = cx
    p[_P_CY] = cy
    p[_P_OMC0] = 1.0 - c0
    if c0 <= 1.0:
        inside = True
        # split where ê ⊥ S c: the ray is tangent to the level set of q through c
        psi_t = math.atan2(cy * s22, cx) + 0.5 * math.pi
        edges = np.empty(5)
        for i in range(5):
            edges[i] = psi_t + 0.5 * math.pi * i
    else:
        inside = False
        d = math.hypot(cx, cy)
        ecx = -cx / d
        ecy = -cy / d
        nx = -ecy
        ny = ecx
        suu = ecx * ecx + ecy * ecy * s22
        suv = ecx * nx + ecy * ny * s22
        r = math.sqrt(s22 * (c0 - 1.0))
        a_plus = math.atan2(suu, r - suv)
        a_minus = math.atan2(-suu, suv + r)
        p[_P_D] = d
        p[_P_ECX] = ecx
        p[_P_ECY] = ecy
        p[_P_AMID] = 0.5 * (a_plus + a_minus)
        p[_P_AHALF] = 0.5 * (a_plus - a_minus)
        edges = np.empty(3)
        edges[0] = -0.5 * math.pi
        edges[1] = 0.0
        edges[2] = 0.5 * math.pi
    res, err, nint, status = _adaptive(p, edges, inside, tol)
    return -sgn * res[0], -sgn * res[1], -sgn * res[2], status


@jit
def wrench_world(bn, law, xg, yg, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol):
    """Friction wrench in the fixed frame (unit load, a = 1).

    The tensor (t00..t11) is given in its own frame: the plane's (``body_frame`` false,
    the paper's choice) or the body's. Velocities are those of G in the fixed frame.
    Returns (Fx, Fy, M, status) with M about G, counter-clockwise positive.
    """
    c = math.cos(phi)
    s = math.sin(phi)
    vbx = c * vx + s * vy
    vby = -s * vx + c * vy
    if body_frame:
        b00, b01, b10, b11 = t00, t01, t10, t11
    else:
        # 𝔽_body = Rᵀ 𝔽 R
        a00 = c * t00 + s * t10
        a01 = c * t01 + s * t11
        a10 = -s * t00 + c * t10
        a11 = -s * t01 + c * t11
        b00 = a00 * c + a01 * s
        b01 = -a00 * s + a01 * c
        b10 = a10 * c + a11 * s
        b11 = -a10 * s + a11 * c
    fbx, fby, m, status = wrench_body(bn, law, xg, yg, b00, b01, b10, b11, vbx, vby, omega, tol)
    return c * fbx - s * fby, s * fbx + c * fby, m, status


@jit
def wrench_array(bn, law, xg, yg, t00, t01, t10, t11, body_frame, phi, vx, vy, omega, tol):
    """:func:`wrench_world` over 1-D arrays ``phi, vx, vy, omega`` of equal length.

    Returns (Fx, Fy, M, status) arrays.
    """
    n = vx.size
    fx = np.empty(n)
    fy = np.empty(n)
    mm = np.empty(n)
    st = np.empty(n, dtype=np.int64)
    for i in range(n):
        fx[i], fy[i], mm[i], st[i] = wrench_world(
            bn, law, xg, yg, t00, t01, t10, t11, body_frame, phi[i], vx[i], vy[i], omega[i], tol
        )
    return fx, fy, mm, st
