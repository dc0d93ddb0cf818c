"""Every refusal in the contact and fitting modules states the valid range or values.

A static check of the source: each ``raise ValueError(...)`` / ``raise TypeError(...)`` whose
message is written at the raise (a string, an f-string, or a name bound to one in the same
function) says "valid" (``valid range``, ``valid values``, ``valid here``, ...), and a few
refusals checked at run time.
"""

from __future__ import annotations

import ast
import math
from pathlib import Path

import pytest

import slidespin as ss

SRC = Path(__file__).resolve().parents[2] / "src" / "slidespin"
FILES = [
    *(
        f"contact/{n}.py"
        for n in (
            "friction",
            "shapes",
            "_polygon",
            "footprint_arrays",
            "statics",
            "static_set",
            "limit_surface",
            "_kernel_footprint",
            "_kernel_blade",
            "pressure_map",
            "pressure",
            "body",
            "incline",
            "wrench",
        )
    ),
    *(f"analysis/{n}.py" for n in ("fit", "fit_data", "fit_result", "_fit_problem")),
]


def _texts(node):
    """The literal text pieces of a message expression (str, f-string, concatenations)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return "".join(_texts(v) for v in node.values)
    if isinstance(node, ast.FormattedValue):
        return "{}"
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left, right = _texts(node.left), _texts(node.right)
        if left is not None or right is not None:
            return (left or "{}") + (right or "{}")
    return None


def _refusals(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for func in ast.walk(tree):
        if not isinstance(func, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        bound = {}
        for node in ast.walk(func):
            if isinstance(node, ast.Assign) and len(node.targets) == 1:
                target = node.targets[0]
                if isinstance(target, ast.Name) and _texts(node.value) is not None:
                    bound[target.id] = _texts(node.value)
        for node in ast.walk(func):
            exc = node.exc if isinstance(node, ast.Raise) else None
            if not (
                isinstance(exc, ast.Call)
                and getattr(exc.func, "id", "")
                in (
                    "ValueError",
                    "TypeError",
                )
            ):
                continue
            if not exc.args:
                yield node.lineno, ""
                continue
            arg = exc.args[0]
            text = bound.get(arg.id) if isinstance(arg, ast.Name) else _texts(arg)
            if text is not None:  # a message built elsewhere is checked where it is built
                yield node.lineno, text


@pytest.mark.parametrize("rel", FILES)
def test_every_refusal_states_what_is_valid(rel):
    missing = [
        f"{rel}:{line}: {text[:70]!r}"
        for line, text in _refusals(SRC / rel)
        if "valid" not in text.lower()
    ]
    assert not missing, "\n".join(missing)


@pytest.mark.parametrize(
    "make",
    [
        lambda: ss.FrictionTensor(0.3, 0.4, angle=30),
        lambda: ss.Polygon([(0, 0), (1, 0), b"ab"]),
        lambda: ss.Disk(0.1).outlines(-1),
        lambda: ss.Body(ss.Rectangle(1, 1), ss.UniformPressure(), 1.0).engine_params("x"),
        lambda: ss.Incline(math.pi / 2),
        lambda: ss.Pads(),
    ],
)
def test_sample_refusals_at_run_time(make):
    with pytest.raises(ValueError, match="valid"):
        make()
