"""model._pchip: PCHIP slopes, coefficients and evaluation against SciPy's PchipInterpolator.

SciPy is the independent oracle here (it stays a dependency; the model no longer imports it,
issue 14). Closed forms cover the rest: a straight line through two points, the data at the
stations, monotone data giving a monotone curve, C1 joins between pieces.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import PchipInterpolator

from juncture.errors import GeometryError
from juncture.model import CircularBody, WingLike, interpolate_chordwise
from juncture.model._pchip import (
    evaluate_cubics,
    hermite_coefficients,
    pchip,
    pchip_coefficients,
    pchip_slopes,
)

RTOL = 1e-13
TRAILING = [(), (3,), (2, 5)]  # every trailing dimension a different size


def close(actual, expected):
    """Equal to RTOL relative, with zeros compared on the scale of the largest entry."""
    expected = np.asarray(expected)
    scale = float(np.abs(expected).max(initial=0.0))
    np.testing.assert_allclose(actual, expected, rtol=RTOL, atol=RTOL * scale)


@st.composite
def samples(draw):
    """Stations with non-uniform gaps and values that repeat, stay flat and change sign."""
    n = draw(st.integers(2, 9))
    gaps = draw(st.lists(st.floats(0.05, 20.0), min_size=n - 1, max_size=n - 1))
    x = draw(st.floats(-50.0, 50.0)) + np.concatenate([[0.0], np.cumsum(gaps)])
    shape = draw(st.sampled_from(TRAILING))
    size = n * int(np.prod(shape, dtype=int))
    kind = draw(st.sampled_from(["levels", "monotone", "floats"]))
    if kind == "floats":
        y = np.array(draw(st.lists(st.floats(-1e3, 1e3), min_size=size, max_size=size)))
    else:
        # few distinct levels: repeated values, flat stretches and sign changes are common
        y = np.array(draw(st.lists(st.integers(-3, 3), min_size=size, max_size=size)), float)
        y *= draw(st.floats(0.1, 10.0))
    y = y.reshape((n,) + shape)
    if kind == "monotone":
        y = np.cumsum(np.abs(y), axis=0) * draw(st.sampled_from([1.0, -1.0]))
    return x, y


def queries(x):
    """Points inside, at the stations, and up to one span outside on each side."""
    span = x[-1] - x[0]
    return np.concatenate([np.linspace(x[0] - span, x[-1] + span, 40), x])


@settings(max_examples=300, deadline=None)
@given(samples())
def test_coefficients_and_values_match_scipy(data):
    x, y = data
    ref = PchipInterpolator(x, y, axis=0, extrapolate=True)
    c = pchip_coefficients(x, y)
    assert c.shape == ref.c.shape == (4, x.size - 1) + y.shape[1:]
    close(c, ref.c)
    close(pchip_slopes(x, y), ref(x, nu=1))
    xq = queries(x)
    close(pchip(x, y, xq), ref(xq))
    grid = xq[:40].reshape(5, 8)  # any query shape: result is grid.shape + trailing
    close(evaluate_cubics(x, c, grid), ref(grid))


@pytest.mark.parametrize("shape", TRAILING)
def test_trailing_axes_are_independent_columns(shape):
    rng = np.random.default_rng(11)
    x = np.cumsum(rng.uniform(0.2, 3.0, 7))
    y = rng.integers(-2, 3, (7,) + shape) * 1.5
    xq = np.linspace(x[0] - 2.0, x[-1] + 2.0, 13)
    got = pchip(x, y, xq)
    assert got.shape == (13,) + shape
    for idx in np.ndindex(*shape):
        col = y[(slice(None),) + idx]
        np.testing.assert_array_equal(got[(slice(None),) + idx], pchip(x, col, xq))


def test_two_points_give_the_straight_line_also_outside():
    x, y = np.array([1.0, 4.0]), np.array([2.0, -4.0])
    np.testing.assert_array_equal(pchip_slopes(x, y), [-2.0, -2.0])
    xq = np.array([-2.0, 1.0, 2.5, 4.0, 7.0])
    np.testing.assert_allclose(pchip(x, y, xq), 2.0 - 2.0 * (xq - 1.0), rtol=0, atol=1e-15)


def test_three_points_end_rules():
    # m = (1, 1): the three-point end estimate is the common slope, no limiting
    np.testing.assert_allclose(pchip_slopes([0.0, 1.0, 3.0], [0.0, 1.0, 3.0]), [1.0, 1.0, 1.0])
    # a peak: interior slope 0; end estimate ((2 h0 + h1) m0 - h0 m1) / (h0 + h1) = 2 m0,
    # within 3 |m0| so kept
    np.testing.assert_allclose(pchip_slopes([0.0, 1.0, 2.0], [0.0, 1.0, 0.0]),
                               [2.0, 0.0, -2.0])
    # steep neighbour of the other sign: the estimate overshoots 3 |m0| and is clipped to 3 m0
    np.testing.assert_allclose(pchip_slopes([0.0, 1.0, 1.1], [0.0, 1.0, 0.0]),
                               [3.0, 0.0, -11.0])
    # m1 much steeper than m0: the estimate takes the wrong sign and is set to 0
    np.testing.assert_allclose(pchip_slopes([0.0, 1.0, 2.0], [0.0, 0.1, 3.0])[0], 0.0)


def test_data_reproduced_and_monotone_data_stay_monotone():
    x = np.array([0.0, 0.5, 2.0, 2.2, 5.0, 9.0])
    y = np.array([0.0, 0.0, 1.0, 3.0, 3.0, 3.5])
    np.testing.assert_allclose(pchip(x, y, x), y, rtol=0, atol=1e-15)
    dense = pchip(x, y, np.linspace(0.0, 9.0, 2001))
    assert np.all(np.diff(dense) >= 0.0)
    assert dense.min() >= 0.0 and dense.max() <= 3.5  # no overshoot on flat stretches


def test_pieces_join_with_continuous_slope():
    rng = np.random.default_rng(3)
    x = np.cumsum(rng.uniform(0.1, 2.0, 8))
    y = rng.normal(size=(8, 4))
    c = pchip_coefficients(x, y)
    h = np.diff(x)[:, None]
    end_value = ((c[0] * h + c[1]) * h + c[2]) * h + c[3]
    end_slope = (3 * c[0] * h + 2 * c[1]) * h + c[2]
    np.testing.assert_allclose(end_value, y[1:], rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(end_slope[:-1], c[2, 1:], rtol=1e-12, atol=1e-12)


def test_hermite_coefficients_take_the_given_slopes():
    x = np.array([0.0, 2.0, 3.0])
    y = np.array([1.0, 5.0, 2.0])
    d = np.array([0.5, -1.0, 4.0])
    c = hermite_coefficients(x, y, d)
    np.testing.assert_array_equal(c[2], d[:-1])
    np.testing.assert_array_equal(c[3], y[:-1])
    h = np.diff(x)
    np.testing.assert_allclose(3 * c[0] * h ** 2 + 2 * c[1] * h + c[2], d[1:], atol=1e-14)


@pytest.mark.parametrize(("x", "y", "match"), [
    ([0.0], [1.0], "at least 2"),
    ([[0.0, 1.0]], [1.0, 2.0], "1-D"),
    ([0.0, 1.0, 2.0], [1.0, 2.0], r"shape \(3, \.\.\.\).*found \(2,\)"),
    ([0.0, 1.0, 1.0], [1.0, 2.0, 3.0], "increase strictly"),
    ([0.0, 2.0, 1.0], [1.0, 2.0, 3.0], "increase strictly"),
])
def test_bad_input_raises(x, y, match):
    with pytest.raises(GeometryError, match=match):
        pchip_coefficients(x, y)


def test_hermite_slopes_of_the_wrong_shape_raise():
    with pytest.raises(GeometryError, match=r"values' shape \(3,\), found \(2,\)"):
        hermite_coefficients([0.0, 1.0, 2.0], [1.0, 2.0, 0.0], [0.5, 0.5])


# The model's callers give what SciPy gave them before (issue 14).

def test_interpolate_chordwise_matches_scipy_including_extrapolation():
    rng = np.random.default_rng(5)
    xc = np.array([0.0, 3.0, 10.0, 30.0, 55.0, 80.0, 100.0])
    off = rng.uniform(-1.0, 2.0, (2, 3, xc.size))
    f = np.linspace(-0.1, 1.1, 17)
    ref = np.moveaxis(PchipInterpolator(xc / 100, np.moveaxis(off, -1, 0), axis=0,
                                        extrapolate=True)(f), 0, -1)
    close(interpolate_chordwise(xc, off, f), ref)


def test_wing_chord_cubics_match_scipy():
    xc = np.array([0.0, 5.0, 20.0, 45.0, 70.0, 100.0])
    up = np.array([[0.0, 1.2, 2.1, 2.4, 1.6, 0.1], [0.0, 1.0, 1.8, 2.0, 1.3, 0.1],
                   [0.0, 0.8, 1.5, 1.5, 1.1, 0.0]])
    w = WingLike("wing", "wing", [[0.0, 1.0, 0.0], [3.0, 5.0, 0.2], [6.0, 9.0, 0.4]],
                 [10.0, 7.0, 4.0], xc, up)
    t, coefs = w._chord_cubics("upper")
    close(coefs, PchipInterpolator(t, w._offsets("upper").T, axis=0).c)


def test_body_radius_matches_scipy_segment_by_segment():
    x = np.array([0.0, 2.0, 5.0, 5.0, 9.0, 14.0, 20.0])
    r = np.array([0.0, 1.0, 1.5, 1.5, 1.5, 1.2, 0.4])
    b = CircularBody("body", x, r, segments=(3, 4))
    xq = np.concatenate([np.linspace(0.0, 4.999, 9), np.linspace(5.0, 20.0, 11)])
    ref = np.concatenate([PchipInterpolator(x[:3], r[:3])(xq[:9]),
                          PchipInterpolator(x[3:], r[3:])(xq[9:])])
    close(b.radius_at(xq), ref)


def test_flat_stretches_raise_no_floating_point_errors():
    # a cylindrical stretch once made SciPy divide by zero inside (silenced by the caller)
    x = np.array([0.0, 4.0, 9.0, 15.0, 22.0])
    r = np.array([0.0, 1.0, 1.0, 1.0, 0.5])
    with np.errstate(all="raise"):
        b = CircularBody("body", x, r)
        np.testing.assert_array_equal(b.radius_at(np.array([4.0, 6.5, 9.0, 12.0])), 1.0)
