"""Parametric-surface layer of the long-strake blend: points, first derivatives, normals.

Every surface maps parameters ``(u, v)`` (any broadcastable float arrays) to points and the two
first derivatives, all of shape ``u.shape + (3,)``. Concrete surfaces implement
``_evaluate(u, v) -> (P, P_u, P_v)`` on equal-shape arrays; the base class broadcasts, offers
:meth:`ParametricSurface.points`, :meth:`normals` and :meth:`grid`, and nothing else.

Surfaces here (Song, Ma & Wang 2008, section 1):

========================  ==============================================  ====================
class                     parameters                                      paper
========================  ==============================================  ====================
``ConstantSectionBody``   ``u = x`` [length], ``v`` section parameter      S1(u, v)
``AirfoilWing``           ``u`` in [-1, 1] (lower < 0 < upper), ``v``     S2(u, v)
                          in [0, 1] from first to last section
``PlaneSurface``          ``o + u a + v b``                                S3, plane T
``MappedSurface``         a surface evaluated on a parameter-plane map    B1, B2, B3 (eqs 2-8)
========================  ==============================================  ====================

Axes: x aft, y to starboard, z up. The body angle of a circular section is theta as in TM-4406
eqs 2-3: ``y = R cos(theta)``, ``z = z_axis + R sin(theta)``, theta = 0 on the horizontal,
+pi/2 at the top.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline

from ..errors import GeometryError

__all__ = [
    "ParametricSurface",
    "CircleSection",
    "SplineSection",
    "ConstantSectionBody",
    "AirfoilWing",
    "PlaneSurface",
    "MappedSurface",
    "naca_thickness",
    "unit",
]

# NACA 4-digit half-thickness per unit thickness ratio, in xi = sqrt(x/c), closed trailing
# edge (last coefficient -0.1036): Y(xi) = 5 (0.2969 xi - 0.1260 xi^2 - 0.3516 xi^4
# + 0.2843 xi^6 - 0.1036 xi^8). A polynomial in xi: smooth, vertical tangent at the nose.
_NACA = np.array([0.0, 0.2969, -0.1260, 0.0, -0.3516, 0.0, 0.2843, 0.0, -0.1036]) * 5.0


def naca_thickness(xi, deriv=0):
    """NACA 4-digit half-thickness per unit t/c at ``xi = sqrt(x/c)`` (or its derivative).

    Parameters
    ----------
    xi : float array
        Square root of the chord fraction, in [0, 1].
    deriv : {0, 1, 2}
        Order of the derivative with respect to xi.

    Examples
    --------
    >>> abs(float(naca_thickness(1.0))) < 1e-12  # closed trailing edge
    True
    >>> round(float(naca_thickness(0.3 ** 0.5)), 3)  # t/2 at 30 % chord
    0.5
    """
    poly = np.polynomial.Polynomial(_NACA)
    return (poly.deriv(deriv) if deriv else poly)(np.asarray(xi, dtype=float))


def unit(vec):
    """Vectors (..., 3) scaled to unit length (zero vectors stay zero)."""
    vec = np.asarray(vec, dtype=float)
    norm = np.linalg.norm(vec, axis=-1, keepdims=True)
    return np.divide(vec, norm, out=np.zeros_like(vec), where=norm > 0)


class ParametricSurface:
    """Base class: broadcasting, points, unit normals, tensor grids."""

    __slots__ = ()

    def evaluate(self, u, v):
        """Points and first derivatives at ``(u, v)``.

        Returns
        -------
        P, P_u, P_v : (..., 3) float
            Points and the derivatives with respect to u and v; ``...`` is the broadcast
            shape of ``u`` and ``v``.
        """
        u, v = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
        return self._evaluate(u.copy(), v.copy())

    def points(self, u, v):
        """Points (..., 3) at ``(u, v)``."""
        return self.evaluate(u, v)[0]

    def normals(self, u, v):
        """Unit normals ``unit(P_u x P_v)`` (..., 3) at ``(u, v)``."""
        _, pu, pv = self.evaluate(u, v)
        return unit(np.cross(pu, pv))

    def grid(self, u, v):
        """Points on the tensor grid of 1-D ``u`` (n) and ``v`` (m): (n, m, 3)."""
        uu, vv = np.meshgrid(np.asarray(u, float), np.asarray(v, float), indexing="ij")
        return self.points(uu, vv)

    def _evaluate(self, u, v):  # pragma: no cover - abstract
        raise NotImplementedError


# ----------------------------------------------------------------------------- body sections
@dataclass(frozen=True, slots=True, eq=False)
class CircleSection:
    """Circular cross-section of radius ``radius`` centred on ``(0, z_axis)``; v = theta."""

    radius: float
    z_axis: float = 0.0

    def __post_init__(self):
        if not np.isfinite(self.radius) or self.radius <= 0:
            raise GeometryError(f"body radius must be positive, found {self.radius!r}",
                                component="body")

    @property
    def size(self):
        """The body radius R [length] (the scale of the report's tolerances)."""
        return float(self.radius)

    def evaluate(self, v):
        """(y, z) and (dy/dv, dz/dv) of the section at ``v`` (theta, radians): 4 arrays."""
        r = self.radius
        return r * np.cos(v), self.z_axis + r * np.sin(v), -r * np.sin(v), r * np.cos(v)

    def v_at_height(self, z):
        """Right-side (y > 0) section parameter at height ``z``, dv/dz and d2v/dz2.

        Raises
        ------
        GeometryError
            If a height lies outside the open span of the section.
        """
        s = (np.asarray(z, float) - self.z_axis) / self.radius
        if np.any(np.abs(s) >= 1.0):
            raise GeometryError(f"height z = {np.max(np.abs(s)) * self.radius:.6g} from the "
                                f"axis is outside the body radius {self.radius:.6g}",
                                component="body")
        v = np.arcsin(s)
        c = np.cos(v)
        return v, 1.0 / (self.radius * c), np.sin(v) / (self.radius**2 * c**3)


@dataclass(frozen=True, slots=True, eq=False)
class SplineSection:
    """Closed cross-section through points ``(k, 2)`` of (y, z): periodic cubic spline.

    The points run with increasing angle about the section centre, like theta (from y > 0
    over the top to y < 0). The parameter v is chord length scaled onto [0, 2 pi).
    """

    points: object
    _spline: object = None

    def __post_init__(self):
        pts = np.asarray(self.points, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 4:
            raise GeometryError(f"a body section needs (k >= 4, 2) points, found {pts.shape}",
                                component="body")
        if np.allclose(pts[0], pts[-1]):
            pts = pts[:-1]
        closed = np.vstack([pts, pts[:1]])
        seg = np.linalg.norm(np.diff(closed, axis=0), axis=1)
        if np.any(seg <= 0):
            raise GeometryError("body section has repeated points", component="body")
        v = np.concatenate([[0.0], np.cumsum(seg)]) * (2 * np.pi / seg.sum())
        area2 = np.sum(pts[:, 0] * np.roll(pts[:, 1], -1) - np.roll(pts[:, 0], -1) * pts[:, 1])
        if area2 <= 0:
            raise GeometryError("body section points must run counter-clockwise (y > 0 "
                                "first, then over the top)", component="body")
        spline = CubicSpline(v, closed, bc_type="periodic")
        object.__setattr__(self, "points", pts)
        object.__setattr__(self, "_spline", spline)

    @property
    def size(self):
        """Largest distance of a section point from the centroid of the points [length]."""
        c = self.points.mean(axis=0)
        return float(np.max(np.linalg.norm(self.points - c, axis=1)))

    def evaluate(self, v):
        """(y, z) and (dy/dv, dz/dv) at ``v``."""
        p = self._spline(np.mod(v, 2 * np.pi))
        d = self._spline(np.mod(v, 2 * np.pi), 1)
        return p[..., 0], p[..., 1], d[..., 0], d[..., 1]

    def v_at_height(self, z):
        """Section parameter on the y > 0 side at height ``z``, dv/dz, d2v/dz2 (Newton)."""
        z = np.asarray(z, float)
        vs = np.linspace(-np.pi, np.pi, 4097)
        y, zz, _, dz = self.evaluate(vs)
        ok = (y > 0) & (dz > 0)
        if not np.any(ok):
            raise GeometryError("body section has no right side rising in z", component="body")
        # the longest run of right-side, rising samples
        idx = np.flatnonzero(ok)
        runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
        run = max(runs, key=len)
        zr, vr = zz[run], vs[run]
        if np.any(z <= zr[0]) or np.any(z >= zr[-1]):
            raise GeometryError(f"height z outside the right side of the body section "
                                f"[{zr[0]:.6g}, {zr[-1]:.6g}]", component="body")
        v = np.interp(z, zr, vr)
        for _ in range(30):
            _, zv, _, dzv = self.evaluate(v)
            step = (zv - z) / dzv
            v = v - step
            if np.max(np.abs(step), initial=0.0) < 1e-15:
                break
        dz = self.evaluate(v)[3]
        d2z = self._spline(np.mod(v, 2 * np.pi), 2)[..., 1]
        return v, 1.0 / dz, -d2z / dz**3


@dataclass(frozen=True, slots=True, eq=False)
class ConstantSectionBody(ParametricSurface):
    """Missile body: a constant cross-section swept along the x axis (a general cylinder).

    S1(u, v) = (u, y(v), z(v)) with ``u = x`` [length] and ``v`` the section parameter
    (theta for a :class:`CircleSection`). The body is a ruled surface of constant section, the
    property the paper's proof 2 (eqs 14-19) rests on: its normal does not change along x.

    Parameters
    ----------
    section : CircleSection or SplineSection
    x_start, x_end : float
        Axial extent used for output networks [length] (evaluation is not limited).
    """

    section: object
    x_start: float
    x_end: float

    def __post_init__(self):
        if not self.x_end > self.x_start:
            raise GeometryError(f"body x_end ({self.x_end}) must exceed x_start "
                                f"({self.x_start})", component="body")

    @property
    def size(self):
        """Body radius (circle) or largest section radius [length]."""
        return self.section.size

    def _evaluate(self, u, v):
        y, z, yv, zv = self.section.evaluate(v)
        one, zero = np.ones_like(u), np.zeros_like(u)
        p = np.stack([u, y, z], axis=-1)
        pu = np.stack([one, zero, zero], axis=-1)
        pv = np.stack([zero, yv, zv], axis=-1)
        return p, pu, pv

    def outward_normals(self, u, v):
        """Unit normals pointing out of the body (= unit(P_v x P_u) for ccw sections)."""
        _, pu, pv = self.evaluate(u, v)
        return unit(np.cross(pv, pu))


# ----------------------------------------------------------------------------- wing
@dataclass(frozen=True, slots=True, eq=False)
class AirfoilWing(ParametricSurface):
    """A wing lofted linearly in span between symmetric NACA 4-digit sections (closed TE).

    Each section k lies in the plane ``y = y[k]`` with leading edge ``(x_le[k], z_le[k])``,
    chord ``chord[k]`` and thickness ratio ``thickness[k]``. Parameters: ``u`` in [-1, 1] runs
    from the lower trailing edge (-1) round the nose (0) to the upper trailing edge (+1) with
    ``xi = |u| = sqrt(x/c)``; ``v`` in [0, 1] maps piecewise linearly onto the section y
    stations (beyond [0, 1] the end panels are extended linearly). Points of neighbouring
    sections are joined by straight lines (the architecture's linear spanwise loft).

    Parameters
    ----------
    y, x_le, z_le, chord, thickness : (k,) float, k >= 2, y strictly increasing
    """

    y: object
    x_le: object
    z_le: object
    chord: object
    thickness: object

    def __post_init__(self):
        arrs = [np.atleast_1d(np.asarray(getattr(self, f), dtype=float))
                for f in ("y", "x_le", "z_le", "chord", "thickness")]
        n = len(arrs[0])
        if n < 2 or any(a.shape != (n,) for a in arrs):
            raise GeometryError(f"wing sections need >= 2 equal-length 1-D arrays, found "
                                f"{[a.shape for a in arrs]}", component="wing")
        if np.any(np.diff(arrs[0]) <= 0):
            raise GeometryError("wing section y stations must increase", component="wing")
        if np.any(arrs[3] <= 0) or np.any(arrs[4] <= 0) or np.any(arrs[4] >= 0.5):
            raise GeometryError("wing chords must be positive and thickness ratios in (0, 0.5)",
                                component="wing")
        for f, a in zip(("y", "x_le", "z_le", "chord", "thickness"), arrs, strict=True):
            a.flags.writeable = False
            object.__setattr__(self, f, a)

    @property
    def v_stations(self):
        """Parameter v of each section (k,): 0 ... 1 proportional to y."""
        return (self.y - self.y[0]) / (self.y[-1] - self.y[0])

    def v_at_y(self, y):
        """Spanwise parameter of the plane ``y = const`` (linear, extended beyond the ends)."""
        return (np.asarray(y, float) - self.y[0]) / (self.y[-1] - self.y[0])

    def section_at(self, y):
        """Lofted section at span station ``y``: (x_le, z_le, chord, chord * thickness)."""
        lam, k = self._segment(self.v_at_y(y))
        ct = self.chord * self.thickness
        return tuple(float((1 - lam) * a[k] + lam * a[k + 1])
                     for a in (self.x_le, self.z_le, self.chord, ct))

    def _segment(self, v):
        vs = self.v_stations
        k = np.clip(np.searchsorted(vs, v, side="right") - 1, 0, len(vs) - 2)
        lam = (v - vs[k]) / (vs[k + 1] - vs[k])
        return lam, k

    def _evaluate(self, u, v):
        lam, k = self._segment(v)
        dlam_dv = 1.0 / (self.v_stations[k + 1] - self.v_stations[k])
        xi = np.abs(u)
        sgn = np.where(u < 0, -1.0, 1.0)
        Y, dY = naca_thickness(xi), naca_thickness(xi, 1)

        def sec(j):
            c, ct = self.chord[j], self.chord[j] * self.thickness[j]
            p = np.stack([self.x_le[j] + c * xi**2, np.broadcast_to(self.y[j], u.shape),
                          self.z_le[j] + sgn * ct * Y], axis=-1)
            du = np.stack([2 * c * u, np.zeros_like(u), ct * dY], axis=-1)
            return p, du

        p0, d0 = sec(k)
        p1, d1 = sec(k + 1)
        lam3 = lam[..., None]
        p = (1 - lam3) * p0 + lam3 * p1
        pu = (1 - lam3) * d0 + lam3 * d1
        pv = (p1 - p0) * dlam_dv[..., None]
        return p, pu, pv


# ----------------------------------------------------------------------------- plane, maps
@dataclass(frozen=True, slots=True, eq=False)
class PlaneSurface(ParametricSurface):
    """Plane ``P(u, v) = origin + u a + v b`` (auxiliary plane S3, projection plane T)."""

    origin: object
    a: object
    b: object

    def _evaluate(self, u, v):
        o, a, b = (np.asarray(x, float) for x in (self.origin, self.a, self.b))
        p = o + u[..., None] * a + v[..., None] * b
        return p, np.broadcast_to(a, p.shape).copy(), np.broadcast_to(b, p.shape).copy()


@dataclass(frozen=True, slots=True, eq=False)
class MappedSurface(ParametricSurface):
    """A base surface on a parameter-plane patch: ``B(s, t) = S(P(s, t))`` (eqs 2, 4, 8).

    ``param_map(s, t)`` returns ``(uv, uv_s, uv_t)``, each of shape (..., 2): the patch
    point in the base surface's parameter plane and its derivatives. The chain rule gives
    ``B_s = S_u u_s + S_v v_s`` and likewise for t.
    """

    base: object
    param_map: object

    def _evaluate(self, s, t):
        uv, uv_s, uv_t = self.param_map(s, t)
        p, su, sv = self.base.evaluate(uv[..., 0], uv[..., 1])
        ps = su * uv_s[..., :1] + sv * uv_s[..., 1:]
        pt = su * uv_t[..., :1] + sv * uv_t[..., 1:]
        return p, ps, pt
