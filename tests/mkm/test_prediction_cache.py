"""The FE prediction cache (mkm/prediction_cache.py): a hit returns what the model computed, any
change of model, parameters, code or inputs misses, and entries load without pickle."""

import numpy as np
import pytest

from mkm import prediction_cache
from mkm.prediction_cache import cache_key, cached_predict
from mkm.registry import parse_spec

P = np.array([0.0, 1.0, 2.5])


@pytest.fixture
def axisym():
    return parse_spec("axisym:mesh=coarse").build()


def test_a_hit_returns_the_computed_prediction(tmp_path, axisym):
    first, hit1 = cached_predict(axisym, P, 35.0, 2.5, 0.05, cache_dir=tmp_path)
    again, hit2 = cached_predict(axisym, P, 35.0, 2.5, 0.05, cache_dir=tmp_path)
    assert (hit1, hit2) == (False, True)
    np.testing.assert_array_equal(again.force_N, first.force_N)
    np.testing.assert_array_equal(again.valid, first.valid)
    assert again.seconds == first.seconds  # the time of the original solve, not of the read
    assert again.params == first.params
    np.testing.assert_array_equal(again.extras["threshold_pressure_bar"],
                                  first.extras["threshold_pressure_bar"])
    # the entry is a plain .npz: it loads with pickle forbidden
    (entry,) = tmp_path.glob("*.npz")
    with np.load(entry, allow_pickle=False) as data:
        assert "force_N" in data.files


def test_text_extras_survive(tmp_path):
    # a solve that fails carries its reason as text; it must come back as text, not as a pickle
    model = parse_spec("axisym:mesh=coarse").build()
    first, _ = cached_predict(model, [1.0], 30.0, 2.0, 0.31, cache_dir=tmp_path)
    again, hit = cached_predict(model, [1.0], 30.0, 2.0, 0.31, cache_dir=tmp_path)
    assert hit and not again.converged.any()
    assert str(np.ravel(again.extras["failure"])[0]) == str(np.ravel(first.extras["failure"])[0])
    assert "threshold search failed" in str(np.ravel(again.extras["failure"])[0])


def test_the_key_changes_with_parameters_inputs_and_code(axisym, monkeypatch):
    inputs = tuple(np.broadcast_arrays(P, 35.0, 2.5, 0.05))
    key = cache_key(axisym, inputs)
    assert cache_key(axisym, inputs) == key
    assert cache_key(parse_spec("axisym:mesh=medium").build(), inputs) != key
    other = tuple(np.broadcast_arrays(P + 1e-9, 35.0, 2.5, 0.05))
    assert cache_key(axisym, other) != key
    # an edit of the physics changes the model version, hence the key
    monkeypatch.setattr(prediction_cache, "model_version", lambda model: "edited")
    assert cache_key(axisym, inputs) != key


def test_no_cache_dir_means_no_cache(tmp_path, axisym):
    _, hit = cached_predict(axisym, P, 35.0, 2.5, 0.05, cache_dir=None)
    _, hit_again = cached_predict(axisym, P, 35.0, 2.5, 0.05, cache_dir=None)
    assert not hit and not hit_again


def test_predict_many_batches_the_fe_sweeps_and_equals_predict(tmp_path, axisym):
    from mkm.prediction_cache import predict_many

    sliding = parse_spec("axisym:mesh=coarse,braid=sliding").build()  # a job cannot carry it
    eq2 = parse_spec("eq2").build()
    # the second muscle passes the braid lock: NaN forces and failure strings must survive
    requests = [(axisym, P, 35.0, 2.5, 0.05), (axisym, P, 30.0, 2.0, 0.35),
                (sliding, P, 35.0, 2.5, 0.05), (eq2, P, 35.0, 2.5, 0.05)]
    solved = predict_many(requests, tmp_path / "predictions", workers=1)
    assert [hit for _, hit in solved] == [False] * 4
    for (model, *inputs), (pred, _) in zip(requests, solved, strict=True):
        direct = model.predict(*inputs)
        assert pred.params == direct.params and set(pred.extras) == set(direct.extras)
        for name in ("force_N", "valid", "converged", "pressure_bar", "eps"):
            np.testing.assert_array_equal(getattr(pred, name), getattr(direct, name))
        for name, values in direct.extras.items():  # same values and dtypes, to the last bit
            assert pred.extras[name].dtype == np.asarray(values).dtype, name
            np.testing.assert_array_equal(pred.extras[name], values)
    # stored in the prediction cache: the next report or study reads them
    again = predict_many(requests, tmp_path / "predictions", workers=1)
    assert [hit for _, hit in again] == [True] * 4
    assert again[1][0].seconds == solved[1][0].seconds


@pytest.mark.parametrize("damage", [b"", b"PK\x03\x04 cut", b"x" * 500])
def test_a_damaged_entry_is_computed_again_and_replaced(damage, tmp_path):
    # a write cut short or a damaged file: BadZipFile / EOFError / ValueError tracebacks
    model = parse_spec("thickwall").build()
    pressures = np.array([0.5, 1.0])
    first, hit = cached_predict(model, pressures, 30.0, 3.0, 0.0, cache_dir=tmp_path)
    (entry,) = tmp_path.glob("*.npz")
    entry.write_bytes(damage)
    again, hit = cached_predict(model, pressures, 30.0, 3.0, 0.0, cache_dir=tmp_path)
    assert not hit
    np.testing.assert_array_equal(again.force_N, first.force_N)
    (many,) = prediction_cache.predict_many([(model, pressures, 30.0, 3.0, 0.0)], tmp_path)
    assert many[1] and np.array_equal(many[0].force_N, first.force_N)  # replaced: a hit now
