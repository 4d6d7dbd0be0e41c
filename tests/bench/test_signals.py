"""Signals and kills of a real `mkm acquire` process on the real-clock simulated bench.

Each test runs for about 2-4 s of wall time: the process starts (imports ~1.5 s), acquires at
10 Hz until 15 samples are flushed (or the first pressure step is commanded), and is then
signalled. Issue 12: only SIGINT vented; SIGTERM and SIGHUP left the last command in place.
"""

import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from mkm.bench.signals import (
    CONSOLE_HOLD_S,
    CTRL_C_EVENT,
    CTRL_CLOSE_EVENT,
    StopSignal,
    StopSignals,
)
from mkm.bench.storage import load_run
from mkm.cli import main

FAST = """
[sequence]
pressures_bar = [0.5, 1.0]
tare_s = 1.0
preconditioning_cycles = 0
"""


def write_config(tmp_path):
    text = (Path(__file__).parents[2] / "bench/configs/paper_prototype.toml").read_text()
    head, _, rest = text.partition("[sequence]")
    rest = rest[rest.index("[settle]"):]
    # the closed form instead of the FE table: a second less of start-up, same signals
    rest = rest.replace('model = "axisym"', 'model = "thickwall"')
    config = tmp_path / "mkm.bench.toml"
    config.write_text(head + FAST + rest)
    return config


def start_run(tmp_path, until="samples"):
    """Start `mkm acquire` on the real clock; return once 15 samples are flushed (``samples``)
    or the first pressure step has been commanded (``step``)."""
    config = write_config(tmp_path)
    out = tmp_path / "runs"
    proc = subprocess.Popen(
        [sys.executable, "-m", "mkm", "acquire", "--config", str(config), "--clock",
         "real", "--out", str(out), "--no-progress"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        folders = list(out.glob("*_paper-prototype-SIMULATED")) if out.exists() else []
        if folders and (folders[0] / "commands.csv").exists():
            rows = (folders[0] / "samples.csv").read_text().count("\n") - 1
            commands = (folders[0] / "commands.csv").read_text()
            if (until == "samples" and rows >= 15) or (until == "step" and ",step\n" in commands):
                return proc, folders[0], rows
        if proc.poll() is not None:
            pytest.fail(f"run ended early: {proc.communicate()}")
        time.sleep(0.02)
    proc.kill()
    pytest.fail("no samples within 30 s")


def vented(folder) -> bool:
    """The run in ``folder`` has written its vent after a pressure step (commands.csv)."""
    commands = (folder / "commands.csv").read_text()
    return ",step\n" in commands and commands.rstrip().endswith(",vent")


def assert_every_flushed_sample(run, flushed):
    assert len(run.samples) >= flushed
    np.testing.assert_array_equal(run.samples["sample"], np.arange(len(run.samples)))


STOPS = [("SIGINT", 1), ("SIGINT", 2), ("SIGTERM", 1), ("SIGTERM", 2)]
if hasattr(signal, "SIGHUP"):
    STOPS.append(("SIGHUP", 1))
if hasattr(signal, "SIGABRT") and sys.platform != "win32":  # os.kill ends it on Windows
    STOPS.append(("SIGABRT", 1))


@pytest.mark.slow  # sends signals to runs in subprocesses
@pytest.mark.parametrize("name, times", STOPS, ids=[f"{n}x{k}" for n, k in STOPS])
def test_stop_signal_vents_first_and_records(tmp_path, name, times):
    proc, folder, flushed = start_run(tmp_path, until="step")  # pressurised when signalled
    signum = getattr(signal, name)
    sent = time.time()
    proc.send_signal(signum)
    if times == 2:
        # the second once the first one's vent is on disk: it then comes while the run stops
        # (its vent check lasts a second or more). Sent 20 ms after the first, on a loaded
        # machine it merged with it (one signal of a kind is pending at a time, in the kernel
        # and in Python's handler) or, a Ctrl-C, came after the first one's safe point: three
        # outcomes, a flake in 3 of 8 loops. A second Ctrl-C before that point is held in
        # test_a_second_ctrl_c_before_the_safe_point_vents_at_once
        deadline = time.monotonic() + 10
        while not vented(folder) and time.monotonic() < deadline:
            time.sleep(0.01)
        proc.send_signal(signum)
    stdout, stderr = proc.communicate(timeout=20)
    assert proc.returncode == 128 + signum, stderr
    assert stdout.strip().splitlines()[-1] == str(folder)
    run = load_run(folder)
    assert run.status == "aborted" and run.meta.stop_signal == name
    assert run.meta.stop_signal_number == signum
    if name == "SIGINT":
        assert run.reason.startswith("stopped by Ctrl-C (SIGINT) at a safe point; vented")
    else:
        assert run.reason.startswith(f"stopped by {name} at once; vented"), run.reason
    if times == 2:  # the second is noted, the first one's stop goes on
        assert run.reason.endswith(f"; {name} received while stopping: noted, the vent and the "
                                   "record went first"), run.reason
    assert_every_flushed_sample(run, flushed)
    # the order the record holds, whatever the load: the first step was on disk when the
    # signal was sent, and it lasts 9 s or more (settle.min_dwell_s 4 s, hold_s 5 s); the vent
    # is the one command after it, written after the signal, and every sample the device
    # acquired before the vent's write (its sample clock then) is recorded. The delay is
    # measured, not bounded here: on a loaded machine a process waits for a core as long as
    # the load says (the delay per signal: benchmarks/bench_acquisition.py; the order the
    # loop acts in, on any clock: test_a_stop_vents_before_anything_else)
    assert run.commands["purpose"].tolist()[-2:] == ["step", "vent"]
    last = run.commands.iloc[-1]
    assert last["ok"] and last["command_bar"] == 0.0
    assert run.commands["command_bar"].iloc[-2] == 0.5  # it was pressurised
    assert run.meta.vented_at_unix_s >= sent and run.meta.stop_to_vent_s >= 0
    acquired = run.samples[run.samples["phase"] != "vent"]
    assert acquired["sample"].iloc[-1] >= last["sample"] - 1
    assert not list((tmp_path / "mkm-state").rglob("*.json"))  # its marker is gone: vented


#: where a stop comes in the run's loop, and what the run finishes of what it was doing before
#: its vent: the block in hand (read, queued to its recorder: the device no longer holds it),
#: a command write with its row (the books of a pressure on the device); nothing else
STOP_ORDERS = [
    ("SIGTERM", 1, "read", [("read", 30), ("books", "samples")]),
    ("SIGTERM", 1, "safe point", []),
    ("SIGTERM", 1, "write", [("AO", 2.5), ("books", "command")]),
    ("SIGINT", 1, "read", [("read", 30), ("books", "samples")]),  # at the block's safe point
    ("SIGINT", 1, "safe point", []),
    ("SIGINT", 2, "read", [("read", 30), ("books", "samples")]),
]
if hasattr(signal, "SIGHUP"):
    STOP_ORDERS.append(("SIGHUP", 1, "read", [("read", 30), ("books", "samples")]))


@pytest.mark.parametrize("name, times, where, finished", STOP_ORDERS,
                         ids=[f"{n}x{k}-{w}" for n, k, w, _ in STOP_ORDERS])
def test_a_stop_vents_before_anything_else(config, tmp_path, run_events, name, times, where,
                                           finished):
    # every stop vents first, then records: from the signal on, the run's first act on the
    # device is the vent, after only the block or the command write it had in hand, on
    # whatever clock and however loaded the machine (the delay is bench_acquisition.py's)
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    backend = SimBackend(config)
    run = BenchRun(config, backend, tmp_path, handle_signals=True, notify=lambda m: None)
    stop = ("signal", name)

    def send():
        run_events.append(stop)
        for _ in range(times):
            signal.raise_signal(getattr(signal, name))  # its handler runs before this returns

    if where == "read":  # as the loop waits in a read, its usual place: sample 30, at 0.5 bar
        read = backend.read

        def reading(n, timeout):
            if backend._index == 30 and stop not in run_events:
                send()
            return read(n, timeout)

        backend.read = reading
    elif where == "write":  # as the second step's 1.0 bar (2.5 V) is written
        write = backend.write_command

        def writing(volts):
            if volts == 2.5 and stop not in run_events:
                send()
            return write(volts)

        backend.write_command = writing
    else:  # between two blocks, at the loop's safe point after sample 30
        pending = run._pending_stop

        def safe_point():
            if run.acquisition.next_index == 31 and stop not in run_events:
                send()
            return pending()

        run._pending_stop = safe_point
    result = run.execute()
    assert result.status == "aborted" and result.exit_code == 128 + getattr(signal, name)
    assert run_events.after_the_stop(stop) == finished, run_events
    vent = run_events.index(("AO", 0.0), run_events.index(stop))
    # run.json is marked and finished after the vent, the rows queued before it written
    assert ("books", "finish") in run_events[vent:]
    assert not any(e[0] == "books" and e[1] in ("mark", "finish")
                   for e in run_events[run_events.index(stop):vent])
    loaded = load_run(result.path)
    vent_row = loaded.commands[loaded.commands["purpose"] == "vent"].iloc[-1]
    assert vent_row["ok"] and vent_row["command_bar"] == 0.0
    assert loaded.meta.stop_to_vent_s is not None and loaded.meta.stop_to_vent_s >= 0


@pytest.mark.slow  # kills a run in a subprocess
def test_sigkill_is_noticed_and_vented_by_the_next_command(tmp_path, capsys):
    proc, folder, flushed = start_run(tmp_path, until="step")
    os.kill(proc.pid, getattr(signal, "SIGKILL", signal.SIGTERM))
    proc.communicate(timeout=20)
    run = load_run(folder)
    # run.json cannot be rewritten by a killed process; the loader tells the truth instead.
    assert run.meta.status == "running"
    assert run.status == "incomplete" and not run.complete
    assert_every_flushed_sample(run, flushed)
    assert "ended without venting: the last commanded pressure was 0.5 bar" in run.unvented
    assert any("ended without venting" in p for p in run.problems)  # the report lists these
    # the next command on that bench says which run, when, the pressure, and vents first
    assert main(["vent", "--config", str(write_config(tmp_path))]) == 0
    captured = capsys.readouterr()
    assert f"run {folder} (started {run.meta.started_utc}, pid {proc.pid})" in captured.err
    assert "last commanded pressure was 0.5 bar" in captured.err and "vented now" in captured.err
    assert captured.out.startswith("vented: ")
    assert main(["check"]) == 0  # said once: the marker is gone
    assert "ended without venting" not in capsys.readouterr().err


@pytest.mark.parametrize("command", [["check"], ["tare", "--seconds", "1", "--backend", "sim"],
                                     ["acquire", "--pressures", "0.5", "--no-progress"]])
def test_every_bench_command_vents_a_dead_run_first(tmp_path, capsys, command):
    from mkm.bench.storage import ProcessIdentity
    from mkm.bench.unvented import Marker, bench_folder
    from mkm.core.records import write_json_atomic

    dead = ProcessIdentity(2**22 + 7, socket.gethostname(), 1.0, None)  # pid above pid_max
    marker = Marker("sim-Dev1", str(tmp_path / "old-run"), "2026-12-01T10:00:00+00:00",
                    vars(dead), 2.5, "2026-12-01T10:05:00+00:00")
    folder = bench_folder("sim-Dev1")
    folder.mkdir(parents=True)
    write_json_atomic(folder / "dead.json", vars(marker))
    extra = ["--out", str(tmp_path / "runs")] if command[0] == "acquire" else []
    assert main(command + extra) == 0
    err = capsys.readouterr().err
    assert (f"run {tmp_path / 'old-run'} (started 2026-12-01T10:00:00+00:00, pid {2**22 + 7}) "
            "ended without venting; its last commanded pressure was 2.5 bar at "
            "2026-12-01T10:05:00+00:00: vented now") in err
    assert not (folder / "dead.json").exists()
    if command[0] == "acquire":
        (run_dir,) = (tmp_path / "runs").iterdir()
        assert load_run(run_dir).meta.unvented_before[0]["last_command_bar"] == 2.5


def test_console_close_is_a_stop_that_waits_for_the_vent():
    # Windows: closing the console calls the control handler in another thread; it must stop
    # the main thread as SIGBREAK does and hold the process until the run has recorded.
    interrupted = []
    guard = StopSignals(interrupt_main=interrupted.append)
    assert guard.on_console_event(CTRL_C_EVENT) is False  # Python raises SIGINT itself
    done_at = []

    def the_run_recorded():
        done_at.append(time.monotonic())
        guard.done()

    threading.Timer(0.2, the_run_recorded).start()
    assert guard.on_console_event(CTRL_CLOSE_EVENT) is True
    returned = time.monotonic()
    # released by done(), not before it nor by the hold's limit (a loaded machine's timer may
    # be late, never by seconds); timed from the timer's start, a pause of this process
    # between that start and the clock's reading under load gave 0.14 s where 0.2 s was least
    assert done_at and done_at[0] <= returned < done_at[0] + CONSOLE_HOLD_S - 0.5
    assert interrupted == [getattr(signal, "SIGBREAK", signal.SIGTERM)]
    assert guard.console_event == "console closed"


def test_stop_signal_names_the_signal_and_exit_code():
    stop = StopSignal(signal.SIGTERM)
    assert stop.name == "SIGTERM" and stop.exit_code == 128 + signal.SIGTERM
    assert str(StopSignal(signal.SIGINT, "second Ctrl-C")) == "SIGINT (second Ctrl-C)"


class _Kernel32:
    """``kernel32.SetConsoleCtrlHandler`` as Windows has it: it keeps the registered handler
    (a ctypes callback), which Windows then calls on its own thread at a console event."""

    def __init__(self):
        self.registrations = []

    def SetConsoleCtrlHandler(self, handler, add):  # noqa: N802 (the Windows name)
        self.registrations.append((handler, bool(add)))
        return 1


@pytest.fixture
def windows_console(monkeypatch):
    """The Windows API part of mkm.bench.signals on this platform: WINDOWS set, ``ctypes.windll``
    a fake kernel32, ``WINFUNCTYPE`` the C calling convention (stdcall exists on Windows only)."""
    import ctypes

    import mkm.bench.signals as signals

    kernel32 = _Kernel32()
    monkeypatch.setattr(signals, "WINDOWS", True)
    monkeypatch.setattr(ctypes, "windll", type("WinDLL", (), {"kernel32": kernel32}),
                        raising=False)
    monkeypatch.setattr(ctypes, "WINFUNCTYPE", ctypes.CFUNCTYPE, raising=False)
    return kernel32


def test_the_console_handler_is_registered_called_through_ctypes_and_removed(windows_console):
    guard = StopSignals()
    with guard:
        ((handler, added),) = windows_console.registrations
        assert added
        assert handler(CTRL_C_EVENT) == 0  # not ours: Python turns Ctrl-C into SIGINT
        returned = []
        caller = threading.Thread(target=lambda: returned.append(handler(CTRL_CLOSE_EVENT)))
        with pytest.raises(StopSignal) as stop:  # Windows' thread stops the main thread
            caller.start()
            # ended by the StopSignal as soon as that thread runs; the bound is a net only
            deadline = time.monotonic() + 30.0
            while time.monotonic() < deadline:
                time.sleep(0.01)
        assert stop.value.detail == "console closed"
        assert caller.is_alive()  # held until the run has recorded
        guard.done()
        caller.join(1.0)
        assert returned == [1]
    assert windows_console.registrations[-1] == (handler, False)


@pytest.mark.slow  # a real-clock run held at pressure, about 3 s
def test_console_close_vents_then_records_within_the_grace_time(config, tmp_path, monkeypatch,
                                                                 windows_console, run_events):
    # Windows ends the process when the handler returns, at the latest 5 s after the event. A
    # regulator stuck at pressure keeps the vent check waiting up to vent_timeout_s (10 s), so
    # the run must vent, keep its books and cut the check short so as to be recorded in time.
    # The hold is shortened to 1.5 s here (the same code path, a third of the wait).
    import mkm.bench.signals as signals
    from mkm.bench.run import BenchRun, make_backend

    monkeypatch.setattr(signals, "CONSOLE_HOLD_S", 1.5)
    handle = signals.StopSignals._handle

    def handled(self, signum, frame):  # in the run's thread, where the stop comes
        run_events.append(("signal", signum))
        return handle(self, signum, frame)

    monkeypatch.setattr(signals.StopSignals, "_handle", handled)
    stuck_at_s = 1.5  # sample time: the first step (0.5 bar) has raised the pressure
    c = config.replace(sequence={"tare_s": 1.0},
                       sim={"faults": {"regulator_stuck_at_s": stuck_at_s}})
    assert c.safety.vent_timeout_s > 4 * signals.CONSOLE_HOLD_S
    run = BenchRun(c, make_backend(c, "real"), tmp_path / "runs", notify=lambda m: None)
    seen = {}

    def windows_closes_the_console():
        while run.acquisition is None or run.acquisition.next_index < 10 * (stuck_at_s + 0.2):
            time.sleep(0.01)
        ((handler, _),) = windows_console.registrations
        seen["event"], seen["unix"] = time.monotonic(), time.time()
        seen["returned"] = handler(CTRL_CLOSE_EVENT)
        seen["released"] = time.monotonic()
        # Windows ends the process here: what the run folder says now is all it will say
        seen["run.json"] = json.loads((run.recorder.path / "run.json").read_text())

    closer = threading.Thread(target=windows_closes_the_console)
    closer.start()
    result = run.execute()
    closer.join(5.0)
    assert seen["returned"] == 1
    assert seen["released"] - seen["event"] < signals.CONSOLE_HOLD_S
    meta = seen["run.json"]
    assert meta["status"] == "failed" and meta["stop_signal"] == "SIGTERM"
    assert "console closed" in meta["reason"] and "cut short" in meta["reason"]
    assert meta["manual_vent_required"] and "VENT BY HAND" in meta["reason"]
    assert meta["vent_check"]["pressure_bar"] > c.safety.vent_below_bar  # stuck, held
    # the vent first: the run's first act after the stop, with only the block it had in hand
    # finished, and run.json marked after it; both before Windows would end the process, the
    # promise here (the handler's hold: a vent after it is never written; measured, the vent
    # comes 0.1 s after the event, bench_console_close.py)
    (stop,) = [e for e in run_events if e[0] == "signal"]
    assert run_events.after_the_stop(stop) in ([], [run_events[run_events.index(stop) + 1],
                                                     ("books", "samples")])
    vent = run_events.index(("AO", 0.0), run_events.index(stop))
    assert ("books", "mark") in run_events[vent:]
    assert meta["vented_at_unix_s"] - seen["unix"] < signals.CONSOLE_HOLD_S
    assert meta["counters"]["samples"] == len(load_run(result.path).samples) > 0
    last = load_run(result.path).commands.iloc[-1]
    assert last["purpose"] == "vent" and last["ok"] and last["command_bar"] == 0.0
    assert result.manual_vent_required and list((tmp_path / "mkm-state").rglob("*.json"))


def test_a_signal_while_the_run_folder_is_made_leaves_no_half_made_folder(config, tmp_path,
                                                                        monkeypatch):
    # SIGTERM between run.json and the CSV files of a new folder: the run vented and said so,
    # but left a folder with run.json 'running' and no samples.csv, which every later reader
    # took for a run that died while it recorded
    from mkm.bench.run import acquire
    from mkm.bench.signals import StopSignal
    from mkm.bench.storage import RunWriter

    write_meta, written = RunWriter.write_meta, []

    def sigterm_after_the_first_run_json(self, meta):
        write_meta(self, meta)
        if not written:
            written.append(meta.status)
            raise StopSignal(signal.SIGTERM)

    monkeypatch.setattr(RunWriter, "write_meta", sigterm_after_the_first_run_json)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    assert written == ["running"]
    assert result.path is None and result.exit_code == 128 + signal.SIGTERM
    assert result.status == "aborted" and result.reason == "stopped by SIGTERM at once; vented"
    assert list((tmp_path / "runs").iterdir()) == []


def test_a_signal_just_after_the_run_folder_is_made_is_recorded_in_it(config, tmp_path,
                                                                      monkeypatch):
    # SIGTERM once the run folder is whole but before the run held its recorder: the run
    # vented and said "stopped by SIGTERM" with no folder, and left the folder with run.json
    # 'running', which every later reader took for a run that died while it recorded. Now
    # the signal waits for the recorder, and the folder says why the run stopped
    from mkm.bench import recorder
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    init = recorder.Recorder.__init__

    def signalled_once_made(self, *args, **kwargs):
        init(self, *args, **kwargs)
        run.signals._handle(signal.SIGTERM, None)  # what the handler does as it arrives

    monkeypatch.setattr(recorder.Recorder, "__init__", signalled_once_made)
    run = BenchRun(config, SimBackend(config), tmp_path / "runs", handle_signals=False,
                   notify=lambda m: None)
    result = run.execute()
    assert result.status == "aborted" and result.exit_code == 128 + signal.SIGTERM
    assert result.reason == "stopped by SIGTERM at once; vented"
    (folder,) = (tmp_path / "runs").iterdir()
    assert result.path == folder
    recorded = load_run(folder)
    assert recorded.status == "aborted" and recorded.meta.reason == result.reason
    assert recorded.meta.stop_signal == "SIGTERM"


@pytest.mark.slow  # sends a signal to this process
@pytest.mark.skipif(not hasattr(signal, "pthread_kill"),
                    reason="a signal to the main thread, while it waits, needs pthread_kill")
@pytest.mark.parametrize("returns", [True, False], ids=["open-returns", "open-hangs"])
def test_a_signal_during_the_devices_open_is_held_until_the_open_ends(config, tmp_path,
                                                                     monkeypatch, returns):
    # SIGTERM while the driver is still in the device's open (waited for up to OPEN_WAIT_S on
    # a thread of its own): the shutdown wrote the vent and closed the device beside the open
    # under way (on NI the AO task not yet made: a write that does nothing), and the reason
    # said "vented". Now the signal is held until the open returns, then the vent is written
    # and said; or, past the open's bound, nothing is written behind the open that hangs, and
    # the reason says the vent is not known to be written, VENT BY HAND, exit 128 + 15.
    import mkm.bench.run as run
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    main, calls = threading.main_thread().ident, []
    opening, wrote, release = threading.Event(), threading.Event(), threading.Event()

    class SlowOpen(SimBackend):
        def open(self):
            calls.append("open")
            opening.set()
            signal.pthread_kill(main, signal.SIGTERM)  # to the thread waiting for the open
            # the test's nets: the shutdown's vent came at once when it did not wait; an open
            # that hangs is let go once the run returned
            wrote.wait(1.0) if returns else release.wait(10)
            info = super().open()
            calls.append("opened")
            return info

        def write_command(self, volts):
            if opening.is_set() and "opened" not in calls and \
                    threading.current_thread().ident == main:
                calls.append("written beside the open")
                wrote.set()
            super().write_command(volts)

        def close(self):
            calls.append("close")
            super().close()

    monkeypatch.setattr(run, "OPEN_WAIT_S", 10.0 if returns else 0.2)
    bench = BenchRun(config, SlowOpen(config), tmp_path / "runs", notify=lambda m: None)
    try:
        result = bench.execute()
    finally:
        release.set()
    assert result.exit_code == 128 + signal.SIGTERM and result.path is None
    if returns:
        assert calls == ["open", "opened", "close"]
        assert (result.status, result.reason) == (
            "aborted", "stopped by SIGTERM during the device's open, held until it returned; "
            "vented")
        assert not list((tmp_path / "mkm-state").rglob("*.json"))  # nothing pressurised
    else:
        assert calls == ["open"]  # no vent, no close behind the open that hangs
        assert (result.status, result.reason) == (
            "failed", "stopped by SIGTERM during the device's open, held until its bound "
            "passed: opening the device did not return within 0.2 s (the driver hangs): the "
            "vent is NOT known to be written (the open writes it); VENT BY HAND")


@pytest.mark.skipif(not hasattr(signal, "SIGQUIT"), reason="POSIX signals")
@pytest.mark.parametrize("name", ["SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGXCPU", "SIGRTMIN+1",
                                  "SIGABRT", "SIGTRAP", "SIGSYS"])
def test_a_signal_that_would_end_the_process_vents_and_records(config, tmp_path, name):
    # Ctrl-\ (SIGQUIT), or a SIGUSR1, SIGUSR2, SIGXCPU (ulimit -t), a real-time signal
    # (`kill -s RTMIN+1`), a SIGABRT, SIGTRAP or SIGSYS sent with kill mid-step: their default
    # action ended the process at once, the regulator holding the step's pressure (the AO
    # keeps its last value), run.json "running", the block in hand lost. Each is a stop
    # signal: vented at once, recorded with it, exit 128 + N.
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    if name.startswith("SIGRTMIN+") and not hasattr(signal, "SIGRTMIN"):
        pytest.skip("no real-time signals on this platform")
    if not name.startswith("SIGRTMIN+") and not hasattr(signal, name):
        pytest.skip(f"no {name} on this platform")
    signum = (signal.SIGRTMIN + int(name.removeprefix("SIGRTMIN+"))
              if name.startswith("SIGRTMIN+") else getattr(signal, name))
    backend = SimBackend(config)
    original = backend.read

    def read(n, timeout):
        block = original(n, timeout)
        if block.first_index == 30:  # on the 0.5 bar step (the tare's 2 s are 20 samples)
            signal.raise_signal(signum)  # its handler runs before read returns
        return block

    backend.read = read
    result = BenchRun(config, backend, tmp_path, handle_signals=True,
                      notify=lambda m: None).execute()
    assert result.status == "aborted" and result.exit_code == 128 + signum
    assert result.reason == f"stopped by {name} at once; vented"
    run = load_run(result.path)
    assert run.meta.stop_signal == name and run.meta.stop_signal_number == signum
    acquired = run.samples[run.samples["phase"] != "vent"]
    assert list(acquired["sample"]) == list(range(31))  # the block in hand kept
    assert (run.commands["command_bar"] > 0).any()  # it was pressurised
    assert backend.commands[-1][1] == 0.0 and run.commands["purpose"].iloc[-1] == "vent"
    assert run.meta.vent_check["verified"]
    assert signal.getsignal(signum) == signal.SIG_DFL  # given back after the run


def test_a_second_ctrl_c_before_the_safe_point_vents_at_once(config, tmp_path):
    # the first Ctrl-C stops at the next block's end; a second one before it (both arrive
    # while a block is read, their handlers run before the read returns) stops at once
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    backend = SimBackend(config)
    original = backend.read

    def read(n, timeout):
        block = original(n, timeout)
        if block.first_index == 30:  # on the 0.5 bar step (the tare's 2 s are 20 samples)
            signal.raise_signal(signal.SIGINT)
            signal.raise_signal(signal.SIGINT)
        return block

    backend.read = read
    result = BenchRun(config, backend, tmp_path, handle_signals=True,
                      notify=lambda m: None).execute()
    assert result.exit_code == 128 + signal.SIGINT and result.status == "aborted"
    assert result.reason == "stopped by SIGINT (second Ctrl-C) at once; vented"
    run = load_run(result.path)
    assert run.meta.stop_signal == "SIGINT" and run.meta.stop_signal_number == signal.SIGINT
    acquired = run.samples[run.samples["phase"] != "vent"]
    assert list(acquired["sample"]) == list(range(31))  # the block in hand kept
    assert (run.commands["command_bar"] > 0).any() and run.meta.vent_check["verified"]
    assert backend.commands[-1][1] == 0.0 and run.commands["purpose"].iloc[-1] == "vent"


def test_a_signal_as_a_pressure_write_returns_leaves_it_in_the_books(config, tmp_path):
    # SIGTERM arrives as the write of the 0.5 bar step returns: the stop cut the books, the
    # device holding 0.5 bar while commands.csv called the write failed and the run's last
    # pressure commanded stayed 0 bar (what a vent that then fails says the regulator may still
    # hold). The signal is held until the write's books are kept, then vents as ever.
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    backend = SimBackend(config)
    write = backend.write_command

    def signalled_as_it_returns(volts):
        write(volts)
        if volts > 0:
            signal.raise_signal(signal.SIGTERM)  # its handler runs as the write returns

    backend.write_command = signalled_as_it_returns
    run = BenchRun(config, backend, tmp_path, handle_signals=True, notify=lambda m: None)
    result = run.execute()
    assert result.status == "aborted" and result.exit_code == 128 + signal.SIGTERM
    assert result.reason == "stopped by SIGTERM at once; vented"
    commands = load_run(result.path).commands
    assert list(commands["purpose"]) == ["vent", "vent", "step", "vent"]
    assert list(commands["ok"]) == [True] * 4  # the step's write reached the device
    assert commands["command_bar"].iloc[2] == 0.5 == run.acquisition.pressure_commanded_bar
    volts = [v for _, v in backend.commands]  # the device's own: 0.5 bar, then vents only
    assert volts.count(1.25) == 1 and set(volts[volts.index(1.25) + 1:]) == {0.0}


@pytest.mark.slow  # starts a process that aborts
def test_an_abort_still_ends_the_process_with_the_stop_handlers_installed(tmp_path):
    # SIGABRT is a stop signal while a run goes; the process's own abort() (a driver's failed
    # assertion) must still end it, not return into the code that aborted: C's abort restores
    # the default action and raises again once the handler returns
    script = ("import os\nfrom mkm.bench.signals import StopSignals\n"
              "with StopSignals():\n    os.abort()\n")
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=30, cwd=tmp_path)
    expected = -signal.SIGABRT if sys.platform != "win32" else 3
    assert proc.returncode == expected, proc.stderr


@pytest.mark.skipif(not hasattr(signal, "SIGPROF"), reason="POSIX signals")
def test_a_signal_handled_by_its_own_handler_is_left_to_it(config, tmp_path):
    # a profiler's SIGPROF, a test timer's SIGALRM (pytest-timeout's): not the run's to take
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    def own(signum, frame):
        pass

    previous = signal.signal(signal.SIGPROF, own)
    try:
        backend = SimBackend(config)
        original, seen = backend.read, []

        def read(n, timeout):
            seen.append(signal.getsignal(signal.SIGPROF))
            return original(n, timeout)

        backend.read = read
        result = BenchRun(config, backend, tmp_path, handle_signals=True,
                          notify=lambda m: None).execute()
        assert result.status == "complete" and set(seen) == {own}
    finally:
        signal.signal(signal.SIGPROF, previous)


@pytest.mark.skipif(not hasattr(signal, "SIGTSTP"), reason="POSIX job control")
def test_ctrl_z_does_not_suspend_a_run(config, tmp_path):
    # Ctrl-Z on the 0.5 bar step suspended the process: the regulator held the step's pressure
    # with no interlock watching for as long as it stayed suspended (`mkm vent` could only ask
    # it to stop). It is refused, said once, and the run goes on to its end.
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    backend = SimBackend(config)
    original, said = backend.read, []

    def read(n, timeout):
        block = original(n, timeout)
        if block.first_index == 30:
            signal.raise_signal(signal.SIGTSTP)  # its handler runs before read returns
        return block

    backend.read = read
    result = BenchRun(config, backend, tmp_path, handle_signals=True,
                      notify=said.append).execute()
    assert result.status == "complete" and result.exit_code == 0, result.reason
    assert said.count("Ctrl-Z does not suspend a run: suspended, it would hold the regulator's "
                      "pressure with no interlock watching; Ctrl-C stops it at a safe point, "
                      "vented") == 1
    assert signal.getsignal(signal.SIGTSTP) == signal.SIG_DFL  # given back after the run


@pytest.mark.skipif(not hasattr(signal, "SIGTTOU"), reason="POSIX job control")
@pytest.mark.parametrize("name", ["SIGTTOU", "SIGTTIN"])
def test_a_run_in_the_background_is_not_stopped_by_its_terminal(config, tmp_path, name):
    # `mkm acquire ... &` on a terminal set `stty tostop`: its first line to the terminal
    # (SIGTTOU; a manual regulator's prompt read, SIGTTIN) stopped the process, the regulator
    # holding its pressure with no interlock watching. Ignored during the run: it goes on.
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    signum = getattr(signal, name)
    backend = SimBackend(config)
    original = backend.read

    def read(n, timeout):
        block = original(n, timeout)
        if block.first_index == 30:
            signal.raise_signal(signum)
        return block

    backend.read = read
    result = BenchRun(config, backend, tmp_path, handle_signals=True,
                      notify=lambda m: None).execute()
    assert result.status == "complete" and result.exit_code == 0, result.reason
    assert signal.getsignal(signum) == signal.SIG_DFL  # given back after the run


@pytest.mark.parametrize("name", ["SIGINT", "SIGTSTP"])
def test_a_signal_handler_writes_nothing_the_loop_says_its_notice(config, tmp_path, name):
    # The first Ctrl-C's notice (and a refused Ctrl-Z's) was written by the signal handler,
    # which runs in the loop's own thread between two of its steps: landing inside the loop's
    # write to the console (its queue's lock held), the handler's write would wait for that
    # lock for good, and the loop, every interlock with it, with the pressure held. The handler
    # only notes it; the loop says it at its next block.
    from mkm.bench.run import BenchRun
    from mkm.bench.signals import FIRST_INTERRUPT, SUSPEND_REFUSED
    from mkm.bench.sim import SimBackend

    if not hasattr(signal, name):
        pytest.skip(f"no {name} here")
    backend = SimBackend(config)
    original, said, during = backend.read, [], []

    def read(n, timeout):
        block = original(n, timeout)
        if block.first_index == 30:
            before = len(said)
            signal.raise_signal(getattr(signal, name))  # its handler runs before this returns
            during.append(said[before:])
        return block

    backend.read = read
    result = BenchRun(config, backend, tmp_path, handle_signals=True,
                      notify=said.append).execute()
    assert during == [[]]  # nothing written by the handler
    notice = FIRST_INTERRUPT if name == "SIGINT" else SUSPEND_REFUSED
    assert said.count(notice) == 1
    assert result.status == ("aborted" if name == "SIGINT" else "complete"), result.reason


FAULTING_RUN = """
import signal, sys
from mkm.bench.config import load_config
from mkm.bench.run import BenchRun
from mkm.bench.sim import SimBackend

config = load_config(sys.argv[1])
backend = SimBackend(config)
read = backend.read

def read_then_fault(n, timeout):
    block = read(n, timeout)
    if block.first_index >= 20 and any(b > 0 for _, b in backend.commands):  # pressurised
        signal.raise_signal(getattr(signal, sys.argv[2]))  # as a fault in a driver raises it
    return block

backend.read = read_then_fault
BenchRun(config, backend, sys.argv[3], notify=lambda m: None).execute()
"""


@pytest.mark.slow  # starts a process that a fatal signal ends
@pytest.mark.skipif(sys.platform == "win32", reason="POSIX fatal signals")
@pytest.mark.parametrize("name, words", [("SIGSEGV", "Segmentation fault"),
                                         ("SIGBUS", "Bus error"),
                                         ("SIGFPE", "Floating point exception"),
                                         ("SIGILL", "Illegal instruction")])
def test_a_fatal_signal_leaves_its_trace_in_the_run_folder_and_the_next_command_says_so(
        tmp_path, capsys, name, words):
    # a fault in a driver or an extension (SIGSEGV, SIGBUS, SIGFPE, SIGILL) ends the process
    # with the regulator holding its pressure; the next command vented and called the run
    # killed, with nothing to say why: no trace was written anywhere
    config = write_config(tmp_path)
    proc = subprocess.run([sys.executable, "-c", FAULTING_RUN, str(config), name,
                           str(tmp_path / "runs")], capture_output=True, text=True, timeout=60)
    assert proc.returncode == -getattr(signal, name), proc.stderr
    (folder,) = (tmp_path / "runs").iterdir()
    trace = (folder / "fatal-error.txt").read_text()
    assert trace.startswith(f"Fatal Python error: {words}\n"), trace
    assert "in read_then_fault" in trace  # the Python stack where it failed
    assert load_run(folder).problems[0] == (
        f"the run's process died of a fatal error ({words}, {name}) without closing its record: "
        f"the trace of the thread that faulted is in {folder / 'fatal-error.txt'}")  # the report
    assert main(["vent", "--config", str(config)]) == 0
    err = capsys.readouterr().err
    assert "ended without venting; its last commanded pressure was 0.5 bar" in err
    said = (f"its process died of a fatal error ({words}, {name}): the trace of the thread "
            f"that faulted is in {folder / 'fatal-error.txt'}")
    assert said in err, err
    run = load_run(folder)
    assert run.status == "killed", run.reason
    pid = run.meta.process.pid
    assert run.reason.startswith(f"its process (pid {pid}) died of a fatal error "
                                 f"({words}, {name}), at about "), run.reason
    assert run.reason.endswith(
        f"; the trace of the thread that faulted is in {folder / 'fatal-error.txt'}")


def test_a_run_that_ends_leaves_no_fatal_trace_and_gives_faulthandler_back(config, tmp_path):
    import faulthandler

    from mkm.bench.run import acquire

    enabled = faulthandler.is_enabled()
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert result.status == "complete", result.reason
    assert not (result.path / "fatal-error.txt").exists()
    assert faulthandler.is_enabled() == enabled
