"""MassProperties: parallel-axis sums, transforms and checks against clouds of point masses
whose moments are summed directly (no parallel-axis theorem in the reference)."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.errors import GeometryError
from juncture.massprops import MassProperties


def cloud_moments(points, masses, about=None):
    """Direct sums: mass, cg, inertia about ``about`` (default the cg)."""
    m = masses.sum()
    cg = masses @ points / m
    ref = cg if about is None else np.asarray(about, float)
    s = points - ref
    inertia = np.einsum("k,ki,kj->ij", masses, s, s)
    return m, cg, np.trace(inertia) * np.eye(3) - inertia


def cloud(points, masses, name=None):
    m, cg, inertia = cloud_moments(points, masses)
    return MassProperties(m, float(len(masses)), cg, inertia, name)


def random_cloud(rng, n, negative=False):
    pts = rng.normal(size=(n, 3)) * rng.uniform(0.5, 3.0, 3) + rng.normal(size=3) * 4
    masses = rng.uniform(0.2, 2.0, n)
    if negative:
        masses[: n // 4] *= -0.3            # lightening holes, total stays positive
    return pts, masses


def random_rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), negative=st.booleans())
def test_sum_matches_direct_summation(seed, negative):
    rng = np.random.default_rng(seed)
    pts, masses = random_cloud(rng, 23, negative)
    cut = [0, 5, 11, 23]
    parts = [cloud(pts[a:b], masses[a:b]) for a, b in zip(cut[:-1], cut[1:], strict=True)]
    m, cg, inertia = cloud_moments(pts, masses)
    for total in (parts[0] + parts[1] + parts[2], MassProperties.sum(parts), sum(parts)):
        assert total.mass == pytest.approx(m, rel=1e-12)
        assert total.volume == 23.0
        np.testing.assert_allclose(total.cg, cg, rtol=1e-11, atol=1e-11)
        np.testing.assert_allclose(total.inertia, inertia, rtol=1e-10,
                                   atol=1e-11 * np.abs(inertia).max())


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_inertia_about_point_matches_direct_summation(seed):
    rng = np.random.default_rng(seed)
    pts, masses = random_cloud(rng, 17)
    point = rng.normal(size=3) * 5
    body = cloud(pts, masses)
    np.testing.assert_allclose(body.inertia_about(point), cloud_moments(pts, masses, point)[2],
                               rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(body.inertia_origin, cloud_moments(pts, masses, [0, 0, 0])[2],
                               rtol=1e-10, atol=1e-10)


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), plane=st.sampled_from(["xz", "xy", "yz"]))
def test_rotated_mirrored_shifted_match_transformed_cloud(seed, plane):
    rng = np.random.default_rng(seed)
    pts, masses = random_cloud(rng, 13)
    body = cloud(pts, masses)
    rot = random_rotation(rng)
    assert body.rotated(rot).allclose(cloud(pts @ rot.T, masses), rtol=1e-10)
    axis = {"yz": 0, "xz": 1, "xy": 2}[plane]
    flipped = pts.copy()
    flipped[:, axis] *= -1
    assert body.mirrored(plane).allclose(cloud(flipped, masses), rtol=1e-12)
    off = rng.normal(size=3)
    assert body.shifted(off).allclose(cloud(pts + off, masses), rtol=1e-10)
    assert body.is_physical()


def test_two_unit_cubes_make_a_2x1x1_box():
    """Textbook box a x b x c: Ixx = m (b^2 + c^2) / 12 etc."""
    cube = MassProperties(1.0, 1.0, [0.5, 0.5, 0.5], np.eye(3) / 6.0)
    box = cube + cube.shifted([1.0, 0.0, 0.0])
    assert box.mass == 2.0 and box.volume == 2.0
    np.testing.assert_allclose(box.cg, [1.0, 0.5, 0.5])
    np.testing.assert_allclose(box.inertia, np.diag([2 * 2 / 12, 2 * 5 / 12, 2 * 5 / 12]),
                               atol=1e-15)


def test_negative_mass_removes_a_part():
    whole = MassProperties(2.0, 2.0, [1.0, 0.5, 0.5], np.diag([4 / 12, 10 / 12, 10 / 12]))
    hole = MassProperties(-1.0, -1.0, [1.5, 0.5, 0.5], -np.eye(3) / 6.0)   # m < 0: I < 0
    rest = whole + hole
    assert rest.allclose(MassProperties(1.0, 1.0, [0.5, 0.5, 0.5], np.eye(3) / 6.0), rtol=1e-13)
    assert not hole.is_physical()


def test_zero_and_empty_sum():
    z = MassProperties.zero()
    assert z.mass == 0.0 and z.volume == 0.0
    body = MassProperties(2.0, 1.0, [1, 2, 3], np.diag([1.0, 2.0, 2.5]))
    assert (z + body).allclose(body, rtol=0, atol=0)
    assert MassProperties.sum([]).mass == 0.0
    assert MassProperties.sum([], name="none").name == "none"


def test_point_mass():
    p = MassProperties.point(3.0, [1.0, 2.0, 0.0])
    r = np.array([1.0, 2.0, 0.0])
    np.testing.assert_allclose(p.inertia_origin, 3.0 * (r @ r * np.eye(3) - np.outer(r, r)))
    assert p.is_physical()


def test_is_physical_detects_triangle_violation_and_negative_moment():
    assert not MassProperties(1.0, 1.0, [0, 0, 0], np.diag([1.0, 1.0, 2.5])).is_physical()
    assert MassProperties(1.0, 1.0, [0, 0, 0], np.diag([1.0, 1.0, 2.0])).is_physical()
    assert not MassProperties(1.0, 1.0, [0, 0, 0], np.diag([-0.1, 1.0, 1.0])).is_physical()


def test_to_dict_keys_and_values():
    body = MassProperties(2.0, 0.5, [1.0, 0.0, 0.0], np.diag([1.0, 2.0, 3.0]), name="pod")
    d = body.to_dict()
    assert list(d) == ["name", "mass", "volume", "cg", "inertia_cg", "inertia_origin"]
    assert d["inertia_origin"] == [[1.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 5.0]]
    json.dumps(d)
    assert "name" not in MassProperties.zero().to_dict()
    assert body.renamed("x").name == "x" and "pod" in repr(body)


def test_immutable():
    body = MassProperties(1.0, 1.0, [0, 0, 0], np.eye(3))
    with pytest.raises(dataclasses.FrozenInstanceError):
        body.mass = 2.0
    with pytest.raises(ValueError, match="read-only"):
        body.cg[0] = 1.0
    with pytest.raises(ValueError, match="read-only"):
        body.inertia[0, 0] = 1.0
    with pytest.raises((AttributeError, TypeError)):   # slots; 3.11 raises TypeError
        body.extra = 1


def test_allclose_tolerances():
    a = MassProperties(1.0, 1.0, [0, 0, 0], np.eye(3))
    b = MassProperties(1.0 + 1e-12, 1.0, [1e-13, 0, 0], np.eye(3))
    assert a.allclose(b) and not a.allclose(b, rtol=1e-14)
    assert not a.allclose(a.shifted([1e-6, 0, 0]))
    assert a.allclose(a.shifted([1e-6, 0, 0]), atol=1e-5)


def test_errors():
    with pytest.raises(GeometryError, match=r"cg must have shape \(3,\), found \(2,\)"):
        MassProperties(1.0, 1.0, [0, 0], np.eye(3))
    with pytest.raises(GeometryError, match=r"inertia must have shape \(3, 3\)"):
        MassProperties(1.0, 1.0, [0, 0, 0], np.eye(2))
    with pytest.raises(GeometryError, match="mass and volume must be finite"):
        MassProperties(float("nan"), 1.0, [0, 0, 0], np.eye(3))
    with pytest.raises(GeometryError, match="cg must be finite"):
        MassProperties(1.0, 1.0, [0, np.inf, 0], np.eye(3))
    body = MassProperties(1.0, 1.0, [0, 0, 0], np.eye(3))
    with pytest.raises(GeometryError, match="must be orthogonal"):
        body.rotated(np.diag([1.0, 2.0, 1.0]))
    with pytest.raises(GeometryError, match=r"rotation matrix must have shape \(3, 3\)"):
        body.rotated(np.eye(2))
    with pytest.raises(GeometryError, match="mirror plane must be one of"):
        body.mirrored("x")
    with pytest.raises(GeometryError, match=r"offset must have shape \(3,\)"):
        body.shifted([1.0])
    with pytest.raises(GeometryError, match=r"point must have shape \(3,\)"):
        body.inertia_about([1.0, 2.0])
    neg = MassProperties(-1.0, -1.0, [1, 0, 0], -np.eye(3))
    with pytest.raises(GeometryError, match="combined mass is zero"):
        MassProperties.sum([body, neg])
    assert body.__add__(3) is NotImplemented
    with pytest.raises(TypeError):
        _ = 1 + body
