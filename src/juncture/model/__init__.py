"""The component model: airfoils, wing-like surfaces, bodies and configurations (no I/O)."""

from .airfoil import Airfoil, interpolate_chordwise, surface_offsets
from .body import ArbitraryBody, CircularBody
from .configuration import Component, Configuration, rebuilt
from .winglike import WingLike

__all__ = ["Airfoil", "WingLike", "CircularBody", "ArbitraryBody", "Configuration", "Component",
           "rebuilt", "surface_offsets", "interpolate_chordwise"]
