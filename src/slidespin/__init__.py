"""slidespin: a flat rigid body sliding and spinning on a plane under anisotropic dry friction.

The friction force and moment are integrated exactly over a finite elliptic contact patch
for four pressure laws and a full 2×2 friction tensor, and the motion is integrated to its
finite stop. Source: "About the movement of a solid body on a plane surface in accordance
with elliptic contact area and anisotropic friction"; the model as built, with the paper's
errata, is documented in MODEL.md.
"""

from .body import Body, State
from .friction import FrictionTensor
from .geometry import Circle, Ellipse
from .pressure import BoussinesqPressure, HertzPressure, LinearPressure, UniformPressure
from .simulate import Trajectory, simulate
from .wrench import Wrench, friction_wrench

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
    "friction_wrench",
    "Wrench",
    "simulate",
    "Trajectory",
    "__version__",
]
