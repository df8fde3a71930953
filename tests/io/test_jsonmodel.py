"""juncture's JSON/TOML model: exact round trip and clear errors."""

import json
import warnings

import numpy as np
import pytest

import juncture as jc
from tests.support import EXAMPLE_DECK


def example():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(EXAMPLE_DECK)


def test_json_round_trip_is_exact(tmp_path):
    cfg = example()
    jc.write(cfg, tmp_path / "sst.json")
    back = jc.read(tmp_path / "sst.json")
    assert list(back.components) == list(cfg.components)
    assert back.reference_area == cfg.reference_area
    for name in cfg.components:
        for a, b in zip(cfg[name].networks().values(), back[name].networks().values()):
            np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("deck", ["two_configurations_canard_signs.inp",
                                  "two_configurations_four_canard_sets.inp"])
def test_deck_json_deck_keeps_the_control_card_j6(tmp_path, deck):
    """J6 = 1 (X-Y symmetry) and J6 = -1 survive deck -> JSON -> deck (the JSON model says
    ``xy_symmetric``); compared on the control card's field (columns 19-21)."""
    from tests.support import DATA

    src = DATA / "decks" / deck
    jc.write(jc.read(src), tmp_path / "m.json")
    jc.write(jc.read(tmp_path / "m.json"), tmp_path / "back.inp")
    j6 = [p.read_text().splitlines()[1][18:21] for p in (src, tmp_path / "back.inp")]
    assert j6[0] == j6[1]
    assert json.loads((tmp_path / "m.json").read_text()).get("xy_symmetric", False) == (
        j6[0].strip() == "1")


def test_toml_reads_the_same_model(tmp_path):
    toml = tmp_path / "w.toml"
    toml.write_text('juncture = 1\ntitle = "plate"\n[[components]]\nname = "wing"\n'
                    'type = "wing"\nle = [[0.0, 0.0, 0.0], [1.0, 5.0, 0.0]]\nchord = [4.0, 2.0]\n'
                    'x_over_c = [0.0, 50.0, 100.0]\nupper = [[0.0, 3.0, 0.0], [0.0, 3.0, 0.0]]\n')
    cfg = jc.read(toml)
    np.testing.assert_allclose(cfg["wing"].point(5.0, 0.5), [2.0, 5.0, 0.06])


@pytest.mark.parametrize("mutate, match", [
    (lambda d: d["components"][0].pop("chord"), r"components\[0\] \('wing'\): missing field"),
    (lambda d: d["components"][0].update(span=3), r"unknown field\(s\) 'span'"),
    (lambda d: d["components"][0].update(type="rudder"), r"type must be one of"),
    (lambda d: d["components"][1]["radius"].__setitem__(0, -1.0),
     r"components\[1\] \('body'\): radius is negative \(-1\) \(station 1\)"),
    (lambda d: d.update(juncture=9), r"format version 9 is not supported"),
])
def test_bad_models_name_the_field(tmp_path, mutate, match):
    from juncture.io.jsonmodel import configuration_to_dict

    d = configuration_to_dict(example())
    mutate(d)
    p = tmp_path / "bad.json"
    p.write_text(json.dumps(d))
    with pytest.raises(jc.DeckError, match=match):
        jc.read(p)


def test_json_syntax_error_names_line_and_column(tmp_path):
    p = tmp_path / "bad.json"
    p.write_text('{"juncture": 1,\n "components": [,]}\n')
    with pytest.raises(jc.DeckError, match=r"bad.json, line 2, column 17: invalid JSON"):
        jc.read(p)


def test_a_re_designed_fuselage_round_trips_with_its_slopes(tmp_path):
    geo = jc.complete(example(), "cubic", keep_area=True)
    cfg = geo.configuration
    body = cfg["body"]
    assert body.slopes is not None
    jc.write(cfg, tmp_path / "redesigned.json")
    back = jc.read(tmp_path / "redesigned.json")["body"]
    np.testing.assert_array_equal(back.slopes, body.slopes)
    xq = np.linspace(body.x_global[0], body.x_global[-1], 997)
    np.testing.assert_array_equal(back.radius_at(xq), body.radius_at(xq))


def test_a_re_designed_arbitrary_fuselage_round_trips_with_its_parameters(tmp_path):
    from tests.test_complete import squashed

    geo = jc.complete(squashed(example()), "cubic", keep_area=True)
    body = geo.configuration["body"]
    assert body.params is not None
    jc.write(geo.configuration, tmp_path / "redesigned.json")
    back = jc.read(tmp_path / "redesigned.json")["body"]
    xq = np.linspace(body.x_global[0], body.x_global[-1], 397)
    s = np.linspace(0.0, 1.0, 41)
    np.testing.assert_array_equal(back.point(xq[:, None], s[None]),
                                  body.point(xq[:, None], s[None]))
