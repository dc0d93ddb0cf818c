"""Sweep inputs: wrong arguments and infeasible loads are refused before anything is written,
naming the parameter as the user wrote it; the work of a loaded case is bounded; one
vocabulary for the start state in case files and sweep specs."""

from __future__ import annotations

import concurrent.futures as cf
import math
import time

import numpy as np
import pytest

import slidespin as ss
from slidespin.cli.main import main
from slidespin.studies.case import case_from_dict
from slidespin.studies.sweep import connect_dask, sweep
from slidespin.studies.sweep_chunk import compute_chunk
from slidespin.studies.sweep_parse import load_spec
from slidespin.studies.sweep_read import read_sweep
from slidespin.studies.sweep_spec import SweepError

G = 9.81


def stop_spec(**fixed):
    base = {"a": 0.05, "e": 0.6, "fx": 0.3, "mu": 0.1, "v0": 0.5, "omega0": 6.0}
    base.update(fixed)
    return {"name": "t", "kind": "grid", "chunk_size": 4, "fixed": base, "vary": {}}


def loads_spec(compute, fixed, vary=None):
    base = {"a": 0.05, "e": 0.6, "fx": 0.3, "mu": 0.1, "mass": 2.0}
    base.update(fixed)
    return {
        "name": "loads",
        "kind": "grid",
        "chunk_size": 4,
        "compute": compute,
        "fixed": base,
        "vary": vary or {"phi0": [0.0, 0.5]},
    }


# --------------------------------------------------------------------------- sweep() arguments
@pytest.mark.parametrize(
    "kwargs, words",
    [
        ({"executor": "dask"}, ["executor = 'dask' is invalid", "valid values: None", "Client"]),
        ({"executor": 4}, ["executor = 4 is invalid", "concurrent.futures.Executor"]),
        ({"resume": "yes"}, ["resume = 'yes' is invalid; valid values: True, False"]),
        ({"progress": 1}, ["progress = 1 is invalid; valid values: True, False or None"]),
    ],
)
def test_bad_sweep_arguments_are_named(tmp_path, kwargs, words):
    out = tmp_path / "s"
    with pytest.raises(SweepError) as err:
        sweep(stop_spec(), out, **kwargs)
    for w in words:
        assert w in str(err.value), (w, str(err.value))
    assert not out.exists()


def test_out_none_and_spec_none_are_named(tmp_path):
    with pytest.raises(SweepError, match=r"out = None is invalid; valid values: a directory"):
        sweep(stop_spec(), None)
    with pytest.raises(SweepError, match=r"spec = None is invalid; valid values: a path"):
        sweep(None, tmp_path / "s")
    assert not (tmp_path / "s").exists()


def test_a_concurrent_futures_executor_is_accepted(tmp_path):
    with cf.ThreadPoolExecutor(1) as pool:
        res = sweep(stop_spec(), tmp_path / "s", executor=pool, progress=False)
    assert res.n_cases == 1 and res.chunks_computed == 1


def test_connect_dask_workers_and_address_exclude_each_other():
    pytest.importorskip("distributed")
    with pytest.raises(SweepError, match="workers = 0 is invalid; valid range: integer >= 1"):
        connect_dask(None, 0)
    with pytest.raises(SweepError, match="valid: one of them"):
        connect_dask("tcp://127.0.0.1:1", 2)


def test_cli_scheduler_and_workers_exclude_each_other(tmp_path, capsys):
    spec = tmp_path / "s.toml"
    spec.write_text("[fixed]\na = 0.05\nfx = 0.3\nmu = 0.1\n")
    code = main(
        [
            "sweep",
            str(spec),
            "--out",
            str(tmp_path / "o"),
            "--scheduler",
            "tcp://x:1",
            "--workers",
            "2",
        ]
    )
    assert code == 2 and "exclude each other" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


# ---------------------------------------------------------------- names the user wrote
@pytest.mark.parametrize(
    "shape",
    [{}, {"shape": "disk", "radius": 0.05, "a": None, "e": None}],
)
@pytest.mark.parametrize(
    "key, value, fragment",
    [
        ("I_star", 0.0, "I_star = 0.0 (case 0) is invalid; valid range: [1e-08, 1e+08]"),
        ("v0", -1.0, "v0 = -1.0 (case 0) is invalid; valid range: [0, 1e+08] m/s"),
        ("omega0", 1e300, "omega0 = 1e+300 (case 0) is invalid; valid range: [-1e+12, 1e+12]"),
        ("x0", 1e101, "x0 = 1e+101 (case 0) is invalid; valid range: [-1e+100, 1e+100] m"),
        ("vx0", -2e8, "vx0 = -200000000.0 (case 0) is invalid; valid range: [-1e+08, 1e+08]"),
        # not finite: refused with the spec's key when the spec is read
        ("theta0", math.nan, "theta0 = nan is not finite; valid range: any finite real number"),
        ("phi0_deg", math.inf, "phi0_deg = inf is not finite"),
    ],
)
def test_start_and_inertia_are_named_as_written(shape, key, value, fragment):
    spec = stop_spec(**{key: value})
    if key == "vx0":
        spec["fixed"].pop("v0")
    for k, val in shape.items():
        if val is None:
            spec["fixed"].pop(k)
        else:
            spec["fixed"][k] = val
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    assert fragment in str(err.value)


def test_case_numbers_are_the_sweeps_not_the_blocks():
    """The spec is checked in blocks of 200 000 cases: the refused case is named by its number
    in the sweep (here 250 000, the first with mu = -0.5), not by its row in the block."""
    spec = stop_spec()
    spec["fixed"].pop("mu")
    spec["fixed"].pop("omega0")
    spec["chunk_size"] = 100_000
    spec["vary"] = {"mu": [0.1, -0.5], "omega0": {"start": 1.0, "stop": 2.0, "num": 250_000}}
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    msg = str(err.value)
    assert "fy = -0.2 (case 250000) is invalid" in msg and "with mu = -0.5" in msg
    spec["vary"]["mu"] = [0.1, 0.2]
    assert load_spec(spec).parameters(250_000, 250_001)["mu"][0] == 0.2


def test_mu_is_named_when_fy_is_out_of_range():
    spec = stop_spec()
    spec["fixed"].pop("mu")
    spec["vary"] = {"mu": [0.1, -0.5]}
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    msg = str(err.value)
    assert "fy = -0.2 (case 1) is invalid" in msg and "mu = -0.5" in msg


# ------------------------------------------------------------------- loads refused up front
@pytest.mark.parametrize(
    "compute, fixed, words",
    [
        ("statics", {"load_fx": 1e300}, ["load_fx = 1e+300", "valid range: at most 1e+06"]),
        ("statics", {"incline_angle": 1.5707963}, ["incline_angle = 1.5707963", "at most 1e+06"]),
        ("loaded", {"load_fx": 1e300, "t_end": 1.0}, ["load_fx = 1e+300", "at most 1e+06"]),
        (
            "loaded",
            {"load_torque": 1e7 * 2.0 * G * 0.05, "t_end": 1.0},
            ["load_torque =", "compute = 'loaded'"],
        ),
    ],
)
def test_infeasible_loads_are_refused_before_anything_is_written(
    tmp_path, capsys, compute, fixed, words
):
    spec = loads_spec(compute, fixed)
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    for w in words:
        assert w in str(err.value), (w, str(err.value))
    # the command line: exit 2, one line, no directory
    path = tmp_path / "spec.toml"
    lines = [f'compute = "{compute}"', "chunk_size = 4", "[fixed]"]
    lines += [f"{k} = {v!r}" for k, v in spec["fixed"].items()]
    lines += ["[vary]", "phi0 = [0.0, 0.5]"]
    path.write_text("\n".join(lines).replace("inf", "inf") + "\n")
    out = tmp_path / "run"
    assert main(["sweep", str(path), "--out", str(out), "--quiet"]) == 2
    err_text = capsys.readouterr().err
    assert err_text.count("\n") == 1 and words[0] in err_text
    assert not out.exists()


def test_the_engines_refuse_what_the_check_refuses():
    """Independent truth: the engines themselves refuse these loads (mid-run, before)."""
    body = ss.Body(ss.Ellipse.from_eccentricity(0.05, 0.6), ss.UniformPressure(), 2.0)
    fr = ss.FrictionTensor(0.3, 0.4)
    from slidespin.contact.statics import load_factor

    with pytest.raises(ValueError, match="valid range: .*1e\\+06"):
        load_factor(body, fr, (1e300, 0.0, 0.0), 0.0, G)
    with pytest.raises(ValueError, match="valid range: .*1e\\+06"):
        load_factor(body, fr, (0.0, 0.0, 0.0), 0.0, G, incline=ss.Incline(1.5707963))
    with pytest.raises(ValueError, match="valid range: .*1e\\+06"):
        ss.simulate(body, fr, ss.State(), G, load=ss.Load((1e300, 0.0)), t_end=1.0)


def test_loads_just_inside_the_bound_run(tmp_path):
    """0.9e6 times the weight passes the check and every case runs (no mid-run refusal)."""
    spec = loads_spec("statics", {"load_fx": 0.9e6 * 2.0 * G})
    res = sweep(spec, tmp_path / "s", progress=False)
    t = read_sweep(tmp_path / "s", include_unconverged=True)
    assert res.status_counts == {"ok": 2} and list(t["ending"]) == ["slides", "slides"]


# ----------------------------------------------------------------------- the work is bounded
def test_a_long_loaded_run_ends_at_its_step_budget(tmp_path):
    """t_end = 1e7 s of a pushed, spinning disk: max_steps bounds the work (status max_steps);
    the same run as one simulate() call gives the same status and end time."""
    spec = loads_spec(
        "loaded",
        {"load_fx": 2.5 * 2.0, "load_torque": 0.5, "t_end": 1e7, "e": 0.0},
        {"phi0": [0.0]},
    )
    spec["max_steps"] = 300
    t0 = time.perf_counter()
    res = sweep(spec, tmp_path / "s", progress=False)
    assert time.perf_counter() - t0 < 120
    t = read_sweep(tmp_path / "s", include_unconverged=True)
    assert res.status_counts == {"max_steps": 1} and t["t_final"][0] < 1e7
    body = ss.Body(ss.Ellipse.from_eccentricity(0.05, 0.0), ss.UniformPressure(), 2.0)
    tr = ss.simulate(
        body,
        ss.FrictionTensor(0.3, 0.4),
        ss.State(),
        G,
        max_steps=300,
        load=ss.Load((5.0, 0.0), 0.5),
        t_end=1e7,
    )
    assert tr.status == "max_steps" and t["t_final"][0] == tr.t[-1]


def test_max_steps_is_the_stop_sweeps_budget_too(tmp_path):
    spec = stop_spec()
    spec["max_steps"] = 3
    sweep(spec, tmp_path / "s", progress=False)
    t = read_sweep(tmp_path / "s", include_unconverged=True)
    body = ss.Body(ss.Ellipse.from_eccentricity(0.05, 0.6), ss.UniformPressure(), 1.0)
    tr = ss.simulate(body, ss.FrictionTensor(0.3, 0.4), ss.State.from_speed(0.5, 6.0), max_steps=3)
    assert t["status"][0] == tr.status == "max_steps"


@pytest.mark.parametrize(
    "edit, words",
    [
        ({"max_steps": 0}, ["max_steps = 0 is invalid; valid range: integer >= 1"]),
        ({"max_steps": 2.5}, ["max_steps = 2.5 is invalid"]),
        (
            {"compute": "statics", "max_steps": 10},
            ["'max_steps' is not used by compute = 'statics'"],
        ),
        ({"compute": "statics", "rtol": 1e-8}, ["'rtol' is not used by compute = 'statics'"]),
    ],
)
def test_max_steps_and_statics_refusals(edit, words):
    spec = loads_spec("stop", {}) if "compute" not in edit else loads_spec("statics", {})
    spec.update(edit)
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    for w in words:
        assert w in str(err.value)


@pytest.mark.parametrize("key", ["v0", "omega0", "x0", "vx0", "theta0_deg"])
def test_statics_refuses_the_start_motion(key):
    spec = loads_spec("statics", {key: 1.0})
    with pytest.raises(SweepError, match=f"'{key}' is not used by compute = 'statics'"):
        load_spec(spec)


def test_on_case_counts_every_statics_case():
    spec = load_spec(loads_spec("statics", {}, {"phi0": [0.0, 0.1, 0.2, 0.3, 0.4]}))
    calls = []
    compute_chunk(spec, 1, on_case=lambda: calls.append(1))
    assert len(calls) == 1  # chunk 1 of 5 cases in chunks of 4 holds one case
    compute_chunk(spec, 0, on_case=lambda: calls.append(1))
    assert len(calls) == 5


# ------------------------------------------------------------------------- one vocabulary
def test_degrees_and_components_in_a_sweep_spec(tmp_path):
    """theta0_deg and phi0_deg are the radians keys in degrees (bit for bit); vx0, vy0 give the
    velocity itself (each case equals one simulate() on that State)."""
    rad = stop_spec(theta0=math.radians(40.0), phi0=math.radians(25.0))
    deg = stop_spec(theta0_deg=40.0, phi0_deg=25.0)
    sweep(rad, tmp_path / "rad", progress=False)
    sweep(deg, tmp_path / "deg", progress=False)
    a = read_sweep(tmp_path / "rad", include_unconverged=True)
    b = read_sweep(tmp_path / "deg", include_unconverged=True)
    for k in a:
        assert np.array_equal(np.asarray(a[k]).astype(str), np.asarray(b[k]).astype(str)), k
    # the degrees are columns too, as written (a sweep is read by the names it was given)
    assert set(b) - set(a) == {"theta0_deg", "phi0_deg"}
    assert (b["theta0_deg"][0], b["phi0_deg"][0]) == (40.0, 25.0)
    comp = stop_spec(vx0=0.3, vy0=-0.2)
    comp["fixed"].pop("v0")
    sweep(comp, tmp_path / "xy", progress=False)
    c = read_sweep(tmp_path / "xy", include_unconverged=True)
    body = ss.Body(ss.Ellipse.from_eccentricity(0.05, 0.6), ss.UniformPressure(), 1.0)
    tr = ss.simulate(body, ss.FrictionTensor(0.3, 0.4), ss.State(0, 0, 0, 0.3, -0.2, 6.0))
    assert c["vx0"][0] == 0.3 and c["vy0"][0] == -0.2
    assert c["t_stop"][0] == pytest.approx(tr.t_stop, rel=1e-12)
    assert c["x_stop"][0] == pytest.approx(tr.stop_state.x, rel=1e-10)


@pytest.mark.parametrize(
    "fixed, words",
    [
        ({"v0": 1.0, "vx0": 0.5}, ["either as v0 and theta0", "v0 and vx0"]),
        ({"theta0": 0.1, "theta0_deg": 5.0}, ["at most one of theta0, theta0_deg"]),
        ({"phi0": 0.1, "phi0_deg": 5.0}, ["at most one of phi0, phi0_deg"]),
        ({"speed": 1.0}, ["unknown key 'speed' in [fixed]", "is 'v0' here"]),
        ({"theta_deg": 1.0}, ["unknown key 'theta_deg' in [fixed]", "is 'theta0_deg' here"]),
    ],
)
def test_start_state_keys_of_a_sweep_spec(fixed, words):
    spec = stop_spec(**fixed)
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    for w in words:
        assert w in str(err.value), (w, str(err.value))


CASE = {
    "patch": {"a": 0.05, "eccentricity": 0.6},
    "pressure": {"law": "uniform"},
    "friction": {"fx": 0.3, "fy": 0.4},
    "body": {"mass": 1.0},
}


@pytest.mark.parametrize(
    "new, old",
    [
        (
            {"v0": 0.5, "theta0_deg": 30.0, "omega0": 6.0, "phi0_deg": 10.0, "x0": 1.0},
            {"speed": 0.5, "theta_deg": 30.0, "omega": 6.0, "phi_deg": 10.0, "x": 1.0},
        ),
        (
            {"vx0": 0.3, "vy0": -0.2, "y0": 2.0, "phi0": 0.4},
            {"vx": 0.3, "vy": -0.2, "y": 2.0, "phi": 0.4},
        ),
        ({"v0": 0.5, "theta0": 0.3}, {"speed": 0.5, "theta": 0.3}),
    ],
)
def test_case_file_names_and_their_aliases_give_the_same_state(new, old):
    a = case_from_dict({**CASE, "initial": new}).initial_state
    b = case_from_dict({**CASE, "initial": old}).initial_state
    assert a == b
    # and a sweep of the same start gives the same columns
    assert a.vx == pytest.approx(b.vx, abs=0)


@pytest.mark.parametrize(
    "initial, fragment",
    [
        ({"v0": 1.0, "speed": 1.0}, "gives both 'v0' and 'speed', two names of v0"),
        ({"omega": 1.0, "omega0": 2.0}, "gives both 'omega' and 'omega0'"),
        ({"v0": -1.0}, "[initial] v0 = -1.0 is invalid; valid range: [0, 1e+08]"),
        ({"speed": -1.0}, "[initial] speed = -1.0 is invalid"),
        ({"omega0": math.nan}, "[initial] omega0 = nan is not finite"),
        ({"vx0": 1e9}, "[initial] vx0 = 1000000000.0 m/s is invalid; valid range"),
        (
            {"speed": 1.0, "vx0": 1.0},
            "give either speed/theta or vx/vy, not both: 'speed' and 'vx0'",
        ),
        ({"theta0": 1.0, "theta0_deg": 2.0}, "gives both theta0 and theta0_deg"),
        ({"phi": 1.0, "phi0_deg": 2.0}, "gives both phi and phi0_deg"),
    ],
)
def test_case_file_start_errors_name_the_key_as_written(initial, fragment):
    with pytest.raises(ValueError) as err:
        case_from_dict({**CASE, "initial": initial})
    assert fragment in str(err.value), str(err.value)


def test_a_pressure_centroid_needs_a_linear_law_somewhere():
    spec = stop_spec(xi_c=0.005)
    with pytest.raises(SweepError) as err:
        load_spec(spec)
    msg = str(err.value)
    assert "'xi_c' is the centroid of the linear pressure law" in msg and "valid:" in msg
    spec["vary"] = {"law": ["uniform", "linear"]}
    assert load_spec(spec).n_cases == 2  # used by the linear cases
    spec = stop_spec(eta_c=0.001, law="linear")
    assert load_spec(spec).n_cases == 1
