"""Every command over a corpus of bad inputs: exit status 2, one line naming the file or the
option and what was expected, never a traceback (issue 14)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from juncture.cli import main
from tests.support import EXAMPLE_DECK, LAWGS_DIR, PDAS_DECK, ROOT

EXAMPLES = ROOT / "examples"
MASS_SPEC = EXAMPLES / "massprops_wing_prop.json"
BLEND_SPEC = EXAMPLES / "missile_blend.json"
LAWGS = LAWGS_DIR / "tm85767_ex3_very_simple_airplane.wgs"


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    """Name -> path of each bad (or other-format) input."""
    d = tmp_path_factory.mktemp("corpus")
    rng = np.random.default_rng(14)
    files = {"missing": d / "missing.inp", "directory": d}
    (d / "empty.inp").write_bytes(b"")
    files["empty"] = d / "empty.inp"
    (d / "binary.inp").write_bytes(rng.integers(0, 256, 3000, dtype=np.uint8).tobytes())
    files["binary"] = d / "binary.inp"
    (d / "picture.png").write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 4)
    files["png"] = d / "picture.png"
    (d / "blank.inp").write_text("\n\n   \n")
    files["blank lines"] = d / "blank.inp"
    lines = EXAMPLE_DECK.read_text().splitlines(keepends=True)
    for frac in (0.05, 0.3, 0.6, 0.9):
        p = d / f"truncated_{frac}.inp"
        p.write_text("".join(lines[: max(1, int(frac * len(lines)))]))
        files[f"deck cut at {frac:.0%}"] = p
    text = EXAMPLE_DECK.read_text()
    p = d / "mid_field.inp"
    p.write_text(text[: len(text) // 2 + 3])  # cut inside a card's field
    files["deck cut mid-field"] = p
    model = d / "model.json"
    main(["convert", str(EXAMPLE_DECK), str(model), "-q"])
    p = d / "model_truncated.json"
    p.write_text(model.read_text()[: len(model.read_text()) // 2])
    files["model cut"] = p
    p = d / "list.json"
    p.write_text(json.dumps([1, 2, 3]))
    files["json list"] = p
    p = d / "spec_truncated.json"
    p.write_text(MASS_SPEC.read_text()[:200])
    files["mass spec cut"] = p
    p = d / "blend_truncated.json"
    p.write_text(BLEND_SPEC.read_text()[:150])
    files["blend spec cut"] = p
    files.update({"lawgs": LAWGS, "mass spec": MASS_SPEC, "blend spec": BLEND_SPEC,
                  "deck": EXAMPLE_DECK, "model": model})
    return files


# Inputs each command accepts; every other corpus entry must be refused in one line.
ACCEPTS = {"info": {"lawgs", "deck", "model"}, "convert": {"lawgs", "deck", "model"},
           "complete": {"deck", "model"}, "wavedrag": {"deck", "model"},
           "massprops": {"deck", "model", "mass spec"}, "blend": {"blend spec"},
           "mesh": {"deck", "model"}}
NAMES = ["missing", "directory", "empty", "binary", "png", "blank lines", "deck cut at 5%",
         "deck cut at 30%", "deck cut at 60%", "deck cut at 90%", "deck cut mid-field",
         "model cut", "json list", "mass spec cut", "blend spec cut", "lawgs", "mass spec",
         "blend spec"]


def _argv(command, path, out):
    return {"info": ["info", path], "convert": ["convert", path, str(out / "x.wgs")],
            "complete": ["complete", path, "-o", str(out)], "wavedrag": ["wavedrag", path],
            "massprops": ["massprops", path], "blend": ["blend", path, "-o", str(out)],
            "mesh": ["mesh", path, "-o", str(out)]}[command]


def _one_line(capsys):
    err = capsys.readouterr().err
    lines = [s for s in err.splitlines() if not s.startswith("juncture: warning:")]
    assert "Traceback" not in err, err
    assert len(lines) == 1, err
    return lines[0]


@pytest.mark.parametrize("command, name", [(c, n) for c in sorted(ACCEPTS) for n in NAMES
                                           if n not in ACCEPTS[c]])
def test_every_command_refuses_bad_files_in_one_line(corpus, tmp_path, capsys, command, name):
    path = corpus[name]
    status = main(_argv(command, str(path), tmp_path / "out"))
    line = _one_line(capsys)
    assert status == 2, line
    assert line.startswith("juncture: error: ") and path.name in line, line
    assert not (tmp_path / "out" / "x.wgs").exists()


@pytest.mark.parametrize("name", ["lawgs", "deck", "model"])
def test_accepted_inputs_run(corpus, tmp_path, capsys, name):
    assert main(["info", str(corpus[name])]) == 0


def _file(tmp_path):
    f = tmp_path / "a_file"
    f.write_text("x")
    return f


@pytest.mark.parametrize("argv", [
    ["convert", str(EXAMPLE_DECK), "{file}/x.wgs"],
    ["convert", str(EXAMPLE_DECK), "{tmp}/x.unknown"],
    ["convert", str(LAWGS), "{tmp}/x.inp"],
    ["complete", str(EXAMPLE_DECK), "-o", "{file}"],
    ["complete", str(EXAMPLE_DECK), "-o", "{file}/sub"],
    ["wavedrag", str(PDAS_DECK), "-o", "{file}"],
    ["blend", str(BLEND_SPEC), "-o", "{file}"],
    ["mesh", str(PDAS_DECK), "-o", "{file}"],
    ["demo", "-o", "{file}"],
])
def test_unwritable_or_unknown_outputs_are_one_line(tmp_path, capsys, argv):
    f = _file(tmp_path)
    argv = [a.format(file=f, tmp=tmp_path) for a in argv]
    assert main(argv) == 2
    line = _one_line(capsys)
    assert line.startswith("juncture: error: ") and ("a_file" in line or "x." in line), line
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a_file"]  # nothing half-written


BAD_OPTIONS = [
    (["complete", "--theta-u", "-10"], "--theta-u"),
    (["complete", "--theta-u", "90"], "--theta-u"),
    (["complete", "--theta-u", "abc"], "--theta-u"),
    (["complete", "--theta-u", "nan"], "--theta-u"),
    (["complete", "--fillet", "cubic", "--end-value", "0"], "--end-value"),
    (["complete", "--fillet", "cubic", "--end-value", "-1"], "--end-value"),
    (["complete", "--fillet", "cubic", "--end", "section", "--end-value", "100"],
     "--end-value"),
    (["complete", "--fillet", "cubic", "--blend-length", "-3"], "--blend-length"),
    (["complete", "--fillet", "circular", "--radius", "0"], "--radius"),
    (["complete", "--fillet", "cubic", "--radius", "3"], "--radius"),
    (["complete", "--fillet", "circular", "--theta-u", "30"], "--theta-u"),
    (["complete", "--fillet", "circular", "--remedy", "parabolas"], "--remedy"),
    (["complete", "--blend-length", "2"], "--blend-length"),
    (["complete", "--keep-area"], "--keep-area"),
    (["complete", "--blocks", "5"], "--blocks"),
    (["complete", "--fillet", "round"], "--fillet"),
    (["complete", "--format", "foo"], "--format"),
    (["complete", "--format", "wgs", "inp"], "--format"),
    (["complete", "--fillet", "cubic", "--single-network", "--remedy", "parabolas"],
     "--remedy"),
    (["wavedrag", "--mach", "0.5"], "--mach"),
    (["wavedrag", "--mach", "abc"], "--mach"),
    (["wavedrag", "--n-x", "0"], "--n-x"),
    (["wavedrag", "--n-theta", "-2"], "--n-theta"),
    (["wavedrag", "--keep-area"], "--keep-area"),
    (["massprops", "--density", "-1"], "--density"),
    (["massprops", "--density", "0"], "--density"),
    (["massprops", "--density", "inf"], "--density"),
    (["info", "--format", "nope"], "--format"),
    (["nocommand"], "invalid choice"),
]


@pytest.mark.parametrize("argv, flag", BAD_OPTIONS, ids=lambda v: " ".join(v)
                         if isinstance(v, list) else v)
def test_option_values_outside_their_range_are_one_line(tmp_path, capsys, argv, flag):
    full = argv[:1] + [str(EXAMPLE_DECK)] + argv[1:] if argv[0] != "nocommand" else argv
    if argv[0] == "complete":
        full += ["-o", str(tmp_path / "out")]
    assert main(full) == 2
    line = _one_line(capsys)
    assert flag in line and "error" in line, line
    assert not (tmp_path / "out").exists()  # refused before any work
