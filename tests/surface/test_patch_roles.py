"""Tests for juncture.surface.patch_roles: what a charted patch knows of its seams."""

import types

import numpy as np
import pytest

from juncture.surface.assemble import SurfaceMesh
from juncture.surface.patch_roles import TAPER, away_from, mark_slopes
from juncture.surface.patches import charts, taper


@pytest.mark.parametrize("wedge_deg", [90.0, 10.0])
def test_a_lift_may_rise_from_a_seam_by_a_quarter_of_the_wedge_of_air_there(wedge_deg):
    """patch_roles.mark_slopes: two flat squares meeting along the y axis with ``wedge_deg`` of
    air between them, the first taken for a circular body's: its boundary edges on the seam
    may be risen from at tan(wedge / 4) (90 deg: 0.414), never less than 1 / TAPER (10 deg:
    0.1, as before for every seam), its open edges at 1 / TAPER (and all of them at that
    off a circular body); taper() then gives a point a quarter of the
    lift's length from the seam that slope times four of its lift."""

    w = np.radians(wedge_deg)
    g = np.linspace(0.0, 1.0, 5)
    u, v = np.meshgrid(g, g, indexing="ij")
    flat = np.stack([u.ravel(), v.ravel(), 0.0 * u.ravel()], 1)              # z = 0, up
    other = np.stack([np.cos(w) * u.ravel(), v.ravel(), np.sin(w) * u.ravel()], 1)
    quads = [(i * 5 + j, (i + 1) * 5 + j, (i + 1) * 5 + j + 1, i * 5 + j + 1)
             for i in range(4) for j in range(4)]
    tri = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))])
    vertices = np.concatenate([flat, other[5:]])
    ids = np.concatenate([np.arange(5), np.arange(25, 45)])   # the u = 0 row is shared
    mesh = SurfaceMesh(vertices, np.concatenate([tri, ids[tri][:, ::-1]]),
                       np.zeros(64, int), np.repeat([0, 1], 32), ("c",), ("a", "b"))
    p = mesh.vertices[mesh.triangles]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert np.all(n[:32, 2] > 0)                            # the flat square faces up ...
    assert np.all(np.einsum("ij,j->i", n[32:], [np.sin(w), 0.0, -np.cos(w)]) > 0)  # ... into air
    (patch,) = charts(mesh, np.arange(32))
    patch.free = np.ones(len(patch.edges), bool)
    mark_slopes([patch], mesh)
    assert patch.slope is None                     # not on a circular body: as before
    patch.lift = types.SimpleNamespace(bodies=frozenset({0}))
    mark_slopes([patch], mesh)
    ends = mesh.vertices[patch.ids[patch.edges]]
    seam = np.all(ends[:, :, 0] == 0.0, axis=1)
    expect = max(np.tan(w / 4.0), 1.0 / TAPER)
    np.testing.assert_allclose(patch.slope[seam], expect, rtol=1e-12)
    np.testing.assert_allclose(patch.slope[~seam], 1.0 / TAPER)
    # a point of the chart off the middle of the seam, lift 0.1: its share of the lift
    mid = patch.uv[patch.edges[seam]].mean(axis=(0, 1))
    inward = patch.uv.mean(axis=0) - mid
    q = mid + 0.025 * inward / np.linalg.norm(inward)
    share = taper(patch, q[None], np.array([0.1]), 1.0 / TAPER)[0]
    assert share == pytest.approx(min(1.0, 0.25 * expect), abs=0.02)


def test_held_triangles_are_lifted_away_from_where_surfaces_crossed():
    """patch_roles.away_from: held triangles' new points within a crossing's radius of its
    centre stay where they are; beyond, they rise by at most their distance past it over
    TAPER, and in full where that allows; without crossings they are not lifted at all."""

    def up(points, corners, component, surface):          # the exact surface: z + 1
        return points + np.array([0.0, 0.0, 1.0])

    assert away_from(up, None) is None and away_from(None, np.ones((1, 4))) is None
    lift = away_from(up, np.array([[0.0, 0.0, 0.0, 2.0]]))
    x = np.array([0.0, 1.0, 2.0, 3.0, 2.0 + TAPER, 50.0])
    pts = np.stack([x, 0 * x, 0 * x], axis=1)
    out = lift(pts, None, 0, 0)
    np.testing.assert_array_equal(out[:, :2], pts[:, :2])
    np.testing.assert_allclose(out[:, 2], [0.0, 0.0, 0.0, 1.0 / TAPER, 1.0, 1.0],
                               atol=1e-15)


def _rows_patch(gap):
    """A flat grid patch of 6 x 6 points 1 apart whose third row is ``gap`` from the
    second (the rest of the rows moved along), as a Patch with its boundary loop."""
    x = np.concatenate([[0.0, 1.0, 1.0 + gap], 2.0 + gap + np.arange(3.0)])
    u, v = np.meshgrid(x, np.arange(6.0), indexing="ij")
    pts = np.stack([u.ravel(), v.ravel(), 0.0 * u.ravel()], 1)
    quads = [(i * 6 + j, (i + 1) * 6 + j, (i + 1) * 6 + j + 1, i * 6 + j + 1)
             for i in range(5) for j in range(5)]
    tri = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))])
    ring = [*range(0, 6), *range(11, 36, 6), *range(34, 29, -1), *range(24, 0, -6)]
    edges = np.stack([ring, np.roll(ring, -1)], 1)
    return types.SimpleNamespace(ids=np.arange(36), tri=tri, xyz=pts, edges=edges,
                                 kept=np.ones(36, bool), lift=None), pts


def test_rows_crowded_to_a_tenth_of_their_spacing_are_not_kept():
    """patch_roles.mark_rows: of a grid whose second and third rows are 0.05 apart (the
    others 1), the inner points of those two rows are left out of the triangulation (their
    shortest edge 0.05 of their longest); the boundary's stay, and so do points on an
    arbitrary section's corner line; at a gap of 0.2 every point stays."""
    from juncture.surface.creases import CORNER_LINE
    from juncture.surface.patch_roles import ROWS, mark_rows, thin_rows

    patch, pts = _rows_patch(0.05)
    inner = np.zeros(36, bool)
    inner[[7, 8, 9, 10, 13, 14, 15, 16]] = True          # rows 1 and 2, not on the loop
    assert ROWS == 0.1
    np.testing.assert_array_equal(thin_rows(pts, patch.tri) & inner,
                                  inner & (np.arange(36) // 6 > 0) & (np.arange(36) // 6 < 3))
    mark_rows([patch], None)
    assert not patch.kept[[7, 8, 9, 10, 13, 14, 15, 16]].any()
    assert patch.kept[patch.edges.ravel()].all() and patch.kept.sum() == 36 - 8
    lines = np.zeros(36, int)
    lines[[8, 14]] = CORNER_LINE
    patch, _ = _rows_patch(0.05)
    mark_rows([patch], None, lines)
    assert patch.kept[[8, 14]].all() and patch.kept.sum() == 36 - 6
    patch, _ = _rows_patch(0.2)
    mark_rows([patch], None)
    assert patch.kept.all()
