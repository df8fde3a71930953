"""Body ends that a deck gives as a section too small to be anything but a point.

A fuselage or pod drawn to a point and written with rounded cards often ends (or starts) at a
station whose section is a few ten-thousandths of a foot across: the tail-cone formula
evaluated at the rounded last station, a point written with four decimals. Meshed as given,
that section is a cap a millionth of the airplane across, bounded by points the rounding has
put nearly in line, and the last panel narrows to it over one network row: triangles of a
fraction of a degree that no triangulation of the surface as given avoids (seed 2626 of
``tools/survey_mesh.py``: 80 and 52 triangles under 5 deg on two airplanes).

Where an end section of a body lies within :data:`TINY_END` of the body's length of its
centre, every network point on that station within twice the section's extent of the centre
(or of its mirror image) is moved onto the centre, in every network that carries it, before
the points are merged: the body ends at a point, as the designer drew it. The surface moves
by at most the section's extent (under 1e-5 of the body's length); no point off that station
moves, and a point shared by two networks moves in both to the same place, so seams stay
bit-identical.
"""

from __future__ import annotations

import numpy as np

__all__ = ["point_ends", "TINY_END"]

#: An end section no wider than this share of its body's length is taken for a point.
TINY_END = 1e-5


def _centres(body):
    """(x, centre (3,), extent) of each end of ``body`` whose section is a near point."""
    sections = np.asarray(body.cross_sections(), float)
    length = float(np.ptp(sections[..., 0]))
    out = []
    for sec in (sections[0], sections[-1]):
        extent = float(np.ptp(sec[:, 1:], axis=0).max())
        if 0.0 < extent <= TINY_END * length:
            x = float(sec[0, 0])
            yz = np.asarray(body.center_at(np.array([x])), float)[0]
            out.append((x, np.array([x, yz[0], yz[1]]), extent))
    return out


def point_ends(geometry, nets):
    """``nets`` (name -> (n, m, 3) points) with the near-point end sections of the bodies of
    ``geometry`` moved onto their centres (module docstring); the same dict when there is
    none."""
    model = geometry.configuration
    if model is None:
        return nets
    ends = []
    for name in dict.fromkeys(geometry.component_of(n) for n in nets):
        body = model.components.get(name)
        if body is not None and hasattr(body, "center_at") and hasattr(body, "cross_sections"):
            ends += _centres(body)
    if not ends:
        return nets
    out = {}
    for name, net in nets.items():
        net = np.array(net, float)
        for x, c, extent in ends:
            for centre in (c, c * np.array([1.0, -1.0, 1.0])):
                near = (net[..., 0] == x) & (
                    np.linalg.norm(net - centre, axis=-1) <= 2.0 * extent)
                net[near] = centre
        out[name] = net
    return out
