"""bench.storage: the loader reads what a run leaves, and says clearly what is wrong."""

import json
import os

import pytest

from bench.run import acquire
from bench.storage import load_run
from fem.records import write_json_atomic


@pytest.fixture
def run_path(config, tmp_path):
    return acquire(config, out_root=tmp_path).path


def test_killed_run_is_reported_incomplete(run_path):
    n_whole = len(load_run(run_path).samples)
    meta = json.loads((run_path / "run.json").read_text())
    meta["status"] = "running"
    meta["process"]["pid"] = 2**22 + 12345  # above Linux's pid_max: never alive
    write_json_atomic(run_path / "run.json", meta)
    with open(run_path / "samples.csv", "a") as f:
        f.write("999,99.9,1,step,0.5")  # a row cut in the middle, as a kill leaves it
    run = load_run(run_path)
    assert run.status == "incomplete" and not run.complete
    assert any("partial last row" in p for p in run.problems)
    assert any("stopped without closing" in p for p in run.problems)
    assert len(run.samples) == n_whole and run.samples["sample"].iloc[-1] != 999


def test_live_run_is_reported_running(run_path):
    meta = json.loads((run_path / "run.json").read_text())
    meta["status"] = "running"  # recorded by this very process (the pytest run)
    assert meta["process"]["pid"] == os.getpid()
    write_json_atomic(run_path / "run.json", meta)
    run = load_run(run_path)
    assert run.status == "running" and not run.complete


def test_reused_pid_does_not_look_alive(run_path):
    # A live pid with another start time is another process: the recorder is dead (issue 12).
    meta = json.loads((run_path / "run.json").read_text())
    meta["status"] = "running"
    meta["process"]["started_unix_s"] -= 3600.0
    write_json_atomic(run_path / "run.json", meta)
    assert load_run(run_path).status == "incomplete"


def test_not_a_run_folder(tmp_path):
    with pytest.raises(ValueError, match="is not a run folder: run.json is missing"):
        load_run(tmp_path)


def test_corrupt_run_json(run_path):
    (run_path / "run.json").write_text('{"status": "compl')
    with pytest.raises(ValueError, match="run.json is corrupt"):
        load_run(run_path)
    (run_path / "run.json").write_text('{"status": "finished"}')
    with pytest.raises(ValueError, match="expected a 'status' among"):
        load_run(run_path)


def test_corrupt_samples(run_path):
    (run_path / "samples.csv").write_text("garbage\n1,2\n")
    with pytest.raises(ValueError, match="samples.csv is corrupt"):
        load_run(run_path)


def test_missing_steps_is_a_problem_not_a_crash(run_path):
    (run_path / "steps.csv").unlink()
    run = load_run(run_path)
    assert run.steps.empty and "steps.csv is missing" in run.problems
    assert run.status == "complete"  # as recorded; the caller sees the problem listed


def test_atomic_json_leaves_no_temporary_files(tmp_path):
    write_json_atomic(tmp_path / "run.json", {"status": "running"})
    write_json_atomic(tmp_path / "run.json", {"status": "complete"})
    assert [p.name for p in tmp_path.iterdir()] == ["run.json"]
    assert json.loads((tmp_path / "run.json").read_text()) == {"status": "complete"}
