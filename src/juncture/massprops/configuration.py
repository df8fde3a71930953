"""Mass properties of a whole Configuration: every component as a solid of uniform density.

Each component is integrated as the model itself describes it, with Gauss-Legendre rules whose
degree covers the integrand exactly (up to rounding):

* **Wing-like** (wing, canard, tail, fin, pylon). Between sections ``k`` and ``k + 1`` a point
  of either surface at span parameter ``lam`` and chord fraction ``f`` is the straight blend
  ``(1 - lam) C_k(f) + lam C_k+1(f)`` (linear loft). Both surfaces share x and the span
  coordinate at equal ``(lam, f)``; only the thickness coordinate ``t`` differs, so the solid
  is ``t_lo(lam, f) <= t <= t_up(lam, f)`` over the planform, with area element
  ``c(lam) ds df``. The t-integrals are done in closed form (``t_up - t_lo``,
  ``(t_up^2 - t_lo^2) / 2``, ``(t_up^3 - t_lo^3) / 3``). What remains is a polynomial of
  degree <= 4 in ``lam`` and, on each interval between chordwise stations where the offsets are
  cubic (PCHIP) or linear, of degree <= 9 in ``f``: 3 Gauss points in ``lam`` (exact to degree
  5) and 5 per chordwise interval (exact to degree 9).
* **Circular body**. A slice at x is a disc of radius r(x) about (y_c, z_c(x)), with r and z_c
  cubic (PCHIP) or linear between stations. Volume, first and second moments are integrals
  of ``pi r^2``, ``pi r^2 x``, ``pi r^2 z_c``, ``pi r^2 x^2``, ``pi r^2 z_c^2 + pi r^4 / 4``,
  ...: degree <= 12 in x on each station interval, 7 Gauss points (exact to degree 13).
* **Arbitrary body**. The half-section at x is the deck's polyline (its points joined by
  straight lines, blended linearly in x between stations: :class:`ArbitraryBody`, nothing
  resampled), closed across the plane of symmetry (top point to (0, z_top), down y = 0 to
  (0, z_bottom), back to the bottom point), as :meth:`ArbitraryBody.area_at` closes it.
  Polygon area and moments (Green's theorem) are polynomials of degree <= 2, 3, 4 in the
  vertex coordinates, hence <= 4 in x with the x weights: 3 Gauss points per interval
  (exact to degree 5).

Halves and images (``Configuration.symmetric`` true, as every wave-drag deck): a
``mirrored`` component contributes itself plus its mirror image in the x-z plane; a centre-line
body (not mirrored) is described by its y >= 0 half but is a whole solid (a circular body's
disc is whole anyway; an arbitrary body's half-section is doubled). An arbitrary body is
always whole in this sense: with ``mirrored`` set it is still its half-section plus the mirror
image. With ``symmetric`` false nothing is mirrored and an arbitrary body is its half-section.

Overlaps are not removed: each component is integrated as given, so where a wing root is
buried in the fuselage (or a pylon in a pod) that volume is counted in both.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..errors import GeometryError, JunctureWarning
from ..model.airfoil import interpolate_chordwise, surface_offsets
from ..model.body import ArbitraryBody, CircularBody
from ..model.configuration import Configuration
from ..model.winglike import WingLike
from .properties import MassProperties

__all__ = ["configuration_mass_properties", "component_mass_properties",
           "GAUSS_POINTS"]

#: Gauss-Legendre points per piece: wing span parameter, wing chordwise interval, circular-body
#: station interval, arbitrary-body station interval (see the module docstring for degrees).
GAUSS_POINTS = {"span": 3, "chord": 5, "circular": 7, "arbitrary": 3}


def _gauss(n):
    """n-point Gauss-Legendre nodes and weights on [0, 1]."""
    x, w = np.polynomial.legendre.leggauss(int(n))
    return 0.5 * (x + 1.0), 0.5 * w


def _on_intervals(edges, n):
    """Gauss nodes and weights on every interval of increasing ``edges``, flattened."""
    u, w = _gauss(n)
    h = np.diff(edges)
    return (edges[:-1, None] + h[:, None] * u).ravel(), (h[:, None] * w).ravel()


def _props(volume, first, second, ref, name, component):
    """Unit-density MassProperties from integrals about ``ref``.

    ``first`` (3,) = integral (r - ref) dV, ``second`` (3, 3) = integral (r - ref)(r - ref)^T dV.
    """
    if volume < 0:
        raise GeometryError(f"integrates to a negative volume ({volume:.6g}); expected its "
                            "upper surface above its lower one", component)
    if volume == 0:
        warnings.warn(f"{component}: has no volume (zero thickness or radius); it contributes "
                      "no mass", JunctureWarning, stacklevel=3)
        return MassProperties.zero(name)
    d = first / volume
    central = second - volume * np.outer(d, d)
    inertia = np.trace(central) * np.eye(3) - central
    return MassProperties(volume, volume, ref + d, inertia, name)


def _winglike_unit(w, n_span=None, n_chord=None):
    """Unit-density mass properties of one wing-like component (no image)."""
    n_span = GAUSS_POINTS["span"] if n_span is None else n_span
    n_chord = GAUSS_POINTS["chord"] if n_chord is None else n_chord
    sa, ta = w.span_axis, w.thickness_axis
    f, wf = _on_intervals(w.x_over_c / 100.0, n_chord)                   # (m,)
    offsets = interpolate_chordwise(
        w.x_over_c, surface_offsets(w.camber, w.upper, w.lower, w.chord), f, w.chordwise)
    lam, wl = _gauss(n_span)                                            # (q,)
    ref = w.le[0]
    le = w.le - ref
    blend = np.stack([1.0 - lam, lam], axis=-1)                         # (q, 2)
    pair = np.stack([np.arange(w.n_sections - 1), np.arange(1, w.n_sections)], axis=-1)
    le_l = np.einsum("qa,pai->pqi", blend, le[pair])                    # (P, q, 3)
    chord_l = np.einsum("qa,pa->pq", blend, w.chord[pair])              # (P, q)
    off_l = np.einsum("qa,spam->spqm", blend, offsets[:, pair])         # (2, P, q, m)
    ds = np.diff(w.span_stations)                                       # (P,) > 0
    weight = (ds[:, None, None] * wl[None, :, None] * wf[None, None, :]
              * chord_l[..., None])                                     # (P, q, m)
    t_up = le_l[..., ta, None] + off_l[0]
    t_lo = le_l[..., ta, None] + off_l[1]
    h = t_up - t_lo
    t1 = 0.5 * (t_up * t_up - t_lo * t_lo)
    t2 = (t_up ** 3 - t_lo ** 3) / 3.0
    r = np.zeros(h.shape + (3,))
    r[..., 0] = le_l[..., 0, None] + chord_l[..., None] * f
    r[..., sa] = le_l[..., sa, None]
    r = r.reshape(-1, 3)
    wh, wt1 = (weight * h).ravel(), (weight * t1).ravel()
    volume = wh.sum()
    first = wh @ r
    first[ta] = wt1.sum()
    second = np.einsum("k,ki,kj->ij", wh, r, r)
    cross = wt1 @ r                                                     # cross[ta] == 0
    second[ta, :] += cross
    second[:, ta] += cross
    second[ta, ta] = (weight * t2).sum()
    return _props(volume, first, second, ref, w.name, w.name)


def _circular_unit(b, n=None):
    """Unit-density mass properties of a circular body (the whole disc at every x, no image)."""
    n = GAUSS_POINTS["circular"] if n is None else n
    edges = np.unique(b.x_global)
    xq, wq = _on_intervals(edges, n)
    r = b.radius_at(xq)
    c = b.center_at(xq)
    ref = np.array([edges[0], b.origin[1], b.origin[2]])
    d = np.stack([xq - ref[0], c[:, 0] - ref[1], c[:, 1] - ref[2]], axis=-1)   # slice centre
    area = wq * np.pi * r * r
    volume = area.sum()
    first = area @ d
    second = np.einsum("k,ki,kj->ij", area, d, d)
    own = (wq * np.pi * r ** 4 / 4.0).sum()         # disc: integral y'^2 dA = pi r^4 / 4
    second[1, 1] += own
    second[2, 2] += own
    return _props(volume, first, second, ref, b.name, b.name)


def _arbitrary_unit(b, whole=True, n=None):
    """Unit-density mass properties of an arbitrary body (half-section doubled if ``whole``)."""
    n = GAUSS_POINTS["arbitrary"] if n is None else n
    edges = np.unique(b.x)
    xq, wq = _on_intervals(edges, n)
    sec = b._sections_at(xq)                                            # (Q, M, 2), exact
    axis = np.stack([np.zeros_like(sec[:, [-1, 0], 0]), sec[:, [-1, 0], 1]], axis=-1)
    sec = np.concatenate([sec, axis], axis=1)           # closed through (0, z_top), (0, z_bot)
    ref = np.array([edges[0], 0.0, float(sec[..., 1].mean())])          # y ref on the plane
    y, z = sec[..., 0], sec[..., 1] - ref[2]
    y1, z1 = np.roll(y, -1, axis=-1), np.roll(z, -1, axis=-1)
    cr = y * z1 - y1 * z
    a = 0.5 * cr.sum(-1)
    sign = np.where(a < 0, -1.0, 1.0)                                   # either point order
    area = sign * a
    sy = sign * ((y + y1) * cr).sum(-1) / 6.0
    sz = sign * ((z + z1) * cr).sum(-1) / 6.0
    syy = sign * ((y * y + y * y1 + y1 * y1) * cr).sum(-1) / 12.0
    szz = sign * ((z * z + z * z1 + z1 * z1) * cr).sum(-1) / 12.0
    syz = sign * ((y * z1 + 2 * y * z + 2 * y1 * z1 + y1 * z) * cr).sum(-1) / 24.0
    if whole:   # half-section plus its mirror image y -> -y
        area, sz, syy, szz = 2 * area, 2 * sz, 2 * syy, 2 * szz
        sy, syz = np.zeros_like(sy), np.zeros_like(syz)
    dx = xq - ref[0]
    volume = wq @ area
    first = np.array([wq @ (dx * area), wq @ sy, wq @ sz])
    sxy, sxz = wq @ (dx * sy), wq @ (dx * sz)
    second = np.array([[wq @ (dx * dx * area), sxy, sxz],
                       [sxy, wq @ syy, wq @ syz],
                       [sxz, wq @ syz, wq @ szz]])
    return _props(volume, first, second, ref, b.name, b.name)


def _unit(component, symmetric):
    """Unit-density mass properties of a component including its image (if any)."""
    if isinstance(component, WingLike):
        props = _winglike_unit(component)
    elif isinstance(component, CircularBody):
        props = _circular_unit(component)
    elif isinstance(component, ArbitraryBody):
        return _arbitrary_unit(component, whole=symmetric)     # its image is in "whole"
    else:
        raise GeometryError(f"is a {type(component).__name__}, not a wing-like component or "
                            "body", getattr(component, "name", None))
    if symmetric and component.mirrored:
        props = MassProperties.sum([props, props.mirrored("xz")], name=component.name)
    return props


def _scaled(unit, rho):
    """A unit-density body at density ``rho`` (volume keeps the sign of rho, as elsewhere)."""
    if unit._is_zero():
        return unit
    return MassProperties(rho * unit.mass, float(np.copysign(unit.volume, rho)), unit.cg,
                          rho * unit.inertia, unit.name)


def _number(value, what, component=None):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise GeometryError(f"{what} must be a number, found {value!r}", component) from None
    if not np.isfinite(v):
        raise GeometryError(f"{what} must be finite, found {value!r}", component)
    return v


def component_mass_properties(component, density=None, mass=None, symmetric=True):
    """Mass properties of one component of uniform density, its mirror image included.

    Parameters
    ----------
    component : WingLike, CircularBody or ArbitraryBody
    density : float, optional
        Density [mass / deck length^3]. Default 1 (then mass = volume) if ``mass`` is not given.
    mass : float, optional
        Mass of the component with its image [mass]; the density is mass / volume.
    symmetric : bool
        Whether the configuration is symmetric (images exist); see the module docstring.

    Returns
    -------
    MassProperties
        Named after the component; project axes.

    Raises
    ------
    GeometryError
        Both density and mass given, a non-finite value, or a mass for a body of no volume.

    Examples
    --------
    A cylinder of radius 1 and length 2 (volume 2 pi):

    >>> from juncture.model import CircularBody
    >>> p = component_mass_properties(CircularBody("can", [0, 2], [1, 1]))
    >>> round(p.volume, 9), round(float(p.inertia[0, 0]), 9)    # m R^2 / 2 = pi
    (6.283185307, 3.141592654)
    """
    name = getattr(component, "name", None)
    if density is not None and mass is not None:
        raise GeometryError("give density or mass, not both", name)
    unit = _unit(component, bool(symmetric))
    if mass is None:
        return _scaled(unit, 1.0 if density is None else _number(density, "density", name))
    m = _number(mass, "mass", name)
    if unit.volume == 0 and m != 0:
        raise GeometryError(f"has no volume, so it cannot carry the mass {m:g}", name)
    return _scaled(unit, m / unit.volume if unit.volume else 1.0)


def _per_component(cfg, values, mapping, what):
    values = {} if values is None else dict(values)
    unknown = [k for k in values if k not in cfg.components]
    if unknown:
        raise GeometryError(f"no such component (in {mapping}); the configuration has "
                            f"{', '.join(cfg.components) or 'none'}", unknown[0])
    return {k: _number(v, what, k) for k, v in values.items()}


def configuration_mass_properties(cfg, density=None, mass=None, densities=None, masses=None):
    """Mass properties of every component of a Configuration and of the whole airplane.

    Each wing-like component and body is a solid of uniform density, integrated exactly for
    the model's own interpolation (module docstring). Mirror images are included: a
    ``mirrored`` component's entry is the pair, and a centre-line body is whole. Overlapping
    components (a wing root inside the fuselage) are each integrated as given, so the shared
    volume is counted in both.

    Parameters
    ----------
    cfg : Configuration
    density : float, optional
        Density of every component without its own entry [mass / deck length^3]. If neither
        ``density`` nor ``mass`` is given it is 1, and every mass equals the volume.
    mass : float, optional
        Total mass of the components without their own entry [mass], spread over them at one
        uniform density (their total mass over their total volume). Not with ``density``.
    densities, masses : mapping of str to float, optional
        Per-component density, or mass (the component with its image), by component name.
        A component may appear in one of them at most.

    Returns
    -------
    total : MassProperties
        Named ``"total"``.
    parts : list of (str, MassProperties)
        One per component, in the configuration's order.

    Raises
    ------
    GeometryError
        Not a Configuration, an unknown name, a component in both mappings, both ``density``
        and ``mass``, a non-finite value, or a mass for components without volume.
    """
    if not isinstance(cfg, Configuration):
        raise GeometryError(f"mass properties need a Configuration of components (a solid "
                            f"description), found {type(cfg).__name__}")
    if density is not None and mass is not None:
        raise GeometryError("give density or mass for the configuration, not both")
    dens = _per_component(cfg, densities, "densities", "density")
    mass_of = _per_component(cfg, masses, "masses", "mass")
    both = sorted(set(dens) & set(mass_of))
    if both:
        raise GeometryError("is given both a density and a mass", both[0])
    units = {c.name: _unit(c, cfg.symmetric) for c in cfg}
    rest = [k for k in units if k not in dens and k not in mass_of]
    if mass is not None:
        m = _number(mass, "mass")
        vol = sum(units[k].volume for k in rest)
        if not rest or vol == 0:
            raise GeometryError(f"mass {m:g} is for the components without their own density or "
                                "mass, but " + ("there are none" if not rest else
                                                "they have no volume"))
        default = m / vol
    else:
        default = 1.0 if density is None else _number(density, "density")
    parts = []
    for key, unit in units.items():
        if key in mass_of:
            if unit.volume == 0 and mass_of[key] != 0:
                raise GeometryError(f"has no volume, so it cannot carry the mass "
                                    f"{mass_of[key]:g}", key)
            rho = mass_of[key] / unit.volume if unit.volume else 1.0
        else:
            rho = dens.get(key, default)
        parts.append((key, _scaled(unit, rho)))
    total = MassProperties.sum((p for _, p in parts), name="total")
    return total, parts
