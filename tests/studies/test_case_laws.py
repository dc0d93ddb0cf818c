"""Case files with a friction law, a static ratio and a spring (MODEL §14): the keys are the
Python API's names, every key is checked, and the shipped example runs its closed form."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import slidespin as ss
from slidespin.studies.case import case_from_dict

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _doc(friction=None, spring=None):
    doc = {
        "patch": {"shape": "rectangle", "length": 0.02, "width": 0.02},
        "pressure": {"law": "uniform"},
        "friction": {"fx": 0.3, "fy": 0.3, **(friction or {})},
        "body": {"mass": 1.0},
        "initial": {"v0": 0.0},
    }
    if spring is not None:
        doc["spring"] = spring
    return doc


@pytest.mark.parametrize(
    "keys, law",
    [
        ({"law": "power", "q": 0.5, "v0": 2.0}, ss.PowerLaw(0.5, 2.0)),
        ({"law": "stribeck", "static_ratio": 1.4, "vs": 0.1}, ss.Stribeck(1.4, 0.1)),
        (
            {"law": "table", "speeds": [0, 1], "factors": [1.2, 1.0]},
            ss.SpeedTable([0, 1], [1.2, 1.0]),
        ),
        ({"law": "constant"}, None),
        ({}, None),
    ],
)
def test_friction_law_keys_build_the_law(keys, law):
    case = case_from_dict(_doc(keys))
    assert case.friction.speed_law == law


def test_static_key_and_spring_table():
    spring = {"stiffness": 50.0, "anchor_path": [[0, 0, 0], [2, 0.1, 0]], "damping": 0.5}
    case = case_from_dict(_doc({"static": 1.5}, spring))
    assert case.friction.static == 1.5
    assert case.load == ss.Spring(50.0, [(0, 0, 0), (2, 0.1, 0)], damping=0.5)


@pytest.mark.parametrize(
    "friction, spring, match",
    [
        ({"law": "ice"}, None, r"\[friction\] law = 'ice' is invalid"),
        ({"law": "power", "vs": 1.0, "q": 0.5}, None, r"\[friction\] key 'vs' does not belong"),
        ({"law": "stribeck", "vs": 1.0}, None, r"missing the required key 'static_ratio'"),
        ({"law": "power", "q": 2.0}, None, r"\[friction\] q = 2\.0 is invalid"),
        ({"static": 0.5}, None, r"\[friction\] static = 0\.5 is invalid"),
        ({}, {"stiffness": 1.0}, r"\[spring\] is missing the required key 'anchor_path'"),
        ({}, {"stiffness": 1.0, "anchor_path": [[0, 0, 0]], "k": 2}, r"unknown key 'k'"),
        ({}, {"stiffness": -1.0, "anchor_path": [[0, 0, 0]]}, r"\[spring\] stiffness = -1\.0"),
    ],
)
def test_bad_law_and_spring_keys_are_refused(friction, spring, match):
    with pytest.raises(ValueError, match=match):
        case_from_dict(_doc(friction, spring))


def test_the_shipped_spring_block_runs_its_closed_form_period():
    case = ss.load_case(EXAMPLES / "spring_block.toml")
    tr = ss.simulate(case.body, case.friction, case.initial_state, load=case.load, t_end=case.t_end)
    slips = [t0 for kind, t0, _ in tr.phases if kind == "slip"]
    w0 = math.sqrt(100.0 / 1.0)
    delta = 0.15 * 9.81 / 100.0
    period = 2 * delta / 0.05 + 2 / w0 * (math.pi - math.atan(delta * w0 / 0.05))
    assert slips[2] - slips[1] == pytest.approx(period, rel=1e-8)
