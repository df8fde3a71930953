"""The argument parser of the ``juncture`` command: every option checked as it is parsed.

Numeric and choice options of ``complete`` are checked by the same rules as
:class:`juncture.CompleteOptions` (:func:`juncture.options.check_option`), so a value outside
its range is refused before any work, with one line naming the flag.
"""

from __future__ import annotations

import argparse
import math

from ..errors import JunctureError, OptionError
from ..options import check_option

__all__ = ["build_parser", "COMPLETE_FLAGS"]

# complete's flags -> CompleteOptions fields (to name the flag when the library refuses one)
COMPLETE_FLAGS = {"theta_u": ("theta_u_deg", "--theta-u"), "end": ("end", "--end"),
                  "end_value": ("end_value", "--end-value"),
                  "blend_length": ("blend_length", "--blend-length"),
                  "radius": ("fillet_radius", "--radius"), "remedy": ("remedy", "--remedy"),
                  "blocks": ("blocks", "--blocks"),
                  "single_network": ("single_network", "--single-network"),
                  "compensate": ("compensation", "--compensate"),
                  "circular_tangent": ("circular_tangent", "--circular-tangent"),
                  "refine": ("refine", "--refine")}


class OneLineParser(argparse.ArgumentParser):
    """An ArgumentParser whose usage errors are one line on stderr and exit status 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see '{self.prog} --help')\n")


def _float(name, what):
    """An argparse type: a finite number that ``check_option(name)`` accepts."""
    def parse(text):
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {what}, found {text!r}") from None
        try:
            check_option(name, value, end="section" if name == "end_value" else "dy")
        except OptionError as exc:
            if name != "end_value":  # its range depends on --end: checked after parsing
                raise argparse.ArgumentTypeError(f"expected {exc.expected}, found {text!r}") \
                    from None
            if not (math.isfinite(value) and value > 0):
                raise argparse.ArgumentTypeError(f"expected a number > 0, found {text!r}") \
                    from None
        return value
    return parse


def _positive(what):
    def parse(text):
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not (math.isfinite(value) and value > 0):
            raise argparse.ArgumentTypeError(f"expected {what} > 0, found {text!r}")
        return value
    return parse


def _count(lo, hi, what):
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            value = lo - 1
        if not lo <= value <= hi:
            raise argparse.ArgumentTypeError(f"expected {what} from {lo} to {hi}, found {text!r}")
        return value
    return parse


def _blocks(text):
    if text == "split":
        return text
    if text in ("4", "6"):
        return int(text)
    raise argparse.ArgumentTypeError(f"expected 4, 6 or split, found {text!r}")


def _mach(text):
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and 1.0 <= value <= 10.0):
        raise argparse.ArgumentTypeError(f"expected a Mach number from 1 to 10, found {text!r}")
    return value


#: the Harris program's conventions, as --harris-off names them
HARRIS_CONVENTIONS = ("linear-chordwise", "sum-components", "normal-mach", "half-turn",
                      "fusard-fit")


def _common():
    """Flags every command takes (after the command name as well as before it)."""
    p = argparse.ArgumentParser(add_help=False)
    p.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                   help="show the traceback of an error")
    p.add_argument("-q", "--quiet", action="store_true", default=argparse.SUPPRESS,
                   help="no progress bar and no summary, only warnings and errors")
    return p


def _units(p):
    p.add_argument("--units", default="ft", metavar="LABEL",
                   help="length unit of the deck (default: ft): written on figure axes, in "
                   "the report, and declared in STEP/IGES files (mm, cm, m, km, in, ft, mi); "
                   "coordinates are never converted")


def completion_arguments(s, output):
    """The arguments every command that completes a deck takes: the deck, -o (default
    ``output``), --fillet and --keep-area."""
    s.add_argument("deck", help="wave-drag deck or juncture JSON/TOML model")
    s.add_argument("-o", "--output", default=output,
                   help=f"output directory (default: {output})")
    s.add_argument("--fillet", choices=("none", "cubic", "circular"), default="none",
                   help="wing-body fillet (default: none)")
    s.add_argument("--keep-area", action="store_true",
                   help="shrink the fuselage so body + fillet keeps the original area "
                   "(needs --fillet)")


def _complete_parser(sub, common, extensions):
    s = sub.add_parser("complete", parents=[common],
                       help="intersect, fillet and re-design the wing-body juncture")
    completion_arguments(s, "juncture-output")
    s.add_argument("--compensate", choices=("section", "fillet"),
                   help="with --keep-area: keep the whole section's area (default: fillets "
                   "and the wing root the shrinking uncovers) or, as TM-4406 eqs 11-14, only "
                   "the fillets' area")
    s.add_argument("--format", nargs="+", default=["wgs"], metavar="EXT",
                   help=f"output formats by extension (default: wgs); one or more of "
                   f"{', '.join(extensions)}")
    s.add_argument("--blocks", type=_blocks, metavar="{4,6,split}",
                   help="output layout: TM-4406's 4 or 6 blocks, or TM-4607's fuselage split by "
                   "theta_b (default: split when other components touch the fuselage or the wing's "
                   "root line turns back in x, else 4)")
    s.add_argument("--single-network", action="store_true", default=None,
                   help="fuselage as one network (TM-4406 figs 4-5)")
    s.add_argument("--theta-u", type=_float("theta_u_deg", "an angle in (0, 90) [deg]"),
                   metavar="DEG", help="cubic fillet: start angle above/below the intersection, "
                   "in (0, 90) deg (default 20)")
    s.add_argument("--end", choices=("dy", "intersection", "section"),
                   help="cubic fillet end point: span increment from the intersection (default),"
                   " fraction of the way from it to section 2, or from section 1 to 2")
    s.add_argument("--end-value", type=_float("end_value", "a number"),
                   help="cubic fillet: span increment > 0 with --end dy (default: a quarter of "
                   "the largest body radius), else a fraction in (0, 1] (default 0.5)")
    s.add_argument("--blend-length", type=_float("blend_length", "a length > 0"),
                   help="LE/TE blending length l_b > 0 (default: a tenth of the root's x extent)")
    s.add_argument("--circular-tangent", choices=("section", "lofting-line"),
                   help="circular fillet: the arc is tangent to the wing's own section in the "
                   "plane x = const (default; it cannot dip into the wing) or to the lofting "
                   "line projected on it (TM-4406's construction)")
    s.add_argument("--radius", type=_float("fillet_radius", "a radius > 0"),
                   help="circular fillet radius rho > 0 (default: 10 %% of the largest body "
                   "radius)")
    s.add_argument("--remedy", choices=("z-constraint", "parabolas"),
                   help="cubic fillet: low-wing dip remedy")
    s.add_argument("--figures", action="store_true",
                   help="also draw the figures (views, intersections, fillet sections, areas)")
    s.add_argument("--report", action="store_true",
                   help="also write report.html: inputs, tables, figures, wave drag, mass")
    s.add_argument("--cad", choices=("components", "fused", "faces"), default="components",
                   help="what STEP/IGES files hold: one closed solid per component "
                   "(default), the fused solid of the completed airplane (fillets "
                   "included), or the networks as faces")
    _units(s)
    return s


def build_parser(version):
    """The ``juncture`` parser, its commands and their options."""
    from ..io import reader_formats, writer_formats
    from ._commands import network_extensions

    common = _common()
    p = OneLineParser(prog="juncture", parents=[common], description=(
        "Complete an airplane described as separate components into one surface."))
    p.add_argument("--version", action="version", version=f"juncture {version}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    s = sub.add_parser("info", parents=[common], help="what is in a geometry file, checked")
    s.add_argument("file")
    s.add_argument("--format", choices=reader_formats(), help="input format (default: sniff)")

    s = sub.add_parser("convert", parents=[common],
                       help="read any supported file, write any supported format")
    s.add_argument("input")
    s.add_argument("output")
    s.add_argument("--from", dest="input_format", choices=reader_formats())
    s.add_argument("--to", dest="output_format", choices=writer_formats(),
                   help="output format (default: by extension)")

    _complete_parser(sub, common, network_extensions())

    s = sub.add_parser("wavedrag", parents=[common],
                       help="area distributions and supersonic wave drag")
    s.add_argument("deck")
    s.add_argument("--mach", type=_mach,
                   help="far-field wave drag at this Mach number, 1-10 (default: each case "
                   "card of the deck, with its NX and NTHETA; slender body without cards)")
    s.add_argument("--converge", nargs="?", const=5e-3, default=None, metavar="TOL",
                   type=_positive("a relative tolerance"),
                   help="refine n_x, then NTHETA, by doubling until D/q changes by less than "
                   "TOL (default 0.005); report the estimate, its error and how far the "
                   "chosen resolution was off")
    s.add_argument("--slender-body", action="store_true",
                   help="slender-body wave drag of the normal areas, whatever the case cards")
    s.add_argument("--harris", action="store_true",
                   help="the Harris program's conventions: straight lines between chordwise "
                   "ordinates, component areas summed (no union), normal area as M = "
                   "1.000001, NTHETA + 1 angles over a half turn with Boole's rule, the "
                   "fuselage's areas fitted by least-drag curves segment by segment")
    s.add_argument("--harris-off", nargs="+", default=(), metavar="CONVENTION",
                   choices=HARRIS_CONVENTIONS,
                   help="with --harris, leave these conventions out: "
                   + ", ".join(HARRIS_CONVENTIONS))
    s.add_argument("--fillet", choices=("none", "cubic", "circular"), default="none",
                   help="also analyse the configuration with this wing-body fillet")
    s.add_argument("--keep-area", action="store_true",
                   help="and with the fuselage re-designed to keep the area distribution")
    s.add_argument("--json", action="store_true",
                   help='print {"mach", "D_over_q", "CD", "method"} (of the last case)')
    s.add_argument("-o", "--output", help="directory for areas.png and wavedrag.json")
    s.add_argument("--n-x", type=_count(11, 100_000, "a number of stations"),
                   help="stations / cuts per angle (default: a case card's NX + 1, else 101)")
    s.add_argument("--n-theta", type=_count(1, 3600, "a number of roll angles"),
                   help="Harris NTHETA: roll-angle intervals per half turn of a symmetric "
                   "airplane, full turn otherwise (default: the case card's, else 16)")
    _units(s)

    s = sub.add_parser("blend", parents=[common],
                       help="G1 long-strake wing-body blend (Song, Ma & Wang 2008)")
    s.add_argument("spec", help="blend spec (JSON), e.g. examples/missile_blend.json")
    s.add_argument("-o", "--output", required=True, help="output directory")

    s = sub.add_parser("massprops", parents=[common],
                       help="mass, CG and inertia of a spec or of every deck component")
    s.add_argument("file", help="JSON mass-properties spec, wave-drag deck or juncture model")
    s.add_argument("--json", action="store_true", help="print JSON instead of a table")
    s.add_argument("--density", type=_positive("a density"),
                   help="deck/model only: density > 0 of every component (default 1: mass = "
                   "volume)")

    from . import _check, _mesh, _sweep

    _mesh.add_parser(sub, common)
    _check.add_parser(sub, common)
    _sweep.add_parser(sub, common)

    s = sub.add_parser("demo", parents=[common],
                       help="run the main job on the bundled supersonic transport")
    s.add_argument("-o", "--output", default="demo-output",
                   help="output directory (default: demo-output)")
    _units(s)
    return p


def fail(message):
    """Refuse an option combination found after parsing: one line, exit status 2."""
    raise UsageError(message)


class UsageError(JunctureError):
    """Options that each parse but do not go together (names the flags)."""
