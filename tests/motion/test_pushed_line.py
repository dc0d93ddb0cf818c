"""Dynamic pushing with a line pusher (MODEL §13): closed forms, an independent constrained
reference, the energy balance, mirror symmetry, event convergence and input errors.

The reference here is written apart from the engine: a constrained Newton–Euler integration in
full coordinates (x, y, φ, vx, vy, ω) with a Lagrange multiplier and Baumgarte stabilisation,
calling only the public ``friction_wrench`` (the engine works in reduced coordinates on the
contact's features and evaluates the wrench through its own kernel).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import slidespin as ss
from slidespin.motion.pushed import simulate_pushed
from slidespin.motion.pushers import LinePusher, PointPusher

G = 9.81
SIDE = 0.1
SQUARE = ss.Body(ss.Rectangle(SIDE, SIDE), ss.UniformPressure(), mass=2.0)
ISO = ss.FrictionTensor(0.3, 0.3)


def _corners(phi):
    c, s = math.cos(phi), math.sin(phi)
    h = 0.5 * SIDE
    return np.array(
        [[c * x - s * y, s * x + c * y] for x, y in [(-h, -h), (h, -h), (h, h), (-h, h)]]
    )


def _angled(phi0, mu, speed=0.3, t_stop=1.5, vx0=0.0):
    """A vertical line pusher touching the square's leftmost corner, pushing along +x."""
    v = _corners(phi0)
    j = int(np.argmin(v[:, 0]))
    pusher = LinePusher.constant_velocity(
        (v[j, 0], 0.0, math.pi / 2), (speed, 0.0, 0.0), t_stop, length=0.2, mu=mu
    )
    return pusher, ss.State(phi=phi0, vx=vx0), v[j]


# ---- closed forms -------------------------------------------------------------------------


def test_centred_face_push_translates_with_mu_m_g():
    """A line pusher centred on the square's back face, pushing along the normal at constant
    speed from contact: a plastic impact m V, then face sticking with λ = μ m g, no rotation;
    when it stops the square slides V²/(2 μ g) further (MODEL §13 closed forms)."""
    speed, t1 = 0.5, 1.0
    pusher = LinePusher.constant_velocity(
        (-0.5 * SIDE, 0.0, math.pi / 2), (speed, 0.0, 0.0), t1, length=0.06, mu=0.4
    )
    tr = ss.simulate(SQUARE, ISO, ss.State(), pusher=pusher, t_end=1.5)
    assert tr.status == "ok"
    assert tr.switches == ((0.0, "separated", "face_sticking"), (1.0, "face_sticking", "separated"))
    ((t_imp, jx, jy, loss),) = tr.impacts
    assert t_imp == 0.0
    assert jx == pytest.approx(SQUARE.mass * speed, rel=1e-12) and abs(jy) < 1e-12
    assert loss == pytest.approx(0.5 * SQUARE.mass * speed**2, rel=1e-12)
    stick = np.array([m == "face_sticking" for m in tr.mode])
    assert stick.sum() >= 3
    np.testing.assert_allclose(tr.pusher_force[stick, 0], 0.3 * SQUARE.mass * G, rtol=1e-11)
    np.testing.assert_allclose(tr.pusher_force[stick, 1], 0.0, atol=1e-11)
    # the resultant sits at the face's middle (the pressure is symmetric)
    np.testing.assert_allclose(tr.contact_point[stick, 1], 0.0, atol=1e-12)
    np.testing.assert_allclose(tr.contact_point[stick, 0], tr.x[stick] - 0.5 * SIDE, atol=1e-12)
    assert np.max(np.abs(tr.phi)) < 1e-12 and np.max(np.abs(tr.y)) < 1e-12
    np.testing.assert_allclose(tr.x[stick], speed * tr.t[stick], rtol=1e-12, atol=1e-14)
    assert tr.x[-1] == pytest.approx(speed * t1 + speed**2 / (2 * 0.3 * G), rel=1e-9)
    assert tr.relative_energy_error < 1e-9


def test_pusher_arriving_from_a_distance():
    """A face pusher starting 2 cm behind the square reaches it at t = d / V (a gap event)."""
    speed, d = 0.4, 0.02
    pusher = LinePusher.constant_velocity(
        (-0.5 * SIDE - d, 0.01, math.pi / 2), (speed, 0.0, 0.0), 0.5, length=0.05, mu=0.5
    )
    tr = simulate_pushed(SQUARE, ISO, ss.State(), pusher, 0.5)
    assert tr.status == "ok"
    assert tr.switches[0][1:] == ("separated", "face_sticking")
    assert tr.switches[0][0] == pytest.approx(d / speed, abs=1e-12)
    assert np.max(np.abs(tr.phi)) < 1e-12
    assert tr.relative_energy_error < 1e-9


def test_frictionless_face_slides_then_rotates_about_its_end():
    """A frictionless face (μp = 0) moving along (0.3, 0.1) behind the square: the square is
    pushed along the normal only (λ = μ m g, no rotation) while the face slides past it; the
    resultant sits on G's line, so the contact rotates about the pusher's lower end when
    that end reaches y = 0: at t = (h − 0)/0.1 = 0.2 s (MODEL §13)."""
    h = 0.02
    pusher = LinePusher.constant_velocity(
        (-0.5 * SIDE, 0.0, math.pi / 2), (0.3, 0.1, 0.0), 0.5, length=2 * h, mu=0.0
    )
    tr = simulate_pushed(SQUARE, ISO, ss.State(), pusher, 0.5)
    assert tr.status == "ok"
    assert tr.switches[0] == (0.0, "separated", "face_sliding_left")
    t_end_contact, m0, m1 = tr.switches[1]
    assert (m0, m1) == ("face_sliding_left", "end_sliding_left")
    assert t_end_contact == pytest.approx(h / 0.1, abs=1e-12)
    face = np.array([m == "face_sliding_left" for m in tr.mode])
    np.testing.assert_allclose(tr.pusher_force[face, 0], 0.3 * SQUARE.mass * G, rtol=1e-11)
    np.testing.assert_allclose(tr.pusher_force[face, 1], 0.0, atol=1e-11)
    np.testing.assert_allclose(tr.contact_point[face, 1], 0.0, atol=1e-12)
    assert np.max(np.abs(tr.phi[face])) < 1e-12
    assert tr.relative_energy_error < 1e-9


@pytest.mark.parametrize("mu", [0.0, 0.2, 0.5])
def test_end_contact_is_a_finger_at_the_end(mu):
    """The pusher's end on the square's back face, the segment angled away from the body:
    while the contact stays at the end, the body moves as under a finger on the end's path
    (the point-pusher engine, written apart): poses and switch times agree."""
    h, th, end = 0.05, math.pi / 4, (-0.5 * SIDE, 0.02)
    centre = (end[0] - h * math.cos(th), end[1] - h * math.sin(th), th)
    line = LinePusher.constant_velocity(centre, (0.3, 0.0, 0.0), 0.3, length=2 * h, mu=mu)
    finger = PointPusher.constant_velocity(end, (0.3, 0.0), 0.3, mu=mu)
    a = simulate_pushed(SQUARE, ISO, ss.State(), line, 0.3)
    b = simulate_pushed(SQUARE, ISO, ss.State(), finger, 0.3)
    assert a.status == b.status == "ok"
    assert all(m.startswith("end_") for _, _, m in a.switches)
    assert [m1.removeprefix("end_") for _, _, m1 in a.switches] == [m1 for _, _, m1 in b.switches]
    for (ta, *_), (tb, *_) in zip(a.switches, b.switches):
        assert abs(ta - tb) < 1e-9
    got = [a.x[-1], a.y[-1], a.phi[-1], a.omega[-1]]
    want = [b.x[-1], b.y[-1], b.phi[-1], b.omega[-1]]
    np.testing.assert_allclose(got, want, atol=1e-9)
    assert abs(a.phi[-1]) > 0.3  # the push turns the square
    assert a.relative_energy_error < 1e-9


# ---- an independent constrained reference ------------------------------------------------


def _vertex_reference(state, corner_b, nb_b, speed, t_end, sticking):
    """The square's corner (body frame corner_b, relative to G) on a vertical pusher line
    moving at (speed, 0): frictionless (1 constraint, force along +x at the corner) or
    sticking (2 constraints). Full coordinates, Baumgarte-stabilised; stops where the
    neighbouring corner nb_b reaches the pusher's line."""
    m, inertia = SQUARE.mass, SQUARE.moment_of_inertia
    alpha = 50.0
    cx0 = state.x + math.cos(state.phi) * corner_b[0] - math.sin(state.phi) * corner_b[1]
    cy0 = state.y + math.sin(state.phi) * corner_b[0] + math.cos(state.phi) * corner_b[1]

    def rhs(t, y):
        x, yy, phi, vx, vy, om = y
        w = ss.friction_wrench(SQUARE, ISO, vx, vy, om, phi, G)
        fx, fy, mz = float(w.force_x), float(w.force_y), float(w.moment)
        c, s = math.cos(phi), math.sin(phi)
        r = np.array([c * corner_b[0] - s * corner_b[1], s * corner_b[0] + c * corner_b[1]])
        e = np.array([x + r[0] - (cx0 + speed * t), yy + r[1] - cy0])
        de = np.array([vx - om * r[1] - speed, vy + om * r[0]])
        rows = 2 if sticking else 1
        a = np.zeros((3 + rows, 3 + rows))
        a[0, 0], a[1, 1], a[2, 2] = m, m, inertia
        a[0, 3], a[2, 3] = -1.0, r[1]  # λx at the corner
        a[3, 0], a[3, 2] = 1.0, -r[1]  # the corner's x acceleration
        b = [fx, fy, mz, om * om * r[0] - 2 * alpha * de[0] - alpha**2 * e[0]]
        if sticking:
            a[1, 4], a[2, 4] = -1.0, -r[0]
            a[4, 1], a[4, 2] = 1.0, r[0]
            b.append(om * om * r[1] - 2 * alpha * de[1] - alpha**2 * e[1])
        sol = np.linalg.solve(a, np.array(b))
        return [vx, vy, om, *sol[:3]]

    def flush(t, y):
        c, s = math.cos(y[2]), math.sin(y[2])
        return y[0] + c * nb_b[0] - s * nb_b[1] - (cx0 + speed * t)

    flush.terminal, flush.direction = True, -1
    y0 = [state.x, state.y, state.phi, state.vx, state.vy, state.omega]
    return solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=1e-12, atol=1e-14, events=flush)


@pytest.mark.parametrize(("mu", "mode"), [(0.0, "vertex_sliding"), (1.0, "vertex_sticking")])
def test_vertex_contact_matches_constrained_reference(mu, mode):
    """A square resting at 0.4 rad, its corner on a translating pusher, moving with it (no
    impact): the rotation onto the face. The engine's reduced dynamics (φ, σ) against the
    full-coordinate constrained integration: the time the edge turns flush (the event) and
    the state there."""
    phi0, speed = 0.4, 0.3
    pusher, _, corner = _angled(phi0, mu, speed)
    state = ss.State(phi=phi0, vx=speed)
    tr = simulate_pushed(SQUARE, ISO, state, pusher, 1.0)
    assert tr.status == "ok" and tr.impacts and tr.impacts[0][0] > 0.0  # impact only at flush
    t_flush = tr.impacts[0][0]
    assert all(m.startswith(mode) for m, t in zip(tr.mode, tr.t) if t < t_flush)
    # the corner's neighbour that reaches the line first: the one with the smaller x
    c, s = math.cos(phi0), math.sin(phi0)
    v = _corners(phi0)
    j = int(np.argmin(v[:, 0]))
    back = np.array([[c * p[0] + s * p[1], -s * p[0] + c * p[1]] for p in v])  # body frame
    nbs = [back[(j - 1) % 4], back[(j + 1) % 4]]
    nb = min(nbs, key=lambda q: c * q[0] - s * q[1])
    ref = _vertex_reference(state, back[j], nb, speed, 1.0, sticking=mu > 0.0)
    assert ref.t_events[0].size == 1
    assert t_flush == pytest.approx(float(ref.t_events[0][0]), abs=1e-8)
    k = int(np.flatnonzero(tr.t == t_flush)[0])  # the row before the impact
    got = np.array([tr.x[k], tr.y[k], tr.phi[k], tr.vx[k], tr.vy[k], tr.omega[k]])
    np.testing.assert_allclose(got, ref.y_events[0][0], atol=1e-8)


def test_angled_hit_turns_flat_then_translates():
    """A square at rest at 0.3 rad hit at its corner by the face: an impact, vertex contact,
    the edge turns flush (an event, a face impact), then the square rides flat on the pusher
    with λ = μ m g along the push and no further rotation."""
    pusher, state, _ = _angled(0.3, 0.4)
    tr = simulate_pushed(SQUARE, ISO, state, pusher, 1.5)
    assert tr.status == "ok"
    kinds = [m1.split("_")[0] for _, _, m1 in tr.switches]
    assert kinds[0] == "vertex" and "face" in kinds
    assert tr.switches[-1][2] == "face_sticking"
    assert tr.impacts[0][0] == 0.0 and len(tr.impacts) >= 2
    flat = np.array([m == "face_sticking" for m in tr.mode])
    assert flat.sum() >= 3
    np.testing.assert_allclose(tr.phi[flat], 0.0, atol=1e-12)
    np.testing.assert_allclose(tr.omega[flat], 0.0, atol=1e-12)
    np.testing.assert_allclose(tr.vx[flat], 0.3, rtol=1e-12)
    np.testing.assert_allclose(tr.pusher_force[flat, 0], 0.3 * SQUARE.mass * G, rtol=1e-10)
    np.testing.assert_allclose(tr.pusher_force[flat, 1], 0.0, atol=1e-10)
    assert tr.relative_energy_error < 1e-9


# ---- energy, symmetry, event accuracy ----------------------------------------------------


@pytest.mark.parametrize(
    ("phi0", "mu", "friction"),
    [
        (0.3, 0.4, ISO),
        (0.3, 0.0, ISO),
        (0.6, 0.2, ISO),
        (0.7, 1.0, ISO),  # rocking onto the face: a converging run of impacts
        (0.5, 0.3, ss.FrictionTensor(0.2, 0.4, 0.05)),
    ],
)
def test_energy_balance_closes(phi0, mu, friction):
    """Pusher work = ΔKE + plane friction + contact slip + impact losses (MODEL §13), through
    vertex, face and separated phases (the pusher stops at 1.5 s)."""
    pusher, state, _ = _angled(phi0, mu)
    tr = simulate_pushed(SQUARE, friction, state, pusher, 2.0)
    assert tr.status == "ok"
    assert len(tr.switches) >= 2
    assert tr.relative_energy_error < 1e-9
    balance = (
        tr.kinetic_energy[-1]
        - tr.kinetic_energy[0]
        + tr.friction_work[-1]
        + tr.contact_slip_work[-1]
        + tr.impact_loss[-1]
    )
    assert balance == pytest.approx(tr.pusher_work[-1], rel=1e-9)
    wp = tr.pusher_work[-1]
    assert np.all(np.diff(tr.friction_work) >= -1e-15 * wp)
    assert np.all(np.diff(tr.contact_slip_work) >= -1e-15 * wp)
    assert np.all(np.diff(tr.impact_loss) >= -1e-15 * wp)


def test_mirrored_hit_mirrors_the_motion():
    """Mirror the start in the x axis (φ → −φ): y → −y, φ → −φ, left ↔ right."""
    pa, sa, _ = _angled(0.3, 0.4)
    pb, sb, _ = _angled(-0.3, 0.4)
    a = simulate_pushed(SQUARE, ISO, sa, pa, 2.0)
    b = simulate_pushed(SQUARE, ISO, sb, pb, 2.0)

    def swap(m):
        return m.replace("left", "L").replace("right", "left").replace("L", "right")

    assert [(t, swap(m0), swap(m1)) for t, m0, m1 in a.switches] == [
        (pytest.approx(t, abs=1e-9), m0, m1) for t, m0, m1 in b.switches
    ]
    assert b.x[-1] == pytest.approx(a.x[-1], abs=1e-10)
    assert b.y[-1] == pytest.approx(-a.y[-1], abs=1e-10)
    assert b.phi[-1] == pytest.approx(-a.phi[-1], abs=1e-10)


def test_switch_times_converge_with_rtol():
    """The located switches are a property of the motion: rtol 1e-9 and 1e-11 agree."""
    pusher, state, _ = _angled(0.6, 0.2)
    loose = simulate_pushed(SQUARE, ISO, state, pusher, 2.0, rtol=1e-9)
    tight = simulate_pushed(SQUARE, ISO, state, pusher, 2.0, rtol=1e-11)
    assert [s[1:] for s in loose.switches] == [s[1:] for s in tight.switches]
    assert len(tight.switches) >= 4
    for (ta, *_), (tb, *_) in zip(loose.switches, tight.switches):
        assert abs(ta - tb) < 1e-9
    assert tight.x[-1] == pytest.approx(loose.x[-1], abs=1e-8)


# ---- input errors -------------------------------------------------------------------------


def test_pusher_inside_the_body_is_refused():
    pusher = LinePusher.constant_velocity((0.0, 0.0, math.pi / 2), (0.3, 0.0, 0.0), 1.0, 0.1)
    with pytest.raises(ValueError, match="inside") as info:
        simulate_pushed(SQUARE, ISO, ss.State(), pusher, 1.0)
    assert "\n" not in str(info.value) and str(info.value).startswith("pusher = ")


def test_turning_face_carries_the_body_rigidly():
    """Face sticking on a turning pusher (ṗ = (0.3, 0), θ̇ = 0.4 rad/s): the square keeps its
    pose in the pusher's frame, and the pusher's force and its point balance Newton–Euler
    with the public friction wrench: λ = m a_G − F (a_G = −θ̇² (G − p), centripetal) and
    (c − G) × λ = −M (ω̇ = 0), MODEL §13."""
    w, speed = 0.4, 0.3
    pusher = LinePusher.constant_velocity(
        (-0.5 * SIDE, 0.0, math.pi / 2), (speed, 0.0, w), 1.0, length=0.08, mu=1.0
    )
    tr = simulate_pushed(SQUARE, ISO, ss.State(), pusher, 1.0)
    assert tr.status == "ok"
    stick = np.flatnonzero([m == "face_sticking" for m in tr.mode])
    assert stick.size >= 5 and tr.t[stick[-1]] - tr.t[stick[0]] > 0.9
    pose = pusher.pose(tr.t[stick])
    c, s = np.cos(pose[:, 2]), np.sin(pose[:, 2])
    dx, dy = tr.x[stick] - pose[:, 0], tr.y[stick] - pose[:, 1]
    rel = np.column_stack((c * dx + s * dy, -s * dx + c * dy, tr.phi[stick] - pose[:, 2]))
    np.testing.assert_allclose(rel, np.tile(rel[0], (stick.size, 1)), atol=1e-12)
    np.testing.assert_allclose(tr.omega[stick], w, rtol=1e-12)
    for k in stick:
        f = ss.friction_wrench(SQUARE, ISO, tr.vx[k], tr.vy[k], tr.omega[k], tr.phi[k], G)
        a_g = -(w**2) * np.array(
            [tr.x[k] - pusher.pose(tr.t[k])[0], tr.y[k] - pusher.pose(tr.t[k])[1]]
        )
        lam = SQUARE.mass * a_g - np.array([float(f.force_x), float(f.force_y)])
        np.testing.assert_allclose(tr.pusher_force[k], lam, atol=1e-10)
        arm = tr.contact_point[k] - np.array([tr.x[k], tr.y[k]])
        moment = arm[0] * lam[1] - arm[1] * lam[0]
        assert moment == pytest.approx(-float(f.moment), abs=1e-10)
    assert tr.relative_energy_error < 1e-9


@pytest.mark.parametrize(
    ("body", "path", "mu", "extra"),
    [
        # a turning pusher with a knot: face sticking, sliding, rotation about the end
        (
            SQUARE,
            [
                (0, -0.05, 0.0, math.pi / 2),
                (1.0, 0.2, 0.1, math.pi / 2 + 0.5),
                (1.5, 0.3, 0.3, 1.8),
            ],
            0.5,
            {},
        ),
        (
            ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=2.0),
            [(0, -0.1, 0.0, math.pi / 2), (1.0, 0.3, 0.0, math.pi / 2)],
            0.5,
            {"load": ss.Load(force=(0.0, 2.0))},
        ),
        (
            ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=2.0),
            [(0, -0.1, 0.0, math.pi / 2), (1.0, 0.3, 0.0, math.pi / 2)],
            0.5,
            {"incline": ss.Incline(0.1, downhill=math.pi / 2)},
        ),
    ],
)
def test_energy_balance_with_turning_pushers_loads_and_slopes(body, path, mu, extra):
    """Pusher work + load work = ΔKE + friction + slip + impact losses (MODEL §11, §13)."""
    tr = simulate_pushed(body, ISO, ss.State(), LinePusher(0.08, path, mu=mu), 2.0, **extra)
    assert tr.status == "ok" and len(tr.switches) >= 2
    assert tr.relative_energy_error < 1e-9
    lhs = tr.pusher_work[-1] + tr.load_work[-1]
    rhs = (
        tr.kinetic_energy[-1]
        - tr.kinetic_energy[0]
        + tr.friction_work[-1]
        + tr.contact_slip_work[-1]
        + tr.impact_loss[-1]
    )
    assert rhs == pytest.approx(lhs, rel=1e-9, abs=1e-12)
