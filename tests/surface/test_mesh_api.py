"""``juncture.mesh(geo)``: the assembled surface, checked, or a one-line refusal."""

import warnings

import numpy as np
import pytest
import trimesh

import juncture as jc
from juncture.analysis.areas import normal_area_distribution
from tests.support import DATA, EXAMPLE_DECK, PDAS_DECK, smallest_angles
from tests.union_oracle import union_volume


def _complete(deck, fillet=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.complete(jc.read(deck), fillet)


def test_mesh_of_a_wing_body_is_closed_for_trimesh():
    surface = jc.mesh(_complete(PDAS_DECK, "cubic"))
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert tm.volume == pytest.approx(surface.volume(), rel=1e-12)
    assert surface.volume() > 0


def test_mesh_refuses_an_open_surface_in_one_line():
    geo = _complete(PDAS_DECK)
    nets = {k: v for k, v in geo.networks.items() if k != "wing-body upper"}
    open_geo = geo.replace(networks=nets,
                           symmetry={k: v for k, v in geo.symmetry.items() if k in nets})
    with pytest.raises(jc.GeometryError, match="the completed surface is not closed") as err:
        jc.mesh(open_geo)
    assert "\n" not in str(err.value)
    unchecked = jc.mesh(open_geo, check=False)
    assert len(unchecked.open_loops) > 0


def test_the_complete_transport_closes_pods_pylons_fins_and_tail_included():
    """Every seam of the bundled airplane: wing/body, pylons on the wing (cut into its lower
    surface) and on their nacelles, the centre fin and the tail on the fuselage."""
    geo = _complete(EXAMPLE_DECK)
    surface = jc.mesh(geo, min_angle=0)  # checked; the re-triangulation: test_remesh, test_lift
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert tm.volume == pytest.approx(surface.volume(), rel=1e-12)
    # Every intersection point (and its mirror image) is a mesh vertex, bit for bit.
    verts = {tuple(v) for v in (surface.vertices + 0.0).tolist()}
    for name, pts in geo.intersections.items():
        for p in np.asarray(pts)[np.all(np.isfinite(pts), axis=1)]:
            assert tuple((p + 0.0).tolist()) in verts, name
            assert tuple((p * [1.0, -1.0, 1.0] + 0.0).tolist()) in verts, name
    # Independent of the networks: the model's union of normal areas A(x), integrated.
    # The mesh's flat panels between network points cut the curved surfaces' chords, so it
    # is below the model's volume by their sag (about 1 % at the networks' spacing).
    dist = normal_area_distribution(geo.configuration, n_x=801, flow_through=False)
    exact = np.trapezoid(dist["total"], dist["x"])
    assert -0.015 < surface.volume() / exact - 1.0 < 0.0
    names = set(surface.components)
    assert {"body", "wing", "pod 1", "pod 2", "fin 1", "fin 2", "fin 3", "tail 1"} <= names


def _model_volume(cfg, n_x=801):
    dist = normal_area_distribution(cfg, n_x=n_x, flow_through=False)  # 0.03 % high
    return np.trapezoid(dist["total"], dist["x"])


def test_refine_brings_the_transport_volume_within_half_a_percent_of_the_model():
    cfg = jc.read(EXAMPLE_DECK)
    exact = _model_volume(cfg)
    # the networks' own triangles (min_angle=0): the re-triangulation's sag is its own test
    coarse = jc.mesh(_complete_refined(cfg, 1), min_angle=0).volume()
    fine = jc.mesh(_complete_refined(cfg, 2), min_angle=0).volume()
    assert abs(fine / exact - 1.0) < 0.005 < abs(coarse / exact - 1.0)
    assert coarse < fine < exact          # flat panels inside the convex-ish surfaces


@pytest.mark.slow
def test_the_volume_converges_under_refinement():
    cfg = jc.read(EXAMPLE_DECK)
    exact = _model_volume(cfg)
    err = [jc.mesh(_complete_refined(cfg, k), min_angle=0).volume() / exact - 1.0
           for k in (1, 2, 3, 4)]
    assert all(abs(b) < abs(a) for a, b in zip(err, err[1:]))
    # The fuselage stations are the deck's: what is left is its linear panels between them.
    assert abs(err[-1]) < 0.003


def _complete_refined(cfg, k):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.complete(cfg, refine=k)


# generated/assembly: airplanes whose assembled surface closes, but whose re-triangulation
# does not yet reach test_remesh's angles (tests/data/generated/README.md)
GENERATED = sorted((DATA / "generated").glob("*.inp")) + sorted(
    (DATA / "generated" / "assembly").glob("*.inp"))


@pytest.mark.parametrize("deck", GENERATED, ids=[p.stem for p in GENERATED])
def test_generated_airplanes_close(deck):
    """Airplanes juncture was not built on (tests/data/generated): closed, oriented, no
    crossing triangles, every intersection point a vertex, and the volume below the
    model's union of normal areas (overlaps counted once) by no more than the flat panels'
    sag, never above it (the re-triangulated surface's volume: test_remesh)."""
    cfg = jc.read(deck)
    geo = _complete_refined(cfg, 1)
    surface = jc.mesh(geo, min_angle=0)     # the assembly; test_remesh re-triangulates
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    verts = {tuple(v) for v in (surface.vertices + 0.0).tolist()}
    for name, pts in geo.intersections.items():
        for p in np.asarray(pts)[np.all(np.isfinite(pts), axis=1)]:
            assert tuple((p + 0.0).tolist()) in verts, name
    # The model kept with the geometry (roots outside the fuselage continued to it). Never
    # above it (no overlap counted twice); below it by the networks' flat panels, which
    # follow the deck's resolution: a pod given at four stations loses a third of its area
    # near its nose between them, a circular fuselage given five points per half-section
    # (NRADX = 5) is an octagon, 10 % short. 401 stations: the trapezoidal rule within 5e-4
    # of 3201 stations' on every one of these airplanes (801: 3e-4, twice the time); their
    # meshes lie 0.15 % to 4.6 % below it.
    model = _model_volume(geo.configuration, n_x=401)
    assert -0.15 < surface.volume() / model - 1.0 < 1e-3


@pytest.mark.parametrize("fillet", ["cubic", "circular"])
@pytest.mark.parametrize("keep_area", [False, True])
def test_the_transport_with_a_fillet_closes(fillet, keep_area):
    """The fillets' strips, the fuselage blocks beside them and the degenerate fillet lines
    at the leading and trailing edges all meet by vertex ids; with keep_area the fuselage
    gives up what the fillets add, so the enclosed volume is the sharp airplane's; without
    it the fillets add the integral of their added section areas (the paper's closed form,
    integrated along x here), to the networks' resolution (1e-3: the circular fillet adds
    12 ft^3, 2e-4 of the airplane, the cubic one 294)."""
    from scipy.integrate import trapezoid

    cfg = jc.read(EXAMPLE_DECK)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(cfg, fillet, keep_area)
        surface = jc.mesh(geo, min_angle=0)
        sharp = jc.mesh(jc.complete(cfg), min_angle=0).volume()
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    if keep_area:
        assert surface.volume() == pytest.approx(sharp, rel=1e-3)
    else:
        added = trapezoid(geo.stations["area_fillet"], geo.stations["x"])
        assert surface.volume() == pytest.approx(sharp + added, rel=1e-3)
        if fillet == "cubic":
            assert surface.volume() > sharp + 0.5 * added


def test_a_tail_root_running_through_the_wing_root_is_refused_by_name():
    """A tail whose root begins inside the wing's junction with the fuselage, near the wing's
    root trailing edge (tests/data/generated/refused): one runs through the other, so
    complete refuses in one line naming both, the stations and what to move."""
    from juncture.intersect.pairs import Pair, intersect_pair

    deck = DATA / "generated" / "refused" / "tail_root_overlaps_wing_root.inp"
    cfg = jc.read(deck)
    # Independently of the refusal's polygon test: the tail's leading-edge point on the
    # body lies between the wing's upper and lower lines there, round the body's axis.
    body = cfg["body"]

    def angle(p):
        c = body.center_at(p[:, 0])
        return np.arctan2(p[:, 2] - c[:, 1], p[:, 1] - c[:, 0])
    up, lo = intersect_pair(cfg, Pair("wing", "body", "body"))
    tail = intersect_pair(cfg, Pair("tail 1", "body", "body"))[0].points[:1]
    x = tail[0, 0]
    a_up, a_lo = (np.interp(x, p.points[:, 0], angle(p.points)) for p in (up, lo))
    assert min(a_up, a_lo) < angle(tail)[0] < max(a_up, a_lo)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        with pytest.raises(jc.GeometryError) as err:
            jc.complete(cfg, fillet=None)
    msg = str(err.value)
    assert "\n" not in msg
    assert msg.startswith("tail 1: its junction with body")
    assert "overlaps that of wing" in msg and "move tail 1 clear of wing" in msg


def test_a_canard_buried_past_mid_span_keeps_its_exposed_part():
    """A canard whose root lies deep in a wide fuselage meets it nearer its tip than its
    root (tests/data/generated/README.md): the network kept runs from that line to the tip,
    every point of it outside the fuselage (the fuselage's own signed distance)."""
    cfg = jc.read(DATA / "generated" / "arbitrary_body_canard_root_buried_past_mid_span.inp")
    geo = _complete_refined(cfg, 1)
    body, canard = cfg["body"], cfg["canard 1"]
    size = float(body.length)
    for side in ("upper", "lower"):
        net = np.asarray(geo.networks[f"canard 1 {side}"])
        assert body.signed_distance(net).min() > -1e-9 * size
        tip = canard.le[-1, 1]
        assert np.isclose(net[..., 1].max(), tip)


def test_a_pylon_without_its_pod_keeps_the_part_below_the_wing():
    """The transport without its pods: the pylons (fin 1, fin 2) hang from the wing's lower
    surface, their tips inside the wing and their roots free. The end trimmed is the one
    inside the wing (it met the wing nearer its root, where the fuselage rule would have
    trimmed the root), so the pylon's points lie on or below the wing's lower surface at
    their span station and chord fraction (the model's own sections), and the airplane
    closes (trimesh)."""
    cfg = jc.read(EXAMPLE_DECK)
    cfg = cfg.replace(components={k: v for k, v in cfg.components.items()
                                  if not k.startswith("pod")})
    geo = _complete_refined(cfg, 1)
    wing = cfg["wing"]
    for side in ("outboard", "inboard"):
        p = np.asarray(geo.networks[f"fin 1 {side}"]).reshape(-1, 3)
        le = wing.point(p[:, 1], np.zeros(len(p)), "upper")[:, 0]
        te = wing.point(p[:, 1], np.ones(len(p)), "upper")[:, 0]
        lower = wing.point(p[:, 1], (p[:, 0] - le) / (te - le), "lower")[:, 2]
        assert np.all(p[:, 2] <= lower + 1e-9 * 300.0)
    surface = jc.mesh(geo, min_angle=0)   # every check; the re-triangulation is not at stake
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent and surface.volume() > 0


@pytest.mark.parametrize("keep_area", [False, True])
def test_a_pointed_tail_given_as_one_point_stays_one_point(keep_area):
    """An arbitrary fuselage whose last section is one point repeated (a generated airplane,
    tests/data/generated/README.md): every network row there is that one point, bit for bit,
    with the fuselage as given and re-designed (keep_area scales its sections), so the
    surface closes at it. The section blend a + w (b - a) had put them an ulp apart."""
    cfg = jc.read(DATA / "generated" / "arbitrary_body_pointed_upswept_tail.inp")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(cfg, "cubic" if keep_area else None, keep_area)
    tip = np.asarray(cfg["body"].sections[-1])[0]
    for name in ("body upper", "body lower"):
        net = np.asarray(geo.networks[name])
        end = net[np.argmax(net[:, 0, 0])]
        assert {tuple(p) for p in end.tolist()} == {(cfg["body"].x[-1], *tip.tolist())}
    surface = jc.mesh(geo, min_angle=0)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent


def test_a_pointed_circular_tail_is_one_point():
    """A circular fuselage whose last radius is 0: the cubic through the stations gives
    8.9e-16 there, and the sections at the end were a ring of points that far apart (the
    fuselage's blocks were then not charted for re-triangulation: slivers). The value at
    the last station is the deck's."""
    cfg = jc.read(EXAMPLE_DECK)
    body = cfg["body"]
    body = type(body)(body.name, body.x, np.r_[body.radius[:-1], 0.0], body.camber,
                      body.origin, body.segments)
    x = body.x_global[-1]
    assert body.radius_at(np.array([x]))[0] == 0.0
    pts = body.point(np.full(7, x), np.linspace(-0.5 * np.pi, 0.5 * np.pi, 7))
    assert len({tuple(p) for p in (pts + 0.0).tolist()}) == 1


@pytest.mark.slow
def test_curvature_and_depth_bring_the_transport_within_half_a_percent():
    """Sizing by the exact surfaces (deviation.bent): edges turning by at most 10 deg of a
    curved surface and cutting into it by at most 3e-3 of its size bring the enclosed volume
    from 0.67 % to under 0.5 % short of the model's, still closed and valid."""
    import trimesh

    cfg = jc.read(EXAMPLE_DECK)
    exact = _model_volume(cfg)
    geo = _complete_refined(cfg, 1)
    default = jc.mesh(geo)
    sized = jc.mesh(geo, curvature=10.0, depth=3e-3)
    tm = trimesh.Trimesh(sized.vertices, sized.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert abs(sized.volume() / exact - 1.0) < 0.005 < abs(default.volume() / exact - 1.0)
    assert len(sized.triangles) > len(default.triangles)
    # against the union counted by cells (a fin standing on the wing counted once; the
    # model's A(x) counts the overlap twice, 0.14 % of the volume): -0.51 % and -0.30 %
    cells = union_volume(geo.configuration, n=201, cells=3000)
    assert abs(sized.volume() / cells - 1.0) < 0.004
    assert abs(sized.volume() / cells - 1.0) < abs(default.volume() / cells - 1.0)


def test_a_canard_inside_the_fillets_region_is_refused_by_name():
    """A canard whose root (x 18.1 to 21.0) runs beside the wing's leading edge (18.4) at
    its height, inside the cubic fillet's region (tests/data/generated/refused; seed 9696,
    draw 6): complete refuses in one line naming both, the stations and which to move
    (the wing covers the body up to its fillet's start lines). Oracle: the canard's
    intersection points at the fillet's stations lie round the body between the fillet's
    two start lines (completed without the canard), each line's angle interpolated in x.
    Without a fillet the two junctions are clear of each other and it completes."""
    from juncture.intersect import intersect_body_both

    deck = DATA / "generated" / "refused" / "canard_at_the_wing_height_by_its_fillet.inp"
    cfg = jc.read(deck)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        with pytest.raises(jc.GeometryError) as err:
            jc.complete(cfg, fillet="cubic", keep_area=True)
        jc.complete(cfg)
        alone = cfg.replace(components={k: v for k, v in cfg.components.items()
                                        if k != "canard 1"})
        fillet = jc.complete(alone, fillet="cubic", keep_area=True).fillets
    msg = str(err.value)
    assert "\n" not in msg
    assert msg.startswith("canard 1: its junction with body")
    assert "overlaps that of wing fillet" in msg and "move canard 1 clear of" in msg
    body = cfg["body"]

    def angle(p):
        c = body.center_at(p[:, 0])
        return np.arctan2(p[:, 2] - c[:, 1], p[:, 1] - c[:, 0])
    starts = [fillet[f"fillet {side}"][:, 0] for side in ("upper", "lower")]
    canard = np.concatenate([i.points for i in intersect_body_both(cfg["canard 1"], body)])
    canard = canard[np.all(np.isfinite(canard), axis=1)]
    lo, hi = max(s[:, 0].min() for s in starts), min(s[:, 0].max() for s in starts)
    at = canard[(canard[:, 0] > lo) & (canard[:, 0] < hi)]
    up, low = (np.interp(at[:, 0], *zip(*sorted(zip(s[:, 0], angle(s))))) for s in starts)
    between = (angle(at) < np.maximum(up, low)) & (angle(at) > np.minimum(up, low))
    assert len(at) and between.any()


def test_a_fin_root_overhanging_the_fuselage_is_refused_naming_its_lines():
    """A generated twin fin (tests/data/generated/refused; seed 9696, draw 15) whose root
    runs aft off a narrowing tail cone: lofting lines 7 to 9 never meet the fuselage, keep
    their input root points, and the cap closing the root crosses the fuselage. mesh
    refuses in one line that names the fin, the lines and what to change, before what it
    leads to. Oracle: those lines' input root points lie outside the fuselage on both
    sides (its own signed distance), the first four inside it: the root crosses it."""
    deck = DATA / "generated" / "refused" / "fin_root_overhanging_the_tail_cone.inp"
    cfg = jc.read(deck)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(cfg)
    with pytest.raises(jc.GeometryError) as err:
        jc.mesh(geo, min_angle=0)
    msg = str(err.value)
    assert "\n" not in msg
    assert "fin 2: lofting lines 7, 8, 9 never meet body" in msg
    assert "move fin 2 so that its root section lies on or inside body" in msg
    for side in ("upper", "lower"):
        outside = cfg["body"].signed_distance(cfg["fin 2"].lofting_lines(side)[:, 0]) > 0
        assert outside[6:].all() and not outside[:4].any()


def test_a_fin_standing_partly_on_the_fuselage_partly_on_a_tail_is_refused_by_name():
    """A generated canted twin fin (deck_from_seed(1096, ...), session 26) whose root stands
    on a narrowing tail cone forward and on the tail aft: the root line crosses the tail /
    fuselage junction, a point where three surfaces meet that juncture does not build. mesh
    refuses in one line naming the fin, both hosts and what to change, before what it leads
    to. Oracle: the fin's outboard root points lie on the fuselage (its own signed distance,
    0 to 1e-9 L) forward and off it (outside by more than 1e-3 L) aft."""
    from tests.deckgen import deck_from_seed, read_text

    text, desc = deck_from_seed(1096, ("fins", "canards"), canards="canard+tail",
                                section="arbitrary")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(read_text(text))
    root = np.asarray(geo.networks["fin 1 outboard"])[0]
    d = geo.configuration["body"].signed_distance(root) / desc["length"]
    assert (np.abs(d) <= 1e-9).sum() >= 3 and (d > 1e-3).sum() >= 2
    with pytest.raises(jc.GeometryError) as err:
        jc.mesh(geo, min_angle=0)
    msg = str(err.value)
    assert "\n" not in msg
    assert msg.startswith("the completed surface is not closed and valid: fin 1 stands partly "
                          "on body and partly on tail 1: its root crosses their junction")
    assert "move fin 1 so that its root lies on one of them" in msg


@pytest.mark.slow  # one held-out airplane, three re-triangulations (~10 s): make test-all
def test_surfaces_that_cross_where_a_wing_passes_under_a_tail_cone_are_mended_locally():
    """A low wing whose trailing-edge line passes under the narrowing tail cone
    (tests/data/generated/README.md): the re-triangulated fuselage block and wing surface
    crossed there, and the retry kept both surfaces' network triangles (0.797 of the
    triangles at 20 deg or more, smallest 0.04 deg). Only the triangles near the crossing
    are now re-triangulated on the assembled surface: closed, no crossing (the check
    inside mesh, and trimesh), nearly every triangle at 20 deg or more. Since the fuselage's
    rows behind the trailing edge start from the body, not from the wing's end point under
    it (session 33, `body_split._beyond_rows`: no web from the body to that point), the
    mended triangles at the wing's root near the trailing edge are thinner: smallest 1.47
    deg (2.99 before), 62 under 5 deg (4 before), 99.4 % at 20 deg or more."""
    deck = DATA / "generated" / "remesh" / "low_wing_trailing_edge_under_a_narrowing_tail_cone.inp"
    geo = _complete(deck)
    with warnings.catch_warnings():
        warnings.simplefilter("error", jc.JunctureWarning)   # the re-triangulation kept
        surface = jc.mesh(geo)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    angles = smallest_angles(surface.vertices, surface.triangles)
    assert np.mean(angles >= 20.0) > 0.99 and angles.min() > 1.0


@pytest.mark.slow  # two held-out airplanes meshed three times (~40 s): make test-all
def test_triangles_held_where_surfaces_crossed_are_lifted_away_from_the_crossing(monkeypatch):
    """Held-out airplanes (tests/data/generated/README.md) whose re-triangulated fuselage
    block and low wing crossed: the retry holds the fuselage's network triangles near the
    crossing (`pipeline._held_near`), facets up to ten feet long and a quarter of the circle
    round. Their new points were left on them (0.27 ft inside; the canted fin's airplane
    1.7 % short of the union's volume); they are now lifted but within a crossing's reach,
    rising from there at 1 / TAPER. The low wing under a narrowing tail cone still takes that
    path: closed, wound consistently (trimesh), within 0.5 % of the union's cells
    (tests/union_oracle.py; -0.30 %), and left unlifted the held points leave it further short
    (-0.43 %). The canted fin's airplane no longer crosses since session 34 (the lift at a
    tip of no chord): meshed on the first try, -0.41 % (-0.52 % with the held retry)."""
    import juncture.surface.patch_roles as patch_roles
    import juncture.surface.pipeline as pipeline

    held = []
    near = pipeline._held_near
    monkeypatch.setattr(pipeline, "_held_near", lambda *a: held.append(1) or near(*a))
    volumes = {}
    for name in ("low_wing_trailing_edge_under_a_narrowing_tail_cone",
                 "canted_fin_between_a_low_wing_and_the_tail_cone_top"):
        geo = _complete(DATA / "generated" / "remesh" / f"{name}.inp")
        cells = union_volume(geo.configuration, n=121, cells=1500)
        held.clear()
        with warnings.catch_warnings():
            warnings.simplefilter("error", jc.JunctureWarning)   # the re-triangulation kept
            surface = jc.mesh(geo)
        tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
        assert tm.is_watertight and tm.is_winding_consistent
        assert abs(tm.volume / cells - 1.0) < 0.005
        volumes[name] = (len(held), tm.volume / cells - 1.0, geo, cells)
    assert volumes["low_wing_trailing_edge_under_a_narrowing_tail_cone"][0] == 1
    assert volumes["canted_fin_between_a_low_wing_and_the_tail_cone_top"][0] == 0
    _, kept, geo, cells = volumes["low_wing_trailing_edge_under_a_narrowing_tail_cone"]
    monkeypatch.setattr(patch_roles, "away_from", lambda lift, crossings: None)
    assert jc.mesh(geo).volume() / cells - 1.0 < kept - 0.001
