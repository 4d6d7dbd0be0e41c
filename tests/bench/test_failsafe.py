"""Issue 35: a vent that vents whatever else is broken, a pressure limit watched on the measured
pressure, one lock per physical device, a run folder that tells the truth. One test (or a few)
per finding; each failed before the fix.
"""

import errno
import json
import os
import re
import sys
from pathlib import Path

import pytest

from mkm.bench.run import acquire
from mkm.bench.storage import load_run
from mkm.core.home import user_state

QUIET = {"notify": lambda m: None}


def _lock_path(bench_key):
    from mkm.bench.unvented import bench_folder_name

    return user_state() / "benches" / f"{bench_folder_name(bench_key)}.lock"


def _commands_of_vents(monkeypatch):
    """Record every AO write of the simulated bench (volts), across the backends made."""
    from mkm.bench.sim import SimBackend

    written: list[float] = []
    write = SimBackend.write_command

    def spy(self, volts):
        write(self, volts)
        written.append(float(volts))

    monkeypatch.setattr(SimBackend, "write_command", spy)
    return written


# 1. mkm vent vents first, bookkeeping after --------------------------------------------------

def test_vent_with_a_lock_that_is_a_folder_vents_then_says_so(mkm_cli, monkeypatch):
    written = _commands_of_vents(monkeypatch)
    _lock_path("sim-Dev1").mkdir(parents=True)
    code, out, err = mkm_cli(["vent", "--backend", "sim"])
    assert out.startswith("vented: 0.000 bar") and written and set(written) == {0.0}
    assert code == 1 and "Traceback" not in err and err.count("mkm vent: error") == 1
    assert "vented, but the bench bookkeeping failed" in err and "is not a file" in err


def test_vent_with_a_read_only_state_folder_vents_then_says_so(mkm_cli, monkeypatch):
    from pathlib import Path

    state, mkdir = user_state(), Path.mkdir

    def read_only(self, *args, **kwargs):  # as root, chmod cannot make a folder read-only
        if self == state or state in self.parents:
            raise OSError(errno.EROFS, "Read-only file system")
        return mkdir(self, *args, **kwargs)

    monkeypatch.setattr(Path, "mkdir", read_only)
    written = _commands_of_vents(monkeypatch)
    code, out, err = mkm_cli(["vent", "--backend", "sim"])
    assert out.startswith("vented: 0.000 bar") and written
    assert code == 1 and "cannot be made (Read-only file system)" in err
    assert "Traceback" not in err


def test_vent_with_a_full_state_folder_vents_then_says_so(mkm_cli, monkeypatch):
    import mkm.bench.ownership as ownership

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(ownership, "write_atomic", full)
    written = _commands_of_vents(monkeypatch)
    code, out, err = mkm_cli(["vent", "--backend", "sim"])
    assert out.startswith("vented: 0.000 bar") and written
    assert code == 1 and "not writable (No space left on device)" in err


@pytest.mark.parametrize("argv", [["tare", "--backend", "sim"], ["check", "--backend", "sim"],
                                  ["calibrate-loadcell", "--backend", "sim", "--masses", "0,1,2"],
                                  ["vent", "--backend", "sim"]])
@pytest.mark.parametrize("at", ["open", "read"])
def test_every_bench_command_says_an_os_error_of_the_device_in_words(mkm_cli, monkeypatch,
                                                                     argv, at):
    # the driver raises an OSError (a crash inside its DLL, a USB stack's I/O error) as the
    # device opens or as it is read: tare, check and calibrate-loadcell said "[Errno 5]
    # Input/output error", exit 2, as a bad argument. Every bench command says it as vent
    # does, exit 1 as the device's other failures; vent asks for a vent by hand
    from mkm.bench.sim import SimBackend

    def broken(self, *args, **kwargs):
        raise OSError(errno.EIO, "Input/output error")

    monkeypatch.setattr(SimBackend, at, broken)
    code, out, err = mkm_cli(argv)
    said = ("the DAQ device or its driver failed (Input/output error): check its USB cable "
            "and power" + ("; VENT BY HAND" if argv[0] == "vent" else ""))
    assert code == 1 and out == "" and "Traceback" not in err
    assert err.splitlines()[-1] == f"mkm {argv[0]}: error: {said}"


def test_an_os_error_naming_a_file_is_not_said_as_the_device_s():
    # an error of a file met while the device was driven (the state folder's disk full) names
    # that file, not the DAQ device's cable
    from mkm.bench.backend import device_said

    full = OSError(errno.ENOSPC, "No space left on device", "/state/benches/sim-dev1.lock")
    assert device_said(full) == "No space left on device: /state/benches/sim-dev1.lock"


def test_vent_with_a_state_folder_that_hangs_vents_then_says_so(monkeypatch):
    # the state folder (a roaming profile on a network share) hangs as `mkm vent` looks for a
    # run holding the bench: the vent never went out. Now it goes out once the state folder has
    # not answered within the wait (none here: the hang is certain), and the line says why the
    # bookkeeping was left
    import threading

    import filelock

    from mkm.bench import procedures
    from mkm.bench.config import load_config

    monkeypatch.setattr(procedures, "STATE_START_S", 0.0)
    _lock_path("sim-Dev1").parent.mkdir(parents=True)
    release, acquire = threading.Event(), filelock.FileLock.acquire
    asked, request_stop = threading.Event(), procedures.request_stop

    def hanging(self, *args, **kwargs):
        release.wait(120)  # released below
        return acquire(self, *args, **kwargs)

    def ends(*args, **kwargs):  # the request to stop, let go at the end: waited for below
        try:
            return request_stop(*args, **kwargs)
        finally:
            asked.set()

    monkeypatch.setattr(filelock.FileLock, "acquire", hanging)
    monkeypatch.setattr(procedures, "request_stop", ends)
    written = _commands_of_vents(monkeypatch)
    try:
        out = procedures.vent(load_config(), backend="sim", notify=lambda m: None,
                              stop_wait_s=0.0)
    finally:
        release.set()
    assert asked.wait(120)  # its thread is done with this test's state folder and lock
    assert out["vented"] and out["pressure_bar"] < 0.05 and written and set(written) == {0.0}
    (problem,) = out["bookkeeping"]  # `mkm vent` says it on one line, exit 1
    assert problem.endswith("did not answer within 0 s (it hangs): no run holding the bench "
                            "was asked to stop, the bench was vented without its lock and the "
                            "markers of dead runs were not looked for")


def test_vent_asks_in_the_state_folder_it_was_called_with_however_late(monkeypatch, tmp_path):
    # the thread that asks a holder to stop ran after `vent` had returned (a busy machine),
    # and only then read MKM_STATE_DIR: in a process that had moved it since (the test after,
    # the Python API), it took the lock of another state folder's bench. Now the folder is
    # resolved as `vent` is called
    import threading

    from mkm.bench import procedures
    from mkm.bench.config import load_config

    called_with, later = _lock_path("sim-Dev1"), tmp_path / "later-state"
    called_with.parent.mkdir(parents=True)
    (later / "benches").mkdir(parents=True)
    go, asked, request_stop = threading.Event(), threading.Event(), procedures.request_stop

    def late(*args, **kwargs):
        go.wait(120)  # set below, once `vent` has returned and the folder moved
        try:
            return request_stop(*args, **kwargs)
        finally:
            asked.set()

    monkeypatch.setattr(procedures, "STATE_START_S", 0.0)
    monkeypatch.setattr(procedures, "request_stop", late)
    try:
        out = procedures.vent(load_config(), backend="sim", notify=lambda m: None,
                              stop_wait_s=0.0)
        monkeypatch.setenv("MKM_STATE_DIR", str(later))
    finally:
        go.set()
    assert asked.wait(120)
    assert out["vented"] and str(called_with.parent.parent.parent) in out["bookkeeping"][0]
    assert called_with.is_file()  # the free bench was probed there: its lock file
    assert list((later / "benches").iterdir()) == []


def test_a_run_is_refused_not_started_when_the_lock_is_a_folder(config, tmp_path):
    from mkm.bench.backend import BenchError

    _lock_path("sim-Dev1").mkdir(parents=True)
    with pytest.raises(BenchError, match="is not a file"):
        acquire(config, out_root=tmp_path / "runs", **QUIET)
    assert list((tmp_path / "runs").iterdir()) == []


# 2. over-pressure on the measured pressure ----------------------------------------------------

def test_a_small_overshoot_held_at_the_limit_fails_the_run(config, tmp_path):
    # the case: 2.5 bar commanded at max_pressure_bar 2.5, the regulator delivers 2.64;
    # above 2.55 bar (2 % margin) for more than 1 s is an over-pressure
    c = config.replace(sequence={"pressures_bar": (2.5,)}, sim={"faults": {"overshoot_bar": 0.14}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 1
    assert "over-pressure interlock: 2.6" in result.reason and "for more than 1 s" in result.reason
    assert run.meta.vent_check["verified"]
    assert run.samples["pressure_bar"].max() < 2.5 * 1.1  # never reached the hard margin


def test_a_wide_tolerance_cannot_permit_an_over_pressure(config, tmp_path):
    # accepted by check: a 10 bar regulator with a 1 bar tolerance; an overshoot of 0.95 bar
    # heads for 3.45 bar at 2.5 bar commanded, and the hard margin (2.75 bar) trips at once
    c = config.replace(regulator={"full_scale_bar": 10.0},
                       safety={"pressure_tolerance_bar": 1.0},
                       sequence={"pressures_bar": (2.5,)}, sim={"faults": {"overshoot_bar": 0.95}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 1
    assert "over-pressure interlock" in result.reason and "+ 0.25 bar" in result.reason
    # samples are 0.1 s apart at most 2 bar/s of slew: at most 0.2 bar past the margin
    assert run.samples["pressure_bar"].max() < 2.75 + 0.2


def test_a_hand_regulator_turned_past_the_limit_fails_the_run(config, tmp_path):
    # a manual regulator: the measured pressure is the manometer reading the operator types;
    # 2.5 bar typed at the 1.0 bar step (max_pressure_bar 2.0) is an over-pressure, not a step
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    class Overshooting:
        def set_pressure(self, pressure_bar):
            return 2.5 * pressure_bar

        def vent(self):
            return 0.0

    c = config.replace(regulator={"kind": "manual", "max_pressure_bar": 2.0})
    result = BenchRun(c, SimBackend(c), tmp_path, operator=Overshooting(), handle_signals=False,
                      **QUIET).execute()
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 1
    assert result.reason.startswith("over-pressure interlock: 2.500 bar measured at ")
    tripped = run.samples[run.samples["flags"] == "interlock"]
    assert list(tripped["pressure_bar"]) == [2.5] and list(tripped["step"]) == [1]
    assert run.steps["set_pressure_bar"].tolist() == [0.5]  # the 1.0 bar step was not recorded


def test_a_normal_run_to_the_limit_is_not_an_over_pressure(config, tmp_path):
    c = config.replace(sequence={"pressures_bar": (2.5,)})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "complete" and result.exit_code == 0


# 3. one lock per physical device ------------------------------------------------------------

@pytest.mark.parametrize("device", ["dev1", "Dev1 ", "DEV1"])
def test_one_device_written_differently_is_one_bench(config, tmp_path, device):
    from mkm.bench.ownership import BenchBusy, BenchOwner
    from mkm.bench.sim import SimBackend

    held = SimBackend(config)
    other = config.replace(daq={"device": device})
    with BenchOwner(held.bench_key, "acquire"):
        with pytest.raises(BenchBusy, match="in use by pid"):
            acquire(other, out_root=tmp_path / "runs", **QUIET)
    assert _lock_path(SimBackend(other).bench_key) == _lock_path(held.bench_key)


def test_a_real_bench_is_keyed_by_its_serial_number(config, fake_driver):
    from mkm.bench.ni import NIBackend

    # the fake driver's device has serial 0x1F2E3D4, whatever NI MAX calls it
    keys = {NIBackend(config.replace(daq={"backend": "ni", "device": d})).bench_key
            for d in ("Dev1", "bench-left")}
    assert keys == {"ni-serial-1F2E3D4"}


# 4. a dead run's folder is mended by the command that finds it --------------------------------

def _killed_run(tmp_path):
    """`mkm acquire --clock real` killed (SIGKILL) once it has commanded a pressure; returns the
    run folder. The run records into a relative --out, as an operator types it."""
    import signal
    import subprocess
    import time

    from mkm.bench.config import load_config

    text = load_config().text.replace("tare_s = 5.0", "tare_s = 2.0")
    (tmp_path / "bench.toml").write_text(text, encoding="utf-8")
    proc = subprocess.Popen(
        [sys.executable, "-m", "mkm", "acquire", "--config", "bench.toml", "--clock", "real",
         "--out", "runs", "--no-progress"], cwd=tmp_path, stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            commands = list((tmp_path / "runs").glob("*/commands.csv"))
            if commands and "2.5" in commands[0].read_text():
                break
            time.sleep(0.1)
        else:
            raise AssertionError("the run never commanded a pressure")
    finally:
        proc.send_signal(signal.SIGKILL if hasattr(signal, "SIGKILL") else signal.SIGTERM)
        proc.wait(30)
    return commands[0].parent


def test_the_command_that_finds_a_killed_run_mends_its_folder(tmp_path, mkm_cli):
    from mkm.bench.unvented import find_unvented

    path = _killed_run(tmp_path)
    ((_, marker),) = find_unvented("sim-Dev1")
    assert marker.run_path == str(path.resolve())  # absolute, whatever the cwd was
    assert json.loads((path / "run.json").read_text())["status"] == "running"
    code, out, err = mkm_cli(["vent", "--backend", "sim"])
    assert code == 0 and "run.json mended: status killed" in err
    meta = json.loads((path / "run.json").read_text())
    rows = len((path / "samples.csv").read_text().splitlines()) - 1
    assert meta["status"] == "killed" and meta["counters"]["samples"] == rows > 10
    assert "died without closing the record" in meta["reason"] and meta["ended_utc"]
    assert "last commanded pressure was 2.5 bar" in meta["reason"]
    assert find_unvented("sim-Dev1") == []
    run = load_run(path)
    assert run.status == "killed" and not run.complete


def test_a_signal_after_the_run_was_recorded_does_not_contradict_it(tmp_path):
    import subprocess

    # SIGTERM sent to itself right after the run was recorded, before the process exits
    script = (
        "import os, signal, sys\n"
        "import mkm.bench.run as run\n"
        "from mkm.__main__ import run as mkm\n"
        "execute = run.BenchRun.execute\n"
        "def late(self):\n"
        "    result = execute(self)\n"
        "    os.kill(os.getpid(), signal.SIGTERM)\n"
        "    return result\n"
        "run.BenchRun.execute = late\n"
        "sys.argv = ['mkm', 'acquire', '--pressures', '0.5', '--out', 'runs', '--no-progress']\n"
        "mkm()\n")
    proc = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    (path,) = (tmp_path / "runs").iterdir()
    assert json.loads((path / "run.json").read_text())["status"] == "complete"
    assert proc.returncode == 0, proc.stderr[-500:]


# 5. no success without content --------------------------------------------------------------

@pytest.fixture
def recorded(config, tmp_path):
    return acquire(config, out_root=tmp_path / "runs", **QUIET).path


def _header_only(path):
    lines = (path / "samples.csv").read_text().splitlines()
    (path / "samples.csv").write_text(lines[0] + "\n")


def test_reprocess_of_a_run_without_samples_refuses(recorded, tmp_path, mkm_cli):
    _header_only(recorded)
    (tmp_path / "new.toml").write_text('[loadcell]\nchannel = "ai0"\ncapacity_N = 1961.33\n'
                                       'sensitivity_N_per_V = 200.0\noffset_V = 0.0\n')
    before = sorted((tmp_path / "runs").iterdir())
    code, out, err = mkm_cli(["reprocess", str(recorded), "--config",
                              str(tmp_path / "new.toml")])
    assert code == 2 and out == "" and err.count("\n") == 1
    # the header alone of a run that counted its samples: the loss is named
    assert "samples.csv holds 0 samples, run.json counted" in err
    assert "expected the whole record to reprocess" in err
    assert sorted((tmp_path / "runs").iterdir()) == before  # nothing written


@pytest.mark.parametrize("damage", ["header only", "missing", "fifo", "link to /dev/zero",
                                    "no finite force"])
def test_export_of_a_run_without_content_refuses(recorded, tmp_path, mkm_cli, damage,
                                                  symlink):
    samples = recorded / "samples.csv"
    if damage == "header only":
        _header_only(recorded)
    elif damage == "missing":
        samples.unlink()
    elif damage == "fifo":
        if not hasattr(os, "mkfifo"):
            pytest.skip("no FIFOs here")
        samples.unlink()
        os.mkfifo(samples)
    elif damage == "link to /dev/zero":
        if not Path("/dev/zero").exists():
            pytest.skip("no /dev/zero here")
        samples.unlink()
        symlink(samples, "/dev/zero")
    else:
        lines = samples.read_text().splitlines()
        header = lines[0].split(",")
        k = header.index("force_N")
        rows = [row.split(",") for row in lines[1:]]
        for row in rows:
            row[k] = ""
        samples.write_text("\n".join([lines[0], *(",".join(r) for r in rows)]) + "\n")
    out_file = tmp_path / "out.xlsx"
    code, out, err = mkm_cli(["export", str(recorded), "--out", str(out_file)])
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert not out_file.exists()


def test_export_of_a_dead_run_says_incomplete_not_running(recorded, tmp_path, mkm_cli):
    meta = json.loads((recorded / "run.json").read_text())
    meta["status"], meta["process"]["pid"] = "running", 2**22 + 5  # dead
    (recorded / "run.json").write_text(json.dumps(meta))
    code, _, err = mkm_cli(["export", str(recorded), "--format", "csv", "--out",
                            str(tmp_path / "csv")])
    assert code == 0, err
    text = (tmp_path / "csv" / "metadata.csv").read_text()
    assert "status,incomplete" in text and "status,running" not in text


# 6. guarded readers -------------------------------------------------------------------------

MUSCLE = ["--id", "lab-7", "--D0", "30", "--t0", "3", "--L0", "282", "--eps", "0.1"]


def _workbook(path, sheet_xml: bytes | None = None, pad_bytes: int = 0):
    """A real .xlsx written by openpyxl, its first sheet's XML replaced or padded if asked."""
    import zipfile

    import pandas as pd

    pd.DataFrame({"pressure_bar": [0.5, 1.0], "force_N": [10.0, 20.0]}).to_excel(
        path, index=False, engine="openpyxl")
    if sheet_xml is None and not pad_bytes:
        return path
    with zipfile.ZipFile(path) as old:
        members = {m.filename: old.read(m) for m in old.infolist()}
    if sheet_xml is not None:
        members["xl/worksheets/sheet1.xml"] = sheet_xml
    if pad_bytes:  # highly compressible: a small file that expands to pad_bytes
        members["xl/media/pad.bin"] = b"\0" * pad_bytes
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as new:
        for name, data in members.items():
            new.writestr(name, data)
    return path


BILLION_LAUGHS = (b'<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">'
                  b'<!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">]>'
                  b'<worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/'
                  b'main"><sheetData><row r="1"><c r="A1" t="inlineStr"><is><t>&lol2;</t>'
                  b'</is></c></row></sheetData></worksheet>')


@pytest.mark.parametrize("name, make, message", [
    ("empty.csv", lambda p: p.write_bytes(b""), "is empty (0 bytes)"),
    ("text.xlsx", lambda p: p.write_text("pressure_bar,force_N\n1,2\n"),
     "is not an Excel workbook"),
    ("random.xlsx", lambda p: p.write_bytes(bytes(range(256)) * 40), "is not an Excel workbook"),
    ("laughs.xlsx", lambda p: _workbook(p, BILLION_LAUGHS), "holds an XML document type"),
    ("bomb.xlsx", lambda p: _workbook(p, pad_bytes=250_000_000), "expands to"),
    ("passwd.csv", None, "is a symbolic link: refused"),
])
def test_hostile_tables_are_refused_in_one_line(tmp_path, mkm_cli, symlink, name, make,
                                                message):
    table = tmp_path / name
    if make is None:  # a link to a file a table never is
        if not Path("/etc/passwd").exists():
            pytest.skip("no /etc/passwd here")
        symlink(table, "/etc/passwd")
    else:
        make(table)
    code, out, err = mkm_cli(["import", str(table), *MUSCLE, "--out", str(tmp_path / "runs")])
    assert code == 2 and out == "" and err.count("\n") == 1 and message in err, err
    assert "root:" not in err  # no file content in a message
    assert not (tmp_path / "runs").exists() or not any((tmp_path / "runs").iterdir())


def test_a_real_workbook_still_imports(tmp_path, mkm_cli):
    code, out, err = mkm_cli(["import", str(_workbook(tmp_path / "lab.xlsx")), *MUSCLE,
                              "--out", str(tmp_path / "runs")])
    assert code == 0, err
    assert load_run(out.strip()).status == "imported"


def test_link_tests_skip_where_the_platform_refuses_links(symlink, tmp_path, monkeypatch):
    # Windows without developer mode: os.symlink raises OSError, WinError 1314
    def refuse(src, dst, target_is_directory=False):
        raise OSError(1314, "A required privilege is not held by the client")

    monkeypatch.setattr(os, "symlink", refuse)
    refused = type(symlink)(tmp_path)  # the probe, tried once
    assert "cannot make symbolic links here" in refused.reason
    with pytest.raises(pytest.skip.Exception, match="privilege is not held"):
        refused(tmp_path / "link", tmp_path / "target")
    assert symlink.reason is None or sys.platform == "win32"  # links work on Linux and macOS


@pytest.mark.parametrize("name", ["run.json", "samples.csv", "steps.csv"])
def test_a_run_folder_file_that_is_a_link_is_refused(recorded, name, symlink):
    target = recorded.parent / f"elsewhere-{name}"
    (recorded / name).rename(target)
    symlink(recorded / name, target)
    with pytest.raises(ValueError, match=f"{name} is a symbolic link: refused"):
        load_run(recorded).samples  # noqa: B018 (read on first use)


def test_a_run_folder_deleted_mid_run_stops_the_run(config, tmp_path, monkeypatch):
    # the folder removed after the tare (a clean-up of the runs folder): the run must not go on
    # pressurising the muscle into files no one can read; it vents and says what happened
    import shutil

    from mkm.bench.recorder import Recorder

    tare = Recorder.tare

    def tare_then_delete(self, values):
        tare(self, values)
        self.wait_written()  # recorded, then deleted
        shutil.rmtree(self.path)

    monkeypatch.setattr(Recorder, "tare", tare_then_delete)
    written = _commands_of_vents(monkeypatch)
    result = acquire(config, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 2
    assert re.search(r"(samples|commands)\.csv was deleted while recording \(its rows went "
                     r"with it\): the run folder was removed", result.reason)
    assert written[-2:] == [0.0, 0.0]  # the step's command went out, then the vent, then close
    meta = json.loads((result.path / "run.json").read_text(encoding="utf-8"))
    assert meta["status"] == "failed" and meta["vent_check"]["verified"]
    assert meta["counters"]["samples"] == 20  # the 2 s tare, then nothing more was recorded


@pytest.mark.parametrize("failure", [OSError(errno.ENOSPC, "No space left on device"),
                                     KeyboardInterrupt()])
def test_a_report_cut_short_leaves_nothing_partial(recorded, tmp_path, monkeypatch, failure):
    import mkm.report as report

    out = tmp_path / "report"
    out.mkdir()
    (out / "notes.txt").write_text("the user's own file")

    def cut(*args, **kwargs):  # the disk fills (or Ctrl-C) at the first figure
        raise failure

    monkeypatch.setattr(report, "save_figure", cut)
    expected = ValueError if isinstance(failure, OSError) else KeyboardInterrupt
    with pytest.raises(expected) as caught:
        report.build_report([recorded], ["eq2"], out_dir=out, cache_dir=None, tolerance=None,
                            surrogate_section=False)
    if expected is ValueError:
        assert "the report was not written (No space left on device)" in str(caught.value)
    assert not [p for p in tmp_path.iterdir() if "partial" in p.name]
    assert [p.name for p in out.iterdir()] == ["notes.txt"]  # nothing partial, nothing lost


def test_a_report_that_completes_is_moved_into_place(recorded, tmp_path):
    from mkm.report import build_report

    path = build_report([recorded], ["eq2"], out_dir=tmp_path / "report", cache_dir=None,
                        tolerance=None, surrogate_section=False)
    assert path == tmp_path / "report" / "report.html" and path.is_file()
    assert (tmp_path / "report" / "summary.csv").is_file()
    assert not list(tmp_path.glob(".*partial"))
    assert ".partial" not in path.read_text(encoding="utf-8")  # no staging path leaked


# 7. settings with floors, numbers in ASCII, one truth per key, formulas ----------------------

@pytest.mark.parametrize("section, values, message", [
    ("safety", {"vent_timeout_s": 1e-320}, r"safety\.vent_timeout_s=.* is invalid: expected 2 to"),
    ("safety", {"pressure_follow_s": 1e-320}, r"safety\.pressure_follow_s=.* expected 1 to 10"),
    ("safety", {"force_limit_fraction": 1e-320}, r"force_limit_fraction=.* expected 0\.1 to 1"),
    ("daq", {"read_timeout_s": 60.0, "read_retries": 100},
     r"lets a run go 6060 s without a reading: expected at most 60 s"),
])
def test_settings_that_fail_every_run_are_refused(section, values, message):
    from mkm.bench.config import load_config

    with pytest.raises(ValueError, match=message):
        load_config().replace(**{section: values})


@pytest.mark.parametrize("text", ["٠.٥", "０.５", "0.2_5", "0,5_0"])
def test_numbers_are_ascii_decimals(text, mkm_cli, tmp_path):
    code, out, err = mkm_cli(["acquire", "--pressures", text, "--out", str(tmp_path)])
    assert code == 2 and "is not a number in ASCII decimal notation" in err, err
    assert not any(tmp_path.iterdir())


def test_run_json_with_a_repeated_key_is_refused(recorded):
    text = (recorded / "run.json").read_text()
    (recorded / "run.json").write_text(text.replace('"status": "complete"',
                                                    '"status": "complete", "status": "running"'))
    with pytest.raises(ValueError, match="the key 'status' appears twice"):
        load_run(recorded)


@pytest.mark.parametrize("cell", [" =1+1", "\n=1+1", "\uff1d1+1", "\uff0bcmd", "\u3000@x",
                                  "=1+1"])
def test_formula_cells_are_neutralised_as_a_spreadsheet_reads_them(cell):
    from mkm.core.records import spreadsheet_safe_text

    assert spreadsheet_safe_text(cell) == "'" + cell
    assert spreadsheet_safe_text("a =1") == "a =1"  # a formula only at the start


def test_a_read_timeout_while_pressurised_vents_at_once(config, tmp_path):
    # at 5 s the 0.5 bar step is commanded: one timeout (2 s blind) ends the run, vented
    c = config.replace(sim={"faults": {"read_timeout_at_s": 5.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    run = load_run(result.path)
    assert result.status == "failed" and "read interlock: no reading within 2 s" in result.reason
    assert run.meta.counters["read_timeouts"] == 1
    assert run.commands["purpose"].iloc[-1] == "vent" and run.meta.vent_check["verified"]


@pytest.mark.parametrize("timeouts", [3, 4])
def test_read_timeouts_in_the_vent_check_are_retried_as_at_0_bar(config, tmp_path, timeouts):
    # the reads time out 3 times in a row from 5 s, as the 0.5 bar step is commanded: the first
    # trips the read interlock, which vents; the vent check gave up at its first timeout and
    # asked for a vent by hand (exit 4) while the regulator exhausted the muscle. Now it
    # retries daq.read_retries (2) timeouts in a row, as the run does at 0 bar, and verifies
    # the vent; a third in a row still gives up
    c = config.replace(sim={"faults": {"read_timeout_at_s": 5.0, "read_timeouts": timeouts}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    run = load_run(result.path)
    assert result.status == "failed" and "read interlock: no reading within 2 s" in result.reason
    check = run.meta.vent_check
    if timeouts - 1 <= c.daq.read_retries:
        assert result.exit_code == 1 and not result.manual_vent_required, result.reason
        assert check["verified"] and check["pressure_bar"] < c.safety.vent_below_bar
    else:
        assert result.exit_code == 4 and result.manual_vent_required
        assert ("the vent could not be verified (the DAQ device sent no samples in time: check "
                "its USB cable and power (simulated read timeout") in result.reason
        assert not check["verified"]


# 8. hardware commands say what they drive ---------------------------------------------------

@pytest.mark.parametrize("argv", [["vent"], ["tare"], ["calibrate-loadcell", "--masses", "0,1"]])
def test_a_hardware_command_without_a_backend_refuses(argv, mkm_cli, monkeypatch):
    from mkm.bench.backends import BACKENDS

    written = _commands_of_vents(monkeypatch)
    code, out, err = mkm_cli(argv)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert f"mkm {argv[0]} drives the bench: pass --backend {'|'.join(BACKENDS)}" in err
    assert written == []  # nothing opened


@pytest.mark.parametrize("argv", [["vent"], ["tare", "--seconds", "1"],
                                  ["calibrate-loadcell", "--masses", "0,1", "--seconds", "1"]])
def test_a_simulated_hardware_command_says_so(argv, mkm_cli):
    code, out, err = mkm_cli([*argv, "--backend", "sim"])
    assert code == 0 and "SIMULATED bench (sim): no hardware is driven" in err


def test_a_fit_of_volts_measured_elsewhere_needs_no_backend(mkm_cli):
    code, out, _ = mkm_cli(["calibrate-loadcell", "--masses", "0,10", "--volts", "0.01,0.51"])
    assert code == 0 and "[loadcell]" in out


# 9. the real device's monitor: a reading no regulator gives is no vent --------------------------

def test_a_lost_monitor_mid_run_is_a_fault_not_a_vent(config, tmp_path):
    # at 4 s (the 0.5 bar step) the monitor input drops to 0 V: converted, -1 bar, which would
    # pass for vented; it is a monitor fault: the run vents and asks for a vent by hand
    c = config.replace(sim={"faults": {"monitor_lost_at_s": 4.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "monitor fault: the monitor reads 0.000 V" in result.reason
    assert "VENT BY HAND" in result.reason and not run.meta.vent_check["verified"]
    tripped = run.samples[run.samples["flags"].str.contains("interlock")]
    assert tripped["time_s"].iloc[0] == pytest.approx(4.0)  # the first sample at 0 V
    # what the regulator may still hold: the 0.5 bar step's last reading, not 0 V's -1 bar
    last = run.samples["pressure_bar"][run.samples["time_s"] < 4.0].iloc[-1]
    assert result.reason.endswith(f"VENT BY HAND (the regulator may still hold {last:.3g} bar)")
    assert last == pytest.approx(0.5, abs=0.02)
    assert run.meta.vent_check["pressure_bar"] is None  # 0 V read: no pressure


def test_run_json_of_a_vent_check_that_read_nothing_is_strict_json(config, tmp_path):
    # the monitor lost: the check's pressure is no number; run.json said NaN, which jq and
    # every strict JSON reader refuse
    c = config.replace(sim={"faults": {"monitor_lost_at_s": 4.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)

    def refuse(constant):
        raise ValueError(f"{constant} is not JSON")

    meta = json.loads((result.path / "run.json").read_text(encoding="utf-8"),
                      parse_constant=refuse)
    assert meta["vent_check"]["pressure_bar"] is None and not meta["vent_check"]["verified"]
    assert load_run(result.path).meta.vent_check["pressure_bar"] is None


def test_mkm_vent_with_a_lost_monitor_says_vent_by_hand(tmp_path, mkm_cli):
    from mkm.bench.config import load_config

    text = load_config().text.replace("monitor_noise_V = 0.001", "monitor_noise_V = 0.001\n"
                                      "[sim.faults]\nmonitor_lost_at_s = 0.0")
    (tmp_path / "lost.toml").write_text(text, encoding="utf-8")
    code, out, err = mkm_cli(["vent", "--config", str(tmp_path / "lost.toml")])
    assert code == 1 and out == "" and "VENT BY HAND" in err
    assert "could not be verified (monitor fault: the monitor reads 0.000 V" in err


def test_a_run_keeps_windows_awake_and_lets_it_sleep_after(config, tmp_path, monkeypatch):
    import ctypes

    from mkm.bench import wakelock

    states = []

    class Kernel32:
        def SetThreadExecutionState(self, flags):  # noqa: N802 (the Windows name)
            states.append((flags, len(list(tmp_path.glob("*/samples.csv")))))
            return 0x80000000

    monkeypatch.setattr(wakelock, "WINDOWS", True)
    monkeypatch.setattr(ctypes, "windll", type("WinDLL", (), {"kernel32": Kernel32()}),
                        raising=False)
    result = acquire(config, out_root=tmp_path, **QUIET)
    assert result.status == "complete"
    # asked before the run folder existed, released once it was recorded
    assert states == [(wakelock.ES_CONTINUOUS | wakelock.ES_SYSTEM_REQUIRED, 0),
                      (wakelock.ES_CONTINUOUS, 1)]


def test_a_calibration_file_that_is_a_link_is_refused(tmp_path, mkm_cli, symlink):
    from mkm.fem.calibration import CALIBRATION_FILE

    link = symlink(tmp_path / "calibration.json", CALIBRATION_FILE)
    code, out, err = mkm_cli(["fem", "solve", "--model", "eq2", "--D0", "30", "--t0", "3",
                              "--eps", "0.1", "--pressures", "1", "--calibration", str(link)])
    assert code == 2 and out == "" and "is a symbolic link: refused" in err


def test_a_state_folder_problem_is_named_not_called_a_recording_failure(config, tmp_path,
                                                                      monkeypatch):
    from mkm.bench.unvented import BenchLease

    command = BenchLease.command

    def full(self, pressure_bar):
        if pressure_bar > 0:
            raise OSError(errno.ENOSPC, "No space left on device")
        command(self, pressure_bar)

    monkeypatch.setattr(BenchLease, "command", full)
    result = acquire(config, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 1
    assert result.reason.startswith("the bench marker ")
    assert "could not be written (No space left on device)" in result.reason
    assert "recording failed" not in result.reason and "0.5 bar not commanded" in result.reason
    assert load_run(result.path).meta.vent_check is None or \
        load_run(result.path).meta.vent_check["verified"]


def test_an_os_error_of_the_device_is_not_called_a_recording_failure(config, tmp_path,
                                                                      monkeypatch):
    # the driver raises an OSError mid-run (ctypes says "OSError: exception: access violation"
    # for a crash inside a DLL; a USB stack an I/O error): the run vented and kept its samples
    # but said "recording failed", exit 2, sending the user to a disk that was fine. Now it is
    # the device's failure, exit 1; the disk's refusals stay "recording failed", exit 2
    import errno

    from mkm.bench.run import acquire
    from mkm.bench.sim import SimBackend

    read, failed = SimBackend.read, []

    def failing(self, n, timeout):  # once: the vent check's reads work
        if self._head >= 45 and not failed:
            failed.append(self._head)
            raise OSError(errno.EIO, "Input/output error")
        return read(self, n, timeout)

    monkeypatch.setattr(SimBackend, "read", failing)
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert result.status == "failed" and result.exit_code == 1
    assert result.reason == ("the DAQ device or its driver failed (Input/output error): check "
                             "its USB cable and power")
    run = load_run(result.path)
    assert run.meta.vent_check["verified"]
    s = run.samples  # every sample read before the failure, and the vent check's after it
    assert list(s["sample"]) == list(range(len(s))) and run.meta.counters["samples"] == len(s)
    assert (s["phase"] != "vent").sum() == 45


def test_a_monitor_reading_nan_after_the_vent_is_said_so(config, tmp_path, monkeypatch):
    # the monitor input reads NaN from sample 45 (0.5 bar commanded): the pressure interlock
    # vents; the vent check cannot verify it, and said "the monitor still reads nan bar 0.1 s
    # after the vent, above 0.05 bar". Now it names the reading that is no number
    import numpy as np

    from mkm.bench.run import acquire
    from mkm.bench.sim import SimBackend

    read = SimBackend.read

    def nan_monitor(self, n, timeout):
        block = read(self, n, timeout)
        index = block.first_index + np.arange(len(block.volts))
        block.volts[index >= 45, 1] = np.nan
        return block

    monkeypatch.setattr(SimBackend, "read", nan_monitor)
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert result.reason.startswith("pressure interlock: the pressure reading is not a number")
    assert result.reason.endswith("; vented; the vent could not be verified (the monitor reads "
                                  "nan V, not a number): VENT BY HAND (the regulator may still "
                                  "hold 0.5 bar)")
    assert "above" not in result.reason


def test_a_full_state_folder_as_an_unverified_vent_is_marked_is_said(config, tmp_path,
                                                                     monkeypatch):
    # the regulator sticks at 0.5 bar: the vent is not verified, and the bench marker, which
    # must say so to the next command, cannot be written (the state folder's disk is full):
    # nothing said it; the marker left names the run and its last command all the same
    from mkm.bench.unvented import BenchLease, bench_folder

    def full(self, what, unfollowed_bar=None):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(BenchLease, "unverified", full)
    c = config.replace(sim={"faults": {"regulator_stuck_at_s": 4.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "could not record the vent not verified (No space left on device): it names the " \
        "run and its last command, and the next command on this bench vents first" \
        in result.reason
    (marker,) = bench_folder("sim-Dev1").glob("*.json")  # still there, naming the run
    assert json.loads(marker.read_text())["run_path"] == str(result.path.resolve())


def test_the_over_pressure_limit_watches_the_pressure_a_monitor_reading_low_hides(config,
                                                                                 tmp_path):
    # the regulator's sensor, its monitor, reads 0.045 bar low (vented: -0.045 bar, within
    # vent_below_bar 0.05), so it delivers 2.545 bar at 2.5 commanded, and it overshoots its
    # command by 0.02: 2.565 bar held, read 2.52, under the 2 % margin (2.55) the limit
    # watched; the tare's vented reading puts it back
    c = config.replace(sequence={"pressures_bar": (2.5,)},
                       sim={"faults": {"overshoot_bar": 0.02},
                            "truth": {"monitor_offset_bar": -0.045}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 1, result.reason
    assert re.search(r"over-pressure interlock: 2\.5[5-9]\d bar measured \(2\.5[0-4]\d bar read, "
                     r"the monitor reading -0\.04\d\d bar vented at the tare\)", result.reason)
    assert run.meta.vent_check["verified"]
    # a monitor reading 0.045 bar high vented is not taken off (the limit is never loosened):
    # 2.515 bar held under an overshoot of 0.06, read 2.56, trips as read
    high = config.replace(sequence={"pressures_bar": (2.5,)},
                          sim={"faults": {"overshoot_bar": 0.06},
                               "truth": {"monitor_offset_bar": 0.045}})
    result = acquire(high, out_root=tmp_path / "high", **QUIET)
    assert result.status == "failed", result.reason
    assert re.search(r"over-pressure interlock: 2\.5[5-9]\d bar measured at ", result.reason)
