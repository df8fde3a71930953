"""FilletLines: a fillet line that is one point to round-off is exactly that point."""

import numpy as np

from juncture.fillet.lines import FilletLines


def _lines(points, start, end):
    n = len(points)
    return FilletLines("upper", points, start, end, np.zeros(n), np.zeros(n), np.ones(n),
                       np.zeros(n, bool))


def test_a_degenerate_line_is_its_end_point_bit_for_bit():
    end = np.array([[264.35893575952696, 4.068440400788382, -1.4893155959921163],
                    [250.0, 5.0, 0.5]])
    start = end.copy()
    start[0, 2] = np.nextafter(start[0, 2], 0.0)          # one ulp off, as solved
    start[1] = [249.0, 5.5, 2.0]                            # a real fillet
    s = np.linspace(0.0, 1.0, 5)[:, None]
    pts = start[:, None, :] + s * (end - start)[:, None, :]
    pts[0, 2, 0] = np.nextafter(pts[0, 2, 0], 0.0)
    f = _lines(pts, start, end)
    assert np.array_equal(f.points[0], np.broadcast_to(end[0], (5, 3)))
    assert np.array_equal(f.start[0], end[0])
    assert np.array_equal(f.points[1], pts[1]) and np.array_equal(f.start[1], start[1])


def test_a_line_spread_over_a_few_ulps_is_one_point_and_a_tiny_fillet_is_not():
    """A held-out airplane (seed 9696, draw 37, cubic fillet): a line blended to nothing came
    out spread over 2.1e-13 of a 27 ft coordinate (8 ulps), beyond 16 ulps of the old test;
    its points stayed apart and a cap of no size crossed the wing. Within ONE_POINT of the
    coordinates' size it is the end point; a fillet 1e-6 of that size stays a fillet."""
    end = np.array([[26.564499351143315, 2.380951122852316, 2.1624302920422456],
                    [26.564499351143315, 2.380951122852316, 2.1624302920422456]])
    start = end + [[0.0, -2.084e-13, -1.981e-13], [0.0, -2.7e-5, -2.6e-5]]
    s = np.linspace(0.0, 1.0, 9)[:, None]
    pts = start[:, None, :] + s * (end - start)[:, None, :]
    f = _lines(pts, start, end)
    assert np.array_equal(f.points[0], np.broadcast_to(end[0], (9, 3)))
    assert np.array_equal(f.start[0], end[0])
    assert np.array_equal(f.points[1], pts[1]) and np.array_equal(f.start[1], start[1])
