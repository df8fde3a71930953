"""Wing-like surfaces: wings, canards and tails (sections at constant y), fins and pylons
(sections at constant z).

Anatomy. A wing-like surface is an ordered list of airfoil *sections*, from the root (most
inboard, or lowest for a fin) to the tip. Each section has a leading-edge point ``le``, a
streamwise ``chord`` and an airfoil given at chordwise stations shared by all sections
(percent chord). Points with the same station index on successive sections lie on one
*lofting line* (TM-4406 fig. 1(b)); between sections the surface is lofted linearly along the
lofting lines, which is also how the papers extrapolate them inboard (TM-4406 eq 4). Along the
chord the offsets are interpolated by PCHIP (or linearly).

Only the described half of the airplane is held; ``mirrored`` says whether the component has an
image at -y (false for a surface on the plane of symmetry, such as a centre-line fin).

Axes: x aft, y to starboard, z up. For sections at constant y the thickness is in z ("upper" is
+z); for sections at constant z the thickness is in y ("upper" is the outboard, +y side).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import GeometryError
from ._arrays import check_finite, check_increasing, frozen
from ._pchip import pchip_coefficients
from .airfoil import Airfoil, ChordwiseInterpolation, interpolate_chordwise, surface_offsets

__all__ = ["WingLike", "WingKind", "Side"]

WingKind = Literal["wing", "canard", "tail", "fin", "pylon"]
Side = Literal["upper", "lower"]

_SPAN_AXIS = {"wing": 1, "canard": 1, "tail": 1, "fin": 2, "pylon": 2}


@dataclass(frozen=True, slots=True, eq=False)
class WingLike:
    """A wing, canard, tail, fin or pylon given by airfoil sections.

    Parameters
    ----------
    name : str
        Component name, e.g. ``"wing"``, ``"fin 1"``.
    kind : {"wing", "canard", "tail", "fin", "pylon"}
        Wing, canard and tail have sections at constant y; fin and pylon at constant z.
    le : (n_sections, 3) float
        Leading-edge points, root first [deck length].
    chord : (n_sections,) float
        Streamwise chords, >= 0 (a pointed tip has chord 0) [deck length].
    x_over_c : (n_stations,) float
        Chordwise stations shared by all sections [% chord].
    upper, lower : (n_sections, n_stations) float
        Half-thicknesses above / below the mean line [% chord] ("upper" = outboard for fins).
    camber : (n_sections, n_stations) float, optional
        Mean-line height above the chord line [deck length] (the deck's TZORD). Zero if omitted.
    mirrored : bool
        Whether the component has a mirror image at -y.
    chordwise : {"pchip", "linear"}
        Interpolation along the chord between stations.
    """

    name: str
    kind: WingKind
    le: np.ndarray
    chord: np.ndarray
    x_over_c: np.ndarray
    upper: np.ndarray
    lower: np.ndarray = None
    camber: np.ndarray = None
    mirrored: bool = True
    chordwise: ChordwiseInterpolation = "pchip"
    _poly: dict = None

    def __post_init__(self):
        name = self.name
        if self.kind not in _SPAN_AXIS:
            raise GeometryError(f"kind must be one of {sorted(_SPAN_AXIS)}, found {self.kind!r}",
                                name)
        if self.chordwise not in ("pchip", "linear"):
            raise GeometryError(f"chordwise must be 'pchip' or 'linear', found "
                                f"{self.chordwise!r}", name)
        le = frozen(self.le, (None, 3), name, "le")
        n_sec = le.shape[0]
        chord = frozen(self.chord, (n_sec,), name, "chord (one per section)")
        x = frozen(self.x_over_c, (None,), name, "x_over_c")
        shape = (n_sec, x.size)
        up = frozen(self.upper, shape, name, "upper half-thickness")
        lo = up if self.lower is None else frozen(self.lower, shape, name, "lower half-thickness")
        cam = frozen(np.zeros(shape) if self.camber is None else self.camber, shape, name,
                     "camber")
        if n_sec < 2:
            raise GeometryError(f"needs at least 2 sections, found {n_sec}", name)
        if x.size < 2:
            raise GeometryError(f"needs at least 2 chordwise stations, found {x.size}", name)
        for arr, what in ((le, "leading edge"), (chord, "chord"), (up, "upper half-thickness"),
                          (lo, "lower half-thickness"), (cam, "camber")):
            check_finite(arr, name, what)
        check_increasing(x, name, "x_over_c")
        span_name = "y" if _SPAN_AXIS[self.kind] == 1 else "z"
        check_increasing(le[:, _SPAN_AXIS[self.kind]], name, f"section {span_name} (root first)")
        for arr, what, unit in ((chord, "chord", ""), (up, "upper half-thickness", " % chord"),
                                (lo, "lower half-thickness", " % chord")):
            if (arr < 0).any():
                k = np.argwhere(arr < 0)[0]
                raise GeometryError(f"{what} is negative ({arr[tuple(k)]:g}{unit})", name,
                                    int(k[0]) + 1)
        for field, value in (("le", le), ("chord", chord), ("x_over_c", x), ("upper", up),
                             ("lower", lo), ("camber", cam)):
            object.__setattr__(self, field, value)
        object.__setattr__(self, "mirrored", bool(self.mirrored))
        object.__setattr__(self, "_poly", {})

    # -- layout -------------------------------------------------------------------------
    @property
    def span_axis(self):
        """Index of the spanwise axis: 1 (y) for wing/canard/tail, 2 (z) for fin/pylon."""
        return _SPAN_AXIS[self.kind]

    @property
    def thickness_axis(self):
        """Index of the thickness axis: 2 (z) for wing/canard/tail, 1 (y) for fin/pylon."""
        return 3 - self.span_axis

    @property
    def n_sections(self):
        """Number of airfoil sections."""
        return self.le.shape[0]

    @property
    def n_stations(self):
        """Number of chordwise stations per section (points on each lofting line's section)."""
        return self.x_over_c.size

    @property
    def span_stations(self):
        """(n_sections,) spanwise coordinate of each section (y or z of its leading edge)."""
        return self.le[:, self.span_axis]

    def airfoil(self, section):
        """The :class:`Airfoil` of section ``section`` (0-based)."""
        return Airfoil(self.x_over_c, self.upper[section], self.lower[section],
                       self.camber[section], name=f"{self.name} section {section + 1}")

    # -- points -------------------------------------------------------------------------
    def _offsets(self, side: Side):
        if side not in ("upper", "lower"):
            raise GeometryError(f"side must be 'upper' or 'lower', found {side!r}", self.name)
        up, lo = surface_offsets(self.camber, self.upper, self.lower, self.chord)
        return up if side == "upper" else lo

    def section_points(self, side: Side = "upper"):
        """Surface points at the input stations of every section.

        Returns
        -------
        (n_sections, n_stations, 3) float
            Leading edge first along each section; row k lies on section k.
        """
        pts = np.empty((self.n_sections, self.n_stations, 3))
        pts[...] = self.le[:, None, :]
        pts[..., 0] += self.chord[:, None] * self.x_over_c / 100.0
        pts[..., self.thickness_axis] += self._offsets(side)
        return pts

    def lofting_lines(self, side: Side = "upper"):
        """(n_stations, n_sections, 3): lofting line j joins the points of station j, root first.

        Read-only (computed once per side and kept: the root finders ask for it often)."""
        key = ("lines", side)
        if key not in self._poly:
            lines = np.ascontiguousarray(np.swapaxes(self.section_points(side), 0, 1))
            lines.flags.writeable = False
            self._poly[key] = lines
        return self._poly[key]

    def _bracket(self, span, extrapolate):
        s = np.asarray(span, dtype=float)
        st = self.span_stations
        k = np.clip(np.searchsorted(st, s, side="right") - 1, 0, self.n_sections - 2)
        lam = (s - st[k]) / (st[k + 1] - st[k])
        if not extrapolate:
            tol = 1e-12 * max(1.0, float(np.abs(st).max()))
            out = (s < st[0] - tol) | (s > st[-1] + tol)
            if np.any(out):
                bad = float(np.ravel(s)[np.argmax(np.ravel(out))])
                raise GeometryError(f"span station {bad:g} lies outside the sections "
                                    f"[{st[0]:g}, {st[-1]:g}] (pass extrapolate=True to extend "
                                    "the lofting lines)", self.name)
        return k, lam

    def _chord_cubics(self, side):
        """Chordwise piecewise cubics of every section's offsets, built once per side.

        Returns (breaks (n_stations,) in chord fraction, coefs (4, n_stations - 1,
        n_sections)) in the local variable f - breaks[i], the same curves as
        :func:`interpolate_chordwise`.
        """
        if side not in self._poly:
            t = self.x_over_c / 100.0
            off = self._offsets(side)  # (n_sections, n_stations)
            if self.chordwise == "pchip":
                coefs = pchip_coefficients(t, off.T)  # (4, n_st - 1, n_sec)
            else:
                slope = np.diff(off, axis=1).T / np.diff(t)[:, None]
                coefs = np.stack([np.zeros_like(slope), np.zeros_like(slope), slope,
                                  off[:, :-1].T])
            self._poly[side] = (t, coefs)
        return self._poly[side]

    def _cubic_rows(self, side):
        """The coefficients of :meth:`_chord_cubics` as rows ((n_stations - 1) n_sections,
        4): piece i of section k is row i n_sections + k."""
        key = ("rows", side)
        if key not in self._poly:
            coefs = self._chord_cubics(side)[1]
            self._poly[key] = np.ascontiguousarray(np.moveaxis(coefs, 0, -1)).reshape(-1, 4)
        return self._poly[key]

    def point(self, span, fraction, side: Side = "upper", extrapolate=False):
        """Surface point at a span station and chord fraction, vectorised.

        Parameters
        ----------
        span : array_like
            Spanwise coordinate (y for wing-type, z for fin-type surfaces) [deck length].
        fraction : array_like
            Chord fraction, 0 at the leading edge, 1 at the trailing edge; broadcast with span.
        side : {"upper", "lower"}
        extrapolate : bool
            Extend the first/last lofting-line segments linearly beyond the root/tip (TM-4406
            eq 4 does this inboard). Otherwise a station outside raises GeometryError.

        Returns
        -------
        (..., 3) float
            The ruled blend ``(1 - lam) C_k(f) + lam C_k+1(f)`` of the two neighbouring section
            curves at equal chord fraction: lofting lines are straight between sections.
        """
        s, f = np.broadcast_arrays(np.asarray(span, float), np.asarray(fraction, float))
        k, lam = self._bracket(s, extrapolate)
        if side not in ("upper", "lower"):
            raise GeometryError(f"side must be 'upper' or 'lower', found {side!r}", self.name)
        t, coefs = self._chord_cubics(side)
        rows = self._cubic_rows(side)
        fr, kk = f.ravel(), k.ravel()
        i = np.minimum(np.maximum(np.searchsorted(t, fr, side="right") - 1, 0), t.size - 2)
        h = (fr - t[i])
        # At the trailing edge the section's own ordinate, not the last cubic's round-off:
        # a sharp edge is then the same point on both sides, bit for bit.
        te = fr == t[-1]
        last = self._offsets(side)[:, -1] if te.any() else None
        pts = []
        for kk_i in (kk, kk + 1):
            # np.take on rows: several times faster than fancy indexing on the hot path
            c3, c2, c1, c0 = np.take(rows, i * coefs.shape[2] + kk_i, axis=0).T
            p = np.take(self.le, kk_i, axis=0)
            p[:, 0] += np.take(self.chord, kk_i) * fr
            off = ((c3 * h + c2) * h + c1) * h + c0
            if last is not None:
                off = np.where(te, np.take(last, kk_i), off)
            p[:, self.thickness_axis] += off
            pts.append(p)
        w = lam.ravel()[:, None]
        return ((1.0 - w) * pts[0] + w * pts[1]).reshape(s.shape + (3,))

    def with_chord_stations(self, x_over_c):
        """A copy with extra chordwise stations [% chord], on the present section curves.

        The new stations' offsets are the present section curves' there, and the copy keeps
        those curves (each cubic piece split at the new stations), so its :meth:`point` is
        this one's: refining the lofting lines does not move the surface. (The camber there
        is the camber's own interpolation and the half-thicknesses make up the offsets;
        interpolating camber and thickness apart put the points up to 1e-3 of the thickness
        off.) Input stations are kept, their ordinates bit for bit (a sharp edge stays one
        line on both surfaces).
        """
        xc = np.union1d(self.x_over_c, np.asarray(x_over_c, float))
        if xc.size == self.n_stations:
            return self
        f = xc / 100.0
        cam = interpolate_chordwise(self.x_over_c, self.camber, f, self.chordwise)
        c = self.chord[:, None]
        split = {side: self._split_cubics(side, f) for side in ("upper", "lower")}
        up, lo = (_values_at_breaks(split[side], f) for side in ("upper", "lower"))
        with np.errstate(invalid="ignore", divide="ignore"):
            up = np.where(c > 0, 100.0 * (up - cam) / np.where(c > 0, c, 1.0),
                          interpolate_chordwise(self.x_over_c, self.upper, f, self.chordwise))
            lo = np.where(c > 0, 100.0 * (cam - lo) / np.where(c > 0, c, 1.0),
                          interpolate_chordwise(self.x_over_c, self.lower, f, self.chordwise))
        at = np.searchsorted(xc, self.x_over_c)
        for new, old in ((up, self.upper), (lo, self.lower), (cam, self.camber)):
            new[..., at] = old
        # Round-off can leave -1e-17 where a thickness returns to zero.
        args = (np.maximum(up, 0.0), np.maximum(lo, 0.0), cam)
        out = WingLike(self.name, self.kind, self.le, self.chord, xc, *args, self.mirrored,
                       self.chordwise)
        for side in ("upper", "lower"):
            out._poly[side] = (f, split[side])
        return out

    def _split_cubics(self, side, f):
        """The section curves' cubic pieces (as :meth:`_chord_cubics`) on the breaks ``f``
        (the present ones among them): each piece the present one about its new start."""
        t, coefs = self._chord_cubics(side)
        i = np.clip(np.searchsorted(t, f[:-1], side="right") - 1, 0, t.size - 2)
        d = (f[:-1] - t[i])[:, None]
        c3, c2, c1, c0 = coefs[:, i]
        return np.stack([c3, c2 + 3.0 * c3 * d, c1 + (2.0 * c2 + 3.0 * c3 * d) * d,
                         ((c3 * d + c2) * d + c1) * d + c0])

    def extended_to(self, span):
        """A copy whose lofting lines continue straight beyond the root to ``span``.

        A new root section is added at the span station ``span`` (inboard of the present
        root) on the extended lofting lines, as TM-4406 eq 4 extends them to meet a body;
        the surface between is exactly that extension. Returns ``self`` if ``span`` is not
        inboard of the root.
        """
        s0 = self.span_stations[0]
        if not span < s0:
            return self
        return self.with_sections([span], extrapolate=True)

    def with_sections(self, span, extrapolate=False):
        """A copy with extra sections inserted at the given span stations (linear loft).

        The new sections lie exactly on the lofted surface: their leading edges, chords and
        ordinates are those of the straight lofting lines, and their chordwise curves are the
        blends of their neighbours' curves (a PCHIP through the blended ordinates is not the
        blend of the PCHIPs: a generated airplane's 4-point sections put a root continued
        into the fuselage 6e-3 ft off the extended surface between stations), so the copy's
        :meth:`point` is this one's, extrapolated beyond the root or tip too. A copy made from
        the ordinates alone (a deck written and read again) has curves through them. Stations
        that coincide with existing sections are ignored.
        """
        st = self.span_stations
        new = np.setdiff1d(np.asarray(span, float), st)
        if new.size == 0:
            return self
        k, lam = self._bracket(new, extrapolate=extrapolate)
        w = lam[:, None]
        le = (1 - w) * self.le[k] + w * self.le[k + 1]
        chord = (1 - lam) * self.chord[k] + lam * self.chord[k + 1]
        # Offsets (absolute lengths) are linear along lofting lines; split back into camber
        # and percent-chord thickness so the section can be written to a deck.
        cam = (1 - w) * self.camber[k] + w * self.camber[k + 1]
        thick = []
        for t in (self.upper, self.lower):
            ct = (1 - w) * self.chord[k, None] * t[k] + w * self.chord[k + 1, None] * t[k + 1]
            with np.errstate(invalid="ignore", divide="ignore"):
                thick.append(np.where(chord[:, None] > 0, ct / chord[:, None],
                                      (1 - w) * t[k] + w * t[k + 1]))
        order = np.argsort(np.concatenate([st, new]), kind="stable")

        def merged(a, b):
            return np.concatenate([a, b])[order]

        out = WingLike(self.name, self.kind, merged(self.le, le), merged(self.chord, chord),
                       self.x_over_c, merged(self.upper, thick[0]), merged(self.lower, thick[1]),
                       merged(self.camber, cam), self.mirrored, self.chordwise)
        for side in ("upper", "lower"):
            t, coefs = self._chord_cubics(side)
            blend = (1 - lam) * coefs[..., k] + lam * coefs[..., k + 1]
            out._poly[side] = (t, np.concatenate([coefs, blend], axis=-1)[..., order])
        return out

    def networks(self):
        """Surface networks of the component, each oriented with outward normals.

        Returns
        -------
        dict of str to (n_sections, n_stations, 3) float
            ``"<name> upper"`` and ``"<name> lower"`` (``outboard``/``inboard`` for fins and
            pylons); n-lines are the sections root first, points run along the chord in the
            direction that makes cross(d point, d line) point out of the solid.
        """
        names = ("upper", "lower") if self.span_axis == 1 else ("outboard", "inboard")
        e_span = np.eye(3)[self.span_axis]
        e_thick = np.eye(3)[self.thickness_axis]
        natural_out = float(np.cross([1.0, 0.0, 0.0], e_span) @ e_thick)  # +1: upper LE->TE
        out = {}
        for side, label, sign in (("upper", names[0], 1.0), ("lower", names[1], -1.0)):
            pts = self.section_points(side)
            out[f"{self.name} {label}"] = pts if sign * natural_out > 0 else pts[:, ::-1]
        return out

    def planform(self):
        """(2 * n_sections + 1, 3) closed outline: leading edge root to tip, trailing edge back."""
        te = self.le.copy()
        te[:, 0] += self.chord
        return np.concatenate([self.le, te[::-1], self.le[:1]])


def _values_at_breaks(coefs, f):
    """(n_sections, len(f)) the piecewise cubics ``coefs`` ((4, len(f) - 1, n_sections), in
    f - f[i]) at their breaks ``f``: each piece's start, and the last piece's end."""
    c3, c2, c1, c0 = coefs[:, -1]
    h = f[-1] - f[-2]
    end = ((c3 * h + c2) * h + c1) * h + c0
    return np.concatenate([coefs[3], end[None]]).T
