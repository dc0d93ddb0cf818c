"""The friction wrench against independent truth: the slow adaptive-quadrature reference
(tests/reference.py), closed forms and limits (MODEL §8), symmetry and invariance."""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss
from conftest import LAWS, make_law, state_with_icr
from reference import reference_dissipation, reference_wrench

TOL = 1e-10  # the contract: absolute, in units of m g and m g a with a = 1

# ICR positions in units of the semi-axes: (radius factor along a direction) -> kinds of state
ICR_CASES = {
    "deep inside": (0.23, -0.31),
    "centre": (0.0, 0.0),
    "near rim inside": ("rim", 0.7, 1 - 1e-7),
    "on rim (xi axis)": (1.0, 0.0),
    "on rim (eta axis)": (0.0, 1.0),
    "on rim (oblique)": ("rim", 2.2, 1.0),
    "near rim outside": ("rim", -2.5, 1 + 1e-7),
    "outside": (1.3, 0.9),
    "far": (-310.0, 95.0),
    "very far": (2.0e6, -3.0e6),
}


def icr_point(spec, a, b):
    if spec[0] == "rim":
        _, t, r = spec
        return r * a * math.cos(t), r * b * math.sin(t)
    return spec[0] * a, spec[1] * b


def tensor_matrix(fr: ss.FrictionTensor, phi: float) -> np.ndarray:
    return fr.world_matrix(phi)


def compare(body, fr, vx, vy, om, phi, tol=TOL):
    w = ss.friction_wrench(body, fr, vx, vy, om, phi, g=1.0)
    xc, yc = body.mass_centre
    ref = reference_wrench(
        body.patch.a,
        body.patch.b,
        body.pressure.name,
        tensor_matrix(fr, phi),
        phi,
        vx,
        vy,
        om,
        xi_c=xc,
        eta_c=yc,
        P=1.0,
    )
    got = np.array([w.force_x, w.force_y, w.moment / body.patch.a])
    want = np.array([ref[0], ref[1], ref[2] / body.patch.a])
    assert np.all(np.isfinite(got))
    assert np.max(np.abs(got - want)) < tol, (got, want, got - want)
    return w


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("where", list(ICR_CASES))
def test_wrench_matches_reference_ellipse(law, where):
    a, b = 1.0, 0.5
    body = ss.Body(ss.Ellipse(a, b), make_law(law, a, b), mass=1.0)
    fr = ss.FrictionTensor(0.42, 0.61, f=0.13)
    cx, cy = icr_point(ICR_CASES[where], a, b)
    phi = 0.37
    for om in (1.7, -0.9):
        vx, vy = state_with_icr(body, cx, cy, phi, om)
        compare(body, fr, vx, vy, om, phi)


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("where", ["deep inside", "on rim (oblique)", "near rim outside", "far"])
def test_wrench_matches_reference_circle_body_tensor(law, where):
    r = 1.0
    body = ss.Body(ss.Circle(r), make_law(law, r, r), mass=1.0)
    fr = ss.FrictionTensor(0.3, 0.8, f=-0.2, frame="body", angle=0.4)
    cx, cy = icr_point(ICR_CASES[where], r, r)
    phi = -1.1
    vx, vy = state_with_icr(body, cx, cy, phi, 2.3)
    compare(body, fr, vx, vy, 2.3, phi)


@pytest.mark.parametrize("law", LAWS)
def test_pure_translation_and_pure_spin_match_reference(law):
    body = ss.Body(ss.Ellipse(1.0, 0.6), make_law(law, 1.0, 0.6), mass=1.0)
    fr = ss.FrictionTensor(0.5, 0.35, f=0.07)
    compare(body, fr, 0.8, -0.3, 0.0, 0.9)  # omega = 0 exactly
    compare(body, fr, 0.0, 0.0, -1.4, 0.9)  # v = 0 exactly: ICR at G


@pytest.mark.parametrize("law", LAWS)
def test_pure_translation_closed_form(law):
    """ω = 0: F = −P 𝔽 v̂ and M = 0 since G lies over the pressure centroid (MODEL §8)."""
    body = ss.Body(ss.Ellipse(0.2, 0.07), make_law(law, 0.2, 0.07), mass=3.0)
    fr = ss.FrictionTensor(0.3, 0.5, f=0.1, angle=0.3)
    v = np.array([0.6, -0.8])
    w = ss.friction_wrench(body, fr, v[0], v[1], 0.0, 1.2, g=9.81)
    want = -3.0 * 9.81 * fr.world_matrix(1.2) @ v
    assert np.allclose([w.force_x, w.force_y], want, atol=1e-12, rtol=0)
    assert w.moment == 0.0


@pytest.mark.parametrize(
    "law, factor",
    [("uniform", 2.0 / 3.0), ("boussinesq", math.pi / 4.0), ("hertz", 3.0 * math.pi / 16.0)],
)
def test_pure_spin_of_a_disk(law, factor):
    """Spinning disk, isotropic friction: M = −sign(ω) f P a · factor, F = 0 (MODEL §8)."""
    a, f, m, g = 0.25, 0.37, 2.0, 9.81
    body = ss.Body(ss.Circle(a), make_law(law, a, a), mass=m)
    for om in (3.0, -0.5):
        w = ss.friction_wrench(body, ss.FrictionTensor.isotropic(f), 0.0, 0.0, om, 0.4, g=g)
        assert w.moment == pytest.approx(
            -math.copysign(1, om) * f * m * g * a * factor, abs=1e-12 * m * g * a
        )
        assert abs(w.force_x) < 1e-12 * m * g and abs(w.force_y) < 1e-12 * m * g


@pytest.mark.parametrize("law", LAWS)
def test_friction_power_equals_dissipation_integral(law):
    """F·v + M ω = −∫ p (w·𝔽_sym w)/|w| dS (MODEL §8), the right side from the reference."""
    a, b = 1.0, 0.45
    body = ss.Body(ss.Ellipse(a, b), make_law(law, a, b), mass=1.0)
    fr = ss.FrictionTensor(0.35, 0.7, f=0.25)
    for cx, cy, om in [(0.3, 0.1, 1.2), (1.8, -0.4, -0.7), (0.99, 0.0, 2.0)]:
        phi = 0.6
        vx, vy = state_with_icr(body, cx, cy, phi, om)
        w = ss.friction_wrench(body, fr, vx, vy, om, phi, g=1.0)
        diss = reference_dissipation(
            a,
            b,
            body.pressure.name,
            fr.world_matrix(phi),
            phi,
            vx,
            vy,
            om,
            xi_c=body.mass_centre[0],
            eta_c=body.mass_centre[1],
            P=1.0,
        )
        power = w.power(vx, vy, om)
        assert power < 0
        assert power == pytest.approx(-abs(diss), abs=1e-10 * (1 + abs(om)))


@pytest.mark.parametrize("law", LAWS)
def test_homogeneous_of_degree_zero(law, rng):
    body = ss.Body(ss.Ellipse(0.3, 0.2), make_law(law, 0.3, 0.2), mass=1.0)
    fr = ss.FrictionTensor(0.4, 0.6, f=0.1)
    for _ in range(5):
        vx, vy, om, phi = rng.normal(size=4)
        w1 = ss.friction_wrench(body, fr, vx, vy, om, phi)
        w2 = ss.friction_wrench(body, fr, 37.0 * vx, 37.0 * vy, 37.0 * om, phi)
        assert np.allclose(
            [w1.force_x, w1.force_y, w1.moment],
            [w2.force_x, w2.force_y, w2.moment],
            atol=1e-11,
            rtol=0,
        )


@pytest.mark.parametrize("law", LAWS)
def test_rotation_equivariance(law, rng):
    """Turning the whole set-up (body angle, velocity and plane tensor) by α turns F by α
    and leaves M unchanged."""
    body = ss.Body(ss.Ellipse(1.0, 0.4), make_law(law, 1.0, 0.4), mass=1.0)
    for _ in range(4):
        vx, vy, om, phi, alpha = rng.normal(size=5)
        fr = ss.FrictionTensor(0.3, 0.9, f=0.2, angle=0.1)
        fr_rot = ss.FrictionTensor(0.3, 0.9, f=0.2, angle=0.1 + alpha)
        c, s = math.cos(alpha), math.sin(alpha)
        w1 = ss.friction_wrench(body, fr, vx, vy, om, phi)
        w2 = ss.friction_wrench(body, fr_rot, c * vx - s * vy, s * vx + c * vy, om, phi + alpha)
        assert np.allclose(
            [c * w1.force_x - s * w1.force_y, s * w1.force_x + c * w1.force_y, w1.moment],
            [w2.force_x, w2.force_y, w2.moment],
            atol=1e-11,
            rtol=0,
        )


@pytest.mark.parametrize("law", LAWS)
def test_mirror_symmetry(law, rng):
    """Reflecting y → −y (φ → −φ, vy → −vy, ω → −ω, f → −f, ηc → −ηc) reflects F, flips M."""
    a, b = 1.0, 0.7
    for _ in range(4):
        vx, vy, om, phi = rng.normal(size=4)
        law1 = make_law(law, a, b)
        law2 = ss.LinearPressure(law1.xi_c, -law1.eta_c) if law == "linear" else law1
        b1 = ss.Body(ss.Ellipse(a, b), law1, mass=1.0)
        b2 = ss.Body(ss.Ellipse(a, b), law2, mass=1.0)
        w1 = ss.friction_wrench(b1, ss.FrictionTensor(0.3, 0.5, f=0.15), vx, vy, om, phi)
        w2 = ss.friction_wrench(b2, ss.FrictionTensor(0.3, 0.5, f=-0.15), vx, -vy, -om, -phi)
        assert np.allclose(
            [w1.force_x, -w1.force_y, -w1.moment],
            [w2.force_x, w2.force_y, w2.moment],
            atol=1e-11,
            rtol=0,
        )


def test_body_frame_tensor_is_plane_tensor_turned_with_the_body(rng):
    body = ss.Body(ss.Ellipse(1.0, 0.5), ss.HertzPressure(), mass=1.0)
    for _ in range(4):
        vx, vy, om, phi = rng.normal(size=4)
        wb = ss.friction_wrench(
            body, ss.FrictionTensor(0.2, 0.7, 0.1, "body", 0.3), vx, vy, om, phi
        )
        wp = ss.friction_wrench(
            body, ss.FrictionTensor(0.2, 0.7, 0.1, "plane", 0.3 + phi), vx, vy, om, phi
        )
        assert np.allclose(
            [wb.force_x, wb.force_y, wb.moment],
            [wp.force_x, wp.force_y, wp.moment],
            atol=1e-12,
            rtol=0,
        )


@pytest.mark.parametrize("law", LAWS)
def test_scale_invariance(law):
    """a → λa at fixed v/(aω): the force is unchanged and the moment scales with λ."""
    fr = ss.FrictionTensor(0.4, 0.55, f=0.05)
    w = []
    for scale in (1e-6, 1.0, 1e3):
        body = ss.Body(ss.Ellipse(scale, 0.6 * scale), make_law(law, scale, 0.6 * scale), 1.0)
        vx, vy = state_with_icr(body, 0.4 * scale, 0.5 * scale, 0.2, 1.0)
        r = ss.friction_wrench(body, fr, vx, vy, 1.0, 0.2, g=1.0)
        w.append([r.force_x, r.force_y, r.moment / scale])
    assert np.allclose(w[0], w[1], atol=1e-11, rtol=0)
    assert np.allclose(w[2], w[1], atol=1e-11, rtol=0)


def test_continuity_across_the_rim_and_towards_zero_spin():
    body = ss.Body(ss.Ellipse(1.0, 0.5), ss.BoussinesqPressure(), mass=1.0)
    fr = ss.FrictionTensor(0.3, 0.6, f=0.1)

    def w(cx, cy, om=1.0):
        vx, vy = state_with_icr(body, cx, cy, 0.0, om)
        r = ss.friction_wrench(body, fr, vx, vy, om, 0.0, g=1.0)
        return np.array([r.force_x, r.force_y, r.moment])

    t = 0.9
    on = w(math.cos(t), 0.5 * math.sin(t))
    for eps in (1e-4, 1e-7, 1e-10):
        for sgn in (-1, 1):
            near = w((1 + sgn * eps) * math.cos(t), (1 + sgn * eps) * 0.5 * math.sin(t))
            assert np.max(np.abs(near - on)) < 10 * eps + 1e-11
    # ω → 0 at fixed velocity: the wrench tends to the pure-translation one
    trans = ss.friction_wrench(body, fr, 1.0, 0.0, 0.0, 0.0, g=1.0)
    for om in (1e-3, 1e-6, 1e-9):
        r = ss.friction_wrench(body, fr, 1.0, 0.0, om, 0.0, g=1.0)
        assert abs(r.force_x - trans.force_x) + abs(r.force_y - trans.force_y) < 10 * om
        assert abs(r.moment) < 10 * om


def test_array_input_matches_scalar_calls(rng):
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.LinearPressure(0.01, 0.005), mass=2.0)
    fr = ss.FrictionTensor(0.3, 0.4, f=0.05)
    vx, vy, om = rng.normal(size=(3, 7))
    w = ss.friction_wrench(body, fr, vx, vy, om, 0.5)
    assert w.force_x.shape == (7,)
    for i in range(7):
        wi = ss.friction_wrench(body, fr, vx[i], vy[i], om[i], 0.5)
        assert (w.force_x[i], w.force_y[i], w.moment[i]) == (wi.force_x, wi.force_y, wi.moment)
    # paper components are the force along and across the velocity, with the paper's signs
    th = np.arctan2(vy, vx)
    assert np.allclose(w.tangential, -(w.force_x * np.cos(th) + w.force_y * np.sin(th)))
    assert np.allclose(w.normal, -(-w.force_x * np.sin(th) + w.force_y * np.cos(th)))
    assert np.array_equal(w.moment_paper, -w.moment)


def test_at_rest_the_wrench_is_zero():
    body = ss.Body(ss.Circle(1.0), ss.UniformPressure(), mass=1.0)
    w = ss.friction_wrench(body, ss.FrictionTensor(0.3, 0.3), 0.0, 0.0, 0.0)
    assert (w.force_x, w.force_y, w.moment) == (0.0, 0.0, 0.0)
