"""Exact orientation predicates and triangle-pair intersection tests for mesh checks.

``orient3d(a, b, c, d)`` is the sign of the determinant of ``(a - d, b - d, c - d)``: +1 when
``d`` lies below the plane through ``a, b, c`` seen with ``a, b, c`` counter-clockwise
(Shewchuk's convention), 0 when the four points are coplanar. It is evaluated in floating
point with Shewchuk's static error bound for the rounded differences ((7 + 56 eps) eps times
the permanent) and, only where that bound cannot decide the sign, again in exact rational
arithmetic (the floats, which are dyadic rationals, as integers over one power-of-two
denominator). The sign is
therefore always the exact sign for the given floating-point coordinates. ``orient2d`` is
the same in the plane.

:func:`triangles_intersect` tells, for pairs of triangles that share no vertex, whether they
intersect or touch (a vertex on the other's face counts), with only these predicates: two
non-coplanar triangles meet exactly when an edge of one meets the other triangle, and a
segment meets a triangle when its ends are not strictly on one side of the triangle's plane
and it does not pass strictly beside one of the triangle's edges; coplanar triangles meet
when two edges cross or a vertex lies in the other triangle.
"""

from __future__ import annotations

import numpy as np

__all__ = ["orient3d", "orient2d", "triangles_intersect", "segments_hit_triangles"]

_EPS = 2.0 ** -53
_BOUND3 = (7.0 + 56.0 * _EPS) * _EPS
_BOUND2 = (3.0 + 16.0 * _EPS) * _EPS


def _integers(points):
    """Coordinates (k, n, dim) as Python integers (an object array) over one power-of-two
    denominator per row k (floats are dyadic rationals, so this is exact; a sign computed
    from them is the sign for the floats). Vectorised: the mantissas as int64 and one shift
    per coordinate, in numpy's object loops rather than per-point Python code."""
    mant, expo = np.frexp(points)
    ints = (mant * 2.0 ** 53).astype(np.int64)
    expo = np.where(ints == 0, np.iinfo(np.int32).max, expo.astype(np.int64))
    low = expo.reshape(len(points), -1).min(axis=1)
    low = np.where(low == np.iinfo(np.int32).max, 0, low)
    shift = np.where(ints == 0, 0, expo - low[:, None, None])
    return np.left_shift(ints.astype(object), shift.astype(object))


def _sign(det):
    return (det > 0).astype(np.int64) - (det < 0).astype(np.int64)


def _exact3(a, b, c, d):
    """Exact signs of orient3d for rows of (k, 3) points."""
    p = _integers(np.stack([a, b, c, d], axis=1))
    ad, bd, cd = p[:, 0] - p[:, 3], p[:, 1] - p[:, 3], p[:, 2] - p[:, 3]
    det = (ad[:, 0] * (bd[:, 1] * cd[:, 2] - bd[:, 2] * cd[:, 1])
           + bd[:, 0] * (cd[:, 1] * ad[:, 2] - cd[:, 2] * ad[:, 1])
           + cd[:, 0] * (ad[:, 1] * bd[:, 2] - ad[:, 2] * bd[:, 1]))
    return _sign(det)


def _exact2(a, b, c):
    """Exact signs of orient2d for rows of (k, 2) points."""
    p = _integers(np.stack([a, b, c], axis=1))
    det = ((p[:, 0, 0] - p[:, 2, 0]) * (p[:, 1, 1] - p[:, 2, 1])
           - (p[:, 0, 1] - p[:, 2, 1]) * (p[:, 1, 0] - p[:, 2, 0]))
    return _sign(det)


def orient3d(a, b, c, d):
    """(n,) int signs of the orientation of the point sets (n, 3) each (see the module)."""
    a, b, c, d = (np.asarray(p, float).reshape(-1, 3) for p in (a, b, c, d))
    ad, bd, cd = a - d, b - d, c - d
    t1 = bd[:, 1] * cd[:, 2] - bd[:, 2] * cd[:, 1]
    t2 = cd[:, 1] * ad[:, 2] - cd[:, 2] * ad[:, 1]
    t3 = ad[:, 1] * bd[:, 2] - ad[:, 2] * bd[:, 1]
    det = ad[:, 0] * t1 + bd[:, 0] * t2 + cd[:, 0] * t3
    perm = (np.abs(ad[:, 0]) * (np.abs(bd[:, 1] * cd[:, 2]) + np.abs(bd[:, 2] * cd[:, 1]))
            + np.abs(bd[:, 0]) * (np.abs(cd[:, 1] * ad[:, 2]) + np.abs(cd[:, 2] * ad[:, 1]))
            + np.abs(cd[:, 0]) * (np.abs(ad[:, 1] * bd[:, 2]) + np.abs(ad[:, 2] * bd[:, 1])))
    bound = _BOUND3 * perm
    sign = np.where(det > bound, 1, np.where(-det > bound, -1, 0))
    # Four points with one coordinate equal (a cap in a plane x = const, the plane of
    # symmetry): differences of equal floats are exactly 0, so is the determinant.
    flat = np.any((ad == 0.0) & (bd == 0.0) & (cd == 0.0), axis=1)
    i = np.flatnonzero((np.abs(det) <= bound) & ~flat)
    if i.size:
        sign[i] = _exact3(a[i], b[i], c[i], d[i])
    return sign


def orient2d(a, b, c):
    """(n,) int signs of the orientation of the point sets (n, 2) each: +1 counter-clockwise."""
    a, b, c = (np.asarray(p, float).reshape(-1, 2) for p in (a, b, c))
    det_l = (a[:, 0] - c[:, 0]) * (b[:, 1] - c[:, 1])
    det_r = (a[:, 1] - c[:, 1]) * (b[:, 0] - c[:, 0])
    det = det_l - det_r
    bound = _BOUND2 * (np.abs(det_l) + np.abs(det_r))
    sign = np.where(det > bound, 1, np.where(-det > bound, -1, 0))
    i = np.flatnonzero(np.abs(det) <= bound)
    if i.size:
        sign[i] = _exact2(a[i], b[i], c[i])
    return sign


def segments_hit_triangles(s0, s1, p, q, r):
    """(n,) bool: the closed segments s0-s1 meet the closed triangles pqr (non-coplanar)."""
    a = orient3d(p, q, r, s0)
    b = orient3d(p, q, r, s1)
    crosses = a * b <= 0
    crosses &= ~((a == 0) & (b == 0))  # a segment in the triangle's plane: the 2-D test
    e1 = orient3d(s0, s1, p, q)
    e2 = orient3d(s0, s1, q, r)
    e3 = orient3d(s0, s1, r, p)
    same = ((e1 >= 0) & (e2 >= 0) & (e3 >= 0)) | ((e1 <= 0) & (e2 <= 0) & (e3 <= 0))
    return crosses & same


def _drop_axis(p, q, r):
    """The two coordinates to keep for a 2-D test of triangles in the plane of pqr."""
    n = np.abs(np.cross(q - p, r - p))
    return np.argmax(n, axis=1)


def _coplanar_intersect(t1, t2):
    """(n,) bool for coplanar triangle pairs (n, 3, 3): edges cross or a vertex is inside."""
    axis = _drop_axis(t1[:, 0], t1[:, 1], t1[:, 2])
    keep = np.array([[1, 2], [0, 2], [0, 1]])[axis]
    rows = np.arange(len(t1))[:, None, None]
    u = t1[rows, np.arange(3)[None, :, None], keep[:, None, :]]
    v = t2[rows, np.arange(3)[None, :, None], keep[:, None, :]]
    hit = np.zeros(len(t1), bool)
    for i in range(3):
        a0, a1 = u[:, i], u[:, (i + 1) % 3]
        for j in range(3):
            b0, b1 = v[:, j], v[:, (j + 1) % 3]
            d1, d2 = orient2d(a0, a1, b0), orient2d(a0, a1, b1)
            d3, d4 = orient2d(b0, b1, a0), orient2d(b0, b1, a1)
            hit |= (d1 * d2 <= 0) & (d3 * d4 <= 0) & ~((d1 == 0) & (d2 == 0) & (d3 == 0))
    for w, tri in ((v, u), (u, v)):  # a vertex of one inside the other
        o = [orient2d(tri[:, k], tri[:, (k + 1) % 3], w[:, 0]) for k in range(3)]
        hit |= ((o[0] >= 0) & (o[1] >= 0) & (o[2] >= 0)) | ((o[0] <= 0) & (o[1] <= 0)
                                                            & (o[2] <= 0))
    return hit


def triangles_intersect(t1, t2):
    """(n,) bool: triangles t1 (n, 3, 3) and t2 (n, 3, 3), sharing no vertex, meet."""
    t1, t2 = np.asarray(t1, float), np.asarray(t2, float)
    n = len(t1)
    if n == 0:
        return np.zeros(0, bool)
    rep = lambda t, k: t[:, k]  # noqa: E731
    side2 = np.stack([orient3d(rep(t1, 0), rep(t1, 1), rep(t1, 2), rep(t2, k)) for k in range(3)])
    side1 = np.stack([orient3d(rep(t2, 0), rep(t2, 1), rep(t2, 2), rep(t1, k)) for k in range(3)])
    apart = (np.all(side2 > 0, axis=0) | np.all(side2 < 0, axis=0)
             | np.all(side1 > 0, axis=0) | np.all(side1 < 0, axis=0))
    coplanar = np.all(side2 == 0, axis=0)
    out = np.zeros(n, bool)
    rest = ~apart & ~coplanar
    if coplanar.any():
        out[coplanar] = _coplanar_intersect(t1[coplanar], t2[coplanar])
    idx = np.flatnonzero(rest)
    if idx.size:
        a, b = t1[idx], t2[idx]
        hit = np.zeros(idx.size, bool)
        for s, t in ((a, b), (b, a)):
            for k in range(3):
                hit |= segments_hit_triangles(s[:, k], s[:, (k + 1) % 3], t[:, 0], t[:, 1],
                                              t[:, 2])
        out[idx] = hit
    return out
