"""The ``juncture`` command: thin wrappers that parse, call the public API and print.

Bad input never gives a traceback: a :class:`~juncture.errors.JunctureError`, an unreadable
or unwritable file and a usage error each become one line on stderr and exit status 2;
``--debug`` shows the traceback instead. Warnings are one line each (``juncture: warning:``).
A progress bar is drawn on stderr for the long steps when it is a terminal, unless
``--quiet``.
"""

from __future__ import annotations

import sys
import warnings

__all__ = ["main", "bundled_example"]


def bundled_example(name="supersonic_transport.inp"):
    """Path of a bundled example file (package data)."""
    from importlib import resources
    from pathlib import Path

    return Path(str(resources.files("juncture") / "data" / name))


def _command_table():
    from . import _check, _mesh, _sweep
    from . import _commands as c
    from ._demo import demo

    return {"info": c.info, "convert": c.convert, "complete": c.complete,
            "wavedrag": c.wavedrag, "massprops": c.massprops, "blend": c.blend, "demo": demo,
            "mesh": _mesh.run, "sweep": _sweep.run, "check": _check.run}


def _oserror(exc):
    name = exc.filename if exc.filename is not None else ""
    what = exc.strerror or type(exc).__name__
    return f"{name}: {what}" if name else f"{what}: {exc}"


def _show_warning(seen):
    def show(message, category, filename, lineno, file=None, line=None):
        text = " ".join(str(message).split())
        if text not in seen:
            seen.add(text)
            print(f"juncture: warning: {text}", file=sys.stderr)
    return show


def _run(args):
    from functools import partial

    from .._progress import Progress

    quiet = getattr(args, "quiet", False)
    progress = partial(Progress, enabled=False) if quiet else Progress
    return int(_command_table()[args.command](args, progress) or 0)


def main(argv=None) -> int:
    """Run the command line; returns the exit status (0 ok, 2 bad input, 1 internal error)."""
    from .. import __version__
    from ..errors import JunctureError
    from ._parser import build_parser

    argv = sys.argv[1:] if argv is None else list(argv)
    if argv == ["--version"]:  # answered before the parser loads the format registry
        print(f"juncture {__version__}")
        return 0
    try:
        args = build_parser(__version__).parse_args(argv)
    except SystemExit as exc:  # --help, --version, or a usage error already printed
        return exc.code if isinstance(exc.code, int) else 2
    debug = getattr(args, "debug", False)
    old = warnings.showwarning
    warnings.showwarning = _show_warning(set())
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("always")
            warnings.filterwarnings("ignore", category=ResourceWarning)
            return _run(args)
    except JunctureError as exc:
        if debug:
            raise
        print(f"juncture: error: {' '.join(str(exc).split())}", file=sys.stderr)
        return 2
    except OSError as exc:
        if debug:
            raise
        print(f"juncture: error: {_oserror(exc)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("juncture: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # a bug: say so in one line, and how to see more
        if debug:
            raise
        print(f"juncture: internal error: {type(exc).__name__}: {' '.join(str(exc).split())} "
              f"(a bug in juncture: run again with --debug for the traceback and report it)",
              file=sys.stderr)
        return 1
    finally:
        warnings.showwarning = old
