"""Benchmark geometry: a 20-section x 30-station cranked wing on a 60-station cambered body."""

import numpy as np

from juncture.model import CircularBody, Configuration, WingLike


def benchmark_configuration(n_sections=20, n_stations=30, n_body=60):
    """The issue-3 benchmark case (units: feet, a 300 ft transport-like layout)."""
    x = np.linspace(0.0, 300.0, n_body)
    xi = x / 300.0
    r = 6.0 * np.clip(np.minimum(xi / 0.2, (1 - xi) / 0.27), 0.0, 1.0) ** 0.7
    r[0] = 0.0
    body = CircularBody("body", x, r, 0.8 * np.sin(np.pi * xi) - 0.4, segments=(n_body,))
    y = np.linspace(3.0, 62.0, n_sections)
    x_le = np.where(y < 30, 95 + (y - 3) * 2.9, 95 + 27 * 2.9 + (y - 30) * 1.3)
    chord = np.interp(y, [3, 30, 62], [170.0, 80.0, 22.0])
    le = np.stack([x_le, y, -1.5 + 0.02 * (y - 3)], axis=1)
    xc = 100 * (1 - np.cos(np.linspace(0, np.pi, n_stations))) / 2
    f = xc / 100
    half = 1.8 * np.sqrt(np.maximum(4 * f * (1 - f), 0.0))
    up = np.tile(half, (n_sections, 1))
    cam = 0.006 * chord[:, None] * 4 * f * (1 - f)
    wing = WingLike("wing", "wing", le, chord, xc, up, 0.9 * up, cam)
    return Configuration({"wing": wing, "body": body}, title="benchmark wing-body",
                         reference_area=9000.0)
