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
