"""Progress: a bar on a terminal, a status line every 10 s elsewhere; one summary line."""

from __future__ import annotations

import io
import sys

from mkm.progress import StatusLine, progress_bar, summary_line


def test_no_bar_when_stderr_is_not_a_terminal_a_status_line_instead(monkeypatch):
    monkeypatch.setattr(sys, "stderr", io.StringIO())
    with progress_bar(3, "report") as bar:  # done within 10 s: nothing to say
        bar.update(3)
    assert sys.stderr.getvalue() == ""
    clock = iter([0.0, 4.0, 12.0, 13.0, 25.0])
    monkeypatch.setattr("mkm.progress.time.monotonic", lambda: next(clock))
    bar = progress_bar(4, "report", unit="task")
    assert isinstance(bar, StatusLine)
    bar.update(1)  # 4 s: quiet
    bar.update(1)  # 12 s: a line, with the time left at the rate so far
    bar.update(1)  # 13 s: quiet again
    bar.update(1)  # 25 s
    lines = sys.stderr.getvalue().splitlines()
    assert lines == ["mkm report: 2/4 tasks, 12 s, about 12 s left", "mkm report: 4/4 tasks, 25 s"]
    assert "\r" not in sys.stderr.getvalue()  # a log gets lines, not bar frames


def test_bar_with_an_estimate_on_a_terminal(monkeypatch):
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.setattr(sys, "stderr", Terminal())
    with progress_bar(4, "report", unit="task") as bar:
        bar.update(2)
        bar.refresh()  # tqdm redraws at most every 0.1 s by itself
    text = sys.stderr.getvalue()
    assert "report" in text and "2/4" in text and "<" in text  # elapsed<remaining
    monkeypatch.setattr(sys, "stderr", Terminal())
    with progress_bar(4, "report", enabled=False) as bar:  # --no-progress
        bar.update(4)
    assert sys.stderr.getvalue() == ""


def test_summary_line(capsys):
    summary_line("report", "2 run(s) in 3.0 s")
    assert capsys.readouterr().err == "mkm report: 2 run(s) in 3.0 s\n"


def test_a_phase_with_its_own_estimate_stays_out_of_the_time_left(monkeypatch):
    """A first-use training (99 s) before the first task does not make the 10 s tasks look
    like 100 s ones: the status line's estimate is the tasks' own rate."""
    monkeypatch.setattr(sys, "stderr", io.StringIO())
    clock = iter([0.0, 99.0, 109.0, 119.0, 119.0])
    monkeypatch.setattr("mkm.progress.time.monotonic", lambda: next(clock))
    bar = progress_bar(4, "report", unit="task")
    bar.unpause()  # 99 s: the training ends, announced with its own estimate
    bar.update(1)  # 109 s: one task of 10 s (a line: 10 s since the last one)
    bar.update(1)  # 119 s: a line
    assert sys.stderr.getvalue().splitlines() == ["mkm report: 1/4 tasks, 10 s, about 30 s left",
                                                  "mkm report: 2/4 tasks, 20 s, about 20 s left"]
