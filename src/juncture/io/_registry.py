"""Format registry: extension -> formats, format -> reader / writer / sniffer (meshio pattern).

Each ``io/<format>.py`` calls :func:`register_format` in its last lines; ``io/__init__.py``
imports them all. :func:`read` lets an explicit format win, then asks every format's sniffer
about the first bytes of the file, and only then goes by the extension.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..errors import DeckError, JunctureError

__all__ = ["register_format", "read", "write", "formats", "atomic_output", "atomic_path",
           "to_geometry",
           "reader_formats", "writer_formats"]


@dataclass(frozen=True, slots=True)
class _Format:
    name: str
    extensions: tuple
    reader: Callable | None
    writer: Callable | None
    sniff: Callable | None  # (head: bytes) -> bool


_FORMATS: dict[str, _Format] = {}


def register_format(name, extensions, reader=None, writer=None, sniff=None):
    """Register a format under ``name`` with its file extensions (``".wgs"``) and functions.

    ``reader(path, **kw)`` returns a Configuration or Geometry; ``writer(obj, path, **kw)``
    writes one; ``sniff(head: bytes) -> bool`` says whether a file's first 4 kB look like it.
    """
    _FORMATS[name] = _Format(name, tuple(e.lower() for e in extensions), reader, writer, sniff)


def formats():
    """Names of all registered formats."""
    return sorted(_FORMATS)


def reader_formats():
    """Names of formats that can be read."""
    return sorted(n for n, f in _FORMATS.items() if f.reader is not None)


def writer_formats():
    """Names of formats that can be written."""
    return sorted(n for n, f in _FORMATS.items() if f.writer is not None)


def _by_extension(path):
    name = Path(path).name.lower()
    hits = [f for f in _FORMATS.values() for e in f.extensions if name.endswith(e)]
    return sorted(hits, key=lambda f: -max(len(e) for e in f.extensions if name.endswith(e)))


def _get(fmt):
    try:
        return _FORMATS[fmt]
    except KeyError:
        raise JunctureError(f"unknown format {fmt!r}; known formats: {', '.join(formats())}") \
            from None


def read(path, format=None, **kwargs):
    """Read a geometry file; the format is ``format``, else sniffed from content, else extension.

    Parameters
    ----------
    path : str or path-like
        The file to read.
    format : str, optional
        A registered format name (see :func:`formats`), e.g. ``"wavedrag"``, ``"lawgs"``.

    Returns
    -------
    Configuration or Geometry
        A Configuration for component descriptions (wave-drag deck, juncture JSON), a Geometry
        for surface networks (LaWGS, Plot3D).

    Raises
    ------
    DeckError
        If the file cannot be opened, its format cannot be told, or its content is malformed.
    """
    path = Path(path)
    if format is not None:
        f = _get(format)
        if f.reader is None:
            raise JunctureError(f"format {format!r} can be written but not read")
        return f.reader(path, **kwargs)
    try:
        with open(path, "rb") as fh:
            head = fh.read(4096)
    except OSError as exc:
        raise DeckError(f"cannot open file: {exc.strerror}", path=path) from None
    candidates = [f for f in _FORMATS.values() if f.reader is not None]
    sniffed = [f for f in candidates if f.sniff is not None and f.sniff(head)]
    by_ext = [f for f in _by_extension(path) if f.reader is not None]
    # A sniffer that agrees with the extension wins; else the first sniffer; else the extension.
    agreed = [f for f in sniffed if f in by_ext]
    chosen = (agreed or sniffed or by_ext or [None])[0]
    if chosen is None:
        raise DeckError("cannot tell the format from the content or the extension; known "
                        f"readable formats: {', '.join(reader_formats())}", path=path)
    return chosen.reader(path, **kwargs)


def write(obj, path, format=None, **kwargs):
    """Write ``obj`` (Geometry, Configuration or a dict of networks) to ``path``.

    The format is ``format`` if given, else the file extension (``.wgs``, ``.p3d``, ``.hess``,
    ``.stl``, ``.vtk``, ``.inp``, ``.step``, ``.igs``). The file appears whole or not at all.
    """
    if format is not None:
        f = _get(format)
    else:
        hits = [f for f in _by_extension(path) if f.writer is not None]
        if not hits:
            raise JunctureError(f"cannot tell the output format of {str(path)!r} from its "
                                f"extension; writable formats: {', '.join(writer_formats())}")
        f = hits[0]
    if f.writer is None:
        raise JunctureError(f"format {f.name!r} can be read but not written")
    return f.writer(obj, Path(path), **kwargs)


@contextlib.contextmanager
def atomic_path(path, suffix=".tmp"):
    """Yield a temporary path beside ``path``; rename it onto ``path`` only on success.

    For writers that need a file name (meshio, OCP) rather than an open file. On any exception
    the temporary file is removed and ``path`` is left as it was.
    """
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=suffix, dir=directory)
    os.close(fd)
    try:
        yield tmp
        # mkstemp creates the file 0600; give it the permissions a plain open() would.
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


@contextlib.contextmanager
def atomic_output(path, mode="w", **open_kwargs):
    """Open a temporary file beside ``path``; rename it onto ``path`` only if the block succeeds.

    Yields the open file object. On any exception the temporary file is removed and ``path``
    is left as it was: never a half-written output file.
    """
    with atomic_path(path) as tmp, open(tmp, mode, **open_kwargs) as fh:
        yield fh


def to_geometry(obj):
    """Coerce a Geometry, a Configuration or a mapping of networks to a Geometry."""
    from ..geometry import Geometry

    if isinstance(obj, Geometry):
        return obj
    to_geo = getattr(obj, "to_geometry", None)
    if callable(to_geo):
        return to_geo()
    if isinstance(obj, dict):
        return Geometry(networks=obj)
    raise JunctureError(f"cannot write an object of type {type(obj).__name__}; expected a "
                        "Geometry, a Configuration or a dict of networks")
