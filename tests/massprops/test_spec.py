"""JSON mass-properties specs: evaluation, degree conversion, reports and every error path."""

from __future__ import annotations

import copy
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from juncture.errors import SpecError
from juncture.massprops import (
    Cuboid,
    Cylinder,
    Diamond,
    MassProperties,
    Naca4,
    Rotor,
    Sphere,
    WingSegment,
    evaluate_spec,
    format_table,
    load_spec,
    spec_report_json,
    validate_spec,
)

SPEC = {
    "title": "test airplane",
    "units": "ft, slug",
    "components": [
        {"name": "wing", "type": "wing", "side": "both", "root": [2.0, 0.5, -0.2],
         "semispan": 4.0, "chord": [1.2, 0.6], "thickness": [0.12, 0.09], "sweep": 10.0,
         "dihedral": 5.0, "airfoil": {"naca4": [2.969, -1.26, -3.516, 2.843, -1.015]},
         "mass": 3.0},
        {"type": "wing", "root": [6.0, 0.0, 0.0], "semispan": 1.5, "chord": [0.8, 0.5],
         "thickness": [0.1, 0.1], "airfoil": {"diamond": 0.4}, "density": 10.0},
        {"name": "prop", "type": "rotor", "blades": 3, "diameter": 5.0, "hub_diameter": 0.5,
         "hub_height": 0.4, "chord": [0.4, 0.2], "thickness": [0.15, 0.06],
         "center": [-0.5, 0.0, 0.0], "airfoil": {"naca4": "closed_te"}, "density": 2.5},
        {"name": "spar", "type": "cuboid", "center": [2.2, 0.0, -0.2], "size": [0.1, 8.0, 0.1],
         "density": 100.0},
        {"name": "actuator", "type": "cylinder", "center": [2.5, 1.0, -0.2],
         "axis": [1.0, 0.0, 0.0], "radius": 0.05, "length": 0.3, "inner_radius": 0.02,
         "mass": 0.1},
        {"name": "tank", "type": "sphere", "center": [1.0, 0.0, 0.0], "radius": 0.4,
         "inner_radius": 0.38, "density": 5.0},
        {"name": "pilot", "type": "point", "center": [1.5, 0.0, 0.5], "mass": 5.0},
    ],
}


def test_evaluate_spec_matches_the_python_api():
    total, parts = evaluate_spec(SPEC)
    names = [n for n, _ in parts]
    assert names == ["wing", "wing 2", "prop", "spar", "actuator", "tank", "pilot"]
    rad = math.radians
    expected = [
        WingSegment(4.0, 1.2, 0.6, 0.12, 0.09, rad(10.0), rad(5.0), "both", Naca4(),
                    (2.0, 0.5, -0.2)).mass_properties(mass=3.0),
        WingSegment(1.5, 0.8, 0.5, 0.1, 0.1, airfoil=Diamond(0.4),
                    root_quarter_chord=(6.0, 0.0, 0.0)).mass_properties(density=10.0),
        Rotor(3, 5.0, 0.5, 0.4, 0.4, 0.2, 0.15, 0.06, Naca4.preset("closed_te"),
              (-0.5, 0, 0)).mass_properties(density=2.5),
        Cuboid([2.2, 0, -0.2], [0.1, 8.0, 0.1]).mass_properties(density=100.0),
        Cylinder([2.5, 1.0, -0.2], [1, 0, 0], 0.05, 0.3, 0.02).mass_properties(mass=0.1),
        Sphere([1.0, 0, 0], 0.4, 0.38).mass_properties(density=5.0),
        MassProperties.point(5.0, [1.5, 0.0, 0.5]),
    ]
    for (name, got), want in zip(parts, expected, strict=True):
        assert got.name == name
        assert got.allclose(want, rtol=1e-14)
    assert total.name == "total"
    assert total.allclose(MassProperties.sum(expected), rtol=1e-13)


def test_angles_are_degrees():
    """Rectangular unswept panel, dihedral 30 deg: the CG rises by (b/2) sin 30 = b/4."""
    spec = {"components": [{"type": "wing", "semispan": 2.0, "chord": [1.0, 1.0],
                            "thickness": [0.1, 0.1], "dihedral": 30.0, "density": 1.0}]}
    total, _ = evaluate_spec(spec)
    assert total.cg[2] == pytest.approx(0.5, rel=1e-13)
    assert total.cg[1] == pytest.approx(math.sqrt(3) / 2, rel=1e-13)
    spec["components"][0].update(dihedral=0.0, sweep=45.0)
    total, _ = evaluate_spec(spec)
    # sheared aft by y tan 45 = y, so x_cg = b/2 + section centroid aft of the quarter chord,
    # integral (x - 1/4) mu / integral mu = (v1 / 4) / v0 (module docstring of thickness.py)
    v = Naca4().v
    assert total.cg[0] == pytest.approx(1.0 + v[1] / 4 / v[0], rel=1e-13)


def test_rotor_per_part_densities_as_in_table6():
    spec = {"components": [{"type": "rotor", "blades": 5, "diameter": 10.5, "hub_diameter": 1.0,
                            "hub_height": 0.85774, "chord": [0.87333, 0.29111],
                            "thickness": [0.16, 0.06], "hub_density": 2.54864,
                            "blade_mass": 1.91211}]}
    total, _ = evaluate_spec(spec)
    assert total.mass == pytest.approx(1.91211 + 2.54864 * math.pi * 0.25 * 0.85774, rel=1e-12)


def test_load_spec_and_reports(tmp_path):
    path = tmp_path / "plane.json"
    path.write_text(json.dumps(SPEC))
    spec = load_spec(path)
    assert spec == SPEC
    total, parts = evaluate_spec(spec)
    report = spec_report_json(total, parts)
    assert list(report) == ["total", "components"]
    assert report["total"]["name"] == "total" and len(report["components"]) == 7
    assert set(report["components"][2]) == {"name", "mass", "volume", "cg", "inertia_cg",
                                             "inertia_origin"}
    assert json.loads(json.dumps(report)) == report
    np.testing.assert_allclose(report["total"]["inertia_origin"], total.inertia_origin)
    table = format_table(total, parts)
    lines = table.splitlines()
    for name in ("wing 2", "prop", "actuator", "pilot", "total @ origin"):
        assert any(line.startswith(name) for line in lines)
    data = [line for line in lines[:-1] if not line.startswith("-")]
    assert len({len(line) for line in data}) == 1           # aligned columns
    assert "Ixy = -integral x y dm" in lines[-1]


def test_spec_is_not_mutated():
    spec = copy.deepcopy(SPEC)
    evaluate_spec(spec)
    assert spec == SPEC


def _wing(**changes):
    comp = {"name": "w", "type": "wing", "semispan": 2.0, "chord": [1.0, 0.5],
            "thickness": [0.1, 0.1], "density": 1.0}
    comp.update(changes)
    return {"components": [comp]}


@pytest.mark.parametrize("spec, match", [
    (_wing(semispan="2"), 'component 1 \\("w"\\): field "semispan" must be a number > 0, '
                          'found "2"'),
    (_wing(chord=[1.0]), 'field "chord" must be a list of 2 numbers >= 0 \\[root, tip\\], '
                         r'found \[1.0\]'),
    (_wing(thickness=[12, 10]), 'field "thickness" must be a list of 2 thickness/chord '
                                r'fractions in \[0, 1\].*\(0.12 for 12 %\), found \[12, 10\]'),
    (_wing(sweep=95), r'field "sweep" must be an angle in degrees, a number in \(-90, 90\)'),
    (_wing(side="port"), 'field "side" must be one of "right", "left", "both", found "port"'),
    (_wing(root=[0, 0]), r'field "root" must be a list of 3 numbers \[x, y, z\]'),
    (_wing(airfoil={"naca": "0012"}), 'field "airfoil" must be .*"naca4"'),
    (_wing(airfoil={"naca4": "nonesuch"}), 'field "airfoil" must be'),
    (_wing(airfoil={"diamond": 1.5}), 'field "airfoil" must be'),
    (_wing(span=3.0), 'component 1 \\("w"\\): unknown field "span" for a wing; expected '
                      'fields: airfoil, chord'),
    (_wing(mass=2.0), 'give exactly one of "density" and "mass", found both'),
    (_wing(name=3), 'field "name" must be a string, found 3'),
    (_wing(type="flap"), 'component 1 \\("w"\\): field "type" must be one of wing, rotor'),
    (_wing(dihedral=True), 'field "dihedral" must be an angle in degrees'),
    (_wing(density=float("inf")), 'field "density" must be a finite number'),
    ({"components": []}, 'field "components" must be a non-empty list'),
    ({"parts": []}, 'unknown top-level field "parts"; expected: components, title, units'),
    ({"components": [3]}, "component 1: expected an object"),
    ({"components": [{"name": "x"}]}, 'component 1 \\("x"\\): field "type" must be one of '
                                      '.*found nothing'),
    ({"components": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.0}]},
     'component 1: give exactly one of "density" and "mass", found neither'),
    ({"components": [{"type": "rotor", "blades": 2.5, "diameter": 1, "hub_diameter": .2,
                      "hub_height": .1, "chord": [.1, .1], "thickness": [.1, .1],
                      "density": 1}]}, 'field "blades" must be a whole number >= 1, found 2.5'),
    ({"components": [{"type": "rotor", "blades": 2, "diameter": 1, "hub_diameter": .2,
                      "hub_height": .1, "chord": [.1, .1], "thickness": [.1, .1],
                      "hub_density": 1}]}, r'\(or both "hub_density"\|"hub_mass" and '),
    ({"components": [{"type": "cuboid", "center": [0, 0, 0], "size": [1, 1, 1],
                      "axes": [[1, 0, 0]], "mass": 1}]}, 'field "axes" must be 3 orthonormal'),
    ({"components": [{"type": "point", "center": [0, 0, 0], "density": 1}]},
     'unknown field "density" for a point'),
    ("not a dict", "the spec must be a JSON object"),
    ({"title": 5, "components": [{"type": "point", "center": [0, 0, 0], "mass": 1}]},
     'field "title" must be a string'),
])
def test_field_errors(spec, match):
    with pytest.raises(SpecError, match=match):
        evaluate_spec(spec)


def test_missing_fields_all_reported_at_once():
    spec = {"components": [{"type": "wing", "density": 1.0},
                           {"name": "p", "type": "rotor", "blades": 2, "mass": 1.0}]}
    with pytest.raises(SpecError) as info:
        validate_spec(spec)
    problems = info.value.problems
    assert 'component 1: missing field "semispan" (a number > 0)' in problems
    assert 'component 1: missing field "chord" (a list of 2 numbers >= 0 [root, tip])' in problems
    assert any(p.startswith('component 2 ("p"): missing field "hub_height"') for p in problems)
    assert len(problems) == 3 + 5


def test_geometry_errors_name_the_component():
    spec = {"components": [{"type": "point", "center": [0, 0, 0], "mass": 1.0},
                           {"name": "prop", "type": "rotor", "blades": 2, "diameter": 1.0,
                            "hub_diameter": 2.0, "hub_height": 0.1, "chord": [0.1, 0.1],
                            "thickness": [0.1, 0.1], "density": 1.0}]}
    with pytest.raises(SpecError, match='component 2 \\("prop"\\): expected 0 < hub_diameter'):
        evaluate_spec(spec)
    spec = {"components": [{"type": "cuboid", "center": [0, 0, 0], "size": [1, 1, 1],
                            "axes": [[1, 0, 0], [1, 0, 0], [0, 0, 1]], "mass": 1}]}
    with pytest.raises(SpecError, match="component 1: axes must be 3 orthonormal rows"):
        evaluate_spec(spec)
    spec = {"components": [{"type": "point", "center": [0, 0, 0], "mass": 1.0},
                           {"type": "point", "center": [1, 0, 0], "mass": -1.0}]}
    with pytest.raises(SpecError, match="total: the combined mass is zero"):
        evaluate_spec(spec)


def test_load_spec_errors(tmp_path):
    with pytest.raises(SpecError, match="cannot read the spec"):
        load_spec(tmp_path / "missing.json")
    bad = tmp_path / "bad.json"
    bad.write_text('{"components": [\n  {"type": "point",, }\n]}')
    with pytest.raises(SpecError, match=r"bad.json, line 2, column 20: invalid JSON"):
        load_spec(bad)
    wrong = tmp_path / "wrong.json"
    wrong.write_text(json.dumps(_wing(chord="wide")))
    with pytest.raises(SpecError, match=r'wrong.json: component 1 \("w"\): field "chord"') as e:
        load_spec(wrong)
    assert len(e.value.problems) == 1


def test_documented_example_evaluates():
    doc = Path(__file__).resolve().parents[2] / "docs" / "massprops-spec.md"
    blocks = [json.loads(b) for b in re.findall(r"```json\n(.*?)```", doc.read_text(), re.S)]
    specs = [b for b in blocks if "components" in b]
    for fragment in (b for b in blocks if "components" not in b):    # a single component
        evaluate_spec({"components": [fragment]})
    assert len(specs) == 1
    example = specs[0]
    total, parts = evaluate_spec(example)
    assert [n for n, _ in parts][:2] == ["skin outside", "skin inside"]
    skin = parts[0][1] + parts[1][1]
    assert 0 < skin.volume < 0.2 * parts[0][1].volume and skin.is_physical()
    assert "-0 " not in format_table(total, parts) and total.is_physical()
