"""Two regions over the same fuselage stations: a middle block between them.

TM-4607 splits the fuselage into an upper block (from the top down to the upper bounding
curve) and a lower block (from the bottom up to the lower one), one region (canard, wing,
tail) after another along the body. A close-coupled canard whose trailing edge lies behind
the wing's root leading edge, or a tail whose root starts ahead of the wing's trailing edge,
puts two regions over the same stations: there the section has three exposed arcs, above
the higher region, between the two, and below the lower one.

For two regions F (starting first) and G whose roots overlap in x over [m0, m1] (G's
leading edge to F's trailing edge; G ending after F), the higher region H and the lower Lr:

- the upper block follows H's upper curve over the whole of H and Lr's upper curve only
  outside [m0, m1]; the lower block Lr's lower curve over all of Lr and H's lower curve only
  outside [m0, m1];
- the middle block has a row at every station in [m0, m1] from H's lower curve down to Lr's
  upper curve;
- where a block passes from one region to the other (the upper block at m0 when G is the
  higher, at m1 when F is; the lower block likewise) its neighbouring row ends on the first
  region's curve on one side and on the second's on the other. The triangle of body between
  (the second region's edge, the first's curve and the block's panel edge) is closed by one
  degenerate row of the middle block: at that neighbouring station, every point the block's
  row end, so the middle block's panels fan from it across to the arc at m0 (m1).

Where G lies inside F's range (a canard whose root runs over the wing's, above it), [m0, m1]
is G's range: the block on G's side follows F's curve outside it and G's inside, passing
twice (a degenerate row of the middle block at each of its stations next to m0 and m1);
the other block follows F's other curve throughout, and the middle block runs from G's
curve facing F to F's curve facing G.

Every row end is a point of a region (its own intersection points, or the exact plane
point at a body station, :func:`juncture.intersect.stations.plane_points`, where the region
has one), so the seams close by vertex ids as elsewhere. Two regions at one height over
the same stations and more than two regions over one station are left to the caller's
refusal (:func:`juncture.surface.pipeline.overlapping_regions`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["Overlap", "find_overlap", "restricted", "curve_at", "middle_block",
           "outside_regions", "switch_points"]


class Overlap(NamedTuple):
    high: int        # index of the higher region (in the aligned upper / lower lists)
    low: int         # index of the lower region
    first: int       # index of the region that starts first (F)
    m0: float        # G's leading edge
    m1: float        # F's trailing edge (G's, when G lies inside F's range)
    nested: bool = False   # G starts and ends inside F's range


def _span(up, lo):
    xs = np.concatenate([up.x, lo.x])
    return float(xs.min()), float(xs.max())


def find_overlap(uppers, lowers):
    """The one staggered overlap of two regions (aligned lists: uppers[i] and lowers[i] are
    one component), or None: none, several, a nested pair, or regions whose curves do not
    lie one above the other over the overlap."""
    if len(uppers) != len(lowers):
        return None
    spans = [_span(u, lo) if u.x.size and lo.x.size else None
             for u, lo in zip(uppers, lowers)]
    found = []
    for i in range(len(spans)):
        for j in range(i + 1, len(spans)):
            if spans[i] is None or spans[j] is None:
                continue
            (a0, a1), (b0, b1) = spans[i], spans[j]
            if a0 < b1 and b0 < a1:
                found.append((i, j) if a0 <= b0 else (j, i))
    if len(found) != 1:
        return None
    f, g = found[0]
    (f0, f1), (g0, g1) = spans[f], spans[g]
    nested = f0 < g0 < g1 < f1
    if not (f0 < g0 < f1 < g1 or nested):
        return None                                     # sharing an end
    m0, m1 = g0, min(f1, g1)
    mid = np.linspace(m0, m1, 5)[1:-1]
    lo_of = {k: np.interp(mid, lowers[k].x, lowers[k].theta) for k in (f, g)}
    up_of = {k: np.interp(mid, uppers[k].x, uppers[k].theta) for k in (f, g)}
    if np.all(lo_of[f] > up_of[g]):
        high, low = f, g
    elif np.all(lo_of[g] > up_of[f]):
        high, low = g, f
    else:
        return None
    return Overlap(high, low, f, m0, m1, nested)


def curve_at(body, region, x):
    """(k, 3) points of ``region``'s curve at stations x (its own points where it has them,
    its exact plane points where it can, else the body at the angle interpolated between
    its points) and their angles."""
    from ..intersect.body import _body_angle

    x = np.asarray(x, float)
    pts = body.point(x, np.interp(x, region.x, region.theta))
    if region.exact is not None:
        got = region.exact(x)
        ok = np.all(np.isfinite(got), axis=1)
        pts[ok] = got[ok]
    if region.points is not None:
        at = np.searchsorted(region.x, x)
        at = np.minimum(at, region.x.size - 1)
        own = region.x[at] == x
        pts[own] = region.points[at[own]]
    return pts, _body_angle(body, pts)


def restricted(body, region, keep, extra_x):
    """``region`` with only its points at stations ``keep(x)`` (a bool mask function) and,
    at ``extra_x`` (None: none), its curve's point there (:func:`curve_at`)."""
    from .body_split import Boundary

    m = keep(region.x)
    x, th = region.x[m], region.theta[m]
    pts = None if region.points is None else region.points[m]
    if extra_x is not None and not np.any(x == extra_x):
        p, t = curve_at(body, region, [extra_x])
        x, th = np.append(x, extra_x), np.append(th, t)
        pts = None if pts is None else np.concatenate([pts, p])
    return Boundary(x, th, region.name, pts, region.exact)


def middle_block(body, ov, uppers, lowers, stations, n_points, ends):
    """(n_rows, n_points, 3) the middle block: rows at ``stations`` (in [m0, m1]) from the
    higher region's lower curve down to the lower region's upper curve, and the degenerate
    rows ``ends`` ([(x, point)], each a whole row of that point) before or after them."""
    top, bottom = lowers[ov.high], uppers[ov.low]
    xs = np.asarray(stations, float)
    p_top, t_top = curve_at(body, top, xs)
    p_bot, t_bot = curve_at(body, bottom, xs)
    frac = np.linspace(0.0, 1.0, int(n_points))
    ang = t_top[:, None] + frac[None, :] * (t_bot - t_top)[:, None]
    net = body.point(xs[:, None], ang)
    net[:, 0], net[:, -1] = p_top, p_bot
    rows = [net]
    for x, p in sorted(ends, key=lambda e: e[0]):
        rows.insert(0 if x < xs[0] else len(rows), np.broadcast_to(p, (1, len(frac), 3)))
    return np.concatenate(rows)


def outside_regions(ov, uppers, lowers):
    """The upper and lower blocks' regions over two regions that overlap (``ov``): the
    lower region's upper curve and the higher region's lower curve only outside [m0, m1]
    (the middle block has them inside)."""
    def cut(region, first):
        if first:    # the region that starts first: its points ahead of m0
            return restricted(None, region, lambda x: x < ov.m0, None)
        return restricted(None, region, lambda x: x > ov.m1, None)
    ups, los = list(uppers), list(lowers)
    if ov.nested:   # the outer region's curve facing the inner one outside [m0, m1] only;
        #             the inner one's curve facing the outer one is the middle block's
        def outside(x):
            return (x < ov.m0) | (x > ov.m1)
        if ov.first == ov.low:
            ups[ov.low] = restricted(None, uppers[ov.low], outside, None)
            los[ov.high] = restricted(None, lowers[ov.high], lambda x: x != x, None)
        else:
            los[ov.high] = restricted(None, lowers[ov.high], outside, None)
            ups[ov.low] = restricted(None, uppers[ov.low], lambda x: x != x, None)
        return ups, los
    ups[ov.low] = cut(uppers[ov.low], ov.low == ov.first)
    los[ov.high] = cut(lowers[ov.high], ov.high == ov.first)
    return ups, los


def switch_points(body, ov, regions, ups, los, xu, xl):
    """(upper regions, lower regions, middle block's degenerate rows): where each block
    passes from one region to the other (at m0 for the region that starts later, at m1
    for the one that ends first), the block's neighbouring station gets the first
    region's curve point there (the module docstring); where one region lies inside the
    other's range, the block on its side passes twice, at the stations next to m0 and m1."""
    from .body_split import Boundary

    ends = []
    ups, los = list(ups), list(los)
    if ov.nested:   # one block passes to the inner region at m0 and back at m1
        outer = ov.first
        block, xs, full = (ups, xu, regions[0]) if outer == ov.low else (los, xl, regions[1])
        xa, xb = float(xs[xs < ov.m0].max()), float(xs[xs > ov.m1].min())
        r = block[outer]
        p, t = curve_at(body, full[outer], [xa, xb])
        keep = np.isin(full[outer].x, r.x) & ~np.isin(full[outer].x, [xa, xb])
        x = np.concatenate([full[outer].x[keep], [xa, xb]])
        pts = None if full[outer].points is None else np.concatenate(
            [full[outer].points[keep], p])
        block[outer] = Boundary(x, np.concatenate([full[outer].theta[keep], t]), r.name,
                                pts, r.exact)
        return ups, los, [(xa, p[0]), (xb, p[1])]
    for block, xs, full, k in ((ups, xu, regions[0], ov.low), (los, xl, regions[1], ov.high)):
        if k == ov.first:          # clipped ahead of m0: its last station before m0
            x = float(xs[xs < ov.m0].max())
        else:                      # clipped after m1: its first station after m1
            x = float(xs[xs > ov.m1].min())
        block[k] = restricted(body, full[k], (lambda v, r=block[k]: np.isin(v, r.x)), x)
        ends.append((x, curve_at(body, full[k], [x])[0][0]))
    return ups, los, ends
