"""Derivatives of where and when a motion stops (MODEL §15).

:func:`stop_sensitivities` differentiates the stop of a free motion (its time t_stop, the stop
pose x, y, φ and the terminal ratio β*) with respect to the friction entries, the pressure
centre, the moment of inertia and the start's velocities, by the variational equations
integrated with the motion (:mod:`slidespin.motion.sensitivity`). The same run along the
whole path is ``simulate(..., sensitivities=...)``.
"""

from __future__ import annotations

from collections.abc import Sequence

from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.motion.sensitivity import PARAMETERS, STOP_OUTPUTS, check_parameters
from slidespin.motion.simulate import simulate
from slidespin.motion.state import State

__all__ = ["stop_sensitivities"]


def stop_sensitivities(
    body: Body,
    friction: FrictionTensor,
    state: State,
    parameters: Sequence[str] | str = PARAMETERS,
    g: float = 9.81,
    rtol: float = 1e-10,
) -> dict[str, dict[str, float]]:
    """Derivatives of the stop of a free motion with respect to its parameters (MODEL §15).

    Parameters
    ----------
    body : Body
        Any patch and pressure law that :func:`slidespin.simulate` runs (``xi_c``,
        ``eta_c`` need the uniform or linear law: the pressure centre must be free to move).
    friction : FrictionTensor
        A constant friction law (plane- or body-fixed, any angle).
    state : State
        The start (SI); it must move.
    parameters : sequence of str, default all nine below
        Among ``fx``, ``fy``, ``f`` (the tensor's entries), ``xi_c``, ``eta_c`` (the
        pressure centre = G in the body frame [m]), ``moment_of_inertia`` [kg m²], ``vx``,
        ``vy`` [m/s], ``omega`` [rad/s] (the start's velocities); also ``angle`` (the
        tensor's principal axes [rad]) and ``phi0`` (the start's body angle [rad]).
    g : float, default 9.81
        Gravitational acceleration [m/s²].
    rtol : float, default 1e-10
        Tolerance of the integration (the motion and its sensitivities).

    Returns
    -------
    dict
        ``{parameter: {"t_stop": ∂t_stop/∂θ, "x": ∂x_stop/∂θ, "y": ∂y_stop/∂θ, "phi":
        ∂φ_stop/∂θ, "beta_stop": ∂β*/∂θ}}`` in SI units (per unit of the parameter). For a
        pure sliding or pure spinning ending that attracts nearby motions ∂β*/∂θ is 0 (β*
        stays ∞ or 0); for an ending that does not attract them (a start on an invariant set,
        e.g. pure translation whose pure-sliding ending is unstable) β* jumps under a change
        that leaves the set, its derivative does not exist and is NaN, with a warning; so
        for a spiral ending (no terminal direction), and for a round body under an isotropic
        tensor with respect to ``fx``, ``fy``, ``xi_c``, ``eta_c``, which break its symmetry
        (β* has a kink there).

    Raises
    ------
    ValueError
        For an unknown parameter, a start at rest, a motion that does not stop (status other
        than ``stopped``), or a load, slope, speed law or tall body (not covered).

    Notes
    -----
    Forward mode: the variational equation dS/dτ = (∂G/∂y) S + ∂G/∂θ of the regularised
    system (MODEL §5) is integrated with the motion, ∂G/∂y from the wrench's exact
    derivatives (analytic on an ellipse; on a footprint, differences of its exact wrench in
    the ICR), ∂G/∂θ exact for the tensor, the inertia, an ellipse's pressure centre and the
    start, a central difference of the exact right-hand side for a footprint's pressure
    centre (:mod:`slidespin.motion._sensitivity_core`);
    the stop's derivatives are the limits of S as τ → ∞. Agreement with
    Richardson-extrapolated differences of whole simulations is about 1e-8 relative (tests).

    Examples
    --------
    >>> import slidespin as ss
    >>> body = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), mass=1.0)
    >>> d = ss.stop_sensitivities(body, ss.FrictionTensor(0.3, 0.3), ss.State(vx=1.0),
    ...                           parameters=("vx",))
    >>> round(d["vx"]["t_stop"], 6)  # t_stop = v0/(μ g)
    0.339789
    """
    parameters = check_parameters(parameters)
    if not isinstance(state, State):
        raise ValueError(f"state = {state!r} is invalid; valid values: a slidespin.State")
    if (state.vx, state.vy, state.omega) == (0.0, 0.0, 0.0):
        raise ValueError(
            f"state = {state!r} is at rest: there is no motion to differentiate; valid "
            "values: a state with a nonzero velocity or spin"
        )
    tr = simulate(body, friction, state, g, rtol, sensitivities=parameters)
    assert tr.sensitivities is not None
    stop = tr.sensitivities.stop
    return {p: {q: float(stop[p][q]) for q in STOP_OUTPUTS} for p in stop}
