"""Fillet lines as every fillet kind returns them, their curves and their blending.

:class:`FilletLines` holds one wing surface's fillet lines (cubic, parabolas or circular);
:func:`hermite` and :func:`bezier` evaluate cubic curves; :func:`blend_over` and
:func:`blend_factor` are TM-4406's blending towards the leading and trailing edges
(eqs 8-9), shared by the cubic and circular fillets.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["FilletLines", "hermite", "bezier", "blend_over", "blend_factor", "ONE_POINT"]

#: A fillet line whose points all lie within this share of its coordinates' size of its
#: end is that one point (no fillet there).
ONE_POINT = 1e-10


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
        Upper (lower) fillet dips below (rises above) the wing's tangent plane at its end:
        the low-wing problem of TM-4406, which :func:`cubic_fillet` no longer has (only
        ``missed_lines="paper"`` lines can show it).
    kind : str
        ``"cubic"``, ``"parabolas"`` or ``"circular"``.
    log : tuple of str
    blend_range : tuple of float or None
        (x_le, x_te, l_b) the blending used [deck length]: pass it back as ``blend_range``
        to blend another body's fillet over the same region.
    control : (n_stations, 4, 3) float or None
        Bezier control points of each line when it is a cubic in s (the points are the
        cubic at equally spaced s); a row of NaN where a line is not (the z-constraint).
        Used for the exact added area (:func:`juncture.fillet.fillet_added_area`).
    towards : (n_stations,) float or None
        Cubic fillets: how far each line's tangent lengths went from the guaranteed legs
        towards the paper's (0 to 1; NaN where the paper's fit): pass it back as
        ``towards`` to build another body's fillet the same way (keep_area's iterates).
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
    control: np.ndarray = None
    towards: np.ndarray = None

    def __post_init__(self):
        # A line whose points are one point to round-off (no fillet at the leading or
        # trailing edge, or where the blending takes it to nothing) is its end, the
        # intersection point, start included: not a cubic through it that round-off spreads
        # by ulps (a held-out airplane's line spread over 2e-13 of 27 ft, 8 ulps: the points
        # stayed apart and a cap of no size crossed the wing). The upper and lower fillets
        # and the body rows there then share the point, bit for bit.
        pts = np.asarray(self.points)
        start, end = np.asarray(self.start), np.asarray(self.end)
        if pts.ndim == 3 and start.shape == (len(pts), 3) and end.shape == start.shape:
            scale = 1.0 + np.abs(end).max(axis=1)
            spread = np.abs(pts - end[:, None, :]).max(axis=(1, 2))
            point = np.isfinite(end).all(axis=1) & (spread <= ONE_POINT * scale)
            if point.any():
                pts, start = np.array(pts, dtype=float), np.array(start, dtype=float)
                pts[point] = end[point][:, None, :]
                start[point] = end[point]
                object.__setattr__(self, "points", pts)
                object.__setattr__(self, "start", start)


def hermite(p0, p1, t0, t1, s):
    """Cubic Hermite curves, vectorised: (m, 3) ends and tangents, s (k,) -> (m, k, 3)."""
    s = np.asarray(s, float)[None, :, None]
    h00 = 2 * s ** 3 - 3 * s ** 2 + 1
    h10 = s ** 3 - 2 * s ** 2 + s
    h01 = -2 * s ** 3 + 3 * s ** 2
    h11 = s ** 3 - s ** 2
    return (h00 * p0[:, None] + h10 * t0[:, None] + h01 * p1[:, None] + h11 * t1[:, None])


def bezier(control, s):
    """Cubic Bezier curves, vectorised: control (m, 4, d), s (k,) -> (m, k, d)."""
    s = np.asarray(s, float)[None, :, None]
    c = np.asarray(control, float)
    w = 1.0 - s
    return (w ** 3 * c[:, None, 0] + 3 * w * w * s * c[:, None, 1]
            + 3 * w * s * s * c[:, None, 2] + s ** 3 * c[:, None, 3])


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
