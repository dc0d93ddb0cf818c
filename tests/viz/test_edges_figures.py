"""The figures a reviewer reads: drawn fast (no pyplot unless it is in use, no layout engine,
titles at a fixed height), the path panel shaped by the path, the β panel's legend in the
figure's own units and its off-scale note out of the data, the ϑ panel without the atan2(0, 0)
drop at a stop, a flat spin said to be flat, heat maps with titles, and a fit figure whose
measured points and fitted lines can be told apart.

Loaded runs are built here from their inputs (a body, a load, recorded arrays), not by the
loaded engine: these tests check the drawing, whatever the engine records."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

import slidespin as ss  # noqa: E402
from slidespin.studies.case import load_case  # noqa: E402
from slidespin.viz.fit_plot import MARKS_PER_RUN, plot_fit  # noqa: E402
from slidespin.viz.sweep_plot import plot_sweep  # noqa: E402
from slidespin.viz.trajectory_plot import (  # noqa: E402
    WIDE_PATH,
    draw_angle,
    draw_beta,
    plot_loaded_trajectory,
    plot_trajectory,
)

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def demo_run():
    body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)
    return ss.simulate(
        body,
        ss.FrictionTensor(0.42, 0.54),
        ss.State.from_speed(1.0, omega=5.0, theta=math.pi / 4),
        max_step=0.05,
    )


@pytest.fixture(scope="module")
def straight_run():
    """uniform_circle.toml: a disk sliding straight along x (a long, flat path)."""
    case = load_case(EXAMPLES / "uniform_circle.toml")
    return ss.simulate(case.body, case.friction, case.initial_state, g=case.g, max_step=0.05)


def fill(ax) -> float:
    """Fraction of the path panel's box that the path (with its outlines) spans, once drawn."""
    ax.figure.canvas.draw()
    box = ax.dataLim
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    return (box.width / (x1 - x0)) * (box.height / (y1 - y0))


# ---- drawing fast ---------------------------------------------------------------------------
def test_a_script_that_only_saves_does_not_import_pyplot(tmp_path):
    code = (
        "import sys, matplotlib\n"
        "import slidespin as ss\n"
        "from slidespin.viz.trajectory_plot import plot_trajectory\n"
        "body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), mass=1.0)\n"
        "tr = ss.simulate(body, ss.FrictionTensor.isotropic(0.3), ss.State.from_speed(1, 5))\n"
        "fig = plot_trajectory(tr, title='t')\n"
        f"fig.savefig({str(tmp_path / 'f.png')!r})\n"
        "print('matplotlib.pyplot' in sys.modules, fig.get_layout_engine())\n"
    )
    out = subprocess.run(
        [sys.executable, "-W", "ignore", "-c", code], capture_output=True, text=True, check=True
    )
    assert out.stdout.split() == ["False", "None"]
    assert (tmp_path / "f.png").stat().st_size > 20_000


def test_with_pyplot_in_use_the_figure_is_pyplot_s(demo_run):
    import matplotlib.pyplot as plt

    fig = plot_trajectory(demo_run)
    try:
        assert plt.fignum_exists(fig.number)  # plt.show() would show it
        assert fig.get_layout_engine() is None
    finally:
        plt.close(fig)


def test_titles_are_placed_once_not_measured_at_each_draw(demo_run):
    fig = plot_trajectory(demo_run, title="demo")
    for ax in fig.axes:
        assert ax.get_title() and ax._autotitlepos is False, ax.get_title()


def test_nothing_sticks_out_of_the_figure_or_into_another_axes(demo_run, straight_run):
    """The fixed margins hold the tick labels, axis labels and titles of every panel."""
    for tr in (demo_run, straight_run):
        fig = plot_trajectory(tr, title="a title")
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        page = fig.bbox
        boxes = [ax.get_tightbbox(renderer) for ax in fig.axes]
        for ax, box in zip(fig.axes, boxes):
            assert page.x0 - 1 <= box.x0 and box.x1 <= page.x1 + 1, ax.get_title()
            assert page.y0 - 1 <= box.y0 and box.y1 <= page.y1 + 1, ax.get_title()
        for a, box in zip(fig.axes, boxes):  # labels and ticks of one panel off the others
            for b in fig.axes:
                if b is not a:
                    assert not box.overlaps(b.get_window_extent()), (a.get_title(), b.get_title())


# ---- the path panel takes the shape of the path --------------------------------------------
def test_a_long_straight_path_fills_a_panel_across_the_top(straight_run):
    fig = plot_trajectory(straight_run)
    path, beta, theta, v, w = fig.axes
    assert fill(path) > 0.6  # 0.08 before: a thin strip in a tall column
    # the time panels sit in one row below the path
    assert path.get_position().y0 > max(ax.get_position().y1 for ax in (beta, theta, v, w))
    assert len({round(ax.get_position().y0, 6) for ax in (beta, theta, v, w)}) == 1


def test_a_compact_path_keeps_its_column(demo_run):
    fig = plot_trajectory(demo_run)
    path, beta = fig.axes[:2]
    assert path.get_position().x1 < beta.get_position().x0
    assert fill(path) > 0.45
    assert fig.get_size_inches()[0] <= 12.5 + 1e-9


def loaded_run(force=(2.0, 0.0), torque=0.0, n=60, omega=None):
    """A LoadedTrajectory-like record of a disk pushed along x (the drawing reads only these)."""
    body = ss.Body(ss.Disk(0.05), ss.UniformPressure(), mass=1.0)
    t = np.linspace(0.0, 2.0, n)
    x = 0.3 * t**2
    return SimpleNamespace(
        body=body,
        t=t,
        x=x,
        y=np.zeros(n),
        phi=np.zeros(n) if omega is None else np.cumsum(omega) * (t[1] - t[0]),
        speed=0.6 * t,
        omega=np.zeros(n) if omega is None else omega,
        phases=(("stick", 0.0, 0.2), ("slip", 0.2, 2.0)),
        ending="moving_at_t_end",
        status="ok",
        incline=None,
        load=ss.Load(force=force, torque=torque),
        g=9.81,
    )


def test_loaded_push_path_is_not_mostly_empty():
    fig = plot_loaded_trajectory(loaded_run())
    path = fig.axes[0]
    box = path.dataLim
    assert box.width / box.height >= WIDE_PATH
    assert fill(path) > 0.5  # 0.06 before, in a column beside the time panels


def test_loaded_flat_spin_is_said_to_be_flat_with_sensible_limits():
    fig = plot_loaded_trajectory(loaded_run())
    spin = fig.axes[2]
    assert spin.get_title() == "spin rate"
    texts = [t.get_text() for t in spin.texts]
    assert any(t.startswith("ω = 0 throughout") for t in texts)
    assert spin.get_ylim() == (-1.0, 1.0)
    # a spin that changes gets no such note
    fig = plot_loaded_trajectory(loaded_run(omega=np.linspace(3.0, 0.0, 60)))
    assert not fig.axes[2].texts


def test_loaded_zero_force_component_is_named_not_drawn():
    fig = plot_loaded_trajectory(loaded_run(force=(2.0, 0.0)))
    force = fig.axes[3]
    labels = [ln.get_label() for ln in force.get_lines()]
    assert labels == ["$Q_x$ (force, x); $Q_y$ = 0"]
    # its colour is not the path's (they share the legend)
    assert force.get_lines()[0].get_color() != fig.axes[0].get_lines()[0].get_color()
    fig = plot_loaded_trajectory(loaded_run(force=(2.0, 1.0), torque=0.3))
    labels = [ln.get_label() for ax in fig.axes[3:] for ln in ax.get_lines()]
    assert labels == ["$Q_x$ (force, x)", "$Q_y$ (force, y)", "moment about G (right axis)"]


def test_loaded_legend_stays_outside_the_axes_in_both_layouts():
    for run in (loaded_run(), loaded_run(force=(0.0, 0.5))):
        fig = plot_loaded_trajectory(run)
        fig.canvas.draw()
        (legend,) = fig.legends
        box = legend.get_window_extent()
        assert box.y0 >= 0
        for ax in fig.axes:
            assert not box.overlaps(ax.get_window_extent()), ax.get_title()


# ---- the β panel -----------------------------------------------------------------------------
def test_beta_legend_uses_the_axis_s_unit_and_holds_the_off_scale_note():
    import matplotlib.figure

    ax = matplotlib.figure.Figure().add_subplot()
    t = np.linspace(0.0, 1.0, 50)
    ratio = np.where(t < 0.5, 50.0, 5.0 * (1.0 - t))  # off the scale, then down to 0
    draw_beta(ax, t, ratio, 0.0, symbol="β/ℓ")
    labels = [x.get_text() for x in ax.get_legend().get_texts()]
    assert labels == ["β*/ℓ = 0.0000", "|β/ℓ| > 10: off the scale"]
    assert not ax.texts  # no free-standing note that could sit on the β* line
    ax = matplotlib.figure.Figure().add_subplot()
    draw_beta(ax, t, ratio, math.inf)
    labels = [x.get_text() for x in ax.get_legend().get_texts()]
    assert labels == ["β* = ∞ (pure sliding)", "|β/a| > 10: off the scale"]


def test_footprint_trajectory_says_beta_over_l_everywhere():
    case = load_case(EXAMPLES / "box.toml")
    tr = ss.simulate(case.body, case.friction, case.initial_state, g=case.g, max_step=0.05)
    beta = plot_trajectory(tr).axes[1]
    assert beta.get_ylabel().startswith("β/ℓ")
    assert all("/ℓ" in x.get_text() for x in beta.get_legend().get_texts())


# ---- the ϑ panel at a stop ---------------------------------------------------------------------
def test_direction_is_not_drawn_where_the_speed_is_zero():
    import matplotlib.figure

    t = np.linspace(0.0, 1.0, 20)
    theta = np.full(20, 0.7)
    theta[-1] = 0.0  # atan2(0, 0) at the stop
    speed = np.linspace(1.0, 0.0, 20)
    ax = matplotlib.figure.Figure().add_subplot()
    draw_angle(ax, t, theta, 0.7, speed=speed)
    (line,) = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == 20]
    y = np.asarray(line.get_ydata(), dtype=float)
    assert np.isnan(y[-1]) and np.all(y[:-1] == 0.7)
    lo, hi = ax.get_ylim()
    assert lo < 0.7 < hi and hi - lo == pytest.approx(0.2)  # drawn as constant, no drop
    # once the data give the limit at the stop (ϑ = ϑ* there), that point is drawn
    theta[-1] = 0.7
    ax = matplotlib.figure.Figure().add_subplot()
    draw_angle(ax, t, theta, 0.7, speed=speed)
    (line,) = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == 20]
    assert np.asarray(line.get_ydata())[-1] == 0.7


def test_pure_spinning_stop_has_no_drop_in_its_theta_panel():
    from slidespin.analysis.intervals import inertia_intervals

    i3 = inertia_intervals(ss.UniformPressure(), ss.FrictionTensor(0.3, 0.3))[2]
    body = ss.Body.from_inertia_ratio(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), 1.0, 1.5 * i3)
    tr = ss.simulate(body, ss.FrictionTensor.isotropic(0.3), ss.State.from_speed(0.5, 10.0, 0.7))
    assert tr.ending == "pure_spinning"
    theta = plot_trajectory(tr).axes[2]
    (line,) = [ln for ln in theta.get_lines() if len(ln.get_xdata()) == tr.t.size]
    y = np.asarray(line.get_ydata(), dtype=float)
    y = y[np.isfinite(y)]
    assert np.ptp(y) < 1e-9 and y[-1] == pytest.approx(0.7, abs=1e-9)
    assert not any("-0.0000" in x.get_text() for x in theta.get_legend().get_texts())


# ---- sweep titles --------------------------------------------------------------------------------
def sweep_table():
    mu, ist = (a.ravel() for a in np.meshgrid([0.0, 0.1, 0.2], [0.2, 0.5, 0.8], indexing="ij"))
    n = mu.size
    return {
        "mu": mu,
        "I_star": ist,
        "beta_stop": 0.01 + mu * ist,
        "ending": np.array(["mixed"] * n, dtype=object),
        "status": np.array(["stopped"] * n, dtype=object),
    }


@pytest.mark.parametrize(
    "value, y, words",
    [
        ("beta_stop", "I_star", [r"$\beta^*$", "over the", r"$\mu$", "$I^*$", "9 cases"]),
        ("ending", "I_star", ["ending", "over the", r"$\mu$", "$I^*$"]),
        ("beta_stop", None, [r"$\beta^*$", "against", r"$\mu$", "one line per value of"]),
    ],
)
def test_every_sweep_figure_has_a_title_saying_what_over_what(value, y, words):
    fig = plot_sweep(sweep_table(), "mu", value, y, varied=["mu", "I_star"])
    title = fig.axes[0].get_title()
    for w in words:
        assert w in title, (w, title)
    assert fig.get_layout_engine() is None


def test_a_given_title_comes_first_and_the_description_stays():
    fig = plot_sweep(sweep_table(), "mu", "beta_stop", "I_star", title="my sweep")
    title = fig.axes[0].get_title()
    assert title.startswith("my sweep\n") and "over the" in title


def test_heat_map_text_stays_inside_the_figure():
    fig = plot_sweep(sweep_table(), "mu", "ending", "I_star")
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    page = fig.bbox
    for ax in fig.axes:  # the map and its colour bar (category names as tick labels)
        box = ax.get_tightbbox(renderer)
        assert page.x0 - 1 <= box.x0 and box.x1 <= page.x1 + 1
        assert page.y0 - 1 <= box.y0 and box.y1 <= page.y1 + 1


# ---- the fit figure ------------------------------------------------------------------------------
def fake_fit(n_runs=2, n=300):
    """What plot_fit reads of a FitResult: data, residuals, a prediction, the estimates."""
    rng = np.random.default_rng(7)
    data, res = [], []
    for k in range(n_runs):
        t = np.linspace(0.0, 1.0, n) + k
        truth = {"x": 0.3 * (t - k), "y": 0.1 * (t - k) ** 2, "phi": 2.0 * (t - k)}
        noise = {c: 1e-3 * rng.standard_normal(n) for c in truth}
        data.append({"t": t, **{c: truth[c] + noise[c] for c in truth}})
        res.append(noise)

    def predict(k, tt):
        s = tt - k
        return {"x": 0.3 * s, "y": 0.1 * s**2, "phi": 2.0 * s}

    return SimpleNamespace(
        n_runs=n_runs,
        data=data,
        residuals=res,
        predict=predict,
        estimates={"fx": 0.42},
        std_errors={"fx": 0.001},
        reduced_chi2=1.0,
    )


def test_fit_measured_points_and_fitted_lines_differ_in_kind_and_shade():
    fig = plot_fit(fake_fit(), title="fit")
    path, phi, rp, ra = fig.axes
    for ax in (path, phi):
        measured = [ln for ln in ax.get_lines() if ln.get_marker() == "o"]
        fitted = [ln for ln in ax.get_lines() if ln.get_linestyle() == "-"]
        assert len(measured) == len(fitted) == 2
        for m, f in zip(measured, fitted):
            assert m.get_linestyle() == "None" and m.get_markerfacecolor() == "white"
            assert f.get_marker() == "None" and f.get_zorder() > m.get_zorder()
            assert matplotlib.colors.to_rgb(f.get_color()) != matplotlib.colors.to_rgb(
                m.get_markeredgecolor()
            )
            assert len(m.get_xdata()) <= MARKS_PER_RUN
    labels = [x.get_text() for x in phi.get_legend().get_texts()]
    assert labels[:2] == ["run 0", "run 1"]
    assert labels[2].startswith("measured\n(every") and labels[3] == "fitted"
    # every measured point is in the residual panels
    assert sum(len(ln.get_xdata()) for ln in ra.get_lines()[:2]) == 600
    assert fig.get_layout_engine() is None
