"""``mkm demo``: argument parsing only; calls :func:`mkm.demo.run_demo`."""

from __future__ import annotations

import time

from mkm.cli.common import add_progress_argument, say


def register(subparsers) -> None:
    demo = subparsers.add_parser(
        "demo", help="simulated bench runs of the paper's two tests and their report",
        description="Record the paper's two tests of its prototype (D0 30 mm, t0 3 mm; eps 0 and "
        "12.2 %, 0.25 to 2.5 bar up and down) on the simulated bench (virtual clock) and write "
        "one validation report of both. The last line printed is the path of report.html. "
        "This is what `make demo` runs.",
        epilog="example: mkm demo --out mkm-out/demo   (then open mkm-out/demo/report/"
        "report.html)")
    demo.add_argument("--out", help="folder for runs/ and report/ (default: mkm-out/demo, or "
                      "$MKM_OUT/demo)")
    add_progress_argument(demo)
    demo.set_defaults(func=_demo)


def _demo(args) -> int:
    from mkm.bench.backend import BenchError, in_words  # here: the bench loads pandas
    from mkm.cli.bench import EXIT_FAILED
    from mkm.demo import run_demo
    from mkm.progress import summary_line

    start = time.perf_counter()
    try:
        path = run_demo(args.out, progress=not args.no_progress,
                        notify=lambda line: summary_line("demo", line))
    except BenchError as exc:  # the simulated bench held by another process, a run cut short
        say(args, "error", in_words(exc))
        return EXIT_FAILED
    summary_line("demo", f"2 simulated runs (eps 0 and 12.2 %) and their report in "
                 f"{time.perf_counter() - start:.0f} s")
    print(path)
    return 0
