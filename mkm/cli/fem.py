"""``mkm fem ...`` subcommands: argument parsing only, each calls one library function."""

from __future__ import annotations

import argparse
import sys

from mkm.cli.common import (
    IDENTIFIED_L0,
    add_batch_arguments,
    add_calibration_argument,
    add_geometry_arguments,
    add_model_arguments,
    add_progress_argument,
    argtype,
    choices,
    derived_help,
    emit_prediction,
    identified_length,
    model_from_args,
    parse_within,
    say,
    say_defaults,
    shared_help,
    spec_from_args,
    sweep_grid,
    with_calibration,
)
from mkm.core.ranges import parse_fraction, parse_number, parse_tolerance
from mkm.fem.ladder import static_names
from mkm.paths import default_cache, default_out


def register(subparsers) -> None:
    fem = subparsers.add_parser(
        "fem", help="physics force models: solve, calibrate, convergence, dataset",
        description="The physics ladder: Equation 2 (Chou-Hannaford), the thick-wall closed "
        "form and the axisymmetric FE model (see `mkm models`).",
        epilog="example: mkm fem solve --model thickwall --D0 35 --t0 2.5 --eps 5%")
    fem_sub = fem.add_subparsers(dest="fem_command", required=True, metavar="COMMAND")

    solve = fem_sub.add_parser(
        "solve", help="force of one muscle over a pressure sweep (CSV)",
        description="Force of one muscle over a pressure sweep with any predictor spec (see "
        "`mkm models`): CSV on stdout, or to --out FILE with the metadata in a .json beside.",
        epilog="example: mkm fem solve --model axisym:mesh=coarse --D0 35 --t0 2.5 --eps 5% "
        "--pressures 0:2.5:0.5")
    add_model_arguments(solve, default=None, default_said=(
        f"{DEFAULT_SOLVE_MODEL}, or with --calibration of a muscle `mkm identify` wrote, the "
        "model it was identified with (its 95 %% band beside the force)"),
        L0_default=IDENTIFIED_L0)
    add_geometry_arguments(solve)
    solve.add_argument("--out", help="write the CSV here instead of stdout; a name ending "
                      "in .xlsx writes an Excel workbook (a German Excel opens a CSV "
                      "in one column)")
    solve.add_argument("--tolerance", type=argtype(parse_tolerance, "--tolerance"),
                       help="auto only: largest acceptable error against the finest FE, "
                       "e.g. 2%% (default 2%%)")
    add_calibration_argument(solve)
    solve.add_argument("--cache", metavar="DIR", help="with --calibration of an identified "
                       "muscle: its band's FE predictions kept here, as mkm design keeps them, "
                       "so a second solve is fast (default: the user cache, predictions/)")
    solve.add_argument("--no-cache", action="store_true",
                       help="solve every FE sweep of the band; no cache")
    solve.set_defaults(func=with_calibration(_solve), written_files={"out": ".csv"})

    cal = fem_sub.add_parser(
        "calibrate", help="fit theta0 of a model to a reference sweep (CSV or bench run)",
        description="Fit the braid angle theta0 of a model to a reference: the paper's muscle I "
        "(default), a CSV, or a bench run folder (its settled steps; where a pressure was "
        "measured rising and falling, the mean of both branches is fitted). Prints the fit; "
        "--out FILE writes it to a calibration file that --calibration FILE selects in other "
        "commands; only --update-shipped rewrites the shipped mkm/fem/calibration.json.",
        epilog="example: mkm fem calibrate --model axisym --reference RUN_DIR --out lab.json; "
        "then mkm fem solve --model axisym --calibration lab.json --D0 40 --t0 3 --eps 0.1")
    add_model_arguments(cal, theta0=False, models=static_names())
    cal.add_argument("--reference", metavar="CSV|RUN_DIR",
                     help="CSV with pressure_bar,D0_mm,t0_mm,eps,force_N (optional L0_mm, "
                     "direction), a run folder of mkm acquire or mkm import (a lab's own table "
                     "becomes one), or a folder of them (one sweep each) (default: the paper's "
                     "muscle I)")
    cal.add_argument("--target", type=_target, metavar="TARGET",
                     action=derived_help(_targets_help))
    cal.add_argument("--out", metavar="FILE",
                     help="write the fit into this calibration file (other entries kept)")
    cal.add_argument("--update-shipped", action="store_true",
                     help="write the fit into the shipped mkm/fem/calibration.json, the default of "
                     "every command")
    cal.add_argument("--dry-run", action="store_true",
                     help="print the fit, write nothing (also the default without --out or "
                     "--update-shipped)")
    cal.set_defaults(func=_calibrate, written_files={"out": ".json"})

    data = fem_sub.add_parser(
        "dataset", help="forces of a model over a grid of muscles (CSV), resumable, on local "
        "workers or a Dask cluster",
        description="Forces of a model over a grid of muscles (the paper's Table 1 by default): "
        "one cache file per finished job, so an interrupted run resumes; local worker processes "
        "or a Dask cluster. Writes --out FILE and its .json provenance; a progress bar with an "
        "estimate runs on stderr.",
        epilog="example: mkm fem dataset --grid paper --model thickwall --out "
        "mkm-out/dataset/thickwall.csv")
    data.add_argument("--grid", default="paper",
                      help="'paper' (Table 1 of the paper, 162 points) or a grid TOML file "
                      "(default: %(default)s)")
    data.add_argument("--model", default="axisym", help=f"one of {', '.join(static_names())} "
                      "(default: %(default)s)")
    data.add_argument("--mesh", choices=choices("axisym", "mesh"),
                      help="mesh level of an FE model (default: the model's)")
    data.add_argument("--out", default=str(default_out("dataset", "mkm_dataset.csv")),
                      help="CSV to write; provenance goes next to it as .json (default: "
                      "%(default)s; the shipped dataset is replaced only if named here)")
    add_batch_arguments(data)
    data.add_argument("--cache", default=str(default_cache("dataset")),
                      help="one file per finished job; re-runs compute only what is missing "
                      "(default: %(default)s)")
    add_calibration_argument(data)
    add_progress_argument(data)
    data.set_defaults(func=with_calibration(_dataset), written_files={"out": ".csv"})

    conv = fem_sub.add_parser(
        "convergence", help="axisym mesh study: force, dofs and seconds per mesh level, with a "
        "chart",
        description="Mesh study of the axisymmetric FE model at one muscle and pressure: force, "
        "degrees of freedom and seconds per mesh level; CSV, JSON and PNG under --out.",
        epilog="example: mkm fem convergence --D0 35 --t0 2.5 --eps 5% --pressure 2.5")
    conv.add_argument("--D0", default=35.0, type=argtype(parse_number, "--D0", "mm"),
                      help=shared_help("--D0", "default: %(default)s, muscle I"))
    conv.add_argument("--t0", default=2.5, type=argtype(parse_number, "--t0", "mm"),
                      help=shared_help("--t0", "default: %(default)s"))
    conv.add_argument("--eps", default=0.05, type=argtype(parse_fraction),
                      help=shared_help("--eps", "default: %(default)s"))
    conv.add_argument("--pressure", default=2.5, type=_practical_pressure,
                      help="pressure [bar], within the practical range's 0-8 bar "
                      "(default: %(default)s)")
    conv.add_argument("--theta0", type=argtype(parse_within, "--theta0", "theta0_deg"),
                      help=shared_help("--theta0", "default: calibrated"))
    conv.add_argument("--L0", default=282.0, type=argtype(parse_within, "--L0", "L0_mm"),
                      help=shared_help("--L0", "default: %(default)s"))
    conv.add_argument("--out", default=str(default_out("fem-convergence")),
                      help="folder for the CSV, JSON and PNG (default: %(default)s)")
    add_calibration_argument(conv)
    conv.set_defaults(func=with_calibration(_convergence))


def _practical_pressure(text: str) -> float:
    """``--pressure`` of the mesh study: within the practical range, the pressures the chosen
    mesh is used at (a study at 100 bar would pick a mesh for a muscle no lab runs)."""
    from mkm.fem.limits import PRACTICAL_RANGE

    try:
        value = parse_number(text, "--pressure", "bar")
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None
    low, high = PRACTICAL_RANGE.pressure_bar
    if not low <= value <= high:
        raise argparse.ArgumentTypeError(f"--pressure {text}: expected a pressure in "
                                         f"[{low:g}, {high:g}] bar, the practical range")
    return value


def _target(text: str) -> str:
    """``--target``: one of the calibration's targets (read when given: the calibration module
    loads numpy, which `mkm --help` does without)."""
    from mkm.fem.calibration import TARGETS

    if text not in TARGETS:
        raise argparse.ArgumentTypeError(f"{text!r} is invalid: expected one of "
                                         f"{', '.join(TARGETS)}")
    return text


def _targets_help() -> str:
    from mkm.fem.calibration import TARGETS

    return "; ".join(f"{name}: {what}" for name, what in TARGETS.items())


#: the model `mkm fem solve` predicts with when --model is not given, but for an identified muscle
DEFAULT_SOLVE_MODEL = "eq2"


def _solve_model(args) -> str:
    """``--model``, or when it is not given the model the ``--calibration``'s muscle was
    identified with (said in a note: Equation 2 has no threshold, and no band of that muscle),
    else :data:`DEFAULT_SOLVE_MODEL`."""
    if args.model is not None:
        return args.model
    from mkm.identify.band import identified_entry

    found = identified_entry(args.calibration) if args.calibration is not None else None
    if found is None:
        return DEFAULT_SOLVE_MODEL
    say(args, "note", f"--model not given: {found[0]}, the model the muscle of --calibration "
        f"was identified with (--model {DEFAULT_SOLVE_MODEL} or another to predict with it)")
    return found[0]


def _solve(args) -> int:
    args.pressures, args.eps = sweep_grid(args.pressures, args.eps)
    args.model = _solve_model(args)
    spec = spec_from_args(args)
    identified_length(args, "L0_mm" in spec.entry.parameters and "L0_mm" not in dict(spec.params))
    model = model_from_args(args)
    prediction = model.predict(args.pressures, args.D0, args.t0, args.eps)
    if args.calibration is not None:  # an identified muscle's: its 95 % band beside the force
        import dataclasses

        from mkm.identify.band import prediction_ends
        from mkm.prediction_cache import DEFAULT_CACHE_DIR

        ends = prediction_ends(spec_from_args(args), args.calibration, prediction.force_N,
                               args.pressures, args.D0, args.t0, args.eps,
                               cache_dir=None if args.no_cache else args.cache or
                               DEFAULT_CACHE_DIR)
        if ends is not None:  # the upper end differs near the threshold
            prediction = dataclasses.replace(prediction, extras={
                "band95_N": ends[0], "band95_above_N": ends[1], **prediction.extras})
    if model.name == "auto":
        from mkm.auto import explain
        from mkm.verdict import model_label

        print(explain(prediction, label=model_label), file=sys.stderr)
    emit_prediction(_answered(prediction, model), args.out, model)
    say_defaults(args, model, dict(spec.params),
                 f"--model {args.model}{',' if ':' in args.model else ':'}C10_MPa=X,C01_MPa=Y",
                 prediction)
    outside = _outside_practical_range(prediction, args.D0, args.t0)
    if outside:  # computed all the same (inside LIMITS it is a muscle), but never validated
        say(args, "warning", f"outside the practical range every model is validated over "
            f"({'; '.join(outside)}): computed all the same, an extrapolation (`mkm models` "
            "states the range)")
    invalid = int((~prediction.valid).sum())
    if invalid:
        say(args, "warning", f"{invalid} of {prediction.valid.size} points valid=False "
            f"({_invalid_reasons(prediction)}): no force written for them (their reason in the "
            "reason column)")
    return 0


def _answered(prediction, model):
    """``prediction`` with no number where it has no answer, as `mkm surrogate predict` writes
    it: a ``valid=False`` point keeps its row, with NaN for ``force_N`` and the extras that are
    forces (an empty CSV cell), and the extra ``reason`` says why (empty where answered). The
    model's number there (Equation 2's negative force past the braid lock, a surrogate's
    extrapolation) would be taken for a force of the muscle by a table or a script."""
    import dataclasses

    import numpy as np

    unanswered = ~np.asarray(prediction.valid, dtype=bool)
    reason = np.full(unanswered.shape, "", dtype=object)
    for said, these in _reasons(prediction):
        reason[these] = said
    answered = getattr(model, "answered", None)
    if answered is not None:  # a surrogate names the inputs outside its box
        prediction = answered(prediction)
        own = np.asarray(prediction.extras["reason"], dtype=object)
        # after a reason of its own (past the braid lock), which the warning counts the point
        # under, unless the surrogate's says it first; in place of the bare "outside the
        # model's domain"
        reason = np.reshape([_merged(r, o) for r, o in zip(reason.ravel(), own.ravel(),
                                                           strict=True)],
                            reason.shape).astype(object)
    extras = {**prediction.extras, "reason": reason}
    for name in ("force_std_N", "band95_N", "band95_above_N"):
        if name in extras:
            extras[name] = np.where(unanswered, np.nan, extras[name])
    return dataclasses.replace(prediction, extras=extras,
                               force_N=np.where(unanswered, np.nan, prediction.force_N))


def _merged(reason: str, own: str) -> str:
    """A point's reason of the sweep (:func:`_reasons`) and a surrogate's own, said once."""
    if not own:
        return reason
    if not reason or reason == _OUTSIDE_DOMAIN or own.startswith(reason):
        return own
    return f"{reason}; {own}"


def _invalid_reasons(prediction) -> str:
    """Why the sweep's points are ``valid=False``, counted by reason (:func:`_reasons`)."""
    return "; ".join(f"{int(these.sum())} {said}" for said, these in _reasons(prediction))


def _reasons(prediction) -> list:
    """Why the sweep's points are ``valid=False``: (reason, which points) by their outcome
    (:func:`mkm.fem.outcomes.classify`), each point under the first that applies: past the braid
    lock of its angle (with eps_max), the braid locking before eps in the model's muscle (a
    physical limit), not converged, a surrogate's point without an answer in its own box
    (:data:`mkm.surrogate.model.UNINFORMED`), outside the model's domain."""
    import numpy as np

    from mkm.fem.limits import lock_eps, past_lock_text
    from mkm.fem.outcomes import BRAID_LOCKS, classify

    bad = ~np.asarray(prediction.valid, dtype=bool)
    theta0 = prediction.params.get("theta0_deg")
    reasons = []
    if isinstance(theta0, int | float):
        locked = bad & (np.asarray(prediction.eps, dtype=float) >= lock_eps(float(theta0)))
        if locked.any():
            reasons.append((past_lock_text(float(theta0)), locked))
            bad = bad & ~locked
    status = np.reshape(classify(prediction), bad.shape)
    # short of eps_max only where the points past it were told apart above (auto's candidates
    # each have their own calibrated theta0: it states none)
    short = "short of eps_max: " if isinstance(theta0, int | float) else ""
    for outcome, said in ((BRAID_LOCKS, f"where the braid locks before eps ({short}a physical "
                                        "limit of the muscle)"),
                          ("not converged", "not converged")):
        these = bad & (status == outcome)
        if these.any():
            reasons.append((said, these))
            bad = bad & ~these
    in_domain = prediction.extras.get("in_domain")
    if in_domain is not None and bad.any():  # a surrogate's: no answer inside its own box
        from mkm.surrogate.model import UNINFORMED

        these = (bad & np.reshape(np.asarray(in_domain, dtype=bool), bad.shape)
                 & (status == "invalid (model's own limit)"))
        if these.any():
            reasons.append((UNINFORMED, these))
            bad = bad & ~these
    if bad.any():
        reasons.append((_OUTSIDE_DOMAIN, bad))
    return reasons


_OUTSIDE_DOMAIN = "outside the model's domain"


def _outside_practical_range(prediction, D0_mm: float, t0_mm: float) -> list[str]:
    """What of the sweep lies outside the practical range, one phrase each; empty inside, and
    for a model that flags its own domain (a surrogate's ``in_domain``). eps is left out: past
    the braid lock the points are ``valid=False``, which the warning after says."""
    from mkm.fem.limits import PRACTICAL_RANGE

    if "in_domain" in prediction.extras:
        return []
    muscle = {k: prediction.params.get(k) for k in ("L0_mm", "theta0_deg", "C10_MPa",
                                                    "C01_MPa")}
    pressures = (float(prediction.pressure_bar.min()), float(prediction.pressure_bar.max()))
    found = [v for p in pressures for v in PRACTICAL_RANGE.violations(pressure_bar=p)]
    return list(dict.fromkeys(found)) + PRACTICAL_RANGE.violations(
        D0_mm=D0_mm, t0_mm=t0_mm, **{k: v for k, v in muscle.items() if v is not None})


def _calibrate(args) -> int:
    from mkm.bench.reference import calibration_reference
    from mkm.fem.calibration import (
        CALIBRATION_FILE,
        calibrate,
        calibration_entry,
        store_calibration,
    )
    from mkm.fem.ladder import entry
    from mkm.fem.paper import CASE_I_CSV

    args.reference = args.reference or str(CASE_I_CSV)
    reference, name, sha256 = calibration_reference(args.reference)
    try:
        fitted = calibrate(lambda **params: model_from_args(args, **params), reference,
                           args.target, getattr(args, "L0", None))
    except RuntimeError as exc:  # a fit that failed: said, nothing written
        say(args, "error", f"{exc} at every point of {name}; nothing written")
        return 1
    model = fitted.model
    # stored before anything is printed: `| head` closing stdout must not lose the fit
    paths = [] if args.dry_run else [p for p in (args.out, args.update_shipped and
                                                 CALIBRATION_FILE) if p]
    if paths:
        record = calibration_entry(fitted.fit, model, name, sha256, entry(model.name).module)
        for path in paths:
            store_calibration(path, model.calibration_key, record)
            print(f"stored in {path} under {model.calibration_key!r}", file=sys.stderr)
    print(fitted.summary(name))
    sys.stdout.write(fitted.table_csv())
    return 0


def _dataset(args) -> int:
    from mkm.fem.dataset import build_dataset, load_grid

    run = build_dataset(load_grid(args.grid), args.model, mesh=args.mesh, out=args.out,
                        workers=args.workers, scheduler=args.scheduler, cache_dir=args.cache,
                        progress=not args.no_progress, calibration=args.calibration)
    print(f"mkm fem dataset: {run.summary()}", file=sys.stderr)
    return 0


def _convergence(args) -> int:
    from mkm.fem.fe.convergence import convergence_study
    from mkm.fem.fe.model import Axisym

    frame, png = convergence_study(args.out, D0_mm=args.D0, t0_mm=args.t0, eps=args.eps,
                                   pressure_bar=args.pressure, theta0_deg=args.theta0,
                                   L0_mm=args.L0, calibration=args.calibration)
    failed = frame[~frame["converged"]]
    print(frame.drop(columns="failure").to_string(index=False,
                                                  float_format=lambda v: f"{v:.6g}"))
    print(f"wrote {png} and mesh_convergence.csv/.json", file=sys.stderr)
    # the muscle every level solved (the mesh aside), as mkm fem solve says of its axisym
    say_defaults(args, Axisym(theta0_deg=args.theta0, L0_mm=args.L0,
                              calibration=args.calibration),
                 ["theta0_deg"] * (args.theta0 is not None),
                 "--calibration of an identified muscle")
    if len(failed):  # a NaN force is no mesh error: said with why
        say(args, "warning", f"mesh {', '.join(failed['mesh'])} did not converge, force_N NaN: "
            f"{failed['failure'].iloc[0]}")
    elif (frame["force_N"] == 0).all():  # below P*: no force to compare, 0/0 is no error
        say(args, "warning", f"force 0 N on every mesh: {args.pressure:g} bar is below the "
            f"threshold pressure ({frame['threshold_pressure_bar'].iloc[-1]:.4g} bar on the "
            "finest mesh), so force_change_vs_finest is empty; compare threshold_pressure_bar, "
            "or give a --pressure above it")
    return 0
