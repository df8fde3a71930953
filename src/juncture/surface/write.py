"""Writers of a :class:`~juncture.surface.assemble.SurfaceMesh`: STL, Gmsh, VTU.

- **STL** binary (default): float32 triangles, the facet normal computed from the vertices
  in double precision, and the triangle's component index in the 16-bit attribute word (the
  "colour" field many readers ignore). ASCII (``ascii=True``): one ``solid <component>``
  block per component, numbers with 9 significant digits (float32 exactly).
- **Gmsh** ``.msh`` 2.2 (ASCII) through meshio: one physical surface per component (its
  name, as SU2 markers and Gmsh read them), the elementary entity = the surface (network or
  cap). Version 2.2 because it tags every element with both; meshio's 4.1 writer puts every
  node and element in one entity and loses the physical groups.
- **Cart3D** ``.tri`` (ASCII): the vertex and triangle counts, the vertices in double
  precision (17 significant digits: the float64 values exactly), the triangles' 1-based
  vertex ids, then each triangle's 1-based component id; beside it ``Config.xml`` names the
  components (``<Component Name="wing" Type="tri"><Data>Face Label=1</Data>``, inside a
  container ``all``), as Cart3D and its tools read it.
- **VTU** through meshio: cell data ``component`` and ``surface`` (indices into the mesh's
  ``components`` and ``surfaces``), field data naming them is not part of VTU: the names are in
  the order of :attr:`SurfaceMesh.components`.

Every file appears whole or not at all (``juncture.io.atomic_output``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import JunctureError
from ..io._registry import atomic_output, atomic_path

__all__ = ["write_mesh", "MESH_FORMATS"]

#: Extensions :func:`write_mesh` knows.
MESH_FORMATS = (".stl", ".msh", ".vtu", ".tri")

_STL_RECORD = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])


def _normals(mesh):
    p = mesh.vertices[mesh.triangles]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    size = np.linalg.norm(n, axis=1)
    return n / np.where(size > 0, size, 1.0)[:, None]


def _stl_binary(mesh, path):
    rec = np.zeros(len(mesh.triangles), _STL_RECORD)
    rec["normal"] = _normals(mesh)
    rec["v"] = mesh.vertices[mesh.triangles]
    rec["attr"] = mesh.component
    header = b"juncture surface mesh; attribute = component index".ljust(80, b" ")
    with atomic_output(path, "wb") as fh:
        fh.write(header)
        fh.write(np.uint32(len(rec)).tobytes())
        fh.write(rec.tobytes())


def _stl_ascii(mesh, path):
    normals = _normals(mesh)
    corners = mesh.vertices[mesh.triangles]
    facet = ("facet normal {:.9e} {:.9e} {:.9e}\n outer loop\n"
             "  vertex {:.9e} {:.9e} {:.9e}\n  vertex {:.9e} {:.9e} {:.9e}\n"
             "  vertex {:.9e} {:.9e} {:.9e}\n endloop\nendfacet\n")
    with atomic_output(path) as fh:
        for k, name in enumerate(mesh.components):
            sel = mesh.component == k
            label = "_".join(name.split()) or f"component_{k}"
            fh.write(f"solid {label}\n")
            rows = np.concatenate([normals[sel], corners[sel].reshape(-1, 9)], axis=1)
            fh.write("".join(facet.format(*r) for r in rows.tolist()))
            fh.write(f"endsolid {label}\n")


def _meshio_mesh(mesh, gmsh):
    import meshio

    tri = mesh.triangles.astype(np.int64)
    if gmsh:
        phys = mesh.component.astype(np.int32) + 1
        geom = mesh.surface.astype(np.int32) + 1
        fields = {name: np.array([k + 1, 2]) for k, name in enumerate(mesh.components)}
        return meshio.Mesh(mesh.vertices, [("triangle", tri)],
                           cell_data={"gmsh:physical": [phys], "gmsh:geometrical": [geom]},
                           field_data=fields)
    return meshio.Mesh(mesh.vertices, [("triangle", tri)],
                       cell_data={"component": [mesh.component.astype(np.int32)],
                                  "surface": [mesh.surface.astype(np.int32)]})


def write_mesh(mesh, path, *, ascii=False):
    """Write ``mesh`` to ``path`` by extension (.stl, .msh, .vtu, .tri); returns the path.

    A ``.tri`` file gets its ``Config.xml`` beside it (in the same directory).

    Raises
    ------
    JunctureError
        For another extension (the message lists these).
    """
    path = Path(path)
    ext = path.suffix.lower()
    if ext == ".stl":
        (_stl_ascii if ascii else _stl_binary)(mesh, path)
    elif ext in (".msh", ".vtu"):
        _write_by_meshio(mesh, path, "gmsh22" if ext == ".msh" else "vtu")
    elif ext == ".tri":
        _cart3d(mesh, path)
    else:
        raise JunctureError(f"cannot write a mesh to {str(path)!r}: the extension must be one "
                            f"of {', '.join(MESH_FORMATS)}")
    return path


def _write_by_meshio(mesh, path, fmt):
    import meshio

    m = _meshio_mesh(mesh, fmt == "gmsh22")
    with atomic_path(path, suffix=path.suffix) as tmp:
        meshio.write(tmp, m, file_format=fmt, **({"binary": False} if fmt == "gmsh22" else {}))


def _cart3d(mesh, path):
    from xml.sax.saxutils import quoteattr

    with atomic_output(path) as fh:
        fh.write(f"{len(mesh.vertices)} {len(mesh.triangles)}\n")
        np.savetxt(fh, mesh.vertices, fmt="%.17g")
        np.savetxt(fh, mesh.triangles + 1, fmt="%d")
        np.savetxt(fh, mesh.component + 1, fmt="%d")
    parts = "".join(f"  <Component Name={quoteattr(name)} Type=\"tri\">\n"
                    f"    <Data>Face Label={k + 1}</Data>\n  </Component>\n"
                    for k, name in enumerate(mesh.components))
    names = ",".join(mesh.components)
    xml = ('<?xml version="1.0" encoding="ISO-8859-1"?>\n'
           f"<Configuration Name=\"juncture\" Source={quoteattr(path.name)}>\n{parts}"
           f"  <Component Name=\"all\" Type=\"container\">\n    <Data>{names}</Data>\n"
           "  </Component>\n</Configuration>\n")
    with atomic_output(path.with_name("Config.xml")) as fh:
        fh.write(xml)
