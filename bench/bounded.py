"""A call waited for a bounded time on a thread of its own: a driver or a disk that hangs is
let go (a daemon thread, ended with the process) and said by the caller, never waited for."""

from __future__ import annotations

import threading
from collections.abc import Callable


def call_within(call: Callable[[], object], wait_s: float, name: str
                ) -> tuple[bool, BaseException | None]:
    """Run ``call`` on a daemon thread named ``name`` and wait up to ``wait_s`` [s]: whether it
    returned in that time, and what it raised (None when it returned or is still running)."""
    done, failed = threading.Event(), []

    def run() -> None:
        try:
            call()
        except BaseException as exc:  # the caller says or raises it
            failed.append(exc)
        finally:
            done.set()

    threading.Thread(target=run, name=name, daemon=True).start()
    if not done.wait(wait_s):
        return False, None
    return True, (failed[0] if failed else None)
