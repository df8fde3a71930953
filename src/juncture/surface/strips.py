"""Thin strips in the re-triangulation: the cap of a blunt trailing edge.

A blunt trailing edge is closed by a strip between the upper and the lower surface's last
lines (:func:`juncture.surface.assemble.strip_cap`), often a hundredth of the chord wide and
the whole span long. Refined in its own chart it needs triangles as small as its width, and
where it pinches to nothing (a trailing edge that meets the fuselage at a point) the
refinement runs on towards the corner and pushes ever shorter pieces onto the wing's seams;
zipped as it is, its triangles are as thin as its width is short against the networks'
spacing. So a strip is not charted: its long sides are split once, before the rounds, into
pieces of at most :func:`spacing` times its width there (shared with the wing surfaces
across them, which refine to that spacing), and at the end it is zipped again over every
point on its sides. A zipped triangle of width h and base b has a smallest angle of about
atan(h / b): the spacing follows the smallest angle asked of the charts (20 deg at b = 2.7 h
for the default 25). Where a neighbour's refinement put one side's points much closer
together than the strip is wide, the zip fans them from the other side's long piece; that
stretch takes points inside (:func:`zipped`, :mod:`juncture.surface.strip_fill`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .assemble import boundary_loops, equal_run, strip_chains, zip_strip
from .quality import triangle_angles

__all__ = ["Strip", "strip", "tip_and_strip", "presplit", "zipped", "zipped_all", "spacing",
           "STRIP", "MOST", "FILL"]

#: A cap patch is a strip when its area is below this share of a circle's of its boundary's
#: length (a rectangle narrower than about STRIP / pi of its length).
STRIP = 0.05
#: A strip's sides are split into pieces of at most :func:`spacing` times its local width:
#: 1 / tan(SHARE * min_angle), 2.7 at the default smallest angle of 25 deg (a zipped
#: triangle of width h and base b has a smallest angle of about atan(h / b): 20 deg) ...
SHARE = 0.8
#: ... but no finer than that times this share of its widest (where it pinches to a point
#: no spacing helps the triangle at the corner), and each edge into at most :data:`MOST`.
NARROWEST = 0.1
#: A strip pinches at a corner its sides leave within this angle [deg] of one another.
PINCH = 20.0
MOST = 4000
#: A zipped strip with a triangle under this [deg] takes points inside.
FILL = 10.0


class Strip(NamedTuple):
    rows: np.ndarray     # the patch's triangle rows
    a: np.ndarray        # its two sides, corner to corner (vertex ids; see strip_chains)
    b: np.ndarray
    normal: np.ndarray   # the sum of its triangles' area vectors (its orientation)


def tip_and_strip(mesh, rows):
    """(the tip's triangle rows, a :class:`Strip` of the rest) of a cap that is a planar tip
    and a thin strip joined (a blunt trailing edge running into the tip, capped so by
    :func:`juncture.surface.assemble.assemble`: the tip's points share its span station),
    else None. As one patch the strip was refined in the cap's chart, down to its width, and
    pushed points a few thousandths of a foot apart onto the wing's seams (slivers there)."""
    tri, loop = _cap_loop(mesh, rows)
    found = None if loop is None else equal_run(mesh.vertices[loop])
    if found is None:
        return None
    start, n = found
    tip = np.isin(tri, np.roll(loop, -start)[:n]).all(axis=1)
    if tip.all() or not tip.any():
        return None
    thin = strip(mesh, rows[~tip])
    return None if thin is None else (rows[tip], thin)


def _cap_loop(mesh, rows):
    """(the triangles, their one boundary loop) of a cap patch; loop None if the patch is
    not a cap or has more than one loop."""
    tri = mesh.triangles[rows]
    if not mesh.surfaces[mesh.surface[rows[0]]].endswith(" cap"):
        return tri, None
    loops = boundary_loops(tri)
    return tri, (loops[0] if len(loops) == 1 else None)


def _area_vectors(p):
    return 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])


def strip(mesh, rows):
    """A :class:`Strip` of the triangles ``rows`` (one patch) where they are a thin cap
    between two chains, else None."""
    tri, lp = _cap_loop(mesh, rows)
    if lp is None:
        return None
    v = mesh.vertices
    area = _area_vectors(v[tri])
    length = np.linalg.norm(v[lp] - v[np.roll(lp, -1)], axis=1).sum()
    if not 4.0 * np.pi * np.linalg.norm(area, axis=1).sum() < STRIP * length ** 2:
        return None
    chains = strip_chains(v, lp[::-1])     # as the loop of the hole it closes
    return None if chains is None else Strip(rows, *chains, area.sum(axis=0))


def _distance(points, chain):
    """(k,) distances of points to the polyline ``chain`` (m, 3)."""
    a, d = chain[:-1], chain[1:] - chain[:-1]
    dd = np.maximum((d * d).sum(axis=1), 1e-300)
    t = np.clip(((points[:, None] - a) * d).sum(axis=2) / dd, 0.0, 1.0)
    return np.linalg.norm(points[:, None] - a - t[..., None] * d, axis=2).min(axis=1)


def spacing(min_angle):
    """The longest piece of a strip's side, in widths, for triangles of about
    ``SHARE * min_angle`` [deg] (:data:`SHARE`)."""
    return 1.0 / np.tan(np.radians(SHARE * min_angle))


def presplit(s, vertices, splits, min_angle):
    """Split each side's edges of the strip ``s`` (in ``splits``, shared with the surface
    across) into pieces of at most :func:`spacing` times the width where each starts
    (:func:`_graded`)."""
    for side, other in ((s.a, s.b), (s.b, s.a)):
        p, q = vertices[side[:-1]], vertices[side[1:]]
        w0, w1 = _distance(p, vertices[other]), _distance(q, vertices[other])
        w0[0], w1[-1] = _corner_width(vertices, side, other)
        length = np.linalg.norm(q - p, axis=1)
        for i, j, ln, a, b in zip(side[:-1].tolist(), side[1:].tolist(), length, w0, w1):
            for t in _graded(ln, a, b, spacing(min_angle)):
                splits.split(i, j, float(t))


def _corner_width(vertices, side, other):
    """The strip's width at the two corners its sides share: 0 where it pinches there (its
    sides leave the corner within :data:`PINCH` of one another: a blunt trailing edge that
    closes at a pointed tip), else the distance from each to the other side without that
    corner (its rung, where the strip ends in an edge across it: a trailing edge cut by the
    fuselage)."""
    out = []
    for end, step in ((0, 1), (-1, -2)):
        c = vertices[side[end]]
        u, v = vertices[side[step]] - c, vertices[other[step]] - c
        cos = u @ v / max(np.linalg.norm(u) * np.linalg.norm(v), 1e-300)
        rest = other[1:] if end == 0 else other[:-1]
        out.append(0.0 if cos > np.cos(np.radians(PINCH)) else
                   float(_distance(c[None], vertices[rest])[0]))
    return out[0], out[1]


def _graded(length, w0, w1, most):
    """Inner fractions of an edge of ``length`` whose strip is ``w0`` wide at its start and
    ``w1`` at its end (linearly between): each piece at most ``most`` times the width where
    it starts, marched from the narrow end; :data:`MOST` equal pieces where that takes
    more. Where the strip pinches (0 wide at one end) the piece at that end reaches to
    where it is :data:`NARROWEST` of its widest: one triangle to the corner, whose angle
    there is the corner's (pieces of ``most`` times that width all the way there would be
    zipped into triangles ever thinner). The wing's charts beside it may still split that
    piece (their refinement into a pointed tip's corner does), and each such point is a
    sliver of the strip there: pieces short enough for good triangles all the way to the
    corner would take thousands per e-fold of the distance to it."""
    thin, wide = min(w0, w1), max(w0, w1)
    first = NARROWEST if thin == 0.0 else 0.0
    if length <= most * max(thin, NARROWEST * wide) or wide <= 0.0:
        return np.zeros(0)
    t = [0.0, first] if first else [0.0]
    while t[-1] < 1.0 and len(t) <= MOST:
        t.append(t[-1] + most * max(thin + (wide - thin) * t[-1], NARROWEST * wide) / length)
    if t[-1] < 1.0:
        t = np.linspace(0.0, 1.0, MOST + 1)
    t = np.asarray(t) / t[-1]
    t = t[1:-1]
    return t if w0 <= w1 else (1.0 - t)[::-1]


def _filled(tri, vertices, min_angle):
    """(triangles, new points): the zip ``tri`` with each stretch around triangles under
    :data:`FILL` deg taken again with points inside where that mends it
    (:func:`juncture.surface.strip_fill.filled`), the new points numbered from
    ``len(vertices)``."""
    from .strip_fill import filled, windows

    parts, new, last = [], [np.zeros((0, 3))], 0
    for lo, hi in windows(triangle_angles(vertices, tri).min(axis=1), FILL):
        got = filled(np.concatenate([vertices] + new), tri[lo:hi + 1], min_angle)
        if got is None:
            continue
        new.append(got[0])
        parts += [tri[last:lo], got[1]]
        last = hi + 1
    return (np.concatenate(parts + [tri[last:]]) if parts else tri), np.concatenate(new)


def _with_points(side, splits):
    out = [side[:1]]
    for i, j in zip(side[:-1].tolist(), side[1:].tolist()):
        out.extend([splits.along(i, j)[1], [j]])
    return np.concatenate(out).astype(np.int64)


def zipped_all(strips, splits, min_angle=None):
    """[(triangles, rows)] of every strip (:func:`zipped`); of a strip and its mirror image
    in y = 0 (another of them), the one whose triangles are better (:func:`_score`: the
    two are zipped from opposite ends) is kept and copied as the other
    (:func:`juncture.surface.mirror.copy_triangles`: the points filled inside it get their
    images), so the two halves stay each other's images."""
    from types import SimpleNamespace

    from .mirror import copy_triangles

    m = splits.mirror
    keys = [frozenset(np.concatenate([s.a, s.b]).tolist()) for s in strips]
    where = {k: i for i, k in enumerate(keys)}
    out = [None] * len(strips)
    for i, s in enumerate(strips):
        if out[i] is not None:
            continue
        ids = np.array(sorted(keys[i]))
        j = None if m is None or np.any(m[ids] < 0) else \
            where.get(frozenset(m[ids].tolist()))
        if j is None or j == i:
            out[i] = _kept(zipped(s, splits, min_angle), splits)
            continue
        got = [zipped(s, splits, min_angle), zipped(strips[j], splits, min_angle)]
        v = splits.all()
        first = 0 if _score(v, *got[0]) >= _score(v, *got[1]) else 1
        k, other = (i, j) if first == 0 else (j, i)
        out[k] = _kept(got[first], splits)
        tri = copy_triangles(SimpleNamespace(out=out[k]), splits)
        flip = _area_vectors(splits.all()[tri]).sum(axis=0) @ strips[other].normal < 0.0
        out[other] = tri[:, ::-1] if flip else tri
    return [(t, s.rows) for t, s in zip(out, strips)]


def _kept(got, splits):
    """The triangles of a strip's (triangles, new points), the points added to ``splits``
    (numbered so from its end)."""
    splits.add_vertex(got[1])
    return got[0]


def _score(vertices, tri, new):
    """:func:`juncture.surface.strip_fill.score` of a strip's (triangles, new points
    numbered from the end of ``vertices``): larger is better."""
    from .strip_fill import score

    return score(triangle_angles(np.concatenate([vertices, new]), tri))


def zipped(s, splits, min_angle=None):
    """(triangles, new points) of the strip over every point now on its sides, oriented as
    it was (new points numbered from the end of ``splits``, not added to it); with
    ``min_angle``, where the zip has a triangle under :data:`FILL` deg, points inside it
    where they mend that (:func:`juncture.surface.strip_fill.filled`)."""
    v = splits.all()
    a, b = _with_points(s.a, splits), _with_points(s.b, splits)
    tri, new = zip_strip(v, a, b, angles=True), np.zeros((0, 3))
    if min_angle and len(tri):
        tri, new = _filled(tri, v, min_angle)
    if _area_vectors(np.concatenate([v, new])[tri]).sum(axis=0) @ s.normal < 0.0:
        tri = tri[:, ::-1]
    return tri, new
