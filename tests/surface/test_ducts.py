"""Flow-through nacelles (issue 12): a duct of the inlet's radius through each open pod.

Oracles: trimesh (watertight, winding, Euler number), the model's own centre line and inlet
radius (every duct point up to the last station but one lies on that cylinder), the
analytic volume of the ducts (cylinder and frustum), and the check's handle count.
"""

import warnings

import numpy as np
import pytest
import trimesh

import juncture as jc
from juncture.model import CircularBody, Configuration
from juncture.surface.check import check_mesh
from juncture.surface.ducts import DUCT
from tests.support import DATA, EXAMPLE_DECK, wing_body


@pytest.fixture(scope="module")
def transport():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(EXAMPLE_DECK))
        return geo, jc.mesh(geo, min_angle=0), jc.mesh(geo, min_angle=0, flow_through=True)


def _ducts_volume(cfg):
    """Both halves' ducts: a cylinder of the inlet radius to the last station but one, a
    frustum on to the exit."""
    total = 0.0
    for body in cfg.components.values():
        if isinstance(body, CircularBody) and body.mirrored and body.radius[0] > 0:
            x, r0, r1 = np.asarray(body.x, float), body.radius[0], body.radius[-1]
            dx = x[-1] - x[-2]
            total += 2 * (np.pi * r0 ** 2 * (x[-2] - x[0])
                          + np.pi / 3.0 * dx * (r0 ** 2 + r0 * r1 + r1 ** 2))
    return total


def test_the_transport_nacelles_are_rings_the_flow_passes_through(transport):
    geo, closed, through = transport
    tm = trimesh.Trimesh(through.vertices, through.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert tm.euler_number == 2 - 2 * 4                # two nacelles a side, one handle each
    assert check_mesh(through.vertices, through.triangles, handles=4).ok
    plain = check_mesh(through.vertices, through.triangles)
    assert any("not spheres" in f for f in plain.failures())
    assert not any(s.startswith("pod") and s.endswith("cap") for s in through.surfaces)
    # what the ducts take out is the cylinders' and frustums' volume (the networks'
    # polygons inside the model's circles: within 1 %)
    taken = closed.volume() - through.volume()
    assert taken == pytest.approx(_ducts_volume(geo.configuration), rel=1e-2)
    assert through.wetted_area()["pod 1"] > 1.8 * closed.wetted_area()["pod 1"]


def test_new_duct_points_lie_on_the_inlet_cylinder():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(EXAMPLE_DECK))
        surface = jc.mesh(geo, flow_through=True)
    body = geo.configuration.components["pod 1"]
    x = np.asarray(body.x, float) + body.origin[0]
    centre = np.array([body.origin[1], body.origin[2] + body.camber[0]])
    duct = surface.surface == surface.surfaces.index("pod 1" + DUCT)
    p = surface.vertices[np.unique(surface.triangles[duct])]
    p = p[p[:, 0] <= x[-2]]
    assert len(p) > 500
    rho = np.linalg.norm(p[:, 1:] - centre, axis=1)
    np.testing.assert_allclose(rho, body.radius[0], rtol=1e-9)


def _pod_only(radius):
    """tests.support's wing-body with a free pod well outboard of its wing tip."""
    cfg = wing_body()
    pod = CircularBody("pod 1", [0.0, 1.0, 4.0, 7.0, 8.0], radius, origin=(10.0, 30.0, 0.0),
                       mirrored=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.complete(Configuration({**cfg.components, "pod 1": pod}))


def test_a_duct_that_would_leave_the_wall_is_refused_by_name():
    geo = _pod_only([1.0, 1.3, 0.95, 1.2, 1.1])
    wall = r"pod 1, station 1[34][.0-9]*: flow-through: .* leaves the nacelle's wall"
    with pytest.raises(jc.GeometryError, match=wall):
        jc.mesh(geo, flow_through=True, min_angle=0)


def test_a_pod_closed_at_its_rear_stays_closed_with_a_warning():
    geo = _pod_only([1.0, 1.3, 1.4, 1.2, 0.0])
    with pytest.warns(jc.JunctureWarning, match="pod 1: closed at its rear"):
        surface = jc.mesh(geo, flow_through=True, min_angle=0)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.euler_number == 2 * 3    # airplane and two pods


def test_a_lone_flow_through_pod_is_remeshed_as_a_ring():
    geo = _pod_only([1.0, 1.3, 1.4, 1.2, 1.1])
    surface = jc.mesh(geo, flow_through=True)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert tm.euler_number == 2 + 0 + 0                     # the airplane, two rings
    assert surface.volume() > 0


def test_juncture_check_counts_the_ducts_as_handles(transport, tmp_path, capsys):
    from juncture.cli import main
    from juncture.surface.write import write_mesh

    path = write_mesh(transport[2], tmp_path / "through.stl")
    assert main(["check", str(path)]) == 2
    assert "not spheres" in capsys.readouterr().out
    assert main(["check", str(path), "--handles", "4"]) == 0
    assert main(["check", str(path), "--handles", "3"]) == 2
    assert "4 handles in all" in capsys.readouterr().out


def _open_pods(cfg):
    return [c for c in cfg if isinstance(c, CircularBody) and c.mirrored and c.radius[0] > 0]


WITH_PODS = [p for p in sorted((DATA / "generated").glob("*.inp"))
             + sorted((DATA / "generated" / "assembly").glob("*.inp"))
             if _open_pods(jc.read(p))]


@pytest.mark.slow
@pytest.mark.parametrize("deck", WITH_PODS, ids=[p.stem for p in WITH_PODS])
def test_generated_nacelles_are_ducted_or_refused_by_name(deck):
    """Airplanes juncture was not built on (tests/data/generated) with open pods, as
    assembled: each pod open at both ends is a ring (the Euler number falls by 2 per duct
    of both halves), watertight and consistently wound; or it is refused naming the pod."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(deck))
        closed = jc.mesh(geo, min_angle=0)
        try:
            through = jc.mesh(geo, min_angle=0, flow_through=True)
        except jc.GeometryError as err:
            assert "leaves the nacelle's wall" in str(err)
            assert str(err).split(",")[0] in {p.name for p in _open_pods(geo.configuration)}
            return
    ducted = [p for p in _open_pods(geo.configuration) if p.radius[-1] > 0]
    a = trimesh.Trimesh(closed.vertices, closed.triangles, process=False)
    b = trimesh.Trimesh(through.vertices, through.triangles, process=False)
    assert b.is_watertight and b.is_winding_consistent
    assert b.euler_number == a.euler_number - 2 * 2 * len(ducted)
    assert through.volume() < closed.volume() or not ducted
