import warnings

import numpy as np
import pytest

from surrogate.model import OutOfDomainWarning
from surrogate.train import train_surrogate


@pytest.fixture(scope="module")
def physics(thickwall_dataset):
    return train_surrogate("physics", thickwall_dataset, seeds=(0,))


@pytest.fixture(scope="module")
def gp(thickwall_dataset):
    return train_surrogate("gp", thickwall_dataset, seeds=())


def test_domain_is_the_training_box(physics):
    assert physics.domain.as_dict() == {"pressure_bar": [0.0, 2.5], "D0_mm": [30.0, 50.0],
                                        "t0_mm": [2.0, 4.0], "eps": [0.0, 0.2]}


def test_inside_the_domain_no_warning(physics):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        prediction = physics.predict([0.0, 1.0, 2.5], 35.0, 2.5, 0.05)
    assert prediction.valid.all() and prediction.extras["in_domain"].all()


@pytest.mark.parametrize("point", [(2.6, 40, 3, 0.1), (1.0, 29.0, 3, 0.1), (1.0, 40, 4.5, 0.1),
                                   (1.0, 40, 3, 0.25)])
def test_outside_the_domain_flagged_and_warned(physics, point):
    with pytest.warns(OutOfDomainWarning, match="1 of 2 points lie outside"):
        prediction = physics.predict([1.0, point[0]], [40, point[1]], [3, point[2]],
                                     [0.1, point[3]])
    np.testing.assert_array_equal(prediction.valid, [True, False])
    np.testing.assert_array_equal(prediction.extras["in_domain"], [True, False])
    assert np.isfinite(prediction.force_N).all()  # the number is kept, the flag says it is not


def test_gp_gives_a_predictive_spread(gp):
    prediction = gp.predict([0.5, 1.0, 2.0], 40.0, 3.0, 0.1)
    std = prediction.extras["force_std_N"]
    assert std.shape == (3,) and np.all(std > 0)
    # On exact training-grid data the spread is small against the forces (hundreds of N).
    assert np.all(std < 0.01 * prediction.force_N.max())


def test_prediction_is_exact_on_thickwall_data(physics):
    # The dataset is the thick-wall model itself, which the physics surrogate holds exactly
    # (its priors): the off-grid muscle I must come out to round-off.
    from fem.ladder import make_model

    P = np.linspace(0.0, 2.5, 11)
    expected = make_model("thickwall").predict(P, 35.0, 2.5, 0.05).force_N
    np.testing.assert_allclose(physics.predict(P, 35.0, 2.5, 0.05).force_N, expected,
                               atol=1e-6 * expected.max())


def test_fast_path_equals_the_estimator(physics):
    # The surrogate skips scikit-learn's per-call checks for speed: same numbers, bit for bit.
    X = np.array([[0.0, 30.0, 2.0, 0.0], [1.3, 41.0, 2.7, 0.13], [2.5, 50.0, 4.0, 0.2]])
    assert physics._fast_predict is not None
    np.testing.assert_array_equal(physics.predict(*X.T).force_N, physics.estimator.predict(X))
