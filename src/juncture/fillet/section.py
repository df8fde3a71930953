"""The fuselage cross-section as the fillet constructions see it: circles and polylines.

TM-4406 builds its fillets on a circular fuselage: the start point B lies an angle theta_u
from the intersection I along the section circle, and the fillet leaves B along the circle's
tangent. The same construction holds on any section that has a tangent at B and an outward
side, which is what this module gives the fillet code, vectorised over lines:

- :class:`CircleFrame` (a :class:`~juncture.model.CircularBody`): the parameter is the
  angle theta (-pi/2 bottom, pi/2 top); every value is the closed form the circular code
  has always used, so fillets on circular fuselages are unchanged bit for bit.
- :class:`PolylineFrame` (a :class:`~juncture.model.ArbitraryBody`, the deck's J2 = +1
  sections): the parameter is the body's surface parameter s (0 bottom, 1 top: normalised
  arc length at the stations). **Past the paper:** the start point lies at the arc length
  ``phi * r_eq`` from I along the section (r_eq = sqrt(A / pi), the equivalent radius, so
  theta_u = 20 deg means the same arc on a circle and on a section of the same area), and
  the tangent at B is that of the polyline piece on I's side of B, turned outward near a
  vertex towards the next piece's direction (a vertex has no single tangent; turning there
  makes the fillet a continuous function of the geometry and keeps it out of the section:
  :meth:`PolylineFrame._up`). A straight piece has no curvature, so the circle's
  curvature terms vanish there.

Methods (x, parameters and signs (m,); points (m, 3)):

``start(x, p, sign, phi)``  the parameter an arc ``phi`` (in units of r_ref) from p,
                            upward for sign = +1 (upper fillets), downward for -1
``point(x, p)``             surface points
``tangent(x, p, sign)``     unit tangent in the plane x = const at p, towards I
``normal(x, p, sign)``      unit outward normal with the body's slope along x
``normal2(x, p, sign)``     unit outward normal in the plane x = const
``wedge(d, x, p, sign)``    angle between the section's tangent at I towards the fillet
                            side and a wing line leaving I along d (m, 2) in the y-z plane
``ref_radius(x)``           r (circle) or r_eq (polyline)
``distance(points)``        signed distance to the body, > 0 outside
``plane_gap(points, x0)``   the same in the planes x = x0 (points (m, n, 3))
``bend(control)``           the second derivative of the gap of a cubic leaving the body at
                            its first control point (< 0: it enters the body)
``parameter_of(points)``    the parameter of points on the body
``extreme(sign)``           the bottom (sign = -1) or top (+1) of the half-section
"""

from __future__ import annotations

import numpy as np

__all__ = ["CircleFrame", "PolylineFrame", "section_frame"]

#: Share of a section's median piece, from a vertex, over which a fillet's start direction
#: turns from one piece's to the other's (:meth:`PolylineFrame._up`).
ZONE = 0.25


def section_frame(body):
    """The frame of a fuselage: :class:`CircleFrame` or :class:`PolylineFrame`."""
    from ..model import CircularBody

    return CircleFrame(body) if isinstance(body, CircularBody) else PolylineFrame(body)


class _Frame:
    """What both frames share: the body, its name and length."""

    def __init__(self, body):
        self.body = body

    @property
    def name(self):
        return self.body.name

    @property
    def length(self):
        return self.body.length


class CircleFrame(_Frame):
    """A circular body's section (TM-4406's own geometry)."""

    circular = True

    def start(self, x, p, sign, phi):
        return p + sign * phi

    def point(self, x, p):
        return self.body.point(x, p)

    def tangent(self, x, p, sign):
        # Circle tangent at p pointing towards the wing (theta moving back towards theta_I).
        return np.stack([np.zeros(np.shape(p)), np.sin(p), -np.cos(p)], axis=1) * sign

    def normal(self, x, p, sign=None):
        slope = self.body.radius_at(x, 1) + self.body.center_at(x, 1)[:, 1] * np.sin(p)
        n = np.stack([-slope, np.cos(p), np.sin(p)], axis=1)
        return n / np.linalg.norm(n, axis=1)[:, None]

    def normal2(self, x, p, sign=None):
        return np.stack([np.zeros(np.shape(p)), np.cos(p), np.sin(p)], axis=1)

    def wedge(self, direction, x, p, sign):
        phi = 0.5 * np.pi + sign * (np.arctan2(direction[:, 1], direction[:, 0]) - p)
        return (phi + np.pi) % (2 * np.pi) - np.pi

    def ref_radius(self, x):
        return self.body.radius_at(x)

    def distance(self, points):
        return self.body.radial_error(points)

    def plane_gap(self, points, x0):
        ctr, r = self.body.section_at(x0)
        return np.hypot(points[..., 1] - ctr[:, None, 0],
                        points[..., 2] - ctr[:, None, 1]) - r[:, None]

    def bend(self, control):
        """e''(0) = |T_B|^2 / r + 6 N_B . (P2 - B), N_B the normal with the cone's slope
        (unnormalised), and its scale |T_B|^2 / r."""
        body = self.body
        B = control[:, 0]
        ctr, r = body.section_at(B[:, 0])
        theta = np.arctan2(B[:, 2] - ctr[:, 1], B[:, 1] - ctr[:, 0])
        slope = body.radius_at(B[:, 0], 1) + body.center_at(B[:, 0], 1)[:, 1] * np.sin(theta)
        n_b = np.stack([-slope, np.cos(theta), np.sin(theta)], axis=1)
        t0 = 3.0 * (control[:, 1] - B)
        with np.errstate(divide="ignore", invalid="ignore"):
            curv = (t0 * t0).sum(1) / r
            scale = (t0 * t0).sum(1) / np.where(r > 0, r, 1.0)
        return curv + 6.0 * (n_b * (control[:, 2] - B)).sum(1), scale

    def parameter_of(self, points):
        ctr = self.body.center_at(points[:, 0])
        return np.arctan2(points[:, 2] - ctr[:, 1], points[:, 1] - ctr[:, 0])

    def extreme(self, sign):
        return 0.5 * np.pi * sign


class PolylineFrame(_Frame):
    """An arbitrary-section body's polyline sections (past the paper: module docstring)."""

    circular = False

    def _piece(self, x, s, above):
        """End points (m, 2) of the polyline piece holding s at x, and its index j (m,): the
        piece above s where s is a vertex and ``above`` (m,) is True, else the one below."""
        b = self.body
        k, w = b._pair(np.asarray(x, float))
        u = b._u[k]
        s = np.asarray(s, float)
        j = np.where(above, (u <= s[:, None]).sum(-1), (u < s[:, None]).sum(-1)) - 1
        j = np.clip(j, 0, b._count[k] - 2)
        p0 = b._blend(k, w[:, None], j)
        p1 = b._blend(k, w[:, None], j + 1)
        # A zero-length piece (a repeated point): the next non-degenerate one along.
        for step in (1, -1):
            flat = np.hypot(*(p1 - p0).T) <= 0
            if not flat.any():
                break
            jj = np.clip(j + step, 0, b._count[k] - 2)
            p0 = np.where(flat[:, None], b._blend(k, w[:, None], jj), p0)
            p1 = np.where(flat[:, None], b._blend(k, w[:, None], jj + 1), p1)
            j = np.where(flat, jj, j)
        return p0, p1, j

    def _along(self, x, s, above):
        """Unit direction (m, 2) of increasing s along the piece (see :meth:`_piece`)."""
        p0, p1, _ = self._piece(x, s, above)
        d = p1 - p0
        return d / np.maximum(np.hypot(*d.T), 1e-300)[:, None]

    def _up(self, x, s, toward_up):
        """Unit direction (m, 2) of increasing s along the section at B = point(x, s), with
        I on the side ``toward_up`` (m,) (True: I at larger s).

        That of the piece on I's side of B, turned outward near the vertices where that
        direction would jump into the section as B crosses them: a convex vertex behind B
        (away from I) and a concave one ahead of it. Each such vertex within h of B (along
        the section) turns the direction by its turn angle times 1 - distance / h, h =
        :data:`ZONE` times the longer of its two pieces or the section's median piece (of
        those longer than a thousandth of it), whichever is shorter; so at the vertex the
        direction is already the next piece's. It is therefore a continuous function of B
        (a fillet on a polyline section moves continuously with the geometry, as keep_area's
        iteration and a design study need, also across the near-duplicate vertices of a
        section blended between two stations), and never points into the section: it is B's
        own piece's direction turned outward by at most the turns within h.
        """
        b = self.body
        x = np.asarray(x, float)
        up = np.asarray(toward_up, bool)
        _, _, j = self._piece(x, s, up)
        sec = b._sections_at(x)                                  # (m, M, 2)
        d = np.diff(sec, axis=1)
        length = np.hypot(d[..., 0], d[..., 1])
        angle = np.where(length > 0, np.arctan2(d[..., 1], d[..., 0]), np.nan)
        # zero-length pieces take the previous piece's direction (its turn goes to one vertex)
        idx = np.where(length > 0, np.arange(length.shape[1]), 0)
        np.maximum.accumulate(idx, axis=1, out=idx)
        angle = np.take_along_axis(angle, idx, axis=1)
        first = np.nanmax(np.where(length > 0, angle, -np.inf), axis=1, keepdims=True)
        angle = np.where(np.isnan(angle), np.where(np.isfinite(first), first, 0.0), angle)
        turn = (np.diff(angle, axis=1) + np.pi) % (2 * np.pi) - np.pi   # at vertices 1..M-2
        sigma = np.concatenate([np.zeros((len(x), 1)), np.cumsum(length, axis=1)], axis=1)
        rows = np.arange(len(x))
        t = np.clip((np.linalg.norm(b.point(x, s)[:, 1:] - sec[rows, j], axis=1)
                     / np.maximum(length[rows, j], 1e-300)), 0.0, 1.0)
        at = sigma[rows, j] + t * length[rows, j]               # B's arc length
        # the median piece, of those longer than a thousandth of the section (a section
        # blended between two stations has near-duplicate vertices; a point section none)
        real = length > 1e-3 * sigma[:, -1:]
        ordered = np.sort(np.where(real, length, np.inf), axis=1)
        middle = np.maximum(real.sum(axis=1) - 1, 0)[:, None] // 2
        median = np.take_along_axis(ordered, middle, axis=1)[:, 0]
        median = np.where(np.isfinite(median), median, 0.0)
        h = ZONE * np.minimum(median[:, None], np.maximum(length[:, :-1], length[:, 1:]))
        vertex = sigma[:, 1:-1]
        behind = np.where(up[:, None], vertex <= at[:, None], vertex >= at[:, None])
        outward = np.where(behind, np.maximum(turn, 0.0), np.maximum(-turn, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            weight = np.clip(1.0 - np.abs(vertex - at[:, None]) / h, 0.0, 1.0)
        weight = np.where(h > 0, weight, 0.0)
        psi = angle[rows, j] + np.where(up, -1.0, 1.0) * (outward * weight).sum(axis=1)
        return np.stack([np.cos(psi), np.sin(psi)], axis=1)

    def _half_length(self, x):
        sec = self.body._sections_at(np.asarray(x, float))
        return np.hypot(*np.diff(sec, axis=-2).transpose(2, 0, 1)).sum(-1)

    def start(self, x, p, sign, phi):
        length = self._half_length(x)
        ds = phi * self.ref_radius(x) / np.where(length > 0, length, 1.0)
        return np.clip(p + sign * ds, 0.0, 1.0)

    def point(self, x, p):
        return self.body.point(x, p)

    def tangent(self, x, p, sign):
        sign = np.broadcast_to(np.asarray(sign, float), np.shape(p))
        d = self._up(x, p, sign < 0) * -sign[:, None]
        return np.concatenate([np.zeros((len(d), 1)), d], axis=1)

    def normal2(self, x, p, sign):
        sign = np.broadcast_to(np.asarray(sign, float), np.shape(p))
        d = self._up(x, p, sign < 0)
        return np.stack([np.zeros(len(d)), d[:, 1], -d[:, 0]], axis=1)

    def normal(self, x, p, sign):
        """With the section's speed v along x at fixed s: n = (-(v . n2), n2), normalised."""
        n2 = self.normal2(x, p, sign)
        b = self.body
        x = np.asarray(x, float)
        h = 1e-7 * max(b.length, 1.0)
        lo, hi = np.maximum(x - h, b.x[0]), np.minimum(x + h, b.x[-1])
        span = np.where(hi > lo, hi - lo, 1.0)
        v = (b.point(hi, p) - b.point(lo, p))[:, 1:] / span[:, None]
        n = np.concatenate([-(v * n2[:, 1:]).sum(1)[:, None], n2[:, 1:]], axis=1)
        return n / np.linalg.norm(n, axis=1)[:, None]

    def wedge(self, direction, x, p, sign):
        sign = np.broadcast_to(np.asarray(sign, float), np.shape(p))
        # towards the fillet side, turned outward near a vertex as at a start (continuous
        # in I, and the smaller wedge there)
        t = self._up(x, p, sign > 0) * sign[:, None]
        phi = np.pi - sign * (np.arctan2(t[:, 1], t[:, 0])
                              - np.arctan2(direction[:, 1], direction[:, 0]))
        return (phi + np.pi) % (2 * np.pi) - np.pi

    def ref_radius(self, x):
        return np.sqrt(self.body.area_at(x) / np.pi)

    def distance(self, points):
        return self.body.signed_distance(points)

    def plane_gap(self, points, x0):
        q = np.array(points, float)
        q[..., 0] = np.asarray(x0, float)[:, None]
        return self.body.signed_distance(q)

    def bend(self, control):
        """A straight piece has no curvature: e''(0) = 6 N_B . (P2 - B), with the scale
        6e4 |P2 - B| (so that P2 may lie 6e-8 of its distance from B below the tangent
        plane: round-off where the construction put it on the plane)."""
        B = control[:, 0]
        s = self.body.parameter_of(B)
        # The piece the curve leaves along: the one P1 lies towards (B -> P1 is its tangent).
        up = self._along(B[:, 0], s, np.ones(len(s), bool))
        toward_up = ((control[:, 1, 1:] - B[:, 1:]) * up).sum(1) > 0
        sign = np.where(toward_up, -1.0, 1.0)  # the fillet side is opposite to its travel
        n = self.normal(B[:, 0], s, sign)
        leg = control[:, 2] - B
        return 6.0 * (n * leg).sum(1), 6e4 * np.linalg.norm(leg, axis=1)

    def parameter_of(self, points):
        return self.body.parameter_of(points)

    def extreme(self, sign):
        return 0.5 * (1.0 + sign)
