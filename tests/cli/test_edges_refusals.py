"""Every refusal written in `slidespin.studies` and `slidespin.cli` states what is valid.

The source is read: each ``raise ValueError(...)`` / ``raise SweepError(...)`` with a message
of its own must say ``valid`` (the valid range, values or form). Exempt are the messages that
only pass another one on (``raise SweepError(str(exc))``, ``f"{path}: {exc}"``: the message
they carry states it) and the missing optional dependencies (``pip install ...``).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[2] / "src" / "slidespin"
FILES = sorted((SRC / "studies").glob("*.py")) + sorted((SRC / "cli").glob("*.py"))
ERRORS = {"ValueError", "SweepError"}
#: names of a caught exception or of its message, passed on by a wrapper
CARRIED = {"exc", "msg", "err", "error"}


def constant_text(node) -> str:
    return "".join(
        n.value for n in ast.walk(node) if isinstance(n, ast.Constant) and isinstance(n.value, str)
    )


def carries_another_message(node) -> bool:
    """A message that is (or embeds) a caught exception's message, or not a literal at all."""
    if not isinstance(node, (ast.JoinedStr, ast.Constant, ast.BinOp)):
        return True  # SweepError(msg), ValueError(str(exc)), ValueError(write_failure(...))
    for n in ast.walk(node):
        if isinstance(n, ast.FormattedValue):
            names = {x.id for x in ast.walk(n.value) if isinstance(x, ast.Name)}
            if names & CARRIED:
                return True
    return False


def refusals():
    out = []
    for path in FILES:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not (isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call)):
                continue
            func = node.exc.func
            name = getattr(func, "id", getattr(func, "attr", ""))
            if name in ERRORS and node.exc.args:
                out.append((path.relative_to(SRC), node.lineno, node.exc.args[0]))
    return out


REFUSALS = refusals()


def test_there_are_refusals_to_check():
    assert len(REFUSALS) > 100


@pytest.mark.parametrize("where, line, message", REFUSALS, ids=[f"{w}:{n}" for w, n, _ in REFUSALS])
def test_each_refusal_states_what_is_valid(where, line, message):
    if carries_another_message(message):
        return
    text = constant_text(message)
    if "pip install" in text:  # an optional dependency that is missing
        return
    assert "valid" in text, f"{where}:{line}: {text!r}"


def test_the_scan_sees_a_refusal_without_a_range():
    """The check can fail: a message without 'valid' is caught, a wrapper is not."""
    bad = ast.parse('raise ValueError(f"x = {x} is wrong")').body[0].exc.args[0]
    assert not carries_another_message(bad) and "valid" not in constant_text(bad)
    wrapper = ast.parse('raise ValueError(f"{path}: {exc}")').body[0].exc.args[0]
    assert carries_another_message(wrapper)


@pytest.mark.parametrize(
    "argv",
    [
        ["sweep", "SPEC", "--out", "DIR/o", "--workers", "0"],
        ["limit-surface", "CASE", "--n", "3"],
        ["animate", "CASE", "--out", "DIR/x.gif", "--fps", "0"],
        ["reproduce", "table1", "--mu", "0.1"],
        ["reproduce", "fig2", "--fx", "-1"],
        ["fit", "DIR/d.csv", "--case", "CASE", "--sigma", "x=1,x=2"],
        ["bench", "--batch", "3", "--no-save"],
        ["bench", "--no-save", "--out", "DIR/b"],
    ],
)
def test_command_line_refusals_say_what_is_valid(tmp_path, capsys, argv):
    from slidespin.cli.main import main

    case = tmp_path / "c.toml"
    case.write_text(
        '[patch]\nshape = "circle"\nradius = 0.05\n[pressure]\nlaw = "uniform"\n'
        "[friction]\nfx = 0.3\nfy = 0.3\n[body]\nmass = 1.0\n[initial]\n"
    )
    spec = tmp_path / "s.toml"
    spec.write_text("[fixed]\na = 0.05\nfx = 0.3\nmu = 0.1\n")
    (tmp_path / "d.csv").write_text("t,x\n0,0\n0.1,0.01\n")
    args = [
        a.replace("CASE", str(case)).replace("SPEC", str(spec)).replace("DIR", str(tmp_path))
        for a in argv
    ]
    assert main(args) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and err.startswith("slidespin: error: ")
    assert "valid" in err, err
