"""Cases described in TOML files (``slidespin simulate CASE.toml``).

A case file has the tables ``[patch]``, ``[pressure]``, ``[friction]``, ``[body]``,
``[initial]`` and optionally ``[solver]`` (see ``examples/*.toml``). Every key is checked:
an unknown key (a typo) or a missing required key is an error naming the table and the key,
never silently ignored. Angles are in radians unless the key ends in ``_deg``.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass

from . import _validate as v
from .body import Body, State
from .friction import FrictionTensor
from .geometry import Circle, Ellipse
from .pressure import pressure_law_from_name

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

__all__ = ["Case", "load_case", "case_from_dict", "read_toml"]

_TABLES = {
    "patch": {"shape", "a", "b", "eccentricity", "radius"},
    "pressure": {"law", "xi_c", "eta_c"},
    "friction": {"fx", "fy", "f", "frame", "angle", "angle_deg"},
    "body": {"mass", "moment_of_inertia", "inertia_ratio"},
    "initial": {
        "x", "y", "phi", "phi_deg", "vx", "vy", "omega", "speed", "theta", "theta_deg",
    },
    "solver": {"g", "rtol", "max_steps"},
}
_TOP = {"name", "description"}


@dataclass(frozen=True, slots=True)
class Case:
    """A complete simulation case: body, friction, initial state and solver settings."""

    body: Body
    friction: FrictionTensor
    initial_state: State
    g: float = 9.81
    rtol: float = 1e-10
    max_steps: int = 200_000
    name: str = ""


def _angle(table: dict, where: str, key: str, default: float = 0.0) -> float:
    if key in table and f"{key}_deg" in table:
        raise ValueError(f"[{where}] gives both {key} and {key}_deg; give one")
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
        raise ValueError(f"[{where}] is missing the required key {key!r}")
    return table[key]


def case_from_dict(data: dict) -> Case:
    """Build and validate a :class:`Case` from a parsed TOML document."""
    if not isinstance(data, dict):
        raise ValueError("a case must be a TOML table")
    for key in data:
        if key not in _TABLES and key not in _TOP:
            raise ValueError(
                f"unknown table or key {key!r} in the case file; valid: "
                + ", ".join(sorted(set(_TABLES) | _TOP))
            )
    for name in ("patch", "pressure", "friction", "body", "initial"):
        if name not in data:
            raise ValueError(f"the case file is missing the table [{name}]")
    for name, allowed in _TABLES.items():
        table = data.get(name, {})
        if not isinstance(table, dict):
            raise ValueError(f"[{name}] must be a table, got {table!r}")
        for key in table:
            if key not in allowed:
                raise ValueError(
                    f"unknown key {key!r} in [{name}]; valid keys: {', '.join(sorted(allowed))}"
                )

    p = data["patch"]
    shape = v.choice("[patch] shape", p.get("shape", "ellipse"), ("ellipse", "circle"))
    if shape == "circle":
        extra = sorted(set(p) - {"shape", "radius"})
        if extra:
            raise ValueError(f"[patch] shape 'circle' takes only 'radius', not {extra[0]!r}")
        patch = Circle(v.positive("[patch] radius", _need(p, "patch", "radius"), "m"))
    else:
        if "radius" in p:
            raise ValueError("[patch] 'radius' is for shape = 'circle'; an ellipse takes a and b or eccentricity")
        a = v.positive("[patch] a", _need(p, "patch", "a"), "m")
        if ("b" in p) == ("eccentricity" in p):
            raise ValueError("[patch] give exactly one of 'b' and 'eccentricity' for an ellipse")
        if "b" in p:
            patch = Ellipse(a, v.positive("[patch] b", p["b"], "m"))
        else:
            e = v.in_range("[patch] eccentricity", p["eccentricity"], 0.0, 1.0, hi_open=True)
            patch = Ellipse.from_eccentricity(a, e)

    pr = dict(data["pressure"])
    law_name = _need(pr, "pressure", "law")
    law = _in("pressure", pressure_law_from_name, law_name,
              **{k: val for k, val in pr.items() if k != "law"})

    fr = data["friction"]
    friction = _in(
        "friction", FrictionTensor,
        fx=_need(fr, "friction", "fx"),
        fy=_need(fr, "friction", "fy"),
        f=fr.get("f", 0.0),
        frame=fr.get("frame", "plane"),
        angle=_angle(fr, "friction", "angle"),
    )

    bd = data["body"]
    mass = v.positive("[body] mass", _need(bd, "body", "mass"), "kg")
    if "moment_of_inertia" in bd and "inertia_ratio" in bd:
        raise ValueError("[body] give at most one of 'moment_of_inertia' and 'inertia_ratio'")
    if "inertia_ratio" in bd:
        body = Body.from_inertia_ratio(patch, law, mass, bd["inertia_ratio"])
    else:
        body = Body(patch, law, mass, bd.get("moment_of_inertia"))

    ini = data["initial"]
    has_speed = "speed" in ini or "theta" in ini or "theta_deg" in ini
    has_v = "vx" in ini or "vy" in ini
    if has_speed and has_v:
        raise ValueError("[initial] give either speed/theta or vx/vy, not both")
    phi = _angle(ini, "initial", "phi")
    omega = v.finite("[initial] omega", ini.get("omega", 0.0))
    x0 = v.finite("[initial] x", ini.get("x", 0.0))
    y0 = v.finite("[initial] y", ini.get("y", 0.0))
    if has_speed:
        speed = v.in_range("[initial] speed", ini.get("speed", 0.0), 0.0, math.inf,
                           hi_open=True)
        state = State.from_speed(speed, omega, _angle(ini, "initial", "theta"), phi, x0, y0)
    else:
        state = State(x0, y0, phi, ini.get("vx", 0.0), ini.get("vy", 0.0), omega)

    so = data.get("solver", {})
    g = v.positive("[solver] g", so.get("g", 9.81), "m/s^2")
    rtol = v.in_range("[solver] rtol", so.get("rtol", 1e-10), 0.0, 1e-3, lo_open=True)
    max_steps = so.get("max_steps", 200_000)
    if isinstance(max_steps, bool) or not isinstance(max_steps, int) or max_steps < 1:
        raise ValueError(f"[solver] max_steps = {max_steps!r} is invalid; valid range: integer >= 1")
    name = data.get("name", "")
    if not isinstance(name, str):
        raise ValueError(f"name = {name!r} must be a string")
    return Case(body, friction, state, g, rtol, max_steps, name)


def read_toml(path, what: str) -> dict:
    """Parse a TOML file; unreadable or malformed files raise a one-line ``ValueError``."""
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise ValueError(f"{what} {str(path)!r} does not exist") from None
    except IsADirectoryError:
        raise ValueError(f"{what} {str(path)!r} is a directory, not a TOML file") from None
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{what} {str(path)!r} is not valid TOML: {exc}") from None
    except OSError as exc:
        raise ValueError(f"{what} {str(path)!r} cannot be read: {exc.strerror}") from None


def load_case(path) -> Case:
    """Read and validate a case file.

    Raises
    ------
    ValueError
        Unreadable or malformed TOML, unknown or missing keys, or invalid values; the message
        names the file, the key, the value and the valid range.
    """
    data = read_toml(path, "case file")
    try:
        return case_from_dict(data)
    except ValueError as exc:
        raise ValueError(f"{path}: {exc}") from None
