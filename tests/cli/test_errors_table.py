"""Runs every row of docs/errors.md: the table of bad inputs is the test."""

from __future__ import annotations

import contextlib
import io
import json
import math
import re
import select
import subprocess
import sys
import time
from pathlib import Path

import pytest

import slidespin as ss
from slidespin.cli.main import main

DOC = Path(__file__).resolve().parents[2] / "docs" / "errors.md"

GOOD_CASE = """\
[patch]
a = 0.1
eccentricity = 0.5
[pressure]
law = "uniform"
[friction]
fx = 0.3
fy = 0.4
angle = 0.0
[body]
mass = 1.0
[initial]
speed = 1.0
omega = 3.0
[solver]
g = 9.81
"""

GOOD_SWEEP = """\
kind = "grid"
chunk_size = 10
[fixed]
a = 0.1
law = "linear"
xi_c = 0.0
fx = 0.3
v0 = 1.0
omega0 = 3.0
[vary]
mu = [0.0, 0.1]
"""


def rows():
    out = []
    for line in DOC.read_text(encoding="utf-8").splitlines():
        m = re.match(r"^\| (python|case|sweep|cli) \| `(.*)` \| `(.*)` \|$", line)
        if m:
            out.append(m.groups())
    return out


ROWS = rows()


def test_the_table_is_there():
    kinds = {r[0] for r in ROWS}
    assert kinds == {"python", "case", "sweep", "cli"} and len(ROWS) > 60


def edit_toml(text: str, edit: str) -> str:
    """Apply one edit of the table's little language to a TOML document."""
    if edit.startswith("raw: "):
        return edit[5:].replace("\\n", "\n")
    if edit.startswith("+ "):
        return text + edit[2:] + "\n"
    m = re.match(r"^(-?)(?:\[(\w+)\] )?(\w+)(?: = (.*))?$", edit)
    assert m, edit
    delete, table, key, value = m.groups()
    lines = text.splitlines()
    # find the table's span (top level if no table)
    if table:
        start = lines.index(f"[{table}]") + 1
        end = next((i for i in range(start, len(lines)) if lines[i].startswith("[")), len(lines))
    else:
        start = 0
        end = next((i for i, s in enumerate(lines) if s.startswith("[")), len(lines))
    for i in range(start, end):
        if lines[i].split(" = ")[0] == key:
            if delete:
                del lines[i]
            else:
                lines[i] = f"{key} = {value}"
            break
    else:
        assert not delete, edit
        lines.insert(end, f"{key} = {value}")
    return "\n".join(lines) + "\n"


def check_cli(args, fragment, forbidden=()):
    """``slidespin ARGS`` exits 2 with one line on stderr containing ``fragment``."""
    err, out = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
        code = main(args)
    err = err.getvalue()
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    assert lines[0].startswith("slidespin: error: ")
    assert fragment in lines[0], (fragment, lines[0])
    for path in forbidden:
        assert not Path(path).exists()


def run_row(where: str, text: str, fragment: str, tmp: str) -> None:
    """Check one row of the table; raises AssertionError (or the unexpected exception)."""
    tmp_path = Path(tmp)
    if where == "python":
        try:
            eval(text, {"ss": ss, "math": math})  # noqa: S307 - our own table
        except ValueError as err:
            msg = str(err)
        else:
            raise AssertionError(f"{text} raised nothing")
        assert fragment in msg, (fragment, msg)
        assert "\n" not in msg, msg
    elif where == "case":
        case = tmp_path / "case.toml"
        case.write_text(edit_toml(GOOD_CASE, text))
        out = tmp_path / "out.png"
        check_cli(["simulate", str(case), "--plot", str(out)], fragment, [out])
    elif where == "sweep":
        spec = tmp_path / "spec.toml"
        spec.write_text(edit_toml(GOOD_SWEEP, text))
        out = tmp_path / "run"
        check_cli(["sweep", str(spec), "--out", str(out), "--quiet"], fragment, [out])
    else:
        case = tmp_path / "good.toml"
        case.write_text(GOOD_CASE)
        args = [a.replace("CASE", str(case)).replace("DIR", str(tmp_path)) for a in text.split()]
        check_cli(args, fragment)


# ------------------------------------------------------------------------------------------
# Every row runs in a worker process with a time limit: a hang in compiled code cannot be
# interrupted from Python (not even by a signal), so a row that does not answer within
# ROW_SECONDS fails and the worker is killed and replaced.
# ------------------------------------------------------------------------------------------
ROW_SECONDS = 30.0
START_SECONDS = 300.0  # the worker imports slidespin and loads (or compiles) the kernel

_WORKER = r"""
import json, os, sys, traceback
proto = os.fdopen(os.dup(1), "w")  # the protocol's channel; prints of the code go to stderr
os.dup2(2, 1)
sys.path.insert(0, {tests!r})
import test_errors_table as t
import slidespin as ss
ss.friction_wrench(ss.Body(ss.Circle(1.0), ss.UniformPressure(), 1.0),
                   ss.FrictionTensor(0.3, 0.4), 1.0, 0.0, 1.0)  # warm the kernel up
proto.write("ready\n"); proto.flush()
for line in sys.stdin:
    try:
        t.run_row(*json.loads(line))
        out = {{"ok": True}}
    except BaseException:  # noqa: BLE001 - report everything to the parent
        out = {{"ok": False, "error": traceback.format_exc(limit=-3)}}
    proto.write(json.dumps(out) + "\n"); proto.flush()
"""


class Worker:
    """A Python process that runs rows one at a time, each within a time limit."""

    def __init__(self):
        code = _WORKER.format(tests=str(Path(__file__).resolve().parent))
        self.proc = subprocess.Popen(
            [sys.executable, "-c", code],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
            bufsize=1,
        )
        first = self._read(START_SECONDS)
        if first != "ready":
            self.close()
            raise RuntimeError(f"the row worker did not start: {first!r}")

    def _read(self, seconds):
        ready, _, _ = select.select([self.proc.stdout], [], [], seconds)
        if not ready:
            return None
        return self.proc.stdout.readline().strip()

    def run(self, row, tmp):
        self.proc.stdin.write(json.dumps([*row, str(tmp)]) + "\n")
        self.proc.stdin.flush()
        t0 = time.monotonic()
        line = self._read(ROW_SECONDS)
        return line, time.monotonic() - t0

    def close(self):
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait()


@pytest.fixture(scope="module")
def worker():
    box = {"w": Worker()}
    yield box
    box["w"].close()


@pytest.mark.parametrize("where, text, fragment", ROWS, ids=[f"{r[0]}:{r[1][:40]}" for r in ROWS])
def test_bad_input_row(where, text, fragment, tmp_path, worker):
    line, _ = worker["w"].run((where, text, fragment), tmp_path)
    if line is None or line == "":
        worker["w"].close()
        worker["w"] = Worker()
        pytest.fail(
            f"{where} row {text!r} did not finish within {ROW_SECONDS:g} s (or its worker died)"
        )
    result = json.loads(line)
    assert result["ok"], result["error"]


def test_a_hanging_row_fails_instead_of_blocking(worker, monkeypatch):
    """The time limit works: a row that sleeps past it fails and the worker is replaced."""
    monkeypatch.setattr(sys.modules[__name__], "ROW_SECONDS", 2.0)
    w = worker["w"]
    line, seconds = w.run(("python", "__import__('time').sleep(30)", "x"), "/nonexistent")
    assert line is None and seconds < 10.0
    w.close()
    worker["w"] = Worker()
    line, _ = worker["w"].run(("python", "ss.Circle(0.0)", "radius = 0.0 m"), "/nonexistent")
    assert json.loads(line)["ok"]


def test_good_inputs_used_by_the_table_are_good(tmp_path, capsys):
    case = tmp_path / "case.toml"
    case.write_text(GOOD_CASE)
    assert main(["simulate", str(case), "--json"]) == 0
    spec = tmp_path / "spec.toml"
    spec.write_text(GOOD_SWEEP)
    assert main(["sweep", str(spec), "--out", str(tmp_path / "run"), "--quiet"]) == 0
    capsys.readouterr()
