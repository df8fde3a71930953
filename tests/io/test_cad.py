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


def _read_in(path, metres):
    """The shape in ``path`` with coordinates in the file's unit (OCP reads into mm)."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
    from OCP.gp import gp_Trsf

    trsf = gp_Trsf()
    trsf.SetScaleFactor(1.0 / (1000.0 * metres))
    return BRepBuilderAPI_Transform(_read(path), trsf, True).Shape()


def _box(shape):
    """Tight bounding box (xmin, ymin, zmin, xmax, ymax, zmax) of a shape."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape, box, False, False)
    lo, hi = box.CornerMin(), box.CornerMax()
    return [lo.X(), lo.Y(), lo.Z(), hi.X(), hi.Y(), hi.Z()]


def _distance_to_faces(points, faces):
    from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
    from OCP.gp import gp_Pnt

    surfs = [_surface_of(f) for f in faces]
    return max(min(GeomAPI_ProjectPointOnSurf(gp_Pnt(*map(float, p)), s).LowerDistance()
                   for s in surfs) for p in points)


@pytest.mark.parametrize("name", ["out.step", "out.stp", "out.igs", "out.iges"])
def test_faces_are_the_networks_bilinear_quads(tmp_path, name):
    """Every point and every quad centre (the bilinear patch's value there) is on a face."""
    pytest.importorskip("OCP")
    path = tmp_path / name
    jc.write(GEO, path, units="mm")
    faces = _faces(_read(path))
    assert len(faces) == 2
    for net in GEO.networks.values():
        centres = 0.25 * (net[:-1, :-1] + net[1:, :-1] + net[:-1, 1:] + net[1:, 1:])
        pts = np.concatenate([net.reshape(-1, 3)[::3], centres.reshape(-1, 3)[::4]])
        assert _distance_to_faces(pts, faces) < 1e-9


@pytest.mark.parametrize("unit", ["mm", "cm", "m", "in", "ft", "mi"])
@pytest.mark.parametrize("ext", ["step", "igs"])
def test_the_file_declares_the_unit_and_keeps_the_coordinates(tmp_path, unit, ext):
    """Read back by OpenCASCADE into millimetres: the coordinates scale by the unit's size,
    so they were written as they are, in the unit declared."""
    pytest.importorskip("OCP")
    path = jc.write(GEO, tmp_path / f"u.{ext}", units=unit)
    lo, hi = GEO.extents()
    np.testing.assert_allclose(_box(_read_in(path, cad.CAD_UNITS[unit][1])), [*lo, *hi],
                               atol=1e-6 * np.max(hi - lo))  # OCP pads by 1e-7


def test_an_unknown_unit_is_refused_before_anything_is_written(tmp_path):
    with pytest.raises(JunctureError, match="units: a CAD file declares one of"):
        jc.write(GEO, tmp_path / "x.step", units="furlong")
    assert not (tmp_path / "x.step").exists()


def _product_names(path):
    from OCP.STEPCAFControl import STEPCAFControl_Reader
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.TDataStd import TDataStd_Name
    from OCP.TDocStd import TDocStd_Document
    from OCP.XCAFDoc import XCAFDoc_DocumentTool

    try:  # OCP 8.0
        from OCP.collections import Sequence_TDF_Label as TDF_LabelSequence
    except ImportError:  # OCP 7.9
        from OCP.TDF import TDF_LabelSequence

    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    reader = STEPCAFControl_Reader()
    reader.SetNameMode(True)
    assert reader.Perform(str(path), doc)
    labels = TDF_LabelSequence()
    XCAFDoc_DocumentTool.ShapeTool_s(doc.Main()).GetFreeShapes(labels)
    names = []
    for i in range(1, labels.Length() + 1):
        attr = TDataStd_Name()
        assert labels.Value(i).FindAttribute(TDataStd_Name.GetID_s(), attr)
        names.append(attr.Get().ToExtString())
    return names


def test_the_whole_completed_airplane_one_product_per_component(tmp_path):
    """The transport: both halves, products named after the components, every face inside
    the networks' box (a fitted face once reached x = -221,520 ft)."""
    pytest.importorskip("OCP")
    from tests.support import EXAMPLE_DECK

    cfg = jc.read(EXAMPLE_DECK)
    geo = jc.complete(cfg, "cubic")
    path = jc.write(geo, tmp_path / "t.step")
    names = _product_names(path)
    assert len(names) == len(set(names))
    comps = set(cfg.components)
    assert {"wing", "body"} <= set(names) <= comps | {n for n in geo.networks}
    nets = geo.mirrored_networks()
    pts = np.concatenate([n.reshape(-1, 3) for n in nets.values()])
    assert pts[:, 1].min() < -1.0  # images written
    shape = _read_in(path, 0.3048)
    size = np.ptp(pts, axis=0).max()
    np.testing.assert_allclose(_box(shape), [*pts.min(0), *pts.max(0)], atol=1e-6 * size)
    n_faces = len(_faces(shape))
    half = jc.write(geo, tmp_path / "h.step", mirror=False)
    assert len(_faces(_read(half))) < n_faces


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
    jc.write(geo, path, mirror=False)
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
