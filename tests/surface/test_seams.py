"""Seams whose two sides carry different points of one line are made conformal."""

import numpy as np

from juncture.surface.assemble import boundary_loops
from juncture.surface.check import check_mesh
from juncture.surface.seams import split_seams


def _fan_strip(chain, apex_shift):
    """Triangles between a chain of points (k, 3) and the same chain shifted by apex_shift,
    as (points, triangles), oriented so the chain's edges run backwards (i+1 -> i)."""
    outer = chain + apex_shift
    pts = np.concatenate([chain, outer])
    k = len(chain)
    tris = []
    for i in range(k - 1):
        tris.append((i + 1, i, k + i))
        tris.append((i + 1, k + i, k + i + 1))
    return pts, np.array(tris)


def _arc(angles, radius=10.0):
    return np.stack([radius * np.cos(angles), radius * np.sin(angles),
                     np.zeros_like(angles)], axis=1)


def _two_sides(coarse, fine, gap=0.0):
    """Two strips in the plane z = 0 meeting along an arc: one outside it carrying the arc's
    points at ``coarse`` angles, one inside at ``fine`` angles (shifted outwards by ``gap``)."""
    a_pts, a_tri = _fan_strip(_arc(coarse), 0.0)
    a_pts[len(coarse):] *= 1.2                       # outward ring
    b_pts, b_tri = _fan_strip(_arc(fine, 10.0 + gap), 0.0)
    b_pts[len(fine):] *= 0.8                         # inward ring
    b_tri = b_tri[:, ::-1] + len(a_pts)              # the other side of the line
    pts = np.concatenate([a_pts, b_pts])
    # The shared end points are the same points, bit for bit, as a layout makes them.
    ends = [len(a_pts), len(a_pts) + len(fine) - 1]
    tri = np.concatenate([a_tri, b_tri])
    tri[tri == ends[0]] = 0
    tri[tri == ends[1]] = len(coarse) - 1
    return pts, tri, np.r_[np.zeros(len(a_tri), int), np.ones(len(b_tri), int)]


def _seam_open_edges(pts, tri):
    """Boundary edges whose both ends lie on the arc of radius 10."""
    loops = boundary_loops(tri)
    r = np.linalg.norm(pts[:, :2], axis=1)
    on = np.isclose(r, 10.0, rtol=1e-12)
    edges = [(a, b) for lp in loops for a, b in zip(lp, np.roll(lp, -1))]
    return sum(bool(on[a] and on[b]) for a, b in edges)


def _closed_by_split(pts, tri, comp):
    """split_seams' (triangles, parent) of a seam open before, checked closed and
    consistently oriented along it."""
    assert _seam_open_edges(pts, tri) > 0
    out, parent = split_seams(pts, tri, comp)
    assert _seam_open_edges(pts, out) == 0
    report = check_mesh(pts, out)
    assert report.misoriented_edges == 0 and report.nonmanifold_edges == 0
    return out, parent


def test_a_seam_with_different_points_on_each_side_closes_by_vertex_ids():
    rng = np.random.default_rng(3)
    coarse = np.linspace(0.0, 1.0, 6)
    fine = np.sort(np.r_[0.0, 1.0, rng.uniform(0.02, 0.98, 13)])
    pts, tri, comp = _two_sides(coarse, fine)
    out, parent = _closed_by_split(pts, tri, comp)
    # Nothing is moved or added: the same vertices; the coarse side now reaches the arc's
    # points, so it gives up at most the circular segments between its chords and the arc.
    def area(t):
        p = pts[t]
        return 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum()
    alpha = np.diff(coarse)
    segments = (0.5 * 10.0 ** 2 * (alpha - np.sin(alpha))).sum()
    assert 0.0 < area(tri) - area(out) <= segments
    assert set(np.unique(out)) <= set(np.unique(tri))
    assert np.array_equal(np.sort(np.unique(parent)), np.arange(len(tri)))


def test_a_gap_between_two_networks_of_one_component_is_not_folded_shut():
    coarse = np.linspace(0.0, 1.0, 6)
    fine = np.linspace(0.0, 1.0, 11)
    pts, tri, comp = _two_sides(coarse, fine, gap=-0.01)   # a real gap, 1 % of a spacing
    same = np.zeros_like(comp)
    out, _ = split_seams(pts, tri, same)
    assert len(out) == len(tri)                             # untouched
    out_other, _ = split_seams(pts, tri, comp)              # two components: a seam
    assert len(out_other) > len(tri)


def test_a_seam_curve_bending_past_the_lens_between_two_shared_points_closes():
    """One side carries only the ends of an arc of 1 rad (its chord stands 12.8 % of its
    length off the arc's middle, past the lens), the other four points between: the other
    side's chain between the two shared points is taken into the chord's triangle (a
    fuselage row ending on a wing's exact intersection between two of its chord stations)."""
    pts, tri, comp = _two_sides(np.array([0.0, 1.0]), np.linspace(0.0, 1.0, 6))
    _closed_by_split(pts, tri, comp)


def test_a_chain_partly_in_the_lens_between_two_shared_points_closes_whole():
    """One side carries the ends of an arc of 0.6 rad (its chord stands 7.5 % of its length
    off the arc's middle, past the lens), the other a point near one end, inside the lens,
    and one at the middle, outside it: the whole chain is taken (a fillet's start line round
    a corner of an arbitrary fuselage section between two of the wing's stations, seed 3434
    draw 5: the row end half-way stood 5.6 % off the edge and the seam stayed open)."""
    from juncture.surface.seams import LENS, _between

    fine = np.array([0.0, 0.03, 0.3, 0.6])
    pts, tri, comp = _two_sides(np.array([0.0, 0.6]), fine)
    inside, _, _ = _between(_arc(fine[1:-1]), _arc(np.zeros(1))[0], _arc(np.full(1, 0.6))[0],
                            LENS)
    assert inside.tolist() == [True, False]
    _closed_by_split(pts, tri, comp)


def test_a_long_edge_takes_a_long_chain_between_two_shared_points():
    """A wing network with two stations 28 ft apart beside a fuselage block with seven
    stations between them (seed 3232 draw 16, cubic fillet): all seven are taken."""
    pts, tri, comp = _two_sides(np.array([0.0, 0.8]), np.linspace(0.0, 0.8, 9))
    _closed_by_split(pts, tri, comp)


def test_a_chain_far_off_the_edge_between_two_shared_points_stays_open():
    """A chain farther than WIDE off the edge (an arc of 2.2 rad stands 29 % of its chord
    off at its middle) is not taken: the loop is not closed by guesswork."""
    fine = np.linspace(0.0, 2.2, 4)
    pts, tri, comp = _two_sides(np.array([0.0, 2.2]), fine)
    out, _ = split_seams(pts, tri, comp)
    assert _seam_open_edges(pts, out) == _seam_open_edges(pts, tri) > 0


def _edge_and_point(point):
    """Component 0: a triangle whose boundary edge A -> B runs 20 ft along y (a wing's upper
    trailing edge); component 1: a triangle with the corner ``point`` beside it (a body
    triangle at the wing's lower trailing edge) sharing A."""
    pts = np.array([[0.0, 0.0, 0.0], [0.0, 20.0, 0.0], [-1.0, 10.0, 0.0], point,
                    [3.0, -2.0, -1.0]])
    tri = np.array([[0, 1, 2], [3, 0, 4]])
    return pts, tri, np.array([0, 1])


def test_the_lens_about_an_edge_narrows_to_its_ends():
    """The lens about an edge narrows to its ends (seams.END): the lower trailing-edge point
    where a body cuts a blunt trailing edge, 0.066 ft off the 20 ft upper trailing edge at
    0.15 % of its length, was taken into it and folded the strip between them to a point at
    the root (hundreds of slivers in the zipped strip). Points 3 % of the edge off it at its
    middle and at a tenth of its length (a fillet's line bending off a wing's root) are
    taken."""
    for point in ([0.02, 0.03, -0.063], [0.0, 0.2, -0.1]):
        pts, tri, comp = _edge_and_point(point)
        out, _ = split_seams(pts, tri, comp)
        assert len(out) == len(tri)
    for y in (10.0, 2.0):
        pts, tri, comp = _edge_and_point([0.02, y, -0.6])
        out, _ = split_seams(pts, tri, comp)
        assert len(out) == len(tri) + 1 and (out == 3).sum() == 3


def test_a_long_root_edge_takes_only_points_of_its_own_seam(monkeypatch):
    """A held-out airplane (tests/data/generated/README.md): a wing with four chord stations
    whose root runs past the fuselage's end; its upper root edge from x = 227.9 to 258.8 (a
    lens 1.5 ft wide) lies within a thin trailing edge's thickness of the lower seam, and
    took the fuselage lower block's row ends, nearer to it than to their own edges, as
    points of its seam, then dropped them as off its path: both seams stayed open (22 open
    edges, `mesh` refused the airplane). A point now goes to the nearest edge whose other
    side's boundary runs through it: the assembled surface passes every check (exact
    predicates). Counterfactual: each point at its nearest edge, open."""
    import warnings

    import juncture as jc
    import juncture.surface.seams as sm
    from juncture.surface.assemble import assemble
    from tests.support import DATA

    deck = DATA / "generated" / "assembly" / \
        "wing_root_edge_past_the_fuselage_end_over_a_thin_trailing_edge.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))
    surface = assemble(geo)
    assert not surface.open_loops
    assert check_mesh(surface.vertices, surface.triangles).failures() == []

    def nearest(found, *args):
        best = {}
        for off, v, e, s in sorted(found):
            best.setdefault(v, (off, e, s))
        return best

    monkeypatch.setattr(sm, "_nearest_edges", nearest)
    assert len(assemble(geo).open_loops) == 4


def _jog():
    """A wing triangle a b c (sharp at a) with its neighbours across b c and c a, and a
    fuselage strip below a b whose boundary runs b -> p2 -> p1 -> a: the curve jogs at
    x = 1 from p1 to p2, beyond the wing triangle's side c a (as a seam crossing a
    fuselage's step at a joint does), inside the seam's lens."""
    pts = np.array([[0.0, 0.0], [10.0, 0.0], [5.0, 1.0], [9.0, 4.0], [1.0, 4.0],
                    [1.0, 0.1], [1.0, 0.3], [0.0, -2.0], [10.0, -2.0]])
    pts = np.column_stack([pts, np.zeros(len(pts))])
    a, b, c, d, e, p1, p2, q0, q1 = range(9)
    tri = np.array([(a, b, c), (c, b, d), (a, c, e),                   # the wing
                    (a, q0, p1), (p1, q0, q1), (p1, q1, p2), (p2, q1, b)])  # the fuselage
    return pts, tri, np.array([0, 0, 0, 1, 1, 1, 1])


def test_a_curve_jogging_past_the_triangle_is_taken_by_its_neighbours(monkeypatch):
    """The fan from c would turn over (p1 p2 c) and the polygon a p1 p2 b c crosses itself:
    the triangle and its neighbours are triangulated again with the chain in their border.
    The seam closes with both jog points kept (every edge between seam points in two
    triangles), every triangle facing +z and the wing's area grown by the sliver the jog
    takes from it. Without this (the counterfactual), the fuselage gave the points up."""
    import juncture.surface.seams as seams

    pts, tri, comp = _jog()
    out, parent = split_seams(pts, tri, comp)
    assert _seam_edges_open(pts, out) == 0
    assert {5, 6} <= set(out.ravel().tolist())
    n = np.cross(pts[out[:, 1]] - pts[out[:, 0]], pts[out[:, 2]] - pts[out[:, 0]])
    assert np.all(n[:, 2] > 0.0)
    area = 0.5 * n[:, 2]
    before = 0.5 * np.cross(pts[tri[:, 1]] - pts[tri[:, 0]], pts[tri[:, 2]] - pts[tri[:, 0]])[:, 2]
    jog = pts[[0, 5, 6, 1], :2]                       # a p1 p2 b: what the wing gives up
    taken = 0.5 * abs(np.dot(jog[:, 0], np.roll(jog[:, 1], -1))
                      - np.dot(jog[:, 1], np.roll(jog[:, 0], -1)))
    wing = comp[parent] == 0
    np.testing.assert_allclose(area[wing].sum(), before[comp == 0].sum() - taken, atol=1e-12)
    np.testing.assert_allclose(area[~wing].sum(), before[comp == 1].sum(), atol=1e-12)
    monkeypatch.setattr(seams, "_widened", lambda *a: None)
    out, _ = split_seams(pts, tri, comp)
    assert not {5, 6} & set(out.ravel().tolist())


def _seam_edges_open(pts, tri):
    """Boundary edges whose two ends both lie on the seam (a, b and the jog's points)."""
    on = np.zeros(len(pts), bool)
    on[[0, 1, 5, 6]] = True
    loops = boundary_loops(tri)
    return sum(bool(on[a] and on[b]) for lp in loops for a, b in zip(lp, np.roll(lp, -1)))
