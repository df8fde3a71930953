"""Inner vertices beside a followed seam, moved off it.

:func:`juncture.surface.seam_curves.follow_curves` splits a seam edge onto the exact curve
and fans the triangle beside it from its far corner. Where that corner is a grid point
just beside the curve (a body's network point next to a wing's footprint) and the curve
bulges past it, the fan would turn over. Such a corner, when it is a free vertex (inside
one surface of one component, on no intersection, corner or split line, all its edges in
two triangles) on the curve's host (a grid point of the wing beside the curve stays:
taken onto the fuselage it would leave the wing), is moved to the point that sees the
whole polygon around it farthest inside (the Chebyshev centre of the polygon's kernel, a
linear programme, in the plane of its triangles), taken onto the host's exact surface in
its station's plane (Newton steps on the host's error function), where then none of its
triangles turns over against the triangle it came from; its mirror image in y = 0 moves
to the mirror image, bit for bit. Where the polygon has no kernel (a thin wedge between
the curve and the grid) the edge keeps its chord, as before.

Tried and dropped (held-out seeds 8181 and 8282): taking the corner out and triangulating
the polygon around it again. Constrained Delaunay left triangles of three nearly
collinear curve points, which the re-triangulation refined into clusters of slivers (48
under 5 deg at one tail root, 146 more in two meshes); a strip with a corner on the curve
and one off it in every triangle (dynamic programming over the two polylines) had flat
triangles where the wedge closes (168 slivers in one mesh). Moving the corner to a share
of the way to its other neighbours' middle left one triangle turned in most cases.
"""

from __future__ import annotations

import numpy as np

__all__ = ["free_vertices", "relocate", "normals"]

#: Newton steps that take a moved corner onto the host.
STEPS = 8


def normals(xyz, tri):
    """(k, 3) the triangles' (unnormalised) normals."""
    return np.cross(xyz[tri[:, 1]] - xyz[tri[:, 0]], xyz[tri[:, 2]] - xyz[tri[:, 0]])


def free_vertices(mesh, fixed=None):
    """(n,) bool: the vertices of ``mesh`` that may move: not ``fixed``, every edge at them
    in two triangles, all their triangles of one surface and one component."""
    from .chart import patch_edges

    tri = np.asarray(mesh.triangles)
    n = len(mesh.vertices)
    free = np.ones(n, bool) if fixed is None else ~np.asarray(fixed, bool)
    _, und, uses, _ = patch_edges(tri)
    free[und[uses != 2].ravel()] = False
    for tag in (mesh.surface, mesh.component):
        pairs = np.unique(np.stack([tri.ravel(), np.repeat(tag, 3)], axis=1), axis=0)
        free[np.bincount(pairs[:, 0], minlength=n) > 1] = False
    return free


def relocate(xyz, tri, ref, free, first_new, host):
    """``xyz`` with every free corner of a turned triangle of ``tri`` (its normal against
    ``ref``, the normal of the triangle it came from) that is an old vertex (id below
    ``first_new``) moved (module docstring). ``host(q, p)``: (error function, mirror flip)
    of the host on whose curve the new point ``p`` lies, None where the corner's point
    ``q`` does not lie on that host's surface (it stays)."""
    xyz = np.array(xyz, float)
    turned = np.einsum("ij,ij->i", normals(xyz, tri), ref) <= 0.0
    cand = np.unique(tri[turned])
    cand = cand[cand < first_new]
    cand = cand[free[cand]]
    if not len(cand):
        return xyz
    from .mirror import FLIP, mirror_map

    mirror = mirror_map(xyz)
    size = float(np.ptp(xyz, axis=0).max())
    for c in cand.tolist():
        m = int(mirror[c])
        if m == c or (m >= 0 and xyz[c, 1] < 0.0):
            continue                           # on the plane, or its image's turn
        got = _moved(xyz, tri, ref, c, first_new, host, size)
        if got is None:
            continue
        both = [c] if m < 0 else [c, m]
        before = xyz[both].copy()
        xyz[c] = got
        if m >= 0:
            xyz[m] = got * FLIP + 0.0
        rows = np.flatnonzero(np.isin(tri, both).any(axis=1))
        if np.any(np.einsum("ij,ij->i", normals(xyz, tri[rows]), ref[rows]) <= 0.0):
            xyz[both] = before                 # the image would turn: neither moves
    return xyz


def _moved(xyz, tri, ref, c, first_new, host, size):
    """Where corner ``c`` goes, or None: the centre of the largest circle inside the kernel
    of the polygon around it (the points from which the whole polygon is seen,
    :func:`_kernel_centre`) in the plane of its triangles' original normals ``ref``, taken
    onto the host (``host``, by the new point nearest ``c``; Newton to 1e-13 of ``size``);
    None where ``c`` is not on that host, the kernel is empty or a triangle still turns
    over."""
    from .plane import frame

    rows = np.flatnonzero(np.any(tri == c, axis=1))
    near = np.unique(tri[rows])
    new = near[near >= first_new]
    loop = _loop(tri[rows], c)
    if not len(new) or loop is None:
        return None
    n = ref[rows].sum(axis=0)
    n /= np.linalg.norm(n)
    axes = frame(n)
    origin = xyz[loop].mean(axis=0)
    centre = _kernel_centre((xyz[loop] - origin) @ axes.T)
    if centre is None:
        return None
    p = new[np.argmin(np.linalg.norm(xyz[new] - xyz[c], axis=1))]
    got = host(xyz[c], int(p))
    if got is None:
        return None
    error, flip = got
    q = _onto(error, flip, origin + centre @ axes, size)
    if q is None:
        return None
    trial = xyz.copy()
    trial[c] = q
    if np.any(np.einsum("ij,ij->i", normals(trial, tri[rows]), ref[rows]) <= 0.0):
        return None
    return q


def _loop(star, c):
    """(k,) the polygon around ``c``: the far edges of its triangles ``star`` in order,
    counter-clockwise as they are; None where they are not one closed loop."""
    at = np.argmax(star == c, axis=1)
    k = np.arange(len(star))
    nxt = dict(zip(star[k, (at + 1) % 3].tolist(), star[k, (at + 2) % 3].tolist()))
    if len(nxt) != len(star):
        return None
    loop = [next(iter(nxt))]
    while len(loop) <= len(star):
        loop.append(nxt.get(loop[-1], -1))
        if loop[-1] == loop[0]:
            break
    if len(loop) != len(star) + 1 or loop[-1] != loop[0]:
        return None
    return np.array(loop[:-1])


def _kernel_centre(uv):
    """(2,) the point of the counter-clockwise polygon ``uv`` (k, 2) farthest inside the
    half-planes left of all its edges (a linear programme: the Chebyshev centre of its
    kernel), or None where no point is inside them all."""
    from scipy.optimize import linprog

    d = np.roll(uv, -1, axis=0) - uv
    length = np.linalg.norm(d, axis=1)
    keep = length > 0
    d, a, length = d[keep], uv[keep], length[keep]
    inward = np.column_stack([-d[:, 1], d[:, 0]]) / length[:, None]
    # inward . x - inward . a >= t  ->  -inward . x + t <= -inward . a
    a_ub = np.column_stack([-inward, np.ones(len(d))])
    b_ub = -np.einsum("ij,ij->i", inward, a)
    got = linprog([0.0, 0.0, -1.0], A_ub=a_ub, b_ub=b_ub,
                  bounds=[(None, None), (None, None), (0.0, None)], method="highs")
    if not got.success or got.x[2] <= 0.0:
        return None
    return got.x[:2]


def _onto(error, flip, p, size):
    """``p`` taken onto the surface of ``error`` (evaluated at points times ``flip``) in its
    plane x = const, to 1e-13 of ``size``; None where Newton's steps do not settle."""
    h = 1e-7 * size
    q = np.array(p, float)
    for _ in range(STEPS):
        e = float(error((q * flip)[None])[0])
        if abs(e) <= 1e-13 * size:
            return q
        steps = q + np.array([[0, h, 0], [0, -h, 0], [0, 0, h], [0, 0, -h]])
        d = error(steps * flip)
        grad = np.array([0.0, d[0] - d[1], d[2] - d[3]]) / (2 * h)
        norm = grad @ grad
        if not np.isfinite(norm) or norm == 0.0:
            return None
        q = q - e * grad / norm
    return None
