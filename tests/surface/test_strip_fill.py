"""Points inside a thin strip where its zip leaves slivers (juncture.surface.strip_fill).

Oracles: the strip's polygon drawn in its own plane before it is turned into 3-D (its
shoelace area, matplotlib's point-in-polygon test), edge counts of the triangulation, and
triangle angles from the law of cosines."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.path import Path

from juncture.surface.assemble import zip_strip
from juncture.surface.strips import FILL, _filled


def _angles(p):
    """(m, 3) angles [deg] of triangles p (m, 3, 3), law of cosines."""
    a = np.linalg.norm(p[:, 1] - p[:, 2], axis=1)
    b = np.linalg.norm(p[:, 2] - p[:, 0], axis=1)
    c = np.linalg.norm(p[:, 0] - p[:, 1], axis=1)
    ca = np.clip((b * b + c * c - a * a) / (2 * b * c), -1, 1)
    cb = np.clip((a * a + c * c - b * b) / (2 * a * c), -1, 1)
    A, B = np.degrees(np.arccos(ca)), np.degrees(np.arccos(cb))
    return np.stack([A, B, 180.0 - A - B], axis=1)


@st.composite
def strips(draw):
    """A flat strip 1 long and w wide (its sides x -> (x, 0) and (x, w(x)), tapering or not),
    one side with a run of close points beside a rung end or in its middle, turned and
    moved into 3-D: (2-D points, 3-D points, side a ids, side b ids)."""
    w0 = draw(st.floats(0.02, 0.15))
    w1 = w0 * draw(st.floats(0.5, 1.0))
    coarse = draw(st.floats(1.0, 2.7))
    fine = draw(st.floats(0.05, 0.3))
    run = draw(st.integers(2, 10))
    at = draw(st.sampled_from([0.0, 0.4]))

    def width(x):
        return w0 + (w1 - w0) * x

    def side(step):
        xs, x = [0.0], 0.0
        while x < 1.0:
            x = min(1.0, x + step(x))
            xs.append(x)
        if xs[-1] - xs[-2] < 0.3 * step(xs[-2]):    # no remainder of almost no length
            del xs[-2]
        return np.array(xs)

    xa = side(lambda x: fine * width(x) if at <= x < at + run * fine * w0 else
              coarse * width(x))
    xb = side(lambda x: coarse * width(x))
    pa = np.stack([xa, 0 * xa], axis=1)
    pb = np.stack([xb, width(xb)], axis=1)
    flat = np.concatenate([pa, pb])
    angle = draw(st.floats(0, 2 * np.pi))
    tilt = draw(st.floats(-1.2, 1.2))
    axes = np.array([[np.cos(angle), np.sin(angle), 0.0],
                     [-np.sin(angle) * np.cos(tilt), np.cos(angle) * np.cos(tilt),
                      np.sin(tilt)]])
    xyz = flat @ axes + draw(st.floats(-100, 100))
    a = np.arange(len(pa))
    b = np.concatenate([[0], len(pa) + np.arange(len(pb)), [len(pa) - 1]])
    return flat, xyz, a, b


def _edges(tri):
    return np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])


@settings(max_examples=40, deadline=None)
@given(strips())
def test_a_filled_strip_covers_the_strip_with_better_triangles(case):
    """Hypothesis: where the zip has a triangle under FILL deg, the filled strip has the zip's
    boundary edges (same direction) and every other edge twice (both directions), covers the
    polygon's shoelace area, its new points lie inside the polygon and in its plane, and its
    smallest angle is larger than the zip's and at least 5 deg."""
    flat, xyz, a, b = case
    tri = zip_strip(xyz, a, b, angles=True)
    zip_worst = _angles(xyz[tri]).min()
    got, new = _filled(tri, xyz, 25.0)
    v = np.concatenate([xyz, new])
    if zip_worst >= FILL:
        assert got is tri
        return
    directed = {tuple(e) for e in _edges(got).tolist()}
    assert len(directed) == 3 * len(got)                         # no edge twice one way
    zipped = {tuple(e) for e in _edges(tri).tolist()}
    outline = {e for e in zipped if e[::-1] not in zipped}
    assert {e for e in directed if e[::-1] not in directed} == outline
    ring = np.concatenate([a, b[-2:0:-1]])
    area = 0.5 * abs(np.sum(flat[ring, 0] * np.roll(flat[ring, 1], -1)
                            - np.roll(flat[ring, 0], -1) * flat[ring, 1]))
    p = v[got]
    cross = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert np.isclose(0.5 * np.linalg.norm(cross, axis=1).sum(), area, rtol=1e-9)
    normal = np.cross(xyz[tri[0, 1]] - xyz[tri[0, 0]], xyz[tri[0, 2]] - xyz[tri[0, 0]])
    assert np.all(cross @ normal > 0.0)                          # oriented as the zip
    new = v[len(xyz):]
    origin, (ex, ey) = xyz[0], (xyz[len(a) - 1] - xyz[0], xyz[len(a) + 1] - xyz[0])
    n = np.cross(ex, ey) / np.linalg.norm(np.cross(ex, ey))
    assert np.abs((new - origin) @ n).max(initial=0.0) < 1e-9
    basis = np.linalg.lstsq(np.stack([ex, ey], axis=1), (new - origin).T, rcond=None)[0].T
    inside = basis @ np.stack([flat[len(a) - 1], flat[len(a) + 1]])
    assert Path(flat[ring]).contains_points(inside).all()
    worst = _angles(p).min()
    assert worst >= 5.0
    assert worst > zip_worst


def _wall_distance(p, w):
    """(k,) distance of points p (k, 3) from the L-shaped wall: x in [0, 1] at y = 0 and
    y in [0, 1] at x = 1, z in [0, w] (exact)."""
    def rect(u, v, n):                      # in-plane coordinates, off-plane distance
        du = np.maximum(0.0, np.maximum(-u, u - 1.0))
        dv = np.maximum(0.0, np.maximum(-v, v - w))
        return np.sqrt(du * du + dv * dv + n * n)
    x, y, z = p.T
    return np.minimum(rect(x, z, y), rect(y, z, x - 1.0))


@settings(max_examples=30, deadline=None)
@given(st.floats(0.03, 0.15), st.floats(0.05, 0.3), st.integers(2, 8), st.floats(1.0, 2.7))
def test_a_filled_strip_stays_on_a_strip_that_turns_a_corner(w, fine, run, coarse):
    """Hypothesis: a strip standing on an L (a blunt trailing edge turning into a tip), its
    lower side split finely just before the corner: its conformal chart is straight, so a
    triangle there could cut across the corner in 3-D. The filled strip's triangles (their
    corners and edge midpoints) stand off the wall no farther than the zip's triangles do
    (which cut the corner where a side has no point on it)."""
    def leg(n, step):
        return np.arange(1, n + 1) * step
    near = 1.0 - leg(run, fine * w)[::-1]           # close points just before the corner
    xa = np.concatenate([[0.0], np.arange(coarse * w, near[0] - 0.5 * coarse * w,
                                          coarse * w), near, [1.0]])
    xb = np.concatenate([[0.0], np.arange(coarse * w, 1.0 - 0.5 * coarse * w, coarse * w),
                         [1.0]])
    ya = np.concatenate([np.arange(coarse * w, 1.0 - 0.5 * coarse * w, coarse * w), [1.0]])

    def path(x, y, z):
        return np.concatenate([np.stack([x, 0 * x, 0 * x + z], 1),
                               np.stack([0 * y + 1.0, y, 0 * y + z], 1)])
    pa, pb = path(xa, ya, 0.0), path(xb, ya, w)
    xyz = np.concatenate([pa, pb])
    a = np.arange(len(pa))
    b = np.concatenate([[0], len(pa) + np.arange(1, len(pb)), [len(pa) - 1]])
    xyz = np.concatenate([xyz, [[1.0, 1.0, w]]])   # its far end: a rung
    b[-1] = len(xyz) - 1
    b = np.concatenate([b, [len(pa) - 1]])
    tri = zip_strip(xyz, a, b, angles=True)

    def standoff(v, t, n):
        """The largest distance off the wall of points on the triangles t (a barycentric
        grid of n steps: n = 2 their corners, edge midpoints and more)."""
        i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
        keep = i + j <= n
        w3 = np.stack([i[keep], j[keep], n - i[keep] - j[keep]], axis=1) / n
        return _wall_distance(np.einsum("gk,tkd->tgd", w3, v[t]).reshape(-1, 3), w).max()
    got, new = _filled(tri, xyz, 25.0)
    assert standoff(np.concatenate([xyz, new]), got, 2) <= standoff(xyz, tri, 64) + 1e-9


def _root_fan_airplane():
    import warnings

    import juncture as jc
    from tests.support import DATA

    deck = DATA / "generated" / "remesh" / "blunt_trailing_edge_fanned_at_the_wing_root.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.complete(jc.read(deck), fillet="cubic", keep_area=True)


def _cap_angles(surface):
    """(smallest angle of each wing-body cap triangle, whether each has a mirror image)."""
    from juncture.surface.mirror import triangle_mirror

    name = np.array(surface.surfaces)[surface.surface].astype(str)
    rows = np.flatnonzero(name == "wing-body cap")
    image = triangle_mirror(surface.vertices, surface.triangles)[rows]
    return _angles(surface.vertices[surface.triangles[rows]]).min(axis=1), image >= 0


def test_a_wing_roots_trailing_edge_strip_is_not_fanned():
    """A mid wing with a cubic fillet and a blunt trailing edge (tests/data/generated/
    README.md): the wing's chart refines towards the root's corner and puts close points on
    the lower trailing edge, while the strip's upper side keeps a long piece there; zipped,
    that fanned triangles of 1.6 deg. Filled, every triangle of the cap is at least 5 deg,
    and each has its mirror image (the strip of one half is filled, the other copied)."""
    import juncture as jc

    smallest, mirrored = _cap_angles(jc.mesh(_root_fan_airplane()))
    assert smallest.min() >= 5.0
    assert mirrored.all()


@pytest.mark.slow  # the airplane meshed again without the fill: make test-all
def test_slow_without_the_fill_the_wing_roots_strip_keeps_its_fan(monkeypatch):
    """The counterfactual of the test above: with no strip filled, the cap keeps triangles
    under 5 deg."""
    import juncture as jc
    import juncture.surface.strips as strips

    monkeypatch.setattr(strips, "FILL", 0.0)
    smallest, _ = _cap_angles(jc.mesh(_root_fan_airplane()))
    assert smallest.min() < 5.0
