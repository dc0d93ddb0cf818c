"""Pressure laws where they are defined on footprints (issue #12 item 2) and the blade.

Boussinesq and Hertz pressure are defined on ellipses and circles (MODEL §3, §10): a ``Disk``
under them is the circle of its radius with G at its centre. Truth used here: the body on
``Circle(R)`` (the paper's patch, a different input path to the elliptic kernel), the
closed-form pure-spin torques of MODEL §8 (3π/16 μ P R for Hertz, π/4 μ P R for Boussinesq),
and a slow reference written here with ``scipy.integrate.quad`` (rays through the ICR; the
pressure's square-root rim behaviour handled by quad's algebraic weights), which shares no
code with slidespin.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

import slidespin as ss
from slidespin.footprint import Annulus, Disk, Pads, Polygon, Rectangle
from slidespin.footprint_pressure import density, mass_centre
from slidespin.footprint_wrench import footprint_wrench

ROUND_LAWS = {"hertz": ss.HertzPressure(), "boussinesq": ss.BoussinesqPressure()}
#: pure-spin torque of a centred disk under isotropic friction, in units of μ P R (MODEL §8)
SPIN_TORQUE = {"hertz": 3.0 * math.pi / 16.0, "boussinesq": math.pi / 4.0}

STATES = [  # (vx, vy, omega, phi): ICR inside, on the rim region, outside, far, pure moves
    (0.3, -0.2, 5.0, 0.7),
    (1.0, 0.4, -12.0, -2.0),
    (0.0, 0.0, 3.0, 0.1),
    (0.5, 0.2, 0.0, 0.4),
    (0.01, 0.02, 40.0, 1.3),
    (2.0, -1.0, 1e-3, 0.0),
]
FRICTIONS = [
    ss.FrictionTensor(0.3, 0.3),
    ss.FrictionTensor(0.3, 0.45, 0.05),
    ss.FrictionTensor(0.5, 0.2, -0.1, frame="body"),
]


# ---------------------------------------------------------------------------------------------
# a slow reference: rays through the ICR (independent of slidespin)


def _reference_round(radius, centre, law, tensor, frame, vx, vy, omega, phi, load=1.0):
    """(Fx, Fy, M) of a disk of ``radius`` at ``centre`` (G) under Hertz or Boussinesq
    pressure, in the fixed frame, moment about G: polar coordinates about the ICR c.

    On the line c + ρ ê the slip direction is sign(ωρ) ẑ × ê, and the pressure is
    p₀ ((ρ − ρ₀)(ρ₁ − ρ)/R²)^(±1/2) between the rim crossings ρ₀ < ρ₁; each side of ρ = 0
    is one ``quad`` with the algebraic weight of its rim end(s). ψ runs over [0, π)."""
    c_, s_ = math.cos(phi), math.sin(phi)
    rot = np.array([[c_, -s_], [s_, c_]])
    t = np.asarray(tensor, dtype=float)
    tb = t if frame == "body" else rot.T @ t @ rot
    vb = rot.T @ np.array([vx, vy])
    ox, oy = centre
    area = math.pi * radius**2
    if law == "hertz":
        alpha, p0 = 0.5, 1.5 * load / area
    else:
        alpha, p0 = -0.5, 0.5 * load / area
    if omega == 0.0:
        raise AssertionError("the reference is for ω ≠ 0")
    cx, cy = ox - vb[1] / omega, oy + vb[0] / omega  # ICR, body frame (G = the disk's centre)

    def half(a, b, wa, wb, rho1, rho0, power):
        """∫_a^b p(ρ) |ρ| ρ^power dρ with the weight (ρ − a)^wa (b − ρ)^wb."""

        def f(rho):
            rest = 1.0
            if wa == 0.0:
                rest *= (rho - rho0) ** alpha
            if wb == 0.0:
                rest *= (rho1 - rho) ** alpha
            return p0 * rest / radius ** (2 * alpha) * abs(rho) * rho**power

        val, _ = quad(f, a, b, weight="alg", wvar=(wa, wb), epsabs=1e-15, epsrel=1e-13, limit=200)
        return val

    def ray(psi):
        ex, ey = math.cos(psi), math.sin(psi)
        dx, dy = cx - ox, cy - oy
        m = dx * ex + dy * ey
        disc = m * m - (dx * dx + dy * dy) + radius**2
        out = np.zeros(3)
        if disc <= 0.0:
            return out
        h = math.sqrt(disc)
        r0, r1 = -m - h, -m + h
        pieces = (
            [(r0, 0.0, alpha, 0.0, -1.0), (0.0, r1, 0.0, alpha, 1.0)]
            if r0 < 0.0 < r1
            else [(r0, r1, alpha, alpha, 1.0 if r0 >= 0.0 else -1.0)]
        )
        sgn_w = 1.0 if omega > 0.0 else -1.0
        for a, b, wa, wb, side in pieces:
            k0 = half(a, b, wa, wb, r1, r0, 0)
            k1 = half(a, b, wa, wb, r1, r0, 1)
            wx, wy = -ey * side * sgn_w, ex * side * sgn_w  # ŵ = sign(ωρ) ẑ × ê
            tx = -(tb[0, 0] * wx + tb[0, 1] * wy)
            ty = -(tb[1, 0] * wx + tb[1, 1] * wy)
            # moment about G: ((c − G) + ρ ê) × τ
            out += np.array(
                [
                    tx * k0,
                    ty * k0,
                    ((cx - ox) * ty - (cy - oy) * tx) * k0 + (ex * ty - ey * tx) * k1,
                ]
            )
        return out

    # breaks: the directions of the rim tangents (c outside) and of the centre
    dist = math.hypot(cx - ox, cy - oy)
    base = math.atan2(oy - cy, ox - cx)
    brk = [base % math.pi]
    if dist > radius:
        a = math.asin(radius / dist)
        brk += [(base + a) % math.pi, (base - a) % math.pi]
    brk = sorted(set([0.0, math.pi] + brk))
    total = np.zeros(3)
    for lo, hi in zip(brk[:-1], brk[1:]):
        for k in range(3):
            total[k] += quad(
                lambda p, k=k: ray(p)[k], lo, hi, epsabs=1e-14, epsrel=1e-12, limit=200
            )[0]
    f = rot @ total[:2]
    return f[0], f[1], total[2]


# ---------------------------------------------------------------------------------------------
# Task: Boussinesq and Hertz on a Disk


@pytest.mark.parametrize("law", sorted(ROUND_LAWS))
@pytest.mark.parametrize("friction", FRICTIONS, ids=["iso", "skew", "body"])
def test_disk_round_law_equals_circle_body(law, friction):
    """A Disk anywhere in the body frame, turned, under Hertz or Boussinesq, has the wrench of
    the body on Circle(R) (G at the centre in both) for every motion state."""
    pressure = ROUND_LAWS[law]
    circle = ss.Body(ss.Circle(0.05), pressure, mass=0.4)
    for disk in (Disk(0.05), Disk(0.05, centre=(0.02, -0.013), angle=0.6)):
        body = ss.Body(disk, pressure, mass=0.4)
        assert not body.is_footprint
        assert body.mass_centre == disk.centre
        assert body.moment_of_inertia == pytest.approx(0.4 * 0.05**2 / 2.0, rel=1e-15)
        assert body.length_unit == 0.05
        vx, vy, om, ph = (np.array(c) for c in zip(*STATES))
        w0 = ss.friction_wrench(circle, friction, vx, vy, om, ph)
        w1 = ss.friction_wrench(body, friction, vx, vy, om, ph)
        w2 = footprint_wrench(disk, pressure, friction, vx, vy, om, ph, load=0.4 * 9.81)
        for name in ("force_x", "force_y", "moment", "tangential", "normal", "moment_paper"):
            ref = getattr(w0, name)
            scale = 0.4 * 9.81 * (0.05 if "moment" in name else 1.0)
            assert np.max(np.abs(getattr(w1, name) - ref)) <= 1e-12 * scale, name
            assert np.max(np.abs(getattr(w2, name) - ref)) <= 1e-12 * scale, name


@pytest.mark.parametrize("law", sorted(ROUND_LAWS))
def test_disk_round_law_simulate_equals_circle(law):
    """simulate: the same stop time, stop state and path as the body on Circle(R)."""
    pressure = ROUND_LAWS[law]
    friction = ss.FrictionTensor(0.3, 0.45, 0.05)
    circle = ss.Body(ss.Circle(0.05), pressure, mass=0.4, moment_of_inertia=3e-4)
    disk = ss.Body(
        Disk(0.05, centre=(0.03, 0.01), angle=-1.0), pressure, mass=0.4, moment_of_inertia=3e-4
    )
    s0 = ss.State(0.1, -0.2, 0.3, 1.0, 0.2, 20.0)
    a, b = ss.simulate(circle, friction, s0), ss.simulate(disk, friction, s0)
    assert a.t_stop > 0.1
    assert abs(a.t_stop - b.t_stop) <= 1e-12 * a.t_stop
    for name in ("x", "y", "phi"):
        assert abs(getattr(a.stop_state, name) - getattr(b.stop_state, name)) <= 1e-12
    assert b.ending == a.ending and b.status == a.status
    assert np.array_equal(a.t, b.t)


@pytest.mark.parametrize("law", sorted(ROUND_LAWS))
@pytest.mark.parametrize("centre", [(0.0, 0.0), (0.07, -0.03)])
def test_disk_round_law_pure_spin_closed_form(law, centre):
    """MODEL §8: M = −sign(ω) μ P R (3π/16 Hertz, π/4 Boussinesq), F = 0, about G = the
    disk's centre wherever the disk lies in the body frame."""
    mu, load, radius = 0.35, 7.0, 0.04
    disk = Disk(radius, centre=centre)
    for omega in (2.0, -30.0):
        w = footprint_wrench(
            disk, ROUND_LAWS[law], ss.FrictionTensor(mu, mu), 0.0, 0.0, omega, 0.4, load=load
        )
        expect = -math.copysign(1.0, omega) * SPIN_TORQUE[law] * mu * load * radius
        assert abs(w.moment - expect) <= 1e-12 * load * radius
        assert math.hypot(w.force_x, w.force_y) <= 1e-12 * load


@pytest.mark.parametrize("law", sorted(ROUND_LAWS))
@pytest.mark.parametrize(
    "state",
    [(0.1, -0.05, 4.0, 0.3), (0.5, 0.3, -2.0, -1.1), (0.002, 0.001, 1.0, 2.0)],
    ids=["icr-inside", "icr-outside", "icr-near-centre"],
)
def test_off_centre_disk_against_quadrature(law, state):
    """An off-centre disk, skew anisotropic friction: the slow quad reference to 1e-10."""
    radius, centre, load = 0.06, (0.04, -0.025), 3.0
    friction = ss.FrictionTensor(0.3, 0.5, 0.08)
    vx, vy, om, ph = state
    w = footprint_wrench(
        Disk(radius, centre=centre, angle=0.9), ROUND_LAWS[law], friction, vx, vy, om, ph, load=load
    )
    fx, fy, m = _reference_round(
        radius, centre, law, friction.matrix, "plane", vx, vy, om, ph, load
    )
    assert abs(w.force_x - fx) <= 1e-10 * load
    assert abs(w.force_y - fy) <= 1e-10 * load
    assert abs(w.moment - m) <= 1e-10 * load * radius


def test_reference_reproduces_closed_forms():
    """The quad reference itself: the pure-spin torques of MODEL §8 (the ICR at the centre)."""
    for law in ROUND_LAWS:
        fx, fy, m = _reference_round(
            0.05, (0.01, 0.02), law, np.eye(2) * 0.4, "plane", 0.0, 0.0, 1.0, 0.0, load=2.0
        )
        assert abs(m + SPIN_TORQUE[law] * 0.4 * 2.0 * 0.05) <= 1e-12
        assert math.hypot(fx, fy) <= 1e-12


def test_round_law_pressure_and_mass_centre():
    """density and mass_centre on a Disk under these laws: the circle's law about its centre."""
    disk = Disk(0.05, centre=(0.02, -0.01))
    load = 10.0
    for law, peak in ((ss.HertzPressure(), 1.5), (ss.BoussinesqPressure(), 0.5)):
        assert mass_centre(disk, law) == (0.02, -0.01)
        p = density(disk, law, [0.02, 0.02 + 0.03, 0.2], [-0.01, -0.01, 0.0], load=load)
        mean = load / (math.pi * 0.05**2)
        q = (0.03 / 0.05) ** 2
        shape = math.sqrt(1.0 - q) if peak == 1.5 else 1.0 / math.sqrt(1.0 - q)
        assert p[0] == pytest.approx(peak * mean, rel=1e-14)
        assert p[1] == pytest.approx(peak * mean * shape, rel=1e-14)
        assert p[2] == 0.0


@pytest.mark.parametrize(
    "patch",
    [
        Annulus(0.01, 0.05),
        Annulus(0.0, 0.05),
        Rectangle(0.1, 0.05),
        Polygon([(0, 0), (0.1, 0), (0.05, 0.08)]),
        Pads([Disk(0.01), Disk(0.01, centre=(0.1, 0.0))]),
    ],
    ids=["ring", "annulus-no-hole", "rectangle", "polygon", "pads-of-disks"],
)
@pytest.mark.parametrize("law", sorted(ROUND_LAWS))
def test_round_laws_refused_elsewhere(patch, law):
    """Where the laws are not defined: a ValueError naming the parameter, the patch and what
    is supported, from Body and from footprint_wrench alike."""
    name = type(ROUND_LAWS[law]).__name__
    with pytest.raises(ValueError, match=rf"pressure = {name}\(\) is invalid on patch = ") as e:
        ss.Body(patch, ROUND_LAWS[law], mass=1.0)
    assert "single Disk" in str(e.value) and "UniformPressure()" in str(e.value)
    with pytest.raises(ValueError, match=rf"pressure = {name}\(\) is invalid"):
        footprint_wrench(patch, ROUND_LAWS[law], ss.FrictionTensor(0.3, 0.3), 1.0, 0.0, 1.0)
    with pytest.raises(ValueError, match=rf"pressure = {name}\(\) is invalid"):
        mass_centre(patch, ROUND_LAWS[law])


def test_uniform_disk_still_a_footprint():
    """The uniform and linear laws on a Disk keep the footprint kernel (unchanged)."""
    body = ss.Body(Disk(0.05, centre=(0.01, 0.0)), ss.UniformPressure(), mass=1.0)
    assert body.is_footprint
    with pytest.raises(ValueError, match="elliptic patches only"):
        body.kernel_params(ss.FrictionTensor(0.3, 0.3))
