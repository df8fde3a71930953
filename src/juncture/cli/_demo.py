"""``juncture demo``: the main job on the bundled supersonic transport, with a progress bar."""

from __future__ import annotations

import json

from . import bundled_example
from ._commands import _say, output_dir, read_configuration, write_outputs, write_report
from ._describe import completion_summary, describe

__all__ = ["demo"]

_FORMATS = ("wgs", "p3d", "hess", "stl", "vtu", "vtk", "step", "igs")


def demo(args, progress):
    """Every intersection, a cubic fillet with the fuselage re-designed at fixed area, every
    output format, figures, wave drag before and after, mass properties and the report."""
    from ..analysis import wavedrag
    from ..completion import complete
    from ..io import atomic_output
    from ..massprops import configuration_mass_properties, format_table
    from ..plots import plot_area_distribution, write_figures

    out = output_dir(args.output)
    deck = bundled_example()
    with progress(9, "demo") as bar:
        bar.step("read")
        cfg = read_configuration(deck, "demo")
        _say(args, f"read {deck.name}: {cfg.title}", *("  " + s for s in describe(cfg)[1:]))
        bar.step("complete: sharp, cubic fillet, cubic fillet at fixed area")
        original = complete(cfg, None, False)
        sharp = complete(cfg, "cubic", False)
        geo = complete(cfg, "cubic", True)
        _say(args, *completion_summary(cfg, geo, "cubic"))
        bar.step("write " + " ".join(_FORMATS))
        written = write_outputs(cfg, geo, out, _FORMATS, "cubic", True)
        bar.step("figures")
        written += write_figures(cfg, geo, out, fillet="cubic", units=args.units)
        cases = {}
        for label, g in (("original", original), ("cubic fillet", sharp),
                         ("cubic fillet, fixed area", geo)):
            bar.step(f"wave drag, {label}")
            cases[label] = wavedrag(cfg, geometry=g)
        plot_area_distribution(cases, out / "wavedrag_areas.png", title=cfg.title,
                               units=args.units)
        with atomic_output(out / "wavedrag.json") as fh:
            json.dump({k: {f: v[f] for f in ("mach", "D_over_q", "CD", "method")}
                       for k, v in cases.items()}, fh, indent=1)
        written += ["wavedrag_areas.png", "wavedrag.json"]
        bar.step("closed mesh and mass properties")
        total, parts = configuration_mass_properties(geo.configuration)
        surface = _closed_mesh(geo, out, written)
        with atomic_output(out / "massprops.txt") as fh:
            fh.write(format_table(total, parts) + "\n")
            if not isinstance(surface, str):
                solid = surface.mass_properties()
                fh.write(f"enclosed solid of mesh.stl (overlaps counted once): volume "
                         f"{solid.volume:.6g}, centre " + ", ".join(f"{c:.6g}" for c in
                                                                      solid.cg) + "\n")
        written.append("massprops.txt")
        bar.step("report")
        written.append(write_report(cfg, geo, out, command="juncture demo", units=args.units,
                                    cases=cases, mass=(total, parts), surface=surface,
                                    written=written))
    base = cases["original"]["D_over_q"]
    for label, r in cases.items():
        _say(args, f"  wave drag {label:<26} D/q {r['D_over_q']:10.5g}  "
             f"({100 * (r['D_over_q'] - base) / base:+.3f} %)")
    _say(args, f"wrote {len(written)} files to {out}/: {', '.join(written)}")
    return 0


def _closed_mesh(geo, out, written):
    """mesh.stl, the completed airplane as one closed surface; the surface, or (with a line
    saying so) why it does not close."""
    from ..errors import GeometryError
    from ..surface.pipeline import mesh
    from ..surface.write import write_mesh

    try:
        surface = mesh(geo)
    except GeometryError as exc:
        print(f"juncture demo: no mesh.stl: {exc}")
        return str(exc)
    written.append(write_mesh(surface, out / "mesh.stl").name)
    return surface
