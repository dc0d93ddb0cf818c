"""Engines: slidespin's exact patch friction inside rigid-body engines (MODEL §16).

An engine (MuJoCo, Drake) integrates the body in 3-D and resolves the normal contact;
slidespin supplies the tangential friction of the flat contact. Here live the
engine-independent step (:mod:`slidespin.engines._coupling`), the adapters
(:mod:`slidespin.engines.mujoco`, :mod:`slidespin.engines.drake`; users import them as
``slidespin.mujoco`` and ``slidespin.drake``), and the engines' own contact parameters fitted
to the exact model (:mod:`slidespin.engines.parameters`). The engines are optional extras
(``pip install "slidespin[mujoco]"``, ``[drake]``, ``[pybullet]``): each adapter imports its
engine and says how to install it when it is missing.

May import: :mod:`slidespin.studies` and the layers below it, and the private root helpers.
"""
