"""Readers and writers, one module per format, dispatched by content or extension.

See ``docs/formats.md`` for the formats. Importing this package registers
every format module.
"""

from ._registry import (
    atomic_output,
    formats,
    output_format,
    read,
    reader_formats,
    to_geometry,
    write,
    writer_extensions,
    writer_formats,
)

__all__ = ["read", "write", "formats", "reader_formats", "writer_formats", "writer_extensions",
           "output_format", "atomic_output", "to_geometry"]

# Each import registers its format(s) in its last lines.
import importlib as _importlib

for _name in ("wavedrag", "lawgs", "plot3d", "hess", "mesh", "cad", "jsonmodel"):
    try:
        _importlib.import_module(f"{__name__}.{_name}")
    except ModuleNotFoundError as _exc:  # a format module not written yet
        if _exc.name != f"{__name__}.{_name}":
            raise
