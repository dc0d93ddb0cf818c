"""Dynamic pushing with a finger (MODEL §13): closed forms, an independent constrained
reference, the energy balance, mirror symmetry, event convergence and input errors.

The references here are written apart from the engine: closed forms of translation pushes, and
a constrained Newton–Euler integration in full coordinates (x, y, φ, vx, vy, ω) with Lagrange
multipliers and Baumgarte stabilisation, calling only the public ``friction_wrench`` (the
engine works in reduced coordinates instead and evaluates the wrench through its own kernel).
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
BOX = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=2.0)
DISK = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.5)
ISO = ss.FrictionTensor(0.3, 0.3)


# ---- closed forms -------------------------------------------------------------------------


def test_push_through_centre_translates_with_mu_m_g():
    """A finger on the back face of a box at G's height, at constant speed from contact:
    a plastic impact m V, then pure translation at V with λ = μ m g; when the finger stops the
    box separates and slides V²/(2 μ g) further in V/(μ g) (MODEL §13 closed forms)."""
    speed, t1 = 0.5, 1.0
    finger = PointPusher.constant_velocity((-0.1, 0.0), (speed, 0.0), t1, mu=0.4)
    tr = simulate_pushed(BOX, ISO, ss.State(), finger, 1.5)
    assert tr.status == "ok"
    assert len(tr.impacts) == 1
    t_imp, jx, jy, loss = tr.impacts[0]
    assert t_imp == 0.0
    assert jx == pytest.approx(BOX.mass * speed, rel=1e-12)
    assert abs(jy) < 1e-12
    assert loss == pytest.approx(0.5 * BOX.mass * speed**2, rel=1e-12)
    stick = np.array([m == "sticking" for m in tr.mode])
    assert stick.sum() >= 3
    np.testing.assert_allclose(tr.pusher_force[stick, 0], 0.3 * BOX.mass * G, rtol=1e-11)
    np.testing.assert_allclose(tr.pusher_force[stick, 1], 0.0, atol=1e-11)
    assert np.max(np.abs(tr.phi)) < 1e-12 and np.max(np.abs(tr.y)) < 1e-12
    np.testing.assert_allclose(tr.x[stick], speed * tr.t[stick], rtol=1e-12, atol=1e-14)
    assert tr.switches == ((0.0, "separated", "sticking"), (1.0, "sticking", "separated"))
    stop_d = speed**2 / (2.0 * 0.3 * G)
    assert tr.x[-1] == pytest.approx(speed * t1 + stop_d, rel=1e-9)
    moving = np.flatnonzero(np.abs(tr.vx) > 0.0)
    t_stop = tr.t[moving[-1] + 1]
    assert t_stop == pytest.approx(t1 + speed / (0.3 * G), abs=1e-9)


def test_anisotropic_push_along_axis():
    """A diagonal tensor F = diag(fx, fy): a push along y through G translates the box with
    λ = fy m g (MODEL §8's pure translation)."""
    fr = ss.FrictionTensor(0.2, 0.45)
    finger = PointPusher.constant_velocity((0.0, -0.05), (0.0, 0.3), 0.5)
    tr = simulate_pushed(BOX, fr, ss.State(), finger, 0.5)
    contact = np.array([m != "separated" for m in tr.mode])
    np.testing.assert_allclose(tr.pusher_force[contact][1:, 1], 0.45 * BOX.mass * G, rtol=1e-11)
    assert np.max(np.abs(tr.phi)) < 1e-12
    assert tr.y[-1] == pytest.approx(0.3 * 0.5, rel=1e-12)


def test_speed_jump_impulse_is_m_delta_v():
    """A finger that speeds up from V1 to V2 at a knot strikes the box: impulse m (V2 − V1),
    energy lost ½ m (V2 − V1)² (a plastic impact of a prescribed motion on a free mass)."""
    v1, v2 = 0.2, 0.7
    finger = PointPusher(
        [(0.0, -0.1, 0.0), (1.0, -0.1 + v1, 0.0), (1.5, -0.1 + v1 + 0.5 * v2, 0.0)]
    )
    state = ss.State(vx=v1)  # moving with the finger: no impact at t = 0
    tr = simulate_pushed(BOX, ISO, state, finger, 1.5)
    assert [round(i[0], 12) for i in tr.impacts] == [1.0]
    _, jx, jy, loss = tr.impacts[0]
    assert jx == pytest.approx(BOX.mass * (v2 - v1), rel=1e-10)
    assert abs(jy) < 1e-12
    assert loss == pytest.approx(0.5 * BOX.mass * (v2 - v1) ** 2, rel=1e-10)
    assert tr.x[-1] == pytest.approx(v1 * 1.0 + v2 * 0.5, rel=1e-12)
    assert tr.vx[-1] == pytest.approx(v2, rel=1e-12)


def test_disk_rim_frictionless_finger_arrives_and_separates():
    """A frictionless finger approaching a disk along a line through its centre: arrival at
    d/V, impact m V, translation with λ = μ m g, separation when the finger stops, then the
    disk slides V²/(2 μ g) further."""
    speed, d, t1 = 0.4, 0.05, 1.0
    finger = PointPusher.constant_velocity((-0.1 - d, 0.0), (speed, 0.0), t1, mu=0.0)
    tr = simulate_pushed(DISK, ISO, ss.State(), finger, 1.4)
    assert tr.status == "ok"
    (t_hit, m0, m1), (t_sep, m2, m3) = tr.switches
    assert (m0, m1, m2, m3) == ("separated", "sticking", "sticking", "separated")
    assert t_hit == pytest.approx(d / speed, abs=1e-12)
    assert t_sep == 1.0
    assert tr.impacts[0][1] == pytest.approx(DISK.mass * speed, rel=1e-12)
    stick = np.array([m == "sticking" for m in tr.mode])
    np.testing.assert_allclose(tr.pusher_force[stick, 0], 0.3 * DISK.mass * G, rtol=1e-11)
    assert tr.x[-1] == pytest.approx(speed * (t1 - d / speed) + speed**2 / (0.6 * G), rel=1e-9)
    assert np.max(np.abs(tr.phi)) < 1e-12


# ---- an independent constrained reference ------------------------------------------------


def _reference(body, friction, state, finger_v, contact_b, t_end, normal_only=False):
    """Full coordinates with multipliers: sticking (c_b fixed on the finger: 2 constraints) or
    a frictionless finger on a flat face (1 constraint: the finger on the face's line, the
    force along the face's normal, applied at the finger). Baumgarte-stabilised."""
    m, inertia = body.mass, body.moment_of_inertia
    p0 = np.array(contact_b, dtype=float)  # finger at t = 0 (body at the origin, φ = 0)
    vf = np.array(finger_v, dtype=float)
    alpha = 50.0
    nb = np.array([1.0, 0.0])  # the face's inward normal in the body frame (the back face)
    h0 = float(nb @ p0)

    def rhs(t, y):
        x, yy, phi, vx, vy, om = y
        w = ss.friction_wrench(body, friction, vx, vy, om, phi, G)
        fx, fy, mz = float(w.force_x), float(w.force_y), float(w.moment)
        c, s = math.cos(phi), math.sin(phi)
        p = p0 + vf * t
        if not normal_only:
            r = np.array([c * p0[0] - s * p0[1], s * p0[0] + c * p0[1]])
            e = np.array([x, yy]) + r - p
            de = np.array([vx - om * r[1], vy + om * r[0]]) - vf
            # unknowns ax, ay, om_dot, lx, ly
            a = np.array(
                [
                    [m, 0, 0, -1, 0],
                    [0, m, 0, 0, -1],
                    [0, 0, inertia, r[1], -r[0]],
                    [1, 0, -r[1], 0, 0],
                    [0, 1, r[0], 0, 0],
                ],
                dtype=float,
            )
            b = np.array(
                [
                    fx,
                    fy,
                    mz,
                    om * om * r[0] - 2 * alpha * de[0] - alpha**2 * e[0],
                    om * om * r[1] - 2 * alpha * de[1] - alpha**2 * e[1],
                ]
            )
            ax, ay, omd, _, _ = np.linalg.solve(a, b)
        else:
            n = np.array([c * nb[0] - s * nb[1], s * nb[0] + c * nb[1]])
            nperp = np.array([-n[1], n[0]])
            rr = p - np.array([x, yy])
            v = np.array([vx, vy])
            h = float(n @ rr) - h0
            dh = om * float(nperp @ rr) + float(n @ (vf - v))
            rxn = rr[0] * n[1] - rr[1] * n[0]
            # ḧ = ω̇ n⊥·r − ω² n·r + 2ω n⊥·(ṗ − v) − n·a, a = (F + λ n)/m, ω̇ = (M + λ r×n)/I
            k0 = (
                (mz / inertia) * float(nperp @ rr)
                - om * om * float(n @ rr)
                + 2 * om * float(nperp @ (vf - v))
                - float(n @ np.array([fx, fy])) / m
            )
            k1 = rxn / inertia * float(nperp @ rr) - 1.0 / m
            lam = (-2 * alpha * dh - alpha**2 * h - k0) / k1
            ax, ay = (fx + lam * n[0]) / m, (fy + lam * n[1]) / m
            omd = (mz + lam * rxn) / inertia
        return [vx, vy, om, ax, ay, omd]

    y0 = [state.x, state.y, state.phi, state.vx, state.vy, state.omega]
    return solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]


def test_sticking_push_matches_constrained_reference():
    """An off-centre sticking push (μp = 1): the engine's reduced one-degree-of-freedom
    dynamics against the full-coordinate constrained integration."""
    speed, c = 0.3, (-0.1, 0.03)
    finger = PointPusher.constant_velocity(c, (speed, 0.0), 0.4, mu=1.0)
    state = ss.State(vx=speed)  # the contact point moves with the finger: no impact
    tr = simulate_pushed(BOX, ISO, state, finger, 0.4)
    assert set(tr.mode) == {"sticking"} and tr.switches == ()
    ref = _reference(BOX, ISO, state, (speed, 0.0), c, 0.4)
    got = np.array([tr.x[-1], tr.y[-1], tr.phi[-1], tr.vx[-1], tr.vy[-1], tr.omega[-1]])
    np.testing.assert_allclose(got, ref, atol=1e-7)
    assert abs(tr.phi[-1]) > 0.05  # the push turns the box


def test_frictionless_sliding_push_matches_constrained_reference():
    """An off-centre frictionless push (μp = 0): the finger slides along the back face; the
    engine's (φ, s) dynamics against the full-coordinate constrained integration."""
    speed, c = 0.3, (-0.1, 0.02)
    finger = PointPusher.constant_velocity(c, (speed, 0.0), 0.3, mu=0.0)
    state = ss.State(vx=speed)
    tr = simulate_pushed(BOX, ISO, state, finger, 0.3)
    assert set(tr.mode) <= {"sliding_right", "sliding_left"}
    assert "separated" not in tr.mode
    ref = _reference(BOX, ISO, state, (speed, 0.0), c, 0.3, normal_only=True)
    got = np.array([tr.x[-1], tr.y[-1], tr.phi[-1], tr.vx[-1], tr.vy[-1], tr.omega[-1]])
    np.testing.assert_allclose(got, ref, atol=1e-7)
    assert abs(tr.phi[-1]) > 0.02


# ---- energy, symmetry, event accuracy ----------------------------------------------------

CORNER_PATH = [(0.0, -0.1, 0.03), (1.0, 0.3, 0.03), (2.0, 0.3, 0.4)]


@pytest.mark.parametrize(
    ("body", "path", "mu"),
    [
        (BOX, CORNER_PATH, 0.2),  # impact, sliding, sticking, sliding, separation
        (BOX, CORNER_PATH, 0.0),
        (DISK, [(0.0, -0.1, 0.0), (0.5, 0.1, 0.05), (1.2, 0.1, 0.3)], 0.3),
    ],
)
def test_energy_balance_closes(body, path, mu):
    """Pusher work = ΔKE + plane friction + contact slip + impact losses (MODEL §13)."""
    tr = simulate_pushed(body, ISO, ss.State(), PointPusher(path, mu=mu), 2.2)
    assert tr.status == "ok"
    assert len(tr.switches) >= 1
    assert tr.relative_energy_error < 1e-9
    wp = tr.pusher_work[-1]
    balance = (
        tr.kinetic_energy[-1]
        - tr.kinetic_energy[0]
        + tr.friction_work[-1]
        + tr.contact_slip_work[-1]
        + tr.impact_loss[-1]
    )
    assert balance == pytest.approx(wp, rel=1e-9)
    assert np.all(np.diff(tr.friction_work) >= -1e-15 * wp)
    assert np.all(np.diff(tr.contact_slip_work) >= -1e-15 * wp)
    if mu > 0.0 and body is BOX:
        assert {"sticking", "sliding_left", "sliding_right"} & set(tr.mode) >= {"sticking"}
        assert tr.contact_slip_work[-1] > 0.0


def test_mirrored_path_mirrors_the_motion():
    """Mirror the path in the x axis: y → −y, φ → −φ, left ↔ right (an isotropic box is
    symmetric about that axis)."""
    path = np.array(CORNER_PATH)
    mirrored = path * np.array([1.0, 1.0, -1.0])
    a = simulate_pushed(BOX, ISO, ss.State(), PointPusher(path, mu=0.2), 2.0)
    b = simulate_pushed(BOX, ISO, ss.State(), PointPusher(mirrored, mu=0.2), 2.0)
    swap = {"sliding_left": "sliding_right", "sliding_right": "sliding_left"}
    assert [(t, swap.get(m0, m0), swap.get(m1, m1)) for t, m0, m1 in a.switches] == [
        (pytest.approx(t, abs=1e-9), m0, m1) for t, m0, m1 in b.switches
    ]
    assert b.x[-1] == pytest.approx(a.x[-1], abs=1e-10)
    assert b.y[-1] == pytest.approx(-a.y[-1], abs=1e-10)
    assert b.phi[-1] == pytest.approx(-a.phi[-1], abs=1e-10)


def test_switch_times_converge_with_rtol():
    """The located switches are a property of the motion: rtol 1e-9 and 1e-11 agree to 1e-9 s
    (events are located on the dense output to ~1e-15 of the time scale)."""
    finger = PointPusher(CORNER_PATH, mu=0.2)
    loose = simulate_pushed(BOX, ISO, ss.State(), finger, 2.0, rtol=1e-9)
    tight = simulate_pushed(BOX, ISO, ss.State(), finger, 2.0, rtol=1e-11)
    assert [s[1:] for s in loose.switches] == [s[1:] for s in tight.switches]
    assert len(tight.switches) >= 3
    for (ta, *_), (tb, *_) in zip(loose.switches, tight.switches):
        assert abs(ta - tb) < 1e-9
    assert tight.x[-1] == pytest.approx(loose.x[-1], abs=1e-8)


# ---- input errors -------------------------------------------------------------------------

FINGER = PointPusher.constant_velocity((-0.1, 0.0), (0.5, 0.0), 1.0)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"t_end": 0.0}, "t_end"),
        ({"t_end": math.nan}, "t_end"),
        ({"t_end": -1.0}, "t_end"),
        ({"pusher": "finger"}, "pusher"),
        ({"pusher": LinePusher(0.1, [(0.0, 0.0, 0.0, math.pi / 2)])}, "pusher = .*inside"),
        ({"pusher": PointPusher([(0.0, 0.0, 0.0)])}, "inside"),
        ({"state": (0.0, 0.0)}, "state"),
        ({"rtol": 0.0}, "rtol"),
        ({"g": -1.0}, "g"),
        ({"max_steps": 0}, "max_steps"),
        ({"load": "push"}, "load"),
    ],
)
def test_bad_inputs_raise_one_line_errors(kwargs, match):
    args = {"state": ss.State(), "pusher": FINGER, "t_end": 1.0}
    args.update(kwargs)
    state, pusher, t_end = args.pop("state"), args.pop("pusher"), args.pop("t_end")
    with pytest.raises(ValueError, match=match) as info:
        simulate_pushed(BOX, ISO, state, pusher, t_end, **args)
    assert "\n" not in str(info.value)


def test_separation_rows_report_no_pull():
    """At a contact → separated switch λn crosses 0 (MODEL §13): that row reports λ = 0 (the
    cone then holds λt = 0), and no contact row pulls; mirrored path and tensor of the
    cross-check (the finger leaves the rim where the disk comes to rest)."""
    aniso = ss.FrictionTensor(0.2, 0.45, angle=-0.3)
    path = [(0.0, -0.14, -0.02), (1.0, -0.04, -0.02), (2.0, 0.01, -0.1)]
    finger = PointPusher(path, mu=0.3)
    tr = ss.simulate(DISK, aniso, ss.State(), pusher=finger, t_end=2.5)
    c = np.array([m != "separated" for m in tr.mode])
    r = tr.contact_point[c] - np.column_stack((tr.x, tr.y))[c]
    n = -r / np.hypot(*r.T)[:, None]
    ln = np.sum(tr.pusher_force[c] * n, axis=1)
    assert np.min(ln) >= -1e-9 * DISK.mass * G
    knots = {t for t, _, _ in path}  # a finger turning away at a knot leaves with λ ≠ 0
    exits = [t for t, a, b in tr.switches if b == "separated" and a != "separated"]
    exits = [t for t in exits if t not in knots]
    assert exits
    for t_sw in exits:
        k = np.nonzero((tr.t == t_sw) & c)[0]
        np.testing.assert_array_equal(tr.pusher_force[k], 0.0)


def test_corner_hit_sticks_at_the_corner_and_tends_to_quasi_static():
    """A finger hitting the box's corner (−0.1, −0.05) along the diagonal, inside the union of
    the two edges' friction cones (MODEL §13): it sticks at the corner, and as the speed falls
    the final angle approaches push_quasi_static's (an independent engine), with the energy
    balance closed at each speed."""
    length = 0.2 * math.sqrt(2.0)
    gaps = []
    for speed in (0.03, 0.01):
        t_end = length / speed
        finger = PointPusher([(0.0, -0.2, -0.15), (t_end, 0.0, 0.05)], mu=0.3)
        tr = simulate_pushed(BOX, ISO, ss.State(), finger, t_end)
        qs = ss.push_quasi_static(BOX, ISO, finger, [0.0, t_end])
        assert tr.status == qs.status == "ok"
        assert [s[1:] for s in tr.switches] == [("separated", "sticking")]
        assert tr.relative_energy_error < 1e-9
        gaps.append(abs(tr.phi[-1] - qs.phi[-1]))
    assert gaps[0] < 2e-3 and gaps[1] < 2e-4  # 1.2e-3, 1.4e-4: ~ V² (was −0.2758 vs −0.5144)
    assert gaps[1] < gaps[0] / 5.0
