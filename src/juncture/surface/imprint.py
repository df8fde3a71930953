"""A component's footprint cut into the surface it stands on.

A pylon ends on the wing's lower surface, a fin or a tail on the fuselage: juncture trims the
standing component at its intersection line, so its networks end in a closed loop of exact
points of the other surface (the *host*). Where the layout has not already opened the host
there (the fuselage blocks do it for fins and tails, the nacelle for its pylon), the host's
triangles pass under the footprint. :func:`imprint` removes them and re-triangulates the
region between the loop and the untouched triangles around it with a constrained Delaunay
triangulation (PythonCDT, MPL-2.0) in the plane the host faces there: the loop's edges and
the region's border are constraints, the host's own vertices in between are kept where they
are not crowding the loop. No point is created or moved, so every vertex stays an exact
point of its surface and the seam closes by vertex ids.
"""

from __future__ import annotations

import numpy as np

from .plane import constrained_triangles, distance, frame, inside, is_simple, unit

__all__ = ["imprint", "imprint_many", "footprints", "hosts_of", "body_chart"]

#: Host vertices nearer the loop than this share of the local edge length are left out.
CROWD = 0.1


def _region(vertices, triangles, cand, uv, loop2, margin):
    """Candidate triangles (ids into ``cand``) whose projection meets the loop's polygon or
    comes within ``margin`` of it."""
    t2 = uv[triangles[cand]]                                    # (c, 3, 2)
    corners = t2.reshape(-1, 2)
    hit = inside(corners, loop2) | (distance(corners, loop2) <= margin)
    hit = hit.reshape(-1, 3).any(axis=1)
    # A loop point inside a triangle (a loop that lies inside one large triangle).
    u, v = t2[:, None, 1] - t2[:, None, 0], t2[:, None, 2] - t2[:, None, 0]
    w = np.concatenate([loop2, loop2.mean(axis=0, keepdims=True)])[None] - t2[:, None, 0]
    det = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        lam1 = (w[..., 0] * v[..., 1] - w[..., 1] * v[..., 0]) / det
        lam2 = (u[..., 0] * w[..., 1] - u[..., 1] * w[..., 0]) / det
        hit |= ((lam1 >= 0) & (lam2 >= 0) & (lam1 + lam2 <= 1)).any(axis=1)
    # A long sliver that crosses the loop with every corner far from it.
    hit |= _crossing(t2, loop2)
    return np.flatnonzero(hit)


def _crossing(t2, loop2):
    """(c,) whether an edge of each 2-D triangle (c, 3, 2) crosses an edge of the loop."""
    a0, a1 = t2, np.roll(t2, -1, axis=1)                       # (c, 3, 2)
    b0, b1 = loop2, np.roll(loop2, -1, axis=0)                 # (k, 2)

    def orient(p, q, r):
        return np.sign((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1])
                       - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))
    a0, a1 = a0[:, :, None], a1[:, :, None]                    # (c, 3, 1, 2)
    d1, d2 = orient(a0, a1, b0[None, None]), orient(a0, a1, b1[None, None])
    d3, d4 = orient(b0[None, None], b1[None, None], a0), orient(b0[None, None],
                                                                 b1[None, None], a1)
    return ((d1 * d2 < 0) & (d3 * d4 < 0)).any(axis=(1, 2))


def _under(p, corner, normal):
    """Host triangles (ids into ``corner``) under the points ``p`` (k, 3): for each point,
    the triangle whose plane is nearest among those it projects into (its exact surface
    point lies off the flat triangles by their sag); None where a point has none."""
    lo, hi = corner.min(axis=1), corner.max(axis=1)
    pad = 0.05 * (hi - lo).max(axis=1, keepdims=True)
    out = []
    for q in p:  # a loop has tens of points; each test is vectorised over the host
        cand = np.flatnonzero(np.all((q >= lo - pad) & (q <= hi + pad), axis=1))
        if not len(cand):
            return None
        a, u, v = corner[cand, 0], corner[cand, 1] - corner[cand, 0], \
            corner[cand, 2] - corner[cand, 0]
        nn = unit(normal[cand])
        w = q - a
        dist = np.abs((w * nn).sum(axis=1))
        w = w - (w * nn).sum(axis=1, keepdims=True) * nn
        uu, uv, vv = (u * u).sum(1), (u * v).sum(1), (v * v).sum(1)
        wu, wv = (w * u).sum(1), (w * v).sum(1)
        den = uu * vv - uv * uv
        with np.errstate(divide="ignore", invalid="ignore"):
            s_, t_ = (vv * wu - uv * wv) / den, (uu * wv - uv * wu) / den
            inside = (s_ >= -1e-6) & (t_ >= -1e-6) & (s_ + t_ <= 1 + 1e-6)
        if not inside.any():
            return None
        out.append(int(cand[inside][np.argmin(dist[inside])]))
    return np.array(out)


def _outer(triangles, uv):
    """The boundary loop of a set of triangles that encloses the largest area in the plane
    (the others are holes the margin test left), or None."""
    from .assemble import boundary_loops

    def area(loop):
        p = uv[loop]
        return abs(np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1]))

    loops = boundary_loops(triangles)
    return max(loops, key=area) if loops else None


def _border(triangles):
    """The single boundary loop of a set of triangles, or None (none, or several)."""
    from .assemble import boundary_loops

    loops = boundary_loops(triangles)
    return loops[0] if len(loops) == 1 else None


def imprint(vertices, triangles, host, loop):
    """Cut a closed loop of exact points into the host surface.

    Parameters
    ----------
    vertices : (n, 3) float
    triangles : (m, 3) int
    host : (m,) bool
        The host component's triangles.
    loop : (k,) int
        Vertex ids of the footprint, in the order the standing component's triangles use
        them.

    Returns
    -------
    (removed, new) : ((r,) int, (s, 3) int), or None
        Host triangles to remove and the triangles that replace them (oriented as the host),
        or None where the footprint cannot be cut in one plane (a loop that folds over in
        projection, a region with a hole, a triangulation that would fold in space).
    """
    cuts = imprint_many(vertices, triangles, host, [loop])
    return cuts[0] if cuts else None


class _Host:
    """The host's triangles with their corners, normals and centres, and the vertices on
    intersection lines (``seams``)."""

    def __init__(self, vertices, triangles, host, seams=None):
        self.vertices, self.triangles = vertices, triangles
        self.seams = np.zeros(len(vertices), bool) if seams is None else \
            np.asarray(seams, bool)
        self.hid = np.flatnonzero(host)
        self.corner = vertices[triangles[self.hid]]
        c = self.corner
        self.normal = np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0])
        self.cent = c.mean(axis=1)
        self.edge = np.linalg.norm(c - np.roll(c, 1, axis=1), axis=2)


def _plan(h_, loop):
    """(normal, edge length, the host triangles round the loop) for one loop, or None."""
    from scipy.spatial import cKDTree

    p = h_.vertices[loop]
    under = _under(p, h_.corner, h_.normal)
    if under is None:
        _, under = cKDTree(h_.cent).query(p, k=min(3, len(h_.hid)))
    under = np.unique(under)
    n = unit(unit(h_.normal[under]).sum(axis=0))
    h = float(np.median(h_.edge[under].min(axis=1)))  # across the panels, not along
    size = float(np.linalg.norm(p - p.mean(axis=0), axis=1).max())
    axes, origin = frame(n), p.mean(axis=0)
    uv = (h_.vertices - origin) @ axes.T
    if not is_simple(uv[loop]):
        return None
    # Facing the loop's side, or degenerate (the zero-width strip between two traced curves
    # that coincide away from a pylon faces nowhere, yet lies under it).
    flat = np.linalg.norm(h_.normal, axis=1) <= 1e-12 * h * h
    # Near by the triangle's bounding box, not its corners: a long panel (a wing given by
    # root and tip only) can pass under the loop with every corner far from it.
    lo, hi = h_.corner.min(axis=1), h_.corner.max(axis=1)
    gap = np.linalg.norm(np.maximum(np.maximum(lo - origin, origin - hi), 0.0), axis=1)
    near = gap <= 2.0 * (size + h)
    cand = h_.hid[((unit(h_.normal) @ n > 0.25) | flat) & near]
    if not len(cand):
        return None
    region = cand[_region(h_.vertices, h_.triangles, cand, uv, uv[loop], h)]
    return n, h, _connected(h_, region, h_.hid[under])


def _connected(h_, region, seeds):
    """The triangles of ``region`` reached from ``seeds`` through shared corners that are
    not on an intersection line (``h_.seams``): the host's surface ends at those, and the
    margin round a loop under large panels (a wing given by few sections) reaches past
    them onto another surface of the same network (a four-block layout's body arcs under
    the wing root). All of ``region`` where no seed is in it."""
    got = np.intersect1d(region, seeds)
    return _reach(h_, got, np.setdiff1d(region, got)) if len(got) else region


def _reach(h_, got, pool, rounds=None):
    """``got`` (host triangle ids) with the triangles of ``pool`` reached from it, step by
    step (at most ``rounds`` steps), through shared corners not on an intersection line."""
    seams = np.flatnonzero(h_.seams)
    for _ in range(len(pool) if rounds is None else rounds):
        if not len(pool):
            break
        through = np.setdiff1d(h_.triangles[got], seams)
        reached = pool[np.isin(h_.triangles[pool], through).any(axis=1)]
        if not len(reached):
            break
        got = np.union1d(got, reached)
        pool = np.setdiff1d(pool, reached)
    return got


def imprint_many(vertices, triangles, host, loops, chart=None, seams=None):
    """:func:`imprint` for several loops on one host: loops whose regions share a triangle
    (twin fins either side of the plane of symmetry) are cut together, in one plane, each
    a hole of one triangulation. Returns a list of (removed, new), one per group that could
    be cut (groups never share a triangle).

    ``chart(points)`` (k, 2), optional: the host's own surface parameters (a fuselage's x
    and arc round its axis, :func:`body_chart`), used where the region does not project
    onto one plane without folding (twin fins canted on a tail cone: their common region
    spans the top of a section that turns aft).

    ``seams`` (n,) bool, optional: the vertices on intersection lines. The region never
    grows through them: the host's surface ends there (a four-block layout's "wing-body
    lower" block runs on round the body under the wing root, and its body arcs face the
    same way and project inside a region of large wing panels)."""
    h_ = _Host(vertices, triangles, host, seams)
    loops = [np.asarray(lp) for lp in loops if len(lp) >= 3]
    if not len(h_.hid) or not loops:
        return []
    plans = [(lp, _plan(h_, lp)) for lp in loops]
    plans = [(lp, pl) for lp, pl in plans if pl is not None]
    groups = []  # [(loops, normals, edge lengths, region)]
    for lp, (n, h, region) in plans:
        joined = [g for g in groups if np.intersect1d(g[3], region).size]
        groups = [g for g in groups if not any(g is j for j in joined)]
        groups.append(([lp] + [x for g in joined for x in g[0]],
                       [n] + [x for g in joined for x in g[1]],
                       [h] + [x for g in joined for x in g[2]],
                       np.union1d(region, np.concatenate([g[3] for g in joined] or [[]])
                                  ).astype(np.int64)))
    out = []
    for group_loops, normals, hs, region in groups:
        n = unit(np.sum(normals, axis=0))
        axes, origin = frame(n), vertices[np.concatenate(group_loops)].mean(axis=0)
        cut = _cut(h_, group_loops, n, max(hs), region,
                   lambda p, o=origin, a=axes: (p - o) @ a.T)
        if cut is None and chart is not None:
            cut = _cut(h_, group_loops, None, max(hs), region, chart)
        if cut is not None:
            out.append(cut)
    return out


def _cut(h_, loops, n, h, region, flat):
    """Re-triangulate ``region`` with the loops as holes (see :func:`imprint`), in the
    plane ``flat(points)`` (k, 2) maps onto: the plane normal to ``n``, or with ``n`` None
    the host's own parameters (the new triangles then take the host's orientation there)."""
    vertices, triangles = h_.vertices, h_.triangles
    all_loop = np.concatenate(loops)
    uv = flat(vertices)
    border = _outer(triangles[region], uv)
    if border is None:
        return None
    # Fill what the border encloses (host triangles the margin test left out), once.
    # Only triangles reached from the region through shared corners: the far side of a
    # body can face the same way and project inside too.
    facing = np.ones(len(h_.hid), bool) if n is None else unit(h_.normal) @ n > 0.25
    fill = h_.hid[facing & inside(flat(h_.cent), uv[border])]
    region = _reach(h_, region, np.setdiff1d(fill, region), rounds=50)
    # And any host triangle all of whose corners the region uses (a sliver facing nowhere).
    closed = h_.hid[np.isin(triangles[h_.hid], triangles[region]).all(axis=1)]
    region = np.union1d(region, closed)
    border = _border(triangles[region])
    if border is None or np.isin(all_loop, border).any():
        return None
    interior = np.setdiff1d(np.unique(triangles[region]), np.concatenate([border, all_loop]))
    for lp in loops:
        interior = interior[~inside(uv[interior], uv[lp])
                            & (distance(uv[interior], uv[lp]) > CROWD * h)]
    ids = np.concatenate([border, interior, all_loop])
    local = {int(v): i for i, v in enumerate(ids)}
    if len(local) != len(ids):
        return None
    local_tri = constrained_triangles(uv[ids], [[local[int(v)] for v in chain]
                                                for chain in [border] + loops], holes=True)
    if local_tri is None:
        return None
    new = ids[local_tri]
    if n is None:
        return _oriented(uv, triangles[region], new, region)
    q = vertices[new]
    if np.any(np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0]) @ n <= 0.0):
        return None
    return region, new


def _signed(uv, tri):
    a, b, c = uv[tri[:, 0]], uv[tri[:, 1]], uv[tri[:, 2]]
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])


def _oriented(uv, old, new, region):
    """(region, new) with ``new`` turned as the host's triangles ``old`` turn in the chart
    ``uv``; None where the chart folds them (both turns) or a new triangle is flat."""
    before, after = np.sign(_signed(uv, old)), np.sign(_signed(uv, new))
    if np.any(before == 0) or np.any(after == 0) or len(np.unique(before)) != 1 \
            or len(np.unique(after)) != 1:
        return None
    return region, (new if before[0] == after[0] else new[:, ::-1])


def body_chart(body, points):
    """``chart(p)`` (k, 2) of a fuselage for :func:`imprint_many`: x, and the arc round
    the section centre from the mean direction of ``points`` (the loops), at the body's
    largest radius (the branch cut is opposite the loops)."""
    def angle(p):
        c = body.center_at(p[:, 0])
        return np.arctan2(p[:, 2] - c[:, 1], p[:, 1] - c[:, 0])
    ref = np.angle(np.exp(1j * angle(np.asarray(points, float))).mean())
    scale = float(np.sqrt(np.max(body.area_at(body.x_global)) / np.pi)) or 1.0

    def chart(p):
        p = np.asarray(p, float)
        return np.stack([p[:, 0], scale * np.angle(np.exp(1j * (angle(p) - ref)))], axis=1)
    return chart


def hosts_of(name, components):
    """Indices of the components that carry the surface of component ``name``: itself, or
    the blocks it shares with another component (the four-block layout's ``"wing-body
    upper"`` and ``"wing-body lower"`` carry both the wing and the body)."""
    out = []
    for k, c in enumerate(components):
        head = c.split(" ", 1)[0]
        if c == name or ("-" in head and name in head.split("-")):
            out.append(k)
    return tuple(out)


def on_lines(geometry, vertices):
    """{vertex id: {(standing component, host)}} of the vertices that are intersection
    points of ``geometry`` (bit for bit; mirror images count for the image half)."""
    def keys(points):
        q = np.ascontiguousarray(np.asarray(points, float) + 0.0)
        return q.view(np.dtype((np.void, 24))).ravel()

    vkeys = keys(vertices)
    order = np.argsort(vkeys)
    on = {}
    for name, pts in geometry.intersections.items():
        a, rest = name.split("/", 1)
        b = rest.rsplit(" ", 1)[0]
        for q in (pts, pts * np.array([1.0, -1.0, 1.0])):
            q = np.asarray(q, float)
            qk = keys(q[np.all(np.isfinite(q), axis=1)])
            at = np.minimum(np.searchsorted(vkeys, qk, sorter=order), len(order) - 1)
            for k in order[at][vkeys[order[at]] == qk].tolist():
                on.setdefault(k, set()).add((a, b))
    return on


def footprints(geometry, vertices, triangles, component, components, on=None):
    """Loops to imprint: ``[(host component indices, loop)]`` for every open boundary loop of
    a component made (mostly) of its intersection points with another component.

    The intersection lines ``"a/b side"`` of ``geometry`` name the standing component ``a``
    and the host ``b`` (:func:`hosts_of`: the components that carry ``b``'s surface); their
    mirror images count for the image half. ``on``: :func:`on_lines` where the caller has it.
    """
    from .assemble import boundary_loops

    if on is None:
        on = on_lines(geometry, vertices)
    out = []
    for loop in boundary_loops(triangles):
        pairs = [on.get(int(x), set()) for x in loop]
        owners = {components[c] for c in np.unique(component[np.isin(triangles, loop)
                                                               .any(axis=1)])}
        for a, b in set().union(*pairs):
            share = np.mean([(a, b) in s for s in pairs])
            hosts = hosts_of(b, components)
            if share >= 0.5 and owners == {a} and hosts:
                out.append((hosts, loop))
                break
    return out
