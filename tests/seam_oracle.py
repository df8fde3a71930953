"""An independent oracle for seams: the exact curves where wing-like components meet bodies,
and how far their points lie from a triangulated surface.

It never uses juncture's intersection, seam or mesh code: it asks the component models
(:class:`juncture.model.WingLike`, :class:`~juncture.model.CircularBody`,
:class:`~juncture.model.ArbitraryBody`) only for surface points and a body's error function.

**The curves.** The point of the curve where wing-like component W meets body B, on W's
upper or lower surface at chord fraction f, is a span station s where W's surface point
``W.point(s, f, side, extrapolate=True)`` lies on B: a zero of B's error there
(``radial_error`` of a circular body, ``signed_distance`` of an arbitrary one; negative
inside, zero exactly on the surface). For each f the error is sampled along the span and
every sign change refined by regula falsi with the Illinois step (all brackets of all
fractions at once, vectorised) to the last bit of s. A sign change that is a jump, not a
zero (a body's end, a step at a joint), is dropped: the error there does not vanish.

Which zeros are seams: every zero on W's own span (root to tip section; a completed
geometry's model has its roots continued into the fuselage) is a point where the two exact
surfaces meet. Inboard of the root, W's lofting lines are extended (TM-4406 eq 4) only where
W is attached to B: for the pairs named in ``attached`` the zero nearest the root within half
a span inboard of it counts on a line that has none on the span (a pylon given down to a
pod's top). A line that misses B has no zero and gives no point. Both halves: a mirrored
component's curve with a centre-line or mirrored body has its image at -y.

**Where along the curves** (:func:`seam_distances`): at the chord fractions of W's lofting
lines, ``subdivide`` pieces between each two, ``uniform`` fractions evenly spaced; at the
fraction of every mesh vertex that lies on the curve (on both exact surfaces to 1e-9 of the
size: the seam's vertices) and midway between each two neighbouring ones (issue 12's
measure: the chord of a seam sags most about there); then, because the distance to a surface
changes by at most the distance moved, every piece between neighbouring samples p, q whose
bound ``(d(p) + d(q) + |p - q|) / 2`` exceeds the largest distance found so far is cut in
quarters, the largest bounds first (``most`` a round, ``rounds`` rounds), until none is left
or the pieces are shorter than 1e-7 of the size: the largest distance found is then the
largest on the curve to about that (where the curve bends little between samples, its chord
is its length). Where it stops on the round limit, the bound can still exceed what it found:
a search for the worst point, not a proof that none is worse.

Not measured: the curves of two wing-like components (a fin on a wing), and the lines of a
fillet (its lines on the wing and the body are juncture's own construction, with no exact
curve outside it): with ``fillets`` the wing/body curve is left out between lofting lines
where the fillet replaces it.

**The distance** from a point to a surface is the exact distance to its nearest triangle
(the foot of the perpendicular where it falls inside, else the nearest point of the three
edges), found among the triangles that can be nearest: a KD-tree over triangle centroids, in
classes of triangles of similar size, bounds each class by the centroid distance less the
class's largest centroid-to-corner radius.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

__all__ = ["SeamPoints", "seam_points", "point_triangle_distance", "surface_distance",
           "seam_distances"]

#: A point lies on an exact surface within this share of the size.
ON = 1e-9


@dataclass
class SeamPoints:
    """Points of exact wing/body curves: ``points`` (n, 3) and, per point, its ``wing`` and
    ``body`` (names), ``side`` ("upper" / "lower"), ``image`` (True for the -y copy), chord
    fraction ``fraction`` and ``branch`` (0 for the zero nearest the root on its line, 1 for
    the next: a wing through a pod meets it twice), and ``curve``, a number for the pair,
    side and half."""

    points: np.ndarray
    wing: np.ndarray
    body: np.ndarray
    side: np.ndarray
    image: np.ndarray
    fraction: np.ndarray
    branch: np.ndarray
    curve: np.ndarray

    def where(self, i):
        """A line naming point i: wing/body, side, half, x, y, z and chord fraction."""
        half = " (image, y < 0)" if self.image[i] else ""
        x, y, z = self.points[i]
        return (f"{self.wing[i]}/{self.body[i]} {self.side[i]}{half} x={x:.6g} y={y:.6g} "
                f"z={z:.6g} f={self.fraction[i]:.5f}")

    def __len__(self):
        return len(self.points)


def _error(body):
    from juncture.model import CircularBody

    return body.radial_error if isinstance(body, CircularBody) else body.signed_distance


def _has_image(cfg, wing, body):
    """Whether the pair has a copy at -y: a mirrored component on a centre-line or mirrored
    body."""
    from juncture.model import CircularBody

    if not (cfg.symmetric and wing.mirrored):
        return False
    on_plane = not isinstance(body, CircularBody) or float(body.origin[1]) == 0.0
    return bool(body.mirrored or on_plane)


class _Curve:
    """One wing-like component's side against one body: its zeros at any chord fractions."""

    def __init__(self, wing, body, side, attached, image, size, span_samples):
        self.wing, self.body, self.side = wing, body, side
        self.err, self.attached, self.image, self.size = _error(body), attached, image, size
        st = wing.span_stations
        self.root, self.tip = float(st[0]), float(st[-1])
        self.length = self.tip - self.root
        lo = self.root - (0.5 if attached else 1e-9) * self.length
        if wing.span_axis == 1 and wing.mirrored and self.root >= 0.0:
            lo = max(lo, 0.0)                   # the y >= 0 half: the image is apart
        self.lo, self.samples = lo, span_samples
        self.base_f = self.base_s = None

    def error(self, s, f):
        return self.err(self.wing.point(s, f, self.side, extrapolate=True))

    def zeros(self, f, lo=None, hi=None, samples=None):
        """(s, f, branch) of the seam zeros at fractions f (n,), searched between lo and hi
        (each (n,) or the whole span)."""
        n = len(f)
        lo = np.full(n, self.lo) if lo is None else np.maximum(lo, self.lo)
        hi = np.full(n, self.tip) if hi is None else np.minimum(hi, self.tip)
        k = self.samples if samples is None else samples
        s = lo[:, None] + (hi - lo)[:, None] * np.linspace(0.0, 1.0, k)[None, :]
        ff = np.broadcast_to(f[:, None], s.shape)
        e = self.error(s, ff)
        neg = e < 0.0
        row, col = np.nonzero(neg[:, :-1] != neg[:, 1:])
        a, b = s[row, col], s[row, col + 1]
        fr = f[row]
        r = self._bracketed(a, b, e[row, col], e[row, col + 1], fr)
        ok = np.abs(self.error(r, fr)) <= ON * self.size
        r, fr, row = r[ok], fr[ok], row[ok]
        on_span = r >= self.root - 1e-9 * self.length
        keep = on_span.copy()
        if self.attached and r.size:
            # inboard of the root: the zero nearest it, on a line with none on the span
            has_span = np.zeros(n, bool)
            has_span[row[on_span]] = True
            best = np.full(n, -np.inf)
            np.maximum.at(best, row[~on_span], r[~on_span])
            keep |= ~on_span & ~has_span[row] & (r == best[row])
        r, fr, row = r[keep], fr[keep], row[keep]
        order = np.lexsort((r, row))             # by line, then outward
        r, fr, row = r[order], fr[order], row[order]
        first = np.r_[True, row[1:] != row[:-1]]
        start = np.maximum.accumulate(np.where(first, np.arange(len(row)), 0))
        return r, fr, np.arange(len(row)) - start

    def _bracketed(self, a, b, ea, eb, f, steps=60):
        """The zeros in the brackets [a, b] (signs of the error differ at the ends), all at
        once: regula falsi with the Illinois halving of the weight of an end kept twice, a
        bisection step where it would land outside, until every bracket has closed to
        rounding or the error at an end vanishes to 1e-15 of the size (or ``steps``)."""
        a, b, ea, eb = (np.array(v, float) for v in (a, b, ea, eb))
        wa, wb = np.ones_like(a), np.ones_like(b)
        side = np.zeros(a.shape, int)
        tiny = 1e-15 * self.size
        for _ in range(steps):
            live = (np.abs(b - a) > 4e-16 * np.maximum(np.abs(a), np.abs(b)) + 1e-300) & (
                np.minimum(np.abs(ea), np.abs(eb)) > tiny)
            if not live.any():
                break
            i = np.flatnonzero(live)
            ai, bi = a[i], b[i]
            ga, gb = ea[i] * wa[i], eb[i] * wb[i]
            den = gb - ga
            m = bi - gb * (bi - ai) / np.where(den != 0.0, den, 1.0)
            bad = (den == 0.0) | ~((m > np.minimum(ai, bi)) & (m < np.maximum(ai, bi)))
            m = np.where(bad, 0.5 * (ai + bi), m)
            em = self.error(m, f[i])
            left = np.signbit(em) == np.signbit(ea[i])      # m replaces a, b is kept
            sd = side[i]
            wb[i] = np.where(left, np.where(sd == 1, 0.5 * wb[i], wb[i]), 1.0)
            wa[i] = np.where(left, 1.0, np.where(sd == -1, 0.5 * wa[i], wa[i]))
            a[i], ea[i] = np.where(left, m, ai), np.where(left, em, ea[i])
            b[i], eb[i] = np.where(left, bi, m), np.where(left, eb[i], em)
            side[i] = np.where(left, 1, -1)
        return np.where(np.abs(ea) <= np.abs(eb), a, b)

    def base(self, f):
        """Zeros at the base fractions, searched along the whole span; kept to bracket the
        zeros at other fractions."""
        s, fr, br = self.zeros(f)
        self.base_f, self.base_s = np.asarray(f), (s, fr)
        return s, fr, br

    def near(self, f):
        """Zeros at fractions f between base fractions, searched only about the base zeros
        of the two neighbouring base fractions (a line with none there is skipped)."""
        bf = self.base_f
        bs, bfr = self.base_s
        if not bs.size or not len(f):
            return np.zeros(0), np.zeros(0), np.zeros(0, int)
        line = np.searchsorted(bf, bfr)
        lo_line = np.full(bf.size, np.inf)
        hi_line = np.full(bf.size, -np.inf)
        np.minimum.at(lo_line, line, bs)
        np.maximum.at(hi_line, line, bs)
        j = np.clip(np.searchsorted(bf, f, side="right") - 1, 0, bf.size - 2)
        lo = np.minimum(lo_line[j], lo_line[j + 1])
        hi = np.maximum(hi_line[j], hi_line[j + 1])
        step = (self.tip - self.lo) / (self.samples - 1)
        ok = np.isfinite(lo) & np.isfinite(hi)
        span = np.where(ok, hi - lo, 0.0)
        lo, hi = lo - span - 2 * step, hi + span + 2 * step
        return self.zeros(f[ok], lo[ok], hi[ok], samples=65)

    def on_curve(self, vertices):
        """Chord fractions of the vertices that lie on this curve (both exact surfaces, to
        :data:`ON` of the size), in this half and, with an image, the other."""
        out = []
        tol = ON * self.size
        for flip in ((1.0, -1.0) if self.image else (1.0,)):
            v = vertices * [1.0, flip, 1.0]
            ax = self.wing.span_axis
            s = v[:, ax]
            near = (s >= self.lo - tol) & (s <= self.tip + tol)
            v, s = v[near], s[near]
            near = np.abs(self.err(v)) <= tol
            v, s = v[near], s[near]
            if not len(v):
                continue
            x0 = self.wing.point(s, np.zeros_like(s), self.side, extrapolate=True)[:, 0]
            x1 = self.wing.point(s, np.ones_like(s), self.side, extrapolate=True)[:, 0]
            f = (v[:, 0] - x0) / np.where(x1 > x0, x1 - x0, 1.0)
            inside = (f >= 0.0) & (f <= 1.0) & (x1 > x0)
            f, v, s = f[inside], v[inside], s[inside]
            p = self.wing.point(s, f, self.side, extrapolate=True)
            out.append(f[np.linalg.norm(p - v, axis=1) <= tol])
        return np.unique(np.concatenate(out)) if out else np.zeros(0)


def _curves(cfg, size, attached, fillets, span_samples):
    from juncture.model import ArbitraryBody, CircularBody, WingLike

    comps = list(cfg)
    wings = [c for c in comps if isinstance(c, WingLike)]
    bodies = [c for c in comps if isinstance(c, (CircularBody, ArbitraryBody))]
    attached = {tuple(p) for p in attached}
    out = []
    for w in wings:
        for b in bodies:
            for side in ("upper", "lower"):
                c = _Curve(w, b, side, (w.name, b.name) in attached, _has_image(cfg, w, b),
                           size, span_samples)
                c.index = len(out)
                fil = (fillets or {}).get((w.name, b.name, side))
                c.fillet = None if fil is None else np.asarray(fil, bool)
                out.append(c)
    return out


def _allowed(curve, f):
    """Fractions off the pieces between lofting lines where a fillet replaces the curve."""
    if curve.fillet is None:
        return f
    t = curve.wing.x_over_c / 100.0
    j_lo = np.clip(np.searchsorted(t, f, side="right") - 1, 0, t.size - 1)
    j_hi = np.clip(np.searchsorted(t, f, side="left"), 0, t.size - 1)
    return f[~(curve.fillet[j_lo] | curve.fillet[j_hi])]


def _fractions(wing, subdivide, uniform):
    t = wing.x_over_c / 100.0
    u = np.linspace(0.0, 1.0, subdivide + 1)[:-1]
    fine = (t[:-1, None] + np.diff(t)[:, None] * u[None, :]).ravel()
    return np.unique(np.concatenate([t, fine, np.linspace(t[0], t[-1], uniform)]))


def _assemble(parts):
    """SeamPoints from (curve, s, f, branch) parts, with the images."""
    cols = [[] for _ in range(8)]
    for c, s, f, br in parts:
        if not len(s):
            continue
        p = c.wing.point(s, f, c.side, extrapolate=True)
        for q, im in [(p, False)] + ([(p * [1.0, -1.0, 1.0], True)] if c.image else []):
            n = len(q)
            for col, val in zip(cols, (q, [c.wing.name] * n, [c.body.name] * n,
                                       [c.side] * n, [im] * n, f, br,
                                       np.full(n, 2 * c.index + im))):
                col.append(np.asarray(val))
    if not cols[0]:
        z = np.zeros(0)
        return SeamPoints(np.zeros((0, 3)), z.astype(str), z.astype(str), z.astype(str),
                          z.astype(bool), z, z.astype(int), z.astype(int))
    return SeamPoints(*(np.concatenate(col) for col in cols))


def seam_points(cfg, size, subdivide=4, uniform=101, span_samples=257, attached=(),
                fillets=None):
    """The exact curves of every wing-like component of ``cfg`` with every body it meets,
    at the base fractions (no mesh needed): :class:`SeamPoints`.

    ``size``: the airplane's size (a zero is one where the error is within 1e-9 of it).
    ``attached``: (wing name, body name) pairs whose lofting lines are extended inboard of
    the root to the body. ``fillets``: {(wing name, body name, side): (n_stations,) bool},
    True on the lofting lines that have a fillet; the curve is left out on the pieces
    between lofting lines where either end has one (the fillet's lines are the seams there).
    """
    parts = []
    for c in _curves(cfg, size, attached, fillets, span_samples):
        f = _fractions(c.wing, subdivide, uniform)
        parts.append((c, *c.base(f)))
    kept = [(c, *_keep(c, s, f, br)) for c, s, f, br in parts]
    return _assemble(kept)


def _keep(c, s, f, br):
    ok = np.isin(f, _allowed(c, f))
    return s[ok], f[ok], br[ok]


def seam_distances(cfg, vertices, triangles, subdivide=4, uniform=101, span_samples=257,
                   attached=(), fillets=None, rounds=12, most=128):
    """(distances / size (n,), :class:`SeamPoints`): the exact seam curves' points (see the
    module docstring for where) and their distances from the surface, as a share of the
    surface's size (its box's longest side)."""
    V = np.asarray(vertices, float)
    T = np.asarray(triangles)
    size = float(np.ptp(V, axis=0).max())
    curves = _curves(cfg, size, attached, fillets, span_samples)
    parts = []
    for c in curves:
        bs, bf, bb = c.base(_fractions(c.wing, subdivide, uniform))
        if not bs.size:
            continue
        fv = c.on_curve(V)
        mid = 0.5 * (fv[1:] + fv[:-1])
        extra = np.setdiff1d(np.concatenate([fv, mid]), c.base_f)
        parts.append((c, *_merge((bs, bf, bb), c.near(extra))))
    parts = [(c, *_keep(c, s, f, br)) for c, s, f, br in parts]
    pts = _assemble(parts)
    d = surface_distance(pts.points, V, T)
    for _ in range(rounds):
        new = _refine(curves, pts, d, size, most)
        if not new:
            break
        add = [(c, *_keep(c, *c.near(f))) for c, f in new]
        more = _assemble(add)
        if not len(more):
            break
        dm = surface_distance(more.points, V, T)
        pts = _assemble_join(pts, more)
        d = np.concatenate([d, dm])
        parts = parts + add
    return d / size, pts


def _merge(a, b):
    return tuple(np.concatenate([x, y]) for x, y in zip(a, b))


def _assemble_join(a, b):
    return SeamPoints(*(np.concatenate([getattr(a, k), getattr(b, k)]) for k in
                        ("points", "wing", "body", "side", "image", "fraction", "branch",
                         "curve")))


def _refine(curves, pts, d, size, most, pieces=4):
    """[(curve, fractions)]: the pieces between neighbouring samples of a curve (same pair,
    side, half and branch) whose Lipschitz bound exceeds the largest distance found, longer
    than 1e-7 of the size, cut in ``pieces``; the ``most`` largest bounds of them."""
    top = d.max(initial=0.0)
    key = pts.curve * 64 + np.minimum(pts.branch, 63)
    order = np.lexsort((pts.fraction, key))
    k, f, p, dd = key[order], pts.fraction[order], pts.points[order], d[order]
    same = (k[1:] == k[:-1]) & (f[1:] > f[:-1])
    length = np.linalg.norm(p[1:] - p[:-1], axis=1)
    bound = 0.5 * (dd[1:] + dd[:-1] + length)
    split = same & (bound > top) & (length > 1e-7 * size)
    if split.sum() > most:                       # best first: the largest bounds
        split &= bound >= np.partition(bound[split], -most)[-most]
    if not split.any():
        return []
    u = np.arange(1, pieces) / pieces
    new = (f[:-1][split, None] + (f[1:] - f[:-1])[split, None] * u[None, :]).ravel()
    owner = np.repeat(k[:-1][split] // 64 // 2, pieces - 1)
    return [(curves[i], np.unique(new[owner == i])) for i in np.unique(owner)]


def point_triangle_distance(q, a, b, c):
    """Exact distance from points q to triangles (a, b, c), all (n, 3), row by row.

    Where the foot of the perpendicular on the triangle's plane lies inside (barycentric
    coordinates >= 0) it is the distance to the plane; otherwise the nearest point lies on
    the boundary, the nearest of the three edges' (clamped) nearest points. A degenerate
    triangle has only its edges."""
    e0, e1, v = b - a, c - a, q - a
    a00, a01, a11 = (e0 * e0).sum(1), (e0 * e1).sum(1), (e1 * e1).sum(1)
    b0, b1 = (e0 * v).sum(1), (e1 * v).sum(1)
    det = a00 * a11 - a01 * a01
    good = det > 1e-14 * a00 * a11
    den = np.where(good, det, 1.0)
    u, w = (a11 * b0 - a01 * b1) / den, (a00 * b1 - a01 * b0) / den
    inside = good & (u >= 0.0) & (w >= 0.0) & (u + w <= 1.0)
    plane = np.linalg.norm(v - u[:, None] * e0 - w[:, None] * e1, axis=1)

    def edge(p0, p1):
        d = p1 - p0
        t = np.clip(((q - p0) * d).sum(1) / np.maximum((d * d).sum(1), 1e-300), 0.0, 1.0)
        return np.linalg.norm(q - p0 - t[:, None] * d, axis=1)

    rim = np.minimum(np.minimum(edge(a, b), edge(b, c)), edge(c, a))
    return np.where(inside, np.minimum(plane, rim), rim)


def surface_distance(points, vertices, triangles, chunk=200_000):
    """(n,) exact distance from each point to the nearest triangle of the surface.

    Triangles go into classes by their radius (largest centroid-to-corner distance, halving
    from class to class), each with a KD-tree over its centroids. A first bound is the
    distance to the triangles of the 4 nearest centroids of each class; then every triangle
    whose centroid lies within that bound plus its class's radius is measured exactly.
    """
    from scipy.spatial import cKDTree

    q = np.asarray(points, float)
    V = np.asarray(vertices, float)
    T = np.asarray(triangles)
    if not len(q):
        return np.zeros(0)
    corners = V[T]                                     # (m, 3, 3)
    cent = corners.mean(axis=1)
    rad = np.linalg.norm(corners - cent[:, None], axis=2).max(axis=1)
    top = max(float(rad.max()), 1e-300)
    level = np.minimum(np.floor(np.log2(top / np.maximum(rad, 1e-300 * top))), 30).astype(int)

    def exact(qi, ti):
        out = np.empty(len(qi))
        for lo in range(0, len(qi), chunk):
            s = slice(lo, lo + chunk)
            c = corners[ti[s]]
            out[s] = point_triangle_distance(q[qi[s]], c[:, 0], c[:, 1], c[:, 2])
        return out

    classes = []
    for lev in np.unique(level):
        idx = np.flatnonzero(level == lev)
        classes.append((idx, cKDTree(cent[idx]), float(rad[idx].max())))
    best = np.full(len(q), np.inf)
    rows = np.arange(len(q))
    for idx, tree, _ in classes:
        k = min(4, len(idx))
        _, near = tree.query(q, k=k)
        near = near.reshape(len(q), -1)
        d = exact(np.repeat(rows, near.shape[1]), idx[near.ravel()])
        np.minimum.at(best, np.repeat(rows, near.shape[1]), d)
    for idx, tree, r in classes:
        found = tree.query_ball_point(q, best + r * (1.0 + 1e-12) + 1e-300)
        counts = np.fromiter(map(len, found), int, len(q))
        if not counts.sum():
            continue
        ti = idx[np.fromiter(itertools.chain.from_iterable(found), int, counts.sum())]
        qi = np.repeat(rows, counts)
        np.minimum.at(best, qi, exact(qi, ti))
    return best
