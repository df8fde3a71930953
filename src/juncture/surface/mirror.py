"""Both halves of a symmetric surface re-triangulated once (:func:`juncture.surface.remesh`).

A network and its image (``"<name> image"``, :meth:`juncture.geometry.Geometry.mirrored_networks`)
carry mirror-image points bit for bit, but their charts were triangulated apart: ties in
the Delaunay triangulation of a structured grid break differently in each half, so the two
halves differed, refinement did twice the work, and a defect could show in one half only.
Here every vertex is matched with the vertex at its mirror image in y = 0 (bit for bit), and
a patch (a connected part of one surface) whose vertices and rim are the mirror images of
another's is that patch's copy: only the patch on the y > 0 side is charted and
triangulated, a point split on any edge is split on its mirror image too
(:class:`juncture.surface.splits.Splits`), and the copy takes the mirror image of the
triangles (corners reversed, so its normals point out).
Patches that meet the plane of symmetry on both sides (a blunt base's cap) and those with no
mirror image (a centre-line fin whose two sides differ) are triangulated on their own.
"""

from __future__ import annotations

import numpy as np

from .rows import unique_pairs, unique_points

__all__ = ["mirror_map", "twins", "copy_triangles", "symmetrise", "triangle_mirror", "FLIP"]

#: The mirror image in y = 0.
FLIP = np.array([1.0, -1.0, 1.0])


def mirror_map(vertices):
    """(n,) int: the vertex at each vertex's mirror image in y = 0 (bit for bit; itself on
    the plane), or -1 where there is none."""
    v = np.asarray(vertices, float)
    n = len(v)
    both = np.concatenate([v, v * FLIP]) + 0.0             # -0.0 is 0.0
    _, first, inverse = unique_points(both, return_index=True, return_inverse=True)
    at = first[inverse[n:]]
    return np.where(at < n, at, -1)


def twins(mesh, groups, mirror):
    """{copy: primary} among the patches ``groups`` (rows of ``mesh.triangles``): pairs whose
    vertices and rims are mirror images of each other, the primary the one on the y > 0
    side (by its vertices' mean)."""
    tri = np.asarray(mesh.triangles)
    y = np.asarray(mesh.vertices, float)[:, 1]

    def key(t):
        return tuple(np.unique(t).tolist()), _rim(t)

    found = {key(tri[rows]): i for i, rows in enumerate(groups)}
    out = {}
    for i, rows in enumerate(groups):
        t = tri[rows]
        if np.any(mirror[t] < 0) or np.mean(y[t]) <= 0.0:
            continue
        j = found.get(key(mirror[t]))
        if j is not None and j != i:
            out[j] = i
    return out


def _rim(triangles):
    """The edges (a < b) in one of ``triangles`` (global ids): the region's boundary, the
    same whichever diagonals its quads have and wherever its chart was cut open."""
    e = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]],
                                triangles[:, [2, 0]]]), axis=1)
    u, count = unique_pairs(e, return_counts=True)
    return tuple(map(tuple, u[count == 1].tolist()))


def copy_triangles(primary, splits):
    """The mirror image of ``primary.out`` (global ids) for its copy, corners reversed; a
    vertex with no mirror yet (a point refinement put inside the primary) gets one, at its
    mirror image."""
    out = primary.out
    ids = np.unique(out)
    lone = ids[splits.mirror[ids] < 0]
    if len(lone):
        made = splits.add_vertex(splits.all()[lone] * FLIP)
        splits.mirror[lone], splits.mirror[made] = made, lone
    return splits.mirror[out][:, [0, 2, 1]]


def symmetrise(splits):
    """Put every vertex on the y < 0 side with a mirror on the y > 0 side at that vertex's
    mirror image exactly (the split points of a copy were made from its own ends, and
    lifted on their own: a few ulps apart)."""
    xyz = splits.all()
    m = splits.mirror[:splits.n]
    src = np.flatnonzero((m >= 0) & (xyz[:, 1] > 0.0))
    xyz[m[src]] = xyz[src] * FLIP


def triangle_mirror(vertices, triangles):
    """(m,) int: the triangle whose corners are each triangle's corners' mirror images in
    y = 0 (bit for bit), or -1 where there is none."""
    m = mirror_map(vertices)
    t = np.asarray(triangles, np.int64).reshape(-1, 3)
    out = np.full(len(t), -1, np.int64)
    n = len(m)
    ok = np.all(m[t] >= 0, axis=1)
    if not ok.any() or n >= 2**20:      # (three ids in one int64 key up to 2**21 vertices)
        return out
    weight = np.array([n * n, n, 1], np.int64)
    key = np.sort(t, axis=1) @ weight
    image = np.sort(m[t[ok]], axis=1) @ weight
    order = np.argsort(key, kind="stable")
    at = np.searchsorted(key[order], image)
    at = np.minimum(at, len(t) - 1)
    hit = key[order][at] == image
    out[np.flatnonzero(ok)[hit]] = order[at[hit]]
    return out
