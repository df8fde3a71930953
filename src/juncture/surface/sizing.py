"""A graded size field for the re-triangulation: finer at the intersection lines, and no
faster growth than asked for.

CFD meshers ask a surface mesh for triangles that are small where the flow changes fast
(the junctions between components) and that grow smoothly away from there. Refinement for
angles and for the distance from the surface alone (:mod:`juncture.surface.remesh`) leaves
small triangles wherever a seam's pieces are short and large ones right beside them (a ratio
of up to 1 / sin(min angle) per triangle). With a size field, a triangle whose longest
edge exceeds :data:`SLACK` times the field at its centre takes a point there, in the rounds
that refine:

    h(p) = min(cap, min over the sources q of h_q + (growth - 1) |p - q|)

The sources are the vertices on the assembled surface's seams and boundaries, each with
its shortest boundary edge (so triangles grade away from the finest pieces the surface
already has), and, with ``seam_size``, the vertices on the lines where components meet with
that size (finer near intersections). ``cap`` is the largest edge asked for, if any. The
minimum is taken over each point's :data:`NEAREST` nearest sources (a k-d tree): a source
further away than those only decides where it is far smaller, which the growth from the
nearer ones already bounds to within a few per cent.
"""

from __future__ import annotations

import numpy as np

__all__ = ["GROWTH", "NEAREST", "SLACK", "SizeField", "size_field"]

#: The growth rate when only ``seam_size`` is given.
GROWTH = 1.25
#: Sources taken for each point.
NEAREST = 16
#: A triangle whose longest edge exceeds this many times the field at its centre is split.
SLACK = 1.5


class SizeField:
    """``field(points)`` (k,): the target edge length at 3-D points (see the module)."""

    def __init__(self, points, sizes, growth, cap=None):
        from scipy.spatial import cKDTree

        self.points, self.sizes = np.asarray(points, float), np.asarray(sizes, float)
        self.growth, self.cap = float(growth), cap
        self.tree = cKDTree(self.points)

    def __call__(self, query):
        query = np.asarray(query, float)
        k = min(NEAREST, len(self.points))
        dist, at = self.tree.query(query, k=k)
        dist, at = dist.reshape(len(query), k), at.reshape(len(query), k)
        h = (self.sizes[at] + (self.growth - 1.0) * dist).min(axis=1)
        return h if self.cap is None else np.minimum(h, self.cap)


def size_field(mesh, growth=None, seam_size=None, edge_length=None, lines=None):
    """The :class:`SizeField` of an assembled surface ``mesh``
    (:class:`~juncture.surface.assemble.SurfaceMesh`), or None without ``growth`` and
    ``seam_size``. ``lines`` ((n,) int, 1 on the lines where components meet, as
    :func:`juncture.surface.remesh.remesh` takes it): where ``seam_size`` holds; without
    it, the vertices that triangles of two components share."""
    if growth is None and seam_size is None:
        return None
    t = np.asarray(mesh.triangles)
    v = np.asarray(mesh.vertices, float)
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    s = np.tile(np.asarray(mesh.surface), 3)
    edges, inv, uses = np.unique(e, axis=0, return_inverse=True, return_counts=True)
    inv = inv.ravel()
    lo, hi = np.full(len(edges), np.iinfo(np.int64).max), np.full(len(edges), -1)
    np.minimum.at(lo, inv, s)
    np.maximum.at(hi, inv, s)
    # seams and boundaries: edges between two surfaces, or not in two triangles
    ends = edges[(uses != 2) | (lo != hi)]
    length = np.linalg.norm(v[ends[:, 0]] - v[ends[:, 1]], axis=1)
    h = np.full(len(v), np.inf)
    np.minimum.at(h, ends[:, 0], length)
    np.minimum.at(h, ends[:, 1], length)
    if seam_size is not None:
        if lines is None:
            from .lift import shared_vertices

            on = shared_vertices(mesh)
        else:
            on = np.asarray(lines) == 1
        h[on] = np.minimum(h[on], float(seam_size))
    src = np.isfinite(h)
    return SizeField(v[src], h[src], GROWTH if growth is None else growth, edge_length)

