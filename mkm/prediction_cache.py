"""On-disk cache of force-model predictions, so a second report or study skips the FE solves.

A cache entry is keyed by the model's name and parameters, the inputs, and the model's *version*:
the package version plus a hash of the sources the model depends on and of its package's data
files (so editing the physics or recalibrating invalidates the entry; editing the report does
not).
Entries are ``.npz`` files written atomically (temporary file + ``os.replace``), read without
pickle.
"""

from __future__ import annotations

import ast
import hashlib
import importlib
import importlib.util
import json
import os
import sys
import tempfile
from importlib.metadata import version
from pathlib import Path

import numpy as np

from fem.interface import INPUTS, ForceModel, Prediction

DEFAULT_CACHE_DIR = Path(".cache/mkm-report")


def model_version(model: ForceModel) -> str:
    """Package version + hash of the sources the model's module depends on, and its data files.

    The dependencies are the model's module and, transitively, every module of the same package
    it imports (at any depth in the file) or names in a registry of ``"module:Class"`` strings
    (``fem.ladder.MODELS``). The package's ``*.json`` files (the calibration) are hashed too: a
    stale force is worse than a recomputed one.
    """
    modules = _dependencies(type(model).__module__)
    digest = hashlib.sha256(version("mkm-bench").encode())
    paths = {Path(sys.modules[name].__file__) for name in modules}
    for package in {path.parent for path in paths}:
        paths |= set(package.glob("*.json"))
    for path in sorted(paths):
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def _dependencies(module_name: str) -> set[str]:
    package = module_name.split(".")[0]
    seen: set[str] = set()
    todo = [module_name]
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        module = importlib.import_module(name)
        path = getattr(module, "__file__", None)
        if not path or not path.endswith(".py"):
            continue
        seen.add(name)
        for node in ast.walk(ast.parse(Path(path).read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                todo += [node.module, *(f"{node.module}.{a.name}" for a in node.names)]
            elif isinstance(node, ast.Import):
                todo += [a.name for a in node.names]
        registry = getattr(module, "MODELS", None)
        if isinstance(registry, dict):
            todo += [v.split(":")[0] for v in registry.values() if isinstance(v, str)]
        todo = [t for t in todo if t.split(".")[0] == package and _is_module(t)]
    return seen


def _is_module(name: str) -> bool:
    try:
        return importlib.util.find_spec(name) is not None
    except (ImportError, ValueError):
        return False


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
    path.parent.mkdir(parents=True, exist_ok=True)
    arrays = {name: getattr(prediction, name) for name in (*INPUTS, "force_N", "valid",
                                                           "converged")}
    # object arrays (failure messages) would need pickle to load: store them as text
    arrays |= {f"extra__{k}": np.asarray(v).astype(str) if np.asarray(v).dtype == object
               else np.asarray(v) for k, v in prediction.extras.items()}
    meta = {"model": prediction.model, "params": prediction.params,
            "seconds": prediction.seconds}
    arrays["meta"] = np.array(json.dumps(meta, default=repr))
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            np.savez(f, **arrays)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _load(path: Path) -> Prediction:
    with np.load(path, allow_pickle=False) as data:
        meta = json.loads(str(data["meta"]))
        extras = {k.removeprefix("extra__"): data[k] for k in data.files
                  if k.startswith("extra__")}
        return Prediction(model=meta["model"], params=meta["params"],
                          seconds=float(meta["seconds"]), extras=extras,
                          **{name: data[name] for name in (*INPUTS, "force_N", "valid",
                                                           "converged")})
