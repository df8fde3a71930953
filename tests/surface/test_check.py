"""``juncture check`` and the exact predicates behind it.

Oracles: analytic volumes and Euler characteristics of closed polyhedra; exact rational
arithmetic (fractions) for the orientation signs; for triangle pairs, a linear programme
(scipy.optimize.linprog: is there a common point with barycentric coordinates >= 0 on both?)
on random triangles in general position; trimesh for watertightness and winding. The float
expansion stage of orient3d is checked against its last stage, the integer arithmetic of
``_exact3``, on exactly coplanar points (constructed so that the floats are exact), points
one ulp off such planes, random points and extreme magnitudes.
"""

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.optimize import linprog

from juncture.cli import main
from juncture.surface.check import check_mesh, read_triangles, self_intersections
from juncture.surface.predicates import (
    _exact3,
    _expansion3,
    orient2d,
    orient3d,
    triangles_intersect,
)


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


def _rows(points):
    """(4, n, 3) -> the four (n, 3) arguments of orient3d."""
    return tuple(np.ascontiguousarray(p) for p in points)


def _tilted_dyadic(rng, n, patch):
    """Exactly coplanar p0 + s u + t v in a tilted plane: u, v, s, t with few bits, so every
    float operation is exact; s, t near one another (a mesh patch) or anywhere in [0, 1)."""
    p0, u, v = np.array([[1.5, 2.25, -0.625], [0.75, 0.125, 0.3125], [-0.25, 0.875, 0.4375]])
    if patch:
        par = rng.integers(0, 2**20, (1, n, 2)) / 2**20 + rng.integers(0, 2**6, (4, n, 2)) / 2**30
    else:
        par = rng.integers(0, 2**20, (4, n, 2)) / 2**20
    return p0 + par[..., :1] * u + par[..., 1:] * v


def _tilted_snapped(rng, n):
    """Random floats snapped to grids coarse enough for p0 + s u + t v to be exact."""
    snap = lambda x, bits: np.round(x * 2.0**bits) / 2.0**bits  # noqa: E731
    p0 = snap(rng.uniform(-4, 4, (1, n, 3)), 12)
    u, v = snap(rng.uniform(-1, 1, (2, 1, n, 3)), 20)
    s, t = snap(rng.random((2, 4, n, 1)), 20)
    return p0 + s * u + t * v


def _plane_through_axis(rng, n, scale):
    """Exactly coplanar points (2 y, y, z) on the tilted plane x = 2 y, with coordinates of
    both signs and magnitudes over 4 decades: differences of such floats are mostly not
    floats."""
    y, z = rng.choice([-1.0, 1.0], (2, 4, n)) * 10.0 ** rng.uniform(-4, 0, (2, 4, n)) * scale
    return np.stack([2 * y, y, z], axis=-1)


def _one_ulp_off(rng, points):
    """The points with one coordinate of d moved by one ulp up or down."""
    out = points.copy()
    rows, axis = np.arange(points.shape[1]), rng.integers(0, 3, points.shape[1])
    out[3, rows, axis] = np.nextafter(out[3, rows, axis], rng.choice([-np.inf, np.inf], rows.size))
    return out


def _assert_stage_exact(points, all_decided=True):
    """The expansion stage agrees with _exact3 where it decides (and decides every row,
    unless told), and so does orient3d on every row."""
    args = _rows(points)
    want = _exact3(*args)
    sign, decided = _expansion3(*args)
    np.testing.assert_array_equal(sign[decided], want[decided])
    if all_decided:
        assert decided.all()
    np.testing.assert_array_equal(orient3d(*args), want)
    return want, decided


@pytest.mark.parametrize("patch", [True, False])
def test_expansion_stage_decides_exactly_coplanar_tilted_planes(patch):
    rng = np.random.default_rng(21)
    want, _ = _assert_stage_exact(_tilted_dyadic(rng, 3000, patch))
    assert not want.any()
    want, _ = _assert_stage_exact(_tilted_snapped(rng, 3000))
    assert not want.any()


def _inexact_differences(points):
    """(n,) bool: some difference of a, b, c and d is not a float (independently: fsum)."""
    a, d = points[:3], points[3]
    return np.array([any(math.fsum([p, -q, -(p - q)]) != 0 for p, q in
                         zip(a[:, i].ravel(), np.tile(d[i], 3))) for i in range(len(d))])


def test_inexact_differences_are_left_to_exact3():
    # Coplanar points across the coordinate planes (inexact differences) mixed with a patch
    # of a tilted plane (exact ones): stage 2 takes exactly the latter.
    rng = np.random.default_rng(22)
    for scale in (1e-3, 1.0, 1e250, 1e-250):
        patch = np.ldexp(_tilted_dyadic(rng, 300, True), round(math.log2(scale)))
        points = np.concatenate([_plane_through_axis(rng, 300, scale), patch], axis=1)
        for pts in (points, _one_ulp_off(rng, points)):
            want, decided = _assert_stage_exact(pts, all_decided=False)
            inexact = _inexact_differences(pts)
            assert inexact[:300].mean() > 0.9 and not inexact[300:].any()
            np.testing.assert_array_equal(decided, ~inexact)
            assert pts is not points or not want.any()


def test_expansion_stage_one_ulp_off_the_plane_and_at_random():
    rng = np.random.default_rng(23)
    want, _ = _assert_stage_exact(_one_ulp_off(rng, _tilted_dyadic(rng, 3000, True)))
    assert np.count_nonzero(want) > 2950  # but for a few degenerate ones (a, b, c collinear)
    # one ulp off the snapping grid: some differences across 0 become inexact
    _assert_stage_exact(_one_ulp_off(rng, _tilted_snapped(rng, 3000)), all_decided=False)
    want, _ = _assert_stage_exact(rng.random((4, 3000, 3)))
    assert np.all(want != 0)


def test_extreme_magnitudes_and_the_rows_left_to_exact3():
    rng = np.random.default_rng(24)
    for k in (990, -1000):  # tilted planes scaled by 2**k (exact; subnormals for -1000)
        points = np.ldexp(_tilted_dyadic(rng, 1000, True), k)
        want, _ = _assert_stage_exact(points)
        assert not want.any()
        _assert_stage_exact(_one_ulp_off(rng, points))
    for scale in (1e300, 1e-300, 1e-107, 1e-160):  # overflow and underflow in the filter
        _assert_stage_exact(rng.random((4, 2000, 3)) * scale, all_decided=False)
    # Differences spanning more than 2**280 in a row, or overflowing: left to _exact3.
    wide = rng.choice([-1.0, 1.0], (4, 2000, 3)) * 10.0 ** rng.uniform(-300, 300, (4, 2000, 3))
    _, decided = _assert_stage_exact(wide, all_decided=False)
    assert decided.mean() < 0.01
    huge = rng.choice([-1.0, 1.0], (4, 2000, 3)) * 1.7e308
    _, decided = _assert_stage_exact(huge, all_decided=False)
    assert decided.mean() < 0.01
    far = np.array([[[1.0, 0, 0]], [[0, 1e-90, 0]], [[0, 0, 1.0]], [[0, 0, 0]]])
    want, decided = _assert_stage_exact(far, all_decided=False)
    assert want[0] == 1 and not decided[0]  # 1e-90 < 2**-280: left to _exact3
    # inf and nan are not points: the filter's answer, no exact stage
    bad = np.array([[[np.nan, 0, 0]], [[0, 1.0, 0]], [[0, 0, 1.0]], [[0, 0, 0]]])
    assert orient3d(*_rows(bad))[0] == 0


_COORD = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False)


@settings(max_examples=100, deadline=None)
@given(arrays(np.float64, (4, 8, 2), elements=_COORD), st.integers(0, 3),
       st.permutations([0, 1, 2]), st.booleans(), st.integers(0, 2**32 - 1))
def test_expansion_stage_matches_exact3_on_generated_planes(yz, k, axes, off, seed):
    # Points (2**k y, y, z) with their axes permuted: exactly coplanar, any floats (0,
    # subnormals, wide ranges; 2**k y is exact); or one ulp off that plane.
    points = np.concatenate([np.ldexp(yz[..., :1], k), yz], axis=-1)[..., axes]
    if off:
        points = _one_ulp_off(np.random.default_rng(seed), points)
    want, _ = _assert_stage_exact(points, all_decided=False)
    assert off or not want.any()


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


def _box_pairs_brute(v, tri):
    p = v[tri]
    lo, hi = p.min(axis=1), p.max(axis=1)
    ov = np.all((lo[:, None] <= hi[None]) & (lo[None] <= hi[:, None]), axis=2)
    i, j = np.nonzero(np.triu(ov, 1))
    return set(zip(i.tolist(), j.tolist()))


@pytest.mark.parametrize("seed", range(4))
def test_candidate_pairs_are_every_overlapping_box_pair_once(seed):
    # Oracle: every pair of boxes compared directly. The soup mixes sizes over four orders
    # of magnitude (long triangles among small ones, a uniform grid's worst case), with
    # duplicates and degenerate (zero-area, zero-extent) triangles.
    from juncture.surface.check import _candidate_pairs

    rng = np.random.default_rng(seed)
    n = 700
    centre = rng.uniform(-10.0, 10.0, (n, 1, 3))
    size = 10.0 ** rng.uniform(-3.0, 1.0, (n, 1, 1))
    v = (centre + size * rng.normal(size=(n, 3, 3))).reshape(-1, 3)
    v[:30] = v[30:60]                                 # coincident points
    tri = np.arange(3 * n).reshape(n, 3)
    tri[-5:] = tri[:5]                                # repeated triangles
    tri[-10:-5, 2] = tri[-10:-5, 1]                   # degenerate ones
    got = _candidate_pairs(v, tri)
    assert np.all(got[:, 0] < got[:, 1])
    assert len(np.unique(got, axis=0)) == len(got)
    assert set(map(tuple, got.tolist())) == _box_pairs_brute(v, tri)
    assert _candidate_pairs(v, tri[:1]).shape == (0, 2)


@pytest.mark.parametrize("seed, n_few", [(0, 1), (1, 3), (2, 40), (3, 350)])
def test_box_pairs_of_two_sets_are_every_overlapping_pair_once(seed, n_few):
    # Oracle: every box of one set compared with every box of the other; sets of very
    # different sizes (a few triangles without mirror images against half a surface).
    from juncture.surface.check import _box_pairs

    rng = np.random.default_rng(seed)
    n = 700
    centre = rng.uniform(-10.0, 10.0, (n, 1, 3))
    size = 10.0 ** rng.uniform(-3.0, 1.0, (n, 1, 1))
    v = (centre + size * rng.normal(size=(n, 3, 3))).reshape(-1, 3)
    tri = np.arange(3 * n).reshape(n, 3)
    ids = rng.permutation(n)
    few, many = np.sort(ids[:n_few]), np.sort(ids[n_few:])
    got = _box_pairs(v, tri, few, many)
    every = _box_pairs_brute(v, tri)
    want = {(i, j) for i, j in every if (i in set(few.tolist())) != (j in set(few.tolist()))}
    assert len(np.unique(got, axis=0)) == len(got) and np.all(got[:, 0] < got[:, 1])
    assert set(map(tuple, got.tolist())) == want and want
    assert _box_pairs(v, tri, few[:0], many).shape == (0, 2)


def _panel(rng, n, jitter):
    """n triangles, three points each, on the tilted plane p0 + s u + t v (exact dyadic
    floats), optionally moved off it by up to ``jitter``."""
    p0, u, v = np.array([[1.5, 2.25, -0.625], [0.75, 0.125, 0.3125], [-0.25, 0.875, 0.4375]])
    st = rng.integers(0, 2**12, (n, 1, 2)) / 2**12 + rng.integers(-2**6, 2**6, (n, 3, 2)) / 2**14
    pts = p0 + st[..., :1] * u + st[..., 1:] * v
    return pts + jitter * rng.normal(size=pts.shape)


@pytest.mark.parametrize("jitter", [0.0, 1e-12, 1e-3])
def test_the_float_separation_tests_never_separate_triangles_that_meet(jitter):
    # Oracle: the exact predicates. Triangles in one tilted plane (and just off it), no
    # vertex shared, then fans sharing one vertex: where the float test says apart, the
    # exact test finds no contact; and it takes most pairs off the exact path.
    from juncture.surface.check import _apart, _apart_at, _one_shared

    rng = np.random.default_rng(31)
    a, b = _panel(rng, 4000, jitter), _panel(rng, 4000, jitter)
    c = _panel(rng, 4000, 0.0)
    b = b - b[:, :1] + a[:, :1] + 2.0 * (c[:, 1:2] - c[:, :1])   # near a: some meet
    apart = _apart(a, b)
    assert not triangles_intersect(a[apart], b[apart]).any()
    meet = triangles_intersect(a, b)
    assert 0 < meet.sum()
    if jitter < 1e-9:  # (nearly) one plane: the test is tried, and takes most pairs
        assert apart.sum() > 0.5 * (~meet).sum()
    # fans: triangles (s, p, q) and (s, r, w) around one shared vertex s
    n = 4000
    one, two = _panel(rng, n, jitter), _panel(rng, n, jitter)
    two = two - two[:, :1] + one[:, :1]        # the second fan's corner moved onto s
    v = np.concatenate([one[:, 0], one[:, 1], one[:, 2], two[:, 1], two[:, 2]])
    ids = np.arange(n)
    ta = np.stack([ids, ids + n, ids + 2 * n], axis=1)
    tb = np.stack([ids, ids + 3 * n, ids + 4 * n], axis=1)
    shared = ta[:, :, None] == tb[:, None, :]
    apart = _apart_at(v, ta, tb, shared)
    if apart.any():
        assert not _one_shared(v, ta[apart], tb[apart], shared[apart]).any()
    if jitter < 1e-9:
        assert apart.sum() > 0.2 * n


def test_triangles_in_one_plane_overlapping_at_a_shared_corner_intersect():
    # Oracle: the triangles' areas. Two triangles in one plane (a tilted one and z = 0)
    # around a shared corner overlap beyond it exactly when their angles at it overlap;
    # a fan whose triangles only touch along no edge is clean.
    for rot in (np.eye(3), np.array([[0.6, 0.0, 0.8], [0.0, 1.0, 0.0], [-0.8, 0.0, 0.6]])):
        v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 0.25, 0], [0.25, 1, 0],
                      [-1, 0.5, 0], [-1, -1, 0]], float) @ rot.T
        over = self_intersections(v, np.array([[0, 1, 2], [0, 3, 4]]))  # inside a's angle
        assert len(over) == 1
        apart = self_intersections(v, np.array([[0, 1, 2], [0, 5, 6]]))  # beside it
        assert len(apart) == 0
        along = self_intersections(v, np.array([[0, 1, 2], [0, 6, 1]]))  # share edge 0-1
        assert len(along) == 0


def test_the_integer_stage_takes_rows_in_blocks_with_the_same_signs(monkeypatch):
    """Python integers take a few hundred bytes each: 570,000 nearly coplanar rows of a
    held-out airplane's check (seed 9797, draw 3, cubic fillet) ran out of memory at once.
    The integer stage runs in blocks of rows; its signs are Fraction determinants' (the
    oracle), in blocks of 7 rows as in one."""
    import juncture.surface.predicates as pred

    rng = np.random.default_rng(7)
    base = rng.normal(size=(50, 3)) * 100.0
    u, v = rng.normal(size=(2, 50, 3))
    a, b, c = base, base + u, base + v
    d = base + 0.3 * u + 0.6 * v + rng.choice([-1e-13, 0.0, 1e-13], size=(50, 1)) * \
        np.cross(u, v)

    def oracle(p, q, r, s):
        m = [[Fraction(x) - Fraction(y) for x, y in zip(row, s)] for row in (p, q, r)]
        det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
               - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
               + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
        return (det > 0) - (det < 0)
    want = [oracle(*rows) for rows in zip(a, b, c, d)]
    whole = _exact3(a, b, c, d)
    monkeypatch.setattr(pred, "_BLOCK", 7)
    assert np.array_equal(pred._exact3(a, b, c, d), whole)
    assert whole.tolist() == want
    assert np.array_equal(pred._exact2(a[:, :2], b[:, :2], c[:, :2]),
                          [oracle([*p, 0.0], [*q, 0.0], [0.0, 0.0, 1.0], [*r, 0.0])
                           for p, q, r in zip(a[:, :2], b[:, :2], c[:, :2])])


def test_candidate_pairs_are_tested_in_blocks_with_the_same_result(monkeypatch):
    """A strip zipped across a wing (held-out seed 1111, draw 13, cubic fillet) gave 40
    million candidate pairs, and testing them at once ran out of memory. They are tested in
    blocks of PAIR_BLOCK: the same intersecting pairs (oracle: the whole set at once) for
    blocks of 5 pairs, on two cubes that overlap and one apart."""
    import juncture.surface.check as chk

    v, t = joined(cube(), cube(centre=(0.5, 0.3, 0.2)), cube(centre=(3.0, 0.0, 0.0)))
    whole = chk.self_intersections(v, t)
    assert len(whole) > 5
    monkeypatch.setattr(chk, "PAIR_BLOCK", 5)
    blocks = chk.self_intersections(v, t)
    assert np.array_equal(np.sort(blocks, axis=0), np.sort(whole, axis=0))
    assert {tuple(p) for p in blocks.tolist()} == {tuple(p) for p in whole.tolist()}
