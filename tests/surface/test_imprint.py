"""A standing component's footprint cut into its host: closed, oriented, exact volume."""

import numpy as np
import pytest

from juncture.surface.assemble import _merge, boundary_loops
from juncture.surface.check import check_mesh
from juncture.surface.imprint import imprint


def _grid_face(origin, du, dv, n):
    """An n x n grid on origin + s du + t dv, triangles oriented along du x dv."""
    s = np.linspace(0.0, 1.0, n)
    pts = origin + s[:, None, None] * du + s[None, :, None] * dv
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    a, b, c, d = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
    tri = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                          np.stack([a, c, d], -1).reshape(-1, 3)])
    return pts.reshape(-1, 3), tri


def _box(n=6, size=4.0, depth=1.0, length=None):
    """The closed box [0, length] x [0, size] x [-depth, 0] (length = size by default),
    outward, every face an n x n grid."""
    o, x, y, z = np.zeros(3), np.array([length or size, 0, 0.]), np.array([0, size, 0.]), \
        np.array([0, 0, depth])
    lo = o - z
    faces = [(o, x, y), (lo, y, x), (lo, x, z), (lo + y, z, x), (lo, z, y), (lo + x, y, z)]
    pts, tri, off = [], [], 0
    for origin, du, dv in faces:
        p, t = _grid_face(origin, du, dv, n)
        pts.append(p)
        tri.append(t + off)
        off += len(p)
    return np.concatenate(pts), np.concatenate(tri)


def _prism(centre, radius, height, k, phase):
    """A k-sided prism standing on z = 0, open at the bottom: (points, triangles, base ids)."""
    a = phase + 2 * np.pi * np.arange(k) / k
    ring = np.stack([centre[0] + radius * np.cos(a), centre[1] + radius * np.sin(a),
                     np.zeros(k)], axis=1)
    top = ring + [0.0, 0.0, height]
    apex = np.array([[centre[0], centre[1], height]])
    pts = np.concatenate([ring, top, apex])
    i = np.arange(k)
    j = (i + 1) % k
    sides = np.concatenate([np.stack([i, j, k + j], 1), np.stack([i, k + j, k + i], 1)])
    cap = np.stack([k + i, k + j, np.full(k, 2 * k)], 1)
    return pts, np.concatenate([sides, cap]), ring


@pytest.mark.parametrize("k, radius, phase", [(12, 0.7, 0.1), (7, 0.23, 0.4), (40, 1.3, 0.0)])
def test_a_prism_imprinted_on_a_box_closes_with_the_exact_volume(k, radius, phase):
    bp, bt = _box()
    pp, pt, ring = _prism((1.93, 2.11), radius, 1.0, k, phase)
    vertices, inverse = _merge(np.concatenate([bp, pp]))
    triangles = inverse[np.concatenate([bt, pt + len(bp)])]
    host = np.r_[np.ones(len(bt), bool), np.zeros(len(pt), bool)]
    loop = inverse[len(bp) + np.arange(k)]
    assert len(boundary_loops(triangles)) == 1        # the prism stands on the box, uncut
    removed, new = imprint(vertices, triangles, host, loop)
    keep = np.ones(len(triangles), bool)
    keep[removed] = False
    out = np.concatenate([triangles[keep], new])
    report = check_mesh(vertices, out)
    assert report.ok, report.failures()
    assert report.euler == (2,)
    # Box plus prism: the polygon's area (shoelace) times the height.
    x, y = ring[:, 0], ring[:, 1]
    base = 0.5 * abs(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))
    assert report.volume == pytest.approx(16.0 + base * 1.0, rel=1e-12)
    # Every edge of the footprint is an edge of the host's new triangles.
    e = {tuple(sorted(p)) for t in new for p in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))}
    assert all(tuple(sorted((loop[i], loop[(i + 1) % k]))) in e for i in range(k))
    # No point is created: the new triangles use the box's and the prism's own vertices.
    assert set(np.unique(new)) <= set(np.unique(triangles))


def test_a_loop_that_folds_over_in_projection_is_refused():
    bp, bt = _box()
    vertices, inverse = _merge(bp)
    triangles = inverse[bt]
    bow = np.array([[1.0, 1.0, 0.0], [2.0, 2.0, 0.0], [2.0, 1.0, 0.0], [1.0, 2.0, 0.0]])
    vertices = np.concatenate([vertices, bow])
    loop = len(vertices) - 4 + np.arange(4)
    assert imprint(vertices, triangles, np.ones(len(triangles), bool), loop) is None


def test_a_footprint_on_long_triangles_whose_centres_lie_far_away():
    """A pylon on a wing whose panels run far along the span: triangles are taken by their
    nearest corner, not their centre, so none under the footprint is left out."""
    bp, bt = _box(n=3, length=200.0)
    pp, pt, ring = _prism((101.3, 2.11), 0.5, 1.0, 9, 0.2)
    vertices, inverse = _merge(np.concatenate([bp, pp]))
    triangles = inverse[np.concatenate([bt, pt + len(bp)])]
    host = np.r_[np.ones(len(bt), bool), np.zeros(len(pt), bool)]
    loop = inverse[len(bp) + np.arange(9)]
    report = _imprinted(vertices, triangles, host, loop)
    assert report.volume == pytest.approx(200.0 * 4.0 + _area(ring), rel=1e-12)


def test_footprints_whose_regions_meet_are_cut_together():
    """Three prisms close together on one face (twin fins either side of the plane of
    symmetry): their regions share triangles, so they are cut in one triangulation."""
    from juncture.surface.imprint import imprint_many

    bp, bt = _box(n=4)
    parts = [_prism(c, 0.3, 1.0, 8, 0.1) for c in ((1.6, 2.0), (2.4, 2.0), (2.0, 2.9))]
    pts = np.concatenate([bp] + [p for p, _, _ in parts])
    tris, loops_local, off = [bt], [], len(bp)
    for p, t, _ in parts:
        tris.append(t + off)
        loops_local.append(off + np.arange(8))
        off += len(p)
    vertices, inverse = _merge(pts)
    triangles = inverse[np.concatenate(tris)]
    host = np.r_[np.ones(len(bt), bool), np.zeros(len(triangles) - len(bt), bool)]
    cuts = imprint_many(vertices, triangles, host, [inverse[lp] for lp in loops_local])
    assert len(cuts) == 1                               # one group
    removed, new = cuts[0]
    keep = np.ones(len(triangles), bool)
    keep[removed] = False
    report = check_mesh(vertices, np.concatenate([triangles[keep], new]))
    assert report.ok, report.failures()
    base = sum(0.5 * abs(np.sum(r[:, 0] * np.roll(r[:, 1], -1) - np.roll(r[:, 0], -1) * r[:, 1]))
               for _, _, r in parts)
    assert report.volume == pytest.approx(16.0 + base, rel=1e-12)


def test_a_footprint_under_slivers_whose_corners_are_all_far_away():
    """A wing given by root and tip only is one strip of slivers that run across the whole
    span, skewed: a footprint in the middle lies under slivers none of whose corners, nor
    centres, come near it. Every one it crosses is cut."""
    # Top face z = 0 of a solid 100 long across, made of long skewed slivers 2 wide.
    n = 21
    xs = np.linspace(0.0, 40.0, n)
    lo = np.stack([xs, np.zeros(n), np.zeros(n)], 1)
    hi = np.stack([xs + 30.0, np.full(n, 100.0), np.zeros(n)], 1)
    top_p = np.concatenate([lo, hi])
    i = np.arange(n - 1)
    top_t = np.concatenate([np.stack([i, i + 1, n + i + 1], 1), np.stack([i, n + i + 1, n + i], 1)])
    # The rest of a closed solid: the prism under that face, its side walls fanned.
    bot_p = top_p - [0.0, 0.0, 1.0]
    pts = np.concatenate([top_p, bot_p])
    m = 2 * n
    bot_t = top_t[:, ::-1] + m
    ring = np.r_[np.arange(n), 2 * n - 1 - np.arange(n)]          # round the face's edge
    a, b = ring, np.roll(ring, -1)
    walls = np.concatenate([np.stack([b, a, a + m], 1), np.stack([b, a + m, b + m], 1)])
    pp, pt, foot = _prism((38.0, 60.0), 1.5, 1.0, 11, 0.3)
    vertices, inverse = _merge(np.concatenate([pts, pp]))
    box_t = np.concatenate([top_t, bot_t, walls])
    triangles = inverse[np.concatenate([box_t, pt + len(pts)])]
    host = np.r_[np.ones(len(box_t), bool), np.zeros(len(pt), bool)]
    loop = inverse[len(pts) + np.arange(11)]
    base = check_mesh(vertices, inverse[box_t])
    assert base.ok, base.failures()
    report = _imprinted(vertices, triangles, host, loop)
    assert report.volume == pytest.approx(base.volume + _area(foot), rel=1e-12)


def test_the_host_of_a_footprint_on_the_four_block_layout_is_both_wing_body_blocks():
    from juncture.surface.imprint import hosts_of

    comps = ("body", "wing-body upper", "wing-body lower", "pod 1", "fin 1")
    assert hosts_of("wing", comps) == (1, 2)
    assert hosts_of("body", comps) == (0, 1, 2)
    assert hosts_of("pod 1", comps) == (3,)
    assert hosts_of("wing", ("body", "wing", "pod 1")) == (1,)


def _imprinted(vertices, triangles, host, loop):
    """check_mesh report of the surface with ``loop`` cut into the ``host`` triangles;
    asserted valid."""
    removed, new = imprint(vertices, triangles, host, loop)
    keep = np.ones(len(triangles), bool)
    keep[removed] = False
    report = check_mesh(vertices, np.concatenate([triangles[keep], new]))
    assert report.ok, report.failures()
    return report


def _area(ring):
    """Shoelace area of a polygon's x, y."""
    x, y = ring[:, 0], ring[:, 1]
    return 0.5 * abs(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def test_a_body_chart_unrolls_the_section_with_its_cut_opposite_the_loops():
    """juncture.surface.imprint.body_chart: x, and the arc round the section centre at the
    body's largest radius, measured from the loops' mean direction (here the top), so a
    region straddling the top (twin fins) unrolls without a cut or a fold."""
    from juncture.model import CircularBody
    from juncture.surface.imprint import body_chart

    body = CircularBody("body", np.linspace(0.0, 50.0, 6), np.r_[0.5, 2.0, 3.0, 3.0, 2.0, 1.0],
                        camber=np.full(6, 0.4))
    theta = np.linspace(-3.0, 3.0, 61) + 0.5 * np.pi          # round from below the left
    x = np.full(theta.size, 25.0)
    pts = body.point(x, theta)
    loops = body.point(np.array([24.0, 26.0]), np.array([0.5 * np.pi - 0.4, 0.5 * np.pi + 0.4]))
    uv = body_chart(body, loops)(pts)
    assert np.array_equal(uv[:, 0], x)
    assert np.allclose(uv[:, 1], 3.0 * (theta - 0.5 * np.pi), atol=1e-12)   # r_max = 3
