"""Geometry: the surface networks juncture writes, plus what was learnt building them.

A *network* is a float array of shape ``(n_lines, n_points, 3)``: n-lines are sections (an
airfoil section, a body cross-section), m-lines join equal point indices across them (the Hess
vocabulary of TM-4406). Only the described half of a symmetric airplane is stored; a network's
entry in :attr:`Geometry.symmetry` says in which plane its image lies.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Literal

import numpy as np

__all__ = ["Geometry", "MirrorPlane", "mirror_points", "as_network"]

#: Plane in which a network has a mirror image: ``"xz"`` (y -> -y, the usual left/right
#: symmetry), ``"xy"`` (z -> -z), ``"yz"`` (x -> -x). These are LaWGS symmetry codes 1, 2, 3.
MirrorPlane = Literal["xz", "xy", "yz"]

_AXIS_OF_PLANE = {"xz": 1, "xy": 2, "yz": 0}


def as_network(points, name="network"):
    """Return ``points`` as a read-only float64 array of shape ``(n_lines, n_points, 3)``.

    Raises
    ------
    GeometryError
        If the shape is wrong or a coordinate is not finite.
    """
    from .errors import GeometryError

    arr = np.array(points, dtype=float)
    if arr.ndim != 3 or arr.shape[2] != 3 or arr.shape[0] < 1 or arr.shape[1] < 1:
        raise GeometryError(f"a network must have shape (n_lines, n_points, 3), found {arr.shape}",
                            component=name)
    if not np.all(np.isfinite(arr)):
        bad = np.argwhere(~np.isfinite(arr))[0]
        raise GeometryError(f"non-finite coordinate at point {bad[1] + 1}", component=name,
                            station=int(bad[0]) + 1)
    arr.flags.writeable = False
    return arr


def mirror_points(points, plane: MirrorPlane = "xz"):
    """Mirror image of ``points`` (..., 3) in ``plane``; the last axis holds x, y, z."""
    out = np.array(points, dtype=float, copy=True)
    out[..., _AXIS_OF_PLANE[plane]] *= -1.0
    return out


def _freeze_dict(mapping, convert):
    return MappingProxyType({str(k): convert(v, str(k)) for k, v in (mapping or {}).items()})


def _frozen_array(value, name):
    arr = np.array(value, dtype=float)
    arr.flags.writeable = False
    return arr


@dataclass(frozen=True, slots=True, eq=False)
class Geometry:
    """A set of named surface networks and the record of how they were made.

    Attributes
    ----------
    networks : mapping of str to (n_lines, n_points, 3) float
        Surface networks, named ``"<component> <part>"`` in lower case (``"wing upper"``).
    symmetry : mapping of str to MirrorPlane
        For each network that has a mirror image, the plane of the image. Absent means none.
    title : str
        A one-line title (the deck's title card, the LaWGS title record).
    intersections : mapping of str to (k, 3) float
        Intersection polylines named ``"<a>/<b> <surface>"``, e.g. ``"wing/body upper"``.
    fillets : mapping of str to (n_stations, n_points, 3) float
        Fillet lines, each running from its point on the body to its point on the wing.
    stations : mapping of str to (n,) float
        Per-station data of equal length (``x``, ``area_original``, ...).
    log : tuple of str
        What was done: options, iterations, residuals, warnings.
    configuration : Configuration or None
        The component model the networks were built from (for a completed geometry: with the
        re-designed fuselage), for analyses that need the exact model.
    """

    networks: object = field(default_factory=dict)
    symmetry: object = field(default_factory=dict)
    title: str = ""
    intersections: object = field(default_factory=dict)
    fillets: object = field(default_factory=dict)
    stations: object = field(default_factory=dict)
    log: tuple = ()
    configuration: object = None

    def __post_init__(self):
        nets = _freeze_dict(self.networks, lambda v, k: as_network(v, k))
        object.__setattr__(self, "networks", nets)
        sym = {}
        for name, plane in dict(self.symmetry or {}).items():
            if plane is None:
                continue
            if plane not in _AXIS_OF_PLANE:
                from .errors import GeometryError

                raise GeometryError(f"symmetry plane must be one of 'xz', 'xy', 'yz', found "
                                    f"{plane!r}", component=name)
            sym[str(name)] = plane
        object.__setattr__(self, "symmetry", MappingProxyType(sym))
        object.__setattr__(self, "intersections", _freeze_dict(self.intersections, _frozen_array))
        object.__setattr__(self, "fillets", _freeze_dict(self.fillets, _frozen_array))
        object.__setattr__(self, "stations", _freeze_dict(self.stations, _frozen_array))
        object.__setattr__(self, "log", tuple(str(s) for s in self.log))

    def mirrored_networks(self):
        """All networks with their images: dict name -> array.

        An image is named ``"<name> image"`` and has its n-lines reversed, so that a surface
        whose point order gives outward normals keeps outward normals after mirroring.
        """
        out = dict(self.networks)
        for name, plane in self.symmetry.items():
            out[f"{name} image"] = mirror_points(self.networks[name], plane)[::-1]
        return out

    def component_of(self, name):
        """The component a network (or its ``" image"``) belongs to: the longest component
        name of ``configuration`` that the network's name is or starts with (``"pod 1"`` for
        ``"pod 1"``, ``"fin 3"`` for ``"fin 3 outboard image"``), else the network's own
        name without ``" image"``; a juncture block of the four-block layout, which holds
        the fuselage's arcs and the wing (``"wing-body upper"``), belongs to ``"wing-body"``
        with its lower block."""
        base = name[:-len(" image")] if name.endswith(" image") else name
        names = sorted(getattr(self.configuration, "components", None) or (), key=len,
                       reverse=True)
        found = next((c for c in names if base == c or base.startswith(c + " ")), None)
        if found is None and base.startswith("wing-body "):
            return "wing-body"
        return base if found is None else found

    def extents(self):
        """(2, 3) array: minimum and maximum x, y, z over all networks (images excluded)."""
        if not self.networks:
            return np.zeros((2, 3))
        pts = np.concatenate([n.reshape(-1, 3) for n in self.networks.values()])
        return np.array([pts.min(axis=0), pts.max(axis=0)])

    def replace(self, **changes):
        """A copy with some fields replaced (the value itself is immutable)."""
        fields = {f: getattr(self, f) for f in self.__dataclass_fields__}
        fields.update(changes)
        return Geometry(**fields)

    def allclose(self, other, rtol=1e-12, atol=0.0):
        """True if both hold the same network names, symmetry and points (within tolerance)."""
        if set(self.networks) != set(other.networks) or dict(self.symmetry) != dict(
                other.symmetry):
            return False
        return all(
            self.networks[k].shape == other.networks[k].shape
            and np.allclose(self.networks[k], other.networks[k], rtol=rtol, atol=atol)
            for k in self.networks
        )
