"""Running a sweep again on its own directory: complete (exit 0, one line, nothing written),
unfinished or damaged (exit 2, saying which chunks), or another spec (saying which keys)."""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest

from slidespin.cli.main import main
from slidespin.studies.sweep import sweep
from slidespin.studies.sweep_read import read_sweep
from slidespin.studies.sweep_spec import SweepError
from slidespin.studies.sweep_store import spec_differences

SPEC = {
    "name": "again",
    "kind": "grid",
    "chunk_size": 4,
    "fixed": {"a": 0.05, "e": 0.6, "fx": 0.3, "v0": 0.5, "omega0": 6.0, "theta0": 0.3},
    "vary": {"mu": [0.0, 0.1, 0.2], "I_star": [0.4, 0.8, 1.2]},
}
TOML = """name = "again"
kind = "grid"
chunk_size = 4
[fixed]
a = 0.05
e = 0.6
fx = 0.3
v0 = 0.5
omega0 = 6.0
theta0 = 0.3
[vary]
mu = [0.0, 0.1, 0.2]
I_star = [0.4, 0.8, 1.2]
"""


def snapshot(out):
    return {
        p: (p.stat().st_mtime_ns, p.read_bytes()) for p in sorted(out.rglob("*")) if p.is_file()
    }


@pytest.fixture
def finished(tmp_path):
    out = tmp_path / "s"
    first = sweep(copy.deepcopy(SPEC), out, progress=False)
    assert first.chunks_computed == 3 and not first.already_complete
    return out, first


def test_a_finished_sweep_is_reported_complete_and_nothing_is_written(finished):
    out, first = finished
    before = snapshot(out)
    again = sweep(copy.deepcopy(SPEC), out, progress=False)
    assert again.already_complete
    assert again.chunks_computed == 0 and again.cases_computed == 0 and again.n_cases == 9
    # the counts come from the chunk files, and are those of the run that made them
    assert again.status_counts == first.status_counts
    assert again.ending_counts == first.ending_counts
    assert snapshot(out) == before


def test_cli_says_complete_in_one_line_exit_0(finished, tmp_path, capsys):
    out, first = finished
    spec = tmp_path / "spec.toml"
    spec.write_text(TOML)
    before = snapshot(out)
    assert main(["sweep", str(spec), "--out", str(out)]) == 0
    cap = capsys.readouterr()
    assert cap.err == ""
    lines = cap.out.strip().splitlines()
    assert len(lines) == 1 and "complete already" in lines[0] and "9 cases" in lines[0]
    counts = ", ".join(f"{k} {v}" for k, v in first.status_counts.items())
    assert lines[0].endswith(counts)
    assert main(["sweep", str(spec), "--out", str(out), "--quiet"]) == 0
    assert capsys.readouterr().out == ""
    assert snapshot(out) == before


def test_unfinished_sweep_names_the_missing_chunks(finished):
    out, _ = finished
    (out / "chunks" / "chunk-000001.parquet").unlink()
    before = snapshot(out)
    with pytest.raises(SweepError) as err:
        sweep(copy.deepcopy(SPEC), out, progress=False)
    msg = str(err.value)
    assert "unfinished: 2 of 3 chunks done, chunk 1 missing" in msg and "--resume" in msg
    assert snapshot(out) == before
    res = sweep(copy.deepcopy(SPEC), out, progress=False, resume=True)
    assert res.chunks_computed == 1 and not res.already_complete


def test_damaged_chunk_is_named_and_left_for_resume(finished):
    out, _ = finished
    ref = read_sweep(out, include_unconverged=True)
    bad = out / "chunks" / "chunk-000002.parquet"
    bad.write_bytes(bad.read_bytes()[:-40])  # footer gone
    before = snapshot(out)
    with pytest.raises(SweepError) as err:
        sweep(copy.deepcopy(SPEC), out, progress=False)
    msg = str(err.value)
    assert "chunk file 2 is damaged" in msg and "chunk-000002.parquet" in msg
    assert "--resume" in msg
    assert snapshot(out) == before
    res = sweep(copy.deepcopy(SPEC), out, progress=False, resume=True)
    assert res.chunks_repaired == 1 and res.chunks_computed == 1
    again = read_sweep(out, include_unconverged=True)
    for k in ref:
        assert np.array_equal(np.asarray(ref[k]).astype(str), np.asarray(again[k]).astype(str))


def test_another_spec_is_refused_naming_the_keys_that_differ(finished):
    out, _ = finished
    other = copy.deepcopy(SPEC)
    other["vary"]["mu"] = [0.0, 0.1, 0.25]
    other["fixed"]["v0"] = 0.7
    before = snapshot(out)
    with pytest.raises(SweepError) as err:
        sweep(other, out, progress=False)
    msg = str(err.value)
    assert "holds a different sweep" in msg
    assert "[fixed] v0 = 0.5 there, 0.7 in this spec" in msg
    assert "[vary] mu = [0.0, 0.1, 0.2] there, [0.0, 0.1, 0.25] in this spec" in msg
    assert "valid: the spec that made it" in msg
    assert snapshot(out) == before


def test_spec_differences_lists_added_and_removed_keys():
    old = {"kind": "grid", "fixed": {"a": 0.1, "e": 0.5}, "vary": {"mu": [0.0]}}
    new = {"kind": "grid", "fixed": {"a": 0.1, "b": 0.05}, "vary": {"mu": [0.0]}, "rtol": 1e-8}
    text = spec_differences(old, new)
    assert "rtol = absent there, 1e-08 in this spec" in text
    assert "[fixed] b = absent there, 0.05 in this spec" in text
    assert "[fixed] e = 0.5 there, absent in this spec" in text
    many = {"fixed": {f"k{i}": i for i in range(6)}}
    assert spec_differences({}, many).endswith("and 3 more")
    assert "no readable spec" in spec_differences(None, new)


def test_manifest_of_a_complete_rerun_is_unchanged(finished):
    out, _ = finished
    text = (out / "manifest.json").read_text()
    sweep(copy.deepcopy(SPEC), out, progress=False)
    assert (out / "manifest.json").read_text() == text
    assert json.loads(text)["complete"]
