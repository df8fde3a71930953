"""Areas of plane cuts through closed surface networks, projected onto the x-normal plane.

The solid is bounded by closed, outward-oriented networks (architecture.md, common.md:
``normal = cross(P[i, j+1] - P[i, j], P[i+1, j] - P[i, j])`` points out of the solid). Each quad
``P[i, j], P[i, j+1], P[i+1, j+1], P[i+1, j]`` becomes the triangles
``(P[i,j], P[i,j+1], P[i+1,j])`` and ``(P[i,j+1], P[i+1,j+1], P[i+1,j])``, both with the
quad's orientation. A plane ``n . p = c`` cuts each triangle it crosses in one segment; the
segments of all triangles form the closed boundary curves of the cross-section.

**Why no chaining is needed.** Classify the vertices by ``d = n . p - c >= 0`` ("ahead"; a
vertex on the plane counts as ahead: a symbolic perturbation, so a shared edge is cut at the
same point by both of its triangles and every curve closes). Walking the triangle's vertices in
their outward order, the segment runs from the crossing of the edge going from ``d >= 0`` to
``d < 0`` to the crossing of the edge going back. That direction is ``n x N`` (``N`` the outward
normal), i.e. counter-clockwise about ``n`` with the solid on its left, so outer boundaries run
counter-clockwise and holes (a duct) clockwise, and each closed curve ``C`` gives its *vector
area* ``(1/2) oint_C r x dr = A n / |n|``. Its x-component,

    (1/2) oint (y dz - z dy) = (1/2) sum_segments (y1 z2 - y2 z1),

is the area projected onto the y-z plane, ``A |n_x| / |n|`` (sign fixed so that it is >= 0).
Because a vertex on the plane counts as on the ``+n`` side, the cut is in effect taken at
``c - 0`` (an infinitesimal step towards ``-n``, i.e. forward for x = const): a flat nose face
lying in the plane gives 0, a flat base face gives the base area.
Disjoint components simply add, holes subtract. The sum is taken about the mean (y, z) of the
vertices, which changes nothing for closed curves and limits the error of small gaps between
networks that do not quite meet.

The work is vectorised: per plane family the vertex heights ``n . p`` are computed once; with
the offsets sorted, each triangle straddles a contiguous run of planes found by two binary
searches on its height range, the (triangle, plane) pairs are expanded with ``np.repeat``, and
only those pairs are intersected, in chunks of a bounded number of pairs.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ..errors import GeometryError, JunctureError

__all__ = ["plane_cut_areas", "normal_areas", "mach_plane_areas", "mach_plane_extents",
           "triangulate"]

#: (triangle, plane) pairs intersected at once (bounds the temporary memory to ~100 MB).
_CHUNK = 500_000


def _network_list(networks):
    """Networks as a list of (n_lines, n_points, 3) arrays, with mirror images for a Geometry."""
    if hasattr(networks, "mirrored_networks"):
        items = list(networks.mirrored_networks().items())
    elif isinstance(networks, Mapping):
        items = list(networks.items())
    elif isinstance(networks, np.ndarray) and networks.ndim == 3:
        items = [("network", networks)]
    else:
        items = [(f"network {k + 1}", v) for k, v in enumerate(networks)]
    out = []
    for name, net in items:
        arr = np.asarray(net, dtype=float)
        if arr.ndim != 3 or arr.shape[2] != 3:
            raise GeometryError(f"a network must have shape (n_lines, n_points, 3), found "
                                f"{arr.shape}", component=str(name))
        if not np.all(np.isfinite(arr)):
            raise GeometryError("non-finite coordinate", component=str(name))
        out.append(arr)
    if not out:
        raise GeometryError("no networks to cut")
    return out


def triangulate(networks):
    """Triangles of closed networks, each ordered so that its normal points outward.

    Parameters
    ----------
    networks : Geometry, mapping of str to array, or sequence of (n_lines, n_points, 3) float
        Surface networks (a Geometry contributes its mirror images too).

    Returns
    -------
    (n_triangles, 3, 3) float
        Vertices; ``cross(v1 - v0, v2 - v0)`` points out of the solid. Triangles of zero area
        (collapsed quads at a pole or a pointed tip) are left out.
    """
    tris = []
    for p in _network_list(networks):
        if p.shape[0] < 2 or p.shape[1] < 2:
            continue
        p00, p01 = p[:-1, :-1], p[:-1, 1:]
        p10, p11 = p[1:, :-1], p[1:, 1:]
        t1 = np.stack([p00, p01, p10], axis=-2).reshape(-1, 3, 3)
        t2 = np.stack([p01, p11, p10], axis=-2).reshape(-1, 3, 3)
        tris.extend([t1, t2])
    if not tris:
        return np.zeros((0, 3, 3))
    t = np.concatenate(tris)
    cr = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    scale = np.max(np.abs(t)) if t.size else 1.0
    keep = np.einsum("ij,ij->i", cr, cr) > (1e-14 * scale * scale) ** 2
    return t[keep]


def _straddling_pairs(dmin, dmax, c_sorted):
    """Per triangle, the range [lo, hi) of sorted offsets with dmin < c <= dmax."""
    lo = np.searchsorted(c_sorted, dmin, side="right")
    hi = np.searchsorted(c_sorted, dmax, side="right")
    return lo, hi - lo


def _segment_areas(d_tri, y_tri, z_tri, c):
    """(1/2)(y1 z2 - y2 z1) of the cut segment of each (triangle, plane) pair.

    ``d_tri``, ``y_tri``, ``z_tri`` (3, k): vertex heights and coordinates; ``c`` (k,) offsets.
    The three edges are handled one after the other (a loop of 3, over whole arrays: numpy
    reductions along a length-3 axis are slow).
    """
    h = [d_tri[v] - c for v in range(3)]
    ahead = [hv >= 0.0 for hv in h]
    y1 = np.zeros(c.size)
    z1, y2, z2 = y1.copy(), y1.copy(), y1.copy()
    for a in range(3):
        b = (a + 1) % 3  # edge a -> b in the outward vertex order
        down = ahead[a] & ~ahead[b]  # ahead -> behind: the segment starts here
        up = ~ahead[a] & ahead[b]  # behind -> ahead: the segment ends here
        cross = down | up
        frac = np.where(cross, h[a] / np.where(cross, h[a] - h[b], 1.0), 0.0)
        yc = y_tri[a] + frac * (y_tri[b] - y_tri[a])
        zc = z_tri[a] + frac * (z_tri[b] - z_tri[a])
        y1 += np.where(down, yc, 0.0)
        z1 += np.where(down, zc, 0.0)
        y2 += np.where(up, yc, 0.0)
        z2 += np.where(up, zc, 0.0)
    return 0.5 * (y1 * z2 - y2 * z1)


class _Mesh:
    """Triangles as three (3, n) arrays x, y, z (vertex k of every triangle contiguous), so
    that the vertex heights of a plane family are three whole-array operations; ``yz0`` is
    the point about which the areas are summed (the mean vertex of the first mesh)."""

    __slots__ = ("x", "y", "z", "yz0")

    def __init__(self, tri, yz0=None):
        self.x, self.y, self.z = (np.ascontiguousarray(tri[:, :, k].T) for k in range(3))
        self.yz0 = (np.array([self.y.mean(), self.z.mean()]) if yz0 is None
                    else np.asarray(yz0, float))

    def heights(self, normal):
        """(3, n) ``normal . p`` of every vertex."""
        return normal[0] * self.x + normal[1] * self.y + normal[2] * self.z

    def cut(self, d, offsets):
        """Signed projected areas of the planes ``d = offsets`` (``d`` from :meth:`heights`)."""
        order = np.argsort(offsets, kind="stable")
        c_sorted = offsets[order]
        dmin = np.minimum(np.minimum(d[0], d[1]), d[2])
        dmax = np.maximum(np.maximum(d[0], d[1]), d[2])
        lo, count = _straddling_pairs(dmin, dmax, c_sorted)
        sel = np.flatnonzero(count)
        acc = np.zeros(offsets.size)
        if sel.size == 0:
            return acc
        lo, count = lo[sel], count[sel]
        ends = np.cumsum(count)
        # chunks of triangles holding about _CHUNK (triangle, plane) pairs each
        bounds = np.searchsorted(ends, np.arange(_CHUNK, ends[-1], _CHUNK), side="left")
        for ta, tb in zip(np.r_[0, bounds], np.r_[bounds, sel.size], strict=True):
            if tb <= ta:
                continue
            cnt = count[ta:tb]
            first = np.cumsum(cnt) - cnt
            it = np.repeat(np.arange(ta, tb), cnt)  # index into sel
            ip = lo[it] + (np.arange(it.size) - np.repeat(first, cnt))  # sorted plane index
            t_idx = sel[it]
            seg = _segment_areas(d[:, t_idx], self.y[:, t_idx] - self.yz0[0],
                                 self.z[:, t_idx] - self.yz0[1], c_sorted[ip])
            acc += np.bincount(ip, weights=seg, minlength=offsets.size)
        out = np.empty(offsets.size)
        out[order] = acc
        return out


def _prepare(networks, yz0=None):
    tri = triangulate(networks)
    if tri.shape[0] == 0:
        raise GeometryError("the networks have no triangle of nonzero area")
    return _Mesh(tri, yz0)


def _offsets(values, name):
    arr = np.asarray(values, dtype=float)
    if arr.ndim > 1 or not np.all(np.isfinite(arr)):
        raise JunctureError(f"{name} must be a finite 1-D array, found shape {arr.shape}")
    return np.atleast_1d(arr)


def plane_cut_areas(networks, normal, offsets):
    """Areas of the cross-sections by the planes ``normal . p = c``, projected onto y-z.

    Parameters
    ----------
    networks : Geometry, mapping of str to array, or sequence of (n_lines, n_points, 3) float
        Closed, outward-oriented networks bounding one or more disjoint solids (a Geometry is
        cut with its mirror images).
    normal : (3,) float
        Plane normal (any length; the offsets are in units of ``normal . p``).
    offsets : (n_offsets,) float
        ``c`` of each plane.

    Returns
    -------
    (n_offsets,) float
        Cross-section area times ``|n_x| / |n|``, i.e. projected onto the plane x = const
        [deck length^2]. 0 for planes parallel to x.

    Raises
    ------
    GeometryError
        Malformed networks or none with area.
    JunctureError
        A zero or non-finite normal, non-finite offsets.

    Examples
    --------
    A unit cube cut at x = 0.5 and by an oblique plane across its side faces:

    >>> g = np.linspace(0, 1, 3)
    >>> a, b = np.meshgrid(g, g, indexing="ij")
    >>> one, zero = np.ones_like(a), np.zeros_like(a)
    >>> faces = [np.stack([zero, a, b], -1), np.stack([one, b, a], -1),
    ...          np.stack([b, zero, a], -1), np.stack([a, one, b], -1),
    ...          np.stack([a, b, zero], -1), np.stack([b, a, one], -1)]
    >>> plane_cut_areas(faces, [1.0, 0.0, 0.0], [0.5]).round(12).tolist()
    [1.0]
    >>> plane_cut_areas(faces, [1.0, 0.2, 0.3], [0.75]).round(12).tolist()
    [1.0]
    """
    n = np.asarray(normal, dtype=float)
    if n.shape != (3,) or not np.all(np.isfinite(n)) or not np.any(n != 0.0):
        raise JunctureError(f"normal must be a finite nonzero (3,) vector, found {normal!r}")
    c = _offsets(offsets, "offsets")
    mesh = _prepare(networks)
    return np.sign(n[0]) * mesh.cut(mesh.heights(n), c)


def normal_areas(networks, x):
    """Normal cross-sectional areas ``S(x)`` (cuts by the planes x = const).

    Parameters
    ----------
    networks : Geometry, mapping of str to array, or sequence of (n_lines, n_points, 3) float
        Closed, outward-oriented networks.
    x : (n_x,) float
        Stations [deck length].

    Returns
    -------
    (n_x,) float
        Area [deck length^2].
    """
    return plane_cut_areas(networks, [1.0, 0.0, 0.0], x)


def _mach_normals(mach, thetas):
    mach = float(mach)
    if not (np.isfinite(mach) and mach >= 1.0):
        raise JunctureError(f"Mach-plane cuts need a supersonic Mach number >= 1, found {mach}")
    th = _offsets(thetas, "thetas")
    beta = np.sqrt(mach * mach - 1.0)
    return np.column_stack([np.ones_like(th), -beta * np.cos(th), -beta * np.sin(th)])


def mach_plane_areas(networks, mach, thetas, x_offsets):
    """Far-field equivalent-body areas ``S(X, theta)`` cut by Mach planes (Harris TM X-947).

    The planes are ``x - beta (y cos theta + z sin theta) = X``, ``beta = sqrt(M^2 - 1)``:
    tangent to the Mach cone, seen from roll angle ``theta`` (theta = 0 towards +y, pi/2
    towards +z, architecture.md). Each cut is projected onto the x-normal plane.

    Parameters
    ----------
    networks : Geometry, mapping of str to array, or sequence of (n_lines, n_points, 3) float
        Closed, outward-oriented networks of the whole configuration (a Geometry is cut with
        its mirror images: both halves).
    mach : float
        Free-stream Mach number, >= 1 (M = 1 gives the normal areas for every theta).
    thetas : (n_theta,) float
        Roll angles [rad].
    x_offsets : (n_X,) or (n_theta, n_X) float
        Plane offsets ``X``, shared or per angle [deck length].

    Returns
    -------
    (n_theta, n_X) float
        Projected areas [deck length^2].

    Raises
    ------
    JunctureError
        Mach number below 1, offsets of the wrong shape.
    """
    normals = _mach_normals(mach, thetas)
    xo = np.asarray(x_offsets, dtype=float)
    if xo.ndim == 1:
        xo = np.broadcast_to(xo, (normals.shape[0], xo.size))
    if xo.ndim != 2 or xo.shape[0] != normals.shape[0] or not np.all(np.isfinite(xo)):
        raise JunctureError(f"x_offsets must be finite, (n_X,) or (n_theta, n_X) with n_theta = "
                            f"{normals.shape[0]}, found shape {np.shape(x_offsets)}")
    mesh = _prepare(networks)
    return np.stack([mesh.cut(mesh.heights(nk), xk) for nk, xk in zip(normals, xo, strict=True)])


def mach_plane_extents(networks, mach, thetas):
    """Range of ``X = x - beta (y cos theta + z sin theta)`` over the networks, per angle.

    Parameters
    ----------
    networks : Geometry, mapping of str to array, or sequence of (n_lines, n_points, 3) float
        As for :func:`mach_plane_areas`.
    mach : float
        Mach number >= 1.
    thetas : (n_theta,) float
        Roll angles [rad].

    Returns
    -------
    (n_theta, 2) float
        First and last X at which a Mach plane touches the configuration [deck length]: the
        nose and base of each equivalent body, to pass as ``np.linspace(*ext[k], n_X)``.
    """
    normals = _mach_normals(mach, thetas)
    pts = np.concatenate([p.reshape(-1, 3) for p in _network_list(networks)])
    xs = pts @ normals.T  # (n_points, n_theta)
    return np.column_stack([xs.min(axis=0), xs.max(axis=0)])
