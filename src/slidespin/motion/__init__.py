"""Motion: the body's state in time, what acts on it, and its integration to the stop.

The kinematic state, loads (forces and torques given in time), the compiled integrator (the
integration core in the regularised time of MODEL §5, and the stop classification of MODEL
§9), ``simulate`` (free and loaded motion with exact stick–slip, one entry), the batch engine,
the one vocabulary of statuses and endings, and pushers (MODEL §13): point and line pushers
with a prescribed motion, the dynamics of a pushed body and its quasi-static limit.

May import: :mod:`slidespin.contact` and the private root helpers.
"""
