"""Lofting lines that miss the fuselage: where each wing surface ends instead.

TM-4406 extends every lofting line inboard until it meets the fuselage (eq 4). A line can
miss it: the upper surface of a high wing passes over the top of the body, the lower surface
of a low wing passes under it, and a highly swept leading edge continued inboard runs ahead
of a slender nose (or a trailing edge behind the body's end). Going inboard, the search for a
crossing stops at the body's centre plane (y = y_c, the plane of symmetry), so a line that
misses has there a point Q on the wing surface, above or below the body.

Rule, for every line that misses: the surface is continued along its lofting line to the
plane of symmetry, where it meets its mirror image; the line ends at Q. This is the surface of
the union of the components: where the body lies wholly below (above) the extended wing
surface at y = y_c there is no wing-body junction at that chordwise station, the body under
(over) the wing is covered by it, and what is exposed is the wing surface itself, all the way
to its mirror image. A fillet has nothing to round there, so cubic and circular fillet lines of
such a line are degenerate at Q (no fillet), as at the leading and trailing edges. A surface
without a mirror image ends open there. A canard or tail with a mirror image on the fuselage
follows the same rule in the split layout (a tail's trailing edge passing under a narrowing
tail cone); elsewhere its line keeps its input root point
(:mod:`juncture.surface.component_networks`).

TM-4406 ("Special situations") treats one case, a lower line of a low wing passing under the
body, with a cubic fillet: "the theta = -90 deg location at the appropriate x-station is taken
as the initial point for the fillet line, and the initial values of both dx/dy and dz/dy are
set equal to 0". That start lies inside the wing or above it (the body's bottom is above the
wing's lower surface there, since the line passes under the body), so such a fillet crosses
the wing to reach its lower surface and dents it up to the body's bottom; it is kept as an
option of :func:`juncture.fillet.cubic.cubic_fillet` (``missed_lines="paper"``), and
:func:`juncture.complete` continues every line instead. The paper is silent on the other
cases. Joining an upper line at the body's top line (the paper's rule turned upside down)
would likewise cut a notch into the wing: the straight panel from the body's top to the
second section runs inside the wing, up to the height by which the wing clears the body.

The body arc on the wing's side of the junction ends at the line's end point. Where Q lies on
the side of the body the arc would cover (above the top for the upper surface, below the
bottom for the lower), that arc is empty: the network row is degenerate at Q (every point Q),
so the body and wing networks stay closed. Where both surfaces of a line pass on the same
side of the body (the wing does not touch it at that chordwise station, e.g. a leading edge
that runs ahead of a slender nose), the other arc covers the whole half-section and its last
point is Q: a panel in the plane of symmetry joins the body to the wing there. In the
fuselage split by theta_b (TM-4607, the default layout) that arc ends on the plane at the
body's own point before Q, so the panel lies in the plane, where the mirror image's cancels
it in a mesh of both halves, and at the first or last station of such a run (a tail's
trailing edge passing under a tail cone, a high wing's over the fuselage's top) the body's
stations beyond start from the body, not from Q
(:func:`juncture.surface.body_split.split_body`).

``theta`` of an end point Q is that of the body point nearest to it in the plane of symmetry
(+pi/2 above the body, -pi/2 below; 1 and 0 on an arbitrary-section body), so boundary curves
(the theta_b of TM-4607) and point counts stay defined.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .errors import GeometryError
from .intersect.rays import polyline_points
from .surface.networks import body_range

__all__ = ["LineEnds", "line_ends", "plane_points", "ended_lines"]


def _centre_coordinate(wing, body, lines):
    """Section coordinate u at which each lofting line reaches the body's centre plane."""
    s = wing.span_stations
    if wing.span_axis == 1:
        origin = getattr(body, "origin", None)
        c = np.full(lines.shape[0], 0.0 if origin is None else float(origin[1]))
    else:  # a fin or pylon: the centre height at the line's root
        c = body.center_at(lines[:, 0, 0])[:, 1]
    return (c - s[0]) / (s[1] - s[0])


def plane_points(wing, body, side):
    """Where each lofting line of ``side`` reaches the body's centre plane (the point Q).

    Returns ``(points (m, 3), u (m,))``: the point and its section coordinate (<= 0: on the
    extension beyond the root, TM-4406 eq 4; 0 if the root lies inboard of the plane).
    """
    lines = wing.lofting_lines(side)
    u = np.minimum(_centre_coordinate(wing, body, lines), 0.0)
    return polyline_points(lines, u[:, None])[:, 0], u


@dataclass(frozen=True, slots=True, eq=False)
class LineEnds:
    """Where each lofting line of one wing surface ends (module docstring).

    Attributes
    ----------
    points : (m, 3) float
        The intersection with the body, or Q on the plane of symmetry for a line that misses.
    theta : (m,) float
        Body angle (section parameter) of the intersection, or of the body's top / bottom
        for Q above / below the body.
    u : (m,) float
        Section coordinate of the point on its lofting line.
    missed : (m,) bool
        Lines that miss the body.
    above : (m,) bool
        Among those, lines whose Q lies above the body (else below).
    log : tuple of str
        One message per line that misses, in line order.
    """

    points: np.ndarray
    theta: np.ndarray
    u: np.ndarray
    missed: np.ndarray
    above: np.ndarray
    log: tuple = ()


def line_ends(wing, body, inter):
    """:class:`LineEnds` of one surface from its intersection with the body."""
    missed = ~np.asarray(inter.found, bool)
    pts = np.array(inter.points, float)
    theta = np.array(inter.theta, float)
    u = np.array(inter.u, float)
    above = np.zeros(missed.shape, bool)
    log = []
    if missed.any():
        q, u_q = plane_points(wing, body, inter.side)
        bottom, top, _ = body_range(body)
        above = missed & (q[:, 2] >= body.center_at(q[:, 0])[:, 1])
        pts[missed], u[missed] = q[missed], u_q[missed]
        theta[missed] = np.where(above[missed], top, bottom)
        for j in np.flatnonzero(missed):
            where = "over" if above[j] else "under"
            log.append(f"{inter.name}: lofting line {j + 1} passes {where} {body.name}; "
                       f"continued to the plane of symmetry at x = {q[j, 0]:.6g} "
                       "(meets its mirror image there)")
        _refuse_buried(wing, body, inter, missed, q)
    return LineEnds(pts, theta, u, missed, above, tuple(log))


def _refuse_buried(wing, body, inter, missed, q):
    """A line "missing" the body whose end Q on the plane of symmetry lies inside it entered
    the body where it has no surface to meet: the face of a step at a joint station that two
    segments repeat with different sections, or an open end. Continued to Q it would run
    through the body's inside (and a fillet there would lie in it): refused (issue 11),
    naming the line and the step's station."""
    size = 1e-9 * max(float(body.length), 1.0)
    distance = body.radial_error if hasattr(body, "radial_error") else body.signed_distance
    buried = missed & (distance(np.where(missed[:, None], q, 0.0)) < -size)
    if not buried.any():
        return
    j = int(np.argmax(buried))
    refuse_buried_line(wing, body, inter.side, j, wing.lofting_lines(inter.side)[j], q[j],
                       "continued to the plane of symmetry")


def refuse_buried_line(wing, host, side, j, line, point, kept):
    """Raise the GeometryError for lofting line ``j`` of ``wing``'s ``side`` that meets no
    surface of ``host`` but whose end ``point`` lies inside it: for a body, the step at a
    joint station between the line's x range and the point's, else its open end."""
    lo, hi = min(line[:, 0].min(), point[0]), max(line[:, 0].max(), point[0])
    x = np.asarray(getattr(host, "x_global", ()), float)
    steps = [float(v) for v in x[1:][(x[1:] == x[:-1])] if lo <= v <= hi]
    if not hasattr(host, "signed_distance"):
        where, change = "through a face juncture does not model", "Change its end"
    elif steps:
        where = (f"through the face of the step at x = {steps[0]:.6g}, where two fuselage "
                 "segments repeat the station with different sections")
        change = "Give both segments the same section at the joint"
    else:
        where, change = "through an open end", f"Close {host.name}'s end"
    raise GeometryError(f"{side} lofting line {j + 1} enters {host.name} only "
                        f"{where}, which is no surface juncture intersects: {kept} it would "
                        f"run inside {host.name} (x = {point[0]:.6g}). {change}, or move "
                        f"{wing.name} so that the line meets {host.name}'s surface", wing.name)


def ended_lines(lines, ends, rows):
    """``lines`` (FilletLines) with ``rows`` (bool mask) degenerate at their end points.

    Every point of such a line, its start and its end are ``ends.points`` (no fillet there),
    with ``theta_start`` and ``u_end`` from ``ends`` and no blending.
    """
    rows = np.asarray(rows, bool)
    if not rows.any():
        return lines
    said = dict(zip(np.flatnonzero(ends.missed), ends.log))
    log = tuple(said[j] for j in np.flatnonzero(rows) if j in said)
    pts = np.array(lines.points, float)
    pts[rows] = ends.points[rows, None, :]
    start, end = np.array(lines.start, float), np.array(lines.end, float)
    start[rows], end[rows] = ends.points[rows], ends.points[rows]
    theta, u_end = np.array(lines.theta_start, float), np.array(lines.u_end, float)
    theta[rows], u_end[rows] = ends.theta[rows], ends.u[rows]
    blend, dips = np.array(lines.blend, float), np.array(lines.dips, bool)
    blend[rows], dips[rows] = 0.0, False
    extra = {}
    if getattr(lines, "control", None) is not None:  # Bezier control points: those of Q
        control = np.array(lines.control, float)
        control[rows] = ends.points[rows, None, :]
        extra["control"] = control
    return replace(lines, points=pts, start=start, end=end, theta_start=theta, u_end=u_end,
                   blend=blend, dips=dips, log=tuple(lines.log) + log, **extra)
