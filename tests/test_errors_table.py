"""Runs every row of docs/errors.md: the table of bad inputs is the test."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

import slidespin as ss
from slidespin.cli import main

DOC = Path(__file__).resolve().parents[1] / "docs" / "errors.md"

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


def check_cli(args, fragment, capsys, forbidden=()):
    code = main(args)
    err = capsys.readouterr().err
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    assert lines[0].startswith("slidespin: error: ")
    assert fragment in lines[0], (fragment, lines[0])
    for path in forbidden:
        assert not Path(path).exists()


@pytest.mark.parametrize("where, text, fragment", ROWS, ids=[f"{r[0]}:{r[1][:40]}" for r in ROWS])
def test_bad_input_row(where, text, fragment, tmp_path, capsys):
    if where == "python":
        with pytest.raises(ValueError) as err:
            eval(text, {"ss": ss, "math": math})  # noqa: S307 - our own table
        assert fragment in str(err.value), (fragment, str(err.value))
    elif where == "case":
        case = tmp_path / "case.toml"
        case.write_text(edit_toml(GOOD_CASE, text))
        out = tmp_path / "out.png"
        check_cli(["simulate", str(case), "--plot", str(out)], fragment, capsys, [out])
    elif where == "sweep":
        spec = tmp_path / "spec.toml"
        spec.write_text(edit_toml(GOOD_SWEEP, text))
        out = tmp_path / "run"
        check_cli(["sweep", str(spec), "--out", str(out), "--quiet"], fragment, capsys, [out])
    else:
        case = tmp_path / "good.toml"
        case.write_text(GOOD_CASE)
        args = [a.replace("CASE", str(case)).replace("DIR", str(tmp_path)) for a in text.split()]
        check_cli(args, fragment, capsys)


def test_good_inputs_used_by_the_table_are_good(tmp_path, capsys):
    case = tmp_path / "case.toml"
    case.write_text(GOOD_CASE)
    assert main(["simulate", str(case), "--json"]) == 0
    spec = tmp_path / "spec.toml"
    spec.write_text(GOOD_SWEEP)
    assert main(["sweep", str(spec), "--out", str(tmp_path / "run"), "--quiet"]) == 0
    capsys.readouterr()
