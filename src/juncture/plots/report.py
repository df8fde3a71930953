"""A self-contained HTML report of a juncture run, readable by a designer at a glance.

One file, no external resources: the style sheet and a small wireframe viewer are inline
(:mod:`juncture.plots.report_css`, :mod:`juncture.plots.report_js`), figures are base64 PNG
``data:`` images, and the 3-D view's polylines are JSON in a ``<script
type="application/json">`` element. Sections, in order: header (title, deck title, date,
juncture version, command), key numbers, 3-D view, inputs (components; options and log),
intersections, fillet stations, wave drag, mass properties, figures. A section without data
is left out.

Components have the colours of the figures (:func:`juncture.plots.style.component_colour`),
and every length, area and mass states its unit: ``units`` (default ``"ft"``) is a label
only, the deck's coordinates are never converted.
"""

from __future__ import annotations

import base64
import datetime as _dt
import io
import json
import shlex
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from .. import __version__
from ..errors import JunctureError
from ..geometry import Geometry
from ..io._registry import atomic_output
from .report_css import REPORT_CSS
from .report_html import _e, _num, _section, _table, _u
from .report_js import REPORT_JS
from .report_surface import closed_surface_key, closed_surface_section
from .style import DEFAULT_UNITS, INTERSECTION_COLOUR, component_colour, component_of, unit_label

__all__ = ["write_report", "render_report", "wireframe_data"]

_PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
#: Caption of the wave-drag cases' area distributions among the report's figures.
WAVEDRAG_CAPTION = "area distributions of the wave-drag cases"
# (key, heading, power of the length unit: 0 for a ratio)
_STATION_COLUMNS = (("x", "x", 1), ("area_original", "original area", 2),
                    ("area_fillet", "fillet area", 2), ("area_body", "body area", 2),
                    ("radius_original", "original radius", 1), ("radius_new", "new radius", 1),
                    ("residual", "residual", 0))


# ------------------------------------------------------------------ 3-D view data
def _pick(n, limit):
    """At most ``limit`` indices of range(n), evenly spread, always with the first and last."""
    if n <= limit:
        return np.arange(n)
    return np.unique(np.round(np.linspace(0, n - 1, limit)).astype(int))


def wireframe_data(geo, max_lines=40, max_points=60, components=(), aliases=None):
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
        ``"pod 1"``); other networks are grouped by their name less its part words
        (:func:`juncture.plots.style.component_of`).
    aliases : mapping of str to str, optional
        Network prefix -> component for networks not named after their component
        (:func:`juncture.plots.juncture.network_aliases`).

    Returns
    -------
    dict
        ``"centre"`` (3,) and ``"size"`` (the bounding-box diagonal) [deck length];
        ``"components"``: list of ``{"name", "colour"}`` (the figures' colour of the
        component, :func:`juncture.plots.style.component_colour`); ``"networks"``: list of
        ``{"name",
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
        comp = component_of(name, components, aliases)
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
        # A lofting line that missed the other surface leaves a NaN point: a break.
        ok = np.isfinite(pts).all(axis=1)
        runs = [r for r in np.split(pts, np.flatnonzero(~ok)) if len(r)]
        runs = [r[np.isfinite(r).all(axis=1)] for r in runs]
        lines = [flat(r) for r in runs if len(r)]
        if mirror:
            lines += [flat(r * np.array([1.0, -1.0, 1.0])) for r in runs if len(r)]
        inters.append({"name": name, "lines": lines})
    return {"centre": flat(0.5 * (ext[0] + ext[1])), "size": size,
            "components": [{"name": c, "colour": component_colour(c)} for c in comps],
            "intersection_colour": INTERSECTION_COLOUR,
            "networks": out, "intersections": inters}


def _json_script(obj):
    """JSON safe to place inside a <script> element (no '<', '>' or '&' characters)."""
    text = json.dumps(obj, separators=(",", ":"), allow_nan=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def _viewer(geo, model):
    from .juncture import network_aliases

    names = [c.name for c in model] if model is not None else ()
    data = wireframe_data(geo, components=names,
                          aliases=network_aliases(model, geo) if model is not None else None)
    legend = "".join(f'<span><i style="background:{c["colour"]}"></i>{_e(c["name"])}</span>'
                     for c in data["components"])
    if data["intersections"]:
        legend += (f'<span><i style="background:{INTERSECTION_COLOUR}"></i>intersections'
                   "</span>")
    n_pts = sum(len(line) // 3 for n in data["networks"] for line in n["lines"])
    tools = "".join(f'<button type="button" data-view="{v}">{lab}</button>' for v, lab in
                    (("iso", "reset"), ("top", "top"), ("side", "side"), ("front", "front")))
    body = (f'<div class="tools">{tools} <span class="note">drag: rotate, shift-drag: pan, '
            f"wheel: zoom; mirror images lighter; top: from above, y up (the plan view); "
            f"front: from ahead</span></div>"
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


def _inputs(cfg, geo, units):
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
        parts.append(_table(("component", "kind", "sections x stations / stations", "mirrored")
                            + tuple(f"{a} extent{_u(units)}" for a in "xyz"), rows,
                            text_columns=(0, 1, 2, 3)))
        ref = getattr(cfg, "reference_area", None)
        if ref:
            parts.append(f'<p class="note">reference area {_num(ref)} {unit_label(units, 2)}; '
                         f"symmetric about the x-z plane: "
                         f"{'yes' if getattr(cfg, 'symmetric', True) else 'no'}</p>")
    parts.append(f"<p class=\"note\">output: {len(geo.networks)} networks; lengths in "
                 f"{_e(unit_label(units))}, the deck's own unit (nothing converted)</p>")
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


def _intersections(geo, model, units):
    if not geo.intersections:
        return None
    rows = []
    for name, all_pts in geo.intersections.items():
        pts = all_pts[np.isfinite(all_pts).all(axis=1)]  # NaN: a line that missed
        body = _body_of(name, model)
        dist = None
        if body is not None and hasattr(body, "radial_error") and len(pts):
            dist = float(np.max(np.abs(body.radial_error(pts))))
        count = str(len(pts)) if len(pts) == len(all_pts) else f"{len(pts)} of {len(all_pts)}"
        span = f"{_num(pts[:, 0].min())} &hellip; {_num(pts[:, 0].max())}" if len(pts) \
            else "&ndash;"
        rows.append([_e(name), count, span, _num(dist, ".3g")])
    note = ('<p class="note">distance from the body: largest |distance from the local section '
            "centre - r(x)| (TM-4406 eq 6) of the points, on the body of the completed "
            "model; \"k of n\" points: n - k lofting lines missed the other surface</p>")
    return _section("intersections", "Intersections",
                    _table(("intersection", "points", f"x range{_u(units)}",
                            f"max distance from body{_u(units)}"), rows) + note)


def _stations(geo, units):
    st = geo.stations
    if not st or "x" not in st:
        return None
    cols = [(k, label + _u(units, power)) for k, label, power in _STATION_COLUMNS if k in st]
    rows = [[_num(st[k][i], ".3g" if k == "residual" else ".7g") for k, _ in cols]
            for i in range(len(st["x"]))]
    note = ('<p class="note">areas of both halves; residual: |body + fillet - original| / '
            "original area at the station</p>")
    return _section("stations", "Fillet stations",
                    _table([label for _, label in cols], rows, text_columns=()) + note)


def _wavedrag(results, units):
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
                    _table(("case", "method", "Mach", f"D/q{_u(units, 2)}", "CD",
                            "change vs first"), rows, text_columns=(0, 1)) +
                    '<p class="note">D/q: wave drag over dynamic pressure; CD = (D/q) / '
                    "reference area</p>")


def _unit_density(items):
    """Whether every mass equals its volume: no density given, so it was 1."""
    return all(abs(p.mass - p.volume) <= 1e-9 * max(abs(p.volume), 1e-300) for _, p in items)


def _mass_units(massprops, units):
    """(mass unit, inertia unit, sentence) of the mass properties, for headings and notes."""
    total, parts = massprops
    parts = list(parts.items() if isinstance(parts, Mapping) else parts)
    vol, inertia = unit_label(units, 3), unit_label(units, 5)
    if _unit_density(list(parts) + [("total", total)]):
        return (f"{vol} at density 1", f"{inertia} at density 1",
                f"mass = density x volume; no density was given, so it is 1 and each mass is "
                f"its volume in {vol} (inertias in {inertia})")
    return (f"density x {vol}", f"mass x {unit_label(units, 2)}",
            f"mass = density x volume, in the unit of the densities given times {vol}; "
            f"inertias in that mass unit times {unit_label(units, 2)}")


def _massprops(massprops, units):
    try:
        total, parts = massprops
        parts = list(parts.items() if isinstance(parts, Mapping) else parts)
        items = [(str(n), p) for n, p in parts] + [("total", total)]
        cells = [(n, p.mass, p.volume, np.asarray(p.cg, float), np.diag(p.inertia))
                 for n, p in items]
        mass_unit, inertia_unit, sentence = _mass_units(massprops, units)
    except (TypeError, ValueError, AttributeError):
        raise JunctureError("massprops must be (total, parts) as returned by "
                            "configuration_mass_properties: MassProperties and a list of "
                            "(name, MassProperties)") from None
    rows = [[_e(n), _num(m), _num(v)] + [_num(c) for c in cg] + [_num(i) for i in ii]
            for n, m, v, cg, ii in cells]
    note = (f'<p class="note">{_e(sentence)}; inertia about each body\'s own CG; overlaps '
            "counted in both</p>")
    headings = (("component", f"mass [{mass_unit}]", f"volume{_u(units, 3)}")
                + tuple(f"CG {a}{_u(units)}" for a in "xyz")
                + tuple(f"I{a}{a} [{inertia_unit}]" for a in "xyz"))
    return _section("massprops", "Mass properties",
                    _table(headings, rows[:-1], total=rows[-1]) + note)


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


def _default_figures(cfg, geo, wavedrag, units):
    """caption -> Figure: the run's figures that apply, and the wave-drag areas."""
    from .areas import plot_wavedrag_areas
    from .figures import run_figures

    figs = {caption: fig for _, caption, fig in run_figures(
        cfg, geo, fillet=bool(geo.fillets), units=units, warn=False)}
    if wavedrag:
        figs[WAVEDRAG_CAPTION] = plot_wavedrag_areas(
            wavedrag, title=(cfg.title if cfg is not None else "") or geo.title, units=units)
    return figs


def _figures(figures, dpi):
    parts = []
    for caption, fig in figures.items():
        b64 = base64.b64encode(_png_of(caption, fig, dpi)).decode("ascii")
        parts.append(f'<figure><img alt="{_e(caption)}" src="data:image/png;base64,{b64}">'
                     f"<figcaption>{_e(caption)}</figcaption></figure>")
    return _section("figures", "Figures", "".join(parts)) if parts else None


def _keys(geo, wavedrag, massprops, units, surface=None):
    st, items = geo.stations, [(str(len(geo.networks)), "networks")]
    if "x" in st and len(st["x"]):
        items.append((str(len(st["x"])), "fillet stations"))
        if "area_fillet" in st:
            items.append((f"{_num(np.max(st['area_fillet']), '.4g')} "
                          f"{_e(unit_label(units, 2))}", "largest added area"))
        if "radius_original" in st and "radius_new" in st:
            items.append((f"{_num(np.max(st['radius_original'] - st['radius_new']), '.4g')} "
                          f"{_e(unit_label(units))}", "largest radius reduction"))
        if "residual" in st:
            items.append((_num(np.max(st["residual"]), ".3g"), "worst area residual"))
    if wavedrag and len(wavedrag) > 1:
        vals = [float(r["D_over_q"]) for r in wavedrag.values()]
        if vals[0]:
            items.append((f"{100 * (vals[-1] - vals[0]) / vals[0]:+.3f} %",
                          "wave drag, last case vs first"))
    if massprops:
        mass_unit = _mass_units(massprops, units)[0]
        if mass_unit.endswith("at density 1"):
            items.append((f"{_num(massprops[0].mass, '.5g')} {_e(unit_label(units, 3))}",
                          "total mass (density 1: mass = volume)"))
        else:
            items.append((_num(massprops[0].mass, ".5g"), f"total mass [{mass_unit}]"))
    key = closed_surface_key(surface, units)
    if key:
        items.append(key)
    return '<div class="keys">' + "".join(f"<div><b>{v}</b><small>{_e(k)}</small></div>"
                                          for v, k in items) + "</div>"


# ------------------------------------------------------------------ public API
def render_report(cfg, geo, *, wavedrag=None, massprops=None, figures=None, title=None,
                  command=None, dpi=100, units=DEFAULT_UNITS, surface=None):
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
    sections = [_viewer(geo, model),
                _inputs(cfg, geo, units), _intersections(geo, model, units),
                _stations(geo, units)]
    if wavedrag is not None:
        sections.append(_wavedrag(wavedrag, units))
    if massprops is not None:
        sections.append(_massprops(massprops, units))
    sections.append(closed_surface_section(surface, units))
    own = figures is None
    figs = _default_figures(cfg, geo, wavedrag, units) if own else dict(figures)
    try:
        sections.append(_figures(figs, dpi))
    finally:
        if own:
            from ._backend import pyplot

            for fig in figs.values():
                pyplot().close(fig)
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
            f"{_keys(geo, wavedrag, massprops, units, surface)}</header><nav>{nav}</nav><main>"
            f"{''.join(s for _, _, s in sections)}</main>"
            f"<script>{REPORT_JS}</script></body></html>\n")


def write_report(path, cfg, geo, *, wavedrag=None, massprops=None, figures=None, title=None,
                 command=None, units=DEFAULT_UNITS, surface=None) -> Path:
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
    surface : SurfaceMesh or str, optional
        The completed airplane's closed surface (:func:`juncture.mesh`): its enclosed volume,
        wetted areas and triangle quality get a section; a str says why there is none.
    figures : mapping of str to (matplotlib Figure or path of a PNG), optional
        Caption -> figure, embedded as base64 PNG in this order. None: the report draws its
        own (three views; the juncture figures that apply, those of the fillet when there is
        one; with ``wavedrag`` the area distributions). An empty mapping: no figures.
        Figures passed in are not closed.
    title : str, optional
        Heading; default ``"juncture report: <deck title>"``.
    command : str or sequence of str, optional
        The command line of the run, shown in the header.
    units : str
        Length unit written in the tables, key numbers and figures (default ``"ft"``; areas
        in its square, volumes and masses at density 1 in its cube). A label only: the
        deck's coordinates are never converted.

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
    >>> from juncture.plots import write_report
    >>> from juncture.cli import bundled_example
    >>> cfg = jc.read(bundled_example())
    >>> geo = jc.complete(cfg, fillet="cubic", keep_area=True)
    >>> out = write_report(tempfile.mkdtemp() + "/report.html", cfg, geo, figures={})
    >>> out.read_text().startswith("<!DOCTYPE html>")
    True
    """
    text = render_report(cfg, geo, wavedrag=wavedrag, massprops=massprops, figures=figures,
                         title=title, command=command, units=units, surface=surface)
    path = Path(path)
    with atomic_output(path, "w", encoding="utf-8") as fh:
        fh.write(text)
    return path
