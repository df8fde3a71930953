"""Cubic fillets on generated airplanes (issue 11, item 2): fillets that are fillets.

On decks drawn from ``tests.deckgen`` (low, mid and high wings; roots inside, crossing and
outside the fuselage; sweep, dihedral, cranks, camber; 1-4 fuselage segments), every fillet
line of both surfaces, with the default options and with drawn ones, is checked against the
deck's own surfaces (``tests.deckgen`` references, SciPy PCHIP, independent of juncture):

- no point inside the fuselage or inside the wing (its lofting lines extended inboard);
- the polygon each line fills (its points closed through the intersection point) and the
  line itself do not cross themselves (exact orientation predicate);
- the start tangent lies along the body circle's tangent, the end tangent along the lofting
  line, to 1e-9 rad (from the exact cubic through the points);
- the area the line adds equals that of a 4001-point polygon of the same region.

With ``keep_area``, the re-designed fuselage nowhere exceeds the original (the fillets only
add area) and body + fillet area is the original at every station to 1e-9.

The fast profile runs a few decks of each wing height and root family (derandomized); the
slow profile (``make test-all``) hundreds.
"""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import juncture as jc
from juncture.fillet import cubic_fillet, wedge_area
from juncture.intersect import intersect_body_both
from tests.deckgen import read_text, references, wing_body_decks
from tests.fillet.fillet_checks import (
    FAMILIES,
    FAST,
    SLOW,
    angle,
    crossing_pairs,
    end_tangents,
    wedge_reference,
)

TOL = 1e-9  # relative to the fuselage length
ANGLE = 1e-9  # rad

options = st.fixed_dictionaries({
    "theta_u": st.floats(3.0, 60.0).map(np.radians),
    "end": st.sampled_from(["dy", "intersection", "section"]),
    "end_value": st.floats(0.05, 1.0),
})


#: complete()'s defaults: theta_u 20 deg, E a quarter of the largest radius out ("dy" values
#: are drawn as fractions of the largest radius).
DEFAULT = {"theta_u": np.radians(20.0), "end": "dy", "end_value": 0.25}


def fillet_lines(text, opts=None):
    cfg = read_text(text)
    wing, body = cfg["wing"], cfg["body"]
    iu, il = intersect_body_both(wing, body)
    opts = opts or DEFAULT
    if opts["end"] == "dy":
        opts = dict(opts, end_value=opts["end_value"] * float(np.max(body.radius)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            fu = cubic_fillet(wing, body, iu, **opts)
            fl = cubic_fillet(wing, body, il, upper_reference=iu, **opts)
        except jc.GeometryError as exc:
            # The one refusal left: an end option that puts E inboard of I.
            assert "is not outboard of the intersection" in str(exc)
            assert opts["end"] == "section"
            return None
    return cfg, ((iu, fu), (il, fl))


def check_fillets(text, desc, opts=None):
    out = fillet_lines(text, opts)
    if out is None:
        return
    cfg, sides = out
    length = desc["length"]
    refs = references(desc)
    wing_ref, body_ref = refs["wing"], refs["body"]
    for inter, f in sides:
        pts = f.points
        assert np.isfinite(pts).all()
        # Outside the fuselage and the wing, as the deck describes them.
        assert body_ref.radial_error(pts.reshape(-1, 3)).min() >= -TOL * length, f.side
        depth = wing_ref.depth(pts.reshape(-1, 3), extend_root=True)
        assert np.max(depth, initial=-np.inf) <= TOL * length, f.side
        live = inter.found & (f.blend > 0)
        corner = np.where(inter.found[:, None], inter.points, f.start)
        for j in np.flatnonzero(live):
            # Simple: the line, and the region it fills (closed through I; none where the
            # line starts at I: no room for a fillet there, the line runs along the wing).
            assert not crossing_pairs(pts[j, :, 1:], closed=False), (f.side, j)
            if np.linalg.norm(pts[j, 0] - corner[j]) > 1e-9 * length:
                assert not crossing_pairs(np.vstack([pts[j, :, 1:], corner[j, 1:]])), \
                    (f.side, j)
        # Tangent to the body circle at the start, to the lofting line at the end.
        d0, d1 = end_tangents(pts)
        x0 = pts[:, 0, 0]
        r0, zc, _ = body_ref.section(x0)
        radial = np.stack([np.zeros_like(x0), pts[:, 0, 1] - body_ref.y_centre,
                           pts[:, 0, 2] - zc], axis=1)
        circle = np.cross([1.0, 0.0, 0.0], radial)
        lines = np.swapaxes(wing_ref.section_points(f.side), 0, 1)
        span = wing_ref.span
        seg = np.clip(np.searchsorted(span, pts[:, -1, 1] - 1e-9 * length, side="left") - 1,
                      0, span.size - 2)
        rows = np.arange(len(seg))
        line_dir = lines[rows, seg + 1] - lines[rows, seg]
        big = live & (np.linalg.norm(d0, axis=1) > 1e-4 * length)
        assert np.all(np.abs(d0[big, 0]) <= ANGLE * np.linalg.norm(d0[big], axis=1))
        a0 = angle(d0[big], circle[big])
        assert np.all(np.minimum(a0, np.pi - a0) < ANGLE), a0
        big = live & (np.linalg.norm(d1, axis=1) > 1e-4 * length)
        assert np.all(angle(d1[big], line_dir[big]) < ANGLE)
        # The area it adds, against a 4001-point polygon of the same region.
        area = wedge_area(cfg["body"], f, corner)
        ctr = np.stack([np.full_like(zc, body_ref.y_centre), zc], axis=1)
        ref = wedge_reference(pts[live], corner[live], ctr[live], r0[live])
        np.testing.assert_allclose(area[live], ref, rtol=1e-6, atol=1e-12 * length ** 2)


def check_keep_area(text, desc):
    cfg = read_text(text)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            geo = jc.complete(cfg, "cubic", keep_area=True)
        except (jc.ConvergenceError, jc.GeometryError) as exc:
            # The known open classes (issue 11; about 1 % of generated circular-body decks in
            # tools/survey_decks.py): the fixed-area iteration does not settle where fillet
            # stations move with the body faster than it shrinks (highly swept roots, stations
            # that go back in x near an edge, an intersection on a bend of the lofting line),
            # or the fillet asks more than a body mostly covered by wing roots can give up.
            # Each must be refused in one line naming the body, the station and (for the
            # second) what to change; every check below on the runs that complete holds.
            msg = str(exc)
            if "only through an open end" in msg:
                # the re-designed (thinner) body leaves a lofting line entering it only
                # through its open end: refused by name, saying what to change
                # (tests/test_complete_misses.py)
                assert "\n" not in msg and "lofting line" in msg and "Close" in msg, msg
                return
            if "only through the face of the step" in msg:
                # or only through the face of a step between two segments (a line grazing
                # the shrinking body; before rays.MAX_DIPS its search ran out of memory)
                assert "\n" not in msg and "lofting line" in msg and \
                    "Give both segments the same section" in msg, msg
                assert desc["segments"] > 1, desc
                return
            assert "\n" not in msg and msg.startswith("body") and "x = " in msg, msg
            if not isinstance(exc, jc.ConvergenceError):  # (a GeometryError subclass)
                assert "can give up" in msg and "use a smaller fillet" in msg, msg
            return
    st_ = geo.stations
    body0, body1 = cfg["body"], geo.configuration["body"]
    a0 = np.pi * body0.radius_at(st_["x"]) ** 2
    np.testing.assert_allclose(np.pi * st_["radius_new"] ** 2 + st_["area_fillet"], a0,
                               rtol=1e-8, atol=1e-9 * a0.max())
    # A fillet only adds area (round-off where it is blended out to nothing).
    assert np.all(st_["area_fillet"] >= -1e-12 * a0.max())
    xs = np.linspace(body0.x_global[0], body0.x_global[-1], 4001)
    assert np.all(body1.radius_at(xs) <= body0.radius_at(xs) + 1e-12 * desc["length"])


@pytest.mark.parametrize("height, root", FAMILIES)
def test_default_fillets_stay_between_body_and_wing(height, root):
    @settings(max_examples=3, **FAST)
    @given(wing_body_decks(section="circular", wing_height=height, root=root))
    def run(example):
        check_fillets(*example)

    run()


@settings(max_examples=12, **FAST)
@given(wing_body_decks(section="circular"), options)
def test_fillets_with_any_options_stay_between_body_and_wing(example, opts):
    check_fillets(*example, opts)


@settings(max_examples=6, **FAST)
@given(wing_body_decks(section="circular"))
def test_keep_area_never_grows_the_fuselage_and_conserves_area(example):
    check_keep_area(*example)


@pytest.mark.slow
@pytest.mark.parametrize("height, root", FAMILIES)
def test_slow_default_fillets_stay_between_body_and_wing(height, root):
    @settings(max_examples=40, **SLOW)
    @given(wing_body_decks(section="circular", wing_height=height, root=root))
    def run(example):
        check_fillets(*example)

    run()


@pytest.mark.slow
@settings(max_examples=300, **SLOW)
@given(wing_body_decks(section="circular"), options)
def test_slow_fillets_with_any_options_stay_between_body_and_wing(example, opts):
    check_fillets(*example, opts)


@pytest.mark.slow
@settings(max_examples=150, **SLOW)
@given(wing_body_decks(section="circular"))
def test_slow_keep_area_never_grows_the_fuselage_and_conserves_area(example):
    check_keep_area(*example)
