"""Bodies on round feet for the pushing tests (pads with disks, MODEL §13), with the discs
they are made of (x, y, radius in the patch frame; radius 0: a plate's sharp corner), for the
tests' own geometry."""

from __future__ import annotations

import slidespin as ss

#: three round feet: a hull of three arcs and three tangent edges, smooth everywhere
FEET_DISCS = [(0.1, 0.0, 0.02), (-0.05, 0.0866, 0.02), (-0.05, -0.0866, 0.02)]
FEET = ss.Body(
    ss.Pads(*(ss.Disk(r, centre=(x, y)) for x, y, r in FEET_DISCS)),
    ss.UniformPressure(),
    mass=1.0,
)
#: a plate and a round foot: the plate's corners (radius 0) and the foot's arc on the hull
PLATE_CORNERS = [(-0.1, -0.03), (0.0, -0.03), (0.0, 0.03), (-0.1, 0.03)]
MIXED_DISCS = [(x, y, 0.0) for x, y in PLATE_CORNERS] + [(0.07, 0.0, 0.03)]
MIXED = ss.Body(
    ss.Pads(ss.Rectangle(0.1, 0.06, centre=(-0.05, 0.0)), ss.Disk(0.03, centre=(0.07, 0.0))),
    ss.UniformPressure(),
    mass=1.0,
)
