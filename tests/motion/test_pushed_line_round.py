"""A line pusher on round outlines (disks, ellipses; MODEL §13): closed forms, a constrained
reference written apart from the engine, the end contact against the finger engine, the
quasi-static limit against the quasi-static line engine, the energy balance, mirror symmetry
and the contact's geometry.

The reference is a Newton–Euler integration in full coordinates (x, y, φ, vx, vy, ω) for a
disk whose centre is off G, on a translating face: the contact at the disk's centre less R n,
the normal constraint (G + q0 − p)·n = R and, when rolling, the slip (Ġ + ω ẑ×r − V)·t = 0,
both held by Lagrange multipliers (Baumgarte-stabilised), with the public
``friction_wrench``. The engine instead works in reduced coordinates (φ, σ) on the outline's
support function.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from test_push_crosschecks import _hermite

import slidespin as ss

G = 9.81
ISO = ss.FrictionTensor(0.3, 0.3)
ANISO = ss.FrictionTensor(0.2, 0.45, angle=0.3)
DISK = ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0)
#: G at (0.02, 0.01) from the disk's centre
OFFSET_DISK = ss.Body(ss.Disk(0.1), ss.LinearPressure(0.02, 0.01), mass=1.0)
ELLIPSE = ss.Body(ss.Ellipse(0.1, 0.06), ss.UniformPressure(), mass=1.0)
LINEAR = ss.Body(
    ss.Ellipse(0.1, 0.08), ss.LinearPressure(0.015, 0.0), mass=1.0, moment_of_inertia=0.004
)
BODIES = {"disk": DISK, "offset-disk": OFFSET_DISK, "ellipse": ELLIPSE, "linear": LINEAR}
#: a turning pusher with knots, arriving from the left off-centre
TURN = [(0, -0.15, 0.03, math.pi / 2), (1.0, 0.0, 0.05, math.pi / 2 + 0.4), (2.0, 0.1, 0.2, 1.2)]


def _contact_rows(tr):
    return np.array([m != "separated" for m in tr.mode])


def test_centred_push_of_a_disk_translates_with_mu_m_g():
    """A face pushing a resting disk along the normal through G at V: a plastic impact m V,
    rolling-free sticking with λ = μ m g and no rotation; after the pusher stops the disk
    slides V²/(2 μ g) further (closed forms)."""
    speed, t1 = 0.3, 1.0
    pusher = ss.LinePusher.constant_velocity(
        (-0.1, 0.02, math.pi / 2), (speed, 0.0, 0.0), t1, length=0.1, mu=0.5
    )
    tr = ss.simulate(DISK, ISO, ss.State(), pusher=pusher, t_end=1.5)
    assert tr.status == "ok", tr.message
    assert [m for _, _, m in tr.switches] == ["vertex_sticking", "separated"]
    assert tr.switches[1][0] == pytest.approx(t1, abs=1e-12)
    ((t_imp, jx, jy, loss),) = tr.impacts
    assert (t_imp, jx, jy) == pytest.approx((0.0, DISK.mass * speed, 0.0), abs=1e-14)
    assert loss == pytest.approx(0.5 * DISK.mass * speed**2, rel=1e-12)
    stick = np.flatnonzero([m == "vertex_sticking" for m in tr.mode])
    np.testing.assert_allclose(tr.pusher_force[stick[1:], 0], 0.3 * DISK.mass * G, rtol=1e-10)
    np.testing.assert_allclose(tr.pusher_force[stick, 1], 0.0, atol=1e-10)
    np.testing.assert_allclose(tr.phi, 0.0, atol=1e-12)
    # the contact point: the disk's leftmost point, at the pusher's height 0.02 m off centre
    np.testing.assert_allclose(tr.contact_point[stick, 0], tr.x[stick] - 0.1, atol=1e-12)
    np.testing.assert_allclose(tr.contact_point[stick, 1], 0.0, atol=1e-12)
    assert tr.x[-1] == pytest.approx(speed * t1 + speed**2 / (2 * 0.3 * G), rel=1e-9)
    assert tr.relative_energy_error < 1e-9


def _disk_reference(body, friction, mu_p, vel, t_end, rolling):
    """The off-centre disk on a vertical face moving at ``vel``: full coordinates, the
    multipliers (λn, λt) at the contact; rolling (λt from the slip constraint) or sliding
    (λt = −μp λn sign(slip)). G at the origin, φ = 0, the face touching at t = 0."""
    m, inertia = body.mass, body.moment_of_inertia
    radius = 0.1
    c0 = -np.asarray(body.mass_centre, float)  # the disk's centre from G, body frame
    n, t_dir = np.array([1.0, 0.0]), np.array([0.0, 1.0])
    p0 = np.array([c0[0] - radius, 0.0])
    alpha = 40.0

    def rhs(t, y):
        x, yy, phi, vx, vy, om = y
        w = ss.friction_wrench(body, friction, vx, vy, om, phi, G)
        c, s = math.cos(phi), math.sin(phi)
        q0 = np.array([c * c0[0] - s * c0[1], s * c0[0] + c * c0[1]])
        r = q0 - radius * n
        zq, zr = np.array([-q0[1], q0[0]]), np.array([-r[1], r[0]])
        gv = np.array([vx, vy])
        gap = (np.array([x, yy]) + q0 - p0 - vel * t) @ n - radius
        gap_rate = (gv + om * zq - vel) @ n
        slip = (gv + om * zr - vel) @ t_dir
        a = np.zeros((5, 5))
        b = np.zeros(5)
        a[0, 0] = a[1, 1] = m
        a[2, 2] = inertia
        a[:3, 3] = -np.array([n[0], n[1], r[0] * n[1] - r[1] * n[0]])
        a[:3, 4] = -np.array([t_dir[0], t_dir[1], r[0] * t_dir[1] - r[1] * t_dir[0]])
        b[:3] = [float(w.force_x), float(w.force_y), float(w.moment)]
        a[3, :2], a[3, 2] = n, zq @ n
        b[3] = om * om * (q0 @ n) - 2 * alpha * gap_rate - alpha**2 * gap
        if rolling:
            a[4, :2], a[4, 2] = t_dir, zr @ t_dir
            b[4] = om * om * (q0 @ t_dir) - alpha * slip
        else:
            a[4, 3], a[4, 4] = mu_p * math.copysign(1.0, slip), 1.0
        sol = np.linalg.solve(a, b)
        return [vx, vy, om, *sol[:3]]

    y0 = [0.0, 0.0, 0.0, vel[0], vel[1] if rolling else 0.0, 0.0]
    ref = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=1e-12, atol=1e-14)
    return ref.y[:, -1], p0


@pytest.mark.parametrize(
    ("mu_p", "vel", "rolling", "mode"),
    [
        (2.0, (0.3, 0.1), True, "vertex_sticking"),
        (0.0, (0.3, 0.1), False, "vertex_sliding_left"),
        (0.2, (0.3, -0.6), False, "vertex_sliding_right"),
    ],
)
@pytest.mark.parametrize("friction", [ISO, ANISO], ids=["iso", "aniso"])
def test_rolling_and_sliding_match_the_constrained_reference(mu_p, vel, rolling, mode, friction):
    """An off-centre disk on a translating face (no impact: the disk starts with the face's
    normal velocity): rolling without slip, frictionless sliding and sliding against μp,
    against the full-coordinate reference at 0.3 s."""
    vel = np.array(vel)
    ref, p0 = _disk_reference(OFFSET_DISK, friction, mu_p, vel, 0.3, rolling)
    pusher = ss.LinePusher.constant_velocity(
        (p0[0], 0.0, math.pi / 2), (vel[0], vel[1], 0.0), 2.0, length=1.0, mu=mu_p
    )
    start = ss.State(vx=vel[0], vy=vel[1] if rolling else 0.0)
    tr = ss.simulate(OFFSET_DISK, friction, start, pusher=pusher, t_end=0.3)
    assert tr.status == "ok" and not tr.impacts
    assert set(tr.mode) == {mode}
    got = [tr.x[-1], tr.y[-1], tr.phi[-1], tr.vx[-1], tr.vy[-1], tr.omega[-1]]
    np.testing.assert_allclose(got, ref, atol=1e-9)
    assert abs(tr.phi[-1]) > 1e-3  # the disk turned: the test is not a translation
    assert tr.relative_energy_error < 1e-9


def test_end_contact_is_a_finger_at_the_end():
    """A translating pusher whose end meets an ellipse (its face never touches): the same
    motion as a finger on the end's path (the finger engine, written apart)."""
    length = 0.04
    rows = np.array([(0.0, -0.15, 0.07, math.pi / 2), (1.5, 0.05, 0.07, math.pi / 2)])
    line = ss.LinePusher(length, rows, mu=0.4)
    finger = ss.PointPusher(
        np.column_stack((rows[:, 0], rows[:, 1], rows[:, 2] - 0.5 * length)), mu=0.4
    )
    a = ss.simulate(ELLIPSE, ANISO, ss.State(), pusher=line, t_end=2.0)
    b = ss.simulate(ELLIPSE, ANISO, ss.State(), pusher=finger, t_end=2.0)
    assert a.status == b.status == "ok"
    assert [m.removeprefix("end_") for _, _, m in a.switches] == [m for _, _, m in b.switches]
    for (ta, *_), (tb, *_) in zip(a.switches, b.switches):
        assert ta == pytest.approx(tb, abs=1e-9)
    tq = np.linspace(a.switches[0][0] + 0.01, 2.0, 12)  # after the arrival's impact
    np.testing.assert_allclose(_hermite(a, tq), _hermite(b, tq), atol=1e-8)
    assert a.impact_loss[-1] == pytest.approx(b.impact_loss[-1], rel=1e-9)


@pytest.mark.parametrize("friction", [ISO, ANISO], ids=["iso", "aniso"])
def test_slow_push_tends_to_quasi_static(friction):
    """A rotated ellipse pushed off-centre by a sticking face, the same 6 cm at V = 0.1 …
    0.003 m/s: the dynamic poses tend to ``push_quasi_static``'s (the quasi-static line
    engine, written apart) like V², below 1e-5 ℓ at 3 mm/s."""
    phi0, a, b = 0.4, 0.1, 0.06
    reach = math.hypot(a * math.cos(phi0), b * math.sin(phi0))  # the support along −x
    errs = []
    for speed in (0.1, 0.03, 0.01, 0.003):
        t_end = 0.06 / speed
        path = [(0.0, -reach, 0.0, math.pi / 2), (t_end, 0.06 - reach, 0.0, math.pi / 2)]
        pusher = ss.LinePusher(0.1, path, mu=0.5)
        tr = ss.simulate(ELLIPSE, friction, ss.State(phi=phi0), pusher=pusher, t_end=t_end)
        assert tr.status == "ok" and set(tr.mode[1:]) == {"vertex_sticking"}  # after the impact
        tq = np.linspace(0.0, t_end, 7)[1:]
        qs = ss.push_quasi_static(ELLIPSE, friction, pusher, np.r_[0.0, tq], start=(0, 0, phi0))
        assert qs.status == "ok" and set(qs.mode) == {"vertex_sticking"}
        x, y, phi = _hermite(tr, tq)
        errs.append(
            max(np.max(np.abs(x - qs.x[1:])) / a, np.max(np.abs(y - qs.y[1:])) / a)
            + np.max(np.abs(phi - qs.phi[1:]))
        )
    errs = np.array(errs)
    assert np.all(errs[:-1] / errs[1:] > 5.0)  # ~ (10/3)² = 11 per step
    assert errs[-1] < 1e-5


@pytest.mark.parametrize("mu", [0.0, 0.3, 1.0])
@pytest.mark.parametrize("friction", [ISO, ANISO], ids=["iso", "aniso"])
@pytest.mark.parametrize("name", list(BODIES))
def test_energy_balance_and_contact_geometry(name, friction, mu):
    """A turning pusher with knots: pusher work = ΔKE + friction + slip + impact losses to
    1e-9; every contact row on the outline and on the pusher's segment; λ in the cone and on
    its edge while sliding."""
    body = BODIES[name]
    pusher = ss.LinePusher(0.08, TURN, mu=mu)
    tr = ss.simulate(body, friction, ss.State(), pusher=pusher, t_end=2.5)
    assert tr.status == "ok", tr.message
    assert len(tr.switches) >= 2
    assert tr.relative_energy_error < 1e-9
    c = _contact_rows(tr)
    pose = pusher.pose(tr.t[c])
    e = np.column_stack((np.cos(pose[:, 2]), np.sin(pose[:, 2])))
    rel = tr.contact_point[c] - pose[:, :2]
    np.testing.assert_allclose(rel[:, 0] * e[:, 1] - rel[:, 1] * e[:, 0], 0.0, atol=1e-12)
    assert np.all(np.abs(np.sum(rel * e, axis=1)) <= 0.04 * (1 + 1e-9))
    # on the outline: the patch's implicit equation in the body frame
    ph = tr.phi[c]
    d = tr.contact_point[c] - np.column_stack((tr.x, tr.y))[c]
    bx = np.cos(ph) * d[:, 0] + np.sin(ph) * d[:, 1] + body.mass_centre[0]
    by = -np.sin(ph) * d[:, 0] + np.cos(ph) * d[:, 1] + body.mass_centre[1]
    axes = (0.1, 0.1) if "disk" in name else (0.1, 0.06 if name == "ellipse" else 0.08)
    np.testing.assert_allclose(np.hypot(bx / axes[0], by / axes[1]), 1.0, atol=1e-10)
    # λ: along the outline's inward normal and in the cone (no row at a separation)
    nx, ny = bx / axes[0] ** 2, by / axes[1] ** 2
    nb = -np.column_stack((nx, ny)) / np.hypot(nx, ny)[:, None]
    n = np.column_stack(
        (
            np.cos(ph) * nb[:, 0] - np.sin(ph) * nb[:, 1],
            np.sin(ph) * nb[:, 0] + np.cos(ph) * nb[:, 1],
        )
    )
    lam = tr.pusher_force[c]
    ln = np.sum(lam * n, axis=1)
    lt = n[:, 0] * lam[:, 1] - n[:, 1] * lam[:, 0]
    scale = body.mass * G
    assert np.all(ln >= -1e-9 * scale)
    assert np.all(np.abs(lt) <= mu * ln + 1e-9 * scale)
    sliding = np.array(["sliding" in m for m in np.array(tr.mode)[c]])
    np.testing.assert_allclose(np.abs(lt[sliding]), mu * ln[sliding], atol=1e-9 * scale)


def test_rolling_off_the_face_and_back():
    """A face rolling an ellipse towards its end: the contact passes to the end
    (``vertex_*`` → ``end_*``) at σ = h, and the energy still closes."""
    path = [
        (0, -0.15, 0.03, math.pi / 2),
        (1.0, 0.0, 0.05, math.pi / 2 + 0.4),
        (2.0, 0.1, 0.2, 1.2),
    ]
    tr = ss.simulate(LINEAR, ISO, ss.State(), pusher=ss.LinePusher(0.08, path, mu=0.0), t_end=2.5)
    kinds = [(a.split("_")[0], b.split("_")[0]) for _, a, b in tr.switches]
    assert ("vertex", "end") in kinds and ("end", "vertex") in kinds
    for t, a, b in tr.switches:
        if (a.split("_")[0], b.split("_")[0]) in (("vertex", "end"), ("end", "vertex")):
            k = int(np.flatnonzero(tr.t == t)[-1])
            pose = pusher_pose = ss.LinePusher(0.08, path).pose(t)
            sig = (tr.contact_point[k] - pusher_pose[:2]) @ (math.cos(pose[2]), math.sin(pose[2]))
            assert abs(sig) == pytest.approx(0.04, abs=1e-9)
    assert tr.relative_energy_error < 1e-9


def mirror_check(body, friction, rows, t_end):
    """Reflect the line pusher's path (rows (t, x, y, angle)) and the tensor in the x axis,
    a symmetry line of ``body`` through G: y → −y, φ → −φ, left and right swap."""
    mirrored = ss.FrictionTensor(friction.fx, friction.fy, -friction.f, angle=-friction.angle)
    rows = np.array(rows, float)
    mrows = rows * np.array([1.0, 1.0, -1.0, -1.0])
    a = ss.simulate(body, friction, ss.State(), pusher=ss.LinePusher(0.08, rows, 0.3), t_end=t_end)
    b = ss.simulate(body, mirrored, ss.State(), pusher=ss.LinePusher(0.08, mrows, 0.3), t_end=t_end)
    assert a.status == b.status == "ok" and len(a.switches) >= 2

    def swap(m):
        return m.replace("left", "L").replace("right", "left").replace("L", "right")

    assert [(round(t, 9), swap(m)) for t, _, m in a.switches] == [
        (round(t, 9), m) for t, _, m in b.switches
    ]
    tq = np.linspace(0.05, t_end, 15)
    xa, ya, pa = _hermite(a, tq)
    xb, yb, pb = _hermite(b, tq)
    np.testing.assert_allclose(np.c_[xa, -ya, -pa], np.c_[xb, yb, pb], atol=1e-9)


@pytest.mark.parametrize("tensor", ["iso", "aniso"])
def test_mirrored_path_mirrors_the_motion(tensor):
    """An ellipse symmetric about the x axis (G on it, linear pressure along x)."""
    mirror_check(LINEAR, ISO if tensor == "iso" else ANISO, TURN, 2.5)
