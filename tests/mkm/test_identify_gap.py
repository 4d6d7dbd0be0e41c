"""mkm identify --params ...,gap: a simulated gap between tube and braid, found blind from runs
at two eps (the thick-wall closed form simulates and identifies; issue target: the gap within
10 % of its value)."""

from __future__ import annotations

import re

import numpy as np
import pytest

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.sim_settings import remove_simulator_settings, sim_of
from mkm.fem.calibration import Calibration
from mkm.fem.ladder import make_model
from mkm.fem.materials import SILASTIC_S
from mkm.identify import identify
from mkm.identify.page import report_section
from mkm.identify.runs import load_run_data

SEED = int(np.random.SeedSequence().entropy % 2**32)


def record(truth: dict, eps: float, out, seed: int):
    """One blind simulated staircase (0.25-2.5 bar up and down) of the thick-wall muscle
    ``truth``, with the simulator's default friction, creep and noise."""
    config = load_config(eps=eps).replace(
        sim=sim_of({"theta0_deg": truth["theta0_deg"], "rubber_scale": truth["rubber_scale"]},
                   seed, gap_mm=truth["gap_mm"]))
    result = acquire(config, out_root=out, notify=lambda message: None)
    assert result.status == "complete"
    remove_simulator_settings(result.path)
    assert "gap_mm" not in (result.path / "run.json").read_text(encoding="utf-8")
    return result.path


@pytest.fixture(scope="module")
def gapped(tmp_path_factory):
    rng = np.random.default_rng(SEED)
    truth = {"theta0_deg": rng.uniform(28.0, 36.0), "rubber_scale": rng.uniform(0.8, 1.5),
             "gap_mm": rng.uniform(0.5, 1.5)}
    out = tmp_path_factory.mktemp("gap-runs")
    return truth, [record(truth, eps, out, seed=k) for k, eps in enumerate((0.0, 0.122))]


@pytest.mark.slow  # a gap, theta0 and the rubber fitted blind: seconds, out of the fast tier
def test_a_simulated_gap_is_found_blind_from_two_eps(gapped, tmp_path):
    truth, runs = gapped
    result = identify(runs, params="theta0,rubber,gap,friction,creep", model="thickwall",
                      search="model")
    found, why = result.fit.values, f"seed {SEED}, truth {truth}"
    # the target is 10 %; in its own family the fit finds the gap to about 0.1 % (six
    # seeds, default friction, creep and noise), so 2 % leaves room for unlucky noise draws
    assert found["gap_mm"] == pytest.approx(truth["gap_mm"], rel=0.02), why
    assert found["theta0_deg"] == pytest.approx(truth["theta0_deg"], abs=0.3), why
    table = result.parameters().set_index("parameter")
    low, high = table.loc["gap_mm", ["ci_low", "ci_high"]]
    assert low <= found["gap_mm"] <= high and table.loc["gap_mm", "unit"] == "mm"
    assert result.values["gap_mm"] == found["gap_mm"]

    # the calibration it writes carries the gap to every command that takes --calibration
    files = result.write(tmp_path / "identified")
    learnt = Calibration.load(files["calibration"])
    model = make_model("thickwall", learnt)
    assert model.params()["gap_mm"] == pytest.approx(found["gap_mm"], abs=1e-6)
    explicit = make_model("thickwall", theta0_deg=model.params()["theta0_deg"],
                          C10_MPa=model.material.C10_MPa, C01_MPa=model.material.C01_MPa,
                          gap_mm=model.params()["gap_mm"])
    pressures = np.linspace(0.0, 2.5, 11)
    np.testing.assert_array_equal(model.predict(pressures, 30.0, 3.0, 0.0).force_N,
                                  explicit.predict(pressures, 30.0, 3.0, 0.0).force_N)
    # the report's identified muscle predicts with the gap: as closely as the fit itself
    (tmp_path / "page").mkdir()
    page = report_section(runs, tmp_path / "page", learnt)
    assert "gap_mm" in page
    identified = re.findall(r"<td>identified</td>\s*<td>([0-9.e+-]+)</td>", page)
    assert identified and max(map(float, identified)) < 0.5, page
    assert "gap_mm" not in make_model("thickwall").params()  # the shipped calibration has none

    # the identified threshold at each run's eps against the measured one (issue target 0.1 bar)
    table = page[:page.index("Threshold pressure at each run's eps")]
    table = table[table.rindex('<div class="table">'):]
    rows = re.findall(r"<tr>\s*<td>([^<]+)</td>" + r"\s*<td>([-0-9.]+)</td>" * 4, table)
    assert [name for name, *_ in rows] == [run.name for run in runs], table
    for (_, eps, fitted, measured, difference), run in zip(rows, runs, strict=True):
        D0_mm, t0_mm, eps_truth = load_run_data(run).geometry
        assert float(eps) == pytest.approx(eps_truth, abs=1e-3)
        truth_bar = make_model("thickwall", theta0_deg=truth["theta0_deg"],
                               C10_MPa=truth["rubber_scale"] * SILASTIC_S.C10_MPa,
                               C01_MPa=truth["rubber_scale"] * SILASTIC_S.C01_MPa,
                               gap_mm=truth["gap_mm"]).predict(
            1.0, D0_mm, t0_mm, eps_truth).extras["threshold_pressure_bar"]
        assert abs(float(difference)) <= 0.1 and float(fitted) - float(measured) == \
            pytest.approx(float(difference), abs=2e-3), (table, why)  # 3 decimals shown
        # the measured zero is the truth's: the line through the steps is no artefact
        assert float(measured) == pytest.approx(truth_bar, abs=0.1), (table, why)
    # a threshold even at eps 0, where a gap-free muscle has 0: the truths drawn here (gap >=
    # 0.5 mm) put it at 0.047 bar or more
    assert float(rows[0][2]) > 0.03, (table, why)


def test_a_gap_fitted_with_the_fe_leaves_the_sliding_braid_out_of_the_intervals(gapped):
    # the guide's `--params theta0,rubber,gap --model axisym:mesh=coarse`: the sliding sleeve
    # takes no gap, so its model-form term cannot be computed (was: 'gap_mm=0.66 is invalid
    # with braid='sliding'' after the fit, nothing written)
    truth, runs = gapped
    result = identify(runs[:1], params="theta0,gap", model="axisym:mesh=coarse",
                      search="model", workers=1, cache_dir=None)
    assert result.model_form["braid"] == {
        "skipped": "a gap is fitted, and a gap is modelled with the bonded braid only"}
    assert result.fit.values["gap_mm"] > 0.0


@pytest.mark.parametrize("model, braid", [("axisym:mesh=coarse", "sliding"),
                                          ("axisym:mesh=coarse,braid=sliding", None)])
def test_a_gap_with_the_sliding_sleeve_is_refused_before_the_search(gapped, model, braid):
    # was: 'gap_mm=0.2 is invalid with braid=sliding', the search's start value refused
    _, runs = gapped
    with pytest.raises(ValueError) as caught:
        identify(runs, params="theta0,gap", model=model, braid=braid, search="model",
                 workers=1, cache_dir=None)
    assert str(caught.value) == (
        "--params gap needs the bonded braid: axisym:braid=sliding,mesh=coarse has the sliding "
        "sleeve, which takes no gap (expected --braid bonded and a --model without "
        "braid=sliding)")


def test_a_gap_asked_of_a_model_without_one_is_refused(gapped):
    # every physics rung with a rubber takes the gap now: a plug-in rung without one (the
    # thick-wall form registered without its gap parameter) is what identify must refuse
    from mkm.fem.ladder import C01, C10, L0, THETA0, Entry, register, unregister

    _, runs = gapped
    register(Entry("nogap", "mkm.fem.thickwall:ThickWall", "no gap", "a rung without a gap",
                   "closed form", {"theta0_deg": THETA0, "L0_mm": L0, "C10_MPa": C10,
                                   "C01_MPa": C01}))
    try:
        with pytest.raises(ValueError, match=r"--params gap needs a model with a gap between "
                                             r"tube and braid: --model 'nogap' has none "
                                             r"\(expected one of thickwall, axisym\)"):
            identify(runs, params="theta0,gap", model="nogap", search="model")
    finally:
        unregister("nogap")
