"""``mkm surrogate ...`` subcommands: argument parsing only, each calls the surrogate library."""

from __future__ import annotations

import time
import warnings
from pathlib import Path

from mkm.cli.common import (
    IDENTIFIED_L0,
    add_batch_arguments,
    add_calibration_argument,
    add_geometry_arguments,
    add_progress_argument,
    argtype,
    choices,
    emit_prediction,
    identified_length,
    parse_within,
    say,
    say_defaults,
    shared_help,
    sweep_grid,
    with_calibration,
)
from mkm.core.ranges import list_items, parse_number, parse_numbers, parse_seed
from mkm.paths import default_cache, default_out
from mkm.progress import summary_line
from mkm.surrogate import kinds


def register(subparsers) -> None:
    sur = subparsers.add_parser(
        "surrogate", help="scikit-learn surrogates of the FE model: design, train, predict, "
        "evaluate, test, grid, reference",
        description="Learned force models trained on FE datasets: the space-filling FE design, "
        "training and saving, prediction, off-grid evaluation against fresh FE muscles, tests "
        "on the paper's muscles, the paper's 27-net grid, the FE reference.",
        epilog="example: mkm surrogate predict --D0 35 --t0 2.5 --eps 5%")
    sub = sur.add_subparsers(dest="surrogate_command", required=True, metavar="COMMAND")

    grid = sub.add_parser(
        "grid", help="the paper's 27-net study over repeated 80/20 splits",
        description="The paper's Table 2 study: 27 nets (layers x neurons x activation) trained "
        "over repeated 80/20 splits of the FE dataset; paper_grid.csv, .md and .png under --out. "
        "Long: minutes per net and seed on two cores (start with --nets and --seeds).",
        epilog="example: mkm surrogate grid --nets 1,14 --seeds 2 --out mkm-out/surrogate-grid")
    grid.add_argument("--dataset", help="FE dataset CSV (default: the shipped paper grid, "
                      "mkm/surrogate/data/mkm_dataset.csv)")
    grid.add_argument("--seeds", type=int, default=10, help="number of splits (default 10)")
    grid.add_argument("--out", default=str(default_out("surrogate-grid")),
                      help="folder (default %(default)s)")
    grid.add_argument("--jobs", type=int, default=2, help="parallel workers (default 2)")
    grid.add_argument("--variants", default="paper,standardised",
                      help="comma list of paper (response in N, as fitrnet) and standardised "
                      "(default: both)")
    grid.add_argument("--nets", help="comma list of Table 2 numbers 1-27 (default: all 27)")
    grid.set_defaults(func=_grid)

    train = sub.add_parser(
        "train", help="fit a surrogate on the FE dataset and save it",
        description="Fit a surrogate kind on an FE dataset (errors over repeated splits that "
        "hold out whole muscles) and save it as a model folder that --model / "
        "surrogate:path=DIR accept (JSON and skops arrays: loading it runs no code). The "
        "kinds: " + "; ".join(kinds.describe_each()) + ".",
        epilog="example: mkm surrogate train --kind gp --out mkm-out/models/gp")
    _dataset_argument(train)
    train.add_argument("--kind", default="best",
                       help=f"{kinds.describe()} (default: %(default)s)")
    train.add_argument("--splits", type=int, default=10,
                       help="muscle-held-out splits for the metrics (default 10; 0: none)")
    train.add_argument("--out", help="model folder (default mkm-out/models/<kind>)")
    train.set_defaults(func=_train)

    predict = sub.add_parser(
        "predict", help="forces of one muscle from a saved surrogate (CSV)",
        description="Forces of one muscle over a pressure sweep from the default surrogate or a "
        "saved one; points outside its training domain are flagged valid=false, with a warning.",
        epilog="example: mkm surrogate predict --D0 35 --t0 2.5 --eps 5% --pressures 0:2.5:0.5")
    predict.add_argument("--model", default="default",
                         help="folder written by `mkm surrogate train`, default (the cached "
                         "best surrogate), or surrogate:kind=KIND (trained on first use)")
    add_geometry_arguments(predict)
    _parameter_arguments(predict)
    predict.add_argument("--out", help="write the CSV here instead of stdout; a name ending "
                      "in .xlsx writes an Excel workbook (a German Excel opens a CSV "
                      "in one column)")
    predict.set_defaults(func=_predict, written_files={"out": ".csv"})

    test = sub.add_parser(
        "test", help="test muscles I-V against our FE: Table 3, Figure 6",
        description="Surrogates against our FE reference on the test muscles I-V: the paper's "
        "Table 3 and Figure 6 with our numbers, under --out.",
        epilog="example: mkm surrogate test --kind gp --out mkm-out/surrogate-test")
    test.add_argument("--model", action="append",
                      help="saved surrogate folder, or default (repeatable; default: default "
                      "unless --kind is given)")
    test.add_argument("--kind", action="append",
                      help="also train this kind on --dataset and test it (repeatable)")
    _dataset_argument(test)
    _accept_argument(test)
    test.add_argument("--reference", help="FE reference CSV (default: the shipped one, "
                      "mkm/surrogate/data/fe_test_muscles.csv, from `mkm surrogate reference "
                      "--update-shipped`)")
    test.add_argument("--out", default=str(default_out("surrogate-test")),
                      help="folder (default %(default)s)")
    test.set_defaults(func=_test)

    ref = sub.add_parser(
        "reference", help="build the FE reference of the test muscles",
        description="Solve the FE model on the test muscles I-V: the reference `surrogate test` "
        "and the report compare with. Writes --out; --update-shipped replaces the shipped one.",
        epilog="example: mkm surrogate reference --mesh coarse --out mkm-out/ref.csv")
    ref.add_argument("--model", default="axisym",
                     help="predictor spec of the reference (see `mkm models`; default "
                     "%(default)s, the FE model the surrogates are trained on)")
    ref.add_argument("--mesh", choices=choices("axisym", "mesh"),
                     help="mesh level of the FE model (default: its own)")
    ref.add_argument("--theta0", type=argtype(parse_number, "--theta0", "deg"),
                     help=shared_help("--theta0", "default: calibrated"))
    ref.add_argument("--out", default=str(default_out("surrogate-reference",
                                                      "fe_test_muscles.csv")),
                     help="CSV to write (default %(default)s)")
    ref.add_argument("--update-shipped", action="store_true",
                     help="write the shipped reference mkm/surrogate/data/fe_test_muscles.csv "
                     "instead (what the report and `surrogate test` read by default)")
    ref.set_defaults(func=_reference, written_files={"out": ".csv"})
    design = sub.add_parser(
        "design", help="build the space-filling FE design the default surrogate learns from",
        description="Place --muscles muscles over the box (pressure 0-2.5 bar, D0 30-50 mm, t0 "
        "2-4 mm, eps 0-0.2, L0 150-400 mm, theta0 28-38 deg, C10 and C01 within +-50 % of "
        "Silastic S): the 16 corners of a fractional factorial and a Latin hypercube; one FE "
        "sweep per muscle through the dataset cache (resumable) on local Dask workers. "
        "~2 s per muscle at the fine mesh.",
        epilog="example: mkm surrogate design --muscles 24 --mesh medium")
    design.add_argument("--muscles", required=True, type=int,
                        help="FE budget: number of muscles (one FE sweep each)")
    design.add_argument("--seed", type=argtype(parse_seed, "--seed"), default=0,
                        help="Latin hypercube seed (default 0)")
    design.add_argument("--adaptive", type=int, default=0,
                        help="then this many more muscles where the surrogate of the first is "
                        "least sure (default 0); with --range practical: only this many of the "
                        "--muscles drawn, where the shipped muscle-gp-range is least sure")
    design.add_argument("--refine", type=int, default=0,
                        help="then this many more space-filling muscles in --refine-box, where "
                        "the box's share is too few (default 0)")
    design.add_argument("--refine-box", type=argtype(_sub_box),
                        help="the sub-box of --refine: NAME=LO:HI,... over D0_mm, t0_mm, eps, "
                        "L0_mm, theta0_deg, C10_MPa, C01_MPa (the others span the box), "
                        "recorded in the sidecar")
    design.add_argument("--mesh", default="fine", choices=choices("axisym", "mesh"),
                        help="FE mesh level (default fine, the converged one)")
    add_batch_arguments(design)
    design.add_argument("--cache", default=str(default_cache("dataset")),
                        help="job cache folder (default %(default)s)")
    design.add_argument("--out", default=str(default_out("surrogate-design", "mkm_design.csv")),
                        help="CSV to write, with a .json sidecar (default %(default)s)")
    design.add_argument("--random-seeds",
                        help="comma list of seeds: --muscles random muscles per seed instead "
                        "of the space-filling design (the std calibration set)")
    design.add_argument("--update-shipped", action="store_true",
                        help="write the shipped file instead: mkm/surrogate/data/mkm_design.csv "
                        "(what the default surrogate trains on), or with --random-seeds "
                        "mkm/surrogate/data/mkm_std_calibration.csv (what scales its std), or "
                        "with --random-seeds --held-out mkm/surrogate/data/mkm_std_holdout.csv "
                        "(what rescales its std to 68/95/99.7 %% within 1/2/3 std)")
    design.add_argument("--held-out", action="store_true",
                        help="with --random-seeds --update-shipped: write the held-out set")
    design.add_argument("--range", choices=tuple(kinds.RANGES), default="box",
                        help="box: the space-filling design over the box (default); practical: "
                        "--muscles fresh random muscles of the practical range (seed --seed; "
                        "sweeps 0-8 bar) instead")
    design.set_defaults(func=_design, written_files={"out": ".csv"})

    evaluate = sub.add_parser(
        "evaluate", help="score a surrogate on fresh random muscles the FE computes now",
        description="Draw --muscles random muscles in the surrogate's box (seed recorded; fresh "
        "unless --seed), compute their FE sweeps, and score the surrogate: largest |Err%| per "
        "muscle, pooled RMSE, fraction of points within 1 and 2 std, and whether points just "
        "outside the box are flagged. Writes offgrid_points.csv and offgrid_summary.json.",
        epilog="example: mkm surrogate evaluate --muscles 4 --mesh medium")
    evaluate.add_argument("--model", default="default",
                          help="folder written by `mkm surrogate train`, default, or "
                          "surrogate:kind=KIND")
    evaluate.add_argument("--muscles", type=int, default=12,
                          help="FE budget: random muscles (default 12)")
    evaluate.add_argument("--seed", type=argtype(parse_seed, "--seed"),
                          help="seed of the draw (default: a fresh one)")
    evaluate.add_argument("--mesh", default="fine", choices=choices("axisym", "mesh"),
                          help="FE mesh level of the reference (default fine, the converged one)")
    add_batch_arguments(evaluate)
    evaluate.add_argument("--cache", default=str(default_cache("dataset")),
                          help="job cache folder (default %(default)s)")
    evaluate.add_argument("--out", default=str(default_out("surrogate-evaluate")),
                          help="folder (default %(default)s)")
    _accept_argument(evaluate)
    evaluate.set_defaults(func=_evaluate)

    for command in (predict, test, ref, evaluate):
        # the default braid angle of a surrogate, and the FE's, come from the calibration; a
        # training, its dataset and the paper's grid take the angle as data or the shipped one
        add_calibration_argument(command)
        command.set_defaults(func=with_calibration(command.get_default("func")))
    for command in (grid, train, predict, test, ref, design, evaluate):
        add_progress_argument(command)
    _accept_argument(predict)


def _sub_box(text: str) -> dict:
    from mkm.surrogate.design import parse_sub_box  # on use: the design's imports are heavy

    return parse_sub_box(text)


def _parameter_arguments(parser) -> None:
    parser.add_argument("--L0", type=argtype(parse_within, "--L0", "L0_mm"),
                        help=shared_help("--L0", IDENTIFIED_L0))
    parser.add_argument("--theta0", type=argtype(parse_within, "--theta0", "theta0_deg"),
                        help=shared_help("--theta0", "default: calibrated"))
    parser.add_argument("--C10", type=argtype(parse_within, "--C10", "C10_MPa"),
                        help=shared_help("--C10", "default Silastic S, 0.0694"))
    parser.add_argument("--C01", type=argtype(parse_within, "--C01", "C01_MPa"),
                        help=shared_help("--C01", "default Silastic S, 0.0628"))


def _accept_argument(parser) -> None:
    parser.add_argument("--accept-mismatch", action="store_true",
                        help="use a saved surrogate even if the code, calibration or training "
                        "data differ from those it was trained with")


def _dataset_argument(parser) -> None:
    parser.add_argument("--dataset", help="FE dataset CSV (default: the shipped design, "
                        "mkm/surrogate/data/mkm_design.csv)")


def _dataset(args):
    from mkm.surrogate.training_data import DEFAULT_DATASET

    return args.dataset or DEFAULT_DATASET


def _grid(args) -> int:
    from mkm.surrogate.paper_grid import paper_grid_study
    from mkm.surrogate.training_data import PAPER_DATASET

    start = time.perf_counter()
    variants = tuple(filter(None, list_items(args.variants)))
    nets = [int(n) for n in parse_numbers(args.nets, "--nets")] if args.nets else None
    table = paper_grid_study(args.out, args.dataset or PAPER_DATASET, args.seeds, args.jobs,
                             variants, nets, progress=not args.no_progress)
    summary_line("surrogate grid", f"{len(table)} configurations x {args.seeds} splits in "
                 f"{time.perf_counter() - start:.0f} s; wrote "
                 f"{Path(args.out) / 'paper_grid.csv'}, .md, .png")
    return 0


def _train(args) -> int:
    from mkm.surrogate.io import check_replaceable, save_model
    from mkm.surrogate.train import train_surrogate

    start = time.perf_counter()
    out = args.out or default_out("models", args.kind)
    check_replaceable(out)  # before the training, which takes minutes
    model = train_surrogate(args.kind, _dataset(args), splits=args.splits,
                            progress=not args.no_progress)
    out = save_model(model, out)
    held_out = model.metadata["metrics"]["muscle_held_out"]
    text = f"wrote {out} ({model.kind}) in {time.perf_counter() - start:.0f} s"
    if held_out:
        rmse, worst = held_out["rmse_test_N"], held_out["worst_err_pct"]
        text += (f": muscle-held-out RMSE median {rmse['median']:.2f} N "
                 f"[{rmse['min']:.2f}-{rmse['max']:.2f}], worst |Err%| median "
                 f"{worst['median']:.2f} % over {rmse['n']} splits")
        if "within_1std" in held_out:
            text += (f"; within 1/2 std {100 * held_out['within_1std']['median']:.0f}/"
                     f"{100 * held_out['within_2std']['median']:.0f} %")
    summary_line("surrogate train", text)
    return 0


def _load(path, calibration, accept_mismatch=False, progress=False, **parameters):
    from mkm.surrogate.io import load_model
    from mkm.surrogate.train import cached_model, default_model

    parameters = {k: v for k, v in parameters.items() if v is not None}
    if path == "default":
        model = default_model(progress=progress)
    elif str(path).startswith("surrogate:") and not Path(path).exists():
        # the spec a warning names where another kind answers (surrogate:kind=muscle-gp-range)
        model = cached_model(_spec_kind(path), progress=progress)
    else:
        model = load_model(path, accept_mismatch=accept_mismatch)
    return model.with_parameters(calibration, **parameters)


def _spec_kind(text: str) -> str:
    """The kind a ``surrogate:kind=K`` spec names; ``ValueError`` for any other spec."""
    from mkm.registry import parse_spec

    params = dict(parse_spec(text).params)
    if set(params) != {"kind"}:
        raise ValueError(f"--model {text!r}: expected a folder written by `mkm surrogate "
                         "train`, default, or surrogate:kind=KIND (`mkm models` lists the kinds)")
    return str(params["kind"])


def _label(path: str) -> str:
    return "default" if path == "default" else Path(path).name


def _predict(args) -> int:
    from mkm.surrogate.model import UNINFORMED

    args.pressures, args.eps = sweep_grid(args.pressures, args.eps)
    identified_length(args)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = _load(args.model, args.calibration, args.accept_mismatch, not args.no_progress,
                      L0_mm=args.L0, theta0_deg=args.theta0, C10_MPa=args.C10,
                      C01_MPa=args.C01)
        prediction = model.predict(args.pressures, args.D0, args.t0, args.eps)
    for w in caught:
        say(args, "warning", w.message)
    # an extrapolation is no answer: written as an empty force with its reason, the sweep's
    # answered points kept
    answered = model.answered(prediction)
    emit_prediction(answered, args.out, model)
    say_defaults(args, model, [k for k, v in (
        ("theta0_deg", args.theta0), ("C10_MPa", args.C10), ("C01_MPa", args.C01))
        if v is not None], "--C10, --C01", prediction)
    reasons = [str(r) for r, ok in zip(answered.extras["reason"].ravel(),
                                       prediction.valid.ravel(), strict=True) if not ok]
    locked = sum(r.startswith("past the braid lock") for r in reasons)
    unknown = sum(r.startswith(UNINFORMED) for r in reasons)
    counted = [f"{n} {why}" for n, why in (
        (locked, "past the braid lock"), (unknown, "without an answer (a std beyond any force)"),
        (len(reasons) - locked - unknown, "outside the training domain")) if n]
    summary_line("surrogate predict", f"{prediction.force_N.size} points of {model.name} in "
                 f"{1e3 * prediction.seconds:.2f} ms"
                 + (f", {' and '.join(counted)}: no force written (valid=False, their reason in "
                    "the reason column)" if counted else ""))
    return 0


def _test(args) -> int:
    from mkm.surrogate.testset import FE_REFERENCE, read_fe_reference, run_test
    from mkm.surrogate.train import train_surrogate

    reference = args.reference or FE_REFERENCE
    read_fe_reference(reference)  # a bad reference is named before minutes of training
    paths = args.model or ([] if args.kind else ["default"])
    models = {_label(path): _load(path, args.calibration, args.accept_mismatch,
                                  not args.no_progress) for path in paths}
    models.update({kind: train_surrogate(kind, _dataset(args), splits=0,
                                         progress=not args.no_progress)
                   for kind in args.kind or []})
    summary = run_test(models, args.out, reference)
    _figure6(Path(args.out), reference)
    print(summary.to_string(index=False, float_format=lambda v: f"{v:.3g}"))
    partial = summary.loc[~summary["all_valid"], ["muscle", "model"]]
    # a muscle a model answers only in part is scored on those points: said, not hidden
    scored = ("" if partial.empty else
              f" over the points each model answers ({len(partial)} muscle(s) with points "
              "outside a model's domain, not scored: valid_points in test_muscles.csv)")
    summary_line("surrogate test", f"{len(models)} model(s), worst |Err%| "
                 f"{summary['max_abs_err_pct'].max():.2f} %{scored}; wrote "
                 f"{Path(args.out) / 'test_muscles.csv'}, "
                 "test_muscles.md, test_muscles.png")
    return 0


def _figure6(out: Path, reference) -> None:
    """The paper's Figure 6 from run_test's points: the one Figure-6 plot of the project."""
    import pandas as pd

    from mkm.core.records import read_prediction_header, save_figure
    from mkm.figures import surrogate_fe_figure

    points = pd.read_csv(out / "test_muscles_points.csv")
    fe_model = read_prediction_header(reference).get("model", "FE")
    save_figure(surrogate_fe_figure(points, f"surrogates against our FE model ({fe_model}): "
                                    "the paper's Figure 6"), out / "test_muscles.png")


def _reference(args) -> int:
    from mkm.fem.ladder import make_model
    from mkm.surrogate.testset import FE_REFERENCE, build_fe_reference

    model = make_model(args.model, args.calibration, mesh=args.mesh, theta0_deg=args.theta0)
    out = FE_REFERENCE if args.update_shipped else args.out
    build_fe_reference(model, out)
    summary_line("surrogate reference", f"wrote {out}")
    return 0


def _design(args) -> int:
    from mkm.surrogate.design import (
        DESIGN_DATASET,
        build_design,
        build_practical_set,
        build_random_set,
    )
    from mkm.surrogate.training_data import STD_CALIBRATION_SET, STD_HOLDOUT_SET

    start = time.perf_counter()
    if args.held_out and not (args.random_seeds and args.update_shipped):
        raise ValueError("--held-out is invalid here: expected it with --random-seeds and "
                         "--update-shipped (it names the shipped file to write)")
    if args.range == "practical":
        if args.random_seeds or args.update_shipped or args.refine:
            raise ValueError("--range practical is invalid with --random-seeds, "
                             "--update-shipped or --refine: expected --muscles, --seed, "
                             "--adaptive and --out")
        frame, info = build_practical_set(args.muscles, args.seed, Path(args.out),
                                          mesh=args.mesh, workers=args.workers,
                                          cache_dir=args.cache, progress=not args.no_progress,
                                          scheduler=args.scheduler, adaptive=args.adaptive)
        picked = (f"{args.adaptive} picked among {args.muscles}" if args.adaptive
                  else str(args.muscles))
        summary_line("surrogate design", f"{picked} random muscles of the practical range "
                     f"(seed {args.seed}, {len(info['muscles_with_failed_points'])} with failed "
                     f"points) in {time.perf_counter() - start:.0f} s; wrote {args.out}")
        return 0
    if args.random_seeds:
        seeds = [int(v) for v in parse_numbers(args.random_seeds, "--random-seeds")]
        shipped = STD_HOLDOUT_SET if args.held_out else STD_CALIBRATION_SET
        out = shipped if args.update_shipped else Path(args.out)
        frame, info = build_random_set(args.muscles, seeds, out, mesh=args.mesh,
                                       workers=args.workers, cache_dir=args.cache,
                                       progress=not args.no_progress, scheduler=args.scheduler)
        summary_line("surrogate design", f"{args.muscles} random muscles x {len(seeds)} seeds in "
                     f"{time.perf_counter() - start:.0f} s; wrote {out} and "
                     f"{out.with_suffix('.json').name}")
        return 0
    out = DESIGN_DATASET if args.update_shipped else Path(args.out)
    frame, info = build_design(args.muscles, out, seed=args.seed, mesh=args.mesh,
                               workers=args.workers, cache_dir=args.cache,
                               progress=not args.no_progress, adaptive=args.adaptive,
                               scheduler=args.scheduler, refine=args.refine,
                               refine_box=args.refine_box)
    refined = f" + {args.refine} refinement" if args.refine else ""
    summary_line("surrogate design", f"{args.muscles}{refined} + {args.adaptive} adaptive muscles "
                 f"({info['jobs_computed']} FE sweeps "
                 f"computed, {info['jobs_from_cache']} from cache, "
                 f"{len(info['muscles_with_failed_points'])} with failed points) in "
                 f"{time.perf_counter() - start:.0f} s; wrote {out} and "
                 f"{out.with_suffix('.json').name}")
    return 0


def _evaluate(args) -> int:
    from mkm.surrogate.offgrid import evaluate_offgrid, write_offgrid

    start = time.perf_counter()
    model = _load(args.model, args.calibration, args.accept_mismatch, not args.no_progress)
    points, summary = evaluate_offgrid(model, args.muscles, args.seed, args.mesh, args.workers,
                                       args.cache, progress=not args.no_progress,
                                       scheduler=args.scheduler)
    out = Path(args.out)
    write_offgrid(points, summary, out)
    cover = (f", within 1/2 std {100 * summary['within_1std']:.0f}/"
             f"{100 * summary['within_2std']:.0f} %" if "within_1std" in summary else "")
    box = summary["outside_box"]
    summary_line("surrogate evaluate", f"{model.name} on {args.muscles} random muscles (seed "
                 f"{summary['seed']}, FE {args.mesh}): worst |Err%| "
                 f"{summary['worst_max_abs_err_pct']:.3f} %, pooled RMSE "
                 f"{summary['pooled_rmse_N']:.3f} N{cover}; {box['flagged']} of {box['points']} "
                 f"points outside the box flagged; {time.perf_counter() - start:.0f} s; wrote "
                 f"{out / 'offgrid_points.csv'}, offgrid_summary.json")
    return 0
