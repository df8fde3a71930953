"""The fuselage's upper and lower blocks (surface/body_split.py) meet on one line."""

import numpy as np
import pytest

from juncture.model import CircularBody
from juncture.surface.body_split import Boundary, split_body


def _keys(points):
    return {tuple(p) for p in (np.asarray(points) + 0.0).tolist()}


def test_upper_and_lower_blocks_carry_the_same_points_where_they_meet():
    """A fin on the fuselage aft of the wing adds stations to the upper block; outside the
    wing's region the lower block ends on the same line, so it takes them too: every point
    of either block on that line is a point of the other (else the seam stays open)."""
    body = CircularBody("body", np.linspace(0.0, 100.0, 11),
                        np.r_[0.0, 3.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 3.5, 2.5, 1.0])
    # The wing's region from x = 30 to 55 (one line each side, sharp edges: common ends),
    # a fin from x = 71.3 to 88.7 on top.
    xs = np.array([30.0, 37.1, 44.9, 55.0])
    upper = Boundary(xs, np.array([-0.1, 0.05, 0.02, -0.1]))
    lower = Boundary(xs, np.array([-0.1, -0.3, -0.25, -0.1]))
    fin = Boundary(np.array([71.3, 76.9, 83.3, 88.7]), np.full(4, 1.45))
    nets = split_body(body, [upper], [lower], fins=[fin])
    up, lo = nets["body upper"][:, -1], nets["body lower"][:, -1]
    outside = lambda p: p[(p[:, 0] < 30.0) | (p[:, 0] > 55.0)]  # noqa: E731
    assert _keys(outside(up)) == _keys(outside(lo))
    assert {71.3, 76.9, 83.3, 88.7} <= {p[0] for p in _keys(outside(lo))}


def _region(body, x, theta):
    x, theta = np.asarray(x, float), np.asarray(theta, float)
    return Boundary(x, theta, "", body.point(x, theta))


def test_a_staggered_overlap_is_found_with_the_higher_region_and_its_stations():
    from juncture.surface.overlap_blocks import find_overlap

    body = CircularBody("body", np.linspace(0.0, 100.0, 11), np.full(11, 4.0))
    canard = (_region(body, [20, 30, 45], [0.6, 0.7, 0.6]),
              _region(body, [20, 30, 45], [0.6, 0.4, 0.6]))
    wing = (_region(body, [40, 60, 80], [-0.2, -0.1, -0.2]),
            _region(body, [40, 60, 80], [-0.2, -0.4, -0.2]))
    ov = find_overlap([canard[0], wing[0]], [canard[1], wing[1]])
    assert (ov.high, ov.low, ov.first, ov.m0, ov.m1) == (0, 1, 0, 40.0, 45.0)
    ov = find_overlap([wing[0], canard[0]], [wing[1], canard[1]])
    assert (ov.high, ov.low, ov.first) == (1, 0, 1)
    # nested (one inside the other's range, above it): found, m0 and m1 its ends
    inner = (_region(body, [50, 60, 70], [0.6, 0.7, 0.6]),
             _region(body, [50, 60, 70], [0.6, 0.4, 0.6]))
    ov = find_overlap([inner[0], wing[0]], [inner[1], wing[1]])
    assert (ov.high, ov.low, ov.first, ov.m0, ov.m1, ov.nested) == (0, 1, 1, 50.0, 70.0, True)
    # at one height: not handled
    level = (_region(body, [20, 30, 45], [-0.2, -0.1, -0.2]),
             _region(body, [20, 30, 45], [-0.2, -0.3, -0.2]))
    assert find_overlap([level[0], wing[0]], [level[1], wing[1]]) is None


def _canard_and_wing(canard_x):
    """A cylinder of radius 4 (length 100), a canard's region at ``canard_x`` above the
    wing's (x 40 to 80) on it."""
    body = CircularBody("body", np.linspace(0.0, 100.0, 21), np.full(21, 4.0))
    canard = (_region(body, canard_x, [0.6, 0.7, 0.6]),
              _region(body, canard_x, [0.6, 0.4, 0.6]))
    wing = (_region(body, [40, 60, 80], [-0.2, -0.1, -0.2]),
            _region(body, [40, 60, 80], [-0.2, -0.4, -0.2]))
    return body, canard, wing


def test_three_blocks_tile_the_section_where_two_regions_overlap():
    """A canard (high) whose trailing edge lies behind the wing's (low) leading edge: at
    every station of the overlap the upper block runs from the top to the canard's upper
    curve, the middle block from its lower curve to the wing's upper curve, the lower block
    from the wing's lower curve to the bottom; the middle block's rows end on the regions'
    own points where it has their stations, and its two degenerate rows are the points
    where the upper (lower) block passes from one region to the other."""
    body, canard, wing = _canard_and_wing([20, 30, 45])
    nets = split_body(body, [canard[0], wing[0]], [canard[1], wing[1]])
    mid = nets["body middle"]

    def angle(p):
        return np.arctan2(p[..., 2], p[..., 1])
    real = mid[1:-1]                                   # without the degenerate rows
    assert np.all(np.ptp(mid[0], axis=0) == 0) and np.all(np.ptp(mid[-1], axis=0) == 0)
    xs = real[:, 0, 0]
    assert xs.min() == 40.0 and xs.max() == 45.0 and 45.0 in xs and 40.0 in xs
    ends = _keys(np.concatenate([real[:, 0], real[:, -1]]))
    assert _keys([canard[1].points[-1], wing[0].points[0]]) <= ends   # their own points
    hi = np.maximum(angle(real[:, 0]), angle(real[:, -1]))
    lo = np.minimum(angle(real[:, 0]), angle(real[:, -1]))
    assert np.allclose(hi, np.interp(xs, canard[1].x, canard[1].theta), atol=1e-12)
    assert np.allclose(lo, np.interp(xs, wing[0].x, wing[0].theta), atol=1e-12)
    # the upper and lower blocks at the overlap's stations stop at the outer curves
    for name, curve in (("body upper", canard[0]), ("body lower", wing[1])):
        net = nets[name]
        rows = net[(net[:, 0, 0] >= 40.0) & (net[:, 0, 0] <= 45.0)]
        inner = np.where(np.abs(angle(rows[:, 0])) < np.abs(angle(rows[:, -1])),
                         angle(rows[:, 0]), angle(rows[:, -1]))
        assert np.allclose(inner, np.interp(rows[:, 0, 0], curve.x, curve.theta), atol=1e-12)
    # the degenerate rows are the blocks' row ends at their switching stations
    up_ends = {tuple(p) for p in (nets["body upper"].reshape(-1, 3) + 0.0).tolist()}
    lo_ends = {tuple(p) for p in (nets["body lower"].reshape(-1, 3) + 0.0).tolist()}
    before, after = sorted((mid[0, 0], mid[-1, 0]), key=lambda p: p[0])
    assert before[0] < 40.0 < 45.0 < after[0]
    assert tuple((before + 0.0).tolist()) in lo_ends      # before m0: the lower block's
    assert tuple((after + 0.0).tolist()) in up_ends       # after m1: the upper block's


def test_three_blocks_tile_the_section_where_a_region_lies_inside_anothers_range():
    """A canard (high) whose root runs from x = 50 to 70 over a wing's (low) from 40 to 80
    (seed 9696, draw 16: refused before as "over the same stations"): over [50, 70] the
    middle block runs from the canard's lower curve to the wing's upper curve; the upper
    block follows the wing's upper curve outside [50, 70] and the canard's inside, passing
    twice (two degenerate rows of the middle block, at the upper block's stations next to
    50 and 70, each one of its row ends); the lower block follows the wing's lower curve."""
    body, canard, wing = _canard_and_wing([50, 60, 70])
    nets = split_body(body, [canard[0], wing[0]], [canard[1], wing[1]])
    mid = nets["body middle"]

    def angle(p):
        return np.arctan2(p[..., 2], p[..., 1])
    assert np.all(np.ptp(mid[0], axis=0) == 0) and np.all(np.ptp(mid[-1], axis=0) == 0)
    real = mid[1:-1]
    xs = real[:, 0, 0]
    assert xs.min() == 50.0 and xs.max() == 70.0
    hi = np.maximum(angle(real[:, 0]), angle(real[:, -1]))
    lo = np.minimum(angle(real[:, 0]), angle(real[:, -1]))
    assert np.allclose(hi, np.interp(xs, canard[1].x, canard[1].theta), atol=1e-12)
    assert np.allclose(lo, np.interp(xs, wing[0].x, wing[0].theta), atol=1e-12)
    up = nets["body upper"]
    ends = np.where(np.abs(angle(up[:, 0])) < np.abs(angle(up[:, -1])), angle(up[:, 0]),
                    angle(up[:, -1]))
    x = up[:, 0, 0]
    inside = (x >= 50.0) & (x <= 70.0)
    assert np.allclose(ends[inside], np.interp(x[inside], canard[0].x, canard[0].theta),
                       atol=1e-12)
    wing_part = ((x >= 40.0) & (x < 50.0)) | ((x > 70.0) & (x <= 80.0))
    switch = {float(mid[0, 0, 0]), float(mid[-1, 0, 0])}
    plain = wing_part & ~np.isin(x, list(switch))
    assert np.allclose(ends[plain], np.interp(x[plain], wing[0].x, wing[0].theta),
                       atol=1e-12)
    up_pts = {tuple(p) for p in (up.reshape(-1, 3) + 0.0).tolist()}
    a, b = sorted(switch)
    assert 40.0 <= a < 50.0 and 70.0 < b <= 80.0
    assert tuple((mid[0, 0] + 0.0).tolist()) in up_pts
    assert tuple((mid[-1, 0] + 0.0).tolist()) in up_pts
    lo_net = nets["body lower"]
    xl = lo_net[:, 0, 0]
    in_wing = (xl >= 40.0) & (xl <= 80.0)
    lo_ends = np.where(np.abs(angle(lo_net[:, 0])) < np.abs(angle(lo_net[:, -1])),
                       angle(lo_net[:, 0]), angle(lo_net[:, -1]))
    assert np.allclose(lo_ends[in_wing], np.interp(xl[in_wing], wing[1].x, wing[1].theta),
                       atol=1e-12)


def test_a_line_turning_back_at_the_leading_edge_bounds_the_other_block_there():
    """The upper line runs forward from the leading-edge point before it turns aft (a high
    swept wing's intersection bulging forward and up): at the stations of that forward run
    the region lies between two of its points, so the run, taken aft, bounds the lower
    block up to the leading-edge point and the lower line goes on from there; the upper
    block follows the upper line from its foremost point. Both chains run aft."""
    from juncture.surface.body_split import footprint_chains

    le = [10.0, 3.0, 0.0]
    upper = np.array([le, [9.0, 2.5, 1.0], [8.5, 1.5, 2.0], [12.0, 0.5, 2.5], [20.0, 0.5, 2.0]])
    lower = np.array([le, [12.0, 3.0, -1.0], [15.0, 3.0, -1.2], [18.0, 2.5, -1.0],
                      [20.0, 0.5, 2.0]])
    up_chain, low_chain = footprint_chains(upper, lower)
    assert up_chain == [(0, 2), (0, 3), (0, 4)]
    assert low_chain == [(0, 2), (0, 1), (0, 0), (1, 1), (1, 2), (1, 3), (1, 4)]
    for chain in (up_chain, low_chain):
        x = [(upper, lower)[s][i, 0] for s, i in chain]
        assert np.all(np.diff(x) > 0)
    # The same turned the other way up: the chains swap roles.
    flipped = footprint_chains(lower * [1, 1, -1], upper * [1, 1, -1])
    assert flipped == ([(1, i) for i in (2, 1, 0)] + [(0, i) for i in (1, 2, 3, 4)],
                       [(1, 2), (1, 3), (1, 4)])


def test_lines_that_run_aft_or_both_turn_back_have_no_chains():
    """Lines that run aft from the leading edge keep the blocks as they were
    (body_split.forward); two lines that both turn back are left to it too."""
    from juncture.surface.body_split import footprint_chains

    le = [10.0, 3.0, 0.0]
    aft = np.array([le, [12.0, 2.5, 1.0], [15.0, 2.0, 1.5]])
    back = np.array([le, [9.0, 2.5, 1.0], [15.0, 2.0, 1.5]])
    assert footprint_chains(aft, aft * [1, 1, -1]) is None
    assert footprint_chains(back, back * [1, 1, -1]) is None


def test_points_of_a_chain_that_turn_back_are_left_out():
    """A run that wiggles keeps the points that run aft (as body_split.forward does), and
    the forward run keeps the leading-edge point the lines share: an upper line that runs
    aft by 0.05 ft from the leading-edge point before it turns forward (a high wing whose
    upper lines pass over the fuselage, continued to the plane of symmetry ahead of the
    leading edge: they were left to forward(), the loop between the wing and the fuselage
    open and the upper block under the wing)."""
    from juncture.surface.body_split import footprint_chains

    le = [10.0, 3.0, 0.0]
    back = np.array([le, [9.0, 2.5, 1.0], [15.0, 2.0, 1.5]])
    wiggle = np.array([le, [12.0, 3.0, -1.0], [11.0, 3.0, -1.2], [15.0, 2.0, -1.5]])
    assert footprint_chains(back, wiggle) == ([(0, 1), (0, 2)],
                                              [(0, 1), (0, 0), (1, 1), (1, 3)])
    upper = np.array([le, [10.05, 2.8, 0.4], [9.5, 2.0, 1.0], [4.0, 0.0, 1.5],
                      [15.0, 0.0, 1.5]])
    lower = np.array([le, [12.0, 3.0, -1.0], [15.0, 2.0, -1.5]])
    assert footprint_chains(upper, lower) == ([(0, 3), (0, 4)],
                                              [(0, 3), (0, 2), (0, 0), (1, 1), (1, 2)])


def test_a_line_running_aft_of_the_trailing_edge_bounds_the_other_block_after_it():
    """The lower line runs aft of the trailing-edge point before it comes back to it (a line
    continued to the plane of symmetry behind the trailing edge): at those stations the
    region lies between two of its points, so that run, taken aft, bounds the upper block
    after the shared trailing edge. Both chains run aft."""
    from juncture.surface.body_split import footprint_chains

    te = [20.0, 0.5, 2.0]
    upper = np.array([[10.0, 3.0, 0.0], [12.0, 2.5, 1.0], [16.0, 1.5, 2.0], te])
    lower = np.array([[10.0, 3.0, 0.0], [13.0, 2.5, -1.0], [22.0, 0.0, -1.0], te])
    up_chain, low_chain = footprint_chains(upper, lower)
    assert up_chain == [(0, 0), (0, 1), (0, 2), (0, 3), (1, 2)]
    assert low_chain == [(1, 0), (1, 1), (1, 2)]


def test_a_blunt_trailing_edge_at_one_station_leaves_one_line_behind_it():
    """A blunt trailing edge whose two points lie at one body station (the wing's root
    section in a station's plane): the two curves end there at two points, but behind it
    both blocks end on one line (the upper's), with the same points: before, the lower
    block ran on from its own point and the body between the two lines, as long as the
    fuselage behind the wing, belonged to neither (capped flat by assembly)."""
    body = CircularBody("body", np.linspace(0.0, 100.0, 11),
                        np.r_[0.0, 3.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 3.5, 2.5, 1.0])
    xs = np.array([30.0, 40.0, 55.0])
    upper = _region(body, xs, [-0.1, 0.05, -0.1])
    lower = _region(body, xs, [-0.1, -0.3, -0.2])
    nets = split_body(body, [upper], [lower])
    up, lo = nets["body upper"][:, -1], nets["body lower"][:, -1]
    aft = lambda p: p[p[:, 0] > 55.0]  # noqa: E731
    assert len(aft(up)) >= 4 and _keys(aft(up)) == _keys(aft(lo))
    at_edge = lambda p: _keys(p[p[:, 0] == 55.0])  # noqa: E731
    assert at_edge(up) == _keys(upper.points[-1:]) and at_edge(lo) == _keys(lower.points[-1:])


@pytest.mark.slow  # a held-out airplane meshed whole (> 7 s): make test-all
def test_rows_follow_a_bounding_curve_that_runs_to_the_keel(monkeypatch):
    """A low wing on an arbitrary-section fuselage (tests/data/generated/README.md): aft of
    the wing's trailing edge the blocks' bounding curve runs down to the keel before the
    next body station, and stations are added so that it turns by at most 1 / TURNS of the
    section a step: the mesh's section mid-interval is within 0.5 % of the union's (an
    independent slice against the oracle's cells). With one interval there, the rows
    twisted round the body and their straight lines cut 11 % of the section away."""
    import warnings

    import juncture as jc
    import juncture.surface.body_split as bs
    from tests.support import DATA, section_area
    from tests.union_oracle import union_area

    deck = DATA / "generated" / "assembly" / "low_wing_whose_block_boundary_runs_to_the_keel.inp"

    def short(x):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", jc.JunctureWarning)
            geo = jc.complete(jc.read(deck))
            surface = jc.mesh(geo)
        return 1.0 - section_area(surface.vertices, surface.triangles, x) / \
            union_area(geo.configuration, x)

    assert abs(short(103.0)) < 0.005
    monkeypatch.setattr(bs, "TURNS", 1e-9)
    assert short(103.0) > 0.08


def test_rows_of_an_arbitrary_body_pass_through_its_sections_corners():
    """Every vertex the deck gives for an arbitrary section (an icosagon here), between a
    block row's ends (but within a quarter step of them), is a point of that row at the
    deck's stations: the rows keep the
    polygon (sampled at equal steps of the surface parameter they cut its corners, 0.7 % of
    the section). Checked against the deck's own points."""
    import warnings

    import juncture as jc
    import juncture.surface.body_split as bs
    from juncture.model import ArbitraryBody
    from tests.support import DATA

    deck = DATA / "generated" / "assembly" / "low_wing_whose_block_boundary_runs_to_the_keel.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))
    body = next(c for c in geo.configuration if isinstance(c, ArbitraryBody))
    checked = 0
    for name in ("body upper", "body lower"):
        net = np.asarray(geo.networks[name])
        for row in net:
            hit = np.flatnonzero(body.x == row[0, 0])
            if not hit.size or np.ptp(row[:, 0]) > 0.0:
                continue
            section = body.sections[hit[-1]]
            s = body.parameter_of(np.column_stack([np.full(len(section), row[0, 0]), section]))
            ends = body.parameter_of(row[[0, -1]])
            gap = bs.NEAR_END * np.ptp(ends) / (len(row) - 1)   # a corner at an end stays off
            inside = (s > ends.min() + gap) & (s < ends.max() - gap)
            gap = np.linalg.norm(section[inside][:, None] - row[None, :, 1:], axis=2).min(axis=1)
            assert np.all(gap < 1e-9), (name, row[0, 0], gap.max())
            checked += int(inside.sum())
    assert checked > 20


def test_a_blunt_trailing_edge_meeting_the_body_a_rounding_apart_adds_no_sliver_row():
    """A blunt, swept trailing edge cut by a cylinder, with a centre-line fin (so the fuselage
    is split into upper and lower blocks, TM-4607): its upper and lower edges meet the body
    2e-4 apart in x, and the upper block, extended to the lower edge's point, had a row at
    each, a rounding apart (held-out seed 2626 draw 12: 1.7e-5 ft). Their points on the plane
    of symmetry stayed mesh vertices (triangles of 1e-3 deg). Oracles: trimesh (closed,
    consistently wound) and the corner angles from the edge lengths (law of cosines)."""
    import dataclasses

    import trimesh

    import juncture as jc
    from juncture.model import WingLike
    from tests.support import smallest_angles, wing_body

    cfg = wing_body(camber=2.0)
    w = cfg["wing"]
    up, lo = np.array(w.upper, float), np.array(w.lower, float)
    up[:, -1], lo[:, -1] = 0.4, 0.2
    wing = dataclasses.replace(w, upper=up, lower=lo, _poly=None)
    half = np.array([0.0, 1.5, 2.5, 2.6, 1.8, 0.0])
    fin = WingLike("fin 1", "fin", np.array([[44.0, 0.0, 2.0], [50.0, 0.0, 7.0]]),
                   np.array([9.0, 4.0]), np.array([0.0, 10.0, 30.0, 50.0, 75.0, 100.0]),
                   np.tile(half, (2, 1)), np.tile(half, (2, 1)), mirrored=False)
    geo = jc.complete(cfg.with_component(wing).with_component(fin))
    assert "body upper" in geo.networks
    te_up = np.asarray(geo.intersections["wing/body upper"])[-1]
    te_lo = np.asarray(geo.intersections["wing/body lower"])[-1]
    assert 0.0 < abs(te_up[0] - te_lo[0]) < 1e-4 * 60.0

    surface = jc.mesh(geo)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert smallest_angles(surface.vertices, surface.triangles).min() >= 5.0


def test_a_low_wing_leading_edge_just_aft_of_a_body_station_leaves_no_folded_rows(monkeypatch):
    """A held-out airplane (tests/data/generated/README.md): a low wing's leading edge meets
    the elliptical fuselage 0.09 ft aft of a body station, and the blocks' bounding curve
    falls from the horizontal to the wing's root there. Stations added so that it turns
    little a step lay closer than SLIVER of the length and were closed onto the row before:
    both blocks fanned to the curve and the lower one's rows ran up and back down, over the
    upper block (78 crossing pairs, the mesh refused). Now no station is added nearer
    than that: every row of each block runs one way round the section (the surface
    parameter, the body's own), and the assembled surface passes every check (exact
    predicates). Counterfactual: the stations closer than that, closed onto the row before
    whatever their ends (as before _close_rows looked at them, the next test), fold rows."""
    import warnings

    import juncture as jc
    import juncture.surface.body_split as bs
    from juncture.surface.check import check_mesh
    from tests.support import DATA

    deck = DATA / "generated" / "assembly" / \
        "low_wing_leading_edge_just_aft_of_a_body_station.inp"

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        cfg = jc.read(deck)
        geo = jc.complete(cfg)
        assert _folded_rows(geo) == 0
        surface = jc.mesh(geo, min_angle=0)
        assert check_mesh(surface.vertices, surface.triangles).failures() == []
        turning, close = bs._turning, bs._close_rows
        monkeypatch.setattr(bs, "_turning", lambda x, th, spans, turn, gap=0.0:
                            turning(x, th, spans, turn))
        monkeypatch.setattr(bs, "_close_rows", lambda net, x, gap, ang=None:
                            close(net, x, gap))
        assert _folded_rows(jc.complete(cfg)) > 0
    # _turning itself: 0.09 ft in which the curve turns by 1, steps of at most 0.1 wanted
    # (ten), but none shorter than 0.013: six equal steps
    added = turning(np.array([0.0, 0.09]), np.array([0.0, -1.0]), [], 0.1, 0.013)
    np.testing.assert_allclose(np.diff(np.r_[0.0, added, 0.09]), 0.015, rtol=1e-12)


def _folded_rows(geo):
    """How many rows of the fuselage's upper and lower blocks run one way round the section
    and then back (by the body's own surface parameter, or angle on a circular body)."""
    body = geo.configuration["body"]
    out = 0
    for name in ("body upper", "body lower"):
        for row in np.asarray(geo.networks[name]):
            if hasattr(body, "parameter_of"):
                s = body.parameter_of(row)
            else:
                c = body.center_at(row[:, 0])
                s = np.unwrap(np.arctan2(row[:, 2] - c[:, 1], row[:, 1] - c[:, 0]))
            s = np.diff(s)
            s = s[np.abs(s) > 1e-12]
            out += int(s.size and (s.min() < 0.0 < s.max()))
    return out


def test_a_row_a_rounding_aft_of_another_keeps_its_points_where_its_end_lies_back(monkeypatch):
    """A held-out airplane (tests/data/generated/README.md) with a cubic fillet and
    keep_area: a tail's leading edge meets the fuselage 0.004 ft aft of a row that ends at
    the wing's root below it. Rows that near the one before take its points but their end
    (_close_rows): this one ran down to the wing's root and back up to the tail's edge,
    folded over the block beside it (70 crossing pairs, the mesh refused). Now a row whose
    end lies back among those points keeps its own: no row folds, and the assembled
    surface passes every check. Counterfactual: without the rows' angles it folds."""
    import warnings

    import juncture as jc
    import juncture.surface.body_split as bs
    from juncture.surface.check import check_mesh
    from tests.support import DATA

    deck = DATA / "generated" / "assembly" / \
        "tail_leading_edge_a_rounding_aft_of_a_wing_root_row.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        cfg = jc.read(deck)
        geo = jc.complete(cfg, "cubic", keep_area=True)
        assert _folded_rows(geo) == 0
        surface = jc.mesh(geo, min_angle=0)
        assert check_mesh(surface.vertices, surface.triangles).failures() == []
        close = bs._close_rows
        monkeypatch.setattr(bs, "_close_rows", lambda net, x, gap, ang=None:
                            close(net, x, gap))
        assert _folded_rows(jc.complete(cfg, "cubic", keep_area=True)) > 0


def test_a_corner_found_twice_a_hair_apart_takes_one_point_of_a_row():
    """through_corners: at the joint of two segments an arbitrary body finds each corner of
    the section once from either side's parameters (0.2560 and 0.2561); anchored twice,
    two of the row's points sat a hair apart and the triangles between them had angles
    of 0.002 deg. Corners nearer than a quarter step are one: the row holds 0.3 once,
    0.6, and its other points where they were."""
    import types

    from juncture.surface.body_split import through_corners

    body = types.SimpleNamespace(corners=lambda x: np.array([0.6, 0.3, 0.3000001]))
    row = np.linspace(0.0, 1.0, 11)
    out = through_corners(body, np.array([0.0]), row[None, :])[0]
    assert np.count_nonzero(np.abs(out - 0.3) < 1e-3) == 1
    assert 0.6 in out and 0.3 in out and 0.3000001 not in out
    assert np.all(np.diff(out) > 0.0)
    np.testing.assert_allclose(out, row, rtol=0, atol=1e-15)   # the nearest points moved
