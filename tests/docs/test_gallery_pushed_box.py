"""The pushed-box gallery script (docs/gallery/plot_10_pushed_box.py) runs and prints the start
of slip, checked against its closed form: the push F = 12.5 t [N] at G overcomes static
friction on the rectangle exactly when it reaches μ m g."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

GALLERY = Path(__file__).resolve().parents[2] / "docs" / "gallery"
G = 9.81


def run(name: str, label: str, tmp_path) -> float:
    """Run a gallery script in a fresh interpreter; return the number printed after label."""
    env = dict(os.environ, MPLBACKEND="Agg")
    proc = subprocess.run(
        [sys.executable, str(GALLERY / name)],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    m = re.search(r"^" + re.escape(label) + r" = ([-+0-9.eE]+)", proc.stdout, re.MULTILINE)
    assert m, f"{name} printed no '{label} = <number>':\n{proc.stdout}"
    assert not os.listdir(tmp_path), "a gallery script left files behind"
    return float(m.group(1))


def test_pushed_box(tmp_path):
    t = run("plot_10_pushed_box.py", "start of slip", tmp_path)
    # the push ramps at 25 N / 2 s; for a push at G the threshold is μ m g whatever the
    # footprint (friction can give no more force, and pure translation gives exactly that)
    mu, m = 0.35, 5.0
    assert t == pytest.approx(mu * m * G / 12.5, abs=2e-9)  # printed to 1e-9 s
