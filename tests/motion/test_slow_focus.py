"""A direction that creeps towards its limit (a strongly skew tensor) ends as a marginal stop
at the fixed point, never at the step budget (found by tests/api/test_properties.py)."""

from __future__ import annotations

import math

import pytest

import slidespin as ss

BODY = ss.Body(ss.Ellipse(1.0, 0.96875), ss.HertzPressure(), 1.0, 0.484619140625)
SKEW = ss.FrictionTensor(1.0, 1.0625, 1.0)


@pytest.mark.parametrize("phi", [-1.25, -1.0, 2.0, 2.5])
def test_a_slow_approach_is_marginal_not_out_of_steps(phi):
    tr = ss.simulate(BODY, SKEW, ss.State.from_speed(1.0, 23.5, 0.0, phi))
    assert tr.status == "marginal" and tr.n_steps < 10_000
    # the same stop as from φ = 0, where the approach is recognised as marginal at once
    # (the body is nearly round: φ moves the stop by little), and the same at rtol 1e-12
    ref = ss.simulate(BODY, SKEW, ss.State.from_speed(1.0, 23.5, 0.0, 0.0))
    fine = ss.simulate(BODY, SKEW, ss.State.from_speed(1.0, 23.5, 0.0, phi), rtol=1e-12)
    assert ref.status == "marginal"
    assert tr.ending == ref.ending == fine.ending == "pure_spinning"
    assert tr.t_stop == pytest.approx(ref.t_stop, rel=1e-3)
    assert tr.t_stop == pytest.approx(fine.t_stop, rel=1e-8)
    assert tr.beta_stop == 0.0 and math.isfinite(tr.t_stop)
