"""Slow, independent reference for the friction wrench on any footprint (test oracle).

Shares no code with ``slidespin`` beyond reading a footprint's public geometry (polygon
vertices, ring radii and centres) and the pressure laws' parameters: areas, centroids, second
moments, pressure coefficients, the mass centre and every integral are computed here from
scratch.

Model (MODEL §2, §10): a point r (body frame) moves with w = v_G + ω ẑ×(r − r_G); its traction
is τ = −p 𝔽 w/|w|; F = ∫τ dS, M = ∫(r − r_G) × τ dS (about G, counter-clockwise positive).

Method
------
* ω ≠ 0 and the ICR c not far: **polar coordinates about the ICR**, which removes the only
  singularity (the direction of w jumps at c) by splitting the footprint into rays from c.
  On a ray r = c + ρ ê the slip direction is constant, sign(ω) ẑ×ê, so the radial integral of
  p ρ (1, r − r_G) is a polynomial (linear pressure) integrated exactly by Gauss–Legendre; the
  ray's intervals inside the footprint come from ray–edge crossings (parity) and ray–circle
  roots. The angular integral runs over the full turn with ``scipy.integrate.quad_vec``
  (adaptive Gauss–Kronrod), broken at every vertex direction and every circle tangent (and,
  for c inside a circle, at the directions ±90° from its centre, where the rim is nearest
  to tangent).
* ω = 0 or c far (|c| > ``FAR`` × size): the integrand is analytic on the footprint and a
  high-order Gauss rule over signed triangles (vertex 0, Pᵢ, Pᵢ₊₁) and polar rings is used.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad_vec

__all__ = ["reference_power", "reference_pressure", "reference_wrench", "regions_of"]

FAR = 30.0
_GLX, _GLW = np.polynomial.legendre.leggauss(12)
_GLX = 0.5 * (_GLX + 1.0)
_GLW = 0.5 * _GLW
_G2X, _G2W = np.polynomial.legendre.leggauss(30)
_G2X = 0.5 * (_G2X + 1.0)
_G2W = 0.5 * _G2W


def regions_of(footprint):
    """[('poly', (n, 2) array) | ('ring', (ox, oy), r_in, r_out)] from public attributes."""
    items = footprint.patches if hasattr(footprint, "patches") else (footprint,)
    out = []
    for p in items:
        if hasattr(p, "outer_radius"):
            out.append(("ring", tuple(p.centre), p.inner_radius, p.outer_radius))
        elif hasattr(p, "vertices"):
            c, s = math.cos(p.angle), math.sin(p.angle)
            v = np.array(p.vertices, dtype=float)
            out.append(
                (
                    "poly",
                    np.column_stack(
                        (
                            p.centre[0] + c * v[:, 0] - s * v[:, 1],
                            p.centre[1] + s * v[:, 0] + c * v[:, 1],
                        )
                    ),
                )
            )
        else:  # rectangle
            a, b = 0.5 * p.length, 0.5 * p.width
            v = np.array([(-a, -b), (a, -b), (a, b), (-a, b)])
            c, s = math.cos(p.angle), math.sin(p.angle)
            out.append(
                (
                    "poly",
                    np.column_stack(
                        (
                            p.centre[0] + c * v[:, 0] - s * v[:, 1],
                            p.centre[1] + s * v[:, 0] + c * v[:, 1],
                        )
                    ),
                )
            )
    return out


def _area_nodes(regions):
    """Gauss nodes and (signed-fan) weights over the regions, exact for polynomials of degree
    ≤ 58 on triangles; rings: 30 radial × 64 angular."""
    pts, wts = [], []
    for reg in regions:
        if reg[0] == "poly":
            v = reg[1]
            a = v[0]
            for i in range(1, len(v) - 1):
                b, c = v[i], v[i + 1]
                jac = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
                u, t = np.meshgrid(_G2X, _G2X, indexing="ij")
                w = np.outer(_G2W * _G2X, _G2W) * jac
                x = a[0] + u * (b[0] - a[0]) + u * t * (c[0] - b[0])
                y = a[1] + u * (b[1] - a[1]) + u * t * (c[1] - b[1])
                pts.append(np.column_stack((x.ravel(), y.ravel())))
                wts.append(w.ravel())
        else:
            (ox, oy), r0, r1 = reg[1], reg[2], reg[3]
            nt = 64
            th = 2 * np.pi * np.arange(nt) / nt
            r = r0 + (r1 - r0) * _G2X
            w = (r1 - r0) * _G2W * r * 2 * np.pi / nt
            rr, tt = np.meshgrid(r, th, indexing="ij")
            pts.append(
                np.column_stack(((ox + rr * np.cos(tt)).ravel(), (oy + rr * np.sin(tt)).ravel()))
            )
            wts.append(np.repeat(w, nt))
    p = np.vstack(pts)
    w = np.concatenate(wts)
    # orientation of each polygon: make total area positive per polygon
    return p, w


def _signed_fix(regions):
    """Regions with polygons made counter-clockwise."""
    out = []
    for reg in regions:
        if reg[0] == "poly":
            v = reg[1]
            area = 0.5 * np.sum(v[:, 0] * np.roll(v[:, 1], -1) - np.roll(v[:, 0], -1) * v[:, 1])
            out.append(("poly", v if area > 0 else v[::-1].copy()))
        else:
            out.append(reg)
    return out


def reference_pressure(footprint, law, load=1.0):
    """A callable p(x, y) normalised to ``load`` and the mass centre G, computed here.

    ``law``: ("uniform",), ("linear", xi_c, eta_c) or ("map", f) with f(x, y) vectorised.
    """
    regions = _signed_fix(regions_of(footprint))
    pts, w = _area_nodes(regions)
    x, y = pts[:, 0], pts[:, 1]
    area = w.sum()
    cx, cy = (w @ x) / area, (w @ y) / area
    if law[0] == "uniform":

        def p(xx, yy):
            return np.full(np.shape(xx), load / area)

        return p, (cx, cy)
    if law[0] == "linear":
        jxx = w @ ((x - cx) ** 2)
        jxy = w @ ((x - cx) * (y - cy))
        jyy = w @ ((y - cy) ** 2)
        g = np.linalg.solve([[jxx, jxy], [jxy, jyy]], area * np.array([law[1] - cx, law[2] - cy]))

        def p(xx, yy):
            return load / area * (1.0 + g[0] * (np.asarray(xx) - cx) + g[1] * (np.asarray(yy) - cy))

        return p, (law[1], law[2])
    f = law[1]
    tot = w @ f(x, y)
    gx = (w @ (f(x, y) * x)) / tot
    gy = (w @ (f(x, y) * y)) / tot

    def p(xx, yy):
        return load / tot * f(np.asarray(xx, dtype=float), np.asarray(yy, dtype=float))

    return p, (gx, gy)


def _ray_intervals(regions, c, e):
    """Intervals [ρa, ρb] (ρ ≥ 0) of the ray c + ρ e inside the footprint."""
    out = []
    for reg in regions:
        if reg[0] == "poly":
            v = reg[1]
            d = v - c
            s = d[:, 0] * e[1] - d[:, 1] * e[0]  # which side of the line each vertex is
            pos = s > 0
            nxt = np.roll(np.arange(len(v)), -1)
            cross = pos != pos[nxt]
            rhos = []
            for i in np.nonzero(cross)[0]:
                j = nxt[i]
                t = s[i] / (s[i] - s[j])
                q = v[i] + t * (v[j] - v[i])
                rhos.append((q - c) @ e)
            rhos = sorted(r for r in rhos)
            ahead = [r for r in rhos if r > 0]
            inside = (len(rhos) - len(ahead)) % 2 == 1
            pts = ([0.0] if inside else []) + ahead
            for k in range(0, len(pts) - 1, 2):
                out.append((pts[k], pts[k + 1]))
        else:
            (ox, oy), r0, r1 = reg[1], reg[2], reg[3]
            oc = np.array([ox, oy]) - c
            m = oc @ e
            dd = oc @ oc - m * m

            def chord(r, m=m, dd=dd):
                h2 = r * r - dd
                if h2 <= 0:
                    return None
                h = math.sqrt(h2)
                a, b = max(m - h, 0.0), m + h
                return (a, b) if b > a else None

            big = chord(r1)
            if big is None:
                continue
            small = chord(r0) if r0 > 0 else None
            if small is None:
                out.append(big)
            else:
                if small[0] > big[0]:
                    out.append((big[0], small[0]))
                if big[1] > small[1]:
                    out.append((small[1], big[1]))
    return out


def _breaks(regions, c):
    br = []
    for reg in regions:
        if reg[0] == "poly":
            d = reg[1] - c
            br.extend(np.arctan2(d[:, 1], d[:, 0]))
        else:
            (ox, oy), r0, r1 = reg[1], reg[2], reg[3]
            dx, dy = ox - c[0], oy - c[1]
            dist = math.hypot(dx, dy)
            base = math.atan2(dy, dx)
            br.extend([base, base + math.pi, base + 0.5 * math.pi, base - 0.5 * math.pi])
            for r in (r0, r1):
                if 0 < r < dist:
                    a = math.asin(r / dist)
                    br.extend([base + a, base - a])
    return np.array(br)


def reference_wrench(
    footprint, law, tensor, vx, vy, omega, phi=0.0, frame="plane", load=1.0, tol=1e-13
):
    """(Fx, Fy, M): force in the fixed frame [N] and moment about G [N m].

    ``law`` as in :func:`reference_pressure`; ``tensor`` the 2×2 friction matrix in its own
    frame (``frame`` "plane" or "body"); (vx, vy) the velocity of G in the fixed frame.
    """
    regions = _signed_fix(regions_of(footprint))
    p, (gx, gy) = reference_pressure(footprint, law, load)
    cph, sph = math.cos(phi), math.sin(phi)
    rot = np.array([[cph, -sph], [sph, cph]])
    T = np.asarray(tensor, dtype=float)
    tb = T if frame == "body" else rot.T @ T @ rot
    vb = rot.T @ np.array([vx, vy], dtype=float)
    size = max(
        np.max(np.abs(r[1])) if r[0] == "poly" else abs(r[1][0]) + abs(r[1][1]) + r[3]
        for r in regions
    )
    g = np.array([gx, gy])
    if omega == 0.0 or np.hypot(*vb) > FAR * size * abs(omega):
        pts, w = _area_nodes(regions)
        x, y = pts[:, 0], pts[:, 1]
        wx = vb[0] - omega * (y - gy)
        wy = vb[1] + omega * (x - gx)
        n = np.hypot(wx, wy)
        pw = p(x, y) * w / n
        tx = -(tb[0, 0] * wx + tb[0, 1] * wy) * pw
        ty = -(tb[1, 0] * wx + tb[1, 1] * wy) * pw
        fb = np.array([tx.sum(), ty.sum()])
        m = float(((x - gx) * ty - (y - gy) * tx).sum())
    else:
        c = g + np.array([-vb[1], vb[0]]) / omega
        sgn = 1.0 if omega > 0 else -1.0

        def integrand(psi):
            e = np.array([math.cos(psi), math.sin(psi)])
            t = sgn * np.array([-e[1], e[0]])  # slip direction on this ray
            tau = -(tb @ t)
            k1 = 0.0
            k2 = np.zeros(2)
            for a, b in _ray_intervals(regions, c, e):
                rho = a + (b - a) * _GLX
                wr = (b - a) * _GLW * rho
                pts = c + np.outer(rho, e)
                pr = p(pts[:, 0], pts[:, 1]) * wr
                k1 += pr.sum()
                k2 += pr @ (pts - g)
            mom = k2[0] * tau[1] - k2[1] * tau[0]
            return np.array([k1 * tau[0], k1 * tau[1], mom])

        br = np.sort(np.mod(_breaks(regions, c), 2 * np.pi))
        start = br[0] if len(br) else 0.0
        pts_ = [b for b in br if start < b < start + 2 * np.pi]
        res, _ = quad_vec(
            integrand,
            start,
            start + 2 * np.pi,
            points=pts_,
            epsabs=tol * load,
            epsrel=1e-13,
            norm="max",
            limit=20000,
        )
        fb = res[:2]
        m = float(res[2])
    f = rot @ fb
    return float(f[0]), float(f[1]), m


def reference_power(footprint, law, tensor, vx, vy, omega, frame="body", load=1.0):
    """−∫ p (w·𝔽_sym w)/|w| dS [W] in the body frame (φ = 0): the friction power, by the
    far-field Gauss rule (smooth integrand only; for checks with a far ICR)."""
    regions = _signed_fix(regions_of(footprint))
    p, (gx, gy) = reference_pressure(footprint, law, load)
    pts, w = _area_nodes(regions)
    x, y = pts[:, 0], pts[:, 1]
    wx = vx - omega * (y - gy)
    wy = vy + omega * (x - gx)
    n = np.hypot(wx, wy)
    T = np.asarray(tensor, dtype=float)
    q = T[0, 0] * wx * wx + (T[0, 1] + T[1, 0]) * wx * wy + T[1, 1] * wy * wy
    return float(-(p(x, y) * w * q / n).sum())
