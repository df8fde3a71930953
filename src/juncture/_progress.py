"""A progress bar for the steps of a long command (tqdm), silent when nobody watches.

The bar is drawn on standard error only when it is a terminal and the user did not ask for
quiet output, so logs, pipes and tests see nothing of it. tqdm is imported only when a bar is
actually drawn.
"""

from __future__ import annotations

import sys

__all__ = ["Progress"]


class Progress:
    """Steps of one job: ``with Progress(4, "complete") as p: p.step("intersect"); ...``.

    Parameters
    ----------
    total : int
        Number of steps.
    description : str
        What the whole job is, shown before the bar.
    enabled : bool, optional
        Draw the bar; None (the default): when standard error is a terminal.

    Each :meth:`step` closes the step before it and names the one starting, so the bar
    shows what is running now; leaving the ``with`` block closes the last step.
    """

    def __init__(self, total, description, enabled=None):
        if enabled is None:
            enabled = sys.stderr.isatty()
        self._bar = None
        self._started = False
        if enabled and total > 0:
            from tqdm import tqdm

            self._bar = tqdm(total=total, desc=description, unit="step", leave=False,
                             file=sys.stderr, dynamic_ncols=True,
                             bar_format="{desc}: {n_fmt}/{total_fmt} |{bar}| {elapsed} "
                                        "{postfix}")

    @property
    def enabled(self):
        """Whether a bar is drawn."""
        return self._bar is not None

    def step(self, label):
        """Close the running step (if any) and start the one called ``label``."""
        if self._bar is None:
            return
        if self._started:
            self._bar.update(1)
        self._started = True
        self._bar.set_postfix_str(label)

    def close(self):
        """Close the last step and remove the bar."""
        if self._bar is not None:
            if self._started:
                self._bar.update(1)
            self._bar.close()
            self._bar = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False
