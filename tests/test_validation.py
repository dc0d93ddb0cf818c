"""Bad input is rejected before any work, with a message naming parameter, value and range."""

from __future__ import annotations

import math

import pytest

import slidespin as ss
from slidespin.case import case_from_dict

BAD_CONSTRUCTORS = [
    (lambda: ss.Ellipse(0.0, 1.0), "a = 0.0"),
    (lambda: ss.Ellipse(1.0, -2.0), "b = -2.0"),
    (lambda: ss.Ellipse(math.nan, 1.0), "a = nan"),
    (lambda: ss.Ellipse(1.0, math.inf), "b = inf"),
    (lambda: ss.Ellipse("1", 1.0), "a must be a real number"),
    (lambda: ss.Ellipse.from_eccentricity(1.0, 1.0), "eccentricity = 1.0"),
    (lambda: ss.Ellipse.from_eccentricity(1.0, -0.1), "eccentricity = -0.1"),
    (lambda: ss.Circle(-1.0), "radius = -1.0"),
    (lambda: ss.FrictionTensor(0.0, 0.3), "fx = 0.0"),
    (lambda: ss.FrictionTensor(0.3, -0.1), "fy = -0.1"),
    (lambda: ss.FrictionTensor(0.3, 0.3, f=math.inf), "f = inf"),
    (lambda: ss.FrictionTensor(0.3, 0.3, frame="world"), "frame = 'world'"),
    (lambda: ss.LinearPressure(math.nan, 0.0), "xi_c = nan"),
    (lambda: ss.Body(ss.Circle(1.0), ss.UniformPressure(), mass=0.0), "mass = 0.0"),
    (lambda: ss.Body(ss.Circle(1.0), ss.UniformPressure(), 1.0, -1.0), "moment_of_inertia = -1.0"),
    (lambda: ss.Body(ss.Circle(1.0), ss.LinearPressure(0.3, 0.0), 1.0), "outside the core"),
    (lambda: ss.Body(ss.Circle(1.0), "uniform", 1.0), "pressure = 'uniform'"),
    (lambda: ss.Body((1.0, 1.0), ss.UniformPressure(), 1.0), "patch = (1.0, 1.0)"),
    (lambda: ss.State(vx=math.nan), "vx = nan"),
    (lambda: ss.State.from_speed(-1.0, 1.0), "speed = -1.0"),
]


@pytest.mark.parametrize("make, fragment", BAD_CONSTRUCTORS)
def test_constructors_reject_bad_values(make, fragment):
    with pytest.raises(ValueError) as err:
        make()
    assert fragment in str(err.value)
    msg = str(err.value)
    assert "valid" in msg or "must be" in msg


def test_linear_law_core_boundary_is_accepted():
    # (xi_c/a)^2 + (eta_c/b)^2 = 1/16 exactly: p vanishes at one rim point, still valid
    ss.Body(ss.Ellipse(1.0, 0.5), ss.LinearPressure(0.25, 0.0), 1.0)


def test_api_functions_reject_bad_arguments():
    body = ss.Body(ss.Circle(1.0), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor(0.3, 0.3)
    with pytest.raises(ValueError, match="g = 0.0"):
        ss.friction_wrench(body, fr, 1.0, 0.0, 0.0, g=0.0)
    with pytest.raises(ValueError, match="omega = nan"):
        ss.friction_wrench(body, fr, 1.0, 0.0, math.nan)
    with pytest.raises(ValueError, match="do not broadcast"):
        ss.friction_wrench(body, fr, [1.0, 2.0], [0.0, 1.0, 2.0], 0.0)
    with pytest.raises(ValueError, match="rtol = 0.1"):
        ss.simulate(body, fr, ss.State(vx=1.0), rtol=0.1)
    with pytest.raises(ValueError, match="initial_state"):
        ss.simulate(body, fr, (0, 0, 0, 1, 0, 0))
    with pytest.raises(ValueError, match="max_steps"):
        ss.simulate(body, fr, ss.State(vx=1.0), max_steps=0)


def good_case():
    return {
        "patch": {"a": 0.1, "eccentricity": 0.5},
        "pressure": {"law": "uniform"},
        "friction": {"fx": 0.3, "fy": 0.4},
        "body": {"mass": 1.0},
        "initial": {"speed": 1.0, "omega": 2.0},
    }


def test_good_case_loads():
    case = case_from_dict(good_case())
    assert case.body.patch.b == pytest.approx(0.1 * math.sqrt(0.75))


BAD_CASES = [
    (("patch", "eccentricity", 1.2), "eccentricity = 1.2"),
    (("patch", "a", -1.0), "a = -1.0"),
    (("patch", "aa", 1.0), "unknown key 'aa' in [patch]"),
    (("pressure", "law", "parabolic"), "pressure law = 'parabolic'"),
    (("pressure", "xi_c", 0.01), "takes no parameter 'xi_c'"),
    (("friction", "fx", 0.0), "fx = 0.0"),
    (("friction", "frame", "world"), "frame = 'world'"),
    (("body", "mass", "heavy"), "mass must be a real number"),
    (("body", "inertia_ratio", 0.0), "inertia_ratio = 0.0"),
    (("initial", "omgea", 1.0), "unknown key 'omgea' in [initial]"),
    (("initial", "vx", 1.0), "either speed/theta or vx/vy"),
    (("solver", "rtol", 1.0), "rtol = 1.0"),
    (("solver", "g", -9.81), "g = -9.81"),
]


@pytest.mark.parametrize("edit, fragment", BAD_CASES)
def test_case_files_reject_bad_entries(edit, fragment):
    data = good_case()
    table, key, value = edit
    data.setdefault(table, {})[key] = value
    with pytest.raises(ValueError) as err:
        case_from_dict(data)
    assert fragment in str(err.value)


def test_case_missing_table_and_key():
    data = good_case()
    del data["friction"]
    with pytest.raises(ValueError, match=r"missing the table \[friction\]"):
        case_from_dict(data)
    data = good_case()
    del data["body"]["mass"]
    with pytest.raises(ValueError, match=r"\[body\] is missing the required key 'mass'"):
        case_from_dict(data)
    data = good_case()
    data["sovler"] = {}
    with pytest.raises(ValueError, match="unknown table or key 'sovler'"):
        case_from_dict(data)
