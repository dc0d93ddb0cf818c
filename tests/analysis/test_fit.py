"""Identification of friction parameters (slidespin.fit, MODEL §12).

Independent truths used here: the known parameters of synthetic runs (made by a dense
simulation sampled by plain linear interpolation, not by the fit's Hermite interpolant), the
closed form of a pure translation x = x0 + v0 t − fx g t²/2 (for which the fit is a linear
regression whose estimate and covariance are known exactly), the binomial law of interval
coverage over noise draws, and symmetry (a spinning disk tells only fx + fy).
"""

from __future__ import annotations

import functools
import math
import warnings

import numpy as np
import pytest

import slidespin as ss
from slidespin.analysis.fit import FitWarning, IdentifiabilityWarning, fit
from slidespin.analysis.fit_data import as_runs, read_runs, trajectory_at
from slidespin.analysis.fit_result import FitResult

G = 9.81
A = 0.1


def plate():
    return ss.Body(ss.Ellipse.from_eccentricity(A, 0.866), ss.UniformPressure(), mass=1.0)


@functools.cache
def dense(friction, state, body=None):
    """A dense simulation (τ steps of 0.002): the truth that synthetic data sample."""
    return ss.simulate(body or plate(), friction, state, max_step=0.002)


def sample(traj, t):
    """Linear interpolation of a dense run (independent of fit.trajectory_at)."""
    out = {}
    for c in ("x", "y", "phi"):
        out[c] = np.interp(t, traj.t, getattr(traj, c))
    return out


def synthetic(friction, states, n, sigma, rng, body=None, span=1.05):
    runs = []
    for st in states:
        tr = dense(friction, st, body)
        t = np.linspace(0.0, span * tr.t_stop, n)
        clean = sample(tr, t)
        runs.append({"t": t, **{c: clean[c] + rng.normal(0.0, sigma[c], n) for c in clean}})
    return runs


TRUE = ss.FrictionTensor(0.42, 0.54, 0.04)
STATES = (
    ss.State.from_speed(1.0, 6.0, theta=0.6, phi=0.2),
    ss.State.from_speed(0.9, -9.0, theta=2.0, phi=1.0),
    ss.State.from_speed(1.2, 2.0, theta=-0.5, phi=-0.4),
)
SIGMA = {"x": 1e-3, "y": 1e-3, "phi": 1e-2}


# -- the model at measured times ----------------------------------------------------------------


def test_hermite_interpolation_of_default_steps_matches_a_dense_run():
    for st in STATES:
        coarse = ss.simulate(plate(), TRUE, st, rtol=1e-12)  # fit()'s default steps
        ref = dense(TRUE, st)
        t = np.linspace(0.0, 1.2 * ref.t_stop, 3001)
        got = trajectory_at(coarse, t)
        want = sample(ref, t)
        assert np.max(np.abs(got["x"] - want["x"])) < 1e-6 * A
        assert np.max(np.abs(got["y"] - want["y"])) < 1e-6 * A
        assert np.max(np.abs(got["phi"] - want["phi"])) < 1e-5
        after = t > ref.t_stop
        assert np.all(got["x"][after] == coarse.stop_state.x)
        assert np.all(got["phi"][after] == coarse.stop_state.phi)


def test_interpolated_pure_translation_is_the_closed_form():
    fx, v0 = 0.4, 1.3
    tr = ss.simulate(plate(), ss.FrictionTensor(fx, 0.7), ss.State(0.02, 0.0, 0.0, v0, 0.0, 0.0))
    ts = v0 / (fx * G)
    t = np.linspace(0.0, 1.5 * ts, 500)
    tc = np.minimum(t, ts)
    x = 0.02 + v0 * tc - 0.5 * fx * G * tc**2
    got = trajectory_at(tr, t)
    assert np.max(np.abs(got["x"] - x)) < 1e-9
    assert np.max(np.abs(got["y"])) < 1e-12


# -- estimates and their errors --------------------------------------------------------------


def test_pure_translation_fit_is_the_linear_regression():
    """Before the stop x = x0 + v0 t − (g/2) fx t² is linear in (x0, v0, fx): the fit must
    return the least-squares solution and the covariance σ²(XᵀX)⁻¹ exactly."""
    rng = np.random.default_rng(11)
    fx, v0, sig = 0.4, 1.0, 1e-3
    t = np.linspace(0.0, 0.9 * v0 / (fx * G), 70)
    x = 0.01 + v0 * t - 0.5 * fx * G * t**2 + rng.normal(0.0, sig, t.size)
    res = fit(
        {"t": t, "x": x}, plate(), ss.FrictionTensor(0.3, 0.3, 0.0), free=("fx",), sigma={"x": sig}
    )
    X = np.column_stack([np.ones_like(t), t, -0.5 * G * t**2])
    beta = np.linalg.lstsq(X, x, rcond=None)[0]
    cov = sig**2 * np.linalg.inv(X.T @ X)
    assert res.estimates["fx"] == pytest.approx(beta[2], rel=1e-7)
    assert res.std_errors["fx"] == pytest.approx(math.sqrt(cov[2, 2]), rel=1e-5)
    assert res.starts[0].x == pytest.approx(beta[0], abs=1e-9)
    assert res.starts[0].vx == pytest.approx(beta[1], rel=1e-7)
    assert res.start_errors[0]["vx"] == pytest.approx(math.sqrt(cov[1, 1]), rel=1e-5)
    k = res.parameter_names.index("run0.vx")
    want = cov[2, 1] / math.sqrt(cov[1, 1] * cov[2, 2])
    assert res.correlation[0, k] == pytest.approx(want, abs=1e-6)
    assert res.parameter_names == ("fx", "run0.x", "run0.vx")
    assert res.dof == t.size - 3
    assert res.chi2 == pytest.approx(np.sum((x - X @ beta) ** 2) / sig**2, rel=1e-7)


def test_three_runs_recover_the_truth_from_a_distant_guess():
    rng = np.random.default_rng(5)
    runs = synthetic(TRUE, STATES, 100, SIGMA, rng)
    with warnings.catch_warnings():
        warnings.simplefilter("error", FitWarning)
        res = fit(runs, plate(), ss.FrictionTensor(0.3, 0.3))
    assert res.success
    for name, truth in (("fx", 0.42), ("fy", 0.54), ("f", 0.04)):
        assert abs(res.estimates[name] - truth) < 3.0 * res.std_errors[name]
        assert res.std_errors[name] < 0.01  # useful, not merely honest
    for c, s in SIGMA.items():  # the estimated noise levels
        assert res.sigma[c] == pytest.approx(s, rel=0.15)
        assert res.sigma_estimated[c]
    assert res.reduced_chi2 == pytest.approx(1.0, abs=1e-9)  # σ estimated: by construction
    for st, true_st in zip(res.starts, STATES):
        assert st.omega == pytest.approx(true_st.omega, abs=0.3)
        assert st.vx == pytest.approx(true_st.vx, abs=0.05)
    assert all(res.identifiable.values())
    assert res.friction.fx == res.estimates["fx"] and res.friction.frame == "plane"
    text = repr(res)
    assert "fx=" in text and "\n" not in text and len(text) < 300
    import json

    json.dumps(res.summary())  # JSON-ready


def test_given_sigma_gives_chi2_near_dof():
    rng = np.random.default_rng(8)
    runs = synthetic(TRUE, STATES[:2], 120, SIGMA, rng)
    res = fit(runs, plate(), TRUE, sigma=SIGMA)
    assert not any(res.sigma_estimated.values())
    assert abs(res.chi2 - res.dof) < 4.0 * math.sqrt(2.0 * res.dof)


def test_coverage_of_95_percent_intervals_and_bias():
    """40 noise draws of one run: the true values fall inside the reported 95 % intervals as
    often as a binomial(40, 0.95) allows, the estimates scatter as the standard errors say,
    and the bias is below the standard error (and within the Monte-Carlo resolution)."""
    st = ss.State.from_speed(1.0, 6.0, theta=0.6, phi=0.2)
    tr = dense(TRUE, st)
    t = np.linspace(0.0, 1.05 * tr.t_stop, 60)
    clean = sample(tr, t)  # one trajectory, reused by every draw
    sig = {"x": 2e-3, "y": 2e-3, "phi": 2e-2}
    rng = np.random.default_rng(2026)
    names, truth = ("fx", "fy", "f"), np.array([0.42, 0.54, 0.04])
    est, se = [], []
    n = 40
    for _ in range(n):
        run = {"t": t, **{c: clean[c] + rng.normal(0.0, sig[c], t.size) for c in clean}}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FitWarning)
            res = fit(run, plate(), TRUE)  # σ estimated from the residuals
        est.append([res.estimates[k] for k in names])
        se.append([res.std_errors[k] for k in names])
    est, se = np.array(est), np.array(se)
    inside = np.abs(est - truth) < 1.959964 * se
    # binomial(40, 0.95): mean 38, sd 1.38; 3 sd below is 33.9
    assert np.all(inside.sum(axis=0) >= 34), inside.sum(axis=0)
    assert inside.sum() >= 107  # of 120: 114 - 3 * 2.39
    sd = est.std(axis=0, ddof=1)
    ratio = sd / se.mean(axis=0)
    assert np.all((ratio > 0.7) & (ratio < 1.4)), ratio  # 40 draws: sd known to ~11 %
    bias = est.mean(axis=0) - truth
    assert np.all(np.abs(bias) < se.mean(axis=0))
    assert np.all(np.abs(bias) < 4.0 * sd / math.sqrt(n)), bias


def test_moment_of_inertia_and_friction_together():
    rng = np.random.default_rng(3)
    body_true = ss.Body(plate().patch, ss.UniformPressure(), 1.0, moment_of_inertia=0.005)
    runs = synthetic(TRUE, STATES[:2], 100, SIGMA, rng, body=body_true)
    res = fit(runs, plate(), ss.FrictionTensor(0.42, 0.54, 0.04), free=("fx", "moment_of_inertia"))
    assert abs(res.estimates["moment_of_inertia"] - 0.005) < 3 * res.std_errors["moment_of_inertia"]
    assert res.std_errors["moment_of_inertia"] < 5e-4
    assert abs(res.estimates["fx"] - 0.42) < 3 * res.std_errors["fx"]


def test_linear_law_centroid_and_tensor_angle():
    rng = np.random.default_rng(4)
    law = ss.LinearPressure(0.01, -0.004)
    body_true = ss.Body(plate().patch, law, 1.0, moment_of_inertia=0.003)
    fr_true = ss.FrictionTensor(0.4, 0.6, 0.0, angle=0.5)
    runs = synthetic(fr_true, STATES[:2], 100, SIGMA, rng, body=body_true)
    guess_body = ss.Body(plate().patch, ss.LinearPressure(0.0, 0.0), 1.0, 0.003)
    res = fit(
        runs,
        guess_body,
        ss.FrictionTensor(0.4, 0.6, 0.0, angle=0.3),
        free=("xi_c", "eta_c", "angle"),
    )
    for name, truth in (("xi_c", 0.01), ("eta_c", -0.004), ("angle", 0.5)):
        assert abs(res.estimates[name] - truth) < 3 * res.std_errors[name], name


def test_robust_loss_resists_outliers():
    rng = np.random.default_rng(9)
    runs = synthetic(TRUE, STATES[:2], 120, SIGMA, rng)
    for run in runs:  # 5 % gross outliers, 30 sigma, all on one side
        idx = rng.choice(run["t"].size, 6, replace=False)
        run["x"][idx] += 30 * SIGMA["x"]
    res = fit(runs, plate(), TRUE, loss="soft_l1", f_scale=2.0)
    for name, truth in (("fx", 0.42), ("fy", 0.54), ("f", 0.04)):
        assert abs(res.estimates[name] - truth) < 3.0 * res.std_errors[name], name
    assert res.sigma["x"] == pytest.approx(SIGMA["x"], rel=0.3)  # MAD, not pulled up


# -- identifiability ----------------------------------------------------------------------------


@pytest.mark.filterwarnings("ignore:the fit ended at a bound:slidespin.analysis.fit.FitWarning")
def test_run_sliding_only_along_x_cannot_tell_fy():
    """Closed-form pure translation along x (y and phi measured as noise around 0)."""
    rng = np.random.default_rng(3)
    fx, v0 = 0.4, 1.0
    ts = v0 / (fx * G)
    t = np.linspace(0.0, 1.2 * ts, 80)
    tc = np.minimum(t, ts)
    run = {
        "t": t,
        "x": v0 * tc - 0.5 * fx * G * tc**2 + rng.normal(0, 1e-3, t.size),
        "y": rng.normal(0, 1e-3, t.size),
        "phi": rng.normal(0, 1e-2, t.size),
    }
    with pytest.warns(IdentifiabilityWarning, match="fy"):
        res = fit(run, plate(), ss.FrictionTensor(0.3, 0.3), free=("fx", "fy"))
    assert res.std_errors["fy"] == math.inf
    assert not res.identifiable["fy"]
    assert res.identifiable["fx"]
    assert abs(res.estimates["fx"] - fx) < 3 * res.std_errors["fx"]
    assert any("fy" in w for w in res.warnings)
    assert "not identifiable" in repr(res)


def test_spinning_disk_tells_only_the_sum_of_fx_and_fy():
    """A disk spinning in place feels a torque ∝ (fx + fy)/2 (symmetry): fx − fy is free."""
    rng = np.random.default_rng(6)
    disk = ss.Body(ss.Circle(0.05), ss.UniformPressure(), mass=1.0)
    st = ss.State(0.0, 0.0, 0.0, 0.0, 0.0, 20.0)
    tr = ss.simulate(disk, ss.FrictionTensor(0.35, 0.45), st, max_step=0.002)
    t = np.linspace(0.0, 1.1 * tr.t_stop, 80)
    run = {"t": t, **{c: sample(tr, t)[c] + rng.normal(0, s, t.size) for c, s in SIGMA.items()}}
    with pytest.warns(IdentifiabilityWarning) as rec:
        res = fit(run, disk, ss.FrictionTensor(0.3, 0.5), free=("fx", "fy"))
    msg = " ".join(str(w.message) for w in rec)
    assert "fx" in msg and "fy" in msg
    assert not res.identifiable["fx"] and not res.identifiable["fy"]
    assert math.isinf(res.std_errors["fx"]) and math.isinf(res.std_errors["fy"])
    # the sum is what the data fix
    assert res.estimates["fx"] + res.estimates["fy"] == pytest.approx(0.8, abs=0.03)


# -- input ------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "data, match",
    [
        (42, "data = int is invalid"),
        ([], "holds no run"),
        ({"x": [0.0, 1.0]}, "'t'"),
        ({"t": [0.0, 0.0], "x": [0.0, 1.0]}, "row 1 .*strictly increasing"),
        ({"t": [0.0, np.nan], "x": [0.0, 1.0]}, "column 't' row 1"),
        ({"t": [0.0, 1.0], "x": [0.0, np.inf]}, "column 'x' row 1"),
        ({"t": [0.0, 1.0], "x": [0.0]}, "column 'x' has shape"),
        ({"t": [0.0, 1.0], "vx": [0.0, 1.0]}, "unknown column 'vx'"),
        ({"t": [0.0, 1.0], "x": [np.nan, np.nan]}, "no measured value"),
        ([{"t": [0.0, 1.0], "x": [0.0, 1.0]}, {"t": [1.0], "q": [1]}], r"data\[1\]"),
    ],
)
def test_bad_data_is_one_line_naming_the_column_and_row(data, match):
    with pytest.raises(ValueError, match=match) as exc:
        as_runs(data)
    assert "\n" not in str(exc.value)


def test_structured_array_run_and_missing_values():
    t = np.linspace(0.0, 0.2, 30)
    arr = np.zeros(30, dtype=[("t", float), ("x", float)])
    arr["t"], arr["x"] = t, 1.0 * t - 0.5 * 0.4 * G * t**2
    arr["x"][5] = np.nan  # a missing value is skipped
    res = fit(arr, plate(), ss.FrictionTensor(0.3, 0.3), free=("fx",), sigma={"x": 1e-6})
    assert res.estimates["fx"] == pytest.approx(0.4, rel=1e-5)
    assert res.n_points == 29


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"free": ("fx", "mu")}, "free parameter 'mu' is unknown"),
        ({"free": ("fx", "fx")}, "given twice"),
        ({"free": ("xi_c",)}, "LinearPressure"),
        ({"sigma": {"x": -1.0}}, r"sigma\['x'\]"),
        ({"sigma": {"z": 1.0}}, "sigma channel 'z'"),
        ({"loss": "l2"}, "loss"),
        ({"starts": [None, None]}, "starts"),
        ({"start_free": ("vz",)}, "start_free component 'vz'"),
        ({"g": 0.0}, "g = 0.0"),
        ({"max_nfev": 0}, "max_nfev"),
    ],
)
def test_bad_options(kwargs, match):
    run = {"t": np.linspace(0, 0.2, 20), "x": np.linspace(0, 0.1, 20)}
    with pytest.raises(ValueError, match=match):
        fit(run, plate(), ss.FrictionTensor(0.3, 0.3), **kwargs)


def test_too_few_points():
    with pytest.raises(ValueError, match="too few measured values: 3 for 4"):
        fit(
            {"t": [0.0, 0.1, 0.2], "x": [0.0, 0.1, 0.15]},
            plate(),
            ss.FrictionTensor(0.3, 0.3),
            free=("fx", "fy"),
        )


def test_known_start_is_not_fitted():
    rng = np.random.default_rng(1)
    runs = synthetic(TRUE, STATES[:1], 80, SIGMA, rng)
    res = fit(runs, plate(), TRUE, starts=STATES[0])
    assert res.parameter_names == ("fx", "fy", "f")
    assert res.starts[0] == STATES[0]
    assert res.start_errors[0] == {}
    assert isinstance(res, FitResult)


# -- CSV -------------------------------------------------------------------------------------


def test_read_runs_groups_by_run_and_keeps_missing_cells(tmp_path):
    p = tmp_path / "d.csv"
    p.write_text("run,t,x,phi\nA,0,0.0,0.1\nA,0.1,0.05,\nB,0,1.0,nan\nB,0.2,1.1,0.3\n")
    runs, labels = read_runs(p, labels=True)
    assert labels == ["A", "B"]
    assert set(runs[0]) == {"t", "x", "phi"}
    assert np.isnan(runs[0]["phi"][1]) and np.isnan(runs[1]["phi"][0])
    assert runs[1]["x"].tolist() == [1.0, 1.1]
    p.write_text("t,y\n0,1\n1,2\n")
    assert read_runs(p)[0]["y"].tolist() == [1.0, 2.0]


@pytest.mark.parametrize(
    "text, match",
    [
        ("", "empty"),
        ("t,x,speed\n0,1,2\n", "line 1: unknown column 'speed'"),
        ("x,y\n0,1\n", "column 't'"),
        ("t,x,x\n0,1,2\n", "column 'x' appears twice"),
        ("t,run\n0,a\n", "no column x, y or phi"),
        ("t,x\n", "no data rows"),
        ("t,x\n0,1\n0.1,abc\n", "line 3, column 'x': 'abc' is not a number"),
        ("t,x\n0,1\n0.1,inf\n", "line 3, column 'x': 'inf' is not finite"),
        ("t,x\n0,1\n,2\n", "line 3, column 't': missing time"),
        ("t,x\n0,1\n0.1\n", "line 3 has 1 fields"),
        ("t,x\n0,1\n0,2\n", "line 3, column 't': 0.0 does not increase"),
        ("run,t,x\na,0,1\nb,0,\n", "run 'b' .*no measured"),
        ("run,t,x\n,0,1\n", "line 2, column 'run': empty run label"),
    ],
)
def test_read_runs_errors_name_file_line_and_column(tmp_path, text, match):
    p = tmp_path / "bad.csv"
    p.write_text(text)
    with pytest.raises(ValueError, match=match) as exc:
        read_runs(p)
    assert "bad.csv" in str(exc.value) and "\n" not in str(exc.value)


def test_read_runs_missing_file(tmp_path):
    with pytest.raises(ValueError, match="does not exist"):
        read_runs(tmp_path / "nope.csv")
    with pytest.raises(ValueError, match="is a directory"):
        read_runs(tmp_path)


def test_unfinished_quick_simulations_are_redone_in_full(monkeypatch):
    """Inside a fit a simulation first gets a small step budget; one that ends still moving
    must be run again with the full budget, so the result cannot depend on that budget."""
    import slidespin.analysis._fit_problem as fit_module

    rng = np.random.default_rng(12)
    runs = synthetic(TRUE, STATES[:1], 60, SIGMA, rng)
    ref = fit(runs, plate(), TRUE, sigma=SIGMA)
    monkeypatch.setattr(fit_module, "QUICK_STEPS", 3)
    res = fit(runs, plate(), TRUE, sigma=SIGMA)
    for name in ("fx", "fy", "f"):
        assert res.estimates[name] == pytest.approx(ref.estimates[name], rel=1e-9)


def test_wrapped_tracker_angles_fit_like_unwrapped_ones():
    """A tracker reporting φ in (−π, π] must give the same fit as the continuous angle."""
    rng = np.random.default_rng(21)
    st = ss.State.from_speed(0.8, 25.0, theta=0.4, phi=3.0)  # turns through the cut at π
    runs = synthetic(TRUE, (st,), 80, SIGMA, rng)
    wrapped = dict(runs[0])
    wrapped["phi"] = np.angle(np.exp(1j * runs[0]["phi"]))
    assert np.ptp(runs[0]["phi"]) > math.pi and np.ptp(wrapped["phi"]) > 6.0  # it jumps
    a = fit(runs[0], plate(), TRUE, sigma=SIGMA)
    b = fit(wrapped, plate(), TRUE, sigma=SIGMA)
    # The two problems are the same but for round-off: a wrapped φ residual differs from the
    # continuous one in its last bits (the wrap of data − model ≈ 2πk), and the objective, a
    # sum over ODE solutions differenced for the Jacobian, is only smooth to ~1e-11. The
    # least-squares minimum is therefore located to ~1e-5 standard errors whatever the
    # stopping tolerances (measured: 4e-5 σ at ftol = 1e-9, 6e-6 σ at 1e-15; 5 and 6
    # evaluations), so the estimates are compared on the scale that matters, their standard
    # errors: a mishandled cut at ±π moves them by many σ and leaves φ residuals of ~2π.
    for name in ("fx", "fy", "f"):
        assert abs(b.estimates[name] - a.estimates[name]) < 1e-3 * a.std_errors[name]
        assert b.std_errors[name] == pytest.approx(a.std_errors[name], rel=1e-4)
    assert abs(b.residuals[0]["phi"]).max() < 6 * SIGMA["phi"]


def test_table_with_columns_like_a_dataframe():
    """Anything with ``columns`` and item access (a pandas DataFrame) is a run."""

    class Table:
        def __init__(self, data):
            self.data = data
            self.columns = list(data)

        def __getitem__(self, key):
            return self.data[key]

    t = np.linspace(0.0, 0.2, 30)
    table = Table({"t": t, "x": 1.0 * t - 0.5 * 0.4 * G * t**2})
    res = fit(table, plate(), ss.FrictionTensor(0.3, 0.3), free=("fx",), sigma={"x": 1e-6})
    assert res.estimates["fx"] == pytest.approx(0.4, rel=1e-5)
    with pytest.raises(ValueError, match="unknown column 'run'"):
        as_runs(Table({"t": t, "x": t, "run": t}))


def test_compare_frames_prefers_the_frame_the_data_were_made_with():
    from dataclasses import replace

    from slidespin.analysis.fit import compare_frames, frame_score

    rng = np.random.default_rng(31)
    for frame in ("body", "plane"):
        fr = ss.FrictionTensor(0.3, 0.6, 0.0, frame=frame)
        runs = synthetic(fr, STATES[:2], 80, SIGMA, rng)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FitWarning)
            best, scores, fits = compare_frames(
                runs, plate(), replace(fr, frame="plane"), free=("fx", "fy")
            )
        assert best.friction.frame == frame
        assert scores[frame] < min(scores.values()) + 1e-12
        assert scores == {k: frame_score(v) for k, v in fits.items()}
        assert abs(best.estimates["fy"] - 0.6) < 3 * best.std_errors["fy"]
