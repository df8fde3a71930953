"""Bodies: circular fuselages and pods (TM-4406 eqs 1-3) and arbitrary-section fuselages.

A body is a sequence of cross-sections at increasing x, grouped in *segments* (the deck's
fuselage segments). Between segments the body is the surface the deck describes, the same
for every method (point, radius, area, distances, the slope bounds of the root finders):

============================  ===========================================================
joint                          surface
============================  ===========================================================
within a segment               circular: radius and camber PCHIP in x (linear on request);
                               arbitrary: sections matched by arc length, linear in x
repeated joint station         a step if the two sections differ; at x = x_joint itself
(segment k ends at x_j,        the later segment's section holds; the step's x = const
segment k + 1 starts at x_j)   face is not part of the parametric surface
gap (segment k ends at x_a,    straight lines from the last section of one segment to the
segment k + 1 starts at        first of the next: circular, radius and camber linear in x
x_b > x_a, valid per the       (a frustum); arbitrary, matched points joined linearly,
format)                        as between any two stations
============================  ===========================================================

The straight bridge is what the Harris program draws: it joins given points by straight lines
(issue 11), and straight lines between corresponding points of two circles (same angle
theta) sweep a frustum, whose radius is linear in x and whose area is therefore quadratic in
x. Linear in area instead would bulge the bridge outward (r = sqrt of a linear function lies
above the chord) and no longer join the given points by straight lines. docs/formats.md
section 1.5 and TM-4406/TM-4607 give the circular fuselage only at its stations ("a radius
distribution r(x) can be synthesized from the input array", TM-4607) and say nothing of
gaps.

Angle convention (TM-4406 eqs 2-3, architecture.md): y = y_c + r cos(theta),
z = c(x) + r sin(theta); theta = 0 on the horizontal to starboard, +pi/2 at the top, -pi/2 at
the bottom. (The deck's wireframe measures from the top: that is converted at the io edge.)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import GeometryError
from ._arrays import check_finite, frozen
from ._pchip import hermite_coefficients, pchip_coefficients
from ._range_max import range_max, range_max_table
from ._sections import area_and_centroid, matched_pairs

__all__ = ["CircularBody", "ArbitraryBody", "AxialInterpolation"]

AxialInterpolation = Literal["pchip", "linear"]


def _segment_layout(x, segments, name):
    """Validate x against a segment layout; return (start, stop) index pairs."""
    n = x.size
    seg = (n,) if segments is None else tuple(int(s) for s in segments)
    if sum(seg) != n or any(s < 2 for s in seg):
        raise GeometryError(f"segment sizes {seg} must each be >= 2 and add up to the "
                            f"{n} stations", name)
    bounds, start = [], 0
    for s in seg:
        bounds.append((start, start + s))
        start += s
    for a, b in bounds:
        d = np.diff(x[a:b])
        if (d <= 0).any():
            k = a + int(np.argmax(d <= 0)) + 1
            raise GeometryError(f"x must increase within a segment: {x[k - 1]:g} then "
                                f"{x[k]:g}", name, k + 1)
    for (_, b0), (a1, _) in zip(bounds, bounds[1:]):
        if x[a1] < x[b0 - 1]:
            raise GeometryError(f"segments overlap: a segment starts at x = {x[a1]:g} before "
                                f"the previous one ends at {x[b0 - 1]:g}", name, a1 + 1)
    return seg, bounds


def hermite_pieces(x, values, slopes, segments):
    """Segment-wise cubic Hermite interpolant of columns ``values`` (n, cols) along ``x``.

    ``slopes`` (n, cols) are the x-derivatives at the stations; ``segments`` the station
    count of each segment, as for a body. Returns a callable ``f(xq) -> (..., cols)`` (the
    body's own piecewise evaluator: the first / last cubic extrapolates).
    """
    x = np.asarray(x, float)
    _, bounds = _segment_layout(x, segments, "hermite pieces")
    return _Piecewise(x, np.asarray(values, float), bounds, "pchip",
                      np.asarray(slopes, float))


class _Piecewise:
    """Segment-wise interpolant of several columns of data along x, as one piecewise cubic.

    Each segment gets its own PCHIP (or linear, or Hermite with given slopes) interpolant;
    their polynomial pieces are merged into a single table of breakpoints and cubic
    coefficients so that evaluation is one binary search and one Horner pass for all columns
    at once (the root finders call this in their inner loop). Zero-length intervals at
    repeated joint stations are dropped (at the joint the later segment holds). A gap between
    segments (segment k ends at x_a, segment k + 1 starts at x_b > x_a) is bridged by one
    straight piece from the last station of one to the first of the next, as the Harris
    program joins given points by straight lines. Beyond the ends the first / last cubic
    extrapolates.

    ``segment_pieces`` (n_stations - n_segments,) maps the segments' own pieces, numbered
    without the bridges (segment 1's first, ..., then segment 2's), to rows of the table.
    """

    def __init__(self, x, columns, bounds, method, slopes=None):
        breaks, coefs, own, count = [], [], [], 0
        for i, (a, b) in enumerate(bounds):
            xs, ys = x[a:b], columns[a:b]
            if i and x[a] > x[a - 1]:  # a gap after the previous segment: a straight bridge
                slope = (ys[0] - columns[a - 1]) / (x[a] - x[a - 1])
                breaks.append(x[a - 1:a])
                coefs.append(np.stack([np.zeros_like(slope), np.zeros_like(slope), slope,
                                       columns[a - 1]])[:, None, :])
                count += 1
            if slopes is not None:
                c = hermite_coefficients(xs, ys, slopes[a:b])
            elif method == "pchip":
                c = pchip_coefficients(xs, ys)  # (4, n-1, cols), local coordinate x - x_k
            else:
                slope = np.diff(ys, axis=0) / np.diff(xs)[:, None]
                c = np.stack([np.zeros_like(slope), np.zeros_like(slope), slope, ys[:-1]])
            breaks.append(xs[:-1])
            coefs.append(c)
            own.append(np.arange(count, count + xs.size - 1))
            count += xs.size - 1
        self.breaks = np.concatenate(breaks)
        self.coefs = np.concatenate(coefs, axis=1)  # (4, n_pieces, cols)
        self.ncols = columns.shape[1]
        self.segment_pieces = np.concatenate(own)
        # The last station is the right end of its cubic, which gives its value only to
        # rounding (a pointed tail's radius 0 came out 8.9e-16): taken as given there.
        self.end = (float(x[-1]), np.asarray(columns[-1], float))

    def _exact_end(self, xq, values):
        at = xq == self.end[0]
        return np.where(at[..., None], self.end[1], values) if at.any() else values

    def value_and_slope(self, xq, pieces=None):
        """Values and x-derivatives at xq in one pass (shared coefficient gather).

        ``pieces = (first, last)`` restricts the evaluation to those pieces, numbered as the
        segments' own pieces (bridges across gaps not counted; see ``segment_pieces``): one
        segment's, so that its end station takes that segment's one-sided slope.
        """
        xq = np.asarray(xq, dtype=float)
        if pieces is None:
            lo, hi = 0, self.breaks.size - 1
        else:
            lo, hi = (int(self.segment_pieces[p]) for p in pieces)
        k = np.minimum(np.maximum(np.searchsorted(self.breaks, xq, side="right") - 1, lo), hi)
        t = (xq - self.breaks[k])[..., None]
        c3, c2, c1, c0 = self.coefs[:, k]
        return (self._exact_end(xq, ((c3 * t + c2) * t + c1) * t + c0),
                (3 * c3 * t + 2 * c2) * t + c1)

    def __call__(self, xq, nu=0):
        xq = np.asarray(xq, dtype=float)
        # np.minimum/maximum: np.clip's overhead shows in the root finders' inner loops.
        k = np.minimum(np.maximum(np.searchsorted(self.breaks, xq, side="right") - 1, 0),
                       self.breaks.size - 1)
        t = (xq - self.breaks[k])[..., None]
        c3, c2, c1, c0 = self.coefs[:, k]
        if nu == 0:
            return self._exact_end(xq, ((c3 * t + c2) * t + c1) * t + c0)
        if nu == 1:
            return (3 * c3 * t + 2 * c2) * t + c1
        if nu == 2:
            return 6 * c3 * t + 2 * c2
        raise ValueError(f"derivative order {nu} not supported")


@dataclass(frozen=True, slots=True, eq=False)
class CircularBody:
    """A body with circular cross-sections: a fuselage (on the centre line) or a pod.

    Parameters
    ----------
    name : str
        Component name, e.g. ``"body"``, ``"pod 1"``.
    x : (n,) float
        Stations along the axis, relative to ``origin[0]`` [deck length].
    radius : (n,) float
        Cross-section radius at each station, >= 0 [deck length].
    camber : (n,) float, optional
        Height of each section centre above ``origin[2]`` (the deck's ZFUS) [deck length].
    origin : (3,) float
        Origin of the body's stations; the axis runs through (origin[1], origin[2] + camber).
    segments : tuple of int, optional
        Number of stations in each segment (default: one segment). A segment may repeat the
        previous one's last station (a joint, a step if the radius differs) or start after
        it (a gap, bridged by a straight frustum: see the module docstring).
    mirrored : bool
        Whether the body has an image at -y (a pod off the centre line). A centre-line body
        is described by its y >= 0 half and is not "mirrored" in this sense.
    axial : {"pchip", "linear"}
        Interpolation of radius and camber along x within a segment.
    points_per_section : tuple of int, optional
        Points per half cross-section of each segment in the output networks (the deck's
        NRADX); 19 if not given.
    slopes : (n, 2) float, optional
        dr/dx and d(camber)/dx at each station. Given, radius and camber are interpolated by
        cubic Hermite pieces with these slopes instead of ``axial`` (a re-designed body keeps
        its original's shape between stations this way, and depends smoothly on its radii);
        a gap between segments stays a straight bridge.
    """

    name: str
    x: np.ndarray
    radius: np.ndarray
    camber: np.ndarray = None
    origin: np.ndarray = (0.0, 0.0, 0.0)
    segments: tuple = None
    mirrored: bool = False
    axial: AxialInterpolation = "pchip"
    points_per_section: tuple = None
    slopes: np.ndarray = None
    _interp: object = None
    _lipschitz: float = None

    def __post_init__(self):
        name = self.name
        x = frozen(self.x, (None,), name, "x")
        r = frozen(self.radius, (x.size,), name, "radius (one per station)")
        c = frozen(np.zeros(x.size) if self.camber is None else self.camber, (x.size,), name,
                   "camber (one per station)")
        o = frozen(self.origin, (3,), name, "origin")
        for arr, what in ((x, "x"), (r, "radius"), (c, "camber"), (o, "origin")):
            check_finite(arr, name, what)
        if (r < 0).any():
            k = int(np.argmax(r < 0))
            raise GeometryError(f"radius is negative ({r[k]:g})", name, k + 1)
        if self.axial not in ("pchip", "linear"):
            raise GeometryError(f"axial interpolation must be 'pchip' or 'linear', found "
                                f"{self.axial!r}", name)
        seg, bounds = _segment_layout(x, self.segments, name)
        pps = self.points_per_section
        if pps is not None:
            pps = tuple(int(m) for m in pps)
            if len(pps) != len(seg) or any(m < 2 for m in pps):
                raise GeometryError(f"points_per_section {pps} must give a count >= 2 for each "
                                    f"of the {len(seg)} segments", name)
        object.__setattr__(self, "points_per_section", pps)
        slopes = None
        if self.slopes is not None:
            slopes = frozen(self.slopes, (x.size, 2), name, "slopes (dr/dx, dc/dx per station)")
            check_finite(slopes, name, "slopes")
        for field, value in (("x", x), ("radius", r), ("camber", c), ("origin", o),
                             ("segments", seg), ("mirrored", bool(self.mirrored)),
                             ("slopes", slopes)):
            object.__setattr__(self, field, value)
        interp = _Piecewise(x, np.stack([r, c], axis=1), bounds, self.axial, slopes)
        object.__setattr__(self, "_interp", interp)


    @property
    def x_global(self):
        """(n,) stations in configuration coordinates [deck length]."""
        return self.x + self.origin[0]

    @property
    def length(self):
        """Body length from first to last station [deck length]."""
        return float(self.x[-1] - self.x[0])

    def _on_body(self, xq):
        """Whether local stations xq lie on the body, up to the rounding of origin + x.

        A global station ``origin[0] + x[k]`` taken back to local may land an ulp or two
        beyond ``x[k]``; at the end stations that would read as off the body (radius 0) and
        close an open base or nose in every output.
        """
        tol = 4.0 * np.finfo(float).eps * (abs(float(self.origin[0]))
                                           + max(abs(float(self.x[0])), abs(float(self.x[-1]))))
        return (xq >= self.x[0] - tol) & (xq <= self.x[-1] + tol)

    def _local(self, x):
        """Global stations x as local ones; one within the rounding of ``origin + x[k]`` of a
        station is that station exactly.

        ``origin[0] + x[k]`` taken back to local may land an ulp or two off ``x[k]``; where
        the radius is zero there (a closed nose or tail), the cubic piece read an ulp away
        gives 1e-15 instead of 0, and the closing section became a ring of distinct points
        an ulp apart instead of one point.
        """
        xq = np.asarray(x, float) - self.origin[0]
        st = self.x
        k = np.clip(np.searchsorted(st, xq), 1, st.size - 1)
        near = np.where(np.abs(xq - st[k - 1]) <= np.abs(st[k] - xq), st[k - 1], st[k])
        tol = 4.0 * np.finfo(float).eps * (abs(float(self.origin[0])) + np.abs(near))
        return np.where(np.abs(xq - near) <= tol, near, xq)

    def radius_at(self, x, derivative=0):
        """Radius r(x) (or its x-derivative) at global stations; 0 outside the body."""
        xq = self._local(x)
        val = self._interp(xq, derivative)[..., 0]
        inside = self._on_body(xq)
        return np.where(inside, np.maximum(val, 0.0) if derivative == 0 else val, 0.0)

    def center_at(self, x, derivative=0):
        """(..., 2): y and z of the section centre (or their x-derivatives) at global x."""
        xq = self._local(x)
        zc = self._interp(xq, derivative)[..., 1] + (self.origin[2] if derivative == 0 else 0.0)
        yc = np.full_like(zc, self.origin[1] if derivative == 0 else 0.0)
        return np.stack([yc, zc], axis=-1)

    def section_at(self, x):
        """(centre (..., 2), radius (...)) at global x in one interpolation pass.

        The same values as :meth:`center_at` and :meth:`radius_at` (radius 0 outside the body).
        """
        xq = self._local(x)
        rc = self._interp(xq)
        inside = self._on_body(xq)
        r = np.where(inside, np.maximum(rc[..., 0], 0.0), 0.0)
        zc = rc[..., 1] + self.origin[2]
        return np.stack([np.full_like(zc, self.origin[1]), zc], axis=-1), r

    def area_at(self, x):
        """Cross-sectional area pi r(x)^2 at global x [deck length^2]."""
        return np.pi * self.radius_at(x) ** 2

    def point(self, x, theta):
        """Surface point at global station x and angle theta (TM-4406 eqs 1-3), vectorised.

        theta [rad] = 0 on the horizontal to +y, +pi/2 at the top; x and theta broadcast.
        Returns (..., 3). At the top and the bottom (theta within a few ulps of pi/2 + k pi,
        as an angle interpolated up to pi/2 comes out) the point is exactly on the body's
        centre plane (cos taken as 0, not 6.1e-17 or 4e-16), so a network and its mirror
        image share their lines on the plane of symmetry bit for bit.
        """
        x, theta = np.broadcast_arrays(np.asarray(x, float), np.asarray(theta, float))
        c, r = self.section_at(x)
        cos = np.cos(theta)
        cos = np.where(np.abs(cos) <= 8.0 * np.spacing(np.maximum(np.abs(theta), 4.0)), 0.0,
                       cos)
        return np.stack([x, c[..., 0] + r * cos, c[..., 1] + r * np.sin(theta)], -1)

    def _slope_table(self):
        """(global bound, range-max table) of |r'| + |c'| per piece, built on first use."""
        if self._lipschitz is None:
            interp, x = self._interp, self.x
            # |grad e| <= 1 + |r'| + |c'| for e = |p_yz - c(x)| - r(x). On each cubic piece
            # the slope is a quadratic in the local variable: its largest magnitude is at an
            # end or at the vertex, so the per-piece maximum is exact (no sampling margin).
            # A straight bridge across a gap between segments is a piece like the others.
            c3, c2, c1 = interp.coefs[0], interp.coefs[1], interp.coefs[2]  # (n_pc, cols)
            h = np.append(np.diff(interp.breaks), x[-1] - interp.breaks[-1])[:, None]
            with np.errstate(divide="ignore", invalid="ignore"):
                tv = np.where(c3 != 0, -c2 / (3 * c3), 0.0)
            tv = np.clip(np.nan_to_num(tv), 0.0, h)
            slope = [np.abs(3 * c3 * t * t + 2 * c2 * t + c1) for t in (0.0, h, tv)]
            piece = np.max(slope, axis=0).sum(axis=-1) * (1.0 + 1e-9)  # (n_pieces,)
            object.__setattr__(self, "_lipschitz", (float(1.0 + piece.max()),
                                                    range_max_table(piece)))
        return self._lipschitz

    @property
    def error_lipschitz(self):
        """A bound on |d radial_error / d length| along any straight line [-]."""
        return self._slope_table()[0]

    def error_lipschitz_between(self, pa, pb):
        """Local bound on |d radial_error / d length| on the segments pa -> pb, vectorised.

        Uses the largest |r'| + |c'| over the body pieces the segment's x range spans
        (1 + that slope), so a segment along the cylindrical mid-body is not penalised by
        the steep nose.
        """
        xa = np.asarray(pa, float)[..., 0] - self.origin[0]
        xb = np.asarray(pb, float)[..., 0] - self.origin[0]
        brk = self._interp.breaks
        ia = np.clip(np.searchsorted(brk, np.minimum(xa, xb), side="right") - 1, 0,
                     brk.size - 1)
        ib = np.clip(np.searchsorted(brk, np.maximum(xa, xb), side="right") - 1, 0,
                     brk.size - 1)
        return 1.0 + range_max(self._slope_table()[1], ia, ib)

    def radial_error(self, points):
        """TM-4406 eq 6: distance from the local section centre minus r(x), vectorised.

        points (..., 3) -> (...): negative inside, positive outside, zero on the surface.
        Outside the body's x range the radius is 0, so the error is the distance to the axis.
        """
        p = np.asarray(points, float)
        xq = p[..., 0] - self.origin[0]
        rc = self._interp(xq)
        inside = self._on_body(xq)
        r = np.where(inside, np.maximum(rc[..., 0], 0.0), 0.0)
        d = np.hypot(p[..., 1] - self.origin[1], p[..., 2] - (rc[..., 1] + self.origin[2]))
        return d - r

    def radial_error_and_gradient(self, points):
        """:meth:`radial_error` and its gradient with respect to the point, vectorised.

        Returns (e (...), grad (..., 3)): de/dy, de/dz are the unit radial direction in the
        section, de/dx = -(unit z) c'(x) - r'(x).
        """
        p = np.asarray(points, float)
        xq = p[..., 0] - self.origin[0]
        rc, drc = self._interp.value_and_slope(xq)
        inside = self._on_body(xq)
        r = np.where(inside, np.maximum(rc[..., 0], 0.0), 0.0)
        dr = np.where(inside, drc[..., 0], 0.0)
        dy = p[..., 1] - self.origin[1]
        dz = p[..., 2] - (rc[..., 1] + self.origin[2])
        d = np.hypot(dy, dz)
        safe = np.where(d > 0, d, 1.0)
        ny, nz = np.where(d > 0, dy / safe, 0.0), np.where(d > 0, dz / safe, 0.0)
        grad = np.stack([-nz * drc[..., 1] - dr, ny, nz], axis=-1)
        return d - r, grad

    def signed_distance(self, points, samples=2001):
        """Signed distance from points (..., 3) to the surface, negative inside [deck length].

        Measured in the meridian half-plane through the point (exact for an uncambered body of
        revolution; for a cambered body the camber slope's effect is neglected, an error of
        second order in that slope). The meridian r(x) is sampled densely and at every
        station (where r' may jump: a joint, the ends of a straight bridge across a gap), and
        the distance is that to the polyline through the samples, then taken to the curve
        itself by Newton steps on the foot point from the nearest sample piece (a point on
        the surface is 0 to rounding, where the polyline's chords alone would put it up to
        their sag inside or out).
        """
        p = np.asarray(points, float)
        shape = p.shape[:-1]
        p = p.reshape(-1, 3)
        c = self.center_at(p[:, 0])
        rho = np.hypot(p[:, 1] - c[:, 0], p[:, 2] - c[:, 1])
        x0, x1 = self.x_global[0], self.x_global[-1]
        xs = np.union1d(np.linspace(x0, x1, samples), self.x_global)
        rs = self.radius_at(xs)
        # Closed meridian outline: axis at the nose, the radius curve, axis at the base.
        mx = np.concatenate([[x0], xs, [x1]])
        mr = np.concatenate([[0.0], rs, [0.0]])
        ax, ar = mx[:-1], mr[:-1]
        dx, dr = np.diff(mx), np.diff(mr)
        len2 = np.maximum(dx * dx + dr * dr, 1e-300)
        best = np.full(p.shape[0], np.inf)
        piece, foot = np.zeros(p.shape[0], int), np.zeros(p.shape[0])
        for lo in range(0, p.shape[0], 2048):  # chunks bound memory, not a per-point loop
            px, pr = p[lo:lo + 2048, 0, None], rho[lo:lo + 2048, None]
            t = np.clip(((px - ax) * dx + (pr - ar) * dr) / len2, 0.0, 1.0)
            d2 = (px - ax - t * dx) ** 2 + (pr - ar - t * dr) ** 2
            k = d2.argmin(axis=1)
            rows = np.arange(k.size)
            best[lo:lo + 2048] = np.sqrt(d2[rows, k])
            piece[lo:lo + 2048], foot[lo:lo + 2048] = k, ax[k] + t[rows, k] * dx[k]
        on_curve = (piece > 0) & (piece < ax.size - 1)  # not the closures to the axis
        if on_curve.any():
            best[on_curve] = self._foot_distance(p[on_curve, 0], rho[on_curve],
                                                 foot[on_curve], best[on_curve])
        inside = (p[:, 0] > x0) & (p[:, 0] < x1) & (rho < self.radius_at(p[:, 0]))
        return np.where(inside, -best, best).reshape(shape)

    def _foot_distance(self, px, pr, xf, fallback, steps=6):
        """Distance from meridian points (px, pr) to the curve r(x), by Newton steps on the
        foot xf (minimising (x - px)^2 + (r(x) - pr)^2); ``fallback`` where they do not
        settle (a kink of r at a joint station)."""
        x0, x1 = self.x_global[0], self.x_global[-1]
        for _ in range(steps):
            r, r1, r2 = (self.radius_at(xf, k) for k in (0, 1, 2))
            g = (xf - px) + (r - pr) * r1
            gp = 1.0 + r1 * r1 + (r - pr) * r2
            xf = np.clip(xf - g / np.where(gp > 0.0, gp, 1.0), x0, x1)
        r, r1 = self.radius_at(xf), self.radius_at(xf, 1)
        size = max(self.length, 1.0)
        found = np.hypot(px - xf, pr - r)
        # settled, and near the polyline's foot (not another local minimum far off)
        good = (np.abs((xf - px) + (r - pr) * r1) <= 1e-9 * size) & (
            found <= fallback + 1e-6 * size)
        return np.where(good, found, fallback)

    def cross_sections(self, n_points=None, theta=None, stations=None):
        """Body n-lines: (n_stations, n_points, 3) points at the input stations (or at
        ``stations``, global).

        Points run from theta = -pi/2 (bottom) to +pi/2 (top) on the y >= 0 side, which with
        the stations in increasing x gives outward normals. A pod (``mirrored`` or off the centre
        line) is closed all round: theta from -pi/2 to 3 pi/2.
        """
        if theta is None:
            n = 19 if n_points is None else int(n_points)
            full = self.origin[1] != 0.0 or self.mirrored
            theta = np.linspace(-np.pi / 2, 3 * np.pi / 2 if full else np.pi / 2,
                                2 * n - 1 if full else n)
        xg = self.x_global if stations is None else np.asarray(stations, float)
        return self.point(xg[:, None], np.asarray(theta, float)[None, :])

    def networks(self, n_points=None, stations=None):
        """Cross-section networks: ``{"<name>": ...}``, or ``"<name> segment k"`` per segment.

        Each segment uses ``n_points`` points per half-section if given, else its
        ``points_per_section`` entry, else 19; its rows are its own stations, or those of
        ``stations`` (sorted, global, holding the body's own) from its first to its last.
        """
        counts = self.points_per_section or (None,) * len(self.segments)
        xg = self.x_global
        out, start = {}, 0
        for i, (s, m) in enumerate(zip(self.segments, counts), 1):
            n = n_points if n_points is not None else (m or 19)
            rows = xg[start:start + s]
            if stations is not None:
                st = np.asarray(stations, float)
                inner = st[(st > rows[0]) & (st < rows[-1])]
                rows = np.sort(np.concatenate([rows, inner[~np.isin(inner, rows)]]))
            secs = self.cross_sections(n, stations=rows)
            out[self.name if len(self.segments) == 1 else f"{self.name} segment {i}"] = secs
            start += s
        return out


#: A half-section's vertex turning by more than this [deg] is a corner
#: (:meth:`ArbitraryBody.corners`).
CORNER = 1.0


@dataclass(frozen=True, slots=True, eq=False)
class ArbitraryBody:
    """A fuselage with arbitrary (y, z) half-sections, as the deck's J2 = +1 option.

    Anatomy. At each station the half-section is the polyline through the deck's (y, z)
    points, ordered from the bottom to the top on the y >= 0 side: the Harris program joins
    the given points by straight lines, and so does juncture; nothing is resampled. The whole
    section is the half-section and its mirror image at -y, joined across y = 0 at the top and
    at the bottom (a half-section that ends on y = 0, as decks do, needs no join).

    Between two consecutive stations (within a segment, or across a gap between segments)
    the two polylines are matched by normalised arc length, TM-4607's parameter for
    non-circular sections: the point at fraction s of one section is joined by a straight
    line to the point at fraction s of the next. The section at x is therefore the linear
    blend of both, a polyline through the union of their vertex fractions, evaluated exactly
    (``tests/deckgen/references.py``, ``ArbitraryBodyRef``, builds the same surface
    independently). Along x the blend is linear, not PCHIP: straight lines between given
    points, as on every other joint. At a repeated joint station whose two sections differ the
    surface steps; at x = x_joint the later segment's section holds (see the module
    docstring).

    The surface parameter ``s`` (:meth:`point`, :meth:`parameter_of`) is the matched
    fraction: at a station it is the normalised arc length of the deck's polyline, 0 at the
    bottom, 1 at the top; between stations it is the blend of both sections' arc length (the
    blended polyline's own arc length fraction differs from it slightly).

    Parameters
    ----------
    name : str
    x : (n,) float
        Stations [deck length]; segments may repeat their joint station or leave a gap.
    sections : sequence of (m_k, 2) float
        Half-section at each station: (y, z) points ordered from bottom to top on the
        y >= 0 side [deck length]. Counts may differ between stations.
    segments : tuple of int, optional
        Number of stations per segment.
    resample : int
        Deprecated, and no part of the surface: the number of equally spaced s values at
        which a caller that samples the sections uniformly (the mass properties) still does;
        every method here evaluates the given polylines exactly.
    mirrored : bool
        As for :class:`CircularBody`.
    params : sequence of (m_k,) float, optional
        The surface parameter of each section's points, increasing from 0 to 1 (default:
        normalised arc length, the deck's convention). Sections are matched between stations
        by these values. A body that inserts stations into another one (the fuselage
        re-designed at fixed area) gives its new sections the parameters of the surface they
        were cut from, so that it is that surface exactly where nothing changes.

    Examples
    --------
    A square half-section of side 2 (corners at arc length fractions 0.25 and 0.75), kept
    from x = 0 to 10: its whole-section area is 2 x 2 and the point at s = 0.5 is the middle
    of the outer side.

    >>> sq = [[0.0, -1.0], [1.0, -1.0], [1.0, 1.0], [0.0, 1.0]]
    >>> b = ArbitraryBody("box", [0.0, 10.0], [sq, sq])
    >>> float(b.area_at(5.0))
    4.0
    >>> b.point(5.0, 0.5).tolist()
    [5.0, 1.0, 0.0]
    """

    name: str
    x: np.ndarray
    sections: tuple
    segments: tuple = None
    resample: int = 201
    mirrored: bool = False
    params: tuple = None
    _u: np.ndarray = None
    _a: np.ndarray = None
    _b: np.ndarray = None
    _count: np.ndarray = None
    _grid: np.ndarray = None
    _lipschitz: tuple = None

    def __post_init__(self):
        name = self.name
        x = frozen(self.x, (None,), name, "x")
        if len(self.sections) != x.size:
            raise GeometryError(f"{x.size} stations but {len(self.sections)} sections", name)
        secs = []
        for k, s in enumerate(self.sections):
            a = frozen(s, (None, 2), name, f"section {k + 1} (m, 2) y, z points")
            check_finite(a, name, f"section {k + 1}")
            if a.shape[0] < 2:
                raise GeometryError("a half-section needs at least 2 points", name, k + 1)
            if (a[:, 0] < 0).any():
                raise GeometryError("half-section has y < 0 (describe the y >= 0 side)",
                                    name, k + 1)
            secs.append(a)
        seg, _ = _segment_layout(x, self.segments, name)
        params = None
        if self.params is not None:
            params = []
            if len(self.params) != len(secs):
                raise GeometryError(f"{len(secs)} sections but {len(self.params)} params", name)
            for k, (pk, sec) in enumerate(zip(self.params, secs)):
                pk = frozen(pk, (len(sec),), name, f"params of section {k + 1}")
                if pk[0] != 0.0 or pk[-1] != 1.0 or np.any(np.diff(pk) < 0):
                    raise GeometryError("params must increase from 0 to 1", name, k + 1)
                params.append(pk)
            params = tuple(params)
        u, a, b, count = matched_pairs(secs, params)
        # Speed of the matched points along x per station pair: the section moves by at most
        # this much per unit x (0 across a repeated joint station, where it steps instead).
        h = np.diff(x)
        speed = np.where(h > 0, np.linalg.norm(b - a, axis=-1).max(axis=-1)
                         / np.where(h > 0, h, 1.0), 0.0) * (1.0 + 1e-9)
        grid = np.concatenate([a, b])  # every vertex of every section (bounding boxes)
        for arr in (u, a, b, count, grid):
            arr.flags.writeable = False
        for field, value in (("x", x), ("sections", tuple(secs)), ("segments", seg),
                             ("mirrored", bool(self.mirrored)), ("params", params),
                             ("_u", u), ("_a", a), ("_b", b), ("_count", count),
                             ("_grid", grid),
                             ("_lipschitz", (float(1.0 + speed.max()),
                                             range_max_table(speed)))):
            object.__setattr__(self, field, value)

    @property
    def x_global(self):
        """(n,) stations [deck length]."""
        return self.x

    @property
    def length(self):
        """Body length [deck length]."""
        return float(self.x[-1] - self.x[0])

    def _pair(self, xq):
        """Station pair k (sections k, k + 1) and blend fraction w in [0, 1] at stations xq.

        At a repeated joint station the later segment's pair (searchsorted side="right");
        beyond the ends the end section (w clipped).
        """
        xq = np.asarray(xq, float)
        x = self.x
        k = np.minimum(np.maximum(np.searchsorted(x, xq, side="right") - 1, 0), x.size - 2)
        h = x[k + 1] - x[k]  # > 0: side="right" never lands on a repeated joint's pair
        # np.minimum/maximum: np.clip's overhead shows in the root finders' inner loops.
        w = np.minimum(np.maximum((xq - x[k]) / np.where(h > 0, h, 1.0), 0.0), 1.0)
        return k, w

    def _sections_at(self, xq):
        """(..., M, 2): the half-section polylines at stations xq, exact (padded to M points
        by repeating the top one: zero-length pieces that change no distance or area)."""
        k, w = self._pair(xq)
        return self._blend(k, w[..., None, None])

    def _blend(self, k, w, j=slice(None)):
        """Matched points ``j`` of station pair ``k`` at blend fraction ``w`` (broadcast):
        (1 - w) a + w b, which is each end section exactly at w = 0 and 1 (a + w (b - a) is
        not: a pointed tail given as one point repeated came out an ulp apart)."""
        return (1.0 - w) * self._a[k, j] + w * self._b[k, j]

    def point(self, x, s):
        """Surface point at station x and surface parameter s (0 bottom, 1 top). (..., 3).

        ``s`` is the matched arc length fraction (see the class docstring); outside [0, 1]
        the first / last piece of the section extends straight.
        """
        x, s = np.broadcast_arrays(np.asarray(x, float), np.asarray(s, float))
        k, w = self._pair(x)
        u = self._u[k]  # (..., M)
        j = np.minimum(np.maximum((u <= s[..., None]).sum(-1) - 1, 0), self._count[k] - 2)
        u0 = np.take_along_axis(u, j[..., None], -1)[..., 0]
        u1 = np.take_along_axis(u, (j + 1)[..., None], -1)[..., 0]
        t = ((s - u0) / (u1 - u0))[..., None]
        w = w[..., None]
        p0 = self._blend(k, w, j)
        p1 = self._blend(k, w, j + 1)
        return np.concatenate([x[..., None], p0 + t * (p1 - p0)], axis=-1)

    def corners(self, x, turn=CORNER):
        """(k,) the surface parameters of the corners of the half-section at the station x
        (a float): its vertices where the polyline turns by more than ``turn`` degrees, ends
        excluded. Network rows through them keep the section's corners (rows sampled at
        equal steps of ``s`` cut them: 0.7 % of an octagon-like section)."""
        k, w = self._pair(float(x))
        n = int(self._count[k])
        u = self._u[k][:n]
        p = self._blend(k, w, slice(0, n))
        d = np.diff(p, axis=0)
        length = np.linalg.norm(d, axis=1)
        a, b = d[:-1], d[1:]
        ok = (length[:-1] > 0.0) & (length[1:] > 0.0)
        cos = np.einsum("ij,ij->i", a, b) / np.maximum(length[:-1] * length[1:], 1e-300)
        return u[1:-1][ok & (cos < np.cos(np.radians(turn)))]

    def center_at(self, x):
        """(..., 2): y = 0 and the mean height of the section over its surface parameter,
        the integral of z(s) ds from 0 to 1 (a reference centre for orientation; not a
        geometric centroid)."""
        k, w = self._pair(x)
        z = self._blend(k, w[..., None, None])[..., 1]
        zc = 0.5 * (np.diff(self._u[k], axis=-1) * (z[..., 1:] + z[..., :-1])).sum(-1)
        return np.stack([np.zeros_like(zc), zc], axis=-1)

    def _project(self, p):
        """Points (q, 3) onto the segments of their half-sections.

        Returns the pair ``k`` (q,), segment starts ``a`` and steps ``d`` (y and z parts,
        each (q, M-1)), the points in the section plane ``q`` (y, z: each (q, 1)) with |y|
        (the section is symmetric), the clamped segment parameters ``t`` and squared
        distances ``dist2`` (q, M-1). Kept apart by coordinate: the same numbers as the
        (..., 2) arrays summed over their last axis, without those two-term reductions.
        """
        k, w = self._pair(p[:, 0])
        w = w[:, None]
        a, b = np.take(self._a, k, axis=0), np.take(self._b, k, axis=0)   # (q, M, 2)
        ay, az = ((1.0 - w) * a[..., i] + w * b[..., i] for i in (0, 1))
        dy, dz = ay[:, 1:] - ay[:, :-1], az[:, 1:] - az[:, :-1]
        ay, az = ay[:, :-1], az[:, :-1]
        qy, qz = np.abs(p[:, 1])[:, None], p[:, 2][:, None]
        ey, ez = qy - ay, qz - az
        len2 = np.maximum(dy * dy + dz * dz, 1e-300)
        t = np.minimum(np.maximum((ey * dy + ez * dz) / len2, 0.0), 1.0)
        ry, rz = ey - t * dy, ez - t * dz
        return k, (ay, az), (dy, dz), (qy, qz), t, ry * ry + rz * rz

    def parameter_of(self, points):
        """Surface parameter s (0 bottom, 1 top) of points on the surface: the inverse of
        :meth:`point` (the nearest point of the section, projected).

        points (..., 3) -> (...). Points off the surface get the s of their nearest point.
        """
        p = np.asarray(points, float)
        shape = p.shape[:-1]
        k, _, _, _, t, dist2 = self._project(p.reshape(-1, 3))
        j = np.argmin(dist2, axis=1)
        rows = np.arange(len(j))
        tj = t[rows, j]
        u = self._u[k]
        return (u[rows, j] + tj * (u[rows, j + 1] - u[rows, j])).reshape(shape)

    def area_at(self, x):
        """Cross-sectional area of the whole (both halves) section at x [deck length^2].

        The half polygon is closed across the symmetry plane (top point to (0, z_top), down
        y = 0 to (0, z_bottom), back to the bottom point), as the mirror image closes it;
        0 outside the stations.
        """
        sec = self._sections_at(x)
        y, z = sec[..., 0], sec[..., 1]
        # Shoelace; the two closing pieces through y = 0 contribute y_top z_top - y_bot z_bot.
        half = 0.5 * np.abs(np.sum(y[..., :-1] * z[..., 1:] - y[..., 1:] * z[..., :-1], -1)
                            + y[..., -1] * z[..., -1] - y[..., 0] * z[..., 0])
        inside = (np.asarray(x) >= self.x[0]) & (np.asarray(x) <= self.x[-1])
        return np.where(inside, 2.0 * half, 0.0)

    def centroid_at(self, x):
        """(..., 2): the area centroid of the whole section at x (y = 0 by symmetry).

        The half polygon is closed along y = 0 as in :meth:`area_at`; a section of no area
        (a pointed nose) gives its mean point height.
        """
        _, zc = area_and_centroid(self._sections_at(x))
        return np.stack([np.zeros_like(zc), zc], axis=-1)

    @property
    def error_lipschitz(self):
        """A bound on |d signed_distance / d length| along any straight line [-].

        The in-plane distance changes at most 1 per unit in y, z and at most the largest
        speed v of the matched section points per unit x, so 1 + v bounds
        sqrt(1 + v^2). It holds between the end stations and away from repeated joint
        stations, where the distance jumps by up to the step between the two sections.
        """
        return self._lipschitz[0]

    def error_lipschitz_between(self, pa, pb):
        """Local bound of :attr:`error_lipschitz` on the segments pa -> pb, vectorised:
        1 + the largest section speed over the station pairs the segment's x range spans."""
        xa = np.asarray(pa, float)[..., 0]
        xb = np.asarray(pb, float)[..., 0]
        ka, _ = self._pair(np.minimum(xa, xb))
        kb, _ = self._pair(np.maximum(xa, xb))
        return 1.0 + range_max(self._lipschitz[1], ka, kb)

    def signed_distance(self, points):
        """Distance in the plane x = const to the section, negative inside [deck length].

        points (..., 3) -> (...); the section is closed by its mirror image. The distance
        is to the polylines the deck gives (blended between stations), exact to rounding.
        """
        p = np.asarray(points, float)
        shape = p.shape[:-1]
        p = p.reshape(-1, 3)
        _, (ya, za), (dy, dz), (qy, qz), _, dist2 = self._project(p)
        dist = np.sqrt(dist2.min(-1))
        # Inside test: crossing number against the half outline closed along y = 0.
        yb, zb = ya + dy, za + dz
        crosses = ((za > qz) != (zb > qz)) & (
            qy < ya + (qz - za) * (yb - ya) / np.where(zb != za, zb - za, 1.0))
        inside = (crosses.sum(-1) % 2 == 1) & (p[:, 0] > self.x[0]) & (p[:, 0] < self.x[-1])
        return np.where(inside, -dist, dist).reshape(shape)

    def cross_sections(self, n_points=None):
        """(n_stations, n_points, 3): the input stations at equally spaced s (0 to 1)."""
        n = 19 if n_points is None else int(n_points)
        s = np.linspace(0.0, 1.0, n)
        return self.point(self.x[:, None], s[None, :])

    def networks(self, n_points=None):
        """Body networks as for :meth:`CircularBody.networks` (points bottom to top).

        With ``n_points=None`` a segment whose sections all have the same point count is
        written with its input points; otherwise sections are sampled at equal s.
        """
        out, start = {}, 0
        for i, s in enumerate(self.segments, 1):
            raw = self.sections[start:start + s]
            if n_points is None and len({len(a) for a in raw}) == 1:
                yz = np.stack(raw)
                secs = np.concatenate([np.broadcast_to(self.x[start:start + s, None, None],
                                                       yz.shape[:2] + (1,)), yz], axis=-1)
            else:
                secs = self.cross_sections(n_points or max(len(a) for a in raw))[start:start + s]
            out[self.name if len(self.segments) == 1 else f"{self.name} segment {i}"] = secs
            start += s
        return out
