"""How a run ended: one vocabulary of statuses and endings for every part of slidespin.

``Trajectory.status``, ``StopResults.status``, JSON, CSV, Parquet sweeps and the CLI all use
these names (diffrax's habit: a result carries a status with a message, it does not raise).

Statuses (is the reported stop a property of the motion, independent of solver settings?)

========================  =====================================================================
``stopped``               Converged: the body stops, and the ending, t_stop, β* and ϑ* are
                          independent of ``rtol`` and ``max_step`` to the documented accuracy.
``marginal``              The direction of motion approaches a fixed point of the sphere flow
                          at which an eigenvalue vanishes (a Table 2 boundary or its analogue):
                          the approach is algebraic, not exponential (or, measured, slower
                          than a halving of the distance while ln s falls by 720). The
                          reported ending, β* and ϑ* are the analytic limit (the fixed
                          point), t_stop and the position are converged.
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

Loaded runs (applied loads, slopes, ``t_end``; MODEL §11, :mod:`slidespin.motion.loaded`)

A loaded body need not stop, so its run is bounded by ``t_end`` and the questions differ: did
the integration reach its end (status), and in what state is the body there (ending)? Their
names are kept apart from the unloaded ones (:data:`LOADED_STATUSES`, :data:`LOADED_ENDINGS`);
``max_steps`` and ``step_too_small`` mean the same in both, with a loaded wording.

========================  =====================================================================
``ok``                    Converged: the run reached its end (``t_end``, or the final stick
                          when there is none) with every stick–slip transition located to
                          the integrator's tolerance.
``max_steps``             The step budget ran out before the end: values as reached.
``max_phases``            More stick and slip phases than the budget ``max_phases``: values as
                          reached.
``step_too_small``        The integrator could not meet its tolerance: values as reached.
``no_onset``              The load left the static-friction set but no slip direction was
                          found (a solver failure: one always exists, MODEL §11); the run
                          ends there with the body at rest.
``tipping``               A tall body (``Body(..., height=h)``, MODEL §14) tips: its
                          pressure centroid reached the convex hull of the footprint, at
                          ``LoadedTrajectory.tip_time`` (located to ``time_tol``); the run
                          ends there, at rest or sliding.
========================  =====================================================================

Pushed runs (a pusher with a prescribed motion; MODEL §13, :mod:`slidespin.motion.pushed`,
:mod:`slidespin.motion.quasi_static`) use the loaded statuses, plus ``indeterminate``: no
contact mode is consistent at a switch (a Painlevé-type case of the dynamics, or no
quasi-static balance): the run ends there, values as reached. The contact modes of a point
pusher (:data:`PUSH_MODES`): ``separated``, ``sticking``, ``sliding_left`` and ``sliding_right``
(the finger slides towards +t = ẑ × n over the body, n the inward normal: to its left looking
into the body; the tangential force is then +μp λn along t, and −μp λn for ``sliding_right``).
A line pusher (:mod:`slidespin.motion.pushed_line`) adds ``face_sticking``,
``face_sliding_left`` and ``face_sliding_right`` (a body edge flush with its face, carrying a
line load whose resultant lies on the shared segment), ``vertex_*`` (a body vertex on its face)
and ``end_*`` (its end on a body edge), each ``*_sticking``, ``*_sliding_left`` or
``*_sliding_right`` in the same sense.

Loaded endings: ``stopped_stuck`` (moved, and is at rest and held at the end),
``at_rest_throughout`` (static friction held it over the whole run), ``moving_at_t_end``
(still moving at the end of the run: ``t_end``, or where an unconverged status ended it),
``steady_sliding`` (moving at ``t_end`` under a constant load at a speed that no longer changes,
to 1e-6 of itself over the run).
"""

from __future__ import annotations

__all__ = [
    "STATUSES",
    "ENDINGS",
    "STATUS_MESSAGES",
    "CONVERGED",
    "FLAGGED",
    "UNCONVERGED",
    "ENDING_MESSAGES",
    "LOADED_STATUSES",
    "LOADED_ENDINGS",
    "LOADED_STATUS_MESSAGES",
    "LOADED_ENDING_MESSAGES",
    "LOADED_CONVERGED",
    "LOADED_FLAGGED",
    "LOADED_UNCONVERGED",
    "PUSH_MODES",
    "PUSHED_STATUSES",
    "PUSHED_STATUS_MESSAGES",
    "status_message",
    "ending_message",
]

#: status names, indexed by the integer codes of the compiled integrator
#: (``slidespin.motion._integrator.ST_*``)
STATUSES = (
    "stopped",
    "max_steps",
    "step_too_small",
    "at_rest",
    "marginal",
    "saddle",
    "non_finite",
)

#: ending names, indexed by the integer ending codes of :class:`slidespin.motion.batch.StopResults`
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


#: one-line explanation of each ending
ENDING_MESSAGES = {
    "mixed": "stops sliding and spinning together, v = beta* omega with finite beta*",
    "pure_sliding": "the spin vanishes before the speed (omega/v -> 0): beta* infinite",
    "pure_spinning": "the speed vanishes before the spin (v/omega -> 0): beta* = 0",
    "at_rest": "the body starts at rest",
    "spiral": "stops while the direction of motion keeps turning: no theta*",
}

#: status names of a loaded run (``LoadedTrajectory.status``)
LOADED_STATUSES = ("ok", "max_steps", "max_phases", "step_too_small", "no_onset", "tipping")

#: ending names of a loaded run (``LoadedTrajectory.ending``)
LOADED_ENDINGS = ("stopped_stuck", "at_rest_throughout", "moving_at_t_end", "steady_sliding")

#: one-line explanation of each loaded status
LOADED_STATUS_MESSAGES = {
    "ok": "converged: the run reached its end with every stick-slip transition located",
    "max_steps": "step budget exhausted before the end of the run; values as reached",
    "max_phases": "more stick and slip phases than max_phases; values as reached",
    "step_too_small": "the integrator could not meet its tolerance; values as reached",
    "no_onset": "the load left the static-friction set but no slip direction was found "
    "(a solver failure); the run ends there with the body at rest",
    "tipping": "the tall body tips: its pressure centroid reached the footprint's convex "
    "hull at tip_time; the run ends there",
}

#: one-line explanation of each loaded ending
LOADED_ENDING_MESSAGES = {
    "stopped_stuck": "moved, and is at rest and held by static friction at the end",
    "at_rest_throughout": "static friction held the body at rest over the whole run",
    "moving_at_t_end": "still moving at the end of the run (t_end, unless the status says "
    "the run ended early)",
    "steady_sliding": "sliding at t_end under a constant load at a speed that no longer "
    "changes (by less than 1e-6 of itself over the run)",
}

#: contact modes of a pusher, indexed by the integer mode codes of the pushed results: a point
#: pusher's (0–3), then a line pusher's (4–12): its face flush with an edge of the body
#: (``face_*``), a body vertex on its face (``vertex_*``), its end on a body edge (``end_*``)
PUSH_MODES = (
    "separated",
    "sticking",
    "sliding_left",
    "sliding_right",
    "face_sticking",
    "face_sliding_left",
    "face_sliding_right",
    "vertex_sticking",
    "vertex_sliding_left",
    "vertex_sliding_right",
    "end_sticking",
    "end_sliding_left",
    "end_sliding_right",
)

#: status names of a pushed run (``PushedTrajectory.status``, ``QuasiStaticPush.status``)
PUSHED_STATUSES = ("ok", "max_steps", "max_phases", "step_too_small", "no_onset", "indeterminate")

#: one-line explanation of each pushed status (the loaded ones, and ``indeterminate``)
PUSHED_STATUS_MESSAGES = {
    **LOADED_STATUS_MESSAGES,
    "max_phases": "more mode switches and path knots than max_phases; values as reached",
    "no_onset": "a separated body at rest under a load beyond static friction (its slow start "
    "is not integrated in a pushed run); the run ends there",
    "indeterminate": "no contact mode of the pusher is consistent (a Painleve-type case, or "
    "no quasi-static balance); the run ends there, values as reached",
}

#: the loaded run reached its end: converged
LOADED_CONVERGED = frozenset({"ok", "tipping"})
#: no loaded status is an analytic limit (kept for symmetry with :data:`FLAGGED`)
LOADED_FLAGGED: frozenset[str] = frozenset()
#: the loaded run ended early: values as reached (exit status 1 in the CLI)
LOADED_UNCONVERGED = frozenset({"max_steps", "max_phases", "step_too_small", "no_onset"})


def _lookup(kind: str, name: str, messages: dict[str, str], names: tuple[str, ...]) -> str:
    try:
        return messages[name]
    except KeyError:
        raise ValueError(
            f"{kind} = {name!r} is invalid; valid values: {', '.join(names)}"
        ) from None


def status_message(status: str, *, loaded: bool = False, pushed: bool = False) -> str:
    """One-line explanation of a status name.

    Parameters
    ----------
    status : str
        A name of :data:`STATUSES`, of :data:`LOADED_STATUSES` with ``loaded=True``, or of
        :data:`PUSHED_STATUSES` with ``pushed=True``.
    loaded : bool, default False
        Explain the status of a loaded run
        (:class:`slidespin.motion.loaded_trajectory.LoadedTrajectory`).
    pushed : bool, default False
        Explain the status of a pushed run
        (:class:`slidespin.motion.pushed_trajectory.PushedTrajectory`,
        :class:`slidespin.motion.quasi_static.QuasiStaticPush`).

    Raises
    ------
    ValueError
        If ``status`` is not in the vocabulary chosen by ``loaded``.
    """
    if pushed:
        return _lookup("status", status, PUSHED_STATUS_MESSAGES, PUSHED_STATUSES)
    if loaded:
        return _lookup("status", status, LOADED_STATUS_MESSAGES, LOADED_STATUSES)
    return _lookup("status", status, STATUS_MESSAGES, STATUSES)


def ending_message(ending: str, *, loaded: bool = False) -> str:
    """One-line explanation of an ending name.

    Parameters
    ----------
    ending : str
        A name of :data:`ENDINGS`, or of :data:`LOADED_ENDINGS` with ``loaded=True``.
    loaded : bool, default False
        Explain the ending of a loaded run
        (:class:`slidespin.motion.loaded_trajectory.LoadedTrajectory`).

    Raises
    ------
    ValueError
        If ``ending`` is not in the vocabulary chosen by ``loaded``.
    """
    if loaded:
        return _lookup("ending", ending, LOADED_ENDING_MESSAGES, LOADED_ENDINGS)
    return _lookup("ending", ending, ENDING_MESSAGES, ENDINGS)
