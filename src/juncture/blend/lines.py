"""Blending and boundary lines of the long-strake blend (Song, Ma & Wang 2008, section 1).

The blend region on the upper side of the wing is bounded by (paper fig 1):

* AB, the blending line on the wing: the iso-line ``v = v_AB`` of the wing S2, from B
  (chord parameter ``xi_B``, nose side) to A (``xi_A``, trailing-edge side);
* CDE, the strake edge: CD straight and axial at ``(y_C, z_C)`` from C forward to D; DE a
  cubic from D (tangent to the axis, continuing CD) to E on the body, E a little above the
  strake (``nose_rise`` of the way up to G), reaching E tangent to the body and climbing, so
  that DE and FE meet at E at an angle inside the body's tangent plane (the patch W must
  have the body's normal at E);
* EFGH, the blending line on the body: GH part of the projection (along -y) onto the body of
  the wing section at the junction enlarged ``enlarge`` times about its mid-chord point; M is
  the nose of that projection, on the axial iso-line of H (closed trailing edge, no camber);
  GF the axial body iso-line from G forward to the plane of D (GF parallel to CD); FE a body
  curve from F to E, axial at F;
* free edges AH and BC, found by the construction.

All body-side lines live in the body parameter plane (u, v) = (x, section parameter), the
paper's fig 2. ``rho1(s)``, s in [0, 1], runs M (0) -> G (``s_G``) -> H (1); ``rho2`` is the
paper's "scaled copy" of rho1, read here as rho1 moved by an offset delta(s): delta = (h, 0)
(axial, aft) on M..G, so that B1's cross-boundary tangent along MG is the body's axial
direction (eq 11), then turning smoothly (C1 at G) through "down" to (-h, 0) at H, so that B2
stays regular where rho1 is axial (the section's thickest point). (A scaled copy would make
B2 degenerate there.)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import GeometryError
from .surfaces import naca_thickness

__all__ = ["BlendLines", "build_lines"]


@dataclass(frozen=True, slots=True, eq=False)
class BlendLines:
    """The blending and boundary lines, with the points A ... M (3-D, [length]).

    Attributes
    ----------
    body, wing : ConstantSectionBody, AirfoilWing
    kappa, s_g, h : float
        Enlargement factor, parameter of G on rho1, offset length of rho2 [length].
    junction : tuple
        Wing section at the body: (y, x_le, z_le, chord, chord * thickness).
    v_ab, xi_b, xi_a : float
        Wing line AB: spanwise parameter and chord parameters of B and A.
    points : dict of str to (3,) float
        A, B, C, D, E, F, G, H, M.
    v_g, v_e, x_d, x_e : float
        Body parameters of G and E, axial stations of D (plane T) and E.
    strake_dir : (3,) float
        Unit in-plane direction of the auxiliary plane S3 at C, pointing inboard.
    strake_depth : float
        Extent of S3 along ``strake_dir`` [length].
    de_tangents : (2, 3) float
        Tangents of the nose edge DE at D (axial) and at E (in the body's tangent plane).
    """

    body: object
    wing: object
    kappa: float
    s_g: float
    h: float
    junction: tuple
    v_ab: float
    xi_b: float
    xi_a: float
    points: dict
    v_g: float
    v_e: float
    x_d: float
    x_e: float
    strake_dir: object
    strake_depth: float
    de_tangents: object = None

    @property
    def _lv(self):
        return self.body.size

    # ------------------------------------------------------------------ body-side curves
    def rho1(self, s, second=False):
        """Projected enlarged section M -> H in the body parameter plane.

        Returns
        -------
        uv, uv_s : (n, 2) float
            (x, v) and its derivative with respect to s (and uv_ss if ``second``).
        """
        s = np.asarray(s, float)
        _, x_le, z_le, c, ct = self.junction
        k = self.kappa
        x = x_le + 0.5 * c + k * c * (s**2 - 0.5)
        z = z_le + k * ct * naca_thickness(s)
        v, dvdz, d2vdz2 = self.body.section.v_at_height(z)
        dz = k * ct * naca_thickness(s, 1)
        out = (np.stack([x, v], -1), np.stack([2 * k * c * s, dvdz * dz], -1))
        if second:
            d2z = k * ct * naca_thickness(s, 2)
            out += (np.stack([np.full_like(s, 2 * k * c), dvdz * d2z + d2vdz2 * dz**2], -1),)
        return out

    def _tangent_angle(self, s):
        """Angle psi of rho1 in the isotropic plane (x, L v) and d psi / ds."""
        _, d1, d2 = self.rho1(s, second=True)
        lv = self._lv
        xs, ys, xss, yss = d1[..., 0], lv * d1[..., 1], d2[..., 0], lv * d2[..., 1]
        return np.arctan2(ys, xs), (xs * yss - ys * xss) / (xs**2 + ys**2)

    def delta(self, s):
        """Offset rho2 - rho1 and its s-derivative, (n, 2) each (see module notes).

        On M..G delta = (h, 0). On G..H, with w = (s - s_G) / (1 - s_G), delta has length h
        and direction psi(s) - alpha(w) in the plane (x, L v) (L = body size): rho1's tangent
        turned clockwise by alpha, a cubic in w from psi_G (axial at G, with matching slope so
        that delta is C1) to pi + psi_H (axial, forward, at H: the free edge AH then stays in
        the wing plane). While 0 < alpha < pi, delta does not line up with rho1.
        """
        s = np.asarray(s, float)
        sg = self.s_g
        psi_g, dpsi_g = (float(x[0]) for x in self._tangent_angle(np.array([sg])))
        w = np.clip((s - sg) / (1.0 - sg), 0.0, 1.0)
        a0, a1 = psi_g, dpsi_g * (1.0 - sg)
        psi_h = float(self._tangent_angle(np.array([1.0]))[0][0])
        a3 = np.pi + psi_h
        c2, c3 = 3 * (a3 - a0) - 2 * a1, -2 * (a3 - a0) + a1
        alpha = a0 + a1 * w + c2 * w**2 + c3 * w**3
        dalpha = (a1 + 2 * c2 * w + 3 * c3 * w**2) / (1.0 - sg)
        psi, dpsi = self._tangent_angle(np.clip(s, sg, 1.0))
        after = s > sg
        phi = np.where(after, psi - alpha, 0.0)
        dphi = np.where(after, dpsi - dalpha, 0.0)
        lv = self._lv
        d = self.h * np.stack([np.cos(phi), np.sin(phi) / lv], -1)
        dd = self.h * dphi[..., None] * np.stack([-np.sin(phi), np.cos(phi) / lv], -1)
        return d, dd

    def rho2(self, s):
        """The offset copy of rho1 (paper's rho2): (uv, uv_s), (n, 2) each."""
        p, dp = self.rho1(s)
        d, dd = self.delta(s)
        return p + d, dp + dd

    def fe(self, u):
        """Body line F -> E in the body parameter plane: (uv, uv_u), u in [0, 1]."""
        u = np.asarray(u, float)
        x = self.x_d + (self.x_e - self.x_d) * u
        v = self.v_g + (self.v_e - self.v_g) * u**2
        dx = np.full_like(u, self.x_e - self.x_d)
        dv = 2 * (self.v_e - self.v_g) * u
        return np.stack([x, v], -1), np.stack([dx, dv], -1)

    def de(self, u):
        """Strake nose edge D -> E: cubic Hermite, (points, u-derivatives), (n, 3) each.

        Leaves D along the axis (continuing CD) and reaches E tangent to the body, climbing
        along the body section (``de_tangents`` holds both end tangents).
        """
        u = np.asarray(u, float)[..., None]
        d, e = self.points["D"], self.points["E"]
        t0, t1 = self.de_tangents
        h00, h10 = 1 - 3 * u**2 + 2 * u**3, u - 2 * u**2 + u**3
        h01, h11 = 3 * u**2 - 2 * u**3, -(u**2) + u**3
        p = h00 * d + h10 * t0 + h01 * e + h11 * t1
        dp = ((-6 * u + 6 * u**2) * d + (1 - 4 * u + 3 * u**2) * t0
              + (6 * u - 6 * u**2) * e + (-2 * u + 3 * u**2) * t1)
        return p, dp

    # ------------------------------------------------------------------ wing-side curves
    def rho3(self, sigma):
        """Wing line AB in the wing parameter plane (B at sigma = 0): (uv, uv_sigma)."""
        sigma = np.asarray(sigma, float)
        u = self.xi_b + (self.xi_a - self.xi_b) * sigma
        uv = np.stack([u, np.full_like(u, self.v_ab)], -1)
        duv = np.stack([np.full_like(u, self.xi_a - self.xi_b), np.zeros_like(u)], -1)
        return uv, duv

    def rho4(self, sigma, beta):
        """Offset of rho3 by beta U, U = (0, -1) (eq 6): (uv, uv_sigma)."""
        uv, duv = self.rho3(sigma)
        return uv - np.array([0.0, beta]), duv


def _check_regular(rho_a, rho_b, name):
    """Raise if the ruled parameter patch between two curves folds or degenerates."""
    s = np.linspace(0.0, 1.0, 201)
    pa, da = rho_a(s)
    pb, db = rho_b(s)
    dets = []
    for r in (0.0, 0.5, 1.0):
        ds_ = pb - pa
        dt_ = (1 - r) * da + r * db
        dets.append(ds_[:, 0] * dt_[:, 1] - ds_[:, 1] * dt_[:, 0])
    dets = np.concatenate(dets)
    if not (np.all(dets > 0) or np.all(dets < 0)):
        raise GeometryError(f"base surface {name} folds or degenerates: choose G further "
                            "forward on the enlarged section or a smaller base_offset",
                            component="blend")


def build_lines(body, wing, opts):
    """Blending and boundary lines from a body, a wing and the ``lines`` options.

    Parameters
    ----------
    body : ConstantSectionBody
    wing : AirfoilWing
    opts : mapping
        The ``lines`` section of a blend spec (see :mod:`juncture.blend.spec`); ``None``
        values are replaced by the defaults derived from wing and body documented there.

    Returns
    -------
    BlendLines

    Raises
    ------
    GeometryError
        If a line leaves the body, the strake edge lies inside the body, or a base surface
        would fold.
    """
    z_w = wing.section_at(wing.y[0])[1]
    y_j = float(body.section.evaluate(body.section.v_at_height(z_w)[0])[0])
    x_le, z_le, c, ct = wing.section_at(y_j)
    kappa = float(opts["enlarge"])
    s_g = float(opts["g_fraction"])
    h = float(opts["base_offset"] if opts["base_offset"] is not None else 0.05 * c)
    y_ab = float(opts["wing_line_y"] if opts["wing_line_y"] is not None else y_j + 0.25 * c)
    xi_b, xi_a = (float(x) for x in opts["wing_line_xi"])
    if not y_ab > y_j:
        raise GeometryError(f"wing line y ({y_ab:.6g}) must lie outboard of the junction "
                            f"({y_j:.6g})", component="blend")
    v_ab = float(wing.v_at_y(y_ab))
    tmp = BlendLines(body, wing, kappa, s_g, h, (y_j, x_le, z_le, c, ct), v_ab, xi_b, xi_a,
                     {}, 0.0, 0.0, 0.0, 0.0, np.zeros(3), 0.0)
    (m_uv, g_uv, h_uv), _ = tmp.rho1(np.array([0.0, s_g, 1.0]))
    pts = {k: body.points(*uv) for k, uv in zip("MGH", (m_uv, g_uv, h_uv), strict=True)}
    pts["B"], pts["A"] = (wing.points(u, v_ab) for u in (xi_b, xi_a))
    y_c = float(opts["strake_y"] if opts["strake_y"] is not None else
                y_j + 0.5 * (y_ab - y_j))
    z_c = float(opts["strake_z"] if opts["strake_z"] is not None else z_le)
    x_c = float(opts["strake_x"] if opts["strake_x"] is not None else pts["M"][0])
    length = float(opts["strake_length"] if opts["strake_length"] is not None else 1.5 * c)
    nose = float(opts["nose_length"] if opts["nose_length"] is not None else 0.5 * c)
    if length <= 0 or nose <= 0:
        raise GeometryError("strake_length and nose_length must be positive",
                            component="blend")
    y_body = float(body.section.evaluate(body.section.v_at_height(z_c)[0])[0])
    if not y_c > y_body:
        raise GeometryError(f"strake edge y ({y_c:.6g}) must lie outside the body "
                            f"({y_body:.6g} at z = {z_c:.6g})", component="blend")
    rise = float(opts["nose_rise"])
    if not 0.0 < rise < 1.0:
        raise GeometryError(f"nose_rise must lie in (0, 1), found {rise}", component="blend")
    z_e = z_c + rise * (float(pts["G"][2]) - z_c)
    v_e = float(body.section.v_at_height(z_e)[0])
    x_d, x_e = x_c - length, x_c - length - nose
    if x_e <= body.x_start:
        raise GeometryError(f"strake nose E (x = {x_e:.6g}) lies ahead of the body start "
                            f"({body.x_start:.6g})", component="blend")
    gam = np.radians(float(opts["plane_angle_deg"]))
    strake_dir = np.array([0.0, -np.cos(gam), -np.sin(gam)])
    pts["C"] = np.array([x_c, y_c, z_c])
    pts["D"] = np.array([x_d, y_c, z_c])
    pts["E"] = body.points(x_e, v_e)
    pts["F"] = body.points(x_d, g_uv[1])
    if x_d >= min(pts["M"][0], x_c):
        raise GeometryError("plane T (at D) must lie ahead of the strake's aft end",
                            component="blend")
    _, _, ev = body.evaluate(x_e, v_e)
    e_theta = ev / np.linalg.norm(ev)
    t0 = np.array([x_e - x_d, 0.0, 0.0])
    t1 = t0 + 1.5 * (pts["E"][2] - z_c) / e_theta[2] * e_theta
    lines = BlendLines(body, wing, kappa, s_g, h, (y_j, x_le, z_le, c, ct), v_ab, xi_b, xi_a,
                       pts, float(g_uv[1]), v_e, x_d, x_e, strake_dir, y_c - y_j,
                       np.array([t0, t1]))
    if not 0.0 < s_g < 1.0:
        raise GeometryError(f"g_fraction must lie in (0, 1), found {s_g}", component="blend")
    if lines.rho1(np.array([s_g]))[1][0, 1] <= 0:
        raise GeometryError("G must lie ahead of the thickest point of the enlarged section "
                            "(g_fraction too large)", component="blend")

    def piece(f, a, b):
        return lambda t: tuple(x * (1 if i == 0 else (b - a)) for i, x in
                               enumerate(f(a + (b - a) * t)))

    _check_regular(piece(lines.rho1, 0, s_g), piece(lines.rho2, 0, s_g), "B1")
    _check_regular(piece(lines.rho1, s_g, 1), piece(lines.rho2, s_g, 1), "B2")
    return lines
