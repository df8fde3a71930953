"""The report's "Closed surface" section: the completed airplane as one closed surface.

What ``juncture mesh`` writes (:func:`juncture.mesh`, default sizing): its enclosed volume and
centre of volume (overlaps counted once, unlike the per-component mass table), the wetted
area of each component and in total (caps excluded), and the triangles' quality. Where the
surface does not close, the section says why in one line.
"""

from __future__ import annotations

from .report_html import _e, _num, _section, _table, _u
from .style import unit_label

__all__ = ["closed_surface_section", "closed_surface_key"]


def closed_surface_section(surface, units):
    """(id, heading, HTML) of the section; ``surface`` a SurfaceMesh or the reason it has
    none (str); None: no section."""
    if surface is None:
        return None
    if isinstance(surface, str):
        return _section("surface", "Closed surface",
                        f'<p class="note">No closed surface: {_e(surface)}</p>')
    from ..surface.quality import summarize

    summary = summarize(surface)
    cg = surface.centre_of_volume()
    facts = [["triangles", str(summary.n_triangles)],
             ["vertices", str(summary.n_vertices)],
             [f"enclosed volume{_u(units, 3)}", _num(summary.volume, ".8g")],
             [f"centre of volume{_u(units)}", ", ".join(_num(c) for c in cg)],
             ["every angle >= 20 deg", f"{100 * summary.share_20deg:.1f} %"],
             ["smallest angle [deg]", _num(summary.min_angle, ".3g")]]
    wetted = dict(summary.wetted_area)
    total = wetted.pop("total", sum(wetted.values()))
    rows = [[_e(name), _num(area)] for name, area in wetted.items()]
    note = ('<p class="note">The completed airplane as one closed, checked surface (what '
            "<code>juncture mesh</code> writes): overlaps counted once, fillets included. "
            "Wetted areas exclude the caps that close tips, bases and nacelle ends.</p>")
    return _section("surface", "Closed surface",
                    _table(("quantity", "value"), facts, text_columns=(0, 1))
                    + _table(("component", f"wetted area{_u(units, 2)}"), rows,
                             total=["total", _num(total)]) + note)


def closed_surface_key(surface, units):
    """(value, label) of the key number, or None."""
    if surface is None or isinstance(surface, str):
        return None
    return (f"{_num(surface.volume(), '.5g')} {_e(unit_label(units, 3))}",
            "enclosed volume (overlaps once)")
