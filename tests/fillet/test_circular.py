"""Circular-arc fillet (TM-4406 fig 8): an arc of radius rho tangent to body and lofting line."""

import numpy as np
import pytest

from juncture.fillet import circular_fillet
from juncture.intersect import intersect_body
from tests.support import wing_body


@pytest.mark.parametrize("z, rho", [(0.0, 0.8), (1.5, 0.5), (-1.5, 1.2)])
def test_arc_is_tangent_to_the_body_circle_and_the_projected_lofting_line(z, rho):
    cfg = wing_body(z_root=z)
    wing, body = cfg["wing"], cfg["body"]
    for side in ("upper", "lower"):
        inter = intersect_body(wing, body, side)
        f = circular_fillet(wing, body, inter, rho, blend_length=1e-9)
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
