"""The command line: ``slidespin`` and one module per command.

:func:`slidespin.cli.main.main` is the console entry point (``slidespin = slidespin.cli.main:main``
in ``pyproject.toml``); :mod:`~slidespin.cli.main` builds the parser and runs ``demo``,
``simulate`` and the sweep commands, and each other command lives in its own module
(``reproduce``, ``bench``, ``fit``, ``limit_surface``, ``animate``), each with ``configure(parser)``
and ``run(args)``. May import every layer of slidespin; nothing in slidespin imports it. The
command modules import the numerical stack inside their ``run`` functions, so that
``slidespin --help`` does not load it.
"""
