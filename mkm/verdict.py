"""The report's verdict per run, in one sentence: which model to use, how far, how fast, whether
the measurement and the models agree, and why ``auto`` may pick another model.

The model to use is the cheapest (seconds per force) whose largest |Err%| against the
measurement (the paper's Equation 7) meets the tolerance at every kept step; when none does, the
closest. ``auto`` bounds a model's error against the FE model, not against a measurement
(:mod:`mkm.auto`): when its choice differs, the sentence says so, and when the model auto trusts
is further from the measurement than the tolerance, the measurement is further from the FE model
than auto's bound, which points to the muscle (its braid angle, its rubber), not to the model.
Nothing here computes a number: the inputs are the rows of :func:`mkm.scoring.summarise_run`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from mkm.paths import command_argument


def format_seconds(seconds: float) -> str:
    """A duration as a reader takes it in: ``6.10 µs``, ``12.0 ms``, ``1.40 s``, ``0.948 µs``
    (in s, ms or µs, three significant digits, never scientific notation); ``—`` when
    unknown."""
    if seconds is None or not math.isfinite(seconds) or seconds <= 0:
        return "—"
    unit, scale = next(((u, f) for u, f in (("s", 1.0), ("ms", 1e-3)) if seconds >= f),
                       ("µs", 1e-6))
    value = seconds / scale
    decimals = max(0, 2 - math.floor(math.log10(value)))
    return f"{value:.{decimals}f} {unit}"


@dataclass(frozen=True)
class AutoPick:
    """What ``auto`` chose for a run: the spec, the name shown, its error bound against the FE
    model [%] (largest over the run's points) and auto's own explanation."""

    spec: str
    name: str
    bound_pct: float
    explanation: str


def model_label(predictor: str) -> str:
    """The registry's name (:attr:`mkm.registry.Spec.display_name`) of a study predictor
    (``surrogate-muscle-gp`` -> ``Surrogate``): the one name every table and sentence uses."""
    from mkm.auto import spec_of
    from mkm.registry import parse_spec

    try:
        return parse_spec(spec_of(predictor)).display_name
    except ValueError:  # a predictor no registry entry has: its study name
        return predictor


def _fully_valid(row: dict) -> bool:
    return row["points"] > 0 and row["valid_points"] == row["points"]


def _err(row: dict) -> float:
    value = row.get("max_abs_err_pct")
    return math.inf if value is None or not math.isfinite(value) else float(value)


def recommend(summary: list[dict], tolerance: float | None) -> tuple[dict | None, bool]:
    """``(row, within)``: the cheapest model valid at every step whose largest |Err%| meets
    ``tolerance`` (a fraction), ``within`` True; else the closest model (valid at every step if
    one is, else valid somewhere), ``within`` False; ``(None, False)`` if no model is valid
    anywhere. Without a tolerance: the closest."""
    full = [r for r in summary if _fully_valid(r) and math.isfinite(_err(r))]
    if tolerance is not None:
        meets = [r for r in full if _err(r) <= 100.0 * tolerance]
        if meets:
            return min(meets, key=lambda r: (r["seconds_per_point"], _err(r))), True
    pool = full or [r for r in summary if r["valid_points"] > 0 and math.isfinite(_err(r))]
    if not pool:
        return None, False
    return min(pool, key=_err), False


#: why a run has no E_n: its steps carry no uncertainty budget
NO_BUDGET = "the run was recorded without an uncertainty budget"
#: the same for a table imported without the instruments' accuracy, and what gives it one
NO_BUDGET_IMPORTED = ("the table was imported without its instruments' accuracy (mkm import "
                      "--accuracy force=...,pressure=... gives its steps one)")


def _consistency(row: dict, summary: list[dict], no_budget: str = NO_BUDGET,
                 dynamics: bool = True) -> str:
    verdicts = [r.get("consistent") for r in summary]
    agree = sum(v is True for v in verdicts)
    judged = sum(v is not None for v in verdicts)
    if row.get("consistent") is None:
        return f"no E_n: {no_budget}" if judged == 0 else "no E_n for this model"
    others = f"{agree} of {judged} models {'is' if agree == 1 else 'are'}"
    if row["consistent"]:
        return f"consistent with the measurement (|E_n| <= 1 at every step; {others})"
    # friction and creep explain a miss only where the run can show them
    lacking = "; the models have no braid friction or creep" if dynamics else ""
    return (f"not consistent with the measurement (E_n = {row['worst_E_n']:+.1f} at step "
            f"{row['worst_step']}; {others}{lacking})")


def _closest_to_slack(summary: list[dict]) -> dict | None:
    """The model whose forces are nearest a slack run's (the smallest largest |residual| in N,
    Equation 7 having no scale there); None where no model has one."""
    rows = [r for r in summary if r.get("valid_points", 0) > 0
            and math.isfinite(r.get("max_abs_residual_N", math.nan))]
    return min(rows, key=lambda r: r["max_abs_residual_N"], default=None)


def _is_friction(spec: str) -> bool:
    """Whether a report's model ``spec`` is the friction rung (a static force with the
    calibration's braid friction and creep)."""
    from mkm.registry import parse_spec

    try:
        return parse_spec(spec).name == "friction"
    except ValueError:
        return False


def friction_explains(summary: list[dict], tolerance: float | None) -> dict | None:
    """The report's friction rung where it meets ``tolerance`` at every step (its row), else
    None: the static models' distance from the run is then the braid friction and creep it
    adds, and the calibration carries over to the run."""
    row = next((r for r in summary if _is_friction(r["model"]) and _fully_valid(r)), None)
    if row is None or tolerance is None or _err(row) > 100.0 * tolerance:
        return None
    return row


def muscle_advice(run_path: str, identified: list[dict] | None = None,
                  calibration_name: str = "", muscle_runs=(), fit: dict | None = None,
                  command_below: bool = False, at_rest_length: bool = False,
                  models=()) -> str:
    """What the FE model's distance from a run, beyond auto's bound, tells a reader: identify
    the muscle, from ``muscle_runs`` (its runs at hand, this one among them); or, where the
    report's calibration was identified (``identified``: its runs as :mod:`mkm.identify`
    records them, ``run``, ``path`` and ``muscle``), that it does not carry over to a run it did
    not see (identify with the run among the others), or, for one of its own runs, that the
    model does not fit it (no calibration would). ``fit``: the identification's record
    (calibration.json's ``identified``, its ``misfit`` and ``parameters``): an identification
    that fitted its runs within their noise did so with braid friction and creep, which the
    report's static models lack, and that is what the distance is then. ``command_below``:
    the identify command (:func:`advice_command`) is said once below the verdicts of the runs
    it concerns, so this one refers to it rather than repeating every run's path.
    ``at_rest_length``: the run is declared at its rest length and the command fits that length
    (a table's first length may be shortened already); where that fit is a misfit too (the
    published DMSP-10-250's), the calibration of the shortened runs is the one to keep.
    ``models``: the report's model specs, which the ``--models`` it suggests to add the friction
    rung to repeats."""
    command = advice_command(run_path, identified, muscle_runs, (fit or {}).get("options", ()))
    shown = "the mkm identify command below" if command_below else f"`{command}`"
    if not identified:
        runs = list(dict.fromkeys([*muscle_runs, run_path]))
        whose = "it" if len(runs) == 1 else f"it from its {len(runs)} runs here"
        return f"which points to the muscle, not the model: identify {whose} ({shown})"
    name = f" ({calibration_name})" if calibration_name else ""
    if command is None:
        misfit = (fit or {}).get("misfit") or {}
        where = "on this run" + (" with the others" if len(identified) > 1 else "")
        found = {p.get("parameter"): p.get("value") for p in (fit or {}).get("parameters", [])
                 if p.get("status") == "fitted"}
        terms = [f"{what} {100 * float(found[key]):.1f} %" for key, what in
                 (("hysteresis_fraction", "braid friction"), ("creep_fraction", "creep"))
                 if found.get(key)]
        verb = "is" if len(terms) == 1 else "are"
        models = list(models)
        rung = ("the friction rung of this report has them" if any(map(_is_friction, models))
                else "add the rung that has them: --models "
                + (",".join([*models, "friction"]) if models else "friction,..."))
        if misfit and not misfit.get("judged"):
            # a table's fit: no noise to judge it by, so no misfit to blame the distance on;
            # what it fitted beyond the static force is no miss of the identified model
            lacks = (f"the {' and '.join(terms)} identified with it, which these static models "
                     f"lack, {verb} part of this distance "
                     f"({rung}), the rest" if terms else
                     "this distance")
            return (f"although the calibration{name} was identified {where}: identify could not "
                    f"judge that fit (the runs show no noise to judge it by), and {lacks} is the "
                    "identified model's own miss: weigh it against the instruments' "
                    "accuracy (mkm import --accuracy force=...,pressure=... lets identify and "
                    "the report judge it)")
        if misfit.get("judged") and not misfit.get("misfit_branches"):
            lacks = (f"the {' and '.join(terms)} identified with it, which these static models "
                     f"lack, {verb} that distance" if terms else "these static models lack the "
                     "identified model's friction and creep")
            fits = "them within their" if len(identified) > 1 else "it within its"
            return (f"although the calibration{name} was identified {where} and fits {fits} "
                    f"noise (chi2/nu {misfit['chi2_per_nu']:.2g}): "
                    f"{lacks} ({rung}; identify's steps.csv has the steps predicted with them)")
        # a misfit of a fraction of a per cent beside a friction of several: the friction the
        # static models lack may be most of the distance
        lacks = (f", and the {' and '.join(terms)} identified with it, which these static "
                 f"models lack, {verb} part of this distance ({rung})" if terms else "")
        return (f"although the calibration{name} was identified {where}: the model does not "
                f"fit {'them all' if len(identified) > 1 else 'it'} with one muscle (the "
                f"identification's misfit notes say where){lacks}")
    return ("which points to the muscle, not the model: "
            + not_carried_over(identified, calibration_name, shown, at_rest_length))


def not_carried_over(identified: list[dict], calibration_name: str, shown: str,
                     at_rest_length: bool = False) -> str:
    """That the calibration identified on ``identified`` (its runs as :func:`muscle_advice`
    takes them) does not carry over to a run it did not see, and the identify command
    (``shown``) that takes the run among them; ``at_rest_length`` as :func:`muscle_advice`."""
    name = f" ({calibration_name})" if calibration_name else ""
    at = ", ".join(f"{r['muscle']['eps']:g}" for r in identified if "muscle" in r)
    head = (f"the calibration{name}, identified on the runs at eps {at}, does not carry over "
            "to this run")
    if at_rest_length:
        return (f"{head} at its declared rest length; a table's first length may be shortened "
                f"already: identify with it among them, its rest length fitted ({shown}); if "
                "identify calls that a misfit too (as on the DMSP-10-250's published map), no "
                "model has this run's threshold at rest length: keep the calibration for the "
                "shortened runs")
    return f"{head}; identify with it among them ({shown})"


def advice_command(run_path: str, identified: list[dict] | None = None,
                   muscle_runs=(), options=()) -> str | None:
    """The ``mkm identify`` line :func:`muscle_advice` suggests for a run (same arguments):
    the muscle's runs at hand, or the calibration's runs and those at hand it did not see,
    this one among them, with the options that identification was asked with (``options``,
    its record's: a rest length or a gap it fitted is fitted again); ``None`` for a run the
    calibration was identified on (identifying it again would not help)."""
    if not identified:
        return identify_command(*dict.fromkeys([*muscle_runs, run_path]))
    seen = {r.get("run") for r in identified}
    if Path(run_path).name in seen:
        return None
    # every run it did not see in one command: one per run would leave the others out
    unseen = [p for p in muscle_runs if Path(p).name not in seen]
    return identify_command(*[r["path"] for r in identified if "path" in r],
                            *dict.fromkeys([*unseen, run_path]), options=options)


def identify_command(*run_paths, options=()) -> str:
    """The ``mkm identify`` line a verdict suggests, each run path one argument even with a
    space in it (a Windows user folder), then ``options``."""
    return " ".join(["mkm identify", *(command_argument(str(p)) for p in
                                        (*run_paths, *options))])


def _auto_err(row: dict, summary: list[dict], names: dict[str, str], auto: AutoPick,
              auto_same: bool) -> float:
    """The largest |Err%| against the measurement of auto's pick (NaN: not in the report)."""
    measured = row if auto_same else next(
        (r for r in summary if names.get(r["model"]) == auto.name), None)
    return _err(measured) if measured is not None else math.nan


def gives_advice(summary: list[dict], names: dict[str, str], tolerance: float | None,
                 auto: AutoPick | None = None, auto_same: bool = False,
                 fe_err: tuple[str, float] | None = None) -> bool:
    """Whether :func:`verdict` (same arguments) says the muscle advice: auto's pick is further
    from the measurement than the tolerance; where its pick is not among the report's models,
    the FE model's distance ``fe_err`` less auto's bound against it is as far as it can be."""
    row = recommend(summary, tolerance)[0]
    if row is None or auto is None or tolerance is None:
        return False
    auto_err = _auto_err(row, summary, names, auto, auto_same)
    if not math.isfinite(auto_err) and fe_err is not None:
        auto_err = fe_err[1] - auto.bound_pct
    return math.isfinite(auto_err) and auto_err > 100 * tolerance


def verdict(run_label: str, summary: list[dict], names: dict[str, str],
            tolerance: float | None, auto: AutoPick | None = None,
            auto_same: bool = False, fe_err: tuple[str, float] | None = None,
            advice: str | None = None, no_budget: str = NO_BUDGET,
            dynamics: bool = True, ended: str = "") -> str:
    """The verdict sentence of one run (plain text).

    ``summary``: one :func:`mkm.scoring.summarise_run` row per model (``model`` is the spec
    text, named by ``names``), each with ``band_pct`` (the model's ± 2 u band at its worst step,
    % of the largest measured force) when it has a band. ``auto``: auto's pick at ``tolerance``,
    ``auto_same``: whether it is the recommended model. ``fe_err``: ``(name, largest |Err%|)``
    of an FE model of the report, the measurement's distance from the FE model; ``advice``:
    what that distance, beyond auto's bound, tells (:func:`muscle_advice`); ``no_budget``: why
    the run has no E_n, if it has none; ``dynamics``: whether the run can show braid friction or
    creep (a bench run's holds, a table's rising and falling branches), which the static models
    lack; ``ended``: how the run ended, its status and reason, said where it left no step.
    """
    row, within = recommend(summary, tolerance)
    if not any(r.get("points", 0) > 0 for r in summary):
        # a run stopped before its first step was recorded (Ctrl-C, SIGTERM, an interlock): no
        # model failed, there was nothing to score
        return (f"{run_label}: no step was kept, so no model can be scored: the run ended "
                "before its first step was recorded "
                f"({ended or 'its status and signals below say why'}).")
    if row is None and any(r["valid_points"] > 0 for r in summary):
        # valid forces without an error: Equation 7 divides by the largest measured force
        head = (f"{run_label}: no model can be scored: the run's largest measured force is "
                "not above 0 N or its steps' uncertainty (a slack muscle), and Equation 7's "
                "error is relative to it")
        slack_row = _closest_to_slack(summary)
        if slack_row is None:
            return head + "."
        # whether a model has the muscle slack here is what the run can still tell
        return (f"{head}; the closest to it is {names[slack_row['model']]}, at most "
                f"{slack_row['max_abs_residual_N']:.3g} N from its forces, "
                f"{_consistency(slack_row, summary, no_budget, dynamics)}.")
    if row is None:
        return f"{run_label}: no model gives a valid force at any kept step: nothing to use."
    name = names[row["model"]]
    tol = f"{100 * tolerance:g} %" if tolerance is not None else None
    band = row.get("band_pct")
    band_text = (f" (band ± {band:.1f} %)" if band is not None and math.isfinite(band)
                 else "")
    how_far = (f"{_err(row):.2f} % off at worst{band_text}, "
               f"{format_seconds(row['seconds_per_point'])} per force")
    if within:
        head = f"use {name}, the cheapest model within {tol} of the measurement: {how_far}"
    elif tol is not None:
        head = f"no model is within {tol} of the measurement; the closest is {name}, {how_far}"
    else:
        head = f"the closest model is {name}, {how_far}"
    text = f"{run_label}: {head}, {_consistency(row, summary, no_budget, dynamics)}."
    if auto is None or tol is None:
        return text
    auto_err = _auto_err(row, summary, names, auto, auto_same)
    which = "it too" if auto_same else f"{auto.name} instead"
    why = (f" auto at {tol} picks {which}, bounding its error against the FE model "
           f"({auto.bound_pct:.2f} %), not against this measurement")
    if gives_advice(summary, names, tolerance, auto, auto_same, fe_err):
        gap = (f"{fe_err[1]:.2f} %" if fe_err is not None
               else f"at least {max(auto_err - auto.bound_pct, 0.0):.2f} %")
        off = ("" if auto_same else f", from which it is {auto_err:.2f} % off"
               if math.isfinite(auto_err) else f" ({auto.name} is not among this report's models)")
        if (rung := friction_explains(summary, tolerance)) is not None:
            # the muscle agrees with the calibration: identifying it again would not help
            rung_name = names[rung["model"]]
            advice = (f"and the braid friction and creep {rung_name} adds to the static force "
                      f"are that distance ({rung_name} is {_err(rung):.2f} % off)")
        return text + (f"{why}{off}: the FE model itself is {gap} off, more than that bound, "
                       f"{advice or muscle_advice('RUN_DIR')}.")
    if auto_same:
        return text + f" auto at {tol} picks it too."
    if math.isfinite(auto_err):
        return text + (f"{why}; {auto.name} is {auto_err:.2f} % off here, also within {tol}, "
                       f"and {name} is cheaper, but auto cannot bound it within {tol} of the "
                       "FE model at every point.")
    return text + f"{why} ({auto.name} is not among this report's models)."
