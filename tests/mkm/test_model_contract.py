"""The force-model contract, checked on every entry of the registry (mkm.registry.entries()).

A model registered anywhere is tested here the moment it is registered: the contract is a
function (:func:`check_contract`) run over the entries at collection time, and run again by the
toy-entry test on a model registered inside the test.

The physics behind each check, for the muscle of the paper's prototype (D0 30 mm, t0 2 mm):
- no pressure, no force: every model's force at 0 bar is 0 (within 0.5 N, two bench ADC steps);
- an isometric muscle pulls harder as the pressure rises: forces never fall along a sweep;
- past the braid's locking shortening (eps 0.5 is beyond 1 - 1/(sqrt(3) cos theta0) = 0.31 at
  theta0 33 deg) no model may call its number valid;
- units: at 2 bar and eps 0 the force lies between half and 105 % of the ideal thin-walled
  muscle on the braid diameter (Equation 2 with the model's own theta0): a bar/MPa or mm/m slip
  is a factor of 10 or more;
- arrays broadcast like numpy, the same call gives the same numbers, the time is measured.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from mkm.fem.calibration import calibrated
from mkm.fem.eq2 import chou_hannaford
from mkm.fem.interface import ForceModel
from mkm.fem.ladder import L0, THETA0, Entry, StudyVariant
from mkm.registry import build_spec, entries, register, unregister

D0, T0 = 30.0, 2.0
SWEEP_BAR = np.linspace(0.0, 2.5, 11)
ZERO_FORCE_N = 0.5  # two steps of the USB-6001's ADC on the default load cell (0.24 N each)
# A surrogate's GP may wiggle by less than its own std between pressures: 0.1 N is far below
# what the bench resolves
MONOTONE_SLACK_N = 0.1
# the surrogate trains on the shipped design (GP fitting); auto falls back to the fine mesh
SLOW = {"surrogate", "auto"}


def check_contract(entry: Entry) -> None:
    """Assert the contract of the module docstring for the model ``entry.contract_spec``
    builds (or ``entry.name``)."""
    model = build_spec(entry.contract_spec or entry.name)
    assert isinstance(model, ForceModel)

    sweep = model.predict(SWEEP_BAR, D0, T0, 0.0)
    assert sweep.force_N.shape == SWEEP_BAR.shape
    assert sweep.valid.all(), f"{entry.name}: invalid inside the muscle's range"
    assert abs(sweep.force_N[0]) <= ZERO_FORCE_N
    assert np.all(np.diff(sweep.force_N) >= -MONOTONE_SLACK_N), sweep.force_N
    assert np.isfinite(sweep.seconds) and sweep.seconds >= 0.0
    json.dumps(sweep.params)  # provenance: plain data

    theta0 = sweep.params.get("theta0_deg", calibrated("axisym")["theta0_deg"])
    ideal = float(chou_hannaford(2.0, D0 + 2 * T0, 0.0, theta0))
    at_2_bar = float(sweep.force_N[SWEEP_BAR == 2.0][0])
    assert 0.5 * ideal < at_2_bar < 1.05 * ideal, (at_2_bar, ideal)

    past_lock = model.predict([1.0, 2.0], D0, T0, 0.5)
    assert not past_lock.valid.any(), f"{entry.name} claims a valid force past the braid lock"

    grid = model.predict(np.array([[1.0], [2.0]]), np.array([30.0, 35.0]), T0, 0.05)
    for name in ("force_N", "valid", "converged"):
        assert getattr(grid, name).shape == (2, 2)
    again = model.predict(np.array([[1.0], [2.0]]), np.array([30.0, 35.0]), T0, 0.05)
    np.testing.assert_array_equal(again.force_N, grid.force_N)


@pytest.mark.parametrize("name", [
    pytest.param(name, marks=pytest.mark.slow) if name in SLOW else name
    for name in entries()])
def test_every_registered_model_keeps_the_contract(name):
    check_contract(entries()[name])


class IdealCylinder(ForceModel):
    """A toy model: Equation 2 on the braid diameter (the thin-walled ideal), nothing else."""

    name = "toy-ideal"

    def __init__(self, theta0_deg: float = 33.0, L0_mm: float = 282.0):
        self.theta0_deg, self.L0_mm = theta0_deg, L0_mm

    def params(self):
        return {"theta0_deg": self.theta0_deg, "L0_mm": self.L0_mm}

    def _forces(self, P, D0, t0, eps):
        lock = 1.0 - 1.0 / (np.sqrt(3.0) * np.cos(np.deg2rad(self.theta0_deg)))
        return {"force_N": chou_hannaford(P, D0 + 2 * t0, eps, self.theta0_deg),
                "valid": eps < lock}


class TenfoldOff(IdealCylinder):
    """The same toy with a units slip (MPa taken for bar): the contract must catch it."""

    name = "toy-broken"

    def _forces(self, P, D0, t0, eps):
        out = super()._forces(P, D0, t0, eps)
        return {**out, "force_N": 10.0 * out["force_N"]}


TOY = Entry("toy-ideal", IdealCylinder, "Ideal cylinder (toy)", "a toy for the registry test",
            "closed form", {"theta0_deg": THETA0, "L0_mm": L0}, colour="tab:cyan",
            study=(StudyVariant("toy-ideal", "toy-ideal"),), contract_spec="toy-ideal")


@pytest.fixture
def toy():
    register(TOY)
    yield TOY
    unregister(TOY.name)


def test_a_registered_toy_is_everywhere_at_once(toy, mkm_run, tmp_path):
    check_contract(toy)
    code, out, _ = mkm_run(["models"])
    assert code == 0 and "toy-ideal  Ideal cylinder (toy): a toy for the registry test" in out
    code, out, _ = mkm_run(["fem", "solve", "--model", "toy-ideal:theta0_deg=30", "--D0", "40",
                            "--t0", "3", "--eps", "0", "--pressures", "2"])
    assert code == 0
    # pi (46 mm)^2 / 4 x 0.2 MPa x (3 / tan^2 30 - 1 / sin^2 30) = 332.4 N x (9 - 4) = 1662 N
    assert float(out.strip().splitlines()[-1].split(",")[4]) == pytest.approx(1661.9, abs=0.1)
    code, out, _ = mkm_run(["fem", "solve", "--help"])
    assert "toy-ideal" in "".join(out.split())  # the --model choices (argparse wraps at "-")
    code, _, err = mkm_run(["fem", "solve", "--model", "toy-ideal:mesh=fine", "--D0", "40",
                            "--t0", "3", "--eps", "0"])
    assert code == 2 and "expected some of theta0_deg, L0_mm" in err


def test_a_registered_toy_is_in_every_list_derived_from_the_registry(toy, mkm_run, tmp_path):
    from mkm.auto import candidates, read_model_errors
    from mkm.fem.ladder import entry
    from mkm.identify.result import closed_forms
    from mkm.study import StudyConfig, physics_predictors, run_study, stability_methods

    assert "toy-ideal" in entry("friction").parameters["static"].options()
    code, out, err = mkm_run(["fem", "solve", "--model", "friction:static=toy-ideal,"
                              "theta0_deg=30", "--D0", "40", "--t0", "3", "--eps", "0",
                              "--pressures", "2"])
    assert code == 0, err  # the toy's force (1662 N, above) as the static rung, no friction
    assert float(out.strip().splitlines()[-1].split(",")[4]) == pytest.approx(1661.9, abs=0.1)
    assert "toy-ideal" in closed_forms()  # identify refits its theta0
    predictors = physics_predictors()
    assert "toy-ideal" in [p.label for p in predictors]  # the study scores it
    assert "toy-ideal" in stability_methods(StudyConfig(), predictors)  # and maps it
    closed = StudyConfig(
        muscles=(("I", 35.0, 2.5, 0.05, "test"),), pressures=(0.0, 1.25, 2.5),
        predictors=lambda cache_dir: [p for p in physics_predictors()
                                      if p.family == "closed form"],
        reference="eq2-braid", stability_muscles=(("smallest", 30.0, 2.0),),
        stability_pressures=(0.0, 2.0), stability_eps=(0.0, 0.1))
    run_study(tmp_path / "study", closed, cache_dir=None)
    table = read_model_errors(tmp_path / "study" / "model_errors.csv")
    assert "toy-ideal" in set(candidates(table)["spec"])  # auto may choose it


def test_a_registered_toy_is_scored_in_the_report(toy, tmp_path):
    from dataclasses import replace

    import pandas as pd

    from mkm.bench.config import load_config
    from mkm.bench.run import acquire
    from mkm.registry import parse_specs
    from mkm.report import build_report

    config = load_config()
    config = replace(config, sequence=replace(config.sequence, pressures_bar=(1.0, 2.0),
                                              preconditioning_cycles=0))
    run = acquire(config, out_root=tmp_path / "runs")
    # the toy is Equation 2 on the braid diameter: at eq2's calibrated angle, the same numbers
    toy_spec = f"toy-ideal:theta0_deg={calibrated('eq2-braid')['theta0_deg']}"
    build_report([run.path], parse_specs(f"eq2:diameter=braid,{toy_spec}"),
                 out_dir=tmp_path / "r", cache_dir=None, tolerance=None,
                 surrogate_section=False)
    rows = pd.read_csv(tmp_path / "r" / "summary.csv").set_index("model")
    toy_row = rows.loc[rows.index.str.startswith("toy-ideal")].iloc[0]
    assert toy_row["valid_points"] == rows.loc["eq2:diameter=braid", "valid_points"] > 0
    assert toy_row["max_abs_err_pct"] == pytest.approx(
        rows.loc["eq2:diameter=braid", "max_abs_err_pct"], rel=1e-9)


def test_a_broken_toy_fails_the_contract():
    broken = Entry("toy-broken", TenfoldOff, "Broken toy", "a units slip", "closed form",
                   {"theta0_deg": THETA0}, contract_spec="toy-broken")
    register(broken)
    try:
        with pytest.raises(AssertionError):
            check_contract(broken)
    finally:
        unregister(broken.name)


def test_names_are_unique():
    with pytest.raises(ValueError, match="'eq2' is already registered"):
        register(Entry("eq2", IdealCylinder, "x", "x", "x"))
