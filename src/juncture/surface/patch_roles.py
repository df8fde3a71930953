"""Which patches of an assembled surface are charted, and what each must know of its seams.

:func:`sorted_patches` sorts the patches of an assembled surface for
:func:`juncture.surface.remesh.remesh`: charted and re-triangulated, kept (with their
neighbours' seam points as fans), zipped as thin strips (:mod:`juncture.surface.strips`),
or copied from their mirror image (:mod:`juncture.surface.mirror`); triangles held where
re-triangulated surfaces crossed are charted apart and lifted only away from the crossing
(:func:`away_from`). Each charted patch learns which of its boundary edges are free seams
(:func:`mark_free`: their two sides do not lift alike) and how steeply a new point may rise
from each (:func:`mark_slopes`), which :func:`juncture.surface.patches.taper` uses.
"""

from __future__ import annotations

import numpy as np

from .creases import mark_creases, mark_curves
from .mirror import twins
from .patches import charts, patches
from .rows import unique_pairs

#: A new point lifted onto the exact surface moves at most 1 / TAPER of its distance from
#: the patch's boundary (surfaces meeting at less than atan(1 / TAPER) = 5.7 deg could
#: still cross).
TAPER = 10.0


def sorted_patches(mesh, keep, lift, splits, min_angle, lines=None, tiny=0.0,
                    held=(None, None), crossings=None):
    """(charted patches, kept triangle rows, strips, copies): a thin cap is a strip
    (:mod:`juncture.surface.strips`, its sides split in ``splits`` now for triangles of
    about ``min_angle``); a patch in ``keep``
    or one that cannot be charted keeps its triangles, as does one no larger than ``tiny``
    (the cap of a section a rounding's size across); a patch with rows in ``held`` (two
    masks or None: re-triangulated unlifted, kept) is charted in pieces, those of the first
    not lifted, those of the second kept; the mirror image of a patch charted
    whole (:func:`juncture.surface.mirror.twins`) is (its rows, that patch's charts), and
    takes their triangles mirrored at the end."""
    from .strips import presplit, strip, tip_and_strip

    charted, kept, strips, copied = [], [], [], []
    flat, frozen = (np.zeros(len(mesh.triangles), bool) if m is None else m for m in held)
    groups = patches(mesh, None if lines is None else np.asarray(lines) == 1)
    twin = {} if splits.mirror is None else twins(mesh, groups, splits.mirror)
    whole = {}                          # primary: its charts, where it is charted whole
    for i in [i for i in range(len(groups)) if i not in twin] + list(twin):
        rows = groups[i]
        if flat[rows].any() or frozen[rows].any():
            if frozen[rows].any():
                kept.append(rows[frozen[rows]])
            charted += _pieces(mesh, rows[flat[rows] & ~frozen[rows]], kept,
                               away_from(lift, crossings), held=True)
            charted += _pieces(mesh, rows[~flat[rows] & ~frozen[rows]], kept, lift)
            continue
        if whole.get(twin.get(i)):
            copied.append((rows, whole[twin[i]]))
            continue
        hold = mesh.surface[rows[0]] in keep or _extent(mesh, rows) <= tiny
        thin = None if hold else strip(mesh, rows)
        if thin is not None:
            strips.append(thin)
            presplit(thin, mesh.vertices, splits, min_angle)
            continue
        parts = None if hold else tip_and_strip(mesh, rows)
        if parts is not None:           # the strip zipped, the tip charted
            rows, thin = parts
            strips.append(thin)
            presplit(thin, mesh.vertices, splits, min_angle)
        pieces = []
        got = None if hold else charts(mesh, rows, kept=pieces)
        kept.extend(pieces)
        if got is None:
            kept.append(rows)
        elif parts is None and not pieces:
            whole[i] = got
        for patch in got or ():
            patch.lift = lift
            charted.append(patch)
    mark_creases(charted, lines)
    mark_curves(charted, getattr(lift, "seam", None))
    mark_free(charted, splits)
    mark_slopes(charted, mesh)
    return charted, kept, strips, copied


def away_from(lift, crossings):
    """``lift`` for held triangles: None (new points stay on them) without ``crossings``;
    with them ((k, 4): centres and radii of where re-triangulated surfaces crossed), a point
    within a radius of a centre is not lifted and one further away is lifted by at most
    its distance beyond that over :data:`TAPER` (a held facet may span a quarter of a body's
    circle and ten feet along it: its far parts, left on it, stood a tenth of the radius
    inside)."""
    if lift is None or crossings is None or not len(crossings):
        return None
    from scipy.spatial import cKDTree

    tree, radius = cKDTree(crossings[:, :3]), np.append(crossings[:, 3], np.inf)

    def held_lift(points, corners, component, surface):
        full = lift(points, corners, component, surface)
        move = np.linalg.norm(full - points, axis=1)
        dist, near = tree.query(points)
        room = np.maximum(dist - radius[near], 0.0) / TAPER
        w = np.clip(room / np.maximum(move, 1e-300), 0.0, 1.0)
        return points + w[:, None] * (full - points)

    return held_lift


def _pieces(mesh, rows, kept, lift, held=False):
    """The charts of the connected pieces of the triangle ``rows`` (what a patch leaves
    around its held triangles, or those, ``held``); a piece that does not chart is appended
    to ``kept``."""
    from .patches import _connected

    out = []
    for part in _connected(mesh, rows) if len(rows) else ():
        pieces = []
        got = charts(mesh, part, kept=pieces)
        kept.extend(pieces)
        if got is None:
            kept.append(part)
        for patch in got or ():
            patch.lift, patch.held = lift, held
            out.append(patch)
    return out


def _extent(mesh, rows):
    """The largest extent along x, y or z of the triangle ``rows``."""
    return float(np.ptp(mesh.vertices[mesh.triangles[rows].ravel()], axis=0).max())


def mark_free(charted, splits):
    """``patch.free`` of every charted patch: its boundary edges whose two sides do not
    lift alike (``splits.move.agree``, asked once per seam edge, which two patches share)."""
    if not charted:
        return
    ends = [np.sort(p.ids[p.edges], axis=1) for p in charted]
    if splits.move is None:
        free = np.ones(sum(map(len, ends)), bool)
    else:
        seams, inverse = unique_pairs(np.concatenate(ends), return_inverse=True)
        free = ~splits.move.agree(seams[:, 0], seams[:, 1])[inverse]
    for patch, part in zip(charted, np.split(free, np.cumsum(list(map(len, ends)))[:-1])):
        patch.free = part


def mark_slopes(charted, mesh):
    """``patch.slope`` of every charted patch on a circular body (``patch.lift.bodies``; a
    wing's thin sections crossed each other so): per boundary edge, tan of a quarter of the
    wedge of air between the patch's assembled triangle on it and the other surface's
    (:func:`juncture.surface.patches.taper`), at least 1 / :data:`TAPER`. Two surfaces
    lifted towards each other from a seam then each take at most half of the wedge between
    them: a canard meeting the fuselage at 90 deg lets the fuselage's points rise onto its
    circle within 2.4 times the lift of the seam, where 1 / TAPER kept points 10 times their
    lift away from it short of it (by a tenth of the radius where a block's facets span a
    quarter of its circle).

    ``patch.valley`` of every other lifted patch (a wing's) with such edges (else None): per
    boundary edge, where two surfaces meet in a valley (:func:`_valleys`) whose wedge of air
    is so narrow that a quarter of it rises less than 1 / TAPER (under 22.8 deg), tan of
    that quarter (at least 1 / (TAPER :data:`NARROWEST`)), else inf: a lift out of the
    patch's solid there, towards the other surface, rises no steeper (a low wing's upper
    surface passing just under a narrowing tail cone met the fuselage's block at 2.9 deg:
    lifted up at 1 / TAPER, its fan facets crossed the block); one into it, away from the
    other surface, as before. A body keeps its slopes (its lift is most of the volume; the
    held retry mends where it alone crosses)."""
    lifted = [p for p in charted if p.lift is not None]
    if not lifted:
        return
    from .chart import edge_sides, patch_edges

    t = np.asarray(mesh.triangles)
    _, und, uses, inverse = patch_edges(t)
    a, b = edge_sides(uses, inverse)
    p = mesh.vertices[t]
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-300)
    cos = np.clip(np.einsum("ij,ij->i", normal[a], normal[b]), -1.0, 1.0)
    rise = np.tan((np.pi - np.arccos(cos)) / 4.0)
    steep = np.where(uses == 2, np.clip(rise, 1.0 / TAPER, 1e3), 1.0 / TAPER)
    narrow = (uses == 2) & (rise < 1.0 / TAPER) & _valleys(mesh, und, a, b, normal)
    valley = np.where(narrow, np.maximum(rise, 1.0 / (TAPER * NARROWEST)), np.inf)
    for patch in lifted:        # its boundary edges among the mesh's (all of them there)
        body = patch.component in getattr(patch.lift, "bodies", ())
        if not body and not narrow.any():
            continue
        ends = np.sort(patch.ids[patch.edges], axis=1)
        _, at = unique_pairs(np.concatenate([und, ends]), return_inverse=True)
        at = at[len(und):]
        if body:
            patch.slope = steep[at]
        elif np.isfinite(valley[at]).any():
            patch.valley = valley[at]


#: The slope a lift out of its patch's solid may rise at from a seam in the narrowest
#: valleys is at least 1 / (TAPER NARROWEST) (:func:`mark_slopes`).
NARROWEST = 100.0


def _valleys(mesh, und, a, b, normal):
    """(e,) bool over the unique edges ``und`` (triangle rows ``a``, ``b`` on each side,
    ``normal`` per triangle): the second triangle's third corner lies on the outer side of
    the first's plane (the surface folds outwards there: the wedge of air between them is
    pi less the angle between their normals, where at a ridge it is pi more)."""
    t = np.asarray(mesh.triangles)[b]
    third = np.argmax((t != und[:, :1]) & (t != und[:, 1:]), axis=1)
    corner = mesh.vertices[t[np.arange(len(t)), third]]
    return np.einsum("ij,ij->i", normal[a], corner - mesh.vertices[und[:, 0]]) > 0.0
