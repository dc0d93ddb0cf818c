"""Sweeps over applied loads and tilt: does a body at rest hold, and how does a loaded body move.

A sweep spec with ``compute = "statics"`` or ``compute = "loaded"`` (:mod:`slidespin.studies.sweep`)
adds the keys of the case file's ``[load]`` and ``[incline]`` tables, prefixed by the table's
name (``load_fx``, ``incline_angle``, ...), and ``t_end`` of ``[solver]``:

==========================  ================================================================
``load_fx``, ``load_fy``    applied force [N] at G, in ``load_frame`` (default 0)
``load_torque``             applied torque about the vertical [N m] (default 0)
``load_frame``              plane | body (default plane)
``incline_angle``           tilt α of the plane [rad], in [0, π/2) (or ``incline_angle_deg``)
``incline_downhill``        direction of steepest descent δ in the plane frame [rad] (default 0)
``t_end``                   end of a loaded run [s], in (0, 1e9] (required when loaded)
==========================  ================================================================

What bounds the work of a loaded case is the spec's ``max_steps`` (the budget of integrator
steps of each run, default 200 000, as :func:`slidespin.simulate`; the engine's budget of stick
and slip phases is 1000), not ``t_end``: a long ``t_end`` ends, at the latest, with the status
``max_steps`` (measured on a spinning, pushed disk with t_end = 1e7 s: about 2 minutes per
case on one core of a 2-core machine at the default budget). Loads the engines would refuse
mid-run (larger than 10⁶ times the weight) are refused before the sweep starts
(:func:`slidespin.studies._sweep_inputs.check_loads`).

``compute = "statics"`` (MODEL §11; :mod:`slidespin.contact.statics`): per case, the critical tilt
α_c along ``incline_downhill`` at the body angle ``phi0``
(:func:`~slidespin.critical_tilt`; the load keys do not enter it), the load factor
λ* of the whole applied wrench (load plus the downhill pull of the tilt;
:func:`~slidespin.contact.statics.load_factor`, ``inf`` for none) and whether the body at rest holds
(``ending`` = ``sticks`` iff λ* ≥ 1, else ``slides``; status ``ok``). The initial velocities
are not used.

``compute = "loaded"`` (:func:`slidespin.simulate` with ``load=``, ``incline=``, ``t_end=``,
i.e. :func:`~slidespin.motion.loaded.simulate_loaded`): the ending and status of the run
(:class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory`) and its final state.

Both call Python per case (one case is one statics solve or one loaded integration), so they
are far slower than the compiled stop sweeps: ``docs/guide/sweeps.md`` gives the measured
rates. They run through the same chunks, resume and executors.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.contact import statics  # module attribute: tests patch statics.critical_tilt
from slidespin.contact.incline import Incline
from slidespin.motion.loads import Load, applied_wrench
from slidespin.motion.simulate import simulate
from slidespin.motion.state import State

__all__ = [
    "CaseError",
    "MODES",
    "LOAD_PARAMETERS",
    "LOAD_COLUMNS",
    "STATICS_COLUMNS",
    "LOADED_COLUMNS",
    "STATICS_STATUSES",
    "STATICS_ENDINGS",
    "load_columns",
    "compute_statics",
    "compute_loaded",
]

#: what a sweep computes per case: the stop (compiled batch engine), the statics, a loaded run
MODES = ("stop", "statics", "loaded")
#: load and tilt keys of a sweep spec and their defaults (None: derived or required)
LOAD_PARAMETERS = {
    "load_fx": 0.0,
    "load_fy": 0.0,
    "load_torque": 0.0,
    "load_frame": "plane",
    "incline_angle": None,
    "incline_angle_deg": None,
    "incline_downhill": 0.0,
    "t_end": None,
}
_LOAD_KEYS = ("load_fx", "load_fy", "load_torque", "load_frame")
_INCLINE_KEYS = ("incline_angle", "incline_angle_deg", "incline_downhill")
#: the load and tilt columns of every statics or loaded chunk
LOAD_COLUMNS = (
    "load_fx",
    "load_fy",
    "load_torque",
    "load_frame",
    "incline_angle",
    "incline_angle_deg",
    "incline_downhill",
)
#: result columns of ``compute = "statics"``
STATICS_COLUMNS = ("critical_tilt", "critical_tilt_deg", "load_factor", "ending", "status")
#: result columns of ``compute = "loaded"``
LOADED_COLUMNS = (
    "t_end",
    "t_final",
    "t_stop",
    "x_end",
    "y_end",
    "phi_end",
    "vx_end",
    "vy_end",
    "omega_end",
    "speed_end",
    "n_slip",
    "slip_time",
    "energy_error",
    "n_rhs",
    "ending",
    "status",
)
#: the status of a statics case (a statics solve has no budget to run out of)
STATICS_STATUSES = ("ok",)
#: the ending of a statics case: the body at rest holds (λ* ≥ 1) or starts to slide
STATICS_ENDINGS = ("sticks", "slides")


class CaseError(RuntimeError):
    """A statics or loaded case failed; ``index`` is its row in the block of cases."""

    def __init__(self, index: int, exc: Exception) -> None:
        super().__init__(f"{type(exc).__name__}: {exc}")
        self.index = index


def _bad(name, arr, ok, valid):
    if not ok.all():
        i = int(np.flatnonzero(~ok)[0])
        val = arr[i].item() if isinstance(arr[i], np.generic) else arr[i]
        raise ValueError(f"{name} = {val!r} (case {i}) is invalid; valid range: {valid}")


def load_columns(cols: dict, n: int, mode: str) -> dict:
    """The validated load and tilt columns of ``n`` cases (:data:`LOAD_COLUMNS`, and
    ``t_end`` for ``mode = "loaded"``), defaults filled in, angles in radians and degrees.

    Raises ValueError naming the key, the first bad case, its value and the valid range.
    """

    def get(k, default):
        val = cols.get(k)
        if val is None:
            return np.full(n, default, dtype=object if isinstance(default, str) else float)
        return np.asarray(val)

    out: dict = {}
    for k in ("load_fx", "load_fy", "load_torque", "incline_downhill"):
        arr = get(k, LOAD_PARAMETERS[k]).astype(float)
        _bad(k, arr, np.isfinite(arr), "finite")
        out[k] = arr
    frame = get("load_frame", "plane").astype(str)
    _bad("load_frame", frame, np.isin(frame, ("plane", "body")), "one of plane, body")
    out["load_frame"] = frame
    if "incline_angle_deg" in cols:
        deg = np.asarray(cols["incline_angle_deg"], dtype=float)
        with np.errstate(all="ignore"):
            _bad("incline_angle_deg", deg, np.isfinite(deg) & (deg >= 0) & (deg < 90), "[0, 90)")
        rad = np.radians(deg)
    else:
        rad = get("incline_angle", 0.0).astype(float)
        with np.errstate(all="ignore"):
            _bad(
                "incline_angle",
                rad,
                np.isfinite(rad) & (rad >= 0) & (rad < math.pi / 2),
                f"[0, {math.pi / 2!r}) rad",
            )
        deg = np.degrees(rad)
    out["incline_angle"] = rad
    out["incline_angle_deg"] = deg
    if mode == "loaded":
        if "t_end" not in cols:
            raise ValueError(
                "compute = 'loaded' needs 't_end' [s] (fix or vary it); valid range: (0, 1e9] s"
            )
        t_end = np.asarray(cols["t_end"], dtype=float)
        with np.errstate(all="ignore"):
            _bad("t_end", t_end, np.isfinite(t_end) & (t_end > 0) & (t_end <= 1e9), "(0, 1e9] s")
        out["t_end"] = t_end
    return out


def _load_objects(loads: dict, i: int, given: set):
    """(Load or None, Incline or None) of case ``i``: None for a group the spec omits."""
    load = None
    if given & set(_LOAD_KEYS):
        load = Load(
            force=(float(loads["load_fx"][i]), float(loads["load_fy"][i])),
            torque=float(loads["load_torque"][i]),
            frame=str(loads["load_frame"][i]),
        )
    incline = None
    if given & set(_INCLINE_KEYS):
        incline = Incline(float(loads["incline_angle"][i]), float(loads["incline_downhill"][i]))
    return load, incline


def compute_statics(
    bodies, frictions, states: np.ndarray, g: np.ndarray, loads: dict, given: set, on_case=None
) -> dict:
    """Statics of each case at rest (critical tilt, load factor, sticks or slides).

    Parameters
    ----------
    bodies, frictions : sequences of Body, FrictionTensor (one per case)
    states : ndarray, shape (N, 6)
        Initial states (x, y, phi, vx, vy, omega); only phi is used.
    g : ndarray, shape (N,)
        Gravitational acceleration [m/s²].
    loads : dict
        :func:`load_columns`.
    given : set of str
        The keys the spec fixes or varies (a load or tilt group it omits is absent).
    on_case : callable or None
        Called with no argument after each case (progress).

    Returns
    -------
    dict
        The columns of :data:`STATICS_COLUMNS`.
    """
    n = len(bodies)
    tilt = np.empty(n)
    lam = np.empty(n)
    for i in range(n):
        body, fr, phi = bodies[i], frictions[i], float(states[i, 2])
        try:
            load, incline = _load_objects(loads, i, given)
            tilt[i] = statics.critical_tilt(body, fr, float(loads["incline_downhill"][i]), phi)
            # load_factor adds the tilt's downhill pull itself (MODEL §11)
            w = applied_wrench(body, 0.0, phi, load, None, float(g[i]))
            lam[i] = statics.load_factor(body, fr, w, phi, float(g[i]), incline=incline)
        except (ValueError, RuntimeError) as exc:
            raise CaseError(i, exc) from exc
        if on_case is not None:
            on_case()
    sticks = lam >= 1.0
    return {
        "critical_tilt": tilt,
        "critical_tilt_deg": np.degrees(tilt),
        "load_factor": lam,
        "ending": np.where(sticks, "sticks", "slides").astype(object),
        "status": np.full(n, "ok", dtype=object),
    }


def compute_loaded(
    bodies,
    frictions,
    states: np.ndarray,
    g: np.ndarray,
    loads: dict,
    given: set,
    rtol: float,
    *,
    max_steps: int = 200_000,
    on_case=None,
) -> dict:
    """One loaded run per case (:func:`slidespin.simulate` with ``load``, ``incline`` and
    ``t_end``); the columns of :data:`LOADED_COLUMNS` (final state at the end of the run,
    number and total time of the slip phases, energy-balance error, right-hand sides).

    ``max_steps`` is each run's budget of integrator steps: it bounds a case's work whatever
    its ``t_end`` (a run that spends it has the status ``max_steps``). ``on_case`` is called
    with no argument after each case (progress)."""
    n = len(bodies)
    num = {
        k: np.empty(n) for k in LOADED_COLUMNS if k not in ("ending", "status", "n_slip", "n_rhs")
    }
    n_slip = np.empty(n, dtype=np.int64)
    n_rhs = np.empty(n, dtype=np.int64)
    ending = np.empty(n, dtype=object)
    status = np.empty(n, dtype=object)
    for i in range(n):
        load, incline = _load_objects(loads, i, given)
        t_end = float(loads["t_end"][i])
        try:
            tr = simulate(
                bodies[i],
                frictions[i],
                State(*(float(x) for x in states[i])),
                float(g[i]),
                rtol,
                max_steps=max_steps,
                load=load,
                incline=incline,
                t_end=t_end,
            )
        except (ValueError, RuntimeError) as exc:
            raise CaseError(i, exc) from exc
        slips = tr.slip_intervals
        num["t_end"][i] = t_end
        num["t_final"][i] = tr.t[-1]
        num["t_stop"][i] = tr.t_stop
        for k, arr in (
            ("x", tr.x),
            ("y", tr.y),
            ("phi", tr.phi),
            ("vx", tr.vx),
            ("vy", tr.vy),
            ("omega", tr.omega),
        ):
            num[f"{k}_end"][i] = arr[-1]
        num["speed_end"][i] = math.hypot(tr.vx[-1], tr.vy[-1])
        num["slip_time"][i] = sum(b - a for a, b in slips)
        num["energy_error"][i] = tr.energy_error
        n_slip[i] = len(slips)
        n_rhs[i] = tr.n_rhs
        ending[i] = tr.ending
        status[i] = tr.status
        if on_case is not None:
            on_case()
    return {**num, "n_slip": n_slip, "n_rhs": n_rhs, "ending": ending, "status": status}
