"""Cubic-arc fillet lines of a wing-body juncture (TM-4406 eq 7) with LE/TE blending (eqs 8-10).

For each lofting line j of one wing surface (upper or lower) a fillet line runs from a start
point B on the body's cross-section circle through the intersection point I, an angular
distance theta_u above (upper) or below (lower) I, to an end point E on the lofting line. It is
the cubic f(s) = a1 + a2 s + a3 s^2 + a4 s^3 tangent to the body circle at B and to the
lofting line at E. Following the paper, s is the nondimensional y-coordinate along the line, so
the end tangents are dP/dy of the circle and of the lofting line (a Hermite cubic in y).
Where the circle's tangent at B is nearly vertical (|dy| small: a start near theta = 0 or
pi), dP/dy is unbounded; there the tangent magnitudes are taken as the chord |E - B| instead
(same directions, still tangent) and the log says so.

Near the leading and trailing edges the fillet is blended into the sharp intersection over a
length l_b in x, with beta(L) = sin(pi L / 2) and L = (x - x_le) / l_b (eqs 8-9). Two ways:

- ``blending="points"`` is eq 10 as printed: f_t = (1 - beta) v + beta f, v being the point on
  the extrapolated lofting line between I and E at the same s. Its first point lies on the
  chord between I and B, slightly inside the body, so the body arc and the fillet do not
  quite meet where 0 < beta < 1.
- ``blending="scale"`` (default) scales the fillet instead: theta_u -> beta theta_u and the end
  point -> I + beta (E - I) along the lofting line. It passes through the same two limits
  (a sharp intersection at beta = 0, the full fillet at beta = 1), but every fillet line starts
  on the body circle and stays tangent to both surfaces, so the output networks are
  watertight.

End point options (the paper's three): ``end="section"`` puts E at the fraction ``end_value``
of the distance from section 1 to section 2; ``"intersection"`` at that fraction of the
distance from I to section 2; ``"dy"`` at a span increment ``end_value`` from I.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import GeometryError
from ..intersect import BodyIntersection, polyline_points

__all__ = ["FilletLines", "cubic_fillet", "EndMode", "Blending", "hermite", "blend_factor",
           "blend_over"]

EndMode = Literal["section", "intersection", "dy"]
Blending = Literal["scale", "points"]

#: Default angular distance of the fillet start from the intersection [rad] (20 deg).
THETA_U_DEFAULT = float(np.radians(20.0))


@dataclass(frozen=True, slots=True, eq=False)
class FilletLines:
    """Fillet lines of one wing surface.

    Attributes
    ----------
    side : {"upper", "lower"}
    points : (n_stations, n_points, 3) float
        Each line from its start on the body (index 0) to its end on the wing (index -1).
    start, end : (n_stations, 3) float
        B (on the body circle) and E (on the lofting line).
    theta_start : (n_stations,) float
        Body angle of B [rad] (TM-4406 convention).
    u_end : (n_stations,) float
        Section coordinate of E on its lofting line.
    blend : (n_stations,) float
        beta(L) of each line (0 at the leading / trailing edge, 1 in the blended-in region).
    dips : (n_stations,) bool
        Upper (lower) fillet dips below (rises above) the extrapolated wing surface: the
        low-wing problem of TM-4406; see ``remedy`` of :func:`cubic_fillet`.
    kind : str
        ``"cubic"``, ``"parabolas"`` or ``"circular"``.
    log : tuple of str
    blend_range : tuple of float or None
        (x_le, x_te, l_b) the blending used [deck length]: pass it back as ``blend_range``
        to blend another body's fillet over the same region.
    """

    side: str
    points: np.ndarray
    start: np.ndarray
    end: np.ndarray
    theta_start: np.ndarray
    u_end: np.ndarray
    blend: np.ndarray
    dips: np.ndarray
    kind: str = "cubic"
    log: tuple = ()
    blend_range: tuple = None


def hermite(p0, p1, t0, t1, s):
    """Cubic Hermite curves, vectorised: (m, 3) ends and tangents, s (k,) -> (m, k, 3)."""
    s = np.asarray(s, float)[None, :, None]
    h00 = 2 * s ** 3 - 3 * s ** 2 + 1
    h10 = s ** 3 - 2 * s ** 2 + s
    h01 = -2 * s ** 3 + 3 * s ** 2
    h11 = s ** 3 - s ** 2
    return (h00 * p0[:, None] + h10 * t0[:, None] + h01 * p1[:, None] + h11 * t1[:, None])


def _end_coordinate(wing, inter, end, end_value):
    u_i = inter.u
    if end == "section":
        u_e = np.full_like(u_i, float(end_value))
    elif end == "intersection":
        u_e = u_i + float(end_value) * (1.0 - u_i)
    elif end == "dy":
        st = wing.span_stations
        u_e = u_i + float(end_value) / (st[1] - st[0])
    else:
        raise GeometryError(f"fillet end must be 'section', 'intersection' or 'dy', found "
                            f"{end!r}", wing.name)
    bad = u_e <= u_i
    if np.any(bad & inter.found):
        j = int(np.argmax(bad & inter.found))
        raise GeometryError(f"fillet end point (u = {u_e[j]:.4g}) is not outboard of the "
                            f"intersection (u = {u_i[j]:.4g}) on lofting line {j + 1}; "
                            "choose a larger end value", wing.name)
    return u_e


def blend_over(x_i, blend_length=None, blend_range=None):
    """beta(L) per lofting line and the (x_le, x_te, l_b) it used (eqs 8-9).

    By default the edges are the first and last intersection points (leading and trailing
    edge lines) and l_b a tenth of the distance between them. A given ``blend_range`` fixes
    them instead (the fixed-area iteration blends every re-designed body's fillet over the
    original body's region, so that no fillet depends on where the edge lines happen to
    meet the body); the edge lines themselves still get beta = 0.
    """
    if blend_range is None:
        x_le, x_te = float(x_i[0]), float(x_i[-1])
        if blend_length is None:
            blend_length = 0.1 * (np.max(x_i) - np.min(x_i))
        blend_range = (x_le, x_te, blend_length)
    beta = blend_factor(x_i, *blend_range)
    if blend_range[2] is not None and blend_range[2] > 0:
        beta[[0, -1]] = 0.0
    return beta, blend_range


def blend_factor(x, x_le, x_te, blend_length):
    """beta(L) = sin(pi L / 2) with L the distance from the nearer edge over l_b (eqs 8-9)."""
    if blend_length is None or blend_length <= 0:
        return np.ones_like(x)
    L = np.clip(np.minimum(x - x_le, x_te - x) / blend_length, 0.0, 1.0)
    return np.sin(0.5 * np.pi * L)


def cubic_fillet(wing, body, inter: BodyIntersection, theta_u=THETA_U_DEFAULT,
                 end: EndMode = "intersection", end_value=0.5, blend_length=None,
                 n_points=9, remedy=None, upper_reference=None, blending: Blending = "scale",
                 blend_range=None):
    """Cubic-arc fillet lines for one surface (TM-4406 eq 7, eqs 8-10).

    Parameters
    ----------
    wing : WingLike
    body : CircularBody
    inter : BodyIntersection
        The intersection of this surface (``inter.side``) with the body.
    theta_u : float or (n_stations,) float
        Angular distance of the start point from the intersection along the body circle,
        upward for the upper surface, downward for the lower [rad].
    end, end_value :
        End-point option and its value (see the module docstring).
    blend_length : float, optional
        l_b of eq 8 [deck length]; default a tenth of the intersection line's x extent.
    n_points : int
        Points per fillet line (>= 2), equally spaced in s.
    remedy : {None, "z-constraint", "parabolas"}
        What to do where a fillet dips through the extrapolated wing surface: nothing (only
        report it in ``dips`` and the log), clamp it to that surface (a slope discontinuity,
        as the paper warns), or use the method of blended parabolas (an Overhauser curve
        through a body point before B, B, E and a lofting-line point after E).
    upper_reference : BodyIntersection, optional
        Where the lower-surface line misses the body (the paper's special case), the x of the
        fillet start is taken from this upper-surface intersection's line of the same index.
    blending : {"scale", "points"}
        How the fillet is blended out towards the leading and trailing edges (module docstring).
    blend_range : (x_le, x_te, l_b), optional
        A fixed blending region (see :func:`blend_over`), e.g. a previous fillet's
        ``blend_range``; ``blend_length`` is then ignored.

    Returns
    -------
    FilletLines
    """
    side = inter.side
    sign = 1.0 if side == "upper" else -1.0
    if blending not in ("scale", "points"):
        raise GeometryError(f"fillet blending must be 'scale' or 'points', found {blending!r}",
                            wing.name)
    lines = wing.lofting_lines(side)
    m = lines.shape[0]
    u_full = _end_coordinate(wing, inter, end, end_value)
    missed = ~inter.found
    I = inter.points.copy()
    theta_i = inter.theta.copy()
    log = []
    x_b = I[:, 0].copy()
    if missed.any():
        # The paper's special case: the lower line misses the body. Start at theta = -90 deg,
        # at the x of the upper intersection of the same line (else the line's root x), with
        # dx/dy = dz/dy = 0.
        x_ref = lines[:, 0, 0] if upper_reference is None else np.where(
            upper_reference.found, upper_reference.points[:, 0], lines[:, 0, 0])
        x_b[missed] = x_ref[missed]
        theta_i[missed] = 0.5 * np.pi * sign  # the bottom for the lower surface
        I[missed] = body.point(x_b[missed], theta_i[missed])
        u_full = np.where(missed, 0.0, u_full)
        for j in np.flatnonzero(missed):
            log.append(f"{wing.name} {side} fillet line {j + 1}: lofting line misses "
                       f"{body.name}; fillet starts at theta = {np.degrees(theta_i[j]):.0f} deg "
                       "with dx/dy = dz/dy = 0 (TM-4406 special case)")
    x_i = I[:, 0]
    beta, blend_range = blend_over(x_i, blend_length, blend_range)
    beta = np.where(missed, 1.0, beta)
    scale = beta if blending == "scale" else np.ones(m)
    theta_u = np.broadcast_to(np.asarray(theta_u, float), (m,))
    theta_b = np.where(missed, theta_i, theta_i + sign * scale * theta_u)
    u_i = np.where(missed, 0.0, inter.u)
    u_e = u_i + scale * (u_full - u_i)
    E = polyline_points(lines, u_e[:, None])[:, 0]
    dirs = lines[:, 1] - lines[:, 0]
    t_e = dirs / np.linalg.norm(dirs, axis=1)[:, None]
    B = body.point(x_b, theta_b)
    # Circle tangent at B pointing away from the body towards the wing (theta moving towards
    # theta_i), then scaled to dP/dy.
    t_b = np.stack([np.zeros(m), np.sin(theta_b), -np.cos(theta_b)], axis=1) * sign
    t_b[missed] = [0.0, 1.0, 0.0]
    live = scale > 0
    dy = E[:, 1] - B[:, 1]
    if np.any(live & (dy <= 0)):
        j = int(np.argmax(live & (dy <= 0)))
        raise GeometryError(f"{side} fillet line {j + 1}: the end point is not outboard of the "
                            "start point; reduce theta_u or move the end point out",
                            wing.name, j + 1)
    steep = np.abs(t_b[:, 1]) < 0.2
    chord = np.linalg.norm(E - B, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        mag_b = np.where(steep, chord, dy / np.where(steep, 1.0, t_b[:, 1]))
        mag_e = np.where(steep, chord, dy / t_e[:, 1])
    mag_b = np.where(live, mag_b, 0.0)
    mag_e = np.where(live, mag_e, 0.0)
    for j in np.flatnonzero(steep & ~missed & live):
        log.append(f"{wing.name} {side} fillet line {j + 1}: start tangent nearly vertical "
                   f"(theta = {np.degrees(theta_b[j]):.1f} deg); chord-length tangents used")
    s = np.linspace(0.0, 1.0, int(n_points))
    kind = "cubic"
    if remedy == "parabolas":
        f = _blended_parabolas(body, B, theta_b, sign, E, t_e, chord, s)
        kind = "parabolas"
    else:
        f = hermite(B, E, t_b * mag_b[:, None], t_e * mag_e[:, None], s)
    # Extrapolated lofting line from I to E at the same s (the v of eq 10).
    v = I[:, None] + s[None, :, None] * (E - I)[:, None]
    dips = _dips(f, v, sign, s) & live
    if remedy == "z-constraint":
        f = f.copy()
        f[..., 2] = np.where(sign * (f[..., 2] - v[..., 2]) < 0, v[..., 2], f[..., 2])
        log.append(f"{wing.name} {side}: z-constraint applied to {int(dips.sum())} dipping "
                   "fillet lines (slope discontinuities where it acts)")
    elif remedy not in (None, "parabolas"):
        raise GeometryError(f"fillet remedy must be None, 'z-constraint' or 'parabolas', found "
                            f"{remedy!r}", wing.name)
    for j in np.flatnonzero(dips):
        log.append(f"{wing.name} {side} fillet line {j + 1}: fillet "
                   f"{'dips below' if sign > 0 else 'rises above'} the extrapolated wing "
                   "surface (low-wing case); remedies: larger theta_u, remedy='z-constraint', "
                   "remedy='parabolas', or fillet='circular'")
    if blending == "points":
        pts = (1.0 - beta)[:, None, None] * v + beta[:, None, None] * f
        start = pts[:, 0]
        ctr = body.center_at(start[:, 0])
        theta_b = np.arctan2(start[:, 2] - ctr[:, 1], start[:, 1] - ctr[:, 0])
    else:
        pts, start = f, B
    return FilletLines(side, pts, start, E, theta_b, u_e, beta, dips, kind, tuple(log),
                       blend_range)


def _dips(f, v, sign, s):
    """Interior fillet points on the wrong side of the extrapolated wing surface."""
    # Compare heights at the same y: v is linear in y between I and E.
    inner = (s > 0) & (s < 1)
    yv0, yv1 = v[:, 0, 1], v[:, -1, 1]
    t = (f[..., 1] - yv0[:, None]) / np.where(yv1 != yv0, yv1 - yv0, 1.0)[:, None]
    within = (t > 0) & (t < 1) & inner[None, :]
    zv = v[:, 0, 2][:, None] + t * (v[:, -1, 2] - v[:, 0, 2])[:, None]
    return np.any(within & (sign * (f[..., 2] - zv) < -1e-12), axis=1)


def _blended_parabolas(body, B, theta_b, sign, E, t_e, chord, s):
    """Overhauser (blended parabolas) curve between B and E through neighbouring points.

    P0 lies on the body circle beyond B (a further theta step away from the wing), P3 on the
    lofting line beyond E; the curve on [B, E] blends the parabola through P0, B, E with the
    parabola through B, E, P3 (Catmull-Rom form, uniform parameter).
    """
    step = np.radians(10.0) * sign
    P0 = body.point(B[:, 0], theta_b + step)
    P3 = E + t_e * chord[:, None]
    s_ = np.asarray(s, float)[None, :, None]
    return 0.5 * ((2 * B[:, None]) + (-P0 + E)[:, None] * s_
                  + (2 * P0 - 5 * B + 4 * E - P3)[:, None] * s_ ** 2
                  + (-P0 + 3 * B - 3 * E + P3)[:, None] * s_ ** 3)
