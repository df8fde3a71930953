"""Independent checks of fillet lines: outside body and wing, simple polygons, tangency, area.

Nothing here uses juncture's fillet code. The surfaces are the deck's own (``tests.deckgen``
reference surfaces, SciPy PCHIP) or juncture's body model where a test builds its
configuration in code; tangents come from the exact cubic through the sampled points (a cubic
sampled at equal s is recovered exactly by a degree-3 fit); areas from polygons with
thousands of points; crossings from an exact orientation predicate.
"""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, Phase

#: Hypothesis settings of the generated-deck fillet tests: the fast profile derandomized,
#: the slow one (``make test-all``) drawing afresh; and the wing height x root families.
FAST = dict(deadline=None, derandomize=True, suppress_health_check=list(HealthCheck),
            phases=(Phase.explicit, Phase.generate))
SLOW = dict(deadline=None, suppress_health_check=list(HealthCheck),
            phases=(Phase.explicit, Phase.reuse, Phase.generate))
FAMILIES = [(h, r) for h in ("low", "mid", "high") for r in ("inside", "crossing", "outside")]


def cubic_of(points):
    """Coefficients (4, m, 3), highest power first, of the cubic through each line's points
    (sampled at equal s in [0, 1])."""
    s = np.linspace(0.0, 1.0, points.shape[1])
    m = points.shape[0]
    coef = np.polyfit(s, points.transpose(1, 0, 2).reshape(len(s), -1), 3)
    return coef.reshape(4, m, 3)


def end_tangents(points):
    """d/ds at s = 0 and s = 1 of the cubic through each line's points: (m, 3) each."""
    c = cubic_of(points)
    return c[2], 3 * c[0] + 2 * c[1] + c[2]


def dense(points, n=4001):
    """The cubic through each line's points at n equally spaced s: (m, n, 3)."""
    c = cubic_of(points)
    s = np.linspace(0.0, 1.0, n)[None, :, None]
    return ((c[0][:, None] * s + c[1][:, None]) * s + c[2][:, None]) * s + c[3][:, None]


def angle(a, b):
    """Angle [rad] between vectors (..., 3), from atan2 of |a x b| and a . b (accurate
    near 0)."""
    return np.arctan2(np.linalg.norm(np.cross(a, b), axis=-1), (a * b).sum(-1))


def _orient(a, b, c):
    return np.sign((b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1])
                   - (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0]))


def _on_segment(a, b, p):
    return ((np.minimum(a[..., 0], b[..., 0]) <= p[..., 0])
            & (p[..., 0] <= np.maximum(a[..., 0], b[..., 0]))
            & (np.minimum(a[..., 1], b[..., 1]) <= p[..., 1])
            & (p[..., 1] <= np.maximum(a[..., 1], b[..., 1])))


def crossing_pairs(poly, closed=True):
    """Pairs (i, j) of non-adjacent edges of a 2-D polyline (k, 2) that meet or touch.

    The orientation predicate: segments p q and r s meet when r, s lie on different sides
    of p q and p, q on different sides of r s, or when an end lies on the other segment
    (collinear touching). Zero-length edges (repeated points) are dropped first.
    """
    p = np.asarray(poly, float)
    keep = np.ones(len(p), bool)
    keep[1:] = np.any(np.diff(p, axis=0) != 0, axis=1)
    p = p[keep]
    if closed and len(p) > 1 and np.all(p[0] == p[-1]):
        p = p[:-1]
    edges = np.stack([p, np.roll(p, -1, axis=0)], axis=1) if closed else \
        np.stack([p[:-1], p[1:]], axis=1)
    n = len(edges)
    i, j = np.triu_indices(n, 2)
    adjacent = (j - i == 1) | (closed & (i == 0) & (j == n - 1))
    i, j = i[~adjacent], j[~adjacent]
    a, b = edges[i, 0], edges[i, 1]
    c, d = edges[j, 0], edges[j, 1]
    o1, o2, o3, o4 = _orient(a, b, c), _orient(a, b, d), _orient(c, d, a), _orient(c, d, b)
    proper = (o1 * o2 < 0) & (o3 * o4 < 0)
    touch = ((o1 == 0) & _on_segment(a, b, c)) | ((o2 == 0) & _on_segment(a, b, d)) \
        | ((o3 == 0) & _on_segment(c, d, a)) | ((o4 == 0) & _on_segment(c, d, b))
    hit = proper | touch
    return list(zip(i[hit].tolist(), j[hit].tolist()))


def shoelace(poly):
    """Signed area of closed polygons (..., k, 2)."""
    q = np.roll(poly, -1, axis=-2)
    return 0.5 * (poly[..., 0] * q[..., 1] - poly[..., 1] * q[..., 0]).sum(-1)


def wedge_reference(points, corner, center, radius, n=4001):
    """Area filled by each fillet line: the polygon of the curve (n points of the cubic
    through its samples), the straight wing from E to I and the body arc from I to the
    start (n points), in the y-z plane. (m,) [length^2]."""
    curve = dense(points, n)[..., 1:]
    th_i = np.arctan2(corner[:, 2] - center[:, 1], corner[:, 1] - center[:, 0])
    start = points[:, 0]
    th_b = np.arctan2(start[:, 2] - center[:, 1], start[:, 1] - center[:, 0])
    dth = (th_b - th_i + np.pi) % (2 * np.pi) - np.pi
    t = np.linspace(0.0, 1.0, n)[None, :]
    th = th_i[:, None] + t * dth[:, None]
    arc = np.stack([center[:, 0, None] + radius[:, None] * np.cos(th),
                    center[:, 1, None] + radius[:, None] * np.sin(th)], axis=-1)
    poly = np.concatenate([curve, arc], axis=1)
    return np.abs(shoelace(poly))
