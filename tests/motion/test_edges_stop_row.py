"""The stop row of a Trajectory holds the limits along the motion (ϑ*, β*), not atan2(0, 0).

At the stop the velocity is zero, so its direction is no longer given by the state; the last
row must carry the limits, the same numbers as ``theta_stop`` and ``beta_stop``, in every
array that has one. The truths used here are independent of the integrator:

* symmetry: an axisymmetric patch under isotropic friction feels a friction force
  antiparallel to v (MODEL §2; the curling-stone result), so the direction ϑ of the velocity
  never changes: ϑ(t) = ϑ₀ up to and including the stop, for every ending;
* a heavy ring (I = 3 m R², beyond I₃ of Table 2) ends pure spinning: β* = 0, and the net
  force vanishes at a pure-spinning fixed point (A(u*) ∥ u* = (0, 0, ±1)), so F_τ, F_n → 0;
* the uniform disk with I* = 1/2 stops with β* = 0.653 a (Voyenli & Eriksen 1985; MODEL §8);
* a light disk ends pure sliding: β* = +∞;
* pure sliding under 𝔽 = c·I + f·J (a spiral ending): F_τ = c m g and F_n = −f m g at every
  instant, whatever the direction (v̂·𝔽v̂ = c, and the skew part is across v̂).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss

ISOTROPIC = ss.FrictionTensor(0.3, 0.3)


def heavy_ring(mass: float = 0.7) -> ss.Body:
    """A ring R = 10 cm, r = 8 cm with I = 3 m R² (a curling-stone-like heavy rim)."""
    return ss.Body(
        ss.Annulus(0.08, 0.1), ss.UniformPressure(), mass=mass, moment_of_inertia=3 * mass * 0.01
    )


@pytest.mark.parametrize("theta0", [math.pi / 2, 0.3, -2.0, 3.0])
@pytest.mark.parametrize("omega0", [30.0, -25.0])
def test_pure_spinning_stop_row_keeps_the_launch_direction(theta0, omega0):
    """The reported bug: a ring launched spinning ends spinning; ϑ at the stop is ϑ₀ (π/2 in
    the report), and the stop row used to read atan2(0, 0) = 0."""
    tr = ss.simulate(heavy_ring(), ISOTROPIC, ss.State.from_speed(1.0, omega0, theta0, phi=0.4))
    assert tr.status == "stopped" and tr.ending == "pure_spinning"
    # the limit itself, from symmetry (ϑ is constant along the whole motion)
    assert tr.theta_stop == pytest.approx(theta0, abs=1e-9)
    assert np.all(np.abs(tr.theta - theta0) < 1e-9), tr.theta[-3:]
    # the stop row is the limit, exactly the reported terminal values
    assert tr.theta[-1] == tr.theta_stop
    assert tr.beta[-1] == tr.beta_stop == 0.0
    assert tr.speed[-1] == 0.0 and tr.omega[-1] == 0.0
    # F_τ, F_n → 0 at a pure-spinning stop; M_paper is the braking moment of pure spin about
    # the centre, μ m g (2/3)(R³ − r³)/(R² − r²) for a uniformly loaded ring (MODEL §8)
    weight = tr.body.mass * tr.g
    assert abs(tr.tangential[-1]) <= 1e-12 * weight and abs(tr.normal[-1]) <= 1e-12 * weight
    spin_moment = 0.3 * weight * (2 / 3) * (0.1**3 - 0.08**3) / (0.1**2 - 0.08**2)
    assert tr.moment_paper[-1] == pytest.approx(math.copysign(spin_moment, omega0), rel=1e-8)


def test_stop_row_is_the_limit_in_every_export():
    """to_pandas and to_csv carry the same stop row (the arrays are the Trajectory's)."""
    pd = pytest.importorskip("pandas")
    tr = ss.simulate(heavy_ring(), ISOTROPIC, ss.State.from_speed(1.0, 30.0, math.pi / 2))
    df = tr.to_pandas()
    assert isinstance(df, pd.DataFrame)
    assert df["theta"].iloc[-1] == pytest.approx(math.pi / 2, abs=1e-9)
    last = tr.to_csv().strip().splitlines()[-1].split(",")
    assert float(last[tr.COLUMNS.index("theta")]) == tr.theta_stop


def test_mixed_stop_row_is_the_published_ratio():
    """Uniform disk, I* = 1/2: β*/a = 0.653 (published to 3 digits); ϑ ≡ ϑ₀ by symmetry."""
    disk = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0)
    tr = ss.simulate(disk, ISOTROPIC, ss.State.from_speed(1.0, 30.0, 0.3), max_step=0.2)
    assert tr.status == "stopped" and tr.ending == "mixed"
    assert tr.beta[-1] == tr.beta_stop
    assert tr.beta[-1] / 0.1 == pytest.approx(0.653, abs=5e-4)
    assert tr.theta[-1] == tr.theta_stop == pytest.approx(0.3, abs=1e-9)
    # the approach is continuous: the last recorded steps lead to the limit
    assert tr.beta[-2] / 0.1 == pytest.approx(0.653, abs=5e-3)


@pytest.mark.parametrize("omega0", [-5.0, 5.0])
def test_pure_sliding_stop_row_is_plus_infinity(omega0):
    """A light disk (I* = 0.02) ends pure sliding: β* = +∞ whatever the sign of the vanishing
    spin; ϑ ≡ ϑ₀ by symmetry."""
    disk = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0, moment_of_inertia=2e-4)
    tr = ss.simulate(disk, ISOTROPIC, ss.State.from_speed(1.0, omega0, 0.3))
    assert tr.status == "stopped" and tr.ending == "pure_sliding"
    assert tr.beta[-1] == tr.beta_stop == math.inf
    assert tr.theta[-1] == tr.theta_stop == pytest.approx(0.3, abs=1e-9)


def test_spiral_stop_row_has_no_direction_but_finite_forces():
    """𝔽 = c·I + f·J in pure sliding: the direction turns for ever, so ϑ has no limit (NaN
    at the stop, like ϑ*), while F_τ = c m g and F_n = −f m g hold at every instant."""
    c, f, m, g = 0.4, 0.3, 2.0, 9.81
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.HertzPressure(), mass=m)
    tr = ss.simulate(body, ss.FrictionTensor(c, c, f=f), ss.State.from_speed(1.5, 0.0, 0.7))
    assert tr.ending == "spiral" and math.isnan(tr.theta_stop)
    assert math.isnan(tr.theta[-1]) and np.all(np.isfinite(tr.theta[:-1]))
    assert tr.beta[-1] == tr.beta_stop == math.inf
    np.testing.assert_allclose(tr.tangential, c * m * g, rtol=1e-9)
    np.testing.assert_allclose(tr.normal, -f * m * g, rtol=1e-9)


def test_at_rest_has_no_direction():
    """A body at rest has no velocity direction: ϑ is NaN like ϑ* and β (was 0)."""
    disk = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0)
    tr = ss.simulate(disk, ISOTROPIC, ss.State(0.2, -0.1, 0.5))
    assert tr.status == "at_rest"
    assert math.isnan(tr.theta[-1]) and math.isnan(tr.theta_stop)
    assert math.isnan(tr.beta[-1]) and math.isnan(tr.beta_stop)
    assert tr.tangential[-1] == tr.normal[-1] == 0.0
