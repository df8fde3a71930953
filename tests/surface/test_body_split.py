"""The fuselage's upper and lower blocks (surface/body_split.py) meet on one line."""

import numpy as np

from juncture.model import CircularBody
from juncture.surface.body_split import Boundary, split_body


def _keys(points):
    return {tuple(p) for p in (np.asarray(points) + 0.0).tolist()}


def test_upper_and_lower_blocks_carry_the_same_points_where_they_meet():
    """A fin on the fuselage aft of the wing adds stations to the upper block; outside the
    wing's region the lower block ends on the same line, so it takes them too: every point
    of either block on that line is a point of the other (else the seam stays open)."""
    body = CircularBody("body", np.linspace(0.0, 100.0, 11),
                        np.r_[0.0, 3.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 3.5, 2.5, 1.0])
    # The wing's region from x = 30 to 55 (one line each side, sharp edges: common ends),
    # a fin from x = 71.3 to 88.7 on top.
    xs = np.array([30.0, 37.1, 44.9, 55.0])
    upper = Boundary(xs, np.array([-0.1, 0.05, 0.02, -0.1]))
    lower = Boundary(xs, np.array([-0.1, -0.3, -0.25, -0.1]))
    fin = Boundary(np.array([71.3, 76.9, 83.3, 88.7]), np.full(4, 1.45))
    nets = split_body(body, [upper], [lower], fins=[fin])
    up, lo = nets["body upper"][:, -1], nets["body lower"][:, -1]
    outside = lambda p: p[(p[:, 0] < 30.0) | (p[:, 0] > 55.0)]  # noqa: E731
    assert _keys(outside(up)) == _keys(outside(lo))
    assert {71.3, 76.9, 83.3, 88.7} <= {p[0] for p in _keys(outside(lo))}
