"""Boundary pieces to split for the triangles PythonCDT's refinement leaves thin.

PythonCDT's ``refine_triangles`` does not refine a triangle whose circumcentre lies outside
the chart (it counts it in ``Unrefined.circumcenter_outside``). Ruppert's refinement splits
the boundary piece such a circumcentre lies beyond instead. Where a neighbour's refinement
puts seam points close together on one side of a thin patch (a wing's tip cap near its
trailing edge) and the other side keeps a long piece, the triangles fanned from that
piece's end stayed under 3 deg. :func:`outside_splits` gives those pieces, so that the
re-triangulation splits them (:func:`juncture.surface.remesh._triangulate_once`).

After the refining rounds (:data:`juncture.surface.remesh.REFINING`), seams split in the
last of them fan the patches beside them. Those rounds do Ruppert's refinement in two
parts: :func:`interior_points`, the circumcentres that encroach no piece, which split
nothing on a seam, and, in the first two of them only, the pieces the other circumcentres
encroach (``encroached``), whose split points the neighbours take in the next round.
"""

from __future__ import annotations

import numpy as np

from .quality import triangle_angles

__all__ = ["outside_splits", "interior_points"]


def _circumcentres(p):
    """(k, 2) circumcentres of the chart triangles ``p`` (k, 3, 2); NaN where flat."""
    b, c = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    d = 2.0 * (b[:, 0] * c[:, 1] - b[:, 1] * c[:, 0])
    bb, cc = (b * b).sum(axis=1), (c * c).sum(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        x = (c[:, 1] * bb - b[:, 1] * cc) / d
        y = (b[:, 0] * cc - c[:, 0] * bb) / d
    return p[:, 0] + np.stack([x, y], axis=1)


def _first_crossed(start, end, a, b):
    """(k,) index of the first segment (a, b) crossed going from ``start`` to ``end``
    (k, 2 each), -1 where none is."""
    d = end - start                                      # (k, 2)
    e = b - a                                            # (m, 2)
    den = d[:, None, 0] * e[None, :, 1] - d[:, None, 1] * e[None, :, 0]
    w = a[None] - start[:, None]                         # (k, m, 2)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = (w[..., 0] * e[None, :, 1] - w[..., 1] * e[None, :, 0]) / den
        u = (w[..., 0] * d[:, None, 1] - w[..., 1] * d[:, None, 0]) / den
    hit = (s > 0.0) & (s <= 1.0) & (u >= 0.0) & (u <= 1.0)
    s = np.where(hit, s, np.inf)
    first = s.argmin(axis=1)
    return np.where(np.isfinite(s[np.arange(len(s)), first]), first, -1)


def outside_splits(pts, local, cons, parent, min_angle, shortest, encroached=False):
    """[(global i, global j, fraction from i)]: the midpoints of the boundary pieces
    ``cons`` (chart ids into ``pts``; ``parent``: their original edges and the fractions of
    their ends along them) that the circumcentre of a triangle of ``local`` under
    ``min_angle`` [deg] lies beyond, seen from the triangle's centre; pieces shorter than
    twice ``shortest`` are not split (refinement makes no shorter edge). With
    ``encroached``, also the piece whose diametral circle holds such a circumcentre inside
    the chart (Ruppert's rule), but not for a triangle whose smallest angle lies between
    two pieces (a corner of the chart)."""
    thin = _thin(pts, local, cons, min_angle, corners=not encroached)
    if thin is None:
        return []
    p, cc, _ = thin
    a, b = pts[cons[:, 0]], pts[cons[:, 1]]
    hit = _first_crossed(p.mean(axis=1), cc, a, b)
    if encroached:
        inside = hit < 0
        hit[inside] = _encroached(cc[inside], a, b)
    hit = np.unique(hit[hit >= 0])
    long = np.linalg.norm(b[hit] - a[hit], axis=1) > 2.0 * shortest
    return [(int(parent[0][k]), int(parent[1][k]), 0.5 * float(parent[2][k] + parent[3][k]))
            for k in hit[long]]


def interior_points(pts, local, cons, min_angle, shortest):
    """(k, 2) chart points that refine the triangles of ``local`` under ``min_angle`` [deg]
    without splitting a boundary piece of ``cons``: Ruppert's circumcentres, but only those
    inside the chart (no piece crossed on the way from the triangle's centre), outside every
    piece's diametral circle (where Ruppert would split the piece instead) and with a
    circumradius of at least ``shortest``; not for a triangle whose smallest angle lies
    between two pieces (a corner of the chart no point can mend). Worst triangle first, no
    two points nearer than half the smaller circumradius (each would spoil the other's)."""
    thin = _thin(pts, local, cons, min_angle)
    if thin is None:
        return np.zeros((0, 2))
    p, cc, worst = thin
    radius = np.linalg.norm(cc - p[:, 0], axis=1)
    a, b = pts[cons[:, 0]], pts[cons[:, 1]]
    ok = radius >= shortest
    ok[ok] = _first_crossed(p[ok].mean(axis=1), cc[ok], a, b) < 0
    ok[ok] = _encroached(cc[ok], a, b) < 0
    return cc[_spread(cc, radius, np.flatnonzero(ok)[np.argsort(worst[ok], kind="stable")])
              ].reshape(-1, 2)


def _spread(cc, radius, order):
    """The points ``order`` (ids into ``cc``, best first) kept one at a time, each no nearer
    than half the smaller circumradius to one kept before it; only the points within half
    its own radius can be that near, so only those are compared (a k-d tree)."""
    from scipy.spatial import cKDTree

    if not len(order):
        return []
    near = cKDTree(cc[order]).query_ball_point(cc[order], 0.5 * radius[order])
    taken = np.zeros(len(order), bool)
    for i, k in enumerate(order.tolist()):
        taken[i] = not any(taken[j] and np.linalg.norm(cc[k] - cc[order[j]])
                           < 0.5 * min(radius[k], radius[order[j]]) for j in near[i])
    return order[taken]


def _thin(pts, local, cons, min_angle, corners=False):
    """(corners (k, 3, 2), circumcentres (k, 2), smallest angles (k,)) of the triangles of
    ``local`` under ``min_angle`` [deg] with a circumcentre, but (unless ``corners``) those
    whose smallest angle lies between two pieces of ``cons``; None if there are none."""
    if not len(local) or not len(cons):
        return None
    angles = triangle_angles(pts, local)
    bad = np.flatnonzero(angles.min(axis=1) < min_angle)
    if not corners and len(bad):
        n = len(pts)
        key = _key(cons[:, 0], cons[:, 1], n)
        apex = angles[bad].argmin(axis=1)
        tri, rows = local[bad], np.arange(len(bad))
        v = tri[rows, apex]
        corner = np.isin(_key(v, tri[rows, (apex + 1) % 3], n), key) & \
            np.isin(_key(v, tri[rows, (apex + 2) % 3], n), key)
        bad = bad[~corner]
    p = pts[local[bad]]
    cc = _circumcentres(p)
    ok = np.isfinite(cc).all(axis=1)
    if not ok.any():
        return None
    return p[ok], cc[ok], angles[bad[ok]].min(axis=1)


def _encroached(points, a, b):
    """(k,) the piece (a, b) whose diametral circle holds each point most deeply (distance
    from its middle over its half length), -1 where none does."""
    if not len(points):
        return np.zeros(0, np.int64)
    half = 0.5 * np.linalg.norm(b - a, axis=1)
    depth = np.linalg.norm(points[:, None] - 0.5 * (a + b)[None], axis=2) / \
        np.maximum(half, 1e-300)[None]
    k = depth.argmin(axis=1)
    return np.where(depth[np.arange(len(points)), k] < 1.0, k, -1)


def _key(a, b, n):
    """Edge keys (smaller id * n + larger id)."""
    return np.minimum(a, b).astype(np.int64) * n + np.maximum(a, b)
