"""On-disk cache of force-model predictions, so a second report or study skips the FE solves.

An entry is keyed by the model's name and parameters, the inputs, and the model's *version*
(:func:`mkm.fem.records.source_version` of its module: the package version plus a hash of the
sources it depends on and of the calibration), so editing the physics or recalibrating
invalidates the entry and editing the report does not. Entries are ``.npz`` files written with
:func:`mkm.fem.records.write_atomic` and read without pickle, in the user's cache folder
(:func:`mkm.paths.default_cache`) unless told otherwise.
"""

from __future__ import annotations

import hashlib
import io
import json
from pathlib import Path

import numpy as np

from mkm.fem.interface import INPUTS, ForceModel, Prediction
from mkm.fem.records import source_version, write_atomic
from mkm.paths import CacheFolder

DEFAULT_CACHE_DIR = CacheFolder("predictions")


def model_version(model: ForceModel) -> str:
    """Version of the code and data behind ``model``: :func:`mkm.fem.records.source_version` of the
    module that defines its class."""
    return source_version(type(model).__module__)


def cache_key(model: ForceModel, inputs: tuple[np.ndarray, ...]) -> str:
    """Hash of model name, parameters, version and the exact input values."""
    digest = hashlib.sha256()
    digest.update(json.dumps({"model": model.name, "params": model.params(),
                              "version": model_version(model)},
                             sort_keys=True, default=repr).encode())
    for array in inputs:
        a = np.ascontiguousarray(array, dtype=float)
        digest.update(str(a.shape).encode())
        digest.update(a.tobytes())
    return digest.hexdigest()[:32]


def cached_predict(model: ForceModel, pressure_bar, D0_mm, t0_mm, eps,
                   cache_dir: Path | str | None = DEFAULT_CACHE_DIR) -> tuple[Prediction, bool]:
    """``model.predict(...)`` through the cache; returns the prediction and whether it was a hit.

    ``seconds`` of a cached prediction is the wall time measured when it was computed.
    ``cache_dir=None`` disables the cache.
    """
    inputs = tuple(np.broadcast_arrays(*(np.asarray(v, dtype=float)
                                         for v in (pressure_bar, D0_mm, t0_mm, eps))))
    if cache_dir is None:
        return model.predict(*inputs), False
    path = Path(cache_dir) / f"{model.name}-{cache_key(model, inputs)}.npz"
    if path.exists():
        return _load(path), True
    prediction = model.predict(*inputs)
    _store(prediction, path)
    return prediction, False


def _store(prediction: Prediction, path: Path) -> None:
    arrays = {name: getattr(prediction, name) for name in (*INPUTS, "force_N", "valid",
                                                           "converged")}
    # object arrays (failure messages) would need pickle to load: store them as text
    arrays |= {f"extra__{k}": np.asarray(v).astype(str) if np.asarray(v).dtype == object
               else np.asarray(v) for k, v in prediction.extras.items()}
    meta = {"model": prediction.model, "params": prediction.params,
            "seconds": prediction.seconds}
    arrays["meta"] = np.array(json.dumps(meta, default=repr))
    buffer = io.BytesIO()
    np.savez(buffer, **arrays)
    write_atomic(path, buffer.getvalue())


def _load(path: Path) -> Prediction:
    with np.load(path, allow_pickle=False) as data:
        meta = json.loads(str(data["meta"]))
        extras = {k.removeprefix("extra__"): data[k] for k in data.files
                  if k.startswith("extra__")}
        return Prediction(model=meta["model"], params=meta["params"],
                          seconds=float(meta["seconds"]), extras=extras,
                          **{name: data[name] for name in (*INPUTS, "force_N", "valid",
                                                           "converged")})
