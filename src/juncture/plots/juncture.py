"""Figures of the wing-body juncture, after TM-4406 figs 3-10.

The juncture is the pair :func:`juncture.complete` intersected first (its ``options.wing``
and ``options.body``, ``"wing"`` and ``"body"`` by default): :func:`main_pair` finds it in a
completed geometry whatever the components are called. Every figure raises
:class:`~juncture.errors.JunctureError` when it cannot apply (no such pair, no fillet), which
:func:`juncture.plots.write_figures` turns into a skipped figure.

Colours are the components' (:func:`juncture.plots.style.component_colour`); intersection
lines are :data:`~juncture.plots.style.INTERSECTION_COLOUR`. The root-region figures
(intersection, lower intersection) stretch y (and z) against x, and say by how much: at true
scale a one-foot gap along a 150-foot root is a hair's breadth. Fillet sections are at true
scale, one scale for all of them.
"""

from __future__ import annotations

import numpy as np

from ..errors import JunctureError
from ._backend import GRID, pyplot
from .style import (
    DEFAULT_UNITS,
    INTERSECTION_COLOUR,
    axis_label,
    component_colour,
    unit_label,
)

__all__ = ["main_pair", "network_aliases", "plot_gap_and_intersection", "plot_lower_intersection",
           "plot_fillet_sections", "plot_station_areas"]


# ------------------------------------------------------------------ which pair, which shapes
def main_pair(cfg, geo):
    """Names ``(wing, body)`` of the wing-body juncture of a completed geometry, or None.

    Parameters
    ----------
    cfg : Configuration or None
        The input configuration; None: the geometry's own ``configuration``.
    geo : Geometry

    Returns
    -------
    tuple of str or None
        The first intersection pair ``"<wing>/<body> upper"`` (with its ``" lower"``) whose
        first component is wing-like and second a body in the model; None if there is none
        (no wing, networks read from a file, ...).
    """
    model = cfg if cfg is not None else getattr(geo, "configuration", None)
    if model is None:
        return None
    comps = {c.name: c for c in model}
    for key in geo.intersections:
        if "/" not in key or not key.endswith(" upper"):
            continue
        a, b = key[:-len(" upper")].split("/", 1)
        if f"{a}/{b} lower" in geo.intersections and a in comps and b in comps and \
                hasattr(comps[a], "lofting_lines") and hasattr(comps[b], "x_global"):
            return a, b
    return None


def network_aliases(cfg, geo):
    """``{"wing": <wing>, "body": <body>}`` for the juncture's networks when its components
    have other names (:func:`juncture.complete` names those networks ``"wing upper"``,
    ``"body lower"``, ...); empty otherwise. For
    :func:`juncture.plots.style.component_of`."""
    pair = main_pair(cfg, geo)
    if pair is None:
        return {}
    return {k: v for k, v in zip(("wing", "body"), pair) if k != v}


def _pair(cfg, geo, wing, body, figure):
    """The wing and body components of the figure, or a JunctureError saying why not."""
    model = cfg if cfg is not None else geo.configuration
    if wing is None or body is None:
        found = main_pair(model, geo)
        if found is None:
            raise JunctureError(f"no wing-body intersection in the geometry (the {figure} "
                                f"needs a wing-like component intersected with a body by "
                                f"juncture.complete)")
        wing, body = wing or found[0], body or found[1]
    if model is None or wing not in {c.name for c in model} or \
            body not in {c.name for c in model}:
        raise JunctureError(f"no components {wing!r} and {body!r} in the configuration "
                            f"(the {figure} needs both)")
    for side in ("upper", "lower"):
        if f"{wing}/{body} {side}" not in geo.intersections:
            raise JunctureError(f"no '{wing}/{body} {side}' intersection in the geometry "
                                f"(the {figure} needs it)")
    return model[wing], model[body]


def _half_section(body, x, n=121):
    """(..., n, 2): y, z of the y >= 0 half-section at stations x, bottom to top."""
    x = np.asarray(x, float)[..., None]
    if hasattr(body, "radius_at"):  # circular: by angle theta (TM-4406 eqs 2-3)
        pts = body.point(x, np.linspace(-np.pi / 2, np.pi / 2, n))
    else:  # arbitrary sections: by normalised arc length (TM-4607)
        pts = body.point(x, np.linspace(0.0, 1.0, n))
    return pts[..., 1:]


def _plan_outline(body, n=300):
    """(n,), (n,): stations and the body's largest y (its plan-view edge) there."""
    x = np.linspace(body.x_global[0], body.x_global[-1], n)
    return x, _half_section(body, x, 61)[..., 0].max(axis=-1)


def _outboard(lines, points, axis):
    """For each lofting line j, its first section point outboard of ``points[j]``."""
    beyond = lines[..., axis] > points[:, None, axis]
    k = np.where(beyond.any(axis=1), beyond.argmax(axis=1), lines.shape[1] - 1)
    return lines[np.arange(len(lines)), k]


def _window(ax, pts, pad=0.06, x=True, y=True):
    """Tight limits around (k, 2) points, ``pad`` of the extent on each side (points of a
    lofting line that missed the other surface are NaN, and are left out)."""
    pts = pts[np.isfinite(pts).all(axis=1)]
    if not len(pts):
        return
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    d = np.maximum(hi - lo, 1e-6 * max(float(np.max(np.abs(pts))), 1.0))
    if x:
        ax.set_xlim(lo[0] - pad * d[0], hi[0] + pad * d[0])
    if y:
        ax.set_ylim(lo[1] - pad * d[1], hi[1] + pad * d[1])


def _stretch(fig, ax):
    """How many times the vertical scale of ``ax`` exceeds its horizontal one."""
    fig.draw_without_rendering()
    box = ax.get_window_extent()
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    return (box.height / abs(y1 - y0)) / (box.width / abs(x1 - x0))


# ------------------------------------------------------------------ figures
def plot_gap_and_intersection(cfg, geo, wing=None, body=None, units=DEFAULT_UNITS):
    """Plan view of the wing root: the input wing and its gap to the body (a), and the upper
    surface extended along its lofting lines to the intersection line (b) (TM-4406 fig 3).

    Parameters
    ----------
    cfg : Configuration or None
        The input configuration (its wing sections); None: the geometry's model.
    geo : Geometry
        From :func:`juncture.complete`, with ``"<wing>/<body> upper"``.
    wing, body : str, optional
        Component names; default the pair :func:`main_pair` finds.
    units : str
        Length unit on the axes (default ``"ft"``; a label only, nothing is converted).

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    JunctureError
        No wing-body intersection in the geometry.
    """
    w, b = _pair(cfg, geo, wing, body, "intersection figure")
    plt = pyplot()
    span = w.span_axis
    sec = w.section_points("upper")
    iu = geo.intersections[f"{w.name}/{b.name} upper"]
    xb, yb = _plan_outline(b)
    # The root region: up to four body half-widths out, or the whole wing if it is shorter.
    ymax = min(float(sec[..., span].max()), 4.0 * float(yb.max()))
    near = sec[sec[..., span] <= ymax]
    xs = np.concatenate([near[:, 0], iu[:, 0]])
    fig, axes = plt.subplots(2, 1, figsize=(11, 8.5), layout="constrained", sharex=True)
    wc, bc = component_colour(w.name), component_colour(b.name)
    for ax, alpha in ((axes[0], 0.9), (axes[1], 0.35)):
        ax.plot(xb, yb, color=bc, lw=1.4, label=f"{b.name} (plan-view edge)")
        ax.plot(sec[..., 0].T, sec[..., span].T, color=wc, lw=0.7, alpha=alpha)
        ax.plot(sec[..., 0], sec[..., span], color=wc, lw=0.7, alpha=alpha)
        ax.plot([], [], color=wc, lw=0.7, alpha=alpha,
                label=f"{w.name} as input: sections and lofting lines")
        ax.set_ylabel(axis_label("y, starboard", units))
        ax.grid(True, **GRID)
        _window(ax, np.array([[xs.min(), min(0.0, float(near[:, span].min()))],
                              [xs.max(), ymax]]), pad=0.03)
    ends = _outboard(w.lofting_lines("upper"), iu, span)
    ext = np.stack([iu, ends], axis=1)[..., [0, span]]
    axes[1].plot(ext[..., 0].T, ext[..., 1].T, color=wc, lw=1.8)
    axes[1].plot([], [], color=wc, lw=1.8, label="lofting lines from the intersection to the "
                 "next section")
    axes[1].plot(iu[:, 0], iu[:, span], "o-", color=INTERSECTION_COLOUR, ms=3, lw=1.4,
                 label="upper intersection line")
    axes[1].set_xlabel(axis_label("x, aft", units))
    k = _stretch(fig, axes[0])
    axes[0].set_title(f"(a) input: the {w.name} root and the {b.name} (upper surface)")
    axes[1].set_title("(b) upper surface extended or trimmed along its lofting lines to the "
                      "intersection line")
    for ax in axes:
        ax.legend(fontsize=8, loc="upper left", framealpha=0.9)
    fig.suptitle(f"{w.name}-{b.name} intersection, plan view from above (y scale "
                 f"{k:.2g} x the x scale)")
    return fig


def plot_lower_intersection(cfg, geo, wing=None, body=None, units=DEFAULT_UNITS):
    """The lower-surface intersection beside the upper one and the fillet start lines, in
    plan (a) and side (b) view (TM-4406 fig 4); limits fit the lines tightly.

    Parameters and errors are those of :func:`plot_gap_and_intersection`. The lower
    surface's lofting lines are drawn from the lower intersection outboard (clipped).

    Returns
    -------
    matplotlib.figure.Figure
    """
    w, b = _pair(cfg, geo, wing, body, "lower-intersection figure")
    plt = pyplot()
    span = w.span_axis
    il = geo.intersections[f"{w.name}/{b.name} lower"]
    iu = geo.intersections[f"{w.name}/{b.name} upper"]
    fl, fu = geo.fillets.get("fillet lower"), geo.fillets.get("fillet upper")
    fig, axes = plt.subplots(2, 1, figsize=(11, 7.5), layout="constrained", sharex=True)
    wc, bc = component_colour(w.name), component_colour(b.name)
    fc = component_colour("fillet")
    marked = [il, iu] + [f[:, 0] for f in (fl, fu) if f is not None and len(f)]
    ends = _outboard(w.lofting_lines("lower"), il, span)
    xb, yb = _plan_outline(b)
    for ax, k, name in ((axes[0], span, "y, starboard"), (axes[1], 2, "z, up")):
        if k == span:
            ax.plot(xb, yb, color=bc, lw=1.2, label=f"{b.name} (plan-view edge)")
        seg = np.stack([il, ends], axis=1)
        ax.plot(seg[..., 0].T, seg[..., k].T, color=wc, lw=0.7)
        ax.plot(il[:, 0], il[:, k], "s-", color=INTERSECTION_COLOUR, ms=3, lw=1.4,
                label="lower intersection")
        ax.plot(iu[:, 0], iu[:, k], "o--", color=INTERSECTION_COLOUR, ms=2.5, lw=0.8,
                alpha=0.6, label="upper intersection")
        if fl is not None and len(fl):
            ax.plot(fl[:, 0, 0], fl[:, 0, k], "^-", color=fc, ms=3, lw=0.8,
                    label="lower fillet start (on the body)")
        if fu is not None and len(fu):
            ax.plot(fu[:, 0, 0], fu[:, 0, k], "v:", color=fc, ms=3, lw=0.8,
                    label="upper fillet start")
        ax.plot([], [], color=wc, lw=0.7, label=f"{w.name} lower lofting lines")
        ax.set_ylabel(axis_label(name, units))
        ax.grid(True, **GRID)
        _window(ax, np.concatenate([m[:, [0, k]] for m in marked]))
    axes[1].set_xlabel(axis_label("x, aft", units))
    ka, kb = _stretch(fig, axes[0]), _stretch(fig, axes[1])
    axes[0].set_title(f"(a) plan view from above (y scale {ka:.2g} x the x scale)")
    axes[1].set_title(f"(b) side view from port (z scale {kb:.2g} x the x scale)")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncols=3, fontsize=8,
               frameon=False)
    fig.suptitle(f"{w.name}-{b.name} lower-surface intersection")
    return fig


def _model_component(geo, name, like):
    """The completed model's component ``name`` if it matches ``like``'s stations."""
    model = geo.configuration
    comp = model.components.get(name) if model is not None else None
    return comp if comp is not None and type(comp) is type(like) else None


def plot_fillet_sections(cfg, geo, n=6, wing=None, body=None, units=DEFAULT_UNITS):
    """Fillet lines at ``n`` stations, seen along x (TM-4406 figs 6-9), one scale for all.

    Each panel: the station x in its title with the fillet's added area, the original body
    section (dashed) and the re-designed one (solid), the wing's upper and lower lofting
    lines at that station, and the upper and lower fillet lines; axes y and z with units;
    one legend for the figure.

    Parameters
    ----------
    cfg : Configuration or None
        The input configuration (the original body and wing); None: the geometry's model.
    geo : Geometry
        From :func:`juncture.complete` with a fillet (``fillets``, ``stations``).
    n : int
        Number of stations shown (evenly spread, ends excluded: their fillets vanish).
    wing, body : str, optional
        Component names; default the pair :func:`main_pair` finds.
    units : str
        Length unit on the axes (default ``"ft"``; a label only, nothing is converted).

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    JunctureError
        No wing-body intersection, or no fillet in the geometry.
    """
    w, b = _pair(cfg, geo, wing, body, "fillet-section figure")
    fu, fl = geo.fillets.get("fillet upper"), geo.fillets.get("fillet lower")
    st = geo.stations
    if fu is None or fl is None or "x" not in st or len(st["x"]) != len(fu):
        raise JunctureError("no fillet in the geometry (the fillet-section figure needs "
                            "complete() with fillet='cubic' or 'circular')")
    plt = pyplot()
    m = len(fu)
    picks = np.unique(np.linspace(1, max(m - 2, 1), min(int(n), max(m - 2, 1)))
                      .round().astype(int))
    cols = min(3, len(picks))
    rows = int(np.ceil(len(picks) / cols))
    fig, axes = plt.subplots(rows, cols, figsize=(4.3 * cols, 3.9 * rows + 0.9),
                             layout="constrained", squeeze=False)
    wing_now = _model_component(geo, w.name, w)
    lines = {side: (wing_now if wing_now is not None and wing_now.n_stations == m else w)
             .lofting_lines(side) for side in ("upper", "lower")}
    body_now = _model_component(geo, b.name, b)
    wc, bc, fc = component_colour(w.name), component_colour(b.name), component_colour("fillet")
    # One window size for all panels (true scale, comparable), centred on each fillet.
    both = np.concatenate([fu[picks], fl[picks]], axis=1)[..., 1:]
    lo, hi = np.nanmin(both, axis=1), np.nanmax(both, axis=1)  # (n_picks, 2)
    half = 0.75 * float(np.nanmax(hi - lo, initial=0.0))
    if not np.isfinite(half) or half <= 0.0:  # no fillet points: the body's size instead
        half = 0.5 * float(np.nanmax(np.abs(_half_section(b, st["x"][picks])), initial=1.0))
    area_unit = unit_label(units, 2)
    for ax, j in zip(axes.ravel(), picks):
        x = float(st["x"][j])
        sec0 = _half_section(b, x)
        ax.plot(sec0[:, 0], sec0[:, 1], color=bc, ls="--", lw=1.0, alpha=0.7,
                label=f"{b.name}, original")
        if body_now is not None and body_now is not b:
            sec1 = _half_section(body_now, x)
            ax.plot(sec1[:, 0], sec1[:, 1], color=bc, lw=1.3, label=f"{b.name}, re-designed")
        if len(lines["upper"]) == m:
            for side, ls in (("upper", "-"), ("lower", "--")):
                line = lines[side][j]
                ax.plot(line[:, 1], line[:, 2], ls, marker="o", color=wc, ms=2.5, lw=0.9,
                        label=f"{w.name} {side} lofting line")
        ax.plot(fu[j, :, 1], fu[j, :, 2], color=fc, lw=1.8, label="fillet, upper")
        ax.plot(fl[j, :, 1], fl[j, :, 2], color=fc, lw=1.8, ls="-.", label="fillet, lower")
        k = list(picks).index(j)
        centre = 0.5 * (lo[k] + hi[k])
        if np.isfinite(centre).all():
            ax.set_xlim(centre[0] - half, centre[0] + half)
            ax.set_ylim(centre[1] - half, centre[1] + half)
        ax.set_aspect("equal", adjustable="box")
        added = f", added area {st['area_fillet'][j]:.3g} {area_unit}" \
            if "area_fillet" in st else ""
        ax.set_title(f"x = {x:.5g} {unit_label(units)}{added}", fontsize=9)
        ax.set_xlabel(axis_label("y, starboard", units), fontsize=8)
        ax.set_ylabel(axis_label("z, up", units), fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, **GRID)
    for ax in axes.ravel()[len(picks):]:
        ax.set_visible(False)
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncols=min(len(labels), 4),
               fontsize=8, frameon=False)
    fig.suptitle("fillet lines at constant x, looking forward (starboard to the right; "
                 "added area of both sides)", fontsize=11)
    return fig


def plot_station_areas(geo, units=DEFAULT_UNITS):
    """Cross-sectional areas at the fillet stations: original body, re-designed body, body +
    fillet (top); fillet area added and area taken from the body (bottom).

    Parameters
    ----------
    geo : Geometry
        From :func:`juncture.complete` with a fillet (``stations``: ``x``,
        ``area_original``, ``area_body``, ``area_fillet``; areas of both halves).
    units : str
        Length unit (default ``"ft"``): areas are labelled in its square. A label only.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    JunctureError
        The geometry has no fillet stations.
    """
    st = geo.stations
    need = ("x", "area_original", "area_body", "area_fillet")
    if not all(k in st for k in need) or not len(st["x"]):
        raise JunctureError("no fillet stations in the geometry (the station-area figure "
                            "needs complete() with a fillet)")
    plt = pyplot()
    pair = main_pair(None, geo)
    bc, fc = component_colour(pair[1] if pair else "body"), component_colour("fillet")
    fig, (a0, a1) = plt.subplots(2, 1, figsize=(10, 6.5), layout="constrained", sharex=True)
    x = st["x"]
    a0.plot(x, st["area_original"], "--", color="k", lw=1.2, label="original body")
    a0.plot(x, st["area_body"], "-", color=bc, lw=1.4, label="re-designed body")
    a0.plot(x, st["area_body"] + st["area_fillet"], ":", color=fc, lw=2.2,
            label="re-designed body + fillet")
    a1.plot(x, st["area_fillet"], "o-", color=fc, ms=3, label="added by the fillet")
    a1.plot(x, st["area_original"] - st["area_body"], "s--", color=bc, ms=3,
            label="taken from the body")
    for ax in (a0, a1):
        ax.set_ylabel(axis_label("area", units, 2))
        ax.grid(True, **GRID)
        ax.legend(fontsize=8, loc="best")
        ax.margins(x=0.01)
    a1.set_xlabel(axis_label("x, aft", units))
    a0.set_title("cross-sectional area at the fillet stations (both halves)")
    a1.set_title("area added and taken", fontsize=10)
    return fig
