"""Edge states: finite, correct answers where naive methods break (issue: hardening)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss
from conftest import make_law, state_with_icr
from reference import reference_wrench


def check(body, fr, cx, cy, om=1.3, phi=0.4, tol=1e-10):
    vx, vy = state_with_icr(body, cx, cy, phi, om)
    w = ss.friction_wrench(body, fr, vx, vy, om, phi, g=1.0)
    xc, yc = body.mass_centre
    r = reference_wrench(
        body.patch.a,
        body.patch.b,
        body.pressure.name,
        fr.world_matrix(phi),
        phi,
        vx,
        vy,
        om,
        xi_c=xc,
        eta_c=yc,
        P=body.mass,
    )
    a = body.patch.a
    got = np.array([w.force_x, w.force_y, w.moment / a]) / body.mass
    want = np.array([r[0], r[1], r[2] / a]) / body.mass
    assert np.all(np.isfinite(got))
    assert np.max(np.abs(got - want)) < tol * max(1.0, fr.norm), (got, want)


@pytest.mark.parametrize("law", ["uniform", "boussinesq", "hertz"])
@pytest.mark.parametrize(
    "icr", [(0.2, 3e-4), (0.5, 0.0), (1.0, 0.0), (0.0, 1e-3), (0.3, 0.01), (2.0, 0.1)]
)
def test_very_flat_ellipse(law, icr):
    """b/a = 1e-3 (a blade): ICR inside, on the rim, on the short axis's rim, outside."""
    a, b = 1.0, 1e-3
    body = ss.Body(ss.Ellipse(a, b), make_law(law, a, b), mass=1.0)
    check(body, ss.FrictionTensor(0.3, 0.5, f=0.1), icr[0] * a, icr[1])


@pytest.mark.parametrize(
    "fr",
    [
        ss.FrictionTensor(0.01, 1.0),
        ss.FrictionTensor(1.0, 0.01, angle=0.7),
        ss.FrictionTensor(0.1, 0.2, f=0.5),
        ss.FrictionTensor(0.2, 0.3, f=-3.0, frame="body"),
    ],
    ids=["fy/fx=100", "fx/fy=100", "|f|>fx", "|f|>>fx body"],
)
@pytest.mark.parametrize("icr", [(0.2, 0.1), (1.0, 0.0), (0.7, -0.36), (3.0, 1.0)])
def test_extreme_anisotropy(fr, icr):
    body = ss.Body(ss.Ellipse(1.0, 0.5), ss.HertzPressure(), mass=1.0)
    check(body, fr, *icr)


@pytest.mark.parametrize("a", [1e-6, 1e3])
@pytest.mark.parametrize("law", ["uniform", "linear", "boussinesq", "hertz"])
def test_tiny_and_huge_patches(a, law):
    body = ss.Body(ss.Ellipse(a, 0.6 * a), make_law(law, a, 0.6 * a), mass=1.0)
    for icr in [(0.3 * a, 0.2 * a), (a, 0.0), (2.0 * a, -a)]:
        check(body, ss.FrictionTensor(0.3, 0.45, f=0.05), *icr, om=7.0 / a)


def test_ten_thousand_rotations_before_stopping():
    """Pure spin of a disk under an orthotropic tensor: M = −(2/3) P a (fx + fy)/2, so it
    turns I ω₀²/(2|M|) radians; chosen to be 10⁴ turns."""
    a, fx, fy, m = 0.1, 0.3, 0.5, 1.0
    body = ss.Body(ss.Circle(a), ss.UniformPressure(), m)
    torque = 2.0 / 3.0 * m * 9.81 * a * (fx + fy) / 2.0
    inertia = body.moment_of_inertia
    w0 = math.sqrt(2.0 * torque * 2.0 * math.pi * 1e4 / inertia)
    tr = ss.simulate(body, ss.FrictionTensor(fx, fy), ss.State(omega=w0))
    assert tr.status == "stopped"
    assert tr.stop_state.phi / (2.0 * math.pi) == pytest.approx(1e4, rel=1e-9)
    assert tr.t_stop == pytest.approx(inertia * w0 / torque, rel=1e-9)


def test_long_run_of_a_spinning_ellipse_stops():
    """An ellipse spinning thousands of times under a plane-fixed anisotropic tensor (the
    wrench oscillates with φ all the way) still stops, losing energy monotonically."""
    body = ss.Body(ss.Ellipse(0.1, 0.05), ss.UniformPressure(), 1.0)
    tr = ss.simulate(
        body, ss.FrictionTensor(0.3, 0.5), ss.State(omega=1200.0, vx=0.01), max_steps=400_000
    )
    assert tr.status == "stopped"
    assert tr.stop_state.phi / (2 * math.pi) > 1000
    e = 0.5 * (tr.vx**2 + tr.vy**2) + 0.5 * body.moment_of_inertia * tr.omega**2
    assert np.all(np.diff(e) <= 1e-12 * e[0])


# ------------------------------------------------------------------------------------------
# issue 11: states of any finite size, and the corners of the valid ranges
# ------------------------------------------------------------------------------------------
def test_huge_speed_is_pure_translation():
    """vx = 1e308 with vy = 0.7, ω = 5: the ICR is 2e307 m away, i.e. pure translation along
    OX, whose wrench is F = −m g 𝔽 x̂ and M = 0 (centred pressure) in closed form. Before the
    rescaling this returned NaN or zero."""
    body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 2.0)
    fr = ss.FrictionTensor(0.3, 0.4, f=0.1)
    w = ss.friction_wrench(body, fr, 1e308, 0.7, 5.0, g=9.0)
    assert (w.force_x, w.force_y) == pytest.approx((-2.0 * 9.0 * 0.3, 2.0 * 9.0 * 0.1), abs=1e-12)
    assert w.moment == pytest.approx(0.0, abs=1e-12)


def test_huge_spin_is_pure_spin():
    """(1e-300, 1e-300, 1e300): a pure spin about G; a uniformly loaded isotropic disk feels
    M = −(2/3) μ m g a and no force (closed form)."""
    body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    w = ss.friction_wrench(body, ss.FrictionTensor(0.3, 0.3), 1e-300, 1e-300, 1e300, g=10.0)
    assert w.moment == pytest.approx(-2.0 / 3.0 * 0.3 * 10.0 * 0.05, rel=1e-12)
    assert abs(w.force_x) < 1e-12 and abs(w.force_y) < 1e-12


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1e-8, 1e8, 1e150, 1e300])
def test_wrench_is_homogeneous_of_degree_zero(scale):
    """The same state scaled by 1e±300 gives the wrench of the independent reference at the
    unit state (MODEL §2: only the direction of (v, a ω) matters)."""
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.LinearPressure(0.01, -0.005), 1.5)
    fr = ss.FrictionTensor(0.3, 0.45, f=0.05, angle=0.4)
    vx, vy, om, phi = 0.03, -0.02, 0.7, 0.3
    w = ss.friction_wrench(body, fr, vx * scale, vy * scale, om * scale, phi, g=1.0)
    xc, yc = body.mass_centre
    r = reference_wrench(
        0.1, 0.06, "linear", fr.world_matrix(phi), phi, vx, vy, om, xi_c=xc, eta_c=yc, P=1.5
    )
    got = np.array([w.force_x, w.force_y, w.moment / 0.1])
    want = np.array([r[0], r[1], r[2] / 0.1])
    assert np.all(np.isfinite(got))
    assert np.max(np.abs(got - want)) < 1e-10 * 1.5


def test_arrays_of_mixed_magnitudes():
    """Elementwise rescaling: each entry of an array gets the wrench of its own direction."""
    body = ss.Body(ss.Circle(0.05), ss.HertzPressure(), 1.0)
    fr = ss.FrictionTensor(0.3, 0.5)
    vx = np.array([1e300, 1.0, 0.0, 5e-324, 0.3])
    vy = np.array([0.0, 1e-300, 0.0, 0.0, -0.2])
    om = np.array([1e300 / 0.05, 1.0 / 0.05, 0.0, 0.0, 4.0])
    w = ss.friction_wrench(body, fr, vx, vy, om)
    one = [
        ss.friction_wrench(body, fr, 1.0, 0.0, 20.0),
        ss.friction_wrench(body, fr, 1.0, 0.0, 20.0),
    ]
    assert np.all(np.isfinite([w.force_x, w.force_y, w.moment]))
    for i in range(2):
        assert (w.force_x[i], w.moment[i]) == pytest.approx(
            (one[i].force_x, one[i].moment), rel=1e-12, abs=1e-14
        )
    assert (w.force_x[2], w.force_y[2], w.moment[2]) == (0.0, 0.0, 0.0)  # at rest
    assert w.force_x[3] == pytest.approx(-0.3 * 9.81, rel=1e-12)  # subnormal speed: sliding


@pytest.mark.parametrize("bn", [1e-3, 30.0])
@pytest.mark.parametrize(
    "fr",
    [
        ss.FrictionTensor(5.0, 1e-6, f=5.0, angle=0.7),
        ss.FrictionTensor(1e-6, 5.0, f=-5.0, frame="body"),
    ],
    ids=["plane", "body"],
)
def test_corners_of_the_valid_ranges(bn, fr):
    """The extreme patch and tensor the ranges allow, with the linear law's centroid on the
    rim of its core: the wrench meets the independent reference and terminal_states (which
    asks for 1e-13) finishes without a quadrature failure."""
    a = 1.0
    b = bn * a
    body = ss.Body(ss.Ellipse(a, b), ss.LinearPressure(0.25 * a * 0.6, 0.25 * b * 0.8), 1.0)
    for icr in [(0.3 * a, 0.2 * b), (a, 0.0), (0.0, 1.5 * b), (3.0 * a, -2.0 * b)]:
        check(body, fr, *icr, tol=1e-10)
    states = ss.terminal_states(body, fr, 0.4)
    assert states and all(math.isfinite(s.beta) or s.beta == math.inf for s in states)
