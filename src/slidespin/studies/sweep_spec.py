"""The sweep specification: the parameters a spec may fix or vary, their defaults and limits,
:class:`SweepSpec` (the cases, numbered, as parameter columns) and :class:`SweepError`.

A sweep specification (TOML, see ``examples/sweep_*.toml``; read and checked by
:func:`slidespin.studies.sweep_parse.load_spec`) fixes some parameters and varies others on a
grid (``[vary] k = [values]`` or ``{start, stop, num[, log]}``) or by random sampling
(``kind = "random"``: ``{low, high[, log]}`` or a list to pick from, one independent stream
per parameter). The cases are numbered deterministically, whatever the chunking.

Parameters a spec may fix or vary (SI units, angles in radians):

==================================  =============================================================
``a``                               semi-axis along ξ [m] (required)
``b`` | ``e`` | ``aspect``          semi-axis along η [m], eccentricity, or b/a (default: circle)
``law``                             uniform | linear | boussinesq | hertz
``xi_c``, ``eta_c``                 linear-law centroid = mass centre [m]
``fx``                              friction coefficient along the tensor's first axis (required)
``fy`` | ``mu``                     second coefficient, or μ = fy − fx (one required)
``f``                               skew coefficient
``frame``                           plane | body
``angle``                           principal axes of the tensor [rad]
``mass``                            [kg]
``I_star`` | ``moment_of_inertia``  I/(m a²), or I [kg m²] (default: uniform plate)
``g``                               [m/s²]
``v0``, ``theta0`` | ``theta0_deg``  initial speed of G [m/s] and its direction [rad] or [deg]
``vx0``, ``vy0``                    or the initial velocity of G [m/s] (not with v0, theta0)
``omega0``                          initial spin [rad/s]
``phi0`` | ``phi0_deg``, ``x0``,    initial body angle [rad] or [deg] and position [m]
``y0``
``shape``                           patch shape, fixed (default ellipse; footprints below)
==================================  =============================================================

The initial-state names are those of a case file's ``[initial]`` table and of the result
columns (one vocabulary; a case file also accepts the earlier names ``speed``, ``theta``,
``omega``, ... as aliases, :data:`slidespin.studies.case.INITIAL_ALIASES`; a sweep spec does
not, and says which name it means).

Footprints (``shape`` other than ellipse; issue #12) take the keys of the case file's
``[patch]`` table instead of ``a``, ``b``, ``e``, ``aspect``: ``radius`` (disk);
``outer_radius`` and one of ``inner_radius``, ``ring_width``, ``radius_ratio`` (annulus);
``length`` and one of ``width``, ``aspect`` = width/length (rectangle); ``vertices``
(fixed) and ``scale`` (polygon); ``pad_shape``, ``n_pads``, ``pad_spacing`` and
``pad_radius`` or ``pad_length``, ``pad_width`` (pads: equal, unrotated, centred on a
circle about the origin, the first on the η axis, neighbours ``pad_spacing`` apart).
``I_star`` is then I/(m ℓ²) with ℓ the footprint's extent
(:attr:`slidespin.Body.length_unit`).

The top-level key ``compute`` (``"stop"``, ``"statics"`` or ``"loaded"``) adds the load and
tilt keys of :mod:`slidespin.studies.sweep_loads`. The top-level key ``max_steps`` (integer in
[1, 1e9], default :data:`DEFAULT_MAX_STEPS`) is each case's budget of integrator steps (stop
and loaded sweeps): it bounds the work of every case, whatever ``t_end``; a case that runs out
has the status ``max_steps``. ``compute = "statics"`` (a body at rest) integrates nothing and
refuses ``rtol``, ``max_steps`` and the start state other than ``phi0``. The top-level key
``sensitivities`` (a list of the parameters of :func:`slidespin.stop_sensitivities`, with
``compute = "stop"``) adds each case's stop derivatives as the columns
``d_<q>/d_<parameter>`` (q: ``t_stop``, ``x``, ``y``, ``phi``, ``beta_stop``; MODEL §15), one
sensitivity run per case (10–15 plain runs' cost for 6 parameters).

Limits (checked before any work, with the key and the valid range in the message): at most
:data:`MAX_CASES` cases, :data:`MAX_AXIS` values per grid axis or list, :data:`MAX_CHUNK`
cases per chunk.
"""

from __future__ import annotations

import hashlib
import json
import math
from dataclasses import dataclass, field

import numpy as np

from slidespin import _validate as v
from slidespin.contact.pressure import LAW_NAMES
from slidespin.motion._cases import SHAPE_KEYS
from slidespin.studies.sweep_loads import LOAD_PARAMETERS

__all__ = [
    "SweepSpec",
    "SweepError",
    "PARAMETERS",
    "SHAPES",
    "MAX_CASES",
    "MAX_AXIS",
    "MAX_CHUNK",
    "DEFAULT_MAX_STEPS",
]

#: sweep parameters and their defaults (None: required, or derived from another one)
PARAMETERS = {
    "a": None,
    "b": None,
    "e": None,
    "aspect": None,
    "law": "uniform",
    "xi_c": 0.0,
    "eta_c": 0.0,
    "fx": None,
    "fy": None,
    "mu": None,
    "f": 0.0,
    "frame": "plane",
    "angle": 0.0,
    "mass": 1.0,
    "I_star": None,
    "moment_of_inertia": None,
    "g": 9.81,
    "v0": 0.0,
    "theta0": 0.0,
    "theta0_deg": None,
    "vx0": None,
    "vy0": None,
    "omega0": 0.0,
    "phi0": 0.0,
    "phi0_deg": None,
    "x0": 0.0,
    "y0": 0.0,
    # footprints (issue #12): the keys of the TOML [patch] table, see _cases.SHAPE_KEYS
    "shape": "ellipse",
    "radius": None,
    "outer_radius": None,
    "inner_radius": None,
    "ring_width": None,
    "radius_ratio": None,
    "length": None,
    "width": None,
    "vertices": None,
    "scale": 1.0,
    "pad_shape": "disk",
    "n_pads": 2.0,
    "pad_spacing": None,
    "pad_radius": None,
    "pad_length": None,
    "pad_width": None,
    # loads and tilt (issue #13, compute = "statics" | "loaded"): see slidespin.studies.sweep_loads
    **LOAD_PARAMETERS,
}
#: patch shapes of a sweep: the paper's ellipse (keys a, b | e | aspect) and the footprints
SHAPES = ("ellipse", *SHAPE_KEYS)
_ELLIPSE_KEYS = ("a", "b", "e", "aspect")
_GEOMETRY_KEYS = set(_ELLIPSE_KEYS).union(*SHAPE_KEYS.values())
_STRING_PARAMS = {
    "law": LAW_NAMES,
    "frame": ("plane", "body"),
    "shape": SHAPES,
    "pad_shape": ("disk", "rectangle"),
    "load_frame": ("plane", "body"),
}
_FIXED_ONLY = ("shape", "pad_shape", "vertices")
_EXCLUSIVE = (
    ("b", "e", "aspect"),
    ("fy", "mu"),
    ("I_star", "moment_of_inertia"),
    ("inner_radius", "ring_width", "radius_ratio"),
    ("width", "aspect"),
    ("incline_angle", "incline_angle_deg"),
    ("theta0", "theta0_deg"),
    ("phi0", "phi0_deg"),
)
#: the start state's speed and direction, or its velocity components (not both)
_POLAR = ("v0", "theta0", "theta0_deg")
_CARTESIAN = ("vx0", "vy0")
#: the start state, which ``compute = "statics"`` (a body at rest at angle phi0) does not use
_MOTION_KEYS = ("v0", "theta0", "theta0_deg", "vx0", "vy0", "omega0", "x0", "y0")
#: names of a case file's [initial] table that a sweep spec spells otherwise (for messages)
_CASE_FILE_NAMES = {
    "speed": "v0",
    "theta": "theta0",
    "theta_deg": "theta0_deg",
    "omega": "omega0",
    "phi": "phi0",
    "phi_deg": "phi0_deg",
    "x": "x0",
    "y": "y0",
    "vx": "vx0",
    "vy": "vy0",
}
_TOP_KEYS = {
    "name",
    "description",
    "kind",
    "chunk_size",
    "rtol",
    "fixed",
    "vary",
    "random",
    "compute",
    "max_steps",
    "sensitivities",
}
#: the budget of integrator steps of each case unless ``max_steps`` says otherwise (that of
#: :func:`slidespin.simulate`)
DEFAULT_MAX_STEPS = 200_000
#: most cases in one sweep (they are all validated before work starts: about 1 µs each)
MAX_CASES = 10_000_000
#: most values on one grid axis (``num`` or a list) or in one list to pick from
MAX_AXIS = 1_000_000
#: largest ``chunk_size`` (one chunk is held in memory and written as one file)
MAX_CHUNK = 1_000_000


class SweepError(ValueError):
    """A sweep cannot start or resume (bad spec, foreign directory, missing extra)."""


@dataclass(frozen=True)
class SweepSpec:
    """A validated sweep specification.

    Attributes
    ----------
    data : dict
        The specification as parsed from TOML (canonical form; hashed for resuming).
    n_cases : int
        Number of cases.
    chunk_size : int
        Cases per chunk (one file, one task).
    """

    data: dict = field(repr=False)
    n_cases: int
    chunk_size: int

    @property
    def name(self) -> str:
        """The spec's ``name`` (empty if it has none)."""
        return self.data.get("name", "")

    @property
    def n_chunks(self) -> int:
        """Number of chunks (Parquet files, tasks) the cases are split into."""
        return -(-self.n_cases // self.chunk_size)

    @property
    def digest(self) -> str:
        """SHA-256 of the canonical specification."""
        text = json.dumps(self.data, sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(text.encode()).hexdigest()

    @property
    def shape(self) -> str:
        """The patch shape (``[fixed] shape``; ``"ellipse"`` by default)."""
        return str(self.data.get("fixed", {}).get("shape", "ellipse"))

    @property
    def max_steps(self) -> int:
        """Each case's budget of integrator steps (``max_steps``; default
        :data:`DEFAULT_MAX_STEPS`)."""
        return int(self.data.get("max_steps", DEFAULT_MAX_STEPS))

    @property
    def sensitivities(self) -> tuple[str, ...]:
        """The parameters whose stop derivatives each case gets as columns
        ``d_<q>/d_<parameter>`` (the top-level key ``sensitivities``, compute = "stop"; none
        by default)."""
        return tuple(self.data.get("sensitivities", ()))

    @property
    def mode(self) -> str:
        """What is computed per case: ``"stop"`` (default), ``"statics"`` or ``"loaded"``."""
        return str(self.data.get("compute", "stop"))

    def varied(self) -> list[str]:
        """Names of the varied parameters, in spec order."""
        return list(self.data.get("vary", {}))

    def parameters(self, start: int = 0, stop: int | None = None) -> dict:
        """Parameter columns (name → array) of the cases ``start:stop``."""
        stop = self.n_cases if stop is None else min(stop, self.n_cases)
        idx = np.arange(start, stop)
        fixed = self.data.get("fixed", {})
        vary = self.data.get("vary", {})
        cols: dict = {}
        if self.data.get("kind", "grid") == "grid":
            axes = [_grid_values(k, spec) for k, spec in vary.items()]
            shape = [len(ax) for ax in axes]
            if axes:
                sub = np.unravel_index(idx, shape)
                for (k, ax), s in zip(zip(vary, axes), sub):
                    cols[k] = np.asarray(ax)[s]
        else:
            rnd = self.data["random"]
            # one independent stream per parameter: case i gets the i-th draw of its stream,
            # whatever the chunking and the order chunks are computed in. A uniform draw takes
            # exactly one 64-bit word, so the stream is advanced to ``start``; picks from a
            # list may take more, so their stream is drawn from its beginning (cheap).
            for j, (k, spec) in enumerate(vary.items()):
                rng = np.random.default_rng([int(rnd.get("seed", 0)), j])
                if isinstance(spec, list):
                    cols[k] = _random_values(k, spec, rng, stop)[start:stop]
                else:
                    rng.bit_generator.advance(start)  # type: ignore[attr-defined]  # PCG64
                    cols[k] = _random_values(k, spec, rng, stop - start)
        for k, val in fixed.items():
            if k in ("vertices",):  # not a column: read from the spec by the footprint builder
                continue
            cols[k] = np.full(idx.size, val, dtype=object if isinstance(val, str) else float)
        cols["case_id"] = idx
        return cols


def _flag(where, spec):
    log = spec.get("log", False)
    if not isinstance(log, bool):
        raise SweepError(f"{where}.log = {log!r} is invalid; valid values: true, false")
    return log


def _value_list(where, name, spec):
    if not spec:
        raise SweepError(f"{where} is an empty list; valid: 1 to {MAX_AXIS} values")
    if len(spec) > MAX_AXIS:
        raise SweepError(f"{where} has {len(spec)} values; valid: 1 to {MAX_AXIS} values")
    vals = [_check_value(f"{where}[{i}]", x, name) for i, x in enumerate(spec)]
    if len({type(x) for x in vals}) > 1:
        raise SweepError(f"{where} mixes strings and numbers; valid: values of one kind")
    return vals


def _grid_values(name, spec):
    where = f"[vary] {name}"
    if isinstance(spec, list):
        return _value_list(where, name, spec)
    if isinstance(spec, dict):
        _only(spec, {"start", "stop", "num", "log"}, where)
        num = spec.get("num")
        if isinstance(num, bool) or not isinstance(num, int) or not 1 <= num <= MAX_AXIS:
            raise SweepError(
                f"{where}.num = {num!r} is invalid; valid range: integer >= 1 and <= {MAX_AXIS}"
            )
        lo = v.finite(f"{where}.start", spec.get("start"))
        hi = v.finite(f"{where}.stop", spec.get("stop"))
        if _flag(where, spec):
            if lo <= 0 or hi <= 0:
                raise SweepError(
                    f"{where}: log spacing needs start > 0 and stop > 0, got "
                    f"start = {lo!r}, stop = {hi!r}; valid range: start > 0, stop > 0"
                )
            vals = np.geomspace(lo, hi, num)
        else:
            with np.errstate(over="ignore", invalid="ignore"):
                vals = np.linspace(lo, hi, num)
            if not np.isfinite(vals).all():
                raise SweepError(
                    f"{where}: stop - start = {hi!r} - {lo!r} overflows; valid: a finite difference"
                )
        return [_check_value(name, float(x)) for x in vals]
    raise SweepError(
        f"{where} = {_short(spec)} is invalid; valid values: a list of values or "
        "{start, stop, num[, log]}"
    )


def _random_values(name, spec, rng, n):
    where = f"[vary] {name}"
    if isinstance(spec, list):
        vals = _value_list(where, name, spec)
        pick = rng.integers(0, len(vals), size=n)
        arr = np.empty(n, dtype=object if isinstance(vals[0], str) else float)
        arr[:] = [vals[i] for i in pick]
        return arr
    if not isinstance(spec, dict):
        raise SweepError(
            f"{where} = {_short(spec)} is invalid; valid values: a list of values to pick "
            "from or {low, high[, log]}"
        )
    _only(spec, {"low", "high", "log"}, where)
    lo = v.finite(f"{where}.low", spec.get("low"))
    hi = v.finite(f"{where}.high", spec.get("high"))
    if not lo <= hi:
        raise SweepError(f"{where}: low = {lo!r} > high = {hi!r}; valid: low <= high")
    if _flag(where, spec):
        if lo <= 0:
            raise SweepError(
                f"{where}: log sampling needs low > 0, got low = {lo!r}; valid range: low > 0"
            )
        return np.exp(rng.uniform(math.log(lo), math.log(hi), size=n))
    if not math.isfinite(hi - lo):
        raise SweepError(
            f"{where}: high - low = {hi!r} - {lo!r} overflows; valid: a finite difference"
        )
    return rng.uniform(lo, hi, size=n)


def _only(table, allowed, where):
    if not isinstance(table, dict):
        raise SweepError(f"{where} must be a table, got {_short(table)}; valid: a TOML table")
    for k in table:
        if k not in allowed:
            hint = ""
            if k in _CASE_FILE_NAMES and _CASE_FILE_NAMES[k] in allowed:
                hint = f" (a case file's {k!r} is {_CASE_FILE_NAMES[k]!r} here)"
            raise SweepError(
                f"unknown key {k!r} in {where}{hint}; valid keys: {', '.join(sorted(allowed))}"
            )


def _short(value, n: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= n else text[: n - 1] + "…"


def _check_value(name, value, param=None):
    """``value`` checked as a value of parameter ``param`` (default ``name``), named ``name``."""
    param = name if param is None else param
    if param == "vertices":
        if (
            not isinstance(value, list)
            or len(value) < 3
            or not all(isinstance(p, list) and len(p) == 2 for p in value)
        ):
            raise SweepError(
                f"{name} = {value!r} is invalid; valid values: a list of at least "
                "3 pairs [xi, eta] in m"
            )
        for i, p in enumerate(value):
            for j, x in enumerate(p):
                v.finite(f"{name}[{i}][{j}]", x)
        return value
    if param in _STRING_PARAMS:
        return v.choice(name, value, _STRING_PARAMS[param])
    return v.finite(name, value)
