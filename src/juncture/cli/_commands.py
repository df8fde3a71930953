"""One function per command: parse the arguments' meaning, call the public API, print.

Each takes the parsed arguments and a :class:`~juncture._progress.Progress` factory and
returns the exit status. Bad input surfaces as a :class:`~juncture.errors.JunctureError`,
which :func:`juncture.cli.main` prints as one line.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from ..errors import JunctureError, OptionError
from ._describe import completion_summary, describe
from ._parser import COMPLETE_FLAGS, fail

__all__ = ["info", "convert", "complete", "wavedrag", "massprops", "blend",
           "read_configuration", "output_dir", "write_outputs", "write_report"]


def _say(args, *lines):
    if not getattr(args, "quiet", False):
        for line in lines:
            print(line)


def read_configuration(path, command):
    """The components in ``path`` (a deck or a juncture model), or one clear error."""
    from ..io import read
    from ..model import Configuration

    obj = read(path)
    if not isinstance(obj, Configuration):
        raise JunctureError(f"{path}: holds surface networks, not components: 'juncture "
                            f"{command}' needs a wave-drag deck or a juncture JSON/TOML model "
                            f"(use 'juncture info' or 'juncture convert' on networks)")
    return obj


def output_dir(path):
    """Create the output directory (and its parents); a clear error when it cannot be."""
    out = Path(path)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise JunctureError(f"{out}: exists and is not a directory (expected an output "
                            f"directory)") from None
    except OSError as exc:
        raise JunctureError(f"{out}: cannot create the output directory "
                            f"({exc.strerror or exc})") from None
    return out


def info(args, progress):
    import warnings

    from ..io import read

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        obj = read(args.file, format=args.format)
    print("\n".join(describe(obj)))
    notes = list(dict.fromkeys(" ".join(str(w.message).split()) for w in caught))
    if notes:
        print(f"{len(notes)} warning(s):", *(f"  {n}" for n in notes), sep="\n")
    return 0


def convert(args, progress):
    from ..io import read, write

    obj = read(args.input, format=args.input_format)
    write(obj, args.output, format=args.output_format)
    _say(args, f"wrote {args.output}")
    return 0


def _complete_options(args, fillet):
    """CompleteOptions from complete's flags; a refused value names its flag."""
    from ..options import CompleteOptions, check_combination

    fields = {field: getattr(args, dest, None) for dest, (field, _) in COMPLETE_FLAGS.items()
              if getattr(args, dest, None) is not None}
    flag_of = {field: flag for field, flag in COMPLETE_FLAGS.values()}
    flag_of.update(keep_area="--keep-area", fillet="--fillet")
    try:
        opts = CompleteOptions(**fields)
        check_combination(fillet, args.keep_area, opts, given=fields)
    except OptionError as exc:
        flag = flag_of.get(exc.option, exc.option)
        if exc.option == "compensation":
            fail("argument --compensate: only with --keep-area")
        if exc.option == "keep_area":
            fail("argument --keep-area: needs --fillet cubic or circular (without "
                 "a fillet there is no added area to compensate)")
        if exc.expected.startswith("no value"):
            kind = exc.expected.split("'")[1] if "'" in exc.expected else "cubic or circular"
            fail(f"argument {flag}: only with --fillet {kind} (given: --fillet "
                 f"{args.fillet})")
        fail(f"argument {flag}: expected {exc.expected}, found {exc.value!r}")
    return opts


def _check_formats(formats):
    known = network_extensions()
    for ext in formats:
        if ext.lstrip(".").lower() not in known:
            fail(f"argument --format: {ext!r} is not a format of surface networks; complete "
                 f"writes {', '.join(known)} (a deck or JSON model of the input: 'juncture "
                 f"convert')")
    return [ext.lstrip(".").lower() for ext in formats]


def _summary_json(geo, cfg, fillet, keep_area):
    st = {k: [float(v) for v in arr] for k, arr in geo.stations.items()}
    return json.dumps({
        "title": cfg.title, "fillet": fillet or "none", "keep_area": keep_area,
        "networks": {k: list(v.shape) for k, v in geo.networks.items()},
        "intersections": {k: v.tolist() for k, v in geo.intersections.items()},
        "stations": st, "log": list(geo.log)}, indent=1)


# Formats that hold components, not surface networks: not outputs of complete.
_COMPONENT_FORMATS = ("wavedrag", "juncture")


def network_extensions():
    """Extensions of the formats that hold surface networks (what complete writes)."""
    from ..io import output_format, writer_extensions

    return [e for e in writer_extensions() if output_format(f"x.{e}") not in _COMPONENT_FORMATS]


def write_outputs(cfg, geo, out, formats, fillet, keep_area, units="ft", cad="components"):
    """The networks in every format asked (geometry.<ext>) and summary.json; returns the names
    written. CAD files (STEP, IGES) hold ``cad`` (:mod:`juncture.surface.solids`) and declare
    ``units``."""
    from ..errors import MissingDependencyError
    from ..io import atomic_output, output_format, write
    from ..surface.solids import write_solids

    written = []
    for fmt in formats:
        name = f"geometry.{fmt}"
        try:
            if output_format(name) in ("step", "iges"):
                write_solids(geo, out / name, cad, units)
            else:
                write(geo, out / name)
        except MissingDependencyError as exc:
            print(f"juncture: skipped {name}: {exc}", file=sys.stderr)
            continue
        written.append(name)
    with atomic_output(out / "summary.json") as fh:
        fh.write(_summary_json(geo, cfg, fillet, keep_area))
    written.append("summary.json")
    return written


def wavedrag_cases(cfg, geo, fillet, keep_area, progress):
    """Wave drag of the original airplane and of each filleted form of it, by label."""
    from ..analysis import wavedrag as wave_drag
    from ..completion import complete as complete_

    progress.step("wave drag, original")
    cases = {"original": wave_drag(cfg, geometry=complete_(cfg, None, False))}
    if fillet is not None:
        progress.step(f"wave drag, {fillet} fillet")
        cases[f"{fillet} fillet"] = wave_drag(cfg, geometry=geo if not keep_area else
                                              complete_(cfg, fillet, False))
        if keep_area:
            progress.step(f"wave drag, {fillet} fillet, fixed area")
            cases[f"{fillet} fillet, fixed area"] = wave_drag(cfg, geometry=geo)
    return cases


def write_report(cfg, geo, out, *, command, units, cases, mass=None, surface=None,
                 written=()):
    """report.html with the wave drag of each case, the mass properties and the closed
    surface (``surface``; by default :func:`juncture.mesh` of ``geo``, or why it has none).
    Figures the run already wrote into ``out`` (names in ``written``) are embedded as they
    are, not drawn again."""
    from ..errors import GeometryError
    from ..massprops import configuration_mass_properties
    from ..plots import write_report as render
    from ..surface.pipeline import mesh

    if mass is None:
        mass = configuration_mass_properties(geo.configuration or cfg)
    if surface is None:
        try:
            surface = mesh(geo)
        except GeometryError as exc:
            surface = str(exc)
    render(out / "report.html", cfg, geo, wavedrag=cases, massprops=mass, command=command,
           units=units, surface=surface, figures=_report_figures(cfg, geo, out, cases, units,
                                                                 written))
    return "report.html"


def _report_figures(cfg, geo, out, cases, units, written):
    """caption -> PNG path or Figure for the report: the run's figures and the wave-drag
    areas, read from ``out`` where the run wrote them (``written``), else drawn; None when
    the run wrote none (the report draws its own)."""
    from ..plots.figures import FIGURES
    from ..plots.report import WAVEDRAG_CAPTION

    names = [n for n in written if n in FIGURES]
    if not names:
        return None
    figures = {FIGURES[n][0]: out / n for n in names}
    if cases:
        if "wavedrag_areas.png" in written:
            figures[WAVEDRAG_CAPTION] = out / "wavedrag_areas.png"
        else:
            from ..plots.areas import plot_wavedrag_areas

            figures[WAVEDRAG_CAPTION] = plot_wavedrag_areas(
                cases, title=(cfg.title if cfg is not None else "") or geo.title, units=units)
    return figures


def complete(args, progress):
    from ..completion import complete as complete_
    from ..io import output_format
    from ..io._cad_write import cad_unit

    fillet = None if args.fillet == "none" else args.fillet
    opts = _complete_options(args, fillet)
    formats = _check_formats(args.format)
    if any(output_format(f"x.{f}") in ("step", "iges") for f in formats):
        cad_unit(args.units)  # refused before any work: a CAD file declares its unit
    report_steps = 2 + (fillet is not None) + (fillet is not None and args.keep_area)
    steps = 3 + args.figures + (report_steps if args.report else 0)
    with progress(steps, "complete") as bar:
        bar.step("read")
        cfg = read_configuration(args.deck, "complete")
        out = output_dir(args.output)
        bar.step("complete")
        geo = complete_(cfg, fillet, args.keep_area, options=opts)
        bar.step("write " + " ".join(formats))
        written = write_outputs(cfg, geo, out, formats, fillet, args.keep_area, args.units,
                                args.cad)
        if args.figures:
            from ..plots import write_figures

            bar.step("figures")
            written += write_figures(cfg, geo, out, fillet=fillet, units=args.units)
        if args.report:
            cases = wavedrag_cases(cfg, geo, fillet, args.keep_area, bar)
            bar.step("mass properties and report")
            written.append(write_report(cfg, geo, out, command="juncture " + " ".join(
                sys.argv[1:]), units=args.units, cases=cases, written=written))
    _say(args, *completion_summary(cfg, geo, fillet),
         f"wrote {len(written)} files to {out}/: {', '.join(written)}")
    return 0


def _wavedrag_cases(cfg, fillet, keep_area):
    """Label -> a function giving the completed geometry (or None) of each case."""
    from ..completion import complete as complete_

    # With a fillet, compare completed surfaces: a root section given on the fuselage leaves a
    # gap in the deck (TM-4406 fig 3) that the completed wing fills, fillet or not.
    cases = {"original": (lambda: None) if fillet is None else
             (lambda: complete_(cfg, None, False))}
    if fillet is not None:
        cases[f"{fillet} fillet"] = lambda: complete_(cfg, fillet, False)
        if keep_area:
            cases[f"{fillet} fillet, fixed area"] = lambda: complete_(cfg, fillet, True)
    return cases


def wavedrag(args, progress):
    from ..analysis import wavedrag as wave_drag

    fillet = None if args.fillet == "none" else args.fillet
    if args.keep_area and fillet is None:
        fail("argument --keep-area: needs --fillet cubic or circular (without "
             "a fillet there is no added area to compensate)")
    if args.slender_body and args.mach is not None:
        fail("argument --slender-body: not with --mach (one or the other)")
    options = _harris_options(args, fillet)
    cfg = read_configuration(args.deck, "wavedrag")
    out = None if args.output is None else output_dir(args.output)
    runs = mach_runs(cfg, args.mach, args.n_x, args.n_theta, args.slender_body)
    cases = _wavedrag_cases(cfg, fillet, args.keep_area)
    geometries = {}
    per_run = []
    with progress(len(cases) * len(runs), "wave drag") as bar:
        for run in runs:
            results = {}
            for label, geometry in cases.items():
                bar.step(f"{run['case']} {label}".strip())
                if label not in geometries:
                    geometries[label] = geometry()
                results[label] = wave_drag(cfg, run["mach"], n_x=run["n_x"],
                                           n_theta=run["n_theta"], geometry=geometries[label],
                                           **options)
            per_run.append((run, results))
    if not args.json:
        _say(args, cfg.title)
        if runs[0]["case"]:
            _say(args, *(f"case card {r['case']}: Mach {r['mach']:g}, {r['n_x']} stations, "
                         f"NTHETA {r['n_theta']}" for r in runs))
    status = _print_wavedrag(args, per_run[0][1], out, cfg.title) if len(per_run) == 1 \
        else _print_mach_cases(args, per_run, out, cfg.title)
    if args.converge is not None:
        _converge(args, cfg, runs, geometries.get("original"), progress, options)
    return status


def _harris_options(args, fillet):
    """wavedrag()'s method and conventions for --harris / --harris-off."""
    if args.harris_off and not args.harris:
        fail("argument --harris-off: needs --harris")
    if not args.harris:
        return {}
    if fillet is not None:
        fail("argument --harris: analyses the deck's components as the Harris program does; "
             "not with --fillet")
    from ..analysis.harris import HarrisConventions

    off = {name.replace("-", "_"): (None if name == "normal-mach" else False)
           for name in args.harris_off}
    return {"method": "harris", "conventions": HarrisConventions(**off)}


def _converge(args, cfg, runs, geometry, progress, options):
    """--converge: each run refined (analysis.converged_wavedrag), one line each, and a
    warning where the chosen resolution is off by more than 1 %."""
    import warnings

    from ..analysis import converged_wavedrag
    from ..errors import JunctureWarning

    with progress(len(runs), "convergence") as bar:
        for run in runs:
            bar.step(run["case"] or "convergence")
            c = converged_wavedrag(cfg, run["mach"], run["n_x"], run["n_theta"],
                                   tolerance=args.converge, geometry=geometry, **options)
            label = (run["case"] + ": ") if run["case"] else ""
            state = "converged" if c["converged"] else "NOT converged"
            print(f"{label}{state}: D/q {c['D_over_q']:.6g} +- {c['error']:.3g} at n_x "
                  f"{c['n_x']}, NTHETA {c['n_theta']} (start {c['start']:.6g} at n_x "
                  f"{run['n_x']}, NTHETA {run['n_theta']}: off by "
                  f"{100 * c['start_error']:.2f} %)")
            if c["start_error"] > 0.01:
                warnings.warn(f"{label}the wave drag at n_x {run['n_x']}, NTHETA "
                              f"{run['n_theta']} is {100 * c['start_error']:.1f} % from the "
                              f"refined value (n_x {c['n_x']}, NTHETA {c['n_theta']})",
                              JunctureWarning, stacklevel=2)


def mach_runs(cfg, mach=None, n_x=None, n_theta=None, slender=False):
    """The wave-drag runs a command asks for: ``--mach`` (or ``--slender-body``) alone, else
    one per case card of the deck with a Mach number (Mach = MACH / 1000, NX + 1 stations,
    NTHETA; ``n_x`` and ``n_theta`` given override the cards'), else slender body.

    Returns a list of dicts ``case`` (NCASE), ``mach`` (None: slender body), ``n_x``,
    ``n_theta``.
    """
    cards = [] if (mach is not None or slender) else [
        c for c in (getattr(cfg.source, "cases", None) or ()) if c.mach > 0]
    if not cards:
        return [{"case": "", "mach": mach, "n_x": n_x or 101, "n_theta": n_theta or 16}]
    return [{"case": c.ncase.strip() or f"case {i + 1}", "mach": c.mach / 1000.0,
             "n_x": n_x or (c.nx + 1 if c.nx > 0 else 101),
             "n_theta": n_theta or (c.ntheta if c.ntheta > 0 else 16)}
            for i, c in enumerate(cards)]


def _print_mach_cases(args, per_run, out, title):
    """One table per case card (several Mach numbers); JSON: a list of the cases."""
    from ..io import atomic_output

    keys = ("mach", "D_over_q", "CD", "method")
    if out is not None:
        from ..plots import plot_area_distribution

        for k, (run, results) in enumerate(per_run, 1):
            plot_area_distribution(results, out / f"areas_{k}.png",
                                   title=f"{title} ({run['case']})", units=args.units)
        with atomic_output(out / "wavedrag.json") as fh:
            json.dump([{**run, "results": results} for run, results in per_run], fh, indent=1)
    if args.json:
        print(json.dumps([{**run, "results": {label: {k: r[k] for k in keys}
                                              for label, r in results.items()}}
                          for run, results in per_run], indent=1))
        return 0
    print(f"{'card':<8}{'Mach':>6}{'n_x':>6}{'NTHETA':>8}  {'case':<30}{'D/q':>14}{'CD':>12}")
    for run, results in per_run:
        for label, r in results.items():
            cd = "" if r["CD"] is None else f"{r['CD']:.6f}"
            print(f"{run['case']:<8}{run['mach']:>6g}{run['n_x']:>6}{run['n_theta']:>8}  "
                  f"{label:<30}{r['D_over_q']:>14.6g}{cd:>12}")
    if out is not None:
        _say(args, f"wrote {len(per_run)} area figures and {out / 'wavedrag.json'}")
    return 0


def _print_wavedrag(args, results, out, title):
    from ..io import atomic_output

    first = results["original"]
    last = list(results.values())[-1]
    if out is not None:
        from ..plots import plot_area_distribution

        plot_area_distribution(results, out / "areas.png", title=title,
                               units=args.units)
        with atomic_output(out / "wavedrag.json") as fh:
            json.dump(results, fh, indent=1)
    if args.json:
        keys = ("mach", "D_over_q", "CD", "method")
        doc = {k: last[k] for k in keys}
        if len(results) > 1:
            doc["cases"] = {label: {k: r[k] for k in keys} for label, r in results.items()}
        print(json.dumps(doc, indent=1))
        return 0
    print(f"method: {first['method']}" + ("" if first["mach"] is None else
                                          f", Mach {first['mach']:g}"))
    print(f"{'case':<34}{'D/q':>14}{'CD':>12}{'change':>10}")
    for label, r in results.items():
        cd = "" if r["CD"] is None else f"{r['CD']:.6f}"
        change = (r["D_over_q"] - first["D_over_q"]) / first["D_over_q"]
        print(f"{label:<34}{r['D_over_q']:>14.6g}{cd:>12}{100 * change:>9.3f}%")
    if first["reference_area"] is None:
        print("(no reference area in the input: CD not available)")
    if out is not None:
        _say(args, f"wrote {out / 'areas.png'} and {out / 'wavedrag.json'}")
    return 0


def massprops(args, progress):
    from ..massprops.command import run_massprops

    print(run_massprops(args.file, as_json=args.json, density=args.density), end="")
    return 0


def blend(args, progress):
    from ..blend import run

    with progress(1, "blend") as bar:
        bar.step("surfaces, seams and figures")
        result = run(args.spec, args.output)
    for seam in result["report"]["seams"]:
        _say(args, f"  {seam['seam']:<12} max gap {seam['max_gap']:.3g}  max normal angle "
             f"{seam['max_angle_deg']:.3g} deg  ({seam['samples']} samples)")
    _say(args, *(f"wrote {name}" for name in result["files"]))
    for fmt, reason in dict(result.get("skipped") or {}).items():
        print(f"juncture: skipped {fmt}: {reason}", file=sys.stderr)
    return 0
