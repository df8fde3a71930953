"""The ``juncture wavedrag`` job as library functions: area distributions and wave drag.

:func:`wavedrag` returns plain JSON-ready values (floats and lists) so the CLI only prints
them. The figure of several results is :func:`juncture.plots.plot_area_distribution`.
"""

from __future__ import annotations

import numpy as np

from ..errors import JunctureError
from .areas import default_stations, mach_plane_area_distribution, normal_area_distribution
from .wavedrag import eminton_lord, far_field_drag

__all__ = ["wavedrag", "fillet_areas"]


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


def _fillet_mach(geo, x_cuts, thetas, mach):
    """Fillet area in each Mach-plane cut: each side's station areas moved to its own X."""
    xf, af, yc, zc, sides = fillet_areas(geo)
    beta = np.sqrt(mach * mach - 1.0)
    out = np.zeros(np.shape(x_cuts))
    for k, th in enumerate(thetas):
        for side in ((1.0, -1.0) if sides == 2 else (1.0,)):
            xs = xf - beta * (side * yc * np.cos(th) + zc * np.sin(th))
            o = np.argsort(xs)
            out[k] += np.interp(x_cuts[k], xs[o], af[o], left=0.0, right=0.0)
    return out


def wavedrag(cfg, mach=None, n_x=101, n_theta=16, geometry=None):
    """Area distribution and supersonic wave drag of a configuration (both halves).

    Parameters
    ----------
    cfg : Configuration or Geometry
        The airplane; a Configuration's ``reference_area`` (the deck's REFA) gives ``CD``.
    mach : float, optional
        Free-stream Mach number >= 1. Without it: slender-body drag of the normal-area
        distribution. With it: far-field drag averaged over ``n_theta`` roll angles.
    n_x : int
        Stations of the normal-area distribution (equally spaced over the configuration's
        length) and cuts per roll angle.
    n_theta : int
        Roll angles of the far-field average (equally spaced over a full turn).
    geometry : Geometry or mapping of str to (n_lines, n_points, 3) float, optional
        A geometry from :func:`juncture.complete` (with its ``configuration`` and fillet
        ``stations``): areas are then those of its model (the re-designed fuselage, the wing
        trimmed at it) plus the fillets' added area, interpolated linearly between the
        fillet stations; in a Mach-plane cut each side's fillet area is moved to the X of
        its own centroid (the fillet lies close to the body, so this is the thin-fillet
        limit). Any other geometry: closed, outward networks cut instead of the model.

    Returns
    -------
    dict
        ``"mach"`` (float or None), ``"D_over_q"`` [deck length^2], ``"CD"`` (``D_over_q /
        reference_area``, None without a reference area), ``"reference_area"``,
        ``"method"``, ``"x"`` and ``"area"`` (the normal-area distribution, lists),
        ``"components"`` (name -> list of areas; model only), and with a Mach number
        ``"thetas"``, ``"D_over_q_theta"``, ``"x_cuts"`` and ``"cut_areas"``
        ((n_theta, n_x) nested lists).

    Raises
    ------
    JunctureError
        A Mach number below 1, too few stations or roll angles, or an area distribution
        that does not start at zero (slender-body theory needs a closed nose: subtract an
        inlet capture area first).

    Notes
    -----
    Slender body: the Eminton-Lord least-drag curve through the station areas
    (:func:`juncture.analysis.wavedrag.eminton_lord`). Far field (Harris, NASA TM X-947):
    the mean over roll angles of the Eminton-Lord drag of each Mach-plane equivalent body
    (:func:`juncture.analysis.wavedrag.far_field_drag`).
    """
    n_x, n_theta = int(n_x), int(n_theta)
    if n_x < 3:
        raise JunctureError(f"n_x must be at least 3, found {n_x}")
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
    x = default_stations(source, n_x)
    normal = dict(normal_area_distribution(source, x))
    if completed and geometry.fillets:
        normal["fillet"] = _fillet_normal(geometry, x)
        normal["total"] = np.asarray(normal["total"], float) + normal["fillet"]
    ref = getattr(cfg, "reference_area", None)
    ref = float(ref) if ref else None
    out = {"mach": None if mach is None else float(mach), "reference_area": ref,
           "x": _floats(x), "area": _floats(normal["total"]),
           "components": {k: _floats(v) for k, v in normal.items() if k not in ("x", "total")}}
    if mach is None:
        area = np.asarray(normal["total"], dtype=float).copy()
        area[np.abs(area) <= 1e-12 * max(float(np.max(np.abs(area))), 1e-300)] = 0.0
        body = eminton_lord(x, area)
        out.update(method="slender-body (Eminton-Lord)", D_over_q=float(body.d_over_q))
    else:
        mach = float(mach)
        if not (np.isfinite(mach) and mach >= 1.0):
            raise JunctureError(f"the far-field wave drag needs a Mach number >= 1, found "
                                f"{mach}")
        if n_theta < 1:
            raise JunctureError(f"n_theta must be at least 1, found {n_theta}")
        cuts = dict(mach_plane_area_distribution(source, mach, n_x=n_x, n_theta=n_theta))
        if completed and geometry.fillets:
            cuts["area"] = np.asarray(cuts["area"], float) + _fillet_mach(
                geometry, np.asarray(cuts["x"], float), cuts["thetas"], mach)
        ff = far_field_drag(cuts["area"], cuts["x"], cuts["thetas"])
        out.update(method=f"far-field (Harris), {n_theta} roll angles",
                   D_over_q=float(ff.d_over_q), thetas=_floats(cuts["thetas"]),
                   D_over_q_theta=_floats(ff.d_over_q_theta),
                   x_cuts=np.asarray(cuts["x"]).tolist(),
                   cut_areas=np.asarray(cuts["area"]).tolist())
    out["CD"] = None if ref is None else out["D_over_q"] / ref
    return out
