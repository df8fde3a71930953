"""Networks as CAD: one named product per component, faces that follow the networks.

Every network becomes one degree-1 B-spline face whose poles are the network's points, with
knots at the averaged chord lengths of its rows and columns: the face *is* the network's
bilinear quads (no fit, so nothing can overshoot between points, as a high-degree fit did at
the wing root's collapsed lines), and faces that share a seam share its edge polyline. Rows or
columns that repeat the previous one exactly are dropped; a network that collapses to a line
or a point has no area and is left out.

The whole airplane is written by default: networks with a mirror plane get their images
(``Geometry.mirrored_networks``). Faces are grouped into products named after the
components of the configuration they were made from (``"wing"``, ``"body"``, ``"pod 1"``);
a network whose name starts with no component's name is its own product. STEP goes through
an XCAF document (``STEPCAFControl_Writer``) so that the names reach the file; its length
unit is the one the user gives, declared in the file and not converted to (coordinates are
written as they are). IGES carries the unit in its global section (names are not kept).
"""

from __future__ import annotations

import numpy as np

from ..errors import JunctureError

__all__ = ["CAD_UNITS", "cad_unit", "bilinear_face", "products", "step_document", "iges_model"]

#: Length units a CAD file can declare: label -> (OpenCASCADE's name, metres per unit).
CAD_UNITS = {"mm": ("MM", 1e-3), "cm": ("CM", 1e-2), "m": ("M", 1.0), "km": ("KM", 1e3),
             "in": ("INCH", 0.0254), "ft": ("FT", 0.3048), "mi": ("MI", 1609.344)}
_ALIASES = {"inch": "in", "inches": "in", "foot": "ft", "feet": "ft", "meter": "m",
            "metre": "m", "meters": "m", "metres": "m", "millimetre": "mm",
            "millimeter": "mm", "centimetre": "cm", "centimeter": "cm", "mile": "mi"}


def cad_unit(units):
    """(OpenCASCADE unit name, metres per unit) of a length-unit label (``"ft"``, ``"m"``...).

    Raises
    ------
    JunctureError
        For a label a CAD file cannot declare (the message lists those it can).
    """
    key = str(units).strip().lower()
    key = _ALIASES.get(key, key)
    if key not in CAD_UNITS:
        raise JunctureError(f"units: a CAD file declares one of {', '.join(CAD_UNITS)}; "
                            f"found {units!r}")
    return CAD_UNITS[key]


def _distinct(net, axis):
    """Drop rows (axis 0) or columns (axis 1) equal to the previous one; knots from the
    averaged chord lengths of what remains, scaled to [0, 1] (None if fewer than two)."""
    step = np.linalg.norm(np.diff(net, axis=axis), axis=2).mean(axis=1 - axis)
    keep = np.r_[True, step > 0]
    net = net[keep] if axis == 0 else net[:, keep]
    chord = np.r_[0.0, np.cumsum(step[step > 0])]
    if len(chord) < 2 or chord[-1] <= 0:
        return net, None
    return net, chord / chord[-1]


def bilinear_face(api, net, size):
    """An OCP face that is the network's bilinear quads, or None if it has no area."""
    net = np.asarray(net, float)
    net, u = _distinct(net, 0)
    if u is None:
        return None
    net, v = _distinct(net, 1)
    if v is None:
        return None
    from .cad import _array1, _array2

    def mults(k):
        return _array1(api.Array1Int, [2] + [1] * (k - 2) + [2])

    geom = api.BSplineSurface(_array2(api, net), _array1(api.Array1Real, [float(t) for t in u]),
                              _array1(api.Array1Real, [float(t) for t in v]),
                              mults(len(u)), mults(len(v)), 1, 1)
    return api.MakeFace(geom, 1e-9 * size).Face()


def products(geometry, mirror=True):
    """{product name: [(network name, points)]} in the networks' order."""
    nets = geometry.mirrored_networks() if mirror else dict(geometry.networks)
    out = {}
    for name, pts in nets.items():
        out.setdefault(geometry.component_of(name), []).append((name, pts))
    return out


def _size(geometry):
    lo, hi = geometry.extents()
    return float(np.max(hi - lo)) or 1.0


def _compound(api, faces):
    comp = api.Compound()
    builder = api.Builder()
    builder.MakeCompound(comp)
    for face in faces:
        builder.Add(comp, face)
    return comp


def _product_shapes(api, geometry, mirror):
    size = _size(geometry)
    out = []
    for owner, nets in products(geometry, mirror).items():
        faces = [f for f in (bilinear_face(api, pts, size) for _, pts in nets) if f is not None]
        if faces:
            out.append((owner, _compound(api, faces)))
    return out


def step_document(api, geometry, units="ft", mirror=True):
    """An XCAF document holding one named shape per component, in ``units``."""
    from OCP.Interface import Interface_Static
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.TDataStd import TDataStd_Name
    from OCP.TDocStd import TDocStd_Document
    from OCP.XCAFDoc import XCAFDoc_DocumentTool

    name, metres = cad_unit(units)
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    XCAFDoc_DocumentTool.SetLengthUnit_s(doc, metres)
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    for owner, shape in _product_shapes(api, geometry, mirror):
        TDataStd_Name.Set_s(tool.AddShape(shape, False), TCollection_ExtendedString(owner))
    Interface_Static.SetCVal_s("write.step.unit", name)
    return doc


def iges_model(api, geometry, units="ft", mirror=True):
    """An IGES writer holding every face, its global section in ``units`` (no scaling)."""
    name, metres = cad_unit(units)
    writer = api.IgesWriter(name, 0)
    model = writer.Model()
    section = model.GlobalSection()
    section.SetCascadeUnit(metres * 1000.0)
    model.SetGlobalSection(section)
    for _, shape in _product_shapes(api, geometry, mirror):
        writer.AddShape(shape)
    return writer
