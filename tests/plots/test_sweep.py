"""Sweep figures and report: what is plotted is exactly the ok cases, categories label their
axes, figures are real PNGs, and the report states the right counts, minima and errors."""

import base64
import math
import subprocess
import sys
from html.parser import HTMLParser

import numpy as np
import pytest

from juncture.errors import JunctureError
from juncture.plots._backend import pyplot

pd = pytest.importorskip("pandas")

from juncture.plots.sweep import (  # noqa: E402
    drag_columns,
    plot_against_parameters,
    plot_scatter_matrix,
    render_sweep_report,
    write_sweep_figures,
    write_sweep_report,
)

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
PARAMETERS = ["wing_z", "sweep", "fillet"]
MACHS = (1.6, 2.0)
SCRIPT = "<script>alert('x')</script> fillet & blend failed"
# case -> error message (7 errors, 33 ok cases)
ERRORS = {3: "wing misses the body", 11: "wing misses the body", 25: "wing misses the body",
          33: "wing misses the body", 17: SCRIPT, 26: SCRIPT, 38: "timeout"}


def dq(wing_z, sweep, fillet, mach):
    """A known wave drag: least near wing_z = mach - 1.75, sweep = 70 - 15 mach, cubic fillet
    (another case at each Mach number)."""
    return (0.5 + (wing_z - mach + 1.75) ** 2 + 1e-3 * (sweep - 70 + 15 * mach) ** 2
            - (0.05 if fillet == "cubic" else 0.0)) / mach


def volume(wing_z, sweep, fillet):
    return 100.0 + 10.0 * wing_z + sweep / 10.0 + (2.0 if fillet == "cubic" else 0.0)


def inputs():
    """The 40 cases' parameters, in case order: 5 wing_z x 4 sweep x 2 fillet."""
    return [(z, s, f) for z in (-0.4, -0.2, 0.0, 0.2, 0.4) for s in (30.0, 40.0, 50.0, 60.0)
            for f in ("none", "cubic")]


def frame(errors=ERRORS, finite_errors=False):
    """Sweep results; error rows hold NaN results (or, ``finite_errors``, outliers 999)."""
    rows = []
    for case, (z, s, f) in enumerate(inputs()):
        bad = case in errors
        nan = 999.0 if finite_errors else math.nan
        row = {"case": case, "key": f"{case * 2654435761 % 2**32:08x}", "wing_z": z,
               "sweep": s, "fillet": f, "status": "error" if bad else "ok",
               "error": errors.get(case, ""), "error_type": "JunctureError" if bad else "",
               "wall_time": 0.5 + 0.01 * case, "volume": nan if bad else volume(z, s, f),
               "wetted_area": nan if bad else 50.0 + z, "n_panels": 100 + case}
        for mach in reversed(MACHS):  # columns out of Mach order on purpose
            d = nan if bad else dq(z, s, f, mach)
            row[f"D_over_q_M{mach:g}"] = d
            row[f"CD_M{mach:g}"] = d / 2.5
        rows.append(row)
    return pd.DataFrame(rows)


def ok_rows():
    return [(case, p) for case, p in enumerate(inputs()) if case not in ERRORS]


def offsets(ax):
    """Every scatter point of an axes, as a sorted list of (x, y)."""
    return sorted(tuple(map(float, xy)) for c in ax.collections for xy in c.get_offsets())


@pytest.fixture(scope="module")
def df():
    return frame()


@pytest.fixture(scope="module")
def written(df, tmp_path_factory):
    out = tmp_path_factory.mktemp("sweep")
    paths = write_sweep_figures(df, PARAMETERS, out / "figures")
    spec = "[sweep]\nwing_z = [-0.4, 0.4]  # a < b & c"
    report = write_sweep_report(df, PARAMETERS, out / "report.html", figures=paths,
                                title="wing <height> study", spec_text=spec)
    text = report.read_text(encoding="utf-8")
    return {"paths": paths, "report": report, "text": text, "page": Page(text), "spec": spec}


@pytest.fixture
def close_figures():
    yield
    pyplot().close("all")


class Page(HTMLParser):
    """Tags, section tables (rows of cell text), key numbers and <pre> text of a page."""

    def __init__(self, text):
        super().__init__(convert_charrefs=True)
        self.tags, self.tables, self.keys, self.pre = [], {}, {}, ""
        self.section = self.row = self.cell = self.key = None
        self.in_pre = False
        self.feed(text)
        self.close()

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        if tag == "section":
            self.section = dict(attrs)["id"]
        elif tag == "tr":
            self.row = []
        elif tag in ("td", "th"):
            self.cell = ""
        elif tag in ("b", "small"):
            self.key = [tag, ""]
        elif tag == "pre":
            self.in_pre = True

    def handle_endtag(self, tag):
        if tag in ("td", "th"):
            self.row.append(self.cell)
            self.cell = None
        elif tag == "tr":
            self.tables.setdefault(self.section, []).append(self.row)
        elif tag == "b":
            self.value = self.key[1]
        elif tag == "small":
            self.keys[self.key[1]] = self.value
        elif tag == "pre":
            self.in_pre = False

    def handle_data(self, data):
        if self.cell is not None:
            self.cell += data
        if self.key is not None:
            self.key[1] += data
        if self.in_pre:
            self.pre += data


# ------------------------------------------------------------------ columns
def test_drag_columns_sorted_by_mach_and_only_d_over_q():
    cols = ["case", "D_over_q_M2", "CD_M2", "D_over_q_M1.6", "D_over_q_M10", "D_over_q_Mx",
            "D_over_q_M0.95"]
    assert drag_columns(pd.DataFrame(columns=cols)) == [
        (0.95, "D_over_q_M0.95"), (1.6, "D_over_q_M1.6"), (2.0, "D_over_q_M2"),
        (10.0, "D_over_q_M10")]
    assert drag_columns(pd.DataFrame(columns=["case", "volume"])) == []


# ------------------------------------------------------------------ against parameters
def test_drag_against_parameters_plots_exactly_the_ok_cases(df, close_figures):
    fig = plot_against_parameters(df, PARAMETERS, "drag")
    assert [ax.get_label() for ax in fig.axes] == PARAMETERS
    ax = fig.axes[0]
    assert ax.get_xlabel() == "wing_z" and ax.get_ylabel() == "D/q [ft²]"
    assert [c.get_label() for c in ax.collections] == ["M 1.6", "M 2"]
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["M 1.6", "M 2"]
    for coll, mach in zip(ax.collections, MACHS):
        got = sorted(tuple(map(float, xy)) for xy in coll.get_offsets())
        want = sorted((p[0], dq(*p, mach)) for _, p in ok_rows())
        np.testing.assert_allclose(got, want, rtol=1e-12)
    # The line of means per distinct wing_z value, over ok cases only.
    line = ax.get_lines()[0]
    zs = sorted({p[0] for _, p in ok_rows()})
    means = [np.mean([dq(*p, 1.6) for _, p in ok_rows() if p[0] == z]) for z in zs]
    np.testing.assert_allclose(line.get_xdata(), zs)
    np.testing.assert_allclose(line.get_ydata(), means, rtol=1e-12)


def test_categorical_parameter_is_labelled_with_its_categories(df, close_figures):
    ax = plot_against_parameters(df, PARAMETERS, "volume").axes[2]
    labels = [t.get_text() for t in ax.get_xticklabels()]
    assert labels == sorted({"none", "cubic"})
    assert list(ax.get_xticks()) == [0, 1]
    want = sorted((float(labels.index(p[2])), volume(*p)) for _, p in ok_rows())
    np.testing.assert_allclose(offsets(ax), want, rtol=1e-12)
    assert ax.get_xlabel() == "fillet" and ax.get_ylabel() == "volume [ft³]"


def test_units_label_and_grid_of_axes(df, close_figures):
    fig = plot_against_parameters(df, ["wing_z", "sweep", "fillet", "wing_z"], "volume",
                                  units="m")
    assert len(fig.axes) == 4  # a 2 x 3 grid less its two empty places
    assert {ax.get_ylabel() for ax in fig.axes} == {"volume [m³]"}
    assert all(len(ax.collections) == 1 for ax in fig.axes)
    assert fig.axes[0].get_legend() is None  # one series: no legend


def test_bad_quantity_parameter_or_missing_drag_raise(df, close_figures):
    with pytest.raises(JunctureError, match="quantity"):
        plot_against_parameters(df, PARAMETERS, "lift")
    with pytest.raises(JunctureError, match="'span'"):
        plot_against_parameters(df, ["span"], "drag")
    with pytest.raises(JunctureError, match="D_over_q"):
        plot_against_parameters(df.drop(columns=["D_over_q_M1.6", "D_over_q_M2"]),
                                PARAMETERS, "drag")


def test_error_rows_are_never_plotted(close_figures):
    bad = frame(finite_errors=True)  # error rows hold 999 everywhere: must not show
    figs = [plot_against_parameters(bad, PARAMETERS, "drag"),
            plot_against_parameters(bad, PARAMETERS, "volume"),
            plot_scatter_matrix(bad, PARAMETERS)]
    points = [xy for fig in figs for ax in fig.axes for xy in offsets(ax)]
    assert points and not any(999.0 in xy for xy in points)
    assert len(offsets(figs[0].axes[0])) == 2 * len(ok_rows())


# ------------------------------------------------------------------ scatter matrix
def test_scatter_matrix_axes_colours_and_histograms(df, close_figures):
    fig = plot_scatter_matrix(df, PARAMETERS)
    n = 5  # wing_z, sweep, D/q at two Mach numbers, volume (fillet colours the points)
    assert len(fig.axes) == n * n
    grid = np.array(fig.axes).reshape(n, n)
    assert all(not grid[i, j].axison for i in range(n) for j in range(n) if j > i)
    assert grid[-1, 0].get_xlabel() == "wing_z" and grid[-1, 2].get_xlabel() == "D/q M1.6 [ft²]"
    assert grid[-1, 0].get_ylabel() == "volume [ft³]"
    # Lower triangle: one scatter per category, together the ok cases' pairs.
    want = sorted((dq(*p, 2.0), volume(*p)) for _, p in ok_rows())  # row: volume, column: M2
    np.testing.assert_allclose(offsets(grid[4, 3]), want, rtol=1e-12)
    assert len(grid[1, 0].collections) == 2
    colours = {tuple(c.get_facecolor()[0]) for c in grid[1, 0].collections}
    assert len(colours) == 2
    # Diagonal: the stacked histogram counts every ok case once.
    assert sum(p.get_height() for p in grid[0, 0].patches) == len(ok_rows())
    legend = next(ax.get_legend() for ax in fig.axes if ax.get_legend() is not None)
    assert [t.get_text() for t in legend.get_texts()] == ["cubic", "none"]
    assert legend.get_title().get_text() == "fillet"


def test_scatter_matrix_keeps_ten_variables_and_says_so(close_figures):
    rng = np.random.default_rng(1)
    wide = pd.DataFrame(rng.normal(size=(12, 12)), columns=[f"p{k}" for k in range(12)])
    wide["status"] = "ok"
    fig = plot_scatter_matrix(wide, list(wide.columns[:12]))
    assert len(fig.axes) == 100
    assert "first 10 of 12" in fig.get_suptitle()


# ------------------------------------------------------------------ files
def test_written_figures_are_real_pngs(written):
    from matplotlib.image import imread

    names = [p.name for p in written["paths"]]
    assert names == ["drag_vs_parameters.png", "volume_vs_parameters.png", "scatter_matrix.png"]
    for path in written["paths"]:
        assert path.read_bytes()[:8] == PNG_MAGIC
        image = imread(path)
        assert image.ndim == 3 and image.shape[0] > 300 and image.shape[1] > 500
        assert image[..., :3].std() > 0.05  # not a blank page


def test_no_figures_without_ok_cases_and_no_drag_figure_without_drag(tmp_path):
    failed = frame(errors={case: "boom" for case in range(40)})
    assert write_sweep_figures(failed, PARAMETERS, tmp_path / "none") == []
    assert not (tmp_path / "none").exists()
    no_drag = frame().drop(columns=["D_over_q_M1.6", "D_over_q_M2"])
    paths = write_sweep_figures(no_drag, PARAMETERS, tmp_path / "some")
    assert [p.name for p in paths] == ["volume_vs_parameters.png", "scatter_matrix.png"]
    assert sorted(p.name for p in (tmp_path / "some").iterdir()) == sorted(
        p.name for p in paths)


# ------------------------------------------------------------------ report
def test_report_counts_title_and_no_external_resources(written):
    page, text = written["page"], written["text"]
    assert text.startswith("<!DOCTYPE html>")
    assert page.keys["cases"] == "40" and page.keys["ok"] == "33" and page.keys["error"] == "7"
    assert "wing &lt;height&gt; study" in text and "<height>" not in text
    from juncture import __version__

    assert f"juncture {__version__}" in text
    assert not any(t in ("script", "link", "iframe") for t, _ in page.tags)
    assert "http://" not in text and "https://" not in text


def test_report_embeds_each_figure_file(written):
    srcs = [a["src"] for t, a in written["page"].tags if t == "img"]
    prefix = "data:image/png;base64,"
    assert len(srcs) == len(written["paths"]) == 3
    for src, path in zip(srcs, written["paths"]):
        assert src.startswith(prefix)
        assert base64.b64decode(src[len(prefix):]) == path.read_bytes()


def test_report_names_the_least_drag_case_per_mach(written):
    head, *rows = written["page"].tables["minimum"]
    assert head[:4] == ["Mach", "least D/q [ft²]", "CD", "case"] and head[4:] == PARAMETERS
    assert [r[0] for r in rows] == ["1.6", "2"] and rows[0][3] != rows[1][3]
    for row, mach in zip(rows, MACHS):
        best_case, best = None, math.inf
        for case, p in ok_rows():
            if dq(*p, mach) < best:
                best_case, best = case, dq(*p, mach)
        z, s, f = inputs()[best_case]
        assert row[3] == str(best_case)
        assert float(row[1]) == pytest.approx(best, rel=1e-5)
        assert float(row[2]) == pytest.approx(best / 2.5, rel=1e-5)
        assert (float(row[4]), float(row[5]), row[6]) == (z, s, f)


def test_report_parameters_errors_and_spec(written):
    page, text = written["page"], written["text"]
    params = {r[0]: r for r in page.tables["parameters"][1:]}
    assert list(params) == PARAMETERS
    assert (float(params["wing_z"][1]), float(params["wing_z"][2])) == (-0.4, 0.4)
    assert params["sweep"][3] == "4" and params["fillet"][4] == "cubic, none"
    errors = {r[0]: r[1:] for r in page.tables["errors"][1:]}
    assert errors["wing misses the body"] == ["JunctureError", "4", "3, 11, 25, 33"]
    assert errors[SCRIPT] == ["JunctureError", "2", "17, 26"]
    assert errors["timeout"][1:] == ["1", "38"]
    assert "&lt;script&gt;alert(&#x27;x&#x27;)&lt;/script&gt; fillet &amp; blend" in text
    assert "<script>" not in text
    assert page.pre == written["spec"]


def test_report_lists_first_five_cases_and_takes_figure_objects(df, close_figures):
    many = frame(errors={case: "diverged" for case in range(0, 40, 3)})
    fig = plot_against_parameters(many, PARAMETERS, "volume")
    page = Page(render_sweep_report(many, PARAMETERS, figures={"my volume": fig}))
    row = page.tables["errors"][1]
    assert row[0] == "diverged" and row[2] == "14" and row[3] == "0, 3, 6, 9, 12, ..."
    assert [a["alt"] for t, a in page.tags if t == "img"] == ["my volume"]
    assert "minimum" in {a.get("id") for t, a in page.tags if t == "section"}
    with pytest.raises(JunctureError, match="PNG"):
        render_sweep_report(df, PARAMETERS, figures=[__file__])


def test_report_of_a_sweep_without_drag_or_errors():
    clean = frame(errors={}).drop(columns=["D_over_q_M1.6", "D_over_q_M2"])
    page = Page(render_sweep_report(clean, ["wing_z"]))
    ids = {a.get("id") for t, a in page.tags if t == "section"}
    assert ids == {"parameters"}
    assert page.keys["ok"] == "40" and page.keys["error"] == "0"


def test_importing_the_module_imports_neither_matplotlib_nor_pandas():
    code = ("import sys, juncture.plots.sweep; "
            "print(sorted(m for m in ('matplotlib', 'pandas') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "[]"
