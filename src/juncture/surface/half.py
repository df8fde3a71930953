"""A half model: the y >= 0 half of a closed surface that is its own mirror image in y = 0,
closed by its section in that plane, tagged as the symmetry plane.

CFD codes run a symmetric airplane at zero sideslip on half the cells: the surface of one
half, with the plane of symmetry as a boundary of its own (SU2's ``MARKER_SYM``, a Cart3D
component, a Gmsh physical group). :func:`half_model` takes the closed surface of
:func:`juncture.mesh` (both halves, every vertex matched with its mirror image) and keeps:

- every triangle on the y >= 0 side as it is (the mesh's own vertices and seams);
- the y >= 0 part of each surface that straddles the plane (a blunt base's cap, a centre-line
  fin's tip cap): a planar one is triangulated again in its plane, its rim the old rim on
  that side and the chord along y = 0 (constrained Delaunay, PythonCDT, with points put
  inside where a triangle is thinner than ``min_angle``; none on the rim), any other one has
  its triangles cut at y = 0 (the same point on an edge for both triangles at it);
- the section in y = 0, bounded by the half's rim there, triangulated the same way in (x,
  z): the component :data:`SYMMETRY`, facing -y.

Refused (:class:`~juncture.errors.GeometryError`, naming the component): an airplane that
is not symmetric (a centre-line fin of cambered or unsymmetric section: a half model would
misstate it; :func:`symmetric`), a rim left off the plane. The result passes
:func:`juncture.surface.check.check_mesh` or is refused the same way. Its volume is half the
whole surface's, the symmetry plane adding none (its points have y = 0).
"""

from __future__ import annotations

import numpy as np

__all__ = ["SYMMETRY", "half_model", "symmetric"]

#: The component (and surface) name of the section in the plane of symmetry.
SYMMETRY = "symmetry"
#: A straddling surface whose points lie this close to one plane (share of the size) is
#: triangulated again in that plane.
PLANAR = 1e-9
#: Below this smallest angle [deg] a re-triangulated region takes points one at a time in
#: its worst triangle while that helps (:func:`juncture.surface.strip_fill._polished`).
POLISH = 10.0
#: Rounds of points put inside a re-triangulated region (each round puts the circumcentres
#: of the triangles thinner than the angle asked for, Ruppert's, where they split no rim).
ROUNDS = 12


def half_model(surface, min_angle=25.0, configuration=None):
    """The y >= 0 half of the closed ``surface`` (a
    :class:`~juncture.surface.assemble.SurfaceMesh`) of a symmetric airplane, closed by its
    section in y = 0 (the component and surface :data:`SYMMETRY`); see the module. The
    airplane is symmetric where ``configuration`` says so (:func:`symmetric`), or without
    one where every vertex has its mirror image in the mesh."""
    from ..errors import GeometryError
    from .assemble import SurfaceMesh

    v, t = surface.vertices, surface.triangles
    y = v[t][:, :, 1]
    pos, neg = (y > 0).any(axis=1), (y < 0).any(axis=1)
    straddle = np.unique(surface.surface[pos & neg])
    if configuration is None:
        _mirrored(surface, straddle)
    else:
        symmetric(configuration)
    size = float(np.ptp(v, axis=0).max())
    keep = pos & ~neg & ~np.isin(surface.surface, straddle)
    crossed, at = _crossings(v, t[pos & neg])
    pts, tris, comp, surf = [v, crossed], [t[keep]], [surface.component[keep]], \
        [surface.surface[keep]]
    for s in straddle:
        mine = surface.surface == s
        new, tri = _half_of(v, t[mine], at, len(v) + sum(map(len, pts[1:])), size,
                            min_angle)
        pts.append(new)
        tris.append(tri)
        comp.append(np.full(len(tri), surface.component[mine][0]))
        surf.append(np.full(len(tri), s))
    vertices = np.concatenate(pts)
    half = np.concatenate(tris)
    new, cap = _symmetry_cap(vertices, half, len(vertices), min_angle)
    if cap is None:
        raise GeometryError("no half model: the half surface's rim does not lie in the "
                            "plane of symmetry y = 0 (the airplane is not its own mirror "
                            "image there)", component=SYMMETRY)
    n_comp, n_surf = len(surface.components), len(surface.surfaces)
    out = SurfaceMesh(np.concatenate([vertices, new]), np.concatenate([half, cap]),
                      np.concatenate(comp + [np.full(len(cap), n_comp)]),
                      np.concatenate(surf + [np.full(len(cap), n_surf)]),
                      tuple(surface.components) + (SYMMETRY,),
                      tuple(surface.surfaces) + (SYMMETRY,))
    return _compact(out)


def symmetric(configuration):
    """Refuse (:class:`~juncture.errors.GeometryError`, naming it) a component that is not
    its own mirror image in y = 0 and has no image there: a centre-line fin whose section is
    cambered or unsymmetric or that leaves the plane, a body off the plane without an image,
    or a configuration not described as symmetric."""
    from ..errors import GeometryError
    from ..model import CircularBody, WingLike

    if not configuration.symmetric:
        raise GeometryError("no half model: the configuration is not described as symmetric "
                            "about y = 0, so mesh both halves", component=SYMMETRY)
    for comp in configuration:
        if comp.mirrored:
            continue
        if isinstance(comp, WingLike):
            lower = comp.upper if comp.lower is None else comp.lower
            flat = comp.camber is None or not np.any(comp.camber)
            if comp.span_axis == 2 and not np.any(comp.le[:, 1]) and flat and \
                    np.array_equal(comp.upper, lower):
                continue
            why = "its sections are cambered or unsymmetric, or it leaves the plane"
        elif isinstance(comp, CircularBody) and comp.origin[1] != 0.0:
            why = "it lies off the plane with no image"
        else:
            continue
        raise GeometryError(f"no half model: {comp.name} is not its own mirror image in "
                            f"y = 0 ({why}), so mesh both halves", component=comp.name)


def _mirrored(surface, straddle):
    """Refuse a surface with a vertex that has no mirror image in y = 0, bit for bit (but
    the points inside a planar surface that straddles the plane: a blunt base's cap is
    triangulated on its own, and its half is triangulated again)."""
    from ..errors import GeometryError
    from .assemble import _plane, boundary_loops

    v, t = surface.vertices, surface.triangles
    size = float(np.ptp(v, axis=0).max())
    used = np.zeros(len(v), bool)
    used[t.ravel()] = True
    for s in straddle:
        tri = t[surface.surface == s]
        if _plane(v[np.unique(tri)])[3] <= PLANAR * size:
            inner = np.setdiff1d(np.unique(tri), np.concatenate(boundary_loops(tri)))
            used[inner] = False
    used[t[~np.isin(surface.surface, straddle)].ravel()] = True
    ids = np.flatnonzero(used)
    own = v[ids] + 0.0                      # -0.0 and 0.0 alike
    image = own * [1.0, -1.0, 1.0] + 0.0
    _, inv = np.unique(np.concatenate([own, image]), axis=0, return_inverse=True)
    inv = inv.ravel()
    lone = ids[~np.isin(inv[len(ids):], inv[:len(ids)])]
    if not len(lone):
        return
    rows = np.isin(t, lone).any(axis=1)
    names = sorted({surface.surfaces[s] for s in np.unique(surface.surface[rows])})
    p = np.round(v[lone[0]], 6).tolist()
    raise GeometryError(
        f"no half model: {len(lone)} points of {', '.join(names)} have no mirror image in "
        f"y = 0 (e.g. at {p}); the airplane is not symmetric (a centre-line fin or pod of "
        "unsymmetric section?), so mesh both halves", component=names[0])


def _half_of(v, tri, at, first, size, min_angle):
    """(new points, triangles in global ids, new ones from ``first``) of the y >= 0 part of
    one straddling surface ``tri``: triangulated again in its plane where it is planar and
    its rim meets y = 0 at vertices only, else its triangles cut at y = 0 (``at``: the
    points where edges cross the plane, :func:`_crossings`)."""
    from .assemble import _plane, boundary_loops

    loops = boundary_loops(tri)
    centre, normal, axes, dist = _plane(v[np.unique(tri)])
    if dist <= PLANAR * size and len(loops) == 1:
        got = _planar_half(v, tri, loops[0], centre, normal, axes, first, min_angle)
        if got is not None:
            return got
    return np.zeros((0, 3)), _clipped(v, tri, at)


def _crossings(v, tri):
    """(points, {(a, b): id}) where the edges of the triangles ``tri`` cross y = 0 (a < b;
    ids from ``len(v)``), y = 0 exactly: one point per edge, whichever surface cuts it."""
    e = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    e = np.unique(e[v[e[:, 0], 1] * v[e[:, 1], 1] < 0], axis=0)
    a, b = v[e[:, 0]], v[e[:, 1]]
    p = a + (b - a) * (a[:, 1] / (a[:, 1] - b[:, 1]))[:, None]
    p[:, 1] = 0.0
    return p, dict(zip(map(tuple, e.tolist()), range(len(v), len(v) + len(e))))


def _planar_half(v, tri, loop, centre, normal, axes, first, min_angle):
    """The planar surface's y >= 0 part triangulated again (see :func:`_half_of`), or None
    where its rim crosses y = 0 between vertices or leaves the y > 0 side more than once."""
    y = v[loop, 1]
    if np.any(y * np.roll(y, -1) < 0):
        return None
    chain = _kept_chain(loop, y)
    if chain is None:
        return None
    rim = v[chain]
    step = np.linalg.norm(np.diff(rim, axis=0), axis=1)
    h = float(np.median(step))
    span = float(np.linalg.norm(rim[0] - rim[-1]))
    along = rim[-1] + _spacing(span, step[-1], step[0], h)[:, None] * (rim[0] - rim[-1])
    along[:, 1] = 0.0
    inner = np.setdiff1d(np.unique(tri), loop)
    inner = inner[v[inner, 1] > 0.5 * h]
    fixed = np.concatenate([rim, along, v[inner]])
    uv = (fixed - centre) @ axes.T
    n_rim = len(chain) + len(along)
    cons = np.stack([np.arange(n_rim), np.roll(np.arange(n_rim), -1)], axis=1)
    got = _filled(uv, cons, min_angle)
    if got is None:
        return None
    uv_all, local = got
    extra = centre + uv_all[len(fixed):] @ axes
    xyz = np.concatenate([fixed, extra])
    local = _facing(xyz, local, normal * _side(v, tri, normal))
    glob = np.concatenate([chain, first + np.arange(len(along)), inner,
                           first + len(along) + np.arange(len(extra))])
    return np.concatenate([along, extra]), glob[local]


def _spacing(span, first, last, h):
    """(k,) fractions strictly between 0 and 1 of points on a segment of length ``span``:
    the first piece about ``first`` long, the last about ``last`` (the rim's pieces that meet
    the segment's ends, so the triangle in each corner has two sides alike: a thin
    section's trailing edge meets y = 0 at a few degrees, and a point on y = 0 nearer the
    corner than the rim's next point made a sliver), turning towards ``h`` by half the
    distance from the nearer end."""
    def size(u):                             # a thousandth of the span at least
        end, d = (first, u) if u <= 0.5 * span else (last, max(span - u, 0.0))
        return max(end + float(np.clip(h - end, -0.5 * d, 0.5 * d)), 1e-3 * span)

    out = [size(0.0)]
    while out[-1] + size(out[-1]) < span:
        out.append(out[-1] + size(out[-1]))
    out = np.asarray(out)
    if out[-1] >= span:                      # one piece: no point between
        return np.zeros(0)
    step = size(out[-1])
    if span - out[-1] >= 0.5 * step:         # the last gap is a piece as it is
        return out / span
    # else stretched to the far end: the last gap scaled to a whole piece, or the last
    # point left out and the rest spread, whichever stretches less
    shrink = span / (out[-1] + step)
    spread = span / out[-1]
    if spread - 1.0 < 1.0 / shrink - 1.0:
        return out[:-1] * spread / span
    return out * shrink / span


def _kept_chain(loop, y):
    """The loop's one run of vertices with y > 0 with a vertex on y = 0 at each end, or
    None where there is not exactly one such run."""
    side = y > 0
    starts = np.flatnonzero(~side & np.roll(side, -1))
    if len(starts) != 1:
        return None
    loop, y, side = (np.roll(a, -starts[0]) for a in (loop, y, side))
    stop = 1 + int(np.flatnonzero(~side[1:])[0])
    if y[0] != 0 or y[stop] != 0:
        return None
    return loop[:stop + 1]


def _side(v, tri, normal):
    """+1 where the surface's triangles face along ``normal``, else -1."""
    p = v[tri]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]).sum(axis=0)
    return 1.0 if float(n @ normal) > 0 else -1.0


def _facing(xyz, local, direction):
    """Triangles ``local`` turned to face along ``direction``."""
    p = xyz[local]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    flip = n @ direction < 0
    local = local.copy()
    local[flip] = local[flip][:, [0, 2, 1]]
    return local


def _clipped(v, tri, at):
    """Triangles of the y >= 0 parts of the triangles ``tri`` cut at y = 0 (``at``: the
    points where their edges cross it, :func:`_crossings`)."""
    y = v[tri][:, :, 1]
    out = [tri[(y >= 0).all(axis=1) & (y > 0).any(axis=1)]]
    for corners in tri[(y > 0).any(axis=1) & (y < 0).any(axis=1)].tolist():  # a few
        ring = []
        for k in range(3):
            a, b = corners[k], corners[(k + 1) % 3]
            if v[a, 1] >= 0:
                ring.append(a)
            if v[a, 1] * v[b, 1] < 0:
                ring.append(at[(min(a, b), max(a, b))])
        out.append(np.array([[ring[0], ring[i], ring[i + 1]]
                             for i in range(1, len(ring) - 1)], np.int64).reshape(-1, 3))
    return np.concatenate(out)


def _symmetry_cap(vertices, half, first, min_angle):
    """(new points, triangles facing -y) of the section in y = 0 bounded by the half
    surface's rim, or (None, None) when the rim leaves the plane."""
    e = np.concatenate([half[:, [0, 1]], half[:, [1, 2]], half[:, [2, 0]]])
    n = len(vertices)
    rim = e[~np.isin(e[:, 0] * n + e[:, 1], e[:, 1] * n + e[:, 0])]
    if not len(rim):
        return np.zeros((0, 3)), np.zeros((0, 3), np.int64)
    if np.any(vertices[rim.ravel(), 1] != 0):
        return np.zeros((0, 3)), None
    ids, where = np.unique(rim, return_inverse=True)
    uv = vertices[ids][:, [0, 2]]
    cons = where.reshape(-1, 2)
    got = _filled(uv, cons, min_angle)
    if got is None:
        return np.zeros((0, 3)), None
    uv_all, local = got
    extra = np.stack([uv_all[len(ids):, 0], np.zeros(len(uv_all) - len(ids)),
                      uv_all[len(ids):, 1]], axis=1)
    xyz = np.concatenate([vertices[ids], extra])
    local = _facing(xyz, local, np.array([0.0, -1.0, 0.0]))
    glob = np.concatenate([ids, first + np.arange(len(extra))])
    return extra, glob[local]


def _filled(uv, cons, min_angle):
    """(points (the given ones first), triangles) of the constrained Delaunay triangulation
    inside the pieces ``cons`` with points put inside for ``min_angle``
    (:func:`juncture.surface.outside.interior_points`, no rim piece split), or None where
    PythonCDT refuses it."""
    from .outside import interior_points
    from .quality import triangle_angles
    from .strip_fill import _cdt, _polished

    cons = np.asarray(cons, np.uint32)
    piece = np.linalg.norm(uv[cons[:, 0]] - uv[cons[:, 1]], axis=1)
    shortest = 0.05 * float(piece.min())
    pts = uv
    local = _cdt(pts, cons)
    for _ in range(ROUNDS if local is not None else 0):
        more = interior_points(pts, local, cons, min_angle, shortest)
        if not len(more):
            break
        again = _cdt(np.concatenate([pts, more]), cons)
        if again is None:
            break
        pts, local = np.concatenate([pts, more]), again
    if local is None:
        return None
    if triangle_angles(pts, local).min() < POLISH:        # where Ruppert's points cannot go
        got = _polished(uv, cons, pts[len(uv):], loop=False)
        if got is not None:
            pts, local = np.concatenate([uv, got[0]]), got[1]
    return pts, local


def _compact(mesh):
    """The mesh with the vertices no triangle uses left out."""
    from .assemble import SurfaceMesh

    used = np.unique(mesh.triangles)
    remap = np.full(len(mesh.vertices), -1, np.int64)
    remap[used] = np.arange(len(used))
    return SurfaceMesh(mesh.vertices[used], remap[mesh.triangles], mesh.component,
                       mesh.surface, mesh.components, mesh.surfaces)
