"""Footprint inputs found by new users and adversarial rounds: closed outlines, non-numeric
vertices, ``Pads`` given patches positionally, and the ``n`` of ``outlines``.

Independent truths: the shoelace area of the open outline (written out here), the disks'
areas π R², and the points of a circle (on it, n of them).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from slidespin.contact.shapes import (
    Annulus,
    Blade,
    Disk,
    Pads,
    Polygon,
    Rectangle,
)

SQUARE = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]


def _shoelace(pts):
    x, y = np.array(pts).T
    return 0.5 * abs(float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)))


@pytest.mark.parametrize("outline", (SQUARE, SQUARE[::-1], [(0, 0), (1, 0), (0.3, 0.8)]))
def test_a_closed_outline_is_the_open_one(outline):
    closed = Polygon(list(outline) + [outline[0]])
    assert closed == Polygon(outline)
    assert len(closed.vertices) == len(outline)
    assert closed.area == pytest.approx(_shoelace(outline), rel=1e-15)
    np_closed = Polygon(np.array(list(outline) + [outline[0]], dtype=float))
    assert np_closed.area == pytest.approx(_shoelace(outline), rel=1e-15)


def test_a_closed_outline_of_two_points_is_too_short():
    with pytest.raises(ValueError, match=r"2 distinct point\(s\); valid range: at least 3"):
        Polygon([(0, 0), (1, 0), (0, 0)])


def test_a_vertex_repeated_inside_the_outline_is_still_refused():
    with pytest.raises(ValueError, match="repeats vertex"):
        Polygon([(0, 0), (1, 0), (1, 0), (0, 1), (0, 0)])


@pytest.mark.parametrize(
    "vertices, where",
    [
        ([(0, 0), (1, 0), b"ab"], r"vertices\[2\] = b'ab'"),
        ([(0, 0), "10", (0, 1)], r"vertices\[1\] = '10'"),
        ([(0, 0), (1, 0), (True, 1)], r"vertices\[2\]\[0\]"),
        ([(0, 0), (1, 0), (0, np.bool_(True))], r"vertices\[2\]\[1\]"),
        (b"abcdef", "vertices = b'abcdef'"),
        ("abc", "vertices = 'abc'"),
        ([(0, 0), (1, 0), (0, 1, 2)], r"vertices\[2\]"),
    ],
)
def test_non_numeric_vertices_are_refused_by_name(vertices, where):
    with pytest.raises(ValueError, match=where) as e:
        Polygon(vertices)
    assert "valid values" in str(e.value)


def test_a_bytes_centre_is_refused():
    with pytest.raises(ValueError, match=r"centre = b'ab' is invalid; valid values"):
        Disk(0.1, centre=b"ab")


def test_pads_take_their_patches_positionally_as_a_list_or_by_keyword():
    a, b = Disk(0.1), Disk(0.05, centre=(1.0, 0.0))
    c = Rectangle(0.2, 0.1, centre=(0.0, 1.0))
    forms = (Pads(a, b, c), Pads([a, b, c]), Pads((a, b, c)), Pads(patches=[a, b, c]))
    assert all(f == forms[0] for f in forms)
    assert len({hash(f) for f in forms}) == 1
    assert forms[0].area == pytest.approx(math.pi * (0.01 + 0.0025) + 0.02, rel=1e-14)
    assert Pads(a).area == pytest.approx(math.pi * 0.01, rel=1e-14)
    assert Pads(Pads(a, b), c) == forms[0]  # nested pads are flattened


@pytest.mark.parametrize(
    "make, match",
    [
        (lambda: Pads(), "at least one patch"),
        (lambda: Pads(Disk(0.1), patches=[Disk(0.1)]), "either positionally"),
        (lambda: Pads(Disk(0.1), 3), r"patches\[1\] = 3 is invalid; valid values"),
        (lambda: Pads("ab"), r"patches\[0\] = 'ab' is invalid; valid values"),
        (lambda: Pads(Disk(0.1), Disk(0.1)), "overlap"),
        (lambda: Pads(Blade(0.3), Disk(0.1, centre=(1, 0))), "several blades"),
    ],
)
def test_bad_pads_say_how_to_call(make, match):
    with pytest.raises(ValueError, match=match):
        make()


PATCHES = (
    Polygon(SQUARE),
    Rectangle(0.3, 0.2),
    Disk(0.1),
    Annulus(0.05, 0.1),
    Pads(Disk(0.1), Rectangle(0.1, 0.1, centre=(1.0, 0.0))),
    Blade(0.3),
)


@pytest.mark.parametrize("patch", PATCHES, ids=lambda p: type(p).__name__)
@pytest.mark.parametrize("n", (-1, 0, 1, 10**9, 2.5, True, "5", None))
def test_outlines_refuse_a_bad_n(patch, n):
    with pytest.raises(
        ValueError, match=r"n = .* is invalid; valid range: an integer in \[2, 1000000\]"
    ):
        patch.outlines(n)


@pytest.mark.parametrize("n", (2, 3, 181, np.int64(7)))
def test_outlines_of_a_ring_are_n_points_on_its_circles(n):
    ring = Annulus(0.05, 0.1, centre=(0.2, -0.1))
    outer, inner = ring.outlines(n)
    for curve, radius in ((outer, 0.1), (inner, 0.05)):
        assert curve.shape == (int(n), 2)
        assert np.hypot(curve[:, 0] - 0.2, curve[:, 1] + 0.1) == pytest.approx(radius, rel=1e-14)
    assert Polygon(SQUARE).outlines(n)[0].shape == (5, 2)  # exact: n is not needed
