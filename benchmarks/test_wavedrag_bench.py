"""Benchmark: far-field wave drag of the full bundled transport, 100 cuts x 16 roll angles.

Run with ``make bench`` (``pytest benchmarks --benchmark-only``); no time is asserted. Both
cases are in the group ``"wavedrag transport M 1.6"``, so one run shows before and after:

* ``after``: ``wavedrag(cfg, mach=1.6, n_x=100, n_theta=16)`` as it is now: Harris NTHETA 16
  (17 angles over a half turn, Boole's rule), each equivalent body solved with the
  closed-form infinite-mode kernel (an m x m Cholesky factorisation and substitutions, no
  threaded LAPACK), the triangles' vertex heights as whole-array operations, and no normal
  areas integrated from the model.
* ``before``: the work the previous code did, rebuilt from functions that still exist: the
  model's normal-area distribution (computed although only a Mach number was asked for),
  16 angles over a full turn, and a 100 x 800 singular value decomposition per roll angle
  (``n_modes = max(400, 8 m)``); its cuts already use the faster vertex heights, so it
  understates the old time.

Measured on the development machine (2 shared cores, load 2-3) with the previous commit
(1489da4) against this code, best of 5, in alternating processes:

=========================================  ========  ============
                                           before    after
=========================================  ========  ============
default BLAS threading                     1.9-3.8 s  0.21 s
``OPENBLAS_NUM_THREADS=1``                 0.78 s    0.20-0.25 s
=========================================  ========  ============
"""

import numpy as np
import pytest

import juncture as jc
from juncture.analysis import (
    far_field_drag,
    mach_plane_area_distribution,
    normal_area_distribution,
    wavedrag,
)
from juncture.analysis.areas import default_stations
from support import EXAMPLE_DECK

GROUP = "wavedrag transport M 1.6"


@pytest.fixture(scope="module")
def transport():
    return jc.read(EXAMPLE_DECK)


def _before(cfg):
    x = default_stations(cfg, 100)
    normal_area_distribution(cfg, x)
    cuts = mach_plane_area_distribution(cfg, 1.6, n_x=100, n_theta=16)
    return far_field_drag(cuts["area"], cuts["x"], cuts["thetas"], n_modes=800)


@pytest.mark.benchmark(group=GROUP)
def test_after(benchmark, transport):
    r = benchmark(wavedrag, transport, 1.6, 100, 16)
    assert len(r["thetas"]) == 17 and np.isfinite(r["D_over_q"]) and r["D_over_q"] > 0.0


@pytest.mark.benchmark(group=GROUP)
def test_before(benchmark, transport):
    ff = benchmark.pedantic(_before, args=(transport,), rounds=3, iterations=1)
    assert ff.thetas.size == 16 and ff.d_over_q > 0.0
