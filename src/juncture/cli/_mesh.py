"""``juncture mesh``: one closed triangulated surface of the completed airplane."""

from __future__ import annotations

__all__ = ["add_parser", "run"]

_FORMATS = ("stl", "msh", "vtu", "tri")


def add_parser(sub, common):
    """The ``mesh`` sub-command's parser."""
    from ._parser import completion_arguments

    s = sub.add_parser("mesh", parents=[common],
                       help="one closed, oriented triangulated surface of the completed airplane")
    completion_arguments(s, "juncture-mesh")
    s.add_argument("--format", nargs="+", default=["stl"], choices=_FORMATS, metavar="EXT",
                   help=f"mesh formats (default: stl); one or more of {', '.join(_FORMATS)}")
    s.add_argument("--refine", type=int, default=None, metavar="K",
                   help="divide every chordwise interval and every cross-section's point "
                        "spacing into K (default 1: the deck's points); the volume converges "
                        "as K grows")
    s.add_argument("--min-angle", type=float, default=25.0, metavar="DEG",
                   help="re-triangulate every surface until its triangles' smallest angle "
                        "is at least DEG where the corners allow (default 25; 0 keeps the "
                        "networks' own triangles)")
    s.add_argument("--tolerance", type=float, default=1e-4, metavar="SHARE",
                   help="largest distance of a triangle's centre from the surface, as a "
                        "share of the airplane's size (default 1e-4)")
    s.add_argument("--curvature", type=float, default=None, metavar="DEG",
                   help="largest turn of a curved surface (a body, a wing section) under one "
                        "triangle edge (default: no such limit; 10 is a good start)")
    s.add_argument("--depth", type=float, default=None, metavar="SHARE",
                   help="largest distance of an edge's middle from the exact surface, as a "
                        "share of its size there (a body's radius, a wing section's "
                        "thickness; default: no such limit); the volume converges as it "
                        "shrinks, at many more triangles (3e-3 is a good start)")
    s.add_argument("--edge-length", type=float, default=None, metavar="H",
                   help="no triangle larger than an equilateral one of edge H (deck units; "
                        "default: none, the angle and the tolerance decide)")
    s.add_argument("--seam-size", type=float, default=None, metavar="H",
                   help="triangles of edge H at the lines where components meet, growing "
                        "away from them by --growth (deck units; default: none)")
    s.add_argument("--growth", type=float, default=None, metavar="RATIO",
                   help="triangles grow away from the seams' finest pieces (and from "
                        "--seam-size) by at most RATIO - 1 of the distance, e.g. 1.2 "
                        "(default: no limit but the angle's; 1.25 with --seam-size)")
    s.add_argument("--flow-through", action="store_true",
                   help="nacelles open at both ends get a duct of the inlet's radius from "
                        "inlet to exit (and a flat exit ring) instead of two caps, as the "
                        "area rule's flow-through nacelles")
    s.add_argument("--half", action="store_true",
                   help="the y >= 0 half, closed by its section in the plane of symmetry, "
                        "written as the component 'symmetry' (a symmetry-plane marker); "
                        "refused where the airplane is not its own mirror image")
    s.add_argument("--ascii", action="store_true",
                   help="ASCII STL with one named solid per component (default: binary)")
    return s


def run(args, progress):
    """Complete, assemble, check; write only a mesh that is closed and oriented."""

    from ..completion import complete
    from ..errors import GeometryError
    from ..surface.assemble import assemble
    from ..surface.lift import surface_lift
    from ..surface.pipeline import finish, half_checked, overlapping_regions
    from ..surface.quality import summarize
    from ..surface.write import write_mesh
    from ._commands import _complete_options, output_dir, read_configuration
    from ._parser import COMPLETE_FLAGS, fail

    fillet = None if args.fillet == "none" else args.fillet
    for dest in COMPLETE_FLAGS:  # complete's fillet options keep their defaults here
        if not hasattr(args, dest):
            setattr(args, dest, None)
    opts = _complete_options(args, fillet)
    _check_sizing(args, fail)
    with progress(4, "mesh") as bar:
        bar.step("read and complete")
        cfg = read_configuration(args.deck, "mesh")
        geo = complete(cfg, fillet, args.keep_area, options=opts)
        bar.step("assemble")
        mesh = assemble(geo, flow_through=args.flow_through)
        summary = summarize(mesh)
        if not summary.closed or summary.open_loops:
            # the cause in the user's terms first, where it is known (as jc.mesh says it)
            fail("the completed surface is not closed, so no mesh was written: "
                 + "; ".join(overlapping_regions(geo) + [line[6:] for line in summary.lines()
                                                         if line.startswith("FAIL")]))
        lift = None
        if args.min_angle:
            bar.step(f"re-triangulate (smallest angle {args.min_angle:g} deg) and check")
            lift = surface_lift(geo, mesh)
        else:
            bar.step("check (exact predicates)")
        try:
            better, report = finish(geo, mesh, True, args.min_angle, args.edge_length,
                                    args.tolerance, lift, args.curvature, args.depth,
                                    (args.growth, args.seam_size))
        except GeometryError as exc:
            fail(f"{exc}, so no mesh was written")
        if better is not mesh:
            mesh, summary = better, summarize(better)
        if args.half:
            try:
                mesh, report = half_checked(mesh, args.min_angle, True, geo.configuration)
            except GeometryError as exc:
                fail(f"{exc}, so no mesh was written")
            summary = summarize(mesh)
        bar.step("write " + " ".join(args.format))
        out = output_dir(args.output)
        written = [write_mesh(mesh, out / f"mesh.{ext}", ascii=args.ascii).name
                   for ext in args.format]
    if not getattr(args, "quiet", False):
        print("\n".join(summary.lines()))
        mp = mesh.mass_properties()
        print("centre of volume " + ", ".join(f"{c:.6g}" for c in mesh.centre_of_volume())
              + "; inertia per unit density about it Ixx, Iyy, Izz "
              + ", ".join(f"{mp.inertia[i, i]:.6g}" for i in range(3))
              + " (the enclosed solid, overlaps counted once)")
        print(f"checked: {report.intersecting_pairs} intersecting triangle pairs (exact "
              f"predicates), Euler characteristic {', '.join(map(str, report.euler))}")
        print(f"wrote {len(written)} files to {out}/: {', '.join(written)}")
    return 0


def _check_sizing(args, fail):
    """One line for a sizing option out of range."""
    if not 0.0 <= args.min_angle <= 30.0:
        fail(f"--min-angle {args.min_angle:g}: expected 0 (off) to 30 degrees (a larger "
             "smallest angle cannot be guaranteed)")
    if not args.tolerance > 0.0:
        fail(f"--tolerance {args.tolerance:g}: expected a share of the size > 0, e.g. 1e-4")
    if args.curvature is not None and not 0.0 < args.curvature <= 90.0:
        fail(f"--curvature {args.curvature:g}: expected an angle in degrees, > 0 and <= 90")
    if args.depth is not None and not args.depth > 0.0:
        fail(f"--depth {args.depth:g}: expected a share of the surface's size > 0, e.g. 3e-3")
    if args.edge_length is not None and not args.edge_length > 0.0:
        fail(f"--edge-length {args.edge_length:g}: expected a length > 0 in deck units")
    if args.seam_size is not None and not args.seam_size > 0.0:
        fail(f"--seam-size {args.seam_size:g}: expected a length > 0 in deck units")
    if args.growth is not None and not 1.0 < args.growth <= 10.0:
        fail(f"--growth {args.growth:g}: expected a ratio > 1 (e.g. 1.2) and <= 10")
