"""An independent oracle: the area of the union of a configuration's components in planes
x = const, and its volume, by counting the cells of a fine y-z grid that lie in any of them.

It never uses juncture's area code (:mod:`juncture.analysis.areas`) or a mesh: it asks each
component model only for its section at x (a circular body's centre and radius, an arbitrary
body's polyline, a wing's upper and lower surface at each span station) and decides for every
cell centre whether it lies inside, so overlaps of any two components (a fin standing on a
wing, a pod through it) count once. A cell of size h on a boundary is in or out: the error
of an area is of the order of its perimeter times h over the square root of the number of
cells along it, about 0.05 % at the default 1500 cells across the airplane.
"""

from __future__ import annotations

import numpy as np

__all__ = ["union_area", "union_volume"]


def _grid(cfg, cells):
    lo, hi = cfg.extents()
    span = max(abs(lo[1]), abs(hi[1]))
    h = max(2.0 * span, hi[2] - lo[2]) / cells
    y = np.arange(-span - h, span + 2 * h, h)
    z = np.arange(lo[2] - h, hi[2] + 2 * h, h)
    return y, z, h


def _images(comp, symmetric):
    """Signs of y of the component's copies: its own, and its image where it has one."""
    return (1.0, -1.0) if symmetric and getattr(comp, "mirrored", False) else (1.0,)


def _circular(body, x, y, z, sign):
    centre, radius = body.section_at(np.array([x]))
    r = float(radius[0])
    if not np.isfinite(r) or r <= 0.0:
        return None
    cy, cz = sign * centre[0, 0], centre[0, 1]
    return (y[:, None] - cy) ** 2 + (z[None, :] - cz) ** 2 < r * r


def _arbitrary(body, x, y, z, n=2001):
    """An arbitrary (centre-line) body: both halves of its polyline section at x, inside by
    the even-odd rule along each y column (the polygon's z crossings below a cell)."""
    if not body.x_global[0] <= x <= body.x_global[-1]:
        return None
    half = body.point(np.full(n, x), np.linspace(0.0, 1.0, n))[:, 1:]
    ring = np.concatenate([half, half[::-1] * [-1.0, 1.0]])
    a, b = ring, np.roll(ring, -1, axis=0)
    out = np.zeros((len(y), len(z)), bool)
    cols = np.flatnonzero((y >= ring[:, 0].min()) & (y <= ring[:, 0].max()))
    yc = y[cols][:, None]
    spans = (a[:, 0] <= yc) != (b[:, 0] <= yc)            # edge crosses the column's line
    dy = np.where(b[:, 0] != a[:, 0], b[:, 0] - a[:, 0], 1.0)
    zc = np.where(spans, a[:, 1] + (yc - a[:, 0]) * (b[:, 1] - a[:, 1]) / dy, np.inf)
    zc.sort(axis=1)
    for row, col in zip(zc, cols):
        out[col] = np.searchsorted(row, z) % 2 == 1
    return out


def _winglike(wing, x, y, z, sign):
    """The cells between the wing's lower and upper surfaces at x, along its span axis."""
    span = y * sign if wing.span_axis == 1 else z
    s0, s1 = wing.span_stations[0], wing.span_stations[-1]
    s = np.clip(span, s0, s1)
    zero, one = np.zeros_like(s), np.ones_like(s)
    le, te = wing.point(s, zero, "upper")[:, 0], wing.point(s, one, "upper")[:, 0]
    f = (x - le) / np.where(te > le, te - le, 1.0)
    ok = (span >= s0) & (span <= s1) & (te > le) & (f >= 0.0) & (f <= 1.0)
    f = np.clip(f, 0.0, 1.0)
    t = wing.thickness_axis
    up, low = wing.point(s, f, "upper")[:, t], wing.point(s, f, "lower")[:, t]
    lo, hi = np.minimum(up, low), np.maximum(up, low)
    if wing.span_axis == 1:          # thickness along z: an interval in each y column
        return ok[:, None] & (z[None, :] >= lo[:, None]) & (z[None, :] <= hi[:, None])
    ys = sign * y[:, None]           # a fin: thickness along y, an interval in each z row
    return ok[None, :] & (ys >= lo[None, :]) & (ys <= hi[None, :])


def union_area(cfg, x, cells=1500):
    """Area of the union of every component of ``cfg`` (both halves) in the plane x."""
    from juncture.model import CircularBody, WingLike

    y, z, h = _grid(cfg, cells)
    inside = np.zeros((len(y), len(z)), bool)
    for comp in cfg:
        for sign in _images(comp, cfg.symmetric):
            if isinstance(comp, CircularBody):
                mask = _circular(comp, x, y, z, sign)
            elif isinstance(comp, WingLike):
                mask = _winglike(comp, x, y, z, sign)
            else:
                mask = _arbitrary(comp, x, y, z) if sign > 0 else None
            if mask is not None:
                inside |= mask
    return float(inside.sum()) * h * h


def union_volume(cfg, n=201, cells=1500):
    """The union's volume: :func:`union_area` at ``n`` stations, Simpson's rule in x."""
    from scipy.integrate import simpson

    lo, hi = cfg.extents()
    x = np.linspace(lo[0], hi[0], n)
    return float(simpson([union_area(cfg, xi, cells) for xi in x], x=x))
