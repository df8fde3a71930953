"""Cubic-arc fillet lines of a wing-body juncture (TM-4406 eq 7) with LE/TE blending (eqs 8-10).

For each lofting line j of one wing surface (upper or lower) a fillet line runs from a start
point B on the body's cross-section circle through the intersection point I, an angular
distance theta_u above (upper) or below (lower) I, to an end point E on the lofting line. It is
the cubic f(s) = a1 + a2 s + a3 s^2 + a4 s^3 tangent to the body circle at B and to the
lofting line at E (eq 7): a Hermite cubic, here also written with its Bezier control points
B, P1 = B + T_B / 3, P2 = E - T_E / 3, E (``FilletLines.control``).

**A fillet that stays a fillet** (issue 11; TM-4406 lets the cubic dip through the wing, see
its "Special situations", and its start tangent reverses where B lies past the horizontal).
A Bezier curve lies in the convex hull of its control points. P1 lies on the body's tangent
at B (the start tangent), P2 and E on the lofting line (the end tangent), so the curve stays
between body and wing when P1 and B are on the fillet's side of the wing and P2 and E on the
outer side of the body, each against two planes:

- the wing's tangent plane along the lofting line at E (its chordwise slope included: a point
  of the fillet beside the line lies at another chord fraction) and the plane through the
  lofting line along x (its trace in x = const is the projected line, so each fillet's
  cross-section polygon stays simple);
- the body's tangent plane at B (with the slopes of r(x) and of the centre line: the body is
  locally a cone, and the fillet runs in x from x_I to x_E) and the circle's tangent plane
  along x.

So, per line:

- **theta_u.** In the cross-section plane the tangent at B meets the wing line at K. With phi
  the arc from I to B and phi_max the whole body-wing angle at I (pi/2 - theta_i + delta
  above, pi/2 + theta_i - delta below, delta the wing line's angle in the y-z plane: so
  phi_max(upper) + phi_max(lower) = pi; the smaller of the values for the wing's plane and
  the projected line), ``|IK| = r (1 - cos phi) / sin(phi_max - phi)``
  (:func:`tangent_intersection_distance`). Where that exceeds half of |IE| (the obtuse side
  of a high or low wing; a wing nearly tangent to the body) theta_u is reduced on that line to
  the angle that puts K half-way (closed form) and the log says so. As phi_max goes to 0 the
  fillet shrinks continuously to the sharp intersection ("no room for a fillet").
- **Tangent lengths.** The paper's parameter s = y (|T_B| = dy / t_By, |T_E| = dy / t_Ey,
  dy = y_E - y_B: P1 and P2 a third and two thirds of the way in y) wherever that keeps P1
  and P2 within the longest legs the planes allow; elsewhere the legs' lengths (clipped).
  Where the chord B -> E runs less than 60 deg from the y axis (s = y is singular at dy =
  0) the thirds are taken along a direction turned continuously from y towards the chord.
  Where the paper's lengths reach a little past the legs (up to 1.5 times) they are kept as
  far as the curve stays clear of the surfaces themselves (checked on 33 points; on the
  bundled transport the paper's cubic is kept on every line where it fits). How far is the
  root of a continuous clearance margin, so the fillet moves continuously with the geometry
  (keep_area's Newton steps rely on it; eighths of the way jumped).
- **Safety net.** The planes are the surfaces' tangents; over a long fillet a twisted or
  curved wing can leave less room. Every line is checked against the surfaces themselves
  (33 points, and the radial gap's second derivative at B), and where one enters either,
  phi is reduced by bisection (a line with phi = 0 lies on the wing).

The paper's cubic is thus kept where it stays between body and wing, and continued
continuously elsewhere. Along x, the control points have x_I, x_I, x of P2 on the lofting
line, x_E: x runs monotonically from the intersection's station to the end point's.

**End point** (the paper's three options, counted on the lofting-line segment that holds I:
TM-4406's "first and second sections" are the root segment): ``end="section"`` puts E at
the fraction ``end_value`` of that segment from its inboard section; ``"intersection"`` at
that fraction of the distance from I to the outboard section; ``"dy"`` at a span increment
``end_value`` from I. E is held where the lofting line first bends outboard of I (sections
it runs straight through do not count), so the wing between I and E is straight and the
curve cannot cut a corner of it; the log says where.

Near the leading and trailing edges the fillet is blended into the sharp intersection over a
length l_b in x, with beta(L) = sin(pi L / 2) and L = (x - x_le) / l_b (eqs 8-9). Two ways:

- ``blending="points"`` is eq 10 as printed: f_t = (1 - beta) v + beta f, v being the point on
  the extrapolated lofting line between I and E at the same s. Its first point lies on the
  chord between I and B, slightly inside the body, so the body arc and the fillet do not
  quite meet where 0 < beta < 1.
- ``blending="scale"`` (default) scales the fillet instead: theta_u -> beta theta_u and the end
  point -> I + beta (E - I) along the lofting line. It passes through the same two limits
  (a sharp intersection at beta = 0, the full fillet at beta = 1), but every fillet line starts
  on the body and stays tangent to both surfaces and between them, so the output networks
  are watertight.

**A lofting line that misses the body** (``missed_lines``): by default ("plane") the line has
no fillet and is degenerate where the lofting line reaches the plane of symmetry, as without
a fillet (:mod:`juncture.misses`). TM-4406's special case ("paper": start at theta = -90 deg
with dx/dy = dz/dy = 0) is kept as an option, but it always lies partly inside the wing: the
body's bottom is above the wing's lower surface there (the line passes under the body), so
the start point is inside the wing or above it, and the curve must cross the wing to reach
its lower surface.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Literal

import numpy as np

from ..errors import GeometryError
from ..intersect import BodyIntersection, polyline_points
from .clearance import line_runs, tolerance, wing_depth
from .endpoint import _end_coordinate, _line_direction, _segment
from .lines import FilletLines, bezier, blend_factor, blend_over, hermite
from .section import section_frame

__all__ = ["FilletLines", "cubic_fillet", "EndMode", "Blending", "MissedLines", "hermite",
           "bezier", "blend_factor", "blend_over", "tangent_intersection_distance"]

EndMode = Literal["section", "intersection", "dy"]
Blending = Literal["scale", "points"]
MissedLines = Literal["plane", "paper"]

#: Default angular distance of the fillet start from the intersection [rad] (20 deg).
THETA_U_DEFAULT = float(np.radians(20.0))
#: The tangent intersection K may lie at most this fraction of the way from I to E.
K_SHARE = 0.5
#: Below this share dy / |E - B|, kappa is measured along a direction turned to the chord.
_Y_SHARE = 0.5


def tangent_intersection_distance(radius, phi, phi_max):
    """|IK|: where the circle's tangent at B meets the wing line, measured from I.

    B lies an arc ``phi`` from I on a circle of ``radius``; the wing line leaves I at the
    angle ``pi - phi_max`` to the circle's tangent towards B (``phi_max``: the body-wing
    angle at I). In the triangle I T K (T where the tangents at I and B meet, |TI| =
    r tan(phi / 2)) the angles are pi - phi_max at I and phi at T, so by the law of sines
    ``|IK| = r tan(phi / 2) sin(phi) / sin(phi_max - phi) = r (1 - cos phi) /
    sin(phi_max - phi)`` [deck length]; infinite for phi >= phi_max.

    Examples
    --------
    >>> round(float(tangent_intersection_distance(1.0, np.pi / 4, np.pi / 2)), 12)
    0.414213562373
    """
    radius, phi, phi_max = (np.asarray(a, float) for a in (radius, phi, phi_max))
    den = np.sin(phi_max - phi)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = radius * (1.0 - np.cos(phi)) / den
    return np.where((phi < phi_max) & (den > 0), out, np.inf)


def _fit_angle(radius, length, phi_max):
    """Largest phi in [0, phi_max) with |IK|(phi) <= length (closed form).

    r (1 - cos phi) = c sin(phi_max - phi) is A cos phi + b sin phi = r with A = r +
    c sin phi_max, b = -c cos phi_max; its root in (0, phi_max) is gamma + acos(r / R),
    R = hypot(A, b), gamma = atan2(b, A).
    """
    c = np.maximum(length, 0.0)
    a = radius + c * np.sin(phi_max)
    b = -c * np.cos(phi_max)
    big = np.hypot(a, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        phi = np.arctan2(b, a) + np.arccos(np.clip(radius / big, -1.0, 1.0))
    ok = (phi_max > 0) & (c > 0) & (big > 0)
    return np.where(ok, np.clip(np.nan_to_num(phi), 0.0, np.maximum(phi_max, 0.0)), 0.0)


def _wing_normal(wing, side, points, t_e, sign, inboard=None, h=1e-6):
    """(m, 3) unit normal of the wing surface at points on its lofting lines, away from the
    wing (up for the upper surface): the chordwise derivative crossed with the line.

    Where the surface has no chordwise extent there (a pointed tip), the normal a hundredth
    of the way back towards ``inboard`` is taken, and failing that the normal of the plane
    through the line along x."""
    f = np.asarray(wing.x_over_c, float) / 100.0
    lo, hi = np.clip(f - h, 0.0, 1.0), np.clip(f + h, 0.0, 1.0)

    def normal(at):
        span = at[:, wing.span_axis]
        d_f = (wing.point(span, hi, side, extrapolate=True)
               - wing.point(span, lo, side, extrapolate=True)) / (hi - lo)[:, None]
        n = np.cross(d_f, t_e) * sign
        size = np.linalg.norm(n, axis=1)
        ok = size > 1e-9 * np.maximum(np.linalg.norm(d_f, axis=1), 1e-300)
        ok &= size > 1e-12 * max(float(np.abs(wing.chord).max()), 1.0)
        return n / np.where(ok, size, 1.0)[:, None], ok

    n, ok = normal(points)
    if inboard is not None and not ok.all():
        n2, ok2 = normal(points + 0.01 * (inboard - points))
        n = np.where(ok[:, None], n, n2)
        ok = ok | ok2
    if not ok.all():
        flat = np.stack([np.zeros(len(t_e)), -t_e[:, 2], t_e[:, 1]], axis=1) * sign
        flat /= np.maximum(np.linalg.norm(flat, axis=1), 1e-300)[:, None]
        n = np.where(ok[:, None], n, flat)
    return n


def _ray_to_plane(origin, direction, normal, on_plane, scale):
    """Distance along ``direction`` from ``origin`` to the plane through ``on_plane`` whose
    ``normal`` points to the side ``origin`` should be on (all (m, 3)).

    0 where ``origin`` is on the plane or on its other side (no room); at most |scale|, which
    is also the value where the ray runs parallel to the plane or away from it (the plane
    sets no limit there, and a shorter leg keeps the control point on the same side).
    """
    gap = ((origin - on_plane) * normal).sum(1)
    rate = -(direction * normal).sum(1)
    far = np.linalg.norm(scale, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.minimum(gap / rate, far)
    return np.where(gap <= 0, 0.0, np.where(rate > 0, out, far))


def _clear(wing, side, body, control, tol, corner, n=17):
    """Lines (m,) whose cubic stays out of the body and the wing (both :func:`_margins`
    >= 0)."""
    inner, ends = _margins(wing, side, body, control, tol, corner, n)
    return np.minimum(inner, ends) >= 0.0


def _margins(wing, side, body, control, tol, corner, n=17):
    """((m,), (m,)) how far each line's cubic stays out of the body and the wing between its
    ends and at them, >= 0 where it does (NaN where a sample cannot be placed: not clear):
    sampled densely (also in projection on x = x_I, against the body circle and the
    straight wing line from E back to the ``corner`` I), each sample's depth inside either
    less ``tol``; between the ends also at its start, where it leaves the body
    tangentially, by the second derivative of the radial gap, e''(0) = |T_B|^2 / r +
    6 N_B . (P2 - B) >= 0 (N_B the body's normal with the cone's slope, unnormalised), over
    its scale. Each term is continuous in the control points, so the least is too: where it
    changes sign the curve starts to enter a surface. The ends lie on the surfaces by
    construction (their margin is about ``tol`` whatever the curve does between them)."""
    p = bezier(control, np.linspace(0.0, 1.0, n))
    out_body = body.distance(p.reshape(-1, 3)).reshape(p.shape[:2]) + tol
    out_wing = tol - wing_depth(wing, p)
    B = control[:, 0]
    flat = body.plane_gap(p, B[:, 0]) + tol
    line = control[:, 3, 1:] - corner[:, 1:]
    normal = np.stack([-line[:, 1], line[:, 0]], axis=1)
    normal *= np.where((normal * (B[:, 1:] - corner[:, 1:])).sum(1) < 0, -1.0, 1.0)[:, None]
    normal /= np.maximum(np.linalg.norm(normal, axis=1), 1e-300)[:, None]
    above = ((p[..., 1:] - corner[:, None, 1:]) * normal[:, None]).sum(-1) + tol
    least = np.minimum(np.minimum(out_body, out_wing), np.minimum(flat, above))
    least = np.where(np.isfinite(p).all(-1), least, np.inf)
    bend, scale = body.bend(control)
    with np.errstate(divide="ignore", invalid="ignore"):
        start = bend / scale + 1e-12
    inner = np.minimum(least[:, 1:-1].min(axis=1, initial=np.inf),
                       np.where(np.isnan(start), np.inf, start))
    return inner, np.minimum(least[:, 0], least[:, -1])


def _leg_share(along, rate, leg):
    """Share of the longest leg that the paper's tangent length takes (s = y generalised to
    s along v: |T| = (chord . v) / (t . v), the control point a third of the way along v);
    +inf where t . v <= 0 (the tangent runs backwards along v: its length is not bounded by
    the paper's rule, so the longest leg is taken)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        share = along / (3.0 * rate * leg)
    return np.where((rate > 0) & (leg > 0), share, np.inf)


def _cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def cubic_fillet(wing, body, inter: BodyIntersection, theta_u=THETA_U_DEFAULT,
                 end: EndMode = "intersection", end_value=0.5, blend_length=None,
                 n_points=9, remedy=None, upper_reference=None, blending: Blending = "scale",
                 blend_range=None, missed_lines: MissedLines = "plane", towards=None):
    """Cubic-arc fillet lines for one surface (TM-4406 eq 7, eqs 8-10).

    Parameters
    ----------
    wing : WingLike
    body : CircularBody
    inter : BodyIntersection
        The intersection of this surface (``inter.side``) with the body.
    theta_u : float or (n_stations,) float
        Angular distance of the start point from the intersection along the body circle,
        upward for the upper surface, downward for the lower [rad]; reduced on a line where
        the fillet would not fit between body and wing (module docstring).
    end, end_value :
        End-point option and its value (see the module docstring).
    blend_length : float, optional
        l_b of eq 8 [deck length]; default a tenth of the intersection line's x extent.
    n_points : int
        Points per fillet line (>= 2), equally spaced in s.
    remedy : {None, "z-constraint", "parabolas"}
        TM-4406's remedies for a fillet that dips through the extrapolated wing surface. The
        fillet here cannot dip (module docstring), so "z-constraint" (clamp to that surface)
        never acts; it is kept for old option sets. "parabolas" is the method of blended
        parabolas (Overhauser) with the neighbouring points taken on the end tangents, so
        that it stays tangent at both ends: P0 = E - 2 T_B on the body's tangent at B and
        P3 = B + 2 T_E on the lofting line, with the lengths the paper's neighbours give
        (|E - P0'| / 2 and |P3' - B| / 2 for P0' on the circle 10 deg beyond B, P3' one
        chord beyond E), limited to the longest legs (module docstring).
    upper_reference : BodyIntersection, optional
        With ``missed_lines="paper"``: where the lower-surface line misses the body, the x of
        the fillet start is taken from this upper-surface intersection's line.
    blending : {"scale", "points"}
        How the fillet is blended out towards the leading and trailing edges (module docstring).
    blend_range : (x_le, x_te, l_b), optional
        A fixed blending region (see :func:`blend_over`), e.g. a previous fillet's
        ``blend_range``; ``blend_length`` is then ignored.
    missed_lines : {"plane", "paper"}
        Lofting lines that miss the body: no fillet, the line degenerate where it reaches the
        plane of symmetry (default), or TM-4406's start at the bottom (module docstring).
    towards : (n_stations,) float, optional
        A previous fillet's ``towards`` (how far each line's tangent lengths went towards
        the paper's): kept on every line where its curve is still clear of both surfaces,
        so that the fillet on a re-designed body is a smooth function of it (keep_area).

    Returns
    -------
    FilletLines
        With ``control``, the Bezier control points of every line.

    Raises
    ------
    GeometryError
        An end option that puts E inboard of I (``end="section"`` with a fraction short of
        the intersection), naming the line; with ``missed_lines="paper"``, an end point not
        outboard of the start.
    """
    side = inter.side
    sign = 1.0 if side == "upper" else -1.0
    _check_options(wing, blending, remedy, missed_lines)
    body = section_frame(body)
    if not body.circular and blending == "points":
        raise GeometryError("fillet blending 'points' (TM-4406 eq 10 as printed) starts inside "
                            "a circular body's section; on an arbitrary-section fuselage use "
                            "blending='scale'", wing.name)
    lines = wing.lofting_lines(side)
    m = lines.shape[0]
    found = np.asarray(inter.found, bool)
    log = []
    st = _line_starts(wing, body, inter, lines, end, end_value, missed_lines,
                      upper_reference, sign, log)
    I, theta_i, u_full, k = st["I"], st["theta_i"], st["u_full"], st["k"]
    paper_miss, plane_miss = st["paper_miss"], st["plane_miss"]
    x_i = I[:, 0]
    beta, blend_range = blend_over(x_i, blend_length, blend_range)
    beta = np.where(paper_miss, 1.0, np.where(plane_miss, 0.0, beta))
    scale = beta if blending == "scale" else np.ones(m)
    scale = np.where(plane_miss, 0.0, scale)
    theta_u = np.broadcast_to(np.asarray(theta_u, float), (m,))
    phi, k_full = _start_angles(wing, body, side, sign, lines, I, theta_i, u_full, k, found,
                                scale, theta_u, log)
    u_e = st["u_i"] + scale * (u_full - st["u_i"])
    E = polyline_points(lines, u_e[:, None])[:, 0]
    live = scale > 0
    # The end tangent and the wing's plane where the (blended) end point lies.
    t_e = _line_direction(lines, u_e, k, found, k_full)
    n_e = _wing_normal(wing, side, E, t_e, sign, I)
    if paper_miss.any():
        _check_paper_starts(body, side, wing, E, x_i, theta_i, paper_miss)
    con = _Construction(body, E, t_e, n_e, x_i, theta_i, sign, scale, paper_miss, live, remedy)
    phi = _safety_net(con, wing, side, body, I, found & live & ~paper_miss, phi, log)
    geo = con.geometry(phi)
    B, theta_b, T0, T1, control, reach = con.finish(geo)
    share = np.full(len(I), np.nan)
    if reach.any():
        control, T0, T1, share[reach] = _towards_paper(con, geo, wing, side, body, I, reach,
                                                       control, T0, T1, towards)
    out = _assembled(wing, body, side, sign, n_points, remedy, blending, I, B, E, T0, T1,
                     control, theta_b, u_e, beta, n_e, live, plane_miss, st["ends"],
                     blend_range, log)
    return replace(out, towards=share)


def _check_options(wing, blending, remedy, missed_lines):
    if blending not in ("scale", "points"):
        raise GeometryError(f"fillet blending must be 'scale' or 'points', found {blending!r}",
                            wing.name)
    if remedy not in (None, "z-constraint", "parabolas"):
        raise GeometryError(f"fillet remedy must be None, 'z-constraint' or 'parabolas', found "
                            f"{remedy!r}", wing.name)
    if missed_lines not in ("plane", "paper"):
        raise GeometryError(f"missed_lines must be 'plane' or 'paper', found {missed_lines!r}",
                            wing.name)


def _line_starts(wing, body, inter, lines, end, end_value, missed_lines, upper_reference,
                 sign, log):
    """I, theta_I and the section coordinates of I and of the requested E per line, with
    the lines that miss the body handled as ``missed_lines`` says (appends to ``log``)."""
    side = inter.side
    n_sec = lines.shape[1]
    missed = ~np.asarray(inter.found, bool)
    k = _segment(inter.u, n_sec)
    u_full, held = _end_coordinate(wing, inter, end, end_value, k, side, lines)
    I, theta_i, u_i = inter.points.copy(), inter.theta.copy(), inter.u.copy()
    paper_miss = missed & (missed_lines == "paper")
    plane_miss = missed & (missed_lines == "plane")
    ends = None
    if paper_miss.any():
        # TM-4406's special case: start at theta = -90 deg (+90 above), at the x of the upper
        # intersection of the same line (else the line's root x), with dx/dy = dz/dy = 0.
        x_ref = lines[:, 0, 0] if upper_reference is None else np.where(
            upper_reference.found, upper_reference.points[:, 0], lines[:, 0, 0])
        theta_i[paper_miss] = body.extreme(sign)
        I[paper_miss] = body.point(x_ref[paper_miss], theta_i[paper_miss])
        u_full[paper_miss], u_i[paper_miss], k[paper_miss] = 0.0, 0.0, 0
        for j in np.flatnonzero(paper_miss):
            log.append(f"{wing.name} {side} fillet line {j + 1}: lofting line misses "
                       f"{body.name}; fillet starts at theta = {np.degrees(theta_i[j]):.0f} deg "
                       "with dx/dy = dz/dy = 0 (TM-4406 special case; it lies partly inside "
                       "the wing)")
    if plane_miss.any():
        from ..misses import line_ends

        ends = line_ends(wing, body.body, inter)
        I[plane_miss], theta_i[plane_miss] = ends.points[plane_miss], ends.theta[plane_miss]
        u_i[plane_miss] = u_full[plane_miss] = ends.u[plane_miss]
        log.append(f"{wing.name} {side} fillet lines {line_runs(np.flatnonzero(plane_miss))}: the "
                   f"lofting line misses {body.name}; no fillet there (the line ends on the "
                   "plane of symmetry; TM-4406's start at the body's bottom would lie inside "
                   "the wing)")
    if held.any():
        log.append(f"{wing.name} {side} fillet lines {line_runs(np.flatnonzero(held))}: end point "
                   "held at the next section where the lofting line bends (the fillet ends on "
                   "the straight part of the line that holds the intersection)")
    return {"I": I, "theta_i": theta_i, "u_i": u_i, "u_full": u_full, "k": k,
            "paper_miss": paper_miss, "plane_miss": plane_miss, "ends": ends}


def _start_angles(wing, body, side, sign, lines, I, theta_i, u_full, k, found, scale,
                  theta_u, log):
    """theta_u per line, reduced where the fillet would not fit between the body and the
    wing's tangent plane (appends to ``log``), and the segment of the requested E."""
    m, n_sec = lines.shape[:2]
    # The wing's tangent plane along the lofting line (at the requested end point) and its
    # trace in the cross-section plane x = x_I (module docstring).
    E_full = polyline_points(lines, u_full[:, None])[:, 0]
    t_full = _line_direction(lines, u_full, k, found)
    k_full = np.clip(np.ceil(np.nan_to_num(u_full) - 1e-9) - 1, 0, n_sec - 2).astype(int)
    n_w = _wing_normal(wing, side, E_full, t_full, sign, I)
    trace = np.stack([-n_w[:, 2], n_w[:, 1]], axis=1)
    trace *= np.where((trace * t_full[:, 1:]).sum(1) < 0, -1.0, 1.0)[:, None]
    # The body-wing angle at I, against the wing's plane and against the lofting line
    # projected into x = x_I (the cross-section the added area is measured in): the fillet
    # keeps to the smaller wedge of the two.
    projected = t_full[:, 1:] / np.linalg.norm(t_full[:, 1:], axis=1)[:, None]
    phi_max = np.minimum(body.wedge(trace, I[:, 0], theta_i, sign),
                         body.wedge(projected, I[:, 0], theta_i, sign))
    r_i = body.ref_radius(I[:, 0])
    mu_full = np.linalg.norm(E_full[:, 1:] - I[:, 1:], axis=1)
    phi_fit = _fit_angle(r_i, K_SHARE * mu_full, phi_max)
    phi = np.where(found, np.minimum(theta_u, phi_fit), theta_u)
    reduced = found & (scale > 0) & (phi < theta_u)
    phi = _within_half(body, side, sign, theta_i, found, scale, phi, wing, log)
    if reduced.any():
        worst = int(np.argmin(np.where(reduced, phi, np.inf)))
        log.append(f"{wing.name} {side} fillet lines {line_runs(np.flatnonzero(reduced))}: theta_u "
                   f"reduced (to {np.degrees(phi[worst]):.3g} deg on line {worst + 1}, where "
                   f"body and wing meet at {np.degrees(phi_max[worst]):.3g} deg) so that the "
                   "fillet stays between body and wing")
    tight = found & (scale > 0) & (phi_max < np.radians(1.0))
    if tight.any():
        log.append(f"{wing.name} {side} fillet lines {line_runs(np.flatnonzero(tight))}: the wing "
                   f"is nearly tangent to {body.name} (less than 1 deg between them): no room "
                   "for a fillet there, the line is left nearly sharp")
    return phi, k_full


def _within_half(body, side, sign, theta_i, found, scale, phi, wing, log):
    """``phi`` no larger than the arc from the intersection to the plane of symmetry on its
    side (the top above a high wing, the bottom below a low one): a start past it lay on the
    other half of the fuselage, whose rows then ran back over the plane of symmetry and
    crossed their own mirror image (held-out high wings with a cubic fillet). The start is
    then at the top (bottom), where the fillets of both halves meet. A polyline section's
    start is kept on its half by its frame (:class:`~juncture.fillet.section.PolylineFrame`)."""
    if not getattr(body, "circular", False):
        return phi
    room = np.maximum(sign * (body.extreme(sign) - theta_i), 0.0)
    over = found & (scale > 0) & (scale * phi > room)
    if not over.any():
        return phi
    log.append(f"{wing.name} {side} fillet lines {line_runs(np.flatnonzero(over))}: theta_u "
               f"reduced so that the fillet starts no further than the plane of symmetry "
               f"({'top' if sign > 0 else 'bottom'} of {body.name})")
    return np.where(over, room / np.where(scale > 0, scale, 1.0), phi)


def _check_paper_starts(body, side, wing, E, x_i, theta_i, paper_miss):
    dy = E[:, 1] - body.point(x_i, theta_i)[:, 1]
    bad = paper_miss & (dy <= 0)
    if bad.any():
        j = int(np.argmax(bad))
        raise GeometryError(f"{side} fillet line {j + 1}: the end point is not outboard of "
                            "the start point at the body's bottom (TM-4406 special case); "
                            "use missed_lines='plane' or move the end point out",
                            wing.name, j + 1)


class _Construction:
    """The Bezier construction of one surface's fillet lines for given start arcs phi."""

    def __init__(self, body, E, t_e, n_e, x_i, theta_i, sign, scale, paper_miss, live,
                 remedy):
        m = len(E)
        self.body, self.E, self.t_e, self.n_e = body, E, t_e, n_e
        self.x_i, self.theta_i, self.sign, self.scale = x_i, theta_i, sign, scale
        self.paper_miss, self.live, self.remedy, self.m = paper_miss, live, remedy, m
        # The plane through the lofting line along x (its trace in x = const is the
        # projected line: keeping to it keeps each fillet's cross-section polygon simple).
        n_e2 = np.stack([np.zeros(m), -t_e[:, 2], t_e[:, 1]], axis=1) * sign
        self.n_e2 = n_e2 / np.linalg.norm(n_e2, axis=1)[:, None]

    def geometry(self, phi):
        """Start point, tangent, longest legs and the paper's shares for arcs ``phi``."""
        E, t_e, sign, paper_miss = self.E, self.t_e, self.sign, self.paper_miss
        theta_b = np.where(paper_miss, self.theta_i,
                           self.body.start(self.x_i, self.theta_i, sign, self.scale * phi))
        B = self.body.point(self.x_i, theta_b)
        # The section's tangent at B pointing towards the wing (back towards I).
        t_b = self.body.tangent(self.x_i, theta_b, sign)
        t_b[paper_miss] = [0.0, 1.0, 0.0]
        dy = E[:, 1] - B[:, 1]
        # The longest legs that keep the control polygon between the two tangent planes: P1
        # on the body's tangent at B up to the wing's plane, P2 on the lofting line back to
        # the body's tangent plane at B.
        n_b = self.body.normal(self.x_i, theta_b, sign)
        n_b2 = self.body.normal2(self.x_i, theta_b, sign)
        leg_b = np.minimum(_ray_to_plane(B, t_b, self.n_e, E, E - B),
                           _ray_to_plane(B, t_b, self.n_e2, E, E - B))
        leg_e = np.minimum(_ray_to_plane(E, -t_e, n_b, B, E - B),
                           _ray_to_plane(E, -t_e, n_b2, B, E - B))
        chord = E[:, 1:] - B[:, 1:]
        c_len = np.linalg.norm(chord, axis=1)
        c_dir = chord / np.where(c_len > 0, c_len, 1.0)[:, None]
        mix = np.maximum(0.0, _Y_SHARE - c_dir[:, 0])
        v = np.stack([1.0 + mix * c_dir[:, 0], mix * c_dir[:, 1]], axis=1)
        along = (chord * v).sum(1)
        share_b = _leg_share(along, (t_b[:, 1:] * v).sum(1), leg_b)
        share_e = _leg_share(along, (t_e[:, 1:] * v).sum(1), leg_e)
        eligible = (mix == 0) & (dy > 0) & np.isfinite(share_b) & np.isfinite(share_e) & \
            (share_b > 0) & (share_e > 0)
        return theta_b, B, t_b, dy, leg_b, leg_e, share_b, share_e, eligible

    def finish(self, geo, w=0.0):
        """Tangents and control points, and the lines whose paper tangents lie beyond the
        guarantee (``w``: how far towards them, see :func:`_towards_paper`)."""
        theta_b, B, t_b, dy, leg_b, leg_e, share_b, share_e, eligible = geo
        E, t_e, live, paper_miss = self.E, self.t_e, self.live, self.paper_miss
        top = np.maximum(share_b, share_e)
        # Beyond the guarantee (a share above 1), the paper's tangents are taken as far as
        # the caller found them clear of both surfaces (w), tapering off between 1.25 and 1.5.
        reach = eligible & (top > 1.0) & (top < 1.5)
        w = np.where(reach, np.minimum(w, np.clip((1.5 - top) / 0.25, 0.0, 1.0)), 0.0)
        paper = eligible & ((top <= 1.0) | (w == 1.0))
        g_b, g_e = np.clip(share_b, 0.0, 1.0), np.clip(share_e, 0.0, 1.0)
        share_b = np.where(reach, g_b + w * np.where(reach, share_b - g_b, 0.0), g_b)
        share_e = np.where(reach, g_e + w * np.where(reach, share_e - g_e, 0.0), g_e)
        with np.errstate(divide="ignore", invalid="ignore"):
            mag_b = np.where(paper, dy / np.where(paper, t_b[:, 1], 1.0), 3.0 * share_b * leg_b)
            mag_e = np.where(paper, dy / np.where(paper, t_e[:, 1], 1.0), 3.0 * share_e * leg_e)
            mag_b = np.where(paper_miss, dy, mag_b)
            mag_e = np.where(paper_miss, dy / t_e[:, 1], mag_e)
        mag_b = np.where(live, mag_b, 0.0)
        mag_e = np.where(live, mag_e, 0.0)
        if self.remedy == "parabolas":
            mag_b, mag_e = _parabola_lengths(self.body, B, theta_b, self.sign, E, t_e, leg_b,
                                             leg_e, mag_b, mag_e, ~paper_miss & live)
        T0, T1 = t_b * mag_b[:, None], t_e * mag_e[:, None]
        control = np.stack([B, B + T0 / 3.0, E - T1 / 3.0, E], axis=1)
        return B, theta_b, T0, T1, control, reach & live & ~paper_miss


#: Points along each line where a fillet is checked against the surfaces.
_SAMPLES = 33
#: Illinois steps for how far towards the paper's tangents a fillet stays clear
#: (:func:`_towards_paper`).
_ROOT_STEPS = 12
#: A bracket this narrow (a share of the way) is narrow enough (:func:`_first_root`).
_ROOT_WIDTH = 1e-9
#: Shares of theta_u the safety net tries first (:func:`_safety_net`).
_GRID = 8


def _safety_net(con, wing, side, body, I, check, phi, log):
    """phi, reduced (bisection) on the lines whose curve enters the body or the wing.

    The construction keeps the control polygon between the tangent planes of body and wing;
    where the surfaces curve away from those planes the wrong way over a long fillet (a
    twisted wing, far end points), the curve is checked against the surfaces themselves and
    B brought closer to I on the lines that enter either.
    """
    tol = tolerance(body)

    def clear(ctrl, rows):
        out = np.ones(con.m, bool)
        if rows.any():
            out[rows] = _clear(wing, side, body, ctrl[rows], tol, I[rows], _SAMPLES)
        return out

    bad = check & ~clear(con.finish(con.geometry(phi))[4], check)
    if not bad.any():
        return phi
    # The first share of phi that is not clear, not any one: a grid first, then bisection
    # in the first cell that fails (where the clear shares are not one interval, bisection
    # over all of [0, 1] lands on one boundary or another as the geometry moves a little).
    hi = np.ones(con.m)
    for k in range(_GRID - 1, 0, -1):
        share = k / _GRID
        ok = clear(con.finish(con.geometry(np.where(bad, share * phi, phi)))[4], bad)
        hi = np.where(bad & ~ok, share, hi)
    lo = hi - 1.0 / _GRID
    for _ in range(20):
        mid = 0.5 * (lo + hi)
        ok = clear(con.finish(con.geometry(np.where(bad, mid * phi, phi)))[4], bad)
        lo, hi = np.where(bad & ok, mid, lo), np.where(bad & ~ok, mid, hi)
    log.append(f"{wing.name} {side} fillet lines {line_runs(np.flatnonzero(bad))}: theta_u "
               "reduced further where the curved surfaces leave less room than their "
               "tangent planes")
    return np.where(bad, lo * phi, phi)


def _towards_paper(con, geo, wing, side, body, I, reach, control, T0, T1, towards=None):
    """Where the paper's own tangent lengths (s = y) reach a little past the guaranteed
    legs, they are kept if the curve they give stays clear of both surfaces (the transport's
    numbers stay the paper's), else taken as far towards them as it does
    (:func:`_first_clear`): the control points are linear in w (the guaranteed lengths at
    w = 0, the paper's at 1). ``towards`` (per line, NaN where not given): a previous
    fillet's shares, kept where their curve is clear (keep_area's iterates: the share found
    afresh on each re-designed body couples the stations the fillet spans, and the
    iteration took four times the steps). Returns the control points, tangents and each
    line's share."""
    full = con.finish(geo, 1.0)
    c0, c1 = control, full[4]
    rows = np.flatnonzero(reach)
    tol = tolerance(body)

    def margins(at, w):                 # rows ``at`` of ``rows``, shares w (len(at), k)
        r = rows[at]
        cand = c0[r, None] + w[..., None, None] * (c1 - c0)[r, None]
        k = w.shape[1]
        got = _margins(wing, side, body, cand.reshape(-1, 4, 3), tol,
                       np.repeat(I[r], k, axis=0), _SAMPLES)
        return tuple(m.reshape(len(r), k) for m in got)

    w = np.full(rows.size, np.nan)
    if towards is not None:
        given = np.flatnonzero(np.isfinite(np.asarray(towards, float)[rows]))
        if given.size:
            share = np.clip(np.asarray(towards, float)[rows[given]], 0.0, 1.0)
            inner, ends = margins(given, share[:, None])
            keep = np.minimum(inner, ends)[:, 0] >= 0.0
            w[given[keep]] = share[keep]
    todo = np.flatnonzero(np.isnan(w))
    if todo.size:
        w[todo] = _first_clear(margins, todo)
    control, T0, T1 = control.copy(), T0.copy(), T1.copy()
    part, whole = rows[w < 1.0], rows[w == 1.0]
    control[part] = c0[part] + w[w < 1.0, None, None] * (c1 - c0)[part]
    T0[part] = 3.0 * (control[part, 1] - control[part, 0])
    T1[part] = 3.0 * (control[part, 3] - control[part, 2])
    control[whole], T0[whole], T1[whole] = c1[whole], full[2][whole], full[3][whole]
    return control, T0, T1, w


def _first_clear(margins, todo):
    """The shares w of the lines ``todo`` up to which their curves stay clear
    (``margins(lines, w)``: :func:`_margins` of the candidates): all candidates w = k / 8 at
    once, and in the first cell that fails the root of the clearance margin by regula falsi
    (:func:`_first_root`). The fillet then moves continuously with the geometry (a grid
    value alone jumped by an eighth of the way as the body shrank by 1e-7 under keep_area,
    and the added area with it: no re-designed body kept the area)."""
    grid = np.arange(9) / 8.0
    inner, ends = margins(todo, np.broadcast_to(grid, (todo.size, grid.size)))
    # The largest w up to which every candidate is clear (w = 1: the paper's cubic).
    upto = np.cumprod(np.minimum(inner, ends)[:, 1:] >= 0.0, axis=1).sum(axis=1)
    at = np.minimum(upto, 7)
    # The ends do not move with w: where they are not clear, no candidate is and the
    # guaranteed lengths are kept (w = 0), as where the curve at the cell's start is not.
    w = np.where(upto == 8, 1.0, 0.0)
    k = np.flatnonzero((upto < 8) & (ends[:, 0] >= 0.0)
                       & (inner[np.arange(todo.size), at] >= 0.0))
    if k.size:
        w[k] = _first_root(lambda j, x: margins(todo[k[j]], x[:, None])[0][:, 0],
                           upto[k] / 8.0, (upto[k] + 1) / 8.0, inner[k, upto[k]],
                           inner[k, upto[k] + 1])
    return w


def _first_root(f, lo, hi, f_lo, f_hi):
    """The clear end (f >= 0) of brackets [lo, hi] of a continuous f that is >= 0 at lo and
    < 0 (or NaN) at hi, narrowed by at most :data:`_ROOT_STEPS` Illinois steps (regula falsi
    whose retained end's value is halved; bisection where the values give no finite
    secant) to :data:`_ROOT_WIDTH`.
    ``f(at, x)``: f of the brackets ``at`` at x."""
    lo, hi = lo.astype(float).copy(), hi.astype(float).copy()
    f_lo = np.where(np.isfinite(f_lo), f_lo, np.nan)
    f_hi = np.where(np.isnan(f_hi), -np.inf, f_hi)
    side = np.zeros(lo.size, np.int8)           # the end kept last (-1: lo, +1: hi)
    for _ in range(_ROOT_STEPS):
        if np.all(hi - lo <= _ROOT_WIDTH):
            break
        with np.errstate(divide="ignore", invalid="ignore"):
            x = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        ok = np.isfinite(x) & (x > lo) & (x < hi)
        x = np.where(ok, x, 0.5 * (lo + hi))
        fx = f(np.arange(lo.size), x)
        good = fx >= 0.0
        # Illinois: halve the value kept at the end that stays twice in a row
        f_lo = np.where(~good & (side == -1), 0.5 * f_lo, f_lo)
        f_hi = np.where(good & (side == 1), 0.5 * f_hi, f_hi)
        lo, f_lo = np.where(good, x, lo), np.where(good, fx, f_lo)
        hi, f_hi = np.where(good, hi, x), np.where(good, f_hi, np.where(np.isnan(fx), -np.inf,
                                                                        fx))
        side = np.where(good, 1, -1).astype(np.int8)
    return lo


def _assembled(wing, body, side, sign, n_points, remedy, blending, I, B, E, T0, T1, control,
               theta_b, u_e, beta, n_e, live, plane_miss, ends, blend_range, log):
    """The FilletLines: the cubics sampled, remedies and edge blending applied."""
    s = np.linspace(0.0, 1.0, int(n_points))
    kind = "parabolas" if remedy == "parabolas" else "cubic"
    f = hermite(B, E, T0, T1, s)
    # Extrapolated lofting line from I to E at the same s (the v of eq 10).
    v_line = I[:, None] + s[None, :, None] * (E - I)[:, None]
    dips = _dips(f, n_e, E, np.linalg.norm(E - B, axis=1)) & live
    if remedy == "z-constraint":
        f = f.copy()
        clamp = sign * (f[..., 2] - v_line[..., 2]) < 0
        f[..., 2] = np.where(clamp, v_line[..., 2], f[..., 2])
        control[clamp.any(axis=1)] = np.nan
        log.append(f"{wing.name} {side}: z-constraint applied to {int(dips.sum())} dipping "
                   "fillet lines (slope discontinuities where it acts)")
    for j in np.flatnonzero(dips):
        log.append(f"{wing.name} {side} fillet line {j + 1}: fillet "
                   f"{'dips below' if sign > 0 else 'rises above'} the extrapolated wing "
                   "surface (low-wing case); remedies: larger theta_u, remedy='z-constraint', "
                   "remedy='parabolas', or fillet='circular'")
    start, end_pt, theta_start, u_end = B, E, theta_b, u_e
    if blending == "points":
        pts = (1.0 - beta)[:, None, None] * v_line + beta[:, None, None] * f
        line_ctrl = I[:, None] + np.array([0.0, 1.0, 2.0, 3.0])[None, :, None] / 3.0 * \
            (E - I)[:, None]
        control = (1.0 - beta)[:, None, None] * line_ctrl + beta[:, None, None] * control
        start = pts[:, 0]
        theta_start = body.parameter_of(start)
    else:
        pts = f
    if plane_miss.any():
        pts, control = pts.copy(), control.copy()
        start, end_pt = start.copy(), end_pt.copy()
        theta_start, u_end = np.array(theta_start, float), np.array(u_end, float)
        q_pts = ends.points[plane_miss]
        pts[plane_miss] = q_pts[:, None, :]
        control[plane_miss] = q_pts[:, None, :]
        start[plane_miss], end_pt[plane_miss] = q_pts, q_pts
        theta_start[plane_miss], u_end[plane_miss] = ends.theta[plane_miss], ends.u[plane_miss]
    return FilletLines(side, pts, start, end_pt, theta_start, u_end, beta, dips, kind,
                       tuple(log), blend_range, control)


def _dips(f, normal, on_plane, size):
    """Lines with interior points on the wing's side of its tangent plane (the low-wing dip
    of TM-4406), beyond 1e-9 of the line's chord."""
    depth = -((f[:, 1:-1] - on_plane[:, None]) * normal[:, None]).sum(-1)
    return np.any(depth > 1e-9 * size[:, None], axis=1)


def _parabola_lengths(body, B, theta_b, sign, E, t_e, leg_b, leg_e, mag_b, mag_e, rows):
    """Tangent lengths of the blended-parabolas curve (``remedy="parabolas"``).

    The Overhauser curve through P0, B, E, P3 on [B, E] is the Hermite cubic with tangents
    (E - P0) / 2 and (P3 - B) / 2. TM-4406 takes P0 and P3 on the body and on the lofting
    line; the tangent at B is then off the circle's (by 36 deg on the issue's example). Here
    P0 and P3 are moved onto the end tangents at the same distances from E and from B, and
    the lengths limited to the longest legs (P1 and P2 each at least half-way along them).
    """
    P0 = body.point(B[:, 0], body.start(B[:, 0], theta_b, sign, np.radians(10.0)))
    chord = np.linalg.norm(E - B, axis=1)
    P3 = E + t_e * chord[:, None]
    len_b = 0.5 * np.linalg.norm(E - P0, axis=1)
    len_e = 0.5 * np.linalg.norm(P3 - B, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        a_b = np.clip(len_b / (3.0 * leg_b), 0.5, 1.0)
        a_e = np.clip(len_e / (3.0 * leg_e), 0.5, 1.0)
    new_b = np.where(leg_b > 0, 3.0 * np.nan_to_num(a_b) * leg_b, 0.0)
    new_e = np.where(leg_e > 0, 3.0 * np.nan_to_num(a_e) * leg_e, 0.0)
    return np.where(rows, new_b, mag_b), np.where(rows, new_e, mag_e)
