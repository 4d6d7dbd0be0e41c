"""bench.recorder: a disk that fills during a run loses no more than it must and hides nothing."""

import errno
from pathlib import Path

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
    assert captured.err.count("\n") == 2 and "mkm: SIMULATED bench (sim)" in captured.err
    assert "run SIMULATED failed: recording failed (OSError: [Errno 28] No space left on " \
        "device)" in captured.err
    run = load_run(Path(captured.out.strip().splitlines()[-1]))  # the path is still printed
    assert run.status == "failed" and len(run.samples) == 30  # every sample written is kept
    assert run.commands["purpose"].iloc[-1] == "vent" and run.commands["ok"].iloc[-1]
    assert calls["closed"] == 1  # synced and closed
