"""The fuselage section as the fillets see it (:mod:`juncture.fillet.section`).

On a polyline section (the deck's J2 = +1 fuselage) a fillet leaves its start B along the
piece B lies on; near a vertex that direction turns towards the next piece's, so that it is
a continuous function of B and never points into the section. Checked against the
section's own points (no juncture geometry), and on a generated airplane whose area
compensation did not converge while it jumped.
"""

import warnings

import numpy as np

import juncture as jc
from juncture.fillet.section import section_frame
from juncture.model import ArbitraryBody
from tests.support import DATA

# A half-octagon (corners every 45 degrees) and a coarser, unsymmetric, partly concave
# section: turns of 45 degrees and more, where a piece's own direction jumps.
OCTAGON = [[0.0, -1.0], [0.7071, -0.7071], [1.0, 0.0], [0.7071, 0.7071], [0.0, 1.0]]
DENTED = [[0.0, -1.2], [0.9, -0.9], [1.1, -0.1], [0.8, 0.2], [1.0, 0.6], [0.0, 1.0]]


def _frame(section):
    return section_frame(ArbitraryBody("box", [0.0, 10.0], [section, section]))


def _oracle(section, q):
    """Unit direction (up the section) and outward normal of the piece through q (2,)."""
    sec = np.asarray(section, float)
    a, d = sec[:-1], np.diff(sec, axis=0)
    t = np.clip(((q - a) * d).sum(1) / (d * d).sum(1), 0.0, 1.0)
    i = int(np.argmin(np.linalg.norm(q - a - t[:, None] * d, axis=1)))
    u = d[i] / np.linalg.norm(d[i])
    return u, np.array([u[1], -u[0]])


def test_the_start_direction_is_continuous_and_never_points_into_the_section():
    for section in (OCTAGON, DENTED):
        frame = _frame(section)
        s = np.linspace(0.02, 0.98, 20001)
        x = np.full(s.size, 5.0)
        for sign in (1.0, -1.0):
            t = frame.tangent(x, s, np.full(s.size, sign))[:, 1:]
            assert np.allclose(np.linalg.norm(t, axis=1), 1.0)
            # continuous: neighbouring starts 5e-5 of the section apart turn by far less
            # than the 45 degrees and more that a piece's own direction jumps by
            step = np.degrees(np.arccos(np.clip((t[1:] * t[:-1]).sum(1), -1.0, 1.0)))
            assert step.max() < 1.0, (sign, step.max())
            pts = frame.point(x, s)[:, 1:]
            for k in range(0, s.size, 50):
                u, n = _oracle(section, pts[k])
                # never into the section; on the octagon (turns of 45 degrees) towards I
                # (down the section for an upper fillet)
                assert section is not OCTAGON or t[k] @ (-sign * u) > 0.0
                assert t[k] @ n >= -1e-12, (sign, s[k], t[k] @ n)


def test_away_from_vertices_the_start_leaves_along_its_piece():
    section = np.asarray(OCTAGON)
    frame = _frame(OCTAGON)
    mids = 0.5 * (section[:-1] + section[1:])
    s = frame.parameter_of(np.column_stack([np.full(len(mids), 5.0), mids]))
    for sign in (1.0, -1.0):
        t = frame.tangent(np.full(len(s), 5.0), s, np.full(len(s), sign))[:, 1:]
        for k, m in enumerate(mids):
            u, _ = _oracle(OCTAGON, m)
            assert np.allclose(t[k], -sign * u, atol=1e-12)


def test_keep_area_converges_where_fillet_starts_cross_section_vertices():
    """A generated airplane (tests/data/generated/README.md) whose area compensation
    stopped at a residual of 0.0037: the re-designed fuselage's sections plus the fillets
    now give the original area at every fillet station."""
    cfg = jc.read(DATA / "generated" / "keep_area" / "fillet_start_crossing_section_vertices.inp")
    with warnings.catch_warnings():
        warnings.simplefilter("error", jc.JunctureWarning)
        geo = jc.complete(cfg, fillet="cubic", keep_area=True)
    st = geo.stations
    body0, body1 = cfg["body"], geo.configuration["body"]
    a0 = body0.area_at(st["x"])
    assert len(st["x"]) and np.all(st["area_fillet"] > 0)
    # (the areas' independent check on such fuselages: test_arbitrary_fillets.py)
    np.testing.assert_allclose(body1.area_at(st["x"]) + st["area_fillet"], a0, rtol=1e-9)
