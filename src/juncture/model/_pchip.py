"""Shape-preserving piecewise cubic Hermite interpolation (PCHIP) in numpy alone.

The model interpolates section offsets and body radii with the same curves as SciPy's
``PchipInterpolator``; importing ``scipy.interpolate`` costs about 0.4 s, more than the rest of
``import juncture`` (issue 14), so the few lines it takes live here.

Slopes (Fritsch & Carlson 1980; Moler, *Numerical Computing with MATLAB* ch 3.6, ``pchiptx``):

- interior station k, with interval widths ``h`` and secant slopes ``m``: ``d_k = 0`` where
  ``m_(k-1)`` and ``m_k`` differ in sign or either is zero, else the weighted harmonic mean
  ``(w1 + w2) / d_k = w1 / m_(k-1) + w2 / m_k``, ``w1 = 2 h_k + h_(k-1)``,
  ``w2 = h_k + 2 h_(k-1)``;
- end station: the one-sided three-point estimate ``d = ((2 h0 + h1) m0 - h0 m1) / (h0 + h1)``
  (``h0, m0`` the end interval, ``h1, m1`` its neighbour), set to 0 where its sign differs from
  ``m0``'s, and to ``3 m0`` where ``m0`` and ``m1`` differ in sign and ``|d| > 3 |m0|``;
- two stations: both slopes are the secant slope (a straight line).

Coefficients are in SciPy's ``PPoly`` layout ``c[:, k]`` = (cubic, quadratic, linear,
constant) in the local coordinate ``x - x_k``, built and evaluated with the same arithmetic
as SciPy, so its ``PchipInterpolator`` (the test oracle) agrees to rounding (in practice to
the last bit).
"""

from __future__ import annotations

import numpy as np

from ..errors import GeometryError

__all__ = ["pchip_slopes", "hermite_coefficients", "pchip_coefficients", "evaluate_cubics",
           "pchip"]


def _check(x, y):
    """x as a float (n,) array, strictly increasing, and y (n, ...) as floats."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    if x.ndim != 1 or x.size < 2:
        raise GeometryError(f"PCHIP stations must be a 1-D array of at least 2 values, found "
                            f"shape {x.shape}")
    if y.ndim < 1 or y.shape[0] != x.size:
        raise GeometryError(f"PCHIP values must have shape ({x.size}, ...) to match the "
                            f"stations, found {y.shape}")
    if not (np.diff(x) > 0).all():
        raise GeometryError("PCHIP stations must increase strictly")
    return x, y


def _widths(x, y):
    """Interval widths shaped (n - 1, 1, ...) to broadcast over y's trailing axes."""
    return np.diff(x).reshape((x.size - 1,) + (1,) * (y.ndim - 1))


def _end_slope(h0, h1, m0, m1):
    """Three-point end slope, kept shape-preserving (see the module docstring)."""
    d = ((2 * h0 + h1) * m0 - h0 * m1) / (h0 + h1)
    wrong_sign = np.sign(d) != np.sign(m0)
    overshoot = (np.sign(m0) != np.sign(m1)) & (np.abs(d) > 3.0 * np.abs(m0))
    return np.where(wrong_sign, 0.0, np.where(overshoot, 3.0 * m0, d))


def pchip_slopes(x, y):
    """PCHIP slopes dy/dx at the stations, along axis 0 for any trailing shape.

    Parameters
    ----------
    x : (n,) float
        Stations, strictly increasing, n >= 2.
    y : (n, ...) float
        Values at the stations.

    Returns
    -------
    (n, ...) float
    """
    x, y = _check(x, y)
    h = _widths(x, y)
    m = np.diff(y, axis=0) / h
    if x.size == 2:
        return np.concatenate([m, m])
    m0, m1 = m[:-1], m[1:]
    flat = (np.sign(m0) != np.sign(m1)) | (m0 == 0) | (m1 == 0)
    w1 = 2 * h[1:] + h[:-1]
    w2 = h[1:] + 2 * h[:-1]
    # Where ``flat`` the mean is discarded: a unit divisor keeps it finite, and leaves the
    # others' arithmetic (and so their rounding) untouched.
    with np.errstate(over="ignore", divide="ignore"):
        mean = (w1 / np.where(flat, 1.0, m0) + w2 / np.where(flat, 1.0, m1)) / (w1 + w2)
        inner = np.where(flat, 0.0, 1.0 / mean)
    first = _end_slope(h[0], h[1], m[0], m[1])
    last = _end_slope(h[-1], h[-2], m[-1], m[-2])
    return np.concatenate([first[None], inner, last[None]])


def hermite_coefficients(x, y, dydx):
    """Cubic coefficients of the Hermite interpolant through given values and slopes.

    Parameters
    ----------
    x : (n,) float
        Stations, strictly increasing, n >= 2.
    y, dydx : (n, ...) float
        Values and slopes dy/dx at the stations.

    Returns
    -------
    (4, n - 1, ...) float
        Row 0 the cubic coefficient, row 3 the value at the piece's start, in the local
        coordinate ``x - x_k`` (SciPy's ``PPoly.c``).
    """
    x, y = _check(x, y)
    dydx = np.asarray(dydx, dtype=float)
    if dydx.shape != y.shape:
        raise GeometryError(f"Hermite slopes must have the values' shape {y.shape}, found "
                            f"{dydx.shape}")
    h = _widths(x, y)
    slope = np.diff(y, axis=0) / h
    t = (dydx[:-1] + dydx[1:] - 2 * slope) / h
    return np.stack([t / h, (slope - dydx[:-1]) / h - t, dydx[:-1], y[:-1]])


def pchip_coefficients(x, y):
    """PCHIP cubic coefficients (4, n - 1, ...) along axis 0 of ``y`` (n, ...).

    Examples
    --------
    Monotone data give a monotone curve through the points:

    >>> c = pchip_coefficients([0.0, 1.0, 2.0], [0.0, 1.0, 1.0])
    >>> c.shape
    (4, 2)
    >>> c[:, 1].tolist()   # flat second piece: constant 1
    [0.0, 0.0, 0.0, 1.0]
    """
    return hermite_coefficients(x, y, pchip_slopes(x, y))


def evaluate_cubics(breaks, coefs, xq):
    """Values of piecewise cubics at ``xq``; beyond the ends the end cubics extrapolate.

    Parameters
    ----------
    breaks : (n,) float
        Breakpoints, increasing (all n of them, as SciPy's ``PPoly.x``).
    coefs : (4, n - 1, ...) float
        Coefficients as returned by :func:`pchip_coefficients`.
    xq : array_like
        Query points, any shape.

    Returns
    -------
    xq.shape + coefs.shape[2:] float

    Notes
    -----
    Piece k holds ``[x_k, x_(k+1))``, the last piece also its right end. The powers of the
    local coordinate are summed in ascending order, as SciPy's ``PPoly`` does.
    """
    breaks = np.asarray(breaks, dtype=float)
    coefs = np.asarray(coefs, dtype=float)
    xq = np.asarray(xq, dtype=float)
    k = np.minimum(np.maximum(np.searchsorted(breaks, xq, side="right") - 1, 0),
                   breaks.size - 2)
    s = (xq - breaks[k]).reshape(xq.shape + (1,) * (coefs.ndim - 2))
    a3, a2, a1, a0 = coefs[:, k]
    s2 = s * s
    return ((a0 + a1 * s) + a2 * s2) + a3 * (s2 * s)


def pchip(x, y, xq):
    """PCHIP through ``y`` (n, ...) at stations ``x`` (n,), evaluated at ``xq``.

    Returns ``xq.shape + y.shape[1:]`` values; outside ``[x[0], x[-1]]`` the end cubics
    extrapolate (SciPy's ``PchipInterpolator(x, y, axis=0, extrapolate=True)(xq)``).

    Examples
    --------
    >>> pchip([0.0, 1.0, 3.0], [0.0, 2.0, 2.0], [0.0, 1.0, 2.0]).tolist()
    [0.0, 2.0, 2.0]
    """
    return evaluate_cubics(x, pchip_coefficients(x, y), xq)
