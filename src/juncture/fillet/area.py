"""Added fillet area per station (TM-4406 eqs 11-14) and the fixed-area fuselage re-design.

TM-4406 projects an upper fillet line and the corresponding lower one into the plane
x = const, takes the polygon through five points of each (eq 11), and subtracts the wing root
trapezoid (eq 12) and the circular segment of the body between the fillet start points
(eq 13). What is left is the two wedges each fillet fills: between the fillet line, the wing
surface from its end point E back to the intersection I, and the body arc from I to the
fillet's start B. Here each wedge is measured on its own, in the cross-section plane of its
own intersection point (the upper and lower intersections of a swept wing lie at different
x), and exactly:

- a cubic fillet (its Bezier control points in ``FilletLines.control``, starting on the
  body circle) by Green's theorem on the closed curve cubic B -> E, segment E -> I, arc
  I -> B: A = 1/2 |integral of (y dz - z dy)|, the cubic's part by 3-point Gauss-Legendre
  quadrature (exact for its degree-5 integrand), the arc's in closed form. The fillet lies
  outside the body, so this is eqs 11-14 with the fillet itself instead of a polygon through
  some of its points (9 points over-state the area by about 1.5 %);
- any other line (circular arcs, the eq 10 blending whose first point lies inside the body,
  degenerate lines) by the polygon of its points closed through I, less its part inside the
  body's disk: the exact area of a polygon cut by a circle (a sum over edges of the signed
  area of the disk within each edge's triangle with the centre).

With a re-designed (smaller) body, the wing root the shrinking body uncovers is added on
request: the part of the wing quadrilateral (I_u, E_u, E_l, I_l) between the original and
the re-designed body circles.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import ConvergenceError, GeometryError

__all__ = ["polygon_disk_area", "fillet_added_area", "wedge_area", "reduced_body",
           "BodyReduction", "keep_area", "Compensation", "Compensate"]

#: What the re-designed body gives up (:func:`keep_area`).
Compensate = Literal["section", "fillet"]


def _cross(u, v):
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _angle(u, v):
    return np.arctan2(_cross(u, v), (u * v).sum(-1))


def polygon_disk_area(poly, center, radius):
    """Signed area of polygon ∩ disk, vectorised over stations.

    Parameters
    ----------
    poly : (m, k, 2) float
        m closed polygons (the last vertex joins the first), any orientation; the sign of the
        result follows it (counter-clockwise positive).
    center : (m, 2) float
    radius : (m,) float

    Returns
    -------
    (m,) float
    """
    p = np.asarray(poly, float) - np.asarray(center, float)[:, None, :]
    r = np.asarray(radius, float)[:, None]
    a_pt, b_pt = p, np.roll(p, -1, axis=1)
    d = b_pt - a_pt
    qa = (d * d).sum(-1)
    qb = 2.0 * (a_pt * d).sum(-1)
    qc = (a_pt * a_pt).sum(-1) - r ** 2
    disc = qb * qb - 4 * qa * qc
    sq = np.sqrt(np.maximum(disc, 0.0))
    safe = np.where(qa > 0, qa, 1.0)
    t1 = np.where((disc > 0) & (qa > 0), (-qb - sq) / (2 * safe), 1.0)
    t2 = np.where((disc > 0) & (qa > 0), (-qb + sq) / (2 * safe), 1.0)
    s1 = np.clip(t1, 0.0, 1.0)
    s2 = np.clip(np.maximum(t2, t1), 0.0, 1.0)
    p1 = a_pt + s1[..., None] * d
    p2 = a_pt + s2[..., None] * d
    r2 = r ** 2
    area = 0.5 * r2 * _angle(a_pt, p1) + 0.5 * _cross(p1, p2) + 0.5 * r2 * _angle(p2, b_pt)
    # An edge that never enters the disk is a pure sector (the clipping above gives that too
    # when s1 == s2, but keep degenerate zero-length edges at zero).
    area = np.where(qa > 0, area, 0.0)
    return area.sum(axis=1)


def _polygon_area(poly):
    q = np.roll(poly, -1, axis=1)
    return 0.5 * _cross(poly, q).sum(axis=1)


_GAUSS_S = 0.5 + 0.5 * np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
_GAUSS_W = np.array([5.0, 8.0, 5.0]) / 18.0


def _bezier_green(control):
    """(m,) integral over s in [0, 1] of 1/2 (y z' - z y') of cubic Bezier curves (m, 4, 2)."""
    c = np.asarray(control, float)
    s = _GAUSS_S[None, :, None]
    w = 1.0 - s
    p = (w ** 3 * c[:, None, 0] + 3 * w * w * s * c[:, None, 1] + 3 * w * s * s * c[:, None, 2]
         + s ** 3 * c[:, None, 3])
    d = 3.0 * (w * w * (c[:, None, 1] - c[:, None, 0]) + 2 * w * s * (c[:, None, 2] - c[:, None, 1])
               + s * s * (c[:, None, 3] - c[:, None, 2]))
    return 0.5 * (_cross(p, d) * _GAUSS_W[None, :]).sum(axis=1)


def _cubic_rows(lines):
    """Rows of ``lines`` that are the cubic their ``control`` gives, sampled at equal s."""
    ctrl = getattr(lines, "control", None)
    m, k = lines.points.shape[:2]
    if ctrl is None or k < 2:
        return np.zeros(m, bool), None
    from .lines import bezier

    ctrl = np.asarray(ctrl, float)
    pts = bezier(np.nan_to_num(ctrl), np.linspace(0.0, 1.0, k))
    size = np.abs(lines.points).max(axis=(1, 2)) + 1.0
    same = np.abs(pts - lines.points).max(axis=(1, 2)) <= 1e-9 * size
    return same & np.isfinite(ctrl).all(axis=(1, 2)), ctrl


def wedge_area(body, lines, corner):
    """Area each fillet line adds to its cross-section (TM-4406 eqs 11-14, one side).

    Parameters
    ----------
    body : CircularBody
    lines : FilletLines
        Fillet lines, each from its start on the body to its end on the wing.
    corner : (m, 3) float
        The intersection point I of each line (where the sharp juncture was).

    Returns
    -------
    (m,) float
        The area between the fillet, the wing from E back to I and the body from I to the
        start, in the plane x = x_I [deck length^2] (module docstring).
    """
    pts = np.asarray(lines.points, float)
    corner = np.asarray(corner, float)
    if not hasattr(body, "section_at"):
        return _polyline_wedge_area(body, lines, corner)
    x = corner[:, 0]
    ctr, r = body.section_at(x)
    # Polygon of the points closed through I, less its part inside the disk.
    poly = np.concatenate([pts[..., 1:], corner[:, None, 1:]], axis=1)
    a_poly = _polygon_area(poly)
    polygon = np.abs(a_poly - polygon_disk_area(poly, ctr, r))
    cubic, ctrl = _cubic_rows(lines)
    start = pts[:, 0]
    on_circle = np.abs(np.hypot(start[:, 1] - ctr[:, 0], start[:, 2] - ctr[:, 1]) - r) <= \
        1e-9 * np.maximum(r, 1.0)
    exact = cubic & on_circle & np.isfinite(pts).all(axis=(1, 2))
    if not exact.any():
        return polygon
    th_i = np.arctan2(corner[:, 2] - ctr[:, 1], corner[:, 1] - ctr[:, 0])
    th_b = np.arctan2(start[:, 2] - ctr[:, 1], start[:, 1] - ctr[:, 0])
    dth = (th_b - th_i + np.pi) % (2 * np.pi) - np.pi
    arc = 0.5 * (r * (ctr[:, 0] * (np.sin(th_b) - np.sin(th_i))
                      - ctr[:, 1] * (np.cos(th_b) - np.cos(th_i))) + r * r * dth)
    end = pts[:, -1, 1:]
    green = _bezier_green(np.nan_to_num(ctrl[..., 1:])) + 0.5 * _cross(end, corner[:, 1:]) + arc
    return np.where(exact, np.abs(green), polygon)


def _section_green(body, x, s_from, s_to):
    """1/2 of the integral of (y dz - z dy) along an arbitrary body's section at stations x
    (m,), from parameter s_from to s_to: the polyline's vertices between them, exactly."""
    k, _ = body._pair(x)
    lo, hi = np.minimum(s_from, s_to), np.maximum(s_from, s_to)
    s = np.concatenate([lo[:, None], np.clip(body._u[k], lo[:, None], hi[:, None]),
                        hi[:, None]], axis=1)
    p = body.point(np.broadcast_to(x[:, None], s.shape), s)[..., 1:]
    g = 0.5 * _cross(p[:, :-1], p[:, 1:]).sum(axis=1)
    return np.where(s_to >= s_from, g, -g)


def _polyline_wedge_area(body, lines, corner):
    """:func:`wedge_area` on an arbitrary-section body: Green's theorem on the closed curve
    fillet B -> E (the cubic exactly where ``control`` gives it, else its polyline), E -> I,
    the section at x_I from I to B's parameter, and on to B (nothing where B lies at x_I)."""
    pts = np.asarray(lines.points, float)
    x = corner[:, 0]
    start = pts[:, 0]
    s_b, s_i = body.parameter_of(start), body.parameter_of(corner)
    b_at = body.point(x, s_b)[:, 1:]
    cubic, ctrl = _cubic_rows(lines)
    yz = pts[..., 1:]
    fillet = 0.5 * _cross(yz[:, :-1], yz[:, 1:]).sum(axis=1)
    if cubic.any():
        fillet = np.where(cubic, _bezier_green(np.nan_to_num(ctrl[..., 1:])), fillet)
    total = (fillet + 0.5 * _cross(yz[:, -1], corner[:, 1:])
             + _section_green(body, x, s_i, s_b) + 0.5 * _cross(b_at, start[:, 1:]))
    return np.where(np.isfinite(total), np.abs(total), 0.0)


def fillet_added_area(body, upper, lower, upper_inter, lower_inter, reference_body=None):
    """Net added cross-sectional area of the fillet at each station (eqs 11-14).

    Parameters
    ----------
    body : CircularBody
    upper, lower : FilletLines
        Fillet lines of the upper and lower surfaces, paired by lofting-line index.
    upper_inter, lower_inter : BodyIntersection
        The intersections (their points are the corners I_u, I_l of the wedges; where a line
        misses the body, its fillet line's start).
    reference_body : CircularBody, optional
        The original body, when ``body`` is a re-designed (smaller) one. Then a third value
        is returned: the area added relative to the original configuration, i.e. the fillets
        plus the wing root uncovered between the original and the re-designed body circles.

    Returns
    -------
    x : (m,) float
        Station of each pair: the x of the upper fillet line's start [deck length].
    area : (m,) float
        Added area of the two fillets (the upper and the lower wedge), one side of the
        airplane [deck length^2].
    area_total : (m,) float
        Only with ``reference_body``: fillet plus uncovered wing root, one side.
    """
    x = upper.points[:, 0, 0]
    i_u = np.where(upper_inter.found[:, None], upper_inter.points, upper.start)
    i_l = np.where(lower_inter.found[:, None], lower_inter.points, lower.start)
    fillet = wedge_area(body, upper, i_u) + wedge_area(body, lower, i_l)
    if reference_body is None:
        return x, fillet
    wing = np.stack([i_u[:, 1:], upper.end[:, 1:], lower.end[:, 1:], i_l[:, 1:]], axis=1)
    ctr, r = body.section_at(x)
    ctr0, r0 = reference_body.section_at(x)
    uncovered = np.abs(polygon_disk_area(wing, ctr0, r0)) - np.abs(polygon_disk_area(wing, ctr, r))
    return x, fillet, fillet + uncovered


@dataclass(frozen=True, slots=True, eq=False)
class Compensation:
    """Result of :func:`keep_area`.

    Attributes
    ----------
    body : CircularBody
        The re-designed body: the original stations plus every fillet station, radius reduced
        so that body area + fillet area equals the original area at each fillet station.
    x : (m,) float
        Fillet stations (x of the upper fillet lines' starts) of the final iteration.
    area_original, area_fillet, area_fillet_only, area_body : (m,) float
        pi r0(x)^2; the area the re-design takes from the body: the fillets' added area plus
        (``compensate="section"``) the wing root they uncover as the body shrinks; the
        fillets' area alone (TM-4406 eq 14); pi r_new(x)^2 [deck length^2]. All for
        ``sides`` fillets.
    radius_original, radius_new : (m,) float
    residual : (m,) float
        |area_body + area_fillet - area_original| / area_original per station.
    iterations : (m,) int
        Iteration at which each station first met the tolerance.
    n_iterations : int
    fillets : tuple
        (upper intersection, lower intersection, upper fillet, lower fillet) of the final body.
    """

    body: object
    x: np.ndarray
    area_original: np.ndarray
    area_fillet: np.ndarray
    area_fillet_only: np.ndarray
    area_body: np.ndarray
    radius_original: np.ndarray
    radius_new: np.ndarray
    residual: np.ndarray
    iterations: np.ndarray
    n_iterations: int
    fillets: tuple


def reduced_body(body, x, area_removed, densify=None, exposure=None):
    """``body`` with the fillet stations ``x`` added and pi r^2 reduced by ``area_removed``.

    The removed area is interpolated linearly between the stations (zero outside them),
    except where that is more than half the section and more than the share A_j /
    pi r0(x_j)^2 interpolated between the same stations, which is then taken (so no station
    in between gives up more area than it has, e.g. towards a closing tail), and taken off
    at every station of the new body: the new radius at a fillet station x_j is exactly
    sqrt(r0(x_j)^2 - A_j / pi). ``densify`` extra stations between
    neighbouring fillet stations (default max(4, 96 / stations): the PDAS deck's three
    fillet stations need 32 near the kinks where the fillet starts, 30 stations need 4) make
    the body's area follow that interpolation in between (with only the fillet stations, the
    body's cubic radius would bulge between them and the area distribution, so the wave
    drag, would not be restored). Camber is kept. Stations in a gap between segments become
    a segment of their own on the straight bridge. Raises GeometryError if the fillet needs
    more area than the body has.

    ``exposure(x) -> L`` (optional) is the length of body perimeter at x covered by the roots
    of wing-like components: shrinking the radius by d there uncovers about L d of their
    area, which is removed too: pi (r0^2 - r^2) = A + L (r0 - r), solved exactly per station.
    """
    return BodyReduction(body, x, densify, exposure).body(area_removed)


def _radius_of(body):
    """r(x): a circular body's radius, an arbitrary one's equivalent radius sqrt(A / pi)."""
    if hasattr(body, "radius_at"):
        return body.radius_at
    return lambda x: np.sqrt(body.area_at(x) / np.pi)


def _new_stations(body, stations, tol):
    """The re-designed body's segments: each original segment with the ``stations`` inside
    it added, and the stations in a gap between two segments as a segment of their own on
    the straight bridge (so the body can give up area there too). Returns a list of
    ``(x (k,), (kind, i, piece, size))``: kind "segment" or "gap", i the original segment
    (after the gap), ``piece`` its first piece and ``size`` its station count."""
    xg = body.x_global
    out, start, piece = [], 0, 0
    for i, size in enumerate(body.segments):
        sx = xg[start:start + size]
        inner = stations[(stations > sx[0] + tol) & (stations < sx[-1] - tol)]
        inner = inner[np.min(np.abs(inner[:, None] - sx[None, :]), axis=1) > tol] \
            if inner.size else inner
        if out and sx[0] > out[-1][0][-1] + tol:
            x_a, x_b = out[-1][0][-1], sx[0]
            gap = stations[(stations > x_a + tol) & (stations < x_b - tol)]
            if gap.size:
                out.append((np.concatenate([[x_a], gap, [x_b]]), ("gap", i, piece, size)))
        out.append((np.union1d(sx, inner), ("segment", i, piece, size)))
        start += size
        piece += size - 1
    return out


class BodyReduction:
    """The re-design of one body at fixed stations, for any removed areas (:func:`reduced_body`).

    Everything that depends only on the body and the stations (the new station layout, the
    original radius, camber and slopes there, the covered perimeter, the interpolation of the
    removed area) is computed once; :meth:`body` then builds the re-designed body for a
    vector of removed areas and :meth:`jacobian` differentiates its radius reduction.
    """

    def __init__(self, body, x, densify=None, exposure=None):
        self.original = body
        self.order = np.argsort(x)
        xs = np.asarray(x, float)[self.order]
        xg = body.x_global
        if densify is None:
            densify = max(4, int(np.ceil(96 / max(xs.size, 1))))
        if densify and xs.size > 1:
            t = np.arange(1, densify + 1) / (densify + 1)
            # Also the body intervals just outside the fillet range, where nothing is
            # removed: there the new stations pin the body to its original radius, so its
            # cubic does not swing away from the original next to the last re-designed
            # station.
            before = xg[xg < xs[0]][-1:] if (xg < xs[0]).any() else xs[:1]
            after = xg[xg > xs[-1]][:1] if (xg > xs[-1]).any() else xs[-1:]
            knots = np.concatenate([before, xs, after])
            between = (knots[:-1, None] + t[None, :] * np.diff(knots)[:, None]).ravel()
            stations = np.union1d(xs, between)
        else:
            stations = xs
        tol = 1e-12 * max(body.length, 1.0)
        layout = _new_stations(body, stations, tol)
        new_x = [xs_ for xs_, _ in layout]
        self.xs, self.seg_sizes = xs, tuple(len(xs_) for xs_ in new_x)
        base = self._base(body, layout)
        self.xn = xn = np.concatenate(new_x)
        self.rc = np.concatenate([b[0] for b in base])
        self.drc = np.concatenate([b[1] for b in base])
        self.r0 = np.maximum(self.rc[:, 0], 0.0)
        radius_at = _radius_of(body)
        lcov = np.zeros_like(xn) if exposure is None else np.asarray(exposure(xn), float)
        self.b = 2 * np.pi * self.r0 - lcov
        # removed(xn) = P a: linear interpolation between the stations, zero outside.
        n_a = xs.size
        P = np.zeros((xn.size, n_a))
        if n_a == 1:
            P[np.abs(xn - xs[0]) <= tol, 0] = 1.0
        else:
            k = np.clip(np.searchsorted(xs, xn, side="right") - 1, 0, n_a - 2)
            w = (xn - xs[k]) / (xs[k + 1] - xs[k])
            ok = (xn >= xs[0]) & (xn <= xs[-1])
            rows = np.flatnonzero(ok)
            P[rows, k[ok]] += 1.0 - w[ok]
            P[rows, k[ok] + 1] += w[ok]
        # Between the stations the area given up is interpolated linearly, but where that is
        # more than half the section it is capped at the share of the section the stations
        # around give up, interpolated (towards a closing tail, the linear interpolation of
        # the area asked for more than the body has).
        area_n = np.pi * self.r0 ** 2
        at = np.abs(xn[:, None] - xs[None, :]) <= tol
        area_s = np.where(at.any(axis=0), (area_n[:, None] * at).max(axis=0),
                          np.pi * radius_at(xs) ** 2)
        with np.errstate(divide="ignore", invalid="ignore"):
            share = np.where(area_s[None, :] > 0, area_n[:, None] / area_s[None, :],
                             at.astype(float))
        self.P = P
        self.P_share = P * share
        self._rows = None
        self._dd_da = None
        # Node spacing to the left and right within each segment (inf where a segment ends):
        # the slope limiter of :meth:`_slopes` keeps each Hermite piece of the radius
        # reduction on the side of zero its two nodes are on.
        h_left, h_right, first = np.full(xn.size, np.inf), np.full(xn.size, np.inf), 0
        for size in self.seg_sizes:
            h = np.diff(xn[first:first + size])
            h_left[first + 1:first + size] = h
            h_right[first:first + size - 1] = h
            first += size
        self._h = (h_left, h_right)
        self._limit = None

    def _base(self, body, layout):
        """Per new segment, the original radius and camber (k, 2) and their slopes (k, 2):
        from the segment's own pieces (one-sided at a joint where the next segment starts at
        the same x), straight across a gap (a bridge)."""
        base, counts, pps = [], body.points_per_section, []
        for merged, (kind, i, piece, size) in layout:
            if kind == "gap":
                x_a, x_b = merged[0], merged[-1]
                ra = base[-1][0][-1]
                rb = body._interp.value_and_slope(np.array([x_b]) - body.origin[0],
                                                  (piece, piece + size - 2))[0][0]
                slope = (rb - ra) / (x_b - x_a)
                base.append((ra + (merged - x_a)[:, None] * slope[None, :],
                             np.repeat(slope[None, :], merged.size, axis=0)))
                pps.append(None if counts is None else counts[i - 1])
                continue
            rc, drc = body._interp.value_and_slope(merged - body.origin[0],
                                                   (piece, piece + size - 2))
            base.append((rc, drc))
            pps.append(None if counts is None else counts[i])
        self.points_per_section = None if counts is None else tuple(pps)
        return base

    def _gradient(self, values):
        """d(values)/dx along the new stations, segment by segment (np.gradient's scheme)."""
        out = np.empty_like(values)
        first = 0
        for size in self.seg_sizes:
            sl = slice(first, first + size)
            out[sl] = np.gradient(values[sl], self.xn[sl], axis=0) if size > 2 else \
                np.diff(values[sl], axis=0) / np.diff(self.xn[sl])[0]
            first += size
        return out

    def _slopes(self, d):
        """Slopes of the radius reduction d at the nodes: np.gradient's, limited so that
        every Hermite piece keeps the sign of its two end values (its Bezier control values
        d + m h / 3 and d - m h / 3 stay on the side of zero d is on). Without the limit
        the cubic between a station that gives up area and one that gives up none swings
        past zero: the re-designed body grew there, aft of the last fillet station (issue
        11). The limit acts only where the slope would carry the curve across zero."""
        h_left, h_right = self._h
        m = self._gradient(d)
        with np.errstate(divide="ignore", invalid="ignore"):
            to_left = np.where(np.isfinite(h_left), 3.0 * d / h_left, np.inf)
            to_right = np.where(np.isfinite(h_right), 3.0 * d / h_right, np.inf)
        pos = d >= 0
        lo = np.where(pos, -to_right, np.where(np.isfinite(h_left), to_left, -np.inf))
        hi = np.where(pos, to_left, np.where(np.isfinite(h_right), -to_right, np.inf))
        below, above = m < lo, m > hi
        # d(slope) / d(d) where a bound acts (the bounds are linear in d): kept for jacobian.
        coef = np.where(below, np.where(pos, -3.0 / h_right, 3.0 / h_left),
                        np.where(pos, 3.0 / h_left, -3.0 / h_right))
        self._limit = (below | above, np.where(below | above, coef, 0.0))
        return np.where(below, lo, np.where(above, hi, m))

    def body(self, area_removed):
        """The re-designed CircularBody for removed areas (one per station, input order)."""
        return self._build(self._reduce(area_removed))

    def _reduce(self, area_removed):
        """The radius reduction d (r0 - r, equivalent radius on an arbitrary section) at
        every new station, and the state :meth:`jacobian` needs."""
        body, xn, r0, b = self.original, self.xn, self.r0, self.b
        a = np.asarray(area_removed, float)[self.order]
        linear, shared = self.P @ a, self.P_share @ a
        half = 0.5 * np.pi * r0 ** 2
        cap = np.maximum(shared, half)
        # Never less than nothing: a fillet only adds area, so the body never grows (a
        # station whose fillet is blended out to nothing would otherwise give up -1e-8 of
        # round-off, and the body grow behind it).
        self._rows = (linear > cap, shared >= half, linear < 0)
        removed = np.maximum(np.minimum(linear, cap), 0.0)
        # pi d^2 - (2 pi r0 - L) d + A = 0 for the radius reduction d = r0 - r (smaller root).
        disc = b * b - 4 * np.pi * removed
        if np.any(disc < 0) or np.any(r0 ** 2 - removed / np.pi < 0):
            k = int(np.argmax((disc < 0) | (r0 ** 2 - removed / np.pi < 0)))
            covered = 2 * np.pi * r0[k] - b[k]
            most = b[k] ** 2 / (4 * np.pi)  # what shrinking can give up with that cover
            raise GeometryError(f"the fillet adds more area ({removed[k]:.4g}) than the body "
                                f"can give up at x = {xn[k]:.6g} (section {np.pi * r0[k] ** 2:.4g}"
                                f", wing roots covering {covered:.4g} of its perimeter "
                                f"{2 * np.pi * r0[k]:.4g}: at most {most:.4g}); use a smaller "
                                "fillet (theta_u, end value) or compensate='fillet'",
                                body.name, f"x = {xn[k]:.6g}")
        sqrt_disc = np.sqrt(disc)
        den = b + sqrt_disc
        # The stable form of (b - sqrt(disc)) / (2 pi); nothing to remove where the body is
        # a point.
        d = np.where(den > 0, 2 * removed / np.where(den > 0, den, 1.0), 0.0)
        self._dd_da = np.where(den > 0, 1.0 / np.where(sqrt_disc > 0, sqrt_disc, np.inf), 0.0)
        self._slope_d = self._slopes(d)
        return d

    def _build(self, d):
        from ..model import CircularBody

        body, xn, r0 = self.original, self.xn, self.r0
        # Hermite pieces with the original slopes less the reduction's: where nothing is
        # removed the new body is the original cubic exactly, and everywhere it depends
        # smoothly on the removed areas (a PCHIP rebuild would switch its slope limiter on a
        # cylindrical mid-body, and kink the area iteration's map).
        slopes = self.drc.copy()
        slopes[:, 0] -= self._slope_d
        return CircularBody(body.name, xn - body.origin[0], r0 - d, self.rc[:, 1], body.origin,
                            self.seg_sizes, body.mirrored, body.axial, self.points_per_section,
                            slopes)

    def _between(self, dnode, xq):
        """d(xq) from nodal values: the Hermite interpolant of the nodal d with slopes
        grad(d), linear in d, so each column of ``dnode`` is interpolated the same way."""
        from ..model.body import hermite_pieces

        limited, coef = self._limit
        dslope = np.where(limited[:, None], coef[:, None] * dnode, self._gradient(dnode))
        return hermite_pieces(self.xn, dnode, dslope, self.seg_sizes)(xq)

    def jacobian(self, xq):
        """d(r0 - r)(xq) / d(area_removed) of the last :meth:`body`: (len(xq), stations)."""
        capped, by_share, clipped = self._rows
        used = np.where(capped[:, None], np.where(by_share[:, None], self.P_share, 0.0), self.P)
        used = np.where(clipped[:, None], 0.0, used)
        dnode = self._dd_da[:, None] * used  # d(d_n) / d(a), sorted station order
        xq = np.asarray(xq, float)
        d_q = self._between(dnode, xq)
        inside = (xq >= self.xn[0]) & (xq <= self.xn[-1])
        out = np.zeros((xq.size, self.xs.size))
        out[:, self.order] = np.where(inside[:, None], d_q, 0.0)
        return out


def _structured_newton(history, c_upper, w_upper, w_lower):
    """Newton step for F(t) = G(t) - given(t) = 0 with a Jacobian built from its structure.

    A station's added area G_j depends on the body where its two fillet lines start: the
    radius reductions D_u = d(x_u,j) (upper, the station itself) and D_l = d(x_l,j) (the
    lower line of the same lofting line, at another x). Model G_j = const + alpha_j D_u +
    beta_j D_l, with alpha_j, beta_j fitted to the measured differences of the last
    iterates (least squares per station; minimum norm from a single difference); the given
    area depends on D_u through c_upper = d(given)/dD_u = 2 pi r - L. With w_upper, w_lower
    = dD/dt (exact, from the re-designed body) the Jacobian is

        J = diag(alpha - c_upper) w_upper + diag(beta) w_lower.

    ``history`` holds (t, F, (D_u, D_l, G)) per iterate, oldest first. Returns the step, or
    None if the model is singular (then the caller substitutes).
    """
    du = np.diff(np.array([h[2][0] for h in history]), axis=0)  # (k, n)
    dl = np.diff(np.array([h[2][1] for h in history]), axis=0)
    dg = np.diff(np.array([h[2][2] for h in history]), axis=0)
    # Per-station 2x2 normal equations, with a ridge so that one difference gives the
    # minimum-norm fit.
    suu, sul, sll = (du * du).sum(0), (du * dl).sum(0), (dl * dl).sum(0)
    sug, slg = (du * dg).sum(0), (dl * dg).sum(0)
    if len(du) == 1:
        # One difference cannot separate alpha from beta at a station; fit them as
        # constants across the stations (they vary slowly along the wing) instead.
        m = np.stack([du[0], dl[0]], axis=1)
        coef, _, rank, sv = np.linalg.lstsq(m, dg[0], rcond=None)
        if rank == 2 and sv[-1] > 1e-3 * sv[0]:
            suu, sul, sll = np.ones_like(suu), np.zeros_like(sul), np.ones_like(sll)
            sug, slg = np.full_like(sug, coef[0]), np.full_like(slg, coef[1])
    ridge = 1e-10 * (suu + sll)
    det = (suu + ridge) * (sll + ridge) - sul * sul
    moved = det > 0  # a station whose body never moved keeps alpha = beta = 0
    safe = np.where(moved, det, 1.0)
    alpha = np.where(moved, ((sll + ridge) * sug - sul * slg) / safe, 0.0)
    beta = np.where(moved, ((suu + ridge) * slg - sul * sug) / safe, 0.0)
    jac = (alpha - c_upper)[:, None] * w_upper + beta[:, None] * w_lower
    f = history[-1][1]
    try:
        with np.errstate(all="ignore"):
            step = np.linalg.solve(jac, -f)
    except np.linalg.LinAlgError:
        return None
    # A step far beyond the substitution's is a broken model, not a Newton step.
    if not np.all(np.isfinite(step)) or np.abs(step).max() > 10 * np.abs(f).max():
        return None
    return step


def _feasible(reduction, t, step, scale=1.0, tries=6):
    """t + scale step, halved towards t until the body has the area it asks for (the last
    try raises the GeometryError)."""
    for k in range(tries):
        trial = t + scale * 0.5 ** k * step
        try:
            reduction.body(trial)
            return trial
        except GeometryError:
            if k == tries - 1:
                raise
    return trial


def _fillets_on(make_fillets, current, previous, warm, it, x):
    """make_fillets on an iterate; on a re-designed body a failure (a lofting line that
    grazes it) is the iteration's, named by the body and the stations it had reached."""
    if x is None:
        return make_fillets(current, previous, warm)
    try:
        return make_fillets(current, previous, warm)
    except ConvergenceError as exc:
        raise ConvergenceError(f"area compensation stopped at iteration {it} (stations x = "
                               f"{x.min():.6g} to {x.max():.6g}): on the re-designed body, "
                               f"{exc.reason}", current.name) from None


def keep_area(body, make_fillets, tolerance=1e-9, max_iterations=150, sides=2, exposure=None,
              memory=1, initial=None, compensate: Compensate = "section"):
    """Shrink the body until body area + added area equals the original area (TM-4406).

    TM-4406 compensates the fillet's area (eq 14) only (``compensate="fillet"``). When the
    body shrinks, the wing's root extends into the space it leaves, which adds area too
    (about a fifth of the fillet's on the PDAS sample deck, where compensating the fillet
    alone left the slender-body wave drag 0.25 % high). By default (``"section"``) the added
    area compensated is therefore the fillet plus that uncovered wing root, so that the whole
    cross-section keeps its original area.

    Parameters
    ----------
    body : CircularBody
        The original body.
    make_fillets : callable
        ``make_fillets(body, previous, warm) -> (upper_inter, lower_inter, upper_fillet,
        lower_fillet)`` for a given body (the fillet is rebuilt on each re-designed body);
        ``previous`` is None (the original body) or that tuple from the previous iterate,
        whose blending region the new fillets keep; ``warm`` says whether its solutions may
        seed the root finders (only while every re-designed body lies inside the original).
    tolerance : float
        Relative area residual to reach at every fillet station.
    sides : {1, 2}
        How many fillets share each body cross-section: 2 for a wing with a mirror image (the
        body's pi r^2 is the whole section, so both sides' fillets are compensated), 1 for a
        surface on the plane of symmetry.
    exposure : callable, optional
        ``exposure(x) -> L``: body perimeter covered by wing-like roots at x (all of them,
        both sides; see :func:`reduced_body`). The fillets are then measured on their
        stations and the uncovered roots everywhere on the re-designed body, so the whole
        cross-section keeps its area between the fillet stations too. Without it the
        uncovered wing root is measured on the fillet stations only (fillet polygons).
    memory : int
        Past differences the Newton step's sensitivities are fitted to (1: the last one,
        with the sensitivities taken as constants across the stations).
    initial : tuple, optional
        ``make_fillets(body, None, False)`` if the caller already has it.
    compensate : {"section", "fillet"}
        What the body gives up: the fillets and the wing root they uncover (the whole
        cross-section keeps its area), or the fillets' area alone (TM-4406 eqs 11-14: the
        body area plus the fillets' equals the original; ``exposure`` is then not used).

    Returns
    -------
    Compensation
        ``area_fillet`` is the added area of all ``sides`` fillets at each station (with
        ``compensate="section"``, plus the uncovered root).

    Raises
    ------
    GeometryError
        An unknown ``compensate``; the fillets need more area than the body has.
    ConvergenceError
        The residual does not reach ``tolerance`` in ``max_iterations``.

    Notes
    -----
    Each iteration removes an area t from the original body (not from the previous iterate)
    at fixed nodes (the stations on the original body), so the problem is the root of
    F(t) = A(body(t)) - given(body(t)), the added area against what the body gives up, both
    measured at the current stations. The first step is the paper's substitution (which
    alone converges linearly, about 0.07 per step on the benchmark wing). After it, a Newton
    step uses the structure of the Jacobian: a station's area depends on the body only
    where its upper and its lower fillet lines start (the lower one at another x), with
    sensitivities fitted to the measured differences (:func:`_structured_newton`) and the
    exact derivative of the re-designed body (:meth:`BodyReduction.jacobian`). The fillets
    keep the original body's blending region, and the re-designed body is a smooth function
    of t (Hermite pieces), so the model holds. The intersections are warm-started from the
    previous iterate while the body only shrinks.
    """
    if compensate not in ("section", "fillet"):
        raise GeometryError(f"compensate must be 'section' or 'fillet', found {compensate!r}",
                            body.name)
    if compensate == "fillet":
        exposure = None
    elif exposure is None and not hasattr(body, "radius_at"):
        raise GeometryError("keep_area on an arbitrary-section body measures the wing root "
                            "it uncovers by its covered perimeter: pass exposure, or "
                            "compensate='fillet'", body.name)
    from .section_redesign import reduction_for

    radius = _radius_of(body)
    current = body
    first_met = None
    history = []
    previous, warm = None, False
    reduction = t = None
    x = None  # the stations of the last iterate
    for it in range(1, max_iterations + 1):
        parts = initial if (it == 1 and initial is not None) else \
            _fillets_on(make_fillets, current, previous, warm, it, x)
        if compensate == "fillet":
            # TM-4406: the fillets alone.
            x, only = fillet_added_area(current, *parts[2:], *parts[:2])
            r_orig, r_now = radius(x), _radius_of(current)(x)
            only = sides * only
            a_f, covered = only, 0.0
        elif exposure is not None:
            # Fillets by their areas; every uncovered root by its covered perimeter.
            x, only = fillet_added_area(current, *parts[2:], *parts[:2])
            r_orig, r_now = radius(x), _radius_of(current)(x)
            covered = exposure(x)
            only = sides * only
            a_f = only + covered * (r_orig - r_now)
        else:
            x, only, a_f = fillet_added_area(current, *parts[2:], *parts[:2],
                                             reference_body=body)
            only, a_f = sides * only, sides * a_f
            r_orig, r_now = radius(x), _radius_of(current)(x)
            covered = 0.0  # the polygons already hold the uncovered root
        a0 = np.pi * r_orig ** 2
        a_b = np.pi * r_now ** 2
        residual = np.abs(a_b + a_f - a0) / np.where(a0 > 0, a0, 1.0)
        met = residual <= tolerance
        first_met = np.where(met, it, 0) if first_met is None else \
            np.where((first_met == 0) & met, it, first_met)
        if met.all():
            return Compensation(current, x, a0, a_f, only, a_b, np.sqrt(a0 / np.pi), r_now,
                                residual, first_met, it, parts)
        # The unknown: the area t given up for the fillets (and, without an exposure model,
        # for the uncovered root too) at fixed nodes, the first iteration's stations. The
        # stations move a little as the body shrinks (the lofting lines meet it further
        # inboard), so the residual F = G - given is measured where they are now, on what
        # the body really gives up there; with the nodes fixed it is a function of t alone.
        g = only if (exposure is not None or compensate == "fillet") else a_f
        given = a0 - a_b - covered * (r_orig - r_now)
        x_low = parts[3].points[:, 0, 0]
        sample = (r_orig - r_now, radius(x_low) - _radius_of(current)(x_low), g)
        if reduction is None:
            reduction, t = reduction_for(body, x, exposure=exposure), given
        f = g - given
        size = np.abs(f).max()
        if history and size > np.abs(history[-1][1]).max():
            history = []  # no progress: start the model again from here
        history.append((t, f, sample))
        step = None
        if len(history) >= 2:
            w = reduction.jacobian(np.concatenate([x, x_low]))
            step = _structured_newton(history[-(memory + 1):], 2 * np.pi * r_now - covered,
                                      w[:x.size], w[x.size:])
        if step is not None:
            try:
                reduction.body(t + step)
            except GeometryError:
                # A Newton step that asks more than the body has: the paper's substitution.
                step, history = None, []
        t = _feasible(reduction, t, f if step is None else step)
        current = reduction.body(t)
        # Warm starts are safe while the body only shrinks (nothing new outboard to meet).
        previous, warm = parts, bool(np.all(t >= 0))
    raise ConvergenceError(f"area compensation did not reach {tolerance:g} in {max_iterations} "
                           f"iterations (worst residual {residual.max():.3g} at x = "
                           f"{x[np.argmax(residual)]:.6g})", body.name)
