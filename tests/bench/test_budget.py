"""The uncertainty budget of a step (mkm.bench.budget): its terms against GUM arithmetic, its
columns in steps.csv, mkm check's printout, and its coverage on simulated runs of known truth."""

import math

import numpy as np
import pytest

from mkm.bench.budget import (
    COVERAGE_PROBABILITY,
    Instrument,
    Term,
    budget_table,
    coverage_factor,
    expected_budget,
    residual_std,
    step_budget,
)
from mkm.bench.config import Step, load_config
from mkm.bench.coverage import instrument_draw, simulated_coverage
from mkm.bench.procedures import check
from mkm.bench.run import acquire
from mkm.bench.sequence import HoldStats
from mkm.bench.storage import STEP_COLUMNS, STEP_COLUMNS_UNBUDGETED, load_run
from mkm.identify.runs import load_run_data


@pytest.fixture(scope="module")
def config():
    return load_config()


def test_adc_step_of_the_usb6001_on_the_default_cell(config):
    # the numbers: 14 bits over +-10 V = 1.22 mV = 0.24 N at 196.133 N/V
    i = Instrument.from_config(config)
    assert i.lsb_V == pytest.approx(20.0 / 2**14)
    assert i.lsb_N == pytest.approx(0.2394, abs=1e-4)


def test_terms_follow_the_gum_for_known_inputs(config):
    i = Instrument.from_config(config)
    b = step_budget(i, force_N=500.0, force_N_std=0.4, n=50, force_drift_N=0.0,
                    tare_std_N=0.4, tare_n=50, pressure_bar=2.0)
    terms = {t.name: t.u for t in b.terms}
    assert terms["load-cell sensitivity"] == pytest.approx(0.001 * 500 / math.sqrt(3))
    assert terms["load-cell non-linearity"] == pytest.approx(0.0005 * 1961.33 / math.sqrt(3))
    assert terms["load-cell zero drift"] == pytest.approx(0.0002 * 1961.33 / math.sqrt(3))
    # the scatter about a fitted line has n - 2 degrees of freedom
    assert terms["noise over the hold"] == pytest.approx(0.4 * math.sqrt(49 / 48) / math.sqrt(50))
    assert terms["tare spread"] == pytest.approx(0.4 / math.sqrt(50))
    # dithered (scatter 0.4 N >= half a step): the rounding averages down in hold and tare
    assert terms["ADC resolution"] == pytest.approx(
        i.lsb_N / math.sqrt(12) * math.sqrt(2 / 50))
    assert b.force_u_N == pytest.approx(math.sqrt(sum(
        u**2 for name, u in terms.items() if not name.startswith(("pressure", "ADC resolution ("))
    )))
    assert b.force_U_N == pytest.approx(b.k("force") * b.force_u_N)
    # the rectangular data-sheet bounds dominate: k between one bound alone's 1.65 and 2
    assert 1.7 < b.k("force") < 2.0
    assert b.pressure_u_bar == pytest.approx(math.hypot(
        0.04 / math.sqrt(3), i.lsb_V * 4.0 / 4.0 / math.sqrt(12)))
    ranked = b.ranked("force")
    assert ranked[0][0].name == "load-cell non-linearity"
    assert sum(share for _, share in ranked) == pytest.approx(1.0)


def test_a_quiet_signal_keeps_the_full_rounding(config):
    # scatter below half a step: the ADC rounds every sample the same way, averaging cannot help
    i = Instrument.from_config(config)
    b = step_budget(i, 100.0, 0.05, 50, 0.0, 0.05, 50, pressure_bar=0.5)
    q = {t.name: t.u for t in b.terms}["ADC resolution"]
    assert q == pytest.approx(math.sqrt(2) * i.lsb_N / math.sqrt(12))


def test_residual_std_removes_an_exact_trend():
    rng = np.random.default_rng(1)
    t = np.arange(50) * 0.1
    f = 100 + 0.3 * t + rng.normal(0, 0.4, t.size)
    slope, intercept = np.polyfit(t, f, 1)
    expected = np.sqrt(np.sum((f - (slope * t + intercept))**2) / (t.size - 2))
    drift = slope * (t[-1] - t[0])
    assert residual_std(f.std(ddof=1), t.size, drift) == pytest.approx(expected, rel=1e-9)


def test_hold_stats_match_numpy(config):
    rng = np.random.default_rng(2)
    t = 10 + np.arange(60) * 0.1
    f = 300 - 0.2 * (t - 10) + rng.normal(0, 0.5, t.size)
    hold = HoldStats()
    for ti, fi in zip(t, f, strict=True):
        hold.add(float(ti), float(fi), 1.0)
    assert hold.mean == pytest.approx(f.mean())
    assert hold.std == pytest.approx(f.std(ddof=1))
    assert hold.drift_N == pytest.approx(np.polyfit(t, f, 1)[0] * (t[-1] - t[0]))
    row = hold.record(Step(0, "up", 0, 1.0), Instrument.from_config(config),
                      {"std_N": 0.4, "n": 50}, True, 5.0, 5.0, 16.0)
    assert 1.65 < row.force_U_N / row.force_u_N <= 2.0
    assert row.force_u_N > 0.5 / math.sqrt(60)  # at least the noise of the mean


def test_steps_csv_carries_the_budget(config, tmp_path):
    small = config.replace(sequence={"pressures_bar": (0.5, 1.0), "down_sweep": False,
                                     "preconditioning_cycles": 0})
    result = acquire(small, out_root=tmp_path, notify=lambda m: None)
    steps = load_run(result.path).steps
    assert list(steps.columns) == list(STEP_COLUMNS)
    for column in ("force_u_N", "force_U_N", "pressure_u_bar", "pressure_U_bar"):
        assert (steps[column] > 0).all()
    k = steps["force_U_N"] / steps["force_u_N"]
    assert ((k > 1.65) & (k <= 2.0 + 1e-4)).all()
    # the default cell's data sheet alone: non-linearity 0.57 N, zero drift 0.23 N
    assert (steps["force_u_N"] > 0.6).all() and (steps["force_u_N"] < 2.0).all()


def test_steps_csv_without_the_budget_still_loads(config, tmp_path):
    small = config.replace(sequence={"pressures_bar": (0.5,), "down_sweep": False,
                                     "preconditioning_cycles": 0})
    path = acquire(small, out_root=tmp_path, notify=lambda m: None).path
    csv = path / "steps.csv"
    lines = csv.read_text().splitlines()
    k = len(STEP_COLUMNS_UNBUDGETED)
    csv.write_text("\n".join(",".join(line.split(",")[:k]) for line in lines) + "\n")
    steps = load_run(path).steps
    assert list(steps.columns) == list(STEP_COLUMNS)
    assert steps["force_U_N"].isna().all() and steps["force_N_mean"].notna().all()


def test_datasheet_settings_are_bounded(config):
    with pytest.raises(ValueError, match=r"loadcell\.sensitivity_tolerance_fraction=0\.2 is "
                                         r"invalid: expected 0 to 0\.05"):
        config.replace(loadcell={"sensitivity_tolerance_fraction": 0.2})
    with pytest.raises(ValueError, match=r"regulator\.monitor_accuracy_bar=-0\.1 is invalid"):
        config.replace(regulator={"monitor_accuracy_bar": -0.1})


#: a monitor's error itemised (bar, and a fraction of the reading for the span)
COMPONENTS = {"monitor_zero_bar": 0.016, "monitor_span_fraction": 0.004,
              "monitor_nonlinearity_bar": 0.008, "monitor_hysteresis_bar": 0.012}


def test_monitor_components_are_terms_of_their_own(config):
    c = config.replace(regulator=COMPONENTS)
    i = Instrument.from_config(c)
    lsb_bar = 20.0 / 2**14 * 4.0 / 4.0  # one ADC step over the 4 V monitor span of 4 bar
    for p, expected_u in ((0.0, 0.010899), (4.0, 0.014287)):
        b = step_budget(i, 500.0, 0.4, 50, 0.0, 0.4, 50, pressure_bar=p)
        terms = {t.name: t for t in b.terms if t.quantity == "pressure"}
        assert {t.distribution for t in terms.values()} == {"rectangular"}
        # GUM 4.3.7: a +- a bound, nothing more known, is u = a / sqrt 3; the span error is a
        # fraction of the reading; a branch's reading is off by at most half the hysteresis
        u = math.sqrt((0.016**2 + (0.004 * p)**2 + 0.008**2 + (0.012 / 2)**2) / 3
                      + lsb_bar**2 / 12)
        assert terms["monitor span error"].u == pytest.approx(0.004 * p / math.sqrt(3))
        assert terms["monitor hysteresis"].u == pytest.approx(0.006 / math.sqrt(3))
        assert "pressure reading accuracy" not in terms
        assert b.pressure_u_bar == pytest.approx(u, rel=1e-12)
        assert b.pressure_u_bar == pytest.approx(expected_u, rel=1e-4)
        # four bounds and a step convolved: between one bound alone's 1.65 and a normal's 2
        assert 1.8 < b.k("pressure") < 2.0
        assert b.pressure_U_bar == pytest.approx(b.k("pressure") * u)
    # a component not declared is no term
    only = Instrument.from_config(config.replace(regulator={"monitor_zero_bar": 0.02}))
    names = [t.name for t in step_budget(only, 500.0, 0.4, 50, 0.0, 0.4, 50,
                                         pressure_bar=1.0).terms if t.quantity == "pressure"]
    assert names == ["monitor zero error", "ADC resolution (monitor)"]


def test_a_run_records_the_components_and_its_steps_carry_them(config, tmp_path):
    small = config.replace(regulator=COMPONENTS, sequence={
        "pressures_bar": (2.0,), "down_sweep": False, "preconditioning_cycles": 0})
    run = load_run(acquire(small, out_root=tmp_path, notify=lambda m: None).path)
    # the report recomputes a step's terms from run.json: the components are there
    i = Instrument.from_run(run.meta)
    assert i.monitor_components == COMPONENTS
    s = run.steps.iloc[0]
    b = step_budget(i, s.force_N_mean, s.force_N_std, int(s.n), s.force_drift_N, math.nan, 0,
                    pressure_bar=s.pressure_bar_mean)
    assert s.pressure_u_bar == pytest.approx(b.pressure_u_bar, rel=1e-5)  # steps.csv: 6 digits
    assert s.pressure_u_bar == pytest.approx(math.sqrt(
        (0.016**2 + (0.004 * s.pressure_bar_mean)**2 + 0.008**2 + 0.006**2) / 3
        + (i.lsb_V * i.monitor_bar_per_V)**2 / 12), rel=1e-5)
    # identify bounds the monitor's offset by what no line carries (zero, non-linearity, half
    # the hysteresis) and its gain by the span error, read from the same record
    data = load_run_data(run.path)
    assert data.instrument_declared
    assert data.monitor_offset_bound_bar == pytest.approx(0.016 + 0.008 + 0.012 / 2)
    assert data.monitor_gain_bound == pytest.approx(0.004)


def test_without_components_the_pressure_budget_is_the_one_bound(config):
    # identify's bounds: the one accuracy as the offset, and as the gain at the top pressure
    regulator = config.regulator
    assert regulator.reading_bounds() == (regulator.monitor_accuracy_bar,
                                          regulator.monitor_accuracy_bar
                                          / regulator.max_pressure_bar)
    i = Instrument.from_config(config)
    assert config.regulator.monitor_components == {} and i.monitor_components == {}
    lsb_bar = i.lsb_V * i.monitor_bar_per_V  # 1.22 mV over 1 V/bar
    expected = (Term("pressure reading accuracy", "pressure", 0.04 / math.sqrt(3), "B",
                     "regulator.monitor_accuracy_bar=0.04", "rectangular"),
                Term("ADC resolution (monitor)", "pressure", lsb_bar / math.sqrt(12), "B",
                     f"1 step = {lsb_bar:.3g} bar", "rectangular"))
    for p in (0.0, 1.0, 2.5):
        b = step_budget(i, 500.0, 0.4, 50, 0.0, 0.4, 50, pressure_bar=p)
        assert tuple(t for t in b.terms if t.quantity == "pressure") == expected
        # one bound dominating: k near 0.9545 sqrt 3
        assert b.pressure_U_bar == pytest.approx(0.0382, abs=1e-4)


@pytest.mark.parametrize("setting, message", [
    ("monitor_span_fraction = 0.2", "regulator.monitor_span_fraction=0.2 is invalid: expected "
                                    "0 to 0.05 (a fraction of the reading)"),
    ("monitor_zero_bar = -0.01", "regulator.monitor_zero_bar=-0.01 is invalid: expected 0 to "
                                 "0.4 bar"),
    ("monitor_hysteresis_bar = 1.0", "regulator.monitor_hysteresis_bar=1 is invalid"),
])
def test_a_bad_component_is_one_line_and_exit_2(config, tmp_path, capsys, setting, message):
    from mkm.cli import main

    path = tmp_path / "bad.toml"
    path.write_text(config.text.replace("[regulator]\n", f"[regulator]\n{setting}\n"),
                    encoding="utf-8")
    assert main(["check", "--config", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0]


def test_monitor_component_draws_fill_each_bound(config):
    # each component uniform within its own bound, independent: the truth it stands for
    c = config.replace(regulator=COMPONENTS)
    draws = [instrument_draw(c, seed) for seed in range(2000)]
    for key, low, high in (("monitor_offset_bar", -0.016, 0.016),
                           ("monitor_gain", 1 - 0.004, 1 + 0.004),
                           ("monitor_bow_bar", -0.008, 0.008),
                           ("monitor_hysteresis_bar", 0.0, 0.012)):
        x = np.array([d[key] for d in draws])
        assert low <= x.min() and x.max() <= high
        # uniform: a mean in the middle, a standard deviation of width / sqrt 12 (sd 1.6 %)
        assert x.mean() == pytest.approx((low + high) / 2, abs=0.03 * (high - low))
        assert x.std() == pytest.approx((high - low) / math.sqrt(12), rel=0.05)
    # only monitor_accuracy_bar: the draw is the linear sensor's, unchanged
    assert set(instrument_draw(config, 0)) == {"loadcell_gain", "monitor_offset_bar",
                                               "monitor_gain"}


def test_check_prints_the_expected_budget(config):
    text, _, _ = check(config)
    lines = text.splitlines()
    start = next(k for k, line in enumerate(lines) if line.split()[:2] == ["P", "[bar]"])
    rows = [line.split() for line in lines[start + 1:start + 11]]
    assert [float(r[0]) for r in rows] == pytest.approx(np.arange(0.25, 2.51, 0.25))
    U = [float(r[2]) for r in rows]
    assert U == sorted(U)  # the sensitivity term grows with the force
    top = expected_budget(config, float(rows[-1][1]), float(rows[-1][0]))
    assert U[-1] == pytest.approx(top.force_U_N, abs=0.01)
    table = budget_table(top)
    assert table[0].split()[:2] == ["term", "type"]
    assert any(line.split()[0] == "combined" for line in table)
    assert table[0] in lines and "," not in table[0]  # a table to read, not CSV in the prose
    # the pressure's terms at the top pressure: the declared components, each on its line
    text, _, _ = check(config.replace(regulator=COMPONENTS))
    span = [line for line in text.splitlines() if "monitor span error" in line]
    assert len(span) == 1 and span[0].endswith("regulator.monitor_span_fraction=0.004 x 2.5 bar")
    assert "monitor non-linearity" in text and "pressure reading accuracy" not in text


def test_coverage_on_simulated_runs():
    # 5 runs x 19 settled steps of known truth (noise, quantisation, friction, creep on), each
    # run's load-cell gain and monitor error drawn within the data sheet. The steps of a run
    # share its gain, so 5 runs tell little about the coverage (the benchmark pools 200 runs
    # for the 95 +- 3 % target); here: the standard uncertainty is the error's spread.
    steps = simulated_coverage(load_config(), range(5))
    assert len(steps) == 95
    assert steps["covered"].mean() >= 0.75
    z = (steps["force_N_mean"] - steps["force_true_N"]) / steps["force_u_N"]
    assert 0.6 < z.std() < 1.4
    # the recorded force is the true one times the drawn gain, to within the step's noise
    top = steps.loc[steps["force_true_N"] > 500]
    assert ((top["force_N_mean"] / top["force_true_N"] - top["loadcell_gain"]).abs()
            < 3 * top["force_u_N"] / top["force_true_N"]).all()


def test_monitor_draws_meet_the_data_sheet_over_the_range_and_reach_it_at_its_ends():
    # the monitor reads gain * P + offset: a linear sensor within +-a at 0 and at full scale is
    # within it at every pressure; every such sensor equally likely makes the error at either
    # end uniform on +-a (mean |e| = a/2, the budget's rectangular term exact there) and the
    # error mid-range the mean of two such: P(|e| <= a/2) = 3/4 instead of 1/2
    config = load_config()
    a, top = config.regulator.monitor_accuracy_bar, config.regulator.max_pressure_bar
    draws = [instrument_draw(config, seed) for seed in range(4000)]
    offset = np.array([d["monitor_offset_bar"] for d in draws])
    full = np.array([(d["monitor_gain"] - 1) * top for d in draws]) + offset
    middle = offset + (full - offset) / 2
    for end in (offset, full):
        assert np.abs(end).max() <= a
        assert np.mean(np.abs(end)) == pytest.approx(a / 2, rel=0.03)  # binomial sd ~1 %
    assert np.mean(np.abs(middle) <= a / 2) == pytest.approx(0.75, abs=0.03)
    assert abs(np.corrcoef(offset, full)[0, 1]) < 0.05
    gain = np.array([d["loadcell_gain"] for d in draws]) - 1
    assert np.abs(gain).max() <= config.loadcell.sensitivity_tolerance_fraction


def test_coverage_factors_are_the_quantiles_of_known_distributions():
    normal = Term("noise", "force", 1.0, "A", "")

    def bound(u):
        return Term("bound", "force", u, "B", "", "rectangular")

    assert COVERAGE_PROBABILITY == pytest.approx(0.9545, abs=1e-4)
    assert coverage_factor([normal]) == pytest.approx(2.0, abs=1e-9)
    assert coverage_factor([bound(1.0)]) == pytest.approx(COVERAGE_PROBABILITY * math.sqrt(3))
    # two equal bounds: a triangle of half-width 2a; P(|X| <= x) = 1 - (1 - x/2a)^2
    a = math.sqrt(3)
    x = 2 * a * (1 - math.sqrt(1 - COVERAGE_PROBABILITY))
    assert coverage_factor([bound(1.0), bound(1.0)]) == pytest.approx(x / math.sqrt(2),
                                                                      rel=2e-3)
    # a bound and a normal term of equal u: checked against 400 000 seeded draws
    rng = np.random.default_rng(3)
    draws = rng.uniform(-a, a, 400_000) + rng.standard_normal(400_000)
    k = coverage_factor([bound(1.0), normal])
    assert np.mean(np.abs(draws) <= k * math.sqrt(2)) == pytest.approx(COVERAGE_PROBABILITY,
                                                                       abs=0.002)
    # a bound far narrower than the grid's step beside a normal term is the normal term's
    # (a bound of 1.4e-20 beside u 1.9e-3 gave NaN: no grid point inside the box)
    tiny = Term("resolution", "force", 1.3985004312108452e-20, "B", "", "rectangular")
    wide = Term("noise", "force", 0.001914979014822696, "A", "")
    assert coverage_factor([wide, tiny]) == pytest.approx(2.0, abs=1e-5)



def test_the_convolution_is_the_direct_sum_centred():
    """The coverage factor convolves through scipy.fft (scipy.signal, a second of import at every
    acquisition's start, is left out): the direct sum's numbers, centred as ``mode="same"``,
    boxes of both parities and a Gaussian."""
    from mkm.bench.budget import _convolve_same

    rng = np.random.default_rng(7)
    x = np.linspace(-3.0, 3.0, 4001)
    density = np.zeros_like(x)
    density[2000] = 1.0 / (x[1] - x[0])
    kernels = [(np.abs(x) <= a).astype(float) for a in rng.uniform(0.05, 1.0, 3)]
    kernels.append(np.exp(-0.5 * (x / 0.3) ** 2))
    kernels.append(np.ones(6))  # an even length: the centring's other case
    for kernel in kernels:
        expected = np.convolve(density, kernel / kernel.sum(), mode="same")
        got = _convolve_same(density, kernel / kernel.sum())
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12 * expected.max())
        density = got


def test_a_declared_accuracy_is_one_rectangular_term_per_part():
    """A table measured elsewhere carries the bounds its lab declares: each part its own
    rectangular term (u = a / sqrt 3), the expanded U the quantile of their sum."""
    from mkm.bench.budget import Declared, declared_budget

    declared = {"force": Declared(0.5, 0.01, "0.5N+1%"), "pressure": Declared(0.01, 0.0, "")}
    budget = declared_budget(declared, force_N=50.0, pressure_bar=2.0)
    # 0.5 N and 1 % of 50 N: two equal bounds, a triangle of half-width 1 N
    assert budget.force_u_N == pytest.approx(math.sqrt(2 / 3) * 0.5)
    triangle = 2 * 0.5 * (1 - math.sqrt(1 - COVERAGE_PROBABILITY))
    assert budget.force_U_N == pytest.approx(triangle, rel=2e-3)
    # one bound alone: U is 95.45 % of the half-width
    assert budget.pressure_U_bar == pytest.approx(COVERAGE_PROBABILITY * 0.01)
    # a pressure without a declared bound has none: U 0, so E_n still has a denominator
    alone = declared_budget({"force": Declared(0.5)}, 50.0, 2.0)
    assert (alone.pressure_u_bar, alone.pressure_U_bar) == (0.0, 0.0)
    # a plateau of a time series adds its noise over the hold (type A), as the bench does
    held = declared_budget({"force": Declared(0.5)}, 50.0, 2.0, force_N_std=0.3, n=30,
                           force_drift_N=0.0)
    noise = residual_std(0.3, 30, 0.0) / math.sqrt(30)
    assert held.force_u_N == pytest.approx(math.hypot(0.5 / math.sqrt(3), noise))
