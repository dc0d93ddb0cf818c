"""Free motion under a speed-dependent law (MODEL §5, §14): ``simulate`` with
``FrictionTensor(..., speed_law=...)``.

Independent truth:
* closed forms on a uniform disk: a power law in pure translation (t_stop = v^(1+q) v0^(−q)/
  ((1+q) μ g), distance v^(2+q) v0^(−q)/((2+q) μ g)) and in pure spin (the same with the
  disk's torque 2 μ P R^(1−q) (ω/v0)^(−q)/(3 − q));
* a Stribeck law in pure translation: t_stop and the distance as one-dimensional integrals
  (scipy's ``quad``);
* a law whose factor is a constant r: the constant law's motion (the compiled integrator, a
  separate engine) with time, distance and turn divided by r, and the same β*;
* a power law's homogeneity: launching λ times faster stops λ^(1+q) later, λ^(2+q) farther;
* a plain integration in t of Newton–Euler with the public wrench (scipy's DOP853), compared
  at the recorded rows;
* mirror symmetry.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

import slidespin as ss

G = 9.81
DISK = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0)
BOX = ss.Body(ss.Rectangle(0.1, 0.06), ss.UniformPressure(), mass=1.5)


@pytest.mark.parametrize("q", [0.5, 0.2])
def test_power_law_disk_in_pure_translation_stops_as_the_closed_form(q):
    mu, v0, v = 0.3, 0.7, 2.0
    fr = ss.FrictionTensor(mu, mu, speed_law=ss.PowerLaw(q, v0))
    tr = ss.simulate(DISK, fr, ss.State(vx=v * 0.6, vy=v * 0.8))
    t_stop = v ** (1 + q) * v0 ** (-q) / ((1 + q) * mu * G)
    dist = v ** (2 + q) * v0 ** (-q) / ((2 + q) * mu * G)
    assert tr.status == "stopped" and tr.ending == "pure_sliding"
    assert tr.t_stop == pytest.approx(t_stop, rel=1e-9)
    assert math.hypot(tr.stop_state.x, tr.stop_state.y) == pytest.approx(dist, rel=1e-9)
    assert math.atan2(tr.stop_state.y, tr.stop_state.x) == pytest.approx(math.atan2(0.8, 0.6))


@pytest.mark.parametrize("q", [0.5, 0.3])
def test_power_law_disk_in_pure_spin_stops_as_the_closed_form(q):
    mu, v0, w, r = 0.3, 1.0, -25.0, 0.1
    fr = ss.FrictionTensor(mu, mu, speed_law=ss.PowerLaw(q, v0))
    tr = ss.simulate(DISK, fr, ss.State(omega=w))
    inertia = DISK.moment_of_inertia
    c = mu * G * 2.0 * r ** (1 - q) / (3 - q) * v0**q / inertia  # |ω̇| = c |ω|^(−q)
    assert tr.ending == "pure_spinning"
    assert tr.t_stop == pytest.approx(abs(w) ** (1 + q) / ((1 + q) * c), rel=1e-9)
    assert tr.stop_state.phi == pytest.approx(-(abs(w) ** (2 + q)) / ((2 + q) * c), rel=1e-9)
    assert abs(tr.stop_state.x) < 1e-12 and abs(tr.stop_state.y) < 1e-12


def test_stribeck_disk_in_pure_translation_against_quadrature():
    mu, v = 0.25, 1.5
    law = ss.Stribeck(1.6, 0.2, delta=1.5)
    fr = ss.FrictionTensor(mu, mu, speed_law=law)
    tr = ss.simulate(DISK, fr, ss.State(vx=v))

    def decel(u):
        return mu * G * (1.0 + 0.6 * math.exp(-((u / 0.2) ** 1.5)))

    t_stop = quad(lambda u: 1.0 / decel(u), 0.0, v, epsabs=0, epsrel=1e-13)[0]
    dist = quad(lambda u: u / decel(u), 0.0, v, epsabs=0, epsrel=1e-13)[0]
    assert tr.t_stop == pytest.approx(t_stop, rel=1e-9)
    assert tr.stop_state.x == pytest.approx(dist, rel=1e-9)


@pytest.mark.parametrize(
    "body, friction, state",
    [
        (BOX, ss.FrictionTensor(0.3, 0.42, 0.05, angle=0.4), ss.State(vx=1.0, vy=0.3, omega=8.0)),
        (
            ss.Body(ss.Ellipse(0.1, 0.05), ss.HertzPressure(), 1.0),
            ss.FrictionTensor(0.35, 0.3, frame="body"),
            ss.State(vx=0.5, vy=-0.4, omega=-12.0, phi=0.3),
        ),
        (
            ss.Body(ss.Annulus(0.06, 0.1), ss.UniformPressure(), 1.0),
            ss.FrictionTensor(0.3, 0.3),
            ss.State(vx=0.8, omega=10.0),
        ),
    ],
)
@pytest.mark.parametrize(
    "law, ratio",
    [(ss.Stribeck(1.4, 1e6), 1.4), (ss.SpeedTable([0.0, 1e3], [1.3, 1.3]), 1.3)],
)
def test_a_law_of_constant_factor_is_the_constant_law_of_the_scaled_tensor(
    body, friction, state, law, ratio
):
    """A factor r on every coefficient at every speed is the constant law with the tensor
    r 𝔽, which the compiled integrator (a separate engine) runs (for the Stribeck law with
    vs = 1e6 m/s the factor is 1.4 to 1e-12)."""
    f = friction
    scaled = ss.FrictionTensor(ratio * f.fx, ratio * f.fy, ratio * f.f, f.frame, f.angle)
    ref = ss.simulate(body, scaled, state, rtol=1e-12)
    lawed = ss.FrictionTensor(f.fx, f.fy, f.f, f.frame, f.angle, speed_law=law)
    tr = ss.simulate(body, lawed, state, rtol=1e-11)
    size = body.length_unit
    assert tr.status == "stopped"
    assert tr.ending == ref.ending
    assert tr.t_stop == pytest.approx(ref.t_stop, rel=1e-8)
    assert tr.stop_state.x == pytest.approx(ref.stop_state.x, abs=1e-9 * size)
    assert tr.stop_state.y == pytest.approx(ref.stop_state.y, abs=1e-9 * size)
    assert tr.stop_state.phi == pytest.approx(ref.stop_state.phi, abs=1e-8)
    if math.isfinite(ref.beta_stop):
        assert tr.beta_stop == pytest.approx(ref.beta_stop, rel=1e-6)


def test_power_law_homogeneity_scales_stop_time_and_distance():
    """An axisymmetric body under an isotropic tensor (the wrench does not depend on φ):
    a(λν) = λ^(−q) a(ν), so launching λ times faster stops λ^(1+q) later and λ^(2+q)
    farther, turned λ^(2+q) as much, along the same direction."""
    q, lam = 0.5, 2.5
    fr = ss.FrictionTensor(0.3, 0.3, speed_law=ss.PowerLaw(q, 0.5))
    body = ss.Body(ss.Annulus(0.05, 0.1), ss.UniformPressure(), 1.0)
    a = ss.simulate(body, fr, ss.State(vx=0.4, vy=0.1, omega=5.0), rtol=1e-11)
    b = ss.simulate(body, fr, ss.State(vx=0.4 * lam, vy=0.1 * lam, omega=5.0 * lam), rtol=1e-11)
    assert a.status == b.status == "stopped"
    assert b.t_stop == pytest.approx(lam ** (1 + q) * a.t_stop, rel=1e-8)
    assert b.stop_state.x == pytest.approx(lam ** (2 + q) * a.stop_state.x, rel=1e-8)
    assert b.stop_state.y == pytest.approx(lam ** (2 + q) * a.stop_state.y, rel=1e-8)
    assert b.stop_state.phi == pytest.approx(lam ** (2 + q) * a.stop_state.phi, rel=1e-8)
    assert b.beta_stop == pytest.approx(a.beta_stop, rel=1e-6)


def test_a_skewed_tensor_spirals_under_a_power_law_as_under_the_constant_law():
    """|f| = |μ|/2: the constant law's run ends in a spiral (no ϑ*); so does the power law's."""
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor(0.3, 0.4, 0.05)
    state = ss.State(vx=0.4, vy=0.1, omega=5.0)
    assert ss.simulate(body, fr, state).ending == "spiral"
    tr = ss.simulate(body, ss.FrictionTensor(0.3, 0.4, 0.05, speed_law=ss.PowerLaw(0.5)), state)
    assert (tr.status, tr.ending) == ("stopped", "spiral")
    assert math.isnan(tr.theta_stop) and math.isnan(tr.beta_stop)


@pytest.mark.parametrize(
    "law",
    [ss.Stribeck(1.5, 0.05), ss.PowerLaw(0.5, 1.0), ss.SpeedTable([0, 0.1, 0.4], [1.4, 1.1, 1.0])],
)
def test_rows_agree_with_a_plain_integration_in_time(law):
    """Newton–Euler in t with the public wrench (scipy's DOP853), to the rows of the
    regularised integration before the stop."""
    fr = ss.FrictionTensor(0.3, 0.4, 0.05, speed_law=law)
    state = ss.State(vx=1.0, vy=0.3, omega=8.0)
    tr = ss.simulate(BOX, fr, state, rtol=1e-11)
    m, inertia = BOX.mass, BOX.moment_of_inertia

    def rhs(t, y):
        w = ss.friction_wrench(BOX, fr, y[3], y[4], y[5], y[2], g=G)
        return [y[3], y[4], y[5], w.force_x / m, w.force_y / m, w.moment / inertia]

    pick = [i for i in range(len(tr.t)) if tr.t[i] < 0.6 * tr.t_stop][-1]
    t1 = tr.t[pick]
    sol = solve_ivp(rhs, (0.0, t1), [0, 0, 0, 1.0, 0.3, 8.0], method="DOP853", rtol=1e-11,
                    atol=1e-13)  # fmt: skip
    x, y, phi, vx, vy, om = sol.y[:, -1]
    assert tr.x[pick] == pytest.approx(x, abs=1e-9)
    assert tr.y[pick] == pytest.approx(y, abs=1e-9)
    assert tr.phi[pick] == pytest.approx(phi, abs=1e-8)
    assert tr.vx[pick] == pytest.approx(vx, abs=1e-8)
    assert tr.vy[pick] == pytest.approx(vy, abs=1e-8)
    assert tr.omega[pick] == pytest.approx(om, abs=1e-7)


def test_mirror_symmetry_of_an_isotropic_symmetric_body():
    fr = ss.FrictionTensor(0.3, 0.3, speed_law=ss.Stribeck(1.5, 0.1, delta=1.0))
    a = ss.simulate(BOX, fr, ss.State(vx=0.8, vy=0.3, omega=6.0))
    b = ss.simulate(BOX, fr, ss.State(vx=0.8, vy=-0.3, omega=-6.0))
    assert b.t_stop == pytest.approx(a.t_stop, rel=1e-9)
    assert b.stop_state.x == pytest.approx(a.stop_state.x, rel=1e-9)
    assert b.stop_state.y == pytest.approx(-a.stop_state.y, rel=1e-9)
    assert b.stop_state.phi == pytest.approx(-a.stop_state.phi, rel=1e-9)


def test_step_budget_and_rest_are_reported():
    fr = ss.FrictionTensor(0.3, 0.3, speed_law=ss.PowerLaw(0.5))
    tr = ss.simulate(BOX, fr, ss.State(vx=1.0, omega=3.0), max_steps=3)
    assert tr.status == "max_steps"
    assert np.all(np.isfinite(tr.x))
    rest = ss.simulate(BOX, fr, ss.State())
    assert rest.status == "at_rest" and rest.t_stop == 0.0
