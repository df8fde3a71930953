"""Fortran list-directed (free-format) text, shared by the LaWGS, Plot3D and Hess modules.

A real is a signed mantissa with an optional exponent whose letter (E, D) may be left out
when the exponent has a sign ("1.5+2" = 150); ``r*c`` repeats c r times; ``/`` ends the
input; items are separated by blanks or commas. Names are quoted with ' or " (a doubled
quote stands for itself).
"""

from __future__ import annotations

import re

from ..errors import DeckError, GeometryError

__all__ = ["Token", "FAST", "parse_real", "line_tokens", "unquote", "quote", "decode"]

_REAL = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][+-]?\d+|[+-]\d+)?")
_REPEAT = re.compile(r"(\d+)\*(.*)")
_FIELD = re.compile(r"[^\s,]+")
FAST = re.compile(r"[\s,0-9.eE+-]*")


class Token:
    """One list-directed item: ``value`` (float, or None for ``/``), where it was, its text."""

    __slots__ = ("value", "line", "columns", "text")

    def __init__(self, value, line, columns, text):
        self.value, self.line, self.columns, self.text = value, line, columns, text


def parse_real(text):
    """Float of a Fortran real literal, or None if ``text`` is not one."""
    if not _REAL.fullmatch(text):
        return None
    s = text.replace("d", "e").replace("D", "e")
    if "e" not in s and "E" not in s:
        s = re.sub(r"(?<=[\d.])([+-])", r"e\1", s)
    return float(s)


def line_tokens(line, line_no, path):
    """List-directed items of one line: ``Token`` iterable; ``r*c`` expanded, ``/`` kept.

    Items are parsed lazily, so text after the last item a READ needs is never looked at
    (as in Fortran). A bad item raises DeckError naming the line, the columns and the token.
    """
    if FAST.fullmatch(line):
        try:
            return [Token(float(m.group()), line_no, (m.start() + 1, m.end()), m.group())
                    for m in _FIELD.finditer(line)]
        except ValueError:
            pass  # "1.5+2" and the like: the careful path below
    return _careful_tokens(line, line_no, path)


def _careful_tokens(line, line_no, path):
    for m in _FIELD.finditer(line):
        text, cols = m.group(), (m.start() + 1, m.end())
        if text.startswith("/"):
            yield Token(None, line_no, cols, "/")
            return
        count, item = 1, text
        rep = _REPEAT.fullmatch(text)
        if rep:
            count, item = int(rep.group(1)), rep.group(2)
            if count < 1 or item == "":
                raise DeckError(f"null values ({text!r}) are not supported; give every value",
                                path=path, line=line_no, columns=cols)
        value = parse_real(item)
        if value is None:
            raise DeckError(f"expected a number, found {text!r}", path=path, line=line_no,
                            columns=cols)
        for _ in range(count):
            yield Token(value, line_no, cols, text)


def unquote(line):
    """Text inside the leading quotes of ``line`` ('' or "" doubled inside), and what follows.

    Returns ``(text, rest)``, or ``None`` if the line does not start with a quote.
    """
    s = line.lstrip()
    if not s or s[0] not in "'\"":
        return None
    q = s[0]
    i, chars = 1, []
    while i < len(s):
        if s[i] == q:
            if s[i + 1:i + 2] == q:
                chars.append(q)
                i += 2
                continue
            return "".join(chars), s[i + 1:]
        chars.append(s[i])
        i += 1
    return "".join(chars), ""  # unterminated quote: take the rest of the line


def decode(raw):
    """Text of a file's bytes: UTF-8, else Latin-1 (old decks)."""
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("latin-1")


def quote(text, what):
    """``text`` in single quotes (inner quotes doubled); ``what`` names it in errors."""
    if "\n" in text or "\r" in text:
        raise GeometryError(f"a {what} must be one line, found {text!r}", component=text)
    return "'" + text.replace("'", "''") + "'"
