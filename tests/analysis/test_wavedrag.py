"""Slender-body and far-field wave drag: juncture.analysis.wavedrag.

Reference values are closed forms (wavedrag.md; Ashley & Landahl ch. 9):

* Sears-Haack body, S = S_max (4 xi (1 - xi))^1.5: D/q = 128 V^2 / (pi l^4) = (9 pi/2)(S_max/l)^2.
* von Karman ogive (least drag for given length and base area), S' = a_1 sin(theta):
  D/q = 4 S_b^2 / (pi l^2).
* Parabolic-arc body, r = r_max 4 xi (1 - xi), S' = (2 S_max / l)(cos theta - cos 3 theta):
  D/q = 128 S_max^2 / (3 pi l^2) (the sine coefficients of cos(k theta) on (0, pi) summed
  analytically).
* A finite sine series S' = sum a_n sin(n theta): D/q = (pi/4) sum n a_n^2, S(l) = pi l a_1 / 4.
* The least-drag curve's many-mode limit and the kernel sums: tests/analysis/references.py.
"""

import dataclasses
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.analysis._kernel import area_kernel, slope_kernel
from juncture.analysis.cuts import mach_plane_areas, mach_plane_extents, normal_areas
from juncture.analysis.wavedrag import (
    eminton_lord,
    eminton_lord_convergence,
    far_field_drag,
    roll_angles,
    sears_haack_area,
    sears_haack_drag,
    von_karman,
)
from juncture.errors import GeometryError, JunctureError, JunctureWarning
from tests.analysis.references import kernel_sum, least_drag_limit, least_drag_modes


def sh_exact(volume, length):
    s_max = 16.0 * volume / (3.0 * np.pi * length)
    return 4.5 * np.pi * (s_max / length) ** 2


def sh_stations(kind, m, rng):
    """Stations on [0, 1] of several spacings, first 0 and last 1."""
    if kind == "uniform":
        return np.linspace(0.0, 1.0, m)
    if kind == "cosine":
        return 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, m)))
    if kind == "clustered-nose":
        return np.linspace(0.0, 1.0, m) ** 2
    inner = np.sort(rng.uniform(0.0, 1.0, m - 2))  # random
    return np.concatenate([[0.0], inner, [1.0]])


@pytest.mark.parametrize("fineness", [6.0, 12.0, 25.0])
@pytest.mark.parametrize("kind", ["uniform", "cosine", "clustered-nose", "random"])
def test_sears_haack_bodies(fineness, kind):
    rng = np.random.default_rng(11)
    length = 37.0
    d_max = length / fineness
    s_max = 0.25 * np.pi * d_max**2
    volume = 3.0 * np.pi * s_max * length / 16.0
    x = 4.5 + length * sh_stations(kind, 117, rng)
    area = sears_haack_area(x - 4.5, length, volume)
    assert area.max() == pytest.approx(s_max, rel=1e-3)
    r = eminton_lord(x, area)
    expected = 128.0 * volume**2 / (np.pi * length**4)
    assert sears_haack_drag(volume, length) == pytest.approx(expected, rel=1e-14)
    assert sh_exact(volume, length) == pytest.approx(expected, rel=1e-14)
    tol = 1e-5 if kind != "random" else 1e-4  # random gaps leave parts of the body unsampled
    assert r.d_over_q == pytest.approx(expected, rel=tol)
    assert r.d_over_q <= expected * (1 + 1e-9)  # least drag through points of the body
    assert r.residual < 1e-10 * s_max
    assert r.method == "eminton-lord" and r.x_nose == 4.5 and r.length == pytest.approx(length)


def test_convergence_table_117_station_sears_haack():
    x = np.linspace(0.0, 1.0, 117)
    area = sears_haack_area(x, 1.0, 3.0 * np.pi / 16.0)
    table = eminton_lord_convergence(x, area, n_modes=(200, 400, 1000, 2000, 4000))
    assert table[:, 0].tolist() == [200, 400, 1000, 2000, 4000]
    d = table[:, 1]
    assert np.all(np.diff(d) <= 1e-12 * d[0])  # more modes, more freedom: never more drag
    assert np.abs(d / d[-1] - 1.0).max() < 1e-6
    assert d == pytest.approx(4.5 * np.pi, rel=1e-5)
    assert eminton_lord(x, area).d_over_q == pytest.approx(d[-1], rel=1e-7)  # default modes


def test_von_karman_ogive_open_base():
    length, s_base = 3.0, 0.8
    x = np.linspace(0.0, length, 41)
    theta = np.arccos(1.0 - 2.0 * x / length)
    area = s_base / np.pi * (theta - 0.5 * np.sin(2.0 * theta))
    expected = 4.0 * s_base**2 / (np.pi * length**2)
    r = eminton_lord(x, area, n_modes=300)
    assert r.d_over_q == pytest.approx(expected, rel=1e-10)
    assert r.base_area == pytest.approx(s_base, rel=1e-12)
    assert eminton_lord([0.0, length], [0.0, s_base]).d_over_q == pytest.approx(expected,
                                                                               rel=1e-12)
    vk = von_karman(lambda xx: 8 * s_base / (np.pi * length) * np.sqrt(xx / length *
                                                                        (1 - xx / length)),
                    length, 20)
    assert vk.d_over_q == pytest.approx(expected, rel=1e-12)
    assert vk.area(x) == pytest.approx(area, abs=1e-12)


def test_open_base_finite_series_body():
    # S' = a1 sin t + a2 sin 2t + a3 sin 3t: open base pi l a1 / 4; exact D/q from the series
    length, a = 2.5, np.array([0.3, 0.25, -0.04])
    expected = 0.25 * np.pi * np.sum(np.arange(1, 4) * a**2)
    x = np.linspace(0.0, length, 97)
    th = np.arccos(1 - 2 * x / length)
    area = 0.25 * length * (a[0] * (th - 0.5 * np.sin(2 * th))
                            + a[1] * (np.sin(th) - np.sin(3 * th) / 3)
                            + a[2] * (np.sin(2 * th) / 2 - np.sin(4 * th) / 4))
    assert area.min() > -1e-15
    r = eminton_lord(x, area)
    assert r.base_area == pytest.approx(0.25 * np.pi * length * a[0], rel=1e-12)
    assert r.d_over_q == pytest.approx(expected, rel=1e-5)
    assert r.d_over_q <= expected * (1 + 1e-12)
    assert r.coefficients[:3] == pytest.approx(a, abs=1e-3 * np.abs(a).max())


def test_parabolic_arc_body_against_von_karman_exact_slope():
    length, s_max = 9.0, 0.6
    expected = 128.0 * s_max**2 / (3.0 * np.pi * length**2)

    def slope(xx):
        xi = xx / length
        return 32.0 * s_max / length * xi * (1 - xi) * (1 - 2 * xi)

    vk = von_karman(slope, length, 400)
    assert vk.d_over_q == pytest.approx(expected, rel=1e-9)
    x = np.linspace(0.0, length, 117)
    area = s_max * (4 * x / length * (1 - x / length)) ** 2
    r = eminton_lord(x, area)
    # S'' != 0 at the ends: the least-drag curve through 117 points lies 7e-5 below, O(h^2)
    assert r.d_over_q == pytest.approx(vk.d_over_q, rel=1e-4)
    assert r.d_over_q < vk.d_over_q
    x2 = np.linspace(0.0, length, 233)
    r2 = eminton_lord(x2, s_max * (4 * x2 / length * (1 - x2 / length)) ** 2)
    assert 3.5 < (vk.d_over_q - r.d_over_q) / (vk.d_over_q - r2.d_over_q) < 4.5
    xs = np.linspace(-1.0, length + 1.0, 53)
    exact_area = s_max * (4 * np.clip(xs / length, 0, 1) * (1 - np.clip(xs / length, 0, 1))) ** 2
    assert r.area(xs) == pytest.approx(exact_area, abs=1e-4 * s_max)
    assert r.area(x) == pytest.approx(area, abs=1e-12)
    # the least-drag slope follows the exact one except within one spacing of the ends
    away = (xs < -1e-9) | (xs > length + 1e-9) | ((xs > x[1]) & (xs < x[-2]))
    exact_slope = np.where((xs >= 0) & (xs <= length), slope(xs), 0.0)
    assert r.slope(xs[away]) == pytest.approx(exact_slope[away], abs=2e-3 * s_max / length)


def test_von_karman_sears_haack_exact_and_area():
    length, volume = 4.0, 1.3
    s_max = 16 * volume / (3 * np.pi * length)

    def slope(xx):
        xi = (xx - 1.0) / length
        return 6.0 * s_max / length * np.sqrt(4 * xi * (1 - xi)) * (1 - 2 * xi)

    r = von_karman(slope, length, 12, x_nose=1.0)
    assert r.d_over_q == pytest.approx(sears_haack_drag(volume, length), rel=1e-12)
    assert r.coefficients[1] == pytest.approx(3 * s_max / length, rel=1e-12)
    x = np.linspace(1.0, 5.0, 31)
    assert r.area(x) == pytest.approx(sears_haack_area(x - 1.0, length, volume), abs=1e-12)
    assert r.c_d(2.0) == pytest.approx(r.d_over_q / 2.0)


@settings(max_examples=30, deadline=None)
@given(shift=st.floats(-1e3, 1e3), x_scale=st.floats(0.05, 50.0),
       a_scale=st.floats(1e-3, 1e3))
def test_invariance_under_shift_and_scale(shift, x_scale, a_scale):
    rng = np.random.default_rng(3)
    x = np.concatenate([[0.0], np.sort(rng.uniform(0.02, 0.98, 29)), [1.0]])
    area = (np.sin(np.pi * x) ** 2) * (1 + 0.3 * x) + 0.2 * x**3  # open base 0.2
    ref = eminton_lord(x, area, n_modes=400).d_over_q
    r = eminton_lord(shift + x_scale * x, a_scale * area, n_modes=400)
    assert r.d_over_q == pytest.approx(ref * a_scale**2 / x_scale**2, rel=1e-8)


def test_result_is_immutable():
    r = eminton_lord([0.0, 1.0, 2.0], [0.0, 1.0, 0.0])
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.d_over_q = 0.0
    with pytest.raises(ValueError, match="read-only"):
        r.coefficients[0] = 1.0


# ---------------------------------------------------------------------------------------------
# Far field


def test_far_field_identical_bodies_and_trig_average():
    x = np.linspace(0.0, 1.0, 81)
    base = sears_haack_area(x, 1.0, 3 * np.pi / 16)
    one = eminton_lord(x, base).d_over_q
    thetas = np.pi / 3 + 2 * np.pi * np.arange(5) / 5
    r = far_field_drag(np.tile(base, (5, 1)), x, thetas)
    assert r.d_over_q == pytest.approx(one, rel=1e-12)
    # S_max(theta) = 1 + eps cos(theta): D(theta) ~ (1 + eps cos)^2, mean 1 + eps^2 / 2 exactly
    eps = 0.4
    areas = (1 + eps * np.cos(thetas))[:, None] * base
    r = far_field_drag(areas, x, thetas)
    assert r.d_over_q == pytest.approx(one * (1 + eps**2 / 2), rel=1e-12)
    assert r.d_over_q_theta == pytest.approx(one * (1 + eps * np.cos(thetas)) ** 2, rel=1e-12)
    assert r.c_d(4.0) == pytest.approx(r.d_over_q / 4.0)


def test_far_field_trims_each_equivalent_body():
    x = np.linspace(0.0, 1.0, 61)
    base = sears_haack_area(x, 1.0, 0.5)
    one = eminton_lord(x, base).d_over_q
    dx = x[1] - x[0]
    grid = -10 * dx + dx * np.arange(100)
    padded = np.zeros((4, 100))
    for k, lead in enumerate([10, 3, 25, 0]):  # equivalent bodies starting at different X
        padded[k, lead:lead + 61] = base
    thetas = 2 * np.pi * np.arange(4) / 4
    r = far_field_drag(padded, grid, thetas)
    assert r.d_over_q_theta == pytest.approx(np.full(4, one), rel=1e-9)
    untrimmed = far_field_drag(padded, grid, thetas, trim=False)
    assert np.all(untrimmed.d_over_q_theta <= one * (1 + 1e-9))  # zeros only at points
    empty = far_field_drag(np.zeros((2, 5)), np.arange(5.0), [0.0, np.pi])
    assert empty.d_over_q == 0.0 and empty.bodies == (None, None)


def test_far_field_of_cut_body_of_revolution():
    # end to end: faceted Sears-Haack body -> Mach-plane cuts -> averaged drag
    length, volume = 10.0, 0.6
    xs = 0.5 * length * (1 - np.cos(np.linspace(0.0, np.pi, 121)))
    rs = np.sqrt(sears_haack_area(xs, length, volume) / np.pi)
    phi = np.linspace(0.0, 2 * np.pi, 65)
    body = np.stack([np.broadcast_to(xs[:, None], (121, 65)), rs[:, None] * np.cos(phi),
                     rs[:, None] * np.sin(phi)], axis=-1)
    exact = sears_haack_drag(volume, length)
    x = np.linspace(0.0, length, 101)
    normal = eminton_lord(x, normal_areas([body], x)).d_over_q
    assert normal == pytest.approx(exact, rel=5e-3)  # faceting: inscribed polygons
    thetas = 2 * np.pi * np.arange(4) / 4
    ext = mach_plane_extents([body], 1.0, thetas)
    offsets = np.linspace(ext[:, 0], ext[:, 1], 101).T
    s = mach_plane_areas([body], 1.0, thetas, offsets)
    assert far_field_drag(s, offsets, thetas).d_over_q == pytest.approx(normal, rel=1e-9)
    ext = mach_plane_extents([body], 1.4, thetas)
    offsets = np.linspace(ext[:, 0], ext[:, 1], 101).T
    s = mach_plane_areas([body], 1.4, thetas, offsets)
    ff = far_field_drag(s, offsets, thetas)
    assert ff.d_over_q == pytest.approx(normal, rel=3e-2)
    assert np.ptp(ff.d_over_q_theta) < 1e-6 * ff.d_over_q  # roll symmetry


# ---------------------------------------------------------------------------------------------
# Errors and warnings


def test_eminton_lord_errors_and_warning():
    with pytest.raises(GeometryError, match="equal length"):
        eminton_lord([0.0, 1.0], [0.0, 1.0, 2.0])
    with pytest.raises(GeometryError, match="at least 2 stations"):
        eminton_lord([0.0], [0.0])
    with pytest.raises(GeometryError, match="increase strictly"):
        eminton_lord([0.0, 1.0, 1.0, 2.0], [0.0, 1.0, 1.0, 0.0])
    with pytest.raises(GeometryError, match="non-finite"):
        eminton_lord([0.0, np.nan, 2.0], [0.0, 1.0, 0.0])
    with pytest.raises(GeometryError, match="negative"):
        eminton_lord([0.0, 1.0, 2.0], [0.0, -1.0, 0.0])
    with pytest.raises(GeometryError, match="S = 0 at the nose"):
        eminton_lord([0.0, 1.0, 2.0], [0.5, 1.0, 0.0])
    with pytest.raises(JunctureError, match="n_modes must be at least"):
        eminton_lord(np.linspace(0, 1, 10), np.sin(np.linspace(0, np.pi, 10)), n_modes=5)
    with pytest.warns(JunctureWarning, match="ill-conditioned"):
        eminton_lord([0.0, 0.5, 0.5 + 1e-13, 1.0], [0.0, 1.0, 1.0, 0.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        eminton_lord(np.linspace(0, 1, 117), np.sin(np.linspace(0, np.pi, 117)))


def test_other_errors():
    with pytest.raises(JunctureError, match="length must be positive"):
        von_karman(np.sin, 0.0, 10)
    with pytest.raises(JunctureError, match="n_modes must be at least 1"):
        von_karman(np.sin, 1.0, 0)
    with pytest.raises(JunctureError, match="dSdx must return"):
        von_karman(lambda x: 1.0, 1.0, 5)
    with pytest.raises(JunctureError, match="positive"):
        sears_haack_drag(-1.0, 1.0)
    with pytest.raises(JunctureError, match="positive"):
        sears_haack_area([0.5], 0.0, 1.0)
    with pytest.raises(JunctureError, match="reference area"):
        eminton_lord([0.0, 1.0], [0.0, 1.0]).c_d(0.0)
    x = np.linspace(0, 1, 6)
    with pytest.raises(JunctureError, match="equally spaced"):
        far_field_drag(np.zeros((3, 6)), x, [0.0, 1.0, 2.0])
    with pytest.raises(JunctureError, match=r"cut_areas must be \(n_theta, n_x\)"):
        far_field_drag(np.zeros(6), x, [0.0])
    with pytest.raises(JunctureError, match="x_cut must be"):
        far_field_drag(np.zeros((2, 6)), x[:4], [0.0, np.pi])
    with pytest.raises(JunctureError, match="reference area"):
        far_field_drag(np.zeros((2, 6)), x, [0.0, np.pi]).c_d(-1.0)


# ---------------------------------------------------------------------------------------------
# The infinite series: closed-form kernels and the many-mode limit (independent references in
# tests/analysis/references.py: numpy sums and least squares on their own sine basis)


def test_closed_form_kernels_equal_the_mode_sums():
    rng = np.random.default_rng(5)
    theta = np.concatenate([rng.uniform(0.0, np.pi, 5), [np.pi, 1e-3, 0.5, 0.5 + 1e-9]])
    phi = np.concatenate([rng.uniform(0.0, np.pi, 4), [np.pi, 0.5, 2.0]])
    k_sum, j_sum = kernel_sum(theta, phi)  # 200,000 modes: K's tail < 1e-11, J's ~ 1e-8
    k = area_kernel(theta[:, None], phi[None, :])
    assert np.abs(k - k_sum).max() < 1e-10
    assert np.abs(slope_kernel(theta[:, None], phi[None, :]) - j_sum).max() < 1e-7
    assert k == pytest.approx(area_kernel(phi[None, :], theta[:, None]), abs=1e-15)
    g1 = phi - 0.5 * np.sin(2 * phi)
    assert area_kernel(np.pi, phi) == pytest.approx(np.pi * g1, rel=1e-14)
    # dK/dtheta = 2 sin(theta) J (centred differences)
    h = 1e-6
    dk = (area_kernel(theta[:, None] + h, phi) - area_kernel(theta[:, None] - h, phi)) / (2 * h)
    inner = (theta > 2 * h) & (theta < np.pi - 2 * h)
    assert dk[inner] == pytest.approx((2 * np.sin(theta[:, None]) *
                                       slope_kernel(theta[:, None], phi))[inner], abs=1e-7)


def kinked_cases():
    """Station areas of kinked curves (S' jumps at stations): an open-base cone-cylinder-
    boattail on uniform stations, and a seeded closed polyline on uneven ones."""
    x1 = np.linspace(0.0, 10.0, 41)
    s1 = np.interp(x1, [0.0, 3.0, 7.0, 10.0], [0.0, 1.0, 1.0, 0.6])
    rng = np.random.default_rng(23)
    x2 = np.concatenate([[0.0], np.sort(rng.uniform(0.05, 2.95, 27)), [3.0]]) + 4.0
    knots = np.linspace(4.0, 7.0, 7)
    s2 = np.interp(x2, knots, [0.0, 0.3, 0.9, 1.0, 0.7, 0.25, 0.0])
    return [(x1, s1), (x2, s2)]


@pytest.mark.parametrize("case", [0, 1])
def test_eminton_lord_is_the_many_mode_limit_on_kinked_areas(case):
    x, area = kinked_cases()[case]
    limit, order = least_drag_limit(x, area)
    assert order == pytest.approx(2.0, abs=0.15)  # the truncation error falls as N^-2
    r = eminton_lord(x, area)
    assert r.n_modes is None and r.nodes.shape == (x.size - 1,)
    assert r.d_over_q == pytest.approx(limit, rel=1e-7)
    assert r.area(x) == pytest.approx(area, abs=1e-12 * area.max())
    assert r.residual < 1e-12 * area.max()
    # the old default, max(400, 8 m) modes, leaves more than 1e-4 on these curves
    old = eminton_lord(x, area, n_modes=max(400, 8 * x.size)).d_over_q
    assert old / limit - 1.0 > 1e-4
    assert old == pytest.approx(least_drag_modes(x, area, max(400, 8 * x.size)), rel=1e-9)
    # the slope is the derivative of the area (independent kernels)
    xm = 0.5 * (x[1:] + x[:-1])
    h = 1e-6 * (x[-1] - x[0])
    fd = (r.area(xm + h) - r.area(xm - h)) / (2 * h)
    assert r.slope(xm) == pytest.approx(fd, abs=1e-6 * np.abs(fd).max())
    # the first coefficients: a_n = (1/n) sum_i lambda_i g_n(theta_i); a_1 carries the base
    assert r.base_area == pytest.approx(area[-1], abs=1e-12)
    assert r.series(3) == pytest.approx(r.coefficients[:3], rel=1e-12)


def test_infinite_series_drag_is_the_least():
    x, area = kinked_cases()[0]
    exact = eminton_lord(x, area).d_over_q
    finite = eminton_lord_convergence(x, area, n_modes=(100, 400, 1600))[:, 1]
    assert np.all(finite > exact) and np.all(np.diff(finite) < 0.0)
    assert (finite[1] - exact) / (finite[2] - exact) == pytest.approx(16.0, rel=0.05)


# ---------------------------------------------------------------------------------------------
# Roll angles


def test_roll_angles_half_turn_boole_and_full_turn():
    th, w = roll_angles(16, half_turn=True)
    assert th.size == 17 and np.degrees(np.diff(th)) == pytest.approx(np.full(16, 11.25))
    assert th[0] == pytest.approx(-np.pi / 2) and th[-1] == pytest.approx(np.pi / 2)
    assert w.sum() == pytest.approx(1.0, rel=1e-15)
    assert (w * 16 * 45 / 2)[:9] == pytest.approx([7, 32, 12, 32, 14, 32, 12, 32, 14])
    # Boole's rule integrates polynomials of degree 5 exactly: (1/pi) int theta^4 = pi^4 / 80
    assert np.dot(w, th**4) == pytest.approx(np.pi**4 / 80, rel=1e-13)
    assert np.dot(w, np.cos(th) ** 2) == pytest.approx(0.5, abs=1e-9)
    th6, w6 = roll_angles(6, half_turn=True)  # not a multiple of 4: Simpson
    assert (w6 * 18) == pytest.approx([1, 4, 2, 4, 2, 4, 1])
    th5, w5 = roll_angles(5, half_turn=True)  # odd: trapezoid
    assert (w5 * 10) == pytest.approx([1, 2, 2, 2, 2, 1])
    thf, wf = roll_angles(8)
    assert thf == pytest.approx(2 * np.pi * np.arange(8) / 8) and wf == pytest.approx(
        np.full(8, 1 / 8))
    with pytest.raises(JunctureError, match="n_theta must be at least 1"):
        roll_angles(0)


def test_far_field_with_weights():
    x = np.linspace(0.0, 1.0, 41)
    base = sears_haack_area(x, 1.0, 0.5)
    th, w = roll_angles(4, half_turn=True)
    scale = 1.0 + 0.3 * np.cos(th)
    r = far_field_drag(scale[:, None] * base, x, th, weights=w)
    one = eminton_lord(x, base).d_over_q
    assert r.d_over_q == pytest.approx(one * np.dot(w, scale**2), rel=1e-12)
    assert r.weights == pytest.approx(w) and r.thetas == pytest.approx(th)
    with pytest.raises(JunctureError, match="summing to 1"):
        far_field_drag(np.tile(base, (5, 1)), x, th, weights=2 * w)
    with pytest.raises(JunctureError, match="or come with weights"):
        far_field_drag(np.tile(base, (5, 1)), x, th)
