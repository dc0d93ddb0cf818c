"""`slidespin simulate` and `slidespin animate` on a case with a [pusher] (MODEL §13): a finger
pushing a box, end to end (exit status, JSON keys, CSV columns, figure), and the commands that
cannot use a pusher refuse it."""

import csv
import json
import math

import pytest

from slidespin.cli._pushed import CSV_COLUMNS
from slidespin.cli.main import main

CASE = """
name = "finger"
[patch]
shape = "rectangle"
length = 0.2
width = 0.15
[pressure]
law = "uniform"
[friction]
fx = 0.35
fy = 0.35
[body]
mass = 2.0
[initial]
[pusher]
kind = "point"
mu = 0.3
path = [[0.0, -0.2, -0.03], [1.0, 0.0, -0.03], [1.5, 0.05, 0.1]]
[solver]
t_end = 2.0
"""
#: through G along a symmetry axis: a pure translation at the finger's speed, λ = μ m g
CENTRED = CASE.replace("-0.03], [1.0, 0.0, -0.03], [1.5, 0.05, 0.1]]", "0.0], [1.0, 0.0, 0.0]]")
CENTRED = CENTRED.replace("t_end = 2.0", "t_end = 1.0")


@pytest.fixture()
def case_file(tmp_path):
    p = tmp_path / "finger.toml"
    p.write_text(CASE)
    return p


def test_json_summary(case_file, capsys):
    code = main(["simulate", str(case_file), "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == 0
    for key in (
        "status", "t_final", "x_final", "y_final", "phi_final", "vx_final", "vy_final",
        "omega_final", "switches", "impacts", "pusher_work", "friction_work",
        "contact_slip_work", "impact_loss", "energy_error", "relative_energy_error",
        "phases", "mode_switches", "pusher_kind", "pusher_mu",
    ):  # fmt: skip
        assert key in out, key
    assert out["status"] == "ok" and out["t_final"] == 2.0
    assert out["pusher_kind"] == "point" and out["pusher_mu"] == 0.3
    assert out["phases"][0][0] == "separated" and out["phases"][1][0] == "sticking"
    assert out["phases"][1][1] == pytest.approx(0.5, abs=1e-9)  # the finger arrives
    assert out["relative_energy_error"] < 1e-9
    assert out["impacts"] >= 1


def test_centred_push_translates(tmp_path, capsys):
    p = tmp_path / "centred.toml"
    p.write_text(CENTRED)
    assert main(["simulate", str(p), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    # the finger meets the face at t = 0.5 s and carries the box 0.1 m, without turning
    assert out["x_final"] == pytest.approx(0.1, abs=1e-9)
    assert out["phi_final"] == pytest.approx(0.0, abs=1e-9)
    assert out["pusher_work"] == pytest.approx(
        0.35 * 2.0 * 9.81 * 0.1 + out["impact_loss"] + 0.5 * 2.0 * 0.2**2, rel=1e-6
    )


def test_text_csv_and_plot(case_file, tmp_path, capsys):
    out_csv, out_png = tmp_path / "run.csv", tmp_path / "run.png"
    code = main(["simulate", str(case_file), "--csv", str(out_csv), "--plot", str(out_png)])
    text = capsys.readouterr().out
    assert code == 0
    for word in ("status      : ok", "pusher work", "energy error", "modes", "sticking"):
        assert word in text
    rows = list(csv.DictReader(out_csv.open()))
    assert tuple(rows[0]) == CSV_COLUMNS
    assert rows[0]["mode"] == "separated" and rows[0]["contact_point_x"] == ""
    sticking = [r for r in rows if r["mode"] == "sticking"]
    assert sticking and all(math.isfinite(float(r["pusher_force_x"])) for r in sticking)
    assert float(rows[-1]["t"]) == 2.0
    assert out_png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_finger_inside_the_body_is_refused(tmp_path, capsys):
    p = tmp_path / "inside.toml"
    p.write_text(CASE.replace("[[0.0, -0.2, -0.03]", "[[0.0, 0.0, -0.03]"))
    assert main(["simulate", str(p)]) == 2
    err = capsys.readouterr().err
    assert "inside the body's outline" in err and err.count("\n") == 1


def test_bad_pusher_key_exit_2(tmp_path, capsys):
    p = tmp_path / "bad.toml"
    p.write_text(CASE.replace("mu = 0.3", "mu = -1.0"))
    assert main(["simulate", str(p)]) == 2
    err = capsys.readouterr().err
    assert "[pusher] mu = -1.0" in err and "valid range: [0, 1e+09]" in err


@pytest.mark.parametrize("command", [["fit", "data.csv", "--case"], ["limit-surface"]])
def test_commands_without_pushers_refuse_the_table(case_file, tmp_path, capsys, command):
    data = tmp_path / "data.csv"
    data.write_text("t,x,y,phi\n0,0,0,0\n0.1,0.01,0,0\n0.2,0.02,0,0\n")
    argv = [c.replace("data.csv", str(data)) for c in command] + [str(case_file)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "[pusher] is not used by" in err


def test_animate_pushed(case_file, tmp_path, capsys):
    out = tmp_path / "run.gif"
    code = main(["animate", str(case_file), "--out", str(out), "--frames", "5"])
    assert code == 0
    assert out.read_bytes()[:6] == b"GIF89a"
    assert "pushed to t = 2 s" in capsys.readouterr().out


LINE = CASE.replace(
    'kind = "point"\nmu = 0.3\npath = [[0.0, -0.2, -0.03], [1.0, 0.0, -0.03], [1.5, 0.05, 0.1]]',
    'kind = "line"\nlength = 0.1\nmu = 0.3\npath_deg = [[0.0, -0.2, 0.0, 90.0], [1.0, 0.0, 0.0, 90.0]]',
).replace("t_end = 2.0", "t_end = 1.0")


def test_line_pusher_case(tmp_path, capsys):
    p, out_csv = tmp_path / "line.toml", tmp_path / "line.csv"
    p.write_text(LINE)
    code = main(["simulate", str(p), "--json", "--csv", str(out_csv)])
    captured = capsys.readouterr()
    if code == 2 and "not implemented" in captured.err:
        pytest.skip("the dynamics of a line pusher is not in this build")
    assert code == 0, captured.err
    out = json.loads(captured.out)
    assert out["pusher_kind"] == "line"
    # the face meets the box's left face squarely at t = 0.5 s and carries it 0.1 m
    assert out["x_final"] == pytest.approx(0.1, abs=1e-9)
    assert out["phi_final"] == pytest.approx(0.0, abs=1e-9)
    rows = list(csv.DictReader(out_csv.open()))
    assert "pusher_angle" in rows[0] and float(rows[0]["pusher_angle"]) == pytest.approx(
        math.pi / 2
    )
