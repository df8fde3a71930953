"""Normal (x = const) cross-sectional area distributions, from the component model itself.

The area of the whole airplane (BOTH halves: the deck's REFA-based C_D uses the full airplane)
at a station x is the area of the union of its components cut by the plane x = const:

* a body (fuselage, pod) contributes its own section area: ``pi r(x)^2``
  (:meth:`CircularBody.area_at`) or the polygon area of an arbitrary section
  (:meth:`ArbitraryBody.area_at`); a body with an image at -y (a pod) counts twice;
* a wing-like component contributes the integral over its span ``s`` of its thickness along
  the thickness axis at that x (``z_upper - z_lower`` for a wing, canard or tail, ``y_out -
  y_in`` for a fin or pylon), with the part of that thickness lying INSIDE any body removed,
  so that a root buried in the fuselage is counted once (the union, not the sum). A mirrored
  component counts twice.

**Quadrature in span.** At fixed x the plane meets the chord of span station ``s`` at the chord
fraction ``f(s) = (x - x_le(s)) / c(s)``, and between two sections the surface is ruled
(linear lofting at equal chord fraction), so the thickness is a smooth function of ``s``
except at: the section stations, the span stations where the plane crosses the leading or
trailing edge or a chordwise station of the airfoil data (a knot of the chordwise PCHIP or
linear interpolant: these are all roots of linear equations, solved exactly), the body's edge
``s = s_c +- r(x)`` (where the body's chord ``2 sqrt(r^2 - (s - s_c)^2)`` has a square-root
end), and the span stations where a wing surface enters a body (``z_upper = z_body`` and the
like: bracketed on a grid and closed by the Illinois variant of regula falsi). The span
integral is split at all of them, and each piece is integrated by Gauss-Legendre after the
substitution ``s = a + (b - a) (3 t^2 - 2 t^3)``, whose vanishing derivative at both ends makes
square-root end behaviour smooth. The result converges geometrically in the number of Gauss
points per piece (see the tests: 1e-10 with 8 points).

Known limits: overlaps of bodies with one another and of wing-like components with one
another (a pylon whose tip is buried in the wing) are NOT removed; only wing-like against
body. The pylons of the bundled transport reach into the wing (tips at z = -1.0, above its
lower surface): up to 1.6 ft^2 per pylon copy, about 0.8 % of A(x) near x = 215, is counted
twice (the closed networks of :mod:`.closed` do the same, so the two paths agree).

A :class:`~juncture.geometry.Geometry` (networks only, no model) falls back to plane cuts of
its networks (:func:`juncture.analysis.cuts.normal_areas`), which must then be closed and
outward-oriented (e.g. :func:`juncture.analysis.closed.closed_networks`); its accuracy is
that of the faceting (second order in the spacing).
"""

from __future__ import annotations

import numpy as np

from ..errors import GeometryError, JunctureError
from ..model import ArbitraryBody, CircularBody, WingLike
from ._components import body_box, boxes_overlap, copies, is_flow_through, wing_box
from .cuts import normal_areas

__all__ = ["normal_area_distribution", "winglike_normal_area", "default_stations",
           "is_flow_through"]

#: Gauss-Legendre points per span piece.
_N_GAUSS = 8
#: Relative distances of the breakpoints graded towards a zero chord (pointed tip).
_GRADING = 0.5 ** np.arange(1, 21)
#: Samples per span piece used to bracket where a wing surface enters a body.
_N_BRACKET = 4
#: Points per chunk when evaluating arbitrary-body sections (bounds temporary memory).
_CHUNK = 4096


# --------------------------------------------------------------------------------------------
# Bodies: the interval of a line (fixed x and span coordinate) that lies inside a body


def _circular_interval(body, x, s, span_axis):
    """Interval ``(lo, hi)`` along the thickness axis of the line (x, s) inside a circular body.

    Empty intervals come back with ``lo == hi`` at the section centre, which continues the
    boundary functions continuously past the body's edge (the root bracketing relies on it).
    """
    x, s = np.broadcast_arrays(np.asarray(x, float), np.asarray(s, float))
    # The quadrature asks at a few stations many times over (every point of a plane x):
    # the section once per station.
    xu, inverse = np.unique(x, return_inverse=True)
    c = body.center_at(xu)[inverse.reshape(x.shape)]
    r = body.radius_at(xu)[inverse.reshape(x.shape)]
    sc, tc = (c[..., 0], c[..., 1]) if span_axis == 1 else (c[..., 1], c[..., 0])
    half = np.sqrt(np.maximum(r * r - (s - sc) ** 2, 0.0))
    return tc - half, tc + half


def _arbitrary_interval(body, x, s, span_axis):
    """As :func:`_circular_interval` for an arbitrary body (half-section mirrored at y = 0)."""
    x, s = np.broadcast_arrays(np.asarray(x, float), np.asarray(s, float))
    shape = x.shape
    xf, sf = x.ravel(), s.ravel()
    lo, hi = np.zeros(xf.size), np.zeros(xf.size)
    xu, inverse = np.unique(xf, return_inverse=True)      # a few stations, asked many times
    sections = body._sections_at(xu)
    for a in range(0, xf.size, _CHUNK):
        sec = sections[inverse[a:a + _CHUNK]]  # (q, m, 2) y, z from bottom to top
        y, z = sec[..., 0], sec[..., 1]
        if span_axis == 1:  # line y = |s|: crossings in z
            u, v, q = y, z, np.abs(sf[a:a + _CHUNK])[:, None]
        else:  # line z = s: crossings in y
            u, v, q = z, y, sf[a:a + _CHUNK][:, None]
        u0, u1, v0, v1 = u[:, :-1], u[:, 1:], v[:, :-1], v[:, 1:]
        du = u1 - u0
        hit = ((u0 - q) * (u1 - q) <= 0.0) & (du != 0.0)
        w = np.where(hit, (q - u0) / np.where(du != 0.0, du, 1.0), 0.0)
        vc = v0 + w * (v1 - v0)
        any_hit = hit.any(axis=1)
        vmax = np.where(hit, vc, -np.inf).max(axis=1)
        vmin = np.where(hit, vc, np.inf).min(axis=1)
        mid = 0.5 * (v.min(axis=1) + v.max(axis=1)) if span_axis == 1 else np.zeros(len(q))
        if span_axis == 1:
            lo_c, hi_c = np.where(any_hit, vmin, mid), np.where(any_hit, vmax, mid)
        else:
            hi_c = np.where(any_hit, vmax, 0.0)
            lo_c = -hi_c
        inside = (xf[a:a + _CHUNK] >= body.x[0]) & (xf[a:a + _CHUNK] <= body.x[-1])
        lo[a:a + _CHUNK] = np.where(inside, lo_c, mid)
        hi[a:a + _CHUNK] = np.where(inside, hi_c, mid)
    return lo.reshape(shape), hi.reshape(shape)


def _body_interval(body, x, s, span_axis):
    if isinstance(body, CircularBody):
        return _circular_interval(body, x, s, span_axis)
    return _arbitrary_interval(body, x, s, span_axis)


def _body_edges(body, x, span_axis):
    """(n_x, 2) span coordinates of the body's edges seen along the span axis at each x."""
    x = np.asarray(x, float)
    if isinstance(body, CircularBody):
        c = body.center_at(x)
        r = body.radius_at(x)
        sc = c[:, 0] if span_axis == 1 else c[:, 1]
        out = np.stack([sc - r, sc + r], axis=-1)
        return np.where((r > 0)[:, None], out, np.nan)
    sec = body._sections_at(x)
    inside = ((x >= body.x[0]) & (x <= body.x[-1]))[:, None]
    if span_axis == 1:
        ymax = sec[..., 0].max(axis=1)
        out = np.stack([-ymax, ymax], axis=-1)
    else:
        out = np.stack([sec[..., 1].min(axis=1), sec[..., 1].max(axis=1)], axis=-1)
    return np.where(inside, out, np.nan)


def _union_overlap(lo, hi, t_lo, t_hi):
    """Length of ``[t_lo, t_hi]`` covered by the union of intervals ``[lo_k, hi_k]``.

    ``lo``, ``hi`` have a leading axis of size k (bodies); the rest broadcasts with ``t_lo``.
    """
    a = np.maximum(lo, t_lo)
    b = np.maximum(np.minimum(hi, t_hi), a)  # an empty clip has zero length
    if a.shape[0] == 1:
        return b[0] - a[0]
    order = np.argsort(a, axis=0)
    a = np.take_along_axis(a, order, axis=0)
    b = np.take_along_axis(b, order, axis=0)
    reach = np.maximum.accumulate(b, axis=0)
    prev = np.concatenate([np.full((1,) + a.shape[1:], -np.inf), reach[:-1]], axis=0)
    return np.maximum(b - np.maximum(a, prev), 0.0).sum(axis=0)


# --------------------------------------------------------------------------------------------
# Wing-like components


class _WingCut:
    """Evaluation of one wing-like component's cut by planes x = const (all stations at once)."""

    def __init__(self, wing, bodies):
        self.wing = wing
        self.bodies = bodies
        self.st = wing.span_stations
        self.ax = wing.thickness_axis
        self.sa = wing.span_axis

    def chord_fraction(self, x, s):
        """Chord fraction of the plane x at span s, and the linear LE x and chord there."""
        w = self.wing
        k, lam = w._bracket(np.clip(s, self.st[0], self.st[-1]), extrapolate=False)
        xle = w.le[k, 0] + lam * (w.le[k + 1, 0] - w.le[k, 0])
        c = w.chord[k] + lam * (w.chord[k + 1] - w.chord[k])
        with np.errstate(divide="ignore", invalid="ignore"):
            f = np.where(c > 0.0, (x - xle) / np.where(c > 0.0, c, 1.0), np.nan)
        return f

    def surfaces(self, x, s):
        """Thickness-axis coordinates (lower, upper) and the in-chord mask at (x, s)."""
        f = self.chord_fraction(x, s)
        tol = 1e-12
        inside = np.isfinite(f) & (f >= -tol) & (f <= 1.0 + tol)
        fc = np.clip(np.nan_to_num(f, nan=0.0), 0.0, 1.0)
        sc = np.clip(s, self.st[0], self.st[-1])
        up = self.wing.point(sc, fc, "upper")[..., self.ax]
        lo = self.wing.point(sc, fc, "lower")[..., self.ax]
        return lo, up, inside

    def intervals(self, x, s):
        """(k, ...) lower and upper ends of every body's interval on the line (x, s)."""
        los, his = zip(*(_body_interval(b, x, s, self.sa) for b in self.bodies))
        return np.stack(los), np.stack(his)

    def overlap(self, x, s):
        """Length of the wing's thickness interval at (x, s) inside the bodies."""
        t_lo, t_hi, inside = self.surfaces(x, s)
        lo, hi = self.intervals(x, s)
        return np.where(inside, _union_overlap(lo, hi, t_lo, t_hi), 0.0)

    def integrand(self, x, s):
        t_lo, t_hi, inside = self.surfaces(x, s)
        thick = np.maximum(t_hi - t_lo, 0.0)
        if self.bodies:
            lo, hi = self.intervals(x, s)
            thick = thick - _union_overlap(lo, hi, t_lo, t_hi)
        return np.where(inside, thick, 0.0)

    def kink_functions(self, x, s):
        """(..., 4 k) functions whose roots are the span stations where a surface meets a body."""
        t_lo, t_hi, _ = self.surfaces(x, s)
        lo, hi = self.intervals(x, s)
        return np.concatenate([t_hi - hi, t_lo - lo, t_hi - lo, t_lo - hi], axis=0)

    # -- breakpoints --------------------------------------------------------------------
    def linear_breakpoints(self, x):
        """(n_x, k) span stations where the plane crosses a section, LE, TE or data station."""
        w = self.wing
        fr = np.unique(np.concatenate([[0.0, 1.0], w.x_over_c / 100.0]))
        xa = w.le[:-1, 0, None] + fr * w.chord[:-1, None]  # (n_seg, n_f) x of the fraction
        xb = w.le[1:, 0, None] + fr * w.chord[1:, None]
        d = xb - xa
        with np.errstate(divide="ignore", invalid="ignore"):
            lam = (x[:, None, None] - xa) / np.where(d != 0.0, d, np.nan)
        ok = (lam > 0.0) & (lam < 1.0)
        s = self.st[:-1, None] + lam * (self.st[1:] - self.st[:-1])[:, None]
        s = np.where(ok, s, np.nan).reshape(x.size, -1)
        sec = np.broadcast_to(self.st, (x.size, self.st.size))
        # A zero chord (pointed tip) is a pole of f(s) = (x - x_le) / c(s) next to the pieces:
        # grade them geometrically towards it so every piece sees it at a distance of the
        # order of its own length (uniform geometric convergence of the Gauss rule).
        grade = [self.st[k] + (self.st[j] - self.st[k]) * _GRADING
                 for k in np.flatnonzero(w.chord == 0.0) for j in (k - 1, k + 1)
                 if 0 <= j < self.st.size]
        grade = np.concatenate(grade) if grade else np.zeros(0)
        return np.concatenate([sec, s, np.broadcast_to(grade, (x.size, grade.size))], axis=1)

    def body_breakpoints(self, x, bp):
        """Body edges (n_x, 2 k); graded stations and surface/body crossings (n_x, m)."""
        edges = np.concatenate([_body_edges(b, x, self.sa) for b in self.bodies], axis=1)
        # The body's chord sqrt(r^2 - (s - s_c)^2) is singular at its edges: grade the pieces
        # geometrically towards them (from inside), as towards a pointed tip.
        half = 0.5 * (edges[:, 1::2] - edges[:, 0::2])[..., None] * _GRADING
        graded = np.concatenate([edges[:, 0::2, None] + half, edges[:, 1::2, None] - half],
                                axis=1).reshape(x.size, -1)
        bp = np.concatenate([bp, graded], axis=1)
        a, b = _compact(*_pieces(np.concatenate([bp, edges], axis=1)))
        t = np.arange(_N_BRACKET) / _N_BRACKET
        grid = np.concatenate([(a[..., None] + (b - a)[..., None] * t).reshape(x.size, -1),
                               b[:, -1:]], axis=1)  # (n_x, n_grid), non-decreasing
        g = self.kink_functions(np.broadcast_to(x[:, None], grid.shape), grid)
        change = np.sign(g[..., :-1]) * np.sign(g[..., 1:]) < 0.0  # (4 k, n_x, n_grid - 1)
        fi, xi, gi = np.nonzero(change)
        if fi.size == 0:
            return edges, graded
        rows = np.arange(fi.size)
        roots = _illinois(lambda ss: self.kink_functions(x[xi], ss)[fi, rows],
                          grid[xi, gi], grid[xi, gi + 1], g[fi, xi, gi], g[fi, xi, gi + 1])
        counts = np.bincount(xi, minlength=x.size)
        out = np.full((x.size, int(counts.max())), np.nan)
        order = np.argsort(xi, kind="stable")
        first = np.cumsum(counts) - counts
        out[xi[order], np.arange(xi.size) - first[xi[order]]] = roots[order]
        return edges, np.concatenate([graded, out], axis=1)

    def area(self, x, n_gauss=_N_GAUSS):
        """(n_x,) area of the cut of this component (one copy, trimmed by the bodies)."""
        bp = self.linear_breakpoints(x)
        edges = np.zeros((x.size, 0))
        if self.bodies:
            edges, roots = self.body_breakpoints(x, bp)
            bp = np.concatenate([bp, edges, roots], axis=1)
        a, b = _pieces(np.clip(bp, self.st[0], self.st[-1]))
        # Only the pieces of positive length (most rows' breakpoints are padding: the
        # transport's wing has 85 columns and at most 16 pieces), as one list.
        row, col = np.nonzero(b > a)
        ea = (a[row, col, None] == edges[row]).any(axis=-1)
        eb = (b[row, col, None] == edges[row]).any(axis=-1)
        a, b, xs = a[row, col], b[row, col], x[row]
        # Gauss-Legendre on every piece. Where a piece ends at a body edge and the body cuts
        # the wing there, the overlap has a square-root end: substitute s - a = (b - a) t^2
        # (and likewise at b), which makes it smooth.
        g, wg = np.polynomial.legendre.leggauss(int(n_gauss))
        t, wt = 0.5 * (g + 1.0), 0.5 * wg
        if ea.any() or eb.any():
            cut = self.overlap(xs, 0.5 * (a + b)) > 0.0
            ea, eb = ea & cut, eb & cut
        ea, eb = ea[..., None], eb[..., None]
        # phi(t) on [0, 1]: t (smooth), t^2 (root at a), 1 - (1-t)^2 (at b), 3t^2 - 2t^3 (both)
        phi = np.where(ea & eb, t * t * (3 - 2 * t), np.where(ea, t * t, np.where(
            eb, 1 - (1 - t) ** 2, t)))
        dphi = np.where(ea & eb, 6 * t * (1 - t), np.where(ea, 2 * t, np.where(
            eb, 2 * (1 - t), 1.0)))
        s = a[..., None] + (b - a)[..., None] * phi
        w = (b - a)[..., None] * dphi * wt
        val = self.integrand(np.broadcast_to(xs[:, None], s.shape), s)
        return np.bincount(row, weights=np.einsum("jk,jk->j", val, w), minlength=x.size)


def _pieces(bp):
    """Sorted breakpoints (NaN = none) -> (n_x, k - 1) starts and ends of the pieces."""
    bp = np.sort(bp, axis=1)  # NaN last
    last = np.nanmax(bp, axis=1)
    bp = np.where(np.isnan(bp), last[:, None], bp)
    return bp[:, :-1], bp[:, 1:]


def _compact(a, b):
    """Pieces ``(a, b)`` (n_x, k) of :func:`_pieces` with those of zero length moved to the
    end of their row and the columns no row needs dropped (the end padded by the row's
    last breakpoint, so each row's breakpoints stay non-decreasing)."""
    keep = b > a
    width = max(int(keep.sum(axis=1).max(initial=0)), 1)
    order = np.argsort(~keep, axis=1, kind="stable")[:, :width]
    a, b = np.take_along_axis(a, order, 1), np.take_along_axis(b, order, 1)
    pad = ~np.take_along_axis(keep, order, 1)
    last = np.max(np.where(pad, -np.inf, b), axis=1, keepdims=True)
    last = np.where(np.isfinite(last), last, b[:, :1])         # a row with no piece
    return np.where(pad, last, a), np.where(pad, last, b)


def _illinois(func, a, b, fa, fb, iters=80):
    """Vectorised Illinois regula falsi on brackets [a, b] with fa fb < 0; returns roots."""
    a, b, fa, fb = (np.array(v, dtype=float) for v in (a, b, fa, fb))
    side = np.zeros(a.size, int)
    scale = np.maximum(np.abs(a), np.abs(b)) + 1.0
    for _ in range(iters):
        act = np.abs(b - a) > 1e-14 * scale
        if not act.any():
            break
        with np.errstate(divide="ignore", invalid="ignore"):
            c = b - fb * (b - a) / (fb - fa)
        bad = ~np.isfinite(c) | ((c - a) * (c - b) > 0.0)
        c = np.where(bad, 0.5 * (a + b), c)
        fc = func(c)
        same_a = np.sign(fc) == np.sign(fa)
        a_new = np.where(same_a, c, a)
        b_new = np.where(same_a, b, c)
        fa_new = np.where(same_a, fc, np.where(side == 1, 0.5 * fa, fa))
        fb_new = np.where(same_a, np.where(side == -1, 0.5 * fb, fb), fc)
        side = np.where(act, np.where(same_a, -1, 1), side)
        a, b = np.where(act, a_new, a), np.where(act, b_new, b)
        fa, fb = np.where(act, fa_new, fa), np.where(act, fb_new, fb)
        exact = fc == 0.0
        a, b = np.where(act & exact, c, a), np.where(act & exact, c, b)
    return np.where(np.abs(fa) < np.abs(fb), a, b)


def _check_x(x):
    try:
        arr = np.asarray(x, dtype=float)
    except (TypeError, ValueError):
        raise JunctureError(f"stations x must be numbers, found {x!r}") from None
    if arr.ndim > 1 or not np.all(np.isfinite(arr)):
        raise JunctureError(f"stations x must be a finite 1-D array, found shape {arr.shape}")
    return np.atleast_1d(arr)


def winglike_normal_area(wing, x, bodies=(), n_gauss=_N_GAUSS):
    """Area of the cut of one wing-like component by planes x = const, minus its buried part.

    Parameters
    ----------
    wing : WingLike
        The component (its described copy only: the image is not included).
    x : (n_x,) float
        Stations [deck length].
    bodies : sequence of CircularBody or ArbitraryBody
        Bodies whose interior is removed from the component's cut.
    n_gauss : int
        Gauss points per span piece (see the module notes).

    Returns
    -------
    (n_x,) float
        ``int (t_upper - t_lower - overlap with bodies) ds`` over the span [deck length^2].

    Examples
    --------
    A rectangular wing of chord 2, span 3 (y from 1 to 4), a 10 % diamond section: at mid
    chord the cut is 3 x 0.2.

    >>> w = WingLike("w", "wing", [[0, 1, 0], [0, 4, 0]], [2, 2], [0, 50, 100],
    ...              [[0, 5, 0], [0, 5, 0]], chordwise="linear")
    >>> round(float(winglike_normal_area(w, [1.0])[0]), 12)
    0.6
    """
    if not isinstance(wing, WingLike):
        raise GeometryError(f"expected a WingLike, found a {type(wing).__name__}")
    x = _check_x(x)
    n_gauss = int(n_gauss)
    if n_gauss < 1:
        raise JunctureError(f"n_gauss must be at least 1, found {n_gauss}")
    box = wing_box(wing)
    near = [b for b in bodies if boxes_overlap(box, body_box(b))]
    return _WingCut(wing, near).area(x, n_gauss)


# --------------------------------------------------------------------------------------------
# Configurations


def default_stations(obj, n_x=101):
    """``n_x`` equally spaced stations from the first to the last x of a configuration.

    Parameters
    ----------
    obj : Configuration or Geometry
    n_x : int
        Number of stations (>= 2).

    Returns
    -------
    (n_x,) float
        Stations [deck length].
    """
    n_x = int(n_x)
    if n_x < 2:
        raise JunctureError(f"n_x must be at least 2, found {n_x}")
    ext = obj.extents()
    return np.linspace(ext[0, 0], ext[1, 0], n_x)


def normal_area_distribution(cfg, x=None, components=None, n_x=101, n_gauss=_N_GAUSS,
                             flow_through=True):
    """Normal cross-sectional areas ``A(x)`` of a configuration, both halves, from the model.

    Parameters
    ----------
    cfg : Configuration or Geometry
        The airplane. A Configuration is integrated from its component model (accurate to
        round-off, see the module notes). A Geometry has no model: its networks are cut by
        planes (:func:`juncture.analysis.cuts.normal_areas`, with their mirror images); they
        must be closed and outward, and only ``"total"`` is returned.
    x : (n_x,) float, optional
        Stations [deck length]. Default: ``n_x`` equally spaced from the first to the last x
        of the configuration.
    components : sequence of str, optional
        Component names to include (default: all). A wing-like component is still trimmed
        by every body of the configuration, requested or not.
    n_x : int
        Number of default stations.
    n_gauss : int
        Gauss points per span piece of a wing-like component.
    flow_through : bool
        Subtract each open nacelle's inlet capture area (a flow-through nacelle, see
        :func:`is_flow_through`).

    Returns
    -------
    dict of str to (n_x,) float
        ``"x"``: the stations used [deck length]; ``"total"``: the area of the union of the
        requested components [deck length^2]; and one entry per component: a body's section
        area, a wing-like component's cut minus its part inside bodies, each counted twice if
        the component has an image at -y (full airplane, matching the deck's REFA).

    Raises
    ------
    GeometryError
        An unknown component name.
    JunctureError
        Stations not a finite 1-D array.

    Examples
    --------
    >>> from juncture.model import CircularBody, Configuration
    >>> body = CircularBody("body", [0.0, 10.0], [1.0, 1.0], axial="linear")
    >>> a = normal_area_distribution(Configuration({"body": body}), [5.0])
    >>> round(float(a["total"][0] / np.pi), 12)
    1.0
    """
    if not hasattr(cfg, "components"):
        if not hasattr(cfg, "networks"):
            raise JunctureError(f"expected a Configuration or Geometry, found "
                                f"{type(cfg).__name__}")
        xs = default_stations(cfg, n_x) if x is None else _check_x(x)
        return {"x": xs, "total": normal_areas(cfg, xs)}
    xs = default_stations(cfg, n_x) if x is None else _check_x(x)
    names = list(cfg.components) if components is None else [str(c) for c in components]
    comps = [cfg[n] for n in names]  # raises GeometryError for an unknown name
    bodies = cfg.bodies
    out = {"x": xs}
    total = np.zeros(xs.size)
    for comp in comps:
        if isinstance(comp, (CircularBody, ArbitraryBody)):
            a = comp.area_at(xs)
            if flow_through and is_flow_through(comp):
                xg = comp.x_global
                a = a - np.where((xs >= xg[0]) & (xs <= xg[-1]), np.pi * comp.radius[0] ** 2,
                                 0.0)
        else:
            a = winglike_normal_area(comp, xs, bodies, n_gauss)
        a = copies(comp, cfg) * np.asarray(a, dtype=float)
        out[comp.name] = a
        total = total + a
    out["total"] = total
    return out


def __getattr__(name):
    # mach_plane_area_distribution moved to juncture.analysis.machplanes (areas no longer
    # imports the closed networks): still importable from here, with a warning.
    if name == "mach_plane_area_distribution":
        import warnings

        from .machplanes import mach_plane_area_distribution

        warnings.warn("juncture.analysis.areas.mach_plane_area_distribution moved to "
                      "juncture.analysis.machplanes (also juncture.analysis."
                      "mach_plane_area_distribution)", DeprecationWarning, stacklevel=2)
        return mach_plane_area_distribution
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
