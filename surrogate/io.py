"""Saving and loading surrogates with their metadata.

A saved surrogate is a folder: ``estimator.joblib`` (the fitted scikit-learn estimator, pickled
by joblib as scikit-learn documents) and ``metadata.json`` (kind, domain, training-data hash and
provenance, metrics, library versions, and the estimator file's sha256). Pickles run code when
loaded: load only surrogates you or this project made. Loading with other library versions than
the ones that trained the model warns with :class:`LibraryVersionWarning`.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
import warnings
from pathlib import Path

import joblib

from fem.interface import Domain
from fem.records import provenance
from surrogate.model import SurrogateForceModel
from surrogate.training_data import file_sha256

ESTIMATOR_FILE = "estimator.joblib"
METADATA_FILE = "metadata.json"
CHECKED_LIBRARIES = ("python", "numpy", "scipy", "scikit-learn")


class LibraryVersionWarning(UserWarning):
    """A surrogate is loaded with library versions other than those it was trained with."""


def save_model(model: SurrogateForceModel, directory) -> Path:
    """Write ``model`` to ``directory`` (created; replaced atomically if it exists)."""
    directory = Path(directory)
    directory.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{directory.name}-", dir=directory.parent))
    joblib.dump(model.estimator, staging / ESTIMATOR_FILE)
    metadata = {**model.metadata, "kind": model.kind, "domain": model.domain.as_dict(),
                "estimator_sha256": file_sha256(staging / ESTIMATOR_FILE),
                "saved": provenance()}
    metadata.setdefault("trained", metadata["saved"])
    (staging / METADATA_FILE).write_text(json.dumps(metadata, indent=2, default=_json_default)
                                         + "\n", encoding="utf-8")
    if directory.exists():  # swap, so a reader never sees half a model
        old = Path(tempfile.mkdtemp(prefix=f".{directory.name}-old-", dir=directory.parent))
        os.replace(directory, old / "model")
        os.replace(staging, directory)
        shutil.rmtree(old)
    else:
        os.replace(staging, directory)
    return directory


def read_metadata(directory) -> dict:
    path = Path(directory) / METADATA_FILE
    if not path.is_file():
        raise ValueError(f"{str(directory)!r} is not a saved surrogate: {METADATA_FILE} missing "
                         "(expected a folder written by `mkm surrogate train`)")
    return json.loads(path.read_text(encoding="utf-8"))


def load_model(directory) -> SurrogateForceModel:
    """The surrogate saved in ``directory``, as a :class:`~fem.interface.ForceModel`.

    Raises ``ValueError`` if the folder is not a saved surrogate or the estimator file does not
    match the hash recorded at saving; warns (:class:`LibraryVersionWarning`) if the libraries
    differ from those that trained it.
    """
    directory = Path(directory)
    metadata = read_metadata(directory)
    estimator_path = directory / ESTIMATOR_FILE
    if not estimator_path.is_file() or file_sha256(estimator_path) != metadata.get(
            "estimator_sha256"):
        raise ValueError(f"{str(estimator_path)!r} is missing or does not match the sha256 "
                         f"recorded in {METADATA_FILE}: expected the file saved with it")
    trained = metadata.get("trained", {}).get("versions", {})
    current = provenance()["versions"]
    differ = [f"{lib} {trained.get(lib)} -> {current.get(lib)}" for lib in CHECKED_LIBRARIES
              if trained.get(lib) != current.get(lib)]
    if differ:
        warnings.warn(f"surrogate {str(directory)!r} was trained with other library versions "
                      f"({'; '.join(differ)}): its predictions may differ; retrain it with "
                      "`mkm surrogate train`", LibraryVersionWarning, stacklevel=2)
    with warnings.catch_warnings():
        # scikit-learn's own InconsistentVersionWarning says the same as ours, less clearly.
        warnings.filterwarnings("ignore", message=".*Trying to unpickle estimator")
        try:
            estimator = joblib.load(estimator_path)
        except (AttributeError, ImportError, TypeError) as exc:  # code it refers to changed
            raise ValueError(f"surrogate {str(directory)!r} cannot be loaded by this version of "
                             f"the code ({exc}): retrain it with `mkm surrogate train`") from None
    domain = Domain(**{k: tuple(v) for k, v in metadata["domain"].items()})
    return SurrogateForceModel(estimator, domain, metadata["kind"], metadata)


def _json_default(value):
    if hasattr(value, "item"):
        return value.item()
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"{type(value).__name__} is not JSON serialisable")
