"""bench.recorder: a disk that fills during a run loses no more than it must and hides nothing."""

import errno
import re
import time
from pathlib import Path

import pytest

from mkm.bench.storage import RunWriter, load_run
from mkm.cli import main


def test_disk_full_during_a_run_vents_syncs_and_prints_the_run(tmp_path, capsys, monkeypatch):
    calls = {"samples": 0, "closed": 0}
    append, close = RunWriter.append_samples, RunWriter.close

    def full_after_30(self, rows):
        calls["samples"] += 1
        if calls["samples"] > 30:
            raise OSError(errno.ENOSPC, "No space left on device")
        append(self, rows)

    def counted_close(self):
        calls["closed"] += 1
        close(self)

    monkeypatch.setattr(RunWriter, "append_samples", full_after_30)
    monkeypatch.setattr(RunWriter, "close", counted_close)
    rc = main(["acquire", "--pressures", "0.5", "--out", str(tmp_path / "runs"),
               "--no-progress"])
    captured = capsys.readouterr()
    assert rc == 2  # storage failed: exit 2, like bad input
    assert captured.err.count("\n") == 2 and "mkm acquire: SIMULATED bench (sim)" in captured.err
    assert "run SIMULATED failed: recording failed for samples 30 (No space left on " \
        "device)" in captured.err
    run = load_run(Path(captured.out.strip().splitlines()[-1]))  # the path is still printed
    assert run.status == "failed" and len(run.samples) == 30  # every sample written is kept
    assert run.commands["purpose"].iloc[-1] == "vent" and run.commands["ok"].iloc[-1]
    assert calls["closed"] == 1  # synced and closed


# a disk that hangs: the loop never waits for it ----------------------------------------------

def _hung_disk(monkeypatch, from_sample):
    """samples.csv's appends block (a network share that hangs) from the block holding
    ``from_sample`` until ``release`` is set; ``hung`` says the disk is hanging."""
    import threading

    release, hung = threading.Event(), threading.Event()
    append = RunWriter.append_samples

    def blocking(self, rows):
        if rows[-1].sample >= from_sample and not release.is_set():
            hung.set()
            release.wait(120)  # a net under a broken fix, never reached when it works
        append(self, rows)

    monkeypatch.setattr(RunWriter, "append_samples", blocking)
    return release, hung


def _hung_path(monkeypatch, method: str, suffix: str):
    """``Path.<method>`` blocks on files ending ``suffix`` (a bench state folder on a share that
    hangs) until ``release`` is set; ``hung`` says it is hanging."""
    import threading

    release, hung = threading.Event(), threading.Event()
    original = getattr(Path, method)

    def hanging(self, *args, **kwargs):
        if self.suffix == suffix and not release.is_set():
            hung.set()
            release.wait(120)  # a net under a broken fix, never reached when it works
        return original(self, *args, **kwargs)

    monkeypatch.setattr(Path, method, hanging)
    return release, hung


def _run_in_thread(config, tmp_path, monkeypatch):
    """``acquire`` in a thread of its own; the first vent after a pressure is reported through
    ``vented``, with the device's sample clock at it and the rows samples.csv held then."""
    import threading

    from mkm.bench.run import acquire
    from mkm.bench.sim import SimBackend

    vented, at, out = threading.Event(), {}, {}
    write = SimBackend.write_command

    def spy(self, volts):
        write(self, volts)
        if volts > 0:
            at["pressurised"] = True
        elif at.get("pressurised") and not vented.is_set():
            at["sample"] = self._head
            (csv,) = Path(tmp_path).glob("*/samples.csv")
            at["rows_on_disk"] = len(csv.read_text(encoding="utf-8").splitlines()) - 1
            vented.set()

    monkeypatch.setattr(SimBackend, "write_command", spy)
    worker = threading.Thread(target=lambda: out.update(result=acquire(
        config, out_root=tmp_path, notify=lambda m: None)), daemon=True)
    worker.start()
    return worker, vented, at, out


def test_an_over_pressure_while_the_disk_hangs_is_vented_at_once(config, tmp_path, monkeypatch):
    # the run folder's disk hangs from the first sample; the regulator overshoots 0.14 bar over
    # its 2.5 bar command (max_pressure_bar 2.5): above 2.55 bar for more than 1 s is an
    # over-pressure. The loop used to block in the write, so nothing was watched or vented
    # until the disk came back; now the vent goes out at the sample it does with a good disk
    from mkm.bench.run import acquire

    c = config.replace(sequence={"pressures_bar": (2.5,)},
                       sim={"faults": {"overshoot_bar": 0.14}})
    reference = load_run(acquire(c, out_root=tmp_path / "reference",
                                 notify=lambda m: None).path)
    normal = reference.commands[reference.commands["purpose"] == "interlock vent"]
    assert reference.status == "failed" and len(normal) == 1
    release, hung = _hung_disk(monkeypatch, 0)
    worker, vented, at, out = _run_in_thread(c, tmp_path / "runs", monkeypatch)
    try:
        assert vented.wait(60), "the loop waited for the hung disk: nothing was vented"
        assert at["rows_on_disk"] == 0 and not release.is_set()  # vented, the disk hung
        assert at["sample"] == normal["sample"].iloc[0]  # the same sample as with a good disk
    finally:
        release.set()
        worker.join(120)
    result = out["result"]
    run = load_run(result.path)
    assert result.status == "failed" and result.reason.startswith("over-pressure interlock")
    assert run.meta.reason == result.reason
    s = run.samples
    assert list(s["sample"]) == list(range(len(s)))  # every sample held reached the disk
    assert run.meta.counters["samples"] == len(s) > normal["sample"].iloc[0]
    tripped = s[s["flags"].str.contains("interlock")]
    assert tripped["sample"].tolist() == [normal["sample"].iloc[0] - 1]


def test_a_disk_that_hangs_too_long_stops_the_run_vented(config, tmp_path, monkeypatch):
    # the disk hangs from the first sample and finishes no write within DISK_STUCK_S (30 s by
    # the recorder's clock, put forward as it hangs): the run vents and stops with the reason;
    # once the disk returns, every sample held in memory is written and run.json says why
    from mkm.bench import recorder

    offset = _recorder_clock(monkeypatch)
    samples = recorder.Recorder.samples

    def hanging_from_20(self, rows):  # the disk hangs 31 s once 20 samples are queued
        samples(self, rows)
        if rows[-1].sample >= 20:
            offset[0] = 31.0

    monkeypatch.setattr(recorder.Recorder, "samples", hanging_from_20)
    release, hung = _hung_disk(monkeypatch, 0)
    worker, vented, at, out = _run_in_thread(config, tmp_path, monkeypatch)
    try:
        assert vented.wait(60), "the loop waited for the hung disk: nothing was vented"
        assert at["rows_on_disk"] == 0 and not release.is_set()
        # stuck at the first block past sample 20 (21 samples, 2.1 s of them, held); the vent
        # is written after that block, at sample 21 by the device's clock
        assert at["sample"] == 21
    finally:
        release.set()
        worker.join(120)
    result = out["result"]
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 2
    assert re.match(r"disk not taking the record: no write finished for 3[01] s, 21 samples "
                    r"\(2\.1 s, the oldest from 0 s\) held in memory; vented", result.reason)
    assert run.meta.reason == result.reason and run.meta.vent_check["verified"]
    s = run.samples
    assert list(s["sample"]) == list(range(len(s))) and s["sample"].iloc[-1] > 21
    assert run.meta.counters["samples"] == len(s)
    assert run.commands["purpose"].tolist()[-2:] == ["interlock vent", "vent"]


def _recorder_clock(monkeypatch):
    """The recorder's clock (``time.monotonic``) put forward by ``offset[0]`` seconds: a write
    that takes that long, without a test that waits for it."""
    import time
    import types

    from mkm.bench import recorder

    offset = [0.0]
    monkeypatch.setattr(recorder, "time", types.SimpleNamespace(
        monotonic=lambda: time.monotonic() + offset[0], sleep=time.sleep))
    return offset


def test_a_disk_slow_for_one_write_while_the_virtual_clock_runs_is_not_stuck(tmp_path,
                                                                             monkeypatch):
    # a write of samples.csv takes 1.5 s (a loaded machine's sync), the paper's run on the
    # virtual clock acquiring 38 s of samples meanwhile: the run stopped, "disk not taking
    # the record", the disk working all along (more than 30 s of samples held, no write done
    # for 1 s). Now a disk is stuck when it finishes no write for DISK_STUCK_S of its own time,
    # whatever the samples held meanwhile: the run completes, every sample once and in order
    import threading

    from mkm.bench import recorder
    from mkm.bench.config import load_config
    from mkm.bench.run import acquire

    offset = _recorder_clock(monkeypatch)
    queued, more = [0], threading.Event()
    samples, append = recorder.Recorder.samples, RunWriter.append_samples

    def counting(self, rows):
        samples(self, rows)
        queued[0] += len(rows)
        if queued[0] >= 400:  # 380 samples (38 s) held behind the slow write
            more.set()

    def slow_once(self, rows):
        if rows[-1].sample >= 20 and not offset[0]:
            offset[0] = 1.5  # the write takes 1.5 s
            more.wait(60)  # a net under a broken fix, never reached when it works
        append(self, rows)

    monkeypatch.setattr(recorder.Recorder, "samples", counting)
    monkeypatch.setattr(RunWriter, "append_samples", slow_once)
    result = acquire(load_config(), out_root=tmp_path, notify=lambda m: None)
    assert more.is_set() and (result.status, result.exit_code) == ("complete", 0), result.reason
    run = load_run(result.path)
    assert run.samples["sample"].tolist() == list(range(queued[0]))


def test_a_disk_that_writes_slower_than_the_run_acquires_stops_it_vented(tmp_path,
                                                                          monkeypatch):
    # each write of samples.csv takes 0.2 s (a share far away), one block of 0.1 s of samples
    # each, the run acquiring two blocks a write: the disk finished a write every 0.2 s, so it
    # was never stuck, while the samples held in memory grew without end (until 300 000 rows,
    # 8 h at 10 Hz), the record on disk further and further behind and the run's end waiting
    # for all of it. Now a disk that has trailed by more than DISK_STUCK_S of samples for
    # DISK_STUCK_S stops the run, vented, every sample kept
    import threading

    from mkm.bench import recorder
    from mkm.bench.config import load_config
    from mkm.bench.run import acquire

    offset, cond, count = _recorder_clock(monkeypatch), threading.Condition(), [0, 0]
    ended = threading.Event()
    samples, append = recorder.Recorder.samples, RunWriter.append_samples
    wait_written = recorder.Recorder.wait_written

    # two blocks queued a write, both ways: the loop waits for the disk, and the disk for the
    # loop, whatever a loaded machine slows (a disk that waited for nothing keeps up with a
    # slowed loop, holds nothing, and the run completes). Nets under a broken fix: 60 s
    def two_blocks_a_write(self, rows):  # count: blocks queued, blocks written
        with cond:
            cond.wait_for(lambda: 2 * count[1] >= count[0] - 1, 60)
            count[0] += 1
            cond.notify_all()
        samples(self, rows)

    def slow(self, rows):
        with cond:  # the write of block w once the loop has queued 2w - 1, until the run ends
            cond.wait_for(lambda: count[0] >= 2 * count[1] + 1 or ended.is_set(), 60)
        offset[0] += 0.2  # the write takes 0.2 s
        append(self, rows)
        with cond:
            count[1] += 1
            cond.notify_all()

    def waited_at_the_end(self, timeout_s=None):  # the run queues no more: the disk goes on
        with cond:
            ended.set()
            cond.notify_all()
        return wait_written(self, timeout_s)

    monkeypatch.setattr(recorder.Recorder, "samples", two_blocks_a_write)
    monkeypatch.setattr(RunWriter, "append_samples", slow)
    monkeypatch.setattr(recorder.Recorder, "wait_written", waited_at_the_end)
    result = acquire(load_config(), out_root=tmp_path, notify=lambda m: None)
    assert (result.status, result.exit_code) == ("failed", 2), result.reason
    assert re.match(r"disk not taking the record: slower than the run, \d+ samples \([\d.]+ "
                    r"s, the oldest from [\d.]+ s\) held in memory, more than 30 s of samples "
                    r"for 30 s; vented", result.reason), result.reason
    run = load_run(result.path)
    assert run.meta.vent_check["verified"]
    assert run.samples["sample"].tolist() == list(range(len(run.samples)))  # every one kept
    assert len(run.samples) == run.meta.counters["samples"] > 600  # 30 s held, 30 s on


def test_run_json_held_open_at_the_tare_is_tried_again(config, tmp_path, monkeypatch):
    # Windows: a virus scanner or the indexer holding run.json as the tare rewrites it: the
    # final record tried again, the tare's rewrite did not, and the run failed (exit 2) with
    # the muscle never pressurised. Now it is tried again as well (by the recorder's thread:
    # the loop does not wait for it)
    import os

    from mkm.bench import recorder
    from mkm.bench.run import acquire

    monkeypatch.setattr(recorder, "LOCKED_RETRY_S", 0.0)
    replace, written, refused = os.replace, [], []

    def held_open(source, target):
        if str(target).endswith("run.json"):
            written.append(target)
        if str(target).endswith("run.json") and len(written) in (2, 3):  # the tare's
            refused.append(target)
            raise PermissionError(13, "The process cannot access the file because it is "
                                  "being used by another process", str(target))
        return replace(source, target)

    monkeypatch.setattr(os, "replace", held_open)
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert result.status == "complete" and result.exit_code == 0, result.reason
    assert len(refused) == 2  # the tare's rewrite, twice
    assert load_run(result.path).meta.tare["n"] > 0


# a state folder that hangs: the loop never waits for it either --------------------------------

def _over_pressure_reference(config, tmp_path):
    """The 2.5 bar step with a regulator 0.14 bar over it (max_pressure_bar 2.5): above 2.55 bar
    for more than 1 s is an over-pressure. The run with a working state folder, and the device's
    sample clock at its interlock vent."""
    from mkm.bench.run import acquire

    c = config.replace(sequence={"pressures_bar": (2.5,)},
                       sim={"faults": {"overshoot_bar": 0.14}})
    reference = load_run(acquire(c, out_root=tmp_path / "reference", notify=lambda m: None).path)
    normal = reference.commands[reference.commands["purpose"] == "interlock vent"]
    assert reference.status == "failed" and len(normal) == 1
    return c, int(normal["sample"].iloc[0])


def test_an_over_pressure_while_the_bench_marker_hangs_is_vented_at_once(config, tmp_path,
                                                                        monkeypatch):
    # the bench state folder (a roaming profile on a network share) hangs from the first
    # pressure's marker write on: the loop used to wait in it before writing the pressure, with
    # no interlock watched. Now the marker is written by the lease's thread: the pressure goes
    # out after MARKER_WAIT_S, and the over-pressure is vented at the sample it is with a
    # working state folder, the marker still hung
    import threading

    from mkm.bench.unvented import BenchLease

    c, vent_sample = _over_pressure_reference(config, tmp_path)
    release, hung = threading.Event(), threading.Event()
    command = BenchLease.command

    def hanging(self, pressure_bar):
        if pressure_bar > 0 and not release.is_set():
            hung.set()
            release.wait(120)  # a net under a broken fix, never reached when it works
        command(self, pressure_bar)

    monkeypatch.setattr(BenchLease, "command", hanging)
    worker, vented, at, out = _run_in_thread(c, tmp_path / "runs", monkeypatch)
    try:
        assert vented.wait(60), "the loop waited for the hung state folder: nothing was vented"
        assert hung.wait(60) and not release.is_set()  # vented, the state folder hung
        assert at["sample"] == vent_sample  # the same sample as with a working state folder
        worker.join(60)  # the shutdown waits STATE_WAIT_S for the state folder, then goes on
        assert not worker.is_alive(), "the shutdown waited for the hung state folder"
    finally:
        release.set()
        worker.join(120)
    result = out["result"]
    assert result.status == "failed" and result.reason.startswith("over-pressure interlock")
    assert "the bench state folder did not take the bench marker" in result.reason
    run = load_run(result.path)
    assert run.meta.vent_check["verified"] and run.meta.reason == result.reason


def test_an_over_pressure_while_the_stop_request_read_hangs_is_vented_at_once(config, tmp_path,
                                                                              monkeypatch):
    # reading the stop request (`mkm vent` asking) from the state folder hangs from the first
    # block: the loop used to wait in it at every block, with no interlock watched. Now the
    # read is a thread's: the over-pressure is vented at the same sample as with a working
    # state folder
    from mkm.bench.sim import SimBackend

    c, vent_sample = _over_pressure_reference(config, tmp_path)
    release, hung = _hung_path(monkeypatch, "read_text", ".stop")
    write = SimBackend.write_command

    def once_hung(self, volts):  # the pressure goes out once the read hangs, whenever that is
        if volts > 0:
            assert hung.wait(60), "the stop request was never read"
        write(self, volts)

    monkeypatch.setattr(SimBackend, "write_command", once_hung)
    worker, vented, at, out = _run_in_thread(c, tmp_path / "runs", monkeypatch)
    try:
        assert vented.wait(60), "the loop waited for the hung stop request: nothing was vented"
        assert hung.is_set() and not release.is_set()
        assert at["sample"] == vent_sample
        worker.join(60)
        assert not worker.is_alive(), "the run waited for the hung stop request"
    finally:
        release.set()
        worker.join(120)
    result = out["result"]
    assert result.status == "failed" and result.reason.startswith("over-pressure interlock")
    assert load_run(result.path).meta.vent_check["verified"]


def test_a_failed_vent_with_the_state_folder_hung_is_not_said_to_have_gone_out(
        ctrl_c_run, monkeypatch):
    # the state folder hangs from the 0.5 bar marker on; a Ctrl-C at sample 45; every vent
    # write after it fails. The marker's problem used to end "the vent went out without it"
    # while no vent had gone out
    import threading

    from mkm.bench.unvented import BenchLease

    release = threading.Event()
    command = BenchLease.command

    def hanging(self, pressure_bar):
        if pressure_bar > 0 and not release.is_set():
            release.wait(120)  # released at the end of the test
        command(self, pressure_bar)

    run, _ = ctrl_c_run(None)  # every vent write fails
    monkeypatch.setattr(BenchLease, "command", hanging)
    try:
        result = run.execute()
    finally:
        release.set()
    assert result.status == "failed" and result.manual_vent_required
    assert "the bench state folder did not take the bench marker" in result.reason
    assert "went out" not in result.reason and "vented" not in result.reason
    assert "VENT BY HAND" in result.reason


def test_a_state_folder_that_hangs_as_the_bench_is_let_go_does_not_hold_the_run(
        config, tmp_path, monkeypatch):
    # the run is vented and recorded; then the bench's owner file is removed and its lock let go
    # in the state folder, which hangs from then on (a roaming profile on a network share):
    # `mkm acquire` never returned. Now it waits STATE_WAIT_S, says so, and returns
    import threading

    from mkm.bench.run import acquire

    release, hung = _hung_path(monkeypatch, "unlink", ".owner")
    notes, out = [], {}
    worker = threading.Thread(target=lambda: out.update(result=acquire(
        config, out_root=tmp_path, notify=notes.append)), daemon=True)
    worker.start()
    try:
        assert hung.wait(60), "the owner file was never removed"
        worker.join(60)  # STATE_WAIT_S, then the run returns
        assert not worker.is_alive(), "the run waited for the hung state folder"
    finally:
        release.set()
        worker.join(120)
    result = out["result"]
    assert result.status == "complete" and result.exit_code == 0
    run = load_run(result.path)
    assert run.status == "complete" and run.meta.vent_check["verified"]
    assert run.meta.counters["samples"] == len(run.samples) > 0
    assert notes[-1].startswith("the bench state folder ") and "(it hangs)" in notes[-1]


def test_a_state_folder_that_hangs_at_the_start_refuses_the_run_untouched(
        tmp_path, monkeypatch, mkm_cli):
    # the state folder hangs as the bench's lock is taken, before the device is opened:
    # `mkm acquire` never returned. Now it refuses in one line once STATE_START_S has passed
    # (0 here: the hang is certain), the device never opened, and lets the lock go once the
    # folder answers
    import threading

    import filelock

    from mkm.bench import ownership
    from mkm.bench.sim import SimBackend

    monkeypatch.setattr(ownership, "STATE_START_S", 0.0)
    release, opened = threading.Event(), []
    acquire_lock = filelock.FileLock.acquire

    def hanging(self, *args, **kwargs):
        release.wait(120)  # released below
        return acquire_lock(self, *args, **kwargs)

    monkeypatch.setattr(filelock.FileLock, "acquire", hanging)
    monkeypatch.setattr(SimBackend, "open", lambda self: opened.append(self))
    try:
        code, out, err = mkm_cli(["acquire", "--out", str(tmp_path / "runs"),
                                  "--no-progress"])
    finally:
        release.set()
    assert code == 1 and out == "" and not opened
    assert err.startswith("mkm acquire: error: the bench state folder ") and err.count("\n") == 1
    assert err.rstrip().endswith("did not answer within 0 s (it hangs): nothing was touched")
    assert not list((tmp_path / "runs").glob("*"))


def test_rows_are_synced_to_the_disk_every_second_while_the_run_goes(config, tmp_path,
                                                                      monkeypatch):
    # rows were flushed to the operating system at every block but synced to the disk only at
    # the end: a crash of the operating system or a power cut lost every sample its cache held
    # (Linux writes it back after up to 30 s). Now the recorder's thread syncs them at the
    # first write SYNC_EVERY_S after the last sync. The recorder's wall clock is the device's
    # sample clock here, as on a real bench, and the loop waits for each block to be written,
    # so the syncs fall where they would in real time: one every 10 rows at 10 Hz
    import os
    import types

    from mkm.bench import recorder
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    now = {"s": 0.0}
    monkeypatch.setattr(recorder, "time", types.SimpleNamespace(
        monotonic=lambda: now["s"], sleep=lambda s: None))
    backend = SimBackend(config)
    read, synced = backend.read, []

    def in_step(n, timeout):
        block = read(n, timeout)
        run.recorder.wait_written()  # the blocks before it are on disk (and synced if due)
        now["s"] = (block.first_index + len(block.volts)) / config.daq.sample_rate_hz
        return block

    fsync = os.fsync

    def spy(fd):
        f = run.recorder.writer._files.get("samples", (None,))[0] if run.recorder else None
        if f is not None and not f.closed and fd == f.fileno():
            synced.append(run.recorder.meta.counters["samples"])
        fsync(fd)

    backend.read = in_step
    monkeypatch.setattr(os, "fsync", spy)
    run = BenchRun(config, backend, tmp_path, handle_signals=False, notify=lambda m: None)
    result = run.execute()
    assert result.status == "complete", result.reason
    rows = load_run(result.path).meta.counters["samples"]
    assert synced[-1] == rows > 200  # the close's
    assert len(synced) > rows / 11
    gaps = [b - a for a, b in zip([0, *synced], synced, strict=False)]
    # 1 s of samples, and the block written when it was due (one-sample blocks)
    assert max(gaps[:-1]) <= config.daq.sample_rate_hz * recorder.SYNC_EVERY_S + 1, gaps


def test_rows_are_synced_to_the_disk_when_the_acquisition_stalls(config, tmp_path,
                                                                 monkeypatch):
    # the rows were synced only at a write a second after the last sync: a DAQ read that hangs
    # (no new rows) left the last ones in the operating system's cache, lost to a power cut
    # for as long as it hung. The recorder's thread syncs them SYNC_EVERY_S after the last
    # sync whatever comes. Here the read of sample 45 hangs until the rows before it are synced
    # (the test's net: 60 s); the last of them, sample 44, is written only once the read hangs,
    # so its sync is the one nothing but the clock calls for (left to the threads, the rows
    # could be synced before the read began, and the hang waited for the watchdog's vent)
    import os
    import threading

    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    backend = SimBackend(config)
    read, hanging_now, synced, hung = backend.read, threading.Event(), threading.Event(), {}

    def hanging(n, timeout):
        if backend._index == 45 and not hung:
            hung["rows"] = 45
            hanging_now.set()
            hung["synced"] = synced.wait(60)
        return read(n, timeout)

    append = RunWriter.append_samples

    def after_the_hang(self, rows):
        if rows[-1].sample == hung.get("rows", 45) - 1:
            hanging_now.wait(60)
        append(self, rows)

    fsync = os.fsync

    def spy(fd):
        fsync(fd)
        f = run.recorder.writer._files.get("samples", (None,))[0] if run.recorder else None
        if f is not None and not f.closed and fd == f.fileno() and \
                run.recorder.meta.counters["samples"] == 45:
            synced.set()

    backend.read = hanging
    monkeypatch.setattr(RunWriter, "append_samples", after_the_hang)
    monkeypatch.setattr(os, "fsync", spy)
    run = BenchRun(config, backend, tmp_path, handle_signals=False, notify=lambda m: None)
    result = run.execute()
    assert result.status == "complete", result.reason
    assert hung["synced"], "the rows written before the read hung were not synced"


def test_every_write_of_the_rows_is_the_recorders_threads(config, tmp_path, monkeypatch):
    # the recorder's thread syncs the rows on its own once a second has passed; the last try
    # of the rows a full disk refused was made by the run's thread, which could then write
    # samples.csv while the recorder's thread synced or reopened it
    import errno
    import threading

    from mkm.bench.run import acquire

    appended, append = [], RunWriter.append_samples

    def full_from_40(self, rows):
        appended.append(threading.current_thread().name)
        if rows[-1].sample >= 40:
            raise OSError(errno.ENOSPC, "No space left on device")
        append(self, rows)

    monkeypatch.setattr(RunWriter, "append_samples", full_from_40)
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert result.status == "failed" and result.exit_code == 2
    assert "samples could not be written" in result.reason  # the last try was made
    assert set(appended) == {"mkm-recorder"}


def test_a_marker_update_queued_behind_a_vent_is_not_a_slow_state_folder(config, tmp_path,
                                                                         monkeypatch):
    # the vent's marker update (never waited for) is still queued when the next pressure is
    # commanded, as on the virtual clock, where the tare takes milliseconds: every such run
    # said "the bench state folder was slow" (8 runs of 8 with the packaged staircase). Now the
    # pressure waits for both, MARKER_WAIT_S at most, and only a wait that runs out is slow.
    # Here the 0 bar updates before the first pressure are held until a later update is posted
    import threading

    from mkm.bench.run import acquire
    from mkm.bench.unvented import BenchLease

    posted, before_pressure = threading.Event(), [True]
    post, command = BenchLease.post, BenchLease.command

    def posting(self, update):
        ticket = post(self, update)
        posted.set()
        return ticket

    def held_vent(self, pressure_bar):
        if pressure_bar > 0.0:
            before_pressure[0] = False
        elif before_pressure[0]:
            mine = self._written + 1  # this update's ticket: the lease's thread runs it
            while self.posted <= mine:
                assert posted.wait(60), "nothing followed the vent"
                posted.clear()
        command(self, pressure_bar)

    monkeypatch.setattr(BenchLease, "post", posting)
    monkeypatch.setattr(BenchLease, "command", held_vent)
    result = acquire(config.replace(sequence={"pressures_bar": (0.5,)}), out_root=tmp_path,
                     notify=lambda m: None)
    assert result.status == "complete" and result.reason == "the 1 step done"  # not "all 1 steps"


def test_a_recorder_thread_that_fails_stops_the_run_vented_and_loses_no_sample(config,
                                                                              tmp_path,
                                                                              monkeypatch):
    # The recorder's thread fails outside a write (memory exhausted as it takes samples 60
    # from the queue): the run went on without a writer, its vent went out, and its shutdown
    # waited for the dead thread for ever ("the disk is not taking the record"), run.json
    # running, the samples held lost to the kill that ended it. The loop now stops the run at
    # its next block, and the shutdown writes what the thread held.
    import threading

    from mkm.bench.recorder import Recorder
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    what = Recorder._what

    def failing(kind, payload):
        if kind == "samples" and payload[0].sample == 60:
            raise MemoryError("injected")
        return what(kind, payload)

    monkeypatch.setattr(Recorder, "_what", staticmethod(failing))
    backend = SimBackend(config)
    run = BenchRun(config, backend, tmp_path, handle_signals=False, notify=lambda m: None)
    # the loop reads on once the thread has taken samples 60 and failed: on the virtual clock
    # it ran ahead of a thread that a loaded machine slowed, past the run's last step (a
    # complete run then, below), and the test failed once so
    read = backend.read

    def read_once_the_thread_failed(n, timeout):
        block = read(n, timeout)
        if block.first_index > 60 and run.recorder is not None:
            deadline = time.monotonic() + 30
            while not run.recorder.crashed and time.monotonic() < deadline:
                time.sleep(0.001)
        return block

    backend.read = read_once_the_thread_failed
    out = []
    runner = threading.Thread(target=lambda: out.append(run.execute()), daemon=True)
    runner.start()
    runner.join(60)  # a net under a broken fix: it used to wait for ever
    assert not runner.is_alive() and out
    (result,) = out
    assert result.status == "failed" and result.exit_code == 2, result.reason
    assert result.reason.startswith("the recorder's thread failed (MemoryError: injected)")
    assert "were written as the run ended" in result.reason
    recorded = load_run(result.path)
    assert list(recorded.samples["sample"]) == list(range(len(recorded.samples)))  # none lost
    assert recorded.meta.counters["samples"] == len(recorded.samples) > 61
    assert recorded.commands["purpose"].iloc[-1] == "vent" and recorded.meta.vent_check["verified"]
    assert backend.bench.pressure_bar < config.safety.vent_below_bar  # the truth: vented
    assert recorded.meta.steps_done < 3  # stopped there, not at the end


def test_a_recorder_thread_that_fails_after_the_last_step_is_said_every_sample_kept(
        config, tmp_path, monkeypatch):
    # The other order, a loaded machine's: the thread reaches samples 60 only once the loop
    # has done its last step and vented. The run is complete, every sample written as it
    # ended, and says what failed. It exited 2, a failed disk's status, beside run.json's
    # `complete`: the disk took the whole record, so the exit is the complete run's, 0, and
    # the reason names the thread's failure.
    import threading

    from mkm.bench.recorder import Recorder
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    what, append = Recorder._what, RunWriter.append_samples
    vented = threading.Event()

    def failing(kind, payload):
        if kind == "samples" and payload[0].sample == 60:
            raise MemoryError("injected")
        return what(kind, payload)

    def lagging(self, rows):
        if rows[-1].sample >= 50:
            vented.wait(30)  # a net under a broken run: it vents at its end
        append(self, rows)

    monkeypatch.setattr(Recorder, "_what", staticmethod(failing))
    monkeypatch.setattr(RunWriter, "append_samples", lagging)
    backend = SimBackend(config)
    write = backend.write_command

    def noting_the_end(volts):
        write(volts)
        if volts == 0.0 and max(v for _, v in backend.commands) > 0:
            vented.set()

    backend.write_command = noting_the_end
    result = BenchRun(config, backend, tmp_path, handle_signals=False,
                      notify=lambda m: None).execute()
    assert result.status == "complete" and result.exit_code == 0, result.reason
    assert re.fullmatch(r"all 3 steps done; the recorder's thread failed \(MemoryError: "
                        r"injected\): the \d+ samples it held were written as the run ended",
                        result.reason), result.reason
    recorded = load_run(result.path)
    assert list(recorded.samples["sample"]) == list(range(len(recorded.samples)))  # none lost
    assert recorded.meta.counters["samples"] == len(recorded.samples)
    assert recorded.meta.steps_done == 3 and recorded.meta.vent_check["verified"]


def test_samples_the_run_folder_refuses_after_the_last_step_are_a_failed_disk(config,
                                                                             tmp_path,
                                                                             monkeypatch):
    # The run folder turns read-only as the vent check reads (samples 215 on): those samples
    # are kept in the user state folder, samples.csv holds 215 of 225, and the run exited 0,
    # as a whole record does: a script took it for one. The record is not whole in its
    # folder: exit 2, the run's status still complete (every step done, the vent verified)
    from mkm.bench.run import EXIT_STORAGE, acquire

    append = RunWriter.append_samples

    def read_only_from_215(self, rows):
        if rows[-1].sample >= 215:
            raise OSError(errno.EROFS, "Read-only file system")
        append(self, rows)

    monkeypatch.setattr(RunWriter, "append_samples", read_only_from_215)
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert result.status == "complete" and result.exit_code == EXIT_STORAGE, result.reason
    assert re.fullmatch(r"all 3 steps done; the disk refused samples 215 \(Read-only "
                        r"file system\), and \d+ later write\(s\); 10 samples could "
                        r"not be written to the run folder: samples 215-224 are kept in .*"
                        r"-samples\.csv", result.reason), result.reason
    run = load_run(result.path)
    assert len(run.samples) == 215 and run.meta.vent_check["verified"]
    assert run.meta.status == "complete" and run.meta.steps_done == 3


def test_a_close_that_fails_otherwise_than_the_disk_still_records_the_outcome(tmp_path, capsys,
                                                                               monkeypatch):
    # a writer's close raising other than OSError (a library's bug, a codec) escaped the
    # shutdown: no run.json outcome, a traceback where the run's path belongs
    close = RunWriter.close

    def broken_close(self):
        close(self)
        raise RuntimeError("codec gave up")

    monkeypatch.setattr(RunWriter, "close", broken_close)
    rc = main(["acquire", "--pressures", "0.5", "--out", str(tmp_path / "runs"),
               "--no-progress"])
    captured = capsys.readouterr()
    assert "Traceback" not in captured.err
    assert "could not all be synced (RuntimeError: codec gave up)" in captured.err
    run = load_run(Path(captured.out.strip().splitlines()[-1]))  # the path is still printed
    assert run.status == "complete" and rc != 0  # the outcome kept, the problem said
    assert run.commands["purpose"].iloc[-1] == "vent" and run.commands["ok"].iloc[-1]


def _read_only_from_60(monkeypatch, first: int = 60) -> list[int]:
    """The run folder refuses every write from sample ``first`` on (gone read-only:
    samples.csv, run.json); the samples the run queued, returned, in order. The state folder
    that keeps what it refused is waited for until it has (a run waits STATE_WAIT_S, 2 s,
    for one that hangs: on a loaded machine the kept files' synced writes took longer, and
    the run ended saying they were being written while the test read them half-written)."""
    from mkm.bench import recorder
    from mkm.bench.recorder import Recorder

    monkeypatch.setattr(recorder, "STATE_WAIT_S", 60.0)

    queued, read_only = [], {"from": None}
    samples, append = Recorder.samples, RunWriter.append_samples

    def spy(self, rows):
        queued.extend(r.sample for r in rows)
        samples(self, rows)

    def denied(*args):
        raise PermissionError(errno.EACCES, "Permission denied")

    def read_only_from_60(self, rows):
        if read_only["from"] is not None:
            denied()
        # the rows before ``first`` reach the disk whatever block the writer made of them
        # (a writer lagging under load joins the rows before a stall to those after it)
        before = [r for r in rows if r.sample < first]
        if len(before) < len(rows):
            read_only["from"] = first
            if before:
                append(self, before)
            denied()
        append(self, rows)

    def guarded(method):
        def call(self, *args):
            if read_only["from"] is not None:
                denied()
            return method(self, *args)
        return call

    monkeypatch.setattr(Recorder, "samples", spy)
    monkeypatch.setattr(RunWriter, "append_samples", read_only_from_60)
    monkeypatch.setattr(RunWriter, "reopen_samples", guarded(RunWriter.reopen_samples))
    monkeypatch.setattr(RunWriter, "write_meta", guarded(RunWriter.write_meta))
    return queued


def _loop_waits_for_the_write(monkeypatch, method: str, first) -> None:
    """The loop waits for the recorder's thread to write what ``Recorder.<method>`` queued, the
    first time ``first(payload)`` holds: a refusal is then made before the loop's next block,
    as on an idle machine (on a loaded one the thread, trailing the virtual clock, may reach it
    only after the last step)."""
    from mkm.bench.recorder import Recorder

    queue, waited = getattr(Recorder, method), []

    def then_wait(self, payload):
        queue(self, payload)
        if not waited and first(payload):
            waited.append(self.wait_written(60))  # a net under a broken fix: 60 s

    monkeypatch.setattr(Recorder, method, then_wait)


def _written_after_the_last_step(monkeypatch, method: str, first) -> None:
    """``RunWriter.<method>`` waits, from the first call where ``first(payload)`` holds, until
    the run waits for its record (the shutdown, after the last step): the order of a loaded
    machine, the recorder's thread trailing the loop by the whole run."""
    import threading

    from mkm.bench.recorder import Recorder

    ended, write, wait_written = threading.Event(), getattr(RunWriter, method), \
        Recorder.wait_written

    def late(self, payload):
        if first(payload):
            ended.wait(60)  # a net under a broken fix: 60 s
        return write(self, payload)

    def waited_at_the_end(self, timeout_s=None):
        ended.set()
        return wait_written(self, timeout_s)

    monkeypatch.setattr(RunWriter, method, late)
    monkeypatch.setattr(Recorder, "wait_written", waited_at_the_end)


def test_samples_a_read_only_run_folder_refuses_are_kept_elsewhere_and_named(config, tmp_path,
                                                                             monkeypatch):
    # a run folder that went read-only at sample 60 (a share remounted, permissions changed)
    # lost the samples it refused from then on: "23 samples could not be written". Now they
    # are written to the user state folder, and the reason (kept in the bench marker when
    # run.json is refused too) names the file
    import json

    import pandas as pd

    from mkm.bench.run import acquire

    queued = _read_only_from_60(monkeypatch)
    _loop_waits_for_the_write(monkeypatch, "samples", lambda rows: rows[-1].sample >= 60)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    assert result.status == "failed" and result.exit_code == 2, result.reason
    kept = tmp_path / "mkm-state" / "unwritten" / f"{result.path.name}-samples.csv"
    assert f"are kept in {kept}" in result.reason
    on_disk = pd.read_csv(result.path / "samples.csv")["sample"].tolist()
    elsewhere = pd.read_csv(kept)["sample"].tolist()
    assert on_disk == list(range(60)) and elsewhere[0] == 60  # the folder refused from 60 on
    assert on_disk + elsewhere == queued  # every sample acquired, once, in order
    # run.json refused too: the marker keeps the outcome, and with it the file's name
    marker, = (tmp_path / "mkm-state" / "benches").glob("*/*.json")
    assert str(kept) in json.loads(marker.read_text(encoding="utf-8"))["outcome"]["reason"]


def test_samples_refused_mid_run_but_written_after_the_last_step_leave_it_complete_exit_2(
        config, tmp_path, monkeypatch):
    # on a loaded machine the recorder's thread trails the virtual clock by the whole run: the
    # read-only folder refuses sample 60 only once the loop has done its last step. The run,
    # every step done and vented, is complete; its record is not whole in its folder: exit 2,
    # the reason naming the refusal and where the samples are kept
    from mkm.bench.run import EXIT_STORAGE, acquire

    queued = _read_only_from_60(monkeypatch)
    _written_after_the_last_step(monkeypatch, "append_samples",
                                 lambda rows: rows[-1].sample >= 60)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    assert (result.status, result.exit_code) == ("complete", EXIT_STORAGE), result.reason
    kept = tmp_path / "mkm-state" / "unwritten" / f"{result.path.name}-samples.csv"
    assert result.reason.startswith(
        f"all 3 steps done; the disk refused samples 60 (Permission denied)"
        f", and {len(queued) - 61} later write(s); {len(queued) - 60} samples could not "
        f"be written to the run folder: samples 60-{queued[-1]} are kept in {kept}; "), \
        result.reason
    assert not result.manual_vent_required


def test_a_run_whose_refused_samples_are_kept_elsewhere_says_so_when_read(config, tmp_path,
                                                                          monkeypatch):
    # the samples a read-only run folder refused are kept in the state folder, but `mkm report`
    # and `mkm export` on that run showed it short without a word. Now the loader names the
    # kept file, how many samples it holds and which, in the run's problems: the report's
    # loader note and the export's metadata
    import json

    import pandas as pd

    from mkm.bench.exchange import export_run
    from mkm.bench.run import acquire

    _read_only_from_60(monkeypatch)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    monkeypatch.undo()  # the folder takes writes again (the export writes elsewhere anyway)
    monkeypatch.setenv("MKM_STATE_DIR", str(tmp_path / "mkm-state"))
    kept = tmp_path / "mkm-state" / "unwritten" / f"{result.path.name}-samples.csv"
    elsewhere = pd.read_csv(kept)["sample"]
    said = (f"samples 60-{elsewhere.iloc[-1]} ({len(elsewhere)}) are not in samples.csv: the "
            f"run folder refused them, and they are kept in {kept} (`mkm recover {result.path}` "
            "joins them to samples.csv once the folder takes writes again)")
    assert said in load_run(result.path).problems
    out = export_run(result.path, tmp_path / "export", "csv")
    metadata = pd.read_csv(out / "metadata.csv").set_index("key")["value"]
    assert said in json.loads(metadata["problems"])


def test_kept_samples_appended_to_the_run_are_no_longer_said_missing(config, tmp_path,
                                                                     monkeypatch):
    # the engineer does as the note says: the kept rows appended to samples.csv. The note
    # still said they were not in it. Now only the kept samples past samples.csv's last are
    # named, and none once all are there.
    from mkm.bench.run import acquire

    _read_only_from_60(monkeypatch)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    monkeypatch.undo()
    monkeypatch.setenv("MKM_STATE_DIR", str(tmp_path / "mkm-state"))
    kept = tmp_path / "mkm-state" / "unwritten" / f"{result.path.name}-samples.csv"
    rows = kept.read_text(encoding="utf-8").splitlines(keepends=True)[1:]
    with open(result.path / "samples.csv", "a", encoding="utf-8", newline="") as f:
        f.writelines(rows[:10])  # half done: ten rows appended
    (said,) = [p for p in load_run(result.path).problems if str(kept) in p]
    assert said.startswith(f"samples 70-{int(rows[-1].split(',')[0])} ({len(rows) - 10}) are "
                           "not in samples.csv")
    with open(result.path / "samples.csv", "a", encoding="utf-8", newline="") as f:
        f.writelines(rows[10:])
    run = load_run(result.path)
    assert not [p for p in run.problems if str(kept) in p]
    assert run.samples["sample"].tolist() == list(range(len(run.samples)))  # whole, once


def test_mkm_recover_joins_the_kept_samples_back_once_the_folder_takes_writes(
        config, tmp_path, monkeypatch, mkm_cli):
    # the samples a read-only run folder refused are kept in the state folder, and the note
    # asked the engineer to append them by hand. Now `mkm recover RUN` does: refused in one line,
    # nothing changed, while the folder is still read-only or when the kept rows do not
    # continue samples.csv; then the rows joined, every sample once and in order, and counted
    # in run.json; asked again, it says there is nothing left to join.
    import json
    import types

    import mkm.bench.storage as storage
    from mkm.bench.run import acquire

    queued = _read_only_from_60(monkeypatch)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    monkeypatch.undo()
    monkeypatch.setenv("MKM_STATE_DIR", str(tmp_path / "mkm-state"))
    run_json, samples_csv = result.path / "run.json", result.path / "samples.csv"
    meta = json.loads(run_json.read_text(encoding="utf-8"))
    assert meta["status"] == "running"  # run.json refused too: the marker keeps the outcome
    meta["process"]["started_unix_s"] -= 100.0  # its process has ended since
    run_json.write_text(json.dumps(meta), encoding="utf-8")
    kept = tmp_path / "mkm-state" / "unwritten" / f"{result.path.name}-samples.csv"
    before = (run_json.read_bytes(), samples_csv.read_bytes(), kept.read_bytes())

    def denied(*args, **kwargs):
        raise PermissionError(errno.EROFS, "Read-only file system")

    with monkeypatch.context() as read_only:  # the folder still refuses writes
        read_only.setattr(storage, "tempfile", types.SimpleNamespace(TemporaryFile=denied))
        code, out, err = mkm_cli(["recover", str(result.path)])
    assert (code, out) == (2, "") and err == (
        f"mkm recover: error: {result.path} still refuses writes (Read-only file system): "
        f"nothing joined, the samples stay kept in {kept}; expected a run folder this user can "
        "write to again\n")
    header, *rows = before[2].splitlines(keepends=True)
    kept.write_bytes(header + b"".join(rows[10:]))  # rows that do not follow samples.csv's
    code, out, err = mkm_cli(["recover", str(result.path)])
    assert (code, out) == (2, "") and err == (
        f"mkm recover: error: the samples kept in {kept} begin at sample 70, but {samples_csv} "
        "ends at sample 59: expected this run's kept rows, from sample 60; nothing joined\n")
    kept.write_bytes(before[2])
    assert (run_json.read_bytes(), samples_csv.read_bytes(), kept.read_bytes()) == before

    code, out, err = mkm_cli(["recover", str(result.path)])
    n = len(queued)
    assert (code, out) == (0, f"{result.path}\n") and err == (
        f"mkm recover: note: samples 60-{queued[-1]} ({n - 60}) kept in {kept} were joined to "
        f"{samples_csv}; run.json counts {n} samples\n")
    run = load_run(result.path)
    assert run.samples["sample"].tolist() == queued  # every sample acquired, once, in order
    assert json.loads(run_json.read_text(encoding="utf-8"))["counters"]["samples"] == n
    assert not [p for p in run.problems if str(kept) in p or "samples counted" in p]
    assert kept.read_bytes() == before[2]  # kept until the engineer deletes it
    code, out, err = mkm_cli(["recover", str(result.path)])
    assert code == 2 and "are all in" in err and "nothing to join" in err


def _kept_run(config, tmp_path, monkeypatch):
    """A run whose folder refused every write from sample 60 on, its process since ended, the
    folder taking writes again: its folder, run.json, samples.csv, the kept file and the
    samples queued."""
    import json

    from mkm.bench.run import acquire

    queued = _read_only_from_60(monkeypatch)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    monkeypatch.undo()
    monkeypatch.setenv("MKM_STATE_DIR", str(tmp_path / "mkm-state"))
    run_json = result.path / "run.json"
    meta = json.loads(run_json.read_text(encoding="utf-8"))
    meta["process"]["started_unix_s"] -= 100.0  # its process has ended since
    run_json.write_text(json.dumps(meta), encoding="utf-8")
    kept = tmp_path / "mkm-state" / "unwritten" / f"{result.path.name}-samples.csv"
    return result.path, run_json, result.path / "samples.csv", kept, queued


def test_mkm_recover_joins_kept_rows_after_a_gap_recorded_at_samples_csvs_end(
        config, tmp_path, monkeypatch, mkm_cli):
    # a buffer overflow lost 5 samples right after samples.csv's last (59), so the kept rows
    # begin at 65: run.json's gap says so and they are joined; without that gap, rows from 65
    # do not continue samples.csv and nothing is joined
    import json

    import pandas as pd

    path, run_json, samples_csv, kept = _kept_run(config, tmp_path, monkeypatch)[:4]
    header, *rows = kept.read_text(encoding="utf-8").splitlines(keepends=True)
    shifted = [f"{int(r.split(',', 1)[0]) + 5},{r.split(',', 1)[1]}" for r in rows]
    kept.write_text(header + "".join(shifted), encoding="utf-8")
    before = samples_csv.read_bytes()
    code, out, err = mkm_cli(["recover", str(path)])
    assert (code, out) == (2, "") and err == (
        f"mkm recover: error: the samples kept in {kept} begin at sample 65, but {samples_csv} "
        "ends at sample 59: expected this run's kept rows, from sample 60; nothing joined\n")
    assert samples_csv.read_bytes() == before
    meta = json.loads(run_json.read_text(encoding="utf-8"))
    meta["gaps"] = [{"after_sample": 59, "lost_samples": 5, "start_s": 6.0, "end_s": 6.5,
                     "message": "buffer overflow"}]
    meta["lost_samples"] = 5
    run_json.write_text(json.dumps(meta), encoding="utf-8")
    code, out, err = mkm_cli(["recover", str(path)])
    assert (code, out) == (0, f"{path}\n") and "were joined" in err
    joined = pd.read_csv(samples_csv)["sample"].tolist()
    assert joined == list(range(60)) + [int(r.split(",", 1)[0]) for r in shifted]
    assert json.loads(run_json.read_text(encoding="utf-8"))["counters"]["samples"] == len(joined)


def _stalled_then_read_only(config, tmp_path, monkeypatch):
    """A run whose 30 s stall against a 10 s buffer lost samples 40-339 and whose folder went
    read-only with the first block after it (samples.csv ends at 39, the rows from 340 kept in
    the state folder, run.json refused at the end: still running, without the gap), its
    process since ended: its folder, run.json and the samples it queued."""
    import json

    from mkm.bench.run import acquire

    c = config.replace(sim={"buffer_s": 10.0, "faults": {"stall_at_s": 4.0, "stall_s": 30.0}})
    queued = _read_only_from_60(monkeypatch, first=340)
    result = acquire(c, out_root=tmp_path / "runs", notify=lambda m: None)
    monkeypatch.undo()
    monkeypatch.setenv("MKM_STATE_DIR", str(tmp_path / "mkm-state"))
    path, run_json = result.path, result.path / "run.json"
    meta = json.loads(run_json.read_text(encoding="utf-8"))
    assert meta["status"] == "running"  # refused at the end
    # the last run.json the folder took is the tare's; the loop records the gap in the books
    # that save writes, so a writer lagging under load (the save done after the stall) wrote
    # it with the gap: the run.json that never took it, as the save in time leaves it
    meta["gaps"], meta["lost_samples"] = [], 0
    meta["process"]["started_unix_s"] -= 100.0  # its process has ended since
    run_json.write_text(json.dumps(meta), encoding="utf-8")
    return path, run_json, queued


def test_mkm_recover_joins_kept_rows_after_a_gap_run_json_never_took(config, tmp_path,
                                                                     monkeypatch, mkm_cli):
    # a 30 s stall against a 10 s buffer lost samples 40-339 (the simulator's overflow), and the
    # run folder went read-only with the first block after it: samples.csv ends at 39, the
    # kept rows begin at 340, and run.json, refused at the end, never held the gap. `mkm
    # recover` refused them ("expected ... from sample 40"). Now the gaps are kept beside the
    # rows, and recover joins them with the gap recorded in run.json as any gap
    import pandas as pd

    path, run_json, queued = _stalled_then_read_only(config, tmp_path, monkeypatch)
    assert pd.read_csv(path / "samples.csv")["sample"].iloc[-1] == 39
    gaps = tmp_path / "mkm-state" / "unwritten" / f"{path.name}-gaps.json"
    text = gaps.read_text(encoding="utf-8")
    gaps.write_text("[{", encoding="utf-8")  # a kept file no one can read: nothing joined
    code, out, err = mkm_cli(["recover", str(path)])
    assert (code, out) == (2, "") and err.startswith(f"mkm recover: error: {gaps} cannot be "
                                                     "read (") and err.count("\n") == 1
    assert pd.read_csv(path / "samples.csv")["sample"].iloc[-1] == 39
    gaps.write_text(text, encoding="utf-8")
    code, out, err = mkm_cli(["recover", str(path)])
    kept = tmp_path / "mkm-state" / "unwritten" / f"{path.name}-samples.csv"
    n = len(queued)
    assert (code, out) == (0, f"{path}\n") and err == (
        f"mkm recover: note: samples 340-{queued[-1]} ({n - 40}) kept in {kept} were joined to "
        f"{path / 'samples.csv'}, and the 1 gap(s) kept beside them (300 samples lost) "
        f"recorded; run.json counts {n} samples\n")
    run = load_run(path)
    assert run.samples["sample"].tolist() == queued and queued[:40] == list(range(40))
    assert queued[40] == 340  # 300 samples lost: 30 s at 10 Hz
    (gap,) = run.meta.gaps
    assert (gap.after_sample, gap.lost_samples, gap.start_s, gap.end_s) == (39, 300, 4.0, 34.0)
    assert run.meta.lost_samples == 300 and run.meta.counters["samples"] == len(queued)
    assert not [p for p in run.problems if "samples counted" in p]


def _stalled_refused_signalled(config, tmp_path, monkeypatch):
    """A run that lost samples 40-339 to a 30 s stall against a 10 s buffer, whose folder went
    read-only with the first block after it (samples.csv ends at 39, run.json refused to the
    end), stopped by SIGTERM as that block is read; its process since ended, the folder taking
    writes again: its result, the samples queued and its bench marker's kept outcome."""
    import json
    import signal

    from mkm.bench import recorder
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend
    from mkm.bench.unvented import bench_folder

    monkeypatch.setattr(recorder, "LOCKED_RETRY_S", 0.0)
    c = config.replace(sim={"buffer_s": 10.0, "faults": {"stall_at_s": 4.0, "stall_s": 30.0}})
    queued = _read_only_from_60(monkeypatch, first=340)
    backend = SimBackend(c)
    read = backend.read

    def signalled_at_400(n, timeout):
        block = read(n, timeout)
        if block.first_index == 340:
            signal.raise_signal(signal.SIGTERM)  # its handler runs before read returns
        return block

    backend.read = signalled_at_400
    result = BenchRun(c, backend, tmp_path / "runs", handle_signals=True,
                      notify=lambda m: None).execute()
    monkeypatch.undo()
    monkeypatch.setenv("MKM_STATE_DIR", str(tmp_path / "mkm-state"))
    (marker,) = bench_folder("sim-Dev1").glob("*.json")
    for written in (marker, result.path / "run.json"):  # as if its process had ended
        data = json.loads(written.read_text(encoding="utf-8"))
        data["process"]["started_unix_s"] -= 100.0
        written.write_text(json.dumps(data), encoding="utf-8")
    return result, queued, json.loads(marker.read_text(encoding="utf-8"))["outcome"]


def test_a_refused_final_record_is_written_whole_next_and_recover_joins_after_its_gap(
        config, tmp_path, monkeypatch, mkm_cli):
    # run.json refused the final record of a run that lost 300 samples to a stall after its last
    # write, was stopped by SIGTERM and verified its vent: the bench marker kept its status,
    # reason, end and manual vent only, so the next command wrote run.json without the gap, the
    # lost samples, the vent check or the signal (samples 340 on then looked contiguous with 39).
    # Now the marker keeps the whole record and the next command writes it, counting the rows
    # on disk; `mkm recover` then joins the kept rows after that gap, which run.json holds
    import json
    import signal

    from mkm.bench import procedures

    result, queued, kept = _stalled_refused_signalled(config, tmp_path, monkeypatch)
    # exit 2: the storage's failure goes before the signal's
    assert result.status == "aborted" and result.exit_code == 2
    run_json = result.path / "run.json"
    assert json.loads(run_json.read_text(encoding="utf-8"))["status"] == "running"
    notes = []
    assert procedures.vent(config, notify=notes.append)["vented"]
    (said,) = notes
    assert said.endswith("vented now; run.json mended: status aborted, 40 samples on disk")
    run = load_run(result.path)
    assert run.status == "aborted" and run.reason.startswith(kept["reason"])
    assert "; this outcome was refused by run.json as the run ended, kept in its bench marker " \
        "and written by the next command at " in run.reason
    (gap,) = run.meta.gaps
    assert (gap.after_sample, gap.lost_samples, gap.start_s, gap.end_s) == (39, 300, 4.0, 34.0)
    assert run.meta.lost_samples == 300
    assert run.meta.stop_signal == "SIGTERM" and run.meta.stop_signal_number == signal.SIGTERM
    assert run.meta.vent_check == kept["vent_check"] and run.meta.vent_check["verified"]
    assert run.meta.stop_to_vent_s == kept["stop_to_vent_s"] is not None
    assert run.meta.counters["samples"] == len(run.samples) == 40  # samples 0-39 on disk
    samples_csv = result.path / "samples.csv"
    kept_csv = tmp_path / "mkm-state" / "unwritten" / f"{result.path.name}-samples.csv"
    n = len(queued)
    code, out, err = mkm_cli(["recover", str(result.path)])
    assert (code, out) == (0, f"{result.path}\n") and err == (
        f"mkm recover: note: samples 340-{queued[-1]} ({n - 40}) kept in {kept_csv} were joined "
        f"to {samples_csv}; run.json counts {n} samples\n")  # the gap recorded already
    run = load_run(result.path)
    assert run.samples["sample"].tolist() == queued and queued[40] == 340
    assert len(run.meta.gaps) == 1 and run.meta.lost_samples == 300
    assert run.meta.counters["samples"] == n and run.meta.stop_signal == "SIGTERM"


def test_mkm_recover_says_a_run_json_it_cannot_read_in_one_line(config, tmp_path,
                                                                monkeypatch, mkm_cli):
    # run.json cannot be read (no permission): `mkm recover` said "run.json cannot be written
    # (Permission denied): expected a folder this user can write to", a write it never tried.
    # Now it says the file cannot be read, exit 2, nothing changed
    path, run_json, samples_csv, kept, _ = _kept_run(config, tmp_path, monkeypatch)
    before = (run_json.read_bytes(), samples_csv.read_bytes())
    read_text = Path.read_text

    def denied(self, *args, **kwargs):
        if self == run_json:
            raise PermissionError(errno.EACCES, "Permission denied", str(self))
        return read_text(self, *args, **kwargs)

    monkeypatch.setattr(Path, "read_text", denied)
    code, out, err = mkm_cli(["recover", str(path)])
    assert (code, out) == (2, "") and err == (
        f"mkm recover: error: {run_json} cannot be read (Permission denied): expected a run "
        "record this user can read\n")
    assert (run_json.read_bytes(), samples_csv.read_bytes()) == before


def test_mkm_recover_counts_rows_it_joined_once_run_json_takes_the_count(
        config, tmp_path, monkeypatch, mkm_cli):
    # run.json refused the count (read-only) after the kept rows were joined: exit 1, said;
    # asked again once run.json takes writes, `mkm recover` said the rows were all in
    # samples.csv, nothing to join, and run.json never counted them. Now it counts them then
    import json

    import mkm.bench.storage as storage

    path, run_json, samples_csv, kept, queued = _kept_run(config, tmp_path, monkeypatch)
    counted = json.loads(run_json.read_text(encoding="utf-8"))["counters"]["samples"]

    def denied(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")

    with monkeypatch.context() as read_only:
        read_only.setattr(storage, "write_json_atomic", denied)
        code, out, err = mkm_cli(["recover", str(path)])
    n = len(queued)
    assert (code, out) == (1, f"{path}\n") and err == (
        f"mkm recover: error: samples 60-{queued[-1]} ({n - 60}) kept in {kept} were joined to "
        f"{samples_csv}, but run.json could not count them (Permission denied): samples.csv "
        f"holds {n} samples\n")
    assert json.loads(run_json.read_text(encoding="utf-8"))["counters"]["samples"] == counted
    code, out, err = mkm_cli(["recover", str(path)])
    assert (code, out) == (0, f"{path}\n") and err == (
        f"mkm recover: note: the samples kept in {kept} are all in {samples_csv} already, "
        f"joined before; run.json counts {n} samples\n")
    assert json.loads(run_json.read_text(encoding="utf-8"))["counters"]["samples"] == n
    assert load_run(path).samples["sample"].tolist() == queued
    code, out, err = mkm_cli(["recover", str(path)])
    assert code == 2 and "are all in" in err and "nothing to join" in err


@pytest.mark.parametrize("counted", [False, True])
def test_mkm_recover_joined_before_says_the_gaps_it_records(config, tmp_path, monkeypatch,
                                                            mkm_cli, counted):
    # the kept rows after a gap run.json never held were joined, and run.json refused the count
    # and the gap with it; asked again, `mkm recover` recorded the gap but said only that it
    # counted the rows, and when run.json counted them already (a mend by an older version,
    # from the rows on disk) it said there was nothing to join and left the gap out. Now it
    # records the gap and says so, as a first join does
    import json

    import pandas as pd

    import mkm.bench.storage as storage

    path, run_json, queued = _stalled_then_read_only(config, tmp_path, monkeypatch)

    def denied(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")

    with monkeypatch.context() as read_only:
        read_only.setattr(storage, "write_json_atomic", denied)
        code, out, err = mkm_cli(["recover", str(path)])
    assert code == 1 and "but run.json could not count them (Permission denied)" in err
    assert pd.read_csv(path / "samples.csv")["sample"].tolist() == queued
    meta = json.loads(run_json.read_text(encoding="utf-8"))
    assert meta["gaps"] == [] and meta["lost_samples"] == 0
    n = len(queued)
    if counted:
        meta["counters"]["samples"] = n
        run_json.write_text(json.dumps(meta), encoding="utf-8")
    kept = tmp_path / "mkm-state" / "unwritten" / f"{path.name}-samples.csv"
    code, out, err = mkm_cli(["recover", str(path)])
    assert (code, out) == (0, f"{path}\n") and err == (
        f"mkm recover: note: the samples kept in {kept} are all in {path / 'samples.csv'} "
        "already, joined before, and the 1 gap(s) kept beside them (300 samples lost) "
        f"recorded; run.json counts {n} samples\n")
    run = load_run(path)
    (gap,) = run.meta.gaps
    assert (gap.after_sample, gap.lost_samples) == (39, 300) and run.meta.lost_samples == 300
    assert run.meta.counters["samples"] == n
    code, out, err = mkm_cli(["recover", str(path)])
    assert code == 2 and "nothing to join" in err


def test_a_step_row_the_disk_refuses_stops_the_run_vented_with_every_sample_kept(config,
                                                                                tmp_path,
                                                                                monkeypatch):
    # steps.csv refuses the first step's row (EIO: a dying drive) while samples.csv takes its
    # rows: the run stops at its next block, vents and verifies the vent, fails with exit 2
    # (storage), and keeps every sample it acquired, the vent check's included. Its reason
    # said only "recording failed (OSError: [Errno 5] Input/output error)", as for samples
    # refused: now it names what the disk refused
    from mkm.bench.recorder import Recorder
    from mkm.bench.run import acquire

    queued, samples = [], Recorder.samples

    def spy(self, rows):
        queued.extend(r.sample for r in rows)
        samples(self, rows)

    def dying(self, row):
        raise OSError(errno.EIO, "Input/output error")

    monkeypatch.setattr(Recorder, "samples", spy)
    monkeypatch.setattr(RunWriter, "append_step", dying)
    _loop_waits_for_the_write(monkeypatch, "step", lambda row: True)
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert result.status == "failed" and result.exit_code == 2, result.reason
    # the reason names what the disk refused: the row of step 0, not samples
    assert result.reason.startswith("recording failed for step 0 (Input/output "
                                    "error)")
    assert not result.manual_vent_required
    run = load_run(result.path)
    assert run.meta.vent_check["verified"] and len(run.steps) == 0
    assert run.commands["purpose"].iloc[-1] == "vent" and run.commands["ok"].iloc[-1]
    assert run.samples["sample"].tolist() == queued  # every sample, once, in order
    assert (run.samples["phase"] == "vent").any()  # the vent check's decay with them


def test_step_rows_refused_after_the_last_step_leave_the_run_complete_exit_2(config, tmp_path,
                                                                            monkeypatch):
    # on a loaded machine the recorder's thread reached the steps' rows only once the loop had
    # done its last step, and steps.csv refused all three (EIO): the run exited 0, as a whole
    # record does, steps.csv holding none of them. Now the record not whole in its folder
    # exits 2; the run, every step done and vented, is complete, the reason naming the refusal
    from mkm.bench.run import EXIT_STORAGE, acquire

    def dying(self, row):
        raise OSError(errno.EIO, "Input/output error")

    monkeypatch.setattr(RunWriter, "append_step", dying)
    _written_after_the_last_step(monkeypatch, "append_step", lambda row: True)
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert (result.status, result.exit_code) == ("complete", EXIT_STORAGE), result.reason
    assert result.reason == ("all 3 steps done; recording failed for step 0 (Input/output "
                             "error), and 2 later write(s)")
    run = load_run(result.path)
    assert run.meta.status == "complete" and len(run.steps) == 0
    assert run.meta.vent_check["verified"]


@pytest.mark.parametrize("fault", ["refused", "hangs"])
def test_samples_the_state_folder_cannot_keep_either_are_said_and_hold_nothing(
        config, tmp_path, monkeypatch, fault):
    # the run folder went read-only at sample 60, and the state folder that keeps the refused
    # samples refuses them too, or hangs (a roaming profile on a share): the run still ends,
    # vented and recorded in its marker, saying what became of them (a hang waited for
    # STATE_WAIT_S, the write left to finish once the folder answers)
    import threading

    import mkm.bench.recorder as recorder
    from mkm.bench.run import acquire
    from mkm.bench.unvented import STATE_WAIT_S

    _read_only_from_60(monkeypatch)
    _loop_waits_for_the_write(monkeypatch, "samples", lambda rows: rows[-1].sample >= 60)
    monkeypatch.setattr(recorder, "STATE_WAIT_S", STATE_WAIT_S)  # the wait a hang ends
    release = threading.Event()

    def keep(path, rows):
        if fault == "hangs":
            release.wait(60)  # the test's net; released once the run has ended
        raise OSError(errno.EROFS, "Read-only file system")

    monkeypatch.setattr(recorder, "write_samples", keep)
    try:
        result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
        ended_while_hung = not release.is_set()
    finally:
        release.set()
    assert result.status == "failed" and result.exit_code == 2 and ended_while_hung
    assert not result.manual_vent_required  # vented, verified
    kept = tmp_path / "mkm-state" / "unwritten" / f"{result.path.name}-samples.csv"
    said = re.search(r"(\d+) samples could not be written to the run folder(.*?); run\.json",
                     result.reason)
    assert said is not None and int(said.group(1)) > 0, result.reason
    if fault == "refused":
        assert said.group(2) == f", nor kept in {kept} (Read-only file " \
            "system)"
    else:
        assert said.group(2).endswith(f"are being written to {kept}, which did not answer "
                                      "within 2 s (it hangs): kept once it answers, lost if "
                                      "this process ends first")


def test_run_json_saved_behind_rows_holds_the_books_of_the_rows_on_disk(config, tmp_path,
                                                                         monkeypatch):
    # The tare's run.json is queued behind samples 0-9, which the disk is still writing; the
    # loop meanwhile queues samples 10-19, then records 5 samples lost after them. The writer
    # wrote run.json with the books as they were when it reached the save: the gap after
    # sample 19 recorded while samples.csv held samples 0-9, a record (a crash there leaves
    # it) whose gap lies past its rows. It writes them as they were when the save was queued,
    # with the count of the rows on disk.
    import threading

    from mkm.bench.recorder import Recorder
    from mkm.bench.sim import SimBackend
    from mkm.bench.storage import Gap, Sample

    def rows(first):
        return [Sample(k, k / 10, -1, "tare", 0.0, 0.0, 0.0, 0.015, 1.0, 0.0, "")
                for k in range(first, first + 10)]

    release, writing = threading.Event(), threading.Event()
    append, write_meta = RunWriter.append_samples, RunWriter.write_meta
    saved = []

    def held_at_the_first_block(self, block):
        if block[0].sample == 0:
            writing.set()
            release.wait(30)
        append(self, block)

    def recorded(self, meta):
        csv = self.path / "samples.csv"
        on_disk = csv.read_text().count("\n") - 1 if csv.exists() else 0
        saved.append((list(meta.gaps), meta.lost_samples, meta.counters["samples"], on_disk))
        write_meta(self, meta)

    monkeypatch.setattr(RunWriter, "append_samples", held_at_the_first_block)
    monkeypatch.setattr(RunWriter, "write_meta", recorded)
    backend = SimBackend(config)
    recorder = Recorder(tmp_path, config, backend.open(), 2, (1.0, 2.0))
    saved.clear()  # the folder's first run.json
    recorder.samples(rows(0))
    assert writing.wait(30)  # the writer holds samples 0-9
    recorder.tare({"offset_V": 0.015})  # the save, queued behind them
    recorder.samples(rows(10))
    recorder.gap(Gap(19, 5, 2.0, 2.5, "overflow"))
    release.set()
    assert recorder.wait_written(30)
    assert saved == [([], 0, 10, 10)]  # the books of samples 0-9, as on disk
    assert recorder.finish("complete", "done") == []
    final = load_run(recorder.path).meta
    assert final.lost_samples == 5 and final.counters["samples"] == 20  # the end's books whole
