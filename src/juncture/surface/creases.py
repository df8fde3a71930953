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

__all__ = ["corner_points", "mark_creases", "CORNER_LINE", "CORNER_CREASE", "ON_CORNER"]

#: ``lines`` value (:func:`juncture.surface.pipeline._line_points`) of a vertex on a corner
#: line of an arbitrary section.
CORNER_LINE = 2
#: An edge between two corner-line vertices whose triangles turn by more than this [deg]
#: is kept.
CORNER_CREASE = 5.0
#: A vertex whose surface parameter is this near a corner's lies on that corner line.
ON_CORNER = 1e-9


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
