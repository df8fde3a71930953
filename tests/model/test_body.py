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


@given(start=st.floats(-3.0, 3.0), k=st.integers(-2, 3))
def test_top_and_bottom_points_lie_on_the_centre_plane_bit_for_bit(start, k):
    """An angle interpolated up to pi/2 + k pi comes out a few ulps off it: the point is
    still on the plane y = 0, so a network and its mirror image share it exactly."""
    end = 0.5 * np.pi + k * np.pi
    theta = start + np.linspace(0.0, 1.0, 7)[-1] * (end - start)
    p = cylinder().point(12.0, theta)
    assert p[1] == 0.0
    assert abs(p[2]) == pytest.approx(2.0, rel=1e-15)


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


def test_signed_distance_is_exact_on_a_strongly_curved_body():
    """Points on the surface (radius from the body's own r(x)) are 0 to rounding, and points
    off it along the meridian's normal at their distance (small enough not to reach round
    another bend), where the 2001-sample polyline alone was off by the chords' sag."""
    rng = np.random.default_rng(5)
    x = np.linspace(0.0, 100.0, 12) + np.r_[0.0, rng.uniform(-2.0, 2.0, 10), 0.0]
    b = CircularBody("body", x, np.r_[0.0, rng.uniform(3.0, 8.0, 10), 2.0])
    xs = rng.uniform(5.0, 95.0, 4000)
    th = rng.uniform(0.0, 2 * np.pi, xs.size)
    r, r1, r2 = (b.radius_at(xs, k) for k in (0, 1, 2))
    on = np.stack([xs, r * np.cos(th), r * np.sin(th)], -1)
    assert np.abs(b.signed_distance(on)).max() <= 1e-12 * b.length
    bend = np.abs(r2) / (1 + r1 * r1) ** 1.5  # meridian curvature
    d = rng.uniform(-0.02, 0.02, xs.size) * (bend < 1.0)
    nx, nr = -r1 / np.hypot(1, r1), 1 / np.hypot(1, r1)
    xq, rq = xs + d * nx, r + d * nr
    off = np.stack([xq, rq * np.cos(th), rq * np.sin(th)], -1)
    np.testing.assert_allclose(b.signed_distance(off), d, rtol=0, atol=1e-9)


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


# ------------------------------------------------------------------ the surface the deck gives
# Issue 11: arbitrary sections are the polylines through the deck's points (no resampling),
# matched between stations by normalised arc length and blended linearly in x; a gap between
# fuselage segments is bridged by straight lines. References: closed forms, and the
# independent model of tests/deckgen/references.py.
DIAMOND = np.array([[0.0, -1.0], [1.0, 0.0], [0.0, 1.0]])  # arc fractions 0, 1/2, 1
SQUARE = _square_sections(1.0)  # arc fractions 0, 1/4, 3/4, 1


def test_arbitrary_section_is_the_polyline_through_its_points():
    """An irregular convex half-section whose corners fall between any equal-s sampling:
    a point on the outward bisector of a corner is exactly as far from the section as from
    the corner (a resampled section cuts the corner and comes nearer)."""
    sec = np.array([[0.0, -1.3], [0.83, -1.1], [1.37, 0.21], [0.61, 1.09], [0.0, 1.17]])
    b = ArbitraryBody("body", [0.0, 7.0, 13.0], [sec, sec, sec])
    rng = np.random.default_rng(4)
    side = np.diff(sec, axis=0)
    normal = np.stack([side[:, 1], -side[:, 0]], -1)  # outward: points run counter-clockwise
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    for j, corner in enumerate(sec[1:-1]):
        bisector = normal[j] + normal[j + 1]
        d = rng.uniform(0.05, 0.6)
        out = corner + d * bisector / np.linalg.norm(bisector)
        got = b.signed_distance([[3.1, out[0], out[1]], [3.1, -out[0], out[1]]])
        np.testing.assert_allclose(got, [d, d], rtol=1e-14)
        assert b.signed_distance([4.2, *corner]) == pytest.approx(0.0, abs=1e-15)
    # Mid-side points are on the surface; points just inside are negative.
    mids = 0.5 * (sec[1:] + sec[:-1])
    pts = np.concatenate([np.full((4, 1), 9.0), mids], axis=1)
    np.testing.assert_allclose(b.signed_distance(pts), 0.0, atol=1e-15)
    assert (b.signed_distance(pts * [1, 0.99, 0.99]) < 0).all()
    # s runs along the polyline by arc length: the corners' fractions map to the corners.
    seg = np.hypot(*np.diff(sec, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)]) / seg.sum()
    np.testing.assert_allclose(b.point(5.0, s)[:, 1:], sec, atol=1e-15)
    np.testing.assert_allclose(b.parameter_of(b.point(5.0, s)), s, atol=1e-15)


def test_sections_between_stations_are_matched_by_arc_length_and_blended_linearly():
    """Diamond (3 points) at x = 0 to square (4 points) at x = 10: at x = 5 the section is
    the polyline (0,-1), (3/4,-3/4), (1,0), (3/4,3/4), (0,1) (both matched at s = 0, 1/4,
    1/2, 3/4, 1)."""
    b = ArbitraryBody("body", [0.0, 10.0], [DIAMOND, SQUARE])
    mid = np.array([[0, -1], [0.75, -0.75], [1, 0], [0.75, 0.75], [0, 1]])
    np.testing.assert_allclose(b.point(5.0, [0, 0.25, 0.5, 0.75, 1])[:, 1:], mid, atol=1e-15)
    # Outward of the corner (3/4, 3/4): nearest is the corner, distance 1.25 sqrt(2).
    assert b.signed_distance([5.0, 2.0, 2.0]) == pytest.approx(1.25 * np.sqrt(2), rel=1e-15)
    # The centre is 3 / sqrt(10) inside both sides through (3/4, 3/4).
    assert b.signed_distance([5.0, 0.0, 0.0]) == pytest.approx(-3 / np.sqrt(10), rel=1e-14)
    # Whole-section area: diamond 2, square 4, and the mid polygon 4 x 3/4 = 3.
    np.testing.assert_allclose(b.area_at([0.0, 5.0, 10.0]), [2.0, 3.0, 4.0], rtol=1e-15)
    # Mean height over s (the centre for orientation) of a section symmetric in z: 0.
    np.testing.assert_allclose(b.center_at([0.0, 5.0, 10.0]), 0.0, atol=1e-15)
    # At the stations the section is the deck's polyline itself.
    np.testing.assert_allclose(b.point(0.0, [0, 0.5, 1])[:, 1:], DIAMOND, atol=1e-15)
    np.testing.assert_allclose(b.point(10.0, [0, 0.25, 0.75, 1])[:, 1:], SQUARE, atol=1e-15)


def random_arbitrary_body(rng, counts=(5, 7, 6, 9, 4), joints=(2, 3)):
    """Random star-shaped half-sections (different point counts), in segments of stations."""
    secs = []
    for m in counts:
        th = np.sort(rng.uniform(-np.pi / 2, np.pi / 2, m))
        th[0], th[-1] = -np.pi / 2, np.pi / 2
        r = rng.uniform(0.8, 1.6, m)
        secs.append(np.stack([r * np.cos(th), 0.3 + r * np.sin(th)], -1))
        secs[-1][[0, -1], 0] = 0.0
    x = np.cumsum(rng.uniform(1.0, 3.0, len(counts)))
    return x, secs


def test_arbitrary_body_distance_agrees_with_the_independent_reference():
    from tests.deckgen.references import ArbitraryBodyRef

    rng = np.random.default_rng(12)
    x, secs = random_arbitrary_body(rng)
    # Two segments with a gap between stations 3 and 4 (x[2] < x[3]).
    b = ArbitraryBody("body", x, secs, segments=(3, 2))
    ref = ArbitraryBodyRef([(x[sl], [s[:, 0] for s in secs[sl]], [s[:, 1] for s in secs[sl]])
                            for sl in (slice(0, 3), slice(3, 5))])
    xq = rng.uniform(x[0] + 1e-3, x[-1] - 1e-3, 300)
    pts = np.stack([xq, rng.uniform(-2, 2, xq.size), rng.uniform(-1.5, 2.0, xq.size)], -1)
    d_ref, _ = ref.distance(pts)
    np.testing.assert_allclose(np.abs(b.signed_distance(pts)), d_ref, rtol=0, atol=1e-14)
    # Points of the surface lie on the reference surface, and s is recovered from them.
    s = rng.uniform(0, 1, xq.size)
    on = b.point(xq, s)
    assert ref.distance(on)[0].max() < 1e-14
    np.testing.assert_allclose(b.parameter_of(on), s, rtol=0, atol=1e-13)


def test_arbitrary_body_lipschitz_bounds_hold():
    rng = np.random.default_rng(2)
    x, secs = random_arbitrary_body(rng)
    b = ArbitraryBody("body", x, secs)
    pa = np.stack([rng.uniform(x[0], x[-1], 400), rng.uniform(-2, 2, 400),
                   rng.uniform(-1.5, 2, 400)], -1)
    step = rng.normal(size=(400, 3))
    step *= rng.uniform(1e-4, 0.5, (400, 1)) / np.linalg.norm(step, axis=1)[:, None]
    pb = pa + step
    pb[:, 0] = np.clip(pb[:, 0], x[0], x[-1])
    rate = np.abs(b.signed_distance(pb) - b.signed_distance(pa)) / np.linalg.norm(pb - pa,
                                                                                   axis=1)
    local = b.error_lipschitz_between(pa, pb)
    assert (rate <= local).all() and (local <= b.error_lipschitz).all()
    # A section that does not move along x: the distance is 1-Lipschitz, exactly.
    still = ArbitraryBody("body", [0.0, 5.0], [SQUARE, SQUARE])
    assert still.error_lipschitz == 1.0


@pytest.mark.parametrize("axial", ["pchip", "linear"])
def test_a_gap_between_segments_is_a_straight_frustum(axial):
    """Segment 1 ends at x = 4 (r 1.5, camber 0.2), segment 2 starts at x = 6 (r 2.5, camber
    -0.2): between them r and camber are linear in x; no overshoot, no jump at either end."""
    x = [0.0, 1.0, 2.5, 4.0, 6.0, 7.0, 9.0, 10.0]
    r = [0.2, 0.9, 1.3, 1.5, 2.5, 2.2, 2.1, 1.0]
    c = [0.0, 0.1, 0.15, 0.2, -0.2, -0.1, 0.0, 0.1]
    b = CircularBody("body", x, r, c, origin=(3.0, 0.0, 0.5), segments=(4, 4), axial=axial)
    xg = np.linspace(7.0, 9.0, 9)  # the gap, global x
    w = (xg - 7.0) / 2.0
    r_line, c_line = 1.5 + w * 1.0, 0.5 + 0.2 - 0.4 * w
    np.testing.assert_allclose(b.radius_at(xg), r_line, rtol=1e-15, atol=1e-15)
    np.testing.assert_allclose(b.center_at(xg)[:, 1], c_line, rtol=1e-15, atol=1e-15)
    np.testing.assert_allclose(b.radius_at(xg[:-1], 1), 0.5, rtol=1e-14)  # x = 9: segment 2
    np.testing.assert_allclose(b.area_at(xg), np.pi * r_line ** 2, rtol=1e-15)
    th = np.linspace(-np.pi / 2, np.pi / 2, 9)
    p = b.point(xg, th)
    np.testing.assert_allclose(p[:, 1:], np.stack([r_line * np.cos(th),
                                                   c_line + r_line * np.sin(th)], -1),
                               atol=1e-15)
    np.testing.assert_allclose(b.radial_error(p), 0.0, atol=1e-15)
    # Straight lines between corresponding points of the two end circles: the frustum.
    a_pts, b_pts = b.point(7.0, th), b.point(9.0, th)
    np.testing.assert_allclose(p, a_pts + w[:, None] * (b_pts - a_pts), atol=1e-14)
    # The slope bound on a segment in the gap is 1 + |r'| + |c'| = 1 + 0.5 + 0.2.
    assert b.error_lipschitz_between([7.2, 0, 0], [8.8, 1, 1]) == pytest.approx(1.7, rel=1e-8)
    # Both segments keep their own interpolants up to their end stations.
    np.testing.assert_allclose(b.radius_at([3.0, 7.0, 9.0, 13.0]), [0.2, 1.5, 2.5, 1.0],
                               rtol=1e-15)
    # Signed distance (meridian polyline sampled at every station): a point 0.3 outside
    # the frustum, along its normal, is 0.3 away (uncambered copy of the body).
    flat = CircularBody("body", x, r, segments=(4, 4), axial=axial)
    n = np.array([-0.5, 1.0]) / np.hypot(0.5, 1.0)  # meridian normal: r' = 0.5
    q = np.array([5.0, 2.0]) + 0.3 * n
    assert flat.signed_distance([q[0], q[1], 0.0]) == pytest.approx(0.3, rel=1e-12)


def test_segment_pieces_skip_the_bridge():
    """``value_and_slope(pieces=...)`` counts the segments' own pieces (the numbering the
    re-designed fuselage uses): segment 2's first station takes segment 2's slope."""
    x = np.array([0.0, 1.0, 2.0, 4.0, 5.0, 7.0])
    r = np.array([1.0, 1.0, 1.0, 3.0, 4.0, 4.0])
    b = CircularBody("body", x, r, segments=(3, 3), axial="linear")
    v, s = b._interp.value_and_slope(np.array([4.0]), (2, 3))  # segment 2: pieces 2 and 3
    assert v[0, 0] == 3.0 and s[0, 0] == 1.0
    v, s = b._interp.value_and_slope(np.array([2.0]), (0, 1))  # segment 1 at its end
    assert v[0, 0] == 1.0 and s[0, 0] == 0.0
    assert b.radius_at(3.0) == 2.0 and b.radius_at(3.0, 1) == 1.0  # the bridge


def test_arbitrary_body_gap_is_a_straight_blend():
    """An arbitrary body with a gap: between the last section of one segment and the first of
    the next, matched points are joined linearly (as between any two stations)."""
    b = ArbitraryBody("body", [0.0, 2.0, 5.0, 8.0], [SQUARE, SQUARE, 2 * DIAMOND,
                                                      2 * DIAMOND], segments=(2, 2))
    mid = np.array([[0, -1.5], [1, -1], [1.5, 0], [1, 1], [0, 1.5]])
    np.testing.assert_allclose(b.point(3.5, [0, 0.25, 0.5, 0.75, 1])[:, 1:], mid,
                               atol=1e-15)
