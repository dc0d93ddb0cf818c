"""Case files with a tall body (MODEL §14): ``[body] height`` and ``[load] height``, checked
like every key, and the shipped tipping box tips at its closed-form time, also from the CLI."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import slidespin as ss
from slidespin.studies.case import case_from_dict

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _doc(body=None, load=None):
    doc = {
        "patch": {"shape": "rectangle", "length": 0.4, "width": 0.3},
        "pressure": {"law": "uniform"},
        "friction": {"fx": 0.5, "fy": 0.5},
        "body": {"mass": 2.0, **(body or {})},
        "initial": {"v0": 0.0},
        "solver": {"t_end": 1.0},
    }
    if load is not None:
        doc["load"] = load
    return doc


def test_heights_reach_the_body_and_the_load():
    case = case_from_dict(_doc({"height": 0.3}, {"fx": 2.0, "height": 0.5}))
    assert case.body.height == 0.3
    assert case.load.height == 0.5
    assert case.loaded
    case = case_from_dict(_doc({"height": 0.3, "inertia_ratio": 0.4}))
    assert case.body.height == 0.3
    assert case.body.inertia_ratio == pytest.approx(0.4, rel=1e-14)
    prof = {"times": [0, 1], "profile_fx": [0, 1], "profile_fy": [0, 0], "height": 0.2}
    assert case_from_dict(_doc(None, prof)).load.height == 0.2


@pytest.mark.parametrize(
    ("body", "load", "match"),
    [
        ({"height": -0.1}, None, r"height = -0.1 m is invalid"),
        ({"hight": 0.1}, None, r"unknown key 'hight' in \[body\]"),
        (None, {"fx": 1.0, "height": -2.0}, r"\[load\] height = -2.0 m is invalid"),
    ],
)
def test_bad_heights_are_refused_with_the_key(body, load, match):
    with pytest.raises(ValueError, match=match):
        case_from_dict(_doc(body, load))


def test_the_shipped_tipping_box_tips_at_p_w_over_2_h_q():
    case = ss.load_case(EXAMPLES / "tipping_box.toml")
    tr = ss.simulate(case.body, case.friction, case.initial_state, load=case.load,
                     t_end=case.t_end, g=case.g)  # fmt: skip
    p = case.body.mass * case.g
    assert tr.status == "tipping"
    assert tr.tip_time == pytest.approx(p * 0.4 / (2.0 * 0.5) / 10.0, abs=1e-9)


def test_the_cli_reports_the_tipping():
    out = subprocess.run(
        [sys.executable, "-m", "slidespin", "simulate", str(EXAMPLES / "tipping_box.toml")],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert out.returncode == 0, out.stderr
    assert "tipping" in out.stdout and "0.7848" in out.stdout
