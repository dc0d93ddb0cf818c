"""``slidespin fit`` (slidespin.cli.fit) and the shipped synthetic example.

The plugin is registered here the way slidespin.cli.main registers its plugins, so the tests
run through ``slidespin.cli.main`` (one-line errors, exit status 2) whether or not the
line is already in ``cli._PLUGINS``.
"""

from __future__ import annotations

import csv
import importlib.util
import json
import os

import numpy as np
import pytest

import slidespin as ss

cli = importlib.import_module("slidespin.cli.main")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = os.path.join(ROOT, "examples")
DATA = os.path.join(EXAMPLES, "fit_synthetic.csv")
CASE = os.path.join(EXAMPLES, "fit_case.toml")


@pytest.fixture(autouse=True)
def fit_plugin(monkeypatch):
    if not any(name == "fit" for name, *_ in cli._PLUGINS):
        monkeypatch.setattr(
            cli,
            "_PLUGINS",
            cli._PLUGINS
            + (("fit", "slidespin.cli.fit", "fit friction parameters to tracked motion"),),
        )


def example_module():
    spec = importlib.util.spec_from_file_location(
        "fit_synthetic", os.path.join(EXAMPLES, "fit_synthetic.py")
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def write_csv(path, runs):
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["run", "t", "x", "y", "phi"])
        for k, run in enumerate(runs):
            for i in range(run["t"].size):
                w.writerow([k] + [repr(float(run[c][i])) for c in ("t", "x", "y", "phi")])


CASE_TEXT = """
[patch]
a = 0.1
eccentricity = 0.866
[pressure]
law = "uniform"
[friction]
fx = 0.3
fy = 0.3
[body]
mass = 1.0
"""


def small_runs(rng, states, n=60, sigma=(1e-3, 1e-3, 1e-2)):
    fr = ss.FrictionTensor(0.42, 0.54, 0.04)
    body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), 1.0)
    runs = []
    for st in states:
        tr = ss.simulate(body, fr, st, max_step=0.002)
        t = np.linspace(0.0, 1.05 * tr.t_stop, n)
        runs.append(
            {
                "t": t,
                **{
                    c: np.interp(t, tr.t, getattr(tr, c)) + rng.normal(0, s, n)
                    for c, s in zip(("x", "y", "phi"), sigma)
                },
            }
        )
    return runs


def test_shipped_dataset_is_what_the_script_makes():
    mod = example_module()
    runs, _ = mod.make_runs()
    with open(DATA, newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == len(runs) * mod.N_POINTS == 1000
    for row in rows[::97]:
        run = runs[int(row["run"])]
        i = int(np.argmin(np.abs(run["t"] - float(row["t"]))))
        assert float(row["x"]) == pytest.approx(run["x"][i], abs=1e-6)
        assert float(row["phi"]) == pytest.approx(run["phi"][i], abs=1e-5)


def test_example_fit_json_recovers_the_truth(capsys):
    mod = example_module()
    code = cli.main(["fit", DATA, "--case", CASE, "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == 0
    assert out["n_runs"] == 5 and out["n_points"] == 3000
    for name, truth in mod.TRUTH.items():
        est, se = out["estimates"][name], out["std_errors"][name]
        assert abs(est - truth) < 3.0 * se, name
        assert se < 2e-3
    assert out["warnings"] == []
    assert set(out["correlation"]) == {"fx", "fy", "f"}
    assert out["correlation"]["fx"]["fx"] == pytest.approx(1.0)
    assert out["sigma"]["x"] == pytest.approx(mod.SIGMA["x"], rel=0.1)
    assert out["dof"] == 3000 - 3 - 5 * 6
    assert len(out["starts"]) == 5 and out["runs"] == ["0", "1", "2", "3", "4"]


def test_table_and_figure(tmp_path, capsys):
    rng = np.random.default_rng(1)
    data = tmp_path / "d.csv"
    write_csv(
        data,
        small_runs(
            rng, [ss.State.from_speed(1.0, 6.0, 0.6, 0.2), ss.State.from_speed(0.9, -9.0, 2.0, 1.0)]
        ),
    )
    case = tmp_path / "c.toml"
    case.write_text(CASE_TEXT)
    png = tmp_path / "fit.png"
    code = cli.main(
        [
            "fit",
            str(data),
            "--case",
            str(case),
            "--plot",
            str(png),
            "--sigma",
            "x=1e-3,y=1e-3,phi=0.01",
        ]
    )
    out = capsys.readouterr().out
    assert code == 0
    assert "std error" in out and "fx" in out and "chi2 / dof" in out
    assert "(estimated)" not in out  # sigma given for every channel
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_run_along_x_warns_on_stderr_and_reports_null(tmp_path, capsys):
    rng = np.random.default_rng(3)
    fx, v0, g = 0.4, 1.0, 9.81
    t = np.linspace(0.0, 1.2 * v0 / (fx * g), 80)
    tc = np.minimum(t, v0 / (fx * g))
    run = {
        "t": t,
        "x": v0 * tc - 0.5 * fx * g * tc**2 + rng.normal(0, 1e-3, t.size),
        "y": rng.normal(0, 1e-3, t.size),
        "phi": rng.normal(0, 1e-2, t.size),
    }
    data = tmp_path / "x.csv"
    write_csv(data, [run])
    case = tmp_path / "c.toml"
    case.write_text(CASE_TEXT)
    code = cli.main(["fit", str(data), "--case", str(case), "--free", "fx,fy", "--json"])
    cap = capsys.readouterr()
    out = json.loads(cap.out)
    assert code == 0
    assert "slidespin: warning: the data cannot determine fy" in cap.err
    assert out["std_errors"]["fy"] is None and out["identifiable"]["fy"] is False
    assert abs(out["estimates"]["fx"] - fx) < 3 * out["std_errors"]["fx"]


def test_fixed_start_uses_the_case_initial_state(tmp_path, capsys):
    rng = np.random.default_rng(4)
    st = ss.State.from_speed(1.0, 6.0, 0.6, 0.2)
    data = tmp_path / "d.csv"
    write_csv(data, small_runs(rng, [st]))
    case = tmp_path / "c.toml"
    case.write_text(CASE_TEXT + "[initial]\nspeed = 1.0\nomega = 6.0\ntheta = 0.6\nphi = 0.2\n")
    assert cli.main(["fit", str(data), "--case", str(case), "--fixed-start", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["starts"][0]["vx"] == pytest.approx(st.vx, rel=1e-12)
    assert out["starts"][0]["std_errors"] == {}
    assert out["dof"] == 180 - 3


@pytest.mark.parametrize(
    "extra, match",
    [
        (["--plot", "out.xyz"], "--plot = 'out.xyz': unknown figure format"),
        (["--plot", "no/such/dir/out.png"], "does not exist"),
        (["--free", "fx,mu"], "--free: free parameter 'mu' is unknown"),
        (["--free", "xi_c"], "LinearPressure"),
        (["--sigma", "x=-1"], "--sigma x = -1.0"),
        (["--sigma", "z=1"], "--sigma item 'z=1'"),
        (["--sigma", "x=abc"], "--sigma x = 'abc' is not a number"),
        (["--fixed-start"], "--fixed-start needs an \\[initial\\] table"),
    ],
)
def test_bad_options_exit_2_with_one_line(tmp_path, capsys, monkeypatch, extra, match):
    monkeypatch.chdir(tmp_path)
    case = tmp_path / "c.toml"
    case.write_text(CASE_TEXT)
    code = cli.main(["fit", DATA, "--case", str(case)] + extra)
    err = capsys.readouterr().err
    assert code == 2
    assert err.startswith("slidespin: error: ") and err.count("\n") == 1
    import re

    assert re.search(match, err), err
    assert not os.path.exists(tmp_path / "out.xyz")


def test_plot_checked_before_the_data_is_read(tmp_path, capsys):
    code = cli.main(["fit", str(tmp_path / "missing.csv"), "--case", CASE, "--plot", "x.bad"])
    assert code == 2 and "--plot" in capsys.readouterr().err


@pytest.mark.parametrize(
    "data_text, case_text, match",
    [
        (None, CASE_TEXT, "data file .* does not exist"),
        ("t,x\n0,1\n0.1,abc\n", CASE_TEXT, "line 3, column 'x': 'abc' is not a number"),
        ("t,x\n0,1\n", CASE_TEXT.replace("fx = 0.3", "fx = -1"), r"c.toml: \[friction\] fx"),
        ("t,x\n0,1\n", CASE_TEXT + "[bogus]\n", "unknown table or key 'bogus'"),
        ("t,x\n0,1\n0.1,2\n", CASE_TEXT, "too few measured values"),
    ],
)
def test_bad_files_exit_2(tmp_path, capsys, data_text, case_text, match):
    data = tmp_path / "d.csv"
    if data_text is not None:
        data.write_text(data_text)
    case = tmp_path / "c.toml"
    case.write_text(case_text)
    code = cli.main(["fit", str(data), "--case", str(case)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1
    import re

    assert re.search(match, err), err


def test_missing_case_file(capsys):
    assert cli.main(["fit", DATA, "--case", "/nonexistent/case.toml"]) == 2
    assert "case file" in capsys.readouterr().err


def test_help_lists_the_free_parameters(capsys):
    assert cli.main(["fit", "--help"]) == 0
    out = capsys.readouterr().out
    assert "moment_of_inertia" in out and "--sigma" in out


def test_frame_best_reports_both_scores(tmp_path, capsys):
    rng = np.random.default_rng(5)
    data = tmp_path / "d.csv"
    write_csv(data, small_runs(rng, [ss.State.from_speed(1.0, 6.0, 0.6, 0.2)]))
    case = tmp_path / "c.toml"
    case.write_text(CASE_TEXT)
    assert cli.main(["fit", str(data), "--case", str(case), "--frame", "best", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out["frame_scores"]) == {"plane", "body"}
    assert out["frame"] == "plane"  # the data were made with a plane tensor
    assert out["frame_scores"]["plane"] < out["frame_scores"]["body"]
