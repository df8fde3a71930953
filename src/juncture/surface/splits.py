"""Points added on the seams of a re-triangulation, shared by every patch that has them.

:class:`Splits` holds the growing vertex array and, per input edge, the points added on it
(one id per fraction, whichever patch made it), so that both sides of a seam take the same
points. :func:`seam_lift` moves a split point onto the exact surface where the surfaces on
both sides agree; :func:`fans` takes split points into a patch that keeps its triangles;
:func:`edge_points` finds the points PythonCDT put on a chart's boundary pieces, each on its
original edge.
"""

from __future__ import annotations

import numpy as np

from .chart import patch_edges
from .patches import SUPER

__all__ = ["Splits", "edge_points", "fans", "seam_lift", "SAME_T"]

#: Split points closer than this fraction of their edge are one point.
SAME_T = 1e-6
_NONE = (np.zeros(0), np.zeros(0, int))


class Splits:
    """The vertices, growing, and the points added on edges: one id per (edge, fraction),
    shared by every patch that has the edge."""

    def __init__(self, vertices, move=None, mirror=None, edges=None):
        self._xyz = np.array(vertices, float)
        self.move = move                 # move(a, b, points): seam points onto the surface
        self.pending = []                # (a, b, id) of split points not yet moved
        self.n = len(vertices)
        self.on = {}                     # (a, b) with a < b -> {t: id}, t from a
        self._sorted = {}                # (a, b) -> (fractions, ids), sorted, as last asked
        # the vertex at each one's mirror image (-1: none), and the input edges (a < b):
        # a point split on an edge is split on its mirror image too (juncture.surface.mirror)
        self.mirror = None if mirror is None else np.array(mirror, np.int64)
        self.edges = edges

    def add_vertex(self, p):
        p = np.atleast_2d(p)
        if self.n + len(p) > len(self._xyz):
            grown = np.empty((2 * (self.n + len(p)), 3))
            grown[:self.n] = self._xyz[:self.n]
            self._xyz = grown
            if self.mirror is not None:
                self.mirror = np.concatenate([self.mirror,
                                              np.full(len(grown) - len(self.mirror), -1)])
        ids = np.arange(self.n, self.n + len(p))
        self._xyz[ids] = p
        if self.mirror is not None:
            self.mirror[ids] = -1
        self.n += len(p)
        return ids

    def _add_one(self, p):
        """:meth:`add_vertex` of one point (3,): its id."""
        if self.n == len(self._xyz):
            return int(self.add_vertex(p)[0])
        self._xyz[self.n] = p
        if self.mirror is not None:
            self.mirror[self.n] = -1
        self.n += 1
        return self.n - 1

    def split(self, a, b, t):
        """The id of the point at fraction t from a on edge (a, b), made (with its mirror
        image) if new."""
        new = self._split(a, b, t)
        if self.mirror is None:
            return new
        ma, mb = int(self.mirror[a]), int(self.mirror[b])
        if ma < 0 or mb < 0:
            return new
        if (ma, mb) == (a, b):          # an edge in the plane: the point is its own image
            self.mirror[new] = new
        elif (ma, mb) == (b, a):        # an edge across the plane: the point at 1 - t
            other = self._split(a, b, 1.0 - t)
            self.mirror[new], self.mirror[other] = other, new
        elif (min(ma, mb), max(ma, mb)) in self.edges:
            other = self._split(ma, mb, t)
            self.mirror[new], self.mirror[other] = other, new
        return new

    def _split(self, a, b, t):
        """The id of the point at fraction t from a on edge (a, b), made if new."""
        if a > b:
            a, b, t = b, a, 1.0 - t
        got = self.on.setdefault((a, b), {})
        # Two patches that split one edge at its middle find fractions a few ulps apart.
        for x, i in got.items():
            if abs(t - x) < SAME_T:
                return i
        pa, pb = self._xyz[a], self._xyz[b]
        got[t] = self._add_one(pa + t * (pb - pa))
        self._sorted.pop((a, b), None)
        self.pending.append((a, b, got[t]))
        return got[t]

    def settle(self):
        """Move the split points made since the last call onto the surface (``move``)."""
        if self.move is not None and self.pending:
            a, b, ids = (np.array(c) for c in zip(*self.pending))
            self._xyz[ids] = self.move(a, b, self._xyz[ids])
        self.pending = []

    def along(self, a, b):
        """(fractions from a, ids) of the points on edge (a, b), in order from a."""
        key = (a, b) if a < b else (b, a)
        if key not in self.on:
            return _NONE
        if key not in self._sorted:
            got = self.on[key]
            t = np.array(sorted(got))
            self._sorted[key] = (t, np.array([got[x] for x in t]))
        t, ids = self._sorted[key]
        return (t, ids) if a < b else (1.0 - t[::-1], ids[::-1])

    def count(self, keys):
        """How many split points lie on the edges ``keys`` ((a, b) with a < b)."""
        on = self.on
        return sum(len(on[k]) for k in keys if k in on)

    def all(self):
        return self._xyz[:self.n]


def fans(triangles, splits):
    """Triangles (global ids) of a patch that keeps its own ``triangles``, with the split
    points on their edges taken in: a triangle with points on an edge becomes the fan from
    the opposite corner over them, and each piece again while it has points on an edge."""
    out, todo = [], [tuple(t) for t in np.asarray(triangles).tolist()]
    while todo:
        t = todo.pop()
        for k in range(3):
            a, b, c = t[k], t[(k + 1) % 3], t[(k + 2) % 3]
            ids = splits.along(a, b)[1].tolist()
            if ids:
                chain = [a, *ids, b]
                todo.extend((p, q, c) for p, q in zip(chain[:-1], chain[1:]))
                break
        else:
            out.append(t)
    return np.array(out, np.int64).reshape(-1, 3)


def seam_lift(mesh, lift):
    """``move(a, b, points)`` for split points on the input edges (a, b): onto the exact
    surface where both triangles on the edge lift a point to the same place (a split
    between two blocks of one body: a straight edge between stations cuts the circle);
    elsewhere (an intersection line, whose two sides would lift it apart) it stays on the
    edge. ``move.agree(a, b)`` says on which input edges both sides agree. None without
    ``lift``."""
    if lift is None:
        return None
    tri = np.asarray(mesh.triangles)
    n = len(mesh.vertices)
    _, und, uses, inverse = patch_edges(tri)
    rows = np.tile(np.arange(len(tri)), 3)
    order = np.argsort(inverse, kind="stable")
    first = np.searchsorted(inverse[order], np.arange(len(und)))
    two = uses == 2                                    # the edge's two triangles
    pair = np.stack([rows[order][first], rows[order][np.minimum(first + 1, len(rows) - 1)]],
                    axis=1)
    key = und[:, 0] * n + und[:, 1]

    def both(a, b, points):
        """(points lifted by the triangle on one side, by the other, both sides exist)."""
        k = np.searchsorted(key, np.minimum(a, b) * n + np.maximum(a, b))
        ok = two[k]
        r = pair[k].T.ravel()                  # both sides at once: one lift per surface
        on, at = np.tile(ok, 2), np.concatenate([points, points])
        comp, surf = mesh.component[r], mesh.surface[r]
        out = at.copy()
        for c, s in set(zip(comp[on].tolist(), surf[on].tolist())):
            sel = on & (comp == c) & (surf == s)
            out[sel] = lift(at[sel], tri[r[sel]], c, s)
        return out[:len(points)], out[len(points):], ok

    def move(a, b, points):
        one, other, ok = both(a, b, points)
        same = ok & np.all(one == other, axis=1)
        return np.where(same[:, None], one, points)

    def agree(a, b):
        """(k,) bool: the input edges (a, b) on which both sides lift a point to the same
        place (tried at their middles): a split point there lies on the exact surface, or
        stays on an edge of it (a split within one body, a wing's leading edge, a body's
        straight generator). Not an intersection line: its two sides lift apart."""
        a, b = np.asarray(a, np.int64), np.asarray(b, np.int64)
        if not len(a):
            return np.zeros(0, bool)
        xyz = np.asarray(mesh.vertices, float)
        one, other, ok = both(a, b, 0.5 * (xyz[a] + xyz[b]))
        return ok & np.all(one == other, axis=1)

    move.agree = agree
    return move


def edge_points(tri, n, cons, parent, uv, pts):
    """{new vertex: (global i, global j, fraction from i)} for the new vertices PythonCDT
    put on constraint pieces, each on the piece's original edge."""
    if tri.fixed_edges_count() == len(cons):   # no piece was split
        return {}
    found = {}                                  # new vertex: its original piece's ends
    for sub, originals in tri.piece_to_originals_iter():
        for v in (sub.v1 - SUPER, sub.v2 - SUPER):
            if v >= n and v not in found:
                found[v] = (originals[0].v1 - SUPER, originals[0].v2 - SUPER)
    if not found:
        return {}
    ends = np.array(list(found.values()), np.int64)
    rows = _pieces_of(cons, ends, len(uv)).tolist()
    out = {}
    for v, k in zip(found, rows):
        a, b = (int(x) for x in cons[k])
        d = uv[b] - uv[a]
        s = float(np.clip((pts[v] - uv[a]) @ d / (d @ d), 0.0, 1.0))
        ta, tb = float(parent[2][k]), float(parent[3][k])
        out[v] = (int(parent[0][k]), int(parent[1][k]), ta + s * (tb - ta))
    return out


def _pieces_of(cons, ends, n):
    """(k,) the row of ``cons`` that joins each pair of ``ends`` (k, 2), either way round
    (the last such row where two do)."""
    key = np.minimum(cons[:, 0], cons[:, 1]).astype(np.int64) * n + np.maximum(cons[:, 0],
                                                                                cons[:, 1])
    order = np.argsort(key, kind="stable")
    want = np.minimum(ends[:, 0], ends[:, 1]) * n + np.maximum(ends[:, 0], ends[:, 1])
    return order[np.searchsorted(key[order], want, side="right") - 1]
