"""The wave-drag (Harris / D2500 / AWAVE) geometry deck: read and write, card for card.

The format is described in ``docs/formats.md`` section 1, after L. A. McCullers,
*User's Guide for the Revised Wave Drag Analysis Program* (AWAVE, 1992), cross-checked against
R. L. Carmichael's PDAS ``wd2wgs``. This module works at the *raw* level: :func:`read_deck`
returns a :class:`Deck` whose records mirror the cards (percent chord, areas, flags as read),
and :func:`write_deck` writes such a deck back so that ``read -> write -> read`` gives equal
arrays. The Configuration view (``juncture.read("x.inp")``) is built from it by
``_deck_convert``.

Reading rules, in short (details in :mod:`._cards` and :mod:`._deck_read`):

* reals are ``10F7.0`` fields: fixed 7-column slices, so numbers may touch
  (``"  100.0-12.500"`` is two fields); columns 71-80 are never read (labels are ignored;
  cards are counted); a blank field is 0; every list starts on a new card and takes
  ``ceil(n / 10)`` cards;
* the control card is ``24I3``, a case card ``A4,11I4``;
* TAB characters in the columns read are rejected (expand them to blanks first);
* the geometry stops at the case cards; case cards (each followed by its restraint card when
  NREST > 0) are read to the end of the file, or up to one with NCON = 1, after which another
  configuration (title, control card, ...) follows. A deck may also end after its geometry;
* a component flag of 2 ("as in the previous configuration") is kept as read and the component
  refers to the previous configuration's object.

Faults raise :class:`~juncture.errors.DeckError` with line and columns; values outside the
documented limits of AWAVE (NWAF 2..20, NWAFOR 3..30, NFUS 1..4, NRADX 3..30, NFORX 4..30,
NP <= 9, NPODOR 4..30, abs(NF) <= 6, NFINOR 3..10, abs(NCAN) <= 2, abs(NCANOR) 3..10) are
:class:`~juncture.errors.JunctureWarning` s, also kept in :attr:`Deck.warnings`.
"""

from __future__ import annotations

import warnings

from ..errors import JunctureWarning
from ._deck import (
    ControlCard,
    Deck,
    DeckCanard,
    DeckCase,
    DeckConfiguration,
    DeckFin,
    DeckFuselage,
    DeckFuselageSegment,
    DeckPod,
    DeckWing,
)
from ._deck_read import parse_deck
from ._deck_write import format_deck
from ._registry import atomic_output, read_input, register_format, require_configuration

__all__ = ["read_deck", "parse_deck", "format_deck", "write_deck", "read", "write", "Deck",
           "DeckConfiguration", "ControlCard", "DeckWing", "DeckFuselage",
           "DeckFuselageSegment", "DeckPod", "DeckFin", "DeckCanard", "DeckCase"]


def _decode(data):
    """Deck bytes as text: UTF-8 if valid, else Latin-1 (every byte one character)."""
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def read_deck(path):
    """Read a wave-drag deck file.

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    Deck
        All configurations, with ``path`` and the warnings raised while reading.

    Raises
    ------
    DeckError
        If the file cannot be opened, is empty or binary, or a card is malformed (with line
        and columns).

    Examples
    --------
    The same reader works on text (:func:`parse_deck`):

    >>> deck = parse_deck("REFERENCE ONLY\\n  1\\n   16.0   12.5\\n")
    >>> deck.configurations[0].reference
    (16.0, 12.5, 0.0)
    >>> print(format_deck(deck).splitlines()[2])
       16.0   12.5    0.0                                                   REFA
    """
    data = read_input(path, "wave-drag deck (text cards: title, 24I3 control card, ...)")
    return parse_deck(_decode(data), str(path))


def write_deck(deck, path):
    """Write ``deck`` to ``path`` (UTF-8, LF line endings); the file appears whole or not at all.

    Values that cannot be written exactly in 7 columns are rounded to the nearest text that
    fits, with one :class:`~juncture.errors.JunctureWarning` naming ``path``, the number of
    such values and the first of them (:func:`format_deck` warns once per value).

    Raises
    ------
    JunctureError
        If a record does not agree with its control card (see :func:`format_deck`), or
        ``path`` cannot be written.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        text = format_deck(deck)
    rounded = [str(w.message) for w in caught if issubclass(w.category, JunctureWarning)]
    for w in caught:
        if not issubclass(w.category, JunctureWarning):
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    if len(rounded) == 1:
        warnings.warn(f"{path}: {rounded[0]}", JunctureWarning, stacklevel=2)
    elif rounded:
        warnings.warn(f"{path}: {len(rounded)} values cannot be written exactly in 7 columns "
                      f"and were rounded to the nearest text that fits; the first: "
                      f"{rounded[0]}", JunctureWarning, stacklevel=2)
    with atomic_output(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(text)


def read(path, configuration=0):
    """Read configuration ``configuration`` (0-based) of a deck as a Configuration."""
    return _read_configuration(path, configuration)


def write(obj, path):
    """Write a Configuration (or a :class:`Deck`) as a wave-drag deck."""
    return _write_configuration(obj, path)


def _read_configuration(path, configuration=0):
    from ._deck_convert import deck_to_configuration

    return deck_to_configuration(read_deck(path), configuration, path)


def _write_configuration(obj, path):
    from ._deck_convert import configuration_to_deck

    if not isinstance(obj, Deck):
        obj = configuration_to_deck(require_configuration(obj, path, "wave-drag deck"))
    write_deck(obj, path)


_FLAG_RANGES = ((0, 2), (-1, 2), (-1, 2), (0, 2), (0, 2), (0, 2), (-1, 1))


def _sniff(head):
    """True if line 2 of ``head`` (bytes) is a plausible ``24I3`` control card."""
    lines = head.decode("latin-1").replace("\r", "").split("\n")
    if len(lines) < 2:
        return False
    card = lines[1][:72].ljust(72)
    values = []
    for i in range(24):
        field = card[3 * i:3 * i + 3]
        body = field.lstrip(" ")
        if not body:
            values.append(0)
            continue
        sign = body[0] in "+-"
        digits = body[1:] if sign else body
        if not (digits.isascii() and digits.isdigit()):
            return False
        values.append(int(body))
    if not any(values[:7]):
        return False
    if not all(lo <= v <= hi for v, (lo, hi) in zip(values[:7], _FLAG_RANGES, strict=True)):
        return False
    nwaf, nfus, np_, npodor, nfinor = values[7], values[9], values[18], values[19], values[21]
    return nwaf >= 0 and 0 <= nfus <= 4 and min(values[10:18]) >= 0 and np_ >= 0 \
        and npodor >= 0 and nfinor >= 0


register_format("wavedrag", (".inp", ".wd", ".wdk"), reader=_read_configuration,
                writer=_write_configuration, sniff=_sniff)
