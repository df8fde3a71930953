"""``juncture blend SPEC -o DIR``: build the long-strake blend and write everything.

:func:`build_blend` turns a spec into a :class:`BlendModel` (lines, R1 and its base surfaces,
R2, the thin-plate patch); :func:`blend_geometry` samples it into a
:class:`~juncture.geometry.Geometry`; :func:`run` writes into DIR: ``g1_report.json``,
``patch_refinement.json``, the networks in every requested format whose writer is registered
(``blend.wgs``, ``blend.p3d``, ``blend.stl``, ``blend.step``, ``blend.igs``) and PNG figures.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import JunctureError
from ..geometry import Geometry
from .lines import build_lines
from .patch import patch_edges, refinement_study, solve_patch
from .report import g1_report
from .spec import build_body, build_wing, load_spec
from .strake import build_strake
from .surfaces import unit
from .wingbody import build_wing_body

__all__ = ["BlendModel", "build_blend", "blend_geometry", "run", "EXTENSIONS"]

#: Output format name -> file name written by :func:`run`.
EXTENSIONS = {"wgs": "blend.wgs", "p3d": "blend.p3d", "stl": "blend.stl",
              "step": "blend.step", "igs": "blend.igs", "vtk": "blend.vtk"}


@dataclass(frozen=True, slots=True, eq=False)
class BlendModel:
    """Everything built from one spec: ``spec`` (dict), ``lines``, ``wing_body`` (R1 and its
    base surfaces), ``strake`` (R2) and ``patch`` (W)."""

    spec: dict
    lines: object
    wing_body: object
    strake: object
    patch: object


def build_blend(spec):
    """Build the blend from a spec (path, dict, or an already validated dict).

    Raises
    ------
    SpecError, GeometryError
        On a bad spec or impossible lines.
    """
    spec = load_spec(spec)
    body, wing = build_body(spec), build_wing(spec)
    lines = build_lines(body, wing, spec["lines"])
    b = spec["blend"]
    wb = build_wing_body(lines, b["mu"], b["lambda"], b["beta"])
    r2 = build_strake(lines, wb)
    p = spec["patch"]
    w = solve_patch(patch_edges(lines, r2), p["elements"], tuple(p["stretch"]),
                    tuple(p["bend"]), p["de_normal"])
    return BlendModel(spec, lines, wb, r2, w)


def _orient(net, ref):
    """Reverse the n-lines if the network's normals point against ``ref`` (n_l, n_p, 3)."""
    a = net[:-1, 1:] - net[:-1, :-1]
    b = net[1:, :-1] - net[:-1, :-1]
    nrm = np.cross(a, b)
    ref = np.broadcast_to(ref, net.shape)[:-1, :-1]
    return net if np.sum(nrm * ref) >= 0 else net[::-1].copy()


def _radial(net, z_axis):
    r = net.copy()
    r[..., 0] = 0.0
    r[..., 2] -= z_axis
    return unit(r)


def blend_geometry(model):
    """Sample the patches (and, on request, body and wing) into a Geometry.

    Networks: ``"blend wing-body"`` (R1), ``"blend strake"`` (R2), ``"blend nose"`` (W) and,
    with ``output.include_components``, ``"body side"`` (the body's y >= 0 half, untrimmed)
    and ``"wing upper"``, ``"wing lower"`` (untrimmed, from the body axis). Every network is
    oriented with outward normals (project convention); all are mirrored in the xz plane.
    """
    n_l, n_p = model.spec["output"]["points"]
    lines = model.lines
    sec = lines.body.section
    z_axis = getattr(sec, "z_axis", float(np.mean(np.asarray(sec.points)[:, 1]))
                     if hasattr(sec, "points") else 0.0)
    s, t = np.linspace(0, 1, n_l), np.linspace(0, 1, n_p)
    nets = {"blend wing-body": model.wing_body.r1.grid(s, t),
            "blend strake": model.strake.grid(s, t),
            "blend nose": model.patch.grid(np.linspace(0, 1, n_p), s)}
    if model.spec["output"]["include_components"]:
        body, wing = lines.body, lines.wing
        nets["body side"] = body.grid(np.linspace(body.x_start, body.x_end, 2 * n_l),
                                      np.linspace(-0.5 * np.pi, 0.5 * np.pi, n_p))
        v = np.linspace(0, 1, n_l)
        xi = np.linspace(0, 1, n_p)
        nets["wing upper"] = np.swapaxes(wing.grid(xi, v), 0, 1)
        nets["wing lower"] = np.swapaxes(wing.grid(-xi, v), 0, 1)
    out = {}
    for name, net in nets.items():
        if name == "wing upper":
            ref = np.array([0.0, 0.0, 1.0])
        elif name == "wing lower":
            ref = np.array([0.0, 0.0, -1.0])
        else:
            ref = _radial(net, z_axis)
        out[name] = _orient(net, ref)
    return Geometry(networks=out, symmetry={k: "xz" for k in out},
                    title=str(model.spec["title"]),
                    log=(f"blend: mu={model.wing_body.mu} lambda={model.wing_body.lam} "
                         f"beta={model.wing_body.beta}",
                         f"thin-plate patch: {model.patch.elements} bicubic spans per side, "
                         f"energy {model.patch.energy:.6g}"))


def _write_json(path, obj):
    from ..io._registry import atomic_output

    with atomic_output(path, "w") as fh:
        json.dump(obj, fh, indent=2)
        fh.write("\n")


def run(spec_path, out_dir):
    """Do everything ``juncture blend SPEC -o DIR`` does.

    Parameters
    ----------
    spec_path : str or path-like
        The JSON spec (see :mod:`juncture.blend.spec`).
    out_dir : str or path-like
        Created if missing.

    Returns
    -------
    dict
        ``report`` (the G1 report), ``refinement`` (rows of the patch refinement study),
        ``files`` (paths written) and ``skipped`` (format -> reason for each requested
        format not written: writer not registered, or OCP missing).
    """
    model = build_blend(spec_path)
    out = Path(out_dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise JunctureError(f"cannot create output directory {str(out)!r}: "
                            f"{exc.strerror}") from None
    files, skipped = [], {}
    report = g1_report(model)
    _write_json(out / "g1_report.json", report)
    files.append(str(out / "g1_report.json"))
    base = model.patch.elements
    levels = sorted({max(2, base // 4), max(3, base // 2), base, 2 * base})
    p = model.spec["patch"]
    refinement = refinement_study(model.patch.edges, tuple(levels), tuple(p["stretch"]),
                                  tuple(p["bend"]), p["de_normal"])
    _write_json(out / "patch_refinement.json", refinement)
    files.append(str(out / "patch_refinement.json"))
    geometry = blend_geometry(model)
    from .. import io as jio
    from ..errors import MissingDependencyError

    for fmt in model.spec["output"]["formats"]:
        target = out / EXTENSIONS[fmt]
        if not [f for f in jio._registry._by_extension(target) if f.writer is not None]:
            skipped[fmt] = "no writer registered for this format"
            continue
        try:
            jio.write(geometry, target)
        except MissingDependencyError as exc:
            skipped[fmt] = str(exc)
            continue
        files.append(str(target))
    if model.spec["output"]["figures"]:
        from ..plots.blend import write_figures

        files.extend(write_figures(model, out))
    return {"report": report, "refinement": refinement, "files": files, "skipped": skipped}
