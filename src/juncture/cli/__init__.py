"""The ``juncture`` command: thin wrappers that parse, call the public API and print.

A :class:`~juncture.errors.JunctureError` (bad input) becomes one line on stderr and exit
status 2, as argparse gives for a usage error; ``--debug`` shows the traceback instead.
"""

from __future__ import annotations

import argparse
import sys
import warnings
from importlib import resources
from pathlib import Path

import numpy as np

from . import __version__
from .errors import JunctureError

__all__ = ["main", "bundled_example"]


def bundled_example(name="supersonic_transport.inp"):
    """Path of a bundled example file (package data)."""
    return Path(str(resources.files("juncture") / "data" / name))


def _fmt_extent(lo, hi):
    return f"[{lo:10.4g}, {hi:10.4g}]"


def _describe(obj):
    from .geometry import Geometry

    lines = []
    if isinstance(obj, Geometry):
        lines.append(f"title: {obj.title}")
        lines.append(f"{len(obj.networks)} networks:")
        for name, net in obj.networks.items():
            sym = obj.symmetry.get(name)
            lines.append(f"  {name:<32} {net.shape[0]:4d} n-lines x {net.shape[1]:4d} points"
                         + (f"  image in {sym} plane" if sym else ""))
        ext = obj.extents()
    else:
        cfg = obj
        lines.append(f"title: {cfg.title}")
        if cfg.reference_area is not None:
            lines.append(f"reference area: {cfg.reference_area:g}"
                         + (f", chord {cfg.reference_chord:g}" if cfg.reference_chord else "")
                         + (f", moment centre x {cfg.moment_x:g}" if cfg.moment_x else ""))
        lines.append(f"{len(cfg)} components:")
        for comp in cfg:
            kind = getattr(comp, "kind", None) or type(comp).__name__
            if hasattr(comp, "n_sections"):
                counts = f"{comp.n_sections} sections x {comp.n_stations} stations"
            else:
                counts = f"{comp.x.size} stations in {len(comp.segments)} segment(s)"
            nets = comp.networks()
            pts = np.concatenate([n.reshape(-1, 3) for n in nets.values()])
            lo, hi = pts.min(0), pts.max(0)
            lines.append(f"  {comp.name:<12} {kind:<14} {counts:<32}"
                         f"{'mirrored' if comp.mirrored else '':<9}")
            lines.append("      x " + _fmt_extent(lo[0], hi[0]) + "  y " + _fmt_extent(lo[1], hi[1])
                         + "  z " + _fmt_extent(lo[2], hi[2]))
        ext = cfg.extents()
    lines.append("extents: x " + _fmt_extent(ext[0, 0], ext[1, 0]) + "  y "
                 + _fmt_extent(ext[0, 1], ext[1, 1]) + "  z " + _fmt_extent(ext[0, 2], ext[1, 2]))
    return lines


def _read_with_warnings(path, fmt=None):
    from .io import read

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        obj = read(path, format=fmt)
    return obj, [str(w.message) for w in caught]


def _cmd_info(args):
    obj, warns = _read_with_warnings(args.file, args.format)
    print("\n".join(_describe(obj)))
    if warns:
        print(f"{len(warns)} warning(s):")
        for w in warns:
            print(f"  {w}")
    return 0


def _cmd_convert(args):
    from .io import write

    obj, warns = _read_with_warnings(args.input, args.input_format)
    for w in warns:
        print(f"warning: {w}", file=sys.stderr)
    write(obj, args.output, format=args.output_format)
    print(f"wrote {args.output}")
    return 0


def _cmd_demo(args):
    """The main job on the bundled transport: every intersection, a cubic fillet with the
    fuselage re-designed at fixed area, every output format, figures, wave drag, report."""
    import json

    from .analysis import plot_area_distribution, wavedrag
    from .complete import complete
    from .io import atomic_output
    from .massprops import configuration_mass_properties, format_table

    out = Path(args.output)
    out.mkdir(parents=True, exist_ok=True)
    deck = bundled_example()
    cfg, warns = _read_with_warnings(deck)
    for w in warns:
        print(f"warning: {w}", file=sys.stderr)
    print(f"read {deck.name}: {cfg.title}")
    print("\n".join("  " + s for s in _describe(cfg)[1:]))
    sharp = complete(cfg, "cubic", False)
    geo = complete(cfg, "cubic", True)
    _print_completion(cfg, geo, "cubic")
    summary_args = argparse.Namespace(fillet="cubic", keep_area=True)
    written = _write_outputs(cfg, geo, out, ("wgs", "p3d", "hess", "stl", "vtk", "step", "igs"),
                             "cubic", True, summary_args)
    cases = {"original": wavedrag(cfg, geometry=complete(cfg, None, False)),
             "cubic fillet": wavedrag(cfg, geometry=sharp),
             "cubic fillet, fixed area": wavedrag(cfg, geometry=geo)}
    plot_area_distribution(cases, out / "wavedrag_areas.png", title=cfg.title)
    with atomic_output(out / "wavedrag.json") as fh:
        json.dump({k: {f: v[f] for f in ("mach", "D_over_q", "CD", "method")}
                   for k, v in cases.items()}, fh, indent=1)
    written += ["wavedrag_areas.png", "wavedrag.json"]
    base = cases["original"]["D_over_q"]
    for label, r in cases.items():
        print(f"  wave drag {label:<26} D/q {r['D_over_q']:10.5g}  "
              f"({100 * (r['D_over_q'] - base) / base:+.3f} %)")
    total, parts = configuration_mass_properties(geo.configuration)
    with atomic_output(out / "massprops.txt") as fh:
        fh.write(format_table(total, parts) + "\n")
    written.append("massprops.txt")
    try:
        written.append(_report(cfg, geo, out, "cubic", True, "juncture demo"))
    except ImportError:  # the report module is optional in this build
        pass
    print(f"wrote {len(written)} files to {out}/: {', '.join(written)}")
    return 0


def _summary(geo, cfg, args):
    import json

    st = {k: [float(v) for v in arr] for k, arr in geo.stations.items()}
    return json.dumps({
        "title": cfg.title, "fillet": args.fillet, "keep_area": args.keep_area,
        "networks": {k: list(v.shape) for k, v in geo.networks.items()},
        "intersections": {k: v.tolist() for k, v in geo.intersections.items()},
        "stations": st, "log": list(geo.log)}, indent=1)


def _write_outputs(cfg, geo, out, formats, fillet, keep_area, summary_args):
    """Networks in every format asked, summary.json and the figures; returns names written."""
    from . import plots, plots_juncture
    from .errors import MissingDependencyError
    from .io import atomic_output, write

    written = []
    for fmt in formats:
        name = f"geometry.{fmt}"
        try:
            write(geo, out / name)
        except MissingDependencyError as exc:
            print(f"skipped {name}: {exc}", file=sys.stderr)
            continue
        written.append(name)
    with atomic_output(out / "summary.json") as fh:
        fh.write(_summary(geo, cfg, summary_args))
    written.append("summary.json")
    figs = [("views.png", plots.plot_views(geo)),
            ("intersection.png", plots_juncture.plot_gap_and_intersection(cfg, geo)),
            ("lower_intersection.png", plots_juncture.plot_lower_intersection(cfg, geo))]
    if fillet is not None:
        figs += [("fillet_sections.png", plots_juncture.plot_fillet_sections(cfg, geo)),
                 ("areas.png", plots_juncture.plot_station_areas(geo))]
    for name, fig in figs:
        plots.save(fig, out / name)
        written.append(name)
    return written


def _cmd_complete(args):
    from .complete import complete

    cfg, warns = _read_with_warnings(args.deck)
    for w in warns:
        print(f"warning: {w}", file=sys.stderr)
    fillet = None if args.fillet == "none" else args.fillet
    opts = {k: v for k, v in (("theta_u_deg", args.theta_u), ("end", args.end),
                              ("end_value", args.end_value), ("blend_length", args.blend_length),
                              ("fillet_radius", args.radius), ("remedy", args.remedy),
                              ("blocks", args.blocks), ("single_network", args.single_network))
            if v is not None}
    geo = complete(cfg, fillet, args.keep_area, **opts)
    out = Path(args.output)
    out.mkdir(parents=True, exist_ok=True)
    written = _write_outputs(cfg, geo, out, args.format, fillet, args.keep_area, args)
    _print_completion(cfg, geo, fillet)
    if args.report:
        written.append(_report(cfg, geo, out, fillet, args.keep_area,
                               "juncture " + " ".join(sys.argv[1:])))
    print(f"wrote {len(written)} files to {out}/: {', '.join(written)}")
    return 0


def _print_completion(cfg, geo, fillet):
    st = geo.stations
    pairs = [s for s in geo.log if s.startswith("touching pairs:")]
    print(f"{cfg.title}: {len(geo.networks)} networks, {len(geo.intersections)} intersection "
          f"lines; fillet {fillet}; {len(st['x'])} fillet stations")
    if pairs:
        print(f"  {pairs[0]}")
    seams = [s for s in geo.log if s.startswith("seam")]
    gaps = [float(s.rsplit("max gap ", 1)[1]) for s in seams if "traced" not in s]
    if gaps:
        print(f"  {len(gaps)} seams between networks, largest gap {max(gaps):.3g}")
    traced = [float(s.rsplit("max gap ", 1)[1]) for s in seams if "traced" in s]
    if traced:
        print(f"  {len(traced)} fin/pylon lines traced on the wing at its stations, within "
              f"{max(traced):.3g} of the wing grid")
    if fillet is not None:
        print(f"  added area up to {st['area_fillet'].max():.4g}; radius reduced by up to "
              f"{(st['radius_original'] - st['radius_new']).max():.4g}; worst area residual "
              f"{st['residual'].max():.3g}")


def _report(cfg, geo, out, fillet, keep_area, command):
    """Write report.html with the wave drag of each case and the mass properties."""
    from .analysis import wavedrag
    from .complete import complete
    from .massprops import configuration_mass_properties
    from .report import write_report

    cases = {"original": wavedrag(cfg, geometry=complete(cfg, None, False))}
    if fillet is not None:
        cases[f"{fillet} fillet"] = wavedrag(cfg, geometry=geo if not keep_area else
                                             complete(cfg, fillet, False))
        if keep_area:
            cases[f"{fillet} fillet, fixed area"] = wavedrag(cfg, geometry=geo)
    mass = configuration_mass_properties(geo.configuration or cfg)
    write_report(out / "report.html", cfg, geo, wavedrag=cases, massprops=mass,
                 command=command)
    return "report.html"


def _cmd_blend(args):
    from .blend import run

    result = run(args.spec, args.output)
    for seam in result["report"]["seams"]:
        print(f"  {seam['seam']:<12} max gap {seam['max_gap']:.3g}  max normal angle "
              f"{seam['max_angle_deg']:.3g} deg  ({seam['samples']} samples)")
    for name in result["files"]:
        print(f"wrote {name}")
    for fmt, reason in dict(result.get("skipped") or {}).items():
        print(f"skipped {fmt}: {reason}", file=sys.stderr)
    return 0


def _wavedrag_cases(cfg, args):
    """Label -> (configuration, completed geometry or None) for the wavedrag command."""
    from .complete import complete

    fillet = None if args.fillet in (None, "none") else args.fillet
    # With a fillet, compare completed surfaces: a root section given on the fuselage leaves a
    # gap in the deck (TM-4406 fig 3) that the completed wing fills, fillet or not.
    cases = {"original": None if fillet is None else complete(cfg, None, False)}
    if fillet is not None:
        cases[f"{fillet} fillet"] = complete(cfg, fillet, False)
        if args.keep_area:
            cases[f"{fillet} fillet, fixed area"] = complete(cfg, fillet, True)
    elif args.keep_area:
        raise JunctureError("--keep-area needs a fillet (--fillet cubic or circular)")
    return cases


def _cmd_wavedrag(args):
    import json

    from .analysis import plot_area_distribution, wavedrag
    from .io import atomic_output

    cfg, warns = _read_with_warnings(args.deck)
    for w in warns:
        print(f"warning: {w}", file=sys.stderr)
    results = {label: wavedrag(cfg, args.mach, n_x=args.n_x, n_theta=args.n_theta,
                               geometry=geo)
               for label, geo in _wavedrag_cases(cfg, args).items()}
    first = results["original"]
    last = list(results.values())[-1]
    if args.output:
        out = Path(args.output)
        out.mkdir(parents=True, exist_ok=True)
        plot_area_distribution(results, out / "areas.png", title=cfg.title)
        with atomic_output(out / "wavedrag.json") as fh:
            json.dump(results, fh, indent=1)
    if args.json:
        keys = ("mach", "D_over_q", "CD", "method")
        doc = {k: last[k] for k in keys}
        if len(results) > 1:
            doc["cases"] = {label: {k: r[k] for k in keys} for label, r in results.items()}
        print(json.dumps(doc, indent=1))
        return 0
    print(f"{cfg.title}")
    print(f"method: {first['method']}" + ("" if first["mach"] is None else
                                          f", Mach {first['mach']:g}"))
    ref = first["reference_area"]
    print(f"{'case':<34}{'D/q':>14}{'CD':>12}{'change':>10}")
    for label, r in results.items():
        cd = "" if r["CD"] is None else f"{r['CD']:.6f}"
        change = (r["D_over_q"] - first["D_over_q"]) / first["D_over_q"]
        print(f"{label:<34}{r['D_over_q']:>14.6g}{cd:>12}{100 * change:>9.3f}%")
    if ref is None:
        print("(no reference area in the input: CD not available)")
    if args.output:
        print(f"wrote {Path(args.output) / 'areas.png'} and wavedrag.json")
    return 0


def _cmd_massprops(args):
    from .massprops.command import run_massprops

    print(run_massprops(args.file, as_json=args.json, density=args.density), end="")
    return 0


def _build_parser():
    from .io import reader_formats, writer_formats

    p = argparse.ArgumentParser(prog="juncture", description=(
        "Complete an airplane described as separate components into one surface."))
    p.add_argument("--version", action="version", version=f"juncture {__version__}")
    p.add_argument("--debug", action="store_true", help="show tracebacks of errors")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    s = sub.add_parser("info", help="what is in a geometry file, checked")
    s.add_argument("file")
    s.add_argument("--format", choices=reader_formats(), help="input format (default: sniff)")
    s.set_defaults(func=_cmd_info)

    s = sub.add_parser("convert", help="read any supported file, write any supported format")
    s.add_argument("input")
    s.add_argument("output")
    s.add_argument("--from", dest="input_format", choices=reader_formats())
    s.add_argument("--to", dest="output_format", choices=writer_formats(),
                   help="output format (default: by extension)")
    s.set_defaults(func=_cmd_convert)

    s = sub.add_parser("complete", help="intersect, fillet and re-design the wing-body juncture")
    s.add_argument("deck")
    s.add_argument("-o", "--output", default="juncture-output", help="output directory")
    s.add_argument("--fillet", choices=("none", "cubic", "circular"), default="none")
    s.add_argument("--keep-area", action="store_true",
                   help="shrink the fuselage so body + fillet keeps the original area")
    s.add_argument("--format", nargs="+", default=["wgs"], metavar="EXT",
                   help="output formats by extension (default: wgs), e.g. wgs p3d hess stl vtk")
    s.add_argument("--blocks", type=int, choices=(4, 6), help="output blocks (default 4)")
    s.add_argument("--single-network", action="store_true", default=None,
                   help="fuselage as one network (TM-4406 figs 4-5)")
    s.add_argument("--theta-u", type=float, metavar="DEG",
                   help="cubic fillet start above/below the intersection [deg] (default 20)")
    s.add_argument("--end", choices=("dy", "intersection", "section"),
                   help="cubic fillet end point: span increment from the intersection (default),"
                   " fraction of the way from it to section 2, or from section 1 to 2")
    s.add_argument("--end-value", type=float,
                   help="span increment (default: a quarter of the largest body radius) or "
                   "fraction (default 0.5)")
    s.add_argument("--blend-length", type=float, help="LE/TE blending length l_b")
    s.add_argument("--radius", type=float, help="circular fillet radius rho")
    s.add_argument("--remedy", choices=("z-constraint", "parabolas"),
                   help="low-wing dip remedy for the cubic fillet")
    s.add_argument("--report", action="store_true",
                   help="also write report.html: inputs, tables, figures, wave drag, mass")
    s.set_defaults(func=_cmd_complete)

    s = sub.add_parser("wavedrag", help="area distributions and supersonic wave drag")
    s.add_argument("deck")
    s.add_argument("--mach", type=float,
                   help="far-field wave drag at this Mach number (default: slender body)")
    s.add_argument("--fillet", choices=("none", "cubic", "circular"), default="none",
                   help="also analyse the configuration with this wing-body fillet")
    s.add_argument("--keep-area", action="store_true",
                   help="and with the fuselage re-designed to keep the area distribution")
    s.add_argument("--json", action="store_true",
                   help='print {"mach", "D_over_q", "CD", "method"} (of the last case)')
    s.add_argument("-o", "--output", help="directory for areas.png and wavedrag.json")
    s.add_argument("--n-x", type=int, default=101, help="stations / cuts per angle (101)")
    s.add_argument("--n-theta", type=int, default=16, help="roll angles (16)")
    s.set_defaults(func=_cmd_wavedrag)

    s = sub.add_parser("blend", help="G1 long-strake wing-body blend (Song, Ma & Wang 2008)")
    s.add_argument("spec", help="blend spec (JSON), e.g. examples/missile_blend.json")
    s.add_argument("-o", "--output", required=True, help="output directory")
    s.set_defaults(func=_cmd_blend)

    s = sub.add_parser("massprops", help="mass, CG and inertia of a spec or of every deck "
                       "component")
    s.add_argument("file", help="JSON mass-properties spec, wave-drag deck or juncture model")
    s.add_argument("--json", action="store_true", help="print JSON instead of a table")
    s.add_argument("--density", type=float,
                   help="deck/model only: density of every component (default 1: mass = volume)")
    s.set_defaults(func=_cmd_massprops)

    s = sub.add_parser("demo", help="run the main job on the bundled supersonic transport")
    s.add_argument("-o", "--output", default="demo-output", help="output directory")
    s.set_defaults(func=_cmd_demo)
    return p


def main(argv=None) -> int:
    """Run the command line; returns the exit status (0 ok, 2 bad input)."""
    parser = _build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except JunctureError as exc:
        if args.debug:
            raise
        print(f"juncture: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:
        if args.debug:
            raise
        print(f"juncture: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
