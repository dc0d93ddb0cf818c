"""The curling story (docs/gallery/plot_13_curling_curl.py) runs and prints what it claims:
the tall stone presses ahead of its centre by about h μ (closed form of the deceleration), a
speed law on the symmetric band gives no curl (zero by symmetry), and the load shift curls
the stone to the right (the wrong way for a counter-clockwise stone) by millimetres, not the
metre observed."""

from __future__ import annotations

import os
import re
import subprocess
import sys

import pytest
from test_gallery import GALLERY


def test_curling_story(tmp_path):
    proc = subprocess.run(
        [sys.executable, str(GALLERY / "plot_13_curling_curl.py")],
        cwd=tmp_path,
        env=dict(os.environ, MPLBACKEND="Agg"),
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr[-3000:]

    def value(label):
        m = re.search(r"^" + re.escape(label) + r" = ([-+0-9.eE]+)", proc.stdout, re.MULTILINE)
        assert m, f"no '{label} = <number>' in:\n{proc.stdout}"
        return float(m.group(1))

    # the spin turns the shift by a little: |r_p| = h μ to within (ω R / v)² ~ 5e-4
    assert value("pressure shift") == pytest.approx(1000 * 0.06 * 0.0068, rel=1e-3)
    assert abs(value("law curl")) < 1e-6  # mm: zero by symmetry
    assert abs(value("coulomb curl")) < 1e-6
    assert 1.0 < value("tall curl") < 10.0  # to the right, millimetres
    assert not os.listdir(tmp_path), "a gallery script left files behind"
