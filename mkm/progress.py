"""Progress on stderr for commands that take more than a couple of seconds.

One bar style for every command: tqdm on stderr with the elapsed time and an estimate of the
time left, shown only when stderr is a terminal and not turned off (``--no-progress``), so
logs and pipes stay clean. Each command ends with one summary line on stderr
(:func:`summary_line`) and prints the path of what it wrote last on stdout.
"""

from __future__ import annotations

import sys


def progress_bar(total: int, desc: str, enabled: bool = True, unit: str = "item"):
    """A tqdm bar over ``total`` units (disabled, but still usable, when not wanted)."""
    from tqdm import tqdm

    show = enabled and hasattr(sys.stderr, "isatty") and sys.stderr.isatty()
    return tqdm(total=total, desc=desc, unit=unit, disable=not show, file=sys.stderr,
                leave=False, dynamic_ncols=True)


def summary_line(command: str, text: str) -> None:
    """``mkm <command>: <text>`` on stderr: what was done, how long it took."""
    print(f"mkm {command}: {text}", file=sys.stderr)
