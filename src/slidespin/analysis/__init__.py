"""Analysis: what is computed about motions rather than a single motion.

Terminal analysis (the stop direction and β* of paper eq. 14–16, Table 2's inertia intervals,
phase portraits) and identification (fitting friction parameters to tracked motion).

May import: :mod:`slidespin.motion`, :mod:`slidespin.contact` and the private root helpers.
"""
