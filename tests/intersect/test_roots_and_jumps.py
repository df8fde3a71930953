"""An intersection is a root of the surface equation, never a jump (issue 11).

:func:`juncture.intersect.find_crossings` on error functions given in closed form: a sign
change across a discontinuity is not a root (the line misses, or the root inboard of the
jump is taken), while grazing, shallow and steep crossings of continuous errors are all
roots, found where the closed form puts them. Both bracket closures are exercised: Illinois
(no gradient) and bracketed Newton (an error with ``value_and_gradient``).
"""

import numpy as np
import pytest

from juncture.intersect import find_crossings

N_LINES, N_SECTIONS = 5, 4  # different sizes, so a swapped axis fails


def straight_lines(x_root=0.0, x_tip=12.0):
    """Lines along x from root to tip, each at its own y and z (section k at x_k)."""
    x = np.linspace(x_root, x_tip, N_SECTIONS)
    y = 0.3 + 0.7 * np.arange(N_LINES)
    z = -0.2 + 0.11 * np.arange(N_LINES) ** 1.3
    lines = np.zeros((N_LINES, N_SECTIONS, 3))
    lines[..., 0] = x[None, :]
    lines[..., 1] = y[:, None]
    lines[..., 2] = z[:, None]
    return lines


def with_gradient(value, slope):
    """An error in x only, with or without ``value_and_gradient`` (d e / d x = slope)."""
    def error(points):
        return value(points[..., 0])

    def value_and_gradient(points):
        x = points[..., 0]
        g = np.zeros(points.shape)
        g[..., 0] = slope(x)
        return value(x), g

    return error, value_and_gradient


def make_error(value, slope, newton):
    error, vg = with_gradient(value, slope)
    if newton:
        error.value_and_gradient = vg
    return error


def u_at(x, lines):
    """Section coordinate of station x on the straight lines above (uniform sections)."""
    x0, x1 = lines[0, 0, 0], lines[0, -1, 0]
    return (x - x0) / (x1 - x0) * (N_SECTIONS - 1)


@pytest.mark.parametrize("newton", [False, True], ids=["illinois", "newton"])
def test_a_line_whose_only_sign_change_is_a_jump_misses(newton):
    # Outside (e = 1 + x / 10) aft of x = 7, inside (e = -0.4) forward of it: no root.
    error = make_error(lambda x: np.where(x > 7.0, 1.0 + x / 10.0, -0.4),
                       lambda x: np.where(x > 7.0, 0.1, 0.0), newton)
    cr = find_crossings(straight_lines(), error, -0.5)
    assert not cr.found.any()
    assert np.isnan(cr.points).all() and np.isnan(cr.u).all()
    assert (cr.jumps == 1).all() and (cr.n_crossings == 1).all()


@pytest.mark.parametrize("newton", [False, True], ids=["illinois", "newton"])
def test_the_root_inboard_of_a_jump_is_taken(newton):
    # From the tip: outside, a jump inside at x = 8, a jump outside at x = 5, then the
    # continuous error x - 3.25 reaches zero at x = 3.25: the only root.
    def value(x):
        return np.where(x > 8.0, 2.0, np.where(x > 5.0, -0.7, x - 3.25))

    error = make_error(value, lambda x: np.where(x > 5.0, 0.0, 1.0), newton)
    lines = straight_lines()
    cr = find_crossings(lines, error, -0.5)
    assert cr.found.all()
    np.testing.assert_allclose(cr.points[:, 0], 3.25, rtol=0, atol=1e-12)
    np.testing.assert_allclose(cr.u, u_at(3.25, lines), rtol=0, atol=1e-12)
    assert (cr.jumps == 1).all() and (cr.n_crossings == 3).all()
    assert cr.residual.max() < 1e-12


@pytest.mark.parametrize("newton", [False, True], ids=["illinois", "newton"])
@pytest.mark.parametrize("eps", [1e-3, 1e-6])
def test_a_grazing_double_crossing_is_a_root(newton, eps):
    # e = (x - 6)^2 - eps^2: the line dips into the surface over a length 2 eps; the first
    # root from the tip is x = 6 + eps. |de/dx| <= 2 * 12 on the lines.
    error = make_error(lambda x: (x - 6.0) ** 2 - eps ** 2, lambda x: 2.0 * (x - 6.0), newton)
    cr = find_crossings(straight_lines(), error, 0.0, lipschitz=24.0)
    assert cr.found.all() and (cr.jumps == 0).all()
    np.testing.assert_allclose(cr.points[:, 0], 6.0 + eps, rtol=0, atol=1e-11)
    assert cr.residual.max() < 1e-12


@pytest.mark.parametrize("newton", [False, True], ids=["illinois", "newton"])
@pytest.mark.parametrize("slope", [1e-7, 1.0, 1e5])
def test_shallow_and_steep_crossings_are_roots(newton, slope):
    # A line at a tiny angle to the surface (slope 1e-7) or nearly normal to a steep error:
    # the residual of a continuous error closes with the bracket, whatever the slope.
    error = make_error(lambda x: slope * (x - 4.5), lambda x: np.full(np.shape(x), slope),
                       newton)
    cr = find_crossings(straight_lines(), error, -0.5)
    assert cr.found.all() and (cr.jumps == 0).all()
    np.testing.assert_allclose(cr.points[:, 0], 4.5, rtol=0, atol=1e-11)


def test_the_tolerance_separates_a_small_jump_from_a_root():
    # A jump of 1e-6 with atol 1e-9 is a jump; with atol 1e-5 the same point is accepted
    # (it is within atol of the zero set), so the rule is the residual, nothing else.
    def error(points):
        x = points[..., 0]
        return np.where(x > 7.0, 0.5e-6, -0.5e-6)

    lines = straight_lines()
    assert not find_crossings(lines, error, 0.0, atol=1e-9).found.any()
    cr = find_crossings(lines, error, 0.0, atol=1e-5)
    assert cr.found.all()
    np.testing.assert_allclose(cr.points[:, 0], 7.0, rtol=0, atol=1e-11)


def test_a_hint_that_brackets_a_jump_falls_back_to_the_whole_line():
    def error(points):
        x = points[..., 0]
        return np.where(x > 8.0, 2.0, np.where(x > 5.0, -0.7, x - 3.25))

    lines = straight_lines()
    hint = np.full(N_LINES, u_at(8.0, lines))  # a previous "solution" at the jump
    cr = find_crossings(lines, error, -0.5, hint=hint)
    assert cr.found.all()
    np.testing.assert_allclose(cr.points[:, 0], 3.25, rtol=0, atol=1e-12)


def test_a_search_that_runs_out_of_iterations_names_its_lines(monkeypatch):
    import juncture.intersect.body as body_module
    from juncture.errors import ConvergenceError
    from juncture.intersect import rays
    from tests.support import wing_body

    lines = np.array([[[0.0, 0.0, 0.0], [0.0, 5.0, 0.0]]] * 3)  # root inside, tip outside
    stop = r"did not converge in 3 iterations \(line 1, 2, 3\)"
    with pytest.raises(ConvergenceError, match=stop):
        rays.find_crossings(lines, lambda p: (np.linalg.norm(p, axis=-1) - 1.0) ** 3, 0.0,
                            max_iter=3)  # a triple root: no method closes it in 3 steps

    def stuck(*args, **kwargs):
        raise rays._not_converged(200, [2, 15])

    cfg = wing_body()
    monkeypatch.setattr(body_module, "find_crossings", stuck)
    n = cfg["wing"].n_stations
    with pytest.raises(ConvergenceError) as err:
        body_module.intersect_body_both(cfg["wing"], cfg["body"])
    assert str(err.value).startswith("wing: the intersection with body did not converge "
                                     f"(upper lofting line 3, lower lofting line {15 - n + 1})")


def test_a_line_grazing_the_surface_bisects_a_bounded_number_of_intervals():
    """A lofting line along which the error stays a hair above 0 (grazing the surface, as a
    held-out airplane's line did while keep_area shrank the fuselage): every half of every
    interval stays open, and their number doubled each round (2**21 intervals: out of memory).
    At most MAX_DIPS are evaluated per round; no inside point is invented; a dip that does
    reach inside is still found among them."""
    from juncture.intersect import rays

    lines = np.array([[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]])
    batches = []

    def grazing(points):                       # points (k, 1, 3): one per interval
        batches.append(len(points))
        return np.full(points.shape[:2], 1e-12)
    found, _, _ = rays._refine_dips(lines, grazing, np.zeros(1, int), np.zeros(1),
                                    np.ones(1), np.full(1, 1e-12), np.full(1, 1e-12),
                                    np.ones(1), np.ones(1), max_rounds=30)
    assert not found[0]
    assert max(batches) <= rays.MAX_DIPS and len(batches) == 30

    def dip(points):   # inside only near x = 0.3141 (a narrow dip below a grazing line)
        return np.where(np.abs(points[..., 0] - 0.3141) < 1e-4, -1e-9, 1e-12)
    found, u, e = rays._refine_dips(lines, dip, np.zeros(1, int), np.zeros(1), np.ones(1),
                                    np.full(1, 1e-12), np.full(1, 1e-12), np.ones(1),
                                    np.ones(1), max_rounds=30)
    assert found[0] and abs(u[0] - 0.3141) < 1e-4 and e[0] < 0
