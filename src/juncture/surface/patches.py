"""The patches the re-triangulation works on, and their charts.

A patch is the connected part of one network or cap (:func:`patches`; a closed pod is
opened at its middle ring). :func:`chart` flattens it conformally
(:func:`juncture.surface.chart.lscm`) as it is (holes stay holes) or cut open into a disc (a
tube, or one that flattens onto an annulus whose scale varies more than :data:`SPREAD`);
:func:`charts` splits a patch whose chart still varies that much in halves, and
keeps what :mod:`juncture.surface.remesh` needs of it: its boundary edges (the constraints),
normals and areas, the shortest edge refinement may make and the vertices a triangulation
starts from.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .chart import disc, finder, lscm, patch_edges
from .rows import unique_points

__all__ = ["Patch", "patches", "chart", "charts", "spread", "area3", "SHORTEST", "SLIVER", "SPREAD",
           "NEAR", "SUPER", "SAMPLES", "CREASE", "taper"]

#: Refinement makes no edge shorter than this share of a chart's median edge.
SHORTEST = 0.02
#: A patch whose area is below this share of a circle's of its boundary's length is a
#: sliver: it keeps its triangles.
SLIVER = 1e-3
#: A chart with holes whose scale varies more than this (:func:`spread`) is cut open into a
#: disc instead (a tube, a pod open at both ends, maps conformally onto an annulus whose
#: scale grows exponentially along it: new triangles, straight in the chart, are not in 3-D).
SPREAD = 10.0
#: An inner vertex with an edge shorter than this share of its patch's median edge is not
#: a vertex of the re-triangulation (:func:`_kept`).
NEAR = 0.02
#: Samples of a patch's free boundary pieces in the k-d tree that finds the points near them.
SAMPLES = 4000
#: A patch charted with a larger spread is split in halves at most this many times ...
SPLITS = 3
#: ... each with at least this many triangles.
MINIMUM = 8
#: Triangles of one network whose normals turn by more than this [deg] across an edge
#: between two intersection points are in different patches (the edge a seam between them):
#: a layout that makes the wing and the fuselage one network turns 120 deg at their
#: junction, and triangles refined across it cut through the surface. (Elsewhere a network
#: may turn as fast between its stations: a body block whose columns twist between two
#: stations.)
CREASE = 60.0
#: ... along a line of such edges at least this share of the network's extent long.
CREASE_LINE = 0.05
SUPER = 3  # PythonCDT keeps its super-triangle's 3 vertices first until finalised


@dataclass(eq=False)
class Patch:
    ids: np.ndarray                      # global vertex id of every chart vertex
    tri: np.ndarray                      # chart triangles (local ids)
    uv: np.ndarray                       # chart coordinates
    edges: np.ndarray                    # boundary edges (local ids), in the loop's order
    component: int
    surface: int
    normals: np.ndarray | None = None    # unit normals of the chart triangles (3-D)
    areas: np.ndarray | None = None      # 3-D areas of the chart triangles
    size: float = 0.0                    # the patch's extent
    find: object = None                  # the chart's point locator
    shortest: float = 0.0                # no edge shorter is made by refinement (chart)
    kept: np.ndarray | None = None       # chart vertices triangulated (not NEAR others)
    extra_uv: list = field(default_factory=list)   # interior points added, chart coords
    extra_id: list = field(default_factory=list)
    seen: int = -1                       # split points known at the last triangulation
    out: np.ndarray | None = None        # current triangles (global ids)
    lift: object = None                  # lift(points, corners, component, surface)
    free: np.ndarray | None = None       # boundary edges whose split points stay on them
    near: tuple | None = None            # (k-d tree of samples of the free edges, spacing / 2,
    #                                      each sample's slope and sag)
    slope: np.ndarray | None = None      # per boundary edge: how steeply a lift may rise from it
    valley: np.ndarray | None = None     # per boundary edge: how steeply one outwards may
    keys: list | None = None             # boundary edges as (global a, global b), a < b
    spread: float = 1.0                  # how much the chart's scale varies (spread())
    pts: np.ndarray | None = None        # chart coordinates of the current triangulation's
    local: np.ndarray | None = None      # vertices, and its triangles over them
    undo: tuple | None = None            # dropped points (chart, ids), worst angle before
    xyz: np.ndarray | None = None        # 3-D points of the chart vertices (assembled)
    creases: int = 0                     # inner edges kept (juncture.surface.creases)
    holed: bool = False                  # has inner edges and more than one boundary loop
    checked: bool = False                # came to the shape check in a refining round
    held: bool = False                   # charted from triangles held where surfaces crossed
    memo: dict = field(default_factory=dict)   # per-triangle answers kept (surface.memo)


def patches(mesh, lines=None):
    """Connected parts of every surface id, as (global triangle rows); with ``lines`` ((n,)
    bool: the vertices on intersection lines) not connected across a crease between two
    such points (:data:`CREASE`)."""
    out = []
    for s in np.unique(mesh.surface):
        crease = None if mesh.surfaces[s].endswith(" cap") else lines  # a cap: strips
        for rows in _connected(mesh, np.flatnonzero(mesh.surface == s), crease):
            out.extend(_opened(mesh, rows))
    return out


def _connected(mesh, rows, lines=None):
    """The triangle ``rows`` as their parts connected through edges, but not across a
    crease between two vertices marked in ``lines`` (:data:`CREASE`)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    t = mesh.triangles[rows]
    _, und, uses, inverse = patch_edges(t)
    owner = np.tile(np.arange(len(t)), 3)
    order = np.argsort(inverse, kind="stable")
    inv, own = inverse[order], owner[order]
    same = inv[1:] == inv[:-1]
    a, b = own[:-1][same], own[1:][same]
    smooth = np.ones(len(a), bool) if lines is None else _smooth(mesh, t, a, b,
                                                                 und[inv[:-1][same]], lines)
    g = coo_matrix((np.ones(smooth.sum()), (a[smooth], b[smooth])), shape=(len(t), len(t)))
    count, label = connected_components(g, directed=False)
    return [rows[label == k] for k in range(count)]


def _smooth(mesh, t, a, b, ends, lines):
    """(k,) whether the triangles ``a`` and ``b`` of ``t`` stay connected across their
    edges ``ends`` (k, 2): unless the edge joins two points of ``lines``, their normals turn
    by more than :data:`CREASE` there, and the edge lies on a long line of such creases."""
    p = mesh.vertices[t]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    size = np.linalg.norm(n, axis=1)
    n /= np.maximum(size, 1e-300)[:, None]
    smooth = (np.einsum("ij,ij->i", n[a], n[b]) >= np.cos(np.radians(CREASE))) \
        | (size[a] == 0.0) | (size[b] == 0.0) | ~lines[ends].all(axis=1)
    if not smooth.all():
        smooth |= _short_creases(mesh.vertices[ends], t, ~smooth, mesh.vertices)
    return smooth


def _short_creases(ends, t, crease, vertices):
    """(k,) which of the edges ``ends`` (k, 2, 3) marked ``crease`` lie on a line of creases
    shorter than :data:`CREASE_LINE` of the triangles' extent: a sliver between two stations
    a few thousandths apart stands across the surface and is no crease of it."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    k = np.flatnonzero(crease)
    pts, ids = unique_points(ends[k].reshape(-1, 3) + 0.0, return_inverse=True)
    ids = ids.reshape(-1, 2)
    count, label = connected_components(
        coo_matrix((np.ones(len(k)), (ids[:, 0], ids[:, 1])), shape=(len(pts),) * 2),
        directed=False)
    length = np.linalg.norm(ends[k, 0] - ends[k, 1], axis=1)
    line = np.bincount(label[ids[:, 0]], length, minlength=count)
    extent = float(np.ptp(vertices[np.unique(t)], axis=0).max())
    out = np.zeros(len(ends), bool)
    out[k] = line[label[ids[:, 0]]] < CREASE_LINE * extent
    return out


def _opened(mesh, rows):
    """A closed part (a pod pointed at both ends: no boundary, so no disc to chart) as its
    two halves (:func:`_halves`). Any other part as it is."""
    _, _, uses, _ = patch_edges(mesh.triangles[rows])
    if len(rows) < 8 or np.any(uses != 2):
        return [rows]
    return _halves(mesh, rows) or [rows]


def _halves(mesh, rows):
    """The triangles ``rows`` as their two halves on either side of the ring of vertices
    nearest their middle along their longest axis (the ring's edges become a seam between
    them), or None where one side would be empty."""
    t = mesh.triangles[rows]
    p = mesh.vertices[np.unique(t)]
    axis = int(np.argmax(np.ptp(p, axis=0)))
    c = mesh.vertices[:, axis]
    ring = p[np.argmin(np.abs(p[:, axis] - np.median(p[:, axis]))), axis]
    low = (c[t] <= ring).all(axis=1)
    if low.all() or not low.any():
        return None
    return [rows[low], rows[~low]]


def charts(mesh, rows, depth=None, kept=None):
    """The :class:`Patch` charts of the triangles ``rows``, or None if they cannot be
    charted: one (:func:`chart`), or where its scale varies more than :data:`SPREAD`
    (a pod pointed at both ends with a pylon's or wing's footprint cut out of it charts as a
    disc whose far end LSCM squeezes to a point: straight chart triangles there cross in
    3-D) or it does not chart at all (LSCM folds a triangle where a wing's upper surface
    turns down to its leading edge beside a fillet) the charts of its halves
    (:func:`_halves`), each split again the same way, at most :data:`SPLITS` times, as long
    as every piece charts.

    With a list ``kept``, a patch that does not chart at all is charted piece by piece: the
    rows of each piece that still does not chart (the slivers of a fuselage tapering to a
    section a rounding's size across, whose flat triangles LSCM folds) are appended to it,
    the others charted (the result may be empty)."""
    depth = SPLITS if depth is None else depth
    patch = chart(mesh, rows)
    if depth == 0 or (patch is not None and patch.spread <= SPREAD):
        return _leaf(patch, rows, kept)
    parts = [part for half in _halves(mesh, rows) or [] for part in _connected(mesh, half)]
    if len(parts) < 2 or min(map(len, parts)) < MINIMUM:
        return _leaf(patch, rows, kept)
    out, held = [], ([] if patch is None and kept is not None else None)
    for part in parts:
        got = charts(mesh, part, depth - 1, held)
        if got is None:
            return None if patch is None else [patch]
        out.extend(got)
    if held:
        kept.extend(held)
    return out


def _leaf(patch, rows, kept):
    """:func:`charts` of a piece not split further: its chart, else (with ``kept``) none,
    its rows kept."""
    if patch is not None:
        return [patch]
    if kept is None:
        return None
    kept.append(rows)
    return []


def chart(mesh, rows):
    """A :class:`Patch` of the triangles ``rows``, or None if it cannot be charted: flat as
    it is (holes stay holes), else cut open into a disc (a tube, also where it charts as an
    annulus whose scale varies more than :data:`SPREAD`)."""
    t = mesh.triangles[rows]
    used, local = np.unique(t, return_inverse=True)
    local = local.reshape(t.shape)
    if _sliver(mesh.vertices[used], local):
        return None
    annulus = None
    for cut in (False, True):
        got = disc(local, len(used)) if cut else (local, np.arange(len(used)))
        chart = None if got is None else _flattened(mesh, used, *got)
        if chart is None:
            continue
        tri, _, uv, _, cross, loops, _ = chart
        if not cut and loops > 1 and spread(uv[tri], np.linalg.norm(cross, axis=1)) > SPREAD:
            annulus = chart           # a tube charted as an annulus: cut it open if it can be
            continue
        return _patch(mesh, rows, *chart)
    return None if annulus is None else _patch(mesh, rows, *annulus)


def _flattened(mesh, used, tri, parent):
    """(tri, ids, uv, boundary edges, area vectors (twice), number of boundary loops, point
    locator) of a chart of the local triangles ``tri`` over the vertices ``used[parent]``,
    or None (no boundary, folded or crossing itself: its boundary, or triangles inside that
    the point locator finds overlapping)."""
    from .assemble import boundary_loops

    ids = used[parent]
    loops = boundary_loops(tri)
    if not loops:
        return None
    uv = lscm(mesh.vertices[ids], tri)
    edges = np.concatenate([np.stack([lp, np.roll(lp, -1)], 1) for lp in loops])
    if uv is None or not _embedded(uv, edges):
        return None
    find = finder(uv, tri)
    if find is None:
        return None
    p = mesh.vertices[ids][tri]
    return (tri, ids, uv, edges, np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), len(loops),
            find)


def _patch(mesh, rows, tri, ids, uv, edges, cross, _, find):
    p = mesh.vertices[ids][tri]
    double = np.linalg.norm(cross, axis=1)
    return Patch(ids, tri, uv, edges, int(mesh.component[rows[0]]),
                  int(mesh.surface[rows[0]]), cross / double[:, None], 0.5 * double,
                  float(np.ptp(p.reshape(-1, 3), axis=0).max()), find,
                  _shortest(uv, tri), _kept(mesh.vertices[ids], tri, edges),
                  spread=spread(uv[tri], double), xyz=mesh.vertices[ids])


def spread(flat, double):
    """How much a chart's scale varies: the ratio of the 95th to the 5th percentile of its
    triangles' chart area over their 3-D area (``double``: twice the 3-D areas)."""
    e1, e2 = flat[:, 1] - flat[:, 0], flat[:, 2] - flat[:, 0]
    ratio = np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]) / np.maximum(double, 1e-300)
    lo, hi = np.quantile(ratio, [0.05, 0.95])
    return hi / lo if lo > 0.0 else np.inf


def _kept(points, tri, edges):
    """(n,) bool: the chart vertices a triangulation starts from. Every boundary vertex; an
    inner one unless an edge of it is shorter than :data:`NEAR` times the patch's median
    edge (two rows of a network a few thousandths apart, where two intersection lines nearly
    share a station: kept, they leave a row of slivers that refinement cannot mend). New
    points are still taken onto the patch's own triangles, so the surface is the same."""
    e = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    length = np.linalg.norm(points[e[:, 0]] - points[e[:, 1]], axis=1)
    short = length < NEAR * np.median(length)
    out = np.ones(len(points), bool)
    out[e[short].ravel()] = False
    out[edges.ravel()] = True
    return out


def _shortest(uv, tri):
    """The shortest edge refinement may make in a chart: a share ``SHORTEST`` of its median
    edge. Near a corner of tiny angle (a thin trailing edge's wedge) refinement stops there
    instead of grading down without end (and using up the points the rest needs)."""
    e = np.linalg.norm(uv[tri] - uv[np.roll(tri, 1, axis=1)], axis=2)
    return SHORTEST * float(np.median(e[e > 0]))


def _sliver(points, tri):
    """Whether a patch is a sliver (a cap closing a slit): its area below ``SLIVER`` times
    that of a circle of its boundary's length; there is nothing to refine in it."""
    from .assemble import boundary_loops

    area = area3(points[tri]).sum()
    length = sum(np.linalg.norm(points[lp] - points[np.roll(lp, -1)], axis=1).sum()
                 for lp in boundary_loops(tri))
    return length > 0 and 4.0 * np.pi * area < SLIVER * length ** 2


def _embedded(uv, edges):
    """Whether the chart's boundary edges cross nowhere (PythonCDT takes them all)."""
    import pythoncdt as cdt

    tri = cdt.Triangulation(cdt.VertexInsertionOrder.AUTO,
                            cdt.IntersectingConstraintEdges.NOT_ALLOWED, 0.0)
    try:
        tri.insert_vertices(np.ascontiguousarray(uv))
        tri.insert_edges(np.asarray(edges, np.uint32))
    except (RuntimeError, ValueError):
        return False
    return tri.vertices_count() - SUPER == len(uv)


def area3(p):
    """(k,) areas of triangles (k, 3, 3)."""
    return 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)


def taper(patch, query, move, slope, sag=None, outward=None):
    """(k,) the share of its lift (``move``, (k,)) each chart point takes. Near the patch's
    free boundary edges (``patch.free``: seams whose two sides do not lift alike, straight
    chords of an exact curve) a point is left short of its exact surface by at most the
    seam's own sag there (``sag(edges, row, t)``: the lifts, (s,), of the points at
    fractions ``t`` along the boundary edges ``edges[row]``; without it, the whole lift)
    less its distance from the edges times the slope allowed there (``patch.slope`` per
    boundary edge, else ``slope``): the step from the chord to the exact surface rises no
    steeper than that, and where the seam lies on its curve a point off it is lifted in
    full however far its assembled facet stands inside (a body block whose facets span a
    quarter of its circle). The distance is that to the nearest
    of :data:`SAMPLES` points spread along those edges (a k-d tree built once per patch)
    less half their spacing: never more than the true distance, so a point near a seam is
    never lifted further than its share. ``outward`` ((k,) bool: lifts out of the patch's
    solid): those rise no steeper than ``patch.valley`` either (a narrow valley's edges,
    :func:`juncture.surface.patch_roles.mark_slopes`)."""
    from scipy.spatial import cKDTree

    free = np.ones(len(patch.edges), bool) if patch.free is None else patch.free
    edges = patch.edges[free]
    if not len(edges):
        return np.ones(len(query))
    if patch.near is None:
        a, b = patch.uv[edges[:, 0]], patch.uv[edges[:, 1]]
        length = np.linalg.norm(b - a, axis=1)
        count = np.maximum(np.ceil(length / (length.sum() / SAMPLES + 1e-300)), 1).astype(int)
        row = np.repeat(np.arange(len(a)), count + 1)
        t = np.arange(len(row)) - np.repeat(np.cumsum(count + 1) - count - 1, count + 1)
        t = t / np.repeat(count, count + 1)
        at = a[row] + t[:, None] * (b - a)[row]
        steep = np.full(len(edges), slope) if patch.slope is None else patch.slope[free]
        valley = None if patch.valley is None else \
            np.append(np.minimum(steep, patch.valley[free])[row], np.inf)
        deep = np.full(len(at), np.inf) if sag is None else _seam_sag(sag(edges, row, t), row)
        patch.near = (cKDTree(at), 0.5 * float((length / count).max()),
                      np.append(steep[row], np.inf), np.append(deep, 0.0), valley)
    tree, half, steep, deep, valley = patch.near
    out = None if valley is None or outward is None or not np.any(outward) else outward
    reach = np.minimum(float(move.max(initial=0.0)), deep[:-1].max())
    least = steep[:-1].min() if out is None else valley[:-1].min()
    far = float(reach / least) + half                           # beyond: lifted in full
    dist, nearest = tree.query(query, distance_upper_bound=far)
    dist = np.maximum(dist - half, 0.0)
    rate = steep[nearest] if out is None else np.where(out, valley[nearest], steep[nearest])
    short = np.maximum(np.minimum(move, deep[nearest]) - dist * rate, 0.0)
    return np.clip(1.0 - short / np.maximum(move, 1e-300), 0.0, 1.0)


def _seam_sag(deep, row):
    """(s,) the lifts ``deep`` of the seam samples, each at least the largest of its edge's
    (``row``: each sample's edge; the sag is measured at samples, a point between them may
    stand further off)."""
    deep = np.asarray(deep, float)
    most = np.zeros(row.max() + 1)
    np.maximum.at(most, row, deep)
    return most[row]
