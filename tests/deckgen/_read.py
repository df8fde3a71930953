"""Generated deck text into juncture (the one place the tests read it)."""

import tempfile
import warnings
from pathlib import Path

import juncture as jc


def read_text(text, name="deck.inp"):
    """``jc.read`` of deck text through a temporary file; warnings are not errors here."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / name
        path.write_text(text)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return jc.read(path)
