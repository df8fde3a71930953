"""Airfoil sections as the wave-drag deck gives them: percent-chord stations, camber, thickness.

A section is described at ``n`` chordwise stations ``x_over_c`` in percent of the chord
(0 = leading edge, 100 = trailing edge). At each station the mean line lies ``camber`` above the
chord line (absolute deck length units, as the deck's TZORD), and the surfaces lie
``upper`` / ``lower`` percent of the chord above / below the mean line (as WAFORD). For a fin or
pylon "upper" is the outboard (+y) side and "lower" the inboard side.

Between stations the offset is a shape-preserving cubic (PCHIP) in the chord fraction by
default, or linear on request (architecture.md, Interpolation).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import GeometryError
from ._arrays import check_finite, check_increasing, frozen
from ._pchip import pchip

__all__ = ["Airfoil", "ChordwiseInterpolation", "surface_offsets", "interpolate_chordwise"]

ChordwiseInterpolation = Literal["pchip", "linear"]


@dataclass(frozen=True, slots=True, eq=False)
class Airfoil:
    """One airfoil: stations in percent chord, camber [deck length], half-thicknesses [% chord].

    Parameters
    ----------
    x_over_c : (n,) float
        Chordwise stations, percent of chord, strictly increasing.
    upper : (n,) float
        Distance from the mean line to the upper (outboard) surface, percent of chord, >= 0.
    lower : (n,) float, optional
        Distance from the lower (inboard) surface to the mean line, percent of chord, >= 0.
        Defaults to ``upper`` (a symmetric section).
    camber : (n,) float, optional
        Height of the mean line above the chord line [deck length]. Defaults to zero.
    """

    x_over_c: np.ndarray
    upper: np.ndarray
    lower: np.ndarray = None
    camber: np.ndarray = None
    name: str = "airfoil"

    def __post_init__(self):
        x = frozen(self.x_over_c, (None,), self.name, "x_over_c")
        n = x.size
        up = frozen(self.upper, (n,), self.name, "upper half-thickness")
        lo = up if self.lower is None else frozen(self.lower, (n,), self.name,
                                                   "lower half-thickness")
        cam = frozen(np.zeros(n) if self.camber is None else self.camber, (n,), self.name,
                     "camber")
        if n < 2:
            raise GeometryError(f"an airfoil needs at least 2 stations, found {n}", self.name)
        for arr, what in ((x, "x_over_c"), (up, "upper"), (lo, "lower"), (cam, "camber")):
            check_finite(arr, self.name, what)
        check_increasing(x, self.name, "x_over_c")
        for arr, what in ((up, "upper half-thickness"), (lo, "lower half-thickness")):
            if (arr < 0).any():
                k = int(np.argmax(arr < 0))
                raise GeometryError(f"{what} is negative ({arr[k]:g} % chord)", self.name, k + 1)
        object.__setattr__(self, "x_over_c", x)
        object.__setattr__(self, "upper", up)
        object.__setattr__(self, "lower", lo)
        object.__setattr__(self, "camber", cam)

    @property
    def symmetric(self):
        """True if the upper and lower half-thicknesses are equal and there is no camber."""
        return bool(np.array_equal(self.upper, self.lower) and not self.camber.any())


def surface_offsets(camber, upper, lower, chord):
    """Offsets of the two surfaces from the chord line [deck length], vectorised over sections.

    Parameters
    ----------
    camber, upper, lower : (..., n) float
        Camber [deck length] and half-thicknesses [% chord] at the stations.
    chord : (...) float
        Chord of each section [deck length].

    Returns
    -------
    (2, ..., n) float
        ``[upper_offset, lower_offset]`` = camber +/- chord * half-thickness / 100
        (TM-4406: semithickness added to / subtracted from the camber ordinate).
    """
    c = np.asarray(chord, dtype=float)[..., None]
    return np.stack([camber + c * upper / 100.0, camber - c * lower / 100.0])


def interpolate_chordwise(x_over_c, offsets, fraction, method: ChordwiseInterpolation = "pchip"):
    """Offsets at chord fractions, along every section at once.

    Parameters
    ----------
    x_over_c : (n,) float
        Station positions [% chord], shared by all sections.
    offsets : (..., n) float
        Offsets at the stations for any number of sections.
    fraction : (m,) float
        Chord fractions in [0, 1] (0 = leading edge).
    method : {"pchip", "linear"}

    Returns
    -------
    (..., m) float
    """
    t = np.asarray(x_over_c, dtype=float) / 100.0
    f = np.asarray(fraction, dtype=float)
    off = np.asarray(offsets, dtype=float)
    if method == "linear":
        k = np.clip(np.searchsorted(t, f, side="right") - 1, 0, t.size - 2)
        w = (f - t[k]) / (t[k + 1] - t[k])
        return off[..., k] * (1.0 - w) + off[..., k + 1] * w
    if method != "pchip":
        raise GeometryError(f"chordwise interpolation must be 'pchip' or 'linear', found "
                            f"{method!r}")
    # pchip interpolates along axis 0 for any trailing shape: one call for all sections.
    # Outside the stations it extrapolates with the end cubics.
    return np.moveaxis(pchip(t, np.moveaxis(off, -1, 0), f), 0, -1)
