"""A line pusher on hulls of discs (pads with disks: straight edges, arcs and sharp corners;
MODEL §13): the arc's contacts against the ellipse engine on the same circle, a flat push
on a straight edge (closed form), the energy balance and the contact's geometry against a
support function written in the tests, and mirror symmetry."""

from __future__ import annotations

import math

import numpy as np
import pytest
from round_feet import FEET, FEET_DISCS, MIXED, MIXED_DISCS
from test_push_crosschecks import _hermite
from test_pushed_line_round import mirror_check
from test_pushed_round_hull import G_FEET, G_MIXED, _body_frame, _support_gap

import slidespin as ss

G = 9.81
ISO = ss.FrictionTensor(0.3, 0.3)
ANISO = ss.FrictionTensor(0.2, 0.45, angle=0.3)
#: a big disc and a small one: G = (−0.021, 0) inside the big one
TWO = ss.Body(
    ss.Pads(ss.Disk(0.06, centre=(-0.03, 0.0)), ss.Disk(0.02, centre=(0.06, 0.0))),
    ss.UniformPressure(),
    mass=1.0,
)
#: a stadium: two equal discs, G at the origin, flat edges at y = ±0.03
STADIUM = ss.Body(
    ss.Pads(ss.Disk(0.03, centre=(-0.05, 0.0)), ss.Disk(0.03, centre=(0.05, 0.0))),
    ss.UniformPressure(),
    mass=1.0,
)
_LEFT = -0.03 - 0.06 + 0.021  # TWO's leftmost point from G


@pytest.mark.parametrize(
    ("length", "rows", "mu", "first"),
    [
        (
            0.2,
            [(0, _LEFT - 0.05, 0.0, math.pi / 2), (1.0, _LEFT + 0.15, 0.05, 1.87)],
            0.3,
            "vertex",
        ),
        (
            0.03,
            [(0, _LEFT - 0.05, 0.03, math.pi / 2), (1.0, _LEFT + 0.1, 0.03, math.pi / 2)],
            0.5,
            "end",
        ),
    ],
)
def test_an_arc_moves_as_the_circle_it_belongs_to(length, rows, mu, first):
    """A push that touches only the big disc's arc of TWO (the face rolling on it; an end on
    it): the same motion as the body given that disc as its outline (the ellipse engine,
    checked against a constrained reference in test_pushed_line_round.py)."""
    pusher = ss.LinePusher(length, rows, mu=mu)
    a = ss.simulate(TWO, ANISO, ss.State(), pusher=pusher, t_end=1.5)
    b = ss.simulate(
        TWO, ANISO, ss.State(), pusher=pusher, t_end=1.5, outline=ss.Disk(0.06, centre=(-0.03, 0))
    )
    assert a.status == b.status == "ok"
    assert [m for _, _, m in a.switches] == [m for _, _, m in b.switches]
    assert a.switches[0][2].startswith(first)
    for (ta, *_), (tb, *_) in zip(a.switches, b.switches):
        assert ta == pytest.approx(tb, abs=1e-9)
    tq = np.linspace(0.3, 1.5, 9)
    np.testing.assert_allclose(_hermite(a, tq), _hermite(b, tq), atol=1e-9)
    assert abs(a.phi[-1]) > 0.01  # it turned
    assert a.relative_energy_error < 1e-9


def test_flat_push_on_a_straight_edge_translates_with_mu_m_g():
    """A face on the stadium's straight edge, pushing along its normal through G: an impact,
    face sticking with λ = μ m g, no rotation; then V²/(2 μ g) of sliding (closed forms)."""
    speed, t1 = 0.3, 1.0
    pusher = ss.LinePusher.constant_velocity(
        (0.0, -0.03, 0.0), (0.0, speed, 0.0), t1, length=0.06, mu=0.5
    )
    tr = ss.simulate(STADIUM, ISO, ss.State(), pusher=pusher, t_end=1.5)
    assert tr.status == "ok", tr.message
    assert [m for _, _, m in tr.switches] == ["face_sticking", "separated"]
    stick = np.flatnonzero([m == "face_sticking" for m in tr.mode])
    np.testing.assert_allclose(tr.pusher_force[stick[1:], 1], 0.3 * G, rtol=1e-10)
    np.testing.assert_allclose(tr.phi, 0.0, atol=1e-12)
    assert tr.y[-1] == pytest.approx(speed * t1 + speed**2 / (2 * 0.3 * G), rel=1e-9)


TURN = [(0, -0.2, 0.03, math.pi / 2), (1.0, 0.0, 0.05, math.pi / 2 + 0.4), (2.0, 0.1, 0.2, 1.2)]
BACK = [(0, 0.25, 0.01, math.pi / 2), (2.0, -0.05, -0.02, math.pi / 2 - 0.3)]
HULLS = {"feet": (FEET, FEET_DISCS, G_FEET), "mixed": (MIXED, MIXED_DISCS, G_MIXED)}


@pytest.mark.parametrize("mu", [0.0, 0.3])
@pytest.mark.parametrize(
    ("name", "friction", "rows"),
    [
        ("feet", ISO, TURN),
        ("feet", ANISO, TURN),  # a face turning off one end (was 4000 grazing impacts)
        ("feet", ANISO, BACK),
        ("mixed", ANISO, TURN),
        ("mixed", ISO, BACK),
    ],
)
def test_energy_balance_and_contact_on_the_hull(name, friction, rows, mu):
    """Turning pushers over edges, arcs and corners: the energy balance to 1e-9, every
    contact row on the hull (to 1e-10 m) and on the pusher's segment, λ in the cone."""
    body, discs, g = HULLS[name]
    pusher = ss.LinePusher(0.08, rows, mu=mu)
    tr = ss.simulate(body, friction, ss.State(), pusher=pusher, t_end=2.5)
    assert tr.status == "ok", tr.message
    assert len(tr.switches) >= 2
    assert tr.relative_energy_error < 1e-9
    c = np.flatnonzero([m != "separated" for m in tr.mode])
    for q in _body_frame(tr, c, g):
        assert abs(_support_gap(q, discs)[0]) < 1e-10
    pose = pusher.pose(tr.t[c])
    rel = tr.contact_point[c] - pose[:, :2]
    e = np.column_stack((np.cos(pose[:, 2]), np.sin(pose[:, 2])))
    np.testing.assert_allclose(rel[:, 0] * e[:, 1] - rel[:, 1] * e[:, 0], 0.0, atol=1e-12)
    assert np.all(np.abs(np.sum(rel * e, axis=1)) <= 0.04 * (1 + 1e-9))
    # the pusher never enters the hull: points along its face, every 20th row
    every = np.arange(0, tr.t.size, 20)
    poses = pusher.pose(tr.t[every])
    for k, (px, py, th) in zip(every, poses):
        c, s = math.cos(tr.phi[k]), math.sin(tr.phi[k])
        for sig in np.linspace(-0.04, 0.04, 9):
            d = (px + sig * math.cos(th) - tr.x[k], py + sig * math.sin(th) - tr.y[k])
            q = np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]]) + g
            assert _support_gap(q, discs)[0] > -1e-9


def test_mirrored_path_mirrors_the_motion_on_the_stadium():
    mirror_check(STADIUM, ANISO, [(0, -0.15, 0.02, math.pi / 2), (1.0, 0.0, 0.04, 1.87)], 1.5)


# ---- quasi-static -----------------------------------------------------------------------


def test_quasi_static_arc_moves_as_the_circle_it_belongs_to():
    """``push_quasi_static`` on TWO with a face rolling on the big disc's arc: the same poses
    as with that disc as the outline (the ellipse's quasi-static engine)."""
    pusher = ss.LinePusher(
        0.2, [(0, _LEFT - 0.05, 0.0, math.pi / 2), (1.0, _LEFT + 0.15, 0.05, 1.87)], mu=0.3
    )
    times = np.linspace(0.0, 1.0, 11)
    a = ss.push_quasi_static(TWO, ANISO, pusher, times)
    b = ss.push_quasi_static(TWO, ANISO, pusher, times, outline=ss.Disk(0.06, centre=(-0.03, 0)))
    assert a.status == b.status == "ok"
    assert list(a.mode) == list(b.mode) and "vertex_sticking" in a.mode
    np.testing.assert_allclose(np.c_[a.x, a.y, a.phi], np.c_[b.x, b.y, b.phi], atol=1e-9)
    assert abs(a.phi[-1]) > 0.005


@pytest.mark.parametrize(
    ("name", "rows", "mu"),
    [
        (
            "feet",
            [(0, -0.2, 0.03, math.pi / 2), (1.0, 0.0, 0.06, 2.17), (2.0, 0.05, 0.15, 2.5)],
            0.05,
        ),
        (
            "feet",
            [
                (0, -0.2, -0.04, math.pi / 2),
                (1.0, -0.02, -0.04, math.pi / 2),
                (2.0, 0.06, -0.04, 2.07),
            ],
            0.0,
        ),
        ("mixed", [(0, -0.2, 0.03, math.pi / 2), (1.0, 0.0, 0.05, math.pi / 2 + 0.4)], 0.3),
        (
            "mixed",
            [
                (0, -0.2, -0.04, math.pi / 2),
                (1.0, -0.02, -0.04, math.pi / 2),
                (2.0, 0.06, -0.04, 2.07),
            ],
            0.0,
        ),
    ],
)
def test_slow_dynamics_tends_to_quasi_static_on_the_hull(name, rows, mu):
    """The same path at 0.1, 0.03 and 0.01 of its speed: after the arrival the dynamic
    poses tend to the quasi-static ones (two engines written apart) like V², below 1e-5 ℓ."""
    body = HULLS[name][0]
    errs = []
    for scale in (0.1, 0.03, 0.01):
        path = np.array(rows, float)
        path[:, 0] /= scale
        pusher = ss.LinePusher(0.08, path, mu=mu)
        t_end = float(path[-1, 0])
        tr = ss.simulate(body, ANISO, ss.State(), pusher=pusher, t_end=t_end)
        assert tr.status == "ok"
        ta = tr.switches[0][0]  # the arrival (the body rests before it)
        tq = np.linspace(ta + 0.05 * (t_end - ta), t_end, 8)
        qs = ss.push_quasi_static(body, ANISO, pusher, np.r_[0.0, tq])
        assert qs.status == "ok"
        x, y, phi = _hermite(tr, tq)
        ell = body.length_unit
        errs.append(
            max(np.max(np.abs(x - qs.x[1:])), np.max(np.abs(y - qs.y[1:]))) / ell
            + np.max(np.abs(phi - qs.phi[1:]))
        )
    errs = np.array(errs)
    assert np.all(errs[:-1] / errs[1:] > 5.0), errs  # (10/3)² ≈ 11 per step
    assert errs[-1] < 1e-5


@pytest.mark.parametrize("tilt", [0.6, -0.6])
def test_a_tiny_pusher_meets_an_arc_with_the_end_whose_face_stays_outside(tilt):
    """A 1 µm pusher tilted 0.6 rad from the arc's tangent reaches the stadium's arc with
    both ends at once (to 1e-9 ℓ): the contact is the end from which the face leaves the
    body (the other made it 'roll' on a face that is not tangent, and G jumped 5 mm)."""
    b = math.radians(45.0)
    u = np.array([math.cos(b), math.sin(b)])
    start = np.array([0.05, 0.0]) + 0.04 * u
    ang = b + math.pi / 2 + tilt
    pusher = ss.LinePusher(1e-6, [(0.0, *start, ang), (0.5, *(start - 0.1 * u), ang)], mu=0.3)
    tr = ss.simulate(STADIUM, ISO, ss.State(), pusher=pusher, t_end=0.6)
    assert tr.status == "ok"
    assert [m for _, _, m in tr.switches] == ["end_sliding_right", "separated"]
    same = np.flatnonzero(np.diff(tr.t) == 0.0)
    assert np.all(np.hypot(np.diff(tr.x), np.diff(tr.y))[same] == 0.0)
    assert tr.relative_energy_error < 1e-9
