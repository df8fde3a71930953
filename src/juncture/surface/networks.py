"""Output networks of a wing-body juncture (TM-4406 "Output and Surface Grid Considerations").

Four blocks: the body ahead of the wing, the upper and lower wing regions, the body aft of the
wing. In a wing-region block each n-line runs along one lofting line: the body cross-section
arc from the top (bottom) of the body down (up) to the fillet start, the fillet line, then the
lofting line at the input airfoil sections outboard of the fillet end (section 1, replaced by
the fillet, is left out). The six-block option separates the body arcs ("body upper",
"body lower") from the wing ("wing upper", "wing lower"), whose n-lines are spanwise
stations: the first n-line is the line where wing (and fillet) meet the body, i.e. the
intersection line when there is no fillet.

The body ahead and aft uses, at every station, the point distribution of the wing region's
end arcs (TM-4406 fig 5: points below and above the wing leading-edge intersection angle
theta_w in proportion to arc length), so neighbouring blocks share identical boundary points.
All networks are oriented with outward normals (docs/conventions.md).

Every body arc ends exactly at the fillet start (or intersection) of its lofting line, and
the forward and aft networks' rings at the wing's leading- and trailing-edge stations are
made of the wing region's end arcs, so the seams close exactly. Where a lofting line misses
the body and the wing covers that side of it (:mod:`juncture.misses`), the arc is empty:
every point of it is the line's end point, off the body.
"""

from __future__ import annotations

import numpy as np

__all__ = ["body_range", "split_counts", "arc_points", "arc_to", "orient", "radial_outward",
           "juncture_networks", "layout_pieces", "ring", "refined_stations", "half_points",
           "SAG"]

#: A body's network rows are joined by straight lines; between two stations the body may stand
#: off them (a nose or tail whose radius follows a cubic over a long interval, 2 ft off on a
#: 64 ft tail cone). Stations are added until it stands off by at most this share of the
#: body's largest radius (:func:`refined_stations`).
SAG = 1e-3
#: Halvings of one interval between input stations at most (63 added stations).
HALVINGS = 6


def body_range(body):
    """(bottom, top, side) values of a body's section parameter.

    A circular body is parameterised by theta (-pi/2, pi/2, 0 on the horizontal), an
    arbitrary-section body by normalised arc length (0 bottom, 1 top, 0.5 half-way).
    """
    from ..model import CircularBody

    if isinstance(body, CircularBody):
        return -0.5 * np.pi, 0.5 * np.pi, 0.0
    return 0.0, 1.0, 0.5


def split_counts(theta_w, n_points, bottom=-0.5 * np.pi, top=0.5 * np.pi):
    """Points below / above theta_w for a half-section of ``n_points`` (TM-4406 fig 5).

    The share below is the arc from the bottom to theta_w over the whole half-section; both
    parts get at least 2 points and share the point at theta_w. A theta_w that is not finite
    (no leading-edge point on the body) splits the half-section in the middle.
    """
    frac = (theta_w - bottom) / (top - bottom)
    if not np.isfinite(frac):
        frac = 0.5
    n_below = int(np.clip(round(frac * (n_points - 1)) + 1, 2, n_points - 1))
    return n_below, n_points - n_below + 1


def half_points(body):
    """Points per half-section of a body's networks: the largest of its segments' counts (a
    nose segment given 5 points and the middle one 11 is written with 11 all along: the
    first count alone cut the middle's circle by 45 deg chords, 10 % of its area), else 19."""
    return int(max(getattr(body, "points_per_section", None) or (19,)))


def refined_stations(body, stations=None, sag=None):
    """``stations`` (default the body's own) with stations added between consecutive ones,
    by halving, where the body stands off the straight lines joining the two sections at the
    same section parameter by more than ``sag`` times its largest radius (measured at a
    quarter, half and three quarters of the interval, round the whole section). Repeated
    joint stations stay; an interval is measured within itself (a step at a joint between
    segments adds nothing). A body joined by straight lines along x (an arbitrary-section
    body) gets none. ``sag`` defaults to :data:`SAG`."""
    sag = SAG if sag is None else sag
    x = np.asarray(body.x_global if stations is None else stations, float)
    lo, hi, _ = body_range(body)
    par = np.linspace(lo, hi, 9)
    if hi - lo < 2.0:  # a circle: the other half too (a pod's centre off the plane)
        par = np.linspace(-np.pi, np.pi, 17)[:-1]
    tol = sag * float(np.sqrt(np.max(body.area_at(x)) / np.pi))
    a, b = x[:-1][np.diff(x) > 0], x[1:][np.diff(x) > 0]
    added = []
    t = np.array([0.25, 0.5, 0.75])
    for _ in range(HALVINGS):
        if not a.size or not tol > 0:
            break
        h = b - a
        ends = body.point(np.stack([a + 1e-9 * h, b - 1e-9 * h], -1)[..., None], par)
        xm = a[:, None] + t * h[:, None]                                    # (k, 3)
        chord = ends[:, None, 0] + t[None, :, None, None] * (ends[:, None, 1] - ends[:, None, 0])
        off = np.linalg.norm(body.point(xm[..., None], par) - chord, axis=-1).max(axis=(1, 2))
        split = off > tol
        mid = 0.5 * (a + b)[split]
        added.append(mid)
        a, b = np.concatenate([a[split], mid]), np.concatenate([mid, b[split]])
    if not added:
        return x
    return np.sort(np.concatenate([x] + added), kind="stable")


def arc_points(body, x, theta_from, theta_to, n, corners=False):
    """(m, n, 3) points on the body circles at stations x, theta from -> to (equal steps);
    with ``corners``, on an arbitrary section through its corners between the ends
    (:func:`juncture.surface.body_split.through_corners`), so that the network's facets
    keep the polygon the deck gives: at equal steps of the surface parameter they cut its
    corners, and no new point of a re-triangulation is put back on an arbitrary section (a
    held-out airplane's fuselage ahead of the wing stood 0.7 % of its section inside)."""
    t = np.linspace(0.0, 1.0, n)
    th = np.asarray(theta_from, float)[:, None] + t[None, :] * (
        np.asarray(theta_to, float) - np.asarray(theta_from, float))[:, None]
    x = np.asarray(x, float)
    if corners:
        from .body_split import through_corners

        th = through_corners(body, x, th)
    return body.point(x[:, None], th)


def arc_to(body, x, theta_from, theta_to, n, end):
    """Body arcs like :func:`arc_points` that end exactly at the points ``end`` (m, 3).

    The last point of each arc is ``end`` (the start of a fillet or wing line, normally the
    body point at ``theta_to``). Where the arc is empty (``theta_to`` equals ``theta_from``:
    the wing covers that side of the body, :mod:`juncture.misses`) every point is ``end``.
    """
    arc = arc_points(body, x, theta_from, theta_to, n, corners=True)
    end = np.asarray(end, float)
    arc[:, -1] = end
    empty = np.abs(np.asarray(theta_to, float) - np.asarray(theta_from, float)) <= 1e-12
    arc[empty] = end[empty, None, :]
    return arc


def orient(net, outward):
    """Reverse the n-line order if the network's normals point against ``outward``.

    ``outward`` (3,) is a reference direction, or a callable (points (..., 3)) -> (..., 3).
    The decision is by the sum over all quads of normal . outward (robust to degenerate quads).
    """
    a = net[:-1, :-1]
    n = np.cross(net[:-1, 1:] - a, net[1:, :-1] - a)
    ref = outward(a) if callable(outward) else np.broadcast_to(outward, a.shape)
    return net if np.sum(n * ref) >= 0 else net[::-1]


def radial_outward(body):
    """``f(points (..., 3)) -> (..., 3)``: the outward radial direction of a circular body."""
    def out(p):
        c = body.center_at(p[..., 0])
        r = np.zeros_like(p)
        r[..., 1] = p[..., 1] - c[..., 0]
        r[..., 2] = p[..., 2] - c[..., 1]
        return r
    return out


def _strip(wing, fillet, side, k_first):
    """(n_stations, n_span, 3): fillet points then the lofting line at sections >= k_first."""
    sec = wing.lofting_lines(side)[:, k_first:]
    return np.concatenate([fillet.points, sec], axis=1)


def layout_pieces(wing, body, upper, lower, n_body_points=None, stations=None, blunt=False):
    """The raw pieces every juncture layout is cut from (not yet oriented).

    Returns a dict: ``arc_u`` (n_stations, n_above, 3), body arcs from the top down to each
    upper fillet start; ``arc_l`` (n_stations, n_below, 3), from the bottom up to each lower
    fillet start (each ending exactly at the start, :func:`arc_to`); ``strip_u``,
    ``strip_l`` (n_stations, n_span, 3), fillet lines then the lofting lines outboard;
    ``ahead`` (k, n_below + n_above - 1, 3) body sections from the nose to the wing's
    leading-edge station and ``behind`` from its trailing-edge station to the end, whose
    ring at the wing station is made of the first (last) arcs, so that the blocks share
    their boundary points; and ``n_below``, ``n_above``.

    With ``blunt``, an end of the wing whose upper and lower arcs end at different points (a
    blunt trailing edge cut by the body: its upper and lower edges meet the body apart) keeps
    both points in its ring, and the sections beyond it both arcs' end angles, so that the
    block has ``n_below + n_above`` points per section there (``blunt_ends``: (le, te) bool)
    and the edge across the blunt end at the root is a seam of the body's block; otherwise
    the ring's upper end point was left out, and the body's section jumped from the lower
    edge's root over the upper one, leaving a slit.
    """
    u_end = np.concatenate([upper.u_end, lower.u_end])
    k_first = min(max(int(np.floor(np.nanmax(u_end))) + 1, 1), wing.n_sections - 1)
    n_half = n_body_points or half_points(body)
    bottom, top, _ = body_range(body)
    n_below, n_above = split_counts(float(upper.theta_start[0]), n_half, bottom, top)
    xu, xl = upper.start[:, 0], lower.start[:, 0]
    arc_u = arc_to(body, xu, np.full(xu.size, top), upper.theta_start, n_above, upper.start)
    arc_l = arc_to(body, xl, np.full(xl.size, bottom), lower.theta_start, n_below, lower.start)
    xg = body.x_global if stations is None else np.asarray(stations, float)
    x_le, x_te = min(xu[0], xl[0]), max(xu[-1], xl[-1])

    ends = tuple(bool(blunt and np.any(arc_l[k, -1] != arc_u[k, -1])) for k in (0, -1))

    def sections(xs, k, both):
        lo, hi = lower.theta_start[k], upper.theta_start[k]
        below = arc_points(body, xs, np.full(xs.size, bottom), np.full(xs.size, lo), n_below,
                           corners=True)
        above = arc_points(body, xs, np.full(xs.size, hi), np.full(xs.size, top), n_above,
                           corners=True)
        return np.concatenate([below, above[:, 0 if both else 1:]], axis=1)

    return {"arc_u": arc_u, "arc_l": arc_l, "n_below": n_below, "n_above": n_above,
            "strip_u": _strip(wing, upper, "upper", k_first),
            "strip_l": _strip(wing, lower, "lower", k_first), "blunt_ends": ends,
            "ahead": np.concatenate([sections(xg[xg < x_le], 0, ends[0]),
                                     ring(arc_l[:1], arc_u[:1], ends[0])]),
            "behind": np.concatenate([ring(arc_l[-1:], arc_u[-1:], ends[1]),
                                      sections(xg[xg > x_te], -1, ends[1])])}


def ring(arc_l, arc_u, both=False):
    """Cross-sections (k, n_below + n_above - 1, 3) from lower arcs (bottom up) and upper arcs
    (top down) that meet at the wing's leading or trailing edge (the shared point once), or
    with ``both`` (k, n_below + n_above, 3), both arcs' end points (a blunt edge's two)."""
    return np.concatenate([arc_l, arc_u[:, ::-1][:, 0 if both else 1:]], axis=1)


def juncture_networks(wing, body, upper, lower, blocks=4, n_body_points=None, stations=None):
    """Output networks of a wing-body juncture, and the gaps along their shared seams.

    Parameters
    ----------
    wing : WingLike
    body : CircularBody
        The (possibly re-designed) body.
    upper, lower : FilletLines
        Fillet lines of each surface; for no fillet, degenerate lines at the intersection
        (see :func:`juncture.completion.sharp_fillet`), or where a lofting line misses the
        body, at its end point (:mod:`juncture.misses`).
    blocks : {4, 6}
    n_body_points : int, optional
        Points per half cross-section of the body ahead and aft (default: the body's own
        ``points_per_section`` or 19).
    stations : (k,) float, optional
        Body stations for the networks ahead and aft (default: all of the body's).

    Returns
    -------
    networks : dict of str to (n_lines, n_points, 3)
    seams : list of dict
        ``{"a", "b", "seam", "max_gap", "points"}`` for every pair of networks that abut, the
        largest distance between their corresponding boundary points [deck length].
    """
    from ..errors import GeometryError

    if blocks not in (4, 6):
        raise GeometryError(f"blocks must be 4 or 6, found {blocks!r}")
    p = layout_pieces(wing, body, upper, lower, n_body_points, stations, blunt=True)
    arc_u, arc_l, strip_u, strip_l = p["arc_u"], p["arc_l"], p["strip_u"], p["strip_l"]
    n_below, n_above = p["n_below"], p["n_above"]
    fwd, aft_net = p["ahead"], p["behind"]
    seams = []

    def seam(a, b, name, pa, pb):
        seams.append({"a": a, "b": b, "seam": name, "points": int(len(pa)),
                      "max_gap": float(np.linalg.norm(pa - pb, axis=-1).max())})

    nets = {"body forward": fwd}
    if blocks == 4:
        reg_u = np.concatenate([arc_u, strip_u[:, 1:]], axis=1)
        reg_l = np.concatenate([arc_l, strip_l[:, 1:]], axis=1)
        nets["wing-body upper"], nets["wing-body lower"] = reg_u, reg_l
        names_u, names_l = "wing-body upper", "wing-body lower"
        wing_u, wing_l = reg_u[:, n_above - 1:], reg_l[:, n_below - 1:]
    else:
        nets["body upper"], nets["body lower"] = arc_u, arc_l
        nets["wing upper"] = np.swapaxes(strip_u, 0, 1)
        nets["wing lower"] = np.swapaxes(strip_l, 0, 1)
        names_u, names_l = "body upper", "body lower"
        wing_u, wing_l = strip_u, strip_l
        seam("body upper", "wing upper", "fillet start line", arc_u[:, -1], strip_u[:, 0])
        seam("body lower", "wing lower", "fillet start line", arc_l[:, -1], strip_l[:, 0])
    nets["body aft"] = aft_net
    for net_name, end, xs_net in (("body forward", 0, fwd), ("body aft", -1, aft_net)):
        edge = xs_net[-1] if end == 0 else xs_net[0]
        seam(net_name, names_u, "cross-section above the wing",
             edge[n_below - 1 + p["blunt_ends"][end]:], arc_u[end][::-1])
        seam(net_name, names_l, "cross-section below the wing", edge[:n_below], arc_l[end])
    wu, wl = ("wing upper", "wing lower") if blocks == 6 else (names_u, names_l)
    seam(wu, wl, "leading-edge lofting line", wing_u[0], wing_l[0])
    seam(wu, wl, "trailing-edge lofting line", wing_u[-1], wing_l[-1])
    outward = {"body forward": radial_outward(body), "body aft": radial_outward(body),
               "body upper": radial_outward(body), "body lower": radial_outward(body),
               "wing-body upper": np.array([0.0, 0.0, 1.0]),
               "wing upper": np.array([0.0, 0.0, 1.0]),
               "wing-body lower": np.array([0.0, 0.0, -1.0]),
               "wing lower": np.array([0.0, 0.0, -1.0])}
    nets = {k: orient(v, outward[k]) for k, v in nets.items()}
    return {k: nets[k] for k in sorted(nets, key=_block_order)}, seams


def _block_order(name):
    order = ["body forward", "wing-body upper", "wing-body lower", "body upper", "body lower",
             "wing upper", "wing lower", "body aft"]
    return order.index(name) if name in order else len(order)
