"""Generated blend specs for the tests (body radius, sweep, wing position, strake length...).

Each case scales a missile whose wing chord is 4 body radii; the named variations change one
or two things at a time so a failure points at its cause.
"""

from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "missile_blend.json"
BUNDLED = ROOT / "src" / "juncture" / "data" / "missile_blend.json"


def make_spec(radius=1.0, sweep=35.0, x_le=6.0, strake_length=None, z=0.0, thickness=0.08,
              elements=12, section=None, lines=None):
    """A blend spec dict; lengths scale with ``radius`` except explicit ones."""
    spec = {
        "title": "generated",
        "body": {"radius": radius},
        "wing": {"root_chord": 4.0 * radius, "tip_chord": 1.6 * radius,
                 "x_le_root": x_le * radius, "sweep_le_deg": sweep,
                 "semi_span": 5.5 * radius, "z": z * radius, "thickness": thickness},
        "lines": {"strake_length": strake_length},
        "patch": {"elements": elements},
        "output": {"figures": False, "formats": []},
    }
    if section is not None:
        spec["body"] = {"section": section}
    if lines:
        spec["lines"].update(lines)
    return spec


def ellipse(a=1.3, b=0.8, n=48):
    """Closed (y, z) points of an ellipse, angle increasing from y > 0 over the top."""
    th = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    return np.c_[a * np.cos(th), b * np.sin(th)].tolist()


#: (id, kwargs) of generated cases, none of them the bundled example.
CASES = [
    ("small-radius", {"radius": 0.5}),
    ("large-radius-unswept", {"radius": 2.5, "sweep": 0.0}),
    ("high-sweep-aft-wing", {"sweep": 55.0, "x_le": 9.0}),
    ("short-strake-forward-wing", {"strake_length": 2.0, "x_le": 3.0}),
    ("raised-wing-thick", {"z": 0.2, "thickness": 0.12}),
    ("elliptic-body", {"section": ellipse()}),
]
