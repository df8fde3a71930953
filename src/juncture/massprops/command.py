"""The work behind ``juncture massprops FILE``: a JSON spec or a component description.

``cli.py`` parses the arguments and prints what :func:`run_massprops` returns; everything else
happens here, so it is tested without the command line.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from ..errors import GeometryError, SpecError
from .configuration import configuration_mass_properties
from .spec import evaluate_spec, format_table, load_spec, spec_report_json

__all__ = ["run_massprops", "is_massprops_spec", "enclosed_mass_properties"]


def is_massprops_spec(path):
    """Whether ``path`` holds a JSON mass-properties spec (not a deck or a juncture model).

    A spec is a JSON object with a ``"components"`` list and no ``"juncture"`` version field
    (which every juncture model file has; both use ``"type": "wing"``). Anything that is not a
    JSON object (a wave-drag deck, LaWGS, TOML) is not a spec.
    """
    try:
        with open(path, "rb") as fh:
            head = fh.read(4096).lstrip()
    except OSError:
        return False
    if not head.startswith(b"{"):
        return False
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return b'"juncture"' not in head and b'"components"' in head   # let load_spec report
    return isinstance(data, dict) and "juncture" not in data and "components" in data


def run_massprops(path, as_json=False, density=None):
    """Mass properties of a JSON spec or of every component of a deck / model, as text.

    Parameters
    ----------
    path : str or path-like
        A mass-properties spec (``docs/massprops-spec.md``: components of type wing, rotor,
        cuboid, cylinder, sphere, point), or anything :func:`juncture.read` turns into a
        Configuration: a wave-drag deck or a juncture model (JSON / TOML).
    as_json : bool
        Return ``{"total": P, "components": [P, ...]}`` as JSON text (P from
        :meth:`MassProperties.to_dict`, with the name) instead of the table of
        :func:`~juncture.massprops.format_table`.
    density : float, optional
        For a deck or model: the one density of every component [mass / deck length^3],
        default 1, so that each "mass" is the component's volume. Not accepted with a spec,
        which gives each component its own density or mass.

    Returns
    -------
    str
        The JSON text or the table, ending with a newline.

    Raises
    ------
    SpecError
        A spec with bad fields, ``density`` with a spec, or a file that describes surfaces
        only (LaWGS, Plot3D: no solid to integrate).
    DeckError
        A deck that cannot be read.
    """
    enclosed = None
    if is_massprops_spec(path):
        if density is not None:
            raise SpecError(f"{path}: a mass-properties spec gives each component its own "
                            "density or mass; a density applies to decks and models only")
        total, parts = evaluate_spec(load_spec(path))
        header = ""
    else:
        from ..io import read

        cfg = read(path)
        if not hasattr(cfg, "components"):
            raise SpecError(f"{path}: describes surface networks ({type(cfg).__name__}), not "
                            "solid components; mass properties need a mass-properties spec, "
                            "a wave-drag deck or a juncture model")
        rho = 1.0 if density is None else density
        try:
            total, parts = configuration_mass_properties(cfg, density=rho)
        except GeometryError as exc:
            raise SpecError(f"{path}: {exc}") from None
        note = " (mass = volume)" if rho == 1.0 else ""
        header = (f"{cfg.title or Path(path).name}: uniform density {rho:g}{note}; "
                  "components integrated as given (overlaps counted in each), mirror images "
                  "included\n")
        enclosed = enclosed_mass_properties(cfg, rho)
    if as_json:
        out = spec_report_json(total, parts)
        if enclosed is not None:
            out["enclosed"] = (enclosed.to_dict() if hasattr(enclosed, "to_dict")
                               else {"unavailable": enclosed})
        return json.dumps(out, indent=2) + "\n"
    return header + format_table(total, parts) + _enclosed_line(enclosed)


def enclosed_mass_properties(cfg, density=1.0):
    """Mass properties of the completed airplane's one closed surface (overlaps counted
    once: a buried wing root is not counted twice), or the one-line reason it has none.

    The configuration is completed (no fillet) and meshed as ``juncture mesh DECK`` meshes it
    (:func:`juncture.mesh`, default sizing, checked), so the two agree; the solid it
    encloses is integrated exactly (:func:`juncture.massprops.surface_mass_properties`).
    """
    import warnings

    from ..completion import complete
    from ..errors import JunctureError, JunctureWarning
    from ..surface.pipeline import mesh

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", JunctureWarning)
            surface = mesh(complete(cfg))
    except JunctureError as exc:
        return str(exc)
    return surface.mass_properties(density).renamed("enclosed solid")


def _enclosed_line(enclosed):
    if enclosed is None:
        return ""
    if isinstance(enclosed, str):
        return f"enclosed solid: none ({enclosed})\n"
    cg = ", ".join(f"{c:.6g}" for c in np.where(np.abs(enclosed.cg) > 1e-9, enclosed.cg, 0.0))
    inertia = ", ".join(f"{enclosed.inertia[i, i]:.6g}" for i in range(3))
    return (f"enclosed solid (the completed airplane as one closed surface, overlaps counted "
            f"once): mass {enclosed.mass:.6g}, volume {enclosed.volume:.6g}, CG {cg}; "
            f"Ixx, Iyy, Izz about the CG {inertia}\n")
