"""One triangulated surface of a completed airplane, assembled from its networks.

The networks' quads are split into triangles along their shorter diagonal; vertices are
shared where coordinates are **bit-identical** (never by a welding tolerance: a seam closes
only where both networks carry the same points, as juncture's layouts make them), and
triangles that collapse (two equal corners) are dropped. A point of a mirrored network
within 1e-12 of the size from its mirror plane is put on it first, in both halves (``r
cos(pi / 2)`` is 6e-17 r, not 0: its image would leave a slit of zero width). What is left
open is then looked at loop by loop: a boundary loop that lies in one plane (a wing or fin
tip, a blunt base, a nacelle's open end) is capped by a triangulation of the plane polygon,
oriented against the loop so the surface stays consistently oriented; a loop made of two
chains that pair up point by point within a few per cent of its length (a blunt trailing
edge between the upper and the lower surface's last lines) is closed by the ruled strip
between them; any other loop (a seam whose two sides differ) stays open and is reported, so
that a caller never gets a surface closed by guesswork.

Orientation follows the networks' (``docs/conventions.md``: outward normals); the enclosed
volume is the divergence-theorem sum over the triangles, the wetted area the sum of their
areas per component, caps excluded.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .ends import point_ends
from .rows import members
from .seams import split_seams

__all__ = ["SurfaceMesh", "assemble", "boundary_loops", "simple_loops", "cap_polygon",
           "strip_cap", "strip_chains", "zip_strip", "equal_run"]


@dataclass(frozen=True, slots=True, eq=False)
class SurfaceMesh:
    """A triangulated surface with a component and a surface (network) id per triangle.

    Attributes
    ----------
    vertices : (n, 3) float
    triangles : (m, 3) int
        Vertex ids, counter-clockwise seen from outside.
    component : (m,) int
        Index into ``components`` (caps carry their loop's component).
    surface : (m,) int
        Index into ``surfaces``: the network a triangle comes from, or a cap.
    components, surfaces : tuple of str
    open_loops : tuple of (k,) int arrays
        Boundary loops left open (not planar), as vertex ids.
    """

    vertices: np.ndarray
    triangles: np.ndarray
    component: np.ndarray
    surface: np.ndarray
    components: tuple
    surfaces: tuple
    open_loops: tuple = ()

    def volume(self):
        """Enclosed volume (divergence theorem; > 0 for an outward-oriented closed surface)."""
        p = self.vertices[self.triangles]
        return float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0)

    def mass_properties(self, density=1.0):
        """:class:`~juncture.massprops.MassProperties` of the solid the closed surface
        encloses (exact for its triangles; overlapping components counted once)."""
        from ..massprops.closed import surface_mass_properties

        return surface_mass_properties(self.vertices, self.triangles, density, "surface")

    def centre_of_volume(self):
        """(3,) centroid of the enclosed solid, a coordinate within 1e-12 of the size from 0
        (round-off on a plane of symmetry) written as 0."""
        cg = np.asarray(self.mass_properties().cg, float)
        size = float(np.ptp(self.vertices, axis=0).max())
        return np.where(np.abs(cg) > 1e-12 * size, cg, 0.0)

    def areas(self):
        """(m,) triangle areas."""
        p = self.vertices[self.triangles]
        return 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)

    def wetted_area(self):
        """{component: area of its triangles, caps (and a half model's symmetry plane)
        excluded} and ``"total"``."""
        from .half import SYMMETRY

        a = self.areas()
        real = ~np.array([s.endswith(" cap") for s in self.surfaces])[self.surface]
        out = {name: float(a[(self.component == k) & real].sum())
               for k, name in enumerate(self.components) if name != SYMMETRY}
        out["total"] = float(sum(out.values()))
        return out


def _quad_triangles(n, m, pts):
    """(2 (n-1)(m-1), 3) local ids: each quad split along its shorter diagonal, oriented as
    the networks are (``cross(d/d point, d/d line)`` outward: (i, j) -> (i, j+1) ->
    (i+1, j+1) -> (i+1, j), i the line and j the point)."""
    i, j = np.meshgrid(np.arange(n - 1), np.arange(m - 1), indexing="ij")
    a, b = (i * m + j).ravel(), ((i + 1) * m + j).ravel()
    c, d = ((i + 1) * m + j + 1).ravel(), (i * m + j + 1).ravel()
    flat = pts.reshape(-1, 3)
    ac = np.linalg.norm(flat[a] - flat[c], axis=1)
    bd = np.linalg.norm(flat[b] - flat[d], axis=1)
    use_ac = (ac <= bd)[:, None]
    t1 = np.where(use_ac, np.stack([a, c, b], 1), np.stack([a, d, b], 1))
    t2 = np.where(use_ac, np.stack([a, d, c], 1), np.stack([b, d, c], 1))
    return np.concatenate([t1, t2])


def _merge(points):
    """Ids of bit-identical points (-0.0 counts as 0.0): (unique points, inverse)."""
    p = np.ascontiguousarray(np.asarray(points, float) + 0.0)
    keys = p.view(np.dtype((np.void, p.dtype.itemsize * 3))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    return p[first], inverse.ravel()


def boundary_loops(triangles):
    """Closed loops of directed boundary edges (edges with no opposite), as vertex-id arrays.

    Each loop runs along its triangles' edges (so a cap must run the other way). Vertices
    with more than one outgoing boundary edge are followed in input order; a chain that does
    not close is returned as it is.
    """
    e = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    key = e[:, 0].astype(np.int64) * (int(e.max()) + 1) + e[:, 1]
    rev = e[:, 1].astype(np.int64) * (int(e.max()) + 1) + e[:, 0]
    boundary = e[~members(rev, key)]             # no edge runs the other way
    nxt = {}
    for a, b in boundary.tolist():  # construction over the boundary only
        nxt.setdefault(a, []).append(b)
    loops = []
    while nxt:
        start = next(iter(nxt))
        loop, v = [start], start
        while True:
            outs = nxt.get(v)
            if not outs:
                break
            w = outs.pop(0)
            if not outs:
                del nxt[v]
            if w == start:
                break
            loop.append(w)
            v = w
        loops.append(np.array(loop))
    return loops


def _plane(points):
    """(centre, unit normal, in-plane axes (2, 3), largest distance from the plane)."""
    c = points.mean(axis=0)
    _, s, vt = np.linalg.svd(points - c)
    dist = np.abs((points - c) @ vt[2]).max()
    return c, vt[2], vt[:2], float(dist)


def cap_polygon(uv):
    """Triangles (k - 2, 3) of a simple polygon uv (k, 2) (either orientation), by ear
    clipping that takes, at each step, the ear with the largest smallest angle."""
    idx = list(range(len(uv)))
    area = 0.5 * np.sum(uv[:, 0] * np.roll(uv[:, 1], -1) - np.roll(uv[:, 0], -1) * uv[:, 1])
    sgn = 1.0 if area >= 0 else -1.0
    out = []
    while len(idx) > 3:
        k = len(idx)
        best, best_q = None, -1.0
        for t in range(k):
            a, b, c = idx[t - 1], idx[t], idx[(t + 1) % k]
            pa, pb, pc = uv[a], uv[b], uv[c]
            cross = sgn * ((pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]))
            if cross <= 0:
                continue
            others = uv[[i for i in idx if i not in (a, b, c)]]
            if others.size and _inside(others, pa, pb, pc, sgn).any():
                continue
            q = _min_angle(pa, pb, pc)
            if q > best_q:
                best, best_q = t, q
        if best is None:  # numerically degenerate remainder: fan it
            best = 0
        a, b, c = idx[best - 1], idx[best], idx[(best + 1) % k]
        out.append((a, b, c))
        idx.pop(best)
    out.append(tuple(idx))
    return np.array(out, int)


def _cap(uv):
    """Triangles of a planar loop: the constrained Delaunay triangulation of the polygon
    (collinear points along a flat side of a base give no zero-area triangle, which ear
    clipping's fallback fan did, crossing the body there), else :func:`cap_polygon`."""
    from .plane import constrained_triangles

    tri = constrained_triangles(uv, [list(range(len(uv)))])
    if tri is None or len(tri) != len(uv) - 2:
        return cap_polygon(uv)
    return tri


def _inside(p, a, b, c, sgn):
    def side(u, v):
        return sgn * ((v[0] - u[0]) * (p[:, 1] - u[1]) - (v[1] - u[1]) * (p[:, 0] - u[0]))
    return (side(a, b) >= 0) & (side(b, c) >= 0) & (side(c, a) >= 0)


def _min_angle(a, b, c):
    def ang(p, q, r):
        u, v = q - p, r - p
        den = np.linalg.norm(u) * np.linalg.norm(v)
        return np.arccos(np.clip(u @ v / den, -1.0, 1.0)) if den > 0 else 0.0
    return min(ang(a, b, c), ang(b, c, a), ang(c, a, b))


#: A loop is capped by a strip when its two halves pair up within this share of its length.
STRIP_SHARE = 0.05


def _turns(p):
    """(k,) cosines of the turn at each vertex of a closed polyline p (k, 3): 1 straight on,
    -1 turning back."""
    d_in = p - np.roll(p, 1, axis=0)
    d_out = np.roll(p, -1, axis=0) - p
    return (d_in * d_out).sum(1) / np.maximum(
        np.linalg.norm(d_in, axis=1) * np.linalg.norm(d_out, axis=1), 1e-300)


def _corners(p):
    """The two vertices of a closed polyline p (k, 3) where it turns back most sharply,
    at least two apart along it."""
    cos = _turns(p)
    order = np.argsort(cos)  # most negative: turning back
    first = int(order[0])
    k = len(p)
    for j in order[1:]:
        if min(abs(int(j) - first), k - abs(int(j) - first)) >= 2:
            return first, int(j)
    return None


def _zip_chains(pa, pb, angles=False):
    """Triangles (local: 'a' ids 0..n-1, 'b' ids n..n+m-1) of the strip between two polylines
    from a common start to a common end side: advance on the chain whose next diagonal is
    shorter or, with ``angles``, whose next triangle has the larger smallest angle (never a
    triangle on one straight side and its corner, where many points lie on one side)."""
    n, m = len(pa), len(pb)
    fa, fb = _fractions(pa), _fractions(pb)
    i = j = 0
    out = []
    while i < n - 1 or j < m - 1:
        if j == m - 1:
            on_a = True
        elif i == n - 1:
            on_a = False
        elif angles:   # off a shared first corner onto both sides, onto the last from both
            block_a = (j == 0 < i) or (i == n - 2 and j < m - 2)
            block_b = (i == 0 < j) or (j == m - 2 and i < n - 2)
            on_a = block_b if block_a != block_b else (
                _smallest(pa[i], pa[i + 1], pb[j]) >= _smallest(pa[i], pb[j + 1], pb[j]))
            # never on along a chain already past the other's point after next (by length
            # run): one side much finer than the other near a pinch ran away from it, a
            # triangle from the root to the tip
            if fa[i] >= fb[min(j + 2, m - 1)]:
                on_a = False
            elif fb[j] >= fa[min(i + 2, n - 1)]:
                on_a = True
        else:
            on_a = np.linalg.norm(pa[i + 1] - pb[j]) <= np.linalg.norm(pa[i] - pb[j + 1])
        if on_a:
            out.append((i, i + 1, n + j))
            i += 1
        else:
            out.append((i, n + j + 1, n + j))
            j += 1
    return np.array(out, int)


def _fractions(p):
    """(n,) the share of a polyline's length run at each of its points."""
    run = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))])
    return run / run[-1] if run[-1] > 0.0 else np.linspace(0.0, 1.0, len(p))


def _smallest(p, q, r):
    """The smallest angle's sine-like measure of a triangle: twice its area over its longest
    edge squared (0 when degenerate)."""
    area = np.linalg.norm(np.cross(q - p, r - p))
    longest = max(np.sum((q - p) ** 2), np.sum((r - q) ** 2), np.sum((p - r) ** 2))
    return area / longest if longest > 0.0 else 0.0


def strip_cap(vertices, loop):
    """Triangles of a ruled strip closing a thin loop (a blunt trailing edge between the
    upper and the lower surface's last lines), or None.

    The loop is split at the two vertices where it turns back most sharply into two chains
    from one to the other (:func:`strip_chains`); the strip between them is zipped (the
    shorter diagonal first, :func:`zip_strip`). Oriented against the loop.
    """
    chains = strip_chains(vertices, loop)
    return None if chains is None else zip_strip(vertices, *chains)


def strip_chains(vertices, loop):
    """(a, b): the two chains of a thin loop from one of the two vertices where it turns
    back most sharply to the other, ``a`` along the loop and ``b`` against it, or None. Taken
    only when every point of each chain lies within ``STRIP_SHARE`` of the loop's length of
    the other chain's points."""
    k = len(loop)
    if k < 4:
        return None
    p = vertices[loop]
    length = np.linalg.norm(p - np.roll(p, -1, axis=0), axis=1).sum()
    for corners in (_corners(p), _far_corners(p)):
        if corners is None:
            continue
        c0, c1 = sorted(corners)
        a = loop[c0:c1 + 1]                                   # along the loop
        b = np.concatenate([loop[c0::-1], loop[:c1 - 1:-1]])  # against it, c0 -> c1
        b = b[:np.flatnonzero(b == loop[c1])[0] + 1]
        gap = np.linalg.norm(vertices[a][:, None] - vertices[b][None, :], axis=2)
        if max(gap.min(1).max(), gap.min(0).max()) <= STRIP_SHARE * length:
            return a, b
    return None


def _far_corners(p):
    """Of the vertices of a closed polyline p (k, 3) where it turns by more than 60 deg, the
    two farthest apart along it (the shorter way round the longest): the ends of a thin
    strip whose end is not one sharp turn (a centre-line fin's blunt trailing edge, whose
    root end runs out to one side's root, over the fuselage's top line and back to the
    other's: its two sharpest turns are both there), or None."""
    turns = np.flatnonzero(_turns(p) < 0.5)
    if len(turns) < 2:
        return None
    step = np.linalg.norm(np.roll(p, -1, axis=0) - p, axis=1)
    arc = np.concatenate([[0.0], np.cumsum(step)])
    along = np.abs(arc[turns][:, None] - arc[turns][None, :])
    apart = np.minimum(along, arc[-1] - along)
    i, j = np.unravel_index(np.argmax(apart), apart.shape)
    return (int(turns[i]), int(turns[j])) if i != j else None


def zip_strip(vertices, a, b, angles=False):
    """Triangles of the strip between the chains ``a`` (along a loop) and ``b`` (against
    it) of :func:`strip_chains`, running against the loop (``angles``: see
    :func:`_zip_chains`); triangles with a repeated corner are dropped."""
    tri = np.concatenate([a, b])[_zip_chains(vertices[a], vertices[b], angles)]
    # The loop runs a_i -> a_i+1: the cap must use a_i+1 -> a_i, as (a_i+1, a_i, b_j) does.
    tri = tri[:, ::-1]
    ok = (tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 2] != tri[:, 0])
    return tri[ok]


def simple_loops(loop):
    """A boundary loop that passes a vertex more than once (pinched: a tip whose upper and
    lower lines touch between its ends) split there into loops that pass each vertex once."""
    out, stack, seen = [], [], {}
    for v in np.asarray(loop).tolist():
        if v in seen:
            k = seen[v]
            out.append(np.array(stack[k:]))
            for w in stack[k + 1:]:
                del seen[w]
            del stack[k + 1:]
        else:
            seen[v] = len(stack)
            stack.append(v)
    out.append(np.array(stack))
    return [lp for lp in out if len(lp) >= 3]


def _caps(vertices, triangles, tol):
    """Cap triangles for every planar boundary loop and every thin strip, the loops left
    open, and which caps are strips."""
    caps, where, open_, thin = [], [], [], []
    loops = [lp for loop in boundary_loops(triangles) for lp in simple_loops(loop)]
    for loop in loops:
        pts = vertices[loop]
        if len(loop) < 3:
            open_.append(loop)
            continue
        c, _, axes, dist = _plane(pts)
        if dist > tol:
            ways = (_tip_and_strip, _strip_cap) if _turns_inside_tip(pts) else \
                (_strip_cap, _tip_and_strip)
            strip = ways[0](vertices, loop, tol)
            if strip is None:
                strip = ways[1](vertices, loop, tol)
            if strip is None:
                open_.append(loop)
            else:
                caps.append(strip)
                where.append(loop[0])
                thin.append(True)
            continue
        caps.append(_planar_cap(vertices, loop))
        where.append(loop[0])
        thin.append(False)
    return caps, where, open_, thin


#: A strip-cap triangle on another component's surface is that component's where its longest
#: edge is over this many times its shortest (:func:`_wedges`).
WEDGE = 10.0


def _edge_index(triangles, n):
    """(sorted directed-edge keys a * n + b, the row of each) of ``triangles`` over ``n``
    vertices, for :func:`_owners`."""
    e = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    keys = e[:, 0].astype(np.int64) * n + e[:, 1]
    order = np.argsort(keys, kind="stable")
    return keys[order], np.tile(np.arange(len(triangles)), 3)[order], n


def _owners(index, tri):
    """(m, 3) the row of the indexed triangles (:func:`_edge_index`) across each edge of the
    cap triangles ``tri`` (the triangle whose boundary edge it closes), -1 where the edge is
    inside the cap."""
    keys, rows, n = index
    c = np.stack([tri[:, [1, 0]], tri[:, [2, 1]], tri[:, [0, 2]]], axis=1)  # reversed edges
    want = c[..., 0].astype(np.int64) * n + c[..., 1]
    if not len(keys):
        return np.full(want.shape, -1)
    at = np.minimum(np.searchsorted(keys, want), len(keys) - 1)
    return np.where(keys[at] == want, rows[at], -1)


def _wedges(vertices, index, component, tri):
    """(the indexed row (:func:`_edge_index`) whose surface each strip-cap triangle in
    ``tri`` belongs to, -1: the cap's; the cap's component, that of most of its loop's
    edges, -1 if none): a triangle of the strip whose edges on the loop all close triangles
    of one component that is not the cap's (the body's gap between its upper and lower split
    lines, which meet aft of a blunt trailing edge, not at it: a wedge a few feet long and
    the trailing edge's thickness wide) lies on that component's surface, and belongs to it;
    as the cap's, its thin point was zipped into triangles of 0.04 deg. Only a thin such
    triangle (longest edge over :data:`WEDGE` times its shortest): a short one (a centre
    fin's strip running over the fuselage's top line, 0.02 ft long and 0.05 ft across)
    stays the cap's, which zips it well, and its rung would be split to slivers."""
    owner = _owners(index, tri)
    comp = np.where(owner >= 0, component[np.maximum(owner, 0)], -1)
    on_loop = comp >= 0
    if not on_loop.any():
        return np.full(len(tri), -1), -1
    values, counts = np.unique(comp[on_loop], return_counts=True)
    mine = values[np.argmax(counts)]                       # the cap's own component
    rows, pick = np.arange(len(tri)), np.argmax(on_loop, axis=1)   # its first loop edge
    first = comp[rows, pick]                       # -1 where no edge is on the loop
    same = np.all(~on_loop | (comp == first[:, None]), axis=1)
    p = vertices[tri]
    edge = np.linalg.norm(p - np.roll(p, -1, axis=1), axis=2)
    thin = edge.max(axis=1) > WEDGE * edge.min(axis=1)
    wedge = (first >= 0) & same & (first != mine) & thin
    return np.where(wedge, owner[rows, pick], -1), mine


def _planar_cap(vertices, loop):
    """Triangles of a planar loop's cap, running against the loop."""
    pts = vertices[loop]
    c, _, axes, _ = _plane(pts)
    tri = loop[_cap((pts - c) @ axes.T)]
    return tri[:, ::-1] if _runs_with(tri, loop) else tri


def equal_run(p):
    """(start, length) of the longest cyclic run of consecutive points with one coordinate
    bit-identical (a wing tip's points share its span station), or None (under 3)."""
    k, best = len(p), None
    for axis in range(3):
        same = p[:, axis] == np.roll(p[:, axis], -1)          # i and i + 1 share it
        if same.all():
            continue
        start = int(np.flatnonzero(~same)[0]) + 1               # a run starts after a break
        run = 0
        for i in range(k):
            j = (start + i) % k
            if same[j]:
                run += 1
                continue
            if run + 1 >= 3 and (best is None or run + 1 > best[1]):
                best = ((j - run) % k, run + 1)
            run = 0
    return best


def _strip_cap(vertices, loop, tol):
    return strip_cap(vertices, loop)


def _turns_inside_tip(p):
    """Whether a loop's sharpest turn back lies inside a run of points that share a span
    station (a tip's leading edge): taken for one strip from there, a blunt trailing edge
    running into the tip was zipped from the tip's trailing edge to the root."""
    found, corners = equal_run(p), _corners(p)
    if found is None or corners is None:
        return False
    start, n = found
    inner = (np.asarray(corners) - start) % len(p)
    return bool(np.any((inner > 0) & (inner < n - 1)))


def _tip_and_strip(vertices, loop, tol):
    """Cap triangles of a loop that is a planar tip and a thin strip joined (a wing whose
    blunt trailing edge runs into its tip: the tip's points share the span station), split
    along the chord between the tip's two ends; None where it is not that."""
    found = equal_run(vertices[loop])
    if found is None:
        return None
    start, n = found
    rolled = np.roll(loop, -start)
    tip, rest = rolled[:n], np.concatenate([rolled[n - 1:], rolled[:1]])
    if _plane(vertices[tip])[3] > tol or len(rest) < 4:
        return None
    strip = strip_cap(vertices, rest)
    if strip is None:
        return None
    return np.concatenate([_planar_cap(vertices, tip), strip])


def _runs_with(tri, loop):
    """Whether the cap's triangles use the loop's directed edges (they must use the reverse)."""
    edges = {(int(a), int(b)) for a, b in zip(loop, np.roll(loop, -1))}
    used = {(int(t[i]), int(t[(i + 1) % 3])) for t in tri for i in range(3)}
    return len(edges & used) > len(edges) // 2


def _imprint_all(geometry, vertices, triangles, component, surface, components):
    """Every footprint (:mod:`juncture.surface.imprint`) cut into its host."""
    from .imprint import footprints, imprint_many, on_lines

    on = on_lines(geometry, vertices)
    seams = np.zeros(len(vertices), bool)
    seams[list(on)] = True
    by_host = {}
    for host, loop in footprints(geometry, vertices, triangles, component, components, on):
        by_host.setdefault(host, []).append(loop)
    cuts = [cut for host, loops in by_host.items()
            for cut in imprint_many(vertices, triangles, np.isin(component, host), loops,
                                    _chart(geometry, [components[h] for h in host],
                                           vertices[np.concatenate(loops)]), seams)]
    # Every cut is planned on the triangles as assembled; hosts differ or regions are
    # disjoint, so removing them all at once is safe.
    keep = np.ones(len(triangles), bool)
    for removed, _ in cuts:
        keep[removed] = False
    new_tri, new_comp, new_surf = [triangles[keep]], [component[keep]], [surface[keep]]
    for removed, new in cuts:
        new_tri.append(new)
        new_comp.append(np.full(len(new), np.bincount(component[removed]).argmax()))
        new_surf.append(np.full(len(new), np.bincount(surface[removed]).argmax()))
    return np.concatenate(new_tri), np.concatenate(new_comp), np.concatenate(new_surf)


def _chart(geometry, names, points):
    """:func:`juncture.surface.imprint.body_chart` of the one fuselage among the host
    components ``names``, or None (a wing, or a block two components share)."""
    from ..model import ArbitraryBody, CircularBody
    from .imprint import body_chart

    models = {c.name: c for c in getattr(geometry, "configuration", None) or ()}
    found = [models.get(n) for n in names]
    if len(found) == 1 and isinstance(found[0], (CircularBody, ArbitraryBody)):
        return body_chart(found[0], points)
    return None


#: A point of a mirrored network this close to its mirror plane (a share of the size) lies on
#: it: ``r cos(pi / 2)`` is 6e-17 r, and its image would leave a slit of zero width.
ON_PLANE = 1e-12


def _off_plane(geometry, nets, vertices, triangles, surface):
    """(m,) bool: False for the triangles of a network with a mirror image that lie wholly
    in its plane of symmetry (every corner on it exactly, as :func:`_on_plane` puts them).
    The image covers the same region of the plane from the other side: a wall of no
    thickness (a wing whose root runs on behind the fuselage's end, its lofting lines
    continued to the plane there: the panel between the upper and lower surfaces' end
    points lies inside the wing). Without both halves' copies, each edge round the region
    keeps its two other triangles, one from each half."""
    from ..geometry import _AXIS_OF_PLANE

    names = list(nets)
    keep = np.ones(len(triangles), bool)
    for plane in set(geometry.symmetry.values()):
        axis = _AXIS_OF_PLANE[plane]
        halves = [k for k, n in enumerate(names)
                  if (n.endswith(" image") and geometry.symmetry.get(n[:-6]) == plane)
                  or (f"{n} image" in nets and geometry.symmetry.get(n) == plane)]
        flat = np.all(vertices[triangles][..., axis] == 0.0, axis=1)
        keep &= ~(flat & np.isin(surface, halves))
    return keep


def _on_plane(geometry, nets):
    """``nets`` with the points of mirrored networks that lie on their plane put on it
    exactly, in the network and in its image (mirrored or made on its own), so that the two
    halves share them."""
    from ..geometry import _AXIS_OF_PLANE

    size = float(np.max(np.ptp(geometry.extents(), axis=0))) or 1.0
    out = dict(nets)
    planes = dict(geometry.symmetry)
    # a half made on its own (a centre-line fin with two different sides) and its network
    planes.update({n: "xz" for n in nets if f"{n} image" in nets and n not in planes})
    for name, plane in planes.items():
        axis = _AXIS_OF_PLANE[plane]
        for key in (name, f"{name} image"):
            net = np.array(out[key], float)
            near = np.abs(net[..., axis]) <= ON_PLANE * size
            if near.any():
                net[..., axis] = np.where(near, 0.0, net[..., axis])
                out[key] = net
    return out


def assemble(geometry, mirror=True, cap=True, flow_through=False):
    """The networks of ``geometry`` as one :class:`SurfaceMesh` (see the module docstring).

    Parameters
    ----------
    geometry : Geometry
    mirror : bool
        Both halves (networks with a mirror plane and their images; default) or the networks
        as given.
    cap : bool
        Cap planar boundary loops (tips, blunt bases, open nacelle ends).
    flow_through : bool
        Join each nacelle's inlet to its exit by a duct instead of capping them
        (:mod:`juncture.surface.ducts`).
    """
    nets = geometry.mirrored_networks() if mirror else dict(geometry.networks)
    if mirror:
        nets = _on_plane(geometry, nets)
    nets = point_ends(geometry, nets)
    if flow_through:
        from .ducts import with_ducts

        nets = with_ducts(geometry, nets)
    owners = [geometry.component_of(name) for name in nets]
    components = tuple(dict.fromkeys(owners))
    pts, tris, comp_id, surf_id, offset = [], [], [], [], 0
    for k, net in enumerate(nets.values()):
        net = np.asarray(net, float)
        n, m = net.shape[:2]
        t = _quad_triangles(n, m, net) + offset
        pts.append(net.reshape(-1, 3))
        tris.append(t)
        comp_id.append(np.full(len(t), components.index(owners[k])))
        surf_id.append(np.full(len(t), k))
        offset += n * m
    vertices, inverse = _merge(np.concatenate(pts))
    triangles = inverse[np.concatenate(tris)]
    component, surface = np.concatenate(comp_id), np.concatenate(surf_id)
    keep = (triangles[:, 0] != triangles[:, 1]) & (triangles[:, 1] != triangles[:, 2]) & \
        (triangles[:, 2] != triangles[:, 0])
    keep &= _off_plane(geometry, nets, vertices, triangles, surface) if mirror else True
    triangles, component, surface = triangles[keep], component[keep], surface[keep]
    for _ in range(3):  # a triangle with two seam edges gets its second fan next pass
        triangles, parent = split_seams(vertices, triangles, component, surface=surface)
        if len(parent) == len(component) and np.array_equal(parent, np.arange(len(parent))):
            break
        component, surface = component[parent], surface[parent]
    surfaces = tuple(nets)
    triangles, component, surface = _imprint_all(geometry, vertices, triangles, component,
                                                 surface, components)
    open_loops = ()
    if cap:
        size = float(np.ptp(vertices, axis=0).max()) or 1.0
        caps, where, open_loops, thin = _caps(vertices, triangles, 1e-9 * size)
        vertex_comp = np.zeros(len(vertices), int)
        vertex_comp[triangles.ravel()] = np.repeat(component, 3)
        index = _edge_index(triangles, len(vertices))          # the networks' triangles
        for tri, v, strip in zip(caps, where, thin):
            owner, c = _wedges(vertices, index, component, tri) if strip else \
                (np.full(len(tri), -1), -1)
            c = int(vertex_comp[v]) if c < 0 else int(c)
            name = f"{components[c]} cap"
            if name not in surfaces:
                surfaces += (name,)
            own = owner >= 0
            triangles = np.concatenate([triangles, tri])
            component = np.concatenate([component, np.where(own, component[owner], c)])
            surface = np.concatenate([surface, np.where(own, surface[owner],
                                                         surfaces.index(name))])
    return SurfaceMesh(vertices, triangles, component, surface, components, surfaces,
                       tuple(open_loops))
