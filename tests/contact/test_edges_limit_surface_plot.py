"""The limit-surface figure is legible: the moment axis' label is not under the colour bar,
and no two tick labels of an axis overlap (a long rectangle used to crowd them).

Checked on the rendered figure (Agg): the window extents of the texts drawn.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import slidespin as ss
from slidespin.contact.limit_surface import limit_surface

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")


@pytest.mark.parametrize(
    "patch",
    [ss.Rectangle(0.4, 0.1), ss.Rectangle(0.5, 0.02), ss.Ellipse(0.1, 0.05), ss.Blade(0.3)],
    ids=lambda p: type(p).__name__,
)
def test_labels_do_not_collide(patch, tmp_path):
    import matplotlib.pyplot as plt

    body = ss.Body(patch, ss.UniformPressure(), mass=1.0)
    ls = limit_surface(body, ss.FrictionTensor(0.3, 0.5), n=200)
    ax = ls.plot()
    fig = ax.figure
    fig.savefig(tmp_path / "ls.png", dpi=100)  # renders every text
    renderer = fig.canvas.get_renderer()
    colorbar = [a for a in fig.axes if a is not ax]
    assert len(colorbar) == 1
    bar = colorbar[0].get_tightbbox(renderer)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        label = axis.label.get_window_extent(renderer)
        assert label.width > 0 and not label.overlaps(bar), axis.label.get_text()
        boxes = [
            t.get_window_extent(renderer)
            for t in axis.get_ticklabels()
            if t.get_visible() and t.get_text()
        ]
        assert 3 <= len(boxes) <= 6
        for a, b in itertools.combinations(boxes, 2):
            assert not a.overlaps(b)
        for b in boxes:
            assert not b.overlaps(bar)
    assert np.isfinite(ls.ellipsoid).all()
    plt.close(fig)
