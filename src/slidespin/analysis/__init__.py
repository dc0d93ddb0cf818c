"""Analysis: what is computed about motions rather than a single motion.

Terminal analysis (the stop direction and β* of paper eq. 14–16, Table 2's inertia intervals,
phase portraits) and identification (fitting friction parameters to tracked motion, and to
tracked pushes: the MIT push dataset's layout read by :mod:`slidespin.analysis.push_data`,
fitted by :mod:`slidespin.analysis.fit_push`).

May import: :mod:`slidespin.motion`, :mod:`slidespin.contact` and the private root helpers.
"""
