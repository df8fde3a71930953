"""CAD solids (juncture.surface.solids), read back and judged by OpenCASCADE.

Oracles: OCP's STEP reader, ``BRepCheck_Analyzer``, its volume integration
(``BRepGProp``) and distance computation (``BRepExtrema``); volumes also against independent
quadratures of the component model (pi r(x)^2 along a body, section areas across a span).
"""

import warnings

import numpy as np
import pytest

import juncture as jc
from juncture.errors import GeometryError, JunctureError
from juncture.geometry import Geometry
from juncture.io._cad_write import SHORTEST_EDGE
from juncture.surface.solids import write_solids
from tests.io.test_cad import _product_names, _read
from tests.support import DATA, EXAMPLE_DECK, wing_body

pytest.importorskip("OCP")


@pytest.fixture(scope="module")
def transport():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        cfg = jc.read(EXAMPLE_DECK)
        return cfg, jc.complete(cfg, "cubic", True)


def _solids(shape):
    from OCP.TopAbs import TopAbs_SOLID

    from juncture.io._cad_write import _subshapes

    return _subshapes(shape, TopAbs_SOLID)


def _volume(shape, eps=1e-8):
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps

    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, props, eps)  # adaptive: the default is 0.7 % off
    return props.Mass() / 304.8 ** 3  # OCP reads feet into millimetres


def _valid(shape):
    from OCP.BRepCheck import BRepCheck_Analyzer

    return BRepCheck_Analyzer(shape).IsValid()


def _distance(shape, points):
    """Largest distance (mm) of the points from the shape."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeVertex
    from OCP.BRepExtrema import BRepExtrema_DistShapeShape
    from OCP.gp import gp_Pnt

    out = 0.0
    for p in np.asarray(points, float) * 304.8:
        dist = BRepExtrema_DistShapeShape(BRepBuilderAPI_MakeVertex(gp_Pnt(*p)).Vertex(), shape)
        out = max(out, dist.Value())
    return out


def _section_area(wing, s, n=801):
    """Area of the wing's section at span station s (shoelace over many chord fractions)."""
    f = np.linspace(0.0, 1.0, n)
    up = wing.point(np.full(n, s), f, "upper")
    lo = wing.point(np.full(n, s), f, "lower")
    ring = np.concatenate([lo, up[::-1]])[:, [0, wing.thickness_axis]]
    x, t = ring[:, 0], ring[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(t, -1)) - np.dot(t, np.roll(x, -1)))


def _model_volume(comp):
    """Independent quadrature: pi r^2 along a body, section areas across a wing (Simpson on
    every panel, exact for the linear loft's quadratic area)."""
    from scipy.integrate import quad

    if hasattr(comp, "radius_at"):
        x = comp.x_global
        return sum(quad(lambda t: np.pi * float(comp.radius_at(np.array([t]))[0]) ** 2, a, b,
                        limit=200)[0] for a, b in zip(x[:-1], x[1:]) if b > a)
    st = comp.span_stations
    total = 0.0
    for a, b in zip(st[:-1], st[1:]):
        total += (b - a) / 6.0 * (_section_area(comp, a) + 4.0 * _section_area(
            comp, 0.5 * (a + b)) + _section_area(comp, b))
    return total


def test_one_valid_closed_solid_per_component_copy(tmp_path, transport):
    """Both halves; products named after the components; every solid valid and closed, its
    volume within 0.5 % of the model's own (the polygons' chords lose 0.3 % on a circle)."""
    cfg, geo = transport
    path = write_solids(geo, tmp_path / "c.step")
    assert sorted(_product_names(path)) == sorted(cfg.components)
    shape = _read(path)
    solids = _solids(shape)
    model = geo.configuration
    copies = sum(1 + (model.symmetric and c.mirrored) for c in model)
    assert len(solids) == copies and _valid(shape)
    volumes = sorted(_volume(s, 1e-6) for s in solids)
    expected = sorted(v for c in model for v in [_model_volume(c)] * (1 + (
        model.symmetric and c.mirrored)))
    np.testing.assert_allclose(volumes, expected, rtol=5e-3)
    assert min(volumes) > 0.0


def test_the_faces_follow_the_component_networks(tmp_path, transport):
    """Network points and quad centres of every component lie on its solid (1e-6 L)."""
    from juncture.analysis.closed import closed_networks

    _, geo = transport
    shape = _read(write_solids(geo, tmp_path / "c.step", mirror=False))
    nets = closed_networks(geo.configuration, union=False, flow_through=False,
                           equal_area=False)
    rng = np.random.default_rng(3)
    pts = []
    for name, net in nets.items():
        if name.endswith(" image"):
            continue
        centres = 0.25 * (net[:-1, :-1] + net[1:, :-1] + net[:-1, 1:] + net[1:, 1:])
        both = np.concatenate([net.reshape(-1, 3), centres.reshape(-1, 3)])
        pts.append(both[rng.choice(len(both), 6)])
    size = np.ptp(np.concatenate([n.reshape(-1, 3) for n in nets.values()]), axis=0).max()
    assert _distance(shape, np.concatenate(pts)) < 1e-6 * size * 304.8


def _vertices(shape):
    """(n, 3) the shape's vertices, in feet."""
    from OCP.BRep import BRep_Tool
    from OCP.TopAbs import TopAbs_VERTEX
    from OCP.TopoDS import TopoDS

    from juncture.io._cad_write import _subshapes

    down = getattr(TopoDS, "Vertex", None) or TopoDS.Vertex_s
    pnt = getattr(BRep_Tool, "Pnt_s", None) or BRep_Tool.Pnt
    return np.array([[q.X(), q.Y(), q.Z()] for q in
                     (pnt(down(v)) for v in _subshapes(shape, TopAbs_VERTEX))]) / 304.8


def _check_fused(geo, path, atol=None):
    """One valid solid per closed body: OpenCASCADE's volume is the closed surface's (1e-6),
    and every fillet point and every intersection point not under a fillet is one of its
    vertices (within 1e-12 of the size, or ``atol`` where edges shorter than OCP can hold
    were collapsed)."""
    from scipy.spatial import cKDTree

    from juncture.surface.check import check_mesh

    shape = _read(write_solids(geo, path, "fused"))
    surface = jc.mesh(geo, min_angle=0.0)
    bodies = len(check_mesh(surface.vertices, surface.triangles).euler)
    assert len(_solids(shape)) == bodies and _valid(shape)
    assert _volume(shape) == pytest.approx(surface.volume(), rel=1e-6)
    exact = [np.asarray(p, float).reshape(-1, 3) for p in geo.fillets.values()]
    exact += [np.asarray(p, float) for name, p in geo.intersections.items()
              if not (geo.fillets and name.startswith("wing/body"))]
    exact = np.concatenate(exact)
    exact = exact[np.all(np.isfinite(exact), axis=1)]
    size = np.ptp(surface.vertices, axis=0).max()
    assert cKDTree(_vertices(shape)).query(exact)[0].max() < (atol or 1e-12 * size)


@pytest.mark.slow  # OpenCASCADE's sewing and volume of a mesh solid (~13 s): make test-all
def test_the_fused_solid_is_the_closed_surface(tmp_path):
    """A wing-body with a cubic fillet (the transport's too, below). make test keeps one
    valid closed solid per component (test_one_valid_closed_solid_per_component_copy)."""
    _check_fused(jc.complete(wing_body(), "cubic"), tmp_path / "f.step")


@pytest.mark.slow
def test_the_fused_transport(tmp_path, transport):
    _check_fused(transport[1], tmp_path / "f.step")


def test_cli_cad_choice(tmp_path):
    from juncture.cli import main

    assert main(["complete", str(EXAMPLE_DECK), "-o", str(tmp_path / "f"), "--format", "step",
                 "--cad", "faces", "-q"]) == 0
    assert len(_solids(_read(tmp_path / "f" / "geometry.step"))) == 0
    assert main(["complete", str(EXAMPLE_DECK), "-o", str(tmp_path / "c"), "--format", "igs",
                 "-q"]) == 0
    assert (tmp_path / "c" / "geometry.igs").stat().st_size > 0


def test_errors(tmp_path, transport):
    _, geo = transport
    with pytest.raises(JunctureError, match="CAD content 'solid': expected one of"):
        write_solids(geo, tmp_path / "x.step", "solid")
    with pytest.raises(JunctureError, match="use .step, .stp, .igs or .iges"):
        write_solids(geo, tmp_path / "x.stl")
    bare = Geometry(networks=dict(geo.networks))
    with pytest.raises(GeometryError, match="need the component model"):
        write_solids(bare, tmp_path / "x.step")
    assert not list(tmp_path.iterdir())


GENERATED = sorted((DATA / "generated").glob("*.inp"))


@pytest.mark.slow
@pytest.mark.parametrize("deck", GENERATED, ids=lambda p: p.stem)
def test_generated_airplanes(tmp_path, deck):
    """Every generated airplane: valid closed solids per component; where its completed
    surface closes, one valid fused solid of the mesh's volume."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))
    shape = _read(write_solids(geo, tmp_path / "c.step"))
    model = geo.configuration
    assert len(_solids(shape)) == sum(1 + (model.symmetric and c.mirrored) for c in model)
    assert _valid(shape)
    try:
        surface = jc.mesh(geo, min_angle=0.0)
    except GeometryError:
        with pytest.raises(GeometryError, match="not closed and valid"):
            write_solids(geo, tmp_path / "f.step", "fused")
        return
    assert len(surface.triangles)
    _check_fused(geo, tmp_path / "f.step", SHORTEST_EDGE)
