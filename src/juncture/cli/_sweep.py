"""``juncture sweep``: a design study, one row of numbers per case, on a pool or a cluster."""

from __future__ import annotations

__all__ = ["add_parser", "run"]


def add_parser(sub, common):
    """The ``sweep`` sub-command's parser."""
    from ._parser import _count

    s = sub.add_parser("sweep", parents=[common],
                       help="run a design study (TOML spec) and write one row per case")
    s.add_argument("spec", help="sweep spec (TOML): base deck and parameters to vary")
    s.add_argument("-o", "--output", default="sweep.parquet",
                   help="results, .parquet or .csv (default: sweep.parquet); finished cases "
                   "are kept in <output>.journal.jsonl as they come, so a sweep run again "
                   "goes on where it stopped")
    s.add_argument("--workers", type=_count(1, 1024, "a number of workers"), default=1,
                   help="local worker processes (default: 1, in this process)")
    s.add_argument("--dask", metavar="ADDRESS",
                   help="run on the Dask scheduler at ADDRESS (tcp://host:8786), or 'local' "
                   "for a LocalCluster of --workers processes")
    s.add_argument("--restart", action="store_true",
                   help="forget finished cases and run every case again")
    s.add_argument("--figures", action="store_true",
                   help="also write figures (D/q and volume against each parameter, a "
                   "scatter matrix) and an HTML report beside the results")
    s.add_argument("--dry-run", action="store_true",
                   help="check the spec and list the cases without running them")
    return s


def _client(address, workers):
    if address is None or address == "local":
        return address
    from ..study.run import _need

    distributed = _need("distributed", "--dask")
    try:
        return distributed.Client(address, timeout="5s")
    except OSError as exc:
        from ..errors import JunctureError

        raise JunctureError(f"--dask {address}: cannot reach the scheduler ({exc})") from None


def run(args, progress):
    """Check the spec, run the cases not yet in the journal, write the results."""
    from ..study import load_spec, sweep
    from ..study.run import journal_path

    spec = load_spec(args.spec)
    quiet = getattr(args, "quiet", False)
    if args.dry_run:
        cases = spec.cases()
        names = ", ".join(p.name for p in spec.parameters) or "no parameter"
        print(f"{args.spec}: {len(cases)} cases of {names}")
        for i, case in enumerate(cases[:20]):
            print(f"  {i:5d} {spec.key(case)}  " + ", ".join(f"{k}={v}" for k, v in case.items()))
        if len(cases) > 20:
            print(f"  ... {len(cases) - 20} more")
        return 0
    client = _client(args.dask, args.workers)
    try:
        frame = sweep(spec, args.output, workers=args.workers, client=client,
                      progress=None if not quiet else False, restart=args.restart,
                      figures=args.figures)
    finally:
        if client is not None and client != "local":
            client.close()
    if not quiet:
        ok = int((frame["status"] == "ok").sum())
        print(f"{len(frame)} cases: {ok} ok, {len(frame) - ok} error; wrote {args.output} "
              f"(journal {journal_path(args.output).name})")
        errors = frame.loc[frame["status"] != "ok", "error"].value_counts()
        for message, count in errors[:5].items():
            print(f"  error x{count}: {message}")
    return 0
