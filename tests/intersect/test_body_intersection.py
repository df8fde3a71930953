"""Wing / body intersection (TM-4406 eqs 4-6, TM-4607 eq 8): points on both surfaces."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.errors import GeometryError
from juncture.intersect import find_crossings, intersect_body
from juncture.model import ArbitraryBody, CircularBody, WingLike
from tests.support import wing_body


def distance_to_line(p, a, b):
    d = (b - a) / np.linalg.norm(b - a, axis=-1)[..., None]
    v = p - a
    return np.linalg.norm(v - (v * d).sum(-1)[..., None] * d, axis=-1)


def check_on_both(cfg, side):
    wing, body = cfg["wing"], cfg["body"]
    res = intersect_body(wing, body, side)
    L = body.length
    lines = wing.lofting_lines(side)
    p = res.points[res.found]
    # On the body: independent of the solver's own error function, from r(x) and c(x).
    ctr = np.array([[0.0, body.center_at(x)[1]] for x in p[:, 0]])
    dist = np.hypot(p[:, 1] - ctr[:, 0], p[:, 2] - ctr[:, 1])
    assert np.all(np.abs(dist - body.radius_at(p[:, 0])) < 1e-9 * L)
    # On the extended lofting line: the segment (or its extension) the point's u says.
    k = np.clip(np.floor(res.u[res.found]).astype(int), 0, wing.n_sections - 2)
    rows = np.flatnonzero(res.found)
    assert np.all(distance_to_line(p, lines[rows, k], lines[rows, k + 1]) < 1e-9 * L)
    return res


@settings(max_examples=40, deadline=None)
@given(z=st.floats(-2.2, 2.2), dihedral=st.floats(-6.0, 8.0), root_y=st.floats(-0.5, 4.5),
       camber=st.floats(0.0, 2.0), body_camber=st.floats(-0.5, 0.5))
def test_points_lie_on_the_body_and_on_their_lofting_lines(z, dihedral, root_y, camber,
                                                           body_camber):
    """High, mid and low wings; dihedral; root inside, on or outside the body."""
    cfg = wing_body(z_root=z, dihedral_deg=dihedral, root_y=root_y, camber=camber,
                    body_camber=body_camber)
    for side in ("upper", "lower"):
        res = check_on_both(cfg, side)
        # A line reported as missing must really stay outside on the searched range: from
        # the plane of symmetry (y = 0) to the tip, checked by brute force.
        wing, body = cfg["wing"], cfg["body"]
        lines = wing.lofting_lines(side)
        y0, y1 = wing.span_stations[:2]
        u = np.linspace(min((0.0 - y0) / (y1 - y0), 0.0), wing.n_sections - 1, 40001)
        from juncture.intersect import polyline_points

        for j in np.flatnonzero(~res.found):
            e = body.radial_error(polyline_points(lines[j:j + 1], u[None]))[0]
            assert e.min() > -1e-9


def test_root_inside_the_body_gives_points_between_sections_1_and_2():
    res = intersect_body(*[wing_body(root_y=1.0)[n] for n in ("wing", "body")], "upper")
    assert np.all((res.u > 0) & (res.u < 1))
    res = intersect_body(*[wing_body(root_y=4.5)[n] for n in ("wing", "body")], "upper")
    assert np.all(res.u < 0)  # root outside: extrapolated inboard (eq 4, t > 0)


def test_mid_wing_angle_is_near_zero_and_high_wing_positive():
    mid = intersect_body(*[wing_body(z_root=0.0)[n] for n in ("wing", "body")], "upper")
    high = intersect_body(*[wing_body(z_root=2.0)[n] for n in ("wing", "body")], "upper")
    assert np.all(np.abs(mid.theta) < 0.4) and np.all(high.theta > 0.5)


def test_a_lower_line_that_misses_the_body_is_reported():
    # Wing hanging far below a thin body: its lower lofting lines never reach it.
    cfg = wing_body(z_root=-2.9, dihedral_deg=-25.0, radius=3.0, root_y=0.2)
    res = intersect_body(cfg["wing"], cfg["body"], "lower")
    assert (~res.found).any()
    assert any("misses body" in s for s in res.log)
    assert np.isnan(res.points[~res.found]).all()


def test_double_crossing_takes_the_first_reached_coming_inboard():
    # A line that passes through a bump of the body twice: a body of two bulges.
    x = np.linspace(0.0, 40.0, 41)
    r = 2.0 + 1.5 * np.cos(2 * np.pi * x / 20.0)
    body = CircularBody("body", x, r, axial="linear")
    # Sections at y = 6 and 8, sloping so the extension crosses the bulges at x ~ 20 and ~ 0.
    le = np.array([[25.0, 6.0, 0.0], [31.0, 8.0, 0.0]])
    wing = WingLike("wing", "wing", le, [2.0, 2.0], [0.0, 100.0], [[0.0, 0.0], [0.0, 0.0]])
    res = intersect_body(wing, body, "upper")
    assert res.n_crossings.max() >= 2 and any("crosses body" in s for s in res.log)
    # First reached coming inboard = the largest u (closest to the tip) among the crossings.
    u = np.linspace(-4.0, 1.0, 200001)
    pts = le[0] + u[:, None] * (le[1] - le[0])
    e = body.radial_error(pts)
    entering = np.flatnonzero((e[:-1] <= 0) & (e[1:] > 0))  # inside just inboard of outside
    assert res.u[0] == pytest.approx(u[entering.max()], abs=1e-4)


def test_tip_inside_the_body_is_an_error():
    cfg = wing_body(root_y=0.0)
    wing = cfg["wing"]
    small = WingLike("wing", "wing", wing.le * [1, 0.1, 1], wing.chord, wing.x_over_c,
                     wing.upper)
    with pytest.raises(GeometryError, match=r"wing, station 4: the tip of upper lofting line 1 "
                                            r"lies inside body"):
        intersect_body(small, cfg["body"], "upper")


def test_find_crossings_solves_a_line_against_a_sphere_exactly():
    # Independent closed form: line x = 0, z = 0, y from 10 down, sphere radius 2 at origin.
    lines = np.array([[[0.0, 6.0, 0.0], [0.0, 10.0, 0.0]]])
    res = find_crossings(lines, lambda p: np.linalg.norm(p, axis=-1) - 2.0, -3.0)
    assert res.found[0] and res.points[0] == pytest.approx([0.0, 2.0, 0.0], abs=1e-12)
    assert res.u[0] == pytest.approx(-1.0, abs=1e-12)


# ------------------------------------------------------------------ arbitrary sections
# Issue 11: the surface is the deck's polylines, matched by arc length between stations and
# blended linearly in x; an intersection is a root of that surface, never a jump.
DIAMOND = np.array([[0.0, -1.0], [1.0, 0.0], [0.0, 1.0]])
SQUARE = np.array([[0.0, -1.0], [1.0, -1.0], [1.0, 1.0], [0.0, 1.0]])


def flat_wing(x_le, y, z, chord, dihedral_deg=0.0, x_over_c=(0.0, 20.0, 45.0, 70.0, 100.0)):
    """An unswept wing of zero thickness at height z: lofting lines at constant x."""
    y = np.asarray(y, float)
    le = np.stack([np.full(y.size, x_le), y,
                   z + (y - y[0]) * np.tan(np.radians(dihedral_deg))], -1)
    zero = np.zeros((y.size, len(x_over_c)))
    return WingLike("wing", "wing", le, np.full(y.size, chord), x_over_c, zero)


def blended_diamond_rectangle(w):
    """Closed form of the section w of the way from the diamond to the 1.3 x 2 rectangle:
    both at their matched fractions u = 0, a, 1/2, 1 - a, 1 (a = 1.3 / 4.6, the rectangle's
    corners; the diamond's one corner is at 1/2). Returns u (5,) and vertices (len(w), 5, 2).
    """
    a = 1.3 / 4.6
    u = np.array([0.0, a, 0.5, 1.0 - a, 1.0])
    diamond = np.array([[0, -1], [2 * a, -1 + 2 * a], [1, 0], [2 * a, 1 - 2 * a], [0, 1]])
    rect = np.array([[0, -1], [1.3, -1], [1.3, 0], [1.3, 1], [0, 1]])
    w = np.asarray(w, float)[:, None, None]
    return u, (1 - w) * diamond + w * rect


@pytest.mark.parametrize("z0, dihedral_deg", [(0.714, 0.0), (0.69, 4.0), (-0.66, -3.0)])
def test_points_lie_on_the_blended_polylines_of_an_arbitrary_body(z0, dihedral_deg):
    """Diamond (3 points) at x = 0; rectangle 1.3 x 2 (corners at arc fractions off any
    equal-s sampling) at x = 10 and 20. The lofting line y -> (y, z0 + g (y - 2)) at x
    meets the section polyline (closed form above) on one side, at a point solved in closed
    form; heights near the corners, where a resampled section cuts them."""
    rect = np.array([[0.0, -1.0], [1.3, -1.0], [1.3, 1.0], [0.0, 1.0]])
    body = ArbitraryBody("body", [0.0, 10.0, 20.0], [DIAMOND, rect, rect])
    wing = flat_wing(3.0, [2.0, 3.5, 5.0], z0, 4.0, dihedral_deg,
                     x_over_c=(0.0, 25.0, 50.0, 75.0, 100.0))
    res = intersect_body(wing, body, "upper")
    assert res.found.all()
    x = wing.lofting_lines("upper")[:, 0, 0]
    g = np.tan(np.radians(dihedral_deg))
    u, v = blended_diamond_rectangle(x / 10.0)
    p, d = v[:, :-1], np.diff(v, axis=1)  # sides (lines, 4, 2)
    # p_z + t d_z = z0 + g (p_y + t d_y - 2), each side; the one with 0 <= t <= 1
    t = (z0 + g * (p[..., 0] - 2.0) - p[..., 1]) / (d[..., 1] - g * d[..., 0])
    side = np.argmax((t >= 0) & (t <= 1), axis=1)
    rows = np.arange(x.size)
    tj = t[rows, side]
    expect = np.concatenate([x[:, None], p[rows, side] + tj[:, None] * d[rows, side]], -1)
    np.testing.assert_allclose(res.points, expect, rtol=0, atol=1e-12 * body.length)
    np.testing.assert_allclose(res.theta, u[side] + tj * (u[side + 1] - u[side]), rtol=0,
                               atol=1e-12)
    assert res.residual.max() < 1e-12 * body.length


def test_a_line_that_meets_an_arbitrary_body_only_through_a_joint_step_misses():
    """Segment 1 (x 0 to 5) is a square of half-width 1, segment 2 (x 5 to 10, repeated joint
    station) one of half-width 2. A forward-swept line coming inboard is outside the small
    square for x < 5 and inside the large one for x > 5: it meets the body only through the
    step's face at x = 5, which is not part of the parametric surface. The sign change there
    is a jump of the error, not a root: the line misses (NaN), as documented in
    :func:`juncture.intersect.intersect_body`."""
    body = ArbitraryBody("body", [0.0, 5.0, 5.0, 10.0], [SQUARE, SQUARE, 2 * SQUARE,
                                                          2 * SQUARE], segments=(2, 2))
    # Root LE at (3, 2.5), tip LE at (0, 4): y = 1.5 + 0.25 f - (x - 5) / 2 on the lines.
    le = np.array([[3.0, 2.5, 0.0], [0.0, 4.0, 0.0]])
    wing = WingLike("wing", "wing", le, [0.5, 0.5], [0.0, 50.0, 100.0], np.zeros((2, 3)))
    res = intersect_body(wing, body, "upper")
    assert not res.found.any()
    assert np.isnan(res.points).all()
    assert sum("misses body" in s for s in res.log) == 3
    # The same line with the step removed (large square throughout) meets its side at y = 2
    # for x < 5: a root, found to 1e-12.
    big = ArbitraryBody("body", [0.0, 10.0], [2 * SQUARE, 2 * SQUARE])
    res = intersect_body(wing, big, "upper")
    assert res.found.all()
    np.testing.assert_allclose(res.points[:, 1], 2.0, rtol=0, atol=1e-12 * big.length)
    np.testing.assert_allclose(res.points[:, 0], 4.0 + 0.5 * np.array([0.0, 0.5, 1.0]),
                               rtol=0, atol=1e-12 * big.length)


def test_a_sharp_edge_meets_the_body_at_one_point_on_both_sides():
    """The leading and trailing edges are lofting lines of both surfaces: their intersection
    point is the same on both, bit for bit, so the seams close by vertex ids."""
    from juncture.intersect import intersect_body_both

    for z_root in (-1.2, 0.0, 1.7):
        cfg = wing_body(z_root=z_root, dihedral_deg=5.0, camber=1.0)
        wing = cfg["wing"]
        up, lo = intersect_body_both(wing, cfg["body"])
        same = np.all(wing.lofting_lines("upper") == wing.lofting_lines("lower"), axis=(1, 2))
        assert same[0] and same[-1]
        assert np.array_equal(up.points[same], lo.points[same])
        assert np.array_equal(up.u[same], lo.u[same])


def test_a_canted_fin_beside_the_body_at_its_centre_height_meets_it_below():
    """A fin canted 26.6 deg outwards on a cylinder of radius 1 (axis z = 0): extended down,
    each outboard lofting line is still 1.02-1.065 from the axis at the centre height z = 0
    (where the search for a fin's crossing used to stop) and enters the cylinder below it
    (its closest approach to the axis is at most 0.955). Expected: the larger root of the
    line's quadratic with the cylinder, y^2 + z^2 = 1 (the first reached from the tip)."""
    body = CircularBody("body", [0.0, 10.0, 80.0], [0.0, 1.0, 1.0], axial="linear")
    xc = np.array([0.0, 25.0, 50.0, 75.0, 100.0])
    half = np.array([[0.0, 0.3, 0.5, 0.3, 0.0]] * 2)  # % chord
    le = np.array([[40.0, 1.52, 1.0], [42.0, 3.52, 5.0]])
    fin = WingLike("fin 1", "fin", le, [8.0, 4.0], xc, half, half)
    for side in ("upper", "lower"):
        res = intersect_body(fin, body, side)
        assert res.found.all()
        a, b = fin.lofting_lines(side)[:, 0], fin.lofting_lines(side)[:, 1]
        d = b - a
        qa = d[:, 1] ** 2 + d[:, 2] ** 2
        qb = 2 * (a[:, 1] * d[:, 1] + a[:, 2] * d[:, 2])
        qc = a[:, 1] ** 2 + a[:, 2] ** 2 - 1.0
        t = (-qb + np.sqrt(qb ** 2 - 4 * qa * qc)) / (2 * qa)
        expected = a + t[:, None] * d
        if side == "upper":  # outboard: every line below the centre height
            assert np.all(expected[:, 2] < 0)
        np.testing.assert_allclose(res.points, expected, rtol=0, atol=1e-12 * body.length)
