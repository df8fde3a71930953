"""The sweep spec: a base deck and the parameters to vary, read from TOML and expanded to cases.

A spec (``examples/sweep_transport.toml`` is a complete one)::

    base = "supersonic_transport.inp"      # deck, LaWGS or juncture JSON/TOML model,
                                           # relative to the spec file
    [complete]                             # fixed options of juncture.complete()
    fillet = "cubic"                       # "none", "cubic" or "circular"
    keep_area = true

    [analysis]                             # what each case computes
    mach = [1.2, 1.6, 2.0]                 # far-field wave drag at each Mach number
    n_x = 100                              # cuts per roll angle (default 101)
    n_theta = 16                           # Harris NTHETA (default 16)
    massprops = true                       # mass properties at unit density (default true)

    [sampling]
    method = "grid"                        # "grid", "random" or "lhs"
    n = 200                                # cases, for "random" and "lhs"
    seed = 1                               # for "random" and "lhs"

    [parameters.wing_z]                    # one table per parameter; its name is the column
    component = "wing"                     # or a list of components moved together
    field = "z"
    mode = "offset"                        # "set" (default), "offset" or "scale"
    values = [-2.0, 0.0, 2.0]              # or range = [start, stop, count],
                                           # or bounds = [low, high] (random, lhs)
    [parameters.fillet]
    option = "fillet"                      # a complete() option ...
    values = ["none", "cubic"]
    [parameters.mach]
    analysis = "mach"                      # ... or an analysis setting (mach, n_x, n_theta)
    values = [1.2, 2.0]

Sampling: ``grid`` takes every combination of the parameters' values (the first parameter
varies slowest); ``random`` and ``lhs`` (Latin hypercube, :class:`scipy.stats.qmc.LatinHypercube`)
draw ``n`` cases with ``seed``: a parameter with ``bounds`` is sampled uniformly in them, one
with ``values`` or ``range`` picks one of its values.

Every case has a key, the hash of everything that decides its result (the base file's bytes,
the fixed options, the analysis settings, the case's values and the juncture version), so a
sweep that is run again skips the cases it has finished, whatever their order.
"""

from __future__ import annotations

import hashlib
import json
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path

from .. import __version__
from ..errors import SpecError
from .edit import check_edit

__all__ = ["Parameter", "SweepSpec", "load_spec", "parse_spec", "ANALYSIS_KEYS"]

#: analysis settings and their defaults
ANALYSIS_KEYS = {"mach": (), "n_x": 101, "n_theta": 16, "massprops": True}
_TOP = {"base", "title", "complete", "analysis", "sampling", "parameters"}
_PARAM_KEYS = {"component", "field", "mode", "section", "station", "option", "analysis",
               "values", "range", "bounds"}
_METHODS = ("grid", "random", "lhs")


@dataclass(frozen=True)
class Parameter:
    """One varied quantity: a component field, a complete() option or an analysis setting.

    ``kind`` is ``"component"``, ``"option"`` or ``"analysis"``; ``target`` the field, option
    or setting; ``components`` the components a field edit applies to; ``index`` the 1-based
    section (wing-like) or station (body) of a per-section field, or None for all;
    ``values`` the discrete values (None when only ``bounds`` are given).
    """

    name: str
    kind: str
    target: str
    mode: str = "set"
    components: tuple = ()
    index: int | None = None
    values: tuple | None = None
    bounds: tuple | None = None

    def describe(self):
        """The parameter's inputs, as they enter the case key."""
        return {"kind": self.kind, "target": self.target, "mode": self.mode,
                "components": list(self.components), "index": self.index}


@dataclass(frozen=True)
class SweepSpec:
    """A parsed sweep spec (see the module docstring)."""

    base: Path
    base_bytes: bytes
    title: str
    complete: dict
    analysis: dict
    parameters: tuple
    method: str = "grid"
    n: int | None = None
    seed: int = 0
    text: str = ""

    @property
    def machs(self):
        """Every Mach number any case computes, sorted (the results' wave-drag columns)."""
        found = set(self.analysis["mach"])
        for p in self.parameters:
            if p.kind == "analysis" and p.target == "mach":
                found.update(p.values)
        return sorted(found)

    def cases(self):
        """The cases: a list of dicts parameter name -> value, in the spec's order."""
        if not self.parameters:
            return [{}]
        if self.method == "grid":
            return _grid(self.parameters)
        return _sampled(self.parameters, self.method, self.n, self.seed)

    def key(self, case):
        """The case's key: 16 hex digits of the SHA-256 of everything its result depends on."""
        blob = {"base": hashlib.sha256(self.base_bytes).hexdigest(), "complete": self.complete,
                "analysis": self.analysis, "version": __version__,
                "case": [[p.describe(), _plain(case[p.name])] for p in self.parameters]}
        text = json.dumps(blob, sort_keys=True, default=str)
        return hashlib.sha256(text.encode()).hexdigest()[:16]


def _plain(value):
    """A value as it is written to JSON (numpy scalars to Python)."""
    return value.item() if hasattr(value, "item") else value


def _grid(params):
    import itertools

    names = [p.name for p in params]
    return [dict(zip(names, combo)) for combo in itertools.product(*(p.values for p in params))]


def _sampled(params, method, n, seed):
    import numpy as np

    if method == "lhs":
        from scipy.stats import qmc

        u = qmc.LatinHypercube(d=len(params), seed=seed).random(n)
    else:
        u = np.random.default_rng(seed).random((n, len(params)))
    cases = []
    for row in u:
        case = {}
        for p, ui in zip(params, row):
            if p.bounds is not None:
                lo, hi = p.bounds
                case[p.name] = float(lo + ui * (hi - lo))
            else:
                case[p.name] = p.values[min(int(ui * len(p.values)), len(p.values) - 1)]
        cases.append(case)
    return cases


# ------------------------------------------------------------------------------ parsing
def load_spec(path):
    """Read and check a sweep spec file (TOML); errors name the file and the field."""
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as exc:
        raise SpecError(f"{path}: cannot read the sweep spec ({exc.strerror or exc})") from None
    except UnicodeDecodeError:
        raise SpecError(f"{path}: not a text file; expected a TOML sweep spec") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SpecError(f"{path}: invalid TOML: {exc}") from None
    return parse_spec(data, path.parent, text=text, where=str(path))


def parse_spec(data, root=".", text="", where="sweep spec"):
    """Check a spec given as a dict (the TOML's content); ``root`` resolves ``base``."""
    _table_of(data, _TOP, where, "a sweep spec")
    base = _base(data, Path(root), where)
    complete = _complete_options(_table(data, "complete", where), where)
    analysis = _analysis(_table(data, "analysis", where), where)
    sampling = _table(data, "sampling", where)
    method, n, seed = _sampling(sampling, where)
    params = tuple(_parameter(name, body, method, where)
                   for name, body in _table(data, "parameters", where).items())
    title = data.get("title", base.name)
    if not isinstance(title, str):
        raise SpecError(f"{where}: title: expected a string, found {title!r}")
    return SweepSpec(base=base, base_bytes=base.read_bytes(), title=title, complete=complete,
                     analysis=analysis, parameters=params, method=method, n=n, seed=seed,
                     text=text)


def _table_of(data, allowed, what, noun):
    """SpecError unless ``data`` is a table whose keys are all ``allowed``."""
    if not isinstance(data, dict):
        raise SpecError(f"{what}: expected a table, found {data!r}")
    unknown = sorted(set(data) - set(allowed))
    if unknown:
        raise SpecError(f"{what}: unknown key {unknown[0]!r}; {noun} has "
                        f"{', '.join(sorted(allowed))}")


def _table(data, key, where):
    value = data.get(key, {})
    if not isinstance(value, dict):
        raise SpecError(f"{where}: [{key}]: expected a table, found {value!r}")
    return value


def _base(data, root, where):
    if "base" not in data:
        raise SpecError(f"{where}: missing 'base', the deck or model every case starts from")
    if not isinstance(data["base"], str):
        raise SpecError(f"{where}: base: expected a file name, found {data['base']!r}")
    base = Path(data["base"])
    base = base if base.is_absolute() else root / base
    if not base.is_file():
        raise SpecError(f"{where}: base: no such file {base}")
    return base


def _complete_options(table, where):
    """Each fixed option checked alone (combinations are checked per case, where they meet)."""
    for name, value in table.items():
        _check_option(name, value, f"{where}: [complete] {name}")
    return dict(table)


def _check_option(name, value, what):
    from ..errors import OptionError
    from ..options import CompleteOptions

    if name == "fillet":
        if value not in ("none", "cubic", "circular"):
            raise SpecError(f"{what}: expected 'none', 'cubic' or 'circular', found {value!r}")
        return
    if name == "keep_area":
        if not isinstance(value, bool):
            raise SpecError(f"{what}: expected true or false, found {value!r}")
        return
    fields = CompleteOptions.__dataclass_fields__
    if name not in fields or name == "pairs":
        raise SpecError(f"{what}: no such option; the options are fillet, keep_area, "
                        f"{', '.join(sorted(f for f in fields if f != 'pairs'))}")
    try:
        CompleteOptions(**{name: value})
    except OptionError as exc:
        raise SpecError(f"{what}: {exc}") from None


def _analysis(table, where):
    out = dict(ANALYSIS_KEYS)
    for name, value in table.items():
        what = f"{where}: [analysis] {name}"
        if name not in ANALYSIS_KEYS:
            raise SpecError(f"{what}: no such setting; the settings are "
                            f"{', '.join(ANALYSIS_KEYS)}")
        if name == "mach":
            value = [value] if isinstance(value, (int, float)) else value
            if not isinstance(value, list):
                raise SpecError(f"{what}: expected a Mach number or a list, found {value!r}")
            value = tuple(_analysis_value("mach", v, what) for v in value)
        else:
            value = _analysis_value(name, value, what)
        out[name] = value
    return out


def _analysis_value(name, value, what):
    if name == "massprops":
        if not isinstance(value, bool):
            raise SpecError(f"{what}: expected true or false, found {value!r}")
        return value
    if name == "mach":
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not (math.isfinite(value) and value >= 1.0):
            raise SpecError(f"{what}: expected a Mach number >= 1, found {value!r}")
        return float(value)
    low = 3 if name == "n_x" else 1
    if isinstance(value, bool) or not isinstance(value, int) or value < low:
        raise SpecError(f"{what}: expected an integer >= {low}, found {value!r}")
    return value


def _sampling(table, where):
    unknown = sorted(set(table) - {"method", "n", "seed"})
    if unknown:
        raise SpecError(f"{where}: [sampling] {unknown[0]}: no such setting; the settings "
                        "are method, n, seed")
    method = table.get("method", "grid")
    if method not in _METHODS:
        raise SpecError(f"{where}: [sampling] method: expected one of {', '.join(_METHODS)}, "
                        f"found {method!r}")
    n, seed = table.get("n"), table.get("seed", 0)
    if method != "grid" and (isinstance(n, bool) or not isinstance(n, int) or n < 1):
        raise SpecError(f"{where}: [sampling] n: '{method}' sampling needs the number of "
                        f"cases, an integer >= 1, found {n!r}")
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise SpecError(f"{where}: [sampling] seed: expected an integer >= 0, found {seed!r}")
    return method, (n if method != "grid" else None), seed


def _parameter(name, body, method, where):
    what = f"{where}: [parameters.{name}]"
    _table_of(body, _PARAM_KEYS, what, "a parameter")
    kinds = [k for k in ("component", "option", "analysis") if k in body]
    if len(kinds) != 1:
        raise SpecError(f"{what}: give exactly one of component (with field), option or "
                        f"analysis, found {kinds or 'none'}")
    values, bounds = _values(body, method, what)
    kind = kinds[0]
    if kind == "component":
        comps = body["component"]
        comps = (comps,) if isinstance(comps, str) else comps
        if not (isinstance(comps, list | tuple) and comps
                and all(isinstance(c, str) for c in comps)):
            raise SpecError(f"{what}: component: expected a name or a list of names")
        if "field" not in body:
            raise SpecError(f"{what}: missing 'field', the component field to vary")
        index = body.get("section", body.get("station"))
        mode = body.get("mode", "set")
        check_edit(body["field"], mode, index, values, bounds, what)
        return Parameter(name, "component", body["field"], mode, tuple(comps), index,
                         values, bounds)
    if "mode" in body or "field" in body:
        raise SpecError(f"{what}: 'field' and 'mode' belong to component parameters")
    target = body[kind]
    if values is None:
        raise SpecError(f"{what}: {kind} {target!r} takes 'values' or 'range', not bounds")
    for v in values:
        if kind == "option":
            _check_option(target, v, f"{what} option {target}")
        elif target in ("mach", "n_x", "n_theta"):
            _analysis_value(target, v, f"{what} analysis {target}")
        else:
            raise SpecError(f"{what}: analysis: expected mach, n_x or n_theta, found {target!r}")
    return Parameter(name, kind, target, values=values)


def _values(body, method, what):
    given = [k for k in ("values", "range", "bounds") if k in body]
    if len(given) != 1:
        raise SpecError(f"{what}: give exactly one of values, range or bounds, found "
                        f"{given or 'none'}")
    if "values" in body:
        values = body["values"]
        if not isinstance(values, list) or not values:
            raise SpecError(f"{what}: values: expected a non-empty list, found {values!r}")
        return tuple(values), None
    if "range" in body:
        r = body["range"]
        if not (isinstance(r, list) and len(r) == 3 and _real(r[0]) and _real(r[1])
                and isinstance(r[2], int) and not isinstance(r[2], bool) and r[2] >= 1):
            raise SpecError(f"{what}: range: expected [start, stop, count], found {r!r}")
        import numpy as np

        return tuple(float(v) for v in np.linspace(r[0], r[1], r[2])), None
    b = body["bounds"]
    if not (isinstance(b, list) and len(b) == 2 and _real(b[0]) and _real(b[1])
            and b[0] <= b[1]):
        raise SpecError(f"{what}: bounds: expected [low, high] with low <= high, found {b!r}")
    if method == "grid":
        raise SpecError(f"{what}: bounds need random or lhs sampling; a grid takes values "
                        "or range")
    return None, (float(b[0]), float(b[1]))


def _real(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
