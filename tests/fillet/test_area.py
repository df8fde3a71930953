"""Added fillet area (generalised TM-4406 eqs 11-14) and the fixed-area body re-design."""

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from matplotlib.path import Path

import juncture as jc
from juncture.fillet import (
    cubic_fillet,
    fillet_added_area,
    keep_area,
    polygon_disk_area,
    wedge_area,
)
from juncture.intersect import intersect_body, intersect_body_both
from tests.fillet.fillet_checks import dense, wedge_reference
from tests.support import wing_body


def raster_area(inside, lo, hi, n=1500):
    """Area of {p : inside(p)} in the box [lo, hi] by counting cell centres (independent)."""
    g = [np.linspace(lo[i], hi[i], n, endpoint=False) + (hi[i] - lo[i]) / (2 * n)
         for i in (0, 1)]
    yy, zz = np.meshgrid(*g, indexing="ij")
    pts = np.stack([yy.ravel(), zz.ravel()], 1)
    return inside(pts).sum() * (hi[0] - lo[0]) * (hi[1] - lo[1]) / n ** 2


@settings(max_examples=25, deadline=None)
@given(cy=st.floats(-1.0, 1.0), cz=st.floats(-1.0, 1.0), r=st.floats(0.3, 1.8),
       seed=st.integers(0, 10_000))
def test_polygon_disk_area_matches_a_raster_count(cy, cz, r, seed):
    rng = np.random.default_rng(seed)
    k = 9
    # Jittered equal angles: every gap < 180 deg, so the polygon is simple and star-shaped.
    ang = (np.arange(k) + rng.uniform(0.0, 0.8, k)) * 2 * np.pi / k
    rad = rng.uniform(0.5, 1.5, k)
    poly = np.stack([rad * np.cos(ang), rad * np.sin(ang)], 1)  # star-shaped about 0
    exact = polygon_disk_area(poly[None], np.array([[cy, cz]]), np.array([r]))[0]
    path = Path(poly)

    def inside(p):
        return path.contains_points(p) & (np.hypot(p[:, 0] - cy, p[:, 1] - cz) < r)

    ref = raster_area(inside, (-1.6, -1.6), (1.6, 1.6))
    assert abs(abs(exact) - ref) < 4e-3 * 3.2 * 3.2 / 1.5 + 1e-3


def test_added_area_of_one_station_by_raster():
    # Eqs 11-14 per fillet: the region between the fillet line, the wing from its end back to
    # the intersection and the body arc, each in the plane of its own intersection point.
    cfg = wing_body(z_root=0.4, root_y=0.5)
    wing, body = cfg["wing"], cfg["body"]
    geo = jc.complete(cfg, "cubic", blend_length=1e-9, theta_u_deg=30, end_value=0.8)
    iu, il = intersect_body(wing, body, "upper"), intersect_body(wing, body, "lower")
    j = 5
    total = 0.0
    for f, inter in ((geo.fillets["fillet upper"], iu), (geo.fillets["fillet lower"], il)):
        curve = dense(f[j:j + 1], 201)[0, :, 1:]
        corner = inter.points[j]
        ctr, r = body.center_at(corner[0]), body.radius_at(corner[0])
        region = Path(np.vstack([curve, corner[1:]]))

        def inside(p, region=region, ctr=ctr, r=r):
            out_disk = np.hypot(p[:, 0] - ctr[0], p[:, 1] - ctr[1]) > r
            return region.contains_points(p) & out_disk

        lo, hi = curve.min(0) - 0.05, curve.max(0) + 0.05
        total += raster_area(inside, np.minimum(lo, corner[1:]), np.maximum(hi, corner[1:]),
                             n=1200)
    # The stations hold both sides' fillets (the wing has a mirror image).
    assert abs(geo.stations["area_fillet"][j] / 2 - total) < 2e-3 * total + 1e-4


def test_added_area_is_the_curves_not_its_points():
    # The exact area of the cubic: the same with 9 points per line as with 33 (the polygon
    # through 9 points over-stated it by about 1.5 %), and equal to a 4001-point polygon.
    cfg = wing_body(z_root=-0.6, dihedral_deg=4.0, root_y=0.8)
    wing, body = cfg["wing"], cfg["body"]
    iu, il = intersect_body(wing, body, "upper"), intersect_body(wing, body, "lower")
    areas = []
    for n in (9, 33):
        fu = cubic_fillet(wing, body, iu, n_points=n, end="dy", end_value=0.8)
        fl = cubic_fillet(wing, body, il, n_points=n, end="dy", end_value=0.8)
        areas.append(fillet_added_area(body, fu, fl, iu, il)[1])
    np.testing.assert_allclose(areas[0], areas[1], rtol=1e-12, atol=1e-15)
    ref = 0.0
    for f, inter in ((fu, iu), (fl, il)):
        ctr, r = body.section_at(inter.points[:, 0])
        ref = ref + wedge_reference(f.points, inter.points, ctr, r)
    live = ref > 1e-9
    np.testing.assert_allclose(areas[1][live], ref[live], rtol=1e-6)
    exact = cubic_fillet(wing, body, iu, end="dy", end_value=0.8)
    nine = replace(exact, control=None)  # measured as the polygon of its points
    a9, a = wedge_area(body, nine, iu.points), wedge_area(body, exact, iu.points)
    assert np.all(a9[a > 1e-9] > 1.005 * a[a > 1e-9])  # the 9-point polygon over-states


def test_no_fillet_adds_no_area():
    cfg = wing_body()
    wing, body = cfg["wing"], cfg["body"]
    from juncture.completion import sharp_fillet

    iu, il = intersect_body(wing, body, "upper"), intersect_body(wing, body, "lower")
    x, a = fillet_added_area(body, sharp_fillet(iu), sharp_fillet(il), iu, il)
    assert np.abs(a).max() < 1e-12


@settings(max_examples=12, deadline=None)
@given(z=st.floats(-1.2, 1.2), dihedral=st.floats(-4.0, 6.0), root_y=st.floats(-0.5, 3.0),
       kind=st.sampled_from(["cubic", "circular"]))
# Found by a random run: the lower fillet's tangents were taken an eighth of the way at a
# time towards the paper's, and the step flipped as the body shrank by 1e-7 (the added area
# by 1e-3): keep_area did not converge (ConvergenceError, worst residual 2.8e-6).
@example(z=0.7667854301416224, dihedral=0.767578125, root_y=1.5827523167188113, kind="cubic")
def test_keep_area_restores_the_original_area_at_every_station(z, dihedral, root_y, kind):
    cfg = wing_body(z_root=z, dihedral_deg=dihedral, root_y=root_y)
    geo = jc.complete(cfg, kind, keep_area=True)
    st_ = geo.stations
    body0 = cfg["body"]
    # Independent of the solver's bookkeeping: the original area from the original body.
    a0 = np.pi * body0.radius_at(st_["x"]) ** 2
    total = np.pi * st_["radius_new"] ** 2 + st_["area_fillet"]
    np.testing.assert_allclose(total, a0, rtol=1e-8)
    # The fillets only add area, and the body only shrinks: at the stations and everywhere
    # between them (its cubic pieces keep the sign of the reduction at their ends).
    assert np.all(st_["area_fillet"] >= 0)
    assert np.all(st_["radius_new"] <= st_["radius_original"] + 1e-12)
    xs = np.linspace(0.0, body0.length, 6001) + body0.x_global[0]
    assert np.all(geo.configuration["body"].radius_at(xs) <= body0.radius_at(xs) + 1e-12)
    assert len({len(v) for v in st_.values()}) == 1


def _reduction_case():
    from benchmarks.geometry import benchmark_configuration

    body = benchmark_configuration()["body"]
    rng = np.random.default_rng(7)
    x = np.sort(rng.uniform(110.0, 240.0, 14))
    return body, x, rng.uniform(0.05, 1.5, 14)


def test_reduction_jacobian_matches_finite_differences():
    from juncture.fillet import BodyReduction

    body, x, a = _reduction_case()

    def covered(xq):
        return 1.5 + 0.01 * np.asarray(xq)

    red = BodyReduction(body, x, exposure=covered)
    new = red.body(a)
    xq = np.linspace(90.0, 260.0, 61)
    jac = red.jacobian(xq)
    h = 1e-6
    for i in range(a.size):
        e = a.copy()
        e[i] += h
        other = BodyReduction(body, x, exposure=covered).body(e)
        fd = (new.radius_at(xq) - other.radius_at(xq)) / h
        np.testing.assert_allclose(jac[:, i], fd, atol=1e-7)


def test_reduced_body_keeps_the_original_where_nothing_is_removed():
    from juncture.fillet import reduced_body

    body, x, a = _reduction_case()
    new = reduced_body(body, x, a)
    # Exactly the original cubic outside the re-designed range, and the exact area removed
    # at each station (the original body is the reference, not the re-design's bookkeeping).
    xo = np.concatenate([np.linspace(0.0, 100.0, 40), np.linspace(250.0, 300.0, 20)])
    np.testing.assert_allclose(new.radius_at(xo), body.radius_at(xo), atol=1e-12)
    np.testing.assert_allclose(new.center_at(xo), body.center_at(xo), atol=1e-12)
    np.testing.assert_allclose(np.pi * (body.radius_at(x) ** 2 - new.radius_at(x) ** 2), a,
                               rtol=1e-12)


def test_keep_area_converges_superlinearly_on_the_benchmark_case():
    # A regression guard on the solver, not on time: substitution alone needs 7 bodies here
    # (contraction ~0.07 per step), the structured Newton step 5.
    from benchmarks.geometry import benchmark_configuration

    geo = jc.complete(benchmark_configuration(), "cubic", keep_area=True)
    line = next(s for s in geo.log if s.startswith("keep_area:"))
    assert int(line.split()[1]) <= 5
    assert geo.stations["residual"].max() <= 1e-9


def _cubic_maker(wing):
    """make_fillets for keep_area: cubic fillets with complete()'s defaults, blended over
    the original body's region."""
    def make(body, previous=None, warm=False):
        iu, il = intersect_body_both(wing, body)
        ranges = (None, None) if previous is None else (previous[2].blend_range,
                                                        previous[3].blend_range)
        kw = dict(end="dy", end_value=0.75)
        return (iu, il, cubic_fillet(wing, body, iu, blend_range=ranges[0], **kw),
                cubic_fillet(wing, body, il, upper_reference=iu, blend_range=ranges[1], **kw))
    return make


def test_keep_area_compensates_the_fillet_alone_as_the_paper_does():
    # TM-4406 eqs 11-14: fuselage area + fillet area = original fuselage area, at every
    # station; today's default also gives up the wing root the shrinking body uncovers.
    cfg = wing_body(z_root=0.3, dihedral_deg=3.0)
    body0 = cfg["body"]
    make = _cubic_maker(cfg["wing"])
    paper = keep_area(body0, make, compensate="fillet")
    a0 = np.pi * body0.radius_at(paper.x) ** 2
    np.testing.assert_allclose(np.pi * paper.radius_new ** 2 + paper.area_fillet, a0,
                               rtol=1e-9)
    # Independently of the solver's bookkeeping: the fillets measured on the final body.
    x, only = fillet_added_area(paper.body, *paper.fillets[2:], *paper.fillets[:2])
    np.testing.assert_allclose(2 * only, paper.area_fillet, rtol=1e-12)
    np.testing.assert_allclose(np.pi * paper.body.radius_at(x) ** 2 + 2 * only,
                               np.pi * body0.radius_at(x) ** 2, rtol=1e-9)
    section = keep_area(body0, make)
    inner = paper.area_fillet > 1e-9
    # Giving up the uncovered root too takes more from the body.
    assert np.all(section.radius_new[inner] < paper.radius_new[inner])
    with pytest.raises(jc.GeometryError, match="compensate must be"):
        keep_area(body0, make, compensate="root")


def test_reduced_body_never_grows_next_to_a_station_that_gives_up_nothing():
    # Issue 11: the cubic between a station that gives up area and the next that gives up
    # none swung past the original radius (aft of the last fillet station).
    from juncture.fillet import reduced_body

    body, x, a = _reduction_case()
    a = a.copy()
    a[[0, 1, -2, -1]] = 0.0
    a[2:-2] *= 3.0
    new = reduced_body(body, x, a)
    xs = np.linspace(body.x_global[0], body.x_global[-1], 20001)
    assert np.all(new.radius_at(xs) <= body.radius_at(xs) + 1e-12)
    np.testing.assert_allclose(np.pi * (body.radius_at(x) ** 2 - new.radius_at(x) ** 2), a,
                               rtol=1e-12, atol=1e-12)


def test_reduction_jacobian_matches_finite_differences_where_the_limiter_acts():
    from juncture.fillet import BodyReduction

    body, x, a = _reduction_case()
    a = a.copy()
    a[[0, -1]] = 0.0
    red = BodyReduction(body, x)
    new = red.body(a)
    assert red._limit[0].any()  # the slope limit acts next to the zero stations
    xq = np.linspace(100.0, 250.0, 73)
    jac = red.jacobian(xq)
    h = 1e-7
    for i in range(1, a.size - 1):
        e = a.copy()
        e[i] += h
        fd = (new.radius_at(xq) - BodyReduction(body, x).body(e).radius_at(xq)) / h
        np.testing.assert_allclose(jac[:, i], fd, atol=1e-6)


def test_stations_in_a_gap_between_segments_are_re_designed_too():
    from juncture.fillet import reduced_body
    from juncture.model import CircularBody

    # Two segments with a gap between x = 40 and 50 (a straight bridge, radius 4 -> 3).
    body = CircularBody("body", np.array([0, 10, 25, 40, 50, 70, 90, 100.0]),
                        np.array([0, 3.2, 4, 4, 3, 3, 2, 0.0]), segments=(4, 4))
    x = np.array([30.0, 38.0, 43.0, 47.0, 55.0, 62.0])
    a = np.array([0.3, 0.5, 0.6, 0.55, 0.4, 0.2])
    new = reduced_body(body, x, a)
    np.testing.assert_allclose(np.pi * (body.radius_at(x) ** 2 - new.radius_at(x) ** 2), a,
                               rtol=1e-12)
    xs = np.linspace(0.0, 100.0, 4001)
    assert np.all(new.radius_at(xs) <= body.radius_at(xs) + 1e-12)


def test_the_compensation_option_is_checked():
    from juncture.options import check_combination

    assert jc.CompleteOptions(compensation="fillet").compensation == "fillet"
    with pytest.raises(jc.OptionError, match="compensation = 'root': expected one of"):
        jc.CompleteOptions(compensation="root")
    with pytest.raises(jc.OptionError, match="no value unless keep_area=True"):
        check_combination("cubic", False, jc.CompleteOptions(compensation="fillet"))
