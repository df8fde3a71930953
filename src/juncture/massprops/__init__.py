"""Mass properties: wing segments and rotors (Moulton & Hunsaker 2024), analytic solids.

Every producer returns a :class:`MassProperties` in project axes (x aft, y right, z up);
bodies add by the parallel-axis theorem, and negative densities subtract material.
"""

from .closed import surface_mass_properties
from .configuration import component_mass_properties, configuration_mass_properties
from .properties import MassProperties
from .rotor import Rotor, rotor_disk_integrals
from .solids import Cuboid, Cylinder, PointMass, Sphere
from .spec import evaluate_spec, format_table, load_spec, spec_report_json, validate_spec
from .thickness import (
    NACA4_PRESETS,
    ConstantThickness,
    CustomThickness,
    Diamond,
    Naca4,
    ThicknessDistribution,
)
from .wing import WingSegment, WingSegmentsResult, wing_segments_mass_properties

__all__ = [
    "MassProperties",
    "surface_mass_properties",
    "ThicknessDistribution",
    "Naca4",
    "Diamond",
    "ConstantThickness",
    "CustomThickness",
    "NACA4_PRESETS",
    "WingSegment",
    "WingSegmentsResult",
    "wing_segments_mass_properties",
    "Rotor",
    "rotor_disk_integrals",
    "Cuboid",
    "Cylinder",
    "Sphere",
    "PointMass",
    "load_spec",
    "validate_spec",
    "evaluate_spec",
    "spec_report_json",
    "format_table",
    "configuration_mass_properties",
    "component_mass_properties",
]
