"""``identify``: from bench runs of one muscle to its parameters, intervals and held-out check.

1. Search with the fast surrogate (the default's box spans theta0 28-38 deg and the rubber
   x0.5-1.5; outside it, the practical range's); where neither covers the muscle or the optimum
   lies on the box's edge, search with the FE model instead and say so.
2. Model selection: friction and creep are fitted with and without each term; the terms the
   Bayesian information criterion (BIC) of the hold residuals does not warrant are dropped.
   Where the fit with creep does not converge and creep was not asked for by name, the muscle
   is identified again without it, said in a note (:func:`creep_given_up`).
3. Confirm with the FE model (one sweep per run at the optimum): the surrogate is corrected by
   the difference the FE shows there and the fit repeated on the corrected force.
4. 95 % intervals and correlation by a bootstrap over steps (:mod:`mkm.identify.intervals`),
   with what every step shares inside: the load cell's declared tolerance, the monitor
   offset's prior, its gain and its declared hysteresis where not fitted, the declared wall
   and diameter within their tolerances
   (:func:`shared_terms`); what the runs cannot separate (a note only where it makes an
   interval wide: :data:`PRECISION`); the goodness of fit (:mod:`mkm.identify.goodness`): a
   misfit beyond the steps' noise is named in one line and widens the intervals; the
   model-form terms (:func:`model_form_terms`: the FE model against the corrected surrogate,
   the other braid) extend them.
5. The rubber: C01's share fitted as well; C10 and C01 reported apart only where the runs
   separate them (:data:`RATIO_WIDTH`, :data:`RATIO_CONDITION`; a rejected Silastic ratio
   counts with the braid known, or when the other braid cannot follow the runs at it either:
   :func:`other_braid_excess`), else one scale and a note.
6. Leave-one-run-out (and one length out, for runs of several lengths): each run predicted by
   the FE model at the parameters fitted to the others, against the nominal model (the angle
   and rubber the runs declare, else the calibration's; no friction or creep).
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import time
import warnings

import numpy as np
from scipy import optimize
from scipy.stats import chi2

from mkm.core.records import one_argument
from mkm.fem.batch import Runner
from mkm.fem.calibration import Calibration
from mkm.fem.ladder import MODELS, STATIC_FAMILIES
from mkm.fem.limits import PRACTICAL_RANGE
from mkm.fem.options import BRAIDS
from mkm.fem.paper import equation7_err_pct
from mkm.identify import fitting, goodness
from mkm.identify.fitting import GROUPS, STATIC_NAMES, Corrected, ModelStatic, SurrogateStatic
from mkm.identify.groups import DEFAULT_GROUPS, SEARCHES
from mkm.identify.intervals import (
    CONFOUNDED,
    LEVEL,
    PROFILE_RISE,
    PROFILED,
    bootstrap,
    extend,
    linear_scale,
    meets_bound,
    profile,
)
from mkm.identify.result import (
    ONE_EPS_NOTE,
    REST_EXTRAPOLATED_NOTE,
    Identification,
    ratio_profile_said,
)
from mkm.identify.runs import (
    load_runs,
    offset_bound_said,
    offset_search_bar,
    shown_effects,
    vented_beyond_bound,
)
from mkm.prediction_cache import DEFAULT_CACHE_DIR

#: a reduced candidate (friction or creep dropped), or a fit to the runs but one, that has not
#: converged after this many evaluations from the full optimum is given up
CANDIDATE_EVALUATIONS = 150
#: C10 and C01 reported apart when the 95 % interval of C01/C10 lies within this fraction of
#: it (the runs measure the ratio) or excludes Silastic S's (the runs reject the assumed one:
#: holding it would bias the rest) ...
RATIO_WIDTH = 0.25
#: ... and the static parameters' Fisher matrix (columns normalised) is this well conditioned
RATIO_CONDITION = 1e8
#: a rejected ratio also lowers chi2 by this much when freed (95 % of chi2 with one degree)
RATIO_LIKELIHOOD = float(chi2.ppf(0.95, 1))
#: the step of C01's share the FE model's column for it is differenced over (:func:`fe_ratio_test`)
RATIO_STEP = 0.05
#: the 95 % half-width above which an interval is wide (the issue's targets: theta0 within
#: 0.3 deg, the rubber within 10 %, friction within one point, the wall within 0.1 mm; the
#: rest length within 1 mm, a shortening of 0.4 % of a 250 mm muscle)
PRECISION = {"theta0_deg": 0.3, "rubber_scale": 0.10, "c01_fraction": 0.1, "t0_mm": 0.1,
             "D0_mm": 0.1, "L0_mm": 1.0, "gap_mm": 0.1, "hysteresis_fraction": 0.01,
             "creep_fraction": 0.01, "log_tau": 0.5}
#: a run declared at its rest length whose measured threshold lies this far above the fitted
#: model's is named with what can make it (:func:`_rest_length_hint`) [bar]
THRESHOLD_HINT_BAR = 0.1
#: the creep a muscle may hide in runs without timed holds (step tables, ramps), as the share
#: of its force relaxed: silicone relaxes by a few % over a minute's hold (the simulated
#: bench's default 2 %, its coverage draws up to 3 %)
UNTIMED_CREEP_FRACTION = 0.03
#: where the fitted terms start (a term at its zero bound has no gradient to leave it by)
TERM_START = {"hysteresis_fraction": 0.02, "creep_fraction": 0.01, "gap_mm": 0.2}
#: below this share of the force a creep has no time constant the runs can tell
CREEP_IDENTIFIABLE = 1e-3
#: what each braid of :data:`mkm.fem.options.BRAIDS` is, as a note says it
BRAID_SAID = {"bonded": "a braid glued to its tube", "sliding": "a sleeve free to slide on "
              "its tube"}
#: a creep over before the holds start is said to be the other braid's first where that braid
#: without it takes away at least this share of the rise of chi2 that dropping it makes
BRAID_TAKES_CREEP = 0.9
#: the refit without the creep with either braid (:func:`without_creep`) takes Gauss-Newton steps
#: until one lowers the sum of squares by less than this share of it, at most this many: each
#: step is one FE sweep per run, and a first step can overshoot (a braid whose force moves with
#: the parameters otherwise than the fitted one's: 1.5e6 after one step, 0.15 after three)
BRAID_REFIT_CONVERGED, BRAID_REFIT_STEPS = 0.01, 6
#: a creep over before the holds start is said to be the load cell's gain as well only beyond
#: this many times the cell's declared tolerance: a share of one or two tolerances is also what
#: the model's form leaves for a creep to take (a 0.14 % creep at 1 s on an exact cell,
#: bench_identify_rubbers seed 20261223), and the tolerance is already in every interval
CREEP_OR_GAIN_TOLERANCES = 3.0
#: the step in eps [fraction] the force's sensitivity to the held length is differenced over
#: (:func:`frame_hint`): about the shortening a bench's frame gives (0.5-2 mm at the cell's
#: capacity on a 150 mm muscle), over which the force is near linear in eps
FRAME_EPS_STEP = 0.01
#: a frame is named where fitting its compliance takes away at least this share of the misfit's
#: chi-square excess over its degrees of freedom (and more than a rest length declared wrong)
FRAME_TAKES = 0.5
#: a frame and fibres are both named where the chi-square each lowers differs by less than this
#: many times the fit's chi2/nu (:func:`frame_or_fibres`): the 95 % point of the chi-square of
#: one degree of freedom, the difference two fits one parameter apart show on noise alone, with
#: the misfit taken for noise the fit's chi2/nu times larger, as the intervals' Birge widening
#: takes it (the linearised refits' own chi2/nu leaves out the model error the misfit is made of)
FRAME_OR_FIBRES_CHI2 = 3.84
#: the lag [s] the force's sensitivity to a tubing lag is differenced over (:func:`lag_hint`):
#: the middle of a bench's 0.2-2 s, over which a ramp's force is near linear in its pressure
LAG_STEP_S = 0.5
#: the longest lag searched [s]: a muscle that long behind its monitor has no quasi-static bins
LAG_MAX_S = 10.0
#: a tubing lag is named where fitting it lowers the chi-square by at least this: three
#: standard deviations of one parameter's (the loop it leaves is friction's to a fit that has
#: no lag, so it may lower a chi-square already within the noise)
LAG_CHI2 = 9.0
#: the first rise's extra rubber stiffness [fraction] the force's sensitivity to it is
#: differenced over (:func:`softening_hint`): about a rubber's first-cycle softening (5-20 %)
SOFTENING_STEP = 0.1
#: the stiffest first rise searched: a rubber twice as stiff as on its repeats
SOFTENING_MAX = 1.0
#: the least first-rise stiffening named [fraction]: a rubber's first-cycle softening is 5-20 %;
#: under a tenth of that (a preconditioning that stopped a few mbar short of the top step) is
#: no procedure to change
SOFTENING_MIN = 0.005
#: without repeats, a first rise lower than the falling branch is named only where it takes at
#: least this share of the misfit's chi-square excess away (friction's loop, a monitor's
#: hysteresis part the branches too)
SOFTENING_TAKES = 0.5
#: a first-cycle softening is named where fitting it lowers the chi-square by at least this
#: (and more than a zero drifting with time does): three standard deviations of one parameter's
SOFTENING_CHI2 = 9.0


def identify(run_dirs, params: str | None = None, model: str = "axisym",
             search: str = "surrogate", surrogate=None, seed: int = 0,
             notify=lambda message: None, workers: int | None = None,
             scheduler: str | None = None, cache_dir=DEFAULT_CACHE_DIR,
             calibration: Calibration | None = None, braid: str | None = None
             ) -> Identification:
    """Identify the muscle of ``run_dirs`` (see the module docstring).

    Parameters
    ----------
    run_dirs : list of path
        Run folders of one muscle.
    params : str, optional
        Comma list of ``theta0``, ``rubber``, ``t0``, ``D0``, ``friction``, ``creep``, ``gap``,
        ``offset``, ``L0`` (default ``theta0,rubber,friction,creep,offset``: the declared wall,
        diameter and rest length taken as given, creep left out where its fit does not
        converge; given, a fit that does not converge raises :class:`RuntimeError`; the rest
        length needs runs of one length; the
        gap needs a ``model`` that takes ``gap_mm``:
        ``thickwall``, ``axisym``).
    model : str
        The static model's spec for the confirmation (and a search outside the surrogate's box):
        a registry spec taking theta0 and the rubber (``axisym``, ``axisym:mesh=coarse``,
        ``thickwall``).
    search : {"surrogate", "model"}
        Search with the surrogate (default), or with ``model`` itself (a closed form is fast).
    surrogate : SurrogateForceModel, optional
        The surrogate to search with (default: the default surrogate, or outside its box the
        practical range's, :data:`mkm.surrogate.kinds.RANGE`).
    seed : int
        Seed of the bootstrap.
    notify : callable
        Receives one line per stage.
    workers, scheduler : optional
        Where the FE sweeps run (:class:`mkm.fem.batch.Runner`): the runs' sweeps of one
        evaluation are solved side by side; one local cluster serves the whole identification.
    cache_dir : path, optional
        The FE prediction cache (:mod:`mkm.prediction_cache`): an identification repeated or
        interrupted solves only what it has not solved yet; None: no cache.
    calibration : Calibration, optional
        Where the nominal muscle's angle and rubber come from where the runs declare none
        (None: the shipped one); what is not fitted stays at the nominal muscle's.
    braid : {"bonded", "sliding"}, optional
        The muscle's braid when it is known: the confirmation model takes it and no braid
        model-form term is added (:func:`model_form_terms`). None: ``model``'s own braid, and
        the intervals carry the other braid's shift.
    """
    started = time.perf_counter()
    asked, asked_model = fitting.parse_groups(params), model
    groups = asked
    if search not in SEARCHES:
        raise ValueError(f"search={search!r} is invalid: expected one of {', '.join(SEARCHES)}")
    runs = load_runs(run_dirs)
    groups, notes = supported_groups(groups, runs)
    notes = [run.note for run in runs if run.note] + notes  # a failed run's data used: why
    if braid is not None:
        model = _with_braid(model, braid)
    with Runner(workers, scheduler) as runner:
        fe = ModelStatic(model, runner, cache_dir)
        if "gap" in groups and "gap_mm" not in fe.spec.entry.parameters:
            gapped = [e.name for e in MODELS.entries() if "gap_mm" in e.parameters
                      and e.family in STATIC_FAMILIES]
            raise ValueError(f"--params gap needs a model with a gap between tube and braid: "
                             f"--model {model!r} has none (expected one of "
                             f"{', '.join(gapped)})")
        lengths = sorted(fitting.by_length(runs))
        if "L0" in groups and len(lengths) > 1:
            raise ValueError("--params L0 fits one muscle's rest length: these runs declare "
                             f"{len(lengths)} ({', '.join(f'{v:g}' for v in lengths)} mm; "
                             "expected runs of one length, each at its own eps)")
        if "gap" in groups and dict(fe.spec.params).get("braid") == "sliding":
            # said before the search, not as its start value refused by the model
            raise ValueError(f"--params gap needs the bonded braid: {fe.name} has the sliding "
                             "sleeve, which takes no gap (expected --braid bonded and a --model "
                             "without braid=sliding)")
        try:
            result = _identify(runs, groups, fe, search, surrogate, seed, notify, started,
                               notes, calibration, braid)
        except fitting.NotConverged as exc:
            if params is not None or "log_tau" not in exc.names:
                raise  # creep asked for by name: the fit that cannot have it fails, said
            note = creep_given_up(exc)
            notify(f"the fit with creep did not converge in {exc.evaluations} evaluations: "
                   "identifying again without it")
            try:
                result = _identify(runs, tuple(g for g in groups if g != "creep"), fe, search,
                                   surrogate, seed, notify, started, [*notes, note],
                                   calibration, braid, given_up=("creep",))
            except RuntimeError as again:
                raise RuntimeError(f"without creep as with it, {again}") from exc
            # an identification advised again fits as this one did: creep named would fail it
            asked = tuple(g for g in asked if g != "creep")
        result.fe_workers = runner.describe()
    result.options = command_options(asked, asked_model, search, braid)
    return result


def command_options(groups, model: str, search: str, braid: str | None) -> list[str]:
    """The ``mkm identify`` options that fit as asked again (another run among the runs): the
    groups asked for (friction or creep left out for these runs may be told by another), and
    the model, search and braid where not the defaults."""
    options = ["--params", ",".join(groups)]
    for flag, value, default in (("--model", model, "axisym"), ("--search", search, SEARCHES[0]),
                                 ("--braid", braid, None)):
        if value != default:
            options += [flag, value]
    return options


def options_for_runs(options, run_dirs) -> list[str]:
    """``options`` (:func:`command_options`) for an identification of ``run_dirs``: its
    ``--params`` narrowed to the groups these runs can tell (:func:`supported_groups`), so a
    command advised with them fits what it names. Unchanged where the runs cannot be read or
    tell nothing asked: identify then says why itself."""
    options = list(options)
    if "--params" not in options:
        return options
    at = options.index("--params") + 1
    try:
        groups, _ = supported_groups(fitting.parse_groups(options[at]), load_runs(run_dirs))
    except (OSError, ValueError):
        return options
    return [*options[:at], ",".join(groups), *options[at + 1:]]


def with_group(options, group: str) -> list[str]:
    """``options`` (:func:`command_options`) with ``group`` among its ``--params`` (the
    default groups and it where none is given), in :data:`~mkm.identify.groups.GROUPS`'
    order."""
    options = list(options)
    if "--params" not in options:
        return [*options, "--params", ",".join((*DEFAULT_GROUPS, group))]
    at = options.index("--params") + 1
    groups = options[at].split(",")
    if group in groups:
        return options
    return [*options[:at], ",".join(g for g in GROUPS if g in (*groups, group)),
            *options[at + 1:]]


def supported_groups(groups, runs) -> tuple[tuple[str, ...], list[str]]:
    """The groups the runs can tell, and a note for each left out: friction needs a rising and
    a falling branch, creep holds of known duration (:attr:`RunData.timed`)."""
    kept, notes, shown = list(groups), [], shown_effects(runs)
    if "friction" in kept and "friction" not in shown:
        kept.remove("friction")
        notes.append("friction not fitted: no run has both a rising and a falling branch")
    if "creep" in kept and "creep" not in shown:
        kept.remove("creep")
        notes.append("creep not fitted: no run has timed holds (a step table or a ramp)")
    if "offset" in kept and not min(r.monitor_offset_bound_bar for r in runs) > 0:
        kept.remove("offset")
        notes.append("the pressure monitor's offset not fitted: a run declares it exact")
    if not kept:
        raise ValueError(f"--params {','.join(groups)}: nothing these runs can tell ("
                         + "; ".join(notes) + ")")
    return tuple(kept), notes


def creep_given_up(exc: fitting.NotConverged) -> str:
    """The note on a default creep left out because the fit with it did not converge
    (``exc``): where it stopped. A creep over before the holds start (its time constant at the
    shortest searched) scales every held force as a load cell's gain or the rubber's stiffness
    does, so nothing in the runs pins it (``bench_identify_wrong_range.py`` seed 20261622: a
    cell 2.7 % low taken for a 2.4 % creep)."""
    share, log_tau = exc.values["creep_fraction"], exc.values["log_tau"]
    low, high = exc.bounds["log_tau"]
    tau_s = float(np.exp(log_tau))
    where = ""
    if fitting.at_edge(log_tau, (low, high)) and log_tau - low <= high - log_tau:
        where = (", the shortest searched: a creep over before the holds start scales every "
                 "held force as a load cell's gain or the rubber's stiffness does, so nothing "
                 "in the runs pins it")
    elif fitting.at_edge(log_tau, (low, high)):
        where = (", the longest searched: the holds are too short to tell a creep that slow "
                 "from the rubber's stiffness")
    return (f"creep not identifiable from these runs: the fit with it on {exc.source} stopped "
            f"after {exc.evaluations} evaluations without converging, at a creep of "
            f"{100 * share:.2g} % of the force with creep_tau_s {tau_s:.4g} s{where}; fitted "
            "without creep")


def _with_braid(model: str, braid: str) -> str:
    """``model``'s spec with the braid ``braid``; ``ValueError`` when it has no braid option or
    ``braid`` is not one of :data:`mkm.fem.options.BRAIDS`."""
    from mkm.registry import parse_spec

    if braid not in BRAIDS:
        raise ValueError(f"--braid {braid!r}: expected one of {', '.join(BRAIDS)}")
    spec = parse_spec(model)
    if "braid" not in spec.entry.parameters:
        braided = [e.name for e in MODELS.entries() if "braid" in e.parameters]
        raise ValueError(f"--braid {braid}: --model {model!r} has no braid option (expected "
                         f"one of {', '.join(braided)})")
    return spec.with_params(braid=braid).text


def _covering_surrogate(runs, surrogate, notify, nominal, fits_rubber
                        ) -> tuple[SurrogateStatic | None, str | None]:
    """The surrogate to search with and a note: ``surrogate`` when given; else the default
    surrogate where its box covers the runs' muscle (its ``nominal`` rubber too:
    :meth:`~mkm.identify.fitting.SurrogateStatic.outside`), the practical range's
    (:data:`mkm.surrogate.kinds.RANGE`) where only its box does; None (search with the FE
    model) where neither does."""
    from mkm.core.durations import estimate
    from mkm.surrogate.kinds import BEST, RANGE
    from mkm.surrogate.train import cached_model, is_cached, training_task

    def load(kind):
        notify(f"loading the surrogate {kind}" if is_cached(kind) else
               f"training the surrogate {kind} on first use, "
               f"{estimate(training_task(kind))}")
        return cached_model(kind)

    first_outside = None
    for candidate in ([surrogate] if surrogate is not None else [BEST, RANGE]):
        source = SurrogateStatic(load(candidate) if isinstance(candidate, str) else candidate)
        outside = source.outside(runs, nominal, fits_rubber)
        if not outside:
            return source, (None if first_outside is None else
                            f"the default surrogate's box does not cover this muscle ("
                            f"{'; '.join(first_outside)}): searched with {source.name}, the "
                            "practical range's")
        first_outside = first_outside or outside
    return None, ("the surrogate's box does not cover this muscle (" + "; ".join(first_outside)
                  + "): searched with the FE model instead")


def _identify(runs, groups, fe, search, surrogate, seed, notify, started, notes, calibration,
              braid=None, start=None, given_up=()):
    nominal = fitting.nominal_muscle(fe.spec, runs, calibration)
    # a monitor's hysteresis where it is declared (its bound is half of that)
    names = [n for g in groups for n in GROUPS[g] if n != "pressure_hysteresis_bar"
             or min(r.monitor_hysteresis_bar for r in runs) > 0]
    notes = list(notes)
    source = fe
    if search == "surrogate" and "gap_mm" in names:
        notes.append(f"the surrogate has no gap between tube and braid: searched with {fe.name}")
    elif search == "surrogate":
        found, note = _covering_surrogate(runs, surrogate, notify, nominal,
                                          "rubber_scale" in names)
        notes += [note] if note else []
        source = fe if found is None else found
    searched = list(notes)  # what a search again with the FE model keeps of them
    declared = {n: float(runs[0].muscle[n]) for n in (*fitting.GEOMETRY, "L0_mm")}
    start = {**nominal, **{n: TERM_START.get(n, nominal.get(n, declared.get(n, 0.0)))
                           for n in names}, **(start or {})}
    if "rubber_scale" in names:
        # one scale at the ratio of the rubber the runs declare (else Silastic S's), unless the
        # runs separate C10 and C01
        if "c01_fraction" in nominal:
            start["c01_fraction"] = nominal["c01_fraction"]
        else:
            start.pop("c01_fraction", None)

    notify(f"fitting {', '.join(groups)} on {sum(len(r.steps) for r in runs)} settled steps "
           f"of {len(runs)} run(s) with {source.name}")
    best, candidates = _select(source, runs, names, start, nominal)
    if source is not fe and best.at_edge:
        notes.append(f"the optimum lies on the surrogate's box edge ({', '.join(best.at_edge)}):"
                     " searched again with the FE model, outside the box")
        # said before it starts: one sweep of every run per evaluation, where the surrogate
        # took none (minutes on a table of many steps)
        notify(f"the optimum lies on the surrogate's box edge ({', '.join(best.at_edge)}): "
               f"searching again with {fe.name} (one sweep per run and evaluation)")
        source = fe
        best, candidates = _select(source, runs, names, best.values, nominal)
    searched_with = source.name

    confirmation = {"model": fe.name}
    if source is not fe:
        notify(f"confirming the optimum with {fe.name} (one sweep per run)")
        first = best
        corrections = fitting.fe_correction(source, fe, runs, best.values)
        source = Corrected(source, corrections)
        best = fitting.fit(source, runs, best.names, best.values)
        confirmation.update({
            "largest_fe_minus_surrogate_N": float(max(np.max(np.abs(d)) for _, d in
                                                      corrections)),
            "rms_N_surrogate": _rms(first.residual_N),
            "rms_N_fe_corrected": _rms(best.residual_N),
            "shift": {n: best.values[n] - first.values[n] for n in best.names}})
    else:
        confirmation["note"] = "searched with the FE model itself"

    notify("intervals: bootstrap over steps")
    shared = shared_terms(source, runs, best)

    def resample(fit):
        return bootstrap(fit, seed=seed, **instrument_terms(runs), uniform_terms=shared)

    boot = profile_at_bounds(source, runs, best, resample(best), resample, notify)
    rubber = {"separated": False, "why": "runs at one eps: the rubber's ratio not tested"}
    assumed, said = fitting.assumed_ratio(best.values)
    terms = None
    if "rubber_scale" in best.names and len({round(r.eps, 4) for r in runs}) > 1:
        notify("does the data separate C10 and C01? (their ratio fitted too)")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            free, free_boot, rubber, free_terms, free_source = _rubber_ratio(
                source, fe, runs, best, seed, braid)
            again = _one_scale_again(free_source, source, runs, best, free, rubber)
            if again is not None:
                # the fit at the assumed ratio from the free fit's optimum, on its source,
                # fits better: the ratio freed would take the credit for the correction
                notify("the fit at the assumed rubber ratio fits better from the optimum with "
                       "the ratio free: fitted from there, and the ratio tested again")
                notes.append(f"the fit at {said} rubber ratio, started again from the optimum "
                             f"with the ratio free (C01/C10 {rubber['ratio_C01_over_C10']:.3g}) "
                             f"and the FE model's correction taken there, fits better (chi2/nu "
                             f"{goodness.assess(runs, best).reduced:.3g} -> "
                             f"{goodness.assess(runs, again).reduced:.3g}): kept (far outside its "
                             "training the surrogate's error changes fast with the parameters: "
                             "the correction taken at the first optimum did not hold at it)")
                best, source = again, free_source
                shared = shared_terms(source, runs, best)
                boot = profile_at_bounds(source, runs, best, resample(best), resample, notify)
                free, free_boot, rubber, free_terms, free_source = _rubber_ratio(
                    source, fe, runs, best, seed, braid)
        notes += _outside_box(caught)
        if (rubber.get("box_stopped") and rubber["edge_chi2_improvement"] > RATIO_LIKELIHOOD
                and goodness.assess(runs, best).misfit):
            # a misfit that freeing the ratio up to the surrogate's training box already lowers
            # as the test counts: the FE model's search has the ratio's whole range (a fit
            # within the noise, or a ratio that moves nothing up to the box, keeps the note)
            notify(f"C01's share reached the surrogate's box before the runs fixed it: the "
                   f"ratio tested with {fe.name} (one sweep per run and evaluation)")
            notes.append(f"{rubber['why']}: the ratio tested with the FE model over its whole "
                         "range")
            free, free_boot, rubber, free_terms, free_source = _rubber_ratio(
                fe, fe, runs, best, seed, braid)
        if rubber["separated"]:
            one_scale = best
            best, boot, terms, source = free, free_boot, free_terms, free_source
            ratio, (_, top) = rubber["ratio_C01_over_C10"], PRACTICAL_RANGE.C01_per_C10
            share = free.values["c01_fraction"]
            if fitting.at_edge(share, free.bounds["c01_fraction"]):
                # a Festo membrane pushes it to 9, a bench error the model absorbs so to 0:
                # fits best there, but the edge set the number, and the bootstrap collapsed on
                # it: the intervals hold the fit at the assumed ratio too
                terms = {**terms, "ratio_edge": ratio_edge_term(one_scale, free)}
                notes.append(ratio_edge_note(ratio, share, free.bounds["c01_fraction"], said))
            if ratio > top:
                notes.append(f"the identified rubber's C01/C10 {ratio:.3g} is above the "
                             f"practical range's {top:g} (`mkm models`): every model "
                             "extrapolates with it and the surrogate cannot answer for it")
        elif "why" in rubber:
            notes.append(f"C10 and C01 not separated: {rubber['why']}: one rubber scale at "
                         f"{said} ratio {assumed:.3g} assumed")
        elif rubber.get("rejects_silastic_ratio") and rubber.get("braid_in_doubt"):
            low, high = rubber["ratio_ci"]
            notes.append(f"the runs reject {said} C01/C10 (95 % interval {low:.3g}-"
                         f"{high:.3g}{ratio_profile_said(rubber)}{_box_cut(rubber)}), but a "
                         f"braid other than {fe.name}'s "
                         f"bends the curve the same way: one rubber scale kept at {said} "
                         "ratio, its interval holding the other braid's; give --braid if the "
                         "braid is known, and "
                         "C10 and C01 are reported apart")
        elif "ratio_ci" in rubber:
            low, high = rubber["ratio_ci"]
            flat = ("" if low <= assumed <= high else
                    f", yet freeing it lowers chi2 by only {rubber['chi2_improvement']:.2g}, "
                    f"under {RATIO_LIKELIHOOD:.2f}: the fits do not reject {said}")
            notes.append(f"C10 and C01 not separated by these runs (C01/C10 95 % interval "
                         f"{low:.3g}-{high:.3g}{flat}{ratio_profile_said(rubber)}"
                         f"{_box_cut(rubber)}): one rubber scale at "
                         f"{said} ratio {assumed:.3g} assumed; the C10 and "
                         "C01 written are that assumption's (the stiffness the runs fix, "
                         f"not two measured constants){_declared_holds_ratio(rubber)}")
    fitness = goodness.assess(runs, best)
    fitness.ratio_freed = ratio_freed(rubber)
    if "rubber_scale" in best.names and _box_cut_the_ratio(rubber):
        notify(f"the surrogate's box cut the test of C10 and C01: would {fe.name} separate them? "
               "(two or three sweeps per run)")
        try:
            rubber["fe_ratio_test"] = fe_ratio_test(source, fe, runs, best, braid)
        except RuntimeError as exc:  # no FE force at the ratio stepped to: nothing to advise
            rubber["fe_ratio_test"] = {"skipped": str(exc), "separates": False}
        if rubber["fe_ratio_test"]["separates"]:
            notes.append(fe_ratio_note(rubber["fe_ratio_test"], rubber, fitness, runs,
                                       command_options(groups, fe.name, "model", None)))
    if "rubber_scale" in best.names and not rubber["separated"]:
        notify("the assumed rubber ratio: refits at the ends of what the runs allow")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            rubber["assumed_ratio_terms"] = _assumed_ratio_terms(source, runs, best, rubber)
        notes += _outside_box(caught, "the refits at the ends of the assumed rubber ratio",
                              "the prediction band's rubber-ratio term is extrapolated there")
    # a group whose fit did not converge, or that was fitted and the BIC dropped, is not
    # offered as what the fit lacks: asking for it again would repeat this fit
    fitness.shown = tuple(g for g in fitness.shown if g not in given_up and g not in groups)
    if fitness.misfit and isinstance(source, Corrected) and surrogate_misfit(source, fe, runs,
                                                                             best):
        notify(f"the fit on the surrogate misfits where {fe.name} would not: identifying again "
               f"with {fe.name} (one sweep per run and evaluation)")
        return _identify(runs, groups, fe, "model", surrogate, seed, notify, started, [
            *searched, f"the fit on the surrogate corrected by the FE model misfit (chi2/nu "
            f"{fitness.reduced:.3g}) where the FE model itself would not (the surrogate's "
            "error beyond its correction at one point): searched again with the FE model"],
            calibration, braid, start={n: v for n, v in best.values.items()
                                       if n != "c01_fraction"},  # the ratio tested again
            given_up=given_up)
    # judged on the bootstrap's own interval: a misfit's widening stretches any to its bound
    cautions = []
    if creep_at_floor(runs, best, boot):
        cautions.append(creep_or_gain(runs, best, boot, None if braid_skipped(fe, best, braid)
                                      else _without_creep(source, fe, runs, best)))
    boot = goodness.widen(boot, best, fitness)
    notify("model-form terms: the FE model at the optimum (and the other braid)")
    if terms is None:
        terms = model_form_terms(source, fe, runs, best, braid)
    fitness.frame = frame_hint(source, runs, best, fitness)
    if fitness.frame:
        # a frame the misfit names: the intervals hold the muscle fitted with it as well
        terms = {**terms, "frame": {
            "kind": "one-sided", "what": f"a frame of {fitness.frame['stiffness_N_per_mm']:.3g} "
            "N/mm fitted (linearised)", "shift": fitness.frame["shift"]}}
    if fitness.fibres:
        # and the braid's fibres where they stretch in its place
        terms = {**terms, "fibres": {
            "kind": "one-sided", "what": "fibres stretching "
            f"{100 * fitness.fibres['strain_at_largest_tension']:.2g} % at the largest tension "
            "fitted (linearised)", "shift": fitness.fibres["shift"]}}
    if lag := lag_hint(source, runs, best, fitness):
        # so does a lag the ramps show: without it the fit takes its loop for friction
        terms = {**terms, "lag": {"kind": "one-sided", "what": f"a lag of {lag['tau_s']:.3g} "
                                  "s fitted (linearised)", "shift": lag.pop("shift")}}
    if softening := softening_hint(source, runs, best, fitness, lagged=lag is not None):
        # and a first rise stiffer than its repeats: the truth is the preconditioned muscle
        terms = {**terms, "softening": {
            "kind": "one-sided", "what": "a first rise of a rubber "
            f"{softening['first_rise_stiffer_pct']:.3g} % stiffer fitted (linearised)",
            "shift": softening.pop("shift")}}
    boot = extend(boot, best, terms)
    if "shift" in terms.get("creep", {}):
        notes.append(f"the intervals hold a creep of up to {100 * UNTIMED_CREEP_FRACTION:g} % "
                     "of the force, which runs without timed holds cannot fit and which pulls "
                     "the braid angle up (the model-form term creep)")
    notes += [line for line in (fitness.line(), fitness.zero_line()) if line]
    notes += [fitness.frame["said"]] if fitness.frame else []
    notes += [fitness.fibres["said"]] if fitness.fibres else []
    late = _rest_length_hint(runs, fe, best, fitness, groups)
    fitness.pulls_late = bool(late)
    notes += late
    notes += _identifiability(runs, best, boot)
    notes += profile_said(boot.get("profiled", {}), best.bounds)
    if boot.get("stretched"):
        notes.append(f"{', '.join(boot['stretched'])}: the bootstrap's 95 % range left the "
                     "estimate out (its replicates step as if a parameter resting on a bound "
                     "were free): the interval is stretched to hold it; read it as approximate")
    notes += [edge_note(name, best, source) for name in best.at_edge]
    notes += terms_at_bounds(runs, best)
    cautions += [c for c in (lag, softening) if c]
    notes += [c["said"] for c in cautions]
    offset = best.values.get("pressure_offset_bar")
    if "pressure_offset_bar" in best.names and fitting.at_edge(
            offset, best.bounds["pressure_offset_bar"]):
        # a table's user has no monitor to check, only the zero the table's pressures hold
        check = ("check the zero of the table's pressures" if all(r.imported for r in runs)
                 else "check the monitor's zero")
        notes.append(f"the pressure monitor's offset ({offset:+.3g} bar) is at "
                     f"{offset_bound_said(runs)}: the runs' threshold wants more than the "
                     f"monitor may be off; {check}, or the model does not fit these runs near "
                     "the threshold")
    notes += [line for line in (_zero_said(runs, best, boot), _zero_unpinned(best, boot))
              if line]
    if "force_zero_N" in best.names and fitting.at_edge(best.values["force_zero_N"],
                                                        best.bounds["force_zero_N"]):
        low, high = best.bounds["force_zero_N"]
        notes.append(f"the load cell's zero ({best.values['force_zero_N']:+.3g} N) is at the "
                     f"edge of its search ({low:+.3g} to {high:+.3g} N, "
                     f"{fitting.ZERO_SEARCH_FRACTION:.0%} of the largest force read): more "
                     "than a tare left out; check the cell and the table's forces, or the "
                     "model does not fit these runs")
    notes += [line for line in (vented_beyond_bound(runs),) if line]

    notify("leave-one-run-out and the nominal model")
    checks = _checks(runs, fe, source, best, nominal)
    failed = [(c["run"], c.get("heldout_failed") or c["length_heldout_failed"]) for c in checks
              if "heldout_failed" in c or "length_heldout_failed" in c]
    if failed:
        notes.append(f"held out, {', '.join(run for run, _ in failed)} could not be predicted "
                     f"from the other runs (they do not fix {', '.join(best.names)} together): "
                     f"{failed[0][1]}")
    single = [c["run"] for c in checks if "heldout" in c and len(
        {round(r.eps, 4) for r in runs if r.name != c["run"]}) == 1]
    if single and {"theta0_deg", "rubber_scale"} <= set(best.names):
        which = (f"run {single[0]} is" if len(single) == 1
                 else f"runs {', '.join(single)} are each")
        notes.append(f"when held out, {which} predicted from runs at a single eps, where theta0 "
                     "and the rubber are confounded: the held-out error shows what one eps "
                     "cannot tell, not the error of the fit to every run")
    return Identification(
        runs=runs, groups=groups, fit=best, bootstrap=boot, candidates=candidates,
        confirmation=confirmation, checks=checks, notes=notes, model=fe.name,
        searched_with=searched_with, nominal=nominal, seconds=time.perf_counter() - started,
        goodness=fitness, rubber=rubber, model_form=terms, instrument_warnings=cautions)


def terms_at_bounds(runs, best) -> list[str]:
    """A line for each friction or creep term the fit left on a bound of its search
    (:data:`~mkm.identify.fitting.TERM_BOUNDS`; ``best.at_edge`` holds the static parameters
    alone), saying what the bound means: a creep time constant at the longest searched is one
    the holds are too short to tell, at the shortest one over before they start; a friction or
    creep share at the largest more than the model's term holds. A share at 0 is no term (the
    creep's time constant then is said unidentifiable: :func:`_identifiability`)."""
    lines = []
    if "log_tau" in best.names and best.values["creep_fraction"] >= CREEP_IDENTIFIABLE:
        low, high = best.bounds["log_tau"]
        tau_s, (low_s, high_s) = float(np.exp(best.values["log_tau"])), np.exp([low, high])
        searched = f"its search is {low_s:.4g} to {high_s:.4g} s"
        if fitting.at_edge(best.values["log_tau"], (low, high)):
            if tau_s > np.sqrt(low_s * high_s):
                holds = [float((r.steps["end_s"] - r.steps["hold_start_s"]).max())
                         for r in runs if r.timed and len(r.steps)]
                longest = f" (the longest {max(holds):.3g} s)" if holds else ""
                lines.append(f"creep_tau_s is {tau_s:.4g} s, the longest searched ({searched}): "
                             f"the runs' holds{longest} are too short to tell the time "
                             "constant, only that it is long beside them, and its interval "
                             "is the search's; hold each step longer (settle.hold_s) to "
                             "measure it")
            else:
                lines.append(f"creep_tau_s is {tau_s:.4g} s, the shortest searched ({searched}): "
                             "the creep is over before the holds start, so they do not tell "
                             "the time constant, only that it is short")
    for name, what in (("hysteresis_fraction", "friction"), ("creep_fraction", "creep")):
        if name in best.names:
            low, high = best.bounds[name]
            value = best.values[name]
            if high - value <= fitting.EDGE_FRACTION * (high - low):
                lines.append(f"{name} is {value:.3g}, the largest searched ({low:g} to "
                             f"{high:g}): the runs ask for more {what} than the model's term "
                             "holds; it does not fit these runs")
    return lines


def creep_at_floor(runs, best, boot) -> bool:
    """Whether the fitted creep may be over before the holds start and is too large to be the
    model's form: its time constant, or its bootstrap interval (before a misfit widens it), at
    the shortest searched, and its share beyond :data:`CREEP_OR_GAIN_TOLERANCES` times the
    load cell's declared tolerance (and :data:`CREEP_IDENTIFIABLE`)."""
    if "log_tau" not in best.names:
        return False
    bounds = best.bounds["log_tau"]
    low, _ = boot["interval"]["log_tau"]
    short = any(fitting.at_edge(v, bounds) and v - bounds[0] <= bounds[1] - v
                for v in (best.values["log_tau"], low))
    tolerance = max(r.sensitivity_tolerance for r in runs)
    return short and best.values["creep_fraction"] >= max(
        CREEP_IDENTIFIABLE, CREEP_OR_GAIN_TOLERANCES * tolerance)


def _without_creep(source, fe: ModelStatic, runs, best) -> dict:
    """The creep dropped with the braid fitted and with the other one
    (:func:`without_creep`): the braids' names and the rise of chi2 with each, and what the
    refits cost: the model sweeps they made (one per run and evaluation; the fitted braid's
    are the search's source's, none where that is a surrogate) and their seconds."""
    other = _other_braid(fe)
    started, fe_calls = time.perf_counter(), fe.calls
    rises = {"braid": _braid_of(other), "fitted_braid": _braid_of(fe),
             "chi2_rise": without_creep(source, fe, runs, best, other),
             "fitted_braid_chi2_rise": without_creep(source, fe, runs, best, fe)}
    return {**rises, "sweeps": other.calls + fe.calls - fe_calls,
            "seconds": round(time.perf_counter() - started, 3)}


def creep_or_gain(runs, best, boot, other_braid: dict | None = None) -> dict:
    """The warning where the runs cannot tell the fitted creep from the load cell's gain
    (:func:`creep_at_floor`): a creep over before the holds start lowers every held force as
    a cell reading that share low from its first sample does (``bench_identify_wrong_range.py``
    seed 20261601: a cell 1.75 % low fitted as a 1.73 % creep at 1 s, within the noise,
    theta0 0.03 deg outside its interval).

    ``other_braid`` (:func:`_without_creep`, where the braid is in doubt): where the other
    braid without the creep takes away at least :data:`BRAID_TAKES_CREEP` of the rise of chi2
    that dropping the creep with the fitted braid makes, the braid is named first: a sleeve
    sliding on its tube pulls less than a bonded braid by a share of every force, which a fit
    with the bonded braid takes as such a creep (``bench_identify_wrong_range.py`` seed
    20261615: a sliding sleeve fitted as a 5.7 % creep at 1 s, within the noise, on an exact
    cell), and a braid is a likelier cause than a cell that many times off its tolerance.
    Where it does not, the note says so."""
    share = best.values["creep_fraction"]
    tolerance = max(r.sensitivity_tolerance for r in runs)
    low, high = boot["interval"]["log_tau"]
    bounds = best.bounds["log_tau"]
    tau_s, shortest_s = float(np.exp(best.values["log_tau"])), float(np.exp(bounds[0]))
    percent = f"{100 * share:.2g} %"
    check = ("check the calibration of the load cell that recorded them"
             if all(r.imported for r in runs) else "calibrate the load cell (mkm "
             "calibrate-loadcell)")
    advice = (f"if this muscle is not expected to creep by {percent}, {check} and identify "
              "again")
    creep = (f"the fitted creep, {percent} of the force with creep_tau_s {tau_s:.3g} s (the "
             f"runs allow {shortest_s:.4g} s, the shortest searched), may be over before the "
             "holds start, and such a creep is, to these runs, the load cell reading "
             f"{percent} low from its first sample (its declared tolerance "
             f"+-{100 * tolerance:g} %)")
    warning = {"what": "creep or load cell gain", "creep_fraction": share, "creep_tau_s": tau_s,
               "creep_tau_s_bootstrap_ci": [float(v) for v in np.exp([low, high])],
               "loadcell_reads_low_fraction": share, "sensitivity_tolerance": tolerance}
    if other_braid is None:
        return {**warning, "verdict": (
            f"these runs cannot tell a creep of {percent} over before the holds start from a "
            f"load cell reading {percent} low (the note above): {advice}"), "ready_if": "if it is",
            "said": f"creep or load cell: {creep}: they cannot tell the two apart; {advice}"}
    other, fitted = other_braid["braid"], other_braid["fitted_braid"]
    rises = (f"dropping the creep raises chi2 by {other_braid['fitted_braid_chi2_rise']:.3g} "
             f"with the {fitted} braid, by {other_braid['chi2_rise']:.3g} with the {other} one "
             "(refits evaluated with each braid)")
    warning["other_braid"] = other_braid
    if other_braid["chi2_rise"] > (1 - BRAID_TAKES_CREEP) * other_braid[
            "fitted_braid_chi2_rise"]:
        return {**warning, "verdict": (
            f"these runs cannot tell a creep of {percent} over before the holds start from a "
            f"load cell reading {percent} low (the note above): {advice}"), "ready_if": "if it is",
            "said": (f"creep or load cell: {creep}: they cannot tell the two apart, and the "
                     f"{other} braid does not take the creep's place ({rises}); {advice}")}
    braid_advice = (f"if the muscle's braid is {other} ({BRAID_SAID[other]}), identify again "
                    f"with --braid {other}; if it is {fitted} and this muscle is not expected "
                    f"to creep by {percent}, {check} and identify again")
    return {**warning, "what": "braid, creep or load cell gain", "verdict": (
        f"these runs cannot tell a {other} braid from a creep of {percent} over before the "
        f"holds start or a load cell reading {percent} low (the note above): {braid_advice}"),
        "ready_if": f"if it is {fitted} and does creep so",
        "said": (f"braid, creep or load cell: {creep}; but the {other} braid follows them "
                 f"without the creep ({rises}): {BRAID_SAID[other]} pulls a share of every "
                 f"force {'less' if other == 'sliding' else 'more'} than {BRAID_SAID[fitted]}, "
                 "as that creep does, and is a likelier cause than a load cell "
                 f"{share / tolerance:.3g} times its declared tolerance off; {braid_advice}")}


def _rest_length_hint(runs, fe, best, fitness, groups) -> list[str]:
    """Where the fit misses (or is not judged) and a run declared at its rest length pulls only
    above a threshold the fitted model does not have (:data:`THRESHOLD_HINT_BAR` above it):
    what does that, and the ``--params`` that fit it."""
    if (fitness.judged and not fitness.misfit) or {"L0_mm", "gap_mm"} & set(best.names):
        return []
    notes = []
    for run in runs:
        if run.eps > 0:
            continue
        row = goodness.threshold_row(run, fe, best.values)
        fitted, measured = row["fitted threshold [bar]"], row["measured threshold [bar]"]
        if measured - fitted > THRESHOLD_HINT_BAR:
            given = ",".join(groups)
            notes.append(f"run {run.name}, declared at its rest length, pulls only above "
                         f"{measured:.2f} bar (the line through its steps), the fitted model "
                         f"from {fitted:.2f} bar: its length may be shorter than the muscle's "
                         "rest length (a table that starts already shortened, a length "
                         "measured under load), or the tube may stand off the braid; fit the "
                         f"rest length (--params {given},L0) or a gap (--params {given},gap, "
                         "with --model thickwall or axisym)")
    return notes


def frame_hint(source, runs, best, fitness) -> dict | None:
    """Where the fit misfits: whether a frame yielding under the muscle's pull explains it.

    A frame (fixtures, load cell) of compliance ``c`` [mm/N] holds the muscle at ``eps + F c /
    L0``: its static force moves by ``dF/deps F c / L0``, a column from one more sweep per run at
    ``eps`` + :data:`FRAME_EPS_STEP`. Fitted with ``c >= 0`` through a linearised refit of the
    fit's own parameters (:func:`_refitted`), against a rest length declared wrong (``dF/deps
    dL / L0``, either sign; where the fit leaves ``L0`` out), which looks alike at one eps but
    not across eps and pressures. Named (a record with its note, ``said``, and the refit's
    ``shift`` of every fitted parameter with the frame, the model-form term ``frame`` of the
    intervals) where the frame takes :data:`FRAME_TAKES` of the chi-square's excess away and
    more than the rest length does; else None. What the check cost (its model and sweeps) is
    ``fitness.frame_check``, with the stiffness it fits and how far it and a rest length lower
    chi2, named or not.

    Against a braid whose fibres stretch under their tension as well (:func:`_fibres_column`,
    one more sweep per run), which also holds the muscle further contracted the harder it
    pulls, but by the fibres' tension, which the pressure's end load keeps up where the pull
    is small: where the fibres lower the chi-square more than the frame, on the frame's terms,
    they are named instead, in ``fitness.fibres`` (their strain at the largest tension, E A,
    the note and the refit's ``shift``, the model-form term ``fibres``), and the frame is not.
    Where the two lower it within :data:`FRAME_OR_FIBRES_CHI2` times the fit's chi2/nu of each
    other, the data do not tell them apart and both are named (:func:`frame_or_fibres`), each
    record ``told_from_*`` False, the threshold ``frame_check``'s
    ``frame_or_fibres_within_chi2``.
    """
    if not fitness.misfit or not fitness.judged:
        return None
    tables = source.tables(runs, best.values)
    top_N = max(float(np.max(F)) for _, F in tables)
    if not top_N > 0:
        return None
    shifted = [dataclasses.replace(run, muscle={**run.muscle, "eps": run.eps + FRAME_EPS_STEP})
               for run in runs]
    fitness.frame_check = {"model": source.name, "sweeps": len(runs)}
    # the force's change when the held length shortens by FRAME_EPS_STEP (at the largest force,
    # for the frame): never below the force itself, so no table is clipped at zero
    steps = [(grid, np.interp(grid, *moved) - F) for (grid, F), moved in
             zip(tables, source.tables(shifted, best.values), strict=True)]
    frame = _hold_change(source, runs, best, [(grid, dF * F / top_N) for (grid, dF), (_, F)
                                              in zip(steps, tables, strict=True)])
    length = _hold_change(source, runs, best, steps)
    fibres = _fibres_column(source, runs, best, tables)
    if fibres is not None:
        fitness.frame_check["sweeps"] += len(runs)

    def refit_chi2(column, shift: float) -> float:
        """All steps' chi-square after the linearised refit with ``column`` at ``shift`` of
        eps (at the largest force, for the frame)."""
        moved = _refitted(best, best.residual_N + shift / FRAME_EPS_STEP * column)
        return goodness.assess(runs, dataclasses.replace(best, residual_N=moved)).chi2

    # the linearised refit alone, the base both are compared with (the fit minimises every
    # hold sample's residual, not the steps' chi-square)
    base = refit_chi2(frame, 0.0)
    # up to a tenth of the muscle's length
    at_top = optimize.minimize_scalar(lambda e: refit_chi2(frame, e), bounds=(0.0, 0.1),
                                      method="bounded", options={"xatol": 1e-6}).x
    with_frame = refit_chi2(frame, at_top)
    rest = (math.inf if "L0_mm" in best.names else
            optimize.minimize_scalar(lambda e: refit_chi2(length, e), bounds=(-0.1, 0.1),
                                     method="bounded", options={"xatol": 1e-6}).fun)
    lowered, rest_lowered = base - with_frame, base - rest
    if fibres is not None:
        column, top_tension_N = fibres
        strain = optimize.minimize_scalar(lambda e: refit_chi2(column, e), bounds=(0.0, 0.1),
                                          method="bounded", options={"xatol": 1e-6}).x
        with_fibres = refit_chi2(column, strain)
        fibres_lowered = base - with_fibres
    # the shift is eps at the largest force: of the run that pulls it
    L0_mm = max((float(np.max(F)), float(run.muscle["L0_mm"]))
                for (_, F), run in zip(tables, runs, strict=True))[1]
    compliance = at_top * L0_mm / top_N
    # the check's own numbers, named or not: why a frame was not named is in the record
    fitness.frame_check.update(
        fitted_stiffness_N_per_mm=float(f"{1.0 / compliance:.3g}") if at_top > 0 else None,
        chi2_linearised=round(float(base), 3), chi2_lowered=round(float(lowered), 3),
        **({} if "L0_mm" in best.names else
           {"rest_length_chi2_lowered": round(float(rest_lowered), 3)}),
        **({} if fibres is None else
           {"fibre_strain_at_largest_tension": float(f"{strain:.3g}"),
            "fibres_chi2_lowered": round(float(fibres_lowered), 3)}))
    named = frame_or_fibres(
        {"frame": lowered if at_top > 0 else -math.inf,
         "fibres": fibres_lowered if fibres is not None and strain > 0 else -math.inf},
        rest_lowered, base, fitness)
    tied = len(named) == 2
    if tied:
        fitness.frame_check["frame_or_fibres_within_chi2"] = round(
            float(FRAME_OR_FIBRES_CHI2 * fitness.reduced), 3)
    table = published_table(runs)
    if "fibres" in named:
        rest_said = ("" if "L0_mm" in best.names else
                     f" and a rest length declared wrong by {rest_lowered:.3g}")
        within = with_fibres <= fitness.nu
        check = fibres_advice(table, tied)
        apart = (f"; they lower it within {FRAME_OR_FIBRES_CHI2 * fitness.reduced:.3g} of each "
                 f"other ({FRAME_OR_FIBRES_CHI2:g} times the fit's chi2/nu), so the data do not "
                 "tell the fibres from the frame (the note above): the intervals hold the "
                 f"muscle fitted with either (the model-form terms frame and fibres); {check}"
                 if tied else
                 "; the intervals hold the muscle fitted with it (the model-form term fibres); "
                 + check)
        fitness.fibres = {
            "strain_at_largest_tension": float(f"{strain:.3g}"),
            "largest_tension_N": float(f"{top_tension_N:.4g}"),
            "EA_N": float(f"{top_tension_N / strain:.3g}"),
            "chi2_lowered": round(float(fibres_lowered), 3),
            "chi2_per_nu": round(float(with_fibres / fitness.nu), 3),
            "frame_chi2_lowered": round(float(lowered), 3),
            **({} if "L0_mm" in best.names else
               {"rest_length_chi2_lowered": round(float(rest_lowered), 3)}),
            **({"told_from_frame": False} if tied else {}),
            "said": (f"fibres: the braid's fibres stretching under their tension (about "
                     f"{100 * float(f'{strain:.3g}'):.2g} % at the largest, "
                     f"{top_tension_N:.4g} N along them all: E A about "
                     f"{top_tension_N / strain:.3g} N) hold it as a braid of longer fibres, "
                     "further contracted the harder it pulls and the higher the pressure: "
                     f"fitting that (linearised) lowers chi2 by {fibres_lowered:.3g} "
                     f"(chi2/nu {with_fibres / fitness.nu:.3g}"
                     f"{', within the noise' if within else ''}), where a frame yielding under "
                     f"the pull lowers it by {lowered:.3g}{rest_said}{apart}"),
            **({} if table is None else {"published_table": table}),
            "shift": {n: float(v) for n, v in zip(
                best.names, _step(best, strain / FRAME_EPS_STEP * column), strict=True)}}
    if "frame" not in named:
        return None
    stiffness = 1.0 / compliance
    within = with_frame <= fitness.nu
    rest_said = ("" if "L0_mm" in best.names else
                 f", where a rest length declared wrong lowers it by {rest_lowered:.3g}")
    shift = _step(best, at_top / FRAME_EPS_STEP * frame)
    fix = ("stiffen the frame or measure its stiffness, or measure the muscle's held length "
           "under load, and identify again" if table is None else
           f"{table} was measured on its authors' bench, whose frame may have yielded so and "
           "which no one here can stiffen or measure: calibration.json then predicts the "
           "muscle together with that frame, and held at its declared length by a stiffer one "
           "the muscle pulls more, the more the harder it pulls (the intervals hold it); ask "
           "the table's authors for their frame's stiffness or the held lengths under load, "
           "else predict with the intervals")
    return {"stiffness_N_per_mm": float(f"{stiffness:.3g}"),
            "yield_at_largest_force_mm": float(f"{top_N * compliance:.3g}"),
            "chi2_lowered": round(float(lowered), 3),
            "chi2_per_nu": round(float(with_frame / fitness.nu), 3),
            **({} if "L0_mm" in best.names else
               {"rest_length_chi2_lowered": round(float(rest_lowered), 3)}),
            **({"told_from_fibres": False} if tied else {}),
            "said": (f"frame: a frame, fixtures or load cell yielding under the muscle's pull "
                     f"(about {stiffness:.3g} N/mm, {top_N * compliance:.3g} mm at the largest "
                     f"force, {top_N:.4g} N) holds it shorter than declared, more the more it "
                     f"pulls: fitting that (linearised) lowers chi2 by {lowered:.3g} (chi2/nu "
                     f"{with_frame / fitness.nu:.3g}"
                     f"{', within the noise' if within else ''}){rest_said}; the intervals "
                     "hold the muscle fitted with it (the model-form term frame); "
                     + ("the braid's fibres stretching fit as well (the next note)" if tied
                        else fix)),
            **({} if table is None else {"published_table": table}),
            "shift": {n: float(v) for n, v in zip(best.names, shift, strict=True)}}


def fibres_advice(table: str | None, tied: bool) -> str:
    """What the ``fibres:`` note says to do about stretching fibres (``tied``: with a frame the
    data do not tell them from): measure them on the bench the runs were measured on, or, runs
    of a published ``table`` (:func:`published_table`), whose bench and braid are its authors',
    ask them."""
    if table is not None:
        asked = "their frame's stiffness and their braid's fibres" if tied else (
            "their braid's fibres (a strand's force over its strain, times the strands)")
        return (f"{table} was measured on its authors' bench and braid: ask them for {asked}, "
                "else predict with the intervals")
    if tied:
        return ("check the frame's stiffness and measure the fibres (a strand's force over its "
                "strain, times the strands), then identify again")
    return ("measure the braid's fibres (a strand's force over its strain, times the strands) or "
            "use a stiffer braid, and check the frame's stiffness, then identify again")


def published_table(runs) -> str | None:
    """The published table (``mkm data``) every run was imported from
    (:attr:`mkm.identify.runs.RunData.published`), or None: some run was measured here."""
    tables = {run.published for run in runs}
    return tables.pop() if len(tables) == 1 else None


def frame_or_fibres(lowered: dict[str, float], rest_lowered: float, base: float,
                    fitness) -> tuple[str, ...]:
    """What the frame check names: of ``"frame"`` and ``"fibres"``, by how far each lowers the
    linearised refit's chi-square ``base`` (``lowered``, -inf where its fit is at zero), none,
    one, or both where the data do not tell them apart.

    The better one is named where it takes :data:`FRAME_TAKES` of the chi-square's excess over
    ``fitness.nu`` away and more than a rest length declared wrong (``rest_lowered``); the
    other beside it where it lowers chi2 more than the rest length and within
    :data:`FRAME_OR_FIBRES_CHI2` times the fit's chi2/nu (``fitness.reduced``) of the better."""
    better = max(lowered.values())
    if not (base > fitness.nu and better > rest_lowered
            and better >= FRAME_TAKES * (base - fitness.nu)):
        return ()
    return tuple(name for name, chi2 in lowered.items() if chi2 > rest_lowered and (
        better - chi2 < FRAME_OR_FIBRES_CHI2 * fitness.reduced))


def _fibres_column(source, runs, best, tables):
    """The change of the hold residuals [N] when the braid's fibres stretch by
    :data:`FRAME_EPS_STEP` at the largest tension and by their share of it elsewhere, and that
    tension [N]; None where the fit has the tube's geometry or rest length, or no angle.

    One sweep per run of the braid of fibres that much longer
    (:func:`mkm.fem.thickwall.stretched_braid`); their tension at each pressure is the pull
    and the pressure's end load along them at the fitted angle
    (:func:`mkm.fem.thickwall.fibre_tension_N`)."""
    from mkm.fem.thickwall import fibre_tension_N, stretched_braid

    if {"D0_mm", "t0_mm", "L0_mm"} & set(best.names) or "theta0_deg" not in best.values:
        return None
    theta0_deg = float(best.values["theta0_deg"])
    tensions = [fibre_tension_N(F, grid, *run.geometry, theta0_deg)
                for (grid, F), run in zip(tables, runs, strict=True)]
    top_N = max(float(np.max(T)) for T in tensions)
    if not top_N > 0:
        return None
    stretched = []
    for run in runs:
        D0_mm, t0_mm, eps = run.geometry
        D0_at_mm, eps_at = stretched_braid(D0_mm, t0_mm, eps, FRAME_EPS_STEP)
        stretched.append(dataclasses.replace(run, muscle={**run.muscle, "D0_mm": D0_at_mm,
                                                          "eps": eps_at}))
    changes = [(grid, (np.interp(grid, *moved) - F) * T / top_N) for (grid, F), moved, T in
               zip(tables, source.tables(stretched, best.values), tensions, strict=True)]
    return _hold_change(source, runs, best, changes), top_N


def lag_hint(source, runs, best, fitness) -> dict | None:
    """Where imported ramps are judged: whether the force trails the monitored pressure, as a
    muscle filled through tubing behind the monitor does.

    A first-order lag ``tau`` puts the muscle's pressure at the monitor's less its rate times
    ``tau``: each bin's static force moves by its slope times that, a column from one trace at
    :data:`LAG_STEP_S`, fitted with ``tau >= 0`` through a linearised refit of the fit's own
    parameters (:func:`_refitted`). The loop it leaves between the branches is as wide in
    pressure at every force, where friction's grows with the force: a fit without the lag
    takes it for friction, and its chi-square may stay within the noise. Named (an instrument
    warning: its record, note ``said`` and ``verdict``) where the lag lowers the chi-square by
    :data:`LAG_CHI2`, with the refit's ``shift`` of every fitted parameter, the model-form term
    ``lag`` of the intervals; else None. A held step has caught up with its tubing: only ramps
    see a lag."""
    ramps = [run for run in runs if run.ramp_rate_bar_per_s is not None]
    if not fitness.judged or not ramps:
        return None
    column = _on_holds(runs, fitting.traces(source, runs, best.values, LAG_STEP_S),
                       fitting.traces(source, runs, best.values))
    if not np.any(column):
        return None

    def refit_chi2(tau_s: float) -> float:
        moved = _refitted(best, best.residual_N + tau_s / LAG_STEP_S * column)
        return goodness.assess(runs, dataclasses.replace(best, residual_N=moved)).chi2

    base = refit_chi2(0.0)
    tau_s = optimize.minimize_scalar(refit_chi2, bounds=(0.0, LAG_MAX_S), method="bounded",
                                     options={"xatol": 1e-4}).x
    with_lag = refit_chi2(tau_s)
    lowered = base - with_lag
    if not (tau_s > 0 and lowered >= LAG_CHI2):
        return None
    rate = max(float(np.max(np.abs(run.ramp_rate_bar_per_s))) for run in ramps)
    friction, record = "", {}
    step = _step(best, best.residual_N + tau_s / LAG_STEP_S * column)
    if "hysteresis_fraction" in best.names:
        fitted = best.values["hysteresis_fraction"]
        with_it = max(fitted + float(step[best.names.index("hysteresis_fraction")]), 0.0)
        friction = (f"; the fitted friction, {fitted:.3g}, is {with_it:.3g} with the lag: "
                    "the rest of its loop is the lag's, not the braid's")
        record["hysteresis_fraction_with_lag"] = float(f"{with_it:.3g}")
    advice = ("ramp slower, read the pressure at the muscle, or hold the steps, and identify "
              "again")
    return {"what": "lag between monitor and muscle",
            "tau_s": float(f"{tau_s:.3g}"), "trail_bar": float(f"{tau_s * rate:.3g}"),
            "fastest_ramp_bar_per_s": float(f"{rate:.3g}"),
            "chi2_lowered": round(float(lowered), 3),
            "chi2_per_nu": round(float(with_lag / fitness.nu), 3), **record,
            "said": (f"lag: the force trails the pressure by about {tau_s:.2g} s "
                     f"({tau_s * rate:.2g} bar on the fastest ramp, {rate:.2g} bar/s): a lag "
                     "between the monitor and "
                     "the muscle (tubing, a monitor at the regulator), whose loop between the "
                     "branches is not friction: fitting it (linearised) lowers chi2 by "
                     f"{lowered:.3g} (chi2/nu {with_lag / fitness.nu:.3g}){friction}; the "
                     f"intervals hold the muscle fitted with it (the model-form term lag); "
                     f"{advice}"),
            "verdict": (f"the force trails the pressure by about {tau_s:.2g} s, a lag between "
                        f"the monitor and the muscle, not friction (the note above): {advice}"),
            "ready_if": "for the braid angle and rubber (not the friction)",
            "shift": {n: float(v) for n, v in zip(best.names, step, strict=True)}}


def first_rise(run) -> tuple[np.ndarray, np.ndarray]:
    """Per step of ``run``: whether it is on the run's first rise (its steps up to the first
    that is not above the one before), where the run goes on past it; and whether a later
    rising step repeats its set pressure."""
    direction = run.steps["direction"].to_numpy()
    set_bar = run.steps["set_pressure_bar"].to_numpy(dtype=float)
    rising = (direction == "up") & np.r_[True, set_bar[1:] > set_bar[:-1]]
    end = int(np.argmin(rising)) if not rising.all() else rising.size
    first = np.zeros(set_bar.size, dtype=bool)
    first[:end] = end < set_bar.size
    later = set_bar[end:][direction[end:] == "up"]
    repeated = np.zeros_like(first)
    if later.size:
        repeated = first & np.isclose(set_bar[:, None], later[None, :], rtol=0.0,
                                      atol=1e-6).any(axis=1)
    return first, repeated


def softening_hint(source, runs, best, fitness, lagged: bool = False) -> dict | None:
    """Whether the first rise pulls less than the repeats at the same pressures, as a rubber
    that softens on its first loading does (the Mullins effect: a muscle not preconditioned is
    stiffer on its first rise to a new highest pressure than on every later one); where no run
    repeats its staircase, less than the falling branch beyond the fitted friction.

    The first rise's rubber ``1 + a`` times as stiff moves its holds' force by a column from one
    trace at :data:`SOFTENING_STEP` (the holds of its steps a later rise repeats, where any
    does, else of all of them; zero elsewhere), fitted with ``a >= 0`` through a linearised
    refit of the fit's own parameters (:func:`_refitted`); friction and creep, the same on
    every rise, are the fit's. A zero drifting with time (a column of each hold's time, either
    sign) also parts the first rise from what follows it. Named (its record, note ``said``,
    ``verdict`` and the refit's ``shift`` of every fitted parameter, the model-form term
    ``softening`` of the intervals: the truth is the preconditioned muscle) where the first
    rise is at least :data:`SOFTENING_MIN` stiffer and that lowers the chi-square by
    :data:`SOFTENING_CHI2` and more than the drift does; against the falling branch alone
    (a loop friction makes too), only in a misfit whose excess it takes
    :data:`SOFTENING_TAKES` of away, and not where a lag between the monitor and the muscle
    is named (``lagged``, :func:`lag_hint`): its loop parts a ramp's branches the same way
    (named on 3 of 8 lagged ramps of ``bench_identify_wrong_range.py``, 1.2-2.5 %). Else
    None."""
    rises = [first_rise(run) for run in runs]
    repeats = any(repeated.any() for _, repeated in rises)
    firsts = [repeated if repeats else first for first, repeated in rises]
    if not fitness.judged or not any(f.any() for f in firsts):
        return None
    if not repeats and (lagged or not fitness.misfit):
        return None
    stiffer = {**best.values, "rubber_scale": best.values["rubber_scale"] * (1 + SOFTENING_STEP)}
    holds = [run.hold >= 0 for run in runs]
    column = np.concatenate([
        np.where(f[np.maximum(run.hold, 0)], m - b, 0.0)[h]
        for run, f, m, b, h in zip(runs, firsts, fitting.traces(source, runs, stiffer),
                                   fitting.traces(source, runs, best.values), holds,
                                   strict=True)])
    if not np.any(column):
        return None
    drift = np.concatenate([(run.time_s - run.time_s[h].mean())[h] / 60.0
                            for run, h in zip(runs, holds, strict=True)])

    def refit_chi2(amount: float, along=column) -> float:
        moved = _refitted(best, best.residual_N + amount * along)
        return goodness.assess(runs, dataclasses.replace(best, residual_N=moved)).chi2

    base = refit_chi2(0.0)
    stiffness = optimize.minimize_scalar(lambda a: refit_chi2(a / SOFTENING_STEP),
                                         bounds=(0.0, SOFTENING_MAX), method="bounded",
                                         options={"xatol": 1e-4}).x
    with_it = refit_chi2(stiffness / SOFTENING_STEP)
    # a drift of the zero [N/min], either sign: the chi-square is a parabola in it
    drift_chi2 = min(base, optimize.minimize_scalar(lambda n: refit_chi2(n, drift)).fun)
    lowered, drift_lowered = base - with_it, base - drift_chi2
    if not (stiffness >= SOFTENING_MIN and lowered >= SOFTENING_CHI2
            and lowered > drift_lowered
            and (repeats or lowered >= SOFTENING_TAKES * (base - fitness.nu))):
        return None
    gap_N = stiffness / SOFTENING_STEP * float(np.max(np.abs(column)))
    softened_pct = 100 * stiffness / (1 + stiffness)
    step = _step(best, best.residual_N + stiffness / SOFTENING_STEP * column)
    precondition = ("precondition the muscle (cycle it to its top pressure 3-5 times before the "
                    "staircase: [sequence] preconditioning_cycles)")
    if repeats:
        seen = "the first rise pulls less than the repeats at the same pressures"
        cause = "the rubber softened after its first loading"
        advice = f"{precondition} and acquire again"
    else:
        seen = "the first rise pulls less than the falling branch beyond the fitted friction"
        cause = "as a rubber that softened after its first loading does"
        advice = (f"repeat the staircase ([sequence] repeats = 2) to tell (a softened rubber's "
                  f"repeat pulls more than its first rise), or {precondition}, and acquire "
                  "again")
    return {"what": "first-cycle softening", "against": "repeats" if repeats else "falling",
            "first_rise_stiffer_pct": float(f"{100 * stiffness:.3g}"),
            "softened_pct": float(f"{softened_pct:.3g}"),
            "largest_gap_N": float(f"{gap_N:.3g}"),
            "chi2_lowered": round(float(lowered), 3),
            "chi2_per_nu": round(float(with_it / fitness.nu), 3),
            "drift_chi2_lowered": round(float(drift_lowered), 3),
            "said": (f"softening: {seen} (by up to {gap_N:.2g} N): {cause} (the Mullins "
                     f"effect), about {softened_pct:.2g} % (its first rise "
                     f"{100 * stiffness:.2g} % stiffer); "
                     f"fitting that (linearised) lowers chi2 by {lowered:.3g} (chi2/nu "
                     f"{with_it / fitness.nu:.3g}), where a zero drifting with time lowers it by "
                     f"{drift_lowered:.3g}; the intervals hold the preconditioned muscle (the "
                     f"model-form term softening); {advice}"),
            "verdict": f"{seen}: {cause} (the Mullins effect, the note above): {advice}",
            "ready_if": "with the intervals holding the preconditioned muscle",
            "shift": {n: float(v) for n, v in zip(best.names, step, strict=True)}}


def _rms(r) -> float:
    return float(np.sqrt(np.mean(np.square(r))))


#: a rubber at an edge of its search, per edge: how it is said, the practical range's end, and
#: what makes a muscle pull so: its wall, its pressures and its load cell read one way
RUBBER_EDGE = {
    "low": ("softer", "softest", "a wall thinner than declared pulls as a softer rubber",
            "read low, as in MPa taken for bar, or a monitor off its zero: the muscle pulls at "
            "each as at a higher one", "a cell reading high"),
    "high": ("stiffer", "stiffest", "a wall thicker than declared pulls as a stiffer rubber",
             "read high, as in kPa or psi taken for bar, or a monitor off its zero: the muscle "
             "pulls at each as at a lower one", "a cell reading low")}


def edge_note(name: str, best, source) -> str:
    """The note on ``name`` fitted at an edge of its search box (``best.bounds``): which edge,
    what the runs then say and what to check; for a box other than the FE model's (the
    surrogate's, on which a corrected fit ended), that ``--search model`` searches beyond
    it."""
    value = best.values[name]
    low, high = best.bounds[name]
    edge = "low" if value - low <= high - value else "high"
    said = (f"{name} {value:.4g} is at the {edge} edge of its search box ({low:.4g} to "
            f"{high:.4g}): the interval is cut there")
    surrogate = source.box is not fitting.FE_BOX
    if name == "rubber_scale":
        rubber, end, wall, pressures, cell = RUBBER_EDGE[edge]
        said += (f"; these runs pull as a rubber {rubber} than any searched (C10 "
                 f"{fitting.rubber(best.values)[0]:.3g} MPa at "
                 f"{fitting.assumed_ratio(best.values)[1]} ratio; the practical range's "
                 f"{end} C10 is {PRACTICAL_RANGE.C10_MPa[0 if edge == 'low' else 1]:g} MPa): "
                 f"check the wall's declared thickness ({wall}), the pressures ({pressures}) "
                 f"and the load cell's gain ({cell})")
    elif name == "theta0_deg" and not surrogate:
        said += (f"; a braid angle of {value:.3g} deg is not a muscle of this family: check "
                 "the declared diameter and wall and the units of force and pressure")
    elif name in fitting.GEOMETRY_FACTORS and not surrogate:
        factor = fitting.GEOMETRY_FACTORS[name][0 if edge == "low" else 1]
        said += f"; {factor:g} times the declared value: the declaration is far off, measure it"
    else:
        said += "; check the declared geometry and the units of force and pressure"
    if surrogate:
        said += (f"; the box is the surrogate's ({source.name}): --search model searches with "
                 "the FE model beyond it")
    return said


def ratio_edge_note(ratio: float, share: float, bounds: tuple[float, float],
                    said: str) -> str:
    """The note on C01's share ``share`` fitted at an edge of its search ``bounds`` (the ratio
    C01/C10 ``ratio``): which edge, so what the runs want."""
    low, high = bounds
    want = ("no C01 (a neo-Hookean rubber, or an error the model takes for one)"
            if share - low <= high - share else "more of C01 than the box allows")
    return (f"C01/C10 {ratio:.3g} is at the edge of its search box: the runs want {want}, so "
            f"the ratio is the edge's, not measured: the intervals hold the fit at {said} "
            "ratio too")


def _select(source, runs, names, start, nominal):
    """The fit of every friction/creep subset of ``names``; the lowest BIC wins."""
    optional = [g for g in ("friction", "creep") if GROUPS[g][0] in names]
    candidates, fits = [], {}
    full = None
    for dropped in itertools.chain.from_iterable(
            itertools.combinations(optional, k) for k in range(len(optional) + 1)):
        keep = [n for n in names if not any(n in GROUPS[g] for g in dropped)]
        begin = {**(full.values if full else start),
                 **{n: nominal[n] for g in dropped for n in GROUPS[g]}}
        terms = ", ".join(g for g in optional if g not in dropped) or "none"
        try:
            result = fitting.fit(source, runs, keep, begin,
                                 max_nfev=CANDIDATE_EVALUATIONS if dropped else 400)
        except RuntimeError as exc:
            if full is None:  # the full model itself: nothing to select from
                raise
            # a model without a term the runs need may wander without converging: it is not
            # the one, and the others are compared without it
            candidates.append({"terms": terms, "parameters": len(keep), "dropped": dropped,
                               "not_converged": str(exc)})
            continue
        full = full or result
        fits[dropped] = result
        candidates.append({"terms": terms, "parameters": len(keep), "rss_N2": result.rss,
                           "bic": result.bic, "n": result.n, "dropped": dropped})
    chosen = min(fits, key=lambda d: fits[d].bic)
    for row in candidates:
        row["chosen"] = row.pop("dropped") == chosen
    return fits[chosen], candidates


def instrument_terms(runs) -> dict:
    """What the bootstrap draws of the instrument (:func:`mkm.identify.intervals.bootstrap`):
    the load cell's sensitivity tolerance (one cell for every run: the largest declared), the
    monitor offset's prior, uniform over where it is searched
    (:func:`mkm.identify.runs.offset_search_bar`: the smallest declared offset bound, or about
    the vented reading; its standard deviation, the half-width over root 3), and each imported
    step's declared noise (:meth:`~mkm.identify.runs.RunData.declared_noise_N`: its residual
    cannot show it)."""
    low, high = offset_search_bar(runs)
    declared = [r.declared_noise_N() for r in runs]
    return {"sensitivity_tolerance": max(r.sensitivity_tolerance for r in runs),
            "prior_sd": {"pressure_offset_bar": (high - low) / 2 / np.sqrt(3.0)},
            "step_u_N": (np.concatenate([np.zeros(len(r.steps)) if d is None else d
                                         for r, d in zip(runs, declared, strict=True)])
                         if any(d is not None for d in declared) else None)}


def shared_terms(source, runs, best) -> dict[str, tuple[np.ndarray, float]]:
    """What every run shares and the fit takes as given, as the bootstrap's uniform terms
    (:func:`mkm.identify.intervals.bootstrap`): the hold residuals' sensitivity to each (a
    forward difference of a tenth of its bound; backward at the top of the source's box, which
    a tube at the practical range's 60 mm would leave) and its +- bound: the tube's declared wall
    and diameter where not fitted (their declared tolerances, the largest of the runs'), and
    the pressure monitor's gain (its declared span error, or its one accuracy reached at the
    regulator's top pressure: the offset is fitted, a reading error growing with the pressure
    is not) and, where not fitted, its declared hysteresis (each branch's reading off by half of
    it, in opposite directions). The data see these only through the other parameters: the
    intervals carry them."""
    bounds = {n: (max(r.geometry_tolerance_mm.get(n, 0.0) for r in runs),
                  float(runs[0].muscle[n])) for n in fitting.GEOMETRY if n not in best.names}
    bounds["pressure_gain"] = (min(r.monitor_gain_bound for r in runs), 1.0)
    if "pressure_hysteresis_bar" not in best.names:
        bounds["pressure_hysteresis_bar"] = (max(r.monitor_hysteresis_bar for r in runs) / 2,
                                             0.0)
    out, base = {}, None
    for name, (half, at) in bounds.items():
        if not half > 0:
            continue
        base = base or fitting.traces(source, runs, best.values)
        step = 0.1 * half
        if at + step > getattr(source, "box", {}).get(name, (at, np.inf))[1]:
            step = -step  # a tube at the top of the searching surrogate's box: inward
        moved = fitting.traces(source, runs, {**best.values, name: at + step})
        out[name] = (_on_holds(runs, moved, base) / step, half)
    return out


def model_form_terms(source, fe: ModelStatic, runs, best, braid: str | None) -> dict:
    """What the fit's own model may have wrong, as the shift of every fitted parameter a refit
    would make (one Gauss-Newton step from the optimum with its Jacobian, on the static force's
    change; one FE sweep per run each):

    - ``fe_correction`` (when the fit ran on the surrogate corrected by the FE model at the
      first optimum): the FE model against the corrected surrogate at the final optimum, whose
      difference the correction at one point leaves (symmetric: an error of unknown sign);
    - ``braid`` (when the muscle's braid is not given and ``fe`` has the option): the other
      braid of :data:`mkm.fem.options.BRAIDS` against ``fe``'s at the optimum: the runs cannot
      tell a sliding sleeve from a bonded braid (chi2/nu stays near 1), so the intervals hold
      both (one-sided: the other braid's estimate); not with a fitted gap, which only the
      bonded braid takes;
    - ``creep`` (when no run has timed holds: step tables, ramps): the muscle's creep, which
      such runs cannot fit, lowers every step's force by up to :data:`UNTIMED_CREEP_FRACTION`
      of it (one-sided: the fit with it against the fit without).

    Returns ``{term: {"kind", "what", "shift": {name: value}}}`` (and a ``skipped`` reason
    where a term does not apply)."""
    terms: dict = {}
    values = best.values
    fe_tables = None
    if source is not fe:
        fe_tables = fe.tables(runs, values)
        terms["fe_correction"] = {
            "kind": "symmetric", "what": f"{fe.name} minus {source.name} at the optimum",
            "shift": _shift(source, runs, best,
                            _minus(fe_tables, source.tables(runs, values)))}
    skipped = braid_skipped(fe, best, braid)
    if skipped:
        terms["braid"] = {"skipped": skipped}
    else:
        alternative = _other_braid(fe)
        fe_tables = fe_tables or fe.tables(runs, values)
        terms["braid"] = {
            "kind": "one-sided", "what": f"{alternative.name} minus {fe.name} at the optimum",
            "shift": _shift(source, runs, best,
                            _minus(alternative.tables(runs, values), fe_tables))}
    if not any(run.timed for run in runs):
        terms["creep"] = {
            "kind": "one-sided",
            "what": f"a creep of {100 * UNTIMED_CREEP_FRACTION:g} % of the force, which runs "
                    "without timed holds cannot fit",
            "shift": _shift(source, runs, best, [
                (grid, -UNTIMED_CREEP_FRACTION * np.asarray(F, dtype=float))
                for grid, F in source.tables(runs, values)])}
    return terms


def braid_skipped(fe: ModelStatic, best, braid: str | None) -> str | None:
    """Why the other braid is not a model-form term of this fit (the braid given, a model
    without the option, a fitted gap), or None where the runs leave the braid in doubt."""
    if braid is not None:
        return f"the braid is given ({braid})"
    if "braid" not in fe.spec.entry.parameters:
        return f"{fe.name} has no braid option"
    if "gap_mm" in best.names:
        # the sliding sleeve takes no gap: there is no other braid's estimate to hold
        return "a gap is fitted, and a gap is modelled with the bonded braid only"
    return None


def _braid_of(fe: ModelStatic) -> str:
    """The braid ``fe`` models (its spec's, else the default)."""
    return dict(fe.spec.params).get("braid", BRAIDS[0])


def _other_braid(fe: ModelStatic) -> ModelStatic:
    """``fe`` with the other braid of :data:`mkm.fem.options.BRAIDS`."""
    other = next(b for b in BRAIDS if b != _braid_of(fe))
    return ModelStatic(fe.spec.with_params(braid=other).text, fe.runner, fe.cache_dir)


def other_braid_excess(source, fe: ModelStatic, runs, one_scale, free) -> float:
    """How far the fit at the assumed ratio (``one_scale``) refitted with the other braid
    stays above the fit with the ratio free (``free``), in the units of the likelihood-ratio
    test (the free fit's residual variance): the refit is linearised at ``one_scale``'s optimum
    (one Gauss-Newton step, the other braid's change of the static force there; one FE sweep
    per run and braid). At or below :data:`RATIO_LIKELIHOOD` the other braid explains the runs
    as well as another ratio does."""
    differences = _minus(_other_braid(fe).tables(runs, one_scale.values),
                         fe.tables(runs, one_scale.values))
    r = _refitted(one_scale, one_scale.residual_N + _hold_change(source, runs, one_scale,
                                                                  differences))
    variance = free.rss / max(free.n - len(free.names), 1)
    return float((np.sum((one_scale.w * r) ** 2) - free.rss) / variance)


def without_creep(source, fe: ModelStatic, runs, best, braid: ModelStatic) -> float:
    """How far ``best``, which fitted a creep, refitted with ``braid``'s static force and no
    creep stays above it, in units of ``best``'s residual variance (the likelihood-ratio
    test's): the creep set to 0 (the force is linear in its share), the other parameters
    refitted by Gauss-Newton steps with ``best``'s Jacobian, each evaluated with ``braid``
    itself (one FE sweep per run each, the fit's own source for ``fe``), until a step lowers
    the residuals' sum of squares by less than :data:`BRAID_REFIT_CONVERGED` (at most
    :data:`BRAID_REFIT_STEPS`); the lowest evaluated is kept. One step's linear prediction
    misses where ``braid``'s force moves with the parameters otherwise than ``fe``'s: a sleeve
    sliding on a 10 mm tube (``bench_identify_wrong_range.py`` seed 20261612, a creep of
    1.8 % at 1 s) was predicted 873 above the bonded fit with the creep, and is 402 below it
    evaluated."""
    kept = [i for i, n in enumerate(best.names) if n not in ("creep_fraction", "log_tau")]
    base = fitting.traces(source, runs, best.values)

    def residual(values) -> np.ndarray:
        """The weighted hold residuals at ``values`` with ``braid``'s static force."""
        model = source if braid is fe else Corrected(source, _minus(
            braid.tables(runs, values), source.tables(runs, values)))
        return best.w * (best.residual_N + _on_holds(runs, fitting.traces(model, runs, values),
                                                     base))

    values = {**best.values, "creep_fraction": 0.0}
    J = best.weighted_jacobian[:, kept]
    r = residual(values)
    lowest = previous = float(np.sum(r ** 2))
    for _ in range(BRAID_REFIT_STEPS):
        step = np.linalg.lstsq(J, r, rcond=None)[0]
        for i, d in zip(kept, step, strict=True):
            name = best.names[i]
            values[name] = float(np.clip(values[name] - d, *best.bounds[name]))
        r = residual(values)
        now = float(np.sum(r ** 2))
        lowest = min(lowest, now)
        if previous - now < BRAID_REFIT_CONVERGED * previous:
            break
        previous = now
    variance = best.rss / max(best.n - len(best.names), 1)
    return float((lowest - best.rss) / variance)


def surrogate_misfit(source, fe: ModelStatic, runs, best) -> bool:
    """Whether the fit ``best`` on the corrected surrogate ``source``, a misfit, would not be
    one with the FE model ``fe`` (:func:`mkm.identify.goodness.assess`): refitted with
    the FE model's force at the optimum in place of the surrogate's (linearised, as
    :func:`other_braid_excess` refits; one FE sweep per run, which the model-form terms take
    anyway), the runs are within their noise. The surrogate's own error beyond its correction
    at one point then made the misfit, not the muscle or the bench."""
    differences = _minus(fe.tables(runs, best.values), source.tables(runs, best.values))
    r = _refitted(best, best.residual_N + _hold_change(source, runs, best, differences))
    return not goodness.assess(runs, dataclasses.replace(best, residual_N=r)).misfit


def _minus(tables, others) -> list[tuple]:
    """Per run: ``tables``' pressures and their force less ``others``' there."""
    return [(grid, F - fitting.static_force(grid, *other))
            for (grid, F), other in zip(tables, others, strict=True)]


def _shift(source, runs, best, differences) -> dict[str, float]:
    """The refit's shift of ``best``'s parameters when the static force of each run changes by
    ``differences`` (per run: pressures and the change there): ``-(J'J)^-1 J' dr``, the change
    ``dr`` of the hold residuals through the friction and creep of each run's trace."""
    step = _step(best, _hold_change(source, runs, best, differences))
    return {n: float(v) for n, v in zip(best.names, step, strict=True)}


def _step(fit, residual_N) -> np.ndarray:
    """One Gauss-Newton step of ``fit``'s parameters taking the hold residuals ``residual_N``
    [N] away as far as their (weighted) Jacobian can; 0 for a parameter the holds do not
    see."""
    J = fit.weighted_jacobian
    usable = np.sqrt(np.sum(J**2, axis=0)) > 0
    step = np.zeros(len(fit.names))
    if usable.any():
        step[usable] = -np.linalg.lstsq(J[:, usable], fit.w * residual_N, rcond=None)[0]
    return step


def _refitted(fit, residual_N) -> np.ndarray:
    """The hold residuals ``residual_N`` [N] after one linearised refit of ``fit``'s
    parameters (:func:`_step`): what their Jacobian cannot take away."""
    return residual_N + fit.jacobian @ _step(fit, residual_N)


def _hold_change(source, runs, fit, differences) -> np.ndarray:
    """The change of ``fit``'s hold residuals [N] when the static force of each run changes by
    ``differences`` (per run: pressures and the change there), through the friction and creep
    of each run's trace."""
    return _on_holds(runs, fitting.traces(Corrected(source, differences), runs, fit.values),
                     fitting.traces(source, runs, fit.values))


def _on_holds(runs, moved, base) -> np.ndarray:
    """The traces ``moved`` less ``base`` (per run, [N]) at each run's held samples, in the
    order of the fit's hold residuals: a column of their change."""
    return np.concatenate([(m - b)[run.hold >= 0]
                           for run, m, b in zip(runs, moved, base, strict=True)])


def _outside_box(caught, what: str = "the fit with C01's share free",
                 consequence: str = "the test of C10 and C01 is extrapolated there") -> list[str]:
    """Warnings of a refit (``what``: the fit with the rubber's ratio free, the refits at an
    assumed ratio) passed on, except the surrogate's out-of-domain ones and those of points
    without an answer inside its box, which a fit repeats once per evaluation: one note per
    kind says it instead, with what was outside (or why no answer) and ``consequence``."""
    from mkm.surrogate.model import UNINFORMED

    ours = [w for w in caught if w.category.__name__ == "OutOfDomainWarning"]
    for w in caught:
        if w not in ours:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    unanswered = [w for w in ours if UNINFORMED in str(w.message)]
    outside = [w for w in ours if w not in unanswered]
    notes = []
    if outside:
        first = str(outside[0].message).partition("(")[2].partition(")")[0]
        notes.append(f"{what} left the surrogate's training box in {len(outside)} evaluations "
                     f"(first: {first}): {consequence}")
    if unanswered:
        notes.append(f"{what} met points the surrogate has no answer for in {len(unanswered)} "
                     f"evaluations ({UNINFORMED}): {consequence}")
    return notes


def ratio_edge_term(one_scale, free) -> dict:
    """The model-form term of a rubber ratio at the edge of its search: the fit at the assumed
    ratio (``one_scale``) minus the fit with C01's share free (``free``), one-sided."""
    shift = {name: one_scale.values[name] - free.values[name] for name in free.names
             if name in one_scale.values}
    shift["c01_fraction"] = fitting.assumed_share(one_scale.values) - free.values["c01_fraction"]
    return {"kind": "one-sided", "shift": shift,
            "what": f"the fit at {fitting.assumed_ratio(one_scale.values)[1]} C01/C10 minus the "
                    "fit with the ratio at the edge of its search"}


def profile_at_bounds(source, runs, best, boot, resample, notify=None) -> dict:
    """``boot`` with the interval of each static parameter that meets a bound of its search
    (:func:`mkm.identify.intervals.meets_bound`) a profile one: at a bound the bootstrap's
    replicates step from the optimum by its Jacobian there and collapse onto the bound (an
    interval of nothing: C01's share at 0 gave C01/C10 0-1.6e-06), or see a column of nothing
    (its finite difference taken beyond the bound) and call the parameter not identifiable.
    The parameter's column is differenced into the box (one evaluation) and the bootstrap run
    again with it (``resample(fit)``: the same draws) for the scale of its chi2
    (:func:`mkm.identify.intervals.linear_scale`); then it is held at values from its estimate
    towards each bound and the others refitted on ``source`` (the fit's own model), each end
    where chi2 has risen by :data:`mkm.identify.intervals.PROFILE_RISE`, never inside the
    bootstrap's. ``boot["profiled"]``: per parameter, the bootstrap's interval before, the
    profile's, the refits it took; a refit that fails leaves the bootstrap's interval, and says
    why. ``boot["jacobian"]``: the fit's, with the profiled parameters' columns differenced
    into the box (a parameter of a column of nothing there is identifiable where its
    differenced column is not nothing). ``notify``: told before the refits start."""
    low_q, high_q = 100 * (1 - LEVEL) / 2, 100 * (1 + LEVEL) / 2
    flagged = [name for i, name in enumerate(best.names) if name in PROFILED and meets_bound(
        best.values[name], best.bounds[name],
        tuple(np.percentile(boot["draws"][:, i], [low_q, high_q])))]
    if not flagged:
        return boot
    if notify:
        notify(f"intervals: {', '.join(flagged)} at a bound of the search: profiled (refits "
               f"with {source.name})")
    interval, profiled = dict(boot["interval"]), {}
    identifiable, jacobian = dict(boot["identifiable"]), best.jacobian.copy()
    for name in flagged:
        others = tuple(n for n in best.names if n != name)
        given = {n: best.bounds[n] for n in others}

        def refit(value, start, name=name, others=others, given=given):
            return fitting.fit(source, runs, others, {**start, name: value}, given=given)

        value, bounds = best.values[name], best.bounds[name]
        inward = 1 if value - bounds[0] <= bounds[1] - value else -1
        ends, refits = [], 0
        try:
            step = inward * fitting.EDGE_FRACTION * (bounds[1] - bounds[0])
            stepped = fitting.fit(source, runs, (), {**best.values, name: value + step})
            column = (stepped.residual_N - best.residual_N) / step
            if not np.any(column):  # the runs do not see it into the box either
                continue
            differenced = best.jacobian.copy()
            differenced[:, best.names.index(name)] = column
            moved = dataclasses.replace(best, jacobian=differenced)
            scale = linear_scale(moved, resample(moved), name)
            for k, side in enumerate(("low", "high")):
                if fitting.at_edge(value, bounds) and (
                        abs(value - bounds[k]) <= abs(value - bounds[1 - k])):
                    ends.append(bounds[k])  # resting on it: that end is the bound
                    continue
                # the bootstrap's end is kept where wider; not one of a column of nothing
                linear = boot["interval"][name][k] if boot["identifiable"][name] else value
                end, n = profile(refit, best, name, side, scale, linear)
                ends.append(end)
                refits += n
        except RuntimeError as exc:
            profiled[name] = {"bootstrap_interval": list(boot["interval"][name]),
                              "refits": refits, "failed": str(exc)}
            continue
        interval[name] = tuple(ends)
        jacobian[:, best.names.index(name)] = column
        identifiable[name] = True
        profiled[name] = {"bootstrap_interval": list(boot["interval"][name]),
                          "interval": list(ends), "refits": refits,
                          "widened": ends != list(boot["interval"][name]),
                          "chi2_rise": PROFILE_RISE, "residual_variance": scale}
    return {**boot, "interval": interval, "identifiable": identifiable, "profiled": profiled,
            "jacobian": jacobian}


def profile_said(profiled: dict, bounds: dict) -> list[str]:
    """A note per parameter whose interval :func:`profile_at_bounds` widened, or whose profile
    failed."""
    notes = []
    for name, p in profiled.items():
        if not (p.get("widened") or "failed" in p):
            continue  # the bootstrap's interval stood: nothing to say
        low_b, high_b = bounds[name]
        b_low, b_high = p["bootstrap_interval"]
        if "failed" in p:
            notes.append(f"{name} meets a bound of its search ({low_b:.4g} to {high_b:.4g}) and "
                         f"its profile failed after {p['refits']} refits ({p['failed']}): its "
                         f"interval ({b_low:.4g}-{b_high:.4g}) is the bootstrap's, linearised "
                         "at the bound, and says little")
            continue
        low, high = p["interval"]
        said = name
        if name == "c01_fraction":  # said as the ratio the report writes
            said, (low, high, low_b, high_b, b_low, b_high) = "C01/C10", (
                v / (1.0 - v) for v in (low, high, low_b, high_b, b_low, b_high))
        notes.append(f"{said}'s interval ({low:.4g}-{high:.4g}) is a profile one: it meets a "
                     f"bound of its search ({low_b:.4g} to {high_b:.4g}), where the bootstrap's "
                     f"linearised interval ({b_low:.4g}-{b_high:.4g}) says nothing; held at "
                     f"{p['refits']} values, the others refitted, chi2 rises by "
                     f"{p['chi2_rise']:.3g} (on the bootstrap's scale) at its ends, or "
                     "reaches the bound first")
    return notes


def _improvement(one_scale, free) -> float:
    """The likelihood ratio of the fit with C01's share free (``free``) over the fit at one
    ratio (``one_scale``), in units of the free fit's residual variance."""
    return (one_scale.rss - free.rss) / (free.rss / max(free.n - len(free.names), 1))


def _one_scale_again(source, first, runs, best, free, rubber):
    """The fit at the assumed rubber ratio started again from the optimum of the fit with the
    ratio free (``free``, on ``source``: the surrogate with the FE model's correction taken
    again at that optimum), where the runs do not separate C10 and C01 and it fits better than
    ``best`` (on ``first``, the correction taken at the surrogate's optimum) by more than
    :data:`RATIO_LIKELIHOOD` (in the free fit's residual variance); else None, also where the
    free fit ran on ``first`` itself. Far outside its training a surrogate's error
    changes fast with the parameters: the FE model's correction taken at the first optimum
    may not hold there, and the free fit, corrected again at its own, fits better for that,
    not for its ratio."""
    if (rubber.get("separated") or free is best or source is first
            or "ratio_C01_over_C10" not in rubber):
        return None
    try:
        again = fitting.fit(source, runs, best.names,
                            {**free.values, "c01_fraction": fitting.assumed_share(best.values)})
    except RuntimeError:  # no better fit found: the first stands
        return None
    return again if _improvement(best, again) > RATIO_LIKELIHOOD else None


def _rubber_ratio(source, fe, runs, best, seed, braid):
    """The fit with C01's share of the rubber free, its bootstrap, whether the runs separate
    C10 and C01 (:data:`RATIO_WIDTH`, :data:`RATIO_CONDITION`), and its model-form terms
    (:func:`model_form_terms`): the ratio's interval holds their shifts too, so that a braid
    the model does not have, which can look like another ratio, does not separate them; and
    the source the free fit ran on (a surrogate corrected by the FE model: corrected again at
    the free optimum)."""
    names = (*best.names, "c01_fraction")
    low, high = fitting.bounds_of("c01_fraction", source, runs, best.values)
    if not low < high:
        return best, None, {"separated": False, "why": "C01's share has no room in the search "
                            f"box ({source.name}'s) at this rubber scale"}, None, source
    try:
        free = fitting.fit(source, runs, names,
                           {**best.values, "c01_fraction": fitting.assumed_share(best.values)})
        if isinstance(source, Corrected):
            # the FE's correction was taken at the assumed ratio; the surrogate's error changes
            # with the ratio, and left so it misfits the free fit by it (chi2/nu 5-16 on
            # rubbers of C01/C10 0.2-0.5 fitted within the noise by the FE itself): taken
            # again at the free optimum, both fits are the FE's at their own optimum
            source = Corrected(source.base, fitting.fe_correction(source.base, fe, runs,
                                                                  free.values))
            free = fitting.fit(source, runs, names, free.values)
    except RuntimeError as exc:
        return best, None, {"separated": False, "why": f"the fit with the ratio free failed: "
                            f"{exc}"}, None, source
    share_box = tuple(free.bounds["c01_fraction"])
    if share_box != fitting.TERM_BOUNDS["c01_fraction"] and fitting.at_edge(
            free.values["c01_fraction"], share_box):
        return best, None, {"separated": False, "box_stopped": True,
                            "edge_chi2_improvement": float(_improvement(best, free)),
                            "why": "C01's share reached the search box "
                            f"({source.name}'s) before the runs fixed it"}, None, source
    shared = shared_terms(source, runs, free)

    def resample(fit, shared=shared):
        return bootstrap(fit, seed=seed, **instrument_terms(runs), uniform_terms=shared)

    boot = profile_at_bounds(source, runs, free, resample(free), resample)
    terms = model_form_terms(source, fe, runs, free, braid)
    share = free.values["c01_fraction"]
    ratio = share / (1.0 - share)
    # a creep hidden in untimed runs lowers every force by a share: a level, not the bend with
    # eps that tells the ratio, so it widens the final intervals, not this test of the ratio
    tested = {name: term for name, term in terms.items() if name != "creep"}
    widest = fitting.TERM_BOUNDS["c01_fraction"]
    margin = fitting.EDGE_FRACTION * (share_box[1] - share_box[0])

    def ratio_interval(replicates):
        """The ratio's 95 % interval, clipped to the box searched: an end on a surrogate's box
        is the box's, not the runs', which were not tested beyond it: open to the search's own
        bound (and where it was cut)."""
        shares = list(extend(replicates, free, tested)["interval"]["c01_fraction"])
        cut = []
        if share_box[0] > widest[0] and shares[0] <= share_box[0] + margin:
            cut, shares[0] = [share_box[0]], widest[0]
        if share_box[1] < widest[1] and shares[1] >= share_box[1] - margin:
            cut, shares[1] = [*cut, share_box[1]], widest[1]
        return [min(v, 0.999) / (1.0 - min(v, 0.999)) for v in shares], cut

    (low, high), cut = ratio_interval(boot)
    static = [free.names.index(n) for n in STATIC_NAMES if n in free.names]
    # a share at its bound: its column differenced into the box (the fit's saw nothing there)
    J = (free.w[:, None] * boot.get("jacobian", free.jacobian))[:, static]
    norms = np.sqrt(np.sum(J**2, axis=0))
    condition = (float(np.linalg.cond((J / norms).T @ (J / norms))) if np.all(norms > 0)
                 else float("inf"))
    assumed, said = fitting.assumed_ratio(best.values)
    # the bootstrap is linearised at the optimum: at the search box's edge its replicates
    # collapse onto the edge (an interval of nothing, not a measurement), and where C01's share
    # trades against the other parameters along a flat valley it can exclude a ratio the fit
    # barely prefers, so a rejection must also be the fits' (the likelihood ratio of one
    # parameter more)
    narrow = (ratio > 0 and not fitting.at_edge(share, share_box)
              and (1 - RATIO_WIDTH) * ratio <= low and high <= (1 + RATIO_WIDTH) * ratio)
    improvement = _improvement(best, free)
    rejected = not low <= assumed <= high and improvement > RATIO_LIKELIHOOD
    # a misfit at the assumed ratio that the ratio freed takes away names the rubber, not the
    # bench, as what the fit lacks, whether or not the runs pin the ratio
    free_fitness = goodness.assess(runs, free)
    # what the bench declares but does not measure (the tube's wall and diameter, the monitor's
    # gain) trades with the ratio: where it alone keeps the assumed one in the interval of a ratio
    # the fits prefer, the runs want another rubber and the tolerances keep it unmeasured
    declared = None
    if not rejected and shared and improvement > RATIO_LIKELIHOOD:
        (d_low, d_high), _ = ratio_interval(profile_at_bounds(
            source, runs, free, resample(free, None), lambda fit: resample(fit, None)))
        if not d_low <= assumed <= d_high:
            declared = {"ratio_ci": [d_low, d_high], "terms": sorted(shared)}
    # a braid the model may not have bends the curve as another ratio would (measured on the
    # sliding sleeve: C01 driven to 0): with the braid in doubt, a rejection alone is not a
    # measurement of the ratio
    braid_doubt = "shift" in terms.get("braid", {})
    # ... unless the other braid at the assumed ratio cannot follow the runs as the ratio
    # freed does: then the rejection stands whichever the braid (a natural rubber's ratio)
    excess = (other_braid_excess(source, fe, runs, best, free) if rejected and braid_doubt
              else None)
    braid_doubt = braid_doubt and (excess is None or excess <= RATIO_LIKELIHOOD)
    separated = bool(boot["identifiable"]["c01_fraction"]
                     and (narrow or (rejected and not braid_doubt))
                     and condition < RATIO_CONDITION)
    return free, boot, {"separated": separated, "ratio_C01_over_C10": ratio,
                        "ratio_ci": [low, high], "condition": condition,
                        "ratio_box_cut": [v / (1.0 - v) for v in cut],
                        "ratio_profile": boot.get("profiled", {}).get("c01_fraction"),
                        "searched_with": getattr(source, "base", source).name,
                        "rejects_silastic_ratio": rejected, "braid_in_doubt": braid_doubt,
                        "chi2_improvement": float(improvement),
                        "free_chi2_per_nu": (float(free_fitness.reduced) if free_fitness.judged
                                             else None),
                        "free_within_noise": bool(free_fitness.judged
                                                  and not free_fitness.misfit),
                        "other_braid_chi2_excess": excess,
                        "rejects_silastic_ratio_but_for_declared": declared,
                        "assumed_C01_over_C10": assumed, "assumed_from": said,
                        "rule": f"C10 and C01 reported apart when the condition number of the "
                                f"static parameters' normalised Fisher matrix is below "
                                f"{RATIO_CONDITION:.0e} and the 95 % interval of C01/C10 lies "
                                f"within +-{100 * RATIO_WIDTH:.0f} % of it or excludes "
                                f"{said} {assumed:.3f} (the interval holding the model-form "
                                f"terms' shifts) and the fit with the ratio free lowers chi2 "
                                f"by more than {RATIO_LIKELIHOOD:.2f} (the residuals' variance "
                                f"its own); excluding it is not enough while the braid "
                                f"is in doubt and the other braid at it lowers chi2 as "
                                f"far, within {RATIO_LIKELIHOOD:.2f}"}, terms, source


def _box_cut_the_ratio(rubber: dict) -> bool:
    """Whether the runs were left not separating C10 and C01 because the surrogate's box cut
    the test of their ratio (C01's share stopped at it, had no room in it, or its interval was
    cut there), not by the runs."""
    return not rubber["separated"] and bool(
        rubber.get("box_stopped") or rubber.get("ratio_box_cut")
        or rubber.get("why", "").startswith("C01's share has no room in the search box"))


def search_model_note(test: dict, runs, options) -> str:
    """The note where the FE model may separate C10 and C01 that the surrogate's box left
    together (:func:`fe_ratio_test`), with the command that tests it."""
    low, high = test["ratio_ci"]
    paths = " ".join(one_argument(run.path) for run in runs)
    return (f"the surrogate's box cut the test of C10 and C01, and the FE model may separate "
            f"them: its change with the ratio at this optimum puts C01/C10 at "
            f"{test['ratio']:.3g} (95 % interval {low:.3g}-{high:.3g}, linearised; "
            f"{test['assumed_from']} {test['assumed']:.3g}); to test it, identify again with the "
            f"FE model searching (one sweep per run and evaluation): mkm identify {paths} "
            f"{' '.join(map(one_argument, options))}")


#: the share of a misfit's excess chi2/nu over 1 that the fit with the rubber's ratio free
#: must take away for the FE model's step with the ratio free to be read as the rubber's:
#: below it the step is taken at an optimum the misfit has moved, and points where the misfit
#: pulls (docs/guide/calibration.md names the draws it was set on)
RATIO_EXPLAINS_MISFIT = 0.5


def misfit_share_freed(fitness, rubber: dict) -> float | None:
    """The share of the misfit's excess chi2/nu over 1 that the fit with the rubber's ratio
    free (``rubber["free_chi2_per_nu"]``) takes away; None where the ratio was not freed or
    the fit was not judged, or chi2/nu is not above 1 (a branch alone misfits)."""
    freed = rubber.get("free_chi2_per_nu")
    if freed is None or not fitness.reduced > 1:
        return None
    return (fitness.reduced - freed) / (fitness.reduced - 1)


def fe_ratio_note(test: dict, rubber: dict, fitness, runs, options) -> str | None:
    """The note on the FE model's own test of the ratio (:func:`fe_ratio_test`) where it would
    separate C10 and C01: the command that tests it (:func:`search_model_note`) where the fit
    follows the runs within their noise or the ratio freed takes away at least
    :data:`RATIO_EXPLAINS_MISFIT` of the misfit (:func:`misfit_share_freed`); else no search
    direction: the misfit first, and what to check. None where it would not separate them."""
    if not test["separates"]:
        return None
    share = misfit_share_freed(fitness, rubber)
    if not fitness.misfit or (share is not None and share >= RATIO_EXPLAINS_MISFIT):
        return search_model_note(test, runs, options)
    freed = ("the rubber's ratio was not freed" if share is None else
             f"the ratio freed takes away {100 * share:.2g} % of it (chi2/nu "
             f"{rubber['free_chi2_per_nu']:.3g})")
    return (f"the surrogate's box cut the test of C10 and C01, and the FE model's change with the "
            f"ratio at this optimum would separate them, but the fit misfits (chi2/nu "
            f"{fitness.reduced:.3g}) and {freed}: the step is taken at an optimum the misfit "
            "has moved and points where the misfit pulls, so no search for the ratio is "
            f"advised; explain the misfit first ({fitness.checks()}) and identify again, which "
            "tests the ratio again")


def fe_ratio_test(source, fe: ModelStatic, runs, best, braid: str | None) -> dict:
    """What the FE model would make of the rubber's ratio where the search's own test of it was
    cut by the surrogate: the fit at the assumed ratio (``best``) refitted with C01's share
    free by one linearised step, the share's column the FE model's (at the optimum and at a
    share :data:`RATIO_STEP` further: two sweeps per run), its 95 % interval from the Fisher
    matrix (the residuals' variance their own) widened as the rule's is: by the declared
    tolerances every run shares (:func:`shared_terms`) and, with the braid in doubt, one-sided
    by the other braid's refit (a sweep per run more); as C01/C10, and whether that would
    separate C10 and C01 by the rule's width or by excluding the assumed ratio
    (``separates``)."""
    share = fitting.assumed_share(best.values)
    assumed, said = fitting.assumed_ratio(best.values)
    step = RATIO_STEP if share + RATIO_STEP < 1.0 else -RATIO_STEP
    fe_tables = fe.tables(runs, best.values)
    sweeps = 2 * len(runs)
    column = best.w * _hold_change(source, runs, best, _minus(
        fe.tables(runs, {**best.values, "c01_fraction": share + step}), fe_tables)) / step
    if not np.any(column):  # the runs do not see the ratio at all
        top = fitting.TERM_BOUNDS["c01_fraction"][1]
        return {"ratio": assumed, "ratio_ci": [0.0, top / (1.0 - top)], "assumed": assumed,
                "assumed_from": said, "sweeps": sweeps, "separates": False}
    J = best.weighted_jacobian
    J = np.column_stack([J[:, np.sqrt(np.sum(J ** 2, axis=0)) > 0], column])
    # the share's row of the linearised refit: its change for a change of the residuals
    refit = np.linalg.pinv(J)[-1]
    centre = min(max(share - refit @ best.weighted_residual, 0.0), 0.999)
    variance = best.rss / max(best.n - J.shape[1], 1)
    half = 1.96 * math.sqrt(variance * np.linalg.pinv(J.T @ J)[-1, -1]) + sum(
        abs(refit @ (best.w * sensitivity)) * bound
        for sensitivity, bound in shared_terms(source, runs, best).values())
    low, high = centre - half, centre + half
    if braid_skipped(fe, best, braid) is None:
        shift = -refit @ (best.w * _hold_change(source, runs, best, _minus(
            _other_braid(fe).tables(runs, best.values), fe_tables)))
        low, high = min(low, low + shift), max(high, high + shift)
        sweeps += len(runs)
    ratio = centre / (1 - centre)
    low, high = (min(max(v, 0.0), 0.999) / (1 - min(max(v, 0.0), 0.999)) for v in (low, high))
    narrow = ratio > 0 and (1 - RATIO_WIDTH) * ratio <= low and high <= (1 + RATIO_WIDTH) * ratio
    return {"ratio": float(ratio), "ratio_ci": [float(low), float(high)], "assumed": assumed,
            "assumed_from": said, "sweeps": sweeps,
            "separates": bool(narrow or not low <= assumed <= high)}


def ratio_freed(rubber: dict) -> dict | None:
    """What the fit with the rubber's ratio free gains where one scale at the assumed ratio is
    kept (the runs do not separate C10 and C01) though freeing it lowers chi2 by more than
    :data:`RATIO_LIKELIHOOD`: its ratio, chi2/nu and whether it follows the runs within their
    noise (:attr:`mkm.identify.goodness.Goodness.ratio_freed`); else None."""
    if (rubber.get("separated") or "free_chi2_per_nu" not in rubber
            or not rubber["chi2_improvement"] > RATIO_LIKELIHOOD):
        return None
    return {"assumed": rubber["assumed_C01_over_C10"], "assumed_from": rubber["assumed_from"],
            "ratio": rubber["ratio_C01_over_C10"], "ratio_ci": rubber["ratio_ci"],
            "chi2_improvement": rubber["chi2_improvement"],
            "chi2_per_nu": rubber["free_chi2_per_nu"],
            "within_noise": rubber["free_within_noise"]}


#: how a note names what :func:`shared_terms` draws into the intervals
DECLARED_SAID = {"D0_mm": "the tube's diameter", "t0_mm": "its wall",
                 "pressure_gain": "the monitor's gain",
                 "pressure_hysteresis_bar": "the monitor's hysteresis"}


def _declared_holds_ratio(rubber: dict) -> str:
    """Where the bench's declared tolerances alone keep the assumed ratio among those the
    runs allow: what the fit with the ratio free gains, and what to do; else ''."""
    declared = rubber.get("rejects_silastic_ratio_but_for_declared")
    if not declared:
        return ""
    low, high = declared["ratio_ci"]
    said = ", ".join(v for n, v in DECLARED_SAID.items() if n in declared["terms"])
    return (f"; yet the fit with the ratio free lowers chi2 by {rubber['chi2_improvement']:.3g} "
            f"(C01/C10 {rubber['ratio_C01_over_C10']:.3g}), and but for the tolerances "
            f"declared of {said} (drawn into the intervals: they trade with the ratio) the runs "
            f"reject {rubber['assumed_from']} (95 % interval {low:.3g}-{high:.3g}): where those "
            "are known closer, declare them (a bench's [muscle.tolerances] and [regulator]; a "
            "table's mkm import --tolerance D0=MM,t0=MM and --accuracy pressure=...) and "
            "identify again")


def _box_cut(rubber: dict) -> str:
    """Where the box searched stopped the ratio's interval (the runs not tested beyond), or
    ''."""
    cut = rubber.get("ratio_box_cut")
    if not cut:
        return ""
    return (f"; the {rubber['searched_with']}'s box stops the search at C01/C10 "
            f"{' and '.join(f'{r:.3g}' for r in cut)}: the runs were not tested beyond, so "
            "the interval is open there")


def _assumed_ratio_terms(source, runs, best, rubber) -> dict:
    """What a rubber ratio assumed (Silastic S's or the declared rubber's, not separated by the
    runs) may have wrong, for
    the prediction band: the fit redone with C01/C10 held at each end of what the runs allow
    (the free fit's 95 % interval where there is one) within the practical range, as one-sided
    terms (each parameter's shift and C01's share's). At the runs' own eps the refits reproduce
    them; at another eps they can part (the threshold's rise with eps bends with the ratio: a
    C01 = 0 rubber fitted at Silastic S's ratio on eps 0 and 12.2 % starts pulling late at
    6 %), and the band holds that. The parameters' intervals are the assumption's (the note
    says so)."""
    low, high = PRACTICAL_RANGE.C01_per_C10
    if "ratio_ci" in rubber:
        low, high = (min(max(r, low), high) for r in rubber["ratio_ci"])
    box = source.share_bounds(best.values["rubber_scale"])
    assumed, said = fitting.assumed_share(best.values), fitting.assumed_ratio(best.values)[1]
    terms = {}
    for ratio in sorted({low, high}):
        share = min(max(ratio / (1.0 + ratio), box[0]), box[1])
        if abs(share - assumed) < 1e-3:
            continue
        name = f"C01/C10 {share / (1.0 - share):.3g}"
        try:
            refit = fitting.fit(source, runs, best.names, {**best.values, "c01_fraction": share})
        except RuntimeError as exc:
            terms[name] = {"skipped": f"the refit at this ratio failed: {exc}"}
            continue
        shift = {n: refit.values[n] - best.values[n] for n in STATIC_NAMES if n in best.names}
        terms[name] = {"kind": "one-sided",
                       "what": f"the fit at {name} minus the fit at {said} ratio",
                       "shift": {**shift, "c01_fraction": share - assumed}}
    return terms


def _identifiability(runs, best, boot) -> list[str]:
    """Notes on what the runs do not fix: a confounding only where it makes an interval wide
    (wider than :data:`PRECISION`: the issue's targets), a parameter the runs do not inform."""
    notes = []
    names = list(best.names)
    wide = {n: _wide(n, best.values[n], boot["interval"][n]) for n in names}
    if "theta0_deg" in names and "rubber_scale" in names:
        i, j = names.index("theta0_deg"), names.index("rubber_scale")
        corr = float(boot["correlation"][i, j])
        eps = sorted({round(r.eps, 4) for r in runs})
        if len(eps) == 1 and (wide["theta0_deg"] or wide["rubber_scale"]):
            notes.append(f"{ONE_EPS_NOTE} "
                         f"({eps[0]:g}; correlation {corr:+.2f}): a run at a second eps "
                         "separates them")
        elif len(eps) > 1 and abs(corr) > CONFOUNDED and (wide["theta0_deg"] or
                                                          wide["rubber_scale"]):
            # a second eps separates them unless another parameter fitted trades against both
            # (a wall fitted with them: its own notes follow)
            others = [n for k, n in enumerate(names) if n not in ("theta0_deg", "rubber_scale")
                      and abs(boot["correlation"][i, k]) > CONFOUNDED
                      and abs(boot["correlation"][j, k]) > CONFOUNDED]
            widened = " and ".join(n for n in ("theta0_deg", "rubber_scale") if wide[n])
            notes.append(f"theta0 and the rubber are not separated by the runs at eps "
                         f"{', '.join(f'{e:g}' for e in eps)} (correlation {corr:+.2f})"
                         + (f": {' and '.join(others)}, fitted with them, trades against both, "
                            f"so the interval of {widened} is wide; where "
                            f"{' and '.join(others)} is known, leave it out of --params"
                            if others else f": the interval of {widened} is wide because of "
                            "it"))
        elif len(eps) > 1:
            notes.append(f"theta0 and the rubber are separated by the runs at eps "
                         f"{', '.join(f'{e:g}' for e in eps)} (correlation {corr:+.2f})")
    for (a, b) in itertools.combinations(range(len(names)), 2):
        corr = float(boot["correlation"][a, b])
        pair = {names[a], names[b]}
        if (abs(corr) > CONFOUNDED and pair != {"theta0_deg", "rubber_scale"}
                and (wide[names[a]] or wide[names[b]])):
            widened = " and ".join(n for n in (names[a], names[b]) if wide[n])
            notes.append(f"{names[a]} and {names[b]} are confounded (correlation {corr:+.2f}):"
                         f" the interval of {widened} is wide because of it")
    for name in (*fitting.GEOMETRY, "L0_mm"):
        if name in names:
            i = names.index(name)
            low, high = boot["interval"][name]
            with_ = ", ".join(f"{names[j]} {boot['correlation'][i, j]:+.2f}"
                              for j in range(len(names)) if j != i and names[j] in (
                                  *STATIC_NAMES, "pressure_offset_bar"))
            notes.append(f"{name} fitted: {best.values[name]:.3f} mm (95 % CI {low:.3f}-"
                         f"{high:.3f}; declared {float(runs[0].muscle[name]):g} mm); "
                         f"its correlation with {with_}")
    if "L0_mm" in names and min(r.eps for r in runs) > 0:
        notes.append(_rest_length_extrapolated(runs, best.values["L0_mm"]))
    for name, ok in boot["identifiable"].items():
        if not ok:
            notes.append(f"{name} is not identifiable from these runs: its interval is its "
                         "search bound")
    if "log_tau" in names and best.values["creep_fraction"] < CREEP_IDENTIFIABLE:
        notes.append("creep_fraction is near 0: creep_tau_s is not identifiable")
    return notes


def _rest_length_extrapolated(runs, L0_mm: float) -> str:
    """The note on a rest length fitted from runs all held shorter than the declared one: the
    fit carries the model's threshold from their eps back to where the muscle pulls from 0 bar,
    and near the rest length a muscle's threshold may rise as no rung of the ladder has it (the
    published Festo maps, docs/guide/threshold.md), an error its interval does not hold."""
    held = sorted(r.held_mm for r in runs)
    return (f"{REST_EXTRAPOLATED_NOTE}: L0_mm {L0_mm:.1f} mm is extrapolated from runs held at "
            f"{held[0]:.4g}-{held[-1]:.4g} mm (eps {1.0 - held[-1] / L0_mm:.3g}-"
            f"{1.0 - held[0] / L0_mm:.3g} of it) along the model's threshold, and its interval "
            "does not hold how far a muscle's threshold departs from the model's near its rest "
            "length (on the published Festo maps, more steeply than any rung of the ladder "
            "follows): to predict at or near the rest length, identify with a run held there "
            "among them, or declare the rest length (mkm import --L0) and leave L0 out of "
            "--params")


def _zero_said(runs, best, boot) -> str | None:
    """A note when the load cell's fitted zero is not 0 within its interval: the calibration
    is the muscle's without it, the runs' forces still hold it; how to take it out of them."""
    if "force_zero_N" not in best.names:
        return None
    zero, (low, high) = best.values["force_zero_N"], boot["interval"]["force_zero_N"]
    if low <= 0.0 <= high:
        return None
    again = (f"import the tables again with --tare at the tare each import took (run.json's "
             f"imported_from.tare_N) {zero:+.3g} N" if all(r.imported for r in runs)
             else "tare the cell (mkm tare) before the next run")
    return (f"the load cell read {zero:+.3g} N (95 % CI {low:+.3g} to {high:+.3g}) with the "
            "muscle slack: the calibration is the muscle's without it, but the runs' forces "
            f"still hold it, and report and export show them as recorded; {again}")


def _zero_unpinned(best, boot) -> str | None:
    """A note when the load cell's fitted zero has fewer than two steps where the fitted muscle
    is slack (:func:`mkm.identify.intervals.slack_steps`): only those tell it from the muscle's
    force, and the bootstrap shows their noise only from two."""
    slack = boot.get("slack_steps", 0)
    if "force_zero_N" not in best.names or slack > 1:
        return None
    some = "no step" if slack == 0 else "one step"
    return (f"the load cell's zero is told from the muscle's force by {some} where the fitted "
            "muscle is slack: its interval is what the threshold's line leaves it, and may be "
            "wide; runs that start and end below the threshold (two steps or more where the "
            "muscle pulls nothing) pin it")


def _wide(name: str, value: float, interval) -> bool:
    """Whether the 95 % interval's half-width exceeds :data:`PRECISION` (relative for the
    rubber scale; the monitor's offset, a nuisance, is never wide)."""
    if name not in PRECISION:
        return False
    half = (interval[1] - interval[0]) / 2
    return half > PRECISION[name] * (abs(value) if name == "rubber_scale" else 1.0)


def _branch_errors(run, predicted) -> dict:
    """Largest |Err%| (Equation 7 over the run) on the rising and the falling steps; NaN for a
    run without force (a slack muscle all the way: no Equation 7, as in the report)."""
    measured = run.steps["force_N_mean"].to_numpy(dtype=float)
    if not np.nanmax(measured, initial=0.0) > 0:
        err = np.full(measured.shape, np.nan)
        return {"rising": float("nan"), "falling": float("nan"), "err_pct": err}
    err = equation7_err_pct(measured, predicted)
    up = run.steps["direction"].to_numpy() == "up"
    return {"rising": float(np.max(np.abs(err[up]))) if up.any() else float("nan"),
            "falling": float(np.max(np.abs(err[~up]))) if (~up).any() else float("nan"),
            "err_pct": err}


def predict_runs(run_dirs, values: dict, model: str = "axisym") -> list[dict]:
    """Each run predicted by ``model`` with friction and creep at ``values`` (as
    :attr:`Identification.values` names them): the step means [N] and the largest |Err%| of
    each branch (``rising``, ``falling``, ``err_pct`` per step)."""
    runs = load_runs(run_dirs)
    internal = fitting.internal_values(values)
    predicted = fitting.step_predictions(ModelStatic(model), runs, internal)
    return [{"run": run.name, "predicted_N": p, **_branch_errors(run, p)}
            for run, p in zip(runs, predicted, strict=True)]


def held_out_groups(runs) -> list[tuple[str, list[int]]]:
    """What is held out in turn: each run (over eps), and each length when the runs have
    several lengths and one of them several runs (a whole length held out)."""
    groups = [("run", [k]) for k in range(len(runs))] if len(runs) > 1 else []
    lengths = fitting.by_length(runs)
    if len(lengths) > 1 and any(len(m) > 1 for m in lengths.values()):
        groups += [("length", members) for members in lengths.values()]
    return groups


def _checks(runs, fe, source, best, nominal) -> list[dict]:
    """Per run: the nominal model's and the identified model's prediction, and the held-out
    ones (:func:`held_out_groups`: the run predicted from the others by the FE model)."""
    before = fitting.step_predictions(fe, runs, nominal)
    after = fitting.step_predictions(source, runs, best.values)
    out = [{"run": run.name, "eps": run.eps, "L0_mm": float(run.muscle["L0_mm"]),
            "nominal": before[k], "identified": after[k],
            "nominal_err": _branch_errors(run, before[k]),
            "identified_err": _branch_errors(run, after[k])}
           for k, run in enumerate(runs)]
    # the rest length no shorter than any run's held length, the held-out ones' too
    given = {n: fitting.bounds_of(n, source, runs, best.values) for n in ("L0_mm",)
             if n in best.names}
    for kind, members in held_out_groups(runs):
        others = [r for j, r in enumerate(runs) if j not in members]
        kept = source
        if isinstance(source, Corrected):
            for k in sorted(members, reverse=True):
                kept = kept.without(k)
        prefix = "heldout" if kind == "run" else "length_heldout"
        try:
            held = fitting.fit(kept, others, best.names, best.values,
                               max_nfev=CANDIDATE_EVALUATIONS, given=given)
            predicted = fitting.step_predictions(fe, [runs[k] for k in members], held.values)
        except RuntimeError as exc:
            # the other runs do not fix the parameters, or they took the model where it has no
            # force for the held-out run (a gap at its bound, an angle past the lock): said
            for k in members:
                nan = np.full(len(runs[k].steps), np.nan)
                out[k].update({prefix: nan, f"{prefix}_failed": str(exc),
                               f"{prefix}_err": {"rising": np.nan, "falling": np.nan,
                                                 "err_pct": nan}})
            continue
        for k, p in zip(members, predicted, strict=True):
            out[k].update({prefix: p, f"{prefix}_err": _branch_errors(runs[k], p),
                           f"{prefix}_values": fitting.full_parameters(held.values)})
    return out
