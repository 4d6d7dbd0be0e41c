import json

import numpy as np
import pytest

from surrogate.io import LibraryVersionWarning, load_model, save_model
from surrogate.train import train_surrogate
from surrogate.training_data import file_sha256


@pytest.fixture(scope="module")
def saved(thickwall_dataset, tmp_path_factory):
    model = train_surrogate("physics", thickwall_dataset, seeds=(0, 1))
    directory = save_model(model, tmp_path_factory.mktemp("models") / "physics")
    return model, directory, thickwall_dataset


def test_round_trip_predicts_the_same(saved):
    model, directory, _ = saved
    loaded = load_model(directory)
    P = np.linspace(0.0, 2.5, 11)
    np.testing.assert_array_equal(loaded.predict(P, 41.0, 2.7, 0.13).force_N,
                                  model.predict(P, 41.0, 2.7, 0.13).force_N)
    assert loaded.domain == model.domain and loaded.kind == "physics"


def test_metadata_records_data_domain_metrics_versions(saved):
    _, directory, dataset = saved
    meta = json.loads((directory / "metadata.json").read_text())
    assert meta["dataset"]["sha256"] == file_sha256(dataset)
    assert meta["dataset"]["n_rows"] == 162 and meta["dataset"]["fixed"]["model"] == "thickwall"
    assert meta["domain"]["eps"] == [0.0, 0.2]
    assert meta["metrics"]["rmse_test_N"]["n"] == 2
    assert meta["trained"]["versions"]["scikit-learn"]


def test_other_library_versions_warn(saved, tmp_path):
    _, directory, _ = saved
    copy = tmp_path / "old"
    copy.mkdir()
    for f in directory.iterdir():
        (copy / f.name).write_bytes(f.read_bytes())
    meta = json.loads((copy / "metadata.json").read_text())
    meta["trained"]["versions"]["scikit-learn"] = "0.24.2"
    (copy / "metadata.json").write_text(json.dumps(meta))
    with pytest.warns(LibraryVersionWarning, match=r"scikit-learn 0\.24\.2 -> "):
        load_model(copy)


def test_tampered_estimator_is_refused(saved, tmp_path):
    _, directory, _ = saved
    for f in directory.iterdir():
        (tmp_path / f.name).write_bytes(f.read_bytes())
    (tmp_path / "estimator.joblib").write_bytes(b"not a model")
    with pytest.raises(ValueError, match="does not match the sha256"):
        load_model(tmp_path)


def test_not_a_model_folder(tmp_path):
    with pytest.raises(ValueError, match="is not a saved surrogate"):
        load_model(tmp_path)


def test_default_model_is_trained_once_and_cached(thickwall_dataset, tmp_path):
    from surrogate.train import default_model

    first = default_model(thickwall_dataset, cache_dir=tmp_path)
    (entry,) = tmp_path.iterdir()
    stamp = (entry / "estimator.joblib").stat().st_mtime_ns
    second = default_model(thickwall_dataset, cache_dir=tmp_path)
    assert (entry / "estimator.joblib").stat().st_mtime_ns == stamp  # loaded, not retrained
    assert second.kind == first.kind == "physics"
