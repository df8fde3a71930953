"""Mesh files read back by third-party readers (meshio, trimesh, numpy's own STL parse)."""

import numpy as np
import pytest

from juncture.errors import JunctureError
from juncture.geometry import Geometry
from juncture.surface.assemble import assemble
from juncture.surface.write import write_mesh
from tests.surface.test_assemble import _prism


def _two_pods():
    a = _prism()
    b = _prism(n_theta=16, radius=0.7) + [1.0, 4.0, 0.5]
    return assemble(Geometry({"pod 1": a, "pod 2": b}))


def test_binary_stl_is_watertight_for_trimesh_and_carries_the_component(tmp_path):
    import trimesh

    mesh = _two_pods()
    path = write_mesh(mesh, tmp_path / "m.stl")
    tm = trimesh.load(path, process=True)  # trimesh merges STL's repeated corners itself
    assert tm.is_watertight and tm.is_winding_consistent
    assert tm.volume == pytest.approx(mesh.volume(), rel=1e-6)  # float32 coordinates
    raw = np.fromfile(path, dtype=np.uint8)
    count = int(raw[80:84].view("<u4")[0])
    rec = raw[84:].reshape(count, 50)
    attr = rec[:, 48:50].copy().view("<u2").ravel()
    np.testing.assert_array_equal(attr, mesh.component)


# meshio sniffs for binary STL first and overflows a uint32 on ASCII text (harmless).
@pytest.mark.filterwarnings("ignore:overflow encountered:RuntimeWarning")
def test_ascii_stl_has_one_named_solid_per_component(tmp_path):
    import meshio

    mesh = _two_pods()
    path = write_mesh(mesh, tmp_path / "m.stl", ascii=True)
    text = path.read_text()
    assert [ln.split()[1] for ln in text.splitlines() if ln.startswith("solid")] == \
        ["pod_1", "pod_2"]
    back = meshio.read(path)
    assert sum(len(c.data) for c in back.cells) == len(mesh.triangles)


@pytest.mark.parametrize("name", ["m.msh", "m.vtu"])
def test_msh_and_vtu_read_back_with_shared_vertices_and_ids(tmp_path, name):
    import meshio

    mesh = _two_pods()
    back = meshio.read(write_mesh(mesh, tmp_path / name))
    np.testing.assert_array_equal(back.points, mesh.vertices)
    np.testing.assert_array_equal(back.cells_dict["triangle"], mesh.triangles)
    if name.endswith(".msh"):
        np.testing.assert_array_equal(back.cell_data["gmsh:physical"][0], mesh.component + 1)
        assert {k: int(v[0]) for k, v in back.field_data.items()} == {"pod 1": 1, "pod 2": 2}
    else:
        np.testing.assert_array_equal(back.cell_data["component"][0], mesh.component)
        np.testing.assert_array_equal(back.cell_data["surface"][0], mesh.surface)


def test_an_unknown_extension_is_refused_and_nothing_written(tmp_path):
    with pytest.raises(JunctureError, match=r"\.stl, \.msh, \.vtu"):
        write_mesh(_two_pods(), tmp_path / "m.ply")
    assert list(tmp_path.iterdir()) == []


def test_cart3d_tri_and_its_config(tmp_path):
    import xml.etree.ElementTree as ET

    import juncture as jc
    from tests.support import PDAS_DECK

    geo = jc.complete(jc.read(PDAS_DECK), "cubic")
    surface = jc.mesh(geo)
    path = write_mesh(surface, tmp_path / "mesh.tri")
    words = path.read_text().split()
    nv, nt = int(words[0]), int(words[1])
    assert (nv, nt) == (len(surface.vertices), len(surface.triangles))
    numbers = words[2:]
    v = np.array(numbers[:3 * nv], float).reshape(nv, 3)
    t = np.array(numbers[3 * nv:3 * nv + 3 * nt], int).reshape(nt, 3) - 1
    comp = np.array(numbers[3 * nv + 3 * nt:], int) - 1
    np.testing.assert_array_equal(v, surface.vertices)  # double precision, exactly
    np.testing.assert_array_equal(t, surface.triangles)
    np.testing.assert_array_equal(comp, surface.component)
    root = ET.parse(tmp_path / "Config.xml").getroot()
    assert root.tag == "Configuration" and root.get("Source") == "mesh.tri"
    tris = [c for c in root if c.get("Type") == "tri"]
    assert [c.get("Name") for c in tris] == list(surface.components)
    assert [c.find("Data").text for c in tris] == [f"Face Label={k + 1}"
                                                  for k in range(len(tris))]
