"""Deck fields: numbers rounded to and written in 7-column fields (docs/formats.md section 1)."""

from __future__ import annotations

import math

import numpy as np


# ------------------------------------------------------------------------------------------
# Cards
# ------------------------------------------------------------------------------------------
def _field(value):
    """A real as the text of a 7-column F7.0 field (a leading blank whenever it fits)."""
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"cannot write {v!r} on a card")
    if abs(v) < 5e-6:
        return "0.0"
    for width in (6, 7):
        for decimals in range(5, 0, -1):
            text = f"{v:.{decimals}f}"
            if len(text) <= width:
                return text
        text = f"{v:.0f}."
        if len(text) <= width:
            return text
    raise ValueError(f"{v!r} does not fit a 7-column field")


def _q(values):
    """Values as they read back from their fields: every number is rounded before use."""
    arr = np.asarray(values, dtype=float)
    return np.vectorize(lambda v: float(_field(v)), otypes=[float])(arr) if arr.size else arr


def _cards(values, label):
    """A list of values as 10F7.0 cards (ten to a card, label in columns 73-80)."""
    texts = [_field(v) for v in np.ravel(values)]
    return [f"{''.join(t.rjust(7) for t in texts[i:i + 10]):<72}{label}"
            for i in range(0, len(texts), 10)]
