"""Vectorised, bracketed root finding along extrapolated lofting lines (TM-4406 eq 4).

TM-4406 extrapolates each lofting line inboard, v(t) = w1 + t (w1 - w2), and steps t by an
amount proportional to the error e(t) until it is small: a fixed-gain iteration that can
overshoot, stall, or converge to the wrong crossing. Here every lofting line of a surface is
solved at once: each line is parameterised by a *section coordinate* u (u = k on section k,
linear between sections, linearly extended beyond the root for u < 0 and beyond the tip for
u > n - 1), the error is sampled on a grid to bracket the crossing the paper means (the first
one reached coming inboard from the tip), and the bracket is closed by the Illinois variant of
regula falsi (superlinear, never leaves the bracket) to a relative tolerance of 1e-13 in u.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError

__all__ = ["polyline_points", "find_crossings", "Crossings"]


def polyline_points(lines, u):
    """Points at section coordinate u on piecewise-linear lines, extended at both ends.

    Parameters
    ----------
    lines : (m, n, 3) float
        m lofting lines through n sections (root first).
    u : (m, ...) float
        Section coordinate per line (0 on the root section, n - 1 on the tip).

    Returns
    -------
    (m, ..., 3) float
    """
    lines = np.asarray(lines, float)
    u = np.asarray(u, float)
    m, n = lines.shape[:2]
    k = np.clip(np.floor(u).astype(int), 0, n - 2)
    lam = (u - k)[..., None]
    rows = np.arange(m).reshape((m,) + (1,) * (u.ndim - 1))
    a, b = lines[rows, k], lines[rows, k + 1]
    return a + lam * (b - a)


@dataclass(frozen=True, slots=True, eq=False)
class Crossings:
    """Result of :func:`find_crossings`.

    Attributes
    ----------
    u : (m,) float
        Section coordinate of the crossing on each line (NaN where the line misses).
    points : (m, 3) float
        The crossing points (NaN rows where the line misses).
    found : (m,) bool
        Whether each line reached the surface.
    n_crossings : (m,) int
        Number of sign changes seen along the sampled range (2 or more: a double crossing).
    iterations : int
        Illinois iterations used to reach the tolerance.
    residual : (m,) float
        |error| at the crossing [deck length].
    """

    u: np.ndarray
    points: np.ndarray
    found: np.ndarray
    n_crossings: np.ndarray
    iterations: int
    residual: np.ndarray


def find_crossings(lines, error, u_low, samples_per_section=24, rtol=1e-13, max_iter=200):
    """Where each extended lofting line first meets a surface, coming inboard from the tip.

    Parameters
    ----------
    lines : (m, n, 3) float
        Lofting lines, root first.
    error : callable
        ``error(points (..., 3)) -> (...)``: negative inside the other surface, positive
        outside, zero on it (TM-4406 eq 6 for a circular body).
    u_low : (m,) float or float
        How far inboard to search (section coordinate, usually < 0: beyond the root).
    samples_per_section : int
        Bracketing grid density; a crossing pair closer than 1/samples of a section apart can
        be missed (both are then reported as no crossing), never mis-solved.
    rtol : float
        Relative tolerance on u (times max(1, |u|)).

    Returns
    -------
    Crossings
    """
    lines = np.asarray(lines, float)
    m, n = lines.shape[:2]
    u_low = np.broadcast_to(np.asarray(u_low, float), (m,))
    u_top = float(n - 1)
    span = u_top - np.minimum(u_low, 0.0)
    n_samp = int(np.ceil(float(span.max()) * samples_per_section)) + 2
    grid = u_top - np.linspace(0.0, 1.0, n_samp)[None, :] * (u_top - u_low)[:, None]  # tip -> in
    e = error(polyline_points(lines, grid))  # (m, n_samp)
    inside = e <= 0.0
    change = inside[:, 1:] != inside[:, :-1]
    n_cross = change.sum(axis=1)
    # First sample reached coming inboard that is inside, preceded by an outside one.
    entering = ~inside[:, :-1] & inside[:, 1:]
    found = entering.any(axis=1)
    i = np.argmax(entering, axis=1)
    rows = np.arange(m)
    a = grid[rows, i]          # outside (e > 0)
    b = grid[rows, i + 1]      # inside (e <= 0)
    fa = e[rows, i]
    fb = e[rows, i + 1]
    act = found.copy()
    side = np.zeros(m, int)
    it = 0
    while act.any():
        it += 1
        if it > max_iter:
            raise ConvergenceError(f"lofting-line intersection did not converge in {max_iter} "
                                   "iterations")
        with np.errstate(invalid="ignore", divide="ignore"):
            c = np.where(fb != fa, b - fb * (b - a) / (fb - fa), 0.5 * (a + b))
        bad = ~np.isfinite(c) | ((c - a) * (c - b) > 0)
        c = np.where(bad, 0.5 * (a + b), c)
        fc = np.where(act, error(polyline_points(lines, np.where(act, c, b)[:, None]))[:, 0],
                      0.0)
        left = fc > 0.0  # c is outside: replaces a
        # Illinois: halve the retained end's value when the same end is kept twice.
        fa_new = np.where(left, fc, np.where(side == -1, fa * 0.5, fa))
        fb_new = np.where(~left, fc, np.where(side == 1, fb * 0.5, fb))
        a = np.where(act & left, c, a)
        b = np.where(act & ~left, c, b)
        fa = np.where(act, fa_new, fa)
        fb = np.where(act, fb_new, fb)
        side = np.where(act, np.where(left, 1, -1), side)
        exact = act & (fc == 0.0)
        a = np.where(exact, c, a)
        b = np.where(exact, c, b)
        act &= np.abs(b - a) > rtol * np.maximum(1.0, np.abs(c))
    # The end with the smaller residual (both are within rtol in u).
    u = np.where(np.abs(fa) < np.abs(fb), a, b)
    u = np.where(found, u, np.nan)
    pts = polyline_points(lines, np.where(found, u, 0.0)[:, None])[:, 0]
    pts[~found] = np.nan
    res = np.full(m, np.nan)
    if found.any():
        res[found] = np.abs(error(pts[found][:, None])[:, 0])
    return Crossings(u, pts, found, n_cross, it, res)
