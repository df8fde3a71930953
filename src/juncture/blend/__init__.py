"""Song, Ma & Wang (2008) long-strake wing-body blend: G1 patches R1, R2 and W.

Build with :func:`build_blend` (a spec path or dict), sample with :func:`blend_geometry`,
check with :func:`g1_report`, or do everything ``juncture blend SPEC -o DIR`` does with
:func:`run`. See ``docs/blend.md``.
"""

from .report import g1_report
from .run import BlendModel, blend_geometry, build_blend, run
from .spec import load_spec

__all__ = ["BlendModel", "build_blend", "blend_geometry", "g1_report", "load_spec", "run"]
