"""TM-4607: every touching pair of a whole configuration, found and intersected."""

import re
import warnings

import numpy as np
import pytest

import juncture as jc
from juncture.intersect import Pair, find_intersections, intersect_winglike, surface_height
from juncture.model import CircularBody, Configuration, WingLike
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
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always", jc.JunctureWarning)
        geo = jc.complete(cfg)
    said = [str(w.message) for w in got]
    assert any(re.match(r"fin 1/wing outboard: lofting line \d+ never", m) for m in said)
    # every line that misses is named, on the half of the wing it misses
    assert all(re.match(r"fin 1/wing (in|out)board: lofting line \d+ never meets", m)
               for m in said)
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
    from juncture.surface.component_networks import trace_curve

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


# ------------------------------------------------------------------------------------------
# An intersection is a root of the surface equation, never a jump (issue 11)
# ------------------------------------------------------------------------------------------
XC = np.array([0.0, 8.0, 20.0, 35.0, 50.0, 65.0, 80.0, 92.0, 100.0])  # 9 stations
HALF = np.array([0.0, 1.9, 2.8, 3.0, 2.8, 2.3, 1.5, 0.7, 0.0])  # % chord, 0 at both edges


def straight_line_cylinder(root, tip, centre, radius):
    """Where the straight line root -> tip (extended) first meets the cylinder
    (y - yc)^2 + (z - zc)^2 = radius^2 coming from the tip: the parameter s (0 at the root,
    1 at the tip) of the larger root of the quadratic, or NaN if none."""
    d = tip - root
    q = root[1:] - centre
    a = d[1] ** 2 + d[2] ** 2
    b = 2.0 * (q[0] * d[1] + q[1] * d[2])
    c = q[0] ** 2 + q[1] ** 2 - radius ** 2
    disc = b * b - 4 * a * c
    return (-b + np.sqrt(disc)) / (2 * a) if disc >= 0 else np.nan


OPEN_ENDS = {
    # A swept tail whose aft lofting lines pass the open base of a cylindrical fuselage.
    "fuselage base": dict(
        body=dict(name="body", x=[0.0, 8.0, 30.0], radius=[0.0, 2.0, 2.0], origin=(0, 0, 0)),
        wing=dict(name="tail 1", kind="tail", le=[[24.0, 0.5, 0.15], [32.0, 6.0, 0.4]],
                  chord=[6.0, 3.0])),
    # A stub wing on a pod whose aft end is open (an engine exhaust): its rear lines leave
    # through the exit.
    "pod exit": dict(
        body=dict(name="pod 1", x=[0.0, 3.0, 12.0], radius=[0.0, 1.1, 1.1],
                  origin=(40.0, 9.0, -1.5)),
        wing=dict(name="wing", kind="wing", le=[[47.0, 9.3, -1.4], [52.0, 14.0, -1.0]],
                  chord=[5.5, 2.5])),
}


@pytest.mark.parametrize("case", sorted(OPEN_ENDS))
def test_no_intersection_point_at_an_open_end(case):
    """Lines that meet the side of the body there; lines that pass aft of the end at the
    body's radius and reach its end plane inside it (they enter through the open end) miss:
    the closed form of a straight line against a cylinder decides which is which."""
    spec = OPEN_ENDS[case]
    b = spec["body"]
    body = CircularBody(b["name"], b["x"], b["radius"], origin=b["origin"], axial="linear",
                        mirrored=b["origin"][1] != 0)
    w = spec["wing"]
    thick = np.tile(HALF, (2, 1)) * np.array([[1.0], [0.8]])
    wing = WingLike(w["name"], w["kind"], w["le"], w["chord"], XC, thick, thick)
    cfg = Configuration({body.name: body, wing.name: wing})
    found = find_intersections(cfg)
    pair = Pair(wing.name, body.name, "body")
    assert set(found) == {pair}
    x_end = body.x_global[-1]
    centre = np.array(b["origin"][1:], float)
    r = b["radius"][-1]
    n_side = n_end = 0
    for side, inter in zip(("upper", "lower"), found[pair]):
        lines = wing.lofting_lines(side)
        for j, line in enumerate(lines):
            root, tip = line[0], line[-1]
            s = straight_line_cylinder(root, tip, centre, r)
            p = root + s * (tip - root)
            if p[0] <= x_end:  # meets the side of the cylinder
                n_side += 1
                assert inter.found[j]
                np.testing.assert_allclose(inter.points[j], p, rtol=0, atol=1e-9 * body.length)
            else:  # passes aft of the end at the radius ...
                # ... and reaches the end plane inside the circle: through the open end.
                t = (x_end - root[0]) / (tip[0] - root[0])
                q = root + t * (tip - root)
                assert np.hypot(*(q[1:] - centre)) < r
                n_end += 1
                assert not inter.found[j] and np.isnan(inter.points[j]).all()
    assert n_side >= 4 and n_end >= 4  # the case holds both kinds of line


def fin_behind_the_tail():
    """A tail with its trailing edge at x = 56 (all along the span) and a twin fin whose root
    lies aft of it, swept 45 deg: extended downwards, every fin lofting line passes the
    trailing edge below it."""
    x = np.array([0.0, 10.0, 60.0])
    body = CircularBody("body", x, [0.0, 1.0, 1.0], axial="linear")
    tail = WingLike("tail 1", "tail", [[48.0, 0.5, 0.0], [52.0, 8.0, 0.0]], [8.0, 4.0], XC,
                    np.tile(HALF, (2, 1)))
    fin = WingLike("fin 1", "fin", [[56.15, 3.0, 0.1], [61.15, 3.0, 5.1]], [5.0, 3.0], XC,
                   np.tile(HALF, (2, 1)))
    return Configuration({c.name: c for c in (body, tail, fin)})


def test_a_fin_whose_lines_pass_the_tail_trailing_edge_is_not_paired_with_it():
    from juncture.intersect.pairs import _box, _overlap

    cfg = fin_behind_the_tail()
    fin, tail = cfg["fin 1"], cfg["tail 1"]
    assert _overlap(_box(fin), _box(tail), 0.02)  # a candidate pair for the solver
    for side in ("upper", "lower"):
        lines = fin.lofting_lines(side)
        # Analytic: each line is straight; at the trailing edge (x = 56) it is below z = 0,
        # the height of the (closed) trailing edge; forward of it, lower still (dz/dx >= 1),
        # while the symmetric tail's upper surface is never below z = 0.
        d = lines[:, 1] - lines[:, 0]
        t = (56.0 - lines[:, 0, 0]) / d[:, 0]
        z_te = lines[:, 0, 2] + t * d[:, 2]
        assert np.all(z_te < -0.04) and np.all(d[:, 2] / d[:, 0] >= 1.0)
        # Eq 7 jumps there (outside the planform the line counts as outside, inside it is
        # below the upper surface): no root, no point.
        inter = intersect_winglike(fin, tail, "upper", side)
        assert not inter.found.any()
        assert any("edge of the planform" in s for s in inter.log)
    found = find_intersections(cfg)
    assert not any(p.a == "fin 1" and p.b == "tail 1" for p in found)


def test_an_explicit_pair_that_does_not_touch_is_refused():
    cfg = fin_behind_the_tail()
    with pytest.raises(jc.GeometryError, match=r"fin 1.*stated but no lofting line of fin 1 "
                                               r"meets tail 1"):
        find_intersections(cfg, explicit=[("fin 1", "tail 1", "upper")])


def test_trace_curve_refuses_a_line_without_points():
    from juncture.surface.component_networks import trace_curve

    cfg = example()
    with pytest.raises(jc.GeometryError, match=r"wing: no intersection point to trace on "
                                               r"the lower surface"):
        trace_curve(cfg["wing"], "lower", np.full((7, 3), np.nan))


def ruled_reference(wing):
    """The deck's own description of ``wing`` (tests.deckgen, SciPy PCHIP), not juncture's."""
    from tests.deckgen import WingLikeRef

    return WingLikeRef(wing.kind, wing.le, wing.chord, wing.x_over_c, wing.upper, wing.lower,
                       wing.camber)


def reference_points(fin, side, ref, side_b, from_root):
    """Each straight fin lofting line against ``ref``'s surface, by SciPy's brentq on a
    sign change found by fine sampling (the first from the searched end)."""
    from scipy.optimize import brentq

    sign = 1.0 if side_b == "upper" else -1.0
    out = []
    for line in fin.lofting_lines(side):
        a, b = (line[-1], line[0]) if not from_root else (line[0], line[-1])

        def e(t, a=a, b=b):
            p = a + np.atleast_1d(t)[:, None] * (b - a)
            f = ref.coordinates(p)[1]
            return sign * (p[:, 2] - ref.surface(p[:, 1], f, side_b))

        ts = np.linspace(0.0, 4.0, 4001)
        k = int(np.argmax(e(ts) <= 0))
        t = brentq(lambda t: e(t)[0], ts[k - 1], ts[k], xtol=1e-14, rtol=1e-15)
        out.append(a + t * (b - a))
    return np.array(out)


def test_real_fin_on_wing_and_pylon_under_wing_agree_with_an_independent_solve():
    """The jump rule leaves real pairs as they were: points against SciPy on the deck's
    surfaces."""
    cfg = fin_on_wing()
    found = find_intersections(cfg)
    pair = Pair("fin 1", "wing", "upper")
    ref = ruled_reference(cfg["wing"])
    for side, inter in zip(("upper", "lower"), found[pair]):
        assert inter.found.all()
        expect = reference_points(cfg["fin 1"], side, ref, "upper", from_root=False)
        np.testing.assert_allclose(inter.points, expect, rtol=0, atol=1e-9 * 60.0)
    cfg = example()
    found = find_intersections(cfg)
    ref = ruled_reference(cfg["wing"])
    for name in ("fin 1", "fin 2"):
        pair = Pair(name, "wing", "lower")
        for side, inter in zip(("upper", "lower"), found[pair]):
            assert inter.found.all()
            expect = reference_points(cfg[name], side, ref, "lower", from_root=True)
            np.testing.assert_allclose(inter.points, expect, rtol=0, atol=1e-9 * 300.0)



def test_a_fin_on_the_fuselage_is_not_paired_with_the_wing_inside_it():
    """The fin's lofting lines pass through the fuselage top and then meet the wing's upper
    surface inside the fuselage: roots of eq 7, but each beyond the fuselage
    crossing on its line, so the fin stands on the fuselage only (TM-4607: the first surface
    reached from the tip)."""
    x = np.array([0.0, 10.0, 60.0])
    body = CircularBody("body", x, [0.0, 2.0, 2.0], axial="linear")
    wing = WingLike("wing", "wing", [[20.0, 0.5, 0.0], [30.0, 15.0, 0.0]], [20.0, 6.0], XC,
                    np.tile(HALF, (2, 1)))
    # Root inside the fuselage (allowed: TM-4406 needs only the tip outside).
    fin = WingLike("fin 1", "fin", [[25.0, 1.0, 0.8], [29.0, 1.0, 6.0]], [8.0, 4.0], XC,
                   np.tile(HALF, (2, 1)))
    cfg = Configuration({c.name: c for c in (body, wing, fin)})
    from juncture.intersect.pairs import _box, _overlap

    assert _overlap(_box(fin), _box(wing), 0.02)  # a candidate pair for the solver
    found = find_intersections(cfg)
    assert set(found) == {Pair("wing", "body", "body"), Pair("fin 1", "body", "body")}
    # The wing crossings exist (the pair was a candidate with real roots), inside the body.
    on_body = found[Pair("fin 1", "body", "body")]
    for side, inter in zip(("upper", "lower"), on_body):
        below = intersect_winglike(fin, wing, "upper", side)
        assert below.found.all() and inter.found.all()
        assert np.all(below.u < inter.u)
        assert np.all(body.radial_error(below.points) < 0)


def test_a_canard_whose_tip_stays_inside_the_fuselage_is_refused_by_name():
    """A canard whose tip lies partly inside a wide fuselage (tests/data/generated/refused/
    canard_tip_inside_fuselage.inp) was taken for one that does not touch it: its whole
    network was kept, 0.048 L deep inside the fuselage. The search from the tip cannot start
    inside the body, so the pair is refused, naming the canard and its line; a pod off the
    centre line may still hold a tip (a tip tank) without a refusal."""
    from tests.support import DATA

    cfg = jc.read(DATA / "generated" / "refused" / "canard_tip_inside_fuselage.inp")
    # Independent of juncture's intersection code: the canard's tip points lie on both
    # sides of the fuselage's surface (its own signed distance).
    tip = np.concatenate([cfg["canard 1"].lofting_lines(s)[:, -1] for s in ("upper", "lower")])
    depth = cfg["body"].signed_distance(tip)
    assert depth.min() < 0 < depth.max()
    with warnings.catch_warnings(), pytest.raises(jc.GeometryError) as err:
        warnings.simplefilter("ignore")
        find_intersections(cfg)
    msg = str(err.value)
    assert msg.startswith("canard 1, station 2: the tip of upper lofting line 3 lies inside "
                          "body"), msg
    assert "so that its tip is outside body" in msg
