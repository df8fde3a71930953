"""Where a wing meets a body in a cross-section plane (juncture.intersect.stations)."""

from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

import juncture as jc
from juncture.intersect import intersect_body
from juncture.intersect.stations import plane_points

ROOT = Path(__file__).resolve().parents[2]
TRANSPORT = ROOT / "examples" / "supersonic_transport.inp"
SHOULDER = ROOT / "tests" / "data" / "generated" / "high_wing_on_the_fuselage_shoulder.inp"


def wing_height(wing, side, p):
    """The wing surface's thickness coordinate at the points' (x, span): the chord fraction
    solved from x by bracketing on the model's own section point (not the intersection's
    root finder)."""
    out = []
    for q in p:
        span = q[wing.span_axis]
        f = brentq(lambda f, s=span, x=q[0]: wing.point(s, f, side, extrapolate=True)[0] - x,
                   -0.5, 1.5, xtol=1e-15)
        out.append(wing.point(span, f, side, extrapolate=True)[wing.thickness_axis])
    return np.array(out)


@pytest.mark.parametrize("side", ["upper", "lower"])
def test_points_lie_in_their_plane_on_the_deck_circle_and_on_the_wing(side):
    cfg = jc.read(TRANSPORT)
    wing, body = cfg["wing"], cfg["body"]
    inter = intersect_body(wing, body, side)
    xs = body.x_global
    got = plane_points(wing, body, side, inter.points, xs)
    ok = np.all(np.isfinite(got), axis=1)
    x_in = inter.points[inter.found, 0]
    # every station strictly inside the root chord is solved, none outside
    inside = (xs > x_in.min() + 1e-6) & (xs < x_in.max() - 1e-6)
    assert ok.sum() >= 5 and np.array_equal(ok, inside)
    L = body.length
    p = got[ok]
    assert np.abs(p[:, 0] - xs[ok]).max() <= 1e-12 * L
    # on the circle the deck gives at that very station (radius and centre as written)
    i = np.flatnonzero(ok)
    centre_z = body.origin[2] + (body.camber[i] if body.camber is not None else 0.0)
    r = np.hypot(p[:, 1] - body.origin[1], p[:, 2] - centre_z)
    assert np.abs(r - body.radius[i]).max() <= 1e-9 * L
    assert np.abs(wing_height(wing, side, p) - p[:, 2]).max() <= 1e-9 * L


def test_a_station_outside_the_points_or_beside_a_missed_line_is_nan():
    cfg = jc.read(TRANSPORT)
    wing, body = cfg["wing"], cfg["body"]
    inter = intersect_body(wing, body, "upper")
    pts = inter.points.copy()
    pts[3] = np.nan                                   # a line that misses
    x = np.array([pts[0, 0] - 1.0, 0.5 * (pts[2, 0] + pts[4, 0]), pts[-1, 0] + 1.0,
                  0.5 * (pts[5, 0] + pts[6, 0])])
    got = plane_points(wing, body, "upper", pts, x)
    assert np.isnan(got[:3]).all()
    assert np.all(np.isfinite(got[3]))


def test_fuselage_rows_inside_a_high_wing_root_end_on_the_wing():
    """A generated high wing sitting on an arbitrary fuselage's shoulder, with a tail (the
    TM-4607 split layout): the fuselage's rows at its own stations between the wing's chord
    stations ended at the angle interpolated between the intersection points, up to 0.4 ft
    inside the wing (0.02 of the fuselage's height), and the wing's lower surface crossed the
    fuselage block. Now every row inside the root chord ends on the wing's surface."""
    cfg = jc.read(SHOULDER)
    geo = jc.complete(cfg)
    wing = geo.configuration["wing"]
    L = float(np.ptp(geo.extents()[:, 0]))
    for side in ("upper", "lower"):
        inter = np.asarray(geo.intersections[f"wing/body {side}"])
        net = np.asarray(geo.networks[f"body {side}"])
        ends = net[:, -1]                       # rows run from the plane of symmetry
        x_in = inter[np.all(np.isfinite(inter), axis=1), 0]
        rows = (ends[:, 0] > x_in.min()) & (ends[:, 0] < x_in.max())
        assert rows.sum() >= 3
        ends = ends[rows]
        assert np.abs(wing_height(wing, side, ends) - ends[:, 2]).max() <= 1e-9 * L


def _counted_cut(monkeypatch, x_of_f):
    """Replace the trial-line cut by a given x(f) (points (x, 0, 0)); returns the call count."""
    import juncture.intersect.stations as stations

    calls = []

    def cut(wing, body, side, f):
        calls.append(len(f))
        return np.stack([x_of_f(np.asarray(f)), 0 * f, 0 * f], axis=1)

    monkeypatch.setattr(stations, "_cut", cut)
    return stations._false_position, calls


def test_a_station_in_a_jump_of_the_cut_stops_early_and_is_nan(monkeypatch):
    """x(f) jumps by 5e-3 at f = 0.7 (the trial line's first crossing moves to another face):
    a station in the gap has no root; the search stops once the bracket's secant is a
    thousand times steeper than at the start (before: 40 rounds of cuts, closing in on the
    jump to the last digit), and the stations with a root beside it are found."""
    def x_of_f(f):
        return 40.0 * f + np.where(f > 0.7, 5e-3, 0.0)

    solve, calls = _counted_cut(monkeypatch, x_of_f)
    x0 = np.array([28.0025, 20.0, 36.0])
    got = solve(None, None, "upper", x0, np.zeros(3), np.ones(3), -x0, 40.005 - x0, 1e-11)
    assert np.isnan(got[0]).all()
    np.testing.assert_allclose(got[1:, 0], x0[1:], atol=1e-11)
    assert len(calls) <= 20


def test_a_steep_but_continuous_cut_is_still_solved(monkeypatch):
    """A cut whose x(f) is 15 times steeper near the root than across the bracket (a line
    meeting the body at a glancing angle) converges as before."""
    def x_of_f(f):
        return 10.0 * np.arctan(50.0 * (f - 0.4)) + 3.0 * f

    solve, _ = _counted_cut(monkeypatch, x_of_f)
    x0 = np.array([1.2 + 1e-3, 0.5])
    ga, gb = x_of_f(np.zeros(2)) - x0, x_of_f(np.ones(2)) - x0
    got = solve(None, None, "upper", x0, np.zeros(2), np.ones(2), ga, gb, 1e-11)
    np.testing.assert_allclose(got[:, 0], x0, atol=1e-11)


def _stepped(body, at, scale):
    """``body`` (a circular fuselage) with a joint at its station ``at``: the stations from
    there to the end of that segment repeat at ``scale`` times the radius (a step)."""
    from juncture.model import CircularBody

    x, r = np.asarray(body.x), np.asarray(body.radius)
    c = np.asarray(body.camber) if body.camber is not None else np.zeros_like(x)
    k = int(np.flatnonzero(x == at)[0])
    ends = np.cumsum(body.segments)
    seg = int(np.searchsorted(ends, k, side="right"))
    end = ends[seg]
    xs = np.concatenate([x[:k + 1], x[k:]])
    rs = np.concatenate([r[:k + 1], r[k:end] * scale, r[end:]])
    cs = np.concatenate([c[:k + 1], c[k:]])
    counts = list(body.segments)
    counts[seg:seg + 1] = [k + 1 - (ends[seg] - counts[seg]), end - k]
    return CircularBody(body.name, xs, rs, cs, body.origin, tuple(counts), body.mirrored,
                        body.axial)


@pytest.mark.parametrize("scale", [1.05, 0.95])
@pytest.mark.parametrize("side", ["upper", "lower"])
def test_a_station_at_a_step_ends_on_each_section(side, scale):
    """The transport's fuselage stepping out (or in) by 5 % of its radius at x = 140, under
    the wing root: the lofting lines' first crossings jump there (some meet the step's
    face), and the search over chord fractions alone left the joint's station without a
    point (NaN). The point a rounding ahead of the joint lies on the earlier section (the
    deck's radius), the point at the joint on the later one (its radius times the scale),
    both on the wing (the section point root-found on the model) and in their plane."""
    cfg = jc.read(TRANSPORT)
    wing, body = cfg["wing"], _stepped(cfg["body"], 140.0, scale)
    inter = intersect_body(wing, body, side)
    x = np.array([np.nextafter(140.0, -np.inf), 140.0])
    got = plane_points(wing, body, side, inter.points, x)
    assert np.all(np.isfinite(got))
    L = body.length
    assert np.abs(got[:, 0] - 140.0).max() <= 1e-12 * L
    centre_z = float(np.asarray(body.camber)[np.asarray(body.x) == 140.0][0])
    r = np.hypot(got[:, 1] - body.origin[1], got[:, 2] - body.origin[2] - centre_z)
    r_deck = float(np.asarray(cfg["body"].radius)[np.asarray(cfg["body"].x) == 140.0][0])
    np.testing.assert_allclose(r, [r_deck, scale * r_deck], atol=1e-9 * L)
    assert np.abs(wing_height(wing, side, got) - got[:, 2]).max() <= 1e-9 * L
