"""Saving and loading surrogates: model files that cannot run code, and that know what they need.

A saved surrogate is a folder:

- ``estimator.skops``: the fitted estimator in skops' format (a zip of JSON and ``.npy``
  arrays), loaded with an explicit list of trusted types (:data:`TRUSTED_TYPES`: the project's
  own estimator classes and feature function and scikit-learn's kernels; skops itself trusts
  scikit-learn's estimators and numpy arrays, which it rebuilds without pickle). A file naming
  anything else (``os.system``, a class with a crafted ``__reduce__``) is refused before
  anything in it is built: loading a model never runs code from it;
- ``metadata.json``: kind, inputs, recorded parameters, box, metrics, the training data's
  sha256, and the checks: the source version of every module the estimator calls
  (:func:`code_version`, the physics of the closed-form priors included) and the calibration
  (``fem/calibration.json``) at training time, and the estimator file's sha256.

:func:`load_model` refuses a model whose checks do not match this installation, naming each
difference (``accept_mismatch=True`` takes it anyway); other library versions warn
(:class:`LibraryVersionWarning`). :func:`save_model` writes under a lock file (``filelock``:
works on Windows too) and swaps the folder in whole, so two processes saving at once cannot
leave half a model or crash on each other.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
import warnings
from pathlib import Path

from mkm.fem.records import file_sha256, provenance, source_version, write_json_atomic
from mkm.surrogate.model import SurrogateForceModel

ESTIMATOR_FILE = "estimator.skops"
METADATA_FILE = "metadata.json"
CHECKED_LIBRARIES = ("python", "numpy", "scipy", "scikit-learn")
#: Modules whose code a loaded estimator runs (their imports follow: fem.thickwall, fem.eq2...).
MODEL_MODULES = ("mkm.surrogate.estimators", "mkm.surrogate.features", "mkm.surrogate.model")

#: Types a model file may contain beyond what skops trusts itself (scikit-learn estimators,
#: numpy and builtin containers): exactly what :func:`mkm.surrogate.estimators.make_estimator`
#: builds. Nothing else is ever loaded.
TRUSTED_TYPES = (
    "mkm.surrogate.estimators.MuscleThresholdGP",
    "mkm.surrogate.estimators.ThresholdLinearRegressor",
    "mkm.surrogate.features.physics_features",
    "sklearn.gaussian_process.kernels.ConstantKernel",
    "sklearn.gaussian_process.kernels.Matern",
    "sklearn.gaussian_process.kernels.Product",
    "sklearn.gaussian_process.kernels.Sum",
    "sklearn.gaussian_process.kernels.WhiteKernel",
)


class LibraryVersionWarning(UserWarning):
    """A surrogate is loaded with library versions other than those it was trained with."""


def code_version() -> str:
    """Source version of everything a loaded surrogate calls (:data:`MODEL_MODULES`)."""
    return source_version(*MODEL_MODULES)


def calibration_snapshot() -> dict:
    """The calibration in force (``fem/calibration.json``): the default braid angle comes from
    it, and the closed-form physics the priors use is calibrated with it."""
    from mkm.fem.calibration import CALIBRATION_FILE

    return json.loads(Path(CALIBRATION_FILE).read_text(encoding="utf-8"))


def save_model(model: SurrogateForceModel, directory, lock=None) -> Path:
    """Write ``model`` to ``directory`` (created; replaced whole if it exists).

    ``lock``: a context manager held while writing (default: ``<directory>.lock``).
    """
    import skops.io as sio
    from filelock import FileLock

    directory = Path(directory)
    directory.parent.mkdir(parents=True, exist_ok=True)
    with lock if lock is not None else FileLock(str(directory) + ".lock"):
        staging = Path(tempfile.mkdtemp(prefix=f".{directory.name}-", dir=directory.parent))
        try:
            sio.dump(model.estimator, staging / ESTIMATOR_FILE)
            metadata = {**model.metadata, "kind": model.kind, "inputs": list(model.inputs),
                        "fixed": model.fixed, "box": {k: list(v) for k, v in model.box.items()},
                        "checks": {"code_version": code_version(),
                                   "calibration": calibration_snapshot(),
                                   "estimator_sha256": file_sha256(staging / ESTIMATOR_FILE)},
                        "saved": provenance()}
            metadata.setdefault("trained", metadata["saved"])
            write_json_atomic(staging / METADATA_FILE, metadata)
            if directory.exists():  # swap, so a reader never sees half a model
                old = Path(tempfile.mkdtemp(prefix=f".{directory.name}-old-",
                                            dir=directory.parent))
                os.replace(directory, old / "model")
                os.replace(staging, directory)
                shutil.rmtree(old, ignore_errors=True)
            else:
                os.replace(staging, directory)
        finally:
            if staging.exists():
                shutil.rmtree(staging, ignore_errors=True)
    return directory


def read_metadata(directory) -> dict:
    path = Path(directory) / METADATA_FILE
    if not path.is_file():
        raise ValueError(f"{str(directory)!r} is not a saved surrogate: {METADATA_FILE} missing "
                         "(expected a folder written by `mkm surrogate train`)")
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except ValueError as exc:
        raise ValueError(f"{str(path)!r} is not valid JSON ({exc}): expected the metadata "
                         "`mkm surrogate train` writes") from None


def mismatches(metadata: dict) -> list[str]:
    """What differs between a saved model's checks and this installation (empty: none)."""
    checks = metadata.get("checks", {})
    out = []
    if checks.get("code_version") != code_version():
        out.append(f"code version {checks.get('code_version')} (the surrogate and the physics "
                   f"it calls) is now {code_version()}")
    if checks.get("calibration") != calibration_snapshot():
        out.append("fem/calibration.json changed since training")
    dataset = metadata.get("dataset", {})
    path = dataset.get("path")
    if path and Path(path).is_file() and file_sha256(path) != dataset.get("sha256"):
        out.append(f"training data {path} changed since training (sha256 "
                   f"{str(dataset.get('sha256'))[:12]} -> {file_sha256(path)[:12]})")
    return out


def load_model(directory, accept_mismatch: bool = False) -> SurrogateForceModel:
    """The surrogate saved in ``directory``, as a :class:`~mkm.fem.interface.ForceModel`.

    Raises ``ValueError`` if the folder is not a saved surrogate, the estimator file does not
    match its recorded sha256 or holds a type outside :data:`TRUSTED_TYPES`, or (unless
    ``accept_mismatch``) the code, calibration or training data differ from the recorded ones;
    warns (:class:`LibraryVersionWarning`) if the libraries differ from those that trained it.
    """
    import skops.io as sio
    from skops.io.exceptions import UntrustedTypesFoundException

    directory = Path(directory)
    metadata = read_metadata(directory)
    estimator_path = directory / ESTIMATOR_FILE
    checks = metadata.get("checks", {})
    if not estimator_path.is_file() or file_sha256(estimator_path) != checks.get(
            "estimator_sha256"):
        raise ValueError(f"{str(estimator_path)!r} is missing or does not match the sha256 "
                         f"recorded in {METADATA_FILE}: expected the file saved with it")
    differ = mismatches(metadata)
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
    try:
        estimator = sio.load(estimator_path, trusted=list(TRUSTED_TYPES))
    except UntrustedTypesFoundException as exc:
        raise ValueError(f"{str(estimator_path)!r} holds types outside the trusted list "
                         f"({exc}): refused, a model file never runs code") from None
    except Exception as exc:  # noqa: BLE001 - any damage to the file: say which and stop
        raise ValueError(f"{str(estimator_path)!r} cannot be read as a surrogate "
                         f"({type(exc).__name__}: {exc}): retrain it with `mkm surrogate "
                         "train`") from None
    try:
        return SurrogateForceModel(estimator, metadata["kind"], metadata["inputs"],
                                   metadata["fixed"], metadata["box"], metadata)
    except KeyError as exc:
        raise ValueError(f"{str(directory / METADATA_FILE)!r} lacks {exc}: expected the "
                         "metadata `mkm surrogate train` writes") from None
