"""Forward three-sided patch W over DEFD by thin-plate energy (Song, Ma & Wang 2008, sec 5).

The paper minimises (eq 20)

    E = integral a11 |W_u|^2 + 2 a12 W_u.W_v + a22 |W_v|^2
                 + b11 |W_uu|^2 + 2 b12 |W_uv|^2 + b22 |W_vv|^2  du dv      (f = 0)

subject to positions on DF, FE, DE and to the normals of R2 along DF and of the body along
FE, with 6-node triangles on a triangle, then interpolates u-iso-lines through the nodes and
skins them into a four-sided surface that degenerates to E at u = 1.

Choice made here (documented deviation): the unknown is that four-sided surface itself, a
bicubic B-spline W(u, w) on the unit square with its edge u = 1 collapsed to E (u = 0: DF from
F to D; w = 0: FE from F to E; w = 1: DE from D to E). Bicubic B-splines are C1, so the
bending terms are conforming (6-node triangles are only C0, the second derivatives jump across
element edges), the energy is evaluated exactly (Gauss-Legendre, 4 points per span) as a sum of
Kronecker products of 1-D matrices, and no interpolation/skinning step is needed. The energy
of eq 20 is taken in the square's (u, w) parameters with the paper's coefficients (all 5).

Constraints: boundary control rows interpolate the edge curves at the Greville abscissae; the
cross-boundary derivative along DF and along FE is made tangent to R2 / the body
(``n . W_u = 0``, ``n . W_w = 0``) at the interior Greville abscissae (Lagrange multipliers,
one sparse KKT solve with scipy.sparse). Finally a Coons-type correction with Hermite blends
(zero slope at the edges) adds the small residual between each spline edge and the exact edge
curve, so the patch matches DF, FE and DE exactly while its cross-boundary derivatives change
only by the derivative of that residual.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..errors import ConvergenceError, SpecError
from .bspline import BSplineSurface, basis_matrix, clamped_knots, greville, interpolate_curve
from .surfaces import ParametricSurface, unit

__all__ = ["PatchEdges", "ThinPlatePatch", "patch_edges", "solve_patch", "seam_angles",
           "refinement_study"]


@dataclass(frozen=True, slots=True, eq=False)
class PatchEdges:
    """Exact edge curves of W and the normals they impose.

    Each callable takes a parameter array (n,) in [0, 1] and returns ``(points, derivative)``,
    (n, 3) each; ``*_normal`` return unit normals (n, 3). ``de_normal`` (optional) is the
    designer's tangent plane along the free edge DE (not in the paper, see solve_patch).
    """

    df: object
    df_normal: object
    fe: object
    fe_normal: object
    de: object
    e: object
    de_normal: object = None


def patch_edges(lines, strake):
    """Edges of W from the blending lines and the strake R2: DF(w) = R2(1, 1 - w) etc."""
    body = lines.body

    def df(w):
        w = np.asarray(w, float)
        p, _, pt = strake.evaluate(np.ones_like(w), 1.0 - w)
        return p, -pt

    def df_normal(w):
        w = np.asarray(w, float)
        return strake.normals(np.ones_like(w), 1.0 - w)

    def fe(u):
        uv, duv = lines.fe(u)
        p, pu, pv = body.evaluate(uv[..., 0], uv[..., 1])
        return p, pu * duv[..., :1] + pv * duv[..., 1:]

    def fe_normal(u):
        uv, _ = lines.fe(u)
        return body.outward_normals(uv[..., 0], uv[..., 1])

    n_d = strake.normals(np.array([1.0]), np.array([0.0]))[0]
    n_e = body.outward_normals(np.array(lines.x_e), np.array(lines.v_e))
    if np.dot(n_d, n_e) < 0:
        n_d = -n_d

    def de_normal(u):
        u = np.asarray(u, float)
        _, t = lines.de(u)
        t = unit(t)
        b = (3 * u**2 - 2 * u**3)[..., None]
        m = (1 - b) * n_d + b * n_e
        return unit(m - np.sum(m * t, -1, keepdims=True) * t)

    return PatchEdges(df, df_normal, fe, fe_normal, lines.de, np.asarray(lines.points["E"]),
                      de_normal)


def _h0(x):
    return 1 - 3 * x**2 + 2 * x**3, -6 * x + 6 * x**2


def _h1(x):
    return 3 * x**2 - 2 * x**3, 6 * x - 6 * x**2


@dataclass(frozen=True, slots=True, eq=False)
class ThinPlatePatch(ParametricSurface):
    """W(u, w): the thin-plate B-spline plus the Coons correction onto the exact edges.

    Attributes
    ----------
    spline : BSplineSurface
        The energy minimiser (exact B-spline, degenerate at u = 1).
    edges : PatchEdges
    energy : float
        Value of the discrete energy (eq 20) of ``spline``.
    elements : int
        Spans per side.
    """

    spline: object
    edges: object
    energy: float
    elements: int

    def edge_residuals(self, n=201):
        """Largest distance between each spline edge and its exact curve: dict."""
        x = np.linspace(0.0, 1.0, n)
        z, o = np.zeros_like(x), np.ones_like(x)
        return {"DF": float(np.max(np.linalg.norm(self.edges.df(x)[0] -
                                                  self.spline.points(z, x), axis=-1))),
                "FE": float(np.max(np.linalg.norm(self.edges.fe(x)[0] -
                                                  self.spline.points(x, z), axis=-1))),
                "DE": float(np.max(np.linalg.norm(self.edges.de(x)[0] -
                                                  self.spline.points(x, o), axis=-1)))}

    def _evaluate(self, u, w):
        p, pu, pw = self.spline.evaluate(u, w)
        z, o = np.zeros_like(u), np.ones_like(u)
        sd, sd_u, sd_w = self.spline.evaluate(z, w)
        sf, sf_u, _ = self.spline.evaluate(u, z)
        se, se_u, _ = self.spline.evaluate(u, o)
        df, ddf = self.edges.df(w)
        fe, dfe = self.edges.fe(u)
        de, dde = self.edges.de(u)
        r_df, r_df_w = df - sd, ddf - sd_w
        r_fe, r_fe_u = fe - sf, dfe - sf_u
        r_de, r_de_u = de - se, dde - se_u
        a0, da0 = (x[..., None] for x in _h0(u))
        b0, db0 = (x[..., None] for x in _h0(w))
        b1, db1 = (x[..., None] for x in _h1(w))
        p = p + a0 * r_df + b0 * r_fe + b1 * r_de
        pu = pu + da0 * r_df + b0 * r_fe_u + b1 * r_de_u
        pw = pw + a0 * r_df_w + db0 * r_fe + db1 * r_de
        return p, pu, pw


def _gram(knots, degree, a, b):
    """1-D matrix of integrals of N_i^(a) N_k^(b) over [0, 1] (exact Gauss-Legendre)."""
    spans = np.unique(knots)
    xg, wg = np.polynomial.legendre.leggauss(degree + 1)
    lo, hi = spans[:-1, None], spans[1:, None]
    x = (0.5 * (hi - lo) * xg + 0.5 * (hi + lo)).ravel()
    wq = (0.5 * (hi - lo) * wg).ravel()
    na = basis_matrix(knots, degree, x, a)
    nb = basis_matrix(knots, degree, x, b)
    return (na * wq[:, None]).T @ nb


def _energy_matrix(knots, stretch, bend):
    """Sparse (N^2, N^2) matrix K with E = sum over coordinates of c^T K c (eq 20)."""
    g = {(a, b): sp.csr_matrix(_gram(knots, 3, a, b)) for a in range(3) for b in range(3)}
    a11, a12, a22 = stretch
    b11, b12, b22 = bend
    kron = sp.kron
    k = (a11 * kron(g[1, 1], g[0, 0]) + a12 * (kron(g[1, 0], g[0, 1]) + kron(g[0, 1], g[1, 0]))
         + a22 * kron(g[0, 0], g[1, 1]) + b11 * kron(g[2, 2], g[0, 0])
         + 2 * b12 * kron(g[1, 1], g[1, 1]) + b22 * kron(g[0, 0], g[2, 2]))
    return k.tocsr()


def solve_patch(edges, elements=12, stretch=(5.0, 5.0, 5.0), bend=(5.0, 5.0, 5.0),
                de_normal=True):
    """Minimise the thin-plate energy of W under the position and normal constraints.

    Parameters
    ----------
    edges : PatchEdges
    elements : int
        Bicubic spans per side (control net (elements + 3)^2).
    stretch, bend : 3 floats
        (a11, a12, a22) and (b11, b12, b22) of eq 20; paper values all 5.
    de_normal : bool
        Also make W tangent along the free edge DE to a plane turning from R2's at D to the
        body's at E (``edges.de_normal``). Not in the paper (DE carries positions only), but
        without it the minimiser curls over near E, where DE runs close to the body.

    Returns
    -------
    ThinPlatePatch

    Raises
    ------
    SpecError
        For fewer than 2 spans or non-positive definite coefficients.
    ConvergenceError
        If the sparse KKT solve fails.
    """
    if int(elements) < 2:
        raise SpecError(f"patch.elements must be at least 2, found {elements}")
    b11, b12, b22 = bend
    if not (b11 > 0 and b22 > 0 and b12 >= 0):
        raise SpecError(f"patch.bend coefficients must be positive, found {list(bend)}")
    n_el = int(elements)
    knots = clamped_knots(n_el, 3)
    n = n_el + 3
    g = greville(knots, 3)
    ctrl = np.zeros((n, n, 3))
    fixed = np.zeros((n, n), bool)
    ctrl[0, :] = interpolate_curve(lambda x: edges.df(x)[0], knots)
    ctrl[:, 0] = interpolate_curve(lambda x: edges.fe(x)[0], knots)
    ctrl[:, -1] = interpolate_curve(lambda x: edges.de(x)[0], knots)
    ctrl[-1, :] = edges.e
    fixed[0, :] = fixed[-1, :] = fixed[:, 0] = fixed[:, -1] = True

    # Normal constraints at interior Greville abscissae: n . (P_1j - P_0j) M_j(w_k) = 0 (DF)
    # and n . (P_i1 - P_i0) N_i(u_k) = 0 (FE).
    inner = g[1:-1]
    m = basis_matrix(knots, 3, inner)  # (n - 2, n)
    rows, cols, vals = [], [], []
    ni = len(inner)
    use_de = de_normal and edges.de_normal is not None
    nd, nf = edges.df_normal(inner), edges.fe_normal(inner)
    ne = edges.de_normal(inner) if use_de else None
    for k in range(ni):
        for j in np.flatnonzero(m[k]):
            for c in range(3):
                rows += [k, k]
                cols += [3 * (1 * n + j) + c, 3 * (0 * n + j) + c]
                vals += [m[k, j] * nd[k, c], -m[k, j] * nd[k, c]]
                rows += [ni + k, ni + k]
                cols += [3 * (j * n + 1) + c, 3 * (j * n + 0) + c]
                vals += [m[k, j] * nf[k, c], -m[k, j] * nf[k, c]]
                if use_de:
                    rows += [2 * ni + k, 2 * ni + k]
                    cols += [3 * (j * n + n - 1) + c, 3 * (j * n + n - 2) + c]
                    vals += [m[k, j] * ne[k, c], -m[k, j] * ne[k, c]]
    cmat = sp.csr_matrix((vals, (rows, cols)), shape=((3 if use_de else 2) * ni, 3 * n * n))
    k1 = _energy_matrix(knots, stretch, bend)
    k3 = sp.kron(k1, sp.identity(3)).tocsr()
    fix3 = np.repeat(fixed.ravel(), 3)
    free = np.flatnonzero(~fix3)
    fx = np.flatnonzero(fix3)
    x_fixed = ctrl.reshape(-1)[fx]
    kff = k3[free][:, free]
    rhs_e = -(k3[free][:, fx] @ x_fixed)
    cf = cmat[:, free]
    rhs_c = -(cmat[:, fx] @ x_fixed)
    kkt = sp.bmat([[kff, cf.T], [cf, None]], format="csc")
    sol = spla.spsolve(kkt, np.concatenate([rhs_e, rhs_c]))
    if not np.all(np.isfinite(sol)):
        raise ConvergenceError("thin-plate KKT system is singular", component="blend patch")
    x = ctrl.reshape(-1).copy()
    x[free] = sol[:len(free)]
    energy = float(x @ (k3 @ x))
    spline = BSplineSurface(x.reshape(n, n, 3), knots, knots, 3, 3)
    return ThinPlatePatch(spline, edges, energy, n_el)


def seam_angles(patch, n=401):
    """Largest normal angles [deg] of W against R2 along DF and the body along FE."""
    x = np.linspace(0.0, 1.0 - 1e-3, n)
    z = np.zeros_like(x)
    nw_df = patch.normals(z, x)
    nw_fe = patch.normals(x, z)

    def ang(a, b):
        cross = np.linalg.norm(np.cross(a, b), axis=-1)
        return float(np.degrees(np.max(np.arctan2(cross, np.abs(np.sum(a * b, -1))))))

    return {"DF": ang(nw_df, unit(patch.edges.df_normal(x))),
            "FE": ang(nw_fe, unit(patch.edges.fe_normal(x)))}


def refinement_study(edges, levels=(4, 8, 16, 32), stretch=(5.0, 5.0, 5.0),
                     bend=(5.0, 5.0, 5.0), de_normal=True):
    """Energy and seam errors of W under uniform refinement.

    Returns
    -------
    list of dict
        One row per level: ``elements``, ``energy``, ``energy_change`` (|E - E_previous|,
        ``None`` on the first row), ``angle_df_deg``, ``angle_fe_deg`` (largest normal
        angles against R2 and the body) and ``edge_gap`` (largest distance of the spline's
        edges from the exact curves, before the Coons correction) [length].
    """
    rows, prev = [], None
    for n_el in levels:
        w = solve_patch(edges, n_el, stretch, bend, de_normal)
        ang = seam_angles(w)
        rows.append({"elements": int(n_el), "energy": w.energy,
                     "energy_change": None if prev is None else abs(w.energy - prev),
                     "angle_df_deg": ang["DF"], "angle_fe_deg": ang["FE"],
                     "edge_gap": max(w.edge_residuals().values())})
        prev = w.energy
    return rows
