"""Footprint inputs: polygon simplicity, pressure maps with rim singularities, messages and
exports (found in the API review: P1-5, P1-6, P2-4).

Each test compares against truth written apart from the code under test: a slow pairwise
segment-intersection reference for polygon simplicity, the exact Hertz disk for a Hertz-shaped
pressure map, closed forms for the normalisation of rim-singular maps.
"""

from __future__ import annotations

import math
import time
import warnings
from fractions import Fraction

import numpy as np
import pytest

import slidespin as ss
from slidespin.contact.wrench import footprint_wrench
from slidespin.contact.shapes import MAX_VERTICES, Disk, Pads, Polygon, Rectangle

# ---------------------------------------------------------------------------------------------
# P1-6: polygon simplicity, vectorised


def _ref_simple(pts) -> bool:
    """Slow reference: no two non-adjacent edges meet, no adjacent edges overlap (O(n²)
    loops, exact arithmetic on Fractions)."""
    n = len(pts)

    def orient(a, b, c):
        v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        return (v > 0) - (v < 0)

    def onseg(a, b, c):
        return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(
            a[1], b[1]
        )

    def meet(a, b, c, d):
        o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
        if o1 != o2 and o3 != o4 and 0 not in (o1, o2, o3, o4):
            return True
        return (
            (o1 == 0 and onseg(a, b, c))
            or (o2 == 0 and onseg(a, b, d))
            or (o3 == 0 and onseg(c, d, a))
            or (o4 == 0 and onseg(c, d, b))
        )

    for i in range(n):
        a, b = pts[i], pts[(i + 1) % n]
        for k in range(i + 1, n):
            c, d = pts[k], pts[(k + 1) % n]
            if k == i + 1 or (i == 0 and k == n - 1):
                # adjacent: the far ends must not lie on the other edge (fold back)
                shared = b if k == i + 1 else a
                far1 = a if k == i + 1 else b
                far2 = d if k == i + 1 else c
                if orient(shared, far1, far2) == 0 and (
                    (far1[0] - shared[0]) * (far2[0] - shared[0])
                    + (far1[1] - shared[1]) * (far2[1] - shared[1])
                    > 0
                ):
                    return False
                continue
            if meet(a, b, c, d):
                return False
    return True


def test_simplicity_matches_slow_reference_on_random_polygons():
    rng = np.random.default_rng(12)
    n_simple = n_bad = 0
    for trial in range(300):
        n = int(rng.integers(4, 12))
        if trial % 2:  # star-shaped: simple
            ang = np.sort(rng.uniform(0, 2 * np.pi, n))
            r = rng.uniform(0.2, 1.0, n)
            pts = np.column_stack((r * np.cos(ang), r * np.sin(ang)))
        else:  # random order: often self-intersecting
            pts = rng.uniform(-1, 1, (n, 2))
        pts = np.round(pts, 3)  # exact ties (collinear, touching) happen too
        # exact arithmetic on the decimal values (a 1e-3 grid: any non-zero cross product is
        # ≥ 1e-6, far above the code's 1e-13 tolerance)
        expect = _ref_simple([(Fraction(str(x)), Fraction(str(y))) for x, y in pts.tolist()])
        try:
            Polygon(pts)
            got = True
        except ValueError as e:
            msg = str(e)
            if "too thin" in msg or "zero area" in msg or "repeats" in msg:
                continue
            assert "intersect" in msg or "fold back" in msg, msg
            got = False
        assert got == expect, pts.tolist()
        n_simple += got
        n_bad += not got
    assert n_simple > 100 and n_bad > 50


def test_big_polygons_are_fast_and_exact():
    n = 10_000
    k = np.arange(n)
    r = 0.1 * (1.0 + 0.3 * np.cos(37 * 2 * np.pi * k / n))  # non-convex star
    pts = np.column_stack((r * np.cos(2 * np.pi * k / n), r * np.sin(2 * np.pi * k / n)))
    t0 = time.perf_counter()
    p = Polygon(pts)
    took = time.perf_counter() - t0
    # measured ~0.05 s (was ~300 s, O(n²) in pure Python); generous for a shared machine
    assert took < 5.0
    # area of the polygon through r_k = a(1 + ε cos mθ_k): ½ Σ r_k r_k+1 sin Δ, in closed
    # form ½ n a² sin Δ (1 + ε²/2 cos mΔ) (the cos mθ_k sums vanish for m < n)
    dlt = 2 * np.pi / n
    exact = 0.5 * n * 0.01 * math.sin(dlt) * (1.0 + 0.5 * 0.09 * math.cos(37 * dlt))
    assert abs(p.area - exact) < 1e-12 * exact
    # a crossing deep inside a big polygon is still found, and named
    bad = pts.copy()
    bad[[5000, 5001]] = bad[[5001, 5000]]
    with pytest.raises(ValueError, match="edges 4999 and 5001 of the polygon intersect"):
        Polygon(bad)


def test_vertex_limit():
    assert MAX_VERTICES == 20_000
    n = MAX_VERTICES + 1
    t = 2 * np.pi * np.arange(n) / n
    with pytest.raises(ValueError, match=r"vertices has 20001 points; valid range: at most"):
        Polygon(np.column_stack((np.cos(t), np.sin(t))))
    t = 2 * np.pi * np.arange(MAX_VERTICES) / MAX_VERTICES
    assert Polygon(np.column_stack((np.cos(t), np.sin(t)))).area == pytest.approx(np.pi, 1e-6)


def test_many_pads_fast_and_overlap_found():
    t0 = time.perf_counter()
    grid = [Disk(0.001, centre=(0.01 * i, 0.01 * j)) for i in range(40) for j in range(40)]
    pads = Pads(grid)
    assert time.perf_counter() - t0 < 5.0  # measured 0.013 s (was 52 s)
    assert pads.area == pytest.approx(1600 * math.pi * 1e-6, rel=1e-13)
    rects = [
        Rectangle(0.004, 0.004, centre=(0.01 * i, 0.01 * j)) for i in range(20) for j in range(20)
    ]
    Pads(rects)
    # one overlapping pair deep in the grid (patches 210 and the added one)
    with pytest.raises(ValueError, match=r"patch 210 .* and patch 400 .* overlap"):
        Pads(rects + [Rectangle(0.004, 0.004, centre=(0.1025, 0.1))])
    with pytest.raises(ValueError, match="at most MAX_VERTICES"):
        Pads(
            [
                Rectangle(0.004, 0.004, centre=(0.01 * i, 0.01 * j))
                for i in range(71)
                for j in range(71)
            ]
        )


def test_existing_polygon_errors_kept():
    for verts, word in [
        ([(0, 0), (1, 1), (1, 0), (0, 1)], "edges 0 and 2 of the polygon intersect"),
        ([(0, 0), (1, 0), (2, 0)], "edges 0 and 2 fold back"),  # collinear: no area
        ([(0, 0), (1, 0), (1, 0), (0, 1)], r"vertex 2 repeats vertex 1 at \(1.0, 0.0\)"),
        ([(0, 0), (2, 0), (1, 0), (1, 1)], "fold back"),
        ([(0, 0), (2, 0), (2, 2), (1, 0.0), (0, 2)], "intersect"),  # touches an edge
    ]:
        with pytest.raises(ValueError, match=word) as e:
            Polygon(verts)
        assert "np.float64" not in str(e.value)


# ---------------------------------------------------------------------------------------------
# P1-5: user maps with a square-root rim behaviour


def test_hertz_shaped_map_matches_exact_hertz_disk():
    r, load = 0.1, 10.0
    disk = Disk(r)
    hz = ss.PressureMap(lambda x, y: np.sqrt(np.clip(1 - (x**2 + y**2) / r**2, 0, None)))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # accurate, so no warning either
        for f in (ss.FrictionTensor(0.3, 0.3), ss.FrictionTensor(0.2, 0.5, 0.1)):
            for vx, vy, om in [(0, 0, 1), (1, 0.5, 0), (0.03, 0.01, 1), (0.5, 0.2, 1)]:
                w = footprint_wrench(disk, hz, f, vx, vy, om, load=load)
                e = footprint_wrench(disk, ss.HertzPressure(), f, vx, vy, om, load=load)
                assert abs(w.force_x - e.force_x) < 1e-8 * load
                assert abs(w.force_y - e.force_y) < 1e-8 * load
                assert abs(w.moment - e.moment) < 1e-8 * load * r
    # the pure-spin moment in closed form: −(3π/16) μ P R (MODEL §3)
    w = footprint_wrench(disk, hz, ss.FrictionTensor(0.3, 0.3), 0, 0, 1, load=load)
    assert abs(w.moment + 3 * math.pi / 16 * 0.3 * load * r) < 1e-10 * load * r


def test_rough_map_warns():
    kink = ss.PressureMap(lambda x, y: np.abs(x - 0.0123) + 0.01)
    with pytest.warns(RuntimeWarning, match="reached only"):
        footprint_wrench(Disk(0.1), kink, ss.FrictionTensor(0.3, 0.3), 1, 0, 0)


def test_inertia_intervals_accepts_a_body():
    # ring closed forms (isotropic): I1 = (R² + r²)/(4R²), I3 = (2/3)(R² + Rr + r²)/R²
    r, big = 0.05, 0.1
    f = ss.FrictionTensor(0.3, 0.3)
    body = ss.Body(ss.Annulus(r, big), ss.UniformPressure(), 1.0)
    i1, _, i3 = ss.inertia_intervals(body, f)
    assert abs(i1 - (big**2 + r**2) / (4 * big**2)) < 1e-9
    assert abs(i3 - 2 / 3 * (big**2 + big * r + r**2) / big**2) < 1e-9
