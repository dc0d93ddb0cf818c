"""Cases described in TOML files (``slidespin simulate CASE.toml``).

A case file has the tables ``[patch]``, ``[pressure]``, ``[friction]``, ``[body]``,
``[initial]`` and optionally ``[solver]``, ``[load]``, ``[spring]`` (MODEL §14,
:mod:`slidespin.studies.law_tables`, which also reads the speed-law keys of ``[friction]``),
``[incline]`` and ``[pusher]`` (a finger
or a flat pusher moved along a path, MODEL §13: :mod:`slidespin.studies.pusher_table`; see
``examples/*.toml``). The patch is an ellipse
or a circle (the paper's), or a footprint (MODEL §10): ``shape = "polygon"`` (``vertices =
[[xi, eta], ...]``), ``"rectangle"`` (``length``, ``width``), ``"annulus"`` (``inner_radius``,
``outer_radius``), ``"disk"`` (``radius``), each optionally placed by ``centre = [xi, eta]``
and ``angle``/``angle_deg``, or ``"pads"`` with one ``[[patch.pads]]`` table per pad (any of
the four footprint shapes). Every key is checked:
an unknown key (a typo) or a missing required key is an error naming the table and the key,
never silently ignored. Angles are in radians unless the key ends in ``_deg``.

The ``[initial]`` table uses the names of the sweep specifications and of the sweep result
columns (one vocabulary, :data:`INITIAL_KEYS`): ``x0``, ``y0`` [m], ``phi0`` [rad] (or
``phi0_deg``), and either ``v0`` [m/s] with ``theta0`` [rad] (or ``theta0_deg``), the speed of
G and its direction, or ``vx0``, ``vy0`` [m/s]; ``omega0`` [rad/s]. The earlier names ``x``,
``y``, ``phi``, ``phi_deg``, ``speed``, ``theta``, ``theta_deg``, ``vx``, ``vy``, ``omega`` are
aliases (:data:`INITIAL_ALIASES`), accepted so that existing case files keep working; a
message about a key names it as the file spells it.

A command that reads a case file but cannot honour one of its tables or keys refuses it
(:func:`refuse_unused`): every option of a case file is either used or refused.

Files are read defensively (:func:`read_toml`, also used for sweep specs): only a regular file
(a FIFO or a device such as ``/dev/zero`` is refused without waiting), at most
:data:`MAX_FILE_BYTES` bytes, UTF-8 text, nesting of at most :data:`MAX_DEPTH` levels, integers
within 64 bits; ``name`` has at most :data:`MAX_NAME_CHARS` characters and
``[solver] max_steps`` at most :data:`MAX_STEPS_LIMIT`. Every refusal is one line naming the
file and the key.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass

from slidespin import _validate as v
from slidespin._io import read_regular_file
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.pressure import pressure_law_from_name
from slidespin.contact.shapes import Annulus, Circle, Disk, Pads, Polygon, Rectangle
from slidespin.motion.loads import Load
from slidespin.motion.pushers import LinePusher, PointPusher
from slidespin.motion.springs import Spring
from slidespin.motion.state import State
from slidespin.studies.law_tables import (
    LAW_KEYS,
    SPRING_KEYS,
    speed_law_from_table,
    spring_from_table,
)
from slidespin.studies.load_tables import (
    INCLINE_KEYS,
    LOAD_KEYS,
    incline_from_table,
    load_from_table,
)
from slidespin.studies.pusher_table import PUSHER_KEYS, pusher_from_table, pusher_t_end

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

__all__ = [
    "Case",
    "load_case",
    "case_from_dict",
    "read_toml",
    "MAX_FILE_BYTES",
    "MAX_NAME_CHARS",
    "MAX_DEPTH",
    "MAX_STEPS_LIMIT",
    "INITIAL_KEYS",
    "INITIAL_ALIASES",
    "read_case",
    "refuse_unused",
]

#: largest case file or sweep specification read [bytes] (real ones are about 1 kB)
MAX_FILE_BYTES = 1_000_000
#: longest ``name`` of a case or sweep [characters] (it is printed and drawn as a title)
MAX_NAME_CHARS = 200
#: deepest nesting of tables, inline tables and arrays in a case file or sweep spec
MAX_DEPTH = 6
#: largest ``[solver] max_steps`` (the step counter is a 64-bit integer; 10⁹ steps are hours)
MAX_STEPS_LIMIT = v.MAX_STEPS
_INT64 = 2**63 - 1

#: keys of each footprint shape in [patch] (and in every [[patch.pads]] entry)
_FOOTPRINT_KEYS = {
    "polygon": {"vertices"},
    "rectangle": {"length", "width"},
    "annulus": {"inner_radius", "outer_radius"},
    "disk": {"radius"},
}
_PLACEMENT = {"centre", "angle", "angle_deg"}
_SHAPES = ("ellipse", "circle", *_FOOTPRINT_KEYS, "pads")

#: the keys of ``[initial]`` (the names of the sweep specifications and result columns)
INITIAL_KEYS = (
    "x0",
    "y0",
    "phi0",
    "phi0_deg",
    "v0",
    "theta0",
    "theta0_deg",
    "vx0",
    "vy0",
    "omega0",
)
#: earlier names of the ``[initial]`` keys, still accepted (alias → name)
INITIAL_ALIASES = {
    "x": "x0",
    "y": "y0",
    "phi": "phi0",
    "phi_deg": "phi0_deg",
    "speed": "v0",
    "theta": "theta0",
    "theta_deg": "theta0_deg",
    "vx": "vx0",
    "vy": "vy0",
    "omega": "omega0",
}

_TABLES = {
    "patch": {
        "shape",
        "a",
        "b",
        "eccentricity",
        "radius",
        "vertices",
        "length",
        "width",
        "inner_radius",
        "outer_radius",
        "centre",
        "angle",
        "angle_deg",
        "pads",
    },
    "pressure": {"law", "xi_c", "eta_c"},
    "friction": {"fx", "fy", "f", "frame", "angle", "angle_deg", *LAW_KEYS},
    "body": {"mass", "moment_of_inertia", "inertia_ratio", "height"},
    "initial": set(INITIAL_KEYS) | set(INITIAL_ALIASES),
    "solver": {"g", "rtol", "max_steps", "t_end"},
    "load": set(LOAD_KEYS),
    "spring": set(SPRING_KEYS),
    "incline": set(INCLINE_KEYS),
    "pusher": set(PUSHER_KEYS),
}
_TOP = {"name", "description"}


@dataclass(frozen=True, slots=True)
class Case:
    """A complete simulation case: body, friction, initial state and solver settings.

    ``load``, ``incline`` and ``t_end`` are the ``[load]``, ``[incline]`` and ``[solver] t_end``
    of the file (MODEL §11; with a ``[spring]``, ``load`` is the Spring, or [Load, Spring]);
    ``pusher`` and ``outline`` its ``[pusher]`` (MODEL §13: a
    :class:`~slidespin.motion.pushers.PointPusher` or
    :class:`~slidespin.motion.pushers.LinePusher`, and the outline it touches, None for the
    patch's). A pushed case always has ``t_end``: the file's, or the path's last time.
    """

    body: Body
    friction: FrictionTensor
    initial_state: State
    g: float = 9.81
    rtol: float = 1e-10
    max_steps: int = 200_000
    name: str = ""
    load: Load | Spring | list | None = None
    incline: Incline | None = None
    t_end: float | None = None
    pusher: PointPusher | LinePusher | None = None
    outline: object = None

    @property
    def loaded(self) -> bool:
        """True if the case runs the stick-slip engine (MODEL §11): applied loads, a tilt, a
        time bound or a tall body, and no pusher (a pushed case is :attr:`pushed`)."""
        if self.pusher is not None:
            return False
        if self.body.height > 0.0:  # a tall body runs on the stick-slip engine (MODEL §14)
            return True
        return self.load is not None or self.incline is not None or self.t_end is not None

    @property
    def pushed(self) -> bool:
        """True if the case has a ``[pusher]`` (MODEL §13): ``slidespin simulate`` runs
        :func:`slidespin.simulate` with ``pusher=`` and ``t_end=`` (loads and a tilt too)."""
        return self.pusher is not None


def _angle(table: dict, where: str, key: str, default: float = 0.0) -> float:
    if key in table and f"{key}_deg" in table:
        raise ValueError(
            f"[{where}] gives both {key} and {key}_deg; give one (valid: {key} in rad or "
            f"{key}_deg in degrees)"
        )
    if f"{key}_deg" in table:
        return math.radians(v.finite(f"[{where}] {key}_deg", table[f"{key}_deg"]))
    return v.finite(f"[{where}] {key}", table.get(key, default))


def _in(where: str, build, *args, **kwargs):
    """Call ``build``; prefix its ValueError with the TOML table it came from."""
    try:
        return build(*args, **kwargs)
    except ValueError as exc:
        msg = str(exc)
        raise ValueError(msg if msg.startswith("[") else f"[{where}] {msg}") from None


def _need(table: dict, where: str, key: str):
    if key not in table:
        raise ValueError(
            f"[{where}] is missing the required key {key!r}; valid: a [{where}] table that "
            f"gives {key}"
        )
    return table[key]


def case_from_dict(data: dict) -> Case:
    """Build and validate a :class:`Case` from a parsed TOML document."""
    if not isinstance(data, dict):
        raise ValueError(
            f"a case must be a TOML table, got {type(data).__name__}; valid: a document with "
            "the tables [patch], [pressure], [friction], [body], [initial]"
        )
    for key in data:
        if key not in _TABLES and key not in _TOP:
            raise ValueError(
                f"unknown table or key {key!r} in the case file; valid: "
                + ", ".join(sorted(set(_TABLES) | _TOP))
            )
    for name in ("patch", "pressure", "friction", "body", "initial"):
        if name not in data:
            raise ValueError(
                f"the case file is missing the table [{name}]; valid: a case file with the "
                "tables [patch], [pressure], [friction], [body], [initial]"
            )
    for name, allowed in _TABLES.items():
        table = data.get(name, {})
        if not isinstance(table, dict):
            raise ValueError(f"[{name}] must be a table, got {_short(table)}; valid: a TOML table")
        for key in table:
            if key not in allowed:
                raise ValueError(
                    f"unknown key {key!r} in [{name}]; valid keys: {', '.join(sorted(allowed))}"
                )

    p = data["patch"]
    shape = v.choice("[patch] shape", p.get("shape", "ellipse"), _SHAPES)
    if shape in _FOOTPRINT_KEYS or shape == "pads":
        patch = _footprint(p, "patch")
    elif shape == "circle":
        extra = sorted(set(p) - {"shape", "radius"})
        if extra:
            raise ValueError(
                f"[patch] shape 'circle' takes only 'radius', not {extra[0]!r}; valid keys: "
                "shape, radius"
            )
        patch = _in("patch", Circle, v.positive("[patch] radius", _need(p, "patch", "radius"), "m"))
    else:
        extra = sorted(set(p) - {"shape", "a", "b", "eccentricity", "radius"})
        if extra:
            raise ValueError(
                f"[patch] shape 'ellipse' takes a and b or eccentricity, not {extra[0]!r}; "
                "valid keys: shape, a, b, eccentricity"
            )
        if "radius" in p:
            raise ValueError(
                "[patch] 'radius' is for shape = 'circle'; valid keys for an ellipse: a, and b "
                "or eccentricity"
            )
        a = v.positive("[patch] a", _need(p, "patch", "a"), "m")
        if ("b" in p) == ("eccentricity" in p):
            raise ValueError(
                "[patch] give exactly one of 'b' and 'eccentricity' for an ellipse; valid: b "
                "[m] > 0, or eccentricity in [0, 1)"
            )
        if "b" in p:
            patch = _in("patch", Ellipse, a, v.positive("[patch] b", p["b"], "m"))
        else:
            e = v.in_range("[patch] eccentricity", p["eccentricity"], 0.0, 1.0, hi_open=True)
            patch = _in("patch", Ellipse.from_eccentricity, a, e)

    pr = dict(data["pressure"])
    law_name = _need(pr, "pressure", "law")
    law = _in(
        "pressure",
        pressure_law_from_name,
        law_name,
        **{k: val for k, val in pr.items() if k != "law"},
    )

    fr = data["friction"]
    friction = _in(
        "friction",
        FrictionTensor,
        fx=_need(fr, "friction", "fx"),
        fy=_need(fr, "friction", "fy"),
        f=fr.get("f", 0.0),
        frame=fr.get("frame", "plane"),
        angle=_angle(fr, "friction", "angle"),
        static=fr.get("static", 1.0),
        speed_law=speed_law_from_table(fr),
    )

    bd = data["body"]
    mass = v.positive("[body] mass", _need(bd, "body", "mass"), "kg")
    if "moment_of_inertia" in bd and "inertia_ratio" in bd:
        raise ValueError(
            "[body] give at most one of 'moment_of_inertia' and 'inertia_ratio'; valid: one of "
            "them, or neither (the uniform plate)"
        )
    inertia = bd.get("moment_of_inertia")
    if "inertia_ratio" in bd:
        inertia = _in(
            "body", Body.from_inertia_ratio, patch, law, mass, bd["inertia_ratio"]
        ).moment_of_inertia
    body = _in("body", Body, patch, law, mass, inertia, bd.get("height", 0.0))

    state = _initial_state(data["initial"])

    so = data.get("solver", {})
    g = v.positive("[solver] g", so.get("g", 9.81), "m/s^2")
    rtol = v.in_range("[solver] rtol", so.get("rtol", 1e-10), 0.0, 1e-3, lo_open=True)
    max_steps = so.get("max_steps", 200_000)
    if (
        isinstance(max_steps, bool)
        or not isinstance(max_steps, int)
        or not 1 <= max_steps <= MAX_STEPS_LIMIT
    ):
        raise ValueError(
            f"[solver] max_steps = {max_steps!r} is invalid; valid range: "
            f"integer >= 1 and <= {MAX_STEPS_LIMIT}"
        )
    name = check_name(data.get("name", ""))
    load: Load | Spring | list | None = load_from_table(data["load"]) if "load" in data else None
    if "spring" in data:  # a spring alone, or with the [load] (MODEL §14)
        spring = spring_from_table(data["spring"])
        load = spring if load is None else [load, spring]
    incline = incline_from_table(data["incline"]) if "incline" in data else None
    t_end = None
    if "t_end" in so:
        t_end = v.in_range("[solver] t_end", so["t_end"], 0.0, 1e9, lo_open=True)
    pusher = outline = None
    if "pusher" in data:
        pusher, outline = pusher_from_table(data["pusher"], body, _footprint_outline)
        t_end = pusher_t_end(pusher, t_end)
    return Case(
        body, friction, state, g, rtol, max_steps, name, load, incline, t_end, pusher, outline
    )


def _footprint_outline(table: dict, where: str):
    """A ``[pusher] outline`` given as an inline footprint table (no pads)."""
    return _footprint(table, where, nested=True)


def _initial_state(ini: dict) -> State:
    """The ``[initial]`` table (names of :data:`INITIAL_KEYS` or their aliases) as a State;
    every message names the key as the file spells it."""
    table: dict = {}
    spelled: dict = {}
    for key, val in ini.items():
        name = INITIAL_ALIASES.get(key, key)
        if name in table:
            raise ValueError(
                f"[initial] gives both {spelled[name]!r} and {key!r}, two names of {name}; "
                f"give one (valid: {name}, or its alias)"
            )
        table[name], spelled[name] = val, key

    def named(name: str) -> str:
        return f"[initial] {spelled.get(name, name)}"

    def angle(name: str) -> float:
        if name in table and f"{name}_deg" in table:
            raise ValueError(
                f"[initial] gives both {spelled[name]} and {spelled[name + '_deg']}; give one "
                f"(valid: {name} in rad or {name}_deg in degrees)"
            )
        if f"{name}_deg" in table:
            return math.radians(v.finite(named(f"{name}_deg"), table[f"{name}_deg"]))
        return v.finite(named(name), table.get(name, 0.0))

    def component(name: str, bound: float, unit: str) -> float:
        return v.symmetric(named(name), v.finite(named(name), table.get(name, 0.0)), bound, unit)

    polar = [n for n in ("v0", "theta0", "theta0_deg") if n in table]
    cartesian = [n for n in ("vx0", "vy0") if n in table]
    if polar and cartesian:
        raise ValueError(
            "[initial] give either speed/theta or vx/vy, not both: "
            f"{spelled[polar[0]]!r} and {spelled[cartesian[0]]!r} given; valid: v0 and "
            "theta0 (or theta0_deg), or vx0 and vy0"
        )
    phi = angle("phi0")
    omega = component("omega0", v.SPIN, "rad/s")
    x0 = component("x0", v.POSITION, "m")
    y0 = component("y0", v.POSITION, "m")
    if polar:
        speed = v.in_range(named("v0"), table.get("v0", 0.0), 0.0, v.SPEED)
        return _in("initial", State.from_speed, speed, omega, angle("theta0"), phi, x0, y0)
    vx = component("vx0", v.SPEED, "m/s")
    vy = component("vy0", v.SPEED, "m/s")
    return _in("initial", State, x0, y0, phi, vx, vy, omega)


def _footprint(p: dict, where: str, nested: bool = False):
    """A footprint from a [patch] table (or one [[patch.pads]] entry, ``nested``)."""
    shape = v.choice(
        f"[{where}] shape",
        _need(p, where, "shape"),
        tuple(_FOOTPRINT_KEYS) if nested else (*_FOOTPRINT_KEYS, "pads"),
    )
    allowed = (
        {"shape", "pads"} if shape == "pads" else ({"shape"} | _FOOTPRINT_KEYS[shape] | _PLACEMENT)
    )
    for key in p:
        if key not in allowed:
            raise ValueError(
                f"[{where}] shape {shape!r} does not take {key!r}; valid keys: "
                + ", ".join(sorted(allowed))
            )
    if shape == "pads":
        pads = _need(p, where, "pads")
        if not isinstance(pads, list) or not pads or not all(isinstance(x, dict) for x in pads):
            raise ValueError(
                f"[{where}] pads = {_short(pads)} is invalid; valid: one or more "
                f"[[{where}.pads]] tables"
            )
        items = [_footprint(x, f"{where}.pads[{i}]", nested=True) for i, x in enumerate(pads)]
        return _in(where, Pads, items)
    place = {
        "centre": _pair(p.get("centre", (0.0, 0.0)), where, "centre"),
        "angle": _angle(p, where, "angle"),
    }
    if shape == "polygon":
        verts = _need(p, where, "vertices")
        if not isinstance(verts, list):
            raise ValueError(
                f"[{where}] vertices = {_short(verts)} is invalid; valid values: "
                "an array of at least 3 pairs [xi, eta] in m"
            )
        pts = [_pair(x, where, f"vertices[{i}]") for i, x in enumerate(verts)]
        return _in(where, Polygon, pts, **place)
    if shape == "rectangle":
        return _in(where, Rectangle, _need(p, where, "length"), _need(p, where, "width"), **place)
    if shape == "annulus":
        return _in(
            where,
            Annulus,
            _need(p, where, "inner_radius"),
            _need(p, where, "outer_radius"),
            **place,
        )
    return _in(where, Disk, _need(p, where, "radius"), **place)


def _pair(value, where: str, key: str) -> tuple[float, float]:
    """[xi, eta] of real numbers [m]."""
    if (
        not isinstance(value, (list, tuple))
        or len(value) != 2
        or not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in value)
    ):
        raise ValueError(
            f"[{where}] {key} = {_short(value)} is invalid; valid values: a pair "
            "[xi, eta] of real numbers in m"
        )
    return (v.finite(f"[{where}] {key}[0]", value[0]), v.finite(f"[{where}] {key}[1]", value[1]))


def check_name(name, key: str = "name") -> str:
    """The ``name`` of a case or sweep: a string of at most :data:`MAX_NAME_CHARS` characters."""
    if not isinstance(name, str):
        raise ValueError(
            f"{key} = {_short(name)} must be a string; valid: a string of at most "
            f"{MAX_NAME_CHARS} characters"
        )
    if len(name) > MAX_NAME_CHARS:
        raise ValueError(
            f"{key} is {len(name)} characters long; valid: a string of at most "
            f"{MAX_NAME_CHARS} characters"
        )
    return name


def _short(value, n: int = 60) -> str:
    """``repr(value)`` cut to about ``n`` characters, for messages."""
    text = repr(value)
    return text if len(text) <= n else text[: n - 1] + "…"


def check_document(data, where: tuple = (), depth: int = 0) -> None:
    """Refuse what no valid case file or sweep spec contains, naming the key: nesting deeper
    than :data:`MAX_DEPTH`, and integers outside the 64-bit range (e.g. ``2**64``)."""
    if depth > MAX_DEPTH:
        raise ValueError(
            f"{_key(where)} is nested {depth} levels deep; valid: at most "
            f"{MAX_DEPTH} levels of tables and arrays"
        )
    if isinstance(data, dict):
        items = ((where + (str(k),), val) for k, val in data.items())
    elif isinstance(data, list):
        items = (
            (where[:-1] + (f"{where[-1] if where else ''}[{i}]",), val)
            for i, val in enumerate(data)
        )
    else:
        if isinstance(data, int) and not isinstance(data, bool) and abs(data) > _INT64:
            raise ValueError(
                f"{_key(where)} = {_short(data, 40)} does not fit a 64-bit "
                f"integer; valid range: [-{_INT64}, {_INT64}] (and the key's own "
                "range)"
            )
        return
    for key, val in items:
        check_document(val, key, depth + 1)


def _key(path: tuple) -> str:
    """``('solver', 'max_steps')`` → ``[solver] max_steps`` (the way a TOML file shows it)."""
    if not path:
        return "the document"
    if len(path) == 1:
        return path[0]
    return f"[{path[0]}] " + ".".join(path[1:])


def read_toml(path, what: str, max_bytes: int = MAX_FILE_BYTES) -> dict:
    """Parse a TOML file; unreadable, oversized or malformed files raise a one-line
    ``ValueError`` naming the file.

    Only regular files are read (a FIFO, a device such as ``/dev/zero`` or a directory is
    refused without reading), and at most ``max_bytes`` bytes (default
    :data:`MAX_FILE_BYTES`): a larger file is refused. The text must be UTF-8. Nesting deeper
    than :data:`MAX_DEPTH` and integers beyond 64 bits are refused naming the key.
    """
    name = str(path)
    raw = read_regular_file(path, what, "TOML", max_bytes)
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ValueError(
            f"{what} {name!r} is not UTF-8 text (byte {raw[exc.start]:#04x} at "
            f"offset {exc.start}); valid: a UTF-8 TOML file"
        ) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{what} {name!r} is not valid TOML: {exc}") from None
    except RecursionError:
        raise ValueError(
            f"{what} {name!r} is nested too deeply; valid: at most {MAX_DEPTH} "
            "levels of tables and arrays"
        ) from None
    try:
        check_document(data)
    except ValueError as exc:
        raise ValueError(f"{what} {name!r}: {exc}") from None
    return data


def load_case(path) -> Case:
    """Read and validate a case file.

    Raises
    ------
    ValueError
        Unreadable or malformed TOML, unknown or missing keys, or invalid values; the message
        names the file, the key, the value and the valid range.
    """
    return read_case(path)[0]


def read_case(path, *, initial_required: bool = True) -> tuple[Case, dict]:
    """Read and validate a case file: the :class:`Case` and the parsed document (which keys
    the file gives, for :func:`refuse_unused`).

    With ``initial_required=False`` the ``[initial]`` table may be left out (the body then
    starts at rest at the origin).
    """
    data = read_toml(path, "case file")
    doc = data
    if not initial_required and isinstance(data, dict) and "initial" not in data:
        data = {**data, "initial": {}}
    try:
        return case_from_dict(data), doc
    except ValueError as exc:
        raise ValueError(f"{path}: {exc}") from None


def refuse_unused(path, data: dict, command: str, unused) -> None:
    """Refuse the tables and keys of a case file that ``command`` cannot honour.

    Parameters
    ----------
    path : str or Path
        The case file (named in the message).
    data : dict
        Its parsed document (:func:`read_case`).
    command : str
        The command, e.g. ``"slidespin fit"``.
    unused : sequence of (table, keys, reason)
        ``keys`` None refuses the whole table; otherwise the keys of the table (for
        ``[initial]`` the names of :data:`INITIAL_KEYS`, whose aliases are refused with them).
        ``reason`` says why the command cannot use it and what can.

    Raises
    ------
    ValueError
        Naming the file, the table or key as the file spells it, and the reason.
    """
    alias_of: dict[str, list[str]] = {}
    for alias, name in INITIAL_ALIASES.items():
        alias_of.setdefault(name, []).append(alias)
    for table, keys, reason in unused:
        given = data.get(table)
        if given is None:
            continue
        if keys is None:
            raise ValueError(
                f"{path}: [{table}] is not used by {command} ({reason}); valid: a case file "
                f"without [{table}]"
            )
        if not isinstance(given, dict):
            continue  # refused by case_from_dict
        for name in keys:
            spellings = [name] + (alias_of.get(name, []) if table == "initial" else [])
            for key in spellings:
                if key in given:
                    raise ValueError(
                        f"{path}: [{table}] {key} = {_short(given[key])} is not used by "
                        f"{command} ({reason}); valid: leave {key} out of [{table}]"
                    )
