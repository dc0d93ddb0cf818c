"""The adversarial round on the line pusher over round outlines (issue 21): each case that
broke, as a regression test against geometry and mechanics written here (the pusher never
inside the body, contacts on the pusher, forces in closed form, the energy balance)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_pushed_round_hull import _support_gap

import slidespin as ss

ISO = ss.FrictionTensor(0.3, 0.3)
STADIUM_DISCS = [(-0.05, 0.0, 0.03), (0.05, 0.0, 0.03)]
STADIUM = ss.Body(
    ss.Pads(*(ss.Disk(r, centre=(x, y)) for x, y, r in STADIUM_DISCS)),
    ss.UniformPressure(),
    mass=1.0,
)
RECT_DISCS = [(-0.08, -0.03, 0.0), (0.08, -0.03, 0.0), (0.08, 0.03, 0.0), (-0.08, 0.03, 0.0)]
RECT = ss.Body(ss.Rectangle(0.16, 0.06), ss.UniformPressure(), mass=1.0)


def _deepest(tr, pusher, body, discs, every=3):
    """The deepest point of the pusher's face inside the body over the rows [m] (≤ 0 when
    it never enters), from the hull's support function."""
    worst = -math.inf
    g = np.asarray(body.mass_centre, float)
    for k in range(0, tr.t.size, every):
        (ax, ay), (bx, by) = pusher.ends(tr.t[k])
        c, s = math.cos(tr.phi[k]), math.sin(tr.phi[k])
        for w in np.linspace(0.0, 1.0, 7):
            dx, dy = ax + w * (bx - ax) - tr.x[k], ay + w * (by - ay) - tr.y[k]
            q = np.array([c * dx + s * dy, -s * dx + c * dy]) + g
            worst = max(worst, -_support_gap(q, discs)[0])
    return worst


def test_slow_tilted_push_of_a_disk_through_its_centre():
    """Radau's Newton iteration ran off to NaN (an uncaught ValueError): a face tilted 1 rad
    pushing a disk through its centre at 1 mm/s. Sticking: λ = μ m g, 2 mm of translation."""
    disk = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0)
    a = 1.0
    n = (-math.sin(a), math.cos(a))
    pusher = ss.LinePusher.constant_velocity(
        (0.1 * n[0], 0.1 * n[1], a), (-0.001 * n[0], -0.001 * n[1], 0.0), 2.0, length=0.3, mu=0.3
    )
    tr = ss.simulate(disk, ISO, ss.State(), pusher=pusher, t_end=2.4)
    assert tr.status == "ok"
    stick = np.flatnonzero(np.array(tr.mode) == "vertex_sticking")
    mid = stick[stick.size // 2 :]
    np.testing.assert_allclose(np.hypot(*tr.pusher_force[mid].T), 0.3 * 9.81, rtol=1e-6)
    assert math.hypot(tr.x[-1], tr.y[-1]) == pytest.approx(0.002, rel=1e-3)
    np.testing.assert_allclose(tr.phi, 0.0, atol=1e-9)


def _turning_about_an_end(n=101):
    """The pusher's − end pressing up on the bottom edge (y = −0.03) while it turns about
    that end from 200° to 370° (a knot every 10 ms)."""
    rows = []
    for t in np.linspace(0.0, 1.0, n):
        th = math.radians(200 + 170 * t)
        c = np.array([-0.02, -0.03 + 0.004 * t]) + 0.015 * np.array([math.cos(th), math.sin(th)])
        rows.append((t, c[0], c[1], th))
    return ss.LinePusher(0.03, rows, mu=0.3)


@pytest.mark.parametrize(
    ("body", "discs"), [(STADIUM, STADIUM_DISCS), (RECT, RECT_DISCS)], ids=["stadium", "box"]
)
def test_pusher_turning_about_its_end_on_an_edge(body, discs):
    """The box ended ``indeterminate`` with an energy error of 1, the stadium rolled on a
    point 3 cm off the pusher: the flush event watched the vertex chosen at the phase's
    start, which the turning pusher passed."""
    pusher = _turning_about_an_end()
    tr = ss.simulate(body, ISO, ss.State(), pusher=pusher, t_end=1.0)
    assert tr.status == "ok"
    assert tr.relative_energy_error < 1e-9
    assert _deepest(tr, pusher, body, discs) < 1e-9


def test_pusher_turning_through_a_flat_edge_makes_a_face():
    """The face turned through the stadium's flat edge with no flush switch (2.4 cm inside,
    an energy error of 1 %): an off-centre stadium on a slope, the end sliding on the edge
    while the pusher turns by 4 rad."""
    body = ss.Body(
        ss.Pads(*(ss.Disk(r, centre=(x, y)) for x, y, r in STADIUM_DISCS)),
        ss.LinearPressure(0.01, 0.005),
        mass=1.0,
    )
    pusher = ss.LinePusher(
        0.03,
        [(0.0, -0.03019, -0.047128, 2.999241), (2.6, -0.033661, 0.082826, 6.998670)],
        mu=0.3,
    )
    tr = ss.simulate(
        body,
        ss.FrictionTensor(0.2, 0.45, angle=0.3),
        ss.State(),
        pusher=pusher,
        t_end=3.58,
        incline=ss.Incline(0.153221, downhill=1.520882),
    )
    assert tr.status == "ok"
    assert tr.relative_energy_error < 1e-9
    assert _deepest(tr, pusher, body, STADIUM_DISCS) < 1e-9


def test_face_rolling_off_a_small_arc_stays_on_the_pusher():
    """A 3 cm face rolled off the small disc's arc of a two-disc hull onto the edge: it was
    taken for the other edge joining the same two discs and rolled on the big disc, 6.9 cm
    off the pusher, with an impulse there. Every contact point is on the pusher."""
    two_discs = [(-0.03, 0.0, 0.06), (0.06, 0.0, 0.02)]
    two = ss.Body(
        ss.Pads(*(ss.Disk(r, centre=(x, y)) for x, y, r in two_discs)),
        ss.UniformPressure(),
        mass=1.0,
    )
    pusher = ss.LinePusher(
        0.03,
        [
            (0.0, 0.092637338040664, 0.016270388875213, 5.681867242944182),
            (0.12, 0.024749758685279, -0.082680490702819, 5.681867242944182),
        ],
        mu=1.0,
    )
    tr = ss.simulate(two, ISO, ss.State(), pusher=pusher, t_end=0.36)
    assert tr.status == "ok"
    c = np.flatnonzero(np.array(tr.mode) != "separated")
    for k in c:  # every contact point on the pusher's segment
        (ax, ay), (bx, by) = pusher.ends(tr.t[k])
        d = np.array([bx - ax, by - ay])
        w = float(np.clip((tr.contact_point[k] - (ax, ay)) @ d / (d @ d), 0.0, 1.0))
        assert math.dist(tr.contact_point[k], (ax + w * d[0], ay + w * d[1])) < 1e-9
    assert _deepest(tr, pusher, two, two_discs) < 1e-9
    assert tr.relative_energy_error < 1e-9


def test_frictionless_centred_slow_push_does_not_chatter():
    """μp = 0, a face pushing a disk through its centre at 1 mm/s: sticking (λt = 0) held
    only to the integration's error, and the run flipped between sticking and sliding 717
    times in 3 s. The force is the plane friction's, μ m g along the push."""
    disk = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0)
    rows = [
        (0.0, -0.087439806630877, 0.077413830543319, 6.586549768229824),
        (3.0, -0.086543608469613, 0.074550820090012, 6.586549768229824),
    ]
    pusher = ss.LinePusher(0.3, rows, mu=0.0)
    tr = ss.simulate(disk, ISO, ss.State(), pusher=pusher, t_end=4.1)
    assert tr.status == "ok" and len(tr.switches) <= 4
    push = np.flatnonzero((tr.t > 0.5) & (tr.t < 2.9))
    np.testing.assert_allclose(np.hypot(*tr.pusher_force[push].T), 0.3 * 9.81, rtol=1e-6)
    assert tr.relative_energy_error < 1e-9


@pytest.mark.parametrize("mu", [0.0, 0.3])
def test_slow_face_coming_flush_settles_flat(mu):
    """A slow push turning a stadium's flat edge onto the face: the contact rocked between the
    two ends of the shared segment in ever shorter swings (the approach stayed above the
    landing threshold, 1e-5 of a slow pusher's speed, at the floor the events' slack leaves)
    and the run ended max_phases after 40 s with the body frozen. It lands flat and slides
    with the face, as the quasi-static engine does: the edge ends parallel to the pusher."""
    rows = [(0, 0.03, -0.1, 0.1), (3, 0.03, 0.05, 0.1)]
    pusher = ss.LinePusher(0.1, rows, mu=mu)
    tr = ss.simulate(STADIUM, ISO, ss.State(), pusher=pusher, t_end=3.0)
    qs = ss.push_quasi_static(STADIUM, ISO, pusher, [0.0, 3.0])
    assert tr.status == qs.status == "ok"
    assert len(tr.switches) < 40 and tr.switches[-1][2].startswith("face_")
    assert qs.mode[-1].startswith("face_")
    assert tr.phi[-1] == pytest.approx(0.1, abs=1e-9) and qs.phi[-1] == pytest.approx(0.1, abs=1e-9)
    assert tr.relative_energy_error < 1e-9
    assert _deepest(tr, pusher, STADIUM, STADIUM_DISCS) < 1e-9
