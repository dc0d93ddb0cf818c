"""The friction wrench of a user pressure map (:class:`~slidespin.PressureMap`) by adaptive
quadrature about the instantaneous centre of rotation (MODEL §2, §10).

A quadrature in polar coordinates about the instantaneous centre of rotation c, which removes
its singularity: on each ray c + ρ ê the slip direction is constant, the footprint cuts exact
intervals (ray–edge crossings, ray–circle roots), and the radial integral of p ρ (1, r − r_G)
is Gauss–Legendre (24 nodes) on each interval. The angle is split at every vertex
direction, every circle tangent and the directions ±90° from each circle's centre, and, for
an edge at a distance d from c, at the directions of its points s_V/2^k from the foot of
the perpendicular (k = 1, 2, ... while s_V/2^k > d; s_V the vertex's offset): the area
beyond a near edge crowds into angles ~d/s_V wide beside its vertices. Each panel gets 12
Gauss–Legendre nodes in u with ψ = ψ_a + (ψ_b − ψ_a)(1 − cos πu)/2 (square-root ends of
tangent panels become smooth) and is bisected, all panels at once, until the halves agree
with the whole to ``map_tol`` × (panel width)/2π (default map_tol 1e-9 P and P·extent; a
RuntimeWarning if 40 levels do not suffice). For ω = 0 or a far ICR (|c − o| > 24 × extent)
the integrand is smooth and the 24 × 24 Gauss rule of
:func:`~slidespin.contact.pressure_map.area_rule` is used. Measured: the linear law given as
a map agrees with the exact kernel to ≤ 1e-12 with the ICR inside, at 1e-11 … 1e-3 of an
edge, near a ring's rim and outside; 2–30 ms per wrench (pure NumPy, ~1e4–1e5 map
evaluations), up to ~0.1 s with the ICR within 1e-10 of an edge.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from slidespin.contact._kernel_footprint import FAR_RATIO
from slidespin.contact.pressure_map import _unit_rule, area_rule, map_scale
from slidespin.contact.shapes import Annulus, Polygon, as_patches

__all__ = ["MAP_TOL", "MAP_TOL_RANGE", "map_prepare", "map_wrench_world"]

#: default target of the user-map quadrature (units of P and P × extent)
MAP_TOL = 1e-9
#: valid range of ``map_tol``: below 1e-12 the adaptive panels cannot meet it (they refine
#: without end); above 1e-2 the wrench is not worth the name
MAP_TOL_RANGE = (1e-12, 1e-2)
_MAP_OUTER = 12  # Gauss–Legendre nodes per angular panel
_MAP_INNER = 24  # Gauss–Legendre nodes per ray interval (graded)
_MAP_CHECK = 16  # the coarser graded rule per ray interval that checks it
_MAP_MAX_LEVELS = 40


def map_prepare(footprint, pmap, arrays, tol=MAP_TOL):
    total, sx, sy = map_scale(footprint, pmap, tol)
    pts, w = area_rule(footprint, graded=True)
    scale = 1.0 / total  # unit load
    polys = []
    rings = []
    for p in as_patches(footprint):
        if isinstance(p, Annulus):
            rings.append((p.centre[0], p.centre[1], p.inner_radius, p.outer_radius))
        else:
            polys.append(p.points if isinstance(p, Polygon) else p.as_polygon().points)
    return {
        "f": pmap,
        "scale": scale,
        "g": (sx / total, sy / total),
        "pts": pts,
        "w": w * pmap(pts[:, 0], pts[:, 1]) * scale,
        "polys": polys,
        "rings": rings,
        "frame": arrays.frame,
    }


def map_wrench_world(prep, t, body_frame, phi, vx, vy, omega, tol):
    c, s = math.cos(phi), math.sin(phi)
    rot = np.array([[c, -s], [s, c]])
    tb = t if body_frame else rot.T @ t @ rot
    vb = rot.T @ np.array([vx, vy])
    fb, m = _map_wrench_body(prep, tb, vb[0], vb[1], omega, tol)
    f = rot @ fb
    return f[0], f[1], m


def _map_wrench_body(prep, tb, vx, vy, omega, tol):
    gx, gy = prep["g"]
    ox, oy, ext = prep["frame"]
    speed = math.hypot(vx, vy)
    if speed == 0.0 and omega == 0.0:
        return np.zeros(2), 0.0
    far = omega == 0.0 or speed > FAR_RATIO * 2.0 * ext * abs(omega)
    if not far:
        cx, cy = gx - vy / omega, gy + vx / omega
        far = math.hypot(cx - ox, cy - oy) > FAR_RATIO * ext
    if far:
        x, y = prep["pts"][:, 0], prep["pts"][:, 1]
        wx = vx - omega * (y - gy)
        wy = vy + omega * (x - gx)
        pw = prep["w"] / np.hypot(wx, wy)
        tx = -(tb[0, 0] * wx + tb[0, 1] * wy) * pw
        ty = -(tb[1, 0] * wx + tb[1, 1] * wy) * pw
        return np.array([tx.sum(), ty.sum()]), float(((x - gx) * ty - (y - gy) * tx).sum())
    return _map_adaptive(prep, tb, cx, cy, omega, tol, ext)


def _map_adaptive(prep, tb, cx, cy, omega, tol, ext):
    """Globally vectorised adaptive bisection of the angular panels (module notes)."""
    br = _map_breaks(prep, cx, cy)
    lo, hi = br[:-1], br[1:]
    total = np.zeros(3)
    err_left = 0.0
    done_lo, done_hi = [], []
    for _ in range(_MAP_MAX_LEVELS):
        if lo.size == 0:
            break
        mid = 0.5 * (lo + hi)
        both = _map_panels(
            prep,
            tb,
            cx,
            cy,
            omega,
            np.concatenate((lo, lo, mid)),
            np.concatenate((hi, mid, hi)),
            _MAP_INNER,
        )
        k = lo.size
        whole, halves = both[:k], both[k : 2 * k] + both[2 * k :]
        diff = np.maximum(
            np.abs(halves[:, :2] - whole[:, :2]).max(axis=1),
            np.abs(halves[:, 2] - whole[:, 2]) / ext,
        )
        ok = (diff <= tol * (hi - lo) / (2.0 * np.pi)) | (hi - lo < 1e-13)
        total += halves[ok].sum(axis=0)
        done_lo += [lo[ok], mid[ok]]
        done_hi += [mid[ok], hi[ok]]
        lo, hi = np.concatenate((lo[~ok], mid[~ok])), np.concatenate((mid[~ok], hi[~ok]))
    else:
        if lo.size:
            mid = 0.5 * (lo + hi)
            rest = _map_panels(
                prep,
                tb,
                cx,
                cy,
                omega,
                np.concatenate((lo, mid)),
                np.concatenate((mid, hi)),
                _MAP_INNER,
            )
            total += rest.sum(axis=0)
            err_left = lo.size
            done_lo += [lo, mid]
            done_hi += [mid, hi]
    # the radial rule: the same panels with a coarser graded rule on every ray interval
    if done_lo:
        check = _map_panels(
            prep, tb, cx, cy, omega, np.concatenate(done_lo), np.concatenate(done_hi), _MAP_CHECK
        ).sum(axis=0)
        err = max(float(np.abs(check[:2] - total[:2]).max()), abs(check[2] - total[2]) / ext)
        if err > tol:
            warnings.warn(
                f"footprint_wrench: the pressure-map quadrature along the rays reached only "
                f"~{err:.1e} (in units of P and P x extent; two rules differ), not {tol:.1e}, "
                f"with the ICR at ({cx:.6g}, {cy:.6g}) m: the map is not smooth on the "
                "footprint (a kink, a jump, or an edge behaviour other than sqrt(d) or "
                "1/sqrt(d))",
                RuntimeWarning,
                stacklevel=5,
            )
    if err_left:
        warnings.warn(
            f"footprint_wrench: the pressure-map quadrature did not reach {tol:.1e} on "
            f"{err_left} angular panel(s) with the ICR at ({cx:.6g}, {cy:.6g}) m",
            RuntimeWarning,
            stacklevel=5,
        )
    return total[:2], float(total[2])


def _handed(nx, ny, tx, ty):
    """+1 if t̂ is n̂ turned counter-clockwise, else −1."""
    return 1.0 if nx * ty - ny * tx > 0.0 else -1.0


def _map_breaks(prep, cx, cy):
    br = []
    for poly in prep["polys"]:
        br.extend(np.arctan2(poly[:, 1] - cy, poly[:, 0] - cx))
        # an edge close to c: seen from c, the area beyond it crowds into narrow angles next to
        # its vertices; graded breaks at the directions of the edge points s_V/2^k from the foot
        # of the perpendicular (k = 1, 2, ... while s_V/2^k > d) resolve that scale
        q = np.roll(poly, -1, axis=0)
        for (ax, ay), (bx, by) in zip(poly, q):
            ln = math.hypot(bx - ax, by - ay)
            tx, ty = (bx - ax) / ln, (by - ay) / ln
            d = abs((ax - cx) * ty - (ay - cy) * tx)
            if d == 0.0:
                continue
            nx, ny = ty, -tx
            if (ax - cx) * nx + (ay - cy) * ny < 0.0:
                nx, ny = -nx, -ny
            psi0 = math.atan2(ny, nx)
            for sv in ((ax - cx) * tx + (ay - cy) * ty, (bx - cx) * tx + (by - cy) * ty):
                k = abs(sv) / 2.0
                while k > d:
                    br.append(psi0 + math.copysign(math.atan(k / d), sv) * _handed(nx, ny, tx, ty))
                    k *= 0.5
    for ox, oy, r0, r1 in prep["rings"]:
        dx, dy = ox - cx, oy - cy
        dist = math.hypot(dx, dy)
        base = math.atan2(dy, dx)
        br.extend([base, base + math.pi, base + 0.5 * math.pi, base - 0.5 * math.pi])
        for r in (r0, r1):
            if 0.0 < r < dist:
                a = math.asin(r / dist)
                br.extend([base + a, base - a])
    br = np.unique(np.mod(np.array(br), 2.0 * np.pi))
    if br.size == 0:
        br = np.array([0.0])
    return np.concatenate((br, [br[0] + 2.0 * np.pi]))


def _map_panels(prep, tb, cx, cy, omega, lo, hi, n_in):
    """(Fx, Fy, M) in the body frame of each angular panel [lo, hi] of the polar rule about
    the ICR: ``_MAP_OUTER`` Gauss–Legendre nodes in u, ψ = lo + (hi − lo)(1 − cos πu)/2, and
    ``n_in`` Gauss–Legendre nodes on each interval of each ray inside the footprint."""
    gx, gy = prep["g"]
    x, w = np.polynomial.legendre.leggauss(_MAP_OUTER)
    uo = 0.5 * (x + 1.0)
    wo = 0.5 * w
    # graded in ρ on every interval: a map with √d or 1/√d behaviour at a rim or side, which
    # each ray crosses, becomes smooth (footprint_pressure._unit_rule)
    u, wu = _unit_rule(n_in, True)
    width = (hi - lo)[:, None]
    psi = (lo[:, None] + width * 0.5 * (1.0 - np.cos(np.pi * uo))).ravel()
    wpsi = (width * 0.5 * np.pi * np.sin(np.pi * uo) * wo).ravel()
    ex, ey = np.cos(psi), np.sin(psi)
    # crossings of the full line c + ρ ê with the footprint's boundary, per direction
    cols = []
    for poly in prep["polys"]:
        q = np.roll(poly, -1, axis=0)
        for (ax, ay), (bx, by) in zip(poly, q):
            sa = (ax - cx) * ey - (ay - cy) * ex
            sb = (bx - cx) * ey - (by - cy) * ex
            cross = (sa > 0.0) != (sb > 0.0)
            with np.errstate(divide="ignore", invalid="ignore"):
                tt = sa / (sa - sb)
                rho = (ax + tt * (bx - ax) - cx) * ex + (ay + tt * (by - ay) - cy) * ey
            cols.append(np.where(cross, rho, np.inf))
    for ox, oy, r0, r1 in prep["rings"]:
        m = (ox - cx) * ex + (oy - cy) * ey
        dd = (ox - cx) ** 2 + (oy - cy) ** 2 - m * m
        for r in (r1, r0) if r0 > 0.0 else (r1,):
            h2 = r * r - dd
            h = np.sqrt(np.maximum(h2, 0.0))
            ok = h2 > 0.0
            cols.append(np.where(ok, m - h, np.inf))
            cols.append(np.where(ok, m + h, np.inf))
    xs = np.sort(np.column_stack(cols), axis=1)
    a = np.maximum(xs[:, 0::2], 0.0)
    b = np.maximum(xs[:, 1::2], 0.0) if xs.shape[1] > 1 else np.zeros_like(a)
    if a.shape != b.shape:
        a = a[:, : b.shape[1]]
    valid = np.isfinite(a) & np.isfinite(b) & (b > a)
    a = np.where(valid, a, 0.0)
    b = np.where(valid, b, 0.0)
    length = b - a
    rho = a[:, :, None] + length[:, :, None] * u[None, None, :]
    wr = length[:, :, None] * wu[None, None, :] * rho
    px = cx + rho * ex[:, None, None]
    py = cy + rho * ey[:, None, None]
    p = prep["f"](px, py) * prep["scale"]
    k1 = (p * wr).sum(axis=(1, 2))
    k2x = (p * wr * (px - gx)).sum(axis=(1, 2))
    k2y = (p * wr * (py - gy)).sum(axis=(1, 2))
    sg = 1.0 if omega > 0.0 else -1.0
    tx = -sg * (tb[0, 0] * -ey + tb[0, 1] * ex)  # −𝔽 ŵ, ŵ = sign(ω) ẑ×ê
    ty = -sg * (tb[1, 0] * -ey + tb[1, 1] * ex)
    out = np.column_stack((wpsi * k1 * tx, wpsi * k1 * ty, wpsi * (k2x * ty - k2y * tx)))
    return out.reshape(lo.size, _MAP_OUTER, 3).sum(axis=1)
