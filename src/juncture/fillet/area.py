"""Added fillet area per station (TM-4406 eqs 11-14); the re-design: redesign.py, compensation.py.

TM-4406 projects an upper fillet line and the corresponding lower one into the plane
x = const, takes the polygon through five points of each (eq 11), and subtracts the wing root
trapezoid (eq 12) and the circular segment of the body between the fillet start points
(eq 13). What is left is the two wedges each fillet fills: between the fillet line, the wing
surface from its end point E back to the intersection I, and the body arc from I to the
fillet's start B. Here each wedge is measured on its own, in the cross-section plane of its
own intersection point (the upper and lower intersections of a swept wing lie at different
x), and exactly:

- a cubic fillet (its Bezier control points in ``FilletLines.control``, starting on the
  body circle) by Green's theorem on the closed curve cubic B -> E, segment E -> I, arc
  I -> B: A = 1/2 |integral of (y dz - z dy)|, the cubic's part by 3-point Gauss-Legendre
  quadrature (exact for its degree-5 integrand), the arc's in closed form. The fillet lies
  outside the body, so this is eqs 11-14 with the fillet itself instead of a polygon through
  some of its points (9 points over-state the area by about 1.5 %);
- any other line (circular arcs, the eq 10 blending whose first point lies inside the body,
  degenerate lines) by the polygon of its points closed through I, less its part inside the
  body's disk: the exact area of a polygon cut by a circle (a sum over edges of the signed
  area of the disk within each edge's triangle with the centre).

With a re-designed (smaller) body, the wing root the shrinking body uncovers is added on
request: the part of the wing quadrilateral (I_u, E_u, E_l, I_l) between the original and
the re-designed body circles.
"""

from __future__ import annotations

import numpy as np

__all__ = ["polygon_disk_area", "fillet_added_area", "wedge_area"]



def _cross(u, v):
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _angle(u, v):
    return np.arctan2(_cross(u, v), (u * v).sum(-1))


def polygon_disk_area(poly, center, radius):
    """Signed area of polygon ∩ disk, vectorised over stations.

    Parameters
    ----------
    poly : (m, k, 2) float
        m closed polygons (the last vertex joins the first), any orientation; the sign of the
        result follows it (counter-clockwise positive).
    center : (m, 2) float
    radius : (m,) float

    Returns
    -------
    (m,) float
    """
    p = np.asarray(poly, float) - np.asarray(center, float)[:, None, :]
    r = np.asarray(radius, float)[:, None]
    a_pt, b_pt = p, np.roll(p, -1, axis=1)
    d = b_pt - a_pt
    qa = (d * d).sum(-1)
    qb = 2.0 * (a_pt * d).sum(-1)
    qc = (a_pt * a_pt).sum(-1) - r ** 2
    disc = qb * qb - 4 * qa * qc
    sq = np.sqrt(np.maximum(disc, 0.0))
    safe = np.where(qa > 0, qa, 1.0)
    t1 = np.where((disc > 0) & (qa > 0), (-qb - sq) / (2 * safe), 1.0)
    t2 = np.where((disc > 0) & (qa > 0), (-qb + sq) / (2 * safe), 1.0)
    s1 = np.clip(t1, 0.0, 1.0)
    s2 = np.clip(np.maximum(t2, t1), 0.0, 1.0)
    p1 = a_pt + s1[..., None] * d
    p2 = a_pt + s2[..., None] * d
    r2 = r ** 2
    area = 0.5 * r2 * _angle(a_pt, p1) + 0.5 * _cross(p1, p2) + 0.5 * r2 * _angle(p2, b_pt)
    # An edge that never enters the disk is a pure sector (the clipping above gives that too
    # when s1 == s2, but keep degenerate zero-length edges at zero).
    area = np.where(qa > 0, area, 0.0)
    return area.sum(axis=1)


def _polygon_area(poly):
    q = np.roll(poly, -1, axis=1)
    return 0.5 * _cross(poly, q).sum(axis=1)


_GAUSS_S = 0.5 + 0.5 * np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
_GAUSS_W = np.array([5.0, 8.0, 5.0]) / 18.0


def _bezier_green(control):
    """(m,) integral over s in [0, 1] of 1/2 (y z' - z y') of cubic Bezier curves (m, 4, 2)."""
    c = np.asarray(control, float)
    s = _GAUSS_S[None, :, None]
    w = 1.0 - s
    p = (w ** 3 * c[:, None, 0] + 3 * w * w * s * c[:, None, 1] + 3 * w * s * s * c[:, None, 2]
         + s ** 3 * c[:, None, 3])
    d = 3.0 * (w * w * (c[:, None, 1] - c[:, None, 0]) + 2 * w * s * (c[:, None, 2] - c[:, None, 1])
               + s * s * (c[:, None, 3] - c[:, None, 2]))
    return 0.5 * (_cross(p, d) * _GAUSS_W[None, :]).sum(axis=1)


def _cubic_rows(lines):
    """Rows of ``lines`` that are the cubic their ``control`` gives, sampled at equal s."""
    ctrl = getattr(lines, "control", None)
    m, k = lines.points.shape[:2]
    if ctrl is None or k < 2:
        return np.zeros(m, bool), None
    from .lines import bezier

    ctrl = np.asarray(ctrl, float)
    pts = bezier(np.nan_to_num(ctrl), np.linspace(0.0, 1.0, k))
    size = np.abs(lines.points).max(axis=(1, 2)) + 1.0
    same = np.abs(pts - lines.points).max(axis=(1, 2)) <= 1e-9 * size
    return same & np.isfinite(ctrl).all(axis=(1, 2)), ctrl


def wedge_area(body, lines, corner):
    """Area each fillet line adds to its cross-section (TM-4406 eqs 11-14, one side).

    Parameters
    ----------
    body : CircularBody
    lines : FilletLines
        Fillet lines, each from its start on the body to its end on the wing.
    corner : (m, 3) float
        The intersection point I of each line (where the sharp juncture was).

    Returns
    -------
    (m,) float
        The area between the fillet, the wing from E back to I and the body from I to the
        start, in the plane x = x_I [deck length^2] (module docstring).
    """
    pts = np.asarray(lines.points, float)
    corner = np.asarray(corner, float)
    if not hasattr(body, "section_at"):
        return _polyline_wedge_area(body, lines, corner)
    x = corner[:, 0]
    ctr, r = body.section_at(x)
    # Polygon of the points closed through I, less its part inside the disk.
    poly = np.concatenate([pts[..., 1:], corner[:, None, 1:]], axis=1)
    a_poly = _polygon_area(poly)
    polygon = np.abs(a_poly - polygon_disk_area(poly, ctr, r))
    cubic, ctrl = _cubic_rows(lines)
    start = pts[:, 0]
    on_circle = np.abs(np.hypot(start[:, 1] - ctr[:, 0], start[:, 2] - ctr[:, 1]) - r) <= \
        1e-9 * np.maximum(r, 1.0)
    exact = cubic & on_circle & np.isfinite(pts).all(axis=(1, 2))
    if not exact.any():
        return polygon
    th_i = np.arctan2(corner[:, 2] - ctr[:, 1], corner[:, 1] - ctr[:, 0])
    th_b = np.arctan2(start[:, 2] - ctr[:, 1], start[:, 1] - ctr[:, 0])
    dth = (th_b - th_i + np.pi) % (2 * np.pi) - np.pi
    arc = 0.5 * (r * (ctr[:, 0] * (np.sin(th_b) - np.sin(th_i))
                      - ctr[:, 1] * (np.cos(th_b) - np.cos(th_i))) + r * r * dth)
    end = pts[:, -1, 1:]
    green = _bezier_green(np.nan_to_num(ctrl[..., 1:])) + 0.5 * _cross(end, corner[:, 1:]) + arc
    return np.where(exact, np.abs(green), polygon)


def _section_green(body, x, s_from, s_to):
    """1/2 of the integral of (y dz - z dy) along an arbitrary body's section at stations x
    (m,), from parameter s_from to s_to: the polyline's vertices between them, exactly."""
    k, _ = body._pair(x)
    lo, hi = np.minimum(s_from, s_to), np.maximum(s_from, s_to)
    s = np.concatenate([lo[:, None], np.clip(body._u[k], lo[:, None], hi[:, None]),
                        hi[:, None]], axis=1)
    p = body.point(np.broadcast_to(x[:, None], s.shape), s)[..., 1:]
    g = 0.5 * _cross(p[:, :-1], p[:, 1:]).sum(axis=1)
    return np.where(s_to >= s_from, g, -g)


def _polyline_wedge_area(body, lines, corner):
    """:func:`wedge_area` on an arbitrary-section body: Green's theorem on the closed curve
    fillet B -> E (the cubic exactly where ``control`` gives it, else its polyline), E -> I,
    the section at x_I from I to B's parameter, and on to B (nothing where B lies at x_I)."""
    pts = np.asarray(lines.points, float)
    x = corner[:, 0]
    start = pts[:, 0]
    s_b, s_i = body.parameter_of(start), body.parameter_of(corner)
    b_at = body.point(x, s_b)[:, 1:]
    cubic, ctrl = _cubic_rows(lines)
    yz = pts[..., 1:]
    fillet = 0.5 * _cross(yz[:, :-1], yz[:, 1:]).sum(axis=1)
    if cubic.any():
        fillet = np.where(cubic, _bezier_green(np.nan_to_num(ctrl[..., 1:])), fillet)
    total = (fillet + 0.5 * _cross(yz[:, -1], corner[:, 1:])
             + _section_green(body, x, s_i, s_b) + 0.5 * _cross(b_at, start[:, 1:]))
    return np.where(np.isfinite(total), np.abs(total), 0.0)


def fillet_added_area(body, upper, lower, upper_inter, lower_inter, reference_body=None):
    """Net added cross-sectional area of the fillet at each station (eqs 11-14).

    Parameters
    ----------
    body : CircularBody
    upper, lower : FilletLines
        Fillet lines of the upper and lower surfaces, paired by lofting-line index.
    upper_inter, lower_inter : BodyIntersection
        The intersections (their points are the corners I_u, I_l of the wedges; where a line
        misses the body, its fillet line's start).
    reference_body : CircularBody, optional
        The original body, when ``body`` is a re-designed (smaller) one. Then a third value
        is returned: the area added relative to the original configuration, i.e. the fillets
        plus the wing root uncovered between the original and the re-designed body circles.

    Returns
    -------
    x : (m,) float
        Station of each pair: the x of the upper fillet line's start, or of the lower one's
        where only the upper line passes over the body [deck length].
    area : (m,) float
        Added area of the two fillets (the upper and the lower wedge), one side of the
        airplane [deck length^2].
    area_total : (m,) float
        Only with ``reference_body``: fillet plus uncovered wing root, one side.
    """
    # A pair whose upper line passes over the body (its fillet degenerate at Q on the plane
    # of symmetry, far from the junction) adds only its lower wedge: at the lower line's x.
    x = np.where(upper_inter.found | ~lower_inter.found, upper.points[:, 0, 0],
                 lower.points[:, 0, 0])
    i_u = np.where(upper_inter.found[:, None], upper_inter.points, upper.start)
    i_l = np.where(lower_inter.found[:, None], lower_inter.points, lower.start)
    fillet = wedge_area(body, upper, i_u) + wedge_area(body, lower, i_l)
    if reference_body is None:
        return x, fillet
    wing = np.stack([i_u[:, 1:], upper.end[:, 1:], lower.end[:, 1:], i_l[:, 1:]], axis=1)
    ctr, r = body.section_at(x)
    ctr0, r0 = reference_body.section_at(x)
    uncovered = np.abs(polygon_disk_area(wing, ctr0, r0)) - np.abs(polygon_disk_area(wing, ctr, r))
    return x, fillet, fillet + uncovered
