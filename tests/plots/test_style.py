"""One colour per component everywhere, and unit labels: juncture.plots.style."""

import subprocess
import sys

import pytest

from juncture.plots.style import (
    CASE_COLOURS,
    INTERSECTION_COLOUR,
    axis_label,
    component_colour,
    component_of,
    unit_label,
)

KINDS = ["body", "wing", "fillet", "fin 1", "pod 1", "tail 1", "canard 1", "pylon 1",
         "strake"]


def test_each_kind_has_its_own_hue_and_members_shades_of_it():
    hues = [component_colour(k) for k in KINDS]
    assert len(set(hues)) == len(hues)
    assert INTERSECTION_COLOUR not in hues
    assert not set(hues) & set(CASE_COLOURS)
    fins = [component_colour(f"fin {n}") for n in range(1, 6)]
    assert len(set(fins)) == 5
    # Shades: the same hue mixed with black or white keeps the channel order.
    rgb = [tuple(int(c[k:k + 2], 16) for k in (1, 3, 5)) for c in fins]
    order = sorted(range(3), key=lambda k: rgb[0][k])
    assert all(sorted(range(3), key=lambda k: c[k]) == order for c in rgb[1:3])


@pytest.mark.parametrize(("name", "same_as"), [
    (" Wing ", "wing"), ("FUSELAGE", "body"), ("horizontal tail", "tail 1"),
    ("nacelle 2", "pod 2"), ("main wing", "wing"), ("fillet upper", "fillet")])
def test_names_of_one_kind_share_the_colour(name, same_as):
    assert component_colour(name) == component_colour(same_as)


def test_unknown_names_get_a_stable_colour_in_any_process():
    here = component_colour("ventral strut")
    code = ("from juncture.plots.style import component_colour; "
            "print(component_colour('ventral strut'))")
    for seed in ("0", "123"):
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                             env={"PYTHONHASHSEED": seed, "PATH": ""}, check=True)
        assert out.stdout.strip() == here
    assert here.startswith("#") and len(here) == 7


@pytest.mark.parametrize(("network", "components", "aliases", "expected"), [
    ("fin 1 outboard image", (), None, "fin 1"),
    ("pod 2", ("pod 2", "pod 1"), None, "pod 2"),
    ("body upper", ("fuselage",), {"body": "fuselage"}, "fuselage"),
    ("wing lower image", ("main wing", "fuselage"), {"wing": "main wing"}, "main wing"),
    ("FUSELAGE SEGMENT #           2", (), None, "FUSELAGE"),
    ("tail 1 upper", ("tail 1", "tail 10"), None, "tail 1"),
])
def test_component_of_a_network(network, components, aliases, expected):
    assert component_of(network, components, aliases) == expected


def test_unit_labels():
    assert axis_label("x, aft") == "x, aft [ft]"
    assert axis_label("area", "m", 2) == "area [m\u00b2]"
    assert unit_label("in", 3) == "in\u00b3" and unit_label("ft", 5) == "ft\u2075"
    assert unit_label("0.1 m", 2) == "(0.1 m)\u00b2"
    assert unit_label("", 2) == "length\u00b2"
