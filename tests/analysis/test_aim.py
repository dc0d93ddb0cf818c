"""Aiming (MODEL §15): launches recovered from the stops they make, targets hit to 1e-9 m
as :func:`slidespin.simulate` itself measures them, and unreachable targets reported."""

from __future__ import annotations

import math

import pytest

import slidespin as ss

ELLIPSE = ss.Body(ss.Ellipse(0.1, 0.06), ss.LinearPressure(0.01, 0.005), mass=1.0)
SKEW = ss.FrictionTensor(0.3, 0.4, 0.05)
DISK = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0)
ISO = ss.FrictionTensor(0.3, 0.3)


def _stop(body, friction, start):
    s = ss.simulate(body, friction, start).stop_state
    return s.x, s.y, s.phi


@pytest.mark.parametrize(
    ("body", "friction", "launch"),
    [
        (ELLIPSE, SKEW, ss.State(x=0.2, y=-0.1, phi=0.3, vx=1.0, vy=0.3, omega=5.0)),
        (ELLIPSE, SKEW, ss.State(vx=-0.4, vy=1.1, omega=-9.0)),
        (
            ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.5),
            ss.FrictionTensor(0.3, 0.5, angle=0.4),
            ss.State(phi=1.0, vx=0.8, vy=0.2, omega=6.0),
        ),
    ],
)
def test_aim_recovers_the_launch_that_made_the_target(body, friction, launch):
    target = _stop(body, friction, launch)
    start = ss.State(launch.x, launch.y, launch.phi)  # at rest: aim's own first guess
    got = ss.aim(body, friction, target, start=start, free=("vx", "vy", "omega"))
    for n in ("vx", "vy", "omega"):
        assert getattr(got, n) == pytest.approx(getattr(launch, n), rel=1e-8, abs=1e-10)
    assert (got.x, got.y, got.phi) == (launch.x, launch.y, launch.phi)
    x, y, phi = _stop(body, friction, got)
    assert abs(x - target[0]) < 1e-9 and abs(y - target[1]) < 1e-9
    assert abs(phi - target[2]) < 1e-9


def test_aim_at_a_position_with_the_spin_fixed():
    start = ss.State(omega=4.0)
    got = ss.aim(ELLIPSE, SKEW, (0.3, 0.2), start=start, free=("vx", "vy"))
    assert got.omega == 4.0
    x, y, _ = _stop(ELLIPSE, SKEW, got)
    assert math.hypot(x - 0.3, y - 0.2) < 1e-9


def test_aim_a_turn_on_the_spot():
    # a centred disk turning on the spot: φ = I ω²/(2M), M = (2/3) μ m g a
    got = ss.aim(DISK, ISO, (0.0, 0.0, 3.0))
    M = (2 / 3) * 0.3 * 9.81 * 0.1
    assert got.omega == pytest.approx(math.sqrt(2 * M * 3.0 / DISK.moment_of_inertia), rel=1e-8)
    assert abs(got.vx) < 1e-9 and abs(got.vy) < 1e-9


def test_unreachable_angle_without_spin():
    # a symmetric disk launched without spin never turns: φ = 1 cannot be reached
    with pytest.raises(ss.UnreachableTarget) as info:
        ss.aim(DISK, ISO, (1.0, 0.0, 1.0), free=("vx", "vy"))
    err = info.value
    assert isinstance(err, ValueError)
    assert "1" in str(err) and "vx, vy" in str(err)
    assert err.nearest.x == pytest.approx(1.0, abs=1e-6)
    assert err.nearest.phi == pytest.approx(0.0, abs=1e-9)
    assert err.miss == pytest.approx(0.1, rel=1e-3)  # 1 rad weighted by a = 0.1 m
    assert err.angle_miss == pytest.approx(1.0, abs=1e-9)
    assert err.position_miss < 1e-6
    assert err.start.omega == 0.0


def test_unreachable_position_by_spin_alone():
    # spin alone cannot move a centred disk
    with pytest.raises(ss.UnreachableTarget):
        ss.aim(DISK, ISO, (0.5, 0.0), start=ss.State(omega=1.0), free=("omega",))


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"target": (1.0,)}, "target"),
        ({"target": (1.0, math.nan)}, "target"),
        ({"target": "far"}, "target"),
        ({"target": (1.0, 0.0), "free": ("x",)}, "free"),
        ({"target": (1.0, 0.0), "free": ()}, "free"),
        ({"target": (1.0, 0.0), "tol": 0.0}, "tol"),
        ({"target": (1.0, 0.0), "start": (0, 0, 0)}, "start"),
    ],
)
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        ss.aim(DISK, ISO, **kwargs)


def test_a_target_at_the_start_is_the_start_at_rest():
    start = ss.State(x=0.3, y=-0.2, phi=0.5)
    assert ss.aim(DISK, ISO, (0.3, -0.2, 0.5), start=start) == start


def test_a_tall_body_is_aimed_by_differences():
    """A tall body's sensitivities are not built (MODEL §14): aim's Jacobian is then by
    differences. In translation it stops like a thin body: v = √(2 μ g d)."""
    tall = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0, height=0.1)
    got = ss.aim(tall, ISO, (0.5, 0.0), free=("vx",), g=9.81)
    mu = ISO.fx
    assert got.vx == pytest.approx(math.sqrt(2 * mu * 9.81 * 0.5), rel=1e-9)


def test_far_target_is_reached_to_the_resolution_of_the_simulation():
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor(0.42, 0.54)
    got = ss.aim(body, fr, (1e3, 0.0))
    assert abs(ss.simulate(body, fr, got).stop_state.x - 1e3) < 1e-9


@pytest.mark.parametrize("target", [(True, False), (1.0, 2.0, 3.0, 4.0)])
def test_bad_targets(target):
    with pytest.raises(ValueError, match="target"):
        ss.aim(DISK, ISO, target)


def test_aim_in_polar_form_speed_and_direction():
    launch = ss.State(vx=1.0, vy=0.3, omega=5.0)
    target = _stop(ELLIPSE, SKEW, launch)
    got = ss.aim(ELLIPSE, SKEW, target, free=("speed", "direction", "omega"))
    assert (got.vx, got.vy, got.omega) == pytest.approx((1.0, 0.3, 5.0), rel=1e-8)
    # how hard to throw along a given line: only the speed free, the direction kept
    stone = ss.Body(ss.Annulus(0.0595, 0.0655), ss.UniformPressure(), 19.96, 0.2113)
    ice = ss.FrictionTensor(0.0068, 0.0068)
    got = ss.aim(stone, ice, (0.0, 28.0), start=ss.State(vy=1.0, omega=0.7), free=("speed",))
    assert abs(got.vx) < 1e-12 and got.omega == 0.7
    stop = ss.simulate(stone, ice, got).stop_state
    assert abs(stop.x) < 1e-9 and abs(stop.y - 28.0) < 1e-9


def test_polar_and_cartesian_components_are_not_mixed():
    with pytest.raises(ValueError, match="mixes"):
        ss.aim(DISK, ISO, (1.0, 0.0), free=("vx", "speed"))


def test_polar_speed_may_turn_negative_and_direction_needs_a_speed():
    # a target behind the start on its line: the speed found is negative (thrown backwards)
    start = ss.State(vx=0.1, vy=0.05)
    got = ss.aim(DISK, ISO, (-1.0, -0.5), start=start, free=("speed",))
    stop = ss.simulate(DISK, ISO, got).stop_state
    assert abs(stop.x + 1.0) < 1e-9 and abs(stop.y + 0.5) < 1e-9
    with pytest.raises(ValueError, match="zero speed"):
        ss.aim(DISK, ISO, (1.0, 0.0), free=("direction",))
