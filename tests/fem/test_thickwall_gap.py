"""Tests of the thick-wall rung's gap between tube and braid (fem/thickwall.py, ``gap_mm``)."""

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from mkm.fem.eq2 import chou_hannaford, chou_hannaford_eps_max
from mkm.fem.ladder import make_model
from mkm.fem.thickwall import (
    ThickWall,
    gap_closing_pressure,
    klute_hannaford,
    klute_hannaford_threshold_pressure,
    mid_section_kinematics,
    mooney_rivlin_tube_inflation_pressure,
    outer_diameter_mm,
)

GAP_FREE = Path(__file__).parent / "data" / "thickwall_gap_free.csv"
C10, C01 = 0.42, 0.38  # a stiff commercial membrane (about 6x Silastic S, as fitted to Festo's)


def stress_differences(r, k, lz, c10, c01):
    """``sigma_tt - sigma_rr`` and ``2 sigma_zz - sigma_rr - sigma_tt`` [MPa] of the Mooney-Rivlin
    tube at current radius ``r`` (``r^2 = k + R^2 / lz``), from ``sigma = -p I + 2 C10 B - 2 C01
    B^-1`` with the principal stretches written out, independently of the closed forms."""
    R2 = (r * r - k) * lz
    hoop2 = r * r / R2
    radial2 = 1.0 / (hoop2 * lz**2)
    tt_rr = 2 * c10 * (hoop2 - radial2) - 2 * c01 * (1 / hoop2 - 1 / radial2)
    axial = (2 * c10 * (2 * lz**2 - radial2 - hoop2)
             - 2 * c01 * (2 / lz**2 - 1 / radial2 - 1 / hoop2))
    return tt_rr, axial


def free_tube_state(D0, t0, eps, outer_radius):
    lz = 1.0 - eps
    Ri2, Ro2 = (D0 / 2) ** 2, (D0 / 2 + t0) ** 2
    k = outer_radius**2 - Ro2 / lz
    return lz, k, np.sqrt(k + Ri2 / lz)


def test_gap_zero_reproduces_the_gap_free_forces():
    # Frozen outputs of the closed form before it took a gap, at 300 random muscles: a zero gap
    # adds exact zeros to every term, so 1e-12 only leaves room for a different BLAS or libm.
    ref = pd.read_csv(GAP_FREE, comment="#")
    args = [ref[c].to_numpy() for c in ("D0_mm", "t0_mm", "eps", "theta0_deg", "C10_MPa",
                                        "C01_MPa")]
    force = klute_hannaford(ref["pressure_bar"].to_numpy(), *args, gap_mm=0.0)
    threshold = klute_hannaford_threshold_pressure(*args, gap_mm=0.0)
    np.testing.assert_allclose(force, ref["force_N"], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(threshold, ref["threshold_pressure_bar"], rtol=1e-12, atol=1e-15)
    model = ThickWall(theta0_deg=30.0, C10_MPa=C10, C01_MPa=C01)
    gap0 = ThickWall(theta0_deg=30.0, C10_MPa=C10, C01_MPa=C01, gap_mm=0.0)
    P = np.linspace(0, 6, 13)
    assert np.array_equal(model.predict(P, 20, 1.8, 0.1).force_N,
                          gap0.predict(P, 20, 1.8, 0.1).force_N)
    assert "gap_mm" not in gap0.params()  # records of gap-free muscles unchanged


@pytest.mark.parametrize("D0, t0, eps, outer", [(20, 1.8, 0.0, 12.5), (10, 1.8, 0.05, 7.5),
                                                (35, 2.5, 0.15, 26.0), (30, 5, 0.0, 20.5)])
def test_free_inflation_pressure_is_the_integral_of_the_hoop_stress(D0, t0, eps, outer):
    # radial equilibrium through the wall, integrated by adaptive quadrature to ~1e-13
    lz, k, inner = free_tube_state(D0, t0, eps, outer)
    direct = quad(lambda r: stress_differences(r, k, lz, C10, C01)[0] / r, inner, outer,
                  epsabs=0, epsrel=1e-13)[0]
    closed = mooney_rivlin_tube_inflation_pressure(D0, t0, outer, eps, C10, C01)
    assert closed == pytest.approx(10.0 * direct, rel=1e-10)


def test_free_tube_at_fixed_length_is_the_classical_plane_strain_inflation():
    # Ogden's plane-strain neo-Hookean tube: P = C10 [ln(a_i / a_o) + 1/a_o - 1/a_i] with a the
    # squared hoop stretches; zero at rest and rising without a maximum at fixed length.
    Ri, Ro = 10.0, 11.8
    radii = Ro * np.linspace(1.0, 2.5, 61)
    ai = (radii**2 - Ro**2 + Ri**2) / Ri**2
    ao = radii**2 / Ro**2
    classical = 10.0 * C10 * (np.log(ai / ao) + 1 / ao - 1 / ai)
    pressure = mooney_rivlin_tube_inflation_pressure(2 * Ri, Ro - Ri, radii, 0.0, C10, 0.0)
    np.testing.assert_allclose(pressure, classical, rtol=1e-12, atol=1e-15)
    assert pressure[0] == 0.0 and np.all(np.diff(pressure) > 0)


@pytest.mark.parametrize("eps", [0.0, 0.05, 0.15])
@pytest.mark.parametrize("gap", [0.1, 0.5, 1.0, 2.0])
def test_threshold_is_the_closing_pressure_plus_the_free_tube_push(gap, eps):
    # Direct computation: the free tube meets the braid at P_c (its inflation curve at the braid's
    # radius); held at its length it then pushes on its ends with the reduced axial force
    # N = pi * integral (2 s_zz - s_rr - s_tt) r dr (< 0), which the braid's slope A must
    # overcome: P* = P_c - N / A. The closed form gets P* from the energy's derivative instead.
    D0, t0, theta0 = 20.0, 1.8, 28.0
    outer = np.sqrt(mid_section_kinematics(D0, t0, eps, theta0, gap)[5])
    lz, k, inner = free_tube_state(D0, t0, eps, outer)
    closing = gap_closing_pressure(D0, t0, eps, theta0, gap, C10, C01)
    assert closing == pytest.approx(mooney_rivlin_tube_inflation_pressure(D0, t0, outer, eps,
                                                                          C10, C01), rel=1e-14)
    push = np.pi * quad(lambda r: stress_differences(r, k, lz, C10, C01)[1] * r, inner, outer,
                        epsabs=0, epsrel=1e-13)[0]
    assert push < 0
    slope = chou_hannaford(1.0, D0 + 2 * t0 + 2 * gap, eps, theta0)
    assert klute_hannaford(closing, D0, t0, eps, theta0, C10, C01, gap) == pytest.approx(
        push, rel=1e-9)
    threshold = klute_hannaford_threshold_pressure(D0, t0, eps, theta0, C10, C01, gap)
    assert threshold == pytest.approx(closing - push / slope, rel=1e-10)


def test_threshold_at_rest_length_grows_with_the_gap_from_zero():
    gaps = np.array([0.0, 0.05, 0.2, 0.5, 1.0, 2.0])
    threshold = klute_hannaford_threshold_pressure(20.0, 1.8, 0.0, 28.0, C10, C01, gaps)
    closing = gap_closing_pressure(20.0, 1.8, 0.0, 28.0, gaps, C10, C01)
    assert threshold[0] == 0.0 and np.all(np.diff(threshold) > 0)
    assert np.all(threshold >= closing)
    # the push is small against the braid's slope: the threshold follows the inflation curve
    np.testing.assert_allclose(threshold[1:], closing[1:], rtol=0.05)


@settings(max_examples=60, deadline=None)
@given(D0=st.floats(5, 80), t_frac=st.floats(0.01, 0.45), eps_frac=st.floats(0, 0.95),
       theta0=st.floats(15, 45), gap_frac=st.floats(0, 0.2), scale=st.floats(0.5, 20))
def test_no_force_falls_with_pressure_and_none_starts_before_the_tube_meets_the_braid(
        D0, t_frac, eps_frac, theta0, gap_frac, scale):
    eps = eps_frac * chou_hannaford_eps_max(theta0)
    t0, gap = t_frac * D0, gap_frac * D0 / 2
    model = ThickWall(theta0_deg=theta0, C10_MPa=0.0694 * scale, C01_MPa=0.0628 * scale,
                      gap_mm=gap)
    pressures = np.linspace(0, 10, 41)
    prediction = model.predict(pressures, D0, t0, eps)
    assert prediction.valid.all() and prediction.force_N[0] == 0
    assert np.all(prediction.force_N >= 0) and np.all(np.diff(prediction.force_N) >= 0)
    closing = gap_closing_pressure(D0, t0, eps, theta0, gap, model.material.C10_MPa,
                                   model.material.C01_MPa)
    # the free tube held at its length pushes (or at a zero gap, eps 0, does nothing)
    assert prediction.extras["threshold_pressure_bar"][0] >= closing - 1e-9 * max(closing, 1.0)


def test_registry_passes_the_gap_and_refuses_a_bad_one():
    model = make_model("thickwall", theta0_deg=28.0, gap_mm="0.5")
    assert model.params()["gap_mm"] == 0.5
    assert model.predict(0.05, 20, 1.8, 0.0).force_N == 0.0  # below its threshold at rest
    with pytest.raises(ValueError, match=r"^gap_mm=-1 is invalid: expected a radial gap between "
                                         r"tube and braid in \[0, 100\] mm"):
        make_model("thickwall", gap_mm=-1)


def test_outer_diameter_with_a_gap_is_the_wider_braids():
    # below the threshold at rest length the muscle does not shorten: the braid keeps its rest
    # diameter D0 + 2 t0 + 2 g (the tube inside it); above, it shortens and the braid of
    # constant thread length widens from there
    D0, t0, theta0, gap = 20.0, 1.8, 28.0, 0.5
    threshold = float(klute_hannaford_threshold_pressure(D0, t0, 0.0, theta0, gap_mm=gap))
    assert outer_diameter_mm(D0, t0, theta0, 0.5 * threshold, gap_mm=gap) == pytest.approx(
        D0 + 2 * t0 + 2 * gap, rel=1e-9)
    assert outer_diameter_mm(D0, t0, theta0, 2.0, gap_mm=gap) > D0 + 2 * t0 + 2 * gap + 1.0


def test_a_muscle_carries_its_gap_to_the_models_of_a_gap_only():
    from mkm.fem.muscle import Muscle

    muscle = Muscle(D0_mm=20.0, t0_mm=1.8, eps=0.0, theta0_deg=28.0, C10_MPa=C10, C01_MPa=C01,
                    gap_mm=0.5, id="gapped")
    assert muscle.record()["gap_mm"] == 0.5
    assert Muscle.from_dict(muscle.record()) == muscle  # what run.json and design record
    assert "gap_mm" not in Muscle(D0_mm=20.0, t0_mm=1.8, id="m").record()  # not known
    model = make_model("thickwall", muscle=muscle)
    pressures = np.linspace(0.0, 2.0, 9)
    np.testing.assert_array_equal(
        model.predict_muscle(muscle, pressures).force_N,
        klute_hannaford(pressures, 20.0, 1.8, 0.0, 28.0, C10, C01, 0.5).clip(min=0.0))
    # the threshold at rest length is the gapped muscle's, not 0
    threshold = float(model.predict_muscle(muscle, 0.5).extras["threshold_pressure_bar"])
    assert threshold > 0.1
    assert threshold == pytest.approx(
        klute_hannaford_threshold_pressure(20.0, 1.8, 0.0, 28.0, C10, C01, 0.5), rel=1e-12)
    assert "gap_mm" not in make_model("eq2", muscle=muscle).params()  # Equation 2 has none
    with pytest.raises(ValueError, match=r"^muscle.gap_mm=-0.1 is invalid: expected a radial "
                                         r"gap between tube and braid"):
        Muscle.from_dict({**muscle.record(), "gap_mm": -0.1})
