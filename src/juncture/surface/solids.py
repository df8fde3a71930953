"""CAD solids of an airplane: one closed solid per component, or the fused airplane.

``juncture.write_solids(geo, "x.step")`` and ``juncture complete --format step --cad ...``:

- ``"components"`` (default): one closed, outward solid per component copy, whole (a wing's
  root buried in the fuselage included), named after its component; a component with a
  mirror image is one product holding both solids. The faces are
  :func:`juncture.analysis.closed.closed_networks`' networks of the component model (for a
  completed geometry: the re-designed fuselage), circular sections with their corners on the
  circle, each network one face that is its bilinear quads (a degree-1 B-spline), sewn into a
  shell. Tips, roots, blunt bases and open pod ends are closed by flat faces. A fillet is part
  of no component: it is in the fused solid.
- ``"fused"``: one solid, the completed airplane with its fillets, overlaps once: the closed
  surface of :func:`juncture.mesh` (the networks' own triangles, so every intersection point
  is a vertex), one plane face per triangle, edges shared as the mesh shares them (nothing is
  sewn, no tolerance). Refused in one line where that surface does not close.
- ``"faces"``: the networks as faces, not closed (:func:`juncture.io.cad.write_step`).

OpenCASCADE (the ``cad`` extra) builds and writes them; ``BRepCheck_Analyzer`` finds every
solid valid on the bundled transport and the generated airplanes in the tests.
"""

from __future__ import annotations

import numpy as np

from ..errors import GeometryError, JunctureError

__all__ = ["KINDS", "component_solids", "fused_solid", "solid_shapes", "write_solids"]

#: What a CAD file of an airplane can hold (see the module's docstring).
KINDS = ("components", "fused", "faces")

#: Sewing tolerance as a share of the airplane's size (the networks' shared points are equal).
SEW = 1e-7


def _size(points):
    return float(np.ptp(np.asarray(points, float).reshape(-1, 3), axis=0).max()) or 1.0


def component_solids(api, cfg, mirror=True):
    """[(component name, compound of its closed solids)] of a Configuration."""
    from ..analysis.closed import by_copy, closed_networks
    from ..io._cad_write import bilinear_face, compound, sewn_solid

    nets = closed_networks(cfg, union=False, flow_through=False, equal_area=False)
    size = _size(np.concatenate([n.reshape(-1, 3) for n in nets.values()]))
    solids = {}
    for (name, image), group in by_copy(cfg, nets).items():
        if image and not mirror:
            continue
        faces = [f for f in (bilinear_face(api, net, size) for _, net in group)
                 if f is not None]
        solids.setdefault(name, []).append(sewn_solid(api, faces, SEW * size, name))
    return [(name, compound(api, parts)) for name, parts in solids.items()]


def fused_solid(api, surface):
    """The solid a closed :class:`~juncture.surface.assemble.SurfaceMesh` bounds."""
    from ..io._cad_write import mesh_solid

    return mesh_solid(api, surface.vertices, surface.triangles)


def solid_shapes(api, geometry, kind="components", mirror=True):
    """[(product name, OCP shape)] of a completed Geometry for ``kind`` in :data:`KINDS`."""
    if kind == "faces":
        from ..io._cad_write import network_shapes

        return network_shapes(api, geometry, mirror)
    if kind == "fused":
        from .pipeline import mesh

        surface = mesh(geometry, mirror=mirror, min_angle=0.0)
        return [(geometry.title.strip() or "airplane", fused_solid(api, surface))]
    cfg = getattr(geometry, "configuration", None)
    if cfg is None:
        raise GeometryError("solids per component need the component model: write a "
                            "completed geometry (juncture.complete), or --cad faces")
    return component_solids(api, cfg, mirror)


def write_solids(geometry, path, kind="components", units="ft", mirror=True):
    """Write a completed geometry's solids as STEP (``.step``/``.stp``) or IGES.

    Parameters
    ----------
    geometry : Geometry
        From :func:`juncture.complete` (``"components"`` needs its configuration).
    kind : {"components", "fused", "faces"}
        See the module's docstring.
    units : str
        The length unit the file declares (coordinates are never converted).
    mirror : bool
        Both halves (default) or the networks as given.

    Raises
    ------
    JunctureError
        For an unknown kind, extension or unit; GeometryError where a solid does not close;
        MissingDependencyError without OCP.
    """
    from ..io._cad_write import cad_unit
    from ..io.cad import cad_kind, ocp_api, write_shapes

    if kind not in KINDS:
        raise JunctureError(f"CAD content {kind!r}: expected one of {', '.join(KINDS)}")
    file_kind = cad_kind(path)
    cad_unit(units)
    api = ocp_api()
    return write_shapes(solid_shapes(api, geometry, kind, mirror), path, file_kind, units)
