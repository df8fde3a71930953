"""Boundary pieces split for thin triangles whose circumcentre lies outside the chart, and
the points that refine thin triangles without splitting a piece.

Oracles: distances (a circumcentre is equidistant from its corners), charts drawn by hand
(a thin strip with one side split finely and the other one long piece, where the triangles
fanned from that piece's ends have their circumcentres beyond it), and scipy's Delaunay
triangulation of a square split along its sides, refined by the points until none is left.
"""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial import Delaunay

from juncture.surface.outside import (
    _circumcentres,
    _first_crossed,
    interior_points,
    outside_splits,
)
from juncture.surface.quality import triangle_angles


@settings(max_examples=50, deadline=None)
@given(st.lists(st.floats(-10.0, 10.0), min_size=6, max_size=6))
def test_a_circumcentre_is_as_far_from_every_corner(xy):
    p = np.array(xy).reshape(1, 3, 2)
    (bx, by), (cx, cy) = p[0, 1] - p[0, 0], p[0, 2] - p[0, 0]
    twice_area = abs(bx * cy - by * cx)
    if twice_area < 1e-3 * max(1.0, np.ptp(p) ** 2):
        return
    c = _circumcentres(p)[0]
    r = np.linalg.norm(p[0] - c, axis=1)
    assert np.allclose(r, r[0], rtol=1e-8)


def test_the_first_segment_crossed_is_the_nearest_along_the_way():
    a = np.array([[1.0, -1.0], [2.0, -1.0], [5.0, 5.0]])
    b = np.array([[1.0, 1.0], [2.0, 1.0], [6.0, 5.0]])
    start, end = np.array([[0.0, 0.0], [0.0, 0.0]]), np.array([[3.0, 0.0], [0.0, 3.0]])
    assert _first_crossed(start, end, a, b).tolist() == [0, -1]


def _fan():
    """A strip 10 long and 0.2 wide: the lower side in 20 pieces, the upper side one piece
    (ids 21 and 22 are its ends: its corners with the lower side's ends), with the
    triangles of a fan from the upper side's ends over the lower points."""
    lower = np.stack([np.linspace(0.0, 10.0, 21), np.zeros(21)], axis=1)
    pts = np.concatenate([lower, [[0.0, 0.2], [10.0, 0.2]]])
    half = 10
    tri = [(i, i + 1, 21) for i in range(half)] + [(i, i + 1, 22) for i in range(half, 20)]
    tri.append((half, 22, 21))
    cons = np.array([(i, i + 1) for i in range(20)] + [(20, 22), (22, 21), (21, 0)])
    # the original edges: the lower side one edge (global 0 -> 1), the upper (2 -> 3), the
    # ends (1 -> 3, 2 -> 0), with the fractions of every piece's ends along them
    t = np.linspace(0.0, 1.0, 21)
    parent = (np.array([0] * 20 + [1, 3, 2]), np.array([1] * 20 + [3, 2, 0]),
              np.concatenate([t[:-1], [0.0, 0.0, 0.0]]), np.concatenate([t[1:], [1.0, 1.0, 1.0]]))
    return pts, np.array(tri), cons, parent


def test_the_long_piece_beyond_a_fan_of_thin_triangles_is_split_at_its_middle():
    pts, tri, cons, parent = _fan()
    got = outside_splits(pts, tri, cons, parent, 25.0, 0.01)
    assert got == [(3, 2, 0.5)]          # the upper side (22 -> 21: original 3 -> 2), halved


def test_a_piece_no_longer_than_twice_the_shortest_edge_is_not_split():
    pts, tri, cons, parent = _fan()
    assert outside_splits(pts, tri, cons, parent, 25.0, 5.0) == []


def test_triangles_that_meet_the_angle_are_left_alone():
    pts, tri, cons, parent = _fan()
    assert outside_splits(pts, tri, cons, parent, 0.1, 0.01) == []   # 0.25 deg its thinnest


def test_no_point_refines_the_fan_beyond_its_long_piece():
    """The fan's circumcentres lie beyond the upper piece: outside the chart, no point."""
    pts, tri, cons, _ = _fan()
    assert interior_points(pts, tri, cons, 25.0, 0.01).shape == (0, 2)


def _square(n, inner):
    """A square of side 1, each side in ``n`` pieces, with the points ``inner`` inside."""
    t = np.arange(n) / n
    side = np.concatenate([np.stack([t, 0 * t], 1), np.stack([1 + 0 * t, t], 1),
                           np.stack([1 - t, 1 + 0 * t], 1), np.stack([0 * t, 1 - t], 1)])
    ring = np.arange(4 * n)
    return np.concatenate([side, inner]), np.stack([ring, np.roll(ring, -1)], 1)


def test_a_sliver_inside_gets_its_circumcentre_and_a_corner_gets_none():
    """Two points close together in the middle of a square make thin triangles; the
    point given for the thinnest is as far from its three corners. A triangle whose
    smallest angle lies between two pieces (here a corner of 10 deg) gets none."""
    pts, cons = _square(4, np.array([[0.5, 0.5], [0.52, 0.5]]))
    tri = Delaunay(pts).simplices
    got = interior_points(pts, tri, cons, 25.0, 1e-3)
    assert len(got)
    r = np.linalg.norm(pts[tri][:, :, None] - got[None, None], axis=3)   # (t, 3, k)
    assert np.all(np.any(np.ptp(r, axis=1) < 1e-9, axis=0))
    wedge = np.array([[0.0, 0.0], [1.0, 0.0], [np.cos(0.1745), np.sin(0.1745)]])
    closed = np.array([[0, 1], [1, 2], [2, 0]])
    assert interior_points(wedge, np.array([[0, 1, 2]]), closed[[0, 2]], 25.0, 1e-3) \
        .shape == (0, 2)


@settings(max_examples=25, deadline=None)
@given(st.integers(3, 12), st.lists(st.tuples(st.floats(0.05, 0.95), st.floats(0.05, 0.95)),
                                    min_size=1, max_size=12))
def test_points_lie_inside_clear_of_every_piece_and_refinement_ends(n, inner):
    """Every point given lies inside the square, outside every piece's diametral circle
    and is a circumcentre of a triangle under the angle; added and triangulated again
    (scipy's Delaunay) until none is given, the refinement ends, with every point apart."""
    pts, cons = _square(n, np.array(inner))
    if len(np.unique(pts.round(9), axis=0)) < len(pts):
        return
    for _ in range(60):
        tri = Delaunay(pts).simplices
        got = interior_points(pts, tri, cons, 20.0, 1e-3)
        if not len(got):
            break
        assert np.all((got > 0) & (got < 1))
        a, b = pts[cons[:, 0]], pts[cons[:, 1]]
        gap = np.linalg.norm(got[:, None] - 0.5 * (a + b)[None], axis=2)
        assert np.all(gap >= 0.5 * np.linalg.norm(b - a, axis=1)[None])
        bad = tri[triangle_angles(pts, tri).min(axis=1) < 20.0]
        r = np.linalg.norm(pts[bad][:, :, None] - got[None, None], axis=3)
        assert np.all(np.any(np.ptp(r, axis=1) < 1e-9, axis=0))
        pts = np.concatenate([pts, got])
    else:
        raise AssertionError("refinement did not end")
    assert np.linalg.norm(pts[:, None] - pts[None], axis=2)[np.triu_indices(len(pts), 1)] \
        .min() > 1e-6
