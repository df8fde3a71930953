"""Design studies: run many variants of one airplane and collect one row of numbers per case.

``juncture sweep SPEC -o results.parquet`` and :func:`sweep` read a TOML spec (a base deck
and the parameters to vary, :mod:`juncture.study.spec`), edit the base for each case
(:mod:`juncture.study.edit`), complete and analyse it (:mod:`juncture.study.case`) on a
local process pool or a Dask cluster, and stream each row to disk as it finishes
(:mod:`juncture.study.run`). pandas (and pyarrow for Parquet, distributed for Dask) come
with the ``sweep`` extra: ``pip install 'juncture[sweep]'``.
"""

from .run import journal_path, read_journal, sweep, write_sweep_outputs
from .spec import Parameter, SweepSpec, load_spec, parse_spec

__all__ = ["sweep", "load_spec", "parse_spec", "SweepSpec", "Parameter", "journal_path",
           "read_journal", "write_sweep_outputs"]
