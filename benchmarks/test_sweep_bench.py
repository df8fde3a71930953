"""Issue 15: sweep throughput with one and two local workers, side by side.

One spec (the bundled transport, 24 cases: 12 wing heights x fillet none/cubic, wave drag at
M 1.6 with 60 cuts x 8 roll angles, mass properties) run with ``workers=1`` (in this process)
and ``workers=2`` (a spawned process pool), each from an empty journal, in the group ``"sweep
24 cases"``; the speed-up is ``mean(workers 1) / mean(workers 2)``. Nothing is asserted
(speed is measured, never a test). The peak memory of each worker is bounded by one case:
at most two cases per worker are in flight and each row is written to the journal as it
comes (``/usr/bin/time -v`` on the 1000-case example: see the README).

Run with ``make bench`` (``pytest benchmarks --benchmark-only``).
"""

import textwrap

import pytest

from juncture.study import sweep
from tests.support import EXAMPLE_DECK

pytest.importorskip("pandas", reason="the sweep needs the sweep extra")

SPEC = """
[complete]
keep_area = true
[analysis]
mach = [1.6]
n_x = 60
n_theta = 8
[parameters.wing_z]
component = ["wing", "pod 1", "pod 2", "fin 1", "fin 2"]
field = "z"
mode = "offset"
range = [-1.0, 1.0, 12]
[parameters.fillet]
option = "fillet"
values = ["none", "cubic"]
"""


@pytest.fixture(scope="module")
def spec(tmp_path_factory):
    path = tmp_path_factory.mktemp("sweep") / "spec.toml"
    path.write_text(f'base = "{EXAMPLE_DECK}"\n' + textwrap.dedent(SPEC))
    return path


@pytest.mark.parametrize("workers", [1, 2])
@pytest.mark.benchmark(group="sweep 24 cases")
def test_sweep_throughput(benchmark, spec, workers):
    frame = benchmark.pedantic(sweep, args=(spec,), kwargs={"workers": workers}, rounds=3,
                               iterations=1)
    benchmark.extra_info["cases"] = len(frame)
    assert (frame["status"] == "ok").all() and len(frame) == 24
