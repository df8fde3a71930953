"""Issue 14: how fast the command starts, beside the import of numpy it cannot do without.

Three whole processes, each timed by pytest-benchmark in the same run (so the ratios hold on
whatever machine runs them): ``python -c "import numpy"`` (the floor), ``juncture
--version`` (target: at most 2x the floor) and ``juncture complete`` on the bundled transport
without figures (target: at most 4x). The ratios go into extra_info; nothing is asserted.

Run with ``make bench`` (``pytest benchmarks --benchmark-only``).
"""

import subprocess
import sys

import pytest

from tests.support import EXAMPLE_DECK

_CASES = {
    "import numpy": [sys.executable, "-c", "import numpy"],
    "juncture --version": [sys.executable, "-m", "juncture", "--version"],
    "juncture complete (no figures)": [sys.executable, "-m", "juncture", "complete",
                                       str(EXAMPLE_DECK), "-o", "{out}", "-q"],
}


def _run(argv):
    subprocess.run(argv, check=True, capture_output=True)


@pytest.mark.parametrize("case", list(_CASES))
def test_startup(benchmark, tmp_path, case):
    argv = [a.format(out=tmp_path / "out") for a in _CASES[case]]
    benchmark.pedantic(_run, args=(argv,), rounds=7, warmup_rounds=1)
    benchmark.extra_info["command"] = case
