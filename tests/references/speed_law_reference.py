"""Slow, independent reference for the friction wrench under a speed law g(|w|) (test oracle).

Written from MODEL §2, §3, §10 and §14 only; imports numpy and scipy, nothing of slidespin.
Geometry (ray–polygon, ray–circle, ray–ellipse chords), area moments, pressure laws, the
speed laws (PCHIP via ``scipy.interpolate.PchipInterpolator`` held flat outside its knots)
and every integral are computed here.

Model
-----
A point r of the body frame, offset d = r − r_G from the mass centre G, slips with the
body-frame velocity w = v_b + ω ẑ×d (v_b = R(φ)ᵀ v). Its traction (body frame) is
τ = −p(r) g(|w|) 𝔽_b ŵ with 𝔽_b = R(φ)ᵀ 𝔽_world R(φ); F = R(φ) ∫τ dS, M = ∫ d×τ dS.

Method
------
* ω ≠ 0: **polar coordinates about the ICR** c = r_G + ẑ×v_b/ω (in the body frame), where
  w = ω ρ ê_ψ: on the ray r = c + ρ ê the slip speed is |ω|ρ and the slip direction is
  the constant sign(ω) ê_ψ, so
  F_b = −sign ω 𝔽_b ∫ ê_ψ I₀(ψ) dψ,  M = −sign ω [ (c − r_G) × 𝔽_b ∫ ê_ψ I₀ dψ
  + ∫ ê × 𝔽_b ê_ψ I₁(ψ) dψ ],  Iₖ(ψ) = ∫_{ray ∩ Ω} p g(|ω|ρ) ρ^{k+1} dρ.
  The ray's intervals come from exact ray–edge crossings (parity), ray–circle and
  ray–ellipse roots. For uniform and linear pressure (p = α + βρ on the ray) the radial
  integrals are **closed forms**: ∫ρⁿ g(|ω|ρ) dρ is a power for the power law, an
  incomplete gamma function for Stribeck, and exact polynomial integrals of the PCHIP
  pieces (split at the knot radii u_k/|ω|) for a table. For Boussinesq and Hertz pressure
  (p ∝ (1 − q)^{∓½}, 1 − q = A(ρ − ρ₁)(ρ₂ − ρ) on the ray) the radial integral is
  ``scipy.integrate.quad`` with ``weight='alg'`` carrying the rim factors (ρ − ρ₁)^{∓½},
  (ρ₂ − ρ)^{∓½} and, at the ICR, the power law's ρ^{n−q}; pieces split at table knots.
  The angular integral is ``scipy.integrate.quad_vec`` (adaptive Gauss–Kronrod) over the
  intervals between the directions of every vertex and every circle/ellipse tangent, each
  mapped by ψ = ψa + (ψb − ψa)(1 − cos πs)/2 so that the √ behaviour of a chord near a
  tangent becomes smooth.
* ω = 0: w = v everywhere, so F = −P g(|v|) 𝔽_world v̂ and M = 0 (G is the pressure centroid).

Accuracy (measured): against the closed forms (disk in translation; disk, ring and
Hertz/Boussinesq disk in pure spin under a power law) the error is ≤ 3e-16 P and P·size;
tightening the angular target from 1e-13 to 1e-15 (radial from 1e-14 to 1e-16) moves the
ellipse grid of the tests (all four pressures, six laws, both aspects) by ≤ 2e-14 of P and
P·size. The reference is good to ~1e-13 relative, far below the 1e-9 the tests ask.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad_vec
from scipy.interpolate import PchipInterpolator
from scipy.special import gamma, gammainc, gammaincc, roots_jacobi

__all__ = ["SpeedLaw", "footprint_moments", "reference_wrench", "speed_factor"]

TWO_PI = 2.0 * math.pi


# ----------------------------------------------------------------------------- speed laws
class SpeedLaw:
    """g(u) and the exact radial integrals ∫_a^b ρⁿ g(|ω|ρ) dρ for the three laws.

    spec: None (g = 1), ("power", q, v0), ("stribeck", ratio, vs, delta),
    ("table", speeds, factors).
    """

    def __init__(self, spec):
        self.spec = spec
        self.kind = "none" if spec is None else spec[0]
        if self.kind == "table":
            x = np.asarray(spec[1], float)
            y = np.asarray(spec[2], float)
            self.x, self.y = x, y
            self.pp = PchipInterpolator(x, y, extrapolate=False)

    def g(self, u):
        u = np.asarray(u, float)
        if self.kind == "none":
            return np.ones_like(u)
        if self.kind == "power":
            _, q, v0 = self.spec
            return (u / v0) ** (-q)
        if self.kind == "stribeck":
            _, s, vs, dl = self.spec
            return 1.0 + (s - 1.0) * np.exp(-((u / vs) ** dl))
        out = self.pp(np.clip(u, self.x[0], self.x[-1]))
        return np.where(u <= self.x[0], self.y[0], np.where(u >= self.x[-1], self.y[-1], out))

    def scalar(self, u, mid=None):
        """g(u) for one float u (fast path of :meth:`g`); for a table, ``mid`` (a speed in
        the same knot interval as u) picks the cubic piece, so that u may sit on a knot."""
        if self.kind == "none":
            return 1.0
        if self.kind == "power":
            return (u / self.spec[2]) ** (-self.spec[1])
        if self.kind == "stribeck":
            _, s, vs, dl = self.spec
            return 1.0 + (s - 1.0) * math.exp(-((u / vs) ** dl))
        m = u if mid is None else mid
        if m <= self.x[0]:
            return float(self.y[0])
        if m >= self.x[-1]:
            return float(self.y[-1])
        i = min(int(np.searchsorted(self.x, m, side="right")) - 1, len(self.x) - 2)
        c = self.pp.c[:, i]
        t = u - self.x[i]
        return float(((c[0] * t + c[1]) * t + c[2]) * t + c[3])

    def knots(self, w):
        """Radii where g(|ω|ρ) is not analytic (table knots), for |ω| = w."""
        if self.kind == "table":
            return list(self.x / w)
        return []

    def moment(self, n, a, b, w):
        """∫_a^b ρⁿ g(wρ) dρ exactly (0 ≤ a ≤ b, n a non-negative integer, w = |ω| > 0)."""
        if b <= a:
            return 0.0
        if self.kind == "none":
            return _pow_diff(n + 1, a, b) / (n + 1)
        if self.kind == "power":
            _, q, v0 = self.spec
            s = n + 1 - q
            return (w / v0) ** (-q) * _pow_diff(s, a, b) / s
        if self.kind == "stribeck":
            _, ratio, vs, dl = self.spec
            rs = vs / w
            s = (n + 1) / dl
            xa, xb = (a / rs) ** dl, (b / rs) ** dl
            if xa > s:  # both in the upper tail: difference of Q avoids cancellation
                diff = gammaincc(s, xa) - gammaincc(s, xb)
            else:
                diff = gammainc(s, xb) - gammainc(s, xa)
            return (
                _pow_diff(n + 1, a, b) / (n + 1)
                + (ratio - 1.0) * rs ** (n + 1) / dl * gamma(s) * diff
            )
        # table: flat below/above, PCHIP cubic pieces between knot radii
        r = self.x / w
        total = 0.0
        lo = min(b, r[0])
        if lo > a:
            total += self.y[0] * _pow_diff(n + 1, a, lo) / (n + 1)
        hi = max(a, r[-1])
        if b > hi:
            total += self.y[-1] * _pow_diff(n + 1, hi, b) / (n + 1)
        c = self.pp.c  # (4, m): c[k, i] (u − x_i)^(3 − k)
        for i in range(len(r) - 1):
            pa, pb = max(a, r[i]), min(b, r[i + 1])
            if pb <= pa:
                continue
            # ∫ ρⁿ Σ_j c_j (w(ρ − r_i))^j dρ, σ = ρ − r_i ≥ 0: expand (σ + r_i)ⁿ
            sa, sb = pa - r[i], pb - r[i]
            for k in range(4):
                j = 3 - k
                coef = c[k, i] * w**j
                for ell in range(n + 1):
                    e = ell + j + 1
                    total += coef * math.comb(n, ell) * r[i] ** (n - ell) * _pow_diff(e, sa, sb) / e
        return total


def _pow_diff(s, a, b):
    """b^s − a^s without cancellation (0 ≤ a ≤ b)."""
    if a <= 0.0:
        return b**s
    return a**s * math.expm1(s * math.log1p((b - a) / a))


def speed_factor(law_spec, u):
    """g(u) of a law spec (for closed forms in the tests)."""
    return SpeedLaw(law_spec).g(u)


# ----------------------------------------------------------------------------- geometry
def _rot(t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, -s], [s, c]])


def _regions(patch):
    """Flatten a patch spec into [('poly', V) | ('ring', o, r_in, r_out) | ('ellipse', o, a, b)].

    patch specs: ("ellipse", a, b[, centre]), ("polygon", vertices[, centre, angle]),
    ("rectangle", length, width[, centre, angle]), ("disk", R[, centre]),
    ("annulus", r_in, r_out[, centre]), ("pads", [specs]).
    """
    kind = patch[0]
    if kind == "pads":
        out = []
        for p in patch[1]:
            out += _regions(p)
        return out
    if kind == "ellipse":
        centre = patch[3] if len(patch) > 3 else (0.0, 0.0)
        return [("ellipse", np.asarray(centre, float), float(patch[1]), float(patch[2]))]
    if kind in ("disk", "annulus"):
        if kind == "disk":
            r_in, r_out = 0.0, float(patch[1])
            centre = patch[2] if len(patch) > 2 else (0.0, 0.0)
        else:
            r_in, r_out = float(patch[1]), float(patch[2])
            centre = patch[3] if len(patch) > 3 else (0.0, 0.0)
        return [("ring", np.asarray(centre, float), r_in, r_out)]
    if kind == "rectangle":
        length, width = patch[1], patch[2]
        centre = patch[3] if len(patch) > 3 else (0.0, 0.0)
        angle = patch[4] if len(patch) > 4 else 0.0
        v = [(-length / 2, -width / 2), (length / 2, -width / 2)]
        v += [(length / 2, width / 2), (-length / 2, width / 2)]
    elif kind == "polygon":
        v = patch[1]
        centre = patch[2] if len(patch) > 2 else (0.0, 0.0)
        angle = patch[3] if len(patch) > 3 else 0.0
    else:
        raise ValueError(kind)
    v = np.asarray(v, float) @ _rot(angle).T + np.asarray(centre, float)
    return [("poly", v)]


def footprint_moments(patch):
    """(A, ∫r dS, ∫r rᵀ dS) of a patch spec, exactly (Green's theorem / disk formulas)."""
    area, m1, m2 = 0.0, np.zeros(2), np.zeros((2, 2))
    for reg in _regions(patch):
        if reg[0] == "poly":
            v = reg[1]
            x, y = v[:, 0], v[:, 1]
            xn, yn = np.roll(x, -1), np.roll(y, -1)
            cr = x * yn - xn * y
            a = cr.sum() / 2
            sgn = 1.0 if a > 0 else -1.0
            area += abs(a)
            m1 += sgn * np.array([((x + xn) * cr).sum() / 6, ((y + yn) * cr).sum() / 6])
            ixx = ((x * x + x * xn + xn * xn) * cr).sum() / 12
            iyy = ((y * y + y * yn + yn * yn) * cr).sum() / 12
            ixy = ((x * yn + 2 * x * y + 2 * xn * yn + xn * y) * cr).sum() / 24
            m2 += sgn * np.array([[ixx, ixy], [ixy, iyy]])
        else:
            o = reg[1]
            if reg[0] == "ring":
                for r, s in ((reg[3], 1.0), (reg[2], -1.0)):
                    a = math.pi * r * r
                    area += s * a
                    m1 += s * a * o
                    m2 += s * a * (np.eye(2) * r * r / 4 + np.outer(o, o))
            else:
                a = math.pi * reg[2] * reg[3]
                area += a
                m1 += a * o
                m2 += a * (np.diag([reg[2] ** 2, reg[3] ** 2]) / 4 + np.outer(o, o))
    return area, m1, m2


def _line_intervals(regions, c, e):
    """Intervals of t (sorted, disjoint) where c + t e lies in the union of ``regions``;
    for an ellipse also its two roots (ρ₁, ρ₂) and the quadratic's leading coefficient."""
    out = []
    ell = None
    for reg in regions:
        if reg[0] == "poly":
            v = reg[1]
            ts = []
            for i in range(len(v)):
                a, b = v[i], v[(i + 1) % len(v)]
                ed = b - a
                den = e[0] * ed[1] - e[1] * ed[0]
                if den == 0.0:
                    continue
                ac = a - c
                t = (ac[0] * ed[1] - ac[1] * ed[0]) / den
                s = (ac[0] * e[1] - ac[1] * e[0]) / den
                if 0.0 <= s < 1.0:
                    ts.append(t)
            ts.sort()
            out += [(ts[k], ts[k + 1]) for k in range(0, len(ts) - 1, 2)]
        elif reg[0] == "ring":
            o, r_in, r_out = reg[1], reg[2], reg[3]
            oc = o - c
            m = e @ oc
            h2 = r_out**2 - (e[0] * oc[1] - e[1] * oc[0]) ** 2
            if h2 <= 0:
                continue
            t1, t2 = m - math.sqrt(h2), m + math.sqrt(h2)
            k2 = r_in**2 - (e[0] * oc[1] - e[1] * oc[0]) ** 2
            if r_in > 0 and k2 > 0:
                s1, s2 = m - math.sqrt(k2), m + math.sqrt(k2)
                out += [(t1, s1), (s2, t2)]
            else:
                out.append((t1, t2))
        else:
            o, a, b = reg[1], reg[2], reg[3]
            d = c - o
            qa = (e[0] / a) ** 2 + (e[1] / b) ** 2
            qb = 2 * (d[0] * e[0] / a**2 + d[1] * e[1] / b**2)
            qc = (d[0] / a) ** 2 + (d[1] / b) ** 2 - 1.0
            disc = qb * qb - 4 * qa * qc
            if disc <= 0:
                continue
            sq = math.sqrt(disc)
            # stable roots
            qq = -0.5 * (qb + math.copysign(sq, qb))
            r1, r2 = sorted((qq / qa, qc / qq))
            out.append((r1, r2))
            ell = (r1, r2, qa, o, a, b)
    out.sort()
    return out, ell


def _breaks(regions, c):
    """Directions (radians, in [0, 2π)) where a ray from c meets a vertex or a tangent."""
    ang = []
    for reg in regions:
        if reg[0] == "poly":
            d = reg[1] - c
            ang += list(np.arctan2(d[:, 1], d[:, 0]))
        elif reg[0] == "ring":
            d = reg[1] - c
            dist = math.hypot(*d)
            base = math.atan2(d[1], d[0])
            for r in (reg[2], reg[3]):
                if r > 0 and dist > r:
                    h = math.asin(r / dist)
                    ang += [base - h, base + h]
        else:
            o, a, b = reg[1], reg[2], reg[3]
            d = (c - o) / np.array([a, b])
            dist = math.hypot(*d)
            if dist > 1.0:
                base = math.atan2(-d[1], -d[0])
                h = math.asin(1.0 / dist)
                for t in (base - h, base + h):
                    ang.append(math.atan2(b * math.sin(t), a * math.cos(t)))
    ang = sorted({float(x % TWO_PI) for x in ang} | {0.0, math.pi / 2, math.pi, 1.5 * math.pi})
    ang.append(TWO_PI)
    return ang


def _extent(regions, rc):
    """Largest distance from rc to a point of the regions."""
    out = 0.0
    for reg in regions:
        if reg[0] == "poly":
            out = max(out, float(np.hypot(*(reg[1] - rc).T).max()))
        elif reg[0] == "ring":
            out = max(out, math.hypot(*(reg[1] - rc)) + reg[3])
        else:
            out = max(out, math.hypot(*(reg[1] - rc)) + max(reg[2], reg[3]))
    return out


# ----------------------------------------------------------------------------- the wrench
class _Problem:
    def __init__(self, patch, pressure, law, load):
        self.regions = _regions(patch)
        self.law = SpeedLaw(law)
        self.kind = pressure[0]
        self.load = load
        if self.kind in ("boussinesq", "hertz"):
            if len(self.regions) != 1 or self.regions[0][0] == "poly":
                raise ValueError("Boussinesq/Hertz on one ellipse or disk only")
            reg = self.regions[0]
            if reg[0] == "ring":
                if reg[2] > 0:
                    raise ValueError("not on a ring")
                self.regions = [("ellipse", reg[1], reg[3], reg[3])]
            o, a, b = self.regions[0][1:]
            self.gamma = -0.5 if self.kind == "boussinesq" else 0.5
            self.k0 = load / (2 * math.pi * a * b) * (1.0 if self.kind == "boussinesq" else 3.0)
            self.r_g = np.array(o, float)
            self.size = max(a, b)
            return
        area, m1, m2 = footprint_moments(patch)
        rc = m1 / area
        if self.kind == "uniform":
            r_g = rc
            gvec = np.zeros(2)
        elif self.kind == "linear":
            r_g = np.array(pressure[1:3], float)
            jmat = m2 - np.outer(m1, m1) / area
            gvec = np.linalg.solve(jmat, area * (r_g - rc))
        else:
            raise ValueError(self.kind)
        # p = (P/A)(1 + g·(r − r_c)) = p0 + p1 ξ + p2 η
        self.p_lin = (load / area) * np.array([1.0 - gvec @ rc, gvec[0], gvec[1]])
        self.r_g = r_g
        self.size = _extent(self.regions, rc)

    # radial integrals I0 = ∫ p g ρ dρ, I1 = ∫ p g ρ² dρ over the ray's intervals
    def radial(self, c, e, w, epsabs):
        ivals, ell = _line_intervals(self.regions, c, e)
        if self.kind in ("uniform", "linear"):
            p0, p1, p2 = self.p_lin
            alpha = p0 + p1 * c[0] + p2 * c[1]
            beta = p1 * e[0] + p2 * e[1]
            i0 = i1 = 0.0
            for t1, t2 in ivals:
                t1 = max(t1, 0.0)
                if t2 <= t1:
                    continue
                k1 = self.law.moment(1, t1, t2, w)
                k2 = self.law.moment(2, t1, t2, w)
                i0 += alpha * k1 + beta * k2
                if beta != 0.0:
                    i1 += alpha * k2 + beta * self.law.moment(3, t1, t2, w)
                else:
                    i1 += alpha * k2
            return i0, i1
        if ell is None:
            return 0.0, 0.0
        r1, r2, qa, *_ = ell
        if r2 <= 0:
            return 0.0, 0.0
        return (
            self._radial_alg(1, r1, r2, qa, w, epsabs),
            self._radial_alg(2, r1, r2, qa, w, epsabs),
        )

    def _radial_alg(self, n, r1, r2, qa, w, epsabs):
        """∫_{max(r1,0)}^{r2} ρⁿ g(wρ) k0 (qa (ρ − r1)(r2 − ρ))^γ dρ.

        The end factors are Gauss–Jacobi weights: (r2 − ρ)^γ at the rim, (ρ − r1)^γ when
        the ray starts on the rim (ICR outside), ρ^{n−q} for a power law from the ICR.
        """
        gam = self.gamma
        law = self.law
        lo = max(r1, 0.0)
        lo_rim = r1 >= 0.0
        power0 = (not lo_rim) and law.kind == "power"
        if power0:
            q, v0 = law.spec[1], law.spec[2]
            al0 = n - q
            scale = self.k0 * qa**gam * (w / v0) ** (-q)

            def core(x):
                return scale * (x - r1) ** gam

        else:
            al0 = gam if lo_rim else 0.0
            scale = self.k0 * qa**gam

            def core(x):
                val = scale * x**n * law.g(w * x)
                return val if lo_rim else val * (x - r1) ** gam

        cuts = [lo] + [k for k in law.knots(w) if lo < k < r2] + [r2]
        total = 0.0
        for a, b in zip(cuts[:-1], cuts[1:], strict=True):
            total += _adaptive_jacobi(core, lo, al0, r2, gam, a, b, epsabs / len(cuts))
        return total


_JACOBI = {}


def _jacobi(npts, al, be):
    """Nodes on [−1, 1] and weights of ∫ f(x) (1 + x)^al (1 − x)^be dx."""
    key = (npts, al, be)
    if key not in _JACOBI:
        _JACOBI[key] = roots_jacobi(npts, be, al)
    return _JACOBI[key]


def _adaptive_jacobi(core, lo0, al0, hi0, be0, a, b, tol, depth=0):
    """∫_a^b core(x) (x − lo0)^al0 (hi0 − x)^be0 dx, [a, b] ⊂ [lo0, hi0], by Gauss–Jacobi
    rules (24 and 40 points) that carry the end factors owned by [a, b], bisected until the
    two rules agree to ``tol`` (or to 1e-14 of the panel's value, the round-off floor)."""
    al = al0 if a == lo0 else 0.0
    be = be0 if b == hi0 else 0.0
    h = 0.5 * (b - a)

    def rule(npts):
        x, wt = _jacobi(npts, al, be)
        t = a + h * (x + 1.0)
        f = core(t)
        if a != lo0:
            f = f * (t - lo0) ** al0
        if b != hi0:
            f = f * (hi0 - t) ** be0
        return float(wt @ f) * h ** (al + be + 1.0)

    coarse, fine = rule(24), rule(40)
    # the rules' agreement cannot go below round-off of the panel's own value: an absolute
    # target under it (a far ICR makes the radial integrals large) would bisect every panel
    # to the depth limit, 2^60 panels, and never end
    if abs(fine - coarse) <= max(tol, 1e-14 * abs(fine)) or depth > 60:
        return fine
    m = a + h
    return _adaptive_jacobi(core, lo0, al0, hi0, be0, a, m, tol / 2, depth + 1) + _adaptive_jacobi(
        core, lo0, al0, hi0, be0, m, b, tol / 2, depth + 1
    )


def _tensor_body(tensor, phi):
    """𝔽 in the body frame. tensor: (fx, fy, f, angle, frame)."""
    fx, fy, f, angle, frame = tensor
    fmat = np.array([[fx, f], [-f, fy]], float)
    ra = _rot(angle)
    fa = ra @ fmat @ ra.T
    if frame == "body":
        return fa
    rp = _rot(phi)
    return rp.T @ fa @ rp


def reference_wrench(
    patch,
    pressure,
    law,
    tensor,
    vx,
    vy,
    omega,
    phi=0.0,
    load=1.0,
    epsabs=1e-13,
    radial_epsabs=1e-14,
):
    """Reference wrench (Fx, Fy, M) [N, N, N m] in the fixed frame, M about G.

    patch: see ``_regions``; pressure: ("uniform",), ("linear", xi_c, eta_c),
    ("boussinesq",), ("hertz",) (the last two on one ellipse/disk, centred on it);
    law: see ``SpeedLaw``; tensor: (fx, fy, f, angle, frame) with frame "plane" or "body";
    load: P = m g [N]. ``epsabs``: angular target, relative to P and P × size;
    ``radial_epsabs``: radial quad target (Boussinesq/Hertz only), relative to P.
    """
    pb = _Problem(patch, pressure, law, load)
    fb = _tensor_body(tensor, phi)
    rp = _rot(phi)
    v = np.array([vx, vy], float)
    if omega == 0.0:
        speed = math.hypot(vx, vy)
        if speed == 0.0:
            return 0.0, 0.0, 0.0
        gval = float(pb.law.g(speed))
        fw = rp @ fb @ rp.T
        force = -load * gval * fw @ (v / speed)
        return float(force[0]), float(force[1]), 0.0
    vb = rp.T @ v
    c = pb.r_g + np.array([-vb[1], vb[0]]) / omega
    w = abs(omega)
    size = pb.size
    brk = _breaks(pb.regions, c)
    # scale the radial quad's absolute target to the radial integrals' size
    rad_eps = radial_epsabs * load / (size * size)

    def integrand(s, a, b):
        half = 0.5 * (b - a)
        psi = a + half * (1.0 - math.cos(math.pi * s))
        jac = half * math.pi * math.sin(math.pi * s)
        e = np.array([math.cos(psi), math.sin(psi)])
        ep = np.array([-e[1], e[0]])
        i0, i1 = pb.radial(c, e, w, rad_eps)
        fe = fb @ ep
        return jac * np.array([fe[0] * i0, fe[1] * i0, (e[0] * fe[1] - e[1] * fe[0]) * i1 / size])

    total = np.zeros(3)
    for a, b in zip(brk[:-1], brk[1:], strict=True):
        if b - a < 1e-15:
            continue
        val, err = quad_vec(
            integrand,
            0.0,
            1.0,
            args=(a, b),
            epsabs=epsabs * load / len(brk),
            epsrel=0.0,
            norm="max",
            limit=20000,
        )
        total += val
    sgn = math.copysign(1.0, omega)
    force_b = -sgn * total[:2]
    d = c - pb.r_g
    moment = -sgn * (d[0] * total[1] - d[1] * total[0]) - sgn * total[2] * size
    force = rp @ force_b
    return float(force[0]), float(force[1]), float(moment)


def reference_size(patch, pressure):
    """The length the tests scale moments by: largest distance from the centroid to Ω."""
    return _Problem(patch, pressure, None, 1.0).size
