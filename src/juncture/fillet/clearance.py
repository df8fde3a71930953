"""How fillet lines stand against the surfaces, shared by the fillet constructions.

``wing_depth`` (how deep points lie inside the wing, lofting lines extended), ``tolerance``
(how deep counts as inside: 1e-10 of the body length) and ``line_runs`` (fillet lines named
in a log message as runs, "3, 5-8").
"""

from __future__ import annotations

import numpy as np

__all__ = ["wing_depth", "tolerance", "line_runs"]


def wing_depth(wing, points):
    """How deep points (..., 3) lie inside the wing (> 0 inside, lofting lines extended):
    its surfaces at the points' span and chord fraction; -inf off the planform."""
    span = points[..., wing.span_axis]
    ends = wing.point(span[..., None], np.array([0.0, 1.0]), "upper", extrapolate=True)
    x0, x1 = ends[..., 0, 0], ends[..., 1, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        f = (points[..., 0] - x0) / (x1 - x0)
    inside = np.isfinite(f) & (f > 0) & (f < 1)
    fc = np.where(inside, f, 0.5)
    a = wing.thickness_axis
    up = wing.point(span, fc, "upper", extrapolate=True)[..., a]
    lo = wing.point(span, fc, "lower", extrapolate=True)[..., a]
    t = points[..., a]
    return np.where(inside, np.minimum(t - lo, up - t), -np.inf)


def tolerance(body):
    """Depth [deck length] below which a point counts as on a surface, not inside it."""
    return 1e-10 * max(float(body.length), 1.0)


def line_runs(rows):
    """'3, 5-8' from 0-based row indices (1-based in the text)."""
    rows = [int(j) + 1 for j in rows]
    out, start = [], None
    for a, b in zip(rows, rows[1:] + [None]):
        start = a if start is None else start
        if b != a + 1:
            out.append(f"{start}" if start == a else f"{start}-{a}")
            start = None
    return ", ".join(out)
