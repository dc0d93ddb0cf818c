"""Sweeps over loads and tilt (issue #13 item 4): statics and loaded runs per case.

Truth: the closed forms of a block on a slope (it holds iff tan α ≤ μ, else slides with
a = g (sin α − μ cos α); with an orthotropic tensor and the slope along a principal axis, that
axis' coefficient), of a disk under a push (holds iff P ≤ μ m g) and a torque (iff
T ≤ 2/3 μ m g R, uniform pressure), and the messages of bad keys.
"""

from __future__ import annotations

import concurrent.futures as cf
import math
from pathlib import Path

import numpy as np
import pytest

from slidespin.studies.sweep import SweepResult, sweep
from slidespin.studies.sweep_parse import load_spec
from slidespin.studies.sweep_read import read_sweep, split_unconverged
from slidespin.studies.sweep_spec import SweepError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
G = 9.81


def spec_of(fixed, vary, compute="statics", chunk_size=6):
    base = {"a": 0.05, "e": 0.6, "mass": 2.0}
    base.update(fixed)
    return {
        "name": "loads",
        "kind": "grid",
        "chunk_size": chunk_size,
        "compute": compute,
        "fixed": base,
        "vary": vary,
    }


def run(spec, tmp_path, name="out", **kw):
    res = sweep(spec, tmp_path / name, progress=False, **kw)
    return res, read_sweep(tmp_path / name, include_unconverged=True)


def same(x, y) -> bool:
    x, y = np.asarray(x), np.asarray(y)
    if x.dtype.kind == "f":
        return np.array_equal(x, y, equal_nan=True)
    return np.array_equal(x.astype(str), y.astype(str))


# ------------------------------------------------------------------------------- statics
def test_isotropic_threshold_is_atan_mu(tmp_path):
    spec = spec_of(
        {"mu": 0.0},
        {
            "fx": [0.1, 0.3, 0.8],
            "law": ["uniform", "hertz", "linear"],
            "incline_downhill": [0.0, 2.0],
            "phi0": [0.0, 0.7],
        },
    )
    spec["fixed"]["xi_c"] = 0.005
    res, t = run(spec, tmp_path)
    assert res.status_counts == {"ok": 36}
    assert np.allclose(t["critical_tilt"], np.arctan(t["fx"]), rtol=0, atol=1e-10)
    assert np.allclose(t["critical_tilt_deg"], np.degrees(np.arctan(t["fx"])), rtol=0, atol=1e-8)


def test_orthotropic_threshold_along_a_principal_axis(tmp_path):
    """fx along X, fy along Y (plane frame): the slope down X holds to atan fx, down Y to
    atan fy; a body-frame tensor turned with the body by φ0 = π/2 swaps them."""
    spec = spec_of(
        {"fx": 0.3},
        {
            "fy": [0.3, 0.45, 0.7],
            "incline_downhill": [0.0, math.pi / 2],
            "frame": ["plane", "body"],
            "phi0": [0.0, math.pi / 2],
        },
    )
    _, t = run(spec, tmp_path)
    along_x = np.isclose(np.cos(t["incline_downhill"]), 1.0)
    turned = (t["frame"] == "body") & np.isclose(t["phi0"], math.pi / 2)
    coef = np.where(along_x ^ turned, t["fx"], t["fy"])
    assert np.allclose(t["critical_tilt"], np.arctan(coef), rtol=0, atol=1e-9)


def test_block_on_a_slope_sticks_iff_tan_alpha_below_mu(tmp_path):
    mu = 0.4
    deg = [5.0, 15.0, 21.0, 22.5, 25.0, 40.0, 60.0]  # atan 0.4 = 21.80°
    spec = spec_of(
        {"fx": mu, "mu": 0.0}, {"incline_angle_deg": deg, "law": ["uniform", "boussinesq"]}
    )
    res, t = run(spec, tmp_path)
    sticks = np.tan(np.radians(t["incline_angle_deg"])) <= mu
    assert np.array_equal(t["ending"] == "sticks", sticks)
    assert res.ending_counts == {"sticks": int(sticks.sum()), "slides": int((~sticks).sum())}
    # λ* of the slope's pull m g sin α against C scaled by cos α: μ / tan α
    assert np.allclose(t["load_factor"], mu / np.tan(t["incline_angle"]), rtol=1e-9, atol=0)


def test_push_and_torque_thresholds_of_a_disk(tmp_path):
    mu, m, R = 0.3, 2.0, 0.05
    spec = spec_of(
        {"e": 0.0, "fx": mu, "mu": 0.0, "mass": m},
        {"load_fx": [0.0, 2.0, 5.0, 8.0], "load_torque": [0.0, 0.05, 0.2]},
    )
    _, t = run(spec, tmp_path)
    P, T = t["load_fx"], t["load_torque"]
    push = np.where(P == 0, np.inf, mu * m * G / np.where(P == 0, 1.0, P))
    twist = np.where(T == 0, np.inf, 2 / 3 * mu * m * G * R / np.where(T == 0, 1.0, T))
    only_p, only_t = T == 0, P == 0
    assert np.allclose(t["load_factor"][only_p], push[only_p], rtol=1e-9, atol=0)
    assert np.allclose(
        t["load_factor"][only_t & (T > 0)], twist[only_t & (T > 0)], rtol=1e-9, atol=0
    )
    assert np.isinf(t["load_factor"][(P == 0) & (T == 0)]).all()
    # a push and a torque together are held less than either alone
    both = (P > 0) & (T > 0)
    assert np.all(t["load_factor"][both] < np.minimum(push, twist)[both])
    assert np.array_equal(t["ending"] == "sticks", t["load_factor"] >= 1.0)


def test_tilt_example(tmp_path):
    res, t = run(str(EXAMPLES / "sweep_tilt.toml"), tmp_path)
    assert res.n_cases == 98 and res.status_counts == {"ok": 98}
    assert np.allclose(t["critical_tilt"], np.arctan(t["fy"]), rtol=0, atol=1e-9)
    sticks = np.tan(t["incline_angle"]) <= t["fy"]
    assert np.array_equal(t["ending"] == "sticks", sticks)


# ------------------------------------------------------------------------------- loaded runs
def test_loaded_slope_slides_with_the_closed_form_acceleration(tmp_path):
    mu, t_end = 0.3, 0.4
    deg = [10.0, 15.0, 20.0, 30.0]  # atan 0.3 = 16.70°
    spec = spec_of(
        {"fx": mu, "mu": 0.0, "t_end": t_end},
        {"incline_angle_deg": deg, "incline_downhill": [0.0, 2.5]},
        compute="loaded",
        chunk_size=3,
    )
    res, t = run(spec, tmp_path)
    assert res.status_counts == {"ok": 8}
    a = np.radians(t["incline_angle_deg"])
    acc = G * (np.sin(a) - mu * np.cos(a))
    holds = acc <= 0
    assert np.all(t["ending"][holds] == "at_rest_throughout")
    assert np.all(t["speed_end"][holds] == 0.0) and np.all(t["n_slip"][holds] == 0)
    assert np.all(t["ending"][~holds] == "moving_at_t_end")
    assert np.allclose(t["speed_end"][~holds], acc[~holds] * t_end, rtol=1e-8, atol=0)
    d = np.hypot(t["x_end"], t["y_end"])
    assert np.allclose(d[~holds], 0.5 * acc[~holds] * t_end**2, rtol=1e-8, atol=0)
    heading = np.arctan2(t["y_end"][~holds], t["x_end"][~holds])
    assert np.allclose(heading, t["incline_downhill"][~holds], atol=1e-9)
    assert np.allclose(t["t_final"], t_end, rtol=1e-12, atol=0)
    assert np.all(t["energy_error"] < 1e-9)


def test_loaded_orthotropic_slope_uses_the_coefficient_along_it(tmp_path):
    fx, fy, alpha, t_end = 0.2, 0.5, 0.4, 0.3  # tan 0.4 = 0.42: slides down X, holds down Y
    spec = spec_of(
        {"fx": fx, "fy": fy, "incline_angle": alpha, "t_end": t_end},
        {"incline_downhill": [0.0, math.pi / 2]},
        compute="loaded",
    )
    _, t = run(spec, tmp_path)
    assert list(t["ending"]) == ["moving_at_t_end", "at_rest_throughout"]
    acc = G * (math.sin(alpha) - fx * math.cos(alpha))
    assert t["speed_end"][0] == pytest.approx(acc * t_end, rel=1e-8)
    assert t["speed_end"][1] == 0.0


def test_loaded_sweep_resumes_and_runs_on_an_executor(tmp_path):
    spec = spec_of(
        {"fx": 0.3, "mu": 0.1, "t_end": 0.3, "omega0": 3.0},
        {"incline_angle_deg": [5.0, 25.0], "load_fy": [0.0, 4.0, 9.0]},
        compute="loaded",
        chunk_size=2,
    )
    _, first = run(spec, tmp_path)
    assert set(first["status"]) == {"ok"}
    (tmp_path / "out" / "chunks" / "chunk-000002.parquet").unlink()
    (tmp_path / "out" / "chunks" / "chunk-000000.parquet").write_bytes(b"damaged")
    res = sweep(spec, tmp_path / "out", resume=True, progress=False)
    assert res.chunks_computed == 2 and res.chunks_repaired == 1
    again = read_sweep(tmp_path / "out", include_unconverged=True)
    assert list(first) == list(again) and all(same(first[k], again[k]) for k in first)
    with cf.ThreadPoolExecutor(2) as ex:
        _, remote = run(spec, tmp_path, "remote", executor=ex)
    assert all(same(first[k], remote[k]) for k in first)


def test_loaded_unconverged_statuses_are_left_out():
    table = {
        "case_id": np.arange(4),
        "status": np.array(["ok", "max_phases", "no_onset", "ok"], dtype=object),
    }
    kept, left = split_unconverged(table)
    assert list(kept["case_id"]) == [0, 3] and left == {"max_phases": 1, "no_onset": 1}
    res = SweepResult(Path("."), 4, 1, 1, 4, 1.0, {"ok": 2, "max_phases": 1, "no_onset": 1})
    assert res.n_unconverged == 2


# ------------------------------------------------------------------------------- bad keys
@pytest.mark.parametrize(
    "compute, fixed, vary, words",
    [
        (
            "statics",
            {},
            {"incline_angle_deg": [10.0, 95.0]},
            ["incline_angle_deg", "95.0", "[0, 90)"],
        ),
        ("statics", {}, {"incline_angle": [0.1, 2.0]}, ["incline_angle", "2.0", "[0, 1.57"]),
        (
            "statics",
            {"incline_angle": 0.1, "incline_angle_deg": 5.0},
            {},
            ["at most one of", "incline_angle_deg"],
        ),
        ("statics", {"load_frame": "world"}, {}, ["load_frame", "world", "plane, body"]),
        ("statics", {}, {"load_fx": [1.0, float("nan")]}, ["load_fx", "nan", "finite"]),
        ("statics", {"t_end": 1.0}, {}, ["t_end", "loaded"]),
        ("loaded", {}, {"incline_angle": [0.1]}, ["t_end", "compute = 'loaded'"]),
        ("loaded", {"t_end": -1.0}, {}, ["t_end", "-1.0", "(0, 1e9]"]),
        ("stop", {"load_torque": 1.0}, {}, ["load_torque", "compute", "statics", "loaded"]),
        ("dynamic", {}, {}, ["compute", "dynamic", "stop, statics, loaded"]),
        (
            "loaded",
            {"fx": 0.001, "mu": 0.999, "e": 0.9987, "t_end": 1.0},
            {},
            ["case 0", "anisotropy", "elongation", "valid range: [1, 10000]"],
        ),
    ],
)
def test_bad_load_keys_are_named(compute, fixed, vary, words):
    spec = spec_of({"fx": 0.3, "mu": 0.0, **fixed}, vary, compute=compute)
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    msg = str(err.value)
    for w in words:
        assert w in msg, (w, msg)


def test_loaded_footprint_sweep_on_a_dask_cluster_equals_local(tmp_path):
    """The loaded runs go through Dask (one chunk per task) and give the local numbers; the
    ring on a slope holds below atan μ (the footprint's statics) and slides above it."""
    distributed = pytest.importorskip("distributed")
    spec = spec_of(
        {
            "shape": "annulus",
            "outer_radius": 0.05,
            "ring_width": 0.01,
            "fx": 0.3,
            "mu": 0.0,
            "t_end": 0.3,
        },
        {"incline_angle_deg": [10.0, 30.0], "load_torque": [0.0, 0.05]},
        compute="loaded",
        chunk_size=2,
    )
    for k in ("a", "e"):
        spec["fixed"].pop(k)
    _, local = run(spec, tmp_path, "local")
    with distributed.LocalCluster(
        n_workers=1, threads_per_worker=1, host="127.0.0.1", dashboard_address=None, processes=True
    ) as cluster:
        with distributed.Client(cluster) as client:
            _, remote = run(spec, tmp_path, "dask", executor=client)
    assert list(local) == list(remote) and all(same(local[k], remote[k]) for k in local)
    flat = local["load_torque"] == 0.0
    a = np.radians(local["incline_angle_deg"])
    assert list(local["ending"][flat]) == ["at_rest_throughout", "moving_at_t_end"]
    acc = G * (np.sin(a) - 0.3 * np.cos(a))
    assert local["speed_end"][flat][1] == pytest.approx(acc[flat][1] * 0.3, rel=1e-8)


@pytest.mark.parametrize(
    "patch",
    [
        {"shape": "annulus", "outer_radius": 0.05, "radius_ratio": 0.8},
        {"shape": "rectangle", "length": 0.1, "aspect": 0.2},
        {"shape": "pads", "pad_radius": 0.01, "pad_spacing": 0.1, "n_pads": 3},
    ],
)
def test_footprint_threshold_along_a_principal_axis(tmp_path, patch):
    """α_c = atan of the coefficient along the slope, whatever the footprint."""
    spec = spec_of(
        {**patch, "fx": 0.25}, {"fy": [0.25, 0.6], "incline_downhill": [0.0, math.pi / 2]}
    )
    for k in ("a", "e"):
        spec["fixed"].pop(k)
    _, t = run(spec, tmp_path)
    along_x = np.isclose(np.cos(t["incline_downhill"]), 1.0)
    coef = np.where(along_x, t["fx"], t["fy"])
    assert np.allclose(t["critical_tilt"], np.arctan(coef), rtol=0, atol=1e-9)


def test_a_case_failing_mid_sweep_is_named_and_the_sweep_resumes(tmp_path, monkeypatch):
    import slidespin.contact.statics as statics

    real = statics.critical_tilt

    def flaky(body, friction, downhill=0.0, phi=0.0):
        if friction.fx > 0.5:
            raise RuntimeError("statics: the wrench quadrature missed its error target")
        return real(body, friction, downhill, phi)

    spec = spec_of({"mu": 0.0}, {"fx": [0.2, 0.3, 0.4, 0.6]}, chunk_size=2)
    monkeypatch.setattr(statics, "critical_tilt", flaky)
    with pytest.raises(SweepError, match=r"case 3: RuntimeError: statics: the wrench"):
        sweep(spec, tmp_path / "out", progress=False)
    monkeypatch.setattr(statics, "critical_tilt", real)
    res = sweep(spec, tmp_path / "out", resume=True, progress=False)
    assert res.chunks_computed == 1 and res.status_counts == {"ok": 4}
