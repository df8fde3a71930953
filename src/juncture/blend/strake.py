"""Long strake R2 over CDFGC (Song, Ma & Wang 2008, section 4, eq 10).

Plane T passes through D normal to the body axis (``x = x_D``). The edge CG of the auxiliary
surface S4 (``S4(0, t)``, t from C to G) is projected along the body axis onto T, giving DF,
and ``R2(s, t) = (1 - s) R2(0, t) + s R2(1, t)`` with ``R2(0, t)`` = CG and ``R2(1, t)`` = DF:
a ruled surface of constant section along the axis. Its cross-boundary tangents at CG and DF
are axial, as are S4's at CG (eqs 11-13), so R2 is G1 with R1 along CG; along GF it is G1 with
the body because a constant-section body has one normal along each axial line (eqs 14-19).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .surfaces import ParametricSurface, PlaneSurface

__all__ = ["Strake", "build_strake"]


@dataclass(frozen=True, slots=True, eq=False)
class Strake(ParametricSurface):
    """R2(s, t) of eq 10: s from CG (0) to DF (1), t from the strake edge (0) to the body (1).

    Parameters
    ----------
    s4 : ParametricSurface
        The auxiliary surface; its edge ``s4(0, t)`` is CG.
    x_d : float
        Axial station of plane T (through D) [length].
    """

    s4: object
    x_d: float

    def edge_cg(self, t):
        """CG = S4(0, t) and its t-derivative, (..., 3) each."""
        t = np.asarray(t, float)
        p, _, pt = self.s4.evaluate(np.zeros_like(t), t)
        return p, pt

    def _evaluate(self, s, t):
        cg, dcg = self.edge_cg(t)
        df, ddf = cg.copy(), dcg.copy()
        df[..., 0] = self.x_d
        ddf[..., 0] = 0.0
        s_ = s[..., None]
        return (1 - s_) * cg + s_ * df, df - cg, (1 - s_) * dcg + s_ * ddf

    def plane_t(self, size):
        """Plane T at D for figures: a ``size`` x ``size`` square in y and z."""
        return PlaneSurface(np.array([self.x_d, 0.0, -0.5 * size]),
                            np.array([0.0, size, 0.0]), np.array([0.0, 0.0, size]))


def build_strake(lines, wing_body):
    """R2 from the blending lines (plane T at D) and the auxiliary surface S4."""
    return Strake(wing_body.s4, float(lines.x_d))
