"""The pushing API's limits (issue 21, the fuzz round's leftovers): every bad input is one
line naming its parameter, every run is bounded, and the rows end at t_end exactly."""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss

BOX = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
ISO = ss.FrictionTensor(0.3, 0.3)
FINGER = ss.PointPusher([(0.0, -0.2, 0.0), (1.0, 0.0, 0.0)], mu=0.3)


def _one_line(info, start):
    text = str(info.value)
    assert "\n" not in text and text.startswith(start), text


@pytest.mark.parametrize(
    "twist", ["x", None, (1, 2), (1, 2, 3, 4), (math.nan, 0, 0), (True, 0, 0), (0, 0, 0)]
)
def test_motion_cone_contains_names_a_bad_twist(twist):
    cone = ss.motion_cone(BOX, ISO, (-0.1, 0.0), (1.0, 0.0), 0.3)
    with pytest.raises(ValueError) as info:
        cone.contains(twist)
    _one_line(info, "twist")


def test_motion_cone_contains_a_push_through_g_and_not_its_reverse():
    cone = ss.motion_cone(BOX, ISO, (-0.1, 0.0), (1.0, 0.0), 0.3)
    assert cone.contains((1.0, 0.0, 0.0)) and not cone.contains((-1.0, 0.0, 0.0))


def test_a_bool_in_a_start_pose_is_refused():
    with pytest.raises(ValueError) as info:
        ss.push_quasi_static(BOX, ISO, FINGER, [0.0, 1.0], start=(True, 0.0, 0.0))
    _one_line(info, "start")


@pytest.mark.parametrize("outline", [{"shape": "rectangle"}, {(0, 0), (1, 0), (0, 1)}, 5, "abc"])
def test_an_outline_of_the_wrong_kind_lists_the_valid_ones(outline):
    for run in (
        lambda: ss.simulate(BOX, ISO, ss.State(), pusher=FINGER, t_end=1.0, outline=outline),
        lambda: ss.push_quasi_static(BOX, ISO, FINGER, [0.0, 1.0], outline=outline),
    ):
        with pytest.raises(ValueError, match="valid values: None, vertices") as info:
            run()
        _one_line(info, "outline = ")


def test_masked_and_object_paths_are_refused_in_one_line():
    masked = np.ma.array([[0, 0, 0], [1, 1, 0]], mask=[[0, 0, 0], [0, 1, 0]])
    with pytest.raises(ValueError, match="masked") as info:
        ss.PointPusher(masked)
    _one_line(info, "path")
    assert ss.PointPusher(np.ma.array([[0, 0, 0], [1, 1, 0]])).knots.tolist() == [0.0, 1.0]
    with pytest.raises(ValueError) as info:
        ss.PointPusher(np.array([[0, 0, 0], [1, None, 0]], dtype=object))
    _one_line(info, "path = ")


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [({"t_end": 1e10}, "t_end"), ({"t_end": 1.0, "max_steps": 10**12}, "max_steps")],
)
def test_pushed_run_bounds(kwargs, name):
    with pytest.raises(ValueError, match="valid range") as info:
        ss.simulate(BOX, ISO, ss.State(), pusher=FINGER, **kwargs)
    _one_line(info, name)


@pytest.mark.parametrize("bad", [0, True, 1.5, 10**10])
def test_quasi_static_max_phases_is_checked(bad):
    with pytest.raises(ValueError) as info:
        ss.push_quasi_static(BOX, ISO, FINGER, [0.0, 1.0], max_phases=bad)
    _one_line(info, "max_phases")


@pytest.mark.parametrize("kind", ["point", "line"])
def test_quasi_static_push_ends_at_its_budget(kind):
    """A recorded path with a knot every millisecond: the budget of pieces ends the push with
    ``max_phases``, values as reached and NaN after; a larger budget follows the same path."""
    n = 400
    t = np.arange(n) * 1e-3
    x = -0.15 + 0.1 * t
    if kind == "point":
        pusher = ss.PointPusher(np.column_stack((t, x, np.full(n, 0.02))), mu=0.3)
    else:
        pusher = ss.LinePusher(
            0.05, np.column_stack((t, x - 0.05, np.zeros(n), np.full(n, math.pi / 2))), mu=0.3
        )
    times = np.linspace(0.0, t[-1], 9)
    short = ss.push_quasi_static(BOX, ISO, pusher, times, max_phases=100)
    full = ss.push_quasi_static(BOX, ISO, pusher, times)
    assert full.status == "ok" and short.status == "max_phases"
    assert "max_phases = 100" in short.message
    done = ~np.isnan(short.x)
    assert done[0] and not done[-1]
    np.testing.assert_array_equal(short.x[done], full.x[done])


def test_line_pusher_rows_end_at_t_end():
    """A fast line pusher that leaves the body sliding: the last row is at t_end exactly,
    once, and the times never run back."""
    pusher = ss.LinePusher(0.06, [(0, -0.3, 0, math.pi / 2), (0.01, 0.7, 0, math.pi / 2)], mu=0.3)
    for t_end in (0.05, 0.0137, 0.3):
        tr = ss.simulate(BOX, ISO, ss.State(), pusher=pusher, t_end=t_end)
        assert tr.status == "ok"
        assert tr.t[-1] == t_end and tr.t[-2] < t_end
        assert np.all(np.diff(tr.t) >= 0.0)
