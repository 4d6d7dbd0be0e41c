"""Progress on stderr for commands that take more than a couple of seconds.

One style for every command: on a terminal a tqdm bar with the elapsed time and an estimate of
the time left; when stderr is a file or a pipe (a log, CI, a scheduler), one plain status line
every :data:`STATUS_INTERVAL_S` seconds instead, so a long run never fills a log with bar frames
and never stays silent. ``--no-progress`` turns both off. Each command ends with one summary
line on stderr (:func:`summary_line`) and prints the path of what it wrote last on stdout.
"""

from __future__ import annotations

import sys
import time

STATUS_INTERVAL_S = 10.0


class StatusLine:
    """Progress as a line every ``interval_s`` seconds: ``mkm report: 3/11 tasks, 18 s, about
    40 s left``. The part of tqdm's interface the commands use (``update``, ``close``,
    ``set_postfix_str``, a context manager)."""

    def __init__(self, total: int, desc: str, unit: str = "item",
                 interval_s: float = STATUS_INTERVAL_S, stream=None):
        self.total, self.desc, self.unit = total, desc, unit
        self.interval_s = interval_s
        self.stream = stream or sys.stderr
        self.n = 0
        self.postfix = ""
        self.start = self.last = self.last_update = time.monotonic()

    def unpause(self) -> None:
        """Leave the time since the last update out of the rate (tqdm's name): a one-off
        phase with its own estimate (a first-use training) does not inflate the time left."""
        now = time.monotonic()
        self.start += now - self.last_update
        self.last_update = now

    def update(self, n: int = 1) -> None:
        self.n += n
        now = self.last_update = time.monotonic()
        if now - self.last >= self.interval_s:
            self.last = now
            self.print_status(now)

    def print_status(self, now: float | None = None) -> None:
        elapsed = (now or time.monotonic()) - self.start
        left = ""
        if 0 < self.n < self.total:
            left = f", about {elapsed / self.n * (self.total - self.n):.0f} s left"
        extra = f" ({self.postfix})" if self.postfix else ""
        print(f"mkm {self.desc}: {self.n}/{self.total} {self.unit}s, {elapsed:.0f} s{left}"
              f"{extra}", file=self.stream, flush=True)

    def set_postfix_str(self, text: str, refresh: bool = True) -> None:
        self.postfix = text

    def close(self) -> None:
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _terminal() -> bool:
    return hasattr(sys.stderr, "isatty") and sys.stderr.isatty()


def progress_bar(total: int, desc: str, enabled: bool = True, unit: str = "item"):
    """A tqdm bar over ``total`` units on a terminal, a :class:`StatusLine` elsewhere (both
    usable, and silent, when not ``enabled``)."""
    from tqdm import tqdm

    if enabled and not _terminal():
        return StatusLine(total, desc, unit)
    return tqdm(total=total, desc=desc, unit=unit, disable=not enabled, file=sys.stderr,
                leave=False, dynamic_ncols=True)


def phase(command: str, text: str, enabled: bool = True) -> None:
    """Name a long step before it starts (``training the best surrogate on first use, about
    40 s (this machine, last time)``: :func:`mkm.core.durations.estimate`), so no command is
    silent for long whatever the terminal."""
    if enabled:
        print(f"mkm {command}: {text}", file=sys.stderr, flush=True)


def summary_line(command: str, text: str) -> None:
    """``mkm <command>: <text>`` on stderr: what was done, how long it took."""
    print(f"mkm {command}: {text}", file=sys.stderr)
