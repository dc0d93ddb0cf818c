"""The command line: ``slidespin`` and one module per command (``bench`` included).

:func:`main` is the console entry point. May import every layer of slidespin; nothing in
slidespin imports it.
"""

from slidespin.cli.main import main

__all__ = ["main"]
