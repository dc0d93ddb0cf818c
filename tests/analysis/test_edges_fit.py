"""Fitting on a Blade (it used to fail on the blade's missing second moment), and the
tensor angle's bounds (FrictionTensor now refuses |angle| > 2π).

Independent truths: the known tensor of synthetic tracks (a dense simulation sampled by
plain linear interpolation, plus Gaussian noise), recovered within the reported errors.
"""

from __future__ import annotations

import functools
import math
import warnings

import numpy as np
import pytest

import slidespin as ss
from slidespin.analysis._fit_problem import _Problem
from slidespin.analysis.fit import FitWarning, fit

TRUE = ss.FrictionTensor(0.35, 0.55)
STATES = (
    ss.State.from_speed(1.0, 8.0, theta=0.6, phi=0.2),
    ss.State.from_speed(0.9, -10.0, theta=2.0, phi=1.0),
)
SIGMA = {"x": 1e-3, "y": 1e-3, "phi": 1e-2}


def blade():
    return ss.Body(ss.Blade(0.15), ss.UniformPressure(), mass=1.0)


@functools.cache
def dense(body, friction, state):
    return ss.simulate(body, friction, state, max_step=0.002)


def track(body, state, n, rng):
    tr = dense(body, TRUE, state)
    t = np.linspace(0.0, 1.05 * tr.t_stop, n)
    clean = {c: np.interp(t, tr.t, getattr(tr, c)) for c in ("x", "y", "phi")}
    return {"t": t, **{c: clean[c] + rng.normal(0.0, SIGMA[c], t.size) for c in clean}}


def test_a_blade_track_recovers_its_anisotropic_tensor():
    body = blade()
    rng = np.random.default_rng(3)
    runs = [track(body, st, 80, rng) for st in STATES]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FitWarning)
        res = fit(runs, body, ss.FrictionTensor(0.3, 0.3), free=("fx", "fy"))
    assert res.success
    for name, value in (("fx", 0.35), ("fy", 0.55)):
        assert abs(res.estimates[name] - value) < 3.0 * res.std_errors[name], name
        assert res.std_errors[name] < 0.02
    assert res.body.patch == body.patch


def test_the_blades_mass_centre_cannot_be_freed():
    body = blade()
    data = {"t": np.linspace(0.0, 0.1, 10), "x": np.zeros(10)}
    with pytest.raises(ValueError, match=r"xi_c, eta_c need a body with LinearPressure.*valid"):
        fit(data, body, TRUE, free=("fx", "xi_c"))


@pytest.mark.parametrize(
    "body", [blade(), ss.Body(ss.Ellipse(0.1, 0.05), ss.UniformPressure(), 1.0)]
)
def test_the_angle_is_bounded_by_the_tensors_range(body):
    """A trial angle never leaves [−2π, 2π], where FrictionTensor takes it."""
    run = {"t": np.linspace(0.0, 0.1, 10), "x": np.zeros(10)}
    prob = _Problem(
        [run], body, TRUE, ("angle",), [None], None, [ss.State(vx=1.0)], 9.81, 1e-10, None, 1e-4
    )
    assert prob.lb[0] == pytest.approx(-2.0 * math.pi) and prob.ub[0] == pytest.approx(
        2.0 * math.pi
    )
    for angle in (prob.lb[0], prob.ub[0]):
        _, fr = prob.objects({**prob.base, "angle": angle})
        assert fr.angle == angle
