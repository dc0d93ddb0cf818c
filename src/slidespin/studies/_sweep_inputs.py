"""The cases of a sweep as the inputs of the engines: parameter columns (a block of
:meth:`SweepSpec.parameters <slidespin.studies.sweep_spec.SweepSpec.parameters>`) to the
validated fields of :func:`~slidespin.motion.batch.simulate_cases` (ellipse stop sweeps), or
to bodies, friction tensors, states and load columns (footprints, statics and loaded sweeps),
with the input columns of the chunk file.

Each distinct patch is built once per block and each distinct tensor once, so that the batch
engine shares their compiled arrays: every case equals a single :func:`slidespin.simulate`
call on the same body, to the last bit.

Every refusal names the parameter as the spec spells it (``I_star``, ``v0``, ``theta0_deg``,
``mu``, not the engine's ``moment_of_inertia``, ``vx`` or ``fy``), the case number, the value
and the valid range. Statics and loaded sweeps are also checked for what would make a case
fail later (an applied load too large for the engines, :func:`check_loads`), so that a sweep
refuses before it writes anything rather than stopping mid-run.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import pressure_law_from_name
from slidespin.contact.static_set import check_anisotropy
from slidespin.contact.statics import WRENCH_MAX
from slidespin.motion._cases import footprint_geometry, footprint_patch, validated_columns
from slidespin.studies.sweep_loads import LOAD_COLUMNS, load_columns
from slidespin.studies.sweep_spec import PARAMETERS, SweepError, SweepSpec


def _bad(name: str, arr, ok, valid: str, ids) -> None:
    """Refuse the first case where ``ok`` is false, naming ``name``, its case number (from
    ``ids``), the value and the valid range."""
    ok = np.asarray(ok, dtype=bool)
    if not ok.all():
        i = int(np.flatnonzero(~ok)[0])
        val = arr[i].item() if isinstance(arr[i], np.generic) else arr[i]
        raise SweepError(f"{name} = {val!r} (case {int(ids[i])}) is invalid; valid range: {valid}")


def _within(name: str, arr, lo: float, hi: float, ids, unit: str = "") -> np.ndarray:
    """``arr`` as floats, every one finite and in [lo, hi] (else refused, naming ``name``)."""
    arr = np.asarray(arr, dtype=float)
    with np.errstate(invalid="ignore"):
        ok = np.isfinite(arr) & (arr >= lo) & (arr <= hi)
    u = f" {unit}" if unit else ""
    _bad(name, arr, ok, f"[{lo:g}, {hi:g}]{u}", ids)
    return arr


def _finite(name: str, arr, ids) -> np.ndarray:
    arr = np.asarray(arr, dtype=float)
    _bad(name, arr, np.isfinite(arr), "any finite real number", ids)
    return arr


def _initial_columns(cols: dict, ids) -> dict:
    """The start state of the cases (x, y, phi, vx, vy, omega), each spec key checked under
    its own name: ``x0``, ``y0``, ``phi0`` | ``phi0_deg``, ``omega0``, and ``v0`` with
    ``theta0`` | ``theta0_deg``, or ``vx0``, ``vy0``."""
    n = ids.size

    def get(k):
        return cols[k] if k in cols else np.full(n, PARAMETERS[k] or 0.0, dtype=float)

    out = {
        "x": _within("x0", get("x0"), -v.POSITION, v.POSITION, ids, "m"),
        "y": _within("y0", get("y0"), -v.POSITION, v.POSITION, ids, "m"),
    }
    if "phi0_deg" in cols:
        out["phi"] = np.radians(_finite("phi0_deg", cols["phi0_deg"], ids))
    else:
        out["phi"] = _finite("phi0", get("phi0"), ids)
    if "vx0" in cols or "vy0" in cols:
        out["vx"] = _within("vx0", get("vx0"), -v.SPEED, v.SPEED, ids, "m/s")
        out["vy"] = _within("vy0", get("vy0"), -v.SPEED, v.SPEED, ids, "m/s")
    else:
        speed = _within("v0", get("v0"), 0.0, v.SPEED, ids, "m/s")
        if "theta0_deg" in cols:
            th = np.radians(_finite("theta0_deg", cols["theta0_deg"], ids))
        else:
            th = _finite("theta0", get("theta0"), ids)
        out["vx"] = speed * np.cos(th)
        out["vy"] = speed * np.sin(th)
    out["omega"] = _within("omega0", get("omega0"), -v.SPIN, v.SPIN, ids, "rad/s")
    return out


def _check_inertia_ratio(cols: dict, ids) -> None:
    """``I_star`` in its own range, named as the spec spells it (not as the moment of inertia
    it becomes)."""
    if "I_star" in cols:
        _within("I_star", cols["I_star"], *v.INERTIA_RATIO, ids)


#: engine fields computed from other spec keys: (the spec keys, how)
_DERIVED = {
    "fy": (("mu",), "fy = fx + mu"),
    "b": (("e", "aspect"), "b = a sqrt(1 - e^2) or a aspect"),
    "b/a": (("e", "aspect"), "b/a = sqrt(1 - e^2) or aspect"),
    "moment_of_inertia": (("I_star",), "moment_of_inertia = I_star mass a^2"),
    "I/(m a^2) (moment_of_inertia / (mass a^2))": (("I_star",), "I_star"),
}


def _engine_check(fields: dict, cols: dict, ids) -> None:
    """:func:`~slidespin.motion._cases.validated_columns`, its message given the case number
    (not the row of the block) and, for a field computed from other spec keys, those keys and
    their values."""
    try:
        validated_columns(fields)
    except ValueError as exc:
        msg = str(exc)
        m = re.search(r"\(case (\d+)\)", msg)
        row = int(m.group(1)) if m else None
        if m and row is not None and row < ids.size:
            msg = msg.replace(m.group(0), f"(case {int(ids[row])})", 1)
        name = msg.split(" = ", 1)[0]
        if name in _DERIVED and row is not None and row < ids.size:
            keys, how = _DERIVED[name]
            given = [f"{k} = {np.asarray(cols[k])[row].item()!r}" for k in keys if k in cols]
            if given:
                msg += f" ({how}, with {', '.join(given)})"
        raise SweepError(msg) from None


def _case_fields(cols: dict) -> dict:
    """Map sweep parameters to :func:`~slidespin.motion.batch.simulate_cases` fields (validated
    here, naming the spec's keys, and there)."""
    ids = np.asarray(cols["case_id"])
    n = ids.size

    def get(k):
        if k in cols:
            return cols[k]
        return np.full(n, PARAMETERS[k], dtype=object if isinstance(PARAMETERS[k], str) else float)

    a = get("a").astype(float)
    if "b" in cols:
        b = cols["b"].astype(float)
    elif "e" in cols:
        e = cols["e"].astype(float)
        with np.errstate(invalid="ignore"):
            _bad("e", e, (e >= 0) & (e < 1), "[0, 1)", ids)
        b = a * np.sqrt(1.0 - e * e)
    elif "aspect" in cols:
        b = a * _within("aspect", cols["aspect"], *v.ASPECT, ids)
    else:
        b = a
    fx = get("fx").astype(float)
    fy = cols["fy"].astype(float) if "fy" in cols else fx + cols["mu"].astype(float)
    mass = get("mass").astype(float)
    _check_inertia_ratio(cols, ids)
    if "I_star" in cols:
        inertia = cols["I_star"].astype(float) * mass * a * a
    elif "moment_of_inertia" in cols:
        inertia = cols["moment_of_inertia"].astype(float)
    else:
        inertia = mass * (a * a + b * b) / 4.0
    start = _initial_columns(cols, ids)
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
        **start,
    )
    _engine_check(fields, cols, ids)
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
    """Column ``k`` of the cases, or its default from
    :data:`~slidespin.studies.sweep_spec.PARAMETERS`."""
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
        _check_inertia_ratio(cols, cols["case_id"])
        i_star = cols["I_star"].astype(float) if "I_star" in cols else None
    ids = np.asarray(cols["case_id"])
    start = _initial_columns(cols, ids)
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
        **start,
    )
    if shape != "ellipse":
        # the ranges of the batch engine (speed, spin, position, g, coefficients, I*), with
        # the footprint's length unit in the place of a (its own pressure check is the
        # Body's: the ellipse's core condition of the linear law does not apply)
        unit = np.array([b.length_unit for b in bodies])
        _engine_check(
            {
                **{k: fields[k] for k in fields if k != "law"},
                "a": unit,
                "b": unit,
                "law": "uniform",
            },
            cols,
            ids,
        )
        table.update(_common_table(fields, unit))
    states = np.column_stack([fields[k] for k in ("x", "y", "phi", "vx", "vy", "omega")])
    loads = None
    if spec.mode != "stop":
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
        given = set(spec.data.get("fixed", {})) | set(spec.data.get("vary", {}))
        check_loads(spec.mode, bodies, states, fields["g"], loads, given, ids)
        for k in LOAD_COLUMNS:
            table[k] = loads[k].astype(str) if loads[k].dtype == object else loads[k]
    return _Inputs(table, bodies, frictions, states, fields["g"], loads)


def check_loads(mode: str, bodies, states, g, loads: dict, given: set, ids) -> None:
    """Refuse, before any work, the cases whose applied load the engines would refuse mid-run.

    ``compute = "statics"`` judges the applied wrench per unit normal load, (load + m g sin α d,
    torque / ℓ) / (m g cos α), as :func:`slidespin.contact.statics.load_factor` does (the tilt's
    pull included, the normal load scaled by cos α); ``compute = "loaded"`` the load alone,
    (load, torque / ℓ) / (m g), as the stick-slip engine does at every step (a load in the body
    frame turns with the body: its magnitude is judged). Both allow up to
    :data:`slidespin.contact.statics.WRENCH_MAX` (10⁶) in these units.
    """
    load_keys = [k for k in ("load_fx", "load_fy", "load_torque") if k in given]
    tilt_keys = [k for k in ("incline_angle", "incline_angle_deg") if k in given]
    if not load_keys and not (mode == "statics" and tilt_keys):
        return
    mass = np.array([b.mass for b in bodies])
    ell = np.array([b.length_unit for b in bodies])
    mg = mass * np.asarray(g, dtype=float)
    qx, qy, torque = (
        np.asarray(loads[k], dtype=float) for k in ("load_fx", "load_fy", "load_torque")
    )
    if not load_keys:
        qx = qy = torque = np.zeros(mass.size)
    body = np.asarray(loads["load_frame"]).astype(str) == "body"
    with np.errstate(all="ignore"):
        if mode == "statics":
            phi = states[:, 2]
            c, s = np.where(body, np.cos(phi), 1.0), np.where(body, np.sin(phi), 0.0)
            fx, fy = c * qx - s * qy, s * qx + c * qy
            if tilt_keys:
                alpha, down = loads["incline_angle"], loads["incline_downhill"]
                pull = mg * np.sin(alpha)
                fx, fy = fx + pull * np.cos(down), fy + pull * np.sin(down)
                normal = mg * np.cos(alpha)
            else:
                normal = mg
            size = np.hypot(np.hypot(fx / normal, fy / normal), torque / (normal * ell))
            what = "|(load + m g sin α d, torque/ℓ)| / (m g cos α)"
        else:
            force = np.where(body, np.hypot(qx, qy), np.maximum(np.abs(qx), np.abs(qy)))
            size = np.maximum(force, np.abs(torque) / ell) / mg
            what = "max(|force|, |torque|/ℓ) / (m g)"
        ok = size <= WRENCH_MAX
    if ok.all():
        return
    i = int(np.flatnonzero(~ok)[0])
    keys = load_keys + (tilt_keys if mode == "statics" else [])
    values = ", ".join(
        f"{k} = {np.asarray(loads[k])[i].item()!r}" if k in loads else k for k in keys
    )
    raise SweepError(
        f"case {int(ids[i])}: the applied load ({values}) is {float(size[i]):.3g} in units of "
        f"the weight, {what} with m g = {float(mg[i]):.6g} N and ℓ = {float(ell[i]):.6g} m; "
        f"valid range: at most {WRENCH_MAX:g} (compute = {mode!r} cannot resolve a larger load)"
    )


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
        out[_RENAMED.get(k, k)] = val.astype(str) if val.dtype == object else val
    out["I_star"] = out["moment_of_inertia"] / (out["mass"] * out["a"] ** 2)
    out["mu"] = out["fy"] - out["fx"]
    out["aspect"] = out["b"] / out["a"]
    out["v0"] = np.hypot(out["vx0"], out["vy0"])
    out["theta0"] = np.arctan2(out["vy0"], out["vx0"])
    return out
