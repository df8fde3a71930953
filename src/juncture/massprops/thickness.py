"""Airfoil thickness distributions mu(x/c) and their v-integrals (Moulton & Hunsaker eqs 1-3).

A thickness distribution gives the full thickness of a section divided by its maximum
thickness, ``t(x) / t_max = mu(x_hat)`` with ``x_hat = x_a / c`` from 0 at the leading edge to 1
at the trailing edge. The closed-form wing mass properties need only four numbers from it,
the *v-integrals*, normalised as the paper prints them (eqs 20, 30, 47, 48; checked by
expanding the NACA case term by term):

========  =========================================  =================================
symbol    definition                                 used for
========  =========================================  =================================
v0        integral mu dx                             volume (eq 18)
v1        4 integral (x - 1/4) mu dx                 chordwise CG (eq 32)
v2        (48/7) integral (x - 1/4)^2 mu dx          chordwise inertia (eqs 38-39)
v3        integral mu^3 dx                           thickness-wise inertia (eqs 37-38)
========  =========================================  =================================

(all integrals over x in [0, 1]).
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..errors import GeometryError

__all__ = ["ThicknessDistribution", "Naca4", "Diamond", "ConstantThickness", "CustomThickness",
           "NACA4_PRESETS", "thickness_v_integrals"]

#: Table 1 of Moulton & Hunsaker: NACA 4-digit-form coefficients (a0..a4) of eq 2.
NACA4_PRESETS = {
    "original": (2.969, -1.260, -3.516, 2.843, -1.015),      # traditional NACA 4-digit series
    "closed_te": (2.980, -1.320, -3.286, 2.441, -0.815),     # closed trailing edge [26]
    "clark_y": (2.947, -1.102, -3.975, 3.533, -1.399),       # Clark Y, with tau_m = 0.117
    "selig_s1010": (0.0001, 9.998, 0.087, -1.922, 14.381),   # Selig S1010
    "diamond_fit": (0.479, -0.948, 14.248, -26.970, 13.234),  # diamond, max at x/c = 0.5
}

# eq 48 as an exact integral: with x = u^2, mu^3 dx = 2 u mu(u^2)^3 du is a polynomial of
# degree 25 in u, integrated exactly by 16-point Gauss-Legendre on [0, 1]
_GL_U, _GL_W = np.polynomial.legendre.leggauss(16)
_GL_U, _GL_W = 0.5 * (_GL_U + 1.0), 0.5 * _GL_W


class ThicknessDistribution:
    """Base class: a section thickness distribution ``mu(x_hat)`` with its v-integrals.

    Subclasses provide :meth:`mu` (vectorised) and :attr:`v` = (v0, v1, v2, v3).
    """

    __slots__ = ()

    def mu(self, x_hat):
        """Thickness over maximum thickness at chord fractions ``x_hat`` (any shape)."""
        raise NotImplementedError

    @property
    def v(self):
        """The v-integrals (v0, v1, v2, v3) as a (4,) float array (see module docstring)."""
        raise NotImplementedError


@dataclass(frozen=True, slots=True)
class Naca4(ThicknessDistribution):
    """NACA 4-digit-form thickness ``mu = a0 sqrt(x) + a1 x + a2 x^2 + a3 x^3 + a4 x^4`` (eq 2).

    The default coefficients are the traditional NACA 4-digit series; :meth:`preset` gives the
    other rows of Table 1. v0, v1, v2 are eqs 20, 30, 47. v3 is eq 48, the integral of mu^3:
    its 35 printed terms cancel badly for large coefficients (2.5e-12 relative error for the
    diamond fit), so it is evaluated as what it is, the integral of a degree-25 polynomial in
    ``u = sqrt(x)``, by 16-point Gauss-Legendre, exact up to rounding (1e-16).

    Examples
    --------
    >>> round(float(Naca4().v[0]), 6)      # (40*2.969 + 30*-1.26 + ...)/60
    0.685083
    """

    a0: float = 2.969
    a1: float = -1.260
    a2: float = -3.516
    a3: float = 2.843
    a4: float = -1.015

    def __post_init__(self):
        a = np.array([self.a0, self.a1, self.a2, self.a3, self.a4], dtype=float)
        if not np.all(np.isfinite(a)):
            raise GeometryError(f"NACA 4-digit coefficients must be finite, found {a.tolist()}")

    @classmethod
    def preset(cls, name):
        """A Table 1 row by name: one of :data:`NACA4_PRESETS` (``"original"``, ...)."""
        if name not in NACA4_PRESETS:
            raise GeometryError(f"unknown NACA 4-digit preset {name!r}; expected one of "
                                f"{', '.join(sorted(NACA4_PRESETS))}")
        return cls(*NACA4_PRESETS[name])

    @property
    def coefficients(self):
        """(a0, a1, a2, a3, a4) as a (5,) float array."""
        return np.array([self.a0, self.a1, self.a2, self.a3, self.a4], dtype=float)

    def mu(self, x_hat):
        x = np.asarray(x_hat, dtype=float)
        a = self.coefficients
        return a[0] * np.sqrt(x) + x * (a[1] + x * (a[2] + x * (a[3] + x * a[4])))

    @property
    def v(self):
        a0, a1, a2, a3, a4 = self.coefficients
        v0 = (40 * a0 + 30 * a1 + 20 * a2 + 15 * a3 + 12 * a4) / 60.0          # eq 20
        v1 = (56 * a0 + 50 * a1 + 40 * a2 + 33 * a3 + 28 * a4) / 60.0          # eq 30
        v2 = (856 * a0 + 770 * a1 + 644 * a2 + 553 * a3 + 484 * a4) / 980.0    # eq 47
        u, w = _GL_U, _GL_W                                                     # eq 48
        v3 = np.dot(w, 2.0 * u * self.mu(u * u) ** 3)
        return np.array([v0, v1, v2, v3])


@dataclass(frozen=True, slots=True)
class Diamond(ThicknessDistribution):
    """Diamond (double-wedge) thickness, maximum at ``x_m`` (eq 3); v-integrals eqs 21, 31, 49, 50.

    Examples
    --------
    >>> Diamond(0.5).v.tolist()
    [0.5, 0.5, 0.35714285714285715, 0.25]
    """

    x_m: float = 0.5

    def __post_init__(self):
        if not (np.isfinite(self.x_m) and 0.0 <= self.x_m <= 1.0):
            raise GeometryError(f"diamond x_m (chord fraction of maximum thickness) must be in "
                                f"[0, 1], found {self.x_m!r}")

    def mu(self, x_hat):
        x = np.asarray(x_hat, dtype=float)
        xm = float(self.x_m)
        with np.errstate(divide="ignore", invalid="ignore"):
            fore = np.where(xm > 0, x / xm, 1.0)
            aft = np.where(xm < 1, (1.0 - x) / (1.0 - xm), 1.0)
        return np.where(x <= xm, fore, aft)

    @property
    def v(self):
        xm = float(self.x_m)
        return np.array([0.5, (4 * xm + 1) / 6.0, (8 * xm * xm + 3) / 14.0, 0.25])


@dataclass(frozen=True, slots=True)
class ConstantThickness(ThicknessDistribution):
    """Constant thickness ``mu = 1``: a rectangular section, e.g. a fuel tank (section 5).

    Moulton & Hunsaker section 5 models fuel tanks as "wing segments with constant thickness
    distribution (i.e., mu(x_a/c) = 1)": every section is a rectangle of chord c and
    thickness tau c. Its v-integrals are exactly 1: integral 1 dx = 1, 4 integral (x - 1/4) dx
    = 4 (1/2 - 1/4) = 1, (48/7) integral (x - 1/4)^2 dx = (48/7)(7/48) = 1, integral 1 dx = 1.

    Examples
    --------
    >>> ConstantThickness().v.tolist()
    [1.0, 1.0, 1.0, 1.0]
    """

    def mu(self, x_hat):
        return np.ones_like(np.asarray(x_hat, dtype=float))

    @property
    def v(self):
        return np.ones(4)


def thickness_v_integrals(func, breakpoints=()):
    """The v-integrals of an arbitrary ``mu(x_hat)`` by adaptive quadrature.

    Uses ``scipy.integrate.quad`` (QUADPACK QAGS, 21-point Gauss-Kronrod with extrapolation,
    which copes with the sqrt(x) behaviour at a leading edge) with ``epsabs=0``,
    ``epsrel=1e-13``, ``limit=200``, split at ``breakpoints`` (kinks of mu).

    Parameters
    ----------
    func : callable
        ``mu(x_hat) -> float`` on [0, 1].
    breakpoints : sequence of float
        Chord fractions in (0, 1) where mu has a kink or jump.

    Returns
    -------
    (4,) float
        (v0, v1, v2, v3).

    Raises
    ------
    GeometryError
        If mu is not finite or the quadrature does not reach its tolerance.
    """
    from scipy import integrate  # only custom thicknesses need it; the import takes ~0.4 s

    edges = np.unique(np.concatenate([[0.0, 1.0],
                                      [b for b in breakpoints if 0.0 < b < 1.0]]))
    weights = (lambda x, f: f,
               lambda x, f: 4.0 * (x - 0.25) * f,
               lambda x, f: 48.0 / 7.0 * (x - 0.25) ** 2 * f,
               lambda x, f: f ** 3)
    out = np.zeros(4)
    for k, w in enumerate(weights):
        def integrand(x, w=w):
            f = float(func(x))
            if not np.isfinite(f):
                raise GeometryError(f"custom thickness mu({x:.6g}) is not finite ({f})")
            return w(x, f)

        for lo, hi in zip(edges[:-1], edges[1:], strict=True):
            with warnings.catch_warnings():
                warnings.simplefilter("error", integrate.IntegrationWarning)
                try:
                    val, _ = integrate.quad(integrand, lo, hi, epsabs=0.0, epsrel=1e-13,
                                            limit=200)
                except integrate.IntegrationWarning as exc:
                    raise GeometryError(f"custom thickness: v{k} integral over [{lo:g}, {hi:g}] "
                                        f"did not converge ({exc}); expected a smooth mu, give "
                                        f"its kinks as breakpoints") from None
            out[k] += val
    return out


@dataclass(frozen=True, slots=True, eq=False)
class CustomThickness(ThicknessDistribution):
    """Any thickness distribution ``mu(x_hat)``, v-integrals by :func:`thickness_v_integrals`.

    ``func`` is called with scalar floats in [0, 1]. For a fuel tank of constant thickness
    (``mu = 1``, Moulton & Hunsaker section 5) use :class:`ConstantThickness`, exact and
    without quadrature.

    Examples
    --------
    >>> CustomThickness(lambda x: 1.0).v.round(12).tolist()
    [1.0, 1.0, 1.0, 1.0]
    """

    func: Callable
    breakpoints: tuple = ()
    _v: object = field(init=False, repr=False, default=None)

    def __post_init__(self):
        if not callable(self.func):
            raise GeometryError(f"custom thickness needs a callable mu(x), found "
                                f"{type(self.func).__name__}")
        object.__setattr__(self, "breakpoints", tuple(float(b) for b in self.breakpoints))
        v = thickness_v_integrals(self.func, self.breakpoints)
        v.flags.writeable = False
        object.__setattr__(self, "_v", v)

    def mu(self, x_hat):
        return np.vectorize(lambda x: float(self.func(x)), otypes=[float])(x_hat)

    @property
    def v(self):
        return self._v
