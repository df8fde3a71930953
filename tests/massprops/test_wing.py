"""WingSegment closed forms (Moulton & Hunsaker eqs 16-59) against tensor Gauss-Legendre
quadrature of the same solid in span / chord / thickness coordinates (massprops_quadrature)."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.errors import GeometryError
from juncture.massprops import (
    NACA4_PRESETS,
    CustomThickness,
    Diamond,
    MassProperties,
    Naca4,
    WingSegment,
    wing_segments_mass_properties,
)
from juncture.massprops.wing import paper_to_project
from tests.massprops.massprops_quadrature import wing_reference

RTOL = 1e-9


def assert_matches(props, ref, rtol=RTOL):
    m, vol, cg, inertia = ref
    assert props.mass == pytest.approx(m, rel=rtol)
    assert props.volume == pytest.approx(vol, rel=rtol)
    scale_c = max(np.abs(cg).max(), math.sqrt(abs(np.trace(inertia) / m)))
    np.testing.assert_allclose(props.cg, cg, rtol=rtol, atol=rtol * scale_c)
    np.testing.assert_allclose(props.inertia, inertia, rtol=rtol,
                               atol=rtol * np.abs(inertia).max())


def naca_mu(a):
    return lambda x: a[0] * np.sqrt(x) + a[1] * x + a[2] * x**2 + a[3] * x**3 + a[4] * x**4


wing_params = st.fixed_dictionaries({
    "b": st.floats(0.2, 20.0), "cr": st.floats(0.05, 5.0), "taper": st.floats(0.0, 1.5),
    "tr": st.floats(0.02, 0.3), "tt": st.floats(0.0, 0.3),
    "sweep": st.floats(-1.2, 1.2), "dihedral": st.floats(-0.8, 0.8),
    "root": st.tuples(*[st.floats(-5.0, 5.0)] * 3), "density": st.floats(0.1, 1000.0),
    "side": st.sampled_from(["right", "left", "both"]),
})


@settings(max_examples=30, deadline=None)
@given(p=wing_params, preset=st.sampled_from(sorted(NACA4_PRESETS)))
def test_naca_wing_matches_quadrature(p, preset):
    a = NACA4_PRESETS[preset]
    ct = p["cr"] * p["taper"]
    args = (p["b"], p["cr"], ct, p["tr"], p["tt"], p["sweep"], p["dihedral"])
    seg = WingSegment(*args, side=p["side"], airfoil=Naca4.preset(preset),
                      root_quarter_chord=p["root"])
    ref = wing_reference(*args, naca_mu(a), p["root"], p["density"], side=p["side"])
    assert_matches(seg.mass_properties(density=p["density"]), ref)


@settings(max_examples=20, deadline=None)
@given(p=wing_params, x_m=st.floats(0.05, 0.95))
def test_diamond_wing_matches_quadrature(p, x_m):
    ct = p["cr"] * p["taper"]
    args = (p["b"], p["cr"], ct, p["tr"], p["tt"], p["sweep"], p["dihedral"])
    seg = WingSegment(*args, side=p["side"], airfoil=Diamond(x_m), root_quarter_chord=p["root"])
    ref = wing_reference(*args, Diamond(x_m).mu, p["root"], p["density"], side=p["side"],
                         breaks=(x_m,), sqrt_le=False)
    assert_matches(seg.mass_properties(density=p["density"]), ref)


def _custom_mu(x):
    return 1.3 * np.sqrt(x) * (1.0 - x) * (1.0 + 0.4 * x) + 0.05 * x


@settings(max_examples=10, deadline=None)
@given(p=wing_params)
def test_custom_thickness_wing_matches_quadrature(p):
    custom = CustomThickness(_custom_mu)
    ct = p["cr"] * p["taper"]
    args = (p["b"], p["cr"], ct, p["tr"], p["tt"], p["sweep"], p["dihedral"])
    seg = WingSegment(*args, side=p["side"], airfoil=custom, root_quarter_chord=p["root"])
    ref = wing_reference(*args, _custom_mu, p["root"], p["density"], side=p["side"])
    assert_matches(seg.mass_properties(density=p["density"]), ref, rtol=1e-9)


@pytest.mark.parametrize("preset", sorted(NACA4_PRESETS))
def test_naca_v_integrals_match_adaptive_quadrature(preset):
    a = NACA4_PRESETS[preset]
    closed = Naca4.preset(preset).v
    numeric = CustomThickness(naca_mu(a)).v
    np.testing.assert_allclose(closed, numeric, rtol=1e-12)


@pytest.mark.parametrize("preset", sorted(NACA4_PRESETS))
def test_naca_v_integrals_match_exact_rational_arithmetic(preset):
    """Eqs 20, 30, 47, 48 in exact arithmetic: integral x^p (x - 1/4)^n with p = 1/2, 1, .., 4
    and the 125-term triple sum of mu^3 (the printed 35 terms, expanded), from the float
    coefficients taken exactly."""
    a = [Fraction(c) for c in NACA4_PRESETS[preset]]
    p = [Fraction(1, 2), Fraction(1), Fraction(2), Fraction(3), Fraction(4)]

    def mom(q, n):  # integral_0^1 x^q (x - 1/4)^n dx
        return sum(math.comb(n, k) * Fraction(-1, 4) ** (n - k) / (q + k + 1)
                   for k in range(n + 1))

    v0 = sum(ai * mom(pi, 0) for ai, pi in zip(a, p, strict=True))
    v1 = 4 * sum(ai * mom(pi, 1) for ai, pi in zip(a, p, strict=True))
    v2 = Fraction(48, 7) * sum(ai * mom(pi, 2) for ai, pi in zip(a, p, strict=True))
    v3 = sum(a[i] * a[j] * a[k] / (p[i] + p[j] + p[k] + 1)
             for i in range(5) for j in range(5) for k in range(5))
    np.testing.assert_allclose(Naca4.preset(preset).v, [float(v) for v in (v0, v1, v2, v3)],
                               rtol=2e-15)


def test_naca_v_integrals_printed_forms():
    """Eq 20 for the traditional section: (40*2.969 - 30*1.26 - 20*3.516 + 15*2.843 -
    12*1.015)/60, and eq 48's first term 2/5 a0^3 for a pure sqrt distribution."""
    assert Naca4().v[0] == pytest.approx(41.105 / 60, rel=1e-14)
    assert Naca4(1.0, 0, 0, 0, 0).v[3] == pytest.approx(0.4, rel=1e-14)


@pytest.mark.parametrize("x_m", [0.2, 0.5, 0.73])
def test_diamond_v_integrals_match_adaptive_quadrature(x_m):
    numeric = CustomThickness(Diamond(x_m).mu, breakpoints=(x_m,)).v
    np.testing.assert_allclose(Diamond(x_m).v, numeric, rtol=1e-12)


@pytest.mark.parametrize("taper", [0.25, 0.5, 1.0])
def test_table2_wing(taper):
    """Table 2 of the paper (figures 3-6 plot its results; no values are printed):
    right wing, c_r = 1 ft, NACA 0008 -> 0010, b = 4 ft, m = 3 slugs, sweep 10 deg, no
    dihedral, here with its root at [2, 3, -1] in project axes (the paper's root location is
    in its own axes, x forward and z down: test_wing_paper places it as the paper does)."""
    args = (4.0, 1.0, taper, 0.08, 0.10, math.radians(10.0), 0.0)
    seg = WingSegment(*args, root_quarter_chord=(2.0, 3.0, -1.0))
    props = seg.mass_properties(mass=3.0)
    rho = 3.0 / wing_reference(*args, naca_mu(NACA4_PRESETS["original"]), (2, 3, -1), 1.0)[1]
    ref = wing_reference(*args, naca_mu(NACA4_PRESETS["original"]), (2, 3, -1), rho)
    assert props.mass == 3.0
    assert_matches(props, ref)
    assert props.cg[2] == pytest.approx(-1.0, abs=1e-15)       # eq 34: no camber, no dihedral


def test_rectangular_diamond_wing_by_hand():
    """b = 2, c = 1, tau = 0.1, diamond at mid-chord, unswept: a prism of rhombic section.
    Section area c^2 tau / 2 = 0.05; CG at mid-span, mid-chord (x = +0.25 aft of the root
    quarter chord); Ixx about CG = m (b^2 / 12 + t^2 / 24) for a rhombus of height t."""
    props = WingSegment(2.0, 1.0, 1.0, 0.1, 0.1, airfoil=Diamond(0.5)).mass_properties(
        density=2.0)
    assert props.volume == pytest.approx(0.1, rel=1e-14)
    assert props.mass == pytest.approx(0.2, rel=1e-14)
    np.testing.assert_allclose(props.cg, [0.25, 1.0, 0.0], atol=1e-15)
    assert props.inertia[0, 0] == pytest.approx(0.2 * (4.0 / 12 + 0.01 / 24), rel=1e-13)
    # rhombus with diagonals 1 (x) and 0.1 (z): I about z-axis through centre = m d_x^2 / 24
    assert props.inertia[2, 2] == pytest.approx(0.2 * (1.0 / 24 + 4.0 / 12), rel=1e-13)


def test_left_keeps_its_root_and_both_is_the_symmetric_pair():
    """The root location is in the aircraft frame for every side (eq 24 and section 2.1): a
    left panel is the right one mirrored about the xz plane through its own root, so a left
    panel with root (x, -y, z) is the right panel with root (x, y, z) mirrored in y = 0, and
    "both" is that pair. (Until issue 11 "left" mirrored the root too: the old version of this
    test asserted left(root) == right(root).mirrored("xz").)"""
    args = (3.0, 1.2, 0.5, 0.12, 0.09)
    kw = dict(sweep=0.3, dihedral=0.15)
    root, image = (0.4, 0.7, -0.2), (0.4, -0.7, -0.2)
    right = WingSegment(*args, side="right", root_quarter_chord=root, **kw)
    left = WingSegment(*args, side="left", root_quarter_chord=image, **kw)
    both = WingSegment(*args, side="both", root_quarter_chord=root, **kw)
    right, left, both = (w.mass_properties(density=3.0) for w in (right, left, both))
    assert left.allclose(right.mirrored("xz"), rtol=1e-13)
    assert both.allclose(right + left, rtol=1e-13)
    assert both.cg[1] == 0.0
    # the same left panel about its own root: y_cg - y_root is minus the right panel's
    here = WingSegment(*args, side="left", root_quarter_chord=root, **kw).mass_properties(
        density=3.0)
    assert here.cg[1] - root[1] == pytest.approx(-(right.cg[1] - root[1]), rel=1e-14)
    np.testing.assert_allclose(here.inertia, left.inertia, rtol=1e-14, atol=1e-16)
    assert left.cg[2] > root[2]      # dihedral raises the left tip too


def test_mass_instead_of_density():
    seg = WingSegment(2.5, 1.0, 0.6, 0.12, 0.12, sweep=0.2, side="both")
    by_rho = seg.mass_properties(density=1.0)
    by_mass = seg.mass_properties(mass=7.0)
    assert by_mass.mass == pytest.approx(7.0, rel=1e-15)
    np.testing.assert_allclose(by_mass.inertia, by_rho.inertia * 7.0 / by_rho.mass, rtol=1e-13)
    np.testing.assert_allclose(by_mass.cg, by_rho.cg, rtol=1e-14)


def test_skin_from_two_collocated_segments():
    """A skin (paper section 5): outer wing at +rho, inner (smaller chord) at -rho."""
    outer = dict(b=3.0, cr=1.0, ct=0.5, tr=0.12, tt=0.10)
    inner = dict(b=3.0, cr=0.95, ct=0.47, tr=0.11, tt=0.09)
    rho, sweep, dih, root = 50.0, 0.25, 0.05, (1.0, 0.0, 0.3)
    skin = (WingSegment(*outer.values(), sweep=sweep, dihedral=dih, root_quarter_chord=root)
            .mass_properties(density=rho)
            + WingSegment(*inner.values(), sweep=sweep, dihedral=dih, root_quarter_chord=root)
            .mass_properties(density=-rho))
    mu = naca_mu(NACA4_PRESETS["original"])
    m_o, v_o, c_o, i_o = wing_reference(*outer.values(), sweep, dih, mu, root, rho)
    m_i, v_i, c_i, i_i = wing_reference(*inner.values(), sweep, dih, mu, root, -rho)
    assert v_i < 0 and m_i < 0
    m = m_o + m_i
    cg = (m_o * c_o + m_i * c_i) / m
    steiner = [mm * (np.dot(c - cg, c - cg) * np.eye(3) - np.outer(c - cg, c - cg))
               for mm, c in ((m_o, c_o), (m_i, c_i))]
    inertia = i_o + i_i + steiner[0] + steiner[1]
    assert_matches(skin, (m, v_o + v_i, cg, inertia), rtol=1e-8)
    assert skin.volume == pytest.approx(v_o + v_i, rel=1e-9) and skin.volume > 0
    assert skin.is_physical()


def test_identical_opposite_segments_cancel_to_an_error():
    seg = WingSegment(1.0, 1.0, 1.0, 0.1, 0.1)
    with pytest.raises(GeometryError, match="combined mass is zero"):
        _ = seg.mass_properties(density=1.0) + seg.mass_properties(density=-1.0)


def test_batch_equals_single_segments():
    rng = np.random.default_rng(7)
    n = 37
    b, cr = rng.uniform(0.5, 5, n), rng.uniform(0.2, 2, n)
    ct, tr, tt = cr * rng.uniform(0.1, 1.2, n), rng.uniform(0.05, 0.2, n), rng.uniform(0, .2, n)
    sweep, dih = rng.uniform(-0.5, 0.7, n), rng.uniform(-0.3, 0.3, n)
    side = rng.choice(["right", "left", "both"], n)
    root, rho = rng.normal(size=(n, 3)), rng.uniform(1, 100, n)
    airfoil = np.array([Naca4.preset(k).v for k in rng.choice(sorted(NACA4_PRESETS), n)])
    out = wing_segments_mass_properties(b, cr, ct, tr, tt, sweep, dih, side, airfoil, root,
                                        density=rho)
    assert out.mass.shape == (n,) and out.cg.shape == (n, 3) and out.inertia.shape == (n, 3, 3)
    for k in range(n):
        single = wing_segments_mass_properties(b[k], cr[k], ct[k], tr[k], tt[k], sweep[k],
                                               dih[k], str(side[k]), airfoil[k], root[k],
                                               density=rho[k])
        np.testing.assert_allclose(out.inertia[k], single.inertia[0], rtol=1e-13, atol=1e-300)
        np.testing.assert_allclose(out.cg[k], single.cg[0], rtol=1e-13)
        assert out.mass[k] == pytest.approx(single.mass[0], rel=1e-14)


def test_paper_to_project_is_a_rotation_about_y():
    cg, inertia = paper_to_project(np.array([1.0, 2.0, 3.0]),
                                   np.array([[4.0, 1.0, 2.0], [1.0, 5.0, 3.0], [2.0, 3.0, 6.0]]))
    r = np.array([[-1.0, 0, 0], [0, 1.0, 0], [0, 0, -1.0]])     # 180 deg about y
    assert np.linalg.det(r) == 1.0
    np.testing.assert_array_equal(cg, r @ [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(inertia, r @ [[4, 1, 2], [1, 5, 3], [2, 3, 6]] @ r.T)


def test_segment_is_immutable():
    seg = WingSegment(1.0, 1.0, 1.0, 0.1, 0.1, root_quarter_chord=[1.0, 2.0, 3.0])
    with pytest.raises(AttributeError):
        seg.semispan = 2.0
    with pytest.raises(ValueError, match="read-only"):
        seg.root_quarter_chord[0] = 5.0
    assert isinstance(seg.mass_properties(density=1.0), MassProperties)


@pytest.mark.parametrize("kwargs, match", [
    (dict(side="top"), "side must be one of"),
    (dict(semispan=0.0), "station 1.*semispan must be > 0|semispan must be > 0"),
    (dict(chord_root=-1.0), "chords must be >= 0"),
    (dict(chord_root=0.0, chord_tip=0.0), "chords must be >= 0, not both 0"),
    (dict(thickness_root=-0.1), "thickness ratios must be >= 0"),
    (dict(sweep=math.pi / 2), r"sweep must be within \(-90, 90\)"),
    (dict(semispan=float("nan")), "values must be finite"),
    (dict(root_quarter_chord=(0.0, 1.0)), r"root_quarter_chord must have shape \(3,\)"),
    (dict(airfoil="naca0012"), "airfoil must be a ThicknessDistribution"),
])
def test_segment_errors(kwargs, match):
    base = dict(semispan=1.0, chord_root=1.0, chord_tip=0.5, thickness_root=0.1,
                thickness_tip=0.1, name="fin")
    base.update(kwargs)
    with pytest.raises(GeometryError, match=match):
        WingSegment(**base).mass_properties(density=1.0)


def test_density_and_mass_errors():
    seg = WingSegment(1.0, 1.0, 0.5, 0.1, 0.1, name="tail")
    with pytest.raises(GeometryError, match="tail: give exactly one of density and mass"):
        seg.mass_properties()
    with pytest.raises(GeometryError, match="exactly one of density and mass"):
        seg.mass_properties(density=1.0, mass=2.0)


def test_batch_errors_name_the_segment():
    with pytest.raises(GeometryError, match="station 3: semispan must be > 0"):
        wing_segments_mass_properties([1.0, 2.0, -1.0], 1.0, 1.0, 0.1, 0.1, density=1.0)
    with pytest.raises(GeometryError, match="must broadcast to one length N"):
        wing_segments_mass_properties([1.0, 2.0], [1.0, 1.0, 1.0], 1.0, 0.1, 0.1, density=1.0)
    with pytest.raises(GeometryError, match=r"v-integrals of shape \(4,\) or \(2, 4\)"):
        wing_segments_mass_properties([1.0, 2.0], 1.0, 1.0, 0.1, 0.1, airfoil=[0.5, 0.5],
                                      density=1.0)
    with pytest.raises(GeometryError, match=r"root_quarter_chord must be finite with shape"):
        wing_segments_mass_properties([1.0, 2.0], 1.0, 1.0, 0.1, 0.1,
                                      root_quarter_chord=np.zeros((3, 3)), density=1.0)
    with pytest.raises(GeometryError, match="v0 > 0"):
        wing_segments_mass_properties(1.0, 1.0, 1.0, 0.1, 0.1, airfoil=[0.0, 1, 1, 1],
                                      density=1.0)


def test_thickness_errors():
    with pytest.raises(GeometryError, match="unknown NACA 4-digit preset 'naca'; expected one"):
        Naca4.preset("naca")
    with pytest.raises(GeometryError, match=r"x_m .* must be in \[0, 1\], found 1.5"):
        Diamond(1.5)
    with pytest.raises(GeometryError, match="must be finite"):
        Naca4(float("inf"))
    with pytest.raises(GeometryError, match="needs a callable"):
        CustomThickness(3.0)
    with pytest.raises(GeometryError, match="is not finite"):
        CustomThickness(lambda x: float("nan"))
    with pytest.raises(GeometryError, match="did not converge"):
        CustomThickness(lambda x: 1.0 / x)
