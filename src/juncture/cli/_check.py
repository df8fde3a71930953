"""``juncture check FILE``: closed, manifold, oriented, not self-intersecting (exact)."""

from __future__ import annotations

__all__ = ["add_parser", "run"]


def add_parser(sub, common):
    """The ``check`` sub-command's parser."""
    import argparse
    import math

    def angle(text):
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not 0.0 <= value <= 60.0:
            raise argparse.ArgumentTypeError(f"expected an angle in [0, 60] [deg], found "
                                             f"{text!r}")
        return value

    s = sub.add_parser("check", parents=[common],
                       help="check a triangulated surface: closed, manifold, oriented, no "
                       "self-intersection (exact predicates); exit 2 if anything fails")
    s.add_argument("mesh", help="mesh file: .stl, .msh, .vtu, .vtk, .obj, .ply, .off")
    s.add_argument("--min-angle", type=angle,
                   default=0.0, help="also fail when a triangle has a smaller angle [deg]")
    s.add_argument("--handles", type=int, default=0, metavar="N",
                   help="the surface has N handles in all (a flow-through nacelle's duct is "
                        "one; default 0: every body a sphere)")
    return s


def run(args, progress):
    """Print the report; exit status 2 when a check fails."""
    from ..surface.check import check_mesh, read_triangles
    with progress(2, "check") as bar:
        bar.step("read")
        vertices, triangles = read_triangles(args.mesh)
        bar.step("check")
        report = check_mesh(vertices, triangles, min_angle=args.min_angle,
                            handles=args.handles)
    lines = report.lines()
    if getattr(args, "quiet", False):
        lines = [line for line in lines if line.startswith("FAIL")]
    print("\n".join(f"{args.mesh}: {line}" if line.startswith("FAIL") else line
                    for line in lines))
    return 0 if report.ok else 2
