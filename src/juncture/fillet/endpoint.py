"""Where a cubic fillet ends on its lofting line (TM-4406's three end-point options).

The end point E lies on the lofting line outboard of the intersection I: a span increment
(``end="dy"``), a fraction of the way from I to the next section ("intersection"), or a
section coordinate past the segment holding I ("section"). A lofting line is a polyline
through the sections; E is held at the first bend outboard of I, and just outboard of a bend
at most :data:`BEND_MARGIN` times I's distance from it (arc lengths along the line), so that
the fillet changes continuously when the intersection moves across a section
(:func:`_end_coordinate`). Also the direction of a lofting line where it reaches E, and the
segment holding a section coordinate.
"""

from __future__ import annotations

import numpy as np

from ..errors import GeometryError

__all__ = ["BEND_MARGIN"]


def _line_direction(lines, u, k, found, last=None):
    """(m, 3) unit direction of each lofting line where it reaches u from inboard (the
    segment ending at u where u is a section, to rounding), between segments k and last."""
    n = lines.shape[1]
    rows = np.arange(lines.shape[0])
    seg = np.clip(np.ceil(np.nan_to_num(u) - 1e-9) - 1, 0, n - 2).astype(int)
    seg = np.maximum(seg, k) if last is None else np.clip(seg, k, np.maximum(last, k))
    seg = np.where(found, seg, k)
    d = lines[rows, seg + 1] - lines[rows, seg]
    return d / np.linalg.norm(d, axis=1)[:, None]


def _segment(u, n_sections):
    """Index of the lofting-line segment holding section coordinate u (extended at the ends)."""
    u = np.nan_to_num(np.asarray(u, float))
    return np.clip(np.floor(u), 0, n_sections - 2).astype(int)


#: Just outboard of a bend of the lofting line, at a distance a past it, the end point lies
#: at most BEND_MARGIN * a from I (the fillet grows from nothing as I leaves the bend).
BEND_MARGIN = 4.0


def _arc(lines):
    """(m, n) arc length of each lofting line at its sections, and (m, n - 1) piece lengths."""
    piece = np.linalg.norm(np.diff(lines, axis=1), axis=2)
    return np.concatenate([np.zeros((len(lines), 1)), np.cumsum(piece, axis=1)], axis=1), piece


def _length_at(arc, piece, u):
    """Arc length along each line at section coordinate u (m,), clamped to the line."""
    n = arc.shape[1]
    u = np.clip(np.nan_to_num(u), 0.0, n - 1.0)
    j = np.minimum(np.floor(u).astype(int), n - 2)
    rows = np.arange(len(u))
    return arc[rows, j] + (u - j) * piece[rows, j]


def _u_at(arc, piece, s):
    """Section coordinate at arc length s (m,) along each line (inverse of _length_at)."""
    n = arc.shape[1]
    j = np.clip((arc[:, 1:-1] <= s[:, None]).sum(axis=1), 0, n - 2)
    rows = np.arange(len(s))
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (s - arc[rows, j]) / piece[rows, j]
    return j + np.clip(np.nan_to_num(t), 0.0, 1.0)


def _end_coordinate(wing, inter, end, end_value, k, side, lines):
    """Section coordinate of E per line (see the module), and the lines where it is held.

    ``end="dy"`` is a span increment from I, across sections if it reaches past one. E
    is held where the lofting line first bends outboard of I (sections it runs straight
    through do not count; the tip at most), so that the wing between I and E is straight
    and the curve cannot cut a corner of it. Just outboard of a bend, E lies at most
    ``BEND_MARGIN`` times I's distance from the bend away from I: the fillet shrinks to
    nothing as I approaches a bend from either side, so it changes continuously when the
    intersection moves across a section (as it does while the fixed-area iteration shrinks
    the body).
    """
    u_i = inter.u
    st = wing.span_stations
    n = lines.shape[1]
    if end == "section":
        u_e = k + float(end_value)
    elif end == "intersection":
        u_e = u_i + float(end_value) * ((k + 1.0) - u_i)
    elif end == "dy":
        span_i = np.interp(np.nan_to_num(u_i), np.arange(n), st)
        u_e = np.interp(span_i + float(end_value), st, np.arange(n), right=n - 1.0)
        u_e = np.where(span_i + float(end_value) > st[-1], n - 1.0, u_e)
    else:
        raise GeometryError(f"fillet end must be 'section', 'intersection' or 'dy', found "
                            f"{end!r}", wing.name)
    found = np.asarray(inter.found, bool)
    bad = ~(u_e > u_i) & found
    if np.any(bad):
        j = int(np.argmax(bad))
        raise GeometryError(f"{side} fillet line {j + 1}: the fillet end point (u = "
                            f"{u_e[j]:.4g}) is not outboard of the intersection (u = "
                            f"{u_i[j]:.4g}) on its lofting line; choose a larger end value or "
                            "end='dy'", wing.name, j + 1)
    d = np.diff(lines, axis=1)
    d = d / np.linalg.norm(d, axis=2)[..., None]
    kink = np.zeros(lines.shape[:2], bool)
    kink[:, 1:-1] = 1.0 - (d[:, :-1] * d[:, 1:]).sum(-1) > 1e-12
    sections = np.arange(n)
    u_next = np.where((kink | (sections == n - 1)) & (sections[None, :] >= k[:, None] + 1),
                      sections[None, :], n - 1).min(axis=1).astype(float)
    u_prev = np.where(kink & (sections[None, :] <= np.floor(np.nan_to_num(u_i))[:, None]),
                      sections[None, :], -1).max(axis=1).astype(float)
    arc, piece = _arc(lines)
    s_i = _length_at(arc, piece, u_i)
    want = _length_at(arc, piece, np.minimum(u_e, n - 1.0)) - s_i
    allowed = _length_at(arc, piece, u_next) - s_i
    past = s_i - _length_at(arc, piece, u_prev)
    allowed = np.where(u_prev >= 0, np.minimum(allowed, BEND_MARGIN * past), allowed)
    held = found & (allowed < want)
    u_held = _u_at(arc, piece, s_i + np.maximum(allowed, 0.0))
    return np.where(held, u_held, np.minimum(u_e, n - 1.0)), held
