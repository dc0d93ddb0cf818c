"""The MuJoCo story (docs/gallery/plot_14_mujoco_box.py) runs and prints what it claims: the
coupled MuJoCo run stops where slidespin's integrator does (1e-4 of the distance and of the
rotation), MuJoCo's own contacts turn the box tens of per cent too little."""

from __future__ import annotations

import os
import re

import pytest
from test_gallery import story_output

pytest.importorskip("mujoco")


def test_mujoco_box_story(tmp_path):
    stdout = story_output("plot_14_mujoco_box.py", tmp_path)

    def errors(name):
        pattern = (
            re.escape(name) + r": distance error = ([-+0-9.eE]+), rotation error = ([-+0-9.eE]+)"
        )
        m = re.search(pattern, stdout)
        assert m, f"no errors of {name!r} in:\n{stdout}"
        return float(m.group(1)), float(m.group(2))

    dist, rot = errors("MuJoCo + slidespin")
    assert dist < 1e-4 and abs(rot) < 1e-4
    for name in ("MuJoCo, condim 3", "MuJoCo, condim 4"):
        dist, rot = errors(name)
        assert rot < -0.2  # the corner contacts hold the spin far too hard
    assert not os.listdir(tmp_path), "a gallery script left files behind"
