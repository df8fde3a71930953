"""STL / VTK / VTU / OBJ writers through meshio: orientation, areas, closed volumes."""

from __future__ import annotations

import os

import numpy as np
import pytest

import juncture as jc
from juncture.errors import GeometryError, JunctureError
from juncture.geometry import Geometry
from juncture.io import mesh

meshio = pytest.importorskip("meshio")

FORMATS = ["stl", "vtk", "vtu", "obj"]
# Coordinates as stored: binary STL holds float32; the others are written in double.
VOLUME_RTOL = {"stl": 1e-6, "vtk": 1e-13, "vtu": 1e-13, "obj": 1e-13}


def _face(origin, u, v, n_lines, n_points):
    """Planar network P[i, j] = origin + j/(m-1) u + i/(n-1) v; normal cross(u, v)."""
    s = np.linspace(0.0, 1.0, n_points)[None, :, None]
    t = np.linspace(0.0, 1.0, n_lines)[:, None, None]
    return np.asarray(origin, float) + s * np.asarray(u, float) + t * np.asarray(v, float)


def _box(corner=(2.0, -1.0, 3.0), size=(1.5, 0.7, 1.2)):
    """A box as 6 networks of different sizes, each with cross(u, v) pointing outward."""
    o = np.asarray(corner)
    a, b, c = size
    x, y, z = np.array([a, 0, 0]), np.array([0, b, 0]), np.array([0, 0, c])
    return {
        "x max": _face(o + x, y, z, 3, 4), "x min": _face(o, z, y, 4, 2),
        "y max": _face(o + y, z, x, 2, 5), "y min": _face(o, x, z, 5, 3),
        "z max": _face(o + z, x, y, 3, 3), "z min": _face(o, y, x, 2, 2),
    }


def _half_sphere(radius, n_lines, n_points):
    """The y >= 0 half of a sphere: n-lines are cross-sections x = const, nose and tail
    collapsed to points; points run bottom to top, so the normal points outward."""
    phi = np.linspace(0.0, np.pi, n_lines)[:, None]
    t = np.linspace(-np.pi / 2, np.pi / 2, n_points)[None, :]
    rho = radius * np.sin(phi)
    x = -radius * np.cos(phi) + 0 * t
    return np.stack([x, rho * np.cos(t), rho * np.sin(t)], axis=-1)


def _signed_volume(points, triangles):
    p = points[triangles]
    return np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0


def _read(path):
    m = meshio.read(path)
    tri = np.concatenate([c.data for c in m.cells if c.type == "triangle"])
    return m, np.asarray(m.points, float), tri


@pytest.mark.parametrize("fmt", FORMATS)
def test_closed_box_volume_is_positive_and_exact(tmp_path, fmt):
    p = jc.write(_box(), tmp_path / f"box.{fmt}")
    _, pts, tri = _read(p)
    assert len(tri) == 2 * (2 * 3 + 3 * 1 + 1 * 4 + 4 * 2 + 2 * 2 + 1 * 1)
    np.testing.assert_allclose(_signed_volume(pts, tri), 1.5 * 0.7 * 1.2, rtol=VOLUME_RTOL[fmt])


@pytest.mark.parametrize("fmt", FORMATS)
def test_mirrored_half_sphere_closes(tmp_path, fmt):
    n, m, r = 25, 19, 2.0
    geo = Geometry(networks={"body": _half_sphere(r, n, m)}, symmetry={"body": "xz"})
    _, pts, tri = _read(jc.write(geo, tmp_path / f"s.{fmt}"))
    # per half: 2 (n-1)(m-1) quads' triangles less one degenerate triangle per pole quad
    assert len(tri) == 2 * (2 * (n - 1) * (m - 1) - 2 * (m - 1))
    vol = _signed_volume(pts, tri)
    exact = 4.0 / 3.0 * np.pi * r**3
    assert 0.98 * exact < vol < exact  # an inscribed polyhedron, outward normals


def test_without_mirror_only_the_half(tmp_path):
    geo = Geometry(networks={"body": _half_sphere(1.0, 7, 5)}, symmetry={"body": "xz"})
    _, _, tri = _read(mesh.write_stl(geo, tmp_path / "h.stl", mirror=False))
    assert len(tri) == 2 * 6 * 4 - 2 * 4


def test_area_equals_area_of_the_planar_quads(tmp_path):
    rng = np.random.default_rng(3)
    n, m = 5, 7
    ii, jj = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    xy = np.stack([jj * 1.0, ii * 1.3], axis=-1) + rng.uniform(-0.2, 0.2, size=(n, m, 2))
    net = np.concatenate([xy, np.zeros((n, m, 1))], axis=-1)
    # shoelace area of each quad: half the cross product of its diagonals
    d1 = net[1:, 1:] - net[:-1, :-1]
    d2 = net[1:, :-1] - net[:-1, 1:]
    expected = 0.5 * np.abs(np.cross(d1, d2)[..., 2]).sum()
    m_, pts, tri = _read(mesh.write_vtu({"plate": net}, tmp_path / "plate.vtu"))
    p = pts[tri]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum()
    np.testing.assert_allclose(area, expected, rtol=1e-13)
    # normals follow cross(d/d point, d/d line): +z here
    assert np.all(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])[:, 2] > 0)
    assert len(tri) == 2 * (n - 1) * (m - 1)


@pytest.mark.parametrize("fmt", ["vtk", "vtu"])
def test_network_index_cell_data(tmp_path, fmt):
    box = _box()
    m, _, tri = _read(jc.write(box, tmp_path / f"b.{fmt}"))
    ids = np.concatenate(m.cell_data["network"])
    counts = [2 * (a.shape[0] - 1) * (a.shape[1] - 1) for a in box.values()]
    np.testing.assert_array_equal(ids, np.repeat(np.arange(6), counts))


def test_triangulate_orientation_and_degenerate_tip():
    # a cone of 4 n-lines whose last n-line is the tip point
    net = _half_sphere(1.0, 4, 3)
    pts, tri, ids, names = mesh.triangulate({"cone": net})
    assert names == ["cone"] and len(tri) == 2 * 3 * 2 - 2 * 2
    p = pts[tri]
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    centroid = p.mean(axis=1)
    assert np.all(np.einsum("ij,ij->i", nrm, centroid) > 0)  # outward from the centre
    assert np.all(ids == 0)


def test_ascii_and_binary(tmp_path):
    box = _box()
    b = mesh.write_stl(box, tmp_path / "b.stl")
    a = mesh.write_stl(box, tmp_path / "a.stl", binary=False)
    assert a.read_bytes().startswith(b"solid")
    assert not b.read_bytes()[:80].lstrip().startswith(b"solid\n")
    assert b.stat().st_size == 84 + 50 * 52  # binary STL: header, count, 50 bytes a triangle
    assert b"ASCII" in mesh.write_vtk(box, tmp_path / "a.vtk", binary=False).read_bytes()[:200]
    assert b"BINARY" in mesh.write_vtk(box, tmp_path / "b.vtk").read_bytes()[:200]


def test_permissions_follow_umask(tmp_path):
    mask = os.umask(0o022)
    try:
        p = mesh.write_obj(_box(), tmp_path / "p.obj")
    finally:
        os.umask(mask)
    assert p.stat().st_mode & 0o777 == 0o644


def test_errors_and_no_half_written_files(tmp_path, monkeypatch):
    with pytest.raises(GeometryError, match=r"no triangle of non-zero area in 1 networks"):
        mesh.write_stl({"line": np.zeros((1, 4, 3))}, tmp_path / "l.stl")
    with pytest.raises(GeometryError, match="mesh format must be one of stl, vtk, vtu, obj"):
        mesh.write(_box(), tmp_path / "x.ply")
    target = tmp_path / "old.stl"
    target.write_bytes(b"old")

    def boom(*args, **kwargs):
        raise OSError("disk full")

    monkeypatch.setattr(meshio, "write", boom)
    with pytest.raises(JunctureError, match=r"cannot write .*old.stl: disk full"):
        mesh.write_stl(_box(), target)
    assert target.read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.stl"]


def test_writer_only_in_the_registry(tmp_path):
    for fmt in FORMATS:
        assert fmt in jc.io.writer_formats() and fmt not in jc.io.reader_formats()
    p = jc.write(_box(), tmp_path / "b.stl")
    with pytest.raises(JunctureError, match="'stl' can be written but not read"):
        jc.read(p, format="stl")


def test_input_not_mutated(tmp_path):
    box = _box()
    before = {k: v.copy() for k, v in box.items()}
    mesh.write_vtk(box, tmp_path / "b.vtk")
    for k in box:
        np.testing.assert_array_equal(box[k], before[k])


# -- VTK files that VTK itself reads ----------------------------------------------------------

def _transport():
    import warnings

    from tests.support import EXAMPLE_DECK

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(EXAMPLE_DECK)


@pytest.mark.parametrize("binary", [True, False], ids=["binary", "ascii"])
def test_legacy_vtk_uses_only_types_vtk_9_reads(tmp_path, binary):
    path = mesh.write_vtk(_box(), tmp_path / "b.vtk", binary=binary)
    n = len(mesh.triangulate(_box())[1])
    data = path.read_bytes()
    assert data.startswith(b"# vtk DataFile Version 4.2\n")
    assert b"vtktype" not in data  # meshio 5.3's vtktypeint32 / vtktypeint64: VTK 9 refuses them
    assert f"\nCELLS {n} {4 * n}\n".encode() in data
    assert f"\nCELL_DATA {n}\nFIELD FieldData 1\nnetwork 1 {n} int\n".encode() in data
    assert (b"\nBINARY\n" if binary else b"\nASCII\n") in data[:200]


@pytest.mark.parametrize("fmt", ["vtk", "vtu"])
@pytest.mark.parametrize("binary", [True, False], ids=["binary", "ascii"])
def test_meshio_reads_back_exactly(tmp_path, capfd, fmt, binary):
    cfg = _transport()
    points, tri, ids, _ = mesh.triangulate(cfg)
    path = mesh.write(cfg, tmp_path / f"sst.{fmt}", binary=binary)
    assert capfd.readouterr() == ("", "")  # meshio's "ASCII only for debugging" is not printed
    m = meshio.read(path)
    # meshio writes ASCII VTU with 12 significant digits; the others are exact
    rtol = 1e-11 if (fmt, binary) == ("vtu", False) else 0.0
    np.testing.assert_allclose(m.points, points, rtol=rtol, atol=0.0)
    assert [c.type for c in m.cells] == ["triangle"]
    np.testing.assert_array_equal(m.cells[0].data, tri)
    np.testing.assert_array_equal(m.cell_data["network"][0], ids)


@pytest.mark.parametrize("fmt", ["vtk", "vtu"])
@pytest.mark.parametrize("binary", [True, False], ids=["binary", "ascii"])
def test_vtk_reads_the_files(tmp_path, fmt, binary):
    """VTK's own readers (not meshio) load both files without an error or warning."""
    vtk = pytest.importorskip("vtk", reason="an independent VTK reader: pip install vtk to run")
    from vtk.util.numpy_support import vtk_to_numpy

    cfg = _transport()
    points, tri, ids, _ = mesh.triangulate(cfg)
    path = mesh.write(cfg, tmp_path / f"sst.{fmt}", binary=binary)
    readers = ([vtk.vtkXMLUnstructuredGridReader()] if fmt == "vtu" else
               [vtk.vtkUnstructuredGridReader(), vtk.vtkGenericDataObjectReader()])
    window = vtk.vtkStringOutputWindow()
    previous = vtk.vtkOutputWindow.GetInstance()
    vtk.vtkOutputWindow.SetInstance(window)
    try:
        for reader in readers:
            events = []
            for event in ("ErrorEvent", "WarningEvent"):
                reader.AddObserver(event, lambda obj, ev, seen=events: seen.append(ev))
            reader.SetFileName(str(path))
            reader.Update()
            grid = reader.GetOutput()
            assert events == [] and window.GetOutput() == "", window.GetOutput()
            assert grid.GetNumberOfPoints() == len(points)
            assert grid.GetNumberOfCells() == len(tri)
            rtol = 1e-11 if (fmt, binary) == ("vtu", False) else 0.0
            np.testing.assert_allclose(vtk_to_numpy(grid.GetPoints().GetData()), points,
                                       rtol=rtol, atol=0.0)
            types = {grid.GetCellType(i) for i in range(grid.GetNumberOfCells())}
            assert types == {vtk.VTK_TRIANGLE}
            conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
            np.testing.assert_array_equal(conn.reshape(-1, 3), tri)
            network = grid.GetCellData().GetArray("network")
            assert network.GetDataType() == vtk.VTK_INT
            np.testing.assert_array_equal(vtk_to_numpy(network), ids)
    finally:
        vtk.vtkOutputWindow.SetInstance(previous)
