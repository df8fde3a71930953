"""Body ends given as a section too small to be anything but a point (surface/ends.py)."""

import warnings

import numpy as np
import pytest
import trimesh

import juncture as jc
from juncture.model.configuration import rebuilt
from juncture.surface.ends import TINY_END
from tests.support import DATA, smallest_angles


def _near_point_tail(radius):
    """A generated airplane (tests/data/generated) whose fuselage ends at a point, its last
    section replaced by a half-circle of ``radius`` round that point, written to four
    decimals as a deck's cards would (the points rounding puts nearly in line). Its tail,
    whose root runs out 0.016 from the plane of symmetry beside the point, is left off
    (that strip is another matter: the pointed tail as given has triangles of 1.2 deg
    there)."""
    cfg = jc.read(DATA / "generated" / "arbitrary_body_pointed_upswept_tail.inp")
    cfg = cfg.replace(components={k: v for k, v in cfg.components.items() if k != "tail 1"})
    body = cfg["body"]
    tip = np.asarray(body.sections[-1])[0]
    phi = np.linspace(0.0, np.pi, len(body.sections[-1]))
    ring = tip + radius * np.stack([np.sin(phi), -np.cos(phi)], axis=1)
    sections = body.sections[:-1] + (np.round(ring, 4),)
    return cfg.with_component(rebuilt(body, sections=sections)), body.x[-1], tip


def _mesh(cfg):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.mesh(jc.complete(cfg))


def test_a_tail_section_a_rounding_across_is_meshed_as_the_point_it_stands_for():
    """The last section 4e-4 across (3.5e-6 of the fuselage's length): the fuselage ends at
    one vertex on its centre line, closed (trimesh), and no triangle under 5 deg anywhere
    (as given, the section was a cap of rounded points and the last panel narrowed onto it:
    triangles of a fraction of a degree)."""
    cfg, x_end, tip = _near_point_tail(2e-4)
    surface = _mesh(cfg)
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    at_end = surface.vertices[surface.vertices[:, 0] == x_end]
    np.testing.assert_array_equal(at_end, [[x_end, 0.0, tip[1]]])
    assert not any(s.startswith("body cap") for s in surface.surfaces)
    assert smallest_angles(surface.vertices, surface.triangles).min() >= 5.0


def test_a_small_but_real_base_keeps_its_cap():
    """A base ten times the threshold across is a surface of the airplane: capped, kept."""
    length = 71.638
    cfg, x_end, _ = _near_point_tail(10 * TINY_END * length)
    surface = _mesh(cfg)
    assert "body cap" in surface.surfaces
    assert np.count_nonzero(surface.vertices[:, 0] == x_end) > 2
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
    assert pytest.approx(tm.volume, rel=1e-12) == surface.volume()


def test_a_base_section_a_point_rounded_to_the_last_digit_ends_at_one_vertex():
    """A generated airplane whose fuselage ends in a section 2e-4 ft across as drawn
    (tests/data/generated/README.md): one vertex there, no cap, closed (assembled as
    given, the cap's rounded points made it cross the fuselage's blocks: 516 crossing
    pairs)."""
    deck = DATA / "generated" / "remesh" / "base_section_a_point_rounded_to_the_last_digit.inp"
    cfg = jc.read(deck)
    x_end = max(float(c.x_global[-1]) for c in cfg.components.values()
                if hasattr(c, "x_global") and c.name == "body")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        geo = jc.complete(cfg)
    surface = jc.mesh(geo, min_angle=0)
    assert np.count_nonzero(surface.vertices[:, 0] == x_end) == 1
    assert "body cap" not in surface.surfaces
    tm = trimesh.Trimesh(surface.vertices, surface.triangles, process=False)
    assert tm.is_watertight and tm.is_winding_consistent
