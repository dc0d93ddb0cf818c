"""The speed law's curve (MODEL §14): the drawn factor is the law's own, the static ratio is
marked, and bad input is refused with the parameter's name."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

import slidespin as ss


@pytest.mark.parametrize(
    "law",
    [
        ss.PowerLaw(0.5, 1.0),
        ss.Stribeck(1.5, 0.01, 1.0),
        ss.SpeedTable([0.0, 0.1, 1.0], [1.3, 1.1, 1.0]),
    ],
)
def test_the_curve_is_the_factor_on_a_log_axis(law):
    ax = ss.plot_speed_law(law)
    x, y = ax.lines[0].get_data()
    assert ax.get_xscale() == "log"
    np.testing.assert_allclose(y, law.factor(x), rtol=1e-15)
    if isinstance(law, ss.Stribeck):  # two decades each side of vs
        assert x[0] <= law.vs / 100.0 and x[-1] >= law.vs * 100.0


def test_a_tensor_marks_its_static_ratio():
    fr = ss.FrictionTensor(0.3, 0.3, speed_law=ss.Stribeck(1.4, 0.05))
    ax = ss.plot_speed_law(fr, speeds=[1e-3, 1e-2, 1e-1, 1.0])
    assert ax.lines[1].get_ydata()[0] == pytest.approx(1.4)
    assert list(ax.lines[0].get_xdata()) == [1e-3, 1e-2, 1e-1, 1.0]


@pytest.mark.parametrize(
    ("law", "speeds", "match"),
    [
        (ss.FrictionTensor(0.3, 0.3), None, "has no speed law"),
        ("stribeck", None, "law = 'stribeck' is invalid"),
        (ss.PowerLaw(0.5), [0.0, 1.0], "speeds"),
        (ss.PowerLaw(0.5), [1.0], "speeds"),
    ],
)
def test_bad_input_is_refused(law, speeds, match):
    with pytest.raises(ValueError, match=match):
        ss.plot_speed_law(law, speeds=speeds)
