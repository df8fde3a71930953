"""Configuration: the named components of one airplane, with symmetry and reference values."""

from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from ..errors import GeometryError
from .body import ArbitraryBody, CircularBody
from .winglike import WingLike

__all__ = ["Configuration", "Component", "rebuilt"]

Component = WingLike | CircularBody | ArbitraryBody


def rebuilt(component, **changes):
    """A new component of the same type with some public fields changed (its caches and
    checks rebuilt from them)."""
    fields = {f: getattr(component, f) for f in component.__dataclass_fields__
              if not f.startswith("_")}
    fields.update(changes)
    return type(component)(**fields)


@dataclass(frozen=True, slots=True, eq=False)
class Configuration:
    """An airplane as separate components (the wave-drag deck's view of it).

    Only the y >= 0 half is described (``symmetric=True``): a component on the plane of
    symmetry (the fuselage, a centre-line fin) is given by its y >= 0 half, and a component off
    it (a wing, a pod, a fin at y != 0) has an image at -y.

    Parameters
    ----------
    components : mapping of str to WingLike, CircularBody or ArbitraryBody
        Components by name (``"wing"``, ``"body"``, ``"pod 1"``, ``"fin 1"``, ``"canard 1"``).
        The key must equal the component's ``name``.
    title : str
        One-line title (the deck's title card).
    reference_area : float, optional
        Reference area for drag coefficients [deck length^2] (the deck's REFA).
    reference_chord, moment_x : float, optional
        The deck's CBAR and XMC, kept for other programs.
    symmetric : bool
        The configuration is symmetric about the x-z plane.
    source : object, optional
        What it was read from (e.g. the raw deck configuration), kept so a writer can
        reproduce cards juncture does not interpret (cases, restraints).
    """

    components: object
    title: str = ""
    reference_area: float | None = None
    reference_chord: float | None = None
    moment_x: float | None = None
    symmetric: bool = True
    source: object = field(default=None, repr=False)

    def __post_init__(self):
        comps = dict(self.components)
        for key, comp in comps.items():
            if not isinstance(comp, (WingLike, CircularBody, ArbitraryBody)):
                raise GeometryError(f"is a {type(comp).__name__}, not a component", key)
            if comp.name != key:
                raise GeometryError(f"is stored under the key {key!r} but named {comp.name!r}",
                                    key)
        if self.reference_area is not None and not self.reference_area >= 0:
            raise GeometryError(f"reference area must be >= 0, found {self.reference_area}")
        object.__setattr__(self, "components", MappingProxyType(comps))

    def __getitem__(self, name):
        try:
            return self.components[name]
        except KeyError:
            raise GeometryError(f"no such component; the configuration has "
                                f"{', '.join(self.components) or 'none'}", name) from None

    def __iter__(self):
        return iter(self.components.values())

    def __len__(self):
        return len(self.components)

    @property
    def wings(self):
        """Wing-like components (wing, canards, tails, fins, pylons), in order."""
        return [c for c in self if isinstance(c, WingLike)]

    @property
    def bodies(self):
        """Bodies (fuselage and pods), in order."""
        return [c for c in self if isinstance(c, (CircularBody, ArbitraryBody))]

    def networks(self):
        """Surface networks of every component, as given (no intersections): name -> array."""
        out = {}
        for comp in self:
            out.update(comp.networks())
        return out

    def to_geometry(self):
        """The components' own networks as a :class:`~juncture.geometry.Geometry`.

        A network gets an image in the x-z plane if its component is off the plane of
        symmetry (``mirrored``) or is the y >= 0 half of a centre-line body.
        """
        from ..geometry import Geometry

        nets, sym = {}, {}
        for comp in self:
            mine = comp.networks()
            nets.update(mine)
            on_plane_half = isinstance(comp, (CircularBody, ArbitraryBody)) and not comp.mirrored
            if self.symmetric and (comp.mirrored or on_plane_half):
                sym.update({k: "xz" for k in mine})
        return Geometry(networks=nets, symmetry=sym, title=self.title)

    def extents(self):
        """(2, 3): minimum and maximum x, y, z of the described half (images excluded)."""
        pts = np.concatenate([n.reshape(-1, 3) for n in self.networks().values()])
        return np.array([pts.min(axis=0), pts.max(axis=0)])

    def replace(self, **changes):
        """A copy with some fields replaced (components: a new mapping)."""
        fields = {f: getattr(self, f) for f in self.__dataclass_fields__}
        fields.update(changes)
        return Configuration(**fields)

    def with_component(self, component):
        """A copy with ``component`` added or replacing the one of the same name."""
        comps = dict(self.components)
        comps[component.name] = component
        return self.replace(components=comps)
