"""One look for every figure and the report: component colours and unit labels.

A component keeps its colour wherever it is drawn (the three views, the juncture figures, the
report's 3-D viewer) because every one of them asks :func:`component_colour` for it, by the
component's name. Axis labels carry their unit through :func:`axis_label`; the unit is only a
label (``units``, default ``"ft"``): juncture never converts the deck's coordinates.

No matplotlib here: colours are ``"#rrggbb"`` strings that matplotlib and the report's
JavaScript viewer both read.
"""

from __future__ import annotations

import re
import zlib

__all__ = ["component_colour", "component_of", "unit_label", "axis_label", "INTERSECTION_COLOUR",
           "CASE_COLOURS", "DEFAULT_UNITS"]

#: The unit written on axes and in the report unless the caller says otherwise.
DEFAULT_UNITS = "ft"

#: Intersection lines, in every figure and in the 3-D viewer (no component has it).
INTERSECTION_COLOUR = "#111111"

#: Colours of analysis cases ("original", "cubic fillet", ...) in order: unlike any
#: component's hue, so that a case is not read as a component.
CASE_COLOURS = ("#333333", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#a6761d", "#666666")

# One hue per kind of component (matplotlib's tab10 values, readable on white). Numbered
# components of a kind ("fin 1", "fin 2") get shades of it.
_KIND_COLOURS = {
    "body": "#1f77b4", "fuselage": "#1f77b4",
    "wing": "#2ca02c",
    "fillet": "#d62728",
    "fin": "#ff7f0e",
    "pod": "#9467bd", "nacelle": "#9467bd",
    "tail": "#e377c2", "stabilizer": "#e377c2", "stabiliser": "#e377c2",
    "canard": "#17becf",
    "pylon": "#8c564b",
    "strake": "#bcbd22",
}
# Names of no known kind: a stable pick (by a checksum of the name, not Python's hash()).
_OTHER_COLOURS = ("#393b79", "#637939", "#8c6d31", "#843c39", "#7b4173", "#3182bd",
                  "#31a354", "#756bb1", "#636363", "#e6550d")
# Shade of the n-th component of a kind: 0 the hue itself, < 0 towards black, > 0 white.
_SHADES = (0.0, -0.35, 0.35, -0.55, 0.55, -0.2, 0.2)
# Words that name a part of a component's surface, not the component.
_PART_WORDS = {"upper", "lower", "outboard", "inboard", "forward", "aft", "image", "left",
               "right", "top", "bottom", "side", "nose", "base"}


def _shade(colour, amount):
    rgb = [int(colour[k:k + 2], 16) for k in (1, 3, 5)]
    target = 0 if amount < 0 else 255
    mixed = [round(c + abs(amount) * (target - c)) for c in rgb]
    return "#" + "".join(f"{c:02x}" for c in mixed)


def component_colour(name):
    """The colour of a component, by its name: the same in every figure and in the report.

    Parameters
    ----------
    name : str
        A component name, e.g. ``"wing"``, ``"body"``, ``"fin 2"``, ``"pod 1"``,
        ``"fillet"``; case and surrounding blanks do not matter.

    Returns
    -------
    str
        ``"#rrggbb"``. A known kind (body or fuselage, wing, fillet, fin, pod or nacelle,
        tail, canard, pylon, strake) has its own hue, found as a word of the name
        (``"horizontal tail"`` is a tail); its numbered members get shades of it
        (``"fin 1"`` the hue, ``"fin 2"`` darker, ``"fin 3"`` lighter). Any other name gets one
        of ten further colours, chosen by a checksum of the name, so it is stable between runs.

    Examples
    --------
    >>> component_colour("wing") == component_colour(" Wing ")
    True
    >>> component_colour("fin 1"), component_colour("fin 2")
    ('#ff7f0e', '#a65309')
    """
    key = " ".join(str(name).lower().split())
    words = re.findall(r"[a-z]+|\d+", key)
    kind = next((w for w in words if w in _KIND_COLOURS), None)
    if kind is None:
        return _OTHER_COLOURS[zlib.crc32(key.encode("utf-8")) % len(_OTHER_COLOURS)]
    numbers = [int(w) for w in words if w.isdigit()]
    n = numbers[-1] if numbers else 1
    return _shade(_KIND_COLOURS[kind], _SHADES[(max(n, 1) - 1) % len(_SHADES)])


def component_of(network, components=(), aliases=None):
    """The component a network (or intersection side) belongs to, by its name.

    Parameters
    ----------
    network : str
        A network name, ``"<component> <part>"`` (``"fin 1 outboard"``, ``"pod 2 image"``).
    components : iterable of str, optional
        The known component names: the longest one that the network name starts with wins.
    aliases : mapping of str to str, optional
        Network prefix -> component, for networks not named after their component
        (:func:`juncture.complete` names the juncture's networks ``"wing ..."`` and
        ``"body ..."`` whatever the wing and fuselage are called).

    Returns
    -------
    str
        The component name; without a known component, the network name less its trailing
        part words (upper, lower, outboard, inboard, forward, aft, image, ...) and any
        ``"segment ..."`` tail.

    Examples
    --------
    >>> component_of("fin 1 outboard image"), component_of("body upper", ["body", "wing"])
    ('fin 1', 'body')
    """
    base = str(network)
    base = base[:-len(" image")] if base.endswith(" image") else base
    for comp in sorted(components, key=len, reverse=True):
        if base == comp or base.startswith(comp + " "):
            return comp
    for prefix, comp in sorted((aliases or {}).items(), key=lambda kv: -len(kv[0])):
        if base == prefix or base.startswith(prefix + " "):
            return comp
    base = re.split(r"\s+segment\b", base, maxsplit=1, flags=re.IGNORECASE)[0].strip()
    words = base.split()
    while len(words) > 1 and words[-1].lower() in _PART_WORDS:
        words.pop()
    return " ".join(words) or str(network)


_POWERS = {1: "", 2: "\u00b2", 3: "\u00b3", 4: "\u2074", 5: "\u2075"}


def unit_label(units=DEFAULT_UNITS, power=1):
    """A length unit raised to ``power`` for a label: ``"ft"``, ``"ft²"``, ``"ft³"``, ``"ft⁵"``.

    ``units`` is written as given (it is a label: juncture converts no coordinates); an empty
    one reads ``"length"``, and a compound one is bracketed before a power (``"(0.1 m)²"``).
    """
    text = str(units).strip() or "length"
    if power == 1:
        return text
    if not re.fullmatch(r"[A-Za-z\u00b5\u03bc]+", text):
        text = f"({text})"
    return text + (_POWERS.get(power) or f"^{power}")


def axis_label(quantity, units=DEFAULT_UNITS, power=1):
    """``"<quantity> [<unit>]"``, e.g. ``axis_label("x, aft")`` is ``"x, aft [ft]"`` and
    ``axis_label("area", "m", 2)`` is ``"area [m²]"``."""
    return f"{quantity} [{unit_label(units, power)}]"
