"""Raw, lossless records of a wave-drag (Harris / D2500 / AWAVE) deck, card for card.

These classes mirror the cards of ``formats.md`` section 1 without interpreting them: percent
chord stays percent chord, fuselage areas stay areas, flags of value 2 stay 2. The model layer
(``_deck_convert``) turns them into a Configuration. All arrays are float64 and read-only;
the classes are frozen and slotted, and compare by identity (``eq=False``).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields

import numpy as np

from ..errors import JunctureError

__all__ = ["ControlCard", "DeckWing", "DeckFuselageSegment", "DeckFuselage", "DeckPod",
           "DeckFin", "DeckCanard", "DeckCase", "DeckConfiguration", "Deck", "CASE_FIELDS"]

#: Names of the eleven integer fields of a case card (``A4,11I4`` after NCASE).
CASE_FIELDS = ("mach", "nx", "ntheta", "nrest", "ncon", "icyc", "kkode", "jrst", "ialph",
               "iup1", "iup2")


def _array(value, name, shape=None, optional=False):
    """A read-only float64 copy of ``value``, checked against ``shape`` (None = any size)."""
    if value is None:
        if optional:
            return None
        raise JunctureError(f"{name} is required")
    arr = np.array(value, dtype=float)
    if shape is not None:
        ok = arr.ndim == len(shape) and all(
            s is None or s == n for s, n in zip(shape, arr.shape, strict=True))
        if not ok:
            want = "(" + ", ".join("n" if s is None else str(s) for s in shape) + ")"
            raise JunctureError(f"{name} must have shape {want}, found {arr.shape}")
    arr.flags.writeable = False
    return arr


def _freeze(obj, specs):
    for name, shape, optional in specs:
        object.__setattr__(obj, name, _array(getattr(obj, name), name, shape, optional))


@dataclass(frozen=True, slots=True)
class ControlCard:
    """The Geometry Input Control Card (card 2, ``24I3``), field by field (formats.md 1.2).

    ``j0`` reference card; ``j1`` wing (1 cambered, -1 uncambered); ``j2`` fuselage (1
    arbitrary, -1 circular); ``j3`` pods; ``j4`` fins; ``j5`` canards; each 0 absent, 2 the
    previous configuration's. ``j6`` X-Y symmetry. ``nwafor < 0``: upper and lower wing
    ordinates; ``nf < 0``: outboard and inboard fin ordinates; ``ncan < 0``: inboard and
    outboard canard ordinates; ``ncanor < 0``: upper and lower canard ordinates.
    """

    j0: int = 0
    j1: int = 0
    j2: int = 0
    j3: int = 0
    j4: int = 0
    j5: int = 0
    j6: int = 0
    nwaf: int = 0
    nwafor: int = 0
    nfus: int = 0
    nradx: tuple = (0, 0, 0, 0)
    nforx: tuple = (0, 0, 0, 0)
    np: int = 0
    npodor: int = 0
    nf: int = 0
    nfinor: int = 0
    ncan: int = 0
    ncanor: int = 0

    def __post_init__(self):
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name in ("nradx", "nforx"):
                v = tuple(int(x) for x in v)
                if len(v) != 4:
                    raise JunctureError(f"{f.name} must hold 4 integers, found {len(v)}")
            else:
                v = int(v)
            object.__setattr__(self, f.name, v)

    def values(self):
        """The 24 integers in card order."""
        r, f = self.nradx, self.nforx
        return (self.j0, self.j1, self.j2, self.j3, self.j4, self.j5, self.j6, self.nwaf,
                self.nwafor, self.nfus, r[0], f[0], r[1], f[1], r[2], f[2], r[3], f[3],
                self.np, self.npodor, self.nf, self.nfinor, self.ncan, self.ncanor)

    @classmethod
    def from_values(cls, v):
        """Build from the 24 integers in card order."""
        v = [int(x) for x in v]
        if len(v) != 24:
            raise JunctureError(f"a control card holds 24 integers, found {len(v)}")
        return cls(*v[:10], nradx=tuple(v[10:18:2]), nforx=tuple(v[11:18:2]), np=v[18],
                   npodor=v[19], nf=v[20], nfinor=v[21], ncan=v[22], ncanor=v[23])


@dataclass(frozen=True, slots=True, eq=False)
class DeckWing:
    """Wing cards (formats.md 1.4): XAF, WAFORG, TZORD, WAFORD.

    Attributes
    ----------
    xaf : (n,) float
        Chordwise stations, percent chord, shared by all sections.
    origins : (nwaf, 4) float
        WAFORG per section, inboard first: x_le, y_le, z_le, chord [deck length].
    tzord : (nwaf, n) float or None
        Camber ordinates (absolute z above the LE) [deck length]; None when J1 = -1.
    waford_upper : (nwaf, n) float
        Half-thickness (upper, or both when symmetric) [percent chord].
    waford_lower : (nwaf, n) float or None
        Lower half-thickness [percent chord]; None when NWAFOR > 0 (symmetric sections).
    """

    xaf: np.ndarray
    origins: np.ndarray
    tzord: np.ndarray | None
    waford_upper: np.ndarray
    waford_lower: np.ndarray | None = None

    def __post_init__(self):
        _freeze(self, [("xaf", (None,), False)])
        n = self.xaf.shape[0]
        _freeze(self, [("origins", (None, 4), False)])
        m = self.origins.shape[0]
        _freeze(self, [("tzord", (m, n), True), ("waford_upper", (m, n), False),
                       ("waford_lower", (m, n), True)])


@dataclass(frozen=True, slots=True, eq=False)
class DeckFuselageSegment:
    """One fuselage segment (formats.md 1.5).

    Attributes
    ----------
    x : (nforx,) float
        XFUS stations [deck length].
    zfus : (nforx,) float or None
        Centre z of circular sections (J2 = -1 and J6 = 0 only).
    area : (nforx,) float or None
        FUSARD cross-section areas (J2 = -1) [deck length^2]; radius = sqrt(area / pi).
    y, z : (nforx, nradx) float or None
        Half-section points, bottom to top (J2 = +1).
    """

    x: np.ndarray
    zfus: np.ndarray | None = None
    area: np.ndarray | None = None
    y: np.ndarray | None = None
    z: np.ndarray | None = None

    def __post_init__(self):
        _freeze(self, [("x", (None,), False)])
        n = self.x.shape[0]
        _freeze(self, [("zfus", (n,), True), ("area", (n,), True), ("y", (n, None), True)])
        _freeze(self, [("z", (n, None if self.y is None else self.y.shape[1]), True)])
        if (self.y is None) != (self.z is None):
            raise JunctureError("a fuselage segment needs both y and z, or neither")
        if (self.area is None) == (self.y is None):
            raise JunctureError("a fuselage segment has either areas (circular) or y/z "
                                "points (arbitrary)")


@dataclass(frozen=True, slots=True, eq=False)
class DeckFuselage:
    """The fuselage: NFUS consecutive segments along x (formats.md 1.5)."""

    segments: tuple

    def __post_init__(self):
        object.__setattr__(self, "segments", tuple(self.segments))
        if not all(isinstance(s, DeckFuselageSegment) for s in self.segments):
            raise JunctureError("fuselage segments must be DeckFuselageSegment objects")


@dataclass(frozen=True, slots=True, eq=False)
class DeckPod:
    """One pod (formats.md 1.6): PODORG origin (3,), XPOD (relative x) and PODR radii (n,)."""

    origin: np.ndarray
    x: np.ndarray
    radius: np.ndarray

    def __post_init__(self):
        _freeze(self, [("origin", (3,), False), ("x", (None,), False)])
        _freeze(self, [("radius", self.x.shape, False)])


@dataclass(frozen=True, slots=True, eq=False)
class DeckFin:
    """One fin (formats.md 1.7).

    Attributes
    ----------
    origins : (2, 4) float
        FINORG: root (lower) then tip (upper) airfoil: x_le, y_le, z_le, chord.
    xfin : (n,) float
        Percent-chord stations.
    outboard : (n,) float
        Half-thickness, outboard side (both sides when NF > 0) [percent chord].
    inboard : (n,) float or None
        Inboard side (NF < 0 only).
    """

    origins: np.ndarray
    xfin: np.ndarray
    outboard: np.ndarray
    inboard: np.ndarray | None = None

    def __post_init__(self):
        _freeze(self, [("origins", (2, 4), False), ("xfin", (None,), False)])
        n = self.xfin.shape
        _freeze(self, [("outboard", n, False), ("inboard", n, True)])


@dataclass(frozen=True, slots=True, eq=False)
class DeckCanard:
    """One canard or horizontal tail (formats.md 1.8).

    The deck gives 1, 2 or 4 ordinate sets depending on the signs of NCAN and NCANOR; the
    reader fills all four arrays (with 1 set, all four are the same array object) and
    ``n_sets`` records how many were read, so the writer writes the same count.

    Attributes
    ----------
    origins : (2, 4) float
        CANORG: inboard then outboard airfoil: x_le, y_le, z_le, chord.
    xcan : (n,) float
        Percent-chord stations.
    upper_inboard, upper_outboard, lower_inboard, lower_outboard : (n,) float
        Half-thickness above / below the chord plane [percent chord].
    n_sets : int
        1, 2 or 4.
    """

    origins: np.ndarray
    xcan: np.ndarray
    upper_inboard: np.ndarray
    upper_outboard: np.ndarray
    lower_inboard: np.ndarray
    lower_outboard: np.ndarray
    n_sets: int = 1

    def __post_init__(self):
        _freeze(self, [("origins", (2, 4), False), ("xcan", (None,), False)])
        n = self.xcan.shape
        seen = {}
        for name in ("upper_inboard", "upper_outboard", "lower_inboard", "lower_outboard"):
            value = getattr(self, name)
            key = id(value)
            if key not in seen:  # keep shared arrays shared
                seen[key] = _array(value, name, n)
            object.__setattr__(self, name, seen[key])
        if self.n_sets not in (1, 2, 4):
            raise JunctureError(f"n_sets must be 1, 2 or 4, found {self.n_sets}")


@dataclass(frozen=True, slots=True, eq=False)
class DeckCase:
    """A case control card (``A4,11I4``, formats.md 1.9) and its restraint stations.

    Attributes
    ----------
    text : str or None
        The card as read (columns 1-80, trailing blanks removed); written back verbatim when
        it still parses to the fields below.
    ncase : str
        Columns 1-4 as read (4 characters).
    mach, nx, ntheta, nrest, ncon, icyc, kkode, jrst, ialph, iup1, iup2 : int
        The integer fields (blank = 0); ``mach`` is Mach x 1000, ``ialph`` alpha x 100.
    xrest : (nrest,) float or None
        Restraint x stations (NREST > 0).
    """

    ncase: str = "    "
    mach: int = 0
    nx: int = 0
    ntheta: int = 0
    nrest: int = 0
    ncon: int = 0
    icyc: int = 0
    kkode: int = 0
    jrst: int = 0
    ialph: int = 0
    iup1: int = 0
    iup2: int = 0
    xrest: np.ndarray | None = None
    text: str | None = None

    def __post_init__(self):
        for name in CASE_FIELDS:
            object.__setattr__(self, name, int(getattr(self, name)))
        _freeze(self, [("xrest", (None,), True)])

    def fields(self):
        """The eleven integers in card order."""
        return tuple(getattr(self, name) for name in CASE_FIELDS)


@dataclass(frozen=True, slots=True, eq=False)
class DeckConfiguration:
    """One configuration of a deck: title, control card, components and case cards.

    A component whose flag is 2 refers to the previous configuration's object (the writer
    writes no cards for it); likewise ``reference`` when J0 = 2.

    Attributes
    ----------
    title : str
        Card 1 (columns 1-80, trailing blanks removed).
    control : ControlCard
    reference : tuple of 3 float or None
        REFA, CBAR, XMC.
    wing : DeckWing or None
    fuselage : DeckFuselage or None
    pods, fins, canards : tuple
    cases : tuple of DeckCase
    lines : dict
        1-based line number of the first card of each record, keyed ``"title"``,
        ``"control"``, ``"reference"``, ``"xaf"``, ``"waforg 3"``, ``"tzord 3"``,
        ``"waford 3 upper"``, ``"waford 3 lower"``, ``"xfus 1"``, ``"zfus 1"``,
        ``"fusard 1"``, ``"y 1-4"``, ``"z 1-4"`` (segment-station), ``"podorg 1"``,
        ``"xpod 1"``, ``"podr 1"``, ``"finorg 1"``, ``"xfin 1"``, ``"finord 1 outboard"``,
        ``"finord 1 inboard"``, ``"canorg 1"``, ``"xcan 1"``, ``"canord 1 <set>"``
        (set ``all``, ``inboard``, ``outboard``, ``upper``, ``lower``, ``inboard upper``, ...),
        ``"case 1"``, ``"xrest 1"``. Empty for decks built in memory.
    """

    title: str
    control: ControlCard
    reference: tuple | None = None
    wing: DeckWing | None = None
    fuselage: DeckFuselage | None = None
    pods: tuple = ()
    fins: tuple = ()
    canards: tuple = ()
    cases: tuple = ()
    lines: dict = field(default_factory=dict)

    def __post_init__(self):
        for name in ("pods", "fins", "canards", "cases"):
            object.__setattr__(self, name, tuple(getattr(self, name)))
        if self.reference is not None:
            ref = tuple(float(v) for v in self.reference)
            if len(ref) != 3:
                raise JunctureError(f"reference must be (refa, cbar, xmc), found {len(ref)} "
                                    "values")
            object.__setattr__(self, "reference", ref)


@dataclass(frozen=True, slots=True, eq=False)
class Deck:
    """A whole deck: one or more configurations (chained by NCON = 1 on a case card).

    Attributes
    ----------
    configurations : tuple of DeckConfiguration
    path : str or None
        The file read, if any.
    warnings : tuple of str
        Everything accepted with a warning while reading (ranges, embedded blanks, ...).
    """

    configurations: tuple
    path: str | None = None
    warnings: tuple = ()

    def __post_init__(self):
        object.__setattr__(self, "configurations", tuple(self.configurations))
        object.__setattr__(self, "warnings", tuple(self.warnings))
