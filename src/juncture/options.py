"""Options of :func:`juncture.complete`, each checked against its allowed values.

The rules live here once: :class:`CompleteOptions` applies them when it is built, and the
command line applies the same rules to each flag as it parses it (:func:`check_option`), so a
bad value is refused before any geometry is computed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import OptionError

__all__ = ["CompleteOptions", "check_option", "check_combination"]


def _number(value, lo, hi, lo_open=True, hi_open=True):
    """True when value is a finite real number within (lo, hi) (bounds as stated)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    v = float(value)
    if not math.isfinite(v):
        return False
    return (v > lo if lo_open else v >= lo) and (v < hi if hi_open else v <= hi)


def _integer(value, lo):
    return isinstance(value, int) and not isinstance(value, bool) and value >= lo


def _end_value(value, end):
    if value is None:
        return True, ""
    if end == "dy":
        return _number(value, 0.0, math.inf), "a span increment > 0 [deck length]"
    return _number(value, 0.0, 1.0, hi_open=False), (f"a fraction in (0, 1] with end={end!r}")


_RULES = {
    # name: (test(value) -> bool, what is allowed)
    "theta_u_deg": (lambda v: _number(v, 0.0, 90.0), "an angle in (0, 90) [deg]"),
    "end": (lambda v: v in ("dy", "intersection", "section"),
            "one of 'dy', 'intersection', 'section'"),
    "end_value": (None, ""),  # depends on end: _end_value
    "blend_length": (lambda v: v is None or _number(v, 0.0, math.inf),
                     "a length > 0 [deck length]"),
    "blending": (lambda v: v in ("scale", "points"), "one of 'scale', 'points'"),
    "remedy": (lambda v: v in (None, "z-constraint", "parabolas"),
               "None, 'z-constraint' or 'parabolas'"),
    "fillet_radius": (lambda v: v is None or _number(v, 0.0, math.inf),
                      "a radius > 0 [deck length]"),
    "n_fillet_points": (lambda v: _integer(v, 3), "an integer >= 3"),
    "blocks": (lambda v: v is None or (v in (4, 6, "split") and not isinstance(v, bool)),
               "None, 4, 6 or 'split'"),
    "single_network": (lambda v: isinstance(v, bool), "True or False"),
    "tolerance": (lambda v: _number(v, 0.0, 1.0), "a relative tolerance in (0, 1)"),
    "compensation": (lambda v: v in ("section", "fillet"), "one of 'section', 'fillet'"),
    "circular_tangent": (lambda v: v in ("section", "lofting-line"),
                         "one of 'section', 'lofting-line'"),
    "wing": (lambda v: isinstance(v, str) and v != "", "a component name"),
    "body": (lambda v: isinstance(v, str) and v != "", "a component name"),
    "pairs": (lambda v: isinstance(v, tuple), "a tuple of (a, b, role)"),
    "empennage_sections": (lambda v: _integer(v, 0), "an integer >= 0"),
    "min_lofting_lines": (lambda v: _integer(v, 0), "an integer >= 0"),
    "refine": (lambda v: _integer(v, 1), "an integer >= 1"),
}


def check_option(name, value, end="dy"):
    """Raise :class:`OptionError` unless ``value`` is allowed for option ``name``.

    ``end`` is the cubic fillet's end-point option, which decides what ``end_value`` means.

    Examples
    --------
    >>> check_option("theta_u_deg", 30.0)
    >>> check_option("theta_u_deg", -10.0)
    Traceback (most recent call last):
    juncture.errors.OptionError: theta_u_deg = -10.0: expected an angle in (0, 90) [deg]
    """
    if name == "end_value":
        ok, expected = _end_value(value, end)
    else:
        test, expected = _RULES[name]
        ok = test(value)
    if not ok:
        raise OptionError(name, value, expected)


def check_combination(fillet, keep_area, opts, given=()):
    """Refuse options that the chosen fillet would silently ignore.

    ``given`` names options the caller set explicitly (the command line knows which flags it
    was given); options whose default is None count as given when they are not None.
    """
    if fillet not in (None, "cubic", "circular"):
        raise OptionError("fillet", fillet, "None, 'cubic' or 'circular'")
    if keep_area and fillet is None:
        raise OptionError("keep_area", keep_area, "False without a fillet (there is no added "
                          "area to compensate: choose fillet='cubic' or 'circular')")
    set_ = set(given) | {k for k in ("end_value", "remedy", "fillet_radius", "blend_length")
                         if getattr(opts, k) is not None}
    if opts.circular_tangent != "section":
        set_.add("circular_tangent")
    only = {"theta_u_deg": "cubic", "end": "cubic", "end_value": "cubic", "remedy": "cubic",
            "fillet_radius": "circular", "circular_tangent": "circular"}
    for name, kind in only.items():
        if name in set_ and fillet != kind:
            raise OptionError(name, getattr(opts, name),
                              f"no value unless fillet={kind!r} (fillet is {fillet!r})")
    if "blend_length" in set_ and fillet is None:
        raise OptionError("blend_length", opts.blend_length, "no value without a fillet")
    if ("compensation" in set_ or opts.compensation != "section") and not keep_area:
        raise OptionError("compensation", opts.compensation,
                          "no value unless keep_area=True (there is nothing to compensate)")


@dataclass(frozen=True, slots=True)
class CompleteOptions:
    """Options of :func:`complete` (all have paper-like defaults).

    Attributes
    ----------
    theta_u_deg : float
        Cubic fillet: angular distance of the start point above/below the intersection [deg].
    end : {"dy", "intersection", "section"}
        Cubic fillet end-point option (TM-4406): a span increment from the intersection,
        a fraction of the intersection -> section 2 distance, or a fraction of the section
        1 -> 2 distance.
    end_value : float or None
        Its value (a length for "dy", else a fraction). None: a quarter of the body's largest
        radius for "dy" (a fraction of the distance to section 2 is a poor default for a wing
        given by two sections, root and tip), 0.5 otherwise.
    blend_length : float or None
        LE/TE blending length l_b [deck length]; None: a tenth of the wing root's x extent.
    blending : {"scale", "points"}
        How the fillet blends out towards the edges (see juncture.fillet.cubic).
    remedy : {None, "z-constraint", "parabolas"}
        Low-wing dip remedy for the cubic fillet.
    fillet_radius : float or None
        Circular fillet radius rho [deck length]; None: 10 % of the largest body radius.
    circular_tangent : {"section", "lofting-line"}
        Circular fillet: at its end on the lofting line the arc is tangent to the wing's own
        section by the plane x = const ("section": it cannot dip into the wing), or to the
        lofting line projected on that plane, as TM-4406 constructs it ("lofting-line"; on a
        swept wing it enters the wing where the thickness changes along the chord).
    n_fillet_points : int
        Points per fillet line.
    blocks : {None, 4, 6, "split"}
        Output layout: TM-4406's 4 or 6 blocks, or TM-4607's fuselage upper and lower
        surfaces split by theta_b(x) through the canard, wing and tail regions (starting at a
        centre-line fin's intersection). None: "split" when components other than the wing
        touch the fuselage or a fillet start line of the wing turns back in x (the juncture
        blocks' arcs would fold), else 4.
    single_network : bool
        Fuselage as one network with the lower intersection re-interpolated at the upper
        points' x (TM-4406 fig 4) and points redistributed around the wing (fig 5).
    tolerance : float
        Relative area tolerance of the keep-area iteration.
    compensation : {"section", "fillet"}
        With ``keep_area``, what the re-designed fuselage gives up: the fillets' area and the
        wing root its shrinking uncovers, so the whole cross-section keeps its original area
        ("section"), or the fillets' area alone, as TM-4406 does (eqs 11-14: fuselage area +
        fillet area = original fuselage area; "fillet").
    wing, body : str
        Names of the wing and fuselage components.
    pairs : tuple of (a, b, role)
        Touching pairs stated explicitly (role "body", "upper" or "lower", see
        :mod:`juncture.intersect.pairs`); the others are found automatically.
    empennage_sections : int
        Sections interpolated between root and tip of canards, fins, tails and pylons given
        by two sections only (TM-4607).
    min_lofting_lines : int
        With ``keep_area``: a wing with fewer chordwise stations gets extra ones, each input
        interval divided evenly, so the fuselage is re-designed at that many fillet stations.
        The new stations lie on the section curves and the wing keeps those curves
        (:meth:`~juncture.model.WingLike.with_chord_stations`), so its surface does not
        change. Off (0) by default, and rarely needed (the re-designed body follows the
        compensation between fillet stations; the PDAS deck's three lofting lines already
        restore its drag to 2.3e-4).
    refine : int
        Output density: every chordwise interval of every wing-like component and the point
        spacing of every circular body's and nacelle's cross-sections divided into
        ``refine`` (1: the deck's own points; the fuselage stations stay the deck's and the
        intersections'). Body points lie on the body; the wing-like components get extra
        chord stations on their section curves, which they keep, as ``min_lofting_lines``
        does. For meshes whose volume and area converge
        (``juncture mesh --refine``).
    """

    theta_u_deg: float = 20.0
    end: str = "dy"
    end_value: float | None = None
    blend_length: float | None = None
    blending: str = "scale"
    remedy: str | None = None
    fillet_radius: float | None = None
    circular_tangent: str = "section"
    n_fillet_points: int = 9
    blocks: object = None
    single_network: bool = False
    tolerance: float = 1e-9
    compensation: str = "section"
    wing: str = "wing"
    body: str = "body"
    pairs: tuple = ()
    empennage_sections: int = 4
    min_lofting_lines: int = 0
    refine: int = 1

    def __post_init__(self):
        for name in _RULES:
            check_option(name, getattr(self, name), end=self.end)
        if self.single_network and self.remedy == "parabolas":
            raise OptionError("remedy", self.remedy, "'z-constraint' or None with "
                              "single_network (the parabolas remedy reshapes the lower fillet "
                              "lines after the single fuselage network is laid out, which "
                              "leaves a seam open)")
