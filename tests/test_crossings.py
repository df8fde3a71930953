"""Two junctions with one body that overlap on it are refused by name (juncture.crossings).

The polygon test is checked on regions whose answer is known by construction (squares that
overlap, touch along an edge, nest, or lie apart); the refusal on a generated airplane whose
canted fin stands on the fuselage inside the thick wing root's junction, against an
independent test of its points (some of the fin's junction points lie between the wing's
upper and lower lines round the body's axis); and no refusal where the regions lie apart.
"""

import warnings

import numpy as np
import pytest

import juncture as jc
from juncture.crossings import _overlap, refuse_crossing_regions
from juncture.intersect.pairs import Pair, intersect_pair
from tests.support import DATA, EXAMPLE_DECK

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])


@pytest.mark.parametrize("shift, expected", [
    ((0.5, 0.5), True),        # corners inside each other
    ((0.5, -0.25), True),      # edges cross, one corner inside
    ((1.0, 0.0), False),       # side by side, one edge shared
    ((1.0 + 1e-3, 0.2), False),  # apart
    ((0.0, 1.0), False),       # one above the other, touching
])
def test_squares(shift, expected):
    assert _overlap(SQUARE, SQUARE + shift, 1e-9) is expected
    assert _overlap(SQUARE + shift, SQUARE, 1e-9) is expected


def test_a_region_inside_another_and_a_cross_without_corners_inside():
    small = 0.25 + 0.5 * SQUARE
    assert _overlap(SQUARE, small, 1e-9) and _overlap(small, SQUARE, 1e-9)
    bar = np.array([[-1.0, 0.4], [2.0, 0.4], [2.0, 0.6], [-1.0, 0.6]])  # no corner inside
    assert _overlap(SQUARE, bar, 1e-9) and _overlap(bar, SQUARE, 1e-9)


def _angle(body, p):
    c = body.center_at(p[:, 0])
    return np.arctan2(p[:, 2] - c[:, 1], p[:, 1] - c[:, 0])


def test_a_fin_standing_in_the_wing_roots_junction_is_refused_by_name():
    """tests/data/generated/refused/fin_root_inside_the_wing_root.inp: the fin's root runs
    from x 52.2 to 64.5 on the fuselage's top, where the thick root of the wing (continued
    to the body) already meets it; above the body the fin passes through the wing."""
    cfg = jc.read(DATA / "generated" / "refused" / "fin_root_inside_the_wing_root.inp")
    body = cfg["body"]
    up, lo = intersect_pair(cfg, Pair("wing", "body", "body"))
    fin = np.concatenate([r.points for r in intersect_pair(cfg, Pair("fin 1", "body",
                                                                        "body"))])
    fin = fin[(fin[:, 0] > up.points[0, 0]) & (fin[:, 0] < up.points[-1, 0])]
    a_up, a_lo = (np.interp(fin[:, 0], q.points[:, 0], _angle(body, q.points))
                  for q in (up, lo))
    a = _angle(body, fin)
    assert np.any((np.minimum(a_up, a_lo) < a) & (a < np.maximum(a_up, a_lo)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        with pytest.raises(jc.GeometryError) as err:
            jc.complete(cfg)
    msg = str(err.value)
    assert "\n" not in msg
    assert msg.startswith("fin 1: its junction with body")
    assert "overlaps that of wing" in msg and "move fin 1 clear of wing" in msg


def test_the_transports_junctions_lie_apart():
    """The transport's wing, fin and tails meet its fuselage side by side: nothing refused,
    and the same when the fin's lines are handed in as the tail's too (a region against
    itself overlaps)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(EXAMPLE_DECK))
    refuse_crossing_regions(geo.configuration, geo.intersections)
    fin = {k: v for k, v in geo.intersections.items() if k.startswith("fin 3/")}
    assert fin, sorted(geo.intersections)
    twice = dict(geo.intersections)
    twice.update({k.replace("fin 3/", "fin 9/"): v for k, v in fin.items()})
    with pytest.raises(jc.GeometryError, match="fin"):
        refuse_crossing_regions(geo.configuration, twice)


def test_a_fin_trailing_edge_on_a_tail_root_is_refused_and_the_oracle_agrees():
    """A generated airplane (tests/data/generated/README.md) whose twin fin's trailing edge
    ends on the tail's upper root line (24.56 deg round the fuselage, the line at 25.14 deg
    there between its points taken linearly, 24.556 deg along its 3-D chord): juncture
    refuses the pair by name, and the test oracle (tests.support.junctions_overlap), which
    took the chord only and found them 0.004 deg apart, now takes the line either way."""
    from tests.support import junctions_overlap

    cfg = jc.read(DATA / "generated" / "crossings" / "fin_trailing_edge_on_a_tail_root.inp")
    with pytest.raises(jc.GeometryError, match="tail 1: its junction with body .* fin 2"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            jc.complete(cfg)
    assert junctions_overlap(cfg, "tail 1", "fin 2", "body")
