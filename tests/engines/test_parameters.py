"""The engines' own contact parameters fitted to slidespin's motions (MODEL §16).

For a box and a puck in each engine: the fitted parameters bring the worst rotation error
below that of the engine's defaults (MuJoCo's friction (1, 0.005, 0.0001) condim 3,
PyBullet's lateral friction 0.5, Drake's point contact), the keys are the engine's own
names, and bad input raises. Short launches (half a body length), two per fit, so that the
six fits stay within a few seconds each.
"""

from __future__ import annotations

import math
import sys

import pytest

import slidespin as ss
from slidespin.engines.parameters import EngineParameters, engine_parameters

pytestmark = pytest.mark.xdist_group("engine_parameters")

FRICTION = ss.FrictionTensor(0.3, 0.3)
BODIES = {
    "box": ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0),
    "puck": ss.Body(ss.Disk(0.05), ss.UniformPressure(), mass=0.2),
}
KEYS = {
    "mujoco": {"friction", "condim", "cone"},
    "pybullet": {"lateralFriction", "spinningFriction", "rollingFriction", "anisotropicFriction"},
    "drake": {
        "static_friction",
        "dynamic_friction",
        "contact_model",
        "hydroelastic_modulus",
        "resolution_hint",
        "hunt_crossley_dissipation",
        "discrete_contact_approximation",
    },
}
MODULES = {"mujoco": "mujoco", "pybullet": "pybullet", "drake": "pydrake"}


def _launches(body):
    """Slide with spin and spin-dominated, each stopping within about half a length."""
    speed = math.sqrt(2.0 * 0.3 * 9.81 * 0.5 * body.length_unit)
    k = body.radius_of_gyration
    return (
        ss.State(vx=speed, omega=speed / (2.0 * k)),
        ss.State(vy=0.3 * speed, omega=1.5 * speed / k, phi=0.3),
    )


_FITS: dict = {}


def _fit(engine, name):
    if (engine, name) not in _FITS:
        body = BODIES[name]
        _FITS[engine, name] = engine_parameters(body, FRICTION, engine, launches=_launches(body))
    return _FITS[engine, name]


@pytest.mark.parametrize("name", sorted(BODIES))
@pytest.mark.parametrize("engine", sorted(KEYS))
def test_fitted_rotation_beats_defaults(engine, name):
    pytest.importorskip(MODULES[engine])
    ep = _fit(engine, name)
    assert isinstance(ep, EngineParameters) and isinstance(ep, dict)
    assert set(ep) == KEYS[engine]
    assert ep.engine == engine and len(ep.launches) == 2
    fitted, default = ep.errors["fitted"]["worst"], ep.errors["default"]["worst"]
    assert fitted["rotation"] < default["rotation"], ep.summary()
    # the fit is no worse overall than the defaults either, and its errors are per launch
    assert sum(fitted.values()) < sum(default.values())
    assert len(ep.errors["fitted"]["launches"]) == 2
    assert ep.fit_time > 0.0


def test_mujoco_keys_values():
    pytest.importorskip("mujoco")
    ep = _fit("mujoco", "box")
    mu, mu_t, mu_r = ep["friction"]
    assert ep["condim"] == 4 and ep["cone"] == "elliptic"
    assert 0.0 < mu < 1.0 and 0.0 <= mu_t and mu_r == pytest.approx(1e-4)
    assert ep.errors["default"] is not ep.errors["fitted"]


def test_anisotropy_noted():
    pytest.importorskip("mujoco")
    body = BODIES["puck"]
    ep = engine_parameters(
        body, ss.FrictionTensor(0.2, 0.4), "mujoco", launches=_launches(body)[:1]
    )
    assert any("isotropic" in n for n in ep.notes)


def test_pybullet_body_fixed_anisotropy():
    pytest.importorskip("pybullet")
    body = BODIES["box"]
    friction = ss.FrictionTensor(0.2, 0.4, frame="body")
    speed = math.sqrt(2.0 * 0.3 * 9.81 * 0.5 * body.length_unit)
    launches = (ss.State(vx=speed * 0.8, vy=speed * 0.6),)
    ep = engine_parameters(body, friction, "pybullet", launches=launches)
    ax, ay, az = ep["anisotropicFriction"]
    assert ax == 1.0 and az == 1.0 and ay != 1.0  # the body-fixed anisotropy is fitted
    assert ep.errors["fitted"]["distance"] < ep.errors["naive"]["distance"]


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"engine": "bullet"}, "engine = 'bullet' is invalid; valid values: mujoco"),
        ({"dt": 0.5}, r"dt = 0\.5 s is invalid; valid range"),
        ({"g": -1.0}, "g = -1.0"),
        ({"launches": []}, "launches"),
        ({"launches": [ss.State()]}, r"launches\[0\]"),
    ],
)
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        engine_parameters(BODIES["box"], FRICTION, **kwargs)


def test_bad_body_and_friction():
    star = ss.Polygon([(0, 0), (2, 0), (1, 0.2), (2, 1), (0, 1)])
    with pytest.raises(ValueError, match="body.patch"):
        engine_parameters(ss.Body(star, ss.UniformPressure(), mass=1.0), FRICTION)
    with pytest.raises(TypeError, match="body"):
        engine_parameters("box", FRICTION)
    with pytest.raises(TypeError, match="friction"):
        engine_parameters(BODIES["box"], 0.3)


@pytest.mark.parametrize("engine", sorted(MODULES))
def test_missing_engine(engine, monkeypatch):
    for mod in list(sys.modules):
        if mod == MODULES[engine] or mod.startswith(MODULES[engine] + "."):
            monkeypatch.delitem(sys.modules, mod)
    monkeypatch.setitem(sys.modules, MODULES[engine], None)
    if engine == "drake":
        monkeypatch.setitem(sys.modules, "pydrake.all", None)
    with pytest.raises(ImportError, match=rf'pip install "slidespin\[{engine}\]"'):
        engine_parameters(BODIES["box"], FRICTION, engine)
