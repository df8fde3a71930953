"""Blending and boundary lines (paper section 1): geometric properties and errors."""

import numpy as np
import pytest

from juncture.blend.lines import build_lines
from juncture.blend.spec import build_body, build_wing, load_spec
from juncture.errors import GeometryError
from tests.blend.blend_cases import make_spec

SPEC = load_spec(make_spec(radius=1.3, sweep=28.0, x_le=5.5))
BODY, WING = build_body(SPEC), build_wing(SPEC)
LINES = build_lines(BODY, WING, SPEC["lines"])
EX = np.array([1.0, 0.0, 0.0])


def fd(curve, s, h=1e-6):
    return (curve(s + h)[0] - curve(s - h)[0]) / (2 * h)


def test_m_and_h_lie_on_one_axial_iso_line():
    (m, _, h), _ = LINES.rho1(np.array([0.0, LINES.s_g, 1.0]))
    assert m[1] == pytest.approx(h[1], abs=1e-14)
    assert m[0] < h[0]
    # M is the forward-most point of the projection
    uv, _ = LINES.rho1(np.linspace(0, 1, 501))
    assert uv[:, 0].min() == pytest.approx(m[0], abs=1e-14)


def test_rho1_projects_the_enlarged_section_onto_the_body():
    y_j, x_le, z_le, c, ct = LINES.junction
    assert y_j == pytest.approx(1.3)  # wing plane through the axis: junction at y = R
    s = np.linspace(0, 1, 9)
    uv, _ = LINES.rho1(s)
    p = BODY.points(uv[:, 0], uv[:, 1])
    np.testing.assert_allclose(np.hypot(p[:, 1], p[:, 2]), 1.3, rtol=1e-14)
    k = LINES.kappa
    np.testing.assert_allclose(p[:, 0], x_le + c / 2 + k * c * (s**2 - 0.5), atol=1e-13)
    # half-thickness of a NACA 4-digit section, enlarged
    y_t = 5 * (0.2969 * s - 0.1260 * s**2 - 0.3516 * s**4 + 0.2843 * s**6 - 0.1036 * s**8)
    np.testing.assert_allclose(p[:, 2], z_le + k * ct * y_t, atol=1e-13)


@pytest.mark.parametrize("name", ["rho1", "rho2", "fe"])
def test_curve_derivatives_match_finite_differences(name):
    curve = getattr(LINES, name)
    s = np.array([0.05, 0.2, 0.29, 0.31, 0.5, 0.77, 0.95])
    np.testing.assert_allclose(curve(s)[1], fd(curve, s), rtol=1e-6, atol=1e-8)


def test_rho2_is_an_axial_shift_of_rho1_on_mg_and_c1_at_g():
    s = np.linspace(0, LINES.s_g, 31)
    d = LINES.rho2(s)[0] - LINES.rho1(s)[0]
    np.testing.assert_allclose(d, np.tile([LINES.h, 0.0], (31, 1)), atol=1e-14)
    sg, h = LINES.s_g, 1e-5
    left = (LINES.delta(np.array([sg]))[0] - LINES.delta(np.array([sg - h]))[0]) / h
    right = (LINES.delta(np.array([sg + h]))[0] - LINES.delta(np.array([sg]))[0]) / h
    np.testing.assert_allclose(left, 0.0, atol=1e-12)
    np.testing.assert_allclose(right, 0.0, atol=1e-3 * LINES.h)


def test_strake_lines_gf_parallel_to_cd_and_de_tangent_to_the_axis():
    p = LINES.points
    cd, gf = p["D"] - p["C"], p["F"] - p["G"]
    np.testing.assert_allclose(np.cross(cd, EX), 0.0, atol=1e-14)
    np.testing.assert_allclose(np.cross(gf, EX), 0.0, atol=1e-14)
    assert cd[0] < 0 and gf[0] < 0
    t = LINES.de(np.array([0.0, 1.0]))[1]
    np.testing.assert_allclose(np.cross(t[0], EX), 0.0, atol=1e-12)  # continues CD at D
    e = p["E"]
    assert np.hypot(e[1], e[2]) == pytest.approx(1.3, rel=1e-14)
    # at E, DE lies in the body's tangent plane (normal radial) and climbs
    assert abs(np.dot(t[1], e * [0, 1, 1])) < 1e-12 * np.linalg.norm(t[1])
    assert t[1][2] > 0
    assert p["C"][2] < e[2] < p["G"][2]
    np.testing.assert_allclose(fd(LINES.de, np.array([0.1, 0.5, 0.9])),
                               LINES.de(np.array([0.1, 0.5, 0.9]))[1], rtol=1e-7)
    np.testing.assert_allclose(LINES.de(np.array([0.0, 1.0]))[0], [p["D"], p["E"]],
                               atol=1e-14)


def test_wing_line_ab_is_an_iso_line_at_the_requested_station():
    uv, _ = LINES.rho3(np.linspace(0, 1, 11))
    pts = WING.points(uv[:, 0], uv[:, 1])
    np.testing.assert_allclose(pts[:, 1], LINES.points["B"][1], atol=1e-14)
    c_j = LINES.junction[3]
    assert LINES.points["B"][1] == pytest.approx(1.3 + 0.25 * c_j)


@pytest.mark.parametrize("lines, match", [
    ({"strake_y": 1.0}, "strake edge y"),
    ({"g_fraction": 0.8}, "thickest point"),
    ({"wing_line_y": 1.0}, "outboard of the junction"),
    ({"nose_length": 40.0}, "ahead of the body start"),
    ({"strake_length": -1.0}, "must be positive"),
    ({"base_offset": 3.0}, "folds or degenerates"),
    ({"nose_rise": 1.0}, "nose_rise"),
])
def test_bad_lines_raise(lines, match):
    spec = load_spec(make_spec(radius=1.3, sweep=28.0, x_le=5.5, lines=lines))
    with pytest.raises(GeometryError, match=match):
        build_lines(build_body(spec), build_wing(spec), spec["lines"])
