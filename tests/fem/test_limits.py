"""The practical range: declared once, inside the typo limits, stated from its own numbers."""

import math

import numpy as np
import pytest

from mkm.fem.limits import (
    LIMITS,
    LOCKING_ANGLE_DEG,
    PRACTICAL_RANGE,
    PracticalRange,
    lock_eps,
    range_text,
)


def test_lock_is_the_braid_geometry():
    # cos(theta_lock) = 1/sqrt(3): a braid at the locking angle at rest cannot shorten at all
    assert lock_eps(LOCKING_ANGLE_DEG) == pytest.approx(0.0, abs=1e-12)
    # at 30 deg: 1 - 1/(sqrt(3) * sqrt(3)/2) = 1/3
    assert lock_eps(30.0) == pytest.approx(1.0 / 3.0, rel=1e-12)


def test_practical_range_is_inside_the_limits():
    for name in PracticalRange.INTERVALS:
        low, high = getattr(PRACTICAL_RANGE, name)
        assert low <= high
        if name in LIMITS:
            assert LIMITS[name][0] <= low and high <= LIMITS[name][1]


def test_range_text_states_every_number_of_the_range():
    text = range_text()
    for name in PracticalRange.INTERVALS:
        low, high = getattr(PRACTICAL_RANGE, name)
        if name != "eps_per_lock":
            assert f"{low:g}-{high:g}" in text, name
    assert f"t0 <= {PRACTICAL_RANGE.t0_per_D0_max:g} D0" in text
    assert f"L0 >= {PRACTICAL_RANGE.L0_per_D0_min:g} D0" in text
    assert "eps from 0 to the braid lock" in text
    # the lock at both ends of the angle: 1 - 1/(sqrt(3) cos 15 deg) = 0.402, at 40 deg 0.246
    assert "0.402 at 15 deg" in text and "0.246 at 40 deg" in text
    # the numbers come from the range given, not typed
    assert "D0 8-60 mm" in range_text(PRACTICAL_RANGE.replace(D0_mm=(8.0, 60.0)))


def test_violations_name_each_constraint():
    inside = dict(D0_mm=10.0, t0_mm=2.0, L0_mm=100.0, pressure_bar=6.0, theta0_deg=30.0,
                  C10_MPa=0.3, C01_MPa=0.3, eps=0.3)
    assert PRACTICAL_RANGE.violations(**inside) == []
    assert PRACTICAL_RANGE.violations(**{**inside, "t0_mm": 3.5}) == [
        "t0_mm=3.5 above 0.3 D0_mm = 3"]
    assert PRACTICAL_RANGE.violations(**{**inside, "L0_mm": 29.0}) == [
        "L0_mm=29 outside [50, 1000]", "L0_mm=29 below 3 D0_mm = 30"]
    assert PRACTICAL_RANGE.violations(**{**inside, "C01_MPa": 0.46}) == [
        "C01_MPa=0.46 outside [0, 1.5] x C10_MPa"]
    # a value typed at a bound that is a product lies on it: C01/C10 1.5 at the stiffest
    # rubber (1.5 x 0.6 MPa is 0.8999999999999999 in floating point, so C01 0.9 was "outside"),
    # the thickest wall of a 6 mm tube (0.3 x 6 = 1.7999999999999998), the shortest 17.1 mm
    # one (3 x 17.1 = 51.300000000000004)
    at_bounds = dict(C10_MPa=0.6, C01_MPa=0.9, D0_mm=6.0, t0_mm=1.8, L0_mm=60.0)
    assert 1.5 * 0.6 < 0.9 and 0.3 * 6.0 < 1.8 and 3 * 17.1 > 51.3
    assert PRACTICAL_RANGE.violations(**at_bounds) == []
    assert PRACTICAL_RANGE.violations(D0_mm=17.1, L0_mm=51.3) == []
    assert PRACTICAL_RANGE.violations(**{**at_bounds, "C01_MPa": 0.9001}) == [
        "C01_MPa=0.9001 outside [0, 1.5] x C10_MPa"]
    # past the lock at 30 deg (1/3)
    (eps,) = PRACTICAL_RANGE.violations(**{**inside, "eps": 0.34})
    assert eps.startswith("eps=0.34 outside [0, 0.3333]")


def test_hull_is_the_box_around_the_range():
    hull = PRACTICAL_RANGE.hull()
    assert hull["eps"] == pytest.approx((0.0, 1 - 1 / (math.sqrt(3) * math.cos(math.radians(15)))))
    assert hull["C01_MPa"] == pytest.approx((0.0, 0.9))
    assert hull["t0_mm"] == (0.5, 6.0)


@pytest.mark.parametrize("changes, message", [
    ({"D0_mm": (60.0, 5.0)}, "D0_mm=(60, 5) is invalid: expected low <= high"),
    ({"D0_mm": (0.1, 60.0)}, "D0_mm=(0.1, 60) is invalid: expected an inner diameter"),
    ({"eps_per_lock": (0.0, 1.2)}, "eps_per_lock=(0.0, 1.2) is invalid"),
])
def test_a_bad_range_is_refused(changes, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        PRACTICAL_RANGE.replace(**changes)


def test_the_closed_forms_accept_every_muscle_of_the_range():
    """Equation 2 (both diameters) and the thick-wall form on 300 fresh muscles at 0-8 bar:
    every point valid, no negative force, none falling with pressure."""
    from mkm.fem.ladder import make_model
    from mkm.fem.sampling import draw_muscles

    P = np.linspace(*PRACTICAL_RANGE.pressure_bar, 17)
    for muscle in draw_muscles(300, seed=3434).muscles:
        for name, params in (("eq2", {}), ("eq2", {"diameter": "braid"}), ("thickwall", {})):
            pred = make_model(name, muscle=muscle, **params).predict_muscle(muscle, P)
            force = np.ravel(pred.force_N)
            assert np.ravel(pred.valid).all(), (name, muscle)
            assert force.min() >= 0 and np.all(np.diff(force) >= 0), (name, muscle)


def test_the_fe_converges_on_fresh_muscles_of_the_range():
    """The FE (coarse) on three fresh muscles of the range, a 5.6 mm Festo-class tube among
    them: held at eps = 0 the braid cannot move, so the force is Equation 2 on the braid
    diameter exactly; at the drawn eps it converges, rises with pressure, and for the slender
    tube (L0/D0 = 178) meets the thick-wall mid-section form, the FE's long-muscle limit."""
    import dataclasses

    from mkm.fem.eq2 import chou_hannaford
    from mkm.fem.ladder import make_model
    from mkm.fem.sampling import draw_muscles

    P = np.array([0.0, 1.0, 4.0, 8.0])
    muscles = draw_muscles(3, seed=5).muscles
    for muscle in muscles:
        fe = make_model("axisym", mesh="coarse", muscle=muscle)
        rest = fe.predict_muscle(dataclasses.replace(muscle, eps=0.0), P)
        eq2 = chou_hannaford(P, muscle.D0_mm + 2 * muscle.t0_mm, 0.0, muscle.theta0_deg)
        np.testing.assert_allclose(rest.force_N, eq2, rtol=1e-9)
        held = fe.predict_muscle(muscle, P)
        assert np.ravel(held.converged).all()
        assert np.all(np.diff(np.ravel(held.force_N)) > 0)
    slender = muscles[1]
    assert slender.D0_mm < 6 and slender.L0_mm / slender.D0_mm > 170
    fe = make_model("axisym", mesh="coarse", muscle=slender).predict_muscle(slender, P[2:])
    tw = make_model("thickwall", muscle=slender).predict_muscle(slender, P[2:])
    np.testing.assert_allclose(fe.force_N, tw.force_N, rtol=0.01)  # measured 0.3-0.6 %
