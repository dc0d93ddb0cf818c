"""Footprints of any shape: polygons, rectangles, disks, rings and several separate pads.

A footprint Ω is a finite union of disjoint regions in the body frame C ξ η (MODEL §10). Every
patch is a frozen value object, placed in the body frame by ``centre=(ξ, η)`` [m] and
``angle=`` [rad] (counter-clockwise, about the patch's own origin):

=======================================  ============================================
class                                    region (in the patch's own frame)
=======================================  ============================================
``Polygon(vertices)``                    simple polygon, convex or not, either orientation
``Rectangle(length, width)``             |ξ| ≤ length/2, |η| ≤ width/2 (length along ξ)
``Disk(radius)``                         |r| ≤ radius
``Annulus(inner_radius, outer_radius)``  inner_radius ≤ |r| ≤ outer_radius
``Pads(patches)``                        the union of several disjoint patches
``Blade(length)``                        the segment |ξ| ≤ length/2, η = 0: a line contact
=======================================  ============================================

Each has ``area`` [m²], ``centroid`` (area centroid, body frame) [m], ``second_moment``
(J = ∫(r − r_c)(r − r_c)ᵀ dS about the area centroid, MODEL §10) [m⁴], ``outlines()``
(closed curves for plotting) and ``to_arrays()``, the plain-array form that the compiled
kernel (:mod:`slidespin.contact._kernel_footprint`) reads (a ``Blade``, a line contact, has no area
and no second moment: one edge and no circle, see its notes):

* ``edges``, float64 (n_edges, 4): oriented straight edges (ξ₀, η₀, ξ₁, η₁) [m]. Each
  polygon's edges run counter-clockwise, so that the signed fan of triangles (c, P₀, P₁)
  over all edges, from any apex c, adds up to the polygons' area.
* ``circles``, float64 (n_circles, 4): (ξ_o, η_o, radius, sign) [m]: a disk counted with
  ``sign`` +1, or removed with sign −1 (the hole of a ring: an annulus is a disk minus a
  disk).
* ``frame``, float64 (3,): (ξ_o, η_o, extent): a reference point (the area centroid) and the
  largest distance from it to any point of the footprint [m].

Invalid input raises ``ValueError`` naming the parameter: fewer than 3 (or more than
:data:`MAX_VERTICES`) vertices, repeated
vertices, a self-intersecting polygon, zero area, radii out of order, overlapping pads, and
dimensions out of range: lengths and radii in [1e-9, 1e6] m (``_validate.LENGTH``), a
rectangle's length/width (or a polygon's (2R)²/area) within :data:`MAX_ASPECT` = 1e3, a
placement at most :data:`MAX_OFFSET` = 1e6 sizes (and 1e6 m) from the origin.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from slidespin import _validate as v

__all__ = [
    "Annulus",
    "Blade",
    "Disk",
    "Footprint",
    "FootprintArrays",
    "MAX_ASPECT",
    "MAX_OFFSET",
    "MAX_VERTICES",
    "Pads",
    "Polygon",
    "Rectangle",
]


class FootprintArrays(NamedTuple):
    """Plain-array form of a footprint, read by the compiled kernel (see the module notes)."""

    edges: np.ndarray  #: (n, 4) oriented edges ξ₀, η₀, ξ₁, η₁ [m], counter-clockwise
    circles: np.ndarray  #: (m, 4) ξ_o, η_o, radius [m], sign (+1 disk, −1 hole)
    frame: np.ndarray  #: (3,) ξ_o, η_o [m] (area centroid), extent [m]


# ---------------------------------------------------------------------------------------------
# validation helpers


def _point(name: str, value) -> tuple[float, float]:
    try:
        seq = tuple(value)
    except TypeError:
        raise ValueError(
            f"{name} = {value!r} is invalid; valid values: a pair (xi, eta) in m"
        ) from None
    if len(seq) != 2:
        raise ValueError(f"{name} = {value!r} is invalid; valid values: a pair (xi, eta) in m")
    return (v.finite(f"{name}[0]", seq[0]), v.finite(f"{name}[1]", seq[1]))


#: largest length/width of a rectangle (and (2R)²/area of a polygon, R the largest distance
#: of a vertex from the vertices' mean: length/width + width/length for a rectangle). The
#: kernel's moment about a rotated rectangle (angle 1 rad, pure spin, uniform pressure, closed
#: form ∫|r| dS) has relative error 2.6e-12 at aspect 1e3, 4e-11 at 1e4, 9e-9 at 1e5, 3e-6 at
#: 1e6, 3e-2 at 1e8 (the shoelace terms cancel): the ellipse's bound b/a ≥ 1e-3 is kept.
MAX_ASPECT = 1e3
#: a patch may lie at most this many times its size from the body origin (and a polygon's
#: vertices from their own origin): its placed coordinates then keep ≥ 10 significant digits
MAX_OFFSET = 1e6
#: largest number of vertices of a polygon (and of edges and circles of a set of pads,
#: a disk or ring counting 4). Measured (one core of a shared machine): a simple-polygon
#: check in ~0.03 s for 10,000 vertices; the compiled wrench costs ~70 ns per edge (0.8 ms
#: at 10,000, 3.3 ms at 50,000), a trajectory to rest ~0.5 s at 10,000; a pressure map
#: (pure NumPy) is far slower. Simplify a denser measured outline first.
MAX_VERTICES = 20_000
#: valid range of a polygon's size 2R [m] (R: largest distance of a vertex from the
#: vertices' mean): a polygon drawn within LENGTH may be a few times smaller than its
#: bounding dimension; its r⁴ moments stay far from under- and overflow
POLYGON_SIZE = (1e-10, 1e6)


def _length(name: str, value) -> float:
    return v.bounded(name, value, *v.LENGTH, "m")


def _offset(name: str, value, size: float, what: str, shown: str = "") -> None:
    """Raise if the pair ``value`` lies farther than allowed for a patch of ``size`` [m]."""
    far = max(abs(value[0]), abs(value[1]))
    lim = min(v.LENGTH[1], MAX_OFFSET * size)
    if far > lim:
        shown = shown or f"{name} = {value!r} m"
        raise ValueError(
            f"{shown} is invalid for a {what} of size {size!r} m; valid range: coordinates "
            f"within min({v.LENGTH[1]:g} m, {MAX_OFFSET:g} x size) = {lim:g} m (farther, "
            "they lose their digits to round-off)"
        )


def _place(points: np.ndarray, centre: tuple[float, float], angle: float) -> np.ndarray:
    """Rotate ``points`` (n, 2) by ``angle`` about the origin, then shift by ``centre``."""
    c, s = math.cos(angle), math.sin(angle)
    x, y = points[:, 0], points[:, 1]
    return np.column_stack((centre[0] + c * x - s * y, centre[1] + s * x + c * y))


def _cross(ax, ay, bx, by):
    return ax * by - ay * bx


def _segments_intersect(p, q, r, s, eps) -> bool:
    """Closed segments pq and rs share a point (collinear overlaps included)."""
    d1 = _cross(q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1])
    d2 = _cross(q[0] - p[0], q[1] - p[1], s[0] - p[0], s[1] - p[1])
    d3 = _cross(s[0] - r[0], s[1] - r[1], p[0] - r[0], p[1] - r[1])
    d4 = _cross(s[0] - r[0], s[1] - r[1], q[0] - r[0], q[1] - r[1])

    def sgn(x):
        return 0 if abs(x) <= eps else (1 if x > 0 else -1)

    o1, o2, o3, o4 = sgn(d1), sgn(d2), sgn(d3), sgn(d4)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True

    def on(a, b, c):  # c on segment ab, given collinear
        return (
            min(a[0], b[0]) - eps <= c[0] <= max(a[0], b[0]) + eps
            and min(a[1], b[1]) - eps <= c[1] <= max(a[1], b[1]) + eps
        )

    return (
        (o1 == 0 and on(p, q, r))
        or (o2 == 0 and on(p, q, s))
        or (o3 == 0 and on(r, s, p))
        or (o4 == 0 and on(r, s, q))
    )


def _edges(ccw: np.ndarray) -> np.ndarray:
    """Edges (ξ₀, η₀, ξ₁, η₁) of the closed counter-clockwise polygon ``ccw``."""
    return np.column_stack((ccw, np.roll(ccw, -1, axis=0)))


def _signed_area(pts: np.ndarray) -> float:
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def _pair_candidates(lo: np.ndarray, hi: np.ndarray, chunk: int = 1 << 21):
    """Index pairs (i, k), i < k, of boxes [lo, hi] (n, 2) that overlap, in chunks.

    A sweep along the axis with fewer overlapping intervals: the boxes sorted by their lower
    end, each box meets the following ones whose lower end lies below its upper end
    (``searchsorted``), then the other axis filters. Vectorised; the number of pairs examined
    is the number of interval overlaps on the chosen axis (O(n) for a measured outline)."""
    n = len(lo)
    best = None
    for ax in (0, 1):
        order = np.argsort(lo[:, ax], kind="stable")
        slo = lo[order, ax]
        cnt = np.searchsorted(slo, hi[order, ax], side="right") - np.arange(1, n + 1)
        cnt = np.maximum(cnt, 0)
        total = int(cnt.sum())
        if best is None or total < best[0]:
            best = (total, ax, order, cnt)
    assert best is not None
    _, ax, order, cnt = best
    other = 1 - ax
    ends = np.cumsum(cnt)
    start = 0
    while start < n:
        # rows [start, stop) of the sorted boxes, about ``chunk`` pairs at most (≥ 1 row)
        base = ends[start - 1] if start else 0
        stop = int(np.searchsorted(ends, base + chunk, side="right"))
        stop = min(max(stop, start + 1), n)
        c = cnt[start:stop]
        m = int(c.sum())
        if m:
            rows = np.repeat(np.arange(start, stop), c)
            first = np.cumsum(c) - c
            off = np.arange(m) - np.repeat(first, c)
            a, b = order[rows], order[rows + 1 + off]
            keep = (lo[a, other] <= hi[b, other]) & (lo[b, other] <= hi[a, other])
            a, b = a[keep], b[keep]
            yield np.minimum(a, b), np.maximum(a, b)
        start = stop


def _check_simple(pts: np.ndarray) -> None:
    """Raise if the closed polygon ``pts`` repeats a vertex, intersects itself or has no area.

    Every pair of edges is tested (closed segments, a tolerance 1e-13 × size² on the cross
    products; adjacent edges must not fold back onto each other), but only the pairs whose
    bounding boxes overlap are examined, all at once with NumPy (:func:`_pair_candidates`):
    10,000 vertices take ~0.1 s. The first offending pair (i, k) in lexicographic order is
    reported.
    """
    n = len(pts)
    scale = float(np.max(np.abs(pts - pts.mean(axis=0)))) or 1.0
    eps = 1e-13 * scale * scale
    nxt = np.roll(pts, -1, axis=0)
    step = np.hypot(*(nxt - pts).T)
    rep = np.flatnonzero(step <= 1e-14 * scale)
    if rep.size:
        i = int(rep[0])
        j = (i + 1) % n
        raise ValueError(
            f"vertices: vertex {j} repeats vertex {i} at ({float(pts[i, 0])!r}, "
            f"{float(pts[i, 1])!r}); valid values: distinct consecutive vertices of a simple "
            "polygon"
        )
    bad: list[tuple[int, int, str]] = []
    # adjacent edges (j − 1, j) share vertex j: they must not fold back onto each other
    u = np.roll(pts, 1, axis=0) - pts
    w = nxt - pts
    fold = np.flatnonzero(
        (np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]) <= eps)
        & (u[:, 0] * w[:, 0] + u[:, 1] * w[:, 1] > 0.0)
    )
    bad.extend((0, n - 1, "fold") if j == 0 else (j - 1, j, "fold") for j in fold.tolist())
    # every other pair of edges: closed segments must not meet
    pad = eps + 1e-12 * scale
    lo = np.minimum(pts, nxt) - pad
    hi = np.maximum(pts, nxt) + pad
    for i, k in _pair_candidates(lo, hi):
        keep = (k != i + 1) & ~((i == 0) & (k == n - 1))
        i, k = i[keep], k[keep]
        if i.size == 0:
            continue
        hit = _segments_meet(pts[i], nxt[i], pts[k], nxt[k], eps)
        if np.any(hit):
            i, k = i[hit], k[hit]
            first = np.lexsort((k, i))[0]
            bad.append((int(i[first]), int(k[first]), "meet"))
    if bad:
        i, k, kind = min(bad)
        if kind == "fold":
            raise ValueError(
                f"vertices: edges {i} and {k} fold back onto each other; valid values: "
                "a simple (non-self-intersecting) polygon"
            )
        raise ValueError(
            f"vertices: edges {i} and {k} of the polygon intersect; valid values: a "
            "simple (non-self-intersecting) polygon"
        )
    area = _signed_area(pts)
    if not abs(area) > 1e-12 * scale * scale:
        raise ValueError(f"vertices: the polygon has zero area ({area:.6g} m^2); valid range: > 0")


def _segments_meet(p, q, r, s, eps) -> np.ndarray:
    """Closed segments p_i q_i and r_i s_i (arrays (m, 2)) share a point (collinear overlaps
    included): :func:`_segments_intersect`, vectorised."""

    def sgn(x):
        return np.where(np.abs(x) <= eps, 0, np.sign(x))

    def cr(a, b, c):  # (b − a) × (c − a)
        return _cross(b[:, 0] - a[:, 0], b[:, 1] - a[:, 1], c[:, 0] - a[:, 0], c[:, 1] - a[:, 1])

    def on(a, b, c):  # c on segment ab, given collinear
        return np.all((np.minimum(a, b) - eps <= c) & (c <= np.maximum(a, b) + eps), axis=1)

    o1, o2 = sgn(cr(p, q, r)), sgn(cr(p, q, s))
    o3, o4 = sgn(cr(r, s, p)), sgn(cr(r, s, q))
    return (
        ((o1 * o2 < 0) & (o3 * o4 < 0))
        | ((o1 == 0) & on(p, q, r))
        | ((o2 == 0) & on(p, q, s))
        | ((o3 == 0) & on(r, s, p))
        | ((o4 == 0) & on(r, s, q))
    )


def _ear_clip(pts: np.ndarray) -> np.ndarray:
    """Triangles (k, 3, 2) covering a simple counter-clockwise polygon (ear clipping).

    The scan for the next ear resumes where the last one was cut, and each candidate is
    tested against all remaining vertices at once (NumPy): O(n²) arithmetic, vectorised
    (~0.5 s for 10,000 vertices)."""
    idx = list(range(len(pts)))
    tris = []
    # remaining vertices as arrays (compacted when half of them are gone)
    rest = np.arange(len(pts))
    alive = np.ones(len(pts), dtype=bool)

    def blocked(i0, i1, i2, closed) -> bool:  # a remaining vertex in the triangle
        a, b, c = pts[i0], pts[i1], pts[i2]
        q = pts[rest]
        px, py = q[:, 0], q[:, 1]
        s1 = _cross(b[0] - a[0], b[1] - a[1], px - a[0], py - a[1])
        s2 = _cross(c[0] - b[0], c[1] - b[1], px - b[0], py - b[1])
        s3 = _cross(a[0] - c[0], a[1] - c[1], px - c[0], py - c[1])
        if closed:
            hit = (s1 >= 0) & (s2 >= 0) & (s3 >= 0)
        else:
            hit = (s1 > 0) & (s2 > 0) & (s3 > 0)
        hit &= alive[rest] & (rest != i0) & (rest != i1) & (rest != i2)
        return bool(hit.any())

    state = {"start": 0, "gone": 0}

    def drop(k):
        nonlocal rest
        alive[idx.pop(k)] = False
        state["start"] = max(k - 1, 0)
        state["gone"] += 1
        if 2 * state["gone"] >= len(rest):
            rest = np.array(idx)
            state["gone"] = 0

    def clip_one(closed):
        n = len(idx)
        s0 = state["start"] % n
        for kk in range(n):
            k = (s0 + kk) % n
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % n]
            a, b, c = pts[i0], pts[i1], pts[i2]
            cr = _cross(b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1])
            if cr < 0:
                continue
            if cr == 0:  # collinear vertex: drop it, no triangle
                drop(k)
                return True
            if blocked(i0, i1, i2, closed):
                continue
            tris.append((a, b, c))
            drop(k)
            return True
        return False

    while len(idx) > 3:
        # a vertex of the remainder that merely touches a candidate ear (a degenerate but
        # simple polygon) blocks the closed test only: then the open test is used
        if not (clip_one(True) or clip_one(False)):  # pragma: no cover - always an ear
            raise RuntimeError("ear clipping failed")
    if len(idx) == 3:
        a, b, c = (pts[j] for j in idx)
        if _cross(b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]) > 0:
            tris.append((a, b, c))
    return np.array(tris, dtype=float).reshape(-1, 3, 2)


def _clip_area(t1: np.ndarray, t2: np.ndarray) -> float:
    """Area of the intersection of two counter-clockwise convex polygons (Sutherland–Hodgman)."""
    out = [tuple(p) for p in t1]
    m = len(t2)
    for i in range(m):
        a, b = t2[i], t2[(i + 1) % m]
        inp, out = out, []
        if not inp:
            break

        ex, ey = b[0] - a[0], b[1] - a[1]
        for j in range(len(inp)):
            p, q = inp[j], inp[(j + 1) % len(inp)]
            sp = _cross(ex, ey, p[0] - a[0], p[1] - a[1])
            sq = _cross(ex, ey, q[0] - a[0], q[1] - a[1])
            if sp >= 0:
                out.append(p)
            if (sp >= 0) != (sq >= 0):
                t = sp / (sp - sq)
                out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    if len(out) < 3:
        return 0.0
    return abs(_signed_area(np.array(out)))


# ---------------------------------------------------------------------------------------------
# the patches


class _Patch:
    """Common properties, all computed from :meth:`to_arrays` (exact for every shape)."""

    __slots__ = ()

    def to_arrays(self) -> FootprintArrays:  # pragma: no cover - abstract
        raise NotImplementedError

    def _raw_arrays(self):  # (edges, circles)
        raise NotImplementedError

    def _cached(self, key, make):
        """A derived value, computed once (the objects are immutable)."""
        cache = self._cache
        if cache is None:
            cache = {}
            object.__setattr__(self, "_cache", cache)
        if key not in cache:
            cache[key] = make()
        return cache[key]

    def _arrays_copy(self) -> FootprintArrays:
        """Fresh copies of the cached arrays (callers may modify theirs)."""
        a = self._cached("arrays", lambda: _arrays(*self._raw_arrays()))
        return FootprintArrays(a.edges.copy(), a.circles.copy(), a.frame.copy())

    def _central(self):
        """(A, r_c, J): moments taken about a point of the footprint, so that a footprint far
        from the body origin loses no digits to cancellation."""
        return self._cached("central", self._central_moments)

    def _central_moments(self):
        e, c = self._raw_arrays()
        pts = np.vstack((e[:, :2], c[:, :2]))
        sx, sy = pts.mean(axis=0)
        a, mx, my, sxx, sxy, syy = _moments(
            e - np.array([sx, sy, sx, sy]), c - np.array([sx, sy, 0.0, 0.0])
        )
        cx, cy = mx / a, my / a
        j = np.array(
            [[sxx - a * cx * cx, sxy - a * cx * cy], [sxy - a * cx * cy, syy - a * cy * cy]]
        )
        return a, (cx + sx, cy + sy), j

    @property
    def area(self) -> float:
        """Area |Ω| [m²]."""
        return self._central()[0]

    @property
    def centroid(self) -> tuple[float, float]:
        """Area centroid r_c in the body frame [m]."""
        cx, cy = self._central()[1]
        return (float(cx), float(cy))

    @property
    def second_moment(self) -> np.ndarray:
        """J = ∫(r − r_c)(r − r_c)ᵀ dS about the area centroid [m⁴], a 2×2 array (MODEL §10)."""
        return self._central()[2]

    @property
    def extent(self) -> float:
        """Largest distance from the area centroid to a point of the footprint [m]: the
        radius of a disk or ring, the half-diagonal of a centred rectangle (a natural length
        unit: it plays the role of the ellipse's a)."""
        return float(self._cached("arrays", lambda: _arrays(*self._raw_arrays())).frame[2])

    @property
    def polar_moment(self) -> float:
        """∫|r − r_c|² dS [m⁴]: the plate inertia of unit areal density about the centroid."""
        j = self.second_moment
        return float(j[0, 0] + j[1, 1])

    def plate_inertia(self, mass: float) -> float:
        """I of a uniform plate of this shape and ``mass`` [kg] about its area centroid
        [kg m²]: m ∫|r − r_c|² dS / A. For pads this is a plate covering the pads only (no
        mass between them); for a linear law, whose G is off the centroid, give I explicitly."""
        m = v.positive("mass", mass, "kg")
        return m * self.polar_moment / self.area


def _moments(edges: np.ndarray, circles: np.ndarray):
    """(A, ∫ξ, ∫η, ∫ξ², ∫ξη, ∫η²) over the footprint [m², m³, m⁴] (shoelace and disk formulas)."""
    x0, y0, x1, y1 = edges.T if len(edges) else (np.zeros(0),) * 4
    cr = x0 * y1 - x1 * y0
    a = 0.5 * cr.sum()
    sx = (cr * (x0 + x1)).sum() / 6.0
    sy = (cr * (y0 + y1)).sum() / 6.0
    sxx = (cr * (x0 * x0 + x0 * x1 + x1 * x1)).sum() / 12.0
    syy = (cr * (y0 * y0 + y0 * y1 + y1 * y1)).sum() / 12.0
    sxy = (cr * (x0 * y1 + 2.0 * x0 * y0 + 2.0 * x1 * y1 + x1 * y0)).sum() / 24.0
    for ox, oy, r, sg in circles:
        ar = sg * math.pi * r * r
        a += ar
        sx += ar * ox
        sy += ar * oy
        sxx += ar * (ox * ox + 0.25 * r * r)
        syy += ar * (oy * oy + 0.25 * r * r)
        sxy += ar * ox * oy
    return float(a), float(sx), float(sy), float(sxx), float(sxy), float(syy)


def _frame(edges: np.ndarray, circles: np.ndarray) -> np.ndarray:
    pts = np.vstack((edges[:, :2], circles[:, :2]))
    px, py = pts.mean(axis=0)
    a, sx, sy, *_ = _moments(edges - np.array([px, py, px, py]), circles - np.array([px, py, 0, 0]))
    ox, oy = px + sx / a, py + sy / a
    ext = 0.0
    if len(edges):
        ext = float(np.max(np.hypot(edges[:, 0] - ox, edges[:, 1] - oy)))
    for cx, cy, r, sg in circles:
        if sg > 0:
            ext = max(ext, math.hypot(cx - ox, cy - oy) + r)
    return np.array([ox, oy, ext])


def _arrays(edges, circles) -> FootprintArrays:
    e = np.ascontiguousarray(np.asarray(edges, dtype=float).reshape(-1, 4))
    c = np.ascontiguousarray(np.asarray(circles, dtype=float).reshape(-1, 4))
    return FootprintArrays(e, c, _frame(e, c))


def _placement(obj) -> None:
    object.__setattr__(obj, "centre", _point("centre", obj.centre))
    object.__setattr__(obj, "angle", v.finite("angle", obj.angle))


@dataclass(frozen=True, slots=True)
class Polygon(_Patch):
    """A simple polygon, convex or not, its vertices in either orientation.

    Parameters
    ----------
    vertices : sequence of (float, float)
        At least 3 and at most :data:`MAX_VERTICES` = 20,000 vertices (ξ, η) [m] in the
        polygon's own frame, in order around the boundary (clockwise or counter-clockwise; the
        closing edge is implied).
    centre : (float, float), default (0, 0)
        Where the polygon's own origin lies in the body frame [m].
    angle : float, default 0
        Rotation of the polygon about its own origin [rad], counter-clockwise.

    Raises
    ------
    ValueError
        Fewer than 3 vertices, a non-finite coordinate, a repeated vertex, a
        self-intersecting boundary or zero area; a size 2R outside [1e-10, 1e6] m (R: largest
        distance of a vertex from the vertices' mean); (2R)²/area above 1e3 + 1e-3 (too
        thin); vertices or centre farther than min(1e6 m, 1e6 R) from the origin.

    Examples
    --------
    >>> Polygon([(0, 0), (2, 0), (2, 1), (0, 1)]).area
    2.0
    """

    vertices: tuple
    centre: tuple = (0.0, 0.0)
    angle: float = 0.0
    _cache: dict | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        try:
            raw = [tuple(p) for p in self.vertices]
        except TypeError:
            raise ValueError(
                f"vertices = {self.vertices!r} is invalid; valid values: a sequence of at "
                "least 3 pairs (xi, eta) in m"
            ) from None
        if len(raw) < 3:
            raise ValueError(
                f"vertices has {len(raw)} point(s); valid range: at least 3 pairs (xi, eta) in m"
            )
        if len(raw) > MAX_VERTICES:
            raise ValueError(
                f"vertices has {len(raw)} points; valid range: at most MAX_VERTICES = "
                f"{MAX_VERTICES} (the wrench costs ~70 ns per edge; simplify the outline)"
            )
        pts = tuple(_point(f"vertices[{i}]", p) for i, p in enumerate(raw))
        object.__setattr__(self, "vertices", pts)
        _placement(self)
        arr = np.array(pts)
        with np.errstate(all="ignore"):  # coordinates near 1e308: an inf or nan size, refused
            radius = float(np.max(np.hypot(*(arr - arr.mean(axis=0)).T)))
        lo, hi = POLYGON_SIZE
        if not lo <= 2.0 * radius <= hi:
            raise ValueError(
                f"vertices: the polygon's size 2R = {2.0 * radius!r} m (R: largest distance of "
                f"a vertex from the vertices' mean) is invalid; valid range: [{lo:g}, {hi:g}] m"
            )
        far = tuple(np.max(np.abs(arr), axis=0).tolist())
        _offset("vertices", far, radius, "polygon", f"vertices: largest |xi|, |eta| = {far!r} m")
        _offset("centre", self.centre, radius, "polygon")
        _check_simple(arr)
        thin = (2.0 * radius) ** 2 / abs(_signed_area(arr))
        if not thin <= MAX_ASPECT + 1.0 / MAX_ASPECT:
            raise ValueError(
                f"vertices: the polygon is too thin: (2R)^2/area = {thin:.6g} (R: largest "
                "distance of a vertex from the vertices' mean; length/width + width/length for "
                f"a rectangle); valid range: <= {MAX_ASPECT + 1.0 / MAX_ASPECT:g}"
            )

    @property
    def points(self) -> np.ndarray:
        """Vertices placed in the body frame [m], shape (n, 2), in the given order."""
        return _place(np.array(self.vertices, dtype=float), self.centre, self.angle)

    def _ccw(self) -> np.ndarray:
        p = self.points
        return p if _signed_area(p) > 0 else p[::-1].copy()

    def _raw_arrays(self):
        return _edges(self._ccw()), np.zeros((0, 4))

    def to_arrays(self) -> FootprintArrays:
        """Plain arrays for the kernel: the edges, counter-clockwise (module notes)."""
        return self._arrays_copy()

    def outline(self) -> np.ndarray:
        """Closed outline (n + 1, 2) in the body frame [m]."""
        p = self.points
        return np.vstack((p, p[:1]))

    def outlines(self, n: int = 181) -> list[np.ndarray]:
        """Closed outlines in the body frame [m] (one here; ``n`` is unused)."""
        return [self.outline()]

    def triangles(self) -> np.ndarray:
        """A triangulation of the polygon (k, 3, 2), counter-clockwise triangles [m]."""
        return _ear_clip(self._ccw())


@dataclass(frozen=True, slots=True)
class Rectangle(_Patch):
    """A rectangle ``length`` × ``width`` centred on its own origin, ``length`` along ξ.

    Parameters
    ----------
    length, width : float
        Side lengths [m]: the longer in [1e-9, 1e6], length/width in [1e-3, 1e3].
    centre : (float, float), default (0, 0)
        Position of the rectangle's centre in the body frame [m], each coordinate within
        min(1e6 m, 1e6 × half-diagonal).
    angle : float, default 0
        Angle of the ``length`` side from the body axis ξ [rad].
    """

    length: float
    width: float
    centre: tuple = (0.0, 0.0)
    angle: float = 0.0
    _cache: dict | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        # the longer side lies in LENGTH, the shorter one within MAX_ASPECT of it
        length = v.bounded("length", self.length, v.LENGTH[0] / MAX_ASPECT, v.LENGTH[1], "m")
        width = v.bounded("width", self.width, v.LENGTH[0] / MAX_ASPECT, v.LENGTH[1], "m")
        object.__setattr__(self, "length", length)
        object.__setattr__(self, "width", width)
        _placement(self)
        if not max(length, width) >= v.LENGTH[0]:
            raise ValueError(
                f"length = {length!r} m and width = {width!r} m are invalid; valid range: the "
                f"longer side in [{v.LENGTH[0]:g}, {v.LENGTH[1]:g}] m"
            )
        if not max(length, width) <= MAX_ASPECT * min(length, width):
            raise ValueError(
                f"length = {length!r} m and width = {width!r} m are invalid: aspect "
                f"{max(length, width) / min(length, width):.6g}; valid range: length/width in "
                f"[{1.0 / MAX_ASPECT:g}, {MAX_ASPECT:g}]"
            )
        _offset("centre", self.centre, 0.5 * math.hypot(length, width), "rectangle")

    def as_polygon(self) -> Polygon:
        """The same rectangle as a :class:`Polygon`."""
        a, b = 0.5 * self.length, 0.5 * self.width
        return Polygon(((-a, -b), (a, -b), (a, b), (-a, b)), self.centre, self.angle)

    def _raw_arrays(self):
        a, b = 0.5 * self.length, 0.5 * self.width
        corners = np.array([(-a, -b), (a, -b), (a, b), (-a, b)])  # counter-clockwise
        return _edges(_place(corners, self.centre, self.angle)), np.zeros((0, 4))

    def to_arrays(self) -> FootprintArrays:
        """Plain arrays for the kernel (module notes)."""
        return self._arrays_copy()

    def outline(self) -> np.ndarray:
        """Closed outline (5, 2) in the body frame [m]."""
        return self.as_polygon().outline()

    def outlines(self, n: int = 181) -> list[np.ndarray]:
        """Closed outlines in the body frame [m]."""
        return [self.outline()]

    def triangles(self) -> np.ndarray:
        """Two counter-clockwise triangles covering the rectangle [m]."""
        return self.as_polygon().triangles()


@dataclass(frozen=True, slots=True)
class Annulus(_Patch):
    """A ring inner_radius ≤ |r − centre| ≤ outer_radius.

    Parameters
    ----------
    inner_radius : float
        Radius of the hole [m], in [0, 1e6] (0: a full disk).
    outer_radius : float
        Outer radius [m], in [1e-9, 1e6] and > ``inner_radius``.
    centre : (float, float), default (0, 0)
        Centre of the ring in the body frame [m], each coordinate within
        min(1e6 m, 1e6 × outer_radius).
    angle : float, default 0
        Accepted for a uniform placement API; a ring does not change when turned.

    Notes
    -----
    For the kernel a ring is a disk minus a disk (``circles`` rows with signs +1 and −1).
    """

    inner_radius: float
    outer_radius: float
    centre: tuple = (0.0, 0.0)
    angle: float = 0.0
    _cache: dict | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        r = v.bounded("inner_radius", self.inner_radius, 0.0, v.LENGTH[1], "m")
        big = _length("outer_radius", self.outer_radius)
        if not big > r:
            raise ValueError(
                f"outer_radius = {big!r} m is invalid; valid range: > inner_radius = {r!r} m"
            )
        object.__setattr__(self, "inner_radius", r)
        object.__setattr__(self, "outer_radius", big)
        _placement(self)
        _offset("centre", self.centre, big, "ring")

    def _raw_arrays(self):
        cx, cy = self.centre
        rows = [(cx, cy, self.outer_radius, 1.0)]
        if self.inner_radius > 0.0:
            rows.append((cx, cy, self.inner_radius, -1.0))
        return np.zeros((0, 4)), np.array(rows, dtype=float)

    def to_arrays(self) -> FootprintArrays:
        """Plain arrays for the kernel: a disk and, if any, the hole with sign −1."""
        return self._arrays_copy()

    def outlines(self, n: int = 181) -> list[np.ndarray]:
        """The outer circle and (if any) the hole, closed, in the body frame [m]."""
        t = np.linspace(0.0, 2.0 * np.pi, n)
        cx, cy = self.centre
        out = [
            np.column_stack(
                (cx + self.outer_radius * np.cos(t), cy + self.outer_radius * np.sin(t))
            )
        ]
        if self.inner_radius > 0.0:
            out.append(
                np.column_stack(
                    (cx + self.inner_radius * np.cos(t), cy + self.inner_radius * np.sin(t))
                )
            )
        return out


@dataclass(frozen=True, slots=True, init=False)
class Disk(Annulus):
    """A full disk of the given ``radius`` [m] (in [1e-9, 1e6]) at ``centre`` (each coordinate
    within min(1e6 m, 1e6 × radius)): an :class:`Annulus` with no hole."""

    def __init__(self, radius: float, centre=(0.0, 0.0), angle: float = 0.0) -> None:
        object.__setattr__(self, "inner_radius", 0.0)
        object.__setattr__(self, "outer_radius", _length("radius", radius))
        object.__setattr__(self, "centre", centre)
        object.__setattr__(self, "angle", angle)
        object.__setattr__(self, "_cache", None)
        _placement(self)
        _offset("centre", self.centre, self.outer_radius, "disk")

    @property
    def radius(self) -> float:
        """Disk radius [m]."""
        return self.outer_radius

    @property
    def a(self) -> float:
        """Semi-axis a = radius [m]: a disk is a circle, so that under the Boussinesq and Hertz
        laws (defined on ellipses and circles, MODEL §3) it runs on the elliptic engine like
        :class:`~slidespin.Circle` (:class:`slidespin.Body`)."""
        return self.outer_radius

    @property
    def b(self) -> float:
        """Semi-axis b = radius [m] (see :attr:`a`)."""
        return self.outer_radius

    def outline(self, n: int = 181) -> np.ndarray:
        """Closed outline (n, 2) in the body frame [m]."""
        return self.outlines(n)[0]

    def __repr__(self) -> str:
        return f"Disk(radius={self.outer_radius!r}, centre={self.centre!r})"


_SIMPLE = (Polygon, Rectangle, Annulus)


def _round_overlap(a: Annulus, b: Annulus) -> bool:
    """Interiors of two rings (disks: inner radius 0) intersect."""
    d = math.hypot(a.centre[0] - b.centre[0], a.centre[1] - b.centre[1])
    a1, a2, b1, b2 = a.inner_radius, a.outer_radius, b.inner_radius, b.outer_radius
    if d == 0.0:
        return max(a1, b1) < min(a2, b2)
    # a point at distances s from a's centre and t from b's exists iff |s − t| ≤ d ≤ s + t:
    # the interiors meet iff that set meets the open box (a1, a2) × (b1, b2) in an open set
    box = np.array([(a1, b1), (a2, b1), (a2, b2), (a1, b2)])
    big = 4.0 * (a2 + b2 + d)
    # the strip |s − t| ≤ d, s + t ≥ d as a convex polygon (large enough to cover the box)
    strip = np.array([(d, 0.0), (big + d, big), (big, big + d), (0.0, d)])
    return _clip_area(box, strip) > 1e-12 * (a2 - a1) * (b2 - b1)


def _polygon_points(p) -> np.ndarray:
    return p._ccw() if isinstance(p, Polygon) else p.as_polygon()._ccw()


def _point_in_polygon(pt, poly: np.ndarray) -> bool:
    """Point in or on the closed polygon (winding test; boundary counts as inside)."""
    x, y = pt
    n = len(poly)
    wn = 0
    for i in range(n):
        ax, ay = poly[i]
        bx, by = poly[(i + 1) % n]
        cr = _cross(bx - ax, by - ay, x - ax, y - ay)
        if (
            abs(cr) <= 1e-14 * (abs(bx - ax) + abs(by - ay)) * (abs(x - ax) + abs(y - ay) + 1e-300)
            and min(ax, bx) <= x <= max(ax, bx)
            and min(ay, by) <= y <= max(ay, by)
        ):
            return True
        if ay <= y < by and cr > 0:
            wn += 1
        elif by <= y < ay and cr < 0:
            wn -= 1
    return wn != 0


def _poly_round_overlap(poly: np.ndarray, ring: Annulus) -> bool:
    """Interiors of a polygon and a ring intersect: the distances from the ring's centre to
    the polygon's points fill an interval (d_min, d_max), which must meet (r_in, r_out)."""
    o = np.array(ring.centre)
    q = np.roll(poly, -1, axis=0)
    dmax = float(np.max(np.hypot(*(poly - o).T)))
    if _point_in_polygon(o, poly):
        dmin = 0.0
    else:
        e = q - poly
        t = np.clip(np.einsum("ij,ij->i", o - poly, e) / np.einsum("ij,ij->i", e, e), 0.0, 1.0)
        near = poly + t[:, None] * e
        dmin = float(np.min(np.hypot(*(near - o).T)))
    return dmin < ring.outer_radius and dmax > ring.inner_radius


def _poly_overlap(p: np.ndarray, q: np.ndarray) -> bool:
    """Interiors of two simple polygons intersect (area of the intersection > 0)."""
    lo = np.maximum(p.min(axis=0), q.min(axis=0))
    hi = np.minimum(p.max(axis=0), q.max(axis=0))
    if np.any(lo >= hi):
        return False
    ta, tb = _ear_clip(p), _ear_clip(q)
    area = 0.0
    for t1 in ta:
        for t2 in tb:
            if np.any(np.maximum(t1.min(0), t2.min(0)) >= np.minimum(t1.max(0), t2.max(0))):
                continue
            area += _clip_area(t1, t2)
    scale = min(abs(_signed_area(p)), abs(_signed_area(q)))
    return area > 1e-10 * scale


def _bbox(p) -> tuple[float, float, float, float]:
    """(ξ_min, η_min, ξ_max, η_max) of a simple patch [m], padded by 1e-12 of its size."""
    if isinstance(p, Annulus):
        r = p.outer_radius * (1.0 + 1e-12)
        return (p.centre[0] - r, p.centre[1] - r, p.centre[0] + r, p.centre[1] + r)
    pts = _polygon_points(p)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 1e-12 * float(np.max(hi - lo))
    return (float(lo[0] - pad), float(lo[1] - pad), float(hi[0] + pad), float(hi[1] + pad))


def _overlap(a, b) -> bool:
    ra, rb = isinstance(a, Annulus), isinstance(b, Annulus)
    if ra and rb:
        return _round_overlap(a, b)
    if ra:
        return _poly_round_overlap(_polygon_points(b), a)
    if rb:
        return _poly_round_overlap(_polygon_points(a), b)
    return _poly_overlap(_polygon_points(a), _polygon_points(b))


@dataclass(frozen=True, slots=True)
class Pads(_Patch):
    """A body resting on several separate patches (feet, runners, pads).

    Parameters
    ----------
    patches : sequence of Polygon, Rectangle, Disk, Annulus or Pads
        At least one patch, each placed in the body frame by its own ``centre``/``angle``;
        nested ``Pads`` are flattened. Their interiors must be disjoint (touching is allowed).

    Raises
    ------
    ValueError
        No patch, a patch of an unknown type, two patches that overlap, or more than
        :data:`MAX_VERTICES` edges and circles in all (a disk or ring counts 4).

    Examples
    --------
    >>> runners = Pads([Rectangle(0.8, 0.02, centre=(0, -0.2)),
    ...                 Rectangle(0.8, 0.02, centre=(0, 0.2))])
    >>> round(runners.area, 6)
    0.032
    """

    patches: tuple = field(default_factory=tuple)
    _cache: dict | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        try:
            items = list(self.patches)
        except TypeError:
            raise ValueError(
                f"patches = {self.patches!r} is invalid; valid values: a sequence of patches"
            ) from None
        flat: list[Polygon | Rectangle | Annulus] = []
        for i, p in enumerate(items):
            if isinstance(p, Pads):
                flat.extend(p.patches)
            elif isinstance(p, _SIMPLE):
                flat.append(p)
            elif isinstance(p, Blade):
                raise ValueError(
                    f"patches[{i}] = {p!r} is invalid: a body on several blades is not "
                    "supported (their load shares); valid values: Polygon, Rectangle, Disk, "
                    "Annulus or Pads (runners: thin Rectangles)"
                )
            else:
                raise ValueError(
                    f"patches[{i}] = {p!r} is invalid; valid values: Polygon, Rectangle, Disk, "
                    "Annulus or Pads"
                )
        if not flat:
            raise ValueError("patches is empty; valid range: at least one patch")
        parts = sum(len(p.vertices) if isinstance(p, Polygon) else 4 for p in flat)
        if parts > MAX_VERTICES:
            raise ValueError(
                f"patches: {len(flat)} patches with {parts} edges and circles in all (a "
                f"rectangle counts 4, a disk or ring 4) is invalid; valid range: at most "
                f"MAX_VERTICES = {MAX_VERTICES} (the wrench costs ~70 ns per edge)"
            )
        # only the pairs whose bounding boxes overlap can overlap: a vectorised sweep
        # (O(k log k) for k pads on a grid) finds them, the exact test decides
        boxes = np.array([_bbox(p) for p in flat])
        pairs = [
            (int(i), int(j))
            for a, b in _pair_candidates(boxes[:, :2], boxes[:, 2:])
            for i, j in zip(a, b)
        ]
        for i, j in sorted(pairs):
            if _overlap(flat[i], flat[j]):
                raise ValueError(
                    f"patches: patch {i} ({flat[i]!r}) and patch {j} ({flat[j]!r}) overlap; "
                    "valid values: disjoint patches (they may touch)"
                )
        object.__setattr__(self, "patches", tuple(flat))

    def _raw_arrays(self):
        es, cs = [], []
        for p in self.patches:
            e, c = p._raw_arrays()
            es.append(e)
            cs.append(c)
        return np.vstack(es).reshape(-1, 4), np.vstack(cs).reshape(-1, 4)

    def to_arrays(self) -> FootprintArrays:
        """Plain arrays for the kernel: every pad's edges and circles in one set."""
        return self._arrays_copy()

    def outlines(self, n: int = 181) -> list[np.ndarray]:
        """Closed outlines of every pad in the body frame [m]."""
        out = []
        for p in self.patches:
            out.extend(p.outlines(n))
        return out


@dataclass(frozen=True, slots=True)
class Blade:
    """A blade: a straight line contact of ``length`` under a uniform line load.

    The b → 0 limit of a uniformly loaded ``Rectangle(length, b)`` (a knife edge, a skate,
    a runner), with the load P spread evenly along the segment |ξ| ≤ length/2, η = 0 of its
    own frame. G lies over its centre (MODEL §10: the pressure centroid). Its wrench is exact
    in closed form (:mod:`slidespin.contact._kernel_blade`).

    Parameters
    ----------
    length : float
        Length L [m], in [1e-9, 1e6].
    centre : (float, float), default (0, 0)
        The blade's centre in the body frame [m], each coordinate within
        min(1e6 m, 1e6 × L/2).
    angle : float, default 0
        Angle of the blade from the body axis ξ [rad], counter-clockwise.

    Notes
    -----
    Uniform line pressure only (``UniformPressure()``); it has no area (``area`` is 0) and
    ``extent`` = L/2; the default body inertia is the thin rod's, m L²/12
    (:meth:`plate_inertia`). For the kernel (``to_arrays``) a blade is one edge
    (ξ₀, η₀, ξ₁, η₁) and no circle: a polygon has at least three edges, so the single edge
    marks a blade. A body on several blades (a sled) is not supported; use thin
    ``Rectangle`` runners in ``Pads``.

    Examples
    --------
    >>> Blade(0.3, centre=(0.0, 0.1)).plate_inertia(2.0)  # m L²/12
    0.015
    """

    length: float
    centre: tuple = (0.0, 0.0)
    angle: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "length", _length("length", self.length))
        _placement(self)
        _offset("centre", self.centre, 0.5 * self.length, "blade")

    @property
    def ends(self) -> np.ndarray:
        """The two ends (2, 2) in the body frame [m], from −ξ to +ξ of the blade's frame."""
        half = 0.5 * self.length
        return _place(np.array([(-half, 0.0), (half, 0.0)]), self.centre, self.angle)

    @property
    def area(self) -> float:
        """0: a line contact has no area [m²]."""
        return 0.0

    @property
    def centroid(self) -> tuple[float, float]:
        """The blade's centre in the body frame [m] (its load centroid)."""
        return (float(self.centre[0]), float(self.centre[1]))

    @property
    def extent(self) -> float:
        """L/2 [m]: the largest distance from the centre to a point of the blade."""
        return 0.5 * self.length

    def plate_inertia(self, mass: float) -> float:
        """I of a thin uniform rod of this length and ``mass`` [kg] about its centre,
        m L²/12 [kg m²]."""
        m = v.positive("mass", mass, "kg")
        return m * self.length * self.length / 12.0

    def to_arrays(self) -> FootprintArrays:
        """Plain arrays for the kernel: one edge (the blade), no circle, frame (centre, L/2)."""
        (x0, y0), (x1, y1) = self.ends
        return FootprintArrays(
            np.array([[x0, y0, x1, y1]]),
            np.zeros((0, 4)),
            np.array([float(self.centre[0]), float(self.centre[1]), 0.5 * self.length]),
        )

    def outline(self, n: int = 2) -> np.ndarray:
        """The segment (2, 2) in the body frame [m] (``n`` is unused)."""
        return self.ends

    def outlines(self, n: int = 2) -> list[np.ndarray]:
        """The segment, as one open curve (2, 2), in the body frame [m]."""
        return [self.ends]


#: any footprint patch (the type of ``Body.patch`` beside ellipses)
Footprint = Polygon | Rectangle | Disk | Annulus | Pads | Blade


def is_footprint(obj) -> bool:
    """True for the footprint types of this module."""
    return isinstance(obj, (Polygon, Rectangle, Annulus, Pads, Blade))


def as_patches(fp) -> tuple:
    """The simple patches (Polygon, Rectangle, Annulus) that make up ``fp``."""
    return fp.patches if isinstance(fp, Pads) else (fp,)
