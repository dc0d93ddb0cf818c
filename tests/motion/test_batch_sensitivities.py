"""``simulate_many(..., sensitivities=...)``: the stop's derivatives as columns per case
(MODEL §15), the same numbers as one ``stop_sensitivities`` call per case."""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss

BODY = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
FRICTION = ss.FrictionTensor(0.3, 0.4, 0.02)
STATES = [ss.State(vx=1.0, omega=3.0), ss.State(), ss.State(vy=0.5, omega=-2.0, phi=0.4)]


def test_columns_match_single_runs_and_rest_is_nan():
    res = ss.simulate_many(BODY, FRICTION, STATES, sensitivities=("fx", "omega"))
    cols = res.sensitivities
    assert set(cols) == {f"d_{q}/d_{p}" for p in ("fx", "omega")
                         for q in ("t_stop", "x", "y", "phi", "beta_stop")}  # fmt: skip
    for i, st in enumerate(STATES):
        if (st.vx, st.vy, st.omega) == (0.0, 0.0, 0.0):
            assert all(math.isnan(c[i]) for c in cols.values())
            continue
        one = ss.stop_sensitivities(BODY, FRICTION, st, parameters=("fx", "omega"))
        for p in one:
            for q, val in one[p].items():
                assert cols[f"d_{q}/d_{p}"][i] == pytest.approx(val, rel=1e-12, nan_ok=True)
    assert "d_phi/d_fx" in res.as_dict()


def test_no_columns_unless_asked_and_bad_names():
    assert ss.simulate_many(BODY, FRICTION, STATES[:1]).sensitivities is None
    with pytest.raises(ValueError, match="sensitivities = "):
        ss.simulate_many(BODY, FRICTION, STATES[:1], sensitivities=("mu",))
    pd = pytest.importorskip("pandas")
    df = ss.simulate_many(BODY, FRICTION, STATES[:1], sensitivities="vx").to_pandas()
    assert isinstance(df, pd.DataFrame) and np.isfinite(df["d_x/d_vx"][0])


def test_a_parameter_the_body_cannot_vary_is_refused_before_any_run():
    blade = ss.Body(ss.Blade(0.2), ss.UniformPressure(), mass=1.0)
    with pytest.raises(ValueError, match="xi_c"):
        ss.simulate_many(blade, FRICTION, STATES[:1], sensitivities=("fx", "xi_c"))


def test_every_entry_gives_the_same_beta_rule():
    # a pure spin of a disk, whose pure-spinning ending does not attract (the start lies on
    # the invariant set): a velocity makes β* jump; NaN everywhere, not 0 somewhere
    disk = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0)
    iso = ss.FrictionTensor(0.3, 0.3)
    spin = ss.State(omega=10.0)
    tr = ss.simulate(disk, iso, spin)
    if tr.eigenvalue_ratio < 0.0:
        pytest.skip("this pure spin attracts nearby motions here")
    with pytest.warns(RuntimeWarning, match="jumps"):
        one = ss.stop_sensitivities(disk, iso, spin, parameters=("vx",))
    with pytest.warns(RuntimeWarning, match="jumps"):
        many = ss.simulate_many(disk, iso, [spin], sensitivities=("vx",))
    assert math.isnan(one["vx"]["beta_stop"]) and math.isnan(
        many.sensitivities["d_beta_stop/d_vx"][0]
    )
