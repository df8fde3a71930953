"""Small HTML helpers of the report: escaping, numbers, tables, sections, unit labels."""

from __future__ import annotations

import html

import numpy as np

from .style import unit_label

__all__ = ["_e", "_num", "_table", "_section", "_u"]


def _e(text):
    return html.escape(str(text), quote=True)


def _num(value, fmt=".6g"):
    if value is None:
        return "&ndash;"
    v = float(value)
    return format(v, fmt) if np.isfinite(v) else _e(v)


def _table(headers, rows, total=None, text_columns=(0,)):
    """An HTML table; ``rows`` hold already-escaped cell strings."""
    head = "".join(f'<th class="text">{_e(h)}</th>' if i and i in text_columns
                   else f"<th>{_e(h)}</th>" for i, h in enumerate(headers))
    body = []
    for row in list(rows) + ([total] if total else []):
        cells = "".join(f'<td class="text">{c}</td>' if i and i in text_columns
                        else f"<td>{c}</td>" for i, c in enumerate(row))
        body.append(f'<tr class="total">{cells}</tr>' if row is total else f"<tr>{cells}</tr>")
    return f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def _section(ident, heading, body):
    """(id, heading, HTML) of one report section."""
    return ident, heading, f'<section id="{ident}"><h2>{_e(heading)}</h2>{body}</section>'


def _u(units, power=1):
    """`` [unit]`` for a table heading (nothing for a ratio)."""
    return f" [{unit_label(units, power)}]" if power else ""
