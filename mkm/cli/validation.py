"""``mkm report`` and ``mkm study``: argument parsing only, each calls one library function."""

from __future__ import annotations

import argparse

from fem.ranges import parse_fraction


def register(subparsers) -> None:
    report = subparsers.add_parser(
        "report", help="validation report of bench runs against the force models (HTML)")
    report.add_argument("runs", nargs="+", metavar="RUN_DIR", help="run folder(s) of mkm acquire")
    report.add_argument("--models", default="eq2,thickwall,axisym,surrogate",
                        help="comma list: registry names with optional :key=value parameters "
                        "(axisym:mesh=coarse), surrogate (the default one) or surrogate:PATH "
                        "(default: %(default)s)")
    report.add_argument("--out", help="output folder (default: reports/<first run name>)")
    report.add_argument("--tolerance", default=0.02, type=_fraction,
                        help="tolerance of the auto model choice shown per run, e.g. 2%% "
                        "(default: 2%%)")
    _cache_arguments(report)
    report.set_defaults(func=_report)

    study = subparsers.add_parser(
        "study", help="speed against accuracy of every predictor, and stability maps")
    study.add_argument("--out", default="reports/study", help="output folder "
                       "(default: %(default)s)")
    study.add_argument("--table", default=None,
                       help="error table for --model auto (default: fem/model_errors.csv)")
    _cache_arguments(study)
    study.set_defaults(func=_study)


def _cache_arguments(parser) -> None:
    parser.add_argument("--cache", default=".cache/mkm-report", metavar="DIR",
                        help="FE predictions (and the study's trained surrogates) kept here, "
                        "so a second run is fast (default: %(default)s)")
    parser.add_argument("--no-cache", action="store_true",
                        help="recompute everything; read and write no cache")


def _fraction(text):
    try:
        return parse_fraction(text, "--tolerance")
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _cache(args):
    return None if args.no_cache else args.cache


def _report(args) -> int:
    from mkm.registry import parse_specs
    from mkm.report import build_report

    path = build_report(args.runs, parse_specs(args.models), out_dir=args.out,
                        cache_dir=_cache(args), tolerance=args.tolerance)
    print(path)
    return 0


def _study(args) -> int:
    from mkm.auto import MODEL_ERRORS_FILE
    from mkm.study import run_study

    path = run_study(args.out, cache_dir=_cache(args), table_path=args.table or MODEL_ERRORS_FILE)
    print(path)
    return 0
