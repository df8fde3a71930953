"""Circular-arc fillet (TM-4406 fig 8): an arc of radius rho tangent to body and lofting line."""

import numpy as np
import pytest

from juncture.fillet import circular_fillet
from juncture.intersect import intersect_body
from tests.support import wing_body


@pytest.mark.parametrize("z, rho", [(0.0, 0.8), (1.5, 0.5), (-1.5, 1.2)])
def test_arc_is_tangent_to_the_body_circle_and_the_projected_lofting_line(z, rho):
    """The paper's construction (tangent="lofting-line")."""
    cfg = wing_body(z_root=z)
    wing, body = cfg["wing"], cfg["body"]
    for side in ("upper", "lower"):
        inter = intersect_body(wing, body, side)
        f = circular_fillet(wing, body, inter, rho, blend_length=1e-9, tangent="lofting-line")
        live = f.blend > 0
        pts = f.points[live]
        assert np.ptp(pts[..., 0], axis=1).max() < 1e-12  # each arc at constant x
        # The arc's centre: equidistant (rho) from every arc point.
        a, b, c = pts[:, 0], pts[:, 4], pts[:, -1]
        centre = circumcentre(a[:, 1:], b[:, 1:], c[:, 1:])
        radii = np.linalg.norm(pts[..., 1:] - centre[:, None], axis=-1)
        np.testing.assert_allclose(radii, rho, rtol=1e-9)
        x = pts[:, 0, 0]
        ctr = body.center_at(x)
        # Externally tangent to the body circle: centre distance = r + rho.
        dc = np.hypot(centre[:, 0] - ctr[:, 0], centre[:, 1] - ctr[:, 1])
        np.testing.assert_allclose(dc, body.radius_at(x) + rho, rtol=1e-9)
        # Tangent to the lofting line projected on x = const: distance centre-line = rho.
        lines = wing.lofting_lines(side)[live]
        d = (lines[:, 1] - lines[:, 0])[:, 1:]
        d /= np.linalg.norm(d, axis=1)[:, None]
        v = centre - pts[:, -1, 1:]
        dist = np.abs(v[:, 0] * d[:, 1] - v[:, 1] * d[:, 0])
        np.testing.assert_allclose(dist, rho, rtol=1e-9)


def circumcentre(a, b, c):
    d = 2 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1])
             + c[:, 0] * (a[:, 1] - b[:, 1]))
    sa, sb, sc = (a ** 2).sum(1), (b ** 2).sum(1), (c ** 2).sum(1)
    ux = (sa * (b[:, 1] - c[:, 1]) + sb * (c[:, 1] - a[:, 1]) + sc * (a[:, 1] - b[:, 1])) / d
    uy = (sa * (c[:, 0] - b[:, 0]) + sb * (a[:, 0] - c[:, 0]) + sc * (b[:, 0] - a[:, 0])) / d
    return np.stack([ux, uy], axis=1)


def test_radius_may_vary_with_x():
    cfg = wing_body()
    wing, body = cfg["wing"], cfg["body"]
    inter = intersect_body(wing, body, "upper")
    f = circular_fillet(wing, body, inter, lambda x: 0.3 + 0.02 * x, blend_length=1e-9)
    assert f.kind == "circular" and np.isfinite(f.points).all()


def test_a_warm_started_circular_fillet_is_the_cold_one():
    from benchmarks.geometry import benchmark_configuration

    from juncture.fillet import reduced_body
    from juncture.fillet.circular import circular_fillet
    from juncture.intersect import intersect_body

    cfg = benchmark_configuration()
    wing, body = cfg["wing"], cfg["body"]
    first = circular_fillet(wing, body, intersect_body(wing, body, "upper"), 0.6)
    x = first.start[:, 0]
    smaller = reduced_body(body, x, np.full(x.size, 0.3))
    inter = intersect_body(wing, smaller, "upper")
    cold = circular_fillet(wing, smaller, inter, 0.6)
    warm = circular_fillet(wing, smaller, inter, 0.6, hint=first.u_end)
    np.testing.assert_allclose(warm.points, cold.points, atol=1e-10)


@pytest.mark.parametrize("z_root, side", [(2.5, "upper"), (-2.5, "lower")])
def test_lines_that_miss_the_body_are_left_sharp_where_they_reach_the_plane_of_symmetry(
        z_root, side):
    """Issue 11: no NaN. A lofting line that misses the body (here the upper lines of a high
    wing, the lower lines of a low wing) has no junction to round: its fillet line is the
    point where the line reaches y = 0 (juncture.misses)."""
    cfg = wing_body(z_root=z_root, thickness=10.0)
    wing, body = cfg["wing"], cfg["body"]
    inter = intersect_body(wing, body, side)
    missed = ~inter.found
    assert missed.sum() >= 5
    f = circular_fillet(wing, body, inter, 0.5)
    assert np.isfinite(f.points).all() and np.isfinite(f.theta_start).all()
    pts = f.points[missed]
    np.testing.assert_array_equal(pts, np.broadcast_to(pts[:, :1], pts.shape))
    np.testing.assert_array_equal(pts[:, 0, 1], 0.0)
    # On the extended lofting line of its chord station (through sections 1 and 2).
    lines = wing.lofting_lines(side)[missed]
    a, d = lines[:, 0], lines[:, 1] - lines[:, 0]
    t = (0.0 - a[:, 1]) / d[:, 1]
    np.testing.assert_allclose(pts[:, 0], a + t[:, None] * d, rtol=0, atol=1e-12)
    # Off the body, on the side the surface passes (above for the upper surface).
    err = body.radial_error(pts[:, 0])
    assert np.all(err > 0.05)
    assert np.all(np.sign(pts[:, 0, 2] - body.center_at(pts[:, 0, 0])[:, 1]) == np.sign(z_root))
    assert np.all(f.blend[missed] == 0) and np.all(f.blend[~missed][1:-1] > 0)


def _section_direction(wing, side, p, h=1e-6):
    """Outboard direction of the wing's section by the plane x = p_x at p, in (y, z): from
    the deck's planform (leading edge and chord linear between sections) and the surface."""
    y = p[:, 1][:, None] + np.array([-h, h])[None, :]
    le, ch, ys = wing.le[:, 0], wing.chord, wing.le[:, 1]
    f = (p[:, 0][:, None] - np.interp(y, ys, le)) / np.interp(y, ys, ch)
    q = wing.point(y, f, side)
    d = q[:, 1, 1:] - q[:, 0, 1:]
    return d / np.linalg.norm(d, axis=1)[:, None]


@pytest.mark.parametrize("z, rho", [(0.0, 0.8), (1.5, 0.5), (-1.5, 1.2)])
def test_arc_is_tangent_to_the_wing_section_by_default(z, rho):
    cfg = wing_body(z_root=z, sweep_deg=55.0)
    wing, body = cfg["wing"], cfg["body"]
    for side in ("upper", "lower"):
        inter = intersect_body(wing, body, side)
        f = circular_fillet(wing, body, inter, rho, blend_length=1e-9)
        live = f.blend > 0
        pts = f.points[live]
        centre = circumcentre(pts[:, 0, 1:], pts[:, 4, 1:], pts[:, -1, 1:])
        x = pts[:, 0, 0]
        ctr = body.center_at(x)
        dc = np.hypot(centre[:, 0] - ctr[:, 0], centre[:, 1] - ctr[:, 1])
        np.testing.assert_allclose(dc, body.radius_at(x) + rho, rtol=1e-9)
        # the radius at the end point P is normal to the wing's section there
        d = _section_direction(wing, side, pts[:, -1])
        v = centre - pts[:, -1, 1:]
        np.testing.assert_allclose(np.abs(v[:, 0] * d[:, 1] - v[:, 1] * d[:, 0]), rho,
                                   rtol=1e-6)
        np.testing.assert_allclose(np.abs(v[:, 0] * d[:, 0] + v[:, 1] * d[:, 1]), 0.0,
                                   atol=1e-6 * rho)
        # ... and P is on its lofting line, so the wing network's seam is unchanged
        lines = wing.lofting_lines(side)[live]
        from juncture.intersect.rays import polyline_points
        on_line = polyline_points(lines, f.u_end[live][:, None])[:, 0]
        np.testing.assert_allclose(on_line, pts[:, -1], atol=1e-12)


def _check_generated(text, desc, keep_area=False):
    import warnings

    import juncture as jc
    from tests.deckgen import read_text
    from tests.deckgen.references import fillet_depths

    cfg = read_text(text)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            geo = jc.complete(cfg, "circular", keep_area=keep_area)
        except jc.GeometryError as exc:
            # keep_area's known open class (issue 11), or a refusal the deck deserves: a
            # fillet larger than the body can give up, naming the station and what to change.
            msg = str(exc)
            if "enters body only through the face of the step" in msg:
                # a line entering only through a joint step's face (test_complete_misses)
                assert desc["joints"] == "repeated" and desc["segments"] > 1, msg
                return
            assert keep_area and "\n" not in msg and msg.startswith("body"), msg
            if not isinstance(exc, jc.ConvergenceError):  # (a GeometryError subclass)
                assert "can give up" in msg and "use a smaller fillet" in msg, msg
            return
    _, inside_wing = fillet_depths(geo, desc)  # the deck's wing, independent of juncture
    assert inside_wing <= 1e-9, inside_wing
    # the (re-designed) body's exact radial error: tangent arcs touch it, never cut it
    pts = np.concatenate([v.reshape(-1, 3) for v in geo.fillets.values()])
    depth = -np.min(geo.configuration["body"].radial_error(pts)) / desc["length"]
    assert depth <= 1e-10, depth  # the tangency is solved to about 1e-12 of L


FAMILIES = [(h, r) for h in ("low", "mid", "high") for r in ("inside", "crossing", "outside")]


def _generated(count, keep_area, height, root, slow=False):
    from hypothesis import HealthCheck, Phase, given, settings

    from tests.deckgen import wing_body_decks

    phases = (Phase.explicit, Phase.reuse, Phase.generate) if slow else (Phase.explicit,
                                                                          Phase.generate)

    @settings(max_examples=count, deadline=None, derandomize=not slow, phases=phases,
              suppress_health_check=list(HealthCheck))
    @given(wing_body_decks(section="circular", wing_height=height, root=root))
    def run(example):
        _check_generated(*example, keep_area=keep_area)

    run()


@pytest.mark.parametrize("height, root", FAMILIES)
def test_generated_circular_fillets_never_enter_the_wing_or_the_body(height, root):
    _generated(2, False, height, root)


@pytest.mark.parametrize("height", ["low", "high"])
def test_generated_circular_fillets_with_keep_area(height):
    _generated(2, True, height, "crossing")


@pytest.mark.slow
@pytest.mark.parametrize("height, root", FAMILIES)
@pytest.mark.parametrize("keep_area", [False, True])
def test_slow_generated_circular_fillets(height, root, keep_area):
    _generated(15, keep_area, height, root, slow=True)
