"""The JSON specification of a long-strake blend, its defaults and validation.

A spec is a JSON object with the sections below; every field is optional except
``body.radius`` (or ``body.section``) and the wing planform. ``null`` means "derive the
default from wing and body". Lengths are in the spec's own unit, angles in degrees.

.. code-block:: text

    title                       free text
    body.radius                 R of a circular body                                   [length]
    body.section                or a closed section: [[y, z], ...] with increasing angle
    body.z_axis                 height of the circular body's axis (0)                 [length]
    body.x_start, body.x_end    axial extent of the body network                       [length]
    wing.root_chord, tip_chord  chords at y_root and at semi_span                      [length]
    wing.x_le_root              leading edge x at y_root                               [length]
    wing.sweep_le_deg           leading-edge sweep (0)                                  [deg]
    wing.semi_span              tip station y                                           [length]
    wing.y_root                 root station (0: on the axis, inside the body)          [length]
    wing.z                      wing plane height (0)                                   [length]
    wing.thickness              NACA 4-digit thickness ratio (0.08)
    wing.sections               or explicit sections [{y, x_le, z_le, chord, thickness}, ...]
    lines.wing_line_y           station of the wing line AB (junction + 0.25 c_j)       [length]
    lines.wing_line_xi          [xi_B, xi_A], xi = sqrt(x/c) on the upper surface ([0, 1])
    lines.enlarge               enlargement of the junction section for GH (1.3)
    lines.g_fraction            parameter of G on the enlarged section, xi_G (0.3)
    lines.base_offset           offset h between rho1 and rho2 (0.05 c_j)               [length]
    lines.strake_y, strake_z    strake edge CD position (mid-way to AB, wing height)    [length]
    lines.strake_x              x of C, aft end of the strake edge (x of M)             [length]
    lines.strake_length         length of CD (1.5 c_j)                                  [length]
    lines.nose_length           axial length of DE (0.5 c_j)                            [length]
    lines.nose_rise             height of E above the strake, fraction of G's (0.4)
    lines.plane_angle_deg       S3 tilt from horizontal about the axis (0)              [deg]
    blend.mu, lambda, beta      eq 5 and eq 6 factors (0.5, 0.5, 0.2)
    patch.elements              bicubic spans per side of the thin-plate patch (12)
    patch.stretch               [a11, a12, a22] of eq 20 ([5, 5, 5], the paper's values)
    patch.bend                  [b11, b12, b22] of eq 20 ([5, 5, 5])
    patch.de_normal             also prescribe W's tangent plane along DE (true; the paper: false)
    output.formats              network formats to write (["wgs", "p3d", "stl", "step", "igs"];
                                also "vtk")
    output.points               [n_lines, n_points] per patch network ([41, 25])
    output.figures              write PNG figures (true)
    output.include_components   also write untrimmed body and wing networks (true)

c_j is the wing chord at the junction with the body.
"""

from __future__ import annotations

import copy
import json
from pathlib import Path

import numpy as np

from ..errors import SpecError
from .surfaces import AirfoilWing, CircleSection, ConstantSectionBody, SplineSection

__all__ = ["DEFAULTS", "OUTPUT_FORMATS", "load_spec", "build_body", "build_wing"]

#: Network formats ``output.formats`` may name (written as DIR/blend.<name>).
OUTPUT_FORMATS = ("wgs", "p3d", "stl", "vtk", "step", "igs")

DEFAULTS = {
    "title": "long-strake wing-body blend",
    "body": {"radius": None, "section": None, "z_axis": 0.0, "x_start": None, "x_end": None},
    "wing": {"root_chord": None, "tip_chord": None, "x_le_root": None, "sweep_le_deg": 0.0,
             "semi_span": None, "y_root": 0.0, "z": 0.0, "thickness": 0.08,
             "sections": None},
    "lines": {"wing_line_y": None, "wing_line_xi": [0.0, 1.0], "enlarge": 1.3,
              "g_fraction": 0.3, "base_offset": None, "strake_y": None, "strake_z": None,
              "strake_x": None, "strake_length": None, "nose_length": None,
              "nose_rise": 0.4, "plane_angle_deg": 0.0},
    "blend": {"mu": 0.5, "lambda": 0.5, "beta": 0.2},
    "patch": {"elements": 12, "stretch": [5.0, 5.0, 5.0], "bend": [5.0, 5.0, 5.0],
              "de_normal": True},
    "output": {"formats": ["wgs", "p3d", "stl", "step", "igs"], "points": [41, 25],
               "figures": True, "include_components": True},
}


def _merge(defaults, given, where):
    if not isinstance(given, dict):
        raise SpecError(f"{where or 'spec'}: expected an object, found "
                        f"{type(given).__name__}")
    out = copy.deepcopy(defaults)
    for key, value in given.items():
        name = f"{where}.{key}" if where else key
        if key not in defaults:
            raise SpecError(f"unknown field {name!r}; known: {', '.join(sorted(defaults))}")
        if isinstance(defaults[key], dict):
            out[key] = _merge(defaults[key], value, name)
        else:
            out[key] = value
    return out


def _number(spec, path, positive=False, required=True):
    sec, key = path.split(".")
    value = spec[sec][key]
    if value is None:
        if required:
            raise SpecError(f"field {path!r} is required")
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or \
            not np.isfinite(value):
        raise SpecError(f"field {path!r} must be a finite number, found {value!r}")
    if positive and value <= 0:
        raise SpecError(f"field {path!r} must be positive, found {value!r}")
    return float(value)


def load_spec(source):
    """Read and validate a blend spec; fill defaults. Returns a plain nested dict.

    Parameters
    ----------
    source : str, path-like or dict
        A JSON file or an already-parsed object.

    Raises
    ------
    SpecError
        On unreadable JSON, unknown fields, missing or ill-typed values (names the field).
    """
    if isinstance(source, dict):
        return _checked(source)
    try:
        raw = Path(source).read_bytes()
    except OSError as exc:
        raise SpecError(f"{source}: cannot read the blend spec ({exc.strerror or exc})") \
            from None
    try:
        given = json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise SpecError(f"{source}: expected a JSON blend spec, found binary (non UTF-8) "
                        f"data") from None
    except json.JSONDecodeError as exc:
        raise SpecError(f"{source}, line {exc.lineno}, column {exc.colno}: invalid JSON "
                        f"({exc.msg})") from None
    try:
        return _checked(given)
    except SpecError as exc:
        raise SpecError(f"{source}: blend spec: {exc}") from None


def _checked(given):
    """The spec ``given`` (a parsed object) with defaults filled, every field checked."""
    spec = _merge(DEFAULTS, given, "")
    if spec["body"]["section"] is None:
        _number(spec, "body.radius", positive=True)
    if spec["wing"]["sections"] is None:
        for key in ("root_chord", "tip_chord", "semi_span"):
            _number(spec, f"wing.{key}", positive=True)
        _number(spec, "wing.x_le_root")
        for key in ("sweep_le_deg", "y_root", "z"):
            _number(spec, f"wing.{key}")
        _number(spec, "wing.thickness", positive=True)
    for key in ("enlarge", "g_fraction", "nose_rise"):
        _number(spec, f"lines.{key}", positive=True)
    for key in ("wing_line_y", "base_offset", "strake_y", "strake_z", "strake_x",
                "strake_length", "nose_length"):
        _number(spec, f"lines.{key}", required=False)
    for key in ("mu", "lambda", "beta"):
        _number(spec, f"blend.{key}")
    xi = spec["lines"]["wing_line_xi"]
    if not (isinstance(xi, list) and len(xi) == 2 and 0 <= xi[0] < xi[1] <= 1):
        raise SpecError(f"field 'lines.wing_line_xi' must be [xi_B, xi_A] with "
                        f"0 <= xi_B < xi_A <= 1, found {xi!r}")
    el = spec["patch"]["elements"]
    if isinstance(el, bool) or not isinstance(el, int) or not 2 <= el <= 200:
        raise SpecError(f"field 'patch.elements' must be an integer in [2, 200], found {el!r}")
    for key in ("stretch", "bend"):
        val = spec["patch"][key]
        if not (isinstance(val, list) and len(val) == 3 and
                all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in val)):
            raise SpecError(f"field 'patch.{key}' must be three numbers, found {val!r}")
    for sec, key in (("patch", "de_normal"), ("output", "figures"),
                     ("output", "include_components")):
        if not isinstance(spec[sec][key], bool):
            raise SpecError(f"field '{sec}.{key}' must be true or false, found "
                            f"{spec[sec][key]!r}")
    pts = spec["output"]["points"]
    if not (isinstance(pts, list) and len(pts) == 2 and
            all(isinstance(p, int) and p >= 3 for p in pts)):
        raise SpecError(f"field 'output.points' must be two integers >= 3, found {pts!r}")
    fmts = spec["output"]["formats"]
    if not isinstance(fmts, list):
        raise SpecError("field 'output.formats' must be a list of format names")
    for fmt in fmts:
        if fmt not in OUTPUT_FORMATS:
            raise SpecError(f"field 'output.formats': unknown format {fmt!r}; known: "
                            f"{', '.join(OUTPUT_FORMATS)}")
    return spec


def build_body(spec):
    """The ConstantSectionBody of a validated spec (x extent defaults around the wing)."""
    b = spec["body"]
    if b["section"] is not None:
        section = SplineSection(b["section"])
    else:
        section = CircleSection(float(b["radius"]), float(b["z_axis"]))
    w = spec["wing"]
    if w["sections"] is not None:
        xs = [s["x_le"] for s in w["sections"]]
        chord = max(s["chord"] for s in w["sections"])
    else:
        xs, chord = [w["x_le_root"]], w["root_chord"]
    x0 = b["x_start"] if b["x_start"] is not None else min(xs) - 4.0 * chord
    x1 = b["x_end"] if b["x_end"] is not None else max(xs) + 2.0 * chord
    return ConstantSectionBody(section, float(x0), float(x1))


def build_wing(spec):
    """The AirfoilWing of a validated spec (two sections from the planform, or explicit)."""
    w = spec["wing"]
    if w["sections"] is not None:
        try:
            cols = {k: [float(s[k]) for s in w["sections"]]
                    for k in ("y", "x_le", "z_le", "chord", "thickness")}
        except (KeyError, TypeError, ValueError) as exc:
            raise SpecError(f"field 'wing.sections': each section needs numbers y, x_le, "
                            f"z_le, chord, thickness ({exc})") from None
        return AirfoilWing(**cols)
    y0, y1 = w["y_root"], w["semi_span"]
    if not y1 > y0:
        raise SpecError(f"field 'wing.semi_span' ({y1}) must exceed wing.y_root ({y0})")
    x_tip = w["x_le_root"] + (y1 - y0) * np.tan(np.radians(w["sweep_le_deg"]))
    return AirfoilWing(y=[y0, y1], x_le=[w["x_le_root"], x_tip], z_le=[w["z"], w["z"]],
                       chord=[w["root_chord"], w["tip_chord"]],
                       thickness=[w["thickness"], w["thickness"]])
