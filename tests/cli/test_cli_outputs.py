"""Outputs of the command line (issues #10 item 5, #11 item 4): checked before any work,
written whole or not at all, independent of one another, never into the working directory
by default; a full disk says so."""

from __future__ import annotations

import errno
import importlib
import json
import os
from pathlib import Path

import pytest

from slidespin.cli.main import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DEMO = str(EXAMPLES / "demo.toml")


def one_line_error(capsys, *fragments):
    cap = capsys.readouterr()
    lines = cap.err.strip().splitlines()
    assert len(lines) == 1, cap.err
    assert lines[0].startswith("slidespin: error: ") and "Traceback" not in cap.err
    for frag in fragments:
        assert frag in lines[0], (frag, lines[0])
    return lines[0]


@pytest.fixture
def no_simulation(monkeypatch):
    """Fail the test if any trajectory is computed."""
    sim = importlib.import_module("slidespin.motion.simulate")  # the parser loads no layer

    def forbidden(*args, **kwargs):
        raise AssertionError("simulate() was called before the outputs were checked")

    monkeypatch.setattr(sim, "simulate", forbidden)


def test_csv_rows_do_not_depend_on_plot(tmp_path, capsys):
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    assert main(["simulate", DEMO, "--csv", str(a)]) == 0
    assert main(["simulate", DEMO, "--csv", str(b), "--plot", str(tmp_path / "f.png")]) == 0
    assert a.read_bytes() == b.read_bytes()
    rows = a.read_text().splitlines()
    assert rows[0].startswith("t,x,y,phi") and len(rows) > 200  # dense enough to plot
    assert f"({len(rows) - 1} rows)" in capsys.readouterr().out


@pytest.mark.parametrize("plot", ["x.jpgx", "out.xyz", "noextension"])
def test_unknown_figure_format_is_refused_before_any_work(tmp_path, capsys, no_simulation, plot):
    csv = tmp_path / "x.csv"
    code = main(["simulate", DEMO, "--csv", str(csv), "--plot", str(tmp_path / plot)])
    assert code == 2
    one_line_error(capsys, "--plot", plot, "unknown figure format", ".png")
    assert list(tmp_path.iterdir()) == []  # the CSV is not written either


def test_demo_plot_format_checked_first(tmp_path, capsys, no_simulation):
    assert main(["demo", "--plot", str(tmp_path / "demo.gif")]) == 2
    one_line_error(capsys, "'gif'")
    assert list(tmp_path.iterdir()) == []


def test_same_file_for_two_outputs_is_refused(tmp_path, capsys, no_simulation):
    p = str(tmp_path / "both.png")
    assert main(["simulate", DEMO, "--csv", p, "--plot", p]) == 2
    one_line_error(capsys, "same file")


@pytest.mark.parametrize(
    "code, words", [(errno.ENOSPC, "disk full"), (errno.EACCES, "permission denied")]
)
def test_failed_write_leaves_nothing(tmp_path, capsys, monkeypatch, code, words):
    """The second of two outputs fails (disk full, permission denied): the first is removed
    again, and the message says what happened to which file."""
    import builtins

    real_open = builtins.open
    csv, png = tmp_path / "t.csv", tmp_path / "f.png"

    def full_disk(path, mode="r", *args, **kwargs):
        if "w" in mode and os.path.basename(str(path)).startswith(".f.png"):
            raise OSError(code, os.strerror(code), str(path))
        return real_open(path, mode, *args, **kwargs)

    monkeypatch.setattr(builtins, "open", full_disk)
    code = main(["simulate", DEMO, "--csv", str(csv), "--plot", str(png)])
    monkeypatch.setattr(builtins, "open", real_open)
    assert code == 2
    one_line_error(capsys, f"{words} while writing", "f.png", "nothing was written")
    assert list(tmp_path.iterdir()) == []


def test_unconverged_case_exits_1_and_says_why(tmp_path, capsys, monkeypatch):
    """A case whose step budget runs out (max_steps = 3) is reported with exit status 1."""
    case = tmp_path / "c.toml"
    case.write_text(Path(DEMO).read_text() + "max_steps = 3\n")
    assert main(["simulate", str(case)]) == 1
    out = capsys.readouterr().out
    assert "status      : max_steps" in out and "step budget exhausted" in out


def test_default_outputs_go_to_slidespin_out(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["demo"]) == 0
    assert sorted(os.listdir(tmp_path)) == ["slidespin-out"]
    assert (tmp_path / "slidespin-out" / "demo.png").stat().st_size > 20_000
    assert "slidespin-out/demo.png" in capsys.readouterr().out


def test_json_output_is_json_only(tmp_path, capsys):
    assert main(["simulate", DEMO, "--json", "--csv", str(tmp_path / "t.csv")]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["status"] == "stopped" and data["ending"] == "mixed"


def test_write_outputs_is_all_or_nothing(tmp_path, monkeypatch):
    import importlib

    cli = importlib.import_module("slidespin.cli.main")

    good = tmp_path / "a.txt"
    bad = tmp_path / "missing-dir-is-a-file" / "b.txt"
    (tmp_path / "missing-dir-is-a-file").write_text("a file, not a directory")
    with pytest.raises(ValueError, match="b.txt"):
        cli.write_outputs([(str(good), b"1"), (str(bad), b"2")])
    assert not good.exists()


def test_permission_denied_output_directory(tmp_path, capsys, no_simulation):
    if os.geteuid() == 0:
        pytest.skip("root can write anywhere")
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        assert main(["simulate", DEMO, "--csv", str(ro / "t.csv")]) == 2
        one_line_error(capsys, "--csv", "not writable")
    finally:
        ro.chmod(0o700)
