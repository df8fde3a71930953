"""Area-distribution figures say what they show: Mach number, method, which areas, units."""

import re

import numpy as np
import pytest

import juncture as jc
from juncture.analysis import wavedrag
from juncture.plots import plot_area_distribution, plot_wavedrag_areas
from juncture.plots._backend import pyplot
from tests.support import PDAS_DECK

UNIT = re.compile(r"\[[^\]]+\]$")


@pytest.fixture(scope="module")
def pdas():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(PDAS_DECK)


@pytest.fixture(scope="module")
def far(pdas):
    return {"original": wavedrag(pdas, mach=1.7, n_x=31, n_theta=6),
            "scaled": wavedrag(pdas, mach=1.7, n_x=31, n_theta=6)}


def axes_of(fig):
    return {ax.get_label(): ax for ax in fig.axes}


def test_far_field_title_names_mach_and_method_and_plots_mach_plane_areas(far):
    fig = plot_wavedrag_areas(far, title="PDAS")
    axes = axes_of(fig)
    title = axes["areas"].get_title()
    assert "Mach 1.7" in title and "far-field (Harris)" in title and "roll angles" in title
    assert "Mach-plane areas" in title
    assert fig._suptitle.get_text() == "PDAS"
    # The curve drawn is the mean over roll angles of the cuts the drag came from.
    res = far["original"]
    xc, ac = np.asarray(res["x_cuts"]), np.asarray(res["cut_areas"])
    line = axes["areas"].lines[0]
    grid = line.get_xdata()
    w = np.asarray(res["theta_weights"]) / np.sum(res["theta_weights"])
    mean = w @ np.array([np.interp(grid, x, a, left=0, right=0) for x, a in zip(xc, ac)])
    np.testing.assert_allclose(line.get_ydata(), mean)
    assert grid.min() == pytest.approx(xc.min()) and grid.max() == pytest.approx(xc.max())
    # D/q per roll angle, whose weighted mean (the integration rule) is the far-field D/q.
    roll = axes["roll angles"].lines[0]
    np.testing.assert_allclose(roll.get_ydata(), res["D_over_q_theta"])
    assert w @ roll.get_ydata() == pytest.approx(res["D_over_q"], rel=1e-9)
    assert "D/q = " in axes["areas"].get_legend().get_texts()[0].get_text()
    pyplot().close(fig)


def test_slender_body_and_results_without_cuts_say_what_is_shown(pdas, far):
    slender = {"before": wavedrag(pdas, n_x=21)}
    fig = plot_wavedrag_areas(slender)
    title = axes_of(fig)["areas"].get_title()
    pyplot().close(fig)
    assert "slender-body (Eminton-Lord), Mach -> 1" in title and "normal" in title
    bare = {k: {f: v[f] for f in ("x", "area", "mach", "method", "D_over_q")}
            for k, v in far.items()}
    fig = plot_wavedrag_areas(bare)
    title = axes_of(fig)["areas"].get_title()
    assert "roll angles" not in axes_of(fig)
    pyplot().close(fig)
    assert "Mach 1.7" in title and "normal (Mach 1) areas" in title
    assert "no Mach-plane cuts" in title


@pytest.mark.parametrize("units", ["ft", "m"])
def test_every_axis_label_has_the_unit(far, units):
    fig = plot_wavedrag_areas(far, units=units)
    found = [lab for ax in fig.axes for lab in (ax.get_xlabel(), ax.get_ylabel()) if lab]
    pyplot().close(fig)
    assert len(found) >= 4 and all(UNIT.search(lab) for lab in found)
    assert sum(f"[{units}" in lab for lab in found) == len(found) - 1  # roll angle in deg


def test_plot_area_distribution_writes_a_png(tmp_path, far):
    out = plot_area_distribution(far, tmp_path / "a.png", title="t", units="m")
    assert out.read_bytes()[:4] == b"\x89PNG"
    with pytest.raises(jc.JunctureError, match="no area distributions"):
        plot_area_distribution({}, tmp_path / "x.png")
    assert not (tmp_path / "x.png").exists()
