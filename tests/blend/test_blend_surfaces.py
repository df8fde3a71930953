"""Parametric-surface layer: closed forms, finite differences, B-spline precision, errors."""

import dataclasses

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.blend.bspline import BSplineSurface, basis_matrix, clamped_knots, greville
from juncture.blend.surfaces import (
    AirfoilWing,
    CircleSection,
    ConstantSectionBody,
    PlaneSurface,
    SplineSection,
    naca_thickness,
)
from juncture.errors import GeometryError

R = 1.37
BODY = ConstantSectionBody(CircleSection(R, z_axis=0.21), -2.0, 9.0)
WING = AirfoilWing(y=[0.0, 1.1, 4.3], x_le=[5.0, 5.3, 7.9], z_le=[0.1, 0.12, 0.3],
                   chord=[4.0, 3.6, 1.2], thickness=[0.1, 0.09, 0.06])


def fd_check(surface, u, v, h=1e-6, rtol=1e-6):
    """Central differences of points against the analytic first derivatives."""
    _, pu, pv = surface.evaluate(u, v)
    fu = (surface.points(u + h, v) - surface.points(u - h, v)) / (2 * h)
    fv = (surface.points(u, v + h) - surface.points(u, v - h)) / (2 * h)
    scale = max(np.max(np.abs(pu)), np.max(np.abs(pv)), 1.0)
    np.testing.assert_allclose(pu, fu, atol=rtol * scale)
    np.testing.assert_allclose(pv, fv, atol=rtol * scale)


def test_circular_body_points_and_normals_closed_form():
    x = np.array([[-1.0, 0.5, 3.0], [4.0, 6.5, 8.9]])
    th = np.array([[0.0, 0.4, 1.2], [-0.7, 2.0, 3.0]])
    p = BODY.points(x, th)
    assert p.shape == (2, 3, 3)
    np.testing.assert_allclose(p[..., 0], x, atol=1e-15)
    np.testing.assert_allclose(np.hypot(p[..., 1], p[..., 2] - 0.21), R, rtol=1e-14)
    radial = np.stack([np.zeros_like(th), np.cos(th), np.sin(th)], -1)
    np.testing.assert_allclose(BODY.outward_normals(x, th), radial, atol=1e-14)


@settings(max_examples=25, deadline=None)
@given(st.floats(-1.0, 8.0), st.floats(-3.0, 3.0))
def test_body_derivatives_match_finite_differences(x, th):
    fd_check(BODY, np.array([x]), np.array([th]))


@settings(max_examples=40, deadline=None)
@given(st.floats(0.05, 0.95), st.floats(0.02, 0.98), st.booleans())
def test_wing_derivatives_match_finite_differences(u, v, lower):
    # away from the section joint at v = 1.1 / 4.3, where the loft has a slope break
    if abs(v - 1.1 / 4.3) < 1e-3:
        v += 2e-3
    fd_check(WING, np.array([-u if lower else u]), np.array([v]))


def test_naca_thickness_is_half_of_t_at_thirty_percent_chord():
    # NACA 4-digit property: the thickness formula gives t/2 at x/c = 0.3 (Abbott & von
    # Doenhoff, section 6.4); closed trailing edge: zero at x/c = 1
    assert naca_thickness(np.sqrt(0.3)) == pytest.approx(0.5, abs=2e-4)
    assert naca_thickness(1.0) == pytest.approx(0.0, abs=1e-12)


def test_wing_sections_leading_and_trailing_edges():
    v = WING.v_stations
    le = WING.points(np.zeros(3), v)
    np.testing.assert_allclose(le, np.c_[WING.x_le, WING.y, WING.z_le], atol=1e-14)
    te_u, te_l = WING.points(np.ones(3), v), WING.points(-np.ones(3), v)
    np.testing.assert_allclose(te_u, te_l, atol=1e-14)
    np.testing.assert_allclose(te_u[:, 0], WING.x_le + WING.chord, atol=1e-14)
    xi = np.sqrt(0.3)
    thick = WING.points(np.full(3, xi), v)[:, 2] - WING.points(np.full(3, -xi), v)[:, 2]
    np.testing.assert_allclose(thick, WING.thickness * WING.chord, rtol=5e-4)


def test_wing_section_at_interpolates_linearly():
    x_le, z_le, c, ct = WING.section_at(2.7)
    lam = (2.7 - 1.1) / (4.3 - 1.1)
    assert x_le == pytest.approx(5.3 + lam * 2.6)
    assert c == pytest.approx(3.6 + lam * (1.2 - 3.6))
    assert ct == pytest.approx((1 - lam) * 3.6 * 0.09 + lam * 1.2 * 0.06)
    assert z_le == pytest.approx(0.12 + lam * 0.18)


def test_spline_section_of_a_circle_matches_the_circle():
    th = np.linspace(0, 2 * np.pi, 181, endpoint=False)
    sec = SplineSection(np.c_[R * np.cos(th), 0.21 + R * np.sin(th)])
    z = np.array([-0.9, 0.0, 0.3, 1.2])
    v, dvdz, _ = sec.v_at_height(z)
    y, zz, _, dz = sec.evaluate(v)
    np.testing.assert_allclose(zz, z, atol=1e-12)
    np.testing.assert_allclose(y, np.sqrt(R**2 - (z - 0.21) ** 2), rtol=1e-6)
    np.testing.assert_allclose(dvdz * dz, 1.0, rtol=1e-12)


def test_plane_surface():
    pl = PlaneSurface([1.0, 2.0, 3.0], [0.5, 0.0, 0.0], [0.0, 0.0, 2.0])
    p, pu, pv = pl.evaluate(np.array([0.2]), np.array([0.7]))
    np.testing.assert_allclose(p, [[1.1, 2.0, 4.4]])
    np.testing.assert_allclose(pl.normals(0.3, 0.3), [0.0, -1.0, 0.0])


def test_bspline_reproduces_bilinear_function_exactly():
    ku, kv = clamped_knots(5), clamped_knots(7)
    gu, gv = greville(ku), greville(kv)
    ctrl = np.stack(np.broadcast_arrays(gu[:, None] * 2.0, gv[None, :] - 1.0,
                                        gu[:, None] * gv[None, :]), -1)
    surf = BSplineSurface(ctrl, ku, kv)
    rng = np.random.default_rng(3)
    u, v = rng.random(11), rng.random(11)
    p, pu, pv = surf.evaluate(u, v)
    np.testing.assert_allclose(p, np.c_[2 * u, v - 1, u * v], atol=1e-13)
    np.testing.assert_allclose(pu, np.c_[np.full(11, 2.0), np.zeros(11), v], atol=1e-12)
    np.testing.assert_allclose(pv, np.c_[np.zeros(11), np.ones(11), u], atol=1e-12)
    puu, puv, pvv = surf.second_derivatives(u, v)
    np.testing.assert_allclose(puv, np.tile([0.0, 0.0, 1.0], (11, 1)), atol=1e-10)
    np.testing.assert_allclose(puu, 0.0, atol=1e-10)


def test_basis_is_a_partition_of_unity():
    k = clamped_knots(6)
    x = np.linspace(0, 1, 37)
    np.testing.assert_allclose(basis_matrix(k, 3, x).sum(axis=1), 1.0, atol=1e-14)
    np.testing.assert_allclose(basis_matrix(k, 3, x, 1).sum(axis=1), 0.0, atol=1e-11)


def test_values_are_immutable():
    with pytest.raises(dataclasses.FrozenInstanceError):
        BODY.x_start = 0.0
    with pytest.raises(ValueError, match="read-only"):
        WING.chord[0] = 1.0


@pytest.mark.parametrize("make, match", [
    (lambda: CircleSection(-1.0), "radius must be positive"),
    (lambda: CircleSection(1.0).v_at_height(1.5), "outside the body radius"),
    (lambda: ConstantSectionBody(CircleSection(1.0), 2.0, 1.0), "must exceed x_start"),
    (lambda: AirfoilWing([0, 0], [0, 0], [0, 0], [1, 1], [0.1, 0.1]), "must increase"),
    (lambda: AirfoilWing([0, 1], [0, 0], [0, 0], [1, -1], [0.1, 0.1]), "chords must be"),
    (lambda: AirfoilWing([0], [0], [0], [1], [0.1]), ">= 2 equal-length"),
    (lambda: SplineSection([[1, 0], [0, 1]]), "needs"),
    (lambda: SplineSection([[1, 0], [0, -1], [-1, 0], [0, 1]]), "counter-clockwise"),
    (lambda: SplineSection([[1, 0], [0, 1], [-1, 0], [0, -1]]).v_at_height(2.0),
     "outside the right side"),
    (lambda: clamped_knots(0), "at least one span"),
    (lambda: BSplineSurface(np.zeros((4, 4, 2)), clamped_knots(1), clamped_knots(1)),
     "control points must be"),
    (lambda: BSplineSurface(np.zeros((4, 5, 3)), clamped_knots(1), clamped_knots(1)),
     "do not fit"),
])
def test_errors(make, match):
    with pytest.raises(GeometryError, match=match):
        make()
