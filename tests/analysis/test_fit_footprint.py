"""Fitting friction parameters on footprints (slidespin.analysis.fit on Rectangle, Polygon, Pads, ...).

Independent truths: the known parameters of synthetic tracks (a dense simulation sampled by
plain linear interpolation, not by the fit's Hermite interpolant, plus Gaussian noise), the
binomial law of 95 % interval coverage over noise draws, and the closed-form cores (kerns) of
the linear pressure law: the middle-third rule of a rectangle (|ξc|/(L/6) + |ηc|/(W/6) ≤ 1)
and the ring's |r_G| ≤ (R² + r²)/(4R).
"""

from __future__ import annotations

import functools
import math
import warnings

import numpy as np
import pytest

import slidespin as ss
from slidespin.analysis._fit_problem import _core_scale
from slidespin.analysis.fit import FitWarning, fit

L, W = 0.12, 0.06  # rectangle [m]
TRUE = ss.FrictionTensor(0.42, 0.54)
STATES = (
    ss.State.from_speed(1.0, 8.0, theta=0.6, phi=0.2),
    ss.State.from_speed(0.9, -10.0, theta=2.0, phi=1.0),
)
SIGMA = {"x": 1e-3, "y": 1e-3, "phi": 1e-2}


def box():
    return ss.Body(ss.Rectangle(L, W), ss.UniformPressure(), mass=1.0)


@functools.cache
def dense(body, friction, state):
    """A dense simulation (τ steps of 0.002): the truth that synthetic tracks sample."""
    return ss.simulate(body, friction, state, max_step=0.002)


def clean_track(body, friction, state, n):
    tr = dense(body, friction, state)
    t = np.linspace(0.0, 1.05 * tr.t_stop, n)
    return t, {c: np.interp(t, tr.t, getattr(tr, c)) for c in ("x", "y", "phi")}


def noisy(t, clean, rng, sigma=SIGMA):
    return {"t": t, **{c: clean[c] + rng.normal(0.0, sigma[c], t.size) for c in clean}}


def test_footprint_bodies_are_accepted():
    body = box()
    assert body.is_footprint
    t, clean = clean_track(body, TRUE, STATES[0], 60)
    res = fit({"t": t, **clean}, body, TRUE, free=("fx",), sigma=SIGMA)
    # noise-free data made with the true tensor: the fit stays at the truth
    assert res.estimates["fx"] == pytest.approx(0.42, abs=1e-3 * res.std_errors["fx"] + 1e-6)
    assert res.chi2 < 1e-3
    assert res.body.patch == body.patch


def test_rectangle_track_recovers_fx_fy_within_the_reported_uncertainty():
    body = box()
    rng = np.random.default_rng(1)
    runs = [noisy(*clean_track(body, TRUE, st, 100), rng) for st in STATES]
    with warnings.catch_warnings():
        warnings.simplefilter("error", FitWarning)  # identifiable, converged, no bound
        res = fit(runs, body, ss.FrictionTensor(0.3, 0.3), free=("fx", "fy"))
    assert res.success
    for name, truth in (("fx", 0.42), ("fy", 0.54)):
        assert abs(res.estimates[name] - truth) < 3.0 * res.std_errors[name], name
        lo, hi = res.interval(name, 0.997)
        assert lo < truth < hi
        assert res.std_errors[name] < 0.01  # useful, not merely honest
    assert all(res.identifiable.values())
    for c, s in SIGMA.items():  # the estimated noise levels
        assert res.sigma[c] == pytest.approx(s, rel=0.15)


def test_rectangle_coverage_of_95_percent_intervals():
    """20 noise draws of one track of a box: the true fx, fy fall inside the reported 95 %
    intervals as often as binomial(20, 0.95) allows (mean 19, sd 0.97), and the scatter of
    the estimates matches the reported standard errors."""
    body = box()
    t, clean = clean_track(body, TRUE, STATES[0], 80)
    rng = np.random.default_rng(2027)
    truth = np.array([0.42, 0.54])
    est, se = [], []
    n = 20
    for _ in range(n):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FitWarning)
            res = fit(noisy(t, clean, rng), body, TRUE, free=("fx", "fy"))
        est.append([res.estimates["fx"], res.estimates["fy"]])
        se.append([res.std_errors["fx"], res.std_errors["fy"]])
    est, se = np.array(est), np.array(se)
    inside = np.abs(est - truth) < 1.959964 * se
    assert np.all(inside.sum(axis=0) >= 16), inside.sum(axis=0)  # 3 sd below the mean
    ratio = est.std(axis=0, ddof=1) / se.mean(axis=0)
    assert np.all((ratio > 0.6) & (ratio < 1.6)), ratio  # 20 draws: sd known to ~16 %
    assert np.all(np.abs(est.mean(axis=0) - truth) < se.mean(axis=0))  # bias below the SE


@pytest.mark.parametrize(
    "patch",
    [
        # a non-convex L-shaped robot part
        ss.Polygon(
            [(-0.05, -0.04), (0.06, -0.04), (0.06, 0.0), (0.0, 0.0), (0.0, 0.05), (-0.05, 0.05)]
        ),
        # a sled on two runners
        ss.Pads(
            [
                ss.Rectangle(0.16, 0.01, centre=(0.0, 0.04)),
                ss.Rectangle(0.16, 0.01, centre=(0.0, -0.04)),
            ]
        ),
    ],
    ids=["polygon", "pads"],
)
def test_other_footprints_recover_a_skew_tensor(patch):
    body = ss.Body(patch, ss.UniformPressure(), mass=1.0)
    truth = ss.FrictionTensor(0.4, 0.55, 0.05)
    rng = np.random.default_rng(7)
    runs = [noisy(*clean_track(body, truth, st, 80), rng) for st in STATES]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FitWarning)
        res = fit(runs, body, ss.FrictionTensor(0.3, 0.3), free=("fx", "fy", "f"))
    for name, value in (("fx", 0.4), ("fy", 0.55), ("f", 0.05)):
        assert abs(res.estimates[name] - value) < 3.0 * res.std_errors[name], name
        assert res.std_errors[name] < 0.02


def test_core_of_the_linear_law_is_the_closed_form_kern():
    rect = ss.Rectangle(L, W)
    # middle-third rule: along ξ up to L/6, along η up to W/6, along the diagonal to half
    assert _core_scale(rect, (L, 0.0)) * L == pytest.approx(L / 6.0, rel=1e-12)
    assert _core_scale(rect, (0.0, -W)) * W == pytest.approx(W / 6.0, rel=1e-12)
    s = _core_scale(rect, (L / 6.0, W / 6.0))
    assert s == pytest.approx(0.5, rel=1e-12)
    assert _core_scale(rect, (L / 100.0, 0.0)) == 1.0  # inside: no projection
    r, big = 0.05, 0.06
    ring = ss.Annulus(r, big)
    for ang in (0.0, 0.7, 2.5):
        d = np.array([math.cos(ang), math.sin(ang)]) * big
        assert _core_scale(ring, tuple(d)) * big == pytest.approx(
            (big**2 + r**2) / (4.0 * big), rel=1e-12
        )
    # a footprint placed off the origin: the core is about its area centroid
    moved = ss.Rectangle(L, W, centre=(0.3, -0.2), angle=0.0)
    assert _core_scale(moved, (L, 0.0)) * L == pytest.approx(L / 6.0, rel=1e-12)


def test_linear_law_centroid_on_a_rectangle_from_a_nearby_guess():
    """Noise-free tracks of a box with G off-centre: fx, fy and G = (ξc, ηc) are recovered.

    Measured caveat (not hidden): from the guess G = (0, 0) this two-run problem has a local
    minimum at (0.0089, 0.0012) m with χ² = 0.07 (within one reported standard error of the
    truth at σ = 1 mm); from a guess nearer the truth the fit reaches the truth."""
    true_body = ss.Body(ss.Rectangle(L, W), ss.LinearPressure(0.008, -0.003), 1.0, 6e-4)
    runs = [dict(zip(("t", "c"), clean_track(true_body, TRUE, st, 100))) for st in STATES]
    runs = [{"t": r["t"], **r["c"]} for r in runs]
    guess = ss.Body(ss.Rectangle(L, W), ss.LinearPressure(0.004, -0.001), 1.0, 6e-4)
    res = fit(
        runs, guess, ss.FrictionTensor(0.4, 0.5), free=("fx", "fy", "xi_c", "eta_c"), sigma=SIGMA
    )
    for name, truth in (("fx", 0.42), ("fy", 0.54), ("xi_c", 0.008), ("eta_c", -0.003)):
        assert abs(res.estimates[name] - truth) < 0.05 * res.std_errors[name], name
    # the fitted law is valid on the rectangle (p >= 0: G inside the middle-third rhombus)
    xi, eta = res.body.pressure.centroid
    assert abs(xi) / (L / 6.0) + abs(eta) / (W / 6.0) <= 1.0


def test_command_line_fit_on_a_rectangle_case(tmp_path, capsys, monkeypatch):
    """`slidespin fit DATA.csv --case BOX.toml --json` with a [patch] rectangle."""
    import importlib
    import json

    cli = importlib.import_module("slidespin.cli.main")

    if not any(name == "fit" for name, *_ in cli._PLUGINS):  # as tests/test_fit_cli.py
        monkeypatch.setattr(
            cli,
            "_PLUGINS",
            cli._PLUGINS
            + (("fit", "slidespin.cli.fit", "fit friction parameters to tracked motion"),),
        )
    body = box()
    rng = np.random.default_rng(4)
    runs = [noisy(*clean_track(body, TRUE, st, 80), rng) for st in STATES]
    data = tmp_path / "box.csv"
    with open(data, "w", encoding="utf-8") as fh:
        fh.write("run,t,x,y,phi\n")
        for k, run in enumerate(runs):
            for i in range(run["t"].size):
                fh.write(
                    f"{k},"
                    + ",".join(repr(float(run[c][i])) for c in ("t", "x", "y", "phi"))
                    + "\n"
                )
    case = tmp_path / "box.toml"
    case.write_text(
        f'[patch]\nshape = "rectangle"\nlength = {L}\nwidth = {W}\n'
        '[pressure]\nlaw = "uniform"\n[friction]\nfx = 0.3\nfy = 0.3\n'
        "[body]\nmass = 1.0\n"
    )
    code = cli.main(["fit", str(data), "--case", str(case), "--free", "fx,fy", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == 0
    assert out["n_runs"] == 2 and out["n_points"] == 480
    for name, truth in (("fx", 0.42), ("fy", 0.54)):
        assert abs(out["estimates"][name] - truth) < 3.0 * out["std_errors"][name], name
        assert out["std_errors"][name] < 0.01
