"""The body's contact outline: the convex curve a pusher touches, and its geometry (MODEL §13).

A pusher meets the body on its outline ∂B: by default the convex hull of the footprint (of
all the pads of a ``Pads``), or the ellipse itself for an elliptic patch, or the circle of a
disk or ring; a body wider than its patch gives its own ``outline=`` (a polygon or an
ellipse). MODEL §13 symbols and code names:

=========  ==========================================  ===================================
MODEL      meaning                                     code
=========  ==========================================  ===================================
∂B         the outline                                 :class:`Outline`
c          a contact point on ∂B                       ``closest(...)[0]``
n          the inward unit normal at c                 ``closest(...)[1]``
t = ẑ × n  the tangent at c                            :func:`tangent`
gap        the signed distance of a point from ∂B      ``closest(...)[2]`` (> 0 outside)
=========  ==========================================  ===================================

**Frames.** Footprints, ``Load.at`` and a user ``outline=`` are given in the body frame C ξ η
(measured from the patch centre C, MODEL §1). The state (x, y, φ) of :class:`slidespin.State`
is the position of the mass centre G and the angle of the body axis Cξ. So an
:class:`Outline` stores its geometry **relative to G**, in the body's orientation: a plane
point P of a body at (x, y, φ) is the outline point r = R(−φ)(P − (x, y)) (:func:`from_plane`,
:func:`to_plane`), and a body-frame point r_C is r = r_C − r_G (:meth:`Outline.from_body`).
G lies over the area centroid for uniform pressure, at (ξc, ηc) for the linear law
(:attr:`slidespin.Body.mass_centre`).

**Shapes.** An outline is either an ellipse (centre, semi-axes, angle; a circle has equal
axes) or the convex hull of a finite set of discs (centre, radius ≥ 0): a polygon is the
hull of discs of radius 0 (its vertices), and pads that include disks give a hull of
straight tangent segments and circular arcs. Every query is exact to round-off: the
distance to an ellipse is Eberly's bisection on the root of a monotone function (D. Eberly,
"Distance from a point to an ellipse, an ellipsoid or a hyperellipsoid", 2013), carried to
round-off; everything else is closed form. Pure NumPy, no compiled code.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from slidespin import _validate as v
from slidespin.contact import shapes as _fp
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse

__all__ = ["Outline", "body_outline", "from_plane", "tangent", "to_plane"]

TWO_PI = 2.0 * math.pi


def _u(angle: float) -> NDArray[np.float64]:
    return np.array([math.cos(angle), math.sin(angle)])


def _ccw(a: float, b: float) -> float:
    """The counter-clockwise turn from angle a to angle b, in [0, 2π)."""
    d = math.fmod(b - a, TWO_PI)
    return d + TWO_PI if d < 0.0 else d


def tangent(normal: ArrayLike) -> NDArray[np.float64]:
    """t = ẑ × n = (−n_y, n_x) (MODEL §13): the normal turned by +90°; shape (2,) or (n, 2)."""
    n = np.asarray(normal, dtype=float)
    return np.stack((-n[..., 1], n[..., 0]), axis=-1)


def to_plane(points: ArrayLike, x: float, y: float, phi: float) -> NDArray[np.float64]:
    """Outline points r (relative to G, body orientation) in the plane frame for a body at
    (x, y, φ): (x, y) + R(φ) r. Shape (2,) or (n, 2)."""
    p = np.asarray(points, dtype=float)
    c, s = math.cos(phi), math.sin(phi)
    return np.stack((x + c * p[..., 0] - s * p[..., 1], y + s * p[..., 0] + c * p[..., 1]), -1)


def from_plane(points: ArrayLike, x: float, y: float, phi: float) -> NDArray[np.float64]:
    """Plane points P as outline points r = R(−φ)(P − (x, y)) of a body at (x, y, φ)."""
    p = np.asarray(points, dtype=float)
    c, s = math.cos(phi), math.sin(phi)
    dx, dy = p[..., 0] - x, p[..., 1] - y
    return np.stack((c * dx + s * dy, -s * dx + c * dy), axis=-1)


def _point(name: str, value: object) -> NDArray[np.float64]:
    """A finite pair (shape (2,)), no bools or strings."""
    if isinstance(value, (bool, np.bool_, str, bytes)):
        raise ValueError(
            f"{name} = {v._short(value)} is invalid; valid values: a pair of finite numbers [m]"
        )
    if isinstance(value, (list, tuple)) and any(isinstance(x, (bool, np.bool_)) for x in value):
        raise ValueError(f"{name} = {v._short(value)} is invalid: a bool is not a coordinate")
    arr = v.real_array(name, value, unit="m")
    if arr.shape != (2,):
        raise ValueError(f"{name} has shape {arr.shape}; valid values: a pair (x, y) [m]")
    return arr


# ------------------------------------------------------------------------------------------
# convex hulls


def _hull_points(pts: NDArray[np.float64]) -> NDArray[np.float64]:
    """Andrew's monotone chain: the convex hull's vertices, counter-clockwise, collinear and
    repeated points dropped."""
    p = np.unique(pts, axis=0)  # sorted by x, then y
    if len(p) < 3:
        return p

    def half(seq):
        out: list[NDArray[np.float64]] = []
        for q in seq:
            while len(out) >= 2:
                a, b = out[-2], out[-1]
                if (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) <= 0.0:
                    out.pop()
                else:
                    break
            out.append(q)
        return out

    lower, upper = half(p), half(p[::-1])
    return np.array(lower[:-1] + upper[:-1])


def _disc_hull(discs: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Convex hull of discs (cx, cy, r ≥ 0) by gift wrapping: the hull discs in
    counter-clockwise order and, for each, the outward-normal angle ψ_k of the tangent
    segment from it to the next one."""
    d = np.unique(discs, axis=0)
    keep = []
    for i in range(len(d)):  # drop discs inside another one
        inside = False
        for j in range(len(d)):
            if i != j:
                gap = math.hypot(*(d[i, :2] - d[j, :2])) + d[i, 2]
                if gap <= d[j, 2] and (gap < d[j, 2] or j < i or d[i, 2] < d[j, 2]):
                    inside = True
                    break
        if not inside:
            keep.append(i)
    d = d[keep]
    if len(d) == 1:
        return d, np.array([-0.5 * math.pi])
    low = d[:, 1] - d[:, 2]
    start = int(np.lexsort((d[:, 0], low))[0])  # lowest, then leftmost
    hull, angles = [start], []
    theta, cur = -0.5 * math.pi, start
    for _ in range(2 * len(d) + 2):
        best, best_turn, best_far, best_psi = -1, math.inf, -1.0, 0.0
        for j in range(len(d)):
            if j == cur:
                continue
            dx, dy = d[j, 0] - d[cur, 0], d[j, 1] - d[cur, 1]
            dist = math.hypot(dx, dy)
            psi = math.atan2(dy, dx) - math.acos(max(-1.0, min(1.0, (d[cur, 2] - d[j, 2]) / dist)))
            turn = _ccw(theta, psi)
            if turn > TWO_PI - 1e-12:  # round-off of a zero turn
                turn = 0.0
            if turn < best_turn - 1e-14 or (abs(turn - best_turn) <= 1e-14 and dist > best_far):
                best, best_turn, best_far, best_psi = j, turn, dist, psi
        angles.append(best_psi)
        theta, cur = best_psi, best
        if cur == start:
            break
        hull.append(cur)
    return d[hull], np.array(angles)


# ------------------------------------------------------------------------------------------
# the outline


@dataclass(frozen=True, slots=True, eq=False)
class Outline:
    """A convex outline relative to the mass centre G, in the body's orientation.

    Build it with :func:`body_outline`. Two kinds:

    * ``kind == "ellipse"``: ``centre`` (relative to G), ``axes`` (a, b) [m] and
      ``angle`` [rad] of the a-axis from the body axis ξ (a circle: a = b);
    * ``kind == "hull"``: the convex hull of the discs ``discs`` (k, 3) rows
      (cx, cy, r) [m], r ≥ 0, counter-clockwise; a polygon has r = 0 for all rows (its
      vertices, :attr:`vertices`). ``edge_angles`` [rad]: the outward normal angle of the
      straight segment from disc k to disc k + 1 (a polygon's edges).

    Attributes
    ----------
    mass_centre : ndarray (2,)
        G in the body frame C ξ η [m] (the offset between body-frame and outline points).
    """

    kind: str
    mass_centre: NDArray[np.float64]
    discs: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 3)))
    edge_angles: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    centre: NDArray[np.float64] = field(default_factory=lambda: np.zeros(2))
    axes: tuple[float, float] = (0.0, 0.0)
    angle: float = 0.0
    _poly: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 2)), repr=False)

    # ---------------------------------------------------------------- descriptive
    @property
    def is_polygon(self) -> bool:
        """True for a hull of points (a convex polygon)."""
        return self.kind == "hull" and bool(np.all(self.discs[:, 2] == 0.0))

    @property
    def vertices(self) -> NDArray[np.float64]:
        """A polygon's vertices (k, 2) relative to G, counter-clockwise [m] (for a hull with
        round parts: the centres of its discs)."""
        return self.discs[:, :2].copy()

    @property
    def edges(self) -> NDArray[np.float64]:
        """The straight segments (k, 2, 2) of a hull, from disc k to disc k + 1, counter-
        clockwise [m] (a polygon's edges; tangent segments between discs); (0, 2, 2) for an
        ellipse."""
        if self.kind != "hull":
            return np.zeros((0, 2, 2))
        n = np.column_stack((np.cos(self.edge_angles), np.sin(self.edge_angles)))
        nxt = np.roll(self.discs, -1, axis=0)
        a = self.discs[:, :2] + self.discs[:, 2:3] * n
        b = nxt[:, :2] + nxt[:, 2:3] * n
        return np.stack((a, b), axis=1)

    @property
    def edge_normals(self) -> NDArray[np.float64]:
        """Inward unit normals (k, 2) of ``edges``."""
        return -np.column_stack((np.cos(self.edge_angles), np.sin(self.edge_angles)))

    def normal_cone(self, index: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The outward normal cone at hull vertex (disc) ``index``: the outward unit normals
        of the edge arriving at it and of the edge leaving it, in counter-clockwise order.
        Every outward normal of the outline at that vertex (of the arc, for a disc) lies
        between them, counter-clockwise."""
        if self.kind != "hull":
            raise ValueError("normal_cone: an ellipse has no vertices; valid for kind 'hull'")
        k = len(self.discs)
        if (
            isinstance(index, (bool, np.bool_))
            or not isinstance(index, (int, np.integer))
            or not -k <= index < k
        ):
            raise ValueError(
                f"index = {v._short(index)} is invalid; valid range: an integer in [0, {k - 1}]"
            )
        i = int(index) % k
        return _u(float(self.edge_angles[i - 1])), _u(float(self.edge_angles[i]))

    def from_body(self, points: ArrayLike) -> NDArray[np.float64]:
        """Body-frame points (from the patch centre C) as outline points (from G): r − r_G."""
        return np.asarray(points, dtype=float) - self.mass_centre

    def to_body(self, points: ArrayLike) -> NDArray[np.float64]:
        """Outline points (from G) as body-frame points (from C): r + r_G."""
        return np.asarray(points, dtype=float) + self.mass_centre

    def boundary(self, n: int = 181) -> NDArray[np.float64]:
        """Closed curve of points along the outline relative to G (for plotting; exact at
        the vertices, ``n`` points per full turn of a curved part)."""
        if self.kind == "ellipse":
            t = np.linspace(0.0, TWO_PI, n)
            return self._from_local(
                np.column_stack((self.axes[0] * np.cos(t), self.axes[1] * np.sin(t)))
            )
        out = []
        for k in range(len(self.discs)):
            cx, cy, r = self.discs[k]
            a0, a1 = float(self.edge_angles[k - 1]), float(self.edge_angles[k])
            m = max(2, int(math.ceil(n * _ccw(a0, a1) / TWO_PI))) if r > 0 else 1
            ts = a0 + np.linspace(0.0, _ccw(a0, a1), m)
            out.append(np.column_stack((cx + r * np.cos(ts), cy + r * np.sin(ts))))
        pts = np.vstack(out)
        return np.vstack((pts, pts[:1]))

    # ---------------------------------------------------------------- ellipse frame
    def _to_local(self, p: NDArray[np.float64]) -> NDArray[np.float64]:
        c, s = math.cos(self.angle), math.sin(self.angle)
        dx, dy = p[..., 0] - self.centre[0], p[..., 1] - self.centre[1]
        return np.stack((c * dx + s * dy, -s * dx + c * dy), axis=-1)

    def _from_local(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        c, s = math.cos(self.angle), math.sin(self.angle)
        return np.stack(
            (
                self.centre[0] + c * q[..., 0] - s * q[..., 1],
                self.centre[1] + s * q[..., 0] + c * q[..., 1],
            ),
            axis=-1,
        )

    def _rotate(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        c, s = math.cos(self.angle), math.sin(self.angle)
        return np.array([c * q[0] - s * q[1], s * q[0] + c * q[1]])

    # ---------------------------------------------------------------- queries
    def contains(self, point: ArrayLike) -> bool:
        """True if ``point`` (relative to G) lies in the closed region bounded by the outline."""
        return self.closest(point)[2] <= 0.0

    def closest(self, point: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64], float]:
        """The outline point nearest to ``point`` (relative to G), the inward unit normal
        there, and the signed gap (the distance, > 0 outside, < 0 inside) [m].

        For a point outside, the inward normal is the unit vector from the point to the
        nearest outline point (at a vertex: inside its normal cone). At a polygon vertex met
        exactly, the normal of one of the two edges is returned (:meth:`normal_cone` gives
        both)."""
        p = _point("point", point)
        if self.kind == "ellipse":
            return self._closest_ellipse(p)
        return self._closest_hull(p)

    def _closest_hull(self, p):
        best_d, best_q, best_n = math.inf, p, np.zeros(2)
        for (a, b), ang in zip(self.edges, self.edge_angles):
            ab = b - a
            ll = float(ab @ ab)
            s = 0.0 if ll == 0.0 else min(1.0, max(0.0, float((p - a) @ ab) / ll))
            q = a + s * ab
            d = math.hypot(*(p - q))
            if d < best_d:
                best_d, best_q, best_n = d, q, -_u(float(ang))
        for k in range(len(self.discs)):
            c, r = self.discs[k, :2], float(self.discs[k, 2])
            rel = p - c
            rho = math.hypot(*rel)
            if rho == 0.0:
                continue
            phi = math.atan2(rel[1], rel[0])
            a0, a1 = float(self.edge_angles[k - 1]), float(self.edge_angles[k])
            if _ccw(a0, phi) <= _ccw(a0, a1):
                d = abs(rho - r)
                if d <= best_d:  # a tie with an edge's end: the arc's (the cone's) normal
                    u = rel / rho
                    best_d, best_q, best_n = d, c + r * u, -u
        inside = self._inside(p)
        return best_q, best_n, (-best_d if inside and best_d > 0.0 else best_d)

    def _inside(self, p) -> bool:
        poly = self._poly
        if len(poly) >= 3:
            e = np.roll(poly, -1, axis=0) - poly
            w = p - poly
            cr = e[:, 0] * w[:, 1] - e[:, 1] * w[:, 0]
            scale = np.hypot(e[:, 0], e[:, 1])
            if np.all(cr >= -1e-15 * scale * (np.abs(w).max() + np.abs(poly).max())):
                return True
        r = self.discs[:, 2]
        rho = np.hypot(p[0] - self.discs[:, 0], p[1] - self.discs[:, 1])
        return bool(np.any((r > 0.0) & (rho <= r)))

    def _closest_ellipse(self, p):
        a, b = self.axes
        q = self._to_local(p)
        x, n_out, dist, inside = _ellipse_closest(a, b, float(q[0]), float(q[1]))
        point = self._from_local(x)
        normal = -self._rotate(n_out)
        return point, normal, (-dist if inside and dist > 0.0 else dist)

    def support(self, direction: ArrayLike) -> NDArray[np.float64]:
        """The outline point farthest along ``direction`` (relative to G) [m]."""
        d = _point("direction", direction)
        norm = math.hypot(*d)
        if norm == 0.0:
            raise ValueError("direction = (0, 0) is invalid; valid values: a non-zero vector")
        d = d / norm
        if self.kind == "ellipse":
            a, b = self.axes
            c, s = math.cos(self.angle), math.sin(self.angle)
            lx, ly = c * d[0] + s * d[1], -s * d[0] + c * d[1]
            h = math.hypot(a * lx, b * ly)
            return self._from_local(np.array([a * a * lx / h, b * b * ly / h]))
        k = int(np.argmax(self.discs[:, :2] @ d + self.discs[:, 2]))
        return self.discs[k, :2] + self.discs[k, 2] * d

    def entry(self, start: ArrayLike, end: ArrayLike) -> float | None:
        """The first fraction s in [0, 1] at which the point start + s (end − start) (both
        relative to G) lies in the closed region of the outline: 0 if ``start`` is already
        in it, None if the segment misses it. The entry point is on the outline; its
        :meth:`closest` gives the normal there."""
        p0, p1 = _point("start", start), _point("end", end)
        d = p1 - p0
        if self.kind == "ellipse":
            a, b = self.axes
            q0 = self._to_local(p0) / np.array([a, b])
            c, s = math.cos(self.angle), math.sin(self.angle)
            dq = np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]]) / np.array([a, b])
            return _disc_entry(q0, dq, np.zeros(2), 1.0)
        best = _polygon_entry(self._poly, p0, d) if len(self._poly) >= 3 else None
        for cx, cy, r in self.discs:
            if r > 0.0:
                hit = _disc_entry(p0, d, np.array([cx, cy]), float(r))
                if hit is not None and (best is None or hit < best):
                    best = hit
        return best

    def __repr__(self) -> str:
        g = tuple(round(float(x), 12) for x in self.mass_centre)
        if self.kind == "ellipse":
            return (
                f"Outline(ellipse: centre={tuple(self.centre.tolist())}, axes={self.axes}, "
                f"angle={self.angle!r}; G at {g} in the body frame)"
            )
        what = "polygon" if self.is_polygon else "hull of discs"
        return f"Outline({what} with {len(self.discs)} vertices; G at {g} in the body frame)"


def _disc_entry(p0, d, c, r) -> float | None:
    """First s in [0, 1] with |p0 + s d − c| ≤ r (stable quadratic), or None."""
    w = p0 - c
    cc = float(w @ w) - r * r
    if cc <= 0.0:
        return 0.0
    aa = float(d @ d)
    bb = float(w @ d)
    if aa == 0.0 or bb >= 0.0:
        return None
    disc = bb * bb - aa * cc
    if disc < 0.0:
        return None
    s = cc / (-bb + math.sqrt(disc))  # the smaller root, without cancellation
    return s if s <= 1.0 else None


def _polygon_entry(poly, p0, d) -> float | None:
    """Cyrus–Beck: the first s in [0, 1] at which p0 + s d enters a convex CCW polygon."""
    lo, hi = 0.0, 1.0
    e = np.roll(poly, -1, axis=0) - poly
    for k in range(len(poly)):
        n = np.array([e[k, 1], -e[k, 0]])  # outward (CCW polygon)
        num = float(n @ (p0 - poly[k]))  # > 0: outside this edge
        den = float(n @ d)
        if den == 0.0:
            if num > 0.0:
                return None
            continue
        s = -num / den
        if den < 0.0:
            lo = max(lo, s)
        else:
            hi = min(hi, s)
        if lo > hi:
            return None
    return lo


def _ellipse_closest(a: float, b: float, y0: float, y1: float):
    """Nearest point of the ellipse x²/a² + y²/b² = 1 to (y0, y1): (point, outward unit
    normal there, distance, inside). Eberly's bisection, to round-off."""
    swap = b > a
    if swap:
        a, b, y0, y1 = b, a, y1, y0
    s0, s1 = (1.0 if y0 >= 0.0 else -1.0), (1.0 if y1 >= 0.0 else -1.0)
    z0, z1 = abs(y0), abs(y1)
    inside = (z0 / a) ** 2 + (z1 / b) ** 2 <= 1.0
    if z1 > 0.0:
        if z0 > 0.0:
            # Eberly's root: F(s) = (r0 n0/(s + r0))² + (n1/(s + 1))² − 1 = 0, r0 = (a/b)²,
            # n = (z0/a, z1/b); F decreases on s > −1, its root lies in [n1 − 1, hi]
            r0 = (a / b) ** 2
            n0, n1 = z0 / a, z1 / b
            g = n0 * n0 + n1 * n1 - 1.0
            if g != 0.0:
                lo = n1 - 1.0
                hi = math.hypot(r0 * n0, n1) - 1.0 if g > 0.0 else 0.0
                s = 0.0
                for _ in range(400):
                    s = 0.5 * (lo + hi)
                    if s == lo or s == hi:
                        break
                    ra, rb = r0 * n0 / (s + r0), n1 / (s + 1.0)
                    val = ra * ra + rb * rb - 1.0
                    if val > 0.0:
                        lo = s
                    elif val < 0.0:
                        hi = s
                    else:
                        break
                x0, x1 = r0 * z0 / (s + r0), z1 / (s + 1.0)
            else:
                x0, x1 = z0, z1
        else:
            x0, x1 = 0.0, b
    else:
        num, den = a * z0, a * a - b * b
        if num < den:
            xd = num / den
            x0, x1 = a * xd, b * math.sqrt(max(0.0, 1.0 - xd * xd))
        else:
            x0, x1 = a, 0.0
    dist = math.hypot(z0 - x0, z1 - x1)
    nx, ny = x0 / (a * a), x1 / (b * b)
    h = math.hypot(nx, ny)
    pt = np.array([s0 * x0, s1 * x1])
    nrm = np.array([s0 * nx / h, s1 * ny / h])
    if swap:
        pt, nrm = pt[::-1].copy(), nrm[::-1].copy()
    return pt, nrm, dist, inside


# ------------------------------------------------------------------------------------------
# building the outline of a body


def _footprint_discs(patch) -> NDArray[np.float64]:
    rows = []
    for p in _fp.as_patches(patch):
        if isinstance(p, _fp.Annulus):
            rows.append((float(p.centre[0]), float(p.centre[1]), float(p.outer_radius)))
        elif isinstance(p, _fp.Rectangle):
            rows.extend((x, y, 0.0) for x, y in p.as_polygon().points)
        else:
            rows.extend((x, y, 0.0) for x, y in p.points)
    return np.array(rows, dtype=float)


def _hull_outline(discs: NDArray[np.float64], g: NDArray[np.float64]) -> Outline:
    d = discs.copy()
    d[:, :2] -= g
    if np.all(d[:, 2] == 0.0):
        pts = _hull_points(d[:, :2])
        if len(pts) < 3:
            raise ValueError(
                "outline: the points span no area; valid values: a polygon of area > 0"
            )
        e = np.roll(pts, -1, axis=0) - pts
        angles = np.arctan2(-e[:, 0], e[:, 1])  # outward normal (e_y, −e_x) of a CCW edge
        hull = np.column_stack((pts, np.zeros(len(pts))))
        return Outline("hull", g, hull, angles, _poly=pts)
    hull, angles = _disc_hull(d)
    if len(hull) == 1:
        return Outline("ellipse", g, centre=hull[0, :2].copy(), axes=(float(hull[0, 2]),) * 2)
    n = np.column_stack((np.cos(angles), np.sin(angles)))
    a = hull[:, :2] + hull[:, 2:3] * n
    b = np.roll(hull[:, :2], -1, axis=0) + np.roll(hull[:, 2:3], -1, axis=0) * n
    pts = np.vstack([np.vstack((p, q)) for p, q in zip(a, b)])
    poly = _hull_points(pts)
    return Outline("hull", g, hull, angles, _poly=poly)


def body_outline(body, outline: object = None) -> Outline:
    """The outline ∂B a pusher touches (MODEL §13), relative to the mass centre G.

    Parameters
    ----------
    body : slidespin.Body
        The body. By default its outline is its patch's: an ``Ellipse`` itself, the circle of
        a ``Disk`` or ``Annulus``, the convex hull of a ``Polygon`` or ``Rectangle`` (a
        concave polygon's notches are bridged: a pusher cannot reach into them in this
        model), the convex hull of all the pads of ``Pads`` (straight segments and circular
        arcs where disks are on the hull). A ``Blade`` has no area: give ``outline``.
    outline : None, array_like (n, 2), Polygon, Rectangle, Disk, Annulus or Ellipse
        A body wider than its patch: its outline in the body frame C ξ η [m] (like a
        footprint's vertices): a polygon's vertices (its convex hull is used), a footprint
        object, or an ``Ellipse`` (centred at C, a along ξ). G must lie strictly inside it.

    Returns
    -------
    Outline
    """
    if not isinstance(body, Body):
        raise ValueError(f"body = {v._short(body)} is invalid; valid values: a slidespin.Body")
    g = np.array(body.mass_centre, dtype=float)
    shape = body.patch if outline is None else outline
    if isinstance(shape, Ellipse):
        out = Outline("ellipse", g, centre=-g, axes=(shape.a, shape.b))
    elif isinstance(shape, _fp.Blade):
        raise ValueError(
            "body.patch is a Blade (a line contact, no area): give outline=, a polygon or an "
            "Ellipse around it in the body frame [m]"
        )
    elif _fp.is_footprint(shape):
        out = _hull_outline(_footprint_discs(shape), g)
    else:
        name = "outline"
        if not isinstance(shape, (list, tuple, np.ndarray)):
            raise ValueError(
                f"{name} = {v._short(shape)} is invalid; valid values: None, vertices (n, 2) "
                "[m], a Polygon, Rectangle, Disk, Annulus or an Ellipse"
            )
        if isinstance(shape, (str, bytes)) or (
            isinstance(shape, (list, tuple))
            and any(
                isinstance(x, (bool, np.bool_))
                for row in shape
                for x in (row if isinstance(row, (list, tuple)) else [row])
            )
        ):
            raise ValueError(
                f"{name} = {v._short(shape)} is invalid (a bool or a string is not a "
                "coordinate); valid values: None, vertices (n, 2) [m], a Polygon, Rectangle, Disk, Annulus or an Ellipse"
            )
        pts = v.real_array(name, shape, unit="m")
        if pts.ndim != 2 or pts.shape[1] != 2 or pts.shape[0] < 3:
            raise ValueError(
                f"{name} has shape {pts.shape}; valid values: None, vertices (n, 2) with n >= 3 "
                "[m], a Polygon, Rectangle, Disk, Annulus or an Ellipse"
            )
        out = _hull_outline(np.column_stack((pts, np.zeros(len(pts)))), g)
    gap = out.closest(np.zeros(2))[2]
    if not gap < 0.0:
        raise ValueError(
            f"outline = {v._short(shape)} is invalid: the mass centre G = {tuple(g.tolist())} "
            "is not inside it; valid values: an outline around G"
        )
    return out
