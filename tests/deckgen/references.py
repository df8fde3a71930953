"""Reference evaluation of the surfaces a deck describes, independent of juncture (see the package
docstring), and how far completed geometry lies from them."""

from __future__ import annotations

import math

import numpy as np
from scipy.interpolate import PchipInterpolator


# ------------------------------------------------------------------------------------------
# Reference surfaces (independent of juncture)
# ------------------------------------------------------------------------------------------
class WingLikeRef:
    """A wing, canard, tail, fin or pylon as its deck numbers describe it.

    Sections at constant y (wing, canard, tail; thickness in z) or constant z (fin, pylon;
    thickness in y). Offsets are camber +/- chord * half-thickness / 100 at the percent-chord
    stations, joined along the chord by SciPy's PCHIP; between sections the surface is the
    ruled blend of the two section curves at equal chord fraction, so lofting lines are
    straight, and beyond root and tip they continue straight.
    """

    def __init__(self, kind, le, chord, xaf, upper, lower, camber=None):
        self.kind = kind
        self.span_axis = 1 if kind in ("wing", "canard", "tail") else 2
        self.thick_axis = 3 - self.span_axis
        self.le = np.asarray(le, float)
        self.chord = np.asarray(chord, float)
        self.t = np.asarray(xaf, float) / 100.0
        n, m = self.chord.size, self.t.size
        up = np.broadcast_to(np.asarray(upper, float), (n, m))
        lo = np.broadcast_to(np.asarray(lower, float), (n, m))
        cam = np.zeros((n, m)) if camber is None else np.asarray(camber, float)
        c = self.chord[:, None]
        self.offsets = {"upper": cam + c * up / 100.0, "lower": cam - c * lo / 100.0}
        self._pchip = {side: PchipInterpolator(self.t, off.T, axis=0)
                       for side, off in self.offsets.items()}

    @property
    def span(self):
        """(n_sections,) y (or z for fins) of each section."""
        return self.le[:, self.span_axis]

    def section_points(self, side):
        """(n_sections, n_stations, 3): the points the deck gives."""
        pts = np.repeat(self.le[:, None, :], self.t.size, axis=1)
        pts[..., 0] += self.chord[:, None] * self.t
        pts[..., self.thick_axis] += self.offsets[side]
        return pts

    def lofting_distance(self, points, side):
        """Distance of points (P, 3) to the nearest lofting line of ``side``, extended."""
        p = np.asarray(points, float).reshape(-1, 3)
        if not len(p):
            return np.zeros(0)
        lines = np.swapaxes(self.section_points(side), 0, 1)  # (m, n, 3)
        a, d = lines[:, :-1], np.diff(lines, axis=1)  # (m, n - 1, 3)
        len2 = np.maximum((d * d).sum(-1), 1e-300)
        rel = p[:, None, None, :] - a[None]
        t = (rel * d[None]).sum(-1) / len2[None]
        k = d.shape[1]
        lo = np.where(np.arange(k) == 0, -np.inf, 0.0)
        hi = np.where(np.arange(k) == k - 1, np.inf, 1.0)
        t = np.clip(t, lo, hi)
        dist = np.linalg.norm(rel - t[..., None] * d[None], axis=-1)
        return dist.reshape(len(p), -1).min(axis=1)

    def planform(self, span):
        """(section index k, blend lam, leading-edge x, chord) at span stations (extended)."""
        s = np.asarray(span, float)
        st_ = self.span
        k = np.clip(np.searchsorted(st_, s, side="right") - 1, 0, st_.size - 2)
        lam = (s - st_[k]) / (st_[k + 1] - st_[k])
        x_le = self.le[k, 0] + lam * (self.le[k + 1, 0] - self.le[k, 0])
        chord = self.chord[k] + lam * (self.chord[k + 1] - self.chord[k])
        return k, lam, x_le, chord

    def coordinates(self, points):
        """(span, chord fraction, thickness coordinate) of points (P, 3); f NaN at zero chord."""
        p = np.asarray(points, float).reshape(-1, 3)
        _, _, x_le, chord = self.planform(p[:, self.span_axis])
        with np.errstate(divide="ignore", invalid="ignore"):
            f = np.where(chord > 0, (p[:, 0] - x_le) / chord, np.nan)
        return p[:, self.span_axis], f, p[:, self.thick_axis]

    def surface(self, span, fraction, side):
        """Thickness coordinate of ``side`` at span stations and chord fractions (extended)."""
        span, fraction = (np.ravel(a) for a in np.broadcast_arrays(
            np.asarray(span, float), np.asarray(fraction, float)))
        k, lam, _, _ = self.planform(span)
        f = np.clip(np.nan_to_num(fraction, nan=0.0), 0.0, 1.0)
        vals = self._pchip[side](f)  # (P, n_sections)
        rows = np.arange(f.size)
        base = self.le[:, self.thick_axis]
        a = vals[rows, k] + base[k]
        b = vals[rows, k + 1] + base[k + 1]
        return (1.0 - lam) * a + lam * b

    def point(self, span, fraction, side):
        """(P, 3) surface points at span stations and chord fractions (extended)."""
        span, fraction = np.broadcast_arrays(np.asarray(span, float),
                                             np.asarray(fraction, float))
        span, fraction = span.ravel(), fraction.ravel()
        _, _, x_le, chord = self.planform(span)
        out = np.empty((span.size, 3))
        out[:, 0] = x_le + chord * fraction
        out[:, self.span_axis] = span
        out[:, self.thick_axis] = self.surface(span, fraction, side)
        return out

    def surface_distance(self, points, sides=("upper", "lower")):
        """Distance from points (P, 3) to the nearest of ``sides``, in the section plane.

        Along the thickness axis at the point's chord fraction; for a point ahead of the
        leading edge or behind the trailing edge, from the edge's point, with the distance
        along the chord added in quadrature (an upper bound of the true distance). Infinite
        where the chord is zero.
        """
        s, f, t = self.coordinates(points)
        _, _, _, chord = self.planform(s)
        fc = np.clip(f, 0.0, 1.0)
        along = np.nan_to_num((f - fc) * chord, nan=np.inf)
        d = np.min([np.abs(t - self.surface(s, fc, side)) for side in sides], axis=0)
        return np.hypot(d, along)

    def depth(self, points, extend_root=False):
        """How deep points (P, 3) lie inside the solid (> 0 inside); -inf off the planform."""
        s, f, t = self.coordinates(points)
        up = self.surface(s, f, "upper")
        lo = self.surface(s, f, "lower")
        st_ = self.span
        lo_span = -np.inf if extend_root else st_[0]
        within = np.isfinite(f) & (f > 0) & (f < 1) & (s >= lo_span) & (s <= st_[-1])
        return np.where(within, np.minimum(t - lo, up - t), -np.inf)

    def samples(self, n_span=9):
        """(P, 3) points on both surfaces between root and tip (collision tests)."""
        s = np.linspace(self.span[0], self.span[-1], n_span)
        f = np.concatenate([self.t, [0.5 * (self.t[0] + self.t[-1])]])
        ss, ff = np.meshgrid(s, f, indexing="ij")
        return np.concatenate([self.point(ss.ravel(), ff.ravel(), side)
                               for side in ("upper", "lower")])


class CircularBodyRef:
    """A circular fuselage or pod as the deck describes it.

    Within a segment r(x) and the centre height are SciPy PCHIP curves through the stations;
    across a gap between segments, straight lines; outside the stations the radius is 0.
    ``segments`` is a list of ``(x, radius, zc)`` arrays in configuration coordinates.
    """

    def __init__(self, segments, y_centre=0.0):
        self.y_centre = float(y_centre)
        self.pieces = []  # (x0, x1, callable r, callable zc, "segment" | "gap")
        prev = None
        for x, r, zc in segments:
            x, r, zc = (np.asarray(a, float) for a in (x, r, zc))
            if prev is not None and x[0] > prev[0][-1]:
                xa, xb = prev[0][-1], x[0]
                ra, rb, za, zb = prev[1][-1], r[0], prev[2][-1], zc[0]
                self.pieces.append((xa, xb, _line(xa, xb, ra, rb), _line(xa, xb, za, zb),
                                    "gap"))
            self.pieces.append((x[0], x[-1], PchipInterpolator(x, r), PchipInterpolator(x, zc),
                                "segment"))
            prev = (x, r, zc)
        self.x0, self.x1 = self.pieces[0][0], self.pieces[-1][1]

    def section(self, x):
        """(radius, centre z, in a gap) at stations x."""
        x = np.asarray(x, float)
        r, zc, gap = np.zeros(x.shape), np.zeros(x.shape), np.zeros(x.shape, bool)
        for x0, x1, fr, fz, kind in self.pieces:
            m = (x >= x0) & (x <= x1)
            if m.any():
                r[m], zc[m], gap[m] = fr(x[m]), fz(x[m]), kind == "gap"
        return np.maximum(r, 0.0), zc, gap

    def radial_error(self, points):
        """(P,) distance from the section centre minus r(x) (0 on the surface)."""
        p = np.asarray(points, float).reshape(-1, 3)
        r, zc, _ = self.section(p[:, 0])
        return np.hypot(p[:, 1] - self.y_centre, p[:, 2] - zc) - r

    def distance(self, points):
        """(P,) |radial error| and the class of each point (P,): ``"plain"``, ``"gap"``
        (between segments), ``"end"`` (at or beyond the first or last station, where an
        open end has no surface). The generated circular fuselages repeat their joints with
        equal values, so there are no steps."""
        p = np.asarray(points, float).reshape(-1, 3)
        where = np.where(self.section(p[:, 0])[2], "gap", "plain").astype(object)
        where[_at_ends(p[:, 0], self.x0, self.x1)] = "end"
        return np.abs(self.radial_error(p)), where


def _at_ends(x, x0, x1):
    tol = 1e-12 * max(abs(x0), abs(x1), x1 - x0)
    return (x <= x0 + tol) | (x >= x1 - tol)


def _line(xa, xb, va, vb):
    def f(x):
        return va + (np.asarray(x, float) - xa) * (vb - va) / (xb - xa)
    return f


def _arc_fractions(sec):
    seg = np.hypot(*np.diff(sec, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    return s / s[-1] if s[-1] > 0 else np.linspace(0.0, 1.0, len(sec))


def _polyline_distance(q, poly):
    a, d = poly[:-1], np.diff(poly, axis=0)
    len2 = np.maximum((d * d).sum(-1), 1e-300)
    t = np.clip(((q - a) * d).sum(-1) / len2, 0.0, 1.0)
    return float(np.sqrt(((q - a - t[:, None] * d) ** 2).sum(-1)).min())


class ArbitraryBodyRef:
    """An arbitrary-section fuselage as the deck describes it.

    Each station's half-section is the polyline through its (y, z) points (bottom to top);
    between two stations the sections are matched by normalised arc length and blended
    linearly in x (TM-4607 eq 8), which is again a polyline, through the breakpoints of both.
    Where two segments repeat their joint station with different sections (say 6 points, then
    5) the surface has a step there: the face between the two polylines at that x.
    ``segments`` is a list of ``(x (n,), y (n, m), z (n, m))``.
    """

    def __init__(self, segments):
        self.x = np.concatenate([np.asarray(s[0], float) for s in segments])
        self.sections = [np.stack([np.asarray(y, float), np.asarray(z, float)], -1)
                         for _, ys, zs in segments for y, z in zip(ys, zs)]
        ends = np.cumsum([len(s[0]) for s in segments])
        self.gaps = [(self.x[e - 1], self.x[e]) for e in ends[:-1] if self.x[e] > self.x[e - 1]]
        self.steps = [self.x[e] for e in ends[:-1] if self.x[e] == self.x[e - 1] and not (
            self.sections[e].shape == self.sections[e - 1].shape
            and np.array_equal(self.sections[e], self.sections[e - 1]))]

    def section_at(self, x, k):
        """The blended half-section polyline (q, 2) at x between stations k and k + 1."""
        a, b = self.sections[k], self.sections[k + 1]
        ua, ub = _arc_fractions(a), _arc_fractions(b)
        u = np.union1d(ua, ub)
        w = (x - self.x[k]) / (self.x[k + 1] - self.x[k])
        sa = np.stack([np.interp(u, ua, a[:, i]) for i in (0, 1)], -1)
        sb = np.stack([np.interp(u, ub, b[:, i]) for i in (0, 1)], -1)
        return (1 - w) * sa + w * sb

    def distance(self, points):
        """In-plane distance to the deck's section at each point's x, for points (P, 3).

        Returns ``(distance (P,), class (P,))``, the class one of ``"plain"``, ``"gap"``
        (between segments), ``"step"`` (on a joint step; the distance is to the nearer of
        the two sections) or ``"end"`` (at or beyond the first or last station).
        """
        p = np.asarray(points, float).reshape(-1, 3)
        out = np.full(len(p), np.inf)
        where = np.full(len(p), "plain", dtype=object)
        xs = self.x
        tol = 1e-12 * max(abs(xs[0]), abs(xs[-1]), xs[-1] - xs[0])
        for i, (x, y, z) in enumerate(p):
            q = np.array([abs(y), z])
            ks = [k for k in range(xs.size - 1) if xs[k] < xs[k + 1] and xs[k] <= x <= xs[k + 1]]
            if ks:
                out[i] = min(_polyline_distance(q, self.section_at(x, k)) for k in ks)
            if any(a < x < b for a, b in self.gaps):
                where[i] = "gap"
            if any(abs(x - s) <= tol for s in self.steps):
                where[i] = "step"
        where[_at_ends(p[:, 0], xs[0], xs[-1])] = "end"
        return out, where


def references(description):
    """Reference surfaces of every component of a drawn deck: name -> *Ref object."""
    out = {}
    for name, c in description["components"].items():
        kind = c["kind"]
        if kind in ("wing", "canard", "tail", "fin"):
            out[name] = WingLikeRef(kind, c["le"], c["chord"], c["xaf"], c["upper"],
                                    c["lower"], c.get("camber"))
        elif kind == "circular":
            out[name] = CircularBodyRef([(s["x"], s["radius"], s["zc"]) for s in c["segments"]])
        elif kind == "arbitrary":
            out[name] = ArbitraryBodyRef([(s["x"], s["y"], s["z"]) for s in c["segments"]])
        elif kind == "pod":
            o = c["origin"]
            x = np.asarray(c["x"], float) + o[0]
            out[name] = CircularBodyRef([(x, c["radius"], np.full(x.size, o[2]))], o[1])
    return out


_SIDE = {"upper": "upper", "outboard": "upper", "lower": "lower", "inboard": "lower"}


def intersection_offsets(geo, description, redesigned=(), reinterpolated=()):
    """How far the points of every intersection line of ``geo`` lie from both surfaces.

    Parameters
    ----------
    geo : juncture.Geometry
        A completed geometry (``geo.intersections`` named ``"<a>/<b> <side>"``).
    description : dict
        The drawn deck's description (its ``"components"`` numbers).
    redesigned : iterable of str
        Components the run changed (the fuselage with ``keep_area``): their deck reference does
        not apply, only their own model (``geo.configuration[name]``).
    reinterpolated : iterable of str
        Lines whose points were moved along the intersection (the lower line of the single
        fuselage network, TM-4406 fig 4): ``a_deck`` is then the distance from ``a``'s surface
        rather than from its lofting lines.

    Returns
    -------
    list of dict
        Per line: ``name``, ``a``, ``b``, ``meant`` (whether the deck was drawn with ``a``
        touching ``b``), ``points``, ``nan`` (points not found), and the largest distances,
        relative to the fuselage length: ``a_deck`` (from ``a``'s lofting lines of that side),
        ``b_deck`` (from ``b``'s surface in the deck), ``b_gap`` (points in a gap between
        fuselage segments), ``b_step`` (points on a joint step between segments, measured to
        the nearer section), ``b_end`` (points at or beyond an end station, where an open
        end has no surface), ``b_own`` (from ``b``'s own juncture model, radial error or
        signed distance, off steps and ends; None for a wing-like b), ``b_own_jump`` (the same
        on steps and ends). A distance is 0 when no point falls in its class.
    """
    refs = references(description)
    comps = description["components"]
    length = description["length"]
    rows = []
    for name, pts in geo.intersections.items():
        a, rest = name.split("/", 1)
        b, label = rest.rsplit(" ", 1)
        p = np.asarray(pts, float).reshape(-1, 3)
        finite = np.isfinite(p).all(axis=1)
        p = p[finite]
        row = {"name": name, "a": a, "b": b, "meant": b in comps[a]["touches"],
               "points": int(finite.size), "nan": int((~finite).sum()), "a_deck": 0.0,
               "b_deck": 0.0, "b_gap": 0.0, "b_step": 0.0, "b_end": 0.0, "b_own": None,
               "b_own_jump": None}
        if len(p):
            ra, rb = refs[a], refs[b]
            da = (ra.surface_distance(p, (_SIDE[label],)) if name in reinterpolated
                  else ra.lofting_distance(p, _SIDE[label]))
            row["a_deck"] = float(da.max()) / length
            if isinstance(rb, WingLikeRef):
                row["b_deck"] = float(rb.surface_distance(p).max()) / length
            else:
                d, where = rb.distance(p)
                if b not in redesigned:
                    for key, cls in (("b_deck", "plain"), ("b_gap", "gap"), ("b_step", "step"),
                                     ("b_end", "end")):
                        row[key] = float(np.max(d[where == cls], initial=0.0)) / length
                own = geo.configuration[b] if geo.configuration is not None else None
                if own is not None:
                    err = np.abs(own.radial_error(p) if hasattr(own, "radial_error")
                                 else own.signed_distance(p))
                    jump = (where == "step") | (where == "end")
                    row["b_own"] = float(np.max(err[~jump], initial=0.0)) / length
                    row["b_own_jump"] = float(np.max(err[jump], initial=0.0)) / length
        rows.append(row)
    return rows


def fillet_depths(geo, description):
    """Deepest fillet point inside the fuselage and inside the wing, relative to L.

    The fuselage is the completed one (``geo.configuration["body"]``, re-designed with
    ``keep_area``), measured by its own ``signed_distance``; the wing is the deck's, its root
    extended inboard along the lofting lines. Returns ``(inside_body, inside_wing)``, each
    0 when no point is inside, NaN when a fillet point is not finite.
    """
    length = description["length"]
    pts = [np.asarray(v, float).reshape(-1, 3) for v in geo.fillets.values()]
    if not pts:
        return 0.0, 0.0
    p = np.concatenate(pts)
    if not np.isfinite(p).all():
        return math.nan, math.nan
    body = geo.configuration["body"]
    sd = np.asarray(body.signed_distance(p))
    wing = references(description)["wing"]
    depth = wing.depth(p, extend_root=True)
    return (float(max(0.0, -sd.min())) / length,
            float(max(0.0, np.max(depth, initial=0.0))) / length)


def public_description(description):
    """The description without the card numbers (for printing and JSON files)."""
    return {k: v for k, v in description.items() if k != "components"}


def components_differ(a, b):
    """'' if two configurations hold the same components field by field, else what differs."""
    if set(a.components) != set(b.components):
        return f"component names {sorted(a.components)} != {sorted(b.components)}"
    for name in a.components:
        ca, cb = a[name], b[name]
        if type(ca) is not type(cb):
            return f"{name}: {type(ca).__name__} != {type(cb).__name__}"
        for field in ca.__dataclass_fields__:
            if field.startswith("_"):
                continue
            va, vb = getattr(ca, field), getattr(cb, field)
            if isinstance(va, tuple) and va and isinstance(va[0], np.ndarray):
                same = len(va) == len(vb) and all(np.array_equal(p, q) for p, q in zip(va, vb))
            elif isinstance(va, np.ndarray) or isinstance(vb, np.ndarray):
                same = np.shape(va) == np.shape(vb) and np.array_equal(va, vb)
            else:
                same = va == vb
            if not same:
                return f"{name}.{field}: {va!r} != {vb!r}"
    return ""
