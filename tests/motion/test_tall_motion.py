"""Tall bodies in motion (MODEL §14) against closed forms: a box pushed at a height by a
growing force tips (at rest, or while it slides) at the time the moment balance gives; a tall
body sliding in translation stops as a thin one (its force does not depend on the
pressure); the energy balance of a spinning tall body."""

from __future__ import annotations

import math

import pytest
from scipy.integrate import quad

import slidespin as ss
from slidespin.contact._speed_wrench import law_arrays, speed_tol
from slidespin.contact.shapes import Rectangle
from slidespin.contact.tall_speed import TallSpeed

G = 10.0
pytestmark = pytest.mark.xdist_group("tall_motion")


def _box(w=0.4, d=0.3, h=0.5, m=2.0):
    return ss.Body(Rectangle(w, d), ss.UniformPressure(), mass=m, height=h)


def _ramp(k, h_q):
    return ss.Load.piecewise_linear([0.0, 10.0], [0.0, 10.0 * k], [0.0, 0.0], height=h_q)


def test_a_box_pushed_high_tips_at_rest_when_the_push_reaches_p_w_over_2_h_q():
    w, h_q, mu, k = 0.4, 0.5, 0.5, 10.0
    box = _box(w=w, h=0.3)
    tr = ss.simulate(box, ss.FrictionTensor(mu, mu), ss.State(), load=_ramp(k, h_q),
                     t_end=2.0, g=G)  # fmt: skip
    p = box.mass * G
    assert tr.status == "tipping"
    assert tr.tip_time == pytest.approx(p * w / (2.0 * h_q) / k, abs=1e-9)
    assert tr.ending == "at_rest_throughout"
    assert tr.summary()["tip_time"] == tr.tip_time


def test_a_box_pushed_above_g_slides_then_tips_as_the_push_grows():
    # slides at Q = μ P; while it slides in translation r_p = h μ + (h_Q − h) Q / P, which
    # reaches w/2 at Q = P (w/2 − h μ)/(h_Q − h)
    w, h, h_q, mu, k = 0.4, 0.2, 0.5, 0.3, 10.0
    box = _box(w=w, h=h)
    tr = ss.simulate(box, ss.FrictionTensor(mu, mu), ss.State(), load=_ramp(k, h_q),
                     t_end=2.0, g=G)  # fmt: skip
    p = box.mass * G
    assert tr.status == "tipping"
    assert tr.phases[0][0] == "stick"
    assert tr.phases[0][2] == pytest.approx(mu * p / k, abs=1e-9)
    assert tr.tip_time == pytest.approx(p * (w / 2.0 - h * mu) / (h_q - h) / k, abs=1e-9)
    assert tr.ending == "moving_at_t_end"


def test_a_box_pushed_low_slides_and_does_not_tip():
    w, h_q, mu, k = 0.4, 0.3, 0.5, 10.0
    box = _box(w=w, h=0.3)
    tr = ss.simulate(box, ss.FrictionTensor(mu, mu), ss.State(), load=_ramp(k, h_q),
                     t_end=1.5, g=G)  # fmt: skip
    assert tr.status == "ok" and tr.tip_time is None
    assert tr.phases[0][2] == pytest.approx(mu * box.mass * G / k, abs=1e-9)
    # after the start: m a = k t − μ P, so x(t) = (k (t³ − t₀³)/6 − k t₀² (t − t₀)/2 ...)
    t0 = mu * box.mass * G / k
    t1 = 1.5
    x = (k / 6.0 * (t1 - t0) ** 3) / box.mass  # ∫∫ (k (t − t₀)/m) dt²
    assert tr.x[-1] == pytest.approx(x, abs=1e-9)


@pytest.mark.parametrize(
    ("patch", "h"),
    [(ss.Disk(0.1), 0.05), (ss.Disk(0.1), 0.15), (Rectangle(0.3, 0.2), 0.05),
     (ss.Annulus(0.05, 0.1), 0.2)],
    ids=["disk", "disk-lifted", "box", "ring-lifted"],
)  # fmt: skip
def test_a_tall_body_sliding_in_translation_stops_as_a_thin_one(patch, h):
    mu, v0 = 0.3, 1.2
    body = ss.Body(patch, ss.UniformPressure(), mass=1.0, height=h)  # lifted: h μ > R/4
    tr = ss.simulate(body, ss.FrictionTensor(mu, mu), ss.State(vx=v0, vy=0.5 * v0), g=G)
    v = math.hypot(v0, 0.5 * v0)
    assert tr.status == "ok" and tr.ending == "stopped_stuck"
    assert tr.t_stop == pytest.approx(v / (mu * G), rel=1e-9)
    assert math.hypot(tr.x[-1], tr.y[-1]) == pytest.approx(v * v / (2.0 * mu * G), rel=1e-9)


def test_a_tall_box_too_tall_for_its_friction_tips_as_it_is_launched():
    box = _box(w=0.4, h=0.5)  # h μ = 0.25 > w/2 = 0.2
    tr = ss.simulate(box, ss.FrictionTensor(0.5, 0.5), ss.State(vx=1.0), g=G)
    assert tr.status == "tipping" and tr.tip_time == 0.0


def test_a_tall_box_on_a_slope_steeper_than_its_tipping_angle_tips():
    box = _box(w=0.4, h=0.5)  # tips at tan α = 0.4, slides at tan α = μ = 0.6
    tr = ss.simulate(box, ss.FrictionTensor(0.6, 0.6), ss.State(),
                     incline=ss.Incline(math.atan(0.45)), t_end=1.0, g=G)  # fmt: skip
    assert tr.status == "tipping" and tr.tip_time == 0.0
    tr = ss.simulate(box, ss.FrictionTensor(0.6, 0.6), ss.State(),
                     incline=ss.Incline(math.atan(0.35)), t_end=1.0, g=G)  # fmt: skip
    assert tr.status == "ok" and tr.ending == "at_rest_throughout"


def test_the_energy_balance_of_a_spinning_tall_body():
    body = ss.Body(Rectangle(0.3, 0.2), ss.UniformPressure(), mass=1.0, height=0.08)
    fr = ss.FrictionTensor(0.4, 0.25, 0.05)
    s0 = ss.State(vx=0.8, vy=-0.3, omega=6.0)
    tr = ss.simulate(body, fr, s0, g=G)
    assert tr.status == "ok" and tr.ending == "stopped_stuck"
    assert tr.energy_error <= 1e-9 * tr.kinetic_energy[0]
    # the height matters once the body spins: the stop differs from the thin body's
    thin = ss.simulate(ss.Body(Rectangle(0.3, 0.2), ss.UniformPressure(), mass=1.0), fr, s0,
                       g=G)  # fmt: skip
    assert abs(tr.phi[-1] - thin.phi[-1]) > 1e-4


def test_a_tall_disk_under_a_stribeck_law_translating_stops_as_the_1d_law():
    # m dv/dt = −μ m g s(v): t_stop = ∫₀^v dv / (μ g s(v)) (quad); the force of a translation
    # does not depend on the pressure, so the height changes nothing but r_p
    mu, ratio, vs, v = 0.2, 1.3, 0.2, 0.8
    body = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0, height=0.02)
    fr = ss.FrictionTensor(mu, mu, speed_law=ss.Stribeck(ratio, vs))
    tr = ss.simulate(body, fr, ss.State(vx=v), g=G)
    assert tr.status == "stopped"
    want = quad(lambda w: 1.0 / (mu * G * (1 + (ratio - 1) * math.exp(-((w / vs) ** 2)))),
                0.0, v, epsabs=1e-14, epsrel=1e-13)[0]  # fmt: skip
    assert tr.t[-1] == pytest.approx(want, rel=1e-9)
    assert tr.y[-1] == 0.0


def test_a_tall_body_under_a_power_law_is_refused_before_any_work():
    body = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0, height=0.02)
    fr = ss.FrictionTensor(0.2, 0.2, speed_law=ss.PowerLaw(0.3))
    with pytest.raises(ValueError, match="height"):
        ss.simulate(body, fr, ss.State(vx=1.0))


def test_a_tall_spinning_ring_under_a_stribeck_law_keeps_its_moment_balance():
    """r_p = r_G − h F(r_p)/P with F from the public wrench under the law of the shifted linear
    law (another Body: not the tall module's arithmetic)."""
    h = 0.03
    ring = ss.Annulus(0.04, 0.07)
    body = ss.Body(ring, ss.UniformPressure(), mass=1.0, height=h)
    fr = ss.FrictionTensor(0.4, 0.3, 0.05, speed_law=ss.Stribeck(1.4, 0.3))
    ts = TallSpeed(body, fr, law_arrays(fr.speed_law), speed_tol(fr))
    phi, vx, vy, om = 0.3, 0.5, 0.2, 4.0
    fx, fy, _, rp = ts(phi, vx, vy, om)
    shifted = ss.Body(ring, ss.LinearPressure(*rp), mass=1.0)
    c, s = math.cos(phi), math.sin(phi)
    dx, dy = c * rp[0] - s * rp[1], s * rp[0] + c * rp[1]
    wr = ss.friction_wrench(shifted, fr, vx - om * dy, vy + om * dx, om, phi=phi, g=G)
    assert (wr.force_x / G, wr.force_y / G) == pytest.approx((fx, fy), abs=1e-10)
    fb = (c * fx + s * fy, -s * fx + c * fy)
    assert rp == pytest.approx((-h * fb[0], -h * fb[1]), abs=1e-12)
