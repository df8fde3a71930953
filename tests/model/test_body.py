"""Bodies: TM-4406 eqs 1-3, radius interpolation, signed distance, arbitrary sections."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.errors import GeometryError
from juncture.model import ArbitraryBody, CircularBody

XS = np.array([0.0, 4.0, 9.0, 15.0, 22.0, 30.0])


def cylinder(radius=2.0, **kw):
    return CircularBody("body", XS, np.full(XS.size, radius), **kw)


@settings(max_examples=50, deadline=None)
@given(x=st.floats(0.0, 30.0), theta=st.floats(-np.pi, np.pi))
def test_point_follows_eqs_2_and_3(x, theta):
    cam = 0.1 * XS ** 1.2
    b = CircularBody("body", XS, 1.0 + 0.05 * XS, camber=cam, axial="linear")
    p = b.point(x, theta)
    r = np.interp(x, XS, 1.0 + 0.05 * XS)
    c = np.interp(x, XS, cam)
    np.testing.assert_allclose(p, [x, r * np.cos(theta), c + r * np.sin(theta)], atol=1e-12)
    assert abs(b.radial_error(p)) < 1e-12


def test_pchip_radius_reproduces_stations_and_keeps_monotone_shape():
    r = np.array([0.0, 1.0, 1.8, 2.0, 2.0, 1.5])
    b = CircularBody("body", XS, r)
    np.testing.assert_allclose(b.radius_at(XS), r, atol=1e-14)
    dense = b.radius_at(np.linspace(0, 15, 400))
    assert np.all(np.diff(dense) >= -1e-12)  # no overshoot where the data rise
    assert b.radius_at(-1.0) == 0.0 and b.radius_at(31.0) == 0.0


def test_signed_distance_of_a_cylinder_is_exact():
    b = cylinder()
    pts = np.array([[12.0, 0.0, 3.0], [12.0, 1.0, 0.0], [12.0, 0.0, -2.0], [-1.0, 0.0, 0.0],
                    [33.0, 0.0, 5.0]])
    expect = [1.0, -1.0, 0.0, 1.0, 5.0 - 2.0 + 0.0]
    expect[4] = np.hypot(3.0, 3.0)  # nearest point is the base rim (30, r=2)
    np.testing.assert_allclose(b.signed_distance(pts), expect, atol=1e-9)


def test_signed_distance_of_a_sphere():
    R = 5.0
    phi = np.linspace(0, np.pi, 161)  # equal arcs: the meridian polygon's sagitta is 2.4e-4
    x = R * (1 - np.cos(phi))
    b = CircularBody("sphere", x, R * np.sin(phi), axial="linear")
    rng = np.random.default_rng(3)
    d = rng.normal(size=(50, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    radii = rng.uniform(3.0, 8.0, 50)
    pts = np.array([R, 0, 0]) + d * radii[:, None]
    np.testing.assert_allclose(b.signed_distance(pts), radii - R, atol=3e-4)


def test_joint_station_may_repeat_between_segments_only():
    x = [0, 1, 2, 2, 3, 4]
    b = CircularBody("body", x, [0, 1, 1, 2, 2, 1], segments=(3, 3), axial="linear")
    assert b.radius_at(1.5) == pytest.approx(1.0)
    assert b.radius_at(2.5) == pytest.approx(2.0)
    with pytest.raises(GeometryError, match=r"body, station 4: x must increase within a segment"):
        CircularBody("body", x, [0, 1, 1, 2, 2, 1], segments=(6,))


@pytest.mark.parametrize("kw, match", [
    (dict(radius=[1, 1, -0.5, 1, 1, 1]), r"body, station 3: radius is negative"),
    (dict(radius=[1, 1, 1]), r"radius \(one per station\) must have shape \(6\)"),
    (dict(segments=(2, 2)), r"segment sizes \(2, 2\) must each be >= 2 and add up to the 6"),
    (dict(radius=[1, 1, np.nan, 1, 1, 1]), r"body, station 3: radius is not finite"),
])
def test_bad_bodies_name_the_station(kw, match):
    args = dict(name="body", x=XS, radius=np.ones(6))
    args.update(kw)
    with pytest.raises(GeometryError, match=match):
        CircularBody(**args)


def test_pod_about_its_own_origin():
    pod = CircularBody("pod 1", [0, 10, 20], [1.0, 1.5, 1.0], origin=(200.0, 16.0, -5.0),
                       mirrored=True, axial="linear")
    p = pod.point(210.0, 0.0)
    np.testing.assert_allclose(p, [210.0, 17.5, -5.0])
    net = pod.networks()["pod 1"]
    assert net.shape == (3, 37, 3)  # closed all round: 2 * 19 - 1 points
    np.testing.assert_allclose(net[:, 0], net[:, -1], atol=1e-12)


def test_body_network_orientation_is_outward():
    net = cylinder().networks()["body"]
    n = np.cross(net[2, 10] - net[2, 9], net[3, 9] - net[2, 9])
    radial = net[2, 9] - [net[2, 9, 0], 0, 0]
    assert n @ radial > 0


def _square_sections(half):
    # y >= 0 half of a square of half-width `half`, bottom to top.
    return np.array([[0, -half], [half, -half], [half, half], [0, half]], float)


def test_arbitrary_body_area_and_distance():
    secs = [_square_sections(1.0), _square_sections(2.0), _square_sections(2.0)]
    b = ArbitraryBody("body", [0.0, 10.0, 20.0], secs)
    np.testing.assert_allclose(b.area_at([0.0, 5.0, 15.0]), [4.0, 9.0, 16.0], rtol=1e-12)
    np.testing.assert_allclose(b.signed_distance([[15, 0, 0], [15, 3, 0], [15, -2.5, 0]]),
                               [-2.0, 1.0, 0.5], atol=1e-12)
    p = b.point(15.0, 0.5)  # half-way along the outline: the middle of the vertical side
    np.testing.assert_allclose(p, [15.0, 2.0, 0.0], atol=1e-12)


def test_arbitrary_body_rejects_negative_y():
    with pytest.raises(GeometryError, match=r"body, station 2: half-section has y < 0"):
        ArbitraryBody("body", [0, 1], [_square_sections(1), -_square_sections(1)])


def test_hermite_slopes_reproduce_a_cubic_exactly():
    # r(x) = 1 + 0.1 x - 0.02 x^2 + 0.001 x^3 sampled with its exact slopes: Hermite pieces
    # reproduce it everywhere (independent reference: the polynomial itself).
    x = np.array([0.0, 1.5, 4.0, 7.0, 10.0])
    poly = np.polynomial.Polynomial([1.0, 0.1, -0.02, 0.001])
    cam = np.polynomial.Polynomial([0.2, -0.05, 0.003])
    slopes = np.stack([poly.deriv()(x), cam.deriv()(x)], axis=1)
    body = CircularBody("b", x, poly(x), cam(x), slopes=slopes)
    xq = np.linspace(0.0, 10.0, 101)
    np.testing.assert_allclose(body.radius_at(xq), poly(xq), atol=1e-13)
    np.testing.assert_allclose(body.radius_at(xq, 1), poly.deriv()(xq), atol=1e-12)
    np.testing.assert_allclose(body.center_at(xq)[:, 1], cam(xq), atol=1e-13)


def test_section_at_matches_center_and_radius():
    body = CircularBody("b", [0, 2, 5, 9], [0.0, 1.0, 1.2, 0.4], [0, 0.1, 0.2, 0.0],
                        origin=(1.0, 0.5, -0.3))
    xq = np.linspace(-1.0, 11.0, 37)
    c, r = body.section_at(xq)
    np.testing.assert_array_equal(c, body.center_at(xq))
    np.testing.assert_array_equal(r, body.radius_at(xq))


def test_bad_slopes_name_the_body():
    with pytest.raises(GeometryError, match="slopes"):
        CircularBody("b", [0, 1, 2], [1, 1, 1], slopes=np.zeros((2, 2)))
    with pytest.raises(GeometryError, match="slopes"):
        CircularBody("b", [0, 1, 2], [1, 1, 1], slopes=[[0, 0], [np.nan, 0], [0, 0]])
