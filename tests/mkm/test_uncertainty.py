"""Prediction bands from the muscle's tolerances (mkm.uncertainty): parsing, the GUM
propagation against Equation 2's own derivatives, Monte Carlo over the surrogate."""

import math

import numpy as np
import pytest

from mkm.fem.tolerances import Tolerances, draws
from mkm.registry import parse_spec
from mkm.uncertainty import force_band, nominal_parameters, with_band


def test_parse_the_design_flag():
    t = Tolerances.parse("D0=0.3,t0=0.1,theta0=1,rubber=10%")
    assert (t.D0_mm, t.t0_mm, t.theta0_deg, t.rubber_fraction) == (0.3, 0.1, 1.0, 0.1)
    assert t.L0_mm == 0.0 and t.eps == 0.0  # not given: not toleranced
    assert t.standard()["D0_mm"] == pytest.approx(0.3 / math.sqrt(3))
    assert Tolerances.parse("eps=0.01", base=Tolerances()).D0_mm == 0.3


@pytest.mark.parametrize("text, message", [
    ("D0=abc", r"tolerance 'D0=abc' is invalid: expected a number"),
    ("width=1", r"tolerance 'width=1' is invalid: expected NAME=VALUE with NAME one of D0"),
    ("D0=-0.3", r"tolerance D0_mm=-0.3 is invalid: expected a \+- bound from 0 to"),
    ("theta0=5%", r"only rubber takes a percentage"),
    ("rubber=80%", r"tolerance rubber_fraction=0.8 is invalid"),
])
def test_bad_tolerances_are_named(text, message):
    with pytest.raises(ValueError, match=message):
        Tolerances.parse(text)


def test_draws_are_uniform_within_the_bounds():
    nominal = {"D0_mm": 40.0, "t0_mm": 3.0, "L0_mm": 282.0, "eps": 0.0, "theta0_deg": 32.0,
               "C10_MPa": 0.07, "C01_MPa": 0.06}
    d = draws(nominal, Tolerances(rubber_fraction=0.1), 20000, np.random.default_rng(0))
    assert np.abs(d["D0_mm"] - 40.0).max() <= 0.3
    assert d["D0_mm"].std() == pytest.approx(0.3 / math.sqrt(3), rel=0.03)
    assert d["eps"].min() >= 0.0  # a muscle at eps 0 is not stretched by the rod
    assert np.allclose(d["C10_MPa"] / 0.07, d["C01_MPa"] / 0.06)  # one rubber fit


def test_linearised_band_of_equation2_matches_its_derivatives():
    # F = a ((3 (1 - eps)^2 - 1) cot^2 theta - 1), a = pi D0^2 P / 4: dF/dD0 = 2 F / D0,
    # dF/deps = -6 a (1 - eps) cot^2 theta, dF/dtheta = -2 a (3 (1 - eps)^2 - 1) cot / sin^2
    spec = parse_spec("eq2")
    model = spec.build()
    P, D0, eps = np.array([1.0, 2.0, 2.5]), 40.0, 0.1
    tol = Tolerances(D0_mm=0.3, t0_mm=0.1, L0_mm=1.0, eps=0.004, theta0_deg=1.0)
    band = force_band(model, P, D0, 3.0, eps, tol,
                      rebuild=lambda **k: spec.with_params(**k).build())
    assert band.method == "linearised"
    theta = math.radians(nominal_parameters(model, D0, 3.0, eps)["theta0_deg"])
    cot2 = 1 / math.tan(theta) ** 2
    a = band.force_N / ((3 * (1 - eps) ** 2 - 1) * cot2 - 1)
    dD0 = 2 * band.force_N / D0
    deps = -6 * a * (1 - eps) * cot2
    dtheta = -2 * a * (3 * (1 - eps) ** 2 - 1) / math.tan(theta) / math.sin(theta) ** 2
    s = tol.standard()
    expected = np.sqrt((dD0 * s["D0_mm"]) ** 2 + (deps * s["eps"]) ** 2
                       + (dtheta * math.radians(s["theta0_deg"])) ** 2)
    # central differences over +- one standard uncertainty: the error is of order u^2
    assert band.force_u_N == pytest.approx(expected, rel=0.002)


def test_a_prediction_carries_its_band():
    model = parse_spec("thickwall").build()
    pred = model.predict([1.0, 2.0], 40.0, 3.0, 0.1)
    band = force_band(model, [1.0, 2.0], 40.0, 3.0, 0.1, Tolerances(D0_mm=0.3))
    out = with_band(pred, band).to_frame()
    assert (out["force_u_N"] > 0).all()
    # only D0 toleranced: about the relative change of the pressure area, 2 u_D0 / D0, and more
    # (the wall's share falls as D0 grows)
    assert (out["force_u_N"] / out["force_N"] > 2 * 0.3 / math.sqrt(3) / 40.0 * 0.8).all()


@pytest.mark.slow
def test_monte_carlo_over_the_surrogate_agrees_with_its_linearisation():
    # inside the box the surrogate is smooth and nearly linear over +-1 deg, +-0.3 mm: the two
    # propagations of the same model must agree to within the draws' sampling error (1000 draws:
    # the standard deviation to ~2 %) plus curvature, 8 % in all
    spec = parse_spec("surrogate")
    model = spec.build()
    P = np.linspace(0.5, 2.5, 5)
    tol = Tolerances(D0_mm=0.3, t0_mm=0.1, L0_mm=1.0, eps=0.004, theta0_deg=1.0)
    mc = force_band(model, P, 40.0, 3.0, 0.1, tol, n_draws=1000)
    assert mc.method == "monte-carlo"
    # what a report records of it: random draws, so their number and seed
    assert mc.record() == {"method": "monte-carlo", "draws": 1000, "seed": 0}
    linear = force_band(model, P, 40.0, 3.0, 0.1, tol, method="linearised",
                        rebuild=lambda **k: model.with_parameters(**k))
    assert linear.method == "linearised" and linear.record() == {"method": "linearised"}
    assert mc.force_u_N == pytest.approx(linear.force_u_N, rel=0.08)
    # at the box's edge (D0 = 30 mm, draws below it) the band is linearised by itself
    assert force_band(model, P, 30.0, 3.0, 0.1, tol).method == "linearised"


def test_report_gives_en_per_step_and_a_verdict_per_model(tmp_path):
    import pandas as pd

    from mkm.bench.config import load_config
    from mkm.bench.run import acquire
    from mkm.report import build_report

    # the simulated muscle from the thick-wall form: no FE table to build for one test
    config = load_config(eps=0.122, pressures_bar=(0.5, 1.5, 2.5)).replace(
        sim={"model": "thickwall"})
    run = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None).path
    path = build_report([run], ["eq2", "thickwall"], out_dir=tmp_path / "r",
                        cache_dir=None, tolerance=None, surrogate_section=False)
    errors = pd.read_csv(path.parent / "run1_errors.csv")
    steps = pd.read_csv(run / "steps.csv")
    for _, rows in errors.groupby("model"):
        rows = rows.set_index("step").loc[steps["step"]]
        ok = rows["valid"].to_numpy()
        slope = np.polyfit(rows["pressure_bar"][ok], rows["force_N"][ok], 1)[0]
        U = np.sqrt(steps["force_U_N"].to_numpy() ** 2
                    + (slope * steps["pressure_U_bar"].to_numpy()) ** 2
                    + (2 * rows["force_u_N"].to_numpy()) ** 2)
        expected = (steps["force_N_mean"].to_numpy() - rows["force_N"].to_numpy()) / U
        assert rows["E_n"].to_numpy()[ok] == pytest.approx(expected[ok], rel=1e-4)
        # at 2.5 bar the band (theta0 +-1 deg, D0 +-0.3 mm...) is a few % of the force
        top = rows["force_N"].idxmax()
        assert 0.01 < rows.loc[top, "force_u_N"] / rows.loc[top, "force_N"] < 0.15
    summary = pd.read_csv(path.parent / "summary.csv")
    for s in summary.itertuples():
        rows = errors[errors["model"] == s.model]
        assert s.consistent == bool((rows["E_n"].abs().dropna() <= 1).all())
        assert abs(s.worst_E_n) == pytest.approx(rows["E_n"].abs().max(), rel=1e-4)
    html = path.read_text(encoding="utf-8")
    assert "Measurement uncertainty budget of step" in html and "consistent" in html


@pytest.mark.parametrize("argv, message", [
    (["--tolerance", "D0=abc"], "argument --tolerance: tolerance 'D0=abc' is invalid: expected "
                                "a number"),
    (["--tolerance", "D0=0.3", "--probability", "1.5"],
     "--probability 1.5 is invalid: expected a probability between 0.5 and 1"),
    # a nominal design has no probability to meet: the option is not dropped without a word
    (["--probability", "0.99"], "mkm design: error: --probability 0.99 needs --tolerance: "
     "expected the tolerances the muscle is built to, e.g. --tolerance D0=0.3,t0=0.1,theta0=1\n"),
])
def test_design_tolerance_bad_input_is_one_line(mkm_run, argv, message):
    code, out, err = mkm_run(["design", "--require", "580N@2bar,eps=0.10", "--no-progress",
                              *argv])
    assert code == 2 and message in err and "Traceback" not in err


@pytest.mark.slow  # the default surrogate (trained on first use) and FE sweeps
def test_robust_design_meets_the_requirement_with_the_probability_asked(tmp_path):
    from mkm.design import run_design

    tolerances = Tolerances.parse("D0=0.3,t0=0.1,theta0=1,rubber=10%")
    nominal = run_design(["580N@2bar,eps=0.10"], top=2, mesh="coarse", cache_dir=tmp_path)
    robust = run_design(["580N@2bar,eps=0.10"], top=2, mesh="coarse", cache_dir=tmp_path,
                        tolerances=tolerances, probability=0.95)
    d = robust.designs
    for column in ("probability_r1", "probability_r1_search", "probability_all",
                   "r1_tolerance_u_N", "r1_fe_worst_corner_N"):
        assert column in d
    # the search's normal approximation is at least 95 %; the Monte Carlo of 4000 draws
    # (sd 0.3 points) of sums of uniform inputs has lighter tails, so it states more
    assert (d["probability_r1_search"] >= 0.95 - 1e-9).all()
    assert (d["probability_all"] >= 0.95 - 0.01).all()
    # a robust design needs a margin of z_95 u over the nominal one's 3 surrogate std
    assert robust.chosen["r1_surrogate_N"] > nominal.chosen["r1_surrogate_N"] + 20.0
    assert (d["r1_fe_worst_corner_N"] < d["r1_fe_N"]).all()
    assert "worst_corner" not in str(nominal.designs.columns)


@pytest.mark.slow  # the default surrogate (trained on first use) and FE sweeps
def test_the_chosen_robust_design_holds_the_probability_asked_when_a_verified_one_does(tmp_path):
    """At 90 % the search's normal approximation is not conservative: one uniform bound that
    dominates reaches its 10 % point at 0.80 of its half-width, the normal at 1.28 / sqrt(3) =
    0.74. Here the first design it ranked held every requirement in 88.7 % of the Monte Carlo
    draws (the medium FE on 200 draws from the tolerances, seed 20264004: 88.0 %) and was
    chosen, flagged only, while the fourth held 92.4 %: the chosen design is the best that holds
    the probability asked."""
    from mkm.design import run_design

    tolerances = Tolerances.parse("D0=0.5,t0=0.15,theta0=1.5,rubber=15%,eps=0.01")
    result = run_design(["200N@1.5bar,eps=0.18"], top=5, cache_dir=tmp_path,
                        tolerances=tolerances, probability=0.9)
    d = result.designs
    below = d["flags"].str.contains("all:probability_below_target")
    assert below.any() and not below.all()  # the case: some verified designs fall short
    assert (below == (d["probability_all"] < 0.9)).all()
    chosen = result.chosen
    assert chosen["probability_all"] >= 0.9
    assert "probability_below_target" not in chosen["flags"]
    # the designs that hold it come first, each group in the search's order
    assert not below[d["meets_all"]].iloc[:int((~below & d["meets_all"]).sum())].any()
    assert not any("probability" in note for note in result.notes())
    # the first design alone falls short: chosen, and said
    alone = run_design(["200N@1.5bar,eps=0.18"], top=1, cache_dir=tmp_path,
                       tolerances=tolerances, probability=0.9)
    assert alone.chosen["probability_all"] < 0.9
    assert ("no verified design holds every requirement with the 90 % asked (the chosen one: "
            f"{100 * alone.chosen['probability_all']:.1f} % of the Monte Carlo draws)"
            in " ".join(alone.notes()))


def test_a_drawn_muscle_with_no_tube_is_nan_at_a_single_pressure():
    """A robust design draws walls at the tolerance: one past the tube's radius has no force
    (NaN), at one pressure as at a sweep, instead of failing the design."""
    from mkm.fem.ladder import make_model
    from mkm.uncertainty import _predict_changed

    nominal = {"D0_mm": 8.0, "t0_mm": 3.9, "eps": 0.1, "L0_mm": 250.0, "theta0_deg": 25.0,
               "C10_MPa": 0.1, "C01_MPa": 0.1}
    changed = {**nominal, "t0_mm": 4.2}  # t0 >= D0 / 2: no tube
    model = make_model("thickwall")
    for pressure in (6.0, np.array([2.0, 6.0])):
        out = _predict_changed(model, pressure, changed, nominal, None,
                               lambda m, *args: m.predict(*args))
        assert np.shape(out) == np.shape(pressure) and np.isnan(out).all()


def test_a_neo_hookean_rubber_is_drawn_as_itself():
    # identify found C01 = 0 for a 25 mm latex muscle (C10 0.21 MPa): a rubber of one
    # constant. A robust design on that calibration drew C01 about Silastic S's 0.0628 MPa
    # (a 0 read as "not given") while its FE verified at 0, so the stated probability was
    # another rubber's (90 % where the muscle's own draws hold 95 %)
    from mkm.fem.ladder import make_model

    model = make_model("thickwall", theta0_deg=22.23, C10_MPa=0.21, C01_MPa=0.0, L0_mm=200.0)
    nominal = nominal_parameters(model, 9.9, 0.5, 0.10)
    assert (nominal["C10_MPa"], nominal["C01_MPa"], nominal["L0_mm"]) == (0.21, 0.0, 200.0)
    sample = draws(nominal, Tolerances.parse("theta0=1.2,rubber=28%"), 4000,
                   np.random.default_rng(0))
    assert (sample["C01_MPa"] == 0.0).all()
    assert sample["C10_MPa"].min() >= 0.21 * 0.72 and sample["C10_MPa"].max() <= 0.21 * 1.28
