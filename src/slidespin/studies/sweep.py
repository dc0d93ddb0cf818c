"""Parameter sweeps: many cases, chunked, crash-safe and resumable, locally or on Dask.

A sweep specification (TOML, see ``examples/sweep_*.toml``) fixes some parameters and varies
others on a grid or by random sampling. The cases are numbered deterministically and cut into
chunks; each finished chunk is written to ``DIR/chunks/chunk-NNNNNN.parquet`` under a temporary
name and renamed into place, and ``DIR/manifest.json`` records the spec, its hash, the package
version, the chunks done and how many cases ended with each status and each ending
(:mod:`slidespin.motion.outcomes`). A sweep killed at any moment loses only its unfinished chunks;
``resume=True`` checks every chunk file (readable Parquet, columns, row count, case numbers),
recomputes damaged ones and computes the missing ones. ``DIR/.lock`` (pid and host) keeps a
second sweep off a directory in use; a lock whose process is gone is taken over. A write that
fails (disk full, permission denied) raises :class:`SweepError` naming the file and leaves a
directory that ``resume=True`` completes.

:func:`read_sweep` leaves out the cases whose status is unconverged (``max_steps``,
``step_too_small``, ``non_finite``) unless ``include_unconverged=True``.

Limits (checked before any work, with the key and the valid range in the message): at most
:data:`MAX_CASES` cases, :data:`MAX_AXIS` values per grid axis or list, :data:`MAX_CHUNK`
cases per chunk; specs are read like case files (:func:`slidespin.studies.case.read_toml`: a regular
UTF-8 file of at most 1 MB, nesting and integers bounded).

Executors: by default all local cores (the compiled batch engine, :func:`~slidespin.motion.batch.simulate_cases`);
a ``dask.distributed.Client`` (or any ``concurrent.futures.Executor``) runs consecutive chunks
of at least 1000 cases per task; the results are identical to the local ones, bit for bit.

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
``v0``, ``theta0``                  initial speed of G [m/s] and its direction [rad]
``omega0``                          initial spin [rad/s]
``phi0``, ``x0``, ``y0``            initial body angle [rad] and position [m]
``shape``                           patch shape, fixed (default ellipse; footprints below)
==================================  =============================================================

Footprints (``shape`` other than ellipse; issue #12) take the keys of the case file's
``[patch]`` table instead of ``a``, ``b``, ``e``, ``aspect``: ``radius`` (disk);
``outer_radius`` and one of ``inner_radius``, ``ring_width``, ``radius_ratio`` (annulus);
``length`` and one of ``width``, ``aspect`` = width/length (rectangle); ``vertices``
(fixed) and ``scale`` (polygon); ``pad_shape``, ``n_pads``, ``pad_spacing`` and
``pad_radius`` or ``pad_length``, ``pad_width`` (pads: equal, unrotated, centred on a
circle about the origin, the first on the η axis, neighbours ``pad_spacing`` apart).
``I_star`` is then I/(m ℓ²) with ℓ the footprint's extent
(:attr:`slidespin.Body.length_unit`). Each distinct patch is built once per chunk and the
cases go to :func:`slidespin.motion.batch.simulate_bodies` together: every case equals a single
:func:`slidespin.motion.simulate` call on the same body, to the last bit.

The top-level key ``compute`` chooses the result of each case: ``"stop"`` (default; the
compiled batch engine), ``"statics"`` (critical tilt, load factor, sticks or slides) or
``"loaded"`` (a run with applied loads and tilt to ``t_end``); the last two add the load and
tilt keys ``load_fx``, ``load_fy``, ``load_torque``, ``load_frame``, ``incline_angle`` (or
``incline_angle_deg``), ``incline_downhill`` and ``t_end`` (``slidespin.studies.sweep_loads``).
:func:`to_pandas` reads a sweep as a pandas table.
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
import os
import sys
import time
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from slidespin import _validate as v
from slidespin.contact.pressure import LAW_NAMES
from slidespin.motion._cases import (
    SHAPE_KEYS,
    footprint_geometry,
    footprint_patch,
    validated_columns,
)
from slidespin.motion.batch import simulate_bodies, simulate_cases
from slidespin.motion.outcomes import LOADED_ENDINGS, LOADED_STATUSES, LOADED_UNCONVERGED
from slidespin.studies.case import check_document, check_name
from slidespin.studies.sweep_loads import (
    LOAD_COLUMNS,
    LOAD_PARAMETERS,
    LOADED_COLUMNS,
    MODES,
    STATICS_COLUMNS,
    STATICS_ENDINGS,
    STATICS_STATUSES,
    CaseError,
    compute_loaded,
    compute_statics,
    load_columns,
)

__all__ = [
    "SweepSpec",
    "load_spec",
    "sweep",
    "read_sweep",
    "split_unconverged",
    "count_outcomes",
    "compute_chunk",
    "compute_chunks",
    "connect_dask",
    "PARAMETERS",
    "SweepError",
    "SweepResult",
    "MAX_CASES",
    "MAX_AXIS",
    "MAX_CHUNK",
    "SHAPES",
    "chunk_columns",
    "to_pandas",
    "MIN_TASK_CASES",
    "CHUNK_COLUMNS",
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
    "omega0": 0.0,
    "phi0": 0.0,
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
)
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
}
RESULT_COLUMNS = (
    "t_stop",
    "beta_stop",
    "theta_stop",
    "phi_stop",
    "x_stop",
    "y_stop",
    "path_length",
    "ending",
    "status",
    "saddle_energy",
    "n_steps",
)
MANIFEST = "manifest.json"
#: smallest number of cases per task sent to an executor (Dask or concurrent.futures)
MIN_TASK_CASES = 1000
#: most cases in one sweep (they are all validated before work starts: about 1 µs each)
MAX_CASES = 10_000_000
#: most values on one grid axis (``num`` or a list) or in one list to pick from
MAX_AXIS = 1_000_000
#: largest ``chunk_size`` (one chunk is held in memory and written as one file)
MAX_CHUNK = 1_000_000


class SweepError(ValueError):
    """A sweep cannot start or resume (bad spec, foreign directory, missing extra)."""


# --------------------------------------------------------------------------- specification
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
                    f"start = {lo!r}, stop = {hi!r}"
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
    raise SweepError(f"{where} = {spec!r}: give a list of values or {{start, stop, num[, log]}}")


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
            f"{where} = {spec!r}: give a list of values to pick from or {{low, high[, log]}}"
        )
    _only(spec, {"low", "high", "log"}, where)
    lo = v.finite(f"{where}.low", spec.get("low"))
    hi = v.finite(f"{where}.high", spec.get("high"))
    if not lo <= hi:
        raise SweepError(f"{where}: low = {lo!r} > high = {hi!r}; valid: low <= high")
    if _flag(where, spec):
        if lo <= 0:
            raise SweepError(f"{where}: log sampling needs low > 0, got low = {lo!r}")
        return np.exp(rng.uniform(math.log(lo), math.log(hi), size=n))
    if not math.isfinite(hi - lo):
        raise SweepError(
            f"{where}: high - low = {hi!r} - {lo!r} overflows; valid: a finite difference"
        )
    return rng.uniform(lo, hi, size=n)


def _only(table, allowed, where):
    if not isinstance(table, dict):
        raise SweepError(f"{where} must be a table, got {table!r}")
    for k in table:
        if k not in allowed:
            raise SweepError(
                f"unknown key {k!r} in {where}; valid keys: {', '.join(sorted(allowed))}"
            )


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


def _validate_spec(data: dict) -> SweepSpec:
    _only(data, _TOP_KEYS, "the sweep spec")
    check_document(data)
    kind = v.choice("kind", data.get("kind", "grid"), ("grid", "random"))
    fixed = data.get("fixed", {})
    vary = data.get("vary", {})
    _only(fixed, set(PARAMETERS), "[fixed]")
    _only(vary, set(PARAMETERS), "[vary]")
    both = sorted(set(fixed) & set(vary))
    if both:
        raise SweepError(f"parameter {both[0]!r} is both fixed and varied")
    given = set(fixed) | set(vary)
    mode = v.choice("compute", data.get("compute", "stop"), MODES)
    for k in _FIXED_ONLY:
        if k in vary:
            raise SweepError(f"{k!r} cannot be varied; fix it in [fixed] (one {k} per sweep)")
    shape = _check_value("[fixed] shape", fixed.get("shape", "ellipse"), "shape")
    allowed = set(_ELLIPSE_KEYS) if shape == "ellipse" else set(SHAPE_KEYS[shape])
    for k in sorted(given & _GEOMETRY_KEYS - allowed):
        raise SweepError(
            f"shape = {shape!r} does not take {k!r}; valid patch keys: {', '.join(sorted(allowed))}"
        )
    if shape == "pads":
        pad_shape = _check_value("[fixed] pad_shape", fixed.get("pad_shape", "disk"), "pad_shape")
        own = {"disk": {"pad_radius"}, "rectangle": {"pad_length", "pad_width"}}
        for k in sorted(given & (own["disk"] | own["rectangle"]) - own[pad_shape]):
            raise SweepError(
                f"pad_shape = {pad_shape!r} does not take {k!r}; valid size keys: "
                f"{', '.join(sorted(own[pad_shape]))}"
            )
    if mode == "stop":
        for k in sorted(given & set(LOAD_PARAMETERS)):
            raise SweepError(
                f"{k!r} is a load, tilt or time bound: it needs compute = "
                "'statics' or 'loaded' (the default 'stop' coasts on a level plane)"
            )
    elif mode == "statics" and "t_end" in given:
        raise SweepError("'t_end' is for compute = 'loaded'; compute = 'statics' has no time")
    for group in _EXCLUSIVE:
        if len(given & set(group)) > 1:
            raise SweepError(f"give at most one of {', '.join(group)}")
    for req in ("a",) if shape == "ellipse" else ():
        if req not in given:
            raise SweepError(f"the sweep spec must fix or vary {req!r}")
    for req in ("fx",):
        if req not in given:
            raise SweepError(f"the sweep spec must fix or vary {req!r}")
    if not given & {"fy", "mu"}:
        raise SweepError("the sweep spec must fix or vary 'fy' or 'mu'")
    for k, val in fixed.items():
        _check_value(f"[fixed] {k}", val, k)
    check_name(data.get("name", ""))
    chunk = data.get("chunk_size", 1000)
    if isinstance(chunk, bool) or not isinstance(chunk, int) or not 1 <= chunk <= MAX_CHUNK:
        raise SweepError(
            f"chunk_size = {chunk!r} is invalid; valid range: integer >= 1 and <= {MAX_CHUNK}"
        )
    if "rtol" in data:
        v.in_range("rtol", data["rtol"], 0.0, 1e-3, lo_open=True)
    if kind == "grid":
        if "random" in data:
            raise SweepError("[random] is only for kind = 'random'")
        sizes = [len(_grid_values(k, spec)) for k, spec in vary.items()]
        n = math.prod(sizes)
        if n > MAX_CASES:
            raise SweepError(
                f"the grid [vary] has {' x '.join(map(str, sizes))} = {n} cases; "
                f"valid: at most {MAX_CASES} cases in one sweep"
            )
    else:
        rnd = data.get("random")
        if rnd is None:
            raise SweepError("kind = 'random' needs a [random] table with 'samples'")
        _only(rnd, {"samples", "seed"}, "[random]")
        n = rnd.get("samples")
        if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= MAX_CASES:
            raise SweepError(
                f"[random] samples = {n!r} is invalid; valid range: integer >= 1 and <= {MAX_CASES}"
            )
        seed = rnd.get("seed", 0)
        if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed < 2**63:
            raise SweepError(
                f"[random] seed = {seed!r} is invalid; valid range: integer in [0, 2^63 - 1]"
            )
        for k, spec in vary.items():
            _random_values(k, spec, np.random.default_rng(0), 1)
    canonical = copy.deepcopy(data)
    canonical["kind"] = kind
    canonical["chunk_size"] = chunk
    spec = SweepSpec(canonical, int(n), int(chunk))
    # validate every case's physics up front (cheap: no integration), so that a bad value
    # fails before any work starts, naming the parameter
    for start in range(0, spec.n_cases, 200_000):
        cols = spec.parameters(start, start + 200_000)
        if spec.shape == "ellipse" and spec.mode == "stop":
            _case_fields(cols)
        else:  # builds each distinct body once (a footprint checks itself on construction)
            _case_inputs(spec, cols)
    return spec


def load_spec(spec) -> SweepSpec:
    """A :class:`SweepSpec` from a path to a TOML file, a dict, or a spec (returned as is)."""
    if isinstance(spec, SweepSpec):
        return spec
    if isinstance(spec, dict):
        try:
            return _validate_spec(spec)
        except SweepError:
            raise
        except ValueError as exc:
            raise SweepError(str(exc)) from None
    from slidespin.studies.case import read_toml

    try:
        data = read_toml(spec, "sweep spec")
    except ValueError as exc:
        raise SweepError(str(exc)) from None
    try:
        return _validate_spec(data)
    except ValueError as exc:
        raise SweepError(f"{spec}: {exc}") from None


# --------------------------------------------------------------------------- computing
def _case_fields(cols: dict) -> dict:
    """Map sweep parameters to :func:`~slidespin.motion.batch.simulate_cases` fields (validated there)."""
    n = cols["case_id"].size

    def get(k):
        if k in cols:
            return cols[k]
        return np.full(n, PARAMETERS[k], dtype=object if isinstance(PARAMETERS[k], str) else float)

    a = get("a").astype(float)
    if "b" in cols:
        b = cols["b"].astype(float)
    elif "e" in cols:
        e = cols["e"].astype(float)
        bad = ~((e >= 0) & (e < 1))
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise SweepError(f"e = {float(e[i])!r} (case {i}) is invalid; valid range: [0, 1)")
        b = a * np.sqrt(1.0 - e * e)
    elif "aspect" in cols:
        b = a * cols["aspect"].astype(float)
    else:
        b = a
    fx = get("fx").astype(float)
    fy = cols["fy"].astype(float) if "fy" in cols else fx + cols["mu"].astype(float)
    mass = get("mass").astype(float)
    if "I_star" in cols:
        inertia = cols["I_star"].astype(float) * mass * a * a
    elif "moment_of_inertia" in cols:
        inertia = cols["moment_of_inertia"].astype(float)
    else:
        inertia = mass * (a * a + b * b) / 4.0
    v0 = get("v0").astype(float)
    if (v0 < 0).any():
        i = int(np.flatnonzero(v0 < 0)[0])
        raise SweepError(f"v0 = {float(v0[i])!r} (case {i}) is invalid; valid range: >= 0")
    th = get("theta0").astype(float)
    fields = dict(
        a=a,
        b=b,
        law=get("law"),
        xi_c=get("xi_c").astype(float),
        eta_c=get("eta_c").astype(float),
        fx=fx,
        fy=fy,
        f=get("f").astype(float),
        frame=get("frame"),
        angle=get("angle").astype(float),
        mass=mass,
        moment_of_inertia=inertia,
        g=get("g").astype(float),
        x=get("x0").astype(float),
        y=get("y0").astype(float),
        phi=get("phi0").astype(float),
        vx=v0 * np.cos(th),
        vy=v0 * np.sin(th),
        omega=get("omega0").astype(float),
    )
    try:
        validated_columns(fields)
    except ValueError as exc:
        raise SweepError(str(exc)) from None
    return fields


@dataclass(frozen=True)
class _Inputs:
    """The validated inputs of a block of cases, as objects for the per-case engines."""

    table: dict  # input columns of the chunk file (case_id first)
    bodies: list
    frictions: list
    states: np.ndarray  # (N, 6): x, y, phi, vx, vy, omega
    g: np.ndarray
    loads: dict | None  # sweep_loads.load_columns (statics and loaded sweeps)


def _col(cols: dict, k: str) -> np.ndarray:
    """Column ``k`` of the cases, or its default from :data:`PARAMETERS`."""
    if k in cols:
        return cols[k]
    d = PARAMETERS[k]
    return np.full(cols["case_id"].size, d, dtype=object if isinstance(d, str) else float)


def _case_inputs(spec: SweepSpec, cols: dict) -> _Inputs:
    """Bodies, tensors, states and the input columns of the cases ``cols`` (any shape, any
    mode): one Body per distinct patch, pressure, mass and inertia, one tensor per distinct
    tensor, so that the batch engine shares their compiled arrays."""
    try:
        return _build_inputs(spec, cols)
    except SweepError:
        raise
    except ValueError as exc:
        raise SweepError(str(exc)) from None


def _build_inputs(spec: SweepSpec, cols: dict) -> _Inputs:
    from slidespin.contact.body import Body
    from slidespin.contact.ellipse import Ellipse
    from slidespin.contact.friction import FrictionTensor
    from slidespin.contact.pressure import pressure_law_from_name

    n = cols["case_id"].size
    shape = spec.shape
    if shape == "ellipse":
        fields = _case_fields(cols)
        table = _input_table(cols, fields)
        geo_cols = {"a": fields["a"], "b": fields["b"]}
        inertia = fields["moment_of_inertia"]
        i_star = None
    else:
        geo_cols = footprint_geometry(shape, cols, n)
        table = {"case_id": cols["case_id"].astype(np.int64), "shape": np.full(n, shape)}
        table.update(geo_cols)
        if shape == "pads":
            table["pad_shape"] = np.full(n, spec.data["fixed"].get("pad_shape", "disk"))
        inertia = cols["moment_of_inertia"].astype(float) if "moment_of_inertia" in cols else None
        i_star = cols["I_star"].astype(float) if "I_star" in cols else None
    vertices = spec.data.get("fixed", {}).get("vertices")
    pad_shape = spec.data.get("fixed", {}).get("pad_shape", "disk")
    law, xi_c, eta_c = (
        _col(cols, "law"),
        _col(cols, "xi_c").astype(float),
        _col(cols, "eta_c").astype(float),
    )
    mass = _col(cols, "mass").astype(float)
    fx = _col(cols, "fx").astype(float)
    fy = cols["fy"].astype(float) if "fy" in cols else fx + cols["mu"].astype(float)
    names = list(geo_cols)
    geo = np.column_stack([np.asarray(geo_cols[k], dtype=float) for k in names])
    bodies, frictions = [], []
    body_cache: dict = {}
    fr_cache: dict = {}
    f, frame, angle = (
        _col(cols, "f").astype(float),
        _col(cols, "frame"),
        _col(cols, "angle").astype(float),
    )
    for i in range(n):
        key = (
            tuple(geo[i]),
            str(law[i]),
            xi_c[i],
            eta_c[i],
            mass[i],
            None if inertia is None else inertia[i],
            None if i_star is None else i_star[i],
        )
        body = body_cache.get(key)
        if body is None:
            row = dict(zip(names, geo[i].tolist()))
            try:
                patch = (
                    Ellipse(row["a"], row["b"])
                    if shape == "ellipse"
                    else footprint_patch(shape, row, vertices, pad_shape)
                )
                pl = pressure_law_from_name(
                    str(law[i]),
                    **(
                        {"xi_c": float(xi_c[i]), "eta_c": float(eta_c[i])}
                        if str(law[i]).lower() == "linear"
                        else {}
                    ),
                )
                if i_star is not None:
                    body = Body.from_inertia_ratio(patch, pl, float(mass[i]), float(i_star[i]))
                else:
                    body = Body(
                        patch, pl, float(mass[i]), None if inertia is None else float(inertia[i])
                    )
            except ValueError as exc:
                what = ", ".join(
                    [f"{k} = {x!r}" for k, x in row.items()] + [f"law = {str(law[i])!r}"]
                )
                raise SweepError(
                    f"case {int(cols['case_id'][i])} ({shape}: {what}): {exc}"
                ) from None
            body_cache[key] = body
        bodies.append(body)
        fkey = (fx[i], fy[i], f[i], str(frame[i]), angle[i])
        fr = fr_cache.get(fkey)
        if fr is None:
            fr = fr_cache[fkey] = FrictionTensor(
                float(fx[i]), float(fy[i]), float(f[i]), str(frame[i]), float(angle[i])
            )
        frictions.append(fr)
    v0 = _col(cols, "v0").astype(float)
    th = _col(cols, "theta0").astype(float)
    fields = dict(
        law=law,
        xi_c=xi_c,
        eta_c=eta_c,
        fx=fx,
        fy=fy,
        f=f,
        frame=frame,
        angle=angle,
        mass=mass,
        moment_of_inertia=np.array([b.moment_of_inertia for b in bodies]),
        g=_col(cols, "g").astype(float),
        x=_col(cols, "x0").astype(float),
        y=_col(cols, "y0").astype(float),
        phi=_col(cols, "phi0").astype(float),
        vx=v0 * np.cos(th),
        vy=v0 * np.sin(th),
        omega=_col(cols, "omega0").astype(float),
    )
    if shape != "ellipse":
        if (v0 < 0).any():
            i = int(np.flatnonzero(v0 < 0)[0])
            raise SweepError(f"v0 = {float(v0[i])!r} (case {i}) is invalid; valid range: >= 0")
        # the ranges of the batch engine (speed, spin, position, g, coefficients, I*), with
        # the footprint's length unit in the place of a (its own pressure check is the
        # Body's: the ellipse's core condition of the linear law does not apply)
        unit = np.array([b.length_unit for b in bodies])
        validated_columns(
            {**{k: fields[k] for k in fields if k != "law"}, "a": unit, "b": unit, "law": "uniform"}
        )
        table.update(_common_table(fields, unit))
    states = np.column_stack([fields[k] for k in ("x", "y", "phi", "vx", "vy", "omega")])
    loads = None
    if spec.mode != "stop":
        from slidespin.contact.statics import check_anisotropy

        # static friction is solved only where the anisotropy x elongation allows it: refuse
        # the others here, before any work, rather than mid-sweep
        seen = set()
        for i, (body, fr) in enumerate(zip(bodies, frictions)):
            if (id(body), id(fr)) not in seen:
                seen.add((id(body), id(fr)))
                try:
                    check_anisotropy(body, fr)
                except ValueError as exc:
                    raise SweepError(f"case {int(cols['case_id'][i])}: {exc}") from None
        loads = load_columns(cols, n, spec.mode)
        for k in LOAD_COLUMNS:
            table[k] = loads[k].astype(str) if loads[k].dtype == object else loads[k]
    return _Inputs(table, bodies, frictions, states, fields["g"], loads)


def _common_table(fields: dict, unit: np.ndarray) -> dict:
    """The tensor, body and initial-state columns of a footprint chunk."""
    out = {"length_unit": unit}
    for k in (
        "law",
        "xi_c",
        "eta_c",
        "fx",
        "fy",
        "f",
        "frame",
        "angle",
        "mass",
        "moment_of_inertia",
        "g",
        "x",
        "y",
        "phi",
        "vx",
        "vy",
        "omega",
    ):
        val = np.asarray(fields[k])
        out[_RENAMED.get(k, k)] = val.astype(str) if val.dtype == object else val
    out["I_star"] = out["moment_of_inertia"] / (out["mass"] * unit**2)
    out["mu"] = out["fy"] - out["fx"]
    out["v0"] = np.hypot(out["vx0"], out["vy0"])
    out["theta0"] = np.arctan2(out["vy0"], out["vx0"])
    return out


_RENAMED = {"x": "x0", "y": "y0", "phi": "phi0", "vx": "vx0", "vy": "vy0", "omega": "omega0"}


def compute_chunk(spec_data: dict | SweepSpec, index: int) -> dict:
    """Compute chunk ``index`` of a sweep (a pure function: usable as a Dask task).

    Returns a dict of equal-length columns (:func:`chunk_columns`): the case inputs and the
    results (the stop, the statics, or the loaded run: the spec's ``compute``).
    """
    spec = load_spec(spec_data) if not isinstance(spec_data, SweepSpec) else spec_data
    _limit_threads_in_dask_worker()
    start = index * spec.chunk_size
    cols = spec.parameters(start, start + spec.chunk_size)
    rtol = float(spec.data.get("rtol", 1e-10))
    if spec.shape == "ellipse" and spec.mode == "stop":
        fields = _case_fields(cols)
        out = _input_table(cols, fields)
        _add_results(out, simulate_cases(fields, rtol=rtol))
        return out
    inp = _case_inputs(spec, cols)
    out = dict(inp.table)
    given = set(spec.data.get("fixed", {})) | set(spec.data.get("vary", {}))
    if spec.mode != "stop":
        args = (inp.bodies, inp.frictions, inp.states, inp.g, inp.loads or {}, given)
        try:
            if spec.mode == "statics":
                out.update(compute_statics(*args))
            else:
                out.update(compute_loaded(*args, rtol))
        except CaseError as exc:
            # a per-case failure the checks before the run did not foresee: name the case
            raise SweepError(f"case {int(cols['case_id'][exc.index])}: {exc}") from exc
    else:
        # one batch per value of g (simulate_bodies shares g across its cases)
        parts = []
        for gv in np.unique(inp.g):
            sel = np.flatnonzero(inp.g == gv)
            res = simulate_bodies(
                [inp.bodies[i] for i in sel],
                [inp.frictions[i] for i in sel],
                inp.states[sel],
                float(gv),
                rtol,
            ).as_dict()
            parts.append((sel, res))
        for k in RESULT_COLUMNS:
            col = None
            for sel, res in parts:
                val = np.asarray(res[k])
                if col is None:
                    col = np.empty(
                        inp.g.size, dtype=object if val.dtype.kind in "OU" else val.dtype
                    )
                col[sel] = val
            assert col is not None
            out[k] = col.astype(str) if col.dtype == object else col
    return out


def _add_results(out: dict, res) -> None:
    d = res.as_dict()
    for k in RESULT_COLUMNS:
        val = d[k]
        out[k] = val.astype(str) if val.dtype == object else val


def _input_table(cols: dict, fields: dict) -> dict:
    """The input columns of an ellipse chunk (the layout of every earlier sweep)."""
    out = {"case_id": cols["case_id"].astype(np.int64)}
    for k in (
        "a",
        "b",
        "law",
        "xi_c",
        "eta_c",
        "fx",
        "fy",
        "f",
        "frame",
        "angle",
        "mass",
        "moment_of_inertia",
        "g",
        "x",
        "y",
        "phi",
        "vx",
        "vy",
        "omega",
    ):
        val = np.asarray(fields[k])
        out[
            {"x": "x0", "y": "y0", "phi": "phi0", "vx": "vx0", "vy": "vy0", "omega": "omega0"}.get(
                k, k
            )
        ] = val.astype(str) if val.dtype == object else val
    out["I_star"] = out["moment_of_inertia"] / (out["mass"] * out["a"] ** 2)
    out["mu"] = out["fy"] - out["fx"]
    out["aspect"] = out["b"] / out["a"]
    out["v0"] = np.hypot(out["vx0"], out["vy0"])
    out["theta0"] = np.arctan2(out["vy0"], out["vx0"])
    return out


def _limit_threads_in_dask_worker() -> None:
    """Inside a Dask worker, use as many compute threads as the worker has task threads,
    so that N workers on N cores do not oversubscribe them."""
    if "distributed" not in sys.modules:
        return
    try:
        from distributed import get_worker

        worker = get_worker()
    except (ImportError, ValueError):
        return
    from slidespin._jit import set_threads

    nthreads = getattr(worker.state, "nthreads", None) or getattr(worker, "nthreads", None)
    set_threads(int(nthreads or 1))


def compute_chunks(spec_data: dict, indices) -> list:
    """:func:`compute_chunk` for several chunks in one task (a list of tables)."""
    return [compute_chunk(spec_data, int(i)) for i in indices]


# --------------------------------------------------------------------------- storage
def _require_pyarrow():
    try:
        import pyarrow  # noqa: F401
        import pyarrow.parquet  # noqa: F401
    except ImportError:  # pragma: no cover - pyarrow is a dependency
        raise SweepError(
            "sweeps write Parquet files and need pyarrow: pip install pyarrow"
        ) from None


#: the columns of every chunk file, in order (inputs, derived inputs, results)
CHUNK_COLUMNS = (
    "case_id",
    "a",
    "b",
    "law",
    "xi_c",
    "eta_c",
    "fx",
    "fy",
    "f",
    "frame",
    "angle",
    "mass",
    "moment_of_inertia",
    "g",
    "x0",
    "y0",
    "phi0",
    "vx0",
    "vy0",
    "omega0",
    "I_star",
    "mu",
    "aspect",
    "v0",
    "theta0",
) + RESULT_COLUMNS
#: the geometry columns of a footprint chunk, per shape (derived keys included)
_SHAPE_COLUMNS = {
    "disk": ("radius",),
    "annulus": ("outer_radius", "inner_radius", "ring_width", "radius_ratio"),
    "rectangle": ("length", "width", "aspect"),
    "polygon": ("scale",),
}
_FOOTPRINT_COMMON = (
    "length_unit",
    "law",
    "xi_c",
    "eta_c",
    "fx",
    "fy",
    "f",
    "frame",
    "angle",
    "mass",
    "moment_of_inertia",
    "g",
    "x0",
    "y0",
    "phi0",
    "vx0",
    "vy0",
    "omega0",
    "I_star",
    "mu",
    "v0",
    "theta0",
)


def chunk_columns(spec: SweepSpec) -> tuple:
    """The columns of every chunk file of ``spec``, in order: inputs, derived inputs, results.

    An ellipse sweep computing stops has :data:`CHUNK_COLUMNS` (the layout of every earlier
    sweep). A footprint sweep has ``shape``, its geometry columns (``annulus``:
    ``outer_radius``, ``inner_radius``, ``ring_width``, ``radius_ratio``; ``rectangle``:
    ``length``, ``width``, ``aspect``; ``disk``: ``radius``; ``polygon``: ``scale``;
    ``pads``: ``n_pads``, ``pad_spacing``, the pad's size and ``pad_shape``) and
    ``length_unit`` (ℓ of I* = I/(m ℓ²)) in the place of ``a``, ``b``, ``aspect``. Statics
    and loaded sweeps add the load and tilt columns and their own results
    (``slidespin.studies.sweep_loads``).
    """
    shape = spec.shape
    if shape == "ellipse":
        inputs = CHUNK_COLUMNS[: -len(RESULT_COLUMNS)]
    else:
        if shape == "pads":
            size = (
                ("pad_length", "pad_width")
                if spec.data["fixed"].get("pad_shape") == "rectangle"
                else ("pad_radius",)
            )
            geo: tuple = ("n_pads", "pad_spacing", *size, "pad_shape")
        else:
            geo = _SHAPE_COLUMNS[shape]
        inputs = ("case_id", "shape", *geo, *_FOOTPRINT_COMMON)
    if spec.mode == "statics":
        return inputs + LOAD_COLUMNS + STATICS_COLUMNS
    if spec.mode == "loaded":
        return inputs + LOAD_COLUMNS + LOADED_COLUMNS
    return inputs + RESULT_COLUMNS


def _vocabulary(spec: SweepSpec) -> tuple:
    """(statuses, endings) a chunk of ``spec`` may hold."""
    from slidespin.motion.outcomes import ENDINGS, STATUSES

    if spec.mode == "statics":
        return STATICS_STATUSES, STATICS_ENDINGS
    if spec.mode == "loaded":
        return LOADED_STATUSES, LOADED_ENDINGS
    return STATUSES, ENDINGS


LOCK = ".lock"
#: largest manifest read (its chunk list has one number per chunk)
MAX_MANIFEST_BYTES = 128_000_000
#: statuses in the order of the summaries: converged, flagged, unconverged
STATUS_ORDER = (
    "stopped",
    "at_rest",
    "marginal",
    "saddle",
    "max_steps",
    "step_too_small",
    "non_finite",
)


def _os_error(exc: OSError, path, resumable: bool = True) -> SweepError:
    """A one-line :class:`SweepError` saying what went wrong while writing ``path``."""
    from slidespin._io import os_error_kind

    what = os_error_kind(exc)
    tail = (
        (
            "; the finished chunks are kept: free the problem and rerun with --resume "
            "(resume=True) to finish the sweep"
        )
        if resumable
        else ""
    )
    return SweepError(f"{what} while writing {str(path)!r} ({exc.strerror}){tail}")


def _atomic_write_bytes(path: Path, data: bytes) -> None:
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    try:
        with open(tmp, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise _os_error(exc, path) from None


def _chunk_path(out: Path, index: int) -> Path:
    return out / "chunks" / f"chunk-{index:06d}.parquet"


def _parquet_write(table, path) -> None:
    """Write a pyarrow table (a seam for tests that simulate a full disk)."""
    import pyarrow.parquet as pq

    pq.write_table(table, path)


def _write_chunk(out: Path, index: int, table: dict, columns: tuple = CHUNK_COLUMNS) -> None:
    import pyarrow as pa

    path = _chunk_path(out, index)
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    try:
        _parquet_write(pa.table({k: np.asarray(table[k]) for k in columns}), tmp)
        with open(tmp, "rb") as fh:
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise _os_error(exc, path) from None


def _chunks_done(out: Path) -> set[int]:
    done = set()
    d = out / "chunks"
    if d.is_dir():
        for p in d.glob("chunk-*.parquet"):
            try:
                done.add(int(p.stem.split("-")[1]))
            except ValueError:
                continue
    return done


def _read_chunk(path: Path):
    """A chunk file as a pyarrow table; ``SweepError`` naming the file if unreadable."""
    import pyarrow.parquet as pq

    try:
        return pq.read_table(path)
    except Exception as exc:  # noqa: BLE001 - pyarrow raises several types for bad files
        raise SweepError(
            f"{str(path)!r} is not a readable Parquet file ({type(exc).__name__}: "
            f"{str(exc).splitlines()[0] if str(exc) else ''}); rerun "
            "slidespin sweep SPEC --out DIR --resume to recompute it"
        ) from None


def _verify_chunk(out: Path, spec: SweepSpec, index: int):
    """The status and ending columns of chunk ``index`` if its file is sound (readable,
    the right columns, rows and case numbers, known statuses), else ``None``."""
    statuses, endings = _vocabulary(spec)
    start = index * spec.chunk_size
    n = min(spec.chunk_size, spec.n_cases - start)
    try:
        table = _read_chunk(_chunk_path(out, index))
    except SweepError:
        return None
    if tuple(table.column_names) != chunk_columns(spec) or table.num_rows != n:
        return None
    try:
        ids = table.column("case_id").to_numpy()
        status = table.column("status").to_numpy(zero_copy_only=False).astype(str)
        ending = table.column("ending").to_numpy(zero_copy_only=False).astype(str)
    except Exception:  # noqa: BLE001 - wrong types in a foreign or damaged file
        return None
    if not np.array_equal(ids, np.arange(start, start + n)):
        return None
    if not (np.isin(status, statuses).all() and np.isin(ending, endings).all()):
        return None
    return status, ending


def count_outcomes(status, ending=None) -> dict:
    """Cases per status (and per ending): ``{"status": {name: n}, "ending": {...},
    "unconverged": n}``, names in the order of :mod:`slidespin.motion.outcomes`, zeros left out."""
    from slidespin.motion.outcomes import ENDINGS, UNCONVERGED

    def tally(values, names):
        values = np.asarray(values).astype(str)
        names = list(names) + sorted(set(values.tolist()) - set(names))
        counts = {nm: int(np.count_nonzero(values == nm)) for nm in names}
        return {k: c for k, c in counts.items() if c}

    out = {"status": tally(status, STATUS_ORDER)}
    if ending is not None:
        out["ending"] = tally(ending, ENDINGS)
    out["unconverged"] = sum(
        c for k, c in out["status"].items() if k in UNCONVERGED or k in LOADED_UNCONVERGED
    )
    return out


def _add_counts(total: dict, status, ending) -> None:
    new = count_outcomes(status, ending)
    for key in ("status", "ending"):
        for k, c in new[key].items():
            total[key][k] = total[key].get(k, 0) + c


def _write_manifest(out: Path, spec: SweepSpec, done: set[int], counts: dict | None = None) -> None:
    from slidespin import __version__
    from slidespin.motion.outcomes import UNCONVERGED

    counts = counts or {"status": {}, "ending": {}}
    doc = {
        "slidespin_version": __version__,
        "spec_sha256": spec.digest,
        "spec": spec.data,
        "n_cases": spec.n_cases,
        "chunk_size": spec.chunk_size,
        "n_chunks": spec.n_chunks,
        "chunks_done": sorted(done),
        "complete": len(done) == spec.n_chunks,
        # over the chunks done (all cases once complete)
        "status_counts": dict(counts["status"]),
        "ending_counts": dict(counts["ending"]),
        "unconverged": sum(
            c for k, c in counts["status"].items() if k in UNCONVERGED or k in LOADED_UNCONVERGED
        ),
    }
    _atomic_write_bytes(out / MANIFEST, (json.dumps(doc, indent=1) + "\n").encode())


def _read_manifest(out: Path) -> dict | None:
    p = out / MANIFEST
    if not p.exists():
        return None
    if not p.is_file():
        raise SweepError(f"{str(p)!r} is not a regular file; it is not a slidespin sweep directory")
    try:
        with open(p, "rb") as fh:
            raw = fh.read(MAX_MANIFEST_BYTES + 1)
        if len(raw) > MAX_MANIFEST_BYTES:
            raise SweepError(
                f"{str(p)!r} is larger than {MAX_MANIFEST_BYTES} bytes; it is not "
                "a slidespin sweep manifest"
            )
        doc = json.loads(raw.decode("utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError, RecursionError) as exc:
        raise SweepError(
            f"{str(p)!r} is unreadable ({exc}); it is not a slidespin sweep directory"
        ) from None
    if not isinstance(doc, dict):
        raise SweepError(f"{str(p)!r} is not a slidespin sweep manifest")
    return doc


def _check_out(out: Path) -> dict | None:
    """Refuse a file or a foreign non-empty directory; return the manifest if any."""
    if out.exists() and not out.is_dir():
        raise SweepError(f"out = {str(out)!r} exists and is not a directory")
    man = _read_manifest(out) if out.is_dir() else None
    if man is None and out.is_dir() and any(p.name != LOCK for p in out.iterdir()):
        raise SweepError(
            f"out = {str(out)!r} is a non-empty directory without a sweep "
            "manifest; choose a new or empty directory"
        )
    return man


def _prepare(out: Path, spec: SweepSpec, resume: bool):
    """Set up ``out`` (called holding the lock). Returns the sound chunks done, the number
    of damaged chunk files removed for recomputation, and the counts of the sound chunks."""
    man = _check_out(out)
    counts: dict[str, dict[str, int]] = {"status": {}, "ending": {}}
    if man is None:
        try:
            (out / "chunks").mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise SweepError(f"out = {str(out)!r} cannot be created: {exc.strerror}") from None
        if not os.access(out, os.W_OK):
            raise SweepError(f"out = {str(out)!r} is not writable")
        _write_manifest(out, spec, set(), counts)
        return set(), 0, counts
    if man.get("spec_sha256") != spec.digest:
        raise SweepError(
            f"{str(out)!r} holds a different sweep (spec hash {str(man.get('spec_sha256'))[:12]}…, "
            f"this spec {spec.digest[:12]}…); use another directory"
        )
    done = _chunks_done(out)
    if not resume:
        raise SweepError(
            f"{str(out)!r} already holds this sweep ({len(done)} of {spec.n_chunks} chunks "
            "done); pass --resume (resume=True) to finish it"
        )
    if not os.access(out, os.W_OK):
        raise SweepError(f"out = {str(out)!r} is not writable")
    (out / "chunks").mkdir(exist_ok=True)
    # leftovers of a killed run: temporary files are never valid results
    for p in (out / "chunks").glob(".chunk-*.tmp-*"):
        p.unlink(missing_ok=True)
    # every chunk file is checked (readable, columns, rows, case numbers); bad ones go
    sound, repaired = set(), 0
    for i in sorted(done):
        ok = _verify_chunk(out, spec, i) if i < spec.n_chunks else None
        if ok is None:
            _chunk_path(out, i).unlink(missing_ok=True)
            repaired += 1
        else:
            sound.add(i)
            _add_counts(counts, *ok)
    return sound, repaired, counts


class _Lock:
    """``DIR/.lock`` created with O_EXCL, holding ``pid host``: one sweep per directory.

    A lock left by a process that no longer exists on this host is stale and taken over.
    """

    def __init__(self, out: Path):
        self.path = out / LOCK
        self.held = False

    def __enter__(self):
        import socket

        me = f"{os.getpid()} {socket.gethostname()}\n"
        for _ in range(2):
            try:
                fd = os.open(self.path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
            except FileExistsError:
                pid, host = _lock_owner(self.path)
                if pid is not None and host == socket.gethostname() and not _pid_alive(pid):
                    self.path.unlink(missing_ok=True)  # stale: its process is gone
                    continue
                who = f"pid {pid} on {host}" if pid is not None else "another process"
                raise SweepError(
                    f"{str(self.path.parent)!r} is in use by another slidespin sweep ({who}; "
                    f"lock file {str(self.path)!r}); wait for it to finish, or delete the lock "
                    "file if that process no longer runs"
                ) from None
            except OSError as exc:
                raise _os_error(exc, self.path, resumable=False) from None
            try:
                os.write(fd, me.encode())
            finally:
                os.close(fd)
            self.held = True
            return self
        raise SweepError(f"cannot take the lock {str(self.path)!r}")  # pragma: no cover

    def __exit__(self, *exc):
        if self.held:
            self.path.unlink(missing_ok=True)
            self.held = False
        return False


def _lock_owner(path: Path):
    try:
        with open(path, "rb") as fh:
            text = fh.read(200).decode("utf-8", errors="replace").split()
        return int(text[0]), (text[1] if len(text) > 1 else "")
    except (OSError, ValueError, IndexError):
        return None, ""


def _pid_alive(pid: int) -> bool:
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # exists, owned by someone else
        return True
    except OSError:
        return True
    return True


# --------------------------------------------------------------------------- progress
class _Progress:
    def __init__(self, total: int, done: int, enabled: bool):
        self.total, self.done, self.enabled = total, done, enabled
        self.t0 = time.monotonic()
        self.start_done = done

    def update(self, n: int) -> None:
        self.done += n
        if not self.enabled:
            return
        el = time.monotonic() - self.t0
        rate = (self.done - self.start_done) / el if el > 0 else 0.0
        eta = (self.total - self.done) / rate if rate > 0 else float("nan")
        frac = self.done / self.total if self.total else 1.0
        bar = "#" * int(30 * frac)
        eta_s = f"{eta:5.0f}s" if math.isfinite(eta) else "    ?"
        sys.stderr.write(
            f"\r[{bar:<30}] {self.done}/{self.total} cases  {rate:8.0f} cases/s  ETA {eta_s}"
        )
        sys.stderr.flush()

    def close(self) -> None:
        if self.enabled:
            sys.stderr.write("\n")


# --------------------------------------------------------------------------- driver
@dataclass(frozen=True)
class SweepResult:
    """Outcome of :func:`sweep`: where it is, how many chunks were computed now, how long,
    and how the cases ended.

    ``status_counts`` and ``ending_counts`` count the cases of the whole sweep (every chunk
    done, also those of earlier runs) per status and per ending (:mod:`slidespin.motion.outcomes`);
    ``chunks_repaired`` is the number of damaged chunk files found by ``resume`` and computed
    again.
    """

    out: Path
    n_cases: int
    n_chunks: int
    chunks_computed: int
    cases_computed: int
    seconds: float
    status_counts: dict = field(default_factory=dict)
    ending_counts: dict = field(default_factory=dict)
    chunks_repaired: int = 0

    @property
    def cases_per_second(self) -> float:
        """Throughput of this run (0 if nothing was left to compute)."""
        return self.cases_computed / self.seconds if self.cases_computed else 0.0

    @property
    def n_unconverged(self) -> int:
        """Cases whose status is in :data:`slidespin.motion.outcomes.UNCONVERGED`."""
        from slidespin.motion.outcomes import UNCONVERGED

        return sum(
            c for k, c in self.status_counts.items() if k in UNCONVERGED or k in LOADED_UNCONVERGED
        )

    @property
    def n_flagged(self) -> int:
        """Cases whose status is in :data:`slidespin.motion.outcomes.FLAGGED` (marginal, saddle)."""
        from slidespin.motion.outcomes import FLAGGED

        return sum(c for k, c in self.status_counts.items() if k in FLAGGED)

    def to_pandas(self, *, include_unconverged: bool = False):
        """The sweep's results as a :class:`pandas.DataFrame` (:func:`to_pandas` of
        ``out``)."""
        return to_pandas(self.out, include_unconverged=include_unconverged)


def sweep(
    spec,
    out,
    executor=None,
    *,
    resume: bool = False,
    progress: bool | None = None,
    task_cases: int | None = None,
) -> SweepResult:
    """Run (or resume) a parameter sweep and store its results in ``out``.

    Parameters
    ----------
    spec : str, Path, dict or SweepSpec
        Sweep specification (a TOML path or its parsed dict).
    out : str or Path
        Result directory: ``manifest.json`` and ``chunks/chunk-NNNNNN.parquet``. While a
        sweep runs, ``out/.lock`` (holding its process id and host) makes any other sweep on
        the same directory refuse to start; a lock whose process is gone is taken over.
    executor : None, dask.distributed.Client or concurrent.futures.Executor
        ``None`` runs on all local cores; otherwise one chunk is submitted per task.
    resume : bool
        Finish a sweep that was interrupted: only missing chunks are computed. Every chunk
        file already there is checked first (readable Parquet, its columns, row count and
        case numbers); damaged ones are computed again. Without ``resume`` an existing sweep
        directory is refused, and a directory of a different spec always is.
    progress : bool or None
        Progress bar on stderr; ``None`` means only when stderr is a terminal.
    task_cases : int or None
        With an executor, the least number of cases per task (whole chunks are grouped).
        ``None``: :data:`MIN_TASK_CASES` for stop sweeps, one chunk per task for statics and
        loaded sweeps (a loaded case takes milliseconds to seconds).

    Returns
    -------
    SweepResult

    Raises
    ------
    SweepError
        A bad spec, a foreign or busy directory, or a write that failed (disk full,
        permission denied): the message says which file; the chunks finished so far are kept
        and ``resume=True`` completes the sweep.
    """
    _require_pyarrow()
    if task_cases is not None and (
        isinstance(task_cases, bool) or not isinstance(task_cases, int) or task_cases < 1
    ):
        raise SweepError(f"task_cases = {task_cases!r} is invalid; valid range: integer >= 1")
    spec = load_spec(spec)
    if task_cases is None:
        task_cases = MIN_TASK_CASES if spec.mode == "stop" else 1
    out = Path(out)
    _check_out(out)  # before creating anything
    if not out.is_dir():
        try:
            out.mkdir(parents=True)
        except FileExistsError:
            pass
        except OSError as exc:
            raise SweepError(f"out = {str(out)!r} cannot be created: {exc.strerror}") from None
    with _Lock(out):
        return _run_sweep(spec, out, executor, resume, progress, task_cases)


def _run_sweep(spec, out, executor, resume, progress, task_cases) -> SweepResult:
    done, repaired, counts = _prepare(out, spec, resume)
    if repaired:
        _write_manifest(out, spec, done, counts)
    todo = [i for i in range(spec.n_chunks) if i not in done]
    show = sys.stderr.isatty() if progress is None else bool(progress)
    bar = _Progress(spec.n_cases, sum(_chunk_len(spec, i) for i in done), show)
    t0 = time.perf_counter()
    columns = chunk_columns(spec)

    def finish(i, table):
        _write_chunk(out, i, table, columns)
        done.add(i)
        _add_counts(counts, table["status"], table["ending"])
        _write_manifest(out, spec, done, counts)
        bar.update(_chunk_len(spec, i))

    try:
        if executor is None:
            for i in todo:
                finish(i, compute_chunk(spec, i))
        else:
            # one task computes consecutive chunks totalling >= MIN_TASK_CASES cases, so that
            # scheduling overhead stays small; each chunk is still written on its own
            per_task = max(1, -(-task_cases // spec.chunk_size))
            groups = [todo[i : i + per_task] for i in range(0, len(todo), per_task)]
            if _is_dask_client(executor):
                from distributed import as_completed

                futs = {
                    executor.submit(compute_chunks, spec.data, g, pure=False): g for g in groups
                }
                done_iter: Iterable = as_completed(list(futs))
            else:
                import concurrent.futures as cf

                futs = {executor.submit(compute_chunks, spec.data, g): g for g in groups}
                done_iter = cf.as_completed(futs)
            for fut in done_iter:
                for i, table in zip(futs[fut], fut.result()):
                    finish(i, table)
    finally:
        bar.close()
    from slidespin.motion.outcomes import ENDINGS

    def ordered(d, names):
        return {k: d[k] for k in list(names) + sorted(set(d) - set(names)) if d.get(k)}

    return SweepResult(
        out,
        spec.n_cases,
        spec.n_chunks,
        len(todo),
        sum(_chunk_len(spec, i) for i in todo),
        time.perf_counter() - t0,
        ordered(counts["status"], STATUS_ORDER),
        ordered(counts["ending"], ENDINGS),
        repaired,
    )


def _chunk_len(spec, i):
    return min(spec.chunk_size, spec.n_cases - i * spec.chunk_size)


def _is_dask_client(obj) -> bool:
    return type(obj).__name__ == "Client" and type(obj).__module__.startswith("distributed")


def connect_dask(address: str | None = None, workers: int | None = None):
    """A ``dask.distributed.Client``: to ``address`` (``tcp://HOST:PORT``) or a new LocalCluster."""
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        raise SweepError(
            "Dask is not installed: pip install 'slidespin[cluster]' (dask[distributed])"
        ) from None
    if address:
        try:
            return Client(address, timeout="10s")
        except (OSError, TimeoutError) as exc:
            raise SweepError(f"--scheduler {address!r}: cannot connect ({exc})") from None
    cluster = LocalCluster(
        n_workers=workers or 2,
        threads_per_worker=1,
        host="127.0.0.1",
        dashboard_address=None,
        processes=True,
    )
    return Client(cluster)


def read_sweep(out, *, include_unconverged: bool = False) -> dict:
    """The results of a sweep directory as one table: column name → array, sorted by case.

    Parameters
    ----------
    out : str or Path
        Sweep directory.
    include_unconverged : bool, default False
        Keep the cases whose status is in :data:`slidespin.motion.outcomes.UNCONVERGED`
        (``max_steps``, ``step_too_small``, ``non_finite``: values as reached, not a stop).
        By default they are left out; :func:`split_unconverged` counts them.

    Raises
    ------
    ValueError
        If ``out`` is not a sweep directory or a chunk file is unreadable (the message names
        it). An unfinished sweep is read as far as it got.
    """
    _require_pyarrow()
    import pyarrow as pa

    out = Path(out)
    if not out.is_dir() or _read_manifest(out) is None:
        raise SweepError(f"{str(out)!r} is not a sweep directory (no {MANIFEST})")
    files = sorted((out / "chunks").glob("chunk-*.parquet"))
    if not files:
        return {}
    try:
        table = pa.concat_tables([_read_chunk(f) for f in files])
    except pa.ArrowInvalid as exc:
        raise SweepError(
            f"the chunk files of {str(out)!r} do not fit together ({exc}); rerun "
            "slidespin sweep SPEC --out DIR --resume to check them"
        ) from None
    cols = {name: table.column(name).to_numpy(zero_copy_only=False) for name in table.column_names}
    order = np.argsort(cols["case_id"], kind="stable")
    cols = {k: val[order] for k, val in cols.items()}
    return cols if include_unconverged else split_unconverged(cols)[0]


def to_pandas(out, *, include_unconverged: bool = False):
    """A sweep directory's results as a :class:`pandas.DataFrame`, one row per case.

    The table of :func:`read_sweep` (same columns, sorted by ``case_id``, unconverged cases
    left out unless ``include_unconverged``), read from the Parquet chunks; the spec, its
    name and the cases left out per status are in ``DataFrame.attrs``. Needs pandas
    (``pip install pandas``; it is in the ``test`` extra).

    Raises
    ------
    ImportError
        If pandas is not installed (the message says how to install it).
    SweepError
        If ``out`` is not a sweep directory or a chunk is unreadable.
    """
    try:
        import pandas as pd  # type: ignore[import-untyped]  # pandas ships no type information
    except ImportError:  # pragma: no cover - depends on the environment
        raise ImportError(
            "slidespin.studies.sweep.to_pandas needs pandas: pip install pandas "
            "(or pip install 'slidespin[test]')"
        ) from None
    table = read_sweep(out, include_unconverged=True)
    kept, left = (table, {}) if include_unconverged else split_unconverged(table)
    df = pd.DataFrame({k: np.asarray(val) for k, val in kept.items()})
    man = _read_manifest(Path(out)) or {}
    spec = man.get("spec", {}) if isinstance(man.get("spec"), dict) else {}
    df.attrs.update(name=spec.get("name", ""), spec=spec, left_out=left)
    return df


def split_unconverged(table: dict):
    """``(kept, left_out)``: the table without the unconverged cases, and the number left out
    per status (``{}`` if none). A table without a ``status`` column is kept whole."""
    from slidespin.motion.outcomes import UNCONVERGED

    if not table or "status" not in table:
        return table, {}
    status = np.asarray(table["status"]).astype(str)
    bad = np.isin(status, sorted(UNCONVERGED | LOADED_UNCONVERGED))
    if not bad.any():
        return table, {}
    left = {k: int(c) for k, c in zip(*np.unique(status[bad], return_counts=True))}
    return {k: np.asarray(val)[~bad] for k, val in table.items()}, left


def benchmark(
    n_local: int = 1_000_000,
    n_dask: int = 100_000,
    workers: int = 2,
    chunk_size: int = 10_000,
    out=None,
) -> dict:
    """Measure sweep throughput on all local cores and through a local Dask cluster.

    Runs a random sweep (uniform/Hertz laws, random shapes, tensors and starts) of
    ``n_local`` cases with the local engine and ``n_dask`` cases through a ``LocalCluster``
    of ``workers`` single-threaded processes on 127.0.0.1, both written to Parquet like any
    sweep. Returns cases per second for each, per core, and the Dask/local ratio per core.
    """
    import os
    import shutil
    import tempfile

    def spec(n):
        return {
            "name": "benchmark",
            "kind": "random",
            "chunk_size": int(chunk_size),
            "random": {"samples": int(n), "seed": 7},
            "fixed": {"a": 0.05, "mass": 1.0},
            "vary": {
                "aspect": {"low": 0.3, "high": 1.0},
                "law": ["uniform", "hertz"],
                "fx": {"low": 0.2, "high": 0.5},
                "mu": {"low": 0.0, "high": 0.3},
                "I_star": {"low": 0.2, "high": 1.0},
                "v0": {"low": 0.2, "high": 2.0},
                "omega0": {"low": -30.0, "high": 30.0},
                "theta0": {"low": -3.14, "high": 3.14},
            },
        }

    base = Path(out) if out else Path(tempfile.mkdtemp(prefix="slidespin-bench-"))
    cores = os.cpu_count() or 1
    result: dict[str, float] = {"cores": cores, "workers": workers}
    try:
        # warm-up (compilation) outside the timings
        compute_chunk(load_spec(dict(spec(2), chunk_size=2)), 0)
        if n_local:
            t0 = time.perf_counter()
            sweep(spec(n_local), base / "local", progress=False)
            dt = time.perf_counter() - t0
            result.update(
                local_cases=n_local,
                local_seconds=dt,
                local_cases_per_s=n_local / dt,
                local_cases_per_s_per_core=n_local / dt / cores,
            )
        if n_dask:
            client = connect_dask(None, workers)
            try:
                client.run(compute_chunk, dict(spec(2), chunk_size=2), 0)  # warm workers
                t0 = time.perf_counter()
                sweep(spec(n_dask), base / "dask", executor=client, progress=False)
                dt = time.perf_counter() - t0
            finally:
                cluster = getattr(client, "cluster", None)
                client.close()
                if cluster is not None:
                    cluster.close()
            result.update(
                dask_cases=n_dask,
                dask_seconds=dt,
                dask_cases_per_s=n_dask / dt,
                dask_cases_per_s_per_core=n_dask / dt / min(workers, cores),
            )
            if n_local:
                result["dask_over_local_per_core"] = (
                    result["dask_cases_per_s_per_core"] / result["local_cases_per_s_per_core"]
                )
    finally:
        if out is None:
            shutil.rmtree(base, ignore_errors=True)
    return result
