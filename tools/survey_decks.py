"""Survey: what juncture does today with generated airplanes (issue 11, the baseline).

Draws N decks from ``tests.deckgen.decks()`` with a fixed hypothesis seed and runs each
through ``juncture.complete`` with a matrix of options: fillet none / cubic / circular, with
``keep_area`` off and (with a fillet) on, each with the default layout and ``blocks=6``, and
each once more with ``single_network=True`` (15 runs per deck). Every run is classified:

- ``ok``: completed, and every independent check holds;
- ``defects``: completed, but a check fails (each failing check counted in its class):
  intersection points off either surface by more than 1e-9 of the fuselage length (against
  the deck's own numbers, see ``tests/deckgen``, and against juncture's model of the
  fuselage or pod), NaN or inf in a network, fillet or station, fillet points inside the
  fuselage or the wing (deeper than 1e-6 L), a canard, tail or fin network inside the
  fuselage it meets (deeper than 1e-6 L), a ``keep_area`` residual above 1e-6, a
  re-designed fuselage larger than the original;
- ``JunctureError``: by message class (numbers replaced by ``#``);
- ``crash``: any other exception, by type and the innermost juncture frame (file:line);
- ``timeout``.

Notes (not defects) count intersection lines with points not found (NaN, documented for a
lofting line that misses) and pairs found that the deck was not drawn to have.

Usage::

    .venv/bin/python tools/survey_decks.py --n 200 --seed 0 --save survey-out

prints the table and saves, per class, the first deck that shows it (``DIR/<class>.inp``)
with a JSON file beside it (description, options, message, traceback).
"""

from __future__ import annotations

import argparse
import collections
import hashlib
import json
import math
import multiprocessing
import os
import re
import signal
import sys
import tempfile
import time
import traceback
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

TOL_POINT = 1e-9  # intersection points on both surfaces, relative to the fuselage length
TOL_FILLET = 1e-6  # fillet points inside the fuselage or the wing, relative to the length
TOL_RESIDUAL = 1e-6  # keep_area relative area residual
TIMEOUT = 120  # seconds per run


def option_sets():
    """The 15 option sets run on every deck: (label, keyword arguments of complete)."""
    out = []
    for fillet, keep in ((None, False), ("cubic", False), ("cubic", True),
                         ("circular", False), ("circular", True)):
        base = f"{fillet or 'none'}{'+keep_area' if keep else ''}"
        for blocks in (None, 6):
            out.append((base + ("" if blocks is None else " blocks=6"),
                        dict(fillet=fillet, keep_area=keep, blocks=blocks)))
        out.append((base + " single_network", dict(fillet=fillet, keep_area=keep,
                                                   single_network=True)))
    return out


def draw_decks(n, seed):
    """``n`` decks from the ``decks()`` strategy, deterministic for ``seed`` (whatever else
    is loaded)."""
    from hypothesis import HealthCheck, Phase, given, settings
    from hypothesis import seed as hseed

    from tests.deckgen import decks

    drawn = []

    @hseed(seed)
    @settings(max_examples=n, database=None, phases=[Phase.generate], deadline=None,
              suppress_health_check=list(HealthCheck))
    @given(decks())
    def collect(example):
        drawn.append(example)

    # hypothesis (>= 6.131) also draws the literals of the local modules loaded at the time:
    # without this the same seed gave other decks to a script that had imported more of
    # juncture, or whose code had other constants
    from hypothesis.internal.conjecture import providers

    local, providers._get_local_constants = providers._get_local_constants, providers.Constants
    providers.CONSTANTS_CACHE.cache.clear()
    try:
        collect()
    finally:
        providers._get_local_constants = local
        providers.CONSTANTS_CACHE.cache.clear()
    return drawn[:n]


def message_class(message):
    """A JunctureError message with its numbers and file paths taken out."""
    text = re.sub(r"^\S+\.inp, ", "", str(message))
    text = re.sub(r"[-+]?\d+(\.\d+)?([eE][-+]?\d+)?", "#", text)
    return text[:140]


def crash_location(exc):
    """The innermost frame of the juncture package, as ``path:line in function``."""
    frames = traceback.extract_tb(exc.__traceback__)
    mine = [f for f in frames if "/juncture/" in f.filename.replace(os.sep, "/")]
    f = (mine or frames)[-1]
    path = f.filename.replace(os.sep, "/")
    path = path[path.find("src/juncture"):] if "src/juncture" in path else path
    return f"{path}:{f.lineno} in {f.name}"


def _role(description, name):
    comp = description["components"][name]
    if comp["kind"] == "fin":
        return f"{comp['role']} fin" if comp["role"] != "pylon" else "pylon"
    if name == "body":
        return f"{comp['kind']} fuselage"
    return comp["kind"]


def check_geometry(geo, description, keep_area, single_network=False, fillet=None):
    """Defect classes (with their size) and notes of a completed geometry."""
    import numpy as np

    from tests.deckgen import fillet_depths, intersection_offsets

    defects, notes = [], []
    for name, net in geo.networks.items():
        if not np.isfinite(net).all():
            defects.append((f"non-finite network ({name.split()[0]})", math.inf))
    if any(not np.isfinite(pts).all() for pts in geo.fillets.values()):
        defects.append(("non-finite fillet points", math.inf))
    for key, val in geo.stations.items():
        if not np.isfinite(val).all():
            defects.append((f"non-finite stations[{key!r}]", math.inf))
    redesigned = ("body",) if keep_area else ()
    # Without a fillet, the single network's lower line is re-interpolated at the upper x.
    moved = ("wing/body lower",) if single_network and fillet is None else ()
    for row in intersection_offsets(geo, description, redesigned, moved):
        a, b = _role(description, row["a"]), _role(description, row["b"])
        pair = f"{a}/{b}"
        if not row["meant"]:
            notes.append(f"pair not drawn to touch found: {pair}")
            pair += " (a pair not drawn to touch)"
        if row["nan"]:
            notes.append(f"lines not found (NaN points): {a}/{b}")
        if row["a_deck"] > TOL_POINT:
            where = ("surface (re-interpolated single-network lower line)"
                     if row["name"] in moved else "lofting lines")
            defects.append((f"intersection off the {a} {where}: {pair}", row["a_deck"]))
        for key, what in (("b_deck", "deck"), ("b_gap", "deck, in a gap between segments"),
                          ("b_step", "deck, on a joint step between segments"),
                          ("b_end", "deck, at an end station")):
            if row[key] > TOL_POINT:
                defects.append((f"intersection off the {b} ({what}): {pair}", row[key]))
        for key, what in (("b_own", "juncture's model"),
                          ("b_own_jump", "juncture's model, on a joint step or an end")):
            if row[key] is not None and row[key] > TOL_POINT:
                defects.append((f"intersection off the {b} ({what}): {pair}", row[key]))
    body = geo.configuration["body"]
    for name, comp in description["components"].items():
        if comp["kind"] in ("canard", "tail", "fin") and "body" in comp.get("touches", ()):
            nets = [np.asarray(v) for k, v in geo.networks.items() if k.startswith(name + " ")]
            depth = max((-body.signed_distance(n).min() for n in nets), default=0.0)
            if depth / description["length"] > TOL_FILLET:
                defects.append((f"{_role(description, name)} network inside the fuselage",
                                depth / description["length"]))
    if geo.fillets:
        inside_body, inside_wing = fillet_depths(geo, description)
        if inside_body > TOL_FILLET:
            defects.append(("fillet points inside the fuselage", inside_body))
        if inside_wing > TOL_FILLET:
            defects.append(("fillet points inside the wing", inside_wing))
    if keep_area:
        res = np.asarray(geo.stations.get("residual", []), float)
        if res.size and not np.isfinite(res).all():
            defects.append(("keep_area residual not finite", math.inf))
        elif res.size and res.max() > TOL_RESIDUAL:
            defects.append(("keep_area residual > 1e-6", float(res.max())))
        r0 = np.asarray(geo.stations.get("radius_original", []), float)
        r1 = np.asarray(geo.stations.get("radius_new", []), float)
        grow = r1 - r0
        if r0.size and np.nanmax(grow) > 1e-9 * description["length"]:
            defects.append(("keep_area fuselage larger than the original",
                            float(np.nanmax(grow)) / description["length"]))
    return defects, notes


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout()


def survey_deck(job):
    """Every option set on one deck: a list of run records."""
    import juncture as jc

    index, text, description = job
    warnings.simplefilter("ignore")
    records = []
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / f"deck{index}.inp"
        path.write_text(text)
        try:
            cfg = jc.read(path)
        except Exception as exc:  # a generated deck must read
            kind = "JunctureError" if isinstance(exc, jc.JunctureError) else "crash"
            return [{"deck": index, "options": "read", "outcome": kind,
                     "cls": f"read: {type(exc).__name__}: {message_class(exc)}",
                     "message": str(exc), "traceback": traceback.format_exc()}]
        try:
            jc.write(cfg, Path(tmp) / "again.inp")
            from tests.deckgen import components_differ

            diff = components_differ(cfg, jc.read(Path(tmp) / "again.inp"))
        except Exception as exc:
            diff = f"{type(exc).__name__}: {message_class(exc)}"
        if diff:
            records.append({"deck": index, "options": "write+read", "outcome": "defects",
                            "defects": [(f"round trip differs: {diff}", math.inf)]})
        for label, kwargs in option_sets():
            rec = {"deck": index, "options": label}
            signal.signal(signal.SIGALRM, _alarm)
            signal.alarm(TIMEOUT)
            t0 = time.perf_counter()
            try:
                geo = jc.complete(cfg, **kwargs)
                signal.alarm(0)
                rec["seconds"] = time.perf_counter() - t0
                defects, notes = check_geometry(geo, description, kwargs["keep_area"],
                                                kwargs.get("single_network", False),
                                                kwargs["fillet"])
                rec.update(outcome="defects" if defects else "ok", defects=defects,
                           notes=sorted(set(notes)))
            except _Timeout:
                rec.update(outcome="timeout", cls=f"timeout (> {TIMEOUT} s)")
            except jc.JunctureError as exc:
                signal.alarm(0)
                rec.update(outcome="JunctureError",
                           cls=f"{type(exc).__name__}: {message_class(exc)}",
                           message=str(exc), traceback=traceback.format_exc())
            except Exception as exc:
                signal.alarm(0)
                rec.update(outcome="crash",
                           cls=f"{type(exc).__name__} at {crash_location(exc)}: "
                               f"{message_class(exc)[:80]}",
                           message=str(exc), traceback=traceback.format_exc())
            finally:
                signal.alarm(0)
            records.append(rec)
    return records


_FAMILY_KEYS = ("section", "segments", "joints", "wing_height", "root", "cambered",
                "unsymmetric", "body_fin", "wing_fin", "canards", "crank", "pointed_tip")


def _families(description):
    out = {f"{k}={description[k]}" for k in _FAMILY_KEYS}
    out |= {f"pod={p['mount']}" for p in description["pods"]}
    return out


def _overrepresented(decks_with, drawn):
    """The family labels most over-represented among ``decks_with`` (lift >= 1.3)."""
    if not decks_with:
        return ""
    total = collections.Counter(lab for _, d in drawn for lab in _families(d))
    mine = collections.Counter(lab for i in decks_with for lab in _families(drawn[i][1]))
    lifts = []
    for lab, k in mine.items():
        share, base = k / len(decks_with), total[lab] / len(drawn)
        if share >= 0.5 and share / base >= 1.3:
            lifts.append((share / base, f"{lab} {share:.0%}"))
    return ", ".join(t for _, t in sorted(lifts, reverse=True)[:3])


def _slug(text):
    """A file name for a class: its words, shortened, and a hash that keeps it unique."""
    digest = hashlib.sha1(text.encode()).hexdigest()[:6]
    return f"{re.sub(r'[^a-z0-9]+', '-', text.lower()).strip('-')[:72]}-{digest}"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=300, help="decks to draw (default 300)")
    parser.add_argument("--seed", type=int, default=0, help="hypothesis seed (default 0)")
    parser.add_argument("--save", type=Path, default=None,
                        help="directory for one example deck per class")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--json", type=Path, default=None, help="write every run record here")
    args = parser.parse_args(argv)

    from tests.deckgen import public_description

    t0 = time.time()
    drawn = draw_decks(args.n, args.seed)
    jobs = [(i, text, desc) for i, (text, desc) in enumerate(drawn)]
    if args.jobs > 1:
        with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
            results = pool.map(survey_deck, jobs, chunksize=1)
    else:
        results = [survey_deck(j) for j in jobs]
    records = [r for rs in results for r in rs]
    elapsed = time.time() - t0

    runs = [r for r in records if r["options"] not in ("read", "write+read")]
    outcome = collections.Counter(r["outcome"] for r in runs)
    classes = collections.defaultdict(list)  # class -> [(record, size)]
    for r in records:
        if r["outcome"] in ("JunctureError", "crash", "timeout"):
            classes[(r["outcome"], r["cls"])].append((r, None))
        for cls, size in r.get("defects", ()):
            classes[("defect", cls)].append((r, size))
    notes = collections.defaultdict(list)
    for r in runs:
        for note in r.get("notes", ()):
            notes[note].append(r)

    print(f"survey: {len(drawn)} decks (seed {args.seed}) x {len(option_sets())} option sets "
          f"= {len(runs)} runs in {elapsed:.0f} s")
    print(f"\n{'outcome':<18}{'runs':>7}{'share':>8}{'decks':>7}")
    for key in ("ok", "defects", "JunctureError", "crash", "timeout"):
        decks_k = {r["deck"] for r in runs if r["outcome"] == key}
        print(f"{key:<18}{outcome[key]:>7}{outcome[key] / max(len(runs), 1):>8.1%}"
              f"{len(decks_k):>7}")
    ok_decks = {r["deck"] for r in runs} - {r["deck"] for r in runs if r["outcome"] != "ok"}
    print(f"decks with every run ok: {len(ok_decks)} of {len(drawn)}")

    per_option = collections.defaultdict(collections.Counter)
    for r in runs:
        per_option[r["options"]][r["outcome"]] += 1
    print(f"\n{'options':<34}{'ok':>6}{'defects':>9}{'JErr':>6}{'crash':>7}{'timeout':>9}")
    for label, _ in option_sets():
        c = per_option[label]
        print(f"{label:<34}{c['ok']:>6}{c['defects']:>9}{c['JunctureError']:>6}"
              f"{c['crash']:>7}{c['timeout']:>9}")

    saved = {}
    if args.save is not None:
        args.save.mkdir(parents=True, exist_ok=True)
    order = sorted(classes, key=lambda k: (-len({r['deck'] for r, _ in classes[k]}), k))
    for kind in ("crash", "timeout", "JunctureError", "defect"):
        keys = [k for k in order if k[0] == kind]
        if not keys:
            continue
        print(f"\n{kind} classes{'':<60}{'runs':>6}{'decks':>7}{'worst':>10}")
        for key in keys:
            items = classes[key]
            decks_k = sorted({r["deck"] for r, _ in items})
            sizes = [s for _, s in items if s is not None]
            worst = f"{max(sizes):.2g}" if sizes else ""
            print(f"  {key[1][:200]}")
            print(f"  {'':<66}{len(items):>6}{len(decks_k):>7}{worst:>10}")
            fam = _overrepresented(decks_k, drawn)
            if fam:
                print(f"      over-represented: {fam}")
            if args.save is not None:
                first, _ = min(items, key=lambda t: (t[0]["deck"], t[0]["options"]))
                slug = f"{kind}-{_slug(key[1])}"
                i = first["deck"]
                (args.save / f"{slug}.inp").write_text(drawn[i][0])
                info = {"class": key[1], "kind": kind, "deck": i, "options": first["options"],
                        "message": first.get("message"), "traceback": first.get("traceback"),
                        "defects": first.get("defects"),
                        "description": public_description(drawn[i][1])}
                (args.save / f"{slug}.json").write_text(json.dumps(info, indent=1,
                                                                   default=str))
                saved[key] = args.save / f"{slug}.inp"
                print(f"      example: {saved[key]} (deck {i}, {first['options']})")

    if notes:
        print(f"\nnotes (not defects){'':<49}{'runs':>6}{'decks':>7}")
        for note, rs in sorted(notes.items(), key=lambda t: -len(t[1])):
            print(f"  {note:<66}{len(rs):>6}{len({r['deck'] for r in rs}):>7}")
    if args.json is not None:
        args.json.write_text(json.dumps(records, default=str))
    return 0


if __name__ == "__main__":
    sys.exit(main())
