"""``mkm identify``: argument parsing only; the library is :mod:`mkm.identify`."""

from __future__ import annotations

import sys

from mkm.cli.common import (
    add_batch_arguments,
    add_calibration_argument,
    add_progress_argument,
    argtype,
    command_name,
    say,
    with_calibration,
)
from mkm.core.ranges import list_items, parse_seed
from mkm.fem.options import BRAIDS
from mkm.identify.groups import SEARCHES
from mkm.paths import check_writable, default_out


def _params_help() -> str:
    from mkm.identify.groups import DEFAULT_GROUPS, GROUPS

    return (f"what to fit, a comma list of {', '.join(GROUPS)} (default "
            f"{','.join(DEFAULT_GROUPS)}: the runs' declared wall, diameter and rest length "
            "taken as given; t0 and D0 for a muscle whose wall is unknown; offset is the "
            "pressure monitor's, within its declared accuracy; gap needs --model thickwall or "
            "axisym; L0, the rest length, for runs of one length whose table may start already "
            "shortened: each run's eps follows from its held length; zero, the load cell's zero "
            "(a tare left out, a drift), one for every run; theta0 or rubber left out: the "
            "angle and rubber the runs declare, else the calibration's)")


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "identify", help="fit braid angle, rubber, friction and creep to runs of one muscle",
        description="Fit the muscle's braid angle theta0, rubber (one scale on Silastic S's "
        "C10 and C01 unless the runs separate them), braid friction and creep, and the pressure "
        "monitor's offset, to one or more bench runs of one tube (several eps and lengths; "
        "both sweep directions, the holds' time traces): search with the surrogate, confirm "
        "with the FE model, 95 % intervals by a bootstrap over steps with the instrument's "
        "declared tolerances inside, friction and creep kept only where the data warrant them "
        "(BIC). Prints first each run predicted from the others. --out DIR receives "
        "calibration.json (for --calibration in every command), parameters.csv, steps.csv and "
        "identification.json.",
        epilog="example: mkm identify RUN_EPS0 RUN_EPS12 --out mkm-out/identify; then "
        "mkm report RUN_EPS0 RUN_EPS12 --calibration mkm-out/identify/calibration.json")
    parser.add_argument("runs", nargs="+", metavar="RUN_DIR",
                        help="run folders of one muscle; a pattern (runs/*, expanded by mkm in "
                        "any shell) or a folder holding run folders")
    parser.add_argument("--params", default=None, help=_params_help())
    parser.add_argument("--model", default="axisym",
                        help="static model spec that confirms the fit (and searches where the "
                        "surrogate's box ends): axisym, axisym:mesh=coarse or thickwall; "
                        "default %(default)s")
    parser.add_argument("--search", choices=SEARCHES, default=SEARCHES[0],
                        help="search with the surrogate (default) or with --model itself")
    parser.add_argument("--braid", choices=BRAIDS, default=None,
                        help="the muscle's braid when known (a --model with a braid option): "
                             "no braid model-form term in the intervals (default: the model's "
                             "own braid, the intervals holding the other's estimate too)")
    parser.add_argument("--seed", type=argtype(parse_seed, "--seed"), default=0,
                        help="bootstrap seed (default 0)")
    parser.add_argument("--out", default=None,
                        help="output folder (default mkm-out/identify/<first run>)")
    add_batch_arguments(parser)
    add_calibration_argument(parser)
    add_progress_argument(parser)
    parser.set_defaults(func=with_calibration(_identify))


def _identify(args) -> int:
    from pathlib import Path

    from mkm.bench.folders import run_folders
    from mkm.core.records import check_output_folder
    from mkm.identify import identify
    from mkm.identify.result import OUTPUT_FILES

    args.runs = run_folders(args.runs)
    out = check_writable(Path(args.out) if args.out else
                         default_out("identify", Path(args.runs[0]).name), folder=True)
    check_output_folder(out, OUTPUT_FILES.values(), OUTPUT_FILES["identification"])
    try:
        result = identify(args.runs, params=args.params, model=args.model, search=args.search,
                          braid=args.braid,
                          seed=args.seed, workers=args.workers, scheduler=args.scheduler,
                          notify=(lambda line: None) if args.no_progress else
                          lambda line: print(f"{command_name(args)}: {line}", file=sys.stderr),
                          calibration=args.calibration)
    except RuntimeError as exc:  # a fit that failed: said, nothing written
        say(args, "error", f"identification failed: {exc}{_without_creep(args.params, exc)}")
        return 1
    files = result.write(out)
    print(result.summary())
    print(f"wrote {', '.join(str(p) for p in files.values())}")
    return 0


def _without_creep(params: str | None, exc: Exception) -> str:
    """What to try where a fit with creep asked for by name did not converge: a creep the runs
    barely show (one over before the holds start scales the force as a load cell's gain does)
    can leave the fit on a flat bound of its time constant (a 14 mm tube whose cell read 2.7 %
    low: ``bench_identify_wrong_range.py`` seed 20261622, which fits without creep); else ''
    (with the default groups, identify leaves such a creep out itself)."""
    groups = list_items(params) if params else []
    if "did not converge" not in str(exc) or "creep" not in groups:
        return ""
    without = ",".join(g for g in groups if g != "creep")
    return ("; a creep the runs barely show can keep the fit from settling (one over before "
            "the holds start scales the force as a load cell's gain does): identify again "
            f"without it (--params {without})")
