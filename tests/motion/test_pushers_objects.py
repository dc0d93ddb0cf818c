"""Pushers as value objects (MODEL §13): positions and velocities against hand-computed paths,
the knots, and one-line errors naming the parameter for every bad input."""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest

import slidespin as ss
from slidespin.motion.pushers import LinePusher, PointPusher

PATH = [(0.0, 0.0, 0.0), (1.0, 0.2, 0.0), (3.0, 0.2, 0.4), (4.0, 0.2, 0.4)]


def test_point_positions_and_velocities_by_hand():
    f = PointPusher(PATH, mu=0.25)
    assert f.mu == 0.25
    assert f.path.shape == (4, 3) and not f.path.flags.writeable
    np.testing.assert_array_equal(f.times, [0.0, 1.0, 3.0, 4.0])
    # hand values: on [0, 1] x = 0.2 t; on [1, 3] y = 0.2 (t - 1); held from t = 3 on
    np.testing.assert_allclose(f.position(0.5), [0.1, 0.0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(f.position(2.0), [0.2, 0.2], rtol=0, atol=1e-15)
    np.testing.assert_allclose(f.position(10.0), [0.2, 0.4], rtol=0, atol=0)
    np.testing.assert_allclose(f.position(-1.0), [0.0, 0.0], rtol=0, atol=0)
    np.testing.assert_allclose(f.velocity(0.5), [0.2, 0.0], rtol=1e-15)
    np.testing.assert_allclose(f.velocity(2.0), [0.0, 0.2], rtol=1e-15)
    # right-continuous at the knots, zero before the start and from the last knot on
    np.testing.assert_allclose(f.velocity(0.0), [0.2, 0.0], rtol=1e-15)
    np.testing.assert_allclose(f.velocity(1.0), [0.0, 0.2], rtol=1e-15)
    np.testing.assert_array_equal(f.velocity(3.0), [0.0, 0.0])  # segment [3, 4] is at rest
    np.testing.assert_array_equal(f.velocity(4.0), [0.0, 0.0])
    np.testing.assert_array_equal(f.velocity(-0.1), [0.0, 0.0])
    # the knots: where the velocity jumps (not at t = 4: the last segment is at rest)
    np.testing.assert_array_equal(f.knots, [0.0, 1.0, 3.0])
    # exact at the waypoints, arrays in and out
    t = np.array([0.0, 1.0, 3.0, 4.0])
    np.testing.assert_array_equal(f.position(t), np.array(PATH)[:, 1:])
    assert f.velocity(t).shape == (4, 2)


def test_position_is_continuous_and_velocity_is_its_slope():
    f = PointPusher(PATH)
    t = np.linspace(-0.5, 4.5, 1001)
    h = 1e-7
    mid = t[(np.abs(t[:, None] - f.times[None, :]) > 2 * h).all(axis=1)]
    slope = (f.position(mid + h) - f.position(mid - h)) / (2 * h)
    np.testing.assert_allclose(slope, f.velocity(mid), atol=1e-7)


def test_single_row_is_a_finger_held_still():
    f = PointPusher([(1.0, 0.3, -0.2)])
    np.testing.assert_array_equal(f.position(0.0), [0.3, -0.2])
    np.testing.assert_array_equal(f.position(5.0), [0.3, -0.2])
    np.testing.assert_array_equal(f.velocity(1.0), [0.0, 0.0])
    assert f.knots.size == 0


def test_constant_velocity():
    f = PointPusher.constant_velocity((0.1, -0.2), (0.3, 0.4), t_end=2.0, mu=0.5, t_start=1.0)
    np.testing.assert_array_equal(f.velocity(1.5), [0.3, 0.4])
    np.testing.assert_allclose(f.position(2.0), [0.4, 0.2], atol=1e-15)
    np.testing.assert_allclose(f.position(0.0), [0.1, -0.2], atol=0)
    np.testing.assert_array_equal(f.knots, [1.0, 2.0])
    assert f.mu == 0.5


def test_line_pusher_pose_ends_and_velocity():
    e = LinePusher(0.2, [(0.0, 0.0, 0.0, 0.0), (2.0, 0.4, 0.0, math.pi / 2)], mu=0.1)
    np.testing.assert_allclose(e.pose(1.0), [0.2, 0.0, math.pi / 4], rtol=1e-15)
    np.testing.assert_allclose(e.velocity(1.0), [0.2, 0.0, math.pi / 4], rtol=1e-15)
    c = math.sqrt(0.5) * 0.1
    np.testing.assert_allclose(e.ends(1.0), [[0.2 - c, -c], [0.2 + c, c]], atol=1e-15)
    np.testing.assert_allclose(e.ends(5.0), [[0.4, -0.1], [0.4, 0.1]], atol=1e-15)
    np.testing.assert_array_equal(e.velocity(2.0), [0.0, 0.0, 0.0])
    np.testing.assert_array_equal(e.knots, [0.0, 2.0])
    assert e.ends(np.array([0.0, 1.0])).shape == (2, 2, 2)
    assert e.length == 0.2 and e.mu == 0.1
    w = LinePusher.constant_velocity((0.0, 0.0, 0.3), (0.0, 0.1, -1.0), 1.0, length=0.05)
    np.testing.assert_array_equal(w.velocity(0.5), [0.0, 0.1, -1.0])
    np.testing.assert_allclose(w.pose(1.0), [0.0, 0.1, -0.7], atol=1e-15)


def test_equality_hash_pickle():
    f, g = PointPusher(PATH, 0.2), PointPusher(np.array(PATH), 0.2)
    assert f == g and hash(f) == hash(g) and f != PointPusher(PATH, 0.3)
    assert pickle.loads(pickle.dumps(f)) == f
    e = LinePusher(0.1, [(0, 0, 0, 0)])
    assert pickle.loads(pickle.dumps(e)) == e
    with pytest.raises(Exception):
        f.mu = 1.0  # type: ignore[misc]
    with pytest.raises(ValueError):
        f.path[0, 0] = 5.0


BAD_POINT = [
    (dict(path=[(0.0, True, 0.0)]), "path[0][1]"),
    (dict(path=[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)]), "path[1, 0]"),
    (dict(path=[(1.0, 0.0, 0.0), (0.5, 1.0, 0.0)]), "strictly increasing"),
    (dict(path=[(0.0, math.nan, 0.0)]), "path[0, 1]"),
    (dict(path=[(0.0, 0.0, math.inf)]), "path[0, 2]"),
    (dict(path=[(math.nan, 0.0, 0.0)]), "path[0, 0]"),
    (dict(path="abc"), "path"),
    (dict(path=b"abc"), "path"),
    (dict(path=None), "path"),
    (dict(path=[]), "path has shape"),
    (dict(path=[(0.0, 0.0)]), "path has shape (1, 2)"),
    (dict(path=[(0.0, 0.0, 0.0, 0.0)]), "path has shape (1, 4)"),
    (dict(path=[(0.0, 0.0, 0.0), (1.0, 2.0)]), "path"),
    (dict(path=[("a", 0.0, 0.0)]), "path"),
    (dict(path=np.array([[True, False, True]])), "bools"),
    (dict(path=[(0.0, 0.0, 0.0), (1e-300, 1.0, 0.0)]), "speed"),
    (dict(path=[(0.0, 1e101, 0.0)]), "path[0, 1]"),
    (dict(path=[(0.0, 0.0, 0.0)], mu=-0.1), "mu"),
    (dict(path=[(0.0, 0.0, 0.0)], mu=math.nan), "mu"),
    (dict(path=[(0.0, 0.0, 0.0)], mu=math.inf), "mu"),
    (dict(path=[(0.0, 0.0, 0.0)], mu=True), "mu"),
    (dict(path=[(0.0, 0.0, 0.0)], mu="0.3"), "mu"),
    (dict(path=[(0.0, 0.0, 0.0)], mu=[0.3]), "mu"),
]


@pytest.mark.parametrize(("kwargs", "needle"), BAD_POINT)
def test_point_pusher_refuses_bad_input(kwargs, needle):
    with pytest.raises(ValueError) as err:
        PointPusher(**kwargs)
    msg = str(err.value)
    assert needle in msg and "\n" not in msg


BAD_LINE = [
    (dict(length=0.0, path=[(0, 0, 0, 0)]), "length"),
    (dict(length=-1.0, path=[(0, 0, 0, 0)]), "length"),
    (dict(length=True, path=[(0, 0, 0, 0)]), "length"),
    (dict(length=math.nan, path=[(0, 0, 0, 0)]), "length"),
    (dict(length=0.1, path=[(0, 0, 0)]), "path has shape (1, 3)"),
    (dict(length=0.1, path=[(0, 0, 0, math.nan)]), "path[0, 3]"),
    (dict(length=0.1, path=[(0, 0, 0, 0), (1e-20, 0, 0, 1.0)]), "turn rate"),
    (dict(length=0.1, path=[(0, 0, 0, 0)], mu=-1), "mu"),
]


@pytest.mark.parametrize(("kwargs", "needle"), BAD_LINE)
def test_line_pusher_refuses_bad_input(kwargs, needle):
    with pytest.raises(ValueError) as err:
        LinePusher(**kwargs)
    assert needle in str(err.value) and "\n" not in str(err.value)


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        (lambda: PointPusher.constant_velocity((0, 0), (1, 0), t_end=0.0), "t_end"),
        (lambda: PointPusher.constant_velocity((0, 0), (1, 0), t_end=math.inf), "t_end"),
        (lambda: PointPusher.constant_velocity((0, 0, 0), (1, 0), t_end=1.0), "start"),
        (lambda: PointPusher.constant_velocity((0, 0), (True, 0), t_end=1.0), "velocity[0]"),
        (lambda: PointPusher.constant_velocity("ab", (1, 0), t_end=1.0), "start"),
        (lambda: PointPusher.constant_velocity((0, 0), (1e9, 0), t_end=1.0), "speed"),
        (lambda: PointPusher([(0, 0, 0)]).position(math.nan), "t"),
        (lambda: PointPusher([(0, 0, 0)]).velocity(True), "t"),
        (lambda: PointPusher([(0, 0, 0)]).position("1"), "t"),
        (lambda: PointPusher([(0, 0, 0)]).position([[0.0]]), "t has shape"),
        (lambda: LinePusher.constant_velocity((0, 0, 0), (1, 0, 0), 1.0, length=0), "length"),
        (lambda: LinePusher.constant_velocity((0, 0), (1, 0, 0), 1.0, length=1), "start_pose"),
    ],
)
def test_other_refusals(call, needle):
    with pytest.raises(ValueError) as err:
        call()
    assert needle in str(err.value) and "\n" not in str(err.value)


@pytest.mark.parametrize("mu", [1e300, 1.0000001e9, float("inf")])
def test_mu_beyond_the_largest_is_refused_everywhere(mu):
    """μp above 1e9 is refused in one line naming mu (found by fuzzing: 1e300 passed the check
    and the motion cone failed on a NaN it called vx)."""
    box = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
    calls = [
        lambda: ss.PointPusher([(0.0, 0.0, 0.0), (1.0, 1.0, 0.0)], mu=mu),
        lambda: ss.LinePusher(0.1, [(0.0, 0.0, 0.0, 0.0), (1.0, 1.0, 0.0, 0.0)], mu=mu),
        lambda: ss.motion_cone(box, ss.FrictionTensor(0.3, 0.3), (-0.1, 0.0), (1.0, 0.0), mu),
    ]
    for call in calls:
        with pytest.raises(ValueError, match=r"^mu = .*valid range: \[0, 1e\+09\]") as err:
            call()
        assert "\n" not in str(err.value)
    assert ss.PointPusher([(0.0, 0.0, 0.0), (1.0, 1.0, 0.0)], mu=1e9).mu == 1e9
