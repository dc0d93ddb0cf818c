"""Cases with [load], [incline] and [solver] t_end from the command line, against closed forms
(MODEL §11): a disk on a slope slides with a = g (sin α − μ cos α) above the friction angle and
stays put below it; a disk pushed by a constant force above μ m g accelerates at F/m − μ g."""

import json
import math

import pytest

from slidespin.cli.main import main

BASE = """
name = "t"
[patch]
shape = "circle"
radius = 0.05
[pressure]
law = "uniform"
[friction]
fx = 0.3
fy = 0.3
[body]
mass = 2.0
[initial]
vx = 0.0
"""


def run(tmp_path, capsys, extra):
    p = tmp_path / "case.toml"
    p.write_text(BASE + extra)
    code = main(["simulate", str(p), "--json"])
    return code, json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("deg", [25.0, 30.0])
def test_slope_above_friction_angle_slides_with_closed_form(tmp_path, capsys, deg):
    code, out = run(tmp_path, capsys, f"[incline]\nangle_deg = {deg}\n[solver]\nt_end = 0.8\n")
    a = 9.81 * (math.sin(math.radians(deg)) - 0.3 * math.cos(math.radians(deg)))
    assert code == 0
    assert out["ending"] == "moving_at_t_end"
    assert out["x_final"] == pytest.approx(0.5 * a * 0.8**2, rel=1e-8)


def test_slope_below_friction_angle_stays(tmp_path, capsys):
    deg = math.degrees(math.atan(0.3)) - 1.0
    code, out = run(tmp_path, capsys, f"[incline]\nangle_deg = {deg}\n[solver]\nt_end = 0.5\n")
    assert code == 0
    assert out["ending"] == "at_rest_throughout"
    assert out["x_final"] == 0.0


def test_push_above_threshold(tmp_path, capsys):
    force = 1.5 * 0.3 * 2.0 * 9.81
    code, out = run(tmp_path, capsys, f"[load]\nfx = {force}\n[solver]\nt_end = 0.5\n")
    acc = force / 2.0 - 0.3 * 9.81
    assert code == 0
    assert out["x_final"] == pytest.approx(0.5 * acc * 0.5**2, rel=1e-8)


def test_bad_load_key_is_one_line(tmp_path, capsys):
    p = tmp_path / "case.toml"
    p.write_text(BASE + "[load]\nforce_x = 1.0\n")
    assert main(["simulate", str(p)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "force_x" in err[0]
