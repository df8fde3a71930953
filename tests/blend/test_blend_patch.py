"""Thin-plate forward patch W (section 5): energy, constraints, convergence, errors."""

import numpy as np
import pytest

from juncture.blend import build_blend
from juncture.blend.bspline import BSplineSurface, clamped_knots, greville
from juncture.blend.patch import (
    PatchEdges,
    _energy_matrix,
    refinement_study,
    seam_angles,
    solve_patch,
)
from juncture.errors import SpecError
from tests.blend.blend_cases import make_spec

R = 0.8
MODEL = build_blend(make_spec(radius=R, sweep=20.0, x_le=7.0, elements=10))
EDGES = MODEL.patch.edges


def test_energy_matrix_of_a_bilinear_surface_matches_the_closed_form():
    # W(u, w) = (u, w, u w): W_u = (1, 0, w), W_w = (0, 1, u), W_uw = (0, 0, 1), W_uu = W_ww = 0
    # E = a11 (1 + 1/3) + 2 a12 (1/4) + a22 (1 + 1/3) + 2 b12 (1)
    n_el = 5
    k = clamped_knots(n_el)
    g = greville(k)
    ctrl = np.stack(np.broadcast_arrays(g[:, None], g[None, :], g[:, None] * g[None, :]), -1)
    a11, a12, a22, b11, b12, b22 = 1.5, 0.7, 2.0, 3.0, 1.25, 4.0
    km = _energy_matrix(k, (a11, a12, a22), (b11, b12, b22))
    c = ctrl.reshape(-1, 3)
    energy = float(np.einsum("ic,ij,jc->", c, km.toarray(), c))
    assert energy == pytest.approx(a11 * 4 / 3 + 2 * a12 / 4 + a22 * 4 / 3 + 2 * b12,
                                   rel=1e-12)


def _plane_edges():
    """A flat triangle F=(0,0,0), D=(0,1,0), E=(1,0,0) in z = 0, normals +z."""

    def line(a, b):
        a, b = np.asarray(a, float), np.asarray(b, float)
        def curve(x):
            x = np.asarray(x, float)[..., None]
            return a + x * (b - a), np.broadcast_to(b - a, x.shape[:-1] + (3,)).copy()

        return curve

    def up(x):
        return np.broadcast_to([0.0, 0.0, 1.0], np.shape(x) + (3,)).copy()

    return PatchEdges(line([0, 0, 0], [0, 1, 0]), up, line([0, 0, 0], [1, 0, 0]), up,
                      line([0, 1, 0], [1, 0, 0]), np.array([1.0, 0.0, 0.0]))


def test_flat_data_give_a_flat_patch_with_exact_edges():
    w = solve_patch(_plane_edges(), elements=6)
    uu, ww = np.meshgrid(np.linspace(0, 1, 9), np.linspace(0, 1, 9), indexing="ij")
    p = w.points(uu, ww)
    np.testing.assert_allclose(p[..., 2], 0.0, atol=1e-13)
    x = np.linspace(0, 1, 9)
    np.testing.assert_allclose(w.points(np.zeros(9), x), np.c_[0 * x, x, 0 * x], atol=1e-13)
    np.testing.assert_allclose(w.points(x, np.ones(9)), np.c_[x, 1 - x, 0 * x], atol=1e-13)
    np.testing.assert_allclose(w.points(np.ones(9), x), np.tile([1.0, 0, 0], (9, 1)),
                               atol=1e-13)
    assert isinstance(w.spline, BSplineSurface)


def test_patch_edges_lie_on_the_body_and_on_plane_t():
    w = MODEL.patch
    x = np.linspace(0, 1, 41)
    fe = w.points(x, np.zeros_like(x))
    np.testing.assert_allclose(np.hypot(fe[:, 1], fe[:, 2]), R, rtol=1e-13)
    df = w.points(np.zeros_like(x), x)
    np.testing.assert_allclose(df[:, 0], MODEL.lines.x_d, atol=1e-13)
    de = w.points(x, np.ones_like(x))
    np.testing.assert_allclose(de, MODEL.lines.de(x)[0], atol=1e-13)
    np.testing.assert_allclose(w.points(np.ones(5), np.linspace(0, 1, 5)),
                               np.tile(MODEL.lines.points["E"], (5, 1)), atol=1e-13)


def test_patch_normals_along_fe_are_radial_within_half_a_degree():
    w = MODEL.patch
    u = np.linspace(0, 0.999, 101)
    p = w.points(u, np.zeros_like(u))
    n = w.normals(u, np.zeros_like(u))
    radial = p * [0, 1, 1]
    ang = np.degrees(np.arctan2(np.linalg.norm(np.cross(n, radial), axis=-1),
                                np.abs(np.sum(n * radial, -1))))
    assert ang.max() < 0.5


def test_coarse_refinement_decreases_energy_change_and_seam_errors():
    rows = refinement_study(EDGES, levels=(3, 6, 12))
    changes = [r["energy_change"] for r in rows[1:]]
    assert changes[1] < changes[0]
    for key in ("angle_df_deg", "angle_fe_deg", "edge_gap"):
        vals = [r[key] for r in rows]
        assert all(b < a for a, b in zip(vals, vals[1:], strict=False)), (key, vals)


def test_refinement_study_to_32_spans_is_monotone():
    rows = refinement_study(EDGES, levels=(4, 8, 16, 32))
    for key in ("energy", "angle_df_deg", "angle_fe_deg", "edge_gap"):
        vals = [r[key] for r in rows]
        assert all(b < a for a, b in zip(vals, vals[1:], strict=False)), (key, vals)
    changes = [r["energy_change"] for r in rows[1:]]
    assert all(b < a for a, b in zip(changes, changes[1:], strict=False))
    assert rows[-1]["angle_fe_deg"] < 0.05 and rows[-1]["angle_df_deg"] < 0.01


def test_seam_angles_of_the_model_are_below_half_a_degree():
    ang = seam_angles(MODEL.patch)
    assert ang["DF"] < 0.5 and ang["FE"] < 0.5


@pytest.mark.parametrize("de_normal", [True, False])
def test_patch_has_no_fold(de_normal):
    """Neighbouring normals of W never turn by more than 90 degrees (no fold-over)."""
    w = solve_patch(EDGES, 12, de_normal=de_normal)
    uu, ww = np.meshgrid(np.linspace(0, 0.995, 120), np.linspace(0, 1, 120), indexing="ij")
    n = w.normals(uu, ww)
    assert np.sum(n[1:] * n[:-1], -1).min() > 0
    assert np.sum(n[:, 1:] * n[:, :-1], -1).min() > 0


def test_de_normal_constraint_holds_at_collocation_points():
    w = MODEL.patch
    g = greville(clamped_knots(w.elements))[1:-1]
    _, _, pw = w.spline.evaluate(g, np.ones_like(g))
    n = EDGES.de_normal(g)
    assert np.max(np.abs(np.sum(n * pw, -1)) / np.linalg.norm(pw, axis=-1)) < 1e-8


@pytest.mark.parametrize("kw, match", [({"elements": 1}, "at least 2"),
                                       ({"bend": (0.0, 5.0, 5.0)}, "bend coefficients")])
def test_bad_patch_options(kw, match):
    with pytest.raises(SpecError, match=match):
        solve_patch(EDGES, **kw)
