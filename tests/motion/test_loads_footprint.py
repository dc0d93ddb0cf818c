"""Static friction, stick–slip, critical tilt and the limit surface on footprints (MODEL §10–11),
against independent truth: closed forms (a block on a slope, the pure-spin torque of a disk and
of a ring, a push at G, a ramped push integrated by hand), the elliptic engine on the same disk,
the slow reference of ``tests/footprint_reference.py`` (wrenches) and a slow reference of the
support function of C written here from its definition (polar coordinates about the point
where the twist's velocity field vanishes), and the normality of the slip twist to the limit
surface (Goyal, Ruina & Papadopoulos 1991)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import quad_vec

import slidespin as ss
from slidespin.contact.wrench import footprint_wrench
from footprint_reference import (
    _breaks,
    _ray_intervals,
    _signed_fix,
    reference_pressure,
    reference_wrench,
    regions_of,
)
from slidespin.contact import static_set, statics
from slidespin.contact.limit_surface import limit_surface
from slidespin.contact.shapes import Annulus, Disk, Pads, Polygon, Rectangle
from slidespin.motion.loaded import simulate_loaded
from slidespin.contact.incline import Incline
from slidespin.motion.loads import Load

G = 9.81
MU = 0.35
BOX = ss.Body(Rectangle(0.4, 0.3), ss.UniformPressure(), mass=5.0)
ISO = ss.FrictionTensor.isotropic(MU)
ORTHO = ss.FrictionTensor(0.3, 0.5)


# ------------------------------------------------------------------------------------------
# a block on a slope: holds for tan α ≤ μ, slides with a = g (sin α − μ cos α)
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "friction, downhill, mu",
    [
        (ISO, 0.0, MU),
        (ISO, 2.0, MU),
        (ORTHO, 0.0, 0.3),
        (ORTHO, math.pi / 2, 0.5),  # the slope along a principal axis
    ],
)
def test_block_on_slope(friction, downhill, mu):
    phi = 0.7  # the block turned on the slope: a plane-fixed tensor, a centred pressure
    assert statics.critical_tilt(BOX, friction, downhill, phi) == pytest.approx(
        math.atan(mu), abs=1e-12
    )
    below = Incline(math.atan(mu) - 1e-9, downhill)
    tr = simulate_loaded(BOX, friction, ss.State(phi=phi), incline=below, t_end=0.5)
    assert tr.ending == "at_rest_throughout"
    assert (tr.x[-1], tr.y[-1], tr.phi[-1]) == (0.0, 0.0, phi)
    alpha = math.atan(mu) + 0.1
    t_end = 0.8
    tr = simulate_loaded(
        BOX, friction, ss.State(phi=phi), incline=Incline(alpha, downhill), t_end=t_end
    )
    dist = 0.5 * G * (math.sin(alpha) - mu * math.cos(alpha)) * t_end**2
    assert tr.ending == "moving_at_t_end"
    assert tr.x[-1] == pytest.approx(dist * math.cos(downhill), abs=1e-9 * dist)
    assert tr.y[-1] == pytest.approx(dist * math.sin(downhill), abs=1e-9 * dist)
    assert abs(tr.phi[-1] - phi) < 1e-9


def test_block_on_slope_load_factor_closed_form():
    # λ* of the downhill pull on the level plane is μ / tan α for any footprint
    # the incline adds the downhill pull itself: no other load
    lam = statics.load_factor(BOX, ISO, (0.0, 0.0, 0.0), incline=Incline(0.5))
    assert lam == pytest.approx(MU / math.tan(0.5), rel=1e-12)


# ------------------------------------------------------------------------------------------
# a disk and a ring under a torque: they turn only above (2/3) μ m g R_eff
# ------------------------------------------------------------------------------------------
def _ring_torque(r_in, r_out, m, g=G):
    return 2.0 / 3.0 * MU * m * g * (r_out**3 - r_in**3) / (r_out**2 - r_in**2)


@pytest.mark.parametrize(
    "patch, t_c",
    [
        (Disk(0.1), _ring_torque(0.0, 0.1, 2.0)),
        (Annulus(0.06, 0.1), _ring_torque(0.06, 0.1, 2.0)),
    ],
)
def test_torque_threshold(patch, t_c):
    body = ss.Body(patch, ss.UniformPressure(), mass=2.0)
    assert statics.load_factor(body, ISO, (0.0, 0.0, 1.0)) == pytest.approx(t_c, rel=1e-12)
    assert statics.can_stick(body, ISO, (0.0, 0.0, t_c * (1.0 - 1e-9)))
    assert not statics.can_stick(body, ISO, (0.0, 0.0, -t_c * (1.0 + 1e-9)))
    assert statics.onset(body, ISO, (0.0, 0.0, t_c * (1.0 - 1e-9))) is None
    # above: pure spin with ω̇ = (T − T_c)/I (I the default plate, m (R² + r²)/2)
    torque = 1.3 * t_c
    o = statics.onset(body, ISO, (0.0, 0.0, torque))
    assert np.allclose(o.direction, (0.0, 0.0, 1.0), atol=1e-9)
    inertia = 0.5 * 2.0 * (patch.inner_radius**2 + patch.outer_radius**2)
    assert body.moment_of_inertia == pytest.approx(inertia, rel=1e-14)
    t_end = 0.3
    tr = simulate_loaded(body, ISO, ss.State(), load=Load(torque=torque), t_end=t_end)
    alpha = (torque - t_c) / inertia
    assert tr.omega[-1] == pytest.approx(alpha * t_end, rel=1e-8)
    assert tr.phi[-1] == pytest.approx(0.5 * alpha * t_end**2, rel=1e-8)
    assert abs(tr.x[-1]) + abs(tr.y[-1]) < 1e-12


# ------------------------------------------------------------------------------------------
# a horizontal push at G on a rectangle: it starts only above μ m g
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("phi, direction", [(0.0, 0.0), (0.4, 0.9)])
def test_push_threshold_on_rectangle(phi, direction):
    mg = BOX.mass * G
    e = np.array([math.cos(direction), math.sin(direction)])
    lam = statics.load_factor(BOX, ISO, (*(mg * e), 0.0), phi)
    assert lam == pytest.approx(MU, rel=1e-12)
    below = (*(MU * mg * (1.0 - 1e-9) * e), 0.0)
    above = (*(1.4 * MU * mg * e), 0.0)
    assert statics.can_stick(BOX, ISO, below, phi)
    assert not statics.can_stick(BOX, ISO, (*(MU * mg * (1.0 + 1e-9) * e), 0.0), phi)
    o = statics.onset(BOX, ISO, above, phi)
    assert np.allclose(o.direction, (e[0], e[1], 0.0), atol=1e-9)
    assert o.acceleration == pytest.approx(0.4 * MU * G, rel=1e-9)


# ------------------------------------------------------------------------------------------
# the limit surface
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("friction", [ISO, ss.FrictionTensor(0.25, 0.45, 0.1, "body", 0.3)])
def test_limit_surface_disk_footprint_equals_circle(friction):
    m, r = 1.5, 0.08
    fp = limit_surface(ss.Body(Disk(r), ss.UniformPressure(), m), friction, n=80, phi=0.5)
    el = limit_surface(ss.Body(ss.Circle(r), ss.UniformPressure(), m), friction, n=80, phi=0.5)
    p = m * G
    for name, scale in (
        ("force_x", p),
        ("force_y", p),
        ("moment", p * r),
        ("support", p),
        ("dissipation_gap", p),
    ):
        assert np.max(np.abs(getattr(fp, name) - getattr(el, name))) < 1e-9 * scale, name
    assert fp.length == pytest.approx(el.length, rel=1e-14)


POLY = Polygon([(0.0, 0.0), (0.12, -0.02), (0.2, 0.06), (0.09, 0.03), (0.05, 0.11)])


def test_limit_surface_of_a_polygon_equals_its_wrenches():
    body = ss.Body(POLY, ss.LinearPressure(0.08, 0.035), mass=0.7)
    fr = ss.FrictionTensor(0.3, 0.4, 0.05)
    ls = limit_surface(body, fr, n=40, phi=0.2)
    w = footprint_wrench(
        POLY, ss.LinearPressure(0.08, 0.035), fr, ls.vx, ls.vy, ls.omega, 0.2, load=0.7 * G
    )
    assert np.array_equal(ls.force_x, w.force_x)
    assert np.array_equal(ls.moment, w.moment)
    # and the independent reference, for a few of the twists
    p = 0.7 * G
    ext = POLY.extent
    for i in (0, 7, 19, 33):
        ref = reference_wrench(
            POLY, ("linear", 0.08, 0.035), fr.matrix, ls.vx[i], ls.vy[i], ls.omega[i], 0.2, load=p
        )
        assert abs(ls.force_x[i] - ref[0]) < 1e-9 * p
        assert abs(ls.force_y[i] - ref[1]) < 1e-9 * p
        assert abs(ls.moment[i] - ref[2]) < 1e-9 * p * ext


# ------------------------------------------------------------------------------------------
# the support function of C for an anisotropic tensor, from its definition
# ------------------------------------------------------------------------------------------
def reference_support(footprint, law, friction, d, phi, load):
    """h(d) = ∫ p |S c| dS and ∇h (MODEL §11), S = 𝔽ᵀ, c = d_F + d_M J R(φ)(r − r_G), in
    polar coordinates about the body point r₀ where c vanishes (d_M ≠ 0)."""
    regions = _signed_fix(regions_of(footprint))
    p, (gx, gy) = reference_pressure(footprint, law, load)
    fw = friction.world_matrix(phi)
    s_mat = fw.T
    cph, sph = math.cos(phi), math.sin(phi)
    rot = np.array([[cph, -sph], [sph, cph]])
    jm = np.array([[0.0, -1.0], [1.0, 0.0]])
    d_f, d_m = np.array(d[:2], float), float(d[2])
    r0 = np.array([gx, gy]) + rot.T @ jm @ d_f / d_m
    glx, glw = np.polynomial.legendre.leggauss(12)
    glx, glw = 0.5 * (glx + 1.0), 0.5 * glw

    def integrand(psi):
        e = np.array([math.cos(psi), math.sin(psi)])
        sje = s_mat @ jm @ rot @ e
        zhat = math.copysign(1.0, d_m) * sje / np.linalg.norm(sje)
        k1 = k2 = 0.0
        k3 = np.zeros(2)
        for a, b in _ray_intervals(regions, r0, e):
            rho = a + (b - a) * glx
            wr = (b - a) * glw * rho
            pts = r0 + np.outer(rho, e)
            pr = p(pts[:, 0], pts[:, 1]) * wr
            k1 += pr @ rho
            k2 += pr.sum()
            k3 += pr @ ((pts - (gx, gy)) @ rot.T)  # ∫ p r′
        tz = fw @ zhat
        return np.array(
            [
                abs(d_m) * np.linalg.norm(sje) * k1,
                k2 * tz[0],
                k2 * tz[1],
                k3[0] * tz[1] - k3[1] * tz[0],
            ]
        )

    br = np.sort(np.mod(_breaks(regions, r0), 2 * np.pi))
    res, _ = quad_vec(
        integrand,
        br[0],
        br[0] + 2 * np.pi,
        points=[b for b in br if br[0] < b < br[0] + 2 * np.pi],
        epsabs=1e-14 * load,
        epsrel=1e-13,
        norm="max",
        limit=20000,
    )
    return res[0], res[1:]


SUPPORT_CASES = [
    (Rectangle(0.4, 0.3), ss.LinearPressure(0.02, -0.01), ss.FrictionTensor(0.3, 0.5, 0.1)),
    (
        Annulus(0.03, 0.1, centre=(0.01, 0.0)),
        ss.LinearPressure(0.015, 0.005),
        ss.FrictionTensor(0.2, 0.6, -0.15, "body", 0.4),
    ),
    (
        Pads(
            [Rectangle(0.1, 0.05, centre=(-0.15, 0.0), angle=0.3), Disk(0.04, centre=(0.12, 0.05))]
        ),
        ss.UniformPressure(),
        ss.FrictionTensor(0.5, 0.25, 0.0, "plane", 1.0),
    ),
]


def _law(pressure):
    if isinstance(pressure, ss.LinearPressure):
        return ("linear", pressure.xi_c, pressure.eta_c)
    return ("uniform",)


@pytest.mark.parametrize("patch, pressure, friction", SUPPORT_CASES)
@pytest.mark.parametrize("d", [(0.6, -0.8, 12.0), (1.0, 0.3, -2.5), (0.0, 0.1, 30.0)])
def test_support_function_anisotropic(patch, pressure, friction, d):
    body = ss.Body(patch, pressure, mass=2.0)
    phi = 0.35
    h, point = static_set.support_function(body, friction, d, phi)
    h_ref, point_ref = reference_support(patch, _law(pressure), friction, d, phi, 2.0 * G)
    scale = 2.0 * G * friction.norm
    assert abs(h - h_ref) < 1e-9 * scale * (abs(d[0]) + abs(d[1]) + abs(d[2]) * patch.extent)
    assert np.all(np.abs(point[:2] - point_ref[:2]) < 1e-9 * scale)
    assert abs(point[2] - point_ref[2]) < 1e-9 * scale * patch.extent
    assert h == pytest.approx(float(np.dot(point, d)), rel=1e-12)  # h(d) = d·∇h(d)


def test_support_function_pure_force_direction():
    # d_M = 0: h = P |𝔽ᵀ d_F| whatever the footprint
    fr = ss.FrictionTensor(0.3, 0.5, 0.1, "plane", 0.2)
    body = ss.Body(SUPPORT_CASES[2][0], ss.UniformPressure(), mass=2.0)
    h, _ = static_set.support_function(body, fr, (0.6, -0.8, 0.0), 0.3)
    assert h == pytest.approx(2.0 * G * np.linalg.norm(fr.matrix.T @ (0.6, -0.8)), rel=1e-13)


def test_critical_tilt_of_a_skewed_tensor_on_pads_matches_its_disk_twin():
    # the same disk as a footprint and as the paper's circle: the two engines agree
    fr = ss.FrictionTensor(0.25, 0.45, 0.12, "body", 0.3)
    a = statics.critical_tilt(ss.Body(Disk(0.05), ss.UniformPressure(), 1.0), fr, 0.7, 0.2)
    b = statics.critical_tilt(ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0), fr, 0.7, 0.2)
    assert a == pytest.approx(b, abs=1e-10)


# ------------------------------------------------------------------------------------------
# a ramped push on a box: stick, slip, stick, with the energy balance
# ------------------------------------------------------------------------------------------
def _ramped_push_truth(times, fx, m, mu, g=G):
    """Start, stop, distance and load work of a block pushed at G by a piecewise-linear force
    that ends at 0, by hand: m v̇ = F(t) − μ m g while it slides, integrated exactly piece by
    piece (polynomials)."""
    from numpy.polynomial import Polynomial as Poly

    mg = mu * m * g
    t0 = None
    for (ta, tb), (fa, fb) in zip(zip(times[:-1], times[1:]), zip(fx[:-1], fx[1:])):
        if fa < mg <= fb:
            t0 = ta + (mg - fa) / (fb - fa) * (tb - ta)
            break
    v = x = work = 0.0
    for ta, tb, fa, fb in zip(times[:-1], times[1:], fx[:-1], fx[1:]):
        if tb <= t0:
            continue
        slope = (fb - fa) / (tb - ta)
        force = Poly([fa - slope * ta, slope])
        lo = max(ta, t0)
        vel = ((force - mg) / m).integ(lbnd=lo) + v  # speed on [lo, tb]
        x += vel.integ(lbnd=lo)(tb)
        work += (force * vel).integ(lbnd=lo)(tb)
        v = vel(tb)
    t1 = times[-1] + v / (mu * g)  # the force is 0 after the last sample
    x += 0.5 * v * v / (mu * g)
    return t0, t1, x, work


def test_ramped_push_on_a_box_stick_slip_stick():
    times, fx = [0.0, 2.0, 3.0, 3.1], [0.0, 25.0, 25.0, 0.0]
    push = Load.piecewise_linear(times, fx, [0.0] * 4)
    tr = simulate_loaded(BOX, ISO, ss.State(), load=push, t_end=5.0)
    t0, t1, dist, work = _ramped_push_truth(times, fx, BOX.mass, MU)
    assert t0 == pytest.approx(MU * BOX.mass * G / 12.5, rel=1e-14)
    assert [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
    assert tr.status == "ok" and tr.ending == "stopped_stuck"
    assert tr.phases[0][2] == pytest.approx(t0, abs=1e-9)
    assert tr.phases[1][2] == pytest.approx(t1, abs=1e-8)
    assert tr.x[-1] == pytest.approx(dist, rel=1e-8)
    assert abs(tr.y[-1]) < 1e-12 and abs(tr.phi[-1]) < 1e-12
    # energy: the load's work = friction dissipation (μ m g × distance) + ΔKE (= 0)
    assert tr.load_work[-1] == pytest.approx(work, rel=1e-8)
    assert -tr.friction_work[-1] == pytest.approx(MU * BOX.mass * G * dist, rel=1e-8)
    assert tr.kinetic_energy[-1] == 0.0
    assert tr.energy_error < 1e-8 * work


def test_ramped_push_below_threshold_holds():
    push = Load.piecewise_linear([0.0, 1.0], [0.0, 0.999 * MU * BOX.mass * G], [0.0, 0.0])
    tr = simulate_loaded(BOX, ISO, ss.State(), load=push, t_end=2.0)
    assert tr.ending == "at_rest_throughout"
    assert tr.x[-1] == 0.0


def test_off_centre_ramped_push_energy_balance():
    # a push off G turns the box as it slides; ΔKE = W_loads + W_friction along the way
    push = Load.piecewise_linear(
        [0.0, 1.0, 1.5, 1.6], [0.0, 30.0, 30.0, 0.0], [0.0] * 4, at=(0.1, 0.12)
    )
    tr = simulate_loaded(BOX, ISO, ss.State(), load=push, t_end=3.0)
    assert [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
    assert abs(tr.phi[-1]) > 1e-3  # it turned
    assert tr.energy_error < 1e-8 * tr.load_work[-1]
    ke = tr.kinetic_energy
    assert np.max(np.abs(ke - ke[0] - tr.load_work - tr.friction_work)) < 1e-8 * tr.load_work[-1]


# ------------------------------------------------------------------------------------------
# slip onset for an off-centre push: normal to the limit surface (isotropic)
# ------------------------------------------------------------------------------------------
def _twist(body, u):
    return np.array([u[0], u[1], u[2] / body.radius_of_gyration])


def test_onset_of_an_off_centre_push_is_normal_to_the_limit_surface():
    phi = 0.3
    p_load = BOX.mass * G
    at = np.array([-0.2, 0.1])  # a push on the box's edge, off G
    e = np.array([math.cos(0.4), math.sin(0.4)])
    rot = np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])
    ra = rot @ at
    w_unit = np.array([e[0], e[1], ra[0] * e[1] - ra[1] * e[0]])  # unit push and its moment
    lam = statics.load_factor(BOX, ISO, w_unit, phi)
    # just beyond the threshold: the twist whose friction wrench balances the load
    w_a = lam * (1.0 + 1e-9) * w_unit
    o = statics.onset(BOX, ISO, w_a, phi)
    tw = _twist(BOX, o.direction)
    law = ("uniform",)
    ref = np.array(reference_wrench(BOX.patch, law, ISO.matrix, *tw, phi, load=p_load))
    assert np.allclose(ref, -w_a, atol=1e-9 * p_load)  # measured 2e-10
    # the twist is normal to the limit surface there: nearby wrenches W(tw + ε δ) differ from
    # W(tw) by vectors orthogonal to tw (to O(ε²))
    basis = np.linalg.svd(tw.reshape(1, 3))[2][1:]
    eps = 1e-4 * np.linalg.norm(tw)
    for b in basis:
        wp = np.array(
            reference_wrench(BOX.patch, law, ISO.matrix, *(tw + eps * b), phi, load=p_load)
        )
        wm = np.array(
            reference_wrench(BOX.patch, law, ISO.matrix, *(tw - eps * b), phi, load=p_load)
        )
        tangent = (wp - wm) / (2 * eps)
        assert abs(tangent @ tw) < 1e-6 * np.linalg.norm(tangent) * np.linalg.norm(tw)
    # beyond the threshold, the onset law M⁻¹(W_a + W(u)) = λ u with the reference wrench
    w_b = 1.5 * lam * w_unit
    o = statics.onset(BOX, ISO, w_b, phi)
    tw = _twist(BOX, o.direction)
    ref = np.array(reference_wrench(BOX.patch, law, ISO.matrix, *tw, phi, load=p_load))
    k = BOX.radius_of_gyration
    acc = np.array(
        [
            (w_b[0] + ref[0]) / BOX.mass,
            (w_b[1] + ref[1]) / BOX.mass,
            (w_b[2] + ref[2]) / (BOX.mass * k),
        ]
    )
    assert np.allclose(acc, o.acceleration * o.direction, atol=1e-8 * G)


# ------------------------------------------------------------------------------------------
# case files with a footprint, a load and an incline, from the command line
# ------------------------------------------------------------------------------------------
CASE = """
name = "box"
[patch]
shape = "rectangle"
length = 0.4
width = 0.3
[pressure]
law = "uniform"
[friction]
fx = 0.35
fy = 0.35
[body]
mass = 5.0
[initial]
vx = 0.0
"""


def test_cli_simulate_footprint_with_load(tmp_path, capsys):
    from slidespin.cli.main import main

    path = tmp_path / "case.toml"
    force = 1.2 * MU * 5.0 * G
    path.write_text(CASE + f"[load]\nfx = {force}\n[solver]\nt_end = 0.5\n")
    assert main(["simulate", str(path), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["x_final"] == pytest.approx(0.5 * 0.2 * MU * G * 0.5**2, rel=1e-8)


def test_cli_limit_surface_footprint_on_incline(tmp_path, capsys):
    from slidespin.cli.main import main

    path = tmp_path / "case.toml"
    path.write_text(CASE + "[incline]\nangle_deg = 10.0\n")
    assert main(["limit-surface", str(path), "--n", "30", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    load = 5.0 * G * math.cos(math.radians(10.0))
    assert out["normal_load"] == pytest.approx(load, rel=1e-14)
    assert out["max_force"] <= MU * load * (1.0 + 1e-12)  # |F| ≤ μ P, the pure translation
    assert out["max_dissipation_gap"] < 1e-12 * load


# ------------------------------------------------------------------------------------------
# a sled on two runners with a body-fixed orthotropic tensor (low friction along the runners)
# ------------------------------------------------------------------------------------------
SLED = ss.Body(
    Pads([Rectangle(1.0, 0.03, centre=(0.0, 0.2)), Rectangle(1.0, 0.03, centre=(0.0, -0.2))]),
    ss.UniformPressure(),
    mass=20.0,
    moment_of_inertia=20.0 * (1.0 + 0.16) / 12.0,
)
RUNNERS = ss.FrictionTensor(0.05, 0.6, frame="body")


@pytest.mark.parametrize("phi, mu", [(0.0, 0.05), (math.pi / 2, 0.6)])
def test_sled_on_slope_along_and_across_its_runners(phi, mu):
    # the slope runs along OX: along the runners for φ = 0, across them for φ = π/2
    assert statics.critical_tilt(SLED, RUNNERS, 0.0, phi) == pytest.approx(math.atan(mu), abs=1e-12)
    tr = simulate_loaded(
        SLED, RUNNERS, ss.State(phi=phi), incline=Incline(math.atan(mu) - 1e-9), t_end=0.5
    )
    assert tr.ending == "at_rest_throughout"
    alpha, t_end = math.atan(mu) + 0.05, 0.6
    tr = simulate_loaded(SLED, RUNNERS, ss.State(phi=phi), incline=Incline(alpha), t_end=t_end)
    dist = 0.5 * G * (math.sin(alpha) - mu * math.cos(alpha)) * t_end**2
    assert tr.x[-1] == pytest.approx(dist, rel=1e-9)
    assert abs(tr.y[-1]) < 1e-9 * dist and abs(tr.phi[-1] - phi) < 1e-9


def test_sled_spinning_on_slope_energy_balance():
    # thrown with a spin on a slope steeper than its runners' friction angle: friction, gravity
    # and kinetic energy balance (the slope's work from the displacement alone)
    alpha = math.atan(0.05) + 0.1
    tr = simulate_loaded(
        SLED, RUNNERS, ss.State(vx=1.0, omega=3.0), incline=Incline(alpha, 0.3), t_end=1.0
    )
    ke = tr.kinetic_energy
    assert abs(ke[-1] - ke[0] - tr.gravity_work - tr.friction_work[-1]) < 1e-8 * ke[0]
    assert tr.load_work[-1] == pytest.approx(tr.gravity_work, rel=1e-9)
