"""R1 (section 3) and R2 (section 4): blending functions, derivatives, G1 by construction."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.blend import build_blend
from juncture.blend.wingbody import blend_f, blend_q1, blend_q2, build_wing_body
from juncture.errors import SpecError
from tests.blend.blend_cases import make_spec

R = 1.3
MODEL = build_blend(make_spec(radius=R, sweep=28.0, x_le=5.5))
LINES, WB, R2 = MODEL.lines, MODEL.wing_body, MODEL.strake
EX = np.array([1.0, 0.0, 0.0])


def fd_check(surface, s, t, h=1e-6, tol=2e-6):
    _, ps, pt = surface.evaluate(s, t)
    fs = (surface.points(s + h, t) - surface.points(s - h, t)) / (2 * h)
    ft = (surface.points(s, t + h) - surface.points(s, t - h)) / (2 * h)
    scale = max(np.max(np.abs(ps)), np.max(np.abs(pt)), 1.0)
    np.testing.assert_allclose(ps, fs, atol=tol * scale)
    np.testing.assert_allclose(pt, ft, atol=tol * scale)


def angle(a, b):
    """Angle between the lines along a and b (atan2 form: accurate near zero)."""
    return np.arctan2(np.linalg.norm(np.cross(a, b), axis=-1), np.abs(np.sum(a * b, -1)))


def test_blend_function_closed_forms():
    f, df = blend_f(np.array([0.0, 0.5, 1.0]), mu=0.3)
    np.testing.assert_allclose(f, [1.0, 0.3, 0.0], atol=1e-15)
    np.testing.assert_allclose(df[[0, 2]], 0.0, atol=1e-15)
    lam = 0.4
    q1, dq1 = blend_q1(np.array([0.0, 1.0]), lam)
    q2, dq2 = blend_q2(np.array([0.0, 1.0]), lam)
    np.testing.assert_allclose(q1, [0, 1])
    np.testing.assert_allclose(q2, [0, 1])
    np.testing.assert_allclose([dq1[0], dq2[1]], [1 / (1 - lam)] * 2)


@settings(max_examples=50, deadline=None)
@given(st.floats(0.0, 1.0), st.floats(0.0, 0.95), st.floats(0.05, 0.95))
def test_q2_inverts_q1_and_f_is_symmetric_for_mu_half(t, lam, mu):
    assert blend_q2(blend_q1(t, lam)[0], lam)[0] == pytest.approx(t, abs=1e-12)
    assert blend_f(t, 0.5)[0] + blend_f(1 - t, 0.5)[0] == pytest.approx(1.0, abs=1e-12)
    h = 1e-6
    tt = min(max(t, h), 1 - h)
    fd = (blend_f(tt + h, mu)[0] - blend_f(tt - h, mu)[0]) / (2 * h)
    assert blend_f(tt, mu)[1] == pytest.approx(fd, abs=1e-5)


@pytest.mark.parametrize("name", ["b1", "b2", "s3", "s4", "b3", "r1"])
def test_surface_derivatives_match_finite_differences(name):
    rng = np.random.default_rng(7)
    s, t = rng.uniform(0.02, 0.98, 13), rng.uniform(0.02, 0.98, 13)
    fd_check(getattr(WB, name), s, t)


def test_s5_derivatives_and_c1_across_g():
    rng = np.random.default_rng(8)
    sig = rng.uniform(0.02, 0.98, 13)
    sig = sig[np.abs(sig - WB.sigma_g) > 1e-3]
    tau = rng.uniform(0.02, 0.98, len(sig))
    fd_check(WB.s5, sig, tau)
    tau = np.linspace(0, 1, 7)
    g = np.full(7, WB.sigma_g)
    h = 1e-7
    left = (WB.s5.points(g, tau) - WB.s5.points(g - h, tau)) / h
    right = (WB.s5.points(g + h, tau) - WB.s5.points(g, tau)) / h
    np.testing.assert_allclose(left, right, rtol=1e-4, atol=1e-5)


def test_r1_meets_the_body_on_the_cylinder_with_the_cylinder_normal():
    sig = np.linspace(WB.sigma_g, 1.0, 57)
    p = WB.r1.points(sig, np.zeros_like(sig))
    np.testing.assert_allclose(np.hypot(p[:, 1], p[:, 2]), R, rtol=1e-13)
    radial = p * [0, 1, 1]
    assert np.max(angle(WB.r1.normals(sig, np.zeros_like(sig)), radial)) < 1e-9


def test_r1_meets_the_wing_line_with_the_wing_tangent_plane():
    sig = np.linspace(0.0, 1.0, 41)[1:-1]
    p = WB.r1.points(sig, np.ones_like(sig))
    np.testing.assert_allclose(p[:, 1], LINES.points["B"][1], atol=1e-13)
    # wing normal by finite differences of the wing's own point evaluation
    uv, _ = LINES.rho3(sig)
    h = 1e-6
    wing = LINES.wing
    du = (wing.points(uv[:, 0] + h, uv[:, 1]) - wing.points(uv[:, 0] - h, uv[:, 1])) / (2 * h)
    dv = (wing.points(uv[:, 0], uv[:, 1] + h) - wing.points(uv[:, 0], uv[:, 1] - h)) / (2 * h)
    np.testing.assert_allclose(p, wing.points(uv[:, 0], uv[:, 1]), atol=1e-13)
    assert np.max(angle(WB.r1.normals(sig, np.ones_like(sig)), np.cross(du, dv))) < 1e-7


def test_s4_cross_boundary_tangent_along_cg_is_axial_eq13():
    t = np.linspace(0, 1, 33)
    _, ps, _ = WB.s4.evaluate(np.zeros_like(t), t)
    assert np.max(angle(ps, np.tile(EX, (33, 1)))) < 1e-12
    assert np.all(ps[:, 0] > 0)


def test_r2_is_a_translation_surface_between_cg_and_plane_t():
    s, t = np.meshgrid(np.linspace(0, 1, 9), np.linspace(0, 1, 11), indexing="ij")
    p = R2.points(s, t)
    np.testing.assert_allclose(p[..., 1:], np.broadcast_to(p[:1, :, 1:], p[..., 1:].shape),
                               atol=1e-14)
    np.testing.assert_allclose(p[-1, :, 0], LINES.x_d, atol=1e-14)
    np.testing.assert_allclose(p[0], WB.s4.points(np.zeros(11), t[0]), atol=1e-14)
    fd_check(R2, s.ravel()[10:-10], t.ravel()[10:-10])


def test_r2_meets_the_body_along_gf_and_r1_along_cg():
    s = np.linspace(0, 1, 21)
    p = R2.points(s, np.ones_like(s))
    np.testing.assert_allclose(np.hypot(p[:, 1], p[:, 2]), R, rtol=1e-13)
    assert np.max(angle(R2.normals(s, np.ones_like(s)), p * [0, 1, 1])) < 1e-9
    sig = WB.sigma_g * s
    n1 = WB.r1.normals(sig, np.zeros_like(s))
    n2 = R2.normals(np.zeros_like(s), s)
    assert np.max(angle(n1, n2)) < 1e-9


@pytest.mark.parametrize("kw, match", [({"mu": 1.0}, "mu"), ({"lam": 1.0}, "lambda"),
                                       ({"beta": 0.0}, "beta")])
def test_bad_blend_options(kw, match):
    with pytest.raises(SpecError, match=match):
        build_wing_body(LINES, **kw)
