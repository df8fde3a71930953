"""Mass properties of a closed triangulated surface: the solid it encloses, counted once.

A completed airplane's closed mesh (:func:`juncture.mesh`) is the union of its components:
a wing root buried in the fuselage, a pylon in its nacelle are inside it once, where
:func:`~juncture.massprops.configuration_mass_properties` integrates each component as the
deck gives it and counts such overlaps twice. The integrals are exact for the mesh (its flat
triangles, not the curved surfaces between its vertices): each triangle ``(a, b, c)``, with
outward orientation, spans the signed tetrahedron ``(o, a, b, c)`` from a reference point
``o``; for a tetrahedron with a corner at the origin and the others at ``a, b, c``,

- volume ``V = det[a, b, c] / 6``,
- first moment ``V (a + b + c) / 4``,
- second moment ``int x_i x_j dV = V / 20 (sum_k p_k,i p_k,j + s_i s_j)``, with
  ``s = a + b + c``.

Summed over a closed surface the tetrahedra outside cancel. The reference point is the
vertices' mean (the result does not depend on it; the sums lose less to round-off).
"""

from __future__ import annotations

import numpy as np

from .properties import MassProperties

__all__ = ["surface_mass_properties"]


def surface_mass_properties(vertices, triangles, density=1.0, name=None):
    """Mass properties of the solid a closed, outward-oriented triangle mesh encloses.

    Parameters
    ----------
    vertices : (n, 3) float
    triangles : (m, 3) int
        Counter-clockwise seen from outside (as :class:`~juncture.surface.SurfaceMesh`).
    density : float
        Uniform density [mass / length^3]; 1 makes the mass the volume.
    name : str, optional

    Returns
    -------
    MassProperties
        Mass, volume, centre of gravity and inertia tensor about it.
    """
    v = np.asarray(vertices, float)
    o = v.mean(axis=0)
    p = v[np.asarray(triangles)] - o                       # (m, 3, 3) corners from o
    det = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2]))
    vol = det / 6.0
    s = p.sum(axis=1)
    volume = float(vol.sum())
    first = (vol[:, None] * s).sum(axis=0) / 4.0
    second = np.einsum("t,tki,tkj->ij", vol, p, p) + np.einsum("t,ti,tj->ij", vol, s, s)
    second /= 20.0
    cg_local = first / volume
    # About the CG: int x x^T dV - V c c^T, then the inertia tensor tr(S) 1 - S.
    about = second - volume * np.outer(cg_local, cg_local)
    inertia = np.trace(about) * np.eye(3) - about
    return MassProperties(density * volume, volume, cg_local + o, density * inertia, name)
