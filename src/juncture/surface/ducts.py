"""Flow-through nacelles: a duct through the nacelle instead of caps on its ends.

A nacelle given as a pod (:func:`juncture.analysis.is_flow_through`: a circular pod off the
plane of symmetry, open at its front) that is open at its rear too is meshed with the flow
passing through it, as the area rule takes it (:func:`juncture.analysis.closed.
capture_tube`: the streamtube the inlet captures, a cylinder of the inlet's radius along x,
is taken out of the nacelle). The duct is that cylinder (the inlet ring's points carried aft
to the pod's own stations, new points lifted onto it, facing the axis) up to the last
station but one, and from there the straight panels on to the exit ring (so the exit needs
no thin flat ring between the two radii, which refinement split without end). The nacelle
is then a ring: each one a handle of the surface (the check expects them), its wetted area
includes the duct's, and the enclosed volume is the one the flow-through areas A(x) hold,
but for that last interval.

Refused, naming the pod and the station: a duct that leaves the nacelle's wall (a section
behind the inlet not wider than it). A pod closed at its rear (no exit) stays closed, with
a warning.
"""

from __future__ import annotations

import numpy as np

__all__ = ["DUCT", "with_ducts", "duct_circles", "onto_duct", "handles"]

#: Suffix of a duct network's name (its component is the pod's).
DUCT = " duct"
#: The duct must stay inside the wall by this share of the pod's radius at every station.
WALL = 1e-3


def with_ducts(geometry, nets):
    """``nets`` with a duct and an exit ring after each flow-through pod's network (and
    image): see the module."""
    import warnings

    from ..analysis._components import is_flow_through
    from ..errors import JunctureWarning

    model = geometry.configuration
    out, closed = {}, set()
    for name, net in nets.items():
        out[name] = net
        comp = geometry.component_of(name)
        body = None if model is None else model.components.get(comp)
        if body is None or not is_flow_through(body) or name not in (comp, f"{comp} image"):
            continue
        if not body.radius[-1] > 0.0:
            closed.add(comp)
            continue
        suffix = " image" if name.endswith(" image") else ""
        out[f"{comp}{DUCT}{suffix}"] = _duct(np.asarray(net, float), comp)
    for comp in sorted(closed):
        warnings.warn(f"{comp}: closed at its rear (no exit), so meshed closed, not flow-"
                      "through", JunctureWarning, stacklevel=3)
    return out


def _duct(net, comp):
    """(n, m, 3) the duct of the pod network ``net`` (rows at its stations), facing out of
    the nacelle's wall: the inlet's circle carried aft to the last station but one, then
    on to the exit ring."""
    from ..errors import GeometryError

    if net[0, 0, 0] > net[-1, 0, 0]:
        net = net[::-1]                                    # an image's rows run aft-first
    x = net[:, 0, 0]
    ring = net[0]
    duct = ring[None] + (x - x[0])[:, None, None] * np.array([1.0, 0.0, 0.0])
    duct[:, :, 0] = x[:, None]
    duct[0] = ring                                         # the inlet, bit for bit
    c_yz, r_in = _circle(ring[:, 1:])
    centre = np.concatenate([[x[0]], c_yz])
    wall = np.linalg.norm(net[1:, :, 1:] - c_yz, axis=2).min(axis=1)
    low = np.flatnonzero(wall[:-1] < (1.0 + WALL) * r_in)
    if len(low):
        where = int(low[0]) + 1
        raise GeometryError(
            f"flow-through: the duct of the inlet's radius {r_in:.4g} from x = {x[0]:.6g} "
            f"leaves the nacelle's wall at x = {x[where]:.6g} (its radius there "
            f"{wall[where - 1]:.4g}); a flow-through nacelle must be wider than its inlet "
            "behind it, or mesh it closed", component=comp, station=float(x[where]))
    duct[-1] = net[-1]          # the last interval flares (or narrows) to the exit ring
    if _faces_axis(duct, centre):
        return duct
    return duct[::-1]


def _faces_axis(net, centre):
    """Whether the triangles of ``net`` (a triangle (i, j), (i+1, j+1), (i+1, j) of each
    quad, as the mesh orients them) face the line along x through the point ``centre``."""
    a, b, c = net[:-1, :-1], net[1:, 1:], net[1:, :-1]
    n = np.cross(b - a, c - a)
    to_axis = centre - (a + b + c) / 3.0
    to_axis[..., 0] = 0.0
    return float(np.einsum("ijk,ijk->", n, to_axis)) > 0.0


def duct_circles(mesh):
    """{surface id: (centre (2,) in y-z, radius, last x)} of the duct surfaces of ``mesh``:
    the circle of its inlet (its vertices at its smallest x) and where the cylinder ends
    (its vertices on that circle)."""
    out = {}
    for k, name in enumerate(mesh.surfaces):
        if not _is_duct(name):
            continue
        p = mesh.vertices[np.unique(mesh.triangles[mesh.surface == k])]
        centre, radius = _circle(p[p[:, 0] == p[:, 0].min(), 1:])
        on = np.abs(np.linalg.norm(p[:, 1:] - centre, axis=1) - radius) <= 1e-9 * radius
        out[k] = (centre, radius, float(p[on, 0].max()))
    return out


def _circle(yz):
    """(centre (2,), radius) of the least-squares circle through the points ``yz`` (exact
    for points on one)."""
    mid = yz.mean(axis=0)
    q = yz - mid
    a = np.column_stack([2.0 * q, np.ones(len(q))])
    sol = np.linalg.lstsq(a, (q * q).sum(axis=1), rcond=None)[0]
    return mid + sol[:2], float(np.sqrt(sol[2] + sol[:2] @ sol[:2]))


def onto_duct(points, centre, radius, last):
    """``points`` up to x = ``last`` moved radially about the x-parallel axis through
    ``centre`` (y, z) onto the cylinder of ``radius`` (behind it, where the duct runs on to
    the exit, left on its triangles)."""
    out = np.array(points, float)
    rel = out[:, 1:] - centre
    rho = np.linalg.norm(rel, axis=1)
    move = (rho > 0) & (out[:, 0] <= last)
    out[move, 1:] = centre + rel[move] * (radius / rho[move])[:, None]
    return out


def _is_duct(name):
    return name.endswith(DUCT) or name.endswith(DUCT + " image")


def handles(mesh):
    """How many handles the surface ``mesh`` has by construction: one per duct."""
    return sum(_is_duct(mesh.surfaces[k]) for k in np.unique(mesh.surface))
