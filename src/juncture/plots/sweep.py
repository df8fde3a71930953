"""Figures and a one-file HTML report of a design-study sweep, one row of results per case.

The results are a pandas DataFrame: ``case``, ``key``, one column per varied parameter
(numbers; or strings and bools, which are categories), ``status`` (``"ok"`` or ``"error"``),
``error``, ``error_type``, ``wall_time``, ``volume``, ``wetted_area`` and, per Mach number,
``D_over_q_M<mach>`` and ``CD_M<mach>`` (``<mach>`` is ``format(mach, "g")``). Only ok rows
are plotted; other numeric columns are ignored. ``units`` (default ``"ft"``) is a label only,
as in every figure of :mod:`juncture.plots`. Neither matplotlib nor pandas is imported until
a function needs it.
"""

from __future__ import annotations

import base64
import html
import io
import re
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from .. import __version__
from ..errors import JunctureError
from ..io._registry import atomic_output
from ._backend import GRID, pyplot, save
from .report_css import REPORT_CSS
from .style import CASE_COLOURS, DEFAULT_UNITS, axis_label, unit_label

__all__ = ["drag_columns", "plot_against_parameters", "plot_scatter_matrix",
           "write_sweep_figures", "render_sweep_report", "write_sweep_report"]

_DRAG = re.compile(r"D_over_q_M(\d*\.?\d+(?:e[+-]?\d+)?)")  # format(mach, "g")
_MARKERS = ("o", "s", "^", "D", "v", "P", "X")
_MAX_VARIABLES = 10  # of the scatter matrix
_MAX_LINE_VALUES = 50  # a numeric parameter with more distinct values gets no line of means
_PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
_CSS = "td.message { white-space: pre-wrap; text-align: left; max-width: 70ch; }"
_NONE = "&ndash;"


# ------------------------------------------------------------------ columns and rows
def drag_columns(df):
    """``[(mach, column), ...]``, float and str, of every ``D_over_q_M<mach>`` column of the
    sweep results ``df``, sorted by Mach number (a ``<mach>`` that is no number is left out)."""
    found = ((m, col) for col in df.columns if (m := _DRAG.fullmatch(str(col))))
    return sorted(((float(m.group(1)), col) for m, col in found), key=lambda mc: mc[0])


def _parameters(df, parameters):
    """The varied parameters as a list, checked against the columns (and ``status``)."""
    names = [parameters] if isinstance(parameters, str) else list(parameters)
    missing = [n for n in ["status", *names] if n not in df.columns]
    if missing:
        raise JunctureError(f"the sweep results have no column {', '.join(map(repr, missing))}"
                            f"; columns: {', '.join(map(str, df.columns))}")
    return names


def _ok(df):
    return df[df["status"].astype(str) == "ok"]


def _floats(values):
    return values.to_numpy(dtype=float, na_value=np.nan)


def _numeric(values):
    """Whether a parameter is numbers (an x axis) rather than strings or bools (categories)."""
    kind = getattr(values.dtype, "kind", "O")
    vals = values.dropna().tolist() if kind == "O" else []
    return kind in "iuf" or (bool(vals) and all(
        isinstance(v, int | float | np.number) and not isinstance(v, bool | np.bool_)
        for v in vals))


def _categories(values):
    return sorted(set(values.dropna().tolist()), key=str)


def _positions(df, rows, name):
    """(x of ``rows``, categories): a numeric parameter's values and None, or the positions
    0..k-1 of its categories, which are taken from every row of ``df``."""
    if _numeric(df[name]):
        return _floats(rows[name]), None
    cats = _categories(df[name])
    pos = {c: i for i, c in enumerate(cats)}
    return np.array([pos.get(v, np.nan) for v in rows[name].tolist()], float), cats


# ------------------------------------------------------------------ figures
def _series(df, quantity, units):
    """([(legend label, column), ...], y-axis label) of ``quantity``."""
    if quantity == "drag":
        if not drag_columns(df):
            raise JunctureError("the sweep results have no wave-drag column D_over_q_M<mach>")
        return ([(f"M {mach:g}", col) for mach, col in drag_columns(df)],
                axis_label("D/q", units, 2))
    if quantity == "volume":
        if "volume" not in df.columns:
            raise JunctureError("the sweep results have no 'volume' column")
        return [("volume", "volume")], axis_label("volume", units, 3)
    raise JunctureError(f"quantity must be 'drag' or 'volume', found {quantity!r}")


def _panel(ax, df, ok, name, series, ylabel):
    """One parameter's axes: a scatter per series and its mean at each distinct value."""
    x, cats = _positions(df, ok, name)
    for k, (label, col) in enumerate(series):
        y = _floats(ok[col])
        keep = np.isfinite(x) & np.isfinite(y)
        colour = CASE_COLOURS[k % len(CASE_COLOURS)]
        ax.scatter(x[keep], y[keep], s=14, alpha=0.75, color=colour, label=label,
                   marker=_MARKERS[k % len(_MARKERS)], zorder=3)
        xs, inverse = np.unique(x[keep], return_inverse=True)
        mean = np.bincount(inverse, y[keep], xs.size) / np.maximum(np.bincount(inverse), 1)
        if cats is not None:
            ax.plot(xs, mean, ls="none", marker="_", ms=18, mew=2, color=colour)
        elif 0 < xs.size <= _MAX_LINE_VALUES:
            ax.plot(xs, mean, lw=1.1, color=colour)
    if cats is not None:
        ax.set_xticks(range(len(cats)), [str(c) for c in cats])
        ax.set_xlim(-0.5, max(len(cats), 1) - 0.5)
    ax.set_xlabel(name)
    ax.set_ylabel(ylabel)
    ax.grid(True, **GRID)
    ax.set_label(name)


def plot_against_parameters(df, parameters, quantity, units=DEFAULT_UNITS):
    """D/q or volume of the ok cases against each varied parameter, one axes per parameter.

    Parameters
    ----------
    df : pandas.DataFrame
        Sweep results (see the module's docstring).
    parameters : sequence of str
        Varied parameters. A numeric one is an x axis: points, and their mean at each value
        as a line (if at most 50 values). A string or bool one is categorical: positions
        0..k-1 labelled with the categories, the mean a dash.
    quantity : {"drag", "volume"}
        Every D/q column (one marker series per Mach number, legend "M 1.6"), or volume.
    units : str
        Length unit of the y label: D/q in its square, volume in its cube.

    Returns
    -------
    matplotlib.figure.Figure
        Up to three axes a row, each labelled (``Axes.get_label()``) with its parameter.

    Raises
    ------
    JunctureError
        No parameters, a missing column, an unknown quantity, or "drag" without D/q columns.
    """
    names = _parameters(df, parameters)
    if not names:
        raise JunctureError("no varied parameters to plot against")
    series, ylabel = _series(df, quantity, units)
    ok = _ok(df)
    ncols = min(3, len(names))
    nrows = -(-len(names) // ncols)
    fig, axes = pyplot().subplots(nrows, ncols, figsize=(4.4 * ncols, 3.2 * nrows + 0.7),
                                  squeeze=False, layout="constrained")
    for ax in axes.flat[len(names):]:
        fig.delaxes(ax)
    for ax, name in zip(axes.flat, names):
        _panel(ax, df, ok, name, series, ylabel)
    if len(series) > 1:
        axes.flat[0].legend(fontsize=8, loc="best")
    fig.suptitle(f"{'wave drag' if quantity == 'drag' else 'volume'} against the varied "
                 f"parameters: {len(ok)} ok cases of {len(df)} (line or dash: mean per value)",
                 fontsize=11)
    return fig


def _variables(df, names, units):
    """(axis label, column) of the scatter matrix: numeric parameters, D/q, volume."""
    out = [(n, n) for n in names if _numeric(df[n])]
    out += [(axis_label(f"D/q M{mach:g}", units, 2), col) for mach, col in drag_columns(df)]
    return out + ([(axis_label("volume", units, 3), "volume")] if "volume" in df.columns else [])


def _groups(df, ok, names):
    """([(label, mask of ok rows, colour), ...], categorical parameters): one group per
    combination of the categorical parameters' values."""
    cat = [n for n in names if not _numeric(df[n])]
    if not cat:
        return [("ok cases", np.ones(len(ok), bool), CASE_COLOURS[0])], cat
    keys = [tuple(str(v) for v in row) for row in ok[cat].itertuples(index=False)]
    return [(", ".join(key), np.array([k == key for k in keys], bool),
             CASE_COLOURS[i % len(CASE_COLOURS)]) for i, key in enumerate(sorted(set(keys)))], cat


def _limits(v):
    v = v[np.isfinite(v)]
    lo, hi = (float(v.min()), float(v.max())) if v.size else (0.0, 1.0)
    pad = 0.05 * (hi - lo) or 0.05 * abs(lo) or 0.5
    return lo - pad, hi + pad


def _cell(ax, x, y, groups, diagonal):
    """A histogram stacked by group on the diagonal, else a scatter per group."""
    if diagonal:
        parts = [x[m & np.isfinite(x)] for _, m, _ in groups]
        size = sum(p.size for p in parts)
        if size:
            ax.hist(parts, bins=int(np.clip(np.sqrt(size), 5, 20)), range=_limits(x),
                    stacked=True, color=[c for *_, c in groups], edgecolor="white", lw=0.4)
        return
    for _, m, colour in groups:
        keep = m & np.isfinite(x) & np.isfinite(y)
        ax.scatter(x[keep], y[keep], s=8, alpha=0.7, lw=0, color=colour)


def plot_scatter_matrix(df, parameters, units=DEFAULT_UNITS):
    """Scatter matrix of the ok cases over the numeric parameters, every D/q and volume.

    Parameters
    ----------
    df : pandas.DataFrame
        Sweep results (see the module's docstring).
    parameters : sequence of str
        Varied parameters; string or bool ones colour the points (a colour per category, or
        combination of categories, and a legend).
    units : str
        Length unit of D/q (its square) and volume (its cube).

    Returns
    -------
    matplotlib.figure.Figure
        n x n axes for n variables (the first 10 if more, as the title says): histograms on
        the diagonal, scatter plots below, the upper triangle off but for the legend.

    Raises
    ------
    JunctureError
        A missing column, or nothing numeric to plot.
    """
    from matplotlib.lines import Line2D

    names = _parameters(df, parameters)
    variables = _variables(df, names, units)
    if not variables:
        raise JunctureError("no numeric parameter, D/q or volume column for a scatter matrix")
    total, variables = len(variables), variables[:_MAX_VARIABLES]
    ok, n = _ok(df), len(variables)
    groups, cat = _groups(df, ok, names)
    data = [_floats(ok[col]) for _, col in variables]
    fig, axes = pyplot().subplots(n, n, figsize=(1.8 * n + 2.2, 1.8 * n + 1.2), squeeze=False,
                                  layout="constrained")
    for (i, j), ax in np.ndenumerate(axes):
        if j > i:
            ax.axis("off")
            continue
        _cell(ax, data[j], data[i], groups, i == j)
        ax.set_xlim(_limits(data[j]))
        if i != j:
            ax.set_ylim(_limits(data[i]))
        ax.tick_params(labelsize=7, labelbottom=i == n - 1, labelleft=j == 0 and (i or n == 1))
        ax.set_xlabel(variables[j][0] if i == n - 1 else "", fontsize=8)
        ax.set_ylabel(variables[i][0] if j == 0 else "", fontsize=8)
        ax.set_label(f"{variables[i][1]} | {variables[j][1]}")
    if cat:
        handles = [Line2D([], [], ls="none", marker="o", color=c) for *_, c in groups]
        axes[0, -1].legend(handles, [g[0] for g in groups], title=", ".join(cat), fontsize=8,
                           loc="upper right")
    more = f"; the first {n} of {total} variables shown" if total > n else ""
    fig.suptitle(f"scatter matrix of {len(ok)} ok cases of {len(df)}{more}", fontsize=11)
    return fig


def write_sweep_figures(df, parameters, out_dir, units=DEFAULT_UNITS):
    """Write the sweep's figures as PNG files in ``out_dir`` (created if need be).

    Parameters
    ----------
    df : pandas.DataFrame
        Sweep results (see the module's docstring).
    parameters : sequence of str
        Varied parameters.
    out_dir : str or path-like
        Folder of ``drag_vs_parameters.png`` (if there is a D/q column),
        ``volume_vs_parameters.png`` and ``scatter_matrix.png``, each written atomically.
    units : str
        Length unit of the labels.

    Returns
    -------
    list of pathlib.Path
        The files written; none (and nothing drawn) when no case is ok.
    """
    names = _parameters(df, parameters)
    if _ok(df).empty:
        return []
    jobs = {}
    if names and drag_columns(df):
        jobs["drag_vs_parameters.png"] = lambda: plot_against_parameters(df, names, "drag", units)
    if names and "volume" in df.columns:
        jobs["volume_vs_parameters.png"] = lambda: plot_against_parameters(df, names, "volume",
                                                                           units)
    if _variables(df, names, units):
        jobs["scatter_matrix.png"] = lambda: plot_scatter_matrix(df, names, units)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    for name, draw in jobs.items():
        save(draw(), out / name)
    return [out / name for name in jobs]


# ------------------------------------------------------------------ report
def _e(text):
    return html.escape(str(text), quote=True)


def _value(v):
    """A parameter or result value as escaped text."""
    if isinstance(v, float | np.floating):
        return format(float(v), ".6g") if np.isfinite(v) else _NONE
    return _e(int(v) if isinstance(v, np.integer) else bool(v) if isinstance(v, np.bool_) else v)


def _table(headers, rows, classes=None):
    """An HTML table of escaped cells; ``classes``: column index -> CSS class."""
    def cls(i):
        return f' class="{classes[i]}"' if i in (classes or {}) else ""

    head = "".join(f"<th{cls(i)}>{_e(h)}</th>" for i, h in enumerate(headers))
    body = "".join("<tr>" + "".join(f"<td{cls(i)}>{c}</td>" for i, c in enumerate(row))
                   + "</tr>" for row in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _section(ident, heading, body):
    return ident, heading, f'<section id="{ident}"><h2>{_e(heading)}</h2>{body}</section>'


def _parameter_section(df, names):
    rows = []
    for name in names:
        if _numeric(df[name]):
            v = _floats(df[name])
            v = v[np.isfinite(v)]
            rows.append([_e(name), _value(v.min()) if v.size else _NONE,
                         _value(v.max()) if v.size else _NONE, _e(df[name].nunique()), _NONE])
        else:
            cats = _categories(df[name])
            rows.append([_e(name), _NONE, _NONE, _e(len(cats)), _e(", ".join(map(str, cats)))])
    table = _table(("parameter", "min", "max", "distinct values", "categories"), rows,
                   {0: "text", 4: "text"})
    return _section("parameters", "Varied parameters", table) if rows else None


def _minimum_section(df, names, units):
    ok, rows = _ok(df), []
    for mach, col in drag_columns(df):
        y = _floats(ok[col])
        if not np.isfinite(y).any():
            rows.append([_value(mach), _NONE, _NONE, "no ok case"] + [""] * len(names))
            continue
        row = ok.iloc[int(np.nanargmin(y))]
        cd = "CD_M" + str(col)[len("D_over_q_M"):]
        rows.append([_value(mach), _value(row[col]), _value(row[cd]) if cd in ok else _NONE,
                     _value(row["case"] if "case" in ok else row.name)]
                    + [_value(row[n]) for n in names])
    headers = ("Mach", f"least D/q [{unit_label(units, 2)}]", "CD", "case", *names)
    note = '<p class="note">the ok case of least D/q at each Mach number, and its parameters</p>'
    return _section("minimum", "Least wave drag", _table(headers, rows) + note) if rows else None


def _error_section(df):
    err = df[df["status"].astype(str) == "error"]
    if err.empty:
        return None
    blank = [""] * len(err)
    groups = {}
    for msg, kind, case in zip(
            err["error"].fillna("").astype(str) if "error" in err else blank,
            err["error_type"].fillna("").astype(str) if "error_type" in err else blank,
            err["case"] if "case" in err else err.index):
        cases, kinds = groups.setdefault(msg, ([], {}))
        cases.append(case)
        kinds[kind] = None
    rows = [[_e(msg or "(no message)"), _e(", ".join(k for k in kinds if k)), _e(len(cases)),
             _e(", ".join(str(c) for c in sorted(cases)[:5]) + (", ..." if len(cases) > 5
                                                                 else ""))]
            for msg, (cases, kinds) in sorted(groups.items(), key=lambda g: -len(g[1][0]))]
    table = _table(("message", "type", "cases", "first cases"), rows,
                   {0: "message", 1: "text", 3: "text"})
    return _section("errors", f"Errors ({len(err)} cases, {len(rows)} messages)", table)


def _png(fig):
    if hasattr(fig, "savefig"):
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=100)
        return buf.getvalue()
    try:
        data = Path(fig).read_bytes()
    except (OSError, TypeError) as exc:
        raise JunctureError(f"figure {fig!r}: not a matplotlib Figure or a readable PNG file "
                            f"({exc})") from None
    if not data.startswith(_PNG_MAGIC):
        raise JunctureError(f"figure {fig}: not a PNG file")
    return data


def _figure_section(figures):
    items = figures.items() if isinstance(figures, Mapping) else ((None, f) for f in figures)
    parts = []
    for k, (caption, fig) in enumerate(items, 1):
        b64 = base64.b64encode(_png(fig)).decode("ascii")
        if caption is None:
            caption = (Path(fig).stem.replace("_", " ") if isinstance(fig, str | Path)
                       else f"figure {k}")
        parts.append(f'<figure><img alt="{_e(caption)}" src="data:image/png;base64,{b64}">'
                     f"<figcaption>{_e(caption)}</figcaption></figure>")
    return _section("figures", "Figures", "".join(parts)) if parts else None


def _keys(df):
    status = df["status"].astype(str)
    items = [(len(df), "cases"), ((status == "ok").sum(), "ok"),
             ((status == "error").sum(), "error")]
    if "wall_time" in df.columns:
        items.append((format(np.nansum(_floats(df["wall_time"])), ".4g"), "total wall time [s]"))
    return '<div class="keys">' + "".join(f"<div><b>{_e(v)}</b><small>{_e(k)}</small></div>"
                                          for v, k in items) + "</div>"


def render_sweep_report(df, parameters, figures=(), title="juncture sweep", spec_text=None,
                        units=DEFAULT_UNITS):
    """The sweep's report as one self-contained HTML string (see :func:`write_sweep_report`)."""
    names = _parameters(df, parameters)
    sections = [_parameter_section(df, names), _minimum_section(df, names, units),
                _error_section(df), _figure_section(figures)]
    if spec_text is not None:
        sections.append(_section("spec", "Sweep specification", f"<pre>{_e(spec_text)}</pre>"))
    sections = [s for s in sections if s]
    nav = "".join(f'<a href="#{i}">{_e(t)}</a>' for i, t, _ in sections)
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<meta name=\"generator\" content=\"juncture {_e(__version__)}\">"
            f"<title>{_e(title)}</title><style>{REPORT_CSS}{_CSS}</style></head><body>"
            f'<header><h1>{_e(title)}</h1><div class="meta"><span>juncture '
            f"{_e(__version__)}</span><span>{len(names)} varied parameters</span></div>"
            f"{_keys(df)}</header><nav>{nav}</nav><main>"
            f"{''.join(s for _, _, s in sections)}</main></body></html>\n")


def write_sweep_report(df, parameters, path, figures=(), title="juncture sweep",
                       spec_text=None, units=DEFAULT_UNITS):
    """Write the sweep's self-contained HTML report (nothing fetched); return its path.

    Sections: counts (cases, ok, error, wall time), varied parameters (range or categories),
    least wave drag per Mach number (its case and parameters), errors grouped by message
    (count, first five cases), figures, the sweep's specification.

    Parameters
    ----------
    df : pandas.DataFrame
        Sweep results (see the module's docstring).
    parameters : sequence of str
        Varied parameters.
    path : str or path-like
        Output file, written atomically.
    figures : sequence of (PNG path or matplotlib Figure), or mapping caption -> either
        Embedded as base64 PNG ``data:`` images, in order; a path's caption is its name
        (``drag_vs_parameters.png``: "drag vs parameters"). Figures are not closed.
    title : str
        Title and heading of the page.
    spec_text : str, optional
        The sweep's specification, shown verbatim.
    units : str
        Length unit of D/q (its square).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    JunctureError
        A missing column, or a figure that is neither a Figure nor a readable PNG file.
    """
    text = render_sweep_report(df, parameters, figures=figures, title=title,
                               spec_text=spec_text, units=units)
    path = Path(path)
    with atomic_output(path, "w", encoding="utf-8") as fh:
        fh.write(text)
    return path
