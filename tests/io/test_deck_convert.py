"""Deck -> Configuration -> deck: the model's view of the wave-drag deck."""

import warnings

import numpy as np
import pytest
from scipy.spatial import cKDTree

import juncture as jc
from juncture.io._deck_convert import configuration_to_deck
from juncture.io.wavedrag import format_deck, parse_deck
from juncture.model import CircularBody, WingLike
from tests.support import EXAMPLE_DECK, PDAS_DECK, PDAS_WGS


def read(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(path)


def all_points(geo):
    return np.concatenate([n.reshape(-1, 3) for n in geo.networks.values()])


def test_pdas_deck_converts_to_the_points_of_the_pdas_converter(tmp_path):
    out = tmp_path / "wdcase1.wgs"
    jc.write(read(PDAS_DECK), out)
    ours, theirs = all_points(jc.read(out)), all_points(jc.read(PDAS_WGS))
    assert len(ours) == len(theirs) == 138
    # Both ways: every PDAS point has one of ours within 1e-4 and vice versa.
    assert cKDTree(ours).query(theirs)[0].max() < 1e-4
    assert cKDTree(theirs).query(ours)[0].max() < 1e-4


def test_pdas_components_by_hand():
    cfg = read(PDAS_DECK)
    assert list(cfg.components) == ["wing", "body"]
    body = cfg["body"]
    assert isinstance(body, CircularBody) and body.segments == (6, 2, 6)
    np.testing.assert_allclose(body.radius[:6], np.sqrt(np.array([0, 40.7, 128.7, 221.7, 289.5,
                                                                  314.16]) / np.pi))
    wing = cfg["wing"]
    np.testing.assert_array_equal(wing.le, [[100, 10, 0], [240, 150, 0]])
    np.testing.assert_array_equal(wing.chord, [140, 0])
    assert cfg.reference_area == 16.0


def test_example_components_and_options():
    cfg = read(EXAMPLE_DECK)
    assert list(cfg.components) == ["wing", "body", "pod 1", "pod 2", "fin 1", "fin 2", "fin 3",
                                    "tail 1"]
    wing = cfg["wing"]
    assert isinstance(wing, WingLike) and wing.n_sections == 7 and wing.n_stations == 13
    assert wing.camber.any() and not np.array_equal(wing.upper, wing.lower)
    assert cfg["body"].camber.any()  # J6 = 0: ZFUS cards read
    assert cfg["pod 1"].mirrored and not cfg["fin 3"].mirrored  # centre-line fin
    tail = cfg["tail 1"]
    assert not np.array_equal(tail.upper[0], tail.upper[1])  # NCAN < 0: root and tip differ


@pytest.mark.parametrize("path", [PDAS_DECK, EXAMPLE_DECK])
def test_configuration_written_without_its_source_reads_back_to_the_same_surfaces(path):
    cfg = read(path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        text = format_deck(configuration_to_deck(cfg.replace(source=None)))
        again = read_text(text)
    for name, comp in cfg.components.items():
        for a, b in zip(comp.networks().values(), again[name].networks().values()):
            np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12)


def read_text(text):
    from juncture.io._deck_convert import deck_to_configuration

    return deck_to_configuration(parse_deck(text), 0)


@pytest.mark.parametrize("path", [PDAS_DECK, EXAMPLE_DECK])
def test_unchanged_configuration_writes_its_raw_records_back(path, tmp_path):
    cfg = read(path)
    out = tmp_path / "again.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("error", jc.JunctureWarning)  # exact: no precision warning
        text = format_deck(configuration_to_deck(cfg))
    out.write_text(text)
    assert text == format_deck(configuration_to_deck(read(out)))


def test_two_wings_cannot_be_a_deck():
    cfg = read(EXAMPLE_DECK)
    other = WingLike("wing 2", "wing", cfg["wing"].le, cfg["wing"].chord, cfg["wing"].x_over_c,
                     cfg["wing"].upper)
    with pytest.raises(jc.GeometryError, match="a wave-drag deck holds one wing, found 2"):
        configuration_to_deck(cfg.with_component(other))


def test_geometry_error_from_a_deck_names_its_line(tmp_path):
    # Fin tip below its root: a geometry fault only the model sees.
    text = EXAMPLE_DECK.read_text().splitlines()
    k = next(i for i, s in enumerate(text) if s.rstrip().endswith("FINORG 3"))
    text[k] = "  242.0    0.0   26.0   48.0  281.0    0.0    4.0   18.0".ljust(72) + "FINORG 3"
    bad = tmp_path / "bad.inp"
    bad.write_text("\n".join(text) + "\n")
    with pytest.raises(jc.DeckError, match=rf"line {k + 1}: fin 3, station 2: section z"):
        read(bad)


def test_a_missing_configuration_is_a_deck_error():
    with pytest.raises(jc.DeckError, match=r"holds 1 configuration\(s\); configuration 3"):
        jc.read(PDAS_DECK, configuration=3)
