"""Inline style sheet of the HTML report (:mod:`juncture.plots.report`): nothing fetched."""

from __future__ import annotations

__all__ = ["REPORT_CSS"]

#: The report's whole style sheet, embedded in a ``<style>`` element.
REPORT_CSS = """
:root { --ink: #1d2330; --muted: #5b6475; --rule: #d9dde5; --band: #f3f5f8;
        --accent: #1f5fa8; --warn: #a14a00; }
* { box-sizing: border-box; }
body { margin: 0; font: 14px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans",
       Arial, sans-serif; color: var(--ink); background: #fff; }
header { padding: 14px 24px 10px; border-bottom: 3px solid var(--accent); background: var(--band); }
header h1 { margin: 0 0 4px; font-size: 21px; }
header .meta { color: var(--muted); font-size: 13px; }
header .meta span { margin-right: 18px; }
header code { font-size: 12px; background: #fff; padding: 1px 4px; border: 1px solid var(--rule); }
nav { padding: 6px 24px; border-bottom: 1px solid var(--rule); font-size: 13px; }
nav a { margin-right: 14px; color: var(--accent); text-decoration: none; }
main { padding: 0 24px 40px; max-width: 1400px; }
section { margin-top: 22px; }
h2 { font-size: 17px; margin: 0 0 8px; padding-bottom: 3px; border-bottom: 1px solid var(--rule); }
.keys { display: flex; flex-wrap: wrap; gap: 10px; margin-top: 12px; }
.keys div { background: var(--band); border: 1px solid var(--rule); padding: 6px 12px;
            border-radius: 4px; }
.keys b { display: block; font-size: 16px; }
.keys small { color: var(--muted); }
table { border-collapse: collapse; font-size: 13px; margin: 4px 0 10px; }
th, td { padding: 3px 10px; border-bottom: 1px solid var(--rule); text-align: right;
         white-space: nowrap; }
th { background: var(--band); font-weight: 600; }
td:first-child, th:first-child { text-align: left; }
tr.total td { font-weight: 700; border-top: 2px solid var(--ink); }
td.text, th.text { text-align: left; }
.note { color: var(--muted); font-size: 12px; margin: 2px 0 8px; }
details { margin: 6px 0; }
summary { cursor: pointer; color: var(--accent); }
pre { background: var(--band); border: 1px solid var(--rule); padding: 8px; font-size: 12px;
      overflow-x: auto; white-space: pre-wrap; }
.viewer { position: relative; border: 1px solid var(--rule); }
#jr-canvas { display: block; width: 100%; height: 460px; background: #fbfbfd; cursor: grab;
             touch-action: none; }
.tools { margin: 6px 0; font-size: 13px; }
.tools button { margin-right: 6px; padding: 2px 10px; font: inherit; cursor: pointer; }
.legend { font-size: 12px; color: var(--muted); }
.legend span { display: inline-block; margin-right: 12px; }
.legend i { display: inline-block; width: 18px; height: 4px; margin-right: 4px;
            vertical-align: middle; }
figure { margin: 10px 0 24px; }
figure img { max-width: 100%; border: 1px solid var(--rule); }
figcaption { color: var(--muted); font-size: 13px; }
"""
