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
           "to_geometry", "read_input", "require_configuration", "extensions",
           "reader_formats", "writer_formats", "writer_extensions", "output_format"]


@dataclass(frozen=True, slots=True)
class _Format:
    name: str
    extensions: tuple
    reader: Callable | None
    writer: Callable | None
    sniff: Callable | None  # (head: bytes) -> bool
    write_extensions: tuple = ()


_FORMATS: dict[str, _Format] = {}


def register_format(name, extensions, reader=None, writer=None, sniff=None,
                    write_extensions=None):
    """Register a format under ``name`` with its file extensions (``".wgs"``) and functions.

    ``reader(path, **kw)`` returns a Configuration or Geometry; ``writer(obj, path, **kw)``
    writes one; ``sniff(head: bytes) -> bool`` says whether a file's first 4 kB look like it.
    ``write_extensions`` (default: ``extensions``) are those the writer is chosen by.
    """
    exts = tuple(e.lower() for e in extensions)
    wexts = exts if write_extensions is None else tuple(e.lower() for e in write_extensions)
    _FORMATS[name] = _Format(name, exts, reader, writer, sniff, wexts if writer else ())


def formats():
    """Names of all registered formats."""
    return sorted(_FORMATS)


def reader_formats():
    """Names of formats that can be read."""
    return sorted(n for n, f in _FORMATS.items() if f.reader is not None)


def writer_formats():
    """Names of formats that can be written."""
    return sorted(n for n, f in _FORMATS.items() if f.writer is not None)


def writer_extensions():
    """Extensions (without the dot) of every format that can be written, sorted."""
    return sorted({e.lstrip(".") for f in _FORMATS.values() for e in f.write_extensions})


def extensions(kind="read"):
    """Extensions that choose a reader (``kind="read"``) or writer (``"write"``), for messages.

    One string, ``".wgs .lawgs (lawgs); .p3d .xyz .g (plot3d); ..."``.
    """
    out = []
    for name in sorted(_FORMATS):
        f = _FORMATS[name]
        exts = f.write_extensions if kind == "write" else (f.extensions if f.reader else ())
        if exts:
            out.append(f"{' '.join(exts)} ({name})")
    return "; ".join(out)


def _by_extension(path, kind="read"):
    name = Path(path).name.lower()

    def exts(f):
        return f.write_extensions if kind == "write" else f.extensions

    hits = [f for f in _FORMATS.values() for e in exts(f) if name.endswith(e)]
    return sorted(hits, key=lambda f: -max(len(e) for e in exts(f) if name.endswith(e)))


def output_format(path):
    """Name of the format a file written to ``path`` would have (by extension), or None."""
    hits = _by_extension(path, "write")
    return hits[0].name if hits else None


def _get(fmt):
    try:
        return _FORMATS[fmt]
    except KeyError:
        raise JunctureError(f"unknown format {fmt!r}; known formats: {', '.join(formats())}") \
            from None


def _sniffs(f, head):
    """``f.sniff(head)``; a sniffer that fails on odd bytes says no (it is only a guess)."""
    try:
        return bool(f.sniff(head))
    except Exception:  # noqa: BLE001 - any failure of a heuristic means "not this format"
        return False


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
        raise _open_error(path, exc, "file") from None
    candidates = [f for f in _FORMATS.values() if f.reader is not None]
    sniffed = [f for f in candidates if f.sniff is not None and _sniffs(f, head)]
    by_ext = [f for f in _by_extension(path) if f.reader is not None]
    # A sniffer that agrees with the extension wins; else the first sniffer; else the extension.
    agreed = [f for f in sniffed if f in by_ext]
    chosen = (agreed or sniffed or by_ext or [None])[0]
    if chosen is None:
        given = f"extension {path.suffix!r}" if path.suffix else "no extension"
        raise DeckError(f"cannot tell the format from the content or the file name ({given}); "
                        f"juncture reads {extensions('read')}", path=path)
    return chosen.reader(path, **kwargs)


def write(obj, path, format=None, **kwargs):
    """Write ``obj`` (Geometry, Configuration or a dict of networks) to ``path``.

    The format is ``format`` if given, else the file extension (``.wgs``, ``.p3d``, ``.hess``,
    ``.stl``, ``.vtk``, ``.vtu``, ``.obj``, ``.inp``, ``.json``, ``.step``, ``.igs``). The file
    appears whole or not at all.

    Raises
    ------
    JunctureError
        An unknown extension (the message lists the known ones), an object the format cannot
        hold (a Geometry to a wave-drag deck), or a path that cannot be written.
    """
    if format is not None:
        f = _get(format)
    else:
        hits = _by_extension(path, "write")
        if not hits:
            suffix = Path(path).suffix
            if _by_extension(path, "read"):
                why = f"juncture reads {suffix!r} files but does not write them"
            elif suffix:
                why = f"unknown output extension {suffix!r}"
            else:
                why = "no extension to tell the output format by"
            raise JunctureError(f"{path}: {why}; juncture writes {extensions('write')}")
        f = hits[0]
    if f.writer is None:
        raise JunctureError(f"format {f.name!r} can be read but not written")
    return f.writer(obj, Path(path), **kwargs)


def _open_error(path, exc, expected):
    """The DeckError for an input that cannot be opened (``exc``: the OSError)."""
    if Path(path).is_dir():
        return DeckError(f"is a directory: expected a {expected}", path=path)
    return DeckError(f"cannot open file: {exc.strerror or exc}", path=path)


def read_input(path, expected):
    """The bytes of an input file for a text reader; DeckError if it cannot be one.

    ``expected`` names what the file should be (``"LaWGS file"``), for the messages: the file
    cannot be opened (missing, a directory, no permission), is empty (only blanks), or holds
    binary data (a NUL byte in its first 4 kB; no text format juncture reads has one).
    """
    try:
        with open(path, "rb") as fh:
            raw = fh.read()
    except OSError as exc:
        raise _open_error(path, exc, expected) from None
    if not raw.strip():
        raise DeckError(f"empty file: expected a {expected}", path=path)
    nul = raw.find(b"\x00", 0, 4096)
    if nul >= 0:
        raise DeckError(f"binary data (a NUL byte at offset {nul}): expected a {expected}",
                        path=path)
    return raw


@contextlib.contextmanager
def atomic_path(path, suffix=".tmp"):
    """Yield a temporary path beside ``path``; rename it onto ``path`` only on success.

    For writers that need a file name (meshio, OCP) rather than an open file. On any exception
    the temporary file is removed and ``path`` is left as it was; an ``OSError`` (no such
    directory, ``path`` a directory, no permission, disk full) becomes a
    :class:`~juncture.errors.JunctureError` naming ``path``.
    """
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    if path.is_dir():
        raise JunctureError(f"cannot write {path}: it is a directory; give a file name")
    if not directory.is_dir():
        why = (f"{directory} is a file, not a directory" if directory.exists()
               else f"the directory {directory} does not exist")
        raise JunctureError(f"cannot write {path}: {why}")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=suffix, dir=directory)
    except OSError as exc:
        raise JunctureError(f"cannot write {path}: {exc.strerror or exc}") from None
    os.close(fd)
    try:
        yield tmp
        # mkstemp creates the file 0600; give it the permissions a plain open() would.
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)
        os.replace(tmp, path)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise JunctureError(f"cannot write {path}: {exc.strerror or exc}") from None
        raise


@contextlib.contextmanager
def atomic_output(path, mode="w", **open_kwargs):
    """Open a temporary file beside ``path``; rename it onto ``path`` only if the block succeeds.

    Yields the open file object. On any exception the temporary file is removed and ``path``
    is left as it was: never a half-written output file.
    """
    with atomic_path(path) as tmp, open(tmp, mode, **open_kwargs) as fh:
        yield fh


def require_configuration(obj, path, fmt):
    """``obj`` if it is a Configuration, else a JunctureError: ``fmt`` holds components."""
    from ..geometry import Geometry
    from ..model import Configuration

    if isinstance(obj, Configuration):
        return obj
    what = ("surface networks (a Geometry, as read from LaWGS, Plot3D or Hess; write those to "
            ".wgs, .p3d, .hess, .stl, .vtk, .vtu, .obj, .step or .igs)"
            if isinstance(obj, Geometry | dict) else f"a {type(obj).__name__}")
    raise JunctureError(f"cannot write {path}: a {fmt} holds components (a Configuration, as "
                        f"read from a wave-drag deck or a juncture JSON/TOML model), not {what}")


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
