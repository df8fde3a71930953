"""Analysis of complete geometry: plane cuts (area distributions) and supersonic wave drag."""

from .areas import normal_area_distribution
from .closed import closed_networks
from .command import converged_wavedrag, wavedrag
from .cuts import mach_plane_areas, mach_plane_extents, normal_areas, plane_cut_areas
from .machplanes import mach_plane_area_distribution
from .wavedrag import (
    FarFieldResult,
    WaveDragResult,
    eminton_lord,
    eminton_lord_convergence,
    far_field_drag,
    roll_angles,
    sears_haack_area,
    sears_haack_drag,
    von_karman,
)

__all__ = [
    "normal_area_distribution",
    "mach_plane_area_distribution",
    "closed_networks",
    "wavedrag",
    "converged_wavedrag",
    "plane_cut_areas",
    "normal_areas",
    "mach_plane_areas",
    "mach_plane_extents",
    "WaveDragResult",
    "FarFieldResult",
    "eminton_lord",
    "eminton_lord_convergence",
    "von_karman",
    "far_field_drag",
    "roll_angles",
    "sears_haack_drag",
    "sears_haack_area",
]
