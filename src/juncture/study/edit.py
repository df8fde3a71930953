"""Component edits of a sweep: a configuration with one field of some components changed.

Fields, by component type (``mode`` is how the value acts: ``set`` replaces, ``offset``
adds, ``scale`` multiplies; ``section`` / ``station`` (1-based) picks one, else all):

=================  ===========================================================  ===============
field              what changes                                                  modes
=================  ===========================================================  ===============
wing-like (wing, canard, tail, fin, pylon)
``x``, ``y``,      the whole component moves; ``set`` places the root leading   set, offset
``z``              edge (or, with ``section``, that section's leading edge)
``sweep``          leading-edge sweep from root to tip [deg]: each section       set, offset
                   slides in x by its span distance from the root times the
                   change of tan(sweep), so cranks are kept
``dihedral``       the same in the vertical (wing, canard and tail) [deg]        set, offset
``span``           root-to-tip span (y; z for fins and pylons), sweep,           set, scale
                   dihedral and chords kept
``chord``          streamwise chord (thickness in % chord is kept)              set, offset,
                                                                                 scale
``thickness``      upper and lower half-thickness [% chord]                      scale
circular body (fuselage, pod)
``x``, ``y``,      the body moves (its origin)                                   set, offset
``z``
``radius``         cross-section radius                                          set, offset,
                                                                                 scale
``area``           cross-section area (the radius follows)                       set, scale
``length``         stations stretched about the nose                             set, scale
arbitrary body
``x``, ``y``,      the body moves (y only for a pod off the centre line)        offset
``z``
=================  ===========================================================  ===============

An edit that leaves a component invalid (a negative chord, stations out of order) raises the
model's own :class:`~juncture.errors.GeometryError`; in a sweep that case's row says so.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import GeometryError, SpecError
from ..model import CircularBody, WingLike
from ..model import rebuilt as _rebuilt

__all__ = ["apply_edit", "check_edit", "check_target", "FIELDS"]

_ALL = ("set", "offset", "scale")
_MOVE = ("set", "offset")
#: field -> modes, per component type
FIELDS = {
    "wing-like": {"x": _MOVE, "y": _MOVE, "z": _MOVE, "sweep": _MOVE, "dihedral": _MOVE,
                  "span": ("set", "scale"), "chord": _ALL, "thickness": ("scale",)},
    "circular body": {"x": _MOVE, "y": _MOVE, "z": _MOVE, "radius": _ALL,
                      "area": ("set", "scale"), "length": ("set", "scale")},
    "arbitrary body": {"x": ("offset",), "y": ("offset",), "z": ("offset",)},
}
_PER_SECTION = {"x", "y", "z", "chord", "thickness", "radius", "area"}


def _type_of(comp):
    if isinstance(comp, WingLike):
        return "wing-like"
    return "circular body" if isinstance(comp, CircularBody) else "arbitrary body"


def check_edit(field, mode, index, values, bounds, what):
    """Check a component parameter as far as the spec alone tells (the base is checked later)."""
    known = sorted({f for fields in FIELDS.values() for f in fields})
    if field not in known:
        raise SpecError(f"{what}: field: expected one of {', '.join(known)}, found {field!r}")
    modes = sorted({m for fields in FIELDS.values() for m in fields.get(field, ())})
    if mode not in modes:
        raise SpecError(f"{what}: mode: field {field!r} takes {', '.join(modes)}, found "
                        f"{mode!r}")
    if index is not None:
        if isinstance(index, bool) or not isinstance(index, int) or index < 1:
            raise SpecError(f"{what}: section/station: expected a number >= 1, found {index!r}")
        if field not in _PER_SECTION:
            raise SpecError(f"{what}: field {field!r} applies to the whole component; drop "
                            "section/station")
    for v in values or ():
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            raise SpecError(f"{what}: values: expected numbers, found {v!r}")


def check_target(cfg, param):
    """SpecError unless every component of ``param`` is in ``cfg`` and takes its field/mode."""
    for name in param.components:
        if name not in cfg.components:
            raise SpecError(f"parameter {param.name!r}: the base has no component {name!r}; "
                            f"it has {', '.join(cfg.components)}")
        kind = _type_of(cfg[name])
        modes = FIELDS[kind].get(param.target)
        if modes is None or param.mode not in modes:
            allowed = ", ".join(f"{f} ({'/'.join(m)})" for f, m in FIELDS[kind].items())
            raise SpecError(f"parameter {param.name!r}: a {kind} ({name}) has no "
                            f"{param.mode} {param.target!r}; it takes {allowed}")


def apply_edit(cfg, param, value):
    """``cfg`` with ``param`` (a component :class:`~juncture.study.spec.Parameter`) at ``value``."""
    check_target(cfg, param)
    for name in param.components:
        comp = cfg[name]
        cfg = cfg.with_component(_EDITS[_type_of(comp)](comp, param, float(value)))
    return cfg


def _rows(comp, index, count, what):
    if index is None:
        return slice(None)
    if index > count:
        raise GeometryError(f"has {count} {what}s; no {what} {index}", comp.name)
    return index - 1


def _changed(old, mode, value):
    return {"set": value, "offset": old + value, "scale": old * value}[mode]


def _wing(comp, p, v):
    le, chord = np.array(comp.le), np.array(comp.chord)
    axis = comp.span_axis
    rows = _rows(comp, p.index, le.shape[0], "section")
    if p.target in ("x", "y", "z"):
        k = "xyz".index(p.target)
        ref = le[0 if p.index is None else rows, k]
        le[rows, k] += (v - ref) if p.mode == "set" else v
        return _rebuilt(comp, le=le)
    if p.target == "chord":
        chord[rows] = _changed(chord[rows], p.mode, v)
        return _rebuilt(comp, chord=chord)
    if p.target == "thickness":
        up, lo = np.array(comp.upper), np.array(comp.lower)
        up[rows] *= v
        lo[rows] *= v
        return _rebuilt(comp, upper=up, lower=lo)
    s = le[:, axis] - le[0, axis]
    if s[-1] <= 0:
        raise GeometryError("has no span from root to tip to change", comp.name)
    if p.target == "span":
        factor = v if p.mode == "scale" else v / s[-1]
        return _rebuilt(comp, le=le[0] + factor * (le - le[0]))
    k = 0 if p.target == "sweep" else 2
    if p.target == "dihedral" and axis != 1:
        raise GeometryError("a fin or pylon has no dihedral (its span is vertical)", comp.name)
    old = math.degrees(math.atan2(le[-1, k] - le[0, k], s[-1]))
    new = v if p.mode == "set" else old + v
    if not abs(new) < 89.0:
        raise GeometryError(f"{p.target} {new:g} deg: expected within +-89 deg", comp.name)
    le[:, k] += s * (math.tan(math.radians(new)) - math.tan(math.radians(old)))
    return _rebuilt(comp, le=le)


def _circular(comp, p, v):
    if p.target in ("x", "y", "z"):
        origin = np.array(comp.origin)
        k = "xyz".index(p.target)
        origin[k] = v if p.mode == "set" else origin[k] + v
        return _rebuilt(comp, origin=origin)
    if p.target == "length":
        x = np.array(comp.x)
        length = x[-1] - x[0]
        factor = v if p.mode == "scale" else v / length
        return _rebuilt(comp, x=x[0] + factor * (x - x[0]), slopes=None)
    radius = np.array(comp.radius)
    rows = _rows(comp, p.index, radius.size, "station")
    if p.target == "radius":
        radius[rows] = _changed(radius[rows], p.mode, v)
    elif v < 0:
        raise GeometryError(f"area {p.mode} {v:g}: expected a value >= 0", comp.name)
    else:
        radius[rows] = radius[rows] * math.sqrt(v) if p.mode == "scale" else math.sqrt(v / math.pi)
    return _rebuilt(comp, radius=radius, slopes=None)


def _arbitrary(comp, p, v):
    if p.target == "x":
        return _rebuilt(comp, x=np.array(comp.x) + v)
    if p.target == "y" and not comp.mirrored:
        raise GeometryError("is on the centre line (its y >= 0 half is given); only a pod off "
                            "it moves in y", comp.name)
    k = 0 if p.target == "y" else 1
    secs = [np.array(s) for s in comp.sections]
    for s in secs:
        s[:, k] += v
    return _rebuilt(comp, sections=secs)


_EDITS = {"wing-like": _wing, "circular body": _circular, "arbitrary body": _arbitrary}
