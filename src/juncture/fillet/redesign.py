"""The fuselage re-designed at fixed stations for given removed areas (TM-4406).

:class:`BodyReduction` adds the fillet stations (and stations between them) to a circular
body and shrinks its radius there by what each station gives up
(:mod:`juncture.fillet.section_redesign` does the same for arbitrary sections);
:func:`juncture.fillet.compensation.keep_area` iterates it until the area is kept.
"""

from __future__ import annotations

import numpy as np

from ..errors import GeometryError

__all__ = ["reduced_body", "BodyReduction"]


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
