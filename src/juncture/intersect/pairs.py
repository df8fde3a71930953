"""Which components touch, and how (TM-4607): found automatically or stated explicitly.

Candidates come from bounding boxes (each grown by a small margin); each candidate is then
confirmed by the solver: a pair touches if at least one lofting line meets the other
component, i.e. reaches a root of the surface equation (a sign change of the error across a
jump, at a planform edge or an open body end, is no root: :func:`.rays.find_crossings`).
A pair stated explicitly that does not touch in that sense is refused. Roles:

- ``"body"``: a wing-like surface meets a body (wing, canard, tail or fin on the fuselage;
  pylon on a nacelle), TM-4406 eqs 4-6 or TM-4607 eq 8;
- ``"upper"``: a fin stands on a wing-type surface (TM-4607 eq 7, searched from its tip);
- ``"lower"``: a pylon hangs under a wing-type surface (eq 7, searched from its root).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import GeometryError
from ..model import ArbitraryBody, CircularBody, WingLike
from .body import intersect_body_both, settle_past_centre, side_label
from .winglike import intersect_winglike

__all__ = ["Pair", "touching_pairs", "find_intersections", "side_label", "intersect_pair"]


@dataclass(frozen=True, slots=True)
class Pair:
    """Component ``a`` (wing-like) meets component ``b`` in the given role."""

    a: str
    b: str
    role: str  # "body", "upper" or "lower"


def _box(comp):
    pts = np.concatenate([n.reshape(-1, 3) for n in comp.networks().values()])
    return pts.min(axis=0), pts.max(axis=0)


def _overlap(a, b, margin):
    (alo, ahi), (blo, bhi) = a, b
    pad = margin * np.maximum(ahi - alo, bhi - blo).max()
    return bool(np.all(alo - pad <= bhi) and np.all(blo - pad <= ahi))


def intersect_pair(cfg, pair, **kwargs):
    """The intersections of a pair: a tuple (one per surface of ``a``) of BodyIntersection."""
    a, b = cfg[pair.a], cfg[pair.b]
    if pair.role == "body":
        return tuple(intersect_body_both(a, b, **kwargs))
    return tuple(intersect_winglike(a, b, pair.role, side, **kwargs)
                 for side in ("upper", "lower"))


def touching_pairs(cfg, margin=0.02, explicit=()):
    """Every touching (wing-like, other) pair of ``cfg`` (see :func:`find_intersections`)."""
    return list(find_intersections(cfg, margin, explicit))


def find_intersections(cfg, margin=0.02, explicit=(), skip=()):
    """Every touching (wing-like, other) pair of ``cfg`` with its intersections.

    Parameters
    ----------
    cfg : Configuration
    margin : float
        Bounding boxes are grown by this fraction of the larger box before the test.
    explicit : iterable of Pair or (a, b, role) tuples
        Pairs stated by the user; a component named in any explicit pair (as ``a``) is not
        searched automatically.
    skip : iterable of (a, b)
        Pairs handled elsewhere (e.g. the wing-body juncture).

    Returns
    -------
    dict of Pair to tuple of BodyIntersection
        One intersection per surface of ``a`` (upper/outboard, lower/inboard). A pair found
        automatically touches if a lofting line reaches a root of the surface equation on
        ``b`` (never a jump of the error) before it reaches any other component searched
        from the same end of ``a`` (a fin on the fuselage is not paired with the wing its
        extended lines meet inside the fuselage).

    Raises
    ------
    GeometryError
        If an explicit pair names a missing component or role, or does not touch (no
        lofting line meets ``b``).
    """
    pairs = [p if isinstance(p, Pair) else Pair(*p) for p in explicit]
    for p in pairs:
        for name in (p.a, p.b):
            cfg[name]  # raises GeometryError naming a missing component
        if p.role not in ("body", "upper", "lower"):
            raise GeometryError(f"pair role must be 'body', 'upper' or 'lower', found "
                                f"{p.role!r}", p.a)
    stated = {p.a for p in pairs}
    skip = {tuple(s) for s in skip}
    out = {p: intersect_pair(cfg, p) for p in pairs if (p.a, p.b) not in skip}
    auto = _candidates(cfg, stated, skip, margin)
    settled = settle_pairs(cfg, {**out, **auto})
    out = {p: settled[p] for p in out}
    auto = {p: settled[p] for p in auto if any(r.found.any() for r in settled[p])}
    for p, res in out.items():
        if not any(r.found.any() for r in res):
            raise GeometryError(f"the pair ({p.a!r}, {p.b!r}, {p.role!r}) was stated but "
                                f"no lofting line of {p.a} meets {p.b} (as role {p.role!r}); "
                                "remove the pair or move the components so that they touch",
                                p.a)
    out.update(_first_reached(auto))
    return out


def _candidates(cfg, stated, skip, margin):
    """Each pair of ``cfg`` whose boxes overlap (by ``margin``) and whose lofting lines meet
    the other component (a fin meeting a body only past its centre height included, to be
    settled by :func:`settle_pairs`), with its intersections; the first role that meets of
    a fin on a wing."""
    boxes, auto = {}, {}

    def box(c):  # built on first use: the networks are not free
        if c.name not in boxes:
            boxes[c.name] = _box(c)
        return boxes[c.name]

    for a in cfg.wings:
        if a.name in stated:
            continue
        for b in cfg:
            if b is a or (a.name, b.name) in skip or \
                    not _overlap(box(a), box(b), margin):
                continue
            if isinstance(b, (CircularBody, ArbitraryBody)):
                roles = ["body"]
            elif isinstance(b, WingLike) and a.span_axis == 2 and b.span_axis == 1:
                roles = ["upper", "lower"]
            else:
                continue
            for role in roles:
                pair = Pair(a.name, b.name, role)
                try:
                    res = intersect_pair(cfg, pair)
                except GeometryError as exc:
                    # A surface whose tip lies inside a fuselage never leaves it (a pod
                    # off the centre line may hold a tip: a tip tank is not refused).
                    if getattr(exc, "tip_inside", False) and not getattr(b, "mirrored", True):
                        raise
                    continue
                if any(r.found.any() for r in res):
                    if role == "body":
                        _refuse_passing_through(a, b, box(b))
                    auto[pair] = res
                    break
    return auto


def settle_pairs(cfg, found):
    """``found`` (pair to intersections) with each fin's or pylon's crossings past a body's
    centre height kept only where its line would otherwise end inside that body
    (:func:`.body.settle_past_centre`, against the pair's other intersections)."""
    out = dict(found)
    for pair, res in found.items():
        if not any(r.past_centre is not None and r.past_centre.any() for r in res):
            continue
        comp = cfg[pair.a]
        others = [r for q, r in found.items() if q.a == pair.a and q != pair]
        out[pair] = tuple(
            settle_past_centre(r, cfg[pair.b], [o[k] for o in others],
                               comp.lofting_lines(side))
            for k, (r, side) in enumerate(zip(res, ("upper", "lower"))))
    return out


def _refuse_passing_through(wing, body, body_box):
    """A GeometryError if ``wing`` runs through ``body`` and out on its far side.

    A wing, canard or tail whose root lies inboard of a body it touches and whose tip lies
    outboard of it (a wing cutting through a nacelle) meets it along a closed curve, with the
    body standing on neither end of the wing: juncture trims a wing where it *ends* at a body
    (TM-4406, TM-4607), so such a pair is refused rather than completed with a hole.
    """
    if wing.span_axis != 1:
        return
    (lo, hi), y = body_box, wing.le[:, 1]
    if y[0] < lo[1] and y[-1] > hi[1]:
        raise GeometryError(f"passes through {body.name} (its span runs from y = {y[0]:g} to "
                            f"{y[-1]:g}, across {body.name} at y = {lo[1]:g} to {hi[1]:g}); "
                            "juncture completes a wing where it ends at a body: move "
                            f"{body.name} or {wing.name} so that they do not touch",
                            wing.name)


def _first_reached(found):
    """The pairs of which at least one point is the first surface its lofting line reaches.

    A lofting line of a fin is followed from its tip (from its root for a pylon meeting a
    lower surface, TM-4607): the surface it reaches first is the one the fin stands on. A
    pair whose every point lies beyond another pair's point on the same line, searched from
    the same end (a fin on the fuselage whose extended lines also reach the wing inside the
    fuselage), does not touch: it is dropped.
    """
    groups = {}
    for pair in found:
        groups.setdefault((pair.a, pair.role == "lower"), []).append(pair)
    keep = dict(found)
    for (_, from_root), pairs in groups.items():
        if len(pairs) < 2:
            continue
        wins = np.zeros(len(pairs), bool)
        for side in range(2):
            u = np.stack([found[p][side].u for p in pairs])  # (pairs, lines), NaN if missed
            key = np.where(np.isfinite(u), -u if from_root else u, -np.inf)
            best = key.max(axis=0)
            wins |= ((key == best) & np.isfinite(key)).any(axis=1)
        for pair, won in zip(pairs, wins):
            if not won:
                del keep[pair]
    return keep
