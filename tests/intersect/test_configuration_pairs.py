"""TM-4607: every touching pair of a whole configuration, found and intersected."""

import warnings

import numpy as np
import pytest

import juncture as jc
from juncture.intersect import find_intersections, surface_height
from juncture.model import CircularBody, WingLike
from tests.support import EXAMPLE_DECK, wing_body


def example():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(EXAMPLE_DECK)


def on_line(points, lines, u):
    k = np.clip(np.floor(u).astype(int), 0, lines.shape[1] - 2)
    rows = np.arange(len(points))
    a, b = lines[rows, k], lines[rows, k + 1]
    d = (b - a) / np.linalg.norm(b - a, axis=1)[:, None]
    v = points - a
    return np.linalg.norm(v - (v * d).sum(1)[:, None] * d, axis=1)


def test_every_touching_pair_of_the_transport_is_found():
    cfg = example()
    found = find_intersections(cfg)
    got = {(p.a, p.b, p.role) for p in found}
    assert got == {("wing", "body", "body"), ("fin 1", "wing", "lower"),
                   ("fin 1", "pod 1", "body"), ("fin 2", "wing", "lower"),
                   ("fin 2", "pod 2", "body"), ("fin 3", "body", "body"),
                   ("tail 1", "body", "body")}
    L = cfg["body"].length
    for pair, inters in found.items():
        a, b = cfg[pair.a], cfg[pair.b]
        for side, inter in zip(("upper", "lower"), inters):
            p = inter.points[inter.found]
            assert inter.found.all(), inter.name
            if pair.role == "body":
                assert np.abs(b.radial_error(p)).max() < 1e-9 * L
            else:
                z, inside = surface_height(b, p, pair.role)
                assert inside.all() and np.abs(p[:, 2] - z).max() < 1e-9 * L
            lines = a.lofting_lines(side)
            assert on_line(p, lines, inter.u[inter.found]).max() < 1e-9 * L


def fin_on_wing(overhang=0.0):
    """A wing-body with a fin standing on the wing's upper surface at y = 9."""
    cfg = wing_body(root_y=1.0)
    wing = cfg["wing"]
    y = 9.0
    z_mid = float(surface_height(wing, np.array([[28.0, y, 0.0]]), "upper")[0][0])
    le = np.array([[24.0 + overhang, y, z_mid - 0.6], [28.0 + overhang, y, z_mid + 5.0]])
    fin = WingLike("fin 1", "fin", le, [9.0, 4.0], [0.0, 30.0, 70.0, 100.0],
                   [[0.0, 3.0, 3.0, 0.0]] * 2, mirrored=True)
    return cfg.with_component(fin)


def test_fin_standing_on_the_wing_upper_surface():
    cfg = fin_on_wing()
    found = find_intersections(cfg)
    pair = next(p for p in found if p.a == "fin 1")
    assert (pair.b, pair.role) == ("wing", "upper")
    for inter in found[pair]:
        z, inside = surface_height(cfg["wing"], inter.points, "upper")
        assert inside.all() and np.abs(inter.points[:, 2] - z).max() < 1e-10


def test_a_fin_line_that_misses_the_wing_is_a_warning_naming_it():
    cfg = fin_on_wing(overhang=10.0)  # trailing part of the fin hangs past the wing
    with pytest.warns(jc.JunctureWarning, match=r"fin 1/wing outboard: lofting line \d+ never"):
        geo = jc.complete(cfg)
    assert any("never meets" in s for s in geo.log)


def test_explicit_pairs_override_detection():
    cfg = example()
    found = find_intersections(cfg, explicit=[("fin 1", "pod 1", "body")])
    assert not any(p.a == "fin 1" and p.b == "wing" for p in found)
    with pytest.raises(jc.GeometryError, match="pair role must be"):
        find_intersections(cfg, explicit=[("fin 1", "pod 1", "side")])
    with pytest.raises(jc.GeometryError, match="no such component"):
        find_intersections(cfg, explicit=[("fin 9", "pod 1", "body")])


def test_fin_on_the_body_double_crossing_takes_the_outer_one():
    # A centre-line fin whose extended lofting lines pass through the body top and would
    # reach its bottom too (TM-4607 fig 9): the first crossing from the tip is the top.
    x = np.linspace(0.0, 40.0, 21)
    body = CircularBody("body", x, np.full(21, 2.0), axial="linear")
    fin = WingLike("fin 1", "fin", [[10.0, 0.0, 3.0], [14.0, 0.0, 9.0]], [8.0, 4.0],
                   [0.0, 50.0, 100.0], [[0.0, 4.0, 0.0]] * 2, mirrored=False)
    from juncture.intersect import intersect_body

    res = intersect_body(fin, body, "upper")
    assert np.all(res.points[:, 2] > 1.9)  # on the top of the body, not the bottom


def test_nothing_is_dropped_and_pylons_meet_their_nacelles():
    cfg = example()
    geo = jc.complete(cfg, "cubic")
    names = set(geo.networks)
    for comp in cfg:
        if comp.name in ("wing", "body"):
            continue
        assert any(n == comp.name or n.startswith(comp.name + " ") for n in names), comp.name
    # The pylon's first n-line is its pod intersection; the pod's arcs end on those lines.
    pod = geo.networks["pod 1"]
    inter = geo.intersections["fin 1/pod 1 outboard"]
    ends = pod[:, -1]
    d = np.min(np.linalg.norm(ends[:, None] - inter[None], axis=-1), axis=0)
    assert d.max() < 1e-9


def test_interpolated_empennage_sections_lie_on_the_input_loft():
    cfg = example()
    tail = cfg["tail 1"]
    geo = jc.complete(cfg)
    net = geo.networks["tail 1 upper"]
    assert net.shape[0] > 2  # root replaced by the intersection, sections interpolated
    for line in net[1:]:
        np.testing.assert_allclose(line, tail.point(line[0, 1], tail.x_over_c / 100, "upper"),
                                   atol=1e-9)


def test_wing_gets_curves_where_pylons_meet_it():
    from juncture.component_networks import trace_curve

    cfg = example()
    geo = jc.complete(cfg, "cubic")
    wing = cfg["wing"]
    # Per pylon (two of them): two curves on the lower surface, one on the upper.
    plain = jc.complete(cfg.replace(components={k: v for k, v in cfg.components.items()
                                                if k not in ("fin 1", "fin 2")}), "cubic")
    assert len(geo.networks["wing lower"]) == len(plain.networks["wing lower"]) + 4
    assert len(geo.networks["wing upper"]) == len(plain.networks["wing upper"]) + 2
    for name in ("fin 1/wing outboard", "fin 2/wing inboard"):
        line = geo.intersections[name]
        curve = trace_curve(wing, "lower", line)
        z, inside = surface_height(wing, curve, "lower")
        assert np.abs(curve[:, 2] - z).max() < 1e-9
        assert any(np.allclose(curve, n) or np.allclose(curve[::-1], n)
                   for n in geo.networks["wing lower"])


def test_a_canard_is_intersected_and_bounds_the_fuselage_split():
    cfg = example()
    x = np.array([0.0, 30.0, 60.0, 100.0])
    canard = WingLike("canard 1", "canard", [[38.0, 2.0, 0.8], [52.0, 14.0, 1.2]], [18.0, 6.0],
                      x, [[0.0, 1.6, 1.2, 0.0]] * 2, camber=None, mirrored=True)
    cfg = cfg.with_component(canard)
    found = find_intersections(cfg)
    pair = next(p for p in found if p.a == "canard 1")
    assert (pair.b, pair.role) == ("body", "body")
    body = cfg["body"]
    for inter in found[pair]:
        assert inter.found.all()
        assert np.abs(body.radial_error(inter.points)).max() < 1e-9 * body.length
    geo = jc.complete(cfg, "cubic")
    seams = [s for s in geo.log if s.startswith("seam body") and "canard 1" in s]
    assert len(seams) == 2 and all(float(s.rsplit("max gap ", 1)[1]) < 1e-12 for s in seams)
    assert {"canard 1 upper", "canard 1 lower"} <= set(geo.networks)
