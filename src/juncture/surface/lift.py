"""New mesh points onto the exact surface of circular bodies and wing-like components.

The re-triangulation (:mod:`juncture.surface.remesh`) finds each new point on the assembled
surface's flat triangles. On a fuselage or pod those cut the circle by up to
``r (1 - cos(dtheta / 2))`` (0.5 % of the radius at the transport's 12° spacing), and that is
most of the enclosed volume's error. :func:`body_lift` moves a new point radially onto the
body's circle at its station, ``c(x) + r(x) (p - c(x)) / |p - c(x)|``, where the flat
triangle it lies on is the body's own: every corner on that circle (to 1e-9 of the size).
A point on a fillet, a cap, a step between segments (whose triangles face along x) or a wing
stays where it is, and seam
points are never moved (they are made on the seam's straight edges, shared by both sides).

A wing's networks join its ordinates by straight lines, where the model's sections are
PCHIP curves through them (chordwise ``"pchip"``, the default): :func:`surface_lift` also
moves a new point on a wing-like component's own triangle (one of its own upper or lower
networks, or, in a block shared with a body, every corner on the model's upper or every
corner on its lower surface) along the thickness axis onto that surface at the same span
station and chord fraction, the lofting lines extended beyond the end sections where a root
crossing or outside the fuselage meets it there (TM-4406 eq 4).
"""

from __future__ import annotations

import numpy as np

from .ducts import duct_circles, onto_duct

__all__ = ["surface_lift", "body_lift", "wing_lift", "shared_vertices", "ON_BODY"]

#: A corner lies on its body's circle within this share of the airplane's size.
ON_BODY = 1e-9
#: A body's own triangle faces away from its centre line: |cos| of its normal's angle to the
#: radial direction above this (a cap or a flat step between segments faces along x).
FACING = 0.2


#: Chord fractions sampled for a wing section's largest thickness.
THICKNESS_SAMPLES = 21
#: A wing section's size is at least this share of its chord.
THIN = 0.02

#: A wing's triangle is lifted along the thickness axis only where it faces that way (|cos|
#: of its normal's angle to the axis above this): near a leading edge the move would be
#: along the surface and would distort the triangles.
WING_FACING = 0.5
#: A point lies within the chord where its fraction is in [0, 1] to this: a trailing edge's
#: point, le + chord, comes out of the division at 1 + 2e-16 (and its triangles went unlifted).
ROUND = 1e-12


def _normals(triangles):
    """(k, 3) unit normals of triangles (k, 3, 3)."""
    n = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    return n / np.maximum(np.linalg.norm(n, axis=1), np.finfo(float).tiny)[:, None]


def _radial(triangles, unit):
    """|cos| of the angle between each triangle's normal and the radial direction."""
    return np.abs(np.einsum("ij,ij->i", _normals(triangles)[:, 1:], unit))


def _models(geometry, mesh, kind):
    """{component index: [models]} of the mesh's components that are ``kind``. The
    four-block layout's juncture blocks ("wing-body": body arcs and wing in one network) get
    every model of that kind: each move lifts only points whose flat triangle lies on that
    model's surface."""
    comps = getattr(geometry, "configuration", None)
    if comps is None:
        return {}
    mine = [c for c in comps if isinstance(c, kind)]
    by_name = {c.name: c for c in mine}
    out = {}
    for k, name in enumerate(mesh.components):
        if name in by_name:
            out[k] = [by_name[name]]
        elif name == "wing-body" and mine:
            out[k] = mine
    return out


def surface_lift(geometry, mesh):
    """One ``lift`` for :func:`~juncture.surface.remesh.remesh` doing :func:`body_lift` on
    circular bodies and :func:`wing_lift` on wing-like components (None if neither applies).
    ``lift.seam``: the exact curves where wing-like components meet bodies
    (:func:`juncture.surface.seam_curves.seam_curves`; None where there are none);
    ``lift.bodies``: the ids of the mesh's components that are circular bodies."""
    bodies = body_lift(geometry, mesh)
    lifts = [f for f in (bodies, wing_lift(geometry, mesh)) if f]
    if not lifts:
        return None

    def lift(points, corners, component, surface):
        for f in lifts:
            points = f(points, corners, component, surface)
        return points

    def both(points, corners, component, surface):
        size = np.full(len(points), np.inf)
        for f in lifts:
            points, got = f.both(points, corners, component, surface)
            size = np.minimum(size, got)
        return points, size

    lift.both = both
    lift.bodies = bodies.components if bodies else frozenset()   # circular bodies' ids
    from .seam_curves import seam_curves

    lift.seam = seam_curves(geometry, mesh)
    return lift


def _polar(body, points, image):
    """(radius of the points about the body's centre line, its radius there, unit
    directions (k, 2) in y-z) at the points' stations."""
    centre, radius = body.section_at(points[:, 0])
    if image:
        centre = centre * [-1.0, 1.0]
    d = points[:, 1:] - centre
    rho = np.linalg.norm(d, axis=1)
    return rho, radius, centre, d / np.where(rho > 0, rho, 1.0)[:, None]


def shared_vertices(mesh):
    """(n_vertices,) bool: vertices of triangles of more than one component (the seams
    between components: intersection and fillet-start lines)."""
    n = len(mesh.vertices)
    comp = np.repeat(np.asarray(mesh.component), 3)
    ids = np.asarray(mesh.triangles).ravel()
    lo, hi = np.full(n, np.iinfo(np.int64).max), np.full(n, -1)
    np.minimum.at(lo, ids, comp)
    np.maximum.at(hi, ids, comp)
    return (hi >= 0) & (lo != hi)


def _lifter(geometry, mesh, kind, move, classify):
    """``lift(points, corners, component, surface)`` calling ``move(model, points, corners
    (k, 3, 3), seam (k, 3), image, tol, sized, flags)`` (which returns the points and their
    sizes) for points on components of type ``kind`` (caps excluded), or None when the
    geometry has none. ``seam``: the corners that other components' triangles share
    (:func:`shared_vertices`); ``flags``: ``classify(model, vertices, image, tol)`` (a tuple of
    per-vertex arrays: where each vertex lies on the model), made once per model and side
    for every vertex of the mesh and taken at the corners (k, 3).

    ``lift.both(points, corners, component, surface)``: (the lifted points, per point the
    size of the exact surface it is lifted onto: a body's radius, a wing section's largest
    thickness, inf where it is not lifted). A sag of a share of that size costs about that
    share of the volume.
    """
    models = _models(geometry, mesh, kind)
    if not models:
        return None
    vertices = np.asarray(mesh.vertices, float)
    tol = ON_BODY * float(np.ptp(vertices, axis=0).max())
    shared = shared_vertices(mesh)
    known = {}
    ducts = duct_circles(mesh)

    def flags(model, image, corners):
        key = (id(model), image)
        if key not in known:
            known[key] = classify(model, vertices, image, tol)
        return tuple(f[corners] for f in known[key])

    def both(points, corners, component, surface, sized=True):
        name = mesh.surfaces[int(surface)]
        points = np.asarray(points, float)
        size = np.full(len(points), np.inf)
        if not len(points) or name.endswith(" cap"):
            return points, size
        if int(surface) in ducts:
            return onto_duct(points, *ducts[int(surface)]), size
        image = name.endswith(" image")
        for model in models.get(int(component), ()):
            points, got = move(model, points, vertices[corners], shared[corners], image, tol,
                               sized, flags(model, image, corners))
            size = np.minimum(size, got)
        return points, size

    def lift(points, corners, component, surface):
        return both(points, corners, component, surface, sized=False)[0]

    lift.both = both
    lift.components = frozenset(models)
    return lift


def body_lift(geometry, mesh):
    """``lift(points, corners, component, surface)`` for :func:`~juncture.surface.remesh.
    remesh`, or None when the geometry has no circular body.

    ``corners`` (k, 3) are the ids of the vertices of ``mesh`` (the assembled surface) of the
    flat triangle each point lies on; points on a body's own triangles are moved onto its
    circle, the others returned as they are.
    """
    from ..model import CircularBody

    return _lifter(geometry, mesh, CircularBody, _onto_circle, _on_circle)


def _on_circle(body, vertices, image, tol):
    """(per vertex: on the body's circle within ``tol``,)."""
    rho, radius, _, _ = _polar(body, vertices, image)
    return (np.abs(rho - radius) <= tol,)


def _onto_circle(body, points, corners, seam, image, tol, sized, flags):
    on = flags[0].all(axis=1)
    rho, radius, centre, unit = _polar(body, points, image)
    on &= (radius > 0) & (rho > 0) & (_radial(corners, unit) > FACING)
    out = points.copy()
    out[on, 1:] = centre[on] + radius[on, None] * unit[on]
    return out, np.where(on, radius, np.inf)


def edges_x(wing, s, extrapolate=False):
    """(le, te): x of a wing-like component's leading and trailing edges at span stations
    ``s`` (the ruled surface; ``extrapolate``: extended beyond the end sections)."""
    ends = wing.point(np.concatenate([s, s]), np.repeat([0.0, 1.0], len(s)), "upper",
                      extrapolate=extrapolate)[:, 0]
    return ends[:len(s)], ends[len(s):]


def _chordwise(wing, p):
    """(span stations, chord fractions, inside the span) of points in the wing's frame."""
    lo, hi = wing.span_stations[0], wing.span_stations[-1]
    s = np.clip(p[:, wing.span_axis], lo, hi)
    le, te = edges_x(wing, s)
    f = (p[:, 0] - le) / np.where(te > le, te - le, 1.0)
    inside = (p[:, wing.span_axis] >= lo) & (p[:, wing.span_axis] <= hi) & (te > le)
    return s, np.clip(f, 0.0, 1.0), inside & (f >= -ROUND) & (f <= 1.0 + ROUND)


def _thickness(wing, p):
    """(upper, lower) thickness-axis coordinates of the model at the points' (s, f), and
    whether (s, f) is inside the wing."""
    s, f, inside = _chordwise(wing, p)
    t = wing.thickness_axis
    return wing.point(s, f, "upper")[:, t], wing.point(s, f, "lower")[:, t], inside


def wing_lift(geometry, mesh):
    """``lift(points, corners, component, surface)`` moving points on a wing-like
    component's own triangles onto its model surface (see the module's docstring), or None
    when the geometry has no wing-like component."""
    from ..model import WingLike

    return _lifter(geometry, mesh, WingLike, _onto_sections, _on_sides)


def _on_sides(wing, vertices, image, tol):
    """(per vertex: on the upper side within ``tol``, on the lower side), inside the wing's
    span and chord; a vertex at the one point of a section of no chord (a pointed tip) is
    on both."""
    flip = np.array([1.0, -1.0, 1.0]) if image else np.ones(3)
    c = vertices * flip
    t = wing.thickness_axis
    up, low, inside = _thickness(wing, c)
    tip = _at_points_of_no_chord(wing, c, tol)
    return ((inside & (np.abs(c[:, t] - up) <= tol)) | tip,
            (inside & (np.abs(c[:, t] - low) <= tol)) | tip)


def _at_points_of_no_chord(wing, p, tol):
    """(n,) bool: points within ``tol`` of the one point of a section of no chord."""
    s = np.asarray(wing.span_stations, float)
    le, te = edges_x(wing, s)
    ends = s[~(te > le)]
    if not len(ends):
        return np.zeros(len(p), bool)
    tips = wing.point(ends, np.zeros(len(ends)), "upper")
    return np.linalg.norm(p[:, None, :] - tips[None], axis=2).min(axis=1) <= tol


def _onto_sections(wing, points, corners, seam, image, tol, sized, flags):
    """Points moved along the thickness axis onto the side of the wing their flat triangle
    lies on: each corner on that side within ``tol`` or on a ``seam`` with another component
    (the root line's points at the fuselage's stations lie on the body, off the wing's PCHIP
    sections), at least one on it. A fillet's triangles have corners off both. Where as many
    corners lie on either side (a leading or trailing edge's, a pointed tip's, with the
    others on seams: a wing of two sections ending in a point), the side the triangle
    faces (outward) decides."""
    flip = np.array([1.0, -1.0, 1.0]) if image else np.ones(3)
    t = wing.thickness_axis
    faces_up = (_normals(corners) * flip)[:, t] > 0.0
    corners = corners * flip
    facing = np.abs(_normals(corners)[:, t]) > WING_FACING
    on_up, on_low = flags
    n_up, n_low = on_up.sum(axis=1), on_low.sum(axis=1)
    on_up = (on_up | seam).all(axis=1) & (n_up > 0) & facing
    on_low = (on_low | seam).all(axis=1) & (n_low > 0) & facing
    p = points * flip
    up, low, inside = _thickness(wing, p)
    out = p.copy()
    # A leading or trailing edge's corner lies on both sides: the side with more corners.
    tie = n_up == n_low
    up_only = on_up & (~on_low | (n_up > n_low) | (tie & faces_up)) & inside
    low_only = on_low & (~on_up | (n_low > n_up) | (tie & ~faces_up)) & inside
    out[:, t] = np.where(up_only, up, out[:, t])
    out[:, t] = np.where(low_only, low, out[:, t])
    moved = up_only | low_only
    size = np.full(len(p), np.inf)
    if sized and moved.any():
        size[moved] = _largest_thickness(wing, p[moved])
    return out * flip, size


def _largest_thickness(wing, p):
    """The largest thickness of the wing's section at the points' span stations, at least
    :data:`THIN` of its chord (a flat plate's camber line still has a size)."""
    s, _, _ = _chordwise(wing, p)
    f = np.linspace(0.0, 1.0, THICKNESS_SAMPLES)
    ss, ff = np.repeat(s, f.size), np.tile(f, s.size)
    t = wing.thickness_axis
    up, low = wing.point(ss, ff, "upper"), wing.point(ss, ff, "lower")
    gap = np.abs(up[:, t] - low[:, t]).reshape(s.size, f.size).max(axis=1)
    chord = np.ptp(up[:, 0].reshape(s.size, f.size), axis=1)
    return np.maximum(gap, THIN * chord)
