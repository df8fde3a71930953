"""Wing-body blend R1 over ABCGHA (Song, Ma & Wang 2008, section 3, eqs 1-9).

Pieces, each a :class:`~juncture.blend.surfaces.ParametricSurface` in (s, t) in [0, 1]^2:

* B1, B2: reparameterised local base surfaces on the body (eqs 1-4). The parameter-plane
  patches are ruled, ``P(s, t) = (1 - s) P(0, t) + s P(1, t)``, with ``P1(0, t)`` = rho1 on
  M..G, ``P1(1, t)`` = rho2 on M..G, ``P2`` likewise on G..H, each piece re-parameterised
  uniformly (linearly) on [0, 1].
* S3: the auxiliary plane at the strake point C, spanned by the body axis (s) and an inboard
  direction (t).
* S4 = f(t) S3(s, q1(t)) + (1 - f(t)) B1(s, q2(t)), the auxiliary surface (eq 5).
* S5: the auxiliary base surface that merges S4 and B2 (section 3.2). The paper skins a
  B-spline through s-iso-lines of S4 and B2; here S5 is the exact merge those skinning curves
  sample: ``S5(sigma, tau) = S4(tau, sigma / sigma_G)`` for sigma <= sigma_G and
  ``B2(tau, (sigma - sigma_G) / (1 - sigma_G))`` after, with sigma_G chosen so that S5 is C1
  across G. It lies on the body exactly along GH (a skin would only interpolate it).
* B3: local base surface on the wing over the parameter patch ``(1 - t) rho4 + t rho3``
  (eqs 6-8).
* R1 = f(t) S5(s, q1(t)) + (1 - f(t)) B3(s, q2(t)) (eq 9).

Blending function and reparameterisations (eq 5):
``f(t) = mu (1-t)^2 / (mu (1-t)^2 + (1-mu) t^2)``, ``q1(t) = t / (1 - lambda + lambda t)``,
``q2(t) = t (1 - lambda) / (1 - lambda t)``; f(0) = 1, f(1) = 0, f'(0) = f'(1) = 0, so R
meets the first base surface at t = 0 and the second at t = 1 with G1 continuity.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import SpecError
from .surfaces import MappedSurface, ParametricSurface, PlaneSurface

__all__ = ["blend_f", "blend_q1", "blend_q2", "HartmannBlend", "MergedSurface",
           "WingBodyBlend", "build_wing_body"]


def blend_f(t, mu=0.5):
    """Blending function f(t) of eq 5 and its derivative: two arrays."""
    t = np.asarray(t, float)
    a, b = mu * (1 - t) ** 2, (1 - mu) * t**2
    d = a + b
    da, db = -2 * mu * (1 - t), 2 * (1 - mu) * t
    return a / d, (da * d - a * (da + db)) / d**2


def blend_q1(t, lam=0.5):
    """q1(t) = t / (1 - lambda + lambda t) and its derivative."""
    t = np.asarray(t, float)
    d = 1 - lam + lam * t
    return t / d, (1 - lam) / d**2


def blend_q2(t, lam=0.5):
    """q2(t) = t (1 - lambda) / (1 - lambda t) and its derivative."""
    t = np.asarray(t, float)
    d = 1 - lam * t
    return t * (1 - lam) / d, (1 - lam) / d**2


def _check_options(mu, lam):
    if not 0.0 < mu < 1.0:
        raise SpecError(f"blend.mu must lie in (0, 1), found {mu!r}")
    if not 0.0 <= lam < 1.0:
        raise SpecError(f"blend.lambda must lie in [0, 1), found {lam!r}")


@dataclass(frozen=True, slots=True, eq=False)
class HartmannBlend(ParametricSurface):
    """``R(s, t) = f(t) A(s, q1(t)) + (1 - f(t)) B(s, q2(t))`` (eqs 5 and 9).

    ``A(s, 0)`` and ``B(s, 1)`` are the blending lines: R(s, 0) = A(s, 0), R(s, 1) = B(s, 1),
    with R_t = q1'(0) A_t at t = 0 and q2'(1) B_t at t = 1 (G1 with A and B).
    """

    first: object
    second: object
    mu: float = 0.5
    lam: float = 0.5

    def __post_init__(self):
        _check_options(self.mu, self.lam)

    def _evaluate(self, s, t):
        f, df = blend_f(t, self.mu)
        q1, dq1 = blend_q1(t, self.lam)
        q2, dq2 = blend_q2(t, self.lam)
        a, a_s, a_t = self.first.evaluate(s, q1)
        b, b_s, b_t = self.second.evaluate(s, q2)
        f, df, dq1, dq2 = (x[..., None] for x in (f, df, dq1, dq2))
        p = f * a + (1 - f) * b
        ps = f * a_s + (1 - f) * b_s
        pt = df * (a - b) + f * dq1 * a_t + (1 - f) * dq2 * b_t
        return p, ps, pt


@dataclass(frozen=True, slots=True, eq=False)
class MergedSurface(ParametricSurface):
    """S5(sigma, tau): S4 then B2 along sigma, both swept along tau (see module notes)."""

    s4: object
    b2: object
    sigma_g: float

    def split(self, sigma):
        """Which piece (bool array: True = S4) and its t parameter for each sigma."""
        sigma = np.asarray(sigma, float)
        first = sigma <= self.sigma_g
        t = np.where(first, sigma / self.sigma_g,
                     (sigma - self.sigma_g) / (1 - self.sigma_g))
        return first, t

    def _evaluate(self, sigma, tau):
        first, t = self.split(sigma)
        t1, t2 = np.where(first, t, 1.0), np.where(first, 0.0, t)
        p1, s1, d1 = self.s4.evaluate(tau, t1)
        p2, s2, d2 = self.b2.evaluate(tau, t2)
        m = first[..., None]
        p = np.where(m, p1, p2)
        p_sigma = np.where(m, d1 / self.sigma_g, d2 / (1 - self.sigma_g))
        p_tau = np.where(m, s1, s2)
        return p, p_sigma, p_tau


def _ruled_s(curve0, curve1):
    """Parameter map ``(1 - s) c0(t) + s c1(t)`` (eqs 1, 3)."""

    def pmap(s, t):
        p0, d0 = curve0(t)
        p1, d1 = curve1(t)
        s_ = s[..., None]
        return (1 - s_) * p0 + s_ * p1, p1 - p0, (1 - s_) * d0 + s_ * d1

    return pmap


def _ruled_t(curve0, curve1):
    """Parameter map ``(1 - t) c0(s) + t c1(s)`` (eq 7)."""

    def pmap(s, t):
        p0, d0 = curve0(s)
        p1, d1 = curve1(s)
        t_ = t[..., None]
        return (1 - t_) * p0 + t_ * p1, (1 - t_) * d0 + t_ * d1, p1 - p0

    return pmap


def _piece(curve, a, b):
    """curve restricted to [a, b] and re-parameterised uniformly on [0, 1]."""

    def c(t):
        p, d = curve(a + (b - a) * np.asarray(t, float))
        return p, d * (b - a)

    return c


@dataclass(frozen=True, slots=True, eq=False)
class WingBodyBlend:
    """All surfaces of section 3: b1, b2, s3, s4, s5, b3 and the blend r1.

    ``r1(sigma, t)``: sigma runs C (0) -> G (``sigma_g``) -> H (1) along its t = 0 edge and
    B -> A along its t = 1 edge (the wing line AB).
    """

    b1: object
    b2: object
    s3: object
    s4: object
    s5: object
    b3: object
    r1: object
    sigma_g: float
    mu: float
    lam: float
    beta: float


def build_wing_body(lines, mu=0.5, lam=0.5, beta=0.2):
    """Construct B1, B2, S3, S4, S5, B3 and R1 from the blending lines.

    Parameters
    ----------
    lines : BlendLines
    mu, lam, beta : float
        Balance factor (0 < mu < 1), reparameterisation factor (0 <= lambda < 1) and wing
        offset (eq 6, in wing parameter units); paper values 0.5, 0.5, 0.2.

    Returns
    -------
    WingBodyBlend
    """
    _check_options(mu, lam)
    if not beta > 0:
        raise SpecError(f"blend.beta must be positive, found {beta!r}")
    s_g = lines.s_g
    body, wing = lines.body, lines.wing
    b1 = MappedSurface(body, _ruled_s(_piece(lines.rho1, 0.0, s_g),
                                      _piece(lines.rho2, 0.0, s_g)))
    b2 = MappedSurface(body, _ruled_s(_piece(lines.rho1, s_g, 1.0),
                                      _piece(lines.rho2, s_g, 1.0)))
    s3 = PlaneSurface(lines.points["C"], np.array([lines.h, 0.0, 0.0]),
                      lines.strake_depth * np.asarray(lines.strake_dir, float))
    s4 = HartmannBlend(s3, b1, mu, lam)
    dq2_1 = blend_q2(1.0, lam)[1]
    sigma_g = float(s_g * dq2_1 / (s_g * dq2_1 + 1 - s_g))
    s5 = MergedSurface(s4, b2, sigma_g)
    b3 = MappedSurface(wing, _ruled_t(lambda s: lines.rho4(s, beta), lines.rho3))
    r1 = HartmannBlend(s5, b3, mu, lam)
    return WingBodyBlend(b1, b2, s3, s4, s5, b3, r1, sigma_g, mu, lam, beta)
