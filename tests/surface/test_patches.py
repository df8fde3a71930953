"""The patches the re-triangulation works on."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import juncture as jc
import juncture.surface.patches as pt
import juncture.surface.pipeline as pipeline
from juncture.surface.assemble import assemble
from juncture.surface.pipeline import _line_points
from juncture.surface.quality import triangle_angles
from tests.support import DATA


def _geometry(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.complete(jc.read(DATA / "generated" / "remesh" / name))


def test_a_network_that_turns_at_a_crease_is_two_patches(monkeypatch, mesh=False):
    """The wing and the fuselage's middle as one network (tests/data/generated/README.md)
    turn 120 deg at the wing's root: the network is two patches there, the root line a seam
    between them, and the surface re-triangulates with no triangle under 4.5 deg (8.3 with
    the seam on its chords; 4.8 since it follows the exact curve, juncture.surface.
    seam_curves, a triangle beside it whose corner was lifted part of the way, as next to
    every intersection line). As one patch its triangles were refined across the crease,
    crossed each other, and the network kept its assembled triangles (down to 0.0075 deg;
    mended since session 35 by a second held try, below)."""
    geo = _geometry("high_wing_one_network_with_the_body.inp")
    assembled = assemble(geo)
    lower = assembled.surfaces.index("wing-body lower")
    lines = _line_points(geo, assembled)
    parts = [rows for rows in pt.patches(assembled, lines)
             if assembled.surface[rows[0]] == lower]
    assert len(parts) == 2
    # the two parts meet along a line of edges, and across it their normals turn by more
    # than CREASE
    t = [assembled.triangles[rows] for rows in parts]
    shared = np.intersect1d(np.unique(t[0]), np.unique(t[1]))
    assert len(shared) >= 3

    if not mesh:
        return

    def smallest():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", jc.JunctureWarning)
            surface = jc.mesh(geo)
        return triangle_angles(surface.vertices, surface.triangles).min()

    assert smallest() >= 4.5
    monkeypatch.setattr(pt, "CREASE", 180.0)
    assert smallest() >= 3.5
    monkeypatch.setattr(pipeline, "HELD_TRIES", 1)
    assert smallest() < 1.0


@pytest.mark.slow  # this airplane meshes in about 10 s (a retry), three times: make test-all
def test_slow_a_network_charted_across_its_crease_is_mended_by_held_tries(monkeypatch):
    """The test above with its meshes: the smallest angle with the crease a seam, and
    without it. As one patch it crosses in 14 triangle pairs, its held try again in 8; the
    held tries hold both since session 35 (`pipeline._hold`, HELD_TRIES) and the next has
    none. With one held try (as before), the triangles there keep their assembled
    shape. Since session 36 (the check for distance in rounds that add seam points,
    `remesh._triangulate_once`) the patch charted across the crease meshes with two
    triangles of 3.9 and 4.3 deg on the wing's lower surface at mid-span, away from the
    crease (4.5 deg before)."""
    test_a_network_that_turns_at_a_crease_is_two_patches(monkeypatch, mesh=True)


def test_a_sliver_standing_across_the_surface_is_no_crease(monkeypatch):
    """Between two fuselage stations 0.005 ft apart (a wing's upper and lower trailing edge
    cut by an octagonal body: tests/data/generated/README.md) a sliver stands across the
    body, its normal 80-115 deg off its neighbours'; a line of creases that short (under
    CREASE_LINE of the network's extent) does not cut the network, even taken as between
    intersection points."""
    import juncture.surface.body_split as bs

    # the rows at equal steps of the section's parameter, as they were found (rows through
    # the octagon's corners leave no such sliver), and each row at its own station (rows a
    # rounding apart take the row before's points: body_split.SLIVER; nor that)
    monkeypatch.setattr(bs, "through_corners", lambda body, x, par: par)
    monkeypatch.setattr(bs, "SLIVER", 0.0)
    geo = _geometry("blunt_trailing_edge_cut_by_a_polygon_body.inp")
    assembled = assemble(geo)
    upper = assembled.surfaces.index("body upper")
    rows = np.flatnonzero(assembled.surface == upper)
    lines = np.ones(len(assembled.vertices), bool)       # as if every point were on one
    whole = len(pt._connected(assembled, rows))
    assert len(pt._connected(assembled, rows, lines)) == whole
    monkeypatch.setattr(pt, "CREASE_LINE", 0.0)
    assert len(pt._connected(assembled, rows, lines)) > whole


def test_a_patch_whose_chart_folds_is_charted_in_halves(monkeypatch, slow=False):
    """A low wing's upper surface with a cubic fillet (tests/data/generated/README.md)
    flattens by LSCM with one triangle folded where it turns down to the leading edge at the
    root: it is charted in halves, and re-triangulated (it kept its assembled triangles,
    hundreds of them under 5 deg)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(jc.read(DATA / "generated" / "remesh" /
                                  "low_wing_whose_upper_surface_folds_in_its_chart.inp"),
                          fillet="cubic", keep_area=True)
    assembled = assemble(geo)
    upper = assembled.surfaces.index("wing upper")
    rows = np.flatnonzero(assembled.surface == upper)
    assert pt.chart(assembled, rows) is None
    got = pt.charts(assembled, rows)
    assert got is not None and len(got) >= 2
    assert sum(len(p.tri) for p in got) == len(rows)

    def slivers():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", jc.JunctureWarning)
            surface = jc.mesh(geo)
        smallest = triangle_angles(surface.vertices, surface.triangles).min(axis=1)
        name = np.array(surface.surfaces)[surface.surface]
        return int(np.sum((smallest < 5.0) & np.char.startswith(name.astype(str), "wing up")))

    assert slivers() == 0
    if not slow:
        return
    monkeypatch.setattr(pt, "_halves", lambda mesh, rows: None)
    assert slivers() > 100


@pytest.mark.slow
def test_slow_a_patch_whose_chart_folds_keeps_its_slivers_uncharted(monkeypatch):
    """The counterfactual of the test above (one more mesh)."""
    test_a_patch_whose_chart_folds_is_charted_in_halves(monkeypatch, slow=True)
