"""Half models (issue 12): the y >= 0 half of a closed, mirror-symmetric surface, closed by
its section in the plane of symmetry (the component "symmetry").

Oracles: trimesh (watertight, winding), the whole surface's volume and wetted areas (the
half holds exactly half), scipy's convex hull volume for generated symmetric solids, the
shoelace area of the symmetry plane's rim (independent of its triangulation), exact
coordinates (every symmetry-plane point has y = 0).
"""

import warnings

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial import ConvexHull

import juncture as jc
from juncture.surface.assemble import SurfaceMesh
from juncture.surface.check import check_mesh
from juncture.surface.half import SYMMETRY, half_model, symmetric
from juncture.surface.pipeline import half_checked
from juncture.surface.quality import triangle_angles
from tests.support import DATA, EXAMPLE_DECK, wing_body


def _mesh(vertices, triangles, surface=None):
    surface = np.zeros(len(triangles), np.int64) if surface is None else surface
    return SurfaceMesh(np.asarray(vertices, float), np.asarray(triangles, np.int64),
                       np.zeros(len(triangles), np.int64), surface, ("solid",),
                       tuple(f"s{k}" for k in range(int(surface.max()) + 1)))


def _outward_hull(points):
    hull = ConvexHull(points)
    tri = hull.simplices.copy()
    p = points[tri]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    flip = np.einsum("ij,ij->i", n, p.mean(axis=1) - points.mean(axis=0)) < 0
    tri[flip] = tri[flip][:, [0, 2, 1]]
    return tri, hull.volume


def _shoelace(mesh):
    """The area enclosed by the symmetry plane's rim in (x, z), by the shoelace formula
    over its directed boundary edges (independent of how it is triangulated)."""
    sym = mesh.triangles[mesh.component == mesh.components.index(SYMMETRY)]
    e = np.concatenate([sym[:, [0, 1]], sym[:, [1, 2]], sym[:, [2, 0]]])
    n = len(mesh.vertices)
    rim = e[~np.isin(e[:, 0] * n + e[:, 1], e[:, 1] * n + e[:, 0])]
    a, b = mesh.vertices[rim[:, 0]][:, [0, 2]], mesh.vertices[rim[:, 1]][:, [0, 2]]
    return 0.5 * abs(float(np.sum(a[:, 0] * b[:, 1] - b[:, 0] * a[:, 1])))


def _assert_closed_half(half, volume):
    tm = trimesh.Trimesh(half.vertices, half.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert tm.volume == pytest.approx(volume / 2.0, rel=1e-9)
    assert check_mesh(half.vertices, half.triangles).ok
    sym = half.component == half.components.index(SYMMETRY)
    p = half.vertices[half.triangles[sym]]
    assert np.all(p[:, :, 1] == 0.0)
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert np.all(normal[:, 1] < 0)                         # facing -y, out of the half
    assert half.areas()[sym].sum() == pytest.approx(_shoelace(half), rel=1e-9)
    assert np.all(half.vertices[:, 1] >= 0.0)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(6, 40), st.integers(0, 4))
def test_the_half_of_a_symmetric_hull_holds_half_its_volume(seed, n, on_plane):
    """Random solids made symmetric (points and their mirror images, some on y = 0): the
    hull is one curved surface that straddles the plane, so its triangles are cut there."""
    rng = np.random.default_rng(seed)
    p = rng.normal(size=(n, 3)) * [3.0, 1.0, 1.0]
    p[:, 1] = np.abs(p[:, 1]) + 0.05
    plane = rng.normal(size=(on_plane, 3))
    plane[:, 1] = 0.0
    pts = np.concatenate([p, p * [1.0, -1.0, 1.0], plane])
    tri, volume = _outward_hull(pts)
    solid = _mesh(pts, tri)
    if not check_mesh(pts, tri).ok:          # a hull facet in the plane (no image needed)
        return
    _assert_closed_half(half_model(solid), volume)


def test_a_box_with_rows_on_the_plane_keeps_its_planar_sides():
    """A box whose side faces carry points on y = 0: each face that straddles the plane is
    planar, so its half is triangulated again in its plane."""
    x, y, z = np.meshgrid([0.0, 2.0, 4.0], [-1.0, 0.0, 1.0], [-0.5, 0.5], indexing="ij")
    pts = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    tri, volume = _outward_hull(pts)        # qhull splits the faces into triangles
    p = pts[tri]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    face = np.unique(np.round(n / np.linalg.norm(n, axis=1)[:, None]), axis=0,
                     return_inverse=True)[1].ravel()
    half = half_model(_mesh(pts, tri, face))
    _assert_closed_half(half, volume)
    assert volume == pytest.approx(8.0)


def test_an_unsymmetric_solid_is_refused_by_name():
    pts = np.array([[0.0, -1.0, 0.0], [1.0, 1.5, 0.0], [0.0, 0.5, 1.0], [0.3, 0.2, -1.0]])
    tri, _ = _outward_hull(pts)
    with pytest.raises(jc.GeometryError, match="s0: no half model: .* no mirror image in y = 0"):
        half_model(_mesh(pts, tri))


@pytest.fixture(scope="module")
def transport():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.complete(jc.read(EXAMPLE_DECK))


def test_the_transport_half_is_closed_and_holds_half_of_everything(transport):
    """The bundled transport's blunt base and centre fin's tip cap straddle the plane; their
    halves and the symmetry plane are triangulated anew, no angle under 5 deg."""
    whole = jc.mesh(transport)
    half = half_checked(whole)[0]
    _assert_closed_half(half, whole.volume())
    wet, wet_whole = half.wetted_area(), whole.wetted_area()
    assert SYMMETRY not in wet
    for name, area in wet_whole.items():
        assert wet[name] == pytest.approx(area / 2.0, rel=1e-9), name
    # Off the straddling caps, the half's triangles are the whole's, bit for bit.
    caps = np.array([s.endswith("cap") or s == SYMMETRY for s in half.surfaces])
    mine = {tuple(t) for t in np.sort(half.vertices[half.triangles[~caps[half.surface]]]
                                      .reshape(-1, 9), axis=1).tolist()}
    theirs = {tuple(t) for t in np.sort(whole.vertices[whole.triangles].reshape(-1, 9),
                                        axis=1).tolist()}
    assert mine <= theirs
    y = whole.vertices[whole.triangles][:, :, 1]
    names = {whole.surfaces[k] for k in whole.surface[(y > 0).any(axis=1) & (y < 0).any(axis=1)]}
    assert names == {"body cap", "fin 3 cap"}
    new = np.isin(half.surface, [half.surfaces.index(n) for n in names | {SYMMETRY}])
    assert triangle_angles(half.vertices, half.triangles[new]).min() >= 5.0


def _with_fin(upper, lower, camber=None, y=0.0):
    from juncture.model import Configuration, WingLike

    cfg = wing_body()
    xc = np.linspace(0.0, 100.0, 6)
    fin = WingLike("fin 1", "fin", np.array([[40.0, y, 2.5], [50.0, y, 10.0]]),
                   np.array([12.0, 5.0]), xc, np.tile(upper * np.sin(np.pi * xc / 100), (2, 1)),
                   np.tile(lower * np.sin(np.pi * xc / 100), (2, 1)), camber, mirrored=False)
    return Configuration({**cfg.components, "fin 1": fin})


def test_only_an_airplane_that_is_its_own_mirror_image_gets_a_half_model():
    symmetric(jc.read(EXAMPLE_DECK))
    symmetric(_with_fin(3.0, 3.0))
    for cfg in (_with_fin(3.0, 2.0), _with_fin(3.0, 3.0, np.full((2, 6), 0.1)),
                _with_fin(3.0, 3.0, y=0.5)):
        with pytest.raises(jc.GeometryError, match="fin 1: no half model: fin 1 is not its "
                           "own mirror image in y = 0"):
            symmetric(cfg)


GENERATED = sorted((DATA / "generated").glob("*.inp")) + sorted(
    (DATA / "generated" / "assembly").glob("*.inp"))
FAST = {"circular_body_unsymmetric_centre_fin", "arbitrary_body_blunt_base_flat_sides",
        "low_wing_pod_pylon_fin_canard"}


@pytest.mark.parametrize("deck", [pytest.param(p, id=p.stem, marks=() if p.stem in FAST
                                               else pytest.mark.slow) for p in GENERATED])
def test_generated_airplanes_give_a_closed_half_or_a_refusal_by_name(deck):
    """Airplanes juncture was not built on (tests/data/generated), as assembled: the half
    is closed and holds half the whole's volume, its symmetry plane the shoelace area of
    its rim; or the component that is not its own mirror image is named."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))
    whole = jc.mesh(geo, min_angle=0)
    try:
        half = half_checked(whole, 25.0, True, geo.configuration)[0]
    except jc.GeometryError as err:
        assert "is not its own mirror image in y = 0" in str(err), str(err)
        name = str(err).split(":")[0]
        comp = geo.configuration.components[name]
        assert not comp.mirrored
        return
    _assert_closed_half(half, whole.volume())


@settings(max_examples=60, deadline=None)
@given(st.floats(0.5, 50.0), st.floats(0.05, 5.0), st.floats(0.05, 5.0), st.floats(0.05, 5.0))
def test_points_on_the_plane_start_as_far_from_a_corner_as_the_rim(span, first, last, h):
    """The points put on y = 0 between a planar cap's rim ends: the piece at each end about
    as long as the rim's piece there (a nearer point beside a thin trailing edge's corner
    made a 3.3 deg sliver on the transport's fin tip), then turning towards the rim's
    usual piece by half the distance, never a piece under half of what it should be."""
    from juncture.surface.half import _spacing

    t = _spacing(span, first, last, h)
    pieces = np.diff(np.concatenate([[0.0], t * span, [span]]))
    assert np.all(t > 0.0) and np.all(t < 1.0) and np.all(np.diff(t) > 0.0)
    if len(t):
        assert pieces[0] >= 0.5 * min(first, span)
        assert pieces[-1] >= 0.5 * min(last, pieces[:-1].max())
        assert pieces.max() <= 2.0 * max(first, last, h)
