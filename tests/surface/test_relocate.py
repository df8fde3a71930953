"""juncture.surface.relocate: a grid point past which a followed seam bulges moves off it.

The patches are flat (z = 0) or a cylinder, so the oracles are plane geometry and the
cylinder's radius: a set of triangles covers a polygon once, with no fold and no overlap,
when every one turns the same way, their areas add up to the polygon's (shoelace) and no
edge is in more than two; a point on the cylinder has y^2 + z^2 = R^2.
"""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.surface.assemble import SurfaceMesh
from juncture.surface.relocate import _kernel_centre, _onto, free_vertices, normals, relocate
from juncture.surface.seam_curves import SeamCurves, _fanned

#: The patch's rim, counter-clockwise (x, y): the seam edge a-b is its lower side, from
#: (0, 0) to (1, 0) (the wing's side lies below it).
RIM = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 0.5], [0.75, 0.7], [0.5, 0.75],
                [0.25, 0.7], [0.0, 0.5]])
C = len(RIM)                      # the grid point just above the seam edge
D = C + 1                         # the wing side's point under it


def _plane(p):
    """The host's error function: signed distance from the plane z = 0."""
    return np.asarray(p, float)[..., 2]


def _patch(cx, h, y0=0.0):
    """(points (n, 3), triangles): the rim, a grid point c = (cx, h) joined to every rim
    point, and the wing-side point (0.5, -0.5) under the seam edge (triangle b-a-d), all
    shifted by ``y0`` in y."""
    pts = np.concatenate([RIM, [[cx, h], [0.5, -0.5]]])
    pts = np.column_stack([pts[:, 0], pts[:, 1] + y0, np.zeros(len(pts))])
    tri = [[i, (i + 1) % C, C] for i in range(C)] + [[1, 0, D]]
    return pts, np.array(tri)


def _arc(s, k, y0=0.0):
    """(fractions, points): ``k`` points of the seam edge's curve, an arc rising ``s``
    above the chord at its middle."""
    t = np.arange(1, k + 1) / (k + 1.0)
    return t, np.column_stack([t, 4.0 * s * t * (1.0 - t) + y0, np.zeros(k)])


def _covered(points, tri, rim):
    """Whether the triangles cover the polygon ``rim`` (k, 2) once."""
    n = normals(points, tri)[:, 2]
    x, y = rim[:, 0], rim[:, 1]
    area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    _, uses = np.unique(edges, axis=0, return_counts=True)
    return bool(np.all(n > 0) and np.isclose(0.5 * n.sum(), area, rtol=1e-12)
                and uses.max() <= 2)


def _mesh(points, tri):
    k = len(tri)
    return SurfaceMesh(points, tri, np.zeros(k, int), np.zeros(k, int), ("body",), ("body",))


def _curves(points, on):
    """SeamCurves with one curve on the plane through the vertices ``on``."""
    mask = np.zeros(len(points), bool)
    mask[on] = True
    return SeamCurves(points, [(None, "upper", _plane, np.ones(3), mask)], 1.0)


@settings(max_examples=60, deadline=None)
@given(cx=st.floats(0.3, 0.7), h=st.floats(0.01, 0.08), over=st.floats(1.5, 3.0),
       k=st.integers(3, 15))
def test_the_grid_point_under_the_bulge_moves_off_it(cx, h, over, k):
    pts, tri = _patch(cx, h)
    t, arc = _arc(min(over * h, 0.2), k)
    mesh = _mesh(pts, tri)
    free = free_vertices(mesh, fixed=np.arange(len(pts)) != C)
    out = _fanned(mesh, {(0, 1): (t, arc)}, {}, free, _curves(pts, [0, 1]))
    # the curve's points are all in the mesh, the grid point stays on the plane, above the
    # curve, and the triangles cover the rim and the wing side's triangle once
    np.testing.assert_array_equal(out.vertices[len(pts):], arc)
    moved = out.vertices[C]
    assert moved[2] == 0.0 and moved[1] > 4.0 * min(over * h, 0.2) * moved[0] * (1 - moved[0])
    rim = np.concatenate([[[0.5, -0.5]], RIM[1:], RIM[:1]])
    assert _covered(out.vertices, out.triangles, rim)


def test_a_fixed_grid_point_keeps_the_chord():
    """The counterfactual: where the grid point may not move (on a line), the fan would
    turn over, and the edge keeps its chord, as before."""
    pts, tri = _patch(0.5, 0.02)
    t, arc = _arc(0.1, 7)
    mesh = _mesh(pts, tri)
    curves = _curves(pts, [0, 1])
    assert _fanned(mesh, {(0, 1): (t, arc)}, {}, np.zeros(len(pts), bool), curves) is mesh
    moved = _fanned(mesh, {(0, 1): (t, arc)}, {}, free_vertices(mesh), curves)
    assert len(moved.vertices) == len(pts) + 7


def test_a_grid_point_off_the_host_stays():
    """A grid point that does not lie on the curve's host (the wing's beside a fuselage
    curve; here the host is the plane z = 0 and the point stands 0.01 above it) is not
    taken onto the host: the edge keeps its chord."""
    pts, tri = _patch(0.5, 0.02)
    pts[C, 2] = 0.01
    t, arc = _arc(0.1, 7)
    mesh = _mesh(pts, tri)
    out = _fanned(mesh, {(0, 1): (t, arc)}, {}, free_vertices(mesh), _curves(pts, [0, 1]))
    assert out is mesh


def test_a_point_and_its_mirror_image_move_together():
    """A patch and its mirror image in y = 0 (turned so that both face +z): both grid
    points move, to mirror images bit for bit."""
    p1, t1 = _patch(0.4, 0.03, y0=1.0)
    p2 = p1 * [1.0, -1.0, 1.0]
    pts, tri = np.concatenate([p1, p2]), np.concatenate([t1, t1[:, ::-1] + len(p1)])
    n = len(pts)
    _, arc = _arc(0.1, 9, y0=1.0)
    xyz = np.concatenate([pts, arc, arc * [1.0, -1.0, 1.0]])
    # the fans as _fanned makes them: each seam edge's triangle from its far corner
    chain = np.r_[0, np.arange(n, n + 9), 1]
    image = np.r_[len(p1), np.arange(n + 9, n + 18), len(p1) + 1]
    fans = np.concatenate([np.stack([chain[:-1], chain[1:], np.full(10, C)], axis=1),
                           np.stack([image[1:], image[:-1], np.full(10, len(p1) + C)], axis=1)])
    seam = [0, len(t1)]
    keep = np.setdiff1d(np.arange(len(tri)), seam)
    out = np.concatenate([tri[keep], fans])
    src = np.concatenate([keep, np.full(10, seam[0]), np.full(10, seam[1])])
    ref = normals(pts, tri)[src]
    assert np.any(np.einsum("ij,ij->i", normals(xyz, out), ref) <= 0)
    moved = relocate(xyz, out, ref, free_vertices(_mesh(pts, tri)), n,
                     lambda q, p: (_plane, np.ones(3)))
    assert np.all(np.einsum("ij,ij->i", normals(moved, out), ref) > 0)
    assert not np.array_equal(moved[C], xyz[C])
    np.testing.assert_array_equal(moved[len(p1) + C], moved[C] * [1.0, -1.0, 1.0])


@settings(max_examples=40, deadline=None)
@given(x=st.floats(-5, 5), y=st.floats(0.5, 3.0), z=st.floats(-3.0, 3.0),
       radius=st.floats(1.0, 4.0))
def test_a_moved_point_is_taken_onto_a_cylinder_in_its_station(x, y, z, radius):
    def error(p):
        p = np.asarray(p, float)
        return np.hypot(p[..., 1], p[..., 2]) - radius
    q = _onto(error, np.ones(3), np.array([x, y, z]), 10.0)
    assert q is not None and q[0] == x
    assert abs(np.hypot(q[1], q[2]) - radius) <= 1e-12 * radius
    np.testing.assert_allclose(q[1:] / np.hypot(q[1], q[2]),
                               np.array([y, z]) / np.hypot(y, z), atol=1e-9)


@settings(max_examples=40, deadline=None)
@given(k=st.integers(3, 12), r=st.floats(0.1, 10.0), cx=st.floats(-5, 5), cy=st.floats(-5, 5))
def test_the_kernel_centre_of_a_regular_polygon_is_its_centre(k, r, cx, cy):
    t = 2 * np.pi * np.arange(k) / k
    uv = np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])
    np.testing.assert_allclose(_kernel_centre(uv), [cx, cy], atol=1e-9 * (r + 10))


def test_a_polygon_no_point_sees_whole_has_no_kernel_centre():
    """A C opening to the right: a point that sees the inside of both arms would lie
    below the lower arm's inner edge (y <= 1) and above the upper's (y >= 2). A 4 x 3
    rectangle's centre line, y = 1.5, is 1.5 from its long sides."""
    c_shape = np.array([[0, 0], [4, 0], [4, 1], [1, 1], [1, 2], [4, 2], [4, 3], [0, 3]],
                       float)
    assert _kernel_centre(c_shape) is None
    box = np.array([[0, 0], [4, 0], [4, 3], [0, 3]], float)
    np.testing.assert_allclose(_kernel_centre(box)[1], 1.5)
