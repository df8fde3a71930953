"""Two components whose junctions with one body cross: refused by name.

Each wing-like component that meets a body covers a region of its surface: the band between
its two intersection lines (upper and lower, or outboard and inboard for a fin), from the
leading edge's point to the trailing edge's; with a fillet, the wing's band runs between the
fillet's start lines (``complete`` passes them as ``"<wing> fillet/<body> upper"`` and
``lower``). juncture trims each component at its own lines
and cuts each region out of the body (the fuselage blocks of TM-4607, or a footprint cut
into the body's triangles). Where two regions overlap on the body (a fin standing where the
thick root of the wing already meets the fuselage), one component runs through the other
above the body, a junction of three surfaces that neither paper constructs: the completed
surface would have the two crossing each other. :func:`refuse_crossing_regions` raises a
:class:`~juncture.errors.GeometryError` naming both, where and what to change.

The regions are compared in the body's own chart, x and the angle round its section centre,
so that bands on opposite sides of the body never meet, and the test is exact about which
side of an edge a point lies on up to a margin of :data:`MARGIN` of the chart's extent (two
regions that only touch, a fillet line beside a fin, are not refused).
"""

from __future__ import annotations

import numpy as np

from .errors import GeometryError

__all__ = ["refuse_crossing_regions", "MARGIN"]

#: Overlaps thinner than this share of the regions' extent in the chart do not count.
MARGIN = 1e-6


def _regions(intersections, host):
    """{component: ((k, 3) closed loop of its junction with ``host``, (m, 3) points inside
    it)}: the loop is its first line, then its second reversed, the inside points the
    middles of each lofting line's two points (points that miss the body left out)."""
    lines = {}
    for name, pts in intersections.items():
        a, rest = name.split("/", 1)
        if rest.rsplit(" ", 1)[0] == host:
            lines.setdefault(a, []).append(np.asarray(pts, float))
    out = {}
    for a, ls in lines.items():
        if len(ls) != 2:
            continue
        ok = [np.all(np.isfinite(p), axis=1) for p in ls]
        loop = np.concatenate([ls[0][ok[0]], ls[1][ok[1]][::-1]])
        inner = np.zeros((0, 3))
        if ls[0].shape == ls[1].shape:
            inner = 0.5 * (ls[0] + ls[1])[ok[0] & ok[1]]
        if len(loop) >= 3:
            out[a] = (loop, inner)
    return out


def _chart(body, loops):
    """Loops (k, 3) into the body's chart (x, angle round the section centre), the angle
    measured from the loops' mean direction (the branch cut opposite)."""
    def angle(p):
        c = body.center_at(p[:, 0])
        return np.arctan2(p[:, 2] - c[..., 1], p[:, 1] - c[..., 0])
    ref = np.angle(np.exp(1j * np.concatenate([angle(p) for p in loops])).mean())
    return [np.stack([p[:, 0], np.angle(np.exp(1j * (angle(p) - ref)))], axis=1)
            for p in loops]


def _orient(p, q, r):
    return ((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1])
            - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))


def _overlap(a, b, tol, inner_a=(), inner_b=()):
    """Whether two closed 2-D polygons overlap by more than ``tol``: an edge of one crosses
    an edge of the other with every end clear of the other edge's line, or a corner of one
    (or one of its points ``inner``) lies inside the other, clear of its edges."""
    from .surface.plane import distance, inside

    a0, a1 = a[:, None], np.roll(a, -1, axis=0)[:, None]
    b0, b1 = b[None], np.roll(b, -1, axis=0)[None]

    def side(p, q, r):  # signed distance of r from the line p-q, 0 within tol
        d = _orient(p, q, r) / np.maximum(np.linalg.norm(q - p, axis=-1), 1e-300)
        return np.where(np.abs(d) > tol, np.sign(d), 0.0)
    cross = (side(a0, a1, b0) * side(a0, a1, b1) < 0) & (side(b0, b1, a0) * side(b0, b1, a1) < 0)
    if cross.any():
        return True
    for p, q in ((a, b), (b, a), (inner_a, b), (inner_b, a)):
        p = np.asarray(p, float).reshape(-1, 2)
        if len(p) and np.any(inside(p, q) & (distance(p, q) > tol)):
            return True
    return False


def refuse_crossing_regions(configuration, intersections):
    """Raise a :class:`~juncture.errors.GeometryError` if the junctions of two components
    with one body overlap on it (see the module docstring); the smaller one is named as the
    one to move."""
    comps = {c.name: c for c in configuration}
    hosts = {name.split("/", 1)[1].rsplit(" ", 1)[0] for name in intersections}
    for host in sorted(hosts):
        body = comps.get(host)
        if body is None or not hasattr(body, "center_at") or hasattr(body, "span_axis"):
            continue
        regions = _regions(intersections, host)
        if len(regions) < 2:
            continue
        names = list(regions)
        flat = _chart(body, [regions[n][0] for n in names] + [regions[n][1] for n in names])
        loops, inner = flat[:len(names)], flat[len(names):]
        extent = float(np.ptp(np.concatenate(loops), axis=0).max()) or 1.0
        for i, a in enumerate(names):
            for j in range(i + 1, len(names)):
                if _overlap(loops[i], loops[j], MARGIN * extent, inner[i], inner[j]):
                    _raise(host, (a, regions[a][0]), (names[j], regions[names[j]][0]))


def _raise(host, one, two):
    (a, pa), (b, pb) = sorted((one, two), key=lambda r: np.ptp(r[1][:, 0]))
    lo, hi = max(pa[:, 0].min(), pb[:, 0].min()), min(pa[:, 0].max(), pb[:, 0].max())
    raise GeometryError(
        f"its junction with {host} (x {pa[:, 0].min():.6g} to {pa[:, 0].max():.6g}) overlaps "
        f"that of {b} (x {pb[:, 0].min():.6g} to {pb[:, 0].max():.6g}) on {host}'s surface, "
        f"about x {lo:.6g} to {hi:.6g}: one runs through the other there, a junction of "
        f"three surfaces juncture does not construct; move {a} clear of {b} (along x, or "
        f"round {host})", a)
