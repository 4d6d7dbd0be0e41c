"""``mkm acquire|tare|calibrate-loadcell|check|vent|reprocess|recover|close``: argument
parsing only.

Hardware failures (:class:`mkm.bench.backend.BenchError`, a bench another process holds
included) print one line ``mkm <command>: error: ...`` and exit with status 1; bad input is a
``ValueError`` (status 2, handled by ``mkm.cli.main``). ``mkm acquire`` exits with
:attr:`mkm.bench.run.RunResult.exit_code` (0 complete, 3 complete with lost samples, 128 + N
after signal N, 2 when the disk failed, 4 when the vent could not be verified, 1 otherwise) and
always prints the run folder last on stdout once it exists. ``--backend`` choices are the
backends of :mod:`mkm.bench.backends`.
"""

from __future__ import annotations

import math
import os
import sys

from mkm.cli.common import (
    add_progress_argument,
    argtype,
    command_name,
    has_display,
    next_commands,
    say,
    shared_help,
)
from mkm.core.ranges import (
    decimal_comma_reading,
    parse_fraction,
    parse_number,
    parse_numbers,
    parse_pressures,
)
from mkm.paths import default_out

EXIT_FAILED = 1


def _positive_seconds(text: str) -> float:
    from mkm.bench.procedures import MAX_SECONDS

    value = parse_number(text, "--seconds", "s")
    if not 0 < value <= MAX_SECONDS:
        raise ValueError(f"--seconds {text!r} is invalid: expected a duration > 0 s, at most "
                         f"{MAX_SECONDS:g} s")
    return value


def _masses(text: str) -> list[float]:
    values = parse_numbers(text, "--masses", "kg")
    if any(v < 0 for v in values):
        raise ValueError(f"--masses {text!r} has a negative mass: expected kg >= 0")
    if len(set(values)) < 2:  # said before the operator hangs the first mass
        raise ValueError(f"--masses {text!r} holds one mass: expected at least two different "
                         "masses for a sensitivity (0,5,10,20)")
    return values


def _volts(text: str) -> list[float]:
    return parse_numbers(text, "--volts", "V")


def _add_device_arguments(parser, clock: bool = True) -> None:
    from mkm.bench import backend
    from mkm.bench.backends import BACKENDS

    parser.add_argument("--config", help="bench TOML file (default: the packaged example "
                        "paper_prototype.toml, the paper's prototype on the simulated bench; "
                        "`mkm check --example my_bench.toml` writes it for editing)")
    parser.add_argument("--backend", choices=BACKENDS.names(), default=None,
                        help="; ".join(f"{e.name}: {e.label}" for e in BACKENDS.entries())
                        + " (default: the config's [daq] backend)")
    if clock:
        parser.add_argument("--clock", choices=backend.CLOCKS, default=backend.CLOCKS[0],
                            help="sim only: virtual time (instant) or real time "
                                 "(default %(default)s)")


def register(subparsers) -> None:
    acquire = subparsers.add_parser(
        "acquire", help="record a pressure staircase on the bench",
        description="Record a pressure staircase on the bench (NI USB-6001) or the simulated "
        "one: tare at 0 bar, then each step held until the force settles and averaged over a "
        "window; writes a run folder (run.json, samples.csv, steps.csv, commands.csv, "
        "config.toml) under --out and prints its path last. Ctrl-C stops at a safe point; a "
        "second Ctrl-C, SIGTERM, SIGHUP, Ctrl-Break, closing the console or any other signal "
        "that would end the process (SIGQUIT from Ctrl-\\, ...) stop at once; every "
        "stop vents first. Exit status: 0 complete, 3 complete with lost samples, 128+N after "
        "signal N, 1 interlock or device failure, 2 bad input or disk failure, 4 the vent not "
        "verified (VENT BY HAND; it wins over every other). The default "
        "staircase (19 steps) takes 3 to 21 min on the real bench, depending "
        "on settling (`mkm check` prints the estimate); --clock virtual: about a second.",
        epilog="example: mkm acquire --backend sim --eps 12.2% --out mkm-out/runs")
    _add_device_arguments(acquire)
    acquire.add_argument("--eps", type=argtype(parse_fraction),
                         help=shared_help("--eps", "default: the config's"))
    acquire.add_argument("--pressures",
                         help=shared_help("--pressures", "default: the config's"))
    acquire.add_argument("--out", default=str(default_out("runs")),
                         help="folder that receives the run folder (default %(default)s)")
    acquire.add_argument("--plot", action="store_true", help="live plot in a separate window")
    add_progress_argument(acquire)
    acquire.add_argument("--allow-past-lock", action="store_true",
                         help="record even with eps past the braid lock (refused otherwise)")
    acquire.add_argument("--calibration", metavar="FILE",
                         help="the calibration.json of `mkm identify` for this muscle: its "
                         "identified force, with its 95 %% band and friction, bounds what the "
                         "load cell may read at each measured pressure, so that a pressure "
                         "monitor reading low (its regulator then delivers more than it reads, "
                         "unseen by the over-pressure limit) stops the run, vented (default: "
                         "the config's safety.calibration, else no such bound)")
    acquire.set_defaults(func=_acquire)

    tare = subparsers.add_parser(
        "tare", help="load-cell offset at 0 bar",
        description="Measure the load-cell offset at 0 bar (mean and noise over --seconds) and "
        "compare it with the config's offset_V; refused as a run's tare would be (too few "
        "samples, not finite, too noisy or shifted: the [safety] tare limits).",
        epilog="example: mkm tare --backend ni --config my_bench.toml --seconds 10")
    _add_device_arguments(tare)
    tare.add_argument("--seconds", type=argtype(_positive_seconds), default=5.0,
                      help="averaging time [s] (default %(default)s)")
    tare.set_defaults(func=_tare)

    cal = subparsers.add_parser(
        "calibrate-loadcell", help="fit N/V and offset from known masses",
        description="Fit the load cell's sensitivity [N/V] and offset [V] from known masses hung "
        "in turn (measured here), or from volts measured elsewhere (--volts). Prints the "
        "[loadcell] block to paste into the config on stdout, the fit on stderr.",
        epilog="example: mkm calibrate-loadcell --masses 0,1,2,5 --volts "
        "0.015,0.065,0.115,0.265")
    _add_device_arguments(cal)
    cal.add_argument("--masses", required=True, type=argtype(_masses),
                     help="comma list of masses [kg] hung in turn, e.g. 0,1,2,5 (with decimal "
                     "commas, a semicolon list: 0;0,5;1)")
    cal.add_argument("--volts", type=argtype(_volts),
                     help="list of the mean volts measured under each mass, as --masses: fit "
                     "these, no acquisition")
    cal.add_argument("--seconds", type=argtype(_positive_seconds), default=3.0,
                     help="averaging time per mass [s] (default %(default)s)")
    cal.set_defaults(func=_calibrate_loadcell)

    check = subparsers.add_parser(
        "check", help="dry run: device, limits, planned steps, duration",
        description="Dry run: validate the config against the USB-6001 (channels, terminal "
        "configuration, rates, ranges), open the device, print the limits, the planned steps "
        "and the expected duration; warns past the braid lock; nothing is pressurised.",
        epilog="example: mkm check --backend ni --config my_bench.toml; a config to edit: "
        "mkm check --example my_bench.toml")
    _add_device_arguments(check, clock=False)
    check.add_argument("--example", nargs="?", const="-", metavar="FILE",
                       help="write the packaged example configuration into FILE to edit it "
                       "(mkm check --example my_bench.toml; an existing FILE is kept), or "
                       "print it when no FILE is given")
    check.add_argument("--eps", type=argtype(parse_fraction),
                       help=shared_help("--eps", "default: the config's"))
    check.add_argument("--pressures",
                       help=shared_help("--pressures", "default: the config's"))
    check.add_argument("--calibration", metavar="FILE",
                       help="the calibration.json of `mkm identify` for this muscle: print the "
                       "force the over-force interlock holds each step to, and refuse a plan "
                       "whose top step the muscle must pull past the force interlock at "
                       "(default: the config's safety.calibration)")
    check.set_defaults(func=_check, written_files={"example": ".toml"})

    vent = subparsers.add_parser(
        "vent", help="command 0 bar now and wait until the monitor reads it",
        description="Command 0 bar on the bench, wait until the regulator's monitor reads below "
                    "0.05 bar and print the pressure. Also vents (and names) a run that ended "
                    "without venting (kill -9, power loss) and says which.",
        epilog="example: mkm vent --backend ni --config my_bench.toml")
    _add_device_arguments(vent)
    vent.set_defaults(func=_vent)

    rep = subparsers.add_parser(
        "reprocess", help="recompute a run's forces from its raw volts with a new calibration",
        description="Write a new run folder (its name ends in -reprocessed) with every force "
                    "recomputed from the raw load-cell volts with the [loadcell] of NEW.toml "
                    "(tare and hold averages again), with provenance (reprocessed_from in "
                    "run.json). NEW.toml may hold [loadcell] only: its sections replace the "
                    "run's own configuration's.",
        epilog="example: mkm reprocess mkm-out/runs/RUN --config new.toml --out mkm-out/runs")
    rep.add_argument("run_dir", metavar="RUN_DIR", help="run folder written by mkm acquire")
    rep.add_argument("--config", required=True,
                     help="TOML with the new [loadcell] (and any other section to replace)")
    rep.add_argument("--out", help="folder that receives the new run folder (default: beside "
                     "RUN_DIR)")
    rep.set_defaults(func=_reprocess)

    rec = subparsers.add_parser(
        "recover", help="join the samples a read-only run folder refused back into it",
        description="Append the samples a run folder refused to the end (gone read-only, a "
                    "share remounted), kept in the user state folder as "
                    "unwritten/<run folder>-samples.csv, to the run's samples.csv once the "
                    "folder takes writes again, and count them in run.json (with the gaps "
                    "kept beside them, as unwritten/<run folder>-gaps.json). Refused in one "
                    "line, nothing changed, while the folder is still read-only or when the "
                    "kept rows do not continue samples.csv's last sample; the kept file stays.",
        epilog="example: mkm recover mkm-out/runs/20261202T093800Z_paper-prototype")
    rec.add_argument("run_dir", metavar="RUN_DIR", help="run folder written by mkm acquire")
    rec.set_defaults(func=_recover)

    close = subparsers.add_parser(
        "close", help="close the record of a run whose mkm acquire died on a PC gone",
        description="Close by hand the record of a run whose run.json still says running "
                    "though its mkm acquire has died: recorded on another PC (a run folder on a "
                    "share) that will not run mkm again, whose next command on its bench would "
                    "close it. run.json becomes killed, with the samples counted from "
                    "samples.csv, the end at its last write, and --reason, your user name, this "
                    "PC and the time (its 'closed' record); no sample is changed, and mkm "
                    "identify and mkm report take the run. Refused, nothing changed, while its "
                    "mkm acquire runs on this PC or its files were written within the last "
                    "5 minutes. Nothing is vented: a run that ended without venting is named, "
                    "vent its bench there.",
        epilog='example: mkm close S:\\runs\\20261202T093800Z_paper-prototype --reason '
               '"BENCH-PC-A broke during the run"')
    close.add_argument("run_dir", metavar="RUN_DIR", help="run folder written by mkm acquire")
    close.add_argument("--reason", required=True,
                       help="why it is closed by hand, kept in run.json (its reason and "
                       "closed.reason)")
    close.set_defaults(func=_close)


def _failed(args, exc: Exception, then: str = "") -> int:
    """A failure of the bench said in one line (:func:`mkm.bench.backend.device_said`: an
    ``OSError`` as the device's driver or USB stack raises it, in words), ``then`` after it
    unless said already; :data:`EXIT_FAILED`."""
    from mkm.bench.backend import device_said

    said = device_said(exc)
    said = f"{said}; {then}" if then and then not in said else said
    return _kept(EXIT_FAILED, lambda: say(args, "error", said))


def _on_device(args, call, then: str = ""):
    """``(call(), None)`` for a call that drives the bench, or ``(None, exit status)`` once its
    :class:`mkm.bench.backend.BenchError` or ``OSError`` (a crash inside the driver's DLL, the
    USB stack's I/O error: never ``[Errno 5]`` alone, never exit 2 as bad input) is said by
    :func:`_failed`. A reader of the output gone is not the device's failure."""
    from mkm.bench.backend import BenchError  # here: the bench loads pandas

    try:
        return call(), None
    except BrokenPipeError:
        raise
    except (BenchError, OSError) as exc:
        return None, _failed(args, exc, then)


def _config(args, **overrides):
    from mkm.bench.config import load_config

    return load_config(args.config, backend=args.backend, **overrides)


def _staircase(args):
    """``--pressures`` in bar (None: the config's); a list that also reads as one number with
    a decimal comma (``1,5``) is said to be the steps it is, before anything is pressurised."""
    if args.pressures is None:
        return None
    values = parse_pressures(args.pressures)
    single = decimal_comma_reading(args.pressures)
    if single is not None:
        say(args, "note", f"--pressures {args.pressures!r} is two steps, {values[0]:g} and "
            f"{values[1]:g} bar; for one step at {single:g} bar write {single:g}")
    return values


def _hardware_config(args, command: str):
    """The config of a command that drives the bench at once (vent, tare, calibrate-loadcell):
    refused without ``--backend`` and without ``--config`` (the packaged example is simulated,
    and a vent that never happened must not look like one); SIMULATED said on stderr."""
    from mkm.bench.backends import BACKENDS

    if args.backend is None and args.config is None:
        raise ValueError(f"mkm {command} drives the bench: pass --backend "
                         f"{'|'.join(BACKENDS)} (or a --config whose [daq] backend says which)")
    config = _config(args)
    if config.simulated:  # a reader gone does not keep the command from the bench
        _kept(0, lambda: print(f"mkm {command}: SIMULATED bench ({config.daq.backend}): no "
                               "hardware is driven", file=sys.stderr, flush=True))
    return config


def _acquire(args) -> int:
    from mkm.bench.backend import BenchError  # here: the bench loads pandas
    from mkm.bench.run import acquire, check_out_root

    config = _config(args, eps=args.eps, pressures_bar=_staircase(args))
    check_out_root(args.out)  # bad --out: one line, exit 2, before the device is opened
    ceiling = _ceiling(args, config)
    plot = args.plot
    if plot and not has_display():
        say(args, "warning", "--plot needs a display and none is set (DISPLAY and "
            "WAYLAND_DISPLAY are empty): recording without the live plot")
        plot = False
    try:
        result = acquire(config, clock=args.clock, out_root=args.out,
                         progress=not args.no_progress, plot=plot,
                         allow_past_lock=args.allow_past_lock, ceiling=ceiling)
    except BenchError as exc:  # the bench is held by another process: nothing was touched
        return _failed(args, exc)
    return _kept(result.exit_code,
                 lambda: _said(args, result, " SIMULATED" if config.simulated else "",
                               config.muscle.eps))


def _ceiling(args, config):
    """The identified muscle's force ceiling of ``--calibration``, else of the configuration's
    ``safety.calibration``, or None (no over-force interlock)."""
    if args.calibration is None and config.safety.calibration is None:
        return None
    from mkm.identify.band import config_ceiling  # here: the application's models

    return config_ceiling(config, args.calibration)


def _kept(code: int, report) -> int:
    """``report()`` (a bench command's last lines), then ``code``: a reader of the output that
    left (`| tee log` ended by the same Ctrl-C, a closed terminal) does not turn how the bench
    was left into the 0 a reader leaving a report's output (`| head`) gets."""
    try:
        report()
    except BrokenPipeError:
        for stream in (sys.stdout, sys.stderr):
            os.dup2(os.open(os.devnull, os.O_WRONLY), stream.fileno())
    return code


def _said(args, result, simulated: str, eps: float | None = None) -> None:
    """A run's outcome on stderr and its folder on stdout, once it exists; for a run of a
    muscle at ``eps`` that completed, what to type next."""
    if result.path is None:
        say(args, "error", f"{simulated.strip()} {result.reason}".strip())
        return
    print(f"{command_name(args)}: run{simulated} {result.status}: {result.reason}", file=sys.stderr)
    if result.manual_vent_required:
        say(args, "error", "VENT THE MUSCLE BY HAND NOW: the vent was not verified")
    print(result.path, flush=True)
    if eps is not None and result.status == "complete":
        say(args, "note", next_commands([result.path], [eps]))


def _tare(args) -> int:
    from mkm.bench.procedures import AT_REST_WARNINGS, tare

    config = _hardware_config(args, "tare")
    out, failed = _on_device(args, lambda: tare(config, clock=args.clock, seconds=args.seconds))
    if failed is not None:
        return failed
    print(f"offset {out['offset_V']:.5f} V (noise {out['std_V'] * 1e3:.2f} mV = "
          f"{out['std_N']:.2f} N, n = {out['n']}); {out['shift_from_config_N']:+.2f} N from the "
          "config's offset_V")
    if out.get("monitor_vented_settled"):
        print(f"pressure monitor {out['monitor_vented_bar']:+.4f} bar vented "
              f"(+-{out['monitor_vented_se_bar']:.1g} bar standard error)")
    for warning in filter(None, (out[key] for key in AT_REST_WARNINGS)):
        print(f"mkm tare: warning: {warning}", file=sys.stderr)
    return 0


def _calibrate_loadcell(args) -> int:
    from mkm.bench.procedures import (
        calibrate_loadcell,
        check_masses,
        fit_loadcell,
        loadcell_table,
        refused_fit,
    )
    from mkm.core.records import provenance

    if args.volts is not None:  # volts measured elsewhere: nothing is driven
        config = _config(args)
        check_masses(config, args.masses)
        out = fit_loadcell(args.masses, args.volts)
    else:
        config = _hardware_config(args, "calibrate-loadcell")
        out, failed = _on_device(args, lambda: calibrate_loadcell(
            config, args.masses, clock=args.clock, seconds=args.seconds))
        if failed is not None:
            return failed
    # stdout: the block to paste into the config; stderr: the fit, for the operator
    spread = out["sensitivity_U95_fraction"]
    interval = (f"+-{100 * spread:.2g} % at 95 %" if math.isfinite(spread) else
                "no interval from two masses: hang three or more to judge it")
    print(f"sensitivity_N_per_V = {out['sensitivity_N_per_V']:.4f} ({interval}), offset_V = "
          f"{out['offset_V']:.5f} (R^2 {out['r_squared']:.6f}, largest residual "
          f"{out['max_abs_residual_N']:.3f} N over {out['n_points']} masses)", file=sys.stderr)
    print(loadcell_table(out, config, provenance()))
    declared = config.loadcell.sensitivity_tolerance_fraction
    if spread > declared:  # the budget's gain term would claim more than the fit knows
        say(args, "warning", f"the fitted sensitivity's 95 % interval, +-{100 * spread:.2g} %, "
            f"is wider than loadcell.sensitivity_tolerance_fraction = {declared:g} declares: "
            f"declare at least {spread:.2g} there, or calibrate again with more masses up to "
            "the cell's capacity")
    if refused := refused_fit(out, config):
        say(args, "warning", f"this [loadcell] pasted into {args.config or 'the config'} is "
            f"refused: {refused}; lower capacity_N to what the cell reads before its rail, or "
            "raise the amplifier's gain, and calibrate again")
    return 0


def _check(args) -> int:
    from mkm.bench.preflight import braid_lock
    from mkm.bench.procedures import check

    if args.example:
        from mkm.bench.config import copy_example_config, example_config

        if args.example == "-":
            sys.stdout.write(example_config().read_text("utf-8"))
        else:
            print(copy_example_config(args.example), flush=True)
        say(args, "note", f"the packaged example {example_config()}: set [daq] device and "
            "backend, the load cell's sensitivity, the regulator and the limits")
        return 0
    config = _config(args, eps=args.eps, pressures_bar=_staircase(args))
    ceiling = _ceiling(args, config)
    done, failed = _on_device(args, lambda: check(config, ceiling=ceiling))
    if failed is not None:
        return failed
    text, warnings, refusal = done
    print(text)
    for warning in warnings:  # once, on stderr only
        say(args, "warning", warning)
    if refusal:  # the last line: what stops the run, not "ready"
        say(args, "error", f"{refusal}: fix this first")
        return EXIT_FAILED
    # the last line a newcomer reads: what was checked and what to do next
    what = ("the simulated device answered (no hardware driven)" if config.simulated
            else "the device answered")
    # acquire refuses a muscle past its braid lock unless told: the command to type says so
    past_lock = (" and --allow-past-lock, without which it refuses a muscle past its braid "
                 "lock" if braid_lock(config, ceiling) else "")
    then = (f"read the {len(warnings)} warning(s) above, then `mkm acquire` with the same "
            f"options{past_lock}" if warnings else "`mkm acquire` with the same options runs "
            "the steps above")
    say(args, "ready", f"{what} and the configuration holds; {then}")
    return 0


def _vent(args) -> int:
    from mkm.bench.procedures import vent
    from mkm.bench.vent import reading_bar

    config = _hardware_config(args, "vent")
    out, failed = _on_device(args, lambda: vent(config, clock=args.clock), "VENT BY HAND")
    if failed is not None:
        return failed
    said = ("vent commanded; the regulator is manual: no monitor to read, vent it by hand and "
            "check the manometer" if out["manual"] else
            f"vented: {reading_bar(out['pressure_bar'])} bar after {out['waited_s']:.1f} s")

    def report() -> None:
        print(said, flush=True)
        _bookkeeping(args, out["bookkeeping"])

    return _kept(EXIT_FAILED if out["bookkeeping"] else 0, report)


def _bookkeeping(args, problems: list[str]) -> None:
    """After a vent: the bench state folder's problems, one line (exit 1: the lock and the
    markers that keep two commands off one bench do not work until it is mended)."""
    if problems:
        problems = "; ".join(dict.fromkeys(problems))  # request and lock often fail alike
        say(args, "error", f"vented, but the bench bookkeeping failed: {problems}")


def _reprocess(args) -> int:
    from mkm.bench.folders import one_run_folder
    from mkm.bench.reprocess import overlay_config, reprocess

    args.run_dir = one_run_folder(args.run_dir)
    path = reprocess(args.run_dir, overlay_config(args.run_dir, args.config), args.out)
    print(path)
    return 0


def _close(args) -> int:
    from mkm.bench.folders import one_run_folder
    from mkm.bench.storage import close_by_hand, read_meta

    args.run_dir = one_run_folder(args.run_dir)
    say(args, "note", close_by_hand(args.run_dir, args.reason))
    print(args.run_dir, flush=True)
    say(args, "note", next_commands([args.run_dir], [read_meta(args.run_dir).muscle.eps]))
    return 0


def _recover(args) -> int:
    from mkm.bench.folders import one_run_folder
    from mkm.bench.storage import join_kept_samples

    args.run_dir = one_run_folder(args.run_dir)
    done, counted = join_kept_samples(args.run_dir)
    say(args, "note" if counted else "error", done)
    print(args.run_dir)
    return 0 if counted else EXIT_FAILED
