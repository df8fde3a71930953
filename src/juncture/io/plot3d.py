"""Plot3D formatted surface grids, ``.p3d`` (also ``.xyz``, ``.g``): reader and writer.

See ``docs/formats.md`` section 4 (NASA PLOT3D manual; OpenVSP's writer as a
concrete example). juncture writes the formatted, multi-block, "whole" layout with KDIM = 1::

    NBLK
    IDIM JDIM 1            (one line per block)
    x ... (IDIM*JDIM, I fastest), then y ..., then z ...   (per block)

with I = point index along an n-line and J = n-line index, so that the grid's I x J normal is
juncture's outward normal ``cross(P[j, i+1] - P[j, i], P[j+1, i] - P[j, i])``. Plot3D has no
place for names or symmetry: block names are lost (the reader calls them ``"block 1"``, ...)
and mirror images are written as extra blocks.
"""

from __future__ import annotations

import math
import re

import numpy as np

from ..errors import DeckError
from ..geometry import Geometry
from ._freeformat import decode, line_tokens
from ._registry import atomic_output, read_input, register_format, to_geometry

__all__ = ["read", "write"]

_PER_LINE = 5
_NUMERIC_HEAD = re.compile(rb"[\s0-9.eEdD+,*-]*")


def _all_numbers(text, path):
    """Every list-directed number of ``text`` as a float array (repeat counts expanded)."""
    try:
        return np.array(text.replace(",", " ").split(), dtype=float)
    except ValueError:
        pass  # D exponents, r*c, or a bad token: read line by line for the exact place
    vals = []
    for no, line in enumerate(text.splitlines(), start=1):
        try:
            for tok in line_tokens(line, no, path):
                if tok.value is None:
                    raise DeckError("'/' is not allowed in a Plot3D file", path=path, line=no,
                                    columns=tok.columns)
                vals.append(tok.value)
        except DeckError as exc:
            raise DeckError(f"{exc.reason} (a formatted Plot3D grid holds numbers only)",
                            path=exc.path, line=exc.line, columns=exc.columns) from None
    return np.array(vals, dtype=float)


def _posint(values):
    v = np.asarray(values)
    return v.size > 0 and bool(np.all((v >= 1) & (v == np.round(v)) & (v < 2**31)))


def _layout(v):
    """Which layout explains all ``len(v)`` numbers: (name, ndim, dims (n, 3) int, iblank).

    Tried in order: multi-block 3-D, single-block 3-D, multi-block 2-D, single-block 2-D; each
    with or without an IBLANK array per block. The first whose counts add up exactly wins.
    """
    n = v.size
    for name, nd, multi in (("multi-block 3-D", 3, True), ("single-block 3-D", 3, False),
                            ("multi-block 2-D", 2, True), ("single-block 2-D", 2, False)):
        if multi:
            if n < 1 or not _posint(v[:1]):
                continue
            nblk = int(v[0])
            start = 1 + nd * nblk
            if start > n or not _posint(v[1:start]):
                continue
            dims = v[1:start].reshape(nblk, nd).astype(np.int64)
        else:
            start = nd
            if n < nd or not _posint(v[:nd]):
                continue
            dims = v[:nd].reshape(1, nd).astype(np.int64)
        size = sum(math.prod(d) for d in dims.tolist())
        for iblank in (False, True):
            if start + (nd + iblank) * size == n:
                if nd == 2:
                    dims = np.column_stack([dims, np.ones(len(dims), dtype=np.int64)])
                return name, nd, dims, iblank, start
    return None


def read(path):
    """Read a formatted Plot3D grid file as a Geometry, one network per block.

    Parameters
    ----------
    path : str or path-like
        A formatted (ASCII) Plot3D grid file. Detected layouts, tried in this order, the first
        whose number count matches the dimensions exactly winning: multi-block 3-D (``NBLK``,
        ``IDIM JDIM KDIM`` per block, then x, y, z per block), single-block 3-D (no ``NBLK``),
        multi-block 2-D (``IDIM JDIM`` per block, x and y only, z = 0), single-block 2-D. Each
        may carry an IBLANK array after each block's coordinates; it is read and dropped.
        Unformatted (Fortran binary) files are not read.

    Returns
    -------
    Geometry
        Networks ``"block 1"``, ``"block 2"``, ..., each ``(JDIM, IDIM, 3)``: J is the n-line
        index, I the point index (I fastest in the file). A block with KDIM > 1 but one of
        IDIM, JDIM equal to 1 is read as the surface of its other two dimensions. No symmetry.

    Raises
    ------
    DeckError
        A token that is not a number (line, columns), a count that fits no layout, a volume
        block (IDIM, JDIM, KDIM all > 1), or a binary file.

    Examples
    --------
    >>> geo = read("wing.p3d")                                # doctest: +SKIP
    >>> list(geo.networks)                                    # doctest: +SKIP
    ['block 1', 'block 2']
    """
    raw = read_input(path, "formatted (ASCII) Plot3D grid")
    v = _all_numbers(decode(raw), path)
    if not np.all(np.isfinite(v)):
        raise DeckError(f"number out of range (number {int(np.argmin(np.isfinite(v))) + 1} of "
                        "the file)", path=path)
    found = _layout(v)
    if found is None:
        hint = ""
        if v.size and _posint(v[:1]):
            nblk = int(v[0])
            dims = v[1:1 + 3 * nblk]
            if dims.size == 3 * nblk and _posint(dims):
                size = sum(math.prod(d) for d in dims.reshape(nblk, 3).astype(int).tolist())
                hint = (f" (as multi-block 3-D, NBLK = {nblk} and its dimensions need "
                        f"{1 + 3 * nblk + 3 * size} numbers)")
            else:
                hint = (f" (as multi-block 3-D, NBLK = {nblk} needs {3 * nblk} positive "
                        "integer dimensions next)")
        raise DeckError(f"not a formatted Plot3D grid: {v.size} numbers fit no layout{hint}",
                        path=path)
    name, nd, dims, iblank, pos = found
    networks = {}
    for k, (ni, nj, nk) in enumerate(dims, start=1):
        m = int(ni * nj * nk)
        xyz = [v[pos + c * m:pos + (c + 1) * m] for c in range(nd)]
        if nd == 2:
            xyz.append(np.zeros(m))
        pos += (nd + iblank) * m
        grid = np.stack(xyz, axis=-1).reshape(nk, nj, ni, 3)
        if nk == 1:
            net = grid[0]
        elif nj == 1:
            net = grid[:, 0]
        elif ni == 1:
            net = grid[:, :, 0]
        else:
            raise DeckError(f"block {k} is a volume grid ({ni} x {nj} x {nk}); juncture reads "
                            "surface grids (one of IDIM, JDIM, KDIM equal to 1)", path=path)
        networks[f"block {k}"] = net
    return Geometry(networks=networks, log=(f"read Plot3D {path}: {name}, {len(dims)} blocks"
                                            + (", IBLANK dropped" if iblank else ""),))


def _fmt(values, digits):
    if digits is None:
        return [repr(x) for x in values.tolist()]
    return [format(x, f".{int(digits)}g") for x in values.tolist()]


def write(obj, path, *, mirror=True, digits=None):
    """Write networks as a formatted multi-block Plot3D grid (whole layout, KDIM = 1).

    Parameters
    ----------
    obj : Geometry, Configuration or dict of str to (n_lines, n_points, 3) float
        Anything :func:`juncture.io.to_geometry` accepts.
    path : str or path-like
        The output file; it appears whole or not at all.
    mirror : bool, optional
        Also write the mirror image of every network that has a symmetry plane, as extra
        blocks after the others (:meth:`Geometry.mirrored_networks`). Default True.
    digits : int, optional
        Significant digits; ``None`` (default) writes the shortest exact text (``repr``).

    Notes
    -----
    Block k holds network k with IDIM = n_points, JDIM = n_lines. Names are not written.
    """
    geo = to_geometry(obj)
    nets = list((geo.mirrored_networks() if mirror else dict(geo.networks)).values())
    out = [str(len(nets))]
    out.extend(f"{n.shape[1]} {n.shape[0]} 1" for n in nets)
    for net in nets:
        for c in range(3):
            words = _fmt(net[:, :, c].reshape(-1), digits)
            out.extend(" ".join(words[i:i + _PER_LINE]) for i in range(0, len(words), _PER_LINE))
    with atomic_output(path, "w", encoding="ascii", newline="\n") as fh:
        fh.write("\n".join(out) + "\n")
    return path


def _sniff(head):
    """Only digits and number characters, and leading integers that read as Plot3D dimensions.

    Conservative: the first line holds 1 (NBLK), 2 or 3 (single block) positive integers; with
    NBLK, the next integers (as many as fit in ``head``, at most 3 NBLK) are positive. A title
    line with letters or quotes (wave-drag deck, LaWGS, Hess listing) never matches.
    """
    if not head or not _NUMERIC_HEAD.fullmatch(head):
        return False
    lines = head.decode("ascii").splitlines()
    if len(lines) < 2:
        return False
    first = lines[0].split()
    rest = " ".join(lines[1:-1] if len(head) >= 4096 else lines[1:]).split()
    if len(first) not in (1, 2, 3) or not all(t.isdigit() and int(t) >= 1 for t in first):
        return False
    if len(first) == 1:
        want = rest[:3 * int(first[0])]
        return bool(want) and all(t.isdigit() and int(t) >= 1 for t in want)
    return True


register_format("plot3d", [".p3d", ".xyz", ".g"], reader=read, writer=write, sniff=_sniff)
