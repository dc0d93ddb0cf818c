"""Static friction (MODEL §11): the set C, the thresholds of a disk, the onset direction.

Truth: closed forms (μ m g for a push; (2/3, 3π/16, π/4) μ m g R for a torque on a uniform,
Hertz and Boussinesq disk, MODEL §8), the force ellipse P·𝔽(unit disk) of an orthotropic
tensor, a direct 2-D quadrature of h(d) = ∫ p |𝔽ᵀ(d_F + d_M r′⊥)| dS with scipy's dblquad
(written apart from the image-patch method of the code), and the defining equation of the
onset evaluated with the public friction_wrench.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import dblquad

import slidespin as ss
from slidespin.loads import Incline
from slidespin.statics import can_stick, load_factor, onset, support_function

G = 9.81


def h_dblquad(body, friction, d, phi):
    """h(d) by adaptive 2-D quadrature over the patch (polar coordinates of the ellipse)."""
    a, b = body.patch.a, body.patch.b
    xg, yg = body.mass_centre
    fw = friction.world_matrix(phi)
    c, s = math.cos(phi), math.sin(phi)
    load = body.mass * G

    def f(r, t):
        xi, eta = a * r * math.cos(t), b * r * math.sin(t)
        p = float(body.pressure.density(body.patch, xi, eta, load))
        x, y = c * (xi - xg) - s * (eta - yg), s * (xi - xg) + c * (eta - yg)
        cx, cy = d[0] - d[2] * y, d[1] + d[2] * x
        return p * math.hypot(fw[0, 0] * cx + fw[1, 0] * cy, fw[0, 1] * cx + fw[1, 1] * cy) * a * b * r

    return dblquad(f, 0.0, 2.0 * math.pi, 0.0, 1.0, epsabs=1e-11, epsrel=1e-11)[0]


@pytest.mark.parametrize(
    "law, friction, d, phi",
    [
        (ss.LinearPressure(0.015, -0.008), ss.FrictionTensor(0.3, 0.5, 0.1, angle=0.4),
         (1.0, 0.3, 5.0), 0.7),
        (ss.HertzPressure(), ss.FrictionTensor(0.2, 0.6, frame="body", angle=-0.3),
         (0.2, -1.0, 20.0), -1.2),
    ],
)
def test_support_function_matches_direct_quadrature(law, friction, d, phi):
    body = ss.Body(ss.Ellipse(0.1, 0.06), law, 2.0)
    h, _ = support_function(body, friction, d, phi, g=G)
    assert h == pytest.approx(h_dblquad(body, friction, d, phi), rel=1e-9)


def test_support_point_is_the_gradient_and_lies_on_the_supporting_plane():
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.UniformPressure(), 2.0)
    fr = ss.FrictionTensor(0.25, 0.55, 0.05)
    d = np.array([0.4, -0.7, 12.0])
    h, point = support_function(body, fr, d, 0.3, g=G)
    assert float(point @ d) == pytest.approx(h, rel=1e-12)  # Euler: h(d) = d·∇h(d)
    for i, step in enumerate((1e-5, 1e-5, 1e-3)):
        e = np.zeros(3)
        e[i] = step
        hp, _ = support_function(body, fr, d + e, 0.3, g=G)
        hm, _ = support_function(body, fr, d - e, 0.3, g=G)
        assert (hp - hm) / (2 * step) == pytest.approx(point[i], rel=1e-6, abs=1e-9)


@pytest.mark.parametrize("mu", [0.2, 0.7])
def test_disk_push_threshold_is_mu_m_g(mu):
    disk = ss.Body(ss.Circle(0.08), ss.UniformPressure(), 1.5)
    fr = ss.FrictionTensor.isotropic(mu)
    p = mu * 1.5 * G
    assert load_factor(disk, fr, (p * 0.6, p * 0.8, 0.0), g=G) == pytest.approx(1.0, rel=1e-12)
    assert can_stick(disk, fr, (p * (1 - 1e-9), 0.0, 0.0), g=G)
    assert not can_stick(disk, fr, (p * (1 + 1e-9), 0.0, 0.0), g=G)


@pytest.mark.parametrize(
    "law, constant",
    [(ss.UniformPressure(), 2.0 / 3.0), (ss.HertzPressure(), 3.0 * math.pi / 16.0),
     (ss.BoussinesqPressure(), math.pi / 4.0)],
)
def test_disk_torque_threshold(law, constant):
    r, m, mu = 0.05, 2.0, 0.35
    disk = ss.Body(ss.Circle(r), law, m)
    fr = ss.FrictionTensor.isotropic(mu)
    t_c = constant * mu * m * G * r
    assert load_factor(disk, fr, (0.0, 0.0, -t_c), g=G) == pytest.approx(1.0, rel=1e-11)
    assert can_stick(disk, fr, (0.0, 0.0, t_c * (1 - 1e-9)), g=G)
    assert not can_stick(disk, fr, (0.0, 0.0, t_c * (1 + 1e-9)), g=G)


def test_orthotropic_push_threshold_is_the_axis_coefficient():
    body = ss.Body(ss.Ellipse(0.1, 0.07), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor(0.2, 0.5)
    p = 1.0 * G
    assert load_factor(body, fr, (0.2 * p, 0.0, 0.0), g=G) == pytest.approx(1.0, rel=1e-11)
    assert load_factor(body, fr, (0.0, 0.5 * p, 0.0), g=G) == pytest.approx(1.0, rel=1e-11)
    # the force-only section of C is the ellipse P 𝔽(unit disk): (Qx/fx)² + (Qy/fy)² = P²
    t = 0.7
    q = (0.2 * p * math.cos(t), 0.5 * p * math.sin(t), 0.0)
    assert load_factor(body, fr, q, g=G) == pytest.approx(1.0, rel=1e-10)


def test_incline_scales_the_set_by_cos_alpha():
    disk = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor.isotropic(0.4)
    w = (1.0, 0.5, 0.02)
    lev = load_factor(disk, fr, w, g=G)
    tilt = load_factor(disk, fr, w, g=G, incline=Incline(0.5))
    assert tilt == pytest.approx(lev * math.cos(0.5), rel=1e-12)


def test_set_is_symmetric():
    body = ss.Body(ss.Ellipse(0.1, 0.05), ss.LinearPressure(0.01, 0.005), 1.0)
    fr = ss.FrictionTensor(0.3, 0.45, 0.08, angle=0.2)
    w = np.array([1.2, -0.4, 0.07])
    assert load_factor(body, fr, w, 0.3, g=G) == pytest.approx(
        load_factor(body, fr, -w, 0.3, g=G), rel=1e-10)


def test_zero_load_sticks():
    disk = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    assert load_factor(disk, ss.FrictionTensor(0.3, 0.3), (0, 0, 0)) == math.inf
    assert onset(disk, ss.FrictionTensor(0.3, 0.3), (0.1, 0, 0)) is None


def test_pure_push_starts_along_the_push():
    disk = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 2.0)
    fr = ss.FrictionTensor.isotropic(0.3)
    q = 0.3 * 2.0 * G * 1.5
    o = onset(disk, fr, (0.6 * q, 0.8 * q, 0.0), g=G)
    np.testing.assert_allclose(o.direction, [0.6, 0.8, 0.0], atol=1e-12)
    assert o.acceleration == pytest.approx((q - 0.3 * 2.0 * G) / 2.0, rel=1e-12)


@pytest.mark.parametrize(
    "body, friction, wrench, phi",
    [
        (ss.Body(ss.Circle(0.05), ss.UniformPressure(), 2.0), ss.FrictionTensor(0.3, 0.3),
         (5.0, 1.0, -0.4), 0.0),
        (ss.Body(ss.Ellipse(0.1, 0.05), ss.LinearPressure(0.01, 0.005), 2.0),
         ss.FrictionTensor(0.2, 0.5, 0.05, angle=0.3), (10.0, 0.0, 0.3), 0.4),
    ],
)
def test_onset_solves_the_distributed_coulomb_start(body, friction, wrench, phi):
    """M⁻¹(W_a + W(û)) = λ û with λ > 0, checked with the public friction_wrench."""
    o = onset(body, friction, wrench, phi, g=G)
    vx, vy, om = o.twist
    w = ss.friction_wrench(body, friction, vx, vy, om, phi, g=G)
    m, inertia = body.mass, body.moment_of_inertia
    acc = np.array([(wrench[0] + w.force_x) / m, (wrench[1] + w.force_y) / m,
                    (wrench[2] + w.moment) / inertia])
    twist = np.array([vx, vy, om])
    lam = float(acc @ (twist * [1, 1, inertia / m])) / float(
        twist @ (twist * [1, 1, inertia / m]))
    np.testing.assert_allclose(acc, lam * twist, rtol=0, atol=1e-10 * np.abs(acc).max())
    assert lam > 0 and o.acceleration == pytest.approx(lam, rel=1e-9)
    # a force with a torque starts a mixed motion, not along the load
    assert abs(om) > 0 and abs(vx) > 0


def test_validation_messages():
    disk = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor(0.3, 0.3)
    with pytest.raises(ValueError, match="applied_wrench"):
        load_factor(disk, fr, (1.0, 2.0))
    with pytest.raises(ValueError, match="applied_wrench"):
        can_stick(disk, fr, (1.0, math.nan, 0.0))
    with pytest.raises(ValueError, match="body"):
        onset("disk", fr, (1.0, 0.0, 0.0))
    with pytest.raises(ValueError, match="incline"):
        load_factor(disk, fr, (1.0, 0.0, 0.0), incline=0.3)


def test_critical_tilt_is_the_friction_angle_of_the_downhill_direction():
    from slidespin.statics import critical_tilt

    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.HertzPressure(), 1.0)
    assert critical_tilt(body, ss.FrictionTensor.isotropic(0.35), 1.1, 0.4) == pytest.approx(
        math.atan(0.35), rel=1e-12)
    # orthotropic, principal axes turned by 0.3: the force ellipse gives
    # tan α_c = 1/√((cos δ′/fx)² + (sin δ′/fy)²), δ′ = δ − 0.3
    fx, fy = 0.2, 0.5
    fr = ss.FrictionTensor(fx, fy, angle=0.3)
    for delta in (0.3, 1.0, 0.3 + math.pi / 2):
        dp = delta - 0.3
        expected = math.atan(1 / math.hypot(math.cos(dp) / fx, math.sin(dp) / fy))
        assert critical_tilt(body, fr, delta) == pytest.approx(expected, rel=1e-10)
