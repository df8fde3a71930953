"""Throughput of the wing-segment closed forms: one segment, and batches of 1e5 and 1e6.

Run with ``make bench`` (``pytest benchmarks --benchmark-only``). The batch benchmarks
report segments per second in ``extra_info``; the target is >= 1e6 segments per second.
"""

from __future__ import annotations

import numpy as np
import pytest

from juncture.massprops import Naca4, WingSegment, wing_segments_mass_properties


def _batch(n, seed=0):
    rng = np.random.default_rng(seed)
    cr = rng.uniform(0.5, 2.0, n)
    return dict(semispan=rng.uniform(1.0, 10.0, n), chord_root=cr,
                chord_tip=cr * rng.uniform(0.2, 1.0, n), thickness_root=rng.uniform(0.08, 0.2, n),
                thickness_tip=rng.uniform(0.06, 0.15, n), sweep=rng.uniform(-0.3, 0.8, n),
                dihedral=rng.uniform(-0.1, 0.2, n), side="right", airfoil=Naca4().v,
                root_quarter_chord=rng.normal(size=(n, 3)), density=rng.uniform(10, 100, n))


def test_single_segment(benchmark):
    seg = WingSegment(4.0, 1.0, 0.5, 0.12, 0.10, 0.17, 0.05, "both",
                      root_quarter_chord=(2.0, 0.0, -0.5))
    props = benchmark(seg.mass_properties, mass=3.0)
    assert props.mass == 3.0


@pytest.mark.parametrize("n", [100_000, 1_000_000])
def test_batch(benchmark, n):
    kwargs = _batch(n)
    out = benchmark(wing_segments_mass_properties, **kwargs)
    assert out.inertia.shape == (n, 3, 3)
    rate = n / benchmark.stats.stats.min
    benchmark.extra_info["segments_per_second"] = rate
    print(f"\n{n} segments: {rate:.3g} segments/s (best of {benchmark.stats.stats.rounds})")
