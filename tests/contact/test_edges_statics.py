"""Statics inputs: the package's own ``Load`` (and any object with its ``wrench`` method) as
the applied load, and a slope too steep to judge, blamed on the slope.

Independent truths: the applied wrench of a load written out here (the force turned by the
body angle when given in the body frame, its moment about G r′ × Q + T), the closed form
λ* = P/|𝔽⁻¹ W| of a force through G, and tan α ≤ μ on a slope.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss
from slidespin.contact import statics
from slidespin.contact.incline import Incline

G = 9.81
BOX = ss.Body(ss.Rectangle(0.4, 0.3), ss.UniformPressure(), mass=2.0)
FR = ss.FrictionTensor(0.3, 0.5, 0.05, angle=0.2)


def _wrench_of(force, torque, frame, at, phi, g_point):
    """(Qx, Qy, M about G) of a force and torque, written out from MODEL §11."""
    c, s = math.cos(phi), math.sin(phi)
    q = np.array(force, float)
    if frame == "body":
        q = np.array([c * q[0] - s * q[1], s * q[0] + c * q[1]])
    m = torque
    if at is not None:
        d = np.array(at) - np.array(g_point)
        r = np.array([c * d[0] - s * d[1], s * d[0] + c * d[1]])
        m += r[0] * q[1] - r[1] * q[0]
    return (q[0], q[1], m)


@pytest.mark.parametrize(
    "force, torque, frame, at, phi",
    [
        ((3.0, 1.0), 0.0, "plane", None, 0.0),
        ((3.0, 1.0), 0.2, "body", None, 0.9),
        ((2.0, -1.0), -0.1, "body", (0.1, 0.05), -0.4),
        ((0.0, 4.0), 0.0, "plane", (-0.15, 0.1), 2.0),
    ],
)
def test_a_load_is_the_wrench_it_applies(force, torque, frame, at, phi):
    load = ss.Load(force=force, torque=torque, frame=frame, at=at)
    w = _wrench_of(force, torque, frame, at, phi, BOX.mass_centre)
    lam = statics.load_factor(BOX, FR, load, phi, g=G)
    assert lam == pytest.approx(statics.load_factor(BOX, FR, w, phi, g=G), rel=1e-12)
    assert statics.can_stick(BOX, FR, load, phi, g=G) == (lam >= 1.0)
    o1, o2 = statics.onset(BOX, FR, load, phi, g=G), statics.onset(BOX, FR, w, phi, g=G)
    assert (o1 is None) == (o2 is None)


def test_a_load_through_g_closed_form_and_a_load_in_time():
    # a force through G: λ* = P/|𝔽⁻¹ Q| (any patch with G over its pressure centroid)
    q = np.array([4.0, -2.5])
    exact = BOX.mass * G / np.linalg.norm(np.linalg.solve(FR.matrix, q))
    assert statics.load_factor(BOX, FR, ss.Load(force=tuple(q)), g=G) == pytest.approx(exact)
    ramp = ss.Load(force=lambda t: (t * q[0], t * q[1]))
    for t in (0.5, 2.0):
        assert statics.load_factor(BOX, FR, ramp, g=G, t=t) == pytest.approx(exact / t)
    assert math.isinf(statics.load_factor(BOX, FR, ramp, g=G))  # t = 0: no load
    assert statics.can_stick(BOX, FR, ramp, g=G, t=0.5 * exact)
    assert not statics.can_stick(BOX, FR, ramp, g=G, t=1.01 * exact)


def test_any_object_with_a_wrench_method_is_a_load():
    class Push:
        def wrench(self, t, phi, mass_centre):
            return (5.0, 0.0, 0.0)

    assert statics.load_factor(BOX, FR, Push(), g=G) == pytest.approx(
        statics.load_factor(BOX, FR, (5.0, 0.0, 0.0), g=G)
    )

    class Wrong:
        def wrench(self):
            return (5.0, 0.0, 0.0)

    with pytest.raises(ValueError, match=r"applied_wrench = .* wrench method .*; valid values"):
        statics.load_factor(BOX, FR, Wrong())


@pytest.mark.parametrize("bad", ("123", b"123", (True, 0.0, 0.0), (1.0, 2.0), (1.0, math.nan, 0)))
def test_a_bad_applied_wrench_is_refused_by_name(bad):
    with pytest.raises(ValueError, match=r"applied_wrench = .* is invalid; valid values: three"):
        statics.can_stick(BOX, FR, bad)


def test_a_slope_too_steep_to_judge_is_blamed_on_the_slope():
    steep = Incline(math.nextafter(math.pi / 2.0, 0.0))
    with pytest.raises(ValueError) as e:
        statics.load_factor(BOX, FR, (0.2 * BOX.mass * G, 0.0, 0.0), g=G, incline=steep)
    msg = str(e.value)
    assert msg.startswith("incline angle = 1.5707963267948963 rad is invalid")
    assert "valid range" in msg and "atan(1e+06)" in msg
    assert "applied_wrench" not in msg
    with pytest.raises(ValueError, match="incline angle"):
        statics.can_stick(BOX, FR, (0.0, 0.0, 0.0), incline=steep)
    with pytest.raises(ValueError, match="incline angle"):
        statics.onset(BOX, FR, (0.0, 0.0, 0.0), incline=steep)


def test_the_steepest_slope_judged_still_obeys_tan_alpha_le_mu():
    iso = ss.FrictionTensor(0.4, 0.4)
    alpha = math.atan(1e5)  # steep, within the range the message states
    lam = statics.load_factor(BOX, iso, (0.0, 0.0, 0.0), g=G, incline=Incline(alpha))
    assert lam == pytest.approx(0.4 / math.tan(alpha), rel=1e-9)
    assert statics.can_stick(BOX, iso, (0.0, 0.0, 0.0), incline=Incline(math.atan(0.39)))
    assert not statics.can_stick(BOX, iso, (0.0, 0.0, 0.0), incline=Incline(math.atan(0.41)))
