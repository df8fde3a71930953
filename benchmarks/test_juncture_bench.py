"""Issue 3 benchmark: the wing-body intersection and complete(), beside OpenCASCADE.

The case is a 20-section x 30-station wing on a 60-station body (benchmarks/geometry.py).
OpenCASCADE gets B-spline faces fitted through dense samples of the same lofted surfaces and
computes their section with BRepAlgoAPI_Section. Accuracies go into extra_info:
- juncture: the largest distance of its intersection points from the body surface;
- OCC: the largest distance of its section points from the exact body surface, and the
  largest distance from juncture's points to OCC's section curve.

Run with ``make bench`` (``pytest benchmarks --benchmark-only``).
"""

import numpy as np
import pytest
from benchmarks.geometry import benchmark_configuration
from scipy.spatial import cKDTree

import juncture as jc
from juncture.intersect import intersect_body, intersect_body_both


@pytest.fixture(scope="module")
def cfg():
    return benchmark_configuration()


def test_intersection_one_surface(benchmark, cfg):
    res = benchmark(intersect_body, cfg["wing"], cfg["body"], "upper")
    benchmark.extra_info["max_residual"] = float(np.nanmax(res.residual))


def test_intersection_both_surfaces(benchmark, cfg):
    up, lo = benchmark(intersect_body_both, cfg["wing"], cfg["body"])
    body = cfg["body"]
    pts = np.concatenate([up.points, lo.points])
    benchmark.extra_info["max_distance_from_body"] = float(
        np.abs(body.radial_error(pts)).max())


@pytest.mark.parametrize("fillet, keep", [(None, False), ("cubic", False), ("cubic", True),
                                          ("circular", True)])
def test_complete(benchmark, cfg, fillet, keep):
    geo = benchmark(jc.complete, cfg, fillet, keep)
    benchmark.extra_info["worst_area_residual"] = float(geo.stations["residual"].max())


def _dense_wing_upper(wing, n_chord=40):
    """The wing's upper surface at every section, 40 cosine-spaced chord points."""
    f = 0.5 * (1 - np.cos(np.linspace(0, np.pi, n_chord)))
    s = wing.span_stations
    return wing.point(s[:, None], f[None, :], "upper")


def _dense_body(body, x0, x1, n_x=120, n_theta=49):
    """The body's y >= 0 half over the wing region [x0, x1] (no nose singularity for OCC)."""
    th = np.linspace(-np.pi / 2, np.pi / 2, n_theta)
    x = np.linspace(x0, x1, n_x)
    return body.point(x[:, None], th[None, :])


def test_occ_section(benchmark, cfg):
    pytest.importorskip("OCP")
    from juncture.io.cad import network_face, section_points

    wing, body = cfg["wing"], cfg["body"]
    x0 = wing.le[:, 0].min() - 15.0
    x1 = (wing.le[:, 0] + wing.chord).max() + 15.0
    wf = network_face(_dense_wing_upper(wing), "wing upper")
    bf = network_face(_dense_body(body, x0, x1), "body")
    occ = benchmark.pedantic(section_points, (wf, bf, 4000), rounds=1, iterations=1)
    ours = intersect_body(wing, body, "upper").points
    d = cKDTree(occ).query(ours)[0]
    benchmark.extra_info["occ_points"] = int(len(occ))
    benchmark.extra_info["occ_max_distance_from_body"] = float(
        np.abs(body.radial_error(occ)).max())
    benchmark.extra_info["juncture_to_occ_curve_median"] = float(np.median(d))
    benchmark.extra_info["juncture_to_occ_curve_max"] = float(d.max())


@pytest.fixture(scope="module")
def transport():
    import warnings

    from juncture.cli import bundled_example

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(bundled_example())


@pytest.mark.parametrize("fillet, keep", [(None, False), ("cubic", True)])
def test_complete_whole_transport(benchmark, transport, fillet, keep):
    """Issue 4: every intersection of the bundled transport (7 touching pairs)."""
    geo = benchmark(jc.complete, transport, fillet, keep)
    benchmark.extra_info["intersections"] = len(geo.intersections)
