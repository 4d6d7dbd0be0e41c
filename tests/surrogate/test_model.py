import warnings

import numpy as np
import pandas
import pytest

from mkm.fem.calibration import calibrated
from mkm.surrogate.design import BOX
from mkm.surrogate.model import OutOfDomainWarning
from mkm.surrogate.train import cached_model, train_surrogate


@pytest.fixture(scope="module")
def physics(thickwall_dataset):
    return train_surrogate("physics", thickwall_dataset, splits=1)


@pytest.fixture(scope="module")
def gp(thickwall_dataset):
    return train_surrogate("gp", thickwall_dataset, splits=0)


@pytest.fixture(scope="module")
def design_model():
    """The default surrogate (the best kind on the shipped design dataset) as every command gets
    it: trained once per session into the suite's cache and shared with the report and CLI
    tests (the estimator is fitted on the whole dataset whatever the held-out refits)."""
    return cached_model("best")


def test_domain_is_the_training_box(physics):
    assert physics.domain.as_dict() == {"pressure_bar": [0.0, 2.5], "D0_mm": [30.0, 50.0],
                                        "t0_mm": [2.0, 4.0], "eps": [0.0, 0.2]}


def test_inside_the_domain_no_warning(physics):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        prediction = physics.predict([0.0, 1.0, 2.5], 35.0, 2.5, 0.05)
    assert prediction.valid.all() and prediction.extras["in_domain"].all()


@pytest.mark.parametrize("point, named", [
    ((2.6, 40, 3, 0.1), r"pressure_bar=2\.6 not in \[0, 2\.5\]"),
    ((1.0, 29.0, 3, 0.1), r"D0_mm=29 not in \[30, 50\]"),
    ((1.0, 40, 4.5, 0.1), r"t0_mm=4\.5 not in \[2, 4\]"),
    ((1.0, 40, 3, 0.25), r"eps=0\.25 not in \[0, 0\.2\]")])
def test_outside_the_domain_flagged_and_warned(physics, point, named):
    # the warning names the input outside, as the reason column of `mkm surrogate predict` does
    with pytest.warns(OutOfDomainWarning, match=rf"1 of 2 points lie outside .*\({named}\)"):
        prediction = physics.predict([1.0, point[0]], [40, point[1]], [3, point[2]],
                                     [0.1, point[3]])
    np.testing.assert_array_equal(prediction.valid, [True, False])
    np.testing.assert_array_equal(prediction.extras["in_domain"], [True, False])
    assert np.isfinite(prediction.force_N).all()  # the number is kept, the flag says it is not


def test_outside_the_domain_names_the_span_of_an_input_outside(physics):
    with pytest.warns(OutOfDomainWarning, match=r"2 of 3 points lie outside .*\(pressure_bar="
                                                r"2\.75-3 not in \[0, 2\.5\]; D0_mm=29 not in"):
        physics.predict([1.0, 2.75, 3.0], [40, 40, 29.0], 3, 0.1)


@pytest.mark.parametrize("parameter, value", [("L0_mm", 150.0), ("theta0_deg", 30.0),
                                              ("C10_MPa", 0.05), ("C01_MPa", 0.09)])
def test_recorded_parameter_at_another_value_is_refused(physics, parameter, value):
    # The paper-grid style dataset holds one length, angle and rubber: the surrogate answers
    # there only (at L0 = 150 mm the old default answered 568 N where the FE gives 465 N).
    with pytest.raises(ValueError, match=rf"trained at {parameter}=[0-9.]+ only: "
                                         rf"{parameter}={value:g} refused"):
        physics.with_parameters(**{parameter: value})


def test_default_angle_other_than_recorded_is_refused_at_predict(physics, tmp_path):
    # A user who calibrates theta0 on a bench run gets a refusal, not a surrogate silently
    # trained at another angle.
    from mkm.fem.calibration import Calibration

    other = tmp_path / "calibration.json"
    other.write_text('{"axisym": {"theta0_deg": 30.0}}')
    with pytest.raises(ValueError, match=r"theta0_deg=30 \(the default of the calibration "
                                         r".*calibration\.json\) refused"):
        physics.with_parameters(Calibration.load(other)).predict(1.0, 40.0, 3.0, 0.1)


def test_given_angle_needs_no_fe_entry_in_the_calibration(physics, tmp_path):
    # a muscle identified with the thick-wall form has no FE entry; with the angle given, the
    # surrogate, as the physics models, needs none (it refused, pointing at the angle already
    # given) and takes the nominal rubber
    from mkm.fem.calibration import Calibration
    from mkm.fem.materials import SILASTIC_S

    lab = tmp_path / "calibration.json"
    lab.write_text('{"thickwall": {"theta0_deg": 29.2, "C10_MPa": 0.35, "C01_MPa": 0.31}}')
    theta0 = physics.fixed["theta0_deg"]
    model = physics.with_parameters(Calibration.load(lab), theta0_deg=theta0)
    assert model.parameters == {"L0_mm": 282.0, "theta0_deg": theta0,
                                "C10_MPa": SILASTIC_S.C10_MPa, "C01_MPa": SILASTIC_S.C01_MPa}
    np.testing.assert_array_equal(model.predict([1.0, 2.5], 40.0, 3.0, 0.1).force_N,
                                  physics.predict([1.0, 2.5], 40.0, 3.0, 0.1).force_N)
    with pytest.raises(ValueError, match="no calibrated theta0 for model 'axisym'"):
        physics.with_parameters(Calibration.load(lab)).parameters  # noqa: B018


def test_gp_gives_a_predictive_spread(gp):
    prediction = gp.predict([0.5, 1.0, 2.0], 40.0, 3.0, 0.1)
    std = prediction.extras["force_std_N"]
    assert std.shape == (3,) and np.all(std > 0)
    # On exact training-grid data the spread is small against the forces (hundreds of N).
    assert np.all(std < 0.01 * prediction.force_N.max())


def test_prediction_is_exact_on_thickwall_data(physics):
    # The dataset is the thick-wall model itself, which the physics surrogate holds exactly
    # (its priors): the off-grid muscle I must come out to round-off.
    from mkm.fem.ladder import make_model

    P = np.linspace(0.0, 2.5, 11)
    thickwall = make_model("thickwall", theta0_deg=calibrated("axisym")["theta0_deg"])
    expected = thickwall.predict(P, 35.0, 2.5, 0.05).force_N
    np.testing.assert_allclose(physics.predict(P, 35.0, 2.5, 0.05).force_N, expected,
                               atol=1e-6 * expected.max())


@pytest.mark.slow  # trains the design's GP
def test_fast_path_equals_the_estimator(physics, design_model):
    # The surrogates skip scikit-learn's per-call checks for speed: same numbers, bit for bit.
    X = np.array([[0.0, 30.0, 2.0, 0.0], [1.3, 41.0, 2.7, 0.13], [2.5, 50.0, 4.0, 0.2]])
    assert physics._fast_predict is not None
    np.testing.assert_array_equal(physics.predict(*X.T).force_N, physics.estimator.predict(X))
    full = np.column_stack([X, np.tile([250.0, 33.0, 0.07, 0.06], (3, 1))])
    local = design_model.with_parameters(L0_mm=250.0, theta0_deg=33.0, C10_MPa=0.07,
                                         C01_MPa=0.06)
    force, std = design_model.estimator.predict(full, return_std=True)
    prediction = local.predict(*X.T)
    np.testing.assert_array_equal(prediction.force_N, force)
    np.testing.assert_array_equal(prediction.extras["force_std_N"], std)


@pytest.mark.slow  # trains a GP on the design
def test_design_model_takes_every_muscle_parameter(design_model):
    assert design_model.inputs == ("pressure_bar", "D0_mm", "t0_mm", "eps", "L0_mm",
                                   "theta0_deg", "C10_MPa", "C01_MPa")
    assert design_model.fixed == {}
    assert {k: tuple(v) for k, v in design_model.box.items()} == BOX
    # a shorter muscle pulls less at the same geometry (its end zones are a larger share)
    short = design_model.with_parameters(L0_mm=150.0).predict(2.0, 40.0, 3.0, 0.1).force_N
    long = design_model.with_parameters(L0_mm=400.0).predict(2.0, 40.0, 3.0, 0.1).force_N
    assert short < long


@pytest.mark.slow  # trains the design's GP
@pytest.mark.parametrize("parameter, value", [("L0_mm", 120.0), ("L0_mm", 450.0),
                                              ("theta0_deg", 26.0), ("theta0_deg", 40.0),
                                              ("C10_MPa", 0.2), ("C01_MPa", 0.01)])
def test_parameter_outside_the_box_flags_every_point(design_model, parameter, value):
    local = design_model.with_parameters(**{parameter: value})
    with pytest.warns(OutOfDomainWarning, match=rf"3 of 3 points .*{parameter}={value:g} not "
                                                "in"):
        prediction = local.predict([0.5, 1.0, 2.0], 40.0, 3.0, 0.1)
    assert not prediction.valid.any() and not prediction.extras["in_domain"].any()


@pytest.mark.slow  # trains the design's GP
def test_outside_its_box_inside_the_practical_range_it_names_the_spec_that_answers(design_model):
    # a 10 mm muscle at 6 bar: outside the default's box, inside the practical range
    with pytest.warns(OutOfDomainWarning, match=r"practical range, where the spec "
                                                r"surrogate:kind=muscle-gp-range \(or auto\)"):
        design_model.with_parameters(L0_mm=250.0, theta0_deg=25.0).predict(
            [2.0, 6.0], 10.0, 1.0, 0.05)
    # 1.5 m long: outside the practical range too (L0 50-1000 mm), so no spec is named
    with pytest.warns(OutOfDomainWarning) as record:
        design_model.with_parameters(L0_mm=1500.0).predict([0.5, 1.0], 40.0, 3.0, 0.1)
    assert "practical range" not in str(record[0].message)


def test_best_and_the_kind_it_names_are_one_cached_model(design_model):
    # the default surrogate is asked for as `best` (spec `surrogate`) and by its kind
    # (identify, auto): one training on first use, not one per name
    from mkm.surrogate.kinds import BEST
    from mkm.surrogate.train import is_cached, training_task

    assert is_cached(BEST)
    assert training_task("best") == training_task(BEST)
    assert cached_model(BEST).metadata["trained"] == design_model.metadata["trained"]


@pytest.mark.parametrize(("parameter", "value"), [("C10_MPa", -1.0), ("C01_MPa", -5.0),
                                                  ("L0_mm", 1e9)])
def test_a_parameter_outside_the_limits_is_refused(physics, parameter, value):
    """surrogate:C10_MPa=-1 used to be flagged out of the box (valid=False, exit 0) where the
    physics models refuse it: outside LIMITS a value is a typo, not a muscle."""
    with pytest.raises(ValueError, match=rf"^{parameter}=\S+ is invalid: expected"):
        physics.with_parameters(**{parameter: value})


def test_predict_writes_no_force_where_the_surrogate_has_no_answer(design_model, tmp_path,
                                                                   capsys):
    # 3 bar lies above the default surrogate's 2.5 bar box and eps 25 % beyond its 20 %: those
    # points were written with the estimator's extrapolation (0 N at eps 25 %, a number a
    # script reads as a force), flagged only by valid=False
    from mkm.cli import main

    out = tmp_path / "sweep.csv"
    assert main(["surrogate", "predict", "--D0", "40", "--t0", "3", "--eps", "5%",
                 "--pressures", "0:3:1", "--out", str(out)]) == 0
    table = pandas.read_csv(out, keep_default_na=False)
    assert table["valid"].tolist() == [True, True, True, False]
    # the answered points are the model's own numbers, as written (6 significant digits)
    expected = design_model.predict([0.0, 1.0, 2.0], 40.0, 3.0, 0.05).force_N
    assert table["force_N"][:3].astype(float).to_numpy() == pytest.approx(expected, rel=1e-5)
    assert table["force_N"][3] == "" and table["force_std_N"][3] == ""
    assert table["reason"].tolist() == ["", "", "", "outside the training domain: "
                                        "pressure_bar=3 not in [0, 2.5]"]
    assert "1 outside the training domain: no force written" in capsys.readouterr().err
    # a point past the braid lock is counted as such, as its reason says (was: "outside the
    # training domain", its reason column naming the lock)
    assert main(["surrogate", "predict", "--D0", "40", "--t0", "3", "--theta0", "38",
                 "--eps", "30%", "--pressures", "1,2", "--out", str(out)]) == 0
    assert ("2 past the braid lock: no force written (valid=False, their reason in the reason "
            "column)") in capsys.readouterr().err
    assert pandas.read_csv(out)["reason"].str.startswith("past the braid lock").all()
    assert main(["surrogate", "predict", "--D0", "40", "--t0", "3", "--eps", "25%",
                 "--pressures", "1"]) == 0
    row = capsys.readouterr().out.splitlines()[1]
    assert row == ('1,40,3,0.25,,False,True,False,,"outside the training domain: eps=0.25 not '
                   'in [0, 0.2]"')


def test_answered_takes_a_scalar_prediction(design_model):
    # one point, as ForceModel.predict broadcasts scalars: its index is ()
    with pytest.warns(OutOfDomainWarning):
        prediction = design_model.predict(1.0, 40.0, 3.0, 0.25)
    answered = design_model.answered(prediction)
    assert np.isnan(answered.force_N) and not answered.valid
    assert answered.extras["reason"] == "outside the training domain: eps=0.25 not in [0, 0.2]"
