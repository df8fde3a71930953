"""STEP/IGES through OpenCASCADE: write, read back with OCP, count faces, compare points."""

import sys

import numpy as np
import pytest

import juncture as jc
from juncture.blend.bspline import BSplineSurface, clamped_knots
from juncture.errors import GeometryError, JunctureError, MissingDependencyError
from juncture.geometry import Geometry
from juncture.io import cad


def _cylinder_patch(n=9, m=7):
    x = np.linspace(0.0, 3.0, n)
    th = np.linspace(0.1, 1.2, m)
    xx, tt = np.meshgrid(x, th, indexing="ij")
    return np.stack([xx, 0.8 * np.cos(tt), 0.8 * np.sin(tt)], -1)


def _plane_patch():
    a, b = np.meshgrid(np.linspace(0, 1, 5), np.linspace(0, 2, 6), indexing="ij")
    return np.stack([a, b, 0.3 + 0 * a], -1)


GEO = Geometry(networks={"body": _cylinder_patch(), "plate": _plane_patch()})


def _faces(shape):
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer

    out = []
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        out.append(ex.Current())
        ex.Next()
    return out


def _read(path):
    if str(path).lower().endswith((".step", ".stp")):
        from OCP.STEPControl import STEPControl_Reader as Reader
    else:
        from OCP.IGESControl import IGESControl_Reader as Reader
    reader = Reader()
    assert int(reader.ReadFile(str(path))) == 1  # IFSelect_RetDone
    reader.TransferRoots()
    return reader.OneShape()


def _surface_of(face):
    from OCP.BRep import BRep_Tool
    from OCP.TopoDS import TopoDS

    down = getattr(TopoDS, "Face", None) or TopoDS.Face_s
    tool = getattr(BRep_Tool, "Surface_s", None) or BRep_Tool.Surface
    return tool(down(face))


@pytest.mark.parametrize("name", ["out.step", "out.stp", "out.igs", "out.iges"])
def test_networks_round_trip_as_bspline_faces(tmp_path, name):
    pytest.importorskip("OCP")
    path = tmp_path / name
    jc.write(GEO, path)
    faces = _faces(_read(path))
    assert len(faces) == 2
    # every network point lies on one of the read faces (projection distance)
    from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
    from OCP.gp import gp_Pnt

    surfs = [_surface_of(f) for f in faces]
    for net in GEO.networks.values():
        pts = net.reshape(-1, 3)[::5]
        for p in pts:
            d = min(GeomAPI_ProjectPointOnSurf(gp_Pnt(*map(float, p)), s).LowerDistance()
                    for s in surfs)
            assert d < 1e-5


def test_exact_bspline_surfaces_keep_their_definition(tmp_path):
    pytest.importorskip("OCP")
    rng = np.random.default_rng(5)
    ku, kv = clamped_knots(3), clamped_knots(2)
    ctrl = rng.normal(size=(6, 5, 3))
    surf = BSplineSurface(ctrl, ku, kv)
    path = cad.write_bspline_surfaces([surf, surf], tmp_path / "exact.step")
    faces = _faces(_read(path))
    assert len(faces) == 2
    s = _surface_of(faces[0])
    for u, v in rng.random((7, 2)):
        p = s.Value(float(u), float(v))
        np.testing.assert_allclose([p.X(), p.Y(), p.Z()], surf.points(u, v), atol=1e-9)
    path = cad.write_bspline_surfaces([surf], tmp_path / "exact.igs")
    assert len(_faces(_read(path))) == 1


def test_blend_networks_are_written_as_one_face_each(tmp_path):
    pytest.importorskip("OCP")
    from juncture.blend import blend_geometry, build_blend
    from tests.blend.blend_cases import make_spec

    spec = make_spec()
    spec["output"]["include_components"] = False
    geo = blend_geometry(build_blend(spec))
    path = tmp_path / "blend.step"
    jc.write(geo, path)
    assert len(_faces(_read(path))) == 3


def test_errors(tmp_path):
    pytest.importorskip("OCP")
    with pytest.raises(JunctureError, match="extension '.dxf'"):
        cad.write_bspline_surfaces([], tmp_path / "a.dxf")
    with pytest.raises(GeometryError, match="no networks"):
        cad.write_step(Geometry(), tmp_path / "a.step")
    with pytest.raises(GeometryError, match="no surfaces"):
        cad.write_bspline_surfaces([], tmp_path / "a.step")
    assert not (tmp_path / "a.step").exists()


def test_without_ocp_the_error_names_the_extra(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "OCP", None)
    with pytest.raises(MissingDependencyError, match=r"pip install juncture\[cad\]"):
        jc.write(GEO, tmp_path / "x.step")
    with pytest.raises(MissingDependencyError, match="OCP"):
        cad.write_bspline_surfaces([], tmp_path / "x.igs")
    assert not (tmp_path / "x.step").exists()


def test_formats_are_registered():
    from juncture.io import writer_formats

    assert {"step", "iges"} <= set(writer_formats())
