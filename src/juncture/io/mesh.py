"""Triangle-mesh writers through meshio: STL, VTK (legacy), VTU, OBJ. Writers only.

Every network (and, by default, its mirror image) is split into triangles. Quad
``(i, j), (i, j+1), (i+1, j+1), (i+1, j)`` (i = n-line, j = point) becomes the triangles
``(i, j), (i, j+1), (i+1, j+1)`` and ``(i, j), (i+1, j+1), (i+1, j)``; both have the
right-hand normal of the project convention ``cross(P[i, j+1] - P[i, j], P[i+1, j] - P[i, j])``
(common.md), so a network stored with outward normals gives outward triangle normals.
Triangles of zero area (pointed tips, collapsed nose points) are dropped; no point is merged,
within or across networks. VTK and VTU carry the cell-data array ``"network"``: the index of
the triangle's network in :meth:`Geometry.mirrored_networks` order (images after the
networks), so a viewer can colour components.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import GeometryError, MissingDependencyError
from ._registry import atomic_path, register_format, to_geometry

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
    """Write the triangulated networks with meshio.

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
    try:
        import meshio
    except ImportError:
        raise MissingDependencyError("writing STL/VTK/VTU/OBJ needs meshio: pip install "
                                     "meshio") from None
    points, tri, net_id, names = triangulate(obj, mirror=mirror)
    if len(tri) == 0:
        raise GeometryError(f"nothing to write to {path.name}: no triangle of non-zero area "
                            f"in {len(names)} networks")
    cell_data = {"network": [net_id.astype(np.int32)]} if fmt in ("vtk", "vtu") else None
    mesh = meshio.Mesh(points, [("triangle", tri)], cell_data=cell_data)
    kwargs = {} if fmt == "obj" else {"binary": binary}
    with atomic_path(path, suffix=path.suffix or f".{fmt}") as tmp:
        meshio.write(tmp, mesh, file_format=_MESHIO_NAME[fmt], **kwargs)
    return path


def write_stl(obj, path, *, mirror=True, binary=True):
    """STL (binary by default): see :func:`write`."""
    return write(obj, path, file_format="stl", mirror=mirror, binary=binary)


def write_vtk(obj, path, *, mirror=True, binary=True):
    """Legacy VTK with cell data ``"network"``: see :func:`write`."""
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
