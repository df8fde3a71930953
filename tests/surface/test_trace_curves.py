"""Traced curves (a pylon's line on the wing) inserted into the wing's networks."""

from types import SimpleNamespace

import numpy as np

from juncture.surface.component_networks import add_trace_curves


def _wing_lower(reverse_points):
    """A swept wing's lower network, n-lines spanwise from the body out, each line LE -> TE
    (or TE -> LE); at the root the intersection line's second point lies ahead of its
    first, as it can where the wing meets a narrowing body."""
    span = np.array([2.0, 6.0, 10.0])
    f = np.linspace(0.0, 1.0, 6)
    le, chord = 10.0 + 0.8 * span, 12.0 - 0.5 * span
    x = le[:, None] + chord[:, None] * f[None, :]
    x[0, 1] = x[0, 0] - 0.3
    net = np.stack([x, np.broadcast_to(span[:, None], x.shape), -0.1 * x], axis=-1)
    return net[:, ::-1] if reverse_points else net


def _curve(y):
    f = np.linspace(0.0, 1.0, 6)
    x = 10.0 + 0.8 * y + (12.0 - 0.5 * y) * f
    return np.stack([x, np.full(6, y), -0.1 * x], axis=-1)


def _folded_quads(net):
    """Quads whose two diagonals' chordwise directions disagree: a line reversed against
    its neighbour."""
    d = np.diff(net[..., 0], axis=1)                        # along each line
    return int(np.sum(np.sign(d[1:]) * np.sign(d[:-1]) < 0))


def test_a_traced_curve_runs_the_way_the_lines_do_whatever_the_root_line_does():
    wing = SimpleNamespace(name="w")
    for reverse in (False, True):
        net = _wing_lower(reverse)
        out = add_trace_curves(wing, {"w lower": net}, [("lower", _curve(7.5))])["w lower"]
        assert out.shape[0] == net.shape[0] + 1
        # Every line but the root one runs the same way as the input's outboard lines.
        way = np.sign(net[-1, -1, 0] - net[-1, 0, 0])
        assert np.all(np.sign(out[1:, -1, 0] - out[1:, 0, 0]) == way)
        assert _folded_quads(out[1:]) == 0


def test_the_lines_of_a_fillet_keep_their_order_and_a_curve_goes_in_outboard_of_them():
    """A fillet's lines run down the fuselage side, so their mean span is not increasing (a
    generated low wing: 10.69, 10.56, 10.59, 10.74; here 2, 1.87, 1.84, 2.05); sorting every
    line by span swapped two of them and folded the wing's surface. The curve goes in after
    the last line not outboard of it; the other lines keep their order."""
    wing = SimpleNamespace(name="w")
    net = _wing_lower(False)
    fillet = np.stack([net[0] + [0.0, dy, dz] for dy, dz in
                       ((-0.13, -0.5), (-0.16, -1.0), (0.05, -1.4))])
    net = np.concatenate([net[:1], fillet, net[1:]])
    out = add_trace_curves(wing, {"w lower": net}, [("lower", _curve(7.5))])["w lower"]
    assert len(out) == len(net) + 1
    np.testing.assert_array_equal(out[:5], net[:5])   # body line, the fillet's, span 6
    np.testing.assert_array_equal(out[5], _curve(7.5))
    np.testing.assert_array_equal(out[6], net[5])      # span 10


def test_a_pylons_two_lines_a_hair_apart_in_x_make_one_station_of_the_pod():
    """A pylon's outboard and inboard lines meet its pod 1e-5 apart in x (a generated
    airplane): the pod's network had two rows that close, and every triangle between them
    was a sliver. Points within a thousandth of the pod's length share one row, which ends
    exactly at each of them."""
    from juncture.model import CircularBody
    from juncture.surface.component_networks import nacelle_network

    pod = CircularBody("pod 1", np.array([0.0, 4.0, 12.0, 20.0]),
                       np.array([1.0, 2.0, 2.0, 0.0]), origin=np.array([100.0, 20.0, -5.0]))
    x = np.array([104.0, 106.5, 109.0, 111.0])
    top = pod.point(x[:, None], np.array([1.4, 1.74]))     # just either side of the top
    out_pts, in_pts = top[:, 0], pod.point(x + 1e-5, 1.74)
    in_pts[[0, -1]] = out_pts[[0, -1]]          # the leading and trailing edges: one point

    def line(pts):
        return SimpleNamespace(points=pts, found=np.ones(len(pts), bool))

    net = nacelle_network(pod, [(line(out_pts), line(in_pts))])
    rows = net[:, 1:-1, 0]                                   # the arcs' inner points
    assert np.diff(np.unique(rows)).min() > 1e-3 * 20.0      # no two rows a hair apart
    for pts, col in ((out_pts, -1), (in_pts, 0)):
        assert all(any(np.array_equal(p, q) for q in net[:, col]) for p in pts)


def test_a_pod_under_a_fin_ends_its_arcs_on_the_fins_exact_surface():
    """A fin standing on a pod: the pod's stations between the fin's intersection points
    end where the fin's surfaces meet the pod in those planes, on both exact surfaces (the
    angle interpolated between the points put them up to 4e-3 of the airplane off the
    fin); the intersection points themselves stay rows' ends, bit for bit."""
    from juncture.intersect import intersect_body
    from juncture.model import CircularBody, WingLike
    from juncture.surface.component_networks import nacelle_network

    pod = CircularBody("pod 1", np.array([0.0, 3.0, 9.0, 14.0]),
                       np.array([0.6, 1.2, 1.2, 0.3]), origin=np.array([50.0, 12.0, 0.0]))
    x = np.array([0.0, 10.0, 30.0, 60.0, 100.0])
    half = np.array([0.0, 3.0, 5.5, 4.0, 0.2])
    fin = WingLike("fin 1", "fin", [[52.0, 12.0, 0.5], [54.0, 12.0, 4.0]], [4.5, 2.5], x,
                   np.stack([half, 0.8 * half]), mirrored=False)
    lines = {}
    for side in ("upper", "lower"):
        lines[side] = intersect_body(fin, pod, side)
        assert lines[side].found.all()
    net = nacelle_network(pod, [(lines["upper"], lines["lower"], fin)], n_points=19)
    for side, col in (("upper", -1), ("lower", 0)):
        pts = lines[side].points
        for p in pts:
            assert any(np.array_equal(p, q) for q in net[:, col])
        ends = net[:, col]
        between = (ends[:, 0] > pts[:, 0].min() + 1e-9) & (ends[:, 0] < pts[:, 0].max() - 1e-9)
        given = np.array([any(np.array_equal(e, p) for p in pts) for e in ends])
        rows = ends[between & ~given]
        assert len(rows) >= 2                       # pod stations between the points
        span = rows[:, fin.span_axis]
        le = fin.point(span, 0.0, side, extrapolate=True)[:, 0]
        te = fin.point(span, 1.0, side, extrapolate=True)[:, 0]
        on_fin = fin.point(span, (rows[:, 0] - le) / (te - le), side, extrapolate=True)
        np.testing.assert_allclose(on_fin, rows, rtol=0, atol=1e-9)
        np.testing.assert_allclose(pod.radial_error(rows), 0.0, atol=1e-9)


def test_a_curve_a_hair_beside_a_section_is_not_inserted():
    """A fin standing 0.024 ft inboard of a wing section 13.5 ft from the next (a generated
    airplane): its traced curve beside the section made a row of slivers and edges in more
    than two triangles. Within BESIDE of the spacing the curve is left out (the fin's
    footprint is still cut into the wing at assembly); a curve between sections goes in."""
    from juncture.surface.component_networks import BESIDE

    wing = SimpleNamespace(name="w")
    net = _wing_lower(False)
    near = _curve(6.0 - 0.5 * BESIDE * 4.0)         # half the threshold off span 6
    out = add_trace_curves(wing, {"w lower": net}, [("lower", near)])["w lower"]
    np.testing.assert_array_equal(out, net)
    far = _curve(6.0 - 2.0 * BESIDE * 4.0)
    out = add_trace_curves(wing, {"w lower": net}, [("lower", far)])["w lower"]
    assert len(out) == len(net) + 1


def test_a_curve_crossing_a_section_is_not_inserted():
    """A fin's traced curve whose span runs from one side of a wing section to the other
    (a generated airplane: 30.478 at the ends, past 30.575 between) went in on both sides
    of the section by its mean span and folded the network: left out (the footprint is cut
    all the same)."""
    wing = SimpleNamespace(name="w")
    net = _wing_lower(False)
    crossing = _curve(5.8)
    crossing[2:4, 1] = 6.2                          # past the section at span 6
    out = add_trace_curves(wing, {"w lower": net}, [("lower", crossing)])["w lower"]
    np.testing.assert_array_equal(out, net)
