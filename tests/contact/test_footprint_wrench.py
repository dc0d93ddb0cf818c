"""Footprints of any shape: value objects, pressure, and the exact wrench against independent truth.

Truth used here (issue #12 item 6): the slow reference ``tests/footprint_reference.py`` (rays
about the ICR with adaptive quadrature; shares no code with the kernel), the existing ellipse
kernel (``slidespin.friction_wrench`` on a ``Circle``), closed forms (pure translation, the
pure-spin torque of a ring, a ring as the difference of two disks, statics of three pads),
``scipy.integrate.quad`` for the elliptic moments, limits (256-gon → disk, ring with a vanishing
hole → disk), symmetry and dissipation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import ellipe, ellipk

import slidespin as ss
from footprint_reference import reference_power, reference_pressure, reference_wrench
from slidespin.contact import _kernel_disk as KD
from slidespin.contact import _kernel_footprint as K
from slidespin.contact.wrench import footprint_wrench
from slidespin.contact.pressure_map import (
    PressureMap,
    area_rule,
    kernel_geometry,
    mass_centre,
    pressure_coefficients,
)
from slidespin.contact.shapes import Annulus, Disk, Pads, Polygon, Rectangle

TOL = 1e-9  # agreement with the reference: units of P (force) and P × extent (moment)

L_SHAPE = [(0.0, 0.0), (0.3, 0.0), (0.3, 0.1), (0.1, 0.1), (0.1, 0.25), (0.0, 0.25)]
ARROW = [(0.0, 0.0), (0.2, 0.08), (0.0, 0.16), (0.05, 0.08)]  # non-convex, clockwise below

FOOTPRINTS = {
    "square": Rectangle(0.2, 0.2),
    "rectangle": Rectangle(0.3, 0.1, centre=(0.02, -0.01), angle=0.4),
    "triangle": Polygon([(0.0, 0.0), (0.25, 0.02), (0.05, 0.18)]),
    "L-shape": Polygon(L_SHAPE, centre=(-0.1, -0.1)),
    "arrow-cw": Polygon(ARROW[::-1]),
    "disk": Disk(0.1, centre=(0.01, 0.02)),
    "ring": Annulus(0.06, 0.1),
    "pads": Pads(
        [
            Disk(0.03, centre=(-0.15, 0.0)),
            Rectangle(0.06, 0.2, centre=(0.12, 0.0)),
            Polygon([(0.0, 0.1), (0.05, 0.15), (-0.05, 0.15)]),
        ]
    ),
}

TENSORS = {
    "isotropic": ss.FrictionTensor(0.4, 0.4),
    "orthotropic": ss.FrictionTensor(0.3, 0.6),
    "skew": ss.FrictionTensor(0.3, 0.5, f=0.12, angle=0.4),
    "skew-body": ss.FrictionTensor(0.35, 0.55, f=-0.08, frame="body", angle=-0.3),
}


def _law(fp, kind):
    if kind == "uniform":
        return ss.UniformPressure(), ("uniform",)
    cx, cy = fp.centroid
    ext = fp.to_arrays().frame[2]
    xg, yg = cx + 0.04 * ext, cy - 0.03 * ext
    return ss.LinearPressure(xg, yg), ("linear", xg, yg)


def _velocity(fp, law, icr, phi, omega=1.0):
    """World velocity of G for a body-frame ICR ``icr`` (the motion about that point)."""
    gx, gy = mass_centre(fp, law)
    vbx, vby = -omega * (gy - icr[1]), omega * (gx - icr[0])
    c, s = math.cos(phi), math.sin(phi)
    return c * vbx - s * vby, s * vbx + c * vby


def _icr_points(fp):
    """Named ICR positions (body frame) for every motion regime of the footprint."""
    a = fp.to_arrays()
    ox, oy, ext = a.frame
    pts = {
        "centroid-ish": (ox + 0.13 * ext, oy - 0.07 * ext),
        "outside-near": (ox + 1.3 * ext, oy + 0.4 * ext),
        "mid": (ox - 6.0 * ext, oy + 3.0 * ext),
        "far": (ox + 300.0 * ext, oy - 200.0 * ext),
        # either side of the kernel's switch from the exact fan to the far-field rule
        "switch-fan": (ox + 0.99 * K.FAR_RATIO * ext, oy),
        "switch-far": (ox, oy - 1.01 * K.FAR_RATIO * ext),
    }
    if len(a.edges):
        x0, y0, x1, y1 = a.edges[1]
        pts["vertex"] = (x0, y0)
        pts["edge"] = (0.7 * x0 + 0.3 * x1, 0.7 * y0 + 0.3 * y1)
    for cx, cy, r, sg in a.circles:
        if sg < 0:
            pts["hole"] = (cx + 0.5 * r, cy - 0.2 * r)
            pts["hole-rim"] = (cx + r, cy)
        else:
            pts["rim"] = (cx, cy - r)
            pts["near-rim"] = (cx + (1.0 - 1e-7) * r, cy)
    return pts


CASES = [
    (f, law, t, icr)
    for f in FOOTPRINTS
    for law in ("uniform", "linear")
    for t in TENSORS
    for icr in _icr_points(FOOTPRINTS[f])
]
# a representative subset for the slow reference: every footprint × law × ICR regime, the
# tensors cycled through
REF_CASES = [
    c
    for i, c in enumerate(CASES)
    if list(TENSORS).index(c[2]) == i % len(TENSORS) or c[3] in ("vertex", "edge", "hole", "rim")
]


def _compare(fp, lawname, tname, icr_name, phi=0.7, omega=-2.5):
    fp_obj = FOOTPRINTS[fp]
    law, ref_law = _law(fp_obj, lawname)
    icr = _icr_points(fp_obj)[icr_name]
    vx, vy = _velocity(fp_obj, law, icr, phi, omega)
    fr = TENSORS[tname]
    load = 3.0
    w = footprint_wrench(fp_obj, law, fr, vx, vy, omega, phi, load=load)
    ref = reference_wrench(
        fp_obj, ref_law, fr.matrix, vx, vy, omega, phi=phi, frame=fr.frame, load=load
    )
    ext = fp_obj.to_arrays().frame[2]
    return (
        np.array([w.force_x, w.force_y, w.moment / ext]),
        np.array([ref[0], ref[1], ref[2] / ext]),
        load,
    )


@pytest.mark.parametrize("fp,law,tensor,icr", REF_CASES)
def test_wrench_matches_reference(fp, law, tensor, icr):
    got, ref, load = _compare(fp, law, tensor, icr)
    assert np.abs(got - ref).max() <= TOL * load, (got, ref)


@pytest.mark.parametrize("omega", [0.0, 1e-13])
@pytest.mark.parametrize("fp", list(FOOTPRINTS))
def test_translation_closed_form(fp, omega):
    """Pure (or all but pure) translation: F = −P 𝔽 v̂ and M = 0 since G is the centroid."""
    fr = TENSORS["skew"]
    for kind in ("uniform", "linear"):
        law, _ = _law(FOOTPRINTS[fp], kind)
        w = footprint_wrench(FOOTPRINTS[fp], law, fr, 0.6, -0.8, omega, 0.3, load=2.0)
        f = -2.0 * fr.world_matrix(0.3) @ np.array([0.6, -0.8])
        assert abs(w.force_x - f[0]) <= 1e-12 and abs(w.force_y - f[1]) <= 1e-12
        assert abs(w.moment) <= 1e-12


@pytest.mark.parametrize("inner", [0.0, 0.02, 0.06, 0.099])
def test_ring_pure_spin_torque(inner):
    """Uniform ring spinning about its centre: M = −(2/3) μ P (R³ − r³)/(R² − r²)."""
    outer, mu, load = 0.1, 0.35, 7.0
    fp = Annulus(inner, outer, centre=(0.2, -0.1))
    for omega in (3.0, -0.5):
        w = footprint_wrench(
            fp,
            ss.UniformPressure(),
            ss.FrictionTensor.isotropic(mu),
            0.0,
            0.0,
            omega,
            1.1,
            load=load,
        )
        exact = (
            -math.copysign(1.0, omega)
            * 2.0
            / 3.0
            * mu
            * load
            * (outer**3 - inner**3)
            / (outer**2 - inner**2)
        )
        assert abs(w.moment - exact) <= 1e-13 * load * outer
        assert abs(w.force_x) + abs(w.force_y) <= 1e-13 * load


@pytest.mark.parametrize(
    "icr", [(0.02, 0.01), (0.045, 0.0), (0.07, 0.03), (0.1, 0.0), (0.3, -0.2), (0.0, 0.0)]
)
def test_ring_is_disk_minus_disk(icr):
    """Uniform ring = outer disk (load ∝ its area) minus the hole (by linearity)."""
    r, big, load = 0.05, 0.1, 1.0
    fr = TENSORS["skew"]
    ring = Annulus(r, big)
    law = ss.UniformPressure()
    vx, vy = _velocity(ring, law, icr, 0.0)
    p = load / (math.pi * (big**2 - r**2))
    w_ring = footprint_wrench(ring, law, fr, vx, vy, 1.0, load=load)
    w_out = footprint_wrench(Disk(big), law, fr, vx, vy, 1.0, load=p * math.pi * big**2)
    w_in = footprint_wrench(Disk(r), law, fr, vx, vy, 1.0, load=p * math.pi * r**2)
    for name in ("force_x", "force_y", "moment"):
        assert abs(getattr(w_ring, name) - (getattr(w_out, name) - getattr(w_in, name))) <= 1e-13


def _ellipse_kernel(radius, law, fr, vx, vy, omega, phi, load):
    body = ss.Body(ss.Circle(radius), law, mass=load / 9.81)
    return ss.friction_wrench(body, fr, vx, vy, omega, phi, tol=1e-13)


@pytest.mark.parametrize("tensor", list(TENSORS))
@pytest.mark.parametrize("kind", ["uniform", "linear"])
def test_disk_matches_ellipse_kernel(tensor, kind):
    """The elliptic-integral disk against the existing ellipse kernel (a different method:
    angular quadrature), ICR inside, on the rim, near it, outside, far."""
    a, load = 0.1, 1.0
    fr = TENSORS[tensor]
    law = ss.UniformPressure() if kind == "uniform" else ss.LinearPressure(0.015, -0.01)
    disk = Disk(a)
    for icr in [
        (0.0, 0.0),
        (0.03, -0.05),
        (0.1, 0.0),
        (0.0, -0.0999999),
        (0.06, 0.08),
        (0.13, 0.02),
        (0.5, -0.7),
        (40.0, 3.0),
    ]:
        for phi in (0.0, 1.2):
            vx, vy = _velocity(disk, law, icr, phi, 1.7)
            w = footprint_wrench(disk, law, fr, vx, vy, 1.7, phi, load=load)
            e = _ellipse_kernel(a, law, fr, vx, vy, 1.7, phi, load)
            assert abs(w.force_x - e.force_x) <= 1e-10 * load
            assert abs(w.force_y - e.force_y) <= 1e-10 * load
            assert abs(w.moment - e.moment) <= 1e-10 * load * a


def test_disk_pure_spin_closed_form():
    """Pure spin of a uniform disk about its centre: M = −(2/3) f P a (MODEL §8)."""
    w = footprint_wrench(
        Disk(0.2), ss.UniformPressure(), ss.FrictionTensor.isotropic(0.5), 0.0, 0.0, 4.0, load=3.0
    )
    assert abs(w.moment + 2.0 / 3.0 * 0.5 * 3.0 * 0.2) <= 1e-14


def _ngon(n, a):
    t = 2.0 * np.pi * np.arange(n) / n
    return Polygon(np.column_stack((a * np.cos(t), a * np.sin(t))))


def test_polygon_tends_to_disk():
    """Regular n-gons inscribed in a circle tend to the disk (the ellipse kernel on a
    Circle) with error O(1/n²); the 256-gon's pure-spin torque tends to (2/3) f P a."""
    a = 0.1
    fr = TENSORS["orthotropic"]
    law = ss.UniformPressure()
    states = [(0.0, 0.0, 1.0), (0.03, -0.02, 1.0), (0.2, 0.1, -1.0), (1.0, 0.5, 0.0)]
    errs = []
    for n in (64, 128, 256):
        fp = _ngon(n, a)
        err = 0.0
        for vx, vy, om in states:
            w = footprint_wrench(fp, law, fr, vx, vy, om)
            e = _ellipse_kernel(a, law, fr, vx, vy, om, 0.0, 1.0)
            err = max(
                err,
                abs(w.force_x - e.force_x),
                abs(w.force_y - e.force_y),
                abs(w.moment - e.moment) / a,
            )
        errs.append(err)
    assert errs[2] < 2e-4
    assert 3.0 < errs[0] / errs[1] < 5.0 and 3.0 < errs[1] / errs[2] < 5.0
    iso = ss.FrictionTensor.isotropic(0.3)
    w = footprint_wrench(_ngon(256, a), law, iso, 0.0, 0.0, 1.0)
    assert abs(w.moment + 2.0 / 3.0 * 0.3 * a) < 1e-4 * 0.3 * a


@pytest.mark.parametrize("icr", [(0.02, 0.01), (0.09, 0.0), (0.3, 0.1)])
def test_ring_with_vanishing_hole_is_disk(icr):
    fr = TENSORS["skew"]
    law = ss.UniformPressure()
    vx, vy = _velocity(Disk(0.1), law, icr, 0.0)
    disk = footprint_wrench(Disk(0.1), law, fr, vx, vy, 1.0)
    errs = []
    for r in (1e-3, 1e-4, 1e-5):  # hole radius [m]: the difference is O((r/R)²)
        ring = footprint_wrench(Annulus(r, 0.1), law, fr, vx, vy, 1.0)
        errs.append(
            max(
                abs(ring.force_x - disk.force_x),
                abs(ring.force_y - disk.force_y),
                abs(ring.moment - disk.moment) / 0.1,
            )
        )
    assert errs[2] < 2.0 * 0.6 * (1e-5 / 0.1) ** 2  # ‖𝔽‖ (r/R)² P, twice
    assert 80.0 < errs[0] / errs[1] < 120.0 and 80.0 < errs[1] / errs[2] < 120.0


def test_mirror_symmetry():
    """Mirror η → −η: footprint, G, ICR and tensor mirrored; F mirrors, M and ω change sign."""
    fr = ss.FrictionTensor(0.3, 0.55, f=0.1, frame="body")
    s = np.diag([1.0, -1.0])
    tm = s @ fr.matrix @ s
    fr_m = ss.FrictionTensor(tm[0, 0], tm[1, 1], f=tm[0, 1], frame="body")
    poly = Polygon(L_SHAPE, centre=(0.01, 0.02), angle=0.3)
    mirrored = Polygon([(x, -y) for x, y in poly.points])
    law = ss.LinearPressure(poly.centroid[0] + 0.005, poly.centroid[1] - 0.004)
    law_m = ss.LinearPressure(law.xi_c, -law.eta_c)
    rng = np.random.default_rng(5)
    for _ in range(6):
        vx, vy, om = rng.normal(size=3) * (0.2, 0.2, 1.0)
        w = footprint_wrench(poly, law, fr, vx, vy, om)
        m = footprint_wrench(mirrored, law_m, fr_m, vx, -vy, -om)
        assert abs(w.force_x - m.force_x) < 1e-14 and abs(w.force_y + m.force_y) < 1e-14
        assert abs(w.moment + m.moment) < 1e-14


def test_rotation_invariance():
    """Turning the whole motion (φ, velocity, plane tensor) by α turns F and keeps M."""
    fp = FOOTPRINTS["pads"]
    law, _ = _law(fp, "linear")
    fr = TENSORS["skew"]
    alpha = 0.9
    c, s = math.cos(alpha), math.sin(alpha)
    r = np.array([[c, -s], [s, c]])
    tr = r @ fr.matrix @ r.T
    # a tensor turned by α: [[fx, f], [−f, fy]] turned by angle + α
    fr_r = ss.FrictionTensor(fr.fx, fr.fy, f=fr.f, angle=fr.angle + alpha)
    assert np.allclose(fr_r.matrix, tr)
    for vx, vy, om, phi in [(0.1, 0.05, 1.0, 0.2), (0.0, 0.3, -2.0, 1.0), (0.4, -0.1, 0.0, 2.0)]:
        w = footprint_wrench(fp, law, fr, vx, vy, om, phi)
        v2 = r @ np.array([vx, vy])
        w2 = footprint_wrench(fp, law, fr_r, v2[0], v2[1], om, phi + alpha)
        f2 = r @ np.array([w.force_x, w.force_y])
        assert abs(w2.force_x - f2[0]) < 1e-13 and abs(w2.force_y - f2[1]) < 1e-13
        assert abs(w2.moment - w.moment) < 1e-13


@pytest.mark.parametrize("fp", list(FOOTPRINTS))
def test_dissipation(fp):
    """Friction power F·v + M ω ≤ 0 in every state; with a far ICR it equals
    −∫p (w·𝔽w)/|w| dS (the reference's smooth-integrand rule)."""
    fpo = FOOTPRINTS[fp]
    fr = ss.FrictionTensor(0.3, 0.6, f=0.2, frame="body")
    law, ref_law = _law(fpo, "linear")
    rng = np.random.default_rng(11)
    v = rng.normal(size=(200, 3)) * (0.1, 0.1, 1.0)
    w = footprint_wrench(fpo, law, fr, v[:, 0], v[:, 1], v[:, 2])
    assert np.all(w.power(v[:, 0], v[:, 1], v[:, 2]) <= 1e-15)
    ext = fpo.to_arrays().frame[2]
    for vx, vy, om in [(50.0 * ext, 20.0 * ext, 1.0), (0.3, -0.2, 0.0)]:
        w1 = footprint_wrench(fpo, law, fr, vx, vy, om)
        ref = reference_power(fpo, ref_law, fr.matrix, vx, vy, om)
        assert abs(w1.power(vx, vy, om) - ref) <= 1e-10 * math.hypot(vx, vy)


def test_world_array_input_and_paper_components():
    fp = FOOTPRINTS["rectangle"]
    fr = TENSORS["orthotropic"]
    vx = np.array([0.1, 0.0, -0.2])
    w = footprint_wrench(fp, ss.UniformPressure(), fr, vx, 0.05, 1.0, phi=[0.0, 0.5, 1.0])
    assert w.force_x.shape == (3,)
    one = footprint_wrench(fp, ss.UniformPressure(), fr, -0.2, 0.05, 1.0, phi=1.0)
    assert one.force_x == w.force_x[2] and one.moment == w.moment[2]
    th = math.atan2(0.05, -0.2)
    assert abs(one.tangential + one.force_x * math.cos(th) + one.force_y * math.sin(th)) < 1e-15
    assert one.moment_paper == -one.moment
    rest = footprint_wrench(fp, ss.UniformPressure(), fr, 0.0, 0.0, 0.0)
    assert rest.force_x == rest.force_y == rest.moment == 0.0


# ---------------------------------------------------------------------------------------------
# the elliptic moments of the disk


@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
@pytest.mark.parametrize("m", [0.0, 0.1, 0.449, 0.451, 0.8, 0.99, 1.0 - 1e-9, 1.0 - 1e-15, 1.0])
def test_disk_moments_against_quad(m):
    if m == 1.0:  # the rim: ∫ s^{2n} c dψ = 1/(2n + 1) for both forms
        for outside in (False, True):
            assert np.allclose(KD.disk_moments(m, outside), [1, 1 / 3, 1 / 5, 1 / 7], rtol=1e-15)
        return
    for outside in (False, True):
        got = KD.disk_moments(m, outside)
        for n in range(4):

            def f(t, n=n, outside=outside):
                s2 = np.sin(t) ** 2
                if outside:
                    return s2**n * (1.0 - s2) / np.sqrt(1.0 - m * s2)
                return s2**n * np.sqrt(1.0 - m * s2)

            # graded breaks towards π/2, where the integrand is near-singular as m → 1
            brk = [0.5 * np.pi - 10.0**-k for k in range(1, 9)]
            exact = sum(
                quad(f, a, b, epsabs=1e-17, epsrel=1e-14, limit=200)[0]
                for a, b in zip([0.0] + brk, brk + [0.5 * np.pi])
            )
            assert abs(got[n] - exact) <= 2e-14, (n, outside, got[n], exact)
    if m < 1.0:  # U₀ = E(m), U₁ = ((1 − m)K − (1 − 2m)E)/(3m)
        e, k = ellipe(m), ellipk(m)
        u = KD.disk_moments(m, False)
        assert abs(u[0] - e) <= 1e-14
        if m > 0.0:
            assert abs(u[1] - ((1 - m) * k - (1 - 2 * m) * e) / (3 * m)) <= 1e-14 / m


# ---------------------------------------------------------------------------------------------
# value objects


def test_polygon_properties_closed_form():
    r = Rectangle(0.4, 0.1, centre=(0.3, -0.2), angle=0.5)
    assert abs(r.area - 0.04) < 1e-16
    assert np.allclose(r.centroid, (0.3, -0.2), atol=1e-15)
    c, s = math.cos(0.5), math.sin(0.5)
    rot = np.array([[c, -s], [s, c]])
    j = rot @ np.diag([0.4**3 * 0.1 / 12, 0.4 * 0.1**3 / 12]) @ rot.T
    assert np.allclose(r.second_moment, j, rtol=1e-12, atol=1e-18)
    # L-shape = two rectangles; orientation does not matter
    lsh = Polygon(L_SHAPE)
    assert abs(lsh.area - (0.3 * 0.1 + 0.1 * 0.15)) < 1e-15
    cx = (0.03 * 0.15 + 0.015 * 0.05) / 0.045
    cy = (0.03 * 0.05 + 0.015 * 0.175) / 0.045
    assert np.allclose(lsh.centroid, (cx, cy), atol=1e-15)
    assert np.allclose(Polygon(L_SHAPE[::-1]).second_moment, lsh.second_moment, atol=1e-18)
    ring = Annulus(0.05, 0.1, centre=(1.0, 2.0))
    assert abs(ring.area - math.pi * (0.01 - 0.0025)) < 1e-15
    assert np.allclose(ring.second_moment, np.eye(2) * math.pi * (0.1**4 - 0.05**4) / 4, atol=1e-18)
    assert abs(ring.plate_inertia(2.0) - 2.0 * (0.1**2 + 0.05**2) / 2) < 1e-13 * 0.0125


def test_arrays_layout():
    fp = FOOTPRINTS["pads"]
    a = fp.to_arrays()
    assert a.edges.shape == (4 + 3, 4) and a.circles.shape == (1, 4)
    assert a.edges.dtype == np.float64 and a.edges.flags.c_contiguous
    cw = Polygon(ARROW[::-1]).to_arrays().edges
    assert 0.5 * np.sum(cw[:, 0] * cw[:, 3] - cw[:, 2] * cw[:, 1]) > 0  # stored counter-clockwise
    ring = Annulus(0.03, 0.05).to_arrays().circles
    assert ring[:, 3].tolist() == [1.0, -1.0]
    # extent: the farthest vertex or disk rim from the area centroid
    ox, oy = fp.centroid
    far = max(
        np.hypot(a.edges[:, 0] - ox, a.edges[:, 1] - oy).max(), math.hypot(-0.15 - ox, oy) + 0.03
    )
    assert abs(a.frame[2] - far) < 1e-15 and np.allclose(a.frame[:2], (ox, oy), atol=1e-16)
    for o in fp.outlines():
        assert np.allclose(o[0], o[-1])


@pytest.mark.parametrize(
    "make,word",
    [
        (lambda: Polygon([(0, 0), (1, 1), (1, 0), (0, 1)]), "intersect"),
        (lambda: Polygon([(0, 0), (1, 0), (2, 0)]), "vertices"),  # collinear: no area
        (lambda: Polygon([(0, 0), (1, 0), (1, 0), (0, 1)]), "repeats"),
        (lambda: Polygon([(0, 0), (1, 0)]), "at least 3"),
        (lambda: Polygon([(0, 0), (1, 0), (float("nan"), 1)]), "vertices[2]"),
        (lambda: Polygon([(0, 0), (2, 0), (1, 0), (1, 1)]), "fold back"),
        (lambda: Rectangle(0.0, 1.0), "length"),
        (lambda: Rectangle(1.0, 1.0, centre=(1.0,)), "centre"),
        (lambda: Annulus(0.2, 0.1), "outer_radius"),
        (lambda: Annulus(-0.1, 0.1), "inner_radius"),
        (lambda: Disk(-1.0), "radius"),
        (lambda: Pads([]), "patches"),
        (lambda: Pads([Rectangle(1, 1), Rectangle(1, 1, centre=(0.5, 0.5))]), "overlap"),
        (lambda: Pads([Rectangle(2, 1), Rectangle(2, 1, centre=(1.0, 0.0))]), "overlap"),
        (lambda: Pads([Disk(1.0), Rectangle(1, 1, centre=(1.2, 0.0))]), "overlap"),
        (lambda: Pads([Annulus(0.5, 1.0), Disk(0.6)]), "overlap"),
        (lambda: Pads([Annulus(0.5, 1.0), Annulus(0.8, 1.2, centre=(0.1, 0.0))]), "overlap"),
        (lambda: Pads([Disk(1.0), "square"]), "patches[1]"),
    ],
)
def test_invalid_footprints(make, word):
    with pytest.raises(ValueError, match=None) as e:
        make()
    assert word in str(e.value)


def test_disjoint_pads_accepted():
    Pads([Rectangle(1, 1), Rectangle(1, 1, centre=(1.0, 0.0))])  # touching along an edge
    Pads([Annulus(0.5, 1.0), Disk(0.5)])  # a disk filling the hole exactly
    Pads([Annulus(0.5, 1.0), Rectangle(0.4, 0.4)])  # a pad inside the hole
    Pads([Annulus(0.5, 1.0), Annulus(1.0, 1.5)])  # nested rings
    Pads([Disk(1.0), Disk(1.0, centre=(2.0, 0.0))])  # tangent disks
    Pads([Disk(1.0), Rectangle(1.0, 1.0, centre=(1.5, 0.0))])  # tangent at one point


# ---------------------------------------------------------------------------------------------
# pressure


def test_linear_law_on_a_disk_is_eq10():
    """On a disk the footprint linear law is MODEL §3's: P/(πa²)(1 + 4ξcξ/a² + 4ηcη/a²)."""
    a, xc, yc = 0.2, 0.02, -0.03
    p0, p1, p2 = pressure_coefficients(Disk(a), ss.LinearPressure(xc, yc), load=5.0)
    base = 5.0 / (math.pi * a * a)
    assert abs(p0 - base) < 1e-12 * base
    assert abs(p1 - base * 4 * xc / a**2) < 1e-12 * base / a
    assert abs(p2 - base * 4 * yc / a**2) < 1e-12 * base / a


@pytest.mark.parametrize("fp", list(FOOTPRINTS))
def test_pressure_normalised_with_centroid_at_g(fp):
    """∫p = P and ∫p r = P r_G for the library's coefficients, by the reference's own rule."""
    from footprint_reference import _area_nodes, _signed_fix, regions_of

    fpo = FOOTPRINTS[fp]
    pts, w = _area_nodes(_signed_fix(regions_of(fpo)))
    for kind in ("uniform", "linear"):
        law, ref_law = _law(fpo, kind)
        p0, p1, p2 = pressure_coefficients(fpo, law, load=2.0)
        p = p0 + p1 * pts[:, 0] + p2 * pts[:, 1]
        assert abs(w @ p - 2.0) < 1e-12
        g = np.array(mass_centre(fpo, law))
        assert np.allclose((w * p) @ pts / 2.0, g, atol=1e-13)
        pref, _ = reference_pressure(fpo, ref_law, 2.0)
        assert np.allclose(pref(pts[:, 0], pts[:, 1]), p, rtol=1e-12)


def test_three_pads_statically_determined():
    """Three small pads under the linear law carry the loads of rigid-body statics."""
    centres = np.array([(0.0, 0.0), (0.6, 0.0), (0.2, 0.5)])
    g = (0.25, 0.15)
    statics = np.linalg.solve(np.vstack((np.ones(3), centres.T)), [10.0, 10.0 * g[0], 10.0 * g[1]])
    errs = []
    for r in (1e-2, 1e-3):  # pad radius [m]: the pads' own second moments add O(r²)
        fp = Pads([Disk(r, centre=tuple(c)) for c in centres])
        p0, p1, p2 = pressure_coefficients(fp, ss.LinearPressure(*g), load=10.0)
        pads = [(p0 + p1 * c[0] + p2 * c[1]) * math.pi * r**2 for c in centres]  # exact: linear
        errs.append(np.abs(np.array(pads) / statics - 1.0).max())
    assert errs[1] < 1e-6 and 95.0 < errs[0] / errs[1] < 105.0


def test_negative_linear_pressure_is_an_error():
    with pytest.raises(ValueError, match="xi_c"):
        pressure_coefficients(Rectangle(0.2, 0.1), ss.LinearPressure(0.05, 0.0))
    with pytest.raises(ValueError, match="negative"):
        footprint_wrench(
            Annulus(0.05, 0.1), ss.LinearPressure(0.0, 0.04), TENSORS["isotropic"], 1.0, 0.0, 1.0
        )
    # the limit of the core is accepted: a rectangle's linear law vanishes at an edge when the
    # centroid lies at a sixth of the length
    pressure_coefficients(Rectangle(0.3, 0.1), ss.LinearPressure(0.05, 0.0))


def test_pressure_map_linear_reproduces_kernel():
    """A map given as a function or grid samples of the linear law gives the exact linear
    wrench to 1e-9 (the polar quadrature of the map path against the closed form)."""
    fp = FOOTPRINTS["L-shape"]
    law, _ = _law(fp, "linear")
    p0, p1, p2 = pressure_coefficients(fp, law)
    fmap = PressureMap(lambda x, y: 7.0 * (p0 + p1 * x + p2 * y))
    xs = np.linspace(-0.15, 0.25, 9)
    ys = np.linspace(-0.15, 0.2, 8)
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    gmap = PressureMap.from_grid(xs, ys, p0 + p1 * gx + p2 * gy)
    fr = TENSORS["skew"]
    for icr in _icr_points(fp).values():
        vx, vy = _velocity(fp, law, icr, 0.4)
        exact = footprint_wrench(fp, law, fr, vx, vy, 1.0, 0.4, load=2.0)
        for pm in (fmap, gmap):
            w = footprint_wrench(fp, pm, fr, vx, vy, 1.0, 0.4, load=2.0)
            assert abs(w.force_x - exact.force_x) < 2e-9
            assert abs(w.force_y - exact.force_y) < 2e-9
            assert abs(w.moment - exact.moment) < 2e-9 * 0.3


@pytest.mark.parametrize("fp", ["triangle", "ring", "pads"])
def test_pressure_map_matches_reference(fp):
    """A smooth non-linear map: the map quadrature against the reference to 1e-8."""
    fpo = FOOTPRINTS[fp]

    def bump(x, y):
        return 1.0 + 0.5 * np.exp(-((x - 0.02) ** 2 + (y + 0.01) ** 2) / 0.01) + 0.2 * x

    pm = PressureMap(bump)
    fr = TENSORS["orthotropic"]
    gx, gy = mass_centre(fpo, pm)
    _, gref = reference_pressure(fpo, ("map", bump))
    assert abs(gx - gref[0]) < 1e-12 and abs(gy - gref[1]) < 1e-12
    for icr in [(gx + 0.01, gy - 0.02), (gx + 0.3, gy), (gx + 10.0, gy + 3.0)]:
        vx, vy = -(gy - icr[1]), (gx - icr[0])
        w = footprint_wrench(fpo, pm, fr, vx, vy, 1.0)
        ref = reference_wrench(fpo, ("map", bump), fr.matrix, vx, vy, 1.0)
        assert abs(w.force_x - ref[0]) < 1e-8 and abs(w.force_y - ref[1]) < 1e-8
        assert abs(w.moment - ref[2]) < 1e-8 * 0.2


def test_pressure_map_errors():
    with pytest.raises(ValueError, match="function"):
        PressureMap(3.0)
    with pytest.raises(ValueError, match="p = "):
        footprint_wrench(
            Rectangle(0.2, 0.1), PressureMap(lambda x, y: x), TENSORS["isotropic"], 1.0, 0.0, 1.0
        )
    with pytest.raises(ValueError, match="xi"):
        PressureMap.from_grid([0, 1, 1, 2], [0, 1, 2, 3], np.ones((4, 4)))
    with pytest.raises(ValueError, match="shape"):
        PressureMap.from_grid([0, 1, 2, 3], [0, 1, 2, 3], np.ones((3, 4)))


def test_area_rule_exact_for_polynomials():
    for fp in FOOTPRINTS.values():
        pts, w = area_rule(fp)
        assert abs(w.sum() - fp.area) < 1e-15
        j = fp.second_moment
        c = np.array(fp.centroid)
        d = pts - c
        assert np.allclose(
            [(w * d[:, 0] ** 2).sum(), (w * d[:, 0] * d[:, 1]).sum()],
            [j[0, 0], j[0, 1]],
            rtol=1e-12,
            atol=1e-18,
        )


def test_kernel_geometry_layout():
    fp = FOOTPRINTS["rectangle"]
    geo = kernel_geometry(fp, ss.LinearPressure(0.03, -0.02))
    assert geo.shape == (K.NGEO,)
    assert tuple(geo[K.GEO_XG : K.GEO_YG + 1]) == (0.03, -0.02)
    assert geo[K.GEO_LOAD] == 1.0


def test_kernel_in_scaled_units():
    """The kernel reads any length unit: natural units (lengths in ℓ) give F and M/ℓ."""
    from slidespin.contact.pressure_map import scaled_arrays

    fp = FOOTPRINTS["pads"]
    law, _ = _law(fp, "linear")
    t = TENSORS["skew"].matrix
    a = fp.to_arrays()
    geo = kernel_geometry(fp, law, a)
    ell = 0.37
    a2 = scaled_arrays(a, ell)
    geo2 = kernel_geometry(fp, law, a, length=ell)
    for vx, vy, om in [(0.1, -0.05, 1.0), (0.0, 0.0, 2.0), (1.0, 0.2, 0.0), (30.0, 5.0, 1.0)]:
        f1 = K.wrench_world(a.edges, a.circles, geo, *t.ravel(), False, 0.3, vx, vy, om)
        f2 = K.wrench_world(
            a2.edges, a2.circles, geo2, *t.ravel(), False, 0.3, vx / ell, vy / ell, om
        )
        assert np.allclose(f2, (f1[0], f1[1], f1[2] / ell), rtol=0, atol=1e-14)


def _star(rng, n):
    """A random star-shaped (generally non-convex) simple polygon around the origin."""
    t = (np.arange(n) + rng.uniform(0.0, 0.4, n)) * 2.0 * np.pi / n  # gaps < π: simple
    r = rng.uniform(0.3, 1.0, n) * 0.1
    return Polygon(
        np.column_stack((r * np.cos(t), r * np.sin(t))), centre=tuple(rng.normal(size=2) * 0.02)
    )


def test_random_polygons_against_reference():
    """Random star polygons (mostly non-convex), random tensors and laws, the ICR at random
    points, at vertices (reflex ones included) and on edges."""
    rng = np.random.default_rng(2026)
    for k in range(8):
        fp = _star(rng, int(rng.integers(3, 9)))
        a = fp.to_arrays()
        ext = a.frame[2]
        fr = ss.FrictionTensor(
            *rng.uniform(0.2, 0.8, 2),
            f=rng.normal() * 0.1,
            angle=rng.uniform(0, 3),
            frame=("plane", "body")[k % 2],
        )
        kind = ("uniform", "linear")[k % 2]
        law, ref_law = _law(fp, kind)
        i = int(rng.integers(len(a.edges)))
        x0, y0, x1, y1 = a.edges[i]
        t = rng.uniform()
        icrs = [
            (x0, y0),
            (x0 + t * (x1 - x0), y0 + t * (y1 - y0)),
            tuple(a.frame[:2] + rng.normal(size=2) * ext),
            tuple(a.frame[:2] + rng.normal(size=2) * 8 * ext),
        ]
        for icr in icrs:
            phi = rng.uniform(0, 6)
            om = rng.choice([-1.0, 1.0]) * rng.uniform(0.5, 3.0)
            vx, vy = _velocity(fp, law, icr, phi, om)
            w = footprint_wrench(fp, law, fr, vx, vy, om, phi)
            ref = reference_wrench(fp, ref_law, fr.matrix, vx, vy, om, phi=phi, frame=fr.frame)
            got = np.array([w.force_x, w.force_y, w.moment / ext])
            want = np.array([ref[0], ref[1], ref[2] / ext])
            assert np.abs(got - want).max() <= TOL, (k, icr, got, want)


def test_reflex_vertex_icr():
    fp = FOOTPRINTS["L-shape"]
    reflex = (0.1 - 0.1, 0.1 - 0.1)  # vertex (0.1, 0.1) of L_SHAPE, placed at centre (−0.1, −0.1)
    for kind in ("uniform", "linear"):
        law, ref_law = _law(fp, kind)
        fr = TENSORS["skew"]
        vx, vy = _velocity(fp, law, reflex, 0.2, 1.3)
        w = footprint_wrench(fp, law, fr, vx, vy, 1.3, 0.2)
        ref = reference_wrench(fp, ref_law, fr.matrix, vx, vy, 1.3, phi=0.2)
        assert abs(w.force_x - ref[0]) <= TOL and abs(w.force_y - ref[1]) <= TOL
        assert abs(w.moment - ref[2]) <= TOL * 0.3


def test_kernel_runs_as_python():
    """The kernel as plain Python (NUMBA_DISABLE_JIT=1) gives the compiled results."""
    import os
    import subprocess
    import sys

    code = (
        "import numpy as np\n"
        "from slidespin.contact import _kernel_footprint as K\n"
        "from slidespin.contact.shapes import Annulus, Pads, Polygon, Rectangle\n"
        "from slidespin.contact.pressure_map import kernel_geometry\n"
        "from slidespin.contact.pressure import LinearPressure\n"
        "fp = Pads([Polygon([(0, 0), (0.3, 0), (0.3, 0.1), (0.1, 0.1), (0.1, 0.25), (0, 0.25)]),"
        " Annulus(0.03, 0.06, centre=(0.4, 0.1)), Rectangle(0.1, 0.05, centre=(-0.2, 0))])\n"
        "a = fp.to_arrays()\n"
        "g = kernel_geometry(fp, LinearPressure(0.1, 0.08), a)\n"
        "out = [K.wrench_world(a.edges, a.circles, g, 0.3, 0.1, -0.1, 0.5, False, 0.4, vx, vy, om)"
        " for vx, vy, om in [(0.1, 0.0, 1.0), (0.0, 0.0, -1.0), (0.3, -0.1, 1.0),"
        " (1.0, 0.1, 0.0), (0.02, -0.1, 1.0), (40.0, 2.0, 1.0)]]\n"
        "print(repr(np.array(out).tolist()))\n"
    )
    res = {}
    for jit in ("0", "1"):
        env = dict(os.environ, NUMBA_DISABLE_JIT=jit)
        out = subprocess.run(
            [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
        )
        res[jit] = np.array(eval(out.stdout))  # our own output
    assert np.allclose(res["0"], res["1"], rtol=0, atol=1e-15)


@pytest.mark.parametrize("delta", [1e-4, 1e-7, -1e-7, 1e-10, 0.0])
def test_pressure_map_icr_near_an_edge(delta):
    """The map quadrature with the ICR a distance ``delta`` inside (> 0) or outside an edge:
    the area beyond the edge crowds into narrow angles, which the graded breaks resolve."""
    fp = Rectangle(0.2, 0.1)
    law = ss.LinearPressure(0.01, 0.005)
    p0, p1, p2 = pressure_coefficients(fp, law)
    pm = PressureMap(lambda x, y: p0 + p1 * x + p2 * y)
    fr = TENSORS["skew"]
    vx, vy = _velocity(fp, law, (0.1 - delta, 0.02), 0.0)
    w = footprint_wrench(fp, pm, fr, vx, vy, 1.0)
    e = footprint_wrench(fp, law, fr, vx, vy, 1.0)
    assert abs(w.force_x - e.force_x) < 1e-9 and abs(w.force_y - e.force_y) < 1e-9
    assert abs(w.moment - e.moment) < 1e-9 * 0.11


def test_value_objects_pickle():
    """Footprints and grid maps cross process boundaries (sweeps, Dask) intact."""
    import pickle

    for fp in FOOTPRINTS.values():
        assert pickle.loads(pickle.dumps(fp)) == fp
    xs = np.linspace(-0.2, 0.2, 6)
    gmap = PressureMap.from_grid(xs, xs, 1.0 + np.add.outer(xs, xs) ** 2)
    back = pickle.loads(pickle.dumps(gmap))
    pts = np.array([[0.013, -0.07], [0.1, 0.1]])
    assert np.array_equal(back(pts[:, 0], pts[:, 1]), gmap(pts[:, 0], pts[:, 1]))


def test_collinear_vertices_change_nothing():
    """Extra vertices along a side (collinear edges) leave the footprint and wrench as they are."""
    plain = Rectangle(0.2, 0.1, angle=0.3).as_polygon()
    p = plain.points
    extra = Polygon([p[0], 0.5 * (p[0] + p[1]), p[1], p[2], 0.3 * p[2] + 0.7 * p[3], p[3]])
    assert abs(extra.area - plain.area) < 1e-16
    fr = TENSORS["skew"]
    law = ss.LinearPressure(0.01, 0.004)
    for icr in [(0.0, 0.0), tuple(0.5 * (p[0] + p[1])), (0.3, 0.1)]:
        vx, vy = _velocity(plain, law, icr, 0.0)
        a = footprint_wrench(plain, law, fr, vx, vy, 1.0)
        b = footprint_wrench(extra, law, fr, vx, vy, 1.0)
        assert abs(a.force_x - b.force_x) < 1e-15 and abs(a.moment - b.moment) < 1e-15


def _inertia_for_ratio(fp, beta, radius):
    """J(β) = β M_paper/F_τ in units of radius (MODEL §6): the I* = I/(m R²) whose terminal
    ratio v/(Rω) is β, for an axisymmetric footprint under isotropic friction (ϑ = 0)."""
    w = footprint_wrench(
        fp, ss.UniformPressure(), ss.FrictionTensor.isotropic(0.3), beta * radius, 0.0, 1.0
    )
    return beta * w.moment_paper / (w.tangential * radius)


def test_published_terminal_ratios():
    """The uniform disk with I* = 1/2 stops with v/(aω) = 0.653 (Voyenli & Eriksen 1985;
    Weidman & Malhotra 2007); a thin uniform ring with I* = 1 stops with v/(Rω) = 1 (MODEL §8)."""
    from scipy.optimize import brentq

    beta = brentq(lambda b: _inertia_for_ratio(Disk(0.2), b, 0.2) - 0.5, 0.3, 1.0, xtol=1e-12)
    assert abs(beta - 0.653) < 5e-4
    gaps = [
        1.0 - _inertia_for_ratio(Annulus(1.0 - eps, 1.0), 1.0, 1.0) for eps in (1e-2, 1e-3, 1e-4)
    ]
    assert 0.0 < gaps[2] < 1e-3 and gaps[0] > gaps[1] > gaps[2]


def test_arrays_are_copies():
    fp = Rectangle(0.2, 0.1)
    a = fp.to_arrays()
    a.edges[:] = 0.0
    assert np.abs(fp.to_arrays().edges).max() == 0.1


@pytest.mark.parametrize("scale", [1e-3, 1e3])
def test_scale_invariance(scale):
    """Lengths × λ and velocities × λ: the same force, the moment × λ (mm to km footprints)."""
    fr = TENSORS["skew"]
    base = Pads([Polygon(L_SHAPE), Annulus(0.02, 0.05, centre=(0.4, 0.1))])
    big = Pads(
        [
            Polygon([(scale * x, scale * y) for x, y in L_SHAPE]),
            Annulus(0.02 * scale, 0.05 * scale, centre=(0.4 * scale, 0.1 * scale)),
        ]
    )
    for kind in ("uniform", "linear"):
        law, _ = _law(base, kind)
        law_big = (
            law if kind == "uniform" else ss.LinearPressure(law.xi_c * scale, law.eta_c * scale)
        )
        for vx, vy, om in [(0.1, 0.05, 1.0), (0.0, 0.0, 1.0), (3.0, -1.0, 1.0), (1.0, 0.0, 0.0)]:
            a = footprint_wrench(base, law, fr, vx, vy, om)
            b = footprint_wrench(big, law_big, fr, vx * scale, vy * scale, om)
            assert abs(a.force_x - b.force_x) < 1e-13 and abs(a.force_y - b.force_y) < 1e-13
            assert abs(a.moment - b.moment / scale) < 1e-13


def test_triangulations_cover_the_polygons():
    """Ear clipping (used by the overlap test and the map rule) covers each polygon exactly,
    a comb whose notch touches a diagonal and a 256-gon included."""
    comb = Polygon([(0, 0), (4, 0), (4, 1), (3, 1), (2, 0.5), (1, 1), (0, 1)])
    for fp in [comb, _ngon(256, 1.0), Polygon(L_SHAPE), Polygon(ARROW[::-1])]:
        t = fp.triangles()
        cr = (t[:, 1, 0] - t[:, 0, 0]) * (t[:, 2, 1] - t[:, 0, 1]) - (t[:, 1, 1] - t[:, 0, 1]) * (
            t[:, 2, 0] - t[:, 0, 0]
        )
        assert np.all(cr > 0) and abs(0.5 * cr.sum() - fp.area) < 1e-14 * max(fp.area, 1.0)


def test_extent():
    assert Annulus(0.3, 0.5, centre=(1.0, 1.0)).extent == 0.5
    assert abs(Rectangle(0.6, 0.8, angle=1.0).extent - 0.5) < 1e-15
    assert abs(Polygon([(0, 0), (3, 0), (0, 3)]).extent - math.hypot(2, 1)) < 1e-15
