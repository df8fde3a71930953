"""Mach-plane (far-field) area distributions ``S(X, theta)`` of a whole configuration.

Harris (NASA TM X-947): at Mach ``M`` the configuration (both halves) is cut by the planes
``x - beta (y cos theta + z sin theta) = X``, ``beta = sqrt(M^2 - 1)``, and each cut is
projected onto the plane x = const; for each roll angle ``theta`` the areas ``S(., theta)``
form an equivalent body (:func:`juncture.analysis.wavedrag.far_field_drag`).

How a configuration is cut:

* **Closed networks.** A Configuration is closed and resampled by
  :func:`juncture.analysis.closed.closed_networks` (wing roots trimmed at the bodies, so a
  root buried in the fuselage counts once) and cut by :func:`juncture.analysis.cuts.
  mach_plane_areas`; faceting limits the areas to about 0.1 % of the largest (up to 0.39
  ft^2 of 389 on the bundled transport, at M = 1 against the model's exact normal areas). A
  Geometry or a mapping of networks is cut as it is.
* **Open bases** as the Harris program treats them: the area of an open base is held behind
  it (:func:`juncture.analysis._components.held_bases`; closed prisms of the base section,
  :func:`juncture.analysis.closed.held_base_solids`), and each equivalent body runs from the
  first plane that touches the configuration to the last one, so it ends with the held base
  area (an open base for :func:`juncture.analysis.wavedrag.eminton_lord`) instead of falling
  to zero across the base face. Bodies only, and not a flow-through nacelle's exit.
* **M = 1.** Every Mach plane is then x = X: a Configuration's areas are its exact normal
  areas (:func:`juncture.analysis.areas.normal_area_distribution`, plus the held bases) at
  every roll angle, not the faceted cuts.
"""

from __future__ import annotations

import numpy as np

from ..errors import JunctureError
from ._components import held_base_area
from .areas import normal_area_distribution
from .closed import closed_networks, held_base_solids
from .cuts import _mach_normals, _prepare
from .wavedrag import roll_angles

__all__ = ["mach_plane_area_distribution"]


def _is_configuration(obj):
    return hasattr(obj, "components")


def _mach_plane_cuts(obj, mach, n_x, thetas, networks=None):
    """``(x (n, n_x), area (n, n_x), mesh)`` of :func:`mach_plane_area_distribution` at given
    roll angles; ``mesh`` is the triangulated networks that were cut (without the held
    bases), or None on the exact M = 1 path of a Configuration."""
    mach = float(mach)
    if not (np.isfinite(mach) and mach >= 1.0):
        raise JunctureError(f"Mach-plane cuts need a supersonic Mach number >= 1, found {mach}")
    thetas = np.asarray(thetas, dtype=float)
    model = _is_configuration(obj)
    if model and networks is None and mach == 1.0:
        ext = obj.extents()
        x = np.linspace(ext[0, 0], ext[1, 0], n_x)
        area = normal_area_distribution(obj, x)["total"] + held_base_area(obj, x)
        return (np.broadcast_to(x, (thetas.size, n_x)).copy(),
                np.broadcast_to(area, (thetas.size, n_x)).copy(), None)
    if networks is None:
        networks = closed_networks(obj) if model else obj
    mesh = _prepare(networks)
    normals = _mach_normals(mach, thetas)
    heights = [mesh.heights(nk) for nk in normals]
    ext = np.array([[h.min(), h.max()] for h in heights])
    offsets = np.linspace(ext[:, 0], ext[:, 1], n_x).T
    areas = np.stack([mesh.cut(h, offsets[k]) for k, h in enumerate(heights)])
    if model:
        beta = np.sqrt(mach * mach - 1.0)
        reach = float(np.max(np.hypot(mesh.y, mesh.z)))
        size = float(np.ptp(mesh.x)) or 1.0
        tails = held_base_solids(obj, float(ext[:, 1].max()) + beta * reach + 0.01 * size)
        if tails:  # cut on their own (areas add), summed about the same point
            tail = _prepare(tails, mesh.yz0)
            areas += np.stack([tail.cut(tail.heights(nk), offsets[k])
                               for k, nk in enumerate(normals)])
    return offsets, areas, mesh


def mach_plane_area_distribution(obj, mach, n_x=100, n_theta=16, networks=None,
                                 half_turn=False):
    """Far-field equivalent-body areas ``S(X, theta)`` of a whole configuration (both halves).

    Parameters
    ----------
    obj : Configuration or Geometry
        A Configuration is closed and resampled by
        :func:`juncture.analysis.closed.closed_networks` (wing roots trimmed at the bodies)
        and its open bases are held (see the module notes); a Geometry is cut as it is, with
        its mirror images, and must be closed and outward.
    mach : float
        Free-stream Mach number >= 1; M = 1 gives the normal areas for every angle (a
        Configuration's exact ones from its model).
    n_x : int
        Cuts per roll angle, equally spaced from the first to the last plane that touches
        the configuration at that angle (:func:`juncture.analysis.cuts.mach_plane_extents`).
    n_theta : int
        Roll angles (:func:`juncture.analysis.wavedrag.roll_angles`): ``n_theta`` over a full
        turn, or with ``half_turn`` ``n_theta + 1`` over a half turn (Harris NTHETA).
    networks : mapping of str to (n_lines, n_points, 3) float, optional
        Closed networks to cut instead of building them from ``obj``.
    half_turn : bool
        Roll angles over a half turn, for a configuration symmetric about y = 0.

    Returns
    -------
    dict
        ``"thetas"`` (n,) [rad] and ``"weights"`` (n,) of the roll-angle average, ``"x"``
        (n, n_x) plane offsets ``X`` [deck length], ``"area"`` (n, n_x) projected cut areas
        [deck length^2].

    Raises
    ------
    JunctureError
        A Mach number below 1, ``n_theta < 1`` or ``n_x < 2``.

    Notes
    -----
    For a configuration symmetric in y the areas satisfy ``S(X, theta) = S(X, pi - theta)``
    (the image of a plane at theta is the plane at pi - theta); with roll angles measured
    from the vertical, as some programs do (phi = pi/2 - theta), that is S(phi) = S(-phi).
    """
    n_theta, n_x = int(n_theta), int(n_x)
    if n_theta < 1 or n_x < 2:
        raise JunctureError(f"need n_theta >= 1 and n_x >= 2, found {n_theta} and {n_x}")
    thetas, weights = roll_angles(n_theta, half_turn)
    x, area, _ = _mach_plane_cuts(obj, mach, n_x, thetas, networks)
    return {"thetas": thetas, "weights": weights, "x": x, "area": area}
