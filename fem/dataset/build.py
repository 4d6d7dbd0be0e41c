"""The MKM dataset: forces of any registered model over a grid of muscles, resumable and parallel.

A grid (``fem/grids/paper.toml`` is Table 1 of Antonelli et al. 2025) lists values per parameter.
Its jobs are independent: one per muscle (``D0_mm``, ``t0_mm``, ``L0_mm``, ``theta0_deg``) and
``eps``, each the model's pressure sweep. Every finished job is cached in its own file, keyed by
the job's inputs and the model's version, so an interrupted build resumes where it stopped and
editing the physics invalidates what it computed. Jobs run in-process (one worker), on a local
Dask cluster, or on an existing Dask cluster given by its scheduler address; the client writes
the cache, so workers need no shared file system.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import os
import sys
import time
from dataclasses import asdict, dataclass
from importlib.metadata import version
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from mkm.fem.dataset.grid import Grid, load_grid
from mkm.fem.ladder import LADDER, entry, make_model
from mkm.fem.records import provenance, source_version, user_cache, write_atomic

DEFAULT_OUT = Path("data/mkm_dataset.csv")


def default_cache_dir() -> Path:
    """One file per finished job, in the user's cache (:func:`mkm.fem.records.user_cache`)."""
    return user_cache("dataset")

COLUMNS = {
    "pressure_bar": "gauge pressure [bar]",
    "D0_mm": "inner tube diameter at rest [mm]",
    "t0_mm": "wall thickness at rest [mm]",
    "eps": "shortening ratio dL/L0 [fraction]",
    "force_N": "developed force [N]; NaN where the model did not converge",
    "converged": "the model's solve converged at this point",
    "valid": "converged and inside the model's validity range",
    "iterations": "Newton iterations at this point (models that iterate; empty otherwise)",
    "cutbacks": "load-step cutbacks at this point (models that iterate; empty otherwise)",
    "seconds": "wall time of the model's predict() for the job's whole pressure sweep [s]",
    "model": "model name in fem.ladder.LADDER",
    "mesh": "mesh level of the model (empty for mesh-free models)",
    "theta0_deg": "braid angle at rest [deg]",
    "L0_mm": "muscle length at rest [mm]",
}


@dataclass(frozen=True)
class Job:
    """One model call: the pressure sweep of one muscle at one ``eps``, all inputs resolved."""

    model: str
    mesh: str | None
    D0_mm: float
    t0_mm: float
    eps: float
    L0_mm: float | None
    theta0_deg: float | None
    pressure_bar: tuple[float, ...]
    C10_MPa: float | None = None  # wall rubber (Mooney-Rivlin); None: the model's default
    C01_MPa: float | None = None

    def key(self, model_version: str) -> str:
        """Cache key: a hash of every input and of the code that computes the job."""
        job = asdict(self)
        for name in ("C10_MPa", "C01_MPa"):  # default rubber: the keys of jobs before it existed
            if job[name] is None:
                del job[name]
        text = json.dumps({"job": job, "model_version": model_version}, sort_keys=True)
        return hashlib.sha256(text.encode()).hexdigest()[:24]

    def describe(self) -> str:
        return (f"{self.model} D0_mm={self.D0_mm:g} t0_mm={self.t0_mm:g} eps={self.eps:g} "
                f"L0_mm={self.L0_mm} theta0_deg={self.theta0_deg}")


def make_jobs(grid: Grid, model: str, mesh: str | None = None) -> list[Job]:
    """One job per muscle and eps, with theta0 resolved (calibrated default made explicit).

    Resolving theta0 here makes the cache key change when the calibration does, and sends
    workers the angle itself rather than a lookup in their own ``fem/calibration.json``.
    """
    jobs = []
    for D0, t0, e, L0, theta0 in itertools.product(grid.D0_mm, grid.t0_mm, grid.eps,
                                                   grid.L0_mm, grid.theta0_deg):
        params = make_model(model, theta0_deg=theta0, L0_mm=L0, mesh=mesh).params()
        jobs.append(Job(model=model, mesh=_mesh_label(params.get("mesh", mesh)), D0_mm=D0,
                        t0_mm=t0, eps=e, L0_mm=params.get("L0_mm", L0),
                        theta0_deg=params.get("theta0_deg", theta0),
                        pressure_bar=grid.pressure_bar))
    return jobs


def _mesh_label(mesh) -> str | None:
    return None if mesh is None else str(mesh)


def model_version(name: str) -> str:
    """The source version of rung ``name`` (:func:`mkm.fem.records.source_version` of its
    module)."""
    return source_version(entry(name).module)


def run_job(job: Job) -> dict[str, Any]:
    """Compute one job: rows as plain lists, the model's parameters and the model version.

    Runs wherever the job is sent (in-process or on a Dask worker); returns plain data only.
    """
    model = make_model(job.model, theta0_deg=job.theta0_deg, L0_mm=job.L0_mm, mesh=job.mesh,
                       C10_MPa=job.C10_MPa, C01_MPa=job.C01_MPa)
    n = len(job.pressure_bar)
    pred = model.predict(np.array(job.pressure_bar), job.D0_mm, job.t0_mm, job.eps)
    params = pred.params
    rows = {
        "pressure_bar": list(job.pressure_bar),
        "D0_mm": [job.D0_mm] * n, "t0_mm": [job.t0_mm] * n, "eps": [job.eps] * n,
        "force_N": pred.force_N.tolist(),
        "converged": pred.converged.tolist(),
        "valid": pred.valid.tolist(),
        "iterations": _optional_ints(pred.extras.get("iterations"), n),
        "cutbacks": _optional_ints(pred.extras.get("cutbacks"), n),
        "seconds": [pred.seconds] * n,
        "model": [job.model] * n,
        "mesh": [_mesh_label(params.get("mesh", job.mesh))] * n,
        "theta0_deg": [params.get("theta0_deg", job.theta0_deg)] * n,
        "L0_mm": [params.get("L0_mm", job.L0_mm)] * n,
    }
    # the wall rubber, for models that have one (a surrogate learns across rubbers)
    rows.update({k: [params[k]] * n for k in ("C10_MPa", "C01_MPa") if k in params})
    # whatever else the model reports per point (an FE model's threshold pressure, failure
    # reason, ...) is kept: computed anyway, and useful to surrogates and to failure studies
    rows.update({k: np.ravel(v).tolist() for k, v in pred.extras.items() if k not in rows})
    return {"rows": rows, "params": _jsonable(params), "model_version": model_version(job.model)}


def _optional_ints(values, n: int) -> list[int | None]:
    if values is None:
        return [None] * n
    return [int(v) if np.isfinite(v) else None for v in np.ravel(values)]


def _jsonable(obj):
    return json.loads(json.dumps(obj, default=lambda o: o.tolist() if hasattr(o, "tolist")
                                 else str(o)))


class JobCache:
    """One JSON file per finished job in ``directory``, named by its key, written atomically."""

    def __init__(self, directory: str | os.PathLike):
        self.directory = Path(directory)

    def path(self, key: str) -> Path:
        return self.directory / f"{key}.json"

    def get(self, key: str) -> dict | None:
        """The cached result, or None when absent or unreadable (a damaged file is recomputed)."""
        try:
            return json.loads(self.path(key).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None

    def put(self, key: str, job: Job, result: dict) -> None:
        entry = {"key": key, "job": asdict(job), **result,
                 "date_utc": provenance()["date_utc"]}
        write_atomic(self.path(key), json.dumps(entry, indent=1) + "\n")


@dataclass
class DatasetRun:
    """What :func:`build_dataset` did: the rows, the counts and where they were written."""

    frame: pd.DataFrame
    jobs_total: int
    jobs_computed: int
    jobs_cached: int
    wall_seconds: float
    workers: str
    out: Path | None
    sidecar: Path | None

    @property
    def points_not_converged(self) -> int:
        return int((~self.frame["converged"]).sum())

    @property
    def jobs_not_converged(self) -> int:
        keys = ["D0_mm", "t0_mm", "eps", "L0_mm", "theta0_deg"]
        return int((~self.frame.groupby(keys, dropna=False)["converged"].all()).sum())

    def summary(self) -> str:
        where = f"; wrote {self.out} and {self.sidecar}" if self.out else ""
        return (f"{len(self.frame)} rows from {self.jobs_total} jobs ({self.jobs_computed} "
                f"computed, {self.jobs_cached} from cache) in {self.wall_seconds:.1f} s on "
                f"{self.workers}; {self.points_not_converged} of {len(self.frame)} points "
                f"({self.jobs_not_converged} of {self.jobs_total} jobs) did not converge, "
                f"{int((~self.frame['valid']).sum())} points flagged invalid{where}")


def build_dataset(grid: str | os.PathLike | Grid = "paper", model: str = "axisym", *,
                  mesh: str | None = None, out: str | os.PathLike | None = DEFAULT_OUT,
                  workers: int | None = None, scheduler: str | None = None,
                  cache_dir: str | os.PathLike | None = None,
                  progress: bool = True) -> DatasetRun:
    """Build the dataset of ``model`` over ``grid``: compute the jobs not in the cache, write the
    CSV ``out`` (one row per point: :data:`COLUMNS`, then any other per-point output of the
    model) and its provenance ``out.json``.

    ``workers=1`` runs in-process; more (default: the CPU count) start a local Dask cluster of
    single-threaded worker processes; ``scheduler="tcp://HOST:PORT"`` sends the jobs to an
    existing Dask cluster instead. Non-converged points are kept with ``converged=False`` and
    NaN force. ``out=None`` writes nothing (the rows are in the returned ``frame``).
    """
    if scheduler is not None and workers is not None:
        raise ValueError(f"workers={workers} and scheduler={scheduler!r} given: a cluster has its "
                         "own workers; expected one of the two")
    if workers is not None and workers < 1:
        raise ValueError(f"workers={workers} is invalid: expected at least 1")
    grid = grid if isinstance(grid, Grid) else load_grid(grid)
    cache_dir = default_cache_dir() if cache_dir is None else cache_dir
    start = time.perf_counter()
    jobs = make_jobs(grid, model, mesh)
    frame, done = run_jobs(jobs, workers=workers, scheduler=scheduler, cache_dir=cache_dir,
                           progress=progress, desc=f"{model} dataset")
    run = DatasetRun(frame=frame, jobs_total=len(jobs), jobs_computed=done["computed"],
                     jobs_cached=done["cached"], wall_seconds=time.perf_counter() - start,
                     workers=done["workers"], out=None, sidecar=None)
    model_ver, first_params = done["model_version"], done["params"]
    if out is not None:
        run.out = Path(out)
        run.sidecar = run.out.with_suffix(".json")
        info = _provenance(run, grid, jobs, model_ver, first_params, cache_dir)
        write_atomic(run.out, frame.to_csv(index=False, lineterminator="\n"))
        write_atomic(run.sidecar, json.dumps(info, indent=2) + "\n")
    return run


def run_jobs(jobs: list[Job], *, workers: int | None = None, scheduler: str | None = None,
             cache_dir: str | os.PathLike | None = None, progress: bool = True,
             desc: str = "dataset") -> tuple[pd.DataFrame, dict[str, Any]]:
    """Compute ``jobs`` (one model, any list: a grid's product or a space-filling design) through
    the cache, in-process or on Dask as :func:`build_dataset` does.

    Returns the rows of every job in order (:data:`COLUMNS` first) and what was done:
    ``computed``, ``cached``, ``workers`` (where), ``model_version``, ``params`` (of the first).
    """
    if scheduler is not None and workers is not None:
        raise ValueError(f"workers={workers} and scheduler={scheduler!r} given: a cluster has its "
                         "own workers; expected one of the two")
    if workers is not None and workers < 1:
        raise ValueError(f"workers={workers} is invalid: expected at least 1")
    if not jobs:
        raise ValueError("no job to run: expected at least one muscle")
    models = sorted({job.model for job in jobs})
    if len(models) > 1:
        raise ValueError(f"jobs of several models ({', '.join(models)}): expected one")
    model_ver = model_version(models[0])
    keys = [job.key(model_ver) for job in jobs]
    store = JobCache(default_cache_dir() if cache_dir is None else cache_dir)
    results: dict[str, dict] = {}
    for key in keys:
        cached = store.get(key)
        if cached is not None:
            results[key] = cached
    missing = [(key, job) for key, job in zip(keys, jobs, strict=True) if key not in results]
    n_cached = len(jobs) - len(missing)

    from tqdm import tqdm

    bar = tqdm(total=len(jobs), initial=n_cached, unit="job", desc=desc,
               disable=not progress, file=sys.stderr)

    def finished(key: str, job: Job, result: dict) -> None:
        if result["model_version"] != model_ver:
            raise RuntimeError(f"a worker computed {job.describe()} with model version "
                               f"{result['model_version']}, this client has {model_ver}: "
                               "install the same code on the workers")
        store.put(key, job, result)
        results[key] = result
        bar.update()

    if workers is None and scheduler is None:
        workers = os.cpu_count() or 1
    with bar:
        if not missing:
            where = "no worker (all cached)"
        elif scheduler is None and min(workers, len(missing)) == 1:
            for key, job in missing:
                finished(key, job, run_job(job))
            where = "1 worker (in-process)"
        else:
            where = _run_on_dask(missing, finished, workers, scheduler)
    frame = pd.concat([pd.DataFrame(results[key]["rows"]) for key in keys], ignore_index=True)
    frame = frame.astype({"iterations": "Int64", "cutbacks": "Int64", "converged": bool,
                          "valid": bool})
    frame = frame[list(COLUMNS) + [c for c in frame.columns if c not in COLUMNS]]
    return frame, {"computed": len(missing), "cached": n_cached, "workers": where,
                   "model_version": model_ver, "params": results[keys[0]]["params"]}


def _run_on_dask(missing, finished, workers: int | None, scheduler: str | None) -> str:
    """Run ``missing`` jobs on a local Dask cluster or on the one at ``scheduler``; the client
    caches each result as it arrives, so an interruption loses only the jobs in flight."""
    import logging

    import dask
    from dask.distributed import Client, LocalCluster, as_completed

    if scheduler is None:
        # Processes, one thread each; the nanny sets OMP/MKL/OPENBLAS_NUM_THREADS=1 in workers.
        # Its MALLOC_TRIM_THRESHOLD_ makes glibc map and unmap every large temporary array: the
        # axisym FE ran 30-50 % slower per job with it (benchmarks/bench_dataset.py), so unset.
        with dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}):
            cluster = LocalCluster(n_workers=min(workers, len(missing)), threads_per_worker=1,
                                   processes=True, dashboard_address=None,
                                   silence_logs=logging.ERROR)
        where = f"{len(cluster.workers)} local Dask workers"
    else:
        cluster = None
        where = f"the Dask cluster at {scheduler}"
    failures = []
    try:
        try:
            client = Client(cluster or scheduler)
        except OSError as exc:
            raise ValueError(f"scheduler={scheduler!r}: {exc}: expected the address of a "
                             "running Dask scheduler, e.g. tcp://HOST:8786") from None
        with client:
            by_future = {client.submit(run_job, job, key=f"mkm-dataset-{key}"): (key, job)
                         for key, job in missing}
            for future in as_completed(by_future):
                key, job = by_future[future]
                try:
                    result = future.result()
                except Exception as exc:  # keep going: every other finished job gets cached
                    failures.append(f"{job.describe()}: {type(exc).__name__}: {exc}")
                    continue
                finished(key, job, result)
    finally:
        if cluster is not None:
            cluster.close()
    if failures:
        raise RuntimeError(f"{len(failures)} of {len(missing)} jobs failed (the others are "
                           f"cached; re-run to retry): " + "; ".join(failures))
    return where


def _provenance(run: DatasetRun, grid: Grid, jobs: list[Job], model_ver: str,
                params: dict, cache_dir) -> dict[str, Any]:
    from mkm.fem.calibration import calibration_provenance

    info = provenance()
    info["versions"]["dask.distributed"] = version("distributed")
    model = make_model(jobs[0].model, mesh=jobs[0].mesh)
    if None not in grid.theta0_deg:
        calibration = {"key": model.calibration_key, "source": "theta0_deg given by the grid"}
    else:
        try:
            calibration = calibration_provenance(model)
        except ValueError:  # the model's default theta0 does not come from a calibration
            calibration = {"key": model.calibration_key,
                           "source": "the model's default theta0_deg"}
    return {
        **info,
        "model": jobs[0].model,
        "model_version": model_ver,
        "model_params": params,
        "mesh": jobs[0].mesh,
        "calibration": calibration,
        "grid": grid.as_dict(),
        "rows": len(run.frame),
        "jobs": run.jobs_total,
        "jobs_computed": run.jobs_computed,
        "jobs_from_cache": run.jobs_cached,
        "points_not_converged": run.points_not_converged,
        "jobs_not_converged": run.jobs_not_converged,
        "wall_seconds": round(run.wall_seconds, 3),
        "workers": run.workers,
        "cache": str(cache_dir),
        "columns": {c: COLUMNS.get(c, "reported by the model (see "
                                      f"{LADDER[jobs[0].model].factory})")
                    for c in run.frame.columns},
    }
