"""STEP and IGES output through OpenCASCADE (the optional ``cad`` extra, ``import OCP``).

Formats (see ``formats.md``): STEP (ISO 10303-21, AP214 via ``STEPCAFControl_Writer``, one
named product per component) and IGES 5.3 (``IGESControl_Writer``), in the length unit the
user declares. Every network of a Geometry becomes one face that is exactly its bilinear
quads (:mod:`juncture.io._cad_write`). :func:`network_face` (a smooth B-spline fitted through
a network's points, for comparisons with OpenCASCADE) is kept for benchmarks. Exact B-spline
patches (:class:`juncture.blend.bspline.BSplineSurface`) are written as they are by
:func:`write_bspline_surfaces`.

This is the ONE module that touches OCP. It works on OCP 7.9 and 8.0, which renamed the
collection classes (``TColgp_Array2OfPnt`` -> ``OCP.collections.Array2_gp_Pnt``,
``TColStd_Array1OfReal`` -> ``Array1_double``, ``TColStd_Array1OfInteger`` -> ``Array1_int``)
and the downcasts (``TopoDS.Edge_s`` -> ``TopoDS.Edge``): names are found by feature
detection. OCP is imported inside the functions (the import takes about a second); without it
the writers raise :class:`~juncture.errors.MissingDependencyError`. IGES faces are added with
``AddShape`` (``AddGeom`` on a bare surface wrote an empty file, dependencies.md).
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from ..errors import GeometryError, JunctureError, MissingDependencyError
from ._cad_write import CAD_UNITS
from ._registry import atomic_output, register_format, to_geometry

__all__ = ["CAD_UNITS", "write_step", "write_iges", "write_shapes", "write_bspline_surfaces",
           "ocp_api", "network_face", "section_points", "cad_kind"]

_INSTALL = "pip install juncture[cad]"


def _first(module, *names):
    for name in names:
        obj = getattr(module, name, None)
        if obj is not None:
            return obj
    return None


def ocp_api():
    """The OCP classes juncture uses, resolved for the installed OCP version.

    Returns
    -------
    types.SimpleNamespace
        ``Array2Pnt``, ``Array1Real``, ``Array1Int``, ``gp_Pnt``, ``PointsToBSplineSurface``,
        ``BSplineSurface``, ``MakeFace``, ``Compound``, ``Builder``, ``StepWriter``,
        ``StepAsIs``, ``IgesWriter``, ``C2``, ``downcast_face``.

    Raises
    ------
    MissingDependencyError
        If OCP is not installed.
    """
    try:
        import OCP  # noqa: F401
    except ImportError:
        raise MissingDependencyError(f"STEP/IGES output needs OpenCASCADE (OCP): "
                                     f"{_INSTALL}") from None
    from OCP.BRep import BRep_Builder
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeFace
    from OCP.Geom import Geom_BSplineSurface
    from OCP.GeomAbs import GeomAbs_Shape
    from OCP.GeomAPI import GeomAPI_PointsToBSplineSurface
    from OCP.gp import gp_Pnt
    from OCP.IGESControl import IGESControl_Writer
    from OCP.STEPControl import STEPControl_StepModelType, STEPControl_Writer
    from OCP.TopoDS import TopoDS, TopoDS_Compound

    try:  # OCP 8.0
        from OCP import collections as coll

        arr2, arr1r, arr1i = coll.Array2_gp_Pnt, coll.Array1_double, coll.Array1_int
    except (ImportError, AttributeError):  # OCP 7.9
        from OCP.TColgp import TColgp_Array2OfPnt as arr2
        from OCP.TColStd import TColStd_Array1OfInteger as arr1i
        from OCP.TColStd import TColStd_Array1OfReal as arr1r
    _quiet_messages()
    return SimpleNamespace(
        Array2Pnt=arr2, Array1Real=arr1r, Array1Int=arr1i, gp_Pnt=gp_Pnt,
        PointsToBSplineSurface=GeomAPI_PointsToBSplineSurface,
        BSplineSurface=Geom_BSplineSurface, MakeFace=BRepBuilderAPI_MakeFace,
        Compound=TopoDS_Compound, Builder=BRep_Builder, StepWriter=STEPControl_Writer,
        StepAsIs=STEPControl_StepModelType.STEPControl_AsIs, IgesWriter=IGESControl_Writer,
        C2=GeomAbs_Shape.GeomAbs_C2, downcast_face=_first(TopoDS, "Face", "Face_s"))


def _quiet_messages():
    """Keep OCP's transfer statistics off stdout (only failures are printed)."""
    try:
        from OCP.Message import Message, Message_Gravity

        for printer in Message.DefaultMessenger_s().Printers():
            printer.SetTraceLevel(Message_Gravity.Message_Fail)
    except (ImportError, AttributeError, TypeError):  # older bindings: leave as is
        pass


def _array2(api, pts):
    n, m = pts.shape[:2]
    arr = api.Array2Pnt(1, n, 1, m)
    for i in range(n):
        for j in range(m):
            arr.SetValue(i + 1, j + 1, api.gp_Pnt(*(float(c) for c in pts[i, j])))
    return arr


def _array1(cls, values):
    arr = cls(1, len(values))
    for i, v in enumerate(values):
        arr.SetValue(i + 1, v)
    return arr


def _network_face(api, name, net):
    net = np.asarray(net, float)
    if net.ndim != 3 or net.shape[0] < 2 or net.shape[1] < 2 or net.shape[2] != 3:
        raise GeometryError(f"a network needs at least 2 x 2 points, found {net.shape}",
                            component=name)
    size = float(np.max(np.ptp(net.reshape(-1, 3), axis=0))) or 1.0
    fit = api.PointsToBSplineSurface(_array2(api, net), 3, 8, api.C2, 1e-7 * size)
    if not fit.IsDone():
        raise GeometryError("OpenCASCADE could not fit a B-spline surface through the "
                            "points", component=name)
    return api.MakeFace(fit.Surface(), 1e-9 * size).Face()


def network_face(net, name="network"):
    """An OCP face through a network's points (B-spline of degree 3 to 8, C2, fitted to 1e-7
    of the network's size). For comparisons with OpenCASCADE (benchmarks, oracles)."""
    return _network_face(ocp_api(), name, net)


def section_points(shape_a, shape_b, samples_per_edge=64):
    """Points along the intersection curves of two OCP shapes (BRepAlgoAPI_Section).

    Returns
    -------
    (k, 3) float
        ``samples_per_edge`` points on every edge of the section, edge after edge.
    """
    ocp_api()
    from OCP.BRepAdaptor import BRepAdaptor_Curve
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Section
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    edge_of = _first(TopoDS, "Edge", "Edge_s")
    sec = BRepAlgoAPI_Section(shape_a, shape_b)
    sec.Build()
    if not sec.IsDone():
        raise GeometryError("OpenCASCADE could not compute the section")
    out = []
    exp = TopExp_Explorer(sec.Shape(), TopAbs_EDGE)
    while exp.More():
        curve = BRepAdaptor_Curve(edge_of(exp.Current()))
        for t in np.linspace(curve.FirstParameter(), curve.LastParameter(), samples_per_edge):
            p = curve.Value(float(t))
            out.append((p.X(), p.Y(), p.Z()))
        exp.Next()
    return np.array(out, float).reshape(-1, 3)


def _bspline_face(api, surf):
    ku, kv = np.asarray(surf.knots_u, float), np.asarray(surf.knots_v, float)
    uk, um = np.unique(ku, return_counts=True)
    vk, vm = np.unique(kv, return_counts=True)
    geom = api.BSplineSurface(_array2(api, np.asarray(surf.control)),
                              _array1(api.Array1Real, [float(x) for x in uk]),
                              _array1(api.Array1Real, [float(x) for x in vk]),
                              _array1(api.Array1Int, [int(x) for x in um]),
                              _array1(api.Array1Int, [int(x) for x in vm]),
                              int(surf.degree_u), int(surf.degree_v))
    return api.MakeFace(geom, 1e-9).Face()


def _atomic_cad(path, kind, write_to):
    """Call ``write_to(temporary file)`` (True when written), then put the file at ``path``
    whole or not at all."""
    path = Path(path)
    with tempfile.TemporaryDirectory() as tmp:
        tmp_file = os.path.join(tmp, "out.step" if kind == "step" else "out.igs")
        if not write_to(tmp_file) or not os.path.exists(tmp_file):
            raise JunctureError(f"OpenCASCADE failed to write {kind.upper()} file "
                                f"{str(path)!r}")
        data = Path(tmp_file).read_bytes()
    with atomic_output(path, "wb") as fh:
        fh.write(data)
    return path


def _write_faces(api, faces, path, kind):
    """Write faces as STEP or IGES to ``path`` atomically."""
    def write_to(tmp_file):
        if kind == "step":
            comp = api.Compound()
            builder = api.Builder()
            builder.MakeCompound(comp)
            for face in faces:
                builder.Add(comp, face)
            writer = api.StepWriter()
            writer.Transfer(comp, api.StepAsIs)
            return int(writer.Write(tmp_file)) == 1
        writer = api.IgesWriter()
        for face in faces:
            writer.AddShape(face)
        writer.ComputeModel()
        return bool(writer.Write(tmp_file))

    return _atomic_cad(path, kind, write_to)


def _write_geometry(obj, path, kind, units, mirror):
    from ._cad_write import cad_unit, network_shapes

    cad_unit(units)  # a unit the file cannot declare is refused before OCP loads
    api = ocp_api()
    geometry = to_geometry(obj)
    if not geometry.networks:
        raise GeometryError(f"nothing to write to {kind.upper()}: the geometry has no "
                            "networks")
    return write_shapes(network_shapes(api, geometry, mirror), path, kind, units)


def write_shapes(shapes, path, kind, units="ft"):
    """Write named OCP shapes ``[(name, shape)]`` as STEP (one product each) or IGES."""
    from ._cad_write import iges_model, step_document

    api = ocp_api()

    def write_to(tmp_file):
        if kind == "step":
            from OCP.STEPCAFControl import STEPCAFControl_Writer

            writer = STEPCAFControl_Writer()
            writer.Transfer(step_document(api, shapes, units), api.StepAsIs)
            return int(writer.Write(tmp_file)) == 1
        writer = iges_model(api, shapes, units)
        writer.ComputeModel()
        return bool(writer.Write(tmp_file))

    return _atomic_cad(path, kind, write_to)


def write_step(obj, path, *, units="ft", mirror=True):
    """Write ``obj`` (Geometry or dict of networks) as STEP (AP214): one product per component.

    Each network is one face, the network's bilinear quads as a degree-1 B-spline (see
    :mod:`juncture.io._cad_write`).

    Parameters
    ----------
    units : str
        The length unit the file declares (``"ft"`` default, ``"in"``, ``"m"``, ``"mm"``,
        ``"cm"``, ``"km"``, ``"mi"``); coordinates are written as they are, never converted.
    mirror : bool
        Write the whole airplane (networks with a mirror plane and their images, default) or
        only the networks as given (a half model).

    Raises
    ------
    MissingDependencyError
        Without OCP (``pip install juncture[cad]``).
    JunctureError
        For a unit a CAD file cannot declare.
    """
    return _write_geometry(obj, path, "step", units, mirror)


def write_iges(obj, path, *, units="ft", mirror=True):
    """Write ``obj`` as IGES 5.3 faces in ``units`` (see :func:`write_step`)."""
    return _write_geometry(obj, path, "iges", units, mirror)


def write_bspline_surfaces(surfaces, path):
    """Write exact B-spline surfaces as faces: STEP for .step/.stp, IGES for .igs/.iges.

    Parameters
    ----------
    surfaces : iterable of BSplineSurface
        Objects with ``control`` (n_u, n_v, 3), ``knots_u``, ``knots_v``, ``degree_u``,
        ``degree_v`` (clamped, non-rational).
    path : str or path-like

    Raises
    ------
    JunctureError
        For an unknown extension; MissingDependencyError without OCP.
    """
    kind = cad_kind(path)
    api = ocp_api()
    faces = [_bspline_face(api, s) for s in surfaces]
    if not faces:
        raise GeometryError("no surfaces to write")
    return _write_faces(api, faces, path, kind)


def cad_kind(path):
    """``"step"`` or ``"iges"`` from a file's extension (a JunctureError for another)."""
    suffix = Path(path).suffix.lower()
    kinds = {".step": "step", ".stp": "step", ".igs": "iges", ".iges": "iges"}
    if suffix not in kinds:
        raise JunctureError(f"cannot tell STEP or IGES from the extension {suffix!r} of "
                            f"{str(path)!r}; use .step, .stp, .igs or .iges")
    return kinds[suffix]


register_format("step", (".step", ".stp"), writer=write_step)
register_format("iges", (".igs", ".iges"), writer=write_iges)
