"""How a run ended: one vocabulary of statuses and endings for every part of slidespin.

``Trajectory.status``, ``StopResults.status``, JSON, CSV, Parquet sweeps and the CLI all use
these names (diffrax's habit: a result carries a status with a message, it does not raise).

Statuses (is the reported stop a property of the motion, independent of solver settings?)

========================  =====================================================================
``stopped``               Converged: the body stops, and the ending, t_stop, β* and ϑ* are
                          independent of ``rtol`` and ``max_step`` to the documented accuracy.
``marginal``              The direction of motion approaches a fixed point of the sphere flow
                          at which an eigenvalue vanishes (a Table 2 boundary or its analogue):
                          the approach is algebraic, not exponential. The reported ending, β*
                          and ϑ* are the analytic limit (the fixed point), t_stop and the
                          position are converged.
``saddle``                The motion passes so close to an unstable (saddle) fixed point that
                          round-off, not the physics, chooses where it goes next; this happens
                          at an energy far below any physical scale. The reported ending, β*
                          and ϑ* are those of the saddle: what the motion does down to the
                          energy ``saddle_energy`` (fraction of the initial kinetic energy).
``max_steps``             The step budget ran out before the stop converged: values as reached.
``step_too_small``        The integrator could not meet its tolerance: values as reached.
``non_finite``            A state or step became NaN or infinite; the run was ended there.
``at_rest``               The body starts at rest (nothing to integrate).
========================  =====================================================================

Endings (what the motion looks like as it stops; MODEL §5–6, §9)

``mixed`` (v = β* ω, finite β* ≠ 0), ``pure_sliding`` (ω/v → 0), ``pure_spinning`` (v/ω → 0),
``spiral`` (the body stops while the direction of its motion keeps turning: no ϑ*), ``at_rest``.
"""

from __future__ import annotations

__all__ = [
    "STATUSES",
    "ENDINGS",
    "STATUS_MESSAGES",
    "CONVERGED",
    "FLAGGED",
    "UNCONVERGED",
    "status_message",
]

#: status names, indexed by the integer codes of the compiled integrator (``_ode.ST_*``)
STATUSES = (
    "stopped",
    "max_steps",
    "step_too_small",
    "at_rest",
    "marginal",
    "saddle",
    "non_finite",
)

#: ending names, indexed by the integer ending codes of :class:`slidespin.batch.StopResults`
ENDINGS = ("mixed", "pure_sliding", "pure_spinning", "at_rest", "spiral")

#: one-line explanation of each status
STATUS_MESSAGES = {
    "stopped": "converged stop, independent of solver settings",
    "marginal": "approaches a marginal (non-hyperbolic) terminal state algebraically; "
    "the reported terminal values are its analytic limit",
    "saddle": "passes a saddle so closely that round-off chooses the exit; the reported "
    "terminal values are the saddle's, observed down to saddle_energy",
    "max_steps": "step budget exhausted before the stop converged; values as reached",
    "step_too_small": "the integrator could not meet its tolerance; values as reached",
    "non_finite": "a non-finite state or step appeared; the run was ended there",
    "at_rest": "the body starts at rest",
}

#: the stop is converged and independent of solver settings
CONVERGED = frozenset({"stopped", "at_rest"})
#: the stop is a property of the motion, reported as an analytic limit, but flagged
FLAGGED = frozenset({"marginal", "saddle"})
#: the values are those reached, not a converged stop: left out of sweep tables and plots
#: by default
UNCONVERGED = frozenset({"max_steps", "step_too_small", "non_finite"})


def status_message(status: str) -> str:
    """One-line explanation of a status name."""
    try:
        return STATUS_MESSAGES[status]
    except KeyError:
        raise ValueError(
            f"status = {status!r} is invalid; valid values: {', '.join(STATUSES)}"
        ) from None
