"""Arbitrary half-sections as the deck gives them: polylines, matched by normalised arc length.

A half-section is the polyline through the deck's (y, z) points (the Harris program joins the
given points by straight lines). Two consecutive sections are matched by normalised arc length
(TM-4607: "the y and z coordinates of each cross-section curve are expressed parametrically in
terms of arc length"): the point at fraction ``s`` of one is joined by a straight line to the
point at fraction ``s`` of the other. Both polylines are piecewise linear in ``s`` with kinks
at their own vertices, so sampling both at the union of their vertex fractions loses nothing:
the blend ``(1 - w) a + w b`` of the two samplings *is* the section at any fraction ``w`` of
the way from one station to the next, exactly, with no resampling.

Every pair is padded to one vertex count ``M`` (the last vertex repeated, ``u = 1``), so that
one fancy index evaluates any number of stations at once; a padded segment has zero length
and changes no distance, area or crossing count.
"""

from __future__ import annotations

import numpy as np

__all__ = ["arc_fractions", "matched_pairs", "area_and_centroid"]


def arc_fractions(sec):
    """Normalised arc length (0 at the first point, 1 at the last) along a polyline (m, 2).

    A polyline of zero length (all points equal, a pointed nose) gets equal fractions.
    """
    seg = np.hypot(*np.diff(sec, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    return s / s[-1] if s[-1] > 0 else np.linspace(0.0, 1.0, len(sec))


def matched_pairs(sections, params=None):
    """Consecutive half-sections sampled at the union of their vertex fractions.

    Parameters
    ----------
    sections : sequence of (m_k, 2) float
        Half-sections (y, z), bottom to top, at increasing stations (n of them, n >= 2).
    params : sequence of (m_k,) float, optional
        The fraction of each vertex (default: :func:`arc_fractions`).

    Returns
    -------
    u : (n - 1, M) float
        Per pair ``k`` (sections k and k + 1), the union of both sections' vertex fractions,
        increasing from 0 to 1, padded with 1.
    a, b : (n - 1, M, 2) float
        Section k and section k + 1 at those fractions (padded with their last vertex).
    count : (n - 1,) int
        The unpadded length of each row.
    """
    fr = [arc_fractions(s) for s in sections] if params is None else \
        [np.asarray(p, float) for p in params]
    us = [np.union1d(f0, f1) for f0, f1 in zip(fr[:-1], fr[1:])]
    count = np.array([v.size for v in us])
    m = int(count.max())
    n = len(us)
    u = np.ones((n, m))
    a = np.empty((n, m, 2))
    b = np.empty((n, m, 2))
    for k, v in enumerate(us):  # construction only: one pair of np.interp per station pair
        u[k, :v.size] = v
        for out, sec, f in ((a, sections[k], fr[k]), (b, sections[k + 1], fr[k + 1])):
            out[k, :v.size, 0] = np.interp(v, f, sec[:, 0])
            out[k, :v.size, 1] = np.interp(v, f, sec[:, 1])
            out[k, v.size:] = out[k, v.size - 1]
    return u, a, b, count


def area_and_centroid(sec):
    """Area of whole sections (both halves) and the height of their area centroid, for
    half-section polylines (..., m, 2) closed along y = 0 (y = 0 by symmetry); a section
    of no area (a pointed nose) gets its mean point height."""
    sec = np.asarray(sec, float)
    zero = np.zeros(sec.shape[:-2] + (1,))
    y = np.concatenate([sec[..., 0], zero, zero], axis=-1)
    z = np.concatenate([sec[..., 1], sec[..., -1:, 1], sec[..., :1, 1]], axis=-1)
    y1, z1 = np.roll(y, -1, axis=-1), np.roll(z, -1, axis=-1)
    c = y * z1 - y1 * z
    half = 0.5 * c.sum(-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        zc = ((z + z1) * c).sum(-1) / (6.0 * half)
    return 2.0 * np.abs(half), np.where(half != 0, zc, sec[..., 1].mean(-1))
