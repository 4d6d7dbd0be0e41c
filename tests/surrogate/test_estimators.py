import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from sklearn.utils.estimator_checks import parametrize_with_checks

from surrogate.estimators import (
    PAPER_NETS,
    ThresholdLinearRegressor,
    kind_names,
    make_estimator,
    paper_net,
)
from surrogate.training_data import load_training_data


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
    return make_estimator("physics").fit(data.X, y)


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
    names = kind_names()
    assert len(names) == 4 + 54
    for name in names:
        make_estimator(name)


@pytest.mark.parametrize("kind", ["nope", "net-3x100", "net-3x100-swish", "net-ax1-relu",
                                  "net-3x100-relu-scaled"])
def test_unknown_kind_is_a_clear_error(kind):
    with pytest.raises(ValueError, match="unknown surrogate kind|activation="):
        make_estimator(kind)
