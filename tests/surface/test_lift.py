"""New mesh points on the exact surfaces (juncture.surface.lift).

Oracles: the component model itself (r(x) of a circular body, the wing's PCHIP sections) and
the model's union of normal areas A(x) integrated along x
(:func:`juncture.analysis.areas.normal_area_distribution`, which never sees a mesh).
"""

import warnings

import numpy as np
import pytest

import juncture as jc
from juncture.analysis.areas import normal_area_distribution
from juncture.surface.assemble import assemble
from juncture.surface.lift import ON_BODY, _polar, _thickness, surface_lift
from juncture.surface.remesh import remesh
from tests.support import EXAMPLE_DECK


@pytest.fixture(scope="module")
def transport():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        cfg = jc.read(EXAMPLE_DECK)
        geo = jc.complete(cfg)
    assembled = assemble(geo)
    return cfg, geo, assembled, remesh(assembled, lift=surface_lift(geo, assembled))


def _owners(mesh, name):
    """Vertex ids used only by triangles of component ``name`` (no seam, no other part)."""
    comp = mesh.components.index(name)
    mine = np.zeros(len(mesh.vertices), bool)
    other = np.zeros(len(mesh.vertices), bool)
    mine[mesh.triangles[mesh.component == comp].ravel()] = True
    other[mesh.triangles[mesh.component != comp].ravel()] = True
    caps = np.array([s.endswith(" cap") for s in mesh.surfaces])[mesh.surface]
    other[mesh.triangles[caps].ravel()] = True
    return np.flatnonzero(mine & ~other)


def test_the_enclosed_volume_comes_to_the_models(transport):
    """Against the model's A(x) integral: within 0.8 % (-0.7 %; the networks' own triangles:
    -1.3 %), and well under the error of new points left on the flat triangles."""
    cfg, _, assembled, lifted = transport
    lo, hi = cfg.extents()
    x = np.linspace(lo[0], hi[0], 301)  # 0.06 % above the limit of finer sums
    model = np.trapezoid(normal_area_distribution(cfg, x=x, flow_through=False)["total"], x)
    flat = remesh(assembled)
    err, before = lifted.volume() / model - 1.0, flat.volume() / model - 1.0
    assert abs(err) < 8e-3
    assert abs(err) < 0.65 * abs(before)


def test_new_points_on_a_body_lie_on_its_circle(transport):
    """The body's own new vertices (not on a seam) are on r(x) about its centre line, but
    those nearer a seam than ten times their lift (remesh.TAPER), lifted part of the way
    (between the flat triangles and the circle), so that they cannot cross a surface that
    meets the body at a small angle."""
    _, geo, assembled, lifted = transport
    new = _owners(lifted, "body")
    new = new[new >= len(assembled.vertices)]
    size = np.ptp(lifted.vertices, axis=0).max()
    body = geo.configuration.components["body"]
    rho, radius, _, _ = _polar(body, lifted.vertices[new], False)  # on the plane y = 0
    on = np.abs(rho - radius) <= ON_BODY * size
    assert len(new) > 1000 and on.mean() > 0.85
    assert np.all(rho <= radius + ON_BODY * size)      # the others toward the circle


def test_new_points_on_a_wing_lie_on_its_sections(transport):
    """The wing's own new vertices are on the model's upper or lower surface (PCHIP through
    the ordinates), at their span station and chord fraction."""
    _, geo, assembled, lifted = transport
    new = _owners(lifted, "wing")
    new = new[new >= len(assembled.vertices)]
    wing = geo.configuration.components["wing"]
    p = lifted.vertices[new].copy()
    p[:, 1] = np.abs(p[:, 1])  # the image half mirrored back
    up, low, inside = _thickness(wing, p)
    size = np.ptp(lifted.vertices, axis=0).max()
    t = wing.thickness_axis
    on = inside & (np.minimum(np.abs(p[:, t] - up), np.abs(p[:, t] - low)) <= 1e-9 * size)
    assert len(new) > 1000 and on.mean() > 0.8


def test_points_off_a_components_own_triangles_stay(transport):
    """A cap's triangle (every corner on the rim) and a point of another component: unchanged."""
    _, geo, assembled, _ = transport
    lift = surface_lift(geo, assembled)
    cap = next(k for k, s in enumerate(assembled.surfaces) if s.endswith(" cap"))
    rows = np.flatnonzero(assembled.surface == cap)[:5]
    corners = assembled.triangles[rows]
    points = assembled.vertices[corners].mean(axis=1)
    comp = assembled.component[rows[0]]
    np.testing.assert_array_equal(lift(points, corners, comp, cap), points)


def test_without_a_model_there_is_no_lift():
    from juncture.geometry import Geometry

    geo = Geometry(networks={"plate": np.stack(np.meshgrid([0.0, 1.0], [0.0, 1.0], [0.0],
                                                           indexing="ij"), -1)[:, :, 0]})
    assert surface_lift(geo, assemble(geo, cap=False)) is None
