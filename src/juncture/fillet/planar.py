"""Circular arcs in a plane x = const, tangent to the body's section and to the wing's.

The wing's section by the plane x = X is the curve of its surface points at that x (chord
fraction from the planform at each span station, clamped to the chord); an arc of radius rho
about C is tangent to it at P when C = P + rho n (n the section's normal away from the wing)
and to the body circle when |C - centre| = r + rho (to an arbitrary section when C lies at
the distance rho from its polyline). Used by the circular fillet of every
layout (:mod:`juncture.fillet.circular`) and by the single-network layout.
"""

from __future__ import annotations

import numpy as np

__all__ = ["planform", "section", "section_tangent", "planar_arcs"]


def planform(wing, span):
    """Leading-edge x, chord and their span derivatives at span stations (extended)."""
    st = wing.span_stations
    k = np.clip(np.searchsorted(st, span, side="right") - 1, 0, st.size - 2)
    h = st[k + 1] - st[k]
    lam = (span - st[k]) / h
    dle = (wing.le[k + 1, 0] - wing.le[k, 0]) / h
    dc = (wing.chord[k + 1] - wing.chord[k]) / h
    return wing.le[k, 0] + lam * h * dle, wing.chord[k] + lam * h * dc, dle, dc


def section(wing, side, X, span):
    """The wing surface's section by the plane x = X at span stations (chord-clamped)."""
    x_le, chord, _, _ = planform(wing, span)
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.clip(np.where(chord != 0, (X - x_le) / chord, 0.0), 0.0, 1.0)
    pts = wing.point(span, f, side, extrapolate=True)
    pts[..., 0] = X
    return pts


def section_tangent(wing, side, X, span):
    """Unit tangent (outboard) of the wing's section x = X at span stations."""
    st = wing.span_stations
    h = 1e-7 * float(st[-1] - st[0])
    d = section(wing, side, X, span + h) - section(wing, side, X, span - h)
    d[..., 0] = 0.0
    return d / np.linalg.norm(d, axis=-1)[..., None]


def planar_arcs(wing, body, side, X, rho, near, n_points, n_grid=64, max_iter=60):
    """Circular arcs of radius rho (m,) in the planes x = X tangent to body and wing section.

    The tangency point P on the wing's section is the first root, coming inboard, of
    |P + rho n - centre| - r - rho (n the section's normal away from the wing), searched
    from twice the span of ``near`` (the fillet end curve's point at X) to the centre
    plane. Returns ``(points, T, theta_T, P, found)``.
    """
    from .circular import arcs

    m = len(X)
    sign = 1.0 if side == "upper" else -1.0
    origin = getattr(body, "origin", None)
    y_c = 0.0 if origin is None else float(origin[1])
    s_hi = np.minimum(y_c + 2.0 * np.abs(near[:, wing.span_axis] - y_c) + 2.0 * rho,
                      float(wing.span_stations[-1]))
    if hasattr(body, "section_at"):
        ctr, r = body.section_at(X)

        def gap(c):
            return np.hypot(c[..., 1] - ctr[:, None, 0], c[..., 2] - ctr[:, None, 1]) - \
                r[:, None]
    else:
        # An arbitrary section: the distance to its polyline (c lies in the plane x = X).
        def gap(c):
            return body.signed_distance(c)

    def error(span):  # span (m, k)
        p = section(wing, side, X[:, None], span)
        t = section_tangent(wing, side, X[:, None], span)
        nrm = np.stack([np.zeros_like(span), -t[..., 2], t[..., 1]], axis=-1) * sign
        c = p + rho[:, None, None] * nrm
        return gap(c) - rho[:, None], p, c

    grid = s_hi[:, None] - np.linspace(0.0, 1.0, n_grid)[None, :] * (s_hi - y_c)[:, None]
    e, _, _ = error(grid)
    inside = e <= 0
    entering = ~inside[:, :-1] & inside[:, 1:]
    found = entering.any(axis=1) & (rho > 0)
    k = np.argmax(entering, axis=1)
    rows = np.arange(m)
    a, b = grid[rows, k], grid[rows, k + 1]
    for _ in range(max_iter):
        mid = 0.5 * (a + b)
        em = error(mid[:, None])[0][:, 0]
        out = em > 0
        a, b = np.where(out, mid, a), np.where(out, b, mid)
    _, p, c = error(b[:, None])
    P, C = p[:, 0], c[:, 0]
    pts, T, th = arcs(body, P, C, np.where(found, rho, 0.0), n_points)
    return pts, T, th, P, found
