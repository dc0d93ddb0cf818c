"""The contact outline (MODEL §13) against hand-computed geometry: a box, an L-shaped part's hull,
round-footed pads (a rounded square), an ellipse (nearest points by an independent scalar
minimisation), frames relative to G, and segment entries."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

import slidespin as ss
from slidespin.contact.outline import body_outline, from_plane, tangent, to_plane

TOL = 1e-14


def _box(**kw):
    return ss.Body(ss.Rectangle(0.2, 0.1, **kw), ss.UniformPressure(), 1.0)


def test_box_vertices_edges_and_closest():
    o = body_outline(_box())
    assert o.kind == "hull" and o.is_polygon
    np.testing.assert_allclose(
        o.vertices, [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], atol=TOL
    )
    np.testing.assert_allclose(
        o.edge_normals, [[0, 1], [-1, 0], [0, -1], [1, 0]], atol=TOL
    )  # inward
    # a face: the nearest point, the inward normal, the gap
    q, n, gap = o.closest((0.3, 0.01))
    np.testing.assert_allclose(q, [0.1, 0.01], atol=TOL)
    np.testing.assert_allclose(n, [-1.0, 0.0], atol=TOL)
    assert gap == pytest.approx(0.2, abs=TOL)
    # a corner region: the normal points from the point to the corner
    q, n, gap = o.closest((0.13, 0.09))
    np.testing.assert_allclose(q, [0.1, 0.05], atol=TOL)
    np.testing.assert_allclose(n, np.array([-0.03, -0.04]) / 0.05, atol=1e-13)
    assert gap == pytest.approx(0.05, abs=TOL)
    # inside: the nearest face, negative gap
    q, n, gap = o.closest((0.08, -0.01))
    np.testing.assert_allclose(q, [0.1, -0.01], atol=TOL)
    np.testing.assert_allclose(n, [-1.0, 0.0], atol=TOL)
    assert gap == pytest.approx(-0.02, abs=TOL)
    assert o.contains((0.0, 0.0)) and not o.contains((0.0, 0.06))
    # the normal cone at the corner (0.1, 0.05): outward normals (1, 0) then (0, 1)
    a, b = o.normal_cone(2)
    np.testing.assert_allclose(a, [1.0, 0.0], atol=TOL)
    np.testing.assert_allclose(b, [0.0, 1.0], atol=TOL)
    np.testing.assert_allclose(o.support((1.0, 1.0)), [0.1, 0.05], atol=TOL)
    np.testing.assert_allclose(tangent(n), [0.0, -1.0], atol=TOL)  # t = z x n


def test_box_entry_by_hand():
    o = body_outline(_box())
    assert o.entry((0.3, 0.0), (-0.3, 0.0)) == pytest.approx(1 / 3, abs=TOL)
    assert o.entry((0.3, 0.2), (0.3, -0.2)) is None  # passes beside it
    assert o.entry((0.0, 0.0), (1.0, 0.0)) == 0.0  # starts inside
    assert o.entry((0.3, 0.0), (0.2, 0.0)) is None  # stops short
    # along y = 0.75 x from (0.2, 0.15): passes x = 0.1 at y = 0.075 (above the box), enters
    # the top face y = 0.05 at x = 0.2/3, s = 2/3
    s = o.entry((0.2, 0.15), (0.0, 0.0))
    assert s == pytest.approx(2 / 3, abs=TOL)
    p = np.array([0.2, 0.15]) * (1 - s)
    assert abs(o.closest(p)[2]) < 1e-15


def test_l_shape_hull_relative_to_g():
    verts = [(0, 0), (0.2, 0), (0.2, 0.05), (0.05, 0.05), (0.05, 0.2), (0, 0.2)]
    body = ss.Body(ss.Polygon(verts), ss.UniformPressure(), 1.0)
    o = body_outline(body)
    # the area centroid of the L by hand: two rectangles 0.2 x 0.05 and 0.05 x 0.15
    a1, a2 = 0.01, 0.0075
    gx = (a1 * 0.1 + a2 * 0.025) / (a1 + a2)
    gy = (a1 * 0.025 + a2 * 0.125) / (a1 + a2)
    np.testing.assert_allclose(o.mass_centre, [gx, gy], atol=TOL)
    hull = [(0, 0), (0.2, 0), (0.2, 0.05), (0.05, 0.2), (0, 0.2)]  # the notch corner is gone
    np.testing.assert_allclose(o.vertices, np.array(hull) - [gx, gy], atol=TOL)
    np.testing.assert_allclose(o.to_body(o.vertices), hull, atol=TOL)
    # the bridged notch: its chord from (0.2, 0.05) to (0.05, 0.2), inward normal (-1, -1)/√2
    q, n, gap = o.closest(o.from_body((0.2, 0.2)))
    np.testing.assert_allclose(o.to_body(q), [0.125, 0.125], atol=TOL)
    np.testing.assert_allclose(n, [-math.sqrt(0.5)] * 2, atol=TOL)
    assert gap == pytest.approx(0.075 * math.sqrt(2), abs=TOL)


def test_linear_pressure_shifts_g():
    body = ss.Body(ss.Rectangle(0.2, 0.1), ss.LinearPressure(0.005, -0.002), 1.0)
    o = body_outline(body)
    np.testing.assert_allclose(o.mass_centre, [0.005, -0.002], atol=TOL)
    np.testing.assert_allclose(o.vertices[0], [-0.105, -0.048], atol=TOL)
    e = body_outline(ss.Body(ss.Ellipse(0.2, 0.1), ss.LinearPressure(0.01, 0.0), 1.0))
    np.testing.assert_allclose(e.centre, [-0.01, 0.0], atol=TOL)
    np.testing.assert_allclose(e.closest((0.5, 0.0))[0], [0.19, 0.0], atol=TOL)


def test_round_feet_make_a_rounded_square():
    r, h = 0.02, 0.1
    feet = ss.Pads(
        *(ss.Disk(r, centre=(sx * h, sy * h)) for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1)))
    )
    o = body_outline(ss.Body(feet, ss.UniformPressure(), 1.0))
    assert o.kind == "hull" and not o.is_polygon and len(o.discs) == 4
    q, n, gap = o.closest((0.3, 0.05))  # a flat side, x = h + r
    np.testing.assert_allclose(q, [h + r, 0.05], atol=TOL)
    np.testing.assert_allclose(n, [-1.0, 0.0], atol=TOL)
    assert gap == pytest.approx(0.3 - h - r, abs=TOL)
    q, n, gap = o.closest((0.3, 0.3))  # a rounded corner
    np.testing.assert_allclose(q, [h + r * math.sqrt(0.5)] * 2, atol=TOL)
    np.testing.assert_allclose(n, [-math.sqrt(0.5)] * 2, atol=TOL)
    assert gap == pytest.approx((0.3 - h) * math.sqrt(2) - r, abs=1e-15)
    assert o.closest((0.0, 0.0))[2] == pytest.approx(-(h + r), abs=TOL)
    s = o.entry((0.3, 0.3), (0.0, 0.0))
    assert s == pytest.approx(((0.3 - h) * math.sqrt(2) - r) / (0.3 * math.sqrt(2)), abs=TOL)
    assert o.support((0.0, 1.0))[1] == pytest.approx(h + r, abs=TOL)


def test_unequal_feet_tangent_segment():
    # two disks of radii 0.05 and 0.02, centres 0.2 apart: the outer tangent's normal makes
    # sin(β) = (0.05 − 0.02)/0.2 with the perpendicular of the centre line
    feet = ss.Pads(ss.Disk(0.05, centre=(-0.1, 0.0)), ss.Disk(0.02, centre=(0.1, 0.0)))
    o = body_outline(ss.Body(feet, ss.UniformPressure(), 1.0))
    g = o.mass_centre
    beta = math.asin(0.03 / 0.2)
    n_top = np.array([math.sin(beta), math.cos(beta)])
    probe = o.from_body(np.array([0.0, 0.0]) + 0.5 * n_top)
    q, n, gap = o.closest(probe)
    np.testing.assert_allclose(n, -n_top, atol=1e-14)
    # signed distance of the probe from the tangent line n·x = n·c1 + r1
    c1 = np.array([-0.1, 0.0])
    assert gap == pytest.approx(0.5 - (n_top @ c1 + 0.05), abs=1e-14)
    assert g[1] == pytest.approx(0.0, abs=TOL)


def _ellipse_nearest(a, b, p):
    """Independent: minimise the distance over the parameter of x = (a cos t, b sin t)."""
    ts = np.linspace(0, 2 * np.pi, 2001)
    d = np.hypot(a * np.cos(ts) - p[0], b * np.sin(ts) - p[1])
    t0 = ts[np.argmin(d)]
    res = minimize_scalar(
        lambda t: math.hypot(a * math.cos(t) - p[0], b * math.sin(t) - p[1]),
        bracket=(t0 - 0.01, t0, t0 + 0.01),
        tol=1e-14,
    )
    t = res.x
    return np.array([a * math.cos(t), b * math.sin(t)]), res.fun


@pytest.mark.parametrize(
    "p",
    [(0.3, 0.2), (-0.05, 0.3), (0.05, 0.01), (0.0, -0.02), (0.17, 0.0), (0.1, 0.0), (0.3, 0.0)]
    + [(-0.1, -0.09)],
)
def test_ellipse_nearest_point(p):
    a, b = 0.2, 0.1
    o = body_outline(ss.Body(ss.Ellipse(a, b), ss.UniformPressure(), 1.0))
    q, n, gap = o.closest(p)
    q = q.copy()
    ref, dist = _ellipse_nearest(a, b, np.array(p))
    if p[1] == 0.0:  # two mirror-image nearest points: compare |eta|
        q, ref = np.abs(q), np.abs(ref)
    np.testing.assert_allclose(q, ref, atol=1e-7)  # the reference's own accuracy (√ of 1e-14)
    assert abs(gap) == pytest.approx(dist, abs=1e-13)
    assert (gap < 0) == ((p[0] / a) ** 2 + (p[1] / b) ** 2 < 1)
    # exact properties: q on the ellipse, n the inward normal of the ellipse at q
    assert (q[0] / a) ** 2 + (q[1] / b) ** 2 == pytest.approx(1.0, abs=1e-14)
    grad = np.array([q[0] / a**2, q[1] / b**2])
    np.testing.assert_allclose(n, -grad / np.linalg.norm(grad), atol=1e-14)
    # p lies on the normal line through q
    w = np.array(p) - q
    assert abs(n[0] * w[1] - n[1] * w[0]) < 1e-14


def test_ellipse_entry_and_disk_outline():
    o = body_outline(ss.Body(ss.Ellipse(0.2, 0.1), ss.UniformPressure(), 1.0))
    assert o.entry((0.4, 0.0), (-0.4, 0.0)) == pytest.approx(0.25, abs=TOL)
    assert o.entry((0.0, 0.3), (0.0, 0.0)) == pytest.approx(2 / 3, abs=TOL)
    assert o.entry((0.3, 0.3), (0.3, -0.3)) is None
    d = body_outline(ss.Body(ss.Disk(0.1, centre=(0.05, 0.0)), ss.UniformPressure(), 1.0))
    assert d.kind == "ellipse" and d.axes == (0.1, 0.1)
    np.testing.assert_allclose(d.centre, [0.0, 0.0], atol=TOL)  # G at the disk's centre
    ring = body_outline(ss.Body(ss.Annulus(0.05, 0.1), ss.UniformPressure(), 1.0))
    assert ring.closest((0.0, 0.0))[2] == pytest.approx(-0.1, abs=TOL)


def test_user_outline_and_frames():
    body = ss.Body(ss.Disk(0.05), ss.UniformPressure(), 1.0)
    o = body_outline(body, [(-0.1, -0.1), (0.1, -0.1), (0.1, 0.1), (-0.1, 0.1), (0.0, 0.0)])
    assert len(o.vertices) == 4  # the convex hull
    e = body_outline(body, ss.Ellipse(0.3, 0.1))
    assert e.kind == "ellipse" and e.axes == (0.3, 0.1)
    pts = np.array([[0.1, 0.0], [0.0, 0.2]])
    plane = to_plane(pts, 1.0, 2.0, math.pi / 2)
    np.testing.assert_allclose(plane, [[1.0, 2.1], [0.8, 2.0]], atol=TOL)
    np.testing.assert_allclose(from_plane(plane, 1.0, 2.0, math.pi / 2), pts, atol=TOL)


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        (lambda: body_outline("box"), "body"),
        (lambda: body_outline(ss.Body(ss.Blade(0.2), ss.UniformPressure(), 1.0)), "Blade"),
        (lambda: body_outline(_box(), [(0, 0), (1, 0)]), "outline has shape"),
        (lambda: body_outline(_box(), [(0, 0), (1, 0), (2, 0)]), "area"),
        (lambda: body_outline(_box(), [(1, 1), (2, 1), (2, 2)]), "not inside"),
        (lambda: body_outline(_box(), [(0, True), (1, 0), (2, 0)]), "bool"),
        (lambda: body_outline(_box(), "abc"), "outline"),
        (lambda: body_outline(_box(), [(0, math.nan), (1, 0), (0, 1)]), "outline"),
        (lambda: body_outline(_box()).closest((0.0, math.inf)), "point"),
        (lambda: body_outline(_box()).closest((0.0, 1.0, 2.0)), "point"),
        (lambda: body_outline(_box()).normal_cone(7), "index"),
    ],
)
def test_refusals(call, needle):
    with pytest.raises(ValueError) as err:
        call()
    assert needle in str(err.value) and "\n" not in str(err.value)
