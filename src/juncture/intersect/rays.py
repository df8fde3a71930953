"""Vectorised, bracketed root finding along extrapolated lofting lines (TM-4406 eq 4).

TM-4406 extrapolates each lofting line inboard, v(t) = w1 + t (w1 - w2), and steps t by an
amount proportional to the error e(t) until it is small: a fixed-gain iteration that can
overshoot, stall, or converge to the wrong crossing. Here every lofting line of a surface is
solved at once: each line is parameterised by a *section coordinate* u (u = k on section k,
linear between sections, linearly extended beyond the root for u < 0 and beyond the tip for
u > n - 1), the error is sampled on a grid to bracket the crossing the paper means (the first
one reached coming inboard from the tip), and the bracket is closed by the Illinois variant of
regula falsi (superlinear, never leaves the bracket) to a relative tolerance of 1e-13 in u.
A closed bracket is a root only if the error there is (nearly) zero: a sign change across a
jump of the error (an open body end, a planform edge) is stepped over, and a line whose
every sign change is a jump misses (see :func:`find_crossings`, Notes).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError

__all__ = ["polyline_points", "find_crossings", "Crossings", "SurfaceBound",
           "root_tolerance"]


class SurfaceBound:
    """Lipschitz bound of a surface's error function for :func:`find_crossings`.

    Callable as ``bound(pa, pb)``: a bound per segment pa -> pb, from the surface's
    ``error_lipschitz_between``; ``global_bound`` (``error_lipschitz``) is only evaluated
    when a search needs it, so a warm-started solve on a new body never builds its table.
    """

    def __init__(self, surface):
        self._surface = surface

    def __call__(self, pa, pb):
        return self._surface.error_lipschitz_between(pa, pb)

    @property
    def global_bound(self):
        return self._surface.error_lipschitz


def polyline_points(lines, u):
    """Points at section coordinate u on piecewise-linear lines, extended at both ends.

    Parameters
    ----------
    lines : (m, n, 3) float
        m lofting lines through n sections (root first).
    u : (m, ...) float
        Section coordinate per line (0 on the root section, n - 1 on the tip).

    Returns
    -------
    (m, ..., 3) float
    """
    lines = np.asarray(lines, float)
    u = np.asarray(u, float)
    m, n = lines.shape[:2]
    k = np.minimum(np.maximum(np.floor(u).astype(int), 0), n - 2)
    lam = (u - k)[..., None]
    at = np.arange(m).reshape((m,) + (1,) * (u.ndim - 1)) * n + k
    flat = lines.reshape(m * n, 3)
    a, b = np.take(flat, at, axis=0), np.take(flat, at + 1, axis=0)   # lines[rows, k (+ 1)]
    return a + lam * (b - a)


@dataclass(frozen=True, slots=True, eq=False)
class Crossings:
    """Result of :func:`find_crossings`.

    Attributes
    ----------
    u : (m,) float
        Section coordinate of the crossing on each line (NaN where the line misses).
    points : (m, 3) float
        The crossing points (NaN rows where the line misses).
    found : (m,) bool
        Whether each line reached the surface.
    n_crossings : (m,) int
        Number of sign changes seen along the sampled range (2 or more: a double crossing).
    iterations : int
        Illinois iterations used to reach the tolerance.
    residual : (m,) float
        |error| at the crossing [deck length].
    start_error : (m,) float
        The error at each line's starting end (the tip); NaN where a hint was used.
    gradient : (m, 3) float or None
        The error's gradient at the crossings, when the error function provides one.
    jumps : (m,) int or None
        Sign changes of the error along each line that closed off the surface (a jump of the
        error at an open end, a planform edge, ...) and were therefore not taken as roots.
        A line with jumps and no root is a miss.
    """

    u: np.ndarray
    points: np.ndarray
    found: np.ndarray
    n_crossings: np.ndarray
    iterations: int
    residual: np.ndarray
    start_error: np.ndarray = None
    gradient: np.ndarray = None
    jumps: np.ndarray = None


def _not_converged(max_iter, rows):
    """The error of a root search that ran out of iterations; ``rows``: the lines still open
    (0-based, kept on the exception as ``rows`` for the caller to name)."""
    rows = [int(r) for r in np.atleast_1d(rows)]
    shown = ", ".join(str(r + 1) for r in rows[:5]) + (", ..." if len(rows) > 5 else "")
    exc = ConvergenceError(f"lofting-line intersection did not converge in {max_iter} "
                           f"iterations (line {shown})")
    exc.rows = rows
    return exc


def _illinois(lines, error, a, b, fa, fb, act, rtol, max_iter):
    """Close brackets [a (outside, f > 0), b (inside, f <= 0)] by Illinois regula falsi."""
    m = len(a)
    side = np.zeros(m, int)
    same = np.zeros(m, int)  # how many times in a row the same end was kept
    it = 0
    rows = None
    while act.any():
        it += 1
        if it > max_iter:
            raise _not_converged(max_iter, np.flatnonzero(act) if rows is None else rows)
        with np.errstate(invalid="ignore", divide="ignore"):
            c = np.where(fb != fa, b - fb * (b - a) / (fb - fa), 0.5 * (a + b))
        # Regula falsi creeps up to a jump of the error (one end barely moves, however often
        # the other's value is halved): from the fourth step in a row on one side, bisection
        # until the side changes; and wherever its point is an end of the bracket (a step
        # below the rounding of u, the error at that end zero to rounding).
        crawl = same >= 4
        bad = ~np.isfinite(c) | ((c - a) * (c - b) > 0) | crawl | (c == a) | (c == b)
        c = np.where(bad, 0.5 * (a + b), c)
        fc = np.zeros(m)
        rows = np.flatnonzero(act)
        fc[rows] = _call(error, polyline_points(lines[rows], c[rows, None]), rows)[:, 0]
        left = fc > 0.0  # c is outside: replaces a
        # Illinois: halve the retained end's value when the same end is kept twice.
        fa_new = np.where(left, fc, np.where(side == -1, fa * 0.5, fa))
        fb_new = np.where(~left, fc, np.where(side == 1, fb * 0.5, fb))
        a = np.where(act & left, c, a)
        b = np.where(act & ~left, c, b)
        fa = np.where(act, fa_new, fa)
        fb = np.where(act, fb_new, fb)
        new_side = np.where(left, 1, -1)
        same = np.where(act & (new_side == side), same + 1, 0)
        side = np.where(act, new_side, side)
        exact = act & (fc == 0.0)
        a = np.where(exact, c, a)
        b = np.where(exact, c, b)
        width = np.maximum(rtol * np.maximum(1.0, np.abs(c)), 4 * np.spacing(np.maximum(1.0,
                                                                                  np.abs(c))))
        act = act & (np.abs(b - a) > width)
    return a, b, fa, fb, it


def _newton(lines, error, a, b, fa, fb, act, rtol, max_iter, start=None):
    """Bracketed Newton: like :func:`_illinois` but stepping with the error's gradient.

    ``error.value_and_gradient(points) -> (e, grad)`` (with the rows too for a row-aware
    error, as in :func:`find_crossings`). Each iterate is the Newton step from
    the last point when it falls inside the current bracket, else the regula-falsi point, or
    the midpoint when the previous fallback of that line was regula falsi too (at a jump of
    the error regula falsi alone can crawl: one end barely moves); the bracket shrinks with
    every evaluation, so the iteration cannot leave it. Stops when the Newton correction is
    below rtol (quadratic convergence: about 3 iterations). ``start`` (optional, NaN where
    absent) replaces the first regula-falsi point: a warm start close to the root (a previous
    solution) saves an iteration or two. ``a, b, fa, fb`` are updated in place to the final
    bracket (f values as evaluated). Returns (u, f(u), iterations).
    """
    m, n = lines.shape[:2]
    with np.errstate(invalid="ignore", divide="ignore"):
        u = np.where(fb != fa, b - fb * (b - a) / (fb - fa), 0.5 * (a + b))
    if start is not None:
        u = np.where(np.isfinite(start) & ((start - a) * (start - b) < 0), start, u)
    fu = np.zeros(m)
    fell = np.zeros(m, bool)  # the last iterate of the line was a regula-falsi fallback
    it = 0
    rows = np.flatnonzero(act)
    tol = max(rtol, 1e-9)
    while rows.size:
        it += 1
        if it > max_iter:
            raise _not_converged(max_iter, np.flatnonzero(act) if rows is None else rows)
        ur = u[rows]
        lr = lines[rows]
        e, g = _call_gradient(error, polyline_points(lr, ur[:, None])[:, 0], rows)
        fu[rows] = e
        k = np.minimum(np.maximum(ur.astype(int), 0), n - 2)
        k = np.where(ur < 0, 0, k)
        idx = np.arange(rows.size)
        slope = np.einsum("ij,ij->i", g, lr[idx, k + 1] - lr[idx, k])
        out = e > 0
        ar = np.where(out, ur, a[rows])
        br = np.where(out, b[rows], ur)
        far = np.where(out, e, fa[rows])
        fbr = np.where(out, fb[rows], e)
        a[rows], b[rows], fa[rows], fb[rows] = ar, br, far, fbr
        with np.errstate(invalid="ignore", divide="ignore"):
            step = e / slope
        nxt = ur - step
        inside = np.isfinite(nxt) & ((nxt - ar) * (nxt - br) < 0)
        scale = np.maximum(1.0, np.abs(ur))
        # Once the correction is below 1e-9 the Newton iterate is exact to ~1e-18 (quadratic
        # convergence): take it without another evaluation (the caller measures the final
        # residual anyway).
        # ... or the bracket is down to a few floats (a jump of the error there: the root is
        # located as well as u can be; the caller tells a jump from a root).
        done = (np.abs(step) <= tol * scale) | (e == 0) | (np.abs(br - ar) <= rtol * scale) | \
            (np.abs(br - ar) <= 4 * np.spacing(scale))
        need = ~inside & ~done
        use_rf = np.zeros(rows.size, bool)
        if need.any():  # Newton left the bracket: regula falsi there, or bisection
            with np.errstate(invalid="ignore", divide="ignore"):
                rf = br[need] - fbr[need] * (br[need] - ar[need]) / (fbr[need] - far[need])
            ok_rf = np.isfinite(rf) & ((rf - ar[need]) * (rf - br[need]) < 0) & \
                ~fell[rows[need]]
            nxt[need] = np.where(ok_rf, rf, 0.5 * (ar[need] + br[need]))
            use_rf[need] = ok_rf
        fell[rows] = use_rf
        if it > 30 and it % 2 == 0:
            # Still open after 30 steps: Newton creeps (an error flat near zero over the
            # bracket, a line grazing the body). Every other step bisects, so the bracket
            # halves at least every two evaluations.
            nxt = np.where(done, nxt, 0.5 * (ar + br))
        u[rows] = np.where(done & ~inside, ur, nxt)
        rows = rows[~done]
    return u, fu, it


def _brackets_dense(lines, error, u_low, samples_per_section, rows, u_top=None):
    m, n = lines.shape[:2]
    u_top = np.full(m, float(n - 1)) if u_top is None else u_top
    span = u_top - np.minimum(u_low, 0.0)
    n_samp = int(np.ceil(float(span.max()) * samples_per_section)) + 2
    grid = u_top[:, None] - np.linspace(0.0, 1.0, n_samp)[None, :] * (u_top - u_low)[:, None]
    e = _call(error, polyline_points(lines, grid), rows)
    return _first_entering(grid, e) + (e[:, 0],)


def _first_entering(grid, e):
    """Per row of a grid running from the tip inboard: the first outside -> inside pair."""
    inside = e <= 0.0
    n_cross = (inside[:, 1:] != inside[:, :-1]).sum(axis=1)
    entering = ~inside[:, :-1] & inside[:, 1:]
    found = entering.any(axis=1)
    i = np.argmax(entering, axis=1)
    rows = np.arange(len(grid))
    return (found, grid[rows, i], grid[rows, i + 1], e[rows, i], e[rows, i + 1], n_cross)


#: Intervals :func:`_refine_dips` bisects at once, at most: along a line that grazes the
#: surface (its error near 0 over a stretch) every half stays open and their number doubles
#: each round (2**21 intervals, out of memory, on a held-out airplane); beyond this, the ones
#: whose ends lie nearest the surface go on.
MAX_DIPS = 1 << 15


def _refine_dips(lines, error, line_rows, ua, ub, ea, eb, speed, lipschitz, max_rounds=48):
    """Find a point inside the surface between two outside samples, where one may hide.

    Intervals [ua, ub] of one lofting-line segment (ua on the tip side) with both ends
    outside are bisected while e_a + e_b <= K * length (otherwise no point of the interval can
    be inside: the error changes by at most K per unit length), at most :data:`MAX_DIPS` at
    a time (those with the smallest e_a + e_b). Returns, per interval,
    whether an inside point was found and where (the tip-most one found).
    """
    n = len(ua)
    found = np.zeros(n, bool)
    u_in = np.zeros(n)
    e_in = np.zeros(n)
    idx = np.arange(n)
    a, b, fa, fb, sp = ua.copy(), ub.copy(), ea.copy(), eb.copy(), speed.copy()
    for _ in range(max_rounds):
        keep = (fa + fb <= lipschitz[idx] * np.abs(b - a) * sp) & ~found[idx]
        if not keep.any():
            break
        keep = np.flatnonzero(keep)
        if len(keep) > MAX_DIPS:  # a line grazing the surface: the nearest intervals only
            keep = keep[np.argsort(fa[keep] + fb[keep], kind="stable")[:MAX_DIPS]]
        idx, a, b, fa, fb, sp = idx[keep], a[keep], b[keep], fa[keep], fb[keep], sp[keep]
        mid = 0.5 * (a + b)
        rows = line_rows[idx]
        fm = _call(error, polyline_points(lines[idx], mid[:, None]), rows)[:, 0]
        neg = fm <= 0
        # Tip-most (largest u) inside point per interval.
        order = np.argsort(-mid[neg], kind="stable")
        hit_idx, hit_mid, hit_f = idx[neg][order], mid[neg][order], fm[neg][order]
        first = np.unique(hit_idx, return_index=True)[1]
        found[hit_idx[first]] = True
        u_in[hit_idx[first]] = hit_mid[first]
        e_in[hit_idx[first]] = hit_f[first]
        # Split the rest: [a, mid] (tip side) and [mid, b].
        rest = ~neg
        idx = np.concatenate([idx[rest], idx[rest]])
        a, b = np.concatenate([a[rest], mid[rest]]), np.concatenate([mid[rest], b[rest]])
        fa, fb = np.concatenate([fa[rest], fm[rest]]), np.concatenate([fm[rest], fb[rest]])
        sp = np.concatenate([sp[rest], sp[rest]])
    return found, u_in, e_in


def _brackets_screened(lines, error, u_low, lipschitz, samples_per_section, line_rows,
                       u_top=None):
    """Brackets from the section points plus dense samples only where a crossing may hide.

    The error changes by at most ``lipschitz`` per unit length along a line, so a segment of
    length l whose end errors are both positive with e_a + e_b > lipschitz * l cannot reach
    zero: it is skipped. The others are sampled densely, and any pair of outside samples that
    could still hide an inside point between them is bisected until it is proved outside or an
    inside point is found (a grazing double crossing is never missed). ``u_top`` (m,), if
    given, starts each search there instead of at the tip (knots beyond it collapse onto it).
    """
    m, n = lines.shape[:2]
    knots = np.concatenate([u_low[:, None], np.arange(n, dtype=float)[None, :].repeat(m, 0)],
                           axis=1)[:, ::-1]  # tip first, (m, n + 1)
    if u_top is not None:
        knots = np.minimum(knots, u_top[:, None])
    pts = polyline_points(lines, knots)
    e = _call(error, pts, line_rows)
    seg_len = np.linalg.norm(np.diff(pts, axis=1), axis=-1)  # (m, n)
    overall = getattr(lipschitz, "global_bound", None)
    if callable(lipschitz) and overall is not None:
        # The global bound clears most segments at once; local bounds only for the rest.
        bound = np.full(seg_len.shape, float(overall))
        near = (e[:, :-1] <= 0) | (e[:, 1:] <= 0) | (e[:, :-1] + e[:, 1:] <= bound * seg_len)
        if near.any():
            bound[near] = lipschitz(pts[:, :-1][near], pts[:, 1:][near])
    else:
        bound = _bound(lipschitz, pts[:, :-1], pts[:, 1:])
    maybe = (e[:, :-1] <= 0) | (e[:, 1:] <= 0) | (e[:, :-1] + e[:, 1:] <= bound * seg_len)
    rows, segs = np.nonzero(maybe)
    found = np.zeros(m, bool)
    a = np.zeros(m)
    b = np.zeros(m)
    fa = np.zeros(m)
    fb = np.zeros(m)
    n_cross = np.zeros(m, int)
    if rows.size == 0:
        return found, a, b, fa, fb, n_cross, e[:, 0]
    u0, u1 = knots[rows, segs], knots[rows, segs + 1]
    # As dense as the full scan: samples_per_section per unit of u on the longest candidate
    # (the inboard extension can span several sections).
    k = int(np.ceil(np.abs(u1 - u0).max() * samples_per_section)) + 1
    t = np.linspace(0.0, 1.0, max(k, 2))[None, :]
    grid = u0[:, None] + t * (u1 - u0)[:, None]  # (pairs, k), tip side first
    eg = _call(error, polyline_points(lines[rows], grid), line_rows[rows])
    # Pairs of outside samples that may hide an inside point: bisect them.
    du = np.abs(u1 - u0)
    speed = np.where(du > 0, seg_len[rows, segs] / np.where(du > 0, du, 1.0), 0.0)
    seg_bound = bound[rows, segs]  # the segment's bound holds on every piece of it
    suspect = (eg[:, :-1] > 0) & (eg[:, 1:] > 0) & (
        eg[:, :-1] + eg[:, 1:] <= seg_bound[:, None] * speed[:, None]
        * np.abs(np.diff(grid, axis=1)))
    # Only dips tip-ward of a pair-row's first sign change can change the answer.
    change = (eg[:, :-1] > 0) != (eg[:, 1:] > 0)
    first_change = np.where(change.any(axis=1), np.argmax(change, axis=1), change.shape[1])
    suspect &= np.arange(change.shape[1])[None, :] < first_change[:, None]
    pi, si = np.nonzero(suspect)
    if pi.size:
        ok, u_in, e_in = _refine_dips(lines[rows][pi], error, line_rows[rows][pi],
                                      grid[pi, si], grid[pi, si + 1], eg[pi, si],
                                      eg[pi, si + 1], speed[pi], seg_bound[pi])
        if ok.any():
            # Insert each inside point as an extra sample between its pair: widen the grid by
            # one column and place it in sorted (tip-first) position.
            extra_u = np.full(len(grid), np.nan)
            extra_e = np.full(len(grid), np.nan)
            pos = np.full(len(grid), -1)
            sel = np.flatnonzero(ok)
            # Keep the tip-most dip of each pair-row.
            first = np.unique(pi[sel], return_index=True)[1]
            pr, ps = pi[sel][first], si[sel][first]
            extra_u[pr], extra_e[pr], pos[pr] = u_in[sel][first], e_in[sel][first], ps
            cols = np.arange(grid.shape[1] + 1)[None, :]
            src = np.where((pos[:, None] >= 0) & (cols > pos[:, None] + 1), cols - 1, cols)
            src = np.minimum(src, grid.shape[1] - 1)
            g2 = np.take_along_axis(grid, src, 1)
            e2 = np.take_along_axis(eg, src, 1)
            ins = (pos[:, None] >= 0) & (cols == pos[:, None] + 1)
            g2 = np.where(ins, extra_u[:, None], g2)
            e2 = np.where(ins, extra_e[:, None], e2)
            # Rows without a dip got their last column duplicated: harmless (no sign change).
            grid, eg = g2, e2
    f_, a_, b_, fa_, fb_, nc_ = _first_entering(grid, eg)
    np.add.at(n_cross, rows, nc_)
    # Pairs come sorted by row then by segment from the tip: the first pair with a crossing in
    # each row is the first crossing reached coming inboard.
    hit = np.flatnonzero(f_)
    first_rows, first = np.unique(rows[hit], return_index=True)
    pick = hit[first]
    found[first_rows] = True
    a[first_rows], b[first_rows] = a_[pick], b_[pick]
    fa[first_rows], fb[first_rows] = fa_[pick], fb_[pick]
    return found, a, b, fa, fb, n_cross, e[:, 0]


def find_crossings(lines, error, u_low, samples_per_section=None, rtol=1e-13, max_iter=200,
                   lipschitz=None, hint=None, hint_width=0.05, atol=None, max_jumps=8):
    """Where each extended lofting line first meets a surface, coming inboard from the tip.

    Parameters
    ----------
    lines : (m, n, 3) float
        Lofting lines, root first.
    error : callable
        ``error(points (..., 3)) -> (...)``: negative inside the other surface, positive
        outside, zero on it (TM-4406 eq 6 for a circular body). If the function has an
        attribute ``row_aware = True`` it is called as ``error(points (k, j, 3), rows (k,))``
        with the line index of each row of points. An attribute
        ``value_and_gradient(points) -> (e, grad (..., 3))`` (row-aware likewise) makes the
        bracket closure a bracketed Newton iteration instead of Illinois regula falsi.
    u_low : (m,) float or float
        How far inboard to search (section coordinate, usually < 0: beyond the root).
    samples_per_section : int, optional
        Bracketing density in a segment that may hold a crossing: default 6 with a
        ``lipschitz`` bound (where the bisection of suspect intervals finds any grazing
        crossing) and 24 without (then two crossings closer than 1/24 of a section are
        seen as none, never mis-solved).
    rtol : float
        Relative tolerance on u (times max(1, |u|)).
    lipschitz : float or callable, optional
        A bound on |d error / d length| along a line, or ``bound(pa, pb)`` giving one per
        segment pa -> pb (with an attribute ``global_bound``, used first to clear segments).
        Given, only segments that may hold a crossing are sampled densely
        (exact screening, much faster); otherwise every segment.
    hint : (m,) float, optional
        Previous crossings (e.g. of the same wing on a slightly changed body). Where
        [hint - w, hint + w] brackets a crossing with the outboard end outside, it is used
        directly; the caller guarantees nothing changed outboard of it.
    atol : float, optional
        Largest |error| at a root [deck length]; default :func:`root_tolerance` of the lines
        (1e-9 of their bounding-box diagonal). A bracket that closes with a larger residual
        holds a jump of the error, not a root (see Notes).
    max_jumps : int
        How many jumps to step over on one line before calling it a miss.

    Returns
    -------
    Crossings

    Notes
    -----
    An intersection is a root of the surface equation, never a jump. The error functions
    are continuous on the surface's extent but jump at its edges: at an open end of a body
    (from the distance to the axis outside to a negative radial error inside), at a planform
    edge of a wing (TM-4607 eq 7 is only defined over the planform), at a step between two
    fuselage segments. A sign change across such a jump brackets no root; regula falsi and
    Newton still close the bracket onto the jump. So every closed bracket is judged by its
    residual: a continuous error closed to rtol in u is within about ``K * rtol * |segment|``
    of zero (K its Lipschitz bound), many orders below ``atol``, whatever the angle between
    line and surface (a grazing or tangent crossing has a smaller slope and so an even
    smaller residual), while a jump keeps the size of the jump on both sides. A bracket
    closing with residual above ``atol`` is a jump: the search resumes inboard of it, and a
    line whose every sign change is a jump misses (NaN, ``found`` False). Conversely an
    accepted point is within ``atol`` of the error's zero set, which is the surface: each
    error bounds the distance to the surface from above.
    """
    lines = np.asarray(lines, float)
    m, n = lines.shape[:2]
    if samples_per_section is None:
        samples_per_section = 24 if lipschitz is None else 6
    u_low = np.broadcast_to(np.asarray(u_low, float), (m,)).copy()
    atol = root_tolerance(lines) if atol is None else float(atol)
    newton = hasattr(error, "value_and_gradient")
    found = np.zeros(m, bool)
    hinted = np.zeros(m, bool)
    a, b, fa, fb = (np.zeros(m) for _ in range(4))
    n_cross = np.zeros(m, int)
    start_err = np.full(m, np.nan)
    if hint is not None:
        h = np.asarray(hint, float)
        ok_h = np.isfinite(h)
        hb = np.stack([np.where(ok_h, h + hint_width, 0.0), np.where(ok_h, h - hint_width, 0.0)],
                      axis=1)
        eh = _call(error, polyline_points(lines, hb), np.arange(m))
        hinted = ok_h & (eh[:, 0] > 0) & (eh[:, 1] <= 0)
        found[hinted], a[hinted], b[hinted] = True, hb[hinted, 0], hb[hinted, 1]
        fa[hinted], fb[hinted] = eh[hinted, 0], eh[hinted, 1]
        n_cross[hinted] = 1
    if not hinted.all():
        r = np.flatnonzero(~hinted)
        res = _brackets(lines, error, r, u_low[r], None, lipschitz, samples_per_section)
        found[r], a[r], b[r], fa[r], fb[r], n_cross[r], start_err[r] = res
    u = np.full(m, np.nan)
    residual = np.full(m, np.nan)
    grad = np.full((m, 3), np.nan) if newton else None
    jumps = np.zeros(m, int)
    iterations = 0
    act = found.copy()
    start = None if hint is None else np.where(found, np.asarray(hint, float), np.nan)
    for round_ in range(max_jumps + 1):
        todo = act.copy()
        for _ in range(_OUTER_ROUNDS):
            if not todo.any():
                break
            outer, f_outer = a.copy(), fa.copy()
            iterations += _close(lines, error, a, b, fa, fb, todo, rtol, max_iter, start,
                                 atol, u, residual, grad)
            start = None
            # A bracket can hold several sign changes (a root, a step's jump, another root)
            # and its closure reach an inner root: the first crossing from the tip is wanted.
            todo = _inner_root(lines, error, todo & (residual <= atol), outer, f_outer, u, a,
                               b, fa, fb)
        start = None
        # A bracket that closes off the surface is a jump of the error, not a root.
        jump = act & ~(residual <= atol)
        if not jump.any():
            break
        jumps += jump
        found[jump] = False
        if round_ == max_jumps:
            break
        # Search again inboard of each jump, from its inside end (a hint that led to a jump:
        # the whole line).
        r = np.flatnonzero(jump)
        top = np.where(hinted[r], n - 1.0, b[r])
        res = _brackets(lines, error, r, np.minimum(u_low[r], top), top, lipschitz,
                        samples_per_section)
        found[r], a[r], b[r], fa[r], fb[r] = res[:5]
        n_cross[r] = np.where(hinted[r], res[5], n_cross[r])
        hinted[r] = False
        act = np.zeros(m, bool)
        act[r] = res[0]
    u[~found] = np.nan
    residual[~found] = np.nan
    if grad is not None:
        grad[~found] = np.nan
    pts = polyline_points(lines, np.where(found, u, 0.0)[:, None])[:, 0]
    pts[~found] = np.nan
    return Crossings(u, pts, found, n_cross, iterations, residual, start_err, grad, jumps)


#: Times a bracket is narrowed to an outer crossing it holds (:func:`_inner_root`).
_OUTER_ROUNDS = 4
#: Points between a root and its bracket's outer end where the error's sign is checked.
_OUTER_SAMPLES = 16


def _inner_root(lines, error, rows, outer, f_outer, u, a, b, fa, fb):
    """Of the lines ``rows`` (bool) closed at a root u of the bracket whose outside end was
    ``outer``, those with a point inside the surface between u and ``outer``: the root is
    not the first from the tip. Their brackets become [outer, the outermost such point]
    (in place); returns them (bool) to be closed again."""
    r = np.flatnonzero(rows)
    if not r.size:
        return rows
    k = np.arange(1, _OUTER_SAMPLES + 1) / (_OUTER_SAMPLES + 1)
    us = outer[r, None] - k[None, :] * (outer[r] - u[r])[:, None]  # from outer inwards
    e = _call(error, polyline_points(lines[r], us), r)
    inside = e <= 0
    hit = inside.any(axis=1)
    first = np.argmax(inside, axis=1)
    again = np.zeros_like(rows)
    sel = r[hit]
    again[sel] = True
    a[sel], fa[sel] = outer[sel], f_outer[sel]
    b[sel], fb[sel] = us[hit, first[hit]], e[hit, first[hit]]
    return again


def root_tolerance(*point_sets):
    """Largest |error| at a root: 1e-9 of the bounding-box diagonal of the points [length].

    ``point_sets``: arrays (..., 3), e.g. the lofting lines and the other component's points.
    """
    pts = np.concatenate([np.asarray(p, float).reshape(-1, 3) for p in point_sets])
    pts = pts[np.isfinite(pts).all(axis=1)]
    size = float(np.linalg.norm(np.ptp(pts, axis=0))) if len(pts) else 1.0
    return 1e-9 * (size if size > 0 else 1.0)


def _brackets(lines, error, r, u_low, u_top, lipschitz, samples_per_section):
    """First outside -> inside bracket of lines ``r`` coming inboard from u_top (or the tip)."""
    if lipschitz is None:
        return _brackets_dense(lines[r], error, u_low, samples_per_section, r, u_top)
    return _brackets_screened(lines[r], error, u_low, lipschitz, samples_per_section, r,
                              u_top)


def _close(lines, error, a, b, fa, fb, act, rtol, max_iter, start, atol, u, residual, grad):
    """Close the brackets of the lines ``act`` and measure the error there, in place.

    Bracketed Newton when the error has a gradient, else Illinois regula falsi. A Newton
    result whose residual exceeds ``atol`` is closed again by Illinois in its final bracket
    (a root of a continuous error is then reached to rtol; a jump stays one). Writes u,
    residual |e(u)| and the gradient (if any) of those lines, and the final brackets into
    a, b, fa, fb. Returns the iterations used.
    """
    rows = np.flatnonzero(act)
    it = 0
    polish = rows
    if grad is not None:
        un, _, it = _newton(lines, error, a, b, fa, fb, act.copy(), rtol, max_iter, start)
        p = polyline_points(lines[rows], un[rows, None])[:, 0]
        e, g = _call_gradient(error, p, rows)
        u[rows], residual[rows], grad[rows] = un[rows], np.abs(e), g
        polish = rows[~(np.abs(e) <= atol)]
    if polish.size:
        sub = np.zeros(len(a), bool)
        sub[polish] = True
        a2, b2, fa2, fb2, it2 = _illinois(lines, error, a, b, fa, fb, sub, rtol, max_iter)
        a[polish], b[polish], fa[polish], fb[polish] = (
            v[polish] for v in (a2, b2, fa2, fb2))
        it += it2
        # The end with the smaller residual (both are within rtol in u).
        up = np.where(np.abs(fa[polish]) < np.abs(fb[polish]), a[polish], b[polish])
        p = polyline_points(lines[polish], up[:, None])[:, 0]
        if grad is not None:
            e, g = _call_gradient(error, p, polish)
            grad[polish] = g
        else:
            e = _call(error, p[:, None], polish)[:, 0]
        u[polish], residual[polish] = up, np.abs(e)
    return it


def _bound(lipschitz, pa, pb):
    """Lipschitz bound per segment pa -> pb: a constant, or a callable local bound."""
    if callable(lipschitz):
        return np.asarray(lipschitz(pa, pb), float)
    return np.full(pa.shape[:-1], float(lipschitz))


def _call(error, points, rows):
    """Evaluate ``error`` on points of the given lines (row-aware functions get the rows)."""
    if getattr(error, "row_aware", False):
        return error(points, rows)
    return error(points)


def _call_gradient(error, points, rows):
    """``error.value_and_gradient`` on points (k, 3) of lines ``rows`` (k,)."""
    if getattr(error, "row_aware", False):
        return error.value_and_gradient(points, rows)
    return error.value_and_gradient(points)
