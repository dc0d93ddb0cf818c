"""Independent reference for the derivatives of a motion's stop (test oracle, MODEL §15).

Differentiates whole simulations: central differences of :func:`slidespin.simulate`'s stop
values (t_stop, x, y, φ, β*) at steps h and h/2, Richardson-extrapolated, D = (4 D(h/2) −
D(h))/3 (error O(h⁴)). The parameters are changed here by rebuilding the public objects
(``Body``, ``FrictionTensor``, ``State``) from their own fields: no code of
:mod:`slidespin.motion.sensitivity` is used. The simulations run at rtol 1e-12, so that the
differences' round-off (1e-12 / h) stays below 1e-8 of the derivative at the default steps.
"""

from __future__ import annotations

import dataclasses

import numpy as np

import slidespin as ss

OUTPUTS = ("t_stop", "x", "y", "phi", "beta_stop")


def changed(body, friction, state, name, value):
    """The body, tensor and start with parameter ``name`` set to ``value``."""
    if name in ("fx", "fy", "f"):
        return body, dataclasses.replace(friction, **{name: value}), state
    if name in ("vx", "vy", "omega"):
        return body, friction, dataclasses.replace(state, **{name: value})
    if name == "moment_of_inertia":
        return ss.Body(body.patch, body.pressure, body.mass, value), friction, state
    p = body.pressure
    xi, eta = (p.xi_c, p.eta_c) if isinstance(p, ss.LinearPressure) else body.mass_centre
    law = ss.LinearPressure(value, eta) if name == "xi_c" else ss.LinearPressure(xi, value)
    return ss.Body(body.patch, law, body.mass, body.moment_of_inertia), friction, state


def value(body, friction, state, name):
    if name in ("fx", "fy", "f"):
        return getattr(friction, name)
    if name in ("vx", "vy", "omega"):
        return getattr(state, name)
    if name == "moment_of_inertia":
        return body.moment_of_inertia
    p = body.pressure
    xi, eta = (p.xi_c, p.eta_c) if isinstance(p, ss.LinearPressure) else body.mass_centre
    return xi if name == "xi_c" else eta


def stop_values(body, friction, state, g=9.81):
    tr = ss.simulate(body, friction, state, g, 1e-12)
    s = tr.stop_state
    return np.array([tr.t_stop, s.x, s.y, s.phi, tr.beta_stop])


def step(body, friction, state, name, rel):
    if name in ("fx", "fy", "f"):
        return rel * max(friction.fx, friction.fy)
    if name in ("xi_c", "eta_c"):
        return rel * body.length_unit
    if name == "moment_of_inertia":
        return rel * body.moment_of_inertia
    k = body.radius_of_gyration
    speed = float(np.sqrt(state.vx**2 + state.vy**2 + (k * state.omega) ** 2))
    return rel * (speed / k if name == "omega" else speed)


def derivatives(body, friction, state, name, rel=1e-3, g=9.81):
    """Richardson-extrapolated central differences of the stop values with respect to
    ``name``: a dict over :data:`OUTPUTS`."""
    x0 = value(body, friction, state, name)
    h = step(body, friction, state, name, rel)
    d = richardson(lambda x: stop_values(*changed(body, friction, state, name, x), g), x0, h)
    return dict(zip(OUTPUTS, d))


def richardson(f, x, h):
    """f′(x) by central differences at h and h/2, Richardson-extrapolated: (4 D(h/2) − D(h))/3,
    error O(h⁴); ``f`` may return an array (NaN entries stay NaN: β* = ∞ on both sides)."""

    def central(h):
        with np.errstate(invalid="ignore"):
            return (np.asarray(f(x + h)) - np.asarray(f(x - h))) / (2.0 * h)

    with np.errstate(invalid="ignore"):
        return (4.0 * central(h / 2.0) - central(h)) / 3.0
