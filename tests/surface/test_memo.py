"""The re-triangulation's bookkeeping: per-triangle answers kept across rounds
(:mod:`juncture.surface.memo`) and the sorted membership test (:func:`rows.members`),
against plain recomputation and ``np.isin``."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from juncture.surface.memo import Memo, triangle_keys
from juncture.surface.rows import members


@settings(max_examples=100, deadline=None)
@given(st.lists(st.integers(-50, 50), max_size=40), st.lists(st.integers(-50, 50), max_size=40))
def test_members_is_isin(keys, pool):
    keys = np.array(keys, np.int64)
    np.testing.assert_array_equal(members(keys, np.array(pool, np.int64)), np.isin(keys, pool))


@settings(max_examples=50, deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_a_memo_gives_back_exactly_what_was_computed_and_nothing_else(seed):
    rng = np.random.default_rng(seed)
    pts = rng.integers(0, 4, (12, 2)).astype(float)   # few values: many equal corners
    gid = rng.integers(0, 5, 12)
    flags = rng.random((12, 2)) < 0.5
    memo, truth = Memo(), {}
    for _ in range(4):
        local = rng.integers(0, 12, (20, 3))
        keys = triangle_keys(pts, gid, local, flags)
        value, todo, h = memo.get(keys)
        answer = rng.random(len(todo)) < 0.5
        for row, k in zip(keys[todo].tolist(), answer):
            truth.setdefault(tuple(row), bool(k))
        memo.add(h[todo], keys[todo], answer)
        known = np.setdiff1d(np.arange(len(keys)), todo)
        for row, v in zip(keys[known].tolist(), value[known]):
            assert truth[tuple(row)] == v                 # only an exact key is reused
        assert all(tuple(r) in truth for r in keys.tolist())
