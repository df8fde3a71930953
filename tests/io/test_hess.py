"""Hess network listing (docs/hess.md): the documented example, exact round trip, errors."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

import juncture as jc
from juncture.errors import DeckError, GeometryError
from juncture.geometry import Geometry
from juncture.io import hess

DOC = Path(__file__).resolve().parents[2] / "docs" / "hess.md"


def _doc_example():
    text = DOC.read_text()
    block = re.search(r"## Example.*?```\n(.*?)```", text, re.S)
    return block.group(1)


def test_documented_example_reads_as_documented(tmp_path):
    p = tmp_path / "example.hess"
    p.write_text(_doc_example())
    geo = jc.read(p)
    assert geo.title == "tiny example"
    assert dict(geo.symmetry) == {"wing upper": "xz"}
    np.testing.assert_array_equal(geo.networks["wing upper"],
                                  [[[0.0, 1.0, 0.0], [0.5, 1.0, 0.1], [1.0, 1.0, 0.0]],
                                   [[0.2, 3.0, 0.0], [0.6, 3.0, 0.05], [1.0, 3.0, 0.0]]])
    np.testing.assert_array_equal(geo.networks["body"], [[[-1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]])
    # the documented example is oriented by the juncture convention: upper surface normal up
    w = geo.networks["wing upper"]
    assert np.cross(w[0, 1] - w[0, 0], w[1, 0] - w[0, 0])[2] > 0


def test_writer_reproduces_the_documented_example(tmp_path):
    geo = Geometry(networks={
        "wing upper": [[[0.0, 1.0, 0.0], [0.5, 1.0, 0.1], [1.0, 1.0, 0.0]],
                       [[0.2, 3.0, 0.0], [0.6, 3.0, 0.05], [1.0, 3.0, 0.0]]],
        "body": [[[-1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]]},
        symmetry={"wing upper": "xz"}, title="tiny example")
    p = hess.write(geo, tmp_path / "w.hess")
    assert p.read_text() == _doc_example()


def test_exact_round_trip(tmp_path):
    rng = np.random.default_rng(5)
    geo = Geometry(networks={"pilot's canopy": rng.normal(size=(3, 4, 3)) * 1e-9,
                             "flügel oben": rng.normal(size=(2, 5, 3)) * 1e12,
                             "a": np.full((1, 1, 3), -0.0)},
                   symmetry={"pilot's canopy": "yz", "a": "xy"}, title="it's 'quoted'")
    back = jc.read(jc.write(geo, tmp_path / "r.hess"))
    assert back.title == geo.title
    assert list(back.networks) == list(geo.networks)
    assert back.allclose(geo, rtol=0, atol=0)


def test_comments_blank_lines_and_case(tmp_path):
    p = tmp_path / "c.hess"
    p.write_text("# made by hand\n\nhess network list 1\nnetwork 1 'n' 1 2 XZ\n"
                 "  # a comment\nnline 1\n1 2 3\n\n4.5D0 5 6\nend\n# trailing comment\n")
    geo = hess.read(p)
    assert geo.title == ""
    np.testing.assert_array_equal(geo.networks["n"], [[[1, 2, 3], [4.5, 5, 6]]])
    assert dict(geo.symmetry) == {"n": "xz"}


_GOOD = ("HESS NETWORK LIST 1\nTITLE 't'\nNETWORK 1 'a' 2 1 none\nNLINE 1\n1 2 3\nNLINE 2\n"
         "4 5 6\nEND\n")


@pytest.mark.parametrize("text,match,line", [
    ("HESS NETWORK 1\n", r"expected the header 'HESS NETWORK LIST 1'", 1),
    ("HESS NETWORK LIST 2\nEND\n", "unsupported Hess listing version '2'", 1),
    (_GOOD.replace("NETWORK 1", "NETWORK 2"), "expected network index 1, found '2'", 3),
    (_GOOD.replace("'a'", "a"), "expected a quoted network name", 3),
    (_GOOD.replace("2 1 none", "0 1 none"), "number of n-lines must be an integer >= 1, "
     "found '0'", 3),
    (_GOOD.replace("2 1 none", "2 x none"), "points per n-line must be an integer >= 1", 3),
    (_GOOD.replace("none", "xx"), "symmetry plane must be one of none, xz, xy, yz, found 'xx'",
     3),
    (_GOOD.replace("2 1 none", "2 1"), "expected n-lines, points per n-line and symmetry", 3),
    (_GOOD.replace("NLINE 2", "NLINE 3"), r"expected 'NLINE 2' of network 'a' \(2 n-lines of 1 "
     r"points\), found 'NLINE 3'", 6),
    (_GOOD.replace("4 5 6", "4 5"), "expected point 1 of n-line 2 of network 'a' as three "
     "finite numbers 'x y z', found '4 5'", 7),
    (_GOOD.replace("4 5 6", "4 5 nan"), "found '4 5 nan'", 7),
    (_GOOD.replace("4 5 6", "4 5 1e999"), "three finite numbers 'x y z', found '4 5 1e999'", 7),
    (_GOOD.replace("END\n", ""), "file ended, expected 'NETWORK 2 ...' or 'END'", 7),
    (_GOOD + "NLINE 3\n", "unexpected text after END: 'NLINE 3'", 9),
    (_GOOD.replace("END\n", "NETWORK 2 'a' 1 1 none\nNLINE 1\n0 0 0\nEND\n"),
     "network name 'a' repeated", 8),
    (_GOOD.replace("END", "FOO"), "expected 'NETWORK 2 ...' or 'END', found 'FOO'", 8),
])
def test_errors_name_the_line(tmp_path, text, match, line):
    p = tmp_path / "bad.hess"
    p.write_text(text)
    with pytest.raises(DeckError, match=match) as info:
        hess.read(p)
    assert info.value.line == line


def test_missing_file_and_bad_names(tmp_path):
    with pytest.raises(DeckError, match="cannot open file"):
        hess.read(tmp_path / "none.hess")
    with pytest.raises(GeometryError, match="must be one line"):
        hess.write({"a\nb": np.zeros((1, 1, 3))}, tmp_path / "x.hess")
    assert not list(tmp_path.iterdir())


def test_sniffer(tmp_path):
    assert hess._sniff(b"# c\n\n  hess network list 1\n")
    assert not hess._sniff(b"'HESS NETWORK LIST'\n'WING'\n")
    assert not hess._sniff(b"")
    p = tmp_path / "listing.txt"
    p.write_text(_GOOD)
    assert list(jc.read(p).networks) == ["a"]
