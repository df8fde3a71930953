"""What ``import juncture`` and the complete path load (issue 14).

SciPy's ``interpolate`` alone takes about 0.4 s to import and matplotlib as long, against
about 0.1 s for numpy, so neither may be imported by ``import juncture`` nor on the way from a
deck to a completed, written geometry; OCP (the ``cad`` extra) only when a CAD file is
written. Each case runs in a fresh interpreter and reports which of them it loaded. The time
itself is measured, not asserted (it depends on the machine).
"""

import json
import subprocess
import sys

import pytest

from tests.support import EXAMPLE_DECK, ROOT

HEAVY = ("scipy", "matplotlib", "OCP")

_REPORT = ("\nimport json, sys\n"
           f"heavy = {HEAVY!r}\n"
           "print(json.dumps(sorted({m.split('.')[0] for m in sys.modules} & set(heavy))))\n")


def loaded_heavy(code):
    """Run ``code`` in a fresh interpreter; return the heavy top-level packages it loaded."""
    out = subprocess.run([sys.executable, "-c", code + _REPORT], cwd=ROOT, capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_import_juncture_loads_no_scipy_matplotlib_or_ocp():
    code = ("import juncture\n"
            "for name in juncture.__all__:\n"
            "    getattr(juncture, name)\n")  # also the names a lazy __init__ defers
    assert loaded_heavy(code) == []


@pytest.mark.parametrize("module", ["juncture.model", "juncture.completion", "juncture.massprops"])
def test_subpackages_load_no_scipy_at_import(module):
    assert loaded_heavy(f"import {module}\n") == []


@pytest.mark.parametrize(("fillet", "keep_area"), [(None, False), ("cubic", False),
                                                   ("cubic", True)])
def test_complete_path_loads_no_scipy_or_matplotlib(tmp_path, fillet, keep_area):
    code = (f"import juncture as jc\n"
            f"cfg = jc.read({str(EXAMPLE_DECK)!r})\n"
            f"geo = jc.complete(cfg, fillet={fillet!r}, keep_area={keep_area!r})\n"
            f"jc.write(geo, {str(tmp_path / 'out.wgs')!r})\n")
    assert loaded_heavy(code) == []
    assert (tmp_path / "out.wgs").stat().st_size > 0
