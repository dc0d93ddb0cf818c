"""Animations (slidespin.animate, slidespin animate): GIF frames, size, interpolation against
closed forms, outputs checked before any work."""

from __future__ import annotations

import argparse
import os
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import slidespin as ss
from slidespin.cli import animate as animate_cli
from slidespin.viz import animate as anim

ROOT = Path(__file__).resolve().parents[2]
G = 9.81


@pytest.fixture(scope="module")
def demo_traj():
    from slidespin.cli.main import demo_case

    c = demo_case()
    return ss.simulate(c.body, c.friction, c.initial_state)


def _sliding_disk(v0=1.0, mu=0.3):
    body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), mass=1.0)
    return ss.simulate(body, ss.FrictionTensor(mu, mu), ss.State(vx=v0, vy=0.0, omega=0.0))


def test_gif_frames_duration_and_size(demo_traj, tmp_path):
    out = tmp_path / "demo.gif"
    assert anim.animate(demo_traj, out, fps=25, frames=40) == str(out)
    with Image.open(out) as im:
        assert im.format == "GIF"
        assert im.n_frames == 40
        assert im.info["duration"] == 40  # ms: 1000 / 25
        assert im.info.get("loop") == 0
    assert os.path.getsize(out) < 1_000_000
    assert not [p for p in os.listdir(tmp_path) if p != "demo.gif"]  # no temporary left


def test_demo_at_the_cap_stays_under_one_megabyte(demo_traj, tmp_path):
    out = tmp_path / "cap.gif"
    anim.animate(demo_traj, out, frames=anim.MAX_FRAMES)
    with Image.open(out) as im:
        assert im.n_frames == anim.MAX_FRAMES
    assert os.path.getsize(out) < 1_000_000


def test_frames_evenly_spaced_and_end_at_the_stop(demo_traj):
    st = anim.frame_states(demo_traj, 17)
    assert st.t[0] == 0.0 and st.t[-1] == pytest.approx(demo_traj.t_stop, rel=1e-15)
    np.testing.assert_allclose(np.diff(st.t), demo_traj.t_stop / 16, rtol=1e-9)
    s = demo_traj.stop_state
    assert (st.x[-1], st.y[-1], st.phi[-1]) == pytest.approx((s.x, s.y, s.phi), abs=1e-12)


def test_interpolated_positions_match_the_closed_form_of_pure_sliding():
    # isotropic disk sliding without spin: v = v0 - mu g t, x = v0 t - mu g t^2 / 2
    v0, mu = 1.0, 0.3
    tr = _sliding_disk(v0, mu)
    assert tr.t_stop == pytest.approx(v0 / (mu * G), rel=1e-9)
    st = anim.frame_states(tr, 50)
    np.testing.assert_allclose(st.x, v0 * st.t - 0.5 * mu * G * st.t**2, atol=1e-9)
    np.testing.assert_allclose(st.vx, v0 - mu * G * st.t, atol=1e-9)
    np.testing.assert_allclose(st.y, 0.0, atol=1e-12)


def test_interpolation_third_order_between_sparse_steps(demo_traj):
    # a dense run of the same motion is the truth for the interpolated sparse run
    c = demo_traj
    dense = ss.simulate(c.body, c.friction, c.initial_state, max_step=0.01)
    st = anim.frame_states(c, 120)
    # dense rows at the frame times, by Hermite on a grid 20x finer than the sparse one
    ref_x = anim._hermite(dense.t, dense.x, dense.vx, st.t)
    ref_phi = anim._hermite(dense.t, dense.phi, dense.omega, st.t)
    assert c.t.size < dense.t.size / 10
    assert np.max(np.abs(st.x - ref_x)) < 1e-5 * c.distance
    assert np.max(np.abs(st.phi - ref_phi)) < 1e-5 * abs(dense.phi[-1] - dense.phi[0])


def test_footprint_outlines_are_drawn(tmp_path):
    from slidespin.contact.shapes import Rectangle

    body = ss.Body(Rectangle(0.1, 0.06), ss.UniformPressure(), mass=1.0)
    tr = ss.simulate(body, ss.FrictionTensor(0.3, 0.4), ss.State.from_speed(0.8, 6.0, 0.3))
    out = tmp_path / "box.gif"
    anim.animate(tr, out, frames=6)
    with Image.open(out) as im:
        assert im.n_frames == 6


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"fps": 0}, "fps = 0"),
        ({"fps": 51}, "fps = 51"),
        ({"frames": 1}, "frames = 1"),
        ({"frames": anim.MAX_FRAMES + 1}, "frames = 121"),
        ({"frames": 2.5}, "frames = 2.5"),
        ({"fps": True}, "fps = True"),
    ],
)
def test_bad_numbers_refused(demo_traj, tmp_path, kwargs, match):
    out = tmp_path / "x.gif"
    with pytest.raises(ValueError, match=match):
        anim.animate(demo_traj, out, **kwargs)
    assert not out.exists()


def test_bad_paths_refused_before_any_drawing(demo_traj, tmp_path, monkeypatch):
    def boom(*a, **k):
        raise AssertionError("work started before the output path was checked")

    monkeypatch.setattr(anim, "frame_states", boom)
    for bad, match in [
        (tmp_path / "x.png", r"\.gif"),
        (tmp_path, r"\.gif"),
        (tmp_path / "sub.gif", "directory"),
        (tmp_path / "missing" / "x.gif", "does not exist"),
    ]:
        if bad.name == "sub.gif":
            bad.mkdir()
        with pytest.raises(ValueError, match=match):
            anim.animate(demo_traj, bad)


def test_not_a_trajectory_refused(tmp_path):
    with pytest.raises(ValueError, match="trajectory"):
        anim.animate(object(), tmp_path / "x.gif")


def _cli(argv):
    p = argparse.ArgumentParser()
    animate_cli.configure(p)
    return animate_cli.run(p.parse_args(argv))


def test_cli_writes_the_gif(tmp_path, capsys):
    out = tmp_path / "circle.gif"
    assert (
        _cli(
            [
                str(ROOT / "examples" / "uniform_circle.toml"),
                "--out",
                str(out),
                "--frames",
                "8",
                "--fps",
                "10",
            ]
        )
        == 0
    )
    with Image.open(out) as im:
        assert im.n_frames == 8 and im.info["duration"] == 100
    assert str(out) in capsys.readouterr().out


@pytest.mark.parametrize(
    "argv, match",
    [
        (["--out", "{d}/run.mp4"], "--out = .*unknown animation format '.mp4'"),
        (["--out", "{d}/nodir/run.gif"], "--out = .*does not exist"),
        (["--out", "{d}/run.gif", "--fps", "0"], "--fps = 0"),
        (["--out", "{d}/run.gif", "--frames", "500"], "--frames = 500"),
    ],
)
def test_cli_refuses_outputs_before_reading_the_case(tmp_path, monkeypatch, argv, match):
    import slidespin.studies.case

    def boom(*a, **k):
        raise AssertionError("the case was read before the outputs were checked")

    monkeypatch.setattr(slidespin.studies.case, "load_case", boom)
    argv = ["no-such-case.toml"] + [a.format(d=tmp_path) for a in argv]
    with pytest.raises(ValueError, match=match):
        _cli(argv)
    assert os.listdir(tmp_path) == []


def test_main_cli_exit_status_2_and_nothing_written(tmp_path, capsys, monkeypatch):
    # through slidespin.cli.main, with the plugin registered as the lead registers it
    import importlib

    cli = importlib.import_module("slidespin.cli.main")

    if not any(name == "animate" for name, *_ in cli._PLUGINS):
        monkeypatch.setattr(
            cli,
            "_PLUGINS",
            cli._PLUGINS
            + (("animate", "slidespin.cli.animate", "write an animated GIF of a case's motion"),),
        )
    out = tmp_path / "run.txt"
    assert cli.main(["animate", str(ROOT / "examples" / "demo.toml"), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--out" in err and ".gif" in err
    assert not out.exists()
    gif = tmp_path / "run.gif"
    assert (
        cli.main(
            ["animate", str(ROOT / "examples" / "demo.toml"), "--out", str(gif), "--frames", "5"]
        )
        == 0
    )
    with Image.open(gif) as im:
        assert im.n_frames == 5


SPINNING_PUCK_ON_SLOPE = """
name = "spinning puck on a slope"
[patch]
shape = "circle"
radius = 0.04
[pressure]
law = "uniform"
[friction]
fx = 0.3
fy = 0.3
[body]
mass = 0.2
[initial]
speed = 0.0
omega = 30.0
[incline]
angle_deg = 20.0
downhill_deg = 0.0
[solver]
t_end = 1.0
"""


def test_cli_loaded_case_animates_up_to_t_end(tmp_path, capsys):
    case = tmp_path / "slope.toml"
    case.write_text(SPINNING_PUCK_ON_SLOPE)
    out = tmp_path / "slope.gif"
    assert _cli([str(case), "--out", str(out), "--frames", "7"]) == 0
    with Image.open(out) as im:
        assert im.n_frames == 7
    # the frames span the whole run, 0 to t_end, sliding downhill (+x) while it spins
    from slidespin.studies.case import load_case

    c = load_case(str(case))
    tr = ss.simulate(
        c.body, c.friction, c.initial_state, load=c.load, incline=c.incline, t_end=c.t_end
    )
    st = anim.frame_states(tr, 7)
    assert st.t[-1] == pytest.approx(1.0) and st.x[0] == 0.0
    assert np.all(np.diff(st.x) > 0) and abs(st.phi[-1]) > 0.1
