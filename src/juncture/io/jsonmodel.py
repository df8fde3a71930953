"""juncture's own component model as JSON (``.json``) or TOML (``.toml``, read only).

The format is documented in ``docs/model-format.md``. It holds a Configuration losslessly:
every component with its arrays, in the units of the deck it came from, and the wave-drag
case cards (Mach number, NX, NTHETA, restraints, ...) of the deck it came from, so that deck ->
JSON -> deck keeps them. JSON numbers are written with Python's shortest round-trip repr, so
write -> read is exact.
"""

from __future__ import annotations

import json
import math
import tomllib
from dataclasses import dataclass

import numpy as np

from ..errors import DeckError, GeometryError, JunctureError, SpecError
from ..model import ArbitraryBody, CircularBody, Configuration, WingLike
from ._deck import CASE_FIELDS, DeckCase
from ._registry import atomic_output, read_input, register_format, require_configuration

__all__ = ["read", "write", "configuration_from_dict", "configuration_to_dict", "ModelSource",
           "xy_symmetric"]

_EXPECTED = "juncture model (JSON or TOML, docs/model-format.md)"


@dataclass(frozen=True, slots=True, eq=False)
class ModelSource:
    """``Configuration.source`` of a configuration read from a juncture model.

    Attributes
    ----------
    cases : tuple of juncture.io.wavedrag.DeckCase
        The wave-drag case cards the model carries (written back by the deck writer).
    path : str or None
        The file read.
    xy_symmetric : bool
        The deck's J6 = 1: the whole configuration is symmetric about the X-Y plane (written
        back by the deck writer).
    """

    cases: tuple = ()
    path: str | None = None
    xy_symmetric: bool = False

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


def _is_numbers(value):
    """True if ``value`` is a number or a (nested) list of numbers (not bool, not str)."""
    if isinstance(value, list):
        return all(_is_numbers(v) for v in value)
    return isinstance(value, int | float) and not isinstance(value, bool)


def _numbers(d, key, where, default=...):
    """Field ``key`` as a float array of finite numbers (nested lists), or ``default``."""
    if key not in d and default is not ...:
        return default
    value = _get(d, key, where, list)
    if not _is_numbers(value):
        raise SpecError(f"{where}: field {key!r} must hold numbers only (lists of numbers)")
    try:
        arr = np.array(value, dtype=float)
    except ValueError:
        raise SpecError(f"{where}: field {key!r} must be a rectangular array: its rows have "
                        "different lengths") from None
    if not np.all(np.isfinite(arr)):
        raise SpecError(f"{where}: field {key!r} holds a number out of range (inf or nan)")
    return arr


def _integers(d, key, where, default=...):
    """Field ``key`` as a list of integers >= 1, or ``default``."""
    if key not in d and default is not ...:
        return default
    value = _get(d, key, where, list)
    if not all(isinstance(v, int) and not isinstance(v, bool) and v >= 1 for v in value):
        raise SpecError(f"{where}: field {key!r} must be a list of integers >= 1, found "
                        f"{json.dumps(value)[:60]}")
    return value


def _sections(d, where):
    """Field ``sections``: one float array of [y, z] points per station."""
    return tuple(_numbers({"sections": sec}, "sections", f"{where}, section {i + 1}")
                 for i, sec in enumerate(_get(d, "sections", where, list)))


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
            return WingLike(name, ctype, _numbers(d, "le", where), _numbers(d, "chord", where),
                            _numbers(d, "x_over_c", where), _numbers(d, "upper", where),
                            _numbers(d, "lower", where, None), _numbers(d, "camber", where, None),
                            _get(d, "mirrored", where, bool, True),
                            _get(d, "chordwise", where, str, "pchip"))
        if ctype == "circular_body":
            _known(d, {"name", "type", "x", "radius", "camber", "origin", "segments",
                       "mirrored", "axial", "points_per_section", "slopes"}, where)
            pps = _integers(d, "points_per_section", where, None)
            return CircularBody(name, _numbers(d, "x", where), _numbers(d, "radius", where),
                                _numbers(d, "camber", where, None),
                                _numbers(d, "origin", where, [0.0, 0.0, 0.0]),
                                _integers(d, "segments", where, None),
                                _get(d, "mirrored", where, bool, False),
                                _get(d, "axial", where, str, "pchip"),
                                None if pps is None else tuple(pps),
                                _numbers(d, "slopes", where, None))
        if ctype == "arbitrary_body":
            _known(d, {"name", "type", "x", "sections", "segments", "mirrored", "params"},
                   where)
            params = None
            if "params" in d:
                params = tuple(_numbers({"params": p}, "params", f"{where}, params {i + 1}")
                               for i, p in enumerate(_get(d, "params", where, list)))
            return ArbitraryBody(name, _numbers(d, "x", where), _sections(d, where),
                                 _integers(d, "segments", where, None),
                                 mirrored=_get(d, "mirrored", where, bool, False),
                                 params=params)
    except GeometryError as exc:
        raise SpecError(f"{where}: {exc.reason}" + (f" (station {exc.station})"
                                                   if exc.station is not None else "")) from None
    except (TypeError, ValueError) as exc:  # anything the checks above let through
        raise SpecError(f"{where}: cannot build the component: {exc}") from None
    raise SpecError(f"{where}: type must be one of {', '.join(_WING_TYPES)}, circular_body, "
                    f"arbitrary_body; found {ctype!r}")


_CASE_INT_RANGE = (-999, 9999)  # what an I4 field holds


def _case(d, index):
    """One case card (``cases[index]``) as a DeckCase."""
    where = f"cases[{index}]"
    if not isinstance(d, dict):
        raise SpecError(f"{where}: must be an object, found {type(d).__name__}")
    _known(d, {"ncase", *CASE_FIELDS, "xrest"}, where)
    ncase = _get(d, "ncase", where, str, "")
    if len(ncase) > 4 or not ncase.isprintable():
        raise SpecError(f"{where}: field 'ncase' must be at most 4 printable characters, "
                        f"found {ncase!r}")
    values = {}
    lo, hi = _CASE_INT_RANGE
    for name in CASE_FIELDS:
        v = _get(d, name, where, int, 0)
        if isinstance(v, bool) or not lo <= v <= hi:
            raise SpecError(f"{where}: field {name!r} must be an integer in {lo}..{hi} (a "
                            f"4-column field of the case card), found {v!r}")
        values[name] = v
    if values["nrest"] < 0 or values["ncon"] not in (0, 1):
        raise SpecError(f"{where}: 'nrest' must be >= 0 and 'ncon' 0 or 1, found "
                        f"{values['nrest']} and {values['ncon']}")
    xrest = _numbers(d, "xrest", where, None)
    if (0 if xrest is None else xrest.size) != values["nrest"] or (
            xrest is not None and xrest.ndim != 1):
        raise SpecError(f"{where}: 'xrest' must hold nrest = {values['nrest']} restraint "
                        f"stations, found {0 if xrest is None else xrest.size}")
    return DeckCase(ncase.ljust(4), **values, xrest=xrest if values["nrest"] else None)


def _case_dict(case):
    d = {"ncase": case.ncase.rstrip(" ")}
    d.update({name: getattr(case, name) for name in CASE_FIELDS})
    if case.xrest is not None and case.xrest.size:
        d["xrest"] = _lst(case.xrest)
    return d


def configuration_from_dict(data, path=None):
    """Build a Configuration from the parsed JSON/TOML object (see docs/model-format.md).

    Its ``source`` is a :class:`ModelSource` holding the case cards and ``path``.
    """
    if not isinstance(data, dict):
        raise SpecError(f"the model must be an object, found {type(data).__name__}")
    _known(data, {"juncture", "title", "reference", "symmetric", "xy_symmetric", "components",
                  "cases"}, "model")
    version = _get(data, "juncture", "model", int)
    if version != FORMAT_VERSION:
        raise SpecError(f"model: format version {version} is not supported (expected "
                        f"{FORMAT_VERSION})")
    ref = _get(data, "reference", "model", dict, {})
    _known(ref, {"area", "chord", "moment_x"}, "reference")
    for key, value in ref.items():
        if isinstance(value, bool) or not isinstance(value, int | float) \
                or not math.isfinite(value):
            raise SpecError(f"reference: field {key!r} must be a finite number, found "
                            f"{value!r}")
    cases = tuple(_case(c, i) for i, c in enumerate(_get(data, "cases", "model", list, [])))
    comps = [_component(c, i) for i, c in enumerate(_get(data, "components", "model", list))]
    names = [c.name for c in comps]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise SpecError(f"model: component names must be unique, repeated: {', '.join(dup)}")
    return Configuration({c.name: c for c in comps}, title=_get(data, "title", "model", str, ""),
                         reference_area=ref.get("area"), reference_chord=ref.get("chord"),
                         moment_x=ref.get("moment_x"),
                         symmetric=_get(data, "symmetric", "model", bool, True),
                         source=ModelSource(cases, None if path is None else str(path),
                                            _get(data, "xy_symmetric", "model", bool, False)))


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
            d = {"name": c.name, "type": "arbitrary_body", "x": _lst(c.x),
                 "sections": [_lst(s) for s in c.sections],
                 "segments": list(c.segments), "mirrored": c.mirrored}
            if c.params is not None:
                d["params"] = [_lst(p) for p in c.params]
            comps.append(d)
    ref = {k: v for k, v in (("area", cfg.reference_area), ("chord", cfg.reference_chord),
                             ("moment_x", cfg.moment_x)) if v is not None}
    out = {"juncture": FORMAT_VERSION, "title": cfg.title, "reference": ref,
           "symmetric": cfg.symmetric, "components": comps}
    if xy_symmetric(cfg):
        out["xy_symmetric"] = True
    cases = getattr(cfg.source, "cases", None) or ()
    if cases:
        out["cases"] = [_case_dict(c) for c in cases]
    return out


def xy_symmetric(cfg):
    """Whether ``cfg`` came from a deck (or model) that declares X-Y symmetry (J6 = 1)."""
    src = cfg.source
    control = getattr(src, "control", None)
    return bool(getattr(src, "xy_symmetric", False) or getattr(control, "j6", 0) == 1)


def read(path):
    """Read a juncture model file (.json, or .toml) into a Configuration.

    Raises
    ------
    DeckError
        The file cannot be opened, is empty, binary or not UTF-8, is not valid JSON/TOML
        (with line and column), or does not describe a model (naming the field).
    """
    raw = read_input(path, _EXPECTED)
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise DeckError(f"not UTF-8 text (byte {exc.start}): expected a {_EXPECTED}",
                        path=path) from None
    if str(path).lower().endswith(".toml"):
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise DeckError(f"invalid TOML ({exc}): expected a {_EXPECTED}", path=path) \
                from None
    else:
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise DeckError(f"invalid JSON ({exc.msg}): expected a {_EXPECTED}", path=path,
                            line=exc.lineno, columns=(exc.colno, exc.colno)) from None
        except RecursionError:
            raise DeckError(f"JSON nested too deeply: expected a {_EXPECTED}",
                            path=path) from None
    try:
        return configuration_from_dict(data, path)
    except SpecError as exc:
        raise DeckError(str(exc), path=path) from None
    except RecursionError:
        raise DeckError(f"lists nested too deeply: expected a {_EXPECTED}", path=path) from None


def write(obj, path):
    """Write a Configuration as a juncture JSON model (atomically), with its case cards."""
    cfg = require_configuration(obj, path, "juncture JSON model")
    if str(path).lower().endswith(".toml"):
        raise JunctureError(f"cannot write {path}: juncture reads TOML models but writes JSON "
                            "only; give a .json file name")
    with atomic_output(path, "w", encoding="utf-8") as fh:
        json.dump(configuration_to_dict(cfg), fh, indent=1)
        fh.write("\n")


def _sniff(head):
    text = head.lstrip()
    if text.startswith(b"{"):
        return b'"juncture"' in head or b'"components"' in head
    return b"juncture =" in head or b"juncture=" in head


register_format("juncture", (".json", ".toml"), reader=read, writer=write, sniff=_sniff,
                write_extensions=(".json",))
