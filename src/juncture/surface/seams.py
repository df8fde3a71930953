"""Seams whose two sides carry different points of the same line, made conformal.

A layout's networks meet along intersection lines, but each side carries the points its own
grid gives: the wing's root line has a point at each of the wing's chord stations, the body
block beside it a point at each body station as well. Assembled by shared vertex ids, such a
seam leaves a thin open loop: the two chains of points between the shared ones. Each is an
exact point of the same line, so nothing is moved and nothing is welded: every boundary
edge ``a -> b`` of one component gets the other component's points that lie between ``a``
and ``b`` on the line (within a thin lens about the edge), its triangle split into a fan
through them. Both sides then carry every point of the line and the seam closes by vertex
ids.

Points of *another component* are inserted within the lens; points of the same component
only where they lie on the edge itself (within :data:`COLLINEAR` of its length: a traced
curve's trailing-edge point on the straight trailing edge between two sections). A loop
between two networks of one component that is wider than that (the blunt trailing edge
between a wing's upper and lower surfaces) is a gap of the surface, closed by
:func:`juncture.surface.assemble.strip_cap`, never folded shut.
"""

from __future__ import annotations

import numpy as np

from .rows import members

__all__ = ["LENS", "COLLINEAR", "split_seams"]

#: A point lies on a boundary edge's line when its distance from the edge is at most this share
#: of the edge's length (the seam's chord-to-curve sag; a gap between surfaces is wider).
LENS = 0.05

#: Towards its ends the lens narrows to END times the distance along the edge (a point seen
#: from an end at most atan(END) = 22 deg off the edge; a curve of sag LENS through both
#: ends leaves them at 4 LENS = 0.2, 11 deg): the point where a body cuts the lower side of a
#: blunt trailing edge lies 0.3 % of the 21 ft upper trailing edge off it, but across the
#: edge from its end (34-90 deg), and is no point of that seam; a fillet's line bending off
#: a wing's root 14 deg from its end is.
END = 0.4

#: A triangle is re-triangulated with its neighbours (:func:`_widened`) only where their
#: normals lie within this many degrees of its own: flattened further, the new triangles
#: turned over in the surface's chart (a wing with a cubic fillet, turning down to its
#: leading edge at the root, kept hundreds of slivers).
FLAT_RING = 20.0

#: The lens for a point of the edge's own component: on the edge, to round-off.
COLLINEAR = 1e-9

#: A boundary edge between two shared points takes the other side's chain between them
#: (at most WIDE_STEPS points, each within WIDE of the edge's length from it) when its lens
#: holds none of them or only some: the seam curve bends between this side's points
#: (:func:`_wide_chains`).
WIDE = 0.25
WIDE_STEPS = 16


def _boundary_edges(triangles):
    """(k, 2) directed boundary edges and (k,) the triangle each belongs to."""
    e = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    owner = np.tile(np.arange(len(triangles)), 3)
    base = int(triangles.max()) + 1
    key = e[:, 0].astype(np.int64) * base + e[:, 1]
    rev = e[:, 1].astype(np.int64) * base + e[:, 0]
    open_ = ~members(rev, key)                   # no edge runs the other way
    return e[open_], owner[open_]


def _between(p, a, b, lens, end=None):
    """(mask, t, off): which points p (k, 3) lie strictly between a and b within the lens
    (``lens`` of the edge's length off it, narrowing to its ends: ``end``, :data:`END`),
    their parameter along a -> b and their distance from it as a share of its length
    (measured only where t lies strictly between 0 and 1; inf elsewhere)."""
    d = b - a
    length2 = float(d @ d)
    if length2 == 0.0:
        return np.zeros(len(p), bool), np.zeros(len(p)), np.full(len(p), np.inf)
    t = (p - a) @ d / length2
    rows = np.flatnonzero((t > 1e-9) & (t < 1.0 - 1e-9))
    tr = t[rows]
    off = np.full(len(p), np.inf)
    off[rows] = np.linalg.norm(p[rows] - a - tr[:, None] * d, axis=1) / np.sqrt(length2)
    end = END if end is None else end
    width = lens if np.isinf(end) else np.minimum(lens, end * np.minimum(tr, 1.0 - tr))
    near = np.zeros(len(p), bool)
    near[rows] = off[rows] <= width
    return near, t, off


def _fan(tri, a, b, inserted):
    """Triangles replacing ``tri`` (which has the directed edge a -> b): a fan from its third
    corner through the points inserted between a and b."""
    k = list(tri).index(a)
    c = tri[(k + 2) % 3]
    chain = [a, *inserted, b]
    return [(chain[i], chain[i + 1], c) for i in range(len(chain) - 1)]


def _filled(vertices, triangles, t, a, b, chain):
    """(removed, new): the triangle ``t`` (with the directed edge a -> b) where its fan
    (:func:`_fan`) would fold: the polygon of the edge's points and its third corner,
    triangulated in the triangle's plane (:func:`_refilled`), or None. The chain can turn
    back as seen from the third corner (a curve that jogs towards it: across a fuselage's
    step at a joint, or a fillet's line bending off the root), and the corner no longer
    sees it in order."""
    tri = triangles[t]
    k = list(tri).index(a)
    return _refilled(vertices, triangles, [t], [a, *chain, b, int(tri[(k + 2) % 3])], chain)


def _widened(vertices, triangles, t, a, b, chain, owner):
    """(removed, new): the triangle ``t`` (with the boundary edge a -> b) and the triangles
    across its two other edges re-triangulated with the edge replaced by ``a``, ``chain``,
    ``b``, where a chain point lies beyond the triangle (:func:`_filled` is not simple):
    the curve jogs across the triangle's far edge. Only
    neighbours of the triangle's own surface (``owner``: (m,) the surface or component of
    each triangle) are taken: the new triangles are its surface's. Constrained Delaunay in
    their mean plane, no point added; None where it would fold."""
    from .assemble import boundary_loops

    tri = triangles[t]
    k = list(tri).index(a)
    c = int(tri[(k + 2) % 3])
    across = ((np.isin(triangles, [b, c]).sum(axis=1) == 2) |
              (np.isin(triangles, [c, a]).sum(axis=1) == 2)) & (owner == owner[t])
    ring = [t] + [int(r) for r in np.flatnonzero(across) if r != t]
    q = vertices[triangles[ring]]
    n = np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0])
    n /= np.linalg.norm(n, axis=1)[:, None]
    if np.min(n @ n[0]) < np.cos(np.radians(FLAT_RING)):
        return None          # a curved patch (a wing turning down to its leading edge)
    loops = boundary_loops(triangles[ring])
    if len(loops) != 1:
        return None
    border = [int(v) for v in loops[0]]
    i = border.index(a)
    border = border[i:] + border[:i]
    if border[1] != b:
        return None
    return _refilled(vertices, triangles, ring, [a, *chain, b] + border[2:], chain)


def _refilled(vertices, triangles, ring, border, chain):
    """(ring, new): the triangles ``ring`` re-triangulated inside ``border`` (vertex ids,
    in order) with their other vertices inside, in their mean plane (constrained Delaunay,
    no point added); None where it crosses itself or a triangle would turn over."""
    from .plane import constrained_triangles, frame, is_simple

    p = vertices[triangles[ring]]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]).sum(axis=0)
    n /= np.linalg.norm(n)
    interior = np.setdiff1d(np.unique(triangles[ring]), border + list(chain))
    ids = np.concatenate([np.array(border), interior]).astype(np.int64)
    uv = (vertices[ids] - vertices[ids].mean(axis=0)) @ frame(n).T
    m = len(border)
    if not is_simple(uv[:m]):
        return None
    local = constrained_triangles(uv, [list(range(m))])
    if local is None:
        return None
    new = ids[local]
    q = vertices[new]
    if len(new) != m + 2 * len(interior) - 2 or \
            np.any(np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0]) @ n <= 0.0):
        return None
    return [int(r) for r in ring], new


def _normal(v, t):
    return np.cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]])


def split_seams(vertices, triangles, component, lens=LENS, surface=None):
    """Triangles (and their component ids) with every cross-component seam made conformal.

    Parameters
    ----------
    vertices : (n, 3) float
    triangles : (m, 3) int
    component : (m,) int
        The component each triangle belongs to.
    lens : float
        See :data:`LENS`.
    surface : (m,) int, optional
        The surface (network) each triangle comes from: a triangle re-triangulated with its
        neighbours (:func:`_widened`) takes only those of its own surface (default: of its
        component).

    Returns
    -------
    triangles : (m', 3) int
    parent : (m',) int
        The input triangle each output triangle comes from (for its component and surface).
    """
    triangles = np.asarray(triangles)
    if not len(triangles):
        return triangles, np.arange(0)
    edges, owner = _boundary_edges(triangles)
    if not len(edges):
        return triangles, np.arange(len(triangles))
    # The components whose boundary edges touch each boundary vertex.
    touch = {}
    for (a, b), t in zip(edges.tolist(), owner.tolist()):
        touch.setdefault(a, set()).add(int(component[t]))
        touch.setdefault(b, set()).add(int(component[t]))
    ids = np.fromiter(touch, int)
    pts = vertices[ids]
    links = {}
    for a, b in edges.tolist():
        links.setdefault(a, set()).add(b)
        links.setdefault(b, set()).add(a)
    # Each point goes to the one edge it lies nearest (a point near a thin trailing edge is
    # in the lens of both the upper and the lower surface's edge), first among the edges
    # whose other side's boundary runs through it (_chain_points).
    found = []
    for e, ((a, b), t) in enumerate(zip(edges.tolist(), owner.tolist())):
        mine = int(component[t])
        near, s, off = _between(pts, vertices[a], vertices[b], lens)
        for k in np.flatnonzero(near):
            v = int(ids[k])
            if touch[v] - {mine} or off[k] <= COLLINEAR:
                found.append((float(off[k]), v, e, float(s[k])))
    best = _nearest_edges(found, edges, owner, component, touch, links)
    best = _one_side(best, edges)
    per_edge = {}
    for v, (_, e, t_v) in best.items():
        per_edge.setdefault(e, []).append((t_v, v))
    taken = {v for cand in per_edge.values() for _, v in cand}
    for e, chain in _wide_chains(vertices, edges, owner, component, touch, links,
                                 per_edge, taken):
        per_edge[e] = [(k, v) for k, v in enumerate(chain)]
    replaced, used = [], set()
    for e, cand in per_edge.items():
        (a, b), t = edges[e].tolist(), int(owner[e])
        if t in used:
            continue
        chain = _on_path(a, b, [v for _, v in sorted(cand)], links)
        fan = _fan(triangles[t], a, b, chain)
        n0 = _normal(vertices, triangles[t])
        if all(_normal(vertices, f) @ n0 > 0.0 for f in fan):
            cut = ([t], fan)
        elif (filled := _filled(vertices, triangles, t, a, b, chain)) is not None:
            cut = filled
        elif (wide := _widened(vertices, triangles, t, a, b, chain,
                               component if surface is None else surface)) is not None:
            cut = wide
            if used.intersection(cut[0]):
                continue
        else:  # no fill that keeps its side: the other side gives up the points instead
            cut = _collapse(vertices, triangles, a, b, chain)
            if cut is None or used.intersection(cut[0]):
                continue
        used.update(cut[0])
        replaced.append(cut)
    if not replaced:
        return triangles, np.arange(len(triangles))
    keep = np.setdiff1d(np.arange(len(triangles)), np.fromiter(used, int))
    new = [np.asarray(f, dtype=triangles.dtype).reshape(-1, 3) for _, f in replaced]
    parent = np.concatenate([keep] + [np.full(len(f), r[0]) for r, f in replaced])
    return np.concatenate([triangles[keep]] + new), parent


def _nearest_edges(found, edges, owner, component, touch, links):
    """{point: (offset, edge, parameter)}: each point found in edges' lenses (``found``:
    (offset, point, edge, parameter)) at the nearest edge whose other side's boundary runs
    from its ends through the point (:func:`_chain_points`), else at the nearest edge. A wing's
    root edge 31 ft long beside a fuselage's end, whose lens is 1.5 ft wide, took the points
    of the lower surface's seam a thin trailing edge below it, nearer to it than to their
    own edges, and dropped them as off its seam: both seams stayed open."""
    chains, best = {}, {}
    for off, v, e, s in sorted(found):
        if v in best:
            continue
        if e not in chains:
            (a, b), t = edges[e].tolist(), int(owner[e])
            chains[e] = _chain_points(a, b, int(component[t]), touch, links)
        if v in chains[e]:
            best[v] = (off, e, s)
    for off, v, e, s in sorted(found):
        if v not in best and not any(v in c for c in chains.values()):
            best[v] = (off, e, s)
    first = {}
    for _, v, _, _ in found:                 # in the order the edges first found them
        first.setdefault(v, len(first))
    return dict(sorted(best.items(), key=lambda item: first[item[0]]))


#: How far :func:`_chain_points` follows the other side's boundary.
CHAIN_STEPS = 256


def _chain_points(a, b, mine, touch, links):
    """The set of points on the other side's boundary path from ``a`` to ``b``
    (:func:`_other_chain`, followed up to :data:`CHAIN_STEPS` points)."""
    return set(_other_chain(a, b, mine, touch, links, CHAIN_STEPS))


def _one_side(best, edges):
    """``best`` (point: (offset, edge, parameter)) without the second of two insertions that
    would fill one triangle from both sides: point ``c`` into edge ``a -> b`` and ``a`` (or
    ``b``) into an edge between ``b`` (or ``a``) and ``c``. Where a thin gap of three points
    lies between two blocks of one body (behind a blunt trailing edge in the plane of a
    fuselage station, the upper and lower blocks ending on one curve from the next station),
    each took the other's trailing-edge point and both covered the gap: edges in four
    triangles. The insertion nearer its edge is kept."""
    seen, out = {}, dict(best)
    for v, (_, e, _) in sorted(best.items(), key=lambda item: item[1][0]):
        key = frozenset((*edges[e].tolist(), v))
        if len(key) == 3 and key in seen:
            del out[v]
        else:
            seen[key] = v
    return out


def _wide_chains(vertices, edges, owner, component, touch, links, per_edge, taken):
    """(edge, chain) for the boundary edges ``a -> b`` between two points shared with another
    component that no lens point splits, where that component's boundary runs from ``a`` to
    ``b`` through at most :data:`WIDE_STEPS` points of its own, each between ``a`` and ``b``
    and within :data:`WIDE` of the edge's length from it.

    A seam curve that bends between this side's sparse points (a fuselage row ending on the
    wing's exact intersection in its own plane, between two of the wing's chord stations)
    leaves such a loop: the other side's chain is the curve, this side's edge its chord.
    An edge whose lens holds only some of that chain takes all of it: a fillet's start line
    round a corner of an arbitrary section between two of the wing's stations 5.7 ft apart
    left the fuselage's row end next to a station in the lens and the one half-way 0.32 ft
    (5.6 %) off the edge, out of it, and the seam stayed open.
    """
    out = []
    for e, ((a, b), t) in enumerate(zip(edges.tolist(), owner.tolist())):
        mine = int(component[t])
        if not (touch[a] - {mine}) or not (touch[b] - {mine}):
            continue
        own = {v for _, v in per_edge.get(e, ())}
        for chain in _other_chains(a, b, mine, touch, links):
            if not own < set(chain) or (taken - own).intersection(chain):
                continue
            near, _, _ = _between(vertices[chain], vertices[a], vertices[b], WIDE, np.inf)
            if near.all():
                out.append((e, chain))
                taken.update(chain)
                break
    return out


def _other_chain(a, b, mine, touch, links, steps=WIDE_STEPS):
    """The points of the first boundary path from ``a`` to ``b`` (not the edge itself)
    through points that only other components' boundaries touch, at most ``steps`` of them;
    [] when there is none."""
    return next(iter(_other_chains(a, b, mine, touch, links, steps)), [])


def _other_chains(a, b, mine, touch, links, steps=WIDE_STEPS):
    """Every such path (:func:`_other_chain`): the seam's other side, and the far boundary
    of a strip between the same two shared points."""
    out = []
    for first in links.get(a, ()):
        path, prev, v = [], a, first
        while v != b and len(path) < steps and mine not in touch.get(v, {mine}):
            path.append(v)
            step = [w for w in links.get(v, ()) if w != prev]
            if len(step) != 1:
                break
            prev, v = v, step[0]
        if v == b and path:
            out.append(path)
    return out


def _on_path(a, b, chain, links):
    """The points of ``chain`` on a path of boundary edges from ``a`` to ``b`` through
    ``chain`` alone (the other side of the seam), in path order; all of ``chain`` when no
    such path exists (the other side's points between two of this side's: a point of this
    side lies between them).

    A point in the lens that the other side's boundary does not lead through belongs to
    another seam: the lower surface's trailing-edge point, a blunt trailing edge's
    thickness below the upper surface's last root edge.
    """
    allowed = set(chain) | {b}
    previous, frontier = {a: None}, [a]
    while frontier and b not in previous:
        nxt = []
        for v in frontier:
            for w in links.get(v, ()):
                if w in allowed and w not in previous and not (v == a and w == b):
                    previous[w] = v
                    nxt.append(w)
        frontier = nxt
    if b not in previous:
        return chain
    path, v = [], previous[b]
    while v != a:
        path.append(v)
        v = previous[v]
    return path[::-1] or chain


def _collapse(vertices, triangles, a, b, chain):
    """(removed, new): the other side's triangles round ``chain`` re-triangulated with the
    chain replaced by the edge ``b -> a`` (the other side runs the seam the other way), so
    both sides carry the edge; the chain's points, which lie on the seam's line but beyond
    this side's first strip, leave the mesh. Constrained Delaunay in the triangles' mean
    plane, no point added; None where it would fold."""
    from .assemble import boundary_loops

    ring = np.flatnonzero(np.isin(triangles, chain).any(axis=1))
    loops = boundary_loops(triangles[ring])
    if len(loops) != 1:
        return None
    border = [int(v) for v in loops[0]]
    # The other side runs b -> chain reversed -> a; put b first.
    if b not in border:
        return None
    k = border.index(b)
    border = border[k:] + border[:k]
    path = [b] + chain[::-1] + [a]
    if border[:len(path)] != path:
        return None
    border = [b] + border[len(path) - 1:]          # b, a, ... back to b
    return _refilled(vertices, triangles, ring, border, chain)
