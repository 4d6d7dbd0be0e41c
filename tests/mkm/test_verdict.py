"""The report's verdict sentence: the model to use, how far, how fast, consistent or not, and
why auto's pick may differ (rows shaped as :func:`mkm.scoring.summarise_run` writes them)."""

from __future__ import annotations

import math

import pytest

from mkm.verdict import (
    AutoPick,
    advice_command,
    format_seconds,
    gives_advice,
    muscle_advice,
    recommend,
    verdict,
)


def _row(model, err, seconds, consistent=True, valid=5, band=0.5):
    return {"model": model, "points": 5, "valid_points": valid, "max_abs_err_pct": err,
            "seconds_per_point": seconds, "band_pct": band, "consistent": consistent,
            "worst_E_n": 2.4 if consistent is False else 0.3, "worst_step": 4}


NAMES = {"eq2": "Equation 2 (Chou-Hannaford)", "thickwall": "Thick-wall (Klute-Hannaford)",
         "surrogate": "Surrogate", "axisym": "FE model (axisymmetric)"}
# The imported run of the issue: thick-wall 1.60 % off, the surrogate 5.95 %
ROWS = [_row("eq2", 9.8, 6e-6, False), _row("thickwall", 1.60, 5.84e-5),
        _row("surrogate", 5.95, 2e-4, False), _row("axisym", 5.70, 1.2, False)]


@pytest.mark.parametrize(("seconds", "text"), [
    (5.84e-05, "58.4 µs"), (6.0e-6, "6.00 µs"), (0.0123, "12.3 ms"), (1.2, "1.20 s"),
    (250.0, "250 s"), (9.48e-7, "0.948 µs"), (4e-10, "0.000400 µs"), (math.nan, "—"),
    (0.0, "—")])
def test_durations_read_in_units_never_in_scientific_notation(seconds, text):
    assert format_seconds(seconds) == text
    assert "e-" not in format_seconds(seconds) and "e+" not in format_seconds(seconds)


def test_the_cheapest_model_within_the_tolerance_is_the_one_to_use():
    assert recommend(ROWS, 0.02) == (ROWS[1], True)
    # loose: Equation 2 is the cheapest within 10 %
    assert recommend(ROWS, 0.10) == (ROWS[0], True)
    # tight: none is within, the closest is named
    assert recommend(ROWS, 0.01) == (ROWS[1], False)
    # a model invalid at a step is not used while one valid at every step exists
    partial = [_row("eq2", 0.5, 1e-6, valid=3), ROWS[1]]
    assert recommend(partial, 0.02) == (ROWS[1], True)


def test_the_sentence_names_model_distance_band_speed_and_consistency():
    text = verdict("Run 1", ROWS, NAMES, 0.02)
    assert text == ("Run 1: use Thick-wall (Klute-Hannaford), the cheapest model within 2 % of "
                    "the measurement: 1.60 % off at worst (band ± 0.5 %), 58.4 µs per force, "
                    "consistent with the measurement (|E_n| <= 1 at every step; 1 of 4 models "
                    "is).")
    # printed on a Windows console too: its code page (cp1252) has no "≤", which came out
    # as "\u2264"
    text.encode("cp1252")
    none = verdict("Run 1", ROWS, NAMES, 0.01)
    assert "no model is within 1 % of the measurement; the closest is Thick-wall" in none
    bad = verdict("Run 1", ROWS, NAMES, 0.10)  # Equation 2: the cheapest within 10 %
    assert "use Equation 2 (Chou-Hannaford)" in bad
    assert "not consistent with the measurement (E_n = +2.4 at step 4; 1 of 4 models is; " \
        "the models have no braid friction or creep)" in bad
    # an imported table of one branch shows no friction or creep: they explain nothing there
    table = verdict("Run 1", ROWS, NAMES, 0.10, dynamics=False)
    assert "(E_n = +2.4 at step 4; 1 of 4 models is)." in table and "friction" not in table


def test_when_auto_picks_another_model_the_sentence_says_why_and_points_to_the_muscle():
    pick = AutoPick("surrogate", "Surrogate", 0.8, "")
    text = verdict("Run 1", ROWS, NAMES, 0.02, pick, False, (NAMES["axisym"], 5.70),
                   muscle_advice("runs/r1"))
    # auto's choice and the measured ranking, reconciled in the same sentence
    assert text.endswith("auto at 2 % picks Surrogate instead, bounding its error against the "
                         "FE model (0.80 %), not against this measurement, from which it is "
                         "5.95 % off: the FE model itself is 5.70 % off, more than that bound, "
                         "which points to the muscle, not the model: identify it (`mkm identify "
                         "runs/r1`).")
    # without an FE model in the report, the triangle inequality bounds its distance from below
    bare = verdict("Run 1", ROWS[:3], NAMES, 0.02, pick, False, None)
    assert f"the FE model itself is at least {5.95 - 0.8:.2f} % off" in bare
    same = verdict("Run 1", ROWS, NAMES, 0.02, AutoPick("thickwall", NAMES["thickwall"], 1.0,
                                                        ""), True)
    assert same.endswith("auto at 2 % picks it too.")


def test_when_auto_picks_a_model_outside_the_report_the_fe_models_distance_names_the_muscle():
    """A 40 mm natural-rubber tube at 4 bar on the simulated bench (theta0 27 deg, C10 0.20
    MPa, C01 0.02 MPa): the FE model is 41.59 % off its eps 0 run and auto picks the practical
    range's surrogate, 1.18 % from the FE model, which the report does not score; so that
    surrogate is at least 41.59 - 1.18 % off the measurement, far beyond 2 %: identify it."""
    rows = [_row("eq2", 40.36, 1.2e-6, False), _row("thickwall", 43.99, 9e-6, False),
            _row("axisym", 41.59, 5e-3, False), _row("surrogate", 29.27, 3.6e-5, False, valid=3)]
    pick = AutoPick("surrogate:kind=muscle-gp-range", "Surrogate, kind=muscle-gp-range", 1.18,
                    "")
    fe = (NAMES["axisym"], 41.59)
    assert gives_advice(rows, NAMES, 0.02, pick, False, fe)
    text = verdict("Run 1", rows, NAMES, 0.02, pick, False, fe, muscle_advice("runs/r1"))
    assert text.endswith("auto at 2 % picks Surrogate, kind=muscle-gp-range instead, bounding "
                         "its error against the FE model (1.18 %), not against this measurement "
                         "(Surrogate, kind=muscle-gp-range is not among this report's models): "
                         "the FE model itself is 41.59 % off, more than that bound, which "
                         "points to the muscle, not the model: identify it (`mkm identify "
                         "runs/r1`).")
    # an FE model within the tolerance plus auto's bound: that surrogate may well be within it
    near = (NAMES["axisym"], 2.5)
    assert not gives_advice(rows, NAMES, 0.02, pick, False, near)
    assert verdict("Run 1", rows, NAMES, 0.02, pick, False, near).endswith(
        "(Surrogate, kind=muscle-gp-range is not among this report's models).")


def test_when_auto_agrees_but_the_measurement_is_beyond_the_tolerance_the_muscle_is_named():
    """mkm demo's case: the surrogate is the closest (4.63 %), auto trusts it within 2 % of the
    FE model: both say the same model, and the sentence says why it is still 4.63 % off."""
    rows = [_row("eq2", 20.0, 6e-6, False), _row("surrogate", 4.63, 4.2e-5),
            _row("axisym", 4.9, 1.2)]
    text = verdict("Run 1", rows, NAMES, 0.02, AutoPick("surrogate", "Surrogate", 1.1, ""),
                   True, (NAMES["axisym"], 4.9), muscle_advice("r1"))
    assert "no model is within 2 % of the measurement; the closest is Surrogate, 4.63 % off" \
        in text
    assert text.endswith("auto at 2 % picks it too, bounding its error against the FE model "
                         "(1.10 %), not against this measurement: the FE model itself is 4.90 % "
                         "off, more than that bound, which points to the muscle, not the model: "
                         "identify it (`mkm identify r1`).")


def test_with_an_identified_calibration_the_advice_says_whether_it_saw_the_run():
    """The published DMSP-10's rest length, scored with the calibration identified on its
    eps 0.064 and 0.184 lengths: identifying that run alone (the advice without a calibration)
    would fit theta0 and the rubber on one eps, where they are confounded."""
    identified = [{"run": f"r{k}", "path": f"runs/r{k}", "muscle": {"eps": eps}}
                  for k, eps in ((2, 0.064), (4, 0.184))]
    held_out = muscle_advice("runs/r1", identified, "calibration.json")
    assert held_out == ("which points to the muscle, not the model: the calibration "
                        "(calibration.json), identified on the runs at eps 0.064, 0.184, does "
                        "not carry over to this run; identify with it among them (`mkm identify "
                        "runs/r2 runs/r4 runs/r1`)")
    seen = muscle_advice("elsewhere/r4", identified, "calibration.json")
    assert seen.startswith("although the calibration (calibration.json) was identified on this "
                           "run with the others: the model does not fit them all")
    assert "points to the muscle" not in seen
    pick = AutoPick("surrogate", "Surrogate", 0.8, "")
    text = verdict("Run 1", ROWS, NAMES, 0.02, pick, False, (NAMES["axisym"], 5.70), held_out)
    assert text.endswith(f"more than that bound, {held_out}.")


def test_a_calibration_that_fits_its_runs_within_their_noise_is_not_called_a_misfit():
    """A fresh in-family muscle (`[sim.truth]` drawn with numpy seed 2026120571: a 41.5 mm tube
    at 4 bar, braid friction 2.6 %, creep 2.0 %) identified from its three runs at chi2/nu 1.0:
    the report's static FE model, with that calibration, is 4.1 % off its own runs, the
    friction and creep the static models lack, not a misfit of the muscle."""
    identified = [{"run": f"r{k}", "path": f"runs/r{k}", "muscle": {"eps": eps}}
                  for k, eps in ((1, 0.0), (2, 0.165), (3, 0.17))]
    fitted = [{"parameter": "hysteresis_fraction", "value": 0.025868, "status": "fitted"},
              {"parameter": "creep_fraction", "value": 0.020058, "status": "fitted"}]
    fit = {"misfit": {"judged": True, "chi2_per_nu": 0.998, "misfit_branches": []},
           "parameters": fitted}
    advice = muscle_advice("runs/r1", identified, "calibration.json", fit=fit)
    assert advice == ("although the calibration (calibration.json) was identified on this run "
                      "with the others and fits them within their noise (chi2/nu 1): the braid "
                      "friction 2.6 % and creep 2.0 % identified with it, which these static "
                      "models lack, are that distance (add the rung that has them: --models "
                      "friction,...; identify's steps.csv has the steps predicted with them)")
    # a misfit (a monitor 0.022 bar off: chi2/nu 164) is still named as one
    misfit = {**fit, "misfit": {"judged": True, "chi2_per_nu": 164.0,
                                "misfit_branches": ["r1 loading"]}}
    assert "does not fit them all with one muscle" in muscle_advice(
        "runs/r1", identified, "calibration.json", fit=misfit)
    # a fit nobody judged (imported tables without their accuracy) was called one
    # too, 'the identification's misfit notes say where', which has none; and a calibration
    # identified on this run alone was 'identified on this run with the others'
    unjudged = {**fit, "misfit": {"judged": False}}
    static = {**unjudged, "parameters": []}
    assert muscle_advice("runs/r1", identified, fit=static) == (
        "although the calibration was identified on this run with the others: identify could "
        "not judge that fit (the runs show no noise to judge it by), and this distance is the "
        "identified model's own miss: weigh it against the instruments' accuracy (mkm import "
        "--accuracy force=...,pressure=... lets identify and the report judge it)")
    # a hand-made 8 mm latex muscle's step tables, braid friction 5.0 % fitted: the report's
    # static FE model 4.95 % off was called the identified model's own miss, which identify
    # put at 0.28 % with its friction
    assert muscle_advice("runs/r1", identified, fit=unjudged) == (
        "although the calibration was identified on this run with the others: identify could "
        "not judge that fit (the runs show no noise to judge it by), and the braid friction "
        "2.6 % and creep 2.0 % identified with it, which these static models lack, are part of "
        "this distance (add the rung that has them: --models friction,...), the rest is the "
        "identified model's own miss: weigh it against the instruments' accuracy (mkm import "
        "--accuracy force=...,pressure=... lets identify and the report judge it)")
    alone = identified[:1]
    assert muscle_advice("runs/r1", alone, fit=unjudged).startswith(
        "although the calibration was identified on this run: identify could not judge")
    assert muscle_advice("runs/r1", alone, fit=misfit).startswith(
        "although the calibration was identified on this run: the model does not fit it with "
        "one muscle")


def test_the_friction_rung_a_report_scores_is_not_advised_again_and_explains_the_distance():
    """A 60 mm muscle identified from its three simulated runs (friction 3.0 %, creep 2.0 %,
    chi2/nu 0.62), reported with `--models eq2,thickwall,axisym,surrogate,friction`: the verdict
    said 'use Static model + friction and creep ... 0.02 % off' and then 'add the rung that has
    them: --models friction,...', the rung it had just named; on a table of that muscle the
    calibration had not seen, the friction rung 1.69 % off, that the calibration 'does not carry
    over to this run; identify with it among them'."""
    identified = [{"run": f"r{k}", "path": f"runs/r{k}", "muscle": {"eps": eps}}
                  for k, eps in ((1, 0.0), (2, 0.1), (3, 0.2))]
    fitted = [{"parameter": "hysteresis_fraction", "value": 0.030067, "status": "fitted"},
              {"parameter": "creep_fraction", "value": 0.020133, "status": "fitted"}]
    fit = {"misfit": {"judged": True, "chi2_per_nu": 0.625, "misfit_branches": []},
           "parameters": fitted}
    static = ["eq2", "thickwall", "axisym", "surrogate"]
    # the --models to type, whole: the report's own models and the friction rung
    assert muscle_advice("runs/r1", identified, fit=fit, models=static).endswith(
        "(add the rung that has them: --models eq2,thickwall,axisym,surrogate,friction; "
        "identify's steps.csv has the steps predicted with them)")
    assert "(the friction rung of this report has them;" in muscle_advice(
        "runs/r1", identified, fit=fit, models=[*static, "friction"])
    names = {**NAMES, "friction": "Static model + friction and creep"}
    rows = [_row("eq2", 24.4, 1e-6), _row("thickwall", 3.19, 5e-6), _row("axisym", 4.62, 4e-3),
            _row("surrogate", 4.63, 1e-4), _row("friction", 1.69, 8e-3)]
    pick = AutoPick("thickwall", names["thickwall"], 1.66, "")
    held_out = muscle_advice("runs/r4", identified, "calibration.json", fit=fit,
                             models=[r["model"] for r in rows])
    assert "does not carry over" in held_out
    text = verdict("Run 1", rows, names, 0.02, pick, False, (NAMES["axisym"], 4.62), held_out)
    assert text.startswith("Run 1: use Static model + friction and creep, the cheapest model "
                           "within 2 % of the measurement: 1.69 % off")
    assert text.endswith(
        "the FE model itself is 4.62 % off, more than that bound, and the braid friction and "
        "creep Static model + friction and creep adds to the static force are that distance "
        "(Static model + friction and creep is 1.69 % off).")
    # beyond the tolerance the rung explains nothing: the muscle advice stands
    rows[-1] = _row("friction", 2.5, 8e-3)
    assert verdict("Run 1", rows, names, 0.02, pick, False, (NAMES["axisym"], 4.62),
                   held_out).endswith(f"more than that bound, {held_out}.")


def test_the_identify_it_suggests_takes_every_run_of_the_muscle_at_hand():
    # mkm demo's two runs of one prototype: one eps alone confounds the angle and the rubber
    assert muscle_advice("runs/r1", muscle_runs=["runs/r1", "runs/r2"]) == (
        "which points to the muscle, not the model: identify it from its 2 runs here "
        "(`mkm identify runs/r1 runs/r2`)")
    assert muscle_advice("runs/r1", muscle_runs=["runs/r1"]).endswith(
        "identify it (`mkm identify runs/r1`)")


def test_a_verdict_can_refer_to_the_identify_command_said_once_for_several_runs():
    """Several runs of one muscle advise the same identify: the report says it once and each
    verdict refers to it; whether a verdict gives the advice at all is the sentence's own test
    (auto's pick further from the measurement than the tolerance)."""
    runs = ["runs/r1", "runs/r2", "runs/r3"]
    assert muscle_advice("runs/r2", muscle_runs=runs, command_below=True) == (
        "which points to the muscle, not the model: identify it from its 3 runs here "
        "(the mkm identify command below)")
    assert advice_command("runs/r2", muscle_runs=runs) == "mkm identify runs/r1 runs/r2 runs/r3"
    identified = [{"run": "r1", "path": "runs/r1", "muscle": {"eps": 0.0}}]
    assert advice_command("runs/r1", identified) is None  # its own run: no identify helps
    assert advice_command("runs/r2", identified) == "mkm identify runs/r1 runs/r2"
    # a calibration identified with its rest length fitted: the advice fits it again (the
    # comma list quoted: PowerShell reads a bare one as an array)
    options = ["--params", "theta0,rubber,L0", "--model", "axisym:mesh=coarse"]
    assert advice_command("runs/r2", identified, options=options) == (
        'mkm identify runs/r1 runs/r2 --params "theta0,rubber,L0" --model axisym:mesh=coarse')
    assert muscle_advice("runs/r2", identified, fit={"options": options}).endswith(
        '(`mkm identify runs/r1 runs/r2 --params "theta0,rubber,L0" --model '
        'axisym:mesh=coarse`)')
    # the surrogate, auto's pick, is 5.95 % off: beyond 2 %, within 10 %
    pick = AutoPick("surrogate", "Surrogate", 0.8, "")
    assert gives_advice(ROWS, NAMES, 0.02, pick, False)
    assert "the mkm identify command below" in verdict(
        "Run 1", ROWS, NAMES, 0.02, pick, False, None,
        muscle_advice("runs/r1", muscle_runs=runs, command_below=True))
    assert not gives_advice(ROWS, NAMES, 0.10, pick, False)
    assert not gives_advice(ROWS, NAMES, 0.02, None, False)


def test_the_runs_a_calibration_did_not_see_are_advised_one_identification_together():
    """A 40 mm natural-rubber tube identified from its runs at eps 0 and 0.12, reported with
    its runs at eps 0.05 and 0.20 too: the calibration carries over to neither, and each verdict
    advised identify with the calibration's runs and itself alone, two commands that each left
    the other run out; both advise the one command of all four now, said once below them."""
    identified = [{"run": "r1", "path": "runs/r1", "muscle": {"eps": 0.0}},
                  {"run": "r2", "path": "runs/r2", "muscle": {"eps": 0.12}}]
    at_hand = ["elsewhere/r1", "elsewhere/r2", "runs/r3", "runs/r4"]
    for run in ("runs/r3", "runs/r4"):
        assert advice_command(run, identified, at_hand) == (
            "mkm identify runs/r1 runs/r2 runs/r3 runs/r4")
    # a run the calibration saw, under another path: identifying again would not help
    assert advice_command("elsewhere/r2", identified, at_hand) is None


def test_a_slack_run_is_said_to_be_unscorable_not_without_valid_forces():
    # the published DMSP-10 at its shortest length: 0 N at every step, every model valid
    slack = [_row("eq2", math.nan, 1e-6), _row("thickwall", math.nan, 2e-5)]
    assert verdict("Run 1 (eps 20.8 %)", slack, NAMES, 0.02) == (
        "Run 1 (eps 20.8 %): no model can be scored: the run's largest measured force is not "
        "above 0 N or its steps' uncertainty (a slack muscle), and Equation 7's error is "
        "relative to it.")
    invalid = [_row("eq2", math.nan, 1e-6, valid=0)]
    assert verdict("Run 1", invalid, NAMES, 0.02) == (
        "Run 1: no model gives a valid force at any kept step: nothing to use.")


def test_a_slack_run_names_the_model_closest_to_it_and_whether_it_is_consistent():
    """The published DMSP-10-250 at eps 0.208 (0 N to 6.5 bar, imported with force=1N+1%),
    reported with the thick-wall form identified on eps 0 and 0.064: the form pulls up to
    10.9 N there, within the entries' uncertainty, Equation 2 up to 154 N (summary.csv of
    that report). The verdict said no model could be scored and nothing of either."""
    slack = [{**_row("eq2", math.nan, 5.5e-7, consistent=False), "max_abs_residual_N": 153.659,
              "worst_E_n": -6.21389, "worst_step": 16},
             {**_row("thickwall", math.nan, 6.9e-6), "max_abs_residual_N": 10.8849,
              "worst_E_n": -0.667125, "worst_step": 16}]
    assert verdict("Run 5 (eps 20.8 %)", slack, NAMES, 0.02, dynamics=False) == (
        "Run 5 (eps 20.8 %): no model can be scored: the run's largest measured force is not "
        "above 0 N or its steps' uncertainty (a slack muscle), and Equation 7's error is "
        "relative to it; the closest to it is Thick-wall (Klute-Hannaford), at most 10.9 N "
        "from its forces, consistent with the measurement (|E_n| <= 1 at every step; 1 of 2 "
        "models is).")
    # the only model pulling where the muscle is slack is said not consistent, with its step
    assert verdict("Run 5 (eps 20.8 %)", slack[:1], NAMES, 0.02, dynamics=False).endswith(
        "the closest to it is Equation 2 (Chou-Hannaford), at most 154 N from its forces, "
        "not consistent with the measurement (E_n = -6.2 at step 16; 0 of 1 models are).")


def test_a_run_whose_forces_are_within_their_uncertainty_is_slack():
    # a bench run of a slack muscle reads its load cell's noise, up to 0.13 N: its
    # Err% was relative to that (the FE model '103.85 % off')
    import pandas as pd

    from mkm.scoring import slack

    noise = pd.DataFrame({"force_N_mean": [-0.04, 0.02, 0.13], "force_U_N": [1.9, 1.9, 1.9]})
    assert slack(noise)
    assert not slack(noise.assign(force_N_mean=[-0.04, 0.02, 2.5]))  # one step pulls
    # identify's steps hold the standard uncertainty only: twice it is the expanded
    assert slack(noise.rename(columns={"force_U_N": "force_u_N"}).assign(force_u_N=0.95))
    assert not slack(noise.rename(columns={"force_U_N": "force_u_N"}).assign(force_u_N=0.05))
    # a table without its accuracy cannot tell noise: slack only at 0 N or less
    assert not slack(noise[["force_N_mean"]])
    assert slack(pd.DataFrame({"force_N_mean": [0.0, 0.0]}))
    # a budget left empty (a step without one) is no bound
    assert not slack(noise.assign(force_U_N=[1.9, float("nan"), 1.9]))


def test_a_run_without_a_kept_step_is_said_so_not_that_no_model_is_valid():
    # a run stopped by SIGTERM during its first step: its report's first line said "no model
    # gives a valid force at any kept step: nothing to use", as if every model had failed
    empty = [{**_row("eq2", math.nan, 0.0, valid=0), "points": 0},
             {**_row("thickwall", math.nan, 0.0, valid=0), "points": 0}]
    for summary in (empty, []):  # the report scores no model on a run without steps
        assert verdict("Run 1 (eps 5.0 %, simulated)", summary, NAMES, 0.02) == (
            "Run 1 (eps 5.0 %, simulated): no step was kept, so no model can be scored: the "
            "run ended before its first step was recorded (its status and signals below say why).")


def test_a_misfit_names_the_friction_it_fitted_beside_the_static_models_distance():
    """A 5 mm latex muscle's two imported records (braid friction 3.0 %) identified at chi2/nu
    3.5, a misfit of 0.12 % at worst: the report's static FE model is 3.08 % off its runs, which
    the verdict put down to the muscle alone; the friction the static models lack is most of it,
    and the friction rung follows the runs within 0.13 %."""
    identified = [{"run": f"r{k}", "path": f"runs/r{k}", "muscle": {"eps": eps}}
                  for k, eps in ((1, 0.0), (2, 0.1))]
    fit = {"misfit": {"judged": True, "chi2_per_nu": 3.5, "misfit_branches": ["r2 loading"]},
           "parameters": [{"parameter": "hysteresis_fraction", "value": 0.030028,
                           "status": "fitted"}]}
    static = ["eq2", "thickwall", "axisym", "surrogate"]
    assert muscle_advice("runs/r1", identified, "calibration.json", fit=fit,
                         models=static) == (
        "although the calibration (calibration.json) was identified on this run with the "
        "others: the model does not fit them all with one muscle (the identification's misfit "
        "notes say where), and the braid friction 3.0 % identified with it, which these static "
        "models lack, is part of this distance (add the rung that has them: --models "
        "eq2,thickwall,axisym,surrogate,friction)")
    # the within-noise sentence's verb agrees with one term
    within = {**fit, "misfit": {"judged": True, "chi2_per_nu": 0.11, "misfit_branches": []}}
    assert ("the braid friction 3.0 % identified with it, which these static models lack, is "
            "that distance (") in muscle_advice("runs/r1", identified, fit=within, models=static)
