"""slidespin: a flat rigid body sliding and spinning on a plane under anisotropic dry friction.

The friction force and moment are integrated exactly over a finite contact patch (an ellipse
under four pressure laws, or any footprint: polygons, rectangles, disks, rings, pads, a blade,
a user pressure map) for a full 2×2 friction tensor, and the motion is integrated to its finite
stop, with loads, slopes and exact stick–slip. Source: "About the movement of a solid body on a
plane surface in accordance with elliptic contact area and anisotropic friction"; the model as
built, with the paper's errata, is documented in docs/model.md.

Every public name is importable from here (``import slidespin as ss``), each imported from its
defining module on first use, so that importing slidespin costs little until a name is used. The sub-packages are
the layers of the code, each importing only those below it (docs/development.md, "Where
things live"): :mod:`slidespin.contact` < :mod:`slidespin.motion` < :mod:`slidespin.analysis`
< :mod:`slidespin.studies` < :mod:`slidespin.engines` < :mod:`slidespin.viz` <
:mod:`slidespin.paper` < :mod:`slidespin.cli`. The engine couplings (MODEL §16) are the modules
:mod:`slidespin.mujoco` and :mod:`slidespin.drake` (``ss.mujoco``, ``ss.drake``; optional
extras ``slidespin[mujoco]``, ``slidespin[drake]``).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

from slidespin._version import __version__

if TYPE_CHECKING:  # the names as the type checker and IDEs see them
    from slidespin import paper
    from slidespin.analysis.aim import UnreachableTarget, aim
    from slidespin.analysis.fit import FitWarning, IdentifiabilityWarning, compare_frames, fit
    from slidespin.analysis.fit_data import read_runs
    from slidespin.analysis.fit_push import PushFitResult, fit_pushes
    from slidespin.analysis.fit_result import FitResult
    from slidespin.analysis.intervals import (
        InertiaIntervals,
        circle_terminal_ratio,
        inertia_for_ratio,
        inertia_intervals,
        paper_inertia_intervals,
    )
    from slidespin.analysis.phase_portrait import PhasePortrait, phase_portrait
    from slidespin.analysis.push_data import PushRun, read_push, read_pushes
    from slidespin.analysis.sensitivities import stop_sensitivities
    from slidespin.analysis.terminal import TerminalState, terminal_ratio, terminal_states
    from slidespin.contact.body import Body
    from slidespin.contact.ellipse import Ellipse
    from slidespin.contact.friction import FrictionTensor
    from slidespin.contact.incline import Incline
    from slidespin.contact.limit_surface import LimitSurface, limit_surface
    from slidespin.contact.motion_cone import (
        MotionCone,
        StablePushing,
        motion_cone,
        stable_pushing,
    )
    from slidespin.contact.outline import Outline, body_outline
    from slidespin.contact.pressure import (
        BoussinesqPressure,
        HertzPressure,
        LinearPressure,
        UniformPressure,
    )
    from slidespin.contact.pressure_map import PressureMap
    from slidespin.contact.shapes import Annulus, Blade, Circle, Disk, Pads, Polygon, Rectangle
    from slidespin.contact.speed_laws import PowerLaw, SpeedTable, Stribeck
    from slidespin.contact.statics import Onset, can_stick, critical_tilt, load_factor, onset
    from slidespin.contact.tipping import Breakaway, breakaway, pressure_centre
    from slidespin.contact.wrench import Wrench, friction_wrench
    from slidespin.engines.parameters import EngineParameters, engine_parameters
    from slidespin.motion.batch import StopResults, simulate_bodies, simulate_cases, simulate_many
    from slidespin.motion.loaded import simulate_loaded
    from slidespin.motion.loaded_trajectory import LoadedTrajectory
    from slidespin.motion.loads import Load
    from slidespin.motion.outcomes import ENDINGS, STATUSES, ending_message, status_message
    from slidespin.motion.pushed import simulate_pushed
    from slidespin.motion.pushed_trajectory import PushedTrajectory
    from slidespin.motion.pushers import LinePusher, PointPusher
    from slidespin.motion.quasi_static import QuasiStaticPush, push_quasi_static
    from slidespin.motion.sensitivity import Sensitivities
    from slidespin.motion.simulate import simulate
    from slidespin.motion.springs import Spring
    from slidespin.motion.state import State
    from slidespin.motion.trajectory import Trajectory
    from slidespin.studies.case import Case, load_case
    from slidespin.studies.sweep import SweepResult, sweep
    from slidespin.studies.sweep_read import read_sweep
    from slidespin.studies.sweep_spec import SweepError
    from slidespin.viz.animate import animate, frame_states
    from slidespin.viz.law_plot import plot_speed_law
    from slidespin.viz.sweep_plot import plot_sweep
    from slidespin.viz.trajectory_plot import plot_loaded_trajectory, plot_trajectory

#: where each public name is defined: imported on first use (PEP 562), so that
#: ``import slidespin`` and ``slidespin --version`` do not load the numerical stack
_HOMES = {
    "paper": "slidespin.paper",
    # the engine couplings (optional extras; not in __all__, so that ``import *`` needs none)
    "mujoco": "slidespin.mujoco",
    "drake": "slidespin.drake",
    "EngineParameters": "slidespin.engines.parameters",
    "engine_parameters": "slidespin.engines.parameters",
    "aim": "slidespin.analysis.aim",
    "UnreachableTarget": "slidespin.analysis.aim",
    "stop_sensitivities": "slidespin.analysis.sensitivities",
    "Sensitivities": "slidespin.motion.sensitivity",
    "FitWarning": "slidespin.analysis.fit",
    "IdentifiabilityWarning": "slidespin.analysis.fit",
    "compare_frames": "slidespin.analysis.fit",
    "fit": "slidespin.analysis.fit",
    "read_runs": "slidespin.analysis.fit_data",
    "PushFitResult": "slidespin.analysis.fit_push",
    "fit_pushes": "slidespin.analysis.fit_push",
    "PushRun": "slidespin.analysis.push_data",
    "read_push": "slidespin.analysis.push_data",
    "read_pushes": "slidespin.analysis.push_data",
    "FitResult": "slidespin.analysis.fit_result",
    "InertiaIntervals": "slidespin.analysis.intervals",
    "circle_terminal_ratio": "slidespin.analysis.intervals",
    "inertia_for_ratio": "slidespin.analysis.intervals",
    "inertia_intervals": "slidespin.analysis.intervals",
    "paper_inertia_intervals": "slidespin.analysis.intervals",
    "PhasePortrait": "slidespin.analysis.phase_portrait",
    "phase_portrait": "slidespin.analysis.phase_portrait",
    "TerminalState": "slidespin.analysis.terminal",
    "terminal_ratio": "slidespin.analysis.terminal",
    "terminal_states": "slidespin.analysis.terminal",
    "Body": "slidespin.contact.body",
    "Ellipse": "slidespin.contact.ellipse",
    "FrictionTensor": "slidespin.contact.friction",
    "PowerLaw": "slidespin.contact.speed_laws",
    "SpeedTable": "slidespin.contact.speed_laws",
    "Stribeck": "slidespin.contact.speed_laws",
    "Incline": "slidespin.contact.incline",
    "LimitSurface": "slidespin.contact.limit_surface",
    "limit_surface": "slidespin.contact.limit_surface",
    "MotionCone": "slidespin.contact.motion_cone",
    "StablePushing": "slidespin.contact.motion_cone",
    "motion_cone": "slidespin.contact.motion_cone",
    "stable_pushing": "slidespin.contact.motion_cone",
    "Outline": "slidespin.contact.outline",
    "body_outline": "slidespin.contact.outline",
    "BoussinesqPressure": "slidespin.contact.pressure",
    "HertzPressure": "slidespin.contact.pressure",
    "LinearPressure": "slidespin.contact.pressure",
    "UniformPressure": "slidespin.contact.pressure",
    "PressureMap": "slidespin.contact.pressure_map",
    "Annulus": "slidespin.contact.shapes",
    "Blade": "slidespin.contact.shapes",
    "Circle": "slidespin.contact.shapes",
    "Disk": "slidespin.contact.shapes",
    "Pads": "slidespin.contact.shapes",
    "Polygon": "slidespin.contact.shapes",
    "Rectangle": "slidespin.contact.shapes",
    "Onset": "slidespin.contact.statics",
    "can_stick": "slidespin.contact.statics",
    "Breakaway": "slidespin.contact.tipping",
    "breakaway": "slidespin.contact.tipping",
    "pressure_centre": "slidespin.contact.tipping",
    "critical_tilt": "slidespin.contact.statics",
    "load_factor": "slidespin.contact.statics",
    "onset": "slidespin.contact.statics",
    "Wrench": "slidespin.contact.wrench",
    "friction_wrench": "slidespin.contact.wrench",
    "StopResults": "slidespin.motion.batch",
    "simulate_bodies": "slidespin.motion.batch",
    "simulate_cases": "slidespin.motion.batch",
    "simulate_many": "slidespin.motion.batch",
    "simulate_loaded": "slidespin.motion.loaded",
    "LoadedTrajectory": "slidespin.motion.loaded_trajectory",
    "Load": "slidespin.motion.loads",
    "ENDINGS": "slidespin.motion.outcomes",
    "STATUSES": "slidespin.motion.outcomes",
    "ending_message": "slidespin.motion.outcomes",
    "status_message": "slidespin.motion.outcomes",
    "simulate_pushed": "slidespin.motion.pushed",
    "PushedTrajectory": "slidespin.motion.pushed_trajectory",
    "LinePusher": "slidespin.motion.pushers",
    "PointPusher": "slidespin.motion.pushers",
    "QuasiStaticPush": "slidespin.motion.quasi_static",
    "push_quasi_static": "slidespin.motion.quasi_static",
    "Trajectory": "slidespin.motion.trajectory",
    "simulate": "slidespin.motion.simulate",
    "Spring": "slidespin.motion.springs",
    "State": "slidespin.motion.state",
    "Case": "slidespin.studies.case",
    "load_case": "slidespin.studies.case",
    "SweepResult": "slidespin.studies.sweep",
    "sweep": "slidespin.studies.sweep",
    "read_sweep": "slidespin.studies.sweep_read",
    "SweepError": "slidespin.studies.sweep_spec",
    "animate": "slidespin.viz.animate",
    "frame_states": "slidespin.viz.animate",
    "plot_sweep": "slidespin.viz.sweep_plot",
    "plot_loaded_trajectory": "slidespin.viz.trajectory_plot",
    "plot_speed_law": "slidespin.viz.law_plot",
    "plot_trajectory": "slidespin.viz.trajectory_plot",
}

__all__ = [
    "__version__",
    # contact: patches, pressure, friction, the body, the wrench, statics, the limit surface
    "Ellipse",
    "Circle",
    "Disk",
    "Annulus",
    "Rectangle",
    "Polygon",
    "Pads",
    "Blade",
    "UniformPressure",
    "LinearPressure",
    "BoussinesqPressure",
    "HertzPressure",
    "PressureMap",
    "FrictionTensor",
    "PowerLaw",
    "Stribeck",
    "SpeedTable",
    "Body",
    "Incline",
    "Wrench",
    "friction_wrench",
    "can_stick",
    "Breakaway",
    "breakaway",
    "pressure_centre",
    "load_factor",
    "onset",
    "Onset",
    "critical_tilt",
    "limit_surface",
    "LimitSurface",
    "body_outline",
    "Outline",
    "motion_cone",
    "MotionCone",
    "stable_pushing",
    "StablePushing",
    # motion: state, loads, simulation to the stop, batches, statuses and endings
    "State",
    "Load",
    "Spring",
    "simulate",
    "Trajectory",
    "simulate_loaded",
    "LoadedTrajectory",
    "simulate_cases",
    "simulate_many",
    "simulate_bodies",
    "StopResults",
    "STATUSES",
    "ENDINGS",
    "status_message",
    "ending_message",
    # motion: pushers (MODEL §13)
    "PointPusher",
    "LinePusher",
    "simulate_pushed",
    "PushedTrajectory",
    "push_quasi_static",
    "QuasiStaticPush",
    # analysis: terminal analysis (paper eq. 14–16, Table 2) and fitting
    "terminal_ratio",
    "terminal_states",
    "TerminalState",
    "inertia_intervals",
    "paper_inertia_intervals",
    "InertiaIntervals",
    "inertia_for_ratio",
    "circle_terminal_ratio",
    "phase_portrait",
    "PhasePortrait",
    "fit",
    "FitResult",
    "read_runs",
    "compare_frames",
    "FitWarning",
    "IdentifiabilityWarning",
    # analysis: pushing data and their fit (MODEL §12-13)
    "read_push",
    "read_pushes",
    "PushRun",
    "fit_pushes",
    "PushFitResult",
    # analysis: derivatives of a motion's stop, and aiming (MODEL §15)
    "stop_sensitivities",
    "Sensitivities",
    "aim",
    "UnreachableTarget",
    # studies: case files and sweeps
    "Case",
    "load_case",
    "sweep",
    "SweepResult",
    "read_sweep",
    "SweepError",
    # viz: figures and animations (matplotlib and Pillow imported when drawing)
    "plot_trajectory",
    "plot_speed_law",
    "plot_loaded_trajectory",
    "plot_sweep",
    "animate",
    "frame_states",
    # engines: their own contact parameters fitted to the exact model (MODEL §16); the
    # couplings are the modules slidespin.mujoco and slidespin.drake
    "engine_parameters",
    "EngineParameters",
    # the paper's tables and figures (slidespin.paper.table1, ...)
    "paper",
]


def __getattr__(name: str):
    """A public name, imported from its defining module on first use (PEP 562)."""
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module 'slidespin' has no attribute {name!r}")
    module = importlib.import_module(home)
    value = module if home == f"slidespin.{name}" else getattr(module, name)
    globals()[name] = value  # later lookups are plain attribute reads
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
