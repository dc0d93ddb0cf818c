"""Speed-dependent laws and the static ratio (MODEL §14): the value objects, the tensor's new
options, and the static set scaled by μs/μk.

Independent truth: the laws' formulas written out here; scipy's PCHIP for the table; closed
forms of the static set (a block on a slope slides at tan α = μs; a box pushed through G
starts at Q = μs P); the kinetic wrench unchanged by ``static`` and by a constant law, bit
for bit.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.interpolate import PchipInterpolator

import slidespin as ss

BOX = ss.Body(ss.Rectangle(0.1, 0.06), ss.UniformPressure(), mass=2.0)


def test_power_law_formula():
    law = ss.PowerLaw(0.5, 2.0)
    u = np.array([0.5, 2.0, 8.0])
    assert law.factor(u) == pytest.approx((u / 2.0) ** -0.5, rel=1e-15)
    assert law.factor(0.0) == math.inf
    assert ss.PowerLaw(0.0).factor(0.0) == 1.0


def test_stribeck_formula_and_limits():
    law = ss.Stribeck(1.6, 0.02, delta=1.5)
    u = np.array([0.0, 0.01, 0.02, 0.05, 10.0])
    expected = 1.0 + 0.6 * np.exp(-((u / 0.02) ** 1.5))
    assert law.factor(u) == pytest.approx(expected, rel=1e-15)
    assert law.factor(0.0) == pytest.approx(1.6, rel=1e-15)
    assert law.factor(100.0) == pytest.approx(1.0, rel=1e-15)


@pytest.mark.parametrize(
    "speeds, factors",
    [
        ([0.0, 0.01, 0.05, 0.2, 1.0], [1.5, 1.3, 1.05, 1.0, 0.95]),
        ([0.1, 0.3, 0.4, 0.9], [1.0, 1.2, 1.1, 1.3]),  # not monotone: PCHIP flattens turns
        ([0.0, 1.0], [2.0, 1.0]),
    ],
)
def test_speed_table_is_scipy_pchip_held_flat_outside(speeds, factors):
    law = ss.SpeedTable(speeds, factors)
    ref = PchipInterpolator(speeds, factors)
    u = np.linspace(speeds[0], speeds[-1], 997)
    assert law.factor(u) == pytest.approx(ref(u), rel=1e-13, abs=1e-14)
    assert law.factor(speeds[-1] * 3.0) == pytest.approx(factors[-1], rel=1e-15)
    assert law.factor(speeds[0] * 0.5) == pytest.approx(factors[0], rel=1e-15)


@pytest.mark.parametrize(
    "make, match",
    [
        (lambda: ss.PowerLaw(1.0), r"q = 1\.0 is invalid; valid range: \[0, 0\.95\]"),
        (lambda: ss.PowerLaw(-0.1), r"q = -0\.1 is invalid"),
        (lambda: ss.PowerLaw(0.5, 0.0), r"v0 = 0\.0 .*is invalid"),
        (lambda: ss.Stribeck(0.9, 0.1), r"static_ratio = 0\.9 is invalid; valid range: \[1, 100\]"),
        (lambda: ss.Stribeck(1.5, -1.0), r"vs = -1\.0 .*is invalid"),
        (lambda: ss.Stribeck(1.5, 0.1, delta=0.0), r"delta = 0\.0 is invalid"),
        (
            lambda: ss.SpeedTable([0.0], [1.0]),
            r"speeds = .* is invalid; valid values: a sequence of 2",
        ),
        (lambda: ss.SpeedTable([0.0, 0.0], [1.0, 1.0]), r"strictly increasing"),
        (lambda: ss.SpeedTable([-1.0, 0.0], [1.0, 1.0]), r"strictly increasing, from >= 0"),
        (lambda: ss.SpeedTable([0.0, 1.0], [1.0]), r"factors = .* one factor per speed"),
        (lambda: ss.SpeedTable([0.0, 1.0], [1.0, 0.0]), r"factors\[1\] = 0\.0 is invalid"),
        (lambda: ss.SpeedTable([0.0, math.nan], [1.0, 1.0]), r"speeds"),
        (lambda: ss.FrictionTensor(0.3, 0.3, static=0.5), r"static = 0\.5 is invalid"),
        (lambda: ss.FrictionTensor(3.0, 3.0, static=2.0), r"static = 2\.0 is invalid for fx"),
        (lambda: ss.FrictionTensor(0.3, 0.3, speed_law="ice"), r"speed_law = 'ice' is invalid"),
        (
            lambda: ss.FrictionTensor(0.3, 0.3, static=1.2, speed_law=ss.Stribeck(1.5, 0.1)),
            r"static = 1\.2 is invalid with speed_law",
        ),
    ],
)
def test_bad_laws_are_refused_naming_the_parameter(make, match):
    with pytest.raises(ValueError, match=match):
        make()


def test_stribeck_sets_the_static_ratio():
    t = ss.FrictionTensor(0.3, 0.4, speed_law=ss.Stribeck(1.5, 0.1))
    assert t.static == 1.5
    assert ss.FrictionTensor(0.3, 0.4, static=1.5, speed_law=ss.Stribeck(1.5, 0.1)) == t
    assert t.static_tensor.matrix == pytest.approx(1.5 * t.matrix, rel=1e-15)
    assert t.kinetic == ss.FrictionTensor(0.3, 0.4)


def test_repr_shows_new_options_only_when_set():
    assert repr(ss.FrictionTensor(0.3, 0.4)) == (
        "FrictionTensor(fx=0.3, fy=0.4, f=0.0, frame='plane', angle=0.0)"
    )
    r = repr(ss.FrictionTensor(0.3, 0.4, static=1.2, speed_law=ss.PowerLaw(0.5)))
    assert "static=1.2" in r and "speed_law=PowerLaw(q=0.5, v0=1.0)" in r


@pytest.mark.parametrize("body", [BOX, ss.Body(ss.Ellipse(0.1, 0.05), ss.HertzPressure(), 1.0)])
@pytest.mark.parametrize(
    "law", [None, ss.PowerLaw(0.0), ss.Stribeck(1.0, 0.1), ss.SpeedTable([0, 1], [1.0, 1.0])]
)
def test_a_constant_law_and_a_static_ratio_leave_the_kinetic_wrench_bit_for_bit(body, law):
    base = ss.FrictionTensor(0.3, 0.45, 0.05, angle=0.3)
    ratio = 1.0 if isinstance(law, ss.Stribeck) else 1.4  # a Stribeck law sets its own
    other = ss.FrictionTensor(0.3, 0.45, 0.05, angle=0.3, static=ratio, speed_law=law)
    vx = np.array([0.3, -1.0, 0.0, 2.0])
    vy = np.array([0.1, 0.2, 0.0, 0.0])
    om = np.array([4.0, 0.0, 3.0, -0.5])
    a = ss.friction_wrench(body, base, vx, vy, om, 0.4)
    b = ss.friction_wrench(body, other, vx, vy, om, 0.4)
    for name in ("force_x", "force_y", "moment"):
        assert np.array_equal(getattr(a, name), getattr(b, name))


def test_pure_translation_under_a_law_is_the_factor_times_the_constant_wrench():
    law = ss.Stribeck(1.5, 0.3, delta=2.0)
    fr = ss.FrictionTensor(0.3, 0.45, 0.05, speed_law=law)
    w = ss.friction_wrench(BOX, fr, 0.4, -0.3, 0.0, 0.2)
    w0 = ss.friction_wrench(BOX, fr.kinetic, 0.4, -0.3, 0.0, 0.2)
    gv = 1.0 + 0.5 * math.exp(-((0.5 / 0.3) ** 2))
    assert w.force_x == pytest.approx(gv * w0.force_x, rel=1e-14)
    assert w.force_y == pytest.approx(gv * w0.force_y, rel=1e-14)
    assert w.moment == pytest.approx(gv * w0.moment, rel=1e-13, abs=1e-15)


def test_a_speed_law_is_refused_where_it_does_not_run_yet():
    fr = ss.FrictionTensor(0.3, 0.3, speed_law=ss.PowerLaw(0.5))
    with pytest.raises(
        ValueError, match=r"speed_law = PowerLaw\(q=0\.5, v0=1\.0\) is not available"
    ):
        ss.limit_surface(BOX, fr)
    with pytest.raises(ValueError, match="speed_law"):
        ss.simulate(BOX, fr, ss.State(vx=1.0), load=ss.Load((1.0, 0.0)), t_end=1.0)
    blade = ss.Body(ss.Blade(0.1), ss.UniformPressure(), 1.0)
    with pytest.raises(ValueError, match="not available on a Blade"):
        ss.friction_wrench(blade, fr, 1.0, 0.0, 1.0)


# --- the static ratio: the static set is μs/μk times the kinetic one -----------------------


@pytest.mark.parametrize("ratio", [1.0, 1.5, 2.5])
def test_critical_tilt_of_a_block_is_atan_of_the_static_coefficient(ratio):
    fr = ss.FrictionTensor(0.3, 0.3, static=ratio)
    assert ss.critical_tilt(BOX, fr) == pytest.approx(math.atan(0.3 * ratio), rel=1e-9)


def test_can_stick_holds_up_to_the_static_coefficient():
    fr = ss.FrictionTensor(0.3, 0.3, static=1.5)
    p = BOX.mass * 9.81
    assert ss.can_stick(BOX, fr, (0.45 * p * (1 - 1e-9), 0.0, 0.0))
    assert not ss.can_stick(BOX, fr, (0.45 * p * (1 + 1e-9), 0.0, 0.0))
    assert ss.load_factor(BOX, fr, (0.3 * p, 0.0, 0.0)) == pytest.approx(1.5, rel=1e-9)


def test_a_static_tensor_scales_the_whole_static_set_of_an_anisotropic_body():
    kin = ss.FrictionTensor(0.25, 0.4, 0.05, angle=0.4)
    fr = ss.FrictionTensor(0.25, 0.4, 0.05, angle=0.4, static=1.3)
    ell = ss.Body(ss.Ellipse(0.1, 0.04), ss.UniformPressure(), 1.0)
    for d in [(1.0, 0.0, 0.0), (0.3, -1.0, 5.0), (0.0, 0.0, 1.0)]:
        h0, p0 = ss.contact.static_set.support_function(ell, kin, d, 0.3)
        h1, p1 = ss.contact.static_set.support_function(ell, fr, d, 0.3)
        assert h1 == pytest.approx(1.3 * h0, rel=1e-12)
        assert p1 == pytest.approx(1.3 * p0, rel=1e-12, abs=1e-15)


def test_a_ramped_push_starts_at_the_static_threshold_and_slides_under_kinetic_friction():
    """Q(t) = k t through G until 1 s, then down to 0 at 2 s: the box starts when k t = μs P
    and stops when ∫(Q − μk P) dt = 0 (a point mass: the push is through G)."""
    from scipy.integrate import quad
    from scipy.optimize import brentq

    m, g, k, mu, ratio = 2.0, 9.81, 20.0, 0.3, 1.5
    p = m * g
    fr = ss.FrictionTensor(mu, mu, static=ratio)
    load = ss.Load.piecewise_linear([0.0, 1.0, 2.0, 5.0], [0.0, k, 0.0, 0.0], [0.0] * 4)
    tr = ss.simulate(BOX, fr, ss.State(), load=load, t_end=4.0)
    t0 = ratio * mu * p / k

    def push(t):
        return k * t if t < 1.0 else max(k * (2.0 - t), 0.0)

    def speed(t):
        return quad(lambda s: (push(s) - mu * p) / m, t0, t, points=[1.0, 2.0], epsabs=1e-13)[0]

    t1 = brentq(speed, 1.0, 4.0, xtol=1e-13)
    kinds = [ph[0] for ph in tr.phases]
    assert kinds == ["stick", "slip", "stick"]
    assert tr.phases[1][1] == pytest.approx(t0, abs=1e-9)
    assert tr.phases[1][2] == pytest.approx(t1, abs=1e-8)
    # with static = 1 the same push starts earlier, at μk P / k
    tr1 = ss.simulate(BOX, fr.kinetic, ss.State(), load=load, t_end=4.0)
    assert tr1.phases[1][1] == pytest.approx(mu * p / k, abs=1e-9)
