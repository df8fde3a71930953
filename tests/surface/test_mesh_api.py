"""``juncture.mesh(geo)``: the assembled surface, checked, or a one-line refusal."""

import warnings

import pytest
import trimesh

import juncture as jc
from tests.support import EXAMPLE_DECK, PDAS_DECK


def _complete(deck, fillet=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.complete(jc.read(deck), fillet)


def test_mesh_of_a_wing_body_is_closed_for_trimesh():
    surface = jc.mesh(_complete(PDAS_DECK, "cubic"))
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert tm.volume == pytest.approx(surface.volume(), rel=1e-12)
    assert surface.volume() > 0


def test_mesh_refuses_an_open_surface_in_one_line():
    geo = _complete(EXAMPLE_DECK)
    with pytest.raises(jc.GeometryError, match="the completed surface is not closed") as err:
        jc.mesh(geo)
    assert "\n" not in str(err.value)
    unchecked = jc.mesh(geo, check=False)
    assert len(unchecked.open_loops) > 0
