"""Derivatives of a motion (MODEL §15) against independent truth: Richardson-extrapolated
differences of whole simulations (tests/references/stop_differences.py), closed forms of
pure translation and of a spinning disk, and the path's derivatives at fixed time."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from stop_differences import OUTPUTS, derivatives

import slidespin as ss
import slidespin.motion.simulate as simulate_module
from slidespin.motion.sensitivity import PARAMETERS

G = 9.81
ALL = PARAMETERS


def _close(got, ref, rel=1e-6):
    """|got − ref| ≤ rel · max(|ref|, 1e-2 · the row's largest |ref|) per output (the
    reference's own round-off is about 1e-12/h of the stop values)."""
    floor = 1e-2 * max(abs(x) for x in ref.values() if math.isfinite(x))
    bad = {
        q: (got[q], ref[q])
        for q in OUTPUTS
        if math.isfinite(ref[q]) and abs(got[q] - ref[q]) > rel * max(abs(ref[q]), floor)
    }
    assert not bad, bad


CASES = {
    "ellipse_linear_skew": (
        ss.Body(ss.Ellipse(0.1, 0.06), ss.LinearPressure(0.01, 0.005), mass=1.0),
        ss.FrictionTensor(0.3, 0.4, 0.05),
        ss.State(x=0.2, y=-0.1, phi=0.3, vx=1.0, vy=0.3, omega=5.0),
        ALL,
    ),
    # near a boundary of its endings (fx 1 % higher ends in pure sliding): β* curves
    # strongly, and the reference's differences need a smaller step (REL below)
    "ellipse_hertz_body_frame": (
        ss.Body(ss.Ellipse(0.08, 0.05), ss.HertzPressure(), mass=2.0),
        ss.FrictionTensor(0.25, 0.45, -0.03, frame="body"),
        ss.State(vx=-0.7, vy=0.9, omega=-8.0),
        ("fx", "fy", "f", "moment_of_inertia", "vx", "vy", "omega"),
    ),
    "rectangle_uniform_angle": (
        ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.5),
        ss.FrictionTensor(0.3, 0.5, angle=0.4),
        ss.State(vx=0.8, vy=0.2, omega=6.0),
        ALL,
    ),
    "ring_linear": (
        ss.Body(ss.Annulus(0.05, 0.07), ss.LinearPressure(0.004, -0.003), mass=1.0),
        ss.FrictionTensor(0.2, 0.35),
        ss.State(vx=0.5, vy=-0.4, omega=-4.0),
        ALL,
    ),
    "polygon_L": (
        ss.Body(
            ss.Polygon([(0, 0), (0.2, 0), (0.2, 0.06), (0.07, 0.06), (0.07, 0.16), (0, 0.16)]),
            ss.UniformPressure(),
            mass=1.0,
        ),
        ss.FrictionTensor(0.4, 0.3, 0.02),
        ss.State(vx=0.6, vy=0.6, omega=3.0),
        ("fx", "f", "xi_c", "eta_c", "moment_of_inertia", "vy", "omega"),
    ),
}


#: the reference's relative step per case (default 1e-3)
REL = {"ellipse_hertz_body_frame": 1e-4}


@pytest.mark.parametrize("case", sorted(CASES))
def test_stop_derivatives_match_richardson_differences(case):
    body, friction, state, names = CASES[case]
    tr = ss.simulate(body, friction, state)
    assert tr.eigenvalue_ratio < 0.0  # an attracting ending: every derivative exists
    got = ss.stop_sensitivities(body, friction, state, parameters=names)
    assert set(got) == set(names)
    for name in names:
        assert set(got[name]) == set(OUTPUTS)
        _close(got[name], derivatives(body, friction, state, name, rel=REL.get(case, 1e-3)))


@pytest.mark.parametrize("case", ["ellipse_linear_skew", "polygon_L"])
def test_stop_derivatives_integrated_with_the_motion(case, monkeypatch):
    # the other route (a looser rtol than COLLOCATE_RTOL, or no J somewhere): the
    # variational equations integrated with the motion under a joint error control
    monkeypatch.setattr(simulate_module, "COLLOCATE_RTOL", 0.0)
    body, friction, state, names = CASES[case]
    got = ss.stop_sensitivities(body, friction, state, parameters=names)
    for name in names:
        _close(got[name], derivatives(body, friction, state, name, rel=REL.get(case, 1e-3)))


def test_pure_translation_closed_forms():
    # t_stop = v/(μ g), x_stop = v²/(2 μ g); along x only fx acts, and its skew partner f
    # pushes sideways: y_stop = f/μ · x_stop for small f
    body = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=2.0)
    mu, v = 0.3, 1.2
    d = ss.stop_sensitivities(body, ss.FrictionTensor(mu, mu), ss.State(vx=v),
                              parameters=("vx", "fx", "fy", "vy"))  # fmt: skip
    assert d["vx"]["t_stop"] == pytest.approx(1.0 / (mu * G), rel=1e-9)
    assert d["vx"]["x"] == pytest.approx(v / (mu * G), rel=1e-9)
    assert d["fx"]["t_stop"] == pytest.approx(-v / (mu**2 * G), rel=1e-9)
    assert d["fx"]["x"] == pytest.approx(-(v**2) / (2 * mu**2 * G), rel=1e-9)
    # fy does not act on a motion along x; vy turns the path: ∂y/∂vy = v/(μ g) / 2
    assert d["fy"]["x"] == pytest.approx(0.0, abs=1e-12)
    assert d["vy"]["y"] == pytest.approx(v / (2 * mu * G), rel=1e-9)
    assert d["vy"]["x"] == pytest.approx(0.0, abs=1e-12)
    for p in d:
        assert d[p]["phi"] == pytest.approx(0.0, abs=1e-12)


def test_tensor_entries_at_the_ends_of_their_range():
    # fx at its largest valid value and fy at its smallest: the central differences of the
    # rows step outside the range (the rows carry rates only), and the derivatives are still
    # the closed forms of a translation along x (they used to fail with "fx = 5.00005 is
    # invalid")
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.UniformPressure(), mass=1.0)
    mu, v = 5.0, 2.0
    d = ss.stop_sensitivities(body, ss.FrictionTensor(mu, 1e-6), ss.State(vx=v),
                              parameters=("fx", "fy"))  # fmt: skip
    assert d["fx"]["t_stop"] == pytest.approx(-v / (mu**2 * G), rel=1e-9)
    assert d["fx"]["x"] == pytest.approx(-(v**2) / (2 * mu**2 * G), rel=1e-9)
    assert d["fy"]["x"] == pytest.approx(0.0, abs=1e-12)
    assert d["fy"]["t_stop"] == pytest.approx(0.0, abs=1e-12)


def test_spinning_disk_closed_forms():
    # a disk spinning about its centre: M = (2/3) (fx + fy)/2 m g a, t_stop = I ω/M,
    # φ_stop = I ω²/(2M)
    a, m, w = 0.1, 2.0, 10.0
    body = ss.Body(ss.Ellipse(a, a), ss.UniformPressure(), mass=m)
    fx, fy = 0.3, 0.4
    inertia = body.moment_of_inertia
    M = (2 / 3) * 0.5 * (fx + fy) * m * G * a
    d = ss.stop_sensitivities(body, ss.FrictionTensor(fx, fy), ss.State(omega=w),
                              parameters=("omega", "moment_of_inertia", "fx", "fy"))  # fmt: skip
    t = inertia * w / M
    assert d["omega"]["t_stop"] == pytest.approx(inertia / M, rel=1e-9)
    assert d["omega"]["phi"] == pytest.approx(inertia * w / M, rel=1e-9)
    assert d["moment_of_inertia"]["t_stop"] == pytest.approx(w / M, rel=1e-9)
    assert d["fx"]["t_stop"] == pytest.approx(-t / (fx + fy), rel=1e-8)
    assert d["fy"]["phi"] == pytest.approx(-t * w / 2 / (fx + fy), rel=1e-8)
    for p in d:  # pure spin stays pure spin: G does not move, β* stays 0
        assert d[p]["x"] == d[p]["y"] == d[p]["beta_stop"] == 0.0


def test_path_derivatives_at_fixed_time_pure_translation():
    # x(t) = v t − μ g t²/2, vx(t) = v − μ g t on [0, v/(μ g))
    body = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
    mu, v = 0.25, 1.5
    tr = ss.simulate(body, ss.FrictionTensor(mu, mu), ss.State(vx=v), max_step=0.05,
                     sensitivities=("vx", "fx"))  # fmt: skip
    sens = tr.sensitivities
    assert isinstance(sens, ss.Sensitivities)
    np.testing.assert_array_equal(sens.t, tr.t)
    t = tr.t[:-1]
    np.testing.assert_allclose(sens["vx"]["x"][:-1], t, rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(sens["vx"]["vx"][:-1], 1.0, rtol=1e-8)
    np.testing.assert_allclose(sens["fx"]["x"][:-1], -G * t**2 / 2, rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(sens["fx"]["vx"][:-1], -G * t, rtol=1e-8, atol=1e-12)
    # the last row is the stop's
    assert sens["fx"]["x"][-1] == pytest.approx(sens.stop["fx"]["x"], rel=1e-12)
    assert sens["vx"]["vx"][-1] == 0.0


def test_path_derivatives_match_differences_of_interpolated_paths():
    from scipy.interpolate import CubicHermiteSpline

    body, friction, state, _ = CASES["ellipse_linear_skew"]
    tr = ss.simulate(body, friction, state, sensitivities=("omega",))
    rows = np.flatnonzero((tr.t > 0.0) & (tr.t < 0.8 * tr.t_stop))  # both runs still move
    assert rows.size >= 5
    t = tr.t[rows]
    h = 1e-4 * state.omega

    def path(w):
        r = ss.simulate(body, friction, ss.State(state.x, state.y, state.phi, state.vx,
                                                 state.vy, w), rtol=1e-12)  # fmt: skip
        return CubicHermiteSpline(r.t, r.phi, r.omega)(t), CubicHermiteSpline(r.t, r.x, r.vx)(t)

    (pu, xu), (pd, xd) = path(state.omega + h), path(state.omega - h)
    np.testing.assert_allclose(tr.sensitivities["omega"]["phi"][rows], (pu - pd) / (2 * h),
                               rtol=1e-4)  # fmt: skip
    np.testing.assert_allclose(tr.sensitivities["omega"]["x"][rows], (xu - xd) / (2 * h),
                               rtol=1e-4, atol=1e-9)  # fmt: skip


def test_unstable_pure_sliding_ending_warns_and_gives_nan_beta():
    body = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0)
    with pytest.warns(RuntimeWarning, match="omega"):
        d = ss.stop_sensitivities(body, ss.FrictionTensor(0.3, 0.3), ss.State(vx=1.0),
                                  parameters=("omega", "vx"))  # fmt: skip
    assert math.isnan(d["omega"]["beta_stop"])
    assert d["vx"]["beta_stop"] == 0.0
    # the stop pose's derivatives still exist: a small spin turns the body, does not move G
    assert d["omega"]["phi"] > 0.0


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"parameters": ("mu",)}, "parameters"),
        ({"parameters": ()}, "parameters"),
        ({"parameters": ("fx", "fx")}, "parameters"),
        ({"parameters": 3}, "parameters"),
    ],
)
def test_bad_parameters(kwargs, match):
    body = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0)
    with pytest.raises(ValueError, match=match):
        ss.stop_sensitivities(body, ss.FrictionTensor(0.3, 0.3), ss.State(vx=1.0), **kwargs)


def test_refusals():
    body = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0)
    fr = ss.FrictionTensor(0.3, 0.3)
    with pytest.raises(ValueError, match="at rest"):
        ss.stop_sensitivities(body, fr, ss.State())
    with pytest.raises(ValueError, match="t_end"):
        ss.simulate(body, fr, ss.State(vx=1.0), t_end=1.0, sensitivities=("fx",))
    with pytest.raises(ValueError, match="xi_c"):
        hertz = ss.Body(ss.Ellipse(0.1, 0.1), ss.HertzPressure(), mass=1.0)
        ss.stop_sensitivities(hertz, fr, ss.State(vx=1.0, omega=2.0), parameters=("xi_c",))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        plain = ss.simulate(body, fr, ss.State(vx=1.0, omega=3.0))
    assert plain.sensitivities is None


def test_round_body_isotropic_beta_kink_is_nan_not_a_number_made_up():
    # a disk under an isotropic tensor: every terminal direction is one; fx breaks the
    # symmetry and β* changes like |Δfx| (no derivative), f keeps it (derivative 0)
    disk = ss.Body(ss.Disk(0.1), ss.UniformPressure(), 1.0)
    state = ss.State(vx=1.0, vy=0.5, omega=10.0)
    with pytest.warns(RuntimeWarning, match="not differentiable"):
        d = ss.stop_sensitivities(disk, ss.FrictionTensor(0.4, 0.4), state,
                                  parameters=("fx", "f", "omega"))  # fmt: skip
    assert math.isnan(d["fx"]["beta_stop"])
    assert abs(d["f"]["beta_stop"]) < 1e-8
    h = 4e-5
    up = ss.simulate(disk, ss.FrictionTensor(0.4 + h, 0.4), state, rtol=1e-12).beta_stop
    down = ss.simulate(disk, ss.FrictionTensor(0.4 - h, 0.4), state, rtol=1e-12).beta_stop
    base = ss.simulate(disk, ss.FrictionTensor(0.4, 0.4), state, rtol=1e-12).beta_stop
    assert up - base > 1e3 * abs(up - down)  # a kink: both sides move the same way
    assert math.isfinite(d["fx"]["t_stop"]) and math.isfinite(d["omega"]["beta_stop"])


def test_parameters_none_is_a_clear_error():
    body = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0)
    with pytest.raises(ValueError, match="parameters"):
        ss.stop_sensitivities(body, ss.FrictionTensor(0.3, 0.3), ss.State(vx=1.0),
                              parameters=None)  # fmt: skip


def test_sensitivities_in_json_and_pandas():
    import json

    pytest.importorskip("pandas")
    body, friction, state, _ = CASES["ellipse_linear_skew"]
    tr = ss.simulate(body, friction, state, sensitivities=("fx", "omega"))
    doc = json.loads(tr.to_json())
    assert doc["stop_sensitivities"]["fx"]["t_stop"] == pytest.approx(
        tr.sensitivities.stop["fx"]["t_stop"], rel=1e-15
    )
    df = tr.to_pandas()
    np.testing.assert_array_equal(df["d_x/d_omega"].to_numpy(), tr.sensitivities["omega"]["x"])
    assert "d_vy/d_fx" in df.columns and len(df) == tr.t.size
    assert "stop_sensitivities" not in json.loads(ss.simulate(body, friction, state).to_json())
