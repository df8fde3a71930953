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
