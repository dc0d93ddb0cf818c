"""What the docstrings of simulate now promise: a Blade (a line contact) runs, free and loaded,
and a load works on any patch (not only ellipses and circles).

Closed forms (a translating body has every point at the velocity of G, so under isotropic
friction F = −μ m g v̂ and, G lying over the centre of the load, M = 0: MODEL §8):

* free: the blade slides straight, decelerating at μ g: t_stop = v₀/(μ g), distance
  v₀²/(2 μ g), no turning;
* pulled from rest by a constant force Q > μ m g at G along x: a = Q/m − μ g, so at t_end
  v = a t_end and x = a t_end²/2.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss
from slidespin.motion import simulate as simulate_module

MU, G, M = 0.3, 9.81, 1.5


def blade() -> ss.Body:
    return ss.Body(ss.Blade(0.3, angle=0.4), ss.UniformPressure(), mass=M)


@pytest.mark.parametrize("theta0", [0.0, 0.4, 2.0])
def test_free_blade_slides_to_the_closed_form_stop(theta0):
    v0 = 1.2
    tr = ss.simulate(blade(), ss.FrictionTensor.isotropic(MU), ss.State.from_speed(v0, 0.0, theta0))
    # along the blade (θ₀ = 0.4 = its angle) the pure-sliding fixed point is marginal: a
    # converged stop with the analytic limit, like "stopped"
    assert tr.status in ("stopped", "marginal")
    assert tr.t_stop == pytest.approx(v0 / (MU * G), rel=1e-9)
    assert tr.distance == pytest.approx(v0**2 / (2 * MU * G), rel=1e-9)
    assert tr.stop_state.x == pytest.approx(tr.distance * math.cos(theta0), abs=1e-9)
    assert tr.stop_state.y == pytest.approx(tr.distance * math.sin(theta0), abs=1e-9)
    assert np.all(np.abs(tr.omega) < 1e-12) and abs(tr.stop_state.phi) < 1e-12


@pytest.mark.parametrize(
    "patch",
    [ss.Blade(0.3), ss.Annulus(0.05, 0.1), ss.Rectangle(0.2, 0.1), ss.Ellipse(0.1, 0.05)],
    ids=["blade", "annulus", "rectangle", "ellipse"],
)
def test_a_load_works_on_any_patch(patch):
    q, t_end = 2.0 * MU * M * G, 0.5
    body = ss.Body(patch, ss.UniformPressure(), mass=M)
    tr = ss.simulate(
        body, ss.FrictionTensor.isotropic(MU), ss.State(), load=ss.Load(force=(q, 0.0)), t_end=t_end
    )
    acc = q / M - MU * G
    assert tr.status == "ok"
    assert tr.vx[-1] == pytest.approx(acc * t_end, rel=1e-7)
    assert tr.x[-1] == pytest.approx(0.5 * acc * t_end**2, rel=1e-7)
    assert abs(tr.vy[-1]) < 1e-9 and abs(tr.omega[-1]) < 1e-9


def test_docstrings_do_not_refuse_what_runs():
    """The claims that were false (a Blade refused; loads on ellipses and circles only)."""
    text = (simulate_module.__doc__ or "") + (ss.simulate.__doc__ or "")
    assert "Blade" in text
    assert "refused with a ``ValueError``), pressure law" not in text
    assert "ellipses and circles for now" not in text
