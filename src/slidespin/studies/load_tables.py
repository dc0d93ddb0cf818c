"""The ``[load]`` and ``[incline]`` tables of a case file (MODEL §11): every key checked."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, TypeVar

import numpy as np

from slidespin import _validate as v
from slidespin.contact._profile import as_real, check_pair, show_value
from slidespin.contact.incline import Incline
from slidespin.motion.loads import Load

_T = TypeVar("_T")

__all__ = ["INCLINE_KEYS", "LOAD_KEYS", "incline_from_table", "load_from_table"]


#: keys of a ``[load]`` table in a case file (see :func:`load_from_table`)
LOAD_KEYS = (
    "force",
    "fx",
    "fy",
    "torque",
    "frame",
    "at",
    "height",
    "times",
    "profile_fx",
    "profile_fy",
    "profile_torque",
)
#: keys of an ``[incline]`` table in a case file (see :func:`incline_from_table`)
INCLINE_KEYS = (
    "angle",
    "angle_deg",
    "downhill",
    "downhill_deg",
    "times",
    "profile_angle",
    "profile_angle_deg",
)


def _table_value(where: str, build: Callable[..., _T], *args: Any, **kwargs: Any) -> _T:
    try:
        return build(*args, **kwargs)
    except ValueError as exc:
        msg = str(exc)
        raise ValueError(msg if msg.startswith("[") else f"[{where}] {msg}") from None


def load_from_table(table: dict, where: str = "load") -> Load:
    """Build a :class:`Load` from a ``[load]`` TOML table; every key is checked.

    A constant load takes ``fx``, ``fy`` [N] (or ``force = [Fx, Fy]``, the name of the
    Python API; not both), ``torque`` [N m], ``frame`` ("plane" or "body") and
    ``at`` = [ξ, η] [m] (body frame, from the patch centre; default G) and ``height`` [m]
    (where it acts above the plane, for a tall body; default G's height). A load
    varying in time takes ``times`` [s] with ``profile_fx``, ``profile_fy`` [N] and
    optionally ``profile_torque`` [N m] at those times, interpolated linearly
    (:meth:`Load.piecewise_linear`), instead of ``fx``, ``fy``, ``torque``.

    Examples
    --------
    >>> load_from_table({"fx": 2.0, "torque": 0.1}).wrench(0.0)
    (2.0, 0.0, 0.1)
    """
    if not isinstance(table, dict):
        raise ValueError(f"[{where}] must be a table, got {table!r}; valid: a TOML table")
    unknown = sorted(set(table) - set(LOAD_KEYS))
    if unknown:
        raise ValueError(
            f"unknown key {unknown[0]!r} in [{where}]; valid keys: " + ", ".join(sorted(LOAD_KEYS))
        )
    frame = table.get("frame", "plane")
    at = table.get("at")
    if "force" in table:
        both = [k for k in ("fx", "fy") if k in table]
        if both:
            raise ValueError(
                f"[{where}] gives both 'force' and {both[0]!r}; give force = [Fx, Fy] or "
                "fx, fy, not both (valid: one of the two forms)"
            )
    profile = [k for k in ("times", "profile_fx", "profile_fy", "profile_torque") if k in table]
    if profile:
        constant = [k for k in ("force", "fx", "fy", "torque") if k in table]
        if constant:
            raise ValueError(
                f"[{where}] give either {constant[0]!r} (a constant load) or "
                "times/profile_* (a load varying in time), not both (valid: one of the two)"
            )
        for key in ("times", "profile_fx", "profile_fy"):
            if key not in table:
                raise ValueError(
                    f"[{where}] is missing the required key {key!r} of a profile; valid: times "
                    "with profile_fx, profile_fy (and optionally profile_torque)"
                )
        return _table_value(
            where,
            Load.piecewise_linear,
            table["times"],
            table["profile_fx"],
            table["profile_fy"],
            table.get("profile_torque"),
            frame,
            at,
            names=("profile_fx", "profile_fy", "profile_torque"),
            height=table.get("height"),
        )
    if "force" in table:
        force = _table_value(where, check_pair, "force", table["force"])
    else:
        force = _table_value(
            where,
            check_pair,
            "force",
            (table.get("fx", 0.0), table.get("fy", 0.0)),
            ("fx", "fy"),
        )
    return _table_value(
        where, Load, force, table.get("torque", 0.0), frame, at, table.get("height")
    )


def incline_from_table(table: dict, where: str = "incline") -> Incline:
    """Build an :class:`Incline` from an ``[incline]`` TOML table (``angle`` or ``angle_deg``,
    ``downhill`` or ``downhill_deg``; radians unless the key ends in ``_deg``).

    A tilt varying in time takes ``times`` [s] with ``profile_angle`` [rad] or
    ``profile_angle_deg`` at those times, interpolated linearly
    (:meth:`Incline.piecewise_linear`), instead of ``angle``.

    Examples
    --------
    >>> incline_from_table({"angle_deg": 30.0}).downhill_factor  # doctest: +ELLIPSIS
    0.4999...
    >>> rising = incline_from_table({"times": [0.0, 10.0], "profile_angle_deg": [0.0, 30.0]})
    >>> round(math.degrees(rising.angle_at(5.0)), 9)
    15.0
    """
    if not isinstance(table, dict):
        raise ValueError(f"[{where}] must be a table, got {table!r}; valid: a TOML table")
    unknown = sorted(set(table) - set(INCLINE_KEYS))
    if unknown:
        raise ValueError(
            f"unknown key {unknown[0]!r} in [{where}]; valid keys: " + ", ".join(INCLINE_KEYS)
        )

    def angle(key, default=None):
        if key in table and f"{key}_deg" in table:
            raise ValueError(
                f"[{where}] gives both {key} and {key}_deg; give one (valid: {key} in rad or "
                f"{key}_deg in degrees)"
            )
        if f"{key}_deg" in table:
            deg = v.finite(f"[{where}] {key}_deg", as_real(table[f"{key}_deg"]))
            if key == "angle" and not 0.0 <= deg < 90.0:
                raise ValueError(
                    f"[{where}] angle_deg = {deg!r} is invalid; valid range: [0, 90) degrees"
                )
            return math.radians(deg)
        if key not in table:
            if default is None:
                raise ValueError(
                    f"[{where}] is missing the required key 'angle' (or angle_deg); valid: "
                    "angle in [0, pi/2) rad or angle_deg in [0, 90), or times with a profile"
                )
            return default
        return v.finite(f"[{where}] {key}", as_real(table[key]))

    profile = [k for k in ("times", "profile_angle", "profile_angle_deg") if k in table]
    if profile:
        fixed = [k for k in ("angle", "angle_deg") if k in table]
        if fixed:
            raise ValueError(
                f"[{where}] give either {fixed[0]!r} (a fixed tilt) or times/profile_angle "
                "(a tilt varying in time), not both (valid: one of the two)"
            )
        if "times" not in table:
            raise ValueError(
                f"[{where}] is missing the required key 'times' of a profile; valid: times "
                "[s] with profile_angle or profile_angle_deg"
            )
        if ("profile_angle" in table) == ("profile_angle_deg" in table):
            raise ValueError(
                f"[{where}] give one of 'profile_angle' [rad] or 'profile_angle_deg' with "
                "'times' (valid: exactly one of them)"
            )
        if "profile_angle_deg" in table:
            deg = _table_value(where, v.real_array, "profile_angle_deg", table["profile_angle_deg"])
            if np.any(deg >= 90.0) or np.any(deg < 0.0):
                raise ValueError(
                    f"[{where}] profile_angle_deg = {show_value(deg)} is invalid; valid range: "
                    "[0, 90) degrees"
                )
            angles: Any = np.radians(deg)
            name = "profile_angle_deg (in rad)"
        else:
            angles, name = table["profile_angle"], "profile_angle"
        return _table_value(
            where,
            Incline.piecewise_linear,
            table["times"],
            angles,
            angle("downhill", 0.0),
            name=name,
        )
    return _table_value(where, Incline, angle("angle"), angle("downhill", 0.0))
