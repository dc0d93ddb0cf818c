"""slidespin: a flat rigid body sliding and spinning on a plane under anisotropic dry friction.

The friction force and moment are integrated exactly over a finite elliptic contact patch
for four pressure laws and a full 2×2 friction tensor, and the motion is integrated to its
finite stop; beyond the paper, the patch may be any footprint (polygons, rectangles, disks,
rings, several pads) under uniform or linear pressure (MODEL §10). Source: "About the movement of a solid body on a plane surface in accordance
with elliptic contact area and anisotropic friction"; the model as built, with the paper's
errata, is documented in docs/model.md.
"""

from slidespin.analysis.terminal import (
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
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Circle, Ellipse
from slidespin.contact.footprint_wrench import footprint_wrench
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
from slidespin.contact.shapes import Annulus, Blade, Disk, Pads, Polygon, Rectangle
from slidespin.contact.statics import can_stick, critical_tilt, load_factor, onset
from slidespin.contact.wrench import Wrench, friction_wrench
from slidespin.motion.batch import simulate_bodies, simulate_many
from slidespin.motion.loaded import LoadedTrajectory, simulate_loaded
from slidespin.motion.loads import Load
from slidespin.motion.simulate import Trajectory, simulate
from slidespin.motion.state import State
from slidespin.studies.case import Case, load_case

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
