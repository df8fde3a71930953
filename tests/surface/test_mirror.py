"""Both halves re-triangulated once (juncture.surface.mirror)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import juncture as jc
import juncture.surface.remesh as rm
from juncture.surface.assemble import assemble
from juncture.surface.check import check_mesh
from juncture.surface.mirror import mirror_map
from tests.support import EXAMPLE_DECK


@settings(max_examples=50, deadline=None)
@given(st.integers(1, 40), st.integers(0, 10), st.integers(0, 10), st.integers(0, 2**31))
def test_every_vertex_finds_the_vertex_at_its_mirror_image(pairs, on_plane, lone, seed):
    """Hypothesis: points at y > 0 with their images at -y (bit for bit), points on the plane
    (y = 0, some given as -0.0), and points whose image is not there, shuffled: each is
    matched with its image, itself on the plane, -1 without (checked point by point here)."""
    rng = np.random.default_rng(seed)
    up = rng.normal(size=(pairs, 3))
    up[:, 1] = np.abs(up[:, 1]) + 1e-3
    plane = rng.normal(size=(on_plane, 3))
    plane[:, 1] = np.where(rng.random(on_plane) < 0.5, 0.0, -0.0)
    alone = rng.normal(size=(lone, 3))
    alone[:, 1] = np.abs(alone[:, 1]) + 2.0
    pts = np.concatenate([up, up * [1.0, -1.0, 1.0], plane, alone])
    order = rng.permutation(len(pts))
    pts = pts[order]
    m = mirror_map(pts)
    for i, p in enumerate(pts):
        hits = np.flatnonzero(np.all(pts == p * [1.0, -1.0, 1.0], axis=1))
        assert m[i] == (hits[0] if len(hits) else -1)


def _by_coordinates(surface, name):
    """The triangles of surface ``name`` as a set of corner-coordinate triples, each
    rotated to start at its smallest corner (orientation kept)."""
    rows = surface.surface == surface.surfaces.index(name)
    out = set()
    for t in surface.vertices[surface.triangles[rows]].tolist():
        k = min(range(3), key=lambda i: t[i])
        out.add(tuple(tuple(c) for c in t[k:] + t[:k]))
    return out


def test_the_transport_s_halves_are_mirror_images_triangle_for_triangle():
    """On the bundled transport every surface with an image comes out as the image of its
    own triangles: each triangle of "X image" is a triangle of X with y negated and its
    corners reversed (outward normals), bit for bit; the surface passes every check."""
    geo = jc.complete(jc.read(EXAMPLE_DECK))
    surface = jc.mesh(geo)
    assert check_mesh(surface.vertices, surface.triangles).ok
    images = [n for n in surface.surfaces if n.endswith(" image")]
    assert len(images) >= 10
    for name in images:
        mine = _by_coordinates(surface, name[:-6])
        theirs = set()
        for t in _by_coordinates(surface, name):
            flipped = [(x, -y + 0.0, z) for x, y, z in (t[0], t[2], t[1])]
            k = min(range(3), key=lambda i: flipped[i])
            theirs.add(tuple(flipped[k:] + flipped[:k]))
        mine = {tuple((x, y + 0.0, z) for x, y, z in t) for t in mine}
        assert theirs == mine, name


@pytest.mark.slow  # the transport re-triangulated twice (~10 s): make test-all
def test_copying_the_image_halves_the_triangulations(monkeypatch):
    """The charts triangulated with both halves matched are about half of those without
    (only the y > 0 side's and those that straddle the plane), counted by the calls to
    the triangulation."""
    surface = assemble(jc.complete(jc.read(EXAMPLE_DECK)))
    calls = []
    once = rm._triangulate_once

    def counted(patch, *args):
        calls.append(patch.surface)
        return once(patch, *args)

    monkeypatch.setattr(rm, "_triangulate_once", counted)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rm.remesh(surface)
        matched = len(calls)
        monkeypatch.setattr(rm, "MIRROR", False)
        calls.clear()
        rm.remesh(surface)
    names = [surface.surfaces[s] for s in set(calls)]
    assert any(n.endswith(" image") for n in names)
    assert matched < 0.6 * len(calls)


def _dented(surface, vertex, depth, both):
    """``surface``'s vertices with ``vertex`` pushed down by ``depth`` times the surface's
    size (and its mirror image with it, with ``both``)."""
    v = np.array(surface.vertices, float)
    m = mirror_map(v)
    push = np.array([0.0, 0.0, -depth * np.ptp(v, axis=0).max()])
    v[vertex] += push
    if both and m[vertex] != vertex:
        v[m[vertex]] += push
    return v


@settings(max_examples=1, deadline=None)
@given(st.integers(0, 2**31), st.booleans(), st.floats(0.02, 0.05))
def test_the_mirrored_search_finds_every_crossing_pair(seed, both, depth):
    """Hypothesis: a wing-body meshed with both halves matched; a vertex of the wing's upper
    surface where it is thickest (on the y < 0 side alone, or on the y > 0 side with its
    mirror image) pushed down through the lower one. The crossing pairs the search on the
    y >= 0 side finds, with their images, are those the search of every pair finds
    (check.MIRROR_SHARE < 0 searches every pair), and there are some. (1 draw here, 40 in
    the slow profile.)"""
    _assert_mirrored_search_finds_every_pair(seed, both, depth)


@pytest.mark.slow
@settings(max_examples=40, deadline=None)
@given(st.integers(0, 2**31), st.booleans(), st.floats(0.02, 0.05))
def test_slow_the_mirrored_search_finds_every_crossing_pair(seed, both, depth):
    _assert_mirrored_search_finds_every_pair(seed, both, depth)


def _assert_mirrored_search_finds_every_pair(seed, both, depth):
    import juncture.surface.check as ck
    from tests.support import wing_body

    surface = _mesh_of(wing_body(z_root=-1.0))
    name = "wing-body upper" if both else "wing-body upper image"
    rows = surface.surface == surface.surfaces.index(name)
    ids = np.unique(surface.triangles[rows])
    inner = ids[np.abs(surface.vertices[ids, 1]) > 6.0]  # out on the wing
    thick = inner[np.argsort(surface.vertices[inner, 2])[-20:]]   # where it is thickest
    vertex = int(np.random.default_rng(seed).choice(thick))
    v = _dented(surface, vertex, depth, both)
    found = ck.self_intersections(v, surface.triangles)
    old = ck.MIRROR_SHARE
    ck.MIRROR_SHARE = -1.0
    try:
        every = ck.self_intersections(v, surface.triangles)
    finally:
        ck.MIRROR_SHARE = old
    assert len(every)
    assert np.array_equal(np.unique(np.sort(found, 1), axis=0),
                          np.unique(np.sort(every, 1), axis=0))


_MESHES = {}


def _mesh_of(cfg):
    """jc.mesh of ``cfg``, made once per title."""
    if cfg.title not in _MESHES:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            _MESHES[cfg.title] = jc.mesh(jc.complete(cfg))
    return _MESHES[cfg.title]
