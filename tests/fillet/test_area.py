"""Added fillet area (generalised TM-4406 eqs 11-14) and the fixed-area body re-design."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.path import Path

import juncture as jc
from juncture.fillet import fillet_added_area, polygon_disk_area
from juncture.intersect import intersect_body
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
    cfg = wing_body(z_root=0.4, root_y=0.5)
    wing, body = cfg["wing"], cfg["body"]
    geo = jc.complete(cfg, "cubic", blend_length=1e-9, theta_u_deg=30, end_value=0.8)
    fu, fl = geo.fillets["fillet upper"], geo.fillets["fillet lower"]
    iu, il = intersect_body(wing, body, "upper"), intersect_body(wing, body, "lower")
    j = 5
    x = fu[j, 0, 0]
    ctr = body.center_at(x)
    r = body.radius_at(x)
    region = Path(np.concatenate([fu[j, :, 1:], fl[j, ::-1, 1:]]))
    wing_quad = Path(np.array([iu.points[j, 1:], fu[j, -1, 1:], fl[j, -1, 1:],
                               il.points[j, 1:]]))

    def inside(p):
        out_disk = np.hypot(p[:, 0] - ctr[0], p[:, 1] - ctr[1]) > r
        return region.contains_points(p) & out_disk & ~wing_quad.contains_points(p)

    pts = np.concatenate([fu[j, :, 1:], fl[j, :, 1:]])
    ref = raster_area(inside, pts.min(0) - 0.05, pts.max(0) + 0.05, n=2000)
    # The stations hold both sides' fillets (the wing has a mirror image).
    assert abs(geo.stations["area_fillet"][j] / 2 - ref) < 2e-3 * ref + 1e-4


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
def test_keep_area_restores_the_original_area_at_every_station(z, dihedral, root_y, kind):
    cfg = wing_body(z_root=z, dihedral_deg=dihedral, root_y=root_y)
    geo = jc.complete(cfg, kind, keep_area=True)
    st_ = geo.stations
    body0 = cfg["body"]
    # Independent of the solver's bookkeeping: the original area from the original body.
    a0 = np.pi * body0.radius_at(st_["x"]) ** 2
    total = np.pi * st_["radius_new"] ** 2 + st_["area_fillet"]
    np.testing.assert_allclose(total, a0, rtol=1e-8)
    # The body shrinks where the fillet adds area (a dipping cubic can take some away).
    adds = st_["area_fillet"] >= 0
    assert np.all(st_["radius_new"][adds] <= st_["radius_original"][adds] + 1e-12)
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
