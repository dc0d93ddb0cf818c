"""Quasi-static pushing by a finger (MODEL §13) against closed forms, symmetry, convergence
and the independent line-integral reference of ``tests/references/quasi_static_reference.py``."""

from __future__ import annotations

import math

import numpy as np
import pytest
import quasi_static_reference as ref

import slidespin as ss
from slidespin.motion.pushers import LinePusher, PointPusher
from slidespin.motion.quasi_static import push_quasi_static

G = 9.81
MU = 0.4


@pytest.fixture(scope="module")
def box():
    return ss.Body(ss.Rectangle(0.4, 0.3), ss.UniformPressure(), mass=2.0)


@pytest.fixture(scope="module")
def disk():
    return ss.Body(ss.Disk(0.1), ss.UniformPressure(), mass=1.0)


ISO = ss.FrictionTensor(MU, MU)


def test_push_through_g_translates_box(box):
    # finger on the axis of symmetry: arrives at the face x = -0.2 at t = 0.5 s, then pushes
    finger = PointPusher([(0.0, -0.3, 0.0), (2.5, 0.2, 0.0)], mu=0.3)
    t = np.linspace(0.0, 2.5, 11)
    r = push_quasi_static(box, ISO, finger, t)
    assert r.status == "ok"
    xf = -0.3 + 0.2 * t
    np.testing.assert_allclose(r.x, np.maximum(xf + 0.2, 0.0), atol=1e-12)
    np.testing.assert_allclose(r.y, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.phi, 0.0, atol=1e-12)
    moving = t >= 0.5
    assert list(r.mode[~moving]) == ["separated"] * int((~moving).sum())
    assert set(r.mode[moving]) == {"sticking"}
    np.testing.assert_allclose(r.force_x[moving], MU * 2.0 * G, rtol=1e-12)
    np.testing.assert_allclose(r.force_y, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.switch_times, [0.5], atol=1e-12)
    assert r.switch_modes == ("sticking",)
    np.testing.assert_allclose(r.contact_x[moving], xf[moving], atol=1e-12)


def _rim_push(angle_normal, angle_push, mu_p):
    """A finger on the unit-disk rim at polar angle ``angle_normal`` + π (so the inward normal
    points along angle_normal), moving along angle_push."""
    n = np.array([math.cos(angle_normal), math.sin(angle_normal)])
    c = -0.1 * n
    vel = 0.05 * np.array([math.cos(angle_push), math.sin(angle_push)])
    finger = PointPusher([(0.0, *c), (1.0, *(c + vel))], mu=mu_p)
    return finger, c, n, vel


def test_disk_sticking_twist_matches_reference(disk):
    finger, c, n, vel = _rim_push(0.2, 0.7, 2.0)
    r = push_quasi_static(disk, ISO, finger, [0.0, 0.1])
    assert r.mode[0] == "sticking"
    nu_ref, f_ref = ref.sticking_twist(ref.DiskShape(0.1), MU, c, vel)
    got = np.array([r.vx[0], r.vy[0], r.omega[0]])
    np.testing.assert_allclose(got, nu_ref, rtol=1e-9, atol=1e-11)
    np.testing.assert_allclose([r.force_x[0], r.force_y[0]], -f_ref * G, rtol=1e-9)


def test_disk_sliding_twist_matches_reference(disk):
    finger, c, n, vel = _rim_push(0.2, 0.9, 0.1)
    r = push_quasi_static(disk, ISO, finger, [0.0, 0.1])
    assert r.mode[0] in ("sliding_left", "sliding_right")
    sigma = 1.0 if r.mode[0] == "sliding_left" else -1.0
    nu_st, _ = ref.sticking_twist(ref.DiskShape(0.1), MU, c, vel)
    guess = np.array([-nu_st[1], nu_st[0]]) / nu_st[2]
    nu_ref, f_ref, _ = ref.sliding_twist(ref.DiskShape(0.1), MU, c, n, vel, 0.1, sigma, guess)
    got = np.array([r.vx[0], r.vy[0], r.omega[0]])
    np.testing.assert_allclose(got, nu_ref, rtol=1e-8, atol=1e-11)
    lam = np.array([r.force_x[0], r.force_y[0]])
    t = np.array([-n[1], n[0]])
    assert lam @ t == pytest.approx(sigma * 0.1 * (lam @ n), rel=1e-10)


def test_box_twists_match_reference_along_path(box):
    finger = PointPusher([(0.0, -0.2, 0.06), (1.0, 0.0, 0.1)], mu=1.0)
    t = np.array([0.0, 0.5, 1.0])
    r = push_quasi_static(box, ISO, finger, t)
    assert set(r.mode) == {"sticking"}
    verts = [(-0.2, -0.15), (0.2, -0.15), (0.2, 0.15), (-0.2, 0.15)]
    for k in (0, 2):
        shape = ref.PolygonShape(verts).rotated(r.phi[k])
        c = np.array([r.contact_x[k] - r.x[k], r.contact_y[k] - r.y[k]])
        nu_ref, _ = ref.sticking_twist(shape, MU, c, np.array([0.2, 0.04]))
        got = np.array([r.vx[k], r.vy[k], r.omega[k]])
        np.testing.assert_allclose(got, nu_ref, rtol=1e-8, atol=1e-10)
    # the finger stays on the body point it touched first (sticking)
    pb = [
        np.array([[math.cos(p), math.sin(p)], [-math.sin(p), math.cos(p)]])
        @ (np.array([cx - x, cy - y]))
        for p, x, y, cx, cy in zip(r.phi, r.x, r.y, r.contact_x, r.contact_y)
    ]
    np.testing.assert_allclose(pb, [[-0.2, 0.06]] * 3, atol=1e-9)


def test_mirror_path_mirrors_motion(box):
    path = [(0.0, -0.25, 0.05), (1.0, 0.0, 0.08), (2.0, 0.2, -0.05)]
    t = np.linspace(0.0, 2.0, 9)
    a = push_quasi_static(box, ISO, PointPusher(path, mu=0.3), t)
    b = push_quasi_static(box, ISO, PointPusher([(s, x, -y) for s, x, y in path], mu=0.3), t)
    np.testing.assert_allclose(b.x, a.x, atol=1e-9)
    np.testing.assert_allclose(b.y, -a.y, atol=1e-9)
    np.testing.assert_allclose(b.phi, -a.phi, atol=1e-9)
    swap = {"sliding_left": "sliding_right", "sliding_right": "sliding_left"}
    assert [swap.get(m, m) for m in a.mode] == list(b.mode)
    assert np.any(np.abs(a.phi) > 0.05)  # the push turns the box


def test_frictionless_finger_translates_disk(disk):
    finger = PointPusher([(0.0, -0.1, 0.03), (2.0, 0.2, 0.05)], mu=0.0)
    t = np.linspace(0.0, 2.0, 9)
    r = push_quasi_static(disk, ISO, finger, t)
    moving = r.mode != "separated"
    # the frictionless finger slides round the rim until it moves tangentially, then leaves
    assert moving.sum() >= 3 and r.mode[-1] == "separated"
    np.testing.assert_allclose(r.phi, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.omega[moving], 0.0, atol=1e-12)
    lam = np.column_stack((r.force_x, r.force_y))[moving]
    toward_g = np.column_stack((r.x - r.contact_x, r.y - r.contact_y))[moving]
    cross = lam[:, 0] * toward_g[:, 1] - lam[:, 1] * toward_g[:, 0]
    np.testing.assert_allclose(cross, 0.0, atol=1e-10)
    np.testing.assert_allclose(np.hypot(*lam.T), MU * 1.0 * G, rtol=1e-10)
    np.testing.assert_allclose(np.hypot(*toward_g.T), 0.1, rtol=1e-9)


def test_halving_tolerance_converges(box):
    finger = PointPusher([(0.0, -0.25, 0.07), (1.5, 0.1, 0.0), (3.0, 0.3, 0.1)], mu=0.25)
    t = np.linspace(0.0, 3.0, 7)
    a = push_quasi_static(box, ISO, finger, t, rtol=1e-10)
    b = push_quasi_static(box, ISO, finger, t, rtol=5e-11)
    for k in ("x", "y", "phi"):
        np.testing.assert_allclose(getattr(a, k), getattr(b, k), atol=1e-8 * 0.25)
    assert a.switch_times.size >= 2
    np.testing.assert_allclose(a.switch_times, b.switch_times, atol=1e-8)


def test_start_pose_and_separation_return(box):
    # finger pushes, retreats (separated: the box stays), returns and touches again
    finger = PointPusher([(0.0, 0.8, 0.0), (1.0, 0.9, 0.0), (2.0, 0.7, 0.0), (3.0, 1.1, 0.0)])
    t = np.array([0.0, 1.0, 1.5, 2.0, 2.5, 3.0])
    r = push_quasi_static(box, ISO, finger, t, start=(1.0, 0.0, math.pi))
    # turned by π, the box's face x = -0.2 faces +x: the finger at 0.8 touches it at once
    np.testing.assert_allclose(r.x, [1.0, 1.1, 1.1, 1.1, 1.1, 1.3], atol=1e-12)
    np.testing.assert_allclose(r.phi, math.pi, atol=1e-12)
    assert list(r.mode) == [
        "sticking",
        "separated",
        "separated",
        "separated",
        "sticking",
        "sticking",
    ]
    np.testing.assert_allclose(r.switch_times, [1.0, 2.5], atol=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "word"),
    [
        ({"times": [0.0, 1.0, 1.0]}, "times[2]"),
        ({"times": [0.0, float("nan")]}, "times"),
        ({"times": [[0.0, 1.0]]}, "times"),
        ({"start": (0.0, 0.0)}, "start"),
        ({"start": (0.0, 0.0, float("inf"))}, "start"),
        ({"pusher": "finger"}, "pusher"),
        ({"body": 3}, "body"),
        ({"friction": 0.3}, "friction"),
        ({"start": (-0.25, 0.0, 0.0)}, "inside"),
        ({"rtol": 0.0}, "rtol"),
    ],
)
def test_bad_inputs_name_the_parameter(box, kwargs, word):
    args = {
        "body": box,
        "friction": ISO,
        "pusher": PointPusher([(0.0, -0.3, 0.0), (1.0, 0.0, 0.0)]),
        "times": [0.0, 1.0],
    }
    args.update(kwargs)
    with pytest.raises(ValueError, match="valid") as err:
        push_quasi_static(**args)
    assert word in str(err.value)
    assert "\n" not in str(err.value)


def test_line_pusher_dispatched(box):
    # a line pusher goes to slidespin.motion.quasi_static_line (tested in
    # test_push_line_quasi_static.py), with the same result type
    line = LinePusher(0.2, [(0.0, -0.3, 0.0, math.pi / 2), (1.0, 0.0, 0.0, math.pi / 2)])
    r = push_quasi_static(box, ISO, line, [0.0, 0.5])
    assert r.status == "ok" and r.mode[-1] == "face_sticking" and r.modes[0] == "separated"
