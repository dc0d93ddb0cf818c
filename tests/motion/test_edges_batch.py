"""simulate_many's inputs and outputs: tables read by column name, sequences of State, the
initial states in StopResults.to_pandas, and a progress bar that moves without changing a
number.

Truth: pure translation under isotropic friction (ω₀ = 0: no moment about G for any law,
MODEL §8) decelerates at μ g along a straight line, so each case stops after
t = v₀/(μ g) at distance v₀²/(2 μ g) in its own launch direction. A table read by position
instead of by name gives other stops, which these closed forms catch case by case.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss
from slidespin.motion import batch
from slidespin.motion.batch import (
    INPUT_COLUMNS,
    STATE_COLUMNS,
    STATE_FIELDS,
    StopResults,
    chunk_size,
    simulate_many,
)

MU, G = 0.3, 9.81
BODY = ss.Body(ss.Ellipse(0.1, 0.06), ss.HertzPressure(), mass=1.3)
FRICTION = ss.FrictionTensor.isotropic(MU)


def translations(n: int = 5, seed: int = 4) -> dict[str, np.ndarray]:
    """n pure translations: random positions, angles, speeds and directions, no spin."""
    rng = np.random.default_rng(seed)
    speed = rng.uniform(0.2, 2.0, n)
    theta = rng.uniform(-math.pi, math.pi, n)
    return {
        "x": rng.normal(size=n),
        "y": rng.normal(size=n),
        "phi": rng.uniform(-3, 3, n),
        "vx": speed * np.cos(theta),
        "vy": speed * np.sin(theta),
        "omega": np.zeros(n),
        "speed": speed,
        "theta": theta,
    }


def check_closed_form(res: StopResults, cols: dict[str, np.ndarray]) -> None:
    speed, theta = cols["speed"], cols["theta"]
    d = speed**2 / (2 * MU * G)
    np.testing.assert_allclose(res.t_stop, speed / (MU * G), rtol=1e-9)
    np.testing.assert_allclose(res.path_length, d, rtol=1e-9)
    np.testing.assert_allclose(res.x_stop, cols["x"] + d * np.cos(theta), rtol=0, atol=1e-9)
    np.testing.assert_allclose(res.y_stop, cols["y"] + d * np.sin(theta), rtol=0, atol=1e-9)
    np.testing.assert_allclose(res.phi_stop, cols["phi"], rtol=0, atol=1e-12)


@pytest.fixture(scope="module")
def pd():
    return pytest.importorskip("pandas")


def test_dataframe_is_read_by_column_name(pd):
    cols = translations()
    order = ["omega", "vy", "phi", "x", "vx", "y"]  # not the (N, 6) order
    df = pd.DataFrame({k: cols[k] for k in order})
    check_closed_form(simulate_many(BODY, FRICTION, df, progress=False), cols)


def test_dataframe_with_speed_and_theta_and_sweep_names(pd):
    cols = translations()
    df = pd.DataFrame(
        {"theta0": cols["theta"], "omega0": cols["omega"], "v0": cols["speed"]}
        | {"x0": cols["x"], "y0": cols["y"], "phi0": cols["phi"]}
    )
    check_closed_form(simulate_many(BODY, FRICTION, df, progress=False), cols)


def test_dict_of_columns_and_default_positions():
    cols = translations()
    res = simulate_many(BODY, FRICTION, {k: cols[k] for k in ("vx", "vy", "omega")})
    check_closed_form(res, cols | {k: np.zeros(5) for k in ("x", "y", "phi")})


def test_sequence_of_states():
    cols = translations()
    states = [ss.State(*(cols[k][i] for k in STATE_FIELDS)) for i in range(5)]
    check_closed_form(simulate_many(BODY, FRICTION, states), cols)
    check_closed_form(simulate_many(BODY, FRICTION, tuple(states)), cols)


def test_positions_of_a_table_never_count(pd):
    """A DataFrame with unnamed (positional) columns is refused, naming the first column."""
    df = pd.DataFrame(np.zeros((2, 6)))
    with pytest.raises(ValueError, match=r"column 0.*not by position.*valid columns: x, y"):
        simulate_many(BODY, FRICTION, df)


@pytest.mark.parametrize(
    "table, words",
    [
        ({"x": [0.0], "vx": [1.0], "vy": [0.0], "spin": [1.0]}, ["'spin'", "valid columns"]),
        ({"vx": [1.0], "vy": [0.0]}, ["lacks the column 'omega'", "valid"]),
        ({"vx": [1.0], "omega": [0.0]}, ["lacks the column 'vy'"]),
        ({"speed": [1.0], "omega": [0.0]}, ["lacks the column 'theta'"]),
        ({"vx": [1.0], "vy": [0.0], "speed": [1.0], "omega": [0.0]}, ["velocity twice"]),
        ({"vx": [1.0], "vx0": [1.0], "vy": [0.0], "omega": [0.0]}, ["'vx' and 'vx0'"]),
        ({"vx": [1.0, 2.0], "vy": [0.0], "omega": [0.0]}, ["lengths [1, 2]", "valid"]),
        ({"vx": [True], "vy": [0.0], "omega": [0.0]}, ["initial_states['vx']", "bool"]),
        ({"vx": ["fast"], "vy": [0.0], "omega": [0.0]}, ["initial_states['vx']", "valid"]),
        ({"vx": [1e9], "vy": [0.0], "omega": [0.0]}, ["initial_states['vx'][0]", "1e+08"]),
        ({"vx": [0.0], "vy": [0.0], "omega": [math.nan]}, ["'omega'", "not finite"]),
        ({"speed": [-1.0], "theta": [0.0], "omega": [0.0]}, ["'speed'][0] = -1.0", "[0, 1e+08]"]),
        ({"speed": [1.0], "theta": [math.inf], "omega": [0.0]}, ["'theta'][0] = inf"]),
    ],
)
def test_bad_tables_are_refused_by_name(table, words, pd):
    for given in (
        table,
        pd.DataFrame(table) if len({len(c) for c in table.values()}) == 1 else None,
    ):
        if given is None:
            continue
        with pytest.raises(ValueError) as info:
            simulate_many(BODY, FRICTION, given)
        for w in words:
            assert w in str(info.value), (w, str(info.value))


@pytest.mark.parametrize(
    "states, words",
    [
        (ss.State(vx=1.0), ["one State", "[state]"]),
        ([ss.State(vx=1.0), (0, 0, 0, 1.0, 0, 0)], ["initial_states[1]", "State objects only"]),
        (np.array([[0.0, 0, 0, 0, 0, 2e12]]), ["initial_states[0, 5] (omega)", "1e+12"]),
        (np.array([[2e100, 0, 0, 0, 0, 0]]), ["initial_states[0, 0] (x)", "1e+100"]),
        (np.ones((2, 6), dtype=bool), ["initial_states must be an (N, 6) array"]),
    ],
)
def test_bad_sequences_and_arrays_are_refused(states, words):
    with pytest.raises(ValueError) as info:
        simulate_many(BODY, FRICTION, states)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


def test_state_columns_name_the_package_names():
    assert set(STATE_FIELDS) <= set(STATE_COLUMNS)  # the State fields
    assert set(INPUT_COLUMNS) <= set(STATE_COLUMNS)  # what to_pandas writes reads back
    assert {"speed", "theta"} <= set(STATE_COLUMNS)  # State.from_speed


def test_to_pandas_carries_the_initial_states(pd):
    cols = translations()
    arr = np.column_stack([cols[k] for k in STATE_FIELDS])
    res = simulate_many(BODY, FRICTION, arr)
    df = res.to_pandas()
    assert list(df.columns[:6]) == list(INPUT_COLUMNS) == [f + "0" for f in STATE_FIELDS]
    for j, name in enumerate(INPUT_COLUMNS):
        np.testing.assert_array_equal(df[name].to_numpy(), arr[:, j])
    # no clash: every result column is still there, with its own values
    for name, col in res.as_dict().items():
        assert name in df.columns and name not in INPUT_COLUMNS
        np.testing.assert_array_equal(df[name].to_numpy(), col)
    # the displacement closed form, read off the one table
    d = cols["speed"] ** 2 / (2 * MU * G)
    np.testing.assert_allclose(df["x_stop"] - df["x0"], d * np.cos(cols["theta"]), atol=1e-9)
    # the inputs are a copy: changing the array afterwards changes nothing
    arr[:] = 0.0
    assert res.initial_states[0, 3] == cols["vx"][0]
    # and the input columns run the cases again
    again = simulate_many(BODY, FRICTION, df[list(INPUT_COLUMNS)])
    check_closed_form(again, cols)


def test_simulate_cases_results_carry_their_states_too(pd):
    cols = translations(3)
    cases = {"a": 0.1, "b": 0.06, "fx": MU, "fy": MU} | {k: cols[k] for k in STATE_FIELDS}
    df = batch.simulate_cases(cases).to_pandas()
    for name, field in zip(INPUT_COLUMNS, STATE_FIELDS):
        np.testing.assert_array_equal(df[name].to_numpy(), cols[field])


def test_chunk_size_is_about_one_percent_within_bounds():
    assert chunk_size(0) == chunk_size(1) == batch.MIN_CHUNK
    assert chunk_size(10**6) == 10**4  # 1 %
    assert chunk_size(10**5) == batch.MIN_CHUNK  # 1 % is below the floor
    assert chunk_size(10**8) == batch.CHUNK  # 1 % is above the ceiling
    for n in (1, 999, 10**5, 123_457, 10**6, 10**7, 10**8):
        chunks = math.ceil(n / chunk_size(n))
        assert chunks <= 100 or chunk_size(n) == batch.CHUNK


def test_progress_bar_moves_per_chunk_and_changes_nothing(monkeypatch, capsys):
    """With chunks of 3 cases the bar advances 3 at a time, the bar goes to stderr only,
    and every number equals the one-chunk run (and the closed forms)."""
    cols = translations(10)
    arr = np.column_stack([cols[k] for k in STATE_FIELDS])
    whole = simulate_many(BODY, FRICTION, arr, progress=False)
    updates = []

    class Recorder:
        def __init__(self, total, desc, unit="case", enabled=None):
            self.total, self.desc, self.enabled = total, desc, enabled

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            return False

        def update(self, k):
            updates.append(k)

    monkeypatch.setattr(batch, "MIN_CHUNK", 3)
    monkeypatch.setattr(batch, "CHUNK", 3)
    monkeypatch.setattr(batch, "progress_bar", Recorder)
    chunked = simulate_many(BODY, FRICTION, arr, progress=True)
    assert updates == [3, 3, 3, 1]
    for name in ("t_stop", "x_stop", "y_stop", "phi_stop", "path_length", "beta_stop"):
        np.testing.assert_array_equal(getattr(whole, name), getattr(chunked, name))
    np.testing.assert_array_equal(whole.theta_stop, chunked.theta_stop)
    np.testing.assert_array_equal(whole.status_code, chunked.status_code)
    check_closed_form(chunked, cols)
    assert capsys.readouterr().out == ""


def test_without_a_bar_the_chunks_stay_large(monkeypatch):
    """No bar: one call of the parallel engine per CHUNK cases, as before (each call has a
    fixed cost); the bar's small chunks are paid for only when a bar is drawn."""
    calls = []
    real = batch._integrate_chunk

    def counting(res, lo, hi, *args):
        calls.append(hi - lo)
        return real(res, lo, hi, *args)

    monkeypatch.setattr(batch, "_integrate_chunk", counting)
    monkeypatch.setattr(batch, "MIN_CHUNK", 2)
    cols = translations(5)
    arr = np.column_stack([cols[k] for k in STATE_FIELDS])
    check_closed_form(simulate_many(BODY, FRICTION, arr, progress=False), cols)
    assert calls == [5]
    calls.clear()
    check_closed_form(simulate_many(BODY, FRICTION, arr, progress=True), cols)
    assert calls == [2, 2, 1]


def test_progress_true_draws_on_stderr(capsys):
    cols = translations(2)
    simulate_many(BODY, FRICTION, np.column_stack([cols[k] for k in STATE_FIELDS]), progress=True)
    captured = capsys.readouterr()
    assert captured.out == "" and "simulate_many" in captured.err


@pytest.mark.parametrize("progress", ["yes", 1, 0.0])
def test_progress_must_be_a_bool_or_none(progress):
    with pytest.raises(ValueError, match=r"progress = .* valid values: True, False or None"):
        simulate_many(BODY, FRICTION, np.zeros((1, 6)), progress=progress)
