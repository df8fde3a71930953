"""The cell-counting union oracle (tests/union_oracle.py) against analytic areas and
juncture's own normal areas where no two wing-like components overlap."""

import numpy as np
import pytest

import juncture as jc
from juncture.analysis.areas import normal_area_distribution
from tests.support import EXAMPLE_DECK
from tests.union_oracle import union_area


@pytest.fixture(scope="module")
def transport():
    return jc.complete(jc.read(EXAMPLE_DECK)).configuration


def _only(cfg, *names):
    return cfg.replace(components={k: v for k, v in cfg.components.items() if k in names})


def test_a_circle_is_pi_r_squared(transport):
    body = _only(transport, "body")
    _, r = transport.components["body"].section_at(np.array([72.41]))
    assert union_area(body, 72.41, cells=3000) == pytest.approx(np.pi * r[0] ** 2, rel=1e-3)


def test_a_wing_cut_is_its_thickness_integrated_along_the_span(transport):
    """Both halves of the wing at x = 217.24: the thickness at each span station (upper minus
    lower surface at the chord fraction of x) integrated by the trapezoidal rule."""
    wing = transport.components["wing"]
    x = 217.24
    s = np.linspace(wing.span_stations[0], wing.span_stations[-1], 20001)
    le = wing.point(s, np.zeros_like(s), "upper")[:, 0]
    te = wing.point(s, np.ones_like(s), "upper")[:, 0]
    f = (x - le) / (te - le)
    ok = (f >= 0) & (f <= 1)
    f = np.clip(f, 0, 1)
    t = np.where(ok, wing.point(s, f, "upper")[:, 2] - wing.point(s, f, "lower")[:, 2], 0.0)
    expected = 2.0 * np.trapezoid(t, s)
    assert union_area(_only(transport, "wing"), x, cells=3000) == pytest.approx(expected,
                                                                                rel=2e-3)


def test_overlaps_count_once(transport):
    """A fin standing on the wing: the union is the sum less the overlap, which is real."""
    x = 217.24
    wing, fin = (union_area(_only(transport, n), x) for n in ("wing", "fin 1"))
    both = union_area(_only(transport, "wing", "fin 1"), x)
    assert max(wing, fin) < both < wing + fin - 1.0


@pytest.mark.parametrize("x", [72.41, 258.62, 289.65])
def test_where_no_wing_like_components_overlap_it_agrees_with_normal_areas(transport, x):
    model = normal_area_distribution(transport, x=np.array([x]), flow_through=False)["total"]
    assert union_area(transport, x, cells=3000) == pytest.approx(model[0], rel=1.5e-3)
