"""``slidespin aim CASE.toml --target x,y[,phi]`` (MODEL §15)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

import slidespin as ss

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "examples" / "box.toml"


def _run(*args):
    return subprocess.run(
        [sys.executable, "-m", "slidespin", "aim", *map(str, args)],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip


def test_aim_json_hits_the_target():
    r = _run(CASE, "--target", "0.3,0.1,1.5", "--json")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    assert doc["reachable"] is True
    case = ss.load_case(CASE)
    lau = doc["launch"]
    start = ss.State(lau["x"], lau["y"], lau["phi"], lau["vx"], lau["vy"], lau["omega"])
    stop = ss.simulate(case.body, case.friction, start, case.g, case.rtol).stop_state
    assert abs(stop.x - 0.3) < 1e-9 and abs(stop.y - 0.1) < 1e-9 and abs(stop.phi - 1.5) < 1e-9


def test_aim_text_and_unreachable_exit_status():
    r = _run(CASE, "--target", "0.3,0.1")
    assert r.returncode == 0, r.stderr
    assert "launch" in r.stdout and "stops" in r.stdout
    # spin alone cannot carry the box 1 m
    r = _run(CASE, "--target", "1.0,0.0", "--free", "omega")
    assert r.returncode == 1
    assert "unreachable" in r.stdout


@pytest.mark.parametrize("target", ["1.0", "a,b", "1,2,3,4", "nan,0"])
def test_aim_bad_target(target):
    r = _run(CASE, "--target", target)
    assert r.returncode != 0
    assert "--target" in r.stderr


def test_aim_a_case_on_a_slope(tmp_path):
    """A case's [incline] is aimed on (the Jacobian by differences), and the stop printed is
    where ``simulate`` has the body at rest."""
    case_file = tmp_path / "slope.toml"
    case_file.write_text(CASE.read_text() + "\n[incline]\nangle_deg = 8.0\ndownhill_deg = 30.0\n")
    r = _run(case_file, "--target", "0.4,0.2,1.0", "--json")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    case = ss.load_case(case_file)
    lau = doc["launch"]
    start = ss.State(lau["x"], lau["y"], lau["phi"], lau["vx"], lau["vy"], lau["omega"])
    tr = ss.simulate(case.body, case.friction, start, case.g, case.rtol, incline=case.incline)
    assert tr.ending == "stopped_stuck"
    assert abs(tr.x[-1] - 0.4) < 1e-9 and abs(tr.y[-1] - 0.2) < 1e-9
    assert abs(tr.phi[-1] - 1.0) < 1e-9
    assert doc["stop"]["t_stop"] == pytest.approx(tr.t[-1], rel=1e-12)


def test_aim_refuses_a_pushed_case():
    r = _run(ROOT / "examples" / "finger_box.toml", "--target", "0.3,0.1")
    assert r.returncode != 0
    assert "pusher" in r.stderr


def test_aim_finds_a_launch_against_the_case_s_push():
    r = _run(ROOT / "examples" / "pushed_box.toml", "--target", "0.5,0", "--json")
    assert r.returncode == 0, r.stdout + r.stderr
    doc = json.loads(r.stdout)
    assert doc["launch"]["vx"] < 0.0
    assert abs(doc["stop"]["x"] - 0.5) < 1e-9
