"""Running sweeps: the same numbers on every kind of worker, resuming, error rows, outputs."""

import json
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

pandas = pytest.importorskip("pandas", reason="pandas comes with the sweep extra")

import juncture as jc  # noqa: E402
from juncture.analysis import normal_area_distribution, wavedrag  # noqa: E402
from juncture.errors import JunctureError, SpecError  # noqa: E402
from juncture.geometry import Geometry  # noqa: E402
from juncture.study import journal_path, load_spec, read_journal, sweep  # noqa: E402
from juncture.study import run as run_module  # noqa: E402
from juncture.study.case import wetted_area  # noqa: E402
from juncture.study.edit import apply_edit  # noqa: E402
from support import EXAMPLE_DECK  # noqa: E402

SMALL = """
[complete]
keep_area = true
[analysis]
mach = [1.6]
n_x = 40
n_theta = 4
[parameters.wing_z]
component = "wing"
field = "z"
mode = "offset"
values = {z}
[parameters.fillet]
option = "fillet"
values = ["none", "cubic"]
"""


def write_spec(tmp_path, z="[0.0, 0.5]", name="spec.toml", extra=""):
    path = tmp_path / name
    path.write_text(f'base = "{EXAMPLE_DECK}"\n' + textwrap.dedent(SMALL.format(z=z)) + extra)
    return path


def _numbers(frame):
    return frame.drop(columns=["wall_time"])


def test_in_process_pool_and_dask_give_bit_identical_rows(tmp_path):
    pytest.importorskip("distributed", reason="Dask comes with the sweep extra")
    spec = write_spec(tmp_path)
    one = sweep(spec)
    two = sweep(spec, workers=2)
    dask = sweep(spec, workers=2, client="local")
    assert list(one["status"]) == ["ok"] * 4
    pandas.testing.assert_frame_equal(_numbers(one), _numbers(two), check_exact=True)
    pandas.testing.assert_frame_equal(_numbers(one), _numbers(dask), check_exact=True)


def test_rows_are_the_library_calls_and_the_volume_is_the_area_integral(tmp_path):
    spec = load_spec(write_spec(tmp_path, z="[0.5]"))
    frame = sweep(spec)
    cfg = jc.read(EXAMPLE_DECK)
    moved = apply_edit(cfg, spec.parameters[0], 0.5)
    for _, row in frame.iterrows():
        fillet = None if row["fillet"] == "none" else row["fillet"]
        geo = jc.complete(moved, fillet, fillet is not None)
        r = wavedrag(geo.configuration, 1.6, 40, 4, geometry=geo)
        assert row["D_over_q_M1.6"] == r["D_over_q"]
        assert row["CD_M1.6"] == r["CD"]
        assert row["intersections"] == len(geo.intersections)
        # an independent volume: the model's exact normal areas (Gauss in each cut), fine in x
        x = np.linspace(*geo.configuration.extents()[:, 0], 201)
        area = np.asarray(normal_area_distribution(geo.configuration, x)["total"])
        if fillet is not None:
            from juncture.analysis.command import _fillet_normal

            area = area + _fillet_normal(geo, x)
        exact = float(np.sum(0.5 * (area[1:] + area[:-1]) * np.diff(x)))
        assert row["volume"] == pytest.approx(exact, rel=0.01)
        assert row["mass_volume"] > row["volume"]  # massprops counts the buried root twice


def test_wetted_area_of_a_polygonal_prism_is_exact():
    n, r, length = 24, 2.0, 10.0
    th = np.linspace(0.0, 2 * np.pi, n + 1)
    ring = np.stack([np.zeros(n + 1), r * np.cos(th), r * np.sin(th)], axis=1)
    net = np.stack([ring + [x, 0.0, 0.0] for x in np.linspace(0.0, length, 7)])
    geo = Geometry(networks={"tube": net})
    assert wetted_area(geo) == pytest.approx(n * 2 * r * np.sin(np.pi / n) * length, rel=1e-14)
    half = Geometry(networks={"tube": net[:, : n // 2 + 1]}, symmetry={"tube": "xz"})
    assert wetted_area(half) == pytest.approx(wetted_area(geo), rel=1e-14)


def test_a_failing_case_is_a_row_and_the_sweep_goes_on(tmp_path):
    frame = sweep(write_spec(tmp_path, z="[-1.0, 0.0]"))
    bad = frame[frame["wing_z"] == -1.0]
    assert set(bad["status"]) == {"error"} and set(bad["error_type"]) == {"GeometryError"}
    assert all("passes through pod" in m for m in bad["error"])
    assert bad["D_over_q_M1.6"].isna().all()
    good = frame[frame["wing_z"] == 0.0]
    assert set(good["status"]) == {"ok"} and (good["error"] == "").all()
    assert good["D_over_q_M1.6"].notna().all()


def test_results_files_and_journal(tmp_path, monkeypatch):
    spec = write_spec(tmp_path)
    out = tmp_path / "r.parquet"
    frame = sweep(spec, out, figures=True)
    pandas.testing.assert_frame_equal(pandas.read_parquet(out), frame, check_exact=True)
    rows = read_journal(journal_path(out))
    assert sorted(rows) == sorted(frame["key"])
    assert (tmp_path / "r.html").read_text().count("data:image/png;base64") == 3
    csv = tmp_path / "r.csv"
    sweep(spec, csv)
    back = pandas.read_csv(csv, keep_default_na=False, na_values=[""])
    np.testing.assert_array_equal(back["D_over_q_M1.6"], frame["D_over_q_M1.6"])
    # a second run reads every row from the journal and runs no case
    calls = []
    monkeypatch.setattr(run_module, "run_case", lambda *a: calls.append(a))
    again = sweep(spec, out)
    assert calls == []
    pandas.testing.assert_frame_equal(again, frame, check_exact=True)
    with pytest.raises(JunctureError, match="expected a .parquet or .csv"):
        sweep(spec, tmp_path / "r.xlsx")
    with pytest.raises(JunctureError, match="does not exist"):
        sweep(spec, tmp_path / "no" / "r.csv")


def test_spec_targets_checked_against_the_base_before_any_case(tmp_path):
    spec = write_spec(tmp_path, extra='[parameters.pod]\ncomponent = "pod 9"\nfield = "x"\n'
                      'values = [1.0]\n')
    with pytest.raises(SpecError, match="no component 'pod 9'"):
        sweep(spec)


def test_killed_sweep_resumes_without_redoing_finished_cases(tmp_path, monkeypatch):
    spec = write_spec(tmp_path, z="[0.0, 0.1, 0.2, 0.3, 0.4, 0.5]")
    out = tmp_path / "k.csv"
    journal = journal_path(out)
    cli = [sys.executable, "-m", "juncture", "sweep", str(spec), "-o", str(out), "-q"]
    proc = subprocess.Popen(cli, start_new_session=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if journal.exists() and len(journal.read_text().splitlines()) >= 3:
            break
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    assert not out.exists()  # results are written only whole
    done = read_journal(journal)
    assert 3 <= len(done) < 12
    with open(journal, "a") as fh:  # a row cut short by the kill
        fh.write('{"key": "abc", "case": ')
    calls = []
    real = run_module.run_case

    def counted(spec, index, case):
        calls.append(index)
        return real(spec, index, case)

    monkeypatch.setattr(run_module, "run_case", counted)
    frame = sweep(spec, out)
    assert len(calls) == 12 - len(done)
    assert not set(frame.loc[calls, "key"]) & set(done)
    assert len(frame) == 12 and (frame["status"] == "ok").all()
    assert list(frame["case"]) == list(range(12))
    first = {k: v for k, v in done.items()}
    for _, row in frame.iterrows():
        if row["key"] in first:
            assert row["D_over_q_M1.6"] == first[row["key"]]["D_over_q_M1.6"]
    assert json.loads(journal.read_text().splitlines()[0])["key"] in set(frame["key"])


def test_public_name_and_progress_bar(tmp_path, capsys):
    assert jc.sweep is sweep
    sweep(write_spec(tmp_path, z="[0.0]"), progress=True)
    err = capsys.readouterr().err
    assert "sweep" in err and "2/2" in err and "case" in err
