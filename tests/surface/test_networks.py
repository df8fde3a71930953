"""The body stations and point counts the output networks are made with
(juncture.surface.networks.refined_stations, half_points)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import juncture as jc
from juncture.model import ArbitraryBody, CircularBody
from juncture.surface.networks import HALVINGS, SAG, half_points, refined_stations
from tests.support import DATA


def _standoff(body, rows, theta, samples=64):
    """(intervals,) the largest distance, at ``samples`` stations inside each interval
    between consecutive ``rows``, from the body to the straight lines joining the two rows'
    points at the same angle (evaluated here from the radius and camber interpolants alone,
    not through ``body.point``)."""
    a, b = rows[:-1][np.diff(rows) > 0], rows[1:][np.diff(rows) > 0]
    t = (np.arange(1, samples) / samples)[None, :]
    x = a[:, None] + t * (b - a)[:, None]

    def ring(xq):
        r = body.radius_at(xq)[..., None]
        c = body.center_at(xq)
        return np.stack([c[..., 0:1] + r * np.cos(theta), c[..., 1:2] + r * np.sin(theta)], -1)

    h = 1e-9 * (b - a)
    ends_a, ends_b = ring((a + h)[:, None]), ring((b - h)[:, None])
    chord = ends_a + t[..., None, None] * (ends_b - ends_a)
    return np.linalg.norm(ring(x) - chord, axis=-1).max(axis=(1, 2)), b - a


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(0.5, 6.0), min_size=3, max_size=7),
       st.floats(20.0, 200.0), st.floats(-1.0, 1.0))
def test_a_body_stands_off_its_network_rows_by_at_most_the_sag(radii, length, droop):
    """Hypothesis: a body pointed at both ends with a few stations, its radius and camber
    interpolated by PCHIP. Between the rows refined_stations gives, sampled 64 times per
    interval (not at the quarters it measures), the body stands off the straight lines joining
    the rows by at most SAG times its largest radius, with a quarter's margin for what its
    three samples miss; only intervals halved HALVINGS times (a pointed end, whose radius
    grows like the square root of the distance) may keep more. Every input station stays."""
    r = np.concatenate([[0.0], radii, [0.0]])
    x = np.linspace(0.0, length, r.size)
    camber = droop * r.max() * (x / length) ** 2
    body = CircularBody("body", x, r, camber=camber)
    rows = refined_stations(body)
    assert np.isin(x, rows).all() and np.all(np.diff(rows) >= 0)
    off, width = _standoff(body, rows, np.linspace(-np.pi, np.pi, 33)[:, None].T)
    start = rows[:-1][np.diff(rows) > 0]
    given = np.diff(x)[np.searchsorted(x, start, side="right") - 1]
    finest = width <= given / 2 ** HALVINGS * (1 + 1e-9)
    assert np.all((off <= 1.25 * SAG * r.max()) | finest)


def test_a_long_tail_cone_gets_rows_and_a_straight_body_none():
    """A 64-unit tail cone whose area falls from 288 to 0 along a PCHIP curve stands off the
    straight line between its two stations by about 2 units (a sixth of its largest
    radius) at mid-length; rows are added until it stands off by SAG. A cylinder and an
    arbitrary-section body (straight lines along x) get none."""
    x = np.array([0.0, 40.0, 104.0])
    r = np.sqrt(np.array([288.0, 288.0, 0.0]) / np.pi)
    cone = CircularBody("body", x, r)
    mid = cone.radius_at(72.0)[()] - 0.5 * r[1]
    assert mid > 0.15 * r.max()
    rows = refined_stations(cone)
    assert rows.size > 8 and np.all(rows[rows <= 40.0] == [0.0, 40.0])
    assert refined_stations(CircularBody("tube", x, np.full(3, 2.0))).tolist() == x.tolist()
    square = [[0.0, -1.0], [1.0, -1.0], [1.0, 1.0], [0.0, 1.0]]
    box = ArbitraryBody("box", x, [square, [[0.0, -2.0], [2.0, 1.0], [0.0, 2.0]], square])
    assert refined_stations(box).tolist() == x.tolist()


def test_a_step_at_a_joint_adds_no_rows():
    """Two segments that meet at a repeated station with different radii (a step): each
    interval is measured within its own segment, so the step adds nothing."""
    body = CircularBody("body", [0.0, 10.0, 10.0, 20.0], [1.0, 1.0, 2.0, 2.0],
                        segments=(2, 2), axial="linear")
    assert refined_stations(body).tolist() == [0.0, 10.0, 10.0, 20.0]


def test_the_networks_take_the_largest_count_of_points_per_section():
    """A fuselage whose segments give 5, 10 and 11 points per half-section is written with 11
    all along (the first segment's 5 cut the others' circles by 45 deg chords)."""
    body = CircularBody("body", [0.0, 1.0, 1.0, 2.0, 2.0, 3.0], [0.0, 1.0, 1.0, 1.0, 1.0, 0.0],
                        segments=(2, 2, 2), points_per_section=(5, 10, 11))
    assert half_points(body) == 11
    assert half_points(CircularBody("body", [0.0, 1.0], [1.0, 1.0])) == 19


@pytest.mark.slow  # one airplane meshed whole (> 4 s): make test-all
@pytest.mark.parametrize("name", ["high_wing_tail_cone_of_few_stations.inp"])
def test_a_long_tail_cone_is_meshed_to_its_volume(name):
    """A generated airplane (tests/data/generated/README.md) whose fuselage tapers from
    its largest radius to a point over one 64 ft interval, with a fin on it. Its networks
    joined the two stations by straight lines, 2 ft inside the body at mid-length: the mesh
    held 1.45 % less than the union of the components counted by cells, the fin's root a
    zig-zag down to those lines. With rows added along the cone, within 0.5 %."""
    from tests.union_oracle import union_volume

    geo = jc.complete(jc.read(DATA / "generated" / "assembly" / name))
    surface = jc.mesh(geo)
    cells = union_volume(geo.configuration, n=121, cells=1500)
    assert abs(surface.volume() / cells - 1.0) < 5e-3


@pytest.mark.slow  # a held-out airplane meshed whole (> 7 s): make test-all
def test_no_row_is_added_in_the_wing_junction_range():
    """A generated airplane (tests/data/generated/README.md): an arbitrary-section fuselage
    re-designed at fixed area (cubic fillet, keep_area) stands off the straight lines
    between its input stations, so rows are added; one fell between the first points of
    the upper and lower fillet start lines, and the blocks at the wing root's leading edge
    were left open (14 open edges). Rows are added outside the junction's x range only
    (there the fillet lines give the rows), and the surface closes."""
    from juncture.surface.check import check_mesh

    deck = DATA / "generated" / "assembly" / "arbitrary_body_keep_area_rows_at_the_wing_root.inp"
    cfg = jc.read(deck)
    geo = jc.complete(cfg, fillet="cubic", keep_area=True)
    starts = np.concatenate([geo.fillets["fillet upper"][:, 0, 0],
                             geo.fillets["fillet lower"][:, 0, 0]])
    rows = np.unique(np.asarray(geo.networks["body upper"])[:, 0, 0])
    added = rows[~np.isin(rows, cfg["body"].x_global) & ~np.isin(rows, starts)]
    assert added.size and not np.any((added > starts.min()) & (added < starts.max()))
    surface = jc.mesh(geo)
    assert check_mesh(surface.vertices, surface.triangles).ok


def test_a_blunt_trailing_edge_cut_by_the_body_is_closed_by_the_aft_block():
    """A wing whose trailing edge is thick and cambered at the root, cut by a cylinder (held-out
    seed 2525 draw 3): its upper and lower trailing edges meet the body at two points apart in
    x and z. The body's aft block carries both in its first section, so the blunt end is closed
    at the root by an edge of the body. Its sections left the upper point out, and the cap
    closing the blunt end ran up the body to the section's next point (there a 5 ft sliver,
    meshed into triangles of 0.3 deg; here up to z = 2.1, 0.14 deg). Oracles: the exact
    intersection points, the deck's planform (no cap vertex off the wing's trailing edge or
    tip) and the corner angles."""
    import dataclasses

    from juncture.model import WingLike
    from juncture.surface.quality import triangle_angles
    from tests.support import wing_body

    cfg = wing_body(camber=2.0)
    w, body = cfg["wing"], cfg["body"]
    body = dataclasses.replace(body, points_per_section=(5,))   # a coarse body, as the deck's
    up, lo = np.array(w.upper, float), np.array(w.lower, float)
    up[:, -1], lo[:, -1] = 0.4, 0.2          # a blunt trailing edge, 0.6 % of the chord
    w = WingLike("wing", "wing", w.le, w.chord, w.x_over_c, up, lo, w.camber)
    geo = jc.complete(cfg.with_component(w).with_component(body))
    p_up = np.asarray(geo.intersections["wing/body upper"])[-1]
    p_lo = np.asarray(geo.intersections["wing/body lower"])[-1]
    assert np.linalg.norm(p_up - p_lo) > 0.1
    aft = np.asarray(geo.networks["body aft"]).reshape(-1, 3)
    assert (aft == p_up).all(axis=1).any() and (aft == p_lo).all(axis=1).any()

    surface = jc.mesh(geo)
    caps = [k for k, s in enumerate(surface.surfaces) if s.endswith(" cap")]
    capped = surface.vertices[np.unique(surface.triangles[np.isin(surface.surface, caps)])]
    te = w.le[:, 0] + w.chord                                  # trailing edge x
    y_sec = w.le[:, 1]
    x_te = np.interp(np.abs(capped[:, 1]), y_sec, te)
    tip = np.isclose(np.abs(capped[:, 1]), y_sec[-1], atol=1e-9)
    band = (-(lo[:, -1] * w.chord).max() / 100 - 1e-3, (up[:, -1] * w.chord).max() / 100 + 1e-3)
    off = (np.abs(capped[:, 0] - x_te) > 0.05) | (capped[:, 2] < band[0]) | (capped[:, 2] > band[1])
    assert not np.any(off & ~tip), "a cap runs off the wing's trailing edge"
    assert triangle_angles(surface.vertices, surface.triangles).min() >= 5.0


OCTAGON = DATA / "generated" / "assembly" / \
    "arbitrary_body_four_blocks_octagon_ahead_of_the_wing.inp"


def test_the_mesh_of_an_arbitrary_fuselage_keeps_its_polygon(monkeypatch):
    """A held-out airplane's arbitrary fuselage, a half-octagon of nine points, in the
    four-block layout (tests/data/generated/README.md): the rows ahead of the wing hold the
    section's corners (juncture.surface.networks.arc_points; at equal steps of the surface
    parameter they cut them), and every corner the deck gives at its stations there is a
    mesh vertex, in both halves. Where the fuselage keeps one section (x 26.6 to 66.5, ahead of
    the wing) the mesh's section is the deck's polygon: its area equals the shoelace area
    of the deck's points to 1e-7 (no new point is put back on an arbitrary section, and the
    re-triangulation keeps the corner lines as edges, juncture.surface.creases).
    Counterfactual: without the corner lines kept, triangles across them cut the corners
    (more than 0.1 % of the section)."""
    import warnings

    import juncture.surface.patch_roles as patch_roles
    from tests.support import section_area

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(OCTAGON))
        body = geo.configuration["body"]
        k = int(np.flatnonzero(body.x == 45.273)[0])
        y, z = body.sections[k].T
        polygon = abs(np.sum(y[:-1] * z[1:] - y[1:] * z[:-1]))         # both halves
        x = np.array([30.0, 40.0, 50.0, 60.0])

        def short(surface):
            return np.array([1.0 - section_area(surface.vertices, surface.triangles, xi)
                             / polygon for xi in x])

        surface = jc.mesh(geo)
        assert np.abs(short(surface)).max() < 1e-7
        for station in (15.928, 26.642, 45.273):        # the corners are mesh vertices
            half = body.sections[int(np.flatnonzero(body.x == station)[0])]
            d = np.diff(half, axis=0)
            cos = np.einsum("ij,ij->i", d[:-1], d[1:]) / (
                np.linalg.norm(d[:-1], axis=1) * np.linalg.norm(d[1:], axis=1))
            corner = half[1:-1][cos < np.cos(np.radians(1.0))]
            both = np.concatenate([corner, corner * [-1.0, 1.0]])
            on = surface.vertices[surface.vertices[:, 0] == station][:, 1:]
            assert len(corner) == 7
            assert np.linalg.norm(both[:, None] - on[None], axis=2).min(axis=1).max() < 1e-9
        monkeypatch.setattr(patch_roles, "mark_creases", lambda charted, lines: None)
        assert short(jc.mesh(geo)).max() > 1e-3
