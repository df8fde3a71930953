"""Analytic solids against tensor Gauss-Legendre quadrature in their own coordinates and
against textbook values (unit cube 1/6, solid cylinder m R^2 / 2, sphere 2/5 m R^2)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.errors import GeometryError
from juncture.massprops import Cuboid, Cylinder, MassProperties, PointMass, Sphere
from tests.massprops.massprops_quadrature import gauss, moments


def frame(axis):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    tmp = np.array([0.0, 0.0, 1.0]) if abs(a[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    e1 = np.cross(a, tmp)
    e1 /= np.linalg.norm(e1)
    return a, e1, np.cross(a, e1)


def rotation(seed):
    q, r = np.linalg.qr(np.random.default_rng(seed).normal(size=(3, 3)))
    return q * np.sign(np.diag(r))


def check(props, m, cg, inertia, rtol=1e-11):
    assert props.mass == pytest.approx(m, rel=rtol)
    np.testing.assert_allclose(props.cg, cg, rtol=rtol, atol=rtol)
    np.testing.assert_allclose(props.inertia, inertia, rtol=rtol,
                               atol=rtol * np.abs(inertia).max())


vec = st.tuples(*[st.floats(-5, 5)] * 3)


@settings(max_examples=20, deadline=None)
@given(center=vec, size=st.tuples(*[st.floats(0.1, 4)] * 3), seed=st.integers(0, 10**6),
       rho=st.floats(0.1, 100))
def test_cuboid_matches_quadrature(center, size, seed, rho):
    axes = rotation(seed)
    nodes = [gauss(3, -s / 2, s / 2) for s in size]
    grid = np.stack(np.meshgrid(*[n[0] for n in nodes], indexing="ij"), -1)
    w = np.einsum("i,j,k->ijk", *[n[1] for n in nodes])
    pts = grid.reshape(-1, 3) @ axes + center            # rows of axes are the box axes
    m, cg, inertia = moments(pts, rho * w.ravel())
    check(Cuboid(center, size, axes).mass_properties(density=rho), m, cg, inertia)


@settings(max_examples=20, deadline=None)
@given(center=vec, axis=vec.filter(lambda a: np.linalg.norm(a) > 0.1),
       radius=st.floats(0.1, 3), hollow=st.floats(0, 0.95), length=st.floats(0.1, 5),
       rho=st.floats(0.1, 100))
def test_cylinder_matches_quadrature(center, axis, radius, hollow, length, rho):
    a, e1, e2 = frame(axis)
    r, wr = gauss(4, hollow * radius, radius)
    x, wx = gauss(3, -length / 2, length / 2)
    phi = np.linspace(0, 2 * np.pi, 9)[:-1]
    R, X, P = np.meshgrid(r, x, phi, indexing="ij")
    w = (wr[:, None, None] * wx[None, :, None] * R) * (2 * np.pi / 8)
    pts = (X[..., None] * a + (R * np.cos(P))[..., None] * e1 + (R * np.sin(P))[..., None] * e2)
    m, cg, inertia = moments(pts.reshape(-1, 3) + center, rho * w.ravel())
    props = Cylinder(center, axis, radius, length, hollow * radius).mass_properties(density=rho)
    check(props, m, cg, inertia)


@settings(max_examples=20, deadline=None)
@given(center=vec, radius=st.floats(0.1, 3), hollow=st.floats(0, 0.95),
       rho=st.floats(-100, 100).filter(lambda r: abs(r) > 0.1))
def test_sphere_matches_quadrature(center, radius, hollow, rho):
    r, wr = gauss(4, hollow * radius, radius)
    ct, wct = gauss(4, -1.0, 1.0)                      # cos(theta)
    phi = np.linspace(0, 2 * np.pi, 9)[:-1]
    R, C, P = np.meshgrid(r, ct, phi, indexing="ij")
    S = np.sqrt(1 - C * C)
    w = wr[:, None, None] * wct[None, :, None] * R**2 * (2 * np.pi / 8)
    pts = np.stack([R * S * np.cos(P), R * S * np.sin(P), R * C], -1)
    m, cg, inertia = moments(pts.reshape(-1, 3) + center, rho * w.ravel())
    props = Sphere(center, radius, hollow * radius).mass_properties(density=rho)
    check(props, m, cg, inertia)
    assert props.volume == pytest.approx(math.copysign(w.sum(), rho), rel=1e-12)


def test_textbook_values():
    cube = Cuboid([0.5, 0.5, 0.5], [1, 1, 1]).mass_properties(density=1.0)
    np.testing.assert_allclose(cube.inertia, np.eye(3) / 6, rtol=1e-15)
    rod = Cylinder([0, 0, 0], [1, 0, 0], 0.01, 3.0).mass_properties(mass=2.0)   # thin rod
    assert rod.inertia[1, 1] == pytest.approx(2.0 * 9.0 / 12, rel=1e-4)
    disk = Cylinder([0, 0, 0], [0, 1, 0], 2.0, 0.5).mass_properties(mass=3.0)
    assert disk.inertia[1, 1] == pytest.approx(3.0 * 4.0 / 2, rel=1e-15)
    tube = Cylinder([0, 0, 0], [0, 0, 1], 1.0, 1.0, 0.999999).mass_properties(mass=1.0)
    assert tube.inertia[2, 2] == pytest.approx(1.0, rel=1e-5)                 # thin shell m R^2
    ball = Sphere([1, 2, 3], 2.0).mass_properties(mass=5.0)
    np.testing.assert_allclose(ball.inertia, 2 / 5 * 5.0 * 4.0 * np.eye(3), rtol=1e-15)
    shell = Sphere([0, 0, 0], 1.0, 0.999999).mass_properties(mass=3.0)
    assert shell.inertia[0, 0] == pytest.approx(2 / 3 * 3.0, rel=1e-5)      # thin shell
    assert PointMass([1, 0, 0], 2.0, name="pilot").mass_properties().inertia_origin[1, 1] == 2.0


def test_plate_with_lightening_hole():
    """A 2 x 1 x 0.1 plate with a hole of radius 0.3 through it at x = 0.5: the negative
    cylinder removes pi 0.09 0.1 of volume, and the CG moves away from the hole."""
    rho = 2.7
    plate = Cuboid([1.0, 0.5, 0.0], [2.0, 1.0, 0.1]).mass_properties(density=rho)
    hole = Cylinder([0.5, 0.5, 0.0], [0, 0, 1], 0.3, 0.1).mass_properties(density=-rho)
    part = plate + hole
    v_hole = math.pi * 0.09 * 0.1
    assert hole.volume == pytest.approx(-v_hole) and hole.mass < 0
    assert part.volume == pytest.approx(0.2 - v_hole, rel=1e-14)
    assert part.mass == pytest.approx(rho * (0.2 - v_hole), rel=1e-14)
    x_cg = (0.2 * 1.0 - v_hole * 0.5) / (0.2 - v_hole)
    np.testing.assert_allclose(part.cg, [x_cg, 0.5, 0.0], rtol=1e-14)
    # Izz about the CG: plate and hole about their own axes, moved to the CG (textbook)
    izz = (rho * 0.2 * (4 + 1) / 12 + rho * 0.2 * (1.0 - x_cg) ** 2
           - rho * v_hole * (0.09 / 2 + (0.5 - x_cg) ** 2))
    assert part.inertia[2, 2] == pytest.approx(izz, rel=1e-13)
    assert part.is_physical()


def test_solids_are_immutable():
    c = Cylinder([0, 0, 0], [0, 0, 2], 1.0, 1.0)
    np.testing.assert_array_equal(c.axis, [0, 0, 1])
    with pytest.raises(ValueError, match="read-only"):
        c.axis[0] = 1.0
    with pytest.raises(AttributeError):
        c.radius = 2.0
    assert isinstance(c.mass_properties(density=1.0), MassProperties)


@pytest.mark.parametrize("make, match", [
    (lambda: Cuboid([0, 0], [1, 1, 1]), "center must be 3 finite numbers"),
    (lambda: Cuboid([0, 0, 0], [1, 0, 1]), "size must be > 0 along every axis"),
    (lambda: Cuboid([0, 0, 0], [1, 1, 1], np.diag([1, 2, 1])), "axes must be 3 orthonormal"),
    (lambda: Cylinder([0, 0, 0], [0, 0, 0], 1, 1), "axis must be non-zero"),
    (lambda: Cylinder([0, 0, 0], [0, 0, 1], -1, 1), "radius must be > 0, found -1"),
    (lambda: Cylinder([0, 0, 0], [0, 0, 1], 1, 1, 1.0), "expected inner_radius < radius"),
    (lambda: Cylinder([0, 0, 0], [0, 0, 1], 1, 1, -0.1), "inner_radius must be >= 0"),
    (lambda: Sphere([0, 0, 0], 1.0, 2.0), "expected inner_radius < radius"),
    (lambda: Sphere([0, 0, np.nan], 1.0), "center must be 3 finite numbers"),
    (lambda: PointMass([0, 0, 0], np.inf), "mass must be finite"),
    (lambda: Sphere([0, 0, 0], 1.0).mass_properties(), "exactly one of density and mass"),
    (lambda: Sphere([0, 0, 0], 1.0).mass_properties(density=1, mass=1), "exactly one"),
    (lambda: Sphere([0, 0, 0], 1.0).mass_properties(density=np.inf), "density must be finite"),
])
def test_solid_errors(make, match):
    with pytest.raises(GeometryError, match=match):
        make()
