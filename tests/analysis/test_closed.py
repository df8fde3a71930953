"""Closed networks of a configuration for Mach-plane cuts (juncture.analysis.closed).

References: the model's own normal areas (juncture.analysis.areas, checked there against
closed forms) for the M -> 1 limit; the mirror symmetry of the configuration for the roll
angles; the divergence theorem (a closed surface has zero vector area and encloses the volume
int A dx); pi r^2 for the equal-area body polygons.
"""

import numpy as np
import pytest

import juncture as jc
from juncture.analysis.areas import normal_area_distribution, winglike_normal_area
from juncture.analysis.closed import body_solid, closed_networks, oriented, winglike_solid
from juncture.analysis.cuts import normal_areas, triangulate
from juncture.analysis.machplanes import mach_plane_area_distribution
from juncture.errors import GeometryError, JunctureError
from juncture.model import CircularBody, Configuration, WingLike
from support import EXAMPLE_DECK, PDAS_DECK


@pytest.fixture(scope="module")
def pdas():
    with pytest.warns(jc.errors.JunctureWarning):
        return jc.read(PDAS_DECK)


@pytest.fixture(scope="module")
def transport():
    return jc.read(EXAMPLE_DECK)


@pytest.fixture(scope="module")
def transport_nets(transport):
    return closed_networks(transport)


def vector_area(nets):
    t = triangulate(nets)
    return 0.5 * np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]).sum(axis=0)


def volume(nets):
    t = triangulate(nets)
    return np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6.0


def parts(nets, name):
    return {k: v for k, v in nets.items() if k == name or k.startswith(name + " ")}


def test_every_component_copy_is_a_closed_outward_solid(transport, transport_nets):
    for name in transport.components:
        own = parts(transport_nets, name)
        for copy in (False, True):
            sub = {k: v for k, v in own.items() if k.endswith(" image") == copy}
            if not sub:
                continue
            scale = np.abs(np.concatenate([v.reshape(-1, 3) for v in sub.values()])).max()
            assert np.abs(vector_area(sub)).max() < 1e-9 * scale**2, name
            assert volume(sub) > 0.0, name


def test_body_polygons_have_the_circle_area_and_volume():
    body = CircularBody("b", [0.0, 3.0, 10.0], [0.0, 1.0, 1.5], camber=[0.0, 0.2, 0.1])
    nets = body_solid(body, n_theta=17, n_body=400)
    assert set(nets) == {"b", "b base"}
    x = body.x_global
    assert normal_areas(nets, [3.0]) == pytest.approx([np.pi], rel=1e-12)
    assert normal_areas(nets, [10.0]) == pytest.approx([np.pi * 2.25], rel=1e-12)
    xs = np.linspace(x[0], x[-1], 20001)
    exact = np.trapezoid(body.area_at(xs), xs)
    assert volume(nets) == pytest.approx(exact, rel=1e-4)


def test_mach_one_cuts_equal_the_model_normal_areas(transport, transport_nets):
    ext = transport.extents()
    x = np.linspace(ext[0, 0], ext[1, 0], 81)[1:-1] + 0.0137  # off the stations and ends
    model = normal_area_distribution(transport, x)["total"]
    cuts = mach_plane_area_distribution(transport, 1.0, n_theta=2, networks=transport_nets)
    cut = normal_areas(transport_nets, x)
    # documented resampling accuracy: 0.1 % of the largest area (measured 0.32 of 425 ft^2)
    assert np.abs(cut - model).max() < 1e-3 * model.max()
    assert cuts["area"][0] == pytest.approx(cuts["area"][1], abs=1e-9 * model.max())


def test_trimmed_wing_solid_matches_the_exposed_area():
    # slab wing through a cylinder: the closed solid starts at the intersection line
    r = 1.0
    body = CircularBody("body", [-5.0, 10.0], [r, r], axial="linear")
    th = [[0.0, 8.0, 8.0, 0.0]] * 2
    wing = WingLike("wing", "wing", [[0.0, 0.0, 0.1], [0.0, 4.0, 0.1]], [3.0, 3.0],
                    [0.0, 0.001, 99.999, 100.0], th, th, chordwise="linear")
    nets = winglike_solid(wing, [body])
    assert {"wing upper", "wing lower", "wing root", "wing tip"} <= set(nets)
    x = np.array([0.7, 1.5, 2.2])
    model = winglike_normal_area(wing, x, [body])
    assert normal_areas(nets, x) == pytest.approx(model, rel=2e-3)
    assert np.all(normal_areas(nets, x) < winglike_normal_area(wing, x))  # root cut off


def test_roll_angle_symmetry(pdas, transport, transport_nets):
    # a left-right symmetric airplane: the plane at theta and its image at pi - theta
    n = 16
    k = (n // 2 - np.arange(n)) % n  # index of pi - theta
    for cfg, nets, tol in ((pdas, None, 1e-10), (transport, transport_nets, 1e-5)):
        s = mach_plane_area_distribution(cfg, 1.7, n_x=40, n_theta=n, networks=nets)
        assert s["x"][k] == pytest.approx(s["x"], abs=1e-9)
        assert np.abs(s["area"][k] - s["area"]).max() < tol * s["area"].max()
        assert s["area"].min() > -1e-9 * s["area"].max()


def test_oriented_flips_a_network_facing_the_wrong_way():
    g = np.linspace(0.0, 1.0, 3)
    a, b = np.meshgrid(g, g, indexing="ij")
    net = np.stack([a, b, np.zeros_like(a)], axis=-1)  # normal cross(d/db, d/da) = -z
    assert oriented(net, [0, 0, 1])[0, 0, 0] == 1.0
    assert oriented(net, [0, 0, -1]) is not None and oriented(net, [0, 0, -1])[0, 0, 0] == 0.0


def test_errors():
    body = CircularBody("b", [0.0, 1.0], [0.5, 0.5])
    with pytest.raises(GeometryError, match="expected a Configuration"):
        closed_networks(body)
    with pytest.raises(GeometryError, match="n_theta must be at least 3"):
        body_solid(body, n_theta=2)
    with pytest.raises(GeometryError, match="expected a body"):
        body_solid("body")
    with pytest.raises(GeometryError, match="expected a WingLike"):
        winglike_solid(body)
    with pytest.raises(JunctureError, match="n_theta >= 1 and n_x >= 2"):
        mach_plane_area_distribution(Configuration({"b": body}), 1.5, n_x=1)
    with pytest.raises(JunctureError, match="Mach number >= 1"):
        mach_plane_area_distribution(Configuration({"b": body}), 0.9)
