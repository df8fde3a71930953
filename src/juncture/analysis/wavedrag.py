"""Slender-body (von Karman / Eminton-Lord) and far-field averaged supersonic wave drag.

Source: docs/wavedrag-reference.md. A body of length ``l`` with cross-sectional area
``S(x)``, ``S(0) = 0`` at the nose, is described in the angle ``theta`` of

    x = x_nose + (l / 2) (1 - cos theta),     0 <= theta <= pi,

by the sine series of its slope, ``S'(x) = sum_{n>=1} a_n sin(n theta)``. Its slender-body wave
drag is (von Karman; Ashley & Landahl sec 9.5)

    D / q = (pi / 4) sum_{n>=1} n a_n^2,

and integrating ``S' dx = (l/2) S'(theta) sin(theta) d theta`` gives the area itself,

    S(theta) = (l/4) [ a_1 (theta - sin(2 theta)/2)
                      + sum_{n>=2} a_n ( sin((n-1) theta)/(n-1) - sin((n+1) theta)/(n+1) ) ],

so ``S(l) = (pi l / 4) a_1``: only ``a_1`` carries a base area (``a_1 = 0`` for a closed base).

**Eminton-Lord** (Eminton 1956; Eminton & Lord): from station areas alone, take the area curve
of least drag through them. With ``N`` modes this is a least-norm problem, minimise
``sum n a_n^2`` subject to ``C a = s`` (``C_in`` the coefficient of ``a_n`` in ``S(theta_i)``):
``a = W^-1 C^T (C W^-1 C^T)^-1 s``, ``W = diag(n)``. It is solved here, without forming
``C W^-1 C^T``, as the minimum-norm solution of ``(C W^-1/2) b = s``, ``b = W^1/2 a``, by a
singular value decomposition, whose condition number is the square root of that of
``C W^-1 C^T``. Interpolating the stations and then expanding does NOT converge (the trap of
wavedrag.md): never do that.

**Far field** (Hayes; Harris, NASA TM X-947): the wave drag of a configuration at Mach ``M`` is
the average over roll angle of the slender-body drag of the equivalent bodies ``S(X, theta)``
cut by Mach planes (see :mod:`juncture.analysis.cuts`).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ..errors import GeometryError, JunctureError, JunctureWarning

__all__ = [
    "WaveDragResult",
    "FarFieldResult",
    "eminton_lord",
    "eminton_lord_convergence",
    "von_karman",
    "far_field_drag",
    "sears_haack_drag",
    "sears_haack_area",
]

#: Singular values below this fraction of the largest are dropped (with a warning).
_RCOND = 1e-13
#: Condition number of the scaled constraint matrix above which a warning is given.
_COND_WARN = 1e10


# --------------------------------------------------------------------------------------------
# Result values


@dataclass(frozen=True, slots=True, eq=False)
class WaveDragResult:
    """Slender-body wave drag of one (equivalent) body and its sine-series area curve.

    Attributes
    ----------
    d_over_q : float
        Wave drag over dynamic pressure, ``(pi/4) sum n a_n^2`` [deck length^2].
    coefficients : (n_modes,) float
        ``a_n``, n = 1..n_modes, of ``S'(x) = sum a_n sin(n theta)`` [deck length].
    n_modes : int
        Number of sine modes.
    method : str
        ``"eminton-lord"`` (least drag through stations) or ``"von-karman"`` (exact slope).
    x_nose, length : float
        The body runs from ``x_nose`` to ``x_nose + length`` [deck length].
    condition : float
        Condition number of the scaled constraint matrix (``nan`` for von Karman).
    residual : float
        Largest ``|S_fit(x_i) - S_i|`` over the stations (0 for von Karman) [deck length^2].
    """

    d_over_q: float
    coefficients: np.ndarray
    n_modes: int
    method: str
    x_nose: float
    length: float
    condition: float = float("nan")
    residual: float = 0.0

    def __post_init__(self):
        a = np.array(self.coefficients, dtype=float)
        a.flags.writeable = False
        object.__setattr__(self, "coefficients", a)

    @property
    def base_area(self):
        """Area at the base, ``(pi l / 4) a_1`` [deck length^2]."""
        return 0.25 * np.pi * self.length * float(self.coefficients[0])

    def c_d(self, reference_area):
        """Wave-drag coefficient ``(D/q) / reference_area``."""
        reference_area = float(reference_area)
        if not reference_area > 0.0:
            raise JunctureError(f"reference area must be positive, found {reference_area}")
        return self.d_over_q / reference_area

    def area(self, x):
        """The fitted area distribution ``S(x)`` (0 ahead of the nose, base area behind).

        Parameters
        ----------
        x : (...) float
            Stations [deck length].

        Returns
        -------
        (...) float
            Area [deck length^2].
        """
        theta = _theta_of_x(np.asarray(x, dtype=float), self.x_nose, self.length)
        return 0.25 * self.length * (_area_basis(theta.ravel(), self.n_modes)
                                     @ self.coefficients).reshape(theta.shape)

    def slope(self, x):
        """The fitted slope ``S'(x) = sum a_n sin(n theta)`` (0 outside the body) [deck length]."""
        xa = np.asarray(x, dtype=float)
        theta = _theta_of_x(xa, self.x_nose, self.length)
        n = np.arange(1, self.n_modes + 1)
        out = np.sin(theta.ravel()[:, None] * n) @ self.coefficients
        inside = (xa >= self.x_nose) & (xa <= self.x_nose + self.length)
        return np.where(inside, out.reshape(theta.shape), 0.0)


@dataclass(frozen=True, slots=True, eq=False)
class FarFieldResult:
    """Far-field (supersonic area rule) wave drag: the roll-angle average of equivalent bodies.

    Attributes
    ----------
    d_over_q : float
        ``mean_theta D(theta)/q`` [deck length^2].
    thetas : (n_theta,) float
        Roll angles [rad].
    d_over_q_theta : (n_theta,) float
        Slender-body ``D(theta)/q`` of each equivalent body [deck length^2].
    bodies : tuple of WaveDragResult
        The equivalent bodies (``None`` where a cut family has no area).
    """

    d_over_q: float
    thetas: np.ndarray
    d_over_q_theta: np.ndarray
    bodies: tuple

    def __post_init__(self):
        for name in ("thetas", "d_over_q_theta"):
            a = np.array(getattr(self, name), dtype=float)
            a.flags.writeable = False
            object.__setattr__(self, name, a)

    def c_d(self, reference_area):
        """Wave-drag coefficient ``(D/q) / reference_area``."""
        reference_area = float(reference_area)
        if not reference_area > 0.0:
            raise JunctureError(f"reference area must be positive, found {reference_area}")
        return self.d_over_q / reference_area


# --------------------------------------------------------------------------------------------
# Series helpers


def _theta_of_x(x, x_nose, length):
    xi = np.clip((x - x_nose) / length, 0.0, 1.0)
    return np.arccos(np.clip(1.0 - 2.0 * xi, -1.0, 1.0))


def _area_basis(theta, n_modes):
    """(m, n_modes) matrix g_n(theta) with S(theta) = (l/4) sum_n a_n g_n(theta)."""
    theta = np.asarray(theta, dtype=float)
    g = np.empty((theta.size, n_modes))
    g[:, 0] = theta - 0.5 * np.sin(2.0 * theta)
    if n_modes > 1:
        k = np.arange(1, n_modes + 2, dtype=float)  # sin(k theta), k = 1..n_modes+1
        s = np.sin(theta[:, None] * k) / k
        g[:, 1:] = s[:, :-2] - s[:, 2:]  # n = 2..N: sin((n-1)t)/(n-1) - sin((n+1)t)/(n+1)
    return g


def _drag(a):
    n = np.arange(1, a.size + 1)
    return 0.25 * np.pi * float(np.sum(n * a * a))


def _check_stations(x, area):
    x = np.asarray(x, dtype=float)
    area = np.asarray(area, dtype=float)
    if x.ndim != 1 or area.shape != x.shape:
        raise GeometryError(f"x and area must be 1-D arrays of equal length, found shapes "
                            f"{x.shape} and {area.shape}")
    if x.size < 2:
        raise GeometryError(f"at least 2 stations (nose and base) are needed, found {x.size}")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(area))):
        bad = int(np.flatnonzero(~(np.isfinite(x) & np.isfinite(area)))[0])
        raise GeometryError("non-finite station or area", station=bad + 1)
    dx = np.diff(x)
    if np.any(dx <= 0.0):
        bad = int(np.flatnonzero(dx <= 0.0)[0])
        raise GeometryError(f"stations must increase strictly, found x = {x[bad]} then "
                            f"{x[bad + 1]}", station=bad + 2)
    scale = max(float(np.max(np.abs(area))), np.finfo(float).tiny)
    tol = 1e-9 * scale
    if np.any(area < -tol):
        bad = int(np.flatnonzero(area < -tol)[0])
        raise GeometryError(f"area must not be negative, found {area[bad]}", station=bad + 1)
    if abs(area[0]) > tol:
        raise GeometryError(f"slender-body theory needs S = 0 at the nose (first station), found "
                            f"{area[0]}; subtract an inlet capture area first", station=1)
    return x, area


def _default_modes(n_stations):
    return int(max(400, 8 * n_stations))


# --------------------------------------------------------------------------------------------
# Public functions


def eminton_lord(x, area, n_modes=None):
    """Least-drag area distribution through station areas and its wave drag (Eminton-Lord).

    Parameters
    ----------
    x : (m,) float
        Stations, strictly increasing; ``x[0]`` is the nose, ``x[-1]`` the base [deck length].
    area : (m,) float
        Cross-sectional areas; ``area[0]`` must be 0, ``area[-1]`` is the base area (0 for a
        closed body) [deck length^2].
    n_modes : int, optional
        Number of sine modes ``N`` (>= m - 1). Default ``max(400, 8 m)``, which converges the
        drag of a 117-station Sears-Haack body to about 1e-6 (see
        :func:`eminton_lord_convergence`). The drag decreases monotonically with ``N``.

    Returns
    -------
    WaveDragResult
        ``d_over_q`` [deck length^2], the coefficients ``a_n`` and ``area(x)`` of the fit.

    Raises
    ------
    GeometryError
        Stations not strictly increasing, shapes that differ, negative areas, or a nonzero
        nose area.
    JunctureError
        ``n_modes`` smaller than the number of constrained stations.

    Warns
    -----
    JunctureWarning
        If the constraint matrix is ill-conditioned (stations very close near the ends).

    Notes
    -----
    Constraints: ``S(theta_i) = S_i`` for every station after the nose (the nose value S = 0
    holds for every series). The base row ``theta = pi`` fixes ``a_1 = 4 S(l) / (pi l)``, so an
    open base is handled exactly: its drag ``(pi/4) a_1^2`` is the von Karman ogive's
    ``4 S_b^2 / (pi l^2)`` and the other modes only shape the curve between the stations.

    Examples
    --------
    Two stations (nose and base) give the von Karman ogive, ``D/q = 4 S_b^2 / (pi l^2)``:

    >>> r = eminton_lord([0.0, 2.0], [0.0, 1.0])
    >>> round(r.d_over_q * np.pi, 12)
    1.0
    """
    x, area = _check_stations(x, area)
    m = x.size - 1  # constrained stations
    if n_modes is None:
        n_modes = _default_modes(x.size)
    n_modes = int(n_modes)
    if n_modes < m:
        raise JunctureError(f"n_modes must be at least the number of stations after the nose "
                            f"({m}), found {n_modes}")
    x_nose, length = float(x[0]), float(x[-1] - x[0])
    theta = _theta_of_x(x[1:], x_nose, length)
    theta[-1] = np.pi
    g = _area_basis(theta, n_modes)
    g[-1, 1:] = 0.0  # sin(k pi) = 0 exactly at the base
    rhs = 4.0 * area[1:] / length  # S_i = (l/4) g a  ->  g a = 4 S_i / l
    w = 1.0 / np.sqrt(np.arange(1, n_modes + 1, dtype=float))
    amat = g * w  # columns scaled by W^-1/2
    rownorm = np.linalg.norm(amat, axis=1)
    amat = amat / rownorm[:, None]
    rhs_scaled = rhs / rownorm
    u, sig, vt = np.linalg.svd(amat, full_matrices=False)
    cond = float(sig[0] / sig[-1]) if sig[-1] > 0 else float("inf")
    keep = sig > _RCOND * sig[0]
    if cond > _COND_WARN:
        warnings.warn(f"Eminton-Lord constraint matrix is ill-conditioned (condition {cond:.3g},"
                      f" {int(np.sum(~keep))} of {sig.size} singular values dropped): stations "
                      f"too close together?", JunctureWarning, stacklevel=2)
    b = vt[keep].T @ ((u[:, keep].T @ rhs_scaled) / sig[keep])
    a = b * w
    resid = 0.25 * length * float(np.max(np.abs(g @ a - rhs)))
    return WaveDragResult(d_over_q=_drag(a), coefficients=a, n_modes=n_modes,
                          method="eminton-lord", x_nose=x_nose, length=length,
                          condition=cond, residual=resid)


def eminton_lord_convergence(x, area, n_modes=(20, 50, 100, 200, 400, 1000)):
    """D/q of :func:`eminton_lord` for several numbers of modes, to show convergence.

    Parameters
    ----------
    x, area : (m,) float
        As for :func:`eminton_lord`.
    n_modes : sequence of int
        Mode counts, each >= m - 1.

    Returns
    -------
    (k, 2) float
        Rows ``(n_modes, d_over_q)``.
    """
    rows = [(float(n), eminton_lord(x, area, n_modes=n).d_over_q) for n in n_modes]
    return np.array(rows)


def von_karman(dSdx, length, n_modes, x_nose=0.0, n_quad=None):
    """Sine-series wave drag of a body with an analytic slope ``S'(x)``.

    Parameters
    ----------
    dSdx : callable
        ``dSdx(x)`` -> ``S'(x)`` for an array of stations ``x_nose <= x <= x_nose + length``
        [deck length].
    length : float
        Body length [deck length].
    n_modes : int
        Number of sine modes.
    x_nose : float, optional
        Nose station [deck length].
    n_quad : int, optional
        Gauss-Legendre points in theta, default ``2 n_modes + 200``.

    Returns
    -------
    WaveDragResult
        With ``a_n = (2/pi) int_0^pi S'(x(theta)) sin(n theta) d theta``.

    Examples
    --------
    Sears-Haack body of length 1 and S_max 1 (``S' = 3 sin 2 theta``): ``D/q = 9 pi / 2``.

    >>> r = von_karman(lambda x: 6.0 * (4 * x * (1 - x)) ** 0.5 * (1 - 2 * x), 1.0, 10)
    >>> round(r.d_over_q / (4.5 * np.pi), 12)
    1.0
    """
    length = float(length)
    if not length > 0.0:
        raise JunctureError(f"length must be positive, found {length}")
    n_modes = int(n_modes)
    if n_modes < 1:
        raise JunctureError(f"n_modes must be at least 1, found {n_modes}")
    n_quad = 2 * n_modes + 200 if n_quad is None else int(n_quad)
    t, wq = np.polynomial.legendre.leggauss(n_quad)
    theta = 0.5 * np.pi * (t + 1.0)
    wq = 0.5 * np.pi * wq
    xq = x_nose + 0.5 * length * (1.0 - np.cos(theta))
    fq = np.asarray(dSdx(xq), dtype=float)
    if fq.shape != xq.shape or not np.all(np.isfinite(fq)):
        raise JunctureError(f"dSdx must return finite values of shape {xq.shape}, found shape "
                            f"{fq.shape}")
    n = np.arange(1, n_modes + 1)
    a = (2.0 / np.pi) * (np.sin(np.outer(n, theta)) @ (wq * fq))
    return WaveDragResult(d_over_q=_drag(a), coefficients=a, n_modes=n_modes,
                          method="von-karman", x_nose=float(x_nose), length=length)


def far_field_drag(cut_areas, x_cut, thetas, n_modes=None, trim=True):
    """Far-field wave drag: the average over roll angle of the equivalent bodies' drag.

    Parameters
    ----------
    cut_areas : (n_theta, n_x) float
        ``S(X, theta)``, Mach-plane cut areas projected onto the x-normal plane
        (:func:`juncture.analysis.cuts.mach_plane_areas`) [deck length^2].
    x_cut : (n_x,) or (n_theta, n_x) float
        The cut offsets ``X``, strictly increasing (per angle if 2-D) [deck length].
    thetas : (n_theta,) float
        Roll angles, equally spaced over a full turn (``theta_k = theta_0 + 2 pi k / n``) [rad].
    n_modes : int, optional
        Modes per equivalent body (default as :func:`eminton_lord`).
    trim : bool, optional
        Drop the zero areas ahead of each equivalent body's first nonzero area and behind its
        last one (keeping one zero station at each end), so that each equivalent body's length
        is its own. Default True.

    Returns
    -------
    FarFieldResult
        ``d_over_q = (1/n) sum_k D(theta_k)/q``.

    Raises
    ------
    JunctureError
        Shapes that do not match, or angles not equally spaced over a full turn.

    Notes
    -----
    Harris (TM X-947): ``D/q = (1/2 pi) int_0^{2 pi} D(theta)/q d theta``. ``D(theta)`` is
    smooth and 2 pi periodic, and the mean over equally spaced angles is the trapezoid rule for
    a periodic integrand, which is exact for trigonometric polynomials of degree below
    ``n_theta`` and converges geometrically for analytic ones. An equivalent body with no area
    at all has zero drag. The nose and base of each equivalent body are located to within one
    spacing of ``x_cut``; pass per-angle offsets spanning each body's own extent
    (:func:`juncture.analysis.cuts.mach_plane_extents`) for the best resolution.
    """
    s = np.asarray(cut_areas, dtype=float)
    thetas = np.asarray(thetas, dtype=float)
    if s.ndim != 2 or thetas.shape != (s.shape[0],):
        raise JunctureError(f"cut_areas must be (n_theta, n_x) with thetas (n_theta,), found "
                            f"{s.shape} and {thetas.shape}")
    xc = np.asarray(x_cut, dtype=float)
    if xc.shape == s.shape[1:]:
        xc = np.broadcast_to(xc, s.shape)
    if xc.shape != s.shape:
        raise JunctureError(f"x_cut must be (n_x,) or (n_theta, n_x) = {s.shape}, found "
                            f"{np.shape(x_cut)}")
    nt = thetas.size
    step = 2.0 * np.pi / nt
    k = np.arange(nt)
    dev = np.angle(np.exp(1j * (thetas - thetas[0] - step * k)))
    if np.any(np.abs(dev) > 1e-9):
        raise JunctureError(f"thetas must be {nt} angles equally spaced over a full turn "
                            f"(step {step:.6g} rad), found {np.array2string(thetas, precision=4)}")
    d = np.zeros(nt)
    bodies = []
    for i in range(nt):  # one linear solve per roll angle
        xi, si = xc[i], s[i]
        if trim:
            scale = float(np.max(np.abs(si))) if si.size else 0.0
            nz = np.flatnonzero(si > 1e-12 * scale) if scale > 0 else np.array([], int)
            if nz.size == 0:
                bodies.append(None)
                continue
            lo, hi = max(nz[0] - 1, 0), min(nz[-1] + 1, si.size - 1)
            xi, si = xi[lo:hi + 1], si[lo:hi + 1].copy()
            si[0] = 0.0 if lo < nz[0] else si[0]
        body = eminton_lord(xi, si, n_modes=n_modes)
        bodies.append(body)
        d[i] = body.d_over_q
    return FarFieldResult(d_over_q=float(np.mean(d)), thetas=thetas, d_over_q_theta=d,
                          bodies=tuple(bodies))


def sears_haack_drag(volume, length):
    """Wave drag of the Sears-Haack body, ``D/q = 128 V^2 / (pi l^4)`` [deck length^2].

    Examples
    --------
    >>> round(sears_haack_drag(3 * np.pi / 16, 1.0) / (4.5 * np.pi), 12)
    1.0
    """
    volume, length = float(volume), float(length)
    if not (volume > 0.0 and length > 0.0):
        raise JunctureError(f"volume and length must be positive, found {volume}, {length}")
    return 128.0 * volume**2 / (np.pi * length**4)


def sears_haack_area(x, length, volume):
    """Sears-Haack area ``S_max (4 xi (1 - xi))^(3/2)``, ``xi = x / l``, ``S_max = 16 V/(3 pi l)``.

    Parameters
    ----------
    x : (...) float
        Stations measured from the nose; the area is 0 outside ``0 <= x <= length``
        [deck length].
    length, volume : float
        Body length [deck length] and volume [deck length^3].

    Returns
    -------
    (...) float
        Area [deck length^2].
    """
    volume, length = float(volume), float(length)
    if not (volume > 0.0 and length > 0.0):
        raise JunctureError(f"volume and length must be positive, found {volume}, {length}")
    xi = np.clip(np.asarray(x, dtype=float) / length, 0.0, 1.0)
    s_max = 16.0 * volume / (3.0 * np.pi * length)
    return s_max * (4.0 * xi * (1.0 - xi)) ** 1.5
