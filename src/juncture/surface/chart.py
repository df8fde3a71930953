"""Flat charts of surface patches: a patch cut open into a disc, then flattened conformally.

A patch is the part of an assembled surface that comes from one network (or one cap),
connected, as local triangles over local vertex ids. :func:`disc` cuts it open along
shortest edge paths until it has one boundary loop (a fuselage block with fin footprints,
a pod's tube); :func:`lscm` flattens the disc by least-squares conformal maps (Lévy,
Petitjean, Ray & Maillot 2002), which keep angles, so a triangulation of good angles in the
chart has good angles on the surface. :func:`locate` takes chart points back onto the
patch's triangles (barycentric), which lie on juncture's networks.
"""

from __future__ import annotations

import numpy as np

from .rows import unique_pairs

__all__ = ["disc", "finder", "lscm", "locate", "patch_edges"]


def patch_edges(tri):
    """(directed (3m, 2), undirected unique (e, 2), uses per unique edge, inverse (3m,))."""
    directed = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    und, inverse, uses = unique_pairs(np.sort(directed, axis=1), return_inverse=True,
                                      return_counts=True)
    return directed, und, uses, inverse


def edge_sides(uses, inverse):
    """(first, second) triangle rows of each unique edge of :func:`patch_edges` (``uses``,
    ``inverse``); an edge in one triangle has it as both."""
    order = np.argsort(inverse, kind="stable")          # each edge's rows, in turn
    start = np.cumsum(uses) - uses
    owner = np.tile(np.arange(len(inverse) // 3), 3)[order]
    return owner[start], owner[np.minimum(start + 1, len(owner) - 1)]


def _loops(tri):
    from .assemble import boundary_loops

    return boundary_loops(tri) if len(tri) else []


def _cut_path(tri, n, source, target, blocked):
    """Vertex ids of the shortest edge path (by count of edges, then length is not needed)
    from a vertex in ``source`` to one in ``target`` through no vertex in ``blocked`` and
    along no boundary edge, or None."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import dijkstra

    _, und, uses, _ = patch_edges(tri)
    ok = (uses == 2) & ~blocked[und[:, 0]] & ~blocked[und[:, 1]]
    e = und[ok]
    g = coo_matrix((np.ones(len(e)), (e[:, 0], e[:, 1])), shape=(n, n)).tocsr()
    dist, pred, src = dijkstra(g, directed=False, indices=source, return_predecessors=True,
                               min_only=True)
    tgt = np.asarray(target)
    if not np.isfinite(dist[tgt]).any():
        return None
    v = int(tgt[np.argmin(dist[tgt])])
    path = [v]
    while pred[v] >= 0:
        v = int(pred[v])
        path.append(v)
    return path[::-1]


def _cut(tri, n, path):
    """Triangles and the new vertex count after cutting along ``path`` (a simple edge path
    from boundary to boundary): the path's vertices are duplicated for the triangles on one
    side. Returns (tri, parent) with ``parent`` the original id of every vertex."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    on_path = np.zeros(n, bool)
    on_path[path] = True
    near = np.flatnonzero(on_path[tri].any(axis=1))
    cut_edges = {tuple(sorted(e)) for e in zip(path[:-1], path[1:])}
    sub = tri[near]
    directed = np.concatenate([sub[:, [0, 1]], sub[:, [1, 2]], sub[:, [2, 0]]])
    owner = np.tile(np.arange(len(near)), 3)
    key = np.sort(directed, axis=1)
    keep = np.array([tuple(k) not in cut_edges for k in key.tolist()])
    order = np.lexsort((key[:, 1], key[:, 0]))
    k, o, kp = key[order], owner[order], keep[order]
    same = np.all(k[1:] == k[:-1], axis=1) & kp[1:]
    a, b = o[:-1][same], o[1:][same]
    g = coo_matrix((np.ones(len(a)), (a, b)), shape=(len(near), len(near)))
    count, label = connected_components(g, directed=False)
    if count != 2:
        return None
    side = near[label == label[0]]
    dup = np.full(n, -1)
    dup[path] = n + np.arange(len(path))
    out = tri.copy()
    block = out[side]
    out[side] = np.where(on_path[block], dup[block], block)
    parent = np.concatenate([np.arange(n), np.asarray(path)])
    return out, parent


def disc(tri, n):
    """Cut a patch (local triangles over ``n`` vertices) open into a topological disc.

    Returns ``(tri, parent)`` (triangles over the cut vertices, the original id of every
    cut vertex) or None when the patch is not a sphere with holes (no boundary, handles,
    or a cut that does not separate).
    """
    loops = _loops(tri)
    _, und, _, _ = patch_edges(tri)
    if not loops or n - len(und) + len(tri) != 2 - len(loops):
        return None
    parent = np.arange(n)
    loops.sort(key=len, reverse=True)
    joined = np.zeros(n, bool)
    joined[loops[0]] = True
    boundary = np.zeros(n, bool)
    for lp in loops:
        boundary[lp] = True
    for lp in loops[1:]:
        blocked = boundary & ~joined
        blocked[lp] = False
        path = _cut_path(tri, len(parent), lp, np.flatnonzero(joined), blocked)
        if path is None:
            return None
        got = _cut(tri, len(parent), path)
        if got is None:
            return None
        tri, more = got
        parent = parent[more]
        joined = np.concatenate([joined, np.ones(len(path), bool)])
        joined[lp] = True
        joined[path] = True
        boundary = np.concatenate([boundary, np.ones(len(path), bool)])
        boundary[path] = True
    return tri, parent


def lscm(points, tri):
    """(n, 2) least-squares conformal chart of a disc (``points`` (n, 3), ``tri`` (m, 3)),
    oriented so the triangles run counter-clockwise, scaled to the surface's area; None if the
    chart folds (a triangle of zero or negative area)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.linalg import spsolve

    n = len(points)
    p = points[tri]
    e1 = p[:, 1] - p[:, 0]
    e2 = p[:, 2] - p[:, 0]
    l1 = np.linalg.norm(e1, axis=1)
    nrm = np.cross(e1, e2)
    area2 = np.linalg.norm(nrm, axis=1)
    good = (l1 > 0) & (area2 > 0)
    if not good.all():
        return None
    x1 = e1 / l1[:, None]
    y1 = np.cross(nrm / area2[:, None], x1)
    z = np.stack([np.zeros(len(tri), complex), l1 + 0j,
                  np.einsum("ij,ij->i", e2, x1) + 1j * np.einsum("ij,ij->i", e2, y1)], 1)
    w = np.stack([z[:, 2] - z[:, 1], z[:, 0] - z[:, 2], z[:, 1] - z[:, 0]], 1)
    w = w / np.sqrt(np.maximum(area2, 1e-12 * np.median(area2)))[:, None]
    rows = np.arange(len(tri))
    r = np.repeat(rows, 3)
    c = tri.ravel()
    wr, wi = w.real.ravel(), w.imag.ravel()
    # unknowns: u (0..n-1), v (n..2n-1); rows: real parts, then imaginary parts.
    ri = np.concatenate([r, r, r + len(tri), r + len(tri)])
    ci = np.concatenate([c, c + n, c, c + n])
    vals = np.concatenate([wr, -wi, wi, wr])
    a = coo_matrix((vals, (ri, ci)), shape=(2 * len(tri), 2 * n)).tocsc()
    i0, i1 = _far_pair(points, tri)
    pinned = np.array([i0, i1, i0 + n, i1 + n])
    known = np.array([0.0, float(np.linalg.norm(points[i1] - points[i0])), 0.0, 0.0])
    free = np.setdiff1d(np.arange(2 * n), pinned)
    af, ap = a[:, free], a[:, pinned]
    rhs = -(ap @ known)
    sol = spsolve((af.T @ af).tocsc(), af.T @ rhs)
    x = np.empty(2 * n)
    x[free], x[pinned] = sol, known
    uv = np.stack([x[:n], x[n:]], 1)
    signed = _signed_areas(uv, tri)
    if signed.sum() < 0:
        uv[:, 1] *= -1.0
        signed = -signed
    if not np.all(np.isfinite(uv)) or np.any(signed <= 0):
        return None
    return uv * np.sqrt(0.5 * area2.sum() / signed.sum())   # the surface's area


def _far_pair(points, tri):
    loops = _loops(tri)
    b = np.asarray(loops[0]) if loops else np.arange(len(points))
    q = points[b]
    i = int(np.argmax(np.linalg.norm(q - q[0], axis=1)))
    j = int(np.argmax(np.linalg.norm(q - q[i], axis=1)))
    return int(b[i]), int(b[j])


def _signed_areas(uv, tri):
    a, b, c = uv[tri[:, 0]], uv[tri[:, 1]], uv[tri[:, 2]]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1])
                  - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def finder(uv, tri):
    """matplotlib's trapezoid-map point locator of a chart, or None where it takes the
    chart for invalid (points that coincide, triangles that overlap)."""
    from matplotlib.tri import Triangulation

    try:
        return Triangulation(uv[:, 0], uv[:, 1], tri).get_trifinder()
    except (RuntimeError, ValueError):
        return None


def locate(uv, tri, points, query, find=None):
    """(3-D points, triangle) of chart points ``query`` (q, 2): barycentric on the 3-D
    corners ``points[tri]`` of the chart triangle that contains each (matplotlib's
    trapezoid map; the nearest triangle, clamped, where round-off leaves a point just
    outside), and that triangle's row."""
    if len(query) == 0:
        return np.zeros((0, 3)), np.zeros(0, np.int64)
    find = find or finder(uv, tri)
    which = np.asarray(find(query[:, 0], query[:, 1]), np.int64)
    lost = which < 0
    if lost.any():
        which[lost] = _nearest(uv, tri, query[lost])
    corners = tri[which]
    a, b, c = (uv[corners[:, i]] for i in range(3))
    v0, v1, v2 = b - a, c - a, query - a
    den = v0[:, 0] * v1[:, 1] - v0[:, 1] * v1[:, 0]
    s = (v2[:, 0] * v1[:, 1] - v2[:, 1] * v1[:, 0]) / den
    t = (v0[:, 0] * v2[:, 1] - v0[:, 1] * v2[:, 0]) / den
    wgt = np.clip(np.stack([1 - s - t, s, t], 1), 0.0, None)
    wgt /= wgt.sum(axis=1, keepdims=True)
    return np.einsum("qk,qkj->qj", wgt, points[corners]), which


def _nearest(uv, tri, query):
    """The triangle nearest each query point (by its closest corner's triangles: enough for
    points a round-off off the chart's boundary)."""
    from scipy.spatial import cKDTree

    _, corner = cKDTree(uv).query(query)
    out = np.empty(len(query), np.int64)
    for k, (v, q) in enumerate(zip(corner, query)):
        rows = np.flatnonzero((tri == v).any(axis=1))
        centre = uv[tri[rows]].mean(axis=1)
        out[k] = rows[np.argmin(np.linalg.norm(centre - q, axis=1))]
    return out

