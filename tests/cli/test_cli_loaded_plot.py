"""``slidespin simulate CASE.toml --plot`` for loaded cases (issue #13: [load], [incline],
t_end), and the loaded outcome vocabulary of :mod:`slidespin.motion.outcomes`.

The reference case is a closed form: a uniform disk (m = 1 kg, isotropic μ = 0.3, g = 9.81)
pushed through G by a force that ramps linearly, F(t) = μ m g t for 0 ≤ t ≤ 2 s, then falls
linearly to 0 at t = 3 s. Static friction holds it while F ≤ μ m g, i.e. until t = 1 s; it
then slides without turning, m dv/dt = F − μ m g, so v(2) = μ g/2, v(3) = μ g/2 again (the
excess and the deficit of F over μ m g cancel on [2, 3]), and it stops at t = 3.5 s under
friction alone. Phases: stick [0, 1], slip [1, 3.5], stick [3.5, t_end = 4]; the distance is
μ g (1/6 + 2/3 + 1/8) = 23 μ g / 24.
"""

from __future__ import annotations

import ast
import json
import math
from pathlib import Path

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from slidespin.cli.main import main  # noqa: E402
from slidespin.motion import outcomes  # noqa: E402
from slidespin.motion.simulate import simulate  # noqa: E402
from slidespin.studies.case import load_case  # noqa: E402
from slidespin.viz.trajectory_plot import STICK_GID, plot_loaded_trajectory, plot_trajectory  # noqa: E402

MU, G, MASS = 0.3, 9.81, 1.0
PEAK = 2.0 * MU * MASS * G  # the force at t = 2 s [N]
T_ONSET, T_STOP, T_END = 1.0, 3.5, 4.0
DISTANCE = 23.0 * MU * G / 24.0

RAMP = f"""
name = "central ramp"
[patch]
shape = "circle"
radius = 0.05
[pressure]
law = "uniform"
[friction]
fx = {MU}
fy = {MU}
[body]
mass = {MASS}
[initial]
vx = 0.0
[load]
times = [0.0, 2.0, 3.0]
profile_fx = [0.0, {PEAK!r}, 0.0]
profile_fy = [0.0, 0.0, 0.0]
[solver]
t_end = {T_END}
g = {G}
"""

SLOPE = """
name = "spinning puck on a slope"
[patch]
shape = "circle"
radius = 0.05
[pressure]
law = "uniform"
[friction]
fx = 0.3
fy = 0.3
[body]
mass = 1.0
[initial]
omega = 30.0
[incline]
angle_deg = 25.0
[solver]
t_end = 0.5
"""

SRC = Path(__file__).resolve().parents[2] / "src" / "slidespin"


@pytest.fixture(scope="module")
def ramp_case(tmp_path_factory):
    path = tmp_path_factory.mktemp("ramp") / "ramp.toml"
    path.write_text(RAMP)
    return path


@pytest.fixture(scope="module")
def ramp_traj(ramp_case):
    c = load_case(ramp_case)
    return simulate(
        c.body,
        c.friction,
        c.initial_state,
        g=c.g,
        rtol=c.rtol,
        max_steps=c.max_steps,
        load=c.load,
        incline=c.incline,
        t_end=c.t_end,
    )


def stick_spans(ax):
    """(t0, t1) in data coordinates of the spans marked as stick on a time axis."""
    spans = []
    for p in ax.patches:
        if p.get_gid() != STICK_GID:
            continue
        xy = p.get_patch_transform().transform(p.get_path().vertices)
        spans.append((float(xy[:, 0].min()), float(xy[:, 0].max())))
    return sorted(spans)


def test_ramp_phases_follow_the_closed_form(ramp_traj):
    """The reference itself: the engine's phases are the closed form's (to 1e-8 s)."""
    kinds = [k for k, _, _ in ramp_traj.phases]
    assert kinds == ["stick", "slip", "stick"]
    expected = [(0.0, T_ONSET), (T_ONSET, T_STOP), (T_STOP, T_END)]
    for (_, a, b), (ea, eb) in zip(ramp_traj.phases, expected):
        assert a == pytest.approx(ea, abs=1e-8) and b == pytest.approx(eb, abs=1e-8)
    assert ramp_traj.x[-1] == pytest.approx(DISTANCE, rel=1e-8)


def test_simulate_plot_writes_the_figure_for_a_loaded_case(ramp_case, tmp_path, capsys):
    png, csv = tmp_path / "ramp.png", tmp_path / "ramp.csv"
    assert main(["simulate", str(ramp_case), "--plot", str(png), "--csv", str(csv)]) == 0
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 20_000
    out = capsys.readouterr().out
    assert f"figure      : {png}" in out
    # the CSV does not depend on --plot (issue #10 item 5, now for loaded cases too)
    csv2 = tmp_path / "alone.csv"
    assert main(["simulate", str(ramp_case), "--csv", str(csv2)]) == 0
    assert csv2.read_bytes() == csv.read_bytes()


def test_bad_plot_path_is_refused_before_any_work(ramp_case, tmp_path, capsys):
    out = tmp_path / "x.jpgx"
    assert main(["simulate", str(ramp_case), "--plot", str(out)]) == 2
    assert "unknown figure format" in capsys.readouterr().err
    assert not out.exists()


def test_figure_axes_and_labels(ramp_traj):
    fig = plot_loaded_trajectory(ramp_traj, title="ramp")
    path, speed, spin, force = fig.axes[:4]
    assert (path.get_xlabel(), path.get_ylabel()) == ("x [m]", "y [m]")  # 2.8 m: metres
    assert speed.get_ylabel() == "v [m/s]"
    assert spin.get_ylabel() == "ω [rad/s]"
    assert force.get_ylabel() == "force [N]"
    assert force.get_xlabel() == "t [s]"
    assert len(fig.axes) == 4  # a push through G on a disk: no moment, no right-hand axis
    assert "stopped_stuck" in fig.get_suptitle() and "ok" in fig.get_suptitle()
    # the applied force drawn is the case's profile: peak PEAK at t = 2, zero after t = 3
    (qx,) = [ln for ln in force.get_lines() if ln.get_label().startswith("$Q_x$")]
    tq, fq = (np.asarray(d, dtype=float) for d in qx.get_data())
    assert fq.max() == pytest.approx(PEAK, rel=1e-12)
    assert tq[np.argmax(fq)] == pytest.approx(2.0, abs=1e-12)
    assert np.all(fq[tq >= 3.0] == 0.0)
    # the speed drawn is the run's: peak v(2.5) = μ g (1/2 + 1/4) from the closed form
    (v_line,) = speed.get_lines()
    assert np.max(v_line.get_ydata()) == pytest.approx(0.75 * MU * G, rel=1e-3)


def test_legend_is_outside_every_axes(ramp_traj):
    fig = plot_loaded_trajectory(ramp_traj)
    fig.canvas.draw()
    (legend,) = fig.legends
    box = legend.get_window_extent()
    texts = [t.get_text() for t in legend.get_texts()]
    assert "stick (held at rest)" in texts and "path of G" in texts
    for ax in fig.axes:
        assert not box.overlaps(ax.get_window_extent()), ax.get_title()
    assert all(ax.get_legend() is None for ax in fig.axes)


def test_shaded_stick_intervals_match_the_phases(ramp_traj):
    fig = plot_loaded_trajectory(ramp_traj)
    for ax in fig.axes[1:4]:
        spans = np.array(stick_spans(ax))
        assert spans == pytest.approx(np.array(ramp_traj.stick_intervals), abs=1e-12)
        # and against the closed form
        assert spans == pytest.approx(np.array([(0.0, T_ONSET), (T_STOP, T_END)]), abs=1e-8)
    # shaded means at rest in the data: every recorded instant in a span has v = ω = 0 (the
    # instant of the stop itself to round-off of the speed scale)
    v_max = ramp_traj.speed.max()
    for a, b in ramp_traj.stick_intervals:
        inside = (ramp_traj.t >= a) & (ramp_traj.t <= b)
        assert inside.sum() >= 2
        assert np.all(ramp_traj.speed[inside] <= 1e-15 * v_max)
        assert np.all(ramp_traj.omega[inside] == 0.0)
    (a, b) = ramp_traj.slip_intervals[0]
    moving = (ramp_traj.t > a) & (ramp_traj.t < b)
    assert moving.any() and np.all(ramp_traj.speed[moving] > 0.0)


def test_plot_trajectory_dispatches_loaded_runs(ramp_traj):
    fig = plot_trajectory(ramp_traj)
    assert [ax.get_title() for ax in fig.axes[1:4]] == ["speed of G", "spin rate", "applied load"]


def test_slope_figure_draws_gravity_and_a_moving_end(tmp_path, capsys):
    case = tmp_path / "slope.toml"
    case.write_text(SLOPE)
    png = tmp_path / "slope.png"
    assert main(["simulate", str(case), "--plot", str(png), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["ending"] == "moving_at_t_end" and png.stat().st_size > 20_000
    c = load_case(case)
    tr = simulate(c.body, c.friction, c.initial_state, g=c.g, incline=c.incline, t_end=c.t_end)
    fig = plot_loaded_trajectory(tr)
    path, _, _, force = fig.axes[:4]
    assert "tilted 25°" in path.get_title() and "gravity" in force.get_title()
    assert stick_spans(force) == []  # it never sticks
    (qx,) = [ln for ln in force.get_lines() if ln.get_label().startswith("$Q_x$")]
    pull = 1.0 * 9.81 * math.sin(math.radians(25.0))  # m g sin α down the slope (+x)
    assert np.asarray(qx.get_ydata()) == pytest.approx(pull, rel=1e-14)
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "end: moving at t_end" in texts


# ---- the loaded vocabulary ----------------------------------------------------------------


def _literals(path: Path, names: set[str]) -> set[str]:
    """String constants assigned to the variables ``names`` anywhere in a module."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if (
            isinstance(node, ast.Assign)
            and isinstance(node.value, ast.Constant)
            and isinstance(node.value.value, str)
        ):
            if any(isinstance(t, ast.Name) and t.id in names for t in node.targets):
                found.add(node.value.value)
    return found


def test_every_outcome_has_a_one_line_message():
    pairs = [
        (outcomes.STATUSES, outcomes.STATUS_MESSAGES),
        (outcomes.ENDINGS, outcomes.ENDING_MESSAGES),
        (outcomes.LOADED_STATUSES, outcomes.LOADED_STATUS_MESSAGES),
        (outcomes.LOADED_ENDINGS, outcomes.LOADED_ENDING_MESSAGES),
    ]
    for names, messages in pairs:
        assert set(names) == set(messages) and len(set(names)) == len(names)
        for name in names:
            assert messages[name].strip() and "\n" not in messages[name]
    for name in outcomes.LOADED_STATUSES:
        assert outcomes.status_message(name, loaded=True) == outcomes.LOADED_STATUS_MESSAGES[name]
    for name in outcomes.LOADED_ENDINGS:
        assert outcomes.ending_message(name, loaded=True) == outcomes.LOADED_ENDING_MESSAGES[name]
    for name in outcomes.ENDINGS:
        assert outcomes.ending_message(name) == outcomes.ENDING_MESSAGES[name]


def test_loaded_statuses_are_partitioned():
    conv, flag, unconv = (
        outcomes.LOADED_CONVERGED,
        outcomes.LOADED_FLAGGED,
        outcomes.LOADED_UNCONVERGED,
    )
    assert conv | flag | unconv == set(outcomes.LOADED_STATUSES)
    assert not (conv & flag or conv & unconv or flag & unconv)
    assert conv == {"ok", "tipping"}  # tipping (MODEL §14): a located, physical end


def test_unloaded_vocabulary_is_unchanged():
    assert outcomes.STATUSES == (
        "stopped",
        "max_steps",
        "step_too_small",
        "at_rest",
        "marginal",
        "saddle",
        "non_finite",
    )
    assert outcomes.ENDINGS == ("mixed", "pure_sliding", "pure_spinning", "at_rest", "spiral")
    assert outcomes.CONVERGED == {"stopped", "at_rest"}
    assert outcomes.FLAGGED == {"marginal", "saddle"}
    assert outcomes.UNCONVERGED == {"max_steps", "step_too_small", "non_finite"}
    assert outcomes.status_message("saddle") == outcomes.STATUS_MESSAGES["saddle"]


@pytest.mark.parametrize("name, loaded", [("ok", False), ("stopped", True), ("nope", True)])
def test_a_name_outside_the_vocabulary_is_refused(name, loaded):
    with pytest.raises(ValueError, match=repr(name)):
        outcomes.status_message(name, loaded=loaded)
    with pytest.raises(ValueError, match="ending"):
        outcomes.ending_message(name, loaded=loaded)


def test_every_outcome_the_loaded_engine_can_report_is_in_the_vocabulary():
    """Read from loaded.py's source (not from outcomes.py): every status and ending it can
    assign has a name and a message here."""
    src = SRC / "motion" / "loaded.py"
    statuses = _literals(src, {"status"})
    endings = _literals(src, {"ending"})
    assert "ok" in statuses and "max_phases" in statuses and "no_onset" in statuses
    assert statuses <= set(outcomes.LOADED_STATUSES)
    assert endings <= set(outcomes.LOADED_ENDINGS)
    import slidespin.motion.loaded as loaded

    assert tuple(loaded.LOADED_ENDINGS) == outcomes.LOADED_ENDINGS


def test_json_and_summary_carry_the_messages(ramp_case, capsys):
    assert main(["simulate", str(ramp_case), "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["status"] == "ok" and s["ending"] == "stopped_stuck"
    assert s["status_message"] == outcomes.LOADED_STATUS_MESSAGES["ok"]
    assert s["ending_message"] == outcomes.LOADED_ENDING_MESSAGES["stopped_stuck"]
    assert s["t_stop"] == pytest.approx(T_STOP, abs=1e-8)
    assert main(["simulate", str(ramp_case)]) == 0
    text = capsys.readouterr().out
    assert f"status      : ok  ({outcomes.LOADED_STATUS_MESSAGES['ok']})" in text
    assert "phases      : stick 0-1 s, slip 1-3.5 s, stick 3.5-4 s" in text


def test_unconverged_loaded_run_exits_1_with_its_message(tmp_path, capsys):
    case = tmp_path / "short.toml"
    case.write_text(SLOPE + "max_steps = 3\n")
    assert main(["simulate", str(case), "--json"]) == 1
    s = json.loads(capsys.readouterr().out)
    assert s["status"] == "max_steps"
    assert s["status_message"] == outcomes.LOADED_STATUS_MESSAGES["max_steps"]
    assert s["t_final"] < 0.5  # ended early: values as reached
