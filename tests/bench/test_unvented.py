"""bench.unvented: the marker a pressurising run holds, and what counts as dead."""

import json
import re
import threading
import time
from pathlib import Path

import pytest

from mkm.bench.storage import OUTCOME_FIELDS, ProcessIdentity
from mkm.bench.unvented import BenchLease, bench_folder, find_unvented


def test_a_live_lease_is_not_unvented_and_release_removes_it(tmp_path):
    lease = BenchLease("sim-Dev1", tmp_path / "run", "2026-12-01T10:00:00+00:00")
    lease.started()
    lease.end()  # the test writes the marker itself from here on
    lease.command(1.5)
    marker = json.loads(lease.path.read_text())
    assert marker["last_command_bar"] == 1.5 and marker["run_path"] == str(tmp_path / "run")
    assert find_unvented("sim-Dev1") == []  # this process is alive
    lease.release()
    assert not list(bench_folder("sim-Dev1").glob("*.json"))


def test_a_dead_or_reused_pid_is_unvented(tmp_path):
    lease = BenchLease("ni-Dev1", tmp_path / "run", "2026-12-01T10:00:00+00:00")
    lease.started()
    lease.end()  # the test writes the marker itself from here on
    lease.command(2.5)
    # the same pid started at another time: another process now holds it
    data = json.loads(lease.path.read_text())
    data["process"]["started_unix_s"] -= 100.0
    lease.path.write_text(json.dumps(data))
    ((_, marker),) = find_unvented("ni-Dev1")
    assert marker.last_command_bar == 2.5 and "ended without venting" in marker.describe()
    assert find_unvented("sim-Dev1") == []  # another bench


def test_process_identity_of_this_process_is_alive():
    me = ProcessIdentity.current()
    assert me.alive()
    assert not ProcessIdentity(me.pid, me.host, me.started_unix_s + 5.0, me.boot_unix_s).alive()
    assert not ProcessIdentity(me.pid, "another-host", me.started_unix_s).alive()


@pytest.mark.parametrize("boot_moved_s, start_moved_s, alive", [
    (3600.0, 3600.0, True),  # the clock set an hour on, Linux: start times move with the boot
    (-30.0, -30.0, True),  # set back 30 s
    (3600.0, 0.0, True),  # Windows: the start time it stamped stays
    (0.0, 100.0, False),  # the pid reused by a process started later
    (86400.0, 5000.0, False),  # rebooted a day later, the pid reused at another uptime
])
def test_a_live_process_stays_alive_when_the_clock_is_set(monkeypatch, boot_moved_s,
                                                          start_moved_s, alive):
    # the system clock set while a run records (an NTP step, a virtual machine resumed): the
    # boot time psutil gives moved, so the live run was called rebooted-since, dead: its folder
    # loaded as `incomplete`, "stopped without closing its record (killed or crashed)"
    import psutil

    me = ProcessIdentity.current()
    boot_time, create_time = psutil.boot_time, psutil.Process.create_time
    monkeypatch.setattr(psutil, "boot_time", lambda: boot_time() + boot_moved_s)
    monkeypatch.setattr(psutil.Process, "create_time",
                        lambda self: create_time(self) + start_moved_s)
    assert me.alive() is alive


def test_a_run_whose_vent_was_not_verified_is_said_so_not_unvented(config, tmp_path):
    # stuck at 0.5 bar from 4 s: the follow interlock vents, the monitor still reads 0.5 bar;
    # the marker stays, last commanded 0 bar, and said "ended without venting ... last
    # commanded pressure was 0 bar": a contradiction of what happened
    from mkm.bench.run import acquire

    c = config.replace(sim={"faults": {"regulator_stuck_at_s": 4.0}})
    result = acquire(c, out_root=tmp_path / "runs", notify=lambda m: None)
    assert result.manual_vent_required
    (path,) = bench_folder("sim-Dev1").glob("*.json")
    data = json.loads(path.read_text())
    data["process"]["started_unix_s"] -= 100.0  # as if its process had died
    path.write_text(json.dumps(data))
    ((_, marker),) = find_unvented("sim-Dev1")
    said = marker.describe()
    assert "ended without venting" not in said and "last commanded pressure was 0" not in said
    assert f"run {result.path.resolve()}" in said
    assert "vented (0 bar commanded at " in said and "but its vent was not verified: the " \
        "monitor still reads 0.49" in said
    # a run killed between its vent and the check, and one killed before any command
    marker.vent_unverified = ""
    assert "ended after its vent (0 bar commanded at" in marker.describe()
    marker.last_command_utc = ""
    assert marker.describe().endswith("ended before any pressure was commanded")


def test_a_stop_while_the_first_marker_is_written_leaves_no_marker(config, tmp_path,
                                                                   monkeypatch):
    # a stop signal (here a second Ctrl-C) arrives while the run's first bench marker is being
    # written, before any pressure: the run ended aborted, vented, but its marker stayed, and
    # the next command on the bench vented "a run that ended before any pressure was
    # commanded" and named it. Now the shutdown removes it as after any other stop
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend
    from mkm.bench.unvented import StateFolderThread

    wait, interrupted = StateFolderThread.wait, []

    def signal_once_written(self, ticket, timeout_s):
        done = wait(self, ticket, timeout_s)
        if isinstance(self, BenchLease) and not interrupted:
            interrupted.append(ticket)
            raise KeyboardInterrupt  # what the second Ctrl-C raises without the handlers
        return done

    monkeypatch.setattr(StateFolderThread, "wait", signal_once_written)
    run = BenchRun(config, SimBackend(config), tmp_path, handle_signals=False,
                   notify=lambda m: None)
    result = run.execute()
    assert interrupted == [1]  # the first write's
    assert result.status == "aborted" and result.exit_code == 130
    assert result.reason == "stopped by a second Ctrl-C (SIGINT) at once; vented"
    assert not list(bench_folder("sim-Dev1").glob("*.json"))
    assert find_unvented("sim-Dev1") == []


@pytest.fixture
def dead_runs_hang(monkeypatch):
    """The bench state folder hangs right after the bench's lock was taken, as the markers of
    dead runs are looked for (the lock's wait is the usual one; the search's, 0 s: the hang is
    certain); ``release`` lets it answer. Yields the event."""
    from mkm.bench import ownership
    from mkm.bench.ownership import BenchOwner

    release, is_dir, enter = threading.Event(), Path.is_dir, BenchOwner.__enter__
    benches = bench_folder("sim-Dev1")

    def hanging(self, *args, **kwargs):
        if self == benches:
            release.wait(30)  # released by the test
        return is_dir(self, *args, **kwargs)

    def taken(self):
        owner = enter(self)
        monkeypatch.setattr(ownership, "STATE_START_S", 0.0)
        return owner

    monkeypatch.setattr(Path, "is_dir", hanging)
    monkeypatch.setattr(BenchOwner, "__enter__", taken)
    try:
        yield release
    finally:
        release.set()


HANGS = ("did not answer within 0 s as the runs that died on this bench were looked for (it "
         "hangs): ")


@pytest.mark.parametrize("argv", [["acquire", "--no-progress"], ["tare", "--backend", "sim"]])
def test_a_state_folder_that_hangs_as_dead_runs_are_looked_for_refuses_untouched(
        argv, tmp_path, monkeypatch, mkm_cli, dead_runs_hang):
    # the state folder answers as the lock is taken, then hangs as the markers of dead runs
    # are looked for: the command never returned. Now it refuses in one line once
    # STATE_START_S has passed, the device never opened
    from mkm.bench.sim import SimBackend

    opened = []
    monkeypatch.setattr(SimBackend, "open", lambda self: opened.append(self))
    code, out, err = mkm_cli([*argv, "--out", str(tmp_path / "runs")] if argv[0] == "acquire"
                             else argv)
    assert code == 1 and out == "" and not opened
    assert not list((tmp_path / "runs").glob("*"))  # --out is checked, no run folder made
    *simulated, error = err.splitlines()  # tare says SIMULATED first
    assert simulated == ([] if argv[0] == "acquire" else
                         [f"mkm {argv[0]}: SIMULATED bench (sim): no hardware is driven"])
    assert error.startswith(f"mkm {argv[0]}: error: the bench state folder ")
    assert error.endswith(HANGS + "nothing was touched; the bench is let go once it answers, or "
                          "as this process ends")


def test_a_run_refused_so_lets_the_bench_go_once_the_folder_answers(config, tmp_path,
                                                                   dead_runs_hang):
    from mkm.bench.ownership import StateFolderBroken
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    backend = SimBackend(config)
    run = BenchRun(config, backend, tmp_path, handle_signals=False, notify=lambda m: None)
    with pytest.raises(StateFolderBroken, match=re.escape(HANGS + "nothing was touched")):
        run.execute()
    assert backend.commands == [] and run.owner.lock is not None  # never opened, still held
    dead_runs_hang.set()
    state = run.owner._state
    assert state.wait(state.posted, 30) and run.owner.lock is None  # let go once it answered


def test_mkm_vent_vents_when_the_folder_hangs_as_dead_runs_are_looked_for(dead_runs_hang):
    from mkm.bench import procedures
    from mkm.bench.config import load_config

    out = procedures.vent(load_config(), backend="sim", notify=lambda m: None, stop_wait_s=0.0)
    assert out["vented"] and out["pressure_bar"] < 0.05
    (problem,) = out["bookkeeping"]  # `mkm vent` says it on one line, exit 1
    assert (HANGS + "the bench was vented, the runs that died on it were not named") in problem


def test_mkm_vent_after_a_monitor_that_did_not_follow_does_not_call_the_vent_verified(
        config, tmp_path):
    # the monitor reads 0 bar whatever the pressure: the run's follow interlock vents and asks
    # for a vent by hand (its 0 bar proves nothing). `mkm vent` then read the same stuck 0 bar,
    # said "vented: 0.000 bar" and removed the marker; now it vents, names the run and says the
    # reading does not verify the vent
    from mkm.bench.backend import BenchError
    from mkm.bench.procedures import vent
    from mkm.bench.run import acquire

    c = config.replace(sim={"truth": {"monitor_stuck_bar": 0.0}})
    result = acquire(c, out_root=tmp_path / "runs", notify=lambda m: None)
    assert result.manual_vent_required and result.exit_code == 4
    (path,) = bench_folder("sim-Dev1").glob("*.json")
    data = json.loads(path.read_text())
    assert data["unfollowed_bar"] == 0.5
    data["process"]["started_unix_s"] -= 100.0  # as if its process had died
    path.write_text(json.dumps(data))
    notes = []
    with pytest.raises(BenchError) as caught:
        vent(c, notify=notes.append)
    assert re.match(
        re.escape("the vent went out, but the monitor's 0.000 bar does not verify it: in run "
                  f"{result.path.resolve()} the vent could not be verified (the monitor read ")
        + r"0\.00[0-9] bar against 0\.5 bar commanded before the vent, so its reading after it "
        r"proves nothing: stuck near zero, a monitor reads so whatever the muscle holds; ",
        str(caught.value)), str(caught.value)
    assert "check the monitor and the supply); check the muscle and the monitor" in \
        str(caught.value)
    assert any("proves nothing" in n and n.endswith("vented now") for n in notes)
    # a monitor that followed: the marker of a run killed mid-step is vented and verified
    data.update(vent_unverified="", unfollowed_bar=None, last_command_bar=1.0)
    path.write_text(json.dumps(data))
    assert vent(config, notify=notes.append)["vented"]


def _died(bench_key: str = "sim-Dev1") -> None:
    """The bench's one marker made that of a process that died."""
    (path,) = bench_folder(bench_key).glob("*.json")
    data = json.loads(path.read_text())
    data["process"]["started_unix_s"] -= 100.0
    path.write_text(json.dumps(data))


def test_mkm_vent_after_a_load_cell_that_doubted_the_vent_says_what_the_run_found(tmp_path):
    # A slack muscle (eps 0.18, 0.25-0.75 bar, below its threshold) on a load-cell zero
    # drifting 4 N/min: the run's vent check cannot tell it from a muscle still pulling and
    # asks for a vent by hand. The next `mkm vent` refused with "the same monitor read below
    # the 0.25 bar commanded (stuck, or no supply)": that monitor read every command. It says
    # what the run's check found instead.
    from mkm.bench.backend import BenchError
    from mkm.bench.config import load_config
    from mkm.bench.procedures import vent
    from mkm.bench.run import acquire

    c = load_config(eps=0.18).replace(
        sequence={"pressures_bar": (0.25, 0.5, 0.75), "preconditioning_cycles": 0},
        sim={"model": "thickwall", "truth": {"loadcell_drift_N_per_min": 4.0}})
    result = acquire(c, out_root=tmp_path / "runs", notify=lambda m: None)
    assert result.manual_vent_required and result.exit_code == 4, result.reason
    assert "the load cell still reads" in result.reason
    _died()
    with pytest.raises(BenchError) as caught:
        vent(c, notify=lambda m: None)
    said = str(caught.value)
    assert said.startswith("the vent went out, but the monitor's 0.000 bar does not verify it: "
                           f"in run {result.path.resolve()} the vent could not be verified (the "
                           "monitor read "), said
    assert ", but the load cell still reads " in said
    assert "read below the" not in said and "no supply" not in said


def test_mkm_vent_after_a_stuck_load_cell_verifies_on_the_monitor_that_fell(config, tmp_path):
    # The load cell sticks at 12 s (on the 1.0 bar step): the run stops, vented, the monitor
    # falling from 1.0 bar to 0.005, and asks for a vent by hand since the stuck cell weighs
    # nothing. The next `mkm vent` refused the monitor's reading with "the same monitor read
    # below the 1 bar commanded (stuck, or no supply)", of a monitor that followed every command
    # and fell: only the load cell was doubted, so the monitor verifies the vent.
    from mkm.bench.procedures import vent
    from mkm.bench.run import acquire
    from mkm.bench.storage import load_run

    c = config.replace(sim={"faults": {"loadcell_stuck_at_s": 12.0}})
    result = acquire(c, out_root=tmp_path / "runs", notify=lambda m: None)
    assert result.manual_vent_required and result.exit_code == 4, result.reason
    assert load_run(result.path).meta.vent_check["doubted"] == "the load cell"
    _died()
    notes = []
    out = vent(config, notify=notes.append)
    assert out["vented"] and out["pressure_bar"] < config.safety.vent_below_bar
    assert any("stuck or disconnected" in n and n.endswith("vented now") for n in notes)


@pytest.fixture
def dead_marker_hangs(tmp_path, monkeypatch):
    """A marker of a run that died with 1 bar commanded; the state folder hangs as it is
    removed, until the yielded event is set (the searches before it answer as usual; the wait
    for the removal is 0 s: the hang is certain)."""
    from mkm.bench import ownership
    from mkm.bench.ownership import BenchOwner

    lease = BenchLease("sim-Dev1", tmp_path / "dead-run", "2026-12-01T10:00:00+00:00")
    lease.started()
    lease.end()  # the test writes the marker itself from here on
    lease.command(1.0)
    data = json.loads(lease.path.read_text())
    data["process"]["started_unix_s"] -= 100.0  # as if its process had died
    lease.path.write_text(json.dumps(data))
    release, unlink, dead_runs = threading.Event(), Path.unlink, BenchOwner.dead_runs

    def hanging(self, *args, **kwargs):
        if self == lease.path:
            release.wait(120)  # released by the test
        return unlink(self, *args, **kwargs)

    def found(self, *args, **kwargs):
        markers = dead_runs(self, *args, **kwargs)
        monkeypatch.setattr(ownership, "STATE_START_S", 0.0)
        return markers

    monkeypatch.setattr(Path, "unlink", hanging)
    monkeypatch.setattr(BenchOwner, "dead_runs", found)
    try:
        yield release, lease.path
    finally:
        release.set()


NOT_REMOVED = ("did not answer within 0 s as the dead runs' folders were mended and their "
               "markers removed (it hangs): not yet done, done once it answers (the bench is let "
               "go after it, or as this process ends)")


@pytest.mark.parametrize("command", ["acquire", "vent"])
def test_a_state_folder_that_hangs_as_a_dead_runs_marker_is_removed_does_not_hold_the_command(
        command, config, tmp_path, dead_marker_hangs):
    # the next command found the dead run, vented, and removed its marker in the state folder,
    # which hangs from then on (a roaming profile on a network share): the command never
    # returned. Now the removal is waited for within a bound, the run is named with what is
    # left to do, and the command goes on; the marker goes once the folder answers
    from mkm.bench import procedures
    from mkm.bench.run import acquire

    release, marker = dead_marker_hangs
    notes, out = [], {}
    worker = threading.Thread(target=lambda: out.update(result=acquire(
        config, out_root=tmp_path / "runs", notify=notes.append) if command == "acquire" else
        procedures.vent(config, notify=notes.append, stop_wait_s=0.0)), daemon=True)
    worker.start()
    worker.join(60)
    hung = worker.is_alive()
    release.set()
    worker.join(120)
    assert not hung, "the command waited for the hung state folder"
    said = [n for n in notes if "dead-run" in n]
    assert len(said) == 1 and "ended without venting; its last commanded pressure was 1 bar" \
        in said[0]
    assert ": vented now; the bench state folder " in said[0] and said[0].endswith(NOT_REMOVED)
    result = out["result"]
    if command == "acquire":
        assert result.status == "complete" and result.exit_code == 0, result.reason
        assert [m.run_path for m in result.unvented_before] == [str(tmp_path / "dead-run")]
    else:
        assert result["vented"] and result["pressure_bar"] < config.safety.vent_below_bar
    for _ in range(600):  # the marker goes once the folder answers (the test's own bound)
        if not marker.exists():
            break
        threading.Event().wait(0.1)
    assert not marker.exists()


def test_a_marker_left_by_a_run_is_kept_through_the_next_run_of_the_same_process(config,
                                                                                 tmp_path):
    # a run whose vent is not verified keeps its marker for the next command; a second run in
    # the same process (the Python API, `mkm demo`) wrote its own marker in the same file and
    # removed it as it ended, so nothing named the first run once the process had ended. Now
    # each run has a marker of its own
    from mkm.bench.run import acquire

    stuck = acquire(config.replace(sim={"faults": {"regulator_stuck_at_s": 4.0}}),
                    out_root=tmp_path / "runs", notify=lambda m: None)
    assert stuck.manual_vent_required
    after = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    assert after.status == "complete", after.reason
    (path,) = bench_folder("sim-Dev1").glob("*.json")
    data = json.loads(path.read_text())
    assert data["run_path"] == str(stuck.path.resolve()) and data["vent_unverified"]
    data["process"]["started_unix_s"] -= 100.0  # as if the process had ended
    path.write_text(json.dumps(data))
    ((_, marker),) = find_unvented("sim-Dev1")
    assert "but its vent was not verified: the monitor still reads 0.49" in marker.describe()


@pytest.mark.parametrize("kept", [{"status": "running", "reason": "r", "ended_utc": None},
                                  {"status": "done", "reason": "r", "ended_utc": None},
                                  {"status": "failed", "reason": 3, "ended_utc": None},
                                  {"status": "failed"}, ["failed"], "failed"])
def test_a_kept_outcome_that_is_none_a_run_ends_with_is_ignored(tmp_path, kept):
    # a marker edited by hand or by another version: the dead run is still named and vented,
    # and mended as killed, never with a status a run does not end with
    lease = BenchLease("sim-Dev1", tmp_path / "run", "2026-12-01T10:00:00+00:00")
    lease.started()
    lease.end()  # the test writes the marker itself from here on
    lease.command(1.0)
    lease.ended(kept)
    data = json.loads(lease.path.read_text())
    data["process"]["started_unix_s"] -= 100.0  # as if its process had died
    lease.path.write_text(json.dumps(data))
    ((_, marker),) = find_unvented("sim-Dev1")
    assert marker.outcome is None
    assert "ended without venting; its last commanded pressure was 1 bar" in marker.describe()


def test_the_state_folder_threads_end_with_their_owners_and_the_locks_still_exclude(
        config, tmp_path):
    # every BenchOwner, BenchLease and `mkm vent` asking a holder to stop started a thread that
    # never ended (114 after two test modules); each now ends once its owner let go, the lock
    # released on the thread that took it (filelock's locks are per thread)
    from mkm.bench import procedures
    from mkm.bench.ownership import BenchBusy, BenchOwner

    before = set(threading.enumerate())
    for cycle in range(50):
        with BenchOwner("sim-Dev1", "acquire") as owner:
            owner.stop_request()  # the run's loop polls it: a reader thread of its own
            with pytest.raises(BenchBusy):  # held: a second owner is refused
                BenchOwner("sim-Dev1", "tare").__enter__()
            lease = BenchLease("sim-Dev1", tmp_path / f"run-{cycle}", "2026-12-01T10:00:00+00:00")
            lease.started()
            lease.command(0.5)
            assert lease.wait(lease.post(lease.release), 5.0) and lease.error is None
            lease.end()
        with BenchOwner("sim-Dev1", "tare"):  # let go: taken again at once
            pass
    procedures.vent(config, notify=lambda m: None)  # asks a holder to stop: none
    started, waited = set(threading.enumerate()) - before, time.monotonic() + 5.0
    for thread in started:  # each ends once its last update is done
        thread.join(max(waited - time.monotonic(), 0.0))
    assert not [t.name for t in started if t.is_alive()]
    assert not list(bench_folder("sim-Dev1").glob("*.json"))


def test_a_run_leaves_no_thread_behind(config, tmp_path):
    # its bench's owner, its stop request's reader, its marker's lease and its console
    from mkm.bench.run import acquire

    before = set(threading.enumerate())
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert result.status == "complete", result.reason
    started, waited = set(threading.enumerate()) - before, time.monotonic() + 5.0
    for thread in started:
        thread.join(max(waited - time.monotonic(), 0.0))
    assert not [t.name for t in started if t.is_alive()]


@pytest.mark.parametrize("edit, whole", [
    (lambda kept: kept, True),
    (lambda kept: {k: kept[k] for k in OUTCOME_FIELDS}, False),  # an older version's marker
    (lambda kept: {**kept, "gaps": [{"after_sample": "x"}]}, False),  # edited by hand
    (lambda kept: {**kept, "started_utc": "2026-01-01T00:00:00+00:00"}, False),  # another run's
], ids=["whole", "older", "invalid", "another-run"])
def test_a_kept_record_not_whole_or_not_this_runs_is_written_as_its_outcome_alone(
        config, tmp_path, monkeypatch, edit, whole):
    # the bench marker keeps the whole final record a refused run.json was to hold, and the
    # next command writes it; a marker of an older version (its outcome alone), one edited by
    # hand or one whose record is another run's is written as its status, reason, end and
    # manual vent over run.json, and said so. The next run records the dead run's outcome, not
    # its whole record (that is in the dead run's own run.json)
    import errno

    from mkm.bench.run import acquire
    from mkm.bench.storage import RunWriter, load_run

    write = RunWriter.write_meta

    def full_at_the_end(self, meta):
        if meta.status != "running":
            raise OSError(errno.ENOSPC, "No space left on device")
        write(self, meta)

    with monkeypatch.context() as full:
        full.setattr(RunWriter, "write_meta", full_at_the_end)
        dead = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    (path,) = bench_folder("sim-Dev1").glob("*.json")
    data = json.loads(path.read_text())
    kept = data["outcome"]
    assert kept["vent_check"]["verified"] and kept["status"] == "complete"
    data["outcome"] = edit(kept)
    data["process"]["started_unix_s"] -= 100.0  # as if its process had died
    path.write_text(json.dumps(data))
    run_json = dead.path / "run.json"
    record = json.loads(run_json.read_text())
    assert record["status"] == "running" and record["vent_check"] is None
    record["process"]["started_unix_s"] -= 100.0
    run_json.write_text(json.dumps(record))
    notes = []
    after = acquire(config, out_root=tmp_path / "runs", notify=notes.append)
    (said,) = [n for n in notes if "vented now" in n]
    alone = "" if whole else " (its marker kept the outcome alone, not the whole record)"
    assert said.endswith(f"vented now; run.json mended: status complete, "
                         f"{len(load_run(dead.path).samples)} samples on disk{alone}")
    mended = load_run(dead.path)
    assert mended.status == "complete" and mended.reason.startswith(kept["reason"])
    assert mended.meta.vent_check == (kept["vent_check"] if whole else None)
    assert mended.meta.started_utc == record["started_utc"]
    (noted,) = load_run(after.path).meta.unvented_before
    assert noted["outcome"] == {k: kept[k] for k in OUTCOME_FIELDS}
