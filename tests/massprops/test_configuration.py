"""Mass properties of whole Configurations: closed forms (diamond prisms, WingSegment, cylinder,
cone, cuboid), exactness of the Gauss rules against much higher-order rules, mirror images,
parallel-axis consistency, the bundled deck, and ``run_massprops``."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate
from scipy.interpolate import PchipInterpolator

import juncture as jc
from juncture.errors import DeckError, GeometryError, JunctureWarning, SpecError
from juncture.massprops import CustomThickness, Diamond, MassProperties, WingSegment
from juncture.massprops.command import is_massprops_spec, run_massprops
from juncture.massprops.configuration import (
    _arbitrary_unit,
    _circular_unit,
    _props,
    _winglike_unit,
    component_mass_properties,
    configuration_mass_properties,
)
from juncture.massprops.spec import evaluate_spec, format_table, spec_report_json
from juncture.model import ArbitraryBody, CircularBody, Configuration, WingLike
from tests.support import EXAMPLE_DECK, PDAS_DECK, PDAS_WGS

RTOL = 1e-12


def assert_props(p, mass, cg, inertia, rtol=RTOL):
    inertia = np.asarray(inertia, float)
    assert p.mass == pytest.approx(mass, rel=rtol)
    scale = max(np.abs(cg).max(), math.sqrt(np.trace(inertia) / mass))
    np.testing.assert_allclose(p.cg, cg, rtol=rtol, atol=rtol * scale)
    np.testing.assert_allclose(p.inertia, inertia, rtol=rtol, atol=rtol * np.abs(inertia).max())


def diamond_wing(name, kind, le, chord, tau, span, x_m=0.5, mirrored=False, chordwise="linear"):
    # chordwise "linear": PCHIP would round the diamond's ridge (zero slope at the maximum)
    """Two-section wing-like component with a diamond section (max at x_m) of t/c = tau."""
    le = np.asarray(le, float)
    tip = le + np.asarray(span, float)
    half = [0.0, 50.0 * tau, 0.0]
    return WingLike(name, kind, [le, tip], [chord, chord], [0.0, 100.0 * x_m, 100.0], [half, half],
                    mirrored=mirrored, chordwise=chordwise)


# ------------------------------------------------------------------ closed forms: wings
@pytest.mark.parametrize("kind, axes", [("wing", (0, 1, 2)), ("fin", (0, 2, 1))])
def test_rectangular_diamond_prism(kind, axes):
    """Constant diamond section, chord c, thickness t = c tau, span b: a rhombic prism.

    Rhombus with diagonals c, t: area c t / 2, integral x'^2 dA = A c^2 / 24, z'^2: A t^2 / 24.
    """
    c, tau, b = 7.0, 0.06, 11.0
    le = np.array([3.0, 2.0, -1.5])
    span = np.zeros(3)
    span[axes[1]] = b
    w = diamond_wing("p", kind, le, c, tau, span)
    p = component_mass_properties(w, density=2.5)
    t = c * tau
    m = 2.5 * b * c * t / 2
    cg = le.copy()
    cg[0] += c / 2
    cg[axes[1]] += b / 2
    second = np.zeros(3)                        # integral of coordinate^2 dm about the CG
    second[0], second[axes[1]], second[axes[2]] = m * c * c / 24, m * b * b / 12, m * t * t / 24
    assert p.volume == pytest.approx(b * c * t / 2, rel=RTOL)
    assert_props(p, m, cg, np.diag(second.sum() - second))


def test_tapered_swept_diamond_equals_wing_segment():
    """Linear loft of a diamond (max at 30 %) with constant t/c is WingSegment's solid."""
    b, cr, ct, tau, x_m = 9.0, 5.0, 2.0, 0.08, 0.3
    sweep = math.radians(35.0)
    root_qc = np.array([4.0, 1.5, -0.7])
    le_root = root_qc - [cr / 4, 0, 0]
    le_tip = root_qc + [b * math.tan(sweep) - ct / 4, b, 0.0]
    half = [0.0, 50 * tau, 0.0]
    w = WingLike("wing", "wing", [le_root, le_tip], [cr, ct], [0.0, 100 * x_m, 100.0],
                 [half, half], mirrored=True, chordwise="linear")
    ref = WingSegment(b, cr, ct, tau, tau, sweep=sweep, side="both", airfoil=Diamond(x_m),
                      root_quarter_chord=root_qc).mass_properties(density=3.0)
    p = component_mass_properties(w, density=3.0)
    assert p.allclose(ref, rtol=1e-12)
    assert p.cg[1] == 0.0


def test_pchip_naca_wing_equals_wing_segment_with_the_same_thickness():
    """A PCHIP-interpolated NACA 0012 section: WingSegment with mu = the same PCHIP curve
    (built here with scipy directly, v-integrals by adaptive quadrature) is the same solid."""
    x = np.array([0.0, 1.25, 2.5, 5, 10, 15, 20, 30, 40, 50, 60, 70, 80, 90, 95, 100])
    u = x / 100
    half = 100 * 5 * 0.12 * (0.2969 * np.sqrt(u) - 0.126 * u - 0.3516 * u ** 2
                             + 0.2843 * u ** 3 - 0.1036 * u ** 4)   # % chord, closed TE
    half[-1] = 0.0                                                  # not -1.7e-15
    tau = 2 * half.max() / 100
    pchip = PchipInterpolator(u, half)
    # 0.25 too: there the v1 weight (x - 1/4) changes sign, and QUADPACK at epsrel 1e-13
    # reports round-off on an interval straddling it
    mu = CustomThickness(lambda f: 2 * float(pchip(f)) / 100 / tau,
                         breakpoints=(*u[1:-1], 0.25))
    b, cr, ct = 6.0, 3.0, 1.2
    sweep = math.radians(20.0)
    root_qc = np.array([1.0, 0.0, 0.3])
    le = [root_qc - [cr / 4, 0, 0], root_qc + [b * math.tan(sweep) - ct / 4, b, 0.0]]
    w = WingLike("w", "wing", le, [cr, ct], x, [half, half], mirrored=False)
    ref = WingSegment(b, cr, ct, tau, tau, sweep=sweep, airfoil=mu,
                      root_quarter_chord=root_qc).mass_properties(density=1.0)
    assert component_mass_properties(w).allclose(ref, rtol=1e-10)


@pytest.mark.filterwarnings("ignore:.*NFORX:juncture.errors.JunctureWarning")
def test_pdas_deck_wing_with_linear_chordwise_equals_wing_segment():
    """PDAS wdcase1: diamond wing root LE (100, 10, 0) chord 140, pointed tip (240, 150, 0),
    t/c 5 %. With linear chordwise interpolation it is a WingSegment pair: sweep tan = 0.75."""
    cfg = jc.read(PDAS_DECK)
    w = cfg["wing"] if "wing" in cfg.components else cfg.wings[0]
    lin = WingLike(w.name, w.kind, w.le, w.chord, w.x_over_c, w.upper, w.lower, w.camber,
                   w.mirrored, "linear")
    total, parts = configuration_mass_properties(cfg.with_component(lin))
    ref = WingSegment(140.0, 140.0, 0.0, 0.05, 0.05, sweep=math.atan(0.75), side="both",
                      airfoil=Diamond(0.5), root_quarter_chord=[135.0, 10.0, 0.0]
                      ).mass_properties(density=1.0)
    assert dict(parts)[w.name].allclose(ref, rtol=1e-12)
    assert ref.volume == pytest.approx(2 * 0.025 * 140.0 ** 3 / 3, rel=1e-14)


# ------------------------------------------------------------------ closed forms: bodies
@pytest.mark.parametrize("axial", ["pchip", "linear"])
def test_cylinder_body(axial):
    radius, length = 1.7, 9.0
    origin = np.array([5.0, 0.0, -2.0])
    b = CircularBody("can", [1.0, 4.0, 1.0 + length], np.full(3, radius), np.full(3, 0.4),
                     origin=origin, axial=axial)
    p = component_mass_properties(b, density=0.7)
    m = 0.7 * math.pi * radius ** 2 * length
    trans = m * (3 * radius ** 2 + length ** 2) / 12
    assert_props(p, m, [origin[0] + 1.0 + length / 2, 0.0, origin[2] + 0.4],
                 np.diag([m * radius ** 2 / 2, trans, trans]))


@pytest.mark.parametrize("axial", ["pchip", "linear"])
def test_cone_body(axial):
    """Apex at x = 2, base radius R at x = 2 + L: cg 3L/4 from the apex, Ixx = 3 m R^2 / 10,
    transverse about the cg 3 m (R^2 / 20 + L^2 / 80)."""
    radius, length = 2.0, 7.0
    b = CircularBody("cone", [2.0, 2.0 + length], [0.0, radius], axial=axial)
    p = component_mass_properties(b)
    m = math.pi * radius ** 2 * length / 3
    trans = 3 * m * (radius ** 2 / 20 + length ** 2 / 80)
    assert_props(p, m, [2.0 + 0.75 * length, 0.0, 0.0],
                 np.diag([0.3 * m * radius ** 2, trans, trans]))


def test_mirrored_pod_pair():
    """Cylinders at y = +/- y0: cg on y = 0, Ixx and Izz gain m y0^2 each (parallel axes)."""
    radius, length, y0, z0 = 1.1, 6.0, 4.0, -1.0
    b = CircularBody("pod", [0.0, length], [radius, radius], origin=[10.0, y0, z0],
                     mirrored=True)
    p = component_mass_properties(b)
    m1 = math.pi * radius ** 2 * length
    trans = m1 * (3 * radius ** 2 + length ** 2) / 12
    assert_props(p, 2 * m1, [10.0 + length / 2, 0.0, z0],
                 np.diag([2 * (m1 * radius ** 2 / 2 + m1 * y0 ** 2), 2 * trans,
                          2 * (trans + m1 * y0 ** 2)]))
    assert p.cg[1] == 0.0
    single = component_mass_properties(b, symmetric=False)
    assert single.mass == pytest.approx(m1, rel=RTOL)
    assert single.cg[1] == pytest.approx(y0, rel=RTOL)


@pytest.mark.parametrize("reverse", [False, True])
def test_arbitrary_body_box_is_a_cuboid(reverse):
    """Half-section rectangle 0 <= y <= a, z0 - h <= z <= z0 + h: whole section 2a x 2h."""
    a, h, z0, x0, length = 1.2, 0.8, 0.6, 3.0, 5.0
    half = np.array([[0.0, z0 - h], [a, z0 - h], [a, z0], [a, z0 + h], [0.0, z0 + h]])
    if reverse:
        half = half[::-1]
    b = ArbitraryBody("box", [x0, x0 + 2.0, x0 + length], [half] * 3)
    p = component_mass_properties(b, density=2.0)
    m = 2.0 * 2 * a * 2 * h * length
    size2 = np.array([length, 2 * a, 2 * h]) ** 2
    assert_props(p, m, [x0 + length / 2, 0.0, z0], np.diag(m / 12 * (size2.sum() - size2)))
    half_only = component_mass_properties(b, symmetric=False)
    assert half_only.volume == pytest.approx(a * 2 * h * length, rel=RTOL)
    assert half_only.cg[1] == pytest.approx(a / 2, rel=RTOL)


# ------------------------------------------------------------------ exactness of the rules
def random_wing(rng, chordwise, kind="wing"):
    n_sec, x = 4, np.array([0.0, 3.0, 10.0, 25.0, 45.0, 60.0, 80.0, 92.0, 100.0])
    span = np.cumsum(rng.uniform(1.0, 3.0, n_sec))
    le = np.stack([np.cumsum(rng.uniform(0.5, 2.0, n_sec)), span,
                   rng.uniform(-0.5, 0.5, n_sec)], -1)
    if kind == "fin":
        le = le[:, [0, 2, 1]]
    up = rng.uniform(0.5, 6.0, (n_sec, x.size))
    lo = rng.uniform(0.5, 6.0, (n_sec, x.size))
    up[:, [0, -1]] = lo[:, [0, -1]] = 0.0
    cam = rng.uniform(-0.2, 0.2, (n_sec, x.size))
    return WingLike("w", kind, le, rng.uniform(1.0, 5.0, n_sec), x, up, lo, cam,
                    mirrored=False, chordwise=chordwise)


def rel_diff(a, b):
    scale = np.abs(b.inertia).max()
    return max(abs(a.mass - b.mass) / abs(b.mass),
               np.abs(a.cg - b.cg).max() / math.sqrt(scale / b.mass),
               np.abs(a.inertia - b.inertia).max() / scale)


@pytest.mark.parametrize("chordwise, kind", [("pchip", "wing"), ("linear", "wing"),
                                             ("pchip", "fin")])
def test_wing_rule_is_exact(chordwise, kind):
    """3 x 5 Gauss points equal 9 x 14 to rounding; 2 x 4 (degrees 3, 7 < 4, 9) do not."""
    w = random_wing(np.random.default_rng(7), chordwise, kind)
    default, high = _winglike_unit(w), _winglike_unit(w, n_span=9, n_chord=14)
    assert rel_diff(default, high) < 1e-13
    if chordwise == "pchip":
        assert rel_diff(_winglike_unit(w, n_span=3, n_chord=4), high) > 1e-9
    assert rel_diff(_winglike_unit(w, n_span=2, n_chord=5), high) > 1e-9


def test_circular_body_rule_is_exact():
    rng = np.random.default_rng(11)
    x = np.concatenate([[0.0, 1.0, 2.5, 4.0], [4.0, 6.0, 9.0, 10.0, 13.0]])
    r = np.concatenate([[0.0, 0.7, 1.1, 1.3], [1.3, 1.6, 1.2, 1.4, 0.5]])
    b = CircularBody("b", x, r, rng.uniform(-0.3, 0.3, x.size), origin=[2.0, 0.0, 1.0],
                     segments=(4, 5))
    default, high = _circular_unit(b), _circular_unit(b, n=16)
    assert rel_diff(default, high) < 1e-13
    assert rel_diff(_circular_unit(b, n=6), high) > 1e-11      # exact to degree 11 < 12


def test_circular_body_volume_against_adaptive_quadrature():
    cfg = jc.read(EXAMPLE_DECK)
    b = cfg["body"]
    edges = np.unique(b.x_global)
    vol = sum(integrate.quad(lambda s: float(b.area_at(s)), lo, hi, epsabs=0, epsrel=1e-13)[0]
              for lo, hi in zip(edges[:-1], edges[1:]))
    assert component_mass_properties(b).volume == pytest.approx(vol, rel=1e-12)


def test_arbitrary_body_is_the_decks_polylines_not_a_resampling():
    """Sections with corners at irrational arc-length fractions, unequal point counts and a
    top point off the plane of symmetry: the volume is the integral of the exact polygon
    area (adaptive quadrature of ``area_at``), and a frustum of trapezoids has its closed
    form."""
    rng = np.random.default_rng(3)
    secs = [np.stack([rng.uniform(0.3, 2.0, k), np.sort(rng.uniform(-1.5, 1.5, k))], -1)
            for k in (4, 7, 5, 3)]
    b = ArbitraryBody("a", [0.0, 1.7, 4.2, 6.0], secs)
    vol = sum(integrate.quad(lambda s: float(b.area_at(s)), lo, hi, epsabs=0, epsrel=1e-13)[0]
              for lo, hi in zip(b.x[:-1], b.x[1:]))
    assert component_mass_properties(b).volume == pytest.approx(vol, rel=1e-12)
    # Trapezoid half-sections (0, -h) (w_b, -h) (w_t, h) (0, h), scaled by (1 + x / 4):
    # whole area 2 h (w_b + w_t) (1 + x / 4)^2, volume over 0..4 = 2 h (w_b + w_t) 28 / 3.
    w_b, w_t, h = 1.0, 0.4, 0.7
    trap = np.array([[0.0, -h], [w_b, -h], [w_t, h], [0.0, h]])
    t = ArbitraryBody("t", [0.0, 4.0], [trap, 2.0 * trap])
    assert component_mass_properties(t).volume == pytest.approx(
        2 * h * (w_b + w_t) * 28.0 / 3.0, rel=1e-13)


def test_arbitrary_body_rule_is_exact():
    rng = np.random.default_rng(5)
    secs = [np.stack([np.abs(rng.uniform(0.2, 2.0, k)) * np.sin(np.linspace(0, np.pi, k)),
                      np.linspace(-1.0, 1.0, k) + rng.uniform(-0.1, 0.1)], -1)
            for k in (5, 7, 6, 9)]
    b = ArbitraryBody("a", [0.0, 2.0, 5.0, 6.0], secs, resample=31)
    default, high = _arbitrary_unit(b), _arbitrary_unit(b, n=8)
    assert rel_diff(default, high) < 1e-13
    assert rel_diff(_arbitrary_unit(b, n=2), high) > 1e-9


# ------------------------------------------------------------------ invariants
@settings(max_examples=25, deadline=None)
@given(shift=st.tuples(*[st.floats(-50, 50)] * 3), scale=st.floats(0.2, 5.0),
       seed=st.integers(0, 2 ** 16))
def test_translation_and_scaling(shift, scale, seed):
    """Moving a component moves its cg only; scaling lengths by k scales V by k^3, I by k^5."""
    w = random_wing(np.random.default_rng(seed), "pchip")
    p = component_mass_properties(w)
    moved = WingLike("w", "wing", scale * w.le + shift, scale * w.chord, w.x_over_c, w.upper,
                     w.lower, scale * w.camber, mirrored=False)
    q = component_mass_properties(moved)
    assert q.volume == pytest.approx(scale ** 3 * p.volume, rel=1e-12)
    np.testing.assert_allclose(q.cg, scale * p.cg + shift, rtol=1e-12,
                               atol=1e-12 * (np.abs(q.cg).max() + 1))
    np.testing.assert_allclose(q.inertia, scale ** 5 * p.inertia, rtol=1e-11,
                               atol=1e-12 * np.abs(q.inertia).max())
    assert q.is_physical()


# ------------------------------------------------------------------ whole configurations
@pytest.fixture(scope="module")
def deck():
    return jc.read(EXAMPLE_DECK)


def test_bundled_deck(deck):
    total, parts = configuration_mass_properties(deck)
    assert [n for n, _ in parts] == list(deck.components)
    for name, p in parts:
        assert np.isfinite(p.volume) and p.volume > 0, name
        assert p.mass == p.volume                      # default density 1
        assert abs(p.cg[1]) <= 1e-12 * np.abs(p.cg).max(), name
        assert p.is_physical(), name
    assert abs(total.cg[1]) <= 1e-12 * np.abs(total.cg).max()
    assert total.volume == pytest.approx(sum(p.volume for _, p in parts), rel=1e-14)


def test_parallel_axis_consistency(deck):
    total, parts = configuration_mass_properties(deck, densities={"wing": 3.0, "body": 0.5})
    np.testing.assert_allclose(total.inertia_origin, sum(p.inertia_origin for _, p in parts),
                               rtol=1e-12, atol=1e-12 * np.abs(total.inertia_origin).max())
    assert total.mass == pytest.approx(sum(p.mass for _, p in parts), rel=1e-14)
    np.testing.assert_allclose(total.cg * total.mass, sum(p.cg * p.mass for _, p in parts),
                               rtol=1e-12)


def test_mirrored_component_is_the_pair(deck):
    """fin 1 is off the centre line: its entry is itself + image; fin 3 is on it (alone)."""
    fin = deck["fin 1"]
    one = component_mass_properties(fin, symmetric=False)
    pair = component_mass_properties(fin)
    assert pair.cg[1] == 0.0 and one.cg[1] > 0
    assert pair.mass == pytest.approx(2 * one.mass, rel=1e-14)
    assert pair.allclose(one + one.mirrored("xz"), rtol=1e-13)
    c3 = deck["fin 3"]
    assert component_mass_properties(c3).allclose(component_mass_properties(c3, symmetric=False))


def test_densities_and_masses(deck):
    unit, parts1 = configuration_mass_properties(deck)
    vols = {n: p.volume for n, p in parts1}
    _, parts = configuration_mass_properties(deck, density=2.0, densities={"body": 0.5},
                                             masses={"wing": 100.0})
    got = dict(parts)
    assert got["wing"].mass == pytest.approx(100.0, rel=1e-14)
    assert got["body"].mass == pytest.approx(0.5 * vols["body"], rel=1e-14)
    assert got["fin 3"].mass == pytest.approx(2.0 * vols["fin 3"], rel=1e-14)
    assert got["fin 3"].volume == pytest.approx(vols["fin 3"], rel=1e-14)
    np.testing.assert_allclose(got["fin 3"].inertia, 2.0 * dict(parts1)["fin 3"].inertia)
    total, parts = configuration_mass_properties(deck, mass=1000.0, masses={"wing": 10.0})
    assert total.mass == pytest.approx(1010.0, rel=1e-13)
    rest = sum(v for n, v in vols.items() if n != "wing")
    assert dict(parts)["body"].mass == pytest.approx(1000.0 * vols["body"] / rest, rel=1e-13)
    neg = component_mass_properties(deck["pod 1"], density=-1.0)
    assert neg.mass < 0 and neg.volume < 0


def test_errors(deck):
    with pytest.raises(GeometryError, match="not both"):
        configuration_mass_properties(deck, density=1.0, mass=2.0)
    with pytest.raises(GeometryError, match="nacelle: no such component .in densities"):
        configuration_mass_properties(deck, densities={"nacelle": 1.0})
    with pytest.raises(GeometryError, match="wing: is given both a density and a mass"):
        configuration_mass_properties(deck, densities={"wing": 1.0}, masses={"wing": 1.0})
    with pytest.raises(GeometryError, match="body: mass must be finite"):
        configuration_mass_properties(deck, masses={"body": float("nan")})
    with pytest.raises(GeometryError, match="density must be a number, found 'heavy'"):
        configuration_mass_properties(deck, density="heavy")
    with pytest.raises(GeometryError, match="there are none"):
        configuration_mass_properties(deck, mass=5.0, densities=dict.fromkeys(deck.components,
                                                                               1.0))
    with pytest.raises(GeometryError, match="need a Configuration.*found Geometry"):
        configuration_mass_properties(deck.to_geometry())
    with pytest.raises(GeometryError, match="pod 1: give density or mass, not both"):
        component_mass_properties(deck["pod 1"], density=1.0, mass=1.0)
    with pytest.raises(GeometryError, match="not a wing-like component or body"):
        component_mass_properties(MassProperties.zero())


def test_flat_component_has_no_volume():
    flat = WingLike("plate", "wing", [[0, 0, 0], [0, 2, 0]], [1, 1], [0, 100],
                    [[0, 0], [0, 0]], mirrored=True)
    cfg = Configuration({"plate": flat})
    with pytest.warns(JunctureWarning, match="plate: has no volume"):
        total, parts = configuration_mass_properties(cfg)
    assert total.mass == 0.0 and parts[0][1].volume == 0.0
    with pytest.warns(JunctureWarning), pytest.raises(GeometryError,
                                                       match="plate: has no volume, so it"):
        configuration_mass_properties(cfg, masses={"plate": 3.0})
    with pytest.warns(JunctureWarning), pytest.raises(GeometryError,
                                                       match="plate: has no volume, so it"):
        component_mass_properties(flat, mass=3.0)


def test_negative_volume_is_an_error():
    """Unreachable from validated components (sections increase, thicknesses >= 0) short of
    PCHIP offsets crossing everywhere; the guard is checked directly."""
    with pytest.raises(GeometryError, match="odd: integrates to a negative volume .-2.; expected"):
        _props(-2.0, np.zeros(3), np.eye(3), np.zeros(3), "odd", "odd")


def test_unsymmetric_configuration_has_no_images(deck):
    one = deck.replace(symmetric=False)
    total, parts = configuration_mass_properties(one)
    sym = dict(configuration_mass_properties(deck)[1])
    for name, p in parts:
        factor = 2.0 if deck[name].mirrored else 1.0
        assert sym[name].mass == pytest.approx(factor * p.mass, rel=1e-13), name


# ------------------------------------------------------------------ run_massprops
SPEC = {"title": "two solids", "components": [
    {"name": "tank", "type": "cylinder", "center": [1.0, 0.0, 0.0], "axis": [1.0, 0.0, 0.0],
     "radius": 0.5, "length": 2.0, "density": 3.0},
    {"name": "ballast", "type": "point", "center": [4.0, 0.0, -1.0], "mass": 2.0}]}


@pytest.fixture()
def spec_file(tmp_path):
    path = tmp_path / "spec.json"
    path.write_text(json.dumps(SPEC))
    return path


def test_run_massprops_spec(spec_file):
    total, parts = evaluate_spec(SPEC)
    assert json.loads(run_massprops(spec_file, as_json=True)) == json.loads(
        json.dumps(spec_report_json(total, parts)))
    assert run_massprops(spec_file) == format_table(total, parts)
    m = 3.0 * math.pi * 0.25 * 2.0
    out = json.loads(run_massprops(spec_file, as_json=True))
    assert out["total"]["mass"] == pytest.approx(m + 2.0, rel=1e-14)
    assert [c["name"] for c in out["components"]] == ["tank", "ballast"]


def test_run_massprops_deck(deck, monkeypatch):
    """The per-component table and the density; the enclosed solid after the table (its
    numbers are tested in test_closed.py)."""
    from juncture.massprops import command

    total, parts = configuration_mass_properties(deck)
    monkeypatch.setattr(command, "enclosed_mass_properties", lambda cfg, rho: "not here")
    table = run_massprops(EXAMPLE_DECK)
    assert "uniform density 1 (mass = volume)" in table.splitlines()[0]
    assert format_table(total, parts) + "enclosed solid: none (not here)" in table  # then it
    monkeypatch.setattr(command, "enclosed_mass_properties", lambda cfg, rho: None)
    out = json.loads(run_massprops(EXAMPLE_DECK, as_json=True))
    assert out["total"]["mass"] == pytest.approx(total.mass, rel=1e-15)
    assert [c["name"] for c in out["components"]] == list(deck.components)
    np.testing.assert_allclose(out["components"][1]["inertia_origin"],
                               parts[1][1].inertia_origin)
    heavy = json.loads(run_massprops(EXAMPLE_DECK, as_json=True, density=2.0))
    assert heavy["total"]["mass"] == pytest.approx(2 * total.mass, rel=1e-14)
    assert "uniform density 2;" in run_massprops(EXAMPLE_DECK, density=2.0)


def test_run_massprops_juncture_model_is_not_a_spec(deck, tmp_path, monkeypatch):
    from juncture.massprops import command

    monkeypatch.setattr(command, "enclosed_mass_properties", lambda cfg, rho: None)
    path = tmp_path / "model.json"
    jc.write(deck, path)
    assert not is_massprops_spec(path) and not is_massprops_spec(EXAMPLE_DECK)
    got = json.loads(run_massprops(path, as_json=True))["total"]["mass"]
    assert got == pytest.approx(configuration_mass_properties(deck)[0].mass, rel=1e-12)


def test_run_massprops_errors(spec_file, tmp_path):
    with pytest.raises(SpecError, match="a density applies to decks and models only"):
        run_massprops(spec_file, density=2.0)
    with pytest.raises(SpecError, match="describes surface networks .Geometry., not solid"):
        run_massprops(PDAS_WGS)
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"components": [{"type": "blimp", "density": 1.0}]}))
    with pytest.raises(SpecError, match='field "type" must be one of wing, rotor'):
        run_massprops(bad)
    broken = tmp_path / "broken.json"
    broken.write_text('{"components": [{"type": "sphere",}]}')
    with pytest.raises(SpecError, match="line 1, column .*invalid JSON"):
        run_massprops(broken)
    with pytest.raises(DeckError, match="cannot open file"):
        run_massprops(tmp_path / "missing.inp")
    with pytest.raises(SpecError, match=r"wave.inp: .*density must be finite"):
        path = tmp_path / "wave.inp"
        path.write_bytes(EXAMPLE_DECK.read_bytes())
        run_massprops(path, density=float("inf"))
