"""The ``juncture wavedrag`` job as library functions: area distributions, wave drag, a plot.

:func:`wavedrag` returns plain JSON-ready values (floats and lists) so the CLI only prints
them; :func:`plot_area_distribution` draws several results' ``A(x)`` on one figure.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import JunctureError
from .areas import default_stations, mach_plane_area_distribution, normal_area_distribution
from .wavedrag import eminton_lord, far_field_drag

__all__ = ["wavedrag", "plot_area_distribution"]


def _floats(a):
    return [float(v) for v in np.ravel(a)]


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
        Closed, outward networks to cut instead of the model (e.g. after a fillet); areas
        then come from plane cuts of these networks (with their mirror images).

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
    source = cfg if geometry is None else geometry
    if not (hasattr(source, "components") or hasattr(source, "networks")
            or isinstance(source, dict)):
        raise JunctureError(f"expected a Configuration or Geometry, found "
                            f"{type(source).__name__}")
    if isinstance(source, dict):
        from ..geometry import Geometry

        source = Geometry(networks=source)
    x = default_stations(source, n_x)
    normal = normal_area_distribution(source, x)
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
        cuts = mach_plane_area_distribution(source, mach, n_x=n_x, n_theta=n_theta)
        ff = far_field_drag(cuts["area"], cuts["x"], cuts["thetas"])
        out.update(method=f"far-field (Harris), {n_theta} roll angles",
                   D_over_q=float(ff.d_over_q), thetas=_floats(cuts["thetas"]),
                   D_over_q_theta=_floats(ff.d_over_q_theta),
                   x_cuts=np.asarray(cuts["x"]).tolist(),
                   cut_areas=np.asarray(cuts["area"]).tolist())
    out["CD"] = None if ref is None else out["D_over_q"] / ref
    return out


def plot_area_distribution(results, path, title=None):
    """Plot the normal-area curves ``A(x)`` of several :func:`wavedrag` results; save it.

    Parameters
    ----------
    results : mapping of str to dict
        Label (e.g. ``"before"``, ``"after fillet"``, ``"after compensation"``) -> a
        :func:`wavedrag` result (uses ``"x"``, ``"area"`` and, in the legend, ``"D_over_q"``).
    path : str or path-like
        Output image; the format follows the extension (``.png``, ``.svg``, ``.pdf``).
        Written atomically (:func:`juncture.plots.save`).
    title : str, optional

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    JunctureError
        No results, or a result without ``x`` and ``area`` of equal length.
    """
    from ..plots import plt, save

    if not results:
        raise JunctureError("no area distributions to plot")
    fig, ax = plt.subplots(figsize=(9, 5), layout="constrained")
    for label, res in results.items():
        try:
            x, a = np.asarray(res["x"], float), np.asarray(res["area"], float)
        except (KeyError, TypeError, ValueError):
            raise JunctureError(f"result {label!r} has no 'x' and 'area' lists") from None
        if x.ndim != 1 or x.shape != a.shape:
            raise JunctureError(f"result {label!r}: 'x' and 'area' must be 1-D of equal "
                                f"length, found shapes {x.shape} and {a.shape}")
        dq = res.get("D_over_q")
        ax.plot(x, a, lw=1.4, label=f"{label} (D/q = {dq:.4g})" if dq is not None else label)
    ax.set_xlabel("x (aft)")
    ax.set_ylabel("normal cross-sectional area A(x), both halves")
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.legend(fontsize=8, loc="best")
    ax.set_title(title or "area distribution")
    save(fig, path)
    return Path(path)
