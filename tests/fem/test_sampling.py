"""Fresh muscles: every draw inside the practical range and its coupled constraints."""

import numpy as np
import pytest

from mkm.fem.limits import PRACTICAL_RANGE, lock_eps
from mkm.fem.sampling import LOCK_FRACTION, draw_muscles


@pytest.fixture(scope="module")
def draw():
    return draw_muscles(10_000, seed=34)


def test_every_draw_respects_every_constraint(draw):
    box = PRACTICAL_RANGE
    c = draw.columns()
    for name in ("D0_mm", "t0_mm", "L0_mm", "theta0_deg", "C10_MPa"):
        low, high = getattr(box, name)
        assert np.all((c[name] >= low) & (c[name] <= high)), name
    assert np.all(c["t0_mm"] <= box.t0_per_D0_max * c["D0_mm"])
    assert np.all(c["L0_mm"] >= box.L0_per_D0_min * c["D0_mm"])
    assert np.all((c["eps"] >= 0) & (c["eps"] <= LOCK_FRACTION * lock_eps(c["theta0_deg"])))
    ratio = c["C01_MPa"] / c["C10_MPa"]
    assert np.all((ratio >= box.C01_per_C10[0]) & (ratio <= box.C01_per_C10[1]))
    assert not any(box.violations(**m.record()) for m in draw.muscles[:500])


def test_draws_fill_the_range(draw):
    # log-uniform D0 over 5-60 mm: a twelfth of the log span holds ~1/12 of the draws; the
    # corners a lab cares about are reached (Festo-class 10 mm, the paper's 30-50 mm)
    c = draw.columns()
    low, high = PRACTICAL_RANGE.D0_mm
    share = np.mean(c["D0_mm"] < low * (high / low) ** (1 / 12))
    assert share == pytest.approx(1 / 12, abs=0.01)  # binomial sd 0.003 at n = 10 000
    assert np.mean(c["D0_mm"] < 10) > 0.25 and np.mean(c["D0_mm"] > 30) > 0.25
    assert c["eps"].max() > 0.9 * LOCK_FRACTION * lock_eps(15.0)
    assert c["C10_MPa"].min() < 0.031 and c["C10_MPa"].max() > 0.59


def test_the_seed_draws_the_same_muscles_again(draw):
    again = draw_muscles(20, seed=34)
    assert again.muscles == draw.muscles[:20]  # the first k of a draw of n are the draw of k
    fresh = draw_muscles(3)
    assert draw_muscles(3, seed=fresh.seed).muscles == fresh.muscles
    assert draw.record()["seed"] == 34 and draw.record()["box"]["D0_mm"] == [5.0, 60.0]


def test_a_smaller_box_is_respected():
    box = PRACTICAL_RANGE.replace(D0_mm=(30.0, 50.0), t0_mm=(2.0, 4.0), theta0_deg=(28.0, 38.0))
    c = draw_muscles(2000, seed=1, box=box).columns()
    assert c["D0_mm"].min() >= 30 and c["D0_mm"].max() <= 50
    assert c["t0_mm"].min() >= 2 and c["t0_mm"].max() <= 4


@pytest.mark.parametrize("kwargs, message", [
    ({"n": -1}, "n=-1 is invalid"), ({"n": 2.5}, "n=2.5 is invalid"),
    ({"n": 3, "lock_fraction": 1.5}, "lock_fraction=1.5 is invalid"),
])
def test_bad_arguments_are_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        draw_muscles(**kwargs)
