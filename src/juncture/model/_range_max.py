"""Range maxima of a fixed array in O(1) per query (a sparse table), vectorised.

The bodies bound the slope of their error functions piece by piece; a search along a line
needs the largest bound over the pieces the line's x range spans, for many lines at once.
Level ``k`` of the table holds ``max(values[i : i + 2^k])``; the maximum over ``[ia, ib]`` is
the larger of two overlapping power-of-two windows (Bender & Farach-Colton 2000).
"""

from __future__ import annotations

import numpy as np

__all__ = ["range_max_table", "range_max"]


def range_max_table(values):
    """(levels, n) table of window maxima of ``values`` (n,); rows padded with zeros."""
    values = np.asarray(values, float)
    levels = [values]
    while (1 << len(levels)) <= values.size:
        prev, w = levels[-1], 1 << (len(levels) - 1)
        levels.append(np.maximum(prev[:-w], prev[w:]))
    table = np.zeros((len(levels), values.size))
    for lev, row in enumerate(levels):
        table[lev, :row.size] = row
    return table


def range_max(table, ia, ib):
    """max(values[ia : ib + 1]) for index arrays ``ia <= ib`` (any shape, broadcast)."""
    ia, ib = np.broadcast_arrays(np.asarray(ia, int), np.asarray(ib, int))
    k = np.minimum(np.floor(np.log2(ib - ia + 1)).astype(int), table.shape[0] - 1)
    return np.maximum(table[k, ia], table[k, ib - (1 << k) + 1])
