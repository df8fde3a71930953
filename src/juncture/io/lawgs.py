"""LaWGS (Langley Wireframe Geometry Standard, NASA TM-85767) reader and writer, ``.wgs``.

See ``docs/formats.md`` section 3. A LaWGS file is a title record followed by
objects; each object is a name record, a header of 14 list-directed numbers::

    NOBJ NLINE NPNT ISYML RX RY RZ TX TY TZ XSCALE YSCALE ZSCALE ISYMG

and ``3 * NLINE * NPNT`` list-directed numbers: the NPNT points of contour line 1, then of
line 2, ... Contour lines are the n-lines of a juncture network, so an object becomes one
``(NLINE, NPNT, 3)`` network.

Local to global placement (TM-85767, as PDAS ``3view`` states it: "rotation, translation,
scale")::

    p = S * (R @ p_local + T),   R = Rz(RZ) @ Ry(RY) @ Rx(RX),   angles in degrees

Symmetry codes (ISYML, ISYMG): 0 none, 1 image in the x-z plane (y -> -y), 2 x-y plane
(z -> -z), 3 y-z plane (x -> -x). Code 1 is verified (PDAS ``3view``, TM-85767 examples 1
and 2); codes 2 and 3 are UNVERIFIED (recalled from TM-85767, formats.md section 3).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import DeckError, GeometryError
from ..geometry import Geometry, mirror_points
from ._freeformat import FAST, decode, line_tokens, quote, unquote
from ._registry import atomic_output, read_input, register_format, to_geometry

__all__ = ["read", "write", "placement_matrix"]

_PLANE_OF_CODE = {1: "xz", 2: "xy", 3: "yz"}
_CODE_OF_PLANE = {v: k for k, v in _PLANE_OF_CODE.items()}
_HEADER_FIELDS = ("NOBJ", "NLINE", "NPNT", "ISYML", "RX", "RY", "RZ", "TX", "TY", "TZ",
                  "XSCALE", "YSCALE", "ZSCALE", "ISYMG")
#: Header values used after a list-directed ``/`` (ends the header early), from ISYML on.
_HEADER_DEFAULTS = (0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0)

def _is_numbers(line):
    try:
        return bool(list(line_tokens(line, 0, None)))
    except DeckError:
        return False


class _Cursor:
    """Reads list-directed numbers across lines, each read starting on a new line (record)."""

    def __init__(self, lines, path):
        self.lines, self.path, self.i = lines, path, 0

    def next_nonblank(self):
        while self.i < len(self.lines) and not self.lines[self.i].strip():
            self.i += 1
        return self.i < len(self.lines)

    def numbers(self, count, what, first_line=None, allow_slash=False):
        """Read ``count`` numbers; the rest of the last line read is discarded (Fortran READ).

        ``first_line`` is text already taken from the current record (after a name). Returns
        the tokens, fewer than ``count`` only if ``allow_slash`` and a ``/`` ended the read.
        """
        got = []
        pending = [] if first_line is None else [first_line]
        while len(got) < count:
            if pending:
                text, no = pending.pop(), self.i  # the name line, already consumed
            else:
                text, no = self._next_data_line(what, count, len(got))
            for tok in line_tokens(text, no, self.path):
                if tok.value is None:
                    if allow_slash:
                        return got
                    raise DeckError(f"'/' ends the input early: expected {what(count)}, "
                                    f"found {len(got)}", path=self.path, line=no,
                                    columns=tok.columns)
                got.append(tok)
                if len(got) == count:
                    break
        return got

    def _next_data_line(self, what, count, have):
        """The next line and its number; DeckError at the end of the file or at a name."""
        if self.i >= len(self.lines):
            raise DeckError(f"expected {what(count)}, file ended after {have}",
                            path=self.path, line=len(self.lines))
        text, no = self.lines[self.i], self.i + 1
        self.i += 1
        if unquote(text) is not None:
            raise DeckError(f"expected {what(count)}, found the object name {text.strip()} "
                            f"after {have}", path=self.path, line=no)
        return text, no

    def values(self, count, what):
        """Read ``count`` numbers as a float array (the fast path of :meth:`numbers`).

        Returns the array and, per line read, ``(index of its first value, line number,
        text)`` so that a value can be traced back to its token (:meth:`token_of`).
        """
        got, starts = [], []
        while len(got) < count:
            text, no = self._next_data_line(what, count, len(got))
            starts.append((len(got), no, text))
            need = count - len(got)
            if FAST.fullmatch(text):
                try:
                    got.extend([float(w) for w in text.replace(",", " ").split()][:need])
                    continue
                except ValueError:
                    pass
            for tok in line_tokens(text, no, self.path):
                if tok.value is None:
                    raise DeckError(f"'/' ends the input early: expected {what(count)}, "
                                    f"found {len(got)}", path=self.path, line=no,
                                    columns=tok.columns)
                got.append(tok.value)
                if len(got) == count:
                    break
        return np.array(got, dtype=float), starts

    def token_of(self, index, starts):
        """The ``Token`` of value ``index`` of a :meth:`values` read."""
        first, no, text = max(s for s in starts if s[0] <= index)
        return list(line_tokens(text, no, self.path))[index - first]


def _cos_sin_deg(angle):
    """cos and sin of an angle in degrees, exact at multiples of 90 degrees."""
    q, r = divmod(float(angle), 90.0)
    if r == 0.0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(q) % 4]
    a = np.deg2rad(angle)
    return float(np.cos(a)), float(np.sin(a))


def placement_matrix(rx_deg, ry_deg, rz_deg):
    """The LaWGS rotation ``R = Rz(RZ) @ Ry(RY) @ Rx(RX)`` (TM-85767), angles in degrees.

    Returns
    -------
    (3, 3) float
        ``p_rotated = R @ p_local``: roll about x first, then pitch about y, then yaw about z.

    Examples
    --------
    >>> placement_matrix(0, -90, 0) @ [0.0, 0.0, 1.0]
    array([-1.,  0.,  0.])
    """
    cx, sx = _cos_sin_deg(rx_deg)
    cy, sy = _cos_sin_deg(ry_deg)
    cz, sz = _cos_sin_deg(rz_deg)
    rot_x = np.array([[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]])
    rot_y = np.array([[cy, 0.0, sy], [0.0, 1.0, 0.0], [-sy, 0.0, cy]])
    rot_z = np.array([[cz, -sz, 0.0], [sz, cz, 0.0], [0.0, 0.0, 1.0]])
    return rot_z @ rot_y @ rot_x


def _place(local, rotation, translation, scale):
    """``scale * (rotation @ p + translation)`` for every point of ``local`` (..., 3)."""
    if (np.array_equal(rotation, np.eye(3)) and not np.any(translation)
            and np.all(scale == 1.0)):
        return np.array(local, dtype=float)
    return (local @ rotation.T + translation) * scale


def _integer(tok, field, obj, path, low=None, high=None):
    v = tok.value
    if not math.isfinite(v) or v != int(v) or (low is not None and v < low) \
            or (high is not None and v > high):
        rng = (f" >= {low}" if high is None else f" in {low}..{high}") if low is not None else ""
        raise DeckError(f"{field} of object {obj!r} must be an integer{rng}, found {tok.text!r}",
                        path=path, line=tok.line, columns=tok.columns)
    return int(v)


def _read_object(cur, name, rest, path):
    """Header and points of one object: (header dict, (NLINE, NPNT, 3) local points)."""
    toks = cur.numbers(14, lambda n: f"{n} header numbers for object {name!r} "
                       "(NOBJ NLINE NPNT ISYML RX RY RZ TX TY TZ XSCALE YSCALE ZSCALE ISYMG)",
                       first_line=rest, allow_slash=True)
    if len(toks) < 3:
        where = toks[-1] if toks else None
        raise DeckError(f"the header of object {name!r} ends ('/') before NLINE and NPNT",
                        path=path, line=None if where is None else where.line)
    head = {}
    for field, tok in zip(_HEADER_FIELDS, toks, strict=False):
        if field in ("NLINE", "NPNT"):
            head[field] = _integer(tok, field, name, path, low=1)
        elif field in ("ISYML", "ISYMG"):
            head[field] = _integer(tok, field, name, path, low=0, high=3)
        elif field == "NOBJ":
            head[field] = _integer(tok, field, name, path)
        elif not math.isfinite(tok.value):
            raise DeckError(f"{field} of object {name!r} must be a finite number, found "
                            f"{tok.text!r}", path=path, line=tok.line, columns=tok.columns)
        else:
            head[field] = tok.value
    for field, default in zip(_HEADER_FIELDS[3:], _HEADER_DEFAULTS, strict=True):
        head.setdefault(field, default)
    nl, npt = head["NLINE"], head["NPNT"]
    data, starts = cur.values(3 * nl * npt, lambda n: f"{n} numbers for object {name!r} (NLINE "
                              f"{nl} x NPNT {npt} x 3)")
    local = data.reshape(nl, npt, 3)
    if not np.all(np.isfinite(data)):
        tok = cur.token_of(int(np.argmin(np.isfinite(data))), starts)
        raise DeckError(f"number out of range in object {name!r}: {tok.text!r}", path=path,
                        line=tok.line, columns=tok.columns)
    return head, local


def _unique(name, used):
    out, k = name, 1
    while out in used:
        k += 1
        out = f"{name} #{k}"
    used.add(out)
    return out


def read(path):
    """Read a LaWGS file into a Geometry of global points.

    Parameters
    ----------
    path : str or path-like
        A LaWGS file (NASA TM-85767); blanks or commas separate numbers, any number per line;
        ``D`` exponents and Fortran repeat counts ``r*c`` are accepted.

    Returns
    -------
    Geometry
        ``title`` is the title record (quotes and surrounding blanks removed). One network per
        object, ``(NLINE, NPNT, 3)``, placed by ``p = S * (R p_local + T)``
        (:func:`placement_matrix`), named as the object (blanks at both ends stripped, case
        kept; an empty name becomes ``"object <k>"``; repeated names get ``" #2"``, ``" #3"``).
        ISYML != 0 adds the local image, mirrored before placement, as a network
        ``"<name> local image"`` with its contour lines in reverse order (so a point order that
        gives outward normals keeps them). ISYMG 1, 2, 3 becomes symmetry ``"xz"``, ``"xy"``,
        ``"yz"`` (2 and 3 UNVERIFIED, see the module docstring).

    Raises
    ------
    DeckError
        With line and columns: a token that is not a number, too few numbers for an object,
        NLINE or NPNT not a positive integer, ISYML or ISYMG outside 0..3, numbers where an
        object name was expected.

    Notes
    -----
    Read as Fortran list-directed input, one READ per record group: the 14 header numbers
    may wrap over several lines and the points start on the line after the header; anything
    after the last value a READ needs on its line is ignored; ``/`` in a header ends it (the
    fields not given take 0, scale 1). A name line that does not start with a quote is taken
    whole as the name, so long as it is not all numbers.

    Examples
    --------
    >>> geo = read(path)                                     # doctest: +SKIP
    >>> geo.networks["FIRST CYLINDER"].shape                 # doctest: +SKIP
    (2, 7, 3)
    """
    text = decode(read_input(path, "LaWGS file (text: title record, then objects)"))
    lines = text.replace("\x1a", "").splitlines()
    cur = _Cursor(lines, path)
    if not cur.next_nonblank():
        raise DeckError("empty file: expected a LaWGS title record", path=path)
    title_line = lines[cur.i]
    quoted = unquote(title_line)
    title = (quoted[0] if quoted else title_line).strip()
    cur.i += 1
    networks, symmetry, used, log = {}, {}, set(), []
    while cur.next_nonblank():
        line, no = lines[cur.i], cur.i + 1
        cur.i += 1
        quoted = unquote(line)
        if quoted is not None:
            raw, rest = quoted
            rest = rest if rest.strip() else None
        elif _is_numbers(line):
            raise DeckError("expected an object name, found a line of numbers (does the "
                            "previous object hold more points than NLINE x NPNT of its "
                            "header?)", path=path, line=no)
        else:
            raw, rest = line, None
        label = raw.strip() or f"object {len(log) + 1}"
        head, local = _read_object(cur, label, rest, path)
        rot = placement_matrix(head["RX"], head["RY"], head["RZ"])
        shift = np.array([head["TX"], head["TY"], head["TZ"]], dtype=float)
        scale = np.array([head["XSCALE"], head["YSCALE"], head["ZSCALE"]], dtype=float)
        name = _unique(label, used)
        with np.errstate(over="ignore", invalid="ignore"):
            networks[name] = _place(local, rot, shift, scale)
        if not np.all(np.isfinite(networks[name])):
            raise DeckError(f"object {name!r}: its placement (RX RY RZ TX TY TZ XSCALE YSCALE "
                            "ZSCALE) takes coordinates out of range", path=path, line=no)
        if head["ISYML"]:
            image = mirror_points(local, _PLANE_OF_CODE[head["ISYML"]])
            networks[_unique(f"{label} local image", used)] = _place(image, rot, shift,
                                                                     scale)[::-1]
        if head["ISYMG"]:
            symmetry[name] = _PLANE_OF_CODE[head["ISYMG"]]
        log.append(f"lawgs object {head['NOBJ']} {name!r}: NLINE {head['NLINE']}, NPNT "
                   f"{head['NPNT']}, ISYML {head['ISYML']}, ISYMG {head['ISYMG']}")
    try:
        return Geometry(networks=networks, symmetry=symmetry, title=title,
                        log=(f"read LaWGS {path}",) + tuple(log))
    except GeometryError as exc:  # a check of the Geometry the reader does not make itself
        raise DeckError(str(exc), path=path) from None


def _fmt(values, digits):
    if digits is None:
        return [repr(v) for v in values.tolist()]
    return [format(v, f".{int(digits)}g") for v in values.tolist()]


def write(obj, path, *, digits=None):
    """Write networks as a LaWGS file (global coordinates, two points per line).

    Parameters
    ----------
    obj : Geometry, Configuration or dict of str to (n_lines, n_points, 3) float
        Anything :func:`juncture.io.to_geometry` accepts.
    path : str or path-like
        The output file; it appears whole or not at all.
    digits : int, optional
        Significant digits per number. ``None`` (default) writes the shortest text that reads
        back to the same float (Python ``repr``), so a round trip is exact.

    Notes
    -----
    Each network is one object with header ``nobj nline npnt 0 0 0 0 0 0 0 1 1 1 isymg``
    (``nobj`` from 1, ISYMG from :attr:`Geometry.symmetry`: xz 1, xy 2, yz 3). Names are
    quoted, a quote inside is doubled (Fortran list-directed rule).

    Raises
    ------
    GeometryError
        If the title or a network name holds a line break.
    """
    geo = to_geometry(obj)
    out = [quote(geo.title, "LaWGS title")]
    for k, (name, net) in enumerate(geo.networks.items(), start=1):
        nl, npt = net.shape[:2]
        isymg = _CODE_OF_PLANE.get(geo.symmetry.get(name), 0)
        out.append(quote(name, "LaWGS object name"))
        out.append(f"{k} {nl} {npt} 0 0 0 0 0 0 0 1 1 1 {isymg}")
        words = _fmt(net.reshape(-1), digits)
        out.extend(" " + " ".join(words[i:i + 6]) for i in range(0, len(words), 6))
    with atomic_output(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write("\n".join(out) + "\n")
    return path


def _sniff(head):
    """A title record, then a quoted object name, then a line starting with 3 integers."""
    lines = [s for s in decode(head).splitlines() if s.strip()]
    if len(lines) < 3 or unquote(lines[1]) is None:
        return False
    try:
        toks = list(line_tokens(lines[2], 3, None))
    except DeckError:
        return False
    return len(toks) >= 3 and all(t.value is not None and math.isfinite(t.value)
                                  and t.value == int(t.value) for t in toks[:3])


register_format("lawgs", [".wgs", ".lawgs"], reader=read, writer=write, sniff=_sniff)
