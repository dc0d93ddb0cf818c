"""The plain-array form of a footprint, and the area moments computed from it (MODEL §10).

``to_arrays()`` of every patch of :mod:`slidespin.contact.shapes` returns a
:class:`FootprintArrays`, the form the compiled kernel (:mod:`slidespin.contact._kernel_footprint`)
reads (a ``Blade``, a line contact, is one edge and no circle, see its notes):

* ``edges``, float64 (n_edges, 4): oriented straight edges (ξ₀, η₀, ξ₁, η₁) [m]. Each
  polygon's edges run counter-clockwise, so that the signed fan of triangles (c, P₀, P₁)
  over all edges, from any apex c, adds up to the polygons' area.
* ``circles``, float64 (n_circles, 4): (ξ_o, η_o, radius, sign) [m]: a disk counted with
  ``sign`` +1, or removed with sign −1 (the hole of a ring: an annulus is a disk minus a
  disk).
* ``frame``, float64 (3,): (ξ_o, η_o, extent): a reference point (the area centroid) and the
  largest distance from it to any point of the footprint [m].

The area moments (A, ∫ξ, ∫η, ∫ξ², ∫ξη, ∫η²) follow exactly from these arrays (shoelace terms
per edge, closed forms per disk), taken about a point of the footprint so that no digits are
lost far from the body origin. ``_Patch``, the base class of the area patches, derives from
them the ``area`` [m²], ``centroid`` [m], ``second_moment`` J = ∫(r − r_c)(r − r_c)ᵀ dS about
the area centroid [m⁴], ``extent`` [m], ``polar_moment`` and ``plate_inertia``.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from slidespin import _validate as v

__all__ = ["FootprintArrays", "linear_load"]


class FootprintArrays(NamedTuple):
    """Plain-array form of a footprint, read by the compiled kernel (see the module notes)."""

    edges: np.ndarray  #: (n, 4) oriented edges ξ₀, η₀, ξ₁, η₁ [m], counter-clockwise
    circles: np.ndarray  #: (m, 4) ξ_o, η_o, radius [m], sign (+1 disk, −1 hole)
    frame: np.ndarray  #: (3,) ξ_o, η_o [m] (area centroid), extent [m]


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
    for ox, oy, big, small in _rings(circles):
        # a disk (small = 0), or a ring: π (R − r)(R + r), without the cancellation of
        # π R² − π r² for a thin ring (a disk with its hole in the next row)
        ar = math.pi * (big - small) * (big + small)
        quarter = 0.25 * (big * big + small * small)  # ∫(ξ − ξ_o)² dS / area
        a += ar
        sx += ar * ox
        sy += ar * oy
        sxx += ar * (ox * ox + quarter)
        syy += ar * (oy * oy + quarter)
        sxy += ar * ox * oy
    return float(a), float(sx), float(sy), float(sxx), float(sxy), float(syy)


def linear_load(arrays: FootprintArrays, p0: float, p1: float, p2: float) -> float:
    """∫(p₀ + p₁ξ + p₂η) dS over the footprint of ``arrays`` (exact: shoelace and disk
    formulas), taken about the mean of its points so that a footprint far from the origin
    loses no digits. The kernel normalises its pressure by this load of the very arrays it
    integrates (a thin ring's width in units of its radius carries ~1e-16 R/(R − r) of
    rounding: the load must be that of the rounded ring)."""
    e, c = arrays.edges, arrays.circles
    pts = np.vstack((e[:, :2], c[:, :2]))
    sx, sy = pts.mean(axis=0)
    a, mx, my, *_ = _moments(e - np.array([sx, sy, sx, sy]), c - np.array([sx, sy, 0.0, 0.0]))
    return float((p0 + p1 * sx + p2 * sy) * a + p1 * mx + p2 * my)


def _rings(circles: np.ndarray):
    """(ξ_o, η_o, R, r) per disk (r = 0) or ring R ≥ ρ ≥ r (a disk and its hole: the next row,
    same centre, sign −1); a lone hole of radius r (sign −1) is (ξ_o, η_o, 0, r)."""
    rows = []
    i, n = 0, len(circles)
    while i < n:
        ox, oy, r, sg = (float(x) for x in circles[i])
        nxt = circles[i + 1] if i + 1 < n else None
        if sg < 0.0:
            rows.append((ox, oy, 0.0, r))
        elif nxt is not None and nxt[3] < 0.0 and nxt[0] == ox and nxt[1] == oy:
            rows.append((ox, oy, r, float(nxt[2])))
            i += 1
        else:
            rows.append((ox, oy, r, 0.0))
        i += 1
    return rows


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
