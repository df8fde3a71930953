"""Harris mode (juncture.analysis.harris): against an independent implementation of the
Harris program's conventions (tests/analysis/harris_reference.py), and each convention on
its own against an analytic or independent value."""

import warnings
from dataclasses import replace

import numpy as np
import pytest
from scipy.interpolate import PchipInterpolator

import juncture as jc
from juncture.analysis import wavedrag
from juncture.analysis.harris import HarrisConventions, buried_roots, harris_model
from juncture.analysis.wavedrag import roll_angles, sears_haack_drag
from juncture.errors import JunctureError, JunctureWarning
from juncture.model import CircularBody, Configuration, WingLike, rebuilt
from tests.analysis.harris_reference import _boole_weights, harris_far_field, least_drag_curve
from tests.deckgen import deck_from_seed, read_text
from tests.support import EXAMPLE_DECK

H = HarrisConventions


def _quiet(f, *args, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", JunctureWarning)
        return f(*args, **kw)


# The transport at three Mach numbers in make test-all (13 s each: the independent
# implementation's grid); make test checks a held-out airplane against it (below).
@pytest.mark.slow
@pytest.mark.parametrize("mach", [1.2, 1.6, 2.0])
def test_transport_matches_the_independent_harris_implementation(mach):
    cfg = jc.read(EXAMPLE_DECK)
    ours = _quiet(wavedrag, cfg, mach, 41, 8, method="harris")["D_over_q"]
    ref, _ = harris_far_field(cfg, mach, 41, 8, n_grid=200)
    assert ours == pytest.approx(ref, rel=0.01)


def _held_out(seed):
    text, _ = deck_from_seed(seed, ("pods", "fins", "canards"), section="circular")
    return read_text(text)


@pytest.mark.parametrize("seed", [31, pytest.param(47, marks=pytest.mark.slow)])
def test_held_out_airplanes_match_the_independent_implementation(seed):
    cfg = _held_out(seed)
    ours = _quiet(wavedrag, cfg, 1.6, 41, 8, method="harris")["D_over_q"]
    ref, _ = harris_far_field(cfg, 1.6, 41, 8, n_grid=200)
    assert ours == pytest.approx(ref, rel=0.01)


@pytest.mark.slow
@pytest.mark.parametrize("seed", [101, 202, 303, 404, 505, 606])
def test_more_held_out_airplanes_match(seed):
    test_held_out_airplanes_match_the_independent_implementation(seed)


def _rect_wing(ordinates, root_y=0.0, span=4.0, chord=2.0, z=0.0):
    xc = np.array([0.0, 20.0, 45.0, 70.0, 100.0])
    th = np.tile(ordinates, (2, 1))
    return WingLike("wing", "wing", [[0.0, root_y, z], [0.0, root_y + span, z]],
                    [chord, chord], xc, th, th), xc


def test_linear_chordwise_alone_is_straight_lines_between_ordinates():
    ordinates = np.array([0.0, 3.0, 4.0, 2.5, 0.0])  # % chord, a kinked section
    wing, xc = _rect_wing(ordinates)
    cfg = Configuration({"wing": wing})
    x = np.linspace(0.0, 2.0, 41)
    # M = 1 normal areas of the model: thickness x span x 2 copies
    on = wavedrag(cfg, 1.0, 41, method="harris", conventions=H.only("linear_chordwise"))
    off = wavedrag(cfg, 1.0, 41, method="harris", conventions=H.juncture())
    np.testing.assert_allclose(on["x"], x, rtol=0, atol=1e-12)
    linear = 2 * 4.0 * 2 * np.interp(x / 2.0 * 100, xc, ordinates) / 100 * 2.0
    curved = 2 * 4.0 * 2 * PchipInterpolator(xc, ordinates)(x / 2.0 * 100) / 100 * 2.0
    np.testing.assert_allclose(on["area"], linear, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(off["area"], curved, rtol=1e-6, atol=1e-9)
    assert np.abs(np.asarray(off["area"]) - linear).max() > 1e-3


def _wing_in_cylinder(root_y):
    body = CircularBody("body", [0.0, 6.0, 34.0, 40.0], [0.0, 2.0, 2.0, 0.0], axial="linear")
    wing, _ = _rect_wing(np.array([0.0, 1.0, 1.0, 1.0, 0.0]), root_y=root_y, span=6.0,
                         chord=4.0, z=0.3)
    return Configuration({"body": body, "wing": rebuilt(wing, le=wing.le + [18.0, 0.0, 0.0])})


def test_summed_components_count_the_buried_root_twice_and_say_so():
    cfg = _wing_in_cylinder(root_y=0.5)
    assert buried_roots(cfg) == [("wing", "body")]
    with pytest.warns(JunctureWarning, match="wing: root section lies inside body"):
        summed = wavedrag(cfg, 1.0, 81, method="harris", conventions=H.only("sum_components"))
    union = wavedrag(cfg, 1.0, 81, method="harris", conventions=H.juncture())
    x = np.asarray(summed["x"])
    extra = np.asarray(summed["area"]) - np.asarray(union["area"])
    # the buried part: the wing section (thickness t(x)) from y = 0.5 to the cylinder
    # (y = sqrt(R^2 - z^2) at the wing's height z = 0.3 +- t/2), both copies
    t = np.interp((x - 18.0) / 4.0 * 100, [0, 20, 45, 70, 100], [0, 1, 1, 1, 0]) / 100 * 4 * 2
    buried = 2 * t * (np.sqrt(4.0 - 0.09) - 0.5)
    mid = (x > 18.8) & (x < 20.8)  # 20-70 % chord: constant thickness, whatever the curve
    np.testing.assert_allclose(extra[mid], buried[mid], rtol=0.02)
    assert np.abs(extra[(x < 17.9) | (x > 22.1)]).max() < 1e-9
    with warnings.catch_warnings():
        warnings.simplefilter("error", JunctureWarning)  # a wing outside the body: no warning
        # (the cylinder's radii as given: a least-drag area curve through its four
        # stations bulges past the root at y = 2.5)
        wavedrag(_wing_in_cylinder(root_y=2.5), 1.6, 41, 4, method="harris",
                 conventions=replace(H(), fusard_fit=False))


def test_normal_mach_alone_is_the_far_field_at_1_000001():
    length, volume = 10.0, 3.0
    x = np.linspace(0.0, length, 201)
    xi = x / length
    s_max = 16 * volume / (3 * np.pi * length)
    area = s_max * (4 * xi * (1 - xi)) ** 1.5
    body = CircularBody("body", x, np.sqrt(area / np.pi))
    cfg = Configuration({"body": body})
    conv = H.only("normal_mach")
    normal = wavedrag(cfg, None, 101, 8, method="harris", conventions=conv)
    direct = wavedrag(cfg, 1.000001, 101, 8, method="harris", conventions=conv)
    assert normal["D_over_q"] == direct["D_over_q"] and normal["mach"] == 1.000001
    assert "far-field" in normal["method"]
    slender = wavedrag(cfg, None, 101, 8, method="harris", conventions=H.juncture())
    assert slender["method"].startswith("slender-body")
    exact = sears_haack_drag(volume, length)
    assert slender["D_over_q"] == pytest.approx(exact, rel=2e-3)
    assert normal["D_over_q"] == pytest.approx(exact, rel=1e-2)  # faceted surface cuts
    with pytest.raises(JunctureError, match="normal_mach must be None or slightly above 1"):
        H(normal_mach=1.5)


def test_half_turn_alone_averages_ntheta_plus_one_angles_with_boole():
    wing, _ = _rect_wing(np.array([0.0, 3.0, 4.0, 2.5, 0.0]))
    cfg = Configuration({"wing": wing}, symmetric=False)  # one wing: not y-symmetric
    full = wavedrag(cfg, 1.6, 41, 8, method="harris", conventions=H.juncture())
    half = wavedrag(cfg, 1.6, 41, 8, method="harris", conventions=H.only("half_turn"))
    assert len(full["thetas"]) == 16 and len(half["thetas"]) == 9
    np.testing.assert_allclose(half["thetas"], np.linspace(-np.pi / 2, np.pi / 2, 9),
                               atol=1e-15)
    np.testing.assert_allclose(half["theta_weights"], _boole_weights(8), rtol=1e-14)
    assert half["D_over_q"] == pytest.approx(np.dot(_boole_weights(8), half["D_over_q_theta"]),
                                             rel=1e-12)
    thetas, _ = roll_angles(16, False)
    np.testing.assert_allclose(full["thetas"], thetas)


def _two_segment_fuselage():
    """A FUSARD-like fuselage: a nose segment, then (after a gap) one with an open base."""
    x1, a1 = np.array([0.0, 3.0, 8.0, 15.0, 20.0]), np.array([0.0, 2.0, 5.0, 7.0, 7.5])
    x2, a2 = np.array([22.0, 30.0, 38.0, 40.0]), np.array([7.5, 7.0, 4.0, 2.0])
    body = CircularBody("body", np.r_[x1, x2], np.sqrt(np.r_[a1, a2] / np.pi),
                        camber=np.linspace(0.0, 0.4, 9), segments=(5, 4))
    return body, (x1, a1), (x2, a2)


def test_fusard_fit_alone_is_each_segments_least_drag_curve():
    body, *segments = _two_segment_fuselage()
    cfg = Configuration({"body": body})
    on = wavedrag(cfg, None, 401, method="harris", conventions=H.only("fusard_fit"))
    off = wavedrag(cfg, None, 401, method="harris", conventions=H.juncture())
    x, area = np.asarray(on["x"]), np.asarray(on["area"])
    for xs, areas in segments:  # an independent finite series (3000 modes, numpy)
        inner = (x > xs[0]) & (x < xs[-1])
        expected = np.maximum(least_drag_curve(xs, areas, x[inner]), 0.0)
        np.testing.assert_allclose(area[inner], expected, rtol=0, atol=3e-5 * 7.5)
    gap = (x > 20.0) & (x < 22.0)  # the straight bridge: radius linear
    r = np.interp(x[gap], [20.0, 22.0], np.sqrt([7.5 / np.pi, 7.5 / np.pi]))
    np.testing.assert_allclose(area[gap], np.pi * r * r, rtol=1e-9)
    assert np.abs(area - np.asarray(off["area"])).max() > 1e-2  # PCHIP radius otherwise
    fitted = harris_model(cfg, H.only("fusard_fit"))["body"]
    given = np.r_[segments[0][0][:-1], segments[1][0]]  # the joint's later station holds
    np.testing.assert_allclose(np.pi * fitted.radius_at(given) ** 2,
                               np.r_[segments[0][1][:-1], segments[1][1]], rtol=1e-12)
    np.testing.assert_allclose(fitted.center_at(given)[:, 1],
                               np.r_[np.linspace(0.0, 0.4, 9)[:4], np.linspace(0.0, 0.4, 9)[5:]],
                               atol=1e-12)
    assert fitted.segments == (65, 49) and fitted.points_per_section == body.points_per_section


@pytest.mark.slow
def test_fusard_fit_leaves_pods_alone_and_matches_the_reference_far_field():
    body, *_ = _two_segment_fuselage()
    pod = CircularBody("pod 1", [0.0, 2.0, 6.0], [0.0, 0.5, 0.3], origin=[10.0, 3.0, -1.0],
                       mirrored=True)
    cfg = Configuration({"body": body, "pod 1": pod})
    assert harris_model(cfg, H())["pod 1"] is pod
    for fit in (True, False):
        conv = replace(H(), fusard_fit=fit)
        ours = wavedrag(cfg, 1.6, 41, 8, method="harris", conventions=conv)["D_over_q"]
        ref, _ = harris_far_field(cfg, 1.6, 41, 8, n_grid=200, fusard_fit=fit)
        assert ours == pytest.approx(ref, rel=0.01)


def test_harris_mode_refuses_completed_geometry_and_unknown_names():
    cfg = jc.read(EXAMPLE_DECK)
    geo = jc.complete(cfg)
    with pytest.raises(JunctureError, match="apply to a deck's components"):
        wavedrag(cfg, 1.6, geometry=geo, method="harris")
    with pytest.raises(JunctureError, match="method must be 'juncture' or 'harris'"):
        wavedrag(cfg, 1.6, method="awave")
    with pytest.raises(JunctureError, match="no Harris convention 'boole'"):
        H.only("boole")
