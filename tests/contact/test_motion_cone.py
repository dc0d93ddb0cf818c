"""Motion cones (MODEL §13) against independent truth: a slow adaptive quadrature of the friction
wrench written here from MODEL §2 (polar about the instantaneous centre, scipy's ``quad``; no
slidespin kernel), a root finder run here for the edge twists of a uniform disk, the
anti-parallel property W(û±) ∥ −w± for boxes, an L-shaped part and an anisotropic tensor,
symmetry (mirror edges; μ = 0 gives one edge) and pure translation for a push through G."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import root

import slidespin as ss
from slidespin.contact.motion_cone import motion_cone

# ------------------------------------------------------------------------------------------
# the reference: uniform pressure on convex pieces (disks and polygons), unit load P = 1


def _ray(piece, q, e):
    """[ρ1, ρ2] of the ray q + ρ e (ρ ≥ 0) inside a convex piece, or None."""
    if piece[0] == "disk":
        _, o, r = piece
        d = q - o
        b, c = d @ e, d @ d - r * r
        disc = b * b - c
        if disc <= 0.0:
            return None
        s = math.sqrt(disc)
        lo, hi = -b - s, -b + s
    else:
        pts = piece[1]
        lo, hi = -math.inf, math.inf
        for k in range(len(pts)):
            a, b = pts[k], pts[(k + 1) % len(pts)]
            nrm = np.array([b[1] - a[1], a[0] - b[0]])  # outward for counter-clockwise
            num, den = nrm @ (q - a), nrm @ e
            if den == 0.0:
                if num > 0.0:
                    return None
                continue
            s = -num / den
            if den > 0.0:
                hi = min(hi, s)
            else:
                lo = max(lo, s)
        if lo >= hi:
            return None
    lo = max(lo, 0.0)
    return (lo, hi) if hi > lo else None


def _breaks(piece, q):
    if piece[0] == "disk":
        _, o, r = piece
        d = o - q
        dist = math.hypot(*d)
        if dist <= r:
            return []
        a = math.atan2(d[1], d[0])
        h = math.asin(r / dist)
        return [a - h, a + h]
    return [math.atan2(p[1] - q[1], p[0] - q[0]) for p in piece[1]]


def _area(piece):
    if piece[0] == "disk":
        return math.pi * piece[2] ** 2
    p = piece[1]
    return 0.5 * sum(p[k][0] * p[k - 1][1] * -1 + p[k - 1][0] * p[k][1] for k in range(len(p)))


def ref_wrench(pieces, g, tensor, u, ell):
    """(Fx, Fy, M/ℓ) for the unit twist u = (vx, vy, ω ℓ), unit load, uniform pressure."""
    area = sum(_area(pc) for pc in pieces)
    p = 1.0 / area
    vx, vy, wl = u
    i1, i2 = np.zeros(2), np.zeros((2, 2))
    if wl == 0.0:
        vh = np.array([vx, vy]) / math.hypot(vx, vy)
        i1 = vh.copy()
        for pc in pieces:
            cen = pc[1] if pc[0] == "disk" else np.mean(pc[1], axis=0)  # (rectangles: centroid)
            i2 += p * _area(pc) * np.outer(cen - g, vh)
    else:
        om = wl / ell
        q = g + np.array([-vy / om, vx / om])
        sg = math.copysign(1.0, om)
        qg = q - g
        for pc in pieces:
            br = sorted(set(_breaks(pc, q)))
            a0 = br[0] if br else 0.0
            cuts = sorted({a0 + ((b - a0) % (2 * math.pi)) for b in br} | {a0, a0 + 2 * math.pi})

            def f(th, i, j, pc=pc):
                e = np.array([math.cos(th), math.sin(th)])
                seg = _ray(pc, q, e)
                if seg is None:
                    return 0.0
                r1, r2 = seg
                m1 = 0.5 * (r2 - r1) * (r2 + r1)
                m2 = (r2**3 - r1**3) / 3.0
                wh = sg * np.array([-e[1], e[0]])
                if i < 0:
                    return p * wh[j] * m1
                return p * wh[j] * (qg[i] * m1 + e[i] * m2)

            for a, b in zip(cuts[:-1], cuts[1:]):
                if b - a < 1e-15:
                    continue
                for j in range(2):
                    kw = dict(epsabs=1e-14, epsrel=1e-12, limit=200)
                    i1[j] += quad(f, a, b, args=(-1, j), **kw)[0]
                    for i in range(2):
                        i2[i, j] += quad(f, a, b, args=(i, j), **kw)[0]
    force = -tensor @ i1
    moment = -sum(tensor[1, k] * i2[0, k] - tensor[0, k] * i2[1, k] for k in range(2))
    return np.array([force[0], force[1], moment / ell])


def _unit(x):
    x = np.asarray(x, dtype=float)
    return x / np.linalg.norm(x)


def _angle(a, b):
    return math.atan2(np.linalg.norm(np.cross(a, b)), float(np.dot(a, b)))


def _rect(cx, cy, lx, ly):
    return (
        "poly",
        np.array(
            [
                (cx - lx / 2, cy - ly / 2),
                (cx + lx / 2, cy - ly / 2),
                (cx + lx / 2, cy + ly / 2),
                (cx - lx / 2, cy + ly / 2),
            ]
        ),
    )


ISO = ss.FrictionTensor(0.3, 0.3)


def test_reference_reproduces_closed_forms():
    """The reference itself: a spinning disk M = −(2/3) f P R, a translating one F = −f P v̂."""
    r = 0.1
    w = ref_wrench([("disk", np.zeros(2), r)], np.zeros(2), 0.3 * np.eye(2), (0, 0, 1.0), r)
    np.testing.assert_allclose(w, [0.0, 0.0, -0.2], atol=1e-13)
    w = ref_wrench([("disk", np.zeros(2), r)], np.zeros(2), 0.3 * np.eye(2), (0.6, 0.8, 0.0), r)
    np.testing.assert_allclose(w, [-0.18, -0.24, 0.0], atol=1e-15)


# ------------------------------------------------------------------------------------------


@pytest.mark.parametrize(("angle", "mu"), [(0.0, 0.3), (2.0, 0.8)])
def test_disk_edges_by_root_finding_in_the_test(angle, mu):
    """A uniform disk, isotropic friction: each edge twist found here by root finding on the
    reference wrench, from a start independent of slidespin (a translation along f)."""
    radius = 0.1
    body = ss.Body(ss.Circle(radius), ss.UniformPressure(), 1.0)
    c = radius * np.array([math.cos(angle), math.sin(angle)])
    n = -c / radius
    cone = motion_cone(body, ISO, c, n, mu)
    t = np.array([-n[1], n[0]])
    disk = [("disk", np.zeros(2), radius)]
    for k, f in enumerate((n + mu * t, n - mu * t)):
        w = np.array([f[0], f[1], (c[0] * f[1] - c[1] * f[0]) / radius])
        target = -_unit(w)
        e1 = _unit(np.cross(target, [0.3, 0.5, 0.7]))
        e2 = np.cross(target, e1)

        def eqs(x, e1=e1, e2=e2, target=target):
            u = _unit([*f, 0.0] + x[0] * np.array([0, 0, 1.0]) + x[1] * np.array([1.0, 0, 0]))
            wh = _unit(ref_wrench(disk, np.zeros(2), 0.3 * np.eye(2), u, radius))
            return [wh @ e1, wh @ e2]

        sol = root(eqs, [0.1, 0.0], method="hybr", options={"xtol": 1e-14})
        u_ref = _unit(
            [*f, 0.0] + sol.x[0] * np.array([0, 0, 1.0]) + sol.x[1] * np.array([1.0, 0, 0])
        )
        assert max(abs(x) for x in eqs(sol.x)) < 1e-12
        assert _angle(cone.edges[k], u_ref) < 1e-9
        np.testing.assert_allclose(cone.wrenches[k], [*f, w[2] * radius], atol=1e-15)


def test_mirror_symmetry_and_mu_zero():
    box = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), 1.0)
    cone = motion_cone(box, ISO, (0.1, 0.0), (-1.0, 0.0), 0.3)
    a, b = cone.edges
    np.testing.assert_allclose(b, a * [1.0, -1.0, -1.0], atol=1e-12)
    assert a[1] != 0.0 and a[2] != 0.0  # a genuine cone
    one = motion_cone(box, ISO, (0.1, 0.03), (-1.0, 0.0), 0.0)
    np.testing.assert_array_equal(one.edges[0], one.edges[1])
    assert one.half_angle == 0.0
    # mirror the contact across the ξ axis: the mirrored cone, edges swapped
    up = motion_cone(box, ISO, (0.1, 0.03), (-1.0, 0.0), 0.4)
    down = motion_cone(box, ISO, (0.1, -0.03), (-1.0, 0.0), 0.4)
    np.testing.assert_allclose(down.edges[::-1], up.edges * [1.0, -1.0, -1.0], atol=1e-12)
    assert up.contains(up.edges[0] + 2 * up.edges[1]) and not up.contains(-up.edges[0])


@pytest.mark.parametrize(
    ("patch", "contact", "normal"),
    [
        (ss.Rectangle(0.2, 0.1), (-0.1, 0.0), (1.0, 0.0)),
        (ss.Rectangle(0.2, 0.1), (0.0, 0.05), (0.0, -1.0)),
        (ss.Ellipse(0.2, 0.1), (0.0, -0.1), (0.0, 1.0)),
        (ss.Disk(0.1), (0.0, 0.1), (0.0, -1.0)),
    ],
)
def test_push_through_g_translates(patch, contact, normal):
    body = ss.Body(patch, ss.UniformPressure(), 1.0)
    cone = motion_cone(body, ISO, contact, normal, 0.0)
    np.testing.assert_allclose(cone.edges[0], [*normal, 0.0], atol=1e-12)


def test_l_shape_diagonal_push_translates_and_edges_balance():
    verts = [(0, 0), (0.2, 0), (0.2, 0.05), (0.05, 0.05), (0.05, 0.2), (0, 0.2)]
    body = ss.Body(ss.Polygon(verts), ss.UniformPressure(), 1.0)
    g = np.array(body.mass_centre)
    # through G along the symmetry axis ξ = η, from the corner (0, 0)
    cone = motion_cone(body, ISO, (0.0, 0.0), (math.sqrt(0.5), math.sqrt(0.5)), 0.0)
    np.testing.assert_allclose(cone.edges[0], [math.sqrt(0.5), math.sqrt(0.5), 0.0], atol=1e-12)
    # an off-centre push on the long face: W(û) of the reference opposes w
    cone = motion_cone(body, ISO, (0.17, 0.0), (0.0, 1.0), 0.5)
    pieces = [_rect(0.1, 0.025, 0.2, 0.05), _rect(0.025, 0.125, 0.05, 0.15)]
    ell = body.length_unit
    for u, w in zip(cone.edges, cone.wrenches):
        wr = ref_wrench(pieces, g, 0.3 * np.eye(2), u, ell)
        assert _angle(wr, -np.array([w[0], w[1], w[2] / ell])) < 1e-10


def test_anisotropic_box_edges_balance():
    tensor = ss.FrictionTensor(0.2, 0.5, 0.05)
    box = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), 1.0)
    cone = motion_cone(box, tensor, (0.1, 0.02), (-1.0, 0.0), 0.4)
    ell = box.length_unit
    assert np.all(cone.residuals < 1e-12)
    for u, w in zip(cone.edges, cone.wrenches):
        wr = ref_wrench([_rect(0, 0, 0.2, 0.1)], np.zeros(2), tensor.matrix, u, ell)
        assert _angle(wr, -np.array([w[0], w[1], w[2] / ell])) < 1e-10
        assert np.linalg.norm(u) == pytest.approx(1.0, abs=1e-15)


def test_compare_fits_reports_angles():
    disk = ss.Body(ss.Circle(0.1), ss.UniformPressure(), 1.0)
    cone = motion_cone(disk, ISO, (0.1, 0.0), (-1.0, 0.0), 0.5)
    fits = cone.compare_fits(n=200)
    for edges, ang in (
        (fits.ellipsoid_edges, fits.ellipsoid_angle),
        (fits.quartic_edges, fits.quartic_angle),
    ):
        np.testing.assert_allclose(np.linalg.norm(edges, axis=1), 1.0, atol=1e-15)
        for k in range(2):
            assert ang[k] == pytest.approx(_angle(edges[k], cone.edges[k]), abs=1e-15)
        assert np.all(ang < 0.2)  # a fit, not wrong
    # the fits misplace the edges by a measurable angle (the number the field lacks)
    assert np.all(fits.ellipsoid_angle > 1e-6) and np.all(fits.quartic_angle > 1e-6)


@pytest.mark.parametrize(
    ("kwargs", "needle"),
    [
        (dict(contact=(0.1, True)), "contact[1]"),
        (dict(contact="ab"), "contact"),
        (dict(contact=(0.1, math.nan)), "contact[1]"),
        (dict(normal=(0.0, 0.0)), "normal"),
        (dict(normal=(1.0, 0.0)), "inward"),
        (dict(normal=(1.0, 0.0, 0.0)), "normal"),
        (dict(mu=-0.1), "mu"),
        (dict(mu=math.inf), "mu"),
        (dict(mu=True), "mu"),
        (dict(body="box"), "body"),
        (dict(friction=0.3), "friction"),
    ],
)
def test_refusals(kwargs, needle):
    args = dict(
        body=ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), 1.0),
        friction=ISO,
        contact=(0.1, 0.0),
        normal=(-1.0, 0.0),
        mu=0.3,
    )
    args.update(kwargs)
    with pytest.raises(ValueError) as err:
        motion_cone(**args)
    assert needle in str(err.value) and "\n" not in str(err.value)


# ------------------------------------------------------------------------------------------
# stable pushing with a line pusher in face contact


def test_stable_pushing_translations_closed_form():
    """A centred square pushed on its whole face translating at θ from the normal: the
    friction wrench is −f P (cos θ, sin θ, 0) (closed form, MODEL §8), balanced by the face
    iff |tan θ| ≤ μp."""
    from slidespin.contact.motion_cone import stable_pushing

    box = ss.Body(ss.Rectangle(0.1, 0.1), ss.UniformPressure(), 1.0)
    mu = 0.4
    sp = stable_pushing(box, ISO, ((-0.05, -0.05), (-0.05, 0.05)), mu)
    np.testing.assert_allclose(sp.normal, [1.0, 0.0], atol=1e-15)
    assert sp.contains((1.0, 0.0, 0.0))  # straight on, the line-pusher test of the issue
    edge = math.atan(mu)
    for th, inside in ((edge - 1e-3, True), (edge + 1e-3, False), (-edge + 1e-3, True)):
        assert sp.contains((math.cos(th), math.sin(th), 0.0)) is inside
    assert not sp.contains((0.0, 1.0, 0.0))  # sideways: needs a pure tangential force
    assert not sp.contains((0.0, 0.0, 1.0))  # spinning about G: needs zero net normal force
    # the corners: their friction wrenches oppose the generators (the reference quadrature)
    ell = box.length_unit
    for u, w in zip(sp.corners, sp.generators):
        wr = ref_wrench([_rect(0, 0, 0.1, 0.1)], np.zeros(2), 0.3 * np.eye(2), u, ell)
        assert _angle(wr, -np.array([w[0], w[1], w[2] / ell])) < 1e-10
    # mirror symmetry of the set about the ξ axis
    assert sp.contains((1.0, 0.1, 0.2)) == sp.contains((1.0, -0.1, -0.2))
    fits = sp.compare_fits(n=200)
    assert fits.ellipsoid_angle.shape == (4,) and np.all(fits.quartic_angle < 0.3)


def test_stable_pushing_refusals():
    from slidespin.contact.motion_cone import stable_pushing

    box = ss.Body(ss.Rectangle(0.1, 0.1), ss.UniformPressure(), 1.0)
    for face, needle in (
        (((0, 0), (0, 0)), "coincide"),
        (((-0.05, 0.05), (0.05, -0.05)), "G"),
        ("ab", "face"),
        (((0, 0),), "face"),
        (((0, math.nan), (0, 1)), "face[0][1]"),
    ):
        with pytest.raises(ValueError) as err:
            stable_pushing(box, ISO, face, 0.3)
        assert needle in str(err.value) and "\n" not in str(err.value)
    with pytest.raises(ValueError, match="mu"):
        stable_pushing(box, ISO, ((-0.05, -0.05), (-0.05, 0.05)), -1.0)
