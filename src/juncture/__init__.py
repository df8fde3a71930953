"""juncture: complete an airplane described as separate components into one surface.

Public API::

    import juncture as jc
    cfg = jc.read("deck.inp")        # wave-drag deck, LaWGS or juncture JSON, by content
    jc.write(cfg, "out.wgs")         # by extension: .wgs .p3d .hess .stl .vtk .inp

Axes as in the wave-drag deck: x aft, y to starboard, z up; only the y >= 0 half is described.
"""

from .complete import CompleteOptions, complete
from .errors import (
                     ConvergenceError,
                     DeckError,
                     GeometryError,
                     JunctureError,
                     JunctureWarning,
                     MissingDependencyError,
                     OptionError,
                     SpecError,
)
from .geometry import Geometry
from .io import read, write

__version__ = "0.1.0"

__all__ = [
    "read",
    "write",
    "complete",
    "CompleteOptions",
    "Geometry",
    "JunctureError",
    "DeckError",
    "GeometryError",
    "ConvergenceError",
    "SpecError",
    "MissingDependencyError",
    "OptionError",
    "JunctureWarning",
    "__version__",
]
