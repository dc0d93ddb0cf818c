"""Tall bodies at rest and in slip (MODEL §14) against closed forms and independent sums.

The truths: a uniform box pushed horizontally at height h_Q through G's vertical plane
slides first iff μ < w/(2 h_Q), else tips at Q = P w/(2 h_Q); a tall body sliding in pure
translation presses ahead of G by h 𝔽 v̂ (the force of a translation does not depend on
the pressure); a box whose pressure centroid lies beyond w/6 lifts off its back part and
carries a triangular pressure over 3 (w/2 − e); the shifted wrench of a spinning body
against the public wrench of the linear law with that centroid (a different code path) and
against a plain 2-D quadrature of the triangular law.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

import slidespin as ss
from slidespin.contact.footprint_arrays import _moments
from slidespin.contact.shapes import Polygon, Rectangle
from slidespin.contact.tall import LiftOffUnsupported, TallContact

G = 10.0


def _box(w=0.4, d=0.3, h=0.5, m=2.0, **kw):
    return ss.Body(Rectangle(w, d, **kw), ss.UniformPressure(), mass=m, height=h)


@pytest.mark.parametrize(
    ("w", "h_q", "mu"),
    [
        (0.4, 0.5, 0.5),
        (0.4, 0.3, 0.5),
        (0.4, 0.39, 0.5),
        (0.4, 0.41, 0.5),
        (0.2, 1.0, 0.05),
        (0.6, 0.1, 0.9),
        (0.3, 0.25, 0.6),
    ],
)
def test_push_at_height_slides_or_tips_as_the_closed_form(w, h_q, mu):
    box = _box(w=w, d=0.3, h=0.4)
    fr = ss.FrictionTensor(mu, mu)
    q = 3.0
    got = ss.breakaway(box, fr, ss.Load(force=(q, 0.0), height=h_q), g=G)
    p = box.mass * G
    tip = p * w / (2.0 * h_q) / q
    slide = mu * p / q
    assert got.tip_factor == pytest.approx(tip, rel=1e-12)
    assert got.slide_factor == pytest.approx(slide, rel=1e-10)
    assert got.mode == ("slide" if mu < w / (2.0 * h_q) else "tip")
    assert got.load_factor == pytest.approx(min(tip, slide), rel=1e-10)
    assert ss.load_factor(box, fr, ss.Load(force=(q, 0.0), height=h_q), g=G) == pytest.approx(
        min(tip, slide), rel=1e-10
    )


def test_tipping_threshold_turns_with_the_body_and_the_push_direction():
    w, d, h_q = 0.4, 0.3, 0.35
    box = _box(w=w, d=d, h=0.2)
    fr = ss.FrictionTensor(0.9, 0.9)
    p = box.mass * G
    phi = 0.7
    # pushed along the body's η axis (world direction of the body's +η): the half-width is d/2
    ex, ey = -math.sin(phi), math.cos(phi)
    got = ss.breakaway(box, fr, ss.Load(force=(ex, ey), height=h_q), phi=phi, g=G)
    assert got.tip_factor == pytest.approx(p * d / (2.0 * h_q), rel=1e-12)
    assert got.mode == "tip"
    # the same in the body frame
    got_b = ss.breakaway(box, fr, ss.Load(force=(0.0, 1.0), frame="body", height=h_q), phi=phi, g=G)
    assert got_b.tip_factor == pytest.approx(p * d / (2.0 * h_q), rel=1e-12)


def test_a_push_at_gs_height_or_a_triple_tilts_by_the_friction_only():
    box = _box(w=0.4, d=0.3, h=0.5)
    fr = ss.FrictionTensor(0.5, 0.5)
    p = box.mass * G
    # at G's height: the friction at the plane tilts it by h Q / P
    for load in (ss.Load(force=(1.0, 0.0)), (1.0, 0.0, 0.0), ss.Load(force=(1.0, 0.0), height=0.5)):
        assert ss.breakaway(box, fr, load, g=G).tip_factor == pytest.approx(
            p * 0.2 / 0.5, rel=1e-12
        )
    # pushed at the plane (h_Q = 0): nothing tips it
    got = ss.breakaway(box, fr, ss.Load(force=(1.0, 0.0), height=0.0), g=G)
    assert math.isinf(got.tip_factor) and got.mode == "slide"


def test_critical_tilt_of_a_tall_box_is_the_tipping_angle_when_it_comes_first():
    box = _box(w=0.4, d=0.3, h=0.5)
    assert math.tan(ss.critical_tilt(box, ss.FrictionTensor(0.5, 0.5))) == pytest.approx(
        0.2 / 0.5, rel=1e-12
    )
    low = _box(w=0.4, d=0.3, h=0.1)
    assert math.tan(ss.critical_tilt(low, ss.FrictionTensor(0.5, 0.5))) == pytest.approx(
        0.5, rel=1e-10
    )


def test_thin_bodies_are_unchanged():
    box = ss.Body(Rectangle(0.4, 0.3), ss.UniformPressure(), mass=2.0)
    fr = ss.FrictionTensor(0.5, 0.3, 0.1)
    load = ss.Load(force=(3.0, 1.0), torque=0.2, height=0.3)
    got = ss.breakaway(box, fr, load, g=G)
    assert got.mode == "slide" and math.isinf(got.tip_factor)
    assert got.load_factor == ss.load_factor(box, fr, (3.0, 1.0, 0.2), g=G)


def test_onset_of_a_tall_body_tips_or_slides():
    box = _box(w=0.4, d=0.3, h=0.5)
    fr = ss.FrictionTensor(0.5, 0.5)
    on = ss.onset(box, fr, ss.Load(force=(9.0, 0.0), height=0.5), g=G)
    assert on.mode == "tip"
    on = ss.onset(box, fr, ss.Load(force=(11.0, 0.0), height=0.3), g=G)
    assert on.mode == "slide"
    assert on.direction == pytest.approx([1.0, 0.0, 0.0], abs=1e-9)
    assert on.acceleration == pytest.approx((11.0 - 10.0) / 2.0, rel=1e-9)
    assert ss.onset(box, fr, ss.Load(force=(7.0, 0.0), height=0.5), g=G) is None


@pytest.mark.parametrize(
    "patch",
    [ss.Disk(0.1), ss.Ellipse(0.1, 0.06), Rectangle(0.3, 0.2), ss.Annulus(0.05, 0.1)],
    ids=["disk", "ellipse", "box", "ring"],
)
@pytest.mark.parametrize("frame", ["plane", "body"])
def test_a_translating_tall_body_presses_ahead_by_h_times_the_friction(patch, frame):
    h = 0.04
    body = ss.Body(patch, ss.UniformPressure(), mass=1.5, height=h)
    fr = ss.FrictionTensor(0.3, 0.2, 0.05, frame=frame, angle=0.3)
    phi, vx, vy = 0.4, 0.6, -0.8
    got = ss.pressure_centre(body, fr, ss.State(phi=phi, vx=vx, vy=vy))
    # F = −P 𝔽(φ) v̂ whatever the pressure; r_p = r_G − h F_body / P
    fw = fr.world_matrix(phi)
    f_world = -fw @ np.array([vx, vy]) / math.hypot(vx, vy)
    c, s = math.cos(phi), math.sin(phi)
    f_body = np.array([c * f_world[0] + s * f_world[1], -s * f_world[0] + c * f_world[1]])
    gx, gy = body.mass_centre
    assert got == pytest.approx((gx - h * f_body[0], gy - h * f_body[1]), abs=1e-14)


@pytest.mark.parametrize(
    ("patch", "pressure"),
    [
        (ss.Disk(0.1), ss.UniformPressure()),
        (ss.Ellipse(0.1, 0.06), ss.LinearPressure(0.01, -0.005)),
        (Rectangle(0.3, 0.2), ss.LinearPressure(0.02, 0.01)),
        (
            Polygon([(0, 0), (0.3, 0), (0.3, 0.1), (0.1, 0.1), (0.1, 0.25), (0, 0.25)]),
            ss.UniformPressure(),
        ),
    ],
    ids=["disk", "ellipse-linear", "box-linear", "L"],
)
def test_the_spinning_tall_body_satisfies_the_moment_balance(patch, pressure):
    """r_p = r_G − h F(r_p)/P with F from the public wrench of the linear law centred at r_p
    (friction_wrench of another Body: not the tall module's arithmetic)."""
    h = 0.02 if isinstance(patch, ss.Ellipse) else 0.05  # (no lift-off on an ellipse)
    body = ss.Body(patch, pressure, mass=1.0, moment_of_inertia=0.004, height=h)
    fr = ss.FrictionTensor(0.4, 0.25, 0.08)
    state = ss.State(phi=0.3, vx=0.5, vy=0.2, omega=4.0)
    rp = ss.pressure_centre(body, fr, state, g=G)
    shifted = ss.Body(patch, ss.LinearPressure(*rp), mass=1.0, moment_of_inertia=0.004)
    gx, gy = body.mass_centre
    c, s = math.cos(state.phi), math.sin(state.phi)
    dx, dy = c * (rp[0] - gx) - s * (rp[1] - gy), s * (rp[0] - gx) + c * (rp[1] - gy)
    # the twist of the shifted body's G (= r_p): v_p = v_G + ω ẑ × d
    wr = ss.friction_wrench(
        shifted,
        fr,
        state.vx - state.omega * dy,
        state.vy + state.omega * dx,
        state.omega,
        phi=state.phi,
        g=G,
        tol=1e-13,
    )
    fx, fy = wr.force_x / G, wr.force_y / G  # per unit load (m = 1)
    fb = (c * fx + s * fy, -s * fx + c * fy)
    assert rp == pytest.approx((gx - h * fb[0], gy - h * fb[1]), abs=1e-12)


def _triangle_wrench(w, d, e, mu, v, om):
    """Force and moment about the box centre of p = 2/(L² d) (x − x₀)⁺ on x ∈ [x₀, w/2]
    (L = 3 (w/2 − e), x₀ = w/2 − L; unit load) sliding with twist (v, ω) of the centre."""
    big = 3.0 * (w / 2.0 - e)
    x0 = w / 2.0 - big

    def tr(x, y, comp):
        p = 2.0 / (big * big * d) * (x - x0)
        wx, wy = v[0] - om * y, v[1] + om * x
        n = math.hypot(wx, wy)
        tx, ty = -mu * p * wx / n, -mu * p * wy / n
        return (tx, ty, x * ty - y * tx)[comp]

    opts = {"epsabs": 1e-13, "epsrel": 1e-12}
    return [
        integrate.dblquad(lambda y, x, k=k: tr(x, y, k), x0, w / 2.0, -d / 2.0, d / 2.0, **opts)[0]
        for k in range(3)
    ]


@pytest.mark.parametrize("e", [0.08, 0.15, 0.19])
def test_lift_off_gives_the_triangular_pressure_of_a_box(e):
    w, d, mu = 0.4, 0.3, 0.35
    box = ss.Body(Rectangle(w, d), ss.UniformPressure(), mass=1.0, height=0.3)
    fr = ss.FrictionTensor(mu, mu)
    tall = TallContact(box, fr)
    ell = box.length_unit
    pressed = tall.at((e / ell, 0.0))
    v, om = (0.3, -0.2), 1.7
    got = pressed(0.0, v[0] / ell, v[1] / ell, om)
    want = _triangle_wrench(w, d, e, mu, v, om)
    assert got[0] == pytest.approx(want[0], abs=1e-9)
    assert got[1] == pytest.approx(want[1], abs=1e-9)
    assert got[2] * ell == pytest.approx(want[2], abs=1e-9 * ell)
    # the contact is [w/2 − 3 (w/2 − e), w/2] × [−d/2, d/2]
    edges = pressed.tw.edges * ell
    assert edges[:, [0, 2]].min() == pytest.approx(w / 2.0 - 3.0 * (w / 2.0 - e), abs=1e-14)


def test_lift_off_on_an_ellipse_patch_is_refused_clearly():
    ell = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0, height=0.5)
    fr = ss.FrictionTensor(0.3, 0.3)
    with pytest.raises(LiftOffUnsupported, match="would lift off"):
        ss.pressure_centre(ell, fr, ss.State(vx=1.0, omega=2.0))


@pytest.mark.parametrize(("h_q", "mode"), [(0.2, "slide"), (0.4, "tip"), (0.3333, "slide")])
def test_a_disk_pushed_at_height_slides_or_tips_as_the_closed_form(h_q, mode):
    """A cylinder of radius R pushed at h_Q tips at Q = P R / h_Q, slides at μ P (its base
    lifts off beyond R/4: the lifted disk is clipped as a polygon of the same area)."""
    r, mu = 0.1, 0.3
    disk = ss.Body(ss.Disk(r), ss.UniformPressure(), mass=1.0, height=0.5)
    got = ss.breakaway(disk, ss.FrictionTensor(mu, mu), ss.Load(force=(1.0, 0.0), height=h_q),
                       g=G)  # fmt: skip
    assert got.tip_factor == pytest.approx(G * r / h_q, rel=1e-12)
    assert got.slide_factor == pytest.approx(mu * G, rel=1e-7)
    assert got.mode == mode


def test_a_lifted_ring_keeps_its_load_and_centroid():
    ring = ss.Body(ss.Annulus(0.05, 0.1), ss.UniformPressure(), mass=1.0, height=0.5)
    tall = TallContact(ring, ss.FrictionTensor(0.3, 0.3))
    r = (0.6, 0.2)  # natural units: well beyond the ring's kern
    pressed = tall.at(r)
    tw = pressed.tw
    e = tw.edges
    a, sx, sy, sxx, sxy, syy = _moments(e, np.zeros((0, 4)))
    p0, p1, p2 = tw.geo[3:6]
    load = p0 * a + p1 * sx + p2 * sy
    assert load == pytest.approx(1.0, abs=1e-13)
    cx = (p0 * sx + p1 * sxx + p2 * sxy) / load
    cy = (p0 * sy + p1 * sxy + p2 * syy) / load
    assert (cx, cy) == pytest.approx(r, abs=1e-12)
    # p ≥ 0 on the part in contact, and 0 on the clipping line
    vals = p0 + p1 * e[:, 0] + p2 * e[:, 1]
    assert vals.min() >= -1e-12


def test_height_is_validated():
    with pytest.raises(ValueError, match="height = -0.1"):
        _box(h=-0.1)
    with pytest.raises(ValueError, match="height"):
        ss.Body(ss.Blade(0.3), ss.UniformPressure(), mass=1.0, height=0.1)
    with pytest.raises(ValueError, match="height"):
        ss.Body(ss.Ellipse(0.1, 0.1), ss.HertzPressure(), mass=1.0, height=0.1)
    with pytest.raises(ValueError, match="height = -1"):
        ss.Load(force=(1.0, 0.0), height=-1.0)
    with pytest.raises(ValueError, match="height"):
        ss.simulate_many(_box(), ss.FrictionTensor(0.3, 0.3), [ss.State(vx=1.0)])


@pytest.mark.parametrize(
    "law", [ss.Stribeck(1.48, 0.01), ss.PowerLaw(0.5, 1.0), ss.SpeedTable([0, 1], [1.3, 1.0])]
)
def test_the_pressure_centre_under_a_speed_law_reads_the_slip_speed(law):
    # a translation at speed v: F = −P μ g(v) v̂ whatever the pressure, r_p = h μ g(v) v̂
    h, mu, v = 0.05, 0.3, 0.01
    disk = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0, height=h)
    static = max(1.0, float(law.factor(0.0))) if not isinstance(law, ss.PowerLaw) else 1.0
    kw = {} if isinstance(law, ss.Stribeck) else {"static": static}
    fr = ss.FrictionTensor(mu, mu, speed_law=law, **kw)
    got = ss.pressure_centre(disk, fr, ss.State(vx=v))
    assert got == pytest.approx((h * mu * float(law.factor(v)), 0.0), abs=1e-15)


def test_pressure_centre_refuses_a_state_that_is_not_one():
    disk = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0, height=0.05)
    with pytest.raises(ValueError, match="state = "):
        ss.pressure_centre(disk, ss.FrictionTensor(0.3, 0.3), (0.0, 1.0, 0.0))


def test_the_slide_factor_is_the_first_root_not_the_hull_edge():
    """Review cases: a box whose load with a torque slides before it could tip (the slide
    root lies below the tip factor, where the pressure is far from the hull), and pads pushed
    sideways that tip first (at the hull's exact factor). The statics' answer agrees with the
    loaded engine's stick exit under a ramp of the same load (another path: its gauge at each
    time)."""
    box = _box(w=0.4, d=0.3, h=0.5)
    fr = ss.FrictionTensor(0.5, 0.5)
    got = ss.breakaway(box, fr, ss.Load(force=(1.0, 0.3), torque=0.03, height=0.5), g=G)
    assert got.mode == "slide" and got.tip_factor == pytest.approx(8.0, rel=1e-12)
    # the load grows from 7 to 8 times (1, 0.3, 0.03) over 1 s: the stick ends at λ − 7
    ramp = ss.Load.piecewise_linear([0.0, 1.0], [7.0, 8.0], [2.1, 2.4], [0.21, 0.24],
                                    height=0.5)  # fmt: skip
    t_exit = got.slide_factor - 7.0
    tr = ss.simulate(box, fr, ss.State(), load=ramp, t_end=t_exit + 1e-6, g=G,
                     scan_step=0.05)  # fmt: skip
    assert tr.phases[0][0] == "stick"
    assert tr.phases[0][2] == pytest.approx(t_exit, abs=1e-8)
    pads = ss.Body(
        ss.Pads([Rectangle(0.05, 0.2, centre=(-0.1, 0.0)), Rectangle(0.05, 0.2, centre=(0.1, 0.0))]),
        ss.UniformPressure(), mass=2.0, height=0.5,
    )  # fmt: skip
    got = ss.breakaway(pads, fr, ss.Load(force=(0.3, 1.0), torque=0.01, height=0.5), g=G)
    assert got.mode == "tip" and got.load_factor == pytest.approx(4.0, rel=1e-12)
    assert got.slide_factor > 4.0
    over = ss.Load(force=(0.3 * 4.1, 4.1), torque=0.041, height=0.5)
    assert ss.onset(pads, fr, over, g=G).mode == "tip"
