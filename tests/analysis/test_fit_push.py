"""Fitting friction to tracked pushes (slidespin.analysis.fit_push, MODEL §12–13).

Independent truth: the parameters the shipped synthetic pushes were generated with
(examples/push_data/make_synthetic_pushes.py: a dynamic simulation plus seeded noise), which
the fit never sees; it starts from an isotropic guess.
"""

from __future__ import annotations

import importlib.util
import json
import os
import warnings
from dataclasses import replace

import numpy as np
import pytest

import slidespin as ss
from slidespin.analysis._push_problem import _simplify
from slidespin.analysis.fit import IdentifiabilityWarning
from slidespin.analysis.fit_push import PushFitResult, fit_pushes, pushed_at
from slidespin.analysis.push_data import read_pushes

HERE = os.path.dirname(os.path.abspath(__file__))
FOLDER = os.path.join(HERE, "..", "..", "examples", "push_data")


def _script():
    spec = importlib.util.spec_from_file_location(
        "make_synthetic_pushes", os.path.join(FOLDER, "make_synthetic_pushes.py")
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def gen():
    return _script()


@pytest.fixture(scope="module")
def runs():
    out = {r.meta["push"]: r for r in read_pushes(FOLDER)}
    assert sorted(out) == ["1", "2", "3", "4"]
    return out


def test_shipped_files_are_what_the_script_makes(gen):
    """The shipped dataset is reproducible: the script makes the same numbers."""
    for item in gen.make():
        with open(os.path.join(FOLDER, item["name"]), encoding="utf-8") as f:
            shipped = json.load(f)
        assert shipped["source"] == item["doc"]["source"]
        assert shipped["truth"]["fx"] == gen.TRUTH["fx"]
        for key in ("tip_pose", "object_pose", "ft_wrench"):
            np.testing.assert_allclose(shipped[key], item["doc"][key], rtol=0, atol=2e-4)


def test_dynamic_fit_recovers_the_generating_friction(gen, runs):
    """fx, fy from two pushes (one moving the block along x, one along y), start poses
    fitted, poses and forces: within 3 standard errors of the truth."""
    sigma = {"x": 1e-4, "y": 1e-4, "phi": 2e-3, "force_x": 0.05, "force_y": 0.05}
    with warnings.catch_warnings():
        warnings.simplefilter("error", IdentifiabilityWarning)
        res = fit_pushes(
            gen.body(),
            [runs["2"], runs["4"]],
            ss.FrictionTensor(0.3, 0.3),
            ("fx", "fy"),
            mu=gen.MU_P,
            model="dynamic",
            sigma=sigma,
        )
    assert isinstance(res, PushFitResult) and isinstance(res, ss.FitResult)
    assert res.success and res.model == "dynamic"
    for name in ("fx", "fy"):
        se = res.std_errors[name]
        assert 0.0 < se < 0.01 * gen.TRUTH[name]
        assert abs(res.estimates[name] - gen.TRUTH[name]) < 3.0 * se, (name, res.estimates, se)
    assert 0.7 < res.reduced_chi2 < 1.4  # the model reproduces the data to the noise
    assert set(res.rms) == {"x", "y", "phi", "force_x", "force_y"}
    # the fitted start poses: within 4 standard errors of the generating ones
    for k, push in ((0, 2), (1, 4)):
        x0, y0, phi0 = gen.PUSHES[push - 1][0]
        st, err = res.starts[k], res.start_errors[k]
        assert abs(st.x - x0) < 4 * err["x"] and abs(st.y - y0) < 4 * err["y"]
        assert abs(st.phi - phi0) < 4 * err["phi"]
    assert "model             : dynamic" in res.table()
    assert "force_x" in res.fitted[0] and res.data[0]["t_force"].size > 100
    # predict runs the fitted model again at the data's times
    pr = res.predict(0, res.data[0]["t"][10:13])
    np.testing.assert_allclose(pr["x"], res.fitted[0]["x"][10:13], rtol=0, atol=1e-6)


def test_quasi_static_poses_alone_do_not_fix_the_friction_level(gen, runs):
    """Quasi-static poses are invariant under a common scale of the tensor: without force
    data the fit says fx, fy are not identifiable, and still finds their ratio."""
    run = runs["1"]
    light = replace(run, object_pose=run.object_pose[::6], wrench=None)
    with pytest.warns(IdentifiabilityWarning, match="fx, fy.*force data"):
        res = fit_pushes(
            gen.body(),
            light,
            ss.FrictionTensor(0.25, 0.25),
            ("fx", "fy"),
            mu=gen.MU_P,
            model="quasi_static",
            fit_starts=False,
            sigma={"x": 1e-4, "y": 1e-4, "phi": 2e-3},
            max_nfev=6,
        )
    assert res.std_errors["fx"] == np.inf and res.std_errors["fy"] == np.inf
    assert not res.identifiable["fx"]


def test_pushed_at_matches_the_rows_and_quasi_static_times(gen):
    body, fr = gen.body(), gen.friction()
    path = gen.finger_path(*gen.PUSHES[0][:1], *gen.PUSHES[0][1:])
    finger = ss.PointPusher(path, mu=gen.MU_P)
    traj = ss.simulate(body, fr, ss.State(*gen.PUSHES[0][0]), pusher=finger, t_end=1.0)
    at = pushed_at(traj, traj.t[5:8])
    np.testing.assert_allclose(at["x"], traj.x[5:8], rtol=0, atol=1e-12)
    times = np.linspace(0.0, 1.0, 11)
    q = ss.push_quasi_static(body, fr, finger, times, gen.PUSHES[0][0])
    aq = pushed_at(q, times[3:])
    np.testing.assert_array_equal(aq["force_x"], q.force_x[3:])


def test_simplify_keeps_corners_only():
    t = np.linspace(0.0, 2.0, 201)
    x = np.where(t < 1.0, 0.03 * t, 0.03 + 0.01 * (t - 1.0))
    rows = np.column_stack((t, x, np.zeros_like(t)))
    kept = _simplify(rows, 1e-6)
    np.testing.assert_allclose(kept[:, 0], [0.0, 1.0, 2.0])
    assert _simplify(rows, 0.0).shape == rows.shape
    # the thinned path stays within the tolerance of every row
    noisy = rows + np.column_stack((0 * t, np.random.default_rng(0).normal(0, 2e-6, (t.size, 2))))
    thin = _simplify(noisy, 1e-5)
    px = np.interp(t, thin[:, 0], thin[:, 1])
    py = np.interp(t, thin[:, 0], thin[:, 2])
    assert np.max(np.hypot(px - noisy[:, 1], py - noisy[:, 2])) <= 1e-5
    assert thin.shape[0] < 20


def test_bad_arguments(gen, runs):
    body, fr, run = gen.body(), gen.friction(), runs["1"]
    with pytest.raises(ValueError, match="moment_of_inertia.*quasi_static"):
        fit_pushes(body, run, fr, ("fx", "moment_of_inertia"), model="quasi_static")
    with pytest.raises(ValueError, match="free parameter 'mu' is unknown"):
        fit_pushes(body, run, fr, ("fx", "mu"))
    with pytest.raises(ValueError, match=r"runs\[1\] = dict is invalid"):
        fit_pushes(body, [run, {"t": [0.0]}], fr)
    with pytest.raises(ValueError, match="model = 'fast' is invalid"):
        fit_pushes(body, run, fr, model="fast")
    with pytest.raises(ValueError, match="sigma channel 'fz' is unknown"):
        fit_pushes(body, run, fr, sigma={"fz": 1.0})
    uniform = ss.Body(ss.Rectangle(0.09, 0.09), ss.UniformPressure(), 1.0)
    with pytest.raises(ValueError, match="xi_c, eta_c need a body with LinearPressure"):
        fit_pushes(uniform, run, fr, ("fx", "xi_c"))


def test_a_finger_inside_the_body_names_the_push(gen, runs):
    run = runs["1"]
    moved = run.object_pose.copy()
    moved[:, 1] -= 0.01  # the block 1 cm towards the finger: it starts 6 mm inside
    bad = replace(run, object_pose=moved)
    with pytest.raises(ValueError, match=r"push 0 \(.*push=1\.json\): .*inside"):
        fit_pushes(gen.body(), bad, gen.friction(), mu=gen.MU_P, fit_starts=False)
