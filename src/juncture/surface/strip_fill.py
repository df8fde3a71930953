"""Points inside a thin strip where zipping its sides leaves slivers.

A blunt trailing edge's strip (:mod:`juncture.surface.strips`) is zipped at the end of the
re-triangulation over every point its neighbours put on its sides. Where one side took
points much closer together than the strip is wide (the wing's chart refined towards a
root's corner) and the other kept a long piece, the zip fans the close points from the
long piece's end: triangles of 1-4 deg at a wing root's trailing edge, and no triangle with
its three corners on the sides mends that. :func:`filled` takes the zip's rows around such
triangles (:func:`windows`), triangulates them in their own conformal chart
(:func:`juncture.surface.chart.lscm` of the zip) and refines it with PythonCDT, at
``min_angle`` and at each smaller angle of :data:`ANGLES`; the points refinement put on the
sides are dropped (the surfaces across them are final by then), the stretch is
triangulated again over the points it put inside, and then takes one point at a time in
its worst triangle while that raises the smallest angle (:func:`_polished`). The one with
the fewest triangles under :data:`SLIVER` deg, then the largest smallest angle (in 3-D),
is kept if it beats the zip, and none whose edges stand off the strip (:func:`_leaves`: a
chord across a trailing edge turning into a tip cut the wing's surface beside it). New
points lie on the zip's triangles.

Where the strip pinches to nothing at a corner (a blunt trailing edge running into a tip
of no chord) while its sides hold points, no point inside helps: the strip there is
narrower than any triangle on those points could be thin.
"""

from __future__ import annotations

import numpy as np

from .chart import locate, lscm
from .patches import SUPER
from .quality import triangle_angles

__all__ = ["filled", "windows", "score", "ANGLES", "BUDGET", "BEND", "MARGIN", "POLISH", "SLIVER"]

#: Smallest angles [deg] refined to, besides the one asked for (refinement at a smaller
#: angle puts fewer points beside the sides, where their split points are dropped).
ANGLES = (20.0, 15.0, 10.0)
#: Points refinement may add, per point the strip has.
BUDGET = 50
#: A new edge may stand off the strip at its middle by no more than this share of its
#: length (:func:`_leaves`).
BEND = 0.05
#: A triangulation with fewer triangles under this [deg] is better (then the one whose
#: smallest angle is larger).
SLIVER = 5.0
#: Points added one at a time to raise the smallest angle (:func:`_polished`).
POLISH = 30
#: Zip rows taken to each side of a thin one (:func:`windows`).
MARGIN = 12


def filled(vertices, tri, min_angle):
    """(new points (k, 3), triangles) of the part ``tri`` (global ids into ``vertices``;
    consecutive rows of a zip, one boundary loop) of a strip, the new points numbered from
    ``len(vertices)``, where that triangulation is better than the zip (fewer triangles
    under :data:`SLIVER` deg, or as many and a larger smallest angle, in 3-D) and none of
    its edges leaves the strip (:func:`_leaves`); else None."""
    from .assemble import boundary_loops

    loops = boundary_loops(tri)
    if len(loops) != 1:
        return None
    loop = np.asarray(loops[0])
    ids, local = np.unique(tri, return_inverse=True)
    local = local.reshape(-1, 3)
    if len(np.unique(loop)) != len(ids):
        return None                       # a vertex inside: not a plain strip
    xyz = vertices[ids]
    uv = lscm(xyz, local)
    if uv is None:
        return None
    ring = np.searchsorted(ids, loop)
    cons = np.stack([ring, np.roll(ring, -1)], axis=1).astype(np.uint32)
    best, mark = None, score(triangle_angles(vertices, tri))
    for angle in sorted({min_angle, *ANGLES}, reverse=True):
        inner = _inner_points(uv, cons, angle)
        got = None if inner is None else _polished(uv, cons, inner)
        if got is None:
            continue
        inner, t = got
        pts = np.concatenate([uv, inner])
        p3 = np.concatenate([xyz, locate(uv, local, xyz, inner)[0]])
        if _leaves(t, pts, p3, uv, local, xyz):
            continue
        got = score(triangle_angles(p3, t))
        if got > mark:
            best, mark = (p3[len(xyz):], t), got
    if best is None:
        return None
    points, t = best
    glob = np.concatenate([ids, len(vertices) + np.arange(len(points))])
    return points, glob[t]


def score(angles):
    """(minus the triangles under :data:`SLIVER` deg, the smallest angle) of triangles'
    angles (m, 3): larger is better."""
    worst = angles.min(axis=1)
    return -int(np.sum(worst < SLIVER)), float(worst.min(initial=180.0))


def windows(angles, limit, margin=None):
    """[(first, last)] row ranges of a zip around its triangles under ``limit`` [deg]
    (``angles``: each row's smallest), :data:`MARGIN` rows to each side, overlapping ones
    merged."""
    margin = MARGIN if margin is None else margin
    out = []
    for r in np.flatnonzero(angles < limit).tolist():
        lo, hi = max(0, r - margin), min(len(angles) - 1, r + margin)
        if out and lo <= out[-1][1] + 1:
            out[-1] = (out[-1][0], hi)
        else:
            out.append((lo, hi))
    return out


def _leaves(t, pts, p3, uv, local, xyz):
    """Whether an edge of the triangles ``t`` (ids into the chart points ``pts``, 3-D
    ``p3``) that the zip does not have stands off the strip by more than :data:`BEND` of
    its length at its middle (the zip's triangles ``local`` over ``xyz``, charted at
    ``uv``): where a trailing edge turns into a tip, a chord across the turn in the chart
    cuts the surface beside it."""
    def edges(tri):
        return np.unique(np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]],
                                                 tri[:, [2, 0]]]), axis=1), axis=0)

    e = edges(t)
    old = edges(local)
    n = len(pts)
    e = e[~np.isin(e[:, 0] * n + e[:, 1], old[:, 0] * n + old[:, 1])]   # the zip's stay
    on = locate(uv, local, xyz, 0.5 * (pts[e[:, 0]] + pts[e[:, 1]]))[0]
    straight = 0.5 * (p3[e[:, 0]] + p3[e[:, 1]])
    length = np.linalg.norm(p3[e[:, 0]] - p3[e[:, 1]], axis=1)
    return bool(np.any(np.linalg.norm(on - straight, axis=1) > BEND * length))


def _polished(uv, cons, inner, loop=True):
    """(inner points, triangles) of the chart ``uv`` with the points ``inner`` inside the
    loop ``cons``, then, while it raises the smallest angle (up to :data:`POLISH` times),
    one more point in the worst triangle: on the bisector of its shortest edge at a
    quarter, half or all of the way to its circumcentre, or its centroid, whichever gives
    the best; None where PythonCDT refuses the first. Without ``loop`` (``cons`` are pieces
    in any order, of any number of loops) a point outside is not ruled out first: the
    triangulation leaves it out, so it raises nothing."""
    from matplotlib.path import Path

    t = _cdt(np.concatenate([uv, inner]), cons)
    if t is None:
        return None
    ring = Path(uv[cons[:, 0]]) if loop else None
    pts = np.concatenate([uv, inner])
    worst = triangle_angles(pts, t).min(axis=1)
    for _ in range(POLISH):
        k = int(np.argmin(worst))
        best = None
        for q in _candidates(pts[t[k]]):
            if ring is not None and not ring.contains_point(q) or \
                    np.linalg.norm(pts - q, axis=1).min() < 1e-9:
                continue
            more = np.concatenate([pts, q[None]])
            tt = _cdt(more, cons)
            if tt is None:
                continue
            w = triangle_angles(more, tt).min(axis=1)
            if w.min() > worst.min() and (best is None or w.min() > best[2].min()):
                best = (more, tt, w)
        if best is None:
            break
        pts, t, worst = best
    return pts[len(uv):], t


def _candidates(p):
    """(5, 2) points to try in the triangle ``p`` (3, 2): on the bisector of its shortest
    edge at a quarter, half and all of the way to its circumcentre, its centroid, and the
    apex of the equilateral triangle on that edge inside it."""
    edge = np.linalg.norm(p - np.roll(p, -1, axis=0), axis=1)
    k = int(np.argmin(edge))
    a, b, c = p[k], p[(k + 1) % 3], p[(k + 2) % 3]
    mid = 0.5 * (a + b)
    d = b - a
    n = np.array([-d[1], d[0]])
    n *= np.sign(n @ (c - mid)) / max(np.linalg.norm(n), 1e-300)
    u, w = a - c, b - c
    cross = abs(u[0] * w[1] - u[1] * w[0])
    h = 0.5 * edge[k] * (u @ w) / max(cross, 1e-300)       # the circumcentre's height
    h = min(max(h, 0.0), n @ (c - mid))
    out = [mid + f * h * n for f in (0.25, 0.5, 1.0)]
    return np.array(out + [p.mean(axis=0), mid + 0.5 * np.sqrt(3.0) * edge[k] * n])


def _triangulation(pts, cons):
    import pythoncdt as cdt

    tri = cdt.Triangulation(cdt.VertexInsertionOrder.AUTO,
                            cdt.IntersectingConstraintEdges.NOT_ALLOWED, 0.0)
    tri.insert_vertices(np.ascontiguousarray(pts))
    tri.insert_edges(cons)
    return cdt, tri


def _inner_points(uv, cons, angle):
    """(k, 2) the points PythonCDT's refinement at ``angle`` [deg] puts strictly inside the
    loop ``cons`` (those on its pieces dropped), or None where it refuses."""
    a, b = uv[cons[:, 0]], uv[cons[:, 1]]
    piece = np.linalg.norm(b - a, axis=1)
    try:
        cdt, tri = _triangulation(uv, cons)
        outer = tri.collect_outer_triangles_and_holes()
        tri.refine_triangles(BUDGET * len(uv), cdt.RefinementCriterion.SMALLEST_ANGLE,
                             np.radians(angle), outer, 0.5 * float(piece.min()))
    except (RuntimeError, ValueError):
        return None
    p = tri.vertices_array()
    new = np.stack([p["x"], p["y"]], axis=1)[SUPER + len(uv):]
    off = _piece_distance(new, a, b) > 1e-9 * float(np.ptp(uv, axis=0).max())
    return new[off]


def _cdt(pts, cons):
    """Triangles (ids into ``pts``) of the constrained Delaunay triangulation inside the
    loop ``cons``, or None where PythonCDT refuses it."""
    try:
        _, tri = _triangulation(pts, cons)
        tri.remove_triangles(tri.collect_outer_triangles_and_holes())
    except (RuntimeError, ValueError):
        return None
    if tri.vertices_count() - SUPER != len(pts):
        return None
    return tri.triangles_array()["vertices"].astype(np.int64) - SUPER


def _piece_distance(q, a, b):
    """(k,) distance of each point ``q`` to the nearest segment (a, b)."""
    if not len(q):
        return np.zeros(0)
    d = b - a
    dd = np.maximum((d * d).sum(axis=1), 1e-300)
    s = np.clip(((q[:, None] - a[None]) * d[None]).sum(axis=2) / dd[None], 0.0, 1.0)
    return np.linalg.norm(q[:, None] - a[None] - s[..., None] * d[None], axis=2).min(axis=1)
