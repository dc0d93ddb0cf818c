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
kernel (:mod:`slidespin.contact._kernel_footprint`) reads: edges, circles and a frame
(:class:`~slidespin.contact.footprint_arrays.FootprintArrays`, whose module computes the moments
from them). A ``Blade``, a line contact, has no area and no second moment: one edge and no
circle, see its notes. The plane geometry (simplicity check, triangulation, overlap tests) is in
``slidespin.contact._polygon``.

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

import numpy as np

from slidespin import _validate as v
from slidespin.contact._polygon import (
    check_simple,
    ear_clip,
    pair_candidates,
    place,
    poly_overlap,
    poly_round_overlap,
    polygon_edges,
    round_overlap,
    signed_area,
)
from slidespin.contact.footprint_arrays import FootprintArrays, _Patch

__all__ = [
    "Annulus",
    "Circle",
    "Blade",
    "Disk",
    "Footprint",
    "MAX_ASPECT",
    "MAX_OFFSET",
    "MAX_VERTICES",
    "Pads",
    "Polygon",
    "Rectangle",
]


# ---------------------------------------------------------------------------------------------
# validation helpers


def _point(name: str, value) -> tuple[float, float]:
    """A pair of finite real numbers; a string or bytes (whose items are characters or
    character codes, not coordinates) is refused like any other non-pair."""
    bad = f"{name} = {v._short(value)} is invalid; valid values: a pair (xi, eta) of real numbers in m"
    if isinstance(value, (str, bytes, bytearray, memoryview)):
        raise ValueError(bad)
    try:
        seq = tuple(value)
    except TypeError:
        raise ValueError(bad) from None
    if len(seq) != 2:
        raise ValueError(bad)
    out = []
    for i, x in enumerate(seq):
        try:
            out.append(v.finite(f"{name}[{i}]", x))
        except ValueError:
            raise ValueError(
                f"{name}[{i}] = {v._short(x)} ({type(x).__name__}) is invalid; valid values: "
                "a finite real number (a coordinate in m; not a bool or a string)"
            ) from None
    return (out[0], out[1])


#: valid range of ``n``, the number of points of a curved outline (:meth:`Annulus.outlines`)
OUTLINE_POINTS = (2, 1_000_000)


def _outline_points(n) -> int:
    """``n`` of the ``outlines`` methods, an integer in OUTLINE_POINTS (checked for every
    patch, also those whose outline is exact and do not use it)."""
    lo, hi = OUTLINE_POINTS
    if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer)) or not lo <= n <= hi:
        raise ValueError(
            f"n = {v._short(n)} is invalid; valid range: an integer in [{lo}, {hi}] (points "
            "per curved outline)"
        )
    return int(n)


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


def _closes(pts: list[tuple[float, float]]) -> bool:
    """The last vertex repeats the first (to 1e-14 of the outline's size, the tolerance of
    the repeated-vertex check): a closed outline."""
    arr = np.array(pts)
    with np.errstate(all="ignore"):
        scale = float(np.max(np.abs(arr - arr.mean(axis=0))))
    gap = math.hypot(pts[-1][0] - pts[0][0], pts[-1][1] - pts[0][1])
    return gap <= 1e-14 * scale


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


# ---------------------------------------------------------------------------------------------
# the patches


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
        closing edge is implied). A closed outline, whose last vertex repeats the first, is
        accepted: the repeat is dropped. Each vertex is a pair of real numbers (a string,
        bytes or a bool is refused).
    centre : (float, float), default (0, 0)
        Where the polygon's own origin lies in the body frame [m].
    angle : float, default 0
        Rotation of the polygon about its own origin [rad], counter-clockwise.

    Raises
    ------
    ValueError
        Fewer than 3 vertices, a vertex that is not a pair of real numbers, a non-finite
        coordinate, a repeated vertex, a self-intersecting boundary or zero area; a size 2R outside [1e-10, 1e6] m (R: largest
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
        seq = self.vertices
        if isinstance(seq, (str, bytes, bytearray, memoryview)):
            seq = None  # characters are not vertices
        try:
            raw = list(seq)  # type: ignore[arg-type]
        except TypeError:
            raise ValueError(
                f"vertices = {v._short(self.vertices)} is invalid; valid values: a sequence of "
                "at least 3 pairs (xi, eta) of real numbers in m"
            ) from None
        if len(raw) > MAX_VERTICES + 1:  # (+1: a closed outline repeats its first vertex)
            raise ValueError(
                f"vertices has {len(raw)} points; valid range: at most MAX_VERTICES = "
                f"{MAX_VERTICES} (the wrench costs ~70 ns per edge; simplify the outline)"
            )
        pts = [_point(f"vertices[{i}]", p) for i, p in enumerate(raw)]
        if len(pts) >= 3 and _closes(pts):
            pts.pop()  # a closed outline: its last vertex repeats the first
        if len(pts) < 3:
            raise ValueError(
                f"vertices has {len(pts)} distinct point(s); valid range: at least 3 pairs "
                "(xi, eta) in m"
            )
        if len(pts) > MAX_VERTICES:
            raise ValueError(
                f"vertices has {len(pts)} points; valid range: at most MAX_VERTICES = "
                f"{MAX_VERTICES} (the wrench costs ~70 ns per edge; simplify the outline)"
            )
        object.__setattr__(self, "vertices", tuple(pts))
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
        check_simple(arr)
        thin = (2.0 * radius) ** 2 / abs(signed_area(arr))
        if not thin <= MAX_ASPECT + 1.0 / MAX_ASPECT:
            raise ValueError(
                f"vertices: the polygon is too thin: (2R)^2/area = {thin:.6g} (R: largest "
                "distance of a vertex from the vertices' mean; length/width + width/length for "
                f"a rectangle); valid range: <= {MAX_ASPECT + 1.0 / MAX_ASPECT:g}"
            )

    @property
    def points(self) -> np.ndarray:
        """Vertices placed in the body frame [m], shape (n, 2), in the given order."""
        return place(np.array(self.vertices, dtype=float), self.centre, self.angle)

    def _ccw(self) -> np.ndarray:
        p = self.points
        return p if signed_area(p) > 0 else p[::-1].copy()

    def _raw_arrays(self):
        return polygon_edges(self._ccw()), np.zeros((0, 4))

    def to_arrays(self) -> FootprintArrays:
        """Plain arrays for the kernel: the edges, counter-clockwise (module notes)."""
        return self._arrays_copy()

    def outline(self) -> np.ndarray:
        """Closed outline (n + 1, 2) in the body frame [m]."""
        p = self.points
        return np.vstack((p, p[:1]))

    def outlines(self, n: int = 181) -> list[np.ndarray]:
        """Closed outlines in the body frame [m] (one here, exact; ``n``, an integer in
        [2, 1e6], is checked but not needed)."""
        _outline_points(n)
        return [self.outline()]

    def triangles(self) -> np.ndarray:
        """A triangulation of the polygon (k, 3, 2), counter-clockwise triangles [m]."""
        return ear_clip(self._ccw())


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
        return polygon_edges(place(corners, self.centre, self.angle)), np.zeros((0, 4))

    def to_arrays(self) -> FootprintArrays:
        """Plain arrays for the kernel (module notes)."""
        return self._arrays_copy()

    def outline(self) -> np.ndarray:
        """Closed outline (5, 2) in the body frame [m]."""
        return self.as_polygon().outline()

    def outlines(self, n: int = 181) -> list[np.ndarray]:
        """Closed outlines in the body frame [m] (one, exact; ``n``, an integer in [2, 1e6],
        is checked but not needed)."""
        _outline_points(n)
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
        """The outer circle and (if any) the hole, closed, in the body frame [m]; ``n`` points
        each, an integer in [2, 1e6]."""
        t = np.linspace(0.0, 2.0 * np.pi, _outline_points(n))
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
    within min(1e6 m, 1e6 × radius)): an :class:`Annulus` with no hole.

    ``Circle`` is the same class (``Circle(0.1)`` is ``Disk(0.1)``): the paper's circular patch.
    Under uniform or linear pressure a disk runs on the exact footprint kernel (closed forms,
    MODEL §10); under Boussinesq or Hertz pressure (defined on circles, MODEL §3) on the
    elliptic engine, as the circle of its radius with G at its centre. ``Ellipse(r, r)`` is the
    paper's circle on the paper's engine (the elliptic quadrature) under every law.
    """

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
        ``Ellipse(radius, radius)`` (:class:`slidespin.Body`)."""
        return self.outer_radius

    @property
    def b(self) -> float:
        """Semi-axis b = radius [m] (see :attr:`a`)."""
        return self.outer_radius

    def outline(self, n: int = 181) -> np.ndarray:
        """Closed outline (n, 2) in the body frame [m]; n an integer in [2, 1e6]."""
        return self.outlines(n)[0]

    def __repr__(self) -> str:
        return f"Disk(radius={self.outer_radius!r}, centre={self.centre!r})"


#: The paper's circular patch: the same class as :class:`Disk` (``Circle(radius)`` is
#: ``Disk(radius)``, centred at the body origin C). One class, two names: the paper and its
#: Table 2 speak of circles, footprints of disks.
Circle = Disk

_SIMPLE = (Polygon, Rectangle, Annulus)


def _polygon_points(p) -> np.ndarray:
    return p._ccw() if isinstance(p, Polygon) else p.as_polygon()._ccw()


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
        return round_overlap(a, b)
    if ra:
        return poly_round_overlap(_polygon_points(b), a)
    if rb:
        return poly_round_overlap(_polygon_points(a), b)
    return poly_overlap(_polygon_points(a), _polygon_points(b))


@dataclass(frozen=True, slots=True, init=False)
class Pads(_Patch):
    """A body resting on several separate patches (feet, runners, pads).

    ``Pads(p1, p2, ...)``, ``Pads([p1, p2, ...])`` and ``Pads(patches=[p1, p2, ...])`` are
    the same.

    Parameters
    ----------
    *patches : Polygon, Rectangle, Disk, Annulus or Pads, or one sequence of them
        At least one patch, each placed in the body frame by its own ``centre``/``angle``;
        nested ``Pads`` are flattened. Their interiors must be disjoint (touching is allowed).
        The keyword ``patches=`` takes the sequence instead.

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
    >>> feet = Pads(Disk(0.01, centre=(0.0, 0.1)), Disk(0.01, centre=(0.0, -0.1)))
    >>> round(feet.area / (2 * math.pi * 0.01**2), 12)
    1.0
    """

    patches: tuple = field(default_factory=tuple)
    _cache: dict | None = field(default=None, init=False, repr=False, compare=False)

    def __init__(self, *args, patches=None) -> None:
        if patches is not None and args:
            raise ValueError(
                f"Pads got {len(args)} positional argument(s) and patches = "
                f"{v._short(patches)}; valid values: the patches either positionally, "
                "Pads(p1, p2, ...), or as one sequence, Pads([p1, p2, ...]) or "
                "Pads(patches=[p1, p2, ...])"
            )
        if patches is None:
            # one sequence (the list form), or the patches themselves
            one = (
                len(args) == 1
                and hasattr(args[0], "__iter__")
                and not isinstance(args[0], (_Patch, Blade, str, bytes, bytearray))
            )
            patches = args[0] if one else args
        object.__setattr__(self, "patches", patches)
        object.__setattr__(self, "_cache", None)
        self.__post_init__()

    def __post_init__(self) -> None:
        if isinstance(self.patches, (str, bytes, bytearray)):
            items = None
        else:
            try:
                items = list(self.patches)
            except TypeError:
                items = None
        if items is None:
            raise ValueError(
                f"patches = {v._short(self.patches)} is invalid; valid values: patches "
                "(Polygon, Rectangle, Disk, Annulus or Pads), as Pads(p1, p2, ...) or "
                "Pads([p1, p2, ...])"
            )
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
            raise ValueError("patches is empty; valid range: at least one patch, Pads(p1, p2, ...)")
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
            for a, b in pair_candidates(boxes[:, :2], boxes[:, 2:])
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
        """Closed outlines of every pad in the body frame [m], ``n`` points per curved one
        (an integer in [2, 1e6])."""
        _outline_points(n)
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
        return place(np.array([(-half, 0.0), (half, 0.0)]), self.centre, self.angle)

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
        """The segment (2, 2) in the body frame [m] (``n``, an integer in [2, 1e6], is checked
        but not needed)."""
        _outline_points(n)
        return self.ends

    def outlines(self, n: int = 2) -> list[np.ndarray]:
        """The segment, as one open curve (2, 2), in the body frame [m] (``n`` as in
        :meth:`outline`)."""
        return [self.outline(n)]


#: any footprint patch (the type of ``Body.patch`` beside ellipses)
Footprint = Polygon | Rectangle | Disk | Annulus | Pads | Blade


def is_footprint(obj) -> bool:
    """True for the footprint types of this module."""
    return isinstance(obj, (Polygon, Rectangle, Annulus, Pads, Blade))


def as_patches(fp) -> tuple:
    """The simple patches (Polygon, Rectangle, Annulus) that make up ``fp``."""
    return fp.patches if isinstance(fp, Pads) else (fp,)
