"""End-to-end CLI: info, convert, demo, and one clear line (exit 2) for every bad deck."""

import subprocess
import sys

import numpy as np
import pytest

import juncture as jc
from juncture.cli import main
from tests.support import EXAMPLE_DECK, PDAS_DECK


def deck_lines():
    return PDAS_DECK.read_text().splitlines()


def test_info_lists_components_extents_and_warnings(capsys):
    assert main(["info", str(PDAS_DECK)]) == 0
    out = capsys.readouterr().out
    assert "SIMPLE TEST CASE TO ILLUSTRATE BODY RE-SHAPING" in out
    assert "wing" in out and "body" in out and "3 segment(s)" in out
    assert "NFORX(2) = 2 is outside the documented range" in out
    assert "reference area: 16" in out


def test_convert_deck_to_lawgs_and_back(tmp_path, capsys):
    out = tmp_path / "sst.wgs"
    assert main(["convert", str(EXAMPLE_DECK), str(out)]) == 0
    geo = jc.read(out)
    assert {"wing upper", "wing lower", "tail 1 upper", "fin 3 outboard", "pod 1"} <= set(
        geo.networks)
    assert geo.symmetry["wing upper"] == "xz" and "fin 3 outboard" not in geo.symmetry


def test_demo_runs_the_whole_pipeline(tmp_path, capsys):
    import json

    assert main(["demo", "-o", str(tmp_path)]) == 0
    for name in ("geometry.wgs", "geometry.p3d", "geometry.hess", "geometry.stl",
                 "geometry.vtk", "summary.json", "views.png", "intersection.png",
                 "fillet_sections.png", "areas.png", "wavedrag_areas.png", "wavedrag.json",
                 "massprops.txt", "report.html"):
        assert (tmp_path / name).stat().st_size > 0, name
    assert (tmp_path / "views.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    import base64

    report = (tmp_path / "report.html").read_text()
    for name in ("views.png", "areas.png", "wavedrag_areas.png"):  # embedded, not redrawn
        assert base64.b64encode((tmp_path / name).read_bytes()).decode() in report, name
    drag = json.loads((tmp_path / "wavedrag.json").read_text())
    base = drag["original"]["D_over_q"]
    assert drag["cubic fillet"]["D_over_q"] > base
    assert abs(drag["cubic fillet, fixed area"]["D_over_q"] - base) < 1e-3 * base
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert len(summary["intersections"]) == 14  # every touching pair, both surfaces
    import trimesh

    closed = trimesh.load(tmp_path / "mesh.stl")         # the airplane as one closed surface
    assert closed.is_watertight and closed.is_winding_consistent
    mass = (tmp_path / "massprops.txt").read_text()
    line = next(x for x in mass.splitlines() if x.startswith("enclosed solid"))
    assert f"{closed.volume:.6g}" in line
    out = capsys.readouterr().out
    assert "touching pairs:" in out and "largest gap" in out


def _bad(tmp_path, lines):
    p = tmp_path / "bad.inp"
    p.write_text("\r\n".join(lines) + "\r\n")
    return p


MALFORMED = {
    "truncated": (lambda L: L[:8], r"file ended after line 8 while reading"),
    "letter in number": (lambda L: L[:4] + ["  100.0   1O.0  0.000  140.0"] + L[5:],
                         r"line 5, columns 8-14: expected a number"),
    "count mismatch": (lambda L: L[:3] + ["   0.00  50.00 100.00  120.0"] + L[4:],
                       r"line 4, columns 22-28: expected 3 values"),
    "negative area": (lambda L: L[:9] + ["   0.00   40.7 -128.7  221.7  289.5 314.16"] + L[10:],
                      r"line 10, columns 15-21: .*negative"),
    "non-monotone": (lambda L: L[:8] + ["  0.000   10.0   30.0   20.0   40.0   50.0"] + L[9:],
                     r"line 9, columns 22-28: XFUS .*(decrease|increase)"),
}


@pytest.mark.parametrize("case", sorted(MALFORMED))
def test_malformed_decks_give_exit_2_and_one_line(tmp_path, capsys, case):
    mutate, match = MALFORMED[case]
    path = _bad(tmp_path, mutate(deck_lines()))
    assert main(["info", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("juncture: error: ")
    assert "Traceback" not in err
    import re

    assert re.search(match, err), err


def test_missing_file_is_exit_2(tmp_path, capsys):
    assert main(["info", str(tmp_path / "nope.inp")]) == 2
    assert "cannot open file" in capsys.readouterr().err


def test_entry_point_runs_as_a_program(tmp_path):
    bad = _bad(tmp_path, deck_lines()[:8])
    run = subprocess.run([sys.executable, "-m", "juncture", "info", str(bad)],
                         capture_output=True, text=True)
    assert run.returncode == 2 and "Traceback" not in run.stderr
    ok = subprocess.run([sys.executable, "-m", "juncture", "info", str(PDAS_DECK)],
                        capture_output=True, text=True)
    assert ok.returncode == 0 and "body" in ok.stdout


def test_extents_printed_match_the_model(capsys):
    main(["info", str(PDAS_DECK)])
    out = capsys.readouterr().out
    ext = jc.read(PDAS_DECK).extents()
    assert f"{ext[1, 0]:10.4g}" in out and np.isclose(ext[1, 0], 300.0)


def test_complete_writes_networks_summary_and_figures(tmp_path, capsys):
    import json

    out = tmp_path / "run"
    assert main(["complete", str(EXAMPLE_DECK), "-o", str(out), "--fillet", "cubic",
                 "--keep-area", "--format", "wgs", "p3d", "stl", "--blocks", "6",
                 "--figures"]) == 0
    for name in ("geometry.wgs", "geometry.p3d", "geometry.stl", "summary.json", "views.png",
                 "intersection.png", "lower_intersection.png", "fillet_sections.png",
                 "areas.png"):
        assert (out / name).stat().st_size > 0, name
    summary = json.loads((out / "summary.json").read_text())
    st = summary["stations"]
    total = np.pi * np.array(st["radius_new"]) ** 2 + np.array(st["area_fillet"])
    np.testing.assert_allclose(total, st["area_original"], rtol=1e-8)
    assert "wing upper" in summary["networks"]
    assert "worst area residual" in capsys.readouterr().out


def test_complete_on_the_pdas_deck_without_fillet(tmp_path):
    assert main(["complete", str(PDAS_DECK), "-o", str(tmp_path)]) == 0
    geo = jc.read(tmp_path / "geometry.wgs")
    assert {"body forward", "wing-body upper", "wing-body lower", "body aft"} <= set(
        geo.networks)


def test_a_fillet_too_large_for_the_wing_root_is_reduced_and_the_area_kept(tmp_path, capsys):
    """The end point 90 % of the way to section 2 once made the fillet add more area than
    the body had; the start angle is now reduced where the fillet would not fit."""
    import json

    assert main(["complete", str(PDAS_DECK), "-o", str(tmp_path), "--fillet", "cubic",
                 "--keep-area", "--end", "intersection", "--end-value", "0.9"]) == 0
    st = json.loads((tmp_path / "summary.json").read_text())["stations"]
    assert max(st["residual"]) < 1e-8
    assert all(b <= o * (1 + 1e-12) for b, o in zip(st["area_body"], st["area_original"]))


@pytest.mark.parametrize("mode", ["section", "fillet"])
def test_compensate_chooses_what_the_redesigned_body_gives_up(tmp_path, mode):
    """--compensate fillet keeps body + fillet at the original area (TM-4406 eq 14);
    section also gives up the wing root the shrinking uncovers, so it removes more."""
    import json

    assert main(["complete", str(PDAS_DECK), "-o", str(tmp_path / mode), "--fillet", "cubic",
                 "--keep-area", "--compensate", mode, "-q"]) == 0
    st = json.loads((tmp_path / mode / "summary.json").read_text())["stations"]
    body, fillet, orig = (np.array(st[k]) for k in ("area_body", "area_fillet_only",
                                                    "area_original"))
    gap = orig - body - fillet
    if mode == "fillet":
        assert np.max(np.abs(gap)) < 1e-6 * orig.max()
    else:
        assert np.min(gap) > -1e-6 * orig.max() and np.max(gap) > 1e-3 * orig.max()


def test_compensate_without_keep_area_is_a_usage_error(tmp_path, capsys):
    assert main(["complete", str(PDAS_DECK), "-o", str(tmp_path), "--fillet", "cubic",
                 "--compensate", "fillet"]) == 2
    assert "--compensate: only with --keep-area" in capsys.readouterr().err


def test_cad_files_declare_the_units_given_and_an_unknown_one_is_refused_first(tmp_path, capsys):
    pytest.importorskip("OCP")
    from OCP.STEPControl import STEPControl_Reader

    assert main(["complete", str(EXAMPLE_DECK), "-o", str(tmp_path / "a"), "--format", "step",
                 "--units", "in", "-q"]) == 0
    reader = STEPControl_Reader()
    assert int(reader.ReadFile(str(tmp_path / "a" / "geometry.step"))) == 1
    try:  # OCP 8.0
        from OCP.collections import Sequence_TCollection_AsciiString as Names
    except ImportError:  # OCP 7.9
        from OCP.TColStd import TColStd_SequenceOfAsciiString as Names
    length, angle, solid = Names(), Names(), Names()
    reader.FileUnits(length, angle, solid)
    found = {length.Value(i).ToCString().lower() for i in range(1, length.Length() + 1)}
    assert found == {"inch"}
    capsys.readouterr()
    assert main(["complete", str(EXAMPLE_DECK), "-o", str(tmp_path / "b"), "--format", "wgs",
                 "step", "--units", "furlong"]) == 2
    assert "found 'furlong'" in capsys.readouterr().err
    assert not (tmp_path / "b").exists()
