"""Trajectory.plot: the accessor pattern (pandas' DataFrame.plot). The motion layer does not
import the plotting layer; the figure is drawn by slidespin.viz, loaded by name on first use,
and its ϑ panel ends at ϑ* (the stop row's limit), not at atan2(0, 0) = 0."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

import slidespin as ss

pytest.importorskip("matplotlib")


def heavy_ring_run():
    mass = 0.7
    ring = ss.Body(
        ss.Annulus(0.08, 0.1), ss.UniformPressure(), mass=mass, moment_of_inertia=3 * mass * 0.01
    )
    return ss.simulate(
        ring, ss.FrictionTensor(0.3, 0.3), ss.State.from_speed(1.0, 30.0, math.pi / 2)
    )


def test_importing_motion_loads_no_plotting():
    code = (
        "import sys, slidespin.motion.simulate, slidespin.motion.batch\n"
        "bad = [m for m in sys.modules if m.startswith(('slidespin.viz', 'matplotlib'))]\n"
        "print(bad)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]", out.stdout


def test_plot_returns_the_four_panel_figure_ending_at_the_limit():
    from matplotlib.figure import Figure

    tr = heavy_ring_run()
    fig = tr.plot(title="heavy ring", n_outlines=4)
    try:
        assert isinstance(fig, Figure)
        assert len(fig.axes) == 5  # path, β, ϑ, v, ω
        assert fig._suptitle is not None and fig._suptitle.get_text() == "heavy ring"
        ax_theta = next(ax for ax in fig.axes if ax.get_ylabel() == "ϑ [rad]")
        (line,) = [ln for ln in ax_theta.get_lines() if len(ln.get_xdata()) == tr.t.size]
        y = np.asarray(line.get_ydata(), dtype=float)
        # the ϑ panel no longer drops to 0 at the stop: it ends at ϑ* = π/2 (symmetry)
        assert y[-1] == pytest.approx(math.pi / 2, abs=1e-9)
        assert np.ptp(y) < 1e-9
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)


@pytest.mark.parametrize(
    "kwargs, error, words",
    [
        (dict(colour="red"), TypeError, ["'colour'", "valid keywords: title, n_outlines"]),
        (dict(title=3), TypeError, ["title = 3", "valid values: a str or None"]),
        (dict(n_outlines=-1), ValueError, ["n_outlines = -1", "[0, 1000]"]),
        (dict(n_outlines=2.5), ValueError, ["n_outlines = 2.5", "integer"]),
        (dict(n_outlines=True), ValueError, ["n_outlines = True"]),
    ],
)
def test_plot_refuses_bad_keywords_before_drawing(kwargs, error, words):
    tr = heavy_ring_run()
    with pytest.raises(error) as info:
        tr.plot(**kwargs)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


def test_plot_docstring_names_the_pattern_and_the_return():
    doc = " ".join((ss.Trajectory.plot.__doc__ or "").split())
    assert "DataFrame.plot" in doc and "first use" in doc
    assert "matplotlib.figure.Figure" in doc
