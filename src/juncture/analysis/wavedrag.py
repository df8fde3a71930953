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
``a = W^-1 C^T (C W^-1 C^T)^-1 s``, ``W = diag(n)``, and ``D/q = (pi/4) s^T (C W^-1 C^T)^-1 s``.
By default the problem is solved with infinitely many modes: ``C W^-1 C^T`` is then the
closed-form kernel ``K(theta_i, theta_j) = sum_n g_n(theta_i) g_n(theta_j) / n``
(:mod:`juncture.analysis._kernel`), an ``m x m`` matrix for ``m`` stations, and the result is
the exact least-drag curve through the stations. A finite ``N`` (``n_modes``) converges to it
only as ``1/N^2``: 400 modes leave 5e-4 on a 41-station kinked area curve, 32,000 leave 8e-8.
Interpolating the stations and then expanding does NOT converge (the trap of wavedrag.md):
never do that.

**Far field** (Hayes; Harris, NASA TM X-947): the wave drag of a configuration at Mach ``M`` is
the average over roll angle of the slender-body drag of the equivalent bodies ``S(X, theta)``
cut by Mach planes (see :mod:`juncture.analysis.cuts`). A configuration symmetric about
``y = 0`` has ``S(X, theta) = S(X, pi - theta)``, so half a turn holds every equivalent body:
as the Harris program does, :func:`roll_angles` gives ``NTHETA + 1`` angles over a half turn
with Boole's rule (11.25 deg at NTHETA = 16), and the full turn otherwise.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ..errors import GeometryError, JunctureError, JunctureWarning
from ._kernel import area_kernel, slope_kernel

__all__ = [
    "WaveDragResult",
    "FarFieldResult",
    "eminton_lord",
    "eminton_lord_convergence",
    "von_karman",
    "far_field_drag",
    "roll_angles",
    "sears_haack_drag",
    "sears_haack_area",
]

#: Singular values (finite modes) below this fraction of the largest are dropped.
_RCOND = 1e-13
#: Condition number of the scaled constraint matrix above which a warning is given.
_COND_WARN = 1e10
#: Eigenvalues of the scaled kernel (infinite modes) below this fraction of the largest are
#: dropped: its condition number is the square of the constraint matrix's, and its eigenvalues
#: are resolved down to about 1e-16 of the largest.
_RCOND_GRAM = 1e-15
#: Condition number of the scaled kernel above which a warning is given (the constraint
#: matrix's condition number above 1e6: the drag then loses more than 4 digits).
_COND_WARN_GRAM = 1e12


# --------------------------------------------------------------------------------------------
# Result values


@dataclass(frozen=True, slots=True, eq=False)
class WaveDragResult:
    """Slender-body wave drag of one (equivalent) body and its sine-series area curve.

    Attributes
    ----------
    d_over_q : float
        Wave drag over dynamic pressure, ``(pi/4) sum n a_n^2`` [deck length^2].
    coefficients : (k,) float
        ``a_n``, n = 1..k, of ``S'(x) = sum a_n sin(n theta)`` [deck length]: all of them for a
        finite series, the first ``4 m`` (``m`` stations) of the infinite one (more with
        :meth:`series`).
    n_modes : int or None
        Number of sine modes; None for the infinite series (the exact least-drag curve).
    method : str
        ``"eminton-lord"`` (least drag through stations) or ``"von-karman"`` (exact slope).
    x_nose, length : float
        The body runs from ``x_nose`` to ``x_nose + length`` [deck length].
    condition : float
        Condition number of the scaled constraint matrix (``nan`` for von Karman; for the
        infinite series the square root of the scaled kernel's, estimated from its Cholesky
        pivots unless it is ill-conditioned).
    residual : float
        Largest ``|S_fit(x_i) - S_i|`` over the stations (0 for von Karman) [deck length^2].
    nodes, multipliers : (m,) float or None
        The infinite series' station angles ``theta_i`` [rad] and multipliers ``lambda_i``,
        ``a_n = (1/n) sum_i lambda_i g_n(theta_i)`` [deck length]; None for a finite series.
    """

    d_over_q: float
    coefficients: np.ndarray
    n_modes: int | None
    method: str
    x_nose: float
    length: float
    condition: float = float("nan")
    residual: float = 0.0
    nodes: np.ndarray | None = None
    multipliers: np.ndarray | None = None

    def __post_init__(self):
        for name in ("coefficients", "nodes", "multipliers"):
            if getattr(self, name) is not None:
                a = np.array(getattr(self, name), dtype=float)
                a.flags.writeable = False
                object.__setattr__(self, name, a)

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

    def series(self, n_modes):
        """The first ``n_modes`` coefficients ``a_n`` [deck length].

        Parameters
        ----------
        n_modes : int
            Number of coefficients; at most ``n_modes`` of a finite series.

        Returns
        -------
        (n_modes,) float
        """
        n_modes = int(n_modes)
        if self.nodes is None:
            if not 1 <= n_modes <= self.coefficients.size:
                raise JunctureError(f"n_modes must be in 1..{self.coefficients.size}, found "
                                    f"{n_modes}")
            return self.coefficients[:n_modes].copy()
        if n_modes < 1:
            raise JunctureError(f"n_modes must be at least 1, found {n_modes}")
        return _series(self.nodes, self.multipliers, n_modes)

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
        if self.nodes is not None:
            k = area_kernel(theta[..., None], self.nodes)
            return 0.25 * self.length * (k @ self.multipliers)
        n = self.coefficients.size
        return 0.25 * self.length * (_area_basis(theta.ravel(), n)
                                     @ self.coefficients).reshape(theta.shape)

    def slope(self, x):
        """The fitted slope ``S'(x) = sum a_n sin(n theta)`` (0 outside the body) [deck length]."""
        xa = np.asarray(x, dtype=float)
        theta = _theta_of_x(xa, self.x_nose, self.length)
        if self.nodes is not None:
            out = slope_kernel(theta[..., None], self.nodes) @ self.multipliers
        else:
            n = np.arange(1, self.coefficients.size + 1)
            out = (np.sin(theta.ravel()[:, None] * n) @ self.coefficients).reshape(theta.shape)
        inside = (xa >= self.x_nose) & (xa <= self.x_nose + self.length)
        return np.where(inside, out, 0.0)


@dataclass(frozen=True, slots=True, eq=False)
class FarFieldResult:
    """Far-field (supersonic area rule) wave drag: the roll-angle average of equivalent bodies.

    Attributes
    ----------
    d_over_q : float
        ``sum_k w_k D(theta_k)/q`` [deck length^2].
    thetas : (n_theta,) float
        Roll angles [rad].
    d_over_q_theta : (n_theta,) float
        Slender-body ``D(theta)/q`` of each equivalent body [deck length^2].
    bodies : tuple of WaveDragResult
        The equivalent bodies (``None`` where a cut family has no area).
    weights : (n_theta,) float
        Quadrature weights of the roll-angle average, summing to 1 (:func:`roll_angles`).
    """

    d_over_q: float
    thetas: np.ndarray
    d_over_q_theta: np.ndarray
    bodies: tuple
    weights: np.ndarray | None = None

    def __post_init__(self):
        if self.weights is None:
            object.__setattr__(self, "weights", np.full(len(self.thetas), 1.0 / len(self.thetas)))
        for name in ("thetas", "d_over_q_theta", "weights"):
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


def _series(nodes, multipliers, n_modes):
    """The first ``n_modes`` coefficients ``a_n = (1/n) sum_i lambda_i g_n(theta_i)``."""
    g = _area_basis(nodes, n_modes)
    g[nodes == np.pi, 1:] = 0.0  # sin(k pi) = 0 exactly at the base
    return (multipliers @ g) / np.arange(1, n_modes + 1)


def _cholesky_solve(low, b):
    """``x`` with ``low low^T x = b`` by forward and back substitution.

    Vector products only: with OpenBLAS threads on a loaded two-core machine a 100 x 100
    ``numpy.linalg.solve`` was measured at 0.2 s (and ``eigh`` at 35 ms), this at 0.3 ms.
    """
    n = b.size
    y = np.empty(n)
    for i in range(n):
        y[i] = (b[i] - low[i, :i] @ y[:i]) / low[i, i]
    x = np.empty(n)
    for i in range(n - 1, -1, -1):
        x[i] = (y[i] - low[i + 1:, i] @ x[i + 1:]) / low[i, i]
    return x


def _solve_gram(gram, rhs):
    """``lambda`` with ``gram lambda = rhs`` (symmetric positive semi-definite) and the
    condition number of the diagonally scaled ``gram``.

    A Cholesky factorisation (single-threaded at this size) whose pivots estimate the
    condition number, ``(max / min pivot)^2``; if it fails or that estimate exceeds
    ``_COND_WARN_GRAM``, the eigenvalues: the condition number, and the minimum-norm solution
    with the eigenvalues below ``_RCOND_GRAM`` of the largest dropped.
    """
    scale = np.sqrt(np.diag(gram))
    kn = gram / scale[:, None] / scale[None, :]
    try:
        low = np.linalg.cholesky(kn)
        piv = np.diag(low)
        cond = float((piv.max() / piv.min()) ** 2)
    except np.linalg.LinAlgError:
        cond = float("inf")
    if cond <= _COND_WARN_GRAM:
        return _cholesky_solve(low, rhs / scale) / scale, cond, 0
    w, v = np.linalg.eigh(kn)
    keep = w > _RCOND_GRAM * w[-1]
    mu = v[:, keep] @ ((v[:, keep].T @ (rhs / scale)) / w[keep])
    cond = float(w[-1] / w[0]) if w[0] > 0.0 else float("inf")
    return mu / scale, cond, int(np.sum(~keep))


def _warn_conditioning(cond, dropped, total):
    warnings.warn(f"Eminton-Lord constraint matrix is ill-conditioned (condition {cond:.3g}, "
                  f"{dropped} of {total} singular values dropped): stations too close "
                  f"together?", JunctureWarning, stacklevel=3)


def _eminton_lord_modes(theta, rhs, n_modes):
    """Finite series: minimum-norm solution of ``(C W^-1/2) b = rhs`` by an SVD."""
    g = _area_basis(theta, n_modes)
    g[-1, 1:] = 0.0  # sin(k pi) = 0 exactly at the base
    w = 1.0 / np.sqrt(np.arange(1, n_modes + 1, dtype=float))
    amat = g * w  # columns scaled by W^-1/2
    rownorm = np.linalg.norm(amat, axis=1)
    amat = amat / rownorm[:, None]
    u, sig, vt = np.linalg.svd(amat, full_matrices=False)
    cond = float(sig[0] / sig[-1]) if sig[-1] > 0 else float("inf")
    keep = sig > _RCOND * sig[0]
    if cond > _COND_WARN:
        _warn_conditioning(cond, int(np.sum(~keep)), sig.size)
    a = (vt[keep].T @ ((u[:, keep].T @ (rhs / rownorm)) / sig[keep])) * w
    return a, cond, float(np.max(np.abs(g @ a - rhs)))


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
        Number of sine modes ``N`` (>= m - 1). Default: infinitely many, i.e. the exact
        least-drag curve through the stations, from the closed-form kernel (see the module
        notes). A finite ``N`` gives the truncated problem (:func:`eminton_lord_convergence`),
        whose drag decreases monotonically towards the exact one as ``1/N^2``.

    Returns
    -------
    WaveDragResult
        ``d_over_q`` [deck length^2], the coefficients ``a_n`` and ``area(x)``, ``slope(x)``
        of the fit.

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
    With infinitely many modes, ``lambda = K^-1 (4 s / l)`` (``K`` the kernel at the stations),
    ``D/q = (pi/4) lambda^T K lambda``, and ``S(x) = (l/4) sum_i lambda_i K(theta(x), theta_i)``.

    Examples
    --------
    Two stations (nose and base) give the von Karman ogive, ``D/q = 4 S_b^2 / (pi l^2)``:

    >>> r = eminton_lord([0.0, 2.0], [0.0, 1.0])
    >>> round(r.d_over_q * np.pi, 12)
    1.0
    """
    x, area = _check_stations(x, area)
    if n_modes is None:
        return exact_fit(x, area)
    m = x.size - 1  # constrained stations
    x_nose, length = float(x[0]), float(x[-1] - x[0])
    n_modes = int(n_modes)
    if n_modes < m:
        raise JunctureError(f"n_modes must be at least the number of stations after the "
                            f"nose ({m}), found {n_modes}")
    theta, rhs = _constraints(x, area)
    a, cond, resid = _eminton_lord_modes(theta, rhs, n_modes)
    return WaveDragResult(d_over_q=_drag(a), coefficients=a, n_modes=n_modes,
                          method="eminton-lord", x_nose=x_nose, length=length,
                          condition=cond, residual=0.25 * length * resid)


def _constraints(x, area):
    """Station angles (the base at pi) and right-hand sides ``g a = 4 S_i / l`` of the
    stations after the nose."""
    length = float(x[-1] - x[0])
    theta = _theta_of_x(x[1:], float(x[0]), length)
    theta[-1] = np.pi
    return theta, 4.0 * area[1:] / length  # S_i = (l/4) g a


def exact_fit(x, area):
    """The infinite-series Eminton-Lord fit through station areas (``area[0]`` taken as 0),
    from the closed-form kernel: :func:`eminton_lord` without its checks on the areas (a body
    segment's areas less its first may be negative)."""
    x_nose, length = float(x[0]), float(x[-1] - x[0])
    theta, rhs = _constraints(x, area)
    m = theta.size
    gram = area_kernel(theta[:, None], theta[None, :])
    gram = 0.5 * (gram + gram.T)
    lam, cond, dropped = _solve_gram(gram, rhs)
    if cond > _COND_WARN_GRAM:
        _warn_conditioning(np.sqrt(cond), dropped, m)
    k_lam = gram @ lam
    return WaveDragResult(d_over_q=0.25 * np.pi * float(lam @ k_lam),
                          coefficients=_series(theta, lam, 4 * m), n_modes=None,
                          method="eminton-lord", x_nose=x_nose, length=length,
                          condition=float(np.sqrt(cond)),
                          residual=0.25 * length * float(np.max(np.abs(k_lam - rhs))),
                          nodes=theta, multipliers=lam)


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


def roll_angles(n_theta, half_turn=False):
    """Roll angles of the far-field average and their quadrature weights.

    Parameters
    ----------
    n_theta : int
        Full turn: the number of angles. Half turn: the number of intervals (the Harris
        program's NTHETA), i.e. ``n_theta + 1`` angles.
    half_turn : bool
        False: ``theta_k = 2 pi k / n_theta`` with equal weights (the trapezoid rule of a
        periodic integrand, exact for trigonometric polynomials of degree below ``n_theta``).
        True: ``theta_k = -pi/2 + pi k / n_theta`` from below to above through starboard, with
        composite Boole's rule as the Harris program uses (``n_theta`` a multiple of 4; else
        Simpson's rule for an even ``n_theta``, the trapezoid rule for an odd one). Only for a
        configuration symmetric about y = 0, where ``D(theta) = D(pi - theta)``.

    Returns
    -------
    thetas : (n,) float
        Angles, theta = 0 towards +y and pi/2 towards +z [rad].
    weights : (n,) float
        Weights summing to 1: ``D/q = sum_k weights_k D(theta_k)/q``.

    Raises
    ------
    JunctureError
        ``n_theta`` < 1.

    Examples
    --------
    >>> th, w = roll_angles(4, half_turn=True)
    >>> np.degrees(th).round(6).tolist(), (w * 90).round(6).tolist()
    ([-90.0, -45.0, 0.0, 45.0, 90.0], [7.0, 32.0, 12.0, 32.0, 7.0])
    """
    n = int(n_theta)
    if n < 1:
        raise JunctureError(f"n_theta must be at least 1, found {n_theta}")
    if not half_turn:
        return 2.0 * np.pi * np.arange(n) / n, np.full(n, 1.0 / n)
    thetas = -0.5 * np.pi + np.pi * np.arange(n + 1) / n
    if n % 4 == 0:
        panel = np.array([7.0, 32.0, 12.0, 32.0, 7.0])
    elif n % 2 == 0:
        panel = np.array([1.0, 4.0, 1.0])
    else:
        panel = np.array([1.0, 1.0])
    k = panel.size - 1
    w = np.zeros(n + 1)
    for start in range(0, n, k):
        w[start:start + k + 1] += panel
    return thetas, w / w.sum()


def _rule_name(n_theta, half_turn):
    if not half_turn:
        return "trapezoid"
    return "Boole" if n_theta % 4 == 0 else ("Simpson" if n_theta % 2 == 0 else "trapezoid")


def far_field_drag(cut_areas, x_cut, thetas, n_modes=None, trim=True, weights=None):
    """Far-field wave drag: the average over roll angle of the equivalent bodies' drag.

    Parameters
    ----------
    cut_areas : (n_theta, n_x) float
        ``S(X, theta)``, Mach-plane cut areas projected onto the x-normal plane
        (:func:`juncture.analysis.cuts.mach_plane_areas`) [deck length^2].
    x_cut : (n_x,) or (n_theta, n_x) float
        The cut offsets ``X``, strictly increasing (per angle if 2-D) [deck length].
    thetas : (n_theta,) float
        Roll angles [rad]. Without ``weights`` they must be equally spaced over a full turn
        (``theta_k = theta_0 + 2 pi k / n``).
    n_modes : int, optional
        Modes per equivalent body (default: infinitely many, see :func:`eminton_lord`).
    trim : bool, optional
        Drop the zero areas ahead of each equivalent body's first nonzero area and behind its
        last one (keeping one zero station at each end), so that each equivalent body's length
        is its own. Default True.
    weights : (n_theta,) float, optional
        Quadrature weights summing to 1 (:func:`roll_angles`); default equal weights.

    Returns
    -------
    FarFieldResult
        ``d_over_q = sum_k w_k D(theta_k)/q``.

    Raises
    ------
    JunctureError
        Shapes that do not match, angles not equally spaced over a full turn (without
        ``weights``), or weights that do not sum to 1.

    Notes
    -----
    Harris (TM X-947): ``D/q = (1/2 pi) int_0^{2 pi} D(theta)/q d theta``. ``D(theta)`` is
    2 pi periodic, and the mean over equally spaced angles is the trapezoid rule for a
    periodic integrand, which is exact for trigonometric polynomials of degree below
    ``n_theta``. An equivalent body with no area at all has zero drag. The nose and base of
    each equivalent body are located to within one spacing of ``x_cut``; pass per-angle
    offsets spanning each body's own extent (:func:`juncture.analysis.cuts.mach_plane_extents`)
    for the best resolution. The last area of an equivalent body is its base area (an area
    held behind an open base, :func:`juncture.analysis.machplanes.mach_plane_area_distribution`).
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
    if weights is None:
        step = 2.0 * np.pi / nt
        dev = np.angle(np.exp(1j * (thetas - thetas[0] - step * np.arange(nt))))
        if np.any(np.abs(dev) > 1e-9):
            raise JunctureError(f"thetas must be {nt} angles equally spaced over a full turn "
                                f"(step {step:.6g} rad), or come with weights (roll_angles); "
                                f"found {np.array2string(thetas, precision=4)}")
        weights = np.full(nt, 1.0 / nt)
    weights = np.asarray(weights, dtype=float)
    if weights.shape != (nt,) or not np.all(np.isfinite(weights)) \
            or abs(float(weights.sum()) - 1.0) > 1e-9:
        raise JunctureError(f"weights must be {nt} finite numbers summing to 1, found "
                            f"{np.array2string(weights, precision=4)}")
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
    return FarFieldResult(d_over_q=float(weights @ d), thetas=thetas, d_over_q_theta=d,
                          bodies=tuple(bodies), weights=weights)


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
