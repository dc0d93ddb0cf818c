"""Springs to a moving anchor (MODEL §14): the spring–block tribometer and a block on a spring.

Independent truth: the point-mass closed forms of stick–slip (Popov, *Contact Mechanics and
Friction*, ch. 12), which a symmetric box pulled through G along an axis of symmetry obeys
exactly (it translates without turning): with ω₀ = √(k/m), Δ = (μs − μk) P/k and drive speed
V, the slip lasts (2/ω₀)(π − atan(Δ ω₀/V)), the stick 2Δ/V, the spring pulls μs P as a slip
starts and (2 μk − μs) P as it ends; a block released from a stretched spring swings half a period
π/ω₀ to −(x₀ − 2 μk P/k). The spring's force and moment written out here.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss

M, G = 1.0, 9.81
P = M * G
BOX = ss.Body(ss.Rectangle(0.02, 0.02), ss.UniformPressure(), mass=M)


def _slips(tr):
    return [(t0, t1) for kind, t0, t1 in tr.phases if kind == "slip"]


@pytest.mark.parametrize("k, v, mus, muk", [(100.0, 0.05, 0.45, 0.3), (400.0, 0.02, 0.6, 0.5)])
def test_spring_block_stick_slip_matches_the_point_mass_closed_forms(k, v, mus, muk):
    fr = ss.FrictionTensor(muk, muk, static=mus / muk)
    t_end = 6.0
    drive = ss.Spring(k, [(0.0, 0.0, 0.0), (t_end, v * t_end, 0.0)])
    tr = ss.simulate(BOX, fr, ss.State(), load=drive, t_end=t_end)
    assert tr.status == "ok"
    w0 = math.sqrt(k / M)
    delta = (mus - muk) * P / k
    slip = 2.0 / w0 * (math.pi - math.atan(delta * w0 / v))
    stick = 2.0 * delta / v
    slips = _slips(tr)
    assert len(slips) >= 3
    # the first stick: the spring stretches from 0 to μs P/k
    assert slips[0][0] == pytest.approx(mus * P / (k * v), abs=1e-9)
    for (a0, a1), (b0, _) in zip(slips, slips[1:]):
        assert a1 - a0 == pytest.approx(slip, abs=1e-8)
        assert b0 - a1 == pytest.approx(stick, abs=1e-8)
        assert b0 - a0 == pytest.approx(slip + stick, rel=1e-8)
    # the spring force: μs P where a slip starts, (2 μk − μs) P where it ends, and never
    # above μk P + k √(Δ² + (V/ω₀)²), the crest of the slip's oscillation
    force = k * (v * tr.t - tr.x)
    for (t0, t1), _ in zip(slips, slips[1:]):  # the slips that ended before t_end
        assert force[tr.t == t0][-1] == pytest.approx(mus * P, rel=1e-8)
        assert force[tr.t == t1][-1] == pytest.approx((2.0 * muk - mus) * P, rel=1e-7)
    crest = muk * P + k * math.hypot(delta, v / w0)
    assert mus * P < force.max() <= crest * (1 + 1e-9)
    assert np.max(np.abs(tr.phi)) < 1e-12 and np.max(np.abs(tr.y)) < 1e-12
    assert tr.energy_error < 1e-9 * P * v * t_end


def test_a_block_released_on_a_stretched_spring_swings_once_and_sticks():
    k, mus, muk, x0 = 100.0, 0.45, 0.3, 0.1
    fr = ss.FrictionTensor(muk, muk, static=mus / muk)
    tr = ss.simulate(BOX, fr, ss.State(x=x0), load=ss.Spring(k, [(0.0, 0.0, 0.0)]), t_end=2.0)
    w0 = math.sqrt(k / M)
    slips = _slips(tr)
    assert len(slips) == 1
    assert slips[0][0] == 0.0
    assert slips[0][1] == pytest.approx(math.pi / w0, abs=1e-9)
    assert tr.x[-1] == pytest.approx(-(x0 - 2.0 * muk * P / k), abs=1e-10)
    assert tr.ending == "stopped_stuck"


def test_a_spring_with_a_constant_load_starts_when_both_reach_the_static_force():
    k, v, mus, muk, f0 = 100.0, 0.05, 0.45, 0.3, 1.5
    fr = ss.FrictionTensor(muk, muk, static=mus / muk)
    loads = [ss.Spring(k, [(0.0, 0.0, 0.0), (2.0, 2.0 * v, 0.0)]), ss.Load((f0, 0.0))]
    tr = ss.simulate(BOX, fr, ss.State(), load=loads, t_end=1.5)
    assert _slips(tr)[0][0] == pytest.approx((mus * P - f0) / (k * v), abs=1e-9)


def test_a_damped_spring_keeps_the_energy_balance():
    fr = ss.FrictionTensor(0.3, 0.3, static=1.5)
    drive = ss.Spring(100.0, [(0.0, 0.0, 0.0), (3.0, 0.15, 0.0)], damping=2.0, at=(0.005, 0.0))
    tr = ss.simulate(BOX, fr, ss.State(), load=drive, t_end=3.0)
    assert tr.status == "ok" and len(_slips(tr)) >= 2
    assert tr.energy_error < 1e-9


def test_spring_force_and_moment_written_out():
    sp = ss.Spring(50.0, [(0.0, 1.0, 2.0), (2.0, 3.0, 2.0)], at=(0.1, 0.0), damping=3.0)
    # at t = 1 the anchor is at (2, 2) moving at (1, 0); G at (1.5, 1) with φ = π/2
    qx, qy, m = sp.wrench(1.0, 1.5, 1.0, math.pi / 2, 0.2, 0.0, 1.0, (0.0, 0.0))
    r = np.array([0.0, 0.1])  # R(π/2) (0.1, 0)
    p = np.array([1.5, 1.0]) + r
    vp = np.array([0.2, 0.0]) + 1.0 * np.array([-r[1], r[0]])
    q = -50.0 * (p - [2.0, 2.0]) - 3.0 * (vp - [1.0, 0.0])
    assert (qx, qy) == pytest.approx(tuple(q), abs=1e-12)
    assert m == pytest.approx(r[0] * q[1] - r[1] * q[0], abs=1e-12)
    # a rest length acts along the spring only
    sl = ss.Spring(10.0, [(0.0, 0.0, 0.0)], rest_length=0.5)
    assert sl.force(0.0, (0.0, 2.0), (5.0, 0.0)) == pytest.approx((0.0, -15.0), abs=1e-12)
    # the anchor is held beyond its path
    assert sp.anchor(-1.0) == (1.0, 2.0) and sp.anchor(9.0) == (3.0, 2.0)


@pytest.mark.parametrize(
    "make, match",
    [
        (lambda: ss.Spring(0.0, [(0, 0, 0)]), r"stiffness = 0\.0 .*is invalid"),
        (lambda: ss.Spring(1.0, [(0, 0)]), r"anchor_path = .* is invalid; valid values: rows"),
        (lambda: ss.Spring(1.0, [(0, 0, 0), (0, 1, 0)]), r"strictly increasing times"),
        (lambda: ss.Spring(1.0, [(0, 0, math.nan)]), r"anchor_path"),
        (lambda: ss.Spring(1.0, [(0, 0, 0)], at=(1.0,)), r"at = .* is invalid"),
        (lambda: ss.Spring(1.0, [(0, 0, 0)], damping=-1.0), r"damping = -1\.0"),
        (lambda: ss.Spring(1.0, [(0, 0, 0)], rest_length=-1.0), r"rest_length = -1\.0"),
    ],
)
def test_bad_springs_are_refused_naming_the_parameter(make, match):
    with pytest.raises(ValueError, match=match):
        make()


def test_a_bad_member_of_a_load_list_is_named():
    fr = ss.FrictionTensor(0.3, 0.3)
    with pytest.raises(ValueError, match=r"load\[1\] = 3 is invalid"):
        ss.simulate(BOX, fr, ss.State(), load=[ss.Load((1.0, 0.0)), 3], t_end=1.0)
