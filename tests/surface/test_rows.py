"""unique_pairs and unique_points against numpy's own np.unique(axis=0)."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from juncture.surface.rows import unique_pairs, unique_points


def _same(got, want):
    assert len(got) == len(want)
    for g, w in zip(got, want):
        np.testing.assert_array_equal(g, np.asarray(w).reshape(np.shape(g)))


@settings(max_examples=60, deadline=None)
@given(arrays(np.int64, st.tuples(st.integers(0, 40), st.just(2)),
              elements=st.integers(-5, 9)))
def test_pairs_are_numpy_s_unique_rows(pairs):
    flags = dict(return_index=True, return_inverse=True, return_counts=True)
    _same(unique_pairs(pairs, **flags), np.unique(pairs, axis=0, **flags))
    np.testing.assert_array_equal(unique_pairs(pairs), np.unique(pairs, axis=0))


def test_pairs_too_wide_to_pack_fall_back_to_numpy():
    pairs = np.array([[0, 1 << 40], [1 << 40, 0], [0, 1 << 40]], np.int64)
    rows, inverse = unique_pairs(pairs, return_inverse=True)
    np.testing.assert_array_equal(rows, [[0, 1 << 40], [1 << 40, 0]])
    np.testing.assert_array_equal(inverse, [0, 1, 0])


@settings(max_examples=60, deadline=None)
@given(arrays(np.float64, st.tuples(st.integers(0, 40), st.just(3)),
              elements=st.sampled_from([-1.5, -0.0, 0.0, 0.25, 2.0, 1e300])))
def test_points_are_numpy_s_unique_rows(points):
    flags = dict(return_index=True, return_inverse=True, return_counts=True)
    points = points + 0.0                                  # numpy tells -0.0 from 0.0 apart
    _same(unique_points(points, **flags), np.unique(points, axis=0, **flags))
