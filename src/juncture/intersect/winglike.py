"""Wing-like surface against another wing-like surface: TM-4607 eq 7.

A fin on a wing's upper surface, a pylon under a wing's lower surface: the lofting lines of
the first surface (``a``, sections at constant z) are extended towards the second (``b``,
sections at constant y) and cut with its upper or lower surface. The error is the height of
the line above (below) that surface at the same (x, y), e(t) = v_z - z_b(v_x, v_y), eq 7;
points outside ``b``'s planform count as outside. Which end of ``a`` the search starts from
depends on the role: a fin comes down onto the upper surface from its tip; a pylon comes up
onto the lower surface from its root (its tip section usually pierces the wing).

Eq 7 is defined over the planform only, so the error jumps at a planform edge: a line that
passes a leading or trailing edge, the root or the tip, changes sign there without meeting
the surface. Such a jump is never taken for the intersection (:func:`.rays.find_crossings`
keeps only brackets that close on the surface, to 1e-9 of the two components' size); a line
whose only sign change is a jump misses, and its log line says so.
"""

from __future__ import annotations

import numpy as np

from ..errors import ConvergenceError, GeometryError
from .body import BodyIntersection, side_label
from .rays import find_crossings, root_tolerance

__all__ = ["surface_height", "wing_parameters", "intersect_winglike"]


def wing_parameters(wing, points):
    """(span, chord fraction) of points (..., 3) in a wing with sections at constant y.

    The leading edge and chord are lofted linearly in span (extended beyond root and tip);
    the fraction is NaN where the chord is zero.
    """
    p = np.asarray(points, float)
    s = p[..., 1]
    st = wing.span_stations
    k = np.clip(np.searchsorted(st, s, side="right") - 1, 0, wing.n_sections - 2)
    lam = (s - st[k]) / (st[k + 1] - st[k])
    x_le = wing.le[k, 0] + lam * (wing.le[k + 1, 0] - wing.le[k, 0])
    chord = wing.chord[k] + lam * (wing.chord[k + 1] - wing.chord[k])
    with np.errstate(divide="ignore", invalid="ignore"):
        return s, np.where(chord > 0, (p[..., 0] - x_le) / chord, np.nan)


def surface_height(wing, points, side):
    """Height of ``wing``'s surface below / above each point, and whether it covers the point.

    For a wing with sections at constant y: z of its ``side`` surface at the point's (x, y),
    the chord fraction found from the linearly lofted leading edge and chord; extrapolated
    linearly beyond the root and tip sections. Returns ``(height (...), inside_planform
    (...))``.
    """
    if wing.span_axis != 1:
        raise GeometryError("the surface to meet must have sections at constant y (a wing, "
                            "canard or tail)", wing.name)
    p = np.asarray(points, float)
    s, f = wing_parameters(wing, p)
    st = wing.span_stations
    inside = np.isfinite(f) & (f >= 0) & (f <= 1) & (s >= st[0]) & (s <= st[-1])
    fc = np.where(np.isfinite(f), np.clip(f, 0.0, 1.0), 0.0)
    z = wing.point(s, fc, side, extrapolate=True)[..., 2]
    return z, inside


def intersect_winglike(a, b, side_b="upper", side_a="upper", from_root=None,
                       samples_per_section=24, reach=3.0):
    """Intersection of one surface of ``a`` (a fin or pylon) with ``b`` (TM-4607 eq 7).

    Parameters
    ----------
    a : WingLike
        The surface whose lofting lines are extended (sections at constant z).
    b : WingLike
        The surface they meet (sections at constant y).
    side_b : {"upper", "lower"}
        ``"upper"``: a fin standing on ``b``; ``"lower"``: a pylon hanging under it.
    side_a : {"upper", "lower"}
        Which of ``a``'s surfaces (``"upper"`` = outboard).
    from_root : bool, optional
        Search from ``a``'s root end (default: True when meeting a lower surface).
    reach : float
        How far beyond the end section to extend the lines, in section spacings.

    Returns
    -------
    BodyIntersection
        Named ``"<a>/<b> <side_a>"``; ``theta`` is NaN (no body angle). ``u`` is in ``a``'s
        section coordinate (0 at its root).
    """
    if side_b not in ("upper", "lower"):
        raise GeometryError(f"side must be 'upper' or 'lower', found {side_b!r}", b.name)
    from_root = (side_b == "lower") if from_root is None else from_root
    lines = a.lofting_lines(side_a)
    n = a.n_sections
    if from_root:
        lines = lines[:, ::-1]  # the root becomes the search's starting end
    sign = 1.0 if side_b == "upper" else -1.0

    def error(points):
        z, inside = surface_height(b, points, side_b)
        e = sign * (points[..., 2] - z)
        # Outside the planform the line passes beside the surface: outside, and never a root.
        return np.where(inside, e, np.abs(e) + 1.0)

    start_err = error(lines[:, -1])
    if np.any(start_err <= 0):
        j = int(np.argmax(start_err <= 0))
        end = "root" if from_root else "tip"
        raise GeometryError(f"the {end} of {side_a} lofting line {j + 1} is already "
                            f"{'above' if sign < 0 else 'below'} the {side_b} surface of "
                            f"{b.name}: cannot tell where the two meet", a.name)
    atol = root_tolerance(lines, b.section_points("upper"), b.section_points("lower"))
    try:
        cr = find_crossings(lines, error, -float(reach), samples_per_section, atol=atol)
    except ConvergenceError as exc:
        which = ", ".join(str(r + 1) for r in getattr(exc, "rows", [])[:4])
        raise ConvergenceError(f"the intersection with the {side_b} surface of {b.name} did "
                               f"not converge ({side_label(a, side_a)} lofting line {which}): "
                               "the line grazes it; move one of them slightly", a.name) from None
    u = cr.u if not from_root else (n - 1) - cr.u
    name = f"{a.name}/{b.name} {side_label(a, side_a)}"
    log = []
    for j in np.flatnonzero(cr.n_crossings >= 2):
        log.append(f"{name}: lofting line {j + 1} crosses the {side_b} surface of {b.name} "
                   f"{int(cr.n_crossings[j])} times; took the first reached from the "
                   f"{'root' if from_root else 'tip'} (TM-4607 fig 9)")
    for j in np.flatnonzero(~cr.found):
        edge = (f"; it only passes an edge of the planform ({int(cr.jumps[j])} jump(s) of "
                "eq 7, not roots)") if cr.jumps[j] else ""
        log.append(f"{name}: lofting line {j + 1} never meets the {side_b} surface of "
                   f"{b.name} (within {reach:g} section spacings){edge}")
    log.append(f"{name}: {int(cr.found.sum())} of {len(lines)} lines solved in "
               f"{cr.iterations} iterations, max residual "
               f"{np.nanmax(cr.residual, initial=0.0):.3g}")
    return BodyIntersection(name, side_a, cr.points, u, cr.found, np.full(len(u), np.nan),
                            cr.n_crossings, cr.iterations, cr.residual, tuple(log))
