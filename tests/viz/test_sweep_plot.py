"""``slidespin sweep-plot`` (issue #10 items 4 and 5): categories, no zig-zag, fixed
parameters refused, marks for left-out and flagged cells, notes that do not overlap."""

from __future__ import annotations

import re

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from slidespin.cli.main import main  # noqa: E402
from slidespin.viz.sweep_plot import axis_label, plot_sweep  # noqa: E402

MU = np.array([0.0, 0.1, 0.2])
ISTAR = np.array([0.2, 0.5, 0.8, 1.1])


def grid_table(extra_axis=None):
    """A hand-made 3 x 4 grid (mu, I*): mu = 0.2 did not converge, I* = 0.2 is a saddle,
    mu = 0 ends in pure sliding (β* = ∞)."""
    mu, ist = (a.ravel() for a in np.meshgrid(MU, ISTAR, indexing="ij"))
    cols = {"mu": mu, "I_star": ist}
    if extra_axis:
        mu = np.concatenate([mu, mu])
        ist = np.concatenate([ist, ist])
        cols = {"mu": mu, "I_star": ist, "v0": np.repeat([0.5, 1.0], MU.size * ISTAR.size)}
    n = mu.size
    status = np.where(mu > 0.15, "max_steps", np.where(ist < 0.3, "saddle", "stopped"))
    ending = np.where(mu == 0.0, "pure_sliding", "mixed")
    return dict(
        cols,
        case_id=np.arange(n),
        fx=np.full(n, 0.3),
        fy=0.3 + mu,
        beta_stop=np.where(mu == 0.0, np.inf, 0.01 + mu * ist),
        status=status.astype(object),
        ending=ending.astype(object),
    )


def lines_with_marker(ax, marker):
    return [ln for ln in ax.get_lines() if ln.get_marker() == marker and len(ln.get_xdata())]


def test_heat_map_marks_left_out_and_flagged_cells():
    fig = plot_sweep(grid_table(), "mu", "beta_stop", "I_star", varied=["mu", "I_star"])
    ax = fig.axes[0]
    crosses = {
        (round(float(x), 6), round(float(y), 6))
        for ln in lines_with_marker(ax, "x")
        for x, y in zip(ln.get_xdata(), ln.get_ydata())
    }
    assert crosses == {(0.2, float(i)) for i in ISTAR}  # the max_steps cases
    circles = {
        (round(float(x), 6), round(float(y), 6))
        for ln in lines_with_marker(ax, "o")
        for x, y in zip(ln.get_xdata(), ln.get_ydata())
    }
    assert circles == {(0.0, 0.2), (0.1, 0.2)}  # the saddles kept (mu = 0.2 is left out)
    # the mean shown per cell leaves the unconverged cases out
    mesh = np.ma.filled(ax.collections[0].get_array(), np.nan).reshape(ISTAR.size, MU.size)
    assert np.isnan(mesh[:, 2]).all() and np.isnan(mesh[:, 0]).all()  # left out; β* = ∞
    assert mesh[2, 1] == pytest.approx(0.01 + 0.1 * 0.8)
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert any("left out: 4 unconverged cases (max_steps 4)" in t for t in labels)
    assert any("saddle 2" in t for t in labels) and any(t.startswith("blank") for t in labels)


def test_notes_do_not_overlap_the_axis_label():
    fig = plot_sweep(grid_table(), "mu", "beta_stop", "I_star", varied=["mu", "I_star"])
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    label = fig.axes[0].xaxis.label.get_window_extent(renderer)
    legend = fig.legends[0].get_window_extent(renderer)
    ticks = fig.axes[0].xaxis.get_tightbbox(renderer)
    assert not label.overlaps(legend) and not ticks.overlaps(legend)
    assert legend.y1 <= label.y0 + 1  # the notes sit below the label
    assert legend.y0 >= 0  # and inside the figure


def test_categories_are_drawn():
    fig = plot_sweep(grid_table(), "mu", "ending", "I_star", include_unconverged=True)
    cbar = fig.axes[1]
    assert [t.get_text() for t in cbar.get_yticklabels()] == ["mixed", "pure sliding"]
    fig = plot_sweep(
        grid_table(), "mu", "status", varied=["mu", "I_star"], include_unconverged=True
    )
    ticks = [t.get_text() for t in fig.axes[0].get_yticklabels()]
    assert ticks == ["stopped", "saddle", "max steps"]


def test_line_plot_of_a_two_axis_grid_draws_one_line_per_value():
    fig = plot_sweep(
        grid_table(), "mu", "beta_stop", varied=["mu", "I_star"], include_unconverged=True
    )
    ax = fig.axes[0]
    data = [ln for ln in ax.get_lines() if ln.get_label().startswith("$I^*")]
    assert len(data) == ISTAR.size
    for ln in data:  # no zig-zag: every line runs forward in x
        x = np.asarray(ln.get_xdata())
        assert np.all(np.diff(x) > 0)
        assert len(set(np.round(x, 9))) == len(x)


def test_line_plot_of_three_axes_is_refused():
    with pytest.raises(ValueError, match="varies mu, I_star, v0.*give --y I_star"):
        plot_sweep(grid_table(extra_axis=True), "mu", "beta_stop", varied=["mu", "I_star", "v0"])


def test_random_sweeps_are_points_not_lines():
    rng = np.random.default_rng(1)
    n = 50
    t = {
        "mu": rng.uniform(0, 0.3, n),
        "I_star": rng.uniform(0.2, 1, n),
        "beta_stop": rng.uniform(0, 0.1, n),
        "status": np.full(n, "stopped", dtype=object),
    }
    fig = plot_sweep(t, "mu", "beta_stop", varied=["mu", "I_star"], kind="random")
    data = [ln for ln in fig.axes[0].get_lines() if len(ln.get_xdata()) > 1]
    assert data and all(ln.get_linestyle() == "None" for ln in data)


def test_fixed_parameter_is_refused_with_its_value():
    with pytest.raises(ValueError, match=r"--x fx is fixed at 0\.3 in this sweep.*varied: mu"):
        plot_sweep(grid_table(), "fx", "beta_stop", varied=["mu", "I_star"])
    with pytest.raises(ValueError, match=r"--y fx is fixed"):
        plot_sweep(grid_table(), "mu", "beta_stop", "fx", varied=["mu", "I_star"])


@pytest.mark.parametrize(
    "name",
    [
        "fx",
        "fy",
        "mu",
        "I_star",
        "theta0",
        "omega0",
        "beta_stop",
        "theta_stop",
        "x_stop",
        "path_length",
        "n_steps",
        "xi_c",
        "moment_of_inertia",
        "some_new_column",
    ],
)
def test_labels_have_no_raw_underscores(name):
    text = re.sub(r"\$[^$]*\$", "", axis_label(name))  # mathtext renders its subscripts
    assert "_" not in text and text.strip() or axis_label(name).startswith("$")


# ------------------------------------------------------------------------------ the command
SPEC = (
    'name = "p"\nkind = "grid"\nchunk_size = 6\n[fixed]\na = 0.05\nfx = 0.3\nv0 = 1.0\n'
    "omega0 = 10.0\n[vary]\nmu = [0.0, 0.1, 0.2]\nI_star = [0.2, 0.5, 0.8, 1.1]\n"
)


@pytest.fixture
def sweep_dir(tmp_path, monkeypatch):
    from slidespin.studies import sweep_chunk as sw
    from test_sweep_outcomes import fake_engine

    monkeypatch.setattr(sw, "simulate_cases", fake_engine)
    spec = tmp_path / "spec.toml"
    spec.write_text(SPEC)
    assert main(["sweep", str(spec), "--out", str(tmp_path / "s"), "--quiet"]) == 1
    return tmp_path / "s"


def test_cli_value_ending_and_left_out_note(sweep_dir, tmp_path, capsys):
    capsys.readouterr()
    png = tmp_path / "e.png"
    assert (
        main(
            [
                "sweep-plot",
                str(sweep_dir),
                "--x",
                "mu",
                "--y",
                "I_star",
                "--value",
                "ending",
                "--out",
                str(png),
            ]
        )
        == 0
    )
    assert png.stat().st_size > 10_000
    out = capsys.readouterr().out
    assert "left out    : 4 unconverged cases (max_steps 4)" in out


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["--x", "fx"], "--x fx is fixed at 0.3"),
        (["--x", "mu", "--y", "mu"], "both 'mu'"),
        (["--x", "mu", "--out", "p.jpgx"], "unknown figure format 'jpgx'"),
    ],
)
def test_cli_refusals_are_one_line(sweep_dir, tmp_path, capsys, args, fragment, monkeypatch):
    monkeypatch.chdir(tmp_path)
    capsys.readouterr()
    before = sorted(p.name for p in tmp_path.iterdir())
    assert main(["sweep-plot", str(sweep_dir)] + args) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and fragment in err and "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == before  # nothing written
