"""Slow, independent reference for quasi-static pushing (MODEL §13), written from MODEL.md.

It shares no code with ``slidespin``: the friction wrench of a **uniform** pressure on a disk or
a convex polygon under **isotropic** friction μ is computed by line integrals about the
instantaneous centre of rotation I (every point at angle θ about I slips along
ê_θ = (−sin θ, cos θ) for ω > 0, so the force is −μ p ∫ ê_θ (ρ₂² − ρ₁²)/2 dθ and the moment about
I is −μ p ∫ (ρ₂³ − ρ₁³)/3 dθ over the chord [ρ₁, ρ₂] of the ray from I), with
``scipy.integrate.quad`` and breakpoints at the rays through vertices and tangent rays.
The quasi-static twists are found by placing I (a different parametrisation from slidespin's):
sticking puts I on the line through the contact point c normal to the finger's velocity,
sliding solves for I in the plane (2 equations: no moment about c, force along the cone edge).

All positions are relative to G in the plane frame [m]; the wrench is per unit load P = m g.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq, fsolve


class DiskShape:
    """Uniform disk of radius R centred at ``centre`` (relative to G; G at its centre)."""

    def __init__(self, radius, centre=(0.0, 0.0)):
        self.r = float(radius)
        self.c = np.asarray(centre, float)
        self.area = math.pi * self.r**2

    def rotated(self, phi):
        return self

    def chord(self, icr, e):
        w = icr - self.c
        b = e @ w
        disc = b * b - (w @ w - self.r**2)
        if disc <= 0.0:
            return 0.0, 0.0
        sq = math.sqrt(disc)
        return max(0.0, -b - sq), max(0.0, -b + sq)

    def breaks(self, icr):
        w = self.c - icr
        d = math.hypot(*w)
        if d <= self.r:
            return []
        base, half = math.atan2(w[1], w[0]), math.asin(self.r / d)
        return [base - half, base + half]


class PolygonShape:
    """Uniform convex polygon, CCW vertices relative to G (body frame at φ = 0)."""

    def __init__(self, vertices):
        self.v = np.asarray(vertices, float)
        x, y = self.v[:, 0], self.v[:, 1]
        self.area = 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))

    def rotated(self, phi):
        c, s = math.cos(phi), math.sin(phi)
        out = PolygonShape.__new__(PolygonShape)
        out.v = self.v @ np.array([[c, s], [-s, c]])
        out.area = self.area
        return out

    def chord(self, icr, e):
        lo, hi = 0.0, math.inf
        nv = len(self.v)
        for i in range(nv):
            a, b = self.v[i], self.v[(i + 1) % nv]
            d = b - a
            n = np.array([-d[1], d[0]])  # inward for CCW
            num, den = n @ (icr - a), n @ e
            if abs(den) < 1e-300:
                if num < 0.0:
                    return 0.0, 0.0
                continue
            r = -num / den
            if den > 0.0:
                lo = max(lo, r)
            else:
                hi = min(hi, r)
        return (lo, hi) if hi > lo else (0.0, 0.0)

    def breaks(self, icr):
        return [math.atan2(*(p - icr)[::-1]) for p in self.v]


def wrench(shape, mu, vx, vy, omega):
    """(Fx, Fy, M about G) per unit load for the twist (vx, vy, ω) of G."""
    if omega == 0.0:
        s = math.hypot(vx, vy)
        return np.array([-mu * vx / s, -mu * vy / s, 0.0])
    icr = np.array([-vy, vx]) / omega
    p = 1.0 / shape.area
    brk = sorted({(b - 0.0) % (2 * math.pi) for b in shape.breaks(icr)})

    def parts(k):
        def f(th):
            e = np.array([math.cos(th), math.sin(th)])
            r1, r2 = shape.chord(icr, e)
            if k == 0:
                return -math.sin(th) * (r2 * r2 - r1 * r1) / 2
            if k == 1:
                return math.cos(th) * (r2 * r2 - r1 * r1) / 2
            return (r2**3 - r1**3) / 3

        return quad(f, 0.0, 2 * math.pi, points=brk or None, limit=400, epsabs=1e-13, epsrel=1e-12)[
            0
        ]

    sg = math.copysign(1.0, omega)
    fx, fy, mi = (-sg * mu * p * parts(k) for k in range(3))
    mg = mi + (icr[0] * fy - icr[1] * fx)
    return np.array([fx, fy, mg])


def _moment_about(shape, mu, nu, c):
    fx, fy, m = wrench(shape, mu, *nu)
    return m - (c[0] * fy - c[1] * fx), np.array([fx, fy])


def sticking_twist(shape, mu, c, vc):
    """Twist (vx, vy, ω) at G whose body point c (relative to G) moves with velocity vc, with
    no friction moment about c; and the friction force per unit load."""
    speed = math.hypot(*vc)
    vh = np.asarray(vc, float) / speed
    m = np.array([-vh[1], vh[0]])  # ẑ × v̂: I = c + u m gives c the velocity ω u v̂

    def twist(chi):
        # I = c + u m with u = tan(chi), chi in (0, π): ω u = speed gives ω = speed cot(chi) and
        # the velocity of G = ω ẑ × (G − I) = speed (cot(chi) c + m) turned by −90°; the
        # translation (u = ±∞) is chi = π/2, turning about c the ends chi → 0, π
        k = math.cos(chi) / math.sin(chi)
        a = k * np.asarray(c) + m
        return speed * np.array([a[1], -a[0], k])

    def g(chi):
        return _moment_about(shape, mu, twist(chi), c)[0]

    # the line integrals lose digits when I is far (near translation, chi = π/2): bracket the
    # root on a grid that keeps away from it (a root within 1e-3 of translation is not used)
    grid = np.concatenate(
        (
            np.linspace(1e-7, math.pi / 2 - 1e-3, 12),
            np.linspace(math.pi / 2 + 1e-3, math.pi - 1e-7, 12),
        )
    )
    vals = [g(x) for x in grid]
    k = next(i for i in range(len(grid) - 1) if vals[i] * vals[i + 1] <= 0.0)
    chi = brentq(g, grid[k], grid[k + 1], xtol=1e-15, rtol=1e-15)
    nu = twist(chi)
    return nu, _moment_about(shape, mu, nu, c)[1]


def sliding_twist(shape, mu, c, n, pdot, mu_p, sigma, guess):
    """Twist for a sliding contact on the cone edge n + σ μp t (t = ẑ × n) with the normal
    velocity matched, (J_c ν)·n = ṗ·n; ``guess`` an ICR (relative to G) to start from."""
    n = np.asarray(n, float)
    t = np.array([-n[1], n[0]])
    e = n + sigma * mu_p * t
    e /= np.linalg.norm(e)

    def eqs(icr):
        nu = np.array([icr[1], -icr[0], 1.0])  # ω = 1 about I
        mc, f = _moment_about(shape, mu, nu, c)
        return [mc, -f[0] * e[1] + f[1] * e[0]]

    icr = fsolve(eqs, guess, xtol=1e-14)
    nu = np.array([icr[1], -icr[0], 1.0])
    vc = nu[:2] + nu[2] * np.array([-c[1], c[0]])
    scale = (np.asarray(pdot) @ n) / (vc @ n)
    mc, f = _moment_about(shape, mu, nu, c)
    return nu * scale, f, icr


def push_sticking(shape, mu, finger, finger_velocity, times, start):
    """Poses (x, y, φ) at ``times`` of a body whose contact point sticks to a finger moving
    at constant ``finger_velocity`` from ``finger`` at times[0] (the finger touching)."""
    p0, vel = np.asarray(finger, float), np.asarray(finger_velocity, float)

    def rhs(t, q):
        p = p0 + vel * (t - times[0])
        c = p - q[:2]
        body = shape.rotated(q[2])
        nu, _ = sticking_twist(body, mu, c, vel)
        return nu

    sol = solve_ivp(
        rhs, (times[0], times[-1]), start, method="DOP853", rtol=1e-10, atol=1e-12, t_eval=times
    )
    return sol.y
