"""juncture's own component model as JSON (``.json``) or TOML (``.toml``, read only).

The format is documented in ``docs/model-format.md``. It holds a Configuration losslessly:
every component with its arrays, in the units of the deck it came from. JSON numbers are
written with Python's shortest round-trip repr, so write -> read is exact.
"""

from __future__ import annotations

import json
import tomllib

import numpy as np

from ..errors import DeckError, GeometryError, SpecError
from ..model import ArbitraryBody, CircularBody, Configuration, WingLike
from ._registry import atomic_output, register_format

__all__ = ["read", "write", "configuration_from_dict", "configuration_to_dict"]

FORMAT_VERSION = 1
_WING_TYPES = ("wing", "canard", "tail", "fin", "pylon")


def _get(d, key, where, kind=None, default=...):
    if key not in d:
        if default is not ...:
            return default
        raise SpecError(f"{where}: missing field {key!r}")
    value = d[key]
    if kind is not None and not isinstance(value, kind):
        names = kind.__name__ if isinstance(kind, type) else "/".join(k.__name__ for k in kind)
        raise SpecError(f"{where}: field {key!r} must be {names}, found "
                        f"{type(value).__name__}")
    return value


def _known(d, allowed, where):
    unknown = sorted(set(d) - set(allowed))
    if unknown:
        raise SpecError(f"{where}: unknown field(s) {', '.join(map(repr, unknown))}; "
                        f"expected some of {', '.join(sorted(allowed))}")


def _component(d, index):
    where = f"components[{index}]"
    if not isinstance(d, dict):
        raise SpecError(f"{where}: must be an object, found {type(d).__name__}")
    name = _get(d, "name", where, str)
    where = f"components[{index}] ({name!r})"
    ctype = _get(d, "type", where, str)
    try:
        if ctype in _WING_TYPES:
            _known(d, {"name", "type", "le", "chord", "x_over_c", "upper", "lower", "camber",
                       "mirrored", "chordwise"}, where)
            return WingLike(name, ctype, _get(d, "le", where, list),
                            _get(d, "chord", where, list), _get(d, "x_over_c", where, list),
                            _get(d, "upper", where, list), _get(d, "lower", where, list, None),
                            _get(d, "camber", where, list, None),
                            _get(d, "mirrored", where, bool, True),
                            _get(d, "chordwise", where, str, "pchip"))
        if ctype == "circular_body":
            _known(d, {"name", "type", "x", "radius", "camber", "origin", "segments",
                       "mirrored", "axial", "points_per_section", "slopes"}, where)
            pps = _get(d, "points_per_section", where, list, None)
            return CircularBody(name, _get(d, "x", where, list), _get(d, "radius", where, list),
                                _get(d, "camber", where, list, None),
                                _get(d, "origin", where, list, [0.0, 0.0, 0.0]),
                                _get(d, "segments", where, list, None),
                                _get(d, "mirrored", where, bool, False),
                                _get(d, "axial", where, str, "pchip"),
                                None if pps is None else tuple(pps),
                                _get(d, "slopes", where, list, None))
        if ctype == "arbitrary_body":
            _known(d, {"name", "type", "x", "sections", "segments", "mirrored"}, where)
            return ArbitraryBody(name, _get(d, "x", where, list),
                                 tuple(_get(d, "sections", where, list)),
                                 _get(d, "segments", where, list, None),
                                 mirrored=_get(d, "mirrored", where, bool, False))
    except GeometryError as exc:
        raise SpecError(f"{where}: {exc.reason}" + (f" (station {exc.station})"
                                                   if exc.station is not None else "")) from None
    raise SpecError(f"{where}: type must be one of {', '.join(_WING_TYPES)}, circular_body, "
                    f"arbitrary_body; found {ctype!r}")


def configuration_from_dict(data):
    """Build a Configuration from the parsed JSON/TOML object (see docs/model-format.md)."""
    if not isinstance(data, dict):
        raise SpecError(f"the model must be an object, found {type(data).__name__}")
    _known(data, {"juncture", "title", "reference", "symmetric", "components"}, "model")
    version = _get(data, "juncture", "model", int)
    if version != FORMAT_VERSION:
        raise SpecError(f"model: format version {version} is not supported (expected "
                        f"{FORMAT_VERSION})")
    ref = _get(data, "reference", "model", dict, {})
    _known(ref, {"area", "chord", "moment_x"}, "reference")
    comps = [_component(c, i) for i, c in enumerate(_get(data, "components", "model", list))]
    names = [c.name for c in comps]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise SpecError(f"model: component names must be unique, repeated: {', '.join(dup)}")
    return Configuration({c.name: c for c in comps}, title=_get(data, "title", "model", str, ""),
                         reference_area=ref.get("area"), reference_chord=ref.get("chord"),
                         moment_x=ref.get("moment_x"),
                         symmetric=_get(data, "symmetric", "model", bool, True))


def _lst(a):
    return np.asarray(a).tolist()


def configuration_to_dict(cfg):
    """The JSON-ready dict of a Configuration (the inverse of configuration_from_dict)."""
    comps = []
    for c in cfg:
        if isinstance(c, WingLike):
            comps.append({"name": c.name, "type": c.kind, "le": _lst(c.le),
                          "chord": _lst(c.chord), "x_over_c": _lst(c.x_over_c),
                          "upper": _lst(c.upper), "lower": _lst(c.lower),
                          "camber": _lst(c.camber), "mirrored": c.mirrored,
                          "chordwise": c.chordwise})
        elif isinstance(c, CircularBody):
            d = {"name": c.name, "type": "circular_body", "x": _lst(c.x),
                 "radius": _lst(c.radius), "camber": _lst(c.camber), "origin": _lst(c.origin),
                 "segments": list(c.segments), "mirrored": c.mirrored, "axial": c.axial}
            if c.points_per_section:
                d["points_per_section"] = list(c.points_per_section)
            if c.slopes is not None:
                d["slopes"] = _lst(c.slopes)
            comps.append(d)
        else:
            comps.append({"name": c.name, "type": "arbitrary_body", "x": _lst(c.x),
                          "sections": [_lst(s) for s in c.sections],
                          "segments": list(c.segments), "mirrored": c.mirrored})
    ref = {k: v for k, v in (("area", cfg.reference_area), ("chord", cfg.reference_chord),
                             ("moment_x", cfg.moment_x)) if v is not None}
    return {"juncture": FORMAT_VERSION, "title": cfg.title, "reference": ref,
            "symmetric": cfg.symmetric, "components": comps}


def read(path):
    """Read a juncture model file (.json, or .toml) into a Configuration."""
    try:
        raw = open(path, "rb").read()
    except OSError as exc:
        raise DeckError(f"cannot open file: {exc.strerror}", path=path) from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise DeckError(f"not UTF-8 text (byte {exc.start})", path=path) from None
    if str(path).lower().endswith(".toml"):
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise DeckError(f"invalid TOML: {exc}", path=path) from None
    else:
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise DeckError(f"invalid JSON: {exc.msg}", path=path, line=exc.lineno,
                            columns=(exc.colno, exc.colno)) from None
    try:
        return configuration_from_dict(data)
    except SpecError as exc:
        raise DeckError(str(exc), path=path) from None


def write(obj, path):
    """Write a Configuration as a juncture JSON model (atomically)."""
    if not isinstance(obj, Configuration):
        raise SpecError(f"the juncture model format holds a Configuration, not a "
                        f"{type(obj).__name__}")
    with atomic_output(path, "w", encoding="utf-8") as fh:
        json.dump(configuration_to_dict(obj), fh, indent=1)
        fh.write("\n")


def _sniff(head):
    text = head.lstrip()
    if text.startswith(b"{"):
        return b'"juncture"' in head or b'"components"' in head
    return b"juncture =" in head or b"juncture=" in head


register_format("juncture", (".json", ".toml"), reader=read, writer=write, sniff=_sniff)
