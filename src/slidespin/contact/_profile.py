"""Time profiles shared by loads and inclines: checked pairs and angles, samples interpolated
linearly in time (:meth:`slidespin.Load.piecewise_linear`, :meth:`slidespin.Incline.piecewise_linear`)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from slidespin import _validate as v


def check_pair(
    name: str, value: Any, keys: tuple[str, str] | None = None
) -> tuple[float, float]:  # any value; checked here
    """A pair of finite floats; ``keys`` names the components (e.g. the TOML keys fx, fy)."""
    try:
        items = tuple(value)
    except TypeError:
        raise ValueError(
            f"{name} = {show_value(value)} is invalid; valid values: a pair of finite numbers "
            "or a function of time returning one"
        ) from None
    if len(items) != 2:
        raise ValueError(f"{name} = {show_value(value)} has {len(items)} components; valid: 2")
    k0, k1 = keys if keys is not None else (f"{name}[0]", f"{name}[1]")
    return (v.finite(k0, as_real(items[0])), v.finite(k1, as_real(items[1])))


def show_value(value: object) -> str:
    """A short repr with NumPy scalars and arrays shown as plain numbers (no np.float64(...))."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    elif isinstance(value, np.generic):
        value = value.item()
    elif isinstance(value, (tuple, list)):
        value = type(value)(x.item() if isinstance(x, np.generic) else x for x in value)
    return v._short(value)


class Profile:
    """Samples interpolated linearly in time (constant beyond the ends): the callable that
    :meth:`Load.piecewise_linear` and :meth:`Incline.piecewise_linear` build.

    Its ``times`` (the knots) are where the stick test of :func:`slidespin.simulate` always
    looks: between two knots the profile is affine in t.
    """

    __slots__ = ("times", "columns")

    def __init__(self, times: tuple[float, ...], *columns: tuple[float, ...]) -> None:
        self.times = times
        self.columns = columns

    def __call__(self, t: float) -> Any:
        vals = tuple(interp(t, self.times, c) for c in self.columns)
        return vals if len(vals) > 1 else vals[0]

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Profile):
            return NotImplemented
        return self.times == other.times and self.columns == other.columns

    def __hash__(self) -> int:
        return hash((self.times, self.columns))

    def __repr__(self) -> str:
        return (
            f"<piecewise linear: {len(self.times)} samples over "
            f"[{self.times[0]:.6g}, {self.times[-1]:.6g}] s>"
        )


def check_times(t: np.ndarray) -> None:
    if t.ndim != 1 or t.size < 2 or not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
        raise ValueError(
            f"times = {show_value(np.atleast_1d(t))} is invalid; valid values: "
            "at least 2 finite, strictly increasing times [s]"
        )


def interp(t: float, tt: tuple[float, ...], vals: tuple[float, ...]) -> float:
    """Linear interpolation, constant beyond the ends, as (1 − w) v₀ + w v₁: never
    overflows for finite samples (np.interp forms the slope, which can)."""
    t = float(t)
    if t <= tt[0]:
        return vals[0]
    if t >= tt[-1]:
        return vals[-1]
    i = int(np.searchsorted(tt, t, side="right")) - 1
    w = (t - tt[i]) / (tt[i + 1] - tt[i])
    return (1.0 - w) * vals[i] + w * vals[i + 1]


def as_real(x: object) -> object:
    """Plain float for NumPy scalars (numbers.Real rejects none of them, but be explicit)."""
    if isinstance(x, np.generic):
        return x.item()
    return x


def check_angle(name: str, value: object) -> float:
    """A tilt in [0, π/2) rad; the message says the unit and suggests math.radians."""
    x = v._as_float(name, as_real(value))
    if not (math.isfinite(x) and 0.0 <= x < math.pi / 2.0):
        hint = f"; degrees? use math.radians({x:g})" if 1.5707963267948966 <= x < 90.0 else ""
        raise ValueError(
            f"{name} = {x!r} rad is invalid; valid range: [0, 1.5708) rad, i.e. [0, π/2){hint}"
        )
    return x
