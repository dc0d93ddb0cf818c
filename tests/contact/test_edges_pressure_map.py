"""Pressure maps and point arrays of the wrong shape are refused by name (they used to fail
with NumPy's "operands could not be broadcast"), and shapes that broadcast still work.

Independent truth: a uniform law is P/A everywhere on the footprint (A = L W here).
"""

from __future__ import annotations

import numpy as np
import pytest

import slidespin as ss
from slidespin.contact.pressure_map import PressureMap, density, map_scale

RECT = ss.Rectangle(1.0, 0.5)
GRID = PressureMap.from_grid([0.0, 1.0, 2.0, 3.0], [0.0, 1.0, 2.0, 3.0], np.ones((4, 4)))


@pytest.mark.parametrize(
    "call",
    [
        lambda: GRID(np.zeros(3), np.zeros(4)),
        lambda: PressureMap(lambda x, y: 1.0 + 0.0 * x)(np.zeros((2, 3)), np.zeros((3, 2))),
        lambda: density(RECT, ss.UniformPressure(), np.zeros(3), np.zeros(4)),
        lambda: density(RECT, GRID, np.zeros(3), np.zeros(4)),
    ],
)
def test_points_that_do_not_broadcast_are_refused_by_name(call):
    with pytest.raises(ValueError, match=r"xi has shape .* and eta has shape .*; valid values"):
        call()


@pytest.mark.parametrize(
    "function, got",
    [
        (lambda x, y: 1.0, r"returned 1\.0 \(float\)"),
        (lambda x, y: np.ones((x.size, 1)), r"returned an array of shape \(\d+, 1\)"),
        (lambda x, y: np.ones(3), r"returned an array of shape \(3,\)"),
        (lambda x, y: (1.0 + 0.0 * x)[:1], r"returned an array of shape \(1,\)"),
        (lambda x, y: "a", r"returned 'a' \(str\)"),
        (lambda x, y: None, r"returned None"),
    ],
)
def test_a_map_of_the_wrong_shape_is_refused_by_name(function, got):
    pm = PressureMap(function)
    with pytest.raises(ValueError, match=rf"pressure map: function\(xi, eta\) {got}.*valid values"):
        map_scale(RECT, pm)
    with pytest.raises(ValueError, match=r"pressure map: function\(xi, eta\)"):
        ss.friction_wrench(ss.Body(RECT, pm, 1.0), ss.FrictionTensor(0.3, 0.3), 1.0, 0.0, 1.0)


def test_a_map_of_a_2d_grid_of_points_keeps_its_shape():
    xi, eta = np.meshgrid(np.linspace(-0.4, 0.4, 3), np.linspace(-0.2, 0.2, 5))
    pm = PressureMap(lambda x, y: 2.0 + 0.0 * x)
    p = density(RECT, pm, xi, eta, load=3.0)
    assert p.shape == (5, 3)
    assert p == pytest.approx(np.full((5, 3), 3.0 / 0.5), rel=1e-12)
    # a scalar and an array broadcast: the uniform law is P/A inside, 0 outside
    q = density(RECT, ss.UniformPressure(), np.array([0.0, 0.3, 0.7]), 0.1, load=2.0)
    assert q == pytest.approx([4.0, 4.0, 0.0])
