"""Issue 12 benchmark: one closed surface of the bundled transport, beside manifold3d.

- juncture: the completed networks assembled into one closed surface (seams by shared
  vertex ids) and re-triangulated for angles (``juncture.surface.remesh``), from an
  already completed geometry;
- manifold3d: the union of every component's closed surface (the deck's components whole,
  sampled by ``closed_networks``), the measured alternative, closed but with its seams where
  its own triangles happen to cross.

extra_info has each one's triangle count, enclosed volume and how far juncture's exact
intersection points lie from the result's vertices (0 for juncture by construction; the
nearest manifold3d vertex is an upper bound of its seam error at those points). Speed is
compared side by side, never asserted. ``make bench``.
"""

import warnings

import numpy as np
import pytest
from scipy.spatial import cKDTree

import juncture as jc
from juncture.analysis.closed import by_copy, closed_networks
from juncture.surface.assemble import assemble
from juncture.surface.quality import triangle_angles
from juncture.surface.remesh import remesh
from tests.support import EXAMPLE_DECK


@pytest.fixture(scope="module")
def transport():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        cfg = jc.read(EXAMPLE_DECK)
        return cfg, jc.complete(cfg)


def _exact_points(geo):
    pts = np.concatenate([np.asarray(p, float) for p in geo.intersections.values()])
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    return np.concatenate([pts, pts * [1.0, -1.0, 1.0]])


def _seam_error(vertices, geo):
    return float(cKDTree(vertices).query(_exact_points(geo))[0].max())


def test_juncture_closed_surface(benchmark, transport):
    _, geo = transport
    surface = benchmark(lambda: remesh(assemble(geo)))
    smallest = triangle_angles(surface.vertices, surface.triangles).min(axis=1)
    benchmark.extra_info.update(
        triangles=len(surface.triangles), volume=surface.volume(),
        share_20deg=float(np.mean(smallest >= 20.0)), seam_error=_seam_error(surface.vertices,
                                                                             geo))


def _component_meshes(cfg, n_chord, n_theta):
    """(points, triangles) of every component copy, closed: its networks' quads split, the
    points they share merged."""
    nets = closed_networks(cfg, n_chord=n_chord, n_theta=n_theta, union=False,
                           flow_through=False)
    groups = by_copy(cfg, nets)
    out = []
    for group in groups.values():
        pts, tris, off = [], [], 0
        for _, net in group:
            n, m = net.shape[:2]
            i, j = np.meshgrid(np.arange(n - 1), np.arange(m - 1), indexing="ij")
            a = (i * m + j).ravel()
            b, c, d = a + m, a + m + 1, a + 1
            tris.append(np.concatenate([np.stack([a, c, b], 1), np.stack([a, d, c], 1)]) + off)
            pts.append(net.reshape(-1, 3))
            off += n * m
        p, t = np.concatenate(pts), np.concatenate(tris)
        _, first, inv = np.unique(np.round(p / 1e-7).astype(np.int64), axis=0,
                                  return_index=True, return_inverse=True)
        t = inv.ravel()[t]
        t = t[(t[:, 0] != t[:, 1]) & (t[:, 1] != t[:, 2]) & (t[:, 0] != t[:, 2])]
        out.append((p[first], t))
    return out


@pytest.mark.parametrize("n_chord, n_theta", [(49, 48), (97, 96)])
def test_manifold3d_union(benchmark, transport, n_chord, n_theta):
    m3 = pytest.importorskip("manifold3d")
    cfg, geo = transport
    parts = _component_meshes(cfg, n_chord, n_theta)

    def union():
        solids = []
        for p, t in parts:
            mesh = m3.Mesh(vert_properties=p.astype(np.float32),
                           tri_verts=t.astype(np.uint32))
            solids.append(m3.Manifold(mesh))
        return m3.Manifold.batch_boolean(solids, m3.OpType.Add)
    result = benchmark(union)
    out = result.to_mesh()
    vertices = np.asarray(out.vert_properties, float)[:, :3]
    benchmark.extra_info.update(triangles=len(out.tri_verts), volume=result.volume(),
                                seam_error=_seam_error(vertices, geo))
