"""The ``juncture wavedrag`` job as library functions: area distributions and wave drag.

:func:`wavedrag` returns plain JSON-ready values (floats and lists) so the CLI only prints
them. The figure of several results is :func:`juncture.plots.plot_area_distribution`.
"""

from __future__ import annotations

import numpy as np

from ..errors import JunctureError
from ._components import held_base_area, is_y_symmetric
from .areas import default_stations, normal_area_distribution
from .machplanes import _mach_plane_cuts
from .wavedrag import _rule_name, eminton_lord, far_field_drag, roll_angles

__all__ = ["wavedrag", "fillet_areas", "converged_wavedrag"]


def _floats(a):
    return [float(v) for v in np.ravel(a)]


def fillet_areas(geo):
    """Stations, per-side added areas and centroids of a completed geometry's fillets.

    Returns ``(x (m,), area_per_side (m,), y_c (m,), z_c (m,), sides)`` with the stations
    sorted in x; ``sides`` is 2 for a mirrored wing (the stations' ``area_fillet`` holds
    both), the centroid is the mean of the upper and lower fillet points of each station.
    """
    st = geo.stations
    x = np.asarray(st["x"], float)
    order = np.argsort(x)
    fu, fl = geo.fillets["fillet upper"], geo.fillets["fillet lower"]
    pts = np.concatenate([fu, fl], axis=1)
    yc, zc = pts[..., 1].mean(axis=1), pts[..., 2].mean(axis=1)
    sides = 2 if any(k.startswith("wing") and geo.symmetry.get(k) == "xz"
                     for k in geo.networks) else 1
    # The model of the completed configuration already holds the uncovered wing root: add
    # the fillets alone.
    a = np.asarray(st.get("area_fillet_only", st["area_fillet"]), float) / sides
    return x[order], a[order], yc[order], zc[order], sides


def _fillet_normal(geo, x):
    xf, af, _, _, sides = fillet_areas(geo)
    return sides * np.interp(x, xf, af, left=0.0, right=0.0)


def _region(corner, curve):
    """|area| and (y, z) centroid of the polygon corner + fillet curve, per station."""
    poly = np.concatenate([corner[:, None, :], curve], axis=1)
    y, z = poly[..., 1], poly[..., 2]
    yn, zn = np.roll(y, -1, axis=1), np.roll(z, -1, axis=1)
    cr = y * zn - yn * z
    area = 0.5 * cr.sum(axis=1)
    ok = np.abs(area) > 0.0
    safe = np.where(ok, 6.0 * area, 1.0)
    cy = np.where(ok, ((y + yn) * cr).sum(axis=1) / safe, curve[..., 1].mean(axis=1))
    cz = np.where(ok, ((z + zn) * cr).sum(axis=1) / safe, curve[..., 2].mean(axis=1))
    return np.abs(area), cy, cz


def _fillet_parts(geo):
    """The upper and lower fillets' shares of each station's area and their centroids.

    Each fillet's cross-section is the region between its curve (body to wing) and the
    corner where the wing meets the body (the wing/body intersection line, interpolated to
    the station); the station's added area is split in the ratio of those regions' areas.
    Returns ``[(area (m,), y_c (m,), z_c (m,)) for upper, lower]``, stations sorted in x.
    """
    xf, af, _, _, _ = fillet_areas(geo)
    order = np.argsort(np.asarray(geo.stations["x"], float))
    regions = []
    for side in ("upper", "lower"):
        curve = np.asarray(geo.fillets[f"fillet {side}"], float)[order]
        inter = next((np.asarray(v, float) for k, v in geo.intersections.items()
                      if k.endswith(f" {side}")), None)
        if inter is None or len(inter) < 2:
            regions.append((np.ones(xf.size), curve[..., 1].mean(axis=1),
                            curve[..., 2].mean(axis=1)))
            continue
        o = np.argsort(inter[:, 0])
        xs = curve[..., 0].mean(axis=1)
        corner = np.stack([xs] + [np.interp(xs, inter[o, 0], inter[o, k]) for k in (1, 2)], -1)
        regions.append(_region(corner, curve))
    total = regions[0][0] + regions[1][0]
    share = np.where(total > 0.0, regions[0][0] / np.where(total > 0.0, total, 1.0), 0.5)
    return [(af * share, *regions[0][1:]), (af * (1.0 - share), *regions[1][1:])]


def _fillet_mach(geo, x_cuts, thetas, mach):
    """Fillet area in each Mach-plane cut: each fillet's (upper, lower; each side of the
    airplane) station areas moved to the X of its own centroid."""
    xf, _, _, _, sides = fillet_areas(geo)
    beta = np.sqrt(mach * mach - 1.0)
    out = np.zeros(np.shape(x_cuts))
    for k, th in enumerate(thetas):
        for side in ((1.0, -1.0) if sides == 2 else (1.0,)):
            for af, yc, zc in _fillet_parts(geo):
                xs = xf - beta * (side * yc * np.cos(th) + zc * np.sin(th))
                o = np.argsort(xs)
                out[k] += np.interp(x_cuts[k], xs[o], af[o], left=0.0, right=0.0)
    return out


def wavedrag(cfg, mach=None, n_x=101, n_theta=16, geometry=None, half_turn=None,
             method="juncture", conventions=None, networks=None):
    """Area distribution and supersonic wave drag of a configuration (both halves).

    Parameters
    ----------
    cfg : Configuration or Geometry
        The airplane; a Configuration's ``reference_area`` (the deck's REFA) gives ``CD``.
    mach : float, optional
        Free-stream Mach number >= 1. Without it: slender-body drag of the normal-area
        distribution. With it: far-field drag averaged over roll angles.
    n_x : int
        Stations of the normal-area distribution (equally spaced over the configuration's
        length) and cuts per roll angle.
    n_theta : int
        Roll-angle intervals per half turn (the Harris program's NTHETA): a configuration
        symmetric about y = 0 is cut at ``n_theta + 1`` angles over a half turn and averaged
        with Boole's rule (:func:`juncture.analysis.wavedrag.roll_angles`), any other at
        ``2 n_theta`` angles over the full turn (the same spacing).
    geometry : Geometry or mapping of str to (n_lines, n_points, 3) float, optional
        A geometry from :func:`juncture.complete` (with its ``configuration`` and fillet
        ``stations``): areas are then those of its model (the re-designed fuselage, the wing
        trimmed at it) plus the fillets' added area, interpolated linearly between the
        fillet stations; in a Mach-plane cut the upper and lower fillets' shares of it are
        moved to the X of their own centroids (the fillets lie close to the body, so this is
        the thin-fillet limit). Any other geometry: closed, outward networks cut instead of
        the model.
    half_turn : bool, optional
        Override the symmetry test (:func:`juncture.analysis._components.is_y_symmetric`;
        a Geometry without its model counts as not symmetric).
    method : {"juncture", "harris"}
        ``"harris"``: the Harris program's conventions for a deck (a Configuration only;
        :mod:`juncture.analysis.harris`): straight lines between chordwise ordinates,
        component areas summed, normal area as M = 1.000001, NTHETA + 1 angles over a half
        turn with Boole's rule.
    conventions : HarrisConventions, optional
        With ``method="harris"``: which conventions apply (default: all).
    networks : mapping of str to (n_lines, n_points, 3) float, optional
        With a Mach number and a Configuration (or a completed geometry's model): its closed
        networks (:func:`juncture.analysis.closed.closed_networks`) made once for several
        Mach numbers, instead of building them again for each.

    Returns
    -------
    dict
        ``"mach"`` (float or None), ``"D_over_q"`` [deck length^2], ``"CD"`` (``D_over_q /
        reference_area``, None without a reference area), ``"reference_area"``,
        ``"method"``, ``"x"`` and ``"area"`` (the normal-area distribution, lists; with a
        Mach number those of the networks that were cut, to their faceting, or the model's
        at M = 1), ``"components"`` (name -> list of areas, with ``"held bases"``; slender
        body from a model only, else empty), and with a Mach number ``"thetas"``,
        ``"theta_weights"``, ``"D_over_q_theta"``, ``"x_cuts"`` and ``"cut_areas"``
        ((n, n_x) nested lists).

    Raises
    ------
    JunctureError
        A Mach number below 1, too few stations or roll angles, or an area distribution
        that does not start at zero (slender-body theory needs a closed nose: subtract an
        inlet capture area first).

    Notes
    -----
    Slender body: the Eminton-Lord least-drag curve through the station areas
    (:func:`juncture.analysis.wavedrag.eminton_lord`), with the area of each open base held
    behind it. Far field (Harris, NASA TM X-947): the roll-angle average of the Eminton-Lord
    drag of each Mach-plane equivalent body
    (:func:`juncture.analysis.machplanes.mach_plane_area_distribution`,
    :func:`juncture.analysis.wavedrag.far_field_drag`). Only what the result needs is
    computed: with a Mach number the model's normal areas are not integrated.
    """
    n_x, n_theta = int(n_x), int(n_theta)
    if n_x < 3:
        raise JunctureError(f"n_x must be at least 3, found {n_x}")
    if method not in ("juncture", "harris"):
        raise JunctureError(f"method must be 'juncture' or 'harris', found {method!r}")
    if method == "harris":
        return _harris(cfg, mach, n_x, n_theta, geometry, half_turn, conventions)
    completed = geometry is not None and getattr(geometry, "configuration", None) is not None \
        and "area_fillet" in getattr(geometry, "stations", {})
    source = cfg if geometry is None else (geometry.configuration if completed else geometry)
    if not (hasattr(source, "components") or hasattr(source, "networks")
            or isinstance(source, dict)):
        raise JunctureError(f"expected a Configuration or Geometry, found "
                            f"{type(source).__name__}")
    if isinstance(source, dict):
        from ..geometry import Geometry

        source = Geometry(networks=source)
    model = hasattr(source, "components")
    fillets = completed and bool(geometry.fillets)
    ref = getattr(cfg, "reference_area", None)
    ref = float(ref) if ref else None
    out = {"mach": None if mach is None else float(mach), "reference_area": ref}
    x = default_stations(source, n_x)
    if mach is None:
        normal = dict(normal_area_distribution(source, x))
        if model:
            normal["held bases"] = held_base_area(source, x)
            normal["total"] = normal["total"] + normal["held bases"]
        if fillets:
            normal["fillet"] = _fillet_normal(geometry, x)
            normal["total"] = np.asarray(normal["total"], float) + normal["fillet"]
        area = np.asarray(normal["total"], dtype=float).copy()
        area[np.abs(area) <= 1e-12 * max(float(np.max(np.abs(area))), 1e-300)] = 0.0
        body = eminton_lord(x, area)
        out.update(method="slender-body (Eminton-Lord)", D_over_q=float(body.d_over_q),
                   x=_floats(x), area=_floats(normal["total"]),
                   components={k: _floats(v) for k, v in normal.items()
                               if k not in ("x", "total")})
    else:
        half = (model and is_y_symmetric(source)) if half_turn is None else bool(half_turn)
        out.update(_far_field(source, mach, n_x, n_theta, half,
                              geometry=geometry if fillets else None, networks=networks))
    out["CD"] = None if ref is None else out["D_over_q"] / ref
    return out


def _harris(cfg, mach, n_x, n_theta, geometry, half_turn, conventions):
    """:func:`wavedrag` with the Harris program's conventions (a deck's components only)."""
    from .harris import HarrisConventions, harris_model, harris_networks

    if geometry is not None or not hasattr(cfg, "components"):
        raise JunctureError("the Harris conventions apply to a deck's components (a "
                            "Configuration), not to a completed geometry")
    conv = HarrisConventions() if conventions is None else conventions
    model = harris_model(cfg, conv)
    networks = harris_networks(model, conv)
    if mach is None or float(mach) == 1.0:
        if conv.normal_mach is not None:
            mach = conv.normal_mach
        elif mach is None and networks is None:  # juncture's slender body of the model
            return wavedrag(model, None, n_x, n_theta, half_turn=half_turn)
        else:
            mach = 1.0
    half = True if conv.half_turn else (
        is_y_symmetric(model) if half_turn is None else bool(half_turn))
    on = [f for f, v in vars(conv).items() if v]
    ref = float(cfg.reference_area) if cfg.reference_area else None
    out = {"mach": float(mach), "reference_area": ref}
    out.update(_far_field(model, mach, n_x, n_theta, half, networks=networks,
                          label=f"far-field, Harris conventions ({', '.join(on) or 'none'})"))
    out["CD"] = None if ref is None else out["D_over_q"] / ref
    return out


def _far_field(source, mach, n_x, n_theta, half, geometry=None, networks=None, label=None):
    """The far-field part of :func:`wavedrag`'s result (``mach`` >= 1, roll angles ``half``)."""
    mach = float(mach)
    if not (np.isfinite(mach) and mach >= 1.0):
        raise JunctureError(f"the far-field wave drag needs a Mach number >= 1, found {mach}")
    if n_theta < 1:
        raise JunctureError(f"n_theta must be at least 1, found {n_theta}")
    model = hasattr(source, "components")
    count = n_theta if half else 2 * n_theta
    thetas, weights = roll_angles(count, half)
    x_cuts, cut_areas, mesh = _mach_plane_cuts(source, mach, n_x, thetas, networks=networks)
    x = default_stations(source, n_x)
    if mesh is None:  # M = 1 from the model: the cuts are the normal areas
        x, area = x_cuts[0], cut_areas[0].copy()
    else:  # the same triangles cut by the planes x = const
        area = mesh.cut(mesh.heights(np.array([1.0, 0.0, 0.0])), x)
        area = area + (held_base_area(source, x) if model else 0.0)
    if geometry is not None:
        cut_areas = cut_areas + _fillet_mach(geometry, x_cuts, thetas, mach)
        area = area + _fillet_normal(geometry, x)
    ff = far_field_drag(cut_areas, x_cuts, thetas, weights=weights)
    span = "a half turn" if half else "the full turn"
    method = label or "far-field (Harris)"
    return dict(method=f"{method}, NTHETA {n_theta}: {thetas.size} roll angles over {span}, "
                       f"{_rule_name(count, half)} rule",
                D_over_q=float(ff.d_over_q), x=_floats(x), area=_floats(area), components={},
                thetas=_floats(thetas), theta_weights=_floats(weights),
                D_over_q_theta=_floats(ff.d_over_q_theta), x_cuts=np.asarray(x_cuts).tolist(),
                cut_areas=np.asarray(cut_areas).tolist())


def converged_wavedrag(cfg, mach=None, n_x=101, n_theta=16, tolerance=5e-3, max_doublings=4,
                       geometry=None, **options):
    """Wave drag refined until it settles: n_x doubled (its intervals) until D/q changes by
    less than ``tolerance`` (relative), then, for a far-field run, n_theta the same way.

    Returns a dict: ``D_over_q`` (the finest value), ``error`` (the last change, an estimate
    of the remaining error), ``n_x``, ``n_theta`` (the finest), ``converged`` (both stopped
    by the tolerance, not by ``max_doublings``), ``start`` (D/q at the given resolution),
    ``start_error`` (its relative distance from the finest value) and ``history``
    (``[n_x, n_theta, D/q]`` of every run).
    """
    history = []

    def run(nx, nt):
        value = wavedrag(cfg, mach, n_x=nx, n_theta=nt, geometry=geometry,
                         **options)["D_over_q"]
        history.append([nx, nt, value])
        return value

    def refine(value, nx, nt, which):
        for _ in range(max_doublings):
            nx2, nt2 = (2 * nx - 1, nt) if which == "x" else (nx, 2 * nt)
            new = run(nx2, nt2)
            change = abs(new - value)
            nx, nt, value = nx2, nt2, new
            if change <= tolerance * abs(new):
                return value, nx, nt, change, True
        return value, nx, nt, change, False

    start = run(int(n_x), int(n_theta))
    value, nx, nt, err_x, ok_x = refine(start, int(n_x), int(n_theta), "x")
    err_t, ok_t = 0.0, True
    if mach is not None:
        value, nx, nt, err_t, ok_t = refine(value, nx, nt, "theta")
    return {"D_over_q": float(value), "error": float(max(err_x, err_t)), "n_x": nx,
            "n_theta": nt, "converged": bool(ok_x and ok_t), "start": float(start),
            "start_error": float(abs(start - value) / abs(value)) if value else 0.0,
            "history": history}
