"""How long this machine took for a long task last time: the one source of every time promise.

A command that is about to wait (training a surrogate on first use, say) says how long it
expects from what this machine did the last time it did the same task (:func:`estimate`), then
records how long it took (:func:`record`), so the next promise is this machine's, not a guess
typed into a message. The record is one JSON file in the user cache
(:func:`mkm.core.home.user_cache`); a missing or unreadable record gives no estimate, never an
error.
"""

from __future__ import annotations

import json
import time
from contextlib import contextmanager
from pathlib import Path

from mkm.core.home import user_cache
from mkm.core.records import write_json_atomic

FILE = "durations.json"


def _path() -> Path:
    return user_cache(FILE)


def _read() -> dict:
    try:
        data = json.loads(_path().read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def expected_seconds(task: str) -> float | None:
    """Seconds ``task`` took on this machine last time, or None (never done, or no record)."""
    entry = _read().get(task)
    seconds = entry.get("seconds") if isinstance(entry, dict) else None
    return float(seconds) if isinstance(seconds, int | float) and seconds >= 0 else None


def record(task: str, seconds: float) -> None:
    """Keep ``seconds`` as this machine's time for ``task`` (a cache that cannot be written is
    left as it is: the estimate is a courtesy, not a result)."""
    data = _read()
    data[task] = {"seconds": round(float(seconds), 1),
                  "recorded_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}
    try:
        _path().parent.mkdir(parents=True, exist_ok=True)
        write_json_atomic(_path(), data)
    except OSError:
        pass


def estimate(task: str) -> str:
    """The promise for ``task`` in words: ``about 40 s (this machine, last time)``, or that
    there is none to make yet."""
    seconds = expected_seconds(task)
    if seconds is None:
        return "the first time on this machine: no earlier time to estimate from"
    if seconds >= 90:
        return f"about {seconds / 60:.0f} min (this machine, last time)"
    return f"about {max(seconds, 1):.0f} s (this machine, last time)"


@contextmanager
def timed(task: str):
    """``with timed(task):`` records how long the block took when it ends without an
    exception (an interrupted task says nothing about the next one)."""
    start = time.monotonic()
    yield
    record(task, time.monotonic() - start)
