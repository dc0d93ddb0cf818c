"""`read_sweep(..., as_xarray=True)`: a grid sweep on its grid, the swept parameters as
coordinates; refused (with the reason) for random or unfinished sweeps, and without xarray."""

from __future__ import annotations

import json
import sys

import numpy as np
import pytest

import slidespin as ss
from slidespin.studies.sweep import sweep
from slidespin.studies.sweep_read import read_sweep, to_xarray
from slidespin.studies.sweep_spec import SweepError

xr = pytest.importorskip("xarray")

MU = [0.0, 0.1, 0.2]
ISTAR = [0.4, 0.9]
LAWS = ["uniform", "hertz"]


def grid(**extra):
    spec = {
        "name": "grid",
        "kind": "grid",
        "chunk_size": 5,
        "fixed": {"a": 0.05, "e": 0.6, "fx": 0.3, "v0": 0.5, "omega0": 6.0, "theta0": 0.3},
        "vary": {"mu": MU, "law": LAWS, "I_star": ISTAR},
    }
    spec.update(extra)
    return spec


@pytest.fixture(scope="module")
def done(tmp_path_factory):
    out = tmp_path_factory.mktemp("x") / "s"
    sweep(grid(), out, progress=False)
    return out


def test_dimensions_and_coordinates_are_the_grid(done):
    ds = read_sweep(done, as_xarray=True)
    assert isinstance(ds, xr.Dataset)
    assert tuple(ds.sizes) == ("mu", "law", "I_star")
    assert tuple(ds.sizes.values()) == (3, 2, 2)
    assert list(ds["mu"].values) == MU and list(ds["law"].values) == LAWS
    assert list(ds["I_star"].values) == ISTAR
    assert ds.attrs["name"] == "grid" and json.loads(ds.attrs["spec"])["vary"]["mu"] == MU
    for name in ("t_stop", "beta_stop", "status", "ending", "case_id", "fy"):
        assert ds[name].dims == ("mu", "law", "I_star")


def test_every_cell_is_its_case(done):
    """Each cell holds the row of the table whose inputs are the cell's coordinates, and that
    row is one simulate() call on that body (independent of the reshaping)."""
    ds = read_sweep(done, as_xarray=True)
    table = read_sweep(done, include_unconverged=True)
    for i in range(len(table["case_id"])):
        cell = ds.sel(law=table["law"][i]).sel(
            mu=table["mu"][i], I_star=table["I_star"][i], method="nearest"
        )
        assert int(cell["case_id"]) == table["case_id"][i]
        assert float(cell["t_stop"]) == table["t_stop"][i]
        assert str(cell["ending"].values) == table["ending"][i]
    cell = ds.sel(mu=0.2, law="hertz", I_star=0.9)
    body = ss.Body.from_inertia_ratio(
        ss.Ellipse.from_eccentricity(0.05, 0.6), ss.HertzPressure(), 1.0, 0.9
    )
    tr = ss.simulate(body, ss.FrictionTensor(0.3, 0.3 + 0.2), ss.State.from_speed(0.5, 6.0, 0.3))
    assert float(cell["t_stop"]) == pytest.approx(tr.t_stop, rel=1e-12)
    assert float(cell["x_stop"]) == pytest.approx(tr.stop_state.x, rel=1e-10)


def test_to_xarray_is_the_same(done):
    assert read_sweep(done, as_xarray=True).identical(to_xarray(done))


def test_unconverged_results_are_nan_unless_kept(tmp_path):
    out = tmp_path / "s"
    # a budget of 50 steps: the pure translations (omega0 = 0) stop within it, the fast
    # spins do not (measured: 23-32 and 59-86 steps)
    spec = grid(max_steps=50, vary={"mu": MU, "omega0": [0.0, 60.0]})
    spec["fixed"].pop("omega0")
    sweep(spec, out, progress=False)
    table = read_sweep(out, include_unconverged=True)
    bad = np.isin(table["status"], ["max_steps", "step_too_small", "non_finite"])
    assert bad.any() and not bad.all()
    ds = read_sweep(out, as_xarray=True)
    flat = ds["t_stop"].values.ravel()
    assert np.isnan(flat[bad]).all() and np.array_equal(flat[~bad], table["t_stop"][~bad])
    assert list(ds["status"].values.ravel()) == list(table["status"])  # kept, to see why
    assert ds["fy"].values.ravel()[bad].size and np.isfinite(ds["fy"].values).all()
    left = json.loads(ds.attrs["left_out"])
    assert sum(left.values()) == int(bad.sum())
    full = read_sweep(out, as_xarray=True, include_unconverged=True)
    assert np.array_equal(full["t_stop"].values.ravel(), table["t_stop"], equal_nan=True)


def test_random_and_unfinished_sweeps_are_refused(tmp_path):
    rnd = {
        "kind": "random",
        "random": {"samples": 4, "seed": 1},
        "fixed": {"a": 0.05, "fx": 0.3, "v0": 0.5},
        "vary": {"mu": {"low": 0.0, "high": 0.2}},
    }
    sweep(rnd, tmp_path / "r", progress=False)
    with pytest.raises(SweepError, match="random sweep .* no grid; valid for as_xarray: a grid"):
        read_sweep(tmp_path / "r", as_xarray=True)
    out = tmp_path / "g"
    sweep(grid(), out, progress=False)
    (out / "chunks" / "chunk-000001.parquet").unlink()
    with pytest.raises(SweepError, match=r"unfinished \(7 of 12 cases\).*--resume"):
        read_sweep(out, as_xarray=True)
    with pytest.raises(SweepError, match="as_xarray = 'yes' is invalid; valid values: True"):
        read_sweep(out, as_xarray="yes")


def test_without_xarray_the_message_says_how_to_install_it(done, monkeypatch):
    monkeypatch.setitem(sys.modules, "xarray", None)  # import xarray raises ImportError
    with pytest.raises(ImportError, match=r"pip install slidespin\[xarray\]"):
        read_sweep(done, as_xarray=True)
    assert len(read_sweep(done)["case_id"]) == 12  # the table needs no xarray


def test_the_extra_is_declared():
    from pathlib import Path

    try:
        import tomllib
    except ImportError:  # Python 3.10
        import tomli as tomllib

    meta = tomllib.loads((Path(__file__).resolve().parents[2] / "pyproject.toml").read_text())
    extras = meta["project"]["optional-dependencies"]
    assert extras["xarray"] == ["xarray>=2023.1"]
    assert "xarray>=2023.1" in extras["test"]
