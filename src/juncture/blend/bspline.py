"""Tensor-product B-spline surfaces with numpy/scipy: basis matrices, evaluation, fitting.

A B-spline surface of degrees (p, q) with clamped knot vectors ``knots_u`` (n_u + p + 1) and
``knots_v`` (n_v + q + 1) and control points ``control`` (n_u, n_v, 3) is
``S(u, v) = sum_ij N_i,p(u) M_j,q(v) P_ij`` (Piegl & Tiller, The NURBS Book, eq 3.11).
Basis values come from :class:`scipy.interpolate.BSpline` with an identity coefficient matrix,
so every evaluation is one vectorised call.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import BSpline

from ..errors import GeometryError
from .surfaces import ParametricSurface

__all__ = ["BSplineSurface", "basis_matrix", "clamped_knots", "greville",
           "interpolate_curve"]


def clamped_knots(n_spans, degree=3):
    """Uniform clamped knot vector on [0, 1] with ``n_spans`` spans: (n_spans + 2 degree + 1,).

    Examples
    --------
    >>> clamped_knots(2, 1).tolist()
    [0.0, 0.0, 0.5, 1.0, 1.0]
    """
    if int(n_spans) < 1:
        raise GeometryError(f"a knot vector needs at least one span, found {n_spans}")
    inner = np.linspace(0.0, 1.0, int(n_spans) + 1)
    return np.concatenate([np.zeros(degree), inner, np.ones(degree)])


def greville(knots, degree=3):
    """Greville abscissae (n_basis,): averages of ``degree`` consecutive interior knots."""
    knots = np.asarray(knots, float)
    n = len(knots) - degree - 1
    return np.array([knots[i + 1:i + degree + 1].mean() for i in range(n)])


def basis_matrix(knots, degree, x, deriv=0):
    """Values (or derivatives) of all B-spline basis functions: (len(x), n_basis).

    Parameters
    ----------
    knots : (n_basis + degree + 1,) float
        Clamped knot vector.
    degree : int
    x : (m,) float
        Parameters in [knots[0], knots[-1]] (the last one is included).
    deriv : int
        Order of the derivative.
    """
    knots = np.asarray(knots, float)
    n = len(knots) - degree - 1
    spline = BSpline(knots, np.eye(n), degree, extrapolate=True)
    if deriv:
        spline = spline.derivative(deriv)
    return spline(np.clip(np.asarray(x, float), knots[0], knots[-1]))


def interpolate_curve(curve, knots, degree=3):
    """Control points (n_basis, 3) of the spline that interpolates ``curve`` at Greville points.

    ``curve(x)`` returns points (m, 3). The end control points equal the curve's end points
    (clamped knots).
    """
    g = greville(knots, degree)
    a = basis_matrix(knots, degree, g)
    return np.linalg.solve(a, curve(g))


@dataclass(frozen=True, slots=True, eq=False)
class BSplineSurface(ParametricSurface):
    """Non-rational tensor-product B-spline surface.

    Parameters
    ----------
    control : (n_u, n_v, 3) float
        Control points.
    knots_u : (n_u + degree_u + 1,) float
    knots_v : (n_v + degree_v + 1,) float
    degree_u, degree_v : int
    """

    control: object
    knots_u: object
    knots_v: object
    degree_u: int = 3
    degree_v: int = 3

    def __post_init__(self):
        c = np.array(self.control, dtype=float)
        ku, kv = np.array(self.knots_u, float), np.array(self.knots_v, float)
        if c.ndim != 3 or c.shape[2] != 3:
            raise GeometryError(f"control points must be (n_u, n_v, 3), found {c.shape}")
        if len(ku) != c.shape[0] + self.degree_u + 1 or len(kv) != c.shape[1] + \
                self.degree_v + 1:
            raise GeometryError(f"knot vectors of length {len(ku)}, {len(kv)} do not fit "
                                f"{c.shape[:2]} control points of degrees {self.degree_u}, "
                                f"{self.degree_v}")
        for name, arr in (("control", c), ("knots_u", ku), ("knots_v", kv)):
            arr.flags.writeable = False
            object.__setattr__(self, name, arr)

    def _evaluate(self, u, v):
        shape = u.shape
        uf, vf = u.ravel(), v.ravel()
        bu = basis_matrix(self.knots_u, self.degree_u, uf)
        bv = basis_matrix(self.knots_v, self.degree_v, vf)
        du = basis_matrix(self.knots_u, self.degree_u, uf, 1)
        dv = basis_matrix(self.knots_v, self.degree_v, vf, 1)
        c = self.control
        tmp_v = np.einsum("ijc,pj->pic", c, bv)
        tmp_dv = np.einsum("ijc,pj->pic", c, dv)
        p = np.einsum("pi,pic->pc", bu, tmp_v)
        pu = np.einsum("pi,pic->pc", du, tmp_v)
        pv = np.einsum("pi,pic->pc", bu, tmp_dv)
        return (p.reshape(shape + (3,)), pu.reshape(shape + (3,)), pv.reshape(shape + (3,)))

    def second_derivatives(self, u, v):
        """P_uu, P_uv, P_vv at scattered ``(u, v)``: three (..., 3) arrays."""
        u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
        shape, uf, vf = u.shape, u.ravel(), v.ravel()
        b = [basis_matrix(self.knots_u, self.degree_u, uf, k) for k in range(3)]
        m = [basis_matrix(self.knots_v, self.degree_v, vf, k) for k in range(3)]
        out = [np.einsum("pi,ijc,pj->pc", b[a], self.control, m[c_]).reshape(shape + (3,))
               for a, c_ in ((2, 0), (1, 1), (0, 2))]
        return tuple(out)
