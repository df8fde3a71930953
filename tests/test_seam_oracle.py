"""The seam oracle (tests/seam_oracle.py) on curves and distances known in closed form."""

import numpy as np
import pytest

from juncture.model import ArbitraryBody, CircularBody, Configuration, WingLike
from tests.seam_oracle import point_triangle_distance, seam_points, surface_distance

R, Z0, CHORD, PCT = 2.0, 0.5, 4.0, 2.5     # cylinder radius, wing height, chord, % thickness
H = PCT / 100.0 * CHORD                     # half-thickness of the slab sections


def _slab(name="wing", kind="wing", le=((0.0, 0.0, Z0), (0.0, 10.0, Z0)), mirrored=True):
    """A wing of constant section: half-thickness H at every chord station."""
    x = [0.0, 30.0, 70.0, 100.0]
    t = np.full((2, 4), PCT)
    return WingLike(name, kind, np.array(le), [CHORD, CHORD], x, t, t, mirrored=mirrored)


def _cylinder(name="body", origin=(0.0, 0.0, 0.0), mirrored=False):
    return CircularBody(name, [-5.0, 10.0], [R, R], origin=origin, mirrored=mirrored)


def _cfg(*comps):
    return Configuration({c.name: c for c in comps})


def test_a_slab_wing_meets_a_cylinder_at_y_squared_plus_z_squared_r_squared():
    pts = seam_points(_cfg(_slab(), _cylinder()), size=20.0)
    assert len(pts) > 100
    for side, z in (("upper", Z0 + H), ("lower", Z0 - H)):
        for image in (False, True):
            m = (pts.side == side) & (pts.image == image)
            p = pts.points[m]
            assert m.sum() == len(pts) // 4
            np.testing.assert_allclose(p[:, 2], z, atol=1e-12)
            sign = -1.0 if image else 1.0
            np.testing.assert_allclose(p[:, 1], sign * np.sqrt(R * R - z * z), atol=1e-12)
            np.testing.assert_allclose(p[:, 0], CHORD * pts.fraction[m], atol=1e-12)
    assert set(pts.branch) == {0}


def test_a_centre_line_fin_on_a_cylinder_has_no_image():
    fin = _slab("fin", "fin", le=((1.0, 0.0, 0.0), (1.0, 0.0, 5.0)), mirrored=False)
    pts = seam_points(_cfg(fin, _cylinder()), size=20.0)
    assert len(pts) and not pts.image.any()
    for side, y in (("upper", H), ("lower", -H)):
        p = pts.points[pts.side == side]
        np.testing.assert_allclose(p[:, 1], y, atol=1e-12)
        np.testing.assert_allclose(p[:, 2], np.sqrt(R * R - y * y), atol=1e-12)


def test_a_box_body_meets_the_wing_on_its_side_wall():
    a = 1.5
    half = [[0.0, -1.0], [a, -1.0], [a, 1.0], [0.0, 1.0]]
    box = ArbitraryBody("body", [-5.0, 10.0], [half, half])
    pts = seam_points(_cfg(_slab(), box), size=20.0)
    assert len(pts) > 100
    np.testing.assert_allclose(np.abs(pts.points[:, 1]), a, atol=1e-12)


def test_a_wing_through_a_pod_meets_it_twice():
    """A pod (mirrored, off the centre line at y = 5) through the wing: an inboard and an
    outboard curve, y = 5 -+ sqrt(R^2 - z^2)."""
    pod = _cylinder("pod", origin=(0.0, 5.0, 0.0), mirrored=True)
    pts = seam_points(_cfg(_slab(), pod), size=20.0)
    up = (pts.side == "upper") & ~pts.image
    root = np.sqrt(R * R - (Z0 + H) ** 2)
    for branch, y in ((0, 5.0 - root), (1, 5.0 + root)):
        p = pts.points[up & (pts.branch == branch)]
        assert len(p) > 50
        np.testing.assert_allclose(p[:, 1], y, atol=1e-12)


def test_a_pylon_short_of_its_pod_counts_only_where_attached():
    """A fin-like pylon whose root section stops above the cylinder: its lofting lines
    continued down meet it only if it is attached there (z = sqrt(R^2 - y^2))."""
    pylon = _slab("pylon", "pylon", le=((1.0, 0.0, 2.5), (1.0, 0.0, 6.0)), mirrored=False)
    cfg = _cfg(pylon, _cylinder())
    assert len(seam_points(cfg, size=20.0)) == 0
    pts = seam_points(cfg, size=20.0, attached={("pylon", "body")})
    assert len(pts) > 100
    np.testing.assert_allclose(pts.points[:, 2], np.sqrt(R * R - H * H), atol=1e-12)


def test_a_fillet_leaves_the_curve_out_between_its_lines():
    """Fillets on the lofting lines at 30 and 70 % chord: only the pieces with no fillet at
    either end remain (none: every piece touches one; the leading and trailing edges' lines,
    where the fillet has shrunk to the intersection point, stay), and on the lower side
    all."""
    fil = np.array([False, True, True, False])
    pts = seam_points(_cfg(_slab(), _cylinder()), size=20.0,
                      fillets={("wing", "body", "upper"): fil})
    assert set(pts.fraction[pts.side == "upper"]) == {0.0, 1.0}
    assert (pts.side == "lower").sum() > 100
    fil = np.array([False, False, True, False])
    pts = seam_points(_cfg(_slab(), _cylinder()), size=20.0,
                      fillets={("wing", "body", "upper"): fil})
    f = pts.fraction[pts.side == "upper"]
    assert f.size > 20 and f[f < 1.0].max() == 0.3 and 1.0 in f


def _faceted_cylinder(n, x=None):
    """An open faceted cylinder: n facets around (vertices on the radius R circle), rings at
    the stations x."""
    x = np.linspace(0.0, 10.0, 7) if x is None else x
    phi = 2.0 * np.pi * np.arange(n) / n
    m = len(x)
    V = np.stack(np.broadcast_arrays(x[:, None], R * np.cos(phi), R * np.sin(phi)),
                 axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(m - 1), np.arange(n), indexing="ij")
    a, b = i * n + j, i * n + (j + 1) % n
    c, d = a + n, b + n
    T = np.concatenate([np.stack([a, b, d], -1).reshape(-1, 3),
                        np.stack([a, d, c], -1).reshape(-1, 3)])
    return V, T


def test_points_on_a_mesh_are_at_distance_zero():
    V, T = _faceted_cylinder(24)
    rng = np.random.default_rng(1)
    w = rng.dirichlet([1.0, 1.0, 1.0], size=500)
    tri = rng.integers(0, len(T), 500)
    inside = np.einsum("nk,nkd->nd", w, V[T[tri]])
    edges = 0.5 * (V[T[:, 0]] + V[T[:, 1]])
    q = np.concatenate([V, inside, edges])
    assert surface_distance(q, V, T).max() < 1e-12


def test_the_sag_of_a_chord_of_a_circle():
    """Exact circle points midway between two facet corners lie R (1 - cos(theta / 2)) from
    the faceted cylinder (theta = 2 pi / n), at every x along it."""
    for n in (12, 64, 720):
        V, T = _faceted_cylinder(n)
        half = np.pi / n
        phi = 2.0 * np.pi * np.arange(n) / n + half
        x = np.linspace(0.3, 9.7, 5)
        q = np.stack(np.broadcast_arrays(x[:, None], R * np.cos(phi), R * np.sin(phi)),
                     axis=-1).reshape(-1, 3)
        d = surface_distance(q, V, T)
        np.testing.assert_allclose(d, R * (1.0 - np.cos(half)), rtol=1e-9, atol=1e-15)


def test_the_kd_tree_finds_the_nearest_triangle():
    """Against every triangle, for points near and far, on a mesh of very unequal
    triangles (a fan of slivers beside large ones)."""
    V, T = _faceted_cylinder(30, x=np.array([0.0, 0.01, 0.03, 4.0, 10.0]))
    V[:, 1:] *= (1.0 + 0.5 * (V[:, 0] > 5.0))[:, None]
    rng = np.random.default_rng(7)
    q = rng.normal(size=(300, 3)) * [6.0, 3.0, 3.0] + [5.0, 0.0, 0.0]
    c = V[T]
    brute = np.array([point_triangle_distance(np.repeat(p[None], len(T), 0), c[:, 0],
                                              c[:, 1], c[:, 2]).min() for p in q])
    np.testing.assert_allclose(surface_distance(q, V, T), brute, rtol=1e-13, atol=1e-15)


def test_point_triangle_distance_regions():
    a, b, c = np.array([[0.0, 0, 0]]), np.array([[1.0, 0, 0]]), np.array([[0.0, 1, 0]])
    cases = [((0.2, 0.2, 0.5), 0.5),              # above the inside
             ((-1.0, -1.0, 0.0), np.sqrt(2.0)),    # beyond the corner a
             ((0.5, -2.0, 1.0), np.sqrt(5.0)),     # beside the edge ab
             ((1.0, 1.0, 0.0), np.sqrt(0.5)),      # beyond the hypotenuse
             ((3.0, 0.0, 0.0), 2.0)]               # beyond the corner b
    for p, want in cases:
        got = point_triangle_distance(np.array([p]), a, b, c)[0]
        assert got == pytest.approx(want, rel=1e-14)
