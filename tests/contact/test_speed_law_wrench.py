"""Speed-dependent friction (MODEL §14): the library's wrench against an independent reference.

Truth: ``tests/references/speed_law_reference.py`` (rays about the ICR, exact radial
integrals for uniform/linear pressure, Gauss–Jacobi for Boussinesq/Hertz, adaptive angular
quadrature; numpy/scipy only), and closed forms: a disk in pure translation
(F = −μ P g(v)), a disk and a ring in pure spin about the centre under a power law, Hertz and
Boussinesq disks in pure spin (Beta functions), pure translation of any patch
(F = −P g(|v|) 𝔽 v̂, M = 0), and mirror symmetry.

Agreement asked: 1e-9 of P = m g (forces) and of P × size (moment; size = largest distance
from the pressure centroid to the patch).
"""

from __future__ import annotations

import math
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from scipy.special import beta as beta_fn
from speed_law_reference import (
    _line_intervals,
    _regions,
    footprint_moments,
    reference_size,
    reference_wrench,
    speed_factor,
)

import slidespin as ss
from slidespin.contact.speed_laws import PowerLaw, SpeedTable, Stribeck

TOL = 1e-9
MASS, GRAV = 2.0, 9.81
LOAD = MASS * GRAV

# speed laws (slip speeds on the patches below are ~0–1 m/s at |ω| = 2–3 rad/s)
LAWS = {
    "power0.5": ("power", 0.5, 0.5),
    "power0.3": ("power", 0.3, 0.2),
    "stribeck2": ("stribeck", 1.6, 0.3, 2.0),
    "stribeck1": ("stribeck", 2.0, 0.15, 1.0),
    "stribeck0.5": ("stribeck", 1.4, 0.2, 0.5),
    "table": ("table", (0.05, 0.15, 0.3, 0.5, 0.7), (1.4, 1.25, 1.1, 1.02, 1.0)),
}
ISO = (0.4, 0.4, 0.0, 0.0, "plane")
TENSORS = {
    "iso": ISO,
    "plane": (0.3, 0.5, 0.1, 0.4, "plane"),
    "body": (0.45, 0.25, -0.15, -0.7, "body"),
}

L_SHAPE = [(0.0, 0.0), (0.3, 0.0), (0.3, 0.1), (0.1, 0.1), (0.1, 0.25), (0.0, 0.25)]
TRIANGLE = [(0.0, 0.0), (0.25, 0.05), (0.05, 0.2)]
FOOTPRINTS = {
    "lshape": ("polygon", L_SHAPE, (-0.1, -0.05), 0.3),
    "triangle": ("polygon", TRIANGLE, (0.02, 0.01), -0.5),
    "rectangle": ("rectangle", 0.3, 0.12, (0.02, -0.01), 0.4),
    "ring": ("annulus", 0.08, 0.15, (0.01, 0.02)),
    "disk": ("disk", 0.12, (0.05, -0.03)),
    "pads": (
        "pads",
        [
            ("disk", 0.03, (0.0, 0.15)),
            ("rectangle", 0.1, 0.04, (0.1, -0.1), 0.2),
            ("polygon", TRIANGLE, (-0.2, -0.1), 0.0),
        ],
    ),
}


# --------------------------------------------------------------------------- adapters
def lib_patch(spec):
    kind = spec[0]
    if kind == "ellipse":
        return ss.Ellipse(spec[1], spec[2])
    if kind == "disk":
        return ss.Disk(spec[1], centre=spec[2] if len(spec) > 2 else (0.0, 0.0))
    if kind == "annulus":
        return ss.Annulus(spec[1], spec[2], centre=spec[3] if len(spec) > 3 else (0.0, 0.0))
    if kind == "polygon":
        return ss.Polygon(spec[1], centre=spec[2], angle=spec[3])
    if kind == "rectangle":
        return ss.Rectangle(spec[1], spec[2], centre=spec[3], angle=spec[4])
    return ss.Pads([lib_patch(s) for s in spec[1]])


def lib_pressure(spec):
    if spec[0] == "linear":
        return ss.LinearPressure(spec[1], spec[2])
    return {
        "uniform": ss.UniformPressure,
        "boussinesq": ss.BoussinesqPressure,
        "hertz": ss.HertzPressure,
    }[spec[0]]()


def lib_law(spec):
    if spec is None:
        return None
    return {"power": PowerLaw, "stribeck": Stribeck, "table": SpeedTable}[spec[0]](*spec[1:])


def lib_wrench(patch, pressure, law, tensor, vx, vy, omega, phi):
    body = ss.Body(lib_patch(patch), lib_pressure(pressure), mass=MASS)
    fx, fy, f, angle, frame = tensor
    tens = ss.FrictionTensor(fx, fy, f, frame=frame, angle=angle, speed_law=lib_law(law))
    w = ss.friction_wrench(body, tens, vx, vy, omega, phi=phi, g=GRAV)
    return np.array([w.force_x, w.force_y, w.moment], float)


def mass_centre(patch, pressure):
    if pressure[0] == "linear":
        return np.array(pressure[1:3], float)
    area, m1, _ = footprint_moments(patch)
    return m1 / area


def linear_law(patch, dx=0.01, dy=-0.006):
    """A linear law whose centroid is the area centroid shifted by (dx, dy)."""
    area, m1, _ = footprint_moments(patch)
    return ("linear", m1[0] / area + dx, m1[1] / area + dy)


def state_for_icr(r_g, icr, phi, omega):
    """World velocity of G for a body-frame ICR ``icr`` (G at body point ``r_g``)."""
    d = np.asarray(icr, float) - r_g
    vb = omega * np.array([d[1], -d[0]])
    c, s = math.cos(phi), math.sin(phi)
    return c * vb[0] - s * vb[1], s * vb[0] + c * vb[1]


def rim_distance(patch, origin, u):
    """Distance from ``origin`` along the unit vector ``u`` to where the ray first leaves Ω."""
    ivals, _ = _line_intervals(_regions(patch), np.asarray(origin, float), np.asarray(u, float))
    return min(t2 for _, t2 in ivals if t2 > 0)


def check(patch, pressure, law, tensor, vx, vy, omega, phi):
    """Library minus reference, in units of (P, P, P × size); also returns both."""
    ref = np.array(reference_wrench(patch, pressure, law, tensor, vx, vy, omega, phi, LOAD))
    got = lib_wrench(patch, pressure, law, tensor, vx, vy, omega, phi)
    scale = np.array([LOAD, LOAD, LOAD * reference_size(patch, pressure)])
    return (got - ref) / scale, got, ref


def assert_close(err, got, ref):
    assert np.all(np.abs(err) <= TOL), f"err={err}, library={got}, reference={ref}"


# --------------------------------------------------------------------------- ellipses
ELLIPSES = {"b/a=0.5": ("ellipse", 0.2, 0.1), "b/a=1": ("ellipse", 0.2, 0.2)}
PRESSURES = ("uniform", "linear", "boussinesq", "hertz")

# elliptic engine with a power law under Boussinesq/Hertz pressure: wrong (see the
# closed-form test below); Boussinesq + any law with the ICR just outside hangs (see below)
POWER_BH = pytest.mark.xfail(
    strict=True,
    raises=AssertionError,
    reason="library: power law under Boussinesq/Hertz pressure with the ICR within ~1.5 a of "
    "the centre: off by up to 9e-5 (Hertz) and 1.7e-2 (Boussinesq) of P, P × a (also the "
    "pure-spin disk closed form); correct again at 3 a",
)


# elliptic engine, Boussinesq pressure with a Stribeck or table law: friction_wrench does not
# return (> 15 s; the rest of the file takes seconds); not run here, shown by a subprocess test
BOUSS_HANG = pytest.mark.xfail(
    run=False,
    strict=True,
    reason="library: Boussinesq + Stribeck/SpeedTable friction_wrench hangs "
    "(test_elliptic_engine_returns)",
)


# elliptic engine, uniform pressure, table law, ICR far (100 × a): friction_wrench hangs too
FAR_TABLE_HANG = pytest.mark.xfail(
    run=False,
    strict=True,
    reason="library: SpeedTable with the ICR far from an ellipse: friction_wrench hangs "
    "(test_elliptic_engine_returns)",
)


def _marks(pk, lk, ik="inside", ek="b/a=0.5"):
    """Known library faults: none left (the power law under Boussinesq/Hertz, the
    Boussinesq hangs and the rim sliver of an elongated Boussinesq ellipse were fixed after
    this file found them)."""
    return []


def ellipse_pressure(name, patch):
    if name == "linear":
        return ("linear", 0.12 * patch[1] / 4, -0.08 * patch[2] / 4)
    return (name,)


def _ellipse_params():
    out = []
    for ek in ELLIPSES:
        for pk in PRESSURES:
            for lk in LAWS:
                marks = _marks(pk, lk, ek=ek)
                out.append(pytest.param(ek, pk, lk, id=f"{ek}-{pk}-{lk}", marks=marks))
    return out


@pytest.mark.parametrize(("ek", "pk", "lk"), _ellipse_params())
def test_ellipse_every_pressure_and_law(ek, pk, lk):
    """ICR inside the patch, body-fixed anisotropic tensor with skew and angle, φ ≠ 0."""
    patch = ELLIPSES[ek]
    pressure = ellipse_pressure(pk, patch)
    r_g = mass_centre(patch, pressure)
    phi, omega = 0.7, 2.5
    vx, vy = state_for_icr(r_g, (0.06, 0.03), phi, omega)
    assert_close(*check(patch, pressure, LAWS[lk], TENSORS["body"], vx, vy, omega, phi))


# ICR positions as fractions of the rim distance along a direction, or absolute offsets
ICR_CASES = {
    "inside": 0.4,
    "rim-in": 0.98,
    "rim-out": 1.02,
    "out1.5": 1.5,
    "out3": 3.0,
    "far100": 100.0,
}


def _icr_params(pressures, laws):
    out = []
    for ik in ICR_CASES:
        for pk in pressures:
            for lk in laws:
                marks = _marks(pk, lk, ik)
                out.append(pytest.param(ik, pk, lk, id=f"{ik}-{pk}-{lk}", marks=marks))
    return out


@pytest.mark.parametrize(
    ("ik", "pk", "lk"),
    _icr_params(("uniform", "linear", "hertz"), ("power0.5", "stribeck1", "table")),
)
def test_ellipse_icr_positions(ik, pk, lk):
    """ICR inside, at the rim (±2 %), outside and far; plane tensor, negative ω."""
    patch = ELLIPSES["b/a=0.5"]
    pressure = ellipse_pressure(pk, patch)
    r_g = mass_centre(patch, pressure)
    u = np.array([math.cos(0.9), math.sin(0.9)])
    icr = r_g + ICR_CASES[ik] * rim_distance(patch, r_g, u) * u
    phi, omega = -0.4, -2.0
    if ik == "far100":  # same slip speeds as the others: |v| ≈ 0.5 m/s
        omega = -0.5 / (100 * rim_distance(patch, r_g, u))
    vx, vy = state_for_icr(r_g, icr, phi, omega)
    assert_close(*check(patch, pressure, LAWS[lk], TENSORS["plane"], vx, vy, omega, phi))


# --------------------------------------------------------------------------- footprints
def _footprint_params():
    out = []
    combos = [
        ("lshape", "power0.5", "inside"),
        ("lshape", "stribeck2", "rim-in"),
        ("lshape", "table", "out1.5"),
        ("triangle", "power0.3", "rim-out"),
        ("triangle", "stribeck0.5", "inside"),
        ("triangle", "table", "far100"),
        ("rectangle", "power0.3", "inside"),
        ("rectangle", "stribeck1", "rim-out"),
        ("rectangle", "table", "rim-in"),
        ("rectangle", "power0.5", "out3"),
        ("ring", "power0.5", "inside"),
        ("ring", "stribeck2", "rim-in"),
        ("ring", "table", "out3"),
        ("ring", "power0.3", "rim-out"),
        ("disk", "power0.3", "rim-in"),
        ("disk", "stribeck0.5", "out1.5"),
        ("disk", "table", "inside"),
        ("disk", "power0.5", "far100"),
        ("pads", "power0.5", "inside"),
        ("pads", "stribeck1", "out1.5"),
        ("pads", "table", "inside"),
    ]
    for fk, lk, ik in combos:
        for pk in ("uniform", "linear"):
            out.append(pytest.param(fk, pk, lk, ik, id=f"{fk}-{pk}-{lk}-{ik}"))
    return out


@pytest.mark.parametrize(("fk", "pk", "lk", "ik"), _footprint_params())
def test_footprint_laws(fk, pk, lk, ik):
    """Polygons (non-convex L, triangle), rectangle, ring, off-centre disk and pads."""
    patch = FOOTPRINTS[fk]
    pressure = ("uniform",) if pk == "uniform" else linear_law(patch)
    r_g = mass_centre(patch, pressure)
    u = np.array([math.cos(0.35), math.sin(0.35)])
    frac = ICR_CASES[ik]
    if fk == "pads" and ik == "inside":  # inside the disk pad
        icr = np.array([0.01, 0.14])
    else:
        icr = r_g + frac * rim_distance(patch, r_g, u) * u
    tensor = TENSORS["body"] if pk == "uniform" else TENSORS["plane"]
    phi, omega = (1.1, 3.0) if pk == "uniform" else (-2.0, -2.2)
    if ik == "far100":
        omega = math.copysign(0.5 / (100 * reference_size(patch, pressure)), omega)
    vx, vy = state_for_icr(r_g, icr, phi, omega)
    assert_close(*check(patch, pressure, LAWS[lk], tensor, vx, vy, omega, phi))


# --------------------------------------------------------------------------- closed forms
@pytest.mark.parametrize("lk", list(LAWS))
@pytest.mark.parametrize("patch", [("disk", 0.12, (0.05, -0.03)), ("ellipse", 0.15, 0.15)])
def test_disk_pure_translation(patch, lk):
    """ω = 0: F = −μ P g(|v|) v̂, M = 0."""
    vx, vy = 0.21, -0.13
    speed = math.hypot(vx, vy)
    got = lib_wrench(patch, ("uniform",), LAWS[lk], ISO, vx, vy, 0.0, 0.3)
    g_v = float(speed_factor(LAWS[lk], speed))
    want = np.array([-0.4 * LOAD * g_v * vx / speed, -0.4 * LOAD * g_v * vy / speed, 0.0])
    assert np.all(np.abs(got - want) <= TOL * LOAD * np.array([1, 1, 0.15])), (got, want)


@pytest.mark.parametrize("lk", ["power0.5", "stribeck2", "table"])
@pytest.mark.parametrize("fk", ["lshape", "ring", "pads"])
def test_footprint_pure_translation(fk, lk):
    """ω = 0 on any patch: F = −P g(|v|) 𝔽_world v̂ (body-fixed tensor turned by φ), M = 0."""
    patch = FOOTPRINTS[fk]
    pressure = linear_law(patch)
    vx, vy, phi = -0.3, 0.17, 0.8
    got = lib_wrench(patch, pressure, LAWS[lk], TENSORS["body"], vx, vy, 0.0, phi)
    ref = np.array(
        reference_wrench(patch, pressure, LAWS[lk], TENSORS["body"], vx, vy, 0.0, phi, LOAD)
    )
    # the reference's ω = 0 branch is the closed form; check it independently here too
    fx, fy, f, ang, _ = TENSORS["body"]
    rot = np.array(
        [[math.cos(phi + ang), -math.sin(phi + ang)], [math.sin(phi + ang), math.cos(phi + ang)]]
    )
    fw = rot @ np.array([[fx, f], [-f, fy]]) @ rot.T
    speed = math.hypot(vx, vy)
    want = -LOAD * float(speed_factor(LAWS[lk], speed)) * fw @ np.array([vx, vy]) / speed
    assert np.allclose(ref[:2], want, rtol=0, atol=1e-14 * LOAD) and ref[2] == 0.0
    size = reference_size(patch, pressure)
    assert np.all(np.abs(got - ref) <= TOL * LOAD * np.array([1, 1, size])), (got, ref)


@pytest.mark.parametrize("omega", [3.0, -1.7])
@pytest.mark.parametrize("q", [0.5, 0.3])
@pytest.mark.parametrize("patch", [("disk", 0.12, (0.05, -0.03)), ("ellipse", 0.12, 0.12)])
def test_disk_pure_spin_power_law(patch, q, omega):
    """M = −sign ω μ P (|ω|/v0)^(−q) 2 R^(1−q)/(3 − q), F = 0 (spin about the centre)."""
    v0, radius, mu = 0.4, 0.12, 0.4
    law = ("power", q, v0)
    want = -math.copysign(1.0, omega) * mu * LOAD * (abs(omega) / v0) ** (-q)
    want *= 2 * radius ** (1 - q) / (3 - q)
    ref = reference_wrench(patch, ("uniform",), law, ISO, 0.0, 0.0, omega, 0.0, LOAD)
    assert abs(ref[2] - want) <= 1e-14 * LOAD * radius and max(map(abs, ref[:2])) < 1e-14 * LOAD
    got = lib_wrench(patch, ("uniform",), law, ISO, 0.0, 0.0, omega, 0.0)
    assert abs(got[2] - want) <= TOL * LOAD * radius, (got, want)
    assert np.all(np.abs(got[:2]) <= TOL * LOAD), got


@pytest.mark.parametrize("omega", [2.0, -0.8])
@pytest.mark.parametrize("q", [0.5, 0.3])
def test_ring_pure_spin_power_law(q, omega):
    """M = −sign ω μ P (|ω|/v0)^(−q) 2 (R2^(3−q) − R1^(3−q)) / ((3−q)(R2² − R1²))."""
    r1, r2, v0, mu = 0.08, 0.15, 0.5, 0.4
    patch = ("annulus", r1, r2, (0.01, 0.02))
    law = ("power", q, v0)
    want = -math.copysign(1.0, omega) * mu * LOAD * (abs(omega) / v0) ** (-q)
    want *= 2 * (r2 ** (3 - q) - r1 ** (3 - q)) / ((3 - q) * (r2**2 - r1**2))
    ref = reference_wrench(patch, ("uniform",), law, ISO, 0.0, 0.0, omega, 0.0, LOAD)
    assert abs(ref[2] - want) <= 1e-14 * LOAD * r2
    got = lib_wrench(patch, ("uniform",), law, ISO, 0.0, 0.0, omega, 0.0)
    assert abs(got[2] - want) <= TOL * LOAD * r2, (got, want)
    assert np.all(np.abs(got[:2]) <= TOL * LOAD), got


def _bh_spin_params():
    out = []
    for patch in (("disk", 0.12, (0.05, -0.03)), ("ellipse", 0.12, 0.12)):
        for pk in ("hertz", "boussinesq"):
            for q in (0.5, 0.3):
                out.append(pytest.param(patch, pk, q, id=f"{patch[0]}-{pk}-q{q}"))
    return out


def _bh_spin_moment(pk, q, omega, v0, radius, mu):
    """−sign ω μ (|ω|/v0)^(−q) 2π ∫ p(r) r^(2−q) dr with p of Hertz/Boussinesq."""
    k, b = (3.0, 1.5) if pk == "hertz" else (1.0, 0.5)
    integral = (
        k * LOAD / (2 * math.pi * radius**2) * radius ** (3 - q) * 0.5 * beta_fn((3 - q) / 2, b)
    )
    return -math.copysign(1.0, omega) * mu * (abs(omega) / v0) ** (-q) * 2 * math.pi * integral


@pytest.mark.parametrize(("patch", "pk", "q"), _bh_spin_params())
def test_hertz_boussinesq_disk_pure_spin_power_law(patch, pk, q):
    """Pressure (1 − r²/R²)^(±½) in pure spin: M from Beta functions."""
    omega, v0, radius, mu = 3.0, 0.5, 0.12, 0.4
    law = ("power", q, v0)
    want = _bh_spin_moment(pk, q, omega, v0, radius, mu)
    got = lib_wrench(patch, (pk,), law, ISO, 0.0, 0.0, omega, 0.0)
    assert abs(got[2] - want) <= TOL * LOAD * radius, (got, want)


@pytest.mark.parametrize("pk", ["hertz", "boussinesq"])
def test_reference_hertz_boussinesq_spin_closed_form(pk):
    """The reference itself meets the Beta-function closed form (so the xfail above is the
    library's)."""
    omega, v0, radius, mu = 3.0, 0.5, 0.12, 0.4
    for q in (0.5, 0.3):
        want = _bh_spin_moment(pk, q, omega, v0, radius, mu)
        ref = reference_wrench(("disk", radius), (pk,), ("power", q, v0), ISO, 0, 0, omega, 0, LOAD)
        assert abs(ref[2] - want) <= 1e-13 * LOAD * radius, (ref, want)


# --------------------------------------------------------------------------- symmetry
@pytest.mark.parametrize("lk", ["power0.5", "stribeck0.5", "table"])
@pytest.mark.parametrize("pk", ["uniform", "hertz"])
def test_mirror_symmetry(pk, lk):
    """Reflecting (vx, vy, ω) → (vx, −vy, −ω) about the ξ axis of an ellipse (φ = 0, isotropic
    tensor) reflects the wrench: (Fx, Fy, M) → (Fx, −Fy, −M)."""
    patch = ELLIPSES["b/a=0.5"]
    a = lib_wrench(patch, (pk,), LAWS[lk], ISO, 0.17, 0.09, 2.3, 0.0)
    b = lib_wrench(patch, (pk,), LAWS[lk], ISO, 0.17, -0.09, -2.3, 0.0)
    assert abs(a[2]) > 1e-3 * LOAD * 0.2 and abs(a[1]) > 1e-3 * LOAD
    assert np.all(np.abs(a * np.array([1, -1, -1]) - b) <= 1e-12 * LOAD * np.array([1, 1, 0.2]))


# --------------------------------------------------------------------------- library hangs
def _far_table_state():
    patch = ELLIPSES["b/a=0.5"]
    u = np.array([math.cos(0.9), math.sin(0.9)])
    rim = rim_distance(patch, np.zeros(2), u)
    omega = -0.5 / (100 * rim)
    vx, vy = state_for_icr(np.zeros(2), 100 * rim * u, -0.4, omega)
    return ("uniform", "table", "plane", (float(vx), float(vy), float(omega), -0.4))


HANG_CASES = {
    "boussinesq-stribeck2": ("boussinesq", "stribeck2", "body", (0.1, 0.05, 2.5, 0.7)),
    "boussinesq-table": ("boussinesq", "table", "body", (0.1, 0.05, 2.5, 0.7)),
}


@pytest.mark.parametrize("case", list(HANG_CASES))
def test_elliptic_engine_returns(case):
    """Run the call in a subprocess with a time limit, then compare with the reference."""
    pk, lk, tk, (vx, vy, omega, phi) = HANG_CASES[case]
    law, tensor = LAWS[lk], TENSORS[tk]
    cls = "Stribeck" if law[0] == "stribeck" else "SpeedTable"
    pressure = "BoussinesqPressure" if pk == "boussinesq" else "UniformPressure"
    code = textwrap.dedent(
        f"""
        import slidespin as ss
        from slidespin.contact.speed_laws import Stribeck, SpeedTable
        body = ss.Body(ss.Ellipse(0.2, 0.1), ss.{pressure}(), mass={MASS!r})
        t = ss.FrictionTensor({tensor[0]!r}, {tensor[1]!r}, {tensor[2]!r}, frame={tensor[4]!r},
                              angle={tensor[3]!r}, speed_law={cls}{tuple(law[1:])!r})
        w = ss.friction_wrench(body, t, {vx!r}, {vy!r}, {omega!r}, phi={phi!r}, g={GRAV!r})
        print(w.force_x, w.force_y, w.moment)
        """
    )
    try:
        out = subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, timeout=8, check=True
        )
    except subprocess.TimeoutExpired:
        pytest.fail("friction_wrench did not return within 8 s")
    ref = reference_wrench(ELLIPSES["b/a=0.5"], (pk,), law, tensor, vx, vy, omega, phi, LOAD)
    got = np.array([float(x) for x in out.stdout.split()])
    assert np.all(np.abs(got - ref) <= TOL * LOAD * np.array([1, 1, 0.2])), (got, ref)
