"""The wave-drag deck reader and writer at the raw level (juncture.io.wavedrag).

Expected values come from formats.md (the PDAS sample and the wd2wgs output quoted there) and
from the hand-written decks in tests/data/decks/, whose intended numbers are typed here.
"""

import dataclasses
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from juncture.errors import DeckError, JunctureError, JunctureWarning
from juncture.io import wavedrag as wd
from juncture.io._registry import _FORMATS
from tests.support import DECKS_DIR, LAWGS_DIR, PDAS_DECK

SAMPLE = PDAS_DECK
DECKS = DECKS_DIR
ALL_DECKS = [SAMPLE, *sorted(DECKS.glob("*.inp"))]


def _read(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", JunctureWarning)
        return wd.read_deck(path)


def _parse(text):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", JunctureWarning)
        return wd.parse_deck(text)


def _sample_lines():
    return SAMPLE.read_text().split("\n")


def _eq(a, b):
    if a is None or b is None:
        return a is None and b is None
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and np.array_equal(a, b)


def assert_same_deck(d1, d2):
    """Every record and every array equal, exactly; reuse (flag 2) preserved."""
    assert len(d1.configurations) == len(d2.configurations)
    for k, (c1, c2) in enumerate(zip(d1.configurations, d2.configurations, strict=True)):
        assert c1.title == c2.title
        assert c1.control == c2.control
        assert c1.reference == c2.reference
        for name in ("wing",):
            w1, w2 = getattr(c1, name), getattr(c2, name)
            assert (w1 is None) == (w2 is None)
            if w1 is not None:
                for f in ("xaf", "origins", "tzord", "waford_upper", "waford_lower"):
                    assert _eq(getattr(w1, f), getattr(w2, f)), f
        assert (c1.fuselage is None) == (c2.fuselage is None)
        if c1.fuselage is not None:
            assert len(c1.fuselage.segments) == len(c2.fuselage.segments)
            for s1, s2 in zip(c1.fuselage.segments, c2.fuselage.segments, strict=True):
                for f in ("x", "zfus", "area", "y", "z"):
                    assert _eq(getattr(s1, f), getattr(s2, f)), f
        for group, attrs in (("pods", ("origin", "x", "radius")),
                             ("fins", ("origins", "xfin", "outboard", "inboard")),
                             ("canards", ("origins", "xcan", "upper_inboard", "upper_outboard",
                                          "lower_inboard", "lower_outboard", "n_sets"))):
            g1, g2 = getattr(c1, group), getattr(c2, group)
            assert len(g1) == len(g2)
            for o1, o2 in zip(g1, g2, strict=True):
                for f in attrs:
                    assert _eq(getattr(o1, f), getattr(o2, f)), (group, f)
        assert len(c1.cases) == len(c2.cases)
        for a, b in zip(c1.cases, c2.cases, strict=True):
            assert a.ncase == b.ncase and a.fields() == b.fields() and _eq(a.xrest, b.xrest)
        if k:
            prev1, prev2 = d1.configurations[k - 1], d2.configurations[k - 1]
            for flag, name in ((c1.control.j1, "wing"), (c1.control.j2, "fuselage"),
                               (c1.control.j3, "pods"), (c1.control.j4, "fins"),
                               (c1.control.j5, "canards")):
                if flag == 2:
                    assert getattr(c1, name) is getattr(prev1, name)
                    assert getattr(c2, name) is getattr(prev2, name)


# -- the PDAS sample --------------------------------------------------------------------------

def test_sample_reads_to_the_numbers_of_formats_md():
    with pytest.warns(JunctureWarning, match=r"line 2, columns 40-42: NFORX\(2\) = 2 is outside "
                                             r"the documented range 4..30"):
        deck = wd.read_deck(SAMPLE)
    assert deck.path == str(SAMPLE) and len(deck.configurations) == 1
    assert len(deck.warnings) == 1 and "NFORX(2) = 2" in deck.warnings[0]
    cfg = deck.configurations[0]
    assert cfg.title == "SIMPLE TEST CASE TO ILLUSTRATE BODY RE-SHAPING"
    assert cfg.control.values() == (1, -1, -1, 0, 0, 0, -1, 2, 3, 3, 9, 6, 9, 2, 9, 6,
                                    0, 0, 0, 0, 0, 0, 0, 0)
    assert cfg.control.nradx == (9, 9, 9, 0) and cfg.control.nforx == (6, 2, 6, 0)
    assert cfg.reference == (16.0, 0.0, 0.0)
    w = cfg.wing
    np.testing.assert_array_equal(w.xaf, [0.0, 50.0, 100.0])
    np.testing.assert_array_equal(w.origins, [[100.0, 10.0, 0.0, 140.0],
                                              [240.0, 150.0, 0.0, 0.0]])
    np.testing.assert_array_equal(w.waford_upper, [[0.0, 2.5, 0.0], [0.0, 2.5, 0.0]])
    assert w.tzord is None and w.waford_lower is None
    segs = cfg.fuselage.segments
    assert [s.x.tolist() for s in segs] == [[0, 10, 20, 30, 40, 50], [50, 250],
                                            [250, 260, 270, 280, 290, 300]]
    assert all(s.zfus is None and s.y is None for s in segs)  # J6 = -1: no ZFUS
    radius = np.sqrt(segs[0].area / np.pi)
    # wd2wgs output (formats.md 1.10; pdas_wdcase1_wd2wgs_output.wgs), 6 significant digits
    np.testing.assert_allclose(radius[1:], [3.59933, 6.40051, 8.40055, 9.59952, 10.0000],
                               rtol=5e-6)
    np.testing.assert_array_equal(segs[1].area, [314.16, 314.16])
    np.testing.assert_array_equal(segs[2].area, [314.16, 289.5, 221.7, 128.7, 40.7, 0.0])
    assert cfg.pods == cfg.fins == cfg.canards == ()
    (case,) = cfg.cases
    assert (case.ncase, case.mach, case.nx, case.ntheta, case.nrest, case.ncon, case.icyc) == \
        ("M1.2", 1200, 50, 16, 2, 0, 2)
    assert case.fields()[6:] == (0, 0, 0, 0, 0)
    np.testing.assert_array_equal(case.xrest, [100.0, 240.0])
    assert case.text.startswith("M1.21200  50  16   2   0   2   0   0")
    assert cfg.lines["fusard 3"] == 14 and cfg.lines["case 1"] == 15


def test_records_are_frozen_and_arrays_read_only():
    cfg = _read(SAMPLE).configurations[0]
    with pytest.raises(ValueError, match="read-only"):
        cfg.wing.xaf[0] = 1.0
    with pytest.raises(ValueError, match="read-only"):
        cfg.fuselage.segments[0].area[0] = 1.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        cfg.wing.xaf = np.zeros(3)
    with pytest.raises(dataclasses.FrozenInstanceError):
        cfg.title = "x"


# -- hand-written decks -----------------------------------------------------------------------

def test_cambered_wing_twelve_stations_upper_and_lower():
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # this deck is inside every documented range
        deck = wd.read_deck(DECKS / "cambered_wing.inp")
    assert deck.warnings == ()
    (cfg,) = deck.configurations
    c = cfg.control
    assert (c.j0, c.j1, c.j2, c.nwaf, c.nwafor) == (1, 1, 0, 3, -12)
    assert cfg.reference == (850.5, 20.0, 120.0)
    w = cfg.wing
    np.testing.assert_array_equal(w.xaf, [0, 2.5, 5, 10, 20, 30, 40, 50, 60, 70, 80, 100])
    np.testing.assert_array_equal(w.origins, [[100.0, 0.0, -2.0, 150.0],
                                              [150.0, 40.0, 0.5, 80.0],
                                              [190.0, 75.0, 1.25, 35.0]])
    np.testing.assert_array_equal(w.tzord, [
        [0.0, 0.5, 0.8, 1.2, 1.6, 1.8, 1.9, 1.8, 1.6, 1.2, 0.8, 0.0],
        [0.0, -0.125, -0.25, -0.375, -0.5, -0.625, -0.75, -0.875, -1.0, -1.125, -1.25, -1.5],
        list(range(12))])
    np.testing.assert_array_equal(w.waford_upper, [
        [0.0, 1.1, 1.6, 2.2, 2.9, 3.2, 3.3, 3.2, 2.9, 2.4, 1.8, 0.1],
        [0.0, 1.05, 1.55, 2.15, 2.85, 3.15, 3.25, 3.15, 2.85, 2.35, 1.75, 0.05],
        [0.0, 1.0, 1.5, 2.0, 2.5, 3.0, 3.0, 3.0, 2.5, 2.0, 1.5, 0.0]])
    np.testing.assert_array_equal(w.waford_lower, [
        [0.0, 0.9, 1.3, 1.8, 2.3, 2.6, 2.7, 2.6, 2.3, 1.9, 1.4, 0.1],
        [0.0, 0.85, 1.25, 1.75, 2.25, 2.55, 2.65, 2.55, 2.25, 1.85, 1.35, 0.05],
        [0.0, 1.0, 1.5, 2.0, 2.5, 3.0, 3.0, 3.0, 2.5, 2.0, 1.5, 0.0]])
    assert cfg.fuselage is None
    des, m2 = cfg.cases
    assert des.ncase == "DES " and des.fields() == (1600, 60, 24, 3, 0, 0, 1, 1, 200, 0, 0)
    np.testing.assert_array_equal(des.xrest, [120.0, 160.0, 200.0])
    assert m2.ncase == "M2.0" and m2.fields() == (2000, 60, 24, 0, 0, 0, 0, 0, 0, 0, 0)
    assert m2.xrest is None
    assert cfg.lines["tzord 3"] == 13 and cfg.lines["waford 3 lower"] == 25


def test_arbitrary_body_two_segments_pods_and_symmetric_fins():
    with pytest.warns(JunctureWarning) as record:
        deck = wd.read_deck(DECKS / "arbitrary_body_pods_fins.inp")  # CRLF, trailing blanks
    (cfg,) = deck.configurations
    assert [str(w.message) for w in record] == list(deck.warnings)
    assert [w.split(": ", 1)[1] for w in deck.warnings] == [
        "NFORX(1) = 2 is outside the documented range 4..30 of AWAVE",
        "NFORX(2) = 3 is outside the documented range 4..30 of AWAVE"]
    assert cfg.control.nradx == (3, 4, 0, 0) and cfg.control.nforx == (2, 3, 0, 0)
    assert cfg.wing is None and cfg.reference is None
    s1, s2 = cfg.fuselage.segments
    np.testing.assert_array_equal(s1.x, [0.0, 30.0])
    np.testing.assert_array_equal(s1.y, [[0.0, 0.5, 0.0], [0.0, 4.0, 0.0]])
    np.testing.assert_array_equal(s1.z, [[-0.5, 0.0, 0.5], [-3.0, 0.5, 4.0]])
    np.testing.assert_array_equal(s2.x, [30.0, 80.0, 120.0])
    np.testing.assert_array_equal(s2.y, [[0, 3.5, 3.5, 0], [0, 5, 5, 0], [0, 2, 2, 0]])
    np.testing.assert_array_equal(s2.z, [[-3, -1, 2, 4], [-4, -1.5, 2.5, 5.5], [-1, 0, 1, 2]])
    assert s1.area is None and s1.zfus is None
    p1, p2 = cfg.pods
    np.testing.assert_array_equal(p1.origin, [60.0, 12.0, -3.0])
    np.testing.assert_array_equal(p1.x, [0.0, 5.0, 20.0, 30.0])
    np.testing.assert_array_equal(p1.radius, [0.0, 1.2, 1.5, 1.0])
    np.testing.assert_array_equal(p2.origin, [70.0, 20.0, -2.5])
    np.testing.assert_array_equal(p2.radius, [0.0, 1.0, 1.25, 0.75])
    f1, f2 = cfg.fins
    np.testing.assert_array_equal(f1.origins, [[90.0, 0.0, 4.0, 30.0], [110.0, 0.0, 20.0, 12.0]])
    np.testing.assert_array_equal(f1.xfin, [0.0, 50.0, 100.0])
    np.testing.assert_array_equal(f1.outboard, [0.0, 3.0, 0.0])
    assert f1.inboard is None
    np.testing.assert_array_equal(f2.origins, [[95.0, 2.0, -3.0, 20.0], [105.0, 5.0, -8.0, 10.0]])
    np.testing.assert_array_equal(f2.outboard, [0.0, 2.5, 0.25])
    (case,) = cfg.cases
    assert case.ncase == "M1.4" and case.fields()[:4] == (1400, 40, 16, 0)


def test_circular_cambered_body_four_segments_asymmetric_fin_one_canard_set():
    deck = _read(DECKS / "circular_body_4_segments.inp")
    (cfg,) = deck.configurations
    assert cfg.cases == ()  # geometry only
    c = cfg.control
    assert (c.j2, c.j6, c.nfus, c.nf, c.ncan, c.ncanor) == (-1, 0, 4, -1, 1, 3)
    np.testing.assert_array_equal(cfg.wing.xaf, [0.0, 30.0, 60.0, 100.0])
    assert cfg.wing.tzord is None and cfg.wing.waford_lower is None
    np.testing.assert_array_equal(cfg.wing.waford_upper, [[0, 3, 2, 0], [0, 2.5, 1.5, 0]])
    expected = [  # x, zfus, area per segment
        ([0, 10, 20, 40], [-1.0, -0.5, -0.2, 0.0], [0.0, 12.5, 40.0, 78.5]),
        ([40, 100], [0, 0], [78.5, 78.5]),
        ([100, 120, 140], [0.0, 0.3, 0.8], [78.5, 60.0, 35.0]),
        ([140, 150, 160, 170], [0.8, 1.0, 1.2, 1.4], [35.0, 20.0, 10.0, 5.0])]
    for seg, (x, zfus, area) in zip(cfg.fuselage.segments, expected, strict=True):
        np.testing.assert_array_equal(seg.x, x)
        np.testing.assert_array_equal(seg.zfus, zfus)
        np.testing.assert_array_equal(seg.area, area)
    (fin,) = cfg.fins
    np.testing.assert_array_equal(fin.outboard, [0.0, 4.0, 3.0, 0.5])
    np.testing.assert_array_equal(fin.inboard, [0.0, 3.5, 2.5, 0.5])
    (can,) = cfg.canards
    assert can.n_sets == 1
    np.testing.assert_array_equal(can.origins, [[30, 5, 1, 15], [38, 18, 1.5, 6]])
    np.testing.assert_array_equal(can.upper_inboard, [0.0, 4.0, 0.0])
    assert can.upper_inboard is can.upper_outboard is can.lower_inboard is can.lower_outboard


def test_two_configurations_four_canard_sets_and_reuse_flags():
    deck = _read(DECKS / "two_configurations_four_canard_sets.inp")
    c1, c2 = deck.configurations
    assert c1.reference == (2000.0, 45.0, 100.0)
    a, b = c1.canards
    assert (c1.control.ncan, c1.control.ncanor, a.n_sets) == (-2, -3, 4)
    np.testing.assert_array_equal(a.upper_inboard, [0.0, 3.0, 0.0])
    np.testing.assert_array_equal(a.upper_outboard, [0.0, 2.0, 0.0])
    np.testing.assert_array_equal(a.lower_inboard, [0.0, 2.5, 0.0])
    np.testing.assert_array_equal(a.lower_outboard, [0.0, 1.5, 0.0])
    np.testing.assert_array_equal(b.origins, [[160, 3, 2, 30], [175, 25, 2.5, 12]])
    np.testing.assert_array_equal(b.lower_outboard, [0.0, 2.5, 0.1])
    assert c1.cases[0].ncon == 1
    assert c2.title == "CONFIGURATION 2: SAME WING, BODY AND CANARDS, ADDED POD"
    assert (c2.control.j0, c2.control.j1, c2.control.j2, c2.control.j5) == (2, 2, 2, 2)
    assert c2.reference == c1.reference
    assert c2.wing is c1.wing and c2.fuselage is c1.fuselage and c2.canards is c1.canards
    (pod,) = c2.pods
    np.testing.assert_array_equal(pod.origin, [90.0, 30.0, -5.0])
    np.testing.assert_array_equal(pod.radius, [0.0, 2.0, 2.0, 1.5])
    assert [k.fields()[:5] for k in c2.cases] == [(1200, 50, 16, 0, 0), (1500, 50, 16, 2, 0)]
    np.testing.assert_array_equal(c2.cases[1].xrest, [50.0, 150.0])
    assert c2.lines["title"] == 24 and c2.lines["podorg 1"] == 26


def test_canard_sets_inboard_outboard_then_upper_lower():
    c1, c2 = _read(DECKS / "two_configurations_canard_signs.inp").configurations
    (can,) = c1.canards  # NCAN = -1, NCANOR = 4: inboard set, outboard set
    assert can.n_sets == 2
    np.testing.assert_array_equal(can.upper_inboard, [0.0, 3.0, 2.0, 0.0])
    np.testing.assert_array_equal(can.upper_outboard, [0.0, 2.5, 1.5, 0.0])
    assert can.lower_inboard is can.upper_inboard and can.lower_outboard is can.upper_outboard
    assert c1.control.j6 == 1 and c1.fuselage.segments[0].zfus is None
    (can,) = c2.canards  # NCAN = 1, NCANOR = -4: upper set, lower set
    assert can.n_sets == 2
    np.testing.assert_array_equal(can.upper_inboard, [0.0, 2.8, 2.2, 0.0])
    np.testing.assert_array_equal(can.lower_inboard, [0.0, 1.2, 1.0, 0.0])
    assert can.upper_outboard is can.upper_inboard and can.lower_outboard is can.lower_inboard
    assert c2.fuselage is c1.fuselage
    assert c2.cases[0].ncase == "C2  " and c2.cases[0].mach == 1100


# -- round trips ------------------------------------------------------------------------------

@pytest.mark.parametrize("path", ALL_DECKS, ids=lambda p: p.name)
def test_read_write_read_is_the_identity(path, tmp_path):
    deck = _read(path)
    out = tmp_path / "out.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no precision loss writing deck numbers
        wd.write_deck(deck, out)
    again = _read(out)
    assert_same_deck(deck, again)
    assert wd.format_deck(again) == out.read_text()  # the written text is a fixed point
    assert not list(tmp_path.glob(".*.tmp"))


def test_writer_keeps_fields_apart_and_labels_cards():
    text = wd.format_deck(_read(DECKS / "cambered_wing.inp"))
    lines = text.splitlines()
    assert lines[10][:14] == "    0.0 -0.125"  # touching input, separated output
    assert lines[1].endswith(" CONTROL") and lines[3][72:] == "XAF"
    assert lines[14][72:] == "WAFORD1U" and lines[16][72:] == "WAFORD1L"
    assert lines[26].startswith("DES 1600  60  24   3")  # case card kept as read


def test_writer_rejects_records_that_disagree_with_the_control_card():
    cfg = _read(SAMPLE).configurations[0]
    bad = dataclasses.replace(cfg, control=dataclasses.replace(cfg.control, nwaf=3))
    with pytest.raises(JunctureError, match=r"configuration 1: the wing has 2 sections of 3 "
                                            r"stations, the control card says NWAF = 3"):
        wd.format_deck(wd.Deck([bad]))
    c2 = _read(DECKS / "two_configurations_canard_signs.inp").configurations[1]
    can = c2.canards[0]
    four = dataclasses.replace(can, n_sets=4, upper_outboard=np.array([0.0, 9.0, 9.0, 0.0]))
    with pytest.raises(JunctureError, match=r"canard 1 has 4 different ordinate sets but the "
                                            r"signs of NCAN = 1 and NCANOR = -4 give 2"):
        wd.format_deck(wd.Deck([dataclasses.replace(c2, canards=(four,),
                                                    control=dataclasses.replace(c2.control,
                                                                                j2=0))]))
    with pytest.raises(JunctureError, match="flag of value 2 .* in the first configuration"):
        wd.format_deck(wd.Deck([c2]))


def test_writer_builds_a_case_card_from_fields_and_warns_on_precision():
    cfg = _read(SAMPLE).configurations[0]
    case = wd.DeckCase("M2.5", mach=2500, nx=40, ntheta=8)
    wing = dataclasses.replace(cfg.wing, xaf=[0.0, 100.0 / 3.0, 100.0])
    out = dataclasses.replace(cfg, cases=(case,), wing=wing)
    with pytest.warns(JunctureWarning, match=r"XAF value 2 = 33.333333333333336 cannot be "
                                             r"written exactly"):
        text = wd.format_deck(wd.Deck([out]))
    assert "M2.52500  40   8   0   0   0   0   0   0   0   0" in text
    assert _parse(text).configurations[0].wing.xaf[1] == 33.3333


# -- errors -----------------------------------------------------------------------------------

def _sample_with(replace=None, keep=None):
    lines = _sample_lines()
    for number, text in (replace or {}).items():
        lines[number - 1] = text
    if keep is not None:
        lines = lines[:keep]
    return "\n".join(lines)


@pytest.mark.parametrize("replace, keep, pattern", [
    ({}, 7, r"line 7: file ended after line 7 while reading WAFORD for section 2 "
            r"\(0 of 3 values read\)"),
    ({}, 1, r"file ended after line 1 while reading the control card"),
    ({6: "  l40.0  150.0  0.000    0.0"}, None,
     r"line 6, columns 1-7: expected a number \(WAFORG x for section 2\), found 'l40.0'"),
    ({4: "   0.00  50.00 100.00  150.0"}, None,
     r"line 4, columns 22-28: expected 3 values on this XAF card, found a 4th in columns "
     r"22-28: '150.0'"),
    ({2: "  1 -1 -1  0  0  0 -1  2  4  3  9  6  9  2  9  6  0  0  0  0  0  0  0  0"}, None,
     r"line 4, columns 22-28: XAF \(percent chord\) must increase: value 4 \(0.0\) after "
     r"value 3 \(100.0\)"),
    ({10: "   0.00  -40.7  128.7  221.7  289.5 314.16"}, None,
     r"line 10, columns 8-14: FUSARD \(cross-section area\) for segment 1 must not be "
     r"negative, found -40.7 \(value 2\)"),
    ({9: "  0.000   10.0    5.0   30.0   40.0   50.0"}, None,
     r"line 9, columns 15-21: XFUS for segment 1 must not decrease: value 3 \(5.0\) after "
     r"value 2 \(10.0\)"),
    ({13: "  240.0  260.0  270.0  280.0  290.0  300.0"}, None,
     r"line 13, columns 1-7: XFUS must not decrease across segments: segment 3 starts at "
     r"x = 240.0, segment 2 ends at x = 250.0"),
    ({6: "  240.0    5.0  0.000    0.0"}, None,
     r"line 6, columns 8-14: wing sections must be in increasing y: section 2 has y = 5.0, "
     r"section 1 has y = 10.0"),
    ({5: "  100.0   10.0  0.000 -140.0"}, None,
     r"line 5, columns 22-28: WAFORG chord for section 1 must not be negative"),
    ({8: " 0.0000-2.5000 0.0000"}, None,
     r"line 8, columns 8-14: WAFORD \(half-thickness\) for section 2 must not be negative"),
    ({2: "  1  3 -1  0  0  0 -1  2  3  3  9  6  9  2  9  6"}, None,
     r"line 2, columns 4-6: unknown value J1 = 3 \(wing flag\); expected one of -1, 0, 1, 2"),
    ({2: "  1 -1 -1  0  0  0 -1  1  3  3  9  6  9  2  9  6"}, None,
     r"line 2, columns 22-24: NWAF = 1: a wing needs at least 2 sections"),
    ({2: "  1 -1  1  0  0  0  1  2  3  3  9  6  9  2  9  6"}, None,
     r"line 2, columns 7-21: J2 = 1 \(arbitrary fuselage\) and J6 = 1"),
    ({2: "  1  2 -1  0  0  0 -1  2  3  3  9  6  9  2  9  6"}, None,
     r"line 2, columns 4-6: J1 = 2 \(use the previous configuration's wing\) in the first"),
    ({2: "  1 -1 -1  0  0  0 -1  2  3  5  9  6  9  2  9  6"}, None,
     r"line 2, columns 28-30: NFUS = 5: a fuselage has 1 to 4 segments"),
    ({2: "  1 -1 -1  0  0  0 -1  2  3  3  9  6  9  2  9  6  0  0  0  0  0  0  0  0\t"}, None,
     None),  # a TAB after column 72 is harmless
    ({2: "  1 -1 -1  0  0  0 -1  2  3  3  9\t6  9  2  9  6"}, None,
     r"line 2, columns 34-36: TAB character in column 34"),
    ({15: "M1.21200  50  16   2   1   2   0   0"}, 16,
     r"file ended after line 16 while reading the title card of configuration 2"),
    ({15: "M1.21200  50  16   2   3"}, None,
     r"line 15, columns 21-24: unknown value NCON = 3 on case card 1"),
    ({15: "M1.21200  50  16 2.0"}, None,
     r"line 15, columns 17-20: expected an integer \(NREST on case card 1; the geometry "
     r"cards ended at line 14\), found '2.0'"),
])
def test_deck_errors_name_line_columns_and_record(replace, keep, pattern):
    text = _sample_with(replace, keep)
    if pattern is None:
        _parse(text)
        return
    with pytest.raises(DeckError, match=pattern) as err:
        _parse(text)
    assert err.value.line is not None


def test_count_mismatch_extra_card_shifts_the_cards_and_is_caught():
    lines = _sample_lines()
    lines.insert(9, "   60.0   70.0")  # an extra card: FUSARD 1 reads it, XFUS 2 the areas
    with pytest.raises(DeckError, match=r"line 11, columns 15-21: expected 2 values on this "
                                        r"XFUS card \(for segment 2\), found a 3rd in columns "
                                        r"15-21: '128.7'"):
        _parse("\n".join(lines))


@pytest.mark.filterwarnings("ignore::juncture.errors.JunctureWarning")
def test_error_carries_the_path(tmp_path):
    path = tmp_path / "bad.inp"
    path.write_text(_sample_with({6: "  l40.0"}))
    with pytest.raises(DeckError, match=r"bad.inp, line 6, columns 1-7") as err:
        wd.read_deck(path)
    assert err.value.path == str(path) and err.value.columns == (1, 7)
    with pytest.raises(DeckError, match="cannot open file"):
        wd.read_deck(tmp_path / "missing.inp")


@pytest.mark.filterwarnings("ignore:.*NFORX:juncture.errors.JunctureWarning")
def test_negative_pod_radius_and_pod_origin_warning():
    text = (DECKS / "arbitrary_body_pods_fins.inp").read_text()
    bad = text.replace("    0.0    1.0   1.25   0.75", "    0.0    1.0  -1.25   0.75")
    with pytest.raises(DeckError, match=r"line 20, columns 15-21: PODR \(radius\) for pod 2 "
                                        r"must not be negative, found -1.25"):
        _parse(bad)
    shifted = text.replace("    0.0    4.0   16.0   24.0", "    1.0    4.0   16.0   24.0")
    with pytest.warns(JunctureWarning, match=r"line 19, columns 1-7: the first XPOD value for "
                                             r"pod 2 should be 0, found 1.0"):
        deck = wd.parse_deck(shifted)
    assert any("XPOD" in w for w in deck.warnings)


def test_range_limits_are_warnings_not_errors():
    text = _sample_with({2: "  1 -1 -1  0  0  0 -1  2 31  3 51  6  9  2  9  6"})
    text = text.replace("   0.00  50.00 100.00", "".join(f"{v:7.1f}" for v in range(10)))
    text = text.replace(" 0.0000 2.5000 0.0000", ("    1.0" * 10 + "\n") * 3 + "    1.0")
    with pytest.warns(JunctureWarning) as record:
        with pytest.raises(DeckError):  # XAF has only 10 of 31 values: fails later
            wd.parse_deck(text)
    messages = [str(w.message) for w in record]
    assert any("NWAFOR = 31 is outside the documented range 3..30" in m for m in messages)
    assert any("NRADX(1) = 51 is outside the documented range 3..30" in m for m in messages)


# -- sniffing and registration ----------------------------------------------------------------

def test_sniffer_accepts_decks_and_rejects_other_formats():
    for path in ALL_DECKS:
        assert wd._sniff(path.read_bytes()[:4096]), path.name
    for path in LAWGS_DIR.glob("*.wgs"):
        assert not wd._sniff(path.read_bytes()[:4096]), path.name
    assert not wd._sniff(b"just one line")
    assert not wd._sniff(b"title\n" + b"  0" * 24 + b"\n")  # no component at all
    assert not wd._sniff(b"title\n  1  5 -1\n")  # J1 = 5


def test_registered_format():
    fmt = _FORMATS["wavedrag"]
    assert fmt.extensions == (".inp", ".wd", ".wdk")
    assert fmt.sniff is wd._sniff and fmt.reader is not None and fmt.writer is not None


# -- mutation fuzzing -------------------------------------------------------------------------

_TEXTS = [p.read_text() for p in ALL_DECKS]
_CHARS = st.sampled_from(list("0123456789 .-+EDelx\t\r\n,") + ["\u00e9", "\x0c"])


@st.composite
def _mutated(draw):
    text = draw(st.sampled_from(_TEXTS))
    for _ in range(draw(st.integers(1, 4))):
        lines = text.split("\n")
        kind = draw(st.sampled_from(["replace", "delete", "insert", "drop line", "dup line"]))
        if kind in ("drop line", "dup line"):
            i = draw(st.integers(0, len(lines) - 1))
            lines[i:i + 1] = [] if kind == "drop line" else [lines[i], lines[i]]
            text = "\n".join(lines)
            continue
        i = draw(st.integers(0, max(len(text) - 1, 0)))
        if kind == "delete":
            text = text[:i] + text[i + 1:]
        else:
            c = draw(_CHARS)
            text = text[:i] + c + text[i + (kind == "replace"):]
    return text


@settings(max_examples=250, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_mutated())
def test_mutated_decks_raise_only_deck_errors_and_survive_a_round_trip(text):
    try:
        deck = _parse(text)
    except DeckError:
        return
    again = _parse(wd.format_deck(deck))
    assert_same_deck(deck, again)


def test_flag_two_without_a_previous_component_is_an_error():
    text = (DECKS / "two_configurations_canard_signs.inp").read_text()
    bad = text.replace("  0  0  2  0  0  1  1", "  0  2  2  0  0  1  1")  # J1 = 2, no wing before
    with pytest.raises(DeckError, match=r"line 11, columns 4-6: J1 = 2 \(use the previous "
                                        r"configuration's wing\) but configuration 1 has none"):
        _parse(bad)
