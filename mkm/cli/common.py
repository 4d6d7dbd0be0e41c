"""Arguments and output shared by the ``mkm`` subcommands."""

from __future__ import annotations

import argparse
import io
import os
import re
import sys
from pathlib import Path

from mkm.core.ranges import parse_fraction, parse_number, parse_pressures, parse_shortenings
from mkm.core.records import (
    one_argument,
    prediction_metadata,
    sidecar_path,
    write_csv_with_sidecar,
    write_prediction_csv,
    write_workbook_with_sidecar,
)
from mkm.flags import FLAG_OF, dests
from mkm.registry import entries, entry, parse_spec


def has_display() -> bool:
    """Whether a plot window can open: always on Windows and macOS; elsewhere an X11 or
    Wayland display must be named in the environment."""
    if sys.platform in ("win32", "darwin"):
        return True
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def command_name(args) -> str:
    """``mkm <command>`` of the parsed ``args`` (``mkm fem solve``): the prefix of every line
    the command prints on stderr (set by the parser, :func:`remember_command`)."""
    return getattr(args, "_mkm_command", None) or "mkm"


def remember_command(namespace, prog: str) -> None:
    """Record the deepest (sub)command's name in ``namespace``: called by each parser after it
    parsed, the innermost first, so the innermost name stays."""
    if not getattr(namespace, "_mkm_command", None):
        namespace._mkm_command = prog


def error_line(prog: str, message) -> str:
    """``mkm <command>: error: <message>``, the one form of every error, on each line of a
    message of several (a configuration's bad values, one a line); argparse's
    ``argument --eps: --eps 12.2: ...`` is said once: ``--eps 12.2: ...``."""
    message = str(message)
    found = re.match(r"argument (\S+?)(?:/\S+)?: (.*)", message, re.DOTALL)
    if found and found.group(2).startswith(found.group(1)):
        message = found.group(2)
    # argparse's own type check ('argument --top: invalid int value: 'x''): said as ours
    typed = re.fullmatch(r"argument (\S+?)(?:/\S+)?: invalid (int|float) value: (.*)", message,
                         re.DOTALL)
    if typed:
        expected = "a whole number" if typed.group(2) == "int" else "a number"
        message = f"{typed.group(1)} {typed.group(3)}: expected {expected}"
    return "\n".join(f"{prog}: error: {line}" for line in message.splitlines() or [""])


def name_the_flag(args, message) -> str:
    """``message`` about a quantity the command line set, said about its flag
    (:data:`mkm.flags.FLAG_OF`): each of its problems (a line, or a part after ``; ``) that
    opens with ``name=value``: ``D0_mm=-1 is invalid: expected ...`` -> ``--D0 -1: expected
    ...``, ``gap_mm=4 is too wide ...`` -> ``--gap 4 is too wide ...`` (unchanged when the
    value came from elsewhere: a config file, a spec file, a model spec)."""

    def flagged(found) -> str:
        name = found.group(2)
        if name not in FLAG_OF or all(getattr(args, d, None) is None for d in dests(name)):
            return found.group(0)
        flag = FLAG_OF[name]
        said = ": " if found.group(4) else " "
        return f"{found.group(1)}{flag} {found.group(3)}{said}"

    return re.sub(r"(^|; |\n)([\w.]+)=(\S+) (is invalid: )?", flagged, str(message))


def say(args, kind: str, message) -> None:
    """One line on stderr: ``mkm <command>: <kind>: <message>`` (``error``, ``warning``,
    ``note``)."""
    line = (error_line(command_name(args), name_the_flag(args, message)) if kind == "error"
            else f"{command_name(args)}: {kind}: {message}")
    print(line, file=sys.stderr)


def next_commands(paths, eps) -> str:
    """What a newcomer types after recording or importing the run folders ``paths`` (at the
    shortenings ``eps``): the report of them, and identify where they hold two eps or more."""
    typed = " ".join(map(one_argument, paths))
    fit = (f"mkm identify {typed} fits the muscle's braid angle and rubber to them"
           if len({round(float(e), 6) for e in eps}) > 1 else
           "mkm identify with runs of this muscle at two eps or more fits its braid angle and "
           "rubber")
    return f"next: mkm report {typed} scores every model against the measurement; {fit}"


def parse_within(text: str, flag: str, name: str) -> float:
    """``text`` as a number inside ``LIMITS[name]`` (:mod:`mkm.fem.limits`): a model that only
    records a value (Equation 2's ``L0_mm``) or flags it (a surrogate) must not take a typo."""
    from mkm.fem.limits import LIMITS, limit_text, outside

    unit = LIMITS[name][3]
    value = parse_number(text, flag, None if unit.startswith("(") else unit)
    if outside(name, value):
        raise ValueError(f"{flag} {text}: {limit_text(name)}")
    return value


def argtype(parse, *args):
    """Wrap a ``mkm.core.ranges`` parser for argparse, keeping its one-line message."""

    def convert(text):
        try:
            return parse(text, *args)
        except ValueError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    convert.__name__ = parse.__name__
    return convert


#: One description per option that several commands take, so ``--help`` says the same thing
#: everywhere; a command adds only its default (``shared_help("--eps", "default: ...")``).
SHARED_HELP = {
    "--no-progress": "no progress on stderr: neither the bar (on a terminal) nor the status "
                     "lines (in a log or a pipe); the summary line and the result's path stay",
    "--eps": "shortening ratio, a fraction (0.05) or a percentage (5%%)",
    "--pressures": "pressures in bar: start:stop:step (stop included where the steps reach "
                   "it, never exceeded: 0:8:3 is 0, 3, 6) or a comma list (with decimal "
                   "commas, a semicolon list: 0,5;1;1,5)",
    "--D0": "inner tube diameter [mm]",
    "--t0": "wall thickness [mm]",
    "--L0": "muscle length at rest [mm]",
    "--theta0": "braid angle at rest [deg]",
    "--C10": "rubber Mooney-Rivlin C10 [MPa]",
    "--C01": "rubber Mooney-Rivlin C01 [MPa]",
}


def shared_help(option: str, extra: str = "") -> str:
    """The one description of ``option`` (:data:`SHARED_HELP`), with ``extra`` (a command's
    default) in brackets."""
    return SHARED_HELP[option] + (f" ({extra})" if extra else "")


def derived_help(build, action=argparse._StoreAction):
    """An argparse store action (or ``action``: a flag's ``argparse._StoreTrueAction``) whose
    help is ``build()``, called only when the help is shown: a choice list derived from a
    registry that lives with the library code (``OBJECTIVES`` of :mod:`mkm.design.spec`, whose
    package loads pandas and matplotlib) without loading that code for every command line,
    ``mkm --help`` included."""

    class DerivedHelp(action):
        help = property(lambda self: build(), lambda self, value: None)

    return DerivedHelp


def add_progress_argument(parser) -> None:
    """``--no-progress``, described once for every command."""
    parser.add_argument("--no-progress", action="store_true",
                        help=shared_help("--no-progress"))


def parse_workers(text: str) -> int:
    """``--workers N``, checked as the command line is read (:func:`mkm.fem.batch.check_where`),
    not at the command's first FE batch (``mkm study`` works a minute before its first)."""
    from mkm.fem.batch import check_where

    try:
        value = int(text)
        check_where(value, None)
    except ValueError as exc:
        expected = str(exc).partition("is invalid: ")[2] or "expected a whole number, at least 1"
        raise ValueError(f"--workers {text}: {expected}") from None
    return value


def add_batch_arguments(parser, also: str = "", also_default: str = "") -> None:
    """``--workers N`` / ``--scheduler ADDRESS``: where the command's FE batch runs
    (:class:`mkm.fem.batch.Runner`); ``also``: what else the command's workers bound
    (``the surrogates' training``), ``also_default``: its own default (``2 for the
    training``)."""
    what = "local worker processes for the FE solves" + (f" and {also}" if also else "")
    default = "the CPU count" + (f", {also_default}" if also_default else "")
    where = parser.add_mutually_exclusive_group()  # a cluster has its own workers
    where.add_argument("--workers", type=argtype(parse_workers), metavar="N",
                       help=f"{what}; 1 runs in-process (default: {default})")
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="run the FE solves on the Dask cluster at this scheduler, e.g. "
                       "tcp://HOST:8786 (workers need the same mkm-bench installed)")


def choices(model: str, parameter: str) -> tuple[str, ...]:
    """The values a registered model's text parameter takes (the registry declares them)."""
    return entry(model).parameters[parameter].options()


def add_model_arguments(parser, theta0: bool = True, models: tuple[str, ...] | None = None,
                        default: str | None = "eq2", default_said: str = "%(default)s",
                        L0_default: str = "default 282") -> None:
    """``--model`` and the options that set its parameters; ``models``: the registered names
    the command takes (default: every one); ``default`` None leaves the command to choose it
    (``default_said`` says how); ``L0_default``: what --help says of --L0's."""
    names = models or tuple(entries())
    parser.add_argument("--model", default=default, help=f"predictor spec: one of "
                        f"{', '.join(names)}, with :key=value parameters (see `mkm models`); "
                        f"default {default_said}")
    if theta0:
        parser.add_argument("--theta0", type=argtype(parse_within, "--theta0", "theta0_deg"),
                            help=shared_help("--theta0", "default: calibrated"))
    parser.add_argument("--diameter", choices=choices("eq2", "diameter"),
                        help="eq2 only: diameter convention (default inner, as the paper)")
    parser.add_argument("--L0", type=argtype(parse_within, "--L0", "L0_mm"),
                        help=shared_help("--L0", L0_default))
    parser.add_argument("--mesh", choices=choices("axisym", "mesh"),
                        help="axisym only: FE mesh level (default medium)")
    parser.add_argument("--braid", choices=choices("axisym", "braid"),
                        help="axisym only: fibres bonded to the rubber (default) or a "
                        "frictionless sliding sleeve")
    if "auto" in names:
        parser.add_argument("--per-point", action="store_true",
                            help="auto only: choose the model per point (default: one model "
                            "for the whole sweep, the cheapest that meets the tolerance over "
                            "all of it)")


def add_calibration_argument(parser) -> None:
    """``--calibration FILE``: the theta0 calibration file for this command (read by
    :func:`with_calibration`); the shipped ``mkm/fem/calibration.json`` is left as it is."""
    parser.add_argument("--calibration", metavar="FILE",
                        help="calibration file, the calibration.json of `mkm identify` or the "
                        "file of `mkm fem calibrate --out FILE`: the default theta0 (and rubber) "
                        "of every physics model in this command (default: the one shipped in "
                        "the package, mkm/fem/calibration.json)")


#: the default of --L0 where a --calibration may give it (:func:`identified_length`)
IDENTIFIED_L0 = "default: the length of the muscle --calibration was identified on, else 282"


def identified_length(args, takes_L0: bool = True) -> None:
    """``args.L0`` the rest length of the muscle ``--calibration`` was identified on, where
    none was given and it was identified on one length (its angle and rubber, this command's
    defaults, are that muscle's), said in a note where it is not the default 282 mm; several
    lengths are named in a note and the default length kept. Nothing for a predictor without a
    length (``takes_L0`` False)."""
    if not takes_L0 or args.L0 is not None or args.calibration is None:
        return
    from mkm.fem.paper import L0_MM
    from mkm.identify.band import identified_lengths

    lengths = identified_lengths(args.calibration)
    if len(lengths) == 1:
        args.L0 = lengths[0]
        if lengths[0] != L0_MM:  # the default's own length needs no word
            say(args, "note", f"L0 {lengths[0]:g} mm, the identified muscle's "
                "(--calibration); --L0 for another length")
    elif lengths:
        *others, last = (f"{v:g}" for v in lengths)
        say(args, "note", f"the identified muscles are {', '.join(others)} and {last} mm long: "
            f"L0 is the default {L0_MM:g} mm; --L0 for one of those lengths")


def with_calibration(func):
    """Run the command ``func(args)`` with ``args.calibration`` read once into a
    :class:`mkm.fem.calibration.Calibration` (None: the shipped one), which the command hands to
    what it builds; a file that cannot be used is one line before anything runs."""

    def run(args):
        from mkm.fem.calibration import Calibration

        path = getattr(args, "calibration", None)
        args.calibration = Calibration.load(path) if path is not None else None
        return func(args)

    run.__name__ = func.__name__
    return run


def add_muscle_arguments(parser, length: bool = False, sweep: bool = False) -> None:
    """``--D0``, ``--t0``, ``--eps`` (and ``--L0`` with ``length``), all required; with
    ``sweep`` ``--eps`` takes several shortenings too (:func:`sweep_grid`)."""
    parser.add_argument("--D0", required=True, type=argtype(parse_number, "--D0", "mm"),
                        help=shared_help("--D0"))
    parser.add_argument("--t0", required=True, type=argtype(parse_number, "--t0", "mm"),
                        help=shared_help("--t0"))
    if length:
        parser.add_argument("--L0", required=True, type=argtype(parse_within, "--L0", "L0_mm"),
                            help=shared_help("--L0"))
    parser.add_argument("--eps", required=True,
                        type=argtype(parse_shortenings if sweep else parse_fraction),
                        help=shared_help("--eps") + (
                            "; several as start:stop:step (0:20%%:5%%) or a comma list (with "
                            "decimal commas, a semicolon list: 0;0,05;0,1): "
                            "every pressure at each, a force-length curve at one pressure"
                            if sweep else ""))


def add_geometry_arguments(parser) -> None:
    """``--D0``, ``--t0``, ``--eps`` (one or several: :func:`sweep_grid`) and ``--pressures``."""
    add_muscle_arguments(parser, sweep=True)
    parser.add_argument("--pressures", default="0:2.5:0.25", type=argtype(parse_pressures),
                        help=shared_help("--pressures", "default 0:2.5:0.25"))


def sweep_grid(pressures, eps):
    """The points of ``--pressures`` x ``--eps``: one shortening gives the pressures and it as
    they are; several, every pressure at each (eps the slower), as two flat arrays."""
    import numpy as np

    if np.ndim(eps) == 0:
        return pressures, eps
    pressures, eps = np.asarray(pressures, dtype=float), np.asarray(eps, dtype=float)
    return np.tile(pressures, eps.size), np.repeat(eps, pressures.size)


def model_from_args(args, **overrides):
    """The predictor of ``--model SPEC`` with the shortcut flags (``--mesh``, ``--theta0``, ...)
    laid over the spec's own parameters; a flag the predictor does not take is an error."""
    return spec_from_args(args, **overrides).build(getattr(args, "calibration", None))


def spec_from_args(args, **overrides):
    """The :class:`mkm.registry.Spec` :func:`model_from_args` builds."""
    spec = parse_spec(args.model)
    flags = {"theta0_deg": getattr(args, "theta0", None),
             "diameter": getattr(args, "diameter", None), "L0_mm": getattr(args, "L0", None),
             "tolerance": getattr(args, "tolerance", None), "mesh": getattr(args, "mesh", None),
             "per_point": True if getattr(args, "per_point", False) else None,
             "braid": getattr(args, "braid", None)}
    flags.update(overrides)
    flags = {k: v for k, v in flags.items() if v is not None}
    unknown = sorted(set(flags) - set(spec.entry.parameters))
    if unknown:
        raise ValueError(f"--model {spec.text}: {spec.name} takes no "
                         f"{', '.join(unknown)} (its parameters: "
                         f"{', '.join(spec.entry.parameters)})")
    return spec.with_params(**flags)


def emit_prediction(prediction, out: str | None, model=None) -> None:
    """The prediction as plain CSV to ``out`` (an ``.xlsx`` workbook for a name so ending) with
    its metadata in a JSON sidecar (announced on stderr), or the CSV alone to stdout. Given the
    ``model`` that made it, the sidecar also records its code version, for a model with a
    calibrated angle which calibration gave it
    (:func:`mkm.fem.calibration.calibration_provenance`), and for a surrogate its model file's
    sha256, its training's provenance, seed and dataset."""
    if out:
        metadata = prediction_metadata(prediction)
        if model is not None:
            from mkm.fem.calibration import CalibratedTheta0, calibration_provenance
            from mkm.prediction_cache import model_origin, model_version

            metadata["model_version"] = model_version(model)
            if isinstance(model, CalibratedTheta0):
                metadata["calibration"] = calibration_provenance(model)
            metadata.update(model_origin(model))
        if Path(out).suffix.lower() == ".xlsx":
            path = write_workbook_with_sidecar(out, prediction.to_frame(), metadata)
        else:
            buffer = io.StringIO()
            write_prediction_csv(prediction, buffer)
            path = write_csv_with_sidecar(out, buffer.getvalue(), metadata)
        print(f"wrote {path} and {sidecar_path(path).name}", file=sys.stderr)
    else:
        write_prediction_csv(prediction, sys.stdout)


#: the FE model's calibration entry: the braid angle mkm design and mkm identify state
FE_KEY = "axisym"


def say_defaults(args, model, given, rubber_flags: str, prediction=None) -> None:
    """One note on stderr naming the braid angle and rubber ``model`` took where ``given`` (the
    parameter names the user set) lacks them, and where from: each rung has its own calibrated
    angle, so a muscle designed at the FE's and checked with another rung is another braid
    (Equation 2 at its 30.778 deg: 389.8 N for a 19 x 0.5 mm muscle at 6 bar, eps 0.15, that
    the FE and Equation 2 at 32.99 deg put at 301.5 and 301.2 N).
    ``rubber_flags``: how this command takes a rubber; ``prediction``: what ``model`` answered
    (its parameters, and for auto the models that answered), else ``model.params()``. Nothing
    where all were given."""
    params = model.params() if prediction is None else prediction.params
    said = _defaults_taken(model, params, set(given), prediction)
    if not said:
        return
    flags = ", ".join(["--theta0"] * any("theta0 " in s for s in said)
                      + [rubber_flags] * any("rubber " in s for s in said))
    say(args, "note", f"not given: {'; '.join(said)} ({flags} to give the muscle's own)")


def _defaults_taken(model, params: dict, given: set[str], prediction=None) -> list[str]:
    """The phrases of :func:`say_defaults` for ``model`` and the ``params`` it predicted with;
    for auto, those of each model that answered its ``prediction``."""
    from mkm.fem.calibration import Calibration

    if model.name == "auto":
        from mkm.auto import spec_of

        said = []
        for name in dict.fromkeys(str(u) for u in prediction.extras["model_used"].ravel()):
            candidate = model.build(spec_of(name, model.table), **model.muscle)
            own = _defaults_taken(candidate, candidate.params(), given)
            said += [f"by {name}, {s}" if i == 0 else s for i, s in enumerate(own)]
        return said
    surrogate = hasattr(model, "kind")  # its defaults are the FE model's (default_parameters)
    key = FE_KEY if surrogate else model.calibration_key
    calibration = getattr(model, "calibration", None) or Calibration.shipped()
    where = ("the shipped fem/calibration.json" if calibration.is_shipped
             else str(calibration.path))
    entry = calibration.entries.get(key, {})
    said = []
    theta0 = params.get("theta0_deg")
    if "theta0_deg" not in given and isinstance(theta0, int | float):
        identified = "identified" in entry
        text = (f"theta0 {theta0:g} deg, the muscle's identified with {key} ({where})"
                if identified else
                f"theta0 {theta0:g} deg, the FE model's calibrated angle ({key} in {where})"
                if surrogate else f"theta0 {theta0:g} deg, {model.name}'s own calibrated angle "
                f"({key} in {where})")
        fe = calibration.entries.get(FE_KEY, {}).get("theta0_deg")
        if not identified and fe is not None and abs(fe - theta0) > 0.005:
            text += f", not the FE model's {fe:g} deg that mkm design and mkm identify state"
        said.append(text)
    rubber = [k for k in ("C10_MPa", "C01_MPa") if k not in given and k in params]
    if rubber:
        source = (f"the identified muscle's ({key} in {where})" if "C10_MPa" in entry
                  else "Silastic S, the nominal rubber")
        said.append("rubber " + ", ".join(f"{k[:3]} {params[k]:g}" for k in rubber)
                    + f" MPa, {source}")
    return said
