"""Circular-arc fillet of radius rho(x) at constant x (TM-4406, "Circular-arc filleting", fig 8).

On each lofting line, a point P is sought whose offset C = P + rho n lies at rho + r(x) from the
body's section centre, n being the normal to the lofting line's direction projected into the
plane x = const (pointing away from the wing surface: up for the upper surface). C is then at
distance rho from the projected lofting line and from the body circle, so the arc of radius rho
about C is tangent to both (fig 8(b)). The paper steps inboard along the lofting line with
increments proportional to the error; here the same error is solved by the bracketed root
finder of :mod:`juncture.intersect.rays` over all lofting lines at once.

Along the fillet line x is constant, so at its end the derivatives of y and z with respect to
arc length are continuous with the lofting line but that of x is not (as the paper notes).
Towards the leading and trailing edges the radius is scaled by the blending function beta(L)
of eqs 8-9 (the cubic fillet's ``blending="scale"``), so the edges stay sharp and every fillet
line starts on the body.

A lofting line that misses the body has no junction to round: the paper gives no circular
arc for it (its special case, a fillet starting at the body's bottom with dx/dy = dz/dy = 0,
is one a circular arc cannot meet in general: from the bottom of the body to a lower surface
that passes under it, a curve must first bend down and then up). Such a line is left sharp as
without a fillet: it ends where it reaches the plane of symmetry (:mod:`juncture.misses`), and
its fillet line is degenerate there, so the fillet is finite on every line.
"""

from __future__ import annotations

import numpy as np

from ..errors import GeometryError
from ..intersect import BodyIntersection, find_crossings
from ..intersect.rays import SurfaceBound
from ..misses import ended_lines, line_ends
from ..model import CircularBody
from .clearance import line_runs, tolerance, wing_depth
from .lines import FilletLines, blend_over

__all__ = ["circular_fillet", "arcs"]


def _normals(lines, sign):
    d = lines[:, 1] - lines[:, 0]
    dp = np.stack([np.zeros(len(d)), d[:, 1], d[:, 2]], axis=1)
    dp /= np.linalg.norm(dp, axis=1)[:, None]
    # Rotate the projected direction by +90 deg in the y-z plane: (y, z) -> (-z, y); for a
    # lofting line running outboard (+y) this points up.
    n = np.stack([np.zeros(len(d)), -dp[:, 2], dp[:, 1]], axis=1) * sign
    return dp, n


def arcs(body, P, C, rho, n_points):
    """Arcs of radius rho (k,) about C (k, 3) from the body to P (k, 3), in the planes x = P_x.

    The arc starts at T, the body point towards C (where a circle about C of radius rho
    touches the body when |C - centre| = r + rho), and runs the short way round to P; its
    first and last points are T and P exactly.
    Returns ``(points (k, n_points, 3), T (k, 3), theta_T (k,))``.
    """
    x = P[:, 0]
    if isinstance(body, CircularBody):
        ctr = body.center_at(x)
        th = np.arctan2(C[:, 2] - ctr[:, 1], C[:, 1] - ctr[:, 0])
    else:
        # An arbitrary section: the circle about C touches it at C's nearest point.
        th = body.parameter_of(np.concatenate([x[:, None], C[:, 1:]], axis=1))
    T = body.point(x, th)
    a0 = np.arctan2(T[:, 2] - C[:, 2], T[:, 1] - C[:, 1])
    a1 = np.arctan2(P[:, 2] - C[:, 2], P[:, 1] - C[:, 1])
    da = (a1 - a0 + np.pi) % (2 * np.pi) - np.pi
    t = np.linspace(0.0, 1.0, int(n_points))
    ang = a0[:, None] + da[:, None] * t[None, :]
    pts = np.stack([np.broadcast_to(x[:, None], ang.shape),
                    C[:, 1, None] + rho[:, None] * np.cos(ang),
                    C[:, 2, None] + rho[:, None] * np.sin(ang)], axis=-1)
    # The ends are the body point and P themselves, bit for bit, so that the seams with the
    # body and wing networks are exact whatever the residual of the tangency solve.
    live = rho > 0  # (a zero radius: a degenerate arc, all at P)
    pts[live, 0] = T[live]
    pts[:, -1] = P
    return pts, T, th


def _lipschitz(body, radius):
    """A bound on |d error / d length| along a lofting line, or None (dense sampling).

    With a constant rho the offset centre C = P + rho beta n moves with P (n and beta are
    fixed per line and have no x part), so |grad error| <= 1 + |r'| + |c'|: the body's own
    bound, local to the x range of each segment. A rho(x) given as a function has no known
    slope bound, so its lines are sampled densely.
    """
    if callable(radius):
        return None
    return SurfaceBound(body)


def _section_normals(wing, side, sign):
    """normal(points) -> (..., 3): the normal, in the plane x = const and away from the wing,
    of the wing's own section by that plane at points on its surface (juncture's default; the
    paper's normal is the projected lofting line's)."""
    from .planar import section_tangent

    def normal(points):
        t = section_tangent(wing, side, points[..., 0], points[..., wing.span_axis])
        return np.stack([np.zeros(t.shape[:-1]), -t[..., 2], t[..., 1]], axis=-1) * sign
    return normal


class _Solve:
    """The tangency solve of :func:`circular_fillet` on some lofting lines, for given radius
    factors (beta, times a reduction where an arc would enter the wing)."""

    def __init__(self, body, distance, lines, n, rho_of, radius, on_section, inter, hint,
                 circular):
        self.body, self.distance, self.lines, self.n = body, distance, lines, n
        self.rho_of, self.radius, self.on_section = rho_of, radius, on_section
        self.inter, self.hint, self.circular = inter, hint, circular

    def __call__(self, idx, bb):
        ln, nn = self.lines[idx], self.n[idx]
        rho_of, on_section, distance = self.rho_of, self.on_section, self.distance

        def error(points, rows):
            # The body's signed distance at C = P + rho beta n, less rho beta.
            rows = np.asarray(rows)
            shape = (len(rows),) + (1,) * (points.ndim - 2)
            rho = bb[rows].reshape(shape) * rho_of(points[..., 0])
            normal = (nn[rows].reshape(shape + (3,)) if on_section is None
                      else on_section(points))
            c = points + rho[..., None] * normal
            return distance(c) - rho

        error.row_aware = True
        radius = self.radius
        if not callable(radius) and on_section is None and self.circular:
            # Constant rho: C moves with P, so the gradient is the body's at C.
            offset = bb[:, None] * nn

            def value_and_gradient(points, rows):
                step = float(radius) * offset[rows]
                e, g = self.body.radial_error_and_gradient(points + step)
                return e - float(radius) * bb[rows], g
            error.value_and_gradient = value_and_gradient

        # At I the centre C = I + rho beta n is within rho beta of the body (on it only when
        # n is its normal): I is never outside, so the crossing coming inboard from the tip
        # is found before it and the search stops there.
        inter = self.inter
        u_low = np.where(inter.found[idx], inter.u[idx], -1.0)
        # With the section's normal, C also turns with P (the section's curvature): no slope
        # bound is known, so the lines are sampled densely.
        bound = _lipschitz(self.body, radius) if on_section is None else None
        return find_crossings(ln, error, u_low, lipschitz=bound,
                              hint=None if self.hint is None else
                              np.asarray(self.hint, float)[idx])

    def arcs(self, idx, bb, P, found, n_points):
        """(points, T, theta_T) of the arcs of the found lines, NaN elsewhere."""
        k = len(idx)
        pts = np.full((k, int(n_points), 3), np.nan)
        T, th = np.full((k, 3), np.nan), np.full(k, np.nan)
        if found.any():
            x = P[found, 0]
            rho = bb[found] * self.rho_of(x)
            normal = self.n[idx[found]] if self.on_section is None else \
                self.on_section(P[found])
            C = P[found] + rho[:, None] * normal
            pts[found], T[found], th[found] = arcs(self.body, P[found], C, rho, n_points)
        return pts, T, th


def circular_fillet(wing, body, inter: BodyIntersection, radius, blend_length=None,
                    n_points=9, hint=None, blend_range=None, tangent="section"):
    """Circular-arc fillet lines of radius ``radius`` for one surface.

    Parameters
    ----------
    wing : WingLike
    body : CircularBody
    inter : BodyIntersection
        Intersection of the same surface.
    radius : float or callable
        rho [deck length], constant or a function of x (vectorised).
    blend_length : float, optional
        l_b of eq 8; default a tenth of the intersection's x extent. Towards the leading and
        trailing edges the radius is scaled by beta(L) (eq 9), so the fillet shrinks to the
        sharp intersection there and always starts on the body.
    n_points : int
        Points per fillet line, equally spaced in angle along the arc.
    blend_range : (x_le, x_te, l_b), optional
        A fixed blending region (see :func:`.cubic.blend_over`); ``blend_length`` is then
        ignored.
    hint : (n_stations,) float, optional
        Tangency points' section coordinates (``u_end``) of a previous solve on a body that
        contained this one: the search starts there.
    tangent : {"section", "lofting-line"}
        What the arc is tangent to at its end P on the lofting line, in the plane x = P_x:
        the wing's own section by that plane (default: the arc then leaves the wing surface
        along it and cannot dip into the wing; past the paper), or the lofting line
        projected on the plane, as TM-4406 constructs it (on a swept wing whose thickness
        changes along the chord the two differ, and the paper's arc enters the wing).

    Returns
    -------
    FilletLines
        ``kind = "circular"``; ``u_end`` is the tangency point's section coordinate. A line
        that misses the body is degenerate at its end point on the plane of symmetry
        (module docstring).
    """
    side = inter.side
    sign = 1.0 if side == "upper" else -1.0
    if tangent not in ("section", "lofting-line"):
        raise GeometryError(f"tangent must be 'section' or 'lofting-line', found {tangent!r}",
                            wing.name)
    rho_of = radius if callable(radius) else (lambda x: np.full_like(np.asarray(x, float),
                                                                     float(radius)))
    lines = wing.lofting_lines(side)
    m = lines.shape[0]
    if np.any(np.asarray(rho_of(lines[:, 0, 0])) <= 0):
        raise GeometryError("circular fillet radius must be > 0", wing.name)
    circular = isinstance(body, CircularBody)
    # The signed distance to the section: the circle's radial error, or the distance to an
    # arbitrary section's polyline (both > 0 outside, with the same Lipschitz bound).
    distance = body.radial_error if circular else body.signed_distance
    ends = line_ends(wing, body, inter)
    x_i = ends.points[:, 0]
    beta, blend_range = blend_over(x_i, blend_length, blend_range)
    beta = np.where(inter.found, beta, 0.0)
    live = beta > 0
    _, n = _normals(lines, sign)
    log = []
    I = inter.points.copy()
    theta_b = inter.theta.copy()
    u_end = inter.u.copy()
    pts = np.repeat(I[:, None, :], int(n_points), axis=1)
    start, E = I.copy(), I.copy()
    if live.any():
        idx = np.flatnonzero(live)
        on_section = _section_normals(wing, side, sign) if tangent == "section" else None
        solve = _Solve(body, distance, lines, n, rho_of, radius, on_section, inter, hint, circular)
        scale = np.ones(idx.size)
        cr = solve(idx, beta[idx])
        log.append(f"{wing.name} {side}: circular fillet solved on {int(cr.found.sum())} of "
                   f"{idx.size} lofting lines in {cr.iterations} iterations")
        for j in idx[~cr.found]:
            log.append(f"{wing.name} {side} fillet line {j + 1}: no circular arc fits between "
                       f"the lofting line and {body.name}; left sharp")
        found, P, u_p = cr.found, cr.points, cr.u
        arcs_ = solve.arcs(idx, beta[idx], P, found, n_points)
        # A wing whose section by x = const curves towards the arc faster than 1 / rho (near
        # a leading edge) lets the arc enter it: there the radius is halved until it does not.
        deep = found & (wing_depth(wing, arcs_[0]) > tolerance(body)).any(axis=1)
        if deep.any():
            log.append(f"{wing.name} {side} fillet lines {line_runs(idx[deep])}: radius reduced "
                       "where the wing's section curves faster than the arc (it would enter "
                       "the wing)")
        for _ in range(12):
            if not deep.any():
                break
            scale[deep] *= 0.5
            rows = np.flatnonzero(deep)
            again = solve(idx[rows], beta[idx[rows]] * scale[rows])
            found[rows], P[rows], u_p[rows] = again.found, again.points, again.u
            redo = solve.arcs(idx[rows], beta[idx[rows]] * scale[rows], again.points,
                              again.found, n_points)
            for full, part in zip(arcs_, redo):
                full[rows] = part
            deep = np.zeros_like(deep)
            deep[rows] = again.found & (wing_depth(wing, redo[0]) >
                                        tolerance(body)).any(axis=1)
        ok = found & ~deep
        rows = idx[ok]
        pts[rows], start[rows], theta_b[rows] = arcs_[0][ok], arcs_[1][ok], arcs_[2][ok]
        E[rows], u_end[rows] = P[ok], u_p[ok]
        beta = beta.copy()
        beta[idx[ok]] *= scale[ok]
        beta[idx[~ok]] = 0.0
    out = FilletLines(side, pts, start, E, theta_b, u_end, beta, np.zeros(m, bool),
                      "circular", tuple(log), blend_range)
    return ended_lines(out, ends, ends.missed)
