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
from .predicates import orient3d, segments_hit_triangles, triangles_intersect
from .quality import triangle_angles

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
        if odd and not (self.open_edges or self.nonmanifold_edges):
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
    uniq, inverse = np.unique(pts, axis=0, return_inverse=True)
    return uniq, inverse.ravel()[tri]


def _edges(tri):
    directed = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    und = np.sort(directed, axis=1)
    keys, inverse, uses = np.unique(und, axis=0, return_inverse=True, return_counts=True)
    forward = (directed[:, 0] < directed[:, 1]).astype(float)
    n_forward = np.bincount(inverse.ravel(), weights=forward, minlength=len(keys))
    return keys, inverse.ravel(), uses, n_forward


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
    """Pairs (i < j) of triangles whose bounding boxes overlap (a uniform grid of cells)."""
    p = v[tri]
    lo, hi = p.min(axis=1), p.max(axis=1)
    size = np.median(np.max(hi - lo, axis=1))
    size = size if size > 0 else 1.0
    origin = lo.min(axis=0)
    while True:  # cells of the median triangle's size, larger while long ones fill too many
        c0 = np.floor((lo - origin) / size).astype(np.int64)
        c1 = np.floor((hi - origin) / size).astype(np.int64)
        span = c1 - c0 + 1
        count = span.prod(axis=1)
        if count.sum() <= 8 * len(tri):
            break
        size *= 1.5
    owner = np.repeat(np.arange(len(tri)), count)
    offs = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
    sy, sz = span[owner, 1], span[owner, 2]
    cell = c0[owner] + np.stack([offs // (sy * sz), (offs // sz) % sy, offs % sz], axis=1)
    dims = c1.max(axis=0) + 1
    key = (cell[:, 0] * dims[1] + cell[:, 1]) * dims[2] + cell[:, 2]
    order = np.lexsort((owner, key))
    key, owner = key[order], owner[order]
    # Every pair within a cell, at once: element i of a cell pairs with the ones after it.
    starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    ends = np.r_[starts[1:], key.size]
    end_of = np.repeat(ends, ends - starts)
    after = end_of - np.arange(key.size) - 1
    left = np.repeat(np.arange(key.size), after)
    step = np.arange(left.size) - np.repeat(np.cumsum(after) - after, after) + 1
    a, b = owner[left], owner[left + step]
    overlap = np.all((lo[a] <= hi[b]) & (lo[b] <= hi[a]), axis=1)
    code = np.unique(a[overlap] * np.int64(len(tri)) + b[overlap])
    return np.stack([code // len(tri), code % len(tri)], axis=1)


def self_intersections(vertices, triangles):
    """(k, 2) triangle pairs that intersect (exact predicates; see the module)."""
    v, tri = np.asarray(vertices, float), np.asarray(triangles, np.int64)
    pairs = _candidate_pairs(v, tri)
    if not len(pairs):
        return pairs
    ta, tb = tri[pairs[:, 0]], tri[pairs[:, 1]]
    shared = (ta[:, :, None] == tb[:, None, :])
    n_shared = shared.sum(axis=(1, 2))
    bad = np.zeros(len(pairs), bool)
    none = n_shared == 0
    bad[none] = triangles_intersect(v[ta[none]], v[tb[none]])
    for k, test in ((1, _one_shared), (2, _folded)):
        sel = np.flatnonzero(n_shared == k)
        if sel.size:
            bad[sel] = test(v, ta[sel], tb[sel], shared[sel])
    return pairs[bad]


def _opposite(t, mask):
    """Per row, the vertex ids of t not flagged in mask (k, 3), in order: (k, m) for the m
    unflagged per row (the same m in every row)."""
    return t[~mask].reshape(len(t), -1)


def _one_shared(v, ta, tb, shared):
    """Triangles sharing one vertex cross when the edge of one opposite it meets the other."""
    oa = _opposite(ta, shared.any(axis=2))  # (k, 2)
    ob = _opposite(tb, shared.any(axis=1))
    hit = segments_hit_triangles(v[oa[:, 0]], v[oa[:, 1]], v[tb[:, 0]], v[tb[:, 1]],
                                 v[tb[:, 2]])
    hit |= segments_hit_triangles(v[ob[:, 0]], v[ob[:, 1]], v[ta[:, 0]], v[ta[:, 1]],
                                  v[ta[:, 2]])
    return hit


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


def check_mesh(vertices, triangles, min_angle=0.0):
    """The :class:`CheckReport` of a triangulated surface."""
    v, tri = np.asarray(vertices, float), np.asarray(triangles, np.int64)
    keys, _, uses, n_forward = _edges(tri)
    two = uses == 2
    n_bodies, label = _bodies(len(v), tri)
    used = np.zeros(len(v), bool)
    used[tri.ravel()] = True
    body_of_tri = label[tri[:, 0]]
    body_of_edge = label[keys[:, 0]]
    euler = tuple(int(np.sum(used & (label == b)) - np.sum(body_of_edge == b)
                      + np.sum(body_of_tri == b))
                  for b in range(n_bodies) if used[label == b].any())
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
        examples=examples)
