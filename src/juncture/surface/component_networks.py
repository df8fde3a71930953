"""Output networks of the components around the main juncture (TM-4607, "Output").

- A wing-like surface that meets other components is trimmed there: the intersection line at
  its root end replaces the root section (a fin or tail on the fuselage, a fin on the wing,
  a pylon on its nacelle) and, for a pylon, the line where it meets the wing replaces its tip
  section. Canards, fins and tails given by root and tip only get interpolated sections
  first (their count is an option).
- A nacelle (pod) that carries a pylon gets cross-sections interpolated at the x of the
  pylon-nacelle intersection points; there each cross-section is the arc from the outboard
  intersection line round the bottom to the inboard one (the part under the pylon belongs to
  the pylon).

A lofting line that never meets the other component keeps its input end point, and the log
says so (a warning, never a silent change). A canard's or tail's line that misses the
fuselage in the split layout arrives here already continued to the plane of symmetry
(:mod:`juncture.misses`).
"""

from __future__ import annotations

import re
import warnings

import numpy as np

from ..errors import GeometryError, JunctureWarning
from ..intersect.body import side_label
from ..intersect.winglike import wing_parameters

__all__ = ["interpolated", "trimmed_networks", "nacelle_network", "orient_winglike",
           "trace_curve", "add_trace_curves", "kept_roots", "split_roots"]


def interpolated(wing, count):
    """``wing`` with ``count`` extra sections between root and tip if it has only two."""
    if wing.n_sections != 2 or count <= 0:
        return wing
    s = wing.span_stations
    return wing.with_sections(s[0] + (s[1] - s[0]) * np.arange(1, count + 1) / (count + 1))


def orient_winglike(wing, side, pts):
    """Point order of a wing-like network so that normals point outward (as WingLike)."""
    e_span = np.eye(3)[wing.span_axis]
    e_thick = np.eye(3)[wing.thickness_axis]
    natural_out = float(np.cross([1.0, 0.0, 0.0], e_span) @ e_thick)
    sign = 1.0 if side == "upper" else -1.0
    return pts if sign * natural_out > 0 else pts[:, ::-1]


def _mean_u(inter, other=None):
    """Mean span parameter of an intersection line's points (the other side's line of the
    same pair where this one has none); NaN where neither has a point."""
    u = np.asarray(inter.u, float)
    if not np.isfinite(u).any() and other is not None:
        u = np.asarray(other.u, float)
    u = u[np.isfinite(u)]
    return float(np.mean(u)) if u.size else np.nan


def _at_root(wing, inters, others, hosts=None):
    """For each line of ``inters``, whether it trims ``wing``'s root end.

    One line: the end whose section lies inside the component met (``hosts``: name to
    component, those with a ``signed_distance``), else the end its points are nearer. A
    canard whose root is buried deep in a wide fuselage meets it nearer its tip, and still
    loses its root. Several: where each trims the root by that test, all do (a fin standing
    partly on the fuselage, partly on or through a tail); else the line nearest the root
    trims the root and the others the tip (a pylon between its nacelle and the wing, however
    near the root the wing's line lies).
    """
    u = np.array([_mean_u(inter, others[i] if i < len(others) else None)
                  for i, inter in enumerate(inters)])
    u = np.where(np.isfinite(u), u, 0.0)
    buried = [_buried_end(wing, inter, hosts or {}) for inter in inters]
    ends = [bool(v < 0.5 * (wing.n_sections - 1)) if b is None else b
            for v, b in zip(u, buried)]
    if len(u) < 2 or all(ends):
        return ends
    return [bool(i == int(np.argmin(u))) for i in range(len(u))]


def _host(inter, hosts):
    """The component an intersection "a/b side" meets (b), from ``hosts``; None if absent."""
    return hosts.get(inter.name.split("/", 1)[1].rsplit(" ", 1)[0])


def _buried_end(wing, inter, hosts):
    """True when more of the root section's mean line lies inside the component ``inter``
    meets than of the tip section's, False for the reverse, None when it cannot tell (the
    same share, or a component without a signed distance)."""
    host = _host(inter, hosts)
    mean = 0.5 * (wing.section_points("upper") + wing.section_points("lower"))[[0, -1]]
    if hasattr(host, "signed_distance"):
        inside = host.signed_distance(mean) < 0.0
    elif hasattr(host, "thickness_axis"):   # a fin or pylon whose tip is in a wing
        inside = _inside_wing(host, mean.reshape(-1, 3)).reshape(mean.shape[:2])
    else:
        return None
    root, tip = inside.mean(axis=1)
    return None if root == tip else bool(root > tip)


def _inside_wing(wing, p):
    """(k,) bool: points between a wing-like component's lower and upper surfaces (at their
    span station and chord fraction; the y >= 0 half)."""
    from .lift import _thickness

    up, low, inside = _thickness(wing, p)
    t = p[:, wing.thickness_axis]
    return inside & (t > np.minimum(up, low)) & (t < np.maximum(up, low))


def _end_line(wing, side, inters, at_root, log, hosts):
    """The line that trims one end of ``wing``'s ``side`` surface, and its span parameters.

    Several intersections at the same end (a fin standing partly on the fuselage, partly on
    a tail): each lofting line ends where it leaves the last component met going from the
    other end (the largest u at the root, the smallest at the tip). A line that meets none
    keeps its input end point (a warning), unless that point lies inside a component met:
    the line entered it where there is no surface to meet (refused, see ``_refuse_buried``).
    """
    lines = wing.lofting_lines(side)
    pts = np.full((lines.shape[0], 3), np.nan)
    u = np.full(lines.shape[0], np.nan)
    source = np.full(lines.shape[0], -1)
    for k, inter in enumerate(inters):
        v = np.asarray(inter.u, float)
        take = np.asarray(inter.found, bool) & ~((u >= v) if at_root else (u <= v))
        pts[take], u[take], source[take] = np.asarray(inter.points, float)[take], v[take], k
    used = np.unique(source[source >= 0])
    if at_root and len(used) > 1:
        on = "; ".join(f"{inters[k].name.split('/', 1)[1].rsplit(' ', 1)[0]}: lofting lines "
                       + ", ".join(str(j + 1) for j in np.flatnonzero(source == k))
                       for k in used)
        log.append(f"{wing.name} {side_label(wing, side)}: {_SPLIT} {on}")
    missed = np.isnan(u)
    end = 0 if at_root else -1
    pts[missed], u[missed] = lines[missed, end], (0.0 if at_root else wing.n_sections - 1.0)
    names = " and ".join(inter.name for inter in inters)
    if missed.any():
        _refuse_buried(wing, side, inters, pts, missed, hosts)
    for j in np.flatnonzero(missed):
        msg = (f"{names}: lofting line {j + 1} never meets the other component"
               f"{'s' if len(inters) > 1 else ''}; its input "
               f"{'root' if at_root else 'tip'} point is kept")
        log.append(msg)
        warnings.warn(msg, JunctureWarning, stacklevel=3)
    return pts, u


#: The log line above for a root, read back by :func:`kept_roots` (kept beside the message).
_KEPT_ROOT = re.compile(r"(.+?)/(.+?) (?:outboard|inboard|upper|lower)\b.*?: lofting line "
                        r"(\d+) never meets the other components?; its input root point is kept")


#: Log words of a root trimmed by two components or more, read back by :func:`split_roots`.
_SPLIT = "its root stands on more than one component, line by line:"


def split_roots(log):
    """{component: [the components its root stands on]} for roots trimmed by more than one
    (a fin standing partly on the fuselage, partly on a tail), read from the ``log``."""
    out = {}
    for line in log:
        head, _, rest = line.partition(f": {_SPLIT} ")
        if rest:
            name = head.rsplit(" ", 1)[0]
            hosts = [part.rsplit(": lofting lines", 1)[0] for part in rest.split("; ")]
            out.setdefault(name, [])
            out[name] += [h for h in hosts if h not in out[name]]
    return out


def kept_roots(log):
    """{(component, what it stands on): {lofting lines (1-based)}} whose input root points
    were kept, read from the ``log`` lines written above."""
    kept = {}
    for line in log:
        got = _KEPT_ROOT.match(line)
        if got:
            kept.setdefault((got[1], got[2]), set()).add(int(got[3]))
    return kept


def _refuse_buried(wing, side, inters, pts, missed, hosts):
    """A line meeting none of the components at its end, whose input end point lies inside
    one of them, entered it where it has no surface to meet (the face of a step between two
    fuselage segments, an open end): kept, the network would run inside it (issue 11)."""
    from ..misses import refuse_buried_line

    for inter in inters:
        host = _host(inter, hosts)
        if hasattr(host, "signed_distance"):
            size = 1e-9 * max(float(host.length), 1.0)
            inside = missed & (host.signed_distance(np.where(missed[:, None], pts, 0.0))
                               < -size)
        elif hasattr(host, "thickness_axis"):
            inside = missed & _inside_wing(host, np.where(missed[:, None], pts, 0.0))
        else:
            continue
        if inside.any():
            j = int(np.argmax(inside))
            refuse_buried_line(wing, host, side_label(wing, side), j,
                               wing.lofting_lines(side)[j], pts[j],
                               "with its input end point kept")


def trimmed_networks(wing, side_inters, log, hosts=None):
    """Networks of ``wing`` cut at its intersection lines.

    Parameters
    ----------
    wing : WingLike
        Already interpolated if wanted (the intersections must be of this very object).
    side_inters : dict of str to list of BodyIntersection
        For "upper" and "lower": the intersections of that surface with other components,
        one per touching pair, in the same order on both sides.
    hosts : dict of str to component, optional
        The components met, by name: the end of ``wing`` buried in one is the end its line
        trims.

    Returns
    -------
    dict of str to (n_lines, n_points, 3)
    """
    ups, los = side_inters.get("upper", []), side_inters.get("lower", [])
    nets = {}
    for side, inters, others in (("upper", ups, los), ("lower", los, ups)):
        sec = wing.section_points(side)  # (n_sections, n_stations, 3)
        first, last = None, None
        lo, hi = -np.inf, np.inf
        roots = _at_root(wing, inters, others, hosts)
        at_root = [inter for inter, r in zip(inters, roots) if r]
        at_tip = [inter for inter, r in zip(inters, roots) if not r]
        if at_root:
            first, u = _end_line(wing, side, at_root, True, log, hosts or {})
            lo = float(np.max(u))
        if at_tip:
            last, u = _end_line(wing, side, at_tip, False, log, hosts or {})
            hi = float(np.min(u))
        k = np.arange(wing.n_sections)
        keep = sec[(k > lo + 1e-9) & (k < hi - 1e-9)]
        parts = ([first[None]] if first is not None else []) + [keep] + \
            ([last[None]] if last is not None else [])
        net = np.concatenate(parts, axis=0)
        nets[f"{wing.name} {side_label(wing, side)}"] = orient_winglike(wing, side, net)
    return nets


def nacelle_network(pod, pylon_inters, n_points=None):
    """A pod's cross-sections, open under its pylon(s) (TM-4607).

    Parameters
    ----------
    pod : CircularBody
    pylon_inters : list of (outboard BodyIntersection, inboard BodyIntersection[, WingLike])
        Each pylon's intersections with this pod, and the pylon: with it the arcs at pod
        stations between its intersection points end where its surfaces meet the pod in
        those planes (:func:`juncture.intersect.stations.plane_points`), on the exact curve,
        not at an angle interpolated between the points.
    n_points : int, optional
        Points per cross-section (default 2 * 19 - 1).

    Returns
    -------
    (n_lines, n_points, 3) float
        Cross-sections at the pod stations and at the intersection points' x (one station
        for points within :data:`SAME_STATION` of the length of each other or of a pod
        station); where a pylon sits, each runs from its inboard line round the bottom to
        its outboard line, ending exactly at the intersection points at their stations.
    """
    from .networks import refined_stations

    n = int(n_points or 37)
    xg = refined_stations(pod)
    spans, ends = [], []
    for out_i, in_i, *wing in pylon_inters:
        ok_o, ok_i = out_i.found, in_i.found
        if not ok_o.any() or not ok_i.any():
            continue
        xo = out_i.points[ok_o, 0]
        th_o, th_i = _angle(pod, out_i.points[ok_o]), _angle(pod, in_i.points[ok_i])
        order = np.argsort(in_i.points[ok_i, 0])
        th_i_at = np.interp(xo, in_i.points[ok_i, 0][order], np.unwrap(th_i[order]))
        spans.append((xo, th_o, th_i_at, wing[0] if wing else None, out_i, in_i))
        ends.append((out_i.points[ok_o], in_i.points[ok_i]))
    xs = _stations(xg, [p[:, 0] for e in ends for p in e]) if spans else xg
    # Full circles start and end at the top, so the arcs under a pylon continue them smoothly.
    lo = np.full(xs.size, 0.5 * np.pi)
    hi = np.full(xs.size, 2.5 * np.pi)
    exact = []
    for xo, th_o, th_i, wing, out_i, in_i in spans:
        order = np.argsort(xo)
        rows = _nearest(xs, xo)
        inside = (np.arange(xs.size) >= rows.min()) & (np.arange(xs.size) <= rows.max())
        # From the inboard line (theta just above pi/2) round the bottom to the outboard one.
        lo[inside] = np.interp(xs[inside], xo[order], np.mod(th_i[order], 2 * np.pi))
        hi[inside] = np.interp(xs[inside], xo[order], np.mod(th_o[order], 2 * np.pi)) + \
            2 * np.pi
        if wing is not None:
            at = np.flatnonzero(inside)
            for inter, side, col in ((in_i, "lower", 0), (out_i, "upper", -1)):
                p = _exact_at(wing, pod, side, inter, xs[at])
                ok = np.isfinite(p[:, 0])
                angle = np.mod(_angle(pod, p[ok]), 2 * np.pi)
                (lo if col == 0 else hi)[at[ok]] = angle + (0.0 if col == 0 else 2 * np.pi)
                exact.append((at[ok], col, p[ok]))
    t = np.linspace(0.0, 1.0, n)
    theta = lo[:, None] + t[None, :] * (hi - lo)[:, None]
    net = pod.point(xs[:, None], theta)
    for rows, col, pts in exact:
        net[rows, col] = pts
    # Where a station is an intersection point's x, its arc ends exactly at that point, so
    # the pylon's root line and the pod share these points bit for bit.
    for outboard, inboard in ends:
        lo_x, hi_x = outboard[:, 0].min(), outboard[:, 0].max()
        for col, pts in ((-1, outboard), (0, inboard)):
            pts = pts[(pts[:, 0] >= lo_x) & (pts[:, 0] <= hi_x)]  # where the arc is open
            net[_nearest(xs, pts[:, 0]), col] = pts
    return net


def _exact_at(wing, pod, side, inter, x):
    """(len(x), 3) where ``wing``'s ``side`` meets ``pod`` in the planes ``x`` between two
    of its intersection points ``inter`` (NaN elsewhere)."""
    from ..intersect.stations import plane_points

    pts = np.where(inter.found[:, None], inter.points, np.nan)
    return plane_points(wing, pod, side, pts, x, either=True)


def _angle(pod, p):
    """(k,) the angles of the points ``p`` on the circular ``pod`` round its axis."""
    c = pod.center_at(p[:, 0])
    return np.arctan2(p[:, 2] - c[:, 1], p[:, 1] - c[:, 0])


#: Stations of a pod's network closer than this share of its length are one station.
SAME_STATION = 1e-3


def _stations(xg, extra):
    """The pod's stations and the intersection points' x, but one station where they lie
    within :data:`SAME_STATION` of the pod's length (a pylon's outboard and inboard lines
    meet the pod 1e-5 apart in x: two rows that close made slivers); the pod's own
    stations are kept first, then the points' in order."""
    tol = SAME_STATION * float(xg[-1] - xg[0])
    kept = list(xg)
    for x in np.sort(np.concatenate(extra)):
        if np.min(np.abs(np.asarray(kept) - x)) > tol:
            kept.append(float(x))
    return np.unique(np.asarray(kept, float))


def _nearest(xs, x):
    """Index of the station of ``xs`` (sorted) nearest each of ``x``."""
    i = np.clip(np.searchsorted(xs, x), 1, xs.size - 1)
    return np.where(np.abs(x - xs[i - 1]) <= np.abs(xs[i] - x), i - 1, i)


def trace_curve(wing, side, line):
    """A curve on ``wing``'s ``side`` at its chord stations that traces an intersection line.

    In the wing's parameters the line is a span y(f) over its chord fractions f; the curve takes
    y(f) at each of the wing's stations (held constant beyond the line's ends) and the wing's
    surface point there. It lies on the surface everywhere and follows the line at the wing's
    own chord stations: it meets the intersection points exactly only where a station does
    (passing through every one would need extra m-lines across the whole wing, the
    accounting problem TM-4607 describes). Returns (n_stations, 3).

    Raises
    ------
    GeometryError
        If the line has no finite point (a fin or pylon none of whose lofting lines meets
        ``wing``: such a pair does not touch and is never traced).
    """
    line = np.asarray(line, float).reshape(-1, 3)
    ok = np.all(np.isfinite(line), axis=1)
    if not ok.any():
        raise GeometryError(f"no intersection point to trace on the {side} surface: the fin "
                            f"or pylon line given has none of its {len(line)} points on "
                            f"{wing.name} (a pair that does not touch)", wing.name)
    y, f = wing_parameters(wing, line[ok])
    order = np.argsort(f)
    fs = wing.x_over_c / 100.0
    span = np.interp(fs, f[order], y[order])
    return wing.point(span, fs, side)


#: A traced curve within this share of the spacing between its nearest line and that
#: line's neighbour, or crossing a line, is not inserted (the footprint is cut into the
#: surface all the same, :mod:`juncture.surface.imprint`): beside a section 0.2 % of that
#: spacing away it left a row of slivers and edges in more than two triangles; crossing a
#: section, it folded the network.
BESIDE = 0.02


def _beside(curve, lines, axis=1):
    """Whether ``curve`` (n, 3) crosses one of ``lines`` (n-lines of a network, each (n,
    3), in span order; its span coordinate ``axis`` on both sides of the line's) or lies
    within :data:`BESIDE` of the spacing from one: inserted, it would fold the network."""
    if len(lines) < 2:
        return False
    stack = np.stack(lines)
    d = curve[None, :, axis] - stack[:, :, axis]
    if np.any((d.min(axis=1) < 0.0) & (d.max(axis=1) > 0.0)):
        return True
    gap = np.linalg.norm(stack - curve[None], axis=2).max(axis=1)
    k = int(np.argmin(gap))
    other = stack[k + 1] if k + 1 < len(stack) else stack[k - 1]
    spacing = np.linalg.norm(stack[k] - other, axis=1).max()
    return bool(gap[k] < BESIDE * spacing)


def add_trace_curves(wing, nets, traces):
    """Insert traced curves into the wing's networks (n-lines = sections, in span order).

    ``traces`` is a list of (side, curve (n_stations, 3)); ``nets`` maps "wing upper"/"wing
    lower" to networks whose n-lines are spanwise stations, the body-side n-line first or
    (for a network oriented tip to root) last; the order and orientation are kept.
    """
    out = dict(nets)
    for side in ("upper", "lower"):
        name = f"{wing.name} {side}"
        curves = [c for s_, c in traces if s_ == side]
        if name not in out or not curves:
            continue
        net = out[name]
        # Points LE -> TE? Each line's trailing edge lies aft of its leading edge (the first
        # point need not be the line's smallest x: at the root, the intersection line's
        # second point can lie ahead of its first).
        natural = bool(np.median(net[:, -1, 0] - net[:, 0, 0]) > 0.0)
        add = [c if natural else c[::-1] for c in curves]
        # An oriented network may run tip to root (orient() reversed it): the body-side line
        # is then its last, and the result is reversed back so the normals stay outward.
        backward = net[0, :, 1].mean() > net[-1, :, 1].mean()
        base = net[::-1] if backward else net
        rest = list(base[1:])
        for c in sorted(add, key=lambda c: c[:, 1].mean()):
            if _beside(c, rest, getattr(wing, "span_axis", 1)):
                continue
            # after the last line not outboard of it: the lines are kept in their order (a
            # fillet's lines down the fuselage side are not in span order)
            means = np.array([r[:, 1].mean() for r in rest])
            pos = int(np.flatnonzero(means <= c[:, 1].mean()).max(initial=-1)) + 1
            rest.insert(pos, c)
        merged = np.concatenate([base[:1], np.stack(rest)], axis=0)  # body-side line first
        out[name] = merged[::-1] if backward else merged
    return out
