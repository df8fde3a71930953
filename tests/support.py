"""Shared test references: sample files from ../shared/data and the bundled example."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "data"
PDAS_DECK = SHARED / "wavedrag" / "pdas_wdcase1_wing_3segment_circular_body.inp"
PDAS_WGS = SHARED / "lawgs" / "pdas_wdcase1_wd2wgs_output.wgs"
LAWGS_DIR = SHARED / "lawgs"
EXAMPLE_DECK = ROOT / "examples" / "supersonic_transport.inp"
