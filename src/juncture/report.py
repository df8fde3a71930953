"""Deprecated: the HTML report is :mod:`juncture.plots.report` (``juncture.plots.write_report``).

Importing this module still works and warns; it will be removed.
"""

import warnings

from .plots.report import render_report, wireframe_data, write_report

__all__ = ["write_report", "render_report", "wireframe_data"]

warnings.warn("juncture.report moved to juncture.plots (juncture.plots.write_report)",
              DeprecationWarning, stacklevel=2)
