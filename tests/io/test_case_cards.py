"""Case cards survive deck -> JSON/TOML -> deck and deck -> deck; deck writing is quiet.

The reference for each case card is the raw deck record read from the original file
(:func:`juncture.io.wavedrag.read_deck`): every field (NCASE, MACH, NX, NTHETA, NREST, NCON,
ICYC, KKODE, JRST, IALPH, IUP1, IUP2) and the restraint stations must come back, except that
the last case of a configuration written alone gets NCON = 0 (no configuration follows it).
"""

from __future__ import annotations

import json
import subprocess
import sys
import warnings

import numpy as np
import pytest

import juncture as jc
from juncture.errors import DeckError, JunctureWarning
from juncture.io import wavedrag as wd
from juncture.io._deck import CASE_FIELDS
from tests.support import DECKS_DIR, EXAMPLE_DECK, PDAS_DECK

#: (deck, configuration index) pairs with case cards.
WITH_CASES = [(PDAS_DECK, 0), (EXAMPLE_DECK, 0), (DECKS_DIR / "cambered_wing.inp", 0),
              (DECKS_DIR / "two_configurations_four_canard_sets.inp", 0),
              (DECKS_DIR / "two_configurations_four_canard_sets.inp", 1),
              (DECKS_DIR / "two_configurations_canard_signs.inp", 0),
              (DECKS_DIR / "two_configurations_canard_signs.inp", 1)]


def _ids(pairs):
    return [f"{p.stem}[{k}]" for p, k in pairs]


def _quiet(fn, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", JunctureWarning)
        return fn(*args, **kwargs)


def _raw_cases(path, k=0):
    return _quiet(wd.read_deck, path).configurations[k].cases


def _fields(case):
    """Everything a case card holds, as plain values."""
    xrest = None if case.xrest is None else case.xrest.tolist()
    return (case.ncase, *(getattr(case, f) for f in CASE_FIELDS), xrest)


def _expected(cases):
    """The cases of a configuration written alone: the last one has NCON = 0."""
    out = [list(_fields(c)) for c in cases]
    out[-1][1 + CASE_FIELDS.index("ncon")] = 0
    return [tuple(c) for c in out]


def test_the_samples_have_what_the_tests_need():
    all_cases = [c for p, k in WITH_CASES for c in _raw_cases(p, k)]
    assert any(c.nrest > 0 for c in all_cases) and any(c.ncon == 1 for c in all_cases)
    assert any(c.icyc or c.kkode or c.jrst or c.ialph for c in all_cases)
    assert len(_raw_cases(DECKS_DIR / "cambered_wing.inp")) == 2


@pytest.mark.parametrize("path, k", WITH_CASES, ids=_ids(WITH_CASES))
def test_deck_to_json_to_deck_keeps_the_case_cards(tmp_path, path, k):
    cfg = _quiet(wd.read, path, k)
    jc.write(cfg, tmp_path / "model.json")
    model = json.loads((tmp_path / "model.json").read_text())
    assert len(model["cases"]) == len(_raw_cases(path, k))
    back = jc.read(tmp_path / "model.json")
    jc.write(back, tmp_path / "again.inp")
    got = [_fields(c) for c in _raw_cases(tmp_path / "again.inp")]
    assert got == _expected(_raw_cases(path, k))
    # and once more through JSON: nothing drifts (but NCON, as above)
    jc.write(_quiet(jc.read, tmp_path / "again.inp"), tmp_path / "twice.json")
    model["cases"][-1]["ncon"] = 0
    assert json.loads((tmp_path / "twice.json").read_text())["cases"] == model["cases"]


@pytest.mark.parametrize("path, k", WITH_CASES, ids=_ids(WITH_CASES))
def test_deck_to_deck_keeps_the_case_cards(tmp_path, path, k):
    jc.write(_quiet(wd.read, path, k), tmp_path / "again.inp")
    got = [_fields(c) for c in _raw_cases(tmp_path / "again.inp")]
    assert got == _expected(_raw_cases(path, k))


def test_json_case_fields_are_the_card_fields(tmp_path):
    jc.write(_quiet(jc.read, PDAS_DECK), tmp_path / "m.json")
    (case,) = json.loads((tmp_path / "m.json").read_text())["cases"]
    assert case == {"ncase": "M1.2", "mach": 1200, "nx": 50, "ntheta": 16, "nrest": 2,
                    "ncon": 0, "icyc": 2, "kkode": 0, "jrst": 0, "ialph": 0, "iup1": 0,
                    "iup2": 0, "xrest": [100.0, 240.0]}


def test_a_deck_without_case_cards_gives_none(tmp_path):
    cfg = _quiet(jc.read, DECKS_DIR / "circular_body_4_segments.inp")
    jc.write(cfg, tmp_path / "m.json")
    assert "cases" not in json.loads((tmp_path / "m.json").read_text())
    jc.write(jc.read(tmp_path / "m.json"), tmp_path / "m.inp")
    assert _raw_cases(tmp_path / "m.inp") == ()


def test_toml_cases(tmp_path):
    toml = tmp_path / "w.toml"
    toml.write_text('juncture = 1\ntitle = "plate"\n[[components]]\nname = "wing"\n'
                    'type = "wing"\nle = [[0.0, 0.0, 0.0], [1.0, 5.0, 0.0]]\nchord = [4.0, 2.0]\n'
                    'x_over_c = [0.0, 50.0, 100.0]\nupper = [[0.0, 3.0, 0.0], [0.0, 3.0, 0.0]]\n'
                    '[[cases]]\nncase = "M2"\nmach = 2000\nnx = 50\nntheta = 8\nnrest = 1\n'
                    'xrest = [2.5]\n[[cases]]\nmach = 2500\nialph = -150\n')
    jc.write(jc.read(toml), tmp_path / "w.inp")
    got = [_fields(c) for c in _raw_cases(tmp_path / "w.inp")]
    assert got == [("M2  ", 2000, 50, 8, 1, 0, 0, 0, 0, 0, 0, 0, [2.5]),
                   ("    ", 2500, 0, 0, 0, 0, 0, 0, 0, -150, 0, 0, None)]
    text = (tmp_path / "w.inp").read_text().splitlines()
    assert text[-3].startswith("M2  2000  50   8   1   0") and text[-3][72:] == "CASE 1"


@pytest.mark.parametrize("case, match", [
    ({"mach": 12000}, r"cases\[0\]: field 'mach' must be an integer in -999..9999"),
    ({"mach": 1.5}, r"cases\[0\]: field 'mach' must be int, found float"),
    ({"ncase": "M1.25"}, r"cases\[0\]: field 'ncase' must be at most 4 printable"),
    ({"nrest": 2, "xrest": [1.0]}, r"'xrest' must hold nrest = 2 restraint stations, found 1"),
    ({"xrest": [1.0]}, r"'xrest' must hold nrest = 0 restraint stations, found 1"),
    ({"ncon": 2}, r"'ncon' 0 or 1"),
    ({"mach_number": 1.2}, r"cases\[0\]: unknown field\(s\) 'mach_number'"),
])
def test_bad_case_fields_name_the_field(tmp_path, case, match):
    jc.write(_quiet(jc.read, EXAMPLE_DECK), tmp_path / "m.json")
    model = json.loads((tmp_path / "m.json").read_text())
    model["cases"] = [case]
    (tmp_path / "bad.json").write_text(json.dumps(model))
    with pytest.raises(DeckError, match=match):
        jc.read(tmp_path / "bad.json")


# -- quiet writing ---------------------------------------------------------------------------

@pytest.mark.parametrize("path", [PDAS_DECK, EXAMPLE_DECK])
def test_json_to_deck_is_quiet(tmp_path, path):
    """No ResourceWarning (the JSON reader left its file open) and no precision warnings
    (a FUSARD area through r = sqrt(A / pi) and back is 1-2 ulps off its decimal)."""
    jc.write(_quiet(jc.read, path), tmp_path / "m.json")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        jc.write(jc.read(tmp_path / "m.json"), tmp_path / "m.inp")
        import gc

        gc.collect()
    assert [str(w.message) for w in caught] == []
    # and the areas are the deck's own decimals
    assert _quiet(wd.read_deck, tmp_path / "m.inp").configurations[0].fuselage.segments[0] \
        .area.tolist() == _quiet(wd.read_deck, path).configurations[0].fuselage.segments[0] \
        .area.tolist()


def test_convert_json_to_deck_prints_nothing_but_the_result(tmp_path):
    jc.write(_quiet(jc.read, EXAMPLE_DECK), tmp_path / "m.json")
    run = subprocess.run([sys.executable, "-W", "error", "-X", "dev", "-c",
                          "import sys; from juncture.cli import main; sys.exit(main())",
                          "convert", str(tmp_path / "m.json"), str(tmp_path / "out.inp")],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stderr == "" and run.stdout.strip() == f"wrote {tmp_path / 'out.inp'}"


def test_a_deck_that_must_round_warns_once_naming_the_file(tmp_path):
    cfg = _quiet(jc.read, EXAMPLE_DECK)
    wing = cfg["wing"]
    x = wing.x_over_c.copy()
    x[1:-1] = x[1:-1] + 1.0 / 3.0  # not writable in 7 columns
    from juncture.model import WingLike

    odd = WingLike("wing", "wing", wing.le, wing.chord, x, wing.upper, wing.lower, wing.camber)
    path = tmp_path / "odd.inp"
    with pytest.warns(JunctureWarning) as record:
        jc.write(cfg.with_component(odd), path)
    messages = [str(w.message) for w in record if issubclass(w.category, JunctureWarning)]
    assert len(messages) == 1
    (message,) = messages
    assert len(message.splitlines()) == 1 and message.startswith(f"{path}: ")
    n = int(np.count_nonzero(x[1:-1]))
    assert f"{n} values cannot be written exactly in 7 columns" in message
    assert "the first: configuration 1, XAF value 2 = " in message
