"""The ``mkm`` command (``python -m mkm`` and the console script): :func:`run`.

The entry point imports nothing heavy before it can handle a stop: a Ctrl-C while the command
line is still importing ends with one line and status 130, never a traceback; once the command
has returned (its run vented and recorded), a second Ctrl-C during the interpreter's shutdown
cannot turn the status into a kill, nor can a SIGTERM just after a run was recorded
(:data:`mkm.bench.signals.LINGER`).
"""

import signal
import sys


def run() -> None:
    try:
        from mkm.bench import signals
        from mkm.cli import main

        signals.LINGER = True  # this process ends with the command

        code = main()
    except KeyboardInterrupt:
        print("mkm: interrupted", file=sys.stderr)
        code = 130
    if hasattr(signal, "SIGINT"):
        signal.signal(signal.SIGINT, signal.SIG_IGN)
    sys.exit(code)


if __name__ == "__main__":
    run()
