"""The batch engine: simulate_many equals simulate case by case (to the last bit), per-case
parameter arrays, at-rest rows, chunking, and input errors that name the parameter."""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss
from conftest import LAWS, make_law
from slidespin.motion import batch
from slidespin.motion.batch import CASE_FIELDS, StopResults, simulate_cases, simulate_many


def single(body, fr, row, g=9.81, rtol=1e-10):
    tr = ss.simulate(body, fr, ss.State(*row), g=g, rtol=rtol)
    return (
        tr.t_stop,
        tr.stop_state.x,
        tr.stop_state.y,
        tr.stop_state.phi,
        tr.distance,
        tr.beta_stop,
        tr.theta_stop,
        tr.ending,
        tr.status,
        tr.n_steps,
    )


def row_of(res: StopResults, i):
    return (
        res.t_stop[i],
        res.x_stop[i],
        res.y_stop[i],
        res.phi_stop[i],
        res.path_length[i],
        res.beta_stop[i],
        res.theta_stop[i],
        res.ending[i],
        res.status[i],
        res.n_steps[i],
    )


def same(a, b):
    return all(
        x == y or (isinstance(x, float) and math.isnan(x) and math.isnan(y)) for x, y in zip(a, b)
    )


def states(rng, n):
    s = np.column_stack(
        [
            rng.normal(scale=0.1, size=(n, 2)),
            rng.uniform(-3, 3, n),
            rng.normal(scale=0.7, size=(n, 2)),
            rng.normal(scale=12.0, size=n),
        ]
    )
    s[1, 3:] = 0.0  # at rest
    s[2, 5] = 0.0  # pure translation
    s[3, 3:5] = 0.0  # pure spin
    return s


@pytest.mark.parametrize("law", LAWS)
def test_simulate_many_equals_simulate_bit_for_bit(law, rng):
    body = ss.Body(ss.Ellipse(0.1, 0.055), make_law(law, 0.1, 0.055), mass=1.7)
    fr = ss.FrictionTensor(0.32, 0.51, f=0.04, angle=0.6)
    s = states(rng, 7)
    res = simulate_many(body, fr, s, g=9.7)
    assert len(res) == 7
    for i in range(7):
        assert same(row_of(res, i), single(body, fr, s[i], g=9.7)), i


def test_simulate_many_body_tensor_and_rtol(rng):
    body = ss.Body(ss.Circle(0.05), ss.HertzPressure(), mass=0.4, moment_of_inertia=3e-4)
    fr = ss.FrictionTensor(0.2, 0.45, f=-0.1, frame="body", angle=0.3)
    s = states(rng, 5)
    res = simulate_many(body, fr, s, rtol=1e-8)
    for i in range(5):
        assert same(row_of(res, i), single(body, fr, s[i], rtol=1e-8)), i


def test_at_rest_rows():
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.UniformPressure(), mass=1.0)
    s = np.array([[0.3, -0.2, 1.1, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.5, 0.0, 2.0]])
    res = simulate_many(body, ss.FrictionTensor(0.3, 0.4), s)
    assert res.status[0] == "at_rest" and res.ending[0] == "at_rest"
    assert (res.t_stop[0], res.x_stop[0], res.y_stop[0], res.phi_stop[0]) == (0.0, 0.3, -0.2, 1.1)
    assert res.path_length[0] == 0.0 and res.n_steps[0] == 0
    assert math.isnan(res.beta_stop[0]) and math.isnan(res.theta_stop[0])
    assert res.status[1] == "stopped" and res.t_stop[1] > 0


def test_empty_batch():
    body = ss.Body(ss.Circle(0.1), ss.UniformPressure(), mass=1.0)
    res = simulate_many(body, ss.FrictionTensor(0.3, 0.3), np.empty((0, 6)))
    assert len(res) == 0 and res.t_stop.shape == (0,) and res.ending.shape == (0,)


def test_chunks_give_the_same_numbers(monkeypatch, rng):
    body = ss.Body(ss.Ellipse(0.1, 0.07), ss.BoussinesqPressure(), mass=1.0)
    fr = ss.FrictionTensor(0.3, 0.5)
    s = states(rng, 9)
    whole = simulate_many(body, fr, s)
    monkeypatch.setattr(batch, "CHUNK", 4)
    chunked = simulate_many(body, fr, s)
    for name in (
        "t_stop",
        "x_stop",
        "y_stop",
        "phi_stop",
        "path_length",
        "beta_stop",
        "theta_stop",
        "ending_code",
        "status_code",
        "n_steps",
    ):
        np.testing.assert_array_equal(getattr(whole, name), getattr(chunked, name))


def test_results_are_per_case_arrays_without_steps(rng):
    body = ss.Body(ss.Ellipse(0.1, 0.07), ss.UniformPressure(), mass=1.0)
    res = simulate_many(body, ss.FrictionTensor(0.3, 0.5), states(rng, 6))
    for name in (
        "t_stop",
        "x_stop",
        "y_stop",
        "phi_stop",
        "path_length",
        "beta_stop",
        "theta_stop",
        "ending_code",
        "status_code",
        "n_steps",
    ):
        assert getattr(res, name).shape == (6,), name
    d = res.as_dict()
    assert set(d) >= {"t_stop", "ending", "status", "n_steps"}
    assert set(d["ending"]) <= {"mixed", "pure_sliding", "pure_spinning", "at_rest", "spiral"}


def test_simulate_cases_per_case_parameters(rng):
    """Every parameter varying per case: the same numbers as simulate(), up to the rounding
    of building the tensor from (fx, fy, f, angle) with scalar formulas."""
    n = 6
    cases = dict(
        a=rng.uniform(0.05, 0.2, n),
        b=rng.uniform(0.03, 0.2, n),
        law=np.array(["uniform", "linear", "boussinesq", "hertz", "linear", "uniform"]),
        xi_c=np.full(n, 0.004),
        eta_c=np.full(n, -0.002),
        fx=rng.uniform(0.2, 0.5, n),
        fy=rng.uniform(0.2, 0.5, n),
        f=rng.uniform(-0.05, 0.05, n),
        frame=np.array(["plane", "body"] * 3),
        angle=rng.uniform(0, 3, n),
        mass=rng.uniform(0.5, 2.0, n),
        g=rng.uniform(9.0, 10.0, n),
        x=rng.normal(size=n),
        y=rng.normal(size=n),
        phi=rng.normal(size=n),
        vx=rng.normal(size=n),
        vy=rng.normal(size=n),
        omega=rng.normal(scale=10, size=n),
    )
    res = simulate_cases(cases)
    for i in range(n):
        law = str(cases["law"][i])
        a, b = cases["a"][i], cases["b"][i]
        pl = (
            ss.LinearPressure(cases["xi_c"][i], cases["eta_c"][i])
            if law == "linear"
            else make_law(law, a, b)
        )
        body = ss.Body(ss.Ellipse(a, b), pl, mass=cases["mass"][i])
        fr = ss.FrictionTensor(
            cases["fx"][i], cases["fy"][i], cases["f"][i], str(cases["frame"][i]), cases["angle"][i]
        )
        want = single(
            body, fr, [cases[k][i] for k in ("x", "y", "phi", "vx", "vy", "omega")], g=cases["g"][i]
        )
        got = row_of(res, i)
        assert got[7:9] == want[7:9], i
        assert np.allclose(got[:5], want[:5], rtol=1e-9, atol=1e-12), i
        if want[7] == "mixed":
            assert got[5] == pytest.approx(want[5], rel=1e-7)
            assert got[6] == pytest.approx(want[6], abs=1e-7)


def test_simulate_cases_scalars_broadcast():
    res = simulate_cases(dict(a=0.1, b=0.1, fx=0.3, fy=0.3, omega=[1.0, 2.0, 4.0]))
    assert len(res) == 3
    # pure spin of a uniform disk: t_stop = I ω₀ / M with M = (2/3) f m g a, I = m a²/2
    want = 0.5 * 0.1**2 * np.array([1.0, 2.0, 4.0]) / (2 / 3 * 0.3 * 9.81 * 0.1)
    assert np.allclose(res.t_stop, want, rtol=1e-10)
    assert list(res.ending) == ["pure_spinning"] * 3


@pytest.mark.parametrize(
    "bad, message",
    [
        (np.zeros((3, 5)), "initial_states has shape"),
        (np.zeros(6), "initial_states has shape"),
        ([["a"] * 6], "initial_states must be an (N, 6) array"),
        (np.array([[0, 0, 0, np.nan, 0, 1.0]]), "initial_states[0, 3] (vx)"),
        (np.array([[0, 0, 0, 0, 0, np.inf]]), "initial_states[0, 5] (omega)"),
    ],
)
def test_simulate_many_bad_states(bad, message):
    body = ss.Body(ss.Circle(0.1), ss.UniformPressure(), mass=1.0)
    with pytest.raises(ValueError) as exc:
        simulate_many(body, ss.FrictionTensor(0.3, 0.3), bad)
    assert message in str(exc.value)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(rtol=0.0), "rtol"),
        (dict(rtol=1e-2), "rtol"),
        (dict(max_steps=0), "max_steps"),
        (dict(max_steps=1.5), "max_steps"),
        (dict(max_steps=True), "max_steps"),
        (dict(g=-1.0), "g"),
    ],
)
def test_simulate_many_bad_options(kwargs, message):
    body = ss.Body(ss.Circle(0.1), ss.UniformPressure(), mass=1.0)
    with pytest.raises(ValueError, match=message):
        simulate_many(body, ss.FrictionTensor(0.3, 0.3), np.zeros((1, 6)), **kwargs)


def test_simulate_many_bad_objects():
    body = ss.Body(ss.Circle(0.1), ss.UniformPressure(), mass=1.0)
    with pytest.raises(ValueError, match="body"):
        simulate_many("disk", ss.FrictionTensor(0.3, 0.3), np.zeros((1, 6)))
    with pytest.raises(ValueError, match="friction"):
        simulate_many(body, 0.3, np.zeros((1, 6)))


BASE = dict(a=0.1, b=0.1, fx=0.3, fy=0.3, omega=1.0)


@pytest.mark.parametrize(
    "change, message",
    [
        (dict(colour=1), "unknown case field 'colour'"),
        (dict(a=None), "missing case field 'a'"),
        (dict(vx=[1.0, 2.0], vy=[1.0, 2.0, 3.0]), "different lengths"),
        (dict(law="granite"), "law = 'granite' is invalid"),
        (dict(law=7), "law = 7.0 (case 0) is invalid"),
        (dict(frame="wall"), "frame = 'wall' is invalid"),
        (dict(a=[0.1, -0.1]), "a = -0.1 (case 1) is invalid"),
        (dict(fy=np.nan), "fy = nan (case 0) is invalid"),
        (dict(omega=np.inf), "omega = inf (case 0) is invalid"),
        (dict(vx=np.zeros((2, 2))), "vx has shape (2, 2)"),
        (dict(vx=["fast"]), "vx must be real numbers"),
        (dict(law="linear", xi_c=0.05), "core measure"),
        (dict(moment_of_inertia=-1.0), "moment_of_inertia = -1.0 (case 0) is invalid"),
    ],
)
def test_simulate_cases_bad_input_names_the_field(change, message):
    cases = {**BASE, **change}
    cases = {k: v for k, v in cases.items() if v is not None}
    with pytest.raises(ValueError) as exc:
        simulate_cases(cases)
    assert message in str(exc.value)


def test_simulate_cases_bad_container_and_options():
    with pytest.raises(ValueError, match="dict"):
        simulate_cases([("a", 0.1)])
    with pytest.raises(ValueError, match="rtol"):
        simulate_cases(dict(BASE), rtol=-1.0)
    with pytest.raises(ValueError, match="max_steps"):
        simulate_cases(dict(BASE), max_steps=0)
    assert set(CASE_FIELDS) >= {"a", "b", "law", "fx", "fy", "vx", "vy", "omega"}
