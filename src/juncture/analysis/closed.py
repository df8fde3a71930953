"""Closed, outward-oriented, densely resampled networks of a whole configuration, for cuts.

:func:`juncture.analysis.cuts.mach_plane_areas` needs solids: networks that close, with
normals ``cross(P[i, j+1] - P[i, j], P[i+1, j] - P[i, j])`` pointing out. The deck's own
networks do not close (a wing root buried in the fuselage, open pod ends), and cutting a
wing root that lies inside the body would count that part twice. This module builds, from
the component model, one closed solid per component copy (both halves of the airplane):

* a **body** (fuselage, pod): cross-sections at many stations (every input station, plus
  cosine-spaced ones in each segment), all the way round; a step between segments becomes a
  flat annulus; a nonzero nose or base radius is closed by a flat disc. Each polygon's radius
  is scaled by ``sqrt(2 pi / (n sin(2 pi / n)))`` so that the n-gon has the circle's area
  exactly: a cut at a station, or an oblique cut of a cylindrical part, then has the exact
  area ``pi r^2`` instead of the polygon's (a relative loss of ``(2 pi / n)^2 / 6``).
* a **wing-like component**: its upper and lower surfaces at chord fractions that are the
  airfoil stations plus a cosine spacing, and span rows that are the sections plus an even
  subdivision, TRIMMED at the bodies: each lofting line (of a copy of the component holding
  the dense chord fractions, evaluated on the model's own surface) is cut with every body by
  :func:`juncture.intersect.intersect_body`, and the surface network starts at the
  outermost crossing (rows inboard of it collapse onto the intersection line). A root cap
  closes the solid between the upper and lower intersection lines ON the body surface
  (points at interpolated body angles), so body and exposed wing share that face and the
  buried root counts once; a root left outside every body is closed by a flat section, and a
  tip with a chord by a flat tip face; a blunt trailing edge by a strip.

A component with an image at -y gets one, named ``"<network> image"``, with its n-lines
reversed (keeping the normals outward), as :meth:`Geometry.mirrored_networks` does.

Resampling accuracy (measured on the bundled transport against
:func:`juncture.analysis.areas.normal_area_distribution`, the model's exact normal areas):
with the defaults (about 110,000 triangles) the cut areas at M = 1 agree to within 0.1 % of
the largest area (0.32 ft^2 of 425 ft^2; 0.86 of 1112 on the PDAS wing-body). The error is
dominated by the chordwise faceting (``n_chord``: 0.57 ft^2 with 33 fractions, 0.28 with 49,
0.32 with 65 on the wing alone), then the body's stations (``n_body``).
"""

from __future__ import annotations

import numpy as np

from ..errors import GeometryError
from ..intersect import intersect_body, polyline_points
from ..model import ArbitraryBody, CircularBody, WingLike
from ._components import body_box, boxes_overlap, held_bases, is_flow_through, wing_box

__all__ = ["is_flow_through", "capture_tube", "closed_networks", "body_solid",
           "winglike_solid", "held_base_solids", "oriented", "by_copy"]


def oriented(net, direction):
    """``net`` with its n-lines reversed if its area-weighted mean normal opposes ``direction``.

    Parameters
    ----------
    net : (n_lines, n_points, 3) float
    direction : (3,) float
        The outward direction the network should face on the whole (e.g. +z for an upper
        surface).

    Returns
    -------
    (n_lines, n_points, 3) float
    """
    p = np.asarray(net, dtype=float)
    if p.shape[0] < 2 or p.shape[1] < 2:
        return p
    d1 = p[1:, 1:] - p[:-1, :-1]
    d2 = p[:-1, 1:] - p[1:, :-1]
    mean = np.cross(d2, d1).sum(axis=(0, 1))  # twice the vector area, outward convention
    return p[::-1] if float(mean @ np.asarray(direction, float)) < 0.0 else p


def by_copy(cfg, networks):
    """:func:`closed_networks`' networks grouped by component copy.

    Returns
    -------
    dict of (str, bool) to list of (str, (n, m, 3) float)
        ``(component name, is the mirror image)`` -> its networks, in order.
    """
    names = sorted(cfg.components, key=len, reverse=True)
    groups = {}
    for name, net in networks.items():
        base = name.removesuffix(" image")
        comp = next(c for c in names if base == c or base.startswith(c + " "))
        groups.setdefault((comp, name.endswith(" image")), []).append(
            (name, np.asarray(net, float)))
    return groups


def _mirror(net):
    """Mirror image in y, transposed: outward again, and with the same quad diagonals.

    (Reversing the n-lines, as :meth:`Geometry.mirrored_networks` does, also keeps the
    normals outward but splits every quad along its other diagonal, so a cut of the image
    differs from the mirrored cut by the faceting error; transposing keeps it exact.)
    """
    out = np.array(net, dtype=float, copy=True)
    out[..., 1] *= -1.0
    return np.ascontiguousarray(np.swapaxes(out, 0, 1))


# --------------------------------------------------------------------------------------------
# Bodies


def _segment_stations(x, n):
    """Input stations of one segment plus ``n`` cosine-spaced ones, sorted and unique."""
    t = 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, max(int(n), 2))))
    return np.unique(np.concatenate([x, x[0] + (x[-1] - x[0]) * t]))


def _equal_area_factor(n_sides):
    return np.sqrt(2.0 * np.pi / (n_sides * np.sin(2.0 * np.pi / n_sides)))


def body_solid(body, n_theta=48, n_body=121, equal_area=True):
    """Closed networks of one body (both halves of a centre-line body, all round a pod).

    Parameters
    ----------
    body : CircularBody or ArbitraryBody
    n_theta : int
        Polygon sides of each cross-section (an arbitrary section: points per half).
    n_body : int
        Cosine-spaced stations added over the whole length (shared among the segments by
        length), besides every input station.
    equal_area : bool
        Scale a circular section's polygon to the circle's area (for cuts); False: its
        corners on the circle (the surface itself, for CAD faces).

    Returns
    -------
    dict of str to (n_lines, n_points, 3) float
        ``"<name>"`` (the side surface), and ``"<name> nose"`` / ``"<name> base"`` discs
        where the end radius is not zero.
    """
    if not isinstance(body, (CircularBody, ArbitraryBody)):
        raise GeometryError(f"expected a body, found a {type(body).__name__}")
    n_theta = int(n_theta)
    if n_theta < 3:
        raise GeometryError(f"n_theta must be at least 3, found {n_theta}", body.name)
    xg = body.x_global
    length = max(body.length, np.finfo(float).tiny)
    rings, start = [], 0
    for s in body.segments:
        xs = xg[start:start + s]
        start += s
        share = int(np.ceil(n_body * (xs[-1] - xs[0]) / length)) + 1
        xq = _segment_stations(xs, share)
        # Evaluate the segment's own interpolant up to its end (the next segment starts at
        # the joint station itself): the last station a hair inside.
        xe = xq.copy()
        xe[-1] = np.nextafter(xq[-1], -np.inf) if xq.size > 1 else xq[-1]
        rings.append(_rings(body, xq, xe, n_theta, equal_area))
    side = np.concatenate(rings, axis=0)
    out = {body.name: side}
    for end, idx, direction in (("nose", 0, -1.0), ("base", -1, 1.0)):
        ring = side[idx]
        centre = np.broadcast_to(ring.mean(axis=0) if isinstance(body, ArbitraryBody)
                                 else _centre(body, ring[0, 0]), ring.shape)
        if np.ptp(ring[:, 1:], axis=0).max() > 0.0:
            out[f"{body.name} {end}"] = oriented(np.stack([ring, centre]), [direction, 0, 0])
    return out


def _centre(body, x):
    c = body.center_at(np.array([x]))[0]
    return np.array([x, c[0], c[1]])


def _rings(body, xq, xe, n_theta, equal_area=True):
    """(n_x, n_points, 3) closed cross-section polygons, counter-clockwise seen from ahead."""
    if isinstance(body, CircularBody):
        theta = np.linspace(-0.5 * np.pi, 1.5 * np.pi, n_theta + 1)
        r = body.radius_at(xe) * (_equal_area_factor(n_theta) if equal_area else 1.0)
        c = body.center_at(xe)
        return np.stack(np.broadcast_arrays(
            xq[:, None], c[:, 0, None] + r[:, None] * np.cos(theta),
            c[:, 1, None] + r[:, None] * np.sin(theta)), axis=-1)
    s = np.linspace(0.0, 1.0, n_theta)
    half = body.point(xe[:, None], s[None, :])  # bottom to top on the +y side
    half[..., 0] = xq[:, None]
    other = half[:, ::-1].copy()
    other[..., 1] *= -1.0
    return np.concatenate([half, other[:, 1:], half[:, :1]], axis=1)


# --------------------------------------------------------------------------------------------
# Wing-like components


def _dense_copy(wing, fractions):
    """A WingLike on the model's own surface at the given chord fractions (linear between)."""
    st = wing.span_stations
    up = wing.point(st[:, None], fractions[None, :], "upper")[..., wing.thickness_axis]
    lo = wing.point(st[:, None], fractions[None, :], "lower")[..., wing.thickness_axis]
    base = wing.le[:, wing.thickness_axis, None]
    camber = 0.5 * (up + lo) - base
    c = wing.chord[:, None]
    with np.errstate(divide="ignore", invalid="ignore"):
        half = np.where(c > 0.0, 50.0 * (up - lo) / np.where(c > 0.0, c, 1.0), 0.0)
    return WingLike(wing.name, wing.kind, wing.le, wing.chord, 100.0 * fractions,
                    np.maximum(half, 0.0), np.maximum(half, 0.0), camber, wing.mirrored,
                    "linear")


def _span_grid(st, n_span):
    """Section coordinates u: every section plus an even subdivision (~n_span rows)."""
    lengths = np.abs(np.diff(st))
    per = np.maximum(1, np.round(n_span * lengths / max(lengths.sum(), 1e-300))).astype(int)
    return np.unique(np.concatenate([k + np.arange(m) / m for k, m in enumerate(per)]
                                    + [[st.size - 1.0]]))


def _entries(dense, bodies, side):
    """Per lofting line: section coordinate where it enters a body (>= 0) and that body."""
    n = dense.n_stations
    u = np.zeros(n)
    which = np.full(n, -1)
    theta = np.full(n, np.nan)
    for b, body in enumerate(bodies):
        cut = intersect_body(dense, body, side)
        ok = cut.found & (cut.u > u)
        u = np.where(ok, cut.u, u)
        which = np.where(ok, b, which)
        theta = np.where(ok, cut.theta, theta)
    return u, which, theta


def winglike_solid(wing, bodies=(), n_chord=49, n_span=25, n_cap=5):
    """Closed networks of one wing-like component (one copy), trimmed at the bodies.

    Parameters
    ----------
    wing : WingLike
    bodies : sequence of CircularBody or ArbitraryBody
        Bodies the component may enter.
    n_chord : int
        Cosine-spaced chord fractions (besides the airfoil stations).
    n_span : int
        Span rows (besides the sections), shared among the segments by span.
    n_cap : int
        Rows of the root cap from the upper to the lower intersection line.

    Returns
    -------
    dict of str to (n_lines, n_points, 3) float
        ``"<name> upper"``, ``"<name> lower"`` (``outboard``/``inboard`` for fins),
        ``"<name> root"``, and where needed ``"<name> tip"``, ``"<name> trailing edge"``,
        ``"<name> leading edge"``.
    """
    if not isinstance(wing, WingLike):
        raise GeometryError(f"expected a WingLike, found a {type(wing).__name__}")
    f = np.unique(np.concatenate([wing.x_over_c / 100.0, 0.5 * (1.0 - np.cos(
        np.linspace(0.0, np.pi, max(int(n_chord), 2))))]))
    dense = _dense_copy(wing, f)
    box = wing_box(wing)
    near = [b for b in bodies if boxes_overlap(box, body_box(b))]
    grid = _span_grid(wing.span_stations, int(n_span))
    e_span, e_thick = np.eye(3)[wing.span_axis], np.eye(3)[wing.thickness_axis]
    names = ("upper", "lower") if wing.span_axis == 1 else ("outboard", "inboard")
    surf, start = {}, {}
    for side in ("upper", "lower"):
        u0, which, theta = _entries(dense, near, side)
        rows = grid[grid > u0.min()]
        u = np.concatenate([u0[None, :], np.maximum(rows[:, None], u0[None, :])])
        pts = np.swapaxes(polyline_points(dense.lofting_lines(side), u.T), 0, 1)
        surf[side] = pts
        start[side] = (u0, which, theta)
    out = {f"{wing.name} {names[0]}": oriented(surf["upper"], e_thick),
           f"{wing.name} {names[1]}": oriented(surf["lower"], -e_thick)}
    out[f"{wing.name} root"] = oriented(_root_cap(surf, start, near, n_cap), -e_span)
    tip = np.stack([surf["upper"][-1], surf["lower"][-1]])
    tol = 1e-9 * max(float(wing.chord.max()), 1e-300)
    if np.abs(tip[0] - tip[1]).max() > tol:
        out[f"{wing.name} tip"] = oriented(tip, e_span)
    for j, label, direction in ((-1, "trailing edge", 1.0), (0, "leading edge", -1.0)):
        strip = _edge_strip(dense, start, j, tol)
        if strip is not None:
            out[f"{wing.name} {label}"] = oriented(strip, [direction, 0.0, 0.0])
    return out


def _root_cap(surf, start, bodies, n_cap):
    """(n_cap, n_points, 3) from the upper to the lower root line, on the body if both are."""
    up, lo = surf["upper"][0], surf["lower"][0]
    (_, wu, tu), (_, wl, tl) = start["upper"], start["lower"]
    t = np.linspace(0.0, 1.0, max(int(n_cap), 2))[:, None]
    cap = up[None] * (1.0 - t[..., None]) + lo[None] * t[..., None]  # straight: flat root
    for b, body in enumerate(bodies):
        on = (wu == b) & (wl == b)
        if isinstance(body, ArbitraryBody):  # its angle is an arc fraction on the +y side
            on &= (up[:, 1] > 0.0) & (lo[:, 1] > 0.0)
        if not on.any():
            continue
        xq = cap[:, on, 0]
        if isinstance(body, CircularBody):
            dth = np.angle(np.exp(1j * (tl[on] - tu[on])))
            cap[:, on] = body.point(xq, tu[on] + t * dth)
        else:
            cap[:, on] = body.point(xq, tu[on] + t * (tl[on] - tu[on]))
    return cap


def _edge_strip(dense, start, j, tol):
    """Strip closing a blunt edge (chord point j) between upper and lower, or None."""
    lines = {s: dense.lofting_lines(s)[j] for s in ("upper", "lower")}
    if np.abs(lines["upper"] - lines["lower"]).max() <= tol:
        return None
    u = np.unique(np.concatenate([[start["upper"][0][j], start["lower"][0][j]],
                                  np.arange(dense.n_sections, dtype=float)]))
    u = u[u >= max(start["upper"][0][j], start["lower"][0][j])]
    pts = [polyline_points(lines[s][None], u[None, :])[0] for s in ("upper", "lower")]
    return np.stack(pts)


# --------------------------------------------------------------------------------------------
# Configurations


def capture_tube(body, n_theta=48):
    """Inward-oriented closed networks of a nacelle's capture streamtube (a cylinder of the
    inlet radius over the nacelle's length): their cut areas count negative."""
    tube = CircularBody(f"{body.name} capture", [body.x[0], body.x[-1]],
                        [body.radius[0]] * 2, origin=body.origin, axial="linear")
    return {k: v[::-1] for k, v in body_solid(tube, n_theta, 2).items()}


def held_base_solids(cfg, x_far, n_theta=48):
    """Closed prisms of each open base's section from the base to ``x_far``, both halves.

    The Harris program holds the area of an open base behind it
    (:func:`juncture.analysis._components.held_bases`); cut together with
    :func:`closed_networks`, each prism adds the part of the base section that a Mach plane
    has passed, so an equivalent body ends with the base area. The prism's front face is the
    body's base disc reversed (their cuts cancel), its side continues the body's last
    polygon (the same ``n_theta``), and ``x_far`` must lie behind every plane that is cut.

    Parameters
    ----------
    cfg : Configuration
    x_far : float
        Where the prisms end [deck length].
    n_theta : int
        Polygon sides, as for :func:`closed_networks`.

    Returns
    -------
    dict of str to (n_lines, n_points, 3) float
        ``"<body> held base"`` (side), ``"... front"``, ``"... end"``, and their images.
    """
    out = {}
    for body, x_end, _ in held_bases(cfg):
        xe = np.array([np.nextafter(x_end, -np.inf)])
        ring = _rings(body, np.array([x_end]), xe, int(n_theta))[0]
        centre = np.broadcast_to(ring.mean(axis=0) if isinstance(body, ArbitraryBody)
                                 else _centre(body, x_end), ring.shape)
        far = ring + np.array([max(float(x_far) - x_end, 0.0), 0.0, 0.0])
        name = f"{body.name} held base"
        nets = {name: np.stack([ring, far]),
                f"{name} front": oriented(np.stack([ring, centre]), [-1.0, 0.0, 0.0]),
                f"{name} end": oriented(np.stack([far, centre + far - ring]), [1.0, 0.0, 0.0])}
        out.update(nets)
        if cfg.symmetric and body.mirrored:
            out.update({f"{k} image": _mirror(v) for k, v in nets.items()})
    return out


def closed_networks(cfg, n_chord=49, n_span=25, n_theta=48, n_body=121, n_cap=5,
                    flow_through=True, union=True, equal_area=True):
    """Closed, outward networks of every component of a configuration, both halves.

    Parameters
    ----------
    cfg : Configuration
    n_chord, n_span, n_cap : int
        Resampling of wing-like components (see :func:`winglike_solid`).
    n_theta, n_body : int
        Resampling of bodies (see :func:`body_solid`).
    flow_through : bool
        Add each open nacelle's capture streamtube, inward (see :func:`is_flow_through`).
    union : bool
        Trim wing-like components at the bodies they enter, so that a buried root counts
        once; False: every component whole, so that cut areas are summed (the Harris
        program's convention, :mod:`juncture.analysis.harris`).
    equal_area : bool
        Circular sections as polygons of the circle's area (for cuts, default) or with their
        corners on the circle (False: the surface itself, as CAD faces need).

    Returns
    -------
    dict of str to (n_lines, n_points, 3) float
        Every network of every component copy; images are named ``"<network> image"``.
        Pass it to :func:`juncture.analysis.cuts.mach_plane_areas`.

    Raises
    ------
    GeometryError
        A component that is not a body or wing-like surface, or a wing-like surface whose
        tip lies inside a body.
    """
    if not hasattr(cfg, "components"):
        raise GeometryError(f"expected a Configuration, found a {type(cfg).__name__}")
    out = {}
    for comp in cfg:
        if isinstance(comp, WingLike):
            nets = winglike_solid(comp, cfg.bodies if union else (), n_chord, n_span, n_cap)
        else:
            nets = body_solid(comp, n_theta, n_body, equal_area)
        if flow_through and is_flow_through(comp):
            nets.update(capture_tube(comp, n_theta))
        out.update(nets)
        if cfg.symmetric and comp.mirrored:
            out.update({f"{k} image": _mirror(v) for k, v in nets.items()})
    return out
