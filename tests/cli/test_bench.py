"""Smoke test of `slidespin bench` (tiny sizes): it runs, prints the table, writes JSON.

Timings are never asserted (they depend on the machine); only that every row is measured.
"""

from __future__ import annotations

import json
import os

from slidespin.cli.main import main

TINY = [
    "bench",
    "--quick",
    "--no-compile",
    "--naive-seconds",
    "1",
    "--batch",
    "20",
    "--memory-cases",
    "20",
    "--sweep-local",
    "40",
    "--sweep-dask",
    "0",
]


def test_bench_smoke(tmp_path, capsys):
    code = main(TINY + ["--out", str(tmp_path / "b")])
    assert code == 0
    text = capsys.readouterr().out
    for row in (
        "wrench, uniform, ICR inside",
        "trajectory to the converged stop",
        "speed-up vs naive",
        "speed-up vs semi-analytic",
        "sweep, all local cores",
        "footprint wrench, octagon (8 vertices), ICR within 1 extent",
        "footprint wrench, ring, ICR 1.1-10 extents",
        "footprint trajectory to the converged stop, octagon",
        "footprint trajectory to the converged stop, ring",
        "footprint batch, octagon: ellipse / footprint throughput",
        "footprint batch, ring: ellipse / footprint throughput",
    ):
        assert row in text
    data = json.loads((tmp_path / "b" / "bench.json").read_text())
    assert data["accuracy"]["wrench"]["max_abs_error"] < 1e-10
    for name in ("octagon", "ring"):
        fp = data["footprint"][name]
        # the exact footprint kernel against the independent slow reference (units of P)
        assert fp["wrench_max_abs_error"] < 1e-10
        assert fp["status"] == 0 and fp["trajectory_steps"] > 0  # stopped, converged
        assert fp["batch_per_s"] > 0 and fp["ellipse_over_footprint"] > 0
    assert data["naive"]["s_per_rhs"] > 0 and data["sweep"]["local_cases"] == 40


def test_bench_json_is_a_flag_and_nothing_lands_in_the_working_directory(
    tmp_path, capsys, monkeypatch
):
    monkeypatch.chdir(tmp_path)
    assert main(TINY + ["--json"]) == 0
    printed = json.loads(capsys.readouterr().out)  # stdout is JSON only
    assert printed["sweep"]["local_cases"] == 40
    assert os.listdir(tmp_path) == ["slidespin-out"]
    saved = json.loads((tmp_path / "slidespin-out" / "bench.json").read_text())
    assert saved["batch"] == printed["batch"]


def test_bench_rejects_bad_sizes(capsys):
    assert main(["bench", "--batch", "3", "--no-save"]) == 2
    assert "--batch = 3 is invalid" in capsys.readouterr().err


def test_bench_out_must_be_a_directory(tmp_path, capsys):
    f = tmp_path / "file"
    f.write_text("x")
    assert main(["bench", "--out", str(f)]) == 2
    assert "--out" in capsys.readouterr().err and f.read_text() == "x"
