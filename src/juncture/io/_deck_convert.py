"""Wave-drag deck records <-> Configuration (the model's view of a deck).

Reading keeps the deck's meaning exactly: percent-chord stations and ordinates stay percent
chord, camber stays absolute, fuselage areas become radii r = sqrt(A / pi) (formats.md 1.5).
The raw deck configuration is kept as ``Configuration.source``; writing a configuration back
reuses every raw record whose component is unchanged, so read -> write -> read is exact. The
case cards written are those of ``Configuration.source.cases`` (a deck configuration, or the
cases of a juncture JSON/TOML model, :class:`juncture.io.jsonmodel.ModelSource`).

Component names: ``wing``, ``body``, ``pod k``, ``fin k``, and ``canard k`` or ``tail k``
(a canard card set whose inboard leading edge lies aft of the wing's mid root chord is
called a tail).
"""

from __future__ import annotations

import numpy as np

from ..errors import DeckError, GeometryError
from ..model import ArbitraryBody, CircularBody, Configuration, WingLike
from ._deck import (
    CASE_FIELDS,
    ControlCard,
    DeckCanard,
    DeckCase,
    DeckConfiguration,
    DeckFin,
    DeckFuselage,
    DeckFuselageSegment,
    DeckPod,
    DeckWing,
)
from .jsonmodel import xy_symmetric

__all__ = ["deck_to_configuration", "configuration_to_deck"]


def _wing(w: DeckWing):
    o = w.origins
    return WingLike("wing", "wing", o[:, :3], o[:, 3], w.xaf, w.waford_upper,
                    w.waford_upper if w.waford_lower is None else w.waford_lower,
                    None if w.tzord is None else w.tzord, mirrored=True)


def _body(f: DeckFuselage, control):
    segs = f.segments
    x = np.concatenate([s.x for s in segs])
    sizes = tuple(s.x.size for s in segs)
    if segs[0].area is not None:
        area = np.concatenate([s.area for s in segs])
        camber = np.concatenate([s.zfus if s.zfus is not None else np.zeros(s.x.size)
                                 for s in segs])
        return CircularBody("body", x, np.sqrt(np.maximum(area, 0.0) / np.pi), camber,
                            segments=sizes,
                            points_per_section=tuple(control.nradx[:len(segs)]))
    sections = [np.stack([s.y[j], s.z[j]], axis=-1) for s in segs for j in range(s.x.size)]
    return ArbitraryBody("body", x, sections, segments=sizes)


def _pod(k, p: DeckPod):
    return CircularBody(f"pod {k}", p.x, p.radius, origin=p.origin, mirrored=p.origin[1] != 0.0,
                        axial="pchip")


def _fin(k, f: DeckFin):
    o = f.origins
    inb = f.outboard if f.inboard is None else f.inboard
    return WingLike(f"fin {k}", "fin", o[:, :3], o[:, 3], f.xfin, np.stack([f.outboard] * 2),
                    np.stack([inb] * 2), mirrored=bool(o[0, 1] != 0.0 or o[1, 1] != 0.0))


def _canard(name, c: DeckCanard):
    o = c.origins
    kind = name.split()[0]
    return WingLike(name, kind, o[:, :3], o[:, 3], c.xcan,
                    np.stack([c.upper_inboard, c.upper_outboard]),
                    np.stack([c.lower_inboard, c.lower_outboard]), mirrored=True)


def _canard_names(dc):
    names, counts = [], {"canard": 0, "tail": 0}
    wing = dc.wing
    for c in dc.canards:
        kind = "canard"
        if wing is not None:
            x_mid_root = wing.origins[0, 0] + 0.5 * wing.origins[0, 3]
            kind = "tail" if c.origins[0, 0] > x_mid_root else "canard"
        counts[kind] += 1
        names.append(f"{kind} {counts[kind]}")
    return names


def _line_of(dc, component, station):
    """Best line number for a geometry error in ``component`` at 1-based ``station``."""
    lines = dc.lines
    name = component or ""
    keys = []
    if name == "wing":
        keys = [f"waforg {station}", "xaf"]
    elif name == "body":
        keys = ["xfus 1"]
        if station is not None and dc.fuselage is not None:
            k = int(station)
            for i, s in enumerate(dc.fuselage.segments, 1):
                if k <= s.x.size:
                    keys = [f"xfus {i}"]
                    break
                k -= s.x.size
    elif name.startswith("pod "):
        keys = [f"xpod {name.split()[1]}", f"podorg {name.split()[1]}"]
    elif name.startswith("fin "):
        keys = [f"finorg {name.split()[1]}"]
    elif name.startswith(("canard ", "tail ")):
        names = _canard_names(dc)
        if name in names:
            keys = [f"canorg {names.index(name) + 1}"]
    for key in keys:
        if key in lines:
            return lines[key]
    return None


def deck_to_configuration(deck, configuration=0, path=None):
    """The ``configuration``-th (0-based) configuration of a raw deck as a Configuration.

    Raises
    ------
    DeckError
        If there is no such configuration, or the geometry it describes is invalid (the
        message names the line of the component's cards, the component and the station).
    """
    path = path if path is not None else deck.path
    n = len(deck.configurations)
    if not -n <= configuration < n:
        raise DeckError(f"the deck holds {n} configuration(s); configuration {configuration} "
                        "was asked for", path=path)
    dc = deck.configurations[configuration]
    comps = []
    try:
        if dc.wing is not None:
            comps.append(_wing(dc.wing))
        if dc.fuselage is not None:
            comps.append(_body(dc.fuselage, dc.control))
        comps += [_pod(k, p) for k, p in enumerate(dc.pods, 1)]
        comps += [_fin(k, f) for k, f in enumerate(dc.fins, 1)]
        comps += [_canard(nm, c) for nm, c in zip(_canard_names(dc), dc.canards)]
    except GeometryError as exc:
        line = _line_of(dc, exc.component, exc.station)
        raise DeckError(str(exc), path=path, line=line) from None
    ref = dc.reference
    return Configuration({c.name: c for c in comps}, title=dc.title,
                         reference_area=None if ref is None else ref[0],
                         reference_chord=None if ref is None else ref[1],
                         moment_x=None if ref is None else ref[2], symmetric=True, source=dc)


# ---------------------------------------------------------------------------------------
def _same(a, b):
    """True if two components hold identical data (so a raw record can be reused)."""
    if type(a) is not type(b) or a.name != b.name:
        return False
    names = [f for f in a.__dataclass_fields__ if not f.startswith("_")]
    for f in names:
        va, vb = getattr(a, f), getattr(b, f)
        if isinstance(va, np.ndarray) or isinstance(vb, np.ndarray):
            if not (np.shape(va) == np.shape(vb) and np.array_equal(va, vb)):
                return False
        elif isinstance(va, tuple) and va and isinstance(va[0], np.ndarray):
            if len(va) != len(vb) or not all(np.array_equal(p, q) for p, q in zip(va, vb)):
                return False
        elif va != vb:
            return False
    return True


def _fail(message, component=None):
    raise GeometryError(message, component)


def _deck_wing(w: WingLike):
    if w.kind != "wing":
        _fail(f"the deck's wing must be of kind 'wing', found {w.kind!r}", w.name)
    origins = np.column_stack([w.le, w.chord])
    cambered = bool(w.camber.any())
    lower = None if np.array_equal(w.upper, w.lower) else w.lower
    return DeckWing(w.x_over_c, origins, w.camber if cambered else None, w.upper, lower)


def _deck_body(b):
    segs, start = [], 0
    for s in b.segments:
        sl = slice(start, start + s)
        if isinstance(b, CircularBody):
            if b.origin.any():
                _fail("a deck fuselage has its origin at (0, 0, 0)", b.name)
            segs.append(DeckFuselageSegment(b.x[sl], zfus=b.camber[sl],
                                            area=np.pi * b.radius[sl] ** 2))
        else:
            secs = b.sections[sl]
            if len({len(a) for a in secs}) != 1:
                _fail("the half-sections of a deck fuselage segment need equal point counts",
                      b.name)
            segs.append(DeckFuselageSegment(b.x[sl], y=np.stack([a[:, 0] for a in secs]),
                                            z=np.stack([a[:, 1] for a in secs])))
        start += s
    return DeckFuselage(segs)


def _check_two_sections(w, what):
    if w.n_sections != 2:
        _fail(f"a deck {what} is given by root and tip only, found {w.n_sections} sections",
              w.name)


def _deck_fin(f: WingLike):
    _check_two_sections(f, "fin")
    if not (np.array_equal(f.upper[0], f.upper[1]) and np.array_equal(f.lower[0], f.lower[1])):
        _fail("a deck fin has the same ordinates at root and tip", f.name)
    inboard = None if np.array_equal(f.upper[0], f.lower[0]) else f.lower[0]
    return DeckFin(np.column_stack([f.le, f.chord]), f.x_over_c, f.upper[0], inboard)


def _deck_canard(c: WingLike):
    _check_two_sections(c, "canard or tail")
    ui, uo = c.upper
    li, lo = c.lower
    n_sets = (2 if not np.array_equal(ui, uo) or not np.array_equal(li, lo) else 1) * \
        (2 if not (np.array_equal(ui, li) and np.array_equal(uo, lo)) else 1)
    return DeckCanard(np.column_stack([c.le, c.chord]), c.x_over_c, ui, uo, li, lo, n_sets)


def configuration_to_deck(cfg):
    """A raw Deck holding ``cfg`` as one configuration (reusing unchanged raw records).

    Raises
    ------
    GeometryError
        If the configuration cannot be expressed in the deck (two wings, a fin with more than
        two sections, fins with different station counts, a body not on the centre line ...).
    """
    from ._deck import Deck

    src = cfg.source if isinstance(cfg.source, DeckConfiguration) else None
    from_src = {}
    if src is not None:
        try:
            from_src = deck_to_configuration(Deck((src,)), 0).components
        except DeckError:
            from_src = {}

    def reuse(comp, raw):
        return raw if comp.name in from_src and _same(comp, from_src[comp.name]) else None

    wings = [c for c in cfg.wings if c.kind == "wing"]
    fins = [c for c in cfg.wings if c.kind in ("fin", "pylon")]
    canards = [c for c in cfg.wings if c.kind in ("canard", "tail")]
    bodies = [c for c in cfg.bodies if not c.name.startswith("pod")]
    pods = [c for c in cfg.bodies if c.name.startswith("pod")]
    if len(wings) > 1:
        _fail(f"a wave-drag deck holds one wing, found {len(wings)}: "
              f"{', '.join(w.name for w in wings)}")
    if len(bodies) > 1:
        _fail(f"a wave-drag deck holds one fuselage (others are pods), found "
              f"{', '.join(b.name for b in bodies)}")
    for p in pods:
        if not isinstance(p, CircularBody) or p.camber.any():
            _fail("a deck pod is an uncambered body of revolution", p.name)

    wing = None
    if wings:
        wing = (reuse(wings[0], src.wing) if src else None) or _deck_wing(wings[0])
    fus = None
    if bodies:
        fus = (reuse(bodies[0], src.fuselage) if src else None) or _deck_body(bodies[0])
    raw_pods = [(reuse(p, src.pods[i]) if src and i < len(src.pods) else None)
                or DeckPod(p.origin, p.x, p.radius) for i, p in enumerate(pods)]
    raw_fins = [(reuse(f, src.fins[i]) if src and i < len(src.fins) else None) or _deck_fin(f)
                for i, f in enumerate(fins)]
    raw_cans = [(reuse(c, src.canards[i]) if src and i < len(src.canards) else None)
                or _deck_canard(c) for i, c in enumerate(canards)]

    for group, what, attr in ((raw_fins, "fins", "xfin"), (raw_cans, "canards", "xcan")):
        if len({getattr(r, attr).size for r in group}) > 1:
            _fail(f"all deck {what} share one station count, found "
                  f"{sorted({getattr(r, attr).size for r in group})}")
    if any(f.inboard is not None for f in raw_fins):  # NF < 0 applies to every fin
        raw_fins = [f if f.inboard is not None else DeckFin(f.origins, f.xfin, f.outboard,
                                                             f.outboard) for f in raw_fins]
    raw_cans = _common_canard_sets(raw_cans)

    sc = src.control if src is not None else ControlCard(j6=1 if xy_symmetric(cfg) else 0)
    nwafor = 0
    if wing is not None:
        n = wing.xaf.size
        nwafor = -n if wing.waford_lower is not None else n
    j1 = 0 if wing is None else (1 if wing.tzord is not None else -1)
    j2, j6, nradx, nforx = 0, 0, [0] * 4, [0] * 4
    if fus is not None:
        arbitrary = fus.segments[0].y is not None
        j2 = 1 if arbitrary else -1
        cambered = not arbitrary and any(s.zfus is not None and s.zfus.any()
                                         for s in fus.segments)
        j6 = 0 if cambered else (sc.j6 if sc.j6 in (1, -1) and not arbitrary else
                                 (0 if arbitrary else -1))
        if arbitrary and j6 == 1:
            j6 = 0
        if j6 != 0:  # no ZFUS cards: the centre stays at z = 0
            fus = DeckFuselage([DeckFuselageSegment(s.x, None, s.area, s.y, s.z)
                                for s in fus.segments])
        for i, s in enumerate(fus.segments):
            nforx[i] = s.x.size
            if arbitrary:
                nradx[i] = s.y.shape[1]
            else:
                pps = bodies[0].points_per_section
                nradx[i] = pps[i] if pps else (sc.nradx[i] or 19)
    nf = len(raw_fins) * (-1 if any(f.inboard is not None for f in raw_fins) else 1)
    ncan = len(raw_cans)
    ncanor = raw_cans[0].xcan.size if raw_cans else 0
    if raw_cans and src is not None and all(any(r is q for q in src.canards) for r in raw_cans):
        # Unchanged raw records: keep the deck's own signs (the data may not show the split).
        ncan *= -1 if sc.ncan < 0 else 1
        ncanor *= -1 if sc.ncanor < 0 else 1
    else:
        ncan *= -1 if any(_splits_inboard(c) for c in raw_cans) else 1
        ncanor *= -1 if any(_splits_upper(c) for c in raw_cans) else 1
    control = ControlCard(
        j0=1 if cfg.reference_area is not None else 0, j1=j1, j2=j2,
        j3=1 if raw_pods else 0, j4=1 if raw_fins else 0, j5=1 if raw_cans else 0, j6=j6,
        nwaf=0 if wing is None else wing.origins.shape[0], nwafor=nwafor,
        nfus=0 if fus is None else len(fus.segments), nradx=tuple(nradx), nforx=tuple(nforx),
        np=len(raw_pods), npodor=raw_pods[0].x.size if raw_pods else 0, nf=nf,
        nfinor=raw_fins[0].xfin.size if raw_fins else 0, ncan=ncan, ncanor=ncanor)
    if len({p.x.size for p in raw_pods}) > 1:
        _fail("all deck pods share one station count (NPODOR)")
    ref = None
    if cfg.reference_area is not None:
        ref = (cfg.reference_area, cfg.reference_chord or 0.0, cfg.moment_x or 0.0)
    cases = _single_configuration_cases(getattr(cfg.source, "cases", None) or ())
    dc = DeckConfiguration(cfg.title, control, ref, wing, fus, raw_pods, raw_fins, raw_cans,
                           cases)
    return Deck((dc,))


def _single_configuration_cases(cases):
    """The case cards of a configuration written alone: the last one gets NCON = 0.

    A case read from configuration k of a multi-configuration deck may carry NCON = 1 ("a new
    configuration follows"); in a deck holding this configuration only, none follows.
    """
    cases = tuple(cases)
    if cases and cases[-1].ncon != 0:
        last = cases[-1]
        fields = {name: getattr(last, name) for name in CASE_FIELDS}
        cases = cases[:-1] + (DeckCase(last.ncase, **{**fields, "ncon": 0}, xrest=last.xrest),)
    return cases


def _splits_inboard(c):
    return not (np.array_equal(c.upper_inboard, c.upper_outboard)
                and np.array_equal(c.lower_inboard, c.lower_outboard))


def _splits_upper(c):
    return not (np.array_equal(c.upper_inboard, c.lower_inboard)
                and np.array_equal(c.upper_outboard, c.lower_outboard))


def _common_canard_sets(cans):
    """All canards share the deck's NCAN / NCANOR signs: give each the union of splits."""
    if not cans:
        return cans
    inb = any(_splits_inboard(c) for c in cans)
    upp = any(_splits_upper(c) for c in cans)
    n_sets = (2 if inb else 1) * (2 if upp else 1)
    return [c if c.n_sets == n_sets else DeckCanard(c.origins, c.xcan, c.upper_inboard,
                                                    c.upper_outboard, c.lower_inboard,
                                                    c.lower_outboard, n_sets) for c in cans]
