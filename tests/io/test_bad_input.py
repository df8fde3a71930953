"""Bad input never gives a traceback: every reader and writer raises a JunctureError.

For every registered reader (wave-drag deck, LaWGS, Plot3D, Hess listing, juncture JSON/TOML
model): an empty file, binary data (random bytes, a PNG header), truncated and mutated copies
of valid files, a file of another format given with the wrong ``format=``, a missing path and
a directory. For the writers: unknown extensions, a path in a missing directory, a directory,
and a Geometry given to a format that needs components. Each must raise a
:class:`juncture.errors.JunctureError` whose message is one line and names the file.
"""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import juncture as jc
from juncture.errors import DeckError, JunctureError
from tests.support import DECKS_DIR, EXAMPLE_DECK, LAWGS_DIR, PDAS_DECK

READERS = ("wavedrag", "lawgs", "plot3d", "hess", "juncture")
EXT = {"wavedrag": ".inp", "lawgs": ".wgs", "plot3d": ".p3d", "hess": ".hess",
       "juncture": ".json"}
PNG = (b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00\x00\x10\x00\x00\x00\x10\x08\x06\x00\x00"
       b"\x00\x1f\xf3\xffa\x00\x00\x00\x19IDATx\x9cc`\x18\x05\xa3`\x14\x8c\x02\x08\x00\x00")
HYPOTHESIS = settings(max_examples=40, deadline=None,
                      suppress_health_check=[HealthCheck.function_scoped_fixture])


def _quiet_read(path, fmt=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(path, format=fmt)


@pytest.fixture(scope="module")
def samples(tmp_path_factory):
    """Valid files of every readable format: format -> list of paths."""
    d = tmp_path_factory.mktemp("samples")
    cfg = _quiet_read(EXAMPLE_DECK)
    geo = _quiet_read(LAWGS_DIR / "tm85767_ex3_very_simple_airplane.wgs")
    jc.write(cfg, d / "model.json")
    (d / "model.toml").write_text(
        'juncture = 1\ntitle = "plate"\n[[components]]\nname = "wing"\ntype = "wing"\n'
        'le = [[0.0, 0.0, 0.0], [1.0, 5.0, 0.0]]\nchord = [4.0, 2.0]\n'
        'x_over_c = [0.0, 50.0, 100.0]\nupper = [[0.0, 3.0, 0.0], [0.0, 3.0, 0.0]]\n'
        '[[cases]]\nncase = "M2"\nmach = 2000\nnx = 50\n')
    jc.write(geo, d / "grid.p3d")
    jc.write(geo, d / "networks.hess")
    return {
        "wavedrag": [PDAS_DECK, EXAMPLE_DECK, DECKS_DIR / "cambered_wing.inp",
                     DECKS_DIR / "two_configurations_four_canard_sets.inp"],
        "lawgs": [LAWGS_DIR / "tm85767_ex3_very_simple_airplane.wgs",
                  LAWGS_DIR / "tm85767_ex2_three_cylinders_local.wgs"],
        "plot3d": [d / "grid.p3d"],
        "hess": [d / "networks.hess"],
        "juncture": [d / "model.json", d / "model.toml"],
    }


def assert_clean_error(excinfo, path, kind=JunctureError):
    """A ``kind`` whose message is one line and names ``path``."""
    exc = excinfo.value
    assert isinstance(exc, kind), repr(exc)
    message = str(exc)
    assert len(message.splitlines()) == 1, message
    assert str(path) in message, message
    if isinstance(exc, DeckError):
        assert exc.path == str(path)
    return exc


def read_fails_cleanly(path, fmt=None, kind=JunctureError):
    with pytest.raises(Exception) as info:
        _quiet_read(path, fmt)
    return assert_clean_error(info, path, kind)


def read_or_fail_cleanly(path, fmt=None):
    """Reading either succeeds or raises a clean JunctureError (never anything else)."""
    try:
        _quiet_read(path, fmt)
    except Exception as exc:  # noqa: BLE001 - the point is to see what comes out
        assert isinstance(exc, JunctureError), repr(exc)
        assert len(str(exc).splitlines()) == 1, str(exc)
        assert str(path) in str(exc), str(exc)
        return exc
    return None


# -- readers ----------------------------------------------------------------------------------

@pytest.mark.parametrize("fmt", READERS)
@pytest.mark.parametrize("content", [b"", b"  \n\n \r\n"], ids=["empty", "blank"])
@pytest.mark.parametrize("explicit", [True, False], ids=["format=", "sniffed"])
def test_empty_file(tmp_path, fmt, content, explicit):
    path = tmp_path / f"empty{EXT[fmt]}"
    path.write_bytes(content)
    exc = read_fails_cleanly(path, fmt if explicit else None, DeckError)
    assert "empty file: expected a" in str(exc)


@pytest.mark.parametrize("fmt", READERS)
@pytest.mark.parametrize("explicit", [True, False], ids=["format=", "sniffed"])
def test_png_header(tmp_path, fmt, explicit):
    path = tmp_path / f"picture{EXT[fmt]}"
    path.write_bytes(PNG)
    exc = read_fails_cleanly(path, fmt if explicit else None, DeckError)
    assert "binary data (a NUL byte at offset 8): expected a" in str(exc)


@pytest.mark.parametrize("fmt", READERS)
@given(data=st.binary(min_size=1, max_size=600))
@HYPOTHESIS
def test_random_bytes(tmp_path, fmt, data):
    path = tmp_path / f"random{EXT[fmt]}"
    path.write_bytes(data)
    read_or_fail_cleanly(path, fmt)
    read_or_fail_cleanly(path)


@pytest.mark.parametrize("fmt", READERS)
@given(fraction=st.floats(0.0, 1.0), index=st.integers(0, 3))
@HYPOTHESIS
def test_truncated_copies(tmp_path, samples, fmt, fraction, index):
    source = samples[fmt][index % len(samples[fmt])]
    data = source.read_bytes()
    cut = int(fraction * len(data))
    path = tmp_path / f"cut{source.suffix}"
    path.write_bytes(data[:cut])
    exc = read_or_fail_cleanly(path, fmt)
    if fmt == "wavedrag" and exc is not None and data[:cut].strip():
        assert isinstance(exc, DeckError) and exc.line is not None, str(exc)


@pytest.mark.parametrize("fmt", READERS)
def test_truncated_at_every_line(tmp_path, samples, fmt):
    for source in samples[fmt]:
        lines = source.read_bytes().splitlines(keepends=True)
        for k in range(len(lines)):
            path = tmp_path / f"lines{source.suffix}"
            path.write_bytes(b"".join(lines[:k]))
            read_or_fail_cleanly(path, fmt)
            read_or_fail_cleanly(path)


@pytest.mark.parametrize("fmt", READERS)
@given(edits=st.lists(st.tuples(st.floats(0.0, 1.0), st.sampled_from(
    [b"", b"-", b".", b"E", b"+", b"0", b"9", b" ", b"\n", b"\t", b",", b"/", b"*", b"'",
     b'"', b"x", b"1e999", b"[", b"{", b"\xff"]), st.integers(0, 8)), min_size=1,
    max_size=4), index=st.integers(0, 3))
@HYPOTHESIS
def test_mutated_copies(tmp_path, samples, fmt, edits, index):
    source = samples[fmt][index % len(samples[fmt])]
    data = bytearray(source.read_bytes())
    for where, insert, delete in edits:
        i = int(where * len(data))
        data[i:i + delete] = insert
    path = tmp_path / f"mutated{source.suffix}"
    path.write_bytes(bytes(data))
    read_or_fail_cleanly(path, fmt)


@pytest.mark.parametrize("given_fmt, actual_fmt",
                         [(a, b) for a in READERS for b in READERS if a != b])
def test_wrong_explicit_format(samples, given_fmt, actual_fmt):
    for path in samples[actual_fmt]:
        read_fails_cleanly(path, given_fmt, DeckError)


@pytest.mark.parametrize("fmt", [*READERS, None])
def test_missing_path(tmp_path, fmt):
    path = tmp_path / f"missing{EXT.get(fmt, '.inp')}"
    exc = read_fails_cleanly(path, fmt, DeckError)
    assert "cannot open file: No such file or directory" in str(exc)


@pytest.mark.parametrize("fmt", [*READERS, None])
def test_directory(tmp_path, fmt):
    path = tmp_path / f"folder{EXT.get(fmt, '')}"
    path.mkdir()
    exc = read_fails_cleanly(path, fmt, DeckError)
    assert "is a directory: expected a" in str(exc)


def test_unknown_extension_and_content_lists_what_is_read(tmp_path):
    path = tmp_path / "notes.foo"
    path.write_text("hello\nworld\n")
    exc = read_fails_cleanly(path, None, DeckError)
    for ext in (".inp", ".wgs", ".p3d", ".hess", ".json", ".toml"):
        assert ext in str(exc)
    assert "cannot tell the format from the content or the file name (extension '.foo')" \
        in str(exc)


def test_unknown_format_name_lists_the_formats(tmp_path):
    with pytest.raises(JunctureError, match=r"unknown format 'deck'; known formats: .*lawgs"):
        jc.read(tmp_path / "x.inp", format="deck")
    with pytest.raises(JunctureError, match=r"unknown format 'deck'; known formats: .*wavedrag"):
        jc.write({"a": np.zeros((2, 2, 3))}, tmp_path / "x.inp", format="deck")


def test_bad_json_model_fields_are_spec_errors(tmp_path, samples):
    """Ill-typed fields the model constructors would choke on (found by fuzzing)."""
    import json

    base = json.loads(samples["juncture"][0].read_text())
    body = next(i for i, c in enumerate(base["components"]) if c["type"] == "circular_body")
    cases = [
        (("components", body, "segments"), [[1]], "'segments' must be a list of integers"),
        (("components", body, "points_per_section"), ["abc"], "'points_per_section' must"),
        (("components", body, "x"), [1e400, 2.0], "'x' holds a number out of range"),
        (("components", body, "radius"), [1.0, "2"], "'radius' must hold numbers only"),
        (("components", 0, "le"), [[1.0, 2.0], [3.0]], "'le' must be a rectangular array"),
        (("reference", "area"), [1.0], "reference: field 'area' must be a finite number"),
    ]
    for keys, value, match in cases:
        d = json.loads(json.dumps(base))
        target = d
        for k in keys[:-1]:
            target = target[k]
        target[keys[-1]] = value
        path = tmp_path / "bad.json"
        path.write_text(json.dumps(d))
        exc = read_fails_cleanly(path, None, DeckError)
        assert match in str(exc)


# -- writers ----------------------------------------------------------------------------------

def _objects():
    cfg = _quiet_read(EXAMPLE_DECK)
    return cfg, cfg.to_geometry()


def _writable(fmt):
    if fmt in ("step", "iges"):
        pytest.importorskip("OCP", reason="STEP/IGES need the cad extra")
    cfg, geo = _objects()
    return cfg if fmt in ("wavedrag", "juncture") else geo


def _ext(fmt):
    return {"wavedrag": ".inp", "juncture": ".json", "lawgs": ".wgs", "plot3d": ".p3d",
            "hess": ".hess", "stl": ".stl", "vtk": ".vtk", "vtu": ".vtu", "obj": ".obj",
            "step": ".step", "iges": ".igs"}[fmt]


def test_every_writer_is_covered():
    assert set(jc.io.writer_formats()) == {"wavedrag", "juncture", "lawgs", "plot3d", "hess",
                                           "stl", "vtk", "vtu", "obj", "step", "iges"}


@pytest.mark.parametrize("fmt", ["wavedrag", "juncture", "lawgs", "plot3d", "hess", "stl",
                                 "vtk", "vtu", "obj", "step", "iges"])
def test_write_into_a_missing_directory(tmp_path, fmt):
    obj = _writable(fmt)
    path = tmp_path / "no such dir" / f"out{_ext(fmt)}"
    with pytest.raises(Exception) as info:
        jc.write(obj, path)
    exc = assert_clean_error(info, path)
    assert "the directory" in str(exc) and "does not exist" in str(exc)
    assert list(tmp_path.iterdir()) == []


def test_write_below_a_plain_file(tmp_path):
    _, geo = _objects()
    (tmp_path / "a_file").write_text("x")
    path = tmp_path / "a_file" / "out.wgs"
    with pytest.raises(Exception) as info:
        jc.write(geo, path)
    exc = assert_clean_error(info, path)
    assert str(exc).endswith(f": {tmp_path / 'a_file'} is a file, not a directory")
    assert [p.name for p in tmp_path.iterdir()] == ["a_file"]


@pytest.mark.parametrize("fmt", ["wavedrag", "juncture", "lawgs", "plot3d", "hess", "stl",
                                 "vtk", "vtu", "obj", "step", "iges"])
def test_write_onto_a_directory(tmp_path, fmt):
    obj = _writable(fmt)
    path = tmp_path / f"out{_ext(fmt)}"
    path.mkdir()
    (path / "keep.txt").write_text("kept")
    with pytest.raises(Exception) as info:
        jc.write(obj, path)
    exc = assert_clean_error(info, path)
    assert "it is a directory" in str(exc)
    assert [p.name for p in tmp_path.iterdir()] == [path.name]
    assert (path / "keep.txt").read_text() == "kept"


def test_disk_full_while_writing_leaves_nothing(tmp_path, monkeypatch):
    import builtins

    from juncture.io import _registry

    class Full:
        def __init__(self, *args, **kwargs):
            self.fh = builtins.open(*args, **kwargs)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.fh.close()

        def write(self, text):
            raise OSError(28, "No space left on device")

    _, geo = _objects()
    path = tmp_path / "out.wgs"
    path.write_text("old")
    monkeypatch.setattr(_registry, "open", Full, raising=False)
    with pytest.raises(JunctureError, match=r"cannot write .*out.wgs: No space left on device$"):
        jc.write(geo, path)
    assert path.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["out.wgs"]


def test_os_error_in_the_rename_is_a_juncture_error(tmp_path, monkeypatch):
    import os

    _, geo = _objects()
    path = tmp_path / "out.wgs"

    def refuse(src, dst):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(os, "replace", refuse)
    with pytest.raises(JunctureError, match=r"cannot write .*out.wgs: Permission denied$"):
        jc.write(geo, path)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("ext, fmt", [(".inp", "wave-drag deck"), (".wd", "wave-drag deck"),
                                      (".json", "juncture JSON model")])
@pytest.mark.parametrize("source", ["lawgs", "plot3d", "hess"])
def test_geometry_to_a_format_that_needs_components(tmp_path, samples, ext, fmt, source):
    geo = _quiet_read(samples[source][0])
    path = tmp_path / f"out{ext}"
    with pytest.raises(Exception) as info:
        jc.write(geo, path)
    exc = assert_clean_error(info, path)
    assert f"a {fmt} holds components (a Configuration" in str(exc)
    assert "not surface networks (a Geometry" in str(exc)
    assert list(tmp_path.iterdir()) == []


def test_convert_geometry_to_a_deck_is_exit_2(tmp_path, samples, capsys):
    from juncture.cli import main

    for source in (samples["lawgs"][0], samples["plot3d"][0]):
        assert main(["convert", str(source), str(tmp_path / "x.inp")]) == 2
        err = capsys.readouterr().err
        assert len(err.strip().splitlines()) == 1 and "holds components" in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name, match", [
    ("x.foo", r"x.foo: unknown output extension '.foo'; juncture writes "),
    ("x", r"x: no extension to tell the output format by; juncture writes "),
    ("x.toml", r"x.toml: juncture reads '.toml' files but does not write them; juncture "
               r"writes "),
])
def test_unknown_output_extension_lists_the_known_ones(tmp_path, name, match):
    cfg, geo = _objects()
    for obj in (cfg, geo):
        with pytest.raises(JunctureError, match=match) as info:
            jc.write(obj, tmp_path / name)
        assert_clean_error(info, tmp_path / name)
        for ext in (".wgs", ".p3d", ".hess", ".stl", ".vtk", ".vtu", ".obj", ".inp",
                    ".json", ".step", ".igs"):
            assert ext in str(info.value)
    assert list(tmp_path.iterdir()) == []


def test_toml_by_explicit_format_is_refused(tmp_path):
    cfg, _ = _objects()
    with pytest.raises(JunctureError, match="reads TOML models but writes JSON only"):
        jc.write(cfg, tmp_path / "x.toml", format="juncture")
    assert list(tmp_path.iterdir()) == []


def test_a_good_path_still_writes(tmp_path):
    cfg, geo = _objects()
    assert Path(jc.write(geo, tmp_path / "ok.wgs")).stat().st_size > 0
    jc.write(cfg, tmp_path / "ok.inp")
    assert (tmp_path / "ok.inp").stat().st_size > 0


@pytest.mark.parametrize("header, match", [
    ("1e999 2 2 0 0 0 0 0 0 0 1 1 1 0", r"line 3, columns 1-5: NOBJ of object 'W' must be an "
                                        r"integer, found '1e999'"),
    ("1 2 2 0 0 0 0 0 0 1e999 1 1 1 0", r"line 3, columns \d+-\d+: TZ of object 'W' must be a "
                                        r"finite number, found '1e999'"),
    ("1 2 2 0 0 0 0 0 0 0 1e300 1 1 0", r"line 2: object 'W': its placement .* takes "
                                        r"coordinates out of range"),
])
def test_lawgs_header_out_of_range(tmp_path, header, match):
    """Found by the mutation test: an infinite header value crashed int() (and the sniffer),
    an overflowing placement gave a GeometryError without the file."""
    path = tmp_path / "w.wgs"
    path.write_text(f"'T'\n'W'\n{header}\n0 0 0 1e300 0 0\n0 1 0 1 1 0\n")
    for fmt in ("lawgs", None):
        with pytest.raises(Exception) as info:
            _quiet_read(path, fmt)
        exc = assert_clean_error(info, path, DeckError)
        assert re.search(match, str(exc)), str(exc)
