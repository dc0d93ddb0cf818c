"""The curling story (docs/gallery/plot_13_curling_curl.py) runs and prints what it claims:
the tall stone presses ahead of its centre by about h μ (closed form of the deceleration), a
speed law on the symmetric band gives no curl (zero by symmetry), and the load shift curls
the stone to the right (the wrong way for a counter-clockwise stone) by millimetres, not the
metre observed."""

from __future__ import annotations

import os
import re

import pytest
from test_gallery import story_output


def test_curling_story(tmp_path):
    stdout = story_output("plot_13_curling_curl.py", tmp_path)

    def value(label):
        m = re.search(r"^" + re.escape(label) + r" = ([-+0-9.eE]+)", stdout, re.MULTILINE)
        assert m, f"no '{label} = <number>' in:\n{stdout}"
        return float(m.group(1))

    # the spin turns the shift by a little: |r_p| = h μ to within (ω R / v)² ~ 5e-4
    assert value("pressure shift") == pytest.approx(1000 * 0.06 * 0.0068, rel=1e-3)
    assert abs(value("law curl")) < 1e-6  # mm: zero by symmetry
    assert abs(value("coulomb curl")) < 1e-6
    assert 1.0 < value("tall curl") < 10.0  # to the right, millimetres
    assert not os.listdir(tmp_path), "a gallery script left files behind"
