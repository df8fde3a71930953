"""Deprecated: the wing-body figures are :mod:`juncture.plots.juncture` (``juncture.plots``).

Importing this module still works and warns; it will be removed.
"""

import warnings

from .plots.juncture import (
    plot_fillet_sections,
    plot_gap_and_intersection,
    plot_lower_intersection,
    plot_station_areas,
)

__all__ = ["plot_gap_and_intersection", "plot_lower_intersection", "plot_fillet_sections",
           "plot_station_areas"]

warnings.warn("juncture.plots_juncture moved to juncture.plots", DeprecationWarning,
              stacklevel=2)
