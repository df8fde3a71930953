"""Hess network listing, ``.hess``: juncture's plain text form of the TM-4406 output networks.

TM-4406 and TM-4607 write their surfaces "in Hess format" (NASA CR-2962): networks made of
n-lines (sections) whose equal point indices form m-lines. No public card layout of CR-2962
was found (``docs/formats.md`` section 3), so this is a documented plain network
list of the same structure, not the CR-2962 card deck. The exact layout is in ``docs/hess.md``::

    HESS NETWORK LIST 1
    TITLE 'two panels'
    NETWORK 1 'wing upper' 2 3 xz
    NLINE 1
    0.0 0.0 0.0
    ...
    END

Numbers are written as Python ``repr`` (the shortest text that reads back to the same float),
so a write-read round trip is exact.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import DeckError
from ..geometry import Geometry
from ._freeformat import decode, parse_real, quote, unquote
from ._registry import atomic_output, read_input, register_format, to_geometry

__all__ = ["read", "write"]

_MAGIC = "HESS NETWORK LIST"
_VERSION = 1
_PLANES = ("none", "xz", "xy", "yz")


def write(obj, path):
    """Write networks as a Hess network listing (``docs/hess.md``).

    Parameters
    ----------
    obj : Geometry, Configuration or dict of str to (n_lines, n_points, 3) float
        Anything :func:`juncture.io.to_geometry` accepts.
    path : str or path-like
        The output file; it appears whole or not at all.

    Notes
    -----
    Networks are written in order, each with its symmetry plane (``none`` when it has no
    image); images are not written (the reader restores the symmetry entry). Intersections,
    fillets, stations and the log are not part of the listing.

    Raises
    ------
    GeometryError
        If the title or a network name holds a line break.
    """
    geo = to_geometry(obj)
    out = [f"{_MAGIC} {_VERSION}", "TITLE " + quote(geo.title, "Hess title")]
    for k, (name, net) in enumerate(geo.networks.items(), start=1):
        nl, npt = net.shape[:2]
        plane = geo.symmetry.get(name, "none")
        out.append(f"NETWORK {k} {quote(name, 'Hess network name')} {nl} {npt} {plane}")
        for i in range(nl):
            out.append(f"NLINE {i + 1}")
            out.extend(f"{x!r} {y!r} {z!r}" for x, y, z in net[i].tolist())
    out.append("END")
    with atomic_output(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write("\n".join(out) + "\n")
    return path


class _Lines:
    """Significant lines (not blank, not ``#`` comments) with their 1-based numbers."""

    def __init__(self, text, path):
        self.items = [(no, s.strip()) for no, s in enumerate(text.splitlines(), start=1)
                      if s.strip() and not s.lstrip().startswith("#")]
        self.k, self.path = 0, path
        self.last = len(text.splitlines())

    def take(self, expected):
        if self.k >= len(self.items):
            raise DeckError(f"file ended, expected {expected}", path=self.path,
                            line=self.last or None)
        self.k += 1
        return self.items[self.k - 1]

    def error(self, no, message):
        return DeckError(message, path=self.path, line=no)


def _int_field(word, what, lines, no, low):
    if not word.isdigit() or int(word) < low:
        raise lines.error(no, f"{what} must be an integer >= {low}, found {word!r}")
    return int(word)


def _network_line(lines, k):
    no, line = lines.take(f"'NETWORK {k} ...' or 'END'")
    if line.upper() == "END":
        return None
    head, _, rest = line.partition(" ")
    if head.upper() != "NETWORK":
        raise lines.error(no, f"expected 'NETWORK {k} ...' or 'END', found {line!r}")
    index, _, rest = rest.strip().partition(" ")
    if index != str(k):
        raise lines.error(no, f"expected network index {k}, found {index!r}")
    quoted = unquote(rest)
    if quoted is None:
        raise lines.error(no, f"expected a quoted network name after 'NETWORK {k}', found "
                          f"{rest.strip()!r}")
    name, rest = quoted
    words = rest.split()
    if len(words) != 3:
        raise lines.error(no, "expected n-lines, points per n-line and symmetry plane after "
                          f"the name, found {rest.strip()!r}")
    nl = _int_field(words[0], "number of n-lines", lines, no, 1)
    npt = _int_field(words[1], "points per n-line", lines, no, 1)
    plane = words[2].lower()
    if plane not in _PLANES:
        raise lines.error(no, f"symmetry plane must be one of {', '.join(_PLANES)}, found "
                          f"{words[2]!r}")
    return name, nl, npt, plane


def _points(lines, name, i, npt):
    """The ``npt`` point lines of n-line ``i``: (npt, 3) float."""
    rows = [lines.take(f"point {j + 1} of n-line {i} of network {name!r}") for j in range(npt)]
    try:  # fast path: every line three plain decimal numbers
        arr = np.array([line.split() for _, line in rows], dtype=float)
        if arr.shape == (npt, 3) and np.all(np.isfinite(arr)):
            return arr
    except ValueError:
        pass
    for j, (no, line) in enumerate(rows):
        words = line.split()
        vals = [parse_real(w) for w in words]
        if len(words) != 3 or any(v is None or not math.isfinite(v) for v in vals):
            raise lines.error(no, f"expected point {j + 1} of n-line {i} of network {name!r} "
                              f"as three finite numbers 'x y z', found {line!r}")
    return np.array([[parse_real(w) for w in line.split()] for _, line in rows], dtype=float)


def read(path):
    """Read a Hess network listing (``docs/hess.md``) as a Geometry.

    Parameters
    ----------
    path : str or path-like
        A file starting with the line ``HESS NETWORK LIST 1``.

    Returns
    -------
    Geometry
        One ``(n_lines, n_points, 3)`` network per ``NETWORK`` record, its symmetry plane, and
        the title.

    Raises
    ------
    DeckError
        With the line number: a missing or unknown header, a network index or n-line number
        out of sequence, a repeated name, a point that is not three numbers, an unknown
        symmetry plane, a missing ``END``.
    """
    text = decode(read_input(path, f"Hess network listing (text starting '{_MAGIC} "
                                   f"{_VERSION}')"))
    lines = _Lines(text, path)
    no, line = lines.take(f"the header '{_MAGIC} {_VERSION}'")
    words = line.split()
    if " ".join(words[:3]).upper() != _MAGIC or len(words) != 4:
        raise lines.error(no, f"expected the header '{_MAGIC} {_VERSION}', found {line!r}")
    if words[3] != str(_VERSION):
        raise lines.error(no, f"unsupported Hess listing version {words[3]!r}; this reader "
                          f"knows version {_VERSION}")
    title = ""
    if lines.k < len(lines.items) and lines.items[lines.k][1].upper().startswith("TITLE"):
        no, line = lines.take("TITLE")
        quoted = unquote(line[5:])
        title = quoted[0] if quoted else line[5:].strip()
    networks, symmetry = {}, {}
    k = 1
    while (head := _network_line(lines, k)) is not None:
        name, nl, npt, plane = head
        if name in networks:
            raise lines.error(lines.items[lines.k - 1][0], f"network name {name!r} repeated")
        rows = []
        for i in range(1, nl + 1):
            no, line = lines.take(f"'NLINE {i}' of network {name!r}")
            words = line.split()
            if len(words) != 2 or words[0].upper() != "NLINE" or words[1] != str(i):
                raise lines.error(no, f"expected 'NLINE {i}' of network {name!r} ({nl} n-lines "
                                  f"of {npt} points), found {line!r}")
            rows.append(_points(lines, name, i, npt))
        networks[name] = np.array(rows, dtype=float)
        if plane != "none":
            symmetry[name] = plane
        k += 1
    if lines.k < len(lines.items):
        no, line = lines.items[lines.k]
        raise lines.error(no, f"unexpected text after END: {line!r}")
    return Geometry(networks=networks, symmetry=symmetry, title=title,
                    log=(f"read Hess network listing {path}",))


def _sniff(head):
    """The first significant line is ``HESS NETWORK LIST <version>``."""
    for line in decode(head).splitlines():
        s = line.strip()
        if s and not s.startswith("#"):
            return s.upper().startswith(_MAGIC)
    return False


register_format("hess", [".hess"], reader=read, writer=write, sniff=_sniff)
