"""WingLike: section points (deck formula), linear lofting, interpolation, orientation."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.errors import GeometryError
from juncture.model import WingLike

X = np.array([0.0, 5.0, 20.0, 45.0, 70.0, 100.0])  # 6 stations (differs from 3 sections)
LE = np.array([[100.0, 10.0, -1.0], [130.0, 40.0, 0.5], [170.0, 75.0, 2.0]])
CHORD = np.array([120.0, 70.0, 25.0])
RNG = np.random.default_rng(7)
UP = np.array([[0.0, 1.2, 2.1, 2.4, 1.6, 0.1], [0.0, 1.0, 1.8, 2.0, 1.3, 0.1],
               [0.0, 0.8, 1.5, 1.6, 1.1, 0.1]])
LO = UP * 0.8 + RNG.uniform(0, 0.1, UP.shape)
CAM = RNG.uniform(-0.3, 0.6, UP.shape)


def wing(**kw):
    args = dict(name="wing", kind="wing", le=LE, chord=CHORD, x_over_c=X, upper=UP, lower=LO,
                camber=CAM)
    args.update(kw)
    return WingLike(**args)


def test_section_points_follow_the_deck_formula():
    w = wing()
    up, lo = w.section_points("upper"), w.section_points("lower")
    for k in range(3):
        x_le, y_le, z_le = LE[k]
        c = CHORD[k]
        np.testing.assert_allclose(up[k, :, 0], x_le + c * X / 100)
        np.testing.assert_allclose(up[k, :, 1], y_le)
        np.testing.assert_allclose(up[k, :, 2], z_le + CAM[k] + c * UP[k] / 100)
        np.testing.assert_allclose(lo[k, :, 2], z_le + CAM[k] - c * LO[k] / 100)


def test_fin_thickness_is_in_y_and_sections_at_constant_z():
    le = np.array([[200.0, 0.0, 3.0], [230.0, 0.0, 20.0]])
    fin = WingLike("fin 1", "fin", le, [40.0, 15.0], X, UP[:2], LO[:2])
    out = fin.section_points("upper")
    np.testing.assert_allclose(out[..., 2], le[:, 2:3].repeat(6, 1))
    np.testing.assert_allclose(out[1, :, 1], 15.0 * UP[1] / 100)
    assert set(fin.networks()) == {"fin 1 outboard", "fin 1 inboard"}


@settings(max_examples=60, deadline=None)
@given(span=st.floats(10.0, 75.0), j=st.integers(0, 5), side=st.sampled_from(["upper", "lower"]))
def test_point_at_a_station_lies_on_the_straight_lofting_line(span, j, side):
    w = wing()
    p = w.point(span, X[j] / 100, side)
    line = w.lofting_lines(side)[j]  # (n_sections, 3)
    expect = [np.interp(span, LE[:, 1], line[:, i]) for i in range(3)]
    np.testing.assert_allclose(p, expect, rtol=1e-12, atol=1e-9)


def test_point_is_vectorised_and_broadcasts():
    w = wing()
    s = np.linspace(10, 75, 7)[:, None]
    f = np.linspace(0, 1, 5)[None, :]
    p = w.point(s, f)
    assert p.shape == (7, 5, 3)
    np.testing.assert_allclose(p[..., 1], np.broadcast_to(s, (7, 5)))
    for a in range(7):
        for b in range(5):
            np.testing.assert_allclose(p[a, b], w.point(s[a, 0], f[0, b]))


def test_extrapolation_only_on_request():
    w = wing()
    with pytest.raises(GeometryError, match=r"wing: span station 0 lies outside"):
        w.point(0.0, 0.5)
    p = w.point(0.0, 0.0, "upper", extrapolate=True)
    # First lofting line extended inboard by a third of the first segment (y 10 -> 0).
    line = w.lofting_lines("upper")[0]
    np.testing.assert_allclose(p, line[0] - (line[1] - line[0]) / 3, atol=1e-12)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(10.5, 74.5), min_size=1, max_size=4, unique=True))
def test_inserted_sections_lie_on_the_lofted_surface(spans):
    w = wing()
    w2 = w.with_sections(spans)
    assert w2.n_sections == 3 + len(spans)
    for side in ("upper", "lower"):
        new = w2.section_points(side)
        for k, s in enumerate(w2.span_stations):
            np.testing.assert_allclose(new[k], w.point(s, X / 100, side), atol=1e-9)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(-60, 149), min_size=1, max_size=3, unique=True),
       st.sampled_from(["pchip", "linear"]))
def test_inserted_sections_keep_the_surface_between_stations(halves, chordwise):
    """Every point of the copy, at any chord fraction, is the original's: inside, and
    extrapolated inboard as TM-4406 eq 4 extends the lofting lines (a root continued into
    a fuselage). A PCHIP through the blended ordinates of a 4-point section put such a
    root 6e-3 ft off between stations."""
    spans = 0.5 * np.array(halves) + 0.25          # half a unit apart at least
    w = wing(chordwise=chordwise)
    w2 = w.with_sections(spans, extrapolate=True)
    s = np.linspace(min(spans) - 5.0, 75.0, 23)
    f = np.linspace(0.0, 1.0, 37)
    for side in ("upper", "lower"):
        got = w2.point(s[:, None], f[None, :], side, extrapolate=True)
        want = w.point(s[:, None], f[None, :], side, extrapolate=True)
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-9)   # round-off, span 230


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(0.5, 99.5), min_size=1, max_size=8, unique=True),
       st.sampled_from(["pchip", "linear"]))
def test_chord_stations_keep_the_surface(stations, chordwise):
    """Refining the lofting lines (option refine, keep_area's min_lofting_lines) does not
    move the surface: every point of the copy, at any chord fraction and span, inside and
    extrapolated, is the original's, and its new stations' points lie on it (camber and
    thickness interpolated apart put them up to 1e-3 of the thickness off)."""
    w = wing(chordwise=chordwise)
    w2 = w.with_chord_stations(stations)
    s = np.linspace(0.0, 80.0, 19)
    f = np.linspace(0.0, 1.0, 203)
    for side in ("upper", "lower"):
        got = w2.point(s[:, None], f[None, :], side, extrapolate=True)
        want = w.point(s[:, None], f[None, :], side, extrapolate=True)
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
        on = w.point(w2.span_stations[:, None], w2.x_over_c[None, :] / 100.0, side)
        np.testing.assert_allclose(w2.section_points(side), on, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(w2.upper[:, np.searchsorted(w2.x_over_c, X)], UP)


def test_network_orientation_gives_outward_normals():
    w = wing()
    for name, net in w.networks().items():
        n = np.cross(net[0, 2] - net[0, 1], net[1, 1] - net[0, 1])
        assert np.sign(n[2]) == (1 if name.endswith("upper") else -1), name
    fin = WingLike("fin 1", "fin", [[200, 3, 3], [230, 3, 20]], [40, 15], X, UP[:2])
    for name, net in fin.networks().items():
        n = np.cross(net[0, 2] - net[0, 1], net[1, 1] - net[0, 1])
        assert np.sign(n[1]) == (1 if name.endswith("outboard") else -1), name


@pytest.mark.parametrize("kw, match", [
    (dict(le=LE[::-1]), r"wing, station 2: section y \(root first\) must increase"),
    (dict(chord=[120.0, -1.0, 25.0]), r"wing, station 2: chord is negative"),
    (dict(upper=-UP), r"wing, station 1: upper half-thickness is negative"),
    (dict(x_over_c=X[::-1]), r"wing, station 2: x_over_c must increase"),
    (dict(chord=[1.0, 2.0]), r"wing: chord \(one per section\) must have shape \(3\)"),
    (dict(kind="rudder"), r"kind must be one of"),
    (dict(le=LE[:1], chord=CHORD[:1], upper=UP[:1], lower=LO[:1], camber=CAM[:1]),
     r"needs at least 2 sections"),
])
def test_bad_input_names_component_and_station(kw, match):
    with pytest.raises(GeometryError, match=match):
        wing(**kw)


def test_values_are_immutable():
    w = wing()
    with pytest.raises(ValueError):
        w.le[0, 0] = 1.0
    with pytest.raises(AttributeError):
        w.name = "other"


@given(extra=st.lists(st.floats(0.5, 99.5), min_size=1, max_size=12))
def test_extra_chord_stations_keep_the_input_ordinates_bit_for_bit(extra):
    """A sharp trailing edge (both surfaces at the camber line) stays one line after
    refinement: the input stations are not re-interpolated."""
    sharp_up, sharp_lo = UP.copy(), LO.copy()
    sharp_up[:, -1] = sharp_lo[:, -1] = 0.0
    w = wing(upper=sharp_up, lower=sharp_lo)
    fine = w.with_chord_stations(extra)
    at = np.searchsorted(fine.x_over_c, X)
    assert np.array_equal(fine.upper[:, at], w.upper)
    assert np.array_equal(fine.lower[:, at], w.lower)
    assert np.array_equal(fine.camber[:, at], w.camber)
    assert np.array_equal(fine.lofting_lines("upper")[-1], fine.lofting_lines("lower")[-1])
    # And the surface point at the trailing edge is the same point on both sides.
    s = np.linspace(10.0, 75.0, 9)
    assert np.array_equal(fine.point(s, 1.0, "upper"), fine.point(s, 1.0, "lower"))
