"""What the area analyses ask of a configuration's components: boxes, copies, open bases and
flow-through nacelles, and whether the whole airplane is symmetric about y = 0.

Shared by :mod:`.areas` (normal areas from the model), :mod:`.closed` (closed networks for
cuts) and :mod:`.machplanes` (Mach-plane areas), so that none of them imports another for it.
"""

from __future__ import annotations

import numpy as np

from ..model import ArbitraryBody, CircularBody, WingLike

__all__ = ["body_box", "wing_box", "boxes_overlap", "is_flow_through", "copies", "held_bases",
           "held_base_area", "is_y_symmetric"]


def body_box(body):
    """(2, 3) bounding box of a body (its y >= 0 description; arbitrary: both halves)."""
    if isinstance(body, CircularBody):
        xs = np.linspace(body.x_global[0], body.x_global[-1], 401)
        r = body.radius_at(xs)
        c = body.center_at(xs)
        lo = [xs[0], (c[:, 0] - r).min(), (c[:, 1] - r).min()]
        hi = [xs[-1], (c[:, 0] + r).max(), (c[:, 1] + r).max()]
        return np.array([lo, hi])
    g = body._grid
    return np.array([[body.x[0], -g[..., 0].max(), g[..., 1].min()],
                     [body.x[-1], g[..., 0].max(), g[..., 1].max()]])


def wing_box(wing):
    """(2, 3) bounding box of a wing-like component's sections (its described copy)."""
    pts = np.concatenate([wing.section_points("upper").reshape(-1, 3),
                          wing.section_points("lower").reshape(-1, 3)])
    return np.array([pts.min(axis=0), pts.max(axis=0)])


def boxes_overlap(a, b):
    """Whether two (2, 3) boxes touch (to 1e-9 of their size)."""
    tol = 1e-9 * max(1.0, float(np.abs(np.concatenate([a, b])).max()))
    return bool(np.all(a[0] <= b[1] + tol) and np.all(b[0] <= a[1] + tol))


def is_flow_through(body):
    """True for a nacelle (a pod: off the centre line or mirrored) with an open front.

    Its inlet captures a streamtube of the first station's radius; the area-rule practice is
    to subtract that tube from the nacelle's areas (a flow-through nacelle), which also makes
    the area distribution start continuously at the inlet.
    """
    return (isinstance(body, CircularBody) and (body.mirrored or body.origin[1] != 0.0)
            and body.radius[0] > 0.0)


def copies(comp, cfg):
    """2 for a component with an image at -y, else 1."""
    return 2.0 if (cfg.symmetric and comp.mirrored) else 1.0


def _end(body):
    return float(body.x_global[-1]) if isinstance(body, CircularBody) else float(body.x[-1])


def held_bases(cfg):
    """Bodies with an open base whose area is held behind it: ``[(body, x_base, area)]``.

    The Harris program holds the base area of an open base behind it (a sting or wake of the
    base's section), so an equivalent body ends with that area instead of falling to zero
    across the base. Every body whose last section has an area is held, except a
    flow-through nacelle (:func:`is_flow_through`): its inlet's capture streamtube is
    subtracted and its exit is left as it is. ``area`` is one copy's.
    """
    out = []
    for body in cfg.bodies:
        if is_flow_through(body):
            continue
        x_end = _end(body)
        if isinstance(body, CircularBody):  # the deck's last radius: the interpolant at
            area = float(np.pi * body.radius[-1] ** 2)  # origin + x[-1] may be a hair off
        else:
            area = float(np.asarray(body.area_at(np.array([x_end])))[0])
        if area > 0.0:
            out.append((body, x_end, area))
    return out


def held_base_area(cfg, x):
    """(n_x,) area held behind open bases at stations x (both halves) [deck length^2]."""
    x = np.asarray(x, dtype=float)
    total = np.zeros(x.shape)
    for body, x_end, area in held_bases(cfg):
        total += copies(body, cfg) * np.where(x > x_end, area, 0.0)
    return total


def _self_symmetric(comp, tol):
    if isinstance(comp, ArbitraryBody):
        return True  # its half sections are mirrored at y = 0
    if isinstance(comp, CircularBody):
        return abs(float(comp.origin[1])) <= tol
    if not isinstance(comp, WingLike) or comp.span_axis == 1:
        return False  # a wing without an image lies on one side
    up, lo = comp.section_points("upper"), comp.section_points("lower")
    return bool(np.allclose(up * np.array([1.0, -1.0, 1.0]), lo, rtol=0.0, atol=tol))


def is_y_symmetric(cfg):
    """Whether the whole airplane (both halves) is symmetric about the plane y = 0.

    True when the configuration is described by its y >= 0 half (``symmetric``) and each
    component either has an image at -y or is symmetric itself (a body on the centre line, an
    arbitrary body, a centre-line fin with equal sides).
    """
    if not cfg.symmetric:
        return False
    ext = cfg.extents()
    tol = 1e-9 * max(1.0, float(np.abs(ext).max()))
    return all(comp.mirrored or _self_symmetric(comp, tol) for comp in cfg)
