"""slidespin: a flat rigid body sliding and spinning on a plane under anisotropic dry friction.

The friction force and moment are integrated exactly over a finite elliptic contact patch
for four pressure laws and a full 2×2 friction tensor, and the motion is integrated to its
finite stop; beyond the paper, the patch may be any footprint (polygons, rectangles, disks,
rings, several pads) under uniform or linear pressure (MODEL §10). Source: "About the movement of a solid body on a plane surface in accordance
with elliptic contact area and anisotropic friction"; the model as built, with the paper's
errata, is documented in docs/model.md.
"""

from .batch import simulate_bodies, simulate_many
from .body import Body, State
from .case import Case, load_case
from .footprint import Annulus, Blade, Disk, Pads, Polygon, Rectangle
from .footprint_pressure import PressureMap
from .footprint_wrench import footprint_wrench
from .friction import FrictionTensor
from .geometry import Circle, Ellipse
from .limit_surface import LimitSurface, limit_surface
from .loaded import LoadedTrajectory, simulate_loaded
from .loads import Incline, Load
from .pressure import BoussinesqPressure, HertzPressure, LinearPressure, UniformPressure
from .simulate import Trajectory, simulate
from .statics import can_stick, critical_tilt, load_factor, onset
from .terminal import (
    InertiaIntervals,
    PhasePortrait,
    TerminalState,
    circle_terminal_ratio,
    inertia_for_ratio,
    inertia_intervals,
    paper_inertia_intervals,
    phase_portrait,
    terminal_ratio,
    terminal_states,
)
from .wrench import Wrench, friction_wrench

#: the package version (``slidespin --version`` prints it)
__version__ = "0.1.0"

__all__ = [
    "Body",
    "State",
    "FrictionTensor",
    "Ellipse",
    "Circle",
    "UniformPressure",
    "LinearPressure",
    "BoussinesqPressure",
    "HertzPressure",
    "Polygon",
    "Blade",
    "Case",
    "load_case",
    "simulate_bodies",
    "simulate_many",
    "Rectangle",
    "Disk",
    "Annulus",
    "Pads",
    "PressureMap",
    "footprint_wrench",
    "friction_wrench",
    "Wrench",
    "simulate",
    "Trajectory",
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
    "__version__",
    "Load",
    "Incline",
    "simulate_loaded",
    "LoadedTrajectory",
    "can_stick",
    "load_factor",
    "onset",
    "critical_tilt",
    "limit_surface",
    "LimitSurface",
]
