"""`slidespin --help` and `slidespin COMMAND --help` load nothing heavy, and error messages
name the program once.

Each help is asked of a fresh interpreter, which then reports the modules it imported and
its CPU time: the parser must be built from modules that import neither NumPy, SciPy,
matplotlib nor numba (they load when a command runs).
"""

from __future__ import annotations

import contextlib
import io
import json
import resource
import subprocess
import sys

import pytest

from slidespin.cli.main import build_parser, main

HEAVY = ("numpy", "scipy", "matplotlib", "numba", "pyarrow", "pandas", "PIL", "xarray", "dask")

CHILD = r"""
import contextlib, io, json, sys
from slidespin.cli.main import main
buf = io.StringIO()
with contextlib.redirect_stdout(buf):
    code = main(sys.argv[1:])
heavy = sorted({m.split(".")[0] for m in sys.modules} & set(HEAVY))
json.dump({"code": code, "heavy": heavy, "help": buf.getvalue()}, sys.stdout)
"""


def commands():
    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    return list(sub.choices)


def ask(*argv):
    """Run `slidespin ARGV` in a fresh interpreter: (exit code, heavy modules, help text,
    CPU seconds of the child)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run(
        [sys.executable, "-c", f"HEAVY = {HEAVY!r}\n" + CHILD, *argv],
        capture_output=True,
        text=True,
        timeout=120,
    )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    doc = json.loads(r.stdout)
    return doc["code"], doc["heavy"], doc["help"], cpu


def test_every_command_is_listed():
    names = commands()
    for name in ("demo", "simulate", "sweep", "reproduce", "bench", "fit", "limit-surface"):
        assert name in names


@pytest.mark.parametrize("argv", [["--help"]] + [[c, "--help"] for c in commands()])
def test_help_imports_nothing_heavy(argv):
    code, heavy, text, cpu = ask(*argv)
    assert code == 0
    assert text.startswith("usage: slidespin")
    assert heavy == [], f"slidespin {' '.join(argv)} imported {heavy}"
    # the goal is 0.5 s of wall time; CPU time does not depend on how busy the machine is
    # (importing NumPy alone costs about 0.1-0.2 s of it, the whole stack above 1 s)
    assert cpu < 0.5, cpu


def test_the_heavy_check_can_fail():
    """The child's report is real: a command that runs imports NumPy."""
    code, heavy, _, _ = ask("sweep-read", "/nonexistent-dir", "--csv", "/tmp/x.csv")
    assert code == 2 and "numpy" in heavy


def test_constants_spelled_for_the_parser_match_their_modules():
    """The parser shows choices and bounds without importing their modules: the copies must
    equal the originals."""
    from slidespin.analysis import fit as fit_mod
    from slidespin.analysis import fit_data
    from slidespin.cli import _bench_cases, animate, bench, fit, reproduce
    from slidespin.paper import _shared
    from slidespin.viz import animate as viz_animate

    assert reproduce.FORMATS == _shared.FORMATS
    assert fit.PARAMETERS == fit_mod.PARAMETERS
    assert fit.LOSSES == fit_mod.LOSSES
    assert fit.CHANNELS == fit_data.CHANNELS
    assert (animate.MAX_FPS, animate.MAX_FRAMES) == (viz_animate.MAX_FPS, viz_animate.MAX_FRAMES)
    assert bench._LAWS == _bench_cases._LAWS


# ------------------------------------------------------------------- one program name per line
def error_line(argv, capsys):
    code = main(argv)
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1, err
    return lines[0]


def test_no_command_says_slidespin_once(capsys):
    line = error_line([], capsys)
    assert line.startswith("slidespin: error: the following arguments are required: COMMAND")
    assert line.count("slidespin:") == 1


@pytest.mark.parametrize("command", commands())
def test_unknown_option_names_the_command(command, capsys):
    line = error_line([command, "--no-such-option"], capsys)
    # the command's own first complaint (a missing argument, or the unknown option)
    assert line.startswith(f"slidespin: error: {command}: ")
    assert line.count("slidespin:") == 1 and f"'slidespin {command} --help'" in line


def test_unrecognized_argument_names_the_command(capsys):
    line = error_line(["demo", "--bogus"], capsys)
    assert line.startswith("slidespin: error: demo: unrecognized arguments: --bogus")
    assert line.count("slidespin:") == 1


def test_missing_argument_names_the_command(capsys):
    line = error_line(["reproduce"], capsys)
    assert line.startswith("slidespin: error: reproduce: the following arguments are required")
    assert line.count("slidespin:") == 1


def test_unknown_command(capsys):
    line = error_line(["frobnicate"], capsys)
    assert line.startswith("slidespin: error: argument COMMAND: invalid choice: 'frobnicate'")
    assert line.count("slidespin:") == 1


def test_value_errors_say_slidespin_once(tmp_path, capsys):
    line = error_line(["simulate", str(tmp_path / "none.toml")], capsys)
    assert line.startswith("slidespin: error: ") and line.count("slidespin:") == 1


def test_python_m_bench_says_slidespin_once():
    from slidespin.cli.bench import main as bench_main

    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        code = bench_main(["--batch", "3", "--no-save"])
    assert code == 2
    line = err.getvalue().strip()
    assert line.startswith("slidespin: error: bench: --batch = 3 is invalid; valid range")
    assert line.count("slidespin") == 1
