"""Analytic solids of constant density: cuboid, (hollow) cylinder, (hollow) sphere, point mass.

Building blocks for spars, actuators, lightening holes and the like (Moulton & Hunsaker
section 5). Each returns a :class:`MassProperties` in project axes; a negative density (or
mass) removes material and gives a negative mass and volume.

Textbook moments about the CG (m = mass):

=========================  =================================  ===============================
solid                      axial / principal                  transverse
=========================  =================================  ===============================
cuboid a x b x c           Ixx = m (b^2 + c^2) / 12, ...      (box axes)
cylinder R, r, length L    m (R^2 + r^2) / 2                  m (3 (R^2 + r^2) + L^2) / 12
sphere R, r                2 m (R^5 - r^5) / (5 (R^3 - r^3))  (same about every axis)
=========================  =================================  ===============================
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import GeometryError
from .properties import MassProperties

__all__ = ["Cuboid", "Cylinder", "Sphere", "PointMass"]


def _vec3(value, what, who):
    arr = np.array(value, dtype=float)
    if arr.shape != (3,) or not np.all(np.isfinite(arr)):
        raise GeometryError(f"{what} must be 3 finite numbers, found {np.asarray(value).tolist()}",
                            component=who)
    arr.flags.writeable = False
    return arr


def _positive(value, what, who, allow_zero=False):
    v = float(value)
    if not np.isfinite(v) or v < 0 or (v == 0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise GeometryError(f"{what} must be {bound}, found {value!r}", component=who)
    return v


def _density(volume, density, mass, who):
    if (density is None) == (mass is None):
        raise GeometryError("give exactly one of density and mass", component=who)
    rho = float(density) if mass is None else float(mass) / volume
    if not np.isfinite(rho):
        raise GeometryError(f"density must be finite, found {rho}", component=who)
    return rho


@dataclass(frozen=True, slots=True, eq=False)
class Cuboid:
    """A rectangular box.

    Parameters
    ----------
    center : (3,) float
        Centre [length].
    size : (3,) float
        Edge lengths along the box axes [length], > 0.
    axes : (3, 3) float, optional
        Rows are the box axes (unit vectors, orthonormal) in project axes; default the project
        axes themselves.
    name : str, optional

    Examples
    --------
    >>> p = Cuboid([0, 0, 0], [1, 1, 1]).mass_properties(density=1.0)
    >>> round(float(p.inertia[0, 0]), 12)                             # 1/6
    0.166666666667
    """

    center: object
    size: object
    axes: object = None
    name: str | None = None

    def __post_init__(self):
        who = self.name or "cuboid"
        object.__setattr__(self, "center", _vec3(self.center, "center", who))
        size = _vec3(self.size, "size", who)
        if np.any(size <= 0):
            raise GeometryError(f"size must be > 0 along every axis, found {size.tolist()}",
                                component=who)
        object.__setattr__(self, "size", size)
        axes = np.eye(3) if self.axes is None else np.array(self.axes, dtype=float)
        if axes.shape != (3, 3) or not np.all(np.isfinite(axes)) or \
                np.abs(axes @ axes.T - np.eye(3)).max() > 1e-9:
            raise GeometryError(f"axes must be 3 orthonormal rows (3 x 3), found "
                                f"{np.asarray(self.axes).tolist()}", component=who)
        axes.flags.writeable = False
        object.__setattr__(self, "axes", axes)

    def mass_properties(self, density=None, mass=None) -> MassProperties:
        """Mass properties from a density [mass / length^3] or a mass [mass] (exactly one)."""
        vol = float(np.prod(self.size))
        rho = _density(vol, density, mass, self.name or "cuboid")
        m = rho * vol
        a2 = self.size ** 2
        local = np.diag(m / 12.0 * (a2.sum() - a2))
        inertia = self.axes.T @ local @ self.axes
        return MassProperties(m, np.sign(rho) * vol, self.center, inertia, self.name)


@dataclass(frozen=True, slots=True, eq=False)
class Cylinder:
    """A right circular cylinder, solid or a tube.

    Parameters
    ----------
    center : (3,) float
        Centre (mid-length on the axis) [length].
    axis : (3,) float
        Axis direction, normalised on input.
    radius : float
        Outer radius R [length], > 0.
    length : float
        Length L along the axis [length], > 0.
    inner_radius : float
        Bore radius r, 0 <= r < R [length].
    name : str, optional

    Examples
    --------
    >>> p = Cylinder([0, 0, 0], [0, 0, 1], radius=1.0, length=2.0).mass_properties(density=1.0)
    >>> round(p.volume, 9), round(float(p.inertia[2, 2]), 9)          # 2 pi, m R^2 / 2 = pi
    (6.283185307, 3.141592654)
    """

    center: object
    axis: object
    radius: float
    length: float
    inner_radius: float = 0.0
    name: str | None = None

    def __post_init__(self):
        who = self.name or "cylinder"
        object.__setattr__(self, "center", _vec3(self.center, "center", who))
        axis = np.array(_vec3(self.axis, "axis", who))
        if np.linalg.norm(axis) == 0:
            raise GeometryError("axis must be non-zero, found [0, 0, 0]", component=who)
        axis = axis / np.linalg.norm(axis)
        axis.flags.writeable = False
        object.__setattr__(self, "axis", axis)
        r_out = _positive(self.radius, "radius", who)
        length = _positive(self.length, "length", who)
        r_in = _positive(self.inner_radius, "inner_radius", who, allow_zero=True)
        if r_in >= r_out:
            raise GeometryError(f"expected inner_radius < radius, found {r_in} >= {r_out}",
                                component=who)
        object.__setattr__(self, "radius", r_out)
        object.__setattr__(self, "length", length)
        object.__setattr__(self, "inner_radius", r_in)

    def mass_properties(self, density=None, mass=None) -> MassProperties:
        """Mass properties from a density [mass / length^3] or a mass [mass] (exactly one)."""
        rr2 = self.radius ** 2 + self.inner_radius ** 2
        vol = np.pi * (self.radius ** 2 - self.inner_radius ** 2) * self.length
        rho = _density(vol, density, mass, self.name or "cylinder")
        m = rho * vol
        i_axial = 0.5 * m * rr2
        i_trans = m * (3.0 * rr2 + self.length ** 2) / 12.0
        inertia = i_trans * np.eye(3) + (i_axial - i_trans) * np.outer(self.axis, self.axis)
        return MassProperties(m, np.sign(rho) * vol, self.center, inertia, self.name)


@dataclass(frozen=True, slots=True, eq=False)
class Sphere:
    """A solid sphere or a spherical shell.

    Parameters
    ----------
    center : (3,) float
        [length].
    radius : float
        Outer radius R > 0 [length].
    inner_radius : float
        Inner radius r, 0 <= r < R [length].
    name : str, optional

    Examples
    --------
    >>> p = Sphere([0, 0, 0], 1.0).mass_properties(mass=5.0)
    >>> round(float(p.inertia[1, 1]), 12)                              # 2/5 m R^2
    2.0
    """

    center: object
    radius: float
    inner_radius: float = 0.0
    name: str | None = None

    def __post_init__(self):
        who = self.name or "sphere"
        object.__setattr__(self, "center", _vec3(self.center, "center", who))
        r_out = _positive(self.radius, "radius", who)
        r_in = _positive(self.inner_radius, "inner_radius", who, allow_zero=True)
        if r_in >= r_out:
            raise GeometryError(f"expected inner_radius < radius, found {r_in} >= {r_out}",
                                component=who)
        object.__setattr__(self, "radius", r_out)
        object.__setattr__(self, "inner_radius", r_in)

    def mass_properties(self, density=None, mass=None) -> MassProperties:
        """Mass properties from a density [mass / length^3] or a mass [mass] (exactly one)."""
        big, small = self.radius, self.inner_radius
        vol = 4.0 / 3.0 * np.pi * (big ** 3 - small ** 3)
        rho = _density(vol, density, mass, self.name or "sphere")
        # 2/5 m (R^5 - r^5) / (R^3 - r^3) written as 8/15 pi rho (R^5 - r^5)
        i = 8.0 / 15.0 * np.pi * rho * (big ** 5 - small ** 5)
        return MassProperties(rho * vol, np.sign(rho) * vol, self.center, i * np.eye(3),
                              self.name)


@dataclass(frozen=True, slots=True, eq=False)
class PointMass:
    """A concentrated mass (engine, pilot, battery) at ``center``: no volume, no own inertia.

    Parameters
    ----------
    center : (3,) float
        [length].
    mass : float
        [mass].
    name : str, optional
    """

    center: object
    mass: float
    name: str | None = None

    def __post_init__(self):
        object.__setattr__(self, "center", _vec3(self.center, "center", self.name or "point"))
        if not np.isfinite(float(self.mass)):
            raise GeometryError(f"mass must be finite, found {self.mass!r}",
                                component=self.name or "point")

    def mass_properties(self) -> MassProperties:
        """The point mass as a MassProperties."""
        return MassProperties.point(float(self.mass), self.center, self.name)
