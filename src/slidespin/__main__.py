"""``python -m slidespin`` is the ``slidespin`` command."""

import sys

from .cli import main

sys.exit(main())
