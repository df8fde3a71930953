"""Survey: does ``juncture.mesh`` close generated airplanes (issue 12)?

Draws N decks from ``tests.deckgen.decks()`` with a fixed hypothesis seed (the same decks as
``tools/survey_decks.py`` for the same N and seed), completes each sharp and with a cubic
fillet and ``keep_area``, and meshes it with the defaults. Every run is classified:

- ``closed``: ``mesh`` returned a surface that passed every check; its enclosed volume is
  compared with the integral of the union of normal areas A(x) of the model kept with the
  geometry (roots outside the fuselage continued to it; sharp runs only: a fillet adds area
  the model does not have) by juncture's ``normal_area_distribution`` and by the independent
  cell count of ``tests/union_oracle.py`` (which counts overlaps of wing-like components,
  such as a fin standing on a wing, once), its triangle angles recorded (and how many
  under 5 deg have it at a corner of their surface sharper than that: ``sharp_corners``),
  and how far the exact curves where wing-like components meet bodies lie from it (issue
  12: 1e-6 of the size; the independent oracle of ``tests/seam_oracle.py``, the worst
  point named in ``seam_sag_where``);
- ``kept``: closed, but the re-triangulation for quality was not kept (a warning);
- ``complete``: ``complete`` refused the deck (issue 11's business, not the mesh's);
- ``refused``: ``mesh`` refused the surface, by message class;
- ``crash``: any other exception, by type and innermost juncture frame.

Usage::

    .venv/bin/python tools/survey_mesh.py --n 40 --seed 11 --save mesh-out
"""

from __future__ import annotations

import argparse
import collections
import json
import multiprocessing
import os
import signal
import sys
import time
import traceback
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tools"))

from survey_decks import crash_location, draw_decks, message_class  # noqa: E402

TIMEOUT = 300
OPTIONS = (("sharp", {}), ("cubic+keep_area", {"fillet": "cubic", "keep_area": True}))


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout


def union_volume(cfg, n=2001):
    """The model's union of normal areas A(x), integrated by Simpson's rule (both halves)."""
    import numpy as np
    from scipy.integrate import simpson

    from juncture.analysis.areas import normal_area_distribution

    a = normal_area_distribution(cfg, n_x=n, flow_through=False)
    return float(simpson(a["total"], x=a["x"])), np.asarray(a["x"])


def seam_sag(geometry, surface):
    """(largest distance, share of the size, where, points, seconds): how far the exact
    curves where wing-like components meet bodies lie from the mesh, by the independent
    oracle of ``tests/seam_oracle.py`` (the curves root-found on the model, at the chord
    fractions of the lofting lines and between them, at the mesh vertices on the curve and
    midway between them, refined where the distance could be larger; the distance to the
    nearest triangle, exactly).

    Sharp geometries: every wing/body curve (both sides, both halves). With a fillet the main
    wing's curve with the fuselage is no seam where the fillet is (its start lines on wing
    and body are: juncture's construction, with no exact curve to measure them against):
    it is measured only between lofting lines whose fillet lines both have length zero;
    every other pair (a tail, a fin, a pylon on a pod) in full. Curves of two wing-like
    components (a fin on a wing) are not measured."""
    import numpy as np

    from tests.seam_oracle import seam_distances

    t0 = time.perf_counter()
    cfg = geometry.configuration
    keys = list(geometry.intersections)
    attached = {tuple(k.rsplit(" ", 1)[0].split("/", 1)) for k in keys}
    fillets = None
    if geometry.fillets and keys:
        wing, body = keys[0].rsplit(" ", 1)[0].split("/", 1)
        size = float(np.ptp(surface.vertices, axis=0).max())
        fillets = {}
        for side in ("upper", "lower"):
            lines = np.asarray(geometry.fillets[f"fillet {side}"])
            length = np.linalg.norm(np.diff(lines, axis=1), axis=2).sum(axis=1)
            has = length > 1e-9 * size
            if len(has) != cfg[wing].n_stations:   # not one per lofting line: leave it out
                has = np.ones(cfg[wing].n_stations, bool)
            fillets[(wing, body, side)] = has
    d, pts = seam_distances(cfg, surface.vertices, surface.triangles, attached=attached,
                            fillets=fillets)
    seconds = time.perf_counter() - t0
    if not len(d):
        return 0.0, "", 0, seconds
    i = int(np.argmax(d))
    return float(d[i]), pts.where(i) + _near(cfg, pts.points[i]), int(len(d)), seconds


def _near(cfg, point):
    """What lies near a seam's worst point, for the survey's list: a fuselage joint where
    two segments repeat a station (within 1 % of the body's length; where their sections
    differ the rows there end at an interpolated angle, docs/mesh.md session 41), the plane
    of symmetry (within 1e-3 of the longest body's length), or nothing ("")."""
    import numpy as np

    tags, size = [], 1.0
    for comp in cfg:
        x = np.asarray(getattr(comp, "x_global", ()), float)
        if x.size < 2:
            continue
        size = max(size, float(np.ptp(x)))
        joints = x[1:][x[1:] == x[:-1]]
        close = joints[np.abs(joints - point[0]) <= 0.01 * np.ptp(x)]
        if close.size:
            tags.append(f"joint of {comp.name} at x={close[0]:.6g}")
    if abs(point[1]) <= 1e-3 * size:
        tags.append("at the plane of symmetry")
    return f" [near: {'; '.join(tags)}]" if tags else ""


def sharp_corners(surface, angles, limit=5.0):
    """(count, inherent): triangles with an angle under ``limit`` degrees, and how many of
    them have it at a corner of their surface (network or cap) that is itself sharper than
    ``limit``: the sum of the surface's angles at that vertex (a tip cap's corner at a
    section's leading or trailing edge whose included angle is under 5 deg, a fuselage
    half at a fin's sharp leading edge). No triangulation of that surface avoids those."""
    import numpy as np

    t = surface.triangles
    small = angles.min(axis=1) < limit
    keys = t.astype(np.int64) * len(surface.surfaces) + surface.surface[:, None]
    uniq, inv = np.unique(keys.ravel(), return_inverse=True)
    total = np.zeros(len(uniq))
    np.add.at(total, inv, angles.ravel())
    at = np.argmin(angles, axis=1)
    corner = total[inv.reshape(t.shape)[np.arange(len(t)), at]]
    return int(small.sum()), int((small & (corner < limit)).sum())


def survey_deck(job):
    import numpy as np

    import juncture as jc
    from juncture.surface.quality import triangle_angles as angles
    from tests.deckgen import read_text

    index, text = job
    out = []
    try:
        cfg = read_text(text)
    except Exception as exc:
        return [{"deck": index, "options": "read", "outcome": "crash", "cls": repr(exc)}]
    for label, kwargs in OPTIONS:
        rec = {"deck": index, "options": label}
        signal.signal(signal.SIGALRM, _alarm)
        signal.alarm(TIMEOUT)
        try:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                try:
                    geo = jc.complete(cfg, **kwargs)
                except jc.JunctureError as exc:
                    rec.update(outcome="complete", cls=message_class(exc))
                    out.append(rec)
                    continue
                t0 = time.perf_counter()
                surface = jc.mesh(geo)
                rec["seconds"] = time.perf_counter() - t0
            kept = [str(w.message) for w in caught if "re-triangulation" in str(w.message)]
            rec["outcome"] = "kept" if kept else "closed"
            if kept:
                rec["cls"] = message_class(kept[0])[:120]
            ang = angles(surface.vertices, surface.triangles)
            rec["min_angle"] = float(ang.min())
            rec["under5"], rec["under5_at_sharp_corners"] = sharp_corners(surface, ang)
            rec["share20"] = float(np.mean(ang.min(axis=1) >= 20.0))
            rec["triangles"] = int(len(surface.triangles))
            (rec["seam_sag"], rec["seam_sag_where"], rec["seam_points"],
             rec["seam_seconds"]) = seam_sag(geo, surface)
            if not kwargs:
                from tests.union_oracle import union_volume as cells_volume

                ref, _ = union_volume(geo.configuration)
                rec["volume_error"] = surface.volume() / ref - 1.0
                rec["volume_error_cells"] = surface.volume() / cells_volume(
                    geo.configuration, n=121, cells=1500) - 1.0
        except _Timeout:
            rec.update(outcome="timeout", cls=f"> {TIMEOUT} s")
        except jc.JunctureError as exc:
            rec.update(outcome="refused", cls=message_class(exc)[:160], message=str(exc))
        except Exception as exc:
            rec.update(outcome="crash", cls=f"{type(exc).__name__} at {crash_location(exc)}",
                       message=str(exc), traceback=traceback.format_exc())
        finally:
            signal.alarm(0)
        out.append(rec)
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=40)
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--save", type=Path, default=None)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--only", type=str, default=None, help="comma list of deck indices")
    args = parser.parse_args(argv)

    drawn = draw_decks(args.n, args.seed)
    jobs = [(i, text) for i, (text, _) in enumerate(drawn)]
    if args.only:
        keep = {int(s) for s in args.only.split(",")}
        jobs = [j for j in jobs if j[0] in keep]
    t0 = time.time()
    with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
        results = pool.map(survey_deck, jobs, chunksize=1)
    records = [r for rs in results for r in rs]
    print(f"mesh survey: {len(jobs)} decks (seed {args.seed}) in {time.time() - t0:.0f} s")
    for label, _ in OPTIONS:
        mine = [r for r in records if r["options"] == label]
        count = collections.Counter(r["outcome"] for r in mine)
        print(f"\n{label}: " + ", ".join(f"{k} {v}" for k, v in sorted(count.items())))
        closed = [r for r in mine if r["outcome"] in ("closed", "kept")]
        if closed:
            import numpy as np

            mins = np.array([r["min_angle"] for r in closed])
            s20 = np.array([r["share20"] for r in closed])
            secs = np.array([r["seconds"] for r in closed])
            print(f"  min angle: median {np.median(mins):.2f}, worst {mins.min():.2f}, "
                  f">= 5 deg on {np.mean(mins >= 5):.0%}; share >= 20 deg: median "
                  f"{np.median(s20):.3f}, worst {s20.min():.3f}; mesh seconds median "
                  f"{np.median(secs):.2f}, max {secs.max():.2f}")
            avoid = np.array([r["under5"] - r["under5_at_sharp_corners"] for r in closed])
            print(f"  no triangle under 5 deg on {np.mean(mins >= 5):.0%}; none but at corners "
                  f"of the surfaces sharper than 5 deg on {np.mean(avoid == 0):.0%}")
            sag = np.array([r["seam_sag"] for r in closed if "seam_sag" in r])
            if len(sag):
                cost = np.array([r["seam_seconds"] for r in closed if "seam_sag" in r])
                print(f"  exact wing/body curves off the mesh (share of size; "
                      f"tests/seam_oracle.py): median {np.median(sag):.1e}, worst "
                      f"{sag.max():.1e}, within 1e-6 on {np.sum(sag <= 1e-6)}/{len(sag)}; "
                      f"{np.median(cost):.1f} s a mesh (max {cost.max():.1f})")
                for r in sorted(closed, key=lambda r: -r.get("seam_sag", 0.0)):
                    if r.get("seam_sag", 0.0) > 1e-6:
                        print(f"    deck {r['deck']:>3}: {r['seam_sag']:.1e} at "
                              f"{r['seam_sag_where']}")
            vol = [r["volume_error"] for r in closed if "volume_error" in r]
            if vol:
                print(f"  volume vs A(x): median {np.median(vol):+.3%}, worst "
                      f"{min(vol):+.3%} / {max(vol):+.3%}")
                cells = np.array([r["volume_error_cells"] for r in closed
                                  if "volume_error_cells" in r])
                print(f"  volume vs the union counted by cells (tests/union_oracle.py): "
                      f"median {np.median(cells):+.3%}, worst {cells.min():+.3%} / "
                      f"{cells.max():+.3%}, within 0.5 % on {np.mean(abs(cells) < 5e-3):.0%}")
        classes = collections.defaultdict(list)
        for r in mine:
            if "cls" in r:
                classes[(r["outcome"], r["cls"])].append(r["deck"])
        for (outcome, cls), idx in sorted(classes.items(), key=lambda t: -len(t[1])):
            print(f"  {len(idx):>3} {outcome}: {cls}  decks {idx[:8]}")
    if args.save:
        args.save.mkdir(parents=True, exist_ok=True)
        (args.save / "records.json").write_text(json.dumps(records, indent=1))
        for i, (text, _) in enumerate(drawn):
            if any(r["deck"] == i and r["outcome"] not in ("closed",) for r in records):
                (args.save / f"deck{i:03d}.inp").write_text(text)


if __name__ == "__main__":
    main()
