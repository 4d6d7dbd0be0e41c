"""SIGINT and SIGKILL of a real `mkm acquire` process on the real-clock simulated bench.

Each test runs for about 2-4 s of wall time: the process starts (imports ~1.5 s), acquires at
10 Hz until 15 samples are flushed, and is then signalled.
"""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from bench.storage import load_run

FAST = """
[sequence]
pressures_bar = [0.5, 1.0]
tare_s = 1.0
preconditioning_cycles = 0
"""


def start_run(tmp_path):
    text = (Path(__file__).parents[2] / "bench/configs/paper_prototype.toml").read_text()
    head, _, rest = text.partition("[sequence]")
    rest = rest[rest.index("[settle]"):]
    config = tmp_path / "bench.toml"
    config.write_text(head + FAST + rest)
    out = tmp_path / "runs"
    proc = subprocess.Popen(
        [sys.executable, "-m", "mkm", "acquire", "--config", str(config), "--clock",
         "real", "--out", str(out), "--no-progress"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        folders = list(out.glob("*")) if out.exists() else []
        if folders and (folders[0] / "samples.csv").exists():
            rows = (folders[0] / "samples.csv").read_text().count("\n") - 1
            if rows >= 15:
                return proc, folders[0], rows
        if proc.poll() is not None:
            pytest.fail(f"run ended early: {proc.communicate()}")
        time.sleep(0.05)
    proc.kill()
    pytest.fail("no samples within 30 s")


def assert_every_flushed_sample(run, flushed):
    assert len(run.samples) >= flushed
    np.testing.assert_array_equal(run.samples["sample"], np.arange(len(run.samples)))


def test_sigint_stops_vents_and_records(tmp_path):
    proc, folder, flushed = start_run(tmp_path)
    proc.send_signal(signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=20)
    assert proc.returncode == 130, stderr
    assert stdout.strip().splitlines()[-1] == str(folder)
    run = load_run(folder)
    assert run.status == "aborted" and "Ctrl-C" in run.reason
    assert_every_flushed_sample(run, flushed)
    last = run.commands.iloc[-1]
    assert last["purpose"] == "vent" and last["ok"] and last["command_bar"] == 0.0
    # one 0.1 s block at most, plus scheduling on a loaded 2-core machine
    assert run.meta["stop_to_vent_s"] < 0.5


def test_sigkill_keeps_every_flushed_sample(tmp_path):
    proc, folder, flushed = start_run(tmp_path)
    os.kill(proc.pid, signal.SIGKILL)
    proc.communicate(timeout=20)
    run = load_run(folder)
    # run.json cannot be rewritten by a killed process; the loader tells the truth instead.
    # (Nothing can vent at SIGKILL: the next run's startup vents before anything else.)
    assert run.meta["status"] == "running"
    assert run.status == "incomplete" and not run.complete
    assert_every_flushed_sample(run, flushed)
