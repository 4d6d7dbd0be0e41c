"""The contract every registered surrogate kind keeps, and the registry that lists the kinds.

Each kind is fitted on the thick-wall fixture (the paper's 27 muscles, an exact closed form), must
reproduce its training forces, and must come back from its model file with identical predictions
(through the trusted types its entry declares). A toy kind, registered for this module only, goes
through the same suite and shows up wherever the kinds are listed."""

import os
import subprocess
import sys

import numpy as np
import pytest
from sklearn.base import clone

from mkm.surrogate import kinds
from mkm.surrogate.io import load_model, save_model
from mkm.surrogate.train import train_surrogate
from mkm.surrogate.training_data import load_training_data


def toy_estimator():
    """Distance-weighted nearest neighbours on scaled inputs: exact at its training points
    (brute force: a fitted tree would hold types outside those skops trusts by default)."""
    from sklearn.neighbors import KNeighborsRegressor
    from sklearn.pipeline import make_pipeline
    from sklearn.preprocessing import StandardScaler

    return make_pipeline(StandardScaler(), KNeighborsRegressor(n_neighbors=2, weights="distance",
                                                             algorithm="brute"))


TOY = kinds.Kind("toy-knn", toy_estimator, "toy k-NN", "nearest neighbours (a test's kind)")

# Registered while collecting to parametrise the suite from the registry, then only while this
# module's tests run (the `toy_kind` fixture): other modules see the shipped kinds alone.
kinds.register(TOY)
SINGLE_KINDS = kinds.names(include_families=False)
kinds.unregister(TOY.name)
SLOW_TO_TRAIN = {"gp": "a GP on 162 rows, 2 s", "mlp-paper": "3 x 100 net, 5 s"}
CONTRACT_KINDS = [pytest.param(k, marks=pytest.mark.slow) if k in SLOW_TO_TRAIN else k
                  for k in (*SINGLE_KINDS, "net-1x25-tanh-standardised")]
# In-sample RMS error allowed on the fixture, as a fraction of its largest force: every kind
# learns the smooth closed form; the smallest net (1 x 25) is the loosest, at 0.2 % measured.
IN_SAMPLE_RMS = 0.02


@pytest.fixture(scope="module", autouse=True)
def toy_kind():
    kinds.register(TOY)
    yield TOY
    kinds.unregister(TOY.name)


def test_toy_kind_is_in_the_contract_suite():
    assert TOY.name in SINGLE_KINDS


@pytest.mark.parametrize("kind", CONTRACT_KINDS)
def test_kind_contract(kind, thickwall_dataset, tmp_path):
    data = load_training_data(thickwall_dataset)
    estimator = kinds.make_estimator(kind, data.inputs, data.fixed)
    assert clone(estimator).get_params().keys() == estimator.get_params().keys()  # sklearn API
    model = train_surrogate(kind, thickwall_dataset, splits=0)
    force = model.estimator.predict(data.X)
    assert np.all(np.isfinite(force))
    rms = np.sqrt(np.mean((force - data.y) ** 2))
    assert rms <= IN_SAMPLE_RMS * data.y.max(), f"{kind}: in-sample RMS {rms:.3g} N"
    loaded = load_model(save_model(model, tmp_path / kind))
    assert loaded.kind == kinds.entry(kind).name or loaded.kind == kind
    P = np.linspace(0.0, 2.5, 11)
    before, after = model.predict(P, 41.0, 2.7, 0.13), loaded.predict(P, 41.0, 2.7, 0.13)
    np.testing.assert_array_equal(after.force_N, before.force_N)
    assert after.extras.keys() == before.extras.keys()
    for name, values in before.extras.items():
        np.testing.assert_array_equal(after.extras[name], values)


def test_unknown_parameter_of_a_kind_is_one_line():
    with pytest.raises(ValueError, match="surrogate kind 'physics' takes no parameter depth: "
                                         "expected some of degree, alpha"):
        kinds.make_estimator("physics", depth=3)
    assert kinds.make_estimator("physics", degree=3)[-1].degree == 3


def test_a_kind_name_is_registered_once():
    with pytest.raises(ValueError, match="'physics' is already registered"):
        kinds.register(kinds.Kind("physics", toy_estimator, "again", "a duplicate"))


def test_study_default_and_trusted_types_come_from_the_entries():
    assert kinds.study_default() == ("muscle-gp", "physics", "mlp-paper")
    assert "mkm.surrogate.muscle_gp.MuscleThresholdGP" in kinds.trusted_types("best")
    assert kinds.trusted_types("net-2x50-relu") == ()  # scikit-learn's own types only
    assert "mkm.surrogate.paper_nets" in kinds.model_modules("net-2x50-relu")


@pytest.mark.slow  # a fresh process
def test_registered_kind_is_listed_by_the_cli_and_mkm_models():
    # A kind registered before the command line is built appears in `mkm surrogate train
    # --help` and in `mkm models` (a fresh process: the registry's texts are read at import).
    script = (
        "import sys\n"
        "from mkm.surrogate import kinds\n"
        "kinds.register(kinds.Kind('toy-knn', 'sklearn.neighbors:KNeighborsRegressor', "
        "'toy', 'a test kind'))\n"
        "from mkm.cli import main\n"
        "main(['models'])\n"
        "print('---')\n"
        "try:\n"
        "    main(['surrogate', 'train', '--help'])\n"
        "except SystemExit:\n"
        "    pass\n")
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         timeout=120, env={**os.environ, "COLUMNS": "200"})
    models, _, train_help = run.stdout.partition("---")
    assert run.returncode == 0, run.stderr
    (kind_line,) = [line for line in models.splitlines() if line.strip().startswith("kind:")]
    assert "mlp-paper" in kind_line and "toy-knn" in kind_line
    assert "toy-knn" in train_help.split("--kind", 1)[1]
