"""Thin rings (an Annulus with r/R → 1): the wrench keeps its digits however thin the ring.

A ring is a disk minus its hole; subtracted in floating point their tensors (and areas) keep
only ~1e-16 R/(R − r) of their digits. Independent truths: the closed forms of MODEL §8/§10
(pure spin about the centre, M = −(2/3) μ P (R² + Rr + r²)/(R + r); pure translation,
F = −P 𝔽 v̂, M = 0), the area π(R − r)(R + r), the thin ring's limit (a load spread on
circles of radius s ∈ [r, R], each integrated by adaptive quadrature over its angle here),
the slow polar reference of ``tests/references`` where it is accurate (R − r ≥ 1e-3 R),
the stop time of a pure spin I ω₀/|M| (the spin rate falls linearly), and the complete
elliptic integrals by the arithmetic-geometric mean in 40-digit decimal arithmetic.
"""

from __future__ import annotations

import math
import sys
from decimal import Decimal, getcontext
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

import slidespin as ss
from slidespin.contact._kernel_disk import THIN_RING, _dd_ke
from slidespin.contact.shapes import Annulus
from slidespin.contact.wrench import footprint_wrench

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "references"))
from footprint_reference import reference_wrench  # noqa: E402

WIDTHS = (1e-6, 1e-9, 1e-12)
TENSOR = ss.FrictionTensor(0.3, 0.5, 0.1, angle=0.4)


def _spin_closed_form(mu, load, big, small):
    return -(2.0 / 3.0) * mu * load * (big * big + big * small + small * small) / (big + small)


@pytest.mark.parametrize("width", (*WIDTHS, 1e-13, 1e-15, None))
def test_pure_spin_matches_the_closed_form(width):
    big = 0.1
    small = np.nextafter(big, 0.0) if width is None else big * (1.0 - width)
    ring = Annulus(small, big)
    w = footprint_wrench(
        ring, ss.UniformPressure(), ss.FrictionTensor(0.3, 0.3), 0.0, 0.0, 2.0, load=10.0
    )
    exact = _spin_closed_form(0.3, 10.0, big, small)
    assert w.moment == pytest.approx(exact, rel=1e-14)
    assert abs(w.force_x) < 1e-15 and abs(w.force_y) < 1e-15


@pytest.mark.parametrize("width", WIDTHS)
def test_translation_and_area_closed_forms(width):
    big = 2.0
    small = big * (1.0 - width)
    ring = Annulus(small, big, centre=(0.3, -0.1))
    assert ring.area == pytest.approx(math.pi * (big - small) * (big + small), rel=1e-14)
    j = ring.second_moment
    quarter = math.pi * (big - small) * (big + small) * (big * big + small * small) / 4.0
    assert j[0, 0] == pytest.approx(quarter, rel=1e-14)
    assert abs(j[0, 1]) < 1e-14 * quarter
    w = footprint_wrench(ring, ss.UniformPressure(), TENSOR, 0.6, -0.8, 0.0, load=3.0)
    exact = -3.0 * TENSOR.matrix @ np.array([0.6, -0.8])
    assert [w.force_x, w.force_y] == pytest.approx(exact, rel=1e-14)
    assert abs(w.moment) < 1e-14


def _circle_wrench(s, vx, vy, om):
    """(Fx, Fy, M) per unit load spread evenly on the circle of radius s about G = 0."""
    t = TENSOR.matrix
    cx, cy = -vy / om, vx / om  # the ICR
    a0 = math.atan2(cy, cx)

    def part(th, k):
        x, y = s * math.cos(th), s * math.sin(th)
        wx, wy = vx - om * y, vy + om * x
        n = math.hypot(wx, wy)
        if n == 0.0:
            return 0.0
        tx = -(t[0, 0] * wx + t[0, 1] * wy) / n
        ty = -(t[1, 0] * wx + t[1, 1] * wy) / n
        return (tx, ty, x * ty - y * tx)[k] / (2.0 * math.pi)

    # broken at the direction of the ICR, where the slip direction turns fastest
    cuts = (a0 - math.pi, a0 - 1e-3, a0, a0 + 1e-3, a0 + math.pi)
    return np.array(
        [
            sum(
                quad(part, lo, hi, args=(k,), epsabs=1e-16, epsrel=1e-14, limit=500)[0]
                for lo, hi in zip(cuts[:-1], cuts[1:])
            )
            for k in range(3)
        ]
    )


def _thin_ring_reference(big, small, vx, vy, om):
    """The uniformly loaded ring as circles r ≤ s ≤ R (load 2s ds/(R² − r²)), Gauss in s,
    split at the ICR's distance (where the circles' wrench has a kink)."""
    x, w = np.polynomial.legendre.leggauss(4)
    dist = math.hypot(vx, vy) / abs(om)
    cuts = [small, dist, big] if small < dist < big else [small, big]
    out = np.zeros(3)
    for lo, hi in zip(cuts[:-1], cuts[1:]):
        for xi, wi in zip(x, w):
            s = 0.5 * (hi + lo) + 0.5 * (hi - lo) * xi
            out += (
                wi
                * 0.5
                * (hi - lo)
                * 2.0
                * s
                / ((big - small) * (big + small))
                * (_circle_wrench(s, vx, vy, om))
            )
    return out


@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
@pytest.mark.parametrize("width", WIDTHS)
def test_any_motion_matches_the_thin_ring_limit(width):
    """ICR at the centre, inside the hole, on the hole's rim, inside the ring's band, on the
    outer rim, just outside, and far."""
    big = 1.0
    small = big * (1.0 - width)
    ring = Annulus(small, big)
    rng = np.random.default_rng(7)
    # the limit's own error is O(width²) away from the band, O(width² log width) in it
    tol = 1e-12 if width < 1e-6 else 2e-10
    for dist in (0.0, 0.5, small, 1.0 - 0.5 * width, 1.0, 1.0 + 1e-9, 1.001, 3.0, 30.0):
        ang = rng.uniform(0.0, 2.0 * math.pi)
        om = rng.choice([-1.5, 1.0])
        cx, cy = dist * math.cos(ang), dist * math.sin(ang)
        vx, vy = om * cy, -om * cx  # the ICR at (cx, cy)
        w = footprint_wrench(ring, ss.UniformPressure(), TENSOR, vx, vy, om)
        ref = _thin_ring_reference(big, small, vx, vy, om)
        got = np.array([w.force_x, w.force_y, w.moment])
        assert np.max(np.abs(got - ref)) < tol, (dist, got - ref)


@pytest.mark.parametrize("width", (0.5 * THIN_RING, 2e-3))
def test_double_double_path_matches_the_polar_reference(width):
    """Rings thin enough for the double-double path, thick enough for the polar reference
    (whose chords lose ~1e-16 R/(R − r)), under uniform and linear pressure."""
    big = 0.2
    ring = Annulus(big * (1.0 - width), big, centre=(0.05, -0.03))
    rng = np.random.default_rng(3)
    for law, ref_law, g in (
        (ss.UniformPressure(), ("uniform",), (0.05, -0.03)),
        (ss.LinearPressure(0.06, -0.02), ("linear", 0.06, -0.02), (0.06, -0.02)),
    ):
        for dist in (0.0, 0.1, big * (1.0 - width / 2), big, 0.21, 1.0):
            ang = rng.uniform(0.0, 2.0 * math.pi)
            om = 2.0
            c = np.array(ring.centre) + dist * np.array([math.cos(ang), math.sin(ang)])
            vx, vy = om * (c[1] - g[1]), -om * (c[0] - g[0])
            w = footprint_wrench(ring, law, TENSOR, vx, vy, om, 0.3)
            ref = reference_wrench(ring, ref_law, TENSOR.matrix, vx, vy, om, 0.3)
            assert w.force_x == pytest.approx(ref[0], abs=1e-12)
            assert w.force_y == pytest.approx(ref[1], abs=1e-12)
            assert w.moment == pytest.approx(ref[2], abs=1e-12 * big)


def test_thin_ring_spin_stops_at_the_closed_form_time():
    """The spin rate of a ring spinning about its centre falls linearly: t = I ω₀/|M|."""
    big = 0.1
    small = big * (1.0 - 1e-13)
    body = ss.Body(Annulus(small, big), ss.UniformPressure(), mass=1.0)
    tr = ss.simulate(body, ss.FrictionTensor(0.3, 0.3), ss.State(omega=5.0), g=9.81)
    torque = -_spin_closed_form(0.3, 9.81, big, small)
    assert tr.t_stop == pytest.approx(body.moment_of_inertia * 5.0 / torque, rel=1e-9)


def _agm_ke(m: float) -> tuple[Decimal, Decimal]:
    """K(m), E(m) by the AGM in 40-digit decimal arithmetic (Abramowitz & Stegun 17.6)."""
    getcontext().prec = 40
    a, b = Decimal(1), (Decimal(1) - Decimal(m)).sqrt()
    s, pw = Decimal(m) / 2, Decimal("0.5")
    for _ in range(40):
        c = (a - b) / 2
        a, b = (a + b) / 2, (a * b).sqrt()
        pw *= 2
        s += pw * c * c
    pi = Decimal("3.141592653589793238462643383279502884197")
    k = pi / (2 * a)
    return k, k * (1 - s)


@pytest.mark.parametrize("m", (0.45, 0.7, 0.99, 1.0 - 2.0**-40))
def test_double_double_elliptic_integrals(m):
    (kh, kl), (eh, el) = _dd_ke((m, 0.0))
    k_ref, e_ref = _agm_ke(m)
    assert abs((Decimal(kh) + Decimal(kl)) / k_ref - 1) < Decimal("1e-29")
    assert abs((Decimal(eh) + Decimal(el)) / e_ref - 1) < Decimal("1e-29")


def test_statics_of_thin_rings():
    """Isotropic friction takes any ring (the exact kernel): a torque T is held up to
    λ* = (2/3) μ P (R³ − r³)/((R² − r²) T). An anisotropic tensor's static set goes through
    the ring's image (an elliptic ring, disk minus hole by quadrature): rings of relative
    width ≥ 1e-3 keep their digits (a force W through G: λ* = P/|𝔽⁻¹W|), thinner ones are
    refused by name."""
    from slidespin.contact import statics

    big, g = 0.1, 9.81
    for width in WIDTHS:
        small = big * (1.0 - width)
        body = ss.Body(Annulus(small, big), ss.UniformPressure(), mass=1.0)
        lam = statics.load_factor(body, ss.FrictionTensor(0.3, 0.3), (0.0, 0.0, 0.1), g=g)
        assert lam == pytest.approx(-_spin_closed_form(0.3, g, big, small) / 0.1, rel=1e-12)
        with pytest.raises(
            ValueError, match=r"relative width .* valid range: \(R - r\)/R >= 0.001"
        ):
            statics.load_factor(body, TENSOR, (1.0, 0.0, 0.0), g=g)
    for width in (1e-3, 2e-3):
        body = ss.Body(Annulus(big * (1.0 - width), big), ss.UniformPressure(), mass=1.0)
        w = np.array([3.0, 1.0])
        lam = statics.load_factor(body, TENSOR, (w[0], w[1], 0.0), g=g)
        assert lam == pytest.approx(
            g / np.linalg.norm(np.linalg.solve(TENSOR.matrix, w)), rel=1e-12
        )
