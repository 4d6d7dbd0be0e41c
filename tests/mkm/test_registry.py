"""The predictor registry (mkm/registry.py): one spec syntax, one place that builds and lists."""

import numpy as np
import pytest

from mkm.fem.eq2 import chou_hannaford
from mkm.fem.paper import L0_MM
from mkm.registry import describe, entries, parse_spec, parse_specs


@pytest.mark.parametrize("text, name, params, canonical", [
    ("eq2", "eq2", {}, "eq2"),
    (" eq2:diameter=braid ", "eq2", {"diameter": "braid"}, "eq2:diameter=braid"),
    ("axisym:mesh=coarse,L0_mm=150", "axisym", {"mesh": "coarse", "L0_mm": 150.0},
     "axisym:L0_mm=150,mesh=coarse"),
    ("surrogate:kind=gp", "surrogate", {"kind": "gp"}, "surrogate:kind=gp"),
    ("auto:tolerance=0.05,per_point=true", "auto", {"tolerance": 0.05, "per_point": True},
     "auto:per_point=True,tolerance=0.05"),
    # a fraction written as a percentage, as --tolerance takes it and auto's message suggests
    ("auto:tolerance=5%", "auto", {"tolerance": 0.05}, "auto:tolerance=0.05"),
    ("friction:static=thickwall,hysteresis_fraction=3%", "friction",
     {"static": "thickwall", "hysteresis_fraction": 0.03},
     "friction:hysteresis_fraction=0.03,static=thickwall"),
    # a number typed with a unit of its kind, as the CLI's --D0 282mm: converted by pint into
    # the unit the name gives (500 um = 0.5 mm, 100 kPa = 0.1 MPa, 2 min = 120 s)
    ("thickwall:gap_mm=500um,C10_MPa=100kPa,theta0_deg=0.5rad", "thickwall",
     {"gap_mm": 0.5, "C10_MPa": 0.1, "theta0_deg": pytest.approx(28.6478897565)},
     "thickwall:C10_MPa=0.1,gap_mm=0.5,theta0_deg=28.6478897565"),
    ("friction:static=thickwall,hold_s=2min", "friction",
     {"static": "thickwall", "hold_s": 120.0}, "friction:hold_s=120,static=thickwall"),
])
def test_spec_round_trip(text, name, params, canonical):
    spec = parse_spec(text)
    assert spec.name == name and dict(spec.params) == params
    assert spec.text == canonical and parse_spec(spec.text) == spec


def test_comma_lists_keep_parameters_with_their_model():
    specs = parse_specs("eq2,axisym:mesh=coarse,L0_mm=150,thickwall,eq2:diameter=braid")
    assert [s.text for s in specs] == ["eq2", "axisym:L0_mm=150,mesh=coarse", "thickwall",
                                       "eq2:diameter=braid"]


@pytest.mark.parametrize("text, message", [
    ("nope", "unknown model 'nope' in 'nope': expected one of eq2, thickwall, axisym"),
    ("axisym:coarse", "'coarse' is not key=value"),
    ("axisym:grid=1", "unknown parameter 'grid': expected some of mesh, theta0_deg, L0_mm, "
                      "C10_MPa, C01_MPa, braid"),
    ("", "unknown model ''"),
    ("thickwall:gap_mm=0.5kPa", "gap_mm='0.5kPa': 'kPa' is not a unit of the same kind as mm"),
    ("thickwall:gap_mm=abc", r"gap_mm='abc' is not a number: expected a number in mm, or one "
     r"with a unit such as 282mm or 1\.5in \(radial gap"),
])
def test_bad_specs_name_the_bad_part(text, message):
    with pytest.raises(ValueError, match=message):
        parse_spec(text)


def test_empty_list_is_an_error():
    with pytest.raises(ValueError, match="is empty"):
        parse_specs(" , ")


def test_build_applies_defaults_only_where_the_model_takes_them():
    # the report passes the run's L0: eq2 records it, the spec's own value wins over it
    assert parse_spec("eq2").build(L0_mm=150.0).L0_mm == 150.0
    assert parse_spec("thickwall:L0_mm=200").build(L0_mm=150.0).L0_mm == 200.0
    model = parse_spec("eq2:diameter=braid,theta0_deg=30").build(L0_mm=L0_MM)
    pred = model.predict(2.0, 35.0, 2.5, 0.05)
    np.testing.assert_allclose(pred.force_N, chou_hannaford(2.0, 40.0, 0.05, 30.0), rtol=1e-12)


def test_build_refuses_a_bad_value_with_the_models_own_message():
    with pytest.raises(ValueError, match="mesh='huge' is invalid"):
        parse_spec("axisym:mesh=huge").build().predict(1.0, 35.0, 2.5, 0.05)


def test_every_entry_is_listed_with_its_parameters():
    text = describe()
    for name, entry in entries().items():
        assert f"\n{name} " in f"\n{text}" and entry.label in text
        for key in entry.parameters:
            assert f"{key}:" in text


def test_display_name_is_the_papers():
    assert parse_spec("eq2").display_name == "Equation 2 (Chou-Hannaford)"
    assert parse_spec("eq2:diameter=braid").display_name == (
        "Equation 2 (Chou-Hannaford), diameter=braid")


def test_models_states_the_practical_range_from_its_numbers():
    from mkm.fem.limits import range_text

    text = " ".join(describe().split())  # wrapped at 100 columns
    assert range_text() in text
    assert "D0 5-60 mm" in text and "pressure 0-8 bar" in text


def test_a_model_named_twice_is_refused():
    # mkm report --models eq2,eq2 scored eq2 twice: two identical rows in summary.csv
    with pytest.raises(ValueError) as caught:
        parse_specs("eq2,thickwall,eq2")
    assert str(caught.value) == ("--models 'eq2,thickwall,eq2' names eq2 twice ('eq2' and "
                                 "'eq2'): expected each model once")
    with pytest.raises(ValueError, match="names axisym:mesh=coarse twice"):
        parse_specs("axisym:mesh=coarse,eq2,axisym:mesh=coarse")
    # the same rung with other parameters is another model
    assert [s.text for s in parse_specs("eq2,eq2:theta0_deg=50")] == ["eq2",
                                                                      "eq2:theta0_deg=50"]


@pytest.mark.parametrize("text, same", [
    ("axisym,axisym:mesh=medium", "axisym"),  # medium is Axisym's default mesh
    ("eq2:diameter=inner,eq2", "eq2"),
    ("friction,friction:static=axisym,direction=rising", "friction"),
])
def test_a_model_spelled_at_its_defaults_is_named_twice(text, same):
    # axisym and axisym:mesh=medium were scored as two models, the same numbers in two rows
    with pytest.raises(ValueError, match=rf"names {same} twice"):
        parse_specs(text)


def test_a_muscle_parameter_at_the_factory_default_is_another_model():
    # L0_mm unset is the run's muscle's length, not 282 mm: both are kept
    assert [s.text for s in parse_specs("eq2,eq2:L0_mm=282")] == ["eq2", "eq2:L0_mm=282"]
    assert [s.text for s in parse_specs("axisym,axisym:mesh=coarse")] == [
        "axisym", "axisym:mesh=coarse"]
