"""Exact topological counts of a surface mesh, against constructed defects."""

import numpy as np
import pytest

from juncture.geometry import Geometry
from juncture.surface.assemble import SurfaceMesh, assemble
from juncture.surface.quality import summarize, triangle_angles
from tests.surface.test_assemble import _prism


def test_angles_of_known_triangles():
    v = np.array([[0.0, 0, 0], [1, 0, 0], [0.5, np.sqrt(3) / 2, 0], [0, 1, 0]])
    ang = triangle_angles(v, np.array([[0, 1, 2], [0, 1, 3]]))
    np.testing.assert_allclose(ang[0], 60.0, atol=1e-12)
    np.testing.assert_allclose(sorted(ang[1]), [45.0, 45.0, 90.0], atol=1e-12)


def test_a_closed_prism_and_its_defects():
    mesh = assemble(Geometry({"pod": _prism()}))
    s = summarize(mesh)
    assert s.closed and s.open_edges == s.nonmanifold_edges == s.misoriented_edges == 0
    assert s.volume > 0 and 0 < s.min_angle <= 60.0

    def variant(triangles):
        return summarize(SurfaceMesh(mesh.vertices, triangles, mesh.component[:len(triangles)],
                                     mesh.surface[:len(triangles)], mesh.components,
                                     mesh.surfaces))

    assert variant(mesh.triangles[1:]).open_edges == 3
    flipped = mesh.triangles.copy()
    flipped[0] = flipped[0, ::-1]
    assert variant(flipped).misoriented_edges == 3
    doubled = np.concatenate([mesh.triangles, mesh.triangles[:1]])
    s = summarize(SurfaceMesh(mesh.vertices, doubled, np.r_[mesh.component, 0],
                              np.r_[mesh.surface, 0], mesh.components, mesh.surfaces))
    assert s.nonmanifold_edges == 3 and not s.closed
    inward = variant(mesh.triangles[:, ::-1])
    assert inward.volume == pytest.approx(-mesh.volume(), rel=1e-12)
    assert not inward.closed
