"""Notebook and table habits (issue #15 item 4): DataFrames and short HTML summaries."""

import math

import numpy as np
import pytest

import slidespin as ss
from slidespin.motion.batch import simulate_many

pd = pytest.importorskip("pandas")


@pytest.fixture(scope="module")
def demo():
    body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)
    fr = ss.FrictionTensor(0.42, 0.54)
    return body, fr, ss.simulate(body, fr, ss.State.from_speed(1.0, 5.0, math.pi / 4))


def test_trajectory_to_pandas_holds_every_column_and_the_summary(demo):
    _, _, tr = demo
    df = tr.to_pandas()
    assert list(df.columns) == list(tr.COLUMNS)
    assert len(df) == tr.t.size
    for c in tr.COLUMNS:
        np.testing.assert_array_equal(df[c].to_numpy(), getattr(tr, c))
    assert df.attrs["status"] == tr.status and df.attrs["t_stop"] == tr.t_stop
    # the energy is the one of the arrays: it never increases along the rows
    e = 0.5 * (df.vx**2 + df.vy**2) + 0.5 * (tr.body.moment_of_inertia / tr.body.mass) * df.omega**2
    assert np.all(np.diff(e.to_numpy()) <= 1e-12)


def test_stop_results_to_pandas_matches_as_dict(demo):
    body, fr, _ = demo
    rng = np.random.default_rng(3)
    states = np.column_stack([np.zeros((5, 3)), rng.uniform(-1, 1, (5, 2)), rng.uniform(-9, 9, 5)])
    res = simulate_many(body, fr, states)
    df = res.to_pandas()
    assert len(df) == 5
    for k, col in res.as_dict().items():
        got = df[k].to_numpy()
        if col.dtype == object:
            assert list(got) == list(col)
        else:
            np.testing.assert_array_equal(got, col)


def test_html_summaries_are_short_and_name_the_status(demo):
    body, fr, tr = demo
    html = tr._repr_html_()
    assert "status" in html and tr.status in html and "<table>" in html
    assert len(html) < 3000  # no array dumps
    res = simulate_many(body, fr, np.array([[0, 0, 0, 1.0, 0, 2.0], [0, 0, 0, 0, 0, 0]]))
    h = res._repr_html_()
    assert "cases" in h and "stopped" in h and "at_rest" in h and len(h) < 3000
