"""Small shared helpers for model values: read-only arrays and self-validation."""

from __future__ import annotations

import numpy as np

from ..errors import GeometryError

__all__ = ["frozen", "check_finite", "check_increasing"]


def frozen(value, shape=None, component=None, what="array"):
    """Return ``value`` as a read-only float64 array, checking its shape (``None`` = any size)."""
    try:
        arr = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise GeometryError(f"{what} must be numeric", component=component) from None
    if shape is not None:
        ok = arr.ndim == len(shape) and all(s is None or s == a for s, a in zip(shape, arr.shape))
        if not ok:
            want = "(" + ", ".join("n" if s is None else str(s) for s in shape) + ")"
            raise GeometryError(f"{what} must have shape {want}, found {arr.shape}",
                                component=component)
    arr.flags.writeable = False
    return arr


def check_finite(arr, component, what):
    """Raise GeometryError naming the first station (1-based, along axis 0) holding a NaN/inf."""
    bad = ~np.isfinite(arr)
    if bad.any():
        station = int(np.argwhere(bad)[0][0]) + 1
        raise GeometryError(f"{what} is not finite", component=component, station=station)


def check_increasing(values, component, what, strict=True, allow_repeats=False):
    """Raise GeometryError at the first station where ``values`` fails to increase."""
    d = np.diff(values)
    bad = d < 0 if (allow_repeats or not strict) else d <= 0
    if bad.any():
        k = int(np.argmax(bad)) + 1
        rel = "increase" if strict and not allow_repeats else "not decrease"
        raise GeometryError(f"{what} must {rel}: {values[k - 1]:g} then {values[k]:g}",
                            component=component, station=k + 1)
