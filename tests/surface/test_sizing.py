"""Graded sizing (issue 12): finer at the intersection lines, growing no faster than asked.

Oracles: the distance of every triangle from the lines where components meet, measured on
juncture's intersection points joined by straight lines (not on the mesh), and the
assembled surface's seam pieces, measured here by brute force (every source, not the size
field's k-d tree of nearest ones).
"""

import warnings

import numpy as np
import pytest
from scipy.spatial import cKDTree

import juncture as jc
from juncture.surface.assemble import assemble
from juncture.surface.sizing import SLACK, SizeField
from tests.support import PDAS_DECK


@pytest.fixture(scope="module")
def wing_body():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.complete(jc.read(PDAS_DECK))


def _lines(geo):
    """Points every 1/50 of each piece of juncture's intersection lines, both halves."""
    out = []
    for pts in geo.intersections.values():
        p = np.asarray(pts, float)
        p = p[np.all(np.isfinite(p), axis=1)]
        f = np.linspace(0.0, 1.0, 50)[:, None, None]
        dense = (p[:-1][None] * (1 - f) + p[1:][None] * f).reshape(-1, 3)
        out += [dense, dense * [1.0, -1.0, 1.0]]
    return np.concatenate(out)


def _longest(surface):
    p = surface.vertices[surface.triangles]
    return np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2).max(axis=1), p.mean(axis=1)


def test_triangles_are_seam_size_at_the_junction_and_grow_from_it(wing_body):
    h, g = 0.5, 1.25
    plain = jc.mesh(wing_body)
    graded = jc.mesh(wing_body, seam_size=h, growth=g)
    d_plain = cKDTree(_lines(wing_body)).query(_longest(plain)[1])[0]
    longest, centre = _longest(graded)
    d = cKDTree(_lines(wing_body)).query(centre)[0]
    near = d < h
    assert 0.8 * h < np.median(longest[near]) < 1.2 * h
    zone = 2.0 * h                                     # where the default is coarser
    assert np.median(longest[d < zone]) < 0.75 * np.median(_longest(plain)[0][d_plain < zone])
    bound = SLACK * (h + (g - 1.0) * d)
    assert np.mean(longest > bound) < 1e-3 and np.max(longest / bound) < 1.5
    assert graded.volume() > plain.volume()            # finer: nearer the model's


def test_growth_alone_grades_from_the_seams_finest_pieces(wing_body):
    g = 1.2
    graded = jc.mesh(wing_body, growth=g)
    mesh = assemble(wing_body)
    t, v = mesh.triangles, mesh.vertices
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    s = np.tile(mesh.surface, 3)
    pieces = {}
    for (a, b), k in zip(e.tolist(), s.tolist()):
        pieces.setdefault((a, b), set()).add(k)
    uses = {}
    for a, b in e.tolist():
        uses[(a, b)] = uses.get((a, b), 0) + 1
    seams = np.array([ab for ab, ks in pieces.items() if len(ks) > 1 or uses[ab] != 2])
    h = np.full(len(v), np.inf)
    length = np.linalg.norm(v[seams[:, 0]] - v[seams[:, 1]], axis=1)
    np.minimum.at(h, seams[:, 0], length)
    np.minimum.at(h, seams[:, 1], length)
    src = np.isfinite(h)
    longest, centre = _longest(graded)
    bound = np.full(len(centre), np.inf)
    for q, hq in zip(v[src], h[src]):                 # every source, by brute force
        bound = np.minimum(bound, hq + (g - 1.0) * np.linalg.norm(centre - q, axis=1))
    over = longest > SLACK * bound
    assert np.mean(over) < 2e-3
    plain = _longest(jc.mesh(wing_body))[0]
    assert np.percentile(longest, 99) < np.percentile(plain, 99)


def test_the_field_is_the_smallest_source_plus_growth():
    pts = np.array([[0.0, 0.0, 0.0], [10.0, 0.0, 0.0]])
    field = SizeField(pts, [0.1, 2.0], 1.5, cap=3.0)
    q = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [10.0, 0.0, 0.0], [5.0, 40.0, 0.0]])
    np.testing.assert_allclose(field(q), [0.1, 1.1, 2.0, 3.0])
