"""``fit(..., jacobian="exact")`` (MODEL §15): the Jacobian from the motion's sensitivities
agrees with central differences of whole simulations, and the fit reaches the same
estimates and standard errors."""

from __future__ import annotations

import numpy as np
import pytest

import slidespin as ss
from slidespin.analysis._fit_problem import _Problem
from slidespin.analysis.fit_data import as_runs

BODY = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.LinearPressure(0.01, 0.0), mass=1.0)
TRUE = ss.FrictionTensor(0.42, 0.54, 0.04, angle=0.3)
STATES = (ss.State.from_speed(1.0, 6.0, theta=0.6, phi=0.2), ss.State(vx=-0.5, vy=0.8, omega=-7))


def _runs(n=80, sigma=(1e-3, 1e-3, 1e-2), seed=3):
    rng = np.random.default_rng(seed)
    runs = []
    for st in STATES:
        tr = ss.simulate(BODY, TRUE, st, max_step=0.002)
        t = np.linspace(0.0, 1.05 * tr.t_stop, n)
        runs.append({
            "t": t,
            "x": np.interp(t, tr.t, tr.x) + rng.normal(0, sigma[0], n),
            "y": np.interp(t, tr.t, tr.y) + rng.normal(0, sigma[1], n),
            "phi": np.interp(t, tr.t, tr.phi) + rng.normal(0, sigma[2], n),
        })  # fmt: skip
    return runs


@pytest.mark.parametrize(("max_step", "atol"), [(0.01, 1e-6), (None, 3e-4)])
def test_exact_jacobian_matches_differences(max_step, atol):
    # a dense path (max_step 0.01): the two agree to the differences' own error (~1e-7 of
    # each column); at the integrator's own steps the model between steps is the Hermite
    # interpolant, whose derivative differs from the interpolated derivative by ~1e-4 of
    # the column near the stop (both are fine for a fit: the residuals are the same)
    runs = as_runs(_runs())
    free = ("fx", "fy", "f", "angle", "xi_c", "moment_of_inertia")
    guess = [ss.State(st.x, st.y, st.phi, st.vx, st.vy, st.omega) for st in STATES]
    args = (runs, BODY, TRUE, free, [None, None], None, guess, 9.81, 1e-12, max_step, 1e-4)
    exact = _Problem(*args, "exact")
    diff = _Problem(*args, "differences")
    for prob in (exact, diff):
        prob.sigma = {"x": 1e-3, "y": 1e-3, "phi": 1e-2}
    p = exact.x0 * (1.0 + 0.01 * np.sign(exact.x0))  # off the truth
    Je, Jd = exact.jacobian(p), diff.jacobian(p)
    scale = np.max(np.abs(Jd), axis=0)
    assert np.all(scale > 0)
    np.testing.assert_allclose(Je / scale, Jd / scale, atol=atol)


def test_fit_with_the_exact_jacobian_reaches_the_same_estimates():
    runs = _runs()
    guess = ss.FrictionTensor(0.35, 0.35)
    a = ss.fit(runs, BODY, guess, jacobian="exact")
    b = ss.fit(runs, BODY, guess, jacobian="differences")
    for p in ("fx", "fy", "f"):
        assert a.estimates[p] == pytest.approx(b.estimates[p], abs=1e-3 * b.std_errors[p])
        assert a.std_errors[p] == pytest.approx(b.std_errors[p], rel=1e-4)
        assert abs(a.estimates[p] - getattr(TRUE, p)) < 5 * a.std_errors[p]


def test_bad_jacobian_option():
    with pytest.raises(ValueError, match="jacobian"):
        ss.fit(_runs(n=20), BODY, TRUE, jacobian="analytic")
