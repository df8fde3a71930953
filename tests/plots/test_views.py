"""Plan, side and front views: seen as a designer expects, at one true scale, with units."""

import re

import numpy as np
import pytest
from matplotlib.colors import to_hex

import juncture as jc
from juncture.plots import plot_front, plot_planform, plot_side, plot_views
from juncture.plots._backend import pyplot
from juncture.plots.style import component_colour
from tests.plots.plot_cases import example, renamed

UNIT = re.compile(r"\[[^\]]+\]$")


@pytest.fixture(scope="module")
def geo():
    return jc.complete(example(), "cubic", True)


@pytest.fixture(scope="module")
def views(geo):
    fig = plot_views(geo)
    fig.draw_without_rendering()
    yield fig, {ax.get_label(): ax for ax in fig.axes}
    pyplot().close(fig)


def colours(ax):
    """component -> colours of its collections on ``ax`` (set by gid)."""
    out = {}
    for coll in ax.collections:
        out.setdefault(coll.get_gid(), set()).update(to_hex(c) for c in coll.get_colors())
    return out


def test_plan_view_is_from_above_with_starboard_up(views, geo):
    _, axes = views
    plan = axes["plan view"]
    y0, y1 = plan.get_ylim()
    assert y0 < y1 and not plan.yaxis_inverted() and not plan.xaxis_inverted()
    # The described (starboard, y >= 0) wing tip is drawn above its mirror image, and the
    # nose (x = 0) left of the tail.
    wing = geo.networks["wing upper"]
    tip = wing[np.unravel_index(np.argmax(wing[..., 1]), wing.shape[:2])]
    assert tip[1] > 0
    above = plan.transData.transform([[tip[0], tip[1]], [tip[0], -tip[1]]])
    assert above[0, 1] > above[1, 1]
    left = plan.transData.transform([[0.0, 0.0], [300.0, 0.0]])
    assert left[0, 0] < left[1, 0]
    assert plan.get_title() == "plan view, from above"


def test_side_and_front_views_match_the_3d_viewer(views):
    _, axes = views
    side, front = axes["side view"], axes["front view"]
    assert not side.yaxis_inverted() and not side.xaxis_inverted()
    # From ahead: starboard (+y) on the viewer's left, as the report's "front" button.
    assert front.xaxis_inverted() and not front.yaxis_inverted()


def test_one_true_scale_and_aligned_views(views):
    fig, axes = views
    plan, side, front = axes["plan view"], axes["side view"], axes["front view"]
    for ax in (plan, side, front):
        assert ax.get_aspect() == 1.0
    # Units per pixel equal in every view and direction (a three-view drawing).
    scales = []
    for ax in (plan, side, front):
        box = ax.get_window_extent()
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        scales += [abs(x1 - x0) / box.width, abs(y1 - y0) / box.height]
    np.testing.assert_allclose(scales, scales[0], rtol=0.02)
    # The side view sits under the plan view, same x; the front view beside it, same z.
    np.testing.assert_allclose(plan.get_xlim(), side.get_xlim())
    np.testing.assert_allclose(side.get_ylim(), front.get_ylim())
    p, s = plan.get_window_extent(), side.get_window_extent()
    assert abs(p.x0 - s.x0) < 1 and abs(p.x1 - s.x1) < 1


def test_every_axis_label_has_a_unit(geo):
    for make in (plot_views, plot_planform, plot_side, plot_front):
        fig = make(geo, units="m")
        labels = [lab for ax in fig.axes if ax.axison
                  for lab in (ax.get_xlabel(), ax.get_ylabel())]
        pyplot().close(fig)
        assert labels and all(UNIT.search(lab) and "[m]" in lab for lab in labels), labels


def test_tight_limits_around_the_airplane(views, geo):
    _, axes = views
    plan = axes["plan view"]
    ext = geo.extents()
    span_x = np.ptp(plan.get_xlim())
    assert (ext[1, 0] - ext[0, 0]) / span_x > 0.9
    assert (2 * ext[1, 1]) / np.ptp(plan.get_ylim()) > 0.85


def test_one_colour_per_component_with_a_legend_entry_each(views):
    fig, axes = views
    for view in ("plan view", "side view", "front view"):
        for comp, cols in colours(axes[view]).items():
            assert cols == {component_colour(comp)}, (view, comp)
    legend = axes["legend"].get_legend()
    names = [t.get_text() for t in legend.get_texts()]
    assert {"body", "wing", "pod 1", "fin 3", "tail 1", "fillet"} <= set(names)
    assert len(names) == len(set(names))
    for handle, name in zip(legend.legend_handles, names):
        assert to_hex(handle.get_color()) == component_colour(name)


def test_components_named_otherwise_keep_their_names_and_colours():
    cfg = renamed(example())
    geo = jc.complete(cfg, None, wing="main wing", body="fuselage")
    fig = plot_planform(geo)
    ax = fig.axes[0]
    names = [t.get_text() for t in ax.get_legend().get_texts()]
    cols = colours(ax)
    pyplot().close(fig)
    assert {"main wing", "fuselage"} <= set(names) and not {"wing", "body"} & set(names)
    assert cols["fuselage"] == {component_colour("body")}


def test_views_of_networks_without_a_model():
    net = np.stack(np.meshgrid(np.linspace(0, 9, 5), np.linspace(0, 2, 3), [0.0],
                               indexing="ij"), -1)[:, :, 0]
    fig = plot_planform({"FUSELAGE SEGMENT #  1": net + [0, 0, 1.0]})
    (name,) = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    pyplot().close(fig)
    assert name == "FUSELAGE"
