"""The pushing gallery scripts (docs/gallery/plot_11_finger_pushing_box.py,
plot_12_line_pusher_L_part.py) run and print the first contact time, checked against its
closed form: the pusher moves at constant speed towards a face of the resting body."""

from __future__ import annotations

import pytest
from test_gallery_pushed_box import run


def test_finger_pushing_box(tmp_path):
    t = run("plot_11_finger_pushing_box.py", "first contact", tmp_path)
    # the finger starts 0.1 m from the box's left face and moves at 0.2 m/s
    assert t == pytest.approx(0.5, abs=2e-9)


def test_line_pusher_L_part(tmp_path):
    t = run("plot_12_line_pusher_L_part.py", "face contact", tmp_path)
    # the L's bottom edge is eta_G = (area moment / area) below G; the pusher's face starts
    # 0.16 m below G and moves up at 0.26 m / 2 s
    area = 0.2 * 0.06 + 0.06 * 0.10
    eta_g = (0.2 * 0.06 * 0.03 + 0.06 * 0.10 * 0.11) / area
    assert t == pytest.approx((0.16 - eta_g) / 0.13, abs=2e-9)
