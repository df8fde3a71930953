"""The G1 report on the bundled and generated specs, run() outputs, spec validation."""

import json

import numpy as np
import pytest

from juncture.blend import blend_geometry, build_blend, g1_report, load_spec, run
from juncture.blend.report import SEAMS
from juncture.errors import GeometryError, SpecError
from tests.blend.blend_cases import BUNDLED, CASES, EXAMPLE, make_spec

ANALYTIC = ("R1-wing", "R1-body", "R1-R2", "R2-body")


def check_report(report):
    """The acceptance thresholds of the brief."""
    R = report["body_radius"]
    assert [s["seam"] for s in report["seams"]] == list(SEAMS)
    for s in report["seams"]:
        assert set(s) == {"seam", "max_gap", "max_angle_deg", "samples"}
        assert s["samples"] >= 200
        assert s["max_gap"] < 1e-8 * R, s
        limit = 0.05 if s["seam"] in ANALYTIC else 0.5
        assert s["max_angle_deg"] < limit, s


def test_bundled_spec_is_the_example():
    assert json.loads(BUNDLED.read_text()) == json.loads(EXAMPLE.read_text())


@pytest.mark.parametrize("case", [c[1] for c in CASES], ids=[c[0] for c in CASES])
def test_g1_report_on_generated_specs(case):
    check_report(g1_report(build_blend(make_spec(**case))))


def test_g1_seams_are_independently_on_the_body():
    """Body-side seam points of a circular body lie at radius R (closed form)."""
    from juncture.blend.report import seam_samples

    model = build_blend(make_spec(radius=2.5, sweep=0.0))
    for name in ("R1-body", "R2-body", "patch-body"):
        p1 = seam_samples(model, name, 101)[0]
        np.testing.assert_allclose(np.hypot(p1[:, 1], p1[:, 2]), 2.5, rtol=1e-12)


def test_run_writes_report_networks_and_figures(tmp_path):
    out = tmp_path / "out"
    result = run(EXAMPLE, out)
    report = json.loads((out / "g1_report.json").read_text())
    assert set(report) == {"seams", "body_radius"}
    assert report["body_radius"] == 1.0
    check_report(report)
    assert report == result["report"]
    rows = json.loads((out / "patch_refinement.json").read_text())
    assert [r["elements"] for r in rows] == [3, 6, 12, 24]
    angles = [r["angle_fe_deg"] for r in rows]
    assert all(b < a for a, b in zip(angles, angles[1:], strict=False))
    pngs = sorted(p.name for p in out.glob("*.png"))
    assert len(pngs) == 9 and "fig07_r1.png" in pngs
    for fmt, name in (("wgs", "blend.wgs"), ("p3d", "blend.p3d"), ("stl", "blend.stl"),
                      ("step", "blend.step"), ("igs", "blend.igs")):
        assert (out / name).exists() != (fmt in result["skipped"]), fmt
        if (out / name).exists():
            assert (out / name).stat().st_size > 0


def test_run_skips_a_format_without_writer(tmp_path, monkeypatch):
    from juncture.io import _registry

    spec = make_spec()
    spec["output"]["formats"] = ["p3d"]
    monkeypatch.setattr(_registry, "_FORMATS",
                        {k: v for k, v in _registry._FORMATS.items() if ".p3d" not in
                         v.extensions})
    path = tmp_path / "spec.json"
    path.write_text(json.dumps(spec))
    result = run(path, tmp_path / "o")
    assert result["skipped"] == {"p3d": "no writer registered for this format"}
    assert not (tmp_path / "o" / "blend.p3d").exists()


def test_geometry_networks_point_outward_and_are_mirrored():
    geo = blend_geometry(build_blend(make_spec(radius=1.1)))
    assert {"blend wing-body", "blend strake", "blend nose", "body side", "wing upper",
            "wing lower"} <= set(geo.networks)
    assert set(geo.symmetry.values()) == {"xz"}
    for name in ("blend wing-body", "blend strake", "blend nose", "body side"):
        p = geo.networks[name]
        n = np.cross(p[:-1, 1:] - p[:-1, :-1], p[1:, :-1] - p[:-1, :-1])
        radial = p[:-1, :-1] * [0, 1, 1]
        # the upper-side blend faces away from the body and up; the body faces away
        ref = radial / np.linalg.norm(radial, axis=-1, keepdims=True)
        if name != "body side":
            ref = ref + [0.0, 0.0, 1.0]
        ok = np.sum(n * ref, -1)[np.linalg.norm(n, axis=-1) > 1e-12]
        assert np.mean(ok > 0) > 0.95, name
    up = geo.networks["wing upper"]
    n = np.cross(up[:-1, 1:] - up[:-1, :-1], up[1:, :-1] - up[:-1, :-1])
    assert np.sum(n[..., 2]) > 0


@pytest.mark.parametrize("spec, match", [
    ({"body": {"radiuss": 1.0}}, "unknown field 'body.radiuss'"),
    ({"wing": {"root_chord": 4.0}}, "'body.radius' is required"),
    ({**make_spec(), "blend": {"mu": "half"}}, "'blend.mu' must be a finite number"),
    ({**make_spec(), "lines": {"wing_line_xi": [0.5, 0.2]}}, "wing_line_xi"),
    ({**make_spec(), "patch": {"elements": 1.5}}, "patch.elements"),
    ({**make_spec(), "patch": {"bend": [1, 2]}}, "patch.bend"),
    ({**make_spec(), "output": {"points": [2, 10]}}, "output.points"),
    ({**make_spec(), "output": {"formats": "wgs"}}, "output.formats"),
    ({**make_spec(), "body": {"radius": -1.0}}, "'body.radius' must be positive"),
    ({**make_spec(), "body": 3}, "body: expected an object"),
    ({**make_spec(), "patch": {"de_normal": 1}}, "patch.de_normal"),
])
def test_spec_errors(spec, match):
    with pytest.raises(SpecError, match=match):
        load_spec(spec)


def test_spec_file_errors(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"body": {"radius": 1.0,}}')
    with pytest.raises(SpecError, match=r"bad.json, line 1, column \d+: invalid JSON"):
        load_spec(bad)
    with pytest.raises(SpecError, match="missing.json: cannot read the blend spec"):
        load_spec(tmp_path / "missing.json")
    binary = tmp_path / "binary.json"
    binary.write_bytes(b"\x89PNG\r\n\x1a\n\xff\xfe")
    with pytest.raises(SpecError, match="binary.json: expected a JSON blend spec, found binary"):
        load_spec(binary)
    listed = tmp_path / "list.json"
    listed.write_text("[1, 2]")
    with pytest.raises(SpecError, match="list.json: blend spec: .*expected an object"):
        load_spec(listed)


def test_run_rejects_an_unknown_output_format(tmp_path):
    spec = make_spec()
    spec["output"]["formats"] = ["dxf"]
    path = tmp_path / "spec.json"
    path.write_text(json.dumps(spec))
    with pytest.raises(SpecError, match="unknown format 'dxf'"):
        run(path, tmp_path / "o")


def test_impossible_geometry_is_a_geometry_error():
    with pytest.raises(GeometryError, match="semi_span|strake edge"):
        build_blend(make_spec(lines={"strake_y": 0.5}))
