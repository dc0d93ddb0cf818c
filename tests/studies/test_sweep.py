"""Parameter sweeps: specs, determinism, storage, resume after a kill, Dask = local."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import slidespin as ss
from slidespin.studies.sweep import sweep
from slidespin.studies.sweep_parse import load_spec
from slidespin.studies.sweep_read import read_sweep
from slidespin.studies.sweep_spec import SweepError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def same(x, y) -> bool:
    """Exact equality of two result columns (NaN equal to NaN in float columns)."""
    x, y = np.asarray(x), np.asarray(y)
    if x.dtype.kind == "f" and y.dtype.kind == "f":
        return np.array_equal(x, y, equal_nan=True)
    return np.array_equal(x, y)


def small_spec(**over):
    spec = {
        "name": "test",
        "kind": "grid",
        "chunk_size": 7,
        "fixed": {
            "a": 0.05,
            "e": 0.6,
            "fx": 0.3,
            "mass": 1.0,
            "v0": 0.5,
            "theta0": 0.3,
            "omega0": 6.0,
        },
        "vary": {
            "mu": [0.0, 0.1, 0.2],
            "I_star": {"start": 0.2, "stop": 0.8, "num": 4},
            "law": ["uniform", "hertz"],
        },
    }
    spec.update(over)
    return spec


def test_grid_cases_are_the_cartesian_product():
    spec = load_spec(small_spec())
    assert spec.n_cases == 24 and spec.n_chunks == 4
    p = spec.parameters()
    combos = set(zip(p["mu"], p["I_star"], p["law"]))
    assert len(combos) == 24


def test_random_cases_do_not_depend_on_chunking():
    data = small_spec(
        kind="random",
        random={"samples": 50, "seed": 3},
        vary={"fx": {"low": 0.1, "high": 0.5}, "law": ["uniform", "hertz"]},
    )
    data["fixed"] = dict(data["fixed"], fy=0.6)
    del data["fixed"]["fx"]
    spec = load_spec(data)
    whole = spec.parameters()
    part = spec.parameters(21, 28)
    assert np.array_equal(whole["fx"][21:28], part["fx"])
    assert list(whole["law"][21:28]) == list(part["law"])
    assert spec.digest == load_spec(data).digest


@pytest.mark.parametrize(
    "edit, fragment",
    [
        ({"vary": {"fxx": [0.1]}}, "unknown key 'fxx' in [vary]"),
        ({"vary": {"fx": [0.1, 0.2]}}, "'fx' is both fixed and varied"),
        ({"vary": {"aspect": [0.5]}}, "at most one of b, e, aspect"),
        ({"chunk_size": 0}, "chunk_size = 0"),
        ({"kind": "sobol"}, "kind = 'sobol'"),
        ({"vary": {"mu": {"start": 0, "stop": 1}}}, "num = None"),
        ({"vary": {"law": ["uniform", "cubic"]}}, "[vary] law[1] = 'cubic'"),
        # named as the spec spells it, not as the moment of inertia it becomes
        ({"vary": {"I_star": [0.5, -1.0]}}, "I_star = -1.0 (case 2) is invalid"),
        ({"vary": {"mu": [0.1, -0.5]}}, "fy = -0.2"),
        ({"typo": 1}, "unknown key 'typo' in the sweep spec"),
    ],
)
def test_bad_specs_are_refused_before_work(edit, fragment):
    data = small_spec()
    for k, val in edit.items():
        data[k] = dict(data[k], **val) if k == "vary" else val
    with pytest.raises(ValueError) as err:
        load_spec(data)
    assert fragment in str(err.value)


def test_local_sweep_stores_everything_and_matches_simulate(tmp_path):
    data = small_spec()
    res = sweep(data, tmp_path / "s")
    assert res.chunks_computed == 4 and res.cases_computed == 24
    table = read_sweep(tmp_path / "s")
    assert np.array_equal(table["case_id"], np.arange(24))
    for col in (
        "t_stop",
        "beta_stop",
        "theta_stop",
        "phi_stop",
        "x_stop",
        "y_stop",
        "path_length",
        "ending",
        "status",
        "fx",
        "fy",
        "I_star",
        "law",
    ):
        assert col in table
    from slidespin.motion.outcomes import CONVERGED, FLAGGED

    assert set(table["status"]) <= CONVERGED | FLAGGED  # read_sweep leaves out the others
    man = json.loads((tmp_path / "s" / "manifest.json").read_text())
    assert man["complete"] and man["chunks_done"] == [0, 1, 2, 3]
    assert man["slidespin_version"] == ss.__version__
    # two cases recomputed one by one with the public simulate()
    for i in (5, 18):
        law = ss.HertzPressure() if table["law"][i] == "hertz" else ss.UniformPressure()
        body = ss.Body.from_inertia_ratio(
            ss.Ellipse.from_eccentricity(0.05, 0.6), law, 1.0, table["I_star"][i]
        )
        fr = ss.FrictionTensor(0.3, table["fy"][i])
        tr = ss.simulate(body, fr, ss.State.from_speed(0.5, 6.0, 0.3))
        assert table["t_stop"][i] == pytest.approx(tr.t_stop, rel=1e-12)
        assert table["x_stop"][i] == pytest.approx(tr.stop_state.x, rel=1e-10, abs=1e-14)
        assert table["path_length"][i] == pytest.approx(tr.distance, rel=1e-10)
        assert table["ending"][i] == tr.ending
        assert table["status"][i] == tr.status


def test_resume_recomputes_only_missing_chunks(tmp_path):
    out = tmp_path / "s"
    sweep(small_spec(), out)
    before = read_sweep(out)
    (out / "chunks" / "chunk-000002.parquet").unlink()
    with pytest.raises(SweepError, match="pass --resume"):
        sweep(small_spec(), out)
    res = sweep(small_spec(), out, resume=True)
    assert res.chunks_computed == 1 and res.cases_computed == 7
    after = read_sweep(out)
    for k in before:
        assert same(before[k], after[k]), k
    other = small_spec(chunk_size=5)
    with pytest.raises(SweepError, match="holds a different sweep"):
        sweep(other, out, resume=True)


def test_foreign_directory_is_refused(tmp_path):
    (tmp_path / "x.txt").write_text("mine")
    with pytest.raises(SweepError, match="non-empty directory without a sweep manifest"):
        sweep(small_spec(), tmp_path)
    assert (tmp_path / "x.txt").read_text() == "mine"


def run_cli(*args, **kw):
    return subprocess.run(
        [sys.executable, "-m", "slidespin", *args],
        capture_output=True,
        text=True,
        timeout=600,
        **kw,
    )


def test_sigkill_then_resume_loses_nothing(tmp_path):
    spec_path = tmp_path / "spec.toml"
    spec_path.write_text(
        'name = "kill"\nkind = "random"\nchunk_size = 10\n'
        "[random]\nsamples = 1600\nseed = 11\n"
        '[fixed]\na = 0.05\nfx = 0.3\nmass = 1.0\nlaw = "uniform"\n'
        "[vary]\nmu = {low = 0.0, high = 0.3}\nv0 = {low = 0.1, high = 1.0}\n"
        "omega0 = {low = -20.0, high = 20.0}\nI_star = {low = 0.2, high = 1.0}\n"
    )
    out = tmp_path / "run"
    proc = subprocess.Popen(
        [sys.executable, "-m", "slidespin", "sweep", str(spec_path), "--out", str(out), "--quiet"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline:
        n = len(list((out / "chunks").glob("chunk-*.parquet"))) if out.exists() else 0
        if n >= 2 or proc.poll() is not None:
            break
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    done_at_kill = len(list((out / "chunks").glob("chunk-*.parquet")))
    assert done_at_kill < 160, "the sweep finished before it could be killed"
    r = run_cli("sweep", str(spec_path), "--out", str(out), "--resume", "--quiet")
    assert r.returncode == 0, r.stderr
    assert not list((out / "chunks").glob(".chunk-*"))  # no temporary leftovers
    table = read_sweep(out)
    assert np.array_equal(table["case_id"], np.arange(1600))  # complete, no duplicates
    fresh = tmp_path / "fresh"
    sweep(load_spec(spec_path), fresh)
    ref = read_sweep(fresh)
    for k in ref:
        assert same(ref[k], table[k]), k


def test_dask_local_cluster_gives_exactly_the_local_results(tmp_path):
    distributed = pytest.importorskip("distributed")
    data = small_spec(chunk_size=12)
    sweep(data, tmp_path / "local")
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, host="127.0.0.1", dashboard_address=None, processes=True
    ) as cluster:
        with distributed.Client(cluster) as client:
            sweep(data, tmp_path / "dask", executor=client, task_cases=6)  # 2 tasks
    a, b = read_sweep(tmp_path / "local"), read_sweep(tmp_path / "dask")
    for k in a:
        assert same(a[k], b[k]), k


def test_thread_pool_executor_groups_chunks_into_tasks(tmp_path):
    import concurrent.futures as cf

    data = small_spec(chunk_size=5)  # 24 cases, 5 chunks
    sweep(data, tmp_path / "local")
    with cf.ThreadPoolExecutor(2) as ex:
        res = sweep(data, tmp_path / "pool", executor=ex, task_cases=10)
    assert res.chunks_computed == 5
    a, b = read_sweep(tmp_path / "local"), read_sweep(tmp_path / "pool")
    for k in a:
        assert same(a[k], b[k]), k


def test_sweep_cli_read_and_plot(tmp_path):
    spec_path = tmp_path / "spec.json.toml"
    spec_path.write_text(
        'kind = "grid"\nchunk_size = 50\n[fixed]\na = 0.05\nfx = 0.3\nv0 = 1.0\nomega0 = 10.0\n'
        "[vary]\nmu = [0.0, 0.1, 0.2]\nI_star = [0.3, 0.5, 0.7]\n"
    )
    out = tmp_path / "s"
    r = run_cli("sweep", str(spec_path), "--out", str(out), "--quiet")
    assert r.returncode == 0, r.stderr
    r = run_cli("sweep-read", str(out), "--csv", str(tmp_path / "s.csv"))
    assert r.returncode == 0, r.stderr
    lines = (tmp_path / "s.csv").read_text().splitlines()
    assert len(lines) == 10 and "beta_stop" in lines[0]
    png = tmp_path / "s.png"
    r = run_cli(
        "sweep-plot", str(out), "--x", "mu", "--y", "I_star", "--value", "t_stop", "--out", str(png)
    )
    assert r.returncode == 0, r.stderr
    assert png.stat().st_size > 10_000
    r = run_cli("sweep-plot", str(out), "--x", "nope", "--out", str(png))
    assert r.returncode == 2 and "column 'nope'" in r.stderr
    # the same sweep again on its finished directory: complete, one line, nothing written
    before = {p: p.stat().st_mtime_ns for p in out.rglob("*")}
    r = run_cli("sweep", str(spec_path), "--out", str(out))
    assert r.returncode == 0 and r.stderr == "", r.stderr
    assert len(r.stdout.splitlines()) == 1 and "complete already" in r.stdout
    assert before == {p: p.stat().st_mtime_ns for p in out.rglob("*")}


def test_quick_example_spec_is_valid():
    spec = load_spec(EXAMPLES / "sweep_quick.toml")
    assert 1000 <= spec.n_cases <= 5000
    assert load_spec(EXAMPLES / "sweep_random.toml").n_cases == 20000
