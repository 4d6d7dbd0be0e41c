"""``mkm surrogate ...`` subcommands: argument parsing only, each calls the surrogate library."""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

from fem.ranges import parse_number
from mkm.cli.common import (
    add_calibration_argument,
    add_geometry_arguments,
    argtype,
    emit_prediction,
    with_calibration,
)
from mkm.paths import default_out


def register(subparsers) -> None:
    sur = subparsers.add_parser(
        "surrogate", help="scikit-learn surrogates of the FE model: grid, train, predict, test, "
        "reference",
        description="Learned force models trained on the FE dataset: the paper's 27-net grid, "
        "training and saving, prediction, tests on unseen muscles, the FE reference.",
        epilog="example: mkm surrogate predict --D0 35 --t0 2.5 --eps 5%")
    sub = sur.add_subparsers(dest="surrogate_command", required=True, metavar="COMMAND")

    grid = sub.add_parser(
        "grid", help="the paper's 27-net study over repeated 80/20 splits",
        description="The paper's Table 2 study: 27 nets (layers x neurons x activation) trained "
        "over repeated 80/20 splits of the FE dataset; paper_grid.csv, .md and .png under --out. "
        "Long: minutes per net and seed on two cores (start with --nets and --seeds).",
        epilog="example: mkm surrogate grid --nets 1,14 --seeds 2 --out mkm-out/surrogate-grid")
    _dataset_argument(grid)
    grid.add_argument("--seeds", type=int, default=10, help="number of splits (default 10)")
    grid.add_argument("--out", default=str(default_out("surrogate-grid")),
                      help="folder (default %(default)s)")
    grid.add_argument("--jobs", type=int, default=2, help="parallel workers (default 2)")
    grid.add_argument("--variants", default="paper,standardised",
                      help="comma list of paper (response in N, as fitrnet) and standardised")
    grid.add_argument("--nets", help="comma list of Table 2 numbers 1-27 (default: all 27)")
    grid.set_defaults(func=_grid)

    train = sub.add_parser(
        "train", help="fit a surrogate on the FE dataset and save it",
        description="Fit a surrogate kind on the FE dataset (held-out metrics over repeated "
        "splits) and save it as a model folder that --model / surrogate:path=DIR accept.",
        epilog="example: mkm surrogate train --kind gp --out mkm-out/models/gp")
    _dataset_argument(train)
    train.add_argument("--kind", default="best",
                       help="best, mlp-paper, mlp-standardised, gp, physics or "
                       "net-<layers>x<size>-<relu|tanh|sigmoid>[-standardised]")
    train.add_argument("--out", help="model folder (default mkm-out/models/<kind>)")
    train.set_defaults(func=_train)

    predict = sub.add_parser(
        "predict", help="forces of one muscle from a saved surrogate (CSV)",
        description="Forces of one muscle over a pressure sweep from the default surrogate or a "
        "saved one; points outside its training domain are flagged valid=false, with a warning.",
        epilog="example: mkm surrogate predict --D0 35 --t0 2.5 --eps 5% --pressures 0:2.5:0.5")
    predict.add_argument("--model", default="default",
                         help="folder written by `mkm surrogate train`, or default (the cached "
                         "best surrogate)")
    add_geometry_arguments(predict)
    predict.add_argument("--out", help="write the CSV here instead of stdout")
    predict.set_defaults(func=_predict)

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
    test.add_argument("--reference", help="FE reference CSV (default "
                      "data/reference/fe_test_muscles.csv)")
    test.add_argument("--out", default=str(default_out("surrogate-test")),
                      help="folder (default %(default)s)")
    test.set_defaults(func=_test)

    ref = sub.add_parser(
        "reference", help="build the FE reference of the test muscles",
        description="Solve the FE model on the test muscles I-V: the reference `surrogate test` "
        "and the report compare with. Writes --out; --update-shipped replaces the shipped one.",
        epilog="example: mkm surrogate reference --mesh coarse --out mkm-out/ref.csv")
    ref.add_argument("--model", default="axisym", help="FE model (default %(default)s)")
    ref.add_argument("--mesh", help="mesh level of the FE model (default: its own)")
    ref.add_argument("--theta0", type=argtype(parse_number, "--theta0"),
                     help="braid angle at rest [deg] (default: calibrated)")
    ref.add_argument("--out", default=str(default_out("surrogate-reference",
                                                      "fe_test_muscles.csv")),
                     help="CSV to write (default %(default)s)")
    ref.add_argument("--update-shipped", action="store_true",
                     help="write the shipped reference surrogate/data/fe_test_muscles.csv "
                     "instead (what the report and `surrogate test` read by default)")
    ref.set_defaults(func=_reference)
    for command in (grid, train, predict, test, ref):  # the physics features read theta0
        add_calibration_argument(command)
        command.set_defaults(func=with_calibration(command.get_default("func")))


def _dataset_argument(parser) -> None:
    parser.add_argument("--dataset", help="FE dataset CSV (default data/mkm_dataset.csv)")


def _dataset(args):
    from surrogate.training_data import DEFAULT_DATASET

    return args.dataset or DEFAULT_DATASET


def _grid(args) -> int:
    from surrogate.paper_grid import paper_grid_study

    variants = tuple(v.strip() for v in args.variants.split(",") if v.strip())
    nets = [int(parse_number(n, "--nets")) for n in args.nets.split(",")] if args.nets else None
    paper_grid_study(args.out, _dataset(args), args.seeds, args.jobs, variants, nets)
    print(f"wrote {args.out}/paper_grid.csv, paper_grid.md, paper_grid.png", file=sys.stderr)
    return 0


def _train(args) -> int:
    from surrogate.io import save_model
    from surrogate.train import train_surrogate

    model = train_surrogate(args.kind, _dataset(args))
    out = save_model(model, args.out or default_out("models", args.kind))
    rmse = model.metadata["metrics"]["rmse_test_N"]
    print(f"wrote {out} ({model.kind}): held-out RMSE median {rmse['median']:.2f} N "
          f"[{rmse['min']:.2f}-{rmse['max']:.2f}] over {rmse['n']} splits", file=sys.stderr)
    return 0


def _load(path):
    from surrogate.io import load_model
    from surrogate.train import default_model

    return default_model() if path == "default" else load_model(path)


def _label(path: str) -> str:
    return "default" if path == "default" else Path(path).name


def _predict(args) -> int:

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = _load(args.model)
        prediction = model.predict(args.pressures, args.D0, args.t0, args.eps)
    for w in caught:
        print(f"mkm: warning: {w.message}", file=sys.stderr)
    emit_prediction(prediction, args.out)
    return 0


def _test(args) -> int:
    from surrogate.testset import FE_REFERENCE, run_test
    from surrogate.train import train_surrogate

    paths = args.model or ([] if args.kind else ["default"])
    models = {_label(path): _load(path) for path in paths}
    models.update({kind: train_surrogate(kind, _dataset(args), seeds=())
                   for kind in args.kind or []})
    summary = run_test(models, args.out, args.reference or FE_REFERENCE)
    print(summary.to_string(index=False, float_format=lambda v: f"{v:.3g}"))
    print(f"wrote {args.out}/test_muscles.csv, test_muscles.md, test_muscles.png",
          file=sys.stderr)
    return 0


def _reference(args) -> int:
    from fem.ladder import make_model
    from surrogate.testset import FE_REFERENCE, build_fe_reference

    model = make_model(args.model, mesh=args.mesh, theta0_deg=args.theta0)
    out = FE_REFERENCE if args.update_shipped else args.out
    build_fe_reference(model, out)
    print(f"wrote {out}", file=sys.stderr)
    return 0
