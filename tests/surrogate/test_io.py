import json
import os
import re
import subprocess
import sys
import warnings
import zipfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mkm.core.records import file_sha256
from mkm.surrogate.io import (
    ESTIMATOR_FILE,
    METADATA_FILE,
    LibraryVersionWarning,
    UncheckedDataWarning,
    load_model,
    metadata_sha256,
    save_model,
)
from mkm.surrogate.train import train_surrogate


@pytest.fixture(scope="module")
def saved(thickwall_dataset, tmp_path_factory):
    model = train_surrogate("physics", thickwall_dataset, splits=2)
    directory = save_model(model, tmp_path_factory.mktemp("models") / "physics")
    return model, directory, thickwall_dataset


def copy_model(directory, to: Path) -> Path:
    to.mkdir()
    for f in directory.iterdir():
        (to / f.name).write_bytes(f.read_bytes())
    return to


def rewrite_metadata(folder: Path, edit, sign: bool = True) -> None:
    """Edit a model folder's metadata; ``sign``: record the hash of the edited metadata, as a
    training that wrote it would (else the edit is a tampering)."""
    meta = json.loads((folder / METADATA_FILE).read_text())
    edit(meta)
    if sign:
        meta["sha256"] = metadata_sha256(meta)
    (folder / METADATA_FILE).write_text(json.dumps(meta))


def recorded_at(path: str, **dataset):
    """An edit of a model's metadata: its training data recorded at ``path`` alone (and
    ``dataset``'s keys), as a model saved before it recorded where the data lies from its
    folder."""
    def edit(meta):
        meta["dataset"].pop("path_from_model", None)
        meta["dataset"].update({"path": path, **dataset})
    return edit


def test_round_trip_predicts_the_same(saved):
    model, directory, _ = saved
    loaded = load_model(directory)
    P = np.linspace(0.0, 2.5, 11)
    np.testing.assert_array_equal(loaded.predict(P, 41.0, 2.7, 0.13).force_N,
                                  model.predict(P, 41.0, 2.7, 0.13).force_N)
    assert loaded.domain == model.domain and loaded.kind == "physics"
    assert loaded.fixed == model.fixed and loaded.inputs == model.inputs


@pytest.mark.skipif(os.name == "nt", reason="POSIX permissions")
def test_a_model_folder_has_the_permissions_of_the_users_umask(saved):
    # was: drwx------, mkdtemp's, where every other output folder follows the umask: a lab's
    # shared model folder unreadable by the others
    _, directory, _ = saved
    umask = os.umask(0)
    os.umask(umask)
    assert directory.stat().st_mode & 0o777 == 0o777 & ~umask


def test_a_model_saved_says_what_its_file_says(saved):
    # was: the model just trained and saved (the cache's on first use) kept its metadata
    # without the file's sha256: the first report or study after a training named no file
    model, directory, _ = saved
    assert model.metadata == json.loads((directory / METADATA_FILE).read_text())
    assert model.origin()["sha256"] == load_model(directory).origin()["sha256"]


def test_files_are_json_and_arrays_not_pickles(saved):
    _, directory, _ = saved
    assert sorted(f.name for f in directory.iterdir()) == [ESTIMATOR_FILE, METADATA_FILE]
    with zipfile.ZipFile(directory / ESTIMATOR_FILE) as archive:  # skops: JSON schema + .npy
        names = archive.namelist()
    assert "schema.json" in names
    assert all(n == "schema.json" or n.endswith(".npy") for n in names)


def test_metadata_records_data_domain_metrics_checks(saved):
    _, directory, dataset = saved
    meta = json.loads((directory / METADATA_FILE).read_text())
    assert meta["dataset"]["sha256"] == file_sha256(dataset)
    assert meta["dataset"]["n_rows"] == 162 and meta["dataset"]["n_muscles"] == 27
    assert meta["fixed"]["L0_mm"] == 282.0 and set(meta["fixed"]) == {
        "L0_mm", "theta0_deg", "C10_MPa", "C01_MPa"}
    assert meta["box"]["eps"] == [0.0, 0.2]
    assert meta["metrics"]["muscle_held_out"]["rmse_test_N"]["n"] == 2
    assert meta["checks"]["code_version"].count("+") == 1
    assert "axisym" in meta["checks"]["calibration"]
    assert meta["trained"]["versions"]["scikit-learn"]


def test_other_library_versions_warn(saved, tmp_path):
    copy = copy_model(saved[1], tmp_path / "old")
    rewrite_metadata(copy, lambda m: m["trained"]["versions"].update({"scikit-learn": "0.24.2"}))
    with pytest.warns(LibraryVersionWarning, match=r"scikit-learn 0\.24\.2 -> "):
        load_model(copy)


def test_other_code_version_is_refused_unless_accepted(saved, tmp_path):
    # A 2 % edit of the closed form once moved a loaded prediction from 870 to 888 N silently.
    copy = copy_model(saved[1], tmp_path / "stale")
    rewrite_metadata(copy, lambda m: m["checks"].update({"code_version": "0.0.1+000000000000"}))
    with pytest.raises(ValueError, match=r"code version 0\.0\.1\+000000000000 .* is now"):
        load_model(copy)
    assert load_model(copy, accept_mismatch=True).kind == "physics"


def test_other_calibration_is_refused(saved, tmp_path):
    copy = copy_model(saved[1], tmp_path / "calibration")
    rewrite_metadata(copy, lambda m: m["checks"]["calibration"]["axisym"].update(
        {"theta0_deg": 20.0}))
    with pytest.raises(ValueError, match="fem/calibration.json changed since training"):
        load_model(copy)


def test_changed_training_data_is_refused(saved, tmp_path):
    copy = copy_model(saved[1], tmp_path / "data")
    data = tmp_path / "data.csv"
    data.write_text("pressure_bar\n0\n")
    rewrite_metadata(copy, recorded_at(str(data)))
    with pytest.raises(ValueError, match="training data .* changed since training"):
        load_model(copy)


def test_training_data_is_checked_where_it_lies_above_the_model(saved, tmp_path, monkeypatch):
    # was: only from the folder the training ran in (the recorded path is relative to it)
    project = tmp_path / "project"
    (project / "data").mkdir(parents=True)
    data = project / "data" / "d.csv"
    data.write_bytes(saved[2].read_bytes())
    copy = copy_model(saved[1], project / "models")
    rewrite_metadata(copy, recorded_at("data/d.csv", sha256=file_sha256(data)))
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # found and unchanged: nothing to say
        load_model(copy)
    data.write_bytes(data.read_bytes() + b"\n")
    with pytest.raises(ValueError, match=r"training data .*d\.csv changed since training"):
        load_model(copy)


def test_training_data_outside_the_working_directory_is_checked_from_anywhere(
        thickwall_dataset, tmp_path, monkeypatch):
    # was: trained in folder A on data in folder B, the model recorded the data's name alone:
    # loaded from folder C its check was said undone (UncheckedDataWarning)
    for name in "ABC":
        (tmp_path / name).mkdir()
    data = tmp_path / "B" / "d.csv"
    data.write_bytes(thickwall_dataset.read_bytes())
    monkeypatch.chdir(tmp_path / "A")
    directory = save_model(train_surrogate("physics", data, splits=0),
                           tmp_path / "A" / "models" / "m")
    recorded = json.loads((directory / METADATA_FILE).read_text())["dataset"]
    assert recorded["path"] == "d.csv"  # relative to A it is not: its name
    assert recorded["path_from_model"] == "../../../B/d.csv"  # no folder above tmp_path named
    monkeypatch.chdir(tmp_path / "C")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # found and unchanged: nothing to say
        loaded = load_model(directory)
    assert loaded.data_file.resolve() == data.resolve()
    data.write_bytes(data.read_bytes() + b"\n")
    # said as the file it is, not as a path through the model's folder (m/../../../B/d.csv)
    with pytest.raises(ValueError, match=re.escape(f"training data {data.resolve()} changed")):
        load_model(directory)


def test_the_cache_records_no_path_from_its_folder_to_the_data(thickwall_dataset, tmp_path):
    # the cache's folder name holds the data's sha256; a path from the user's cache to a
    # project's data would name the folders of the machine
    from mkm.surrogate.train import cached_model

    cached_model("physics", thickwall_dataset, cache_dir=tmp_path / "cache", splits=0)
    (folder,) = (p for p in (tmp_path / "cache").iterdir() if p.is_dir())
    assert "path_from_model" not in json.loads((folder / METADATA_FILE).read_text())["dataset"]


def test_a_model_reused_from_the_cache_names_its_data_as_found_here(thickwall_dataset,
                                                                    tmp_path, monkeypatch):
    # was: reused from another folder, the cached model's records named its data by the path
    # the process that trained it saw (data/d.csv, relative to a folder this one is not in)
    from mkm.surrogate.train import cached_model

    for folder in ("A/data", "B/sets"):
        (tmp_path / folder).mkdir(parents=True)
        (tmp_path / folder / "d.csv").write_bytes(thickwall_dataset.read_bytes())
    monkeypatch.chdir(tmp_path / "A")
    trained = cached_model("physics", "data/d.csv", cache_dir=tmp_path / "cache", splits=0)
    assert trained.origin()["dataset"]["path"] == "data/d.csv"
    monkeypatch.chdir(tmp_path / "B")
    reused = cached_model("physics", "sets/d.csv", cache_dir=tmp_path / "cache", splits=0)
    assert reused.metadata == trained.metadata  # the same model file, not trained again
    assert reused.origin()["dataset"] == {"path": "sets/d.csv",
                                          "sha256": file_sha256(thickwall_dataset)}
    assert reused.with_parameters(L0_mm=282.0).origin() == reused.origin()


def test_training_data_found_nowhere_is_said_unchecked(saved, tmp_path, monkeypatch):
    # the shipped mkm_dataset.csv is another file of that name: no false "changed"
    copy = copy_model(saved[1], tmp_path / "model")
    rewrite_metadata(copy, recorded_at("mkm_dataset.csv"))
    monkeypatch.chdir(tmp_path)
    with pytest.warns(UncheckedDataWarning, match=r"its training data mkm_dataset\.csv \(sha256 "
                      r"[0-9a-f]{12}\) is found neither .* not checked"):
        assert load_model(copy).kind == "physics"


def test_tampered_estimator_is_refused(saved, tmp_path):
    copy = copy_model(saved[1], tmp_path / "tampered")
    (copy / ESTIMATOR_FILE).write_bytes(b"not a model")
    with pytest.raises(ValueError, match="does not match the sha256"):
        load_model(copy)


def _crafted_object(what):
    """What a crafted estimator file holds instead of a model (skops stores both by name)."""
    if what == "function":  # a function reference the loader would call
        import os

        return os.system
    from mkm.surrogate.model import OutOfDomainWarning

    return OutOfDomainWarning()  # a class of ours that is not a model


@pytest.mark.slow  # a subprocess writes the pickle
@pytest.mark.parametrize("what", ["function", "class", "pickle"])
def test_crafted_model_folder_cannot_run_code(saved, tmp_path, what):
    # A crafted folder with a matching sha256 ran a shell command through a joblib pickle.
    # Here: a model file holding a type outside the trusted list, or a pickle whose loading
    # would write a marker file, with the metadata's hash made to match. Loading refuses and
    # the marker never appears.
    marker = tmp_path / "pwned"
    copy = copy_model(saved[1], tmp_path / "crafted")
    target = copy / ESTIMATOR_FILE
    if what == "pickle":
        script = ("import pickle, sys\n"
                  "class Evil:\n"
                  "    def __reduce__(self):\n"
                  f"        return (open, ({str(marker)!r}, 'w'))\n"
                  "sys.stdout.buffer.write(pickle.dumps(Evil()))\n")
        target.write_bytes(subprocess.run([sys.executable, "-c", script], check=True,
                                          capture_output=True).stdout)
    else:
        import skops.io as sio

        sio.dump(_crafted_object(what), target)
    rewrite_metadata(copy, lambda m: m["checks"].update(
        {"estimator_sha256": file_sha256(target)}))
    expected = "cannot be read" if what == "pickle" else "holds types outside the trusted list"
    with pytest.raises(ValueError, match=expected):
        load_model(copy)
    assert not marker.exists()


def test_not_a_model_folder(tmp_path):
    with pytest.raises(ValueError, match="is not a saved surrogate"):
        load_model(tmp_path)


@pytest.mark.slow  # trains a GP
def test_default_model_is_trained_once_and_cached(thickwall_dataset, tmp_path):
    from mkm.surrogate.train import default_model

    first = default_model(thickwall_dataset, cache_dir=tmp_path)
    (entry,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    stamp = (entry / ESTIMATOR_FILE).stat().st_mtime_ns
    second = default_model(thickwall_dataset, cache_dir=tmp_path)
    assert (entry / ESTIMATOR_FILE).stat().st_mtime_ns == stamp  # loaded, not retrained
    assert second.kind == first.kind == "muscle-gp"


@pytest.mark.slow  # two training processes
def test_two_processes_training_at_once(thickwall_dataset, tmp_path):
    # Two processes training the same cached model at once once crashed ("Directory not
    # empty"). With the lock, one trains and saves, the other waits and loads it: both finish,
    # with the same model, and one entry is left.
    script = ("import sys\nfrom mkm.surrogate.train import cached_model\n"
              "m = cached_model('physics', sys.argv[1], cache_dir=sys.argv[2], splits=0)\n"
              "print(repr(float(m.predict(2.0, 40.0, 3.0, 0.1).force_N)))\n")
    runs = [subprocess.Popen([sys.executable, "-c", script, str(thickwall_dataset),
                              str(tmp_path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True) for _ in range(2)]
    outputs = [run.communicate(timeout=300) for run in runs]
    assert [run.returncode for run in runs] == [0, 0], [err for _, err in outputs]
    assert outputs[0][0] == outputs[1][0]
    entries = [p for p in tmp_path.iterdir() if p.is_dir()]
    assert len(entries) == 1 and (entries[0] / METADATA_FILE).is_file()


def test_error_margin_is_what_training_measured(saved):
    # The physics kind has no std; its two muscle-held-out splits measured its worst error.
    model, directory, _ = saved
    margin = load_model(directory).error_margin()
    held_out = model.metadata["metrics"]["muscle_held_out"]
    assert margin.worst_abs_error_N >= held_out["max_abs_test_N"]["max"] > 0
    assert margin.within_2std is None and "2 muscle-held-out splits" in margin.measured_on


def test_widened_box_is_refused(saved, tmp_path):
    # Widening the box in metadata.json once made D0 = 500 mm predict 128 118 N with valid and
    # in_domain true. The box is covered by the metadata's hash: the edit is refused.
    copy = copy_model(saved[1], tmp_path / "widened")
    rewrite_metadata(copy, lambda m: m["box"].update({"D0_mm": [0.0, 1000.0]}), sign=False)
    with pytest.raises(ValueError, match="does not match the sha256 it records: it was edited"):
        load_model(copy)


def test_tampered_metadata_is_one_line_on_the_cli(saved, tmp_path, capsys):
    from mkm.cli import main

    copy = copy_model(saved[1], tmp_path / "widened")
    rewrite_metadata(copy, lambda m: m["box"].update({"D0_mm": [0.0, 1000.0]}), sign=False)
    assert main(["fem", "solve", "--model", f"surrogate:path={copy}", "--D0", "500", "--t0",
                 "3", "--eps", "0.1"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("mkm fem solve: error: ") and "edited" in err and err.count("\n") == 1


def test_huge_metadata_is_refused_unread(saved, tmp_path):
    from mkm.surrogate.io import MAX_METADATA_BYTES

    copy = copy_model(saved[1], tmp_path / "huge")
    (copy / METADATA_FILE).write_text(" " * (MAX_METADATA_BYTES + 1) + "{}")
    with pytest.raises(ValueError, match=rf"holds {MAX_METADATA_BYTES + 3} bytes: expected at"):
        load_model(copy)


JSON_VALUES = st.recursive(
    st.none() | st.booleans() | st.integers(-10**6, 10**6)
    | st.floats(allow_nan=True, allow_infinity=True) | st.text(max_size=8),
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=5), inner,
                                                                max_size=3),
    max_leaves=6)


def key_paths(node, prefix=()):
    """Every key path of a JSON object, parents before children."""
    for key, value in node.items():
        yield (*prefix, key)
        if isinstance(value, dict):
            yield from key_paths(value, (*prefix, key))


@settings(max_examples=80, deadline=None)
@given(data=st.data(), sign=st.booleans())
def test_malformed_metadata_is_one_value_error(saved, tmp_path_factory, data, sign):
    # Any edit of the metadata (a value replaced by any JSON, a key dropped, the whole file
    # replaced) is refused with a ValueError, hash recomputed or not; never another exception.
    # An edit that keeps the structure with the hash recomputed (what a training could have
    # written) may load: then it predicts and reports its margin without raising anything else.
    directory = saved[1]
    meta = json.loads((directory / METADATA_FILE).read_text())
    action = data.draw(st.sampled_from(["replace", "drop", "whole"]))
    if action == "whole":
        meta = data.draw(JSON_VALUES)
    else:
        *parents, key = data.draw(st.sampled_from(list(key_paths(meta))))
        node = meta
        for part in parents:
            node = node[part]
        if action == "drop":
            del node[key]
        else:
            node[key] = data.draw(JSON_VALUES)
    if sign and isinstance(meta, dict):
        meta["sha256"] = metadata_sha256(meta)
    copy = copy_model(directory, tmp_path_factory.mktemp("fuzz") / "model")
    (copy / METADATA_FILE).write_text(json.dumps(meta))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # other library versions, out of the domain
            model = load_model(copy, accept_mismatch=data.draw(st.booleans()))
            model.predict([0.0, 1.0, 2.0], 40.0, 3.0, 0.1)
            model.error_margin()
    except ValueError as exc:
        assert "\n" not in str(exc)


@pytest.fixture(scope="module")
def saved_gp(thickwall_dataset, tmp_path_factory):
    model = train_surrogate("muscle-gp", thickwall_dataset, splits=0)
    return model, save_model(model, tmp_path_factory.mktemp("models") / "muscle-gp")


@pytest.mark.slow  # trains, then loads in a fresh process
def test_default_kind_loads_without_scikit_learn(saved_gp):
    # The muscle GP predicts from predictor.npz: loading and predicting import neither
    # scikit-learn nor skops (1-2 s of imports), and give the estimator's numbers to the bit.
    _, directory = saved_gp
    script = ("import sys\nimport numpy as np\nfrom mkm.surrogate.io import load_model\n"
              f"m = load_model({str(directory)!r})\n"
              "p = m.predict(np.linspace(0, 2.5, 11), 41.0, 2.7, 0.13)\n"
              "print(sorted(k for k in ('sklearn', 'skops') if k in sys.modules))\n"
              "X = np.column_stack([np.linspace(0, 2.5, 11), *np.full((3, 11), [[41.0], [2.7],"
              " [0.13]])])\n"
              "force, std = m.estimator.predict(X, return_std=True)\n"
              "print(np.array_equal(force, p.force_N), np.array_equal(std, "
              "p.extras['force_std_N']))\n")
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         timeout=120, check=True)
    assert run.stdout.split("\n")[:2] == ["[]", "True True"]


def test_predictor_file_is_numbers_only(saved_gp, tmp_path):
    # A predictor file holding a pickled object, with every hash made to match, is refused
    # (read with allow_pickle=False), and the marker its pickle would write never appears.
    from mkm.surrogate.io import PREDICTOR_FILE

    marker = tmp_path / "pwned"
    copy = copy_model(saved_gp[1], tmp_path / "crafted")
    script = ("import numpy as np, sys\n"
              "class Evil:\n"
              "    def __reduce__(self):\n"
              f"        return (open, ({str(marker)!r}, 'w'))\n"
              "a = np.empty(1, dtype=object); a[0] = Evil()\n"
              f"np.savez({str(copy / PREDICTOR_FILE)!r}, z_mean=a)\n")
    subprocess.run([sys.executable, "-c", script], check=True)
    rewrite_metadata(copy, lambda m: m["checks"].update(
        {"predictor_sha256": file_sha256(copy / PREDICTOR_FILE)}))
    with pytest.raises(ValueError, match="cannot be read as the surrogate's arrays"):
        load_model(copy)
    assert not marker.exists()
    (copy / PREDICTOR_FILE).write_bytes(b"edited")
    with pytest.raises(ValueError, match="predictor.npz' is missing or does not match"):
        load_model(copy)


def test_saving_never_replaces_a_folder_of_the_users(saved, tmp_path):
    """``save_model`` (``mkm surrogate train --out DIR``) used to swap out any folder at DIR
    and delete it: ``--out mkm-out/runs`` deleted every run. A model folder is still
    replaced, as retraining into it asks."""
    model, directory, _ = saved
    runs = tmp_path / "runs"
    runs.mkdir()
    (runs / "run1.csv").write_text("precious", encoding="utf-8")
    with pytest.raises(ValueError, match=r"runs holds files that are not a saved model "
                       r"\(run1\.csv\): .* nothing was replaced"):
        save_model(model, runs)
    assert (runs / "run1.csv").read_text(encoding="utf-8") == "precious"
    again = copy_model(directory, tmp_path / "model")
    save_model(model, again)
    assert load_model(again).kind == "physics"


def test_saving_leaves_the_folder_alone_beside_the_model(saved, tmp_path):
    """``mkm surrogate train --out DIR`` used to leave ``DIR.lock`` beside the model for good
    (filelock keeps its file): the lock now lives in the user's cache."""
    model, _, _ = saved
    save_model(model, tmp_path / "model")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model"]
