"""The cases of a sweep as the inputs of the engines: parameter columns (a block of
:meth:`SweepSpec.parameters <slidespin.studies.sweep_spec.SweepSpec.parameters>`) to the
validated fields of :func:`~slidespin.motion.batch.simulate_cases` (ellipse stop sweeps), or
to bodies, friction tensors, states and load columns (footprints, statics and loaded sweeps),
with the input columns of the chunk file.

Each distinct patch is built once per block and each distinct tensor once, so that the batch
engine shares their compiled arrays: every case equals a single :func:`slidespin.simulate`
call on the same body, to the last bit.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import pressure_law_from_name
from slidespin.contact.static_set import check_anisotropy
from slidespin.motion._cases import footprint_geometry, footprint_patch, validated_columns
from slidespin.studies.sweep_loads import LOAD_COLUMNS, load_columns
from slidespin.studies.sweep_spec import PARAMETERS, SweepError, SweepSpec


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
