"""Saving and loading surrogates: model files that cannot run code, and that know what they need.

A saved surrogate is a folder:

- ``estimator.skops``: the fitted estimator in skops' format (a zip of JSON and ``.npy``
  arrays), loaded with an explicit list of trusted types: those its kind declares
  (:func:`mkm.surrogate.kinds.trusted_types`: the project's own estimator classes and feature
  function, scikit-learn's kernels); skops itself trusts scikit-learn's estimators and numpy
  arrays, which it rebuilds without pickle. A file naming anything else (``os.system``, a class
  with a crafted ``__reduce__``) is refused before anything in it is built: loading a model
  never runs code from it;
- ``predictor.npz``, for a kind that declares a predictor (the default ``muscle-gp``): the
  fitted arrays its predictions need, read with ``allow_pickle=False`` and without
  scikit-learn or skops, so a saved default surrogate loads in a fraction of a second;
- ``metadata.json``: kind, inputs, recorded parameters, box, metrics, the training data's
  sha256 and where it lies seen from the folder (:func:`path_from_model`), and the checks:
  the source version of every module the estimator calls (:func:`code_version`, the physics
  of the closed-form priors included) and the calibration (``fem/calibration.json``) at
  training time, and the sha256 of the other files; ``sha256``, the hash of everything else in
  it (:func:`metadata_sha256`), so an edited box, kind or check is refused, never believed.

:func:`load_model` refuses, with one line, a folder whose metadata is malformed (not an object,
a key missing or of the wrong type, larger than :data:`MAX_METADATA_BYTES`) or does not match
its hash, whose estimator file does not match its recorded hash, or (unless
``accept_mismatch=True``) whose checks do not match this installation, naming each difference;
other library versions warn (:class:`LibraryVersionWarning`). :func:`save_model` writes under a
lock file in the user's cache (``filelock``: works on Windows too) and swaps the folder in
whole, so two processes saving at once cannot leave half a model or crash on each other.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import shutil
import tempfile
import warnings
from pathlib import Path

from mkm.core.records import (
    file_sha256,
    follow_umask,
    jsonable,
    package_file,
    provenance,
    source_version,
    write_json_atomic,
)
from mkm.fem.interface import INPUTS
from mkm.surrogate import kinds
from mkm.surrogate.model import SurrogateForceModel
from mkm.surrogate.training_data import ALL_INPUTS, PARAMETERS

ESTIMATOR_FILE = "estimator.skops"
PREDICTOR_FILE = "predictor.npz"
METADATA_FILE = "metadata.json"
CHECKED_LIBRARIES = ("python", "numpy", "scipy", "scikit-learn")
#: Largest metadata file read (a trained model's is ~15 kB): a larger one is refused unread.
MAX_METADATA_BYTES = 1 << 20
#: The key of a model's ``dataset`` record that says where the data lay seen from the model's
#: folder (:func:`path_from_model`)
PATH_FROM_MODEL = "path_from_model"


class LibraryVersionWarning(UserWarning):
    """A surrogate is loaded with library versions other than those it was trained with."""


class UncheckedDataWarning(UserWarning):
    """A surrogate is loaded where its training data cannot be found: whether that data
    changed since training is not checked."""


def code_version(kind: str) -> str:
    """Source version of everything a loaded surrogate of ``kind`` calls
    (:func:`mkm.surrogate.kinds.model_modules` and the project modules they import)."""
    return source_version(*kinds.model_modules(kind))


def metadata_sha256(metadata: dict) -> str:
    """sha256 of ``metadata`` without its ``sha256`` key, as canonical JSON (sorted keys, no
    spaces): the same for the dict written and the dict read back."""
    body = {k: v for k, v in metadata.items() if k != "sha256"}
    text = json.dumps(body, sort_keys=True, separators=(",", ":"), default=jsonable)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def calibration_snapshot() -> dict:
    """The calibration in force (``fem/calibration.json``): the default braid angle comes from
    it, and the closed-form physics the priors use is calibrated with it."""
    from mkm.fem.calibration import CALIBRATION_FILE

    return json.loads(Path(CALIBRATION_FILE).read_text(encoding="utf-8"))


#: every file a saved model folder holds (the predictor only for kinds that declare one)
MODEL_FILES = frozenset({ESTIMATOR_FILE, PREDICTOR_FILE, METADATA_FILE})


def check_replaceable(directory) -> None:
    """``ValueError`` unless ``directory`` may become a model folder: absent, empty, or a model
    folder (only :data:`MODEL_FILES`), which saving replaces whole. Any other folder is the
    user's (``--out mkm-out/runs``): replacing it would delete what it holds."""
    directory = Path(directory)
    if not directory.exists():
        return
    if not directory.is_dir():
        raise ValueError(f"{directory} is a file: expected a folder for the model (new, or one "
                         "`mkm surrogate train` wrote)")
    others = sorted(p.name for p in directory.iterdir() if p.name not in MODEL_FILES)
    if others:
        shown = ", ".join(others[:3]) + (f" and {len(others) - 3} more" if len(others) > 3
                                         else "")
        raise ValueError(f"{directory} holds files that are not a saved model ({shown}): "
                         "expected a new folder or one `mkm surrogate train` wrote; nothing "
                         "was replaced")


def save_lock(directory: Path):
    """The lock of saving a model to ``directory``: a file in the user's cache named by the
    folder's resolved path. ``filelock`` leaves its file behind, and a ``DIR.lock`` beside the
    user's ``--out DIR`` would stay there for good."""
    from filelock import FileLock

    from mkm.core.home import user_cache

    key = hashlib.sha256(os.fsencode(directory.resolve())).hexdigest()[:16]
    locks = user_cache("locks")
    locks.mkdir(parents=True, exist_ok=True)
    return FileLock(str(locks / f"model-{key}.lock"))


def save_model(model: SurrogateForceModel, directory, lock=None,
               locate_data: bool = True) -> Path:
    """Write ``model`` to ``directory`` (created; a model folder there is replaced whole, any
    other folder refused: :func:`check_replaceable`); ``model.metadata`` becomes the metadata
    saved (checks, sha256), so a record of what it computes names the file.

    ``lock``: a context manager held while writing (default: :func:`save_lock`).
    ``locate_data``: record where the training data lies seen from ``directory``
    (:func:`path_from_model`), so that loading finds it wherever the two are moved together.
    """
    import numpy as np
    import skops.io as sio

    directory = Path(directory)
    check_replaceable(directory)
    directory.parent.mkdir(parents=True, exist_ok=True)
    with lock if lock is not None else save_lock(directory):
        staging = Path(tempfile.mkdtemp(prefix=f".{directory.name}-", dir=directory.parent))
        try:
            follow_umask(staging, 0o777)  # the model folder itself, once moved into place
            sio.dump(model.estimator, staging / ESTIMATOR_FILE)
            checks = {"code_version": code_version(model.kind),
                      "calibration": calibration_snapshot(),
                      "estimator_sha256": file_sha256(staging / ESTIMATOR_FILE)}
            if kinds.predictor_class(model.kind) is not None:
                with open(staging / PREDICTOR_FILE, "wb") as f:
                    np.savez(f, **model.estimator.predictor().arrays())
                checks["predictor_sha256"] = file_sha256(staging / PREDICTOR_FILE)
            dataset = {k: v for k, v in model.metadata.get("dataset", {}).items()
                       if k != PATH_FROM_MODEL}
            found = path_from_model(model.data_file, directory) if locate_data else None
            if found is not None:
                dataset[PATH_FROM_MODEL] = found
            metadata = {**model.metadata, "kind": model.kind, "inputs": list(model.inputs),
                        "fixed": model.fixed, "box": {k: list(v) for k, v in model.box.items()},
                        "checks": checks, "saved": provenance()}
            if dataset:
                metadata["dataset"] = dataset
            metadata.setdefault("trained", metadata["saved"])
            metadata.pop("sha256", None)
            # hashed as it will be read back (numpy values as JSON numbers and lists)
            metadata = json.loads(json.dumps(metadata, default=jsonable))
            metadata["sha256"] = metadata_sha256(metadata)
            write_json_atomic(staging / METADATA_FILE, metadata)
            if directory.exists():  # swap, so a reader never sees half a model
                old = Path(tempfile.mkdtemp(prefix=f".{directory.name}-old-",
                                            dir=directory.parent))
                os.replace(directory, old / "model")
                os.replace(staging, directory)
                shutil.rmtree(old, ignore_errors=True)
            else:
                os.replace(staging, directory)
            model.metadata = metadata  # saved: the model says what its file says (its sha256)
        finally:
            if staging.exists():
                shutil.rmtree(staging, ignore_errors=True)
    return directory


def path_from_model(data_file, directory) -> str | None:
    """Where ``data_file`` lies seen from the model folder ``directory``: a relative path, parts
    joined by ``/`` (``../data/d.csv``), which finds it wherever the two are moved together,
    and names no folder above them. None for no file, a dataset shipped in the package (found
    by its name) or one on another drive."""
    if data_file is None:
        return None
    data_file = Path(data_file).resolve()
    if data_file.parent == package_file("mkm.surrogate", "data"):
        return None
    try:
        return Path(os.path.relpath(data_file, Path(directory).resolve())).as_posix()
    except ValueError:  # another drive on Windows: no relative path
        return None


def read_metadata(directory) -> dict:
    """The metadata of the model folder ``directory``, checked: an object of at most
    :data:`MAX_METADATA_BYTES` that matches its ``sha256`` and holds what :func:`load_model`
    reads, each of the right type (:func:`check_metadata`); a one-line ``ValueError`` if not."""
    path = Path(directory) / METADATA_FILE
    if not path.is_file():
        raise ValueError(f"{str(directory)!r} is not a saved surrogate: {METADATA_FILE} missing "
                         "(expected a folder written by `mkm surrogate train`)")
    size = path.stat().st_size
    if size > MAX_METADATA_BYTES:
        raise ValueError(f"{str(path)!r} holds {size} bytes: expected at most "
                         f"{MAX_METADATA_BYTES} (the metadata `mkm surrogate train` writes)")
    try:
        metadata = json.loads(path.read_bytes().decode("utf-8"))
    except (ValueError, RecursionError) as exc:  # UnicodeDecodeError is a ValueError
        raise ValueError(f"{str(path)!r} is not valid JSON ({type(exc).__name__}: "
                         f"{str(exc)[:80]}): expected the metadata `mkm surrogate train` "
                         "writes") from None
    if not isinstance(metadata, dict):
        raise ValueError(f"{str(path)!r} holds a JSON {type(metadata).__name__}: expected an "
                         "object (the metadata `mkm surrogate train` writes)")
    if metadata.get("sha256") != metadata_sha256(metadata):
        raise ValueError(f"{str(path)!r} does not match the sha256 it records: it was edited "
                         "after `mkm surrogate train` wrote it (box, kind, inputs or checks "
                         "changed); retrain it")
    check_metadata(metadata, path)
    return metadata


def _short(value) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _number(value) -> bool:
    return (isinstance(value, int | float) and not isinstance(value, bool)
            and math.isfinite(value))


def check_metadata(metadata: dict, path) -> None:
    """One-line ``ValueError`` naming the first key of ``metadata`` (read from ``path``) that is
    missing or of the wrong type among those :func:`load_model` and the model read."""

    def require(ok, key, expected):
        if not ok:
            value = _short(lookup(key)) if found(key) else "missing"
            raise ValueError(f"{str(path)!r}: {key} is {value}: expected {expected} (the "
                             "metadata `mkm surrogate train` writes; retrain it)")

    def found(key):
        node = metadata
        for part in key.split("."):
            if not isinstance(node, dict) or part not in node:
                return False
            node = node[part]
        return True

    def lookup(key):
        node = metadata
        for part in key.split("."):
            node = node[part]
        return node

    def typed(key, types, expected, optional=False):
        require((optional and not found(key)) or (found(key) and isinstance(lookup(key), types)
                                                  and not isinstance(lookup(key), bool)),
                key, expected)

    typed("kind", str, "a surrogate kind's name")
    typed("inputs", list, f"a list of input names ({', '.join(INPUTS)} first)")
    inputs = metadata["inputs"]
    require(all(isinstance(n, str) for n in inputs) and tuple(inputs[:len(INPUTS)]) == INPUTS
            and set(inputs) <= set(ALL_INPUTS) and len(set(inputs)) == len(inputs), "inputs",
            f"{', '.join(INPUTS)}, then some of {', '.join(PARAMETERS)}")
    typed("fixed", dict, "an object of muscle parameters and their values")
    for name, value in metadata["fixed"].items():
        require(name in PARAMETERS and name not in inputs and _number(value), f"fixed.{name}",
                f"a finite number of one of {', '.join(PARAMETERS)} that is not an input")
    typed("box", dict, "an object of [low, high] per input")
    for name in inputs:
        bounds = metadata["box"].get(name)
        require(isinstance(bounds, list) and len(bounds) == 2 and all(map(_number, bounds))
                and bounds[0] <= bounds[1], f"box.{name}", "[low, high], finite, low <= high")
    typed("checks", dict, "an object of the checks")
    typed("checks.code_version", str, "a code version")
    typed("checks.calibration", dict, "the calibration at training")
    typed("checks.estimator_sha256", str, "the estimator file's sha256")
    typed("dataset", dict, "an object describing the training data", optional=True)
    typed("dataset.path", str, "the training data's path", optional=True)
    typed("dataset.sha256", str, "the training data's sha256", optional=True)
    typed(f"dataset.{PATH_FROM_MODEL}", str, "the training data's path from the model's folder",
          optional=True)
    typed("trained", dict, "the training's provenance", optional=True)
    typed("trained.versions", dict, "the library versions at training", optional=True)
    typed("metrics", dict, "the errors measured at training", optional=True)


def mismatches(metadata: dict, data: tuple[Path, str] | None = None) -> list[str]:
    """What differs between a saved model's checks and this installation (empty: none);
    ``data``: the training data found and its sha256 (:func:`training_data_file`)."""
    checks = metadata.get("checks", {})
    out = []
    current = code_version(metadata["kind"])
    if checks.get("code_version") != current:
        out.append(f"code version {checks.get('code_version')} (the surrogate and the physics "
                   f"it calls) is now {current}")
    if checks.get("calibration") != calibration_snapshot():
        out.append("fem/calibration.json changed since training")
    recorded = metadata.get("dataset", {}).get("sha256")
    if data is not None and data[1] != recorded:
        out.append(f"training data {data[0]} changed since training (sha256 "
                   f"{str(recorded)[:12]} -> {data[1][:12]})")
    return out


def training_data_file(dataset: dict, directory=None) -> tuple[Path, str] | None:
    """The training data a model's ``dataset`` record names, and its sha256; None where no
    file of that path is found. It is looked for first where it lay seen from the model's
    ``directory`` (its ``path_from_model``, :func:`path_from_model`); then by its recorded
    path, relative to the folder the training ran in, from the working directory and from each
    folder above the model's ``directory`` (a project's data beside its models), nearest
    first. The first file there with the recorded sha256 is the data, unchanged; else the first
    found, changed. A packaged dataset of that name (a model trained on the shipped data,
    recorded by its name alone) is the data only when its sha256 is the recorded one: another
    file may have its name (``mkm fem dataset`` writes ``mkm_dataset.csv`` too)."""
    path = dataset.get("path")
    if not path:
        return None
    recorded = dataset.get("sha256")
    places = [Path()] + (list(Path(directory).resolve().parents) if directory else [])
    packaged = package_file("mkm.surrogate", "data", Path(path).name)
    # lexically from the resolved folder, as path_from_model was made
    beside = ([Path(os.path.normpath(Path(directory).resolve() / dataset[PATH_FROM_MODEL]))]
              if directory and dataset.get(PATH_FROM_MODEL) else [])
    first = None
    for candidate in [*dict.fromkeys([*beside, *(place / path for place in places)]),
                      packaged]:
        if candidate.is_file():
            digest = file_sha256(candidate)
            if digest == recorded:
                return candidate, digest
            if first is None and candidate is not packaged:
                first = candidate, digest
    return first


def load_model(directory, accept_mismatch: bool = False) -> SurrogateForceModel:
    """The surrogate saved in ``directory``, as a :class:`~mkm.fem.interface.ForceModel`.

    Raises ``ValueError`` if the folder is not a saved surrogate, its metadata is malformed or
    edited (:func:`read_metadata`), its kind is not registered, the estimator file (or the
    predictor file) does not match its recorded sha256, or (unless ``accept_mismatch``) the
    code, calibration or training data (:func:`training_data_file`) differ from the recorded
    ones; warns (:class:`LibraryVersionWarning`) if the libraries differ from those that
    trained it, and (:class:`UncheckedDataWarning`) if its training data is not found. A kind
    with a predictor (:class:`mkm.surrogate.kinds.Kind`) predicts from ``predictor.npz`` (read
    with ``allow_pickle=False``) and reads its estimator file on first use of ``.estimator``;
    the others read it now. Either way a file holding a type outside those its kind trusts is
    refused with a ``ValueError`` before anything in it is built.
    """
    directory = Path(directory)
    metadata = read_metadata(directory)
    trusted = kinds.trusted_types(metadata["kind"])  # an unknown kind: refused here
    checks = metadata["checks"]
    _check_file(directory / ESTIMATOR_FILE, checks["estimator_sha256"])
    predictor_class = kinds.predictor_class(metadata["kind"])
    if predictor_class is not None:
        _check_file(directory / PREDICTOR_FILE, checks.get("predictor_sha256"))
    dataset = metadata.get("dataset", {})
    data = training_data_file(dataset, directory)
    differ = mismatches(metadata, data)
    if differ and not accept_mismatch:
        raise ValueError(f"surrogate {str(directory)!r} was trained for another installation: "
                         f"{'; '.join(differ)}: retrain it with `mkm surrogate train`, or "
                         "accept it anyway (--accept-mismatch, surrogate:path=DIR,"
                         "accept_mismatch=true)")
    trained = metadata.get("trained", {}).get("versions", {})
    current = provenance()["versions"]
    libraries = [f"{lib} {trained.get(lib)} -> {current.get(lib)}" for lib in CHECKED_LIBRARIES
                 if trained.get(lib) != current.get(lib)]
    if libraries:
        warnings.warn(f"surrogate {str(directory)!r} was trained with other library versions "
                      f"({'; '.join(libraries)}): its predictions may differ; retrain it with "
                      "`mkm surrogate train`", LibraryVersionWarning, stacklevel=2)
    if dataset.get("path") and data is None:
        beside = (f" nor at {dataset[PATH_FROM_MODEL]} from the model's folder"
                  if dataset.get(PATH_FROM_MODEL) else "")
        warnings.warn(f"surrogate {str(directory)!r}: its training data {dataset['path']} "
                      f"(sha256 {str(dataset.get('sha256'))[:12]}) is found neither from the "
                      f"working directory nor above the model's folder{beside}: whether it "
                      "changed since training is not checked (run from the folder it was "
                      "trained in to check it)", UncheckedDataWarning, stacklevel=2)
    args = (metadata["kind"], metadata["inputs"], metadata["fixed"], metadata["box"], metadata)
    # the data found unchanged: saved elsewhere, the copy records where it lies from there
    data_file = data[0] if data is not None and data[1] == dataset.get("sha256") else None

    def load_estimator():
        return _read_estimator(directory / ESTIMATOR_FILE, checks["estimator_sha256"],
                               trusted, len(metadata["inputs"]))

    if predictor_class is None:
        return SurrogateForceModel(load_estimator(), *args, data_file=data_file)
    predictor = _read_predictor(directory / PREDICTOR_FILE, predictor_class, metadata)
    return SurrogateForceModel(None, *args, predictor=predictor, load_estimator=load_estimator,
                               data_file=data_file)


def _check_file(path: Path, sha256) -> None:
    if not path.is_file() or file_sha256(path) != sha256:
        raise ValueError(f"{str(path)!r} is missing or does not match the sha256 recorded in "
                         f"{METADATA_FILE}: expected the file saved with it")


def _read_estimator(path: Path, sha256: str, trusted, n_inputs: int):
    """The estimator in ``path`` (checked against ``sha256`` again: it is read when first
    used), built by skops from the types it trusts and ``trusted`` alone."""
    import skops.io as sio
    from skops.io.exceptions import UntrustedTypesFoundException

    _check_file(path, sha256)
    try:
        estimator = sio.load(path, trusted=list(trusted))
    except UntrustedTypesFoundException as exc:
        raise ValueError(f"{str(path)!r} holds types outside the trusted list "
                         f"({exc}): refused, a model file never runs code") from None
    except Exception as exc:  # noqa: BLE001 - any damage to the file: say which and stop
        raise ValueError(f"{str(path)!r} cannot be read as a surrogate "
                         f"({type(exc).__name__}: {exc}): retrain it with `mkm surrogate "
                         "train`") from None
    if getattr(estimator, "n_features_in_", None) != n_inputs:
        raise ValueError(f"{str(path)!r} takes "
                         f"{getattr(estimator, 'n_features_in_', 'no known number of')} inputs: "
                         f"expected the {n_inputs} its metadata names")
    return estimator


def _read_predictor(path: Path, predictor_class, metadata: dict):
    """The predictor of the arrays in ``path``: numbers only (``allow_pickle=False``)."""
    import numpy as np

    try:
        with np.load(path, allow_pickle=False) as archive:
            arrays = {name: archive[name] for name in archive.files}
        return predictor_class.from_arrays(arrays, metadata["inputs"], metadata["fixed"])
    except Exception as exc:  # noqa: BLE001 - any damage to the file: say which and stop
        raise ValueError(f"{str(path)!r} cannot be read as the surrogate's arrays "
                         f"({type(exc).__name__}: {exc}): retrain it with `mkm surrogate "
                         "train`") from None
