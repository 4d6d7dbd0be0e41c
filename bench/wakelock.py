"""Keep the bench PC awake while a run goes.

Windows may sleep an idle PC (no keyboard or mouse) in the middle of a run; the USB-6001 then
stops with its analog output held, the muscle pressurised. :func:`awake` asks Windows to keep
the system running for the block (``SetThreadExecutionState(ES_CONTINUOUS |
ES_SYSTEM_REQUIRED)``, Microsoft's documented way for a program that must not be interrupted,
the display allowed to turn off) and lets it go at the end (``ES_CONTINUOUS`` alone). The request
belongs to the calling thread. Elsewhere it does nothing: Linux and macOS do not sleep a busy
process's machine on their own.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager

# winbase.h
ES_CONTINUOUS = 0x80000000
ES_SYSTEM_REQUIRED = 0x00000001
WINDOWS = sys.platform == "win32"


@contextmanager
def awake() -> Iterator[bool]:
    """Keep Windows from sleeping during the block; yields whether the request was granted
    (always False elsewhere)."""
    if not WINDOWS:
        yield False
        return
    import ctypes

    kernel32 = ctypes.windll.kernel32
    granted = bool(kernel32.SetThreadExecutionState(ES_CONTINUOUS | ES_SYSTEM_REQUIRED))
    try:
        yield granted
    finally:
        kernel32.SetThreadExecutionState(ES_CONTINUOUS)
