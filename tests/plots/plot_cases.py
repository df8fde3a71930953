"""Configurations the figure tests draw: the bundled transport, and variants of it that
figures must survive (an arbitrary-section fuselage, components with other names, no wing).

Module constants and small builders only; each test completes what it needs.
"""

import warnings
from dataclasses import replace

import numpy as np

import juncture as jc
from tests.support import EXAMPLE_DECK

#: Components of the renamed transport: input name -> name in the variant.
RENAMED = {"body": "fuselage", "wing": "main wing"}


def example():
    """The bundled supersonic transport (deck warnings silenced)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(EXAMPLE_DECK)


def squashed(cfg):
    """``cfg`` with its fuselage as arbitrary (elliptic, 1.15 wide x 0.9 high) half-sections,
    the deck's J2 = +1 body: an ArbitraryBody, which has no ``radius``."""
    from juncture.model import ArbitraryBody

    b = cfg["body"]
    th = np.linspace(-np.pi / 2, np.pi / 2, 13)
    secs = [np.stack([1.15 * r * np.cos(th), zc + 0.9 * r * np.sin(th)], 1)
            for r, zc in zip(b.radius, b.camber)]
    return cfg.with_component(ArbitraryBody("body", b.x, secs, segments=b.segments))


def renamed(cfg):
    """``cfg`` with the wing called "main wing" and the body "fuselage" (see RENAMED)."""
    comps = {RENAMED.get(c.name, c.name): replace(c, name=RENAMED.get(c.name, c.name))
             for c in cfg}
    return cfg.replace(components=comps)


def without_wing(cfg):
    """``cfg`` less its wing and the fins standing on it: fuselage, pods and tail."""
    return cfg.replace(components={c.name: c for c in cfg
                                   if c.name != "wing" and c.name not in ("fin 1", "fin 2")})
