"""Fillets of the wing-body juncture: cubic arcs, circular arcs, added area (TM-4406)."""

from .area import fillet_added_area, polygon_disk_area, wedge_area
from .circular import circular_fillet
from .compensation import Compensate, Compensation, keep_area
from .cubic import cubic_fillet
from .lines import FilletLines, bezier, blend_factor, hermite
from .redesign import BodyReduction, reduced_body

__all__ = ["FilletLines", "cubic_fillet", "circular_fillet", "fillet_added_area", "keep_area",
           "BodyReduction", "reduced_body", "polygon_disk_area", "Compensation", "blend_factor",
           "hermite", "bezier", "wedge_area", "Compensate"]
