"""The pressure monitor's zero as the runs measure it (mkm.identify.runs.vented_zero): read while
the run is vented for the tare, it bounds the fitted offset where the monitor's data sheet
declares its zero error apart, and a reading beyond the declared bound is said.

The runs are simulated with the thick-wall closed form and fitted with it, the monitor off by a
known offset; its readings carry 1 mbar of noise, so 50 tare readings give the zero to about
0.15 mbar.
"""

from __future__ import annotations

import re

import pytest

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.sim_settings import remove_simulator_settings
from mkm.identify import identify
from mkm.identify.runs import (
    VENTED_SE_FACTOR,
    load_runs,
    offset_bound_said,
    offset_search_bar,
    vented_beyond_bound,
    vented_zero,
)

OFFSET_BAR = 0.025
#: an ITV-class monitor's error itemised: the zero error declared larger than the truth's offset
ITEMISED = {"monitor_zero_bar": 0.03, "monitor_span_fraction": 0.004,
            "monitor_nonlinearity_bar": 0.002, "monitor_hysteresis_bar": 0.002}


def simulated(tmp_path_factory, regulator: dict, offset_bar: float, **truth) -> list:
    out = tmp_path_factory.mktemp("vented")
    paths = []
    for k, eps in enumerate((0.0, 0.122)):
        config = load_config(eps=eps).replace(
            regulator=regulator,
            sequence={"pressures_bar": (0.25, 0.5, 1.0, 1.5, 2.0, 2.5),
                      "preconditioning_cycles": 0},
            sim={"model": "thickwall", "seed": 31 + k,
                 "truth": {"monitor_offset_bar": offset_bar, **truth}})
        result = acquire(config, out_root=out, notify=lambda message: None)
        assert result.status == "complete"
        remove_simulator_settings(result.path)
        paths.append(result.path)
    return paths


@pytest.fixture(scope="module")
def itemised(tmp_path_factory):
    return simulated(tmp_path_factory, ITEMISED, OFFSET_BAR)


def test_the_tare_reads_the_monitors_zero(itemised):
    runs = load_runs(itemised)
    for run in runs:
        mean, se = run.vented_bar
        # vented, the true pressure is 0: the monitor reads its offset and its noise
        assert 0 < se < 0.0005
        assert mean == pytest.approx(OFFSET_BAR, abs=4 * se + 0.001)  # + half the hysteresis
    centre, half = vented_zero(runs)
    # what a zero reading cannot show: the non-linearity and half the hysteresis, as declared
    assert 0.003 <= half < 0.003 + 0.001 + VENTED_SE_FACTOR * 0.0005
    assert offset_search_bar(runs) == pytest.approx((centre - half, centre + half))
    assert "vented reading" in offset_bound_said(runs)
    assert vented_beyond_bound(runs) is None


def test_identify_takes_the_offset_from_the_vented_reading(itemised):
    found = identify(itemised, params="theta0,rubber,friction,creep,offset",
                     model="thickwall", search="model", cache_dir=None, workers=1)
    table = found.parameters().set_index("parameter")
    low, high = table.loc["pressure_offset_bar", ["ci_low", "ci_high"]]
    assert low <= OFFSET_BAR <= high
    # the declared bound alone would allow +-0.036 bar: the vented reading narrows it tenfold
    assert high - low < 0.008
    assert "vented reading" in table.loc["pressure_offset_bar", "source"]


def test_one_accuracy_bound_keeps_the_declared_window(tmp_path_factory):
    # which share of one accuracy is the zero's, nobody declared: the window stays +-0.04 bar
    runs = load_runs(simulated(tmp_path_factory, {}, OFFSET_BAR))
    assert all(run.vented_bar is not None for run in runs)
    assert vented_zero(runs) is None
    assert offset_search_bar(runs) == (-0.04, 0.04)


def test_a_vented_reading_beyond_the_declared_bound_is_said(tmp_path_factory):
    # (past 0.05 bar the run's own vent check fails it: the monitor cannot verify a vent)
    runs = load_runs(simulated(tmp_path_factory, {}, 0.046))
    note = vented_beyond_bound(runs)
    assert note is not None and "+-0.04 bar" in note
    assert re.search(r"read \+0\.04[5-7]\d* bar vented", note), note


def test_a_declared_monitor_hysteresis_is_fitted_within_half_of_it(tmp_path_factory):
    # the monitor reads 2 mbar low on a rising step and 2 mbar high on a falling one (0.004 bar
    # between its branches, as declared): at ~400 N/bar that is 0.8 N, ten times a step's
    # noise, which the braid's friction (a share of the force) cannot take up
    runs = simulated(tmp_path_factory, {**ITEMISED, "monitor_hysteresis_bar": 0.004},
                     OFFSET_BAR, monitor_hysteresis_bar=0.004)
    found = identify(runs, model="thickwall", search="model", cache_dir=None, workers=1)
    assert not found.goodness.misfit and found.goodness.reduced < 2.0
    table = found.parameters().set_index("parameter")
    value, low, high = table.loc["pressure_hysteresis_bar", ["value", "ci_low", "ci_high"]]
    assert low <= 0.002 <= high and value == pytest.approx(0.002, abs=0.0005)
    low, high = table.loc["pressure_offset_bar", ["ci_low", "ci_high"]]
    assert low <= OFFSET_BAR <= high
    # where no hysteresis is declared, none is fitted
    assert "pressure_hysteresis_bar" not in identify(
        simulated(tmp_path_factory, {}, OFFSET_BAR), model="thickwall", search="model",
        cache_dir=None, workers=1).fit.names
