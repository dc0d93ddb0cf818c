"""Input validation shared by the value objects, the TOML loader and the CLI.

Every check raises :class:`ValueError` whose message names the parameter, the value
received and the valid range, so that a user can fix the input without reading code.
"""

from __future__ import annotations

import math
import numbers

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "positive",
    "finite",
    "in_range",
    "choice",
    "bounded",
    "symmetric",
    "real_array",
    "LENGTH",
    "MASS",
    "INERTIA_RATIO",
    "ASPECT",
    "COEFFICIENT",
    "SKEW",
    "GRAVITY",
    "WRENCH_TOL",
    "SPEED",
    "SPIN",
    "POSITION",
    "RATIO",
]

# ------------------------------------------------------------------------------------------
# Valid ranges (docs/errors.md, "Valid ranges", gives the measurements behind each one).
# The compiled kernel works in natural units (a = m = g = 1) and sees only b/a, the tensor,
# I/(m a²) and the direction of (v/a, ω); the dimensional bounds keep every product formed
# from them (m g, m a², I, √(a/g), positions/a) far inside the range of floats.
# ------------------------------------------------------------------------------------------
LENGTH = (1e-9, 1e6)  # semi-axes, radius [m]
MASS = (1e-12, 1e12)  # [kg]
INERTIA_RATIO = (1e-8, 1e8)  # I* = I/(m a²)
ASPECT = (1e-3, 30.0)  # b/a: the wrench meets 1e-13 m g (a) inside, misses it outside
COEFFICIENT = (1e-6, 5.0)  # fx, fy
SKEW = 5.0  # |f|
GRAVITY = (1e-6, 1e6)  # g [m/s²]
WRENCH_TOL = (1e-13, 1e-2)  # absolute quadrature target, units of m g and m g a
SPEED = 1e8  # |vx|, |vy| of a State [m/s]
SPIN = 1e12  # |ω| of a State [rad/s]
POSITION = 1e100  # |x|, |y| of a State [m]: any stop the other ranges allow is far inside
RATIO = (1e-9, 1e9)  # β/a in terminal-ratio inputs
#: largest step budget (the integrator counts steps in 64-bit integers; 1e9 steps of a few
#: microseconds each is already an hour)
MAX_STEPS = 1_000_000_000
T_END = 1e9  # the largest t_end [s] of a pushed run


def _as_float(name: str, value: object) -> float:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise ValueError(
            f"{name} must be a real number, got {_short(value)} ({type(value).__name__})"
        )
    try:
        return float(value)
    except (OverflowError, ValueError, TypeError):
        raise ValueError(
            f"{name} = {_short(value)} is not representable as a float; valid range: a real "
            "number of magnitude below 1.8e308"
        ) from None


def _short(value: object, limit: int = 60) -> str:
    """``repr(value)``, cut to ``limit`` characters (a huge int or string stays one short line)."""
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 - a repr that fails must not hide the real error
        text = f"<{type(value).__name__}>"
    text = " ".join(text.split())  # one line (an array's repr spans several)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _fmt_range(lo: float, hi: float, unit: str) -> str:
    u = f" {unit}" if unit else ""
    return f"[{lo:g}, {hi:g}]{u}"


def bounded(name: str, value: object, lo: float, hi: float, unit: str = "") -> float:
    """Return ``value`` as a float, or raise if it is not finite and in [lo, hi].

    The message names the parameter, the value, its unit and the closed range.
    """
    u = f" {unit}" if unit else ""
    if (
        isinstance(value, numbers.Integral)
        and not isinstance(value, (bool, np.bool_))
        and not -1e308 < int(value) < 1e308  # beyond float: OverflowError in float()
    ):
        raise ValueError(
            f"{name} = {_short(value)}{u} is invalid; valid range: {_fmt_range(lo, hi, unit)}"
        )
    x = _as_float(name, value)
    if not (math.isfinite(x) and lo <= x <= hi):
        raise ValueError(f"{name} = {x!r}{u} is invalid; valid range: {_fmt_range(lo, hi, unit)}")
    return x


def symmetric(name: str, value: object, bound: float, unit: str = "") -> float:
    """Return ``value`` as a float, or raise if it is not finite or |value| > ``bound``."""
    return bounded(name, value, -bound, bound, unit)


def real_array(
    name: str, value: object, lo: float = -math.inf, hi: float = math.inf, unit: str = ""
) -> NDArray[np.float64]:
    """``value`` as a float array (a scalar gives a 0-d array), every entry finite in [lo, hi].

    Bools, strings, complex numbers, objects and ragged sequences are refused with the
    parameter's name.
    """
    if isinstance(value, (bool, np.bool_, str, bytes)) or _holds_bool(value):
        raise ValueError(f"{name} must be a real number or array of them, got {_short(value)}")
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError, OverflowError):
        raise ValueError(
            f"{name} must be a real number or array of them, got {_short(value)}"
        ) from None
    if np.ma.is_masked(value):  # np.asarray drops a mask: its entries would be read as data
        raise ValueError(
            f"{name} has masked entries; valid values: plain real numbers (fill or drop them)"
        )
    if arr.dtype.kind == "O" and arr.ndim == 0:  # e.g. an int beyond int64 or a Fraction
        arr = np.asarray(_as_float(name, value))
    if arr.dtype.kind not in "fiu":
        raise ValueError(f"{name} must be a real number or array of them, got {_short(value)}")
    arr = arr.astype(float)
    bad = ~np.isfinite(arr) | (arr < lo) | (arr > hi)
    if bad.any():
        x = float(arr[bad].flat[0])
        u = f" {unit}" if unit else ""
        rng = (
            "any finite real number"
            if lo == -math.inf and hi == math.inf
            else _fmt_range(lo, hi, unit)
        )
        word = "is not finite" if not math.isfinite(x) else "is invalid"
        raise ValueError(f"{name} = {x!r}{u} {word}; valid range: {rng}")
    return arr


def _holds_bool(value: object) -> bool:
    """True if a (nested) list or tuple holds a bool (NumPy would read True as 1)."""
    if not isinstance(value, (list, tuple)):
        return False
    return any(isinstance(x, (bool, np.bool_)) or _holds_bool(x) for x in value)


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
        raise ValueError(f"{name} = {_short(value)} is invalid; valid values: {', '.join(options)}")
    return value.lower()
