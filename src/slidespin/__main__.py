"""``python -m slidespin`` is the ``slidespin`` command."""

import sys

from slidespin.cli.main import main

sys.exit(main())
