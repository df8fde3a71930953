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

Kept from juncture in both modes (they are the program's too): ``NX + 1`` cuts spanning each
roll angle's own equivalent body, from the first plane that touches the configuration to the
last; the area of an open base held behind it; the Eminton-Lord drag of each equivalent body.
Not reproduced: the program's fit of FUSARD fuselage areas segment by segment (no
description of it was at hand; juncture's circular fuselage interpolates the radius through
the given areas within each segment, straight across gaps).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, fields, replace

import numpy as np

from ..errors import JunctureError, JunctureWarning

__all__ = ["HarrisConventions", "harris_model", "harris_networks", "buried_roots"]


@dataclass(frozen=True)
class HarrisConventions:
    """Which of the Harris program's conventions apply (all, by default; see the module)."""

    linear_chordwise: bool = True
    sum_components: bool = True
    normal_mach: float | None = 1.000001
    half_turn: bool = True

    @classmethod
    def juncture(cls):
        """None of them: juncture's own conventions."""
        return cls(False, False, None, False)

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
    """``cfg`` with straight lines between chordwise ordinates, if the conventions say so."""
    if not conventions.linear_chordwise:
        return cfg
    from ..model import WingLike, rebuilt

    comps = dict(cfg.components)
    for name, comp in comps.items():
        if isinstance(comp, WingLike) and comp.chordwise != "linear":
            comps[name] = rebuilt(comp, chordwise="linear")
    return cfg.replace(components=comps)


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
