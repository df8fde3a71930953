"""Mass properties of a rotor: hub cylinder plus blades spread over a disk (Moulton & Hunsaker 2.2).

The rotor is time-averaged: the N blades (straight, untwisted, uncambered, chord and thickness
ratio linear in radius) are replaced by an axisymmetric disk whose thickness along the axis,
``h(r) = N tau(r) c(r)^2 v0 / (2 pi r)`` (eq 70), gives at each radius the same cross-section
area as the blades. The hub is a solid cylinder of radius ``r_r`` (the blade root) and height
``h_h``. Both are centred on the rotor centre, so the CG is the centre.

Integrals (eq 73), with ``x`` along the axis and ``r`` the radius:

* ``T000 = N V_b`` (eq 79), ``T020 = T002 = pi integral r^3 h dr`` (eq 82, gamma_l..gamma_o of
  eqs 94-97),
* ``T200 = 2 pi integral r h^3 / 12 dr = N^3 v0^3 / (48 pi^2) J`` with
  ``J = integral_{r_r}^{r_t} tau(r)^3 c(r)^6 / r^2 dr``. Eqs 80-93 (the gamma_a..gamma_k closed
  form) are missing from our copy of the paper; :func:`rotor_disk_integrals` derives J from eq 73
  with eq 70 instead.

J's closed form expands ``tau^3 c^6`` (degree 9) in powers of r: ``p0 (1/r_r - 1/r_t) +
p1 ln(r_t/r_r) + sum_k p_k (r_t^(k-1) - r_r^(k-1)) / (k - 1)``. Its terms cancel as r_r -> r_t
(relative error grows like ``(1 - r_r/r_t)^-9`` eps: 4e-14 at r_r/r_t = 0.3, 4e-5 at 0.9), as
does the paper's form with its ``(r_r - r_t)^9`` denominator. So above ``r_r/r_t = 0.25``
(:data:`CLOSED_FORM_MAX_RATIO`) J and T020 are integrated by 40-point Gauss-Legendre in the
blade coordinate ``s = (r - r_r)/(r_t - r_r)``: the integrand is a polynomial over
``(r_r + (r_t - r_r) s)^2`` whose pole lies at least 5/3 half-intervals away, so 40 points
converge to machine precision (error ~ 3^-80).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.polynomial import polynomial as npoly

from ..errors import GeometryError
from .properties import MassProperties
from .thickness import Naca4, ThicknessDistribution
from .wing import wing_kappas

__all__ = ["Rotor", "rotor_disk_integrals", "CLOSED_FORM_MAX_RATIO"]

#: Largest hub-to-tip radius ratio r_r / r_t at which the closed forms are used.
CLOSED_FORM_MAX_RATIO = 0.25

_GL_X, _GL_W = np.polynomial.legendre.leggauss(40)
_GL_S, _GL_W = 0.5 * (_GL_X + 1.0), 0.5 * _GL_W


def _gammas_lmno(cr, ct, tr, tt):
    """gamma_l, gamma_m, gamma_n, gamma_o of eqs 94-97."""
    gl = -tr * (10 * cr * cr + 4 * cr * ct + ct * ct) - tt * (2 * cr * cr + 2 * cr * ct + ct * ct)
    gm = tr * (6 * cr * cr - ct * ct) - tt * (2 * cr * ct + 3 * ct * ct)
    gn = tr * (3 * cr * cr + 2 * cr * ct) + tt * (cr * cr - 6 * ct * ct)
    go = tr * (cr * cr + 2 * cr * ct + 2 * ct * ct) + tt * (cr * cr + 4 * cr * ct + 10 * ct * ct)
    return gl, gm, gn, go


def _j_closed(ratio, cr, ct, tr, tt):
    """r_t * J by the closed form in rho = r / r_t on [ratio, 1]."""
    span = 1.0 - ratio
    bc, bt = (ct - cr) / span, (tt - tr) / span
    p = npoly.polymul(npoly.polypow([tr - bt * ratio, bt], 3),
                      npoly.polypow([cr - bc * ratio, bc], 6))
    p = np.concatenate([p, np.zeros(10 - p.size)])
    k = np.arange(2, 10)
    log_ratio = np.log(ratio)
    return (p[0] * (1.0 / ratio - 1.0) - p[1] * log_ratio
            + np.sum(p[2:] * -np.expm1((k - 1) * log_ratio) / (k - 1)))


def _j_quadrature(ratio, cr, ct, tr, tt):
    """r_t * J by 40-point Gauss-Legendre in s."""
    s = _GL_S
    rho = ratio + (1.0 - ratio) * s
    f = (tr + (tt - tr) * s) ** 3 * (cr + (ct - cr) * s) ** 6 / (rho * rho)
    return (1.0 - ratio) * np.dot(_GL_W, f)


def rotor_disk_integrals(blades, r_root, r_tip, chord_root, chord_tip, thickness_root,
                         thickness_tip, v0, method: Literal["auto", "closed",
                                                            "quadrature"] = "auto"):
    """The disk integrals T000, T020 (= T002) and T200 of eq 73.

    Parameters
    ----------
    blades : int
        N_b.
    r_root, r_tip : float
        Blade root (hub) and tip radii [length], 0 < r_root < r_tip.
    chord_root, chord_tip, thickness_root, thickness_tip : float
        Blade chord [length] and thickness ratio at root and tip.
    v0 : float
        v0 of the blade airfoil (eq 20).
    method : {"auto", "closed", "quadrature"}
        ``"auto"`` uses the closed forms (eqs 79, 82 and J) up to r_root / r_tip =
        :data:`CLOSED_FORM_MAX_RATIO`, Gauss-Legendre above.

    Returns
    -------
    T000 [length^3], T020 [length^5], T200 [length^5] : float
    """
    rr, rt, cr, ct, tr, tt = (float(a) for a in (r_root, r_tip, chord_root, chord_tip,
                                                  thickness_root, thickness_tip))
    n, ratio, span = float(blades), rr / rt, rt - rr
    ka = wing_kappas(cr, ct, tr, tt)[0]
    t000 = n * ka * v0 * span / 12.0                                            # eq 79
    if method not in ("auto", "closed", "quadrature"):
        raise GeometryError(f"method must be 'auto', 'closed' or 'quadrature', found {method!r}")
    closed = method == "closed" or (method == "auto" and ratio <= CLOSED_FORM_MAX_RATIO)
    if closed:
        gl, gm, gn, go = _gammas_lmno(cr, ct, tr, tt)
        t020 = n * v0 / 120.0 * (rr ** 3 * gl + rr * rr * rt * gm + rr * rt * rt * gn
                                 + rt ** 3 * go)                                # eq 82
        j = _j_closed(ratio, cr, ct, tr, tt) / rt
    else:
        s = _GL_S
        r = rr + span * s
        t020 = 0.5 * n * v0 * span * np.dot(_GL_W, r * r * (tr + (tt - tr) * s)
                                            * (cr + (ct - cr) * s) ** 2)
        j = _j_quadrature(ratio, cr, ct, tr, tt) / rt
    t200 = n ** 3 * v0 ** 3 / (48.0 * np.pi ** 2) * j
    return t000, float(t020), float(t200)


@dataclass(frozen=True, slots=True, eq=False)
class Rotor:
    """A rotor or propeller: hub cylinder and N blades averaged over a disk (eqs 60-82).

    Anatomy: a solid hub cylinder of diameter ``hub_diameter`` and height ``hub_height`` along
    ``axis``, centred on ``center``; blades from the hub radius to ``diameter / 2``, chord and
    thickness ratio linear in radius, thickness distribution ``airfoil``, spread over a disk
    (module docstring). Pitch and camber are neglected; the CG is the centre.

    Parameters
    ----------
    blades : int
        N_b >= 1.
    diameter, hub_diameter : float
        d_r > d_h > 0 [length].
    hub_height : float
        h_h >= 0 [length].
    chord_root, chord_tip : float
        c_r, c_t [length].
    thickness_root, thickness_tip : float
        tau_r, tau_t (maximum thickness / chord).
    airfoil : ThicknessDistribution, optional
        Default :class:`Naca4`.
    center : (3,) float
        Rotor centre, project axes [length].
    axis : (3,) float
        Rotation axis (normalised on input); default x.
    name : str, optional
    """

    blades: int
    diameter: float
    hub_diameter: float
    hub_height: float
    chord_root: float
    chord_tip: float
    thickness_root: float
    thickness_tip: float
    airfoil: ThicknessDistribution | None = None
    center: object = (0.0, 0.0, 0.0)
    axis: object = (1.0, 0.0, 0.0)
    name: str | None = None

    def __post_init__(self):
        who = self.name or "rotor"
        if isinstance(self.blades, bool) or int(self.blades) != self.blades or self.blades < 1:
            raise GeometryError(f"blades must be a whole number >= 1, found {self.blades!r}",
                                component=who)
        object.__setattr__(self, "blades", int(self.blades))
        vals = [self.diameter, self.hub_diameter, self.hub_height, self.chord_root,
                self.chord_tip, self.thickness_root, self.thickness_tip]
        if not np.all(np.isfinite(np.asarray(vals, dtype=float))):
            raise GeometryError(f"rotor dimensions must be finite, found {vals}", component=who)
        if not 0 < self.hub_diameter < self.diameter:
            raise GeometryError(f"expected 0 < hub_diameter < diameter, found hub_diameter = "
                                f"{self.hub_diameter}, diameter = {self.diameter}", component=who)
        if self.hub_height < 0:
            raise GeometryError(f"hub_height must be >= 0, found {self.hub_height}",
                                component=who)
        if min(self.chord_root, self.chord_tip, self.thickness_root, self.thickness_tip) < 0 or \
                self.chord_root + self.chord_tip <= 0 or \
                self.thickness_root + self.thickness_tip <= 0:
            raise GeometryError("blade chords and thickness ratios must be >= 0, not both zero",
                                component=who)
        if self.airfoil is None:
            object.__setattr__(self, "airfoil", Naca4())
        elif not isinstance(self.airfoil, ThicknessDistribution):
            raise GeometryError(f"airfoil must be a ThicknessDistribution, found "
                                f"{type(self.airfoil).__name__}", component=who)
        center = np.array(self.center, dtype=float)
        axis = np.array(self.axis, dtype=float)
        if center.shape != (3,) or axis.shape != (3,) or not np.all(np.isfinite(axis)) \
                or not np.all(np.isfinite(center)) or np.linalg.norm(axis) == 0:
            raise GeometryError(f"center and axis must be finite 3-vectors, axis non-zero; "
                                f"found {center.tolist()}, {axis.tolist()}", component=who)
        axis = axis / np.linalg.norm(axis)
        center.flags.writeable = axis.flags.writeable = False
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "axis", axis)

    @property
    def hub_volume(self):
        """Hub volume pi h_h r_r^2 (eq 63) [length^3]."""
        return np.pi * self.hub_height * (0.5 * self.hub_diameter) ** 2

    @property
    def blade_volume(self):
        """Volume of all blades N_b V_b (eqs 64, 65) [length^3]."""
        return self._integrals()[0]

    def _integrals(self):
        return rotor_disk_integrals(self.blades, 0.5 * self.hub_diameter, 0.5 * self.diameter,
                                    self.chord_root, self.chord_tip, self.thickness_root,
                                    self.thickness_tip, float(self.airfoil.v[0]))

    def _densities(self, density, mass, hub_density, hub_mass, blade_density, blade_mass):
        who = self.name or "rotor"
        v_h, v_b = self.hub_volume, self.blade_volume
        parts = (hub_density, hub_mass, blade_density, blade_mass)
        if mass is not None:
            if density is not None or any(p is not None for p in parts):
                raise GeometryError("a total mass cannot be combined with other densities or "
                                    "masses; give mass alone, or per-part values", component=who)
            return (mass / (v_h + v_b),) * 2

        def one(dens, m, vol, part):
            if dens is not None and m is not None:
                raise GeometryError(f"give {part}_density or {part}_mass, not both",
                                    component=who)
            if m is not None:
                if vol == 0:
                    raise GeometryError(f"{part}_mass given but the {part} has zero volume",
                                        component=who)
                return m / vol
            if dens is not None:
                return dens
            if density is None:
                raise GeometryError(f"no density for the {part}: give density, mass, "
                                    f"{part}_density or {part}_mass", component=who)
            return density

        return (float(one(hub_density, hub_mass, v_h, "hub")),
                float(one(blade_density, blade_mass, v_b, "blade")))

    def mass_properties(self, density=None, mass=None, *, hub_density=None, hub_mass=None,
                        blade_density=None, blade_mass=None) -> MassProperties:
        """Mass properties of hub + blades, project axes.

        Give ``density`` [mass / length^3] or total ``mass`` [mass] (one density for both
        parts, found from the total volume, eq 65), or per-part values as Table 6 of the paper
        does (``hub_density`` and ``blade_mass``); a per-part value overrides ``density`` for
        its part.

        Returns
        -------
        MassProperties
            CG at :attr:`center`; inertia ``I_t E + (I_a - I_t) a a^T`` with I_a, I_t the
            axial and transverse moments of eqs 67, 75, 76.
        """
        rho_h, rho_b = self._densities(density, mass, hub_density, hub_mass, blade_density,
                                       blade_mass)
        t000, t020, t200 = self._integrals()
        rr, hh = 0.5 * self.hub_diameter, self.hub_height
        m_h, m_b = rho_h * self.hub_volume, rho_b * t000                            # eq 78
        ia = 0.5 * m_h * rr * rr + rho_b * 2.0 * t020                               # 67, 75
        it = m_h * (3 * rr * rr + hh * hh) / 12.0 + rho_b * (t200 + t020)           # 67, 76
        a = self.axis
        inertia = it * np.eye(3) + (ia - it) * np.outer(a, a)
        volume = np.sign(rho_h) * self.hub_volume + np.sign(rho_b) * t000
        return MassProperties(m_h + m_b, volume, self.center, inertia, self.name)
