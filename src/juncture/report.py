"""A self-contained HTML report of a juncture run, readable by a designer at a glance.

One file, no external resources: the style sheet and a small wireframe viewer are inline
(:mod:`juncture.report_css`, :mod:`juncture.report_js`), figures are base64 PNG ``data:``
images, and the 3-D view's polylines are JSON in a ``<script type="application/json">``
element. Sections, in order: header (title, deck title, date, juncture version, command),
key numbers, 3-D view, inputs (components; options and log), intersections, fillet stations,
wave drag, mass properties, figures. A section without data is left out.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import io
import json
import shlex
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from . import __version__
from .errors import JunctureError
from .geometry import Geometry
from .io._registry import atomic_output
from .report_css import REPORT_CSS
from .report_js import REPORT_JS

__all__ = ["write_report", "render_report", "wireframe_data"]

#: Component colours of the 3-D view (matplotlib's tab10, so they match the figures' order).
PALETTE = ("#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
           "#bcbd22", "#17becf", "#393b79", "#637939", "#8c6d31", "#843c39", "#7b4173")
_PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
_STATION_COLUMNS = (("x", "x"), ("area_original", "original area"),
                    ("area_fillet", "fillet area"), ("area_body", "body area"),
                    ("radius_original", "original radius"), ("radius_new", "new radius"),
                    ("residual", "residual"))


# ------------------------------------------------------------------ small HTML helpers
def _e(text):
    return html.escape(str(text), quote=True)


def _num(value, fmt=".6g"):
    if value is None:
        return "&ndash;"
    v = float(value)
    return format(v, fmt) if np.isfinite(v) else _e(v)


def _table(headers, rows, total=None, text_columns=(0,)):
    """An HTML table; ``rows`` hold already-escaped cell strings."""
    head = "".join(f'<th class="text">{_e(h)}</th>' if i and i in text_columns
                   else f"<th>{_e(h)}</th>" for i, h in enumerate(headers))
    body = []
    for row in list(rows) + ([total] if total else []):
        cells = "".join(f'<td class="text">{c}</td>' if i and i in text_columns
                        else f"<td>{c}</td>" for i, c in enumerate(row))
        body.append(f'<tr class="total">{cells}</tr>' if row is total else f"<tr>{cells}</tr>")
    return f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def _section(ident, heading, body):
    """(id, heading, HTML) of one report section."""
    return ident, heading, f'<section id="{ident}"><h2>{_e(heading)}</h2>{body}</section>'


# ------------------------------------------------------------------ 3-D view data
def _component_of(name, components):
    """The component a network name belongs to: the longest component-name prefix."""
    base = name[:-len(" image")] if name.endswith(" image") else name
    for comp in sorted(components, key=len, reverse=True):
        if base == comp or base.startswith(comp + " "):
            return comp
    return base.rsplit(" ", 1)[0] if " " in base else base


def _pick(n, limit):
    """At most ``limit`` indices of range(n), evenly spread, always with the first and last."""
    if n <= limit:
        return np.arange(n)
    return np.unique(np.round(np.linspace(0, n - 1, limit)).astype(int))


def wireframe_data(geo, max_lines=40, max_points=60, components=()):
    """The 3-D view's content: downsampled n-lines and m-lines of every network and image.

    Parameters
    ----------
    geo : Geometry
        Networks (with mirror images, :meth:`Geometry.mirrored_networks`) and intersections.
    max_lines, max_points : int
        Each network keeps at most this many n-lines and points per n-line (evenly spread,
        first and last kept); its m-lines are drawn at the kept points.
    components : sequence of str
        Component names used to colour networks (a network ``"pod 1 image"`` belongs to
        ``"pod 1"``); other networks are grouped by their name less its last word.

    Returns
    -------
    dict
        ``"centre"`` (3,) and ``"size"`` (the bounding-box diagonal) [deck length];
        ``"components"``: list of ``{"name", "colour"}``; ``"networks"``: list of ``{"name",
        "component" (index), "image" (bool), "lines"}``; ``"intersections"``: list of
        ``{"name", "lines"}``. A line is a flat list ``[x0, y0, z0, x1, ...]`` rounded to
        1e-4 of ``size``. Intersections of a geometry with xz symmetry are mirrored too.
    """
    if int(max_lines) < 2 or int(max_points) < 2:
        raise JunctureError(f"max_lines and max_points must be at least 2, found "
                            f"{max_lines} and {max_points}")
    nets = geo.mirrored_networks()
    ext = geo.extents()
    size = float(np.linalg.norm(ext[1] - ext[0])) or 1.0
    digits = int(max(0, 4 - np.floor(np.log10(size))))
    comps, out = [], []

    def flat(a):
        return np.round(np.asarray(a, float), digits).reshape(-1).tolist()

    for name, net in nets.items():
        comp = _component_of(name, components)
        if comp not in comps:
            comps.append(comp)
        sub = net[_pick(net.shape[0], int(max_lines))][:, _pick(net.shape[1], int(max_points))]
        lines = [flat(row) for row in sub]
        if sub.shape[0] > 1:
            lines += [flat(col) for col in sub.transpose(1, 0, 2)]
        out.append({"name": name, "component": comps.index(comp),
                    "image": name.endswith(" image"), "lines": lines})
    mirror = "xz" in set(geo.symmetry.values())
    inters = []
    for name, pts in geo.intersections.items():
        lines = [flat(pts)]
        if mirror:
            lines.append(flat(pts * np.array([1.0, -1.0, 1.0])))
        inters.append({"name": name, "lines": lines})
    return {"centre": flat(0.5 * (ext[0] + ext[1])), "size": size,
            "components": [{"name": c, "colour": PALETTE[i % len(PALETTE)]}
                           for i, c in enumerate(comps)],
            "networks": out, "intersections": inters}


def _json_script(obj):
    """JSON safe to place inside a <script> element (no '<', '>' or '&' characters)."""
    text = json.dumps(obj, separators=(",", ":"), allow_nan=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def _viewer(geo, components):
    data = wireframe_data(geo, components=components)
    legend = "".join(f'<span><i style="background:{c["colour"]}"></i>{_e(c["name"])}</span>'
                     for c in data["components"])
    if data["intersections"]:
        legend += '<span><i style="background:#d62728"></i>intersections</span>'
    n_pts = sum(len(line) // 3 for n in data["networks"] for line in n["lines"])
    tools = "".join(f'<button type="button" data-view="{v}">{lab}</button>' for v, lab in
                    (("iso", "reset"), ("top", "top"), ("side", "side"), ("front", "front")))
    body = (f'<div class="tools">{tools} <span class="note">drag to rotate, shift-drag to pan, '
            f'wheel to zoom; images of mirrored networks lighter</span></div>'
            f'<div class="viewer"><canvas id="jr-canvas" width="1100" height="460">'
            f"3-D wireframe (needs JavaScript)</canvas></div>"
            f'<div class="legend">{legend}</div>'
            f'<p class="note">{len(data["networks"])} networks, {n_pts} polyline points '
            f"(downsampled to at most 40 n-lines x 60 points per network)</p>"
            f'<script type="application/json" id="jr-data">{_json_script(data)}</script>')
    return _section("view3d", "3-D view", body)


# ------------------------------------------------------------------ sections
def _counts(comp):
    if hasattr(comp, "n_sections"):
        return f"{comp.n_sections} sections x {comp.n_stations} stations"
    if hasattr(comp, "x") and hasattr(comp, "segments"):
        return f"{np.size(comp.x)} stations in {len(comp.segments)} segment(s)"
    return ""


def _inputs(cfg, geo):
    parts = []
    if cfg is not None:
        rows = []
        for comp in cfg:
            pts = np.concatenate([n.reshape(-1, 3) for n in comp.networks().values()])
            lo, hi = pts.min(axis=0), pts.max(axis=0)
            rows.append([_e(comp.name), _e(getattr(comp, "kind", None) or type(comp).__name__),
                         _e(_counts(comp)), "yes" if comp.mirrored else "no"]
                        + [f"{_num(lo[k], '.5g')} &hellip; {_num(hi[k], '.5g')}"
                           for k in range(3)])
        parts.append(_table(("component", "kind", "sections x stations / stations", "mirrored",
                             "x extent", "y extent", "z extent"), rows, text_columns=(0, 1, 2, 3)))
        ref = getattr(cfg, "reference_area", None)
        if ref:
            parts.append(f'<p class="note">reference area {_num(ref)}; symmetric about the x-z '
                         f"plane: {'yes' if getattr(cfg, 'symmetric', True) else 'no'}</p>")
    parts.append(f"<p class=\"note\">output: {len(geo.networks)} networks</p>")
    if geo.log:
        parts.append(f"<details><summary>options and log of the run ({len(geo.log)} lines)"
                     f"</summary><pre>{_e(chr(10).join(geo.log))}</pre></details>")
    return _section("inputs", "Inputs", "".join(parts))


def _body_of(name, model):
    """The component an intersection ``"<a>/<b> <surface>"`` lies on, if the model has it."""
    if model is None or "/" not in name:
        return None
    rest = name.split("/", 1)[1]
    names = [c.name for c in model]
    for comp in sorted(names, key=len, reverse=True):
        if rest == comp or rest.startswith(comp + " "):
            return model[comp]
    return None


def _intersections(geo, model):
    if not geo.intersections:
        return None
    rows = []
    for name, pts in geo.intersections.items():
        body = _body_of(name, model)
        dist = None
        if body is not None and hasattr(body, "radial_error") and len(pts):
            dist = float(np.max(np.abs(body.radial_error(pts))))
        rows.append([_e(name), str(len(pts)), f"{_num(pts[:, 0].min())} &hellip; "
                     f"{_num(pts[:, 0].max())}", _num(dist, ".3g")])
    note = ('<p class="note">distance from the body: largest |distance from the local section '
            "centre - r(x)| (TM-4406 eq 6) of the points, on the body of the completed "
            "model</p>")
    return _section("intersections", "Intersections",
                    _table(("intersection", "points", "x range", "max distance from body"),
                           rows) + note)


def _stations(geo):
    st = geo.stations
    if not st or "x" not in st:
        return None
    cols = [(k, label) for k, label in _STATION_COLUMNS if k in st]
    rows = [[_num(st[k][i], ".3g" if k == "residual" else ".7g") for k, _ in cols]
            for i in range(len(st["x"]))]
    note = ('<p class="note">areas of both halves; residual: |body + fillet - original| / '
            "original area at the station</p>")
    return _section("stations", "Fillet stations",
                    _table([label for _, label in cols], rows, text_columns=()) + note)


def _wavedrag(results):
    if not isinstance(results, Mapping) or not results:
        raise JunctureError(f"wavedrag must be a non-empty mapping label -> wavedrag() "
                            f"result, found {type(results).__name__}")
    rows, first = [], None
    for label, res in results.items():
        if not isinstance(res, Mapping) or "D_over_q" not in res:
            raise JunctureError(f"wavedrag result {label!r} has no 'D_over_q'; expected a "
                                "juncture.analysis.wavedrag() result")
        dq = float(res["D_over_q"])
        first = dq if first is None else first
        change = "&ndash;" if first == 0 else f"{100.0 * (dq - first) / first:+.3f} %"
        rows.append([_e(label), _e(res.get("method", "")), _num(res.get("mach"), "g"),
                     _num(dq), _num(res.get("CD")), change])
    return _section("wavedrag", "Wave drag",
                    _table(("case", "method", "Mach", "D/q", "CD", "change vs first"), rows,
                           text_columns=(0, 1)))


def _massprops(massprops):
    try:
        total, parts = massprops
        parts = list(parts.items() if isinstance(parts, Mapping) else parts)
        items = [(str(n), p) for n, p in parts] + [("total", total)]
        cells = [(n, p.mass, p.volume, np.asarray(p.cg, float), np.diag(p.inertia))
                 for n, p in items]
    except (TypeError, ValueError, AttributeError):
        raise JunctureError("massprops must be (total, parts) as returned by "
                            "configuration_mass_properties: MassProperties and a list of "
                            "(name, MassProperties)") from None
    rows = [[_e(n), _num(m), _num(v)] + [_num(c) for c in cg] + [_num(i) for i in ii]
            for n, m, v, cg, ii in cells]
    note = '<p class="note">inertia about each body\'s own CG; overlaps counted in both</p>'
    return _section("massprops", "Mass properties",
                    _table(("component", "mass", "volume", "CG x", "CG y", "CG z", "Ixx", "Iyy",
                            "Izz"), rows[:-1], total=rows[-1]) + note)


def _png_of(caption, fig, dpi):
    if hasattr(fig, "savefig"):
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=dpi)
        return buf.getvalue()
    if isinstance(fig, (str, Path)):
        try:
            data = Path(fig).read_bytes()
        except OSError as exc:
            raise JunctureError(f"figure {caption!r}: cannot read {fig}: {exc}") from None
        if not data.startswith(_PNG_MAGIC):
            raise JunctureError(f"figure {caption!r}: {fig} is not a PNG file")
        return data
    raise JunctureError(f"figure {caption!r} must be a matplotlib Figure or the path of a "
                        f"PNG, found {type(fig).__name__}")


def _area_figure(results):
    from .plots import plt

    fig, ax = plt.subplots(figsize=(9, 4.5), layout="constrained")
    for label, res in results.items():
        if "x" in res and "area" in res:
            ax.plot(res["x"], res["area"], lw=1.3, label=f"{label} (D/q = {res['D_over_q']:.5g})")
    ax.set_xlabel("x (aft)")
    ax.set_ylabel("normal area A(x), both halves")
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.legend(fontsize=8)
    return fig


def _default_figures(cfg, geo, wavedrag):
    """caption -> Figure: views, and the juncture figures when the geometry has fillets."""
    from . import plots, plots_juncture

    figs = {"planform, side and front views": plots.plot_views(geo)}
    names = set() if cfg is None else {c.name for c in cfg}
    if geo.fillets and {"wing", "body"} <= names:
        figs.update({
            "intersection and gap to the body (TM-4406 fig 3)":
                plots_juncture.plot_gap_and_intersection(cfg, geo),
            "lower intersection": plots_juncture.plot_lower_intersection(cfg, geo),
            "fillet lines at constant x (TM-4406 figs 6-9)":
                plots_juncture.plot_fillet_sections(cfg, geo),
            "areas at the fillet stations": plots_juncture.plot_station_areas(geo)})
    if wavedrag:
        figs["normal-area distributions of the wave-drag cases"] = _area_figure(wavedrag)
    return figs


def _figures(figures, dpi):
    parts = []
    for caption, fig in figures.items():
        b64 = base64.b64encode(_png_of(caption, fig, dpi)).decode("ascii")
        parts.append(f'<figure><img alt="{_e(caption)}" src="data:image/png;base64,{b64}">'
                     f"<figcaption>{_e(caption)}</figcaption></figure>")
    return _section("figures", "Figures", "".join(parts)) if parts else None


def _keys(geo, wavedrag, massprops):
    st, items = geo.stations, [(str(len(geo.networks)), "networks")]
    if "x" in st and len(st["x"]):
        items.append((str(len(st["x"])), "fillet stations"))
        if "area_fillet" in st:
            items.append((_num(np.max(st["area_fillet"]), ".4g"), "largest added area"))
        if "radius_original" in st and "radius_new" in st:
            items.append((_num(np.max(st["radius_original"] - st["radius_new"]), ".4g"),
                          "largest radius reduction"))
        if "residual" in st:
            items.append((_num(np.max(st["residual"]), ".3g"), "worst area residual"))
    if wavedrag and len(wavedrag) > 1:
        vals = [float(r["D_over_q"]) for r in wavedrag.values()]
        if vals[0]:
            items.append((f"{100 * (vals[-1] - vals[0]) / vals[0]:+.3f} %",
                          "wave drag, last case vs first"))
    if massprops:
        items.append((_num(massprops[0].mass, ".5g"), "total mass"))
    return '<div class="keys">' + "".join(f"<div><b>{v}</b><small>{_e(k)}</small></div>"
                                          for v, k in items) + "</div>"


# ------------------------------------------------------------------ public API
def render_report(cfg, geo, *, wavedrag=None, massprops=None, figures=None, title=None,
                  command=None, dpi=100):
    """The report of a run as one HTML string (see :func:`write_report`)."""
    if not isinstance(geo, Geometry):
        raise JunctureError(f"the report needs a Geometry (from juncture.complete), found "
                            f"{type(geo).__name__}")
    if cfg is not None and not hasattr(cfg, "components"):
        raise JunctureError(f"cfg must be a Configuration or None, found {type(cfg).__name__}")
    if figures is not None and not isinstance(figures, Mapping):
        raise JunctureError(f"figures must be a mapping caption -> Figure or PNG path, found "
                            f"{type(figures).__name__}")
    model = geo.configuration if geo.configuration is not None else cfg
    deck_title = (cfg.title if cfg is not None else "") or geo.title or "untitled"
    heading = title or f"juncture report: {deck_title}"
    cmd = command if command is None or isinstance(command, str) else shlex.join(
        [str(c) for c in command])
    sections = [_viewer(geo, [c.name for c in model] if model is not None else ()),
                _inputs(cfg, geo), _intersections(geo, model), _stations(geo)]
    if wavedrag is not None:
        sections.append(_wavedrag(wavedrag))
    if massprops is not None:
        sections.append(_massprops(massprops))
    own = figures is None
    figs = _default_figures(cfg, geo, wavedrag) if own else dict(figures)
    try:
        sections.append(_figures(figs, dpi))
    finally:
        if own:
            from .plots import plt

            for fig in figs.values():
                plt.close(fig)
    sections = [s for s in sections if s]
    nav = "".join(f'<a href="#{i}">{_e(t)}</a>' for i, t, _ in sections)
    now = _dt.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")
    meta = (f"<span>deck: <b>{_e(deck_title)}</b></span><span>{_e(now)}</span>"
            f"<span>juncture {_e(__version__)}</span>")
    if cmd:
        meta += f"<div>command: <code>{_e(cmd)}</code></div>"
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            f"<meta name=\"generator\" content=\"juncture {_e(__version__)}\">"
            f"<title>{_e(heading)}</title><style>{REPORT_CSS}</style></head><body>"
            f'<header><h1>{_e(heading)}</h1><div class="meta">{meta}</div>'
            f"{_keys(geo, wavedrag, massprops)}</header><nav>{nav}</nav><main>"
            f"{''.join(s for _, _, s in sections)}</main>"
            f"<script>{REPORT_JS}</script></body></html>\n")


def write_report(path, cfg, geo, *, wavedrag=None, massprops=None, figures=None, title=None,
                 command=None) -> Path:
    """Write a self-contained HTML report of a juncture run; return its path.

    Parameters
    ----------
    path : str or path-like
        Output file (written atomically: a failed report leaves no partial file).
    cfg : Configuration or None
        The input configuration (components table, deck title, juncture figures).
    geo : Geometry
        The result of :func:`juncture.complete` (networks, intersections, fillets, stations,
        log, completed configuration); any Geometry will do, sections without data are left
        out.
    wavedrag : mapping of str to dict, optional
        Case label -> :func:`juncture.analysis.wavedrag` result; the first case is the
        reference of the "change" column.
    massprops : (MassProperties, list of (str, MassProperties)), optional
        ``(total, parts)`` from :func:`juncture.massprops.configuration_mass_properties`.
    figures : mapping of str to (matplotlib Figure or path of a PNG), optional
        Caption -> figure, embedded as base64 PNG in this order. None: the report draws its
        own (three views; with fillets the juncture figures; with ``wavedrag`` the area
        distributions). An empty mapping: no figures. Figures passed in are not closed.
    title : str, optional
        Heading; default ``"juncture report: <deck title>"``.
    command : str or sequence of str, optional
        The command line of the run, shown in the header.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    JunctureError
        ``geo`` not a Geometry, malformed ``wavedrag``/``massprops``/``figures``, or a
        figure path that cannot be read or is not a PNG.

    Examples
    --------
    >>> import juncture as jc, tempfile, warnings; warnings.simplefilter("ignore")
    >>> from juncture.cli import bundled_example
    >>> cfg = jc.read(bundled_example())
    >>> geo = jc.complete(cfg, fillet="cubic", keep_area=True)
    >>> out = write_report(tempfile.mkdtemp() + "/report.html", cfg, geo, figures={})
    >>> out.read_text().startswith("<!DOCTYPE html>")
    True
    """
    text = render_report(cfg, geo, wavedrag=wavedrag, massprops=massprops, figures=figures,
                         title=title, command=command)
    path = Path(path)
    with atomic_output(path, "w", encoding="utf-8") as fh:
        fh.write(text)
    return path
