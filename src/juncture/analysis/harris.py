"""The Harris program's conventions for the far-field wave drag of a deck, each switchable.

juncture's own far-field wave drag (:func:`juncture.analysis.wavedrag`) cuts the union of
the components with the model's own interpolation. A designer who compares with the Harris
program (NASA TM X-947; D2500, AWAVE) wants its conventions instead; ``method="harris"``
(``juncture wavedrag --harris``) applies them all, and :class:`HarrisConventions` switches
each on or off:

``linear_chordwise``
    Straight lines between the given chordwise ordinates of every wing, canard, tail, fin
    and pylon (the program's airfoil is the polygon through the deck's points), instead of
    juncture's PCHIP curve through them.
``sum_components``
    Each component's areas are cut from its whole closed surface and summed: a wing root
    buried in the fuselage is counted in both (no union), and a warning names each
    wing-like component whose root section lies inside a body.
``normal_mach``
    "Normal area" (Mach 1, or no Mach number) is the far field at this Mach number
    (1.000001: every cut is then nearly x = const), cut from the same faceted surfaces,
    instead of the model's exact normal areas and the slender-body formula.
``half_turn``
    ``NTHETA + 1`` roll angles over a half turn with Boole's rule (the program's symmetric
    half model), also for a configuration juncture would not call symmetric.
``fusard_fit``
    A circular fuselage given by its areas (the deck's FUSARD cards: every circular body but
    the pods) has, within each segment, the least-wave-drag (Eminton-Lord) area curve through
    its given areas between the stations, instead of juncture's PCHIP radius. The fit is the
    segment's own: the minimum of ``sum n a_n^2`` over the segment's slope series, whose
    curve starts at the segment's first area and passes through every later one (the
    closed-form kernel of :func:`juncture.analysis.wavedrag.eminton_lord`); the radius is
    ``sqrt(S / pi)`` (0 where the curve dips below 0). Our reading of the convention: no
    text of the program's fuselage routine was at hand.

Kept from juncture in both modes (they are the program's too): ``NX + 1`` cuts spanning each
roll angle's own equivalent body, from the first plane that touches the configuration to the
last; the area of an open base held behind it; the Eminton-Lord drag of each equivalent body.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, fields, replace

import numpy as np

from ..errors import JunctureError, JunctureWarning

__all__ = ["HarrisConventions", "harris_model", "harris_networks", "buried_roots",
           "fusard_fitted", "segment_area_fit"]

#: Samples per deck interval of the fitted fuselage (cosine-spaced in each interval, cubic
#: Hermite radius between them with the curve's own slopes): on the bundled transport the
#: body's area is within 1.2e-5 of the largest area of the least-drag curve (9e-5 with 8).
PER_INTERVAL = 16


@dataclass(frozen=True)
class HarrisConventions:
    """Which of the Harris program's conventions apply (all, by default; see the module)."""

    linear_chordwise: bool = True
    sum_components: bool = True
    normal_mach: float | None = 1.000001
    half_turn: bool = True
    fusard_fit: bool = True

    @classmethod
    def juncture(cls):
        """None of them: juncture's own conventions."""
        return cls(False, False, None, False, False)

    @classmethod
    def only(cls, name, value=None):
        """One convention on (at its Harris value, or ``value``), every other off."""
        names = [f.name for f in fields(cls)]
        if name not in names:
            raise JunctureError(f"no Harris convention {name!r}; they are {', '.join(names)}")
        on = getattr(cls(), name) if value is None else value
        return replace(cls.juncture(), **{name: on})

    def __post_init__(self):
        m = self.normal_mach
        if m is not None and not (np.isfinite(m) and 1.0 < m < 1.01):
            raise JunctureError(f"normal_mach must be None or slightly above 1 (1.000001), "
                                f"found {m}")


def harris_model(cfg, conventions):
    """``cfg`` with straight lines between chordwise ordinates and the fuselage's areas fitted
    segment by segment, as far as the conventions say so."""
    from ..model import CircularBody, WingLike, rebuilt

    comps = dict(cfg.components)
    for name, comp in comps.items():
        if (conventions.linear_chordwise and isinstance(comp, WingLike)
                and comp.chordwise != "linear"):
            comps[name] = rebuilt(comp, chordwise="linear")
        elif (conventions.fusard_fit and isinstance(comp, CircularBody)
              and not name.startswith("pod")):
            comps[name] = fusard_fitted(comp)
    return cfg.replace(components=comps)


def segment_area_fit(x, area):
    """``S(xq)``: the least-wave-drag area curve through one segment's station areas.

    Parameters
    ----------
    x : (m,) float
        The segment's stations, strictly increasing [deck length].
    area : (m,) float
        Their areas; the first need not be 0 [deck length^2].

    Returns
    -------
    callable
        ``S(xq, derivative=0) -> (...) float``: ``area[0]`` plus the Eminton-Lord curve
        through ``area - area[0]`` (``area[-1]`` behind the segment), or its slope ``dS/dx``.
    """
    from .wavedrag import exact_fit

    x, area = np.asarray(x, float), np.asarray(area, float)
    fit = exact_fit(x, area - area[0])
    return lambda xq, derivative=0: fit.slope(xq) if derivative else area[0] + fit.area(xq)


def _samples(xs, per_interval):
    """A segment's stations plus ``per_interval - 1`` cosine-spaced points in each interval
    (closer at the stations, where the least-drag curve's S'' has a logarithmic singularity);
    and the given stations' indices."""
    t = 0.5 * (1.0 - np.cos(np.pi * np.arange(per_interval) / per_interval))
    xd = np.append((xs[:-1, None] + np.diff(xs)[:, None] * t).ravel(), xs[-1])
    return xd, np.arange(0, xd.size, per_interval)


def fusard_fitted(body, per_interval=PER_INTERVAL):
    """``body`` sampled ``per_interval`` times per interval on each segment's least-drag
    area curve (:func:`segment_area_fit`); its given stations keep their areas and camber."""
    from ..model import rebuilt

    xg = body.x_global
    xs_out, r_out, c_out, slopes, sizes, start = [], [], [], [], [], 0
    for count in body.segments:
        part = slice(start, start + count)
        start += count
        xs, rs, cs = xg[part], body.radius[part], body.camber[part]
        xd, given = _samples(xs, per_interval)
        fit = segment_area_fit(xs, np.pi * rs * rs)
        area = fit(xd)
        area[given] = np.pi * rs * rs
        radius = np.sqrt(np.maximum(area, 0.0) / np.pi)
        camber = body.center_at(xd)[:, 1] - body.origin[2]  # interior points: own segment
        camber[given] = cs
        xs_out.append(xd - body.origin[0])
        r_out.append(radius)
        c_out.append(camber)
        slopes.append(_slopes(body, xd, radius, fit(xd, 1)))
        sizes.append(xd.size)
    return rebuilt(body, x=np.concatenate(xs_out), radius=np.concatenate(r_out),
                   camber=np.concatenate(c_out), segments=tuple(sizes),
                   slopes=np.concatenate(slopes))


def _slopes(body, xd, radius, area_slope):
    """(n, 2): dr/dx = S' / (2 pi r) (where r = 0, a pointed end with an infinite dr/dx, the
    chord slope to the next sample) and the camber's own slope, at one segment's samples."""
    dr = np.divide(area_slope, 2.0 * np.pi * radius, out=np.zeros_like(radius),
                   where=radius > 0.0)
    for k in np.flatnonzero(radius <= 0.0):
        j = k + 1 if k + 1 < xd.size else k - 1
        dr[k] = (radius[j] - radius[k]) / (xd[j] - xd[k])
    xq = xd.copy()  # the segment's own side at its ends (a joint belongs to the next one)
    nudge = 1e-9 * (xd[-1] - xd[0])
    xq[0], xq[-1] = xd[0] + nudge, xd[-1] - nudge
    return np.stack([dr, body.center_at(xq, derivative=1)[:, 1]], axis=1)


def buried_roots(cfg):
    """``[(wing name, body name)]``: wing-like components whose root section lies in a body."""
    from ..model import WingLike

    found = []
    for wing in cfg:
        if not isinstance(wing, WingLike):
            continue
        root = np.concatenate([wing.section_points(side)[0] for side in ("upper", "lower")])
        for body in cfg.bodies:
            if np.any(body.signed_distance(root) < 0.0):
                found.append((wing.name, body.name))
    return found


def harris_networks(cfg, conventions):
    """Closed networks to cut: each component whole when areas are summed, else None."""
    if not conventions.sum_components:
        return None
    from .closed import closed_networks

    for wing, body in buried_roots(cfg):
        warnings.warn(f"{wing}: root section lies inside {body}; with the Harris program's "
                      "convention the component areas are summed, so the buried part counts "
                      "in both", JunctureWarning, stacklevel=3)
    return closed_networks(cfg, union=False)
