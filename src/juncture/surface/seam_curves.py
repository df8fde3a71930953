"""Seams that follow the exact curve where a wing-like component meets its host.

An intersection line is known at the points juncture computed (where the component's
lofting lines meet the host, TM-4406, and where the layout's body stations meet the
component); the assembled surface joins two of them by a straight edge, which cuts the
exact curve by its sag (up to 0.22 ft on the transport's wing root, 7e-4 of its length).
:func:`follow_curves` splits such edges, before the re-triangulation
(:func:`juncture.surface.pipeline.finish`), until the curve's middle between two
neighbouring points lies within :data:`SAG` of the airplane's size of their chord. A new
point keeps the chord fraction of its place on the edge and follows the component's
surface at that fraction (its section curve, ruled spanwise between sections and extended
beyond them as TM-4406 eq 4 extends the lofting lines) along the span to the host (a
secant search on the host's error function), so it lies on both exact surfaces. Hosts: a
circular or arbitrary fuselage or pod. A wing-like host (a pylon under a wing, a fin on a
tail) is left out: followed there, the transport's wing took triangles of 1.3 deg beside
its pylons' footprints (8.6 deg the worst on its chords).

An edge is on a curve where both its ends lie on one side of the component's exact surface
and on the host (to :data:`ON` of the airplane's size), directly or as mirror images, and a
point moves by at most :data:`REACH` of its edge's length (an edge across the footprint,
between two points of the same line, is not the line).
"""

from __future__ import annotations

import numpy as np

__all__ = ["seam_curves", "SeamCurves", "curve_edges", "follow_curves", "ON", "REACH", "SAG"]

#: A vertex lies on an exact surface within this share of the airplane's size.
ON = 1e-9
#: A split point moves onto the curve by at most this share of its edge's length (a chord
#: of a curve of radius R sags h / (8 R) of its length h: 0.013 for the transport's longest;
#: the move is along the span, longer than the sag where the curve runs at a shallow angle
#: to it: 9 % beside a thick swept root's leading edge on a held-out airplane, whose seam
#: kept its chords there with 5 %, 6e-4 of the size off the curve).
REACH = 0.15
#: Default largest sag of a seam piece's chord from the exact curve, share of the size
#: (issue 12: exact points midway between seam vertices within 1e-6 of it from the mesh).
SAG = 1e-6
#: A seam piece shorter than this share of the size is not split again.
PIECE = 1e-5
#: Secant steps of the spanwise search, and its start step (share of the edge's length).
STEPS = 40
START = 1e-3


def _pairs(geometry, mesh):
    """(wing-like model, body, the body's error function) of every wing-like component and
    every body of the geometry."""
    from ..model import ArbitraryBody, CircularBody, WingLike

    comps = list(getattr(geometry, "configuration", None) or ())
    wings = [c for c in comps if isinstance(c, WingLike)]
    bodies = [c for c in comps if isinstance(c, (CircularBody, ArbitraryBody))]
    return [(w, b, _error(b)) for w in wings for b in bodies]


def _error(body):
    """The body's error function: negative inside, zero on the surface."""
    from ..model import CircularBody

    if isinstance(body, CircularBody):
        return body.radial_error
    return body.signed_distance


def _box(model, size):
    """(2, 3) the model's networks' box, grown by a tenth of ``size`` and, for a wing-like
    component, its longest chord: its intersection points lie in it, its lofting lines
    extended to its host included."""
    from ..model import WingLike

    nets = model.networks()
    pts = np.concatenate([n.reshape(-1, 3) for n in nets.values()])
    reach = 0.1 * size + (float(np.max(model.chord)) if isinstance(model, WingLike) else 0.0)
    return np.stack([pts.min(axis=0) - reach, pts.max(axis=0) + reach])


def _fraction(wing, p):
    """Chord fractions of points ``p`` (k, 3) at their span stations (the ruled surface's
    leading and trailing edges, extended beyond the end sections)."""
    from .lift import edges_x

    le, te = edges_x(wing, p[:, wing.span_axis], extrapolate=True)
    return (p[:, 0] - le) / np.where(te > le, te - le, np.nan)


class SeamCurves:
    """The exact intersection curves of a mesh's wing-like components and bodies.

    ``lines``: one entry per curve, (the wing-like model, its side, the host's error
    function, the mirror flip (3,), a (n_vertices,) bool of the mesh's vertices on it)."""

    def __init__(self, vertices, lines, size):
        self.vertices = np.asarray(vertices, float)
        self.lines = lines
        self.size = size

    def on_curve(self, a, b):
        """(k,) index into ``lines`` of the curve edges (a, b) lie on, -1 for none."""
        a, b = np.asarray(a, np.int64), np.asarray(b, np.int64)
        out = np.full(len(a), -1)
        for k, (*_, mask) in enumerate(self.lines):
            out = np.where((out < 0) & mask[a] & mask[b], k, out)
        return out

    def follows(self, a, b, tol):
        """(k,) bool: the edges (a, b) on a curve whose chord's middle lies within ``tol`` of
        the curve (followed, :func:`follow_curves`), or that are no longer than
        :data:`PIECE` of the size (not split again)."""
        a, b = np.asarray(a, np.int64), np.asarray(b, np.int64)
        out = np.zeros(len(a), bool)
        which = self.on_curve(a, b)
        h = np.linalg.norm(self.vertices[b] - self.vertices[a], axis=1)
        mid = 0.5 * (self.vertices[a] + self.vertices[b])
        for k in np.unique(which[which >= 0]):
            sel = np.flatnonzero(which == k)
            wing, side, error, flip, _ = self.lines[k]
            got = _onto(wing, side, error, mid[sel] * flip, h[sel], self.size) * flip
            with np.errstate(invalid="ignore"):
                out[sel] = np.linalg.norm(got - mid[sel], axis=1) <= tol
        return out | ((which >= 0) & (h <= PIECE * self.size))

    def __call__(self, a, b, points):
        """``points`` split on edges (a, b) moved onto the exact curve where the edge lies on
        one (and the point moves by at most :data:`REACH` of the edge), else as they are."""
        points = np.array(points, float)
        which = self.on_curve(a, b)
        h = np.linalg.norm(self.vertices[b] - self.vertices[a], axis=1)
        for k in np.unique(which[which >= 0]):
            sel = np.flatnonzero(which == k)
            wing, side, error, flip, _ = self.lines[k]
            got = _onto(wing, side, error, points[sel] * flip, h[sel], self.size) * flip
            near = np.linalg.norm(got - points[sel], axis=1) <= REACH * h[sel]
            points[sel[near]] = got[near]
        return points

    def sagging(self, edges, tol):
        """{edge index: fractions from its first end} at which the ``edges`` (k, 2) on a
        curve are split so that every piece's chord lies within ``tol`` of the curve at its
        middle (halving pieces), but none shorter than :data:`PIECE` of the size (at a kink
        of the curve, where a fin's root meets a fuselage's shoulder on one held-out
        airplane, halving went on to pieces 1.4e-8 ft long, their triangles 1e-4 deg)."""
        edges = np.asarray(edges, np.int64).reshape(-1, 2)
        on = np.flatnonzero(self.on_curve(edges[:, 0], edges[:, 1]) >= 0)
        cuts = {int(e): [0.0, 1.0] for e in on}
        todo = [(int(e), 0.0, 1.0) for e in on]
        while todo:
            e, t0, t1 = (np.array(c) for c in zip(*todo))
            a, b = edges[e, 0], edges[e, 1]
            pa, pb = self.vertices[a], self.vertices[b]
            ts = np.stack([t0, 0.5 * (t0 + t1), t1], axis=1)
            chord = pa[:, None] + ts[..., None] * (pb - pa)[:, None]
            exact = self(np.repeat(a, 3), np.repeat(b, 3), chord.reshape(-1, 3))
            exact = exact.reshape(-1, 3, 3)
            # the curve's point at the middle of the piece's chord (between its exact ends),
            # as issue 12 measures it, and at the middle of the edge's fractions (the new point)
            mid = 0.5 * (exact[:, 0] + exact[:, 2])
            sag = np.maximum(np.linalg.norm(self(a, b, mid) - mid, axis=1),
                             np.linalg.norm(exact[:, 1] - mid, axis=1))
            moved = np.any(exact[:, 1] != chord[:, 1], axis=1)
            # the piece of the edge too: where the curve jumps (the exact ends stay apart as
            # the piece shrinks) halving would never end (held-out seed 2525 draw 11)
            long = np.minimum(np.linalg.norm(exact[:, 2] - exact[:, 0], axis=1),
                              (t1 - t0) * np.linalg.norm(pb - pa, axis=1)) > PIECE * self.size
            split = (sag > tol) & moved & long
            todo = []
            for k in np.flatnonzero(split):
                m = float(ts[k, 1])
                cuts[int(e[k])].append(m)
                todo += [(int(e[k]), float(t0[k]), m), (int(e[k]), m, float(t1[k]))]
        return {e: np.array(sorted(t))[1:-1] for e, t in cuts.items() if len(t) > 2}


def _onto(wing, side, error, p, h, size):
    """Points ``p`` (k, 3) moved along the span at their chord fraction onto the host (a
    secant search from their own station on ``error``, the host's error function); NaN
    where the search does not settle."""
    f = _fraction(wing, p)
    ax = wing.span_axis

    def e_at(s):
        return error(wing.point(s, f, side, extrapolate=True))

    s0 = p[:, ax].copy()
    s1 = s0 + START * h
    e0, e1 = e_at(s0), e_at(s1)
    done = np.abs(e0) <= 1e-14 * size
    s_best = s0.copy()
    for _ in range(STEPS):
        de = e1 - e0
        step = np.where(de != 0, e1 * (s1 - s0) / np.where(de != 0, de, 1.0), 0.0)
        s2 = s1 - step
        s0, e0 = s1, e1
        s1, e1 = s2, e_at(s2)
        settled = np.abs(e1) <= 1e-13 * size
        s_best = np.where(settled & ~done, s1, s_best)
        done |= settled
        if done.all():
            break
    out = wing.point(s_best, f, side, extrapolate=True)
    out[~done] = np.nan
    return out


def seam_curves(geometry, mesh):
    """:class:`SeamCurves` of the assembled ``mesh`` of ``geometry``, or None when no
    vertex lies on the curve of a wing-like component and its host."""
    vertices = np.asarray(mesh.vertices, float)
    if not len(vertices):
        return None
    size = float(np.ptp(vertices, axis=0).max())
    tol = ON * size
    lines, boxes = [], {}
    for wing, host, error in _pairs(geometry, mesh):
        for m in (wing, host):
            if id(m) not in boxes:
                boxes[id(m)] = _box(m, size)
        lo = np.maximum(boxes[id(wing)][0], boxes[id(host)][0])
        hi = np.minimum(boxes[id(wing)][1], boxes[id(host)][1])
        for flip in (np.ones(3), np.array([1.0, -1.0, 1.0])):
            p = vertices * flip
            near = np.flatnonzero(np.all((p >= lo) & (p <= hi), axis=1))
            with np.errstate(invalid="ignore"):
                on_body = near[np.abs(error(p[near])) <= tol]
            if not len(on_body):
                continue
            q = p[on_body]
            f = _fraction(wing, q)
            inside = (f >= -tol) & (f <= 1.0 + tol)
            s = q[:, wing.span_axis]
            for side in ("upper", "lower"):
                surf = wing.point(s, np.clip(np.nan_to_num(f), 0.0, 1.0), side,
                                  extrapolate=True)
                on = inside & (np.linalg.norm(surf - q, axis=1) <= tol)
                if on.sum() < 2:
                    continue
                mask = np.zeros(len(vertices), bool)
                mask[on_body[on]] = True
                lines.append((wing, side, error, flip, mask))
    return SeamCurves(vertices, lines, size) if lines else None



def curve_edges(edges, curves):
    """(k, 2) the unique ``edges`` (a < b) whose two ends lie on one of the exact
    ``curves``."""
    e = np.asarray(edges, np.int64).reshape(-1, 2)
    e = np.sort(e[curves.on_curve(e[:, 0], e[:, 1]) >= 0], axis=1)
    return np.unique(e, axis=0)


def follow_curves(mesh, curves, sag=SAG, fixed=None):
    """``mesh`` (a :class:`~juncture.surface.assemble.SurfaceMesh`) with its edges on the
    exact ``curves`` split until each piece's chord lies within ``sag`` times the mesh's
    size of the curve at its middle: the new points lie on the curve (on both exact
    surfaces), appended to the vertices, and the triangles on both sides of such an edge
    become fans over them (:func:`juncture.surface.splits.fans`), so the seam stays shared.
    Before any chart is made: a chart's boundary then follows the curve, and points placed
    beside it cannot fall outside it (split points moved off their chord only later folded
    the triangles next to a canted fin's root, 0.2 ft from a 5 ft chord). A point and its
    mirror image in y = 0 are made as mirror images, bit for bit. A grid point past which the
    curve bulges moves off it unless it is ``fixed`` ((n,) bool: on an intersection, corner
    or split line; :mod:`juncture.surface.relocate`). Returns ``mesh`` itself when nothing
    is split."""
    from .mirror import FLIP, mirror_map

    if curves is None or sag is None:
        return mesh
    vertices = np.asarray(mesh.vertices, float)
    tri = np.asarray(mesh.triangles)
    edges = curve_edges(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]),
                        curves)
    if not len(edges):
        return mesh
    mirror = mirror_map(vertices)
    image = np.sort(np.where(mirror[edges] >= 0, mirror[edges], -1), axis=1)
    n = len(vertices)
    index = {k: i for i, k in enumerate((edges[:, 0] * n + edges[:, 1]).tolist())}
    has = np.array([(lo >= 0) and (lo * n + hi) in index for lo, hi in image.tolist()])
    primary = ~has | (vertices[edges].mean(axis=1)[:, 1] >= 0.0)
    cuts = curves.sagging(edges[primary], sag * curves.size)
    found, partner = {}, {}                  # edge key -> (fractions, points); its image
    for k, fractions in cuts.items():
        a, b = (int(v) for v in edges[np.flatnonzero(primary)[k]])
        chord = vertices[a] + fractions[:, None] * (vertices[b] - vertices[a])
        exact = curves(np.full(len(chord), a), np.full(len(chord), b), chord)
        found[(a, b)] = (fractions, exact)
        ma, mb = int(mirror[a]), int(mirror[b])
        key = (min(ma, mb), max(ma, mb))
        if ma >= 0 and mb >= 0 and key != (a, b) and (key[0] * n + key[1]) in index:
            flipped = exact * FLIP + 0.0                    # -0.0 is 0.0
            found[key] = ((fractions, flipped) if ma < mb else
                          (1.0 - fractions[::-1], flipped[::-1]))
            partner[key], partner[(a, b)] = (a, b), key
    from .relocate import free_vertices

    return _fanned(mesh, found, partner, free_vertices(mesh, fixed), curves)


def _fanned(mesh, found, partner, free=None, curves=None):
    """The mesh with the points ``found`` ({edge: (fractions, points)}) on its edges, the
    triangles on them fanned over them. Where a fan would turn a triangle over (a point past
    the corner across from it: the curve bulging into a thin triangle), that corner moves
    off the curve where it is ``free`` (:mod:`juncture.surface.relocate`, onto the host of
    the edge's curve among ``curves``); else the edge keeps its chord, and so does its
    mirror image (``partner``)."""
    from .relocate import normals, relocate

    vertices, tri = np.asarray(mesh.vertices, float), np.asarray(mesh.triangles)
    n0 = normals(vertices, tri)
    free = np.zeros(len(vertices), bool) if free is None or curves is None else free
    for _ in range(5):
        if not found:
            return mesh
        xyz, rows, new = _fans(vertices, tri, found)
        keep = np.ones(len(tri), bool)
        keep[rows] = False
        src = np.concatenate([np.flatnonzero(keep),
                              np.repeat(rows, [len(t) for t in new])])
        out = np.concatenate([tri[keep]] + new)
        if free.any():
            xyz = relocate(xyz, out, n0[src], free, len(vertices),
                           _hosts(found, curves, len(vertices)))
        turned = np.einsum("ij,ij->i", normals(xyz, out), n0[src]) <= 0.0
        if not turned.any():
            break
        bad = {(min(v[i], v[(i + 1) % 3]), max(v[i], v[(i + 1) % 3]))
               for v in tri[np.unique(src[turned])].tolist() for i in range(3)}
        bad = {k for k in bad if k in found}
        if not bad:
            return mesh
        for key in bad | {partner[k] for k in bad if k in partner}:
            found.pop(key, None)
    else:
        return mesh
    return _tagged(mesh, xyz, out, src)


def _hosts(found, curves, first):
    """``host(q, p)`` for :func:`~juncture.surface.relocate.relocate`: (error function,
    mirror flip) of the host of the curve on whose edge the new point ``p`` (from id
    ``first`` on, in the order of ``found``) was put, or None where the point ``q`` (3,)
    does not lie on that host's surface (to :data:`ON` of the size): a grid point of the
    wing beside the curve stays, taken onto the fuselage it would leave the wing. (Whatever
    network carries it: one layout makes the wing and the fuselage's middle one network.)"""
    keys = list(found)
    which = curves.on_curve(np.array([a for a, _ in keys]), np.array([b for _, b in keys]))
    line = np.repeat(which, [len(found[k][1]) for k in keys])

    def host(q, p):
        _, _, error, flip, _ = curves.lines[int(line[p - first])]
        with np.errstate(invalid="ignore"):
            on = abs(float(error((q * flip)[None])[0])) <= ON * curves.size
        return (error, flip) if on else None
    return host


def _fans(vertices, tri, found):
    """(points, rows, fans): the vertices with the ``found`` points appended, the rows of
    ``tri`` with a found point on an edge, and each one's fan over them."""
    from .splits import fans

    ids, count = {}, len(vertices)
    for key, (t, p) in found.items():
        ids[key] = (t, np.arange(count, count + len(p)))
        count += len(p)
    xyz = np.concatenate([vertices] + [p for _, p in found.values()])
    along = _Along(ids, count)
    rows = np.flatnonzero(np.any([along.cut(tri[:, i], tri[:, (i + 1) % 3])
                                  for i in range(3)], axis=0))
    return xyz, rows, [fans(tri[r:r + 1], along) for r in rows]


def _tagged(mesh, xyz, tri, src):
    """A :class:`~juncture.surface.assemble.SurfaceMesh` of points ``xyz`` and triangles
    ``tri``, each tagged as the row ``src`` of ``mesh`` it came from."""
    from .assemble import SurfaceMesh

    return SurfaceMesh(xyz, tri, mesh.component[src], mesh.surface[src], mesh.components,
                       mesh.surfaces, mesh.open_loops)


class _Along:
    """``along(a, b)`` over the points put on edges (the interface of
    :class:`~juncture.surface.splits.Splits` that :func:`~juncture.surface.splits.fans`
    uses)."""

    def __init__(self, on, n):
        self.on = on
        self.keys = np.array([a * n + b for a, b in on], np.int64)
        self.n = n

    def along(self, a, b):
        got = self.on.get((min(a, b), max(a, b)))
        if got is None:
            return np.zeros(0), np.zeros(0, np.int64)
        t, ids = got
        return (t, ids) if a < b else (1.0 - t[::-1], ids[::-1])

    def cut(self, a, b):
        """(k,) bool: the edges (a, b) that carry points."""
        lo, hi = np.minimum(a, b), np.maximum(a, b)
        return np.isin(lo.astype(np.int64) * self.n + hi, self.keys)
