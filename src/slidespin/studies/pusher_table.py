"""The ``[pusher]`` table of a case file (MODEL §13): a finger or a flat pusher, every key checked.

A case file with a ``[pusher]`` table describes a body pushed along a prescribed path
(:class:`~slidespin.motion.pushers.PointPusher`, :class:`~slidespin.motion.pushers.LinePusher`);
``slidespin simulate`` runs it with :func:`slidespin.simulate` ``(..., pusher=..., t_end=...)``.
The keys, in the names of the Python API:

==============  ==============================================================================
key             meaning
==============  ==============================================================================
``kind``        ``"point"`` (a finger) or ``"line"`` (a flat pusher); required
``mu``          μp, the pusher–body Coulomb coefficient: a finite number ≥ 0 (default 0)
``path``        waypoints, piecewise linear in time, plane frame, SI: rows ``[t, x, y]`` [s, m,
                m] for a point pusher; rows ``[t, x, y, angle]`` [s, m, m, rad] for a line
                pusher (the segment's centre and its direction from OX)
``path_deg``    a line pusher's waypoints with the angle in degrees, rows
                ``[t, x, y, angle_deg]`` (instead of ``path``; the case files' rule: angles in
                radians unless the key ends in ``_deg``)
``length``      a line pusher's length [m], in [1e-9, 1e6]; required for ``kind = "line"``
``outline``     the outline the pusher touches, for a body wider than its patch (default: the
                patch's convex hull): vertices ``[[xi, eta], ...]`` [m] in the body frame (from
                the patch centre, like a polygon's), or an inline table ``{shape = "rectangle",
                length = ..., width = ...}`` (any footprint shape but pads, with ``centre`` and
                ``angle``) or ``{shape = "ellipse", a = ..., b = ...}`` (centred on the patch
                centre, a along ξ)
==============  ==============================================================================

Without ``[solver] t_end`` a pushed case runs to the last time of its path (which must then
be > 0); give ``t_end`` to see the body coast after the pusher stops. ``[initial]`` is the
body's start (a finger at t = 0 on or outside the outline), and ``[load]``, ``[incline]`` and
``[solver] g, rtol, max_steps`` apply as in any run. Every bad value is one line naming
``[pusher]``, the key, the value and the valid range.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import Any

from slidespin import _validate as v
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.outline import body_outline
from slidespin.motion.pushers import LinePusher, PointPusher

__all__ = ["PUSHER_KEYS", "PUSHER_KINDS", "pusher_from_table", "pusher_t_end"]

#: keys of a ``[pusher]`` table in a case file (see :func:`pusher_from_table`)
PUSHER_KEYS = ("kind", "mu", "path", "path_deg", "length", "outline")
#: the values of ``[pusher] kind``
PUSHER_KINDS = ("point", "line")


def _short(value: object, n: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= n else text[: n - 1] + "…"


def _where(where: str, build: Callable[..., Any], *args: Any, rename: str = "", **kwargs: Any):
    """Call ``build``; prefix its ValueError with ``[where]`` (and say ``rename`` for a
    message about ``path``)."""
    try:
        return build(*args, **kwargs)
    except ValueError as exc:
        msg = str(exc)
        if rename:
            msg = re.sub(r"\bpath\b", rename, msg)
        raise ValueError(msg if msg.startswith("[") else f"[{where}] {msg}") from None


def pusher_from_table(
    table: dict,
    body,
    footprint: Callable[[dict, str], Any] | None = None,
    where: str = "pusher",
) -> tuple[PointPusher | LinePusher, Any]:
    """Build the pusher (and the outline it touches) from a ``[pusher]`` TOML table.

    Parameters
    ----------
    table : dict
        The parsed ``[pusher]`` table (keys: :data:`PUSHER_KEYS`, module notes).
    body : slidespin.Body
        The case's body (an ``outline`` must enclose its mass centre G).
    footprint : callable, optional
        ``footprint(table, where)`` builds a footprint from an inline ``outline`` table (the
        case reader's own); without it only vertex arrays and ellipses are accepted.
    where : str
        The table's name in messages.

    Returns
    -------
    (PointPusher or LinePusher, outline)
        ``outline`` is None (the patch's), an (n, 2) list of vertices, a footprint or an
        :class:`~slidespin.Ellipse`, body frame [m], for the ``outline=`` of
        :func:`slidespin.simulate_pushed` and :func:`slidespin.push_quasi_static`.

    Raises
    ------
    ValueError
        One line naming ``[pusher]``, the key, its value and the valid range.

    Examples
    --------
    >>> import slidespin as ss
    >>> box = ss.Body(ss.Rectangle(0.4, 0.3), ss.UniformPressure(), mass=5.0)
    >>> finger, _ = pusher_from_table(
    ...     {"kind": "point", "mu": 0.3, "path": [[0, -0.3, 0.0], [1, -0.1, 0.0]]}, box)
    >>> finger
    PointPusher(path=<2 waypoints over [0, 1] s>, mu=0.3)
    """
    if not isinstance(table, dict):
        raise ValueError(f"[{where}] must be a table, got {_short(table)}; valid: a TOML table")
    unknown = sorted(set(table) - set(PUSHER_KEYS))
    if unknown:
        raise ValueError(
            f"unknown key {unknown[0]!r} in [{where}]; valid keys: " + ", ".join(PUSHER_KEYS)
        )
    if "kind" not in table:
        raise ValueError(
            f"[{where}] is missing the required key 'kind'; valid: kind = \"point\" (a finger) "
            'or "line" (a flat pusher)'
        )
    kind = v.choice(f"[{where}] kind", table["kind"], PUSHER_KINDS)
    mu = table.get("mu", 0.0)
    if "path" in table and "path_deg" in table:
        raise ValueError(
            f"[{where}] gives both path and path_deg; give one (valid: path with the angle in "
            "rad, or path_deg with the angle in degrees)"
        )
    if kind == "point":
        for key, why in (
            ("length", "a finger has no length"),
            ("path_deg", "a finger's rows [t, x, y] carry no angle"),
        ):
            if key in table:
                raise ValueError(
                    f'[{where}] {key} = {_short(table[key])} is for kind = "line" ({why}); '
                    f"valid: leave {key} out of a point pusher, whose path rows are [t, x, y]"
                )
        if "path" not in table:
            raise ValueError(
                f"[{where}] is missing the required key 'path'; valid: path = [[t, x, y], ...] "
                "(time [s], position [m], plane frame)"
            )
        pusher: PointPusher | LinePusher = _where(where, PointPusher, table["path"], mu)
    else:
        if "length" not in table:
            raise ValueError(
                f"[{where}] is missing the required key 'length' of a line pusher; valid: "
                "length [m] in [1e-09, 1e+06]"
            )
        if "path" not in table and "path_deg" not in table:
            raise ValueError(
                f"[{where}] is missing the required key 'path'; valid: path = [[t, x, y, "
                "angle], ...] (s, m, m, rad) or path_deg = [[t, x, y, angle_deg], ...]"
            )
        if "path" in table:
            pusher = _where(where, LinePusher, table["length"], table["path"], mu)
        else:
            rows = table["path_deg"]
            # checked as given (shape, numbers, times), then with the angles in radians
            first = _where(where, LinePusher, table["length"], rows, mu, rename="path_deg")
            rad = first.path.copy()
            rad[:, 3] = [math.radians(a) for a in rad[:, 3]]
            pusher = _where(where, LinePusher, table["length"], rad, mu, rename="path_deg")
    outline = None
    if "outline" in table:
        outline = _outline(table["outline"], body, footprint, where)
    return pusher, outline


def _outline(value: object, body, footprint, where: str):
    """The ``outline`` key: vertices, or an inline table of a footprint or an ellipse."""
    key = f"{where}.outline"
    if isinstance(value, dict):
        shape = value.get("shape")
        if shape == "ellipse":
            extra = sorted(set(value) - {"shape", "a", "b"})
            if extra or "a" not in value or "b" not in value:
                raise ValueError(
                    f"[{key}] shape 'ellipse' takes a and b [m] "
                    + (f"(not {extra[0]!r}); " if extra else "(both required); ")
                    + "valid keys: shape, a, b"
                )
            a = v.positive(f"[{key}] a", value["a"], "m")
            b = v.positive(f"[{key}] b", value["b"], "m")
            shape_obj: Any = _where(key, Ellipse, a, b)
        elif footprint is None:
            raise ValueError(
                f"[{where}] outline = {_short(value)} is invalid; valid values: vertices "
                '[[xi, eta], ...] [m] or {shape = "ellipse", a = ..., b = ...}'
            )
        else:
            if shape == "pads":
                raise ValueError(
                    f"[{key}] shape 'pads' is invalid for an outline; valid shapes: polygon, "
                    "rectangle, disk, annulus, ellipse (or vertices [[xi, eta], ...])"
                )
            shape_obj = footprint(value, key)
        _where(where, body_outline, body, shape_obj)
        return shape_obj
    if not isinstance(value, list) or not all(
        isinstance(row, list)
        and len(row) == 2
        and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in row)
        for row in value
    ):
        raise ValueError(
            f"[{where}] outline = {_short(value)} is invalid; valid values: at least 3 vertices "
            "[[xi, eta], ...] [m] (body frame), or an inline table {shape = ..., ...}"
        )
    _where(where, body_outline, body, value)
    return [tuple(float(x) for x in row) for row in value]


def pusher_t_end(pusher: PointPusher | LinePusher, t_end: float | None, where: str = "pusher"):
    """The end of a pushed run: ``[solver] t_end`` if given, else the path's last time
    (which must then be > 0)."""
    if t_end is not None:
        return t_end
    last = float(pusher.path[-1, 0])
    if not last > 0.0:
        raise ValueError(
            f"[{where}] path ends at t = {last!r} s and [solver] t_end is not given; valid: "
            "[solver] t_end in (0, 1e9] s, or a path whose last time is > 0 s (the default end)"
        )
    return v.in_range(f"[{where}] path's last time", last, 0.0, 1e9, lo_open=True)
