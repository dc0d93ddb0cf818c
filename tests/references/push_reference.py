"""Slow, independent closed forms for pushing a uniform disk (MODEL §13), written from MODEL.md.

Shares no code with ``slidespin``. A uniform disk of radius R under isotropic friction μ,
turning at ω > 0 about an instantaneous centre of rotation (ICR) at (d, 0) from its centre:
a point at (r cos θ, r sin θ) slips along ẑ × (p − I)/|p − I|, |p − I| = ρ,
ρ² = r² + d² − 2 r d cos θ. The angular integrals are complete elliptic integrals
(the Contensou form of the disk's limit surface):

    ∫₀^{2π} dθ/ρ = 4 K(m)/(r + d),   ∫₀^{2π} ρ dθ = 4 (r + d) E(m),   m = 4 r d/(r + d)²,

and ∫ cos θ/ρ dθ = (A ∫ 1/ρ − ∫ ρ)/B with A = r² + d², B = 2 r d. Per unit load P = 1:

    Fy(d) = −μ p ∫₀^R r (r I₁ − d I₀) dr,   M(d) = −μ p ∫₀^R r (r² I₀ − r d I₁) dr,

Fx = 0, p = 1/(π R²), M about the centre (= G), by one ``scipy.integrate.quad`` over r with a
break at r = d (where K has its logarithmic singularity). Any other ICR follows by rotation,
ω < 0 by W(−ν) = −W(ν).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.special import ellipe, ellipkm1

_THETA = np.linspace(0.0, 2.0 * math.pi, 64, endpoint=False)
_COS = np.cos(_THETA)


def _angular(r, d):
    """(I₀, I₁) = (∫ dθ/ρ, ∫ cos θ dθ/ρ) over a full turn: complete elliptic integrals for
    m ≥ 1/2, else the periodic trapezoid rule (64 nodes; exponentially convergent there, and
    free of the cancellation of the elliptic form of I₁ at small m)."""
    if d == 0.0:
        return 2.0 * math.pi / r, 0.0
    if r == 0.0:
        return 2.0 * math.pi / d, 0.0
    s = r + d
    m1 = ((r - d) / s) ** 2  # 1 − m, exact
    if m1 > 0.5:
        rho = np.sqrt(r * r + d * d - 2.0 * r * d * _COS)
        w = 2.0 * math.pi / _COS.size
        return float(np.sum(1.0 / rho) * w), float(np.sum(_COS / rho) * w)
    k = ellipkm1(m1)
    e = ellipe(1.0 - m1)
    i0 = 4.0 * k / s
    ip = 4.0 * s * e
    a, b = r * r + d * d, 2.0 * r * d
    return i0, (a * i0 - ip) / b


def disk_wrench_axis(radius, mu, d):
    """(Fy, M) per unit load for ω > 0 about the ICR (d, 0), d ≥ 0 (Fx = 0)."""
    dn = d / radius  # in units of the radius: r = radius·x, integrands of order 1
    pts = [dn] if 0.0 < dn < 1.0 else None

    def fy(x):
        i0, i1 = _angular(x, dn)
        return x * (x * i1 - dn * i0)

    def mm(x):
        i0, i1 = _angular(x, dn)
        return x * (x * x * i0 - x * dn * i1)

    kw = {"points": pts, "limit": 400, "epsabs": 1e-14, "epsrel": 1e-12}
    f = quad(fy, 0.0, 1.0, **kw)[0]
    m = quad(mm, 0.0, 1.0, **kw)[0]
    # p = 1/(π R²); dS = R² x dx dθ, the lever arms carry R
    return -mu * f / math.pi, -mu * m * radius / math.pi


def disk_wrench(radius, mu, vx, vy, omega):
    """(Fx, Fy, M about the centre) per unit load of a uniform disk moving with the twist
    (vx, vy, ω) at its centre."""
    if omega == 0.0:
        s = math.hypot(vx, vy)
        return np.array([-mu * vx / s, -mu * vy / s, 0.0])
    sign = 1.0 if omega > 0.0 else -1.0
    # ICR: v = ω ẑ × (0 − I)  ⇒  I = (−vy, vx)/ω
    ix, iy = -vy / omega, vx / omega
    d = math.hypot(ix, iy)
    a = math.atan2(iy, ix)
    f, m = disk_wrench_axis(radius, mu, d)
    # (0, f) in the frame turned by a
    return sign * np.array([-math.sin(a) * f, math.cos(a) * f, m])


def disk_edge_twist(radius, mu, force, moment):
    """The unit twist (vx, vy, ω R) of a uniform isotropic disk whose friction wrench opposes
    the pusher wrench (force, moment about the centre): the ICR lies on the line through the
    centre normal to the force, at the distance d where −M(d)/Fy(d) equals the moment arm."""
    f = np.asarray(force, float)
    fn = math.hypot(*f)
    fh = f / fn
    h = moment / fn
    if h == 0.0:
        return np.array([fh[0], fh[1], 0.0])
    eperp = np.array([-fh[1], fh[0]])

    def g(logd):
        fy, m = disk_wrench_axis(radius, mu, radius * math.exp(logd))
        return -m / fy - abs(h)

    logd = brentq(g, -6.0, 10.0, xtol=1e-15, rtol=8.9e-16, maxiter=300)
    d = radius * math.exp(logd)
    sign = 1.0 if h > 0.0 else -1.0
    icr = sign * d * eperp
    om = sign
    v = om * np.array([icr[1], -icr[0]])
    out = np.array([v[0], v[1], om * radius])
    return out / np.linalg.norm(out)


def disk_sticking_twist(radius, mu, contact, velocity):
    """The quasi-static twist (vx, vy, ω) of a uniform isotropic disk whose point ``contact``
    (relative to the centre) moves with ``velocity`` (sticking finger): the ICR lies on the
    line through c normal to the velocity, where the friction moment about c vanishes."""
    c = np.asarray(contact, float)
    vel = np.asarray(velocity, float)
    speed = math.hypot(*vel)
    vh = vel / speed

    def twist(chi):
        # ICR at c + radius·cot(chi)·perp, contact speed = speed
        cs, sn = math.cos(chi), math.sin(chi)
        # rotation about c at rate ω moves c by 0; translation along vh: mix
        om = sn / radius
        vg = cs * vh + om * np.array([c[1], -c[0]])  # v_G = v_c + ω ẑ × (G − c)
        return np.array([vg[0], vg[1], om])

    def mc(chi):
        nu = twist(chi)
        fx, fy, m = disk_wrench(radius, mu, *nu)
        return m - (c[0] * fy - c[1] * fx)

    chi = brentq(mc, -0.5 * math.pi + 1e-9, 0.5 * math.pi - 1e-9, xtol=1e-15, rtol=8.9e-16)
    nu = twist(chi)
    return nu * speed / math.cos(chi)
