"""Running a sweep: cases on a process pool or a Dask cluster, rows streamed to a journal.

Each finished case is appended at once to the journal beside the output
(``results.parquet.journal.jsonl``, one JSON row per line, flushed), so an interrupted
sweep loses nothing it finished: run again, and the cases whose key (:meth:`SweepSpec.key`)
is in the journal are not run again. When every case has its row, the results are written
in case order, atomically, as Parquet or CSV (by extension); the journal stays, so that a
sweep extended later (more values, another Mach number in a new column...) reuses what it can.

Workers never share state with each other or with this process: each case reads the base
from the spec's bytes, runs under one BLAS thread (threadpoolctl), and returns a plain row,
so the numbers do not depend on the number or kind of workers (``wall_time`` does).
At most two cases per worker are in flight: memory stays bounded however long the sweep.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

from ..errors import JunctureError, MissingDependencyError, SpecError
from .case import columns, run_case
from .spec import SweepSpec, load_spec

__all__ = ["sweep", "journal_path", "read_journal"]

_FORMATS = {".parquet": "parquet", ".csv": "csv"}


def journal_path(output):
    """The journal of the sweep written to ``output``."""
    output = Path(output)
    return output.with_name(output.name + ".journal.jsonl")


def read_journal(path):
    """Rows of a journal by key (a line cut short by a kill is skipped)."""
    rows = {}
    path = Path(path)
    if not path.is_file():
        return rows
    with open(path) as fh:
        for line in fh:
            try:
                row = json.loads(line)
            except json.JSONDecodeError:
                continue
            if isinstance(row, dict) and "key" in row:
                rows[row["key"]] = row
    return rows


def _need(module, what):
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError:
        raise MissingDependencyError(f"{what} needs {module.split('.')[0]}: install the sweep "
                                     "extra (pip install 'juncture[sweep]')") from None


def _check_targets(spec):
    """Every parameter's components exist in the base and take its field (else SpecError)."""
    from ..model import Configuration
    from .case import _base
    from .edit import check_target

    cfg = _base(spec)
    if not isinstance(cfg, Configuration):
        raise SpecError(f"base {spec.base}: holds surface networks, not components; a sweep "
                        "starts from a deck or a juncture model")
    for p in spec.parameters:
        if p.kind == "component":
            check_target(cfg, p)


def _in_process(tasks):
    for spec, index, case in tasks:
        yield run_case(spec, index, case)


def _pool(tasks, workers):
    import concurrent.futures as cf
    import multiprocessing

    tasks = iter(tasks)
    pool = cf.ProcessPoolExecutor(max_workers=workers,
                                  mp_context=multiprocessing.get_context("spawn"))
    running = set()
    try:
        while True:
            for task in tasks:
                running.add(pool.submit(run_case, *task))
                if len(running) >= 2 * workers:
                    break
            if not running:
                return
            done, running = cf.wait(running, return_when=cf.FIRST_COMPLETED)
            for fut in done:
                yield fut.result()
    finally:
        # an interrupted sweep stops at once; a finished one has nothing left to wait for
        pool.shutdown(wait=not running, cancel_futures=True)


def _dask(tasks, client, workers):
    distributed = _need("distributed", "a sweep on Dask")
    tasks = iter(tasks)
    first = next(tasks, None)
    if first is None:
        return
    spec = client.scatter(first[0], broadcast=True)
    slots = 2 * max(workers, len(client.scheduler_info().get("workers", {})) or 1)
    queue = distributed.as_completed()
    pending = [first] + [t for _, t in zip(range(slots - 1), tasks)]
    for _, index, case in pending:
        queue.add(client.submit(run_case, spec, index, case, pure=False))
    try:
        for fut in queue:
            row = fut.result()
            fut.release()
            nxt = next(tasks, None)
            if nxt is not None:
                queue.add(client.submit(run_case, spec, nxt[1], nxt[2], pure=False))
            yield row
    finally:
        for fut in list(queue.futures):
            fut.cancel()


def _local_cluster(workers):
    distributed = _need("distributed", "--dask local")
    cluster = distributed.LocalCluster(n_workers=max(workers, 1), threads_per_worker=1,
                                       processes=True, dashboard_address=None)
    return cluster, distributed.Client(cluster)


def _progress(total, done, enabled):
    if enabled is None:
        enabled = sys.stderr.isatty()
    if not enabled or total == 0:
        return None
    from tqdm import tqdm

    return tqdm(total=total, initial=done, desc="sweep", unit="case", file=sys.stderr,
                dynamic_ncols=True, leave=False)


def _clean(value):
    """A row value as JSON keeps it (numpy scalars to Python, NaN kept)."""
    return value.item() if hasattr(value, "item") else value


def sweep(spec, output=None, workers=1, client=None, progress=None, restart=False,
          figures=False):
    """Run every case of a sweep spec and return the results as a pandas DataFrame.

    Parameters
    ----------
    spec : str, path-like or SweepSpec
        A TOML sweep spec (:mod:`juncture.study.spec`) or a parsed one.
    output : str or path-like, optional
        ``.parquet`` or ``.csv``: the results, written atomically once every case has a row;
        the journal beside it (:func:`journal_path`) receives each row as it finishes and
        lets a later run skip finished cases. None: nothing is written.
    workers : int
        Local processes (1: in this process); with ``client``, the cases kept in flight
        per worker follow the cluster's size.
    client : distributed.Client or "local", optional
        Run on this Dask cluster; ``"local"`` starts a LocalCluster of ``workers``
        single-threaded processes (at least one) for the sweep and closes it afterwards.
    progress : bool, optional
        Draw a progress bar on standard error (None: when it is a terminal).
    restart : bool
        Forget the journal and run every case again.
    figures : bool
        With ``output``: also write the figures and the HTML report beside it
        (``<output stem>_figures/``, ``<output stem>.html``).

    Returns
    -------
    pandas.DataFrame
        One row per case in the spec's order (columns: :func:`juncture.study.case.columns`).
    """
    pandas = _need("pandas", "sweep results")
    spec = spec if isinstance(spec, SweepSpec) else load_spec(spec)
    fmt = None
    if output is not None:
        output = Path(output)
        fmt = _FORMATS.get(output.suffix.lower())
        if fmt is None:
            raise JunctureError(f"{output}: expected a .parquet or .csv file name for the "
                                "results")
        if fmt == "parquet":
            _need("pyarrow", "Parquet output")
        if not output.parent.is_dir():
            raise JunctureError(f"cannot write {output}: the directory {output.parent} does "
                                "not exist")
    _check_targets(spec)
    cases = spec.cases()
    keys = [spec.key(c) for c in cases]
    journal = journal_path(output) if output is not None else None
    if journal is not None and restart and journal.exists():
        journal.unlink()
    rows = read_journal(journal) if journal is not None else {}
    todo, seen = [], set(rows)
    for i, (case, key) in enumerate(zip(cases, keys)):
        if key not in seen:
            seen.add(key)
            todo.append((spec, i, case))
    rows = _run(todo, rows, journal, workers, client, progress, len(set(keys)))
    frame = _frame(pandas, spec, cases, keys, rows)
    if output is not None:
        _write(frame, output, fmt)
        if figures:
            write_sweep_outputs(frame, spec, output)
    return frame


def _run(todo, rows, journal, workers, client, progress, total):
    """Run ``todo``, appending each row to the journal (if any) as it comes."""
    bar = _progress(total, total - len(todo), progress)
    owned = None
    fh = None
    try:
        if client == "local":
            owned, client = _local_cluster(workers)
        if client is not None:
            stream = _dask(todo, client, workers)
        elif workers > 1 and len(todo) > 1:
            stream = _pool(todo, workers)
        else:
            stream = _in_process(todo)
        if journal is not None:
            fh = open(journal, "a")
        for row in stream:
            row = {k: _clean(v) for k, v in row.items()}
            if fh is not None:
                fh.write(json.dumps(row) + "\n")
                fh.flush()
            rows[row["key"]] = row
            if bar is not None:
                bar.update(1)
    finally:
        if fh is not None:
            fh.close()
        if bar is not None:
            bar.close()
        if owned is not None:
            client.close()
            owned.close()
    return rows


def _frame(pandas, spec, cases, keys, rows):
    names = columns(spec)
    out = []
    for i, key in enumerate(keys):
        row = dict(rows[key])
        row["case"] = i
        out.append([row.get(c, math.nan) for c in names])
    return pandas.DataFrame(out, columns=names)


def _write(frame, output, fmt):
    from ..io._registry import atomic_path

    with atomic_path(output) as tmp:
        if fmt == "parquet":
            frame.to_parquet(tmp, index=False)
        else:
            frame.to_csv(tmp, index=False)


def write_sweep_outputs(frame, spec, output):
    """Figures and the HTML report of a sweep beside its results file; returns their paths."""
    from ..plots.sweep import write_sweep_figures, write_sweep_report

    output = Path(output)
    names = [p.name for p in spec.parameters]
    fig_dir = output.with_name(output.stem + "_figures")
    fig_dir.mkdir(exist_ok=True)
    figs = write_sweep_figures(frame, names, fig_dir)
    report = write_sweep_report(frame, names, output.with_suffix(".html"), figures=figs,
                                title=spec.title, spec_text=spec.text)
    return [*figs, report]
