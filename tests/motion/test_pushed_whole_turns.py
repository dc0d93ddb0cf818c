"""A pushed run started at φ + 2πk is the run started at φ, turned k whole times (found by
fuzzing: a start angle of 1e12 rad made the engines turn the body on the last digits of its
angle and run for minutes)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss

BOX = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
ISO = ss.FrictionTensor(0.3, 0.3)
FINGER = ss.PointPusher([(0.0, -0.3, 0.02), (2.0, 0.2, 0.02)], mu=0.3)
FLAT = ss.LinePusher(0.05, [(0.0, -0.3, 0.0, math.pi / 2), (2.0, 0.2, 0.0, math.pi / 2)], mu=0.3)
TURNS = 2.0 * math.pi * 1e5


@pytest.mark.parametrize("pusher", [FINGER, FLAT], ids=["finger", "line"])
def test_whole_turns_of_the_start_angle_change_nothing_but_phi(pusher):
    big = 0.3 + TURNS
    small = big - TURNS  # the same angle, exactly (0.3 to ~1e-10: a push amplifies that)
    a = ss.simulate(BOX, ISO, ss.State(phi=small), pusher=pusher, t_end=2.5)
    b = ss.simulate(BOX, ISO, ss.State(phi=big), pusher=pusher, t_end=2.5)
    assert a.status == b.status == "ok"
    np.testing.assert_array_equal(b.x, a.x)
    np.testing.assert_array_equal(b.y, a.y)
    np.testing.assert_allclose(b.phi - TURNS, a.phi, atol=1e-9)
    qa = ss.push_quasi_static(BOX, ISO, pusher, [0.0, 1.0, 2.0], start=(0.0, 0.0, small))
    qb = ss.push_quasi_static(BOX, ISO, pusher, [0.0, 1.0, 2.0], start=(0.0, 0.0, big))
    np.testing.assert_array_equal(qb.x, qa.x)
    np.testing.assert_allclose(qb.phi - TURNS, qa.phi, atol=1e-9)


def test_a_huge_start_angle_runs_like_any_other():
    tr = ss.simulate(BOX, ISO, ss.State(phi=1e12), pusher=FINGER, t_end=2.5)
    assert tr.status == "ok" and tr.relative_energy_error < 1e-9
    assert len(tr.t) < 2000
    qs = ss.push_quasi_static(BOX, ISO, FINGER, [0.0, 2.0], start=(0.0, 0.0, 1e12))
    assert qs.status == "ok"
