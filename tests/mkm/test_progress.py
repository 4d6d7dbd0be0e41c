"""Progress bars only on a terminal; one summary line."""

from __future__ import annotations

import io
import sys

from mkm.progress import progress_bar, summary_line


def test_no_bar_when_stderr_is_not_a_terminal(monkeypatch):
    monkeypatch.setattr(sys, "stderr", io.StringIO())
    with progress_bar(3, "report") as bar:
        bar.update(3)
    assert sys.stderr.getvalue() == ""


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
