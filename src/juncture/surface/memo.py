"""Per-triangle answers kept across the rounds of a re-triangulation.

:func:`juncture.surface.remesh.remesh` triangulates a patch's chart again in every round
that gave it new points, and most of its triangles come out as they were: the same
corners, in the same order, at the same chart and 3-D places. What
:func:`juncture.surface.deviation.deviating` says of such a triangle depends on those alone
(and on the patch, which does not change), so :class:`Memo` keeps it: the rows are keyed
by their exact bits (chart corners, vertex ids, boundary flags), a row's answer is taken
only where its whole key matches, and only the rest is computed. The answers are
bit-identical to computing all.
"""

from __future__ import annotations

import numpy as np

__all__ = ["Memo", "triangle_keys"]

_MIX = np.uint64(0x9E3779B97F4A7C15)


def triangle_keys(pts, gid, local, flags):
    """(k, 10) uint64 rows: the exact bits of each triangle's chart corners (in order), its
    vertex ids and its corners' boundary ``flags`` ((n, 2) bool), packed."""
    corners = np.ascontiguousarray(pts[local].reshape(len(local), 6)).view(np.uint64)
    f = np.packbits(flags[local].reshape(len(local), 6), axis=1, bitorder="little")
    return np.concatenate([corners, gid[local].astype(np.uint64), f.astype(np.uint64)], 1)


def _hash(keys):
    """(k,) uint64 hashes of the rows' ids and flags (the rest is compared, not hashed)."""
    h = np.zeros(len(keys), np.uint64)
    with np.errstate(over="ignore"):
        for column in keys[:, 6:].T:
            h = (h ^ column) * _MIX
            h ^= h >> np.uint64(29)
    return h


class Memo:
    """Boolean answers per key row (:func:`triangle_keys`), kept sorted by hash."""

    def __init__(self):
        self.hash = np.zeros(0, np.uint64)
        self.keys = np.zeros((0, 10), np.uint64)
        self.value = np.zeros(0, bool)

    def get(self, keys):
        """(values (k,) bool, rows not known (m,) int, hashes (k,)): the answers known, False
        elsewhere."""
        h = _hash(keys)
        at = np.minimum(np.searchsorted(self.hash, h), max(len(self.hash) - 1, 0))
        known = np.zeros(len(keys), bool)
        if len(self.hash):
            known = (self.hash[at] == h) & np.all(self.keys[at] == keys, axis=1)
        value = np.zeros(len(keys), bool)
        value[known] = self.value[at[known]]
        return value, np.flatnonzero(~known), h

    def add(self, h, keys, value):
        """Keep the answers ``value`` of the rows ``keys`` (hashes ``h``)."""
        h = np.concatenate([self.hash, h])
        order = np.argsort(h, kind="stable")
        self.hash = h[order]
        self.keys = np.concatenate([self.keys, keys])[order]
        self.value = np.concatenate([self.value, value])[order]
