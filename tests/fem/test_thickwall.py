"""Tests of the thick-wall rung (fem/thickwall.py): the Klute-Hannaford virtual-work model."""

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from mkm.fem.calibration import calibrated, read_reference
from mkm.fem.eq2 import LOCKING_ANGLE_DEG, chou_hannaford, chou_hannaford_eps_max
from mkm.fem.ladder import make_model
from mkm.fem.materials import SILASTIC_S
from mkm.fem.paper import CASE_I_CSV
from mkm.fem.thickwall import (
    ThickWall,
    braided_tube_elastic_force,
    braided_tube_energy,
    effective_eps_of_slope,
    effective_eps_of_threshold,
    klute_hannaford,
    klute_hannaford_threshold_pressure,
)

C10, C01 = SILASTIC_S.C10_MPa, SILASTIC_S.C01_MPa
THETA0 = 30.0  # a fixed angle keeps these tests independent of the calibration file
# the paper's dataset grid (Table 1 of Antonelli et al. 2025)
PAPER_P = np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5])
PAPER_D0 = np.array([30.0, 40.0, 50.0])
PAPER_T0 = np.array([2.0, 3.0, 4.0])

CASE_I = CASE_I_CSV


def energy_by_quadrature(D0, t0, eps, theta0, material=SILASTIC_S):
    """The wall energy per unit rest length integrated numerically from the material's own W."""
    lz = 1.0 - eps
    c2 = np.cos(np.deg2rad(theta0)) ** 2
    Ri, Ro = D0 / 2, D0 / 2 + t0
    ro2 = Ro**2 * (1 - lz**2 * c2) / (1 - c2)

    def integrand(R):
        hoop = np.sqrt(ro2 - (Ro**2 - R**2) / lz) / R
        return material.energy(lz, hoop) * 2 * np.pi * R

    return quad(integrand, Ri, Ro, epsabs=0, epsrel=1e-13)[0]


@pytest.mark.parametrize("D0, t0, eps, theta0", [
    (35, 2.5, 0.05, 30), (30, 4, 0.2, 25), (50, 2, 0.3, 20), (10, 4.5, 0.1, 35),
])
def test_braided_tube_energy_matches_quadrature(D0, t0, eps, theta0):
    # The integrand is smooth on the wall, so adaptive quadrature is good to ~1e-13: 1e-10
    # leaves room for the round-off of the logarithms in the closed form.
    closed = braided_tube_energy(D0, t0, eps, theta0, C10, C01)
    assert closed == pytest.approx(energy_by_quadrature(D0, t0, eps, theta0), rel=1e-10)


@pytest.mark.parametrize("eps", [0.01, 0.1, 0.25])
@pytest.mark.parametrize("t0", [0.5, 2.5, 8.0])
def test_elastic_force_is_the_derivative_of_the_energy(eps, t0):
    # Central difference with h = 1e-5: truncation ~h^2 E''' ~ 1e-9 relative, round-off
    # ~1e-16 E / h ~ 1e-10 relative; 1e-6 is a safe bound for both.
    h = 1e-5
    fd = (braided_tube_energy(35, t0, eps - h, THETA0, C10, C01)
          - braided_tube_energy(35, t0, eps + h, THETA0, C10, C01)) / (2 * h)  # d/dlz = -d/deps
    assert braided_tube_elastic_force(35, t0, eps, THETA0, C10, C01) == pytest.approx(fd, rel=1e-6)


@pytest.mark.parametrize("eps", [0.0, 0.05, 0.2])
def test_force_is_the_length_derivative_of_the_potential_with_the_cavity_volume(eps):
    # Virtual work from scratch: Pi(L) = L0 E(lz) - P V(L), V the cavity volume pi r_i^2 L from
    # the kinematics of the modelling notes, and F = dPi/dL by central differences. This checks
    # the sign convention and that the pressure term is Eq. 2 on the braid diameter.
    # h = 1e-4 mm: truncation ~1e-8 N, round-off ~1e-16 * 1e5 N mm / 1e-4 mm ~ 1e-7 N.
    D0, t0, L0, P_bar = 40.0, 3.0, 282.0, 1.5
    c2 = np.cos(np.deg2rad(THETA0)) ** 2
    Ri, Ro = D0 / 2, D0 / 2 + t0

    def potential(L):
        lz = L / L0
        ri2 = Ro**2 * (1 - lz**2 * c2) / (1 - c2) - (Ro**2 - Ri**2) / lz
        energy = L0 * braided_tube_energy(D0, t0, 1 - lz, THETA0, C10, C01)
        return energy - 0.1 * P_bar * np.pi * ri2 * L

    L, h = (1 - eps) * L0, 1e-4
    fd = (potential(L + h) - potential(L - h)) / (2 * h)
    assert klute_hannaford(P_bar, D0, t0, eps, THETA0) == pytest.approx(fd, abs=1e-5)


def test_rest_state_stores_no_energy_and_exerts_no_force():
    # The reference configuration is stress free: W and dW/dlz vanish (to round-off) at eps = 0.
    assert abs(braided_tube_energy(35, 2.5, 0.0, THETA0, C10, C01)) < 1e-12
    assert abs(braided_tube_elastic_force(35, 2.5, 0.0, THETA0, C10, C01)) < 1e-12
    assert klute_hannaford_threshold_pressure(35, 2.5, 0.0, THETA0) == 0.0


def test_massless_wall_gives_equation_2_with_the_braid_diameter():
    # C10 = C01 = 0: only the pressure term is left, which is Equation 2 on D0 + 2 t0 exactly.
    P, eps = np.linspace(0, 2.5, 11), np.array([[0.0], [0.1], [0.3]])
    got = klute_hannaford(P, 35, 2.5, eps, THETA0, 0.0, 0.0)
    np.testing.assert_allclose(got, chou_hannaford(P, 40.0, eps, THETA0), rtol=1e-14, atol=0)


def test_thin_wall_limit_is_equation_2_at_first_order_in_t0():
    # Both the wall energy (its area) and the braid diameter grow linearly with t0, so the
    # relative distance to Equation 2 on D0 must fall tenfold per decade of t0 (slope 1 +- 2 %).
    t0 = np.array([1e-2, 1e-3, 1e-4])
    eq2 = chou_hannaford(2.0, 35.0, 0.1, THETA0)
    rel = np.abs(klute_hannaford(2.0, 35.0, t0, 0.1, THETA0) / eq2 - 1)
    slopes = np.diff(np.log10(rel)) / np.diff(np.log10(t0))
    np.testing.assert_allclose(slopes, 1.0, atol=0.02)
    assert rel[-1] < 1e-4


def test_force_is_linear_in_pressure_above_the_threshold():
    # Affine in P with the slope of the pressure term: second differences vanish to round-off
    # (1e-12 of the largest force) and the slope is Equation 2 per bar on the braid diameter.
    model = ThickWall(theta0_deg=THETA0)
    P = np.linspace(1.0, 2.5, 7)
    force = model.predict(P, 40, 3, 0.15).force_N
    assert np.all(force > 0)
    np.testing.assert_allclose(np.diff(force, 2), 0, atol=1e-12 * force.max())
    slope = np.diff(force) / np.diff(P)
    np.testing.assert_allclose(slope, chou_hannaford(1.0, 46.0, 0.15, THETA0), rtol=1e-12)


def test_force_is_zero_until_the_muscle_has_shortened_by_eps():
    model = ThickWall(theta0_deg=THETA0)
    pred = model.predict(np.linspace(0, 2.5, 51), 40, 3, 0.15)
    p_star = pred.extras["threshold_pressure_bar"][0]
    assert 0.2 < p_star < 2.5  # inside the swept range, so both regimes are exercised
    below = pred.pressure_bar <= p_star
    assert below.any() and (~below).any()
    assert np.all(pred.force_N[below] == 0.0) and pred.valid.all()
    assert np.all(pred.force_N[~below] > 0)
    # at P* the unlocked virtual-work force is zero: the free muscle just reaches eps
    assert abs(klute_hannaford(p_star, 40, 3, 0.15, THETA0)) < 1e-9


def test_threshold_pressure_grows_with_eps_and_t0():
    eps = np.linspace(0.0, 0.3, 13)
    by_eps = klute_hannaford_threshold_pressure(40, 3, eps, THETA0)
    assert by_eps[0] == 0 and np.all(np.diff(by_eps) > 0)
    by_t0 = klute_hannaford_threshold_pressure(40, np.linspace(0.5, 8, 16), 0.1, THETA0)
    assert np.all(np.diff(by_t0) > 0)


def test_force_grows_with_D0_on_the_paper_grid():
    # Where the muscle pulls (force > 0) a larger tube pulls harder; where it is still locked
    # the force stays zero.
    P, t0, eps = np.meshgrid(PAPER_P, PAPER_T0, [0.0, 0.1, 0.2], indexing="ij")
    force = np.stack([ThickWall(theta0_deg=THETA0).predict(P, D0, t0, eps).force_N
                      for D0 in PAPER_D0])
    assert np.all(np.diff(force, axis=0) >= 0)
    assert np.all(np.diff(force, axis=0)[:, force[0] > 0] > 0)


def test_force_falls_with_t0_once_shortened_and_rises_at_eps_0():
    # The paper's trend "falls with t0" is the wall's energy winning over the larger braid
    # diameter D0 + 2 t0: with the calibrated angle it does on the whole paper grid at eps = 0.2.
    # At eps = 0 the wall is undeformed and passes the pressure on to the braid: the force is
    # Equation 2 on D0 + 2 t0 and rises with t0 (the model departs from the paper's trend there).
    model = make_model("thickwall")
    theta0 = model.params()["theta0_deg"]
    for D0 in PAPER_D0:
        shortened = model.predict(PAPER_P[:, None], D0, PAPER_T0, 0.2).force_N
        assert np.all(np.diff(shortened, axis=1) <= 0)
        assert np.all(np.diff(shortened[-1]) < 0)
        rest = model.predict(PAPER_P[1:, None], D0, PAPER_T0, 0.0).force_N
        np.testing.assert_allclose(rest, chou_hannaford(PAPER_P[1:, None], D0 + 2 * PAPER_T0,
                                                        0.0, theta0), rtol=1e-12)
        assert np.all(np.diff(rest, axis=1) > 0)


def test_braid_lock_flags_nan_and_invalid():
    eps_max = chou_hannaford_eps_max(THETA0)  # 1/3 at 30 deg
    eps = [eps_max - 1e-3, eps_max, eps_max + 0.05, 0.9]
    p_near = klute_hannaford_threshold_pressure(35, 2.5, eps[0], THETA0)
    assert p_near > 100  # close to the lock the threshold diverges (the pressure term -> 0)
    pred = ThickWall(theta0_deg=THETA0).predict(2 * p_near, 35, 2.5, eps)
    assert pred.valid.tolist() == [True, False, False, False]
    assert pred.force_N[0] > 0 and np.isnan(pred.force_N[1:]).all()
    assert np.isnan(pred.extras["threshold_pressure_bar"][1:]).all()
    assert pred.converged.all()  # closed form: nothing to converge, the physics ends there



def test_held_past_where_its_caps_lock_the_braid_a_thick_wall_pulls_nothing():
    """D0 10 mm, t0 3 mm, L0 100 mm at 33.425 deg: the FE's caps lock its braid by eps 0.2909,
    short of Equation 2's eps_max 0.3082, and at eps 0.295 it finds no held state. The free
    muscle stops short of the stop at every pressure there, so the force on the stop is 0 N:
    the mid-section's answer at every pressure of the practical range, its own P* (22 bar, not
    the muscle's) above it."""
    from mkm.fem.fe.model import isometric_sweep
    from mkm.fem.outcomes import BRAID_LOCKS

    theta0, eps = 33.425, 0.295
    fe = isometric_sweep([4.0], 10.0, 3.0, eps, theta0, 100.0, mesh="coarse")
    assert fe["limit"].tolist() == [BRAID_LOCKS]
    assert "reaches the locking angle 54.74 deg by eps=0.2909" in fe["failure"][0]
    P = np.arange(0.0, 8.5, 0.5)  # the practical range
    pred = ThickWall(theta0_deg=theta0, L0_mm=100.0).predict(P, 10.0, 3.0, eps)
    assert pred.valid.all() and (pred.force_N == 0.0).all()
    assert pred.extras["threshold_pressure_bar"][0] == pytest.approx(22.1, abs=0.05)
    # the free muscle at 8 bar stops short of the FE's lock, as the mid-section's does
    assert effective_eps_of_threshold([8.0], [10.0], [3.0], [theta0], [C10], [C01])[0] < 0.2909


def test_inner_radius_never_collapses_before_the_braid_lock():
    # The wall fills the braid (r_i^2 <= 0) only beyond eps_max, for any angle and any wall up
    # to t0 -> D0/2; so the braid lock is the first and only failure of this rung.
    for theta0 in (10.0, 20.0, 30.0, 40.0, 50.0, 54.0):
        eps = np.linspace(0, chou_hannaford_eps_max(theta0), 200, endpoint=False)
        assert np.isfinite(braided_tube_energy(10.0, 4.999, eps, theta0, C10, C01)).all()
    # beyond the lock it does collapse for a thick wall, and the energy says so with NaN
    assert np.isnan(braided_tube_energy(10.0, 4.0, 0.9, 30.0, C10, C01))
    assert np.isnan(braided_tube_elastic_force(10.0, 4.0, 0.9, 30.0, C10, C01))


@settings(max_examples=60, deadline=None)
@given(D0=st.floats(5, 80), t_frac=st.floats(0.01, 0.49), eps_frac=st.floats(0, 0.999),
       theta0=st.floats(12, 50))
def test_force_is_nonnegative_and_nondecreasing_in_pressure(D0, t_frac, eps_frac, theta0):
    eps = eps_frac * chou_hannaford_eps_max(theta0)
    pred = ThickWall(theta0_deg=theta0).predict(np.linspace(0, 5, 21), D0, t_frac * D0, eps)
    assert pred.valid.all() and pred.force_N[0] == 0
    assert np.all(pred.force_N >= 0) and np.all(np.diff(pred.force_N) >= 0)


@pytest.mark.parametrize("theta0", [LOCKING_ANGLE_DEG, 60.0, 0.0, -5.0])
def test_theta0_outside_the_braid_range_is_refused(theta0):
    with pytest.raises(ValueError, match=r"^theta0_deg=.* is invalid: expected 0 < theta0 < 54\.7"):
        ThickWall(theta0_deg=theta0).predict(1.0, 35, 2.5, 0.05)


def test_softer_material_pulls_harder():
    stiff = ThickWall(theta0_deg=THETA0).predict(2.0, 35, 2.5, 0.2).force_N
    soft = ThickWall(theta0_deg=THETA0, C10_MPa=C10 / 2, C01_MPa=C01 / 2)
    assert soft.predict(2.0, 35, 2.5, 0.2).force_N > stiff


def test_registered_model_reads_its_calibrated_theta0_and_records_its_params():
    model = make_model("thickwall")
    assert isinstance(model, ThickWall) and model.theta0_deg is None
    params = model.params()
    assert params["theta0_deg"] == calibrated("thickwall")["theta0_deg"]
    assert params == {"theta0_deg": params["theta0_deg"], "L0_mm": 282.0,
                      "C10_MPa": 0.0694, "C01_MPa": 0.0628}
    json.dumps(params)  # goes into every CSV header


def test_calibration_record_matches_the_model_on_muscle_I():
    # The shipped thickwall angle is fitted on the slope (issue 11): above its threshold the
    # model is exactly affine, F = s (P - P*), with the paper's slope s, so against the paper's
    # origin-crossing line it is short by the same s P* at every pressure above 0 bar. The
    # stored RMSE (rounded to 1e-4 N) must be what the model gives at the stored angle, which
    # catches a model changed without recalibrating.
    entry = calibrated("thickwall")
    assert entry["target"] == "slope"
    ref = read_reference(CASE_I)
    pred = ThickWall(theta0_deg=entry["theta0_deg"]).predict(
        ref.pressure_bar, ref.D0_mm, ref.t0_mm, ref.eps)
    residual = pred.force_N - ref.force_N.to_numpy()
    assert np.sqrt(np.mean(residual**2)) == pytest.approx(entry["rmse_N"], abs=1e-3)
    threshold = pred.extras["threshold_pressure_bar"][0]
    assert 0.1 < threshold < 0.25
    # the slopes agree to 1e-5 (theta0 rounded to 1e-3 deg): 2.5 bar x 1e-5 x 367 N/bar = 0.01 N
    np.testing.assert_allclose(residual[1:], -entry["slope_N_per_bar"]["reference"] * threshold,
                               atol=0.02)


def test_prediction_frame_carries_the_threshold_and_broadcasts():
    pred = ThickWall(theta0_deg=THETA0).predict([[0.5], [1.0], [2.0]], [30, 40], 3.0, 0.1)
    assert pred.force_N.shape == (3, 2)
    frame = pred.to_frame()
    assert len(frame) == 6 and "threshold_pressure_bar" in frame
    single = ThickWall(theta0_deg=THETA0).predict(1.0, 40, 3.0, 0.1)
    assert pred.force_N[1, 1] == single.force_N


@settings(max_examples=50, deadline=None)
@given(D0=st.floats(20.0, 60.0), t0=st.floats(1.0, 5.0), theta0=st.floats(20.0, 40.0),
       fraction=st.floats(0.02, 0.95))
def test_effective_eps_inverts_the_forward_closed_form(D0, t0, theta0, fraction):
    # The slope and threshold of the forward model at a shortening e (a fraction of the braid
    # lock) come back to e: the slope's closed-form inverse to round-off, the threshold's root
    # search to its xtol of 1e-12 (relative 1e-8 leaves room for a flat threshold near e = 0).
    e = fraction * chou_hannaford_eps_max(theta0)
    slope = chou_hannaford(1.0, D0 + 2.0 * t0, e, theta0)
    threshold = klute_hannaford_threshold_pressure(D0, t0, e, theta0, C10, C01)
    assert effective_eps_of_slope(slope, D0, t0, theta0) == pytest.approx(e, rel=1e-9)
    got = effective_eps_of_threshold(np.array([threshold]), [D0], [t0], [theta0], [C10], [C01])
    assert got[0] == pytest.approx(e, rel=1e-8)


def test_effective_eps_is_nan_where_no_shortening_gives_the_value():
    # a slope far below what any stretch gives, a zero threshold, one beyond the braid
    # lock's reach; the rest slope is e = 0 exactly
    rest = chou_hannaford(1.0, 46.0, 0.0, THETA0)
    assert np.isnan(effective_eps_of_slope(-10.0 * rest, 40.0, 3.0, THETA0))
    assert effective_eps_of_slope(rest, 40.0, 3.0, THETA0) == 0.0
    got = effective_eps_of_threshold(np.array([0.0, 1e6]), [40.0] * 2, [3.0] * 2, [THETA0] * 2,
                                     [C10] * 2, [C01] * 2)
    assert np.isnan(got).all()
