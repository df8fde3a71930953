"""Figures a designer reads at a glance (matplotlib, Agg back end; no screen needed).

Every function takes a Geometry (or anything :func:`juncture.io.to_geometry` accepts) and
returns a matplotlib Figure; :func:`save` writes one atomically.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .io import to_geometry  # noqa: E402
from .io._registry import atomic_output  # noqa: E402

__all__ = ["plot_views", "plot_planform", "plot_side", "save"]

_VIEWS = {"planform": (0, 1, "x (aft)", "y (starboard)"), "side": (0, 2, "x (aft)", "z (up)"),
          "front": (1, 2, "y (starboard)", "z (up)")}


def _component(name):
    for part in (" upper", " lower", " outboard", " inboard", " segment", " image"):
        if part in name:
            name = name[: name.index(part)]
    return name


def _draw(ax, geo, view, mirror=True):
    i, j, xl, yl = _VIEWS[view]
    nets = geo.mirrored_networks() if mirror else dict(geo.networks)
    comps = sorted({_component(n) for n in nets})
    colours = dict(zip(comps, plt.cm.tab10(np.linspace(0, 1, 10))[: len(comps)]))
    if len(comps) > 10:
        colours = dict(zip(comps, plt.cm.tab20(np.linspace(0, 1, len(comps)))))
    seen = set()
    for name, net in nets.items():
        comp = _component(name)
        alpha = 0.35 if name.endswith(" image") else 0.9
        label = None if comp in seen else comp
        seen.add(comp)
        c = colours[comp]
        # n-lines (sections) and m-lines (lofting lines): one LineCollection-like call each.
        ax.plot(net[..., i].T, net[..., j].T, color=c, lw=0.5, alpha=alpha)
        ax.plot(net[..., i], net[..., j], color=c, lw=0.5, alpha=alpha)
        ax.plot([], [], color=c, label=label)
    ax.set_xlabel(xl)
    ax.set_ylabel(yl)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3, alpha=0.5)
    if view == "planform":
        ax.invert_yaxis()  # starboard down, nose left: the usual planform drawing


def plot_planform(obj, mirror=True, title=None):
    """Planform (x-y) of every network, n-lines and m-lines, images lighter. Returns a Figure."""
    geo = to_geometry(obj)
    fig, ax = plt.subplots(figsize=(10, 6), layout="constrained")
    _draw(ax, geo, "planform", mirror)
    ax.set_title(title or f"{geo.title or 'configuration'}: planform")
    ax.legend(fontsize=7, loc="best")
    return fig


def plot_side(obj, title=None):
    """Side view (x-z) of every network. Returns a Figure."""
    geo = to_geometry(obj)
    fig, ax = plt.subplots(figsize=(10, 4), layout="constrained")
    _draw(ax, geo, "side", mirror=False)
    ax.set_title(title or f"{geo.title or 'configuration'}: side view")
    ax.legend(fontsize=7, loc="best")
    return fig


def plot_views(obj, title=None):
    """Planform, side and front views on one Figure."""
    geo = to_geometry(obj)
    fig = plt.figure(figsize=(12, 9), layout="constrained")
    grid = fig.add_gridspec(2, 2, height_ratios=(2, 1))
    ax = fig.add_subplot(grid[0, :])
    _draw(ax, geo, "planform")
    ax.legend(fontsize=7, loc="best")
    _draw(fig.add_subplot(grid[1, 0]), geo, "side", mirror=False)
    _draw(fig.add_subplot(grid[1, 1]), geo, "front")
    fig.suptitle(title or geo.title or "configuration")
    return fig


def save(fig, path, dpi=130):
    """Write ``fig`` to ``path`` (format by extension) atomically, then close it."""
    fmt = str(path).rsplit(".", 1)[-1]
    with atomic_output(path, "wb") as fh:
        fig.savefig(fh, format=fmt, dpi=dpi)
    plt.close(fig)
