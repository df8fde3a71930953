"""The fixed-area re-design of an arbitrary-section fuselage (past TM-4406).

TM-4406 shrinks a circular fuselage's radius where the fillets add area. An arbitrary
section (the deck's J2 = +1 polylines) has no radius; here each section is scaled about its
area centroid by k = r / r0, r0 = sqrt(A0 / pi) its equivalent radius, so that it keeps its
shape and gives up exactly A0 (1 - k^2) = pi (r0^2 - r^2). Everything else is
:class:`~juncture.fillet.redesign.BodyReduction`'s: the fillet stations (and the extra stations
between them) added to the body, the removed area interpolated between them, the reduction
of the equivalent radius solved per station with the perimeter the wing roots cover
(``exposure``), never growing the body.

The new stations' sections are cut from the original surface: each is the blend of its two
neighbouring stations' polylines, with the surface parameters of that blend
(``ArbitraryBody.params``), so where nothing is removed the re-designed body is the original
surface exactly, and between stations its sections are again blended linearly.
"""

from __future__ import annotations

import numpy as np

from ..model._sections import area_and_centroid
from .redesign import BodyReduction

__all__ = ["SectionReduction", "reduction_for", "root_exposure_rate"]


def reduction_for(body, x, densify=None, exposure=None):
    """:class:`BodyReduction` for a circular body, :class:`SectionReduction` otherwise."""
    if hasattr(body, "radius_at"):
        return BodyReduction(body, x, densify, exposure)
    return SectionReduction(body, x, densify, exposure)


class SectionReduction(BodyReduction):
    """:class:`BodyReduction` of an :class:`~juncture.model.ArbitraryBody` (module
    docstring): the reduction d of the equivalent radius scales each section about its
    centroid by (r0 - d) / r0."""

    def _base(self, body, layout):
        xg = body.x_global
        polys, params = [], []
        for merged, (kind, i, piece, size) in layout:
            start = piece + i  # the segment's first station (pieces: size - 1 each)
            if kind == "gap":
                k = np.full(merged.size, start - 1)  # the pair that bridges the gap
            else:
                sx = xg[start:start + size]
                k = start + np.clip(np.searchsorted(sx, merged, side="right") - 1, 0, size - 2)
            w = np.clip((merged - xg[k]) / (xg[k + 1] - xg[k]), 0.0, 1.0)
            for kk, ww in zip(k, w):
                n = int(body._count[kk])
                polys.append(body._blend(kk, ww, slice(0, n)))
                params.append(body._u[kk, :n].copy())
        self.polylines, self.params = polys, params
        moments = np.array([area_and_centroid(p) for p in polys]).reshape(-1, 2)
        area, self.centroid_z = moments[:, 0], moments[:, 1]
        self.points_per_section = None
        out, first = [], 0
        for merged, _ in layout:
            r0 = np.sqrt(area[first:first + merged.size] / np.pi)
            rc = np.stack([r0, np.zeros_like(r0)], axis=1)
            out.append((rc, np.zeros_like(rc)))
            first += merged.size
        return out

    def _between(self, dnode, xq):
        """Between two stations the sections blend linearly: d is taken linear in x there
        (the model of the area iteration's Newton step)."""
        xn = self.xn
        k = np.clip(np.searchsorted(xn, xq, side="right") - 1, 0, xn.size - 2)
        h = xn[k + 1] - xn[k]
        w = np.clip((xq - xn[k]) / np.where(h > 0, h, 1.0), 0.0, 1.0)[:, None]
        return (1.0 - w) * dnode[k] + w * dnode[k + 1]

    def _build(self, d):
        from ..model import ArbitraryBody

        body, r0 = self.original, self.r0
        k = np.where(r0 > 0, (r0 - d) / np.where(r0 > 0, r0, 1.0), 1.0)
        secs = []
        for p, kk, zc in zip(self.polylines, k, self.centroid_z):
            q = p * kk
            q[:, 1] += (1.0 - kk) * zc
            secs.append(q)
        return ArbitraryBody(body.name, self.xn, secs, self.seg_sizes,
                             mirrored=body.mirrored, params=self.params)


def root_exposure_rate(body, x, s_a, s_b):
    """The area uncovered per unit reduction of the equivalent radius on the part of the
    section between parameters s_a and s_b at stations x (all (...,)): scaling a section by
    k about its centroid c moves its boundary p by (1 - k) (p - c), so the covered part
    uncovers sum (p - c) . n ds / r0 per unit d = r0 (1 - k), i.e. twice the area of the
    sector from c over that part, divided by r0 (r0 delta theta on a circle)."""
    from .area import _section_green

    x = np.asarray(x, float)
    s_a, s_b = np.broadcast_arrays(np.asarray(s_a, float), np.asarray(s_b, float))
    c = body.centroid_at(x)
    pa, pb = body.point(x, s_a)[..., 1:], body.point(x, s_b)[..., 1:]
    about_origin = _section_green(body, x.ravel(), s_a.ravel(), s_b.ravel()).reshape(x.shape)
    sector = about_origin - 0.5 * (c[..., 0] * (pb[..., 1] - pa[..., 1])
                                   - c[..., 1] * (pb[..., 0] - pa[..., 0]))
    r0 = np.sqrt(body.area_at(x) / np.pi)
    return np.where(r0 > 0, 2.0 * np.abs(sector) / np.where(r0 > 0, r0, 1.0), 0.0)
