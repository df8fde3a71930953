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


@pytest.mark.parametrize("wedge_deg", [10.0, 90.0, 350.0])
def test_a_lift_out_of_a_wing_rises_slowly_from_a_narrow_valley(wedge_deg):
    """patch_roles.mark_slopes: the two squares of the test above, the first a lifted
    surface off a circular body (a wing's). In a valley of air narrower than
    4 atan(1 / TAPER) (10 deg) its seam edges get ``patch.valley`` tan(wedge / 4) (inf on
    its open edges): taper() gives a point a quarter of the lift's length from the seam a
    share of its lift of that slope times four where the lift is out of its solid
    (``outward``), 1 / TAPER times four where it is not. A wide valley (90 deg) or a ridge
    (10 deg of solid) gets none, nor does a circular body's patch (which keeps its own
    slopes, at least 1 / TAPER)."""
    w = np.radians(wedge_deg)
    g = np.linspace(0.0, 1.0, 5)
    u, v = np.meshgrid(g, g, indexing="ij")
    flat = np.stack([u.ravel(), v.ravel(), 0.0 * u.ravel()], 1)
    other = np.stack([np.cos(w) * u.ravel(), v.ravel(), np.sin(w) * u.ravel()], 1)
    quads = [(i * 5 + j, (i + 1) * 5 + j, (i + 1) * 5 + j + 1, i * 5 + j + 1)
             for i in range(4) for j in range(4)]
    tri = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))])
    vertices = np.concatenate([flat, other[5:]])
    ids = np.concatenate([np.arange(5), np.arange(25, 45)])
    mesh = SurfaceMesh(vertices, np.concatenate([tri, ids[tri][:, ::-1]]),
                       np.zeros(64, int), np.repeat([0, 1], 32), ("c",), ("a", "b"))
    (patch,) = charts(mesh, np.arange(32))
    patch.free = np.ones(len(patch.edges), bool)
    patch.lift = types.SimpleNamespace(bodies=frozenset())
    mark_slopes([patch], mesh)
    assert patch.slope is None
    if wedge_deg > np.degrees(4.0 * np.arctan(1.0 / TAPER)):
        assert patch.valley is None
        return
    ends = mesh.vertices[patch.ids[patch.edges]]
    seam = np.all(ends[:, :, 0] == 0.0, axis=1)
    np.testing.assert_allclose(patch.valley[seam], np.tan(w / 4.0), rtol=1e-9)
    assert np.all(np.isinf(patch.valley[~seam]))
    mid = patch.uv[patch.edges[seam]].mean(axis=(0, 1))
    inward = patch.uv.mean(axis=0) - mid
    q = mid + 0.025 * inward / np.linalg.norm(inward)
    share = taper(patch, q[None].repeat(2, 0), np.array([0.1, 0.1]), 1.0 / TAPER,
                  outward=np.array([True, False]))
    assert share[0] < 0.5 * share[1]
    assert share[0] == pytest.approx(0.25 * np.tan(w / 4.0), abs=0.005)
    assert share[1] == pytest.approx(0.25 / TAPER, abs=0.005)
    patch.valley = patch.near = None
    patch.lift = types.SimpleNamespace(bodies=frozenset({0}))
    mark_slopes([patch], mesh)
    assert patch.valley is None


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
