"""Compiled exact friction wrench on a blade: a line contact under uniform line pressure.

A blade (:class:`slidespin.contact.shapes.Blade`) is the segment r(s) = m + s ê, |s| ≤ ℓ = L/2,
carrying the load P with line density q = P/L (the b → 0 limit of a uniformly loaded
rectangle L × b). With V the velocity of the blade's centre m and ê⊥ = ẑ × ê, the slip
velocity of the point s is w(s) = v_e ê + u(s) ê⊥, v_e = V·ê, u(s) = v_n + ω s, v_n = V·ê⊥:
only its component across the blade varies. Because 𝔽 is constant (MODEL §2, §10),

    F = −𝔽 I₀,   M_G = (m − r_G) × F − ê × (𝔽 I₁),   I_k = q ∫ s^k ŵ ds = q (A_k ê + B_k ê⊥),

with A_k = v_e ∫ s^k / r ds, B_k = ∫ s^k u / r ds and r = |w| = √(v_e² + u²). With h = |v_e|,
u₀ = u(−ℓ), u₁ = u(ℓ), r_i = √(h² + u_i²) and Δ = asinh(u₁/h) − asinh(u₀/h):

    ∫ 1/r ds = Δ/ω,                         ∫ u/r ds = 4ℓ v_n/(r₀ + r₁),
    ∫ s/r ds = (∫ u/r ds − v_n ∫ 1/r ds)/ω,
    ∫ s u/r ds = ((u₁r₁ − u₀r₀ − h² Δ)/2 − v_n ω ∫ u/r ds)/ω²,

Δ taken as a logarithm of a ratio when u₀, u₁ have one sign (no cancellation) and as a sum
of two logarithms otherwise; h = 0 (the ICR on the blade's line) gives ŵ = sign(u) ê⊥ and
the integrals of a step. These are exact; they divide by ω and ω², so they are used while
the ICR lies within ``NEAR`` = 2 half-lengths of the centre (|V| ≤ 2ℓ|ω|), where the
cancellation costs at most a factor ~10 of round-off. Beyond, ŵ(s) is analytic on a Bernstein
ellipse of parameter ≥ 2 + √3 around the segment (its singularities are the ICR's mirror
points s* ± i d, d the ICR's distance from the blade's line) and ``NODES`` = 20 Gauss–Legendre
points give it to (2 + √3)^(−40) ≈ 1e-23; ω = 0 is exact there (ŵ is constant).

Checked in ``tests/contact/test_footprint_laws.py`` against ``scipy.integrate.quad`` with a break at
the ICR's projection, closed forms (pure translation −P𝔽v̂; pure spin
M = −sign(ω) P (L/4) ê⊥ᵀ𝔽ê⊥, i.e. μ P L/4 for isotropic friction) and the limit of a thin
rectangle (O(b²)).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._kernel_ellipse import tensor_in_body

#: the closed form is used while the ICR lies within NEAR half-lengths of the blade's centre
NEAR = 2.0
#: Gauss–Legendre nodes beyond (error ≲ (NEAR + √(NEAR² − 1))^(−2 NODES))
NODES = 20
_X, _W = np.polynomial.legendre.leggauss(NODES)


@jit(error_model="numpy", inline="always")
def _asinh_diff(u0, u1, h, r0, r1):
    """asinh(u₁/h) − asinh(u₀/h) for h > 0, without cancellation or overflow."""
    if u0 >= 0.0 and u1 >= 0.0:
        return math.log((u1 + r1) / (u0 + r0))
    if u0 <= 0.0 and u1 <= 0.0:
        return -math.log((r1 - u1) / (r0 - u0))
    lh = math.log(h)
    a1 = math.log(abs(u1) + r1) - lh
    a0 = math.log(abs(u0) + r0) - lh
    return math.copysign(a1, u1) - math.copysign(a0, u0)


@jit(error_model="numpy")
def blade_integrals(half, ve, vn, omega):
    """(A₀, B₀, A₁, B₁): ∫ s^k ŵ ds over |s| ≤ ``half`` in the basis (ê, ê⊥), for the slip
    w(s) = (ve, vn + ω s) (module notes). Zero at rest."""
    speed = math.sqrt(ve * ve + vn * vn)
    if speed == 0.0 and omega == 0.0:
        return 0.0, 0.0, 0.0, 0.0
    if speed > NEAR * half * abs(omega):  # the ICR beyond NEAR half-lengths: Gauss–Legendre
        a0 = 0.0
        b0 = 0.0
        a1 = 0.0
        b1 = 0.0
        for k in range(NODES):
            s = half * _X[k]
            u = vn + omega * s
            w = half * _W[k] / math.sqrt(ve * ve + u * u)
            a0 += w * ve
            b0 += w * u
            a1 += w * s * ve
            b1 += w * s * u
        return a0, b0, a1, b1
    u0 = vn - omega * half
    u1 = vn + omega * half
    h = abs(ve)
    if h == 0.0:  # the ICR on the blade's line: ŵ = sign(u) ê⊥, u = ω (s − s*)
        sig = min(max(-vn / omega, -half), half)
        sg = 1.0 if omega > 0.0 else -1.0
        return 0.0, -2.0 * sig * sg, 0.0, (half * half - sig * sig) * sg
    r0 = math.sqrt(h * h + u0 * u0)
    r1 = math.sqrt(h * h + u1 * u1)
    s0 = _asinh_diff(u0, u1, h, r0, r1) / omega  # ∫ 1/r ds
    t0 = 4.0 * half * vn / (r0 + r1)  # ∫ u/r ds
    s1 = (t0 - vn * s0) / omega  # ∫ s/r ds
    t1 = (0.5 * (u1 * r1 - u0 * r0 - h * h * s0 * omega) - vn * omega * t0) / (omega * omega)
    return ve * s0, t0, ve * s1, t1


@jit(error_model="numpy")
def blade_wrench_body(x0, y0, x1, y1, xg, yg, load, t00, t01, t10, t11, vx, vy, omega):
    """Friction force (body frame) and moment about G on the blade from (x0, y0) to (x1, y1)
    under the uniform line load ``load`` (any length unit, consistent).

    Parameters
    ----------
    x0, y0, x1, y1 : float
        The blade's ends in the body frame.
    xg, yg : float
        The mass centre G in the body frame (the blade's centre for a body on one blade).
    load : float
        The normal load P on the blade.
    t00, t01, t10, t11 : float
        Friction tensor 𝔽 in the body frame.
    vx, vy, omega : float
        Velocity of G in the body frame and spin rate (only the direction matters).

    Returns
    -------
    fx, fy, m : float
        Force in the body frame (units of the load) and moment about G (load × length).
    """
    mx = 0.5 * (x0 + x1)
    my = 0.5 * (y0 + y1)
    dx = x1 - x0
    dy = y1 - y0
    length = math.sqrt(dx * dx + dy * dy)
    ex = dx / length
    ey = dy / length
    half = 0.5 * length
    # velocity of the blade's centre: v + ω ẑ × (m − G)
    cvx = vx - omega * (my - yg)
    cvy = vy + omega * (mx - xg)
    ve = cvx * ex + cvy * ey
    vn = -cvx * ey + cvy * ex
    a0, b0, a1, b1 = blade_integrals(half, ve, vn, omega)
    q = load / length
    # I_k = q (A_k ê + B_k ê⊥), ê⊥ = (−e_y, e_x)
    i0x = q * (a0 * ex - b0 * ey)
    i0y = q * (a0 * ey + b0 * ex)
    i1x = q * (a1 * ex - b1 * ey)
    i1y = q * (a1 * ey + b1 * ex)
    fx = -(t00 * i0x + t01 * i0y)
    fy = -(t10 * i0x + t11 * i0y)
    gx = t00 * i1x + t01 * i1y
    gy = t10 * i1x + t11 * i1y
    m = (mx - xg) * fy - (my - yg) * fx - (ex * gy - ey * gx)
    return fx, fy, m


@jit(error_model="numpy")
def blade_wrench_array(
    x0, y0, x1, y1, xg, yg, load, t00, t01, t10, t11, body_frame, phi, vx, vy, omega
):
    """(Fx, Fy, M about G) in the fixed frame over 1-D arrays ``phi, vx, vy, omega`` (velocity
    of G in the fixed frame); the tensor in the plane's frame or, ``body_frame``, the body's."""
    n = vx.size
    fx = np.empty(n)
    fy = np.empty(n)
    mm = np.empty(n)
    for i in range(n):
        c = math.cos(phi[i])
        s = math.sin(phi[i])
        b00, b01, b10, b11 = tensor_in_body(t00, t01, t10, t11, body_frame, c, s)
        vbx = c * vx[i] + s * vy[i]
        vby = -s * vx[i] + c * vy[i]
        fbx, fby, m = blade_wrench_body(
            x0, y0, x1, y1, xg, yg, load, b00, b01, b10, b11, vbx, vby, omega[i]
        )
        fx[i] = c * fbx - s * fby
        fy[i] = s * fbx + c * fby
        mm[i] = m
    return fx, fy, mm
