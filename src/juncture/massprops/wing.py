"""Closed-form mass properties of tapered, swept wing segments (Moulton & Hunsaker eqs 16-59).

A wing segment is a straight, untwisted, uncambered panel: chord and thickness ratio vary
linearly from root to tip, the quarter-chord line is swept by a constant angle (a chordwise
shear, not a rotation), the airfoil thickness distribution ``mu(x/c)`` is the same at every
station, and dihedral is a rigid rotation about the root quarter-chord x axis.

Axes. The paper works in a wing frame with x forward (out of the leading edge), y from root to
tip of a right wing and z down, origin at the root quarter-chord. juncture's project axes are
x aft, y right, z up. The single conversion is :func:`paper_to_project` (x -> -x, z -> -z, a
180 degree rotation about y), applied once to the paper's results, never inside a formula.

Sides and the root location. The paper's wing frame has its origin at the root quarter-chord,
and a segment is placed in the aircraft by giving that point in the aircraft frame (section 2.1;
Table 2's "wing root location"). ``root_quarter_chord`` is that point, in project axes, and the
root stays exactly there for every side:

==========  ===============================================================================
side        panel
==========  ===============================================================================
"right"     root at ``root_quarter_chord``, span towards +y (delta = 1, eq 24)
"left"      root at ``root_quarter_chord``, span towards -y: the right panel mirrored in the
            xz plane *through its own root* (delta = -1, eqs 24, 26, 33, 40, 54). A left
            wing with its root at y = -0.5 has its CG at y = -0.5 - y_bar (eq 33).
"both"      the symmetric pair, as a designer gives a wing by its right half: the right
            panel at ``root_quarter_chord`` = (x, y, z) and its mirror image in the aircraft's
            plane of symmetry y = 0, a left panel with its root at (x, -y, z)
==========  ===============================================================================

Dihedral raises the tip of a left panel too (a rotation by delta Gamma about the root's x
axis). This is what the authors' code does (MMoIpy, ``wing.py`` and ``component.py``: a
segment's CG and tensor are rotated and then shifted by the root location, never mirrored;
a "both" wing mirrors its spanwise root offset ``y_offset`` for the left half).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, NamedTuple

import numpy as np

from ..errors import GeometryError
from .properties import MassProperties, combine_arrays
from .thickness import Naca4, ThicknessDistribution

__all__ = ["WingSegment", "WingSegmentsResult", "wing_segments_mass_properties",
           "paper_to_project", "wing_kappas"]

Side = Literal["right", "left", "both"]
_SIDES = ("right", "left", "both")
_PAPER_TO_PROJECT = np.diag([-1.0, 1.0, -1.0])
_MIRROR_Y = np.array([1.0, -1.0, 1.0])


def paper_to_project(cg, inertia):
    """Convert a CG and inertia tensor from the paper's wing frame to project axes.

    Paper: x forward, y spanwise, z down. Project: x aft, y right, z up. The map is
    ``R = diag(-1, 1, -1)`` (proper rotation by 180 degrees about y): ``cg -> R cg``,
    ``I -> R I R^T``, i.e. the xy and yz products of inertia change sign, xz does not.

    Parameters
    ----------
    cg : (..., 3) float
    inertia : (..., 3, 3) float

    Returns
    -------
    cg, inertia in project axes, same shapes.
    """
    d = np.diag(_PAPER_TO_PROJECT)
    return np.asarray(cg) * d, np.asarray(inertia) * np.outer(d, d)


def wing_kappas(chord_root, chord_tip, thickness_root, thickness_tip):
    """The kappa coefficients of eqs 19, 28, 29, 43-46 (arrays broadcast).

    Eq 46 as printed has ``4 c_r c_r^3``; the reading ``4 c_r c_t^3`` is used (the other three
    rows of eq 46 and the quadrature tests confirm it).

    Returns
    -------
    tuple of 7 arrays
        (kappa_a, kappa_b, kappa_c, kappa_d, kappa_e, kappa_f, kappa_g).
    """
    cr, ct = np.asarray(chord_root, dtype=float), np.asarray(chord_tip, dtype=float)
    tr, tt = np.asarray(thickness_root, dtype=float), np.asarray(thickness_tip, dtype=float)
    cr2, ct2, crct = cr * cr, ct * ct, cr * ct
    ka = tr * (3 * cr2 + 2 * crct + ct2) + tt * (cr2 + 2 * crct + 3 * ct2)                # 19
    kb = (tr * (4 * cr2 * cr + 3 * cr2 * ct + 2 * cr * ct2 + ct2 * ct)
          + tt * (cr2 * cr + 2 * cr2 * ct + 3 * cr * ct2 + 4 * ct2 * ct))                    # 28
    kc = tr * (3 * cr2 + 4 * crct + 3 * ct2) + 2 * tt * (cr2 + 3 * crct + 6 * ct2)         # 29
    kd = (tr * (cr + ct) * (2 * cr2 + crct + 2 * ct2)
          + tt * (cr2 * cr + 3 * cr2 * ct + 6 * cr * ct2 + 10 * ct2 * ct))                   # 43
    cr4, ct4, cr3ct, crct3, cr2ct2 = cr2 * cr2, ct2 * ct2, cr2 * crct, crct * ct2, crct * crct
    ke = (tr * (5 * cr4 + 4 * cr3ct + 3 * cr2ct2 + 2 * crct3 + ct4)
          + tt * (cr4 + 2 * cr3ct + 3 * cr2ct2 + 4 * crct3 + 5 * ct4))                       # 44
    kf = tr * (cr2 + 2 * crct + 2 * ct2) + tt * (cr2 + 4 * crct + 10 * ct2)                # 45
    kg = (tr ** 3 * (35 * cr4 + 20 * cr3ct + 10 * cr2ct2 + 4 * crct3 + ct4)
          + tr * tr * tt * (15 * cr4 + 20 * cr3ct + 18 * cr2ct2 + 12 * crct3 + 5 * ct4)
          + tr * tt * tt * (5 * cr4 + 12 * cr3ct + 18 * cr2ct2 + 20 * crct3 + 15 * ct4)
          + tt ** 3 * (cr4 + 4 * cr3ct + 10 * cr2ct2 + 20 * crct3 + 35 * ct4))              # 46
    return ka, kb, kc, kd, ke, kf, kg


class WingSegmentsResult(NamedTuple):
    """Mass properties of N wing segments (batch form), project axes.

    Attributes
    ----------
    mass : (N,) float
        [mass], negative for a negative density.
    volume : (N,) float
        Signed volume [length^3] (sign of the density).
    cg : (N, 3) float
        Centres of gravity [length].
    inertia : (N, 3, 3) float
        Inertia tensors about each CG [mass length^2], off-diagonal = -integral(x y dm).
    """

    mass: np.ndarray
    volume: np.ndarray
    cg: np.ndarray
    inertia: np.ndarray


def _as_v(airfoil, n):
    if airfoil is None:
        airfoil = Naca4()
    if isinstance(airfoil, ThicknessDistribution):
        v = np.asarray(airfoil.v, dtype=float)
    else:
        v = np.asarray(airfoil, dtype=float)
    if v.shape not in ((4,), (n, 4)):
        raise GeometryError(f"airfoil must be a ThicknessDistribution or v-integrals of shape "
                            f"(4,) or ({n}, 4), found shape {v.shape}")
    v = np.broadcast_to(v, (n, 4))
    if not np.all(np.isfinite(v)) or np.any(v[:, 0] <= 0):
        raise GeometryError("airfoil v-integrals must be finite with v0 > 0")
    return v[:, 0], v[:, 1], v[:, 2], v[:, 3]


def _check(ok, message, index=None):
    bad = np.flatnonzero(~np.asarray(ok))
    if bad.size:
        station = None if index is None else int(bad[0]) + 1
        raise GeometryError(message, component="wing segment", station=station)


def _right_local(b, cr, ct, tr, tt, tan_sweep, v0, v1, v2, v3):
    """Per unit density, right segment, PAPER axes, about the root quarter-chord.

    Returns volume (N,), first moments (Sx, Sy) and the tensor entries Ixx, Iyy, Izz, Pxy
    (Pxy = +integral x y dV). Eqs 18, 25, 26, 37-40.
    """
    ka, kb, kc, kd, ke, kf, kg = wing_kappas(cr, ct, tr, tt)
    vol = b / 12.0 * ka * v0                                                    # eq 18
    sx = -b / 240.0 * (3 * kb * v1 + 4 * b * kc * v0 * tan_sweep)               # eq 25
    sy = b * b / 60.0 * kc * v0                                                 # eq 26
    kfv0, kdv1, t2 = kf * v0, kd * v1, tan_sweep * tan_sweep
    ixx = b / 3360.0 * (56 * b * b * kfv0 + kg * v3)                            # eq 37
    iyy = b / 10080.0 * (84 * b * (2 * b * kfv0 * t2 + kdv1 * tan_sweep)
                         + 49 * ke * v2 + 3 * kg * v3)                          # eq 38
    izz = b / 1440.0 * (12 * b * (2 * b * (t2 + 1) * kfv0 + kdv1 * tan_sweep)
                        + 7 * ke * v2)                                          # eq 39
    pxy = -b * b / 240.0 * (4 * b * kfv0 * tan_sweep + kdv1)                    # eq 40
    return vol, sx, sy, ixx, iyy, izz, pxy


def wing_segments_mass_properties(semispan, chord_root, chord_tip, thickness_root,
                                  thickness_tip, sweep=0.0, dihedral=0.0, side="right",
                                  airfoil=None, root_quarter_chord=None, density=None,
                                  mass=None) -> WingSegmentsResult:
    """Mass properties of N wing segments at once (vectorised eqs 16-59).

    Parameters
    ----------
    semispan, chord_root, chord_tip : (N,) float or scalar
        b, c_r, c_t [length], b > 0, chords >= 0 with c_r + c_t > 0.
    thickness_root, thickness_tip : (N,) float or scalar
        Maximum thickness over chord tau_r, tau_t (0.12 for 12 %), >= 0.
    sweep, dihedral : (N,) float or scalar
        Quarter-chord sweep (positive aft) and dihedral (positive tip up) [rad].
    side : {"right", "left", "both"} or (N,) of these
        See the module docstring.
    airfoil : ThicknessDistribution or (4,) or (N, 4) float, optional
        Thickness distribution or its v-integrals (v0..v3). Default: NACA 4-digit.
    root_quarter_chord : (3,) or (N, 3) float, optional
        Root quarter-chord point of the panel, project axes [length]; default 0. For ``"left"``
        the left panel's own root; for ``"both"`` the right panel's root (the left one's is its
        mirror image (x, -y, z)). See the module docstring.
    density, mass : (N,) float or scalar
        Exactly one: density [mass / length^3] or mass of the segment (both sides together
        for ``"both"``) [mass]. Negative values model removed material.

    Returns
    -------
    WingSegmentsResult
        mass (N,), volume (N,), cg (N, 3), inertia about the CG (N, 3, 3), project axes.

    Raises
    ------
    GeometryError
        Bad shapes, non-finite or out-of-range values (names the 1-based segment index).
    """
    if (density is None) == (mass is None):
        raise GeometryError("give exactly one of density and mass", component="wing segment")
    arrays = [semispan, chord_root, chord_tip, thickness_root, thickness_tip, sweep, dihedral,
              density if mass is None else mass]
    try:
        arrays = np.broadcast_arrays(*[np.atleast_1d(np.asarray(a, dtype=float))
                                       for a in arrays])
    except ValueError as exc:
        raise GeometryError(f"wing segment arrays must broadcast to one length N: {exc}",
                            component="wing segment") from None
    b, cr, ct, tr, tt, sweep, dih, scale = (np.ravel(a) for a in arrays)
    n = b.size
    _check(np.isfinite(np.stack([b, cr, ct, tr, tt, sweep, dih, scale])).all(axis=0),
           "values must be finite", n > 1)
    _check(b > 0, "semispan must be > 0", n > 1)
    _check((cr >= 0) & (ct >= 0) & (cr + ct > 0), "chords must be >= 0, not both 0", n > 1)
    _check((tr >= 0) & (tt >= 0) & (tr + tt > 0),
           "thickness ratios must be >= 0, not both 0", n > 1)
    _check(np.abs(sweep) < np.pi / 2, "sweep must be within (-90, 90) degrees", n > 1)
    v0, v1, v2, v3 = _as_v(airfoil, n)
    side_arr = np.broadcast_to(np.asarray(side), (n,))
    _check(np.isin(side_arr, _SIDES), f"side must be one of {_SIDES}", n > 1)
    root = np.zeros(3) if root_quarter_chord is None else root_quarter_chord
    root = np.asarray(root, dtype=float)
    if root.shape not in ((3,), (n, 3)) or not np.all(np.isfinite(root)):
        raise GeometryError(f"root_quarter_chord must be finite with shape (3,) or ({n}, 3), "
                            f"found shape {root.shape}", component="wing segment")
    root = np.broadcast_to(root, (n, 3))
    both = side_arr == "both"
    delta = np.where(side_arr == "left", -1.0, 1.0)

    vol, sx, sy, ixx, iyy, izz, pxy = _right_local(b, cr, ct, tr, tt, np.tan(sweep),
                                                   v0, v1, v2, v3)
    vol_total = np.where(both, 2.0 * vol, vol)
    rho = scale if mass is None else scale / vol_total
    out = _place(rho, vol, sx, sy, ixx, iyy, izz, pxy, dih, delta, root)
    if np.any(both):
        k = np.flatnonzero(both)
        left = _place(rho[k], vol[k], sx[k], sy[k], ixx[k], iyy[k], izz[k], pxy[k], dih[k],
                      -np.ones(k.size), root[k] * _MIRROR_Y)      # the pair's left root
        m2, v2_, c2, i2 = combine_arrays(np.stack([out[0][k], left[0]], axis=1),
                                         np.stack([out[1][k], left[1]], axis=1),
                                         np.stack([out[2][k], left[2]], axis=1),
                                         np.stack([out[3][k], left[3]], axis=1), axis=1)
        out[0][k], out[1][k], out[2][k], out[3][k] = m2, v2_, c2, i2
    return WingSegmentsResult(*out)


def _place(rho, vol, sx, sy, ixx, iyy, izz, pxy, dihedral, delta, root):
    """Scale by density, shift to the CG, convert to project axes, apply side, dihedral, root.

    All (N,) except root (N, 3), the panel's own root quarter-chord in project axes, which is
    added as it is (not mirrored for delta = -1). Returns [mass, volume, cg, inertia].
    """
    n = vol.size
    m = rho * vol
    # CG and tensor about the root in paper axes for this side (delta of eq 24)
    cgx_p, cgy_p = sx / vol, delta * sy / vol
    cg_paper = np.zeros((n, 3))
    cg_paper[:, 0], cg_paper[:, 1] = cgx_p, cgy_p
    i_paper = np.zeros((n, 3, 3))
    i_paper[:, 0, 0], i_paper[:, 1, 1], i_paper[:, 2, 2] = rho * ixx, rho * iyy, rho * izz
    i_paper[:, 0, 1] = i_paper[:, 1, 0] = -rho * delta * pxy                    # eq 36
    # eq 59: about the CG (cg z = 0 in the paper frame, eq 34)
    i_paper[:, 0, 0] -= m * cgy_p * cgy_p
    i_paper[:, 1, 1] -= m * cgx_p * cgx_p
    i_paper[:, 2, 2] -= m * (cgx_p * cgx_p + cgy_p * cgy_p)
    i_paper[:, 0, 1] += m * cgx_p * cgy_p
    i_paper[:, 1, 0] = i_paper[:, 0, 1]
    cg, i_loc = paper_to_project(cg_paper, i_paper)
    # dihedral: rotation about the root x axis raising the tip (angle delta * Gamma)
    c, s = np.cos(delta * dihedral), np.sin(delta * dihedral)
    ixx_, iyy_, izz_, ixy_ = i_loc[:, 0, 0], i_loc[:, 1, 1], i_loc[:, 2, 2], i_loc[:, 0, 1]
    inertia = np.empty((n, 3, 3))
    inertia[:, 0, 0] = ixx_
    inertia[:, 1, 1] = c * c * iyy_ + s * s * izz_
    inertia[:, 2, 2] = s * s * iyy_ + c * c * izz_
    inertia[:, 0, 1] = inertia[:, 1, 0] = c * ixy_
    inertia[:, 0, 2] = inertia[:, 2, 0] = s * ixy_
    inertia[:, 1, 2] = inertia[:, 2, 1] = c * s * (iyy_ - izz_)
    cg_out = np.empty((n, 3))
    cg_out[:, 0] = cg[:, 0] + root[:, 0]
    cg_out[:, 1] = c * cg[:, 1] + root[:, 1]
    cg_out[:, 2] = s * cg[:, 1] + root[:, 2]
    return [m, np.sign(rho) * vol, cg_out, inertia]


@dataclass(frozen=True, slots=True, eq=False)
class WingSegment:
    """A straight, tapered, swept wing panel of constant density (Moulton & Hunsaker 2.1).

    Anatomy: the root section sits at ``root_quarter_chord`` with chord ``chord_root`` and
    thickness ratio ``thickness_root``; the tip section is ``semispan`` further out along the
    span (measured along y before dihedral), its quarter-chord moved aft by
    ``semispan * tan(sweep)``, with ``chord_tip`` and ``thickness_tip``. Chord and thickness
    ratio vary linearly between them; every section has the thickness distribution
    ``airfoil`` (no camber, no twist). Dihedral then rotates the panel about the x axis through
    the root quarter-chord, tip up. ``side`` chooses the span direction: ``"right"`` towards
    +y, ``"left"`` towards -y from the same root (Moulton & Hunsaker eq 24, delta = -1), or
    ``"both"``, the symmetric pair whose right panel has this root.

    Parameters
    ----------
    semispan : float
        b [length], > 0.
    chord_root, chord_tip : float
        c_r, c_t [length].
    thickness_root, thickness_tip : float
        tau_r, tau_t: maximum thickness / chord (0.12 for 12 %).
    sweep : float
        Quarter-chord sweep Lambda [rad], positive aft.
    dihedral : float
        Gamma [rad], positive tip up.
    side : {"right", "left", "both"}
    airfoil : ThicknessDistribution, optional
        Default :class:`Naca4` (traditional NACA 4-digit coefficients).
    root_quarter_chord : (3,) float
        Root quarter-chord point of the panel in project axes [length]: where the panel's root
        is, for ``"left"`` too; for ``"both"`` the right panel's root, the left panel's being
        (x, -y, z).
    name : str, optional

    Examples
    --------
    A rectangular diamond-section panel (v0 = 1/2): volume = b c^2 tau / 2.

    >>> from juncture.massprops import Diamond
    >>> w = WingSegment(2.0, 1.0, 1.0, 0.1, 0.1, airfoil=Diamond(0.5))
    >>> round(w.mass_properties(density=1.0).volume, 12)
    0.1

    A left panel keeps its root where it is given: rectangular, so its CG is half the span
    further out, at y = -0.5 - 1.

    >>> left = WingSegment(2.0, 1.0, 1.0, 0.1, 0.1, side="left", airfoil=Diamond(0.5),
    ...                    root_quarter_chord=(0.0, -0.5, 0.0))
    >>> round(float(left.mass_properties(density=1.0).cg[1]), 12)
    -1.5
    """

    semispan: float
    chord_root: float
    chord_tip: float
    thickness_root: float
    thickness_tip: float
    sweep: float = 0.0
    dihedral: float = 0.0
    side: Side = "right"
    airfoil: ThicknessDistribution | None = None
    root_quarter_chord: object = (0.0, 0.0, 0.0)
    name: str | None = None

    def __post_init__(self):
        if self.side not in _SIDES:
            raise GeometryError(f"side must be one of {_SIDES}, found {self.side!r}",
                                component=self.name or "wing segment")
        if self.airfoil is None:
            object.__setattr__(self, "airfoil", Naca4())
        elif not isinstance(self.airfoil, ThicknessDistribution):
            raise GeometryError(f"airfoil must be a ThicknessDistribution, found "
                                f"{type(self.airfoil).__name__}",
                                component=self.name or "wing segment")
        root = np.array(self.root_quarter_chord, dtype=float)
        if root.shape != (3,):
            raise GeometryError(f"root_quarter_chord must have shape (3,), found {root.shape}",
                                component=self.name or "wing segment")
        root.flags.writeable = False
        object.__setattr__(self, "root_quarter_chord", root)

    def mass_properties(self, density=None, mass=None) -> MassProperties:
        """Mass properties from a density [mass / length^3] or a mass [mass] (exactly one)."""
        try:
            r = wing_segments_mass_properties(
                self.semispan, self.chord_root, self.chord_tip, self.thickness_root,
                self.thickness_tip, self.sweep, self.dihedral, self.side, self.airfoil,
                self.root_quarter_chord, density, mass)
        except GeometryError as exc:
            raise GeometryError(exc.reason, component=self.name or "wing segment") from None
        return MassProperties(r.mass[0], r.volume[0], r.cg[0], r.inertia[0], self.name)
