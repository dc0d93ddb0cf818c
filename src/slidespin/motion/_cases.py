"""Validation of per-case parameter columns for the batch engine and the sweeps.

One function, :func:`validated_columns`, checks every per-case input (shape, type, range,
the linear law's core condition) before any work starts, naming the parameter, the first bad
case and its value, and the valid range.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.contact.pressure import LAW_NAMES
from slidespin.contact.shapes import Annulus, Disk, Pads, Polygon, Rectangle

__all__ = [
    "CASE_FIELDS",
    "SHAPE_KEYS",
    "validated_columns",
    "footprint_geometry",
    "footprint_patch",
]

#: per-case inputs of :func:`slidespin.motion.batch.simulate_cases` and their defaults (None: required)
CASE_FIELDS = {
    "a": None,
    "b": None,
    "law": "uniform",
    "xi_c": 0.0,
    "eta_c": 0.0,
    "fx": None,
    "fy": None,
    "f": 0.0,
    "frame": "plane",
    "angle": 0.0,
    "mass": 1.0,
    "moment_of_inertia": math.nan,
    "g": 9.81,
    "x": 0.0,
    "y": 0.0,
    "phi": 0.0,
    "vx": 0.0,
    "vy": 0.0,
    "omega": 0.0,
}


def _column(name, value, n, kind="real"):
    arr = np.asarray(value)
    if arr.ndim > 1 or (arr.ndim == 1 and arr.size not in (1, n)):
        raise ValueError(f"{name} has shape {arr.shape}; valid: a scalar or an array of length {n}")
    if kind == "real":
        if arr.dtype.kind not in "fiu":
            raise ValueError(
                f"{name} must be real numbers, got dtype {arr.dtype}; valid values: a real "
                f"scalar or an array of length {n} of ints or floats"
            )
        arr = arr.astype(float)
    return np.broadcast_to(arr, (n,)) if arr.ndim == 0 or arr.size == 1 else arr


def _check(name, arr, ok, valid):
    bad = ~ok
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        # 1.5 rather than np.float64(1.5) in the message
        value = arr[i].item() if isinstance(arr[i], np.generic) else arr[i]
        raise ValueError(f"{name} = {value!r} (case {i}) is invalid; valid range: {valid}")


def _in(name, arr, lo, hi):
    with np.errstate(all="ignore"):
        ok = np.isfinite(arr) & (arr >= lo) & (arr <= hi)
    _check(name, arr, ok, f"[{lo:g}, {hi:g}]")


def validated_columns(cases: dict):
    """Check the per-case inputs and return ``(columns, moment_of_inertia)``.

    ``columns`` maps every name of :data:`CASE_FIELDS` to a float array of length N (codes
    for ``law`` and ``frame``); ``moment_of_inertia`` has the uniform-plate default filled in.
    """
    if not isinstance(cases, dict):
        raise ValueError(
            f"cases = {v._short(cases)} ({type(cases).__name__}) is invalid; valid values: a "
            f"dict of case fields ({', '.join(CASE_FIELDS)}), each a scalar or a 1-D array"
        )
    unknown = sorted(set(cases) - set(CASE_FIELDS))
    if unknown:
        raise ValueError(f"unknown case field {unknown[0]!r}; valid: {', '.join(CASE_FIELDS)}")
    missing = [k for k, d in CASE_FIELDS.items() if d is None and k not in cases]
    if missing:
        required = ", ".join(k for k, d in CASE_FIELDS.items() if d is None)
        raise ValueError(
            f"missing case field {missing[0]!r}; valid cases give the required fields "
            f"{required} (the others have defaults: CASE_FIELDS)"
        )
    sizes = {np.size(v) for v in cases.values() if np.ndim(v) == 1 and np.size(v) != 1}
    if len(sizes) > 1:
        raise ValueError(
            f"case arrays have different lengths {sorted(sizes)}; valid: every array of "
            "one length N (or a scalar, or length 1, shared by all cases)"
        )
    n = sizes.pop() if sizes else 1
    col = {}
    for k, d in CASE_FIELDS.items():
        val = cases.get(k, d)
        if k in ("law", "frame"):
            arr = np.asarray(val)
            names = LAW_NAMES if k == "law" else ("plane", "body")
            if arr.dtype.kind in "USO":
                lookup = {nm: i for i, nm in enumerate(names)}
                flat = np.atleast_1d(arr).ravel()
                try:
                    codes = np.array([lookup[str(x).lower()] for x in flat], dtype=float)
                except KeyError as exc:
                    raise ValueError(
                        f"{k} = {exc.args[0]!r} is invalid; valid values: {', '.join(names)}"
                    ) from None
                val = codes
            arr = _column(k, val, n)
            _check(k, arr, np.isin(arr, np.arange(len(names))), f"one of {', '.join(names)}")
            col[k] = arr
        else:
            col[k] = _column(k, val, n)
    # the same ranges as the value objects (slidespin._validate; docs/errors.md says why):
    # this path skips Body and State, so it must refuse what they refuse
    for k, (lo, hi) in (
        ("a", v.LENGTH),
        ("b", v.LENGTH),
        ("fx", v.COEFFICIENT),
        ("fy", v.COEFFICIENT),
        ("mass", v.MASS),
        ("g", v.GRAVITY),
    ):
        _in(k, col[k], lo, hi)
    _in("b/a", col["b"] / col["a"], *v.ASPECT)
    _in("f", col["f"], -v.SKEW, v.SKEW)
    for k, lim in (
        ("vx", v.SPEED),
        ("vy", v.SPEED),
        ("omega", v.SPIN),
        ("x", v.POSITION),
        ("y", v.POSITION),
    ):
        _in(k, col[k], -lim, lim)
    for k in ("xi_c", "eta_c", "angle", "phi"):
        _check(k, col[k], np.isfinite(col[k]), "finite")
    inertia = col["moment_of_inertia"]
    plate = col["mass"] * (col["a"] ** 2 + col["b"] ** 2) / 4
    inertia = np.where(np.isnan(inertia), plate, inertia)
    _check("moment_of_inertia", inertia, np.isfinite(inertia) & (inertia > 0), "finite and > 0")
    _in(
        "I/(m a^2) (moment_of_inertia / (mass a^2))",
        inertia / (col["mass"] * col["a"] ** 2),
        *v.INERTIA_RATIO,
    )
    is_lin = col["law"] == 1
    core = (col["xi_c"] / col["a"]) ** 2 + (col["eta_c"] / col["b"]) ** 2
    _check(
        "xi_c, eta_c (core measure (xi_c/a)^2 + (eta_c/b)^2)",
        core,
        ~is_lin | (core <= 1.0 / 16.0 * (1 + 1e-12)),
        "[0, 0.0625]",
    )
    return col, inertia


# ------------------------------------------------------------------------------------------
# footprint sweeps: patch parameters per case (the keys of the TOML [patch] table)
# ------------------------------------------------------------------------------------------
#: footprint shapes a sweep may fix, and the sweep keys each takes (``vertices`` fixed only)
SHAPE_KEYS = {
    "disk": ("radius",),
    "annulus": ("outer_radius", "inner_radius", "ring_width", "radius_ratio"),
    "rectangle": ("length", "width", "aspect"),
    "polygon": ("vertices", "scale"),
    "pads": ("pad_shape", "n_pads", "pad_spacing", "pad_radius", "pad_length", "pad_width"),
}
#: most pads of a ``shape = "pads"`` sweep
MAX_PADS = 64


def _need(cols: dict, shape: str, key: str) -> np.ndarray:
    if key not in cols:
        valid = ", ".join(SHAPE_KEYS.get(shape, ()))
        raise ValueError(
            f"shape {shape!r} needs {key!r} (fix or vary it); valid keys of {shape!r}: {valid}"
        )
    return np.asarray(cols[key], dtype=float)


def _ranged(name, arr, ok, valid):
    with np.errstate(all="ignore"):
        _check(name, arr, np.isfinite(arr) & ok, valid)


def footprint_geometry(shape: str, cols: dict, n: int) -> dict:
    """The geometry columns of ``n`` footprint cases, derived keys filled in.

    ``cols`` holds the sweep keys of :data:`SHAPE_KEYS` given (fixed or varied); the result
    holds every numeric key of the shape: ``annulus`` → ``outer_radius``, ``inner_radius``,
    ``ring_width`` (R − r), ``radius_ratio`` (r/R); ``rectangle`` → ``length``, ``width``,
    ``aspect`` (width/length); ``disk`` → ``radius``; ``polygon`` → ``scale``; ``pads`` →
    ``n_pads``, ``pad_spacing`` and ``pad_radius`` or ``pad_length``, ``pad_width``. Values a
    footprint refuses are left to its constructor (:func:`footprint_patch`); the ranges of
    the derived keys are checked here, naming the key, the first bad case and its value.
    """
    if shape == "disk":
        return {"radius": _need(cols, shape, "radius")}
    if shape == "annulus":
        big = _need(cols, shape, "outer_radius")
        if "ring_width" in cols:
            w = np.asarray(cols["ring_width"], dtype=float)
            _ranged("ring_width", w, (w > 0) & (w <= big), "(0, outer_radius]")
            small = np.maximum(big - w, 0.0)
        elif "radius_ratio" in cols:
            q = np.asarray(cols["radius_ratio"], dtype=float)
            _ranged("radius_ratio", q, (q >= 0) & (q < 1), "[0, 1)")
            small = q * big
        else:
            small = _need(cols, shape, "inner_radius")
        with np.errstate(all="ignore"):
            return {
                "outer_radius": big,
                "inner_radius": small,
                "ring_width": big - small,
                "radius_ratio": small / big,
            }
    if shape == "rectangle":
        length = _need(cols, shape, "length")
        if "aspect" in cols:
            q = np.asarray(cols["aspect"], dtype=float)
            _ranged("aspect", q, q > 0, "> 0 (width/length; the rectangle checks the rest)")
            width = q * length
        else:
            width = _need(cols, shape, "width")
        with np.errstate(all="ignore"):
            return {"length": length, "width": width, "aspect": width / length}
    if shape == "polygon":
        s = np.asarray(cols.get("scale", np.ones(n)), dtype=float)
        _ranged("scale", s, s > 0, "> 0")
        return {"scale": np.broadcast_to(s, (n,)).copy()}
    if shape == "pads":
        k = np.asarray(cols.get("n_pads", np.full(n, 2.0)), dtype=float)
        _ranged(
            "n_pads",
            k,
            (k == np.round(k)) & (k >= 2) & (k <= MAX_PADS),
            f"integer in [2, {MAX_PADS}]",
        )
        sp = _need(cols, shape, "pad_spacing")
        _ranged("pad_spacing", sp, sp > 0, "> 0")
        out = {"n_pads": np.broadcast_to(k, (n,)).copy(), "pad_spacing": sp}
        if str(np.asarray(cols.get("pad_shape", ["disk"]))[0]) == "rectangle":
            out["pad_length"] = _need(cols, shape, "pad_length")
            out["pad_width"] = _need(cols, shape, "pad_width")
        else:
            out["pad_radius"] = _need(cols, shape, "pad_radius")
        return out
    raise ValueError(
        f"shape = {shape!r} is invalid; valid values: ellipse, " + ", ".join(SHAPE_KEYS)
    )


def footprint_patch(shape: str, geo: dict, vertices=None, pad_shape: str = "disk"):
    """One footprint from one case's geometry values (a row of :func:`footprint_geometry`).

    ``pads``: ``n_pads`` equal pads (disks of ``pad_radius`` or rectangles ``pad_length`` ×
    ``pad_width``, length along ξ, unrotated) whose centres lie on a circle about the origin,
    the first on the η axis, neighbours ``pad_spacing`` apart (two pads: at η = ±spacing/2,
    runners side by side).
    """
    if shape == "disk":
        return Disk(geo["radius"])
    if shape == "annulus":
        return Annulus(geo["inner_radius"], geo["outer_radius"])
    if shape == "rectangle":
        return Rectangle(geo["length"], geo["width"])
    if shape == "polygon":
        s = geo["scale"]
        return Polygon(tuple((s * float(x), s * float(y)) for x, y in vertices))
    k = int(geo["n_pads"])
    rho = geo["pad_spacing"] / (2.0 * math.sin(math.pi / k))
    # on the axes exactly (cos(pi/2) is 6e-17, not 0: a layout symmetric about an axis
    # stays symmetric to the last bit)
    centres = [
        tuple(
            0.0 if abs(c) < 1e-12 * rho else c
            for c in (
                rho * math.cos(math.pi / 2 + 2 * math.pi * i / k),
                rho * math.sin(math.pi / 2 + 2 * math.pi * i / k),
            )
        )
        for i in range(k)
    ]
    if pad_shape == "rectangle":
        return Pads(
            tuple(Rectangle(geo["pad_length"], geo["pad_width"], centre=c) for c in centres)
        )
    return Pads(tuple(Disk(geo["pad_radius"], centre=c) for c in centres))
