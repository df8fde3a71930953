"""Issue 15: sweep throughput with one and two local workers, side by side.

One spec (the bundled transport, 24 cases: 12 wing heights x fillet none/cubic, each case as
in the 1000-case example: wave drag at M 1.2, 1.6 and 2.0 with 100 cuts x NTHETA 16, mass
properties; about 1 s a case) run with ``workers=1`` (in this process)
and ``workers=2`` (a spawned process pool), each from an empty journal, in the group ``"sweep
24 cases"``; the speed-up is ``mean(workers 1) / mean(workers 2)``. Nothing is asserted
(speed is measured, never a test). The peak memory of each worker is bounded by one case:
at most two cases per worker are in flight and each row is written to the journal as it
comes (``/usr/bin/time -v`` on the 1000-case example: see the README).

Measured on the development machine (2 shared cores), best / mean of 3: one worker 20.2 /
20.6 s, two workers 11.2 / 11.3 s: 1.83x, the two workers' start (spawned processes that
import juncture) included. With the lighter cases of one Mach number, 60 cuts and NTHETA 8
(0.23 s each) the start weighs more: 1.63x.

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
mach = [1.2, 1.6, 2.0]
n_x = 100
n_theta = 16
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
