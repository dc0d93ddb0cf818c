"""Quasi-static pushing by a line pusher (MODEL §13) against closed forms, mirror symmetry,
convergence of the located events, and the independent line-integral reference of
``tests/references/quasi_static_reference.py``."""

from __future__ import annotations

import math

import numpy as np
import pytest
import quasi_static_reference as ref

import slidespin as ss
from slidespin.motion.pushers import LinePusher
from slidespin.motion.quasi_static import push_quasi_static

G = 9.81
MU = 0.4
ISO = ss.FrictionTensor(MU, MU)
UP = math.pi / 2  # a pusher along y, pushing along +x


@pytest.fixture(scope="module")
def square():
    return ss.Body(ss.Rectangle(0.2, 0.2), ss.UniformPressure(), mass=2.0)


@pytest.fixture(scope="module")
def rect():
    return ss.Body(ss.Rectangle(0.3, 0.2), ss.UniformPressure(), mass=1.5)


def _tilted(a, mu, t_end=2.0):
    """A pusher turned by ``a`` from the square's face, moving along its own normal."""
    x0, speed = -0.25, 0.15
    c, s = math.cos(a), math.sin(a)
    path = [(0.0, x0, 0.0, UP + a), (t_end, x0 + speed * t_end * c, speed * t_end * s, UP + a)]
    return LinePusher(0.3, path, mu=mu)


def test_centred_face_push_translates(square):
    line = LinePusher(0.3, [(0.0, -0.2, 0.0, UP), (1.0, 0.1, 0.0, UP)], mu=0.5)
    t = np.linspace(0.0, 1.0, 6)
    r = push_quasi_static(square, ISO, line, t)
    assert r.status == "ok"
    np.testing.assert_allclose(r.x, np.maximum(-0.2 + 0.3 * t + 0.1, 0.0), atol=1e-12)
    np.testing.assert_allclose(r.y, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.phi, 0.0, atol=1e-12)
    moving = t > 1.0 / 3.0
    assert set(r.mode[moving]) == {"face_sticking"}
    assert set(r.mode[~moving]) == {"separated"}
    np.testing.assert_allclose(r.force_x[moving], MU * 2.0 * G, rtol=1e-12)
    np.testing.assert_allclose(r.force_y, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.contact_y[moving], 0.0, atol=1e-12)  # resultant through G
    np.testing.assert_allclose(r.switch_times, [1.0 / 3.0], atol=1e-12)
    assert r.switch_modes == ("face_sticking",)
    assert r.modes[r.mode_code[-1]] == "face_sticking"


def test_anisotropic_aligned_tensor_translates(square):
    # a diagonal tensor aligned with the square's symmetry axes: the push along x translates
    # it with the force fx m g (the traction of a translation along x is -p (fx, 0))
    line = LinePusher(0.3, [(0.0, -0.1, 0.0, UP), (1.0, 0.1, 0.0, UP)], mu=0.2)
    r = push_quasi_static(square, ss.FrictionTensor(0.3, 0.7), line, [0.0, 0.5, 1.0])
    np.testing.assert_allclose(r.x, [0.0, 0.1, 0.2], atol=1e-12)
    np.testing.assert_allclose(r.phi, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.force_x, 0.3 * 2.0 * G, rtol=1e-12)


def test_face_sliding_closed_form(square):
    # the pusher slides along the face: the friction force of the translating square is along
    # its velocity, so the resultant on the face edge n + mu t passes through G and the
    # square translates along (1, mu_p) at the pusher's normal speed
    mu_p, vx, vy = 0.2, 0.1, 0.3
    line = LinePusher(0.4, [(0.0, -0.1, 0.0, UP), (1.0, -0.1 + vx, vy, UP)], mu=mu_p)
    t = np.array([0.0, 0.3, 0.6])
    r = push_quasi_static(square, ISO, line, t)
    assert set(r.mode) == {"face_sliding_left"}  # the pusher slides towards +t = +y
    np.testing.assert_allclose(r.vx, vx, rtol=1e-9)
    np.testing.assert_allclose(r.vy, mu_p * vx, rtol=1e-9)
    np.testing.assert_allclose(r.omega, 0.0, atol=1e-9)
    np.testing.assert_allclose(r.y, mu_p * vx * t, atol=1e-10)
    f = MU * 2.0 * G / math.hypot(1.0, mu_p)
    np.testing.assert_allclose(r.force_x, f, rtol=1e-9)
    np.testing.assert_allclose(r.force_y, mu_p * f, rtol=1e-9)
    np.testing.assert_allclose(r.contact_y - r.y, -mu_p * 0.1, atol=1e-10)
    # the resultant, at y_G - 0.02, leaves the shared segment when the pusher's lower end
    # (y = 0.3 t - 0.2) passes it: then the square turns about the pusher's end
    r2 = push_quasi_static(square, ISO, line, [0.0, 1.0])
    t_sw = (0.2 - mu_p * 0.1) / (vy - mu_p * vx)
    np.testing.assert_allclose(r2.switch_times[0], t_sw, atol=1e-9)
    assert r2.switch_modes[0].startswith("end_")


@pytest.mark.parametrize("mu_p", [0.1, 0.8])
def test_tilted_pusher_turns_square_flat(square, mu_p):
    a = 0.3
    line = _tilted(a, mu_p)
    t = np.array([0.0, 1.0, 2.0])
    runs = [push_quasi_static(square, ISO, line, t, rtol=rtol) for rtol in (1e-9, 1e-12)]
    for r in runs:
        assert r.status == "ok"
        # arrival at the corner (-0.1, -0.1): closed form
        np.testing.assert_allclose(
            r.switch_times[0], math.cos(a) - 2.0 / 3.0 * math.sin(a), atol=1e-12
        )
        assert r.switch_modes[0].startswith("vertex_")
        assert r.switch_modes[-1] == "face_sticking"
        assert r.mode[-1] == "face_sticking"
        np.testing.assert_allclose(r.phi[-1], a, atol=1e-9)  # the face lies flat on the pusher
        np.testing.assert_allclose(r.omega[-1], 0.0, atol=1e-12)
    # the located switch times converge with the tolerance
    assert runs[0].switch_modes == runs[1].switch_modes
    np.testing.assert_allclose(runs[0].switch_times, runs[1].switch_times, atol=1e-9)
    np.testing.assert_allclose(runs[0].phi, runs[1].phi, atol=1e-8)


def test_mirror_path_mirrors_motion(square):
    t = np.linspace(0.0, 2.0, 9)
    r = push_quasi_static(square, ISO, _tilted(0.3, 0.1), t)
    m = push_quasi_static(square, ISO, _tilted(-0.3, 0.1), t)
    np.testing.assert_allclose(m.x, r.x, atol=1e-10)
    np.testing.assert_allclose(m.y, -r.y, atol=1e-10)
    np.testing.assert_allclose(m.phi, -r.phi, atol=1e-10)
    np.testing.assert_allclose(m.force_y, -r.force_y, atol=1e-8)
    np.testing.assert_allclose(m.switch_times, r.switch_times, atol=1e-10)
    swap = {"left": "right", "right": "left"}
    mirrored = ["_".join(swap.get(w, w) for w in name.split("_")) for name in r.switch_modes]
    assert list(m.switch_modes) == mirrored
    assert "vertex_sliding_left" in r.switch_modes


def test_vertex_contact_twist_matches_reference(square):
    line = _tilted(0.3, 0.8)
    r = push_quasi_static(square, ISO, line, [0.0, 1.0])
    assert r.mode[1] == "vertex_sticking"
    phi = r.phi[1]
    corner = np.array([-0.1, -0.1])
    c, s = math.cos(phi), math.sin(phi)
    rc = np.array([c * corner[0] - s * corner[1], s * corner[0] + c * corner[1]])
    np.testing.assert_allclose([r.contact_x[1] - r.x[1], r.contact_y[1] - r.y[1]], rc, atol=1e-12)
    shape = ref.PolygonShape([(-0.1, -0.1), (0.1, -0.1), (0.1, 0.1), (-0.1, 0.1)]).rotated(phi)
    vel = 0.15 * np.array([math.cos(0.3), math.sin(0.3)])
    nu_ref, f_ref = ref.sticking_twist(shape, MU, rc, vel)
    np.testing.assert_allclose([r.vx[1], r.vy[1], r.omega[1]], nu_ref, rtol=1e-8, atol=1e-10)
    np.testing.assert_allclose([r.force_x[1], r.force_y[1]], -f_ref * 2.0 * G, rtol=1e-8)


@pytest.mark.parametrize("centre_y", [0.02, 0.06, -0.06])
def test_off_centre_face_push_sticks_iff_segment_covers_g(rect, centre_y):
    # the pusher (length 0.06) on the face x = -0.15 pushes along +x; sticking needs the
    # translation's friction force mu P (-1, 0), which acts through G, balanced by a line
    # load whose resultant lies on the shared segment: iff the segment covers y = 0
    half = 0.03
    path = [(0.0, -0.15, centre_y, UP), (1.0, -0.05, centre_y, UP)]
    line = LinePusher(2 * half, path, mu=1.0)
    r = push_quasi_static(rect, ISO, line, [0.0, 0.5])
    sticks = centre_y - half <= 0.0 <= centre_y + half
    stable = ss.stable_pushing(
        rect, ISO, [(-0.15, max(centre_y - half, -0.1)), (-0.15, centre_y + half)], mu=1.0
    )
    assert stable.contains([1.0, 0.0, 0.0]) == sticks
    if sticks:
        assert set(r.mode) == {"face_sticking"}
        np.testing.assert_allclose(r.phi, 0.0, atol=1e-12)
        np.testing.assert_allclose(r.force_x, MU * 1.5 * G, rtol=1e-12)
        np.testing.assert_allclose(r.contact_y, 0.0, atol=1e-12)
        return
    # it turns about the pusher's end nearer to G, sticking there (mu_p = 1 is ample)
    assert r.mode[0] == "end_sticking"
    end = np.array([-0.15, centre_y - math.copysign(half, centre_y)])
    np.testing.assert_allclose([r.contact_x[0], r.contact_y[0]], end, atol=1e-12)
    shape = ref.PolygonShape([(-0.15, -0.1), (0.15, -0.1), (0.15, 0.1), (-0.15, 0.1)])
    nu_ref, f_ref = ref.sticking_twist(shape, MU, end, np.array([0.1, 0.0]))
    np.testing.assert_allclose([r.vx[0], r.vy[0], r.omega[0]], nu_ref, rtol=1e-8, atol=1e-10)
    np.testing.assert_allclose([r.force_x[0], r.force_y[0]], -f_ref * 1.5 * G, rtol=1e-8)
    assert math.copysign(1.0, r.phi[1]) == -math.copysign(1.0, centre_y)


def test_ellipse_centred_push_translates():
    body = ss.Body(ss.Ellipse(0.15, 0.1), ss.UniformPressure(), mass=1.0)
    line = LinePusher(0.1, [(0.0, -0.2, 0.0, UP), (1.0, 0.0, 0.0, UP)], mu=0.3)
    t = np.array([0.0, 0.5, 1.0])
    r = push_quasi_static(body, ISO, line, t)
    np.testing.assert_allclose(r.x, [0.0, 0.05, 0.15], atol=1e-12)
    np.testing.assert_allclose(r.phi, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.switch_times, [0.25], atol=1e-12)
    assert list(r.mode) == ["separated", "vertex_sticking", "vertex_sticking"]
    np.testing.assert_allclose(r.force_x[1:], MU * G, rtol=1e-12)


def test_end_on_pusher_pokes_the_face(square):
    # a pusher moving along its own line (G on it) touches the face x = -0.1 with its end:
    # a point push through G, which translates the square (force mu m g)
    line = LinePusher(0.1, [(0.0, -0.3, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0)], mu=0.5)
    r = push_quasi_static(square, ISO, line, [0.0, 0.5, 1.0])
    assert list(r.mode[1:]) == ["end_sticking"] * 2
    np.testing.assert_allclose(r.switch_times, [0.5], atol=1e-12)
    np.testing.assert_allclose(r.x, [0.0, 0.0, 0.15], atol=1e-12)
    np.testing.assert_allclose(r.phi, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.force_x[1:], MU * 2.0 * G, rtol=1e-12)


def test_pusher_at_rest_or_leaving_moves_nothing(square):
    line = LinePusher(0.3, [(0.0, -0.1, 0.0, UP), (1.0, -0.3, 0.0, UP)], mu=0.3)
    r = push_quasi_static(square, ISO, line, [0.0, 1.0, 2.0])
    assert set(r.mode) == {"separated"}
    np.testing.assert_allclose(r.x, 0.0, atol=0.0)


@pytest.mark.parametrize(
    ("kwargs", "word"),
    [
        ({"start": (-0.15, 0.0, 0.0)}, "start"),
        ({"times": [0.0, 0.0]}, "times"),
        ({"rtol": 1.0}, "rtol"),
        ({"g": 0.0}, "g"),
        ({"outline": [(0.0, 0.0), (1.0, 0.0)]}, "outline"),
    ],
)
def test_bad_inputs_one_line(square, kwargs, word):
    args = {
        "body": square,
        "friction": ISO,
        "pusher": LinePusher(0.3, [(0.0, -0.2, 0.0, UP), (1.0, 0.0, 0.0, UP)]),
        "times": [0.0, 1.0],
    }
    args.update(kwargs)
    with pytest.raises(ValueError, match="valid") as err:
        push_quasi_static(**args)
    assert word in str(err.value)
    assert "\n" not in str(err.value)


def test_turning_pusher_carries_square_rigidly(square):
    # the pusher turns about its centre while advancing; the exact stable-pushing set of the
    # face (slidespin.stable_pushing: the friction wrench and NNLS, not this engine) contains
    # the twist of moving with it, so G keeps its place in the pusher's frame
    turn = 0.2
    line = LinePusher(0.3, [(0.0, -0.1, 0.0, UP), (1.0, 0.0, 0.0, UP + turn)], mu=0.8)
    face = [(-0.1, -0.1), (-0.1, 0.1)]
    stable = ss.stable_pushing(square, ISO, face, mu=0.8)
    ell = square.length_unit
    assert stable.contains([0.1, 0.1 * turn, turn * ell])  # (v_G, ω ℓ) at t = 0
    t = np.linspace(0.0, 1.0, 5)
    r = push_quasi_static(square, ISO, line, t)
    assert set(r.mode) == {"face_sticking"}
    th = turn * t
    cx = -0.1 + 0.1 * t
    np.testing.assert_allclose(r.x, cx + 0.1 * np.cos(th), atol=1e-9)
    np.testing.assert_allclose(r.y, 0.1 * np.sin(th), atol=1e-9)
    np.testing.assert_allclose(r.phi, th, atol=1e-9)


def test_turning_about_pusher_end_follows_a_finger_there(rect):
    # while the pusher's end sticks on the face, it is a finger moving with the pusher: the
    # point-pusher engine (validated against the line-integral reference in
    # test_push_quasi_static.py) gives the same poses; the line pusher's end path is
    # (-0.15 + 0.1 t, 0.03)
    line = LinePusher(0.06, [(0.0, -0.15, 0.06, UP), (1.0, -0.05, 0.06, UP)], mu=1.0)
    finger = ss.PointPusher([(0.0, -0.15, 0.03), (1.0, -0.05, 0.03)], mu=1.0)
    t = np.linspace(0.0, 1.0, 6)
    r = push_quasi_static(rect, ISO, line, t)
    p = push_quasi_static(rect, ISO, finger, t)
    assert set(r.mode) == {"end_sticking"} and set(p.mode) == {"sticking"}
    np.testing.assert_allclose(r.x, p.x, atol=1e-9)
    np.testing.assert_allclose(r.y, p.y, atol=1e-9)
    np.testing.assert_allclose(r.phi, p.phi, atol=1e-9)
    np.testing.assert_allclose(r.force_x, p.force_x, rtol=1e-8)


@pytest.mark.parametrize("mu_p", [2.0, 0.5])
def test_oblique_face_push_turns_about_corner_or_slides(rect, mu_p):
    # a long pusher on the face x = -0.15 moving along (1, 1): moving with it needs the
    # friction force of that translation, through G along (1, 1), which crosses the face at
    # y = -0.15, below the face's corner (-0.15, -0.1): no sticking on the face. With
    # mu_p = 2 the corner sticks and the body turns about it (twist from the reference);
    # with mu_p = 0.5 the face slides: translation along (1, mu_p), resultant at y = -0.15 mu_p
    line = LinePusher(0.5, [(0.0, -0.15, 0.0, UP), (2.0, 0.05, 0.2, UP)], mu=mu_p)
    r = push_quasi_static(rect, ISO, line, [0.0, 1.0])
    if mu_p == 0.5:
        assert set(r.mode) == {"face_sliding_left"}
        np.testing.assert_allclose([r.vx[0], r.vy[0], r.omega[0]], [0.1, 0.05, 0.0], atol=1e-10)
        np.testing.assert_allclose(r.contact_y - r.y, -0.15 * mu_p, atol=1e-10)
        return
    assert set(r.mode) == {"vertex_sticking"}
    corner = np.array([-0.15, -0.1])
    np.testing.assert_allclose([r.contact_x[0], r.contact_y[0]], corner, atol=1e-12)
    shape = ref.PolygonShape([(-0.15, -0.1), (0.15, -0.1), (0.15, 0.1), (-0.15, 0.1)])
    nu_ref, f_ref = ref.sticking_twist(shape, MU, corner, np.array([0.1, 0.1]))
    np.testing.assert_allclose([r.vx[0], r.vy[0], r.omega[0]], nu_ref, rtol=1e-8, atol=1e-10)
    np.testing.assert_allclose([r.force_x[0], r.force_y[0]], -f_ref * 1.5 * G, rtol=1e-8)
    assert r.phi[1] < 0.0  # turns clockwise about the lower corner
