"""The command line: the demo, case files, outputs, and one-line errors with exit status 2."""

from __future__ import annotations

import importlib
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

import slidespin as ss
from slidespin.cli.main import demo_case, main
from slidespin.studies.case import load_case

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def run(*args, cwd=None):
    return subprocess.run(
        [sys.executable, "-m", "slidespin", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=600,
    )


def test_demo_writes_figure_and_prints_the_stop(tmp_path):
    r = run("demo", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    for word in ("stop time", "distance", "beta_stop", "theta_stop", "ending"):
        assert word in r.stdout
    png = tmp_path / "slidespin-out" / "demo.png"  # never straight into the working directory
    assert png.stat().st_size > 20_000
    assert sorted(p.name for p in tmp_path.iterdir()) == ["slidespin-out"]
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_demo_toml_is_the_demo():
    a, b = demo_case(), load_case(EXAMPLES / "demo.toml")
    assert a.body == b.body and a.friction == b.friction and a.g == b.g
    assert a.initial_state.vx == pytest.approx(b.initial_state.vx, abs=1e-15)
    assert a.initial_state.vy == pytest.approx(b.initial_state.vy, abs=1e-15)
    assert a.initial_state.omega == b.initial_state.omega


def test_simulate_json_csv_plot(tmp_path, capsys):
    csv_path, png = tmp_path / "t.csv", tmp_path / "f.png"
    code = main(
        [
            "simulate",
            str(EXAMPLES / "demo.toml"),
            "--json",
            "--csv",
            str(csv_path),
            "--plot",
            str(png),
        ]
    )
    assert code == 0
    data = json.loads(capsys.readouterr().out)
    assert data["status"] == "stopped" and data["ending"] == "mixed"
    assert data["t_stop"] > 0
    assert csv_path.read_text().startswith("t,x,y,phi")
    assert png.stat().st_size > 20_000


# case files for `slidespin simulate` (sweep specs and the fit's body description are not)
CASE_FILES = sorted(p for p in EXAMPLES.glob("*.toml") if not p.name.startswith(("sweep_", "fit_")))


@pytest.mark.parametrize("path", CASE_FILES, ids=lambda p: p.name)
def test_every_example_case_runs(path, capsys):
    assert main(["simulate", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    if "phases" in data:  # a loaded case ([load], [incline], t_end): the loaded vocabulary
        from slidespin.motion.outcomes import LOADED_CONVERGED

        assert data["status"] in LOADED_CONVERGED
    else:
        assert data["status"] == "stopped" and math.isfinite(data["t_stop"])


def test_uniform_disk_example_pins_the_published_ratio(capsys):
    case = load_case(EXAMPLES / "uniform_circle.toml")
    tr = ss.simulate(case.body, case.friction, case.initial_state)
    assert tr.beta_stop / case.body.patch.a == pytest.approx(0.653, abs=5e-4)


@pytest.mark.parametrize(
    "content, fragment",
    [
        ("[patch\na=1", "is not valid TOML"),
        (
            "[patch]\na = 0.1\neccentricity = 2.0\n[pressure]\nlaw='uniform'\n[friction]\nfx=0.3\n"
            "fy=0.3\n[body]\nmass=1.0\n[initial]\nspeed=1.0\n",
            "eccentricity = 2.0",
        ),
    ],
)
def test_bad_case_file_one_line_exit_2(tmp_path, content, fragment):
    case = tmp_path / "bad.toml"
    case.write_text(content)
    out = tmp_path / "out.png"
    r = run("simulate", str(case), "--plot", str(out))
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and fragment in lines[0] and "Traceback" not in r.stderr
    assert not out.exists()


def test_missing_file_and_unwritable_output(tmp_path):
    r = run("simulate", str(tmp_path / "nope.toml"))
    assert r.returncode == 2 and "does not exist" in r.stderr
    r = run("simulate", str(EXAMPLES / "demo.toml"), "--csv", str(tmp_path / "no" / "x.csv"))
    assert r.returncode == 2 and "does not exist" in r.stderr and "Traceback" not in r.stderr


def test_internal_error_is_reported_without_traceback(monkeypatch, capsys):
    sim = importlib.import_module("slidespin.motion.simulate")  # the parser loads no layer

    def boom(*args, **kwargs):
        raise RuntimeError("kernel exploded")

    monkeypatch.setattr(sim, "simulate", boom)
    assert main(["simulate", str(EXAMPLES / "demo.toml")]) == 3
    err = capsys.readouterr().err
    assert "internal error: RuntimeError: kernel exploded" in err
    assert "report" in err and "--debug" in err and "Traceback" not in err
    with pytest.raises(RuntimeError, match="kernel exploded"):
        main(["--debug", "simulate", str(EXAMPLES / "demo.toml")])
