"""Wing-like surface against a body: TM-4406 eqs 4-6 (circular), TM-4607 eq 8 (arbitrary).

Every lofting line of one surface (upper or lower) of a wing, canard, tail, fin or pylon is
extended towards the body's axis and cut with the body surface; see :mod:`.rays` for the
root finder that replaces the paper's fixed-gain iteration.

The body surface is the one the deck describes (:mod:`juncture.model.body`): circular
sections with straight frustums across gaps between segments; arbitrary sections as the
deck's polylines, matched by arc length between stations. TM-4607 eq 8 interpolates a
section curve y_i(z) at x = v_x and compares it with v_y; here the error is the signed
in-plane distance to that exact polyline (the same zero set, and a Lipschitz bound for the
bracketing), so points are on the deck's surface to rounding (about 1e-12 of the length).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError, GeometryError
from ..model import ArbitraryBody, CircularBody, WingLike
from .rays import SurfaceBound, find_crossings

__all__ = ["BodyIntersection", "intersect_body", "intersect_body_both", "settle_past_centre",
           "side_label"]


def side_label(wing, side):
    """"upper"/"lower" for wing-type surfaces, "outboard"/"inboard" for fins and pylons."""
    if wing.span_axis == 2:
        return {"upper": "outboard", "lower": "inboard"}[side]
    return side


@dataclass(frozen=True, slots=True, eq=False)
class BodyIntersection:
    """Intersection of one surface of a wing-like component with a body.

    Attributes
    ----------
    name : str
        ``"<wing>/<body> <side>"``, e.g. ``"wing/body upper"``.
    side : {"upper", "lower"}
    points : (n_stations, 3) float
        One point per lofting line, leading edge first; NaN where the line misses the body.
    u : (n_stations,) float
        Section coordinate of each point on its lofting line (0 = root section, < 0 inboard
        of it, between 0 and 1: between sections 1 and 2).
    found : (n_stations,) bool
        Lines that meet the body.
    theta : (n_stations,) float
        Body angle of each point [rad], TM-4406 convention (0 horizontal, +pi/2 top); NaN
        where missed. For an arbitrary body: normalised arc length (0 bottom, 1 top).
    n_crossings : (n_stations,) int
        Sign changes seen along each line; 2 or more means the line crosses the body twice
        and the first crossing reached coming inboard was taken.
    iterations : int
    residual : (n_stations,) float
        Distance of each point from the body surface [deck length].
    log : tuple of str
    """

    name: str
    side: str
    points: np.ndarray
    u: np.ndarray
    found: np.ndarray
    theta: np.ndarray
    n_crossings: np.ndarray
    iterations: int
    residual: np.ndarray
    log: tuple = ()
    past_centre: np.ndarray = None


#: Log words of a fin's line found past the body's centre height (:func:`settle_past_centre`).
_PAST = "passes beside"


def settle_past_centre(inter, body, others, lines):
    """``inter`` (a fin's or pylon's intersection with ``body``) keeping a crossing found
    past the body's centre height (:func:`_past_centre`) only where the line would otherwise
    end inside ``body``: at the root-half point of ``others`` (its intersections with other
    components on the same side) nearest its tip, or at its input root point (``lines[:,
    0]``) if it meets none. A canted fin's trailing edge passing beside a tail cone onto a
    tail inside it meets the cone there; one whose root overhangs the cone is not extended
    down its side (its root is kept and named, :mod:`juncture.surface.component_networks`).
    """
    from dataclasses import replace

    past = inter.past_centre
    if past is None or not past.any():
        return inter
    n = lines.shape[1]
    end, best = np.array(lines[:, 0], float), np.full(len(lines), -np.inf)
    for other in others:
        ou = np.asarray(other.u, float)
        ok = np.asarray(other.found, bool) & (ou < 0.5 * (n - 1)) & (ou > best)
        if other.past_centre is not None:
            ok &= ~other.past_centre
        end[ok], best[ok] = np.asarray(other.points, float)[ok], ou[ok]
    size = 1e-9 * max(float(body.length), 1.0)
    drop = past & ~(body.signed_distance(np.where(past[:, None], end, 0.0)) < -size)
    if not drop.any():
        return inter
    found, pts, u = inter.found.copy(), inter.points.copy(), inter.u.copy()
    theta, residual = inter.theta.copy(), inter.residual.copy()
    found[drop] = False
    for a in (pts, u, theta, residual):
        a[drop] = np.nan
    gone = {f"lofting line {j + 1} {_PAST}" for j in np.flatnonzero(drop)}
    log = [line for line in inter.log if not any(g in line for g in gone)]
    log[-1:-1] = [f"{inter.name}: lofting line {j + 1} misses {body.name}"
                  for j in np.flatnonzero(drop)]
    return replace(inter, points=pts, u=u, found=found, theta=theta, residual=residual,
                   log=tuple(log), past_centre=past & ~drop)


def _error_function(body):
    if isinstance(body, CircularBody):
        def error(points):
            return body.radial_error(points)
        error.value_and_gradient = body.radial_error_and_gradient
        return error
    if isinstance(body, ArbitraryBody):
        return body.signed_distance
    raise GeometryError(f"cannot intersect with a {type(body).__name__}", body)


def _body_angle(body, pts):
    if isinstance(body, CircularBody):
        c = body.center_at(pts[:, 0])
        return np.arctan2(pts[:, 2] - c[:, 1], pts[:, 1] - c[:, 0])
    return body.parameter_of(pts)  # arbitrary body: normalised arc length, 0 bottom, 1 top


def _u_axis(wing, body, lines):
    """Section coordinate at which each line reaches the body's axis (the search limit)."""
    s = wing.span_stations
    if wing.span_axis == 1:
        centre = body.origin[1] if isinstance(body, CircularBody) else 0.0
        c = np.full(lines.shape[0], centre)
    else:
        c = body.center_at(lines[:, 0, 0])[:, 1]
    return (c - s[0]) / (s[1] - s[0])


def _span_extent(body, wing):
    """Lowest and highest coordinate of ``body`` along ``wing``'s span axis (its section
    points, widened by a tenth of the range: circular sections bulge between stations)."""
    pts = np.asarray(body.cross_sections(), float).reshape(-1, 3)[:, wing.span_axis]
    lo, hi = float(np.nanmin(pts)), float(np.nanmax(pts))
    pad = 0.1 * (hi - lo)
    return lo - pad, hi + pad


def _past_centre(wing, body, lines, cr, error, bound, samples_per_section):
    """A fin's or pylon's lines that miss ``body`` above its centre height, searched on past
    it to the far side of the body (issue 11).

    The centre height is no plane of symmetry for a fin: a canted fin's trailing-edge lines,
    passing beside a narrowing tail cone, can reach the body below its centre (and another
    surface, a tail, inside it). Only the lines that missed are searched again, over the whole
    line down to the body's far extent, so every line found before keeps its point bit for
    bit; a root found is a root of the same surface equation, the first from the tip.
    Returns the crossings and which lines were found so (kept only where the line would
    otherwise end inside the body: :func:`settle_past_centre`)."""
    from dataclasses import replace

    from .rays import root_tolerance

    miss = np.flatnonzero(~cr.found)
    s = wing.span_stations
    far = min((v - s[0]) / (s[1] - s[0]) for v in _span_extent(body, wing))
    again = find_crossings(lines[miss], error, min(far, 0.0), samples_per_section,
                           lipschitz=bound, atol=root_tolerance(lines))
    got = miss[again.found]
    past = np.zeros(len(lines), bool)
    past[got] = True
    if not got.size:
        return cr, past
    fields = {}
    for name in ("u", "points", "found", "n_crossings", "residual", "gradient", "jumps"):
        old, new = getattr(cr, name), getattr(again, name)
        if old is not None and new is not None:
            old = old.copy()
            old[got] = new[again.found]
            fields[name] = old
    return replace(cr, iterations=cr.iterations + again.iterations, **fields), past


def intersect_body(wing: WingLike, body, side="upper", samples_per_section=None, hint=None):
    """Intersection line of one surface of ``wing`` with ``body`` (TM-4406 eqs 4-6).

    Parameters
    ----------
    wing : WingLike
    body : CircularBody or ArbitraryBody
    side : {"upper", "lower"}
        For fins and pylons "upper" is the outboard side.
    samples_per_section : int
        Bracketing density where a crossing may hide (see :func:`.rays.find_crossings`).
    hint : (n_stations,) float, optional
        Section coordinates of a previous solve on a body that contained this one.

    Returns
    -------
    BodyIntersection

    Raises
    ------
    GeometryError
        If the tip of a lofting line lies inside the body (the wing does not leave it).

    Notes
    -----
    An intersection is a root of the body's surface equation, never a jump of it. Where two
    fuselage segments repeat their joint station with different sections, the surface steps
    at x = x_joint; the step's face (the region between the two sections in that plane)
    closes the solid but is not part of the parametric surface (no theta or arc-length
    parameter, no body network carries it). A lofting line that enters the body only through
    that face is therefore not given a point on it: the sign change across the step is a jump
    of the error (the closed bracket keeps a residual of the step's size), the search goes on
    inboard of it, and the line is reported as missing unless it meets the surface proper
    further inboard (the same rule as for an open end; :func:`.rays.find_crossings`, Notes).
    :func:`juncture.misses.line_ends` then refuses a missing line whose end on the plane of
    symmetry lies inside the body (it entered through such a face).
    The bracketing's Lipschitz screening holds off such steps: a line that dips into the
    body only within a step's height of the joint may be seen as missing it.
    """
    return _intersect(wing, body, (side,), samples_per_section,
                      None if hint is None else (hint,))[0]


def intersect_body_both(wing: WingLike, body, samples_per_section=None, hints=None):
    """Upper and lower intersections in one vectorised solve: ``(upper, lower)``.

    ``hints`` is ``(upper_u, lower_u)`` from a previous solve, or None.
    """
    return _intersect(wing, body, ("upper", "lower"), samples_per_section, hints)


def _intersect(wing, body, sides, samples_per_section, hints):
    per_side = [wing.lofting_lines(side) for side in sides]
    lines = np.concatenate(per_side)  # (n_sides * n_stations, n_sections, 3)
    error = _error_function(body)
    u_low = np.minimum(_u_axis(wing, body, lines), 0.0)
    hint = None if hints is None else np.concatenate([np.asarray(h, float) for h in hints])
    if hasattr(body, "error_lipschitz_between"):
        bound = SurfaceBound(body)
    else:
        bound = body.error_lipschitz
    try:
        cr = find_crossings(lines, error, u_low, samples_per_section, lipschitz=bound,
                            hint=hint)
    except ConvergenceError as exc:
        n = wing.n_stations
        which = ", ".join(f"{side_label(wing, sides[r // n])} lofting line {r % n + 1}"
                          for r in getattr(exc, "rows", [])[:4])
        raise ConvergenceError(f"the intersection with {body.name} did not converge ({which}):"
                               " the line grazes the body; move one of them slightly",
                               wing.name) from None
    past = np.zeros(len(lines), bool)
    if wing.span_axis != 1 and not cr.found.all():
        cr, past = _past_centre(wing, body, lines, cr, error, bound, samples_per_section)
    tip_inside = cr.start_error <= 0  # NaN (a hinted line) compares False
    if np.any(tip_inside):
        j = int(np.argmax(tip_inside))
        side = sides[j // wing.n_stations]
        exc = GeometryError(f"the tip of {side} lofting line {j % wing.n_stations + 1} lies "
                            f"inside {body.name}: the surface never leaves the body (move or "
                            f"extend {wing.name} so that its tip is outside {body.name})",
                            wing.name, wing.n_sections)
        exc.tip_inside = True  # the pair touches: never taken for one that does not
        raise exc
    out = []
    m = wing.n_stations
    # A lofting line both surfaces share (a sharp leading or trailing edge) takes the first
    # side's point, bit for bit: solved twice, the two can differ in the last bit.
    same = np.zeros(m, bool)
    if len(per_side) == 2:
        same = np.all(per_side[0] == per_side[1], axis=(1, 2))
    for k, side in enumerate(sides):
        sl = np.arange(k * m, (k + 1) * m)
        if k == 1:
            sl[same] = np.flatnonzero(same)
        pts, found, u = cr.points[sl], cr.found[sl], cr.u[sl]
        theta = np.full(m, np.nan)
        if found.any():
            if cr.gradient is not None:  # circular body: the unit radial direction
                g = cr.gradient[sl][found]
                theta[found] = np.arctan2(g[:, 2], g[:, 1])
            else:
                theta[found] = _body_angle(body, pts[found])
        name = f"{wing.name}/{body.name} {side_label(wing, side)}"
        log = []
        for j in np.flatnonzero((cr.n_crossings[sl] >= 2) & ~past[sl]):
            log.append(f"{name}: lofting line {j + 1} crosses {body.name} "
                       f"{int(cr.n_crossings[sl][j])} times; took the first reached coming "
                       f"inboard (u = {u[j]:.6g})")
        for j in np.flatnonzero(~found):
            log.append(f"{name}: lofting line {j + 1} misses {body.name}")
        for j in np.flatnonzero(past[sl]):
            log.append(f"{name}: lofting line {j + 1} {_PAST} {body.name} at its centre "
                       f"height and meets it below (u = {u[j]:.6g}), where it would end "
                       f"inside {body.name} otherwise")
        log.append(f"{name}: {int((found & ~past[sl]).sum())} of {m} lines solved in "
                   f"{cr.iterations} "
                   f"iterations, max residual {np.nanmax(cr.residual[sl], initial=0.0):.3g}")
        out.append(BodyIntersection(name, side, pts, u, found, theta, cr.n_crossings[sl],
                                    cr.iterations, cr.residual[sl], tuple(log), past[sl]))
    return out
