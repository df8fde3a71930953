"""Normal area distributions from the model (juncture.analysis.areas) and the wavedrag command.

References are closed forms: a slab (a wing of constant thickness) through a circular
cylinder (the union is the circle plus the slab minus the circle's band ``|z - z0| <= h``,
whose area follows from ``F(z) = z sqrt(R^2 - z^2) + R^2 asin(z / R)``); the PDAS sample deck's
delta wing, whose PCHIP section through 0 / 2.5 / 0 % is exactly the parabolic arc
``t = 10 f (1 - f)`` % (end slope 10 by the three-point formula, zero slope at the crest), so
its cut at ``X = x - 100`` is ``0.2 (140 - X) [X - (140 - X) ln(140 / (140 - X))]`` per side;
the FUSARD areas themselves; and the Sears-Haack drag ``128 V^2 / (pi l^4)``.
"""

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import juncture as jc
from juncture.analysis.areas import (
    default_stations,
    normal_area_distribution,
    winglike_normal_area,
)
from juncture.analysis.closed import closed_networks
from juncture.analysis.command import wavedrag
from juncture.analysis.wavedrag import sears_haack_drag
from juncture.errors import GeometryError, JunctureError
from juncture.geometry import Geometry
from juncture.model import ArbitraryBody, CircularBody, Configuration, WingLike
from juncture.plots import plot_area_distribution
from support import EXAMPLE_DECK, PDAS_DECK


def band(z1, z2, r):
    """Area of the half disc (y >= 0) of radius r between heights z1 < z2 (centre at 0)."""
    def f(z):
        z = np.clip(z, -r, r)
        return z * np.sqrt(r * r - z * z) + r * r * np.arcsin(z / r)
    return 0.5 * (f(z2) - f(z1))


def slab_wing(y0, y1, chord, t_pct, z0=0.0, x0=0.0, kind="wing"):
    """Rectangular wing with a constant-thickness section (flat plates at +-t/2)."""
    le = [[x0, y0, z0], [x0, y1, z0]] if kind == "wing" else [[x0, z0, y0], [x0, z0, y1]]
    xs = [0.0, 0.0001, 99.9999, 100.0]
    th = [[0.0, t_pct, t_pct, 0.0]] * 2
    return WingLike("w", kind, le, [chord, chord], xs, th, th, chordwise="linear")


def cylinder(r, x0=-10.0, x1=20.0, z0=0.0, name="body"):
    return CircularBody(name, [x0, x1], [r, r], camber=[z0, z0], axial="linear")


@pytest.fixture(scope="module")
def pdas():
    with pytest.warns(jc.errors.JunctureWarning):
        return jc.read(PDAS_DECK)


@pytest.fixture(scope="module")
def transport():
    return jc.read(EXAMPLE_DECK)


# ---------------------------------------------------------------------------------------------
# Wing-like components against closed forms


def test_slab_through_cylinder_removes_the_buried_part_exactly():
    r, span, chord, t = 1.3, 5.0, 4.0, 12.0  # half-thickness 0.48
    h = chord * t / 100.0
    wing = slab_wing(0.0, span, chord, t)
    x = np.array([0.5, 1.7, 3.1])
    exposed = 2 * h * span - band(-h, h, r)
    got = winglike_normal_area(wing, x, [cylinder(r)])
    assert got == pytest.approx(np.full(3, exposed), rel=1e-12)
    # and without the body: the whole slab
    assert winglike_normal_area(wing, x) == pytest.approx(np.full(3, 2 * h * span), rel=1e-13)


def test_quadrature_converges_geometrically():
    r, h, z0 = 1.0, 0.3, 0.55  # a slab cutting the circle off-centre: square-root ends
    wing = slab_wing(0.0, 4.0, 3.0, 10.0, z0=z0)
    exact = 2 * h * 4.0 - band(z0 - h, z0 + h, r)
    errs = [abs(winglike_normal_area(wing, [1.5], [cylinder(r)], n_gauss=n)[0] - exact)
            for n in (1, 2, 4, 8)]
    assert errs[-1] < 1e-12 * exact
    assert errs[2] < 1e-5 * exact
    assert errs[0] > errs[1] > errs[2]


def buried_beyond(y0, z1, z2, r):
    """Area of the disc of radius r with y >= y0 and z1 <= z <= z2 (closed form)."""
    if y0 >= r:
        return 0.0
    zm = np.sqrt(r * r - y0 * y0)
    a, b = max(z1, -zm), min(z2, zm)
    if b <= a:
        return 0.0
    return band(a, b, r) - y0 * (b - a)


@settings(max_examples=40, deadline=None)
@given(r=st.floats(0.5, 2.0), h=st.floats(0.02, 0.45), z0=st.floats(-1.5, 1.5),
       y0=st.sampled_from([0.0, 0.1, 0.37]), x=st.floats(0.01, 1.99))
def test_slab_union_with_cylinder_property(r, h, z0, y0, x):
    chord = 2.0
    wing = slab_wing(y0, 6.0, chord, 100.0 * h / chord, z0=z0)
    exact = 2 * h * (6.0 - y0) - buried_beyond(y0, z0 - h, z0 + h, r)
    got = winglike_normal_area(wing, [x], [cylinder(r)])[0]
    assert got == pytest.approx(exact, rel=1e-10, abs=1e-12)


def test_fin_on_a_body_is_trimmed_along_y():
    # a fin (span along z) rising from inside a cylinder through its top
    r = 1.0
    fin = slab_wing(0.0, 3.0, 2.0, 10.0, kind="fin")  # y thickness 0.4, z from 0 to 3
    h = 0.2
    exposed = 2 * h * 3.0 - band(-h, h, r)  # the circle is symmetric: z and y swap roles
    assert winglike_normal_area(fin, [1.0], [cylinder(r)]) == pytest.approx([exposed],
                                                                            rel=1e-12)


def test_arbitrary_box_body_trims_the_root():
    sec = np.array([[0.0, -1.0], [1.0, -1.0], [1.0, 1.0], [0.0, 1.0]])
    box = ArbitraryBody("box", [-5.0, 10.0], [sec, sec])
    wing = slab_wing(0.0, 4.0, 2.0, 10.0)
    assert winglike_normal_area(wing, [0.7], [box]) == pytest.approx([0.4 * 3.0], rel=1e-12)


def test_diamond_wing_normal_area_is_linear_in_chord_fraction():
    w = WingLike("w", "wing", [[0, 1, 0], [0, 4, 0]], [2, 2], [0, 50, 100],
                 [[0, 5, 0], [0, 5, 0]], chordwise="linear")
    x = np.array([-0.1, 0.0, 0.4, 1.0, 1.3, 2.0, 2.5])
    f = np.clip(x / 2.0, 0.0, 1.0)
    t = 2 * 2.0 * 0.05 * np.minimum(f, 1 - f) / 0.5
    assert winglike_normal_area(w, x) == pytest.approx(3.0 * t, abs=1e-14)


# ---------------------------------------------------------------------------------------------
# Configurations


def test_pdas_deck_body_and_wing_closed_forms(pdas):
    xf = np.array([0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 250.0, 260.0, 270.0, 280.0, 290.0, 300.0])
    fusard = np.array([0.0, 40.7, 128.7, 221.7, 289.5, 314.16, 314.16, 289.5, 221.7, 128.7,
                       40.7, 0.0])
    a = normal_area_distribution(pdas, xf)
    assert a["body"] == pytest.approx(fusard, rel=1e-12, abs=1e-12)
    x = np.array([99.0, 100.5, 130.0, 170.0, 200.0, 239.0, 241.0])
    a = normal_area_distribution(pdas, x)
    big_x = np.clip(x - 100.0, 0.0, 139.0)  # the clip only avoids log(0) outside the wing
    half = 0.2 * (140 - big_x) * (big_x - (140 - big_x) * np.log(140 / (140 - big_x)))
    # FUSARD 314.16 is a hair more than pi 10^2: the body pokes 1.2e-5 past the wing root at
    # y = 10, and that circular segment (inside the wing's thickness) is removed.
    r = np.sqrt(314.16 / np.pi)
    sliver = r * r * np.arccos(10.0 / r) - 10.0 * np.sqrt(r * r - 100.0)
    expected = 2.0 * np.where((x > 100.0) & (x < 240.0), half - sliver, 0.0)
    assert a["wing"] == pytest.approx(expected, rel=1e-11, abs=1e-9)
    assert a["total"] == pytest.approx(a["wing"] + 314.16, rel=1e-12)
    assert a["x"] is not None and np.array_equal(a["x"], x)


def test_images_count_twice_and_components_subset(transport):
    x = np.linspace(200.0, 240.0, 9)
    a = normal_area_distribution(transport, x)
    pod = transport["pod 1"]
    # An open nacelle is flow-through: its inlet capture area is subtracted over its length.
    inside = (x >= pod.x_global[0]) & (x <= pod.x_global[-1])
    wall = np.pi * (pod.radius_at(x) ** 2 - np.where(inside, pod.radius[0] ** 2, 0.0))
    assert a["pod 1"] == pytest.approx(2 * wall, rel=1e-12, abs=1e-12)
    solid = normal_area_distribution(transport, x, flow_through=False)
    assert solid["pod 1"] == pytest.approx(2 * np.pi * pod.radius_at(x) ** 2, rel=1e-13)
    assert a["body"] == pytest.approx(np.pi * transport["body"].radius_at(x) ** 2, rel=1e-13)
    sub = normal_area_distribution(transport, x, components=["wing", "pod 1"])
    assert set(sub) == {"x", "wing", "pod 1", "total"}
    assert sub["wing"] == pytest.approx(a["wing"], rel=1e-13)
    assert sub["total"] == pytest.approx(a["wing"] + a["pod 1"], rel=1e-13)
    one_side = transport.replace(symmetric=False)
    assert normal_area_distribution(one_side, x, ["pod 1"])["pod 1"] == pytest.approx(
        a["pod 1"] / 2, rel=1e-13)


def test_buried_roots_are_removed_on_the_transport(transport):
    # the wing root (y = 3) lies inside the 6 ft fuselage: trimming must lower the area
    x = np.array([120.0, 150.0, 180.0])
    trimmed = winglike_normal_area(transport["wing"], x, transport.bodies)
    whole = winglike_normal_area(transport["wing"], x)
    assert np.all(trimmed < whole - 1.0)
    assert normal_area_distribution(transport, x)["wing"] == pytest.approx(2 * trimmed,
                                                                            rel=1e-13)


def test_geometry_falls_back_to_network_cuts(pdas):
    geo = Geometry(networks=closed_networks(pdas))
    x = np.array([25.0, 150.0, 275.0])
    model = normal_area_distribution(pdas, x)["total"]
    a = normal_area_distribution(geo, x)
    assert set(a) == {"x", "total"}
    # resampling accuracy of closed_networks: 0.1 % of the largest area
    assert a["total"] == pytest.approx(model, abs=1e-3 * 1112.0)
    assert default_stations(geo, 5) == pytest.approx(np.linspace(0.0, 300.0, 5))


def test_errors():
    cfg = Configuration({"body": cylinder(1.0)})
    with pytest.raises(GeometryError, match="no such component"):
        normal_area_distribution(cfg, [1.0], components=["wing"])
    with pytest.raises(JunctureError, match="finite 1-D"):
        normal_area_distribution(cfg, [[1.0, 2.0]])
    with pytest.raises(JunctureError, match="finite 1-D"):
        normal_area_distribution(cfg, [np.nan])
    with pytest.raises(JunctureError, match="must be numbers"):
        normal_area_distribution(cfg, ["a"])
    with pytest.raises(JunctureError, match="Configuration or Geometry"):
        normal_area_distribution(42, [1.0])
    with pytest.raises(GeometryError, match="expected a WingLike"):
        winglike_normal_area(cylinder(1.0), [1.0])
    with pytest.raises(JunctureError, match="n_gauss"):
        winglike_normal_area(slab_wing(0, 1, 1, 5), [1.0], n_gauss=0)
    with pytest.raises(JunctureError, match="n_x must be at least 2"):
        default_stations(cfg, 1)


# ---------------------------------------------------------------------------------------------
# The wavedrag command


def sears_haack_config(n=81, length=100.0, s_max=50.0):
    # deck-like: radii given at stations (clustered at the ends, as a deck would), PCHIP
    # between them. The PCHIP radius between stations is what limits the accuracy: measured
    # +0.16 % with 41 stations, +0.013 % with 81 (101 equally spaced cuts).
    x = 0.5 * length * (1 - np.cos(np.linspace(0.0, np.pi, n)))
    xi = x / length
    r = np.sqrt(s_max * (4 * xi * (1 - xi)) ** 1.5 / np.pi)
    return Configuration({"body": CircularBody("body", x, r)}, reference_area=1000.0)


def test_sears_haack_slender_body_drag():
    length, s_max = 100.0, 50.0
    cfg = sears_haack_config(length=length, s_max=s_max)
    volume = 3 * np.pi * s_max * length / 16
    r = wavedrag(cfg, n_x=101)
    assert r["D_over_q"] == pytest.approx(sears_haack_drag(volume, length), rel=1e-3)
    assert r["CD"] == pytest.approx(r["D_over_q"] / 1000.0, rel=1e-15)
    assert r["method"] == "slender-body (Eminton-Lord)" and r["mach"] is None
    assert len(r["x"]) == len(r["area"]) == 101


def test_far_field_at_mach_one_is_the_slender_body_result(pdas):
    # At M = 1 every Mach plane is x = X: a Configuration's cuts are its exact normal areas
    slender = wavedrag(pdas, n_x=61)
    far = wavedrag(pdas, mach=1.0, n_x=61, n_theta=4)
    assert far["method"] == ("far-field (Harris), NTHETA 4: 5 roll angles over a half turn, "
                             "Boole rule")
    assert far["D_over_q"] == pytest.approx(slender["D_over_q"], rel=1e-12)
    assert np.ptp(far["D_over_q_theta"]) < 1e-12 * far["D_over_q"]
    assert np.array(far["cut_areas"]).shape == (5, 61)
    assert far["x"] == pytest.approx(slender["x"], rel=1e-14)
    assert far["area"] == pytest.approx(slender["area"], rel=1e-12, abs=1e-9)
    assert np.sum(far["theta_weights"]) == pytest.approx(1.0, rel=1e-14)


def test_supersonic_transport_result_is_json_ready(transport):
    # (the transport's pods have flat open inlet faces: jumps in A(x) whose Eminton-Lord drag
    # depends on the station spacing, so only a supersonic result is checked here)
    r = wavedrag(transport, mach=2.4, n_x=61, n_theta=8)
    assert r["D_over_q"] > 0.0 and len(r["D_over_q_theta"]) == 9
    assert r["D_over_q"] == pytest.approx(np.dot(r["theta_weights"], r["D_over_q_theta"]),
                                          rel=1e-12)
    assert r["CD"] == pytest.approx(r["D_over_q"] / 9000.0, rel=1e-15)
    assert r["components"] == {}  # the model's normal areas are not integrated for a Mach
    # its "area": the normal cuts of the same closed networks, to their faceting (0.1 %)
    model = normal_area_distribution(transport, r["x"])["total"]
    assert np.abs(np.array(r["area"]) - model).max() < 1.5e-3 * model.max()
    slender = wavedrag(transport, n_x=61)
    assert set(slender["components"]) == set(transport.components) | {"held bases"}
    json.dumps(r)  # plain floats and lists only


def test_wavedrag_on_a_geometry_and_without_reference_area(pdas):
    geo = Geometry(networks=closed_networks(pdas))
    r = wavedrag(pdas, n_x=51, geometry=geo)
    model = wavedrag(pdas, n_x=51)
    assert r["D_over_q"] == pytest.approx(model["D_over_q"], rel=1e-2)
    assert r["components"] == {}
    bare = wavedrag(pdas.replace(reference_area=None), n_x=21)
    assert bare["CD"] is None and bare["reference_area"] is None


def test_wavedrag_errors(pdas):
    with pytest.raises(JunctureError, match="Mach number >= 1"):
        wavedrag(pdas, mach=0.8)
    with pytest.raises(JunctureError, match="n_x must be at least 3"):
        wavedrag(pdas, n_x=2)
    with pytest.raises(JunctureError, match="n_theta must be at least 1"):
        wavedrag(pdas, mach=1.5, n_theta=0)
    with pytest.raises(JunctureError, match="Configuration or Geometry"):
        wavedrag("deck.inp")


def test_plot_area_distribution(tmp_path, pdas):
    r = wavedrag(pdas, n_x=21)
    out = plot_area_distribution({"before": r, "shifted": {"x": r["x"], "area": r["area"]}},
                                 tmp_path / "areas.png")
    assert out.exists() and out.read_bytes()[:4] == b"\x89PNG"
    with pytest.raises(JunctureError, match="no area distributions"):
        plot_area_distribution({}, tmp_path / "x.png")
    with pytest.raises(JunctureError, match="equal length"):
        plot_area_distribution({"bad": {"x": [1, 2], "area": [1]}}, tmp_path / "x.png")
    with pytest.raises(JunctureError, match="no 'x' and 'area'"):
        plot_area_distribution({"bad": {}}, tmp_path / "x.png")
    assert not (tmp_path / "x.png").exists()
