"""Reading and checking a sweep spec: :func:`load_spec` (a TOML file or a dict → a validated
:class:`~slidespin.studies.sweep_spec.SweepSpec`).

Specs are read like case files (:func:`slidespin.studies.case.read_toml`: a regular UTF-8
file of at most 1 MB, nesting and integers bounded). Every key, every value and the limits of
:mod:`slidespin.studies.sweep_spec` are checked, then every case's physics (cheap: no
integration; a footprint checks itself on construction), so that a bad value fails before any
work starts, naming the parameter.
"""

from __future__ import annotations

import copy
import math
import os

import numpy as np

from slidespin import _validate as v
from slidespin.motion._cases import SHAPE_KEYS
from slidespin.motion.sensitivity import EXTRA_PARAMETERS, check_parameters, check_setup
from slidespin.motion.sensitivity import PARAMETERS as SENSITIVITY_PARAMETERS
from slidespin.studies._sweep_inputs import _case_fields, _case_inputs
from slidespin.studies.case import MAX_STEPS_LIMIT, check_document, check_name, read_toml
from slidespin.studies.sweep_loads import LOAD_PARAMETERS, MODES
from slidespin.studies.sweep_spec import (
    _CARTESIAN,
    _ELLIPSE_KEYS,
    _EXCLUSIVE,
    _FIXED_ONLY,
    _GEOMETRY_KEYS,
    _MOTION_KEYS,
    _POLAR,
    _TOP_KEYS,
    MAX_CASES,
    MAX_CHUNK,
    PARAMETERS,
    SweepError,
    SweepSpec,
    _check_value,
    _grid_values,
    _only,
    _random_values,
)

__all__ = ["load_spec"]


def _check_sensitivities(data: dict, mode: str) -> None:
    """The ``sensitivities`` key: parameters of :func:`slidespin.stop_sensitivities`, with
    compute = "stop" (their canonical order kept as given)."""
    names = data["sensitivities"]
    if mode != "stop":
        raise SweepError(
            f"sensitivities = {names!r} is for compute = 'stop' (the derivatives of the stop); "
            f"valid: leave it out with compute = {mode!r}"
        )
    if isinstance(names, str) or not isinstance(names, list) or not names:
        raise SweepError(
            f"sensitivities = {names!r} is invalid; valid values: a non-empty list of "
            f"parameter names among {', '.join(SENSITIVITY_PARAMETERS + EXTRA_PARAMETERS)}"
        )
    try:
        check_parameters(names, "sensitivities")
    except ValueError as exc:
        raise SweepError(str(exc)) from None


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
        raise SweepError(
            f"parameter {both[0]!r} is both fixed and varied; valid: in [fixed] or in "
            "[vary], not both"
        )
    given = set(fixed) | set(vary)
    mode = v.choice("compute", data.get("compute", "stop"), MODES)
    for k in _FIXED_ONLY:
        if k in vary:
            raise SweepError(
                f"{k!r} cannot be varied; valid: fix it in [fixed] (one {k} per sweep)"
            )
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
    if "sensitivities" in data:
        _check_sensitivities(data, mode)
    if mode == "stop":
        for k in sorted(given & set(LOAD_PARAMETERS)):
            raise SweepError(
                f"{k!r} is a load, tilt or time bound: it needs compute = "
                "'statics' or 'loaded' (the default 'stop' coasts on a level plane); valid: "
                "compute = 'statics' | 'loaded', or leave it out"
            )
    elif mode == "statics":
        if "t_end" in given:
            raise SweepError(
                "'t_end' is for compute = 'loaded'; compute = 'statics' has no time (valid: "
                "leave t_end out, or compute = 'loaded')"
            )
        # a body at rest at the angle phi0: no start motion, no integration to tune
        for k in sorted(given & set(_MOTION_KEYS)):
            raise SweepError(
                f"{k!r} is not used by compute = 'statics' (the statics of a body at rest "
                "at the angle phi0); valid: leave it out, or compute = 'loaded'"
            )
        for k in ("rtol", "max_steps"):
            if k in data:
                raise SweepError(
                    f"{k!r} is not used by compute = 'statics' (it integrates no motion); "
                    "valid: leave it out, or compute = 'stop' | 'loaded'"
                )
    for group in _EXCLUSIVE:
        if len(given & set(group)) > 1:
            raise SweepError(
                f"give at most one of {', '.join(group)} (got "
                f"{', '.join(k for k in group if k in given)}); valid: one of them"
            )
    polar, cartesian = sorted(given & set(_POLAR)), sorted(given & set(_CARTESIAN))
    if polar and cartesian:
        raise SweepError(
            f"give the start velocity either as v0 and theta0 (or theta0_deg) or as vx0 and "
            f"vy0, not both (got {polar[0]} and {cartesian[0]}); valid: one of the two forms"
        )
    for req in ("a",) if shape == "ellipse" else ():
        if req not in given:
            raise SweepError(
                f"the sweep spec must fix or vary {req!r}; valid: a value in [fixed] or "
                "values in [vary]"
            )
    for req in ("fx",):
        if req not in given:
            raise SweepError(
                f"the sweep spec must fix or vary {req!r}; valid: a value in [fixed] or "
                "values in [vary]"
            )
    if not given & {"fy", "mu"}:
        raise SweepError(
            "the sweep spec must fix or vary 'fy' or 'mu'; valid: one of them in [fixed] or [vary]"
        )
    for k, val in fixed.items():
        _check_value(f"[fixed] {k}", val, k)
    centroid = sorted(given & {"xi_c", "eta_c"})
    if centroid:
        laws = [fixed.get("law", PARAMETERS["law"])]
        if isinstance(vary.get("law"), list):
            laws = vary["law"]
        if not any(isinstance(x, str) and x.lower() == "linear" for x in laws):
            raise SweepError(
                f"{centroid[0]!r} is the centroid of the linear pressure law, and no case of "
                f"this sweep has law = 'linear' (law: {', '.join(map(str, laws))}); valid: "
                "law = 'linear' in [fixed] or among the laws in [vary], or leave it out"
            )
    check_name(data.get("name", ""))
    chunk = data.get("chunk_size", 1000)
    if isinstance(chunk, bool) or not isinstance(chunk, int) or not 1 <= chunk <= MAX_CHUNK:
        raise SweepError(
            f"chunk_size = {chunk!r} is invalid; valid range: integer >= 1 and <= {MAX_CHUNK}"
        )
    if "rtol" in data:
        v.in_range("rtol", data["rtol"], 0.0, 1e-3, lo_open=True)
    if "max_steps" in data:
        steps = data["max_steps"]
        if (
            isinstance(steps, bool)
            or not isinstance(steps, int)
            or not 1 <= steps <= MAX_STEPS_LIMIT
        ):
            raise SweepError(
                f"max_steps = {steps!r} is invalid; valid range: integer >= 1 and <= "
                f"{MAX_STEPS_LIMIT}"
            )
    if kind == "grid":
        if "random" in data:
            raise SweepError(
                "[random] is only for kind = 'random'; valid: kind = 'random' with [random], "
                "or a grid without it"
            )
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
            raise SweepError(
                "kind = 'random' needs a [random] table with 'samples'; valid: [random] "
                f"samples = an integer in [1, {MAX_CASES}]"
            )
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
        if spec.shape == "ellipse" and spec.mode == "stop" and not spec.sensitivities:
            _case_fields(cols)
        else:  # builds each distinct body once (a footprint checks itself on construction)
            inp = _case_inputs(spec, cols)
            if spec.sensitivities:  # a parameter a case's body cannot vary
                _check_sensitivity_bodies(spec, inp.bodies, cols["case_id"])
    return spec


def _check_sensitivity_bodies(spec: SweepSpec, bodies, case_ids) -> None:
    """Refuse a ``sensitivities`` parameter some case's body cannot vary, naming the case."""
    seen: set = set()
    for body, case in zip(bodies, case_ids):
        if id(body) in seen:
            continue
        seen.add(id(body))
        try:
            check_setup(body, spec.sensitivities, case=int(case))
        except ValueError as exc:  # (it names the case)
            raise SweepError(str(exc)) from None


def load_spec(spec) -> SweepSpec:
    """A :class:`~slidespin.studies.sweep_spec.SweepSpec` from a path to a TOML file, a dict,
    or a spec (returned as is)."""
    if isinstance(spec, SweepSpec):
        return spec
    if isinstance(spec, dict):
        try:
            return _validate_spec(spec)
        except SweepError:
            raise
        except ValueError as exc:
            raise SweepError(str(exc)) from None
    if not isinstance(spec, (str, os.PathLike)):
        raise SweepError(
            f"spec = {spec!r:.60} is invalid; valid values: a path to a TOML file (str or "
            "os.PathLike), a dict of its tables, or a SweepSpec"
        )
    try:
        data = read_toml(spec, "sweep spec")
    except ValueError as exc:
        raise SweepError(str(exc)) from None
    try:
        return _validate_spec(data)
    except ValueError as exc:
        raise SweepError(f"{spec}: {exc}") from None
