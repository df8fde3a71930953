"""Plane cuts of closed networks: juncture.analysis.cuts.

References are closed forms: the circle/ellipse areas of cuts through spheres, ellipsoids and
cylinders (for an affine image p = p0 + A u of the unit ball, the plane n.p = X cuts a disk of
radius sqrt(1 - delta^2) in u-space, delta = (X - n.p0) / |A^T n|, whose vector area maps by the
cofactor matrix det(A) A^-T: projected area pi det(A) (1 - delta^2) n_x / |A^T n|), and exact
polygon areas for faceted prisms.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.analysis.cuts import (
    mach_plane_areas,
    mach_plane_extents,
    normal_areas,
    plane_cut_areas,
    triangulate,
)
from juncture.errors import GeometryError, JunctureError
from juncture.geometry import Geometry

# ---------------------------------------------------------------------------------------------
# Builders (outward orientation: cross(d/d point, d/d line) points out of the solid)


def revolution(xs, rs, n_phi, phi0=0.0, phi_span=2 * np.pi):
    """Body of revolution: lines at stations xs (increasing), points around phi (increasing)."""
    phi = phi0 + np.linspace(0.0, phi_span, n_phi + 1)
    xx = np.broadcast_to(np.asarray(xs, float)[:, None], (len(xs), n_phi + 1))
    r = np.asarray(rs, float)[:, None]
    return np.stack([xx, r * np.cos(phi), r * np.sin(phi)], axis=-1)


def disk(x, r_in, r_out, n_rings, n_phi, facing_forward):
    """Annulus (or disk if r_in = 0) in the plane x, normal -x if facing_forward else +x."""
    rho = np.linspace(r_in, r_out, n_rings + 1)
    if not facing_forward:
        rho = rho[::-1]
    return revolution(np.full(rho.size, x), rho, n_phi)


def ellipsoid(n_lines, n_phi, a_mat=None, p0=None):
    """Affine image p0 + A u of the unit sphere (det A > 0 keeps the orientation)."""
    a_mat = np.eye(3) if a_mat is None else a_mat
    p0 = np.zeros(3) if p0 is None else p0
    t = np.linspace(0.0, np.pi, n_lines + 1)
    unit = revolution(-np.cos(t), np.sin(t), n_phi)
    return p0 + unit @ np.asarray(a_mat).T


def cylinder(x0, x1, radius, n_x, n_phi, n_rings=3):
    side = revolution(np.linspace(x0, x1, n_x + 1), np.full(n_x + 1, radius), n_phi)
    return [side, disk(x0, 0.0, radius, n_rings, n_phi, True),
            disk(x1, 0.0, radius, n_rings, n_phi, False)]


def polygon_area(radius, n_phi):
    return 0.5 * n_phi * radius**2 * np.sin(2 * np.pi / n_phi)


def enclosed_volume(networks):
    t = triangulate(networks)
    return np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6.0


# ---------------------------------------------------------------------------------------------


def test_builders_are_closed_and_outward():
    # divergence theorem: a positive enclosed volume close to the exact one
    assert enclosed_volume(cylinder(0.0, 3.0, 1.0, 7, 64)) == pytest.approx(
        3.0 * polygon_area(1.0, 64), rel=1e-12)
    assert enclosed_volume([ellipsoid(80, 96)]) == pytest.approx(4 * np.pi / 3, rel=2e-3)


def test_sphere_normal_areas_converge_second_order():
    x = np.linspace(-0.9, 0.9, 37) + 0.0123
    exact = np.pi * (1.0 - x**2)
    errs = []
    for n in (32, 64, 128):
        s = normal_areas([ellipsoid(n + 1, n + 3)], x)
        errs.append(np.max(np.abs(s - exact)))
    assert errs[-1] < 2e-3
    rates = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all((rates > 1.8) & (rates < 2.2))


def test_ellipsoid_oblique_cuts_closed_form():
    rng = np.random.default_rng(7)
    a_mat = np.diag([2.0, 0.7, 0.45]) + 0.1 * rng.standard_normal((3, 3))
    assert np.linalg.det(a_mat) > 0
    p0 = np.array([3.0, 0.2, -0.3])
    net = ellipsoid(160, 190, a_mat, p0)
    n = np.array([1.0, -0.6, 0.35])
    w = np.linalg.norm(a_mat.T @ n)
    offsets = n @ p0 + w * np.array([-0.9, -0.5, 0.05, 0.6, 0.95])
    delta = (offsets - n @ p0) / w
    exact = np.pi * np.linalg.det(a_mat) * (1 - delta**2) * n[0] / w
    assert plane_cut_areas([net], n, offsets) == pytest.approx(exact, rel=2e-3)
    # reversing the normal (and offsets) describes the same planes: same projected areas
    assert plane_cut_areas([net], -n, -offsets) == pytest.approx(exact, rel=2e-3)


def test_oblique_cut_of_cylinder_projects_to_the_circle_polygon():
    nets = cylinder(0.0, 10.0, 1.3, 5, 37)
    n = np.array([1.0, 0.4, -0.7])  # planes crossing only the side: x in (0, 10)
    offsets = np.array([2.5, 5.0, 7.2])
    assert plane_cut_areas(nets, n, offsets) == pytest.approx(
        np.full(3, polygon_area(1.3, 37)), rel=1e-13)
    # normal cuts, including a cut through a ring of vertices (x = 4 is a line of the side)
    assert normal_areas(nets, [4.0, 6.1]) == pytest.approx(polygon_area(1.3, 37), rel=1e-13)


def test_flat_faces_on_the_plane_count_as_just_forward():
    nets = cylinder(0.0, 2.0, 1.0, 3, 20)
    s = normal_areas(nets, [-0.1, 0.0, 2.0, 2.1])
    assert s == pytest.approx([0.0, 0.0, polygon_area(1.0, 20), 0.0], abs=1e-13)


def test_tube_hole_subtracts_and_components_add():
    xs = np.linspace(0.0, 4.0, 6)
    outer = revolution(xs, np.full(6, 1.0), 40)
    inner = revolution(xs, np.full(6, 0.6), 40)[:, ::-1]  # normal towards the axis
    tube = [outer, inner, disk(0.0, 0.6, 1.0, 2, 40, True), disk(4.0, 0.6, 1.0, 2, 40, False)]
    ring = polygon_area(1.0, 40) - polygon_area(0.6, 40)
    assert enclosed_volume(tube) == pytest.approx(4.0 * ring, rel=1e-12)
    assert normal_areas(tube, [1.3]) == pytest.approx([ring], rel=1e-13)
    # a second disjoint body (a cylinder beside the tube) adds its area
    pod = [p + np.array([1.0, 3.0, -0.5]) for p in cylinder(0.0, 2.0, 0.5, 4, 24)]
    both = normal_areas(tube + pod, [1.3, 3.5])
    assert both == pytest.approx([ring + polygon_area(0.5, 24), ring], rel=1e-13)


def test_geometry_is_cut_with_its_mirror_image():
    xs = np.linspace(0.0, 3.0, 61)
    rs = np.sqrt(np.clip(xs * (3.0 - xs), 0, None))
    half = revolution(xs, rs, 18, phi0=-np.pi / 2, phi_span=np.pi)  # y >= 0 half
    geo = Geometry(networks={"body": half}, symmetry={"body": "xz"})
    full = revolution(xs, rs, 36, phi0=-np.pi / 2)
    x = np.array([0.4, 1.1, 2.7])
    assert normal_areas(geo, x) == pytest.approx(normal_areas([full], x), rel=1e-12)
    assert normal_areas(geo, x) == pytest.approx(np.pi * x * (3.0 - x), rel=2e-2)


def test_roll_symmetry_of_a_body_of_revolution():
    xs = np.linspace(0.0, 8.0, 41)
    rs = 0.6 * (4 * xs / 8 * (1 - xs / 8)) ** 0.75
    n_phi = 48
    body = [revolution(xs, rs, n_phi)]
    x_off = np.linspace(-1.0, 9.0, 23)
    thetas = 2 * np.pi * np.arange(8) / 8  # multiples of the faceting angle: exact symmetry
    s = mach_plane_areas(body, 1.7, thetas, x_off)
    assert s.shape == (8, 23)
    assert np.max(np.ptp(s, axis=0)) < 1e-12 * s.max()
    other = mach_plane_areas(body, 1.7, [0.3, 1.9], x_off)  # off the facets: approximately
    assert other == pytest.approx(np.broadcast_to(s[0], (2, 23)), abs=5e-3 * s.max())


def test_mach_plane_sphere_closed_form():
    mach = 1.6
    net = ellipsoid(120, 150)
    thetas = np.array([0.0, 0.7, 2.9])
    x_off = np.array([-1.2, -0.6, 0.0, 0.45, 1.1])
    s = mach_plane_areas([net], mach, thetas, x_off)
    exact = np.pi / mach * (1.0 - x_off**2 / mach**2)
    assert s == pytest.approx(np.broadcast_to(exact, s.shape), rel=2e-3)
    ext = mach_plane_extents([net], mach, thetas)
    assert ext == pytest.approx(np.broadcast_to([-mach, mach], (3, 2)), rel=2e-4)


def test_mach_one_gives_normal_areas_and_per_angle_offsets():
    nets = cylinder(1.0, 5.0, 0.8, 6, 30) + [ellipsoid(20, 22, np.diag([1.0, 0.3, 0.2]),
                                                        np.array([3.0, 1.5, 0.0]))]
    x = np.linspace(0.0, 6.0, 13)
    s = mach_plane_areas(nets, 1.0, [0.0, 1.0, 4.0], x)
    assert s == pytest.approx(np.broadcast_to(normal_areas(nets, x), s.shape), abs=1e-13)
    xs = x + 0.013  # away from the end caps, where any tilt changes the cut discontinuously
    near = mach_plane_areas(nets, 1.0 + 1e-12, [2.0], xs)
    assert near[0] == pytest.approx(normal_areas(nets, xs), abs=1e-5)
    per_angle = np.stack([x, x + 0.5])
    s2 = mach_plane_areas(nets, 1.0, [0.0, 1.0], per_angle)
    assert s2[1] == pytest.approx(normal_areas(nets, x + 0.5), abs=1e-13)


@settings(max_examples=25, deadline=None)
@given(shift=st.tuples(*[st.floats(-50, 50, allow_nan=False)] * 3),
       roll=st.floats(0, 2 * np.pi), mach=st.floats(1.0, 3.0))
def test_invariance_under_translation_and_roll(shift, roll, mach):
    shift = np.array(shift)
    base = cylinder(0.0, 2.0, 0.7, 3, 16) + [ellipsoid(10, 12, np.diag([0.5, 0.2, 0.3]),
                                                        np.array([1.0, 1.5, 0.4]))]
    x = np.array([0.3, 0.9, 1.6])
    ref = normal_areas(base, x)
    moved = [p + shift for p in base]
    assert normal_areas(moved, x + shift[0]) == pytest.approx(ref, rel=1e-9, abs=1e-9)
    c, s = np.cos(roll), np.sin(roll)
    rot = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    rolled = [p @ rot.T for p in base]
    assert normal_areas(rolled, x) == pytest.approx(ref, rel=1e-9, abs=1e-12)
    # rolling the body by phi and the cut angle by phi gives the same Mach-plane areas
    xm = np.array([-0.4, 0.5, 1.2])
    a = mach_plane_areas(base, mach, [0.2], xm)
    b = mach_plane_areas(rolled, mach, [0.2 + roll], xm)
    assert b == pytest.approx(a, rel=1e-9, abs=1e-12)


def test_degenerate_triangles_are_ignored():
    xs = np.linspace(0.0, 2.0, 5)
    body = revolution(xs, np.sin(np.pi * xs / 2.0), 12)  # poles: collapsed quads
    t = triangulate([body])
    assert t.shape == (2 * 4 * 12 - 2 * 12, 3, 3)


def test_errors():
    good = cylinder(0.0, 1.0, 1.0, 2, 8)
    with pytest.raises(GeometryError, match="shape"):
        normal_areas([np.zeros((3, 3))], [0.5])
    with pytest.raises(GeometryError, match="non-finite"):
        normal_areas([np.full((2, 2, 3), np.nan)], [0.5])
    with pytest.raises(GeometryError, match="no networks"):
        normal_areas([], [0.5])
    with pytest.raises(GeometryError, match="no triangle"):
        normal_areas([np.zeros((3, 4, 3))], [0.5])
    with pytest.raises(JunctureError, match="normal must be"):
        plane_cut_areas(good, [0.0, 0.0, 0.0], [0.5])
    with pytest.raises(JunctureError, match="offsets must be"):
        plane_cut_areas(good, [1.0, 0.0, 0.0], [[0.5]])
    with pytest.raises(JunctureError, match="Mach number >= 1"):
        mach_plane_areas(good, 0.8, [0.0], [0.5])
    with pytest.raises(JunctureError, match="x_offsets must be"):
        mach_plane_areas(good, 1.5, [0.0, 1.0], np.zeros((3, 4)))
