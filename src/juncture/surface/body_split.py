"""The fuselage as upper and lower surfaces split by the bounding curve theta_b(x) (TM-4607).

From the nose, theta_b varies linearly from 0 to its value at the first region's leading
edge; in the canard, wing and tail regions it follows the upper (for the upper surface) or
lower (for the lower surface) intersection line of that component; between regions it varies
linearly from one region's trailing-edge value to the next region's leading-edge value, and
after the last region back to 0 at the end of the fuselage. Upper-surface points are spaced
equally from theta = pi/2 down to theta_b, except where a fin stands on the fuselage: there
they begin at the fin's intersection angle. Lower-surface points run from -pi/2 up to the
lower bounding curve. Stations: the body's own plus every intersection point's x, so each
network boundary passes exactly through the intersection points it meets. A wing boundary
given with its points ends each row exactly there; where the point is off the body (a lofting
line that misses it, :mod:`juncture.misses`) and the wing covers that side, the row is empty
(every point that point) and the body stations next to it are left out.
"""

from __future__ import annotations

import numpy as np

from .networks import body_range, orient, radial_outward
from .overlap_blocks import find_overlap, middle_block, outside_regions, switch_points

__all__ = ["Boundary", "bounding_curve", "boundary_from_points", "footprint_chains", "forward",
           "split_body", "seam_gap", "polyline_gap"]


class Boundary:
    """A curve on the body given by stations x and angles theta (sorted in x).

    ``points`` (k, 3), optional: the curve's exact points. The network rows at its stations
    end there; a point off the body is where a wing line that misses the body ends
    (:mod:`juncture.misses`), and where its angle is the top (bottom) the row of the upper
    (lower) surface is empty: every point of it is that point.

    ``exact(x)``, optional: (k, 3) the curve's exact points at stations x (NaN where it has
    none; :func:`juncture.intersect.stations.plane_points`). Body stations between the
    curve's points then end there (:func:`split_body`) instead of at the angle interpolated
    between its points.
    """

    def __init__(self, x, theta, name="", points=None, exact=None):
        order = np.argsort(x, kind="stable")
        self.x = np.asarray(x, float)[order]
        self.theta = np.asarray(theta, float)[order]
        self.name = name
        self.points = None if points is None else np.asarray(points, float)[order]
        self.exact = exact

    def at(self, x):
        """Angle at stations x (linear between the boundary's points)."""
        return np.interp(x, self.x, self.theta)


def boundary_from_points(body, points, name="", exact=None, theta=None):
    """A Boundary through points lying on ``body`` (NaN rows skipped), at their body angles
    or at the angles ``theta`` given (a point off the body: the top's or bottom's)."""
    from ..intersect.body import _body_angle

    ok = np.all(np.isfinite(points), axis=1)
    theta = _body_angle(body, points[ok]) if theta is None else np.asarray(theta)[ok]
    return Boundary(points[ok, 0], theta, name, points[ok], exact)


def _at_stations(body, region, xs):
    """``region`` with its exact points (``region.exact``) at the stations ``xs`` that lie
    between its first and last points, where it has them."""
    from ..intersect.body import _body_angle

    if region.exact is None or region.points is None or region.x.size < 2:
        return region
    inner = np.setdiff1d(xs[(xs > region.x[0]) & (xs < region.x[-1])], region.x)
    if not inner.size:
        return region
    pts = region.exact(inner)
    good = np.all(np.isfinite(pts), axis=1)
    if not good.any():
        return region
    return Boundary(np.concatenate([region.x, inner[good]]),
                    np.concatenate([region.theta, _body_angle(body, pts[good])]),
                    region.name, np.concatenate([region.points, pts[good]]), region.exact)


#: Between regions a block's bounding curve turns by at most 1 / TURNS of the half
#: section's parameter range from one station to the next (stations are added where it
#: would turn more: :func:`_turning`); 5.6 deg on a circular body.
TURNS = 32


def forward(x):
    """(k,) bool: the points of a line (in its order) whose x lies beyond every earlier
    kept point's. The network rows are at constant x, so a block's boundary cannot follow
    a line back in x (a wing root's second point ahead of its leading-edge point): such a
    point stays on the wing's root line only, and the small loop it leaves between the
    wing and the fuselage is capped (where only one line turns back, at the leading edge,
    :func:`footprint_chains` does better). NaN is never kept."""
    x = np.asarray(x, float)
    keep = np.zeros(x.size, bool)
    top = -np.inf
    for i, xi in enumerate(x):
        if np.isfinite(xi) and xi > top:
            keep[i], top = True, xi
    return keep


def _runs(x):
    """(ks, ke) of a line whose points 0..ks run forward to its foremost point ks, ks..ke
    aft to its aftmost point ke and ke..end forward again (ks = 0, ke = last where it only
    runs aft), or None (NaN, or the aftmost point ahead of the foremost). A run may wiggle:
    :func:`_aft` leaves out its points that turn back."""
    if x.size < 2 or not np.all(np.isfinite(x)):
        return None
    ks, ke = int(np.argmin(x)), int(np.argmax(x))
    return (ks, ke) if ks < ke else None


def _aft(line, side, idx, keep_last=False):
    """The (side, index) pairs of a run of ``line``'s points ``idx`` (taken aft) whose x
    lies beyond every earlier one's (:func:`forward`), or with ``keep_last`` below every
    later one's, so that the run's last point (the leading-edge point the two lines share)
    stays: a point that turns back (a line running aft by 0.05 ft from its leading-edge
    point before it turns forward) stays on the wing's root line only, and the small loop
    it leaves between the wing and the fuselage is capped."""
    x = line[idx, 0]
    keep = forward(-x[::-1])[::-1] if keep_last else forward(x)
    return [(side, int(i)) for i in np.asarray(idx)[keep]]


def footprint_chains(upper, lower):
    """(upper chain, lower chain) of a region's two lines (each (n, 3), leading edge first)
    where one of them turns back at an end, else None. Each chain is a list of (side,
    index) pairs (side 0: ``upper``, 1: ``lower``) running aft.

    Rows are at constant x, so a block's boundary must run aft (:func:`forward`). A line can
    run forward from the leading-edge point before it turns aft (the upper intersection of
    a high, swept wing on a large fuselage bulges forward and up; a line continued to the
    plane of symmetry lies ahead of it), or run aft of the trailing-edge point before it
    comes back to it. At those stations the region lies between two points of that one line
    (theta_b is the footprint's lower and upper crossing at each station): that run, taken
    aft, is the other block's boundary ahead of (after) that block's own line. None also
    where both lines turn back at the same end or a chain would not run aft.
    """
    lines = (np.asarray(upper, float), np.asarray(lower, float))
    runs = [_runs(line[:, 0]) for line in lines]
    if runs[0] is None or runs[1] is None:
        return None
    last = [len(line) - 1 for line in lines]
    ahead = [r[0] > 0 for r in runs]
    behind = [r[1] < n for r, n in zip(runs, last)]
    if not (any(ahead) or any(behind)) or all(ahead) or all(behind):
        return None
    chains = []
    for s in (0, 1):
        o = 1 - s
        ks, ke = runs[s]
        chain = _aft(lines[s], s, np.arange(ks, ke + 1))
        if ahead[o]:   # the other line's forward run, aft to the shared leading edge
            if np.array_equal(lines[o][0], lines[s][0]):
                chain = chain[1:]
            chain = _aft(lines[o], o, np.arange(runs[o][0], -1, -1), keep_last=True) + chain
        if behind[o]:  # from the shared trailing edge, the other line's aft run taken aft
            run = _aft(lines[o], o, np.arange(last[o], runs[o][1] - 1, -1))
            if np.array_equal(lines[o][-1], lines[s][-1]):
                run = run[1:]
            chain = chain + run
        x = np.array([lines[t][i, 0] for t, i in chain])
        if not np.all(np.diff(x) > 0.0):
            return None
        chains.append(chain)
    return tuple(chains)


def bounding_curve(x, regions, x_nose, x_end, side=0.0):
    """theta_b at stations x from region boundaries (each a Boundary), ``side`` at both ends
    (the horizontal: theta = 0, or arc length 0.5 on an arbitrary-section body)."""
    xs, ths = [x_nose], [side]
    for reg in sorted((r for r in regions if r.x.size), key=lambda r: r.x[0]):
        xs.extend(reg.x)
        ths.extend(reg.theta)
    xs.append(x_end)
    ths.append(side)
    xs, ths = np.asarray(xs), np.asarray(ths)
    order = np.argsort(xs, kind="stable")
    return np.interp(x, xs[order], ths[order])


def split_body(body, upper_regions, lower_regions, fins=(), n_upper=10, n_lower=10,
               stations=None):
    """Upper and lower fuselage networks split by theta_b (TM-4607).

    Parameters
    ----------
    body : CircularBody
    upper_regions, lower_regions : list of Boundary
        Upper and lower intersection (or fillet start) curves of the canard, wing and tail.
    fins : list of Boundary
        Outboard intersection curves of fins standing on the body (the upper surface starts
        there instead of at pi/2).
    n_upper, n_lower : int
        Points per cross-section of each network.
    stations : (k,) float, optional
        Body stations to use besides the intersection points' (default: all the body's).

    Returns
    -------
    dict with "body upper" and "body lower" networks (n_stations, n_points, 3), and
    "body middle" where two regions overlap in x one above the other
    (:mod:`juncture.surface.overlap_blocks`)
    """
    xg = body.x_global if stations is None else np.asarray(stations, float)
    x_nose, x_end = float(body.x_global[0]), float(body.x_global[-1])
    bottom, top_value, side = body_range(body)
    upper_regions, lower_regions = _shared_ends(upper_regions, lower_regions,
                                                (bottom, top_value))
    # Outside every region the two blocks end on one line (theta_b from the same ends), so
    # each takes the other's stations there: else a fin's stations on the upper block put
    # points on that line the lower block does not have (an open seam between them).
    spans = [(r.x[0], r.x[-1]) for r in (*upper_regions, *lower_regions) if r.x.size]
    regions = (upper_regions, lower_regions)
    overlap = find_overlap(*regions)
    if overlap is not None:  # two regions over the same stations: a middle block
        upper_regions, lower_regions = outside_regions(overlap, *regions)
    xu = np.unique(np.concatenate([_kept(xg, upper_regions, top_value)]
                                  + [r.x for r in upper_regions] + [f.x for f in fins]))
    xl = np.unique(np.concatenate([_kept(xg, lower_regions, bottom)]
                                  + [r.x for r in lower_regions]))
    xu, xl = _shared_stations(xu, xl, spans)
    turn = (top_value - bottom) / TURNS
    more = np.concatenate([
        _turning(xu, bounding_curve(xu, upper_regions, x_nose, x_end, side), spans, turn,
                 SLIVER * (x_end - x_nose)),
        _turning(xl, bounding_curve(xl, lower_regions, x_nose, x_end, side), spans, turn,
                 SLIVER * (x_end - x_nose))])
    xu, xl = np.union1d(xu, more), np.union1d(xl, more)
    if overlap is not None:
        upper_regions, lower_regions, ends = switch_points(body, overlap, regions,
                                                           upper_regions, lower_regions, xu, xl)
    upper_regions = [_at_stations(body, r, xu) for r in upper_regions]
    lower_regions = [_at_stations(body, r, xl) for r in lower_regions]
    fins = [_at_stations(body, f, xu) for f in fins]
    th_u = bounding_curve(xu, upper_regions, x_nose, x_end, side)
    th_l = _one_curve(xl, bounding_curve(xl, lower_regions, x_nose, x_end, side), xu, th_u,
                      spans)
    top = np.full(xu.size, top_value)
    for fin in fins:
        inside = (xu >= fin.x[0]) & (xu <= fin.x[-1])
        top[inside] = np.minimum(top[inside], fin.at(xu[inside]))
    t_u = np.linspace(0.0, 1.0, int(n_upper))
    t_l = np.linspace(0.0, 1.0, int(n_lower))
    ang_u = top[:, None] + t_u[None, :] * (th_u - top)[:, None]
    ang_l = bottom + t_l[None, :] * (th_l - bottom)[:, None]
    # The rows end exactly at theta_b (not at top + 1.0 * (theta_b - top), a bit off), so
    # where the upper and lower bounding curves meet the two blocks share the point.
    ang_u[:, -1], ang_l[:, -1] = th_u, th_l
    ang_u, ang_l = through_corners(body, xu, ang_u), through_corners(body, xl, ang_l)
    up = body.point(xu[:, None], ang_u)
    lo = body.point(xl[:, None], ang_l)
    _whole_rows(body, up, xu, ang_u, upper_regions, bottom)
    _whole_rows(body, lo, xl, ang_l, lower_regions, top_value)
    _close_rows(up, xu, SLIVER * (x_end - x_nose), ang_u)
    _close_rows(lo, xl, SLIVER * (x_end - x_nose), ang_l)
    _end_at_points(up, xu, upper_regions, top_value)
    _end_at_points(lo, xl, lower_regions, bottom)
    for fin in fins:  # rows at a fin's stations start exactly at its points
        _end_at_points(up[:, ::-1], xu, [fin], None)
    passing = _passing_ends(upper_regions, lower_regions, bottom, top_value)
    up = _beyond_rows(body, up, xu, upper_regions, passing, top_value)
    lo = _beyond_rows(body, lo, xl, lower_regions, passing, bottom)
    radial = radial_outward(body)
    nets = {"body upper": orient(up, radial), "body lower": orient(lo, radial)}
    if overlap is not None:
        m0, m1 = overlap.m0, overlap.m1
        inner = np.unique(np.concatenate(
            [xg[(xg >= m0) & (xg <= m1)], [m0, m1]]
            + [r.x[(r.x >= m0) & (r.x <= m1)] for r in (regions[1][overlap.high],
                                                        regions[0][overlap.low])]))
        n_middle = max(3, int(n_upper + n_lower) // 3)
        nets["body middle"] = orient(middle_block(body, overlap, *regions, inner, n_middle,
                                                  ends), radial)
    return nets


#: A row nearer the one before than this share of the body's length takes that row's points
#: but its end (:func:`_close_rows`).
SLIVER = 1e-4


def _close_rows(net, x, gap, ang=None):
    """Rows of ``net`` at stations ``x`` less than ``gap`` after the row before take its
    points but the last (the end on the bounding curve, set apart by :func:`_end_at_points`),
    so the quads between them fall away and only the triangle to the new end is left. A
    blunt trailing edge whose upper and lower edges meet the body 1.7e-5 ft apart in x gives
    one block a row at each (:func:`_shared_ends`): two rows a rounding apart, whose points
    on the plane of symmetry stayed mesh vertices (triangles of 1e-3 deg).

    With the rows' angles ``ang`` (surface parameters), a row whose end lies back among the
    points it would take (a tail's leading edge 0.004 ft aft of a row ending at the wing's
    root below it) keeps its own points: taking the others', it ran down past its end and
    back up to it, folded over the block beside it."""
    eff = None if ang is None else np.array(ang, float)
    for i in np.flatnonzero(np.diff(x) < gap) + 1:   # in order: a run takes the first row's
        if eff is not None:
            way = eff[i - 1, -2] - eff[i - 1, 0]
            if (eff[i, -1] - eff[i - 1, -2]) * way < 0.0:
                continue
            eff[i, :-1] = eff[i - 1, :-1]
        net[i, :-1] = net[i - 1, :-1]


def _one_curve(xl, th_l, xu, th_u, spans):
    """The lower bounding curve ``th_l`` taking the upper's angles at the stations both have
    outside every span: there the two blocks end on one line. They do by construction
    where a region's two curves end at one point (:func:`_shared_ends`); where they end at
    one station at two points (a blunt trailing edge at the wing's root section, its base
    in the plane of a body station), the two curves ran on from the two points to the body's
    end, and the body between them, a sliver as long as the fuselage behind the wing,
    belonged to neither block (it was capped flat: a held-out airplane's 44 ft cap, 0.02 ft
    wide). Now the triangle between the two points and the next station is filled by one
    side's seam (:func:`juncture.surface.seams.split_seams`) or capped."""
    k = np.minimum(np.searchsorted(xu, xl), xu.size - 1)
    same = _outside(xl, spans) & (xu[k] == xl)
    th_l = th_l.copy()
    th_l[same] = th_u[k[same]]
    return th_l


def _shared_ends(uppers, lowers, fars):
    """Upper and lower regions (the same components, in the same order) whose ends are
    shared: where a region's upper and lower curves end at different points (a blunt
    trailing edge, a fillet's two start lines), the side that ends first is extended to the
    other side's end point, and likewise at the leading edge.

    Between regions both blocks then follow one bounding curve from one point (else the
    body between two curves from the two points belongs to neither block), and the body
    between the two end points belongs to the block that was extended. Points off the body
    (a lofting line that misses it: an angle at the top or bottom) are left alone.
    """
    if len(uppers) != len(lowers):
        return uppers, lowers
    up_out, lo_out = [], []
    for up, lo in zip(uppers, lowers):
        if up.points is None or lo.points is None or not up.x.size or not lo.x.size:
            up_out.append(up)
            lo_out.append(lo)
            continue
        for end in (0, -1):
            on = [min(abs(r.theta[end] - f) for f in fars) > 1e-12 for r in (up, lo)]
            if not all(on) or np.array_equal(up.points[end], lo.points[end]):
                continue
            first, other = (up, lo) if (up.x[end] < lo.x[end]) == (end == -1) else (lo, up)
            if up.x[end] == lo.x[end]:
                continue  # the same station: the row ends at one point only (left alone)
            extended = _with_point(first, other, end)
            up, lo = (extended, lo) if first is up else (up, extended)
        up_out.append(up)
        lo_out.append(lo)
    return up_out, lo_out


def _with_point(region, other, end):
    """``region`` with ``other``'s first (end 0) or last (end -1) point added."""
    pick = slice(0, 1) if end == 0 else slice(-1, None)
    return Boundary(np.concatenate([region.x, other.x[pick]]),
                    np.concatenate([region.theta, other.theta[pick]]), region.name,
                    np.concatenate([region.points, other.points[pick]]), region.exact)


#: A corner nearer a row's end than this share of its mean step stays off the row.
NEAR_END = 0.25


def through_corners(body, x, par):
    """Rows of surface parameters ``par`` (k, n) at stations ``x`` through the corners of
    the sections there (:meth:`~juncture.model.body.ArbitraryBody.corners`; a circular body
    has none) between each row's ends: each corner takes an inner point of its own, in
    order and as near as the others leave room for (:func:`_anchors`), and the points
    between stay where they can. The rows keep the polygon of an arbitrary section. A corner
    within :data:`NEAR_END` of a step of a row's end is left out (a corner at 0.499997 of a
    row ending at the side, 0.5, made a piece of a millionth and 2 deg triangles in the
    base's cap)."""
    corners = getattr(body, "corners", None)
    if corners is None or par.shape[1] < 3:
        return par
    out = np.array(par, float)
    for i, xi in enumerate(np.asarray(x, float).tolist()):
        row = out[i]
        lo, hi = min(row[0], row[-1]), max(row[0], row[-1])
        gap = NEAR_END * (hi - lo) / (row.size - 1)
        c = corners(xi)
        c = np.sort(c[(c > lo + gap) & (c < hi - gap)])
        if c.size > 1:  # one corner on each side of a joint: the two a hair apart, once
            c = c[np.r_[True, np.diff(c) > gap]]
        if row[-1] < row[0]:
            c = c[::-1]
        if c.size:
            out[i] = _anchors(row, c)
    return out


def _anchors(row, c):
    """``row`` (n,) with as many of the values ``c`` (in the row's order) as it has inner
    points taken by distinct inner points, in order, each the nearest one the corners after
    it leave free; the other points stay (the columns run on straight from the rows before
    and after), or are spread evenly between where they would fall out of order."""
    n = row.size
    c = c[:n - 2]
    idx, at = [0], 0
    for k, v in enumerate(c):
        window = np.arange(at + 1, n - 1 - (c.size - 1 - k))
        at = int(window[np.argmin(np.abs(row[window] - v))])
        idx.append(at)
    idx.append(n - 1)
    moved = row.copy()
    moved[idx[1:-1]] = c
    step = np.diff(moved)
    if np.all(step > 0.0) or np.all(step < 0.0):
        return moved
    return np.interp(np.arange(n), idx, np.concatenate([[row[0]], c, [row[-1]]]))


def _turning(x, theta, spans, turn, gap=0.0):
    """Stations to add between consecutive stations ``x`` outside every span where the
    bounding curve ``theta`` turns by more than ``turn``: equal steps, each turning at most
    that much, but none shorter than ``gap``. Between a wing's trailing edge and the next
    station the curve can run from the wing's root to the keel, and every row's points,
    spread between the top and the curve, twist round the body with it: the straight lines
    between two rows then cut through the body (11 % of an arbitrary body's section lost
    mid-interval). Rows nearer than ``gap`` are closed onto the row before
    (:func:`_close_rows`): between a body station and a low wing's leading edge 0.09 ft aft
    of it, seven such rows made both blocks fans to the steep curve, the lower one folded
    back over the upper (a held-out airplane's 78 crossing triangle pairs)."""
    h = np.diff(x)
    mid = x[:-1] + 0.5 * h
    steps = np.ceil(np.abs(np.diff(theta)) / turn).astype(int)
    if gap > 0.0:
        steps = np.maximum(np.minimum(steps, np.floor(h / (gap * (1 + 1e-9))).astype(int)), 1)
    steps[~_outside(mid, spans) | (h <= 0.0)] = 1
    out = [x[i] + h[i] * np.arange(1, k) / k for i, k in enumerate(steps) if k > 1]
    return np.concatenate(out) if out else np.zeros(0)


def _outside(x, spans):
    """(k,) bool: the stations x that lie outside every span (lo, hi)."""
    out = np.ones(x.size, bool)
    for lo, hi in spans:
        out &= (x < lo) | (x > hi)
    return out


def _shared_stations(xu, xl, spans):
    """Upper and lower stations, each with the other's that lie outside every span."""
    return (np.union1d(xu, xl[_outside(xl, spans)]),
            np.union1d(xl, xu[_outside(xu, spans)]))


def _empty(region, far):
    """Stations of a region whose row is empty (the angle at the arc's far end)."""
    return np.abs(region.theta - far) <= 1e-12


def _kept(xg, regions, far):
    """Body stations that do not fall between a region's stations next to an empty row.

    Between a station where the wing covers that side of the body (an empty row, at a
    point off the body) and its neighbours the network joins the rows directly, as the
    juncture blocks do: a body station there would add panels from the body to that point.
    """
    keep = np.ones(xg.size, bool)
    for reg in regions:
        if reg.points is None or reg.x.size < 2:
            continue
        e = _empty(reg, far)
        for i in np.flatnonzero(e[:-1] | e[1:]):
            keep &= ~((xg > reg.x[i]) & (xg < reg.x[i + 1]))
    return xg[keep]


def _rows_at(xs, x):
    """(rows, ok): where stations ``x`` fall in the sorted stations ``xs``, and which of them
    are among them exactly."""
    rows = np.searchsorted(xs, x)
    return rows, (rows < xs.size) & (xs[np.minimum(rows, xs.size - 1)] == x)


def _end_at_points(net, xs, regions, far):
    """Rows at a region's stations end at its points; empty rows (at angle ``far``; none
    when it is None) are all that point."""
    for reg in regions:
        if reg.points is None:
            continue
        rows, ok = _rows_at(xs, reg.x)
        rows, pts = rows[ok], reg.points[ok]
        net[rows, -1] = pts
        if far is not None:
            e = _empty(reg, far)[ok]
            net[rows[e]] = pts[e][:, None, :]


def _whole_rows(body, net, xs, ang, regions, near):
    """Rows that cover the whole half-section (a region's point at the angle ``near``, the
    far side's: the wing passes on the other side of the body at that station, its point off
    the body, :mod:`juncture.misses`) keep the body's own end on the plane of symmetry
    before that point (set last by :func:`_end_at_points`): the body arc on all but the last
    point (``net`` and the angles ``ang`` in place). Overwriting the arc's end with the point
    made a slanted panel from the body's last inner point to it, which the mirror image
    doubled (a tail passing under a tail cone at two stations: the edge between its two end
    points in four triangles); the panel between the end and the point lies in the plane of
    symmetry, where the mirror image's cancels it (:func:`juncture.surface.assemble.assemble`).
    """
    n = net.shape[1]
    if n < 3:
        return
    for reg in regions:
        if reg.points is None:
            continue
        rows, ok = _rows_at(xs, reg.x)
        for r in rows[ok & _empty(reg, near)]:
            par = np.linspace(ang[r, 0], ang[r, -1], n - 1)[None, :]
            par = through_corners(body, xs[r:r + 1], par)
            ang[r, :-1] = par[0]
            net[r, :-1] = body.point(np.full(par.shape, xs[r]), par)[0]


def _passing_ends(uppers, lowers, bottom, top):
    """{(region index, 0 or -1)}: the first or last stations of regions (upper and lower
    curves of one component, index-aligned) at which both of its surfaces pass on one side
    of the body (both lines miss it there, :mod:`juncture.misses`: the upper and lower
    curves' points off the body, both at the angle of its top or both at its bottom)."""
    out = set()
    for k, (u, lo) in enumerate(zip(uppers, lowers)):
        if u.points is None or lo.points is None or not u.x.size or not lo.x.size:
            continue
        for end in (0, -1):
            a, b = u.theta[end], lo.theta[end]
            if a == b and any(abs(a - v) <= 1e-12 for v in (bottom, top)):
                out.add((k, end))
    return out


def _beyond_rows(body, net, xs, regions, passing, far):
    """``net`` with a second row at each of the ``passing`` ends of its regions, on the side
    away from the region: the same station with the body's own points only (the region's
    point off the body left out: an empty row is the body's point at the block's far angle
    ``far``, a whole row (:func:`_whole_rows`) ends twice at its arc's end). The wing passes
    the body there without touching it; its end point is joined to the body's rows on the
    region's side only (and in the plane of symmetry, where the mirror image cancels the
    panels). Joined on both sides, the rows beyond fanned to it as well: the mirrored
    surface touched itself at that point (a tail's trailing edge under a tail cone: a vertex
    in two fans) or along the edge to it (a high wing's trailing edge over the fuselage's
    top: an edge in four triangles)."""
    add = []
    for k, end in sorted(passing):
        reg = regions[k] if k < len(regions) else None
        if reg is None or reg.points is None or not reg.x.size:
            continue
        rows, ok = _rows_at(xs, reg.x[end:][:1])
        if not ok[0]:
            continue
        r = int(rows[0])
        row = np.array(net[r])
        if _empty(reg, far)[end]:
            row[:] = body.point(np.full(1, xs[r]), np.full(1, far))[0]
        else:
            row[-1] = row[-2]
        add.append((r + (end == -1), row))
    for r, row in sorted(add, key=lambda a: -a[0]):
        net = np.insert(net, r, row, axis=0)
    return net


def seam_gap(points, net):
    """Largest distance from ``points`` (k, 3) to the nearest boundary point of ``net``."""
    edges = np.concatenate([net[0], net[-1], net[:, 0], net[:, -1]])
    ok = np.all(np.isfinite(points), axis=1)
    if not ok.any():
        return 0.0
    d = np.linalg.norm(points[ok, None, :] - edges[None, :, :], axis=-1).min(axis=1)
    return float(d.max())


def polyline_gap(points, net):
    """Largest distance from ``points`` (k, 3) to the nearest n-line polyline of ``net``."""
    ok = np.all(np.isfinite(points), axis=1)
    p = points[ok][:, None, None, :]
    a, b = net[None, :, :-1], net[None, :, 1:]
    d = b - a
    t = np.clip(((p - a) * d).sum(-1) / np.maximum((d * d).sum(-1), 1e-300), 0.0, 1.0)
    dist = np.linalg.norm(p - a - t[..., None] * d, axis=-1)
    return float(dist.min(axis=(1, 2)).max()) if ok.any() else 0.0
