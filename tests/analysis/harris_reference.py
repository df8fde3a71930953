"""An independent implementation of the Harris program's far-field conventions (tests only).

It shares no cutting, meshing or drag code with :mod:`juncture.analysis`. It reads the
components' deck arrays and evaluates the Mach-plane cut areas its own way:

* a wing-like component's sections are polygons through the given ordinates (straight lines
  between chordwise stations, as the Harris program draws them), blended linearly in span;
  at each span station the plane crosses the closed section polygon, and the projected cut
  area is the integral over span of the thickness between the crossings (exact per station;
  Gauss-Legendre in span, many points per panel);
* a circular body's projected cut area is the area of the points (y, z) whose point on the
  plane, x = X + beta (y cos t + z sin t), lies inside the body (r(x) from the model's radius,
  tabulated finely), by the midpoint rule on a fine grid over the body's y-z extent; an open
  base is held (the last radius continues behind the base) and a nacelle with an open front
  loses its inlet's streamtube (a cylinder of the inlet radius over the nacelle's length,
  subtracted, as juncture documents it);
* component areas are summed (no union), the equivalent body of each roll angle spans the
  first to the last plane that touches the configuration (from dense surface samples), and
  its drag is the least-norm (Eminton-Lord) sine series with many modes, solved by numpy;
* roll angles: NTHETA + 1 over a half turn (-90 to 90 deg from the horizontal; the plane of
  symmetry maps theta to 180 deg - theta), weighted by composite Boole's rule.
"""

from __future__ import annotations

import numpy as np

from juncture.model import CircularBody, WingLike


def _boole_weights(n):
    """Composite Boole weights on [0, pi] with n intervals (n a multiple of 4), summing to 1."""
    w = np.zeros(n + 1)
    for k in range(0, n, 4):
        w[k:k + 5] += np.array([7.0, 32.0, 12.0, 32.0, 7.0])
    return w / w.sum()


def _section_polygons(wing):
    """(n_sections, m, 2): each section's closed polygon in (chord axis x, thickness axis)."""
    t = wing.thickness_axis
    x = wing.le[:, 0:1] + wing.chord[:, None] * wing.x_over_c[None, :] / 100.0
    base = wing.le[:, t:t + 1] + wing.camber
    half = wing.chord[:, None] / 100.0
    upper = np.stack([x, base + wing.upper * half], -1)
    lower = np.stack([x, base - wing.lower * half], -1)
    return np.concatenate([upper, lower[:, ::-1]], axis=1)  # LE -> TE on top, back below


def _wing_sections(wing, per_panel):
    """Span stations (Gauss points in each panel), their weights and section polygons."""
    s = wing.le[:, wing.span_axis]
    polys = _section_polygons(wing)
    g, gw = np.polynomial.legendre.leggauss(per_panel)
    spans, weights, shapes = [], [], []
    for k in range(len(s) - 1):
        a, b = s[k], s[k + 1]
        f = 0.5 * (g + 1.0)
        spans.append(a + f * (b - a))
        weights.append(0.5 * gw * (b - a))
        shapes.append(polys[k][None] * (1 - f)[:, None, None] + polys[k + 1][None] * f[:, None,
                                                                                        None])
    return np.concatenate(spans), np.concatenate(weights), np.concatenate(shapes)


def _wing_cut(span, weight, poly, axis, mirror, beta, theta, offsets):
    """Projected cut areas (n_offsets,) of one wing copy."""
    # position on the plane normal: x - beta (y cos t + z sin t)
    c, s = np.cos(theta), np.sin(theta)
    x, t = poly[..., 0], poly[..., 1]
    if axis == 1:  # sections at constant y: thickness along z
        y = mirror * span[:, None]
        h = x - beta * (y * c + t * s)
    else:  # constant z: thickness along y
        h = x - beta * (mirror * t * c + span[:, None] * s)
    h0, h1 = h, np.roll(h, -1, axis=1)
    t0, t1 = t, np.roll(t, -1, axis=1)
    out = np.zeros(len(offsets))
    for i, X in enumerate(offsets):
        d0, d1 = h0 - X, h1 - X
        cross = (d0 >= 0) != (d1 >= 0)
        with np.errstate(invalid="ignore", divide="ignore"):
            tc = np.where(cross, t0 + (t1 - t0) * d0 / (d0 - d1), np.nan)
        tc = np.sort(tc, axis=1)  # crossings per station, NaN last
        n = cross.sum(axis=1)
        thick = np.zeros(len(span))
        for j in range(0, tc.shape[1] - 1, 2):
            pair = n > j + 1
            thick[pair] += tc[pair, j + 1] - tc[pair, j]
        out[i] = np.sum(weight * thick)
    return out


def _series_basis(th, n_modes):
    """(k, n_modes): the coefficient of a_n in S(theta) / (l/4)."""
    n = np.arange(2, n_modes + 1)
    return np.concatenate([(th - np.sin(2 * th) / 2)[:, None],
                           np.sin(np.outer(th, n - 1)) / (n - 1)
                           - np.sin(np.outer(th, n + 1)) / (n + 1)], axis=1)


def least_drag_curve(x, area, xq, n_modes=3000):
    """Area at xq of the least-drag series through (x, area) started at area[0] (numpy)."""
    length = x[-1] - x[0]
    th = np.arccos(np.clip(1.0 - 2.0 * (x[1:] - x[0]) / length, -1, 1))
    c = _series_basis(th, n_modes) * length / 4
    cw = c / np.arange(1, n_modes + 1)
    a = cw.T @ np.linalg.solve(cw @ c.T, area[1:] - area[0])
    thq = np.arccos(np.clip(1.0 - 2.0 * (xq - x[0]) / length, -1, 1))
    return area[0] + (length / 4) * (_series_basis(thq, n_modes) @ a)


_FITTED = {}


def _fitted_radius(body, xt):
    """The fuselage radius at xt from each segment's own least-drag area curve (a gap between
    segments: the radius linear from one segment's last station to the next one's first)."""
    key = (id(body), xt.size, float(xt[0]), float(xt[-1]))
    if key not in _FITTED:
        if len(_FITTED) > 8:
            _FITTED.clear()
        _FITTED[key] = (body, _fit_radius(body, xt))  # the body held: its id stays unique
    return _FITTED[key][1]


def _fit_radius(body, xt):
    xg, start = body.x_global, 0
    r = np.interp(xt, xg, body.radius)  # in gaps; overwritten within segments
    for count in body.segments:
        xs, rs = xg[start:start + count], body.radius[start:start + count]
        start += count
        on = (xt >= xs[0]) & (xt <= xs[-1])
        xf = np.linspace(xs[0], xs[-1], 2001)  # tabulated, then interpolated
        sf = least_drag_curve(xs, np.pi * rs**2, xf)
        r[on] = np.sqrt(np.maximum(np.interp(xt[on], xf, sf), 0) / np.pi)
    return r


def _body_cut(body, mirror, beta, theta, offsets, n_grid, held, tube, fit):
    """Projected cut areas of one circular body copy (membership on a y-z grid)."""
    x0, x1 = body.x_global[0], body.x_global[-1]
    xt = np.linspace(x0, x1, 40001)
    r = _fitted_radius(body, xt) if fit else body.radius_at(xt)
    zc = body.center_at(xt)[:, 1]
    yc = mirror * body.origin[1]
    reach = r.max()
    zmid, zspan = 0.5 * (zc.max() + zc.min()), 0.5 * np.ptp(zc)
    ny = n_grid
    ys = yc + np.linspace(-reach, reach, ny + 1)
    ys = 0.5 * (ys[1:] + ys[:-1])
    half_z = reach + zspan
    nz = int(np.ceil(ny * half_z / reach))
    zs = zmid + np.linspace(-half_z, half_z, nz + 1)
    zs = 0.5 * (zs[1:] + zs[:-1])
    cell = (2 * reach / ny) * (2 * half_z / nz)
    Y, Z = np.meshgrid(ys, zs, indexing="ij")
    lift = beta * (Y * np.cos(theta) + Z * np.sin(theta))
    out = np.zeros(len(offsets))
    for i, X in enumerate(offsets):
        h = X + lift
        rad = np.interp(h, xt, r)
        cz = np.interp(h, xt, zc)
        rho = np.hypot(Y - yc, Z - cz)
        inside = (h >= x0) & (h <= x1) & (rho <= rad)
        if held:
            inside |= (h > x1) & (np.hypot(Y - yc, Z - zc[-1]) <= r[-1])
        count = inside.sum()
        if tube:  # the inlet's streamtube over the nacelle's length is subtracted
            count -= ((h >= x0) & (h <= x1) & (np.hypot(Y - yc, Z - cz) <= r[0])).sum()
        out[i] = count * cell
    return out


def _extent(cfg, beta, theta, fusard_fit=False):
    """First and last plane offset touching the configuration (dense surface samples)."""
    lo, hi = np.inf, -np.inf
    c, s = np.cos(theta), np.sin(theta)
    for comp in cfg:
        pts = np.concatenate([n.reshape(-1, 3) for n in comp.networks().values()])
        if isinstance(comp, CircularBody):
            ph = np.linspace(0, 2 * np.pi, 721)
            xs = np.linspace(*comp.x_global[[0, -1]], 2001)
            cen, rad = comp.section_at(xs)
            if fusard_fit and not comp.name.startswith("pod"):
                rad = _fitted_radius(comp, xs)
            pts = np.stack([np.repeat(xs, ph.size), np.repeat(cen[:, 0], ph.size)
                            + np.outer(rad, np.cos(ph)).ravel(),
                            np.repeat(cen[:, 1], ph.size) + np.outer(rad, np.sin(ph)).ravel()],
                           -1)
        for m in ((1.0, -1.0) if comp.mirrored else (1.0,)):
            h = pts[:, 0] - beta * (m * pts[:, 1] * c + pts[:, 2] * s)
            lo, hi = min(lo, h.min()), max(hi, h.max())
    return lo, hi


def least_drag(x, area, n_modes=3000):
    """Eminton-Lord: the least (pi/4) sum n a_n^2 whose S(theta) passes through the areas."""
    length = x[-1] - x[0]
    th = np.arccos(1.0 - 2.0 * (x - x[0]) / length)
    n = np.arange(1, n_modes + 1)
    # S(theta) = (l/4) [a_1 (th - sin 2th / 2) + sum_{n>=2} a_n (sin((n-1)th)/(n-1)
    #                                                      - sin((n+1)th)/(n+1))]
    c = np.empty((th.size, n_modes))
    c[:, 0] = th - np.sin(2 * th) / 2
    nn = n[1:]
    c[:, 1:] = (np.sin(np.outer(th, nn - 1)) / (nn - 1) - np.sin(np.outer(th, nn + 1)) / (nn + 1))
    c *= length / 4
    keep = th > 0  # S(0) = 0 holds for every series
    cw = c[keep] / n  # columns scaled by W^-1 (W = diag n)
    lam = np.linalg.solve(cw @ c[keep].T, area[keep])
    a = cw.T @ lam
    return np.pi / 4 * np.sum(n * a * a)


def harris_far_field(cfg, mach, n_x, n_theta, wing_points=64, n_grid=300, fusard_fit=True):
    """D/q of a deck's configuration with the Harris conventions, computed independently.

    ``fusard_fit``: a circular body other than a pod has, within each segment, the least-drag
    area curve through its given areas (a finite series of 3000 modes solved by numpy)."""
    beta = np.sqrt(mach * mach - 1.0)
    thetas = np.linspace(-0.5 * np.pi, 0.5 * np.pi, n_theta + 1)  # a half turn: y-symmetric
    weights = _boole_weights(n_theta)
    drags = []
    for theta in thetas:
        lo, hi = _extent(cfg, beta, theta, fusard_fit)
        offsets = np.linspace(lo, hi, n_x)
        area = np.zeros(n_x)
        for comp in cfg:
            for m in ((1.0, -1.0) if comp.mirrored else (1.0,)):
                if isinstance(comp, WingLike):
                    span, w, poly = _wing_sections(comp, wing_points)
                    area += _wing_cut(span, w, poly, comp.span_axis, m, beta, theta, offsets)
                elif isinstance(comp, CircularBody):
                    pod = comp.mirrored or comp.origin[1] != 0.0
                    tube = pod and comp.radius[0] > 0.0
                    held = comp.radius[-1] > 0.0 and not tube
                    fit = fusard_fit and not comp.name.startswith("pod")
                    area += _body_cut(comp, m, beta, theta, offsets, n_grid, held, tube, fit)
                else:
                    raise NotImplementedError("arbitrary bodies are not in the reference")
        drags.append(least_drag(offsets, area))
    return float(np.dot(weights, drags)), np.array(drags)
