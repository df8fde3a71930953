"""Re-triangulate an assembled surface for triangle quality, keeping it closed and exact.

The assembled surface (:func:`juncture.surface.assemble.assemble`) uses the networks' own
points: long, thin quads along the span and slivers where seams meet. Each patch (the
connected part of one network or cap) is cut open into a disc where it is a tube and
flattened conformally (:mod:`juncture.surface.chart`); its boundary edges become
constraints and every vertex on it is kept, so intersection and fillet points stay
vertices and the seams stay shared (so is every inner vertex but one a fiftieth of the
median edge from another: :mod:`juncture.surface.patches`; seam points:
:mod:`juncture.surface.splits`). In the chart a constrained Delaunay triangulation
(PythonCDT) is refined until every triangle's smallest angle reaches ``min_angle`` (and,
with ``edge_length``, its area that of an equilateral triangle of that edge); triangles that
cut across a curved surface (centre more than ``tolerance`` off it, the surface turning
by more than ``turn`` under them, or an edge cutting the exact surface by more than
``curvature`` degrees or ``depth`` of its size) get their centre as a new point (in a
round that adds seam points, before the patch has come to this check, those clear of the
boundary and more than ``tolerance`` off, but not over thin input triangles: a patch whose
seams split every round came to it only in the rounds that do not refine). New
interior points are taken back onto the patch's triangles, which lie on juncture's networks,
and lifted onto the exact surface where there is one (:mod:`juncture.surface.lift`).

A thin cap (a blunt trailing edge's strip) is not charted: its sides are split to a few
times its width and it is zipped again at the end (:mod:`juncture.surface.strips`), with
points inside where the zip leaves slivers (:mod:`juncture.surface.strip_fill`). Next to
a boundary piece shorter than the chart's usual shortest edge (such a split side), refinement
may go down to half that piece, so the surface beside it grades down instead of fanning.

Refinement splits boundary edges that new points would encroach. A split point is made once,
on the 3-D edge at the same fraction, and every patch that has the edge (the neighbour across
a seam, the other side of a cut) takes it in the next round. The rounds after the refining
ones (``ROUNDS`` - ``REFINING``) do not refine: for the triangles under ``SETTLE`` degrees
all but the last add the circumcentres that lie inside and encroach no boundary piece (no
seam points), the first ``SPLITTING`` of them also split the pieces the others encroach
(Ruppert's rule), the last adds none; a patch that cannot be charted keeps its triangles
and takes split points as fans. So the seams
stay bit-identical and the surface closed, by construction.
"""

from __future__ import annotations

import numpy as np

from .deviation import Shape, chords, deviating, on_surface, oversized
from .mirror import copy_triangles, mirror_map, symmetrise
from .outside import interior_points, outside_splits
from .patch_roles import TAPER, sorted_patches  # noqa: F401  (TAPER: remesh.TAPER)
from .patches import SHORTEST, SUPER
from .sizing import size_field
from .splits import Splits, edge_points, fans, seam_lift

__all__ = ["remesh", "MIN_ANGLE", "ROUNDS", "TOLERANCE", "TURN"]

#: Default smallest angle [deg] the charts are refined to.
MIN_ANGLE = 25.0
#: Triangulate a patch with a mirror image once and copy it (:mod:`juncture.surface.mirror`).
MIRROR = True
#: Triangulation rounds: REFINING rounds of PythonCDT's refinement, then rounds that settle
#: the triangles left under SETTLE deg (seams split in the last refining rounds fan their
#: neighbours): SPLITTING of them split the pieces that such triangles' circumcentres
#: encroach or lie beyond (:func:`~juncture.surface.outside.outside_splits`), and all but
#: the last add the circumcentres that encroach none
#: (:func:`~juncture.surface.outside.interior_points`); the last takes what it gets. (At
#: ``min_angle`` instead of SETTLE they re-triangulated three times the patches, the
#: transport's re-triangulation took 19 % longer, and more seam splits near sharp corners
#: of the charts left more slivers there than they mended.)
ROUNDS = 14
REFINING = 9
SPLITTING = 2
#: Refining rounds added after the size field's (:mod:`juncture.surface.sizing`).
GRADED = 3
SETTLE = 10.0
#: Default largest distance of a triangle's centre from the surface, share of the size.
TOLERANCE = 1e-4
#: Default largest turn [deg] of the surface under one new triangle.
TURN = 12.0
#: Points refinement may add to a chart in all, per point it had and per split point on its
#: edges (:func:`_budget`; a thin trailing edge's wedge would take points without end).
BUDGET = 30
#: Default largest turn [deg] of an exact surface under one new edge, measured by its
#: midpoint's sag (:func:`~juncture.surface.deviation.bent`): the inscribed polygon of a
#: circle at this spacing holds sin(a) / a of its area (0.7 % short at 12 deg, 0.5 % at
#: 10). None: no such limit (the networks' own spacing and ``tolerance`` decide; 10 deg
#: takes the transport from 0.67 % to 0.60 % short of its model's volume at twice the
#: triangles).
CURVATURE = None
#: Default largest sag of a new edge, share of the size of the exact surface under it
#: (:func:`~juncture.surface.deviation.bent`; a wing's PCHIP section between its
#: ordinates): the enclosed volume is short by about twice this share. None: no such
#: limit (it costs many triangles).
DEPTH = None
#: Refinement makes no edge shorter than a chart's SHORTEST share of its median edge, or
#: PIECE times its shortest boundary piece (a seam split to a thin strip's spacing) where
#: that is shorter, down to FINEST times its median edge (a wing given by two sections has
#: edges the span long: at 1e-3 it could not grade down to a strip's pieces along its
#: trailing edge and fanned them, 1,900 triangles under 5 deg on each side).
PIECE = 0.5
FINEST = 1e-4
#: A patch no larger than this share of the surface's size keeps its triangles (a fuselage's
#: base given as a section 1e-4 ft across, a point rounded to the card's last digit: refined,
#: its cap took 88,000 triangles a few nanometres across, and the self-intersection check
#: ran out of memory).
TINY = 1e-5
#: A triangle with a 3-D angle under this [deg] loses the vertex opposite
#: its longest edge where refinement put it there (:func:`_drop_flat_apexes`).
FLAT3D = 6.0


def _inputs(patch, splits):
    """Chart points (originals, then split points, then interior points), their global ids,
    the constraint pieces (the boundary with its split points, chart ids), the pieces'
    original edges (global ids) and the fractions of their ends along them (``parent``:
    four arrays), and whether each piece is free (its split points stay on the straight
    edge, not lifted)."""
    keep = np.flatnonzero(patch.kept)
    where = np.cumsum(patch.kept) - 1
    i, j = patch.edges[:, 0], patch.edges[:, 1]
    gi, gj = patch.ids[i], patch.ids[j]
    count = np.zeros(len(i), np.int64)
    t, sid = [np.zeros(0)], [np.zeros(0, np.int64)]
    for k in [k for k, key in enumerate(_keys(patch)) if key in splits.on]:
        got = splits.along(int(gi[k]), int(gj[k]))
        count[k] = len(got[0])
        t.append(got[0])
        sid.append(got[1])
    t, sid = np.concatenate(t), np.concatenate(sid)
    edge = np.repeat(np.arange(len(i)), count + 1)            # per piece, its edge
    pos = np.arange(len(edge)) - np.repeat(np.cumsum(count + 1) - count - 1, count + 1)
    first = (np.cumsum(count) - count)[edge] + pos             # its split point, if any
    last = pos == count[edge]
    a = np.where(pos == 0, where[i][edge], len(keep) + first - 1)
    b = np.where(last, where[j][edge], len(keep) + first)
    frac = np.concatenate([t, [0.0, 1.0]])
    parent = (gi[edge], gj[edge], frac[np.where(pos == 0, -2, first - 1)],
              frac[np.where(last, -1, first)])
    on = np.repeat(np.arange(len(i)), count)
    uv = [patch.uv[keep], patch.uv[i[on]] + t[:, None] * (patch.uv[j[on]] - patch.uv[i[on]])]
    ids = [patch.ids[keep], sid]
    if patch.extra_uv:
        _drop_repeated(patch, np.concatenate(uv))
        uv.append(np.concatenate(patch.extra_uv))
        ids.append(np.concatenate(patch.extra_id))
    free = np.ones(len(i), bool) if patch.free is None else patch.free
    return (np.concatenate(uv), np.concatenate(ids), np.stack([a, b], 1).astype(np.uint32),
            parent, free[edge])


def _drop_repeated(patch, fixed):
    """Drop the patch's interior points that repeat a chart point bit for bit (one of
    ``fixed``, its boundary points, or an earlier interior point): PythonCDT refuses a
    repeated vertex, and a centre taken again where the triangles beside a piece of almost
    no length are flat can repeat one."""
    extra = np.concatenate(patch.extra_uv)
    both = np.concatenate([fixed, extra])
    z = both[:, 0] + 1j * both[:, 1]
    ordered = np.sort(z)
    if not np.any(ordered[1:] == ordered[:-1]):
        return
    _, first = np.unique(z, return_index=True)
    keep = np.zeros(len(both), bool)
    keep[first] = True
    keep = keep[len(fixed):]
    if not keep.all():
        patch.extra_uv = [extra[keep]]
        patch.extra_id = [np.concatenate(patch.extra_id)[keep]]


def _keys(patch):
    """The patch's boundary edges as (global a, global b) with a < b (made once)."""
    if patch.keys is None:
        ends = np.sort(patch.ids[patch.edges], axis=1)
        patch.keys = list(map(tuple, ends.tolist()))
    return patch.keys


def _known(patch, splits):
    """How many split points lie on the patch's boundary edges."""
    return splits.count(_keys(patch))


def _triangulate(patch, splits, vertices, refine, min_angle, area, tol, shape, split=False):
    """:func:`_triangulate_once`, again while it drops flat triangles' points; where the
    triangles without them are worse in 3-D than the ones that had them (the cavity a point
    leaves is triangulated afresh: a point dropped near a pyramid nose left a triangle of
    3.1 deg where the patch's worst had been 5.4), once more with every point and none
    dropped."""
    drop = True
    while True:
        before = patch.extra_uv, patch.extra_id
        got = _triangulate_once(patch, splits, vertices, refine, min_angle, area, tol, shape,
                                drop, split)
        if isinstance(got, float):              # dropped: the worst angle it had
            uv, ids = np.concatenate(before[0]), np.concatenate(before[1])
            gone = ~np.isin(ids, np.concatenate(patch.extra_id))
            old = patch.undo or (uv[:0], ids[:0], got)
            patch.undo = (np.concatenate([old[0], uv[gone]]),
                          np.concatenate([old[1], ids[gone]]), old[2])
            continue
        if got is True and patch.undo is not None:
            (uv, ids, worst), patch.undo = patch.undo, None
            if _worst(patch, splits) < worst:
                patch.extra_uv, patch.extra_id = patch.extra_uv + [uv], patch.extra_id + [ids]
                drop = False
                continue
        return got


def _worst(patch, splits):
    """The smallest 3-D angle [deg] of the patch's current triangles."""
    from .quality import triangle_angles

    return float(triangle_angles(splits.all(), patch.out).min(initial=180.0))


def _budget(patch, n):
    """How many points refinement may still add to a patch with ``n`` chart points now:
    :data:`BUDGET` per point it had and per split point on its edges (a trailing edge split
    to a thin strip's spacing needs points to grade away from it: a wing of four ordinates
    with a trailing edge 0.015 ft thick ran out at 30 per point of its own and left a fifth
    of its triangles under 20 deg), less those it added."""
    extra = sum(map(len, patch.extra_uv))
    on_seams = n - int(patch.kept.sum()) - extra
    return max(0, BUDGET * (len(patch.uv) + on_seams) + 200 - extra)


def _triangulate_once(patch, splits, vertices, refine, min_angle, area, tol, shape,
                      drop=True, split=False):
    """One constrained (and, with ``refine``, refined) triangulation of a patch's chart.

    New interior points are kept with the patch; new points on boundary pieces are
    registered in ``splits`` (on their original edge, at the same fraction). With ``drop``,
    in the rounds that do not refine, flat triangles' points are dropped first
    (:func:`_drop_flat_apexes`; returns the smallest angle they had). Returns True
    when the triangulation holds every point it must (it is kept in ``patch.out``), False
    when boundary points were added (triangulate again), None when PythonCDT refuses it.
    """
    import pythoncdt as cdt

    uv, ids, cons, parent, free = _inputs(patch, splits)
    n, shortest = len(uv), 0.0
    tri = cdt.Triangulation(cdt.VertexInsertionOrder.AUTO,
                            cdt.IntersectingConstraintEdges.NOT_ALLOWED, 0.0)
    try:
        tri.insert_vertices(np.ascontiguousarray(uv))
        tri.insert_edges(cons)
        outer = (_outer_and_holes(tri, cons, parent, patch) if patch.holed else
                 tri.collect_outer_triangles()) if patch.creases else \
            tri.collect_outer_triangles_and_holes()
        piece = np.linalg.norm(uv[cons[:, 0]] - uv[cons[:, 1]], axis=1).min()
        shortest = max(patch.shortest * FINEST / SHORTEST,
                       min(patch.shortest, PIECE * float(piece)))
        if refine:
            budget = _budget(patch, n)
            if area is not None:
                tri.refine_triangles(budget, cdt.RefinementCriterion.LARGEST_AREA, area,
                                     outer, shortest)
            tri.refine_triangles(budget, cdt.RefinementCriterion.SMALLEST_ANGLE,
                                 np.radians(min_angle), outer, shortest)
        tri.remove_triangles(outer)
    except (RuntimeError, ValueError):
        return None
    if tri.vertices_count() - SUPER < n:
        return None
    pts = tri.vertices_array()
    pts = np.stack([pts["x"], pts["y"]], 1)[SUPER:]
    on_edge = edge_points(tri, n, cons, parent, uv, pts)
    gid = np.concatenate([ids, np.full(len(pts) - n, -1)])
    for v, (gi, gj, t) in on_edge.items():
        gid[v] = splits.split(gi, gj, t)
    splits.settle()
    inner = np.setdiff1d(np.arange(n, len(pts)), np.fromiter(on_edge, int, len(on_edge)))
    if len(inner):
        gid[inner] = splits.add_vertex(on_surface(patch, vertices, pts[inner])[0])
        patch.extra_uv.append(pts[inner])
        patch.extra_id.append(gid[inner])
    local = tri.triangles_array()["vertices"].astype(np.int64) - SUPER
    boundary = np.zeros((len(pts), 2), bool)       # on the boundary, on a free piece
    boundary[cons.ravel(), 0] = True
    boundary[cons[free].ravel(), 1] = True
    if on_edge:
        # Seam points were added: triangulate again. Where refinement splits a patch's seams
        # every round, it never came to the shape check below before the rounds that do not
        # refine, and its triangles were left flat across a curved surface (a wing of four
        # ordinates 0.58 ft off its PCHIP sections over 40 % of its chord). Until it has
        # come to that check its triangles clear of the boundary are checked here, for
        # their distance from the surface only (for turns too, triangles near a wing root's
        # leading edge split without end; in every such round, not only until then, patches
        # checked early split their seams in every later round and never came to the turns:
        # a fuselage block coarser, 0.06 % of the volume), and not where surfaces crossed
        # (held: left on the assembled triangles). Nor over thin input triangles
        # (deviation.THIN): beside a fuselage's pointed nose such points left slivers.
        inside = ~boundary[local, 0].any(axis=1)
        if refine and tol is not None and inside.any() and not (patch.held or patch.checked):
            _add_points(patch, splits, vertices, deviating(patch, splits, vertices, pts, gid,
                                                           local[inside], tol, shape,
                                                           boundary, far_only=True))
        return False
    # pieces beyond thin triangles' circumcentres (in the settling rounds also the pieces
    # they encroach) are split, and the round goes on to the shape check (returning to
    # triangulate again, the patch came to it less often: 5 % fewer triangles, its volume
    # further from the union's)
    more = outside_splits(pts, local, cons, parent, min_angle if refine else
                          min(min_angle, SETTLE), shortest, split) if refine or split else ()
    for gi, gj, t in more:
        splits.split(gi, gj, t)
    if more:
        splits.settle()
    worst = _drop_flat_apexes(patch, splits, gid, local) if drop and not refine else None
    if worst is not None:
        return worst         # no seam points are added now: triangulate again at once
    far = deviating(patch, splits, vertices, pts, gid, local, tol, shape, boundary)
    patch.checked |= bool(refine and tol is not None)
    if tol is not False:
        far = np.concatenate([far, chords(patch, splits, vertices, pts, gid, local,
                                           boundary)])
    if refine:
        far = np.concatenate([far, oversized(splits, pts, gid, local, shape.size)])
    if not refine and tol is None:
        far = np.concatenate([far, interior_points(pts, local, cons, min(min_angle, SETTLE),
                                                   shortest)])
    if _add_points(patch, splits, vertices, far) or more:
        return False
    patch.out, patch.pts, patch.local = gid[local], pts, local
    return True


def _outer_and_holes(tri, cons, parent, patch):
    """The triangles of ``tri`` (constrained by the pieces ``cons``, not yet refined) outside
    the patch's boundary or in its holes: those an even number of boundary pieces away from
    the outside. Its inner kept edges (the last ``patch.creases`` of ``patch.edges``) are
    constraints too but no boundary: PythonCDT's own depths count them, and a curve across
    the patch (a wing's root in a wing-body network, from its leading to its trailing edge)
    made the part beyond it a hole."""
    import pythoncdt as cdt

    inner_keys = {(min(a, b), max(a, b)) for a, b in
                  patch.ids[patch.edges[len(patch.edges) - patch.creases:]].tolist()}
    inner = np.array([(min(a, b), max(a, b)) in inner_keys
                      for a, b in zip(parent[0].tolist(), parent[1].tolist())], bool)
    bound = {(min(a, b), max(a, b)) for a, b in (cons[~inner].astype(np.int64)
                                                  + SUPER).tolist()}
    pieces = tri.piece_to_originals
    crossing = set()
    for e in tri.fixed_edges:
        if any((min(o.v1, o.v2), max(o.v1, o.v2)) in bound for o in pieces.get(e, [e])):
            crossing.add((min(e.v1, e.v2), max(e.v1, e.v2)))
    t = tri.triangles_array()
    v, nb = t["vertices"].astype(np.int64), t["neighbors"].astype(np.int64)
    parity = np.full(len(v), -1)
    todo = list(tri.collect_outer_triangles())
    parity[todo] = 0
    while todo:
        k = todo.pop()
        for n in nb[k].tolist():
            if n == cdt.NO_NEIGHBOR or n >= len(v) or parity[n] >= 0:
                continue
            a, b = sorted(set(v[k].tolist()) & set(v[n].tolist()))
            parity[n] = parity[k] ^ ((a, b) in crossing)
            todo.append(n)
    return set(np.flatnonzero(parity != 1).tolist())


def _add_points(patch, splits, vertices, far):
    """Add the chart points ``far`` to the patch as interior points (but those on a vertex
    or on one another, :func:`_new_places`); whether any was added."""
    if len(far):
        far, xyz = _new_places(patch, splits, far, on_surface(patch, vertices, far)[0])
    if not len(far):
        return False
    patch.extra_uv.append(far)
    patch.extra_id.append(splits.add_vertex(xyz))
    return True


def _new_places(patch, splits, uv, xyz):
    """The chart points ``uv`` (3-D ``xyz``) but those that fall on a vertex of the surface
    or on one another in 3-D (within :data:`TINY` of a millionth of the patch's size): where
    the chart spreads what the surface holds at one place (the rows converging on a pointed
    tail), a triangle's centre taken as a new point could land on a point there already,
    and the two made triangles of no size (0 deg on a held-out arbitrary fuselage)."""
    from scipy.spatial import cKDTree

    near = 1e-6 * TINY * patch.size
    every = splits.all()          # any patch's (a piece of the same surface holds them too)
    box = np.all((every >= xyz.min(axis=0) - near) & (every <= xyz.max(axis=0) + near), axis=1)
    have = every[box]
    clear = (cKDTree(have).query(xyz, distance_upper_bound=near)[0] > near) if len(have) \
        else np.ones(len(xyz), bool)
    first = np.zeros(len(xyz), bool)
    first[np.unique(np.round(xyz / max(near, 1e-300)), axis=0, return_index=True)[1]] = True
    keep = clear & first
    return uv[keep], xyz[keep]


def _drop_flat_apexes(patch, splits, gid, local):
    """In the rounds that add no seam points: drop the interior points (added by this
    patch's refinement) opposite the longest edge of a triangle flat in 3-D (a seam point
    that came late, lifted onto the surface beside a point put there before, or points
    crowded where the chart stretches); if any was dropped, the smallest 3-D angle the
    triangles had (the patch is triangulated again without them at once, each time with
    fewer points), else None."""
    from .quality import triangle_angles

    if not patch.extra_id:
        return None
    angles = triangle_angles(splits.all(), gid[local])
    rows = np.flatnonzero(angles.min(axis=1) < FLAT3D)
    if not len(rows):
        return None
    apex = local[rows, np.argmax(angles[rows], axis=1)]     # opposite the longest edge
    ids = np.concatenate(patch.extra_id)
    drop = np.intersect1d(gid[apex], ids)
    if not len(drop):
        return None
    keep = ~np.isin(ids, drop)
    patch.extra_uv = [np.concatenate(patch.extra_uv)[keep]]
    patch.extra_id = [ids[keep]]
    return float(angles.min())


def _split_shared_chords(charted, splits, vertices):
    """Split the edges that two patches both make inside themselves (each edge of the
    triangulations in more than two triangles): its chart midpoint joins each such patch
    as an inner point and the patch is triangulated again. Two patches whose boundaries
    share two points can each join them by the same chord where their surfaces nearly
    meet there (a wing's upper and lower surfaces at a tip of no chord, between a point on
    the leading edge and one on the trailing edge): four triangles on one edge."""
    done = [p for p in charted if p.out is not None and p.local is not None]
    if not done:
        return
    n = len(splits.all())
    def edges(t):
        return np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])

    rows = [edges(p.local) for p in done]            # chart ids, edge by edge as ...
    keys = [np.sort(edges(p.out), axis=1) for p in done]     # ... the global ones
    flat = [k[:, 0] * n + k[:, 1] for k in keys]
    every, uses = np.unique(np.concatenate(flat), return_counts=True)
    many = every[uses > 2]
    if not len(many):
        return
    for patch, key, ends in zip(done, flat, rows):
        mine, count = np.unique(key[np.isin(key, many)], return_counts=True)
        inside = mine[count == 2]             # in two of this patch's triangles
        if not len(inside):
            continue
        order = np.argsort(key, kind="stable")
        mid = patch.pts[ends[order[np.searchsorted(key[order], inside)]]].mean(axis=1)
        patch.extra_uv.append(mid)
        patch.extra_id.append(splits.add_vertex(on_surface(patch, vertices, mid)[0]))
        patch.seen = -1


def remesh(mesh, min_angle=MIN_ANGLE, edge_length=None, tolerance=TOLERANCE,
           turn=TURN, keep=(), lift=None, curvature=CURVATURE, depth=DEPTH, lines=None,
           held=None, frozen=None, crossings=None, growth=None, seam_size=None):
    """A :class:`~juncture.surface.assemble.SurfaceMesh` of the same closed surface with
    triangles of at least ``min_angle`` degrees wherever the patches' corners allow, and,
    with ``edge_length``, no triangle larger than an equilateral one of that edge.

    Every vertex of ``mesh`` on a patch's boundary stays a vertex (intersection and fillet
    points included), and every inner one but those
    :data:`~juncture.surface.patches.NEAR` another; new
    points lie on its triangles. A new triangle's centre lies within ``tolerance`` times the
    mesh's size of them, and the input triangles under its corners and centre turn by no
    more than ``turn`` degrees (so it spans no more of a curved body's facets than the
    networks' own spacing). The surfaces in ``keep`` (indices into ``mesh.surfaces``) keep
    their triangles, taking their neighbours' seam points as fans. The triangles ``held``
    ((m,) bool over ``mesh.triangles``; where re-triangulated surfaces crossed) are charted
    apart from the rest of their patch and re-triangulated with their new points left on
    them, not lifted (the assembled surface does not cross itself); the triangles
    ``frozen`` (the same) keep theirs, taking seam points as fans. See the module docstring
    for how seams stay shared. ``lift(points, corners, component, surface)`` (e.g.
    :func:`juncture.surface.lift.body_lift`) moves new points from the triangle with vertex
    ids ``corners`` onto the exact surface; a seam point only where both sides lift it to the
    same place (a split within one body), never on an intersection line. On an exact surface
    a new edge turns by at most ``curvature`` degrees and, with ``lift.both`` (the surface's
    size at the points, :func:`juncture.surface.lift.surface_lift`), stands off it by at most
    ``depth`` times that size (:func:`~juncture.surface.deviation.bent`): the enclosed
    volume converges as both shrink. With ``growth`` or ``seam_size``, triangles are no
    larger than a size field that is ``seam_size`` on the lines where components meet and
    grows away from them and from the seams' shortest pieces by at most ``growth``
    (:func:`~juncture.surface.sizing.size_field`).
    ``lines`` ((n,) bool or int: 1 on intersection lines): a network is cut into patches
    where it turns at a crease between such points (:data:`~juncture.surface.patches.CREASE`);
    its edges between two vertices marked :data:`~juncture.surface.creases.CORNER_LINE` (an
    arbitrary section's corners) that turn are kept
    (:func:`~juncture.surface.creases.mark_creases`).
    """
    from ..errors import GeometryError
    from .assemble import SurfaceMesh
    from .strips import zipped_all

    splits = _splits(mesh, lift)
    size = float(np.ptp(mesh.vertices, axis=0).max())
    tol = None if tolerance is None else tolerance * size
    charted, kept, strips, copied = sorted_patches(mesh, keep, lift, splits, min_angle,
                                                  lines, TINY * size, (held, frozen),
                                                  crossings)
    field = size_field(mesh, growth, seam_size, edge_length, lines)
    graded = Shape(np.cos(np.radians(turn)), None if curvature is None else
                   np.radians(curvature), depth, field)
    # a size field splits in the first REFINING rounds; GRADED more refining rounds then
    # let the other rules settle where it added points (without them a nose lost 1 % of
    # its volume)
    refining = REFINING + (GRADED if field is not None else 0)
    rounds = ROUNDS + refining - REFINING
    for rnd in range(rounds):
        # refine and split for shape; then split the pieces thin triangles encroach, then
        # only points inside (no seam points), the last round taking what it gets
        refine = rnd < refining
        rule = tol if refine else (None if rnd < rounds - 1 else False)
        split = refining <= rnd < refining + SPLITTING
        shape = graded if rnd < REFINING else graded._replace(size=None)
        for patch in charted:
            known = _known(patch, splits)
            if patch.out is not None and patch.seen == known:
                continue
            area = _area(patch, mesh.vertices, edge_length)
            done = _triangulate(patch, splits, mesh.vertices, refine, min_angle, area, rule,
                                shape, split)
            if done is None:
                raise GeometryError(f"the chart of {mesh.surfaces[patch.surface]} could "
                                    "not be triangulated")
            patch.seen = known if done else -1
        if rnd < rounds - 1:
            _split_shared_chords(charted, splits, mesh.vertices)
    tris, comp, surf = [], [], []
    for patch in charted:
        if patch.out is None or patch.seen != _known(patch, splits):
            raise GeometryError(f"{mesh.surfaces[patch.surface]} was not triangulated with "
                                "its seam points")
        tris.append(patch.out)
        comp.append(np.full(len(patch.out), patch.component))
        surf.append(np.full(len(patch.out), patch.surface))
    pieces = [(fans(mesh.triangles[rows], splits), rows) for rows in kept]
    pieces += [(np.concatenate([copy_triangles(p, splits) for p in primary]), rows)
               for rows, primary in copied]
    pieces += zipped_all(strips, splits, min_angle)
    for t, rows in pieces:
        tris.append(t)
        comp.append(np.full(len(t), mesh.component[rows[0]]))
        surf.append(np.full(len(t), mesh.surface[rows[0]]))
    if splits.mirror is not None:
        symmetrise(splits)
    return SurfaceMesh(splits.all(), np.concatenate(tris), np.concatenate(comp),
                       np.concatenate(surf), mesh.components, mesh.surfaces, mesh.open_loops)


def _splits(mesh, lift):
    """The :class:`~juncture.surface.splits.Splits` of a re-triangulation: with both halves'
    points matched (:mod:`juncture.surface.mirror`) where the surface has mirror images
    and :data:`MIRROR` is on."""
    vertices = np.asarray(mesh.vertices, float)
    mirror = mirror_map(vertices) if MIRROR else None
    if mirror is None or not np.any(mirror != np.arange(len(mirror))):
        return Splits(vertices, seam_lift(mesh, lift))
    t = np.asarray(mesh.triangles)
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    return Splits(vertices, seam_lift(mesh, lift), mirror,
                  set(zip(e[:, 0].tolist(), e[:, 1].tolist())))


def _area(patch, vertices, edge_length):
    """The chart area of an equilateral triangle of ``edge_length`` on the surface (at the
    chart's median scale)."""
    if edge_length is None:
        return None
    p = vertices[patch.ids][patch.tri]
    flat = patch.uv[patch.tri]
    a3 = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    e1, e2 = flat[:, 1] - flat[:, 0], flat[:, 2] - flat[:, 0]
    a2 = np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
    return float(np.sqrt(3.0) / 4.0 * edge_length ** 2 / np.median(a3 / a2))
