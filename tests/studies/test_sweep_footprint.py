"""Sweeps over patch parameters (issue #12 item 4) and a sweep as a pandas table (#15 item 4).

Truth: single :func:`slidespin.motion.simulate` calls on bodies built by hand from the footprint
classes (the sweep must give the same numbers, to the last bit), the pure-spin closed form of
a uniform ring, the thin-ring limit β* → R, pure translation of any footprint (t = v0/(μ g),
distance v0²/(2 μ g)), and the messages of bad keys.
"""

from __future__ import annotations

import concurrent.futures as cf
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from slidespin import (
    Annulus,
    Body,
    Disk,
    FrictionTensor,
    LinearPressure,
    Pads,
    Polygon,
    Rectangle,
    State,
    UniformPressure,
)
from slidespin.motion.simulate import simulate
from slidespin.studies.sweep import sweep
from slidespin.studies.sweep_chunk import CHUNK_COLUMNS, chunk_columns
from slidespin.studies.sweep_parse import load_spec
from slidespin.studies.sweep_read import read_sweep, to_pandas
from slidespin.studies.sweep_spec import SweepError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
G = 9.81


def spec_of(fixed, vary, chunk_size=5, **top):
    base = {"fx": 0.3, "mass": 1.0}
    base.update(fixed)
    return {
        "name": "fp",
        "kind": "grid",
        "chunk_size": chunk_size,
        "fixed": base,
        "vary": vary,
        **top,
    }


def run(spec, tmp_path, name="out", **kw):
    res = sweep(spec, tmp_path / name, progress=False, **kw)
    return res, read_sweep(tmp_path / name, include_unconverged=True)


def same(x, y, rtol=0.0) -> bool:
    x, y = np.asarray(x), np.asarray(y)
    if x.dtype.kind == "f" or y.dtype.kind == "f":
        if rtol:
            return np.allclose(x.astype(float), y.astype(float), rtol=rtol, atol=0, equal_nan=True)
        return np.array_equal(x.astype(float), y.astype(float), equal_nan=True)
    return np.array_equal(x.astype(str), y.astype(str))


def check_against_simulate(table, patch_of, law_of=lambda i: UniformPressure(), rtol=0.0):
    """Every row equals a single simulate() call on a Body built by hand, to the last bit
    (``rtol`` > 0 where the hand-built patch rounds its coordinates differently)."""
    n = table["case_id"].size
    assert n > 0
    for i in range(n):
        body = Body(
            patch_of(i), law_of(i), float(table["mass"][i]), float(table["moment_of_inertia"][i])
        )
        fr = FrictionTensor(
            float(table["fx"][i]),
            float(table["fy"][i]),
            float(table["f"][i]),
            str(table["frame"][i]),
            float(table["angle"][i]),
        )
        st = State(
            float(table["x0"][i]),
            float(table["y0"][i]),
            float(table["phi0"][i]),
            float(table["vx0"][i]),
            float(table["vy0"][i]),
            float(table["omega0"][i]),
        )
        tr = simulate(body, fr, st, float(table["g"][i]))
        got = {k: table[k][i] for k in ("t_stop", "beta_stop", "theta_stop", "ending", "status")}
        want = {
            "t_stop": tr.t_stop,
            "beta_stop": tr.beta_stop,
            "theta_stop": tr.theta_stop,
            "ending": tr.ending,
            "status": tr.status,
        }
        for k in got:
            assert same(got[k], want[k], rtol), (i, k, got[k], want[k])
        assert same(table["x_stop"][i], tr.stop_state.x, rtol)
        assert same(table["phi_stop"][i], tr.stop_state.phi, rtol)


# ------------------------------------------------------------------------------- rings
def test_ring_sweep_equals_single_simulate_calls(tmp_path):
    spec = spec_of(
        {
            "shape": "annulus",
            "outer_radius": 0.05,
            "v0": 1.0,
            "theta0": 0.4,
            "omega0": 15.0,
            "f": 0.02,
        },
        {"ring_width": [0.05, 0.02, 0.004], "mu": [0.0, 0.15]},
    )
    res, t = run(spec, tmp_path)
    assert res.n_cases == 6 and res.n_chunks == 2
    assert tuple(t) == chunk_columns(load_spec(spec))
    assert np.allclose(t["inner_radius"], 0.05 - np.repeat([0.05, 0.02, 0.004], 2))
    check_against_simulate(t, lambda i: Annulus(float(t["inner_radius"][i]), 0.05))
    # the default inertia is the uniform plate of the ring, m (R² + r²)/2
    assert np.allclose(
        t["moment_of_inertia"], (0.05**2 + t["inner_radius"] ** 2) / 2, rtol=1e-14, atol=0
    )


def test_ring_pure_spin_closed_form(tmp_path):
    """ω̇ = −M/I with M = 2/3 μ m g (R³ − r³)/(R² − r²): t_stop = I ω0 / M."""
    R, mu, w0 = 0.05, 0.3, 10.0
    spec = spec_of(
        {"shape": "annulus", "outer_radius": R, "mu": 0.0, "omega0": w0},
        {"radius_ratio": [0.0, 0.3, 0.7, 0.95], "I_star": [0.4, 1.0]},
    )
    _, t = run(spec, tmp_path)
    r = t["inner_radius"]
    moment = 2.0 / 3.0 * mu * G * (R**3 - r**3) / (R**2 - r**2)
    assert np.all(t["ending"] == "pure_spinning")
    assert np.allclose(t["moment_of_inertia"], t["I_star"] * R**2, rtol=1e-14, atol=0)
    assert np.allclose(t["t_stop"], t["moment_of_inertia"] * w0 / moment, rtol=1e-8, atol=0)


def test_thin_ring_terminal_ratio_tends_to_one(tmp_path):
    R = 0.05
    q = np.array([0.9, 0.99, 0.999, 0.9999])
    spec = spec_of(
        {"shape": "annulus", "outer_radius": R, "mu": 0.0, "v0": 1.0, "omega0": 20.0},
        {"radius_ratio": q.tolist(), "theta0": [0.0, 1.0]},
    )
    _, t = run(spec, tmp_path)
    ratio = t["beta_stop"] / R
    assert np.all(t["ending"] == "mixed")
    err = np.abs(ratio - 1.0)
    assert np.all(err <= np.repeat(1.0 - q, 2))  # O(width/R)
    assert err.max() < 0.1 and err[-1] < 1e-4


def test_zero_hole_ring_is_the_disk(tmp_path):
    ring = spec_of(
        {"shape": "annulus", "outer_radius": 0.05, "inner_radius": 0.0, "v0": 1.0, "omega0": 20.0},
        {"mu": [0.0, 0.1]},
    )
    disk = spec_of({"shape": "disk", "radius": 0.05, "v0": 1.0, "omega0": 20.0}, {"mu": [0.0, 0.1]})
    _, a = run(ring, tmp_path, "ring")
    _, b = run(disk, tmp_path, "disk")
    for k in ("t_stop", "beta_stop", "theta_stop", "x_stop", "y_stop", "phi_stop"):
        assert np.allclose(a[k], b[k], rtol=1e-12, atol=1e-15)
    # the isotropic disk's terminal ratio (Farkas et al. 2003: β* ≈ 0.653 R)
    assert abs(b["beta_stop"][0] / 0.05 - 0.653) < 1e-3


# ------------------------------------------------------------------ rectangles, pads, polygons
def test_rectangle_sweep_equals_single_simulate_calls(tmp_path):
    spec = spec_of(
        {
            "shape": "rectangle",
            "length": 0.1,
            "v0": 0.8,
            "theta0": 1.1,
            "omega0": -12.0,
            "mu": 0.1,
            "angle": 0.3,
        },
        {"aspect": [0.1, 0.5, 1.0], "law": ["uniform", "linear"], "xi_c": [0.0, 0.004]},
    )
    _, t = run(spec, tmp_path)
    assert np.allclose(t["width"], 0.1 * t["aspect"], rtol=1e-15, atol=0)

    def law(i):
        if t["law"][i] == "linear":
            return LinearPressure(float(t["xi_c"][i]), 0.0)
        return UniformPressure()

    check_against_simulate(t, lambda i: Rectangle(0.1, float(t["width"][i])), law)


def test_pads_sweep_equals_hand_built_pads(tmp_path):
    spec = spec_of(
        {
            "shape": "pads",
            "pad_shape": "rectangle",
            "pad_length": 0.3,
            "pad_width": 0.02,
            "v0": 1.0,
            "omega0": 5.0,
            "theta0": 0.2,
            "mu": 0.1,
            "moment_of_inertia": 0.02,
        },
        {"pad_spacing": [0.1, 0.25, 0.4]},
    )
    _, t = run(spec, tmp_path)

    def runners(i):
        s = float(t["pad_spacing"][i])
        return Pads(
            [Rectangle(0.3, 0.02, centre=(0.0, s / 2)), Rectangle(0.3, 0.02, centre=(0.0, -s / 2))]
        )

    check_against_simulate(t, runners)


def test_pads_of_three_feet_equal_hand_built(tmp_path):
    spec = spec_of(
        {"shape": "pads", "pad_radius": 0.01, "n_pads": 3, "v0": 0.5, "omega0": 8.0, "mu": 0.05},
        {"pad_spacing": [0.05, 0.1]},
    )
    _, t = run(spec, tmp_path)

    def feet(i):
        rho = float(t["pad_spacing"][i]) / math.sqrt(3.0)  # side s of an equilateral triangle
        return Pads(
            [
                Disk(
                    0.01,
                    centre=(
                        rho * math.cos(math.pi / 2 + 2 * math.pi * k / 3),
                        rho * math.sin(math.pi / 2 + 2 * math.pi * k / 3),
                    ),
                )
                for k in range(3)
            ]
        )

    for i in range(t["case_id"].size):
        assert Pads(feet(i).patches).area == pytest.approx(3 * math.pi * 1e-4, rel=1e-14)
    # rho = s/sqrt(3) here, s/(2 sin(pi/3)) in the sweep: the centres differ by an ulp
    check_against_simulate(t, feet, rtol=1e-12)


def test_polygon_scale_sweep(tmp_path):
    tri = [[0.0, 0.0], [0.08, 0.0], [0.02, 0.05]]
    spec = spec_of(
        {"shape": "polygon", "vertices": tri, "v0": 0.7, "omega0": -9.0, "mu": 0.12},
        {"scale": [0.5, 1.0, 2.0]},
    )
    _, t = run(spec, tmp_path)

    def poly(i):
        s = float(t["scale"][i])
        return Polygon([(s * x, s * y) for x, y in tri])

    check_against_simulate(t, poly)


@pytest.mark.parametrize(
    "fixed",
    [
        {"shape": "annulus", "outer_radius": 0.05, "radius_ratio": 0.6},
        {"shape": "rectangle", "length": 0.1, "aspect": 0.3},
        {"shape": "pads", "pad_radius": 0.01, "pad_spacing": 0.1, "n_pads": 4},
    ],
)
def test_pure_translation_of_any_footprint(tmp_path, fixed):
    """ω0 = 0, isotropic friction, symmetric footprint: pure sliding in a straight line."""
    v0, mu = 1.2, 0.3
    spec = spec_of({**fixed, "mu": 0.0, "v0": v0}, {"theta0": [0.0, 0.9]})
    _, t = run(spec, tmp_path)
    assert np.all(t["ending"] == "pure_sliding")
    assert np.allclose(t["t_stop"], v0 / (mu * G), rtol=1e-9, atol=0)
    assert np.allclose(t["path_length"], v0**2 / (2 * mu * G), rtol=1e-9, atol=0)
    assert np.allclose(np.arctan2(t["y_stop"], t["x_stop"]), t["theta0"], atol=1e-9)


# ------------------------------------------------------------- machinery: resume, executor
def test_footprint_sweep_resume_repairs_a_damaged_chunk(tmp_path):
    spec = spec_of(
        {"shape": "annulus", "outer_radius": 0.05, "v0": 1.0, "omega0": 10.0},
        {"radius_ratio": [0.0, 0.5, 0.9], "mu": [0.0, 0.1, 0.2]},
        chunk_size=4,
    )
    _, first = run(spec, tmp_path)
    chunk = tmp_path / "out" / "chunks" / "chunk-000001.parquet"
    chunk.write_bytes(b"not parquet")
    res = sweep(spec, tmp_path / "out", resume=True, progress=False)
    assert res.chunks_repaired == 1 and res.chunks_computed == 1
    again = read_sweep(tmp_path / "out", include_unconverged=True)
    assert all(same(first[k], again[k]) for k in first)


def test_footprint_sweep_through_an_executor_is_bit_identical(tmp_path):
    spec = spec_of(
        {"shape": "rectangle", "length": 0.1, "v0": 1.0, "omega0": 10.0},
        {"width": [0.02, 0.05, 0.1], "mu": [0.0, 0.1]},
        chunk_size=2,
    )
    _, local = run(spec, tmp_path, "local")
    with cf.ThreadPoolExecutor(2) as ex:
        _, remote = run(spec, tmp_path, "remote", executor=ex, task_cases=1)
    assert list(local) == list(remote)
    assert all(same(local[k], remote[k]) for k in local)


def test_ellipse_sweeps_keep_their_layout(tmp_path):
    spec = spec_of({"a": 0.05, "e": 0.6, "v0": 1.0, "omega0": 5.0}, {"mu": [0.0, 0.1]})
    assert chunk_columns(load_spec(spec)) == CHUNK_COLUMNS
    _, t = run(spec, tmp_path)
    assert tuple(t) == CHUNK_COLUMNS


# -------------------------------------------------------------------------- bad keys
@pytest.mark.parametrize(
    "fixed, vary, words",
    [
        (
            {"shape": "annulus", "outer_radius": 0.05},
            {"ring_width": [0.01, 0.06]},
            ["ring_width", "0.06", "(0, outer_radius]"],
        ),
        (
            {"shape": "annulus", "outer_radius": 0.05},
            {"radius_ratio": [0.5, 1.0]},
            ["radius_ratio", "1.0", "[0, 1)"],
        ),
        (
            {"shape": "annulus", "outer_radius": 0.05},
            {"inner_radius": [0.01, 0.05]},
            ["outer_radius", "0.05", "valid range", "inner_radius"],
        ),
        (
            {"shape": "annulus", "outer_radius": 0.05, "a": 0.1},
            {},
            ["'a'", "annulus", "valid patch keys", "outer_radius"],
        ),
        ({"shape": "annulus", "outer_radius": 0.05}, {}, ["inner_radius"]),
        (
            {"shape": "annulus", "outer_radius": 0.05, "ring_width": 0.01, "radius_ratio": 0.5},
            {},
            ["at most one of", "ring_width", "radius_ratio"],
        ),
        ({"shape": "hexagon"}, {}, ["shape", "hexagon", "annulus", "rectangle"]),
        ({}, {"shape": ["disk", "annulus"]}, ["'shape'", "cannot be varied"]),
        ({"shape": "rectangle", "length": 0.1}, {"aspect": [0.5, -1.0]}, ["aspect", "-1.0", "> 0"]),
        ({"shape": "rectangle", "length": 0.1, "width": 1e-9}, {}, ["length", "width", "valid"]),
        (
            {"shape": "pads", "pad_radius": 0.01},
            {"pad_spacing": [0.1, 0.015]},
            ["overlap", "pad_spacing = 0.015"],
        ),
        (
            {"shape": "pads", "pad_shape": "rectangle", "pad_radius": 0.01, "pad_spacing": 0.1},
            {},
            ["pad_shape", "rectangle", "'pad_radius'", "pad_length, pad_width"],
        ),
        (
            {"shape": "pads", "pad_radius": 0.01, "pad_spacing": 0.1},
            {"n_pads": [2, 2.5]},
            ["n_pads", "2.5", "integer in [2, 64]"],
        ),
        ({"shape": "polygon", "vertices": [[0, 0], [1, 0]]}, {}, ["vertices", "at least 3 pairs"]),
        (
            {"shape": "polygon", "vertices": [[0, 0], [1, 0], [0, 1]]},
            {"scale": [1.0, 0.0]},
            ["scale", "0.0", "> 0"],
        ),
        (
            {"shape": "annulus", "outer_radius": 0.05, "inner_radius": 0.02, "law": "hertz"},
            {},
            ["hertz", "annulus"],
        ),
        ({"shape": "disk", "radius": 0.05}, {"v0": [1.0, -1.0]}, ["v0", "-1.0", "[0, 1e+08]"]),
        ({"shape": "disk", "radius": 0.05}, {"omega0": [1.0, 1e300]}, ["omega", "1e+300"]),
        ({"shape": "disk", "radius": 0.05, "incline_angle": 0.1}, {}, ["incline_angle", "compute"]),
    ],
)
def test_bad_footprint_keys_are_named(fixed, vary, words):
    base = {"fx": 0.3, "mu": 0.0}
    if "mu" in vary:
        base.pop("mu")
    spec = {"name": "bad", "kind": "grid", "fixed": {**base, **fixed}, "vary": vary}
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    msg = str(err.value)
    for w in words:
        assert w in msg, (w, msg)


# -------------------------------------------------------------------------- pandas, CLI
def test_to_pandas_matches_read_sweep(tmp_path):
    pd = pytest.importorskip("pandas")
    spec = spec_of(
        {"shape": "disk", "radius": 0.05, "v0": 1.0, "omega0": 10.0},
        {"mu": [0.0, 0.1, 0.2]},
        chunk_size=2,
    )
    res, t = run(spec, tmp_path)
    df = to_pandas(tmp_path / "out")
    assert isinstance(df, pd.DataFrame)
    assert list(df.columns) == list(t) and len(df) == 3
    for k in t:
        assert same(df[k].to_numpy(), t[k])
    assert df.attrs["name"] == "fp" and df.attrs["left_out"] == {}
    df2 = res.to_pandas()
    assert df2.equals(df)


def test_to_pandas_without_pandas_names_the_fix(tmp_path, monkeypatch):
    spec = spec_of({"shape": "disk", "radius": 0.05, "v0": 1.0}, {"mu": [0.0]})
    run(spec, tmp_path)
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match="pip install pandas"):
        to_pandas(tmp_path / "out")


def test_cli_ring_example(tmp_path):
    out = tmp_path / "ring"
    cmd = [sys.executable, "-m", "slidespin"]
    r = subprocess.run(
        cmd + ["sweep", str(EXAMPLES / "sweep_ring.toml"), "--out", str(out), "--quiet"],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert r.returncode == 0, r.stderr
    r = subprocess.run(
        cmd
        + [
            "sweep-plot",
            str(out),
            "--x",
            "radius_ratio",
            "--y",
            "mu",
            "--value",
            "beta_stop",
            "--out",
            str(tmp_path / "ring.png"),
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "ring.png").stat().st_size > 1000
    t = read_sweep(out)
    assert t["case_id"].size == 60
    # isotropic column: β*/R runs from the disk's 0.653 to the thin ring's 1 (monotone)
    iso = t["mu"] == 0.0
    ratio = t["beta_stop"][iso][np.argsort(t["radius_ratio"][iso])] / 0.05
    assert abs(ratio[0] - 0.653) < 1e-3 and abs(ratio[-1] - 1.0) < 0.01
    assert np.all(np.diff(ratio) > 0)


def test_random_footprint_sweep_is_independent_of_chunking(tmp_path):
    def spec(chunk):
        return {
            "name": "rnd",
            "kind": "random",
            "chunk_size": chunk,
            "random": {"samples": 9, "seed": 3},
            "fixed": {"shape": "annulus", "outer_radius": 0.05, "fx": 0.3, "v0": 1.0},
            "vary": {
                "radius_ratio": {"low": 0.0, "high": 0.95},
                "mu": {"low": 0.0, "high": 0.2},
                "omega0": {"low": -20.0, "high": 20.0},
            },
        }

    _, a = run(spec(2), tmp_path, "a")
    _, b = run(spec(9), tmp_path, "b")
    assert all(same(a[k], b[k]) for k in a)
    assert np.unique(a["radius_ratio"]).size == 9
    check_against_simulate(a, lambda i: Annulus(float(a["inner_radius"][i]), 0.05))


def test_sweep_patch_keys_are_those_of_the_case_file():
    """The footprint keys of a TOML [patch] table are sweep keys of the same shape."""
    from slidespin.motion._cases import SHAPE_KEYS
    from slidespin.studies.case import _FOOTPRINT_KEYS

    for shape, keys in _FOOTPRINT_KEYS.items():
        assert set(keys) <= set(SHAPE_KEYS[shape]), shape
