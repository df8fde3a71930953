"""Thin strips (a blunt trailing edge's cap) in the re-triangulation."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.surface.assemble import _zip_chains, zip_strip
from juncture.surface.strips import MOST, NARROWEST, _corner_width, _graded, spacing

SPACING = spacing(25.0)


@settings(max_examples=200, deadline=None)
@given(st.floats(0.01, 100.0), st.floats(0.0, 1.0), st.floats(1e-4, 1.0))
def test_graded_pieces_are_at_most_spacing_times_the_width_where_they_start(length, w0, w1):
    """Every piece of the edge is no longer than SPACING times the strip's width at the
    piece's narrow end (linear between the edge's ends; no narrower than NARROWEST of the
    widest), unless the edge takes more than MOST pieces; where the strip pinches (w0 = 0)
    the first piece reaches no further than where it is NARROWEST of its widest."""
    t = np.concatenate([[0.0], _graded(length, w0, w1, SPACING), [1.0]])
    assert np.all(np.diff(t) > 0.0)
    if len(t) - 1 >= MOST:
        return
    thin = np.minimum(w0 + (w1 - w0) * t[:-1], w0 + (w1 - w0) * t[1:])
    most = SPACING * np.maximum(thin, NARROWEST * max(w0, w1)) / length
    ok = np.diff(t) <= most * (1.0 + 1e-9) + 1e-12
    if w0 == 0.0 and len(t) > 2:
        assert t[1] <= NARROWEST * (1.0 + 1e-9)
        ok = ok[1:]
    assert np.all(ok)


def test_a_pinched_edge_leaves_one_piece_at_the_corner():
    """A strip 0 wide at an edge's start (a trailing edge closing at a pointed tip): its
    first piece reaches to where the strip is NARROWEST of its widest (the corner's one
    triangle), the rest are graded; with the floor all the way (the old rule) the edge took
    pieces of constant length to the corner, each zipped into a triangle thinner than the
    last."""
    t = _graded(64.0, 0.0, 0.038, SPACING)
    assert t[0] == pytest.approx(NARROWEST, rel=0.02)
    assert np.all(np.diff(t) > 0.0) and np.all(np.diff(np.diff(t)) > -1e-12)
    width = 0.038 * t[:-1]
    assert np.all(np.diff(t) * 64.0 <= SPACING * width * (1.0 + 1e-6))


def test_a_strip_is_0_wide_where_it_pinches_and_a_rung_wide_where_it_ends_in_one():
    """strips._corner_width: at a corner both sides leave within PINCH of one another the
    strip is 0 wide (measured past the corner, to the other side's far points, it was 64 ft
    at a pointed wing tip whose trailing edge closes there, and the outer panel's strip was
    not split at all: 124 triangles under 5 deg along it, held-out seed 3434 draw 21); at a
    corner where one side runs across the strip (its rung, a trailing edge cut by the
    fuselage) it is the rung's length."""
    pinch_a = np.array([[0.0, 0.0, 0.0], [0.0, 64.0, 0.0], [0.0, 128.0, 0.0]])
    pinch_b = np.array([[0.0, 0.0, 0.0], [0.0, 64.0, 0.04], [0.0, 128.0, 0.0]])
    rung_b = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.1], [0.0, 64.0, 0.04],
                       [0.0, 128.0, 0.0]])
    for b, start in ((pinch_b, 0.0), (rung_b, 0.1)):
        v = np.concatenate([pinch_a, b[1:-1]])
        a_ids = np.arange(3)
        b_ids = np.concatenate([[0], 3 + np.arange(len(b) - 2), [2]])
        w = _corner_width(v, a_ids, b_ids)
        assert w == (pytest.approx(start), 0.0)


def test_graded_is_the_same_edge_from_either_end():
    a = _graded(10.0, 0.05, 0.4, SPACING)
    b = _graded(10.0, 0.4, 0.05, SPACING)
    np.testing.assert_allclose(np.sort(1.0 - a), b, atol=1e-15)


def _chains():
    """Two sides of a strip 0.01 wide between shared corners at x = 0 and x = 1: side a has
    ten points on its first straight piece, side b none."""
    a = np.concatenate([[[0.0, 0.0, 0.0]], np.linspace([0.01, 0.0, 0.0], [0.1, 0.0, 0.0], 10),
                        [[0.5, 0.0, 0.0], [1.0, 0.0, 0.0]]])
    b = np.array([[0.0, 0.0, 0.0], [0.5, 0.01, 0.0], [1.0, 0.0, 0.0]])
    return a, b


def _areas(p, tri):
    q = p[tri]
    return 0.5 * np.linalg.norm(np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0]), axis=1)


def test_the_diagonal_zip_fans_a_straight_side_from_its_corner():
    """What the angle rule mends: zipped by the shorter diagonal, the points on a's first
    piece are fanned from the shared corner, on one straight line (zero area)."""
    a, b = _chains()
    n, m = len(a), len(b)
    local = _zip_chains(a, b)
    both = [(0, n), (n - 1, n + m - 1)]                 # the shared corners' two ids
    real = local[[not any(u in t and v in t for u, v in both) for t in local.tolist()]]
    assert np.sum(_areas(np.concatenate([a, b]), real) == 0.0) >= 5


def test_the_angle_zip_leaves_the_shared_corners_onto_both_sides():
    """Zipped by angles, no triangle is flat and the strip is covered once: its triangles'
    areas add up to the polygon's."""
    a, b = _chains()
    n = len(a)
    vertices = np.concatenate([a, b[1:-1]])
    ids_a = np.arange(n)
    ids_b = np.concatenate([[0], n + np.arange(len(b) - 2), [n - 1]])
    tri = zip_strip(vertices, ids_a, ids_b, angles=True)
    areas = _areas(vertices, tri)
    assert areas.min() > 0.0
    assert areas.sum() == pytest.approx(0.5 * 1.0 * 0.01, rel=1e-12)   # the triangle a-b1-a


@pytest.mark.slow  # one airplane meshed whole (> 5 s): make test-all
def test_a_blunt_trailing_edge_is_zipped_and_the_wing_beside_it_keeps_good_angles():
    """The generated airplane with a blunt trailing edge (tests/data/generated/README.md):
    its strip's sides are split to a few times its width, so the wing surfaces beside it need
    no slivers (183 triangles under 5 deg there before) and the strip's own triangles are
    about atan(1 / SPACING) but where it pinches to the root."""
    import warnings

    import trimesh

    import juncture as jc
    from juncture.surface.quality import triangle_angles
    from tests.support import DATA

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(DATA / "generated" / "arbitrary_body_blunt_trailing_edge.inp"))
        surface = jc.mesh(geo)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    smallest = triangle_angles(surface.vertices, surface.triangles).min(axis=1)
    name = np.array(surface.surfaces)[surface.surface]
    wing = np.isin(name, ["wing upper", "wing lower", "wing upper image", "wing lower image"])
    assert smallest[wing].min() >= 5.0
    # The strip's own triangles (the tip, capped in its plane since 2026-11-27, left out:
    # every corner there at the tip's span station).
    y = np.abs(surface.vertices[surface.triangles][:, :, 1])
    cap = (name == "wing cap") & (np.ptp(y, axis=1) > 0.0)
    assert np.mean(smallest[cap] >= 0.8 * np.degrees(np.arctan(1.0 / SPACING))) >= 0.9


def test_the_angle_zip_does_not_run_away_along_the_finer_chain():
    """A pinched strip's side split finely near the pinch, the other side coarse: the angle
    rule alone ran along the fine side from the pinch and joined its points to the far
    side's first point, a triangle over three quarters of the strip. No triangle now spans
    more than the coarse side's longest piece."""
    run = np.concatenate([[0.0], np.geomspace(1e-3, 1.0, 40), np.linspace(1.5, 10.0, 18)])
    a = np.stack([run, np.zeros(run.size), np.zeros(run.size)], axis=1)
    b = np.array([[0.0, 0.0, 0.0], [2.5, 0.05, 0.0], [5.0, 0.05, 0.0], [7.5, 0.05, 0.0],
                  [10.0, 0.0, 0.0]])
    tri = _zip_chains(a, b, angles=True)
    x = np.concatenate([a, b])[tri][:, :, 0]
    assert np.ptp(x, axis=1).max() <= 2.5 + 1e-12
    assert len(tri) == len(a) + len(b) - 2


@pytest.mark.slow  # a held-out airplane meshed whole (> 7 s): make test-all
def test_a_tip_and_strip_cap_is_charted_and_zipped_apart():
    """The generated airplane whose blunt trailing edge runs into a thick tip
    (tests/data/generated/README.md), capped as tip and strip: re-triangulated, the strip is
    zipped and only the tip charted (as one chart the strip was refined down to its width
    and pushed points thousandths of a foot apart onto the wing's trailing edges: 51 wing
    triangles under 5 deg); the enclosed volume is within 0.5 % of the union's cell count
    (-0.76 % before)."""
    import warnings

    import juncture as jc
    from juncture.surface.assemble import assemble
    from juncture.surface.patches import patches
    from juncture.surface.quality import triangle_angles
    from juncture.surface.strips import tip_and_strip
    from tests.support import DATA
    from tests.union_oracle import union_volume

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(DATA / "generated" / "blunt_trailing_edge_into_a_thick_tip.inp"))
        surface = jc.mesh(geo)
    assembled = assemble(geo)
    cap = assembled.surfaces.index("wing cap")
    found = [tip_and_strip(assembled, rows) for rows in patches(assembled)
             if assembled.surface[rows[0]] == cap]
    assert found and all(f is not None and len(f[0]) and len(f[1].rows) for f in found)
    smallest = triangle_angles(surface.vertices, surface.triangles).min(axis=1)
    name = np.array(surface.surfaces)[surface.surface]
    wing = np.isin(name, ["wing upper", "wing lower", "wing upper image", "wing lower image"])
    assert smallest[wing].min() >= 5.0
    ref = union_volume(geo.configuration, n=121, cells=1500)
    assert abs(surface.volume() / ref - 1.0) < 0.005


def test_a_wing_of_two_sections_grades_down_to_its_strip(monkeypatch, slow=False):
    """A generated wing of two sections (tests/data/generated/README.md) with a wedge of a
    trailing edge, 0.017 ft thick at the tip and closed at the root: its surfaces grade down
    to the strip's pieces (remesh.FINEST), and the strip is graded from its width at the
    corners its sides share measured to the other side without that corner
    (strips._corner_width): measured to the corner itself it is 0 there, the side was split
    ever finer towards it and its pieces fanned against the other side's (18 triangles under
    5 deg; none now). At FINEST = 1e-3 of the charts' median edge (the span) as well, the
    wing's surfaces fanned the strip's pieces too (1,890)."""
    import warnings

    import juncture as jc
    import juncture.surface.remesh as rm
    import juncture.surface.strips as st
    from juncture.surface.quality import triangle_angles
    from tests.support import DATA

    deck = DATA / "generated" / "remesh" / "two_section_wing_with_a_thin_wedge_trailing_edge.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))

    def slivers(caps=True):
        """Triangles under 5 deg (outside the caps unless ``caps``)."""
        surface = jc.mesh(geo)
        smallest = triangle_angles(surface.vertices, surface.triangles).min(axis=1)
        cap = np.char.endswith(np.array(surface.surfaces)[surface.surface].astype(str), " cap")
        return int(np.sum((smallest < 5.0) & (caps | ~cap)))

    assert slivers() == 0
    if not slow:
        return
    monkeypatch.setattr(st, "_corner_width", lambda vertices, side, other: (0.0, 0.0))
    assert slivers() > 10
    monkeypatch.setattr(rm, "FINEST", 1e-3)
    assert slivers(caps=False) > 1000


@pytest.mark.slow
def test_slow_a_wing_of_two_sections_fans_its_strip_without_its_corner_width(monkeypatch):
    """The counterfactuals of the test above (three more meshes of the airplane)."""
    test_a_wing_of_two_sections_grades_down_to_its_strip(monkeypatch, slow=True)


@pytest.mark.slow  # a held-out airplane meshed whole (> 7 s): make test-all
def test_a_blunt_trailing_edge_cut_by_the_body_keeps_its_root_edge(monkeypatch):
    """A wing's blunt trailing edge cut by a flat panel of an octagonal fuselage
    (tests/data/generated/README.md): the strip closing it ends in the edge across it where
    the body cuts it (its root rung), so it is as wide at the root as the deck makes it, and
    no triangle of the wing is under 5 deg. With the old straight lens the body's point at the
    lower trailing edge's root was taken into the upper trailing edge, the strip narrowed to
    it and was split ever finer towards it (slivers down to 0.1 deg)."""
    import warnings

    import juncture as jc
    import juncture.surface.seams as seams
    from juncture.surface.quality import triangle_angles
    from tests.support import DATA

    deck = DATA / "generated" / "remesh" / "blunt_trailing_edge_cut_by_a_polygon_body.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))
    upper, lower = (np.asarray(geo.networks[f"wing {s}"]) for s in ("upper", "lower"))
    root = (upper[0, -1], lower[-1, -1])               # the trailing edge's root points
    assert np.linalg.norm(root[0] - root[1]) > 0.06

    def smallest():
        """The smallest angle of the wing's triangles (its surfaces and its caps)."""
        surface = jc.mesh(geo)
        name = np.array(surface.surfaces)[surface.surface].astype(str)
        wing = np.char.startswith(name, "wing ")
        return triangle_angles(surface.vertices, surface.triangles[wing]).min()

    assert smallest() >= 5.0
    monkeypatch.setattr(seams, "END", np.inf)   # the lens as wide at its ends as between
    assert smallest() < 1.0


@pytest.mark.slow  # a held-out airplane meshed whole (> 7 s): make test-all
def test_a_wing_split_to_its_strips_spacing_grades_away_from_it(monkeypatch, slow=False):
    """A swept wing of four ordinates per section with a trailing edge 0.015 ft thick
    (tests/data/generated/README.md): its trailing edge is split into thousands of pieces
    for the strip, and the wing's surfaces grade away from them with good angles: refinement
    may add points per split point on a patch's edges as well as per point of its own
    (remesh._budget); counting its own only, a fifth of the wing's triangles were under
    20 deg."""
    import warnings

    import juncture as jc
    import juncture.surface.remesh as rm
    from juncture.surface.quality import triangle_angles
    from tests.support import DATA

    deck = DATA / "generated" / "remesh" / "wing_of_four_ordinates_with_a_thin_trailing_edge.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))

    def share_under_20():
        surface = jc.mesh(geo)
        smallest = triangle_angles(surface.vertices, surface.triangles).min(axis=1)
        name = np.array(surface.surfaces)[surface.surface]
        wing = np.isin(name, ["wing upper", "wing lower", "wing upper image",
                              "wing lower image"])
        return float(np.mean(smallest[wing] < 20.0))

    assert share_under_20() < 0.002
    if not slow:
        return
    own = rm._budget

    def own_points_only(patch, n):
        return own(patch, n - (n - int(patch.kept.sum()) - sum(map(len, patch.extra_uv))))

    monkeypatch.setattr(rm, "_budget", own_points_only)
    assert share_under_20() > 0.1


@pytest.mark.slow
def test_slow_a_wing_split_to_its_strips_spacing_without_the_budget_for_it(monkeypatch):
    """The counterfactual of the test above (one more mesh of a 170k-triangle airplane), on
    the surface it was found on (seams on their chords, not followed to the exact curve)."""
    import juncture.surface.seam_curves as sc

    monkeypatch.setattr(sc, "seam_curves", lambda geometry, mesh: None)
    test_a_wing_split_to_its_strips_spacing_grades_away_from_it(monkeypatch, slow=True)


def centre_fin_airplane():
    """(completed geometry, fin root and tip leading edges, chords): a centre-line fin
    with a blunt trailing edge (0.3 % of the chord each side) on the cambered wing-body of
    tests/support.py, whose fuselage has a pointed nose."""
    import juncture as jc
    from juncture.model import WingLike
    from tests.support import wing_body

    half = np.array([0.0, 1.5, 2.5, 2.6, 1.8, 0.3])          # per cent of the chord
    le, chord = np.array([[44.0, 0.0, 2.0], [50.0, 0.0, 7.0]]), np.array([9.0, 4.0])
    fin = WingLike("fin 1", "fin", le, chord, np.array([0.0, 10.0, 30.0, 50.0, 75.0, 100.0]),
                   np.tile(half, (2, 1)), np.tile(half, (2, 1)), mirrored=False)
    return jc.complete(wing_body(camber=2.0).with_component(fin)), le, chord


@pytest.mark.slow  # one airplane meshed whole (> 5 s): make test-all
def test_a_centre_fin_s_blunt_trailing_edge_is_capped_to_the_fuselage():
    """A centre-line fin with a blunt trailing edge (0.3 % of the chord each side) on a
    cylinder: its strip's root end runs from one side's root over the fuselage's top line
    to the other's, so the strip's two sharpest turns were both there, its chains were taken
    from one to the other and refused, and the fin was left open (no mesh: 22 open edges).
    The strip is split at the turns farthest apart along it (its tip and its root). Oracles:
    trimesh (closed, consistently wound), the fin's planform and ordinates (every cap vertex
    on the tip's plane or at the blunt trailing edge, within its half-thickness of the plane
    of symmetry), the corner angles."""
    import trimesh

    import juncture as jc
    from juncture.surface.quality import triangle_angles

    geo, le, chord = centre_fin_airplane()
    surface = jc.mesh(geo)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    cap = surface.surfaces.index("fin 1 cap")
    p = surface.vertices[np.unique(surface.triangles[surface.surface == cap])]
    s = (p[:, 2] - le[0, 2]) / (le[1, 2] - le[0, 2])         # ruled, extended below the root
    c = chord[0] + s * (chord[1] - chord[0])
    te = le[0, 0] + s * (le[1, 0] - le[0, 0]) + c
    z = p[:, 2]
    tip = z == le[1, 2]
    # on the trailing edge, or where its root end crosses the fuselage's top line (0.02 aft)
    edge = (np.abs(p[:, 0] - te) < 0.05) & (np.abs(p[:, 1]) <= 0.003 * c + 1e-12)
    assert np.all(tip | edge)
    assert triangle_angles(surface.vertices, surface.triangles).min() >= 5.0


@pytest.mark.slow  # a held-out airplane meshed whole (> 10 s): make test-all
def test_a_strip_closing_at_a_pointed_tip_is_split_to_its_spacing_up_to_its_last_tenth():
    """The generated airplane whose blunt trailing edge closes at a wing tip of no chord
    (tests/data/generated/README.md): the strip pinches there, so its side is split to its
    spacing but for the last tenth of the edge to the tip (strips._graded). Its triangles
    under 5 deg all lie there, where the wing's charts split that piece (before, measured
    past the corner, the strip was 64 ft wide at the tip, not split, and had slivers along
    the whole outer panel, from 63 ft inboard of the tip)."""
    import warnings

    import trimesh

    import juncture as jc
    from juncture.surface.quality import triangle_angles
    from tests.support import DATA

    deck = DATA / "generated" / "remesh" / "blunt_trailing_edge_closing_at_a_pointed_tip.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))
        surface = jc.mesh(geo)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    smallest = triangle_angles(surface.vertices, surface.triangles).min(axis=1)
    name = np.array(surface.surfaces)[surface.surface]
    tip, before = 136.58, 72.67               # the tip's and the section before's span station
    y = np.abs(surface.vertices[surface.triangles][:, :, 1]).min(axis=1)
    cap = name == "wing cap"
    assert np.any(cap & (smallest < 5.0))     # the corner's piece: what is left (see above)
    assert np.all(y[cap & (smallest < 5.0)] >= tip - NARROWEST * (tip - before) - 1e-6)
    outer = cap & (y > before + 1.0) & (y < tip - NARROWEST * (tip - before))
    assert outer.sum() > 1000 and smallest[outer].min() >= 5.0
