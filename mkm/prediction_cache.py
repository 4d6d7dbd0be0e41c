"""On-disk cache of force-model predictions, so a second report or study skips the FE solves.

An entry is keyed by the model's name and parameters, the inputs, and the model's *version*
(:func:`mkm.core.records.source_version` of its module: the package version plus a hash of the
sources it depends on and of the calibration), so editing the physics or recalibrating
invalidates the entry and editing the report does not. Entries are ``.npz`` files written with
:func:`mkm.core.records.write_atomic` and read without pickle, in the user's cache folder
(:func:`mkm.paths.default_cache`) unless told otherwise.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import sys
import tempfile
import zipfile
from pathlib import Path

import numpy as np

from mkm.core.records import source_version, write_atomic
from mkm.fem.interface import INPUTS, ForceModel, Prediction
from mkm.paths import CacheFolder

DEFAULT_CACHE_DIR = CacheFolder("predictions")


def model_version(model: ForceModel) -> str:
    """Version of the code and data behind ``model``: :func:`mkm.core.records.source_version` of the
    module that defines its class."""
    return source_version(type(model).__module__)


def model_origin(model: ForceModel) -> dict:
    """What a record of a model's predictions names it by besides its version: a surrogate's
    model file, training and dataset (``{"surrogate": ...}``,
    :meth:`mkm.surrogate.model.SurrogateForceModel.origin`); nothing for another model."""
    surrogates = sys.modules.get("mkm.surrogate.model")  # loaded where a surrogate was built
    return ({"surrogate": model.origin()} if surrogates is not None
            and isinstance(model, surrogates.SurrogateForceModel) else {})


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
    inputs = _inputs(pressure_bar, D0_mm, t0_mm, eps)
    if cache_dir is None:
        return model.predict(*inputs), False
    path = _path(model, inputs, cache_dir)
    cached = _load_entry(path)
    if cached is not None:
        return cached, True
    prediction = model.predict(*inputs)
    _store(prediction, path)
    return prediction, False


def _inputs(pressure_bar, D0_mm, t0_mm, eps) -> tuple[np.ndarray, ...]:
    return tuple(np.broadcast_arrays(*(np.asarray(v, dtype=float)
                                       for v in (pressure_bar, D0_mm, t0_mm, eps))))


def _path(model: ForceModel, inputs, cache_dir) -> Path:
    return Path(cache_dir) / f"{model.name}-{cache_key(model, inputs)}.npz"


#: Parameters a batch job (:class:`mkm.fem.batch.Job`) carries: a model with others (the sliding
#: braid) is solved in-process
JOB_PARAMETERS = ("theta0_deg", "L0_mm", "mesh", "C10_MPa", "C01_MPa")


def predict_many(requests, cache_dir: Path | str | None = DEFAULT_CACHE_DIR, *,
                 workers: int | None = None, scheduler: str | None = None, runner=None,
                 progress: bool = False, desc: str = "FE sweeps") -> list[tuple[Prediction, bool]]:
    """:func:`cached_predict` of every request ``(model, pressure_bar, D0_mm, t0_mm, eps)``, the
    sweeps of expensive models missing from the cache computed together on the FE batch runner
    (:func:`mkm.fem.batch.run_jobs`: ``workers`` local processes, the Dask cluster at
    ``scheduler``, or an open ``runner``; its per-job cache makes an interrupted batch resume).

    A request whose muscle is one point (scalar ``D0_mm``, ``t0_mm``, ``eps``) of an expensive
    physics model (:attr:`mkm.fem.ladder.Entry.expensive`) whose parameters a job carries goes
    to the batch; any other is predicted in-process. Returns ``(prediction, hit)`` per request,
    in order; a batched prediction equals ``model.predict`` to the last bit.
    """
    from mkm.fem.batch import run_jobs

    out: list = [None] * len(requests)
    batch: dict[int, tuple] = {}
    for i, (model, *values) in enumerate(requests):
        inputs = _inputs(*values)
        path = None if cache_dir is None else _path(model, inputs, cache_dir)
        cached = None if path is None else _load_entry(path)
        if cached is not None:
            out[i] = cached, True
            continue
        job = _job(model, inputs)
        if job is None:
            out[i] = cached_predict(model, *inputs, cache_dir=cache_dir)
        else:
            batch[i] = (job, model, inputs, path)
    if batch:
        with contextlib.ExitStack() as stack:
            # no prediction cache: the jobs' own cache is a temporary folder too
            jobs_dir = (stack.enter_context(tempfile.TemporaryDirectory(prefix="mkm-jobs-"))
                        if cache_dir is None else None)
            frame, _ = run_jobs([job for job, *_ in batch.values()], workers=workers,
                                scheduler=scheduler, runner=runner, cache_dir=jobs_dir,
                                progress=progress, desc=desc)
        start = 0
        for i, (job, model, inputs, path) in batch.items():
            rows = frame.iloc[start:start + len(job.pressure_bar)]
            start += len(job.pressure_bar)
            prediction = _from_rows(model, inputs, rows)
            if path is not None:
                _store(prediction, path)
            out[i] = prediction, False
    return out


def _job(model: ForceModel, inputs):
    """The batch job of a sweep, or None when the runner cannot carry it."""
    from mkm.fem.batch import Job
    from mkm.fem.ladder import MODELS

    known = MODELS.entry(model.name) if model.name in MODELS else None
    params = model.params()
    P, D0, t0, eps = inputs
    if (known is None or not known.expensive or not set(params) <= set(JOB_PARAMETERS)
            or P.ndim != 1 or any(np.unique(v).size != 1 for v in (D0, t0, eps))):
        return None
    return Job(model.name, params.get("mesh"), float(D0[0]), float(t0[0]), float(eps[0]),
               params.get("L0_mm"), params.get("theta0_deg"), tuple(float(p) for p in P),
               params.get("C10_MPa"), params.get("C01_MPa"))


def _from_rows(model: ForceModel, inputs, rows) -> Prediction:
    """The prediction of one job's rows, as ``model.predict`` returns it (extras as floats where
    the job stored whole numbers: iterations, cutbacks)."""
    from mkm.fem.batch import COLUMNS

    kept = set(COLUMNS) - {"iterations", "cutbacks"} | {"C10_MPa", "C01_MPa"}
    extras = {}
    for name in (c for c in rows.columns if c not in kept):
        values = rows[name].to_numpy()
        if name in ("iterations", "cutbacks"):
            values = rows[name].astype("Float64").to_numpy(dtype=float, na_value=np.nan)
        extras[name] = values
    return Prediction(model=model.name, params=model.params(), pressure_bar=inputs[0],
                      D0_mm=inputs[1], t0_mm=inputs[2], eps=inputs[3],
                      force_N=rows["force_N"].to_numpy(dtype=float),
                      valid=rows["valid"].to_numpy(dtype=bool),
                      converged=rows["converged"].to_numpy(dtype=bool),
                      seconds=float(rows["seconds"].iloc[0]), extras=extras)


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
    # not synced: an entry a power loss cut short is read as a miss (_load_entry)
    write_atomic(path, buffer.getvalue(), sync=False)


def _load_entry(path: Path) -> Prediction | None:
    """The cached prediction at ``path``; None when there is none or it cannot be read (a
    write cut short by a full disk or a kill, a file damaged since): computed again and
    replaced, as a miss."""
    if not path.exists():
        return None
    try:
        return _load(path)
    except (OSError, EOFError, ValueError, KeyError, TypeError, zipfile.BadZipFile):
        return None


def _load(path: Path) -> Prediction:
    with np.load(path, allow_pickle=False) as data:
        meta = json.loads(str(data["meta"]))
        extras = {k.removeprefix("extra__"): data[k] for k in data.files
                  if k.startswith("extra__")}
        return Prediction(model=meta["model"], params=meta["params"],
                          seconds=float(meta["seconds"]), extras=extras,
                          **{name: data[name] for name in (*INPUTS, "force_N", "valid",
                                                           "converged")})
