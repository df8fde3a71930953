"""JSON mass-properties specifications: load, check, evaluate, report (``juncture massprops``).

The format is documented field by field in ``docs/massprops-spec.md``. In short::

    {"title": "...", "units": "...",
     "components": [{"type": "wing" | "rotor" | "cuboid" | "cylinder" | "sphere" | "point",
                     "name": "...", ...fields of the type..., "density": rho | "mass": m}]}

Project axes (x aft, y right, z up); angles in DEGREES. A wing's ``root`` is where its root
quarter-chord is, whatever its ``side`` (a left wing's root is not mirrored; ``"both"`` is the
pair given by its right root). Every missing, unknown or ill-typed field is reported at once
in one :class:`~juncture.errors.SpecError`, each problem naming the component (1-based index
and name) and the field and saying what was expected.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from ..errors import GeometryError, SpecError
from .properties import MassProperties
from .rotor import Rotor
from .solids import Cuboid, Cylinder, PointMass, Sphere
from .thickness import NACA4_PRESETS, ConstantThickness, Diamond, Naca4
from .wing import WingSegment

__all__ = ["load_spec", "validate_spec", "evaluate_spec", "spec_report_json", "format_table",
           "COMPONENT_TYPES"]

_TOP_FIELDS = {"components", "title", "units"}
_DENSITY = {"density": "number", "mass": "number"}

# field -> kind; required fields listed separately. "deg" is a number in degrees.
_SCHEMAS = {
    "wing": ({"side": "side", "root": "vec3", "semispan": "positive", "chord": "pair",
              "thickness": "ratio_pair", "sweep": "deg", "dihedral": "deg",
              "airfoil": "airfoil", **_DENSITY},
             ("semispan", "chord", "thickness")),
    "rotor": ({"blades": "count", "diameter": "positive", "hub_diameter": "positive",
               "hub_height": "nonneg", "chord": "pair", "thickness": "ratio_pair",
               "center": "vec3", "axis": "vec3", "airfoil": "airfoil", **_DENSITY,
               "hub_density": "number", "hub_mass": "number", "blade_density": "number",
               "blade_mass": "number"},
              ("blades", "diameter", "hub_diameter", "hub_height", "chord", "thickness")),
    "cuboid": ({"center": "vec3", "size": "vec3", "axes": "matrix3", **_DENSITY},
               ("center", "size")),
    "cylinder": ({"center": "vec3", "axis": "vec3", "radius": "positive", "length": "positive",
                  "inner_radius": "nonneg", **_DENSITY},
                 ("center", "axis", "radius", "length")),
    "sphere": ({"center": "vec3", "radius": "positive", "inner_radius": "nonneg", **_DENSITY},
               ("center", "radius")),
    "point": ({"center": "vec3", "mass": "number"}, ("center", "mass")),
}
#: The component types a spec may use.
COMPONENT_TYPES = tuple(_SCHEMAS)

_EXPECT = {
    "number": "a finite number",
    "positive": "a number > 0",
    "nonneg": "a number >= 0",
    "deg": "an angle in degrees, a number in (-90, 90)",
    "count": "a whole number >= 1",
    "vec3": "a list of 3 numbers [x, y, z]",
    "pair": "a list of 2 numbers >= 0 [root, tip]",
    "ratio_pair": "a list of 2 thickness/chord fractions in [0, 1] [root, tip] (0.12 for 12 %)",
    "side": 'one of "right", "left", "both"',
    "matrix3": "3 orthonormal rows of 3 numbers [[...], [...], [...]]",
    "airfoil": ('{"naca4": [a0, a1, a2, a3, a4]}, {"naca4": "<preset>"} with a preset in '
                + ", ".join(sorted(NACA4_PRESETS)) + ', {"diamond": x_m} with 0 <= x_m <= 1, '
                'or {"constant": 1} (mu = 1, a rectangular section: a tank)'),
}


def _is_num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _nums(v, n):
    return isinstance(v, list) and len(v) == n and all(_is_num(x) for x in v)


def _check_airfoil(v):
    if not isinstance(v, dict) or len(v) != 1:
        return False
    (key, val), = v.items()
    if key == "naca4":
        return _nums(val, 5) or (isinstance(val, str) and val in NACA4_PRESETS)
    if key == "constant":           # mu = 1 (paper section 5, fuel tanks); no other value
        return _is_num(val) and val == 1
    return key == "diamond" and _is_num(val) and 0 <= val <= 1


def _ok(kind, v):
    checks = {
        "number": _is_num,
        "positive": lambda x: _is_num(x) and x > 0,
        "nonneg": lambda x: _is_num(x) and x >= 0,
        "deg": lambda x: _is_num(x) and abs(x) < 90,
        "count": lambda x: isinstance(x, int) and not isinstance(x, bool) and x >= 1,
        "vec3": lambda x: _nums(x, 3),
        "pair": lambda x: _nums(x, 2) and min(x) >= 0,
        "ratio_pair": lambda x: _nums(x, 2) and min(x) >= 0 and max(x) <= 1,
        "side": lambda x: x in ("right", "left", "both"),
        "matrix3": lambda x: isinstance(x, list) and len(x) == 3 and all(_nums(r, 3) for r in x),
        "airfoil": _check_airfoil,
    }
    return checks[kind](v)


def _where(index, comp):
    name = comp.get("name") if isinstance(comp, dict) else None
    label = f' ("{name}")' if isinstance(name, str) else ""
    return f"component {index}{label}"


def _component_problems(index, comp):
    where = _where(index, comp)
    if not isinstance(comp, dict):
        return [f"{where}: expected an object {{...}}, found {type(comp).__name__}"]
    problems = []
    kind = comp.get("type")
    if kind not in _SCHEMAS:
        found = "nothing" if "type" not in comp else json.dumps(kind)
        return [f'{where}: field "type" must be one of {", ".join(COMPONENT_TYPES)}, '
                f"found {found}"]
    fields, required = _SCHEMAS[kind]
    if "name" in comp and not isinstance(comp["name"], str):
        problems.append(f'{where}: field "name" must be a string, found {json.dumps(comp["name"])}')
    for key in comp:
        if key in ("type", "name"):
            continue
        if key not in fields:
            problems.append(f'{where}: unknown field "{key}" for a {kind}; expected fields: '
                            f'{", ".join(sorted(fields))}')
        elif not _ok(fields[key], comp[key]):
            problems.append(f'{where}: field "{key}" must be {_EXPECT[fields[key]]}, found '
                            f"{json.dumps(comp[key])}")
    for key in required:
        if key not in comp:
            problems.append(f'{where}: missing field "{key}" ({_EXPECT[fields[key]]})')
    if kind != "point":
        given = [k for k in ("density", "mass") if k in comp]
        if kind == "rotor" and not given:
            given = ["per-part"] if all(any(f"{p}_{q}" in comp for q in ("density", "mass"))
                                        for p in ("hub", "blade")) else []
        if len(given) != 1:
            what = "both" if len(given) == 2 else "neither"
            extra = (' (or both "hub_density"|"hub_mass" and "blade_density"|"blade_mass")'
                     if kind == "rotor" else "")
            problems.append(f'{where}: give exactly one of "density" and "mass"{extra}, '
                            f"found {what}")
    return problems


def validate_spec(spec):
    """Check a spec (already parsed from JSON) and raise one SpecError listing every problem.

    Raises
    ------
    SpecError
        Its message joins the problems with ``"; "``; ``exc.problems`` holds them as a list.
    """
    if not isinstance(spec, dict):
        problems = [f"the spec must be a JSON object {{...}}, found {type(spec).__name__}"]
    else:
        problems = [f'unknown top-level field "{k}"; expected: components, title, units'
                    for k in spec if k not in _TOP_FIELDS]
        for key in ("title", "units"):
            if key in spec and not isinstance(spec[key], str):
                problems.append(f'field "{key}" must be a string, found {json.dumps(spec[key])}')
        comps = spec.get("components")
        if not isinstance(comps, list) or not comps:
            problems.append('field "components" must be a non-empty list of component objects, '
                            f"found {json.dumps(comps) if 'components' in spec else 'nothing'}")
        else:
            for i, comp in enumerate(comps, start=1):
                problems.extend(_component_problems(i, comp))
    if problems:
        err = SpecError("; ".join(problems))
        err.problems = problems
        raise err
    return spec


def load_spec(path):
    """Read and check a JSON spec file; returns the parsed dict.

    Raises
    ------
    SpecError
        Unreadable file, invalid JSON (with line and column) or any field problem.
    """
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise SpecError(f"{path}: cannot read the spec ({exc.strerror or exc})") from None
    try:
        spec = json.loads(text)
    except json.JSONDecodeError as exc:
        raise SpecError(f"{path}, line {exc.lineno}, column {exc.colno}: invalid JSON "
                        f"({exc.msg})") from None
    try:
        return validate_spec(spec)
    except SpecError as exc:
        err = SpecError(f"{path}: {exc}")
        err.problems = exc.problems
        raise err from None


def _airfoil(value):
    if value is None:
        return Naca4()
    (key, val), = value.items()
    if key == "diamond":
        return Diamond(float(val))
    if key == "constant":
        return ConstantThickness()
    return Naca4.preset(val) if isinstance(val, str) else Naca4(*map(float, val))


def _build(comp, name):
    kind = comp["type"]
    dens = {k: comp[k] for k in ("density", "mass") if k in comp}
    if kind == "wing":
        w = WingSegment(comp["semispan"], *comp["chord"], *comp["thickness"],
                        sweep=math.radians(comp.get("sweep", 0.0)),
                        dihedral=math.radians(comp.get("dihedral", 0.0)),
                        side=comp.get("side", "right"), airfoil=_airfoil(comp.get("airfoil")),
                        root_quarter_chord=comp.get("root", (0.0, 0.0, 0.0)), name=name)
        return w.mass_properties(**dens)
    if kind == "rotor":
        r = Rotor(comp["blades"], comp["diameter"], comp["hub_diameter"], comp["hub_height"],
                  *comp["chord"], *comp["thickness"], airfoil=_airfoil(comp.get("airfoil")),
                  center=comp.get("center", (0.0, 0.0, 0.0)),
                  axis=comp.get("axis", (1.0, 0.0, 0.0)), name=name)
        parts = {k: comp[k] for k in ("hub_density", "hub_mass", "blade_density", "blade_mass")
                 if k in comp}
        return r.mass_properties(**dens, **parts)
    if kind == "cuboid":
        return Cuboid(comp["center"], comp["size"], comp.get("axes"),
                      name=name).mass_properties(**dens)
    if kind == "cylinder":
        return Cylinder(comp["center"], comp["axis"], comp["radius"], comp["length"],
                        comp.get("inner_radius", 0.0), name=name).mass_properties(**dens)
    if kind == "sphere":
        return Sphere(comp["center"], comp["radius"], comp.get("inner_radius", 0.0),
                      name=name).mass_properties(**dens)
    return PointMass(comp["center"], comp["mass"], name=name).mass_properties()


def evaluate_spec(spec):
    """Mass properties of every component of a spec and of their sum.

    Parameters
    ----------
    spec : dict
        A parsed spec (see :func:`load_spec`); it is checked first.

    Returns
    -------
    total : MassProperties
        Named ``"total"``.
    parts : list of (str, MassProperties)
        One per component, in order; names default to ``"<type> <index>"`` (1-based).

    Raises
    ------
    SpecError
        A field problem, or geometry a component cannot have (names the component).
    """
    validate_spec(spec)
    parts = []
    for i, comp in enumerate(spec["components"], start=1):
        name = comp.get("name", f"{comp['type']} {i}")
        try:
            props = _build(comp, name)
        except GeometryError as exc:
            raise SpecError(f"{_where(i, comp)}: {exc.reason}") from None
        parts.append((name, props.renamed(name)))
    try:
        total = MassProperties.sum((p for _, p in parts), name="total")
    except GeometryError as exc:
        raise SpecError(f"total: {exc.reason}") from None
    return total, parts


def spec_report_json(total, parts):
    """``{"total": P, "components": [P, ...]}`` with P = :meth:`MassProperties.to_dict`."""
    return {"total": total.renamed(total.name or "total").to_dict(),
            "components": [p.renamed(n).to_dict() for n, p in parts]}


_PAIRS = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


def format_table(total, parts):
    """An aligned plain-text table: one row per component and the total.

    Columns: mass, volume, CG (x, y, z) and the inertia tensor about each row's own CG (Ixx,
    Iyy, Izz and the tensor elements Ixy, Ixz, Iyz = -integral x y dm ...), then the total's
    inertia about the origin. Numbers in ``%.6g``.
    """
    head = ["component", "mass", "volume", "x_cg", "y_cg", "z_cg",
            "Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"]

    def row(name, p, inertia):
        vals = [p.mass, p.volume, *p.cg, *(inertia[i, j] for i, j in _PAIRS)]
        return [name] + [f"{float(v) + 0.0:.6g}" for v in vals]   # + 0.0: no "-0"

    rows = [row(n, p, p.inertia) for n, p in parts]
    rows.append(row("total", total, total.inertia))
    rows.append(row("total @ origin", total, total.inertia_origin))
    widths = [max(len(r[k]) for r in [head, *rows]) for k in range(len(head))]

    def line(r):
        return "  ".join(r[0].ljust(widths[0]) if k == 0 else r[k].rjust(widths[k])
                         for k in range(len(r)))

    rule = "-" * len(line(head))
    out = [line(head), rule, *(line(r) for r in rows[:-2]), rule, line(rows[-2]), line(rows[-1])]
    out.append("Inertia about each row's CG (last row: about the origin), project axes x aft, "
               "y right, z up; Ixy = -integral x y dm.")
    return "\n".join(out) + "\n"
