"""Progress bars of the long commands (`sweep`, `reproduce`, `fit`, `bench`): the shared tqdm
bar of :mod:`slidespin._progress`, drawn on stderr only when it is a terminal, never with
``--quiet``; nothing on stderr otherwise.

A terminal is simulated by making :func:`slidespin._progress.show_progress` answer as on a
TTY (the bar is then written to the captured stderr).
"""

from __future__ import annotations

import importlib
import math
import time
from pathlib import Path

import numpy as np
import pytest

import slidespin as ss
import slidespin._progress as progress
from slidespin.cli.main import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture
def terminal(monkeypatch):
    """stderr behaves as a terminal for the bars."""
    monkeypatch.setattr(
        progress, "show_progress", lambda enabled: True if enabled is None else bool(enabled)
    )


def slow(result=None, seconds=0.7):
    def stub(*args, **kwargs):
        time.sleep(seconds)
        return result

    return stub


# ------------------------------------------------------------------------------ reproduce
def test_reproduce_draws_a_bar_on_a_terminal(terminal, capsys):
    assert main(["reproduce", "table2"]) == 0
    cap = capsys.readouterr()
    assert "reproduce table2" in cap.err and "task" in cap.err
    assert "Table 2" in cap.out or "table 2" in cap.out.lower()
    assert "reproduce table2" not in cap.out  # the bar never reaches stdout


@pytest.mark.parametrize("quiet, on_terminal", [(True, True), (False, False), (True, False)])
def test_reproduce_is_silent_when_quiet_or_not_on_a_terminal(
    monkeypatch, capsys, quiet, on_terminal
):
    if on_terminal:
        monkeypatch.setattr(progress, "show_progress", lambda e: True if e is None else bool(e))
    table2 = importlib.import_module("slidespin.paper.table2")
    monkeypatch.setattr(table2, "main", slow())
    assert main(["reproduce", "table2"] + (["--quiet"] if quiet else [])) == 0
    assert capsys.readouterr().err == ""


def test_busy_bar_refreshes_the_elapsed_time(terminal, capsys):
    from slidespin.cli._busy import busy

    with busy("waiting") as bar:
        time.sleep(1.3)
        print("held until the bar is gone")
    cap = capsys.readouterr()
    assert cap.err.count("waiting") >= 3  # the first draw and two refreshes at least
    assert bar.n == 1
    assert cap.out == "held until the bar is gone\n"


# ------------------------------------------------------------------------------------ fit
def small_fit_data(path):
    body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), 1.0)
    tr = ss.simulate(body, ss.FrictionTensor(0.42, 0.54), ss.State.from_speed(1.0, 6.0, 0.6))
    t = np.linspace(0.0, 0.8 * tr.t_stop, 40)
    cols = [t] + [np.interp(t, tr.t, getattr(tr, k)) for k in ("x", "y", "phi")]
    rows = ["t,x,y,phi"] + [",".join(repr(float(c[i])) for c in cols) for i in range(t.size)]
    path.write_text("\n".join(rows) + "\n")


CASE = """[patch]
a = 0.1
eccentricity = 0.866
[pressure]
law = "uniform"
[friction]
fx = 0.4
fy = 0.5
[body]
mass = 1.0
"""


def test_fit_draws_a_bar_on_a_terminal(terminal, tmp_path, capsys):
    data, case = tmp_path / "d.csv", tmp_path / "c.toml"
    small_fit_data(data)
    case.write_text(CASE)
    code = main(["fit", str(data), "--case", str(case), "--free", "fx,fy", "--json"])
    cap = capsys.readouterr()
    assert code in (0, 1)
    assert "fit" in cap.err and "task" in cap.err
    assert cap.out.lstrip().startswith("{")  # the JSON alone on stdout


@pytest.mark.parametrize("quiet", [True, False])
def test_fit_is_silent_when_quiet_or_not_on_a_terminal(monkeypatch, tmp_path, capsys, quiet):
    import slidespin.analysis.fit as fit_mod

    if quiet:
        monkeypatch.setattr(progress, "show_progress", lambda e: True if e is None else bool(e))

    class Done(Exception):
        pass

    def stub(*args, **kwargs):
        time.sleep(0.7)
        raise Done

    monkeypatch.setattr(fit_mod, "fit", stub)
    data, case = tmp_path / "d.csv", tmp_path / "c.toml"
    data.write_text("t,x\n0,0\n0.1,0.01\n0.2,0.015\n")
    case.write_text(CASE)
    with pytest.raises(Done):
        main(["--debug", "fit", str(data), "--case", str(case)] + (["--quiet"] if quiet else []))
    assert capsys.readouterr().err == ""


# ---------------------------------------------------------------------------------- bench
TINY = [
    "bench",
    "--quick",
    "--no-compile",
    "--naive-seconds",
    "1",
    "--batch",
    "20",
    "--memory-cases",
    "20",
    "--sweep-local",
    "40",
    "--sweep-dask",
    "0",
    "--no-save",
]


class SpyBar:
    """Records what the bench tells its bar."""

    made: list = []

    def __init__(self, total, desc, unit="case", enabled=None):
        self.total, self.n, self.descs, self.details = total, 0, [desc], []
        SpyBar.last = self
        SpyBar.made.append(self)

    def update(self, n=1):
        self.n += n

    def set_description(self, desc):
        self.descs.append(desc)

    def set_postfix_str(self, text):
        self.details.append(text)

    def close(self):
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


def test_bench_advances_one_stage_at_a_time_and_is_silent_off_a_terminal(monkeypatch, capsys):
    monkeypatch.setattr(progress, "progress_bar", SpyBar)
    SpyBar.made.clear()
    assert main(TINY) == 0
    cap = capsys.readouterr()
    (bar,) = [b for b in SpyBar.made if b.descs[0] == "bench"]
    stages = [d for d in bar.descs if d.startswith("bench: ")]
    assert len(stages) == bar.total and bar.n == bar.total
    assert "bench: report" == stages[-1] and "bench: wrench" in stages
    assert "  ... " not in cap.err  # the old log lines are gone
    assert "| quantity" in cap.out


@pytest.mark.parametrize("quiet", [True, False])
def test_bench_bar_follows_quiet(monkeypatch, capsys, terminal, quiet):
    import slidespin.cli.bench as bench
    from slidespin.cli import _bench_cases

    def stages(*args):
        for name in ("one", "two", "three"):
            _bench_cases._stage(name)
            time.sleep(0.15)
        return "the report"

    monkeypatch.setattr(bench, "_run", stages)
    assert main(TINY + (["--quiet"] if quiet else [])) == 0
    cap = capsys.readouterr()
    assert cap.out == "the report\n"
    if quiet:
        assert cap.err == ""
    else:
        assert "bench: three" in cap.err


# ---------------------------------------------------------------------------------- sweep
SPEC = """kind = "grid"
chunk_size = 2
[fixed]
a = 0.05
fx = 0.3
v0 = 0.5
omega0 = 5.0
[vary]
mu = [0.0, 0.1, 0.2, 0.3, 0.4]
"""


def test_sweep_uses_the_shared_bar_and_quiet_silences_it(terminal, tmp_path, capsys):
    spec = tmp_path / "s.toml"
    spec.write_text(SPEC)
    assert main(["sweep", str(spec), "--out", str(tmp_path / "a")]) == 0
    err = capsys.readouterr().err
    assert "sweep:" in err and "/5 [" in err and "case/s" in err  # tqdm draws what it has time for
    assert main(["sweep", str(spec), "--out", str(tmp_path / "b"), "--quiet"]) == 0
    assert capsys.readouterr().err == ""


def test_sweep_bar_starts_at_the_cases_done(tmp_path):
    from slidespin.studies.sweep import _progress_bar

    bar = _progress_bar(10, 4, True)
    assert (bar.n, bar.initial, bar.total) == (4, 4, 10)
    bar.update(6)
    assert bar.n == 10
    bar.close()


def test_statics_sweep_bar_moves_with_every_case(monkeypatch, tmp_path):
    from slidespin.studies.sweep import sweep

    monkeypatch.setattr(progress, "progress_bar", SpyBar)
    spec = {
        "kind": "grid",
        "chunk_size": 4,
        "compute": "statics",
        "fixed": {"a": 0.05, "fx": 0.3, "mu": 0.0, "incline_angle_deg": 10.0},
        "vary": {"phi0": [0.0, 0.2, 0.4, 0.6, 0.8]},
    }
    updates = []
    real_update = SpyBar.update

    def record(self, n=1):
        updates.append(n)
        real_update(self, n)

    monkeypatch.setattr(SpyBar, "update", record)
    sweep(spec, tmp_path / "s", progress=True)
    assert SpyBar.last.n == 5 and SpyBar.last.total == 5
    assert updates.count(1) >= 5  # one step per case, not one per chunk
    assert math.isclose(sum(updates), 5)
