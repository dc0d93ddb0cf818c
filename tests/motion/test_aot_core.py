"""The ahead-of-time compiled core (slidespin._aot): the same numbers as the JIT, bit
for bit, and used only while its sources are unchanged."""

from __future__ import annotations

import hashlib
import json
import math
import os
import subprocess
import sys
import types

import numpy as np
import pytest

import slidespin as ss
from slidespin.contact._engine import footprint_argument
from slidespin import _aot
from slidespin.motion import _integrator

BODIES = {
    "ellipse": lambda: ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), 1.0),
    "linear ellipse": lambda: ss.Body(
        ss.Ellipse(0.08, 0.05), ss.LinearPressure(0.01, -0.005), 2.0
    ),
    "rectangle": lambda: ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), 1.0),
    "ring": lambda: ss.Body(ss.Annulus(0.06, 0.1), ss.UniformPressure(), 1.0),
}


def _core_or_skip():
    core = _aot.core()
    if core is None:
        pytest.skip(_aot.status())
    return core


@pytest.mark.parametrize("name", sorted(BODIES))
def test_core_gives_the_jit_numbers_bit_for_bit(name):
    core = _core_or_skip()
    body = BODIES[name]()
    par, fe, fc, geo = body.engine_params(ss.FrictionTensor(fx=0.42, fy=0.54, f=0.05))
    fp = footprint_argument(par, fe, fc, geo)
    y0 = np.array([0.5, 0.5, 0.7, 0.0, 0.0, 0.1, -0.2, 0.3, 0.0])
    y0[:3] /= np.linalg.norm(y0[:3])
    tail = (1e-10, 1e-10, 1e-10, 1e-10, 100_000, math.inf, True, False)
    jit = _integrator.integrate_fp(par, fp, y0, *tail)
    aot = (
        core.integrate_ellipse(par, y0, *tail)
        if fp is None
        else core.integrate_footprint(par, *fp, y0, *tail)
    )
    for a, b in zip(aot, jit, strict=True):
        assert np.array_equal(np.asarray(a), np.asarray(b), equal_nan=True)
    # the recorded wrenches too
    rows = aot[6]
    got = _integrator.wrench_rows(par, fe, fc, geo, rows[:, 8], rows[:, 1], rows[:, 2], rows[:, 3])
    saved = _aot._state.copy()
    try:
        _aot._state.update(checked=True, module=None)
        want = _integrator.wrench_rows(
            par, fe, fc, geo, rows[:, 8], rows[:, 1], rows[:, 2], rows[:, 3]
        )
    finally:
        _aot._state.update(saved)
    for a, b in zip(got, want, strict=True):
        assert np.array_equal(a, b)


def _fake_core(tmp_path, monkeypatch, edit: bool):
    """A stand-in core whose manifest lists one source file of a fake package dir."""
    pkg = tmp_path / "pkg"
    (pkg / "motion").mkdir(parents=True)
    src = pkg / "motion" / "_flow.py"
    src.write_text("x = 1\n")
    module_dir = tmp_path / "ext"
    module_dir.mkdir()
    manifest = {
        "numba": "0",
        "target_cpu": "host",
        "sources": {"motion/_flow.py": hashlib.sha256(src.read_bytes()).hexdigest()},
    }
    (module_dir / _aot.MANIFEST).write_text(json.dumps(manifest))
    if edit:
        src.write_text("x = 2\n")
    fake = types.ModuleType(_aot.MODULE)
    fake.__file__ = str(module_dir / "_aot_core.so")
    monkeypatch.setattr(_aot, "_PACKAGE_DIR", pkg)
    monkeypatch.setattr(_aot.importlib, "import_module", lambda name: fake)
    monkeypatch.setattr(_aot, "_state", {"checked": False, "module": None, "why": ""})
    monkeypatch.delenv("NUMBA_DISABLE_JIT", raising=False)
    monkeypatch.delenv("SLIDESPIN_AOT", raising=False)
    return fake


def test_unchanged_sources_use_the_core(tmp_path, monkeypatch):
    fake = _fake_core(tmp_path, monkeypatch, edit=False)
    assert _aot.core() is fake
    assert "in use" in _aot.status()


def test_an_edited_source_falls_back_to_the_jit_and_says_which(tmp_path, monkeypatch):
    _fake_core(tmp_path, monkeypatch, edit=True)
    with pytest.warns(_aot.CoreWarning, match="motion/_flow.py has changed"):
        assert _aot.core() is None
    assert "JIT" in _aot.status()


@pytest.mark.parametrize(("var", "value"), [("SLIDESPIN_AOT", "0"), ("NUMBA_DISABLE_JIT", "1")])
def test_switches_turn_the_core_off(tmp_path, monkeypatch, var, value):
    _fake_core(tmp_path, monkeypatch, edit=False)
    monkeypatch.setenv(var, value)
    assert _aot.core() is None
    assert var in _aot.status()


def test_a_first_demo_compiles_nothing_with_the_core(tmp_path):
    """From an empty numba cache, the demo runs on the compiled core: numba raises no compile
    event for a slidespin function (so the one compile note is not printed)."""
    _core_or_skip()
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"), MPLBACKEND="Agg")
    code = (
        "import sys; from numba.core import event as ev\n"
        "seen = []\n"
        "class L(ev.Listener):\n"
        "    def on_start(self, e): seen.append(e.data['dispatcher'].py_func.__module__)\n"
        "    def on_end(self, e): pass\n"
        "ev.register('numba:compile', L())\n"
        "import math, slidespin as ss\n"
        "b = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), 1.0)\n"
        "t = ss.simulate(b, ss.FrictionTensor(0.42, 0.54), ss.State.from_speed(1, 5, math.pi/4))\n"
        "r = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), 1.0)\n"
        "t2 = ss.simulate(r, ss.FrictionTensor(0.3, 0.4), ss.State.from_speed(1, 5, 0.3))\n"
        "print(t.t_stop, t2.t_stop, sorted(set(seen)))\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=600
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().endswith("[]"), out.stdout
    assert "compiling" not in out.stderr


@pytest.mark.parametrize("name", ["ellipse", "rectangle"])
def test_a_small_batch_on_the_core_gives_the_parallel_loops_numbers(name, monkeypatch):
    """simulate_many below SERIAL_MAX cases runs serially on the core: the stops are those of
    the compiled parallel loop, bit for bit (the same source)."""
    core = _core_or_skip()
    rng = np.random.default_rng(7)
    body = BODIES[name]()
    friction = ss.FrictionTensor(fx=0.42, fy=0.54)
    states = [
        ss.State.from_speed(rng.uniform(0.1, 2.0), omega=rng.uniform(-10, 10), theta=t)
        for t in rng.uniform(0.0, 2 * math.pi, 40)
    ]
    on_core = ss.simulate_many(body, friction, states).to_pandas()
    monkeypatch.setattr(_aot, "_state", {"checked": True, "module": None, "why": "off"})
    parallel = ss.simulate_many(body, friction, states).to_pandas()
    assert core is not None and on_core.equals(parallel)
