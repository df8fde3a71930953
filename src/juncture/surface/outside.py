"""Boundary pieces to split for the triangles PythonCDT's refinement leaves thin.

PythonCDT's ``refine_triangles`` does not refine a triangle whose circumcentre lies outside
the chart (it counts it in ``Unrefined.circumcenter_outside``). Ruppert's refinement splits
the boundary piece such a circumcentre lies beyond instead. Where a neighbour's refinement
puts seam points close together on one side of a thin patch (a wing's tip cap near its
trailing edge) and the other side keeps a long piece, the triangles fanned from that
piece's end stayed under 3 deg. :func:`outside_splits` gives those pieces, so that the
re-triangulation splits them (:func:`juncture.surface.remesh._triangulate_once`).
"""

from __future__ import annotations

import numpy as np

from .quality import triangle_angles

__all__ = ["outside_splits"]


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


def outside_splits(pts, local, cons, parent, min_angle, shortest):
    """[(global i, global j, fraction from i)]: the midpoints of the boundary pieces
    ``cons`` (chart ids into ``pts``; ``parent``: their original edges and the fractions of
    their ends along them) that the circumcentre of a triangle of ``local`` under
    ``min_angle`` [deg] lies beyond, seen from the triangle's centre; pieces shorter than
    twice ``shortest`` are not split (refinement makes no shorter edge)."""
    p = pts[local]
    bad = np.flatnonzero(triangle_angles(pts, local).min(axis=1) < min_angle)
    if not len(bad) or not len(cons):
        return []
    centre, cc = p[bad].mean(axis=1), _circumcentres(p[bad])
    ok = np.isfinite(cc).all(axis=1)
    hit = _first_crossed(centre[ok], cc[ok], pts[cons[:, 0]], pts[cons[:, 1]])
    hit = np.unique(hit[hit >= 0])
    long = np.linalg.norm(pts[cons[hit, 1]] - pts[cons[hit, 0]], axis=1) > 2.0 * shortest
    return [(int(parent[0][k]), int(parent[1][k]), 0.5 * float(parent[2][k] + parent[3][k]))
            for k in hit[long]]
