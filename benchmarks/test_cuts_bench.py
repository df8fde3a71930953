"""Benchmark: Mach-plane cuts, 100 offsets x 16 roll angles through ~20,000 triangles.

Run with ``make bench`` (``pytest benchmarks --benchmark-only``). Target: well under 1 s.
"""

import numpy as np
import pytest

from juncture.analysis.cuts import mach_plane_areas, mach_plane_extents, triangulate


def _revolution(xs, rs, n_phi):
    phi = np.linspace(0.0, 2 * np.pi, n_phi + 1)
    xx = np.broadcast_to(xs[:, None], (xs.size, n_phi + 1))
    return np.stack([xx, rs[:, None] * np.cos(phi), rs[:, None] * np.sin(phi)], axis=-1)


def _configuration():
    """A fuselage and two flattened-ellipsoid 'wings', all closed and outward."""
    xs = 0.5 * 60.0 * (1 - np.cos(np.linspace(0.0, np.pi, 81)))
    fuselage = _revolution(xs, 2.5 * (4 * xs / 60 * (1 - xs / 60)) ** 0.75, 80)
    t = np.linspace(0.0, np.pi, 41)
    unit = _revolution(-np.cos(t), np.sin(t), 44)
    wing = unit @ np.diag([8.0, 12.0, 0.4]).T + np.array([34.0, 13.0, 0.0])
    image = wing * np.array([1.0, -1.0, 1.0])
    return [fuselage, wing, image[::-1]]


def test_mach_plane_cuts_100_x_16(benchmark):
    nets = _configuration()
    n_tri = triangulate(nets).shape[0]
    assert 18_000 < n_tri < 22_000
    thetas = 2 * np.pi * np.arange(16) / 16
    ext = mach_plane_extents(nets, 1.6, thetas)
    offsets = np.linspace(ext[:, 0], ext[:, 1], 100).T
    s = benchmark(mach_plane_areas, nets, 1.6, thetas, offsets)
    assert s.shape == (16, 100)
    assert np.all(s >= -1e-9) and s.max() > 0.0
    # left-right symmetric configuration: theta and pi - theta see mirror-image cuts
    k = (8 - np.arange(16)) % 16
    assert s[k] == pytest.approx(s, rel=1e-9, abs=1e-9 * s.max())
    stats = getattr(benchmark, "stats", None)
    if stats is not None and stats.stats.rounds:
        assert stats.stats.min < 1.0
