"""The figures of a run, written in one call: what ``juncture complete --figures`` and
``juncture demo`` write, and what the report shows.

Every figure is drawn if it applies to the geometry and skipped otherwise, with a
:class:`~juncture.errors.JunctureWarning` naming it and the reason: a configuration without a
wing-body intersection gets the three views only, a sharp (unfilleted) one no fillet
figures. Nothing here depends on what the components are called.
"""

from __future__ import annotations

import warnings
from pathlib import Path

from ..errors import JunctureError, JunctureWarning
from ._backend import pyplot, save
from .juncture import (
    plot_fillet_sections,
    plot_gap_and_intersection,
    plot_lower_intersection,
    plot_station_areas,
)
from .style import DEFAULT_UNITS
from .views import plot_views

__all__ = ["FIGURES", "run_figures", "write_figures"]

#: File name -> (caption, whether it shows the fillet), in the order written.
FIGURES = {
    "views.png": ("three views: plan from above, side from port, front from ahead", False),
    "intersection.png": ("the wing root, the body and the upper intersection line "
                         "(TM-4406 fig 3)", False),
    "lower_intersection.png": ("lower-surface intersection and fillet start lines "
                               "(TM-4406 fig 4)", False),
    "fillet_sections.png": ("fillet lines at constant x (TM-4406 figs 6-9)", True),
    "areas.png": ("cross-sectional areas at the fillet stations", True),
}


def _draw(name, cfg, geo, units):
    if name == "views.png":
        return plot_views(geo, units=units)
    if name == "intersection.png":
        return plot_gap_and_intersection(cfg, geo, units=units)
    if name == "lower_intersection.png":
        return plot_lower_intersection(cfg, geo, units=units)
    if name == "fillet_sections.png":
        return plot_fillet_sections(cfg, geo, units=units)
    return plot_station_areas(geo, units=units)


def run_figures(cfg, geo, *, fillet, units=DEFAULT_UNITS, warn=True):
    """Draw the figures of :data:`FIGURES` that apply; yield ``(file name, caption, Figure)``.

    Parameters
    ----------
    cfg : Configuration or None
        The input configuration; None: the geometry's own model.
    geo : Geometry
        From :func:`juncture.complete` (any Geometry: the figures that need a wing-body
        intersection or a fillet are skipped without one).
    fillet : str, bool or None
        The fillet of the run (``"cubic"``, ``"circular"``) or None: the fillet figures are
        drawn only with a fillet.
    units : str
        Length unit on the axes (default ``"ft"``; a label only, nothing is converted).
    warn : bool
        Warn (:class:`~juncture.errors.JunctureWarning`) for each figure skipped.

    Yields
    ------
    (str, str, matplotlib.figure.Figure)
        The caller closes (or saves, :func:`juncture.plots.save`) each figure.
    """
    for name, (caption, needs_fillet) in FIGURES.items():
        if needs_fillet and not fillet:
            continue
        before = set(pyplot().get_fignums())
        try:
            fig = _draw(name, cfg, geo, units)
        except BaseException as exc:
            for num in set(pyplot().get_fignums()) - before:  # a figure begun, not finished
                pyplot().close(num)
            if not isinstance(exc, JunctureError):
                raise
            if warn:
                warnings.warn(f"{name} skipped: {exc}", JunctureWarning, stacklevel=3)
            continue
        yield name, caption, fig


def write_figures(cfg, geo, out_dir, *, fillet, units=DEFAULT_UNITS):
    """Write the run's figures into ``out_dir``; return the file names written.

    ``views.png`` (plan, side and front views), ``intersection.png`` and
    ``lower_intersection.png`` (the wing-body intersection), and with a fillet
    ``fillet_sections.png`` and ``areas.png``. A figure that does not apply to the geometry
    (no wing, or a wing that meets no body; no fillet) is skipped with a warning, never an
    error.

    Parameters
    ----------
    cfg : Configuration or None
        The input configuration; None: the geometry's own model.
    geo : Geometry
        From :func:`juncture.complete`.
    out_dir : str or path-like
        An existing directory; each file is written atomically.
    fillet : str or None
        The fillet of the run (``"cubic"``, ``"circular"``) or None (no fillet figures).
    units : str
        Length unit written on every axis (default ``"ft"``, the unit of the bundled
        transport and of most Harris decks). A label only: the deck's coordinates are never
        converted.

    Returns
    -------
    list of str
        File names written, in :data:`FIGURES` order.

    Examples
    --------
    >>> import juncture as jc, tempfile, warnings; warnings.simplefilter("ignore")
    >>> from juncture.cli import bundled_example
    >>> cfg = jc.read(bundled_example())
    >>> write_figures(cfg, jc.complete(cfg), tempfile.mkdtemp(), fillet=None, units="ft")
    ['views.png', 'intersection.png', 'lower_intersection.png']
    """
    out, written = Path(out_dir), []
    for name, _, fig in run_figures(cfg, geo, fillet=fillet, units=units):
        save(fig, out / name)  # closes the figure; the next one is drawn only then
        written.append(name)
    return written
