"""Where a chart's new triangles leave the surface they stand for, and where new points go.

A chart's constrained Delaunay triangulation (:func:`juncture.surface.remesh.remesh`) is
flat; its triangles stand for a curved surface. :func:`deviating` and :func:`chords` give the
chart points where a triangle or an edge across the patch stands too far off that surface
(they become new points); :func:`bent` measures a new edge's sag against the exact surface;
:func:`on_surface` puts chart points on the patch's triangles and lifts them onto the exact
surface, only part of the way beside a free seam (:func:`lifted`,
:func:`juncture.surface.patches.taper`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .chart import locate
from .memo import Memo, triangle_keys
from .patch_roles import TAPER
from .patches import area3, taper

#: A triangle smaller than this share of the input triangle under it is not split again.
SMALL = 0.05
#: A sag below this share of the patch's size is not split for curvature (a nose's tip).
FLOOR = 1e-6
#: In a round that adds seam points, no new point goes where the input triangle under it is
#: thinner than this (twice its area under THIN times its longest edge squared): beside a
#: fuselage's pointed nose, where the chart's triangles are small and thin.
THIN = 0.1
#: An edge between two boundary points across a patch whose middle stands off the patch by
#: more than this share of its length goes through the body (:func:`_chords`).
CHORD = 0.1


class Shape(NamedTuple):
    """What a new triangle may span of the surface it stands for (:func:`deviating`)."""

    turn: float          # cosine of the largest turn of the input triangles under one new
    curvature: float | None   # largest turn of an exact surface under one new edge [rad]
    depth: float | None       # largest sag of a new edge, share of the exact surface's size
    size: object = None       # the target edge length at 3-D points (sizing.SizeField)


def deviating(patch, splits, vertices, pts, gid, local, tol, shape, boundary,
              far_only=False):
    """Chart centroids of the triangles that cut across the patch's surface: the centroid
    of the flat triangle more than ``tol`` off the surface, the patch triangles under
    its corners and centroid turning by more than ``shape.turn`` (cosine), or, on an exact
    surface, an edge cutting it too deep (:func:`bent`); with ``tol`` None only
    the triangles with every corner on the boundary that leave the surface (at a narrow
    corner between two seams, the patch across them would make the same triangle); with
    ``tol`` False none; ``far_only``: only those more than ``tol`` off, and not over an input
    triangle thinner than :data:`THIN`."""
    if tol is False or not len(local):
        return np.zeros((0, 2))
    # keyed by what the answers depend on (not the whole shape: it may carry more)
    memo = patch.memo.setdefault((tol, far_only, shape.turn, shape.curvature, shape.depth),
                                 Memo())
    keys = triangle_keys(pts, gid, local, boundary)
    out, todo, h = memo.get(keys)     # a triangle met before: its answer as it was
    if len(todo):
        out[todo] = _deviating(patch, splits, vertices, pts, gid, local[todo], tol, shape,
                               boundary, far_only)
        memo.add(h[todo], keys[todo], out[todo])
    return pts[local[out]].mean(axis=1)


def _deviating(patch, splits, vertices, pts, gid, local, tol, shape, boundary, far_only):
    """(k,) bool: the triangles of :func:`deviating`."""
    centre = pts[local].mean(axis=1)
    ends = splits.all()[gid[local]]
    flat = ends.mean(axis=1)
    rim = boundary[local, 0].all(axis=1)
    if tol is None:          # only the triangles with every corner on the boundary count
        rows = np.flatnonzero(rim)
        on = locate(patch.uv, patch.tri, vertices[patch.ids], centre[rows], patch.find)[0]
        rim[rows] = np.linalg.norm(on - flat[rows], axis=1) > 1e-9 * patch.size
        return rim
    on, under = locate(patch.uv, patch.tri, vertices[patch.ids], centre, patch.find)
    dev = np.linalg.norm(on - flat, axis=1)
    # a triangle far smaller than the input triangle under it is not split again (at a
    # crease, where every triangle astride it turns, splitting would not end)
    small = area3(ends) < SMALL * patch.areas[under]
    if far_only:
        if patch.lift is not None:
            dev = np.linalg.norm(lifted(patch, on, under, centre) - flat, axis=1)
        corner = vertices[patch.ids[patch.tri[under]]]
        longest = np.linalg.norm(corner - np.roll(corner, 1, axis=1), axis=2).max(axis=1)
        thin = 2 * patch.areas[under] < THIN * longest ** 2
        return (dev > tol) & ~small & ~thin
    across = rim & (dev > 1e-9 * patch.size)
    if patch.lift is not None:  # off the exact surface, where there is one, as a new
        # point there would be put: near a free boundary piece (a straight seam edge, not
        # lifted) only part of the way (:func:`lifted`), so splitting there ends
        dev = np.linalg.norm(lifted(patch, on, under, centre) - flat, axis=1)
        inner = ~boundary[local, 1].any(axis=1)
        deep = inner & bent(patch, splits, vertices, pts, gid, local, shape)
    else:
        deep = np.zeros(len(local), bool)
    corners = pts[local] + 1e-3 * (centre[:, None] - pts[local])     # inside, not on
    nk = patch.normals[locate(patch.uv, patch.tri, vertices[patch.ids],
                              corners.reshape(-1, 2), patch.find)[1]].reshape(-1, 3, 3)
    turns = (np.einsum("ij,ikj->ik", patch.normals[under], nk) < shape.turn).any(axis=1)
    return ((dev > tol) | turns) & ~small | across | deep


def oversized(splits, pts, gid, local, size):
    """Chart centroids of the triangles whose longest 3-D edge exceeds
    :data:`~juncture.surface.sizing.SLACK` times the size field ``size`` at their centre."""
    from .sizing import SLACK

    if size is None or not len(local):
        return np.zeros((0, 2))
    p = splits.all()[gid[local]]
    longest = np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2).max(axis=1)
    return pts[local].mean(axis=1)[longest > SLACK * size(p.mean(axis=1))]


def chords(patch, splits, vertices, pts, gid, local, boundary):
    """Chart midpoints of the edges that join two boundary points across the patch (not
    along a boundary piece) and leave its surface: in 3-D such a chord can cut through the
    body, e.g. from the top to the bottom of a half-fuselage near its nose, where the image
    half makes the same edge (four triangles on it). Off the surface means its midpoint
    more than :data:`CHORD` times the edge from the patch at the chart midpoint (a chord
    across a corner of a curved patch stands off by far less)."""
    ends = np.concatenate([local[:, [0, 1]], local[:, [1, 2]], local[:, [2, 0]]])
    ends = np.sort(ends[boundary[ends, 0].all(axis=1)], axis=1)
    key, uses = np.unique(ends[:, 0] * len(pts) + ends[:, 1], return_counts=True)
    key = key[uses == 2]          # inside the patch (a boundary piece has one triangle)
    if not len(key):
        return np.zeros((0, 2))
    ends = np.stack([key // len(pts), key % len(pts)], axis=1)
    mid = pts[ends].mean(axis=1)
    on, under = locate(patch.uv, patch.tri, vertices[patch.ids], mid, patch.find)
    if patch.lift is not None:
        on = lifted(patch, on, under, mid)
    xyz = splits.all()[gid[ends]]
    off = np.linalg.norm(on - xyz.mean(axis=1), axis=1)
    return mid[off > CHORD * np.linalg.norm(xyz[:, 1] - xyz[:, 0], axis=1)]


def bent(patch, splits, vertices, pts, gid, local, shape):
    """(k,) bool: triangles with an edge that cuts the exact surface too deep. A chord of
    length h on a curve of radius r stands s = h^2 / (8 r) off it at its middle and turns
    by 8 s / h: an edge is too deep where that turn exceeds ``shape.curvature`` (radians),
    or where s exceeds ``shape.depth`` times the size of the surface there (``lift.both``: a
    body's radius, a wing section's largest thickness; the share of the volume the chords
    cut off grows as s over that size). Sags below :data:`FLOOR` of the patch's size do not
    count (a nose's tip)."""
    both = getattr(patch.lift, "both", None)
    ends = splits.all()[gid[local]]
    if shape.curvature is None and shape.depth is None:
        return np.zeros(len(local), bool)
    angle, depth = shape.curvature, shape.depth
    # the three edges of every triangle at once, edge k of all triangles after edge k - 1
    nxt = np.roll(np.arange(3), -1)
    a = ends.transpose(1, 0, 2).reshape(-1, 3)
    b = ends[:, nxt].transpose(1, 0, 2).reshape(-1, 3)
    mid = 0.5 * (pts[local.T.ravel()] + pts[local[:, nxt].T.ravel()])
    on, under = locate(patch.uv, patch.tri, vertices[patch.ids], mid, patch.find)
    corners = patch.ids[patch.tri[under]]
    if both is None or depth is None:     # the surface's size only where depth asks for it
        onto, size = patch.lift(on, corners, patch.component, patch.surface), np.inf
    else:
        onto, size = both(on, corners, patch.component, patch.surface)
    # measured against where a new point there would go: near a free seam only part of the
    # way (lifted), or the gap between the ends, held there, and the full lift never shrank
    # (a wing root's trailing edge next to its strip was split down to 1e-6 ft)
    onto = tapered(patch, on, onto, mid, under)
    sag = np.linalg.norm(onto - 0.5 * (a + b), axis=1)
    h = np.linalg.norm(b - a, axis=1)
    size = np.broadcast_to(size, h.shape)
    turn = np.inf if angle is None else angle / 8.0 * h
    most = np.inf if depth is None else depth * size
    out = ((sag > turn) | (sag > most)) & (sag > FLOOR * patch.size)
    return out.reshape(3, -1).any(axis=0)



def lifted(patch, points, under, query=None):
    """Points on the patch's chart triangles ``under``, lifted onto the exact surface; with
    the chart points ``query``, a point nearer the patch's free boundary (a seam whose two
    sides do not lift alike) than :data:`TAPER` times its lift is lifted that share of the
    way only. Such seams are straight chords of the exact intersection lines: a point next
    to one lifted in full stands out of the chord by the sag, and where the surfaces meet at
    a small angle (a low wing's upper surface and the fuselage side) it went through the
    other surface. A seam that both sides lift alike (a split within one body) or that lies
    on both (a wing's leading edge) tapers nothing: on a body whose stations are far apart,
    whose networks cut its circle by a tenth of its radius, new points near them were left
    that far inside."""
    full = patch.lift(points, patch.ids[patch.tri[under]], patch.component, patch.surface)
    if query is None or not len(points):
        return full
    return tapered(patch, points, full, query, under)


def tapered(patch, points, full, query, under=None):
    """``points`` moved towards ``full`` (their lift) in full, or near the patch's free boundary
    (chart points ``query``) by the share :func:`lifted` describes; with the chart triangles
    ``under`` them, a lift out of the patch's solid (along its assembled triangle's normal)
    rises from a narrow valley's edges no steeper than ``patch.valley``
    (:func:`juncture.surface.patches.taper`)."""
    move = np.linalg.norm(full - points, axis=1)
    outward = None if under is None or patch.valley is None or patch.normals is None else \
        np.einsum("ij,ij->i", full - points, patch.normals[under]) > 0.0

    def sag(edges, row, t):         # on the straight 3-D edges, from their own triangles
        a, b = patch.xyz[edges[row, 0]], patch.xyz[edges[row, 1]]
        on = a + t[:, None] * (b - a)
        corners = patch.ids[patch.tri[_edge_triangles(patch.tri, edges)[row]]]
        return np.linalg.norm(patch.lift(on, corners, patch.component, patch.surface) - on,
                              axis=1)

    w = taper(patch, query, move, 1.0 / TAPER, sag, outward)
    return points + w[:, None] * (full - points)


def _edge_triangles(tri, edges):
    """(k,) the row of ``tri`` (m, 3) that has each edge (k, 2) (a boundary edge: one)."""
    n = int(tri.max()) + 1
    ends = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    key = ends[:, 0] * n + ends[:, 1]
    order = np.argsort(key, kind="stable")
    want = np.sort(edges, axis=1)
    at = np.searchsorted(key[order], want[:, 0] * n + want[:, 1])
    return order[np.minimum(at, len(order) - 1)] % len(tri)


def on_surface(patch, vertices, query):
    """(3-D points, chart triangles under them) of chart points: on the assembled triangles,
    lifted onto the exact surface where the patch has one."""
    xyz, under = locate(patch.uv, patch.tri, vertices[patch.ids], query, patch.find)
    return (xyz if patch.lift is None else lifted(patch, xyz, under, query)), under
