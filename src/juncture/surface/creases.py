"""Corner lines of arbitrary sections kept as edges of a re-triangulation.

An arbitrary fuselage section is the polygon the deck gives (the Harris program joins its
points by straight lines), and between two stations the surface joins the two polygons
point by point: each corner of the polygon runs along the body as a straight line. The
networks put a row's points on those corners
(:func:`juncture.surface.body_split.through_corners`), so the assembled facets are the
surface. No new point of a re-triangulation is put back on an arbitrary section
(:mod:`juncture.surface.lift` lifts only onto circles and wings), and a new triangle across a
corner line cuts the corner off: a held-out airplane's constant section stood 0.3 % inside
where the layout kept every corner. Here the network edges along those lines become
constraint edges of their patch's chart (:func:`mark_creases`), so the re-triangulation
keeps them (split points on them stay on the straight line).
"""

from __future__ import annotations

import numpy as np

__all__ = ["corner_points", "mark_creases", "mark_curves", "CORNER_LINE", "CORNER_CREASE",
           "ON_CORNER"]

#: ``lines`` value (:func:`juncture.surface.pipeline._line_points`) of a vertex on a corner
#: line of an arbitrary section.
CORNER_LINE = 2
#: An edge between two corner-line vertices whose triangles turn by more than this [deg]
#: is kept.
CORNER_CREASE = 5.0
#: A vertex whose surface parameter is this near a corner's lies on that corner line.
ON_CORNER = 1e-9
#: An inner edge on an exact curve is kept only where its chord's middle lies within this
#: share of the size of the curve (followed: :data:`~juncture.surface.seam_curves.SAG`,
#: with room): a chord of the assembled surface, sagging off the curve, kept with its
#: split points lifted onto the wing (both sides one network) folded the thin triangle
#: between it and the fuselage's side (held-out seed 8282 draw 38: 12 crossing pairs,
#: then held tries that doubled the triangles).
FOLLOWS = 4e-6


def corner_points(geometry, surface):
    """(k,) ids of the vertices of ``surface`` on the corner lines of arbitrary-section
    bodies (:meth:`juncture.model.body.ArbitraryBody.corners` at their stations)."""
    out = []
    cfg = getattr(geometry, "configuration", None)
    for k, name in enumerate(surface.components):
        body = cfg.components.get(name) if cfg is not None else None
        if not hasattr(body, "corners"):
            continue
        ids = np.unique(surface.triangles[surface.component == k])
        x = surface.vertices[ids, 0]
        s = body.parameter_of(surface.vertices[ids])
        at = np.zeros(len(ids), bool)
        for xi in np.unique(x).tolist():
            c = body.corners(xi)
            if c.size:
                rows = np.flatnonzero(x == xi)
                at[rows] = np.abs(s[rows, None] - c[None, :]).min(axis=1) <= ON_CORNER
        out.append(ids[at])
    return np.concatenate(out) if out else np.zeros(0, np.int64)


def mark_creases(charted, lines):
    """Append to each charted patch's ``edges`` its inner network edges between two
    vertices marked :data:`CORNER_LINE` in ``lines`` where its triangles turn by more than
    :data:`CORNER_CREASE` (both ends kept in the chart), and count them in
    ``patch.creases``. Only a patch whose chart has one boundary loop takes them (its
    triangulation then drops only the triangles outside that loop: inner constraint
    edges would make the pieces between them holes)."""
    if lines is None:
        return
    marked = np.asarray(lines) == CORNER_LINE
    if not marked.any():
        return
    from .assemble import boundary_loops
    from .chart import edge_sides, patch_edges

    limit = np.cos(np.radians(CORNER_CREASE))
    for patch in charted:
        if marked[patch.ids].sum() < 2:
            continue
        t = patch.tri
        _, und, uses, inverse = patch_edges(t)
        inner = np.flatnonzero((uses == 2) & marked[patch.ids[und]].all(axis=1)
                               & patch.kept[und].all(axis=1))
        if not len(inner) or len(boundary_loops(t)) != 1:
            continue
        first, second = edge_sides(uses, inverse)
        a, b = first[inner], second[inner]
        n = patch.normals
        turned = np.einsum("ij,ij->i", n[a], n[b]) < limit
        if turned.any():
            patch.edges = np.concatenate([patch.edges, und[inner[turned]]])
            patch.keys = None
            patch.creases = int(turned.sum())


def mark_curves(charted, curves):
    """Append to each charted patch's ``edges`` its inner edges on an exact intersection
    curve (``curves``, :class:`~juncture.surface.seam_curves.SeamCurves`: both ends on one
    curve) that follow it (within :data:`FOLLOWS`, ``curves.follows``), keep their ends in
    the chart and count them in ``patch.creases``. A layout that
    makes a wing and the fuselage's middle one network (``wing-body upper``) carries the
    curve inside a patch where the two do not turn by :data:`~juncture.surface.patches.CREASE`
    across it: its points, split to follow the curve
    (:func:`juncture.surface.seam_curves.follow_curves`), were inner vertices, dropped where
    they stood close together (:data:`~juncture.surface.patches.NEAR`) and joined by
    whatever edges the triangulation made, so the mesh cut the curve (by 7.7e-4 of the size
    on held-out seed 8181 draw 10). A patch with more than one boundary loop is ``holed``: its
    outside and holes are then found counting its boundary alone
    (:func:`juncture.surface.remesh._outer_and_holes`)."""
    if curves is None:
        return
    from .assemble import boundary_loops
    from .chart import patch_edges

    for patch in charted:
        _, und, uses, _ = patch_edges(patch.tri)
        inner = np.flatnonzero(uses == 2)
        if not len(inner):
            continue
        ends = patch.ids[und[inner]]
        inner = inner[curves.on_curve(ends[:, 0], ends[:, 1]) >= 0]
        if len(inner):
            ends = patch.ids[und[inner]]
            inner = inner[curves.follows(ends[:, 0], ends[:, 1], FOLLOWS * curves.size)]
        if not len(inner):
            continue
        patch.kept[und[inner].ravel()] = True
        patch.edges = np.concatenate([patch.edges, und[inner]])
        patch.keys = None
        patch.creases += len(inner)
        patch.holed = len(boundary_loops(patch.tri)) != 1
