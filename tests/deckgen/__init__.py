"""Plausible airplanes written as wave-drag decks, and the surfaces those decks describe.

Issue 11, item 5. Two halves, both independent of juncture (numpy and SciPy only):

*Strategies* (hypothesis) that draw an airplane in physically sensible proportions and write it
as deck text, card by card after docs/formats.md section 1:

- :func:`decks` -- everything: a wing and a fuselage, pods (free or on pylons), centre-line,
  twin and wing-mounted fins, canards and tails;
- :func:`wing_body_decks`, :func:`pod_decks`, :func:`fin_decks`, :func:`empennage_decks` --
  the wing and fuselage alone, or with one kind of extra component.

Each returns ``(deck_text, description)``. ``description`` holds the family labels and drawn
parameters (``{"section": "arbitrary", "segments": 3, "wing_height": "high", "root":
"crossing", "sweep_deg": 41.2, ...}``) and, under ``"components"``, the numbers written on the
cards for every component, each rounded to its 7-column field *before* anything else uses it,
so the description is exactly what the deck says. Keyword arguments pin a family, e.g.
``wing_body_decks(section="arbitrary", root="outside")``; the families are listed in
:data:`FAMILIES`. Hypothesis draws one 64-bit seed per airplane and every value comes from a
numpy generator with that seed (hypothesis's own number draws crowd the ends of each range), so
the same hypothesis seed gives the same decks, and a deck hypothesis reports as
``_build(_Draw(<seed>, pins), parts)`` is rebuilt by :func:`deck_from_seed`.

Sizes are set relative to the fuselage: length L in [40, 300] (deck units), fineness L / 2R in
[7, 16], nose and tail 0.12-0.35 L, an open base now and then; wing leading edge at
0.25-0.5 L, root chord 0.15-0.45 L (thickness at most 0.6 R), semispan 0.12-0.45 L (at least
2.5 R, shortened so that a swept tip ends within about 1.05 L), leading-edge sweep -10 to 70
deg (a crank adds 5-25 deg inboard, at most 70), dihedral -10 to 12 deg, taper 0.1-1 (a
pointed tip in 8 %), 2-8 sections, 4-14 chordwise stations, t/c 0.03-0.12 at the root; pods
0.07-0.2 L long, fineness 4-8, under the wing and clear of the fuselage; fins 0.04-0.12 L above
the fuselage (wing fins 0.5-1.5 chords above the wing); tails 0.06-0.15 L and canards
0.04-0.1 L in chord. A component that would touch another one it is not meant to touch (a
tail through the wing, a pod into a canard, a fin root through the wing's root inside the
fuselage) is left out and named under ``description["dropped"]``.

*Reference evaluation* of the deck numbers (:func:`references`): wing-like surfaces as ruled
blends of their sections (SciPy PCHIP along the chord, straight lofting lines extended beyond
root and tip); circular fuselages by PCHIP of r = sqrt(FUSARD / pi) and ZFUS within each
segment and straight lines across a gap between segments (the Harris program joins given
points by straight lines); pods by PCHIP of PODR; arbitrary sections as the polylines the deck
gives, matched between stations by normalised arc length and blended linearly in x.
:func:`intersection_offsets` measures how far each intersection point of a completed geometry
lies from both surfaces it is meant to be on.
"""

from ._read import read_text
from .draw import (
    FAMILIES,
    deck_from_seed,
    decks,
    empennage_decks,
    fin_decks,
    pod_decks,
    wing_body_decks,
)
from .references import (
    ArbitraryBodyRef,
    CircularBodyRef,
    WingLikeRef,
    components_differ,
    fillet_depths,
    intersection_offsets,
    public_description,
    references,
)

__all__ = [
    "read_text",
    "components_differ",
    "FAMILIES",
    "decks",
    "deck_from_seed",
    "wing_body_decks",
    "pod_decks",
    "fin_decks",
    "empennage_decks",
    "references",
    "WingLikeRef",
    "CircularBodyRef",
    "ArbitraryBodyRef",
    "intersection_offsets",
    "fillet_depths",
    "public_description",
]
