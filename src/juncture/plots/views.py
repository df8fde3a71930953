"""Plan, side and front views of a configuration or geometry, at true scale.

The views follow a three-view drawing and the report's 3-D viewer: the plan view is seen from
above (x aft to the right, y to starboard *up*), the side view from port (x to the right, z
up) and the front view from ahead (z up, starboard on the *left*). Every network is drawn as
its n-lines (sections) and m-lines (lofting lines) in its component's colour
(:func:`juncture.plots.style.component_colour`); mirror images lighter; fillets, when the
geometry has them, in the fillet colour. Axes have equal scales and tight limits, and the
figure is sized to the airplane's proportions.
"""

from __future__ import annotations

import numpy as np

from ._backend import GRID, pyplot
from .style import DEFAULT_UNITS, axis_label, component_colour, component_of

__all__ = ["plot_views", "plot_planform", "plot_side", "plot_front"]

# view -> (horizontal axis, vertical axis, axes title); indices into (x, y, z)
_VIEWS = {"plan": (0, 1, "plan view, from above"),
          "side": (0, 2, "side view, from port"),
          "front": (1, 2, "front view, from ahead (starboard on the left)")}
_QUANTITY = ("x, aft", "y, starboard", "z, up")
_PAD = 0.03  # margin around the drawing, as a fraction of its largest extent


def _geometry(obj):
    """(Geometry, (component names, aliases)) of a Geometry, Configuration or mapping of
    networks; see :func:`juncture.plots.style.component_of`."""
    from ..io._registry import to_geometry
    from .juncture import network_aliases

    geo = to_geometry(obj)
    model = geo.configuration if geo.configuration is not None else (
        obj if hasattr(obj, "components") else None)
    if model is None:
        return geo, ((), {})
    return geo, (tuple(c.name for c in model), network_aliases(model, geo))


def _fillet_networks(geo, mirror):
    """The fillets as networks named ``"fillet ..."``, with their images where the wing
    has one (any xz-symmetric network)."""
    out = {name: np.asarray(f, float) for name, f in geo.fillets.items() if np.size(f)}
    if mirror and "xz" in set(geo.symmetry.values()):
        out.update({f"{k} image": v * np.array([1.0, -1.0, 1.0]) for k, v in list(out.items())})
    return out


def _draw(ax, geo, components, view, mirror, units, limits):
    """Draw every network (and fillet) on ``ax`` in ``view`` within ``limits`` ((2, 2):
    lower and upper bounds of the two screen axes); return the legend handles.
    ``components``: (names, aliases) from :func:`_geometry`."""
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D

    i, j, title = _VIEWS[view]
    nets = geo.mirrored_networks() if mirror else dict(geo.networks)
    nets.update(_fillet_networks(geo, mirror))
    handles = {}
    for name, net in nets.items():
        comp = component_of(name, *components)
        colour = component_colour(comp)
        xy = net[..., [i, j]]
        fillet = name.startswith("fillet")
        # A fillet: its station arcs and its two edges; any other network: every line.
        segs = list(xy) + (list(xy.transpose(1, 0, 2)[[0, -1]] if fillet else
                                xy.transpose(1, 0, 2)) if xy.shape[0] > 1 else [])
        image = name.endswith(" image")
        ax.add_collection(LineCollection(segs, colors=colour, alpha=0.4 if image else 0.9,
                                         linewidths=0.5, label=f"_{name}", gid=comp))
        handles.setdefault(comp, Line2D([], [], color=colour, lw=2, label=comp))
    ax.set_xlim(*limits[:, 0])
    ax.set_ylim(*limits[:, 1])
    if view == "front":
        ax.invert_xaxis()  # seen from ahead: +y (starboard) on the viewer's left
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel(axis_label(_QUANTITY[i], units))
    ax.set_ylabel(axis_label(_QUANTITY[j], units))
    ax.set_title(title, fontsize=10)
    ax.set_label(f"{view} view")
    ax.grid(True, **GRID)
    return list(handles.values())


def _box(geo, mirror):
    """(2, 3): lower and upper corners of the drawing (with images when ``mirror``), padded."""
    nets = list(geo.mirrored_networks().values() if mirror else geo.networks.values())
    nets += list(_fillet_networks(geo, mirror).values())
    if not nets:
        return np.array([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
    pts = np.concatenate([n.reshape(-1, 3) for n in nets])
    pts = pts[np.isfinite(pts).all(axis=1)]
    if not len(pts):
        return np.array([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = hi - lo
    half = 0.5 * np.maximum(span, 1e-3 * max(float(span.max()), 1e-9)) + _PAD * span.max()
    mid = 0.5 * (lo + hi)
    return np.array([mid - half, mid + half])


def _widened(box, k, length):
    """``box`` with axis ``k`` widened (about its middle) to ``length``."""
    out = box.copy()
    mid = 0.5 * (box[0, k] + box[1, k])
    half = 0.5 * max(length, box[1, k] - box[0, k])
    out[:, k] = mid - half, mid + half
    return out


def _axes_at(fig, size, left, bottom, width, height):
    """Axes placed in inches on a figure of ``size`` (width, height) inches."""
    w, h = size
    return fig.add_axes((left / w, bottom / h, width / w, height / h))


def _single(obj, view, mirror, title, units, width=11.0):
    geo, comps = _geometry(obj)
    plt = pyplot()
    i, j, _ = _VIEWS[view]
    box = _box(geo, mirror)
    span = box[1] - box[0]
    # Inches: y-label margin left, legend right, x-label below, titles above.
    left, right, bottom, top = 0.95, 1.7, 0.65, 0.75
    scale = (width - left - right) / span[i]
    names = set(geo.mirrored_networks() if mirror else geo.networks) | set(geo.fillets)
    # A very slim view keeps the height its legend needs, at the same scale (some blank).
    least = max(1.2, 0.2 * len({component_of(n, *comps) for n in names}) + 0.4)
    if scale * span[j] < least:
        box = _widened(box, j, least / scale)
    elif scale * span[j] > 9.0:  # a tall one keeps a sensible page: narrower, same scale
        scale = 9.0 / span[j]
    span = box[1] - box[0]
    size = (left + right + scale * span[i], bottom + top + scale * span[j])
    fig = plt.figure(figsize=size)
    ax = _axes_at(fig, size, left, bottom, scale * span[i], scale * span[j])
    handles = _draw(ax, geo, comps, view, mirror, units, box[:, [i, j]])
    ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0),
              borderaxespad=0.0, title="component", title_fontsize=8, frameon=False)
    fig.suptitle(title or geo.title or "configuration", y=1 - 0.2 / size[1], va="top")
    return fig


def plot_planform(obj, mirror=True, title=None, units=DEFAULT_UNITS):
    """Plan view from above: x aft to the right, y (starboard) up, both halves.

    Parameters
    ----------
    obj : Geometry, Configuration or mapping of str to (n_lines, n_points, 3) float
        What to draw; networks are coloured by component (a completed geometry's
        ``configuration`` names them).
    mirror : bool
        Also draw the mirror images (lighter).
    title : str, optional
        Figure title; default the geometry's title.
    units : str
        Length unit written on the axes (default ``"ft"``). A label only: coordinates are
        the deck's, never converted.

    Returns
    -------
    matplotlib.figure.Figure
    """
    return _single(obj, "plan", mirror, title, units)


def plot_side(obj, title=None, units=DEFAULT_UNITS):
    """Side view from port: x aft to the right, z up (images coincide and are left out).

    Parameters are those of :func:`plot_planform`. Returns a matplotlib Figure.
    """
    return _single(obj, "side", False, title, units)


def plot_front(obj, title=None, units=DEFAULT_UNITS):
    """Front view from ahead: z up, y (starboard) to the *left*, as a three-view drawing
    and the report's 3-D "front" view show it. Both halves.

    Parameters are those of :func:`plot_planform`. Returns a matplotlib Figure.
    """
    return _single(obj, "front", True, title, units, width=8.0)


def plot_views(obj, title=None, units=DEFAULT_UNITS):
    """Three-view drawing at one scale: plan (top left), side (below it, same x) and front
    (right of the side view, same z); the component legend top right.

    Parameters
    ----------
    obj : Geometry, Configuration or mapping of str to (n_lines, n_points, 3) float
    title : str, optional
        Figure title; default the geometry's title.
    units : str
        Length unit written on the axes (default ``"ft"``; a label only, nothing is
        converted).

    Returns
    -------
    matplotlib.figure.Figure
        Axes labelled ``"plan view"``, ``"side view"``, ``"front view"`` (``Axes.get_label``).
    """
    geo, comps = _geometry(obj)
    plt = pyplot()
    box = _box(geo, True)
    lx, ly, lz = box[1] - box[0]
    # One scale for the three views, placed in inches so that the plan and side views share
    # their x positions and the side and front views their z positions. Slim views keep a
    # usable size by widening their limits (same scale, some blank).
    width, left, gap, right, bottom, row_gap, top = 14.0, 0.95, 1.05, 0.25, 0.65, 0.95, 0.8
    ly_cell = max(ly, 0.28 * lx)
    scale = (width - left - gap - right) / (lx + ly_cell)
    lz_cell = max(lz, 1.3 / scale)
    if scale * (ly + lz_cell) > 12.0:  # tall airplanes: a smaller scale, narrower page
        scale = 12.0 / (ly + lz_cell)
        lz_cell = max(lz, 1.3 / scale)
    size = (left + gap + right + scale * (lx + ly_cell),
            bottom + row_gap + top + scale * (ly + lz_cell))
    fig = plt.figure(figsize=size)
    side_box = _widened(box, 2, lz_cell)
    front_box = _widened(side_box, 1, ly_cell)
    h_side, h_plan = scale * lz_cell, scale * ly
    x_front = left + scale * lx + gap
    handles = _draw(_axes_at(fig, size, left, bottom + h_side + row_gap, scale * lx, h_plan),
                    geo, comps, "plan", True, units, box[:, [0, 1]])
    _draw(_axes_at(fig, size, left, bottom, scale * lx, h_side), geo, comps, "side", False,
          units, side_box[:, [0, 2]])
    _draw(_axes_at(fig, size, x_front, bottom, scale * ly_cell, h_side), geo, comps, "front",
          True, units, front_box[:, [1, 2]])
    legend_ax = _axes_at(fig, size, x_front, bottom + h_side + row_gap, scale * ly_cell, h_plan)
    legend_ax.set_axis_off()
    legend_ax.set_label("legend")
    legend_ax.legend(handles=handles, loc="center", fontsize=9,
                     title="component (mirror images lighter)",
                     ncols=2 if len(handles) > 12 else 1, frameon=False)
    fig.suptitle(title or geo.title or "configuration", y=1 - 0.2 / size[1], va="top")
    return fig
