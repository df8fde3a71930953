"""Hypothesis profiles.

``make test`` (and CI) runs every property on the same examples each time (``fixed``:
derandomized), so a red run is about the change that made it and repeats on any machine.
``make test-all`` runs ``explore``: new examples on every run, the slow generated sweeps
included. A case ``explore`` finds is mended and pinned with ``@example`` in its test.
Choose one with ``HYPOTHESIS_PROFILE=fixed|explore``.
"""

import os

from hypothesis import settings

settings.register_profile("fixed", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "fixed"))
