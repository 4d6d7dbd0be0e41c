"""Run-folder arguments expanded by mkm itself, so one line works in cmd, PowerShell and bash."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from mkm.bench.folders import one_run_folder, run_folders


def _runs(root, *names):
    for name in names:
        (root / name).mkdir(parents=True)
        (root / name / "run.json").write_text("{}")
    return [root / n for n in names]


def test_patterns_and_parent_folders(tmp_path):
    a, b, c = _runs(tmp_path / "runs", "20260101T000000Z_m-1", "20260101T000001Z_m-2",
                    "20260102T000000Z_other")
    (tmp_path / "runs" / "notes.txt").write_text("not a run")
    assert run_folders([str(tmp_path / "runs" / "*")]) == [a, b, c]
    assert run_folders([str(tmp_path / "runs" / "2026010?T000000Z_*")]) == [a, c]
    assert run_folders([tmp_path / "runs"]) == [a, b, c]  # a folder of run folders
    assert run_folders([a, str(tmp_path / "runs" / "*")]) == [a, b, c]  # each once
    assert run_folders([tmp_path / "missing"]) == [tmp_path / "missing"]  # the loader names it
    assert one_run_folder(str(tmp_path / "runs" / "*other")) == c


def test_a_pattern_naming_no_run_is_refused(tmp_path):
    (tmp_path / "empty").mkdir()
    with pytest.raises(ValueError, match=r"matches no run folder"):
        run_folders([str(tmp_path / "nothing" / "*")])
    with pytest.raises(ValueError, match="is not a run folder .* and holds none"):
        run_folders([tmp_path / "empty"])
    _runs(tmp_path, "r1", "r2")
    with pytest.raises(ValueError, match="names 2 run folders: expected one"):
        one_run_folder(str(tmp_path / "r*"))


def test_a_file_beside_the_runs_says_how_to_pass_them_and_a_run_json_is_its_run(tmp_path):
    # bash expands `mkm report runs/*` itself: the README beside the runs comes as an argument
    a, b = _runs(tmp_path / "runs", "r1", "r2")
    readme = tmp_path / "runs" / "README.md"
    readme.write_text("two runs")
    with pytest.raises(ValueError, match=r"README.md is a file, not a run folder: .*quote the "
                                         r"pattern \(\".*runs.\*\"\)"):
        run_folders([a, readme, b])
    assert run_folders([a / "run.json", b]) == [a, b]


@pytest.mark.parametrize("name", ["lab.csv", "Messung 1.XLSX"])
def test_a_table_given_as_a_run_says_to_import_it(name, tmp_path, mkm_cli):
    table = tmp_path / name
    table.write_text("P;F\n1;100\n")
    code, _, err = mkm_cli(["report", str(table), "--models", "eq2"])
    assert code == 2 and err.count("\n") == 1, err
    assert f"{table} is a table, not a run folder" in err
    assert f'import it first (mkm import "{table}" --id' in err


def test_report_takes_a_quoted_pattern(tmp_path, mkm_cli):
    # what cmd passes: the pattern itself
    code, out, err = mkm_cli(["report", str(tmp_path / "runs" / "*"), "--models", "eq2"])
    assert code == 2 and "matches no run folder" in err and err.count("\n") == 1


def test_a_bracket_in_a_folder_name_is_itself_not_a_pattern(tmp_path):
    """Only ``*`` and ``?`` are patterns, as documented (was: ``Messung [2]/runs/*`` matched no
    run folder, glob reading ``[2]`` as a set of characters)."""
    root = tmp_path / "Messung [2] é"
    a, b = _runs(root / "runs", "20260101T000000Z_m", "20260101T000001Z_m")
    assert run_folders([str(root / "runs" / "*")]) == [a, b]
    assert one_run_folder(str(root / "runs" / "*01Z_m")) == b


def test_runs_of_one_second_come_in_the_order_they_were_made(tmp_path):
    """``mkm import`` of a table of six lengths makes ``X_dmsp-20-imported``,
    ``X_dmsp-20-2-imported``, ... in one second: a pattern or their folder gives them in that
    order (was: by name, the -2 ... -6 folders first and the first made last; -10 before -2)."""
    stamp = "20261204T180132Z_"
    made = [f"{stamp}dmsp-20-imported", *(f"{stamp}dmsp-20-{k}-imported" for k in (2, 3, 10)),
            f"{stamp}lab-7-SIMULATED", f"{stamp}lab-7-2-SIMULATED", "20261204T180133Z_dmsp-20"]
    runs = _runs(tmp_path / "runs", *reversed(made))[::-1]  # made in reverse: not by mtime
    assert run_folders([str(tmp_path / "runs" / "*")])[:4] == runs[:4]
    assert run_folders([tmp_path / "runs"])[:4] == runs[:4]
    by_id = run_folders([str(tmp_path / "runs" / "*lab-7*")])
    assert by_id == [runs[4], runs[5]]
    assert run_folders([tmp_path / "runs"])[-1] == runs[-1]  # the next second after them


@pytest.mark.skipif(os.sep != "/", reason="a backslash separates folders on Windows")
@pytest.mark.parametrize("argument", ["runs\\*", "runs\\20260101T000000Z_m"])
def test_a_windows_path_elsewhere_says_the_separator(argument, tmp_path, monkeypatch):
    # was: "runs\* matches no run folder" and "runs\R: no such folder", the run right there
    _runs(tmp_path / "runs", "20260101T000000Z_m")
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ValueError) as info:
        run_folders([argument])
    posix = argument.replace("\\", "/")
    assert str(info.value).endswith(f"; on this system folders are separated by /: {posix!r}?")
    assert run_folders([posix]) == [Path("runs/20260101T000000Z_m")]
