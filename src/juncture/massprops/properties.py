"""MassProperties: mass, volume, centre of gravity and inertia tensor of a rigid body.

One value type for every mass-properties producer (wing segments, rotors, analytic solids) and
one implementation of the parallel-axis theorem, :func:`combine_arrays`, used both by
``MassProperties.__add__`` / :meth:`MassProperties.sum` and by the vectorised batch forms.

Axes are the project axes: x aft, y right (starboard), z up.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import GeometryError

__all__ = ["MassProperties", "combine_arrays", "parallel_axis_term"]

_PLANE_AXIS = {"yz": 0, "xz": 1, "xy": 2}


def parallel_axis_term(mass, offset):
    """Steiner term ``m [(s.s) E - s s^T]`` (Moulton & Hunsaker eq 56).

    Parameters
    ----------
    mass : (...) float
        Mass [mass].
    offset : (..., 3) float
        Vector ``s`` from the CG to the reference point [length].

    Returns
    -------
    (..., 3, 3) float
        Add it to the inertia about the CG to get the inertia about the point [mass length^2].
    """
    s = np.asarray(offset, dtype=float)
    m = np.asarray(mass, dtype=float)
    ss = np.einsum("...i,...i->...", s, s)
    term = ss[..., None, None] * np.eye(3) - s[..., :, None] * s[..., None, :]
    return m[..., None, None] * term


def combine_arrays(mass, volume, cg, inertia, axis=0):
    """Combine bodies along ``axis`` by the parallel-axis theorem (vectorised).

    Parameters
    ----------
    mass, volume : (..., k, ...) float
        Masses [mass] and signed volumes [length^3] of the bodies to combine.
    cg : (..., k, ..., 3) float
        Centres of gravity [length].
    inertia : (..., k, ..., 3, 3) float
        Inertia tensors about each body's own CG [mass length^2].
    axis : int
        The axis of ``mass`` along which bodies are combined.

    Returns
    -------
    mass, volume, cg, inertia
        Totals with ``axis`` removed. Inertia is about the combined CG.

    Raises
    ------
    GeometryError
        If a combined mass is zero while its parts are not (the CG is then undefined).
    """
    m = np.asarray(mass, dtype=float)
    ax = axis % m.ndim
    c = np.moveaxis(np.asarray(cg, dtype=float), ax, -2)
    i_cg = np.moveaxis(np.asarray(inertia, dtype=float), ax, -3)
    mm = np.moveaxis(m, ax, -1)
    total = mm.sum(axis=-1)
    scale = np.abs(mm).sum(axis=-1)
    bad = (np.abs(total) <= 1e-14 * scale) & (scale > 0)
    if np.any(bad):
        raise GeometryError("the combined mass is zero (parts cancel), so the centre of gravity "
                            "is undefined; expected a non-zero total mass")
    safe = np.where(total == 0.0, 1.0, total)
    cg_total = np.einsum("...k,...ki->...i", mm, c) / safe[..., None]
    s = c - cg_total[..., None, :]
    inertia_total = (i_cg + parallel_axis_term(mm, s)).sum(axis=-3)
    vol = np.asarray(volume, dtype=float).sum(axis=ax)
    return total, vol, cg_total, inertia_total


def _frozen(value, shape, what):
    arr = np.array(value, dtype=float)
    if arr.shape != shape:
        raise GeometryError(f"{what} must have shape {shape}, found {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise GeometryError(f"{what} must be finite, found {arr.tolist()}")
    arr.flags.writeable = False
    return arr


@dataclass(frozen=True, slots=True, eq=False)
class MassProperties:
    """Mass, volume, centre of gravity and inertia tensor about the CG of a rigid body.

    The inertia tensor is the matrix ``I`` with ``L = I @ omega``: moments on the diagonal and
    products of inertia with a minus sign off the diagonal.

    ==========  ==========================  ============================
    element     value                       note
    ==========  ==========================  ============================
    I[0, 0]     integral (y^2 + z^2) dm     Ixx, roll
    I[1, 1]     integral (x^2 + z^2) dm     Iyy, pitch
    I[2, 2]     integral (x^2 + y^2) dm     Izz, yaw
    I[0, 1]     - integral x y dm           = I[1, 0]
    I[0, 2]     - integral x z dm           = I[2, 0]
    I[1, 2]     - integral y z dm           = I[2, 1]
    ==========  ==========================  ============================

    Coordinates are measured from the CG for :attr:`inertia` and from the given point for
    :meth:`inertia_about`. Axes are the project axes: x aft, y right, z up.

    A body given a negative density (a lightening hole, the inner surface of a skin) has a
    negative mass *and* a negative volume, so that sums give the material volume.

    Attributes
    ----------
    mass : float
        Mass [mass]; negative for a removal.
    volume : float
        Signed volume [length^3]; its sign is that of the density.
    cg : (3,) float
        Centre of gravity [length], read-only.
    inertia : (3, 3) float
        Inertia tensor about the CG [mass length^2], symmetric, read-only.
    name : str or None
        Optional label carried into :meth:`to_dict`.

    Examples
    --------
    >>> import numpy as np
    >>> a = MassProperties(1.0, 1.0, [0, 0, 0], np.eye(3) / 6)   # unit cube, unit density
    >>> b = a.shifted([1.0, 0.0, 0.0])
    >>> round(float((a + b).inertia[2, 2]), 6)                    # 2/6 + 2 * 0.5**2
    0.833333
    """

    mass: float
    volume: float
    cg: object
    inertia: object
    name: str | None = None

    def __post_init__(self):
        mass = float(self.mass)
        volume = float(self.volume)
        if not (np.isfinite(mass) and np.isfinite(volume)):
            raise GeometryError(f"mass and volume must be finite, found {mass}, {volume}")
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "volume", volume)
        object.__setattr__(self, "cg", _frozen(self.cg, (3,), "cg"))
        inertia = np.array(self.inertia, dtype=float)
        if inertia.shape == (3, 3):
            inertia = 0.5 * (inertia + inertia.T)
        object.__setattr__(self, "inertia", _frozen(inertia, (3, 3), "inertia"))
        if self.name is not None:
            object.__setattr__(self, "name", str(self.name))

    # ---------------------------------------------------------------- construction
    @classmethod
    def zero(cls, name=None):
        """The empty body: no mass, no volume, CG at the origin."""
        return cls(0.0, 0.0, np.zeros(3), np.zeros((3, 3)), name)

    @classmethod
    def point(cls, mass, position, name=None):
        """A point mass at ``position`` (3,) [length]: zero volume and zero inertia about it."""
        return cls(mass, 0.0, position, np.zeros((3, 3)), name)

    @classmethod
    def sum(cls, items, name=None):
        """Combine any number of bodies at once (parallel-axis theorem).

        Parameters
        ----------
        items : iterable of MassProperties
        name : str, optional
            Name of the result.

        Returns
        -------
        MassProperties
            The zero body for an empty iterable.
        """
        items = list(items)
        items = [p for p in items if not p._is_zero()]
        if not items:
            return cls.zero(name)
        m, v, c, i = combine_arrays(np.array([p.mass for p in items]),
                                    np.array([p.volume for p in items]),
                                    np.array([p.cg for p in items]),
                                    np.array([p.inertia for p in items]))
        return cls(m, v, c, i, name)

    def _is_zero(self):
        return self.mass == 0.0 and self.volume == 0.0 and not np.any(self.inertia)

    def __add__(self, other):
        if not isinstance(other, MassProperties):
            return NotImplemented
        return MassProperties.sum([self, other])

    def __radd__(self, other):
        if isinstance(other, (int, float)) and other == 0:  # builtin sum() starts from 0
            return self
        return NotImplemented

    # ---------------------------------------------------------------- queries
    def inertia_about(self, point):
        """Inertia tensor about ``point`` (3,) [length], axes parallel to the project axes.

        Returns
        -------
        (3, 3) float
            ``I_cg + m [(s.s) E - s s^T]`` with ``s = cg - point`` (Moulton & Hunsaker eq 56).
        """
        p = np.asarray(point, dtype=float)
        if p.shape != (3,):
            raise GeometryError(f"point must have shape (3,), found {p.shape}")
        return self.inertia + parallel_axis_term(self.mass, self.cg - p)

    @property
    def inertia_origin(self):
        """Inertia tensor about the origin of the project axes, (3, 3) [mass length^2]."""
        return self.inertia_about(np.zeros(3))

    @property
    def principal_moments(self):
        """Principal moments of inertia about the CG, ascending, (3,) [mass length^2]."""
        return np.linalg.eigvalsh(self.inertia)

    def is_physical(self, rtol=1e-9):
        """Whether this can be a real body: mass >= 0, principal moments >= 0 and each
        no larger than the sum of the other two (triangle inequality), within ``rtol``."""
        lam = self.principal_moments
        tol = rtol * max(float(np.abs(lam).max()), 1e-300)
        if self.mass < 0 or lam[0] < -tol:
            return False
        return bool(lam[2] <= lam[0] + lam[1] + tol)

    def allclose(self, other, rtol=1e-9, atol=None):
        """Compare with another MassProperties.

        ``atol=None`` scales the absolute tolerance with the body: ``rtol`` times the largest
        inertia element for the inertia, ``rtol`` times the largest of |cg| and the radius of
        gyration for the CG, ``rtol`` times |mass| and |volume| for mass and volume.
        """
        if atol is None:
            a_i = rtol * max(np.abs(self.inertia).max(), np.abs(other.inertia).max())
            gyr = np.sqrt(np.abs(np.trace(self.inertia)) / max(abs(self.mass), 1e-300))
            a_c = rtol * max(np.abs(self.cg).max(), np.abs(other.cg).max(), gyr)
            a_m = rtol * max(abs(self.mass), abs(other.mass))
            a_v = rtol * max(abs(self.volume), abs(other.volume))
        else:
            a_i = a_c = a_m = a_v = atol
        return bool(np.isclose(self.mass, other.mass, rtol=rtol, atol=a_m)
                    and np.isclose(self.volume, other.volume, rtol=rtol, atol=a_v)
                    and np.allclose(self.cg, other.cg, rtol=rtol, atol=a_c)
                    and np.allclose(self.inertia, other.inertia, rtol=rtol, atol=a_i))

    # ---------------------------------------------------------------- transforms
    def renamed(self, name):
        """The same body with another name."""
        return MassProperties(self.mass, self.volume, self.cg, self.inertia, name)

    def shifted(self, offset):
        """The body translated by ``offset`` (3,) [length]; the inertia about the CG is kept."""
        off = np.asarray(offset, dtype=float)
        if off.shape != (3,):
            raise GeometryError(f"offset must have shape (3,), found {off.shape}")
        return MassProperties(self.mass, self.volume, self.cg + off, self.inertia, self.name)

    def rotated(self, matrix):
        """The body rotated by an orthogonal ``matrix`` (3, 3) about the project origin.

        ``cg -> R cg`` and ``I -> R I R^T``. A reflection (det = -1) is accepted too.

        Raises
        ------
        GeometryError
            If the matrix is not (3, 3) or not orthogonal to 1e-9.
        """
        r = np.asarray(matrix, dtype=float)
        if r.shape != (3, 3):
            raise GeometryError(f"rotation matrix must have shape (3, 3), found {r.shape}")
        err = np.abs(r @ r.T - np.eye(3)).max()
        if not err <= 1e-9:
            raise GeometryError(f"rotation matrix must be orthogonal (R R^T = E), found "
                                f"max |R R^T - E| = {err:.3g}")
        return MassProperties(self.mass, self.volume, r @ self.cg, r @ self.inertia @ r.T,
                              self.name)

    def mirrored(self, plane: Literal["xz", "xy", "yz"] = "xz"):
        """Mirror image in a coordinate plane through the origin (``"xz"``: y -> -y)."""
        if plane not in _PLANE_AXIS:
            raise GeometryError(f"mirror plane must be one of 'xz', 'xy', 'yz', found {plane!r}")
        d = np.ones(3)
        d[_PLANE_AXIS[plane]] = -1.0
        return MassProperties(self.mass, self.volume, self.cg * d,
                              self.inertia * np.outer(d, d), self.name)

    # ---------------------------------------------------------------- output
    def to_dict(self):
        """Plain-Python form: ``{"name"?, "mass", "volume", "cg", "inertia_cg",
        "inertia_origin"}`` (``"name"`` only when set); tensors as nested lists."""
        out = {} if self.name is None else {"name": self.name}
        out.update(mass=self.mass, volume=self.volume, cg=self.cg.tolist(),
                   inertia_cg=self.inertia.tolist(), inertia_origin=self.inertia_origin.tolist())
        return out

    def __repr__(self):
        n = "" if self.name is None else f"name={self.name!r}, "
        return (f"MassProperties({n}mass={self.mass:.6g}, volume={self.volume:.6g}, "
                f"cg={np.array2string(self.cg, precision=6)}, "
                f"inertia_diag={np.array2string(np.diag(self.inertia), precision=6)})")
