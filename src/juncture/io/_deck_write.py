"""Write the raw records of :mod:`._deck` back as wave-drag deck cards.

Each real goes into a 7-column field as the shortest text that reads back to exactly the same
float (:func:`._cards.format_real`); identification labels go in columns 73-80 (``XAF``,
``WAFORG 3``, ``WAFORD2U``, ...; never read). Before writing, the records are checked against
the control card so that the file reads back to the same deck; a record the control card
cannot express (say a canard with four different ordinate sets under NCAN > 0) is an error
rather than a silent loss.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..errors import DeckError, JunctureError
from ._cards import LABEL_COLUMN, CardReader, format_card, format_ints
from ._deck import CASE_FIELDS

__all__ = ["format_deck"]

_SET_SUFFIX = {"all": "", "inboard": "I", "outboard": "O", "upper": "U", "lower": "L",
               "inboard upper": "IU", "outboard upper": "OU", "inboard lower": "IL",
               "outboard lower": "OL"}


def _tag(name, number, suffix=""):
    """An identification label of at most 8 characters: ``"WAFORG 3"``, ``"WAFORD2U"``."""
    for text in (f"{name} {number}{suffix}", f"{name}{number}{suffix}",
                 f"{name[:-1]}{number}{suffix}", f"{name[:-2]}{number}{suffix}"):
        if len(text) <= 8:
            return text
    return f"{name}{number}{suffix}"[:8]


def _same(a, b):
    return a is b or (a is not None and b is not None and np.array_equal(a, b))


class _Writer:
    def __init__(self, index):
        self.k = index + 1
        self.out = []

    def fail(self, message):
        return JunctureError(f"cannot write configuration {self.k}: {message}")

    def card(self, values, label, what, count=None):
        values = np.asarray(values, dtype=float).ravel()
        if count is not None and values.size != count:
            raise self.fail(f"{what} has {values.size} values, the control card says {count}")
        self.out += format_card(values, label, f"configuration {self.k}, {what} value")

    # -- components ------------------------------------------------------------------------

    def wing(self, c, w):
        n, m = abs(c.nwafor), c.nwaf
        if w.origins.shape[0] != m or w.xaf.shape[0] != n:
            raise self.fail(f"the wing has {w.origins.shape[0]} sections of {w.xaf.shape[0]} "
                            f"stations, the control card says NWAF = {m}, |NWAFOR| = {n}")
        if c.j1 == -1 and w.tzord is not None and np.any(w.tzord != 0):
            raise self.fail("the wing has camber (TZORD) but J1 = -1 (uncambered)")
        if c.j1 == 1 and w.tzord is None:
            raise self.fail("J1 = 1 (cambered wing) but the wing has no TZORD")
        if c.nwafor < 0 and w.waford_lower is None:
            raise self.fail("NWAFOR < 0 (upper and lower ordinates) but the wing has no "
                            "lower ordinates")
        if c.nwafor > 0 and w.waford_lower is not None \
                and not _same(w.waford_lower, w.waford_upper):
            raise self.fail("the wing has different upper and lower ordinates but NWAFOR > 0 "
                            "(symmetric sections)")
        self.card(w.xaf, "XAF", "XAF")
        for i in range(m):
            self.card(w.origins[i], _tag("WAFORG", i + 1), f"WAFORG {i + 1}")
        if c.j1 == 1:
            for i in range(m):
                self.card(w.tzord[i], _tag("TZORD", i + 1), f"TZORD {i + 1}")
        for i in range(m):
            if c.nwafor > 0:
                self.card(w.waford_upper[i], _tag("WAFORD", i + 1), f"WAFORD {i + 1}")
            else:
                self.card(w.waford_upper[i], _tag("WAFORD", i + 1, "U"), f"WAFORD {i + 1} up")
                self.card(w.waford_lower[i], _tag("WAFORD", i + 1, "L"), f"WAFORD {i + 1} lo")

    def fuselage(self, c, f):
        if len(f.segments) != c.nfus:
            raise self.fail(f"the fuselage has {len(f.segments)} segments, NFUS = {c.nfus}")
        for s, seg in enumerate(f.segments):
            n, nr, num = c.nforx[s], c.nradx[s], s + 1
            self.card(seg.x, _tag("XFUS", num), f"XFUS {num}", n)
            if c.j2 == -1:
                if seg.area is None:
                    raise self.fail(f"J2 = -1 (circular) but segment {num} has no areas")
                if c.j6 == 0:
                    zfus = np.zeros(n) if seg.zfus is None else seg.zfus
                    self.card(zfus, _tag("ZFUS", num), f"ZFUS {num}", n)
                elif seg.zfus is not None and np.any(seg.zfus != 0):
                    raise self.fail(f"segment {num} has ZFUS but J6 = {c.j6} (no ZFUS cards)")
                self.card(seg.area, _tag("FUSARD", num), f"FUSARD {num}", n)
            else:
                if seg.y is None or seg.y.shape != (n, nr):
                    shape = None if seg.y is None else seg.y.shape
                    raise self.fail(f"J2 = 1 (arbitrary) needs y and z of shape ({n}, {nr}) "
                                    f"for segment {num}, found {shape}")
                for j in range(n):
                    self.card(seg.y[j], f"Y {num}-{j + 1}"[:8], f"Y {num}-{j + 1}")
                    self.card(seg.z[j], f"Z {num}-{j + 1}"[:8], f"Z {num}-{j + 1}")

    def pods(self, c, pods):
        if len(pods) != max(c.np, 0):
            raise self.fail(f"{len(pods)} pods, the control card says NP = {c.np}")
        for k, pod in enumerate(pods, 1):
            self.card(pod.origin, _tag("PODORG", k), f"PODORG {k}")
            self.card(pod.x, _tag("XPOD", k), f"XPOD {k}", c.npodor)
            self.card(pod.radius, _tag("PODR", k), f"PODR {k}", c.npodor)

    def fins(self, c, fins):
        if len(fins) != abs(c.nf):
            raise self.fail(f"{len(fins)} fins, the control card says NF = {c.nf}")
        for k, fin in enumerate(fins, 1):
            if c.nf < 0 and fin.inboard is None:
                raise self.fail(f"NF < 0 (two ordinate sets) but fin {k} has no inboard set")
            if c.nf > 0 and fin.inboard is not None and not _same(fin.inboard, fin.outboard):
                raise self.fail(f"fin {k} has different inboard and outboard ordinates but "
                                "NF > 0 (symmetric)")
            self.card(fin.origins, _tag("FINORG", k), f"FINORG {k}")
            self.card(fin.xfin, _tag("XFIN", k), f"XFIN {k}", c.nfinor)
            if c.nf > 0:
                self.card(fin.outboard, _tag("FINORD", k), f"FINORD {k}", c.nfinor)
            else:
                self.card(fin.outboard, _tag("FINORD", k, "O"), f"FINORD {k} out", c.nfinor)
                self.card(fin.inboard, _tag("FINORD", k, "I"), f"FINORD {k} in", c.nfinor)

    def canards(self, c, canards):
        if len(canards) != abs(c.ncan):
            raise self.fail(f"{len(canards)} canards, the control card says NCAN = {c.ncan}")
        n = abs(c.ncanor)
        for k, can in enumerate(canards, 1):
            ui, uo, li, lo = can.upper_inboard, can.upper_outboard, can.lower_inboard, \
                can.lower_outboard
            if c.ncan < 0 and c.ncanor < 0:
                sets, dropped = {"inboard upper": ui, "outboard upper": uo,
                                 "inboard lower": li, "outboard lower": lo}, ()
            elif c.ncan < 0:
                sets, dropped = {"inboard": ui, "outboard": uo}, ((li, ui), (lo, uo))
            elif c.ncanor < 0:
                sets, dropped = {"upper": ui, "lower": li}, ((uo, ui), (lo, li))
            else:
                sets, dropped = {"all": ui}, ((uo, ui), (li, ui), (lo, ui))
            if can.n_sets != len(sets) or not all(_same(a, b) for a, b in dropped):
                raise self.fail(f"canard {k} has {can.n_sets} different ordinate sets but the "
                                f"signs of NCAN = {c.ncan} and NCANOR = {c.ncanor} give "
                                f"{len(sets)}")
            self.card(can.origins, _tag("CANORG", k), f"CANORG {k}")
            self.card(can.xcan, _tag("XCAN", k), f"XCAN {k}", n)
            for name, arr in sets.items():
                self.card(arr, _tag("CANORD", k, _SET_SUFFIX[name]), f"CANORD {k} {name}", n)

    def case(self, k, case, ncon):
        fields = case.fields()
        if fields[CASE_FIELDS.index("ncon")] != ncon:
            raise self.fail(f"case {k} has NCON = {case.ncon}; it must be {ncon} "
                            + ("(the last case of a configuration followed by another)"
                               if ncon else "(only the last case of a configuration that is "
                               "followed by another has NCON = 1)"))
        if len(case.ncase) > 4 or any(ch in case.ncase for ch in "\r\n\t"):
            raise self.fail(f"case {k}: NCASE {case.ncase!r} must be at most 4 plain "
                            "characters")
        self.out.append(_case_text(case, k))
        if case.nrest > 0:
            if case.xrest is None:
                raise self.fail(f"case {k} has NREST = {case.nrest} but no restraint stations")
            self.card(case.xrest, "XREST", f"XREST of case {k}", case.nrest)


def _case_text(case, k):
    """The raw text of a case card if it still reads to the fields, else a card built anew."""
    if case.text is not None and "\n" not in case.text and "\r" not in case.text:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                reader = CardReader(case.text)
                text = reader.lines[0] if reader.lines else ""
                read = tuple(reader.integer(text, 1, 4 * i + 5, 4 * i + 8, "")
                             for i in range(len(CASE_FIELDS)))
            if read == case.fields() and reader.text(text, 1, 1, 4) == case.ncase.ljust(4) \
                    and not reader.warnings and len(case.text) <= 80:
                return case.text
        except DeckError:
            pass
    ints = format_ints(case.fields(), 4, what="case card field")
    return (case.ncase.ljust(4) + ints).ljust(LABEL_COLUMN - 1) + f"CASE {k}"[:8]


def format_deck(deck):
    """Text of a deck (LF line endings), one card per line.

    A component whose flag is 2 is written as no cards at all (the reader takes the previous
    configuration's), whatever object the configuration holds for it.

    Raises
    ------
    JunctureError
        If a record does not agree with its control card (counts, shapes, sign rules), a
        flag 2 appears in the first configuration, NCON does not chain the configurations,
        or a value is not finite.
    """
    out = []
    configurations = deck.configurations
    if not configurations:
        raise JunctureError("cannot write a deck without configurations")
    for index, cfg in enumerate(configurations):
        w = _Writer(index)
        c = cfg.control
        title = cfg.title
        if len(title) > 80 or "\n" in title or "\r" in title:
            raise w.fail("the title must be one line of at most 80 characters")
        w.out.append(title.rstrip(" "))
        w.out.append(format_ints(c.values(), 3, label=" CONTROL", what="control card field"))
        flags = (c.j0, c.j1, c.j2, c.j3, c.j4, c.j5)
        if index == 0 and 2 in flags:
            raise w.fail("a flag of value 2 (use the previous configuration's component) in "
                         "the first configuration")
        if c.j0 == 1:
            if cfg.reference is None:
                raise w.fail("J0 = 1 but there is no reference card")
            w.card(cfg.reference, "REFA", "REFA")
        for flag, values, method, name in (
                (c.j1 in (1, -1), cfg.wing, w.wing, "wing"),
                (c.j2 in (1, -1), cfg.fuselage, w.fuselage, "fuselage"),
                (c.j3 == 1, cfg.pods, w.pods, None), (c.j4 == 1, cfg.fins, w.fins, None),
                (c.j5 == 1, cfg.canards, w.canards, None)):
            if flag:
                if name and values is None:
                    raise w.fail(f"the control card has a {name} but the configuration has "
                                 "none")
                method(c, values)
        last = index == len(configurations) - 1
        if not last and not cfg.cases:
            raise w.fail("a configuration followed by another needs a case card (NCON = 1)")
        for k, case in enumerate(cfg.cases, 1):
            w.case(k, case, 0 if last or k < len(cfg.cases) else 1)
        out += w.out
    return "\n".join(out) + "\n"
