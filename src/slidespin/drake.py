"""slidespin's exact patch friction inside Drake (MODEL §16): see :mod:`slidespin.engines.drake`."""

from slidespin.engines.drake import (
    ExampleDiagram,
    PatchFriction,
    add_patch_friction,
    example_diagram,
    set_planar_state,
)

__all__ = [
    "ExampleDiagram",
    "PatchFriction",
    "add_patch_friction",
    "example_diagram",
    "set_planar_state",
]
