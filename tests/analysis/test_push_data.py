"""Reading pushes in the MIT push dataset's layout (slidespin.analysis.push_data).

The files here are written by the tests in the published layout (the authors'
``parse_bagfile_to_rawjson.py``: a JSON object / HDF5 file with ``tip_pose`` rows
(t, x, y, yaw), ``object_pose`` rows (t, x, y, yaw), ``ft_wrench`` rows (t, fx, fy, tz), UNIX
times), and read back.
"""

from __future__ import annotations

import json
import os
import sys

import numpy as np
import pytest

from slidespin.analysis.push_data import PushRun, read_push, read_pushes

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "push_data")
T0 = 1460088637.2185864  # the epoch time of the authors' example file's first sample
NAME = "motion_surface=plywood_shape=rect1_a=0_v=20_i=0.500_s=0.000_t=0.000"


def _layout(rng, n=40, tip_cols=4, force=True):
    t = T0 + np.arange(n) * 0.004
    tip = np.column_stack((t + 0.001, 0.3 + 0.02 * np.linspace(0, 1, n), np.full(n, -0.05)))
    if tip_cols == 4:
        tip = np.column_stack((tip, np.full(n, 1e-5)))
    obj = np.column_stack(
        (t, 0.35 + rng.normal(0, 1e-4, n), rng.normal(0, 1e-4, n), np.full(n, 0.1))
    )
    doc = {"tip_pose": tip.tolist(), "object_pose": obj.tolist()}
    if force:
        ft = np.column_stack(
            (t + 0.002, rng.normal(-1.0, 0.05, n), rng.normal(0.0, 0.05, n), np.zeros(n))
        )
        doc["ft_wrench"] = ft.tolist()
    return doc


def _write(tmp_path, doc, name=NAME + ".json"):
    path = tmp_path / name
    path.write_text(json.dumps(doc, indent=4))
    return path


def test_json_round_trip(tmp_path):
    doc = _layout(np.random.default_rng(1))
    run = read_push(_write(tmp_path, doc))
    assert isinstance(run, PushRun)
    tip, obj, ft = (np.array(doc[k]) for k in ("tip_pose", "object_pose", "ft_wrench"))
    assert run.t_origin == T0  # the earliest sample: the object's first
    np.testing.assert_allclose(run.object_pose[:, 0] + run.t_origin, obj[:, 0], rtol=0, atol=1e-6)
    np.testing.assert_array_equal(run.object_pose[:, 1:], obj[:, 1:])
    np.testing.assert_allclose(run.tip[:, 0] + run.t_origin, tip[:, 0], rtol=0, atol=1e-6)
    np.testing.assert_array_equal(run.tip[:, 1:], tip[:, 1:3])
    np.testing.assert_array_equal(run.tip_angle, tip[:, 3])
    np.testing.assert_array_equal(run.wrench[:, 1:], ft[:, 1:])
    assert run.object_pose[0, 0] == 0.0 and run.has_force
    # the sensor reads the object's force on the probe: the pusher's force is its negative
    np.testing.assert_array_equal(run.pusher_force()[:, 1:], -ft[:, 1:3])
    assert run.meta == {
        "surface": "plywood", "shape": "rect1", "a": "0", "v": "20", "i": "0.500",
        "s": "0.000", "t": "0.000",
    }  # fmt: skip
    assert not run.object_pose.flags.writeable
    finger = run.pusher(mu=0.2)
    assert finger.mu == 0.2 and finger.path.shape == (40, 3)
    pr = run.pose_run()
    assert set(pr) == {"t", "x", "y", "phi"} and pr["t"].size == 40


def test_three_column_tip_and_no_force(tmp_path):
    doc = _layout(np.random.default_rng(2), tip_cols=3, force=False)
    run = read_push(_write(tmp_path, doc))
    assert run.tip_angle is None and run.wrench is None and not run.has_force
    assert run.pusher_force() is None
    doc["ft_wrench"] = []  # an empty stream is no stream
    assert read_push(_write(tmp_path, doc)).wrench is None


@pytest.mark.parametrize(
    "edit, words",
    [
        (lambda d: d.pop("object_pose"), ["'object_pose'", "missing"]),
        (lambda d: d.pop("tip_pose"), ["'tip_pose'", "missing"]),
        (lambda d: d["object_pose"][3].pop(), ["'object_pose'", "row 3", "3 values"]),
        (lambda d: d["ft_wrench"][5].append(1.0), ["'ft_wrench'", "row 5", "5 values"]),
        (lambda d: d["tip_pose"].__setitem__(2, "x"), ["'tip_pose'", "row 2"]),
        (lambda d: d["object_pose"][4].__setitem__(1, None), ["row 4 column 1"]),
        (
            lambda d: d["object_pose"][7].__setitem__(0, d["object_pose"][6][0]),
            ["row 7", "increasing"],
        ),
        (lambda d: d.__setitem__("object_pose", d["object_pose"][:1]), ["1 row"]),
        (lambda d: d.__setitem__("tip_pose", {"a": 1}), ["'tip_pose'", "dict"]),
    ],
)
def test_bad_json_one_line_errors(tmp_path, edit, words):
    doc = _layout(np.random.default_rng(3))
    edit(doc)
    path = _write(tmp_path, doc)
    with pytest.raises(ValueError) as err:
        read_push(path)
    msg = str(err.value)
    assert "\n" not in msg and str(path) in msg
    for w in words:
        assert w in msg


def test_bad_files(tmp_path):
    p = tmp_path / "a.json"
    p.write_text("[1, 2]")
    with pytest.raises(ValueError, match="top level is a list"):
        read_push(p)
    p.write_text("{not json")
    with pytest.raises(ValueError, match="invalid JSON at line 1"):
        read_push(p)
    q = tmp_path / "a.csv"
    q.write_text("t,x")
    with pytest.raises(ValueError, match="unknown extension"):
        read_push(q)
    with pytest.raises(ValueError, match="does not exist"):
        read_push(tmp_path / "missing.json")
    with pytest.raises(ValueError, match="push file path"):
        read_push(3)


def test_nan_in_json_is_refused(tmp_path):
    doc = _layout(np.random.default_rng(4))
    doc["ft_wrench"][2][1] = float("nan")  # json.dumps writes NaN, json.loads reads it
    with pytest.raises(ValueError, match=r"'ft_wrench' row 2 column 1 is nan; valid: a finite"):
        read_push(_write(tmp_path, doc))


def test_read_pushes_directory_and_list(tmp_path):
    for k in (2, 1):
        _write(tmp_path, _layout(np.random.default_rng(k)), f"push={k}.json")
    (tmp_path / "notes.txt").write_text("not a push")
    runs = read_pushes(tmp_path)
    assert [r.meta["push"] for r in runs] == ["1", "2"]
    assert len(read_pushes([tmp_path / "push=2.json"])) == 1
    assert len(read_pushes(str(tmp_path / "push=1.json"))) == 1
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(ValueError, match="holds no push file"):
        read_pushes(empty)
    with pytest.raises(ValueError, match="holds no file"):
        read_pushes([])


def test_hdf5_round_trip(tmp_path):
    h5py = pytest.importorskip("h5py")
    doc = _layout(np.random.default_rng(5))
    path = tmp_path / (NAME + ".h5")
    with h5py.File(path, "w") as f:  # as parse_bagfile_to_rawjson.py writes it
        for key in ("tip_pose", "ft_wrench", "object_pose"):
            f.create_dataset(key, data=doc[key])
        f.attrs["source"] = "test"
    run = read_push(path)
    ref = read_push(_write(tmp_path, doc))
    for name in ("tip", "object_pose", "wrench", "tip_angle"):
        np.testing.assert_array_equal(getattr(run, name), getattr(ref, name))
    assert run.t_origin == ref.t_origin and run.extra == {"source": "test"}
    assert run.meta["shape"] == "rect1"
    bad = tmp_path / "bad.h5"
    with h5py.File(bad, "w") as f:
        f.create_dataset("tip_pose", data=np.array(doc["tip_pose"])[:, :2])
        f.create_dataset("object_pose", data=doc["object_pose"])
    with pytest.raises(ValueError, match=r"bad.h5: key 'tip_pose' has shape \(40, 2\)"):
        read_push(bad)


def test_hdf5_without_h5py(tmp_path, monkeypatch):
    path = tmp_path / "p.hdf5"
    path.write_bytes(b"\x89HDF\r\n\x1a\n")
    monkeypatch.setitem(sys.modules, "h5py", None)  # import h5py raises ImportError
    with pytest.raises(ImportError, match=r"pip install slidespin\[hdf5\]"):
        read_push(path)


def test_shipped_synthetic_dataset():
    """The shipped files are labelled synthetic, small, and in the layout."""
    runs = read_pushes(EXAMPLES)
    assert len(runs) == 4
    total = sum(os.path.getsize(r.source) for r in runs)
    assert total < 200_000
    for r in runs:
        assert r.extra["source"].startswith("synthetic")
        assert r.has_force and r.tip.shape[0] == r.object_pose.shape[0] == 150
        assert r.t_origin > 1e9  # an epoch-like clock, as in the dataset
