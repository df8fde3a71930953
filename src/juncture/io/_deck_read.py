"""Parse the cards of a wave-drag deck into the raw records of :mod:`._deck`.

Reading order, card counts and sign rules follow ``formats.md`` sections 1.1-1.10 (AWAVE user's
guide, cross-checked against PDAS ``wd2wgs``). Every fault is a :class:`DeckError` naming the
line, the columns and the record being read; limits of the original programs are warnings.
"""

from __future__ import annotations

import numpy as np

from ._cards import CardReader
from ._deck import (
    CASE_FIELDS,
    ControlCard,
    Deck,
    DeckCanard,
    DeckCase,
    DeckConfiguration,
    DeckFin,
    DeckFuselage,
    DeckFuselageSegment,
    DeckPod,
    DeckWing,
)

__all__ = ["parse_deck"]

_CONTROL_NAMES = ("J0", "J1", "J2", "J3", "J4", "J5", "J6", "NWAF", "NWAFOR", "NFUS",
                  "NRADX(1)", "NFORX(1)", "NRADX(2)", "NFORX(2)", "NRADX(3)", "NFORX(3)",
                  "NRADX(4)", "NFORX(4)", "NP", "NPODOR", "NF", "NFINOR", "NCAN", "NCANOR")
_FLAGS = {  # flag index: (allowed values, component)
    0: ((0, 1, 2), "reference area"), 1: ((-1, 0, 1, 2), "wing"),
    2: ((-1, 0, 1, 2), "fuselage"), 3: ((0, 1, 2), "pods"), 4: ((0, 1, 2), "fins"),
    5: ((0, 1, 2), "canards"), 6: ((-1, 0, 1), "X-Y symmetry"),
}
#: Documented ranges of AWAVE (formats.md 1.2); outside them is a warning only.
_RANGES = {"NWAF": (2, 20), "NWAFOR": (3, 30), "NRADX": (3, 30), "NFORX": (4, 30),
           "NP": (0, 9), "NPODOR": (4, 30), "NF": (0, 6), "NFINOR": (3, 10), "NCAN": (0, 2),
           "NCANOR": (3, 10), "NREST": (0, 10)}
#: Canard ordinate sets by (NCAN < 0, NCANOR < 0), and the array each set fills.
_CANARD_SETS = {
    (False, False): ("all",),
    (True, False): ("inboard", "outboard"),
    (False, True): ("upper", "lower"),
    (True, True): ("inboard upper", "outboard upper", "inboard lower", "outboard lower"),
}


def _cols(i):
    """Columns of control-card field ``i`` (0-based)."""
    return 3 * i + 1, 3 * i + 3


class _Parser:
    """One pass over the cards; holds the reader and the configuration being built."""

    def __init__(self, text, path):
        self.r = CardReader(text, path)

    # -- helpers ---------------------------------------------------------------------------

    def values(self, n, card, where="", names=None, key=None):
        vals, first = self.r.reals(n, card, where, names)
        if key is not None and first is not None:
            self.lines[key] = first
        return vals, first

    def fail(self, message, first, i):
        line, cols = self.r.position(first, i)
        return self.r.error(message, line=line, columns=cols)

    def nonnegative(self, vals, first, what, offset=0):
        bad = np.flatnonzero(vals < 0)
        if bad.size:
            i = int(bad[0])
            raise self.fail(f"{what} must not be negative, found {float(vals[i])!r} "
                            f"(value {i + 1})", first, i + offset)

    def increasing(self, vals, first, what, strict=True):
        d = np.diff(vals)
        bad = np.flatnonzero(d <= 0 if strict else d < 0)
        if bad.size:
            i = int(bad[0]) + 1
            word = "increase" if strict else "not decrease"
            raise self.fail(f"{what} must {word}: value {i + 1} ({float(vals[i])!r}) after "
                            f"value {i} ({float(vals[i - 1])!r})", first, i)

    def range_warning(self, name, value, i):
        lo, hi = _RANGES[name.split("(")[0]]
        if not lo <= value <= hi:
            self.r.warn(f"{name} = {value} is outside the documented range {lo}..{hi} of AWAVE",
                        self.lines["control"], _cols(i))

    # -- the deck --------------------------------------------------------------------------

    def deck(self):
        configurations = []
        more = True
        while more:
            cfg, more = self.configuration(configurations[-1] if configurations else None,
                                           len(configurations) + 1)
            configurations.append(cfg)
        return Deck(configurations, path=self.r.path, warnings=self.r.warnings)

    def configuration(self, prev, k):
        self.lines = {}
        r = self.r
        suffix = "" if k == 1 else f" of configuration {k}"
        line, text = r.next_card(f"the title card{suffix}")
        self.lines["title"] = line
        if len(text.rstrip(" ")) > 80:
            r.warn("title card longer than 80 columns; columns 81 and up ignored", line)
        title = text[:80].rstrip(" ")
        control = self.control(prev, k, suffix)
        c = control
        reference = None
        if c.j0 == 1:
            reference = tuple(self.values(3, "REFA", names=("REFA", "CBAR", "XMC"),
                                          key="reference")[0])
        parts = {
            "reference": reference if c.j0 != 2 else prev.reference,
            "wing": self.wing(c) if c.j1 in (1, -1) else (prev.wing if c.j1 == 2 else None),
            "fuselage": (self.fuselage(c) if c.j2 in (1, -1)
                         else (prev.fuselage if c.j2 == 2 else None)),
            "pods": self.pods(c) if c.j3 == 1 else (prev.pods if c.j3 == 2 else ()),
            "fins": self.fins(c) if c.j4 == 1 else (prev.fins if c.j4 == 2 else ()),
            "canards": self.canards(c) if c.j5 == 1 else (prev.canards if c.j5 == 2 else ()),
        }
        cases, more = self.cases()
        return DeckConfiguration(title, control, cases=cases, lines=self.lines,
                                 **parts), more

    # -- control card ----------------------------------------------------------------------

    def control(self, prev, k, suffix):
        r = self.r
        line, text = r.next_card(f"the control card{suffix}")
        self.lines["control"] = line
        v = [r.integer(text, line, *_cols(i), f"{name} on the control card")
             for i, name in enumerate(_CONTROL_NAMES)]
        for i, (allowed, component) in _FLAGS.items():
            name = _CONTROL_NAMES[i]
            if v[i] not in allowed:
                raise r.error(f"unknown value {name} = {v[i]} ({component} flag); expected "
                              f"one of {', '.join(map(str, allowed))}", line, _cols(i))
            if v[i] == 2:
                if prev is None:
                    raise r.error(f"{name} = 2 (use the previous configuration's {component})"
                                  " in the first configuration", line, _cols(i))
                previous = (prev.reference, prev.wing, prev.fuselage, prev.pods, prev.fins,
                            prev.canards)[i]
                if previous is None or previous == ():
                    raise r.error(f"{name} = 2 (use the previous configuration's {component})"
                                  f" but configuration {k - 1} has none", line, _cols(i))
        c = ControlCard.from_values(v)
        if c.j2 == 1 and c.j6 == 1:
            raise r.error("J2 = 1 (arbitrary fuselage) and J6 = 1 (symmetric about the X-Y "
                          "plane, which implies a circular fuselage) cannot both be set",
                          line, (7, 21))
        self.check_counts(c, v, line)
        return c

    def check_counts(self, c, v, line):
        r = self.r

        def need(ok, i, text):
            if not ok:
                raise r.error(f"{_CONTROL_NAMES[i]} = {v[i]}: {text}", line, _cols(i))

        if c.j1 in (1, -1):
            need(c.nwaf >= 2, 7, "a wing needs at least 2 sections")
            need(c.nwafor != 0, 8, "a wing needs chordwise stations")
            self.range_warning("NWAF", c.nwaf, 7)
            self.range_warning("NWAFOR", abs(c.nwafor), 8)
        if c.j2 in (1, -1):
            need(1 <= c.nfus <= 4, 9, "a fuselage has 1 to 4 segments (the control card "
                 "holds counts for 4)")
            for s in range(c.nfus):
                need(c.nforx[s] >= 1, 11 + 2 * s, f"segment {s + 1} needs x stations")
                if c.j2 == 1:
                    need(c.nradx[s] >= 1, 10 + 2 * s, f"segment {s + 1} needs points per "
                         "half-section")
                self.range_warning(_CONTROL_NAMES[10 + 2 * s], c.nradx[s], 10 + 2 * s)
                self.range_warning(_CONTROL_NAMES[11 + 2 * s], c.nforx[s], 11 + 2 * s)
        for flag, jname, ci, si, component in ((c.j3, "J3", 18, 19, "pods"),
                                               (c.j4, "J4", 20, 21, "fins"),
                                               (c.j5, "J5", 22, 23, "canards")):
            if flag != 1:
                continue
            count, stations = v[ci], v[si]
            if component == "pods":
                need(count >= 0, ci, "the number of pods cannot be negative")
            if count == 0:
                r.warn(f"{jname} = 1 but {_CONTROL_NAMES[ci]} = 0: no {component} read", line,
                       _cols(ci))
                continue
            if component == "canards":
                need(stations != 0, si, "canards need chordwise stations")
            else:
                need(stations >= 1, si, f"{component} need at least one station")
            self.range_warning(_CONTROL_NAMES[ci], abs(count), ci)
            self.range_warning(_CONTROL_NAMES[si], abs(stations), si)

    # -- components ------------------------------------------------------------------------

    def wing(self, c):
        n, m = abs(c.nwafor), c.nwaf
        xaf, first = self.values(n, "XAF", key="xaf")
        self.increasing(xaf, first, "XAF (percent chord)")
        origins = np.zeros((m, 4))
        for i in range(m):
            where = f"for section {i + 1}"
            origins[i], first = self.values(4, "WAFORG", where, ("x", "y", "z", "chord"),
                                            key=f"waforg {i + 1}")
            if origins[i, 3] < 0:
                raise self.fail(f"WAFORG chord {where} must not be negative, found "
                                f"{float(origins[i, 3])!r}", first, 3)
            if i and origins[i, 1] <= origins[i - 1, 1]:
                raise self.fail(f"wing sections must be in increasing y: section {i + 1} has "
                                f"y = {float(origins[i, 1])!r}, section {i} has y = "
                                f"{float(origins[i - 1, 1])!r}", first, 1)
        tzord = None
        if c.j1 == 1:
            tzord = np.zeros((m, n))
            for i in range(m):
                tzord[i] = self.values(n, "TZORD", f"for section {i + 1}",
                                       key=f"tzord {i + 1}")[0]
        upper, lower = np.zeros((m, n)), (np.zeros((m, n)) if c.nwafor < 0 else None)
        for i in range(m):
            where = f"for section {i + 1}"
            sides = ((upper, "upper"),) if lower is None else ((upper, "upper"), (lower, "lower"))
            for arr, side in sides:
                card = "WAFORD" if lower is None else f"WAFORD {side}"
                arr[i], first = self.values(n, card, where, key=f"waford {i + 1} {side}")
                self.nonnegative(arr[i], first, f"{card} (half-thickness) {where}")
        return DeckWing(xaf, origins, tzord, upper, lower)

    def fuselage(self, c):
        segments = []
        last = None  # (x, first line, index) of the previous segment's last station
        for s in range(c.nfus):
            n, where = c.nforx[s], f"for segment {s + 1}"
            x, first = self.values(n, "XFUS", where, key=f"xfus {s + 1}")
            self.increasing(x, first, f"XFUS {where}", strict=False)
            if last is not None and x[0] < last:
                raise self.fail(f"XFUS must not decrease across segments: segment {s + 1} "
                                f"starts at x = {float(x[0])!r}, segment {s} ends at x = "
                                f"{float(last)!r}", first, 0)
            last = x[-1]
            zfus = area = y = z = None
            if c.j2 == -1:
                if c.j6 == 0:
                    zfus = self.values(n, "ZFUS", where, key=f"zfus {s + 1}")[0]
                area, first = self.values(n, "FUSARD", where, key=f"fusard {s + 1}")
                self.nonnegative(area, first, f"FUSARD (cross-section area) {where}")
            else:
                nr = c.nradx[s]
                y, z = np.zeros((n, nr)), np.zeros((n, nr))
                for j in range(n):
                    at = f"for segment {s + 1}, station {j + 1}"
                    y[j] = self.values(nr, "Y", at, key=f"y {s + 1}-{j + 1}")[0]
                    z[j] = self.values(nr, "Z", at, key=f"z {s + 1}-{j + 1}")[0]
            segments.append(DeckFuselageSegment(x, zfus, area, y, z))
        return DeckFuselage(segments)

    def pods(self, c):
        pods = []
        for k in range(max(c.np, 0)):
            where = f"for pod {k + 1}"
            origin = self.values(3, "PODORG", where, ("x", "y", "z"), key=f"podorg {k + 1}")[0]
            x, first = self.values(c.npodor, "XPOD", where, key=f"xpod {k + 1}")
            if x[0] != 0:
                line, cols = self.r.position(first, 0)
                self.r.warn(f"the first XPOD value {where} should be 0, found {float(x[0])!r}",
                            line, cols)
            radius, first = self.values(c.npodor, "PODR", where, key=f"podr {k + 1}")
            self.nonnegative(radius, first, f"PODR (radius) {where}")
            pods.append(DeckPod(origin, x, radius))
        return tuple(pods)

    def _origins(self, card, where, key, sections):
        names = [f"{s} {q}" for s in sections for q in ("x", "y", "z", "chord")]
        vals, first = self.values(8, card, where, names, key=key)
        for i in (3, 7):
            if vals[i] < 0:
                raise self.fail(f"{card} {names[i]} {where} must not be negative, found "
                                f"{float(vals[i])!r}", first, i)
        return vals.reshape(2, 4)

    def fins(self, c):
        fins = []
        for k in range(abs(c.nf)):
            where = f"for fin {k + 1}"
            origins = self._origins("FINORG", where, f"finorg {k + 1}", ("root", "tip"))
            xfin, first = self.values(c.nfinor, "XFIN", where, key=f"xfin {k + 1}")
            self.increasing(xfin, first, f"XFIN (percent chord) {where}")
            sides = ("outboard", "inboard") if c.nf < 0 else ("outboard",)
            ords = []
            for side in sides:
                card = "FINORD" if c.nf > 0 else f"FINORD {side}"
                vals, first = self.values(c.nfinor, card, where, key=f"finord {k + 1} {side}")
                self.nonnegative(vals, first, f"{card} (half-thickness) {where}")
                ords.append(vals)
            fins.append(DeckFin(origins, xfin, ords[0], ords[1] if len(ords) > 1 else None))
        return tuple(fins)

    def canards(self, c):
        canards = []
        n = abs(c.ncanor)
        set_names = _CANARD_SETS[(c.ncan < 0, c.ncanor < 0)]
        for k in range(abs(c.ncan)):
            where = f"for canard {k + 1}"
            origins = self._origins("CANORG", where, f"canorg {k + 1}", ("inboard", "outboard"))
            xcan, first = self.values(n, "XCAN", where, key=f"xcan {k + 1}")
            self.increasing(xcan, first, f"XCAN (percent chord) {where}")
            sets = {}
            for name in set_names:
                card = "CANORD" if name == "all" else f"CANORD {name}"
                vals, first = self.values(n, card, where, key=f"canord {k + 1} {name}")
                self.nonnegative(vals, first, f"{card} (half-thickness) {where}")
                sets[name] = vals
            if len(sets) == 1:
                ui = uo = li = lo = sets["all"]
            elif len(sets) == 4:
                ui, uo, li, lo = (sets[s] for s in set_names)
            elif "inboard" in sets:
                ui = li = sets["inboard"]
                uo = lo = sets["outboard"]
            else:
                ui = uo = sets["upper"]
                li = lo = sets["lower"]
            canards.append(DeckCanard(origins, xcan, ui, uo, li, lo, n_sets=len(sets)))
        return tuple(canards)

    # -- case cards ------------------------------------------------------------------------

    def cases(self):
        r = self.r
        geometry_end = r.pos
        cases = []
        while not r.at_end():
            k = len(cases) + 1
            line, text = r.next_card(f"case card {k}")
            self.lines[f"case {k}"] = line
            hint = f"case card {k}; the geometry cards ended at line {geometry_end}"
            ncase = r.text(text, line, 1, 4)
            values = {name: r.integer(text, line, 4 * i + 5, 4 * i + 8,
                                      f"{name.upper()} on {hint}")
                      for i, name in enumerate(CASE_FIELDS)}
            nrest, ncon = values["nrest"], values["ncon"]
            if nrest < 0:
                raise r.error(f"NREST = {nrest} on case card {k} cannot be negative", line,
                              (17, 20))
            if nrest > _RANGES["NREST"][1]:
                r.warn(f"NREST = {nrest} on case card {k} is above the documented limit 10",
                       line, (17, 20))
            if ncon not in (0, 1):
                raise r.error(f"unknown value NCON = {ncon} on case card {k}; expected 0 or 1 "
                              "(1: another configuration follows)", line, (21, 24))
            xrest = None
            if nrest > 0:
                xrest = self.values(nrest, "XREST", f"for case {k}", key=f"xrest {k}")[0]
            cases.append(DeckCase(ncase, **values, xrest=xrest, text=text[:80].rstrip(" ")))
            if ncon == 1:
                return tuple(cases), True
        return tuple(cases), False


def parse_deck(text, path=None):
    """Parse the text of a wave-drag deck.

    Parameters
    ----------
    text : str
        The whole deck (LF or CRLF line endings).
    path : str, optional
        File name used in messages and stored in :attr:`Deck.path`.

    Returns
    -------
    Deck

    Raises
    ------
    DeckError
        On the first fault, with line, columns and the record being read.
    """
    return _Parser(text, path).deck()
