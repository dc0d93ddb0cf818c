"""The friction tensor's angle: radians within ±2π, or degrees by ``angle_deg`` (item: a
user's ``angle=30`` meant degrees and silently became 30 rad).

Independent truth: the rotated tensor R(α) diag(fx, fy) R(α)ᵀ written out here.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from slidespin.contact.friction import FrictionTensor


def _turned(fx, fy, alpha):
    c, s = math.cos(alpha), math.sin(alpha)
    return np.array(
        [[fx * c * c + fy * s * s, (fx - fy) * c * s], [(fx - fy) * c * s, fx * s * s + fy * c * c]]
    )


@pytest.mark.parametrize("angle", (30.0, -7.0, 360.0, 1e6))
def test_an_angle_beyond_two_pi_is_refused_with_a_hint_to_degrees(angle):
    with pytest.raises(
        ValueError, match=r"angle = .* rad is invalid; valid range: \[-6\.28319"
    ) as e:
        FrictionTensor(0.3, 0.4, angle=angle)
    assert f"angle_deg={angle!r}" in str(e.value)


@pytest.mark.parametrize("angle", (2.0 * math.pi, -2.0 * math.pi, 6.0, 0.5))
def test_angles_up_to_two_pi_are_radians(angle):
    t = FrictionTensor(0.3, 0.4, angle=angle)
    assert t.angle == angle
    assert t.matrix == pytest.approx(_turned(0.3, 0.4, angle), abs=1e-15)


@pytest.mark.parametrize("deg", (30.0, -90.0, 360.0, 0.0))
def test_angle_deg_is_the_same_angle_in_degrees(deg):
    t = FrictionTensor(0.3, 0.4, angle_deg=deg)
    assert t.angle == pytest.approx(math.radians(deg), abs=0.0)
    assert t.angle_deg == pytest.approx(deg)
    assert t.matrix == pytest.approx(_turned(0.3, 0.4, math.radians(deg)), abs=1e-15)
    assert FrictionTensor.from_degrees(0.3, 0.4, angle_deg=deg) == t


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(angle_deg=400.0), r"angle_deg = 400.0 deg is invalid; valid range: \[-360, 360\]"),
        (dict(angle_deg=math.nan), "angle_deg"),
        (dict(angle_deg="30"), "angle_deg"),
        (dict(angle=0.5, angle_deg=20.0), "exactly one of them"),
        (dict(angle=math.inf), "angle"),
        (dict(angle=True), "angle"),
    ],
)
def test_bad_angles_name_the_parameter(kwargs, match):
    with pytest.raises(ValueError, match=match):
        FrictionTensor(0.3, 0.4, **kwargs)
