"""Every option of a case file is used or refused by every command that reads it.

``slidespin fit`` models a body coasting on a level plane: ``[load]``, ``[incline]``,
``[solver] t_end`` and ``max_steps`` are refused (never fitted as if absent); ``[solver] rtol``
is used. ``slidespin limit-surface`` uses the body, tensor, ``phi0``, ``g``, ``[incline]`` and the
start velocities (the wrench of the start twist, checked against closed forms); it refuses
``[load]``, ``[solver] t_end``/``rtol``/``max_steps`` and the start position.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from slidespin.cli.main import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DATA = str(EXAMPLES / "fit_synthetic.csv")
FIT_CASE = (EXAMPLES / "fit_case.toml").read_text()

DISK = """name = "disk"
[patch]
shape = "circle"
radius = 0.05
[pressure]
law = "uniform"
[friction]
fx = 0.3
fy = 0.3
[body]
mass = 2.0
"""


def refused(capsys, argv, *fragments):
    code = main(argv)
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1, err
    assert lines[0].startswith("slidespin: error: ") and lines[0].count("slidespin:") == 1
    for frag in fragments:
        assert frag in lines[0], (frag, lines[0])
    return lines[0]


# ---------------------------------------------------------------------------------------- fit
@pytest.mark.parametrize(
    "extra, words",
    [
        ("[load]\nfx = 1.0\n", ["[load] is not used by slidespin fit", "not supported"]),
        ("[incline]\nangle_deg = 5.0\n", ["[incline] is not used by slidespin fit"]),
        ("[solver]\nt_end = 2.0\n", ["[solver] t_end = 2.0 is not used by slidespin fit"]),
        ("[solver]\nmax_steps = 1000\n", ["[solver] max_steps = 1000 is not used"]),
    ],
)
def test_fit_refuses_what_it_cannot_honour(tmp_path, capsys, monkeypatch, extra, words):
    import slidespin.analysis.fit as fit_mod

    def never(*args, **kwargs):
        raise AssertionError("the fit ran on a case it should have refused")

    monkeypatch.setattr(fit_mod, "fit", never)
    text = FIT_CASE
    if extra.startswith("[solver]") and "[solver]" in text:
        text = text.replace("[solver]\n", extra)
    else:
        text += extra
    case = tmp_path / "c.toml"
    case.write_text(text)
    plot = tmp_path / "fit.png"
    line = refused(capsys, ["fit", DATA, "--case", str(case), "--plot", str(plot)], *words)
    assert str(case) in line and "valid:" in line
    assert not plot.exists()


def test_fit_uses_the_case_rtol(tmp_path, capsys, monkeypatch):
    import slidespin.analysis.fit as fit_mod

    seen = {}

    class Stop(Exception):
        pass

    def spy(*args, **kwargs):
        seen.update(kwargs)
        raise Stop

    monkeypatch.setattr(fit_mod, "fit", spy)
    case = tmp_path / "c.toml"
    assert "rtol" not in FIT_CASE
    case.write_text(FIT_CASE)
    with pytest.raises(Stop):
        main(["--debug", "fit", DATA, "--case", str(case), "--quiet"])
    assert "rtol" not in seen  # the fit's own default
    case.write_text(FIT_CASE + "rtol = 1e-9\n" if "[solver]" in FIT_CASE else "")
    assert "rtol = 1e-9" in case.read_text()
    with pytest.raises(Stop):
        main(["--debug", "fit", DATA, "--case", str(case), "--quiet"])
    assert seen["rtol"] == 1e-9


# ------------------------------------------------------------------------------- limit-surface
@pytest.mark.parametrize(
    "extra, words",
    [
        ("[load]\nfx = 1.0\n", ["[load] is not used by slidespin limit-surface"]),
        ("[solver]\nt_end = 1.0\n", ["[solver] t_end = 1.0 is not used"]),
        ("[solver]\nrtol = 1e-8\n", ["[solver] rtol = 1e-08 is not used"]),
        ("[solver]\nmax_steps = 10\n", ["[solver] max_steps = 10 is not used"]),
        ("[initial]\nx0 = 0.2\n", ["[initial] x0 = 0.2 is not used", "where the body is"]),
        ("[initial]\ny = 0.2\n", ["[initial] y = 0.2 is not used"]),  # the alias too
    ],
)
def test_limit_surface_refuses_what_it_cannot_use(tmp_path, capsys, extra, words):
    case = tmp_path / "c.toml"
    case.write_text(DISK + ("" if "[initial]" in extra else "[initial]\n") + extra)
    npz = tmp_path / "ls.npz"
    refused(capsys, ["limit-surface", str(case), "--n", "20", "--npz", str(npz)], *words)
    assert not npz.exists()


def start_of(tmp_path, capsys, initial, extra=""):
    case = tmp_path / "c.toml"
    case.write_text(DISK + "[initial]\n" + initial + extra)
    assert main(["limit-surface", str(case), "--n", "20", "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_limit_surface_start_twist_pure_translation(tmp_path, capsys):
    """Pure translation: W = −μ P v̂, M = 0 (MODEL §8), P = m g."""
    out = start_of(tmp_path, capsys, "v0 = 0.8\ntheta0_deg = 30.0\n")
    p = 2.0 * 9.81
    th = math.radians(30.0)
    assert out["start"]["twist"] == pytest.approx([math.cos(th), math.sin(th), 0.0], abs=1e-15)
    fx, fy, m = out["start"]["wrench"]
    assert fx == pytest.approx(-0.3 * p * math.cos(th), rel=1e-10)
    assert fy == pytest.approx(-0.3 * p * math.sin(th), rel=1e-10)
    assert abs(m) < 1e-12


def test_limit_surface_start_twist_pure_spin_on_an_incline(tmp_path, capsys):
    """Pure spin of a uniform disk about its centre: M = −sign(ω) f P R (2/3), P = m g cos α."""
    out = start_of(tmp_path, capsys, "omega = -4.0\n", "[incline]\nangle_deg = 20.0\n")
    p = 2.0 * 9.81 * math.cos(math.radians(20.0))
    assert out["normal_load"] == pytest.approx(p, rel=1e-14)
    fx, fy, m = out["start"]["wrench"]
    assert abs(fx) < 1e-12 and abs(fy) < 1e-12
    assert m == pytest.approx(+0.3 * p * 0.05 * 2.0 / 3.0, rel=1e-10)


def test_limit_surface_at_rest_has_no_start_twist(tmp_path, capsys):
    out = start_of(tmp_path, capsys, "phi0_deg = 10.0\n")
    assert out["start"] is None and out["phi"] == pytest.approx(math.radians(10.0), rel=1e-15)
    case = tmp_path / "c.toml"
    assert main(["limit-surface", str(case), "--n", "20"]) == 0
    assert "start twist        : none" in capsys.readouterr().out


def test_limit_surface_samples_need_json(tmp_path, capsys):
    case = tmp_path / "c.toml"
    case.write_text(DISK + "[initial]\n")
    refused(capsys, ["limit-surface", str(case), "--n", "20", "--samples"], "--samples", "--json")


# ------------------------------------------------------------------------- simulate: the JSON
def test_simulate_json_names_the_ratio_for_any_footprint(tmp_path, capsys):
    """`beta_stop_over_length_unit` is β*/ℓ, ℓ the footprint's extent (a centred rectangle's
    half-diagonal); `beta_stop_over_a` keeps its old name and value."""
    case = tmp_path / "box.toml"
    case.write_text(
        '[patch]\nshape = "rectangle"\nlength = 0.3\nwidth = 0.2\n[pressure]\nlaw = "uniform"\n'
        "[friction]\nfx = 0.3\nfy = 0.4\n[body]\nmass = 1.0\n"
        "[initial]\nv0 = 1.0\ntheta0_deg = 30.0\nomega0 = 8.0\n"
    )
    assert main(["simulate", str(case), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    ell = math.hypot(0.3, 0.2) / 2.0
    assert out["length_unit"] == pytest.approx(ell, rel=1e-14)
    assert out["beta_stop_over_length_unit"] == pytest.approx(out["beta_stop"] / ell, rel=1e-14)
    assert out["beta_stop_over_a"] == out["beta_stop_over_length_unit"]
    keys = list(out)
    assert keys.index("beta_stop_over_length_unit") == keys.index("beta_stop_over_a") + 1
