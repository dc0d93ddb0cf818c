"""Visualisation: figures and animations of trajectories, sweeps, fits and limit surfaces.

matplotlib and Pillow are imported inside the functions that draw (``ax=`` in, ``Axes`` or a
``Figure`` out), so that importing slidespin does not import them.

May import: :mod:`slidespin.studies` and every layer below it.
"""
