"""Component edits of a sweep, checked against the geometry they should give (analytic)."""

import math

import numpy as np
import pytest

import juncture as jc
from juncture.errors import GeometryError, SpecError
from juncture.study.edit import apply_edit
from juncture.study.spec import Parameter
from support import EXAMPLE_DECK, wing_body


@pytest.fixture(scope="module")
def transport():
    return jc.read(EXAMPLE_DECK)


def _param(field, mode="set", comps=("wing",), index=None):
    return Parameter("p", "component", field, mode, tuple(comps), index)


def _le_sweep(wing, k=0):
    le = wing.le
    return math.degrees(math.atan2(le[-1, k] - le[0, k], le[-1, 1] - le[0, 1]))


@pytest.mark.parametrize("value", [0.0, 35.0, 62.5, -10.0])
def test_sweep_set_gives_that_root_to_tip_angle_and_keeps_the_cranks(transport, value):
    wing = transport["wing"]
    new = apply_edit(transport, _param("sweep"), value)["wing"]
    assert _le_sweep(new) == pytest.approx(value, abs=1e-12)
    # each section slid by (its span from the root) x (change of tan): panel tans shift alike
    dy = np.diff(wing.le[:, 1])
    old_t = np.diff(wing.le[:, 0]) / dy
    new_t = np.diff(new.le[:, 0]) / dy
    assert np.ptp(new_t - old_t) < 1e-12
    np.testing.assert_array_equal(new.le[:, 1:], wing.le[:, 1:])
    np.testing.assert_array_equal(new.chord, wing.chord)


def test_offsets_move_every_point_of_the_component(transport):
    for field, k in (("x", 0), ("y", 1), ("z", 2)):
        cfg = apply_edit(transport, _param(field, "offset", ("pod 1", "wing")), 0.75)
        for name in ("pod 1", "wing"):
            old, new = transport[name].networks(), cfg[name].networks()
            for key in old:
                shift = np.zeros(3)
                shift[k] = 0.75
                np.testing.assert_allclose(new[key], old[key] + shift, rtol=0, atol=1e-12)
        assert cfg["body"] is transport["body"]


def test_set_places_the_root_leading_edge_and_a_section(transport):
    cfg = apply_edit(transport, _param("z"), 1.25)
    assert cfg["wing"].le[0, 2] == 1.25
    np.testing.assert_allclose(np.diff(cfg["wing"].le[:, 2]), np.diff(transport["wing"].le[:, 2]))
    cfg = apply_edit(transport, _param("x", index=3), 151.0)
    np.testing.assert_array_equal(np.delete(cfg["wing"].le, 2, axis=0),
                                  np.delete(transport["wing"].le, 2, axis=0))
    assert cfg["wing"].le[2, 0] == 151.0


def test_dihedral_span_chord_thickness(transport):
    wing = transport["wing"]
    new = apply_edit(transport, _param("dihedral"), 5.0)["wing"]
    assert _le_sweep(new, 2) == pytest.approx(5.0, abs=1e-12)
    span = apply_edit(transport, _param("span", "scale"), 1.2)["wing"]
    np.testing.assert_allclose(span.le - span.le[0], 1.2 * (wing.le - wing.le[0]), atol=1e-12)
    assert _le_sweep(span) == pytest.approx(_le_sweep(wing), abs=1e-12)
    chord = apply_edit(transport, _param("chord", "scale", index=2), 0.5)["wing"]
    assert chord.chord[1] == 0.5 * wing.chord[1]
    np.testing.assert_array_equal(np.delete(chord.chord, 1), np.delete(wing.chord, 1))
    thick = apply_edit(transport, _param("thickness", "scale"), 1.5)["wing"]
    np.testing.assert_allclose(thick.upper, 1.5 * wing.upper)
    np.testing.assert_allclose(thick.lower, 1.5 * wing.lower)


def test_body_area_radius_and_length(transport):
    body = transport["body"]
    k = int(np.argmax(body.radius))
    cfg = apply_edit(transport, _param("area", "set", ("body",), k + 1), 100.0)
    assert math.pi * cfg["body"].radius[k] ** 2 == pytest.approx(100.0, rel=1e-14)
    cfg = apply_edit(transport, _param("area", "scale", ("body",)), 1.21)
    np.testing.assert_allclose(cfg["body"].radius, 1.1 * body.radius, rtol=1e-14)
    cfg = apply_edit(transport, _param("length", "set", ("body",)), 330.0)
    assert cfg["body"].length == pytest.approx(330.0, rel=1e-14)
    assert cfg["body"].x[0] == body.x[0]


def test_edits_that_do_not_fit_the_component(transport):
    with pytest.raises(SpecError, match="circular body .*pod 1.* has no set 'sweep'"):
        apply_edit(transport, _param("sweep", comps=("pod 1",)), 10.0)
    with pytest.raises(SpecError, match="no component 'canard'"):
        apply_edit(transport, _param("z", comps=("canard",)), 1.0)
    with pytest.raises(GeometryError, match="fin 1: a fin or pylon has no dihedral"):
        apply_edit(transport, _param("dihedral", comps=("fin 1",)), 3.0)
    with pytest.raises(GeometryError, match="wing: sweep 95 deg"):
        apply_edit(transport, _param("sweep"), 95.0)
    with pytest.raises(GeometryError, match="no section 9"):
        apply_edit(transport, _param("chord", index=9), 1.0)
    with pytest.raises(GeometryError, match="chord is negative"):
        apply_edit(transport, _param("chord", "offset", index=1), -1e4)


def test_code_built_configuration_sweeps_too():
    cfg = wing_body(sweep_deg=30.0)
    new = apply_edit(cfg, _param("sweep", "offset"), 10.0)["wing"]
    assert _le_sweep(new) == pytest.approx(_le_sweep(cfg["wing"]) + 10.0, abs=1e-12)
