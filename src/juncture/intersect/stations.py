"""Where a wing-like surface meets a body in a given cross-section plane x = const.

The fuselage blocks of the TM-4607 layout have a row at every body station, and inside a
region (canard, wing, tail, fin) each row ends on the region's bounding curve. TM-4607
interpolates that curve's angle linearly in x between the intersection points of the
lofting lines; on a body whose section turns quickly beside the root (a high wing sitting on
the fuselage's shoulder) the interpolated end lies well off the wing: 0.4 ft inside a
generated high wing, whose lower surface then crossed the fuselage block. Here the row ends
at the exact intersection in its own plane: the point of the wing's surface at the chord
fraction whose lofting line meets the body at x = x0 (:func:`plane_points`), found by
false position on the fraction between the two lofting lines that bracket x0, each trial
line cut with the body by the same root finder as every other intersection
(:func:`juncture.intersect.body.intersect_body`). The point lies on both surfaces to the
root finder's precision, in its plane to :data:`XTOL` of the size.
"""

from __future__ import annotations

import numpy as np

__all__ = ["plane_points", "XTOL", "ON_BODY"]

#: Largest distance of a point from its plane x = x0, share of the size.
XTOL = 1e-12
#: A bracketing point lies on the body when its residual is at most this share of the size
#: (a lofting line that misses the body ends off it: no bracket there).
ON_BODY = 1e-9
#: Stations nearer a bracketing point than this share of the size keep the interpolation
#: (the row would nearly repeat that point's).
MARGIN = 1e-9
MAX_ITER = 40
#: A bracket whose secant slope grows past this many times its first one holds a jump of
#: the cut's x, not a root: the trial line's first crossing changes there (x0 in the gap
#: between two faces, a joint's step). The search stops there (NaN) instead of closing in
#: on the jump to the last digit (30 more rounds of cuts).
JUMP = 1e3


def plane_points(wing, body, side, points, x, either=False):
    """(len(x), 3) intersection points of ``wing``'s ``side`` surface with ``body`` in the
    planes x = ``x``, NaN where a station does not lie strictly between the points of two
    neighbouring lofting lines that both meet the body, x increasing from the first to the
    second (with ``either``, or falling: the caller leaves one such pair per station), or
    where the search fails (a trial line that misses the body).

    Parameters
    ----------
    wing : WingLike
        The component whose lofting lines gave ``points`` (one per chord station).
    body : CircularBody or ArbitraryBody
    side : {"upper", "lower"}
    points : (n_stations, 3) float
        Its intersection with ``body`` on that side, one point per lofting line (NaN, or
        off the body, where a line misses it).
    x : (k,) float
        Body stations.
    """
    from .body import _error_function

    x = np.asarray(x, float)
    out = np.full((x.size, 3), np.nan)
    p = np.asarray(points, float)
    ok = np.all(np.isfinite(p), axis=1)
    if x.size == 0 or ok.sum() < 2:
        return out
    size = float(np.ptp(p[ok], axis=0).max()) or 1.0
    ok[ok] = np.abs(_error_function(body)(p[ok])) <= ON_BODY * size
    a = np.flatnonzero(ok[:-1] & ok[1:])          # neighbouring lines, both on the body
    b = a + 1
    f = wing.x_over_c / 100.0
    fa, fb = f[a], f[b]
    xa, xb = p[a, 0], p[b, 0]
    if either:                    # each pair from its foremost point to its aftmost
        swap = xa > xb
        xa, xb = np.where(swap, xb, xa), np.where(swap, xa, xb)
        fa, fb = np.where(swap, fb, fa), np.where(swap, fa, fb)
    pad = MARGIN * size
    inside = (xa[None, :] + pad < x[:, None]) & (x[:, None] < xb[None, :] - pad)
    rows = np.flatnonzero(inside.any(axis=1))
    if not rows.size:
        return out
    j = np.argmax(inside[rows], axis=1)
    x0 = x[rows]
    solved = _false_position(wing, body, side, x0, fa[j], fb[j], xa[j] - x0, xb[j] - x0,
                             XTOL * size)
    error = _error_function(body)
    axis = wing.span_axis
    for i in np.flatnonzero(_at_joint(body, x0, XTOL * size)):
        solved[i] = _in_plane(wing, error, side, x0[i], p[a[j[i]], axis], p[b[j[i]], axis],
                              XTOL * size)
    out[rows] = solved
    return out


def _at_joint(body, x0, tol):
    """(k,) bool: stations within ``tol`` of a joint where two segments repeat a station
    with different sections (a step: there the lofting lines' crossings jump, or the search
    ends a rounding on the wrong side of the joint). A joint whose two sections are one
    keeps the search over chord fractions."""
    from ..model import CircularBody
    from .body import _error_function

    x = np.asarray(body.x_global, float)
    joints = np.unique(x[1:][x[1:] == x[:-1]])
    if not joints.size:
        return np.zeros(x0.size, bool)
    par = np.linspace(-np.pi, np.pi, 13) if isinstance(body, CircularBody) else \
        np.linspace(0.0, 1.0, 13)
    later = body.point(joints[:, None], par[None, :])        # on the later section
    later[..., 0] = np.nextafter(joints, -np.inf)[:, None]   # measured on the earlier one
    off = np.abs(_error_function(body)(later.reshape(-1, 3))).reshape(later.shape[:2])
    steps = joints[off.max(axis=1) > tol]
    if not steps.size:
        return np.zeros(x0.size, bool)
    return np.min(np.abs(x0[:, None] - steps[None, :]), axis=1) <= tol


#: Samples of the wing's cut in a plane x = x0 searched for the body's crossing.
SAMPLES = 64
#: The span searched, on each side of the two bracketing points' span stations, in shares
#: of the span between them: the nearest crossing in the first that has one.
WIDEN = (1.0, 4.0, 16.0)


def _in_plane(wing, error, side, x0, sa, sb, tol):
    """(3,) the point where ``wing``'s ``side`` surface meets the body (``error``, its
    error function) in the plane x = ``x0``, near the span stations ``sa`` and ``sb`` of the
    two lofting lines' points that bracket x0; NaN where it has none there.

    The lofting lines' first crossings with the body jump at a fuselage joint whose two
    sections differ (a step: lines between two fractions meet the step's face), so the
    search over chord fractions cannot close in on a station there; x0 = x_joint is the
    later section's plane, a hair before it the earlier's. In its plane the wing's cut is
    a curve of the span station alone: x = le_x(s) + c(s) f is linear in the fraction f
    at each span station s, so f(s) = (x0 - le_x(s)) / c(s), and the crossing is a root
    of the body's error function along s (sampled, then Brent's method)."""
    from scipy.optimize import brentq

    lo, hi = min(sa, sb), max(sa, sb)

    def on_cut(s):
        s = np.atleast_1d(np.asarray(s, float))
        ends = wing.point(np.stack([s, s], -1), np.array([0.0, 1.0]), side, extrapolate=True)
        f = (x0 - ends[:, 0, 0]) / (ends[:, 1, 0] - ends[:, 0, 0])
        q = wing.point(s, f, side, extrapolate=True)
        q[:, 0] = x0      # in the plane exactly: a hair before a joint is the earlier section
        return q, f

    for widen in WIDEN:       # the span between the two lines' points, then more round it
        pad = max(widen * (hi - lo), tol)
        s = np.linspace(lo - pad, hi + pad, SAMPLES)
        q, f = on_cut(s)
        g = error(q)
        ok = np.isfinite(g) & (f >= 0.0) & (f <= 1.0)
        change = np.flatnonzero(ok[:-1] & ok[1:] & (np.sign(g[:-1]) * np.sign(g[1:]) <= 0.0))
        if change.size:
            break
    else:
        return np.full(3, np.nan)
    k = change[np.argmin(np.abs(s[change] - 0.5 * (lo + hi)))]
    root = brentq(lambda t: float(error(on_cut(t)[0])[0]), s[k], s[k + 1], xtol=tol * 1e-3,
                  rtol=4 * np.finfo(float).eps)
    return on_cut(root)[0][0]


def _false_position(wing, body, side, x0, fa, fb, ga, gb, tol):
    """(k, 3) points at the fractions where the cut's x equals ``x0`` (Illinois false
    position between fa and fb, where x - x0 is ga < 0 and gb > 0); NaN where a trial line
    misses the body or the search does not settle."""
    out = np.full((x0.size, 3), np.nan)
    act = np.arange(x0.size)
    fa, fb, ga, gb = (np.array(v, float) for v in (fa, fb, ga, gb))
    last = np.zeros(x0.size, int)      # which end was kept last time (-1 a, +1 b)
    with np.errstate(divide="ignore", invalid="ignore"):
        steep = JUMP * (gb - ga) / np.abs(fb - fa)
    for _ in range(MAX_ITER):
        if not act.size:
            break
        fm = (fa * gb - fb * ga) / (gb - ga)
        fm = np.clip(fm, np.minimum(fa, fb), np.maximum(fa, fb))
        pts = _cut(wing, body, side, fm)
        gm = pts[:, 0] - x0
        good = np.isfinite(gm)
        done = good & (np.abs(gm) <= tol)
        out[act[done]] = pts[done]
        neg = good & ~done & (gm < 0)
        pos = good & ~done & (gm > 0)
        # Illinois: the end kept twice in a row has its value halved
        gb = np.where(neg & (last == 1), 0.5 * gb, gb)
        ga = np.where(pos & (last == -1), 0.5 * ga, ga)
        fa, ga = np.where(neg, fm, fa), np.where(neg, gm, ga)
        fb, gb = np.where(pos, fm, fb), np.where(pos, gm, gb)
        last = np.where(neg, 1, np.where(pos, -1, last))
        width = np.abs(fb - fa)
        keep = good & ~done & (width > 1e-15) & (gb - ga < steep * width)
        act, x0, steep = act[keep], x0[keep], steep[keep]
        fa, fb, ga, gb, last = fa[keep], fb[keep], ga[keep], gb[keep], last[keep]
    return out


def _cut(wing, body, side, fractions):
    """(k, 3) the points where ``wing``'s lofting lines at chord ``fractions`` meet
    ``body`` on ``side`` (NaN where one misses it)."""
    from .body import intersect_body

    want = np.asarray(fractions, float)
    f = np.unique(np.concatenate([want, [0.0 if want.min() > 0.0 else 1.0]]))  # 2 at least
    cut = intersect_body(_lines_at(wing, side, f), body, "upper")
    rows = np.searchsorted(f, want)
    return np.where(cut.found[rows, None], cut.points[rows], np.nan)


def _lines_at(wing, side, f):
    """A wing-like component whose lofting lines (both sides) are ``wing``'s ``side``
    lofting lines at the chord fractions ``f`` (sorted): its sections' offsets are the
    model's own section curves there (:meth:`~juncture.model.WingLike.point`), as a
    camber line of zero thickness (only the lines at ``f`` are asked for: the other
    chord fractions' curves of this copy are not the model's)."""
    from ..model import WingLike

    span = wing.span_stations
    axis = wing.thickness_axis
    offsets = wing.point(span[:, None], f[None, :], side)[..., axis] - wing.le[:, None, axis]
    zero = np.zeros_like(offsets)
    return WingLike(wing.name, wing.kind, wing.le, wing.chord, 100.0 * f, zero, zero, offsets,
                    wing.mirrored, wing.chordwise)
