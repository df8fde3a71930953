"""``juncture check FILE``: is a triangulated surface one a CFD or CAD tool can take?

Checks, each exact (integer vertex ids, or the exact predicates of
:mod:`juncture.surface.predicates`):

- **closed**: every edge in exactly two triangles (open and non-manifold edges counted);
- **oriented**: each such edge used once in each direction;
- **topology**: per connected body, the Euler characteristic V - E + F (2 for a closed
  body without handles) and the genus it implies;
- **volume**: the enclosed (signed) volume is positive (outward normals), and the same when
  the origin moves (a closed surface's volume does not depend on it, to 1e-9);
- **self-intersection**: no two triangles that share no vertex meet, no two that share one
  vertex cross, and no two neighbours across an edge fold onto each other;
- **shape**: the smallest angle (reported; failing only below ``min_angle``).

Files are read by meshio (STL, Gmsh, VTU/VTK, OBJ, PLY, OFF) and their vertices merged where
they are bit-identical (an STL stores each triangle's own corners); nothing is welded by a
tolerance.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import DeckError
from .predicates import orient2d, orient3d, segments_hit_triangles, triangles_intersect
from .quality import triangle_angles
from .rows import unique_pairs, unique_points

__all__ = ["CheckReport", "check_mesh", "read_triangles", "self_intersections"]


@dataclass(frozen=True)
class CheckReport:
    """What :func:`check_mesh` found; ``ok`` when nothing failed."""

    n_vertices: int
    n_triangles: int
    open_edges: int
    nonmanifold_edges: int
    misoriented_edges: int
    bodies: int
    euler: tuple
    volume: float
    volume_shift: float
    intersecting_pairs: int
    min_angle: float
    min_angle_limit: float = 0.0
    examples: dict = field(default_factory=dict)
    #: the handles the surface should have in all (a flow-through nacelle is one)
    handles: int = 0
    #: (k, 2) the triangle pairs that intersect
    pairs: np.ndarray | None = field(default=None, repr=False, compare=False)

    @property
    def ok(self):
        return not self.failures()

    def failures(self):
        """One line per failed check."""
        out = []
        for count, what in ((self.open_edges, "open edges (in one triangle)"),
                            (self.nonmanifold_edges, "edges in more than two triangles"),
                            (self.misoriented_edges, "edges used twice in one direction "
                             "(inconsistent orientation)"),
                            (self.intersecting_pairs, "pairs of triangles that intersect")):
            if count:
                eg = self.examples.get(what)
                out.append(f"{count} {what}" + (f", e.g. {eg}" if eg else ""))
        odd = [e for e in self.euler if e != 2]
        genus = sum((2 - e) // 2 for e in self.euler)
        if self.handles and odd and genus != self.handles and not (
                self.open_edges or self.nonmanifold_edges):
            out.append(f"{genus} handles in all (Euler characteristic "
                       f"{', '.join(map(str, self.euler))}), expected {self.handles}")
        elif odd and not self.handles and not (self.open_edges or self.nonmanifold_edges):
            out.append(f"{len(odd)} of {self.bodies} closed bodies are not spheres (Euler "
                       f"characteristic {', '.join(map(str, odd))}; genus "
                       f"{', '.join(str((2 - e) // 2) for e in odd)})")
        if not self.volume > 0:
            out.append(f"enclosed volume {self.volume:.6g} <= 0 (normals point inward)")
        if abs(self.volume_shift) > 1e-9 * max(abs(self.volume), 1e-300):
            out.append(f"the volume changes by {self.volume_shift:.3g} when the origin moves "
                       "(the surface is not closed)")
        if self.min_angle < self.min_angle_limit:
            out.append(f"smallest angle {self.min_angle:.3g} deg < {self.min_angle_limit:g}")
        return out

    def lines(self):
        """The report: what the mesh is, then ``FAIL: ...`` lines."""
        head = [f"{self.n_triangles} triangles, {self.n_vertices} vertices, {self.bodies} "
                f"bodies (Euler characteristic {', '.join(map(str, self.euler))})",
                f"enclosed volume {self.volume:.10g}",
                f"smallest angle {self.min_angle:.3g} deg",
                f"self-intersection: {self.intersecting_pairs} intersecting pairs (exact "
                "predicates)"]
        return head + [f"FAIL: {f}" for f in self.failures()]


def read_triangles(path):
    """``(vertices (n, 3), triangles (m, 3))`` of a mesh file, bit-identical points merged."""
    import meshio

    path = Path(path)
    if not path.is_file():
        raise DeckError("no such file" if not path.exists() else "not a file", path=path)
    import warnings

    try:
        with warnings.catch_warnings():  # meshio's STL sniffing overflows on small files
            warnings.simplefilter("ignore", RuntimeWarning)
            m = meshio.read(path)
    except Exception as exc:  # noqa: BLE001 - meshio raises many kinds on a bad file
        raise DeckError(f"cannot read it as a mesh ({type(exc).__name__}: "
                        f"{' '.join(str(exc).split())})", path=path) from None
    tris = [c.data for c in m.cells if c.type == "triangle"]
    if not tris:
        kinds = ", ".join(c.type for c in m.cells) or "none"
        raise DeckError(f"holds no triangles (cells: {kinds})", path=path)
    pts = np.asarray(m.points, float)[:, :3]
    tri = np.concatenate(tris).astype(np.int64)
    uniq, inverse = unique_points(pts + 0.0, return_inverse=True)
    return uniq, inverse[tri]


def _edges(tri):
    directed = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    und = np.sort(directed, axis=1)
    keys, inverse, uses = unique_pairs(und, return_inverse=True, return_counts=True)
    forward = (directed[:, 0] < directed[:, 1]).astype(float)
    n_forward = np.bincount(inverse, weights=forward, minlength=len(keys))
    return keys, inverse, uses, n_forward


def _bodies(n_vertices, tri):
    """Connected components of the triangles (through shared vertices): labels per vertex."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    rows = np.concatenate([tri[:, 0], tri[:, 1], tri[:, 2]])
    cols = np.concatenate([tri[:, 1], tri[:, 2], tri[:, 0]])
    graph = coo_matrix((np.ones(rows.size), (rows, cols)), shape=(n_vertices, n_vertices))
    return connected_components(graph, directed=False)


def _volume(p):
    return float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0)


def _candidate_pairs(v, tri):
    """Pairs (i < j) of triangles whose bounding boxes overlap: a bounding-volume tree over
    the triangles in Morton order of their box centres, walked pairwise level by level (a
    node pair is opened only where the two boxes overlap), so the work follows the pairs
    found, whatever the spread of triangle sizes (a uniform grid repeats a long triangle's
    pairs in every cell it covers)."""
    lo, hi, order = _leaf_boxes(v, tri)
    i = j = np.zeros(1, np.int64)
    for lo_k, hi_k in _tree_boxes(lo, hi)[1:]:
        i, j = _children(i, j)
        keep = _overlap(lo_k, hi_k, i, lo_k, hi_k, j)
        i, j = i[keep], j[keep]
    a, b = order[i[i != j]], order[j[i != j]]
    a, b = np.minimum(a, b), np.maximum(a, b)
    rows = np.lexsort((b, a))
    return np.stack([a[rows], b[rows]], axis=1)


def _overlap(lo_a, hi_a, i, lo_b, hi_b, j):
    """(k,) bool: box i of (lo_a, hi_a) overlaps box j of (lo_b, hi_b) (np.take: several
    times faster than fancy indexing on these (n, 3) arrays)."""
    la, ha = np.take(lo_a, i, axis=0), np.take(hi_a, i, axis=0)
    lb, hb = np.take(lo_b, j, axis=0), np.take(hi_b, j, axis=0)
    ok = (la <= hb) & (lb <= ha)
    return ok[:, 0] & ok[:, 1] & ok[:, 2]


def _leaf_boxes(v, tri, at_least=0):
    """Triangle boxes (lo, hi) in Morton order of their centres (10 bits an axis), padded
    to a power of two (of at least ``at_least`` boxes) with empty boxes (lo = inf > hi =
    -inf, overlapping nothing), and that order."""
    p = v[tri]
    lo, hi = p.min(axis=1), p.max(axis=1)
    centre = 0.5 * (lo + hi)
    low = centre.min(axis=0) if len(tri) else np.zeros(3)
    span = np.ptp(centre, axis=0).max() if len(tri) else 1.0
    cell = np.floor((centre - low) / (span if span > 0 else 1.0) * 1023.0).astype(np.int64)
    code = np.zeros(len(tri), np.int64)
    for bit in range(10):
        for axis in range(3):
            code |= ((cell[:, axis] >> bit) & 1) << (3 * bit + axis)
    order = np.argsort(code, kind="stable")
    size = 1 << max(1, int(np.ceil(np.log2(max(len(tri), at_least, 2)))))
    out_lo, out_hi = np.full((size, 3), np.inf), np.full((size, 3), -np.inf)
    out_lo[:len(tri)], out_hi[:len(tri)] = lo[order], hi[order]
    return out_lo, out_hi, order


def _tree_boxes(lo, hi):
    """[(lo, hi), ...] per level from the root (one box) to the leaves, each node's box the
    union of its two children's."""
    levels = []
    while len(lo) > 1:
        levels.append((lo, hi))
        lo = np.minimum(lo[0::2], lo[1::2])
        hi = np.maximum(hi[0::2], hi[1::2])
    levels.append((lo, hi))
    return levels[::-1]


def _children(i, j):
    """The child pairs of node pairs (i, j), i <= j, one level down: a node with itself
    gives its two children each with itself and with each other, two nodes the four
    pairs of their children."""
    same = i == j
    si, di, dj = i[same], i[~same], j[~same]
    ci = np.concatenate([2 * si, 2 * si, 2 * si + 1,
                         2 * di, 2 * di, 2 * di + 1, 2 * di + 1])
    cj = np.concatenate([2 * si, 2 * si + 1, 2 * si + 1,
                         2 * dj, 2 * dj + 1, 2 * dj, 2 * dj + 1])
    return ci, cj


#: Candidate pairs tested at once (a surface with long triangles across others, a strip
#: zipped across a wing, gave 40 million: MemoryError under a 6 GB limit).
PAIR_BLOCK = 1 << 20


def self_intersections(vertices, triangles):
    """(k, 2) triangle pairs that intersect (exact predicates; see the module).

    Where the surface is its own mirror image in y = 0 but for a few triangles
    (:func:`juncture.surface.mirror.triangle_mirror`; both halves are triangulated once),
    only the pairs with a point at y >= 0 are searched, and those found are given with
    their images: a triangle holding a point at y >= 0 has a corner there, so such a pair
    lies among the mirrored triangles with a corner at y >= 0 and the ones with no image
    (a blunt base's cap across the plane); a pair meeting at y < 0 is the image of one
    meeting at y > 0, unless one of its triangles has no image: those are searched against
    the triangles wholly at y < 0 too."""
    from .mirror import triangle_mirror

    v, tri = np.asarray(vertices, float), np.asarray(triangles, np.int64)
    image = triangle_mirror(v, tri)
    lone = image < 0
    if not len(tri) or lone.mean() > MIRROR_SHARE:
        return _search(v, tri, _candidate_pairs(v, tri))
    upper = ~lone & np.any(v[tri][:, :, 1] >= 0.0, axis=1)
    sub = np.flatnonzero(upper | lone)
    pairs = np.concatenate([sub[_candidate_pairs(v, tri[sub])],
                            _box_pairs(v, tri, np.flatnonzero(lone),
                                       np.flatnonzero(~upper & ~lone))])
    found = _search(v, tri, pairs)
    both = found[np.all(image[found] >= 0, axis=1)]
    return unique_pairs(np.sort(np.concatenate([found, image[both]]), axis=1))


#: A surface with more than this share of its triangles without a mirror image is searched
#: whole (see :func:`self_intersections`).
MIRROR_SHARE = 0.05


def _search(v, tri, pairs):
    """The candidate ``pairs`` that intersect, in blocks of :data:`PAIR_BLOCK`."""
    if len(pairs) <= PAIR_BLOCK:
        return _intersecting(v, tri, pairs)
    return np.concatenate([_intersecting(v, tri, pairs[i:i + PAIR_BLOCK])
                           for i in range(0, len(pairs), PAIR_BLOCK)])


def _box_pairs(v, tri, few, many):
    """Pairs (i < j) of a triangle of ``few`` and one of ``many`` whose boxes overlap: a
    tree over each set (:func:`_leaf_boxes`, padded to the same size), walked together
    level by level, a node pair opened only where the two boxes overlap."""
    if not len(few) or not len(many):
        return np.zeros((0, 2), np.int64)
    size = max(len(few), len(many))
    lo_a, hi_a, order_a = _leaf_boxes(v, tri[few], size)
    lo_b, hi_b, order_b = _leaf_boxes(v, tri[many], size)
    i = j = np.zeros(1, np.int64)
    for (la, ha), (lb, hb) in list(zip(_tree_boxes(lo_a, hi_a), _tree_boxes(lo_b, hi_b)))[1:]:
        i = (2 * i[:, None] + [0, 0, 1, 1]).ravel()     # the four pairs of their children
        j = (2 * j[:, None] + [0, 1, 0, 1]).ravel()
        keep = _overlap(la, ha, i, lb, hb, j)
        i, j = i[keep], j[keep]
    a, b = few[order_a[i]], many[order_b[j]]
    return np.stack([np.minimum(a, b), np.maximum(a, b)], axis=1)


def _intersecting(v, tri, pairs):
    """The candidate ``pairs`` whose triangles intersect."""
    if not len(pairs):
        return pairs
    ta, tb = tri[pairs[:, 0]], tri[pairs[:, 1]]
    shared = (ta[:, :, None] == tb[:, None, :])
    n_shared = shared.sum(axis=(1, 2))
    bad = np.zeros(len(pairs), bool)
    none = np.flatnonzero(n_shared == 0)
    none = none[~_apart(v[ta[none]], v[tb[none]])] if none.size else none
    bad[none] = triangles_intersect(v[ta[none]], v[tb[none]])
    one = np.flatnonzero(n_shared == 1)
    one = one[~_apart_at(v, ta[one], tb[one], shared[one])] if one.size else one
    for sel, test in ((one, _one_shared), (np.flatnonzero(n_shared == 2), _folded)):
        if sel.size:
            bad[sel] = test(v, ta[sel], tb[sel], shared[sel])
    return pairs[bad]


#: A float projection decides only by more than this share of the size of the points
#: projected (times the axis' length); its rounding is some 1e-16 of that.
MARGIN = 1e-10


def _separated(pa, pb, axes, origin, touching=False):
    """(k,) bool, a sufficient test in floats: on some axis (k, n, 3), the points pa (k, m,
    3) project all below those of pb, or all above, by more than :data:`MARGIN` (any axis
    serves; the margin covers the rounding); with ``touching``, on either side of
    ``origin`` (k, 3), the point both share."""
    def project(p):
        q = p - origin[:, None]
        return sum(q[:, :, None, j] * axes[:, None, :, j] for j in range(3))   # (k, m, n)

    da, db = project(pa), project(pb)
    size = np.maximum(np.abs(pa).max(axis=(1, 2)), np.abs(pb).max(axis=(1, 2)))
    tol = MARGIN * np.abs(axes).sum(axis=2) * size[:, None]      # (k, n), |axis|_1 >= |axis|
    lo_a, hi_a, lo_b, hi_b = da.min(1), da.max(1), db.min(1), db.max(1)
    if touching:
        gap = np.maximum(np.minimum(lo_b, -hi_a), np.minimum(lo_a, -hi_b))
    else:
        gap = np.maximum(lo_b - hi_a, lo_a - hi_b)
    return np.any(gap > tol, axis=1)


def _apart(pa, pb):
    """(k,) bool: triangles pa, pb (k, 3, 3) that certainly do not meet (a float test with
    a margin, :func:`_separated`; the exact predicates decide the rest), tried where their
    planes are parallel (:func:`_parallel`): one's plane or an edge's line in it (the axis
    across the edge in that plane) has the other on its far side. Flat panels in one plane
    are mostly told apart here, before predicates that could decide them only exactly."""
    na = np.cross(pa[:, 1] - pa[:, 0], pa[:, 2] - pa[:, 0])
    nb = np.cross(pb[:, 1] - pb[:, 0], pb[:, 2] - pb[:, 0])
    out = np.zeros(len(pa), bool)
    i = np.flatnonzero(_parallel(na, nb))
    pa, pb, na, nb = pa[i], pb[i], na[i], nb[i]
    axes = [na, nb] + [np.cross(n, p[:, (k + 1) % 3] - p[:, k])
                       for n, p in ((na, pa), (nb, pb)) for k in range(3)]
    out[i] = _separated(pa, pb, np.stack(axes, axis=1), pa[:, 0])
    return out


def _parallel(na, nb):
    """(k,) bool: normals within about 1e-6 rad of parallel (or a degenerate one): the
    pairs the exact predicates could decide only slowly, worth a float test first."""
    cross = np.abs(np.cross(na, nb)).sum(axis=1)
    return cross <= 1e-6 * np.abs(na).sum(axis=1) * np.abs(nb).sum(axis=1)


def _apart_at(v, ta, tb, shared):
    """(k,) bool: triangles that share one vertex and certainly meet nowhere else (a plane
    through it has the rest of one on each side, :func:`_separated`), tried where their
    planes are parallel: in that plane, the lines through the shared vertex halfway between
    an edge of each."""
    s = v[ta[shared.any(axis=2)]]
    pa = v[_opposite(ta, shared.any(axis=2))]      # (k, 2, 3)
    pb = v[_opposite(tb, shared.any(axis=1))]
    na = np.cross(pa[:, 0] - s, pa[:, 1] - s)
    nb = np.cross(pb[:, 0] - s, pb[:, 1] - s)
    out = np.zeros(len(s), bool)
    i = np.flatnonzero(_parallel(na, nb))
    s, pa, pb, na, nb = s[i], pa[i], pb[i], na[i], nb[i]
    unit = lambda e: e / np.maximum(np.linalg.norm(e, axis=-1, keepdims=True), 1e-300)  # noqa
    ua, ub = unit(pa - s[:, None]), unit(pb - s[:, None])
    axes = [np.cross(na, ua[:, k] + ub[:, m]) for k in (0, 1) for m in (0, 1)]
    out[i] = _separated(pa, pb, np.stack(axes, axis=1), s, touching=True)
    return out


def _opposite(t, mask):
    """Per row, the vertex ids of t not flagged in mask (k, 3), in order: (k, m) for the m
    unflagged per row (the same m in every row)."""
    return t[~mask].reshape(len(t), -1)


def _one_shared(v, ta, tb, shared):
    """Triangles sharing one vertex cross when the edge of one opposite it meets the other.
    Where the rest of one lies strictly on one side of the other's plane they meet only at
    the shared vertex (the most of them, neighbours on a surface): decided by those two
    signs alone."""
    oa = _opposite(ta, shared.any(axis=2))  # (k, 2)
    ob = _opposite(tb, shared.any(axis=1))
    hit = np.zeros(len(ta), bool)
    b_side = [orient3d(v[ta[:, 0]], v[ta[:, 1]], v[ta[:, 2]], v[ob[:, k]]) for k in (0, 1)]
    rest = np.flatnonzero(b_side[0] * b_side[1] <= 0)
    a_side = [orient3d(v[tb[rest, 0]], v[tb[rest, 1]], v[tb[rest, 2]], v[oa[rest, k]])
              for k in (0, 1)]
    rest = rest[a_side[0] * a_side[1] <= 0]
    if rest.size:
        hit[rest] = _one_shared_exact(v, ta[rest], tb[rest], shared[rest], oa[rest], ob[rest])
    return hit


def _one_shared_exact(v, ta, tb, shared, oa, ob):
    """:func:`_one_shared` for the pairs the planes' signs do not decide (``oa``, ``ob``:
    each triangle's two vertices but the shared one)."""
    hit = segments_hit_triangles(v[oa[:, 0]], v[oa[:, 1]], v[tb[:, 0]], v[tb[:, 1]],
                                 v[tb[:, 2]])
    hit |= segments_hit_triangles(v[ob[:, 0]], v[ob[:, 1]], v[ta[:, 0]], v[ta[:, 1]],
                                  v[ta[:, 2]])
    s = v[ta[shared.any(axis=2)]]
    pa, pb = v[oa], v[ob]
    flat = np.ones(len(s), bool)
    for k in (0, 1):          # the rest of b in a's plane: the segment tests see no crossing
        flat &= orient3d(s, pa[:, 0], pa[:, 1], pb[:, k]) == 0
    i = np.flatnonzero(flat & ~hit)
    if i.size:
        hit[i] = _cones_overlap(s[i], pa[i], pb[i])
    return hit


def _cones_overlap(s, pa, pb):
    """(k,) bool for triangles (s, pa) and (s, pb) in one plane sharing the corner s (pa, pb:
    (k, 2, 3)): they overlap beyond s exactly when an edge from s of one lies in the other's
    (closed) angle at s (exact: orient2d in the plane's best 2-D projection). Triangles of
    no area are left to the other tests."""
    n = np.abs(np.cross(pa[:, 0] - s, pa[:, 1] - s) + np.cross(pb[:, 0] - s, pb[:, 1] - s))
    keep = np.array([[1, 2], [0, 2], [0, 1]])[np.argmax(n, axis=1)]
    take = lambda p: np.take_along_axis(p, keep, axis=1)  # noqa: E731
    s2 = take(s)
    out = np.zeros(len(s), bool)
    for (p, q), others in (((pa[:, 0], pa[:, 1]), pb), ((pb[:, 0], pb[:, 1]), pa)):
        p2, q2 = take(p), take(q)
        turn = orient2d(s2, p2, q2)
        for k in (0, 1):
            r2 = take(others[:, k])
            out |= ((turn != 0) & (orient2d(s2, p2, r2) * turn >= 0)
                    & (orient2d(s2, r2, q2) * turn >= 0))
    return out


def _folded(v, ta, tb, shared):
    """Neighbours across an edge fold onto each other: coplanar, on the same side of it."""
    ea = _opposite(ta, ~shared.any(axis=2))  # the shared edge, as in ta
    a3 = _opposite(ta, shared.any(axis=2))[:, 0]
    b3 = _opposite(tb, shared.any(axis=1))[:, 0]
    p, q = v[ea[:, 0]], v[ea[:, 1]]
    coplanar = orient3d(p, q, v[a3], v[b3]) == 0
    # same side of the edge within the plane: the two normals point the same way
    na = np.cross(q - p, v[a3] - p)
    nb = np.cross(q - p, v[b3] - p)
    return coplanar & (np.einsum("ij,ij->i", na, nb) > 0)


def check_mesh(vertices, triangles, min_angle=0.0, handles=0):
    """The :class:`CheckReport` of a triangulated surface: with ``handles``, its bodies
    together have that many (a flow-through nacelle's duct is one), else each is a
    sphere."""
    v, tri = np.asarray(vertices, float), np.asarray(triangles, np.int64)
    keys, _, uses, n_forward = _edges(tri)
    two = uses == 2
    n_bodies, label = _bodies(len(v), tri)
    used = np.zeros(len(v), bool)
    used[tri.ravel()] = True
    count = lambda ids: np.bincount(ids, minlength=n_bodies)  # noqa: E731
    chi = count(label[used]) - count(label[keys[:, 0]]) + count(label[tri[:, 0]])
    euler = tuple(int(e) for e in chi[np.unique(label[used])])
    p = v[tri]
    vol = _volume(p)
    shift = np.ptp(v, axis=0) + 1.0
    moved = _volume(p + shift)
    pairs = self_intersections(v, tri)
    angles = triangle_angles(v, tri)
    examples = {}
    if len(pairs):
        i, j = pairs[0]
        examples["pairs of triangles that intersect"] = (
            f"triangles {i} and {j} near {np.round(p[i].mean(axis=0), 6).tolist()}")
    if np.any(uses == 1):
        e = keys[np.argmax(uses == 1)]
        examples["open edges (in one triangle)"] = f"at {np.round(v[e[0]], 6).tolist()}"
    return CheckReport(
        n_vertices=int(used.sum()), n_triangles=int(len(tri)),
        open_edges=int(np.sum(uses == 1)), nonmanifold_edges=int(np.sum(uses > 2)),
        misoriented_edges=int(np.sum(two & (n_forward != 1))), bodies=len(euler), euler=euler,
        volume=vol, volume_shift=moved - vol, intersecting_pairs=int(len(pairs)),
        min_angle=float(angles.min()) if len(tri) else 0.0, min_angle_limit=float(min_angle),
        examples=examples, pairs=pairs, handles=int(handles))
