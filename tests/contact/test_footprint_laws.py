"""Pressure laws where they are defined on footprints (issue #12 item 2) and the blade.

The blade (a line contact, issue #12 item 1) is checked against ``quad`` along the segment
(broken at the ICR's projection), the closed forms of pure translation (−P𝔽v̂) and pure spin
(−sign(ω) P (L/4) ê⊥ᵀ𝔽ê⊥: μ P L/4 for isotropic friction) and the limit of a thin uniformly
loaded rectangle, whose wrench must approach it like (w/L)² (times ln(L/w) with the ICR on
the blade).

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
from slidespin.contact._kernel_blade import NEAR
from slidespin.contact.wrench import footprint_wrench
from slidespin.contact.pressure_map import PressureMap, density, mass_centre
from slidespin.contact.shapes import Annulus, Blade, Disk, Pads, Polygon, Rectangle

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


def test_disk_round_law_batch_and_terminal_equal_circle():
    """simulate_many, simulate_bodies and the terminal analysis: the Circle body's numbers."""
    from slidespin.motion.batch import simulate_bodies, simulate_many

    pressure = ss.HertzPressure()
    friction = ss.FrictionTensor(0.3, 0.4, 0.02)
    circle = ss.Body(ss.Circle(0.05), pressure, 0.4, 4e-4)
    disk = ss.Body(Disk(0.05, centre=(0.02, 0.01), angle=0.4), pressure, 0.4, 4e-4)
    states = np.array([[0, 0, 0, 1.0, 0.2, 20.0], [0.1, 0, 0.3, 0.3, 0.1, -5.0]])
    a = simulate_many(circle, friction, states)
    assert np.array_equal(a.t_stop, simulate_many(disk, friction, states).t_stop)
    assert np.array_equal(a.t_stop, simulate_bodies([disk, disk], friction, states).t_stop)
    assert ss.terminal_ratio(disk, friction, 0.3) == ss.terminal_ratio(circle, friction, 0.3)


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


# ---------------------------------------------------------------------------------------------
# the blade: a line contact


def _reference_blade(blade, tensor, frame, vx, vy, omega, phi, load=1.0):
    """(Fx, Fy, M about the blade's centre = G) by ``quad`` along the segment, broken at the
    ICR's projection onto it (where the slip direction turns fastest)."""
    (x0, y0), (x1, y1) = blade.ends
    gx, gy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
    c_, s_ = math.cos(phi), math.sin(phi)
    rot = np.array([[c_, -s_], [s_, c_]])
    t = np.asarray(tensor, dtype=float)
    tb = t if frame == "body" else rot.T @ t @ rot
    vbx, vby = rot.T @ np.array([vx, vy])

    def traction(u, k):
        x, y = x0 + u * (x1 - x0), y0 + u * (y1 - y0)
        wx, wy = vbx - omega * (y - gy), vby + omega * (x - gx)
        n = math.hypot(wx, wy)
        if n == 0.0:
            return 0.0
        tx = -(tb[0, 0] * wx + tb[0, 1] * wy) / n * load
        ty = -(tb[1, 0] * wx + tb[1, 1] * wy) / n * load
        return (tx, ty, (x - gx) * ty - (y - gy) * tx)[k]

    brk = [0.0, 1.0]
    if omega != 0.0:
        cx, cy = gx - vby / omega, gy + vbx / omega
        u = ((cx - x0) * (x1 - x0) + (cy - y0) * (y1 - y0)) / blade.length**2
        if 0.0 < u < 1.0:
            brk = [0.0, u, 1.0]
    out = np.zeros(3)
    for a, b in zip(brk[:-1], brk[1:]):
        for k in range(3):
            out[k] += quad(traction, a, b, args=(k,), epsabs=1e-13, epsrel=1e-12, limit=400)[0]
    f = rot @ out[:2]
    return f[0], f[1], out[2]


def _blade_states():
    """Motion states (vx, vy, ω, φ) of G for the blade of length 0.4 along ``BLADE``'s axis:
    random ones, and the ICR on the blade, on its line beyond an end, just inside and outside
    the switch of the closed form to Gauss–Legendre, nearly on the line, far, ω = 0."""
    rng = np.random.default_rng(20261123)
    out = [
        tuple(rng.normal(size=3) * (1.0, 1.0, 10.0)) + (float(rng.uniform(-3, 3)),)
        for _ in range(40)
    ]
    half, ang, phi = 0.2, BLADE.angle, 0.5
    e_world = (math.cos(ang + phi), math.sin(ang + phi))
    n_world = (-e_world[1], e_world[0])
    for speed_across, speed_along in [
        (0.05, 0.0),
        (0.19, 0.0),
        (0.3, 0.0),
        (0.05, 1e-13),
        (NEAR * half * (1 - 1e-9), 0.0),
        (NEAR * half * (1 + 1e-9), 0.0),
        (NEAR * half * (1 - 1e-9) * 0.6, NEAR * half * 0.8),
        (NEAR * half * (1 + 1e-9) * 0.6, NEAR * half * 0.8),
        (30.0, 2.0),
    ]:
        # ω = 1: the ICR lies at ẑ × v from G, i.e. along the blade for v across it
        vx = speed_across * n_world[0] + speed_along * e_world[0]
        vy = speed_across * n_world[1] + speed_along * e_world[1]
        out.append((vx, vy, 1.0, phi))
    out += [(0.3, -0.4, 0.0, 0.2), (0.0, 0.0, -4.0, 1.0), (1e-9, 0.0, 1e3, 0.0)]
    return out


BLADE = Blade(0.4, centre=(0.05, -0.02), angle=0.6)


@pytest.mark.parametrize("friction", FRICTIONS, ids=["iso", "skew", "body"])
def test_blade_against_quadrature(friction):
    """Every motion state: the exact blade wrench against quad along the segment, to 1e-10
    (units of P and P L/2)."""
    load = 2.5
    worst = 0.0
    for vx, vy, om, ph in _blade_states():
        w = footprint_wrench(BLADE, ss.UniformPressure(), friction, vx, vy, om, ph, load=load)
        ref = _reference_blade(BLADE, friction.matrix, friction.frame, vx, vy, om, ph, load)
        worst = max(
            worst,
            abs(w.force_x - ref[0]) / load,
            abs(w.force_y - ref[1]) / load,
            abs(w.moment - ref[2]) / (load * 0.2),
        )
    assert worst <= 1e-10


def test_blade_closed_forms():
    """Pure translation: F = −P 𝔽 v̂ (|F| = μ P isotropic), M = 0 about the centre; pure spin:
    F = 0, M = −sign(ω) P (L/4) ê⊥ᵀ 𝔽 ê⊥ (μ P L/4 isotropic), ê⊥ the blade's normal."""
    load, length = 3.0, 0.4
    for friction in FRICTIONS:
        for phi in (0.0, 0.8):
            t = friction.world_matrix(phi)
            w = footprint_wrench(
                BLADE, ss.UniformPressure(), friction, 0.6, -0.8, 0.0, phi, load=load
            )
            want = -load * t @ np.array([0.6, -0.8])
            assert abs(w.force_x - want[0]) <= 1e-14 * load
            assert abs(w.force_y - want[1]) <= 1e-14 * load
            assert abs(w.moment) <= 1e-15 * load * length
            ang = BLADE.angle + phi
            en = np.array([-math.sin(ang), math.cos(ang)])
            for omega in (5.0, -0.3):
                w = footprint_wrench(
                    BLADE, ss.UniformPressure(), friction, 0.0, 0.0, omega, phi, load=load
                )
                want_m = -math.copysign(1.0, omega) * load * length / 4.0 * (en @ t @ en)
                assert abs(w.moment - want_m) <= 1e-14 * load * length
                assert math.hypot(w.force_x, w.force_y) <= 1e-14 * load
    iso = footprint_wrench(
        Blade(0.5), ss.UniformPressure(), ss.FrictionTensor(0.3, 0.3), 0.0, 0.0, 2.0, load=10.0
    )
    assert iso.moment == pytest.approx(-0.3 * 10.0 * 0.5 / 4.0, rel=1e-15)


@pytest.mark.parametrize(
    "state",
    [(0.3, -0.2, 2.0, 0.3), (0.0, 0.0, 1.0, 0.0), (0.05, 0.1, 3.0, 1.0), (0.5, 0.5, -1.0, -0.4)],
    ids=["generic", "spin-about-centre", "icr-near", "icr-outside"],
)
def test_blade_is_the_limit_of_thin_rectangles(state):
    """Rectangle(L, w) under uniform pressure tends to the blade like (w/L)² (with a factor
    ln(L/w) when the ICR lies on the blade): halving w divides the gap by 3.4–4.1."""
    friction = ss.FrictionTensor(0.3, 0.5, 0.07)
    length = BLADE.length
    wb = footprint_wrench(BLADE, ss.UniformPressure(), friction, *state)
    gaps = []
    for k in (50, 100, 200, 400):
        rect = Rectangle(length, length / k, centre=BLADE.centre, angle=BLADE.angle)
        wr = footprint_wrench(rect, ss.UniformPressure(), friction, *state)
        gaps.append(
            max(
                abs(wr.force_x - wb.force_x),
                abs(wr.force_y - wb.force_y),
                abs(wr.moment - wb.moment) / (0.5 * length),
            )
        )
        assert gaps[-1] <= (1.0 / k) ** 2 * (1.0 + math.log(k))
    ratios = np.array(gaps[:-1]) / np.array(gaps[1:])
    assert np.all((ratios > 3.4) & (ratios < 4.1)), ratios


def test_blade_body():
    """A body on a blade: the thin rod's inertia m L²/12 (I* = 1/3 in units of ℓ = L/2), G
    over its centre, friction_wrench through the footprint path; the integrator refuses it
    with the reason; other laws and several blades are refused."""
    body = ss.Body(BLADE, ss.UniformPressure(), mass=2.0)
    assert body.is_footprint
    assert body.moment_of_inertia == pytest.approx(2.0 * 0.4**2 / 12.0, rel=1e-15)
    assert body.inertia_ratio == pytest.approx(1.0 / 3.0, rel=1e-15)
    assert body.mass_centre == BLADE.centre
    assert body.length_unit == 0.2
    friction = ss.FrictionTensor(0.3, 0.45, 0.05)
    w = ss.friction_wrench(body, friction, 0.2, 0.1, 3.0, 0.4, g=9.81)
    ref = _reference_blade(BLADE, friction.matrix, "plane", 0.2, 0.1, 3.0, 0.4, 2.0 * 9.81)
    assert abs(w.moment - ref[2]) <= 1e-10 * 2.0 * 9.81 * 0.2
    for law in (ss.LinearPressure(0.05, 0.0), ss.HertzPressure(), ss.BoussinesqPressure()):
        with pytest.raises(ValueError, match="pressure = .* is invalid"):
            ss.Body(BLADE, law, mass=1.0)
    with pytest.raises(ValueError, match="is invalid on a Blade"):
        footprint_wrench(BLADE, PressureMap(lambda x, y: 1.0 + 0.0 * x), friction, 1.0, 0.0, 1.0)
    with pytest.raises(ValueError, match="several blades is not supported"):
        Pads([BLADE, Blade(0.4, centre=(0.0, 0.5))])
    for bad in (0.0, -1.0, math.inf):
        with pytest.raises(ValueError, match="length"):
            Blade(bad)
    with pytest.raises(ValueError, match="centre"):
        Blade(1e-3, centre=(1e4, 0.0))


def test_blade_simulate_closed_forms():
    """Pure spin about the centre: I ω̇ = −μ m g L/4 with I = m L²/12, so t = L ω₀/(3 μ g);
    pure sliding: t = v₀/(μ g) (isotropic friction)."""
    mu, g, length = 0.3, 9.81, 0.4
    body = ss.Body(Blade(length), ss.UniformPressure(), mass=2.0)
    friction = ss.FrictionTensor(mu, mu)
    spin = ss.simulate(body, friction, ss.State(omega=20.0), g=g)
    assert spin.ending == "pure_spinning" and spin.status == "stopped"
    assert spin.t_stop == pytest.approx(length * 20.0 / (3.0 * mu * g), rel=1e-9)
    slide = ss.simulate(body, friction, ss.State(vx=1.0, vy=0.5, phi=0.3), g=g)
    assert slide.ending == "pure_sliding" and slide.status == "stopped"
    assert slide.t_stop == pytest.approx(math.hypot(1.0, 0.5) / (mu * g), rel=1e-9)


@pytest.mark.parametrize("inertia", [None, 2.0 * 0.13**2])
def test_blade_terminal_ratio_closed_form(inertia):
    """The mixed ending (isotropic friction): the velocity of G across the blade and the ICR on
    it at β* with β*² = ℓ² − 2k² (ℓ = L/2, k the radius of gyration), from v̇/v = ω̇/ω with
    F = 2 μ P s*/L and M = μ P (ℓ² − s*²)/L: β* = k = L/√12 for the thin rod."""
    length = 0.4
    body = ss.Body(Blade(length), ss.UniformPressure(), mass=2.0, moment_of_inertia=inertia)
    k2 = body.radius_of_gyration**2
    r = ss.simulate(body, ss.FrictionTensor(0.3, 0.3), ss.State(vx=1.0, omega=20.0))
    assert r.status == "stopped" and r.ending == "mixed"
    assert abs(r.beta_stop) == pytest.approx(math.sqrt(length**2 / 4.0 - 2.0 * k2), rel=1e-8)


def test_blade_stop_time_is_the_limit_of_thin_rectangles():
    """The stop time of a sliding, spinning blade: thin rectangles approach it like (w/L)²."""
    body = ss.Body(Blade(0.4), ss.UniformPressure(), mass=2.0)
    friction = ss.FrictionTensor(0.3, 0.3)
    s0 = ss.State(vx=1.0, omega=20.0)
    t_blade = ss.simulate(body, friction, s0).t_stop
    gaps = []
    for w in (0.02, 0.01, 0.005):
        rect = ss.Body(Rectangle(0.4, w), ss.UniformPressure(), 2.0, body.moment_of_inertia)
        gaps.append(abs(ss.simulate(rect, friction, s0).t_stop - t_blade))
    ratios = np.array(gaps[:-1]) / np.array(gaps[1:])
    assert np.all((ratios > 3.5) & (ratios < 4.5)), ratios
    assert gaps[-1] < 2e-4 * t_blade


@pytest.mark.parametrize("law", ["boussinesq", "hertz"])
def test_disk_under_elliptic_laws_has_table2_inertia_intervals(law):
    """A Disk (any radius and centre) under Boussinesq or Hertz pressure has the printed Table
    2 boundaries (MODEL §6–7; isotropic and orthotropic with μ = fy − fx)."""
    printed = {
        "boussinesq": lambda fx, mu: (
            (fx + mu) / (3 * fx),
            (4 * fx + 3 * mu) / (8 * fx),
            (2 * fx + mu) / (2 * fx),
        ),
        "hertz": lambda fx, mu: (
            (fx + mu) / (5 * fx),
            (6 * fx + 5 * mu) / (24 * fx),
            (2 * fx + mu) / (4 * fx),
        ),
    }[law]
    pressure = ss.HertzPressure() if law == "hertz" else ss.BoussinesqPressure()
    for fx, fy in ((0.3, 0.3), (0.25, 0.4)):
        got = ss.inertia_intervals(
            pressure, ss.FrictionTensor(fx, fy), patch=Disk(0.07, centre=(0.02, -0.01))
        )
        np.testing.assert_allclose(tuple(got), printed(fx, fy - fx), rtol=1e-8)
