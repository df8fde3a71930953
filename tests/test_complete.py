"""complete(): networks, intersections, fillets, stations and seams of a wing-body juncture."""

import re
import warnings

import numpy as np
import pytest

import juncture as jc
from tests.support import EXAMPLE_DECK, wing_body


def example():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(EXAMPLE_DECK)


def seam_gaps(geo, traced=False):
    """Gaps of the seams in the log: exact ones, or those traced at the wing's stations."""
    return [float(m.group(1)) for m in (re.search(r"max gap ([-0-9.e+]+)", s)
                                        for s in geo.log if ("traced" in s) == traced) if m]


@pytest.mark.parametrize("fillet", [None, "cubic", "circular"])
@pytest.mark.parametrize("blocks", [4, 6])
def test_blocks_abut_exactly(fillet, blocks):
    geo = jc.complete(example(), fillet, blocks=blocks)
    expect = {4: {"body forward", "wing-body upper", "wing-body lower", "body aft"},
              6: {"body forward", "body upper", "body lower", "wing upper", "wing lower",
                  "body aft"}}[blocks]
    assert expect <= set(geo.networks)
    gaps = seam_gaps(geo)
    assert len(gaps) >= 6 and max(gaps) < 1e-12
    # Other components pass through untouched.
    assert {"tail 1 upper", "fin 3 outboard", "pod 1"} <= set(geo.networks)


def test_six_block_wing_starts_with_the_intersection_line():
    cfg = example()
    # Without the pylons: they would add traced curves to the wing networks (TM-4607).
    cfg = cfg.replace(components={k: v for k, v in cfg.components.items()
                                  if k not in ("fin 1", "fin 2")})
    geo = jc.complete(cfg, None, blocks=6)
    np.testing.assert_allclose(geo.networks["wing upper"][0],
                               geo.intersections["wing/body upper"], atol=1e-12)
    # The remaining n-lines are the input airfoil sections outboard of it.
    np.testing.assert_allclose(geo.networks["wing upper"][1:],
                               cfg["wing"].section_points("upper")[1:], atol=1e-12)


def test_fillets_run_from_body_to_wing():
    cfg = example()
    geo = jc.complete(cfg, "cubic")
    body, wing = cfg["body"], cfg["wing"]
    fu = geo.fillets["fillet upper"]
    assert fu.shape == (wing.n_stations, 9, 3)
    assert np.abs(body.radial_error(fu[:, 0])).max() < 1e-9 * body.length
    assert np.all(np.abs(body.radial_error(fu[1:-1, -1])) > 1e-3)  # ends off the body


def test_keep_area_on_the_example():
    geo = jc.complete(example(), "cubic", keep_area=True)
    s = geo.stations
    np.testing.assert_allclose(np.pi * s["radius_new"] ** 2 + s["area_fillet"],
                               s["area_original"], rtol=1e-9)
    assert s["area_fillet"][1:-1].min() > 0


def test_keep_area_short_of_its_tolerance_keeps_its_best_iterate_or_says_how_far(monkeypatch):
    """An iteration that cannot reach the tolerance (1e-17, below the fillets' own
    precision) returns its best iterate with a warning naming the residual once that is
    1e-6 or less; one stopped far from it (a single iteration) raises ConvergenceError."""
    import juncture.completion as completion

    real = completion._keep_area

    def capped(n):
        return lambda *a, **kw: real(*a, **{**kw, "max_iterations": n})

    monkeypatch.setattr(completion, "_keep_area", capped(6))
    with pytest.warns(jc.JunctureWarning, match=r"area compensation stopped at a residual "
                                                 r"of .* not 1e-17, after 6 iterations"):
        geo = jc.complete(example(), "cubic", True, tolerance=1e-17)
    res = np.asarray(geo.stations["residual"])
    assert 0.0 < res.max() <= 1e-7  # measured independently of the iteration's own best:
    body, body0 = geo.configuration["body"], example()["body"]
    x = np.asarray(geo.stations["x"])
    total = np.pi * body.radius_at(x) ** 2 + np.asarray(geo.stations["area_fillet"])
    np.testing.assert_allclose(total, np.pi * body0.radius_at(x) ** 2, rtol=1e-7)
    monkeypatch.setattr(completion, "_keep_area", capped(1))
    with pytest.raises(jc.ConvergenceError,
                       match="did not reach 1e-17 in 1 iterations .*a smaller theta_u"):
        jc.complete(example(), "cubic", True, tolerance=1e-17)


def test_single_network_fuselage():
    geo = jc.complete(example(), "cubic", single_network=True)
    body = geo.networks["body"]
    x_le = geo.intersections["wing/body upper"][0, 0]
    assert body.ndim == 3 and body.shape[1] >= 10
    # Lower intersection re-interpolated at the upper points' x (TM-4406 fig 4).
    fl = geo.fillets["fillet lower"]
    np.testing.assert_allclose(fl[:, 0, 0], geo.fillets["fillet upper"][:, 0, 0])
    assert body[:, 0, 0].min() < x_le < body[:, 0, 0].max()


def test_bad_options_are_clear():
    cfg = example()
    with pytest.raises(jc.OptionError, match="theta = 3: expected no such option; the options"):
        jc.complete(cfg, "cubic", theta=3)
    with pytest.raises(jc.OptionError, match="fillet = 'round': expected None, 'cubic' or"):
        jc.complete(cfg, "round")
    with pytest.raises(jc.OptionError, match="blocks = 5: expected None, 4, 6 or 'split'"):
        jc.complete(cfg, blocks=5)
    with pytest.raises(jc.GeometryError, match="needs a fuselage named 'hull'"):
        jc.complete(cfg, body="hull")


@pytest.mark.parametrize("fillet, keep_area, options, match", [
    ("cubic", False, {"theta_u_deg": -10.0},
     r"theta_u_deg = -10.0: expected an angle in \(0, 90\)"),
    ("cubic", False, {"theta_u_deg": 90.0}, "theta_u_deg = 90.0"),
    ("cubic", False, {"theta_u_deg": float("nan")}, "theta_u_deg = nan"),
    ("cubic", False, {"blend_length": -3.0}, "blend_length = -3.0: expected a length > 0"),
    ("cubic", False, {"end_value": 0.0}, "end_value = 0.0: expected a span increment > 0"),
    ("cubic", False, {"end": "section", "end_value": 100.0},
     r"end_value = 100.0: expected a fraction in \(0, 1\] with end='section'"),
    ("cubic", False, {"end": "tip"}, "end = 'tip'"),
    ("circular", False, {"fillet_radius": 0.0}, "fillet_radius = 0.0: expected a radius > 0"),
    ("cubic", False, {"fillet_radius": 1.0}, "fillet_radius = 1.0: expected no value unless "
     "fillet='circular'"),
    ("circular", False, {"theta_u_deg": 30.0}, None),  # a default-valued field: no complaint
    ("circular", False, {"remedy": "parabolas"}, "remedy = 'parabolas': expected no value unless"),
    (None, True, {}, "keep_area = True: expected False without a fillet"),
    (None, False, {"blend_length": 2.0}, "blend_length = 2.0: expected no value without"),
    ("cubic", False, {"single_network": True, "remedy": "parabolas"},
     "remedy = 'parabolas': expected 'z-constraint' or None with single_network"),
    ("cubic", False, {"n_fillet_points": 2}, "n_fillet_points = 2: expected an integer >= 3"),
    ("cubic", False, {"tolerance": 0.0}, r"tolerance = 0.0: expected a relative tolerance"),
])
def test_options_outside_their_range_are_refused_before_any_work(fillet, keep_area, options,
                                                                  match):
    cfg = wing_body()
    if match is None:
        assert jc.complete(cfg, fillet, keep_area, **options).fillets
        return
    with pytest.raises(jc.OptionError, match=match) as info:
        jc.complete(cfg, fillet, keep_area, **options)
    assert "\n" not in str(info.value)


def test_complete_geometry_writes_to_every_format(tmp_path):
    geo = jc.complete(wing_body(), "cubic", keep_area=True)
    for ext in ("wgs", "p3d", "hess", "stl", "vtk"):
        jc.write(geo, tmp_path / f"out.{ext}")
    back = jc.read(tmp_path / "out.wgs")
    assert set(back.networks) == set(geo.networks)


@pytest.mark.parametrize("fillet", [None, "cubic"])
def test_whole_configuration_splits_the_body_by_theta_b(fillet):
    cfg = example()
    geo = jc.complete(cfg, fillet, keep_area=fillet is not None)
    assert {"body upper", "body lower", "wing upper", "wing lower"} <= set(geo.networks)
    seams = [s for s in geo.log if s.startswith("seam") and "traced" not in s]
    # Wing, tail (upper and lower) and the centre-line fin meet the fuselage networks, the
    # two pylons (both sides) their nacelles: 9 seams, all closed.
    assert len(seams) == 9 and max(seam_gaps(geo)) < 1e-12
    # Where pylons meet the wing, the traced curves follow them at the wing's stations.
    assert 0 < max(seam_gaps(geo, traced=True)) < 0.5
    body = geo.configuration["body"]
    up = geo.networks["body upper"]
    assert np.abs(body.radial_error(up)).max() < 1e-9 * body.length
    # The upper surface starts at the fin's intersection where the fin stands.
    fin = geo.intersections["fin 3/body outboard"]
    first = up[:, 0] if up[0, 0, 2] > up[0, -1, 2] else up[:, -1]
    for p in fin:
        assert np.min(np.linalg.norm(first - p, axis=1)) < 1e-9


def squashed(cfg):
    """The example with its fuselage as arbitrary (elliptic) half-sections (deck J2 = +1)."""
    from juncture.model import ArbitraryBody

    b = cfg["body"]
    th = np.linspace(-np.pi / 2, np.pi / 2, 13)
    secs = [np.stack([1.15 * r * np.cos(th), zc + 0.9 * r * np.sin(th)], 1)
            for r, zc in zip(b.radius, b.camber)]
    return cfg.with_component(ArbitraryBody("body", b.x, secs, segments=b.segments))


@pytest.mark.parametrize("blocks", [None, 4, 6])
def test_arbitrary_section_fuselage(blocks):
    cfg = squashed(example())
    body = cfg["body"]
    geo = jc.complete(cfg, None, blocks=blocks)
    for name, pts in geo.intersections.items():
        if name.split("/")[1].startswith("body"):
            assert np.abs(body.signed_distance(pts)).max() < 1e-9 * body.length, name
    assert max(seam_gaps(geo)) < 1e-12
    # Network points on the fuselage lie on it (arc-length parameterisation, TM-4607).
    for name in geo.networks:
        if name.startswith("body"):
            assert np.abs(body.signed_distance(geo.networks[name])).max() < 1e-9


@pytest.mark.parametrize("fillet", ["cubic", "circular"])
@pytest.mark.parametrize("blocks", [None, 4, 6])
def test_fillets_on_an_arbitrary_section_fuselage(fillet, blocks):
    """Past TM-4406 (juncture.fillet.section): the fillet starts on the section, the seams
    are closed and every fuselage network point lies on the fuselage."""
    cfg = squashed(example())
    body = cfg["body"]
    geo = jc.complete(cfg, fillet, blocks=blocks)
    for side in ("upper", "lower"):
        f = geo.fillets[f"fillet {side}"]
        assert np.isfinite(f).all()
        assert np.abs(body.signed_distance(f[:, 0])).max() < 1e-9 * body.length
        assert body.signed_distance(f.reshape(-1, 3)).min() > -1e-9 * body.length
    assert geo.stations["area_fillet"].max() > 0
    assert np.all(geo.stations["area_fillet"] >= 0)
    assert max(seam_gaps(geo)) < 1e-12
    for name in geo.networks:
        if name.startswith("body"):
            assert np.abs(body.signed_distance(geo.networks[name])).max() < 1e-9 * body.length


@pytest.mark.parametrize("fillet", ["cubic", "circular"])
@pytest.mark.parametrize("keep_area", [False, True])
def test_the_single_network_with_a_fillet_on_an_arbitrary_section_fuselage(fillet, keep_area):
    """Completed whole: the fuselage's n-lines are its cross-sections, each lower fillet line
    starts at its upper line's x on the (re-designed) fuselage, circular lines lie in their
    planes, no fillet point is inside the fuselage or the wing (an independent model of the
    deck's wing, lofting lines extended inboard), and the seams close exactly."""
    from tests.deckgen.references import WingLikeRef

    cfg = squashed(example())
    geo = jc.complete(cfg, fillet, keep_area, single_network=True)
    body, w = geo.configuration["body"], cfg["wing"]
    ref = WingLikeRef("wing", w.le, w.chord, w.x_over_c, w.upper, w.lower, w.camber)
    length = body.length
    fu, fl = geo.fillets["fillet upper"], geo.fillets["fillet lower"]
    np.testing.assert_array_equal(fl[:, 0, 0], fu[:, 0, 0])
    assert set(fu[:, 0, 0]) <= set(geo.networks["body"][:, 0, 0])
    assert np.ptp(geo.networks["body"][..., 0], axis=1).max() == 0.0
    if fillet == "circular":
        assert np.all(fl[..., 0] == fl[:, :1, 0]) and np.all(fu[..., 0] == fu[:, :1, 0])
    lines = np.concatenate([fu, fl])
    assert np.isfinite(lines).all()
    assert np.abs(body.signed_distance(lines[:, 0])).max() < 1e-9 * length
    assert body.signed_distance(lines.reshape(-1, 3)).min() > -1e-9 * length
    assert ref.depth(lines.reshape(-1, 3), extend_root=True).max() <= 1e-9 * length
    assert max(seam_gaps(geo)) <= 1e-12 * length


@pytest.mark.parametrize("fillet", ["cubic", "circular"])
@pytest.mark.parametrize("compensation", ["section", "fillet"])
def test_keep_area_scales_an_arbitrary_section_about_its_centroid(fillet, compensation):
    """The re-designed fuselage's sections are the original ones scaled about their
    centroids, body + fillet area is the original at every station (the area of the new
    sections measured here by a 20001-point polygon of the surface), the body never grows,
    and where nothing is removed it is the original surface."""
    cfg = squashed(example())
    body0 = cfg["body"]
    geo = jc.complete(cfg, fillet, keep_area=True, compensation=compensation)
    body1 = geo.configuration["body"]
    st = geo.stations
    s = np.linspace(0.0, 1.0, 20001)
    half = body1.point(st["x"][:, None], s[None, :])[..., 1:]
    y, z = half[..., 0], half[..., 1]
    shoelace = 0.5 * np.abs(np.sum(y[:, :-1] * z[:, 1:] - y[:, 1:] * z[:, :-1], axis=1)
                            + y[:, -1] * z[:, -1] - y[:, 0] * z[:, 0])
    a0 = body0.area_at(st["x"])
    np.testing.assert_allclose(2 * shoelace + st["area_fillet"], a0, rtol=1e-7)
    assert np.all(st["area_fillet"] > 0)
    xs = np.linspace(body0.x_global[0], body0.x_global[-1], 4001)
    assert np.all(body1.area_at(xs) <= body0.area_at(xs) * (1 + 1e-12))
    # A section keeps its shape: scaled about its centroid (the centroid stays put).
    x = st["x"][len(st["x"]) // 2]
    p0, p1 = body0.point(x, s[::500]), body1.point(x, s[::500])
    c0, c1 = body0.centroid_at(x), body1.centroid_at(x)
    np.testing.assert_allclose(c1, c0, atol=1e-9 * body0.length)
    k = np.sqrt(body1.area_at(x) / body0.area_at(x))
    np.testing.assert_allclose(p1[:, 1:] - c1, k * (p0[:, 1:] - c0), atol=1e-9 * body0.length)
    # Ahead of the fillets the surface is the original one.
    x_front = np.linspace(body0.x_global[0], st["x"].min() - 0.05 * body0.length, 50)
    np.testing.assert_allclose(body1.point(x_front[:, None], s[None, ::100]),
                               body0.point(x_front[:, None], s[None, ::100]),
                               rtol=0, atol=1e-12 * body0.length)


def test_the_public_complete_is_the_function_whatever_was_imported_first():
    import juncture.completion

    assert jc.complete is juncture.completion.complete and callable(jc.complete)
    assert jc.CompleteOptions is juncture.completion.CompleteOptions


@pytest.mark.parametrize("fillet", ["cubic", "circular"])
def test_single_network_lines_on_an_arbitrary_section_fuselage(fillet):
    """Underneath complete() (above): on the squashed transport the re-interpolated lines
    start at the upper x on the fuselage, circular arcs lie in their planes x = X, and no
    point is inside the fuselage."""
    from juncture.fillet import circular_fillet, cubic_fillet
    from juncture.intersect import intersect_body_both
    from juncture.single_network import reinterpolated

    cfg = squashed(example())
    wing, body = cfg["wing"], cfg["body"]
    iu, il = intersect_body_both(wing, body)
    make = (lambda i: circular_fillet(wing, body, i, 0.5)) if fillet == "circular" else \
        (lambda i: cubic_fillet(wing, body, i, end="dy", end_value=1.0))
    fu, fl, _ = reinterpolated(wing, body, make(iu), make(il), iu, il, fillet)
    np.testing.assert_array_equal(fl.points[:, 0, 0], fu.points[:, 0, 0])
    if fillet == "circular":
        assert np.all(fl.points[..., 0] == fl.points[:, :1, 0])
    for f in (fu, fl):
        assert np.isfinite(f.points).all()
        assert np.abs(body.signed_distance(f.points[:, 0])).max() < 1e-9 * body.length
        assert body.signed_distance(f.points.reshape(-1, 3)).min() > -1e-9 * body.length


def test_a_single_network_line_beside_a_sharp_trailing_edge_stays_in_the_air(monkeypatch):
    """A held-out airplane (tests/data/generated/README.md): the lower fillet line
    re-interpolated at the last upper x lies between a fillet line and the sharp point at the
    trailing edge, 0.009 ft long. Its inner points, put onto the wing's lower surface, lay
    inside the elliptical fuselage and, put onto that, inside the wing (2.8e-6 L deep by an
    independent model of the deck's wing): they are now on the chord from the line's start on
    the body to its end on the wing. Counterfactual: without that step they are inside."""
    import juncture.single_network as sn
    from tests.deckgen.references import WingLikeRef
    from tests.support import DATA

    cfg = jc.read(DATA / "generated" / "fillet"
                  / "single_network_line_beside_a_sharp_trailing_edge.inp")
    w = cfg["wing"]
    ref = WingLikeRef("wing", w.le, w.chord, w.x_over_c, w.upper, w.lower, w.camber)

    def depths(geo):
        lines = np.concatenate([geo.fillets["fillet upper"], geo.fillets["fillet lower"]])
        body = geo.configuration["body"]
        return (ref.depth(lines.reshape(-1, 3), extend_root=True).max() / body.length,
                -body.signed_distance(lines.reshape(-1, 3)).min() / body.length)

    geo = jc.complete(cfg, "cubic", single_network=True)
    assert np.isfinite(geo.fillets["fillet lower"]).all()
    in_wing, in_body = depths(geo)
    assert in_wing <= 1e-12 and in_body <= 1e-12
    starts = [line for line in geo.log if "fillet start line" in line]
    assert len(starts) == 2 and all(line.endswith("max gap 0") for line in starts)
    monkeypatch.setattr(sn, "_chord_where_buried", lambda wing, body, out, ok: out)
    assert depths(jc.complete(cfg, "cubic", single_network=True))[0] > 1e-6
