"""``python -m juncture``: the same as the ``juncture`` command."""

import sys

from .cli import main

sys.exit(main())
