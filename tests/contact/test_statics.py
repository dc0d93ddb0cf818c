"""Static friction (MODEL §11): the set C, the thresholds of a disk, the onset direction.

Truth: closed forms (μ m g for a push; (2/3, 3π/16, π/4) μ m g R for a torque on a uniform,
Hertz and Boussinesq disk, MODEL §8), the force ellipse P·𝔽(unit disk) of an orthotropic
tensor, a direct 2-D quadrature of h(d) = ∫ p |𝔽ᵀ(d_F + d_M r′⊥)| dS with scipy's dblquad
(written apart from the image-patch method of the code), and the defining equation of the
onset evaluated with the public friction_wrench, and, for a uniform disk pushed off G, the
threshold and the onset twist at the threshold by a 1-D minimisation over rotation centres
of ∫|v| dA written in closed-form geometry (``off_centre_push_threshold``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import dblquad, quad
from scipy.optimize import minimize_scalar

import slidespin as ss
from slidespin.contact.static_set import support_function
from slidespin.contact.statics import OnsetNotFound, can_stick, load_factor, onset
from slidespin.contact.incline import Incline

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
        return (
            p * math.hypot(fw[0, 0] * cx + fw[1, 0] * cy, fw[0, 1] * cx + fw[1, 1] * cy) * a * b * r
        )

    return dblquad(f, 0.0, 2.0 * math.pi, 0.0, 1.0, epsabs=1e-11, epsrel=1e-11)[0]


def disk_distance_integral(c, r):
    """∫ over a disk of radius r of the distance to a point P at distance c ≥ 0 from its
    centre [m³], in polar coordinates about P (dA = ρ dρ dψ): the ray from P = (c, 0) in
    the direction ψ meets the circle at ρ± = −c cos ψ ± √(r² − c² sin² ψ), so the integral
    is ∫ (ρ₊³ − ρ₋³)/3 dψ (with ρ₋ replaced by 0 when P is inside)."""
    if c <= r:

        def f(psi):
            return (-c * math.cos(psi) + math.sqrt(r * r - (c * math.sin(psi)) ** 2)) ** 3 / 3.0

        return quad(f, 0.0, 2.0 * math.pi, epsabs=0.0, epsrel=1e-13, limit=200)[0]
    # P outside: rays within asin(r/c) of the centre; ρ₊³ − ρ₋³ = (ρ₊ − ρ₋)(4c² cos²ψ − c² + r²)
    # and sin ψ = (r/c) sin χ removes the square-root end points
    q = r / c

    def f(chi):
        cp = math.sqrt(1.0 - (q * math.sin(chi)) ** 2)
        return (
            2.0
            * r
            * math.cos(chi)
            * (4 * c * c * cp * cp - c * c + r * r)
            / 3.0
            * q
            * math.cos(chi)
            / cp
        )

    return 2.0 * quad(f, 0.0, math.pi / 2, epsabs=0.0, epsrel=1e-13, limit=200)[0]


def off_centre_push_threshold(r, mu, m, e, g=G):
    """Uniform isotropic disk pushed along x at the body point (0, e): the force F_c [N] at
    which it slips and the twist (vx, vy, ω) normal to C there (the onset at the threshold).

    The wrench per newton is (1, 0, −e). λ* = min over twists d of h(d)/(d·W) with
    h(d) = μ p ∫|v| dA (p = m g/(π r²)); by the mirror symmetry x → −x (which maps W to −W)
    the minimising twist has vy = 0, a rotation about (0, c) with c = vx/ω, so
    h = μ p |ω| ∫ dist(·, (0, c)) dA. Minimised over d = (cos θ, 0, sin θ/r).
    """
    p = m * g / (math.pi * r * r)

    def ratio(theta):
        s, c = math.sin(theta), math.cos(theta)
        den = c - e * s / r
        if s == 0.0:
            return mu * m * g / den
        return mu * p * abs(s) / r * disk_distance_integral(abs(r * c / s), r) / den

    edge = math.atan(e / r)
    res = minimize_scalar(
        ratio,
        bounds=(-math.pi / 2 - edge + 1e-6, math.pi / 2 - edge - 1e-6),
        method="bounded",
        options={"xatol": 1e-12},
    )
    return float(res.fun), np.array([math.cos(res.x), 0.0, math.sin(res.x) / r])


def test_disk_distance_integral_limits():
    r = 0.05
    assert disk_distance_integral(0.0, r) == pytest.approx(2 * math.pi * r**3 / 3, rel=1e-13)
    assert disk_distance_integral(r * (1 - 1e-12), r) == pytest.approx(
        disk_distance_integral(r * (1 + 1e-12), r), rel=1e-10
    )
    far = 1e4 * r  # a distant point sees the disk as its area at distance ≈ c (+ O(r²/c))
    assert disk_distance_integral(far, r) == pytest.approx(math.pi * r * r * far, rel=1e-8)


def test_off_centre_push_threshold_matches_an_independent_minimisation():
    r, mu, m, e = 0.05, 0.3, 1.0, 0.02
    disk = ss.Body(ss.Circle(r), ss.UniformPressure(), m)
    fr = ss.FrictionTensor.isotropic(mu)
    f_c, _ = off_centre_push_threshold(r, mu, m, e)
    # between the convex-hull (diamond) bound and the pure force and pure torque thresholds
    f_push, t_c = mu * m * G, 2.0 / 3.0 * mu * m * G * r
    assert 1.0 / (1.0 / f_push + e / t_c) < f_c < min(f_push, t_c / e)
    assert load_factor(disk, fr, (1.0, 0.0, -e), g=G) == pytest.approx(f_c, rel=1e-10)


def test_onset_at_the_threshold_exists_whatever_the_rounding():
    """Regression: a load on the boundary of C within round-off (where a ramped push starts
    the body) has the onset rate λ = 0⁺; its computed sign is round-off, and the onset was
    rejected ("no onset direction found") although the load factor was below 1."""
    r, mu, m, e = 0.05, 0.3, 1.0, 0.02
    disk = ss.Body(ss.Circle(r), ss.UniformPressure(), m)
    fr = ss.FrictionTensor.isotropic(mu)
    f_c, twist = off_centre_push_threshold(r, mu, m, e)
    ref = twist * [1.0, 1.0, r] / np.linalg.norm(twist * [1.0, 1.0, r])
    slipping = 0
    for j in range(-8, 9):
        f = f_c * (1.0 + j * 2.2e-16)
        w = (f, 0.0, -e * f)
        lf = load_factor(disk, fr, w, g=G)
        o = onset(disk, fr, w, g=G)
        assert (o is None) == (lf >= 1.0), (j, lf)
        if o is None:
            continue
        slipping += 1
        assert 0.0 <= o.acceleration < 1e-9
        got = o.twist * [1.0, 1.0, r] / np.linalg.norm(o.twist * [1.0, 1.0, r])
        np.testing.assert_allclose(got, ref, atol=1e-6)
    assert slipping >= 3


def test_onset_failure_is_a_clear_error(monkeypatch):
    import slidespin.contact.statics as st

    monkeypatch.setattr(st, "_onset_nat", lambda *args, **kwargs: None)
    disk = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    with pytest.raises(OnsetNotFound, match="no slip direction found .*load factor"):
        onset(disk, ss.FrictionTensor(0.3, 0.3), (5.0, 0.0, 0.0), g=G)


@pytest.mark.parametrize(
    "law, friction, d, phi",
    [
        (
            ss.LinearPressure(0.015, -0.008),
            ss.FrictionTensor(0.3, 0.5, 0.1, angle=0.4),
            (1.0, 0.3, 5.0),
            0.7,
        ),
        (
            ss.HertzPressure(),
            ss.FrictionTensor(0.2, 0.6, frame="body", angle=-0.3),
            (0.2, -1.0, 20.0),
            -1.2,
        ),
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
    [
        (ss.UniformPressure(), 2.0 / 3.0),
        (ss.HertzPressure(), 3.0 * math.pi / 16.0),
        (ss.BoussinesqPressure(), math.pi / 4.0),
    ],
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
    # the incline adds its downhill pull m g sin α (along +X here) and scales C by cos α
    pull = disk.mass * G * math.sin(0.5)
    lev = load_factor(disk, fr, (w[0] + pull, w[1], w[2]), g=G)
    tilt = load_factor(disk, fr, w, g=G, incline=Incline(0.5))
    assert tilt == pytest.approx(lev * math.cos(0.5), rel=1e-12)


def test_set_is_symmetric():
    body = ss.Body(ss.Ellipse(0.1, 0.05), ss.LinearPressure(0.01, 0.005), 1.0)
    fr = ss.FrictionTensor(0.3, 0.45, 0.08, angle=0.2)
    w = np.array([1.2, -0.4, 0.07])
    assert load_factor(body, fr, w, 0.3, g=G) == pytest.approx(
        load_factor(body, fr, -w, 0.3, g=G), rel=1e-10
    )


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
        (
            ss.Body(ss.Circle(0.05), ss.UniformPressure(), 2.0),
            ss.FrictionTensor(0.3, 0.3),
            (5.0, 1.0, -0.4),
            0.0,
        ),
        (
            ss.Body(ss.Ellipse(0.1, 0.05), ss.LinearPressure(0.01, 0.005), 2.0),
            ss.FrictionTensor(0.2, 0.5, 0.05, angle=0.3),
            (10.0, 0.0, 0.3),
            0.4,
        ),
    ],
)
def test_onset_solves_the_distributed_coulomb_start(body, friction, wrench, phi):
    """M⁻¹(W_a + W(û)) = λ û with λ > 0, checked with the public friction_wrench."""
    o = onset(body, friction, wrench, phi, g=G)
    vx, vy, om = o.twist
    w = ss.friction_wrench(body, friction, vx, vy, om, phi, g=G)
    m, inertia = body.mass, body.moment_of_inertia
    acc = np.array(
        [(wrench[0] + w.force_x) / m, (wrench[1] + w.force_y) / m, (wrench[2] + w.moment) / inertia]
    )
    twist = np.array([vx, vy, om])
    lam = float(acc @ (twist * [1, 1, inertia / m])) / float(twist @ (twist * [1, 1, inertia / m]))
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
    from slidespin.contact.statics import critical_tilt

    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.HertzPressure(), 1.0)
    assert critical_tilt(body, ss.FrictionTensor.isotropic(0.35), 1.1, 0.4) == pytest.approx(
        math.atan(0.35), rel=1e-12
    )
    # orthotropic, principal axes turned by 0.3: the force ellipse gives
    # tan α_c = 1/√((cos δ′/fx)² + (sin δ′/fy)²), δ′ = δ − 0.3
    fx, fy = 0.2, 0.5
    fr = ss.FrictionTensor(fx, fy, angle=0.3)
    for delta in (0.3, 1.0, 0.3 + math.pi / 2):
        dp = delta - 0.3
        expected = math.atan(1 / math.hypot(math.cos(dp) / fx, math.sin(dp) / fy))
        assert critical_tilt(body, fr, delta) == pytest.approx(expected, rel=1e-10)
