"""``mkm fem ...`` subcommands: argument parsing only, each calls one library function."""

from __future__ import annotations

import sys

from fem.ladder import model_names
from fem.ranges import parse_fraction, parse_number
from mkm.cli.common import (
    add_geometry_arguments,
    add_model_arguments,
    argtype,
    emit_prediction,
    model_from_args,
)


def register(subparsers) -> None:
    fem = subparsers.add_parser(
        "fem", help="physics force models: solve, calibrate, convergence, dataset")
    fem_sub = fem.add_subparsers(dest="fem_command", required=True, metavar="COMMAND")

    solve = fem_sub.add_parser("solve", help="force of one muscle over a pressure sweep (CSV)")
    add_model_arguments(solve)
    add_geometry_arguments(solve)
    solve.add_argument("--out", help="write the CSV here instead of stdout")
    solve.add_argument("--tolerance", type=argtype(parse_fraction, "--tolerance"),
                       help="auto only: largest acceptable error against the finest FE, "
                       "e.g. 2%% (default 2%%)")
    solve.set_defaults(func=_solve)

    cal = fem_sub.add_parser("calibrate", help="fit theta0 of a model to a reference sweep")
    add_model_arguments(cal, theta0=False)
    cal.add_argument("--reference", default="data/reference/paper_case_I.csv",
                     help="CSV with pressure_bar,D0_mm,t0_mm,eps,force_N (default: %(default)s)")
    cal.add_argument("--dry-run", action="store_true", help="print the fit, do not store it")
    cal.set_defaults(func=_calibrate)

    data = fem_sub.add_parser("dataset", help="forces of a model over a grid of muscles (CSV), "
                              "resumable, on local workers or a Dask cluster")
    data.add_argument("--grid", default="paper",
                      help="'paper' (Table 1 of the paper, 162 points) or a grid TOML file")
    data.add_argument("--model", default="axisym", help=f"one of {', '.join(model_names())} "
                      "(default: %(default)s)")
    data.add_argument("--mesh", help="mesh level of FE models (default: the model's)")
    data.add_argument("--out", default="data/mkm_dataset.csv",
                      help="CSV to write; provenance goes next to it as .json "
                      "(default: %(default)s)")
    data.add_argument("--workers", type=int,
                      help="local worker processes; 1 runs in-process (default: CPU count)")
    data.add_argument("--scheduler", metavar="ADDRESS",
                      help="run on the Dask cluster at this scheduler, e.g. tcp://HOST:8786")
    data.add_argument("--cache", default=".cache/mkm-dataset",
                      help="one file per finished job; re-runs compute only what is missing "
                      "(default: %(default)s)")
    data.set_defaults(func=_dataset)

    conv = fem_sub.add_parser("convergence", help="axisym mesh study: force, dofs and seconds "
                              "per mesh level, with a chart")
    conv.add_argument("--D0", default=35.0, type=argtype(parse_number, "--D0"),
                      help="inner tube diameter [mm] (default: %(default)s, muscle I)")
    conv.add_argument("--t0", default=2.5, type=argtype(parse_number, "--t0"),
                      help="wall thickness [mm] (default: %(default)s)")
    conv.add_argument("--eps", default=0.05, type=argtype(parse_fraction),
                      help="shortening ratio, fraction or percentage (default: %(default)s)")
    conv.add_argument("--pressure", default=2.5, type=argtype(parse_number, "--pressure"),
                      help="pressure [bar] (default: %(default)s)")
    conv.add_argument("--theta0", type=argtype(parse_number, "--theta0"),
                      help="braid angle at rest [deg] (default: calibrated)")
    conv.add_argument("--L0", default=282.0, type=argtype(parse_number, "--L0"),
                      help="muscle length at rest [mm] (default: %(default)s)")
    conv.add_argument("--out", default="reports/fem-convergence",
                      help="folder for the CSV, JSON and PNG (default: %(default)s)")
    conv.set_defaults(func=_convergence)


def _solve(args) -> int:
    model = model_from_args(args)
    prediction = model.predict(args.pressures, args.D0, args.t0, args.eps)
    if model.name == "auto":
        from mkm.auto import explain

        print(explain(prediction), file=sys.stderr)
    emit_prediction(prediction, args.out)
    return 0


def _calibrate(args) -> int:
    from fem.calibration import fit_theta0, read_reference, store_calibration

    reference = read_reference(args.reference)
    fit = fit_theta0(lambda th: model_from_args(args, theta0_deg=th), reference)
    model = model_from_args(args, theta0_deg=fit["theta0_deg"])
    print(f"model {model.calibration_key}: theta0 = {fit['theta0_deg']:.3f} deg, "
          f"RMSE {fit['rmse_N']:.2f} N, largest residual {fit['max_abs_residual_N']:.2f} N "
          f"({fit['evaluations']} evaluations) against {args.reference}")
    print("pressure_bar,reference_N,model_N")
    for p, ref, f in zip(reference["pressure_bar"], reference["force_N"], fit["force_N"],
                         strict=True):
        print(f"{p:g},{ref:.2f},{f:.2f}")
    if not args.dry_run:
        store_calibration(model.calibration_key, fit, args.reference, model.params())
        print(f"stored in fem/calibration.json under {model.calibration_key!r}")
    return 0


def _dataset(args) -> int:
    from fem.dataset import build_dataset

    run = build_dataset(args.grid, args.model, mesh=args.mesh, out=args.out,
                        workers=args.workers, scheduler=args.scheduler, cache_dir=args.cache)
    print(f"mkm fem dataset: {run.summary()}", file=sys.stderr)
    return 0


def _convergence(args) -> int:
    from fem.fe.convergence import convergence_study

    frame, png = convergence_study(args.out, D0_mm=args.D0, t0_mm=args.t0, eps=args.eps,
                                   pressure_bar=args.pressure, theta0_deg=args.theta0,
                                   L0_mm=args.L0)
    print(frame.to_string(index=False, float_format=lambda v: f"{v:.6g}"))
    print(f"wrote {png} and mesh_convergence.csv/.json", file=sys.stderr)
    return 0
