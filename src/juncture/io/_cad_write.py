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

__all__ = ["CAD_UNITS", "cad_unit", "bilinear_face", "products", "step_document", "iges_model",
           "sewn_solid", "mesh_solid", "compound", "network_shapes"]

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
    """Drop rows (axis 0) or columns (axis 1) equal to the previous one (within 1e-10 of the
    network's extent in the mean: knots that close are refused); knots from the averaged
    chord lengths of what remains, scaled to [0, 1] (None if fewer than two)."""
    step = np.linalg.norm(np.diff(net, axis=axis), axis=2).mean(axis=1 - axis)
    step = np.where(step > 1e-10 * step.sum(), step, 0.0)
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


def compound(api, shapes):
    """One OCP compound of the shapes."""
    comp = api.Compound()
    builder = api.Builder()
    builder.MakeCompound(comp)
    for shape in shapes:
        builder.Add(comp, shape)
    return comp


def network_shapes(api, geometry, mirror):
    """[(component, compound of its networks' faces)] of a Geometry."""
    size = _size(geometry)
    out = []
    for owner, nets in products(geometry, mirror).items():
        faces = [f for f in (bilinear_face(api, pts, size) for _, pts in nets) if f is not None]
        if faces:
            out.append((owner, compound(api, faces)))
    return out


def _solid_of_shell(shell):
    from OCP.BRep import BRep_Builder
    from OCP.TopoDS import TopoDS_Solid

    solid = TopoDS_Solid()
    builder = BRep_Builder()
    builder.MakeSolid(solid)
    builder.Add(solid, shell)
    return solid


def sewn_solid(api, faces, tolerance, name):
    """The closed solid bounded by ``faces`` (sewn within ``tolerance``), outward.

    Raises
    ------
    GeometryError
        If the faces leave free edges or do not sew into one shell.
    """
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Sewing
    from OCP.ShapeFix import ShapeFix_Solid
    from OCP.TopAbs import TopAbs_FACE, TopAbs_SHELL

    from ..errors import GeometryError

    sew = BRepBuilderAPI_Sewing(tolerance)
    for face in faces:
        sew.Add(face)
    sew.Perform()
    sewn = sew.SewedShape()
    shells = _subshapes(sewn, TopAbs_SHELL) or [_shell(api, _subshapes(sewn, TopAbs_FACE))]
    if sew.NbFreeEdges() or len(shells) != 1:
        raise GeometryError(f"its faces do not close: {sew.NbFreeEdges()} free edges, "
                            f"{len(shells)} shells", component=name)
    fix = ShapeFix_Solid(_solid_of_shell(shells[0]))
    fix.Perform()
    return fix.Solid()


def _shell(api, faces):
    """A shell of the faces (one face that closes on itself sews into no shell)."""
    from OCP.TopoDS import TopoDS_Shell

    shell = TopoDS_Shell()
    builder = api.Builder()
    builder.MakeShell(shell)
    for face in faces:
        builder.Add(shell, face)
    return shell


def _subshapes(shape, kind):
    from OCP.TopExp import TopExp_Explorer

    out = []
    explorer = TopExp_Explorer(shape, kind)
    while explorer.More():
        out.append(explorer.Current())
        explorer.Next()
    return out


#: Edges shorter than this (in the file's unit) are collapsed: OpenCASCADE confuses points
#: closer than 1e-7 (Precision::Confusion) whatever the unit, so no edge can be that short.
SHORTEST_EDGE = 1e-6


def _collapse_short_edges(vertices, triangles):
    """Triangles with the ends of every edge shorter than :data:`SHORTEST_EDGE` merged (onto
    the lower vertex id) and the triangles that collapse dropped."""
    pairs = triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    short = np.linalg.norm(np.diff(vertices[pairs], axis=1)[:, 0], axis=1) < SHORTEST_EDGE
    if not short.any():
        return triangles
    n = len(vertices)
    label = _linked(*pairs[short].T, n)
    first = np.full(label.max() + 1, n)
    np.minimum.at(first, label, np.arange(n))
    out = first[label][triangles]
    return out[(out[:, 0] != out[:, 1]) & (out[:, 1] != out[:, 2]) & (out[:, 0] != out[:, 2])]


def _linked(a, b, n):
    """(n,) label of the group of vertices linked by the pairs (a, b)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    return connected_components(coo_matrix((np.ones(a.size), (a, b)), shape=(n, n)))[1]


def _bodies(triangles, n):
    """(m,) label of the closed body (connected part) each triangle belongs to."""
    return _linked(triangles.ravel(), triangles[:, [1, 2, 0]].ravel(), n)[triangles[:, 0]]


def mesh_solid(api, vertices, triangles):
    """The solid a closed, outward-oriented triangle mesh bounds (a compound of one solid per
    closed body when there are several): one plane face per triangle, one vertex per mesh
    vertex and one edge per mesh edge, shared as the mesh shares them (nothing is sewn).
    Edges shorter than :data:`SHORTEST_EDGE` are collapsed first."""
    from OCP.BRep import BRep_Tool
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge as MakeEdge
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeFace as MakeFace
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeVertex as MakeVertex
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeWire as MakeWire
    from OCP.TopAbs import TopAbs_FORWARD

    from .cad import _first

    vertices = np.asarray(vertices, float)
    triangles = _collapse_short_edges(vertices, np.asarray(triangles, int))
    corners = [MakeVertex(api.gp_Pnt(*p)).Vertex() for p in vertices.tolist()]
    pairs = np.sort(triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    edges, of = np.unique(pairs, axis=0, return_inverse=True)
    edges = [MakeEdge(corners[a], corners[b]).Edge() for a, b in edges.tolist()]
    of = of.reshape(-1, 3).tolist()
    p = vertices[triangles]
    normals = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]).tolist()
    surface_of = _first(BRep_Tool, "Surface_s", "Surface")
    faces = []
    for (i, j, k), n in zip(of, normals):
        face = MakeFace(MakeWire(edges[i], edges[j], edges[k]).Wire(), True).Face()
        axis = surface_of(face).Pln().Axis().Direction()
        sense = 1.0 if face.Orientation() == TopAbs_FORWARD else -1.0
        if sense * (axis.X() * n[0] + axis.Y() * n[1] + axis.Z() * n[2]) < 0.0:
            face.Reverse()
        faces.append(face)
    body = _bodies(triangles, len(vertices))
    solids = [_solid_of_shell(_shell(api, [faces[t] for t in np.flatnonzero(body == b)]))
              for b in np.unique(body)]
    return solids[0] if len(solids) == 1 else compound(api, solids)


def step_document(api, shapes, units="ft"):
    """An XCAF document holding the named shapes ``[(name, shape)]``, in ``units``."""
    from OCP.Interface import Interface_Static
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.TDataStd import TDataStd_Name
    from OCP.TDocStd import TDocStd_Document
    from OCP.XCAFDoc import XCAFDoc_DocumentTool

    name, metres = cad_unit(units)
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    XCAFDoc_DocumentTool.SetLengthUnit_s(doc, metres)
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    for owner, shape in shapes:
        TDataStd_Name.Set_s(tool.AddShape(shape, False), TCollection_ExtendedString(owner))
    Interface_Static.SetCVal_s("write.step.unit", name)
    return doc


def iges_model(api, shapes, units="ft"):
    """An IGES writer holding the shapes ``[(name, shape)]`` (names are not kept), its
    global section in ``units`` (no scaling)."""
    name, metres = cad_unit(units)
    writer = api.IgesWriter(name, 0)
    model = writer.Model()
    section = model.GlobalSection()
    section.SetCascadeUnit(metres * 1000.0)
    model.SetGlobalSection(section)
    for _, shape in shapes:
        writer.AddShape(shape)
    return writer
