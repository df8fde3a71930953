"""Fixed-field card images: reading ``10F7.0`` / ``I3`` / ``I4`` fields, and writing them back.

The wave-drag deck (``formats.md`` section 1.0) is a sequence of 80-column card images. Numbers
sit in fixed 7-column fields (field k in columns ``7(k-1)+1 .. 7k``, at most ten to a card, so
columns 71-80 are never read); integers in fixed 3- or 4-column fields. This module knows
nothing about what the cards mean: :class:`CardReader` hands out cards and converts fields,
with the file, line and columns of every fault; :func:`format_real` and :func:`format_card`
write values back so that they read to exactly the same floats.

Reading rules (Fortran ``F7.0`` read with ``BN``, the default for formatted files):

* an all-blank field is 0; a field without a decimal point is read as an integer value
  (``"16"`` -> 16.0); an explicit point overrides the ``.0`` of the format;
* exponents ``E`` and ``D`` are accepted (``1.5E2``, ``1.5D2``), and so is Fortran's
  letterless signed exponent (``1.5-2`` = 0.015), the latter with a warning;
* blanks inside a number are ignored (``"1 2.5"`` -> 12.5), with a warning, since a compiler
  reading with ``BZ`` would see zeros there;
* a TAB character in the columns that are read is rejected (its column width is undefined for
  fixed fields); TABs elsewhere (titles, identification columns) are left alone;
* CR characters are blanks (as PDAS ``wd2wgs`` treats them), so CRLF files read as LF files;
  trailing blanks and short lines are padded with blanks;
* trailing lines that are entirely blank are not cards: the file ends at its last non-blank line.
"""

from __future__ import annotations

import math
import re
import warnings
from decimal import ROUND_DOWN, ROUND_HALF_EVEN, Decimal

import numpy as np

from ..errors import DeckError, JunctureError, JunctureWarning

__all__ = ["CardReader", "split_lines", "format_real", "format_card", "format_ints",
           "FIELD_WIDTH", "FIELDS_PER_CARD", "LABEL_COLUMN", "NOISE_ULPS"]

#: Width of one real field (``F7.0``) and the number of fields on one card.
FIELD_WIDTH = 7
FIELDS_PER_CARD = 10
#: First column (1-based) of the identification label on written cards.
LABEL_COLUMN = 73
#: A value written as a text this many units in the last place away is written silently.
NOISE_ULPS = 4

_REAL = re.compile(r"([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+))(?:[EeDd]([+-]?[0-9]+)|([+-][0-9]+))?",
                   re.ASCII)
_INTEGER = re.compile(r"[+-]?[0-9]+", re.ASCII)


def _ordinal(k):
    suffix = "th" if 10 <= k % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(k % 10, "th")
    return f"{k}{suffix}"


def split_lines(text):
    """Split deck text into lines: LF, CRLF or CR endings; other CR characters become blanks."""
    text = text.lstrip("\ufeff").replace("\r\n", "\n")
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return [line.replace("\r", " ") for line in lines]


class CardReader:
    """A cursor over the cards of a deck that converts fields and reports faults with positions.

    Parameters
    ----------
    text : str
        The whole deck.
    path : str, optional
        File name for messages.

    Attributes
    ----------
    lines : list of str
        The lines of the file (CR removed).
    pos : int
        Number of lines consumed so far; the next card is ``lines[pos]`` (line ``pos + 1``).
    end : int
        Number of lines up to and including the last non-blank one.
    warnings : list of str
        Messages of everything accepted with a warning, in file order.
    """

    def __init__(self, text, path=None):
        self.path = None if path is None else str(path)
        self.lines = split_lines(text)
        end = len(self.lines)
        while end > 0 and not self.lines[end - 1].strip(" "):
            end -= 1
        self.end = end
        self.pos = 0
        self.warnings = []

    # -- positions, errors and warnings ----------------------------------------------------

    def error(self, message, line=None, columns=None):
        """Return (not raise) a :class:`DeckError` at ``line`` (1-based) and ``columns``."""
        return DeckError(message, path=self.path, line=line, columns=columns)

    def warn(self, message, line=None, columns=None):
        """Record a warning and emit it as a :class:`JunctureWarning`."""
        where = [] if self.path is None else [self.path]
        if line is not None:
            where.append(f"line {line}")
        if columns is not None:
            where.append(f"columns {columns[0]}-{columns[1]}")
        text = ", ".join(where) + ": " + message if where else message
        self.warnings.append(text)
        warnings.warn(text, JunctureWarning, stacklevel=4)

    def at_end(self):
        """True when no non-blank line is left."""
        return self.pos >= self.end

    def next_card(self, what):
        """Consume the next card; return ``(line_number, text)``.

        Raises
        ------
        DeckError
            ``file ended after line N while reading <what>`` at the end of the file.
        """
        if self.pos >= self.end:
            raise self.error(f"file ended after line {self.end} while reading {what}",
                             line=self.end or None)
        self.pos += 1
        return self.pos, self.lines[self.pos - 1]

    def _field(self, text, line, a, b):
        """Columns ``a..b`` (1-based, inclusive) of ``text``, padded; TABs rejected."""
        field = text[a - 1:b].ljust(b - a + 1)
        tab = field.find("\t")
        if tab >= 0:
            raise self.error(f"TAB character in column {a + tab}: deck cards have fixed "
                             "columns; replace TABs by blanks", line=line, columns=(a, b))
        return field

    # -- conversion of single fields ---------------------------------------------------------

    def real(self, text, line, a, b, what):
        """Read columns ``a..b`` of a card as a Fortran ``F`` field (blank -> 0.0)."""
        field = self._field(text, line, a, b)
        body = field.strip(" ")
        if not body:
            return 0.0
        squeezed = body.replace(" ", "")
        m = _REAL.fullmatch(squeezed)
        if m is None:
            raise self.error(f"expected a number ({what}), found {field.strip(' ')!r}",
                             line=line, columns=(a, b))
        if squeezed != body:
            self.warn(f"blanks inside the number {body!r} ({what}) ignored as Fortran BN "
                      f"reads them: {squeezed}", line, (a, b))
        mantissa, exp1, exp2 = m.groups()
        if exp2 is not None:
            self.warn(f"{squeezed!r} ({what}) read as {mantissa}E{exp2} (Fortran exponent "
                      "without a letter)", line, (a, b))
        exponent = exp1 if exp1 is not None else exp2
        value = float(mantissa if exponent is None else f"{mantissa}e{exponent}")
        if not math.isfinite(value):
            raise self.error(f"number out of range ({what}): {body!r}", line=line,
                             columns=(a, b))
        return value

    def integer(self, text, line, a, b, what):
        """Read columns ``a..b`` of a card as a Fortran ``I`` field (blank -> 0)."""
        field = self._field(text, line, a, b)
        body = field.strip(" ")
        if not body:
            return 0
        squeezed = body.replace(" ", "")
        if _INTEGER.fullmatch(squeezed) is None:
            raise self.error(f"expected an integer ({what}), found {body!r}", line=line,
                             columns=(a, b))
        if squeezed != body:
            self.warn(f"blanks inside the integer {body!r} ({what}) ignored as Fortran BN "
                      f"reads them: {squeezed}", line, (a, b))
        return int(squeezed)

    def text(self, text, line, a, b):
        """Columns ``a..b`` as raw text (an ``A`` field), padded with blanks."""
        return self._field(text, line, a, b)

    # -- whole cards -------------------------------------------------------------------------

    def reals(self, n, card, where="", names=None):
        """Read a list of ``n`` real values, ten to a card, starting on a new card.

        Parameters
        ----------
        n : int
            Number of values; the list takes ``ceil(n / 10)`` cards (none when ``n == 0``).
        card : str
            Card name for messages (``"XAF"``, ``"WAFORG"``).
        where : str, optional
            Which one, for messages (``"for section 3"``).
        names : sequence of str, optional
            Names of the values of a one-card record (``("x", "y", "z", "chord")``).

        Returns
        -------
        values : (n,) float ndarray
        first_line : int or None
            Line number of the first card (value ``i`` is on line ``first_line + i // 10``,
            columns ``7 (i % 10) + 1 .. 7 (i % 10) + 7``); ``None`` when ``n == 0``.

        Raises
        ------
        DeckError
            A field that is not a number, a non-blank field beyond the expected count, or the
            end of the file before ``n`` values.
        """
        what = f"{card} {where}".strip()
        values = np.zeros(n)
        first = None
        for start in range(0, n, FIELDS_PER_CARD):
            k = min(FIELDS_PER_CARD, n - start)
            if self.pos >= self.end:
                raise self.error(f"file ended after line {self.end} while reading {what} "
                                 f"({start} of {n} values read)", line=self.end or None)
            line, text = self.next_card(what)
            first = line if first is None else first
            for j in range(k):
                i = start + j
                name = f"{card} {names[i]}" if names else f"{card} value {i + 1}"
                values[i] = self.real(text, line, 7 * j + 1, 7 * j + 7,
                                      f"{name} {where}".strip())
            for j in range(k, FIELDS_PER_CARD):
                a = 7 * j + 1
                field = self._field(text, line, a, a + 6)
                if field.strip(" "):
                    raise self.error(
                        f"expected {k} value{'s' if k != 1 else ''} on this {card} card"
                        f"{f' ({where})' if where else ''}, "
                        f"found a {_ordinal(j + 1)} in columns {a}-{a + 6}: "
                        f"{field.strip(' ')!r}", line=line, columns=(a, a + 6))
        return values, first

    def position(self, first_line, i):
        """``(line, (first column, last column))`` of value ``i`` of a list read by reals."""
        j = i % FIELDS_PER_CARD
        return first_line + i // FIELDS_PER_CARD, (7 * j + 1, 7 * j + 7)


# -- writing ------------------------------------------------------------------------------


def _decimal_parts(value):
    """Shortest round-trip decimal digits of ``value``: (sign, digit string, exponent)."""
    sign, digits, exponent = Decimal(repr(value)).normalize().as_tuple()
    return ("-" if sign else ""), "".join(map(str, digits)), exponent


def _candidates(sign, digits, exponent):
    """Texts of ``sign digits x 10**exponent`` as (rank, text), plainest first.

    Rank 0 plain decimals (``100.0``, ``0.05``), 1 compact ones (``100.``, ``.05``), 2 the
    scientific form (``1.5E-9``), 3 compact exponent forms (``15E-10``, ``.15E-8``).
    """
    n = len(digits)
    out = []
    if exponent >= 0:
        whole = digits + "0" * exponent
        out += [(0, f"{sign}{whole}.0"), (1, f"{sign}{whole}."), (1, f"{sign}{whole}")]
    else:
        k = -exponent  # digits after the point
        if k < n:
            out.append((0, f"{sign}{digits[:n - k]}.{digits[n - k:]}"))
        else:
            frac = "0" * (k - n) + digits
            out += [(0, f"{sign}0.{frac}"), (1, f"{sign}.{frac}")]
    # exponent forms: d.ddE(e), dddE(e), .dddE(e)
    e_sci = exponent + n - 1
    mant = digits[0] + "." + (digits[1:] or "0")
    out += [(2, f"{sign}{mant}E{e_sci}"), (3, f"{sign}{digits[0]}.{digits[1:]}E{e_sci}"),
            (3, f"{sign}{digits}E{exponent}"), (3, f"{sign}.{digits}E{exponent + n}")]
    return out


def format_real(value, width=FIELD_WIDTH):
    """Text of at most ``width`` characters that reads back to exactly ``value`` if possible.

    Plain decimals are preferred, then compact forms (``".5"``, ``"100."``), then exponent
    forms (``"1.5E-9"``); among texts that leave a leading blank (so numbers do not touch),
    the plainest, then the shortest, wins.

    Parameters
    ----------
    value : float
        A finite number.
    width : int
        Field width.

    Returns
    -------
    text : str
        Right-justified to ``width``.
    exact : bool
        False when no text of ``width`` characters reads back exactly; then ``text`` is the
        nearest one found.

    Raises
    ------
    JunctureError
        If ``value`` is not finite, or no text fits at all.

    Examples
    --------
    >>> format_real(100.0)
    ('  100.0', True)
    >>> format_real(-0.0125)
    (' -.0125', True)
    >>> format_real(1.5e-9)
    (' 1.5E-9', True)
    """
    value = float(value)
    if not math.isfinite(value):
        raise JunctureError(f"cannot write the non-finite value {value} in a deck field")
    if value == 0.0:
        return ("-0.0" if math.copysign(1.0, value) < 0 else "0.0").rjust(width), True
    sign, digits, exponent = _decimal_parts(value)

    def best(cands):
        fit = [(len(t) >= width, rank, len(t), i, t)
               for i, (rank, t) in enumerate(cands) if len(t) <= width]
        return min(fit)[4] if fit else None

    text = best(_candidates(sign, digits, exponent))
    if text is not None:
        return text.rjust(width), True
    # no exact text: round to fewer significant digits (nearest, and toward zero in case the
    # nearest overflows), keep the closest text that fits
    exact_value = Decimal(repr(value))
    found = []
    for p in range(len(digits) - 1, 0, -1):
        unit = Decimal(1).scaleb(exact_value.adjusted() - p + 1)
        for rounding in (ROUND_HALF_EVEN, ROUND_DOWN):
            rounded = float(exact_value.quantize(unit, rounding=rounding))
            if math.isfinite(rounded) and rounded != 0.0:
                text = best(_candidates(*_decimal_parts(rounded)))
                if text is not None:
                    found.append((abs(rounded - value), text))
    if found:
        return min(found)[1].rjust(width), False
    raise JunctureError(f"the value {value!r} cannot be written in {width} columns")


def _label(text, label):
    if not label:
        return text.rstrip()
    return text.ljust(LABEL_COLUMN - 1) + label[:80 - LABEL_COLUMN + 1]


def format_card(values, label="", what="value"):
    """Card lines (no newline) for a list of reals, ten to a card, label in columns 73-80.

    A value that cannot be written exactly in 7 columns is written as the nearest text that
    fits, with a :class:`JunctureWarning` naming ``what``, unless that text is within
    :data:`NOISE_ULPS` units in the last place of the value: such a value is a decimal of the
    deck seen through floating-point arithmetic (a FUSARD area that went to a radius
    ``sqrt(A / pi)`` and back is 1 or 2 ulps off), and the text is the decimal it came from.
    """
    values = np.asarray(values, dtype=float).ravel()
    lines = []
    for start in range(0, len(values), FIELDS_PER_CARD):
        parts = []
        for i, v in enumerate(values[start:start + FIELDS_PER_CARD], start):
            text, exact = format_real(v)
            if not exact and abs(float(text) - v) > NOISE_ULPS * math.ulp(v):
                warnings.warn(f"{what} {i + 1} = {float(v)!r} cannot be written exactly in 7 "
                              f"columns; wrote {text.strip()!r} (difference "
                              f"{float(text) - float(v):.3g})", JunctureWarning, stacklevel=3)
            parts.append(text)
        lines.append(_label("".join(parts), label))
    return lines


def format_ints(values, width, label="", what="value"):
    """One card of right-justified integers in ``width``-column fields, label in 73-80."""
    parts = []
    for i, v in enumerate(values):
        text = str(int(v))
        if len(text) > width:
            raise JunctureError(f"{what} {i + 1} = {v} does not fit in {width} columns")
        parts.append(text.rjust(width))
    return _label("".join(parts), label)
