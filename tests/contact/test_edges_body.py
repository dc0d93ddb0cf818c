"""``Body.engine_params`` is computed once per friction tensor and handed out as copies; the
``Body`` docstring says what a Blade can do, and a Blade under anisotropic friction does it.

Independent truths: a fresh body's parameters (the cache changes nothing), and the closed
forms of a blade sliding along its axis (stop time v₀/(fx g), stop distance v₀²/(2 fx g)).
"""

from __future__ import annotations

import numpy as np
import pytest

import slidespin as ss
from slidespin.contact.body import ENGINE_CACHE, Body
from slidespin.contact.shapes import Blade


def _box():
    return Body(ss.Rectangle(0.4, 0.3), ss.UniformPressure(), mass=1.0)


def test_engine_params_are_computed_once_per_tensor(monkeypatch):
    calls = []
    real = Body._engine_params

    def counting(self, friction, tol):
        calls.append((friction, tol))
        return real(self, friction, tol)

    monkeypatch.setattr(Body, "_engine_params", counting)
    body = _box()
    for _ in range(3):
        body.engine_params(ss.FrictionTensor(0.3, 0.4))  # equal tensors, new objects
    assert len(calls) == 1
    body.engine_params(ss.FrictionTensor(0.3, 0.4, angle=0.1))
    body.engine_params(ss.FrictionTensor(0.3, 0.4), 1e-10)
    body.engine_params(ss.FrictionTensor(0.3, 0.4, frame="body"))
    assert len(calls) == 4
    for i in range(2 * ENGINE_CACHE):  # the cache keeps the last ENGINE_CACHE tensors only
        body.engine_params(ss.FrictionTensor(0.3, 0.4 + 0.01 * i))
    assert len(body._cache) == ENGINE_CACHE


def test_engine_params_are_fresh_copies_the_caller_may_change():
    fr = ss.FrictionTensor(0.3, 0.4, 0.1, angle=0.3)
    body = _box()
    first = body.engine_params(fr)
    truth = _box().engine_params(fr)  # a fresh body: nothing cached
    for arr in first:
        assert arr.flags.writeable
        arr[...] = 7.0
    again = body.engine_params(fr)
    for a, b in zip(again, truth):
        assert np.array_equal(a, b)


def test_engine_params_refuse_a_non_tensor():
    with pytest.raises(
        ValueError, match="friction = .* is invalid; valid values: a FrictionTensor"
    ):
        _box().engine_params((0.3, 0.4))


def test_the_docstring_no_longer_says_a_blade_is_refused():
    doc = " ".join(Body.__doc__.split())
    assert "refuse it (" not in doc and "friction_wrench only: the integrating" not in doc
    assert "a ``Blade`` (a line contact) included, works with every feature" in doc


def test_a_blade_under_anisotropic_friction_slides_to_its_closed_form_stop():
    """Pure translation along a blade along ξ: the friction is −fx m g, constant."""
    body = Body(Blade(0.3), ss.UniformPressure(), mass=2.0)
    fr = ss.FrictionTensor(0.3, 0.5)
    tr = ss.simulate(body, fr, ss.State(vx=1.2), g=9.81)
    assert tr.t_stop == pytest.approx(1.2 / (0.3 * 9.81), rel=1e-9)
    assert tr.stop_state.x == pytest.approx(1.2**2 / (2 * 0.3 * 9.81), rel=1e-9)
    many = ss.simulate_many(body, fr, [ss.State(vx=1.2), ss.State(vy=1.2)], g=9.81)
    assert many.t_stop == pytest.approx([1.2 / (0.3 * 9.81), 1.2 / (0.5 * 9.81)], rel=1e-9)


def test_a_pickled_body_leaves_its_cache_behind():
    import pickle

    body = _box()
    fresh = len(pickle.dumps(body))
    body.engine_params(ss.FrictionTensor(0.3, 0.4))
    assert len(pickle.dumps(body)) == fresh
    back = pickle.loads(pickle.dumps(body))
    assert back == body and back._cache is None
    for a, b in zip(
        back.engine_params(ss.FrictionTensor(0.3, 0.4)),
        body.engine_params(ss.FrictionTensor(0.3, 0.4)),
    ):
        assert np.array_equal(a, b)
