"""Bodies: circular fuselages and pods (TM-4406 eqs 1-3) and arbitrary-section fuselages.

A body is a sequence of cross-sections at increasing x, grouped in *segments* (the deck's
fuselage segments; adjacent segments may repeat their joint station). Along x, radius and
camber are interpolated segment by segment (PCHIP by default, linear on request), so a
discontinuity at a joint is kept rather than smoothed.

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

    Each segment gets its own PCHIP (or linear) interpolant; their polynomial pieces are
    merged into a single table of breakpoints and cubic coefficients so that evaluation is one
    binary search and one Horner pass for all columns at once (the root finders call this in
    their inner loop). Zero-length intervals at repeated joint stations are dropped; beyond
    the ends the first / last cubic extrapolates.
    """

    def __init__(self, x, columns, bounds, method, slopes=None):
        breaks, coefs = [], []
        for a, b in bounds:
            xs, ys = x[a:b], columns[a:b]
            if slopes is not None:
                c = hermite_coefficients(xs, ys, slopes[a:b])
            elif method == "pchip":
                c = pchip_coefficients(xs, ys)  # (4, n-1, cols), local coordinate x - x_k
            else:
                slope = np.diff(ys, axis=0) / np.diff(xs)[:, None]
                c = np.stack([np.zeros_like(slope), np.zeros_like(slope), slope, ys[:-1]])
            breaks.append(xs[:-1])
            coefs.append(c)
        self.breaks = np.concatenate(breaks)
        self.coefs = np.concatenate(coefs, axis=1)  # (4, n_pieces, cols)
        self.ncols = columns.shape[1]

    def value_and_slope(self, xq, pieces=None):
        """Values and x-derivatives at xq in one pass (shared coefficient gather).

        ``pieces = (first, last)`` restricts the evaluation to those pieces (one segment's:
        its end station then takes that segment's one-sided slope).
        """
        xq = np.asarray(xq, dtype=float)
        lo, hi = (0, self.breaks.size - 1) if pieces is None else pieces
        k = np.minimum(np.maximum(np.searchsorted(self.breaks, xq, side="right") - 1, lo), hi)
        t = (xq - self.breaks[k])[..., None]
        c3, c2, c1, c0 = self.coefs[:, k]
        return ((c3 * t + c2) * t + c1) * t + c0, (3 * c3 * t + 2 * c2) * t + c1

    def __call__(self, xq, nu=0):
        xq = np.asarray(xq, dtype=float)
        # np.minimum/maximum: np.clip's overhead shows in the root finders' inner loops.
        k = np.minimum(np.maximum(np.searchsorted(self.breaks, xq, side="right") - 1, 0),
                       self.breaks.size - 1)
        t = (xq - self.breaks[k])[..., None]
        c3, c2, c1, c0 = self.coefs[:, k]
        if nu == 0:
            return ((c3 * t + c2) * t + c1) * t + c0
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
        Number of stations in each segment (default: one segment).
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
        its original's shape between stations this way, and depends smoothly on its radii).
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

    def radius_at(self, x, derivative=0):
        """Radius r(x) (or its x-derivative) at global stations; 0 outside the body."""
        xq = np.asarray(x, float) - self.origin[0]
        val = self._interp(xq, derivative)[..., 0]
        inside = (xq >= self.x[0]) & (xq <= self.x[-1])
        return np.where(inside, np.maximum(val, 0.0) if derivative == 0 else val, 0.0)

    def center_at(self, x, derivative=0):
        """(..., 2): y and z of the section centre (or their x-derivatives) at global x."""
        xq = np.asarray(x, float) - self.origin[0]
        zc = self._interp(xq, derivative)[..., 1] + (self.origin[2] if derivative == 0 else 0.0)
        yc = np.full_like(zc, self.origin[1] if derivative == 0 else 0.0)
        return np.stack([yc, zc], axis=-1)

    def section_at(self, x):
        """(centre (..., 2), radius (...)) at global x in one interpolation pass.

        The same values as :meth:`center_at` and :meth:`radius_at` (radius 0 outside the body).
        """
        xq = np.asarray(x, float) - self.origin[0]
        rc = self._interp(xq)
        inside = (xq >= self.x[0]) & (xq <= self.x[-1])
        r = np.where(inside, np.maximum(rc[..., 0], 0.0), 0.0)
        zc = rc[..., 1] + self.origin[2]
        return np.stack([np.full_like(zc, self.origin[1]), zc], axis=-1), r

    def area_at(self, x):
        """Cross-sectional area pi r(x)^2 at global x [deck length^2]."""
        return np.pi * self.radius_at(x) ** 2

    def point(self, x, theta):
        """Surface point at global station x and angle theta (TM-4406 eqs 1-3), vectorised.

        theta [rad] = 0 on the horizontal to +y, +pi/2 at the top; x and theta broadcast.
        Returns (..., 3).
        """
        x, theta = np.broadcast_arrays(np.asarray(x, float), np.asarray(theta, float))
        c, r = self.section_at(x)
        return np.stack([x, c[..., 0] + r * np.cos(theta), c[..., 1] + r * np.sin(theta)], -1)

    def _slope_table(self):
        """(global bound, sparse range-max levels) of |r'| + |c'|, built on first use."""
        if self._lipschitz is None:
            interp, x = self._interp, self.x
            # |grad e| <= 1 + |r'| + |c'| for e = |p_yz - c(x)| - r(x). On each cubic piece
            # the slope is a quadratic in the local variable: its largest magnitude is at an
            # end or at the vertex, so the per-piece maximum is exact (no sampling margin).
            c3, c2, c1 = interp.coefs[0], interp.coefs[1], interp.coefs[2]  # (n_pc, cols)
            h = np.append(np.diff(interp.breaks), x[-1] - interp.breaks[-1])[:, None]
            with np.errstate(divide="ignore", invalid="ignore"):
                tv = np.where(c3 != 0, -c2 / (3 * c3), 0.0)
            tv = np.clip(np.nan_to_num(tv), 0.0, h)
            slope = [np.abs(3 * c3 * t * t + 2 * c2 * t + c1) for t in (0.0, h, tv)]
            piece = np.max(slope, axis=0).sum(axis=-1) * (1.0 + 1e-9)  # (n_pieces,)
            # Sparse table for range maxima: level k holds max(piece[i : i + 2^k]).
            levels = [piece]
            while (1 << len(levels)) <= piece.size:
                prev, w = levels[-1], 1 << (len(levels) - 1)
                levels.append(np.maximum(prev[:-w], prev[w:]))
            table = np.zeros((len(levels), piece.size))  # padded: one fancy index per query
            for lev, row in enumerate(levels):
                table[lev, :row.size] = row
            object.__setattr__(self, "_lipschitz", (float(1.0 + piece.max()), table))
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
        table = self._slope_table()[1]
        k = np.minimum(np.floor(np.log2(ib - ia + 1)).astype(int), table.shape[0] - 1)
        best = np.maximum(table[k, ia], table[k, ib - (1 << k) + 1])
        return 1.0 + best

    def radial_error(self, points):
        """TM-4406 eq 6: distance from the local section centre minus r(x), vectorised.

        points (..., 3) -> (...): negative inside, positive outside, zero on the surface.
        Outside the body's x range the radius is 0, so the error is the distance to the axis.
        """
        p = np.asarray(points, float)
        xq = p[..., 0] - self.origin[0]
        rc = self._interp(xq)
        inside = (xq >= self.x[0]) & (xq <= self.x[-1])
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
        inside = (xq >= self.x[0]) & (xq <= self.x[-1])
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
        second order in that slope). The meridian r(x) is sampled densely, then the nearest
        sample is polished by Newton steps on (x - px) + (r(x) - rho) r'(x) = 0.
        """
        p = np.asarray(points, float)
        shape = p.shape[:-1]
        p = p.reshape(-1, 3)
        c = self.center_at(p[:, 0])
        rho = np.hypot(p[:, 1] - c[:, 0], p[:, 2] - c[:, 1])
        x0, x1 = self.x_global[0], self.x_global[-1]
        xs = np.linspace(x0, x1, samples)
        rs = self.radius_at(xs)
        # Closed meridian outline: axis at the nose, the radius curve, axis at the base.
        mx = np.concatenate([[x0], xs, [x1]])
        mr = np.concatenate([[0.0], rs, [0.0]])
        ax, ar = mx[:-1], mr[:-1]
        dx, dr = np.diff(mx), np.diff(mr)
        len2 = np.maximum(dx * dx + dr * dr, 1e-300)
        best = np.full(p.shape[0], np.inf)
        for lo in range(0, p.shape[0], 2048):  # chunks bound memory, not a per-point loop
            px, pr = p[lo:lo + 2048, 0, None], rho[lo:lo + 2048, None]
            t = np.clip(((px - ax) * dx + (pr - ar) * dr) / len2, 0.0, 1.0)
            d2 = (px - ax - t * dx) ** 2 + (pr - ar - t * dr) ** 2
            best[lo:lo + 2048] = np.sqrt(d2.min(axis=1))
        inside = (p[:, 0] > x0) & (p[:, 0] < x1) & (rho < self.radius_at(p[:, 0]))
        return np.where(inside, -best, best).reshape(shape)

    def cross_sections(self, n_points=None, theta=None):
        """Body n-lines: (n_stations, n_points, 3) points at the input stations.

        Points run from theta = -pi/2 (bottom) to +pi/2 (top) on the y >= 0 side, which with
        the stations in increasing x gives outward normals. A pod (``mirrored`` or off the centre
        line) is closed all round: theta from -pi/2 to 3 pi/2.
        """
        if theta is None:
            n = 19 if n_points is None else int(n_points)
            full = self.origin[1] != 0.0 or self.mirrored
            theta = np.linspace(-np.pi / 2, 3 * np.pi / 2 if full else np.pi / 2,
                                2 * n - 1 if full else n)
        xg = self.x_global
        return self.point(xg[:, None], np.asarray(theta, float)[None, :])

    def networks(self, n_points=None):
        """Cross-section networks: ``{"<name>": ...}``, or ``"<name> segment k"`` per segment.

        Each segment uses ``n_points`` points per half-section if given, else its
        ``points_per_section`` entry, else 19.
        """
        counts = self.points_per_section or (None,) * len(self.segments)
        out, start = {}, 0
        for i, (s, m) in enumerate(zip(self.segments, counts), 1):
            n = n_points if n_points is not None else (m or 19)
            secs = self.cross_sections(n)[start:start + s]
            out[self.name if len(self.segments) == 1 else f"{self.name} segment {i}"] = secs
            start += s
        return out


def _arc_fractions(sec):
    """Normalised arc length (0 at the first point, 1 at the last) along a polyline (m, 2)."""
    seg = np.hypot(*np.diff(sec, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    return s / s[-1] if s[-1] > 0 else np.linspace(0.0, 1.0, len(sec))


@dataclass(frozen=True, slots=True, eq=False)
class ArbitraryBody:
    """A fuselage with arbitrary (y, z) half-sections, as the deck's J2 = +1 option.

    Parameters
    ----------
    name : str
    x : (n,) float
        Stations [deck length]; segments may repeat their joint station.
    sections : sequence of (m_k, 2) float
        Half-section at each station: (y, z) points ordered from bottom to top on the
        y >= 0 side [deck length]. Counts may differ between segments.
    segments : tuple of int, optional
        Number of stations per segment.
    resample : int
        Points per section used for evaluation (equal normalised arc length).

    Notes
    -----
    Between stations, sections are matched by normalised arc length and blended linearly in x
    (TM-4607 eq 8 interpolates sections by arc length). ``point(x, s)`` takes s in [0, 1],
    0 at the bottom, 1 at the top.
    """

    name: str
    x: np.ndarray
    sections: tuple
    segments: tuple = None
    resample: int = 201
    mirrored: bool = False
    _grid: np.ndarray = None
    _lipschitz: float = None

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
        u = np.linspace(0.0, 1.0, self.resample)
        grid = np.stack([np.stack([np.interp(u, _arc_fractions(a), a[:, i]) for i in (0, 1)], -1)
                         for a in secs])
        grid.flags.writeable = False
        dx = np.diff(x)
        move = np.abs(np.diff(grid, axis=0)).max(axis=(1, 2))
        rate = np.max(np.where(dx > 0, move / np.where(dx > 0, dx, 1.0), 0.0), initial=0.0)
        for field, value in (("x", x), ("sections", tuple(secs)), ("segments", seg),
                             ("_grid", grid), ("mirrored", bool(self.mirrored)),
                             ("_lipschitz", float(1.25 * (1.0 + np.sqrt(2.0) * rate)))):
            object.__setattr__(self, field, value)

    @property
    def x_global(self):
        """(n,) stations [deck length]."""
        return self.x

    @property
    def length(self):
        """Body length [deck length]."""
        return float(self.x[-1] - self.x[0])

    def _sections_at(self, xq):
        """(..., resample, 2): resampled half-sections blended linearly at stations xq."""
        xq = np.asarray(xq, float)
        x = self.x
        # Within a repeated joint station take the later segment (searchsorted side="right").
        k = np.clip(np.searchsorted(x, xq, side="right") - 1, 0, x.size - 2)
        h = x[k + 1] - x[k]
        w = np.where(h > 0, (xq - x[k]) / np.where(h > 0, h, 1.0), 1.0)
        w = np.clip(w, 0.0, 1.0)[..., None, None]
        return self._grid[k] * (1 - w) + self._grid[k + 1] * w

    def point(self, x, s):
        """Surface point at station x and normalised arc length s (0 bottom, 1 top). (..., 3)."""
        x, s = np.broadcast_arrays(np.asarray(x, float), np.asarray(s, float))
        sec = self._sections_at(x)  # (..., m, 2)
        u = np.linspace(0.0, 1.0, self.resample)
        j = np.clip(np.searchsorted(u, s, side="right") - 1, 0, u.size - 2)
        t = ((s - u[j]) / (u[1] - u[0]))[..., None]
        yz = np.take_along_axis(sec, j[..., None, None], -2)[..., 0, :] * (1 - t) + \
            np.take_along_axis(sec, (j + 1)[..., None, None], -2)[..., 0, :] * t
        return np.concatenate([x[..., None], yz], axis=-1)

    def center_at(self, x):
        """(..., 2): y = 0 and the mean height of the interpolated section (a reference centre
        for orientation; not a geometric centroid)."""
        sec = self._sections_at(x)
        zc = sec[..., 1].mean(axis=-1)
        return np.stack([np.zeros_like(zc), zc], axis=-1)

    def _project(self, p):
        """Points (q, 3) onto the segments of their interpolated half-sections.

        Returns the segment starts ``a`` and steps ``d`` (q, m-1, 2), the points in the
        section plane ``q`` (q, 1, 2) with |y| (the section is symmetric), the clamped segment
        parameters ``t`` and squared distances ``dist2`` (q, m-1).
        """
        sec = self._sections_at(p[:, 0])  # (q, m, 2)
        a, d = sec[:, :-1], np.diff(sec, axis=1)
        q = np.stack([np.abs(p[:, 1]), p[:, 2]], -1)[:, None, :]
        len2 = np.maximum((d * d).sum(-1), 1e-300)
        t = np.clip(((q - a) * d).sum(-1) / len2, 0.0, 1.0)
        return a, d, q, t, ((q - a - t[..., None] * d) ** 2).sum(-1)

    def parameter_of(self, points):
        """Normalised arc length s (0 bottom, 1 top) of points on the surface: the inverse of
        :meth:`point` (the nearest point of the interpolated section, projected).

        points (..., 3) -> (...). Points off the surface get the s of their nearest point.
        """
        p = np.asarray(points, float)
        shape = p.shape[:-1]
        _, _, _, t, dist2 = self._project(p.reshape(-1, 3))
        j = np.argmin(dist2, axis=1)
        tj = t[np.arange(len(j)), j]
        return ((j + tj) / (self.resample - 1)).reshape(shape)

    def area_at(self, x):
        """Cross-sectional area of the whole (both halves) section at x [deck length^2]."""
        sec = self._sections_at(x)
        y, z = sec[..., 0], sec[..., 1]
        # Shoelace over the half polygon closed along the symmetry plane, doubled.
        half = 0.5 * np.abs(np.sum(y[..., :-1] * z[..., 1:] - y[..., 1:] * z[..., :-1], -1)
                            + y[..., -1] * z[..., 0] - y[..., 0] * z[..., -1])
        inside = (np.asarray(x) >= self.x[0]) & (np.asarray(x) <= self.x[-1])
        return np.where(inside, 2.0 * half, 0.0)

    @property
    def error_lipschitz(self):
        """A bound on |d signed_distance / d length| along any straight line [-]."""
        return self._lipschitz

    def signed_distance(self, points):
        """Distance in the plane x = const to the interpolated section, negative inside.

        points (..., 3) -> (...) [deck length]; the section is closed by its mirror image.
        """
        p = np.asarray(points, float)
        shape = p.shape[:-1]
        p = p.reshape(-1, 3)
        a, d, q, _, dist2 = self._project(p)
        dist = np.sqrt(dist2.min(-1))
        # Inside test: crossing number against the half outline closed along y = 0.
        ya, za = a[..., 0], a[..., 1]
        yb, zb = ya + d[..., 0], za + d[..., 1]
        qy, qz = q[..., 0], q[..., 1]
        crosses = ((za > qz) != (zb > qz)) & (
            qy < ya + (qz - za) * (yb - ya) / np.where(zb != za, zb - za, 1.0))
        inside = (crosses.sum(-1) % 2 == 1) & (p[:, 0] > self.x[0]) & (p[:, 0] < self.x[-1])
        return np.where(inside, -dist, dist).reshape(shape)

    def cross_sections(self, n_points=None):
        """(n_stations, n_points, 3): the input stations resampled to equal arc-length counts."""
        n = 19 if n_points is None else int(n_points)
        s = np.linspace(0.0, 1.0, n)
        return self.point(self.x[:, None], s[None, :])

    def networks(self, n_points=None):
        """Body networks as for :meth:`CircularBody.networks` (points bottom to top).

        With ``n_points=None`` a segment whose sections all have the same point count is
        written with its input points; otherwise sections are resampled by arc length.
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
