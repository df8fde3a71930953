"""Exact orientation predicates and triangle-pair intersection tests for mesh checks.

``orient3d(a, b, c, d)`` is the sign of the determinant of ``(a - d, b - d, c - d)``: +1 when
``d`` lies below the plane through ``a, b, c`` seen with ``a, b, c`` counter-clockwise
(Shewchuk's convention), 0 when the four points are coplanar. The sign is always the exact
sign for the given floating-point coordinates, found in up to three stages, each taking
only the rows the one before leaves undecided:

1. Floating point with Shewchuk's static error bound for the rounded differences
   ((7 + 56 eps) eps times the permanent, plus a margin for products that underflow; an
   overflow leaves the row undecided). This decides points in general position.
2. Exactly in float arithmetic, vectorised over rows, for nearly or exactly coplanar points
   (a flat panel in a tilted plane): where the differences are exact (Knuth's TwoSum leaves
   no error; by Sterbenz's lemma always so for coordinates within a factor 2 of each other,
   as for near points away from the coordinate planes), the row is scaled by a power of two,
   the determinant expanded into 24 doubles with exactly its value as their sum (Dekker's
   TwoProduct with Veltkamp's split; numpy has no fma), and the sign of that sum follows
   from passes of TwoSum along the terms (VecSum, which keeps the exact sum) once all terms
   are 0 or the last one outweighs all the others together. Rows with an inexact
   difference, with differences spanning more than 2**280 (where these error-free
   transformations could underflow) or not settled in a few passes go on to stage 3.
3. Exact rational arithmetic (the floats, which are dyadic rationals, as Python integers
   over one power-of-two denominator): unconditional but some microseconds a row.

``orient2d`` is the same in the plane, with a float filter (bound (3 + 16 eps) eps) and
stage 3.

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
_UNDERFLOW = 2.0 ** -1070  # covers the filter's underflows (2**-1075 each)
_SPLIT = 2.0 ** 27 + 1.0  # Veltkamp's splitter for 53-bit doubles
_RANGE = 2.0 ** -280  # smallest non-zero difference admitted relative to the row's largest
_PASSES = 8  # VecSum passes before a row goes on to _exact3
_BLOCK = 1 << 14  # rows at a time in the expansion stage (bounds its memory)


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
    """Exact signs of orient3d for rows of (k, 3) points, in blocks of rows (Python
    integers take a few hundred bytes each: 570,000 nearly coplanar rows of a held-out
    airplane's check ran out of memory at once)."""
    if len(a) > _BLOCK:
        return np.concatenate([_exact3(a[j:j + _BLOCK], b[j:j + _BLOCK], c[j:j + _BLOCK],
                                       d[j:j + _BLOCK]) for j in range(0, len(a), _BLOCK)])
    p = _integers(np.stack([a, b, c, d], axis=1))
    ad, bd, cd = p[:, 0] - p[:, 3], p[:, 1] - p[:, 3], p[:, 2] - p[:, 3]
    det = (ad[:, 0] * (bd[:, 1] * cd[:, 2] - bd[:, 2] * cd[:, 1])
           + bd[:, 0] * (cd[:, 1] * ad[:, 2] - cd[:, 2] * ad[:, 1])
           + cd[:, 0] * (ad[:, 1] * bd[:, 2] - ad[:, 2] * bd[:, 1]))
    return _sign(det)


def _exact2(a, b, c):
    """Exact signs of orient2d for rows of (k, 2) points, in blocks of rows (as _exact3)."""
    if len(a) > _BLOCK:
        return np.concatenate([_exact2(a[j:j + _BLOCK], b[j:j + _BLOCK], c[j:j + _BLOCK])
                               for j in range(0, len(a), _BLOCK)])
    p = _integers(np.stack([a, b, c], axis=1))
    det = ((p[:, 0, 0] - p[:, 2, 0]) * (p[:, 1, 1] - p[:, 2, 1])
           - (p[:, 0, 1] - p[:, 2, 1]) * (p[:, 1, 0] - p[:, 2, 0]))
    return _sign(det)


def _two_sum(x, y):
    """s, e with s = fl(x + y) and s + e = x + y exactly (Knuth; any finite x, y)."""
    s = x + y
    v = s - x
    return s, (x - (s - v)) + (y - v)


def _split(x):
    """hi, lo of at most 26 bits each with hi + lo = x (Veltkamp)."""
    c = _SPLIT * x
    hi = c - (c - x)
    return hi, x - hi


def _two_prod(x, y):
    """p, e with p = fl(x * y) and p + e = x * y exactly (Dekker), given no overflow and
    no underflow (see _differences)."""
    p = x * y
    (xh, xl), (yh, yl) = _split(x), _split(y)
    return p, ((xh * yh - p) + xh * yl + xl * yh) + xl * yl


def _det_terms(ad, bd, cd):
    """(24, k) terms with the exact determinant of the rows (ad, bd, cd), each (3, k), as
    their sum: each 2x2 minor as 4 terms, each of these times an x coordinate as 2."""
    terms = []
    for p, q, r in ((ad, bd, cd), (bd, cd, ad), (cd, ad, bd)):
        minor = [*_two_prod(q[1], r[2]), *(-t for t in _two_prod(q[2], r[1]))]
        for t in minor:
            terms += _two_prod(p[0], t)
    return np.array(terms)


def _sum_sign(x):
    """Signs of the exact column sums of terms x (m, k) and which columns are decided.

    A pass of TwoSum down each column (VecSum) keeps its exact sum; after each pass a column
    is decided when all its terms are 0, or when its last term exceeds the others' absolute
    sum, computed in floats and raised by (1 + 4 m eps) to cover that sum's rounding.
    """
    m, k = x.shape
    sign = np.zeros(k, np.int64)
    todo = np.arange(k)
    for n_pass in range(_PASSES):
        if n_pass == 2:  # columns still open: terms in order of magnitude converge faster
            x = np.take_along_axis(x, np.argsort(np.abs(x), axis=0), axis=0)
        for i in range(1, m):
            x[i], x[i - 1] = _two_sum(x[i - 1], x[i])
        rest = np.abs(x[:-1]).sum(axis=0) * (1.0 + 4.0 * m * _EPS)
        big = np.abs(x[-1]) > rest
        done = big | ~x.any(axis=0)
        sign[todo[big]] = _sign(x[-1, big])
        todo, x = todo[~done], x[:, ~done]
        if not todo.size:
            break
    decided = np.ones(k, bool)
    decided[todo] = False
    return sign, decided


def _differences(a, b, c, d):
    """The differences (a, b, c) - d as (3, 3, k) (difference, coordinate, row), each row
    scaled by a power of two (its largest difference into [1/2, 1); the sign of the
    determinant stays), and which rows stage 2 can take: differences exact (TwoSum leaves
    no error) and each 0 or in [2**-280, 1) once scaled.

    For those rows every product and error term in _det_terms is 0 or a normal float in
    [2**-996, 1), so TwoProduct and TwoSum are exact there.
    """
    p = np.stack([a, b, c, d]).transpose(0, 2, 1).copy()  # (4, 3, k): rows last
    diff, tail = _two_sum(p[:3], -p[3])
    scaled = np.ldexp(diff, -np.frexp(np.abs(diff).max(axis=(0, 1)))[1])
    size = np.abs(scaled)  # a difference scaled into the subnormals (inexact) is out of range
    fits = np.isfinite(size) & (tail == 0) & ((diff == 0) | (size >= _RANGE))
    return scaled, np.all(fits, axis=(0, 1))


def _expansion3(a, b, c, d):
    """Stage 2 (see the module) for rows of (k, 3) points, in blocks of rows (bounding the
    memory): the exact signs where it can decide, and which rows those are."""
    sign, decided = np.zeros(len(a), np.int64), np.zeros(len(a), bool)
    with np.errstate(over="ignore", invalid="ignore"):
        for j in range(0, len(a), _BLOCK):
            s = slice(j, j + _BLOCK)
            scaled, ok = _differences(a[s], b[s], c[s], d[s])
            i = np.flatnonzero(ok)
            if i.size:
                sign[s][i], decided[s][i] = _sum_sign(_det_terms(*scaled[:, :, i]))
    return sign, decided


def _filter3(ad, bd, cd):
    """The determinant of the rows (ad, bd, cd) in floats and a bound on its error: Shewchuk's
    bound plus the absolute error of products that underflow (at most 2**-1075 each, some
    then multiplied by an x difference). An overflow makes them inf or nan: undecided."""
    t1 = bd[:, 1] * cd[:, 2] - bd[:, 2] * cd[:, 1]
    t2 = cd[:, 1] * ad[:, 2] - cd[:, 2] * ad[:, 1]
    t3 = ad[:, 1] * bd[:, 2] - ad[:, 2] * bd[:, 1]
    det = ad[:, 0] * t1 + bd[:, 0] * t2 + cd[:, 0] * t3
    ax, bx, cx = np.abs(ad[:, 0]), np.abs(bd[:, 0]), np.abs(cd[:, 0])
    perm = (ax * (np.abs(bd[:, 1] * cd[:, 2]) + np.abs(bd[:, 2] * cd[:, 1]))
            + bx * (np.abs(cd[:, 1] * ad[:, 2]) + np.abs(cd[:, 2] * ad[:, 1]))
            + cx * (np.abs(ad[:, 1] * bd[:, 2]) + np.abs(ad[:, 2] * bd[:, 1])))
    return det, _BOUND3 * perm + _UNDERFLOW * (1.0 + ax + bx + cx)


def orient3d(a, b, c, d):
    """(n,) int signs of the orientation of the point sets (n, 3) each (see the module)."""
    a, b, c, d = (np.asarray(p, float).reshape(-1, 3) for p in (a, b, c, d))
    with np.errstate(over="ignore", invalid="ignore"):
        ad, bd, cd = a - d, b - d, c - d
        det, bound = _filter3(ad, bd, cd)
    sign = np.where(det > bound, 1, np.where(-det > bound, -1, 0))
    # Four points with one coordinate equal (a cap in a plane x = const, the plane of
    # symmetry): differences of equal floats are exactly 0, so is the determinant.
    flat = np.any((ad == 0.0) & (bd == 0.0) & (cd == 0.0), axis=1)
    i = np.flatnonzero(~(np.abs(det) > bound) & ~flat)  # within the bound, or inf or nan
    sign[i], decided = _expansion3(a[i], b[i], c[i], d[i])
    i = i[~decided]
    i = i[np.all(np.isfinite(np.hstack([a[i], b[i], c[i], d[i]])), axis=1)]  # inf, nan: no points
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
    i = np.flatnonzero(crosses)        # the rest cannot meet: no need to look further
    s0, s1, p, q, r = (np.asarray(x, float).reshape(-1, 3)[i] for x in (s0, s1, p, q, r))
    e1 = orient3d(s0, s1, p, q)
    e2 = orient3d(s0, s1, q, r)
    e3 = orient3d(s0, s1, r, p)
    crosses[i] = ((e1 >= 0) & (e2 >= 0) & (e3 >= 0)) | ((e1 <= 0) & (e2 <= 0) & (e3 <= 0))
    return crosses


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
