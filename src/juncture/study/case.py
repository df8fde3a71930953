"""One case of a sweep: edit the base, complete it, analyse it, and return one flat row.

A row never raises: whatever goes wrong (a fillet the geometry has no room for, an edit that
leaves a component invalid, a bug) becomes ``status = "error"`` with the one-line message
and the exception's type, and the sweep goes on.

Columns (:func:`columns`): ``case``, ``key``, the parameters, ``status``, ``error``,
``error_type``, ``warnings`` (the distinct warning messages, ``" | "``-joined),
``wall_time`` [s]; the completion summary ``networks``, ``intersections`` (lines),
``intersection_points``, ``fillet_stations``, ``fillet_area_max`` (the largest area a fillet
adds to a cross-section, both sides), ``keep_area_iterations``, ``keep_area_residual``; the
``volume`` (the trapezoidal integral of the completed airplane's normal-area distribution at
the analysis's ``n_x`` stations: the union of the components, fillets included, no overlap
counted twice), the ``wetted_area`` (the completed networks' area, both halves); far-field
wave drag ``D_over_q_M<mach>`` and ``CD_M<mach>`` per Mach number; and mass properties at
unit density (``mass_volume``, which counts overlaps in each component, ``cg_x``, ``cg_z``,
``Ixx``, ``Iyy``, ``Izz`` about the centre of gravity).
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import tempfile
import time
import warnings

import numpy as np

__all__ = ["run_case", "columns", "SUMMARY", "MASS"]

SUMMARY = ("networks", "intersections", "intersection_points", "fillet_stations",
           "fillet_area_max", "keep_area_iterations", "keep_area_residual", "volume",
           "wetted_area")
MASS = ("mass_volume", "cg_x", "cg_z", "Ixx", "Iyy", "Izz")
_BASE = {}  # base file hash -> Configuration, one per worker process


def drag_columns(mach):
    """The two columns of one Mach number: ``D_over_q_M1.6``, ``CD_M1.6``."""
    return f"D_over_q_M{mach:g}", f"CD_M{mach:g}"


def columns(spec):
    """Every column of the results of ``spec``, in order."""
    head = ["case", "key", *(p.name for p in spec.parameters), "status", "error", "error_type",
            "warnings", "wall_time", *SUMMARY]
    drag = [c for m in spec.machs for c in drag_columns(m)]
    return head + drag + (list(MASS) if spec.analysis["massprops"] else [])


def _base(spec):
    """The base configuration, read once per process from the spec's bytes (no shared disk)."""
    digest = hashlib.sha256(spec.base_bytes).hexdigest()
    if digest not in _BASE:
        from ..io import read

        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, spec.base.name)
            with open(path, "wb") as fh:
                fh.write(spec.base_bytes)
            _BASE.clear()
            _BASE[digest] = read(path)
    return _BASE[digest]


def _limits():
    """One BLAS thread during a case, so that every kind of worker adds in the same order."""
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - threadpoolctl comes with the sweep extra
        return contextlib.nullcontext()
    return threadpool_limits(1)


def run_case(spec, index, case):
    """The row of case ``index`` (a dict parameter name -> value) of ``spec``."""
    row = dict.fromkeys(columns(spec), np.nan)
    row.update(case=index, key=spec.key(case), **case, status="ok", error="", error_type="",
               warnings="")
    start = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught, _limits():
        warnings.simplefilter("always")
        try:
            _evaluate(spec, case, row)
        except Exception as exc:  # noqa: BLE001 - a failing case is a row, never a stop
            message = " ".join(str(exc).split()) or type(exc).__name__
            row.update(status="error", error=message, error_type=type(exc).__name__)
    seen = dict.fromkeys(" ".join(str(w.message).split()) for w in caught)
    row["warnings"] = " | ".join(seen)
    row["wall_time"] = time.perf_counter() - start
    return row


def _settings(spec, case):
    """complete() arguments and analysis settings of one case."""
    options, analysis = dict(spec.complete), dict(spec.analysis)
    for p in spec.parameters:
        if p.kind == "option":
            options[p.target] = case[p.name]
        elif p.kind == "analysis":
            analysis[p.target] = (case[p.name],) if p.target == "mach" else case[p.name]
    fillet = options.pop("fillet", "none")
    # keep_area re-designs the fuselage where a fillet adds area: with none, nothing to do
    keep_area = options.pop("keep_area", False) and fillet != "none"
    return (None if fillet == "none" else fillet), keep_area, options, analysis


def _evaluate(spec, case, row):
    from ..completion import complete
    from .edit import apply_edit

    cfg = _base(spec)
    for p in spec.parameters:
        if p.kind == "component":
            cfg = apply_edit(cfg, p, case[p.name])
    fillet, keep_area, options, analysis = _settings(spec, case)
    geo = complete(cfg, fillet, keep_area, **options)
    row.update(_summary(geo))
    row.update(_drag_and_volume(geo, analysis))
    if analysis["massprops"]:
        row.update(_mass(geo.configuration))


def _summary(geo):
    st = geo.stations
    pts = sum(np.asarray(v).reshape(-1, 3).shape[0] for v in geo.intersections.values())
    out = {"networks": len(geo.networks), "intersections": len(geo.intersections),
           "intersection_points": pts, "wetted_area": wetted_area(geo)}
    if st and len(st.get("x", ())):
        out.update(fillet_stations=len(st["x"]),
                   fillet_area_max=float(np.max(st["area_fillet"])),
                   keep_area_iterations=float(np.max(st["iterations"])),
                   keep_area_residual=float(np.max(np.abs(st["residual"]))))
    return out


def wetted_area(geo):
    """Area of every network of ``geo`` with its image, each quad as two triangles."""
    total = 0.0
    for net in geo.mirrored_networks().values():
        p = np.asarray(net, float)
        a, b, c, d = p[:-1, :-1], p[1:, :-1], p[1:, 1:], p[:-1, 1:]
        total += 0.5 * (np.linalg.norm(np.cross(b - a, d - a), axis=-1).sum()
                        + np.linalg.norm(np.cross(d - c, b - c), axis=-1).sum())
    return float(total)


def _drag_and_volume(geo, analysis):
    from ..analysis import closed_networks, wavedrag
    from ..analysis._components import held_base_area

    out, x, area = {}, None, None
    model = geo.configuration
    nets = closed_networks(model) if analysis["mach"] else None  # once for every Mach
    for mach in analysis["mach"]:
        r = wavedrag(model, mach, analysis["n_x"], analysis["n_theta"], geometry=geo,
                     networks=nets if mach > 1.0 else None)  # M 1: the exact normal areas
        dq, cd = drag_columns(mach)
        out[dq] = r["D_over_q"]
        out[cd] = np.nan if r["CD"] is None else r["CD"]
        if x is None:
            x = np.asarray(r["x"])
            area = np.asarray(r["area"]) - held_base_area(model, x)
    if x is None:  # no Mach number: the normal areas alone
        r = wavedrag(model, None, analysis["n_x"], geometry=geo)
        x = np.asarray(r["x"])
        area = np.asarray(r["area"]) - np.asarray(r["components"].get("held bases", 0.0))
    out["volume"] = float(np.sum(0.5 * (area[1:] + area[:-1]) * np.diff(x)))
    return out


def _mass(model):
    from ..massprops.configuration import configuration_mass_properties

    total, _ = configuration_mass_properties(model)
    inertia = np.diag(np.asarray(total.inertia, float))
    return {"mass_volume": float(total.volume), "cg_x": float(total.cg[0]),
            "cg_z": float(total.cg[2]), "Ixx": float(inertia[0]), "Iyy": float(inertia[1]),
            "Izz": float(inertia[2])}
