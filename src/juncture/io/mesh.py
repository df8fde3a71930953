"""Triangle-mesh writers: STL, VTU and OBJ through meshio, legacy VTK directly. Writers only.

Every network (and, by default, its mirror image) is split into triangles. Quad
``(i, j), (i, j+1), (i+1, j+1), (i+1, j)`` (i = n-line, j = point) becomes the triangles
``(i, j), (i, j+1), (i+1, j+1)`` and ``(i, j), (i+1, j+1), (i+1, j)``; both have the
right-hand normal of the project convention ``cross(P[i, j+1] - P[i, j], P[i+1, j] - P[i, j])``
(common.md), so a network stored with outward normals gives outward triangle normals.
Triangles of zero area (pointed tips, collapsed nose points) are dropped; no point is merged,
within or across networks. VTK and VTU carry the cell-data array ``"network"``: the index of
the triangle's network in :meth:`Geometry.mirrored_networks` order (images after the
networks), so a viewer can colour components.

Legacy ``.vtk`` is written here, not by meshio: meshio 5.3 writes the ``DataFile Version 5.1``
layout with data arrays typed ``vtktypeint32`` / ``vtktypeint64``, which VTK 9's
``vtkUnstructuredGridReader`` refuses ("Unsupported data type: vtktypeint32"). This writer
produces ``DataFile Version 4.2`` (VTK file-formats guide, "Simple Legacy Formats"): POINTS as
``double``, CELLS with a leading count per cell, CELL_TYPES 5 (VTK_TRIANGLE) and the cell data
as a one-component ``FIELD`` array ``network`` of type ``int``, big-endian in the binary form,
as VTK 9, ParaView and meshio read it. VTU (XML, binary data zlib-compressed by meshio) needs
no such care.
"""

from __future__ import annotations

import contextlib
import io
from pathlib import Path

import numpy as np

from ..errors import GeometryError, MissingDependencyError
from ._registry import atomic_output, atomic_path, register_format, to_geometry

__all__ = ["triangulate", "write", "write_stl", "write_vtk", "write_vtu", "write_obj"]

#: A triangle counts as degenerate when its area is at most this times the squared diagonal of
#: the bounding box of all points.
DEGENERATE_AREA = 1e-14

_MESHIO_NAME = {"stl": "stl", "vtk": "vtk", "vtu": "vtu", "obj": "obj"}


def triangulate(obj, *, mirror=True):
    """Triangles of every network, with consistent (outward) orientation.

    Parameters
    ----------
    obj : Geometry, Configuration or dict of str to (n_lines, n_points, 3) float
        Anything :func:`juncture.io.to_geometry` accepts.
    mirror : bool, optional
        Include the mirror images (:meth:`Geometry.mirrored_networks`). Default True.

    Returns
    -------
    points : (n_vertices, 3) float
        All network points, network after network, none merged [deck length].
    triangles : (n_triangles, 3) int
        Vertex indices; the right-hand normal follows the network orientation convention.
    network : (n_triangles,) int
        Index of each triangle's network (mirrored_networks order).
    names : list of str
        Network names, by index.

    Examples
    --------
    >>> pts, tri, net, names = triangulate({"square": [[[0, 0, 0], [1, 0, 0]],
    ...                                                [[0, 1, 0], [1, 1, 0]]]})
    >>> tri.tolist(), names
    ([[0, 1, 3], [0, 3, 2]], ['square'])
    """
    geo = to_geometry(obj)
    nets = geo.mirrored_networks() if mirror else dict(geo.networks)
    names = list(nets)
    if not nets:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64), np.zeros(0, np.int64), names
    points = np.concatenate([n.reshape(-1, 3) for n in nets.values()])
    tris, ids, offset = [], [], 0
    for k, net in enumerate(nets.values()):
        nl, npt = net.shape[:2]
        idx = np.arange(nl * npt).reshape(nl, npt) + offset
        offset += nl * npt
        a, b, c, d = idx[:-1, :-1], idx[:-1, 1:], idx[1:, 1:], idx[1:, :-1]
        t = np.stack([np.stack([a, b, c], axis=-1), np.stack([a, c, d], axis=-1)], axis=2)
        t = t.reshape(-1, 3)
        tris.append(t)
        ids.append(np.full(len(t), k, dtype=np.int64))
    tri = np.concatenate(tris)
    net_id = np.concatenate(ids)
    p = points[tri]
    area2 = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    diag2 = float(np.sum((points.max(axis=0) - points.min(axis=0)) ** 2))
    keep = area2 > 2.0 * DEGENERATE_AREA * diag2
    return points, tri[keep], net_id[keep], names


def write(obj, path, *, file_format=None, mirror=True, binary=True):
    """Write the triangulated networks (legacy VTK directly, the others with meshio).

    Parameters
    ----------
    obj : Geometry, Configuration or dict of str to (n_lines, n_points, 3) float
        Anything :func:`juncture.io.to_geometry` accepts.
    path : str or path-like
        Output file; it appears whole or not at all (written beside it, then renamed).
    file_format : {"stl", "vtk", "vtu", "obj"}, optional
        Default: from the extension of ``path``.
    mirror : bool, optional
        Include mirror images. Default True.
    binary : bool, optional
        Binary (default) or ASCII STL / VTK / VTU (OBJ is always text). Binary
        STL stores float32 coordinates (about 7 significant digits).

    Raises
    ------
    GeometryError
        If no triangle of non-zero area is left.
    """
    path = Path(path)
    fmt = file_format or path.suffix.lower().lstrip(".")
    if fmt not in _MESHIO_NAME:
        raise GeometryError(f"mesh format must be one of {', '.join(_MESHIO_NAME)}, found "
                            f"{fmt!r}")
    points, tri, net_id, names = triangulate(obj, mirror=mirror)
    if len(tri) == 0:
        raise GeometryError(f"nothing to write to {path.name}: no triangle of non-zero area "
                            f"in {len(names)} networks")
    if fmt == "vtk":
        title = getattr(to_geometry(obj), "title", "")
        with atomic_output(path, "wb") as fh:
            _write_legacy_vtk(fh, points, tri, net_id, binary, title)
        return path
    try:
        import meshio
    except ImportError:
        raise MissingDependencyError("writing STL/VTU/OBJ needs meshio: pip install "
                                     "meshio") from None
    cell_data = {"network": [net_id.astype(np.int32)]} if fmt == "vtu" else None
    mesh = meshio.Mesh(points, [("triangle", tri)], cell_data=cell_data)
    kwargs = {} if fmt == "obj" else {"binary": binary}
    # meshio prints notes ("VTU ASCII files are only meant for debugging") on stderr; io
    # never prints
    with atomic_path(path, suffix=path.suffix or f".{fmt}") as tmp, \
            contextlib.redirect_stderr(io.StringIO()):
        meshio.write(tmp, mesh, file_format=_MESHIO_NAME[fmt], **kwargs)
    return path


def _write_legacy_vtk(fh, points, tri, net_id, binary, title=""):
    """Legacy VTK 4.2 unstructured grid of triangles with cell data ``network`` (int)."""
    if len(points) > np.iinfo(np.int32).max:
        raise GeometryError(f"{len(points)} points do not fit the 32-bit indices of legacy "
                            "VTK; write .vtu")
    n, m = len(points), len(tri)
    cells = np.column_stack([np.full(m, 3), tri])
    title = " ".join(f"juncture {title}".split())[:255]
    blocks = [
        (f"POINTS {n} double", np.asarray(points, dtype=float), ">f8"),
        (f"CELLS {m} {4 * m}", cells, ">i4"),
        (f"CELL_TYPES {m}", np.full((m, 1), 5), ">i4"),
        (f"CELL_DATA {m}\nFIELD FieldData 1\nnetwork 1 {m} int",
         np.asarray(net_id).reshape(-1, 1), ">i4"),
    ]
    fh.write(f"# vtk DataFile Version 4.2\n{title}\n{'BINARY' if binary else 'ASCII'}\n"
             "DATASET UNSTRUCTURED_GRID\n".encode("ascii", "replace"))
    for head, data, dtype in blocks:
        fh.write(head.encode("ascii") + b"\n")
        if binary:
            fh.write(np.ascontiguousarray(data, dtype=dtype).tobytes() + b"\n")
        else:
            words = (repr if dtype == ">f8" else str)
            rows = data.astype(float if dtype == ">f8" else np.int64).tolist()
            fh.write(("\n".join(" ".join(map(words, r)) for r in rows) + "\n").encode("ascii"))


def write_stl(obj, path, *, mirror=True, binary=True):
    """STL (binary by default): see :func:`write`."""
    return write(obj, path, file_format="stl", mirror=mirror, binary=binary)


def write_vtk(obj, path, *, mirror=True, binary=True):
    """Legacy VTK (DataFile Version 4.2) with cell data ``"network"``: see :func:`write`."""
    return write(obj, path, file_format="vtk", mirror=mirror, binary=binary)


def write_vtu(obj, path, *, mirror=True, binary=True):
    """VTK XML unstructured grid with cell data ``"network"``: see :func:`write`."""
    return write(obj, path, file_format="vtu", mirror=mirror, binary=binary)


def write_obj(obj, path, *, mirror=True):
    """Wavefront OBJ (text): see :func:`write`."""
    return write(obj, path, file_format="obj", mirror=mirror)


register_format("stl", [".stl"], writer=write_stl)
register_format("vtk", [".vtk"], writer=write_vtk)
register_format("vtu", [".vtu"], writer=write_vtu)
register_format("obj", [".obj"], writer=write_obj)
