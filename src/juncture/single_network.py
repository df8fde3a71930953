"""The fuselage as a single network (TM-4406 figs 4-5): lines re-interpolated at the upper x.

TM-4406: "If the fuselage is to be described as a single network ... a new set of
intersection points is determined at the same x-locations as the upper-surface intersection
points by interpolation in the initial set of lower-surface intersection points", and the
fuselage points are redistributed around the wing (fig 5). Each n-line of the fuselage is
then one cross-section x = X_j through the upper fillet start (the upper intersection without
a fillet): from the bottom up to the lower line, and from the upper line up to the top.

Here the re-interpolation is done on the surfaces, not between points, and for fillets
on whole lines (the paper treats only the intersection points):

- **Without a fillet**, the lower point at X_j is the point of the lower surface's end curve
  at that x: the lofting line of the chord fraction f between the two neighbouring lofting
  lines whose crossing with the body lies at x = X_j (a root in f of x(f) - X_j, each x(f) a
  crossing found like the lofting lines' own, or where that line reaches the plane of
  symmetry if it misses the body, :mod:`juncture.misses`). It lies on both surfaces, where the
  paper's interpolated point lies only near them ("no longer collinear with the corresponding
  points on the first and second airfoil sections"). Where the end curve jumps over X_j (from
  the body to the plane of symmetry, where the lines stop meeting the body) the point is
  interpolated across the jump, then moved out of the wing and out of the body, and the log
  says so. Where no line end lies at X_j at all, the nearest end is moved to that x and onto
  the body.
- **With a circular fillet** every line is rebuilt in the plane x = X_j: the arc of the
  neighbouring lines' radius tangent to the body circle and to the wing's section by that
  plane. Every segment of every fillet line lies in the cross-section plane of the
  fuselage n-line it continues. The paper's arcs (:mod:`juncture.fillet.circular`) are
  tangent to the lofting line's direction projected on that plane instead, which differs
  from the wing's section by the chordwise slope times the sweep of the lofting line, so
  near the wing they pass into it; the rebuilt upper arcs are those of the wing section,
  their ends on it next to the lofting lines.
- **With a cubic fillet** the lower lines are re-interpolated whole: line j is the line of
  the lower fillet surface whose start lies at x = X_j, each point interpolated between the
  same points of the two lines whose starts bracket X_j (in the body's cylindrical
  coordinates near the body, in the wing's span station, chord fraction and height near the
  wing, so that it stays outside both), with its start on the body and its end on the wing.
  The upper lines are unchanged. A cubic fillet line (TM-4406 eq 7) is a curve in space: it
  starts in the plane x = X_j, tangent to the body section, and ends tangent to the lofting
  line, which runs aft; a line confined to the plane could not end on its lofting line, and
  where the lofting lines lie closer than a fillet's run in x the wing networks would fold.
  So the starts lie in the fuselage's cross-sections (no jump in x, as when only the first
  point was moved), the rest of each line runs aft like the upper one. A line whose start the
  wing would cover (the two lines lie on either side of a leading edge) or whose end would lie
  inside the body is left sharp at X_j, as next to a line that misses.

The wing networks keep their lofting lines outboard of the fillet (TM-4406 fig 4: the points
of the first n-line are no longer on the lofting lines).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from .fillet.planar import planar_arcs as _planar_arcs
from .fillet.planar import planform as _planform
from .intersect.rays import SurfaceBound, find_crossings, polyline_points
from .surface.networks import layout_pieces, orient, radial_outward

__all__ = ["single_network", "line_end_at", "interpolated_lines", "planar_arcs_at",
           "reinterpolated"]


def _rebuilt(lines, **changes):
    """``lines`` (FilletLines) with ``changes``; control points, if it has them, dropped (the
    re-interpolated lines are no longer the cubics they describe)."""
    if getattr(lines, "control", None) is not None:
        changes["control"] = None
    return replace(lines, **changes)


def _fraction(wing, pts):
    """(span, chord fraction) of points on the wing surface."""
    span = pts[:, wing.span_axis]
    x_le, chord, _, _ = _planform(wing, span)
    with np.errstate(divide="ignore", invalid="ignore"):
        return span, np.where(chord != 0, (pts[:, 0] - x_le) / chord, 0.0)


def _body_angle(body, pts):
    if hasattr(body, "radius"):
        c = body.center_at(pts[:, 0])
        return np.arctan2(pts[:, 2] - c[:, 1], pts[:, 1] - c[:, 0])
    return body.parameter_of(pts)


def _error(body):
    if hasattr(body, "radial_error_and_gradient"):
        def error(points):
            return body.radial_error(points)
        error.value_and_gradient = body.radial_error_and_gradient
        return error, SurfaceBound(body)
    return body.signed_distance, body.error_lipschitz


def _cut(xs, X, near):
    """Where each column of xs (m, n) reaches x = X_i, nearest to row near_i.

    Returns ``(seg (p, n), w (p, n), ok (p, n))``: the point is row seg + w of the column
    (linear between rows seg and seg + 1); ``ok`` is False where the column never reaches X_i.
    """
    a, b = xs[:-1][None], xs[1:][None]
    Xc = np.asarray(X, float)[:, None, None]
    d = b - a
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.where(d != 0, (Xc - a) / d, np.where(Xc == a, 0.0, np.nan))
    inside = (w >= 0) & (w <= 1)
    pos = np.arange(xs.shape[0] - 1)[None, :, None] + w
    dist = np.where(inside, np.abs(pos - np.asarray(near)[:, None, None]), np.inf)
    seg = np.argmin(dist, axis=1)
    ok = np.isfinite(np.min(dist, axis=1))
    w = np.take_along_axis(np.nan_to_num(w), seg[:, None, :], 1)[:, 0]
    return seg, np.where(ok, w, 0.0), ok


def _wing_point_at_x(wing, side, pa, pb, w, X):
    """Points on the wing between surface points pa and pb (p, 3) at x = X (p,).

    Span station and chord fraction are interpolated (from w) and then moved along that
    parameter segment until x = X (a few Newton steps); the points lie on the surface.
    """
    sa, fa = _fraction(wing, pa)
    sb, fb = _fraction(wing, pb)
    lam = np.array(w, float)
    for _ in range(30):
        s, f = sa + lam * (sb - sa), fa + lam * (fb - fa)
        x_le, chord, dle, dc = _planform(wing, s)
        g = x_le + chord * f - X
        dg = (dle + dc * f) * (sb - sa) + chord * (fb - fa)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(dg != 0, g / dg, 0.0)
        lam = lam - step
        if np.all(np.abs(step) < 1e-15):
            break
    s, f = sa + lam * (sb - sa), fa + lam * (fb - fa)
    pts = wing.point(s, f, side, extrapolate=True)
    pts[:, 0] = X
    return pts


def _bracket(x, X):
    """Row seg, weight w with x = X on the polyline of values x (m,), nearest to row i."""
    seg, w, ok = (v[:, 0] for v in _cut(np.asarray(x, float)[:, None], X,
                                       np.minimum(np.arange(len(X)), len(x) - 1)))
    return seg, w, ok


def _moved_starts(body, lines, X):
    """Fillet starts re-interpolated at stations X: ``(points, theta, ok)``.

    The start angle is interpolated between the two lines whose starts bracket X_i (nearest
    to line i), plus their starts' offsets from the body (non-zero only for a start
    continued to the plane of symmetry, :mod:`juncture.misses`): on the body otherwise.
    """
    B = np.asarray(lines.start, float)
    theta = np.asarray(lines.theta_start, float)
    sb, wb, ok = _bracket(B[:, 0], X)
    th = (1 - wb) * theta[sb] + wb * theta[sb + 1]
    offset = B - body.point(B[:, 0], theta)
    pts = body.point(X, th) + (1 - wb)[:, None] * offset[sb] + wb[:, None] * offset[sb + 1]
    return np.where(ok[:, None], pts, B), np.where(ok, th, theta), ok


def _ended(body, lines):
    """Lines that end off the body (continued to the plane of symmetry, juncture.misses)."""
    scale = max(1.0, float(np.abs(body.x_global).max()))
    return np.abs(_radial(body, np.asarray(lines.start, float))) > 1e-9 * scale


def interpolated_lines(wing, body, lines, ends, X):
    """Fillet lines (FilletLines) re-interpolated whole at the stations X (m,).

    TM-4406 re-interpolates the lower intersection points at the upper points' x; here every
    point of a fillet line is: line i is the line of the fillet surface whose start lies at
    x = X_i, each of its points interpolated between the same points of the two lines whose
    starts bracket X_i, with the weight that puts the start there. The start is on the body
    (its angle interpolated, :func:`_moved_starts`), the end on the wing (its span station and
    chord fraction interpolated, then moved to the interpolated x), the points between on the
    surface through the fillet lines (linear between them), blended from the body's
    cylindrical coordinates near the body to the wing's (span, chord fraction, height)
    near the wing, so that they stay outside both where the two lines are. Between a line
    that is continued to the plane of symmetry (no fillet, :mod:`juncture.misses`) and
    another the line is the sharp end at X_i (:func:`line_end_at`).
    """
    pts = np.asarray(lines.points, float)
    m, n = pts.shape[:2]
    X = np.asarray(X, float)
    B = np.asarray(lines.start, float)
    sb, wb, ok = _bracket(B[:, 0], X)
    # In the body's cylindrical coordinates (x, angle, height above the surface), so that
    # the interpolated points stay outside the body where both lines are.
    w = wb[:, None]
    xi = (1 - w) * pts[sb, :, 0] + w * pts[sb + 1, :, 0]
    if hasattr(body, "section_at"):
        ctr, r = body.section_at(pts[..., 0])
        ang = np.arctan2(pts[..., 2] - ctr[..., 1], pts[..., 1] - ctr[..., 0])
        height = np.hypot(pts[..., 2] - ctr[..., 1], pts[..., 1] - ctr[..., 0]) - r
        d_ang = (ang[sb + 1] - ang[sb] + np.pi) % (2 * np.pi) - np.pi
        ai = ang[sb] + w * d_ang
        hi = (1 - w) * height[sb] + w * height[sb + 1]
        c_i, r_i = body.section_at(xi)
        near_body = np.stack([xi, c_i[..., 0] + (r_i + hi) * np.cos(ai),
                              c_i[..., 1] + (r_i + hi) * np.sin(ai)], axis=-1)
    else:
        # An arbitrary section: (x, surface parameter of the nearest point, offset from it).
        s_par, off = _section_coordinates(body, pts)
        near_body = _off_section(body, xi, (1 - w) * s_par[sb] + w * s_par[sb + 1],
                                 (1 - w[..., None]) * off[sb] + w[..., None] * off[sb + 1])
    # And in the wing's (span station, chord fraction, height above the surface), so that
    # they stay outside the wing where both lines are; the two blended along the line.
    a_t = wing.thickness_axis
    span, frac = _fraction(wing, pts.reshape(-1, 3))
    surf = wing.point(span, frac, lines.side, extrapolate=True)
    lift = (pts.reshape(-1, 3) - surf)[:, a_t].reshape(m, n)
    span, frac = span.reshape(m, n), frac.reshape(m, n)
    near_wing = wing.point((1 - w) * span[sb] + w * span[sb + 1],
                           (1 - w) * frac[sb] + w * frac[sb + 1], lines.side, extrapolate=True)
    near_wing[..., a_t] += (1 - w) * lift[sb] + w * lift[sb + 1]
    t = np.linspace(0.0, 1.0, n)[None, :, None]
    t = t * t * (3 - 2 * t)  # each representation dominates towards its own surface
    blended = (1 - t) * near_body + t * near_wing
    # Where the blend dips into either solid, the representation that stays outside both.
    for other in (near_wing, near_body):
        bad = ~_outside(wing, body, blended) & _outside(wing, body, other)
        blended = np.where(bad[..., None], other, blended)
    # Where both dip into the wing (at a rounded leading edge, where the height above the
    # surface at a fixed x says little), the point is put on the wing's surface there.
    blended = _onto_body(body, _onto_wing(wing, lines.side, blended))
    out = np.where(ok[:, None, None], blended, pts)
    start, theta, _ = _moved_starts(body, lines, X)
    out[:, 0] = start
    x_end = (1 - wb) * pts[sb, -1, 0] + wb * pts[sb + 1, -1, 0]
    end = _wing_point_at_x(wing, lines.side, pts[sb, -1], pts[sb + 1, -1], wb, x_end)
    out[ok, -1] = end[ok]
    out[ok, 0, 0] = X[ok]
    out = _chord_where_buried(wing, body, out, ok)
    log = [f"single network: {lines.side} fillet line {j + 1} keeps its start "
           f"(x = {B[j, 0]:.6g}): no fillet start lies at x = {X[j]:.6g}"
           for j in np.flatnonzero(~ok)]
    ended = _ended(body, lines)
    # A start on the body that the wing covers (bracketing lines on either side of a
    # leading edge, where the starts jump round it), or an end on the wing inside the body
    # (between two ends on either side of a bend of the intersection): no room for a fillet.
    from .fillet.clearance import tolerance, wing_depth

    tol = tolerance(body)
    covered = ok & (np.abs(_radial(body, out[:, 0])) <= tol) & (
        wing_depth(wing, out[:, :1])[:, 0] > tol)
    buried = ok & ~covered & (_radial(body, out[:, -1]) < -tol)
    for j in np.flatnonzero(covered | buried):
        log.append(f"single network: {lines.side} fillet line {j + 1} at x = {X[j]:.6g} "
                   f"would {'start inside the wing' if covered[j] else 'end inside the body'}"
                   "; left sharp")
    sharp = ok & (ended[sb] | ended[sb + 1] | covered | buried)
    if sharp.any():
        p_sharp, th_sharp, _, more = line_end_at(wing, body, ends, X, lines.side)
        out[sharp] = p_sharp[sharp, None, :]
        theta = np.where(sharp, th_sharp, theta)
        log += more

    def interp(v):
        v = np.asarray(v, float)
        return np.where(ok, (1 - wb) * v[sb] + wb * v[sb + 1], v)

    return _rebuilt(lines, points=out, start=out[:, 0].copy(), end=out[:, -1].copy(),
                   theta_start=theta, u_end=interp(lines.u_end),
                   blend=np.where(sharp, 0.0, interp(lines.blend)),
                   dips=np.where(ok, lines.dips[sb] | lines.dips[sb + 1], lines.dips),
                   log=tuple(lines.log) + tuple(log))


def planar_arcs_at(wing, body, lines, ends, X):
    """Circular fillet lines (FilletLines) rebuilt in the planes x = X (m,).

    Line i is the arc, of the radius of the lines it lies between (interpolated), tangent to
    the body circle and to the wing's section by the plane x = X_i (solved along that
    section, :func:`_planar_arcs`): every point has x = X_i. Where the neighbouring lines
    are sharp (leading and trailing edges, lines that miss the body) or no arc fits, it is
    the sharp point at X_i (:func:`line_end_at`).
    """
    pts = np.asarray(lines.points, float)
    m, n = pts.shape[:2]
    X = np.asarray(X, float)
    B, E = np.asarray(lines.start, float), np.asarray(lines.end, float)
    sharp, sharp_theta, _, log = line_end_at(wing, body, ends, X, lines.side)
    out = np.repeat(sharp[:, None, :], n, axis=1)
    theta = np.array(sharp_theta, float)
    blend = np.zeros(m)
    rho = np.zeros(m)
    mid = pts[:, n // 2]
    for i in range(m):  # circumradius of the first, middle and last points
        area2 = np.linalg.norm(np.cross(mid[i] - B[i], E[i] - B[i]))
        if area2 > 1e-300:
            rho[i] = (np.linalg.norm(mid[i] - B[i]) * np.linalg.norm(E[i] - mid[i])
                      * np.linalg.norm(E[i] - B[i]) / (2 * area2))
    sb, wb, okb = _bracket(B[:, 0], X)
    ended = _ended(body, lines)
    rho_new = np.where(okb & ~ended[sb] & ~ended[sb + 1],
                       (1 - wb) * rho[sb] + wb * rho[sb + 1], 0.0)
    near = np.where(okb[:, None], (1 - wb)[:, None] * E[sb] + wb[:, None] * E[sb + 1], E)
    arc, _, th_arc, _, found = _planar_arcs(wing, body, lines.side, X, rho_new, near, n)
    # Where the wing's section by x = X curves faster than 1 / rho (a leading edge cut at a
    # shallow angle) the arc would enter the wing: the radius is halved there until not.
    from .fillet.clearance import tolerance, wing_depth

    tol = tolerance(body)
    deep = found & (wing_depth(wing, arc) > tol).any(axis=1)
    for _ in range(12):
        if not deep.any():
            break
        rho_new = np.where(deep, 0.5 * rho_new, rho_new)
        again = _planar_arcs(wing, body, lines.side, X, rho_new, near, n)
        arc = np.where(deep[:, None, None], again[0], arc)
        th_arc = np.where(deep, again[2], th_arc)
        found = np.where(deep, again[4], found)
        deep = deep & found & (wing_depth(wing, arc) > tol).any(axis=1)
    if deep.any():
        found = found & ~deep
    out[found], theta[found] = arc[found], th_arc[found]
    blend[found] = ((1 - wb) * lines.blend[sb] + wb * lines.blend[sb + 1])[found]
    for i in np.flatnonzero((rho_new > 0) & ~found):
        log.append(f"single network: no circular arc fits at x = {X[i]:.6g} "
                   f"({lines.side} line {i + 1}); left sharp")
    out[..., 0] = X[:, None]
    return _rebuilt(lines, points=out, start=out[:, 0].copy(), end=out[:, -1].copy(),
                   theta_start=theta, blend=blend, dips=np.zeros(m, bool),
                   log=tuple(lines.log) + tuple(log))


def line_end_at(wing, body, ends, X, side="lower"):
    """End points of one surface's lines re-interpolated at stations X (module docstring).

    Parameters
    ----------
    ends : LineEnds
        Where each lofting line of the surface ends (:func:`juncture.misses.line_ends`).
    X : (p,) float
        The stations (the upper intersection's x) [deck length].

    Returns
    -------
    points : (p, 3) float
    theta : (p,) float
        Body angle (section parameter) of each point, as :class:`juncture.misses.LineEnds`.
    on_body : (p,) bool
        Points on the intersection curve (else on the plane of symmetry, or interpolated).
    log : list of str
    """
    pts_e = ends.points
    m = len(pts_e)
    X = np.asarray(X, float)
    p = X.size
    near = np.minimum(np.arange(p), m - 1)
    seg, w, ok = (v[:, 0] for v in _cut(pts_e[:, None, 0], X, near))
    hit = ~ends.missed
    t = wing.x_over_c / 100.0
    out = np.where(ok[:, None], (1 - w)[:, None] * pts_e[seg] + w[:, None] * pts_e[seg + 1],
                   pts_e[near])
    theta = np.where(ok, (1 - w) * ends.theta[seg] + w * ends.theta[seg + 1],
                     ends.theta[near])
    on_body = np.where(ok, np.where(w == 0, hit[seg], np.where(w == 1, hit[seg + 1], False)),
                       hit[near])
    exact = ok & ((w == 0) | (w == 1))
    log = []
    # Both ends continued to the plane of symmetry: the wing surface's point on it.
    plane = ok & ~exact & ends.missed[seg] & ends.missed[seg + 1]
    if plane.any():
        out[plane] = _wing_point_at_x(wing, side, pts_e[seg[plane]], pts_e[seg[plane] + 1],
                                      w[plane], X[plane])
    # Otherwise: the chord fraction whose end lies at X (on the body or the plane).
    solve = ok & ~exact & ~plane
    if solve.any():
        i = np.flatnonzero(solve)
        pt, body_pt, on_curve = _curve_point_at_x(wing, body, side, t[seg[i]], t[seg[i] + 1],
                                                  pts_e[seg[i]], pts_e[seg[i] + 1], X[i])
        out[i], on_body[i] = pt, body_pt
        theta[i] = np.where(body_pt, _body_angle(body, pt), theta[i])
        bridge = i[~on_curve]
        if bridge.size:  # across the jump: kept out of the wing, then out of the body
            out[bridge] = _onto_body(body, _onto_wing(wing, side, out[bridge]))
        for j in bridge:
            log.append(f"single network: {side} line at x = {X[j]:.6g} bridges the jump "
                       "where the lofting lines stop meeting the body")
    for j in np.flatnonzero(~ok):
        log.append(f"single network: no {side} line end lies at x = {X[j]:.6g}; the "
                   f"nearest one (x = {pts_e[near[j], 0]:.6g}) is used, moved to that x")
    out[:, 0] = X
    # The nearest end moved to x = X: a point on the body stays on it (its foot in that
    # plane), no longer on the wing.
    moved = ~ok & on_body
    if moved.any():
        out[moved] = _onto_body(body, out[moved], every=True)
        theta[moved] = _body_angle(body, out[moved])
        on_body[moved] = False
    return out, theta, on_body, log


def _blend_outside(body, pa, pb, w):
    """Points between pa and pb (k, 3) at weights w (k,): in the body's cylindrical
    coordinates (x, angle, height above the surface) for a circular body, so that points
    outside it stay outside; linear otherwise."""
    w = np.asarray(w, float)[:, None]
    x = (1 - w[:, 0]) * pa[:, 0] + w[:, 0] * pb[:, 0]
    if not hasattr(body, "section_at"):
        (s0, h0), (s1, h1) = (_section_coordinates(body, p) for p in (pa, pb))
        return _off_section(body, x, (1 - w[:, 0]) * s0 + w[:, 0] * s1,
                            (1 - w) * h0 + w * h1)
    polar = []
    for p in (pa, pb):
        c, r = body.section_at(p[:, 0])
        dy, dz = p[:, 1] - c[:, 0], p[:, 2] - c[:, 1]
        polar.append((np.arctan2(dz, dy), np.hypot(dy, dz) - r))
    (a0, h0), (a1, h1) = polar
    ang = a0 + w[:, 0] * ((a1 - a0 + np.pi) % (2 * np.pi) - np.pi)
    h = (1 - w[:, 0]) * h0 + w[:, 0] * h1
    c, r = body.section_at(x)
    return np.stack([x, c[:, 0] + (r + h) * np.cos(ang), c[:, 1] + (r + h) * np.sin(ang)], -1)


def _curve_point_at_x(wing, body, side, fa, fb, pa, pb, X, max_iter=80):
    """Points of one surface's end curve at x = X between chord fractions fa and fb.

    The end curve at a chord fraction f is where the lofting line of that fraction (straight
    between sections, extended inboard, TM-4406 eq 4) first meets the body coming inboard,
    or, if it misses, where it reaches the centre plane (:mod:`juncture.misses`); pa, pb are
    its points at fa, fb. Illinois regula falsi in f on x(f) - X. Where the curve jumps over
    X (from the body to the plane of symmetry, where a line stops meeting the body), the
    point is interpolated across the jump. Returns ``(points (k, 3), on_body (k,),
    on_curve (k,))``.
    """
    error, _ = _error(body)
    spans = wing.span_stations
    tol = 1e-13 * max(1.0, float(np.abs(body.x_global).max()))
    k = len(X)
    a, b = np.array(fa, float), np.array(fb, float)
    pa, pb = np.array(pa, float), np.array(pb, float)
    ga, gb = pa[:, 0] - X, pb[:, 0] - X
    hit_a = np.abs(_radial(body, pa)) <= 1e-9 * max(1.0, float(np.abs(body.x_global).max()))
    hit_b = np.abs(_radial(body, pb)) <= 1e-9 * max(1.0, float(np.abs(body.x_global).max()))
    pts, on_body = np.full((k, 3), np.nan), np.zeros(k, bool)
    done = np.zeros(k, bool)
    side_kept = np.zeros(k, int)
    origin = getattr(body, "origin", None)
    centre = 0.0 if origin is None else float(origin[1])
    u_low = min((centre - spans[0]) / (spans[1] - spans[0]), 0.0)
    for _ in range(max_iter):
        idx = np.flatnonzero(~done)
        if not idx.size:
            break
        with np.errstate(divide="ignore", invalid="ignore"):
            c = np.where(gb[idx] != ga[idx], b[idx] - gb[idx] * (b[idx] - a[idx]) /
                         (gb[idx] - ga[idx]), 0.5 * (a[idx] + b[idx]))
        bad = ~np.isfinite(c) | ((c - a[idx]) * (c - b[idx]) > 0)
        c = np.where(bad, 0.5 * (a[idx] + b[idx]), c)
        lines = wing.point(spans[None, :], c[:, None], side)
        # A dense scan, without the exact screening: near the jump the lines graze the
        # body, where proving that a line misses it is slow (and not needed here).
        cr = find_crossings(lines, error, u_low)
        pc = np.where(cr.found[:, None], cr.points, polyline_points(lines, np.full(
            (len(c), 1), u_low))[:, 0])
        gc = pc[:, 0] - X[idx]
        conv = np.abs(gc) <= tol
        pts[idx[conv]], on_body[idx[conv]] = pc[conv], cr.found[conv]
        done[idx[conv]] = True
        same = np.sign(gc) == np.sign(ga[idx])
        # Illinois: halve the retained end's value when the same end is kept twice.
        gb[idx] = np.where(same & (side_kept[idx] == 1), 0.5 * gb[idx], gb[idx])
        ga[idx] = np.where(~same & (side_kept[idx] == -1), 0.5 * ga[idx], ga[idx])
        for arr, new, cond in ((a, c, same), (b, c, ~same)):
            arr[idx] = np.where(cond, new, arr[idx])
        pa[idx] = np.where(same[:, None], pc, pa[idx])
        pb[idx] = np.where(same[:, None], pb[idx], pc)
        hit_a[idx] = np.where(same, cr.found, hit_a[idx])
        hit_b[idx] = np.where(same, hit_b[idx], cr.found)
        ga[idx] = np.where(same, gc, ga[idx])
        gb[idx] = np.where(same, gb[idx], gc)
        side_kept[idx] = np.where(same, 1, -1)
        # A bracket that closes without reaching X is a jump of the curve.
        done[idx[np.abs(b[idx] - a[idx]) <= 1e-14]] = True
    jump = ~np.isfinite(pts[:, 0])
    if jump.any():
        # Across the jump: the wing surface's point at X between the two ends (in span
        # station and chord fraction), if it is outside the body, else a point outside it.
        dx = pb[jump, 0] - pa[jump, 0]
        w = np.clip(np.where(dx != 0, (X[jump] - pa[jump, 0]) / np.where(dx != 0, dx, 1.0),
                             0.0), 0.0, 1.0)
        on_wing = _wing_point_at_x(wing, side, pa[jump], pb[jump], w, X[jump])
        outside = _blend_outside(body, pa[jump], pb[jump], w)
        pts[jump] = np.where((_radial(body, on_wing) >= 0)[:, None], on_wing, outside)
    pts[:, 0] = X
    return pts, on_body & ~jump, ~jump


def _onto_wing(wing, side, pts):
    """Points (..., 3) inside the wing moved along its thickness axis onto the ``side``
    surface at their span station and chord fraction; others unchanged."""
    shape = pts.shape[:-1]
    p = pts.reshape(-1, 3).copy()
    span, frac = _fraction(wing, p)
    a_t = wing.thickness_axis
    f = np.clip(frac, 0.0, 1.0)
    lo = wing.point(span, f, "lower", extrapolate=True)[:, a_t]
    up = wing.point(span, f, "upper", extrapolate=True)[:, a_t]
    inside = (frac > 0) & (frac < 1) & (p[:, a_t] > lo) & (p[:, a_t] < up)
    p[:, a_t] = np.where(inside, lo if side == "lower" else up, p[:, a_t])
    return p.reshape(shape + (3,))


def _chord_where_buried(wing, body, out, ok):
    """Fillet lines (m, n, 3) whose inner points still lie inside a solid after they were
    put onto the wing and then onto the body (a line a few thousandths of a foot long beside
    a sharp trailing edge, where the wing's surface at a point's chord fraction lies inside
    the body and the body's inside the wing: the point is in the solids' overlap) have
    those points on the straight chord from the line's start on the body to its end on the
    wing, which crosses the wedge of air between the two surfaces."""
    inner = np.zeros(out.shape[:2], bool)
    inner[:, 1:-1] = ok[:, None]
    if not inner.any():
        return out
    buried = inner & ~_outside(wing, body, out)
    if not buried.any():
        return out
    t = np.linspace(0.0, 1.0, out.shape[1])[None, :, None]
    chord = (1 - t) * out[:, :1] + t * out[:, -1:]
    return np.where(buried[..., None], chord, out)


def _onto_body(body, pts, every=False):
    """Points (..., 3) inside the body (``every``: all of them) moved onto its surface in
    their plane x = const (radially on a circular body, to the nearest point of an arbitrary
    section)."""
    shape = pts.shape[:-1]
    p = pts.reshape(-1, 3).copy()
    inside = np.ones(len(p), bool) if every else _radial(body, p) < 0
    if inside.any():
        q = p[inside]
        if hasattr(body, "section_at"):
            c = body.center_at(q[:, 0])
            foot = body.point(q[:, 0], np.arctan2(q[:, 2] - c[:, 1], q[:, 1] - c[:, 0]))
        else:
            foot = body.point(q[:, 0], body.parameter_of(q))
        p[inside] = foot
    return p.reshape(shape + (3,))


def _outside(wing, body, pts):
    """Whether points (..., 3) lie outside the body and outside the wing (extended inboard).

    The wing's solid is between its lower and upper surfaces at the point's span station
    and chord fraction (0 to 1).
    """
    shape = pts.shape[:-1]
    p = pts.reshape(-1, 3)
    scale = 1e-12 * max(1.0, float(np.abs(p).max()))
    span, frac = _fraction(wing, p)
    a_t = wing.thickness_axis
    lo = wing.point(span, np.clip(frac, 0.0, 1.0), "lower", extrapolate=True)[:, a_t]
    up = wing.point(span, np.clip(frac, 0.0, 1.0), "upper", extrapolate=True)[:, a_t]
    in_wing = (frac > 0) & (frac < 1) & (p[:, a_t] > lo + scale) & (p[:, a_t] < up - scale)
    in_body = _radial(body, p) < -scale
    return (~in_wing & ~in_body).reshape(shape)


def _section_coordinates(body, pts):
    """Points (..., 3) off an arbitrary section as (surface parameter (...) of their nearest
    point on it, their offset (..., 2) in y, z from that point)."""
    flat = np.asarray(pts, float).reshape(-1, 3)
    shape = np.shape(pts)[:-1]
    s = body.parameter_of(flat)
    foot = body.point(flat[:, 0], s)
    return s.reshape(shape), (flat - foot)[:, 1:].reshape(shape + (2,))


def _off_section(body, x, s, offset):
    """The inverse of :func:`_section_coordinates`: the section point at (x, s) plus the
    offset (exact for the points it was taken from, and linear between them)."""
    p = body.point(x, s)
    p[..., 1:] += offset
    return p


def _radial(body, pts):
    if hasattr(body, "radial_error"):
        return body.radial_error(pts)
    return body.signed_distance(pts)


def single_network(wing, body, upper, lower, n_half=None, stations=None):
    """Fuselage as one network (TM-4406 fig 5) plus the two wing networks (6-block style).

    ``upper`` and ``lower`` must start at the same stations (re-interpolated). Returns
    ``(networks, seams)`` as :func:`juncture.surface.networks.juncture_networks`.
    """
    pc = layout_pieces(wing, body, upper, lower, n_half, stations)
    n_below = pc["n_below"]

    def doubled(sections):  # the point at theta_w twice, as in the wing region's rows
        return np.concatenate([sections[:, :n_below], sections[:, n_below - 1:]], axis=1)

    region = np.concatenate([pc["arc_l"], pc["arc_u"][:, ::-1]], axis=1)
    single = np.concatenate([doubled(pc["ahead"][:-1]), region, doubled(pc["behind"][1:])])
    strip_u, strip_l = pc["strip_u"], pc["strip_l"]
    seams = []
    for a, b, name, pa, pb in (
            ("body", "wing upper", "upper fillet start line", pc["arc_u"][:, -1], strip_u[:, 0]),
            ("body", "wing lower", "lower fillet start line", pc["arc_l"][:, -1], strip_l[:, 0]),
            ("wing upper", "wing lower", "leading-edge lofting line", strip_u[0], strip_l[0]),
            ("wing upper", "wing lower", "trailing-edge lofting line", strip_u[-1],
             strip_l[-1])):
        seams.append({"a": a, "b": b, "seam": name, "points": int(len(pa)),
                      "max_gap": float(np.linalg.norm(pa - pb, axis=-1).max())})
    nets = {"body": orient(single, radial_outward(body)),
            "wing upper": orient(np.swapaxes(strip_u, 0, 1), np.array([0.0, 0.0, 1.0])),
            "wing lower": orient(np.swapaxes(strip_l, 0, 1), np.array([0.0, 0.0, -1.0]))}
    return nets, seams


def reinterpolated(wing, body, upper, lower, upper_inter, lower_inter, fillet):
    """Upper and lower lines for the single network, both at the upper starts' x.

    Without a fillet (``fillet`` None) the lower points are re-interpolated on the end curve
    (:func:`line_end_at`); circular fillet lines of both surfaces are rebuilt in the planes
    x = X (:func:`planar_arcs_at`); cubic ones of the lower surface re-interpolated whole
    (:func:`interpolated_lines`). Returns ``(upper, lower, lower_points)``, the last the
    lower intersection line to report: without a fillet the re-interpolated points on the
    body, NaN where a point is not on it; with one, the lower intersection itself.
    """
    from .misses import line_ends

    X = upper.start[:, 0]
    ends = line_ends(wing, body, lower_inter)
    if fillet == "circular":
        return (planar_arcs_at(wing, body, upper, line_ends(wing, body, upper_inter), X),
                planar_arcs_at(wing, body, lower, ends, X), lower_inter.points)
    if fillet is not None:
        return upper, interpolated_lines(wing, body, lower, ends, X), lower_inter.points
    pts, theta, on_body, log = line_end_at(wing, body, ends, X)
    out = _rebuilt(lower, points=pts[:, None, :].copy(), start=pts.copy(), end=pts.copy(),
                  theta_start=theta, log=tuple(lower.log) + tuple(log))
    return upper, out, np.where(on_body[:, None], pts, np.nan)
