"""Figures and the HTML report of a run, one look throughout (matplotlib, Agg back end).

Modules, one job each:

==================  ==========================================================================
``style``           component colours (:func:`component_colour`) and unit labels
``views``           plan (from above, y up), side and front views at true scale
``juncture``        wing-body juncture figures after TM-4406 figs 3-10
``areas``           area distributions of wave-drag cases, titled with Mach number and method
``figures``         :func:`write_figures`: every figure of a run that applies, in one call
``report``          the self-contained HTML report (``report_css``, ``report_js`` inline)
``blend``           figures of the long-strake blend (Song, Ma & Wang)
``sweep``           figures and the one-page report of a design study (``juncture sweep``)
==================  ==========================================================================

Every figure function takes ``units`` (default ``"ft"``), the length unit written on its
axes: a label only, juncture never converts the deck's coordinates. Importing this package
imports no matplotlib (names load on first use, PEP 562); drawing selects the Agg back end
unless the program already imported ``matplotlib.pyplot``.
"""

from __future__ import annotations

import importlib

# public name -> submodule that defines it, imported on first access
_LAZY = {
    "component_colour": ".style", "component_of": ".style", "axis_label": ".style",
    "unit_label": ".style",
    "plot_views": ".views", "plot_planform": ".views", "plot_side": ".views",
    "plot_front": ".views",
    "main_pair": ".juncture", "plot_gap_and_intersection": ".juncture",
    "plot_lower_intersection": ".juncture", "plot_fillet_sections": ".juncture",
    "plot_station_areas": ".juncture",
    "plot_wavedrag_areas": ".areas", "plot_area_distribution": ".areas",
    "write_figures": ".figures", "run_figures": ".figures",
    "write_report": ".report", "render_report": ".report", "wireframe_data": ".report",
    "save": "._backend",
    "plot_against_parameters": ".sweep", "plot_scatter_matrix": ".sweep",
    "write_sweep_figures": ".sweep", "write_sweep_report": ".sweep",
    "render_sweep_report": ".sweep",
}

__all__ = list(_LAZY)


def __getattr__(name):
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name], __name__), name)
        globals()[name] = value
        return value
    if name == "plt":  # matplotlib.pyplot (Agg), for callers that drew with it before
        from ._backend import pyplot

        return pyplot()
    raise AttributeError(f"module 'juncture.plots' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
