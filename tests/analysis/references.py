"""Independent wave-drag references for the analysis tests (numpy only, no juncture code).

* :func:`least_drag_modes`: the Eminton-Lord least-drag sine series through station areas with
  a finite number of modes, solved by ``numpy.linalg.lstsq`` on this module's own basis
  (docs/wavedrag-reference.md: S(theta) = (l/4) sum a_n g_n(theta), D/q = (pi/4) sum n a_n^2).
* :func:`least_drag_limit`: its many-mode limit, extrapolated from 8,000, 16,000 and 32,000
  modes (the truncation error falls as N^-2; the three solves check that rate).
* :func:`kernel_sum`: the kernel ``sum_n g_n(theta) g_n(phi) / n`` and its slope
  ``sum_n sin(n theta) g_n(phi) / n`` summed to many modes.
* :func:`revolution_cuts`: Mach-plane cuts of a body of revolution ``r(x)``, ``0 <= x <= l``,
  semi-analytic: the plane ``x - beta y = X`` (roll angle 0; every angle is alike) meets the
  circle of radius ``r(x)`` at ``x = X + beta y``, so the projected area is
  ``int 2 sqrt(r(X + beta y)^2 - y^2) dy`` over the interval where the root is real, found by
  bisection and integrated by Gauss-Legendre after ``y = a + (b - a)(1 - cos u)/2`` (which
  makes the square-root ends smooth). With ``held=True`` the radius is held at ``r(l)``
  behind the base, as the Harris program holds an open base's area.
"""

import numpy as np


def _basis(theta, n_modes):
    """(m, N) g_n(theta) = sin((n-1) t)/(n-1) - sin((n+1) t)/(n+1), g_1 = t - sin(2 t)/2."""
    n = np.arange(1, n_modes + 1, dtype=float)
    t = np.asarray(theta, float)[:, None]
    lower = np.where(n > 1, np.sin((n - 1) * t) / np.where(n > 1, n - 1, 1.0), t)
    return lower - np.sin((n + 1) * t) / (n + 1)


def _angles(x):
    x = np.asarray(x, float)
    length = x[-1] - x[0]
    theta = np.arccos(np.clip(1.0 - 2.0 * (x[1:] - x[0]) / length, -1.0, 1.0))
    theta[-1] = np.pi
    return theta, length


def least_drag_modes(x, area, n_modes):
    """D/q of the least-drag series of ``n_modes`` modes through ``(x_i, S_i)``, S_0 = 0."""
    theta, length = _angles(x)
    g = _basis(theta, n_modes)
    g[-1, 1:] = 0.0
    w = 1.0 / np.sqrt(np.arange(1, n_modes + 1))
    b = np.linalg.lstsq(g * w, 4.0 * np.asarray(area, float)[1:] / length, rcond=None)[0]
    a = b * w
    return 0.25 * np.pi * float(np.sum(np.arange(1, n_modes + 1) * a * a))


def least_drag_limit(x, area):
    """(limit, observed order) of :func:`least_drag_modes` from 8,000, 16,000, 32,000 modes."""
    d1, d2, d3 = (least_drag_modes(x, area, n) for n in (8000, 16000, 32000))
    order = np.log2((d1 - d2) / (d2 - d3))
    return d3 + (d3 - d2) / (2.0**order - 1.0), order


def kernel_sum(theta, phi, n_modes=200_000, chunk=20_000):
    """(K, J) summed to ``n_modes``: K = sum g_n(t) g_n(p) / n, J = sum sin(n t) g_n(p) / n."""
    theta, phi = np.asarray(theta, float), np.asarray(phi, float)
    k = np.zeros((theta.size, phi.size))
    j = np.zeros_like(k)
    for start in range(1, n_modes + 1, chunk):
        n = np.arange(start, min(start + chunk, n_modes + 1), dtype=float)
        t, p = theta[:, None], phi[:, None]
        gt = np.where(n > 1, np.sin((n - 1) * t) / np.where(n > 1, n - 1, 1.0), t) \
            - np.sin((n + 1) * t) / (n + 1)
        gp = np.where(n > 1, np.sin((n - 1) * p) / np.where(n > 1, n - 1, 1.0), p) \
            - np.sin((n + 1) * p) / (n + 1)
        k += (gt / n) @ gp.T
        j += (np.sin(n * t) / n) @ gp.T
    return k, j


def revolution_cuts(radius, length, beta, x_cut, held=False, n_grid=4001, n_gauss=400):
    """Projected areas of the Mach-plane cuts ``x - beta y = X`` of a body of revolution.

    ``radius(x)`` is vectorised, ``0 <= x <= length``; the body is 0 ahead of the nose and,
    with ``held``, keeps ``radius(length)`` behind the base (else 0).
    """
    r_base = float(radius(np.array([length]))[0]) if held else 0.0

    def r(x):
        inside = np.clip(x, 0.0, length)
        return np.where(x < 0.0, 0.0, np.where(x > length, r_base, radius(inside)))

    x_cut = np.asarray(x_cut, float)[:, None]
    r_max = max(float(radius(np.linspace(0.0, length, 20001)).max()), r_base)

    def f(y):
        return r(x_cut + beta * y) ** 2 - y * y

    ys = np.linspace(-r_max, r_max, n_grid)[None, :]
    pos = f(ys) > 0.0
    out = np.zeros(x_cut.shape[0])
    ok = pos.any(axis=1)
    first = np.argmax(pos, axis=1)
    last = n_grid - 1 - np.argmax(pos[:, ::-1], axis=1)
    # bisection of [ys[first-1], ys[first]] and [ys[last], ys[last+1]] (f changes sign there)
    lo_a, lo_b = ys[0, np.maximum(first - 1, 0)], ys[0, first]
    hi_a, hi_b = ys[0, last], ys[0, np.minimum(last + 1, n_grid - 1)]
    for _ in range(80):
        mid = 0.5 * (lo_a + lo_b)
        inside = f(mid[:, None])[:, 0] > 0.0
        lo_a, lo_b = np.where(inside, lo_a, mid), np.where(inside, mid, lo_b)
        mid = 0.5 * (hi_a + hi_b)
        inside = f(mid[:, None])[:, 0] > 0.0
        hi_a, hi_b = np.where(inside, mid, hi_a), np.where(inside, hi_b, mid)
    a, b = 0.5 * (lo_a + lo_b), 0.5 * (hi_a + hi_b)
    u, w = np.polynomial.legendre.leggauss(n_gauss)
    u, w = 0.5 * np.pi * (u + 1.0), 0.5 * np.pi * w
    y = a[:, None] + (b - a)[:, None] * 0.5 * (1.0 - np.cos(u))
    dy = (b - a)[:, None] * 0.5 * np.sin(u)
    val = 2.0 * np.sqrt(np.maximum(f(y), 0.0))
    out = np.where(ok, np.sum(val * dy * w, axis=1), 0.0)
    return out
