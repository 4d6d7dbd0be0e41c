"""Steps from a lab's time series (:mod:`mkm.bench.series`): the pieces on their own."""

import numpy as np
import pytest

from mkm.bench import series
from mkm.bench.config import load_config


def _staircase(rate_hz: float, seed: int = 0):
    """Vented 5 s, then 1 and 2 bar held 20 s each, reached by 0.1 bar/s ramps; noise
    0.005 bar."""
    t = np.arange(0.0, 85.0, 1.0 / rate_hz)
    p = np.interp(t, [0, 5, 15, 35, 45, 65, 85], [0, 0, 1, 1, 2, 2, 2])
    return t, p + np.random.default_rng(seed).normal(0, 0.005, t.size)


def test_plateaus_scan_each_sample_once(monkeypatch):
    # a start that could not hold min_s went on one sample at a time, each rescanning its band
    # with a running median: a 1 kHz record's ramps took minutes (a 60 s ramp at 1 kHz: 8 min)
    t, p = _staircase(1000.0)
    # a running median every 16 samples of a plateau: about n / 16 (sample by sample over the
    # 20 s of ramp, 20000 starts of about 300 samples each: some 400000)
    limit, calls, median = t.size // 8, [], np.median

    def counted(a, *args, **kwargs):
        calls.append(1)
        assert len(calls) <= limit, "np.median called more than n / 8 times"
        return median(a, *args, **kwargs)

    monkeypatch.setattr(series.np, "median", counted)
    found = series.plateaus(t, p)
    # the vented rest and the two holds, each found whole: it starts where the ramp comes
    # within the 0.03 bar band of its level (0.3 s of a 0.1 bar/s ramp) and ends where the
    # next ramp leaves it
    assert [round(q.level_bar, 2) for q in found] == [0.0, 1.0, 2.0]
    for q, (start_s, stop_s) in zip(found, [(0, 5), (15, 35), (45, 85)], strict=True):
        assert t[q.start] == np.clip(t[q.start], start_s - 0.35, start_s + 0.05)
        assert t[q.stop - 1] == np.clip(t[q.stop - 1], stop_s - 0.05, stop_s + 0.35)


def test_plateaus_are_those_of_the_record_at_any_rate():
    # the same staircase at 10 Hz and at 1 kHz: the same plateaus, to the 0.3 s a 0.1 bar/s
    # ramp takes through the 0.03 bar band and a sample at 10 Hz
    low, high = (series.plateaus(*_staircase(rate)) for rate in (10.0, 1000.0))
    t_low, t_high = _staircase(10.0)[0], _staircase(1000.0)[0]
    assert len(low) == len(high) == 3
    for a, b in zip(low, high, strict=True):
        assert abs(t_low[a.start] - t_high[b.start]) <= 0.4
        assert abs(t_low[a.stop - 1] - t_high[b.stop - 1]) <= 0.4
        assert abs(a.level_bar - b.level_bar) < 0.005


def test_a_slow_ramp_is_a_ramp_and_a_staircase_a_staircase():
    # a quasi-static ramp of 0.017 bar/s stays 2-6 s in the 0.03 bar band that moves with its
    # running median: it was read as a staircase of 94 plateaus, 84 of them unsettled, and
    # identify found no usable step
    rng = np.random.default_rng(4)
    for rate_hz in (10.0, 100.0):
        for bar_per_s in (0.005, 0.017, 0.1):
            top_s = 2.5 / bar_per_s
            t = np.arange(0.0, 2 * top_s + 10.0, 1.0 / rate_hz)
            p = np.interp(t, [0, 5, 5 + top_s, 5 + 2 * top_s, 10 + 2 * top_s],
                          [0, 0, 2.5, 0, 0]) + rng.normal(0, 0.005, t.size)
            assert series.shape(t, p) == "ramp", (rate_hz, bar_per_s)
            # the vented rest before it is still a plateau: a gauge's vented reading is found
            assert abs(series.vented_offset(t, p + 0.6) - 0.6) < 0.006
        t, p = _staircase(rate_hz)
        assert series.shape(t, p) == "staircase"


def test_a_hold_leaves_out_the_next_steps_rise_within_its_band():
    # a 60 mm muscle at 0.1 bar steps (4256 N/bar, a 3 N cell; the regulator's time constant
    # 0.4 s at 10 Hz): the first sample of each rise, 0.022 bar up, lies within the plateau's
    # 0.03 bar band and pulled 95 N into the hold's last sample, its spread 14 N instead of 3
    rng = np.random.default_rng(60)
    levels = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5]
    set_bar = np.repeat(levels, 80)
    p = np.zeros(set_bar.size)
    for k in range(1, p.size):
        p[k] = set_bar[k] + (p[k - 1] - set_bar[k]) * np.exp(-0.1 / 0.4)
    t = np.arange(p.size) * 0.1
    truth = 4256.0 * p
    force = truth + rng.normal(0.0, 3.0, t.size)
    pressure = p + rng.normal(0.0, 0.002, t.size)
    steps, step_of = series.staircase_steps(t, pressure, force, load_config())
    assert [round(s.set_pressure_bar, 1) for s in steps] == levels[1:]
    for k, step in enumerate(steps[:-1]):  # the last one ends with the record
        assert 2.0 < step.force_N_std < 4.5, step
        plateau = step_of == k
        assert set_bar[plateau].max() == set_bar[plateau].min()  # none of the next step's rise
        hold = (t >= step.start_s + step.settle_s - 1e-9) & (t <= step.end_s + 1e-9)
        # 3 N over some 40 samples: a standard error of 0.5 N
        assert step.force_N_mean == pytest.approx(truth[hold].mean(), abs=2.0)
