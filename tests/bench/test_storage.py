"""bench.storage: the loader reads what a run leaves, and says clearly what is wrong."""

import dataclasses
import json
import os
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from mkm.bench.run import acquire
from mkm.bench.storage import (
    SCHEMA_VERSION,
    RunMeta,
    RunStatus,
    RunWriter,
    Sample,
    aggregate_samples,
    iter_samples,
    load_run,
)
from mkm.core.records import write_json_atomic
from mkm.fem.muscle import Muscle


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


def test_a_run_recorded_on_another_pc_is_not_called_killed(run_path):
    # a run folder on a network share, read from a second bench PC while the first records it:
    # its process is that PC's, which this one cannot see, and the loader said "the run stopped
    # without closing its record (killed or crashed)" of a run going on
    meta = json.loads((run_path / "run.json").read_text())
    meta["status"] = "running"
    meta["process"]["host"] = "BENCH-PC-A"
    write_json_atomic(run_path / "run.json", meta)
    run = load_run(run_path)
    assert run.status == "incomplete" and not run.complete
    assert run.problems == ["the run's record is open, written by mkm acquire on BENCH-PC-A: "
                            "this PC cannot tell whether it still records there or stopped "
                            "without closing its record (killed or crashed)"]


def _dead_elsewhere(run_path, minutes_ago=10.0, host="BENCH-PC-A"):
    """run.json as a run recorded on ``host`` leaves it when that PC dies mid-run (running, its
    counter from its last rewrite), its files last written ``minutes_ago``."""
    import datetime

    meta = json.loads((run_path / "run.json").read_text())
    meta.update(status="running", reason="", ended_utc=None)
    meta["process"].update(host=host, pid=2**22 + 7)
    meta["counters"]["samples"] = 10
    write_json_atomic(run_path / "run.json", meta)
    then = datetime.datetime.now(datetime.UTC) - datetime.timedelta(minutes=minutes_ago)
    for file in run_path.iterdir():
        os.utime(file, (then.timestamp(), then.timestamp()))
    return then


def _contents(run_path):
    return {f.name: f.read_bytes() for f in run_path.iterdir() if f.is_file()}


def test_a_run_dead_on_another_pc_is_closed_by_hand_with_every_sample(run_path):
    # its PC broke and runs mkm no more: identify and report refused the run ("may still be
    # recorded on BENCH-PC-A") and only an edit of run.json by hand let them take it
    import datetime
    import getpass
    import socket

    from mkm.bench.storage import close_by_hand

    rows = len(load_run(run_path).samples)
    then = _dead_elsewhere(run_path)
    before = _contents(run_path)
    assert load_run(run_path).meta.recording().startswith("may still be recorded on BENCH-PC-A")
    now = datetime.datetime(2030, 1, 2, 3, 4, 5, tzinfo=datetime.UTC)
    said = close_by_hand(run_path, " BENCH-PC-A broke\nduring the run ", now=now)
    assert said == (f"run {run_path.name} closed: status killed, {rows} samples kept as they "
                    "are on disk")
    after = _contents(run_path)
    assert {k: v for k, v in after.items() if k != "run.json"} == \
        {k: v for k, v in before.items() if k != "run.json"}  # no sample touched
    meta = json.loads(after["run.json"])
    assert meta["status"] == "killed" and meta["counters"]["samples"] == rows
    assert meta["ended_utc"] == then.isoformat(timespec="seconds")  # samples.csv's last write
    assert meta["closed"] == {"reason": "BENCH-PC-A broke during the run",
                              "by": getpass.getuser(), "on": socket.gethostname(),
                              "utc": "2030-01-02T03:04:05+00:00"}
    assert meta["reason"].startswith("BENCH-PC-A broke during the run (closed by hand with mkm "
                                     f"close by {getpass.getuser()} on {socket.gethostname()} "
                                     "at 2030-01-02T03:04:05+00:00); its mkm acquire (pid "
                                     f"{2**22 + 7} on BENCH-PC-A) stopped without closing")
    run = load_run(run_path)
    assert run.status == "killed" and not run.meta.recording() and run.rows_lost == []
    assert len(run.samples) == rows and run.problems[0] == meta["reason"][:200].rstrip() + \
        "... (in full in run.json)"


@pytest.mark.parametrize("case, refused", [
    ("alive here", "is still being recorded on this PC (pid "),
    ("written a minute ago", "less than 5 min ago: its mkm acquire on BENCH-PC-A may still "
     "record it"),
    ("closed", "is closed already (status complete): expected a run whose run.json says "
     "running"),
    ("no reason", "--reason is empty"),
])
def test_a_run_that_may_still_record_is_not_closed_by_hand(run_path, case, refused):
    from mkm.bench.storage import ProcessIdentity, close_by_hand

    if case != "closed":
        _dead_elsewhere(run_path, minutes_ago=1.0 if case == "written a minute ago" else 10.0)
    if case == "alive here":  # this very process, on this PC
        meta = json.loads((run_path / "run.json").read_text())
        meta["process"] = dataclasses.asdict(ProcessIdentity.current())
        write_json_atomic(run_path / "run.json", meta)
    before = _contents(run_path)
    with pytest.raises(ValueError, match=re.escape(refused)):
        close_by_hand(run_path, "" if case == "no reason" else "the PC broke")
    assert _contents(run_path) == before


def test_a_run_closed_by_hand_that_ended_pressurised_says_so(run_path):
    # the run died with 1.5 bar commanded: closing it from here vents nothing, and says so
    from mkm.bench.storage import close_by_hand

    commands = (run_path / "commands.csv").read_text().splitlines()
    last = next(k for k, line in enumerate(commands) if line.split(",")[2] not in ("0", "0.0",
                                                                                  "command_bar"))
    (run_path / "commands.csv").write_text("\n".join(commands[:last + 1]) + "\n")
    _dead_elsewhere(run_path)
    said = close_by_hand(run_path, "the PC broke")
    assert "it ended without venting: the last commanded pressure was" in said
    assert said.endswith(": vent that bench (mkm vent on BENCH-PC-A, or by hand)")


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
    # the missing folder's message said no more than that (a typed path's mistake is the
    # user's to find: what it should name helps)
    with pytest.raises(ValueError, match=r"nope: no such folder: expected a run folder of mkm "
                                         r"acquire or mkm import \(it holds run.json\)$"):
        load_run(tmp_path / "nope")


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


RECORDED = sorted((Path(__file__).parents[2] / "data" / "experimental").glob("*_paper-prototype"))


@pytest.mark.parametrize("folder", RECORDED, ids=[f.name for f in RECORDED])
def test_schema_1_runs_still_load(folder):
    run = load_run(folder)  # the two runs recorded before schema_version existed
    assert run.meta.schema_version == 1 and run.status == RunStatus.COMPLETE
    assert run.meta.n_steps == 19 == run.meta.steps_done == len(run.steps)
    assert run.meta.process.pid > 0 and run.meta.gaps == [] and run.meta.lost_samples == 0
    assert run.meta.as_dict()["schema_version"] == SCHEMA_VERSION  # written in today's layout
    again = RunMeta.from_dict(json.loads(json.dumps(run.meta.as_dict())))
    assert again == dataclasses.replace(run.meta, schema_version=SCHEMA_VERSION)


def test_run_json_without_geometry_is_one_clear_error(run_path):
    meta = json.loads((run_path / "run.json").read_text())
    del meta["muscle"]["D0_mm"]
    write_json_atomic(run_path / "run.json", meta)
    with pytest.raises(ValueError, match=r"run\.json: muscle\.D0_mm is missing"):
        load_run(run_path)


def test_tampered_text_cells_are_refused(run_path):
    # "=cmd" would reach a report's CSV and run in a spreadsheet
    steps = (run_path / "steps.csv").read_text().replace(",up,", ",=cmd|' /C calc'!A0,", 1)
    (run_path / "steps.csv").write_text(steps)
    with pytest.raises(ValueError, match=r"steps\.csv is corrupt: direction=.=cmd"):
        load_run(run_path)


def test_time_keeps_a_tenth_of_a_second_after_days(tmp_path):
    # 6 significant digits lost the 0.1 s after 27.8 h (100,000 s)
    writer = RunWriter(tmp_path, RunMeta(Muscle(30.0, 3.0, 282.0, 0.0, id="m")), "")
    writer.append_samples([Sample(1_000_001, 1_000_001 / 10, 0, "step", 1.0, 1.0, 1.0, 0.5,
                                  2.0, 98.0, "")])
    writer.close()
    text = (writer.path / "samples.csv").read_text()
    assert "1000001,100000.1,0,step," in text
    assert iter_samples(writer.path).__next__()["time_s"].iloc[0] == 100000.1


def test_aggregate_samples_streams_and_matches_the_whole(run_path):
    run = load_run(run_path)
    s = run.samples
    bins = aggregate_samples(run_path, bin_s=1.0)
    whole = s.groupby(np.floor(s["time_s"] / 1.0))
    np.testing.assert_array_equal(bins["n"], whole.size().to_numpy())
    np.testing.assert_allclose(bins["force_N_mean"], whole["force_N"].mean(), rtol=1e-12)
    np.testing.assert_allclose(bins["force_N_max"], whole["force_N"].max())
    np.testing.assert_allclose(bins["pressure_bar_min"], whole["pressure_bar"].min())
    # read in chunks of 7 rows, bins cut across chunks merge to the same numbers
    small = aggregate_samples(run_path, bin_s=1.0, chunksize=7)
    pd.testing.assert_frame_equal(small, bins)
    # default bin: the run's duration over max_bins
    assert len(aggregate_samples(run_path, max_bins=10)) <= 11


@pytest.mark.parametrize("bad", ["nan", "-1.0", "1e300"])
def test_a_sample_time_no_bin_can_hold_is_refused(run_path, bad):
    csv = run_path / "samples.csv"
    lines = csv.read_text().splitlines()
    header = lines[0].split(",")
    row = lines[3].split(",")
    row[header.index("time_s")] = bad
    lines[3] = ",".join(row)
    csv.write_text("\n".join(lines) + "\n")
    # one line naming the value: what no bin can hold, or (1e300) what no bench reads
    with pytest.raises(ValueError, match=re.escape(f"time_s={float(bad)!r} is ")):
        aggregate_samples(run_path, bin_s=1.0)


def test_closed_run_with_rows_lost_names_the_loss(run_path):
    # A complete run copied short: whole rows gone, no partial row to betray it.
    counted = json.loads((run_path / "run.json").read_text())["counters"]["samples"]
    lines = (run_path / "samples.csv").read_text().splitlines(keepends=True)
    (run_path / "samples.csv").write_text("".join(lines[:101]))
    steps = (run_path / "steps.csv").read_text().splitlines(keepends=True)
    (run_path / "steps.csv").write_text("".join(steps[:2]))
    run = load_run(run_path)
    assert run.status == "complete"
    done = run.meta.steps_done
    assert f"samples.csv holds 100 samples, run.json counted {counted}: {counted - 100} lost" \
        in run.problems
    assert f"steps.csv holds 1 steps, run.json counted {done} done: {done - 1} lost" \
        in run.problems


def test_intact_run_has_no_problems(run_path):
    assert load_run(run_path).problems == []


def test_binary_samples_csv_is_named(run_path):
    (run_path / "samples.csv").write_bytes(b"\xfa\xfb,\n" * 100)  # not UTF-8
    with pytest.raises(ValueError, match=r"samples\.csv is corrupt: expected the header"):
        load_run(run_path)


def test_a_negative_steps_done_is_refused(run_path):
    # steps_done -3 loaded as a run that had done fewer than no steps
    meta = json.loads((run_path / "run.json").read_text())
    meta["steps_done"] = -3
    write_json_atomic(run_path / "run.json", meta)
    with pytest.raises(ValueError) as caught:
        load_run(run_path)
    assert str(caught.value) == (f"{run_path / 'run.json'}: steps_done=-3 is invalid: expected "
                                 "a count >= 0")


def test_a_run_folder_saved_again_on_windows_loads_the_same(run_path):
    # a BOM (Excel's "CSV UTF-8", Windows editors) and CRLF line ends: refused as corrupt
    from mkm.bench.reprocess import overlay_config

    before = load_run(run_path)
    cell = overlay_config(run_path, run_path / "config.toml").loadcell
    for name in ("run.json", "samples.csv", "steps.csv", "commands.csv", "config.toml"):
        text = (run_path / name).read_text(encoding="utf-8")
        (run_path / name).write_bytes(b"\xef\xbb\xbf" + text.replace("\n", "\r\n").encode())
    after = load_run(run_path)
    assert after.problems == [] and after.status == before.status
    pd.testing.assert_frame_equal(after.steps, before.steps)
    pd.testing.assert_frame_equal(after.samples, before.samples)
    assert overlay_config(run_path, run_path / "config.toml").loadcell == cell
