"""Plane helpers for re-triangulating a patch of surface: a frame, 2-D polygon tests, and
the constrained Delaunay triangulation (PythonCDT, MPL-2.0) that imprints and seams use.

Nothing here creates a point: a patch's own vertices are projected into the plane its
triangles face, triangulated there with its border (and any holes) as constraints, and the
triangles returned as ids of those vertices.
"""

from __future__ import annotations

import numpy as np

__all__ = ["unit", "frame", "inside", "distance", "is_simple", "constrained_triangles"]


def unit(v):
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n > 0, n, 1.0)


def frame(n):
    """(2, 3) in-plane axes e1, e2 with e1 x e2 = n."""
    e1 = np.cross(n, np.eye(3)[int(np.argmin(np.abs(n)))])
    e1 /= np.linalg.norm(e1)
    return np.stack([e1, np.cross(n, e1)])


def inside(pts, poly):
    """(k,) whether 2-D points lie inside the closed polygon (crossing number)."""
    a, b = poly, np.roll(poly, -1, axis=0)
    x, y = pts[:, None, 0], pts[:, None, 1]
    cross = (a[None, :, 1] > y) != (b[None, :, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xi = a[None, :, 0] + (y - a[None, :, 1]) * (b[None, :, 0] - a[None, :, 0]) / (
            b[None, :, 1] - a[None, :, 1])
    return (cross & (x < xi)).sum(axis=1) % 2 == 1


def distance(pts, poly):
    """(k,) distance of 2-D points from the closed polygon's edges."""
    a, d = poly, np.roll(poly, -1, axis=0) - poly
    rel = pts[:, None, :] - a[None]
    t = np.clip((rel * d[None]).sum(-1) / np.maximum((d * d).sum(-1), 1e-300), 0.0, 1.0)
    return np.linalg.norm(rel - t[..., None] * d[None], axis=-1).min(axis=1)


def is_simple(poly):
    """Whether a closed 2-D polygon has no two non-adjacent edges that cross."""
    a, b = poly, np.roll(poly, -1, axis=0)
    k = len(poly)

    def orient(p, q, r):
        return np.sign((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1])
                       - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))
    i, j = np.triu_indices(k, 2)
    keep = ~((i == 0) & (j == k - 1))
    i, j = i[keep], j[keep]
    d1, d2 = orient(a[i], b[i], a[j]), orient(a[i], b[i], b[j])
    d3, d4 = orient(a[j], b[j], a[i]), orient(a[j], b[j], b[i])
    return not np.any((d1 * d2 < 0) & (d3 * d4 < 0))




def constrained_triangles(uv, chains, holes=False):
    """(k, 3) ids into ``uv`` of the constrained Delaunay triangulation of the 2-D points
    ``uv`` inside the closed ``chains`` (lists of ids: the outer border, then holes when
    ``holes``), or None where the constraints cross or a point would be merged.

    With ``holes`` the triangles inside the inner chains are taken out as well (depth
    parity), else only those outside the outer one.
    """
    import pythoncdt as cdt

    cons = [(int(c[i]), int(c[(i + 1) % len(c)])) for c in chains for i in range(len(c))]
    tri = cdt.Triangulation(cdt.VertexInsertionOrder.AUTO,
                            cdt.IntersectingConstraintEdges.NOT_ALLOWED, 0.0)
    try:
        tri.insert_vertices(np.ascontiguousarray(uv, dtype=float))
        tri.insert_edges(np.array(cons, np.uint32))
        if holes:
            tri.erase_outer_triangles_and_holes()
        else:
            tri.erase_outer_triangles()
    except (RuntimeError, ValueError):
        return None
    if tri.vertices_count() != len(uv):
        return None
    return tri.triangles_array()["vertices"].astype(np.int64)
