"""Matplotlib, loaded on first use with the Agg back end (no screen), and atomic saving.

Nothing imports matplotlib when ``juncture`` or ``juncture.plots`` is imported: a figure
function calls :func:`pyplot` when it draws (matplotlib takes about as long to import as all
of juncture's geometry).
"""

from __future__ import annotations

__all__ = ["pyplot", "save", "GRID"]

#: Keyword arguments of the light grid every Cartesian axes gets.
GRID = {"lw": 0.3, "alpha": 0.5}


def pyplot():
    """``matplotlib.pyplot``, imported on first call with the Agg back end selected.

    A program that imported pyplot itself (a notebook, an application with a window) keeps
    the back end it chose.
    """
    import sys

    import matplotlib

    if "matplotlib.pyplot" not in sys.modules:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save(fig, path, dpi=130):
    """Write ``fig`` to ``path`` (format by extension) atomically, then close it.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    path : str or path-like
        ``.png``, ``.svg``, ``.pdf``, ...; a failed write leaves no partial file.
    dpi : float
        Resolution of raster formats.
    """
    from ..io._registry import atomic_output

    fmt = str(path).rsplit(".", 1)[-1]
    try:
        with atomic_output(path, "wb") as fh:
            fig.savefig(fh, format=fmt, dpi=dpi)
    finally:
        pyplot().close(fig)
