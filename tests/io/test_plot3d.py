"""Plot3D formatted multi-block surface grids: writer layout, reader variants, sniffer."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import juncture as jc
from juncture.errors import DeckError
from juncture.geometry import Geometry
from juncture.io import plot3d
from tests.support import DATA


def _geometry():
    rng = np.random.default_rng(11)
    return Geometry(networks={"wing upper": rng.normal(size=(3, 5, 3)),
                              "body": rng.normal(size=(4, 2, 3)) * 1e3},
                    symmetry={"wing upper": "xz"}, title="t")


def _parse_by_hand(path):
    """The file as the PLOT3D manual describes it: NBLK, dims, then x, y, z per block."""
    vals = np.array(Path(path).read_text().split(), dtype=float)
    nblk = int(vals[0])
    dims = vals[1:1 + 3 * nblk].astype(int).reshape(nblk, 3)
    pos, blocks = 1 + 3 * nblk, []
    for ni, nj, nk in dims:
        m = ni * nj * nk
        # Fortran order: I fastest, so x[i, j] = vals[pos + i + ni * j]
        xyz = [vals[pos + c * m:pos + (c + 1) * m].reshape((ni, nj), order="F")
               for c in range(3)]
        blocks.append(np.stack(xyz, axis=-1))  # (I, J, 3)
        pos += 3 * m
    assert pos == vals.size
    return dims, blocks


def test_writer_layout_and_ij_orientation(tmp_path):
    geo = _geometry()
    p = plot3d.write(geo, tmp_path / "g.p3d")
    lines = p.read_text().splitlines()
    assert lines[:4] == ["3", "5 3 1", "2 4 1", "5 3 1"]  # wing, body, wing image
    dims, blocks = _parse_by_hand(p)
    nets = list(geo.mirrored_networks().values())
    for blk, net in zip(blocks, nets, strict=True):
        np.testing.assert_array_equal(blk, net.transpose(1, 0, 2))
        # I x J normal of the grid equals the juncture convention normal
        n_grid = np.cross(blk[1:, :-1] - blk[:-1, :-1], blk[:-1, 1:] - blk[:-1, :-1])
        n_conv = np.cross(net[:-1, 1:] - net[:-1, :-1], net[1:, :-1] - net[:-1, :-1])
        np.testing.assert_array_equal(n_grid, n_conv.transpose(1, 0, 2))


def test_round_trip_exact_names_lost(tmp_path):
    geo = _geometry()
    back = jc.read(plot3d.write(geo, tmp_path / "g.p3d", mirror=False))
    assert list(back.networks) == ["block 1", "block 2"]
    assert dict(back.symmetry) == {}
    for a, b in zip(back.networks.values(), geo.networks.values(), strict=True):
        np.testing.assert_array_equal(a, b)
    with_images = plot3d.read(plot3d.write(geo, tmp_path / "m.p3d"))
    np.testing.assert_array_equal(with_images.networks["block 3"],
                                  geo.mirrored_networks()["wing upper image"])


def test_digits_option(tmp_path):
    geo = _geometry()
    back = plot3d.read(plot3d.write(geo, tmp_path / "d.p3d", digits=5, mirror=False))
    np.testing.assert_allclose(back.networks["block 2"], geo.networks["body"], rtol=1e-4)


def _nums(a):
    return " ".join(repr(v) for v in np.ravel(a).tolist())


def test_single_block_3d_and_iblank(tmp_path):
    # 3 x 2 grid, I fastest; IBLANK after z is dropped
    x, y, z = np.arange(6.0), np.arange(6.0) + 10, np.arange(6.0) + 20
    p = tmp_path / "s.xyz"
    p.write_text(f"3 2 1\n{_nums(x)}\n{_nums(y)}\n{_nums(z)}\n1 1 1 1 1 1\n")
    geo = plot3d.read(p)
    net = geo.networks["block 1"]
    assert net.shape == (2, 3, 3)
    np.testing.assert_array_equal(net[1, 2], [5.0, 15.0, 25.0])
    np.testing.assert_array_equal(net[0, 1], [1.0, 11.0, 21.0])
    assert "IBLANK dropped" in geo.log[0]


def test_multi_block_2d(tmp_path):
    p = tmp_path / "two.g"
    p.write_text("2\n2 1\n1 2\n1.0 2.0\n3.0 4.0\n5.0 6.0\n7.0 8.0\n")
    geo = plot3d.read(p)
    np.testing.assert_array_equal(geo.networks["block 1"], [[[1, 3, 0], [2, 4, 0]]])
    np.testing.assert_array_equal(geo.networks["block 2"], [[[5, 7, 0]], [[6, 8, 0]]])
    assert "multi-block 2-D" in geo.log[0]


def test_single_block_2d_and_fortran_syntax(tmp_path):
    # IDIM 2, JDIM 2, x and y only; commas, D exponents, a repeat count, an E-less exponent
    p = tmp_path / "s2.p3d"
    p.write_text("2, 2\n1.0D0 2.0d0 2*4.0\n0.5 0.25 0.125 1.5+1\n")
    geo = plot3d.read(p)
    net = geo.networks["block 1"]
    np.testing.assert_array_equal(net[..., 0], [[1.0, 2.0], [4.0, 4.0]])
    np.testing.assert_array_equal(net[..., 1], [[0.5, 0.25], [0.125, 15.0]])
    np.testing.assert_array_equal(net[..., 2], 0.0)
    assert "single-block 2-D" in geo.log[0]


def test_surface_in_another_index_plane(tmp_path):
    # IDIM 2, JDIM 1, KDIM 3: read as a 3 x 2 surface
    vals = np.arange(18.0)
    p = tmp_path / "k.p3d"
    p.write_text(f"1\n2 1 3\n{_nums(vals)}\n")
    net = plot3d.read(p).networks["block 1"]
    assert net.shape == (3, 2, 3)
    np.testing.assert_array_equal(net[2, 1], [5.0, 11.0, 17.0])


@pytest.mark.parametrize("text,match", [
    ("1\n2 2 2\n" + "0 " * 24 + "\n", r"block 1 is a volume grid \(2 x 2 x 2\)"),
    ("1\n2 2 1\n1 2 3\n", r"not a formatted Plot3D grid: 7 numbers fit no layout \(as "
     r"multi-block 3-D, NBLK = 1 and its dimensions need 16 numbers\)"),
    ("4\n2 2 1\n", r"NBLK = 4 needs 12 positive integer dimensions next"),
    ("1\n2 1 1\n1 2 3 x 5 6\n", r"line 3, column 7: expected a number, found 'x'"),
    ("1\n1 1 1\n1 / 3\n", "'/' is not allowed"),
    ("", "empty file: expected a formatted \\(ASCII\\) Plot3D grid"),
    ("1\n1 1 1\n1 -1e400 3\n", r"number out of range \(number 6 of the file\)"),
])
def test_errors(tmp_path, text, match):
    p = tmp_path / "bad.p3d"
    p.write_text(text)
    with pytest.raises(DeckError, match=match):
        plot3d.read(p)


def test_binary_file_is_refused(tmp_path):
    p = tmp_path / "bin.p3d"
    p.write_bytes(np.array([1, 12, 2, 2, 1], dtype="<i4").tobytes())
    with pytest.raises(DeckError, match="binary"):
        plot3d.read(p)


def test_sniffer_reads_plot3d_by_content(tmp_path):
    geo = _geometry()
    p = plot3d.write(geo, tmp_path / "grid.p3d")
    q = tmp_path / "grid.dat"
    q.write_bytes(p.read_bytes())
    assert len(jc.read(q).networks) == 3


@pytest.mark.parametrize("path", sorted((DATA / "lawgs").glob("*.wgs"))
                         + sorted((DATA / "wavedrag").glob("*.inp")), ids=lambda p: p.name)
def test_sniffer_never_takes_lawgs_or_wavedrag(path):
    assert not plot3d._sniff(path.read_bytes()[:4096])


@pytest.mark.parametrize("head", [
    b"1 2 3 4\n5 6 7\n",                      # four integers on the first line
    b"2\n3 0 1\n1.0\n",                       # a zero dimension
    b"1\n2.5 2 1\n",                          # not an integer
    b"  1 -1 -1  0\n",                        # a wave-drag control card
    b"3\n",                                   # nothing after NBLK
    b"HESS NETWORK LIST 1\n",
])
def test_sniffer_is_conservative(head):
    assert not plot3d._sniff(head)
