"""Smoke test of `slidespin bench` (tiny sizes): it runs, prints the table, writes JSON.

Timings are never asserted (they depend on the machine); only that every row is measured.
"""

from __future__ import annotations

import json

from slidespin.cli import main


def test_bench_smoke(tmp_path, capsys):
    out = tmp_path / "bench.json"
    code = main(["bench", "--quick", "--no-compile", "--naive-seconds", "1", "--batch", "20",
                 "--memory-cases", "20", "--sweep-local", "40", "--sweep-dask", "0",
                 "--json", str(out)])
    assert code == 0
    text = capsys.readouterr().out
    for row in ("wrench, uniform, ICR inside", "trajectory to the converged stop",
                "speed-up vs naive", "speed-up vs semi-analytic", "sweep, all local cores"):
        assert row in text
    data = json.loads(out.read_text())
    assert data["accuracy"]["wrench"]["max_abs_error"] < 1e-10
    assert data["naive"]["s_per_rhs"] > 0 and data["sweep"]["local_cases"] == 40


def test_bench_rejects_bad_sizes(capsys):
    assert main(["bench", "--batch", "3", "--no-json"]) == 2
    assert "--batch = 3 is invalid" in capsys.readouterr().err
