"""Juncture figures and write_figures: units, colours, no wasted space, any configuration."""

import re
import warnings

import numpy as np
import pytest
from matplotlib.colors import to_hex

import juncture as jc
from juncture.plots import (
    main_pair,
    plot_fillet_sections,
    plot_gap_and_intersection,
    plot_lower_intersection,
    plot_station_areas,
    plot_views,
    write_figures,
)
from juncture.plots._backend import pyplot
from juncture.plots.style import INTERSECTION_COLOUR, component_colour
from tests.plots.plot_cases import example, renamed, squashed, without_wing

UNIT = re.compile(r"\[[^\]]+\]$")
ALL = ["views.png", "intersection.png", "lower_intersection.png", "fillet_sections.png",
       "areas.png"]


@pytest.fixture(scope="module")
def cfg():
    return example()


@pytest.fixture(scope="module")
def geo(cfg):
    return jc.complete(cfg, "cubic", True)


def labels(fig):
    return [lab for ax in fig.axes if ax.get_visible() and ax.axison
            for lab in (ax.get_xlabel(), ax.get_ylabel()) if lab]


def test_every_axis_label_has_a_unit(cfg, geo):
    for make in (lambda u: plot_gap_and_intersection(cfg, geo, units=u),
                 lambda u: plot_lower_intersection(cfg, geo, units=u),
                 lambda u: plot_fillet_sections(cfg, geo, units=u),
                 lambda u: plot_station_areas(geo, units=u)):
        for units, expect in (("ft", "[ft"), ("in", "[in")):
            fig = make(units)
            found = labels(fig)
            pyplot().close(fig)
            assert found and all(UNIT.search(lab) and expect in lab for lab in found), found


def test_fillet_sections_each_panel_labelled_legend_once(cfg, geo):
    fig = plot_fillet_sections(cfg, geo, n=5)
    panels = [ax for ax in fig.axes if ax.get_visible()]
    assert len(panels) == 5
    xs = []
    for ax in panels:
        m = re.fullmatch(r"x = ([-\d.e+]+) ft, added area ([-\d.e+]+) ft\u00b2", ax.get_title())
        assert m, ax.get_title()
        xs.append(float(m.group(1)))
        assert UNIT.search(ax.get_xlabel()) and UNIT.search(ax.get_ylabel())
        assert ax.get_legend() is None
        assert ax.get_aspect() == 1.0
        # One scale for every panel.
        assert np.ptp(ax.get_xlim()) == pytest.approx(np.ptp(panels[0].get_xlim()))
    assert len(fig.legends) == 1
    np.testing.assert_allclose(xs, geo.stations["x"][[1, 4, 6, 8, 11]], rtol=1e-4)
    pyplot().close(fig)


def _colours(ax, label_start):
    return {to_hex(line.get_color()) for line in ax.lines
            if line.get_label().startswith(label_start)}


def test_a_component_has_one_colour_in_every_figure(cfg, geo):
    from juncture.plots import wireframe_data

    views = plot_views(geo)
    plan = next(ax for ax in views.axes if ax.get_label() == "plan view")
    in_views = {c.get_gid(): to_hex(c.get_colors()[0]) for c in plan.collections}
    sections = plot_fillet_sections(cfg, geo)
    ax = sections.axes[0]
    in_sections = {"wing": _colours(ax, "wing "), "body": _colours(ax, "body,"),
                   "fillet": _colours(ax, "fillet")}
    lower = plot_lower_intersection(cfg, geo)
    in_lower = {to_hex(line.get_color()) for line in lower.axes[0].lines
                if "intersection" in line.get_label()}
    data = wireframe_data(geo, components=[c.name for c in geo.configuration])
    in_report = {c["name"]: c["colour"] for c in data["components"]}
    for fig in (views, sections, lower):
        pyplot().close(fig)
    for comp in ("wing", "body", "fillet"):
        assert in_sections[comp] == {in_views[comp]} == {component_colour(comp)}, comp
    for comp in ("wing", "body", "pod 1", "pod 2", "fin 1", "fin 3", "tail 1"):
        assert in_report[comp] == in_views[comp] == component_colour(comp), comp
    assert in_lower == {INTERSECTION_COLOUR} == {data["intersection_colour"]}


def test_lower_intersection_data_fill_the_axes_and_the_figure(cfg, geo):
    fig = plot_lower_intersection(cfg, geo)
    fig.draw_without_rendering()
    marked = ("lower intersection", "upper intersection", "lower fillet start",
              "upper fillet start")
    axes = [ax for ax in fig.axes if ax.get_visible()]
    assert len(axes) == 2
    for ax in axes:
        pts = np.concatenate([line.get_xydata() for line in ax.lines
                              if line.get_label().startswith(marked)])
        for k, lim in enumerate((ax.get_xlim(), ax.get_ylim())):
            assert np.ptp(pts[:, k]) / abs(lim[1] - lim[0]) >= 0.8, (ax.get_title(), k)
            assert min(lim) <= pts[:, k].min() and pts[:, k].max() <= max(lim)
        assert "scale" in ax.get_title()  # the stretch of y (z) against x is stated
    # The axes cover most of the figure (no empty bands).
    area = sum(ax.get_position().width * ax.get_position().height for ax in axes)
    assert area > 0.6
    pyplot().close(fig)


def test_write_figures_writes_each_figure_once(tmp_path, cfg, geo):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        names = write_figures(cfg, geo, tmp_path, fillet="cubic", units="ft")
    assert names == ALL
    for name in ALL:
        assert (tmp_path / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert pyplot().get_fignums() == []  # every figure closed


def test_arbitrary_body_figures_do_not_crash(tmp_path, cfg):
    sq = squashed(cfg)
    geo = jc.complete(sq, None)
    assert not hasattr(sq["body"], "radius")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        names = write_figures(sq, geo, tmp_path, fillet=None)
    assert names == ALL[:3]
    fig = plot_gap_and_intersection(sq, geo)
    edge = next(line for line in fig.axes[0].lines if "plan-view edge" in line.get_label())
    # The plan-view edge of the elliptic body is 1.15 times the circular radius.
    assert np.max(edge.get_ydata()) == pytest.approx(1.15 * cfg["body"].radius.max(),
                                                     rel=1e-3)
    pyplot().close(fig)


def test_arbitrary_body_deck_through_the_command_line(tmp_path, cfg):
    from juncture.cli import main

    deck = tmp_path / "ellipse.inp"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        jc.write(squashed(cfg), deck)
    assert type(jc.read(deck)["body"]).__name__ == "ArbitraryBody"
    out = tmp_path / "out"
    assert main(["complete", str(deck), "-o", str(out), "--fillet", "none", "--figures",
                 "-q"]) == 0
    for name in ALL[:3]:
        assert (out / name).stat().st_size > 0


def test_other_component_names(tmp_path):
    cfg = renamed(example())
    geo = jc.complete(cfg, "cubic", True, wing="main wing", body="fuselage")
    assert main_pair(cfg, geo) == ("main wing", "fuselage")
    assert write_figures(cfg, geo, tmp_path, fillet="cubic") == ALL
    fig = plot_fillet_sections(cfg, geo)
    legend = [t.get_text() for t in fig.legends[0].get_texts()]
    pyplot().close(fig)
    assert "main wing upper lofting line" in legend and "fuselage, re-designed" in legend


def test_figures_that_cannot_apply_are_skipped_with_a_warning(tmp_path, cfg):
    plain = without_wing(cfg)
    geo = plain.to_geometry()
    assert main_pair(plain, geo) is None
    with pytest.warns(jc.JunctureWarning) as caught:
        names = write_figures(plain, geo, tmp_path, fillet="cubic")
    assert names == ["views.png"]
    said = [str(w.message) for w in caught]
    assert [m.split(" skipped: ")[0] for m in said] == ALL[1:]
    assert said[0].startswith("intersection.png skipped: no wing-body intersection")
    with pytest.raises(jc.JunctureError, match="no wing-body intersection"):
        plot_lower_intersection(plain, geo)
    sharp = jc.complete(cfg, None)
    with pytest.raises(jc.JunctureError, match="no fillet in the geometry"):
        plot_fillet_sections(cfg, sharp)
    with pytest.raises(jc.JunctureError, match="no components 'wing' and 'hull'"):
        plot_gap_and_intersection(cfg, sharp, body="hull")
