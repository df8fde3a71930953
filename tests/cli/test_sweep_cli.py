"""``juncture sweep`` on the command line: a local Dask cluster, dry runs, one-line errors."""

import pytest

from juncture.cli import main
from tests.study.test_run import write_spec

pandas = pytest.importorskip("pandas", reason="pandas comes with the sweep extra")


@pytest.mark.slow  # a local Dask cluster (> 7 s; the API's Dask test runs in make test)
def test_sweep_through_a_dask_local_cluster(tmp_path, capsys):
    pytest.importorskip("distributed", reason="Dask comes with the sweep extra")
    spec = write_spec(tmp_path, z="[0.0, -1.0]")
    out = tmp_path / "r.parquet"
    assert main(["sweep", str(spec), "-o", str(out), "--dask", "local", "--workers", "2",
                 "--figures"]) == 0
    text = capsys.readouterr().out
    assert "4 cases: 2 ok, 2 error" in text and "passes through pod" in text
    frame = pandas.read_parquet(out)
    assert list(frame["case"]) == [0, 1, 2, 3] and set(frame["status"]) == {"ok", "error"}
    assert (tmp_path / "r.html").is_file() and (tmp_path / "r_figures").is_dir()
    # the same sweep in this process: nothing to run, the same rows
    assert main(["sweep", str(spec), "-o", str(tmp_path / "r.csv"), "-q"]) == 0
    assert capsys.readouterr().out == ""


def test_dry_run_lists_cases_and_keys(tmp_path, capsys):
    spec = write_spec(tmp_path)
    assert main(["sweep", str(spec), "--dry-run"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "4 cases of wing_z, fillet" in lines[0] and len(lines) == 5
    assert "wing_z=0.5, fillet=cubic" in lines[-1]


@pytest.mark.parametrize("argv, match", [
    (["--workers", "0"], "expected a number of workers from 1"),
    (["-o", "r.txt"], "expected a .parquet or .csv file name"),
    (["--dask", "tcp://127.0.0.1:1"], "--dask tcp://127.0.0.1:1: cannot reach the scheduler"),
])
def test_bad_arguments_give_one_line_and_status_2(tmp_path, capsys, argv, match):
    spec = write_spec(tmp_path)
    assert main(["sweep", str(spec), *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and match in err[-1]


def test_bad_spec_names_the_field(tmp_path, capsys):
    spec = write_spec(tmp_path, z="['high']")
    assert main(["sweep", str(spec)]) == 2
    err = capsys.readouterr().err.strip()
    assert "[parameters.wing_z]: values: expected numbers, found 'high'" in err
