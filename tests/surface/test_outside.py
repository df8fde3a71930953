"""Boundary pieces split for thin triangles whose circumcentre lies outside the chart.

Oracles: distances (a circumcentre is equidistant from its corners), and a chart drawn by
hand: a thin strip with one side split finely and the other one long piece, where the
triangles fanned from that piece's ends have their circumcentres beyond it.
"""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.surface.outside import _circumcentres, _first_crossed, outside_splits


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
