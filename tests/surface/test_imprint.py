"""A standing component's footprint cut into its host: closed, oriented, exact volume."""

import numpy as np
import pytest

from juncture.surface.assemble import _merge, boundary_loops
from juncture.surface.check import check_mesh
from juncture.surface.imprint import imprint


def _grid_face(origin, du, dv, n):
    """An n x n grid on origin + s du + t dv, triangles oriented along du x dv."""
    s = np.linspace(0.0, 1.0, n)
    pts = origin + s[:, None, None] * du + s[None, :, None] * dv
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    a, b, c, d = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
    tri = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                          np.stack([a, c, d], -1).reshape(-1, 3)])
    return pts.reshape(-1, 3), tri


def _box(n=6, size=4.0, depth=1.0):
    """The closed box [0, size]^2 x [-depth, 0], outward, every face an n x n grid."""
    o, x, y, z = np.zeros(3), np.array([size, 0, 0.]), np.array([0, size, 0.]), \
        np.array([0, 0, depth])
    lo = o - z
    faces = [(o, x, y), (lo, y, x), (lo, x, z), (lo + y, z, x), (lo, z, y), (lo + x, y, z)]
    pts, tri, off = [], [], 0
    for origin, du, dv in faces:
        p, t = _grid_face(origin, du, dv, n)
        pts.append(p)
        tri.append(t + off)
        off += len(p)
    return np.concatenate(pts), np.concatenate(tri)


def _prism(centre, radius, height, k, phase):
    """A k-sided prism standing on z = 0, open at the bottom: (points, triangles, base ids)."""
    a = phase + 2 * np.pi * np.arange(k) / k
    ring = np.stack([centre[0] + radius * np.cos(a), centre[1] + radius * np.sin(a),
                     np.zeros(k)], axis=1)
    top = ring + [0.0, 0.0, height]
    apex = np.array([[centre[0], centre[1], height]])
    pts = np.concatenate([ring, top, apex])
    i = np.arange(k)
    j = (i + 1) % k
    sides = np.concatenate([np.stack([i, j, k + j], 1), np.stack([i, k + j, k + i], 1)])
    cap = np.stack([k + i, k + j, np.full(k, 2 * k)], 1)
    return pts, np.concatenate([sides, cap]), ring


@pytest.mark.parametrize("k, radius, phase", [(12, 0.7, 0.1), (7, 0.23, 0.4), (40, 1.3, 0.0)])
def test_a_prism_imprinted_on_a_box_closes_with_the_exact_volume(k, radius, phase):
    bp, bt = _box()
    pp, pt, ring = _prism((1.93, 2.11), radius, 1.0, k, phase)
    vertices, inverse = _merge(np.concatenate([bp, pp]))
    triangles = inverse[np.concatenate([bt, pt + len(bp)])]
    host = np.r_[np.ones(len(bt), bool), np.zeros(len(pt), bool)]
    loop = inverse[len(bp) + np.arange(k)]
    assert len(boundary_loops(triangles)) == 1        # the prism stands on the box, uncut
    removed, new = imprint(vertices, triangles, host, loop)
    keep = np.ones(len(triangles), bool)
    keep[removed] = False
    out = np.concatenate([triangles[keep], new])
    report = check_mesh(vertices, out)
    assert report.ok, report.failures()
    assert report.euler == (2,)
    # Box plus prism: the polygon's area (shoelace) times the height.
    x, y = ring[:, 0], ring[:, 1]
    base = 0.5 * abs(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))
    assert report.volume == pytest.approx(16.0 + base * 1.0, rel=1e-12)
    # Every edge of the footprint is an edge of the host's new triangles.
    e = {tuple(sorted(p)) for t in new for p in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))}
    assert all(tuple(sorted((loop[i], loop[(i + 1) % k]))) in e for i in range(k))
    # No point is created: the new triangles use the box's and the prism's own vertices.
    assert set(np.unique(new)) <= set(np.unique(triangles))


def test_a_loop_that_folds_over_in_projection_is_refused():
    bp, bt = _box()
    vertices, inverse = _merge(bp)
    triangles = inverse[bt]
    bow = np.array([[1.0, 1.0, 0.0], [2.0, 2.0, 0.0], [2.0, 1.0, 0.0], [1.0, 2.0, 0.0]])
    vertices = np.concatenate([vertices, bow])
    loop = len(vertices) - 4 + np.arange(4)
    assert imprint(vertices, triangles, np.ones(len(triangles), bool), loop) is None
