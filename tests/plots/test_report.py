"""The self-contained HTML report: sections, embedded data, units, component colours, no
external resources, a browser."""

import base64
import json
import shutil
import subprocess
import warnings
from html.parser import HTMLParser

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import juncture as jc
from juncture.plots import render_report, wireframe_data, write_report
from juncture.plots.style import component_colour
from tests.support import EXAMPLE_DECK

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
SECTIONS = {"view3d", "inputs", "intersections", "stations", "wavedrag", "massprops", "figures"}
COMMAND = ["juncture", "complete", "examples/supersonic_transport.inp", "--fillet", "cubic",
           "--keep-area"]


class Page(HTMLParser):
    """Collects what the tests look at: elements, section ids, tables, scripts, images."""

    def __init__(self, text):
        super().__init__(convert_charrefs=True)
        self.tags, self.section, self.tables, self.scripts = [], None, {}, {}
        self.cell = self.row = self.script = None
        self.details = 0
        self.h1 = ""
        self._in_h1 = False
        self.feed(text)
        self.close()

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.append((tag, a))
        if tag == "section":
            self.section = a.get("id")
        elif tag == "tr":
            self.row = []
        elif tag in ("td", "th"):
            self.cell = ""
        elif tag == "script":
            self.script = [a, ""]
        elif tag == "details":
            self.details += 1
        elif tag == "h1":
            self._in_h1 = True

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.cell is not None:
            self.row.append(self.cell.strip())
            self.cell = None
        elif tag == "tr" and self.row is not None:
            self.tables.setdefault(self.section, []).append(self.row)
            self.row = None
        elif tag == "script":
            self.scripts[self.script[0].get("id") or len(self.scripts)] = self.script
            self.script = None
        elif tag == "h1":
            self._in_h1 = False

    def handle_data(self, data):
        if self.cell is not None:
            self.cell += data
        if self.script is not None:
            self.script[1] += data
        if self._in_h1:
            self.h1 += data

    def ids(self):
        return {a["id"] for t, a in self.tags if t == "section"}

    def images(self):
        return [a["src"] for t, a in self.tags if t == "img"]


def _read_example():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jc.JunctureWarning)
        return jc.read(EXAMPLE_DECK)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """The bundled example, cubic fillet, keep_area, with wave drag and mass properties."""
    from juncture.analysis import wavedrag
    from juncture.massprops import configuration_mass_properties

    cfg = _read_example()
    geo = jc.complete(cfg, "cubic", True)
    wd = {"original": wavedrag(cfg), "cubic fillet, fixed area": wavedrag(cfg, geometry=geo)}
    mp = configuration_mass_properties(cfg)
    # Given figures (fast): a Figure and a PNG file; the report's own figures cost seconds
    # and have their own (slow) test.
    from juncture.plots import plt

    tmp = tmp_path_factory.mktemp("report")
    fig, ax = plt.subplots(figsize=(3, 2))
    ax.plot(wd["original"]["x"], wd["original"]["area"])
    png = tmp / "given.png"
    fig.savefig(png, dpi=50)
    path = write_report(tmp / "report.html", cfg, geo, wavedrag=wd, massprops=mp,
                        command=COMMAND, figures={"area": fig, "a file": png})
    plt.close(fig)
    text = path.read_text(encoding="utf-8")
    return {"cfg": cfg, "geo": geo, "wd": wd, "mp": mp, "path": path, "text": text,
            "page": Page(text), "png": png}


@pytest.fixture(scope="module")
def small():
    """A one-network geometry without a configuration (fast error-path tests)."""
    x = np.linspace(0.0, 3.0, 5)
    t = np.linspace(0.0, np.pi, 7)
    net = np.stack(np.broadcast_arrays(x[:, None], np.cos(t)[None, :],
                                       np.sin(t)[None, :]), axis=-1)
    return jc.Geometry(networks={"duct": net}, title="duct")


def _cells(row):
    return [float(c) for c in row]


def test_every_section_and_header(run):
    page = run["page"]
    assert SECTIONS <= page.ids()
    assert run["cfg"].title in page.h1
    assert "juncture " + jc.__version__ in run["text"]
    assert " ".join(COMMAND) in run["text"]
    assert page.details >= 1
    # Components table: one row per component (plus the header row), with its kind and counts.
    comps = page.tables["inputs"]
    assert [r[0] for r in comps[1:]] == [c.name for c in run["cfg"]]
    wing = next(r for r in comps if r[0] == "wing")
    assert wing[1:4] == ["wing", "7 sections x 13 stations", "yes"]
    # Every log line of the run is in the collapsible log.
    for line in run["geo"].log:
        assert line.split("\n")[0][:40].replace("'", "&#x27;") in run["text"]


def test_no_external_resources(run):
    for _, attrs in run["page"].tags:
        for key in ("src", "href"):
            value = attrs.get(key) or ""
            assert not value.lower().startswith(("http://", "https://", "//")), value
    assert not [a for t, a in run["page"].tags if t == "link"]
    assert not [a for t, a in run["page"].tags if t == "script" and "src" in a]
    assert "http://" not in run["text"] and "https://" not in run["text"]


def _check_pngs(imgs, n):
    assert len(imgs) == n
    for src in imgs:
        head, data = src.split(",", 1)
        assert head == "data:image/png;base64"
        assert base64.b64decode(data).startswith(PNG_MAGIC)


def test_images_are_embedded_pngs(run):
    imgs = run["page"].images()
    _check_pngs(imgs, 2)
    assert base64.b64decode(imgs[1].split(",", 1)[1]) == run["png"].read_bytes()


@pytest.mark.slow
def test_own_figures_of_a_filleted_geometry(run):
    page = Page(render_report(run["cfg"], run["geo"], wavedrag=run["wd"]))
    # Three views, four juncture figures (fillets present), the wave-drag area curves.
    _check_pngs(page.images(), 6)
    assert "fillet lines at constant x" in " ".join(a["alt"] for t, a in page.tags
                                                     if t == "img")


def test_wireframe_json_round_trips(run):
    attrs, text = run["page"].scripts["jr-data"]
    assert attrs["type"] == "application/json"
    data = json.loads(text)
    geo = run["geo"]
    mirrored = geo.mirrored_networks()
    assert [n["name"] for n in data["networks"]] == list(mirrored)
    n_points = 0
    for net in data["networks"]:
        assert net["lines"] and all(len(line) % 3 == 0 and line for line in net["lines"])
        n_points += sum(len(line) // 3 for line in net["lines"])
        assert net["image"] == net["name"].endswith(" image")
    assert n_points > 0
    # All points inside the mirrored extents (rounded to 1e-4 of the size).
    pts = np.concatenate([np.reshape(line, (-1, 3)) for n in data["networks"]
                          for line in n["lines"]])
    allpts = np.concatenate([v.reshape(-1, 3) for v in mirrored.values()])
    tol = 1e-4 * data["size"]
    assert np.all(pts >= allpts.min(0) - tol) and np.all(pts <= allpts.max(0) + tol)
    # The first n-line of every network, corner to corner, survives downsampling.
    for net in data["networks"]:
        first = np.reshape(net["lines"][0], (-1, 3))
        np.testing.assert_allclose(first[[0, -1]], mirrored[net["name"]][0, [0, -1]],
                                   atol=tol)
    assert {i["name"] for i in data["intersections"]} == set(geo.intersections)


def test_station_table_matches_geometry(run):
    st_ = run["geo"].stations
    rows = run["page"].tables["stations"]
    assert rows[0] == ["x [ft]", "original area [ft²]", "fillet area [ft²]",
                       "body area [ft²]", "original radius [ft]", "new radius [ft]",
                       "residual"]
    assert len(rows) - 1 == len(st_["x"])
    k = 5
    got = _cells(rows[1 + k])
    keys = ("x", "area_original", "area_fillet", "area_body", "radius_original", "radius_new")
    np.testing.assert_allclose(got[:6], [st_[key][k] for key in keys], rtol=1e-6)
    assert abs(got[6] - st_["residual"][k]) <= 1e-2 * abs(st_["residual"][k]) + 1e-300


def test_intersection_rows(run):
    rows = {r[0]: r for r in run["page"].tables["intersections"][1:]}
    geo = run["geo"]
    assert set(rows) == set(geo.intersections)
    upper = rows["wing/body upper"]
    pts = geo.intersections["wing/body upper"]
    assert int(upper[1]) == len(pts)
    lo, hi = (float(v) for v in upper[2].split("\u2026"))
    # Shown to 6 significant digits.
    np.testing.assert_allclose([lo, hi], [pts[:, 0].min(), pts[:, 0].max()], rtol=5e-6)
    # An intersection lies on the body: its distance from it is round-off.
    assert float(upper[3]) < 1e-9


def test_wavedrag_and_massprops_tables(run):
    wd = run["wd"]
    rows = run["page"].tables["wavedrag"]
    assert [r[0] for r in rows[1:]] == list(wd)
    d0, d1 = (wd[k]["D_over_q"] for k in wd)
    assert rows[1][5] == "+0.000 %"
    assert float(rows[2][5].split()[0]) == pytest.approx(100 * (d1 - d0) / d0, abs=1e-3)
    assert float(rows[2][3]) == pytest.approx(d1, rel=1e-5)
    total, parts = run["mp"]
    mrows = run["page"].tables["massprops"]
    assert [r[0] for r in mrows[1:]] == [n for n, _ in parts] + ["total"]
    tot = _cells(mrows[-1][1:])
    np.testing.assert_allclose(tot[:5], [total.mass, total.volume, *total.cg], rtol=1e-5,
                               atol=1e-9)
    np.testing.assert_allclose(tot[5:], np.diag(total.inertia), rtol=1e-5)
    # The parts add up to the total (the table shows what the caller passed, consistently).
    assert sum(float(r[1]) for r in mrows[1:-1]) == pytest.approx(tot[0], rel=1e-5)


def test_given_figures_and_no_figures(tmp_path, small):
    from juncture.plots import plt

    fig, ax = plt.subplots(figsize=(2, 1.5))
    ax.plot([0, 1], [1, 0])
    png = tmp_path / "given.png"
    fig.savefig(png, dpi=40)
    page = Page(render_report(None, small, figures={"a figure": fig, "a file": png}))
    plt.close(fig)
    imgs = page.images()
    assert len(imgs) == 2
    assert base64.b64decode(imgs[1].split(",", 1)[1]) == png.read_bytes()
    none = Page(render_report(None, small, figures={}))
    assert "figures" not in none.ids() and none.images() == []
    # Without stations or intersections those sections are left out; the 3-D view remains.
    assert none.ids() == {"view3d", "inputs"}


def test_script_data_is_escaped(small):
    geo = jc.Geometry(networks={"</script><b>x": small.networks["duct"]})
    text = render_report(None, geo, figures={}, title="a <title> & more")
    assert "</script><b>" not in text and "<title>a &lt;title&gt; &amp; more</title>" in text
    data = json.loads(Page(text).scripts["jr-data"][1])
    assert data["networks"][0]["name"] == "</script><b>x"


@settings(max_examples=25, deadline=None)
@given(n_lines=st.integers(1, 90), n_points=st.integers(1, 130))
def test_wireframe_downsampling_keeps_ends(n_lines, n_points):
    rng = np.random.default_rng(n_lines * 1000 + n_points)
    net = rng.normal(size=(n_lines, n_points, 3)) * [7.0, 3.0, 2.0]
    data = wireframe_data(jc.Geometry(networks={"n": net}), max_lines=17, max_points=23)
    lines = data["networks"][0]["lines"]
    kept_l, kept_p = min(n_lines, 17), min(n_points, 23)
    assert len(lines) == kept_l + (kept_p if kept_l > 1 else 0)
    assert all(len(line) == 3 * kept_p for line in lines[:kept_l])
    tol = 1e-4 * data["size"]
    first, last = np.reshape(lines[0], (-1, 3)), np.reshape(lines[kept_l - 1], (-1, 3))
    np.testing.assert_allclose(first[[0, -1]], net[0, [0, -1]], atol=tol)
    np.testing.assert_allclose(last[[0, -1]], net[-1, [0, -1]], atol=tol)


def test_errors(tmp_path, small):
    out = tmp_path / "r.html"
    out.write_text("old")
    with pytest.raises(jc.JunctureError, match="needs a Geometry"):
        write_report(out, None, {"duct": small.networks["duct"]})
    with pytest.raises(jc.JunctureError, match="cfg must be a Configuration"):
        write_report(out, "deck.inp", small)
    with pytest.raises(jc.JunctureError, match="non-empty mapping"):
        write_report(out, None, small, wavedrag=[1.0], figures={})
    with pytest.raises(jc.JunctureError, match="has no 'D_over_q'"):
        write_report(out, None, small, wavedrag={"a": {"CD": 1.0}}, figures={})
    with pytest.raises(jc.JunctureError, match=r"massprops must be \(total, parts\)"):
        write_report(out, None, small, massprops=(1.0,), figures={})
    with pytest.raises(jc.JunctureError, match="figures must be a mapping"):
        write_report(out, None, small, figures=["x.png"])
    with pytest.raises(jc.JunctureError, match="must be a matplotlib Figure or the path"):
        write_report(out, None, small, figures={"f": 3})
    with pytest.raises(jc.JunctureError, match="cannot read"):
        write_report(out, None, small, figures={"f": tmp_path / "missing.png"})
    (tmp_path / "not.png").write_text("GIF89a")
    with pytest.raises(jc.JunctureError, match="is not a PNG file"):
        write_report(out, None, small, figures={"f": tmp_path / "not.png"})
    with pytest.raises(jc.JunctureError, match="at least 2"):
        wireframe_data(small, max_lines=1)
    assert out.read_text() == "old"  # a failed report leaves the old file alone


def _chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        exe = shutil.which(name)
        if exe:
            return exe
    return None


@pytest.mark.browser
def test_browser_draws_the_report(run, tmp_path):
    import matplotlib.image as mpimg

    exe = _chromium()
    if exe is None:
        pytest.skip("chromium not installed: make test installs it where apt-get is available")
    shot = tmp_path / "shot.png"
    subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                    "--no-first-run", "--disable-background-networking",
                    "--disable-component-update", "--disable-sync",
                    f"--user-data-dir={tmp_path / 'profile'}", "--window-size=1200,900",
                    f"--screenshot={shot}", run["path"].resolve().as_uri()],
                   timeout=60, capture_output=True, check=False)
    assert shot.exists(), "chromium wrote no screenshot"
    img = mpimg.imread(shot)[..., :3]
    assert img.std() > 0.05
    # The 3-D canvas is the only area of its background colour #fbfbfd near the top: find it,
    # then require the wireframe drawn in it (many colours, a fair share of drawn pixels).
    bg = np.array([0xFB, 0xFB, 0xFD]) / 255.0
    is_bg = np.all(np.abs(img - bg) < 1.5 / 255.0, axis=-1)
    rows, cols = np.flatnonzero(is_bg.sum(1) > 200), np.flatnonzero(is_bg.sum(0) > 200)
    assert rows.size > 200 and cols.size > 300, "canvas background not found"
    region = img[rows.min():rows.max() + 1, cols.min():cols.max() + 1]
    drawn = ~is_bg[rows.min():rows.max() + 1, cols.min():cols.max() + 1]
    assert drawn.mean() > 0.02
    colours = np.unique((region[drawn] * 255).round().astype(int), axis=0)
    assert len(colours) >= 20


def test_mass_properties_state_their_unit(run):
    page, text = run["page"], run["text"]
    head = page.tables["massprops"][0]
    assert head[:3] == ["component", "mass [ft\u00b3 at density 1]", "volume [ft\u00b3]"]
    assert head[3:6] == ["CG x [ft]", "CG y [ft]", "CG z [ft]"]
    assert head[6] == "Ixx [ft\u2075 at density 1]"
    assert "no density was given, so it is 1 and each mass is its volume in ft\u00b3" in text
    # The key number: the total mass with its unit and what it means.
    total = run["mp"][0].mass
    assert f"{total:.5g} ft\u00b3" in text and "total mass (density 1: mass = volume)" in text


def test_mass_unit_with_a_density(small):
    from juncture.massprops import configuration_mass_properties

    cfg = _read_example()
    mp = configuration_mass_properties(cfg, density=2.5)
    page = Page(render_report(None, small, massprops=mp, figures={}, units="m"))
    head = page.tables["massprops"][0]
    assert head[1] == "mass [density x m\u00b3]" and head[6] == "Ixx [mass x m\u00b2]"
    assert "total mass [density x m\u00b3]" in render_report(None, small, massprops=mp,
                                                             figures={}, units="m")


def test_units_label_every_table(run):
    text = render_report(run["cfg"], run["geo"], wavedrag=run["wd"], figures={}, units="in")
    page = Page(text)
    assert page.tables["stations"][0][0] == "x [in]"
    assert page.tables["intersections"][0][2:] == ["x range [in]",
                                                   "max distance from body [in]"]
    assert page.tables["wavedrag"][0][3] == "D/q [in\u00b2]"
    assert page.tables["inputs"][0][4:] == ["x extent [in]", "y extent [in]", "z extent [in]"]
    assert "[ft" not in "".join(c for t in page.tables.values() for c in t[0])


def test_viewer_colours_are_the_figures_colours(run):
    data = json.loads(run["page"].scripts["jr-data"][1])
    comps = {c["name"]: c["colour"] for c in data["components"]}
    assert set(comps) == {c.name for c in run["cfg"]}
    for name, colour in comps.items():
        assert colour == component_colour(name)
    # Networks named "wing upper", "body lower" belong to the components of those names.
    owner = {n["name"]: data["components"][n["component"]]["name"] for n in data["networks"]}
    assert owner["wing upper image"] == "wing" and owner["fin 3 inboard"] == "fin 3"


def test_viewer_knows_components_named_otherwise():
    from tests.plots.plot_cases import example, renamed

    cfg = renamed(example())
    geo = jc.complete(cfg, None, wing="main wing", body="fuselage")
    data = json.loads(Page(render_report(cfg, geo, figures={})).scripts["jr-data"][1])
    names = [c["name"] for c in data["components"]]
    assert "main wing" in names and "fuselage" in names and "wing" not in names
    assert dict(zip(names, (c["colour"] for c in data["components"])))["fuselage"] == \
        component_colour("body")


def test_the_old_import_paths_still_work_and_warn():
    import importlib
    import sys

    from juncture.plots import juncture as plots_juncture

    for name in ("juncture.report", "juncture.plots_juncture"):
        sys.modules.pop(name, None)
        with pytest.warns(DeprecationWarning, match="moved to juncture.plots"):
            importlib.import_module(name)
    import juncture.plots_juncture
    import juncture.report

    assert juncture.report.write_report is write_report
    assert juncture.plots_juncture.plot_fillet_sections is plots_juncture.plot_fillet_sections


def test_the_closed_surface_section(run):
    """The completed airplane's one closed surface: its volume, centre and wetted areas as
    the surface computes them (overlaps once), and a key number; or why there is none."""
    surface = jc.mesh(run["geo"], min_angle=0.0)
    text = render_report(run["cfg"], run["geo"], figures={}, surface=surface)
    page = Page(text)
    rows = {r[0].split(" [")[0]: r[1] for r in page.tables["surface"][1:]}
    assert float(rows["enclosed volume"]) == pytest.approx(surface.volume(), rel=1e-8)
    wetted = surface.wetted_area()
    assert float(rows["total"]) == pytest.approx(wetted["total"], rel=1e-5)
    assert float(rows["wing"]) == pytest.approx(wetted["wing"], rel=1e-5)
    cg = [float(c) for c in rows["centre of volume"].split(",")]
    np.testing.assert_allclose(cg, surface.mass_properties().cg, rtol=1e-5, atol=1e-6)
    assert "enclosed volume (overlaps once)" in text  # a key number in the header
    text = render_report(run["cfg"], run["geo"], figures={}, surface="3 open loops")
    assert "No closed surface: 3 open loops" in text
