"""Closed forms of the infinite sine-series kernels behind the Eminton-Lord solve.

With ``x = x_nose + (l/2)(1 - cos theta)`` and ``S'(x) = sum_{n>=1} a_n sin(n theta)`` the area is
``S(theta) = (l/4) sum_n a_n g_n(theta)`` (docs/wavedrag-reference.md), where

    g_n(theta) = sin((n-1) theta)/(n-1) - sin((n+1) theta)/(n+1)     (g_1 = theta - sin(2 theta)/2)
               = int_0^theta 2 sin(n t) sin(t) dt.

The least-drag series through station areas (minimise ``sum n a_n^2`` subject to the station
constraints) has ``a_n = (1/n) sum_i lambda_i g_n(theta_i)``, so with infinitely many modes
everything is a sum over the stations of two kernels, the slope and the area of a station's
multiplier:

    J(theta, phi) = sum_{n>=1} sin(n theta) g_n(phi) / n,
    K(theta, phi) = sum_{n>=1} g_n(theta) g_n(phi) / n = int_0^theta 2 sin(t) J(t, phi) dt.

Both are elementary. With ``sum_n sin(n t) sin(n u) / n = (1/2) ln|sin((t+u)/2) / sin((t-u)/2)|``,
``J = int_0^phi sin(u) ln|sin((theta+u)/2) / sin((theta-u)/2)| du``; one integration by parts
(``d/du`` of the logarithm is ``sin(theta) / (cos u - cos theta)``) gives, with
``d = theta - phi``, ``s = theta + phi`` and ``L = ln|sin(d/2) / sin(s/2)|``,

    J = phi sin(theta) + 2 sin(d/2) sin(s/2) L,
    K = g_1(theta) g_1(phi) + sin(theta) sin(phi) (sin^2(d/2) + sin^2(s/2))
        + 4 sin^2(d/2) sin^2(s/2) L,

(``K`` checked by ``dK/dtheta = 2 sin(theta) J`` and ``K(0, phi) = 0``; the tests compare both
with sums of 200,000 modes, to which they agree to 6e-12.) ``L`` is infinite at
``theta = phi`` (and at ``theta = phi = pi``), where its factor vanishes faster: the product is
0 there. ``K(pi, phi) = pi g_1(phi)``: the base row fixes ``a_1``. A finite series of ``N``
modes converges to these as ``1/N^2``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["area_kernel", "slope_kernel"]


def _halves(theta, phi):
    """``sin(d/2)``, ``sin(s/2)`` and ``ln|sin(d/2) / sin(s/2)|`` (0 where ``sin(d/2) = 0``)."""
    theta, phi = np.broadcast_arrays(np.asarray(theta, float), np.asarray(phi, float))
    sd, ss = np.sin(0.5 * (theta - phi)), np.sin(0.5 * (theta + phi))
    zero = (sd == 0.0) | (ss == 0.0)
    log = np.where(zero, 0.0, np.log(np.abs(np.where(zero, 1.0, sd) / np.where(zero, 1.0, ss))))
    return theta, phi, sd, ss, log


def area_kernel(theta, phi):
    """``K(theta, phi) = sum_{n>=1} g_n(theta) g_n(phi) / n`` for ``0 <= theta, phi <= pi``.

    Parameters
    ----------
    theta, phi : (...) float
        Angles [rad]; broadcast together.

    Returns
    -------
    (...) float
        Symmetric in its arguments.

    Examples
    --------
    >>> round(float(area_kernel(np.pi, np.pi) / np.pi**2), 12)
    1.0
    """
    theta, phi, sd, ss, log = _halves(theta, phi)
    g = (theta - 0.5 * np.sin(2.0 * theta)) * (phi - 0.5 * np.sin(2.0 * phi))
    p = sd * ss
    return g + np.sin(theta) * np.sin(phi) * (sd * sd + ss * ss) + 4.0 * p * p * log


def slope_kernel(theta, phi):
    """``J(theta, phi) = sum_{n>=1} sin(n theta) g_n(phi) / n`` for ``0 <= theta, phi <= pi``.

    Parameters
    ----------
    theta, phi : (...) float
        Angles [rad]; broadcast together.

    Returns
    -------
    (...) float
    """
    theta, phi, sd, ss, log = _halves(theta, phi)
    return phi * np.sin(theta) + 2.0 * sd * ss * log
