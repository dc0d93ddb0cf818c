"""Sweeps say what happened (issue #10 item 4) and survive damage (issue #11 item 4).

The statuses come from a stand-in for the batch engine (``FakeEngine``) that sets them by a
rule on the inputs, so that the counting, filtering, marking, resuming and locking are tested
against a known truth, independently of the integrator.
"""

from __future__ import annotations

import errno
import json
import os
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from slidespin.cli.main import main
from slidespin.studies import sweep_chunk as sw
from slidespin.studies import sweep_store as store
from slidespin.studies.sweep import sweep
from slidespin.studies.sweep_parse import load_spec
from slidespin.studies.sweep_read import read_sweep, split_unconverged
from slidespin.studies.sweep_spec import SweepError
from slidespin.studies.sweep_store import count_outcomes


class FakeResults:
    def __init__(self, d):
        self.d = d

    def as_dict(self):
        return self.d


def fake_engine(fields, rtol=1e-10):
    """Results by rule: mu > 0.15 → max_steps; I* < 0.3 → saddle; else stopped. Ending:
    pure_sliding (β* = inf) when mu == 0, mixed otherwise."""
    fx, fy = np.asarray(fields["fx"], float), np.asarray(fields["fy"], float)
    mu = fy - fx
    n = mu.size
    istar = np.asarray(fields["moment_of_inertia"]) / (
        np.asarray(fields["mass"]) * np.asarray(fields["a"]) ** 2
    )
    status = np.where(mu > 0.15, "max_steps", np.where(istar < 0.3, "saddle", "stopped"))
    ending = np.where(mu == 0.0, "pure_sliding", "mixed")
    beta = np.where(mu == 0.0, np.inf, 0.01 + mu * istar)
    return FakeResults(
        {
            "t_stop": 1.0 + mu,
            "beta_stop": beta,
            "theta_stop": mu,
            "phi_stop": istar,
            "x_stop": np.zeros(n),
            "y_stop": np.zeros(n),
            "path_length": np.ones(n),
            "ending": ending.astype(object),
            "status": status.astype(object),
            "saddle_energy": np.where(status == "saddle", 1e-20, np.nan),
            "n_steps": np.full(n, 10, dtype=np.int64),
        }
    )


@pytest.fixture
def fake(monkeypatch):
    monkeypatch.setattr(sw, "simulate_cases", fake_engine)


MU = [0.0, 0.1, 0.2]
ISTAR = [0.2, 0.5, 0.8, 1.1]


def grid_spec(**over):
    spec = {
        "name": "outcomes",
        "kind": "grid",
        "chunk_size": 5,
        "fixed": {"a": 0.05, "fx": 0.3, "v0": 1.0, "omega0": 10.0},
        "vary": {"mu": MU, "I_star": ISTAR},
    }
    spec.update(over)
    return spec


def expected_counts():
    """The rule of fake_engine applied by hand to the 12 grid cases."""
    status = {"stopped": 0, "saddle": 0, "max_steps": 0}
    ending = {"mixed": 0, "pure_sliding": 0}
    for mu in MU:
        for i in ISTAR:
            status["max_steps" if mu > 0.15 else "saddle" if i < 0.3 else "stopped"] += 1
            ending["pure_sliding" if mu == 0 else "mixed"] += 1
    return status, ending


def write_spec(tmp_path, data) -> Path:
    lines = [
        f'name = "{data["name"]}"',
        f'kind = "{data["kind"]}"',
        f"chunk_size = {data['chunk_size']}",
        "[fixed]",
    ]
    lines += [f"{k} = {v!r}" for k, v in data["fixed"].items()]
    lines += ["[vary]"] + [f"{k} = {v!r}" for k, v in data["vary"].items()]
    p = tmp_path / "spec.toml"
    p.write_text("\n".join(lines) + "\n")
    return p


# ------------------------------------------------------------------------------ counting
def test_count_outcomes_and_split_by_hand():
    status = np.array(
        ["stopped", "max_steps", "saddle", "stopped", "non_finite", "marginal"], dtype=object
    )
    ending = np.array(["mixed", "mixed", "pure_sliding", "spiral", "mixed", "mixed"], dtype=object)
    c = count_outcomes(status, ending)
    assert c["status"] == {
        "stopped": 2,
        "max_steps": 1,
        "marginal": 1,
        "saddle": 1,
        "non_finite": 1,
    }
    assert list(c["status"]) == ["stopped", "marginal", "saddle", "max_steps", "non_finite"]
    assert c["ending"] == {"mixed": 4, "pure_sliding": 1, "spiral": 1}
    assert c["unconverged"] == 2
    table = {"case_id": np.arange(6), "status": status, "ending": ending}
    kept, left = split_unconverged(table)
    assert list(kept["case_id"]) == [0, 2, 3, 5]
    assert left == {"max_steps": 1, "non_finite": 1}


def test_summary_manifest_and_filtering(tmp_path, fake):
    res = sweep(grid_spec(), tmp_path / "s")
    status, ending = expected_counts()
    assert res.status_counts == status and res.ending_counts == ending
    assert res.n_unconverged == 4 and res.n_flagged == 2
    man = json.loads((tmp_path / "s" / "manifest.json").read_text())
    assert man["status_counts"] == status and man["ending_counts"] == ending
    assert man["unconverged"] == 4 and man["complete"]
    assert not (tmp_path / "s" / ".lock").exists()
    kept = read_sweep(tmp_path / "s")
    full = read_sweep(tmp_path / "s", include_unconverged=True)
    assert len(full["case_id"]) == 12 and len(kept["case_id"]) == 8
    assert set(kept["status"]) == {"stopped", "saddle"}
    assert np.all(kept["mu"] <= 0.15)


def test_cli_sweep_summary_exit_status_and_sweep_read(tmp_path, fake, capsys):
    spec = write_spec(tmp_path, grid_spec())
    out = tmp_path / "s"
    assert main(["sweep", str(spec), "--out", str(out), "--quiet"]) == 1
    err = capsys.readouterr().err
    assert "4 of 12 cases did not converge (max_steps 4)" in err
    assert "--include-unconverged" in err and err.count("\n") == 1
    assert main(["sweep", str(spec), "--out", str(out), "--resume"]) == 1
    text = capsys.readouterr().out
    assert "statuses    : stopped 6, saddle 2, max_steps 4" in text
    assert "endings     : mixed 8, pure_sliding 4" in text
    csv = tmp_path / "t.csv"
    assert main(["sweep-read", str(out), "--csv", str(csv)]) == 0
    said = capsys.readouterr().out
    assert said.startswith("8 cases") and "4 unconverged cases left out (max_steps 4)" in said
    assert len(csv.read_text().splitlines()) == 9
    assert main(["sweep-read", str(out), "--csv", str(csv), "--include-unconverged"]) == 0
    assert len(csv.read_text().splitlines()) == 13


# ------------------------------------------------------------------------------ resume
def test_resume_recomputes_damaged_chunks(tmp_path, fake):
    import pyarrow as pa
    import pyarrow.parquet as pq

    out = tmp_path / "s"
    sweep(grid_spec(), out)  # 12 cases, chunks of 5: 0, 1, 2
    ref = read_sweep(out, include_unconverged=True)
    chunks = out / "chunks"
    (chunks / "chunk-000001.parquet").write_bytes(b"PAR1 garbage, not a parquet file")
    c2 = chunks / "chunk-000002.parquet"
    c2.write_bytes(c2.read_bytes()[:-30])  # truncated: footer gone
    t0 = pq.read_table(chunks / "chunk-000000.parquet")
    pq.write_table(t0.slice(0, 3), chunks / "chunk-000000.parquet")  # rows missing
    with pytest.raises(SweepError, match="chunk-000001.parquet"):
        read_sweep(out)  # reading names the bad file instead of crashing
    res = sweep(grid_spec(), out, resume=True)
    assert res.chunks_repaired == 3 and res.chunks_computed == 3
    again = read_sweep(out, include_unconverged=True)
    for k in ref:
        assert np.array_equal(np.asarray(ref[k]).astype(str), np.asarray(again[k]).astype(str))
    # a chunk with a foreign schema is recomputed too
    pq.write_table(pa.table({"case_id": np.arange(5)}), chunks / "chunk-000000.parquet")
    assert sweep(grid_spec(), out, resume=True).chunks_repaired == 1


def test_resume_keeps_sound_chunks(tmp_path, fake):
    out = tmp_path / "s"
    sweep(grid_spec(), out)
    before = {p.name: p.stat().st_mtime_ns for p in (out / "chunks").iterdir()}
    res = sweep(grid_spec(), out, resume=True)
    assert res.chunks_repaired == 0 and res.chunks_computed == 0
    assert res.status_counts == expected_counts()[0]  # counted from the files
    assert before == {p.name: p.stat().st_mtime_ns for p in (out / "chunks").iterdir()}


# ------------------------------------------------------------------------------ lock
HOLD = """
import sys, time
from pathlib import Path
from slidespin.studies.sweep_store import _Lock
with _Lock(Path(sys.argv[1])):
    print("locked", flush=True)
    time.sleep(60)
"""


def test_concurrent_run_is_refused(tmp_path, fake, capsys):
    out = tmp_path / "s"
    sweep(grid_spec(), out)
    (out / "chunks" / "chunk-000001.parquet").unlink()
    holder = subprocess.Popen(
        [sys.executable, "-c", HOLD, str(out)], stdout=subprocess.PIPE, text=True
    )
    try:
        assert holder.stdout.readline().strip() == "locked"
        spec = write_spec(tmp_path, grid_spec())
        assert main(["sweep", str(spec), "--out", str(out), "--resume", "--quiet"]) == 2
        err = capsys.readouterr().err.strip()
        assert err.count("\n") == 0 and "in use by another slidespin sweep" in err
        assert f"pid {holder.pid}" in err and ".lock" in err
        assert not (out / "chunks" / "chunk-000001.parquet").exists()  # nothing computed
    finally:
        holder.kill()
        holder.wait()
    # the holder died without removing its lock: stale, taken over
    assert (out / ".lock").exists()
    res = sweep(grid_spec(), out, resume=True)
    assert res.chunks_computed == 1 and not (out / ".lock").exists()


def test_lock_of_a_live_process_on_this_host_is_respected(tmp_path, fake):
    out = tmp_path / "s"
    out.mkdir()
    (out / ".lock").write_text(f"{os.getppid()} {socket.gethostname()}\n")
    with pytest.raises(SweepError, match="in use by another slidespin sweep"):
        sweep(grid_spec(), out)
    assert (out / ".lock").exists() and not (out / "chunks").exists()


# ------------------------------------------------------------------------------ full disk
@pytest.mark.parametrize(
    "code, words", [(errno.ENOSPC, "disk full"), (errno.EACCES, "permission denied")]
)
def test_failed_chunk_write_is_reported_and_resumable(
    tmp_path, fake, monkeypatch, capsys, code, words
):
    real = store._parquet_write

    def failing(table, path):
        if ".chunk-000001.parquet" in str(path):
            Path(path).write_bytes(b"partial")  # a half-written temporary file
            raise OSError(code, os.strerror(code), str(path))
        real(table, path)

    monkeypatch.setattr(store, "_parquet_write", failing)
    spec = write_spec(tmp_path, grid_spec())
    out = tmp_path / "s"
    assert main(["sweep", str(spec), "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "Traceback" not in err and "internal error" not in err
    assert f"{words} while writing" in err and "chunk-000001.parquet" in err
    assert "--resume" in err
    names = sorted(p.name for p in (out / "chunks").iterdir())
    assert names == ["chunk-000000.parquet"]  # no temporary leftovers
    assert not (out / ".lock").exists()
    man = json.loads((out / "manifest.json").read_text())
    assert man["chunks_done"] == [0] and not man["complete"]
    monkeypatch.setattr(store, "_parquet_write", real)
    assert main(["sweep", str(spec), "--out", str(out), "--resume", "--quiet"]) == 1
    assert len(read_sweep(out, include_unconverged=True)["case_id"]) == 12


# ------------------------------------------------------------------------------ random streams
def test_random_cases_are_the_draws_of_independent_streams():
    """Case i of parameter j is the i-th draw of default_rng([seed, j]) (drawn here whole,
    independently of the chunked generator)."""
    data = {
        "kind": "random",
        "chunk_size": 7,
        "random": {"samples": 40, "seed": 9},
        "fixed": {"a": 0.05, "fx": 0.3},
        "vary": {
            "mu": {"low": 0.0, "high": 0.3},
            "law": ["uniform", "hertz"],
            "v0": {"low": 0.1, "high": 2.0, "log": True},
        },
    }
    spec = load_spec(data)
    mu = np.random.default_rng([9, 0]).uniform(0.0, 0.3, 40)
    law = np.array(["uniform", "hertz"])[np.random.default_rng([9, 1]).integers(0, 2, 40)]
    v0 = np.exp(np.random.default_rng([9, 2]).uniform(np.log(0.1), np.log(2.0), 40))
    for start in (0, 7, 33):
        p = spec.parameters(start, start + 7)
        stop = min(start + 7, 40)
        assert np.array_equal(p["mu"], mu[start:stop])
        assert list(p["law"]) == list(law[start:stop])
        assert np.array_equal(p["v0"], v0[start:stop])


def test_damaged_manifest_is_named(tmp_path, capsys):
    out = tmp_path / "s"
    out.mkdir()
    (out / "manifest.json").write_bytes(b"\xff{not json")
    assert main(["sweep-read", str(out), "--csv", str(tmp_path / "t.csv")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "manifest.json" in err and "is unreadable" in err
    assert not (tmp_path / "t.csv").exists()


def test_sweep_read_disk_full_writes_nothing(tmp_path, fake, capsys, monkeypatch):
    import builtins

    out = tmp_path / "s"
    sweep(grid_spec(), out)
    real_open = builtins.open

    def full(path, mode="r", *args, **kwargs):
        if "w" in mode and ".t.csv.tmp-" in str(path):
            fh = real_open(path, mode, *args, **kwargs)
            fh.write("case_id,partial\n")
            fh.close()
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))
        return real_open(path, mode, *args, **kwargs)

    monkeypatch.setattr(builtins, "open", full)
    code = main(["sweep-read", str(out), "--csv", str(tmp_path / "t.csv")])
    monkeypatch.setattr(builtins, "open", real_open)
    assert code == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "disk full while writing" in err and "t.csv" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s"]
