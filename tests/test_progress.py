"""The progress bar: drawn on a terminal, silent in pipes, tests and with --quiet."""

import sys

from juncture._progress import Progress
from juncture.cli import main
from tests.support import PDAS_DECK


def test_a_bar_names_the_job_and_the_running_step(capsys):
    with Progress(3, "complete", enabled=True) as bar:
        assert bar.enabled
        bar.step("read")
        bar.step("intersect")
        bar.step("write")
    err = capsys.readouterr().err
    assert "complete:" in err and "intersect" in err and "2/3" in err and "write" in err


def test_no_bar_when_stderr_is_not_a_terminal(capsys):
    assert not sys.stderr.isatty()
    with Progress(2, "job") as bar:
        assert not bar.enabled
        bar.step("one")
        bar.step("two")
    assert capsys.readouterr().err == ""


def test_commands_print_no_bar_into_a_pipe_and_nothing_but_errors_when_quiet(tmp_path, capsys):
    assert main(["complete", str(PDAS_DECK), "-o", str(tmp_path), "--fillet", "cubic"]) == 0
    out, err = capsys.readouterr()
    assert "wrote 2 files" in out and "|" not in err
    assert main(["complete", str(PDAS_DECK), "-o", str(tmp_path), "-q"]) == 0
    out, err = capsys.readouterr()
    assert out == "" and "error" not in err
