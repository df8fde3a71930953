"""G1 report of the long-strake blend: gaps and normal angles along every seam.

Each seam is sampled densely at corresponding parameters of its two surfaces (the
construction says which points coincide). For each seam the report gives the largest
distance between the two points and the largest angle between the two unit normals. Normals
are compared with one orientation for the whole seam (the sign that makes them agree on
average), so a fold along a seam shows up as an angle near 180 degrees. The degenerate corner
E of the thin-plate patch (u = 1) is left out of the angle samples.
"""

from __future__ import annotations

import numpy as np

from .surfaces import unit

__all__ = ["SEAMS", "seam_samples", "g1_report"]

#: Seam names in report order.
SEAMS = ("R1-wing", "R1-body", "R1-R2", "R2-body", "R2-patch", "patch-body")


def _angle_deg(n1, n2):
    n1, n2 = unit(n1), unit(n2)
    dots = np.sum(n1 * n2, axis=-1)
    sign = 1.0 if np.sum(dots) >= 0 else -1.0
    return np.degrees(np.arctan2(np.linalg.norm(np.cross(n1, n2), axis=-1), sign * dots))


def seam_samples(model, name, n=400):
    """Points and normals of both sides of seam ``name``: (p1, n1, p2, n2), (n, 3) each.

    Parameters
    ----------
    model : BlendModel
        The built blend (see :func:`juncture.blend.run.build_blend`).
    name : str
        One of :data:`SEAMS`.
    n : int
        Number of samples.
    """
    lines, wb, r2, w = model.lines, model.wing_body, model.strake, model.patch
    body, wing = lines.body, lines.wing
    x = np.linspace(0.0, 1.0, n)
    zero, one = np.zeros_like(x), np.ones_like(x)
    if name == "R1-wing":
        uv, _ = lines.rho3(x)
        return (wb.r1.points(x, one), wb.r1.normals(x, one), wing.points(uv[:, 0], uv[:, 1]),
                wing.normals(uv[:, 0], uv[:, 1]))
    if name == "R1-body":
        sig = wb.sigma_g + (1 - wb.sigma_g) * x
        uv, _ = lines.rho1(lines.s_g + (1 - lines.s_g) * x)
        return (wb.r1.points(sig, zero), wb.r1.normals(sig, zero),
                body.points(uv[:, 0], uv[:, 1]), body.outward_normals(uv[:, 0], uv[:, 1]))
    if name == "R1-R2":
        sig = wb.sigma_g * x
        return (wb.r1.points(sig, zero), wb.r1.normals(sig, zero), r2.points(zero, x),
                r2.normals(zero, x))
    if name == "R2-body":
        xg = lines.points["G"][0]
        xb = (1 - x) * xg + x * lines.x_d
        vb = np.full_like(x, lines.v_g)
        return (r2.points(x, one), r2.normals(x, one), body.points(xb, vb),
                body.outward_normals(xb, vb))
    xo = np.linspace(0.0, 1.0 - 1e-3, n)
    z = np.zeros_like(xo)
    if name == "R2-patch":
        return (r2.points(np.ones_like(xo), 1 - xo), r2.normals(np.ones_like(xo), 1 - xo),
                w.points(z, xo), w.normals(z, xo))
    if name == "patch-body":
        uv, _ = lines.fe(xo)
        return (w.points(xo, z), w.normals(xo, z), body.points(uv[:, 0], uv[:, 1]),
                body.outward_normals(uv[:, 0], uv[:, 1]))
    raise KeyError(f"unknown seam {name!r}; known: {', '.join(SEAMS)}")


def g1_report(model, n=400):
    """The G1 report as a JSON-ready dict.

    Returns
    -------
    dict
        ``{"seams": [{"seam", "max_gap", "max_angle_deg", "samples"}, ...],
        "body_radius": R}``; gaps in the spec's length unit, R the body radius (largest
        section radius for a non-circular body).
    """
    seams = []
    for name in SEAMS:
        p1, n1, p2, n2 = seam_samples(model, name, n)
        seams.append({"seam": name,
                      "max_gap": float(np.max(np.linalg.norm(p1 - p2, axis=-1))),
                      "max_angle_deg": float(np.max(_angle_deg(n1, n2))),
                      "samples": int(n)})
    return {"seams": seams, "body_radius": float(model.lines.body.size)}
