"""``aim`` under loads, on slopes, with speed laws (MODEL §11, §15): its Jacobian there is by
central differences of whole simulations, the miss by ``simulate`` itself.

Independent truth: targets made by ``simulate`` from known launches (recovered to 1e-8, the
stop within 1e-9 m and rad), and the closed form of a disk sliding straight down a slope,
d = v²/(2 g (μ cos α − sin α)), which needs no integrator at all.
"""

from __future__ import annotations

import math

import pytest

import slidespin as ss

G = 9.81
BOX = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
DISK = ss.Body(ss.Disk(0.05), ss.UniformPressure(), mass=0.5)
ANISO = ss.FrictionTensor(0.3, 0.4)


def _rest(body, friction, start, **kw):
    """The pose where ``simulate`` has the body at rest (first stick, or at t_end)."""
    tr = ss.simulate(body, friction, start, G, 1e-10, **kw)
    assert tr.ending in ("stopped_stuck", "at_rest_throughout"), tr.ending
    return tr.x[-1], tr.y[-1], tr.phi[-1]


LOADED = {
    "slope": dict(incline=ss.Incline(0.15, downhill=0.5)),
    "constant push and torque": dict(load=ss.Load(force=(0.5, -0.3), torque=0.02)),
    "push in the body frame at a point": dict(
        load=ss.Load(force=(0.4, 0.0), frame="body", at=(0.05, 0.02))
    ),
    "a push that ends, with t_end": dict(
        load=ss.Load.piecewise_linear([0.0, 0.3, 0.6], [0.0, 1.5, 0.0], [0.0, 0.0, 0.0]),
        t_end=2.0,
    ),
    "slope and push": dict(incline=ss.Incline(0.1), load=ss.Load(force=(0.0, 0.6))),
}


@pytest.mark.parametrize("name", list(LOADED))
def test_aim_recovers_loaded_launches(name):
    kw = LOADED[name]
    launch = ss.State(vx=1.1, vy=0.4, omega=4.0)
    target = _rest(BOX, ANISO, launch, **kw)
    got = ss.aim(BOX, ANISO, target, g=G, **kw)
    assert (got.vx, got.vy, got.omega) == pytest.approx((1.1, 0.4, 4.0), rel=1e-8)
    x, y, phi = _rest(BOX, ANISO, got, **kw)
    assert max(abs(x - target[0]), abs(y - target[1]), abs(phi - target[2])) <= 1e-9


@pytest.mark.parametrize("alpha", [0.05, 0.2])
def test_a_disk_down_a_slope_against_the_closed_form(alpha):
    """Straight down the slope a disk translates (no spin): the launch speed that stops it
    at distance d is √(2 g (μ cos α − sin α) d)."""
    mu, d, downhill = 0.35, 0.8, 0.7
    slope = ss.Incline(alpha, downhill=downhill)
    start = ss.State(vx=math.cos(downhill), vy=math.sin(downhill))  # the line: downhill
    target = (d * math.cos(downhill), d * math.sin(downhill))
    got = ss.aim(DISK, ss.FrictionTensor(mu, mu), target, start=start, free=("speed",),
                 g=G, incline=slope)  # fmt: skip
    speed = math.hypot(got.vx, got.vy)
    assert speed == pytest.approx(math.sqrt(2 * G * (mu * math.cos(alpha) - math.sin(alpha)) * d),
                                  rel=1e-9)  # fmt: skip
    assert math.atan2(got.vy, got.vx) == pytest.approx(downhill, abs=1e-12)


def test_a_speed_law_aims_by_differences():
    body, fr = DISK, ss.FrictionTensor(0.3, 0.3, speed_law=ss.Stribeck(1.3, 0.2))
    launch = ss.State(vx=0.9, vy=-0.3)
    stop = ss.simulate(body, fr, launch, G, 1e-10).stop_state
    got = ss.aim(body, fr, (stop.x, stop.y), start=ss.State(), free=("vx", "vy"), g=G)
    assert (got.vx, got.vy) == pytest.approx((0.9, -0.3), rel=1e-8)


def test_a_slope_the_body_cannot_stop_on_is_refused_before_any_aiming():
    with pytest.raises(ValueError, match="need never stop") as info:
        ss.aim(BOX, ANISO, (1.0, 0.0), incline=ss.Incline(0.6))
    assert not isinstance(info.value, ss.UnreachableTarget)
    assert "incline" in str(info.value)


def test_unreachable_under_a_load_names_the_nearest_stop():
    """Spin alone cannot move the stop off the line a constant push drives it along."""
    kw = dict(load=ss.Load(force=(0.8, 0.0)))
    start = ss.State(vx=0.5)
    with pytest.raises(ss.UnreachableTarget) as info:
        ss.aim(DISK, ss.FrictionTensor(0.3, 0.3), (0.3, 0.2), start=start, free=("omega",),
               g=G, **kw)  # fmt: skip
    near = info.value.nearest
    assert abs(near.y) < 1e-9 and info.value.position_miss > 0.19


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        (dict(t_end=1.0), "t_end"),
        (dict(incline=0.1), "incline"),
        (dict(load=ss.Load.piecewise_linear([0.0, 1.0], [0.0, 1.0], [0.0, 0.0])), "t_end"),
    ],
)
def test_bad_loaded_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        ss.aim(BOX, ANISO, (0.5, 0.1), **kwargs)


def test_an_xy_target_far_under_a_push_is_hit_with_the_start_s_own_spin():
    """With (vx, vy, ω) free and no target angle every spin has a launch: the start's own
    (here none) is tried first, so the aim neither drifts into large spins nor stalls."""
    kw = dict(load=ss.Load(force=(0.3, 0.0)))
    got = ss.aim(BOX, ANISO, (3.0, 1.0), g=G, **kw)
    assert got.omega == 0.0
    x, y, _ = _rest(BOX, ANISO, got, **kw)
    assert max(abs(x - 3.0), abs(y - 1.0)) <= 1e-9


def test_a_launch_against_a_push_is_found():
    """A push that carries the body on: to stop behind the start it is launched backwards."""
    fr = ss.FrictionTensor(0.5, 0.5)
    kw = dict(
        load=ss.Load.piecewise_linear([0.0, 0.5, 1.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]),
        t_end=3.0,
    )
    x, y, _ = _rest(DISK, fr, ss.State(vx=-1.5), **kw)
    got = ss.aim(DISK, fr, (x, y), free=("vx",), g=G, **kw)
    assert got.vx == pytest.approx(-1.5, rel=1e-8)


def test_the_refusal_carries_the_load_factor_of_the_closed_form():
    """On a slope steeper than the friction angle the body need never stop: simulate (and so
    aim) says so with λ* = μ cos α / sin α along the downhill axis (fx along x here)."""
    from slidespin.motion.loaded import NeverStops

    with pytest.raises(NeverStops) as info:
        ss.simulate(BOX, ANISO, ss.State(), G, incline=ss.Incline(0.6))
    assert info.value.load_factor == pytest.approx(0.3 / math.tan(0.6), rel=1e-6)
