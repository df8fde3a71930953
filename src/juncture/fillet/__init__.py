"""Fillets of the wing-body juncture: cubic arcs, circular arcs, added area (TM-4406)."""

from .area import (
    BodyReduction,
    Compensate,
    Compensation,
    fillet_added_area,
    keep_area,
    polygon_disk_area,
    reduced_body,
    wedge_area,
)
from .circular import circular_fillet
from .cubic import cubic_fillet
from .lines import FilletLines, bezier, blend_factor, hermite

__all__ = ["FilletLines", "cubic_fillet", "circular_fillet", "fillet_added_area", "keep_area",
           "BodyReduction", "reduced_body", "polygon_disk_area", "Compensation", "blend_factor",
           "hermite", "bezier", "wedge_area", "Compensate"]
