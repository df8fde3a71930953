"""Hypothesis strategies that draw plausible airplanes and write them as deck text (see the
package docstring for the families and ranges)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from hypothesis import strategies as st

from ._cards import _cards, _q
from .references import CircularBodyRef, WingLikeRef

#: Families that a keyword argument of the strategies can pin, with their values.
FAMILIES = {
    "section": ("circular", "arbitrary"),
    "segments": (1, 2, 3, 4),
    "joints": ("repeated", "gap"),
    "wing_height": ("low", "mid", "high"),
    "root": ("inside", "crossing", "outside"),
    "cambered": (True, False),
    "unsymmetric": (True, False),
    "pods": (0, 1, 2, 3),
    "pod_mount": ("free", "pylon"),
    "body_fin": ("none", "centre", "twin"),
    "wing_fin": (0, 1),
    "canards": ("none", "canard", "tail", "canard+tail"),
}

_ALL_PARTS = ("pods", "fins", "canards")




# ------------------------------------------------------------------------------------------
# Drawing
# ------------------------------------------------------------------------------------------
class _Draw:
    """Every value of one airplane, from a generator seeded by a hypothesis draw.

    Hypothesis's own integer and float draws favour small and boundary values (a sweep drawn
    from [-10, 70] deg had its median at -9.6); a seeded numpy generator covers the ranges
    evenly, and the seed keeps each airplane a function of hypothesis's choices. A pinned
    family overrides its draw.
    """

    def __init__(self, seed, pins):
        self.rng = np.random.default_rng(seed)
        self.pins = pins

    def uniform(self, lo, hi):
        return float(self.rng.uniform(lo, hi))

    def integer(self, lo, hi):
        return int(self.rng.integers(lo, hi + 1))

    def choice(self, options, pin=None):
        options = tuple(options)
        value = options[int(self.rng.integers(len(options)))]
        return self.pins[pin] if pin is not None and pin in self.pins else value

    def chance(self, p):
        return bool(self.rng.random() < p)


@dataclass(frozen=True)
class _Fuselage:
    """The analytic shape the fuselage stations sample (used to place the other parts)."""

    length: float
    radius: float
    nose: float
    tail: float
    base: float
    droop: float
    upsweep: float
    width: float = 1.0
    top: float = 1.0
    bottom: float = 1.0
    exponent: float = 2.0

    def r(self, x):
        xi = np.clip(np.asarray(x, float) / self.length, 0.0, 1.0)
        nose = np.clip(1.0 - xi / self.nose, 0.0, 1.0)
        s = np.clip((xi - (1.0 - self.tail)) / self.tail, 0.0, 1.0)
        shape = np.where(xi < self.nose, (1.0 - nose ** 2) ** 0.75,
                         1.0 - (1.0 - self.base) * s ** 2)
        return self.radius * shape

    def zc(self, x):
        xi = np.clip(np.asarray(x, float) / self.length, 0.0, 1.0)
        nose = np.clip(1.0 - xi / self.nose, 0.0, 1.0)
        s = np.clip((xi - (1.0 - self.tail)) / self.tail, 0.0, 1.0)
        return -self.droop * nose ** 2 + self.upsweep * s ** 2

    def half_width(self, x, z):
        r = self.r(x)
        dz = np.asarray(z, float) - self.zc(x)
        h = np.where(dz > 0, self.top, self.bottom) * r
        with np.errstate(divide="ignore", invalid="ignore"):
            a = np.where(h > 0, np.abs(dz) / h, np.inf)
        n = self.exponent
        return np.where(a < 1, self.width * r * np.abs(1 - np.minimum(a, 1) ** n) ** (1 / n),
                        0.0)

    def top_at(self, x):
        return self.zc(x) + self.top * self.r(x)

    def inside(self, points, margin=0.0):
        p = np.asarray(points, float).reshape(-1, 3)
        return np.abs(p[:, 1]) < self.half_width(p[:, 0], p[:, 2]) - margin

    def half_section(self, x, m):
        """(m, 2) y, z points from the bottom to the top at station x."""
        th = np.linspace(-np.pi / 2, np.pi / 2, m)
        r, zc, n = self.r(x), self.zc(x), self.exponent
        y = self.width * r * np.abs(np.cos(th)) ** (2 / n)
        s = np.sin(th)
        z = zc + np.where(s > 0, self.top, self.bottom) * r * np.sign(s) * np.abs(s) ** (2 / n)
        y[0] = y[-1] = 0.0
        return np.stack([y, z], -1)


@dataclass
class _Part:
    """One component: its name, reference surface, cards and what it may touch."""

    name: str
    ref: object
    numbers: dict
    labels: dict
    touches: tuple = ()


def _stations(d, n, power=1.0):
    """n fractions from 0 to 1, optionally clustered at 0, jittered, strictly increasing."""
    u = np.linspace(0.0, 1.0, n) ** power
    step = np.diff(u)
    for i in range(1, n - 1):
        u[i] += d.uniform(-0.3, 0.3) * min(step[i - 1], step[i])
    return u


def _draw_fuselage(d):
    L = d.uniform(40.0, 300.0)
    R = L / (2.0 * d.uniform(7.0, 16.0))
    section = d.choice(FAMILIES["section"], "section")
    nose, tail = d.uniform(0.12, 0.35), d.uniform(0.15, 0.35)
    base = 0.0 if d.chance(0.4) else d.uniform(0.05, 0.4)
    shape, width, top, bottom, exponent = "circle", 1.0, 1.0, 1.0, 2.0
    if section == "circular":
        j6 = d.choice((0, -1))
        cambered = j6 == 0 and d.chance(0.7)
    else:
        j6 = 0
        shape = d.choice(("circle", "ellipse", "superellipse", "egg"))
        if shape != "circle":
            width = d.uniform(0.75, 1.3)
            top = bottom = d.uniform(0.75, 1.3)
        if shape == "egg":
            bottom = d.uniform(0.6, 1.2)
        if shape == "superellipse":
            exponent = d.uniform(2.5, 5.0)
        cambered = d.chance(0.6)
    droop = d.uniform(0.0, 0.25) * R if cambered else 0.0
    upsweep = d.uniform(0.0, 0.5) * R if cambered else 0.0
    fus = _Fuselage(L, R, nose, tail, base, droop, upsweep, width, top, bottom, exponent)

    n_seg = d.choice(FAMILIES["segments"], "segments")
    joints = "none" if n_seg == 1 else d.choice(("repeated", "repeated", "gap"), "joints")
    weights = np.array([d.uniform(0.5, 1.5) for _ in range(n_seg)])
    cuts = _q(L * np.cumsum(weights) / weights.sum())
    starts = np.concatenate([[0.0], cuts[:-1]])
    segments, nradx = [], []
    for i in range(n_seg):
        a, b = starts[i], cuts[i]
        if joints == "gap" and i > 0:
            a = float(_q(a + d.uniform(0.005, 0.03) * L))
        n = d.integer(4, 10)
        u = _stations(d, n, d.uniform(1.0, 1.8) if i == 0 else 1.0)
        x = _q(a + (b - a) * u)
        x[0], x[-1] = a, b
        if section == "circular":
            nradx.append(d.integer(5, 15))
            area = _q(np.pi * fus.r(x) ** 2)
            zc = _q(fus.zc(x)) if j6 == 0 else np.zeros(n)
            segments.append({"x": x, "area": area, "zc": zc})
        else:
            m = d.integer(5, 13)
            nradx.append(m)
            secs = _q(np.stack([fus.half_section(xx, m) for xx in x]))
            segments.append({"x": x, "y": secs[..., 0], "z": secs[..., 1]})
    labels = {"section": section, "section_shape": shape, "body_camber": bool(cambered),
              "segments": n_seg, "joints": joints, "length": L, "radius": R,
              "fineness": L / (2 * R)}
    return fus, segments, nradx, j6, labels


def _airfoil_half_thickness(shape, f, tc):
    """Half-thickness / chord at chord fractions f for thickness ratio tc."""
    if shape == "biconvex":
        return 2.0 * tc * f * (1.0 - f)
    te = -0.1036 if shape == "naca" else -0.1015
    return 5.0 * tc * (0.2969 * np.sqrt(f) - 0.126 * f - 0.3516 * f ** 2 + 0.2843 * f ** 3
                       + te * f ** 4)


def _root_family(fus, ref):
    pts = np.concatenate([ref.section_points(s)[0] for s in ("upper", "lower")])
    inside = fus.inside(pts)
    return "inside" if inside.all() else "outside" if not inside.any() else "crossing"


def _draw_wing(d, fus):
    L, R = fus.length, fus.radius
    height = d.choice(FAMILIES["wing_height"], "wing_height")
    target = d.choice(FAMILIES["root"], "root")
    x_le = d.uniform(0.25, 0.5) * L
    c_root = min(d.uniform(0.15, 0.45) * L, 0.92 * L - x_le)
    x_mid = x_le + 0.5 * c_root
    frac = {"low": -d.uniform(0.45, 0.8), "mid": d.uniform(-0.3, 0.3),
            "high": d.uniform(0.45, 0.8)}[height]
    side = fus.top if frac > 0 else fus.bottom
    z_root = float(fus.zc(x_mid) + frac * side * fus.r(x_mid))
    sweep = d.uniform(-10.0, 70.0)
    dihedral = d.uniform(-10.0, 12.0)
    taper = 0.0 if d.chance(0.08) else d.uniform(0.1, 1.0)
    n_sec = d.integer(2, 8)
    crank = n_sec >= 3 and d.chance(0.35)
    semispan = max(d.uniform(0.12, 0.45) * L, 2.5 * fus.width * R)
    sweep_in = min(sweep + d.uniform(5.0, 25.0), 70.0) if crank else sweep
    # Keep the tip's trailing edge within about the fuselage length.
    reach = max(1.05 * L - x_le - c_root * max(taper, 0.3), 0.2 * L)
    if math.tan(math.radians(sweep_in)) * semispan > reach:
        semispan = max(reach / math.tan(math.radians(sweep_in)), 2.5 * fus.width * R)
    eta = np.concatenate([[0.0], np.cumsum([d.uniform(0.5, 1.5) for _ in range(n_sec - 1)])])
    eta /= eta[-1]
    eta_k, c_k = 1.0, c_root
    if crank:
        eta_k = float(eta[d.integer(1, n_sec - 2)])
        c_k = c_root * d.uniform(0.35, 0.8)
        c_tip = c_k * taper
        chord = np.where(eta <= eta_k, c_root + (c_k - c_root) * eta / eta_k,
                         c_k + (c_tip - c_k) * (eta - eta_k) / (1 - eta_k))
    else:
        chord = c_root + (c_root * taper - c_root) * eta
    t_in, t_out = math.tan(math.radians(sweep_in)), math.tan(math.radians(sweep))
    x = np.where(eta <= eta_k, x_le + eta * semispan * t_in,
                 x_le + eta_k * semispan * t_in + (eta - eta_k) * semispan * t_out)
    z = z_root + eta * semispan * math.tan(math.radians(dihedral))

    m = d.integer(4, 14)
    spacing = d.choice(("cosine", "uniform"))
    if spacing == "cosine":
        u = 0.5 * (1 - np.cos(np.pi * np.linspace(0.0, 1.0, m)))
    else:
        u = _stations(d, m, 1.0)
    xaf = _q(100.0 * u)
    f = xaf / 100.0
    shape = d.choice(("biconvex", "naca", "blunt"))
    tc_root = min(d.uniform(0.03, 0.12), 0.6 * R / c_root)
    tc = tc_root * (1.0 - eta * (1.0 - d.uniform(0.5, 1.0)))
    half = 100.0 * _airfoil_half_thickness(shape, f[None, :], tc[:, None])
    unsym = d.choice((True, False), "unsymmetric")
    a = d.uniform(0.15, 0.5) * (1 if d.chance(0.5) else -1) if unsym else 0.0
    upper, lower = _q(half * (1 + a)), _q(half * (1 - a))
    cambered = d.choice((True, False), "cambered")
    camber = None
    if cambered:
        m_c = d.uniform(0.0, 0.04)
        twist = np.radians(d.uniform(-6.0, 2.0)) * eta
        camber = _q(chord[:, None] * (4 * m_c * f * (1 - f) - f * np.tan(twist)[:, None]))

    # The root's place across the fuselage surface, from the half-width of the fuselage at
    # each point of the root section (sections lie at constant y).
    cam0 = 0.0 if camber is None else camber[0]
    xr = np.concatenate([x[0] + chord[0] * f] * 2)
    zr = np.concatenate([z[0] + cam0 + chord[0] * upper[0] / 100,
                         z[0] + cam0 - chord[0] * lower[0] / 100])
    hw = fus.half_width(xr, zr)
    if target == "inside":
        y_root = 0.0 if d.chance(0.25) else d.uniform(0.0, 0.6) * float(hw.min())
    elif target == "crossing":
        y_root = float(np.quantile(hw, d.uniform(0.25, 0.75)))
    else:
        y_root = d.uniform(1.08, 1.35) * float(hw.max()) + 0.02 * R
    y = y_root + eta * semispan
    le = _q(np.stack([x, y, z], -1))
    chord = _q(chord)
    ref = WingLikeRef("wing", le, chord, xaf, upper, lower, camber)
    numbers = {"kind": "wing", "le": le, "chord": chord, "xaf": xaf, "upper": upper,
               "lower": lower, "camber": camber}
    labels = {"wing_height": height, "root": _root_family(fus, ref), "root_target": target,
              "sweep_deg": sweep, "sweep_inboard_deg": sweep_in, "dihedral_deg": dihedral,
              "sections": n_sec, "stations": m, "station_spacing": spacing,
              "cambered": bool(cambered), "unsymmetric": bool(unsym), "crank": bool(crank),
              "taper": taper, "pointed_tip": taper == 0.0, "airfoil": shape,
              "root_chord_over_length": c_root / L, "semispan_over_length": semispan / L,
              "root_t_over_c": tc_root}
    return _Part("wing", ref, numbers, labels)


def _collides(a, b, margin):
    """True if parts a and b overlap (within ``margin``), inside the fuselage or not.

    Parts buried in the fuselage (a wing carried through it, the roots of a fin and a tail)
    count too: a deck whose fin root passes through the wing's root inside the fuselage is
    not a sensible airplane.
    """
    for p, q in ((a, b), (b, a)):
        if np.any(_depth(q.ref, _samples(p.ref)) > -margin):
            return True
    return False


def _samples(ref):
    if isinstance(ref, WingLikeRef):
        return ref.samples()
    x0, x1 = ref.x0, ref.x1
    xs = np.linspace(x0, x1, 12)
    r, zc, _ = ref.section(xs)
    th = np.linspace(0.0, 2 * np.pi, 13)[:-1]
    return np.stack([np.repeat(xs, th.size),
                     ref.y_centre + (r[:, None] * np.cos(th)).ravel(),
                     (zc[:, None] + r[:, None] * np.sin(th)).ravel()], -1)


def _depth(ref, pts):
    if isinstance(ref, WingLikeRef):
        return ref.depth(pts)
    inside = (pts[:, 0] > ref.x0) & (pts[:, 0] < ref.x1)
    return np.where(inside, -ref.radial_error(pts), -np.inf)


def _thin_ordinates(d, m, asym):
    """Percent-chord stations and (outboard/upper, inboard/lower) half-thicknesses."""
    x = _q(100.0 * _stations(d, m, 1.0))
    f = x / 100.0
    tau = d.uniform(0.015, 0.05)
    base = 100.0 * 4.0 * tau * f * (1.0 - f)
    a = d.uniform(-0.3, 0.3) if asym else 0.0
    return x, _q(base * (1 + a)), _q(base * (1 - a))


def _fin_part(name, role, le, chord, xfin, out, inb, touches):
    le, chord = _q(le), _q(chord)
    ref = WingLikeRef("fin", le, chord, xfin, out, inb)
    numbers = {"kind": "fin", "role": role, "le": le, "chord": chord, "xaf": xfin,
               "upper": np.stack([out, out]), "lower": np.stack([inb, inb])}
    return _Part(name, ref, numbers, {"role": role}, touches)


def _wing_bounds(wing, x0, x1, y0, y1, n=15):
    """The wing's surfaces over the box [x0, x1] x [y0, y1] of its planform.

    Returns ``(largest lower height, smallest upper height, smallest lower height, whether
    the whole box lies under the planform)``, over the part that does; None if none does.
    """
    xs, ys = np.meshgrid(np.linspace(x0, x1, n), np.linspace(y0, y1, 3), indexing="ij")
    pts = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], -1)
    s, f, _ = wing.coordinates(pts)
    ok = np.isfinite(f) & (f >= 0) & (f <= 1) & (s >= wing.span[0]) & (s <= wing.span[-1])
    if not ok.any():
        return None
    lower = wing.surface(s[ok], f[ok], "lower")
    upper = wing.surface(s[ok], f[ok], "upper")
    return float(lower.max()), float(upper.min()), float(lower.min()), bool(ok.all())


class _Builder:
    """Places the parts of one airplane, each clear of those it is not meant to touch."""

    def __init__(self, d, fus, m_fin, fin_asym):
        self.d, self.fus = d, fus
        self.parts, self.dropped = [], []
        self.m_fin, self.fin_asym = m_fin, fin_asym

    def fin_ordinates(self):
        """XFIN and the outboard and inboard FINORD of one fin (counts shared by all fins)."""
        return _thin_ordinates(self.d, self.m_fin, self.fin_asym)

    def add(self, part):
        margin = 0.02 * self.fus.radius
        for other in self.parts:
            if other.name in part.touches or part.name in other.touches:
                continue
            if _collides(part, other, margin):
                self.dropped.append(f"{part.labels.get('role', part.name)} "
                                    f"(would touch {other.name})")
                return False
        self.parts.append(part)
        return True

    def part(self, name):
        return next(p for p in self.parts if p.name == name)


def _draw_pods(b, wing, fins):
    d, fus = b.d, b.fus
    L, R = fus.length, fus.radius
    n = d.choice(FAMILIES["pods"], "pods")
    m = d.integer(4, 10)
    pods, labels = [], []
    for _ in range(n):
        mount = d.choice(FAMILIES["pod_mount"], "pod_mount")
        length = d.uniform(0.07, 0.2) * L
        rmax = length / d.uniform(4.0, 8.0)
        y_lo = fus.width * R + 1.6 * rmax
        y_hi = wing.ref.span[-1] - 1.5 * rmax
        if y_lo >= y_hi:
            b.dropped.append(f"{mount} pod (no room under the wing)")
            continue
        taken = [(float(p.numbers["origin"][1]), float(np.max(p.numbers["radius"])))
                 for p in pods]
        for _ in range(5):
            y_p = d.uniform(y_lo, y_hi)
            if all(abs(y_p - yo) > 1.5 * (ro + rmax) for yo, ro in taken):
                break
        else:
            b.dropped.append(f"{mount} pod (no room beside the other pods)")
            continue
        _, _, x_le, c = (float(v) for v in wing.ref.planform(y_p))
        if c < 0.04 * L:
            b.dropped.append(f"{mount} pod (wing chord too small)")
            continue
        xo = x_le + d.uniform(0.3, 0.7) * c - d.uniform(0.35, 0.65) * length
        open_nose, open_exit = d.chance(0.5), d.chance(0.5)
        r0 = d.uniform(0.6, 0.9) * rmax if open_nose else 0.0
        re = d.uniform(0.5, 0.9) * rmax if open_exit else 0.0
        s = _stations(d, m, 1.0)
        prof = np.where(s < 0.4, r0 + (rmax - r0) * (1 - (1 - s / 0.4) ** 2),
                        np.where(s > 0.6, rmax - (rmax - re) * ((s - 0.6) / 0.4) ** 2, rmax))
        xp, rp = _q(length * s), _q(prof)
        xp[0] = 0.0
        box = _wing_bounds(wing.ref, xo, xo + length, y_p - rmax, y_p + rmax)
        z_low = float(wing.ref.surface(y_p, 0.0, "lower")[0]) if box is None else box[2]
        gap = (d.uniform(0.3, 1.2) if mount == "pylon" else d.uniform(0.4, 1.2)) * rmax
        origin = _q([xo, y_p, z_low - gap - rmax])
        name = f"pod {len(pods) + 1}"
        ref = CircularBodyRef([(xp + origin[0], rp, np.full(m, origin[2]))], origin[1])
        pylon = None
        if mount == "pylon":
            pylon = _pylon(b, wing, name, origin, xp, rp, rmax, x_le, c, len(fins))
            if pylon is None:
                mount = "free (no room for a pylon)"
        pod = _Part(name, ref, {"kind": "pod", "origin": origin, "x": xp, "radius": rp},
                    {"mount": mount, "open_nose": open_nose, "open_exit": open_exit,
                     "length_over_L": length / L},
                    touches=(pylon.name,) if pylon is not None else ())
        if not b.add(pod):
            continue
        if pylon is not None and not b.add(pylon):
            b.parts.remove(pod)
            continue
        pods.append(pod)
        labels.append(pod.labels)
        if pylon is not None:
            fins.append(pylon)
    return pods, labels


def _pylon(b, wing, pod_name, origin, xp, rp, rmax, x_le, c, n_fins):
    d = b.d
    full = xp[rp >= 0.7 * rmax] + origin[0]
    if full.size < 2:
        return None
    lo, hi = max(full[0], x_le + 0.15 * c), min(full[-1], x_le + 0.8 * c)
    if hi - lo < 0.2 * min(xp[-1], c):
        return None
    chord = 0.8 * (hi - lo)
    x_r = lo + 0.1 * (hi - lo)
    box = _wing_bounds(wing.ref, x_r, x_r + chord, origin[1], origin[1])
    if box is None or not box[3] or box[0] >= box[1]:
        return None
    z_r = origin[2] + d.uniform(0.2, 0.5) * rmax
    z_t = 0.5 * (box[0] + box[1])
    c_t = chord * d.uniform(0.8, 1.0)
    x_t = x_r + (chord - c_t) * d.uniform(0.0, 1.0)
    le = [[x_r, origin[1], z_r], [x_t, origin[1], z_t]]
    xfin, out, inb = b.fin_ordinates()
    return _fin_part(f"fin {n_fins + 1}", "pylon", le, [chord, c_t], xfin, out, inb,
                     touches=("wing", pod_name))


def _body_fin(b, kind, name, wing):
    d, fus = b.d, b.fus
    L, R = fus.length, fus.radius
    chord = d.uniform(0.07, 0.18) * L
    exposed = d.uniform(0.04, 0.12) * L
    sweep = math.radians(d.uniform(0.0, 60.0))
    taper = d.uniform(0.3, 1.0)
    te = L * (1 - d.uniform(0.03, 0.15))
    for _ in range(8):  # move forward until the root lies where the fuselage is thick enough
        xs = np.linspace(te - chord, te, 15)
        if fus.r(xs).min() >= 0.35 * R:
            break
        te -= 0.05 * L
    else:
        return None
    x_r = te - chord
    r_min = float(fus.r(xs).min())
    if kind == "centre":
        y_r = 0.0
        z_r = float(fus.top_at(xs).min()) - d.uniform(0.15, 0.4) * r_min * fus.top
        cant = 0.0
    else:
        phi = math.radians(d.uniform(35.0, 70.0))
        z_r = float(fus.zc(xs).max()) + 0.7 * fus.top * r_min * math.sin(phi)
        y_r = 0.8 * float(fus.half_width(xs, z_r).min())
        cant = math.radians(d.uniform(0.0, 30.0))
        if y_r <= 0.05 * R:
            return None
    height = float(fus.top_at(xs).max()) - z_r + exposed
    le = [[x_r, y_r, z_r], [x_r + height * math.tan(sweep), y_r + height * math.tan(cant),
                            z_r + height]]
    xfin, out, inb = b.fin_ordinates()
    return _fin_part(name, kind, le, [chord, chord * taper], xfin, out, inb,
                     touches=("body",))


def _wing_fin(b, name, wing, pods):
    """A fin standing on the wing's upper surface, its root section inside the wing."""
    d, L = b.d, b.fus.length
    ref = wing.ref
    clear = [(float(p.numbers["origin"][1]), 3.0 * float(np.max(p.numbers["radius"])))
             for p in pods]
    for _ in range(5):
        y_f = ref.span[0] + d.uniform(0.3, 0.95) * (ref.span[-1] - ref.span[0])
        if y_f > 1.2 * b.fus.width * b.fus.radius and all(abs(y_f - y) > c for y, c in clear):
            break
    else:
        return None
    _, _, x_le, c = (float(v) for v in ref.planform(y_f))
    if c < 0.05 * L:
        return None
    chord = d.uniform(0.3, 0.7) * c
    centre = x_le + 0.15 * c + 0.5 * chord + d.uniform(0.0, 1.0) * (0.7 * c - chord)
    while chord > 0.1 * c:  # shorter where twist or camber tilt the section too much
        x_r = centre - 0.5 * chord
        box = _wing_bounds(ref, x_r, x_r + chord, y_f, y_f)
        if box is not None and box[3] and box[0] < box[1]:
            break
        chord *= 0.7
    else:
        return None
    z_r = 0.5 * (box[0] + box[1])
    height = (box[1] - z_r) + d.uniform(0.5, 1.5) * chord
    sweep = math.radians(d.uniform(0.0, 50.0))
    c_t = chord * d.uniform(0.3, 1.0)
    le = [[x_r, y_f, z_r], [x_r + height * math.tan(sweep), y_f, z_r + height]]
    xfin, out, inb = b.fin_ordinates()
    return _fin_part(name, "wing", le, [chord, c_t], xfin, out, inb, touches=("wing",))


def _surface_part(b, kind, wing, ordinates):
    """A canard or a horizontal tail on the fuselage (None if there is no room)."""
    d, fus = b.d, b.fus
    L, R = fus.length, fus.radius
    x_mid_root = float(wing.numbers["le"][0, 0] + 0.5 * wing.numbers["chord"][0])
    if kind == "tail":
        chord = d.uniform(0.06, 0.15) * L
        semispan = d.uniform(0.07, 0.2) * L
        te = L * (1 - d.uniform(0.01, 0.06))
        while fus.r(np.linspace(te - chord, te, 15)).min() < 0.3 * R and te > 0.5 * L:
            te -= 0.03 * L
        x_in = te - chord
        if x_in <= x_mid_root + 0.01 * L:
            return None
    else:
        chord = d.uniform(0.04, 0.1) * L
        semispan = d.uniform(0.05, 0.14) * L
        x_in = d.uniform(0.06, 0.3) * L
        while fus.r(np.linspace(x_in, x_in + chord, 15)).min() < 0.4 * R and x_in < 0.45 * L:
            x_in += 0.02 * L
        if x_in + 0.5 * chord >= x_mid_root:
            return None
    xs = np.linspace(x_in, x_in + chord, 15)
    r_min = float(fus.r(xs).min())
    frac = d.uniform(-0.4, 0.5)
    z_in = float(fus.zc(x_in + 0.5 * chord)) + frac * (fus.top if frac > 0 else fus.bottom) * \
        r_min
    hw = float(fus.half_width(xs, z_in).min())
    if hw <= 0.05 * R:
        return None
    y_in = d.uniform(0.2, 0.7) * hw
    sweep = math.radians(d.uniform(0.0, 60.0))
    dihedral = math.radians(d.uniform(-10.0, 15.0))
    taper = d.uniform(0.25, 1.0)
    for _ in range(4):
        # The tip clear of the fuselage (a canard or tail whose tip stays inside a wide
        # fuselage is no airplane's): span added until it is.
        x_tip = x_in + semispan * math.tan(sweep) + np.linspace(0.0, chord * taper, 15)
        z_tip = z_in + semispan * math.tan(dihedral)
        reach = float(fus.half_width(x_tip, z_tip).max()) + 0.1 * R - y_in
        if semispan >= reach:
            break
        semispan = reach
    le = _q([[x_in, y_in, z_in], [x_in + semispan * math.tan(sweep), y_in + semispan,
                                  z_in + semispan * math.tan(dihedral)]])
    chords = _q([chord, chord * taper])
    xcan, upper, lower = ordinates
    ref = WingLikeRef(kind, le, chords, xcan, upper, lower)
    numbers = {"kind": kind, "le": le, "chord": chords, "xaf": xcan, "upper": upper,
               "lower": lower}
    return _Part(kind, ref, numbers, {"role": kind}, touches=("body",))


def _canard_ordinates(d, m, both_sections, both_sides):
    """XCAN and the (2, m) upper and lower half-thicknesses (inboard row, outboard row)."""
    x = _q(100.0 * _stations(d, m, 1.0))
    f = x / 100.0
    rows = []
    for _ in range(2 if both_sections else 1):
        tau = d.uniform(0.015, 0.05)
        base = 100.0 * 4.0 * tau * f * (1.0 - f)
        a = d.uniform(-0.3, 0.3) if both_sides else 0.0
        rows.append((_q(base * (1 + a)), _q(base * (1 - a))))
    if len(rows) == 1:
        rows = rows * 2
    return x, np.stack([rows[0][0], rows[1][0]]), np.stack([rows[0][1], rows[1][1]])


# ------------------------------------------------------------------------------------------
# Writing
# ------------------------------------------------------------------------------------------
def _deck_text(title, control, refa, wing, body, pods, fins, canards, case):
    out = [title[:80], "".join(f"{int(v):3d}" for v in control).ljust(72) + "CONTROL"]
    if refa is not None:
        out += _cards(refa, "REFA")
    w = wing.numbers
    out += _cards(w["xaf"], "XAF")
    for i, (le, c) in enumerate(zip(w["le"], w["chord"]), 1):
        out += _cards([*le, c], f"WAFORG {i}")
    if w["camber"] is not None:
        for i, row in enumerate(w["camber"], 1):
            out += _cards(row, f"TZORD {i}")
    for i in range(w["chord"].size):
        out += _cards(w["upper"][i], f"WAFORD{i + 1}U" if control[8] < 0 else f"WAFORD {i + 1}")
        if control[8] < 0:
            out += _cards(w["lower"][i], f"WAFORD{i + 1}L")
    for i, s in enumerate(body["segments"], 1):
        out += _cards(s["x"], f"XFUS {i}")
        if "area" in s:
            if control[2] == -1 and control[6] == 0:
                out += _cards(s["zc"], f"ZFUS {i}")
            out += _cards(s["area"], f"FUSARD {i}")
        else:
            for j in range(len(s["x"])):
                out += _cards(s["y"][j], f"Y {i}-{j + 1}")
                out += _cards(s["z"][j], f"Z {i}-{j + 1}")
    for k, p in enumerate(pods, 1):
        n = p.numbers
        out += _cards(n["origin"], f"PODORG {k}") + _cards(n["x"], f"XPOD {k}")
        out += _cards(n["radius"], f"PODR {k}")
    for k, f in enumerate(fins, 1):
        n = f.numbers
        out += _cards(np.concatenate([np.r_[n["le"][0], n["chord"][0]],
                                      np.r_[n["le"][1], n["chord"][1]]]), f"FINORG {k}")
        out += _cards(n["xaf"], f"XFIN {k}") + _cards(n["upper"][0], f"FINORD{k}O")
        if control[20] < 0:
            out += _cards(n["lower"][0], f"FINORD{k}I")
    for k, c in enumerate(canards, 1):
        n = c.numbers
        out += _cards(np.concatenate([np.r_[n["le"][0], n["chord"][0]],
                                      np.r_[n["le"][1], n["chord"][1]]]), f"CANORG {k}")
        out += _cards(n["xaf"], f"XCAN {k}")
        sets = [n["upper"][0]]
        if control[22] < 0 and control[23] < 0:
            sets = [n["upper"][0], n["upper"][1], n["lower"][0], n["lower"][1]]
        elif control[22] < 0:
            sets = [n["upper"][0], n["upper"][1]]
        elif control[23] < 0:
            sets = [n["upper"][0], n["lower"][0]]
        for s in sets:
            out += _cards(s, f"CANORD {k}")
    if case:
        out.append(f"{'M2.0':4}{2000:4d}{50:4d}{16:4d}{0:4d}{0:4d}".ljust(72) + "CASE 1")
    return "\n".join(out) + "\n"


def _listed(numbers):
    """Card numbers as plain lists (JSON-ready); None stays None."""
    return {k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in numbers.items()}


def _build(d, parts):
    fus, segments, nradx, j6, labels = _draw_fuselage(d)
    desc = dict(labels)
    wing = _draw_wing(d, fus)
    desc.update(wing.labels)
    m_fin, fin_asym = d.integer(3, 10), d.chance(0.3)
    b = _Builder(d, fus, m_fin, fin_asym)
    b.parts.append(wing)
    fins, pods = [], []
    desc["pods"] = []
    if "pods" in parts:
        pods, desc["pods"] = _draw_pods(b, wing, fins)
    desc["body_fin"], desc["wing_fin"] = "none", 0
    if "fins" in parts:
        body_fin = d.choice(FAMILIES["body_fin"], "body_fin")
        if body_fin != "none":
            fin = _body_fin(b, body_fin, f"fin {len(fins) + 1}", wing)
            if fin is None:
                b.dropped.append(f"{body_fin} fin (no room)")
            elif b.add(fin):
                fins.append(fin)
                desc["body_fin"] = body_fin
        if d.choice(FAMILIES["wing_fin"], "wing_fin"):
            fin = _wing_fin(b, f"fin {len(fins) + 1}", wing, pods)
            if fin is None:
                b.dropped.append("wing fin (no room)")
            elif b.add(fin):
                fins.append(fin)
                desc["wing_fin"] = 1
    canards = []
    desc["canards"] = "none"
    m_can = d.integer(3, 10)
    both_sections, both_sides = d.chance(0.4), d.chance(0.4)
    if "canards" in parts:
        kinds = d.choice(FAMILIES["canards"], "canards")
        for kind in () if kinds == "none" else kinds.split("+"):
            ords = _canard_ordinates(d, m_can, both_sections, both_sides)
            part = _surface_part(b, kind, wing, ords)
            if part is None:
                b.dropped.append(f"{kind} (no room)")
            elif b.add(part):
                canards.append(part)
        desc["canards"] = "+".join(p.name for p in canards) or "none"
    counts = {"canard": 0, "tail": 0}
    for part in canards:
        counts[part.name] += 1
        part.name = f"{part.name} {counts[part.name]}"

    cambered = wing.numbers["camber"] is not None
    nwafor = wing.numbers["xaf"].size * (-1 if desc["unsymmetric"] else 1)
    seg_counts = []
    for i in range(4):
        seg_counts += [nradx[i], len(segments[i]["x"])] if i < len(segments) else [0, 0]
    refa = None
    if d.chance(0.5):
        w = wing.numbers
        area = float(np.sum(np.diff(w["le"][:, 1]) * 0.5 * (w["chord"][1:] + w["chord"][:-1])))
        refa = _q([2 * area, w["chord"][0] * 0.6, w["le"][0, 0] + 0.25 * w["chord"][0]])
    control = [1 if refa is not None else 0, 1 if cambered else -1,
               -1 if desc["section"] == "circular" else 1, 1 if pods else 0,
               1 if fins else 0, 1 if canards else 0, j6, wing.numbers["chord"].size, nwafor,
               len(segments), *seg_counts, len(pods),
               pods[0].numbers["x"].size if pods else 0,
               (-1 if fin_asym else 1) * len(fins) if fins else 0, m_fin if fins else 0,
               (-1 if both_sections else 1) * len(canards) if canards else 0,
               (-1 if both_sides else 1) * m_can if canards else 0]
    body_numbers = {"kind": desc["section"], "segments": [
        {"x": s["x"], "radius": np.sqrt(s["area"] / np.pi), "zc": s["zc"]}
        if "area" in s else {"x": s["x"], "y": s["y"], "z": s["z"]} for s in segments]}
    for s, src in zip(body_numbers["segments"], segments):
        if "area" in src:
            s["area"] = src["area"]
    title = (f"GENERATED {desc['section'].upper()} BODY {len(segments)} SEG, "
             f"{desc['wing_height'].upper()} WING ROOT {desc['root'].upper()}, "
             f"{len(pods)} PODS {len(fins)} FINS {len(canards)} CANARDS")
    text = _deck_text(title, control, refa, wing, {"segments": segments}, pods, fins, canards,
                      d.chance(0.5))
    desc["fins"] = [f.labels["role"] for f in fins]
    desc["dropped"] = list(b.dropped)
    comps = {"wing": _listed(wing.numbers), "body": {
        "kind": body_numbers["kind"],
        "segments": [_listed(s) for s in body_numbers["segments"]]}}
    comps["wing"]["touches"] = ["body"]
    comps["body"]["touches"] = []
    for part in pods + fins + canards:
        comps[part.name] = _listed(part.numbers)
        comps[part.name]["touches"] = list(part.touches)
    desc["components"] = comps
    return text, desc


def _airplanes(parts, pins):
    unknown = set(pins) - set(FAMILIES)
    if unknown:
        raise ValueError(f"unknown families {sorted(unknown)}; known: {sorted(FAMILIES)}")
    return st.integers(0, 2 ** 64 - 1).map(lambda seed: _build(_Draw(seed, pins), parts))


def deck_from_seed(seed, parts=_ALL_PARTS, **pins):
    """The ``(deck_text, description)`` a strategy builds from ``seed`` (to rebuild a deck
    hypothesis reports). ``parts``: ``()`` for :func:`wing_body_decks`, ``("pods",)``,
    ``("fins",)``, ``("fins", "canards")`` or all three for :func:`decks`."""
    return _build(_Draw(seed, pins), tuple(parts))


def decks(**pins):
    """Whole airplanes: wing, fuselage, pods, fins, canards and tails, as deck text.

    Returns a strategy of ``(deck_text, description)``; keyword arguments pin families
    (:data:`FAMILIES`), e.g. ``decks(section="circular", pods=2, pod_mount="pylon")``.
    """
    return _airplanes(_ALL_PARTS, pins)


def wing_body_decks(**pins):
    """A wing and a fuselage only (every wing and fuselage family)."""
    return _airplanes((), pins)


def pod_decks(**pins):
    """Wing, fuselage and 1-3 pods, free or on pylons."""
    pins.setdefault("pods", None)
    if pins["pods"] is None:
        del pins["pods"]
        return _airplanes(("pods",), pins).filter(lambda t: len(t[1]["pods"]) > 0)
    return _airplanes(("pods",), pins)


def fin_decks(**pins):
    """Wing, fuselage and fins: centre-line, twin or on the wing."""
    return _airplanes(("fins",), pins)


def empennage_decks(**pins):
    """Wing, fuselage, fins, canards and tails (no pods)."""
    return _airplanes(("fins", "canards"), pins)
