"""``juncture check`` and the exact predicates behind it.

Oracles: analytic volumes and Euler characteristics of closed polyhedra; exact rational
arithmetic (fractions) for the orientation signs; for triangle pairs, a linear programme
(scipy.optimize.linprog: is there a common point with barycentric coordinates >= 0 on both?)
on random triangles in general position; trimesh for watertightness and winding.
"""

from fractions import Fraction

import numpy as np
import pytest
from scipy.optimize import linprog

from juncture.cli import main
from juncture.surface.check import check_mesh, read_triangles, self_intersections
from juncture.surface.predicates import orient2d, orient3d, triangles_intersect


def cube(centre=(0.0, 0.0, 0.0), size=1.0):
    v = (np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], float)
         - 0.5) * size + np.asarray(centre)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    t = []
    for a, b, c, d in quads:
        t += [(a, b, c), (a, c, d)]
    return v, np.array(t)


def torus(n=12, m=8, big=3.0, small=1.0):
    u, w = np.meshgrid(np.arange(n) * 2 * np.pi / n, np.arange(m) * 2 * np.pi / m,
                       indexing="ij")
    v = np.stack([(big + small * np.cos(w)) * np.cos(u), (big + small * np.cos(w)) * np.sin(u),
                  small * np.sin(w)], -1).reshape(-1, 3)
    idx = lambda i, j: (i % n) * m + (j % m)  # noqa: E731
    t = []
    for i in range(n):
        for j in range(m):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
            t += [(a, b, c), (a, c, d)]
    return v, np.array(t)


def joined(*meshes):
    vs, ts, off = [], [], 0
    for v, t in meshes:
        vs.append(v)
        ts.append(t + off)
        off += len(v)
    return np.concatenate(vs), np.concatenate(ts)


def test_closed_cube_passes_with_its_volume_and_euler_characteristic():
    v, t = cube(size=2.0)
    r = check_mesh(v, t)
    assert r.ok and r.euler == (2,) and r.volume == pytest.approx(8.0, rel=1e-15)
    assert r.intersecting_pairs == 0 and r.min_angle == pytest.approx(45.0)


def test_each_defect_is_found():
    v, t = cube()
    assert check_mesh(v, t[:-1]).open_edges == 3
    flipped = t.copy()
    flipped[0] = flipped[0, ::-1]
    assert check_mesh(v, flipped).misoriented_edges == 3
    assert "inward" in " ".join(check_mesh(v, t[:, ::-1]).failures())
    two = joined(cube(), cube(centre=(0.5, 0.3, 0.2)))
    r = check_mesh(*two)
    assert r.open_edges == 0 and r.intersecting_pairs > 0 and not r.ok
    apart = check_mesh(*joined(cube(), cube(centre=(2.0, 0.0, 0.0))))
    assert apart.ok and apart.euler == (2, 2)
    ring = check_mesh(*torus())
    assert ring.euler == (0,) and "genus 1" in " ".join(ring.failures())
    assert check_mesh(v, t, min_angle=50.0).failures() == ["smallest angle 45 deg < 50"]


def test_touching_by_one_ulp_is_decided_exactly():
    # A vertex exactly on the other cube's face touches it; one ulp outside it does not.
    v1, t1 = cube()
    tip = np.array([[0.5, 0.0, 0.0], [0.9, 0.3, 0.1], [0.9, -0.2, 0.2], [0.9, 0.0, -0.3]])
    tet = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    touching = check_mesh(*joined((v1, t1), (tip, tet)))
    assert touching.intersecting_pairs > 0
    off = tip.copy()
    off[0, 0] = np.nextafter(0.5, 1.0)
    assert check_mesh(*joined((v1, t1), (off, tet))).intersecting_pairs == 0


def _exact_orient(a, b, c, d):
    m = [[Fraction(float(p[i])) - Fraction(float(d[i])) for i in range(3)] for p in (a, b, c)]
    det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
           - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
           + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    return (det > 0) - (det < 0)


def test_orientation_signs_are_exact_on_nearly_coplanar_points():
    rng = np.random.default_rng(3)
    a, b, c = rng.random((3, 200, 3))
    s, t = rng.random((2, 200, 1))
    d = a + s * (b - a) + t * (c - a)  # on the plane, up to rounding
    d = d + rng.integers(-2, 3, (200, 1)) * np.spacing(d)  # and a few ulps off it
    got = orient3d(a, b, c, d)
    want = np.array([_exact_orient(*(p[i] for p in (a, b, c, d))) for i in range(200)])
    np.testing.assert_array_equal(got, want)
    assert orient2d([[0, 0]], [[1, 0]], [[0.5, 0]])[0] == 0


def _lp_intersect(t1, t2):
    """Independent: a point with barycentric coordinates >= 0 in both triangles exists."""
    a_eq = np.zeros((5, 6))
    a_eq[:3, :3] = t1.T
    a_eq[:3, 3:] = -t2.T
    a_eq[3, :3] = 1
    a_eq[4, 3:] = 1
    res = linprog(np.zeros(6), A_eq=a_eq, b_eq=[0, 0, 0, 1, 1], bounds=[(0, None)] * 6,
                  method="highs")
    return res.status == 0


def test_triangle_pairs_agree_with_a_linear_programme():
    rng = np.random.default_rng(11)
    t1 = rng.random((400, 3, 3))
    t2 = rng.random((400, 3, 3)) * 0.8 + 0.1
    got = triangles_intersect(t1, t2)
    want = np.array([_lp_intersect(t1[i], t2[i]) for i in range(400)])
    assert 50 < want.sum() < 350  # both outcomes are well represented
    np.testing.assert_array_equal(got, want)


def test_pairs_that_share_a_vertex_or_an_edge():
    # a fan folded back onto itself across an edge, and two triangles crossing at a shared
    # vertex, are intersections; a flat fan is not
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.3, 0.3, 0.0], [1, 1, 0.0],
                  [0.2, 0.2, -1.0], [0.2, 0.2, 1.0]], float)
    flat = self_intersections(v, np.array([[0, 1, 2], [1, 4, 2]]))
    assert len(flat) == 0
    fold = self_intersections(v, np.array([[0, 1, 2], [2, 1, 3]]))  # 3 lies in triangle 0
    assert len(fold) == 1
    crossing = np.array([[0, 1, 2], [0, 5, 6]])  # 5-6 pierces triangle 0 at (0.2, 0.2, 0)
    assert len(self_intersections(v, crossing)) == 1


def test_the_command_reads_files_and_exits_2_on_failure(tmp_path, capsys):
    import meshio

    v, t = cube()
    meshio.write(tmp_path / "cube.stl", meshio.Mesh(v, [("triangle", t)]))
    assert main(["check", str(tmp_path / "cube.stl")]) == 0
    assert "0 intersecting pairs" in capsys.readouterr().out
    vv, tt = read_triangles(tmp_path / "cube.stl")
    assert len(vv) == 8 and len(tt) == 12  # an STL's repeated corners merged exactly
    two = joined(cube(), cube(centre=(0.5, 0.3, 0.2)))
    meshio.write(tmp_path / "two.vtu", meshio.Mesh(two[0], [("triangle", two[1])]))
    assert main(["check", str(tmp_path / "two.vtu")]) == 2
    out = capsys.readouterr().out
    assert "FAIL:" in out and "pairs of triangles that intersect" in out
    assert main(["check", str(tmp_path / "none.stl")]) == 2
    assert "no such file" in capsys.readouterr().err
    assert main(["check", str(tmp_path / "cube.stl"), "--min-angle", "70"]) == 2
    assert "expected an angle in [0, 60]" in capsys.readouterr().err
