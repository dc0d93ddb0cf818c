"""slidespin: a flat rigid body sliding and spinning on a plane under anisotropic dry friction.

The friction force and moment are integrated exactly over a finite contact patch (an ellipse
under four pressure laws, or any footprint: polygons, rectangles, disks, rings, pads, a blade,
a user pressure map) for a full 2×2 friction tensor, and the motion is integrated to its finite
stop, with loads, slopes and exact stick–slip. Source: "About the movement of a solid body on a
plane surface in accordance with elliptic contact area and anisotropic friction"; the model as
built, with the paper's errata, is documented in docs/model.md.

Every public name is importable from here (``import slidespin as ss``). The sub-packages are
the layers of the code, each importing only those below it (docs/development.md, "Where
things live"): :mod:`slidespin.contact` < :mod:`slidespin.motion` < :mod:`slidespin.analysis`
< :mod:`slidespin.studies` < :mod:`slidespin.viz` < :mod:`slidespin.paper` <
:mod:`slidespin.cli`.
"""

from slidespin import paper
from slidespin._version import __version__
from slidespin.analysis.fit import FitWarning, IdentifiabilityWarning, compare_frames, fit
from slidespin.analysis.fit_data import read_runs
from slidespin.analysis.fit_result import FitResult
from slidespin.analysis.intervals import (
    InertiaIntervals,
    circle_terminal_ratio,
    inertia_for_ratio,
    inertia_intervals,
    paper_inertia_intervals,
)
from slidespin.analysis.phase_portrait import PhasePortrait, phase_portrait
from slidespin.analysis.terminal import TerminalState, terminal_ratio, terminal_states
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.limit_surface import LimitSurface, limit_surface
from slidespin.contact.pressure import (
    BoussinesqPressure,
    HertzPressure,
    LinearPressure,
    UniformPressure,
)
from slidespin.contact.pressure_map import PressureMap
from slidespin.contact.shapes import Annulus, Blade, Circle, Disk, Pads, Polygon, Rectangle
from slidespin.contact.statics import Onset, can_stick, critical_tilt, load_factor, onset
from slidespin.contact.wrench import Wrench, friction_wrench
from slidespin.motion.batch import StopResults, simulate_bodies, simulate_cases, simulate_many
from slidespin.motion.loaded import simulate_loaded
from slidespin.motion.loaded_trajectory import LoadedTrajectory
from slidespin.motion.loads import Load
from slidespin.motion.outcomes import ENDINGS, STATUSES, ending_message, status_message
from slidespin.motion.simulate import Trajectory, simulate
from slidespin.motion.state import State
from slidespin.studies.case import Case, load_case
from slidespin.studies.sweep import SweepResult, sweep
from slidespin.studies.sweep_read import read_sweep
from slidespin.studies.sweep_spec import SweepError
from slidespin.viz.animate import animate, frame_states
from slidespin.viz.sweep_plot import plot_sweep
from slidespin.viz.trajectory_plot import plot_loaded_trajectory, plot_trajectory

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
    "Body",
    "Incline",
    "Wrench",
    "friction_wrench",
    "can_stick",
    "load_factor",
    "onset",
    "Onset",
    "critical_tilt",
    "limit_surface",
    "LimitSurface",
    # motion: state, loads, simulation to the stop, batches, statuses and endings
    "State",
    "Load",
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
    # studies: case files and sweeps
    "Case",
    "load_case",
    "sweep",
    "SweepResult",
    "read_sweep",
    "SweepError",
    # viz: figures and animations (matplotlib and Pillow imported when drawing)
    "plot_trajectory",
    "plot_loaded_trajectory",
    "plot_sweep",
    "animate",
    "frame_states",
    # the paper's tables and figures (slidespin.paper.table1, ...)
    "paper",
]
