"""Independent references for the mass-properties tests: tensor Gauss-Legendre quadrature.

Each solid is integrated in its own coordinates (span, chord, thickness for a wing; radius,
axial position, angle for a disk; box / cylinder / sphere coordinates). Nothing here uses the
closed forms, the v-integrals or MassProperties: the functions return plain arrays
``(mass, volume, cg (3,), inertia about cg (3, 3))`` in project axes (x aft, y right, z up).
"""

from __future__ import annotations

import numpy as np


def gauss(n, lo=0.0, hi=1.0):
    """n-point Gauss-Legendre nodes and weights on [lo, hi]."""
    x, w = np.polynomial.legendre.leggauss(n)
    return lo + (hi - lo) * 0.5 * (x + 1.0), 0.5 * (hi - lo) * w


def moments(points, dm):
    """Mass, CG and inertia about the CG of weighted points (..., 3) with masses (...)."""
    p = points.reshape(-1, 3)
    w = dm.ravel()
    m = w.sum()
    cg = w @ p / m
    s = p - cg
    second = np.einsum("k,ki,kj->ij", w, s, s)
    return m, cg, np.trace(second) * np.eye(3) - second


def rot_x(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def wing_points(b, cr, ct, tr, tt, sweep, dihedral, mu, breaks=(), n_span=10, n_chord=24,
                n_thick=4, sqrt_le=True):
    """Quadrature points (k, 3) and volume weights (k,) of a right wing segment, root at 0.

    The chord integral is split at ``breaks``; with ``sqrt_le`` the first piece uses
    x = u^2 so that a sqrt(x) leading edge becomes a polynomial.
    """
    ys, wys = gauss(n_span)
    zs, wzs = gauss(n_thick)
    edges = [0.0, *breaks, 1.0]
    xs, wxs = [], []
    for k, (lo, hi) in enumerate(zip(edges[:-1], edges[1:], strict=True)):
        if k == 0 and sqrt_le:
            u, wu = gauss(n_chord, 0.0, np.sqrt(hi))
            xs.append(u * u)
            wxs.append(wu * 2.0 * u)
        else:
            x, wx = gauss(n_chord, lo, hi)
            xs.append(x)
            wxs.append(wx)
    xs, wxs = np.concatenate(xs), np.concatenate(wxs)
    Y, X, Z = np.meshgrid(ys, xs, zs, indexing="ij")
    W = wys[:, None, None] * wxs[None, :, None] * wzs[None, None, :]
    c = cr + (ct - cr) * Y
    t = (tr + (tt - tr) * Y) * mu(X) * c
    y = b * Y
    x_aft = (X - 0.25) * c + y * np.tan(sweep)
    z_up = t * (Z - 0.5)
    jac = b * c * t
    pts = np.stack([x_aft, y, z_up], axis=-1) @ rot_x(dihedral).T
    return pts.reshape(-1, 3), (W * jac).ravel()


def wing_reference(b, cr, ct, tr, tt, sweep, dihedral, mu, root, density, side="right",
                   breaks=(), sqrt_le=True):
    """(mass, volume, cg, inertia) of a wing segment by quadrature; ``side`` as WingSegment.

    ``root`` is the panel's own root for "right" and "left" (a left panel is the right one's
    points mirrored about its root, y -> -y, then moved to the root); "both" is the right
    panel at ``root`` plus its mirror image in the plane y = 0.
    """
    pts, dv = wing_points(b, cr, ct, tr, tt, sweep, dihedral, mu, breaks, sqrt_le=sqrt_le)
    root = np.asarray(root, dtype=float)
    mirror = np.array([1.0, -1.0, 1.0])
    if side == "left":
        pts = pts * mirror + root
    elif side == "both":
        pts = np.concatenate([pts + root, (pts + root) * mirror])
        dv = np.concatenate([dv, dv])
    else:
        pts = pts + root
    m, cg, inertia = moments(pts, density * dv)
    return m, np.sign(density) * dv.sum(), cg, inertia


def disk_rotor_reference(n_blades, r_root, r_tip, cr, ct, tr, tt, v0, hub_height, rho_hub,
                         rho_blade, center, axis):
    """Hub cylinder + blade disk (eq 70 thickness) integrated in cylindrical coordinates."""
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    # orthonormal frame (a, e1, e2)
    tmp = np.array([0.0, 0.0, 1.0]) if abs(a[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    e1 = np.cross(a, tmp)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(a, e1)
    phi = np.linspace(0.0, 2 * np.pi, 9)[:-1]
    w_phi = np.full(8, 2 * np.pi / 8)
    pieces = []
    # blades: r in [r_root, r_tip], axial in [-h/2, h/2]
    r, wr = gauss(60, r_root, r_tip)
    s = (r - r_root) / (r_tip - r_root)
    h = n_blades * (tr + (tt - tr) * s) * (cr + (ct - cr) * s) ** 2 * v0 / (2 * np.pi * r)
    q, wq = gauss(4, -0.5, 0.5)
    R, Q, P = np.meshgrid(r, q, phi, indexing="ij")
    H = h[:, None, None] * np.ones_like(Q)
    W = wr[:, None, None] * wq[None, :, None] * w_phi[None, None, :] * H * R
    X = Q * H
    pieces.append((X, R, P, rho_blade * W))
    # hub: r in [0, r_root], axial in [-h_h/2, h_h/2]
    r, wr = gauss(6, 0.0, r_root)
    q, wq = gauss(4, -0.5 * hub_height, 0.5 * hub_height)
    R, Q, P = np.meshgrid(r, q, phi, indexing="ij")
    W = wr[:, None, None] * wq[None, :, None] * w_phi[None, None, :] * R
    pieces.append((Q, R, P, rho_hub * W))
    pts, dms = [], []
    for X, R, P, dm in pieces:
        p = (X[..., None] * a + (R * np.cos(P))[..., None] * e1 + (R * np.sin(P))[..., None] * e2)
        pts.append(p.reshape(-1, 3))
        dms.append(dm.ravel())
    m, cg, inertia = moments(np.concatenate(pts) + center, np.concatenate(dms))
    return m, cg, inertia
