"""The friction law keys of a case file's ``[friction]`` table and its ``[spring]`` table
(MODEL §14): every key checked, the names of the Python API.

``[friction]`` takes, beside ``fx``, ``fy``, ``f``, ``frame``, ``angle``: ``static`` (μs/μk) and
``law`` = ``"constant"`` (default), ``"power"`` (``q``, ``v0``), ``"stribeck"``
(``static_ratio``, ``vs``, ``delta``) or ``"table"`` (``speeds``, ``factors``). ``[spring]``
takes ``stiffness`` [N/m], ``anchor_path`` = [[t, x, y], ...], ``at`` = [ξ, η], ``damping``
[N s/m] and ``rest_length`` [m] (:class:`~slidespin.Spring`).
"""

from __future__ import annotations

from slidespin.contact.speed_laws import PowerLaw, SpeedTable, Stribeck
from slidespin.motion.springs import Spring

__all__ = ["LAW_KEYS", "LAWS", "SPRING_KEYS", "speed_law_from_table", "spring_from_table"]

#: the speed laws a ``[friction] law`` names, and each one's keys
LAWS = {
    "constant": (),
    "power": ("q", "v0"),
    "stribeck": ("static_ratio", "vs", "delta"),
    "table": ("speeds", "factors"),
}
#: the law keys of a ``[friction]`` table (beside the tensor's)
LAW_KEYS = ("static", "law", "q", "v0", "static_ratio", "vs", "delta", "speeds", "factors")
#: keys of a ``[spring]`` table
SPRING_KEYS = ("stiffness", "anchor_path", "at", "damping", "rest_length")
_REQUIRED = {"power": ("q",), "stribeck": ("static_ratio", "vs"), "table": ("speeds", "factors")}
_BUILD = {"power": PowerLaw, "stribeck": Stribeck, "table": SpeedTable}


def _wrap(where: str, build, **kwargs):
    try:
        return build(**kwargs)
    except ValueError as exc:
        msg = str(exc)
        raise ValueError(msg if msg.startswith("[") else f"[{where}] {msg}") from None


def speed_law_from_table(table: dict, where: str = "friction"):
    """The speed law (or None) of a ``[friction]`` table's ``law`` and its keys."""
    name = table.get("law", "constant")
    if not isinstance(name, str) or name not in LAWS:
        raise ValueError(
            f"[{where}] law = {name!r} is invalid; valid values: "
            + ", ".join(repr(k) for k in LAWS)
        )
    given = {k for k in LAWS["power"] + LAWS["stribeck"] + LAWS["table"] if k in table}
    stray = sorted(given - set(LAWS[name]))
    if stray:
        raise ValueError(
            f"[{where}] key {stray[0]!r} does not belong to law = {name!r}; valid keys of that "
            f"law: {', '.join(LAWS[name]) or 'none'}"
        )
    if name == "constant":
        return None
    for key in _REQUIRED[name]:
        if key not in table:
            raise ValueError(
                f"[{where}] law = {name!r} is missing the required key {key!r}; valid: give "
                + ", ".join(_REQUIRED[name])
            )
    return _wrap(where, _BUILD[name], **{k: table[k] for k in LAWS[name] if k in table})


def spring_from_table(table: dict, where: str = "spring") -> Spring:
    """A :class:`~slidespin.Spring` from a ``[spring]`` table; every key is checked."""
    unknown = sorted(set(table) - set(SPRING_KEYS))
    if unknown:
        raise ValueError(
            f"[{where}] has the unknown key {unknown[0]!r}; valid keys: {', '.join(SPRING_KEYS)}"
        )
    for key in ("stiffness", "anchor_path"):
        if key not in table:
            raise ValueError(
                f"[{where}] is missing the required key {key!r}; valid: a [{where}] table that "
                f"gives {key}"
            )
    return _wrap(where, Spring, **table)
