"""The ladder of physics models by name (fem/ladder.py)."""

import subprocess
import sys

import pytest

from mkm.fem.eq2 import Eq2
from mkm.fem.ladder import MODELS, entry, make_model, names, static_names


def test_every_rung_builds_and_orders_as_the_physics_says():
    assert static_names() == ("eq2", "thickwall", "axisym")
    assert names()[:4] == ("eq2", "thickwall", "axisym", "friction")
    force = {}
    for name in static_names():
        model = make_model(name, theta0_deg=32.0, mesh="coarse" if name == "axisym" else None)
        assert model.name == name and model.params()["theta0_deg"] == 32.0
        force[name] = float(model.predict(2.5, 35.0, 2.5, 0.05).force_N)
    braid = float(Eq2(theta0_deg=32.0, diameter="braid").predict(2.5, 35.0, 2.5, 0.05).force_N)
    # muscle I at 2.5 bar: the wall costs force against Equation 2 on the braid diameter (a few
    # %), the clamped caps of the FE model cost more; the paper's inner-diameter Equation 2 is
    # lowest (its pressure acts on a smaller area)
    assert force["eq2"] < force["axisym"] < force["thickwall"] < braid < 1.1 * force["thickwall"]


def test_none_means_default_and_unknown_parameters_are_named():
    assert make_model("eq2", theta0_deg=None, diameter="braid").params()["diameter"] == "braid"
    with pytest.raises(ValueError, match="^model 'eq2' takes no parameter mesh: expected some of "
                       "diameter, theta0_deg, L0_mm$"):
        make_model("eq2", mesh="fine")
    with pytest.raises(ValueError, match="^unknown model 'fe': expected one of eq2, thickwall"):
        entry("fe")


def test_cheap_rungs_do_not_import_the_fe_machinery():
    code = ("import sys, mkm.fem.ladder as l; l.make_model('thickwall')\n"
            "print('skfem' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == "False"


def test_rungs_with_a_threshold_say_so():
    # has_threshold picks the default calibration target: it must match what the rung reports
    for name in static_names():
        model = make_model(name, theta0_deg=32.0, mesh="coarse" if name == "axisym" else None)
        pred = model.predict([0.0, 2.5], 35.0, 2.5, 0.05)
        reports = "threshold_pressure_bar" in pred.extras
        assert model.has_threshold == reports
        if reports:
            assert 0.1 < pred.extras["threshold_pressure_bar"][0] < 0.2  # muscle I: 0.14 bar


def test_a_model_built_for_a_muscle_predicts_that_muscle_and_refuses_another():
    from mkm.fem.muscle import Muscle

    muscle = Muscle(D0_mm=35.0, t0_mm=2.5, L0_mm=150.0, eps=0.05, theta0_deg=31.0,
                    C10_MPa=0.05, C01_MPa=0.06)
    model = make_model("thickwall", muscle=muscle)
    params = model.params()
    assert (params["L0_mm"], params["theta0_deg"], params["C10_MPa"], params["C01_MPa"]) == (
        150.0, 31.0, 0.05, 0.06)
    # the muscle's geometry and eps are where it predicts: the same numbers as predict()
    assert float(model.predict_muscle(muscle, 2.0).force_N) == float(
        model.predict(2.0, 35.0, 2.5, 0.05).force_N)
    # an explicit parameter wins over the muscle's; Equation 2 takes no rubber, so only the
    # length and the angle reach it
    assert make_model("thickwall", muscle=muscle, theta0_deg=33.0).params()["theta0_deg"] == 33.0
    assert make_model("eq2", muscle=muscle).params()["theta0_deg"] == 31.0
    other = make_model("thickwall", theta0_deg=31.0, L0_mm=150.0)  # Silastic S, not its rubber
    with pytest.raises(ValueError, match="^C10_MPa=0.05 of the muscle differs from the "
                       "thickwall model's C10_MPa=0.0"):
        other.predict_muscle(muscle, 2.0)


@pytest.mark.parametrize("name, value, expected", [
    # a typo, not a muscle (fem/limits.py LIMITS), refused as the flags --theta0 0.5 and --L0 5
    # are: theta0 0.5 deg gave Equation 2 1.3 MN on a 30 mm tube at 1 bar, valid
    ("theta0_deg", "0.5", r"a braid angle at rest in \[1, 89\] deg"),
    ("L0_mm", "5", r"a length at rest in \[10, 3000\] mm"),
    ("L0_mm", "nan", r"a length at rest in \[10, 3000\] mm"),
    ("C01_MPa", "-0.1", r"a Mooney-Rivlin C01 in \[0, 100\] MPa"),
    ("gap_mm", "-1", r"a radial gap between tube and braid in \[0, 100\] mm"),
])
def test_muscle_parameters_outside_the_limits_are_refused_by_every_model(name, value, expected):
    from mkm.registry import parse_spec

    takers = [e.name for e in MODELS.entries() if name in e.parameters]
    assert takers  # every muscle number is a parameter of some model
    for model in takers:
        with pytest.raises(ValueError, match=f"^{name}={value} is invalid: expected {expected}$"):
            parse_spec(f"{model}:{name}={value}")
