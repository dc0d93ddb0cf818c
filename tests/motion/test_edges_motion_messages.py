"""Every refusal in the motion layer's public shell states what is valid.

Two checks: a scan of the source (every ``raise ValueError(...)`` / ``raise TypeError(...)``
whose message is written out in these modules must say "valid ...": a range, the values, the
columns, the keywords), and the refusals themselves, triggered one by one, naming the
parameter, the value received and the valid range.
"""

from __future__ import annotations

import ast
import math
import re
from pathlib import Path

import numpy as np
import pytest

import slidespin as ss
from slidespin.motion import _cases, batch, outcomes
from slidespin.motion.simulate import check_solver_options

MOTION = Path(ss.__file__).resolve().parent / "motion"
MODULES = ("simulate", "batch", "_cases", "loads", "state", "_report", "outcomes")


def _message_text(node: ast.AST) -> str:
    """The literal text of a message expression (f-strings, concatenations, parentheses)."""
    parts = [n.value for n in ast.walk(node) if isinstance(n, ast.Constant)]
    return " ".join(p for p in parts if isinstance(p, str))


def _refusals(path: Path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if not isinstance(node, ast.Raise) or not isinstance(node.exc, ast.Call):
            continue
        func = node.exc.func
        name = func.id if isinstance(func, ast.Name) else getattr(func, "attr", "")
        if name in ("ValueError", "TypeError") and node.exc.args:
            yield node.lineno, _message_text(node.exc.args[0])


@pytest.mark.parametrize("module", MODULES)
def test_every_written_refusal_states_what_is_valid(module):
    path = MOTION / f"{module}.py"
    missing = [
        (line, text[:80])
        for line, text in _refusals(path)
        if text and not re.search(r"\bvalid\b", text, re.IGNORECASE)
    ]
    assert not missing, f"{path.name}: refusals without a valid range: {missing}"


BODY = ss.Body(ss.Ellipse(0.1, 0.06), ss.UniformPressure(), mass=1.0)
FR = ss.FrictionTensor(0.3, 0.4)


@pytest.mark.parametrize(
    "build, words",
    [
        (lambda: batch.simulate_cases([1, 2]), ["cases = [1, 2]", "valid values: a dict"]),
        (lambda: batch.simulate_cases({"a": 0.1}), ["missing case field 'b'", "a, b, fx, fy"]),
        (
            lambda: batch.simulate_cases({"a": 0.1, "b": 0.1, "fx": [0.3, 0.3], "fy": [1, 2, 3]}),
            ["different lengths [2, 3]", "valid"],
        ),
        (
            lambda: batch.simulate_cases({"a": 0.1, "b": 0.1, "fx": 0.3, "fy": "x"}),
            ["fy must be real numbers", "valid values"],
        ),
        (lambda: _cases.footprint_geometry("disk", {}, 2), ["needs 'radius'", "radius"]),
        (
            lambda: batch.simulate_bodies([1], FR, np.zeros((1, 6))),
            ["bodies = [1]", "valid values: a non-empty sequence of slidespin.Body"],
        ),
        (
            lambda: batch.simulate_bodies([BODY], [FR, FR], np.zeros((1, 6))),
            ["friction = ", "valid values", "sequence of 1 FrictionTensor"],
        ),
        (lambda: batch.simulate_bodies(BODY, FR, np.zeros((1, 6))), ["bodies = ", "valid"]),
        (lambda: batch.simulate_bodies(3, FR, np.zeros((1, 6))), ["bodies = 3", "valid"]),
        (lambda: batch.simulate_bodies([BODY], 7, np.zeros((1, 6))), ["friction = 7", "valid"]),
        (lambda: check_solver_options(1e-10, 0), ["max_steps = 0", "[1, 1000000000]"]),
        (lambda: check_solver_options(0.1, 10), ["rtol = 0.1", "valid range: (0, 0.001]"]),
        (lambda: ss.simulate(BODY, FR, ss.State(vx=1.0), ss.Load()), ["g = ", "valid values"]),
        (
            lambda: ss.simulate(BODY, FR, ss.State(vx=1.0), scan_step=0.1),
            ["scan_step = 0.1", "valid values: None"],
        ),
        (lambda: ss.simulate(BODY, FR, ss.State(vx=1.0), max_step=-1.0), ["max_step = -1.0"]),
        (lambda: ss.State(vx=2e8), ["vx = 200000000.0", "[-1e+08, 1e+08] m/s"]),
        (lambda: ss.State.from_speed(-1.0, 0.0), ["speed = -1.0", "[0, 1e+08] m/s"]),
        (lambda: ss.State(phi=math.inf), ["phi = inf", "valid range"]),
        (lambda: outcomes.status_message("done"), ["status = 'done'", "valid values: stopped"]),
        (lambda: outcomes.ending_message("x", loaded=True), ["valid values: stopped_stuck"]),
        (lambda: ss.Load(torque="1"), ["torque = '1'", "valid values"]),
        (lambda: ss.Load(frame="world"), ["frame = 'world'", "valid values: plane, body"]),
        (lambda: ss.Load(at=(1e7, 0.0)), ["at[0]", "1e+06"]),
    ],
)
def test_refusals_name_parameter_value_and_range(build, words):
    with pytest.raises((ValueError, TypeError)) as info:
        build()
    msg = str(info.value)
    assert re.search(r"\bvalid\b", msg), msg
    assert "np.float64" not in msg and "array(" not in msg, msg
    for w in words:
        assert w in msg, (w, msg)
