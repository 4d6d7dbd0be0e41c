"""``mkm design``: argument parsing only; :func:`mkm.design.run_design` does the work."""

from __future__ import annotations

import argparse

from mkm.cli.common import (
    add_batch_arguments,
    add_calibration_argument,
    add_progress_argument,
    argtype,
    choices,
    derived_help,
    shared_help,
    with_calibration,
)
from mkm.core.ranges import list_items, parse_fraction, parse_number
from mkm.flags import FLAG_OF, unit_of

EXAMPLE = ("example: mkm design --require 300N@2.5bar,eps=0.10 --require 250N@2.5bar,eps=0.20 "
           "--t0 2:3 --out mkm-out/design; robust: add --tolerance D0=0.3,t0=0.1,theta0=1")


def _probability(text: str, name: str) -> float:
    """0.95 or 95%: the form the range check's own message gives (0.95 for 95 %)."""
    return (parse_fraction(text, name) if text.strip().endswith("%")
            else parse_number(text, name))


def _spec(name: str):
    """The parser ``name`` of :mod:`mkm.design.spec`, imported when an argument is parsed: the
    design package loads pandas and matplotlib, which the other commands and ``--help`` do
    without."""

    def parse(text, *args):
        from mkm.design import spec

        return getattr(spec, name)(text, *args)

    parse.__name__ = name
    return parse


def _objective(text: str) -> str:
    from mkm.design.spec import OBJECTIVES

    if text not in OBJECTIVES:
        raise argparse.ArgumentTypeError(f"{text!r} is invalid: expected one of "
                                         f"{', '.join(OBJECTIVES)}")
    return text


def _objective_help() -> str:
    from mkm.design.spec import DEFAULT_OBJECTIVE, OBJECTIVES

    *others, last = OBJECTIVES
    return (f"ranking of the designs: {DEFAULT_OBJECTIVE} (default)"
            + "".join(f", {name}" for name in others[1:]) + f" or {last}")


def _rubber_help() -> str:
    from mkm.design.spec import CALIBRATED_RUBBER, DEFAULT_RUBBER
    from mkm.fem.materials import MATERIALS

    *others, last = (CALIBRATED_RUBBER, *MATERIALS)
    return (f"wall material(s), comma list: {', '.join(others)} or {last} (default: "
            f"{DEFAULT_RUBBER}; {CALIBRATED_RUBBER}: the rubber of the --calibration file, an "
            "identified one, else Silastic S)")


def _probability_help() -> str:
    from mkm.design.spec import DEFAULT_PROBABILITY

    return ("with --tolerance: the probability each design meets every requirement (default: "
            f"{DEFAULT_PROBABILITY:g})")


def _top_help() -> str:
    from mkm.design.spec import DEFAULT_TOP

    return f"designs verified with the FE model (default: {DEFAULT_TOP})"


def _tolerances(text: str):
    from mkm.fem.tolerances import Tolerances  # when given: a robust design's numbers

    return Tolerances.parse(text)


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "design", help="design a muscle for required forces: surrogate search of the design "
        "box, FE verification of the best designs", epilog=EXAMPLE,
        description="Find muscles (D0, t0; L0, theta0 and rubber where the surrogate takes "
        "them) that deliver required forces: a surrogate search of the design box with a "
        "margin covering its uncertainty, then the best designs verified with the FE model at "
        "the converged mesh (a design meets the requirements only when the FE says so). "
        "Writes designs.csv, designs.json (provenance) and design.html under --out; exit "
        "status 1 when no verified design meets every requirement.")
    p.add_argument("--require", action="append", default=[], metavar="F@P,eps=E",
                   type=argtype(_spec("parse_requirement"), "--require"),
                   help="force at least F [N] at pressure P [bar], held at shortening eps "
                   "(fraction or %%), e.g. 400N@2bar,eps=0.10; repeatable")
    p.add_argument("--spec", metavar="FILE", help="TOML spec: [[requirement]] tables "
                   "(force_N, pressure_bar, eps), [constraints], objective, top; the flags "
                   "add requirements and override the rest")
    # each constraint by its flag (mkm.flags, which design's hints name), kept under its key
    for key, default in (("D0_mm", "the surrogate's training box"),
                         ("t0_mm", "the surrogate's training box"),
                         ("L0_mm", "the length of the muscle --calibration was identified on, "
                          "else 282"),
                         ("theta0_deg", "the calibration")):
        flag = FLAG_OF[key]  # 3.5cm or 30deg converted (unit_of), as in a spec file
        p.add_argument(flag, dest=key, type=argtype(_spec("parse_bounds"), flag, unit_of(key)),
                       metavar="V|LO:HI", help=f"{shared_help(flag, f'default: {default}')}: "
                       "a value or a range low:high")
    p.add_argument(FLAG_OF["rubber"], action=derived_help(_rubber_help))
    for key, metavar, what in (
            ("max_outer_diameter_mm", "MM", "largest outer diameter at the working pressure "
             "[mm] (the housing; default: none, any width fits)"),
            ("gap_mm", "MM", "radial gap between tube and braid at rest of the muscles as built "
             "[mm] (default 0): the surrogate has none, so the FE model, which takes it, "
             "searches and verifies"),
            ("max_pressure_bar", "BAR", "largest working pressure [bar] (default: the "
             "requirements' largest)")):
        p.add_argument(FLAG_OF[key], dest=key, metavar=metavar, help=what,
                       type=argtype(parse_number, FLAG_OF[key], unit_of(key)))
    p.add_argument(FLAG_OF["tolerance"], metavar="D0=MM,t0=MM,theta0=DEG[,...]",
                   type=argtype(_tolerances),
                   help="robust designs: +- tolerances the muscle is built to (D0, t0, L0 [mm], "
                   "eps, theta0 [deg], rubber [%% of C10 and C01]), e.g. "
                   "D0=0.3,t0=0.1,theta0=1,rubber=10%%; every requirement is then met with "
                   "--probability and designs.csv gets probability_r<k> columns")
    p.add_argument("--probability", type=argtype(_probability, "--probability"),
                   action=derived_help(_probability_help))
    p.add_argument("--objective", type=_objective, metavar="OBJECTIVE",
                   action=derived_help(_objective_help))
    p.add_argument(FLAG_OF["top"], type=int, metavar="N", action=derived_help(_top_help))
    p.add_argument("--mesh", choices=choices("axisym", "mesh"), default="medium",
                   help="FE mesh of the verification (default: %(default)s, the converged one)")
    p.add_argument("--surrogate", default="surrogate", metavar="SPEC",
                   help="surrogate spec that searches the box (default: %(default)s)")
    p.add_argument("--out", help="output folder (default: mkm-out/design)")
    add_calibration_argument(p)
    p.add_argument("--cache", metavar="DIR", help="FE predictions kept here, so a second run "
                   "is fast (default: the user cache, predictions/)")
    p.add_argument("--no-cache", action="store_true", help="solve every FE sweep; no cache")
    add_progress_argument(p)
    add_batch_arguments(p)
    p.set_defaults(func=with_calibration(_design))


def _design(args) -> int:
    from mkm.core.records import check_output_folder
    from mkm.design import run_design, write_design
    from mkm.design.page import output_files
    from mkm.paths import check_writable, default_out
    from mkm.prediction_cache import DEFAULT_CACHE_DIR
    from mkm.progress import summary_line

    constraints = {k: getattr(args, k) for k in ("D0_mm", "t0_mm", "L0_mm", "theta0_deg",
                                                 "max_outer_diameter_mm", "max_pressure_bar",
                                                 "gap_mm")}
    if args.rubber:
        constraints["rubber"] = tuple(filter(None, list_items(args.rubber)))
    if not args.require and not args.spec:
        raise ValueError("no requirement given: expected --require F@P,eps=E (for example "
                         "--require 400N@2bar,eps=0.10) or --spec FILE")
    if args.probability is not None and args.tolerance is None:
        # a nominal design has no probability: the number would be dropped without a word
        raise ValueError(f"--probability {args.probability:g} needs --tolerance: expected the "
                         "tolerances the muscle is built to, e.g. --tolerance "
                         "D0=0.3,t0=0.1,theta0=1")
    robust = {} if args.probability is None else {"probability": args.probability}
    out = check_writable(args.out or default_out("design"), folder=True)
    # before the FE verification; the requirements' contour figures are checked as written
    check_output_folder(out, output_files(0), "designs.json")
    result = run_design(args.require, constraints, args.objective, args.top, spec=args.spec,
                        mesh=args.mesh, surrogate=args.surrogate,
                        progress=not args.no_progress,
                        cache_dir=None if args.no_cache else args.cache or DEFAULT_CACHE_DIR,
                        tolerances=args.tolerance, **robust,
                        workers=args.workers, scheduler=args.scheduler,
                        calibration=args.calibration)
    write_design(result, out)
    summary_line("design", result.summary())
    for note in result.notes():
        summary_line("design", note)
    print(result.table_text())
    print(result.files["html"])
    return 0 if result.chosen is not None else 1
