"""LaWGS reader and writer (NASA TM-85767), against the sample files in tests/data/lawgs."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import juncture as jc
from juncture.errors import DeckError, GeometryError
from juncture.geometry import Geometry
from juncture.io import lawgs
from tests.support import LAWGS_DIR as DATA

# (file, title, [(name, NLINE, NPNT, ISYMG), ...]) as written in the files' headers (read by eye).
_F16XL = [("WING-UPPER-OB", 5, 20), ("WING-UPPER-IB", 5, 20), ("SPEED-LUMP-UPPER", 11, 7),
          ("WING-LOWER-IB", 5, 20), ("WING-LOWER-OB", 5, 20), ("SPEED-LUMP-LOWER", 7, 11),
          ("WING-TIP", 20, 2), ("CANOPY", 8, 6), ("FUSELAGE-1-UPPER", 6, 7),
          ("FUSELAGE-2-UPPER", 8, 7), ("FUSELAGE-3-UPPER", 14, 7),
          ("EXHAUST-NOZZLE-UPPER", 5, 5), ("EXHAUST-NOZZLE-LOWER", 5, 5), ("EXHAUST-1", 5, 3),
          ("AIR-BRAKE-UPPER", 5, 3), ("AIR-BRAKE-LOWER", 5, 3), ("FUSELAGE-LOWER-BACK", 10, 5),
          ("INTERSECT-F-W-LOWER", 10, 3), ("FRONT-LOWER-TAIL", 6, 3), ("BACK-LOWER-TAIL", 6, 7),
          ("TAIL", 6, 7), ("FUSELAGE-LOWER-FRONT", 14, 5), ("SCOOP", 4, 9),
          ("FUSELAGE-LOWER-MID", 4, 11), ("INTERSECT-F-W-UPPER", 13, 2),
          ("AIR-BRAKE-INTERSECT", 5, 2), ("TAIL-TIP", 7, 2), ("SCOOP-CLOSURE", 9, 2),
          ("EXHAUST-CLOSURE", 2, 11), ("PARACHUTE-CLOSURE", 2, 7), ("RULED", 2, 5)]
SAMPLES = [
    ("tm85767_ex1_three_cylinders_global.wgs", "EXAMPLE 1 - THREE CYLINDERS IN GLOBAL COORDINATES",
     [("FIRST CYLINDER", 2, 7, 1), ("SECOND CYLINDER", 2, 13, 0), ("THIRD CYLINDER", 2, 13, 0)]),
    ("tm85767_ex2_three_cylinders_local.wgs", "EXAMPLE 2 - THREE CYLINDERS IN LOCAL COORDINATES",
     [("FIRST CYLINDER", 2, 7, 0), ("SECOND CYLINDER", 2, 7, 0), ("THIRD CYLINDER", 2, 7, 0)]),
    ("tm85767_ex3_very_simple_airplane.wgs", "VERY SIMPLE AIRPLANE",
     [("WING", 3, 5, 1), ("FUSELAGE 1", 6, 7, 1), ("POD 1-1", 4, 7, 1), ("POD 1-2", 4, 7, 1),
      ("PYLON", 2, 5, 1), ("VERTICAL TAIL", 2, 3, 1), ("HORIZONTAL TAIL", 2, 5, 1)]),
    ("tm85767_ex4_twin_body.wgs", "NONSYMMETRICAL TWIN BODY GEOMETRY SAMPLE",
     [("WING 1", 5, 21, 1), ("WING 2", 2, 39, 1), ("FUSELAGE", 14, 15, 1),
      ("RIGHT CANARD", 5, 5, 0), ("LEFT CANARD", 5, 5, 0), ("BRACE", 4, 7, 0),
      ("POD 1", 18, 25, 0), ("POD 2", 18, 25, 0)]),
    ("pdas_f16xl.wgs", "A more or less accurate model of the F16-XL",
     [(n, a, b, 1) for n, a, b in _F16XL]),
    ("pdas_tnd7505_wingbody.wgs", "Created by wb2wgs from tnd7505.inp",
     [("BODY", 7, 21, 0), ("WING", 9, 7, 0)]),
    ("pdas_wdcase1_wd2wgs_output.wgs", "Created by wd2wgs from: wdcase1.inp",
     [("WING UPPER", 2, 3, 1), ("WING LOWER", 2, 3, 1),
      ("FUSELAGE SEGMENT #           1", 9, 6, 0), ("FUSELAGE SEGMENT #           2", 9, 2, 0),
      ("FUSELAGE SEGMENT #           3", 9, 6, 0)]),
]


def _write(tmp_path, text, name="t.wgs"):
    p = tmp_path / name
    p.write_text(text)
    return p


@pytest.mark.parametrize("fname,title,objects", SAMPLES, ids=[s[0] for s in SAMPLES])
def test_samples_read_with_their_header_counts(fname, title, objects):
    geo = lawgs.read(DATA / fname)
    assert geo.title == title
    ex2 = fname.startswith("tm85767_ex2")  # ISYML = 1 on every object: local images added
    expected = []
    for name, nl, npt, _ in objects:
        expected.append((name, (nl, npt, 3)))
        if ex2:
            expected.append((f"{name} local image", (nl, npt, 3)))
    assert [(k, v.shape) for k, v in geo.networks.items()] == expected
    assert dict(geo.symmetry) == {n: "xz" for n, _, _, s in objects if s == 1}


def test_sample_values_as_printed():
    ex3 = lawgs.read(DATA / "tm85767_ex3_very_simple_airplane.wgs")
    np.testing.assert_array_equal(ex3.networks["WING"][0, :2],
                                  [[117.9, 5.2, 0.0], [80.3, 5.2, -2.748]])
    np.testing.assert_array_equal(ex3.networks["WING"][2, 4], [161.2, 31.7, 0.0])
    f16 = lawgs.read(DATA / "pdas_f16xl.wgs")  # E exponents, three numbers per line
    np.testing.assert_array_equal(f16.networks["WING-UPPER-OB"][0, 0],
                                  [459.441, 194.422, 89.7343])
    np.testing.assert_array_equal(f16.networks["RULED"][-1, -1], [565.906, 27.5735, 102.330])


def test_wd2wgs_fuselage_radii_match_the_deck_areas():
    # formats.md section 1: r = sqrt(FUSARD / pi) = 3.599, 6.401, 8.401, 9.600, 10.0 at x = 10..50
    seg = lawgs.read(DATA / "pdas_wdcase1_wd2wgs_output.wgs").networks[
        "FUSELAGE SEGMENT #           1"]
    r = np.array([0.0, 3.59933, 6.40051, 8.40055, 9.59952, 10.0])
    np.testing.assert_array_equal(seg[:, :, 0], np.tile([0, 10, 20, 30, 40, 50.0], (9, 1)))
    np.testing.assert_allclose(np.hypot(seg[..., 1], seg[..., 2]), np.tile(r, (9, 1)),
                               atol=2e-5)
    assert np.all(seg[..., 1] > -1e-6)  # the described y >= 0 half (wd2wgs prints -3e-7)


def test_ex2_local_reproduces_ex1_global():
    """TM-85767 example 2 (local coordinates, ISYML) is example 1 (global, ISYMG) re-placed.

    ex1: cylinder 1 is a half (7 points) with ISYMG = 1; cylinders 2 and 3 are full circles of
    13 points. ex2: every cylinder is a half with ISYML = 1, cylinders 2 and 3 rotated
    (RY = -90, RZ = 90) and translated. So ex1 cylinder 1 and its "xz" image equal ex2
    cylinder 1 and its local image; the full circles of ex1 split at point 7 into ex2's half
    (points 1-7) and ex2's local image (points 7-13 in reverse order, n-lines reversed).
    """
    g1 = lawgs.read(DATA / "tm85767_ex1_three_cylinders_global.wgs")
    g2 = lawgs.read(DATA / "tm85767_ex2_three_cylinders_local.wgs")
    n1, n2 = g1.mirrored_networks(), g2.networks
    np.testing.assert_allclose(n2["FIRST CYLINDER"], n1["FIRST CYLINDER"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(n2["FIRST CYLINDER local image"], n1["FIRST CYLINDER image"],
                               rtol=0, atol=1e-12)
    for name in ("SECOND CYLINDER", "THIRD CYLINDER"):
        full = n1[name]
        np.testing.assert_allclose(n2[name], full[:, :7], rtol=0, atol=1e-12)
        np.testing.assert_allclose(n2[f"{name} local image"], full[::-1, 12:5:-1], rtol=0,
                                   atol=1e-12)


def test_local_image_keeps_the_orientation():
    # Every ex2 cylinder is oriented one way (normals all inward or all outward about its
    # axis); the local image, n-lines reversed, must be oriented the same way.
    g2 = lawgs.read(DATA / "tm85767_ex2_three_cylinders_local.wgs")
    signs = set()
    for name, axis in (("FIRST CYLINDER", 0), ("SECOND CYLINDER", 2), ("THIRD CYLINDER", 1)):
        for net in (g2.networks[name], g2.networks[f"{name} local image"]):
            nrm = np.cross(net[0, 1:] - net[0, :-1], net[1, :-1] - net[0, :-1])
            mid = 0.5 * (net[0, 1:] + net[0, :-1])
            centre = np.mean(np.concatenate([net[0], g2.networks[name][0]]), axis=0)
            radial = mid - centre
            radial[:, axis] = 0.0
            s = np.sign(np.einsum("ij,ij->i", nrm, radial))
            assert len(set(s)) == 1
            signs.add(s[0])
    assert len(signs) == 1


def _rotation_closed_form(phi, theta, psi):
    """Rz(psi) Ry(theta) Rx(phi) written out entry by entry (formats.md section 3)."""
    cf, sf, ct, st_, cp, sp = (np.cos(phi), np.sin(phi), np.cos(theta), np.sin(theta),
                               np.cos(psi), np.sin(psi))
    return np.array([[ct * cp, -sp * cf + st_ * cp * sf, sp * sf + st_ * cp * cf],
                     [ct * sp, cp * cf + st_ * sp * sf, -cp * sf + st_ * sp * cf],
                     [-st_, ct * sf, ct * cf]])


@given(st.tuples(*[st.floats(-360, 360, allow_nan=False)] * 3))
@settings(max_examples=40, deadline=None)
def test_placement_matrix_is_rz_ry_rx(angles):
    r = lawgs.placement_matrix(*angles)
    np.testing.assert_allclose(r, _rotation_closed_form(*np.deg2rad(angles)), atol=1e-14)
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-14)


def test_transform_rotation_translation_scale(tmp_path):
    local = np.array([[1.0, 2.0, 3.0], [-0.5, 0.25, 4.0]])
    text = ("'T'\n'A'\n1 1 2 0 10 20 30 1 -2 3 2 3 4 0\n"
            + " ".join(repr(v) for v in local.ravel().tolist()) + "\n")
    geo = lawgs.read(_write(tmp_path, text))
    rot = _rotation_closed_form(*np.deg2rad([10.0, 20.0, 30.0]))
    want = np.array([2.0, 3.0, 4.0]) * (local @ rot.T + [1.0, -2.0, 3.0])
    np.testing.assert_allclose(geo.networks["A"][0], want, rtol=1e-14)


def test_list_directed_syntax(tmp_path):
    text = ("  no quotes in this title  \n"
            "   sloppy name  \n"
            "1, 2, 2,\n 0 0 0 0   0 0 0 1 1 1 0  extra words are ignored\n"
            "1.5D0, 2.5d+1, -3e-1 4*7.0\n"
            "1.5+2 .5 -2. 0 0\n"
            "'IT''S' 7 1 1 /\n"
            "1 2 3\n")
    geo = lawgs.read(_write(tmp_path, text))
    assert geo.title == "no quotes in this title"
    assert list(geo.networks) == ["sloppy name", "IT'S"]
    np.testing.assert_array_equal(geo.networks["sloppy name"].reshape(-1),
                                  [1.5, 25.0, -0.3, 7, 7, 7, 7, 150.0, 0.5, -2.0, 0, 0])
    np.testing.assert_array_equal(geo.networks["IT'S"], [[[1.0, 2.0, 3.0]]])


def test_header_wrapped_and_crlf(tmp_path):
    p = tmp_path / "crlf.wgs"
    p.write_bytes(b"'T'\r\n'W'\r\n1 1 1\r\n0 0 0 0\r\n0 0 0 1 1 1\r\n1\r\n4 5 6\r\n")
    geo = lawgs.read(p)
    np.testing.assert_array_equal(geo.networks["W"], [[[4.0, 5.0, 6.0]]])
    assert dict(geo.symmetry) == {"W": "xz"}


def test_symmetry_codes_and_duplicate_names(tmp_path):
    body = "1 0 0\n"
    text = "'T'\n" + "".join(f"' P '\n{k} 1 1 {sl} 0 0 0 0 0 0 1 1 1 {sg}\n{body}"
                             for k, (sl, sg) in enumerate([(0, 2), (0, 3), (2, 0), (3, 1)], 1))
    geo = lawgs.read(_write(tmp_path, text))
    assert list(geo.networks) == ["P", "P #2", "P #3", "P local image", "P #4",
                                  "P local image #2"]
    assert dict(geo.symmetry) == {"P": "xy", "P #2": "yz", "P #4": "xz"}
    # ISYML 2 mirrors z, 3 mirrors x (in local coordinates, before placement)
    np.testing.assert_array_equal(geo.networks["P local image"], [[[1.0, 0.0, -0.0]]])
    np.testing.assert_array_equal(geo.networks["P local image #2"], [[[-1.0, 0.0, 0.0]]])


@pytest.mark.parametrize("text,match,line", [
    ("'T'\n'WING'\n1 3 7 0 0 0 0 0 0 0 1 1 1 0\n" + "1 2 3 4 5 6\n" * 5,
     r"line 8: expected 63 numbers for object 'WING' \(NLINE 3 x NPNT 7 x 3\), file ended "
     "after 30", 8),
    ("'T'\n'W'\n1 1 1 0 0 0 0 0 0 0 1 1 1 0\n1.0 2.O 3\n",
     r"line 4, columns 5-7: expected a number, found '2.O'", 4),
    ("'T'\n'W'\n1 0 1 0 0 0 0 0 0 0 1 1 1 0\n", r"line 3, column 3: NLINE of object 'W' must "
     r"be an integer >= 1, found '0'", 3),
    ("'T'\n'W'\n1 1 -2 0 0 0 0 0 0 0 1 1 1 0\n", "NPNT of object 'W' must be an integer >= 1, "
     "found '-2'", 3),
    ("'T'\n'W'\n1 1 1.5 0 0 0 0 0 0 0 1 1 1 0\n", "NPNT .* found '1.5'", 3),
    ("'T'\n'W'\n1 1 1 4 0 0 0 0 0 0 1 1 1 0\n1 2 3\n", r"ISYML of object 'W' must be an "
     r"integer in 0..3, found '4'", 3),
    ("'T'\n'W'\n1 1 1 0 0 0 0 0 0 0 1 1 1\n-1\n1 2 3\n", r"line 4, columns 1-2: ISYMG .* "
     r"in 0..3, found '-1'", 4),
    ("'T'\n'W'\n1 1 1 0 0 0 0 0 0 0 1 1 1 0\n1 2 3\n4 5 6\n", "line 5: expected an object "
     "name, found a line of numbers", 5),
    ("'T'\n'W'\n1 2 1 0 0 0 0 0 0 0 1 1 1 0\n1 2 3\n'NEXT'\n1 1 1 0 0 0 0 0 0 0 1 1 1 0\n",
     "line 5: expected 6 numbers for object 'W' .*found the object name 'NEXT' after 3", 5),
    ("'T'\n'W'\n1 1 1 0 0 0 0 0 0 0 1 1 1 0\n1 2 / 3\n", "'/' ends the input early", 4),
    ("'T'\n'W'\n1 1 1 0 0 0 0 0 0 0 1 1 1 0\n1 2*\n", r"null values \('2\*'\)", 4),
    ("'T'\n'W'\n1 1 /\n", r"ends \('/'\) before NLINE and NPNT", 3),
    ("'T'\n'W'\n1 1 1 0 0 0 0 0 0 0 1 1 1 0\n1 2e999 3\n", r"line 4, columns 3-7: number out "
     r"of range in object 'W': '2e999'", 4),
    ("\n  \n", "empty file: expected a LaWGS file", None),
])
def test_errors_name_line_and_token(tmp_path, text, match, line):
    with pytest.raises(DeckError, match=match) as info:
        lawgs.read(_write(tmp_path, text))
    assert info.value.line == line
    assert info.value.path == str(tmp_path / "t.wgs")


def test_missing_file():
    with pytest.raises(DeckError, match="cannot open file"):
        lawgs.read("/nonexistent/x.wgs")


def _geometry():
    rng = np.random.default_rng(7)
    return Geometry(networks={"wing upper": rng.normal(size=(3, 5, 3)) * 10,
                              "pilot's canopy": rng.normal(size=(4, 2, 3)),
                              "fin": rng.normal(size=(2, 3, 3)) * 1e-7},
                    symmetry={"wing upper": "xz", "fin": "yz"}, title="round 'trip'")


def test_writer_layout_and_exact_round_trip(tmp_path):
    geo = _geometry()
    p = jc.write(geo, tmp_path / "o.wgs")
    lines = p.read_text().splitlines()
    assert lines[:3] == ["'round ''trip'''", "'wing upper'", "1 3 5 0 0 0 0 0 0 0 1 1 1 1"]
    assert len(lines[3].split()) == 6  # two points per line, as TM-85767 prints them
    assert lines[3 + 8] == "'pilot''s canopy'"  # 15 points: 8 lines
    back = jc.read(p)
    assert back.title == geo.title and back.allclose(geo, rtol=0, atol=0)
    for k in geo.networks:
        np.testing.assert_array_equal(back.networks[k], geo.networks[k])


def test_writer_digits_option(tmp_path):
    geo = _geometry()
    short = lawgs.write(geo, tmp_path / "s.wgs", digits=6)
    full = lawgs.write(geo, tmp_path / "f.wgs")
    assert short.stat().st_size < full.stat().st_size
    back = lawgs.read(short)
    for k in geo.networks:
        np.testing.assert_allclose(back.networks[k], geo.networks[k], rtol=5e-6, atol=0)


def test_writer_accepts_dict_and_does_not_mutate(tmp_path):
    nets = {"a": np.arange(24.0).reshape(2, 4, 3)}
    before = nets["a"].copy()
    lawgs.write(nets, tmp_path / "d.wgs")
    np.testing.assert_array_equal(nets["a"], before)
    assert nets["a"].flags.writeable
    np.testing.assert_array_equal(lawgs.read(tmp_path / "d.wgs").networks["a"], before)


def test_writer_error_leaves_old_file(tmp_path):
    p = tmp_path / "keep.wgs"
    p.write_text("old")
    with pytest.raises(GeometryError, match="must be one line"):
        lawgs.write({"two\nlines": np.zeros((1, 1, 3))}, p)
    assert p.read_text() == "old"
    assert sorted(x.name for x in tmp_path.iterdir()) == ["keep.wgs"]


@pytest.mark.parametrize("fname", [s[0] for s in SAMPLES])
def test_registry_reads_every_sample_as_lawgs(fname):
    geo = jc.read(DATA / fname)
    assert geo.allclose(lawgs.read(DATA / fname), rtol=0, atol=0)


def test_sniffer_picks_lawgs_by_content(tmp_path):
    src = (DATA / "tm85767_ex3_very_simple_airplane.wgs").read_bytes()
    p = tmp_path / "airplane.txt"
    p.write_bytes(src)
    assert list(jc.read(p).networks)[0] == "WING"
    assert not lawgs._sniff(b"HESS NETWORK LIST 1\nTITLE 'x'\n")


@given(arrays(float, st.tuples(st.integers(1, 4), st.integers(1, 5), st.just(3)),
              elements=st.floats(-1e300, 1e300, allow_nan=False, allow_infinity=False)))
@settings(max_examples=30, deadline=None)
def test_round_trip_is_exact_for_any_float(tmp_path_factory, net):
    p = tmp_path_factory.mktemp("h") / "h.wgs"
    lawgs.write({"n": net}, p)
    np.testing.assert_array_equal(lawgs.read(p).networks["n"], net)
