"""``juncture mesh``: writes only a closed, oriented surface (checked by trimesh)."""

import numpy as np
import pytest

from juncture.cli import main
from tests.support import EXAMPLE_DECK, PDAS_DECK


@pytest.mark.parametrize("fillet", ["none", "cubic"])
def test_the_sample_wing_body_is_written_closed(tmp_path, capsys, fillet):
    import meshio
    import trimesh

    args = ["mesh", str(PDAS_DECK), "-o", str(tmp_path), "--fillet", fillet,
            "--format", "stl", "msh"]
    assert main(args + (["--keep-area"] if fillet != "none" else [])) == 0
    out = capsys.readouterr().out
    assert "enclosed volume" in out and "FAIL" not in out
    tm = trimesh.load(tmp_path / "mesh.stl")
    assert tm.is_watertight and tm.is_winding_consistent and tm.volume > 0
    msh = meshio.read(tmp_path / "mesh.msh")
    assert len(msh.cells_dict["triangle"]) == len(tm.faces)


def test_a_half_model_is_written_with_its_symmetry_plane_marked(tmp_path, capsys):
    """``--half``: the y >= 0 half closed by the component "symmetry" (a Gmsh physical
    group, an STL solid), half the whole airplane's volume."""
    import meshio
    import trimesh

    assert main(["mesh", str(PDAS_DECK), "-o", str(tmp_path / "whole"), "-q"]) == 0
    assert main(["mesh", str(PDAS_DECK), "-o", str(tmp_path / "half"), "--half", "--format",
                 "stl", "msh", "--ascii"]) == 0
    assert "FAIL" not in capsys.readouterr().out
    msh = meshio.read(tmp_path / "half" / "mesh.msh")
    assert "symmetry" in msh.field_data
    assert "solid symmetry" in (tmp_path / "half" / "mesh.stl").read_text()
    half = trimesh.load(tmp_path / "half" / "mesh.stl", force="mesh")
    half.merge_vertices()              # one mesh per ASCII solid: their seams joined
    whole = trimesh.load(tmp_path / "whole" / "mesh.stl")
    assert half.is_watertight and half.is_winding_consistent
    assert half.volume == pytest.approx(whole.volume / 2.0, rel=1e-6)  # float32 STL


def test_flow_through_nacelles_are_written_as_rings(tmp_path, capsys):
    """``--flow-through``: the transport's four nacelles are ducted, one handle each."""
    import trimesh

    assert main(["mesh", str(EXAMPLE_DECK), "-o", str(tmp_path), "--flow-through",
                 "--min-angle", "0"]) == 0
    assert "Euler characteristic -6" in capsys.readouterr().out
    tm = trimesh.load(tmp_path / "mesh.stl")
    assert tm.is_watertight and tm.is_winding_consistent and tm.euler_number == -6


def test_the_bundled_airplane_is_written_closed(tmp_path, capsys):
    import trimesh

    assert main(["mesh", str(EXAMPLE_DECK), "-o", str(tmp_path), "--format", "stl"]) == 0
    out = capsys.readouterr().out
    assert "0 intersecting triangle pairs" in out
    assert "overlaps counted once" in out
    tm = trimesh.load(tmp_path / "mesh.stl")
    assert tm.is_watertight and tm.is_winding_consistent and tm.volume > 0
    line = next(x for x in out.splitlines() if x.startswith("centre of volume "))
    centre = [float(v.strip(",")) for v in line.split(";")[0].split()[-3:]]  # "x, y, z"
    np.testing.assert_allclose(centre, tm.center_mass, atol=1e-3)  # float32 STL


def test_a_surface_that_fails_a_check_gets_no_mesh_and_one_line(tmp_path, capsys, monkeypatch):
    """With the footprints of the pylons left uncut, they cross the wing's lower surface
    (the assembled surface is checked as it is: ``--min-angle 0``; re-triangulated, every
    attempt is checked first, which takes three times as long and ends the same way)."""
    from juncture.surface import assemble as assembly

    monkeypatch.setattr(assembly, "_imprint_all", lambda g, v, t, c, s, n: (t, c, s))
    assert main(["mesh", str(EXAMPLE_DECK), "-o", str(tmp_path / "out"),
                 "--min-angle", "0"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "so no mesh was written" in err[0]
    assert not (tmp_path / "out").exists()


def test_refine_must_be_a_positive_integer(tmp_path, capsys):
    assert main(["mesh", str(PDAS_DECK), "-o", str(tmp_path / "o"), "--refine", "0"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--refine" in err[0] and "integer >= 1" in err[0]
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("flag, value, expected", [("--min-angle", "40", "0 (off) to 30"),
                                                   ("--tolerance", "0", "> 0"),
                                                   ("--curvature", "0", "> 0 and <= 90"),
                                                   ("--depth", "0", "> 0"),
                                                   ("--edge-length", "-1", "> 0"),
                                                   ("--seam-size", "0", "> 0"),
                                                   ("--growth", "0.9", "ratio > 1")])
def test_sizing_options_out_of_range_get_one_line(tmp_path, capsys, flag, value, expected):
    assert main(["mesh", str(PDAS_DECK), "-o", str(tmp_path / "o"), flag, value]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and flag in err[0] and expected in err[0]
    assert not (tmp_path / "o").exists()


def test_the_triangles_are_re_triangulated_unless_min_angle_is_zero(tmp_path, capsys):
    import trimesh

    from juncture.surface.quality import triangle_angles

    shares = []
    for k, angle in enumerate(["25", "0"]):
        out = tmp_path / str(k)
        assert main(["mesh", str(PDAS_DECK), "-o", str(out), "--min-angle", angle]) == 0
        tm = trimesh.load(out / "mesh.stl")
        assert tm.is_watertight and tm.is_winding_consistent
        smallest = triangle_angles(tm.vertices, tm.faces).min(axis=1)
        shares.append((smallest >= 20.0).mean())
    assert shares[0] >= 0.97 > shares[1]


def test_a_tail_running_through_the_wing_root_is_refused_with_its_cause(tmp_path, capsys):
    """A tail whose root starts inside the wing's junction with the fuselage, at the wing's
    own height (tests/data/generated/refused): the command line names the cause as
    juncture.complete does (the two junctions overlap on the body; before, the mesh's open
    edges it leads to); one line, exit status 2, nothing written."""
    from tests.support import DATA

    deck = DATA / "generated" / "refused" / "tail_root_overlaps_wing_root.inp"
    out = tmp_path / "out"
    assert main(["mesh", str(deck), "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert "tail 1: its junction with body" in err[0] and "overlaps that of wing" in err[0]
    assert "move tail 1 clear of wing" in err[0]
    assert not out.exists()
