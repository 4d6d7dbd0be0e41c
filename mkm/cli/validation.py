"""``mkm report`` and ``mkm study``: argument parsing only, each calls one library function."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from mkm.cli.common import (
    add_batch_arguments,
    add_calibration_argument,
    add_progress_argument,
    argtype,
    derived_help,
    with_calibration,
)
from mkm.core.ranges import parse_seed, parse_tolerance
from mkm.surrogate import kinds


def register(subparsers) -> None:
    report = subparsers.add_parser(
        "report", help="validation report of bench runs against the force models (HTML)",
        description="Compare bench runs (real or simulated, aborted ones included) with every "
        "force model: a summary table, the runs of one muscle overlaid, pressure and force "
        "against time, Err% (Equation 7) and residuals in N, the speed-accuracy chart and the "
        "model `auto` would choose. Writes report.html (self-contained) with CSVs, PNGs and "
        "provenance.json beside it; prints the path of report.html last.",
        epilog="example: mkm report \"mkm-out/demo/runs/*\" --models eq2,thickwall,surrogate "
        "--out mkm-out/my-report")
    report.add_argument("runs", nargs="+", metavar="RUN_DIR",
                        help="run folder(s) of mkm acquire or mkm import; a pattern (runs/*, "
                        "expanded by mkm in any shell) or a folder holding run folders")
    report.add_argument("--models", action=derived_help(_models_help))
    report.add_argument("--out", help="output folder (default: mkm-out/report/<first run name>)")
    report.add_argument("--tolerance", default=0.02, type=_fraction,
                        help="largest |Err%%| a model may have: the verdict names the cheapest "
                        "model within it against the measurement, auto the cheapest within it "
                        "against the FE model; e.g. 2%% (default: 2%%)")
    _cache_arguments(report)
    add_progress_argument(report)
    add_calibration_argument(report)
    report.set_defaults(func=with_calibration(_report))

    study = subparsers.add_parser(
        "study", help="speed against accuracy of every predictor, and stability maps",
        description="Time every predictor and measure its error (Equation 7) against the finest "
        "FE mesh on the study muscles; map where each method fails. Writes study.html, CSVs "
        "and model_errors.csv (the table `auto` reads) under --out only; --update-shipped also "
        "replaces the table shipped in the package (mkm/data/model_errors.csv). Cold: about a "
        "minute (FE solves and surrogate training; --surrogates all adds about 13); a second "
        "run reads them from the cache.",
        epilog="example: mkm study --out mkm-out/study   (then mkm fem solve --model "
        "auto:table=mkm-out/study/model_errors.csv ...)")
    study.add_argument("--out", help="output folder (default: mkm-out/study)")
    study.add_argument("--update-shipped", action="store_true",
                       help="also replace the shipped study table mkm/data/model_errors.csv "
                       "that `--model auto` reads by default")
    study.add_argument("--surrogates", type=_kinds, metavar="KINDS",
                       help="surrogate kinds scored: a comma list or `all` (the generic gp and "
                       "the paper's 54 nets too; cold, about 13 more minutes of training) "
                       f"(default: {','.join(kinds.study_default())})")
    study.add_argument("--mesh-muscles", type=int, default=0, metavar="N",
                       help="also measure the FE meshes' errors against the fine mesh on N "
                       "fresh random muscles of the practical range (mesh_errors.csv: the "
                       "bound `auto` gives a mesh at the scale of each call; --update-shipped "
                       "replaces mkm/data/mesh_errors.csv); ~3 FE sweeps per muscle (default 0: "
                       "none)")
    study.add_argument("--mesh-seed", type=argtype(parse_seed, "--mesh-seed"),
                       help="seed of --mesh-muscles' draw (default: fresh, recorded)")
    study.add_argument("--mesh-only", action="store_true",
                       help="only the --mesh-muscles measurement, not the study")
    _cache_arguments(study)
    add_progress_argument(study)
    # mkm.study.TRAINING_JOBS, which loads what --help does without
    add_batch_arguments(study, also="the surrogates' training", also_default="2 for the training")
    study.set_defaults(func=_study)


def _models_help() -> str:
    from mkm.registry import REPORT_MODELS

    return ("comma list of predictor specs (see `mkm models`): eq2, thickwall, "
            "axisym:mesh=coarse, surrogate, surrogate:kind=gp, surrogate:path=DIR (default: "
            f"{','.join(REPORT_MODELS)}, less those --calibration has no entry for, said in a "
            "note)")


def _cache_arguments(parser) -> None:
    parser.add_argument("--cache", metavar="DIR",
                        help="FE predictions kept here, so a second run is fast (default: "
                        "the user's cache folder; trained surrogates always live in the "
                        "surrogate cache there)")
    parser.add_argument("--no-cache", action="store_true",
                        help="recompute every FE prediction and retrain the study's surrogates; "
                        "read and write no cache")


def _kinds(text):
    from mkm.study import surrogate_kinds

    try:
        return surrogate_kinds(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _fraction(text):
    try:
        return parse_tolerance(text, "--tolerance")
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _cache(args):
    from mkm.prediction_cache import DEFAULT_CACHE_DIR

    return None if args.no_cache else (args.cache or DEFAULT_CACHE_DIR)


def _report(args) -> int:
    from mkm.bench.folders import run_folders
    from mkm.progress import summary_line
    from mkm.registry import parse_specs
    from mkm.report import build_report, default_models

    start = time.perf_counter()
    args.runs = run_folders(args.runs)
    specs = (default_models(args.calibration) if args.models is None
             else parse_specs(args.models))
    earlier = _earlier_report(args.out, args.runs)
    path = build_report(args.runs, specs, out_dir=args.out, cache_dir=_cache(args),
                        tolerance=args.tolerance, progress=not args.no_progress,
                        calibration=args.calibration,
                        notify=lambda line: summary_line("report", line))
    summary_line("report", f"{len(args.runs)} run(s) x {len(specs)} model(s) in "
                 f"{time.perf_counter() - start:.1f} s; summary.csv beside the report"
                 + (f"; replaced the report of {earlier} there (--out names another folder "
                    "to keep both)" if earlier else ""))
    print(path)
    return 0


def _earlier_report(out, runs) -> str | None:
    """When (UTC, to the minute) the report that ``mkm report`` is about to replace was written,
    or None: the default folder is named after the first run, so a second report of the same
    runs (another calibration, other models) lands where the first is."""
    import datetime

    from mkm.report import report_folder

    page = report_folder(out, runs) / "report.html" if runs else None
    if page is None or not page.is_file():
        return None
    when = datetime.datetime.fromtimestamp(page.stat().st_mtime, datetime.UTC)
    return f"{when:%Y-%m-%d %H:%M} UTC"


def _study(args) -> int:
    from mkm.progress import summary_line
    from mkm.study import StudyConfig, run_study

    start = time.perf_counter()
    if args.mesh_only and not args.mesh_muscles:
        raise ValueError("--mesh-only needs --mesh-muscles N: expected a number of muscles")
    if args.mesh_muscles < 0:
        raise ValueError(f"--mesh-muscles {args.mesh_muscles} is invalid: expected >= 0")
    if args.mesh_muscles:
        _mesh_errors(args)
    if args.mesh_only:
        return 0
    config = StudyConfig.with_surrogates(args.surrogates) if args.surrogates else StudyConfig()
    path = run_study(args.out, config, cache_dir=_cache(args),
                     update_shipped=args.update_shipped, progress=not args.no_progress,
                     workers=args.workers, scheduler=args.scheduler,
                     notify=lambda line: summary_line("study", line))
    shipped = "; replaced mkm/data/model_errors.csv" if args.update_shipped else ""
    summary_line("study", f"done in {time.perf_counter() - start:.0f} s{shipped}")
    print(path)
    return 0


def _mesh_errors(args) -> None:
    import numpy as np

    from mkm import mesh_errors
    from mkm.paths import default_out
    from mkm.progress import summary_line

    start = time.perf_counter()
    seed = (args.mesh_seed if args.mesh_seed is not None
            else int(np.random.SeedSequence().entropy % 2**32))
    out = (mesh_errors.MESH_ERRORS_FILE if args.update_shipped
           else Path(args.out or default_out("study")) / "mesh_errors.csv")
    _, info = mesh_errors.measure(args.mesh_muscles, seed, out, workers=args.workers,
                                  scheduler=args.scheduler, cache_dir=_cache(args),
                                  progress=not args.no_progress)
    summary_line("study", f"mesh errors of {args.mesh_muscles} "
                 f"muscle{'' if args.mesh_muscles == 1 else 's'} (seed {seed}, "
                 f"{info['fe_failed_muscles']} with a failed FE sweep) in "
                 f"{time.perf_counter() - start:.0f} s: {mesh_errors.summary_line(out)}; "
                 f"wrote {out}")
