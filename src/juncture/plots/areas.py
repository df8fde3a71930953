"""Area distributions of wave-drag cases, titled with what they are: Mach number and method.

A slender-body result (:func:`juncture.analysis.wavedrag` without a Mach number) is drawn as
its normal-area distribution A(x), the curve its drag comes from. A far-field result (with a
Mach number) holds the Mach-plane cuts its drag comes from (``"x_cuts"``, ``"cut_areas"``,
one row per roll angle): those are drawn, as the mean over roll angles with the band between
the smallest and largest, beside the drag of each roll angle. A result without the cuts
falls back to its normal areas, and the title says so.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import JunctureError
from ._backend import GRID, pyplot, save
from .style import CASE_COLOURS, DEFAULT_UNITS, axis_label, unit_label

__all__ = ["plot_wavedrag_areas", "plot_area_distribution"]


def _curve(label, res):
    """(x, area) of a result's normal-area distribution, checked."""
    try:
        x, a = np.asarray(res["x"], float), np.asarray(res["area"], float)
    except (KeyError, TypeError, ValueError):
        raise JunctureError(f"result {label!r} has no 'x' and 'area' lists") from None
    if x.ndim != 1 or x.shape != a.shape:
        raise JunctureError(f"result {label!r}: 'x' and 'area' must be 1-D of equal "
                            f"length, found shapes {x.shape} and {a.shape}")
    return x, a


def _cuts(res):
    """(X (n_theta, n_x), A (n_theta, n_x), thetas (n_theta,)) of a far-field result, or
    None if it holds no usable Mach-plane cuts."""
    try:
        xc = np.asarray(res["x_cuts"], float)
        ac = np.asarray(res["cut_areas"], float)
        th = np.asarray(res.get("thetas", np.zeros(len(xc))), float)
    except (KeyError, TypeError, ValueError):
        return None
    if xc.ndim != 2 or xc.shape != ac.shape or th.shape != (xc.shape[0],) or xc.size == 0:
        return None
    w = np.asarray(res.get("theta_weights", np.ones(th.size)), float)
    w = w / w.sum() if w.shape == th.shape and w.sum() > 0 else np.full(th.size, 1 / th.size)
    return xc, ac, th, w


def _mean_cut(xc, ac, th, w):
    """The Mach-plane areas on one grid of X: (X (n,), the drag's own weighted mean over roll
    angles, min, max)."""
    grid = np.linspace(xc.min(), xc.max(), xc.shape[1])
    rows = np.stack([np.interp(grid, x, a, left=0.0, right=0.0) for x, a in zip(xc, ac)])
    return grid, w @ rows, rows.min(axis=0), rows.max(axis=0)


def _what(results, far):
    """The subtitle: method and Mach number(s), then which areas are drawn."""
    machs = sorted({float(r["mach"]) for r in results.values() if r.get("mach") is not None})
    methods = list(dict.fromkeys(str(r["method"]) for r in results.values() if r.get("method")))
    method = "; ".join(methods) or "wave drag"
    if machs:
        head = f"Mach {', '.join(f'{m:g}' for m in machs)}, {method}"
    else:
        head = f"{method}, Mach -> 1 (no Mach number given)"
    if far:
        shown = ("Mach-plane areas, the drag's own: weighted mean over roll angles (band: the "
                 "first case's range)")
    elif machs:
        shown = "shown: normal (Mach 1) areas; the results hold no Mach-plane cuts"
    else:
        shown = "normal cross-sectional areas A(x), the drag's own"
    return f"{head}\n{shown}"


def plot_wavedrag_areas(results, title=None, units=DEFAULT_UNITS):
    """The area distributions of several wave-drag results on one figure.

    Parameters
    ----------
    results : mapping of str to dict
        Label (``"original"``, ``"cubic fillet"``, ...) -> a
        :func:`juncture.analysis.wavedrag` result: ``"x"``, ``"area"`` and optionally
        ``"D_over_q"``, ``"mach"``, ``"method"``, and (far field) ``"x_cuts"``,
        ``"cut_areas"``, ``"thetas"``, ``"D_over_q_theta"``.
    title : str, optional
        First title line (e.g. the deck title); the second names the Mach number and method.
    units : str
        Length unit (default ``"ft"``): x in it, areas in its square, D/q in its square. A
        label only: nothing is converted.

    Returns
    -------
    matplotlib.figure.Figure
        With two or more results, a second panel shows each one's difference from the first
        (the differences a designer looks for are tiny on A(x)); far-field results get a
        panel of D/q against roll angle.

    Raises
    ------
    JunctureError
        No results, or a result without ``x`` and ``area`` of equal length.
    """
    if not results:
        raise JunctureError("no area distributions to plot")
    curves = {label: _curve(label, res) for label, res in results.items()}
    cuts = {label: _cuts(res) for label, res in results.items()}
    far = all(c is not None for c in cuts.values())
    many = len(results) > 1
    plt = pyplot()
    n_rows = 1 + many + far
    ratios = (2.2,) + ((1.0,) if many else ()) + ((1.2,) if far else ())
    fig = plt.figure(figsize=(10, 3.2 + 2.3 * (n_rows - 1) + 1.0), layout="constrained")
    grid = fig.add_gridspec(n_rows, 1, height_ratios=ratios)
    ax = fig.add_subplot(grid[0])
    diff = fig.add_subplot(grid[1], sharex=ax) if many else None
    base = None
    xlabel = axis_label("X, where the Mach plane meets the x axis" if far else "x, aft", units)
    colours = dict(zip(results, CASE_COLOURS * (len(results) // len(CASE_COLOURS) + 1)))
    for label, res in results.items():
        if far:
            x, a, lo, hi = _mean_cut(*cuts[label])
        else:
            x, a = curves[label]
            lo = hi = None
        dq = res.get("D_over_q")
        line, = ax.plot(x, a, lw=1.4, color=colours[label], label=label if dq is None else
                        f"{label} (D/q = {float(dq):.5g} {unit_label(units, 2)})")
        if lo is not None and base is None and not ax.collections:  # the first case's band
            ax.fill_between(x, lo, hi, color=line.get_color(), alpha=0.15, lw=0,
                            label=f"{label}: range over roll angles")
        if diff is not None:
            if base is None:
                base = (x, a, label)
            else:
                diff.plot(x, a - np.interp(x, base[0], base[1]), lw=1.2,
                          color=line.get_color(), label=f"{label} - {base[2]}")
    ax.set_ylabel(axis_label("Mach-plane area, mean" if far else "normal area A(x)", units, 2))
    ax.grid(True, **GRID)
    ax.legend(fontsize=8, loc="best")
    ax.set_title(_what(results, far), fontsize=9)
    ax.set_label("areas")
    last = ax
    if diff is not None:
        diff.axhline(0.0, color="0.5", lw=0.6)
        diff.set_ylabel(axis_label("area difference", units, 2))
        diff.grid(True, **GRID)
        diff.legend(fontsize=8, loc="best")
        diff.set_label("difference")
        last = diff
    last.set_xlabel(xlabel)
    if far:
        _roll_panel(fig.add_subplot(grid[-1]), results, cuts, units)
    fig.suptitle(title or "area distribution", fontsize=12)
    return fig


def _roll_panel(ax, results, cuts, units):
    """D/q of each roll angle's equivalent body (their weighted mean is the far-field D/q)."""
    for label, res in results.items():
        th = np.degrees(cuts[label][2])
        dq = res.get("D_over_q_theta")
        if dq is not None and np.shape(dq) == th.shape:
            ax.plot(th, dq, "o-", ms=3, lw=1.1, label=label, color=CASE_COLOURS[
                list(results).index(label) % len(CASE_COLOURS)])
    ax.set_xlabel("roll angle theta [deg]")
    lo, hi = (np.degrees(min(c[2].min() for c in cuts.values())),
              np.degrees(max(c[2].max() for c in cuts.values())))
    ax.set_xticks(np.arange(np.floor(lo / 45) * 45, hi + 1, 45))
    ax.set_ylabel(axis_label("D/q", units, 2))
    ax.set_title("drag of each roll angle's equivalent body (their weighted mean, the "
                 "integration rule's, is the D/q above)",
                 fontsize=9)
    ax.grid(True, **GRID)
    ax.set_label("roll angles")
    if ax.lines:
        ax.legend(fontsize=8, loc="best")


def plot_area_distribution(results, path, title=None, units=DEFAULT_UNITS):
    """Draw :func:`plot_wavedrag_areas` and save it to ``path``.

    Parameters
    ----------
    results : mapping of str to dict
        Label -> :func:`juncture.analysis.wavedrag` result (see :func:`plot_wavedrag_areas`).
    path : str or path-like
        Output image; the format follows the extension (``.png``, ``.svg``, ``.pdf``).
        Written atomically (:func:`juncture.plots.save`).
    title : str, optional
        First title line (e.g. the deck title).
    units : str
        Length unit written on the axes (default ``"ft"``; a label only, nothing is
        converted).

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    JunctureError
        No results, or a result without ``x`` and ``area`` of equal length.
    """
    save(plot_wavedrag_areas(results, title=title, units=units), path)
    return Path(path)
