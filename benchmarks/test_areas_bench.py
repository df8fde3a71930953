"""Benchmark: Mach-plane area distributions of the bundled transport, 100 cuts x 16 roll angles.

Closing and resampling the model (closed_networks: ~110,000 triangles, wing roots trimmed at
the bodies) plus the cuts. Run with ``make bench``; the time is measured, not asserted.
"""

import numpy as np
import pytest

import juncture as jc
from juncture.analysis.areas import normal_area_distribution
from juncture.analysis.machplanes import mach_plane_area_distribution
from support import EXAMPLE_DECK


def test_mach_plane_areas_transport_100_x_16(benchmark):
    cfg = jc.read(EXAMPLE_DECK)
    s = benchmark(mach_plane_area_distribution, cfg, 2.0, 100, 16)
    assert s["area"].shape == (16, 100) and s["x"].shape == (16, 100)
    assert s["area"].max() > 100.0
    k = (8 - np.arange(16)) % 16
    assert s["area"][k] == pytest.approx(s["area"], abs=1e-5 * s["area"].max())


def test_normal_areas_transport_101(benchmark):
    cfg = jc.read(EXAMPLE_DECK)
    a = benchmark(normal_area_distribution, cfg, None, None, 101)
    assert a["total"].shape == (101,)
