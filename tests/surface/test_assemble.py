"""Assembling networks into one surface: shared ids only where points are bit-identical,
planar loops capped, the rest reported open (checked with trimesh and closed forms)."""

import numpy as np
import pytest

from juncture.geometry import Geometry
from juncture.surface.assemble import assemble, cap_polygon, simple_loops


def _prism(n_theta=24, n_x=7, length=5.0, radius=1.5, mirror=False):
    """A polygonal cylinder as one network (x lines around, outward), open at both ends;
    as two half networks with an x-z mirror image when ``mirror``."""
    x = np.linspace(0.0, length, n_x)
    if mirror:  # the y >= 0 half, bottom to top; its image closes the other side
        th = np.linspace(-np.pi / 2, np.pi / 2, n_theta // 2 + 1)
    else:
        th = np.linspace(0.0, 2 * np.pi, n_theta + 1)
    pts = np.stack(np.broadcast_arrays(x[:, None], radius * np.cos(th)[None, :],
                                       radius * np.sin(th)[None, :]), -1)
    if mirror:
        pts[:, [0, -1], 1] = 0.0  # on the plane of symmetry exactly, as the image's points
    else:
        pts[:, -1] = pts[:, 0]  # the seam repeats the first line bit for bit
    return pts


def _polygon_area(n, r):
    return 0.5 * n * r * r * np.sin(2 * np.pi / n)


@pytest.mark.parametrize("mirror", [False, True])
def test_a_capped_prism_is_closed_and_has_the_prism_volume(mirror):
    import trimesh

    net = _prism(mirror=mirror)
    geo = Geometry({"pod": net}, symmetry={"pod": "xz"} if mirror else {})
    mesh = assemble(geo)
    assert mesh.open_loops == ()
    tm = trimesh.Trimesh(mesh.vertices, mesh.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    exact = _polygon_area(24, 1.5) * 5.0
    assert mesh.volume() == pytest.approx(exact, rel=1e-13)
    assert tm.volume == pytest.approx(exact, rel=1e-13)
    moved = Geometry({"pod": net + [3.0, -7.0, 11.0]},
                     symmetry={"pod": "xz"} if mirror else {})
    if not mirror:
        assert assemble(moved).volume() == pytest.approx(exact, rel=1e-12)
    wet = mesh.wetted_area()
    side = 24 * 2 * 1.5 * np.sin(np.pi / 24) * 5.0
    assert wet["pod"] == pytest.approx(side, rel=1e-13) and wet["total"] == wet["pod"]


def test_points_that_differ_in_the_last_bit_are_not_welded():
    net = _prism()
    net[:, -1] = np.nextafter(net[:, 0], np.inf)  # the seam is off by one ulp
    mesh = assemble(Geometry({"pod": net}))
    # The seam's two sides stay open, not welded: one loop around both (through the ends,
    # which are then no plane loops and stay open too).
    assert len(mesh.open_loops) == 1
    assert mesh.open_loops[0].size == 2 * 7 + 2 * 23  # both seam lines, both rings


def test_a_non_planar_open_loop_is_reported_not_filled():
    net = _prism()
    net[-1, :, 0] += 0.2 * np.sin(3 * np.linspace(0, 2 * np.pi, net.shape[1]))  # warped end
    net[-1, -1] = net[-1, 0]
    mesh = assemble(Geometry({"pod": net}))
    assert len(mesh.open_loops) == 1
    assert mesh.open_loops[0].size == 24


def test_cap_polygon_triangulates_a_non_convex_polygon_inside_it():
    rng = np.random.default_rng(4)
    k = 40
    th = np.sort(rng.uniform(0, 2 * np.pi, k))
    r = 1.0 + 0.5 * rng.random(k)
    uv = np.stack([r * np.cos(th), r * np.sin(th)], 1)
    tri = cap_polygon(uv)
    assert tri.shape == (k - 2, 3)
    a = uv[tri]
    signed = 0.5 * ((a[:, 1, 0] - a[:, 0, 0]) * (a[:, 2, 1] - a[:, 0, 1])
                    - (a[:, 1, 1] - a[:, 0, 1]) * (a[:, 2, 0] - a[:, 0, 0]))
    area = 0.5 * np.sum(uv[:, 0] * np.roll(uv[:, 1], -1) - np.roll(uv[:, 0], -1) * uv[:, 1])
    assert np.all(signed > 0)  # same orientation as the polygon: no folded triangle
    assert signed.sum() == pytest.approx(area, rel=1e-12)  # covers it exactly once


def test_a_blunt_trailing_edge_slot_is_closed_by_a_strip():
    """A wing-like box whose upper and lower surfaces end apart at the trailing edge (its
    'last lines' 0.02 apart) and meet at the leading edge: the slot is zipped shut."""
    import trimesh

    span = np.linspace(0.0, 4.0, 6)
    chord = np.linspace(0.0, 1.0, 9)
    thick = 0.05 * np.sin(np.pi * np.clip(chord, 0, 0.9) / 0.9 * 0.5 + 0.0) + 0.01 * chord
    up = np.stack(np.broadcast_arrays(chord[None, :], span[:, None], thick[None, :]), -1)
    lo = up.copy()
    lo[..., 2] *= -1.0
    lo[:, 0] = up[:, 0]  # the leading edge is shared
    # Networks: lines along the span, points along the chord; cross(d/d point, d/d line) is
    # +z for the upper one as it is, the lower one's lines are reversed; tips capped as planes.
    mesh = assemble(Geometry({"wing upper": up, "wing lower": lo[::-1]}))
    tm = trimesh.Trimesh(mesh.vertices, mesh.triangles, process=False)
    assert mesh.open_loops == ()
    assert tm.is_watertight and tm.is_winding_consistent
    assert mesh.volume() > 0
    slot = np.abs(mesh.vertices[mesh.triangles][..., 0] - 1.0).max(axis=1) == 0
    assert slot.sum() == 2 * (6 - 1)  # the trailing-edge strip: one quad per span interval


@pytest.mark.parametrize("fillet", [None, "cubic", "circular"])
@pytest.mark.parametrize("blocks", [None, 6])
def test_the_pdas_wing_body_is_one_closed_surface(fillet, blocks):
    """The TM-4406 layouts share the intersection and fillet lines bit for bit: the sample
    wing-body closes with no tolerance (trimesh), its volume independent of the origin."""
    import warnings

    import trimesh

    import juncture as jc
    from tests.support import PDAS_DECK

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        geo = jc.complete(jc.read(PDAS_DECK), fillet, options=jc.CompleteOptions(blocks=blocks))
    mesh = assemble(geo)
    tm = trimesh.Trimesh(mesh.vertices, mesh.triangles, process=False)
    assert mesh.open_loops == ()
    assert tm.is_watertight and tm.is_winding_consistent
    assert mesh.volume() > 0 and tm.volume == pytest.approx(mesh.volume(), rel=1e-12)
    shifted = trimesh.Trimesh(mesh.vertices + [-40.0, 3.0, 7.0], mesh.triangles, process=False)
    assert shifted.volume == pytest.approx(mesh.volume(), rel=1e-9)


def test_a_pinched_loop_is_split_into_loops_that_pass_each_vertex_once():
    # A tip whose upper and lower lines touch at vertices 2 and 5 between its ends.
    loop = [0, 1, 2, 3, 4, 2, 5, 6, 7, 5, 8]
    parts = simple_loops(loop)
    assert sorted(map(tuple, parts)) == [(0, 1, 2, 5, 8), (2, 3, 4), (5, 6, 7)]
    edges = {(a, b) for p in parts for a, b in zip(p, np.roll(p, -1))}
    assert edges == set(zip(loop, np.roll(loop, -1)))   # the same directed edges
    assert [tuple(p) for p in simple_loops([4, 5, 6])] == [(4, 5, 6)]


def test_a_closed_pod_tail_off_the_origin_is_one_point():
    """A pod whose radius closes to 0 at its last station, placed where origin + x does not
    round-trip (27.6583 - 19.534 != 8.1243 in floating point): its last section is one point
    bit for bit, not a ring of points an ulp apart whose cap crosses the pod."""
    from juncture.model import CircularBody

    pod = CircularBody("pod 1", np.array([0.0, 2.0, 6.0, 8.1243]),
                       np.array([0.9, 1.1, 0.6, 0.0]), origin=(19.534, 8.07, -3.168),
                       mirrored=True)
    x_end = pod.x_global[-1]
    assert x_end - pod.origin[0] != pod.x[-1]              # the case this is about
    ring = pod.point(np.full(37, x_end), np.linspace(0.5 * np.pi, 2.5 * np.pi, 37))
    assert len(np.unique(ring + 0.0, axis=0)) == 1
    assert pod.radius_at(x_end) == 0.0


def test_points_on_the_mirror_plane_are_shared_by_both_halves():
    """A half tube whose edge points lie on y = 0 by r cos(pi / 2) (6e-17 r, not 0): both
    halves share them, so the tube closes with its two end caps and nothing else (no strip
    of zero width along the plane)."""
    theta = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 7)
    x = np.linspace(0.0, 4.0, 5)
    net = np.stack(np.broadcast_arrays(x[:, None], 2.0 * np.cos(theta)[None, :],
                                       2.0 * np.sin(theta)[None, :]), axis=-1)
    assert 0.0 < abs(net[0, 0, 1]) < 1e-15
    surface = assemble(Geometry(networks={"tube": net}, symmetry={"tube": "xz"}))
    assert not surface.open_loops
    caps = np.array([s.endswith(" cap") for s in surface.surfaces])[surface.surface]
    p = surface.vertices[surface.triangles[caps]]
    assert np.allclose(p[..., 0].min(axis=1), p[..., 0].max(axis=1))  # the end caps only
    assert surface.areas().min() > 0.0
    assert surface.volume() == pytest.approx(4.0 * 0.5 * 12 * 2.0 ** 2 * np.sin(np.pi / 6),
                                             rel=1e-12)  # length x the 12-gon


def test_a_wall_in_the_plane_of_symmetry_made_by_both_halves_is_taken_out():
    """A half network that runs round its half-section and back down the plane of symmetry
    (as a wing-body block does where the wing's lines are continued to the plane behind the
    fuselage's end): with its image, the part in the plane is a wall of no thickness, two
    triangles on the same three vertices in opposite turns. Both are taken out and the rest
    is the closed prism (trimmed: watertight; its volume exact)."""
    import trimesh

    half = _prism(mirror=True)                       # bottom to top round the y >= 0 half
    down = np.linspace(1.5, -1.5, 5)[1:]             # then down the plane to the bottom
    wall = np.stack(np.broadcast_arrays(half[:, :1, 0], 0.0 * down[None], down[None]), -1)
    net = np.concatenate([half, wall], axis=1)
    geo = Geometry({"pod": net}, symmetry={"pod": "xz"})
    mesh = assemble(geo)
    assert not np.any(np.all(mesh.vertices[mesh.triangles][..., 1] == 0.0, axis=1))
    assert mesh.open_loops == ()
    tm = trimesh.Trimesh(mesh.vertices, mesh.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert mesh.volume() == pytest.approx(_polygon_area(24, 1.5) * 5.0, rel=1e-13)


def test_no_flat_cap_runs_along_the_fuselage_behind_a_blunt_trailing_edge():
    """A generated airplane (tests/data/generated/README.md) whose blunt trailing edge has
    both points at one fuselage station: behind it the upper and lower blocks end on one
    line, so no body cap is left there but (at most) the triangle between the two points and
    the next station (it was a 44 ft flat sliver, 0.022 ft wide, along the body to its
    end)."""
    import warnings

    import juncture as jc
    from tests.support import DATA

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(DATA / "generated" / "assembly"
                                  / "blunt_trailing_edge_at_a_body_station.inp"))
    mesh = assemble(geo)
    rows = np.flatnonzero(np.array(mesh.surfaces)[mesh.surface] == "body cap")
    x = mesh.vertices[mesh.triangles[rows]][:, :, 0]
    side = x.max(axis=1) < geo.configuration["body"].x_global[-1]     # not the blunt base
    assert side.sum() <= 2 and (not side.any() or np.ptp(x[side]) < 4.0)


def _caps_on_one_other_component(mesh):
    """Cap triangles whose edges on the networks' boundary all close triangles of one
    component that is not the cap's (counted by a dictionary of directed edges)."""
    names = np.array(mesh.surfaces)[mesh.surface]
    cap = np.char.endswith(names.astype(str), " cap")
    across = {}
    for row in np.flatnonzero(~cap):
        t = mesh.triangles[row].tolist()
        for i in range(3):
            across[(t[i], t[(i + 1) % 3])] = mesh.component[row]
    found = []
    for row in np.flatnonzero(cap):
        t = mesh.triangles[row].tolist()
        got = {across[(t[(i + 1) % 3], t[i])] for i in range(3)
               if (t[(i + 1) % 3], t[i]) in across}
        if len(got) == 1 and got != {mesh.component[row]}:
            found.append(row)
    return found


def test_the_body_between_a_blunt_trailing_edge_and_its_split_point_is_the_bodys():
    """A generated arbitrary fuselage with a flat side the wing's root crosses
    (tests/data/generated/README.md): its upper and lower blocks meet on one point 6.4 ft aft
    of the blunt trailing edge's two root points. The wedge between them lies on the body
    and belongs to it; as a corner of the wing's trailing-edge cap (counterfactual: one such
    triangle on each side, 0.25 deg) the cap's strip was zipped into triangles of 0.035 deg."""
    import warnings

    import trimesh

    import juncture as jc
    from tests.support import DATA

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(DATA / "generated" / "assembly"
                                  / "arbitrary_body_split_meeting_aft_of_a_blunt_trailing_edge"
                                    ".inp"))
    mesh = assemble(geo)
    assert _caps_on_one_other_component(mesh) == []
    tm = trimesh.Trimesh(mesh.vertices, mesh.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    body = mesh.components.index("body")
    p = mesh.vertices[mesh.triangles]
    wedge = (mesh.component == body) & np.all(np.abs(p[..., 1]) == 5.368, axis=1) & \
        (p[..., 0].min(axis=1) >= 69.5) & (p[..., 0].max(axis=1) <= 76.0) & \
        (np.ptp(p[..., 2], axis=1) < 0.03)
    assert wedge.sum() == 2                  # one on each side, now the body's


@pytest.mark.parametrize("deck, part", [
    ("tail_passing_under_the_tail_cone_over_three_stations", "tail 1"),
    ("high_wing_trailing_edge_over_the_fuselage_top", "wing")])
def test_a_surface_passing_the_body_on_one_side_is_joined_to_it_ahead_only(deck, part):
    """Generated airplanes (tests/data/generated/README.md) whose lifting surface passes the
    fuselage on one side near its trailing edge, both surfaces' lofting lines missing it
    (continued to the plane of symmetry, :mod:`juncture.misses`): a tail under a tail cone
    at its last three stations, a high wing's trailing edge over the fuselage's top. The
    surface meets its mirror image there; the fuselage's rows at those stations end on the
    plane of symmetry (counterfactual: at the row's last inner point, a slanted panel the
    mirror image doubled: edges in four triangles) and the rows behind the trailing edge
    start from the body, not from the surface's end point (counterfactual: a vertex in two
    fans, Euler characteristic 1). Checked with an edge count, trimesh's closed, wound and
    Euler characteristic of each body, and the body model's own distance."""
    import warnings

    import trimesh

    import juncture as jc
    from tests.support import DATA

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        cfg = jc.read(DATA / "generated" / "assembly" / f"{deck}.inp")
        geo = jc.complete(cfg)
    mesh = assemble(geo)
    t = mesh.triangles
    edges = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert np.all(counts == 2)
    tm = trimesh.Trimesh(mesh.vertices, t, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert [b.euler_number for b in tm.split(only_watertight=False)] == [2] * len(
        tm.split(only_watertight=False))
    # the surface's points in the plane of symmetry off the body: several; those at its
    # trailing edge (the last of them) on no body triangle behind it
    v = mesh.vertices
    own = np.unique(t[mesh.component == mesh.components.index(part)])
    plane = own[v[own, 1] == 0.0]
    off = plane[np.abs(cfg["body"].signed_distance(v[plane])) > 1e-3]
    assert off.size >= 3
    last = off[v[off, 0] == v[off, 0].max()]
    body = t[mesh.component == mesh.components.index("body")]
    at_end = body[np.isin(body, last).any(axis=1)]
    assert last.size and np.all(v[at_end, 0] <= v[last[0], 0])


def test_a_gap_between_two_blocks_is_filled_from_one_side_only():
    """A generated airplane (tests/data/generated/README.md) whose blunt trailing edge has
    both points at one station on the fuselage's flat side: behind them the two blocks end
    on one curve and leave a gap of three points. Both blocks took the other's trailing-edge
    point into their edge and covered it twice (edges in four triangles, crossing pairs);
    now the assembled surface passes every check."""
    import warnings

    import juncture as jc
    from juncture.surface.check import check_mesh
    from tests.support import DATA

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(DATA / "generated" / "assembly"
                                  / "blunt_trailing_edge_at_a_station_on_a_flat_side.inp"))
    mesh = assemble(geo)
    report = check_mesh(mesh.vertices, mesh.triangles)
    assert report.ok, report.failures()


@pytest.mark.parametrize("deck, layout", [
    ("high_swept_wing_upper_line_ahead_of_its_leading_edge", 4),
    ("high_wing_upper_line_running_aft_before_it_turns_forward", None)])
def test_a_root_line_that_turns_back_is_bounded_by_the_split_layout(deck, layout):
    """Generated airplanes (tests/data/generated/README.md, held out in session 37) whose
    wing's upper intersection line runs forward of its leading-edge point before it turns
    aft. (1) A wing-body with no other component on the fuselage, whose default was the
    4-block layout: its juncture blocks' rows lie at each line point's own station, so the
    band between the leading edge (x 68.46) and the point ahead of it (68.18) folded over the
    next, and the forward block, ending at the leading edge, covered the body under them
    (34 crossing pairs). The default is now the split layout wherever a start line turns
    back in x; the counterfactual (``blocks=4``, asked for) still crosses, with a warning.
    (2) An upper line that runs aft by 0.05 ft from the leading edge before it turns
    forward over the fuselage's top: the split layout's chains refused such a wiggle and
    fell back to each line alone (an open loop, the upper block under the wing); now the
    point that turns back stays on the wing's root line. Oracle: the exact-predicate check
    of the assembled surface."""
    import warnings

    import juncture as jc
    from juncture.surface.check import check_mesh
    from tests.support import DATA

    cfg = jc.read(DATA / "generated" / "assembly" / f"{deck}.inp")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(cfg)
    assert "body upper" in geo.networks and "body wing-body upper" not in geo.networks
    mesh = assemble(geo)
    report = check_mesh(mesh.vertices, mesh.triangles)
    assert report.ok, report.failures()
    if layout is not None:
        with pytest.warns(jc.JunctureWarning, match="fold there"):
            folded = assemble(jc.complete(cfg, blocks=layout))
        assert not check_mesh(folded.vertices, folded.triangles).ok
