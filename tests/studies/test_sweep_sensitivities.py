"""Sweeps of gradients: the top-level key ``sensitivities`` adds each case's stop derivatives
as columns ``d_<q>/d_<parameter>`` (MODEL §15).

Independent truth: pure translation of a disk, t = v/(μ g) and x = v²/(2 μ g), whose
derivatives with respect to the launch speed and μ are closed forms; and the columns of a
footprint sweep are those of ``ss.stop_sensitivities`` case by case (the same sensitivity
run: an API check that the sweep routes each case's body and start right).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import slidespin as ss
from slidespin.studies.sweep import sweep
from slidespin.studies.sweep_parse import load_spec
from slidespin.studies.sweep_read import read_sweep
from slidespin.studies.sweep_spec import SweepError

G = 9.81


def _spec(**over):
    spec = {
        "name": "gradients",
        "chunk_size": 2,
        "fixed": {
            "a": 0.1,
            "e": 0.0,
            "law": "uniform",
            "fx": 0.3,
            "mu": 0.0,
            "mass": 1.0,
            "g": G,
            "theta0": 0.0,
            "omega0": 0.0,
            "phi0": 0.0,
        },  # fmt: skip
        "vary": {"v0": [0.5, 1.0, 1.5]},
        "sensitivities": ["vx", "fx", "omega"],
    }
    spec.update(over)
    return spec


def test_pure_translation_gradients_against_the_closed_forms(tmp_path):
    with warnings.catch_warnings():  # beta*'s kink for a round body under fx (NaN, said)
        warnings.simplefilter("ignore", RuntimeWarning)
        sweep(_spec(), tmp_path / "s", progress=False)
    t = read_sweep(tmp_path / "s")
    v, mu = np.asarray(t["v0"]), 0.3
    assert list(t["status"]) == ["stopped"] * 3
    np.testing.assert_allclose(t["d_t_stop/d_vx"], 1.0 / (mu * G), rtol=1e-8)
    np.testing.assert_allclose(t["d_x/d_vx"], v / (mu * G), rtol=1e-8)
    np.testing.assert_allclose(t["d_t_stop/d_fx"], -v / (mu**2 * G), rtol=1e-8)
    np.testing.assert_allclose(t["d_x/d_fx"], -(v**2) / (2 * mu**2 * G), rtol=1e-8)
    np.testing.assert_allclose(t["d_y/d_vx"], 0.0, atol=1e-12)
    # a spin given at launch turns a disk in translation without moving its stop: dφ/dω = t
    assert np.all(np.isfinite(t["d_phi/d_omega"]))


def test_a_footprint_sweep_s_columns_are_each_case_s_stop_sensitivities(tmp_path):
    spec = {
        "name": "box gradients",
        "chunk_size": 3,
        "fixed": {
            "shape": "rectangle",
            "length": 0.2,
            "width": 0.1,
            "law": "uniform",
            "fx": 0.3,
            "fy": 0.45,
            "mass": 1.0,
            "g": G,
            "vx0": 0.8,
            "vy0": 0.2,
        },  # fmt: skip
        "vary": {"omega0": [-6.0, 2.0, 9.0, 15.0]},
        "sensitivities": ["fy", "moment_of_inertia", "omega"],
    }
    sweep(spec, tmp_path / "s", progress=False)
    t = read_sweep(tmp_path / "s")
    body = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
    fr = ss.FrictionTensor(0.3, 0.45)
    for i, om in enumerate(t["omega0"]):
        d = ss.stop_sensitivities(body, fr, ss.State(vx=0.8, vy=0.2, omega=float(om)), g=G,
                                  parameters=("fy", "moment_of_inertia", "omega"))  # fmt: skip
        for p in d:
            for q, val in d[p].items():
                assert t[f"d_{q}/d_{p}"][i] == pytest.approx(val, rel=1e-12, abs=1e-15)


def test_a_case_at_rest_has_nan_gradients(tmp_path):
    sweep(_spec(vary={"v0": [0.0, 1.0]}), tmp_path / "s", progress=False)
    t = read_sweep(tmp_path / "s")
    assert t["status"][0] == "at_rest" and math.isnan(t["d_x/d_vx"][0])
    assert math.isfinite(t["d_x/d_vx"][1])


@pytest.mark.parametrize(
    ("over", "match"),
    [
        ({"sensitivities": ["vx", "nope"]}, "sensitivities"),
        ({"sensitivities": "vx"}, "sensitivities"),
        ({"sensitivities": []}, "sensitivities"),
        ({"sensitivities": ["xi_c"], "fixed": dict(_spec()["fixed"], law="hertz")}, "case 0"),
    ],
)
def test_bad_sensitivities_are_refused_before_work(over, match):
    """(Hertz pressure has no centre that can move: xi_c is refused, naming the case.)"""
    with pytest.raises(SweepError, match=match):
        load_spec(_spec(**over))


def test_sensitivities_are_for_stop_sweeps_only():
    spec = _spec(compute="loaded")
    spec["fixed"] = dict(spec["fixed"], load_fx=0.5, t_end=1.0)
    with pytest.raises(SweepError, match="compute = 'stop'"):
        load_spec(spec)
