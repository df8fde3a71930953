"""juncture wavedrag: JSON output, the fixed-area proof, Sears-Haack through a real deck."""

import json

import numpy as np
import pytest

import juncture as jc
from juncture.cli import main
from juncture.io.wavedrag import write_deck
from juncture.model import CircularBody, Configuration
from tests.support import EXAMPLE_DECK, PDAS_DECK


def run_json(capsys, *args):
    assert main(["wavedrag", *map(str, args), "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_json_has_the_documented_keys(capsys):
    doc = run_json(capsys, PDAS_DECK, "--slender-body")
    assert set(doc) >= {"mach", "D_over_q", "CD", "method"}
    assert doc["mach"] is None and doc["method"].startswith("slender-body")
    np.testing.assert_allclose(doc["CD"], doc["D_over_q"] / 16.0)  # REFA of the deck
    doc = run_json(capsys, PDAS_DECK, "--mach", "1.5", "--n-theta", "8")
    assert doc["mach"] == 1.5 and "far-field" in doc["method"]


def test_the_decks_case_cards_run_by_default_and_mach_overrides_them(capsys, tmp_path):
    """The PDAS sample's card M1.2 (NX 50, NTHETA 16): the default run is that far-field
    case at 51 stations, equal to the library call with those settings; two cards give a
    table of both; --mach and --n-x override."""
    from juncture.analysis import wavedrag
    from juncture.io._deck import DeckCase

    cfg = jc.read(PDAS_DECK)
    doc = run_json(capsys, PDAS_DECK)
    ref = wavedrag(cfg, 1.2, n_x=51, n_theta=16)
    assert doc["mach"] == 1.2 and doc["D_over_q"] == ref["D_over_q"]
    assert run_json(capsys, PDAS_DECK, "--mach", "1.5")["mach"] == 1.5
    # A second card: a table of both (JSON: a list), each with its own NX and NTHETA.
    src = PDAS_DECK.read_text().splitlines()
    i = next(k for k, ln in enumerate(src) if ln.startswith("M1.2"))
    two = tmp_path / "two.inp"
    two.write_text("\n".join(src[:i + 2] + ["M2.0" + "2000  30   8   0   0"] + src[i + 2:])
                   + "\n")
    cards = [c for c in jc.read(two).source.cases if c.mach > 0]
    assert [(c.mach, c.nx, c.ntheta) for c in cards] == [(1200, 50, 16), (2000, 30, 8)]
    runs = run_json(capsys, two)
    assert [(r["mach"], r["n_x"], r["n_theta"]) for r in runs] == [(1.2, 51, 16), (2.0, 31, 8)]
    assert runs[1]["results"]["original"]["D_over_q"] == \
        wavedrag(cfg, 2.0, n_x=31, n_theta=8)["D_over_q"]
    runs = run_json(capsys, two, "--n-x", "41")
    assert [r["n_x"] for r in runs] == [41, 41]
    assert main(["wavedrag", str(two)]) == 0
    table = capsys.readouterr().out
    assert "M1.2" in table and "M2.0" in table
    assert DeckCase  # the card type the deck reader gives


@pytest.mark.parametrize("fillet", ["cubic", "circular"])
def test_fillet_raises_drag_and_fixed_area_restores_it(capsys, fillet):
    doc = run_json(capsys, EXAMPLE_DECK, "--fillet", fillet, "--keep-area", "--slender-body")
    cases = doc["cases"]
    base = cases["original"]["D_over_q"]
    assert cases[f"{fillet} fillet"]["D_over_q"] > base
    assert abs(cases[f"{fillet} fillet, fixed area"]["D_over_q"] - base) < 1e-3 * base


@pytest.mark.parametrize("fillet", ["cubic", "circular"])
def test_fixed_area_on_a_sparse_deck_with_more_lofting_lines(fillet):
    """The PDAS deck has three lofting lines, so a single interior fillet station: the fixed-
    area drag still returns to the unfilleted one within 0.1 %, and with the chord
    subdivided (the same section curves) too."""
    from juncture.analysis import wavedrag

    cfg = jc.read(PDAS_DECK)
    base = wavedrag(cfg, geometry=jc.complete(cfg, None))["D_over_q"]
    filleted = wavedrag(cfg, geometry=jc.complete(cfg, fillet))["D_over_q"]
    fixed = wavedrag(cfg, geometry=jc.complete(cfg, fillet, True))["D_over_q"]
    assert filleted > base and abs(fixed - base) < 1e-3 * base
    wing = cfg["wing"]
    xc, t = wing.x_over_c, np.arange(1, 12) / 12
    fine = cfg.with_component(wing.with_chord_stations(
        (xc[:-1, None] + t * np.diff(xc)[:, None]).ravel()))
    base = wavedrag(fine, geometry=jc.complete(fine, None))["D_over_q"]
    fixed = wavedrag(fine, geometry=jc.complete(fine, fillet, True))["D_over_q"]
    assert abs(fixed - base) < 1e-3 * base


def _sears_haack_deck(path, length, radius_max, n=81):
    x = length * (1 - np.cos(np.linspace(0, np.pi, n))) / 2  # clustered at both ends
    xi = x / length
    area = np.pi * radius_max ** 2 * (4 * xi * (1 - xi)) ** 1.5
    body = CircularBody("body", x, np.sqrt(area / np.pi), segments=(n // 3, n // 3,
                                                                   n - 2 * (n // 3)))
    # Segments of a deck repeat their joint station: split x into three overlapping pieces.
    k = n // 3
    xs = np.concatenate([x[:k + 1], x[k:2 * k + 1], x[2 * k:]])
    rs = np.concatenate([body.radius[:k + 1], body.radius[k:2 * k + 1], body.radius[2 * k:]])
    body = CircularBody("body", xs, rs, segments=(k + 1, k + 1, n - 2 * k))
    from juncture.io._deck_convert import configuration_to_deck

    write_deck(configuration_to_deck(Configuration({"body": body}, title="SEARS-HAACK",
                                                   reference_area=1.0)), path)
    volume = 3 * np.pi * np.pi * radius_max ** 2 * length / 16
    return 128 * volume ** 2 / (np.pi * length ** 4)


@pytest.mark.filterwarnings("ignore::juncture.JunctureWarning")  # 7-column areas round
@pytest.mark.parametrize("length, radius", [(100.0, 5.0), (60.0, 6.0), (240.0, 7.5)])
def test_sears_haack_bodies_through_a_deck(tmp_path, capsys, length, radius):
    deck = tmp_path / "sh.inp"
    exact = _sears_haack_deck(deck, length, radius)
    doc = run_json(capsys, deck, "--n-x", "121")
    assert doc["D_over_q"] == pytest.approx(exact, rel=1e-3)


def test_output_directory_gets_the_plot_and_numbers(tmp_path, capsys):
    assert main(["wavedrag", str(PDAS_DECK), "--fillet", "cubic", "-o", str(tmp_path)]) == 0
    assert (tmp_path / "areas.png").stat().st_size > 0
    data = json.loads((tmp_path / "wavedrag.json").read_text())
    assert set(data) == {"original", "cubic fillet"}
    assert "D/q" in capsys.readouterr().out


def test_keep_area_without_fillet_is_a_usage_error(capsys):
    assert main(["wavedrag", str(PDAS_DECK), "--keep-area"]) == 2
    assert "argument --keep-area: needs --fillet cubic or circular" in capsys.readouterr().err


def test_converge_refines_until_it_settles_and_says_how_far_the_start_was(capsys):
    """A Sears-Haack body (slender body): refinement stops by the tolerance near the exact
    128 V^2 / (pi l^4); the PDAS wing-body at a coarse start is reported off, with a
    warning, and the refined value is the library's at the final resolution."""
    from juncture.analysis import converged_wavedrag, wavedrag

    length, rmax = 100.0, 5.0
    x = length * (1 - np.cos(np.linspace(0, np.pi, 121))) / 2
    r = rmax * (4 * (x / length) * (1 - x / length)) ** 0.75
    cfg = Configuration({"body": CircularBody("body", x, r)}, reference_area=1.0)
    exact = 128 * (3 * np.pi ** 2 * rmax ** 2 * length / 16) ** 2 / (np.pi * length ** 4)
    c = converged_wavedrag(cfg, None, n_x=21, tolerance=1e-3)
    assert c["converged"] and c["error"] <= 1e-3 * c["D_over_q"]
    assert c["D_over_q"] == pytest.approx(exact, rel=5e-3)
    assert [h[0] for h in c["history"]] == [21 * 2 ** k - (2 ** k - 1)
                                           for k in range(len(c["history"]))]
    short = converged_wavedrag(cfg, None, n_x=21, tolerance=1e-12, max_doublings=2)
    assert not short["converged"] and len(short["history"]) == 3  # stopped by the budget
    assert main(["wavedrag", str(PDAS_DECK), "--n-x", "21", "--n-theta", "4",
                 "--converge", "0.1"]) == 0
    out, err = capsys.readouterr()
    line = next(ln for ln in out.splitlines() if "converged: D/q" in ln)
    assert line.startswith("M1.2: converged: ")  # by the tolerance, at n_x 81, NTHETA 16
    assert "juncture: warning: M1.2: the wave drag at n_x 21, NTHETA 4 is" in err
    final = [int(v) for v in line.split(" at n_x ")[1].split(" (")[0].split(", NTHETA ")]
    value = float(line.split("D/q ")[1].split(" +-")[0])
    ref = wavedrag(jc.read(PDAS_DECK), 1.2, n_x=final[0], n_theta=final[1])["D_over_q"]
    assert value == pytest.approx(ref, rel=1e-5)


def test_harris_mode_and_its_switches(capsys):
    from juncture.analysis import wavedrag
    from juncture.analysis.harris import HarrisConventions

    cfg = jc.read(EXAMPLE_DECK)
    assert main(["wavedrag", str(EXAMPLE_DECK), "--harris", "--mach", "1.6", "--json",
                 "--n-x", "41", "--n-theta", "8"]) == 0
    cap = capsys.readouterr()
    out = json.loads(cap.out)
    assert "Harris conventions (linear_chordwise, sum_components" in out["method"]
    with pytest.warns(jc.JunctureWarning):
        expected = wavedrag(cfg, 1.6, 41, 8, method="harris")["D_over_q"]
    assert out["D_over_q"] == pytest.approx(expected, rel=1e-12)
    assert cap.err.count("root section lies inside") == 5  # wing, 3 fins, tail: once each
    assert main(["wavedrag", str(EXAMPLE_DECK), "--harris", "--harris-off", "sum-components",
                 "linear-chordwise", "fusard-fit", "--mach", "1.6", "--json", "--n-x", "41",
                 "--n-theta", "8"]) == 0
    off = json.loads(capsys.readouterr().out)
    conv = HarrisConventions(linear_chordwise=False, sum_components=False, fusard_fit=False)
    assert off["D_over_q"] == pytest.approx(
        wavedrag(cfg, 1.6, 41, 8, method="harris", conventions=conv)["D_over_q"], rel=1e-12)
    for argv, match in ((["--harris-off", "half-turn"], "--harris-off: needs --harris"),
                        (["--harris", "--fillet", "cubic"], "not with --fillet")):
        assert main(["wavedrag", str(EXAMPLE_DECK), *argv]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and match in err[0]
