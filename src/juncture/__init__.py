"""juncture: complete an airplane described as separate components into one surface.

Public API::

    import juncture as jc
    cfg = jc.read("deck.inp")        # wave-drag deck, LaWGS or juncture JSON, by content
    geo = jc.complete(cfg, fillet="cubic", keep_area=True)
    jc.write(geo, "out.wgs")         # by extension: .wgs .p3d .hess .stl .vtu .vtk .inp ...
    surface = jc.mesh(geo)           # one closed triangulated surface (both halves)
    jc.write_solids(geo, "x.step")   # CAD: one closed solid per component (or "fused")
    df = jc.sweep("study.toml")      # a design study: one row per case (pandas DataFrame)

Axes as in the wave-drag deck: x aft, y to starboard, z up; only the y >= 0 half is described.

The errors are imported with the package; ``read``, ``write``, ``complete`` and the value
classes are loaded on first use (PEP 562), so that ``import juncture`` and ``juncture
--version`` do not pay for numpy and the geometry modules until they are needed.
"""

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

__version__ = "0.1.0"

# name -> module that defines it, imported on first access
_LAZY = {"read": ".io", "write": ".io", "complete": ".completion",
         "CompleteOptions": ".options", "Geometry": ".geometry", "sweep": ".study",
         "mesh": ".surface.pipeline", "write_solids": ".surface.solids"}

__all__ = [
    "read",
    "write",
    "complete",
    "CompleteOptions",
    "Geometry",
    "sweep",
    "mesh",
    "write_solids",
    "JunctureError",
    "DeckError",
    "GeometryError",
    "ConvergenceError",
    "SpecError",
    "OptionError",
    "MissingDependencyError",
    "JunctureWarning",
    "__version__",
]


def __getattr__(name):
    if name in _LAZY:
        import importlib

        value = getattr(importlib.import_module(_LAZY[name], __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'juncture' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
