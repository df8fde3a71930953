"""Text the commands print: what is in a file, and what a completion did."""

from __future__ import annotations

import numpy as np

__all__ = ["describe", "completion_summary"]


def _extent(lo, hi):
    return f"[{lo:10.4g}, {hi:10.4g}]"


def _extents_line(label, ext):
    return (f"{label}x " + _extent(ext[0, 0], ext[1, 0]) + "  y " + _extent(ext[0, 1], ext[1, 1])
            + "  z " + _extent(ext[0, 2], ext[1, 2]))


def _geometry_lines(geo):
    lines = [f"title: {geo.title}", f"{len(geo.networks)} networks:"]
    for name, net in geo.networks.items():
        sym = geo.symmetry.get(name)
        lines.append(f"  {name:<32} {net.shape[0]:4d} n-lines x {net.shape[1]:4d} points"
                     + (f"  image in {sym} plane" if sym else ""))
    return lines


def _configuration_lines(cfg):
    lines = [f"title: {cfg.title}"]
    if cfg.reference_area is not None:
        lines.append(f"reference area: {cfg.reference_area:g}"
                     + (f", chord {cfg.reference_chord:g}" if cfg.reference_chord else "")
                     + (f", moment centre x {cfg.moment_x:g}" if cfg.moment_x else ""))
    lines.append(f"{len(cfg)} components:")
    for comp in cfg:
        kind = getattr(comp, "kind", None) or type(comp).__name__
        if hasattr(comp, "n_sections"):
            counts = f"{comp.n_sections} sections x {comp.n_stations} stations"
        else:
            counts = f"{comp.x.size} stations in {len(comp.segments)} segment(s)"
        pts = np.concatenate([n.reshape(-1, 3) for n in comp.networks().values()])
        lo, hi = pts.min(0), pts.max(0)
        lines.append(f"  {comp.name:<12} {kind:<14} {counts:<32}"
                     f"{'mirrored' if comp.mirrored else '':<9}")
        lines.append("      " + _extents_line("", np.stack([lo, hi])))
    return lines


def describe(obj):
    """Lines describing a Configuration or a Geometry: title, parts, counts, extents."""
    from ..geometry import Geometry

    geo = isinstance(obj, Geometry)
    lines = _geometry_lines(obj) if geo else _configuration_lines(obj)
    lines.append(_extents_line("extents: ", obj.extents()))
    return lines


def completion_summary(cfg, geo, fillet):
    """Lines saying what complete() did: networks, pairs, seams, fillet and area residual."""
    st = geo.stations
    lines = [f"{cfg.title}: {len(geo.networks)} networks, {len(geo.intersections)} intersection "
             f"lines; fillet {fillet}; {len(st['x'])} fillet stations"]
    pairs = [s for s in geo.log if s.startswith("touching pairs:")]
    if pairs:
        lines.append(f"  {pairs[0]}")
    seams = [s for s in geo.log if s.startswith("seam")]
    gaps = [float(s.rsplit("max gap ", 1)[1]) for s in seams if "traced" not in s]
    if gaps:
        lines.append(f"  {len(gaps)} seams between networks, largest gap {max(gaps):.3g}")
    traced = [float(s.rsplit("max gap ", 1)[1]) for s in seams if "traced" in s]
    if traced:
        lines.append(f"  {len(traced)} fin/pylon lines traced on the wing at its stations, "
                     f"within {max(traced):.3g} of the wing grid")
    if fillet is not None:
        lines.append(f"  added area up to {st['area_fillet'].max():.4g}; radius reduced by up "
                     f"to {(st['radius_original'] - st['radius_new']).max():.4g}; worst area "
                     f"residual {st['residual'].max():.3g}")
    return lines
