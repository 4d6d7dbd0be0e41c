"""The estimators of the surrogate kinds: the threshold-linear regressor, the muscle GP and its
std calibration, the paper's nets, and the kinds' factory."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from sklearn.utils.estimator_checks import parametrize_with_checks

from mkm.surrogate.coverage import coverage_fit
from mkm.surrogate.features import braid_slope_N_per_bar, thickwall_threshold_bar
from mkm.surrogate.gp import posterior_mean_std
from mkm.surrogate.kinds import make_estimator, names
from mkm.surrogate.muscle_gp import MuscleThresholdGP, muscle_slopes
from mkm.surrogate.paper_nets import PAPER_NETS, paper_net
from mkm.surrogate.quiet import quiet_fits
from mkm.surrogate.threshold_linear import ThresholdLinearRegressor
from mkm.surrogate.training_data import load_training_data


@pytest.mark.slow  # scikit-learn's common checks, about 40 per estimator
@parametrize_with_checks([ThresholdLinearRegressor(), ThresholdLinearRegressor(degree=1)])
def test_sklearn_contract(estimator, check):
    check(estimator)


def test_threshold_linear_recovers_slope_and_threshold():
    # Data exactly of the model's form: the fit must find A and P* to solver precision.
    rng = np.random.default_rng(0)
    z = rng.uniform(-1.0, 1.0, 60)
    P = np.tile(np.linspace(0.0, 2.5, 6), 10)
    z = np.repeat(z[:10], 6)
    A = 400.0 * np.exp(0.2 * z)
    threshold = 0.3 + 0.1 * z
    y = A * np.maximum(P - threshold, 0.0)
    model = ThresholdLinearRegressor(degree=1, alpha=0.0).fit(np.column_stack([P, z]), y)
    A_fit, threshold_fit = model.decompose(np.column_stack([P, z]))
    np.testing.assert_allclose(A_fit, A, rtol=1e-6)
    np.testing.assert_allclose(threshold_fit, threshold, atol=1e-6)


@pytest.fixture(scope="module")
def physics_fit(thickwall_dataset):
    data = load_training_data(thickwall_dataset)
    # perturb the targets so the fit is not the prior itself: an end effect growing with eps
    y = data.y * (1.0 - 1.2 * data.X[:, 3])
    return make_estimator("physics", data.inputs, data.fixed).fit(data.X, y)


@settings(max_examples=60, deadline=None)
@given(D0=st.floats(20.0, 60.0), t0=st.floats(1.0, 5.0), eps=st.floats(0.0, 0.25),
       pressures=st.lists(st.floats(0.0, 4.0), min_size=2, max_size=8))
def test_physics_model_non_negative_and_monotone_in_pressure(physics_fit, D0, t0, eps,
                                                              pressures):
    # By construction: A > 0 and P* >= 0, inside the training box and well outside it.
    P = np.sort(np.asarray(pressures))
    X = np.column_stack([P, np.full_like(P, D0), np.full_like(P, t0), np.full_like(P, eps)])
    force = physics_fit.predict(X)
    assert np.all(force >= 0.0)
    assert np.all(np.diff(force) >= -1e-9 * np.max(np.abs(force), initial=1.0))


def test_physics_model_zero_below_threshold(physics_fit):
    # At eps = 0.2 the muscle needs a pressure to shorten that far: no force at P = 0 and 0.1.
    X = np.array([[0.0, 40.0, 3.0, 0.2], [0.1, 40.0, 3.0, 0.2]])
    np.testing.assert_array_equal(physics_fit.predict(X), 0.0)


def test_paper_net_matches_fitrnet_settings():
    net = paper_net(3, 100, "sigmoid")[-1]
    assert net.hidden_layer_sizes == (100, 100, 100)
    assert (net.solver, net.alpha, net.max_iter, net.activation) == ("lbfgs", 0.0, 1000,
                                                                    "logistic")
    assert len(PAPER_NETS) == 27 and PAPER_NETS[8] == (3, 100, "relu")  # Table 2, net #9


def test_every_kind_builds():
    kinds = names()
    assert len(kinds) == 5 + 54 and "mlp-standardised" not in kinds  # dropped: see README
    for name in kinds:
        make_estimator(name)


@pytest.mark.parametrize("kind", ["nope", "net-3x100", "net-3x100-swish", "net-ax1-relu",
                                  "net-3x100-relu-scaled"])
def test_unknown_kind_is_a_clear_error(kind):
    with pytest.raises(ValueError, match="unknown surrogate kind|activation="):
        make_estimator(kind)


def test_paper_net_standardised_tolerance_scales_with_the_response():
    # fitrnet's gradient tolerance 1e-6 is on a loss in N^2; on a standardised force (variance
    # ~1e5 N^2) the same stop is 1e-11, or the fits end after ~160 of 1000 iterations.
    assert paper_net(3, 100, "relu")[-1].tol == 1e-6
    assert paper_net(3, 100, "relu", standardise_response=True).regressor[-1].tol == 1e-11


def test_muscle_slopes_of_exact_lines():
    # Two sweeps of the form A max(0, P - P*): the least-squares lines are exact, no error.
    P = np.tile(np.arange(0.0, 3.01, 0.25), 2)
    groups = np.repeat([0, 1], 13)
    y = np.where(groups == 0, 400.0 * np.maximum(P - 0.3, 0), 250.0 * np.maximum(P - 1.1, 0))
    _, A, Pstar, linearity = muscle_slopes(P, y, groups)
    np.testing.assert_allclose(A, [400.0, 250.0], rtol=1e-12)
    np.testing.assert_allclose(Pstar, [0.3, 1.1], atol=1e-12)
    assert np.all(linearity < 1e-12)


def synthetic_sweeps(n_muscles, seed):
    """Sweeps of the closed form at shortenings stretched as the caps stretch them,
    k = 1 / (1 - 0.4 D_braid / L0): what the muscle GP is built to learn."""
    rng = np.random.default_rng(seed)
    rows = []
    for _ in range(n_muscles):
        D0, t0, eps, L0 = rng.uniform(30, 50), rng.uniform(2, 4), rng.uniform(0, 0.2), \
            rng.uniform(150, 400)
        k = 1.0 / (1.0 - 0.4 * (D0 + 2 * t0) / L0)
        A = braid_slope_N_per_bar(D0, t0, k * eps, 33.0)
        Pstar = thickwall_threshold_bar(D0, t0, k * eps, 33.0, 0.0694, 0.0628)
        for P in np.arange(0.0, 3.01, 0.25):
            rows.append((P, D0, t0, eps, L0, A * max(P - Pstar, 0.0)))
    data = np.array(rows)
    return data[:, :5], data[:, 5]


@pytest.fixture(scope="module")
def muscle_gp():
    X, y = synthetic_sweeps(40, seed=0)
    inputs = ("pressure_bar", "D0_mm", "t0_mm", "eps", "L0_mm")
    fixed = {"theta0_deg": 33.0, "C10_MPa": 0.0694, "C01_MPa": 0.0628}
    with quiet_fits():  # length scales at their bounds: inputs the 1-D law does not use
        return MuscleThresholdGP(inputs, fixed).fit(X, y)


def test_muscle_gp_learns_the_end_effect(muscle_gp):
    # Off the training muscles, the force is that of the stretched closed form to 0.1 % of
    # each sweep's largest force (a smooth 1-D function of D_braid / L0 for the processes).
    X, y = synthetic_sweeps(10, seed=1)
    force, std = muscle_gp.predict(X, return_std=True)
    for rows in np.split(np.arange(len(y)), 10):
        if y[rows].max() > 0:
            assert np.max(np.abs(force[rows] - y[rows])) <= 1e-3 * y[rows].max()
    assert np.all(std >= 0)


@settings(max_examples=40, deadline=None)
@given(D0=st.floats(20.0, 60.0), t0=st.floats(1.0, 5.0), eps=st.floats(0.0, 0.25),
       L0=st.floats(100.0, 500.0), pressures=st.lists(st.floats(0.0, 4.0), min_size=2,
                                                     max_size=8))
def test_muscle_gp_non_negative_and_monotone_in_pressure(muscle_gp, D0, t0, eps, L0,
                                                          pressures):
    # By construction (A >= 0, P* >= 0), inside the training box and well outside it.
    P = np.sort(np.asarray(pressures))
    X = np.column_stack([P, *(np.full_like(P, v) for v in (D0, t0, eps, L0))])
    force = muscle_gp.predict(X)
    assert np.all(force >= 0.0)
    assert np.all(np.diff(force) >= -1e-9 * np.max(np.abs(force), initial=1.0))


def test_muscle_gp_std_is_zero_at_zero_pressure_only(muscle_gp):
    # No pressure, no pull: at 0 bar the force is 0 N for any muscle, known exactly; it had a
    # std (0.13 N for the default surrogate at D0 40, t0 3, eps 0), from the linearity floor
    # of the threshold it sits on
    for eps in (0.0, 0.1):
        P = np.array([0.0, 0.01, 0.5, 1.0])
        X = np.column_stack([P, *(np.full_like(P, v) for v in (40.0, 3.0, eps, 250.0))])
        force, std = muscle_gp.predict(X, return_std=True)
        assert force[0] == 0.0 and std[0] == 0.0
        assert np.all(std[2:] > 0)  # pulling, it keeps its spread


def test_muscle_gp_posterior_is_scikit_learns(muscle_gp):
    # The fast posterior skips scikit-learn's checks: the same numbers to round-off.
    Z = np.random.default_rng(2).normal(size=(7, muscle_gp.slope_gp_.X_train_.shape[1]))
    for gp, post in ((muscle_gp.slope_gp_, muscle_gp.slope_posterior_),
                     (muscle_gp.threshold_gp_, muscle_gp.threshold_posterior_)):
        mean, std = gp.predict(Z, return_std=True)  # of the standardised target
        mean, std = mean * post["y_std"] + post["y_mean"], std * post["y_std"]
        fast_mean, fast_std = posterior_mean_std(post, Z)
        np.testing.assert_allclose(fast_mean, mean, rtol=1e-9, atol=1e-12)
        # the variance is amplitude - |V|^2, a difference (with the inverse factor instead of
        # a triangular solve): its round-off is 2e-5 of the variance (1e-5 of the std) or 1e-12
        # of the amplitude, the larger beside a training point (a variance 1e-9 of the amplitude)
        amplitude = (post["amplitude"] + post["noise"]) * post["y_std"] ** 2
        np.testing.assert_allclose(fast_std**2, std**2, rtol=2e-5, atol=1e-12 * amplitude)


def test_calibrate_std_matches_normal_coverage(muscle_gp):
    # Forces off by independent normal errors of 3x the model's std: after calibrate_std on
    # one such sample, 68 and 95 % of a second one lie within 1 and 2 std (to the sampling
    # error of ~400 points, 5 %).
    from sklearn.base import clone

    from mkm.surrogate.coverage import coverage

    X, _ = synthetic_sweeps(40, seed=3)
    with quiet_fits():
        model = clone(muscle_gp).fit(*synthetic_sweeps(40, seed=0))
    force, std = model.predict(X, return_std=True)
    rng = np.random.default_rng(4)
    active = std > 0
    X, force, std = X[active], force[active], std[active]
    model.calibrate_std(X, force + 3.0 * std * rng.standard_normal(len(std)))
    new_std = model.predict(X, return_std=True)[1]
    error = 3.0 * std * rng.standard_normal(len(std))
    assert coverage(error, new_std, 1.0) == pytest.approx(0.6827, abs=0.05)
    assert coverage(error, new_std, 2.0) == pytest.approx(0.9545, abs=0.05)


@pytest.mark.slow  # GP fits
def test_calibrate_std_on_errors_growing_with_the_end_effect(muscle_gp, monkeypatch):
    # The default surrogate's errors grow with the end-effect correction log k_A (short, wide
    # muscles): here 3 x the model's std x (log k / its median)^1.5, normal. Pooled, they are
    # heavier-tailed than normal: one scale misses the 68 / 95 % on a second sample; the
    # power of log k_A meets both. Measured: 69.1 and 94.7 % (one scale: 72.3 and 92.0 %).
    from sklearn.base import clone

    import mkm.surrogate.coverage as calibration
    from mkm.surrogate.coverage import coverage

    with quiet_fits():
        model = clone(muscle_gp).fit(*synthetic_sweeps(40, seed=0))
    X, _ = synthetic_sweeps(300, seed=5)
    force, std = model.predict(X, return_std=True)
    log_k = -np.log(1.0 - 0.4 * (X[:, 1] + 2.0 * X[:, 2]) / X[:, 4])  # synthetic_sweeps' k
    rng = np.random.default_rng(6)
    first, second = (3.0 * std * (log_k / np.median(log_k)) ** 1.5
                     * rng.standard_normal(len(std)) for _ in range(2))
    model.calibrate_std(X, force + first)
    new_std = model.predict(X, return_std=True)[1]
    assert coverage(second, new_std, 1.0) == pytest.approx(0.6827, abs=0.03)
    assert coverage(second, new_std, 2.0) == pytest.approx(0.9545, abs=0.02)
    monkeypatch.setattr(calibration, "STD_POWERS", np.array([0.0]))  # one scale
    model.calibrate_std(X, force + first)
    one_scale = model.predict(X, return_std=True)[1]
    assert coverage(second, one_scale, 2.0) < 0.93


def test_coverage_fit_recovers_scale_and_power():
    # Normal errors of std 2 (m / m_ref)^1: the fit finds c = 2, beta = 1.
    rng = np.random.default_rng(7)
    m = rng.uniform(0.05, 0.5, 20000)
    ref = np.median(m)
    error = np.abs(2.0 * (m / ref) * rng.standard_normal(m.size))
    c, beta = coverage_fit(error, lambda c, beta: c * (m / ref) ** beta)
    assert c == pytest.approx(2.0, rel=0.05)
    assert beta == pytest.approx(1.0, abs=0.15)


def test_rescale_fit_recovers_factor_and_powers():
    # Normal errors of std 1.7 (v / 0.1)^0.8 (theta0 / 30)^-1 against a std of 1, v the
    # effective shortening, theta0 the braid angle: the fit finds k = 1.7, power 0.8 and angle
    # power -1 (grids 0.5 %, 0.05 and 0.2 apart), and the rescaled std holds 68.3 / 95.4 /
    # 99.7 % of a second sample within 1 / 2 / 3 std, in all of it and in its lowest braid
    # angles (sampling error of 20000 points: 0.3, 0.15, 0.04 points; the test allows 1).
    from mkm.surrogate.coverage import NORMAL_COVERAGE, coverage, rescale_factor, rescale_fit

    rng = np.random.default_rng(8)
    v = rng.uniform(0.01, 0.3, 20000)
    theta = rng.uniform(15.0, 40.0, v.size)
    std = np.ones(v.size)
    first, second = (1.7 * (v / 0.1) ** 0.8 * (theta / 30.0) ** -1.0
                     * rng.standard_normal(v.size) for _ in range(2))
    k, power, angle_power = rescale_fit(first, std, v, theta)
    assert k == pytest.approx(1.7, rel=0.03)
    assert power == pytest.approx(0.8, abs=0.1)
    assert angle_power == pytest.approx(-1.0, abs=0.21)
    rescaled = rescale_factor(v, theta, k, power, angle_power) * std
    low = theta < 20.0
    for n_std, target in NORMAL_COVERAGE:
        assert coverage(second, rescaled, n_std) == pytest.approx(target, abs=0.01)
        assert coverage(second[low], rescaled[low], n_std) == pytest.approx(target, abs=0.02)


def test_rescale_fit_without_the_angle_leaves_low_angles_uncovered(monkeypatch):
    # The same errors fitted with the angle power held at 0 (the pooled fractions alone):
    # the braid angles below 20 deg hold 81 % of their errors within 2 std (a normal error:
    # 95.4 %, which the angle power reaches within 2 points above): why the fit asks for every
    # third of the angles as well.
    from mkm.surrogate import coverage as module

    rng = np.random.default_rng(8)
    v = rng.uniform(0.01, 0.3, 20000)
    theta = rng.uniform(15.0, 40.0, v.size)
    error = 1.7 * (v / 0.1) ** 0.8 * (theta / 30.0) ** -1.0 * rng.standard_normal(v.size)
    std = np.ones(v.size)
    monkeypatch.setattr(module, "RESCALE_ANGLE_POWERS", np.array([0.0]))
    k, power, _ = module.rescale_fit(error, std, v, theta)
    low = theta < 20.0
    within = module.coverage(error[low], module.rescale_factor(v, theta, k, power)[low], 2.0)
    assert within < 0.90


def test_coverage_fit_weighs_misses_by_the_tolerances():
    # Heavy tails nothing explains (Student t, 4 degrees of freedom; the power has no effect,
    # so the fit keeps beta = 0): the fit gives up more of the 1-std fraction than of the 2-std
    # one (tolerances 7 and 4 points), so 2-std comes closer to 95 % than an equal-weight fit
    # brings it (69.9 and 92.2 %). Measured: 71.2 and 92.8 %.
    error = np.abs(np.random.default_rng(7).standard_t(4, 20000))
    c, beta = coverage_fit(error, lambda c, beta: np.broadcast_to(c, (c.shape[0], error.size)))
    assert beta == 0.0
    assert np.mean(error <= c) == pytest.approx(0.712, abs=0.01)
    assert np.mean(error <= 2 * c) == pytest.approx(0.928, abs=0.004)


@pytest.mark.parametrize("kind", ["net-2x10-relu", "net-4x50-tanh"])
def test_a_net_outside_table_2_names_the_values_the_family_takes(kind):
    # was "unknown surrogate kind 'net-2x10-relu': expected ... or
    # net-<layers>x<size>-<relu|tanh|sigmoid>[-standardised]", a pattern it matches
    with pytest.raises(ValueError) as caught:
        make_estimator(kind)
    assert str(caught.value).startswith(
        f"unknown surrogate kind {kind!r} (paper net: layers 1, 2 or 3, size 25, 50 or 100, "
        "activation relu, tanh or sigmoid, standardise_response false or true; e.g. "
        "net-1x25-relu): expected best (muscle-gp), ")
