"""The plotting package: public names, no matplotlib until something is drawn, old paths."""

import pytest

import juncture.plots
from tests.test_import_time import loaded_heavy


def test_public_names_resolve():
    for name in juncture.plots.__all__:
        assert callable(getattr(juncture.plots, name)), name
    assert {"plot_views", "plot_planform", "plot_side", "save", "write_figures",
            "write_report", "plot_area_distribution"} <= set(juncture.plots.__all__)
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        juncture.plots.nope  # noqa: B018


def test_importing_the_package_loads_no_matplotlib():
    code = ("import juncture.plots, juncture.analysis\n"
            "from juncture.plots import write_figures, write_report, component_colour\n"
            "component_colour('wing')\n")
    assert "matplotlib" not in loaded_heavy(code)
