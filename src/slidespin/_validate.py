"""Input validation shared by the value objects, the TOML loader and the CLI.

Every check raises :class:`ValueError` whose message names the parameter, the value
received and the valid range, so that a user can fix the input without reading code.
"""

from __future__ import annotations

import math
import numbers

__all__ = ["positive", "finite", "in_range", "choice"]


def _as_float(name: str, value: object) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a real number, got {value!r} ({type(value).__name__})")
    return float(value)


def finite(name: str, value: object) -> float:
    """Return ``value`` as a float, or raise if it is not a finite real number."""
    x = _as_float(name, value)
    if not math.isfinite(x):
        raise ValueError(f"{name} = {x!r} is not finite; valid range: any finite real number")
    return x


def positive(name: str, value: object, unit: str = "") -> float:
    """Return ``value`` as a float, or raise if it is not finite and > 0."""
    x = _as_float(name, value)
    if not (math.isfinite(x) and x > 0.0):
        u = f" {unit}" if unit else ""
        raise ValueError(f"{name} = {x!r}{u} is invalid; valid range: finite and > 0{u}")
    return x


def in_range(
    name: str,
    value: object,
    lo: float,
    hi: float,
    *,
    lo_open: bool = False,
    hi_open: bool = False,
) -> float:
    """Return ``value`` as a float, or raise if it lies outside the interval."""
    x = _as_float(name, value)
    ok = math.isfinite(x) or (math.isinf(x) and math.isinf(hi) and x > 0 and not hi_open)
    ok = ok and (x > lo if lo_open else x >= lo) and (x < hi if hi_open else x <= hi)
    if not ok:
        left = "(" if lo_open else "["
        right = ")" if hi_open else "]"
        raise ValueError(f"{name} = {x!r} is invalid; valid range: {left}{lo:g}, {hi:g}{right}")
    return x


def choice(name: str, value: object, options: tuple[str, ...]) -> str:
    """Return ``value`` if it is one of ``options`` (case-insensitive), else raise."""
    if not isinstance(value, str) or value.lower() not in options:
        raise ValueError(f"{name} = {value!r} is invalid; valid values: {', '.join(options)}")
    return value.lower()
