"""Notebook and table habits of FitResult: ``repr``, ``_repr_html_`` and ``to_pandas``.

Independent truth: a pure translation x = x0 + v0 t − (g/2) fx t² is linear in (x0, v0, fx),
so the fit's estimates, standard errors and 95 % intervals are those of ordinary least squares
(computed here with numpy), and a run that only slides along x cannot tell fy (symmetry).
"""

from __future__ import annotations

import math
import re
import warnings

import numpy as np
import pytest

import slidespin as ss
from slidespin.analysis.fit import IdentifiabilityWarning, fit

pd = pytest.importorskip("pandas")

G = 9.81
Z95 = 1.959963984540054  # the 97.5 % quantile of the standard normal
SIG = 1e-3


def plate():
    return ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)


@pytest.fixture(scope="module")
def regression():
    """A fit of fx to a noisy pure translation, and the OLS truth (beta, covariance)."""
    rng = np.random.default_rng(11)
    fx, v0 = 0.4, 1.0
    t = np.linspace(0.0, 0.9 * v0 / (fx * G), 70)
    x = 0.01 + v0 * t - 0.5 * fx * G * t**2 + rng.normal(0.0, SIG, t.size)
    res = fit(
        {"t": t, "x": x}, plate(), ss.FrictionTensor(0.3, 0.3), free=("fx",), sigma={"x": SIG}
    )
    X = np.column_stack([np.ones_like(t), t, -0.5 * G * t**2])
    beta = np.linalg.lstsq(X, x, rcond=None)[0]
    cov = SIG**2 * np.linalg.inv(X.T @ X)
    return res, beta, cov


@pytest.fixture(scope="module")
def unidentifiable():
    """A run sliding only along x: fy is not determined (closed-form translation)."""
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
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = fit(run, plate(), ss.FrictionTensor(0.3, 0.3), free=("fx", "fy"))
    assert any(issubclass(w.category, IdentifiabilityWarning) for w in caught)
    return res


def numbers(text):
    return re.findall(r"[-+]?\d+\.?\d*(?:e[-+]?\d+)?", text)


def test_to_pandas_is_the_least_squares_table(regression):
    res, beta, cov = regression
    df = res.to_pandas()
    assert list(df.index) == ["fx", "run0.x", "run0.vx"]
    assert df.index.name == "parameter"
    assert list(df.columns) == ["estimate", "std_error", "ci_low", "ci_high", "identifiable"]
    want = {
        "fx": (beta[2], cov[2, 2]),
        "run0.x": (beta[0], cov[0, 0]),
        "run0.vx": (beta[1], cov[1, 1]),
    }
    for name, (b, var) in want.items():
        se = math.sqrt(var)
        row = df.loc[name]
        assert row["estimate"] == pytest.approx(b, rel=1e-7, abs=1e-9)
        assert row["std_error"] == pytest.approx(se, rel=1e-5)
        assert row["ci_low"] == pytest.approx(b - Z95 * se, rel=1e-6, abs=1e-8)
        assert row["ci_high"] == pytest.approx(b + Z95 * se, rel=1e-6, abs=1e-8)
        assert bool(row["identifiable"])
    # a wider level widens the interval by the ratio of the normal quantiles
    df99 = res.to_pandas(level=0.99)
    half = (df99["ci_high"] - df99["ci_low"]) / (df["ci_high"] - df["ci_low"])
    assert np.allclose(half, 2.5758293035489 / Z95, rtol=1e-9)
    assert df.attrs["n_points"] == 70 and df.attrs["dof"] == 67
    assert df.attrs["level"] == 0.95
    assert df.attrs["chi2"] == pytest.approx(res.chi2)


def test_to_pandas_bad_level(regression):
    for bad in (0.0, 1.0, 1.5, float("nan"), "x"):
        with pytest.raises(ValueError, match="level"):
            regression[0].to_pandas(level=bad)


def test_repr_is_one_short_line_with_estimates_and_errors(regression):
    res, beta, cov = regression
    text = repr(res)
    assert "\n" not in text and len(text) < 300
    m = re.search(r"fx=([-+0-9.e]+) ± ([-+0-9.e]+)", text)
    assert m, text
    assert float(m.group(1)) == pytest.approx(beta[2], rel=1e-5)
    assert float(m.group(2)) == pytest.approx(math.sqrt(cov[2, 2]), rel=0.05)  # 2 digits
    assert "points=70" in text and "runs=1" in text
    assert "warnings" not in text  # a clean fit has none
    assert "[" not in text  # no array dumps


def test_html_summary_holds_the_table_and_no_arrays(regression):
    res, beta, cov = regression
    html = res._repr_html_()
    assert html.startswith("<table><caption>FitResult</caption>") and html.endswith("</table>")
    se = math.sqrt(cov[2, 2])
    assert f"{res.estimates['fx']:.6g}" in html
    assert float(f"{res.estimates['fx']:.6g}") == pytest.approx(beta[2], rel=1e-5)
    lo, hi = beta[2] - Z95 * se, beta[2] + Z95 * se
    m = re.search(r"\[([-+0-9.e]+), ([-+0-9.e]+)\]", html)
    assert m and float(m.group(1)) == pytest.approx(lo, rel=1e-5)
    assert float(m.group(2)) == pytest.approx(hi, rel=1e-5)
    assert "chi2 / dof" in html and "70 values in 1 run(s)" in html
    # short: the data (70 points) are not dumped
    assert len(numbers(html)) < 40 and len(html) < 3000


def test_unidentifiable_parameter_and_its_warning_are_shown(unidentifiable):
    res = unidentifiable
    text = repr(res)
    assert "fy=" in text and "not identifiable" in text
    assert f"warnings={len(res.warnings)}" in text and len(res.warnings) >= 1
    html = res._repr_html_()
    assert "not identifiable" in html
    assert "warnings" in html and "cannot determine fy" in html
    df = res.to_pandas()
    assert df.loc["fy", "std_error"] == math.inf
    assert not df.loc["fy", "identifiable"]
    assert df.loc["fy", "ci_low"] == -math.inf and df.loc["fy", "ci_high"] == math.inf
    assert bool(df.loc["fx", "identifiable"]) and math.isfinite(df.loc["fx", "std_error"])


def test_html_escapes_the_messages(regression):
    from dataclasses import replace

    res = replace(regression[0], warnings=("a <b> & c",), message="x < y")
    html = res._repr_html_()
    assert "a &lt;b&gt; &amp; c" in html and "x &lt; y" in html
    assert "<b>" not in html
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        repr(res)
